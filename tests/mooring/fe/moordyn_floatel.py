"""A line of the Floatel-like flagship mooring (chain 1200 m + polyester 1200 m + chain 250 m,
150 m depth, about 1100 m of chain on the seabed) driven by a storm's fairlead track, in
floatmoor and in MoorDyn (PyPI ``moordyn``, MoorDyn-C v2) with identical inputs.  Used by the
slow verification test and by ``benchmarks/verify_fe_floatel_moordyn.py``.

Identical inputs:

* the line: MoorDyn's input is written by ``floatmoor.io.moordyn.export`` from the same
  ``MooringSystem`` (one MoorDyn line per segment joined by free points, the volume-equivalent
  diameter so that the buoyancy is floatmoor's, drag coefficients rescaled to the same force
  per metre, the same element count per segment);
* the current: the scene's profile, sampled where floatmoor's FE lines sample it
  (:func:`floatmoor.mooring.fe.body.scene_line_inputs`), as MoorDyn's steady current profile
  (``Currents 1``, ``current_profile.txt``: linear between the levels, as floatmoor);
* the seabed: MoorDyn's law is a linear spring with damping both ways (``kBot, cBot`` per
  unit of diameter); floatmoor's FE lines get the same (``contact_smoothing: 0``,
  ``lift_off_damping: true``, stiffness and damping per metre of line = MoorDyn's times the
  chain's diameter) and no friction (MoorDyn's ``FrictionCoefficient`` 0);
* the fairlead kinematics: the track is piecewise linear between the storm's samples (every
  0.1 s).  MoorDyn's ``Step(x, xd, t, dt)`` takes the state at the *start* of the step and
  moves the coupled point along ``x + xd (t' - t)`` (MoorDyn-C ``Point::updateFairlead``), so it
  gets ``x = r(t_k)`` and the chord velocity ``(r(t_k+1) - r(t_k)) / dt``: exactly the
  piecewise-linear track.  floatmoor's step to ``t_k+1`` gets ``r(t_k+1)`` and the same chord
  velocity (:class:`~floatmoor.mooring.fe.prescribed.TimeSeriesMotion`).
"""

from __future__ import annotations

import dataclasses
import math
import os
import sys
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[3]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"
KBOT = 3.0e6         # Pa/m, MoorDyn's default seabed stiffness per unit of diameter and length
CBOT = 3.0e5         # Pa s/m, its damping


@contextmanager
def quiet_stdout():
    """MoorDyn-C prints to file descriptor 1."""
    sys.stdout.flush()
    devnull = os.open(os.devnull, os.O_WRONLY)
    saved = os.dup(1)
    os.dup2(devnull, 1)
    try:
        yield
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)


@dataclasses.dataclass
class Case:
    """One line of the flagship scene and what both codes are given."""

    line: str
    system: object          # MooringSystem with this line only
    ld: object              # its LineDef
    current: dict | None    # FE keywords current_z / current_speed / current_heading
    line_types: dict
    chain_d: float          # volume-equivalent chain diameter MoorDyn's seabed law uses (m)


def case(line="line1", *, current=True, friction=0.0) -> Case:
    """The flagship scene's ``line`` with (or without) the scene's current on the line, the
    seabed as MoorDyn models it, and a friction coefficient (0: none, as MoorDyn here)."""
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.io.scene import load_scene
    from floatmoor.mooring.fe.body import scene_line_inputs

    scene = load_scene(SCENE)
    site = scene.site
    system = parse_mooring(scene.mooring_node(), water_depth=site.water_depth,
                           water_density=site.water_density, gravity=site.gravity)
    inp = scene_line_inputs(scene, system)
    sub = system.only_lines([line])
    ld = sub.lines[0]
    chain = [s for s in ld.segments if s.line_type.endswith("chain_84")][0]
    vol = (chain.mass_per_length - chain.w / site.gravity) / site.water_density
    d_v = math.sqrt(4.0 * vol / math.pi)
    if friction:
        ld = dataclasses.replace(ld, cb=float(friction))
        sub = sub.__class__([ld], water_depth=sub.water_depth, water_density=sub.water_density,
                            gravity=sub.gravity, source=sub.source, line_models=sub.line_models,
                            line_types=sub.line_types)
    return Case(line=line, system=sub, ld=ld, current=inp["current"] if current else None,
                line_types=inp["line_types"], chain_d=d_v)


