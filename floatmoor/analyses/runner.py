"""Many seeds of one scene, in parallel on the local cores, resumable, failure-tolerant.

:func:`run_seeds` writes one netCDF file per seed, ``<out>/<scene name>_seed<NNNN>.nc``:

* seeds run in worker processes (:class:`concurrent.futures.ProcessPoolExecutor`), one seed per
  task; a line is printed per finished seed (a tqdm bar when tqdm is installed and the output is
  a terminal);
* a seed whose file already exists is skipped (resume an interrupted batch by running the same
  command again); files are written to ``*.nc.tmp`` and renamed when complete, so a file that
  exists is complete;
* a failing seed never stops the others: its error is written to ``<name>_seed<NNNN>.error.txt``
  and reported at the end (and the file is removed when that seed later succeeds).
"""

from __future__ import annotations

import os
import sys
import time
import traceback
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["run_seeds", "SeedOutcome", "BatchResult", "seed_file"]


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


def _run_one(scene_path: str, seed: int, out_path: str, overrides: dict) -> SeedOutcome:
    """Worker: simulate one seed and write it (temp file + rename)."""
    import warnings

    import numpy as np

    from ..core.errors import FloatmoorWarning
    from ..io.scene import load_scene
    from .simulate import simulate

    out = Path(out_path)
    err_file = out.with_suffix(".error.txt")
    t0 = time.perf_counter()
    try:
        with warnings.catch_warnings():  # the parent has shown the scene's warnings
            warnings.simplefilter("ignore")
            scene = load_scene(scene_path)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("ignore")
            warnings.simplefilter("always", FloatmoorWarning)
            ds = simulate(scene, seed=seed, **overrides)
        messages = tuple(dict.fromkeys(str(w.message) for w in caught
                                       if issubclass(w.category, FloatmoorWarning)))
        tmp = out.with_name(out.name + ".tmp")
        ds.to_netcdf(tmp)
        os.replace(tmp, out)
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
        text = f"{type(exc).__name__}: {exc}"
        try:
            err_file.write_text(text + "\n\n" + traceback.format_exc())
        except OSError:
            pass
        return SeedOutcome(seed, "failed", out, error=text, wall_time=time.perf_counter() - t0)


def run_seeds(scene_path, seeds, out_dir, *, workers: int | None = None, overrides=None,
              echo=print, progress: bool | None = None) -> BatchResult:
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

    Returns
    -------
    BatchResult
        One :class:`SeedOutcome` per seed, in seed order.

    Raises
    ------
    SceneError
        A bad scene file, or a duration not longer than the transient (before any seed runs).
    """
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
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    seeds = [int(s) for s in seeds]
    outcomes: dict[int, SeedOutcome] = {}
    todo = []
    for s in seeds:
        path = seed_file(out_dir, scene.name, s)
        if path.exists():
            outcomes[s] = SeedOutcome(s, "skipped", path)
            if echo:
                echo(f"seed {s}: already done ({path.name}), skipped")
        else:
            todo.append((s, path))
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
    if workers == 1:
        for s, path in todo:
            report(_run_one(src, s, os.fspath(path), overrides))
    elif todo:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            futs = {pool.submit(_run_one, src, s, os.fspath(path), overrides): (s, path)
                    for s, path in todo}
            for fut in as_completed(futs):
                s, path = futs[fut]
                try:
                    o = fut.result()
                except Exception as exc:  # worker died (e.g. killed): record, go on
                    o = SeedOutcome(s, "failed", path, error=f"worker failed: {exc!r}")
                report(o)
    if bar is not None:
        bar.close()
    return BatchResult(tuple(outcomes[s] for s in seeds))
