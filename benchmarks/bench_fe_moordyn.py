"""The floatmoor FE line against MoorDyn at equal accuracy, side by side in one run.

Case: the OC3-Hywind line 1 (902.2 m, 320 m depth; the line of Jonkman (2010)) with the
fairlead driven (a) harmonically (surge 3 m at 15 s, 60 s, the last period evaluated) and (b)
irregularly (surge and heave, a sum of 40 sines from a JONSWAP-like spectrum, Tp 10 s, plus a
100 s slow drift, 200 s, the last 160 s evaluated).  The coupling step (the interval at which
the fairlead position and velocity are handed over, as a floater solver would) is 0.1 s for
both codes; MoorDyn (PyPI ``moordyn``, MoorDyn-C v2, its default RK2) sub-steps it at dtM.
Internal damping: the same axial damping coefficient (N s) at every discretisation (0.8 of
critical for 160 elements), so that refining converges to one physical line.

Accuracy: every run against the converged run of its own code (4x the elements and a much
shorter step: floatmoor 160 elements at dt 0.00625 s, 16 steps per coupling step with the
fairlead on the cubic Hermite curve through the coupling data, which differs from a run with
the exact fairlead motion at every 0.00625 s step by less than 0.001 % (``--check-ref``); until
2026-11-24 the reference was 160 elements at dt 0.025 s with the fairlead interpolated linearly
in position and velocity, 0.15 / 0.54 / 0.44 % away from the exact-motion solution;
MoorDyn 160 segments at dtM 0.25 ms: with the
fixed damping coefficient 160 segments are unstable at 1 ms), on the
fairlead tension at the coupling times: error of the maximum, of the range (max - min) and the
RMS of the difference over the range of the reference.  "Equal accuracy": a floatmoor
setting whose three errors are all at most MoorDyn's.

MoorDyn's time step: ``--scan`` runs 40 segments at dtM from 1 to 10 ms and compares each
with dtM = 0.1 ms (largest dtM whose maximum and range stay within 0.1 %); the default dtM
(``--dtm``, 6 ms) is that limit for this line (see benchmarks/RESULTS.md).

Timing: CPU time of the time stepping only (``time.process_time``; MoorDyn's initial-condition
solve and floatmoor's statics excluded and printed apart), the best of ``--repeat`` runs
interleaved MoorDyn / floatmoor.

Run: ``python benchmarks/bench_fe_moordyn.py [--scan] [--dtm 0.006] [--repeat 3]
[--newton exact modified fast] [--elements 20 30 40 60 80]`` (the Newton modes and element
counts of the floatmoor grid); ``--diagnose`` splits floatmoor's error into its time part (dt
0.1 and 0.05 s against the same elements at dt 0.00625 s, with the spectrum of the difference)
and its space part (elements at dt 0.00625 s against the reference); ``--check-ref`` compares
the reference with the run handed the exact motion at every line step; ``--lift-off-damping``
runs floatmoor (grid and reference) with the seabed damping acting both ways
(``Seabed.lift_off_damping``).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import sys
import time
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from floatmoor.core.errors import NumericalError  # noqa: E402
from floatmoor.mooring.fe import FELine, Seabed  # noqa: E402
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed  # noqa: E402
from tests.mooring.fe.conftest import OC3, oc3_spec  # noqa: E402

DT_C = 0.1                  # coupling step (s)
N_REF = 160
NSUB_REF = 16               # floatmoor reference: line steps per coupling step
SEABED_KW = {}              # floatmoor seabed options of every run (--lift-off-damping)
BA = 0.8 * 2.0 * math.sqrt(384.243e6 * 77.7066) * 902.2 / N_REF   # N s, all discretisations


@dataclass(frozen=True, kw_only=True)
class IrregularMotion:
    """Fairlead surge and heave: sums of sines of a JONSWAP-like spectrum (peak period ``tp``,
    significant amplitudes ``hs_surge`` / ``hs_heave`` as 4 sigma) with random phases, plus a
    slow surge ``drift`` (m) at ``drift_period``; ramped in over ``ramp`` s."""

    seed: int = 1
    tp: float = 10.0
    hs_surge: float = 4.0
    hs_heave: float = 3.0
    drift: float = 3.0
    drift_period: float = 100.0
    n: int = 40
    ramp: float = 20.0

    def __post_init__(self):
        rng = np.random.default_rng(self.seed)
        w = np.linspace(0.3, 1.6, self.n) * 2 * math.pi / self.tp
        wp = 2 * math.pi / self.tp
        sig = np.where(w <= wp, 0.07, 0.09)
        S = w ** -5 * np.exp(-1.25 * (wp / w) ** 4) * 3.3 ** np.exp(-(w - wp) ** 2
                                                                    / (2 * sig ** 2 * wp ** 2))
        a = np.sqrt(2 * S * (w[1] - w[0]))
        a /= math.sqrt(np.sum(a ** 2) / 2)      # unit standard deviation
        object.__setattr__(self, "_w", w)
        object.__setattr__(self, "_a", a)
        object.__setattr__(self, "_ph", rng.uniform(0, 2 * math.pi, (2, self.n)))

    def __call__(self, t):
        w, a, ph = self._w, self._a, self._ph
        s = np.sin(w * t + ph)
        c = np.cos(w * t + ph)
        amp = np.array([self.hs_surge / 4.0, self.hs_heave / 4.0])
        x = amp * (s @ a)
        xd = amp * ((c * w) @ a)
        wd = 2 * math.pi / self.drift_period
        x[0] += self.drift * math.sin(wd * t)
        xd[0] += self.drift * wd * math.cos(wd * t)
        if t < self.ramp:
            g = 0.5 * (1 - math.cos(math.pi * t / self.ramp))
            gd = 0.5 * math.pi / self.ramp * math.sin(math.pi * t / self.ramp)
        else:
            g, gd = 1.0, 0.0
        disp = np.array([-x[0] * g, 0.0, x[1] * g])
        vel = np.array([-(xd[0] * g + x[0] * gd), 0.0, xd[1] * g + x[1] * gd])
        return disp, vel


CASES = {
    "harmonic": (HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0, ramp=15.0), 60.0, 45.0),
    "irregular": (IrregularMotion(), 200.0, 40.0),
}


@contextmanager
def _quiet_stdout():
    """MoorDyn-C prints to file descriptor 1."""
    sys.stdout.flush()
    devnull = os.open(os.devnull, os.O_WRONLY)
    saved = os.dup(1)
    os.dup2(devnull, 1)
    try:
        yield
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)


def run_floatmoor(n, motion, t_end, *, nsub=1, newton="exact", rho=0.7, dt=DT_C, exact=False):
    """Fairlead tension at the coupling times, CPU of the steps, CPU of the statics.  With
    ``exact`` the ``nsub`` line steps per coupling step each get the exact fairlead motion (the
    motion evaluated at every line step, recorded at the coupling times) instead of its
    interpolation between the coupling times."""
    seabed = Seabed(depth=OC3["depth"], **SEABED_KW) if SEABED_KW else None
    line = FELine(oc3_spec(n=n, damping=BA, seabed=seabed))
    c0 = time.process_time()
    line.solve_static()
    line.start(newton=newton, rho_inf=rho)
    c_static = time.process_time() - c0
    c0 = time.process_time()
    if exact:
        ds = run_prescribed(line, motion, t_end, dt / nsub, record_every=nsub)
    else:
        ds = run_prescribed(line, motion, t_end, dt, substeps=nsub)
    cpu = time.process_time() - c0
    return ds.time.values, ds.fairlead_tension.values, cpu, c_static, line.newton_iterations


def run_moordyn(nseg, dtm, motion, t_end, dt=DT_C):
    """Fairlead tension at the coupling times, CPU of the steps, CPU of the initial conditions
    (MoorDyn's own, ``TmaxIC`` 120 s)."""
    import tempfile

    import moordyn

    from tests.mooring.fe.moordyn_ref import TEMPLATE

    with tempfile.TemporaryDirectory() as d, _quiet_stdout():
        path = os.path.join(d, "oc3_line.dat")
        with open(path, "w") as fh:
            fh.write(TEMPLATE.format(ea=384.243e6, ba=BA, nseg=nseg, dtm=dtm))
        cwd = os.getcwd()
        os.chdir(d)
        try:
            c0 = time.process_time()
            system = moordyn.Create(path)
            x0 = np.array([5.2, 0.0, -70.0])
            moordyn.Init(system, x0.tolist(), [0.0, 0.0, 0.0])
            c_ic = time.process_time() - c0
            n = int(round(t_end / dt))
            T = np.zeros(n + 1)
            c0 = time.process_time()
            f = None
            for k in range(1, n + 1):
                t = k * dt
                dsp, vel = motion(t)
                f = moordyn.Step(system, (x0 + dsp).tolist(), list(map(float, vel)), t - dt, dt)
                T[k] = math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2)
            cpu = time.process_time() - c0
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    return np.arange(n + 1) * dt, T, cpu, c_ic