def seabed(c: Case):
    """floatmoor's seabed with MoorDyn's contact law (linear spring, damping both ways)."""
    from floatmoor.mooring.fe.config import Seabed
    return Seabed(depth=c.system.water_depth, stiffness=KBOT * c.chain_d, damping=CBOT * c.chain_d,
                  contact_smoothing=0.0, lift_off_damping=True)


def fe_line(c: Case, *, n_elements=None, element_length=20.0, pose0=None,
            internal_damping=0.0):
    """The started floatmoor FE line of the case, in static equilibrium at ``pose0``."""
    from floatmoor.mooring.fe.from_system import spec_from_linedef
    from floatmoor.mooring.fe.line import FELine

    sysm = c.system
    spec = spec_from_linedef(c.ld, water_depth=sysm.water_depth, pose=pose0,
                             water_density=sysm.water_density, gravity=sysm.gravity,
                             line_types=c.line_types, element_length=element_length,
                             n_elements=n_elements, seabed=seabed(c),
                             internal_damping=internal_damping, **(c.current or {}))
    line = FELine(spec)
    line.solve_static()
    return line


def run_floatmoor(c: Case, t, xyz, *, n_elements=None, element_length=20.0, substeps=1,
                  pose0=None, internal_damping=0.0, rho_inf=0.7):
    """Fairlead and anchor tension (N) at the track's times and the CPU time of the steps.
    ``t`` (nt,) s from 0, ``xyz`` (nt, 3) the fairlead displacement from its position at
    ``pose0``."""
    from floatmoor.mooring.fe.prescribed import TimeSeriesMotion, run_prescribed

    line = fe_line(c, n_elements=n_elements, element_length=element_length, pose0=pose0,
                   internal_damping=internal_damping)
    line.start(rho_inf=rho_inf)
    dt = float(t[1] - t[0])
    stats = {}
    ds = run_prescribed(line, TimeSeriesMotion(t=t, xyz=xyz), float(t[-1] - t[0]), dt,
                        substeps=substeps, stats=stats)
    return (ds.fairlead_tension.values, ds.anchor_tension.values, ds.max_tension.values,
            stats["cpu_steps"], line)


def moordyn_text(c: Case, *, n_segments=None, dtm=1e-3, friction=0.0, internal_damping=0.0,
                 scheme="RK4"):
    """MoorDyn v2 input of the case (``floatmoor.io.moordyn.export``) with the seabed, current
    and options the comparison needs."""
    from floatmoor.io.moordyn import export
    from floatmoor.mooring.fe.options import FEOptions, LineModels

    sysm = c.system
    opts = FEOptions(internal_damping=internal_damping,
                     seabed={"stiffness": KBOT * c.chain_d, "damping": CBOT * c.chain_d},
                     n_elements=n_segments)
    models = LineModels(models={ln.name: "finite-element" for ln in sysm.lines}, options=opts)
    s2 = sysm.__class__(sysm.lines, water_depth=sysm.water_depth,
                        water_density=sysm.water_density, gravity=sysm.gravity,
                        source=sysm.source, line_models=models, line_types=sysm.line_types)
    text = export(s2, dt=dtm)
    # the seabed per unit diameter of the chain (export divides by the largest diameter)
    lines = text.splitlines()
    out = []
    for ln in lines:
        if ln.split()[1:2] == ["kBot"]:
            ln = f"{KBOT:.6g} kBot - seabed stiffness (Pa/m)"
        elif ln.split()[1:2] == ["cBot"]:
            ln = f"{CBOT:.6g} cBot - seabed damping (Pa-s/m)"
        elif ln.split()[1:2] == ["FrictionCoefficient"]:
            continue
        out.append(ln)
        if ln.split()[1:2] == ["cBot"]:
            out.append(f"{friction:.6g} FrictionCoefficient - seabed friction (-)")
            if c.current is not None:
                out.append("1 Currents - steady current profile (current_profile.txt)")
            out.append(f"{scheme} tScheme - time integrator")
            out.append("1 disableOutput - no output files")
            out.append("1 disableOutTime - no time printing")
            out.append("0 writeLog - no log file")
            out.append("120 TmaxIC - initial-condition time limit (s)")
    return "\n".join(out) + "\n"


