"""LF mooring-line damping of the FD (``frequency_domain: line_damping: fe``) against a time-domain
forced oscillation of the same FE line.

Floatel-like 100-year case (scenes/floatel_100yr_fe.yaml, FD with ``line_current_drag`` and
``line_damping: fe``): each chosen line is built as the FD builds it
(:class:`floatmoor.analyses.fd_line_damping.MooringLineDamping`, at the FD mean pose, in the
scene's current) and its fairlead is driven in the time domain
(:func:`floatmoor.mooring.fe.prescribed.run_prescribed`, generalised-alpha, dt 0.2 s) by

    x_f(t) = x_WF(t) + x_LF(t) e_x

with ``x_WF`` a periodic realisation of the FD's WF fairlead motion of that line and ``x_LF`` a
periodic Gaussian realisation of the FD's LF surge spectrum of the fairlead (both periodic over
``duration``; the record is one period after ``settle``).  From the x-force on the fairlead:
dynamic stiffness ``K = -<F x_LF> / <x_LF^2>`` and damping ``B = -<F v_LF> / <v_LF^2>`` (the
power the line dissipates against the LF velocity over its mean square).  The FD value:
:func:`floatmoor.mooring.fe.frequency_damping.fairlead_impedance` with the same WF and LF bands,
evaluated on the realised LF frequencies and averaged with the same weights
(``sum a^2 Re Z / sum a^2``, ``sum a^2 w Im Z / sum a^2 w^2``).

With ``--mean-drag``: instead, the mean drag of the lines oscillating in the current (the
1.1 m of mean surge the FD misses against the coupled FE storms): per node the mean of the
Morison drag ``k |u| u`` over the Gaussian relative velocity of the FD line model (the
current minus the node velocity of the WF and LF bands; 20000 samples) minus its value in the
current alone; the fairlead's share from the line's static tangent (interior nodes loaded,
anchor and fairlead held) plus the fairlead node's own; the body's mean pose change
``K^-1 dF`` with the FD's stiffness.

Run:  PYTHONPATH=. python benchmarks/fd_lf_line_damping.py [--lines 1 3 6] [--seeds 1 2 3]
      [--duration 1800] [--settle 300] [--mean-drag]
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


def td_impedance(line, lf, wf, duration, settle, dt):
    """TD dynamic stiffness and damping along x (N/m, N s/m) under ``lf`` (+ ``wf``), and the
    CPU seconds of the run (:func:`floatmoor.mooring.fe.prescribed.forced_oscillation_impedance`)."""
    from floatmoor.mooring.fe.prescribed import forced_oscillation_impedance
    c0 = time.process_time()
    K, B = forced_oscillation_impedance(line, lf, duration, settle, dt, wf=wf)
    return K, B, time.process_time() - c0


def mean_drag(built, r) -> None:
    """The mean-drag estimate of ``--mean-drag`` (see the module docstring)."""
    from floatmoor.analyses.fd_line_damping import MU_STATIC, MooringLineDamping
    from floatmoor.analyses.fd_line_dynamics import coarse_grid
    from floatmoor.mooring.fe.frequency import _assemble, _tangents, line_statics
    from floatmoor.mooring.fe.frequency_damping import fairlead_impedance
    m, s = r.model, r.solution
    lines = MooringLineDamping(built, r.mean)
    rng = np.random.default_rng(1)
    total = np.zeros(6)
    for i, (line, J) in enumerate(lines.lines):
        h = s.rao @ J.T
        Sx_wf = h[:, :, None] * h[:, None, :].conj() * m.wave_spectrum[:, None, None]
        Sx_lf = np.einsum("ai,nij,bj->nab", J, s.lf_cross_spectrum, J)
        bands = [coarse_grid(m.omega, Sx_wf, 120), coarse_grid(m.mu, Sx_lf, 120)]
        cov = fairlead_impedance(line, bands, [MU_STATIC]).node_velocity_covariance
        st = line_statics(line)
        q = _tangents(st.r)[2]
        n = st.r.shape[0]
        dF = np.zeros((n, 3))
        z = rng.standard_normal((20000, 3))
        for k in range(n):
            def drag(u, k=k):
                ut = u @ q[k]
                un = u - ut[:, None] * q[k][None]
                return (st.kdn[k] * np.linalg.norm(un, axis=1)[:, None] * un
                        + st.kdt[k] * (np.abs(ut) * ut)[:, None] * q[k][None])
            Lc = np.linalg.cholesky(cov[k] + 1e-12 * np.eye(3))
            dF[k] = drag(st.u_c[k][None] - z @ Lc.T).mean(0) - drag(st.u_c[k][None])[0]
        model = _assemble(st, "fe", 0.05, contact_tangent=True)[0]
        ni = n - 2
        A = np.zeros((3 * ni, 3 * ni))
        for a in range(ni):
            A[3 * a:3 * a + 3, 3 * a:3 * a + 3] = model.K[a + 1]
            if a + 1 < ni:
                A[3 * a:3 * a + 3, 3 * a + 3:3 * a + 6] = -model.Ko[a + 1]
                A[3 * a + 3:3 * a + 6, 3 * a:3 * a + 3] = -model.Ko[a + 1].T
        x = np.linalg.solve(A, dF[1:n - 1].ravel()).reshape(ni, 3)
        Ff = model.Ko[-1] @ x[-1] + dF[n - 1]
        total += J.T @ Ff
        print(f"line{i + 1}: mean drag increase on the nodes (x, y) "
              f"{dF.sum(0)[0] / 1e3:.1f}, {dF.sum(0)[1] / 1e3:.1f} kN; on the fairlead "
              f"{Ff[0] / 1e3:.1f}, {Ff[1] / 1e3:.1f}, {Ff[2] / 1e3:.1f} kN")
    dx = np.linalg.solve(m.stiffness, total)
    print(f"on the body: {total[0] / 1e3:.1f} kN surge; mean surge change {dx[0]:+.3f} m "
          f"(FD {r.mean[0]:.2f} m -> {r.mean[0] + dx[0]:.2f} m; coupled FE storms 14.70 m)")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--lines", type=int, nargs="+", default=[1, 3, 6])
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--duration", type=float, default=1800.0)
    ap.add_argument("--settle", type=float, default=300.0)
    ap.add_argument("--dt", type=float, default=0.2)
    ap.add_argument("--mean-drag", action="store_true")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from floatmoor.analyses.fd_line_damping import MU_STATIC, MooringLineDamping
    from floatmoor.analyses.fd_line_dynamics import coarse_grid
    from floatmoor.analyses.frequency_domain import frequency_domain_result
    from floatmoor.io.build import build
    from floatmoor.mooring.fe.fd_td_compare import (
        periodic_realisation,
        periodic_realisation_from_transfer,
    )
    from floatmoor.mooring.fe.frequency_damping import fairlead_impedance

    print(f"load {' / '.join(f'{v:.1f}' for v in os.getloadavg())}")
    built = build(SCENE)
    r = frequency_domain_result(built, line_current_drag=True, line_damping="fe")
    m, s = r.model, r.solution
    if args.mean_drag:
        mean_drag(built, r)
        return
    print(f"FD mean surge {r.mean[0]:.2f} m, LF surge std {r.lf_std[0]:.3f} m, record "
          f"{args.duration:g} s after {args.settle:g} s, dt {args.dt} s")
    lines = MooringLineDamping(built, r.mean)
    dw = 2.0 * math.pi / args.duration
    for k in args.lines:
        line, J = lines.lines[k - 1]
        h = s.rao @ J.T
        Sx_wf = h[:, :, None] * h[:, None, :].conj() * m.wave_spectrum[:, None, None]
        s_lf = np.real(np.einsum("i,nij,j->n", J[0], s.lf_cross_spectrum, J[0]))
        psd = np.zeros((m.mu.size, 3))
        psd[:, 0] = s_lf
        Sx_lf = np.zeros((m.mu.size, 3, 3))
        Sx_lf[:, 0, 0] = s_lf
        wr = np.arange(1, math.floor(m.mu[-1] / dw) + 1) * dw
        a2 = np.interp(wr, m.mu, s_lf)
        bands = [coarse_grid(m.omega, Sx_wf, 120), (m.mu, Sx_lf)]
        imp = fairlead_impedance(line, bands, np.concatenate([[MU_STATIC], wr]))
        Z = imp.impedance[1:, 0, 0]
        fd_k = float(np.sum(a2 * Z.real) / np.sum(a2))
        fd_b = float(np.sum(a2 * wr * Z.imag) / np.sum(a2 * wr * wr))
        print(f"line{k}: FD  K {fd_k / 1e3:8.2f} kN/m  B {fd_b / 1e3:8.1f} kN s/m  (static K "
              f"{imp.stiffness[0, 0, 0] / 1e3:.2f} kN/m; LF fairlead surge std "
              f"{math.sqrt(np.trapezoid(s_lf, m.mu)):.2f} m; {imp.iterations} drag iterations)",
              flush=True)
        res = []
        for seed in args.seeds:
            lf = periodic_realisation(m.mu, psd, args.duration, seed, ramp=args.settle)
            wf = periodic_realisation_from_transfer(m.omega, h, m.wave_spectrum, args.duration,
                                                    seed + 1000, ramp=args.settle)
            K, B, cpu = td_impedance(line, lf, wf, args.duration, args.settle, args.dt)
            print(f"line{k}: TD  K {K / 1e3:8.2f} kN/m  B {B / 1e3:8.1f} kN s/m  (seed {seed}; "
                  f"CPU {cpu:.0f} s)  FD/TD-1: K {fd_k / K - 1:+.1%}  B {fd_b / B - 1:+.1%}",
                  flush=True)
            res.append((K, B))
        if len(res) > 1:
            K, B = np.array(res).T
            se_k, se_b = K.std(ddof=1) / math.sqrt(K.size), B.std(ddof=1) / math.sqrt(B.size)
            print(f"line{k}: TD mean of {K.size} seeds: K {K.mean() / 1e3:.2f} +- "
                  f"{se_k / 1e3:.2f} kN/m, B {B.mean() / 1e3:.1f} +- {se_b / 1e3:.1f} kN s/m "
                  f"(standard errors); FD/TD-1: K {fd_k / K.mean() - 1:+.1%} +- "
                  f"{fd_k * se_k / K.mean() ** 2:.1%}, B {fd_b / B.mean() - 1:+.1%} +- "
                  f"{fd_b * se_b / B.mean() ** 2:.1%}", flush=True)


if __name__ == "__main__":
    main()
