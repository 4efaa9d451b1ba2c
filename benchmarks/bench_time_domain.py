"""Time-domain benchmark: a 3-hour storm of the Floatel-like semi.

12 quasi-static lines, first-order waves, Newman drift, NPD wind, current, radiation memory,
dt = 0.1 s, 10800 s simulated.  Prints

* numba compilation: a first short run in a fresh subprocess with an empty numba cache
  (``NUMBA_CACHE_DIR`` in a temp folder) -- compile from scratch -- and with the project's
  cache (cache load);
* the 3-hour run: setup (scene build, realisations, FFT series, retardation functions, static
  equilibrium, the linear WF velocity for the wind/current relative velocity) and the time loop
  separately, and the real-time factor of the loop and of the
  whole call.

Run: ``.venv/bin/python benchmarks/bench_time_domain.py [--duration 10800] [--dt 0.1]
[--solver catenary=predictor,memory=state_space]``

``--compile-profile``: instead, the first run's compilation function by function (a 60 s run
in a fresh subprocess with an empty numba cache): numba's compile events, nested, inclusive CPU
seconds and the CPU spent holding LLVM's lock (optimisation and machine code) inside each.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"

_FIRST = """
import time, warnings
warnings.simplefilter("ignore")
t0 = time.perf_counter()
from floatmoor.analyses.simulate import simulate
ds = simulate({scene!r}, seed=1, duration=60.0, dt=0.1)
print(time.perf_counter() - t0)
"""


_PROFILE = """
import time, warnings
t_start = time.process_time()
from numba.core import event
stack, rows = [], []
class Compile(event.Listener):
    def on_start(self, ev):
        stack.append([time.process_time(), 0.0])
    def on_end(self, ev):
        t0, llvm = stack.pop()
        rows.append((len(stack), ev.data["dispatcher"].py_func.__qualname__,
                     time.process_time() - t0, llvm))
        if stack:
            stack[-1][1] += llvm
class Llvm(event.Listener):
    def on_start(self, ev):
        self.t0 = time.process_time()
    def on_end(self, ev):
        if stack:
            stack[-1][1] += time.process_time() - self.t0
event.register("numba:compile", Compile())
event.register("numba:llvm_lock", Llvm())
warnings.simplefilter("ignore")
from floatmoor.analyses.simulate import simulate
t_import = time.process_time()
simulate({scene!r}, seed=1, duration=60.0, dt=0.1)
t_end = time.process_time()
print("function (latest first; indented: compiled for its caller)  CPU s  of which LLVM")
for depth, name, cpu, llvm in reversed(rows):
    print(f"{{'  ' * depth + name:52s}} {{cpu:6.2f}}  {{llvm:6.2f}}")
top = sum(r[2] for r in rows if r[0] == 0)
print(f"imports {{t_import - t_start:.2f}} s, all compilation {{top:.2f}} s, whole process "
      f"{{t_end - t_start:.2f}} s (CPU)")
