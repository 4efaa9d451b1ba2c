"""Cost of the load-dependent polyester stiffness in the coupled FE storm.

The flagship coupled FE storm with the `polyester_default` fibre model on the polyester
segments (scenes/floatel_100yr_fe_fibre.yaml) run with the FE option ``fibre_law``
``two_component`` (working curve in statics, dynamic stiffness about the filtered mean strain
in dynamics: floatmoor/mooring/fe/fibre_law.py) and ``constant`` (the constant EA of the line
type: the code path of lines without a fibre model), interleaved, each in a fresh process after
a warm-up run (numba cache).  Optionally the flagship scene itself on another checkout
(``--base DIR``, e.g. the code before the fibre law) in the same rotation.

Prints per run: CPU time of the process for the simulation (``time.process_time``), the loop
wall time, Newton iterations per line step, maximum fairlead tension after the transient,
mean surge.  The load average is printed with each run.

Run: ``.venv/bin/python benchmarks/bench_fibre_fe.py [--duration 3600] [--repeats 3]
[--base DIR]``
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
import warnings
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FIBRE = ROOT / "scenes" / "floatel_100yr_fe_fibre.yaml"
FLAGSHIP = "scenes/floatel_100yr_fe.yaml"


def _one(law: str, duration: float, dt: float, seed: int) -> None:
    """One run in this process: warm-up of 20 s, then the storm; prints one result line."""
    warnings.simplefilter("ignore")

    from floatmoor.analyses.simulate import simulate
    from floatmoor.io import load_scene
    from floatmoor.io.build import build

    if law == "flagship":
        scene = str(Path.cwd() / FLAGSHIP)
    else:
        scene = build(load_scene(FIBRE))
        lm = scene.mooring.line_models
        scene.mooring.line_models = replace(lm, options=replace(lm.options, fibre_law=law))
    simulate(scene, seed=seed, duration=20.0, dt=dt)
    c0 = time.process_time()
    ds = simulate(scene, seed=seed, duration=duration, dt=dt)
    cpu = time.process_time() - c0
    sel = ds.time.values >= min(1200.0, 0.5 * duration)
    n_steps = ds.time.size - 1
    newton = ds.attrs["fe_newton_iterations"] / (12 * n_steps * ds.attrs["fe_substeps"])
    load = " / ".join(f"{v:.2f}" for v in os.getloadavg())
    print(f"RESULT {law} cpu {cpu:.2f} loop {ds.attrs['run_time_s']:.2f} newton {newton:.3f} "
          f"halvings {ds.attrs['fe_step_halvings']} "
          f"tmax {ds.line_tension.values[sel].max() / 1e3:.1f} "
          f"surge {ds.motion.values[sel, 0].mean():.3f} load {load}", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=3600.0)
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--base", type=Path, default=None,
                    help="another checkout: its flagship FE scene joins the rotation")
    ap.add_argument("--one", default=None, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.one:
        _one(args.one, args.duration, args.dt, args.seed)
        return
    runs = [("two_component", ROOT), ("constant", ROOT)]
    if args.base is not None:
        runs += [("flagship", ROOT), ("flagship", args.base.resolve())]
    out = {}
    for rep in range(args.repeats):
        for law, tree in runs:
            env = dict(os.environ, PYTHONPATH=str(tree))
            cmd = [sys.executable, str(Path(__file__).resolve()), "--one", law, "--duration",
                   str(args.duration), "--dt", str(args.dt), "--seed", str(args.seed)]
            res = subprocess.run(cmd, env=env, cwd=tree, capture_output=True, text=True,
                                 check=True)
            line = [ln for ln in res.stdout.splitlines() if ln.startswith("RESULT")][-1]
            tag = f"{law}@{'base' if tree != ROOT else 'this'}"
            print(f"repeat {rep}: {tag}: {line[7:]}", flush=True)
            out.setdefault(tag, []).append(float(line.split()[3]))
    for tag, v in out.items():
        print(f"{tag}: CPU {', '.join(f'{x:.1f}' for x in v)} s (min {min(v):.1f}, "
              f"median {sorted(v)[len(v) // 2]:.1f})")
    if "two_component@this" in out:
        a = sorted(out["two_component@this"])
        b = sorted(out["constant@this"])
        print(f"two_component / constant: min {a[0] / b[0]:.3f}, median "
              f"{a[len(a) // 2] / b[len(b) // 2]:.3f}")


if __name__ == "__main__":
    main()
