"""``floatmoor run SCENE.yaml --seeds 1-20 --out DIR``: time-domain storms, one netCDF per seed.

Seeds run in parallel on the local cores (worker processes); the scene and the files it reads
are checked before any seed starts (a mistake in them: exit status 2); a seed whose file
exists, is readable, holds finite and plausible values and was computed from the same inputs
(the fingerprint of scene, files and code stored in it) is skipped (resumable); files from
other inputs are refused (exit status 2 naming the differing sections) unless ``--force``; an
unreadable, truncated or corrupted file is computed again; a failed seed is reported and the
others go on (exit status 3 naming the failed seeds).  The output folder is locked while the
run writes into it: a second run into it is refused (exit status 2).  A full disk stops the
run with a message saying so (exit status 2; the finished seeds are kept).  Ctrl-C
or SIGTERM stops the workers at once, keeps only complete files, lists the seeds not computed
in ``interrupted.txt``, prints the command that resumes, and exits with status 130.  At the
end a short table of the finished seeds: mean, std and max of the horizontal offset and of the
tensions of the most loaded lines, over the statistics window (after ``analysis.transient``).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .argtypes import check_out_dir, positive_float, positive_int, thread_count

HELP = "time-domain storm simulation of seeds in parallel (one netCDF file per seed)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor run``."""
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file")
    p.add_argument("--seeds", default=None, metavar="LIST",
                   help='seeds, e.g. "1-20", "3,7,11", "1-5,9" (default: analysis.seeds)')
    p.add_argument("--out", default=None, metavar="DIR",
                   help="output folder (default: results/<scene name> next to the scene file)")
    p.add_argument("--force", action="store_true",
                   help="recompute seeds whose files in --out came from other inputs (default: "
                        "refuse to mix the results of two scenes in one folder)")
    p.add_argument("--workers", type=positive_int, default=None, metavar="N",
                   help="parallel processes (default: the local cores)")
    p.add_argument("--duration", type=positive_float, default=None, metavar="S",
                   help="simulated length in s (default: analysis.duration)")
    p.add_argument("--dt", type=positive_float, default=None, metavar="S",
                   help="time step in s (default: analysis.dt)")
    p.add_argument("--lines", type=positive_int, default=3, metavar="N",
                   help="most loaded lines shown in the table (default 3)")
    p.add_argument("--threads", type=thread_count, default=None, metavar="N",
                   help="threads advancing the finite-element lines of each seed, N or auto "
                        "(default: the scene's solver.threads, else 1); at most the cores "
                        "divided by the workers; results are identical")


def summary_table(files, n_lines: int = 3) -> str:
    """Table of mean, std and max of the offset and the most loaded line tensions (window after
    the transient), averaged over the seeds (max: mean of the seed maxima and the largest)."""
    import numpy as np
    import xarray as xr

    rows: dict[str, list] = {}
    for f in files:
        with xr.open_dataset(f) as ds:
            t = ds["time"].values
            sel = t >= float(ds.attrs.get("transient", 0.0))
            m = ds["motion"].values[sel]
            off = np.hypot(m[:, 0], m[:, 1])
            rows.setdefault("offset (m)", []).append((off.mean(), off.std(), off.max(), 1.0))
            if "line_tension" in ds:
                T = ds["line_tension"].values[sel] / 1e3
                for i, name in enumerate(ds["line"].values):
                    rows.setdefault(f"{name} tension (kN)", []).append(
                        (T[:, i].mean(), T[:, i].std(), T[:, i].max(), 1.0))
    if not rows:
        return "no finished seeds"
    lines_keys = [k for k in rows if k != "offset (m)"]
    # by the max as printed (0.1 kN), lines equal to it in the scene's order: mirror-image
    # lines differ only by round-off, which must not decide the order of the table
    lines_keys.sort(key=lambda k: -round(float(np.mean([r[2] for r in rows[k]])), 1))
    keys = ["offset (m)"] + lines_keys[:n_lines]
    n = len(files)
    out = [f"statistics over {n} seed{'s' if n != 1 else ''} (after the transient)",
           f"{'':24s}{'mean':>10s}{'std':>10s}{'max':>10s}" + (f"{'max all':>10s}" if n > 1 else "")]
    for k in keys:
        r = np.array(rows[k])
        line = f"{k:24s}{r[:, 0].mean():10.1f}{r[:, 1].mean():10.1f}{r[:, 2].mean():10.1f}"
        if n > 1:
            line += f"{r[:, 2].max():10.1f}"
        out.append(line)
    return "\n".join(out)