"""


def compile_profile() -> None:
    """Print the compile profile of a first run (empty numba cache, fresh process)."""
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, NUMBA_CACHE_DIR=tmp)
        out = subprocess.run([sys.executable, "-c", _PROFILE.format(scene=str(SCENE))],
                             env=env, capture_output=True, text=True, check=True)
    print(out.stdout)


def first_run(cache_dir: str | None) -> float:
    env = dict(os.environ)
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = cache_dir
    out = subprocess.run([sys.executable, "-c", _FIRST.format(scene=str(SCENE))], env=env,
                         capture_output=True, text=True, check=True)
    return float(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=10800.0)
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--solver", default=None, metavar="KEY=VALUE[,KEY=VALUE]",
                    help="solver options, e.g. catenary=predictor,memory=state_space")
    ap.add_argument("--extreme", action="store_true",
                    help="instead: dt sweep of the storm / taut / slack cases (1200 s each)")
    ap.add_argument("--compile-profile", action="store_true",
                    help="instead: the first run's compilation, function by function")
    args = ap.parse_args()
    if args.compile_profile:
        compile_profile()
        return
    if args.extreme:
        extreme()
        return
    import numba
    import numpy as np

    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python "
          f"{platform.python_version()}, numba {numba.__version__}")
    with tempfile.TemporaryDirectory() as tmp:
        t_fresh = first_run(tmp)
    t_cached = first_run(None)
    print(f"first 60 s run in a new process: empty numba cache {t_fresh:.2f} s (compile), "
          f"project cache {t_cached:.2f} s (cache load + imports)")

    warnings.simplefilter("ignore")
    from floatmoor.analyses.simulate import simulate

    solver = None
    if args.solver:
        from floatmoor.commands.convergence import parse_solver_option
        solver = parse_solver_option(args.solver)
        print(f"solver options: {solver.describe()}")
    simulate(SCENE, seed=args.seed, duration=60.0, dt=args.dt, solver=solver)  # load kernels
    t0 = time.perf_counter()
    ds = simulate(SCENE, seed=args.seed, duration=args.duration, dt=args.dt, solver=solver)
    total = time.perf_counter() - t0
    loop = ds.attrs["run_time_s"]
    setup = ds.attrs["setup_time_s"]
    n = ds.sizes["time"] - 1
    print(f"scene {SCENE.name}: {args.duration:g} s at dt {args.dt:g} s ({n} RK4 steps), "
          f"models {', '.join(ds.attrs['models'])}, {ds.sizes.get('line', 0)} lines, wind and "
          f"current relative to the {ds.attrs['relative_velocity']} body velocity")
    print(f"setup (build, realisations, FFT series, retardation, statics): {setup:.2f} s")
    print(f"time loop: {loop:.2f} s = {1e6 * loop / n:.1f} us/step, "
          f"{args.duration / loop:.0f}x real time")
    print(f"whole simulate() call: {total:.2f} s, {args.duration / total:.0f}x real time")
    t = ds["time"].values
    sel = t >= 1200.0
    m = ds["motion"].values[sel]
    off = np.hypot(m[:, 0], m[:, 1])
    T = ds["line_tension"].values[sel] / 1e3
    i = int(np.argmax(T.max(0)))
    print(f"after 1200 s: offset mean {off.mean():.2f} m, std {off.std():.2f} m, max "
          f"{off.max():.2f} m; most loaded line {ds['line'].values[i]} mean {T[:, i].mean():.0f}"
          f" kN, std {T[:, i].std():.0f} kN, max {T[:, i].max():.0f} kN")


def extreme(duration: float = 1200.0) -> None:
    """Largest stable dt of the three extreme cases of tests/solvers/test_time_domain_extreme.py
    (max tension within 5 % of the dt = 0.05 s run)."""
    import numpy as np

    sys.path.insert(0, str(ROOT))
    from floatmoor.analyses.simulate import simulate
    from floatmoor.core.errors import NumericalError
    from tests.solvers.test_time_domain_extreme import extreme_scene

    warnings.simplefilter("ignore")
    with tempfile.TemporaryDirectory() as tmp:
        for kind in ("storm", "taut", "slack"):
            path = extreme_scene(Path(tmp), kind)
            print(f"case {kind} ({duration:g} s, seed 1):")
            ref = None
            best = None
            for dt in (0.05, 0.1, 0.2, 0.4, 0.8, 1.6):
                try:
                    ds = simulate(path, seed=1, dt=dt, duration=duration)
                except NumericalError as exc:
                    print(f"  dt {dt:5.2f} s: {exc}")
                    continue
                m = ds["motion"].values
                tmax = ds["line_tension"].values.max()
                if ref is None:
                    ref = tmax
                err = tmax / ref - 1.0
                if abs(err) < 0.05:
                    best = dt
                print(f"  dt {dt:5.2f} s: max offset {np.hypot(m[:, 0], m[:, 1]).max():7.2f} m, "
                      f"max tension {tmax / 1e3:8.0f} kN ({100 * err:+.2f} %), loop "
                      f"{ds.attrs['run_time_s']:.2f} s, omega_max dt "
                      f"{2 * np.pi / ds.attrs['stiffest_mode_period_s'] * dt:.3f}")
            print(f"  largest dt with max tension within 5 %: {best} s")


if __name__ == "__main__":
    main()
