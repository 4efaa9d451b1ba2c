"""``floatmoor lines SCENE.yaml --motion RESULTS_seed0001.nc``: decoupled dynamic analysis of the
scene's mooring lines (Wang (2016) chapter 8: SIMO motions into RIFLEX).

The recorded body motion of a previous ``floatmoor run`` seed (``motion(time, dof)``), or a
harmonic motion given with ``--harmonic``, drives finite-element models of the lines (options
from the scene's ``mooring.finite_element`` mapping, whatever model the lines use in the
coupled run; the current of the scene's environment and the drag and added-mass coefficients
of its line types, as a coupled run with FE lines uses them:
:func:`floatmoor.mooring.fe.body.scene_line_inputs`).  Printed per line over the statistics
window: mean, standard deviation and maximum of the fairlead tension FE and quasi-static
(elastic catenary along the same fairlead track), the dynamic amplification factor
DAF = (T_max - T_mean)_FE / (T_max - T_mean)_QS (Wang (2016) eq. 8.1), the maximum tension along
the line and the range of the grounded length.  All series and statistics are written to a
netCDF file with units.

Examples::

    floatmoor lines scenes/oc3_hywind.yaml --motion results/oc3/seed0001.nc --lines line1
    floatmoor lines scenes/oc3_hywind.yaml --harmonic surge:3:15 --duration 120
    floatmoor lines scenes/oc3_hywind.yaml --harmonic sway:1:5,sway:3:15 --out sway.nc

``--harmonic`` takes ``DOF:AMPLITUDE:PERIOD`` terms separated by commas (DOF surge, sway, heave
with the amplitude in m, or roll_deg, pitch_deg, yaw_deg with the amplitude in degrees; period
in s) about the zero pose, ramped in over the longest period.

Exit status 0; 2 for bad input (scene, motion file, options); 3 when a line fails numerically
(the message names the time, line, node and a likely remedy).
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from .argtypes import nonnegative_float, positive_float

HELP = "decoupled FE analysis of mooring lines driven by a floater run's motion (DAF per line)"

_DOF_KEYS = {"surge": (0, 1.0), "sway": (1, 1.0), "heave": (2, 1.0),
             "roll_deg": (3, math.pi / 180.0), "pitch_deg": (4, math.pi / 180.0),
             "yaw_deg": (5, math.pi / 180.0)}


def parse_harmonic(text: str) -> list[tuple[int, float, float]]:
    """``"surge:3:15,pitch_deg:2:30"`` -> ``[(0, 3.0, 15.0), (4, 0.0349, 30.0)]`` (dof index,
    amplitude in m or rad, period in s).  Raises ``argparse.ArgumentTypeError``."""
    out = []
    for term in text.split(","):
        parts = term.strip().split(":")
        if len(parts) != 3:
            raise argparse.ArgumentTypeError(
                f"expected DOF:AMPLITUDE:PERIOD terms separated by commas, found {term!r}")
        dof, amp, per = parts
        if dof not in _DOF_KEYS:
            raise argparse.ArgumentTypeError(
                f"unknown DOF {dof!r} in {term!r}; one of: " + ", ".join(_DOF_KEYS))
        try:
            a, p = float(amp), float(per)
        except ValueError:
            raise argparse.ArgumentTypeError(f"amplitude and period must be numbers in "
                                             f"{term!r}") from None
        if not (math.isfinite(a) and math.isfinite(p) and p > 0.0):
            raise argparse.ArgumentTypeError(f"expected a finite amplitude and a period > 0 "
                                             f"in {term!r}")
        i, scale = _DOF_KEYS[dof]
        out.append((i, a * scale, p))
    return out


MAX_HARMONIC_OFFSET = 0.3
"""Largest summed amplitude of the horizontal harmonic motion, as a fraction of the water depth
(design offsets are a few percent of it; 30 % has broken any catenary mooring)."""

MAX_HARMONIC_HEAVE = 0.2
"""Largest summed heave amplitude, as a fraction of the water depth."""

MAX_HARMONIC_ROTATION_DEG = 30.0
"""Largest summed roll, pitch or yaw amplitude, deg."""


def check_harmonic_amplitudes(comps, water_depth: float, error=argparse.ArgumentTypeError):
    """Refuse ``--harmonic`` amplitudes no floater moves by (a typo, or mm for m): summed per DOF
    against :data:`MAX_HARMONIC_OFFSET` and :data:`MAX_HARMONIC_HEAVE` of the water depth and
    :data:`MAX_HARMONIC_ROTATION_DEG`."""
    names = ("surge", "sway", "heave", "roll_deg", "pitch_deg", "yaw_deg")
    amp = [0.0] * 6
    for i, a, _ in comps:
        amp[i] += abs(a)
    horiz = math.hypot(amp[0], amp[1])
    if horiz > MAX_HARMONIC_OFFSET * water_depth:
        raise error(f"--harmonic: a horizontal amplitude of at most {MAX_HARMONIC_OFFSET:g} x the "
                    f"water depth ({MAX_HARMONIC_OFFSET * water_depth:g} m), found {horiz:g} m")
    if amp[2] > MAX_HARMONIC_HEAVE * water_depth:
        raise error(f"--harmonic: a heave amplitude of at most {MAX_HARMONIC_HEAVE:g} x the water "
                    f"depth ({MAX_HARMONIC_HEAVE * water_depth:g} m), found {amp[2]:g} m")
    for i in (3, 4, 5):
        if math.degrees(amp[i]) > MAX_HARMONIC_ROTATION_DEG:
            raise error(f"--harmonic: a {names[i]} amplitude of at most "
                        f"{MAX_HARMONIC_ROTATION_DEG:g} deg, found {math.degrees(amp[i]):g} deg")


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor lines``."""
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file (its mooring section)")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--motion", metavar="RESULTS.nc",
                     help="a seed file of `floatmoor run` (its motion(time, dof) drives the lines)")
    src.add_argument("--harmonic", type=parse_harmonic, metavar="DOF:AMP:PERIOD[,...]",
                     help="harmonic body motion instead, e.g. surge:3:15 or sway:1:5,sway:3:15 "
                          "(m or deg for roll_deg/pitch_deg/yaw_deg, s)")
    p.add_argument("--lines", default=None, metavar="NAMES",
                   help="comma-separated line names (default: all active lines)")
    p.add_argument("--out", default=None, metavar="FILE",
                   help="netCDF output (default: lines/<motion file>_lines.nc in the motion "
                        "file's folder, outside the seed files `floatmoor report` reads; "
                        "lines_harmonic.nc in the current folder for --harmonic)")
    p.add_argument("--duration", type=positive_float, default=None, metavar="S",
                   help="use only the first S seconds of the motion (harmonic: default 10 longest "
                        "periods plus the ramp)")
    p.add_argument("--dt", type=positive_float, default=None, metavar="S",
                   help="harmonic only: sample interval of the body motion (default 0.1 s)")
    p.add_argument("--discard", type=nonnegative_float, default=None, metavar="S",
                   help="start-up time left out of the statistics (default: the run's transient, "
                        "or the ramp plus one period for --harmonic)")
    p.add_argument("--substeps", type=int, default=None, metavar="N",
                   help="FE line steps per motion sample (default: from finite_element.dt or "
                        "finite_element.substeps)")


