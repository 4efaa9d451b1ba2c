"""The floatmoor FE line against MoorDyn, fed identical fairlead kinematics and judged against
one common converged reference.

Cases:

* ``oc3-harmonic``: the OC3-Hywind line 1 (902.2 m, 320 m depth; Jonkman (2010)), fairlead
  surge 3 m at 15 s, 60 s, the last period evaluated;
* ``oc3-irregular``: the same line, fairlead surge and heave from a sum of 40 sines of a
  JONSWAP-like spectrum (Tp 10 s) plus a 100 s slow drift, 200 s, the last 160 s evaluated;
* ``floatel-slack``: line 1 of the Floatel-like flagship mooring (chain 1200 m + polyester
  1200 m + chain 250 m in 150 m, about 1100 m of chain on the seabed, the windward line that
  goes slack), the scene's 0.94 m/s current on the line, driven by the fairlead track of the
  quasi-static flagship storms of seeds 1, 2, 3 (3 hours after the 1200 s transient each).

Identical inputs (tests/mooring/fe/moordyn_floatel.py for the Floatel-like line, its MoorDyn
file written by ``floatmoor.io.moordyn.export``; the OC3 line as written below):

* the fairlead track is the motion sampled at the coupling step (0.1 s) and linear in between;
  MoorDyn's ``Step(x, xd, t, dt)`` takes the state at the start of the step and moves the
  coupled point along ``x + xd (t' - t)`` (MoorDyn-C ``Point::updateFairlead``), so it gets
  ``x(t_k)`` and the chord velocity ``(x(t_k+1) - x(t_k)) / dt``; floatmoor's step to
  ``t_k+1`` gets ``x(t_k+1)`` and the same chord velocity.  Both codes and their references see
  exactly this piecewise-linear track.  (Until 2026-11-27 this script handed MoorDyn the
  end-of-interval state, so its point ran one step ahead and jumped by about a dt^2 / 2 at
  every coupling step; with axial damping the jumps showed as tension spikes.)
* OC3 line: the same internal damping in N s at every discretisation in both codes (0.8 of the
  critical damping of a 5.6 m element, i.e. of 160 elements), so that refining converges to
  one physical line; the seabed as MoorDyn models it (linear spring from the first contact,
  damping both ways: ``contact_smoothing 0``, ``lift_off_damping``) in both (until 2026-11-28
  floatmoor kept its own contact law here: the same converged line to 0.03 %, but up to 10 %
  more Newton iterations at dt 0.1 s); MoorDyn's schemes RK2 (its default), Euler and
  Midpoint2, the cheapest of a scan of all its schemes (``OC3_MD_DTM`` below).
* Floatel-like line: the seabed as MoorDyn models it (linear spring and damping both ways) in
  both, and since 2026-11-28 an internal damping in N s as for the OC3 line (``BA_FLOATEL``,
  0.8 of the critical damping of a 10 m chain element, every segment, both codes).  Without
  it (the flagship scene has none) the line has no converged answer to judge against: the
  undamped line's high-frequency axial response depends on the time step at any mesh
  (floatmoor, seed 1, 4800 s: 264 elements at dt 0.025 / 0.0125 / 0.00625 s gave maxima of
  1805.9 / 1827.8 / 1813.9 kN and std 229.6 / 234.1 / 230.3 kN; 132 elements at 0.025 /
  0.0125 s 1807.7 / 1827.6 kN), so the reference the earlier runs used (264 elements, dt
  0.025 s) was 1.2 % / 2 % from its own refinement.  With ``BA_FLOATEL``: 264 elements at dt
  0.025 / 0.0125 s and 528 elements at 0.0125 s agree to 0.08 % in the maximum and the std,
  0.1 % of the maximum in the minimum and 0.3 % in the damage.  MoorDyn's RK2 is unstable for
  an undamped line (its amplification factor exceeds 1 on an undamped oscillation at any
  step), so MoorDyn runs its RK4 there.

Accuracy: every run of either code against ONE common reference, floatmoor's converged run
(4x the elements of the finest grid entry (OC3; 1.5x for the Floatel-like line, whose
refinement to 528 elements moves the reference by less than 0.1 %) and a line step 8x shorter
than the coupling step); the MoorDyn run at the same element count and a small dtM is printed
beside it with its difference from the reference (the two converged codes must agree).
Quantities over the evaluation window: the maximum, the standard deviation, the minimum and the
rainflow damage with T-N slope m = 3 (sum n S^3) of the fairlead tension; for the storms the
mean over the seeds of each (the mean of the 3-hour maxima).  The accuracy criterion (options):
maximum, std and damage within ``--tol`` (0.5 %, 0.5 %, 2 %), minimum within 1 % of the
reference maximum.  A setting qualifies when it and the settings of the same step with the next
smaller and next larger element count of the grid all meet the criterion (a lucky cancellation
at one count does not qualify).  The ratio is MoorDyn's CPU time at its cheapest qualifying
setting over floatmoor's at its cheapest qualifying setting.

Timing: CPU time of the time stepping only (``time.process_time``), the best of ``--repeat``
interleaved runs: MoorDyn's loop of ``Step`` calls (its inputs made Python lists before the
clock; its initial-condition solve excluded), floatmoor's steps (``run_prescribed(...,
stats=...)["cpu_steps"]``: its fairlead track evaluated before and its Dataset built after,
about 2 ms per run, excluded (until 2026-11-28 they were counted); its statics excluded).

Run: ``python benchmarks/bench_fe_moordyn.py [--cases oc3-harmonic oc3-irregular floatel-slack]
[--seeds 1 2 3] [--duration 12000] [--repeat 2]``; ``--quick`` shortens the storms to 1800 s
and 1 seed (a smoke run, not the recorded figures).  The Floatel-like grid is long (MoorDyn's
runs of 3 seeds x 12000 s take 20 min to 2.5 h of CPU per setting): ``--jobs 2`` runs the
grid's runs in two worker processes (each run's CPU time is still its own process's; the load
is printed with every run), ``--store DIR`` keeps every finished run and a later invocation
reuses it when nothing that produced it changed (the task, the track, for floatmoor our
sources, for MoorDyn the text it is given and its version; `tests/mooring/fe/test_bench_store.py`),
so an interrupted grid loses nothing; timing repeats always run afresh.  ``--md-segments``
leaves out MoorDyn's finest counts: the ratio is then exact when a count that was run
qualifies, else a lower bound (MoorDyn at its cheapest setting that meets the criterion; the
counts left out are finer and run at smaller steps, so dearer).
"""

