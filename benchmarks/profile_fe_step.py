"""Breakdown of the coupled FE step of the flagship storm (scenes/floatel_100yr_fe.yaml: 12
lines x 50 elements, generalised-alpha, one line step per body step of 0.1 s).

1. The coupled run (``--duration`` s, default 1500) with its time-loop CPU time.
2. The same FE lines replayed alone along the body track of that run (``body_advance`` /
   ``body_accept``, one numba call per body step, as in the coupled kernel): the lines' CPU
   time and Newton iterations per line step; the body side (RK4, force terms, catenaries) is
   the difference.
3. The parts of one line step, timed on the 12 lines at the end of the replay (each kernel
   called many times in a numba loop, CPU time per call): force evaluation with the tangent,
   the residual assembly, the block-tridiagonal solve, the force evaluation of the accepted
   state, the whole ``gen_alpha_step``; the share of each in the line step follows from the
   iteration count.

Run: ``python benchmarks/profile_fe_step.py [--duration 1500] [--newton force|exact|modified|fast]
[--track FILE] [--forces FILE]``.  ``--track FILE``: the body track of the coupled run is saved
to FILE (``.npz``), or read from it when it exists, and the coupled run is then skipped (to
compare two versions of the line kernels along the same track, e.g. before / after a change,
in alternation); ``--forces FILE`` saves the fairlead forces of the replay (every step, every
line) and the final line states, and prints a digest of them (two versions whose arithmetic is
the same give the same digest).  CPU times (``time.process_time``): the machine is shared.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from numba import njit

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from floatmoor.mooring.fe import kernels as K  # noqa: E402
from floatmoor.mooring.fe.line import NEWTON_MODES  # noqa: E402
from floatmoor.mooring.fe.multi import body_accept, body_advance  # noqa: E402

FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"


@njit(cache=True)
def _time_forces(ln, reps, want_jac):
    par = ln.par
    w = ln.work
    s = ln.now
    f = ln.step.f
    cK = 0.001
    cC = 0.01
    acc = 0.0
    # the tension estimate is used for lines with stiff elements only (gen_alpha_step)
    use_act = False
    for j in range(s.r.shape[0] - 1):
        use_act = use_act or K._stiff(par.P, par.E, j)
    for _ in range(reps):
        K._line_forces(s.r, s.v, s.fs, par, want_jac, cK, cC, f, w, use_act)
        acc += f[1, 0]
    return acc


@njit(cache=True)
def _time_residual(ln, reps):
    # the residual loop of gen_alpha_step (mass blocks times accelerations, tangent update;
    # the interpolated accelerations once per node)
    w = ln.work
    Mb = w.Mb
    Dg = w.Dg
    Rr = w.R
    a1 = ln.trial.a
    a = ln.now.a
    f1 = ln.now.f
    fn = ln.now.f
    n = a.shape[0]
    am = 0.5
    af = 0.5
    acc = 0.0
    for _ in range(reps):
        res = 0.0
        for i in range(1, n - 1):
            b0 = (1.0 - am) * a1[i, 0] + am * a[i, 0]
            b1 = (1.0 - am) * a1[i, 1] + am * a[i, 1]
            b2 = (1.0 - am) * a1[i, 2] + am * a[i, 2]
            for k in range(3):
                s = 0.0 + Mb[i, k, 0] * b0 + Mb[i, k, 1] * b1 + Mb[i, k, 2] * b2
                Dg[i, k, 0] += 0.0 * Mb[i, k, 0]
                Dg[i, k, 1] += 0.0 * Mb[i, k, 1]
                Dg[i, k, 2] += 0.0 * Mb[i, k, 2]
                rk = (1.0 - af) * f1[i, k] + af * fn[i, k] - s
                Rr[i, k] = rk
                res += rk * rk
        acc += res
    return acc


@njit(cache=True)
def _time_solve(ln, reps):
    w = ln.work
    n = ln.now.r.shape[0]
    bend = ln.par.S[K.S_BEND] > 0.0
    acc = 0.0
    for _ in range(reps):
        K.solve_blocks(w.Dg, w.Of, w.BX, bend, w.R, 1, n - 1, w.W, w.Y, w.T1, w.dx)
        acc += w.dx[1, 0]
    return acc


@njit(cache=True)
def _time_step(ln, reps, dt):
    w = ln.work
    now = ln.now
    n = now.r.shape[0]
    rf = w.rf
    vf = w.vf
    for k in range(3):
        vf[k] = now.v[n - 1, k]
        rf[k] = now.r[n - 1, k] + dt * vf[k]
    its = 0
    for _ in range(reps):
        its += K.gen_alpha_step(1.0, dt, rf, vf, now, ln.trial, ln.par, w)
    return its


def _cpu(fn, *args):
    t0 = time.process_time()
    fn(*args)
    return time.process_time() - t0


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=1500.0)
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--reps", type=int, default=2000)
    ap.add_argument("--newton", choices=("force", "exact", "modified", "fast"), default="exact")
    ap.add_argument("--track", default=None, help="body track file (.npz): saved, or read "
                    "when it exists (then the coupled run is skipped)")
    ap.add_argument("--forces", default=None, help="save the replay's fairlead forces and "
                    "final line states to this .npz")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    import numba

    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.mooring.fe.line import FELine
    from floatmoor.solvers.fe_coupling import setup as fe_setup
    from floatmoor.solvers.time_domain import assemble, integrate

    print(f"# Python {sys.version.split()[0]}, numba {numba.__version__}; load "
          f"{' / '.join(f'{v:.2f}' for v in os.getloadavg())}")
    dt = args.dt
    built = build(load_scene(FE))
    with_newton(built, args.newton)
    sc = built.scene
    track = Path(args.track) if args.track else None
    if track is not None and track.exists():
        tr = np.load(track)
        motion, velocity = tr["motion"], tr["velocity"]
        x0 = motion[0].copy()
        cpu_coupled = float(tr["cpu"])
        its_coupled = float(tr["iterations"])
        if float(tr["dt"]) != dt:
            raise SystemExit(f"{track}: dt {float(tr['dt'])}, not {dt}")
        print(f"body track read from {track} (coupled run not repeated: its figures are those "
              f"of the run that wrote it)")
    else:
        a = assemble(built, seed=args.seed, dt=dt, duration=20.0, ramp=sc.analysis.ramp)
        integrate(a, built=built)     # warm-up (cache load or compile)
        a = assemble(built, seed=args.seed, dt=dt, duration=args.duration, ramp=sc.analysis.ramp)
        x0 = a.x0.copy()
        c0 = time.process_time()
        r = integrate(a, built=built)
        cpu_coupled = time.process_time() - c0
        motion, velocity = r.motion, r.velocity
        its_coupled = r.info["fe_newton_iterations"]
        if track is not None:
            np.savez(track, motion=motion, velocity=velocity, cpu=cpu_coupled,
                     iterations=its_coupled, dt=dt)
    n_steps = motion.shape[0] - 1
    # replay the lines alone along the body track (after a warm-up of a few steps: compile or
    # cache load of the replay's kernels)
    for warm in (True, False):
        fe = fe_setup(built, pose=x0, dt=dt)
        fm = fe.mooring
        fm.solve_static(x0)
        fm.start(**fe.options.start_kw())
        body, lines = fm._packed
        nl = len(lines)
        if warm:
            _replay(np.ascontiguousarray(motion[:3]), np.zeros((3, 6)), dt, fe.substeps,
                    FELine.MAX_SPLIT, body, lines, np.zeros((2, nl, 3)))
    from floatmoor.solvers.td_kernel import _pose_rate

    vel = np.zeros((n_steps + 1, 6))
    prate = np.zeros(6)
    for n in range(n_steps + 1):
        x = motion[n]
        _pose_rate(x, velocity[n], prate)
        cph, sph = np.cos(x[4]), np.sin(x[4])
        cps, sps = np.cos(x[5]), np.sin(x[5])
        vel[n] = [prate[0], prate[1], prate[2], prate[3] * cps * cph - prate[4] * sps,
                  prate[3] * sps * cph + prate[4] * cps, prate[5] - prate[3] * sph]
    poses = np.ascontiguousarray(motion)
    fair = np.zeros((n_steps, nl, 3))
    c0 = time.process_time()
    _replay(poses, vel, dt, fe.substeps, FELine.MAX_SPLIT, body, lines, fair)
    cpu_lines = time.process_time() - c0
    if args.forces:
        states = np.stack([np.concatenate([ln.now.r, ln.now.v, ln.now.a, ln.now.f], axis=1)
                           for ln in lines])
        np.savez(args.forces, fairlead=fair, states=states)
        h = hashlib.sha256(fair.tobytes() + states.tobytes()).hexdigest()[:16]
        tmax = np.linalg.norm(fair, axis=2).max(axis=0)
        print(f"replay digest {h}; per-line max fairlead tension (kN): "
              + " ".join(f"{t / 1e3:.3f}" for t in tmax))
    its = body.counters[:, 0].sum()
    line_steps = nl * n_steps * fe.substeps
    print(f"coupled storm, newton {args.newton}, {n_steps * dt:g} s at dt {dt:g} s "
          f"({n_steps} body steps, {nl} lines "
          f"x {fm.lines[0].n_nodes - 1} elements)")
    print(f"  coupled time loop CPU {cpu_coupled:.2f} s ({1e6 * cpu_coupled / n_steps:.0f} us "
          f"per body step), Newton iterations {its_coupled / line_steps:.3f} per line step")
    print(f"  FE lines alone along the same track: CPU {cpu_lines:.2f} s "
          f"({100 * cpu_lines / cpu_coupled:.0f} %), {its / line_steps:.3f} iterations per line "
          f"step, {1e6 * cpu_lines / line_steps:.1f} us per line step")
    print(f"  body side (RK4, force terms, catenaries) by difference: "
          f"{cpu_coupled - cpu_lines:.2f} s ({100 * (1 - cpu_lines / cpu_coupled):.0f} %)")
    # parts of one line step at the final states
    reps = args.reps
    parts = {"forces + tangent": 0.0, "forces only": 0.0, "residual": 0.0, "solve": 0.0,
             "whole step": 0.0}
    it_step = 0
    for ln in lines:
        ln_w = ln
        _time_forces(ln_w, 2, True)
        _time_forces(ln_w, 2, False)
        _time_residual(ln_w, 2)
        _time_step(ln_w, 2, dt)
        _time_solve(ln_w, 2)
        parts["forces + tangent"] += _cpu(_time_forces, ln_w, reps, True)
        parts["residual"] += _cpu(_time_residual, ln_w, reps)
        parts["solve"] += _cpu(_time_solve, ln_w, reps)
        parts["forces only"] += _cpu(_time_forces, ln_w, reps, False)
        t0 = time.process_time()
        it_step += _time_step(ln_w, reps, dt)
        parts["whole step"] += time.process_time() - t0
    per = {k: 1e6 * v / (reps * nl) for k, v in parts.items()}
    it_mean = it_step / (reps * nl)
    model = it_mean * (per["forces + tangent"] + per["residual"] + per["solve"]) \
        + per["forces only"]
    print(f"parts of one line step (mean over the {nl} lines at t = {n_steps * dt:g} s, "
          f"{reps} calls each, CPU us per call; {it_mean:.2f} Newton iterations in this step):")
    for k in ("forces + tangent", "residual", "solve", "forces only"):
        n_calls = 1.0 if k == "forces only" else it_mean
        print(f"  {k:18s} {per[k]:6.2f} us x {n_calls:.2f} = {per[k] * n_calls:6.2f} us "
              f"({100 * per[k] * n_calls / per['whole step']:.0f} % of the step)")
    print(f"  whole gen_alpha_step {per['whole step']:.2f} us (sum of the parts {model:.2f} us; "
          f"the rest: predictor, updates, convergence tests)")


def with_newton(built, mode: str) -> None:
    """Set the FE option ``newton`` of a built scene (``finite_element: {newton: mode}``)."""
    import dataclasses

    if mode == "exact" and "force" not in NEWTON_MODES:   # older trees: exact was the default
        return
    lm = built.mooring.line_models
    object.__setattr__(lm, "options", dataclasses.replace(lm.options, newton=mode))


def _replay(poses, vel, dt, nsub, max_split, body, lines, fair):
    st = _replay_steps(poses, vel, dt, nsub, max_split, body, lines, fair)
    if st > 0:
        raise RuntimeError(f"replay failed at step {st}")


@njit(cache=True)
def _replay_steps(poses, vel, dt, nsub, max_split, body, lines, fair):
    """The body steps of the replay in one numba call (as in the coupled kernel: no Python
    call per step); the fairlead forces of every step into ``fair``."""
    for n in range(poses.shape[0] - 1):
        st = body_advance((n + 1) * dt, dt, nsub, max_split, poses[n + 1], vel[n + 1], body,
                          lines)
        if st < 0:
            return n + 1
        body_accept(body.on, lines)
        for i in range(fair.shape[1]):
            for c in range(3):
                fair[n, i, c] = body.forces[i, c]
    return 0


if __name__ == "__main__":
    main()
