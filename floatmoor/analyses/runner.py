"""Many seeds of one scene, in parallel on the local cores, resumable, failure-tolerant.

:func:`run_seeds` writes one netCDF file per seed, ``<out>/<scene name>_seed<NNNN>.nc``:

* seeds run in worker processes (:class:`concurrent.futures.ProcessPoolExecutor`), one seed per
  task; a line is printed per finished seed (a tqdm bar when tqdm is installed and the output is
  a terminal);
* a seed whose file already exists, is whole, holds finite and plausible values
  (:mod:`floatmoor.analyses.result_check`) and was computed from the same inputs (the
  fingerprint of :mod:`floatmoor.analyses.fingerprint`) is skipped (resume an interrupted batch
  by running the same command again); a file that fails a check is computed again, saying why;
  files are written to ``*.nc.<pid>.tmp`` and renamed when complete, so a file that exists is
  complete;
* the scene is read, built and checked (:func:`floatmoor.io.plausibility.check_built`) in this
  process before any seed starts: a mistake in it is one SceneError, not a failed seed each;
* the output folder is locked while the batch writes into it
  (:func:`floatmoor.analyses.folder_lock.folder_lock`): a second batch into it is refused;
* a full disk stops the batch (:class:`~floatmoor.analyses.folder_lock.DiskFull`, naming the
  folder and the free space; the finished seeds are kept);
* the first seeds of a batch whose time loop is not in numba's cache yet say that numba
  compiles it (once: 10-20 s, about 2.5 minutes with SIMD-lane FE lines) before the first result;
* a failing seed never stops the others: its error is written to ``<name>_seed<NNNN>.error.txt``
  and reported at the end (and the file is removed when that seed later succeeds);
* threads of the FE lines (``solver: {threads: N}`` or ``threads=``): each of the ``W`` worker
  processes runs with at most ``cores // W`` threads (at least 1;
  :func:`floatmoor.io.solver_section.with_thread_cap`), so seeds and threads never ask for more
  than the cores; in-process runs take at most the cores.  The threads change no result (not
  part of the fingerprint).
"""

from __future__ import annotations

import os
import sys
import time
import traceback
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass, field
from pathlib import Path

from ..core.errors import SceneError
from .folder_lock import DiskFull, disk_full_error, folder_lock, temp_name

__all__ = ["run_seeds", "SeedOutcome", "BatchResult", "seed_file", "BatchInterrupted",
           "check_result_file", "DiskFull"]

FINGERPRINT_ATTR = "input_fingerprint"  # the same as floatmoor.analyses.fingerprint


class BatchInterrupted(KeyboardInterrupt):
    """Ctrl-C or SIGTERM during :func:`run_seeds`: the workers were stopped, the seeds in
    flight abandoned (no partial file) and recorded.  ``finished``: outcomes of the seeds done
    before the interrupt; ``interrupted``: the seeds abandoned; ``record``: the file listing
    them."""

    def __init__(self, finished, interrupted, record):
        super().__init__("interrupted")
        self.finished = tuple(finished)
        self.interrupted = tuple(interrupted)
        self.record = record


def check_result_file(path: Path):
    """The stored fingerprint (dict, or None when absent) of a complete result file; raises
    OSError/ValueError when the file is unreadable or truncated (a series cannot be read to its
    end), a SceneError naming the file and variable when a value is not finite or not
    plausible (:func:`floatmoor.analyses.result_check.check_series_file`: NaN, a negative
    tension, a tension beyond 10 x MBS)."""
    import json

    import netCDF4

    from .result_check import check_series_file

    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        check_series_file(path, nc)
        text = getattr(nc, FINGERPRINT_ATTR, None)
    try:
        return None if text is None else json.loads(text)
    except ValueError:
        raise SceneError(path, FINGERPRINT_ATTR, "the JSON input fingerprint floatmoor "
                         "writes", text) from None


@dataclass(frozen=True)
class SeedOutcome:
    """One seed: ``status`` "done", "skipped" or "failed"; ``path`` of the netCDF file;
    ``error`` text when failed; ``wall_time`` (s) of the simulation (0 when skipped);
    ``summary`` a few statistics (dict) when done; ``warnings`` the distinct FloatmoorWarning
    messages of the run (e.g. a line above its MBS, a yaw far from the wave heading)."""

    seed: int
    status: str
    path: Path
    error: str = ""
    wall_time: float = 0.0
    summary: dict = field(default_factory=dict)
    warnings: tuple = ()
    disk_full: bool = False