from __future__ import annotations

import argparse
import glob
import hashlib
import inspect
import math
import os
import platform
import sys
import tempfile
import time
from dataclasses import dataclass

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from floatmoor.core.errors import NumericalError  # noqa: E402
from floatmoor.mooring.fe import FELine, Seabed  # noqa: E402
from floatmoor.mooring.fe.prescribed import HarmonicMotion, TimeSeriesMotion, run_prescribed  # noqa: E402
from floatmoor.post.fatigue.rainflow import rainflow  # noqa: E402
from tests.mooring.fe import moordyn_floatel as FL  # noqa: E402
from tests.mooring.fe.conftest import OC3, oc3_spec  # noqa: E402

DT_C = 0.1                  # coupling step (s)
BA_OC3 = 0.8 * 2.0 * math.sqrt(384.243e6 * 77.7066) * 902.2 / 160   # N s, every discretisation
# the Floatel-like line's the same way: 0.8 of the critical damping of a 10 m element of its chain
# (EA 665.46 MN, 140.41 kg/m; the reference mesh's element), every segment, both codes
BA_FLOATEL = 0.8 * 2.0 * math.sqrt(665.4557e6 * 140.41) * 10.0
TOL = {"max": 0.005, "std": 0.005, "damage": 0.02, "min": 0.01}
# MoorDyn's seabed (kBot 3e6 N/m^3, cBot 3e5 N s/m^3 below, times the diameter 0.09 m: per metre
# of line), its contact law too: a linear spring from the first contact and the damping both ways
OC3_SEABED = Seabed(depth=OC3["depth"], stiffness=3.0e6 * 0.09, damping=3.0e5 * 0.09,
                    contact_smoothing=0.0, lift_off_damping=True)

OC3_TEMPLATE = """--------------------- MoorDyn Input File ------------------------------------
One OC3-Hywind line (floatmoor FE benchmark)
---------------------- LINE TYPES -----------------------------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta    EI    Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)     (N-m^2) (-)  (-)    (-)     (-)
main       0.09    77.7066    384.243e6 {ba}        0.0   1.6    1.0    0.1     0.0
---------------------- POINTS ---------------------------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     853.87  0.0   -320.0  0      0       0      0
2     Coupled   5.2     0.0   -70.0   0      0       0      0
---------------------- LINES ----------------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
1     main       1        2        902.2     {nseg}       -
---------------------- OPTIONS --------------------------------------------------------
{dtm}    dtM
{scheme} tScheme
9.80665  g
1025.0   rho
320.0    WtrDpth
3.0e6    kBot
3.0e5    cBot
1.0      dtIC
120.0    TmaxIC
0.0001   threshIC
0        writeLog
1        disableOutput
1        disableOutTime
------------------------- need this line ----------------------------------------------
"""


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
        amp = np.array([self.hs_surge / 4.0, self.hs_heave / 4.0])
        x = amp * (s @ a)
        x[0] += self.drift * math.sin(2 * math.pi / self.drift_period * t)
        g = 0.5 * (1 - math.cos(math.pi * t / self.ramp)) if t < self.ramp else 1.0
        return np.array([-x[0] * g, 0.0, x[1] * g]), np.zeros(3)