def errors(t, T, t_ref, T_ref, t_eval):
    """(max, range, rms) relative errors over t >= t_eval on the common coupling times."""
    sel = t >= t_eval - 1e-9
    sel_r = t_ref >= t_eval - 1e-9
    a = T[sel]
    b = np.interp(t[sel], t_ref[sel_r], T_ref[sel_r])
    if not np.all(np.isfinite(a)):
        return math.inf, math.inf, math.inf
    return (abs(a.max() / b.max() - 1), abs(np.ptp(a) / np.ptp(b) - 1),
            float(np.sqrt(np.mean((a - b) ** 2)) / np.ptp(b)))


def scan(case, nseg=40):
    motion, t_end, t_eval = CASES[case]
    t, base, *_ = run_moordyn(nseg, 1e-4, motion, t_end)
    sel = t >= t_eval
    print(f"MoorDyn {nseg} segments, {case}: dtM 0.1 ms max {base[sel].max() / 1e3:.2f} kN, "
          f"range {np.ptp(base[sel]) / 1e3:.2f} kN")
    for dtm in (1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 7e-3, 8e-3, 10e-3):
        try:
            _, T, cpu, _ = run_moordyn(nseg, dtm, motion, t_end)
        except RuntimeError as exc:
            print(f"  dtM {dtm * 1e3:4.1f} ms: MoorDyn fails ({exc}): unstable")
            break
        em, er, es = errors(t, T, t, base, t_eval)
        ok = em < 1e-3 and er < 1e-3 and np.all(T < 1e8)
        print(f"  dtM {dtm * 1e3:4.1f} ms: max {100 * em:.3f} %, range {100 * er:.3f} %, "
              f"rms {100 * es:.3f} % from dtM 0.1 ms; CPU {cpu:.2f} s "
              f"{'(stable, within 0.1 %)' if ok else '(NOT within 0.1 % or unstable)'}")