def _load_motion(path: Path, duration):
    """Time, poses, transient and the run's fairlead tensions from a seed file; SceneError on
    a file that is not one."""
    import numpy as np
    import xarray as xr

    from ..core.dofs import DOF_NAMES
    from ..core.errors import SceneError

    if not path.is_file():
        raise SceneError(path, "", "a netCDF seed file of `floatmoor run`", "no such file")
    try:
        ds = xr.load_dataset(path)
    except Exception as exc:  # noqa: BLE001 - any reader failure is bad input
        raise SceneError(path, "", "a netCDF seed file of `floatmoor run`",
                         f"unreadable ({type(exc).__name__}: {exc})") from None
    if "motion" not in ds or ds["motion"].dims != ("time", "dof"):
        raise SceneError(path, "motion", "a variable motion(time, dof)",
                         "missing" if "motion" not in ds else str(ds["motion"].dims))
    dofs = [str(d) for d in ds["dof"].values] if "dof" in ds.coords else []
    if dofs != list(DOF_NAMES):
        raise SceneError(path, "dof", "the DOFs " + ", ".join(DOF_NAMES), dofs)
    t = np.asarray(ds["time"].values, float)
    poses = np.asarray(ds["motion"].values, float)
    if t.size < 3 or not np.all(np.diff(t) > 0):
        raise SceneError(path, "time", "at least 3 increasing times", t[:5].tolist())
    if not np.all(np.isfinite(poses)):
        raise SceneError(path, "motion", "finite values", "NaN or inf (a failed seed?)")
    if duration is not None:
        keep = t - t[0] <= duration + 1e-9
        if keep.sum() < 3:
            raise SceneError(path, "time", f"at least 3 samples in the first {duration:g} s",
                             int(keep.sum()))
        t, poses = t[keep], poses[keep]
    ref = {}
    if "line_tension" in ds and "line" in ds.coords:
        for i, n in enumerate(ds["line"].values):
            ref[str(n)] = np.asarray(ds["line_tension"].values[: t.size, i], float)
    return t, poses, float(ds.attrs.get("transient", 0.0)), ref, dict(ds.attrs)