@dataclass
class Track:
    """A fairlead track sampled at the coupling times: ``t`` (nt,) from 0, displacement ``xyz``
    (nt, 3) from the static fairlead position ``r0`` (earth), the evaluation window ``window``
    (nt,) bool, and for the Floatel case the case and start pose."""

    t: np.ndarray
    xyz: np.ndarray
    r0: np.ndarray
    window: np.ndarray
    case: object = None
    pose0: object = None


def short_track(motion, t_end, t_eval):
    t = np.arange(0.0, t_end + 0.5 * DT_C, DT_C)
    xyz = np.array([motion(tt)[0] for tt in t])
    return Track(t=t, xyz=xyz, r0=np.asarray(OC3["fairlead"], float), window=t >= t_eval - 1e-9)


def floatel_tracks(seeds, duration):
    """The fairlead tracks of line 1 in the quasi-static flagship storms of ``seeds``."""
    c = FL.case("line1", current=True)
    out = []
    for seed in seeds:
        t, poses, transient = FL.storm_track(seed=seed, duration=duration)
        r, x = FL.fairlead_track(c, t, poses)
        out.append(Track(t=t, xyz=x, r0=r[0], window=t >= transient, case=c, pose0=poses[0]))
    return out


def run_floatmoor(case, tr: Track, n, nsub=1, newton="exact"):
    """Fairlead tension at the coupling times and the CPU time of the steps."""
    motion = TimeSeriesMotion(t=tr.t, xyz=tr.xyz)
    if case.startswith("oc3"):
        line = FELine(oc3_spec(n=n, damping=BA_OC3, seabed=OC3_SEABED))
        line.solve_static()
    else:
        line = FL.fe_line(tr.case, n_elements=n, pose0=tr.pose0, internal_damping=BA_FLOATEL)
    line.start(newton=newton)
    stats = {}
    ds = run_prescribed(line, motion, float(tr.t[-1]), DT_C, substeps=nsub, stats=stats)
    return ds.fairlead_tension.values, stats["cpu_steps"]


def run_moordyn(case, tr: Track, nseg, dtm, scheme):
    """MoorDyn's fairlead tension at the coupling times (start-of-step state, chord velocity)
    and the CPU time of the steps."""
    import moordyn

    r = tr.r0 + tr.xyz
    if case.startswith("floatel"):
        Tf, _, cpu = FL.run_moordyn(tr.case, tr.t, r, n_segments=nseg, dtm=dtm, scheme=scheme,
                                    internal_damping=BA_FLOATEL)
        return Tf, cpu
    with tempfile.TemporaryDirectory() as d, FL.quiet_stdout():
        path = os.path.join(d, "oc3_line.dat")
        with open(path, "w") as fh:
            fh.write(_moordyn_input(case, tr, nseg, dtm, scheme))
        cwd = os.getcwd()
        os.chdir(d)
        try:
            system = moordyn.Create(path)
            moordyn.Init(system, r[0].tolist(), [0.0, 0.0, 0.0])
            nt = tr.t.size
            T = np.zeros(nt)
            f = moordyn.Step(system, r[0].tolist(), [0.0, 0.0, 0.0], 0.0, 0.0)
            T[0] = math.sqrt(sum(x * x for x in f))
            # the inputs as Python lists before the clock starts (floatmoor's run takes its
            # fairlead track as arrays in one go: TimeSeriesMotion.track)
            rk = [x.tolist() for x in r[:-1]]
            vk = [((r[k + 1] - r[k]) / DT_C).tolist() for k in range(nt - 1)]
            tk = [float(x) for x in tr.t[:-1]]
            c0 = time.process_time()
            for k in range(nt - 1):
                f = moordyn.Step(system, rk[k], vk[k], tk[k], DT_C)
                T[k + 1] = math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2])
            cpu = time.process_time() - c0
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    return T, cpu


