"""Campaign tasks: pure functions of (campaign, case, seed) that write their own result file.

* :func:`run_fd_cases` -- the frequency-domain analysis of a batch of cases, one small netCDF
  per case (``fd/<case>.nc``: static and maximum tensions, MBS, motion maxima).
* :func:`run_storm` -- one time-domain storm of one case, ``td/<case>/seed<NNNN>.nc``.

Both write to ``<file>.tmp`` and rename (a file that exists was written completely), never raise
for a failed case (the outcome carries ``status`` "failed" and the message; a
:class:`~floatmoor.core.errors.NumericalError` of one case never stops the others), and store no
wall-clock time or date in the file, so the same (campaign, case, seed) gives a bit-identical
file on any worker.  The times go to the outcome (and the manifest): ``wall_time_s`` of the
whole task, ``simulate_s`` (storms: the wall time of the ``simulate`` call, the storm's own run
time) and ``solve_s`` (FD: the ``frequency_domain`` call); the rest of a task (case scene,
statistics, writing) is campaign overhead.  The outcome also carries the process CPU times
(``cpu_s``, ``simulate_cpu_s``, ``solve_cpu_s``), the worker's ``pid`` (benchmarks; not in
the manifest) and ``table``: the values the client's screening reads (FD maxima, storm
statistics), as written, so that it does not read every file back.  :func:`warm_worker` loads a worker's caches before its first task.

Storage of a storm (``storage:`` of the campaign file):

* always: per-storm statistics in the window after the transient, computed in float64 from the
  full-rate series -- ``line_tension_max/mean/std/min(line)``, ``anchor_tension_max(line)``,
  ``motion_max/min/mean/std(dof)``, ``offset_max``, ``offset_mean``, ``mbs(line)``, and the
  design statistics of the anchors, fibre ropes, offset limits and points
  (``design_*``, :func:`floatmoor.post.design_statistics.add_design_statistics`);
* ``mode: full``: the series named in ``sampling`` (every ``k``-th time step, ``k = interval /
  dt``; 0 keeps every step), stored as ``precision`` (float32 by default: relative rounding
  error at most 2^-24 = 6.0e-8, i.e. 0.2 N on a 3.3 MN tension and 2 micrometres on a 35 m
  offset) with zlib ``compression`` and the shuffle filter;
* ``mode: statistics``: the statistics only (a few kB per storm); the series of the governing
  cases are rerun bit-identically from their seed at the end of the campaign (``series/``).
"""

from __future__ import annotations

import functools
import hashlib
import os
import time
import traceback
import warnings
from pathlib import Path

import numpy as np

from .store import FD_TABLE_VARS, TD_TABLE_VARS

__all__ = ["check_inputs", "file_digest", "run_fd_cases", "run_storm", "storm_dataset",
           "warm_worker", "write_netcdf"]

_VOLATILE_ATTRS = ("created", "run_time_s", "setup_time_s", "real_time_factor", "scene_file",
                   "run_date_utc")


@functools.lru_cache(maxsize=4)
def _load_base(path: str, stamp: tuple):
    from . import _api
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _api.load_scene(path)


@functools.lru_cache(maxsize=4)
def _environment_file(path: str, base_stat: tuple):
    return _load_base(path, (base_stat,)).environment.source


def _current_base(path: str):
    """The base scene as its files are now: cached while the scene file and the environment
    file it reads are unchanged (the case scenes keep the base environment's spectrum and
    discretisation)."""
    st = _stat(path)
    env = _environment_file(path, st)
    return _load_base(path, (st, _stat(env)) if env else (st,))


def _stat(path) -> tuple:
    try:
        st = os.stat(path)
        return (os.fspath(path), st.st_mtime_ns, st.st_size)
    except OSError:
        return (os.fspath(path), -1, -1)


@functools.lru_cache(maxsize=8)
def _vessel_database(vessel: str, vessel_stat: tuple):
    from ..core.config import Node
    try:
        node = Node.load(vessel)
        return os.fspath(node.path_value("database")) if "database" in node else None
    except Exception:  # noqa: BLE001 - a bad vessel file is reported by the task
        return None