@dataclass(frozen=True)
class BatchResult:
    outcomes: tuple

    @property
    def failed(self) -> list[int]:
        return [o.seed for o in self.outcomes if o.status == "failed"]

    @property
    def files(self) -> list[Path]:
        return [o.path for o in self.outcomes if o.status in ("done", "skipped")]


def seed_file(out_dir: Path, scene_name: str, seed: int) -> Path:
    safe = "".join(c if c.isalnum() or c in "-_." else "_" for c in scene_name)
    return Path(out_dir) / f"{safe}_seed{int(seed):04d}.nc"


def _ignore_sigint() -> None:
    """Worker initializer: the parent alone handles Ctrl-C (it then stops the workers), and
    SIGTERM ends a worker at once.  A forked worker inherits the parent's SIGTERM handler of
    :func:`_interrupts_as_keyboard_interrupt` (raise KeyboardInterrupt); a worker stopped by
    ``terminate()`` then sometimes printed the KeyboardInterrupt's traceback (seen once in a
    full test run, ``tests/test_run_interrupt.py``), depending on where the signal found it."""
    import signal
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _worker_context():
    """The start method of the worker processes: the platform's default (fork on Linux), or
    ``spawn`` once numba's thread pool runs in this process (a threaded run of FE lines before,
    ``solver.threads``): numba's OpenMP pool terminates a forked child (not fork-safe)."""
    par = sys.modules.get("numba.np.ufunc.parallel")
    if par is None or not getattr(par, "_is_initialized", False):
        return None
    import multiprocessing
    return multiprocessing.get_context("spawn")


# Compiling once for the batch (numba cache empty): the first worker to start a seed compiles
# the kernels ("lead"); the others wait until its time loop is compiled and cached, then load
# it from numba's cache instead of compiling the same kernels at the same time.
_TIME_LOOPS = (("floatmoor.solvers.td_kernel", "td_steps"),
               ("floatmoor.solvers.fe_coupling", "td_fe_kernel"),
               ("floatmoor.solvers.fe_coupling", "td_fe_kernel_lanes"))
_WAIT_MAX = 600.0  # s; a waiting worker compiles for itself after that
_compile_once = None  # in a worker: (ready Event, lead Lock), or None


def _worker_init(ready=None, lead=None) -> None:
    """Worker initializer: ignore Ctrl-C, end with the parent, close the parent's folder lock;
    keep the compile-once event and lock (or None)."""
    global _compile_once
    from .folder_lock import die_with_parent, release_inherited
    _ignore_sigint()
    release_inherited()
    die_with_parent()
    _compile_once = (ready, lead) if ready is not None else None


def _time_loop_cached(finite_element: bool = False) -> bool:
    """True when numba's cache folder of this process already holds a time loop (a cache
    filled by an earlier run: nothing to wait for); with ``finite_element`` the coupled FE
    time loop too."""
    if os.environ.get("NUMBA_DISABLE_JIT", "0") not in ("", "0"):
        return True
    folder = os.environ.get("NUMBA_CACHE_DIR")
    if not folder or not Path(folder).is_dir():
        return False
    names = ["td_kernel.td_steps"] + (["fe_coupling.td_fe_kernel"] if finite_element else [])
    return all(any(True for _ in Path(folder).glob(f"**/{n}-*.nbi")) for n in names)


def _ready_listener(ready):
    """numba event listener of the lead worker: sets ``ready`` when the outermost compilation
    (numba's compiler lock released: the compiled kernels are in the cache) leaves a time loop
    kernel with a compiled signature."""
    from ..core.compile_events import outermost_listener

    def check(ev):
        if ready.is_set():
            return
        for mod, name in _TIME_LOOPS:
            kernel = getattr(sys.modules.get(mod), name, None)
            if kernel is not None and kernel.signatures:
                ready.set()
                return

    return outermost_listener(check)


def _compile_role():
    """``("lead", (ready, listener))`` when this worker compiles first for the batch (it sets
    ``ready`` when its time loop is cached, or when its seed ends), else ``(None, None)``, after
    waiting for the lead's ``ready`` when another worker leads.  Only a worker's first seed
    takes part."""
    global _compile_once
    if _compile_once is None:
        return None, None
    ready, lead = _compile_once
    _compile_once = None  # only the first seed of a worker takes part
    if ready.is_set():
        return None, None
    if lead.acquire(block=False):  # never released: one lead per batch
        try:
            from numba.core import event
            listener = _ready_listener(ready)
            event.register("numba:compiler_lock", listener)
        except BaseException:
            ready.set()  # the others compile for themselves
            raise
        return "lead", (ready, listener)
    ready.wait(_WAIT_MAX)
    return None, None