def md_stable_dtm(case, tr: Track, nseg, scheme, dtms, probe=300.0, rtol=1e-3, settle=100.0):
    """MoorDyn's largest stable and accurate step of ``dtms`` for ``nseg`` segments: the
    largest whose run over ``probe`` s of the track (from 1000 s into a storm, where the
    motion is under way) gives the maximum and the standard deviation of the fairlead tension
    within ``rtol`` of the run at the smallest step of ``dtms`` (a step that blows up or drifts
    fails; from the start, the window's maximum can be a start-up transient that a step change
    moves: on the damped Floatel-like line the first 300 s gave 0.6 % between 0.25 and 0.5 ms
    while 0.5, 1 and 2 ms agreed to 5 digits, so a track of 1300 s or more is probed from
    1000 s, the ``--quick`` run's too).  A run started inside a storm starts at rest in
    equilibrium while the fairlead already moves at the storm's velocity: a start-up snap
    (on the Floatel-like line at 66 segments a 1398 / 1302 kN peak at 0.25 / 1 ms, 0.2 s in,
    against 1535 kN in floatmoor's reference, which starts at the storm's start), so such a
    run starts ``settle`` s earlier and only its last ``probe`` s are compared (until
    2026-11-28 the snap was compared and made 66 segments look as if they needed 0.25 ms).
    At such a step MoorDyn's error is that of its segments, so only that step of each count
    enters the grid (the old benchmark's scan: dtM 1-6 ms within 0.1 % of 0.1 ms on the OC3
    line)."""
    t0 = 1000.0 if tr.t[-1] >= 1000.0 + probe else 0.0
    ts = max(t0 - settle, 0.0) if t0 > 0.0 else 0.0
    sel = (tr.t >= ts) & (tr.t <= t0 + probe)
    short = Track(t=tr.t[sel] - tr.t[sel][0], xyz=tr.xyz[sel], r0=tr.r0,
                  window=tr.t[sel] >= t0 - 1e-9, case=tr.case, pose0=tr.pose0)
    base = None
    for dtm in sorted(dtms):
        try:
            with _quiet_stderr():
                T, _ = run_moordyn(case, short, nseg, dtm, scheme)
        except RuntimeError:
            break
        if not (np.all(np.isfinite(T)) and T.max() < 1e9):
            break
        q = (T[short.window].max(), T[short.window].std())
        if base is None:
            base, best = q, dtm
        elif abs(q[0] / base[0] - 1) <= rtol and abs(q[1] / base[1] - 1) <= 10 * rtol:
            best = dtm
        else:
            break
    return None if base is None else best


class _quiet_stderr:
    """MoorDyn-C reports a blow-up on file descriptor 2: silenced while probing steps."""

    def __enter__(self):
        sys.stderr.flush()
        self._null = os.open(os.devnull, os.O_WRONLY)
        self._saved = os.dup(2)
        os.dup2(self._null, 2)

    def __exit__(self, *exc):
        os.dup2(self._saved, 2)
        os.close(self._null)
        os.close(self._saved)


def quantities(T, window):
    x = T[window]
    rng, _, cnt = rainflow(x)
    return {"max": float(x.max()), "std": float(x.std()), "min": float(x.min()),
            "damage": float(np.sum(cnt * rng ** 3))}


def mean_quantities(runs, tracks):
    qs = [quantities(T, tr.window) for T, tr in zip(runs, tracks)]
    return {k: float(np.mean([q[k] for q in qs])) for k in qs[0]}


def errors(q, ref):
    return {"max": abs(q["max"] / ref["max"] - 1), "std": abs(q["std"] / ref["std"] - 1),
            "damage": abs(q["damage"] / ref["damage"] - 1),
            "min": abs(q["min"] - ref["min"]) / ref["max"]}


def meets(e, tol):
    return all(e[k] <= tol[k] for k in tol)


def fmt_e(e):
    return " / ".join(f"{100 * e[k]:.2f}" for k in ("max", "std", "min", "damage"))


def qualifying(results, tol, counts, rest=lambda k: k[1:]):
    """Settings ``(n, ...)`` meeting ``tol`` whose neighbouring element counts of ``counts``
    at the same other settings (``rest(k)``; for MoorDyn the scheme, its step being each
    count's largest stable one) meet it too."""
    ok = [k for k, (e, _) in results.items() if meets(e, tol)]
    good = []
    for k in ok:
        i = counts.index(k[0])
        nb = [counts[j] for j in (i - 1, i + 1) if 0 <= j < len(counts)]
        if all(any(m[0] == c and rest(m) == rest(k) for m in ok) for c in nb):
            good.append(k)
    return good