def _inputs_key(base_path: str) -> tuple:
    """The state (path, modification time, size) of the base scene and of every file it reads
    (vessel, database, mooring, line-type library): the key of this worker's caches, so that
    a file edited while a worker lives is read again, never taken from the cache."""
    scene = _current_base(base_path)
    files = [base_path] + ([scene.environment.source] if scene.environment.source else [])
    if scene.vessel is not None:
        files.append(scene.vessel)
        db = _vessel_database(os.fspath(scene.vessel), _stat(scene.vessel))
        if db is not None:
            files.append(db)
    if isinstance(scene.mooring, Path):
        files.append(scene.mooring)
        lib = _library_of(os.fspath(scene.mooring), _stat(scene.mooring))
        if lib is not None:
            files.append(lib)
    return tuple(_stat(f) for f in files)


@functools.lru_cache(maxsize=8)
def _library_of(mooring: str, mooring_stat: tuple):
    from ..analyses.fingerprint import _mooring_library
    return _mooring_library(Path(mooring))


@functools.lru_cache(maxsize=8)
def _file_sections(base_path: str, key: tuple) -> dict:
    from ..analyses.fingerprint import file_sections
    return file_sections(_current_base(base_path))


def check_inputs(base_path: str, fingerprint: str) -> None:
    """SceneError when the files the base scene reads (and the code) differ, in this worker,
    from those the client fingerprinted (``fingerprint``, the task's JSON): a file edited
    while the campaign ran, or a worker with another floatmoor; the result would not be what
    its fingerprint says."""
    if not fingerprint:
        return
    import json

    from ..analyses.fingerprint import differing_keys
    from ..core.errors import SceneError
    fp = json.loads(fingerprint)
    mine = _file_sections(base_path, _inputs_key(base_path))
    theirs = {k: fp[k] for k in mine.keys() | fp.keys()
              if k in ("code", "vessel", "vessel.database", "mooring",
                       "mooring.line_type_library") and k in fp}
    diff = differing_keys(mine, theirs)
    if diff:
        raise SceneError(base_path, "", "the inputs the campaign started with",
                         "changed: " + ", ".join(diff), "a file the base scene reads was "
                         "edited while the campaign ran (or this worker runs another "
                         "floatmoor); rerun the campaign to compute the case with the files "
                         "as they are now")


def _scene_for(base_path: str, case, analysis: dict):
    from .matrix import case_scene
    base = _current_base(base_path)
    return case_scene(base, case, analysis)


@functools.lru_cache(maxsize=32)
def _built_base(path: str, key: tuple, failed: tuple):
    from . import _api
    return _api.build(_current_base(path), failed_lines=list(failed))


def _built_for(base_path: str, case, analysis: dict, failed_override=None):
    """The built scene of ``case``: the vessel and mooring (which depend only on the base
    scene's site, vessel and mooring files and the failed lines) are built once per worker
    process and condition and never used themselves; each task gets the case's scene
    (environment, analysis, forces) and a fresh copy of the mooring, whose catenary solver keeps
    warm-start state (sharing it would make a result depend on the tasks run before it in the
    same process, and break the bit identity between serial and distributed runs)."""
    import copy
    import dataclasses
    scene, failed = _scene_for(base_path, case, analysis)
    if failed_override is not None:
        failed = failed_override
    built = _built_base(base_path, _inputs_key(base_path), tuple(failed or ()))
    mooring = None if built.mooring is None else copy.deepcopy(built.mooring)
    if mooring is not None and case.condition.fibre_bound:
        mooring = mooring.with_fibre_bound(case.condition.fibre_bound)
    return dataclasses.replace(built, scene=scene, mooring=mooring), failed


def warm_worker(base_path: str, analysis: dict) -> dict:
    """Load, once per worker process, what every task needs, before its first task: the
    imports, the base scene and its built vessel and mooring (the caches of :func:`_built_for`)
    and the compiled-kernel caches of the frequency domain and the time loop (a frequency-domain
    analysis of the base scene and a storm of 20 steps, results discarded).  Nothing a task
    reads is changed: the mooring is copied as in every task.  Never raises; returns the wall
    and CPU seconds spent and the process id."""
    import copy
    import dataclasses
    t0, c0 = time.perf_counter(), time.process_time()
    out = {"pid": os.getpid(), "error": ""}
    try:
        from . import _api
        base = _current_base(base_path)
        built = _built_base(base_path, _inputs_key(base_path), ())
        out["scene_s"] = time.perf_counter() - t0
        an = dict(analysis or {})
        dt = float(an.get("dt", base.analysis.dt))
        an.update(duration=20 * dt, dt=dt, transient=0.0, ramp=0.0)
        scene = dataclasses.replace(base, analysis=dataclasses.replace(base.analysis, **an))
        mooring = None if built.mooring is None else copy.deepcopy(built.mooring)
        short = dataclasses.replace(built, scene=scene, mooring=mooring)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            _api.frequency_domain(short)
            _api.simulate(dataclasses.replace(short, mooring=copy.deepcopy(mooring)), seed=1,
                          solver=one_thread(scene))
    except Exception as exc:  # noqa: BLE001 - the tasks report their own errors
        out["error"] = _error_text(exc)
    out["wall_time_s"] = time.perf_counter() - t0
    out["cpu_s"] = time.process_time() - c0
    return out


