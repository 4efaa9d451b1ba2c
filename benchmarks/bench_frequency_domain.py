"""Benchmark of the frequency-domain analysis.

Run:  .venv/bin/python benchmarks/bench_frequency_domain.py

* one sea state: the Floatel-like semi in the Heidrun 100-year storm (Hs 16 m, Tp 18.2 s,
  wind 36 m/s, current 0.94 m/s, head seas), scene and models already built (target < 0.5 s);
  also with the scene read and built from files;
* a sweep of 12 headings x 8 sea states on the same built scene (target < 30 s).
"""

from __future__ import annotations

import math
import sys
import tempfile
import time
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import yaml

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from floatmoor.analyses.frequency_domain import frequency_domain  # noqa: E402
from floatmoor.io.build import build  # noqa: E402

VESSEL = ROOT / "vessels" / "floatel_like"
ENV = {"waves": {"spectrum": "jonswap", "hs": 16.0, "tp": 18.2, "heading_deg": 0.0},
       "wind": {"spectrum": "npd", "u10": 36.0, "heading_deg": 0.0},
       "current": {"profile": "piecewise_linear", "levels": [[0.0, 0.94], [-50.0, 0.94]],
                   "heading_deg": 0.0}}
# (Hs m, Tp s): points on and inside the Heidrun 100-year contour (Wang (2016) section 5.3) and
# milder states
SEA_STATES = [(16.0, 18.2), (15.5, 15.5), (15.5, 19.8), (12.0, 14.0), (10.0, 12.0), (8.0, 11.0),
              (6.0, 10.0), (4.0, 8.0)]


def main():
    warnings.simplefilter("ignore")
    tmp = Path(tempfile.mkdtemp())
    sc = {"name": "bench-fd", "site": {"water_depth": 150.0, "water_density": 1025.0},
          "vessel": str(VESSEL / "vessel.yaml"), "mooring": str(VESSEL / "mooring.yaml"),
          "environment": ENV}
    path = tmp / "scene.yaml"
    path.write_text(yaml.safe_dump(sc, sort_keys=False))

    t0 = time.perf_counter()
    ds = frequency_domain(path)  # first call: imports, numba cache load
    t_first = time.perf_counter() - t0
    reps = []
    for _ in range(5):
        t0 = time.perf_counter()
        frequency_domain(path)
        reps.append(time.perf_counter() - t0)
    built = build(path)
    reps_b = []
    for _ in range(5):
        t0 = time.perf_counter()
        frequency_domain(built)
        reps_b.append(time.perf_counter() - t0)
    print(f"one sea state, first call (imports, numba cache): {t_first:.3f} s")
    print(f"one sea state, from the scene file: median {np.median(reps):.3f} s "
          f"(min {min(reps):.3f}, 5 runs)")
    print(f"one sea state, built scene: median {np.median(reps_b):.3f} s (min {min(reps_b):.3f})")
    print(f"  omega {ds.sizes['omega']} points, mu {ds.sizes['mu']} points, "
          f"{ds.sizes['line']} lines")

    scene = built.scene
    env = scene.environment
    t0 = time.perf_counter()
    n = 0
    worst = 0.0
    for hs, tp in SEA_STATES:
        for h in range(12):
            head = math.radians(30.0 * h)
            e = replace(env, waves=replace(env.waves, hs=hs, tp=tp, heading=head),
                        wind=replace(env.wind, heading=head),
                        current=replace(env.current, heading=head))
            b = replace(built, scene=replace(scene, environment=e))
            t1 = time.perf_counter()
            r = frequency_domain(b)
            worst = max(worst, time.perf_counter() - t1)
            n += 1
            assert np.isfinite(r.max_total.values).all()
    total = time.perf_counter() - t0
    print(f"sweep 12 headings x 8 sea states ({n} cases): {total:.2f} s "
          f"({total / n:.3f} s per case, slowest {worst:.3f} s)")


if __name__ == "__main__":
    main()