# MoorDyn's schemes on the OC3 line (a scan of its explicit and implicit schemes, 40 segments,
# irregular case, each at its largest stable and accurate dtM of 0.25-100 ms, 2026-11-28: RK2
# at 6 ms 0.266 s, Euler at 3 ms 0.273 s, local Euler 0.287 s, Midpoint2 at 7 ms 0.244 /
# 0.274 s, BEuler2 at 5 ms 0.360 s, Midpoint5 at 12.5 ms 0.366 s, RK4 at 8 ms 0.47-0.51 s,
# Heun at 1 ms 0.905 s, Wilson5 / Wilson10 2.1-2.8 s, AB3 / AB4 unstable): the three
# cheapest enter the grid
OC3_MD_DTM = [2.5e-4, 1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 7e-3, 8e-3, 1e-2]
CASES = {
    "oc3-harmonic": dict(elements=[20, 30, 40, 60, 80], ref=(160, 8),
                         md_segments=[20, 30, 40, 60, 80], md_dtm=OC3_MD_DTM,
                         md_ref=(160, 2.5e-4, "RK2"), schemes=["RK2", "Euler", "Midpoint2"]),
    "oc3-irregular": dict(elements=[20, 30, 40, 60, 80], ref=(160, 8),
                          md_segments=[20, 30, 40, 60, 80], md_dtm=OC3_MD_DTM,
                          md_ref=(160, 2.5e-4, "RK2"), schemes=["RK2", "Euler", "Midpoint2"]),
    "floatel-slack": dict(elements=[66, 88, 132, 176], ref=(264, 8), substeps=(1, 2, 4),
                          md_segments=[66, 88, 132, 176],
                          md_dtm=[2.5e-4, 5e-4, 1e-3, 2e-3, 3e-3, 4e-3, 6e-3],
                          md_ref=(264, 2.5e-4, "RK4"), schemes=["RK4"]),
}


def tracks_of(case, args):
    if case == "oc3-harmonic":
        return [short_track(HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0,
                                           ramp=15.0), 60.0, 45.0)]
    if case == "oc3-irregular":
        return [short_track(IrregularMotion(), 200.0, 40.0)]
    return floatel_tracks(args.seeds, args.duration)


# ---- the runs: one task per (setting, track), in worker processes, each kept in a store ----

_TRACKS: dict = {}          # case -> tracks (set before the worker processes fork)


def _digest(*parts) -> str:
    h = hashlib.sha256()
    for p in parts:
        h.update(p if isinstance(p, bytes) else repr(p).encode())
        h.update(b"\0")
    return h.hexdigest()


def _track_digest(tr: Track) -> str:
    return _digest(np.ascontiguousarray(tr.t).tobytes(), np.ascontiguousarray(tr.xyz).tobytes(),
                   np.ascontiguousarray(tr.r0).tobytes(), np.asarray(tr.window).tobytes())


_SOURCES = None


def _floatmoor_sources() -> str:
    """Digest of everything of ours a floatmoor run depends on: the package's sources, the
    test helpers that build the lines, the flagship scene, :func:`run_floatmoor`."""
    global _SOURCES
    if _SOURCES is None:
        root = os.path.join(os.path.dirname(__file__), "..")
        files = sorted(glob.glob(os.path.join(root, "floatmoor", "**", "*.py"), recursive=True))
        files += [os.path.join(root, "tests", "mooring", "fe", f)
                  for f in ("moordyn_floatel.py", "conftest.py")]
        files += [str(FL.SCENE)]
        _SOURCES = _digest(*[open(f, "rb").read() for f in files],
                           inspect.getsource(run_floatmoor))
    return _SOURCES


def _moordyn_input(case, tr: Track, nseg, dtm, scheme) -> str:
    """The text MoorDyn is given (its input file and current profile): what
    :func:`run_moordyn` writes for the OC3 line and ``FL.run_moordyn`` for the Floatel-like
    line, and what the store keys a MoorDyn run by."""
    if case.startswith("floatel"):
        text = FL.moordyn_text(tr.case, n_segments=nseg, dtm=dtm, scheme=scheme,
                               internal_damping=BA_FLOATEL)
        return text + (FL.current_profile_text(tr.case) if tr.case.current else "")
    return OC3_TEMPLATE.format(ba=BA_OC3, nseg=nseg, dtm=dtm, scheme=scheme)


def _task_key(case, i, task) -> str:
    """A result's identity: the task, the track and everything that produced it (a floatmoor
    run: our sources; a MoorDyn run: its input text and version and the code that steps it),
    so that an edit to any of
    them makes a stored result stale (never reused)."""
    tr = _TRACKS[case][i]
    kind = task[0]
    if kind == "fm":
        what = (_floatmoor_sources(), BA_OC3, BA_FLOATEL, OC3_SEABED, DT_C)
    else:
        nseg, scheme = task[1], task[-1]
        dtms = [task[2]] if kind == "md" else list(task[2])
        what = (_md_version(), DT_C, md_stable_dtm.__defaults__ if kind == "probe" else (),
                inspect.getsource(md_stable_dtm) if kind == "probe" else "",
                [_moordyn_input(case, tr, nseg, d, scheme) for d in dtms],
                # how the kinematics reach MoorDyn's Step (start-of-step state, chord velocity)
                inspect.getsource(run_moordyn), inspect.getsource(FL.run_moordyn))
    return _digest(case, task, _track_digest(tr), what)


