"""Profile of the quasi-static storm step: where the time of one RK4 step of the flagship goes.

Numba has no profiler, so every component kernel of the step is timed on its own over the
calls it makes in a 3-hour run of ``scenes/floatel_100yr.yaml`` (seed 1, dt 0.1 s, 108000
steps, 4 RK4 stages each), with the inputs of that run (the recorded poses and velocities):

* catenary solves: :func:`floatmoor.mooring.system.system_force_kernel` (or with
  ``--catenary predictor`` :func:`floatmoor.mooring.catenary_step.system_force_step_kernel`)
  at the 4 stage poses of every step (recorded by a copy of the loop), warm-started from the previous call as in the
  loop; the mean number of Newton iterations per line solve;
* radiation memory: the convolution sum (or with ``--memory state_space`` its recursion) once
  per step and its stage update 4 times per step;
* relative flow: the wind and current terms (table look-up, atan2) at every stage;
* series: the wave and drift force samples copied at every stage;
* restoring and damping matrices at every stage;
* the rest (RK4 bookkeeping: stage states, accelerations, pose rates, sums of the parts, the
  record, the guards): the whole loop less the components.

CPU time (``time.process_time``), the best of ``--repeat`` repeats (the machine is shared).
Run: ``.venv/bin/python benchmarks/profile_qs_step.py [--duration 10800] [--repeat 3]
[--catenary exact|predictor] [--memory convolution|state_space]``
"""

from __future__ import annotations

import argparse
import time
import warnings
from pathlib import Path

import numpy as np
from numba import njit

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"


def setup(duration: float, dt: float, seed: int, solver=None):
    """Assembly and kernel bundles of the flagship storm."""
    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.solvers.time_domain import assemble

    scene = load_scene(SCENE)
    built = build(scene)
    a = assemble(built, seed=seed, dt=dt, duration=duration, ramp=scene.analysis.ramp,
                 options=scene.forces, solver=solver)
    return a, built


def bundles(a, built):
    from floatmoor.solvers.time_domain import kernel_bundles
    return kernel_bundles(a, built=built)


