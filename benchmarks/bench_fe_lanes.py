"""FE lines as SIMD lanes (``mooring/fe/lanes*.py``) against the line-by-line kernel, along
the body track of the coupled FE flagship (scenes/floatel_100yr_fe.yaml: 12 lines x 50
elements, generalised-alpha, one line step per body step).

Both replays advance the same 12 lines from the same start along the same track (the body
track file written by ``benchmarks/profile_fe_step.py --track FILE``), one numba call for all
the body steps: line by line (``multi.body_advance`` / ``body_accept``) and as lanes (the
fairleads of the lines into the lane blocks, ``lanes_advance.block_advance`` / ``accept`` per
block of :data:`~floatmoor.mooring.fe.lanes.LW` lines).  Prints the CPU time per line step of
each replay, interleaved (``--rounds``), and whether the fairlead forces of every step and the
final line states are bit for bit the same.

Run: ``python benchmarks/profile_fe_step.py --duration 1500 --track /tmp/track.npz`` once,
then ``python benchmarks/bench_fe_lanes.py --track /tmp/track.npz [--newton exact|force]
[--rounds 3]``.  CPU times are ``time.process_time``; the load average is printed with them.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from numba import njit

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from floatmoor.core.frames import rotation_matrix_into  # noqa: E402
from floatmoor.mooring.fe.lanes import LW, accepted, accepted_rows, build_group  # noqa: E402
from floatmoor.mooring.fe.lanes_advance import accept, block_advance  # noqa: E402
from floatmoor.mooring.fe.multi import body_accept, body_advance, fairlead_into  # noqa: E402

FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"


@njit(cache=True)
def _lines_steps(poses, vel, dt, nsub, max_split, body, lines, fair):
    for s in range(poses.shape[0] - 1):
        st = body_advance((s + 1) * dt, dt, nsub, max_split, poses[s + 1], vel[s + 1], body,
                          lines)
        if st < 0:
            return s + 1
        body_accept(body.on, lines)
        for i in range(fair.shape[1]):
            for c in range(3):
                fair[s, i, c] = body.forces[i, c]
    return 0


@njit(cache=True)
def _lanes_steps(poses, vel, dt, nsub, max_split, body, g, n, on, fair):
    fair_b, R, rf_all, vf_all, arm, Q, forces, _, fail, counters = body
    nl = fair.shape[1]
    nb = g.state0.r.shape[0]
    for s in range(poses.shape[0] - 1):
        pose = poses[s + 1]
        v = vel[s + 1]
        rotation_matrix_into(pose[3], pose[4], pose[5], R)
        for i in range(nl):
            fairlead_into(i, pose, v, R, fair_b, arm, rf_all, vf_all)
        for p in range(nb * LW):
            i = p if p < nl else (p // LW) * LW
            b = p // LW
            lane = p % LW
            for c in range(3):
                g.work.fair[b, (9 + c) * LW + lane] = rf_all[i, c]
                g.work.fair[b, (12 + c) * LW + lane] = vf_all[i, c]
        t1 = (s + 1) * dt
        for b in range(nb):
            block_advance(b, n, t1, dt, nsub, max_split, g, on)
        for p in range(nl):
            if g.work.status[p] < 0:
                return s + 1
        for b in range(nb):
            accept(b, n, g, on)
        for p in range(nl):
            b = p // LW
            lane = p % LW
            for c in range(3):
                fair[s, p, c] = accepted(g, b).f[b, ((n - 1) * 3 + c) * LW + lane]
    return 0


def _setup(built, x0, dt):
    from floatmoor.solvers.fe_coupling import setup as fe_setup
    fe = fe_setup(built, pose=x0, dt=dt)
    fm = fe.mooring
    fm.solve_static(x0)
    fm.start(**fe.options.start_kw())
    body, lines = fm._packed
    return fe, fm, body, lines


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--track", required=True)
    ap.add_argument("--newton", default="exact")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--steps", type=int, default=0, help="body steps (default: the track's)")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.mooring.fe.line import FELine
    from floatmoor.solvers.td_kernel import _pose_rate

    sys.path.insert(0, str(ROOT / "benchmarks"))
    from profile_fe_step import with_newton

    built = build(load_scene(FE))
    with_newton(built, args.newton)
    tr = np.load(args.track)
    motion, velocity, dt = tr["motion"], tr["velocity"], float(tr["dt"])
    if args.steps:
        motion, velocity = motion[:args.steps + 1], velocity[:args.steps + 1]
    n_steps = motion.shape[0] - 1
    vel = np.zeros((n_steps + 1, 6))
    prate = np.zeros(6)
    for k in range(n_steps + 1):
        x = motion[k]
        _pose_rate(x, velocity[k], prate)
        cph, sph = np.cos(x[4]), np.sin(x[4])
        cps, sps = np.cos(x[5]), np.sin(x[5])
        vel[k] = [prate[0], prate[1], prate[2], prate[3] * cps * cph - prate[4] * sps,
                  prate[3] * sps * cph + prate[4] * cps, prate[5] - prate[3] * sph]
    poses = np.ascontiguousarray(motion)
    x0 = motion[0].copy()

    def lines_run(steps):
        fe, fm, body, lines = _setup(built, x0, dt)
        fair = np.zeros((steps, len(lines), 3))
        c0 = time.process_time()
        st = _lines_steps(poses[:steps + 1], vel[:steps + 1], dt, fe.substeps, FELine.MAX_SPLIT,
                          body, lines, fair)
        cpu = time.process_time() - c0
        if st:
            raise RuntimeError(f"line-by-line replay failed at step {st}")
        states = np.stack([np.concatenate([ln.now.r, ln.now.v, ln.now.a, ln.now.f], axis=1)
                           for ln in lines])
        return cpu, fair, states

    def lanes_run(steps):
        fe, fm, body, lines = _setup(built, x0, dt)
        bl = [ln.bundle for ln in fm.lines]
        g = build_group([b.par for b in bl], [b.now for b in bl])
        nl = len(bl)
        n = bl[0].now.r.shape[0]
        on = np.zeros(g.work.status.shape[0], dtype=np.bool_)
        on[:nl] = True
        fair = np.zeros((steps, nl, 3))
        c0 = time.process_time()
        st = _lanes_steps(poses[:steps + 1], vel[:steps + 1], dt, fe.substeps, FELine.MAX_SPLIT,
                          body, g, n, on, fair)
        cpu = time.process_time() - c0
        if st:
            raise RuntimeError(f"lane replay failed at step {st}")
        nb = g.state0.r.shape[0]
        arr = [accepted_rows(g, k).reshape(nb, n, 3, LW) for k in ("r", "v", "a", "f")]
        states = np.stack([np.concatenate([a[p // LW, :, :, p % LW] for a in arr], axis=1)
                           for p in range(nl)])
        return cpu, fair, states

    lines_run(3)
    lanes_run(3)          # compile or cache load
    nls = 12 * n_steps
    for r in range(args.rounds):
        order = (("lines", lines_run), ("lanes", lanes_run))
        if r % 2:
            order = order[::-1]
        out = {}
        for name, fn in order:
            load = os.getloadavg()[0]
            cpu, fair, states = fn(n_steps)
            out[name] = (fair, states)
            print(f"round {r + 1} {name}: CPU {cpu:.2f} s, {1e6 * cpu / nls:.1f} us per line "
                  f"step ({n_steps} body steps, newton {args.newton}); load {load:.2f} -> "
                  f"{os.getloadavg()[0]:.2f}", flush=True)
        same = (np.array_equal(out["lines"][0], out["lanes"][0])
                and np.array_equal(out["lines"][1], out["lanes"][1]))
        d = np.abs(out["lines"][0] - out["lanes"][0]).max()
        print(f"  fairlead forces and final states bit for bit the same: {same} "
              f"(largest force difference {d:.3g} N)")


if __name__ == "__main__":
    main()
