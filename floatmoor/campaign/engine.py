"""Running a campaign: FD screening, TD storms, manifest, resume, serial or on Dask.

Phases: (1) the frequency domain for every case (batches of cases per task), (2) the screening
(:mod:`floatmoor.campaign.screening`, ``screening.csv``), (3) the time-domain storms of the kept
cases, one task per (case, seed), (4) in ``storage: {mode: statistics}`` the full series of the
governing case of each line and limit state, rerun from their seeds.

Executors: ``serial`` (in this process) or Dask (:mod:`dask.distributed`): a ``LocalCluster``
of ``workers`` single-threaded processes (:func:`local_cluster`, Dask's background sampling
turned down), or an existing scheduler at ``tcp://HOST:8786``.  Every Dask worker runs
:func:`~floatmoor.campaign.tasks.warm_worker` before its first task.  The tasks
(:mod:`floatmoor.campaign.tasks`) are pure and write their own files; the client only appends
outcomes to the manifest and screens with the values the tasks return (files of an earlier run
are read).  A worker that dies has its tasks rerun on another worker by
the Dask scheduler (up to ``distributed.scheduler.allowed-failures`` times, then the task is
recorded as failed); a task that raises inside floatmoor (e.g. NumericalError) is recorded as
failed with its message and the others go on.  Rerunning the same command resumes: a result
is kept when its manifest row says done, its file has the recorded size (and SHA-256 with
``verify``), was computed from the inputs of the case as it is now (the fingerprint digest of
:func:`floatmoor.analyses.fingerprint.case_fingerprint`: base scene and the files it reads,
the case's sea state, headings, condition and time settings from the campaign file and its
contour or list, the storage settings, the code) and holds finite and plausible values
(:func:`floatmoor.campaign.store.read_result`); anything else (missing, failed, half-written,
stale, corrupted) runs again, and the run says which and why.  A folder holding another
campaign's results is refused unless ``force``; the folder is locked while the campaign runs
(:func:`floatmoor.analyses.folder_lock.folder_lock`); a full disk stops the campaign with
:class:`~floatmoor.analyses.folder_lock.DiskFull` (finished results kept).
"""

from __future__ import annotations

import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import store
from .matrix import build_matrix
from .screening import select_cases, td_case_check, utilisation
from .spec import CampaignSpec, load_campaign
from .tasks import run_fd_cases, run_storm, warm_worker

__all__ = ["QUIET_DASK_CONFIG", "CampaignOutcome", "campaign_analysis", "local_cluster",
           "make_executor", "run_campaign"]


@dataclass
class CampaignOutcome:
    out_dir: Path
    n_cases: int = 0
    n_td_cases: int = 0
    ran: dict = field(default_factory=dict)        # kind -> tasks run now
    skipped: dict = field(default_factory=dict)    # kind -> tasks already done
    failed: list = field(default_factory=list)     # (kind, case, seed, error)
    wall_time: float = 0.0
    task_time: float = 0.0                          # sum of the tasks' own wall times
    warmup: list = field(default_factory=list)      # warm_worker outcome of each Dask worker


def campaign_analysis(spec: CampaignSpec, overrides: dict | None = None) -> dict:
    an = dict(spec.analysis)
    an.update({k: v for k, v in (overrides or {}).items() if k != "seeds" and v is not None})
    return an


