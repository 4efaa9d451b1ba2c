"""Coupled FE mooring benchmark: the 3-hour storm of the Floatel-like semi with 12 FE
lines (scenes/floatel_100yr_fe.yaml, 12 / 26 / 12 elements on its three segments) coupled to
the body.

Prints, per body time step (default 0.1 and 0.2 s): setup time (scene build, FE statics and
start equilibrium included), the time loop (wall and CPU of this process), simulated seconds
per wall second, the Newton iterations per line step, and the maximum fairlead tension after
the transient against the quasi-static run of the same seed (scenes/floatel_100yr.yaml).  The
load average is printed with the timings (the machine is shared).

Run: ``.venv/bin/python benchmarks/bench_coupled_fe.py [--duration 12000] [--dt 0.1 0.2]
[--seed 1] [--newton force exact modified] [--no-qs]``: with several ``--newton`` modes (FE option
``finite_element: {newton: ...}``) the FE runs are interleaved and the maximum tensions compared
with the first mode's.

A mode may carry perturbations for a sensitivity study, ``mode:key=value[:key=value]``:
``tol=1e-8`` (Newton tolerance in m, default 1e-6), ``x0=1e-6`` (every free node of every
line moved by a pseudo-random +-x0 m per coordinate from its static position before the
start), ``code=2`` (a raw ``kernels.NW_*`` code of the iteration, here the predictor alone),
e.g. ``--newton exact exact:tol=1e-8 exact:x0=1e-6 exact:code=2 modified``; ``--per-line`` prints
every line's maximum and its time.

``--fe-stages linear catenary``: the scene option ``solver: {fe_stages: ...}`` (default
``linear``, the scene default), interleaved
with the other options (the first one is the reference of the comparison lines).

``--lanes on off``: one thread, the FE lines as SIMD lanes (``fe_coupling.LANES``, the
default) or line by line, interleaved with the other options; each run is checked bit for bit
against the first setting's run of the same mode (``identical``).

``--elements scene 50 12,26,12``: the FE mesh, interleaved with the other options: the scene's
(``scene``, the default), an element count per line shared among the segments by length, or
counts per segment (anchor to fairlead); scene option ``finite_element: {n_elements: ...}``.

``--threads 1 2``: the FE lines advanced in that many threads (scene option ``solver:
{threads: N}``), the runs interleaved with the Newton modes; the time loop is printed as wall
and CPU seconds of the process (all its threads), and every threaded run is checked bit for bit
against the one-thread run of the same mode (``identical``).  The OpenMP wait policy is
floatmoor's (a bounded spin, ``GOMP_SPINCOUNT`` 100000, on idle cores; passive otherwise:
``fe_coupling.wait_policy``) unless ``OMP_WAIT_POLICY`` or ``GOMP_SPINCOUNT`` is set in the
environment.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"
QS = ROOT / "scenes" / "floatel_100yr.yaml"


def _load():
    return " / ".join(f"{v:.2f}" for v in os.getloadavg())


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=12000.0)
    ap.add_argument("--dt", type=float, nargs="+", default=[0.1, 0.2])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--newton", nargs="+", default=["exact"])
    ap.add_argument("--per-line", action="store_true")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--no-qs", action="store_true")
    ap.add_argument("--threads", type=int, nargs="+", default=[1])
    ap.add_argument("--lanes", nargs="+", default=["on"], choices=("on", "off"))
    ap.add_argument("--elements", nargs="+", default=["scene"],
                    help="FE mesh: scene, N (per line) or a,b,c (per segment)")
    ap.add_argument("--fe-stages", nargs="+", default=["linear"],
                    choices=("catenary", "linear"),
                    help="solver: {fe_stages: ...}: the FE lines' stiffness at the step start "
                    "(linear, the default) or their catenaries at every RK4 stage (catenary); "
                    "interleaved")
    ap.add_argument("--catenary", choices=("exact", "predictor"), default="exact",
                    help="solver: {catenary: ...} of the body side (the FE lines' catenaries "
                    "in the RK4 stages)")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    import numba

    from floatmoor.analyses.simulate import simulate
    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.io.solver_section import SolverSpec
    from floatmoor.mooring.fe.line import FELine

    plain_start = FELine.start
    perturb = {}

    def start(self, **kw):
        # sensitivity study: Newton tolerance and initial node positions (see the docstring)
        if "tol" in perturb:
            kw["tol"] = perturb["tol"]
        if perturb.get("x0", 0.0) > 0.0:
            rng = np.random.default_rng(len(self.r))
            self.r[1:-1] += perturb["x0"] * rng.choice([-1.0, 1.0], size=self.r[1:-1].shape)
        out = plain_start(self, **kw)
        if "code" in perturb:
            # a raw kernels.NW_* code of the Newton iteration (e.g. 2: the predictor alone)
            self._newton_mode = int(perturb["code"])
            self._set_params()
        return out

    FELine.start = start

    def fe_scene(mode, elements="scene"):
        import dataclasses

        newton, *extra = mode.split(":")
        perturb.clear()
        for item in extra:
            key, value = item.split("=")
            perturb[key] = float(value)
        built = build(load_scene(FE))
        lm = built.mooring.line_models
        opts = dataclasses.replace(lm.options, newton=newton)
        if elements != "scene":
            counts = tuple(int(v) for v in elements.split(","))
            opts = dataclasses.replace(opts, n_elements=counts[0] if len(counts) == 1
                                       else counts)
        object.__setattr__(lm, "options", opts)
        return built

    print(f"# {platform.machine()}, Python {platform.python_version()}, numba "
          f"{numba.__version__}; seed {args.seed}, {args.duration:g} s simulated "
          f"(transient 1200 s left out of the maxima)")
    # warm-up (numba cache load / compile) on a short run
    for th in sorted(set(args.threads)):
        t0 = time.perf_counter()
        simulate(FE, seed=args.seed, duration=20.0, dt=args.dt[0], solver=SolverSpec(threads=th))
        print(f"first short FE run, {th} thread(s) (cache load or compile): "
              f"{time.perf_counter() - t0:.1f} s")
    qs = {}
    for dt in ([] if args.no_qs else args.dt):
        w0 = time.perf_counter()
        ds = simulate(QS, seed=args.seed, duration=args.duration, dt=dt)
        sel = ds.time.values >= 1200.0
        qs[dt] = ds.line_tension.values[sel].max(axis=0)
        print(f"QS  dt {dt:g}: loop {ds.attrs['run_time_s']:.1f} s, total "
              f"{time.perf_counter() - w0:.1f} s, max tension {qs[dt].max() / 1e3:.0f} kN "
              f"(line {ds.line.values[int(np.argmax(qs[dt]))]}); load {_load()}")
    first = {}
    single = {}
    from floatmoor.solvers import fe_coupling

    runs = [(dt, nw, fes, th, ln, el) for dt in args.dt for _ in range(args.repeat)
            for nw in args.newton for fes in args.fe_stages for th in args.threads
            for ln in args.lanes for el in args.elements]
    by_lanes = {}
    for dt, nw, fes, th, ln, el in runs:
        fe_coupling.LANES = ln == "on"
        built = fe_scene(nw, el)
        w0 = time.perf_counter()
        c0 = time.process_time()
        ds = simulate(built, seed=args.seed, duration=args.duration, dt=dt,
                      solver=SolverSpec(threads=th, catenary=args.catenary, fe_stages=fes))
        wall = time.perf_counter() - w0
        cpu = time.process_time() - c0
        loop = ds.attrs["run_time_s"]
        if len(args.threads) > 1:
            key = (dt, nw, fes)
            if th == args.threads[0]:
                single.setdefault(key, ds)
            elif key in single:
                same = all(np.array_equal(ds[v].values, single[key][v].values,
                                          equal_nan=ds[v].dtype.kind == "f")
                           for v in ds.data_vars)
                print(f"    {th} thread(s) against {single[key].attrs.get('fe_threads', 1)}: "
                      f"{'identical' if same else 'DIFFERENT'}")
        if len(args.lanes) > 1:
            key = (dt, nw, fes, th)
            if ln == args.lanes[0]:
                by_lanes.setdefault(key, ds)
            elif key in by_lanes:
                same = all(np.array_equal(ds[v].values, by_lanes[key][v].values,
                                          equal_nan=ds[v].dtype.kind == "f")
                           for v in ds.data_vars)
                print(f"    lanes {ln} against lanes {args.lanes[0]}: "
                      f"{'identical' if same else 'DIFFERENT'}")
        sel = ds.time.values >= 1200.0
        tfe = ds.line_tension.values[sel].max(axis=0)
        tmax_line = ds.max_tension_along_line.values[sel].max()
        n_steps = ds.time.size - 1
        newton = ds.attrs["fe_newton_iterations"] / (12 * n_steps * ds.attrs["fe_substeps"])
        i = int(np.argmax(tfe))
        print(f"FE  dt {dt:g} newton {nw} catenary {args.catenary} fe_stages {fes} threads "
              f"{ds.attrs.get('fe_threads', 1)} lanes {ln} elements {el}: "
              f"loop {loop:.1f} s, setup {ds.attrs['setup_time_s']:.1f} s, "
              f"total {wall:.1f} s (CPU {cpu:.1f} s), {args.duration / loop:.1f} simulated s "
              f"per wall s; {newton:.2f} Newton iterations per line step, "
              f"{ds.attrs['fe_step_halvings']} halvings; load {_load()}")
        print(f"    max fairlead tension FE {tfe.max() / 1e3:.1f} kN (line "
              f"{ds.line.values[i]}); max along the line {tmax_line / 1e3:.1f} kN; mean surge FE "
              f"{ds.motion.values[sel, 0].mean():.3f} m; max offset FE "
              f"{np.hypot(*ds.motion.values[sel, :2].T).max():.3f} m")
        if dt in qs:
            print(f"    vs QS {qs[dt].max() / 1e3:.0f} kN: "
                  f"{(tfe.max() / qs[dt].max() - 1) * 100:+.1f} %; per line max FE/QS: "
                  + " ".join(f"{a / b:.3f}" for a, b in zip(tfe, qs[dt])))
        if args.per_line:
            tt = ds.time.values[sel]
            print("    per line max (kN) at (s): " + ", ".join(
                f"{m / 1e3:.2f}@{tt[k]:.1f}" for m, k in
                zip(tfe, ds.line_tension.values[sel].argmax(axis=0))))
        if dt in first:
            f0 = first[dt]
            print(f"    against newton {args.newton[0]}, fe_stages {args.fe_stages[0]}: max "
                  f"fairlead tension "
                  f"{(tfe.max() / f0.max() - 1) * 100:+.4f} %, per line max "
                  f"{np.abs(tfe / f0 - 1).max() * 100:.4f} % at most (line "
                  f"{ds.line.values[int(np.argmax(np.abs(tfe / f0 - 1)))]})")
        else:
            first[dt] = tfe


if __name__ == "__main__":
    main()