def format_table(res) -> str:
    """The per-line table of :func:`floatmoor.mooring.fe.decoupled.run_decoupled` results,
    with each line's self-check (``ok``, or ``FAILED`` and the bounds it breaks below)."""
    import numpy as np

    head = (f"{'line':<10}{'FE mean':>10}{'FE std':>9}{'FE max':>10}{'QS mean':>10}"
            f"{'QS std':>9}{'QS max':>10}{'DAF':>7}{'T max along':>13}{'at s':>8}"
            f"{'grounded length':>18}{'check':>8}")
    units = (f"{'':<10}{'kN':>10}{'kN':>9}{'kN':>10}{'kN':>10}{'kN':>9}{'kN':>10}{'-':>7}"
             f"{'kN':>13}{'m':>8}{'m':>18}{'':>8}")
    rows = [head, units]
    notes = []
    for i, n in enumerate(res["line"].values):
        g = lambda k, i=i: float(res[k].values[i])  # noqa: E731
        chk = str(res["selfcheck"].values[i]) if "selfcheck" in res else "-"
        if chk not in ("ok", "-"):
            notes.append(f"  {n}: {chk}")
        rows.append(f"{str(n):<10}{g('fe_mean') / 1e3:10.1f}{g('fe_std') / 1e3:9.2f}"
                    f"{g('fe_max') / 1e3:10.1f}{g('qs_mean') / 1e3:10.1f}"
                    f"{g('qs_std') / 1e3:9.2f}{g('qs_max') / 1e3:10.1f}{g('daf'):7.3f}"
                    f"{g('max_tension_along_line') / 1e3:13.1f}"
                    f"{g('max_tension_arc_length'):8.1f}"
                    f"{g('grounded_length_min'):9.1f} -{g('grounded_length_max'):7.1f}"
                    f"{'ok' if chk in ('ok', '-') else 'FAILED':>8}")
    if "selfcheck" in res:
        if notes:
            rows.append("self-check FAILED (these tensions break a bound a correct solution "
                        "keeps; do not use them):")
            rows.extend(notes)
        else:
            halv = int(np.nansum(res["selfcheck_energy_halvings"].values))
            rows.append("self-check: ok (tension along each line within its fairlead tension "
                        "plus weight, friction and drag; no step created energy"
                        + (f", {halv} step(s) halved to keep it so" if halv else "") + ")")
    return "\n".join(rows)