def _run_task(case, i, task):
    """One run: ``("fm", n, nsub, newton)`` / ``("md", nseg, dtm, scheme)`` -> (tension, CPU
    s) or ``("probe", nseg, dtms, scheme)`` -> MoorDyn's largest stable step (on track ``i``);
    a numerical failure -> its message."""
    tr = _TRACKS[case][i]
    try:
        if task[0] == "fm":
            return run_floatmoor(case, tr, task[1], task[2], task[3])
        if task[0] == "md":
            T, cpu = run_moordyn(case, tr, task[1], task[2], task[3])
            if not (np.all(np.isfinite(T)) and T.max() < 1e9):
                return "unstable"
            return T, cpu
        return (md_stable_dtm(case, tr, task[1], task[3], task[2]),)
    except (NumericalError, RuntimeError) as exc:
        return str(exc)


def _load(path):
    with np.load(path, allow_pickle=False) as z:
        if "error" in z.files:
            return str(z["error"])
        if "dtm" in z.files:
            d = float(z["dtm"])
            return (None if math.isnan(d) else d,)
        return z["T"].copy(), float(z["cpu"])


def _save(path, r, label):
    meta = dict(label=label, date=time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime()),
                load=np.array(os.getloadavg()), machine=platform.processor() or platform.machine())
    tmp = path + ".tmp.npz"
    if isinstance(r, str):
        np.savez(tmp, error=r, **meta)
    elif len(r) == 1:
        np.savez(tmp, dtm=np.nan if r[0] is None else r[0], **meta)
    else:
        np.savez(tmp, T=r[0], cpu=r[1], **meta)
    os.replace(tmp, path)        # a run is stored whole or not at all


def _label(case, i, task):
    k = task[0]
    if k == "fm":
        return f"floatmoor {task[1]} el. dt {DT_C / task[2]:g} s {task[3]}, track {i + 1}"
    if k == "md":
        return f"MoorDyn {task[1]} seg. {task[3]} dtM {task[2] * 1e3:g} ms, track {i + 1}"
    return f"MoorDyn {task[1]} seg. {task[3]}: largest stable dtM (probe on track {i + 1})"


class Runner:
    """Runs tasks ``(track index, task)`` of a case, ``jobs`` at a time in worker processes
    (each run's CPU time is its own process's; with 2 jobs on 2 cores the load is about 2, as
    printed), dearest first; with a ``store`` directory every finished run is kept there under
    its key (:func:`_task_key`) and a later invocation reuses it, so an interrupted grid loses
    no finished run.  Timing repeats are always run afresh."""

    def __init__(self, case, jobs=1, store=None):
        self.case, self.jobs, self.store = case, max(1, int(jobs)), store
        if store:
            os.makedirs(store, exist_ok=True)
        self.pool = None
        if self.jobs > 1:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor
            self.pool = ProcessPoolExecutor(self.jobs, mp_context=mp.get_context("fork"))

    def close(self):
        if self.pool is not None:
            self.pool.shutdown()

    def run(self, tasks, cost=lambda task: 0.0, fresh=False):
        """Results of ``tasks`` (a list of (i, task)) in their order; progress printed."""
        out = [None] * len(tasks)
        todo = []
        for j, (i, task) in enumerate(tasks):
            path = None
            if self.store and not fresh:
                path = os.path.join(self.store, _task_key(self.case, i, task) + ".npz")
                if os.path.exists(path):
                    out[j] = _load(path)
                    continue
            todo.append((j, i, task, path))
        n_done, n = 0, len(todo)
        if n < len(tasks):
            print(f"  ({len(tasks) - n} of {len(tasks)} runs from the store {self.store})",
                  flush=True)
        todo.sort(key=lambda x: -cost(x[2]))

        def finish(j, i, task, path, r):
            nonlocal n_done
            n_done += 1
            out[j] = r
            if path:
                _save(path, r, _label(self.case, i, task))
            what = (f"CPU {r[1]:.2f} s" if isinstance(r, tuple) and len(r) == 2
                    else f"dtM {r[0]}" if isinstance(r, tuple) else r)
            print(f"  [{n_done}/{n}] {_label(self.case, i, task)}: {what} (load "
                  f"{os.getloadavg()[0]:.2f})", flush=True)

        if self.pool is None:
            for j, i, task, path in todo:
                finish(j, i, task, path, _run_task(self.case, i, task))
        else:
            from concurrent.futures import as_completed
            futs = {self.pool.submit(_run_task, self.case, i, task): (j, i, task, path)
                    for j, i, task, path in todo}
            for f in as_completed(futs):
                finish(*futs[f], f.result())
        return out


def _md_cost(task):
    """Rough relative cost, to start the dearest runs first."""
    if task[0] == "md":
        return task[1] / task[2]
    if task[0] == "probe":
        return 300.0 * sum(task[1] / d for d in task[2]) / 12000.0
    return task[1] * task[2] / 1000.0


