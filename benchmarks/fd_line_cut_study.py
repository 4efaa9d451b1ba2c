"""The cut point of the least-squares touchdown springs (Ong & Pellegrino (2003)) on cases that
did not choose its default (``cut_fraction=0.05`` was chosen on the OC3 line, surge Tp 10 s,
seeds 1-4, sigma 0.25-1.5 m).

Cases: the OC3 line (Jonkman (2010), 50 elements) under JONSWAP-shaped surge of peak period 7
and 14 s, seeds 11-14; and two Floatel-like chain-polyester-chain lines (Wang (2016), the 50-
element lines of scenes/floatel_100yr_fe.yaml; line 1 slack, line 6 taut) under their WF
fairlead motion in the 100-year sea state (FD RAO at the mean pose, periodic realisations,
seeds 11-14).  Prints, per case, the time-domain FE fairlead tension std (``run_prescribed``)
and FD / TD - 1 for the cut fractions 0, 0.05, 0.1, 0.2 and for the other seabed models, and
the margin ``V0 / sigma_V`` of the static vertical force at the cut over its std.

Run:  PYTHONPATH=. python benchmarks/fd_line_cut_study.py
"""

from __future__ import annotations

import math
import os
import sys
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

CUTS = (0.0, 0.05, 0.1, 0.2)
SEEDS = (11, 12, 13, 14)


def oc3_cases():
    from floatmoor.metocean.spectra import jonswap
    from floatmoor.mooring.fe import FELine, FELineSpec, FESegment, Seabed
    from floatmoor.mooring.line_types import LineType
    d = 0.09
    lt = LineType(name="oc3", material="user", diameter=d, mass_per_length=77.7066,
                  displaced_volume=math.pi * d * d / 4, ea=384.243e6, ea_dynamic=384.243e6,
                  mbs=6.0e6, cdn=1.6, cdt=0.1 * math.pi, can=1.0, cat=0.0)
    spec = FELineSpec(name="oc3", anchor=(853.87, 0.0, -320.0), fairlead=(5.2, 0.0, -70.0),
                      segments=(FESegment(line_type=lt, length=902.2, n_elements=50,
                                          internal_damping=-0.8),),
                      seabed=Seabed(depth=320.0))
    line = FELine(spec)
    line.solve_static()
    w = np.linspace(0.2, 2.5, 200)
    for tp, sig in ((7.0, 0.5), (7.0, 1.0), (14.0, 0.5), (14.0, 1.5)):
        S = jonswap(w, 1.0, tp)
        psd = np.zeros((w.size, 3))
        psd[:, 0] = S / np.trapezoid(S, w) * sig ** 2
        yield f"OC3, surge Tp {tp:g} s, sigma {sig:g} m", line, w, psd


def floatel_cases():
    from floatmoor.analyses.fd_line_dynamics import coarse_grid
    from floatmoor.analyses.frequency_domain import frequency_domain_result
    from floatmoor.core.frames import rotation_matrix_into
    from floatmoor.io.build import build
    from floatmoor.mooring.fe import FELine
    from floatmoor.mooring.fe.body import scene_line_inputs
    from floatmoor.mooring.fe.from_system import spec_from_linedef
    built = build(ROOT / "scenes" / "floatel_100yr_fe.yaml")
    res = frequency_domain_result(built)
    system = built.mooring
    kw = system.line_models.options.spec_kw(system.water_depth)
    inputs = scene_line_inputs(built.scene, system)
    R = np.zeros((3, 3))
    rotation_matrix_into(*res.mean[3:], R)
    w, S = res.model.omega, res.model.wave_spectrum
    for i in (0, 5):
        ld = system.lines[i]
        spec = spec_from_linedef(ld, water_depth=system.water_depth, pose=res.mean,
                                 water_density=system.water_density, gravity=system.gravity,
                                 line_types=inputs["line_types"], **kw,
                                 **(inputs["current"] or {}))
        line = FELine(spec)
        line.solve_static()
        h = res.solution.rao[:, :3] + np.cross(res.solution.rao[:, 3:],
                                               R @ np.asarray(ld.fairlead, float))
        Sx = h[:, :, None] * h[:, None, :].conj() * S[:, None, None]
        wc, Sc = coarse_grid(w, Sx, 120)
        yield f"Floatel-like line{i + 1}, WF fairlead motion", line, (w, h, S), (wc, Sc)


def td_std_transfer(line, w, h, S, seeds, duration=600.0, ramp=120.0, dt=0.1):
    from floatmoor.mooring.fe import run_prescribed
    from floatmoor.mooring.fe.fd_td_compare import periodic_realisation_from_transfer
    r0 = line.r.copy()
    out = []
    for seed in seeds:
        line.r[:] = r0
        line.start()
        mo = periodic_realisation_from_transfer(w, h, S, duration, seed, ramp=ramp)
        r = run_prescribed(line, mo, ramp + duration, dt)
        keep = r.time.values > r.time.values[-1] - duration + 1e-9
        out.append(float(r.fairlead_tension.values[keep].std()))
    line.r[:] = r0
    return np.array(out)


def report(name, line, w, Sx, td):
    from floatmoor.mooring.fe.frequency import frequency_response
    ref = math.sqrt(np.mean(td ** 2))
    parts = []
    for cf in CUTS:
        ds = frequency_response(line, w, Sx, cut_fraction=cf, n_modes=0)
        parts.append(f"cut {cf:g} (node {ds.attrs['cut_node']}, margin "
                     f"{ds.attrs['cut_force_margin']:.1f}) "
                     f"{100 * (float(ds.fairlead_tension_std) / ref - 1):+.1f} %")
    for sb in ("pinned", "spring", "fe"):
        fd = float(frequency_response(line, w, Sx, seabed=sb, n_modes=0).fairlead_tension_std)
        parts.append(f"{sb} {100 * (fd / ref - 1):+.1f} %")
    print(f"{name}: TD {ref / 1e3:.1f} kN (seeds scatter {100 * td.std() / ref:.1f} %); "
          + "; ".join(parts), flush=True)


def main():
    warnings.simplefilter("ignore")
    from floatmoor.mooring.fe.fd_td_compare import td_tension_std
    print(f"# load {' / '.join(f'{v:.1f}' for v in os.getloadavg())}")
    t0 = time.perf_counter()
    for name, line, w, psd in oc3_cases():
        td = td_tension_std(line, w, psd, seeds=SEEDS)["std"]
        report(name, line, w, psd, td)
    for name, line, (w, h, S), (wc, Sc) in floatel_cases():
        td = td_std_transfer(line, w, h, S, SEEDS)
        report(name, line, wc, Sc, td)
    print(f"# {time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