def current_profile_text(c: Case) -> str:
    """MoorDyn's ``current_profile.txt`` of the case's current (velocity of travel)."""
    cur = c.current
    head = cur["current_heading"]
    rows = ["--- MoorDyn steady current profile (floatmoor verification) ---",
            "z (m), ux (m/s), uy (m/s), uz (m/s)", "---"]
    for z, u in zip(cur["current_z"], cur["current_speed"]):
        rows.append(f"{z:.6f} {u * math.cos(head):.9g} {u * math.sin(head):.9g} 0.0")
    return "\n".join(rows) + "\n"


def run_moordyn(c: Case, t, r_fair, *, n_segments=None, dtm=1e-3, friction=0.0,
                internal_damping=0.0, scheme="RK4"):
    """MoorDyn's fairlead and anchor tension (N) at the track's times ``t`` for the fairlead
    positions ``r_fair`` (nt, 3, earth), the start-of-step state with the chord velocity at
    every coupling step; and the CPU time of the steps."""
    import moordyn

    text = moordyn_text(c, n_segments=n_segments, dtm=dtm, friction=friction,
                        internal_damping=internal_damping, scheme=scheme)
    nt = t.size
    Tf = np.zeros(nt)
    Ta = np.zeros(nt)
    with tempfile.TemporaryDirectory() as d, quiet_stdout():
        path = os.path.join(d, "floatel_line.dat")
        Path(path).write_text(text)
        if c.current is not None:
            Path(d, "current_profile.txt").write_text(current_profile_text(c))
        cwd = os.getcwd()
        os.chdir(d)
        try:
            system = moordyn.Create(path)
            dt = float(t[1] - t[0])
            v0 = (r_fair[1] - r_fair[0]) / dt
            moordyn.Init(system, r_fair[0].tolist(), [0.0, 0.0, 0.0])
            anchor_line = moordyn.GetLine(system, 1)
            f = moordyn.Step(system, r_fair[0].tolist(), [0.0, 0.0, 0.0], 0.0, 0.0)
            Tf[0] = math.sqrt(sum(x * x for x in f))
            Ta[0] = float(np.linalg.norm(moordyn.GetLineNodeTen(anchor_line, 0)))
            # MoorDyn's inputs as Python lists before the clock starts (the floatmoor run
            # takes its fairlead track as arrays in one go)
            rk = [x.tolist() for x in r_fair[:-1]]
            vk = [((r_fair[k + 1] - r_fair[k]) / dt).tolist() for k in range(nt - 1)]
            tk = [float(x) for x in t[:-1]]
            c0 = time.process_time()
            for k in range(nt - 1):
                f = moordyn.Step(system, rk[k], vk[k], tk[k], dt)
                Tf[k + 1] = math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2])
                Ta[k + 1] = float(np.linalg.norm(moordyn.GetLineNodeTen(anchor_line, 0)))
            cpu = time.process_time() - c0
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    del v0
    return Tf, Ta, cpu


def storm_track(seed=19, duration=None, motion_file=None):
    """Body motion of a quasi-static flagship storm (``floatmoor.simulate``, or a seed file of
    ``floatmoor run``): times from 0 (s), poses (nt, 6) and the statistics start (s)."""
    import xarray as xr

    if motion_file is not None:
        ds = xr.load_dataset(motion_file)
    else:
        import floatmoor
        scene = floatmoor.load_scene(SCENE)
        ds = floatmoor.simulate(scene, seed=seed, duration=duration)
    t = np.asarray(ds.time.values, float)
    poses = np.asarray(ds.motion.values, float)
    if duration is not None:
        keep = t - t[0] <= duration + 1e-9
        t, poses = t[keep], poses[keep]
    return t - t[0], poses, float(ds.attrs.get("transient", 1200.0))


def fairlead_track(c: Case, t, poses):
    """Earth fairlead positions (nt, 3) and displacements from the first (nt, 3)."""
    from floatmoor.mooring.fe.prescribed import fairlead_track_from_body

    tr = fairlead_track_from_body(t, poses, c.ld.fairlead)
    from floatmoor.core.frames import rotation_matrix_into
    R = np.zeros((3, 3))
    p0 = poses[0]
    rotation_matrix_into(p0[3], p0[4], p0[5], R)
    r0 = p0[:3] + R @ np.asarray(c.ld.fairlead, float)
    return r0 + tr.xyz, tr.xyz


def statistics(T, window):
    """Mean, std, max, min of ``T`` over the boolean ``window``."""
    x = T[window]
    return {"mean": float(x.mean()), "std": float(x.std()), "max": float(x.max()),
            "min": float(x.min())}