def _band_power(d, bands=((0.0, 0.3), (0.3, 1.0), (1.0, 2.0), (2.0, 5.01))):
    """Share of the power of the difference ``d`` (sampled every DT_C) in frequency bands."""
    D = np.fft.rfft(d - d.mean())
    fr = np.fft.rfftfreq(d.size, DT_C)
    P = np.abs(D) ** 2
    P /= max(P.sum(), 1e-300)
    return " ".join(f"{lo:g}-{min(hi, 5.0):g} Hz {P[(fr >= lo) & (fr < hi)].sum():.2f}"
                    for lo, hi in bands)


def diagnose(case, elements):
    """Time and space error of floatmoor at each element count: space error = the run at
    NSUB_REF steps per coupling step against the reference; time error = the runs at dt 0.1
    and 0.05 s against the same element count at NSUB_REF steps, with the band powers of the
    difference (where in the spectrum the time error sits)."""
    motion, t_end, t_eval = CASES[case]
    t_r, T_r, *_ = run_floatmoor(N_REF, motion, t_end, nsub=NSUB_REF)
    fmt = lambda e: " / ".join(f"{100 * x:.3f}" for x in e)  # noqa: E731
    print(f"\n## {case}: time and space error (max / range / rms %)")
    for n in elements:
        t_b, T_b, *_ = run_floatmoor(n, motion, t_end, nsub=NSUB_REF)
        print(f"{n} el.: space error (dt {DT_C / NSUB_REF:g} s) {fmt(errors(t_b, T_b, t_r, T_r, t_eval))}")
        sel = t_b >= t_eval - 1e-9
        for nsub in (1, 2):
            t, T, *_ = run_floatmoor(n, motion, t_end, nsub=nsub)
            print(f"    time error dt {DT_C / nsub:g} s {fmt(errors(t, T, t_b, T_b, t_eval))}; "
                  f"power of the difference: {_band_power(T[sel] - T_b[sel])}")