def run_loop(a, built):
    """CPU time of the whole loop and its outputs."""
    from floatmoor.solvers.td_kernel import td_kernel
    body, terms, lines, out = bundles(a, built)
    t0 = time.process_time()
    td_kernel(body, terms, lines, out)
    return time.process_time() - t0, out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=10800.0)
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--catenary", default="exact", help="solver.catenary: exact | predictor")
    ap.add_argument("--memory", default="convolution",
                    help="solver.memory: convolution | state_space")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from floatmoor.forces.kernels import relative_flow_force_into, turn_horizontal
    from floatmoor.mooring.catenary import OUT_ITER
    from floatmoor.mooring.catenary_step import system_force_step_kernel
    from floatmoor.mooring.system import system_force_kernel
    from floatmoor.solvers.td_kernel import _memory_sum, _push_history, _stage, new_run_state

    @njit
    def stage_poses(n_steps, body, terms, lines, st, out, poses):
        """The loop of td_steps, recording the pose of every stage."""
        for n in range(n_steps):
            _memory_sum(n, terms.memory, st)
            _stage(2 * n, 0.0, st.x, st.v, 0, body, terms, lines, st)
            for i in range(6):
                poses[4 * n, i] = st.x[i]
            for k in range(1, 4):
                c = 0.5 if k < 3 else 1.0
                j = 2 * n + 1 if k < 3 else 2 * n + 2
                for i in range(6):
                    st.xs[i] = st.x[i] + c * body.dt * st.q[k - 1, i]
                    st.vs[i] = st.v[i] + c * body.dt * st.a[k - 1, i]
                    poses[4 * n + k, i] = st.xs[i]
                _stage(j, c, st.xs, st.vs, k, body, terms, lines, st)
            for i in range(6):
                st.x[i] += body.dt / 6.0 * (st.q[0, i] + 2.0 * st.q[1, i] + 2.0 * st.q[2, i]
                                            + st.q[3, i])
                st.v[i] += body.dt / 6.0 * (st.a[0, i] + 2.0 * st.a[1, i] + 2.0 * st.a[2, i]
                                            + st.a[3, i])
            _push_history(n + 1, st)

    @njit
    def catenary_loop(poses, cat, active, warm, work, rot, line_out, fm, stiff, xs, iters, tol):
        n_lines = line_out.shape[0]
        for n in range(poses.shape[0]):
            for i in range(6):
                xs[i] = poses[n, i]
            if tol > 0.0:
                bad = system_force_step_kernel(xs, cat.anchors, cat.fairleads, cat.seg_L,
                                               cat.seg_EA, cat.seg_w, cat.seg_P,
                                               cat.line_start, cat.cb, cat.seabed, active,
                                               warm, tol, n % 4 == 2, work, rot,
                                               line_out, fm)
            else:
                bad = system_force_kernel(xs, cat.anchors, cat.fairleads, cat.seg_L,
                                          cat.seg_EA, cat.seg_w, cat.seg_P, cat.line_start,
                                          cat.cb, cat.seabed, active, warm, False, work, rot,
                                          line_out, fm, stiff)
            if bad >= 0:
                return bad
            for i in range(n_lines):
                iters[0] += line_out[i, OUT_ITER]
                iters[1] += 1.0
        return -1

    @njit
    def memory_loop(vel, mem, st, dt, parts):
        for n in range(vel.shape[0] - 1):
            _memory_sum(n, mem, st)
            for k in range(4):
                c = 0.0 if k == 0 else (0.5 if k < 3 else 1.0)
                for p in range(mem.i.shape[0]):
                    i = mem.i[p]
                    jj = mem.j[p]
                    parts[i] -= dt * (0.5 * mem.kernel[p, 0] * vel[n, jj]
                                      + (1.0 - c) * st.s0[p] + c * st.s1[p])
                turn_horizontal(parts, 1.0, 0.0)
            for k in range(6):
                st.v[k] = vel[n + 1, k]
            _push_history(n + 1, st)

    @njit
    def flow_loop(poses, vel, flow, coef, parts):
        for n in range(poses.shape[0] - 1):
            for k in range(4):
                j = 2 * n + (0 if k == 0 else (1 if k < 3 else 2))
                yaw = poses[n, 5]
                cy = np.cos(yaw)
                sy = np.sin(yaw)
                vx = cy * vel[n, 0] - sy * vel[n, 1]
                vy = sy * vel[n, 0] + cy * vel[n, 1]
                if flow.has_wf:
                    vx -= flow.wf_velocity[j, 0]
                    vy -= flow.wf_velocity[j, 1]
                for t in range(flow.heading.shape[0]):
                    nh = flow.n_heading[t]
                    js = j if flow.varies[t] else 0
                    relative_flow_force_into(flow.speed[t, js], flow.heading[t], vx, vy, yaw,
                                             1.0, flow.table_heading[t, :nh],
                                             flow.table[t, :nh], coef, parts)

    @njit
    def series_loop(n_steps, series, parts):
        for n in range(n_steps):
            for k in range(4):
                j = 2 * n + (0 if k == 0 else (1 if k < 3 else 2))
                for q in range(series.shape[0]):
                    for i in range(6):
                        parts[q, i] += series[q, j, i]

    @njit
    def matrix_loop(poses, vel, terms, parts):
        for n in range(poses.shape[0] - 1):
            x = poses[n]
            v = vel[n]
            for _k in range(4):
                cy = np.cos(x[5])
                sy = np.sin(x[5])
                rest = terms.restoring
                for t in range(rest.matrix.shape[0]):
                    for i in range(6):
                        s = rest.const[t, i]
                        for kk in range(6):
                            s -= rest.matrix[t, i, kk] * x[kk]
                        parts[i] = s
                    turn_horizontal(parts, cy, sy)
                dl = terms.damping.matrix
                for t in range(dl.shape[0]):
                    for i in range(6):
                        s = 0.0
                        for kk in range(6):
                            s += dl[t, i, kk] * v[kk]
                        parts[i] -= s
                    turn_horizontal(parts, cy, sy)

    from floatmoor.io.solver_section import SolverSpec
    solver = SolverSpec(catenary=args.catenary, memory=args.memory)
    print(f"scene {SCENE.name}: {args.duration:g} s at dt {args.dt:g} s, seed {args.seed}, "
          f"solver: {solver.describe()}")
    a, built = setup(args.duration, args.dt, args.seed, solver)
    n = a.n_steps
    best = {}

    def keep(name, t):
        best[name] = min(best.get(name, np.inf), t)

    iters = np.zeros(2)
    for rep in range(args.repeat + 1):
        t_loop, out = run_loop(a, built)
        if rep:
            keep("whole loop", t_loop)
        poses = np.ascontiguousarray(out.motion)
        body, terms, lines, out2 = bundles(a, built)
        st = new_run_state(body, terms, lines, out2)
        # yaw-frame velocities from the pose rates
        vel = np.ascontiguousarray(out.velocity).copy()
        cy, sy = np.cos(poses[:, 5]), np.sin(poses[:, 5])
        vel[:, 0] = cy * out.velocity[:, 0] + sy * out.velocity[:, 1]
        vel[:, 1] = -sy * out.velocity[:, 0] + cy * out.velocity[:, 1]
        st_poses = np.zeros((4 * n, 6))
        stage_poses(n, body, terms, lines, st, out2, st_poses)
        body, terms, lines, out2 = bundles(a, built)
        st = new_run_state(body, terms, lines, out2)
        if rep == 0:  # compile
            m = min(n, 50)
            catenary_loop(st_poses[:m], lines.cat, lines.active, lines.warm, st.work, st.rot,
                          st.line_out, st.fm, st.stiff, st.xs, np.zeros(2), lines.step_tol)
            memory_loop(vel[:m], terms.memory, st, body.dt, st.f)
            flow_loop(poses[:m], vel[:m], terms.flow, st.coef, st.f)
            series_loop(m - 1, terms.series, st.parts)
            matrix_loop(poses[:m], vel[:m], terms, st.f)
            continue
        lines.warm[:] = 0.0
        iters[:] = 0.0
        t0 = time.process_time()
        catenary_loop(st_poses, lines.cat, lines.active, lines.warm, st.work, st.rot,
                      st.line_out, st.fm, st.stiff, st.xs, iters, lines.step_tol)
        keep("catenary solves (12 lines x 4 stages)", time.process_time() - t0)
        st = new_run_state(body, terms, lines, out2)
        t0 = time.process_time()
        memory_loop(vel, terms.memory, st, body.dt, st.f)
        keep("radiation memory (sum per step, 4 stage updates)", time.process_time() - t0)
        t0 = time.process_time()
        flow_loop(poses, vel, terms.flow, st.coef, st.f)
        keep("wind and current tables (4 stages)", time.process_time() - t0)
        t0 = time.process_time()
        series_loop(n, terms.series, st.parts)
        keep("wave/drift force series (4 stages)", time.process_time() - t0)
        t0 = time.process_time()
        matrix_loop(poses, vel, terms, st.f)
        keep("restoring and damping matrices (4 stages)", time.process_time() - t0)
    total = best.pop("whole loop")
    print(f"whole loop: {total:.3f} s CPU ({1e6 * total / n:.1f} us/step, "
          f"{args.duration / total:.0f}x real time), best of {args.repeat}")
    parts = 0.0
    for name, t in best.items():
        parts += t
        print(f"  {name:52s} {t:7.3f} s {100 * t / total:5.1f} %  {1e6 * t / n:6.2f} us/step")
    rest = total - parts
    print(f"  {'rest (RK4 bookkeeping, sums, record, guards)':52s} {rest:7.3f} s "
          f"{100 * rest / total:5.1f} %  {1e6 * rest / n:6.2f} us/step")
    print(f"  catenary: {iters[0] / max(iters[1], 1):.2f} Newton iterations per line solve "
          f"(mean over {iters[1]:.0f} solves; 0: a predictor-corrector step)")


if __name__ == "__main__":
    main()