# -- progress --------------------------------------------------------------------------------
class Progress:
    """A tqdm bar (when installed and stderr is a terminal) or plain lines: done, failed,
    remaining and the estimated time left."""

    def __init__(self, label: str, total: int, echo, workers: int, bar: bool | None = None):
        self.label, self.total, self.echo, self.workers = label, total, echo, max(1, workers)
        self.done = self.failed = 0
        self.t0 = time.perf_counter()
        self.last = 0.0
        self.bar = None
        if bar is None:
            bar = sys.stderr.isatty()
        if bar and total:
            try:
                from tqdm import tqdm
                self.bar = tqdm(total=total, desc=label, unit="task")
            except ImportError:
                self.bar = None

    def eta(self) -> float:
        n = self.done + self.failed
        if n == 0:
            return float("nan")
        return (time.perf_counter() - self.t0) / n * (self.total - n)

    def update(self, ok: bool, n: int = 1, note: str = "") -> None:
        if ok:
            self.done += n
        else:
            self.failed += n
        remaining = self.total - self.done - self.failed
        if self.bar is not None:
            self.bar.update(n)
            self.bar.set_postfix(done=self.done, failed=self.failed, remaining=remaining)
            return
        now = time.perf_counter()
        if self.echo and (remaining == 0 or now - self.last > 5.0 or not ok or note):
            self.last = now
            eta = self.eta()
            self.echo(f"[{self.label}] {self.done} done, {self.failed} failed, {remaining} "
                      f"remaining, about {eta:.0f} s left" + (f"  {note}" if note else ""))

    def close(self):
        if self.bar is not None:
            self.bar.close()


# -- executors --------------------------------------------------------------------------------
SINGLE_THREAD_ENV = {"OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
                     "OPENBLAS_NUM_THREADS": "1"}
"""The environment of every task process (as Dask's nanny gives its workers): a multi-threaded
BLAS sums in a different order and changes the last bits of the statics and eigen-solutions, so
a serial run in a process with several BLAS threads would not be bit-identical to a cluster."""


def _task_process_init() -> None:
    """The serial executor's worker process ends with the campaign's process (a killed
    campaign leaves no storm running beside the one that resumes it)."""
    from ..analyses.folder_lock import die_with_parent
    die_with_parent()


class SerialExecutor:
    """One task after the other in one spawned worker process with :data:`SINGLE_THREAD_ENV`
    (a worker that dies is replaced and its task recorded as failed)."""

    workers = 1

    def __init__(self):
        self._saved = {k: os.environ.get(k) for k in SINGLE_THREAD_ENV}
        os.environ.update(SINGLE_THREAD_ENV)
        self.pool = None

    def _pool(self):
        if self.pool is None:
            import multiprocessing
            from concurrent.futures import ProcessPoolExecutor
            self.pool = ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn"),
                                            initializer=_task_process_init)
        return self.pool

    def cancel(self):
        """Nothing to cancel: one task at a time, none submitted ahead."""

    def warm(self, fn, *args):
        """Nothing: the one process warms up in its first task (and serial runs stay the
        reference that the warmed Dask workers must reproduce bit for bit)."""

    def warm_results(self) -> list:
        return []

    def map(self, fn, arg_list):
        from concurrent.futures.process import BrokenProcessPool
        for args in arg_list:
            try:
                res = self._pool().submit(fn, *args).result()
            except BrokenProcessPool as exc:
                self.pool = None
                res = exc
            yield args, res

    def close(self):
        if self.pool is not None:
            self.pool.shutdown()
        for k, v in self._saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


QUIET_DASK_CONFIG = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "5s",
    "distributed.worker.memory.monitor-interval": "1s",
}
"""Dask settings of the campaign's own LocalCluster.  By default every worker samples the stack
of its task thread every 10 ms (the dashboard's profile), every process checks its event loop
every 20 ms and the system and memory monitors poll every 0.1-0.5 s: measured on an idle
1-worker cluster, 2.9 % of a core in the worker and 3.1 % in the client process (scheduler), CPU
taken from the storms on a machine with as many workers as cores; with these settings 0.3 %
and 0.5 %.  The dashboard stays (its task stream and progress do not need the profiler)."""


def local_cluster(n_workers: int):
    """A ``LocalCluster`` of ``n_workers`` single-threaded worker processes with
    :data:`QUIET_DASK_CONFIG` (the workers take the settings when they start)."""
    import logging

    import dask
    from dask.distributed import LocalCluster
    with dask.config.set(QUIET_DASK_CONFIG):
        return LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                            dashboard_address=":0", silence_logs=logging.ERROR)


