"""LF mooring-line damping of the FD (``frequency_domain: line_damping: fe``) against a time-domain
forced oscillation of the same FE line.

Floatel-like 100-year case (scenes/floatel_100yr_fe.yaml, FD with ``line_current_drag``): each
chosen line is built as the FD builds it (:class:`floatmoor.analyses.fd_line_damping.
MooringLineDamping`, at the FD mean pose, in the scene's current) and its fairlead is driven in
the time domain (:func:`floatmoor.mooring.fe.prescribed.run_prescribed`, generalised-alpha) by

    x_f(t) = x_WF(t) + a e_x sin(w t)

with ``x_WF`` a periodic realisation of the FD's WF fairlead motion of that line (period
``cycles`` LF periods) and a surge harmonic of amplitude ``a`` at the FD's LF surge natural
frequency ``w``.  The x-force on the fairlead over ``cycles`` whole periods after ``settle``
periods is fitted by ``c0 + c1 sin + c2 cos``: dynamic stiffness ``K = -c1 / a`` and damping
``B = -c2 / (w a)`` (equivalently the energy dissipated per cycle over ``pi w a^2``).  The FD
value: :func:`floatmoor.mooring.fe.frequency_damping.fairlead_impedance` with the same WF band
and the harmonic as a narrow band of variance a^2 / 2.  Also the catenary's quasi-static
stiffness (the FD impedance at ``MU_STATIC``).

Run:  PYTHONPATH=. python benchmarks/fd_lf_line_damping.py [--lines 1 6] [--cycles 10]
      [--amplitude 2.55] [--seeds 1 2] [--no-waves]
"""

from __future__ import annotations

import argparse
import math
import os
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "floatel_100yr_fe.yaml"


def forced_oscillation(line, wf_motion, omega, amplitude, cycles, settle, dt):
    """TD dynamic stiffness and damping (x, N/m and N s/m) of the line under ``wf_motion``
    plus ``amplitude sin(omega t)`` along x."""
    from floatmoor.mooring.fe.prescribed import run_prescribed
    T = 2.0 * math.pi / omega
    r0 = line.r.copy()
    line.start()

    def motion(t):
        d, v = wf_motion(t) if wf_motion is not None else (np.zeros(3), np.zeros(3))
        d = d.copy()
        v = v.copy()
        d[0] += amplitude * math.sin(omega * t)
        v[0] += amplitude * omega * math.cos(omega * t)
        return d, v

    t_end = (settle + cycles) * T
    c0 = time.process_time()
    ds = run_prescribed(line, motion, t_end, dt)
    cpu = time.process_time() - c0
    line.r[:] = r0
    t = ds.time.values
    keep = t > settle * T - 1e-9
    F = ds.fairlead_force.values[keep, 0]
    tt = t[keep]
    A = np.stack([np.ones_like(tt), np.sin(omega * tt), np.cos(omega * tt)], axis=1)
    c = np.linalg.lstsq(A, F, rcond=None)[0]
    # mean power of the force of the fairlead on the line along the harmonic velocity
    v = amplitude * omega * np.cos(omega * tt)
    power = float(np.trapezoid(-F * v, tt) / (tt[-1] - tt[0]))
    return {"K": -c[1] / amplitude, "B": -c[2] / (omega * amplitude),
            "B_energy": power / (0.5 * (amplitude * omega) ** 2), "cpu_s": cpu}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, nargs="+", default=[1, 6])
    ap.add_argument("--cycles", type=int, default=10)
    ap.add_argument("--settle", type=int, default=2)
    ap.add_argument("--amplitude", type=float, default=2.55)
    ap.add_argument("--seeds", type=int, nargs="+", default=[1])
    ap.add_argument("--dt", type=float, default=0.2)
    ap.add_argument("--no-waves", action="store_true")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from floatmoor.analyses.fd_line_damping import (
        MU_STATIC,
        MooringLineDamping,
        lf_mode_frequency,
    )
    from floatmoor.analyses.fd_line_dynamics import coarse_grid
    from floatmoor.analyses.frequency_domain import frequency_domain_result
    from floatmoor.io.build import build
    from floatmoor.mooring.fe.fd_td_compare import periodic_realisation_from_transfer
    from floatmoor.mooring.fe.frequency_damping import fairlead_impedance, harmonic_band

    print(f"load {' / '.join(f'{v:.1f}' for v in os.getloadavg())}")
    built = build(SCENE)
    r = frequency_domain_result(built, line_current_drag=True)
    m, s = r.model, r.solution
    omega = lf_mode_frequency(m.stiffness, s.lf_mass, 0)
    T = 2.0 * math.pi / omega
    print(f"FD mean surge {r.mean[0]:.2f} m, LF surge natural period {T:.1f} s, "
          f"harmonic amplitude {args.amplitude} m")
    lines = MooringLineDamping(built, r.mean)
    for k in args.lines:
        line, J = lines.lines[k - 1]
        h = s.rao @ J.T
        Sx_wf = h[:, :, None] * h[:, None, :].conj() * m.wave_spectrum[:, None, None]
        bands = [] if args.no_waves else [coarse_grid(m.omega, Sx_wf, 120)]
        bands.append(harmonic_band(omega, args.amplitude))
        imp = fairlead_impedance(line, bands, [MU_STATIC, omega])
        fd_k, fd_b, k0 = imp.stiffness[1, 0, 0], imp.damping[1, 0, 0], imp.stiffness[0, 0, 0]
        print(f"line{k}: FD  K {fd_k / 1e3:8.2f} kN/m  B {fd_b / 1e3:8.1f} kN s/m  "
              f"(static K {k0 / 1e3:.2f} kN/m; {imp.iterations} drag iterations)")
        for seed in args.seeds:
            wf = None if args.no_waves else periodic_realisation_from_transfer(
                m.omega, h, m.wave_spectrum, args.cycles * T, seed,
                ramp=args.settle * T)
            td = forced_oscillation(line, wf, omega, args.amplitude, args.cycles, args.settle,
                                    args.dt)
            print(f"line{k}: TD  K {td['K'] / 1e3:8.2f} kN/m  B {td['B'] / 1e3:8.1f} kN s/m  "
                  f"(energy {td['B_energy'] / 1e3:.1f}; seed {seed}; CPU {td['cpu_s']:.0f} s)"
                  f"  FD/TD-1: K {fd_k / td['K'] - 1:+.1%}  B {fd_b / td['B'] - 1:+.1%}",
                  flush=True)


if __name__ == "__main__":
    main()