def _storm_progress(seed: int):
    """Progress of one storm with finite-element lines: a line on stderr per 5 % of the
    simulated time, naming the seed (several workers interleave their lines)."""
    t0 = time.perf_counter()

    def report(t, t_end):
        print(f"  seed {seed}: {100.0 * t / t_end:3.0f} % ({t:.0f} of {t_end:.0f} s simulated, "
              f"{time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)
    return report


def _run_one(scene_path: str, seed: int, out_path: str, overrides: dict,
             fingerprint: str = "", threads=None, thread_cap: int = 1) -> SeedOutcome:
    """Worker: simulate one seed and write it (temp file + rename); ``threads`` (None: the
    scene's) at most ``thread_cap``."""
    import warnings

    import numpy as np

    from ..core.errors import FloatmoorWarning
    from ..io.scene import load_scene
    from .simulate import simulate

    out = Path(out_path)
    err_file = out.with_suffix(".error.txt")
    role, lead = _compile_role()
    t0 = time.perf_counter()
    try:
        with warnings.catch_warnings():  # the parent has shown the scene's warnings
            warnings.simplefilter("ignore")
            scene = load_scene(scene_path)
        from ..io.solver_section import with_thread_cap
        solver = with_thread_cap(scene.solver, thread_cap, threads)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("ignore")
            warnings.simplefilter("always", FloatmoorWarning)
            ds = simulate(scene, seed=seed, solver=solver, progress=_storm_progress(seed),
                          **overrides)
        messages = tuple(dict.fromkeys(str(w.message) for w in caught
                                       if issubclass(w.category, FloatmoorWarning)))
        if fingerprint:
            ds.attrs[FINGERPRINT_ATTR] = fingerprint
        tmp = temp_name(out)
        need = int(ds.nbytes) + (1 << 16)
        try:
            from .folder_lock import check_free_space
            check_free_space(out.parent, need, out.name)
            ds.to_netcdf(tmp)
            os.replace(tmp, out)
        except BaseException as exc:  # no partial file: interrupted or failed while writing
            tmp.unlink(missing_ok=True)
            if isinstance(exc, Exception):
                full = disk_full_error(exc, out.parent, need, out.name)
                if full is not None:
                    raise full from None
            raise
        if err_file.exists():
            err_file.unlink()
        an = ds.attrs
        sel = ds["time"].values >= an.get("transient", 0.0)
        m = ds["motion"].values[sel]
        summary = {"max_offset": float(np.hypot(m[:, 0], m[:, 1]).max())}
        if "line_tension" in ds:
            summary["max_tension"] = float(ds["line_tension"].values[sel].max())
        return SeedOutcome(seed, "done", out, wall_time=time.perf_counter() - t0,
                           summary=summary, warnings=messages)
    except Exception as exc:  # keep the batch going; record the error
        full = isinstance(exc, DiskFull)
        text = exc.strerror if full else f"{type(exc).__name__}: {exc}"
        try:
            if not full:
                err_file.write_text(text + "\n\n" + traceback.format_exc())
        except OSError:
            pass
        return SeedOutcome(seed, "failed", out, error=text, wall_time=time.perf_counter() - t0,
                           disk_full=full)
    finally:
        if role == "lead":  # also when the seed failed: the others compile for themselves
            from numba.core import event
            ready, listener = lead
            event.unregister("numba:compiler_lock", listener)
            ready.set()


def run_seeds(scene_path, seeds, out_dir, *, workers: int | None = None, overrides=None,
              echo=print, progress: bool | None = None, force: bool = False,
              in_process: bool | None = None, threads=None) -> BatchResult:
    """Run ``seeds`` of the scene file ``scene_path`` into ``out_dir``.

    Parameters
    ----------
    scene_path : path of the scene file (the workers read it themselves).
    seeds : iterable of int.
    out_dir : folder for the per-seed netCDF files (created).
    workers : processes (default: the CPUs available to this process); 1 runs in-process.
    overrides : dict of :func:`floatmoor.simulate` keywords (duration, dt, ...).
    echo : function printing one progress line per finished seed (None: quiet).
    progress : use a tqdm bar (default: when tqdm is installed and stderr is a terminal).
    force : recompute seeds whose files came from different inputs (default: refuse).
    in_process : run the seeds in this process (default: when ``workers`` is 1); otherwise in
        worker processes, which Ctrl-C stops at once (a seed in progress is abandoned).
    threads : threads of the FE lines per seed, a positive integer or ``"auto"`` (default: the
        scene's ``solver.threads``); at most the cores divided among the worker processes.

    Returns
    -------
    BatchResult
        One :class:`SeedOutcome` per seed, in seed order.

    Raises
    ------
    SceneError
        A bad scene file (or a file it reads: vessel, database, mooring), a scene that fails
        its plausibility checks, or a duration not longer than the transient (all before any
        seed runs); files in ``out_dir`` computed from other inputs (unless ``force``), naming
        the sections that differ; ``out_dir`` in use by another batch.
    BatchInterrupted
        Ctrl-C or SIGTERM: the seeds in flight are abandoned and listed in
        ``<out_dir>/interrupted.txt``; a rerun of the same command resumes.
    DiskFull
        No space left on the device: the finished seeds are kept, the others listed in
        ``<out_dir>/interrupted.txt``.
    """
    from ..io.build import build
    from ..io.plausibility import check_built
    from ..io.scene import load_scene
    from .simulate import check_statistics_window

    scene = load_scene(scene_path)  # fail early on a bad scene, in the parent
    overrides = dict(overrides or {})
    an = scene.analysis
    duration = overrides.get("duration")
    transient = overrides.get("transient")
    check_statistics_window(scene.file, float(an.duration if duration is None else duration),
                            float(an.transient if transient is None else transient),
                            key="analysis.duration" if duration is None else "duration")
    import json

    from ..io.analysis import check_time_steps
    from .fingerprint import scene_fingerprint
    check_time_steps(scene.file, float(overrides.get("duration", an.duration)),
                     float(overrides.get("dt", an.dt)),
                     key="analysis.dt" if "dt" not in overrides else "dt")
    if "dt" in overrides:   # the scene's own dt was checked when it was read
        from ..io.checks import check_dt_resolves_waves
        check_dt_resolves_waves(scene.file, "dt (--dt)", float(overrides["dt"]),
                                scene.environment.waves)
    # the vessel, database and mooring read and checked here, once: a mistake in them (a mass
    # of 0, a line above its MBS at zero offset, ...) is a SceneError before any seed starts,
    # not the same failure in every worker
    built = build(scene)
    check_built(built)
    fe_lines = bool(getattr(getattr(built.mooring, "line_models", None), "any_finite_element",
                            False))
    fp = scene_fingerprint(scene, overrides)
    fp_text = json.dumps(fp, sort_keys=True)
    out_dir = Path(out_dir)
    seeds = [int(s) for s in seeds]
    with folder_lock(out_dir, f"floatmoor run {Path(scene_path).name}"):
        return _run_locked(scene, scene_path, seeds, out_dir, fp, fp_text, overrides, echo,
                           progress, force, in_process, threads, workers, fe_lines)


def _run_locked(scene, scene_path, seeds, out_dir, fp, fp_text, overrides, echo, progress,
                force, in_process, threads, workers, fe_lines) -> BatchResult:
    """:func:`run_seeds` with the folder locked."""
    from .fingerprint import differing_keys
    if (out_dir / "campaign.json").is_file() and not force:
        raise SceneError(scene.file, "", f"an output folder for the seeds of a scene "
                         f"({out_dir})", "the folder of a campaign (campaign.json)",
                         "use another --out folder (or --force)")
    outcomes: dict[int, SeedOutcome] = {}
    todo = []
    foreign: dict[int, list[str]] = {}
    for s in seeds:
        path = seed_file(out_dir, scene.name, s)
        for stale in path.parent.glob(path.name + ".*tmp"):  # left by a killed run
            if stale.is_file():
                stale.unlink(missing_ok=True)
        if path.exists():
            try:
                stored = check_result_file(path)
            except Exception as exc:  # truncated, corrupted, not netCDF: compute it again
                if echo and isinstance(exc, SceneError):
                    echo(f"seed {s}: {path.name} holds values no finished run writes "
                         f"({exc.key}: expected {exc.expected}, found {exc.found}), computing "
                         "it again")
                elif echo:
                    echo(f"seed {s}: {path.name} is unreadable or incomplete "
                         f"({type(exc).__name__}), computing it again")
                todo.append((s, path))
                continue
            diff = differing_keys(stored or {}, fp) if stored is not None else ["(no fingerprint)"]
            if diff:
                foreign[s] = diff
                if force:
                    if echo:
                        echo(f"seed {s}: {path.name} came from other inputs "
                             f"({', '.join(diff)}), computing it again (--force)")
                    todo.append((s, path))
                continue
            outcomes[s] = SeedOutcome(s, "skipped", path)
            if echo:
                echo(f"seed {s}: already done ({path.name}), skipped")
        else:
            todo.append((s, path))
    if foreign and not force:
        keys = sorted({k for v in foreign.values() for k in v})
        first = min(foreign)
        raise SceneError(scene.file, "", f"a results folder holding results of this scene "
                         f"and models only ({out_dir})", SceneError.NOT_APPLICABLE,
                         hint=f"{len(foreign)} result file(s) there (e.g. seed {first}) were "
                              f"computed from other inputs; they differ in: {', '.join(keys)}"
                              + ("" if keys != ["code"] else " (floatmoor or its numerical "
                                 "libraries were updated since)")
                              + "; use another --out folder, or --force to compute those "
                              "seeds again")

    if workers is None:
        try:
            workers = len(os.sched_getaffinity(0))
        except AttributeError:  # pragma: no cover - not Linux
            workers = os.cpu_count() or 1
    workers = max(1, min(int(workers), len(todo) or 1))
    bar = None
    if progress is None:
        progress = sys.stderr.isatty()
    if progress and todo:
        try:
            from tqdm import tqdm
            bar = tqdm(total=len(todo), unit="seed")
        except ImportError:
            bar = None
    done_count = 0

    def report(o: SeedOutcome):
        nonlocal done_count
        done_count += 1
        outcomes[o.seed] = o
        if bar is not None:
            bar.update(1)
        if echo:
            head = f"[{done_count}/{len(todo)}] seed {o.seed}: "
            if o.status == "done":
                extra = ", ".join(f"{k} {v / 1e3:.0f} kN" if k == "max_tension" else
                                  f"{k} {v:.2f} m" for k, v in o.summary.items())
                echo(head + f"done in {o.wall_time:.1f} s ({extra}) -> {o.path.name}")
                for text in o.warnings:
                    echo(f"    warning (seed {o.seed}): {text}")
            else:
                echo(head + f"FAILED: {o.error}")

    src = os.fspath(Path(scene_path).resolve())
    if in_process is None:
        in_process = workers == 1
    from ..io.solver_section import worker_thread_cap
    cap = worker_thread_cap(1 if in_process else workers)
    run_kw = {"threads": threads, "thread_cap": cap}
    record = out_dir / "interrupted.txt"
    running: set[int] = set()
    if todo and echo and not _time_loop_cached(fe_lines):
        echo("compiling the time loop" + (" with its finite-element lines" if fe_lines else "")
             + " (numba, once per installation and update of floatmoor: "
             + ("about 2-3 minutes" if fe_lines else "10-20 s")
             + " before the first seed; `floatmoor compile` does it ahead)")
    full: SeedOutcome | None = None
    with _interrupts_as_keyboard_interrupt():
        try:
            if in_process:
                for s, path in todo:
                    running = {s}
                    o = _run_one(src, s, os.fspath(path), overrides, fp_text, **run_kw)
                    if o.disk_full:
                        full = o
                        break
                    report(o)
                running = set()
            elif todo:
                mp_ctx = _worker_context()
                init_args = ()
                if workers > 1 and len(todo) > 1 and not _time_loop_cached(fe_lines):
                    import multiprocessing
                    ctx = mp_ctx if mp_ctx is not None else multiprocessing.get_context()
                    init_args = (ctx.Event(), ctx.Lock())
                pool = ProcessPoolExecutor(max_workers=workers, initializer=_worker_init,
                                           initargs=init_args, mp_context=mp_ctx)
                try:
                    with _deferred_interrupts() as stop:
                        futs = {pool.submit(_run_one, src, s, os.fspath(path), overrides,
                                            fp_text, **run_kw): (s, path) for s, path in todo}
                        running = {s for s, _ in todo}
                        pending = set(futs)
                        while pending:
                            stop.check()
                            done, pending = wait(pending, timeout=0.2,
                                                 return_when=FIRST_COMPLETED)
                            for fut in sorted(done, key=lambda f: futs[f][0]):
                                s, path = futs[fut]
                                if fut.cancelled():
                                    continue
                                try:
                                    o = fut.result()
                                except Exception as exc:  # worker died (e.g. killed): go on
                                    o = SeedOutcome(s, "failed", path,
                                                    error=f"worker failed: {exc!r}")
                                running.discard(s)
                                if o.disk_full:
                                    # every other seed would fail the same way: stop here
                                    full = full or o
                                    for f in futs:
                                        f.cancel()
                                    continue
                                report(o)
                        stop.check()
                except KeyboardInterrupt:
                    _stop_pool(pool)
                    raise
                else:
                    pool.shutdown(wait=True)
        except KeyboardInterrupt:
            if bar is not None:
                bar.close()
            left = _abandon(todo, outcomes, out_dir, scene, record,
                            "seeds not computed (interrupted; run the same command again to "
                            "compute them)")
            raise BatchInterrupted([outcomes[s] for s in seeds if s in outcomes], left,
                                   record) from None
    if bar is not None:
        bar.close()
    if full is not None:
        left = _abandon(todo, outcomes, out_dir, scene, record,
                        "seeds not computed (the disk is full; free some space and run the "
                        "same command again to compute them)")
        done = sum(1 for o in outcomes.values() if o.status in ("done", "skipped"))
        raise DiskFull(out_dir, f"{full.error}; {done} seed(s) finished and kept, "
                       f"{len(left)} not computed (listed in {record}); free some space and "
                       "run the same command again to compute them")
    record.unlink(missing_ok=True)
    return BatchResult(tuple(outcomes[s] for s in seeds))


def _abandon(todo, outcomes, out_dir, scene, record, title) -> list[int]:
    """The seeds of ``todo`` left without a result (their temporary files removed), written
    to ``record``; a seed whose file exists was finished (written whole, then renamed) even
    when its outcome had not reached this process yet."""
    left = sorted(s for s, path in todo if s not in outcomes and not path.is_file())
    for s, path in todo:
        if s not in outcomes and path.is_file():
            outcomes[s] = SeedOutcome(s, "done", path)
    for s in left:
        p = seed_file(out_dir, scene.name, s)
        for tmp in p.parent.glob(p.name + ".*tmp"):
            if tmp.is_file():
                tmp.unlink(missing_ok=True)
    record.write_text(title + ":\n" + "\n".join(str(s) for s in left) + "\n")
    return left


def _stop_pool(pool) -> None:
    """Stop a ProcessPoolExecutor now: cancel queued seeds, terminate the running workers."""
    procs = list((getattr(pool, "_processes", None) or {}).values())
    for p in procs:
        try:
            p.terminate()
        except Exception:  # pragma: no cover - already gone
            pass
    pool.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        try:
            p.terminate()
        except Exception:  # pragma: no cover - already gone
            pass
    for p in procs:
        p.join(timeout=5.0)


class _deferred_interrupts:
    """Within the block (main thread only), Ctrl-C and SIGTERM set a flag that :meth:`check`
    turns into KeyboardInterrupt where the batch loop asks, between its waits for the workers.

    Raised asynchronously, the KeyboardInterrupt could land inside ``concurrent.futures``'
    waits: ``as_completed`` takes the locks of all futures one by one, and an exception
    between two of them leaves a lock held, on which the pool's manager thread then blocks for
    ever.  A batch once ignored Ctrl-C that way (no "interrupted" message, still running 30 s
    later; ``tests/test_run_interrupt.py`` on a loaded machine, 2026-11-27).  A second Ctrl-C
    while the flag is set raises at once, as before."""

    def __enter__(self):
        import signal
        import threading
        self._set = False
        self._old = {}
        if threading.current_thread() is threading.main_thread():
            def handler(signum, frame):
                if self._set:
                    raise KeyboardInterrupt
                self._set = True
            for sig in (signal.SIGINT, signal.SIGTERM):
                self._old[sig] = signal.signal(sig, handler)
        return self

    def check(self) -> None:
        if self._set:
            raise KeyboardInterrupt

    def __exit__(self, *exc):
        import signal
        for sig, old in self._old.items():
            signal.signal(sig, old)
        return False


class _interrupts_as_keyboard_interrupt:
    """Within the block, SIGTERM raises KeyboardInterrupt like Ctrl-C (main thread only)."""

    def __enter__(self):
        import signal
        import threading
        self._old = None
        if threading.current_thread() is threading.main_thread():
            def handler(signum, frame):
                raise KeyboardInterrupt
            self._old = signal.signal(signal.SIGTERM, handler)
        return self

    def __exit__(self, *exc):
        import signal
        if self._old is not None:
            signal.signal(signal.SIGTERM, self._old)
        return False