def bench(case, args, tol):
    spec = CASES[case]
    tracks = tracks_of(case, args)
    _TRACKS[case] = tracks
    nt = len(tracks)
    print(f"\n## {case}: {nt} track(s) of {tracks[0].t[-1]:g} s, evaluated over "
          f"{tracks[0].window.sum() * DT_C:g} s each", flush=True)
    md_counts = args.md_segments or spec["md_segments"]
    omitted = [c for c in spec["md_segments"] if c not in md_counts]
    if omitted and min(omitted) < max(md_counts):
        raise SystemExit(f"--md-segments may leave out only the finest counts of "
                         f"{spec['md_segments']}")
    runner = Runner(case, args.jobs, args.store)
    try:
        return _bench(case, spec, tracks, args, tol, runner, md_counts, omitted)
    finally:
        runner.close()


def _bench(case, spec, tracks, args, tol, runner, md_counts, omitted):
    nt = len(tracks)
    n_ref, nsub_ref = spec["ref"]
    fm_keys = [(n, nsub, newton) for n in spec["elements"]
               for nsub in spec.get("substeps", (1, 2)) for newton in args.newton]
    probes = [(n, scheme) for n in md_counts for scheme in spec["schemes"]]
    # the common reference, floatmoor's grid and MoorDyn's step probes, together
    tasks = [(i, ("fm", n_ref, nsub_ref, "exact")) for i in range(nt)]
    tasks += [(i, ("fm",) + k) for k in fm_keys for i in range(nt)]
    tasks += [(0, ("probe", n, tuple(spec["md_dtm"]), scheme)) for n, scheme in probes]
    if not args.no_md_ref:
        tasks.append((0, ("md",) + tuple(spec["md_ref"])))
    res = runner.run(tasks, cost=_md_cost)
    ref_runs = [r[0] for r in res[:nt]]
    ref = mean_quantities(ref_runs, tracks)
    print(f"reference: floatmoor {n_ref} el. at dt {DT_C / nsub_ref:g} s: max "
          f"{ref['max'] / 1e3:.1f} kN, std {ref['std'] / 1e3:.2f} kN, min {ref['min'] / 1e3:.1f} kN",
          flush=True)
    if not args.no_md_ref:
        nseg, dtm, scheme = spec["md_ref"]
        r = res[-1]
        if isinstance(r, str):
            print(f"MoorDyn {nseg} seg. at dtM {dtm * 1e3:g} ms: {r}")
        else:
            tr0 = tracks[0]
            e = errors(quantities(r[0], tr0.window), quantities(ref_runs[0], tr0.window))
            print(f"MoorDyn {nseg} seg. at dtM {dtm * 1e3:g} ms against it, first track (max / "
                  f"std / min / damage %): {fmt_e(e)}  (the two converged codes)", flush=True)
    def summary(label, runs, into, k):
        """A setting's errors against the reference and CPU over the tracks, printed and kept
        in ``into[k]`` (a failed run printed instead)."""
        bad = [r for r in runs if isinstance(r, str)]
        if bad:
            print(f"  {label}: {bad[0]}")
            return
        q = mean_quantities([r[0] for r in runs], tracks)
        into[k] = (errors(q, ref), sum(r[1] for r in runs))
        print(f"  {label}: {fmt_e(into[k][0])} CPU {into[k][1]:.3f} s", flush=True)

    fm, md = {}, {}
    for j, k in enumerate(fm_keys):
        summary(f"floatmoor {k[0]} el. dt {DT_C / k[1]:g} s {k[2]}",
                res[nt + j * nt: nt + (j + 1) * nt], fm, k)
    steps = {}
    for (n, scheme), r in zip(probes, res[nt + len(fm_keys) * nt:]):
        if isinstance(r, str) or r[0] is None:
            print(f"  MoorDyn {n} seg. {scheme}: unstable at every dtM of {spec['md_dtm']}")
        else:
            steps[(n, scheme)] = r[0]
    md_keys = [(n, steps[(n, s)], s) for n, s in probes if (n, s) in steps]
    res = runner.run([(i, ("md",) + k) for k in md_keys for i in range(nt)], cost=_md_cost)
    for j, k in enumerate(md_keys):
        summary(f"MoorDyn {k[0]} seg. {k[2]} dtM {k[1] * 1e3:g} ms (its largest stable)",
                res[j * nt:(j + 1) * nt], md, k)
    fq = qualifying(fm, tol, spec["elements"])
    # MoorDyn's qualifying settings against the whole grid's counts: a count whose neighbour
    # was left out (--md-segments) cannot qualify
    mq = qualifying(md, tol, spec["md_segments"], rest=lambda k: k[2:])
    bound = False
    if omitted and not mq:
        # every setting that qualifies meets the criterion, and the counts left out are finer,
        # hence dearer at their (smaller) stable steps: MoorDyn's cheapest qualifying setting
        # costs at least its cheapest setting that meets the criterion
        mq, bound = [k for k, (e, _) in md.items() if meets(e, tol)], True
    if not fq or not mq:
        print(f"no qualifying setting: floatmoor {bool(fq)}, MoorDyn {bool(mq)} (criterion "
              f"{tol})")
        return None
    bf = min(fq, key=lambda k: fm[k][1])
    bm = min(mq, key=lambda k: md[k][1])
    # interleaved repeats of the two cheapest qualifying settings
    c_f, c_m = [fm[bf][1]], [md[bm][1]]
    for rep in range(max(args.repeat, args.md_repeat) - 1):
        if rep < args.md_repeat - 1:
            c_m.append(sum(r[1] for r in runner.run([(i, ("md",) + bm) for i in range(nt)],
                                                    fresh=True)))
        if rep < args.repeat - 1:
            c_f.append(sum(r[1] for r in runner.run([(i, ("fm",) + bf) for i in range(nt)],
                                                    fresh=True)))
    ratio = min(c_m) / min(c_f)
    how = (f"best of {len(c_f)} / {len(c_m)}; criterion max/std/damage "
           f"{100 * tol['max']:g}/{100 * tol['std']:g}/{100 * tol['damage']:g} %, min "
           f"{100 * tol['min']:g} % of the maximum, neighbouring counts included")
    if bound:
        how += (f"; MoorDyn's {omitted} seg. not run: a lower bound, MoorDyn at its cheapest "
                "setting that meets the criterion")
    elif omitted:
        how += f"; MoorDyn's {omitted} seg. (finer, dearer) not run"
    print(f"cheapest qualifying: floatmoor {bf[0]} el., dt {DT_C / bf[1]:g} s, Newton {bf[2]} "
          f"(errors {fmt_e(fm[bf][0])} %): CPU {min(c_f):.3f} s; MoorDyn {bm[0]} seg., {bm[2]}, "
          f"dtM {bm[1] * 1e3:g} ms (errors {fmt_e(md[bm][0])} %): CPU {min(c_m):.3f} s -> "
          f"{'at least ' if bound else ''}{ratio:.1f}x ({how})", flush=True)
    return ratio


