"""Per-line tension statistics of the coupled FE flagship storm (scenes/floatel_100yr_fe.yaml:
12 lines, 3 hours after a 1200 s transient) over several seeds, against a converged run.

Each run stores its fairlead tensions after the transient (``--out`` folder, one ``.npz`` per
setting and seed) with its CPU time; ``--compare`` prints, for every line, the mean over the
seeds of the 3-hour maximum and of the tension standard deviation, and their differences from
the reference setting (the issue's accuracy criterion: within 1 % of a converged run, dt 0.05 s
and twice the elements).

Run: ``python benchmarks/bench_coupled_fe_accuracy.py --seeds 1 2 3 --dt 0.1 --elements 50
--newton force --tag fast --out DIR`` (``--elements``: ``scene`` the scene's mesh, the default,
an element count per line shared by length, or counts per segment ``12,26,12``) (one setting; runs already in ``DIR`` are skipped), and
``python benchmarks/bench_coupled_fe_accuracy.py --out DIR --compare REF TAG [TAG ...]``.
``--scene PATH`` another FE scene (e.g. scenes/floatel_100yr_fe_fibre.yaml).
Options as in the scene: ``--fe-stages catenary|linear``, ``--fe-stiffness-interval S``,
``--threads N``.  CPU times are
``time.process_time`` of the whole ``simulate`` (setup included); the load average is printed
with them (the machine may be shared).
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"
TRANSIENT = 1200.0


def _load():
    return " / ".join(f"{v:.2f}" for v in os.getloadavg())


def run(args):
    from floatmoor.analyses.simulate import simulate
    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.io.solver_section import SolverSpec

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for seed in args.seeds:
        path = out / f"{args.tag}_seed{seed}.npz"
        if path.exists():
            print(f"{path.name}: exists, skipped")
            continue
        built = build(load_scene(args.scene))
        lm = built.mooring.line_models
        opts = dataclasses.replace(lm.options, newton=args.newton)
        if args.elements != "scene":
            counts = tuple(int(v) for v in args.elements.split(","))
            if min(counts) < 1:
                raise SystemExit(f"--elements: counts >= 1, found {args.elements}")
            opts = dataclasses.replace(opts, n_elements=counts[0] if len(counts) == 1
                                       else counts)
        object.__setattr__(lm, "options", opts)
        solver = SolverSpec(threads=args.threads, fe_stages=args.fe_stages,
                            fe_stiffness_interval=args.fe_stiffness_interval)
        simulate(built, seed=seed, duration=20.0, dt=args.dt, solver=solver)   # cache load
        load0 = _load()
        c0 = time.process_time()
        w0 = time.perf_counter()
        ds = simulate(built, seed=seed, duration=args.duration, dt=args.dt, solver=solver)
        cpu = time.process_time() - c0
        wall = time.perf_counter() - w0
        sel = ds.time.values >= TRANSIENT
        T = ds.line_tension.values[sel]
        n_steps = ds.time.size - 1
        its = ds.attrs["fe_newton_iterations"] / (12 * n_steps * ds.attrs["fe_substeps"])
        np.savez(path, tension=T, time=ds.time.values[sel], cpu=cpu, wall=wall,
                 loop=ds.attrs["run_time_s"], iterations=its,
                 halvings=ds.attrs["fe_step_halvings"], lines=ds.line.values.astype(str),
                 max_along=ds.max_tension_along_line.values[sel].max(axis=0))
        mesh = "x".join(str(n) for n in np.atleast_1d(opts.n_elements)) if \
            opts.n_elements is not None else f"{opts.element_length:g} m"
        print(f"{args.tag} seed {seed}: dt {args.dt:g} s, elements {mesh}, newton "
              f"{args.newton}, fe_stages {args.fe_stages} (stiffness every "
              f"{args.fe_stiffness_interval:g} s), threads {args.threads}: CPU "
              f"{cpu:.1f} s, wall {wall:.1f} s (loop {ds.attrs['run_time_s']:.1f} s), "
              f"{its:.3f} Newton iterations per line step, {ds.attrs['fe_step_halvings']} "
              f"halvings; load {load0} -> {_load()}", flush=True)


def compare(args):
    out = Path(args.out)
    ref, *tags = args.compare

    def stats(tag):
        files = sorted(out.glob(f"{tag}_seed*.npz"))
        if not files:
            raise SystemExit(f"no runs {tag}_seed*.npz in {out}")
        seeds = [f.stem.split("seed")[-1] for f in files]
        d = [np.load(f) for f in files]
        mx = np.mean([x["tension"].max(axis=0) for x in d], axis=0)
        sd = np.mean([x["tension"].std(axis=0) for x in d], axis=0)
        cpu = [float(x["cpu"]) for x in d]
        return seeds, mx, sd, cpu, d[0]["lines"]

    s0, mx0, sd0, cpu0, lines = stats(ref)
    print(f"reference {ref}: seeds {' '.join(s0)}, CPU per storm "
          + " ".join(f"{c:.1f}" for c in cpu0) + " s")
    print("  line          " + " ".join(f"{n:>9s}" for n in lines))
    print("  mean max kN   " + " ".join(f"{v / 1e3:9.1f}" for v in mx0))
    print("  mean std kN   " + " ".join(f"{v / 1e3:9.2f}" for v in sd0))
    for tag in tags:
        s, mx, sd, cpu, _ = stats(tag)
        if s != s0:
            print(f"{tag}: seeds {s} differ from the reference's {s0}")
        dm = (mx / mx0 - 1) * 100
        ds = (sd / sd0 - 1) * 100
        print(f"{tag}: seeds {' '.join(s)}, CPU per storm " + " ".join(f"{c:.1f}" for c in cpu)
              + f" s; mean max within {np.abs(dm).max():.3f} %, mean std within "
              f"{np.abs(ds).max():.3f} % of {ref}")
        print("  max  diff %  " + " ".join(f"{v:+9.3f}" for v in dm))
        print("  std  diff %  " + " ".join(f"{v:+9.3f}" for v in ds))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--scene", default=str(FE),
                    help="the scene (default scenes/floatel_100yr_fe.yaml; its lines FE)")
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--elements", default="scene",
                    help="scene (the scene's mesh), N per line or a,b,c per segment")
    ap.add_argument("--newton", default="force")
    ap.add_argument("--fe-stages", default="linear", choices=("catenary", "linear"))
    ap.add_argument("--fe-stiffness-interval", type=float, default=1.0)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--duration", type=float, default=12000.0)
    ap.add_argument("--tag", default=None)
    ap.add_argument("--compare", nargs="+", default=None)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    if args.compare:
        compare(args)
        return
    if args.tag is None:
        args.tag = (f"dt{args.dt:g}_n{args.elements.replace(',', '-')}_{args.newton}_"
                    f"{args.fe_stages}_t{args.threads}")
    run(args)


if __name__ == "__main__":
    main()