def run(args: argparse.Namespace) -> int:
    """Run ``floatmoor run``; returns the exit status."""
    from ..cli import EXIT_INTERRUPTED, EXIT_OK, UsageError
    from ..io.analysis import seeds_from_text
    from ..io.scene import load_scene

    scene = load_scene(args.scene)
    if args.seeds is None:
        seeds = scene.analysis.seeds
    else:
        try:
            seeds = seeds_from_text(args.seeds)
        except ValueError as exc:
            raise UsageError(f"--seeds {args.seeds[:60]!r}: {exc}") from None
    out = Path(args.out) if args.out else Path(scene.file).parent / "results" / scene.name
    check_out_dir(out)
    overrides = {}
    if args.duration is not None:
        from ..analyses.simulate import check_statistics_window
        check_statistics_window(scene.file, args.duration, scene.analysis.transient,
                                key="--duration")
        overrides["duration"] = args.duration
    if args.dt is not None:
        overrides["dt"] = args.dt
    if overrides:
        from ..io.analysis import check_time_steps
        duration = overrides.get("duration", scene.analysis.duration)
        dt = overrides.get("dt", scene.analysis.dt)
        if not dt < duration:
            raise UsageError(f"--dt {dt:g}: expected a time step shorter than the duration "
                             f"{duration:g} s")
        check_time_steps(scene.file, duration, dt, key="--dt" if args.dt is not None
                         else "--duration")
    print(f"scene: {scene.name}  [{scene.file}]")
    bounds = _fibre_bounds(scene)
    if bounds:
        status = EXIT_OK
        for b in bounds:
            print(f"fibre stiffness bound {b}: {len(seeds)} seed(s) -> {out / ('fibre_' + b)}")
            st = _run_batch(args, seeds, out / f"fibre_{b}", {**overrides, "fibre_stiffness": b},
                            resume_out=out)
            if st == EXIT_INTERRUPTED:
                return st
            status = max(status, st)
        return status
    print(f"{len(seeds)} seed(s) -> {out}")
    return _run_batch(args, seeds, out, overrides)


def _fibre_bounds(scene) -> tuple[str, ...]:
    """``("lower", "upper")`` when the scene asks for both fibre stiffness bounds and its
    mooring has fibre ropes, else ``()`` (one run with the scene's bound)."""
    if scene.analysis.fibre_stiffness != "both" or scene.mooring is None:
        return ()
    from ..io.mooring_section import parse_mooring
    site = scene.site
    ms = parse_mooring(scene.mooring_node(), water_depth=site.water_depth,
                       water_density=site.water_density, gravity=site.gravity)
    return scene.analysis.fibre_bounds if ms.has_fibre else ()


def _run_batch(args, seeds, out, overrides, resume_out=None) -> int:
    """One ``run_seeds`` batch with the table and the exit status of ``floatmoor run``
    (``resume_out``: the ``--out`` of the command that resumes it, default ``out``)."""
    from ..analyses.runner import BatchInterrupted, run_seeds
    from ..cli import EXIT_INTERRUPTED, EXIT_NUMERICAL_ERROR, EXIT_OK
    from .compile_notice import compile_notice
    try:
        # this process checks the scene (statics kernels); the workers say their own compile
        with compile_notice("the statics kernels", echo=lambda s: print(s, flush=True),
                            report_end=False):
            batch = run_seeds(args.scene, seeds, out, workers=args.workers, overrides=overrides,
                              echo=lambda s: print(s, flush=True), force=args.force,
                              in_process=False, threads=args.threads)
    except BatchInterrupted as exc:
        done = [o.seed for o in exc.finished]
        print(f"floatmoor: interrupted: {len(done)} seed(s) finished, {len(exc.interrupted)} "
              f"not computed (listed in {exc.record}); resume with the same command:\n"
              f"  {_resume_command(args, resume_out or out)}",
              file=sys.stderr, flush=True)
        return EXIT_INTERRUPTED
    files = batch.files
    if files:
        print()
        print(summary_table(files, n_lines=args.lines))
    if batch.failed:
        print(f"floatmoor: error: {len(batch.failed)} seed(s) failed: "
              + ", ".join(str(s) for s in batch.failed)
              + f" (errors in {out}/*.error.txt; run again to retry only those)", file=sys.stderr)
        return EXIT_NUMERICAL_ERROR
    return EXIT_OK


def _resume_command(args: argparse.Namespace, out: Path) -> str:
    """The command that resumes an interrupted ``floatmoor run``."""
    import shlex
    words = ["floatmoor", "run", args.scene, "--out", str(out)]
    for flag, value in (("--seeds", args.seeds), ("--duration", args.duration),
                        ("--dt", args.dt), ("--workers", args.workers),
                        ("--threads", args.threads)):
        if value is not None:
            words += [flag, f"{value:g}" if isinstance(value, float) else str(value)]
    return " ".join(shlex.quote(w) for w in words)
