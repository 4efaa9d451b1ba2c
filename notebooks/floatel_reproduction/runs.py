"""Per-seed summaries of the calibrated Floatel runs (imported by notebooks/floatel_reproduction.ipynb).

One seed = ``floatmoor.simulate(scene, seed=s)`` and ``floatmoor.post.timeseries.statistics``
over the window after the transient: surge mean, std, max, the low-pass (1/30 Hz) maximum
``lf_max`` (mean included, as Wang's (2016) SIMO filter), the low-pass std, the WF std, and for
every line mean, std and max tension (kN).  One CSV row per seed, cached in ``CACHE``
(``FLOATMOOR_NB_CACHE`` overrides): a rerun computes only missing seeds.

Command line (to fill the cache outside the notebook):  python runs.py case1 1-20
"""

from __future__ import annotations

import os
import sys
import time
import warnings
from pathlib import Path

import pandas as pd

from floatmoor.io.analysis import seeds_from_text

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
CACHE = Path(os.environ.get("FLOATMOOR_NB_CACHE",
                            ROOT / "notebooks" / "data" / "floatel_reproduction"))
LINES = [f"line{j}" for j in range(1, 13)]


def summary_row(ds) -> dict:
    """Surge and line-tension statistics of one run after its transient (one CSV row)."""
    from floatmoor.post.timeseries import statistics
    st = statistics(ds, start=float(ds.attrs["transient"]), variables=["motion", "line_tension"])
    row = {"seed": int(ds.attrs["seed"]), "run_time_s": float(ds.attrs["run_time_s"])}
    for k in ("max", "mean", "std", "lf_max", "lf_std", "wf_std"):
        if f"motion_{k}" in st:
            row[f"surge_{k}"] = float(st[f"motion_{k}"].sel(dof="surge"))
    for name in LINES:
        for k in ("max", "mean", "std"):
            row[f"{name}_{k}"] = float(st[f"line_tension_{k}"].sel(line=name)) / 1e3  # kN
    return row


def run_case(key: str, seeds) -> pd.DataFrame:
    """Summaries of ``HERE/<key>.yaml`` for ``seeds``, computing (and caching) missing seeds."""
    import floatmoor
    CACHE.mkdir(parents=True, exist_ok=True)
    csv = CACHE / f"{key}.csv"
    df = pd.read_csv(csv) if csv.is_file() else pd.DataFrame()
    done = set(df["seed"]) if len(df) else set()
    for seed in seeds:
        if seed in done:
            continue
        t0 = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = floatmoor.simulate(HERE / f"{key}.yaml", seed=seed)
            row = summary_row(ds)
        row["wall_s"] = time.perf_counter() - t0
        # re-read: another process may have added seeds meanwhile
        df = pd.read_csv(csv) if csv.is_file() else pd.DataFrame()
        df = pd.concat([df, pd.DataFrame([row])], ignore_index=True)
        df = df.drop_duplicates("seed", keep="last").sort_values("seed")
        df.to_csv(csv, index=False, float_format="%.6g")
        print(f"{key} seed {seed}: {row['wall_s']:.1f} s, max surge {row['surge_max']:.2f} m",
              flush=True)
    return df[df["seed"].isin(list(seeds))].sort_values("seed").reset_index(drop=True)


if __name__ == "__main__":
    run_case(sys.argv[1], list(seeds_from_text(sys.argv[2])))