class DaskExecutor:
    """Tasks on a Dask cluster: a new LocalCluster, or a scheduler address, or a Client."""

    def __init__(self, scheduler: str = "local", workers: int | None = None, client=None):
        from dask.distributed import Client
        self._own = client is None
        self.cluster = None
        if client is not None:
            self.client = client
        elif scheduler == "local":
            self.cluster = local_cluster(workers or len(os.sched_getaffinity(0)))
            self.client = Client(self.cluster)
        else:
            self.client = Client(scheduler)
        info = self.client.scheduler_info()
        self.workers = max(1, sum(w.get("nthreads", 1) for w in info["workers"].values()))

    def warm(self, fn, *args):
        """``fn(*args)`` once on each worker present now, before any task submitted later (a
        worker that joins later, or replaces a dead one, warms up in its first task)."""
        workers = list(self.client.scheduler_info()["workers"])
        self._warm = [self.client.submit(fn, *args, workers=[w], allow_other_workers=False,
                                         pure=False, priority=10) for w in workers]

    def warm_results(self) -> list:
        """The outcomes of the warm-ups that finished (the others are cancelled)."""
        out = []
        for fut in getattr(self, "_warm", []):
            if fut.done() and fut.status == "finished":
                out.append(fut.result())
            else:
                fut.cancel()
        self._warm = []
        return out

    def map(self, fn, arg_list):
        from dask.distributed import as_completed
        futs = self._futs = {}
        for args in arg_list:
            futs[self.client.submit(fn, *args, pure=False, retries=1)] = args
        for fut in as_completed(futs):
            args = futs.pop(fut)
            try:
                res = fut.result()
            except Exception as exc:  # noqa: BLE001 - KilledWorker after repeated deaths, ...
                res = exc
            fut.release()
            yield args, res

    def cancel(self):
        """Cancel the tasks of the current :meth:`map` not finished yet."""
        futs = list(getattr(self, "_futs", {}))
        if futs:
            self.client.cancel(futs)
        self._futs = {}

    def close(self):
        for fut in getattr(self, "_warm", []):
            fut.cancel()
        if self._own:
            self.client.close()
            if self.cluster is not None:
                self.cluster.close()


def make_executor(scheduler: str = "local", workers: int | None = None, client=None):
    if client is None and scheduler == "serial":
        return SerialExecutor()
    return DaskExecutor(scheduler, workers, client)


# -- the campaign -------------------------------------------------------------------------------
def _fd_failed(cases, exc):
    return [{"kind": "fd", "case": c.id, "seed": -1, "status": "failed", "wall_time_s": 0.0,
             "path": "", "error": f"{type(exc).__name__}: {exc}"} for c in cases]


def _record(spec, cases, seeds, analysis, out_dir, fps, lines, files):
    """``campaign.json``: the campaign's parameters, the case list with the fingerprint digest
    of each case's results (fd, td, series), the line names and the base scene's file and
    code fingerprint (``base_inputs``)."""
    from ..analyses.fingerprint import _file_hash
    rows = []
    for c in cases:
        r = c.row()
        r["fingerprints"] = {k: v[1] for k, v in fps[c.id].items()}
        rows.append(r)
    sources = {}
    if spec.file:
        sources["campaign_file"] = _file_hash(spec.file)
    store.write_record(out_dir, {
        "name": spec.name, "description": spec.description,
        "campaign_file": os.fspath(spec.file) if spec.file else "",
        "base_scene": os.fspath(spec.base_scene), "seeds": list(seeds),
        "analysis": analysis,
        "design": {"standard": spec.design.standard,
                   "consequence_class": spec.design.consequence_class,
                   "analysis": spec.design.analysis},
        "screening": {"time_domain": spec.screening.time_domain,
                      "within_percent": spec.screening.within_percent,
                      "top_per_line": spec.screening.top_per_line},
        "storage": {"mode": spec.storage.mode, "precision": spec.storage.precision,
                    "compression": spec.storage.compression,
                    "sampling": dict(spec.storage.sampling)},
        "lines": list(lines), "base_inputs": files, "sources": sources,
        "cases": rows})


