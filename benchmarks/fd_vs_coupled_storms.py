"""Coupled time-domain storms of the Floatel-like 100-year case for the frequency-domain dynamic
line tension (notebooks/fd_line_dynamics.ipynb reads what this writes).

Per seed: ``floatmoor.simulate`` of scenes/floatel_100yr_fe.yaml (12 FE lines coupled to the
body, "fe"; 50 elements per line shared by length, the mesh of the stored rows) or of scenes/floatel_100yr.yaml (quasi-static catenary lines, "qs"), then
``floatmoor.post.timeseries.statistics`` after the transient (the post-processing's LF/WF
separation: zero-phase Butterworth low-pass at 1/30 Hz, WF = signal - LF).  One CSV row per
(model, seed): the WF, LF and total std, mean and maximum tension of every line (kN), and the
mean, LF and WF std of surge, heave (m) and pitch (deg).  Rows already in the file are kept (a
rerun computes only the missing seeds).

Run:  PYTHONPATH=. python benchmarks/fd_vs_coupled_storms.py fe 1-6 [--duration 4800]
      [--transient 1200] [--out notebooks/data/fd_line_dynamics/coupled_storms.csv]
"""

from __future__ import annotations

import argparse
import math
import os
import time
import warnings
from pathlib import Path

import pandas as pd

from floatmoor.io.analysis import seeds_from_text

ROOT = Path(__file__).resolve().parents[1]
SCENES = {"fe": ROOT / "scenes" / "floatel_100yr_fe.yaml",
          "qs": ROOT / "scenes" / "floatel_100yr.yaml"}
OUT = ROOT / "notebooks" / "data" / "fd_line_dynamics" / "coupled_storms.csv"


STORMS_N_ELEMENTS = 50
"""Elements per line of the "fe" rows (shared among the segments by length), the mesh of the
stored rows of 2026-11-24; the scene gives its elements per segment since 2026-11-28
([12, 26, 12], benchmarks/RESULTS.md "A mesh by segment"), so a rerun keeps the rows' mesh."""


def _scene(model: str):
    """The scene of ``model``; for "fe" with :data:`STORMS_N_ELEMENTS` per line."""
    import dataclasses

    import yaml

    import floatmoor
    scene = floatmoor.load_scene(SCENES[model])
    if model != "fe":
        return scene
    mooring = scene.mooring
    if not isinstance(mooring, dict):
        mooring = yaml.safe_load(Path(mooring).read_text())
    mooring = {**mooring, "finite_element": {**mooring.get("finite_element", {}),
                                             "n_elements": STORMS_N_ELEMENTS}}
    return dataclasses.replace(scene, mooring=mooring)


def summary_row(ds, model: str) -> dict:
    """Line tension and motion statistics of one run after its transient (kN, m, deg)."""
    from floatmoor.post.timeseries import statistics
    st = statistics(ds, start=float(ds.attrs["transient"]), variables=["motion", "line_tension"])
    row = {"model": model, "seed": int(ds.attrs["seed"]),
           "window_s": float(ds.time.values[-1]) - float(ds.attrs["transient"]),
           "loop_s": float(ds.attrs["run_time_s"])}
    for dof, f in (("surge", 1.0), ("heave", 1.0), ("pitch", 180.0 / math.pi)):
        for k in ("mean", "lf_std", "wf_std"):
            row[f"{dof}_{k}"] = f * float(st[f"motion_{k}"].sel(dof=dof))
    for name in ds.line.values:
        for k in ("mean", "std", "lf_std", "wf_std", "max"):
            row[f"{name}_{k}"] = float(st[f"line_tension_{k}"].sel(line=name)) / 1e3
    return row


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("model", choices=sorted(SCENES))
    ap.add_argument("seeds", type=seeds_from_text)
    ap.add_argument("--duration", type=float, default=4800.0)
    ap.add_argument("--transient", type=float, default=1200.0)
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    import floatmoor
    args.out.parent.mkdir(parents=True, exist_ok=True)
    for seed in args.seeds:
        df = pd.read_csv(args.out) if args.out.is_file() else pd.DataFrame()
        if len(df) and ((df["model"] == args.model) & (df["seed"] == seed)).any():
            continue
        t0, c0 = time.perf_counter(), time.process_time()
        ds = floatmoor.simulate(_scene(args.model), seed=seed, duration=args.duration,
                                transient=args.transient)
        row = summary_row(ds, args.model)
        row["wall_s"] = time.perf_counter() - t0
        row["cpu_s"] = time.process_time() - c0
        df = pd.read_csv(args.out) if args.out.is_file() else pd.DataFrame()
        df = pd.concat([df, pd.DataFrame([row])], ignore_index=True)
        df = df.drop_duplicates(["model", "seed"], keep="last").sort_values(["model", "seed"])
        df.to_csv(args.out, index=False, float_format="%.6g")
        load = " / ".join(f"{v:.1f}" for v in os.getloadavg())
        print(f"{args.model} seed {seed}: wall {row['wall_s']:.0f} s, CPU {row['cpu_s']:.0f} s "
              f"(loop {row['loop_s']:.0f} s), load {load}", flush=True)


if __name__ == "__main__":
    main()
