"""The dry run's storm estimate against the storms the campaign then runs.

Interleaved rounds on the example campaign (``campaigns/floatel_uls_als.yaml``): (1) ``floatmoor
campaign ... --dry-run`` in a fresh process, its estimated cost of one storm parsed from the
output; (2) the campaign's first case alone (the case the dry run calibrates on: the first
contour sea state, heading 0, intact mooring), its storms run by ``floatmoor campaign
--scheduler serial`` as every campaign runs them, the measured cost per storm the tasks' CPU
time in their worker (scene, storm, statistics, writing; the wall time on an idle core, which
the estimate gives), their wall time printed beside it.  Printed per round:
the estimate, its spread over the calibration runs, the measured storms, the ratio and the load.

Run:  PYTHONPATH=. python benchmarks/bench_dry_run.py [--rounds 3] [--seeds 2]
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "campaigns" / "floatel_uls_als.yaml"
FIRST_CASE = """name: first-case
base_scene: {base}
sea_states: {{contour: {contour}, only: [1]}}
headings: {{waves_deg: [0]}}
conditions: {{intact: true}}
seeds: "1-{n}"
screening: {{time_domain: all}}
storage: {{mode: statistics, precision: float32, compression: 4,
          sampling: {{line_tension: 0.0, motion: 0.5, wave_elevation: 0.5}}}}
"""


def _load() -> str:
    return f"{os.getloadavg()[0]:.1f}"


def dry_run() -> tuple[float, float, float, str]:
    """(estimated storm s, low, high, the calibration line) of a fresh ``--dry-run``."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-m", "floatmoor", "campaign", str(EXAMPLE),
                          "--dry-run"], capture_output=True, text=True, env=env, timeout=1800)
    line = next(ln for ln in out.stdout.splitlines() if ln.startswith("calibration"))
    m = re.search(r"storm ([0-9.]+) s .*; ([0-9.]+)-([0-9.]+) s over", line)
    return float(m.group(1)), float(m.group(2)), float(m.group(3)), line


def storms(n_seeds: int) -> tuple[list[float], list[float]]:
    """(CPU s, wall s) of each of the first case's storms, run by a serial campaign (the task's
    CPU time in its worker process: the wall time on an idle core)."""
    from floatmoor.campaign.engine import run_campaign
    cpu, wall = [], []

    def seen(o):
        if o["kind"] == "td" and o["status"] == "done":
            cpu.append(float(o["cpu_s"]))
            wall.append(float(o["wall_time_s"]))

    with tempfile.TemporaryDirectory() as tmp:
        camp = Path(tmp) / "first.yaml"
        camp.write_text(FIRST_CASE.format(base=ROOT / "scenes" / "floatel_100yr.yaml",
                                          contour=ROOT / "metocean" / "heidrun_contour.yaml",
                                          n=n_seeds))
        run_campaign(camp, Path(tmp) / "out", scheduler="serial", echo=None, on_outcome=seen)
    return cpu, wall


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--seeds", type=int, default=3, help="storms per round (>= 3)")
    a = p.parse_args(argv)
    rows = []
    for r in range(a.rounds):
        l0 = _load()
        est, lo, hi, line = dry_run()
        l1 = _load()
        cpu, wall = storms(max(3, a.seeds))
        l2 = _load()
        # the first storm of a fresh worker loads its caches: the steady storms are the others
        steady = sorted(cpu[1:]) if len(cpu) > 1 else cpu
        meas = steady[len(steady) // 2]
        rows.append((est, lo, hi, meas))
        print(f"round {r + 1}: estimate {est:.2f} s ({lo:.2f}-{hi:.2f}; load {l0}-{l1}); "
              f"storms CPU {', '.join(f'{x:.2f}' for x in cpu)} s, wall "
              f"{', '.join(f'{x:.2f}' for x in wall)} s (CPU median after the first "
              f"{meas:.2f} s; load {l1}-{l2}); estimate / measured {est / meas:.2f}",
              flush=True)
    ests = [r[0] for r in rows]
    meas = [r[3] for r in rows]
    print(f"estimates {min(ests):.2f}-{max(ests):.2f} s over {len(rows)} dry runs (spread "
          f"{100 * (max(ests) / min(ests) - 1):.0f} %); measured storms (CPU) "
          f"{min(meas):.2f}-{max(meas):.2f} s; estimate / measured "
          f"{min(e / m for e, m in zip(ests, meas)):.2f}-"
          f"{max(e / m for e, m in zip(ests, meas)):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
