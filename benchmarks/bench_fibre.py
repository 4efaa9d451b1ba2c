"""Cost of the load-dependent fibre-rope stiffness on the flagship QS storm.

The Floatel-like 100-year storm (``scenes/floatel_100yr.yaml``: 12 chain-polyester-chain
quasi-static lines, waves, drift, wind, current, radiation memory, dt 0.1 s) run with the
constant polyester EA of the shipped mooring and with the ``polyester_default`` fibre model
(working curve in statics, dynamic stiffness about the slowly varying tension in the time
loop, the default ``fibre_time_constant`` 300 s) and with that model under the fixed-mean rule
(``fibre_time_constant: .inf``), interleaved (constant, fibre, fixed, constant, ...), each in this process after one warm-up run of both.
Prints the CPU time (``time.process_time``) of each ``simulate`` call and of its time loop
(``run_time_s`` is wall), and the ratio of the best CPU times.

Run: ``.venv/bin/python benchmarks/bench_fibre.py [--duration 12000] [--repeats 2]``
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"
FL = ROOT / "vessels" / "floatel_like"


def fibre_scene(folder: Path, tau: str = "") -> Path:
    """The flagship scene with the polyester line type given ``fibre: polyester_default``
    (and the mooring key ``fibre_time_constant: tau`` when given)."""
    text = (FL / "mooring.yaml").read_text()
    if tau:
        text = f"fibre_time_constant: {tau}\n" + text
    key = "    source: Wang (2016) table 5.2 (E, MBS, Cd); mass from catalogue fit\n"
    i = text.rindex(key) + len(key)
    name = f"mooring_fibre{'_inf' if tau else ''}.yaml"
    (folder / name).write_text(text[:i] + "    fibre: polyester_default\n" + text[i:])
    scene = SCENE.read_text().replace("../vessels/floatel_like/mooring.yaml", name)
    scene = scene.replace("../", str(ROOT) + os.sep)
    p = folder / f"floatel_100yr_fibre{'_inf' if tau else ''}.yaml"
    p.write_text(scene)
    return p


def one(scene, duration):
    from floatmoor.analyses.simulate import simulate
    c0, w0 = time.process_time(), time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = simulate(scene, seed=1, duration=duration)
    return (time.process_time() - c0, time.perf_counter() - w0, float(ds.attrs["run_time_s"]),
            float(ds["line_tension"].max()) / 1e3)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=12000.0)
    ap.add_argument("--repeats", type=int, default=2)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        scenes = {"constant EA": SCENE, "fibre model": fibre_scene(Path(tmp)),
                  "fibre fixed": fibre_scene(Path(tmp), ".inf")}
        for s in scenes.values():  # warm-up (numba cache load, database read)
            one(s, 60.0)
        rows = {k: [] for k in scenes}
        for r in range(args.repeats):
            for k, s in scenes.items():
                cpu, wall, loop, tmax = one(s, args.duration)
                rows[k].append(cpu)
                print(f"repeat {r + 1} {k:12s}: CPU {cpu:7.1f} s, wall {wall:7.1f} s, loop wall "
                      f"{loop:7.1f} s, max tension {tmax:7.0f} kN", flush=True)
        best = {k: min(v) for k, v in rows.items()}
        print(f"best CPU: constant {best['constant EA']:.1f} s, fibre {best['fibre model']:.1f} s,"
              f" ratio {best['fibre model'] / best['constant EA']:.3f}; fibre fixed-mean "
              f"{best['fibre fixed']:.1f} s")
        print(f"load: {os.getloadavg()}")


if __name__ == "__main__":
    main()
