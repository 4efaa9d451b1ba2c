"""Effect of the wave drift damping (Aranha) on the QS flagship, time and frequency domain.

Run:  .venv/bin/python benchmarks/wave_drift_damping_effect.py [--seeds 1-10] [--out FILE.json]

The flagship scene (``scenes/floatel_100yr.yaml``: Floatel-like semi, Heidrun 100-year storm,
head seas) with ``forces: {wave_drift_damping: false}`` (as shipped) and ``true``:

* frequency domain: the Aranha damping in the LF system (surge), LF surge std, mean and
  maximum surge, the largest eq. 2.49 line tension;
* time domain, every seed both ways (the same wave, wind and gust realisation): the LF surge
  std (zero-phase low-pass at 1/30 Hz, :func:`floatmoor.post.timeseries.lowpass`), the mean and
  maximum surge and the maximum fairlead tension of the most loaded line, over the 3-hour
  window after the transient; means over the seeds and the per-seed ratios.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import floatmoor  # noqa: E402
from floatmoor.io.forces_section import ForcesSpec  # noqa: E402
from floatmoor.post.timeseries import lowpass  # noqa: E402

SCENE = ROOT / "scenes" / "floatel_100yr.yaml"


def _seeds(text: str) -> list[int]:
    a, _, b = text.partition("-")
    return list(range(int(a), int(b or a) + 1))


def td_statistics(ds) -> dict:
    t = ds["time"].values
    keep = t >= ds.attrs["transient"]
    dt = float(t[1] - t[0])
    x = ds["motion"].values[:, 0]
    lf = lowpass(x, dt)[keep]
    tension = ds["line_tension"].values[keep]
    return {"lf_surge_std": float(np.std(lf)), "surge_std": float(np.std(x[keep])),
            "surge_mean": float(np.mean(x[keep])), "surge_max": float(np.max(x[keep])),
            "tension_max": float(np.max(tension)),
            "line": str(ds["line"].values[int(np.argmax(tension.max(axis=0)))]),
            "run_time_s": float(ds.attrs["run_time_s"])}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", default="1-10")
    ap.add_argument("--out", default=None)
    args = ap.parse_args(argv)
    warnings.simplefilter("ignore")
    scene = floatmoor.load_scene(SCENE)
    base = scene.forces or ForcesSpec(file=scene.file)
    variants = {"off": replace(scene, forces=replace(base, wave_drift_damping=False)),
                "on": replace(scene, forces=replace(base, wave_drift_damping=True))}
    out = {"scene": str(SCENE.relative_to(ROOT)), "fd": {}, "td": {k: [] for k in variants}}
    for k, sc in variants.items():
        r = floatmoor.frequency_domain_result(sc)
        out["fd"][k] = {"b_wave_drift_surge": float(r.lf_damping_wave_drift[0, 0]),
                        "lf_damping_surge": float(r.solution.lf_damping[0, 0]),
                        "lf_surge_std": float(r.lf_std[0]), "surge_mean": float(r.mean[0]),
                        "surge_max": float(r.max_total[0]),
                        "tension_max": float(np.nanmax(r.tension_max_total))}
        print(f"FD {k}: {out['fd'][k]}", flush=True)
    for seed in _seeds(args.seeds):
        for k, sc in variants.items():
            t0 = time.perf_counter()
            s = td_statistics(floatmoor.simulate(sc, seed=seed))
            s["seed"] = seed
            out["td"][k].append(s)
            print(f"TD {k} seed {seed} ({time.perf_counter() - t0:.1f} s): {s}", flush=True)
    for q in ("lf_surge_std", "surge_std", "surge_mean", "surge_max", "tension_max"):
        off = np.array([s[q] for s in out["td"]["off"]])
        on = np.array([s[q] for s in out["td"]["on"]])
        print(f"TD {q}: off {off.mean():.4g}, on {on.mean():.4g}, on/off per seed "
              f"{np.mean(on / off):.4f} (min {np.min(on / off):.4f}, max {np.max(on / off):.4f})")
    fd = out["fd"]
    for q in ("lf_surge_std", "surge_mean", "surge_max", "tension_max"):
        print(f"FD {q}: off {fd['off'][q]:.4g}, on {fd['on'][q]:.4g}, on/off "
              f"{fd['on'][q] / fd['off'][q]:.4f}")
    if args.out:
        Path(args.out).write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