def file_digest(path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


COMPRESS_MIN_SIZE = 1024
"""Variables of fewer elements (the per-storm statistics, a few numbers per line) are stored
uncompressed: zlib saves nothing on them and its chunked layout costs time per variable."""


def _local_write_lock():
    """A context in which xarray writes a netCDF file under a process-local lock.

    Inside a Dask worker xarray finds the worker's client and takes a ``distributed.Lock`` for
    the file: two messages through the scheduler for every variable and attribute written
    (about 100 per storm file), 0.2-0.5 s per task measured in a LocalCluster worker against
    0.03 s for the same write in one process.  Each task writes its own file, so no lock across
    processes is needed; with the ``synchronous`` scheduler configured xarray takes its
    threading lock.  The bytes written are the same.  (In a worker of several threads two
    writes may interleave their config changes: a write may then take the distributed lock again,
    slower and otherwise the same, or the setting may stay, which only a Dask computation inside
    a task would see; the campaign's tasks do none.)"""
    try:
        import dask
    except ImportError:
        import contextlib
        return contextlib.nullcontext()
    return dask.config.set(scheduler="synchronous")


def write_netcdf(ds, path: Path, *, compression: int = 4) -> dict:
    """Write ``ds`` atomically (temp file of this process + rename), zlib/shuffle on the
    variables of :data:`COMPRESS_MIN_SIZE` elements or more; returns size and digest.  A full
    disk raises :class:`~floatmoor.analyses.folder_lock.DiskFull` (the netCDF library's own
    error does not say so); no partial file is left."""
    from ..analyses.folder_lock import disk_full_error, temp_name
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    enc = {}
    for k, v in ds.variables.items():
        if v.dtype.kind in "fiu" and compression > 0 and v.size >= COMPRESS_MIN_SIZE:
            enc[k] = {"zlib": True, "complevel": int(compression), "shuffle": True}
    tmp = temp_name(path)
    try:
        with _local_write_lock():
            ds.to_netcdf(tmp, engine="netcdf4", encoding=enc)
        digest = file_digest(tmp)
        size = tmp.stat().st_size
        os.replace(tmp, path)
    except Exception as exc:
        tmp.unlink(missing_ok=True)
        full = disk_full_error(exc, path.parent, int(ds.nbytes) // (4 if enc else 1),
                               path.name)
        if full is not None:
            raise full from None
        raise
    return {"bytes": size, "sha256": digest}


def _outcome(kind, case, seed, path, status, t0, error="", extra=None, c0=None):
    out = {"kind": kind, "case": case.id, "seed": seed, "status": status,
           "wall_time_s": time.perf_counter() - t0, "path": os.fspath(path), "error": error,
           "pid": os.getpid()}
    if c0 is not None:
        out["cpu_s"] = time.process_time() - c0
    out.update(extra or {})
    return out


def _table(ds, names) -> dict:
    """The variables ``names`` of a written dataset, as written (the client screens with them
    without reading the file back)."""
    return {k: np.asarray(ds[k].values) for k in names if k in ds.variables}


def _error_text(exc) -> str:
    from ..analyses.folder_lock import DiskFull
    if isinstance(exc, DiskFull):
        return f"DiskFull: {exc.strerror}"
    return f"{type(exc).__name__}: {exc}".replace("\n", " ")


def _failure_extra(exc) -> dict:
    from ..analyses.folder_lock import DiskFull
    out = {"traceback": traceback.format_exc()}
    if isinstance(exc, DiskFull):
        out["disk_full"] = True
    return out


# -- frequency domain ---------------------------------------------------------------------------
_FD_VARS = ("tension_static", "tension_max_total", "mbs", "line_failed", "mean", "max_total",
            "min_total")


def _fd_dataset(fd, case):
    import xarray as xr
    ds = xr.Dataset({k: fd[k] for k in _FD_VARS})
    ds.attrs = {"case": case.id, **{k: (str(v) if isinstance(v, str) else float(v))
                                    for k, v in case.row().items() if k != "case"}}
    for k in ("drift_method", "tension_model", "duration", "line_current_drag", "line_damping"):
        ds.attrs[f"fd_{k}"] = fd.attrs[k]
    return ds


def run_fd_cases(base_path: str, cases, analysis: dict, out_dir: str, compression: int = 4,
                 fingerprints: dict | None = None):
    """Frequency-domain analysis of each case in ``cases`` into ``out_dir/fd/<case>.nc``.

    A transient condition (line breaking during the storm) is screened with the mooring after
    the failure (the frequency domain has no transient).  ``fingerprints`` maps a case id to
    the JSON input fingerprint stored in its file (the inputs are checked against it first,
    :func:`check_inputs`).  Returns one outcome dict per case."""
    from ..analyses.fingerprint import FINGERPRINT_ATTR
    from . import _api
    results = []
    for case in cases:
        t0, c0 = time.perf_counter(), time.process_time()
        path = Path(out_dir) / "fd" / f"{case.id}.nc"
        fp = (fingerprints or {}).get(case.id, "")
        try:
            check_inputs(base_path, fp)
            failed = list(case.condition.lines) if case.condition.kind == "transient" else None
            built, _ = _built_for(base_path, case, analysis, failed)
            t_solve, c_solve = time.perf_counter(), time.process_time()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                fd = _api.frequency_domain(built)
            t_solve, c_solve = time.perf_counter() - t_solve, time.process_time() - c_solve
            ds = _fd_dataset(fd, case)
            if fp:
                ds.attrs[FINGERPRINT_ATTR] = fp
            info = write_netcdf(ds, path, compression=compression)
            info.update(solve_s=t_solve, solve_cpu_s=c_solve, table=_table(ds, FD_TABLE_VARS))
            results.append(_outcome("fd", case, -1, path, "done", t0, extra=info, c0=c0))
        except Exception as exc:  # noqa: BLE001 - recorded; the campaign goes on
            results.append(_outcome("fd", case, -1, path, "failed", t0, _error_text(exc),
                                    _failure_extra(exc), c0))
    return results


# -- time domain --------------------------------------------------------------------------------
def _stats(ds, transient: float) -> dict:
    """Statistics in the window ``time >= transient``: one contiguous (variable, time) copy per
    series, reduced along time (a third of the time of reducing the (time, variable) layout)."""
    t = ds["time"].values
    i0 = int(np.searchsorted(t, transient, side="left"))   # time is increasing
    out = {}
    if "line_tension" in ds:
        T = np.ascontiguousarray(ds["line_tension"].values[i0:].T)
        out["line_tension_max"] = (("line",), T.max(axis=1), "N", "maximum fairlead tension")
        out["line_tension_min"] = (("line",), T.min(axis=1), "N", "minimum fairlead tension")
        out["line_tension_mean"] = (("line",), T.mean(axis=1), "N", "mean fairlead tension")
        out["line_tension_std"] = (("line",), T.std(axis=1), "N", "std of the fairlead tension")
        out["line_tension_time_of_max"] = (("line",), t[i0:][T.argmax(axis=1)], "s",
                                           "time of the maximum fairlead tension")
        A = np.ascontiguousarray(ds["anchor_tension"].values[i0:].T)
        out["anchor_tension_max"] = (("line",), A.max(axis=1), "N", "maximum anchor tension")
    m = np.ascontiguousarray(ds["motion"].values[i0:].T)
    units = ds["motion"].attrs.get("units", "")
    out["motion_max"] = (("dof",), m.max(axis=1), units, "maximum of the motion")
    out["motion_min"] = (("dof",), m.min(axis=1), units, "minimum of the motion")
    out["motion_mean"] = (("dof",), m.mean(axis=1), units, "mean of the motion")
    out["motion_std"] = (("dof",), m.std(axis=1), units, "std of the motion")
    off = np.hypot(m[0], m[1])
    out["offset_max"] = ((), off.max(), "m", "maximum horizontal offset")
    out["offset_mean"] = ((), off.mean(), "m", "mean horizontal offset")
    return out


def storm_dataset(ds, case, seed: int, storage, transient: float, keep_series: bool):
    """The stored form of one storm: statistics always, series when ``keep_series``."""
    import xarray as xr
    data = {k: (dims, np.asarray(v, np.float64), {"units": u, "long_name": f"{ln} (after the "
                                                  "transient)"})
            for k, (dims, v, u, ln) in _stats(ds, transient).items()}
    coords = {"dof": ds["dof"]}
    if "line" in ds.coords:
        coords["line"] = ds["line"]
        data["mbs"] = ds["mbs"]
    dt = float(ds.attrs["dt"])
    if keep_series:
        dtype = np.float32 if storage.precision == "float32" else np.float64
        for var, interval in storage.sampling:
            if var not in ds:
                continue
            k = max(1, round(interval / dt)) if interval > 0 else 1
            da = ds[var].isel(time=slice(None, None, k))
            tname = f"time_{var}"
            da = da.rename({"time": tname})
            coords[tname] = (tname, da[tname].values,
                             {"units": "s", "long_name": f"time of the {var} samples "
                              f"(every {k} step(s) of {dt:g} s)"})
            attrs = dict(ds[var].attrs)
            if dtype == np.float32:
                attrs["precision_note"] = ("stored as float32: relative rounding error <= "
                                           "6.0e-8; statistics use the float64 values")
            data[var] = (da.dims, da.values.astype(dtype), attrs)
    out = xr.Dataset(data, coords=coords)
    attrs = {k: v for k, v in ds.attrs.items() if k not in _VOLATILE_ATTRS and k != "scene"}
    attrs.update({"case": case.id, "seed": int(seed), "transient": float(transient),
                  "storage_mode": "full" if keep_series else "statistics",
                  "storage_precision": storage.precision,
                  "floatmoor_campaign_file": 1})
    for k, v in case.row().items():
        if k != "case":
            attrs[f"case_{k}"] = v
    out.attrs = {k: (list(v) if isinstance(v, tuple) else v) for k, v in attrs.items()}
    return out


def one_thread(scene):
    """The scene's ``solver`` options with one thread for the FE lines: a campaign runs one
    storm per single-threaded worker process (parallel over storms), so a task never starts
    threads of its own (results are the same: the threads are bit-identical)."""
    from ..io.solver_section import with_thread_cap
    return with_thread_cap(getattr(scene, "solver", None), 1)


def run_storm(base_path: str, case, seed: int, analysis: dict, storage, out_path: str,
              keep_series: bool | None = None, fingerprint: str = "") -> dict:
    """Simulate one storm (``case``, ``seed``) and write ``out_path`` with the JSON input
    ``fingerprint`` (the inputs checked against it first, :func:`check_inputs`); never
    raises."""
    from ..analyses.fingerprint import FINGERPRINT_ATTR
    from ..core.errors import FloatmoorWarning
    from . import _api
    t0, c0 = time.perf_counter(), time.process_time()
    keep = storage.mode == "full" if keep_series is None else keep_series
    try:
        check_inputs(base_path, fingerprint)
        built, failed = _built_for(base_path, case, analysis)
        scene = built.scene
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("ignore")
            warnings.simplefilter("always", FloatmoorWarning)
            t_sim, c_sim = time.perf_counter(), time.process_time()
            ds = _api.simulate(built, seed=int(seed), solver=one_thread(scene))
            sim_time = time.perf_counter() - t_sim   # the storm's own run time
            sim_cpu = time.process_time() - c_sim
        transient = float(scene.analysis.transient)
        out = storm_dataset(ds, case, seed, storage, transient, keep)
        from ..post.design_statistics import add_design_statistics  # anchors, ropes, offsets
        add_design_statistics(out, ds, built.mooring, start=transient,
                              limits=getattr(scene, "limits", None), failed=failed or ())
        if failed:
            out.attrs["failed_lines"] = list(failed)
        if fingerprint:
            out.attrs[FINGERPRINT_ATTR] = fingerprint
        info = write_netcdf(out, Path(out_path), compression=storage.compression)
        info.update(simulate_s=sim_time, simulate_cpu_s=sim_cpu,
                    table=_table(out, TD_TABLE_VARS))
        info["warnings"] = " | ".join(dict.fromkeys(str(w.message) for w in caught))
        return _outcome("td" if keep_series is None else "series", case, int(seed), out_path,
                        "done", t0, extra=info, c0=c0)
    except Exception as exc:  # noqa: BLE001 - NumericalError and the rest: recorded
        return _outcome("td" if keep_series is None else "series", case, int(seed), out_path,
                        "failed", t0, _error_text(exc), _failure_extra(exc), c0)
