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
failed with its message and the others go on.  Rerunning the same command resumes: a task whose
manifest row says done and whose file has the recorded size is skipped; anything else (missing,
failed, half-written) runs again.
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
            self.pool = ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn"))
        return self.pool

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
        futs = {}
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


def _record(spec, cases, seeds, analysis, out_dir):
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
        "cases": [c.row() for c in cases]})


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


def run_campaign(campaign, out_dir, *, scheduler: str = "local", workers: int | None = None,
                 client=None, echo=print, bar: bool | None = None, verify: bool = False,
                 seeds=None, analysis_overrides: dict | None = None,
                 on_outcome=None) -> CampaignOutcome:
    """Run (or resume) a campaign into ``out_dir``; see the module docstring.

    ``campaign`` is a campaign file or a :class:`CampaignSpec`; ``seeds`` and
    ``analysis_overrides`` (duration, dt, transient, ramp) replace the campaign's (smoke runs);
    ``verify`` checks the SHA-256 of finished files before skipping them; ``on_outcome(dict)``
    is called after each task outcome is in the manifest (progress hooks)."""
    t_start = time.perf_counter()
    spec = campaign if isinstance(campaign, CampaignSpec) else load_campaign(campaign)
    out_dir = Path(out_dir).resolve()
    out_dir.mkdir(parents=True, exist_ok=True)
    for tmp in out_dir.rglob("*.tmp"):  # leftovers of interrupted writes
        tmp.unlink()
    cases = build_matrix(spec)
    by_id = {c.id: c for c in cases}
    seeds = tuple(int(s) for s in (seeds or spec.seeds))
    analysis = campaign_analysis(spec, analysis_overrides)
    old_inputs = _check_same_campaign(spec, analysis, out_dir)
    _record(spec, cases, seeds, analysis, out_dir)
    result = CampaignOutcome(out_dir=out_dir, n_cases=len(cases))
    base_path = os.fspath(Path(spec.base_scene).resolve())
    executor = make_executor(scheduler, workers, client)
    try:
        # each worker loads the base scene and the compiled kernels now, while the client
        # reads the base scene itself and the manifest, not inside its first task
        executor.warm(warm_worker, base_path, analysis)
        import warnings

        from ._api import load_scene
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            base = load_scene(spec.base_scene)
        inputs = _check_same_inputs(spec, base, old_inputs, out_dir)
        rec = store.read_record(out_dir)
        rec["lines"] = [str(n.raw("name")) for n in base.mooring_node().item_nodes("lines")]
        rec["base_inputs"] = inputs
        store.write_record(out_dir, rec)
        manifest = store.Manifest(out_dir)

        # what the tasks of this run return for the screening (files of earlier runs are read)
        tables = {"fd": {}, "td": {}, "series": {}}

        def consume(label, fn, arg_list, n_of, kind):
            total = sum(n_of(a) for a in arg_list)
            result.skipped[kind] = result.skipped.get(kind, 0)
            prog = Progress(label, total, echo, executor.workers, bar)
            for args, res in executor.map(fn, arg_list):
                outs = res if isinstance(res, list) else [res]
                if isinstance(res, BaseException):
                    outs = (_fd_failed(args[1], res) if kind == "fd" else
                            [{"kind": kind, "case": args[1].id, "seed": int(args[2]),
                              "status": "failed", "wall_time_s": 0.0, "path": args[5],
                              "error": f"{type(res).__name__}: {res}"}])
                for o in outs:
                    table = o.pop("table", None)
                    if table is not None and o["status"] == "done":
                        tables[kind][o["case"] if kind == "fd" else (o["case"], o["seed"])] = table
                    manifest.append(o, by_id[o["case"]].row())
                    result.ran[kind] = result.ran.get(kind, 0) + 1
                    result.task_time += float(o.get("wall_time_s", 0.0))
                    if o["status"] != "done":
                        result.failed.append((kind, o["case"], o["seed"], o["error"]))
                    prog.update(o["status"] == "done", 1,
                                "" if o["status"] == "done" else
                                f"{o['case']} seed {o['seed']}: {o['error']}")
                    if on_outcome is not None:
                        on_outcome(o)
            prog.close()

        # the client's own imports for the screening (scipy.stats for the Gumbel fits) load in
        # a thread while the workers run the frequency domain, not after it
        preload = _preload("floatmoor.post.dnv_os_e301")
        # (1) frequency domain, every case (also with time_domain all or none: the report
        #     compares FD and TD)
        latest = manifest.latest()
        if True:
            todo = []
            for c in cases:
                if manifest.is_done(latest.get(("fd", c.id, -1)), store.fd_path(out_dir, c.id),
                                    verify):
                    result.skipped["fd"] = result.skipped.get("fd", 0) + 1
                else:
                    todo.append(c)
            size = max(1, min(32, len(todo) // (4 * executor.workers) or 1))
            batches = [(base_path, todo[i:i + size], analysis, os.fspath(out_dir),
                        spec.storage.compression) for i in range(0, len(todo), size)]
            if echo:
                echo(f"frequency domain: {len(todo)} case(s) to run, "
                     f"{result.skipped.get('fd', 0)} done before")
            consume("FD", run_fd_cases, batches, lambda a: len(a[1]), "fd")
        # (2) screening
        preload.join()
        u, keep, _ = screen(spec, cases, out_dir, tables["fd"])
        td_cases = [cases[i] for i in _most_critical_first(u, cases, keep)]
        result.n_td_cases = len(td_cases)
        if echo:
            echo(f"screening ({spec.screening.time_domain}): {len(td_cases)} of {len(cases)} "
                 f"case(s) to the time domain, {len(td_cases) * len(seeds)} storm(s)")
        # (3) time domain
        storms = _storm_args(td_cases, seeds, base_path, analysis, spec.storage, out_dir,
                             manifest, verify, result, "td")
        consume("TD", run_storm, storms, lambda a: 1, "td")
        # (4) statistics mode: the series of the governing cases
        if spec.storage.mode == "statistics" and td_cases:
            gov = governing_cases(spec, td_cases, seeds, out_dir, tables["td"])
            series = _storm_args(gov, seeds, base_path, analysis, spec.storage, out_dir,
                                 manifest, verify, result, "series")
            if echo:
                echo(f"statistics mode: full series of {len(gov)} governing case(s)")
            consume("series", run_storm, series, lambda a: 1, "series")
        result.warmup = executor.warm_results()
    finally:
        executor.close()
    result.wall_time = time.perf_counter() - t_start
    return result


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


def _check_same_campaign(spec, analysis, out_dir) -> dict | None:
    """Refuse to resume into a folder of results made with other storm parameters (their files
    would be taken as done).  Returns the base scene's input fingerprint recorded by the
    earlier run (None for a new folder or a record written before fingerprints were kept),
    for :func:`_check_same_inputs` once the base scene is loaded."""
    from ..core.errors import SceneError
    if not (Path(out_dir) / store.RECORD).is_file():
        return None
    old = store.read_record(out_dir)
    new = {"analysis": analysis, "storage": {"mode": spec.storage.mode,
                                             "precision": spec.storage.precision,
                                             "compression": spec.storage.compression,
                                             "sampling": dict(spec.storage.sampling)},
           "base_scene": os.fspath(spec.base_scene)}
    for key, value in new.items():
        if old.get(key) != value:
            raise SceneError(spec.file, key, f"the {key} of the results already in {out_dir} "
                             f"({old.get(key)})", value, "use another --out folder, or the "
                             "same settings to resume")
    return old.get("base_inputs")


def _check_same_inputs(spec, base, old_inputs, out_dir) -> dict:
    """The input fingerprint of the base scene (:func:`~floatmoor.analyses.fingerprint.
    scene_fingerprint`: site, environment, analysis, forces, vessel and its hydrodynamic
    database, mooring, by content); refuse to resume when it differs from the one recorded
    with the results already in ``out_dir`` (an edited mooring or vessel file behind the same
    base-scene path would otherwise mix old and new results in one report)."""
    from ..analyses.fingerprint import differing_keys, scene_fingerprint
    from ..core.errors import SceneError
    inputs = scene_fingerprint(base)
    if old_inputs is not None and dict(old_inputs) != inputs:
        raise SceneError(spec.file, "base_scene",
                         "the inputs of the results already in the output folder",
                         "changed: " + ", ".join(differing_keys(dict(old_inputs), inputs)),
                         f"{spec.base_scene} or a file it reads was edited since the results "
                         f"in {out_dir} were run; use another --out folder for the edited "
                         "scene, or restore it to resume")
    return inputs


def _storm_args(cases, seeds, base_path, analysis, storage, out_dir, manifest, verify, result,
                kind):
    latest = manifest.latest()
    out = []
    for c in cases:
        for s in seeds:
            p = store.storm_path(out_dir, c.id, s, kind)
            if manifest.is_done(latest.get((kind, c.id, int(s))), p, verify):
                result.skipped[kind] = result.skipped.get(kind, 0) + 1
                continue
            args = [base_path, c, int(s), analysis, storage, os.fspath(p)]
            if kind == "series":
                args.append(True)
            out.append(tuple(args))
    return out