def _md_version():
    import importlib.metadata as md
    return md.version("moordyn")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", nargs="+", default=list(CASES))
    ap.add_argument("--seeds", nargs="+", type=int, default=[1, 2, 3])
    ap.add_argument("--duration", type=float, default=12000.0)
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--newton", nargs="+", default=["exact", "fast"])
    ap.add_argument("--tol", nargs=4, type=float, metavar=("MAX", "STD", "DAMAGE", "MIN"),
                    default=None, help="accuracy criterion (fractions)")
    ap.add_argument("--no-md-ref", action="store_true",
                    help="skip MoorDyn's converged run (its agreement with the reference)")
    ap.add_argument("--quick", action="store_true", help="1 seed of 1800 s (smoke run)")
    ap.add_argument("--jobs", type=int, default=1,
                    help="runs at a time in worker processes (CPU times are per process)")
    ap.add_argument("--store", default=None, metavar="DIR",
                    help="keep every finished run in DIR and reuse it when nothing that "
                         "produced it has changed (an interrupted grid loses no finished run)")
    ap.add_argument("--md-segments", nargs="+", type=int, default=None,
                    help="MoorDyn's counts to run (only the finest may be left out: the "
                         "ratio is then a lower bound unless a run count qualifies)")
    ap.add_argument("--md-repeat", type=int, default=None,
                    help="timing runs of MoorDyn's cheapest setting (default --repeat)")
    args = ap.parse_args()
    if args.quick:
        args.seeds, args.duration = args.seeds[:1], 1800.0
    if args.md_repeat is None:
        args.md_repeat = args.repeat
    tol = dict(TOL) if args.tol is None else dict(zip(("max", "std", "damage", "min"), args.tol))
    import moordyn  # noqa: F401
    import numba

    print(f"# {platform.machine()}, Python {platform.python_version()}, numba "
          f"{numba.__version__}, moordyn {_md_version()}; load "
          f"{' / '.join(f'{v:.2f}' for v in os.getloadavg())}")
    print(f"# coupling step {DT_C} s, both codes fed the start-of-step position and the chord "
          "velocity of the same piecewise-linear fairlead track; errors against floatmoor's "
          "converged run: max / std / min / damage (m = 3) in %")
    run_floatmoor("oc3-harmonic", tracks_of("oc3-harmonic", args)[0], 10)   # compile / load
    for case in args.cases:
        bench(case, args, tol)
    print(f"# load {' / '.join(f'{v:.2f}' for v in os.getloadavg())}")


if __name__ == "__main__":
    main()