def fm_grid(newton=("exact", "modified", "fast"), elements=(20, 30, 40, 60, 80)):
    """floatmoor settings tried: elements, sub-steps per coupling step, Newton mode, rho_inf."""
    return [(n, nsub, nw, rho) for n in elements for nsub in (1, 2, 4)
            for nw in newton for rho in (0.7, 1.0)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scan", action="store_true")
    ap.add_argument("--dtm", type=float, default=6e-3)
    ap.add_argument("--nseg", type=int, default=40)
    ap.add_argument("--dtm-ref", type=float, default=2.5e-4)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--cases", nargs="+", default=list(CASES))
    ap.add_argument("--newton", nargs="+", default=["exact", "modified", "fast"])
    ap.add_argument("--elements", nargs="+", type=int, default=[20, 30, 40, 60, 80])
    ap.add_argument("--lift-off-damping", action="store_true",
                    help="floatmoor runs (and its reference) with seabed lift_off_damping")
    ap.add_argument("--diagnose", action="store_true",
                    help="time and space error of floatmoor per element count, and stop")
    ap.add_argument("--check-ref", action="store_true",
                    help="compare the floatmoor reference with the exact-motion run and stop")
    args = ap.parse_args()
    if args.lift_off_damping:
        SEABED_KW["lift_off_damping"] = True
    import moordyn  # noqa: F401
    import numba

    print(f"# {platform.machine()}, Python {platform.python_version()}, numba "
          f"{numba.__version__}; load {' / '.join(f'{v:.2f}' for v in os.getloadavg())}")
    print(f"# floatmoor seabed options {SEABED_KW or 'default'}")
    print(f"# coupling step {DT_C} s; internal damping {BA:.4g} N s at every discretisation; "
          f"MoorDyn {args.nseg} segments at dtM {args.dtm * 1e3:g} ms (RK2)")
    if args.scan:
        for case in args.cases:
            scan(case, args.nseg)
        return
    run_floatmoor(10, CASES["harmonic"][0], 1.0)      # numba cache load / compile
    if args.diagnose:
        for case in args.cases:
            diagnose(case, args.elements)
        return
    if args.check_ref:
        for case in args.cases:
            motion, t_end, t_eval = CASES[case]
            t_fr, T_fr, *_ = run_floatmoor(N_REF, motion, t_end, nsub=NSUB_REF)
            t_fx, T_fx, *_ = run_floatmoor(N_REF, motion, t_end, nsub=NSUB_REF, exact=True)
            e = errors(t_fr, T_fr, t_fx, T_fx, t_eval)
            print(f"{case}: reference ({N_REF} el., {NSUB_REF} Hermite sub-steps) against the "
                  f"exact-motion run at the same step: max / range / rms "
                  f"{' / '.join(f'{100 * x:.4f}' for x in e)} %")
        return
    for case in args.cases:
        motion, t_end, t_eval = CASES[case]
        t_fr, T_fr, c_fr, *_ = run_floatmoor(N_REF, motion, t_end, nsub=NSUB_REF)
        t_mr, T_mr, c_mr, _ = run_moordyn(N_REF, args.dtm_ref, motion, t_end)
        em, er, es = errors(t_fr, T_fr, t_mr, T_mr, t_eval)
        sel = t_fr >= t_eval
        print(f"\n## {case}: {t_end:g} s, evaluated from {t_eval:g} s")
        print(f"references: floatmoor {N_REF} el. dt {DT_C / NSUB_REF:g} s (max "
              f"{T_fr[sel].max() / 1e3:.1f} kN, range {np.ptp(T_fr[sel]) / 1e3:.1f} kN, CPU "
              f"{c_fr:.1f} s); MoorDyn {N_REF} seg. dtM {args.dtm_ref * 1e3:g} ms (CPU "
              f"{c_mr:.1f} s); the two references differ by max {100 * em:.2f} %, range "
              f"{100 * er:.2f} %, rms {100 * es:.2f} % (model differences)")
        md_runs = []
        for _ in range(args.repeat):
            md_runs.append(run_moordyn(args.nseg, args.dtm, motion, t_end))
        t_m, T_m = md_runs[0][:2]
        md_err = errors(t_m, T_m, t_mr, T_mr, t_eval)
        rows = []
        for n, nsub, nw, rho in fm_grid(args.newton, args.elements):
            try:
                t_f, T_f, c, cs, its = run_floatmoor(n, motion, t_end, nsub=nsub, newton=nw,
                                                     rho=rho)
            except NumericalError as exc:
                print(f"  floatmoor {n} el. nsub {nsub} {nw} rho {rho}: {exc}")
                continue
            rows.append([n, nsub, nw, rho, errors(t_f, T_f, t_fr, T_fr, t_eval), c, cs,
                         its / int(round(t_end / DT_C)) / nsub])
        # (A) each code against its own converged run; (B) both against floatmoor's
        md_err_b = errors(t_m, T_m, t_fr, T_fr, t_eval)
        best = {}
        for view, md in (("A", md_err), ("B", md_err_b)):
            ok = [r for r in rows if all(e <= m for e, m in zip(r[4], md))]
            best[view] = min(ok, key=lambda r: r[5]) if ok else None
        # timing: interleaved repeats of MoorDyn and the cheapest equal-accuracy settings
        c_md = [r[2] for r in md_runs]
        for _ in range(args.repeat):
            c_md.append(run_moordyn(args.nseg, args.dtm, motion, t_end)[2])
            for b in {id(b): b for b in best.values() if b is not None}.values():
                b[5] = min(b[5], run_floatmoor(b[0], motion, t_end, nsub=b[1], newton=b[2],
                                               rho=b[3])[2])
        print("| model | elements | step | rho_inf | Newton | max err | range err | rms err | "
              "CPU steps (s) |")
        print("|---|---|---|---|---|---|---|---|---|")
        print(f"| MoorDyn RK2 (A: own ref.) | {args.nseg} | dtM {args.dtm * 1e3:g} ms | - | - | "
              f"{100 * md_err[0]:.3f} % | {100 * md_err[1]:.3f} % | {100 * md_err[2]:.3f} % | "
              f"{min(c_md):.3f} (IC {md_runs[0][3]:.2f}) |")
        print(f"| MoorDyn RK2 (B: floatmoor ref.) | {args.nseg} | dtM {args.dtm * 1e3:g} ms | - | "
              f"- | {100 * md_err_b[0]:.3f} % | {100 * md_err_b[1]:.3f} % | "
              f"{100 * md_err_b[2]:.3f} % | |")
        for n, nsub, nw, rho, e, c, cs, it in rows:
            mark = "".join(f" ({v})" for v, b in best.items()
                           if b is not None and (n, nsub, nw, rho) == tuple(b[:4]))
            print(f"| floatmoor{mark} | {n} | dt {DT_C / nsub:g} s | {rho:g} | {nw} "
                  f"({it:.2f}/step) | {100 * e[0]:.3f} % | {100 * e[1]:.3f} % | "
                  f"{100 * e[2]:.3f} % | {c:.4f} (statics {cs:.4f}) |")
        for view, what in (("A", "each code against its own converged run"),
                           ("B", "both against the converged floatmoor run")):
            b = best[view]
            if b is None:
                print(f"({view}) {what}: no floatmoor setting of the grid at equal or better "
                      "accuracy")
            else:
                print(f"({view}) {what}: cheapest floatmoor setting at equal or better accuracy "
                      f"{b[0]} elements, dt {DT_C / b[1]:g} s, rho_inf {b[3]:g}, newton {b[2]}: "
                      f"CPU {b[5]:.4f} s vs MoorDyn {min(c_md):.3f} s (best of {len(c_md)}) -> "
                      f"{min(c_md) / b[5]:.1f}x")
        print(f"load {' / '.join(f'{v:.2f}' for v in os.getloadavg())}")


if __name__ == "__main__":
    main()