def screen(spec, cases, out_dir, known: dict | None = None
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """FD utilisation (cases x lines), kept mask, reasons; writes ``screening.csv``.  ``known``:
    the FD tables of this run's tasks by case id (the other cases' files are read)."""
    ids = [c.id for c in cases]
    fd = store.load_fd_table(out_dir, ids, known)
    if not fd:
        n = len(cases)
        return np.full((n, 0), np.nan), np.ones(n, bool), np.zeros((n, 0), int)
    u = np.full(fd["tension_static"].shape, np.nan)
    for i, c in enumerate(cases):
        if np.isfinite(fd["mbs"][i]).all():
            u[i] = utilisation(fd["tension_static"][i], fd["tension_max_total"][i],
                               fd["mbs"][i], c.limit_state, spec.design)
    import dataclasses
    states = [c.limit_state for c in cases]
    rule = dataclasses.replace(spec.screening, time_domain="screened")
    screened, reason = select_cases(u, states, rule)   # what the rule keeps, in every mode
    fd_missing = ~np.isfinite(u).any(axis=1)
    screened |= fd_missing  # no FD result: cannot be screened out
    keep = {"screened": screened, "all": np.ones(len(cases), bool),
            "none": np.zeros(len(cases), bool)}[spec.screening.time_domain]
    lines = [f"u_fd_{j + 1}" for j in range(u.shape[1])]
    rows = ["case,limit_state,td,screened," + ",".join(lines)]
    for i, c in enumerate(cases):
        rows.append(f"{c.id},{c.limit_state},{int(keep[i])},{int(screened[i])}," +
                    ",".join("" if not np.isfinite(x) else f"{x:.6f}" for x in u[i]))
    (Path(out_dir) / "screening.csv").write_text("\n".join(rows) + "\n")
    return u, keep, reason


def governing_cases(spec, cases, seeds, out_dir, known: dict | None = None) -> list:
    """The TD cases governing some line in some limit state (largest TD utilisation).
    ``known``: the storm tables of this run's tasks by (case id, seed)."""
    ids = [c.id for c in cases]
    st = store.load_td_statistics(out_dir, ids, seeds, known=known)
    if not st:
        return []
    n, nl = len(cases), st["mbs"].size
    u = np.full((n, nl), np.nan)
    names = None
    for i, c in enumerate(cases):
        mx = st["line_tension_max"][i]
        ok = np.isfinite(mx).all(axis=1)
        if ok.sum() < 3:
            continue
        skip = _skip_lines(c, out_dir, names)
        u[i] = td_case_check(mx[ok], st["line_tension_mean"][i][ok], st["mbs"], c.limit_state,
                             spec.design, skip)["utilisation"]
    out = set()
    for state in ("ULS", "ALS"):
        rows = np.array([i for i, c in enumerate(cases) if c.limit_state == state])
        if rows.size == 0:
            continue
        for j in range(nl):
            col = u[rows, j]
            if np.isfinite(col).any():
                out.add(int(rows[np.nanargmax(col)]))
    return [cases[i] for i in sorted(out)]


def _skip_lines(case, out_dir, names=None) -> tuple:
    """Column indices of the lines failed or broken in ``case`` (not checked)."""
    if not case.condition.lines:
        return ()
    names = names or line_names(out_dir)
    return tuple(names.index(ln) for ln in case.condition.lines if ln in names)


def line_names(out_dir) -> list[str]:
    rec = store.read_record(out_dir)
    return list(rec.get("lines", []))


def _preload(module: str):
    """Import ``module`` in a background thread (join it before use; an import error then
    surfaces at the ordinary import)."""
    import importlib
    import threading

    def load():
        try:
            importlib.import_module(module)
        except Exception:  # noqa: BLE001 - raised again where the module is used
            pass
    th = threading.Thread(target=load, name=f"preload {module}", daemon=True)
    th.start()
    return th


def _most_critical_first(u, cases, keep) -> list[int]:
    """Indices of the kept cases, the most critical first (largest FD utilisation relative to
    the governing FD utilisation of the same line and limit state; cases without FD first), so
    that an interrupted campaign has its likely governing cases done."""
    idx = np.nonzero(keep)[0]
    if u.size == 0:
        return list(idx)
    states = np.array([c.limit_state for c in cases])
    rel = np.full(u.shape, np.nan)
    for ls in np.unique(states):
        rows = states == ls
        with np.errstate(invalid="ignore", divide="ignore"):
            gov = np.nanmax(np.where(np.isfinite(u[rows]), u[rows], -np.inf), axis=0)
            rel[rows] = u[rows] / np.where(gov > 0, gov, np.nan)
    score = np.array([np.nanmax(rel[i]) if np.isfinite(rel[i]).any() else np.inf for i in idx])
    return [int(i) for i in idx[np.argsort(-score, kind="stable")]]


def run_campaign(campaign, out_dir, *, scheduler: str = "local", workers: int | None = None,
                 client=None, echo=print, bar: bool | None = None, verify: bool = False,
                 seeds=None, analysis_overrides: dict | None = None,
                 on_outcome=None, force: bool = False) -> CampaignOutcome:
    """Run (or resume) a campaign into ``out_dir``; see the module docstring.

    ``campaign`` is a campaign file or a :class:`CampaignSpec`; ``seeds`` and
    ``analysis_overrides`` (duration, dt, transient, ramp) replace the campaign's (smoke runs);
    ``verify`` checks the SHA-256 of finished files before skipping them; ``on_outcome(dict)``
    is called after each task outcome is in the manifest (progress hooks); ``force`` reuses a
    folder holding another campaign's (or other) results, keeping the results whose inputs
    match this campaign's cases.

    Raises SceneError before anything runs (a mistake in the campaign or its base scene, a
    time setting such as ``--duration`` that does not fit, ``out_dir`` in use by another
    process or holding another campaign), and
    :class:`~floatmoor.analyses.folder_lock.DiskFull` when the disk fills (the finished
    results are kept and recorded)."""
    import warnings

    from ..analyses.folder_lock import folder_lock
    from ._api import load_scene
    from .spec import check_times
    t_start = time.perf_counter()
    spec = campaign if isinstance(campaign, CampaignSpec) else load_campaign(campaign)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        base = load_scene(spec.base_scene)
    check_times(spec, base, analysis_overrides)   # --duration, --dt ...: before anything runs
    out_dir = Path(out_dir).resolve()
    with folder_lock(out_dir, f"floatmoor campaign {spec.name}"):
        return _run_locked(spec, base, out_dir, t_start, scheduler=scheduler, workers=workers,
                           client=client, echo=echo, bar=bar, verify=verify, seeds=seeds,
                           analysis_overrides=analysis_overrides, on_outcome=on_outcome,
                           force=force)


def _run_locked(spec, base, out_dir, t_start, *, scheduler, workers, client, echo, bar, verify,
                seeds, analysis_overrides, on_outcome, force) -> CampaignOutcome:
    """:func:`run_campaign` with the folder locked."""
    from .spec import check_storm_count
    _check_folder(spec, out_dir, force, echo)
    analysis = campaign_analysis(spec, analysis_overrides)
    for tmp in out_dir.rglob("*.tmp"):  # leftovers of interrupted writes
        if tmp.is_file():
            tmp.unlink(missing_ok=True)
    cases = build_matrix(spec)
    by_id = {c.id: c for c in cases}
    seeds = tuple(int(s) for s in (seeds or spec.seeds))
    files, fps = _fingerprints(spec, base, cases, analysis)
    lines = [str(n.raw("name")) for n in base.mooring_node().item_nodes("lines")]
    _record(spec, cases, seeds, analysis, out_dir, fps, lines, files)
    result = CampaignOutcome(out_dir=out_dir, n_cases=len(cases))
    base_path = os.fspath(Path(spec.base_scene).resolve())
    executor = make_executor(scheduler, workers, client)
    try:
        # each worker loads the base scene and the compiled kernels now, while the client
        # reads the manifest and the finished results, not inside its first task
        executor.warm(warm_worker, base_path, analysis)
        manifest = store.Manifest(out_dir)
        # the values the screening reads: returned by this run's tasks, or read (and checked)
        # from the files of an earlier run
        tables = {"fd": {}, "td": {}, "series": {}}

        def consume(label, fn, arg_list, n_of, kind):
            total = sum(n_of(a) for a in arg_list)
            result.skipped[kind] = result.skipped.get(kind, 0)
            prog = Progress(label, total, echo, executor.workers, bar)
            full = None
            for args, res in executor.map(fn, arg_list):
                outs = res if isinstance(res, list) else [res]
                if isinstance(res, BaseException):
                    outs = (_fd_failed(args[1], res) if kind == "fd" else
                            [{"kind": kind, "case": args[1].id, "seed": int(args[2]),
                              "status": "failed", "wall_time_s": 0.0, "path": args[5],
                              "error": f"{type(res).__name__}: {res}"}])
                for o in outs:
                    table = o.pop("table", None)
                    key = o["case"] if kind == "fd" else (o["case"], o["seed"])
                    if o["status"] == "done":
                        o["fingerprint"] = fps[o["case"]][kind][1]
                        if table is not None:
                            tables[kind][key] = table
                    manifest.append(o, by_id[o["case"]].row())
                    result.ran[kind] = result.ran.get(kind, 0) + 1
                    result.task_time += float(o.get("wall_time_s", 0.0))
                    if o["status"] != "done":
                        result.failed.append((kind, o["case"], o["seed"], o["error"]))
                        if o.get("disk_full"):
                            full = full or o
                    prog.update(o["status"] == "done", 1,
                                "" if o["status"] == "done" else
                                f"{o['case']} seed {o['seed']}: {o['error']}")
                    if on_outcome is not None:
                        on_outcome(o)
                if full is not None:
                    break   # every other task would fail the same way
            prog.close()
            if full is not None:
                executor.cancel()
                _disk_full(out_dir, full, manifest)

        # the client's own imports for the screening (scipy.stats for the Gumbel fits) load in
        # a thread while the workers run the frequency domain, not after it
        preload = _preload("floatmoor.post.dnv_os_e301")
        # (1) frequency domain, every case (also with time_domain all or none: the report
        #     compares FD and TD)
        latest = manifest.latest()
        todo = []
        redo = _Redo("FD", echo)
        for c in cases:
            state, info = _resume_state("fd", c, -1, store.fd_path(out_dir, c.id), latest,
                                        fps[c.id]["fd"], verify)
            if state == "done":
                result.skipped["fd"] = result.skipped.get("fd", 0) + 1
                tables["fd"][c.id] = info
            else:
                redo.add(c.id, info)
                todo.append(c)
        redo.report()
        size = max(1, min(32, len(todo) // (4 * executor.workers) or 1))
        batches = [(base_path, todo[i:i + size], analysis, os.fspath(out_dir),
                    spec.storage.compression, {c.id: fps[c.id]["fd"][0]
                                               for c in todo[i:i + size]})
                   for i in range(0, len(todo), size)]
        if echo:
            echo(f"frequency domain: {len(todo)} case(s) to run, "
                 f"{result.skipped.get('fd', 0)} done before")
        consume("FD", run_fd_cases, batches, lambda a: len(a[1]), "fd")
        # (2) screening
        preload.join()
        u, keep, _ = screen(spec, cases, out_dir, tables["fd"])
        td_cases = [cases[i] for i in _most_critical_first(u, cases, keep)]
        result.n_td_cases = len(td_cases)
        check_storm_count(spec, len(td_cases), len(seeds), "TD cases after the screening")
        if echo:
            echo(f"screening ({spec.screening.time_domain}): {len(td_cases)} of {len(cases)} "
                 f"case(s) to the time domain, {len(td_cases) * len(seeds)} storm(s)")
        # (3) time domain
        storms = _storm_args(td_cases, seeds, base_path, analysis, spec.storage, out_dir,
                             manifest, verify, result, "td", fps, tables, echo)
        consume("TD", run_storm, storms, lambda a: 1, "td")
        # (4) statistics mode: the series of the governing cases
        if spec.storage.mode == "statistics" and td_cases:
            gov = governing_cases(spec, td_cases, seeds, out_dir, tables["td"])
            series = _storm_args(gov, seeds, base_path, analysis, spec.storage, out_dir,
                                 manifest, verify, result, "series", fps, tables, echo)
            if echo:
                echo(f"statistics mode: full series of {len(gov)} governing case(s)")
            consume("series", run_storm, series, lambda a: 1, "series")
        result.warmup = executor.warm_results()
    finally:
        executor.close()
    result.wall_time = time.perf_counter() - t_start
    return result


def _disk_full(out_dir, outcome, manifest):
    """Stop the campaign on a full disk: every finished result is in the manifest."""
    from ..analyses.folder_lock import DiskFull
    done = sum(1 for r in manifest.latest().values() if r["status"] == "done")
    msg = outcome["error"].removeprefix("DiskFull: ")
    raise DiskFull(out_dir, f"{msg}; the campaign stopped: {done} finished result(s) kept "
                   f"(manifest.csv); free some space and run the same command again to "
                   "compute the rest")


def _check_folder(spec, out_dir: Path, force: bool, echo) -> None:
    """Refuse (unless ``force``) an output folder that holds another campaign's results, an
    unreadable campaign record, or results that are not a campaign's (``floatmoor run``
    seeds): their files would be taken for this campaign's."""
    from ..core.errors import SceneError
    hint = ("use another --out folder, or --force to reuse it (a result whose inputs match a "
            "case of this campaign is kept, the others are computed again)")
    if (out_dir / store.RECORD).is_file():
        try:
            rec = store.read_record(out_dir)
        except SceneError:
            if force:
                if echo:
                    echo(f"--force: {out_dir / store.RECORD} is unreadable; written again")
                return
            raise
        if rec.get("name") != spec.name:
            if not force:
                raise SceneError(spec.file, "name", f"the campaign whose results are in "
                                 f"{out_dir} ({rec.get('name')!r}, campaign file "
                                 f"{rec.get('campaign_file') or 'unknown'})", spec.name,
                                 f"a folder holds the results of one campaign; {hint}")
            if echo:
                echo(f"--force: reusing the folder of the campaign {rec.get('name')!r}")
        return
    others = sorted(p.name for p in out_dir.glob("*.nc"))[:3]
    if others and not force:
        raise SceneError(spec.file, "", f"a new output folder or one of this campaign "
                         f"({out_dir})", f"a folder of other results ({', '.join(others)}, "
                         "no campaign record)", hint)


def _fingerprints(spec, base, cases, analysis):
    """The input fingerprints of every case's results: ``(files, {case id: {kind: (JSON,
    digest)}})`` for the kinds fd, td and series (:func:`floatmoor.analyses.fingerprint.
    case_fingerprint`); the files the base scene reads are hashed once."""
    import json

    from ..analyses.fingerprint import (
        case_fingerprint,
        file_sections,
        fingerprint_digest,
        scene_fingerprint,
    )
    from .matrix import case_scene
    files = file_sections(base)
    out = {}
    for c in cases:
        scene, _ = case_scene(base, c, analysis)
        sfp = scene_fingerprint(scene, files=files)
        out[c.id] = {}
        for kind in ("fd", "td", "series"):
            fp = case_fingerprint(scene, c.condition, files, kind=kind, storage=spec.storage,
                                  compression=spec.storage.compression, scene_fp=sfp)
            out[c.id][kind] = (json.dumps(fp, sort_keys=True), fingerprint_digest(fp))
    return files, out


class _Redo:
    """The results a resume computes again, and why, said once per reason."""

    def __init__(self, label, echo):
        self.label, self.echo = label, echo
        self.groups: dict[str, list[str]] = {}

    def add(self, what: str, reason: str) -> None:
        if reason:
            self.groups.setdefault(reason, []).append(what)

    def report(self) -> None:
        if not self.echo:
            return
        for reason, items in self.groups.items():
            shown = ", ".join(items[:4]) + (f" and {len(items) - 4} more" if len(items) > 4
                                            else "")
            self.echo(f"{self.label}: {len(items)} result(s) {reason}, computing them again: "
                      f"{shown}")


def _stored_fingerprint(path) -> dict | None:
    import json

    import netCDF4

    from ..analyses.fingerprint import FINGERPRINT_ATTR
    try:
        with netCDF4.Dataset(path) as nc:
            text = getattr(nc, FINGERPRINT_ATTR, None)
        return None if text is None else json.loads(text)
    except Exception:  # noqa: BLE001 - an unreadable file is computed again anyway
        return None


def _resume_state(kind, case, seed, path, latest, fp, verify):
    """``("done", table)`` for a finished result that may be kept: the manifest says done,
    the file has the recorded size (and SHA-256 with ``verify``), was computed from the
    inputs ``fp`` (JSON, digest) and holds checked values; else ``("todo", reason)``, the
    reason empty for a result never finished."""
    import json

    from ..analyses.fingerprint import differing_keys
    from ..core.errors import SceneError
    row = latest.get((kind, case.id, int(seed)))
    if row is None or row["status"] != "done":
        return "todo", ""
    if not path.is_file():
        return "todo", "missing from the folder"
    if row.get("fingerprint") != fp[1]:
        stored = _stored_fingerprint(path)
        if stored is None:
            return "todo", "computed without a recorded input fingerprint"
        diff = differing_keys(stored, json.loads(fp[0]))
        return "todo", f"computed from other inputs (differ in: {', '.join(diff) or '?'})"
    if str(path.stat().st_size) != str(row.get("bytes")):
        return "todo", "half-written or changed since written (size)"
    if verify:
        from .tasks import file_digest
        if file_digest(path) != row.get("sha256"):
            return "todo", "changed since written (SHA-256)"
    try:
        values, _ = store.read_result(path, kind, case.id, seed, expected=fp[1])
    except SceneError as exc:
        return "todo", f"unusable ({exc.key or 'file'}: expected {exc.expected})"
    names = store.FD_TABLE_VARS if kind == "fd" else store.TD_TABLE_VARS
    return "done", {k: values[k] for k in names if k in values}


def _storm_args(cases, seeds, base_path, analysis, storage, out_dir, manifest, verify, result,
                kind, fps, tables, echo):
    latest = manifest.latest()
    out = []
    redo = _Redo("TD" if kind == "td" else "series", echo)
    for c in cases:
        for s in seeds:
            p = store.storm_path(out_dir, c.id, s, kind)
            state, info = _resume_state(kind, c, s, p, latest, fps[c.id][kind], verify)
            if state == "done":
                result.skipped[kind] = result.skipped.get(kind, 0) + 1
                tables[kind][(c.id, int(s))] = info
                continue
            redo.add(f"{c.id} seed {s}", info)
            out.append((base_path, c, int(s), analysis, storage, os.fspath(p),
                        True if kind == "series" else None, fps[c.id][kind][0]))
    redo.report()
    return out