def run(args: argparse.Namespace) -> int:
    """Run the decoupled analysis, print the table, write the netCDF; returns the exit status."""
    import warnings

    import numpy as np

    from ..cli import UsageError
    from ..core.errors import FloatmoorWarning, SceneError
    from ..io.mooring_section import parse_mooring
    from ..io.scene import load_scene
    from ..mooring.fe.body import scene_line_inputs
    from ..mooring.fe.decoupled import harmonic_poses, run_decoupled

    scene = load_scene(args.scene)
    node = scene.mooring_node()
    if node is None:
        raise SceneError(scene.file, "mooring", "a mooring section (the lines to analyse)",
                         SceneError.MISSING)
    site = scene.site
    system = parse_mooring(node, water_depth=site.water_depth,
                           water_density=site.water_density, gravity=site.gravity)
    options = system.line_models.options
    active = [n for n, a in zip(system.names, system.active) if a]
    if args.lines:
        names = [s.strip() for s in args.lines.split(",") if s.strip()]
        bad = [n for n in names if n not in system.names]
        if bad or not names:
            raise UsageError(f"--lines {args.lines}: unknown line(s) {', '.join(bad) or '(none)'}"
                             f"; lines of the scene: {', '.join(system.names)}")
    else:
        names = active
    if args.substeps is not None and args.substeps < 1:
        raise UsageError(f"--substeps must be >= 1, found {args.substeps}")

    ref = None
    if args.motion is not None:
        if args.dt is not None:
            raise UsageError("--dt is for --harmonic only (the motion file sets the time step)")
        mpath = Path(args.motion)
        t, poses, transient, ref, attrs = _load_motion(mpath, args.duration)
        if attrs.get("scene_name") and attrs["scene_name"] != scene.name:
            warnings.warn(f"{mpath}: motion of scene {attrs['scene_name']!r}, lines of scene "
                          f"{scene.name!r}", FloatmoorWarning, stacklevel=2)
        ref = {n: ref[n] for n in names if n in ref} or None
        if ref is not None and len(ref) != len(names):
            ref = None
        discard = transient if args.discard is None else args.discard
        source = f"motion of {mpath} (seed {attrs.get('seed', '?')})"
        out = Path(args.out) if args.out else mpath.parent / "lines" / (mpath.stem + "_lines.nc")
    else:
        comps = args.harmonic
        check_harmonic_amplitudes(comps, site.water_depth, UsageError)
        tmax_p = max(c[2] for c in comps)
        dt = 0.1 if args.dt is None else args.dt
        duration = 10.0 * tmax_p + tmax_p if args.duration is None else args.duration
        from ..io.analysis import check_time_steps
        check_time_steps(scene.file, duration, dt, key="--dt")
        t = np.arange(0.0, duration + 0.5 * dt, dt)
        if t.size < 3:
            raise UsageError(f"--duration {duration:g} s gives fewer than 3 steps of {dt:g} s")
        poses = harmonic_poses(t, comps, ramp=tmax_p)
        discard = 2.0 * tmax_p if args.discard is None else args.discard
        source = "harmonic " + ", ".join(f"{['surge', 'sway', 'heave', 'roll', 'pitch', 'yaw'][d]}"
                                         f" {a:g} ({'m' if d < 3 else 'rad'}) at {p:g} s"
                                         for d, a, p in comps)
        out = Path(args.out) if args.out else Path("lines_harmonic.nc")
    span = float(t[-1] - t[0])
    if discard >= span:
        raise UsageError(f"the discarded start-up time {discard:g} s is not shorter than the "
                         f"motion ({span:g} s): give --discard or a longer --duration")
    inputs = scene_line_inputs(scene, system)
    print(f"scene: {scene.name}  [{scene.file}]")
    print(f"driving: {source}; {span:g} s at {t[1] - t[0]:g} s, statistics after {discard:g} s")

    def progress(text):
        print(text, file=sys.stderr, flush=True)
    from .compile_notice import compile_notice
    try:
        with compile_notice("the finite-element line kernels"):
            res = run_decoupled(system, t, poses, options=options, lines=names,
                                discard=discard, substeps=args.substeps,
                                reference_tension=ref, progress=progress, **inputs)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    print(f"FE lines: {options.integrator}, {res.attrs['substeps']} step(s) per sample, "
          f"elements {', '.join(str(int(v)) for v in res['n_elements'].values)}, wall time "
          f"{float(res['wall_time'].sum()):.1f} s; current on the lines: "
          f"{res.attrs['current_on_lines']}")
    print(format_table(res))
    if "run_tension" in res:
        sel = res["time"].values - t[0] >= discard
        d = np.abs(res["qs_tension"].values[:, sel] - res["run_tension"].values[:, sel])
        rel = float((d.max(axis=1) / np.abs(res["run_tension"].values[:, sel]).max(axis=1)).max())
        print(f"check: quasi-static tension along the fairlead track vs the run's line tension: "
              f"max difference {rel:.2e} of the max")
        res.attrs["qs_vs_run_max_relative_difference"] = rel
    res.attrs.update({"title": f"floatmoor decoupled FE line analysis of {scene.name}",
                      "scene_name": scene.name, "scene_file": str(scene.file),
                      "driving_motion": source})
    out.parent.mkdir(parents=True, exist_ok=True)
    res.to_netcdf(out)
    print(f"written: {out}")
    return 0
