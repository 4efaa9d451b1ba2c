"""Timing of the hydro layer: WAMIT read, netCDF save/load, retardation functions, report.

Usage: .venv/bin/python benchmarks/bench_hydro.py [vessels_dir]

The WAMIT files are read from vessels/oc3_hywind/source/ and vessels/oc4_semi/source/.
"""

import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from floatmoor.hydro import (
    consistency_report,
    load_database,
    load_vessel,
    read_wamit,
    retardation_function,
    save_database,
)

ROOT = Path(__file__).resolve().parents[1]
VESSELS = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "vessels"


def best(f, n=3):
    ts = []
    for _ in range(n):
        t0 = time.perf_counter()
        out = f()
        ts.append(time.perf_counter() - t0)
    return min(ts), out


warnings.simplefilter("ignore")
t, oc4 = best(lambda: read_wamit(VESSELS / "oc4_semi" / "source" / "marin_semi"))
print(f"read_wamit OC4 (.1 500 periods, .hst, .12d 9576 rows): {t * 1e3:.0f} ms")
t, oc3 = best(lambda: read_wamit(VESSELS / "oc3_hywind" / "source" / "Spar"))
print(f"read_wamit OC3 (.1, .3 100 x 37 x 6, .hst): {t * 1e3:.0f} ms")
with tempfile.TemporaryDirectory() as d:
    t, _ = best(lambda: save_database(oc4, Path(d) / "x.nc"))
    print(f"save_database OC4: {t * 1e3:.0f} ms")
    t, _ = best(lambda: load_database(Path(d) / "x.nc"))
    print(f"load_database OC4: {t * 1e3:.0f} ms")
B = oc4.radiation_damping.transpose("influenced_dof", "radiating_dof", "omega").values
tt = np.arange(0.0, 150.0, 0.05)
t, K = best(lambda: retardation_function(oc4.omega.values, B, tt))
print(f"retardation_function 6x6 x {oc4.omega.size} frequencies -> {tt.size} times: "
      f"{t * 1e3:.0f} ms")
t, rep = best(lambda: consistency_report(oc4), n=1)
print(f"consistency_report OC4 (K on {rep.time.size} times + reconstruction): {t:.2f} s")
t, rep = best(lambda: consistency_report(oc3), n=1)
print(f"consistency_report OC3: {t:.2f} s")
for name in ("oc3_hywind", "oc4_semi", "floatel_like"):
    p = ROOT / "vessels" / name / "vessel.yaml"
    if (p.parent / "database.nc").exists():
        t, _ = best(lambda: load_vessel(p))
        print(f"load_vessel {name}: {t * 1e3:.0f} ms")

# `floatmoor check` prints consistency_report of the scene's vessel database: its cost
# on the shipped databases, and the whole `floatmoor check` command in a fresh interpreter.
for name in ("oc3_hywind", "oc4_semi", "floatel_like"):
    p = ROOT / "vessels" / name / "vessel.yaml"
    if (p.parent / "database.nc").exists():
        v = load_vessel(p)
        t, _ = best(lambda: consistency_report(v.database))
        print(f"consistency_report shipped {name} ({v.database.omega.size} frequencies): "
              f"{t * 1e3:.0f} ms")
import subprocess  # noqa: E402

for scene in ("oc3_hywind", "floatel_100yr"):
    path = ROOT / "scenes" / f"{scene}.yaml"
    for extra in ([], ["--quick"]):
        cmd = [sys.executable, "-m", "floatmoor.cli", "check", *extra, str(path)]
        ts = []
        for _ in range(3):
            t0 = time.perf_counter()
            subprocess.run(cmd, check=True, capture_output=True, cwd=ROOT)
            ts.append(time.perf_counter() - t0)
        print(f"floatmoor check {' '.join(extra)} scenes/{scene}.yaml (new process): "
              f"{min(ts):.2f} s")
