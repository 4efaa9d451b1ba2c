"""Benchmark of the frequency-domain dynamic line tension (floatmoor.mooring.fe.frequency).

Run:  .venv/bin/python benchmarks/bench_fd_line.py

* one line: the OC3 line with 50 elements at 200 frequencies (surge sigma 0.5 m, JONSWAP shape
  Tp 10 s), every seabed model, drag iterated to convergence (target < 50 ms);
* the 12 Floatel-like lines of the 100-year sea state (scenes/floatel_100yr.yaml) under their WF
  fairlead motion from the FD RAOs: the frequency responses alone (lines already in static
  equilibrium; target < 0.5 s in total) and with the FE statics of the lines.
"""

from __future__ import annotations

import math
import sys
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from floatmoor.analyses.fd_line_dynamics import (
    N_LINE_FREQUENCIES,
    coarse_grid,
    dynamic_wf_tensions,
)
from floatmoor.analyses.frequency_domain import frequency_domain_result
from floatmoor.core.frames import rotation_matrix_into
from floatmoor.io.build import build
from floatmoor.metocean.spectra import jonswap
from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, Seabed
from floatmoor.mooring.fe.body import scene_line_inputs
from floatmoor.mooring.fe.frequency import frequency_response
from floatmoor.mooring.fe.from_system import spec_from_linedef
from floatmoor.mooring.line_types import LineType


def oc3_line(n=50):
    d = 0.09
    lt = LineType(name="oc3", material="user", diameter=d, mass_per_length=77.7066,
                  displaced_volume=math.pi * d * d / 4, ea=384.243e6, ea_dynamic=384.243e6,
                  mbs=6.0e6, cdn=1.6, cdt=0.1 * math.pi, can=1.0, cat=0.0)
    spec = FELineSpec(name="oc3", anchor=(853.87, 0.0, -320.0), fairlead=(5.2, 0.0, -70.0),
                      segments=(FESegment(line_type=lt, length=902.2, n_elements=n,
                                          internal_damping=-0.8),),
                      seabed=Seabed(depth=320.0))
    line = FELine(spec)
    line.solve_static()
    return line


def best(f, n):
    """Minimum wall time and minimum CPU time of the process (s) over ``n`` runs: on a shared,
    loaded machine the CPU time is the better measure of the work."""
    t, c = [], []
    for _ in range(n):
        t0 = time.perf_counter()
        c0 = time.process_time()
        f()
        c.append(time.process_time() - c0)
        t.append(time.perf_counter() - t0)
    return min(t), min(c)


def main():
    warnings.simplefilter("ignore")
    line = oc3_line()
    w = np.linspace(0.2, 2.5, 200)
    S = jonswap(w, 1.0, 10.0)
    psd = np.zeros((w.size, 3))
    psd[:, 0] = S / np.trapezoid(S, w) * 0.25
    frequency_response(line, w, psd)  # numba cache load
    print("one OC3 line, 50 elements, 200 frequencies (wall / CPU time, best of 10 runs):")
    for sb in ("least_squares", "pinned", "spring", "fe"):
        ds = frequency_response(line, w, psd, seabed=sb)
        tmin, tmed = best(lambda sb=sb: frequency_response(line, w, psd, seabed=sb), 10)
        tmin0, _ = best(lambda sb=sb: frequency_response(line, w, psd, seabed=sb, n_modes=0), 10)
        print(f"  {sb:14s} {1e3 * tmin:6.1f} / {1e3 * tmed:6.1f} ms ({ds.attrs['iterations']} "
              f"iterations; without the eigen-analysis {1e3 * tmin0:.1f} ms)")

    path = ROOT / "scenes" / "floatel_100yr.yaml"
    built = build(path)
    res = frequency_domain_result(built)
    system = built.mooring
    wf = res.model.omega
    mean = res.mean
    R = np.zeros((3, 3))
    rotation_matrix_into(mean[3], mean[4], mean[5], R)
    inputs = scene_line_inputs(built.scene, system)
    lines, spectra = [], []
    for ld in system.lines:
        spec = spec_from_linedef(ld, water_depth=system.water_depth, pose=mean,
                                 water_density=system.water_density, gravity=system.gravity,
                                 line_types=inputs["line_types"], **(inputs["current"] or {}))
        fl = FELine(spec)
        fl.solve_static()
        h = res.solution.rao[:, :3] + np.cross(res.solution.rao[:, 3:], R @ np.asarray(ld.fairlead))
        spectra.append(coarse_grid(wf, np.einsum("wi,wj->wij", h, h.conj())
                                   * res.model.wave_spectrum[:, None, None], N_LINE_FREQUENCIES))
        lines.append(fl)
    ne = [fl.n_nodes - 1 for fl in lines]

    def all_lines():
        for fl, (wc, Sc) in zip(lines, spectra):
            frequency_response(fl, wc, Sc, n_modes=0)

    tmin, tmed = best(all_lines, 3)
    print(f"Floatel-like 100-year: 12 lines ({min(ne)}-{max(ne)} elements), FD grid {wf.size} "
          f"frequencies, line model on {spectra[0][0].size}: frequency responses {tmin:.3f} / "
          f"{tmed:.3f} s (wall / CPU, best of 3)")
    tmin, tmed = best(lambda: dynamic_wf_tensions(built, mean, res.solution.rao, wf,
                                                  res.model.wave_spectrum), 3)
    print(f"  with the FE statics of the 12 lines (dynamic_wf_tensions): {tmin:.3f} / {tmed:.3f} s")


if __name__ == "__main__":
    main()
