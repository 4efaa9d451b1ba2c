"""Wind and current relative to the low-frequency body velocity (Wang (2016) eq. 2.24, 2.26).

The solver removes the linear wave-frequency velocity (motion RAOs x the run's wave realisation,
:mod:`floatmoor.solvers.wf_velocity`) from the body velocity in the wind and current forces
(``forces: {relative_velocity: low_frequency}``, the default); ``total`` keeps the total body
velocity.  Floatel-like semi, 10-year current 0.94 m/s along +x, 100-year sea Hs 16 m Tp 18.2 s
(Wang (2016) section 5.2) in head seas.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from floatmoor.analyses.frequency_domain import frequency_domain
from floatmoor.analyses.simulate import simulate
from floatmoor.core.errors import SceneError
from floatmoor.io.build import build
from floatmoor.io.forces_section import ForcesSpec, parse_forces
from floatmoor.io.scene import load_scene
from floatmoor.solvers.time_domain import assemble

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")

ROOT = Path(__file__).resolve().parents[2]
FL = ROOT / "vessels" / "floatel_like"
C_CUR = 3.129e5   # N s^2/m^2, surge current coefficient at 0 deg (vessels/floatel_like/vessel.yaml)
V_CUR = 0.94      # m/s
WAVES = "  waves: {spectrum: jonswap, hs: 16.0, tp: 18.2, heading_deg: 0.0}\n"
CURRENT = "  current: {profile: piecewise_linear, levels: [[0.0, 0.94]], heading_deg: 0.0}\n"
WIND = "  wind: {spectrum: npd, u10: 36.0, heading_deg: 0.0}\n"


def _build(tmp_path_factory, name, env):
    assert (FL / "database.nc").is_file(), "the shipped floatel_like database is missing"
    p = tmp_path_factory.mktemp(name) / "s.yaml"
    p.write_text(f"name: {name}\nsite: {{water_depth: 150.0}}\nvessel: {FL / 'vessel.yaml'}\n"
                 f"mooring: {FL / 'mooring.yaml'}\n" + ("environment:\n" + env if env else ""))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return build(load_scene(p))


@pytest.fixture(scope="module")
def waves_current(tmp_path_factory):
    return _build(tmp_path_factory, "wc", WAVES + CURRENT)


@pytest.fixture(scope="module")
def current_only(tmp_path_factory):
    return _build(tmp_path_factory, "c", CURRENT)


def test_mean_current_force_is_cv2_with_low_frequency_velocity(waves_current):
    """(a) Waves + current, first-order waves only (drift excluded, so the LF motion is small):
    the mean current force over a long run is C V^2 = 276.5 kN (the frequency-domain value,
    eq. 2.27 at rest) with the low-frequency relative velocity (measured 276.5 kN); with the
    total velocity the WF surge velocity (std 1.25 m/s > V) inflates it (measured 634 kN)."""
    means = {}
    for mode in ("low_frequency", "total"):
        ds = simulate(waves_current, seed=1, duration=2400.0, dt=0.2, ramp=100.0,
                      forces=ForcesSpec(exclude=("drift",), relative_velocity=mode,
                                        record_forces=True))
        assert ds.attrs["relative_velocity"] == mode
        sel = ds["time"].values > 300.0
        means[mode] = float(ds["force"].sel(model="current").values[sel, 0].mean())
        if mode == "low_frequency":
            assert "low-frequency" in ds.attrs["relative_velocity_note"]
            # the WF surge velocity really is large here: the test would fail without removal
            assert ds["velocity"].values[sel, 0].std() > V_CUR
    cv2 = C_CUR * V_CUR ** 2
    assert means["low_frequency"] == pytest.approx(cv2, rel=0.03)
    assert means["total"] > 1.8 * cv2


def test_without_waves_both_options_identical(tmp_path_factory):
    """(b) No waves: there is no WF velocity, both options give the same run bit for bit."""
    b = _build(tmp_path_factory, "wcw", CURRENT + WIND)
    runs = [simulate(b, seed=3, duration=200.0, dt=0.2, ramp=20.0,
                     forces=ForcesSpec(relative_velocity=mode)) for mode in
            ("low_frequency", "total")]
    assert np.array_equal(runs[0]["motion"].values, runs[1]["motion"].values)
    assert np.array_equal(runs[0]["line_tension"].values, runs[1]["line_tension"].values)
    a = assemble(b, seed=3, dt=0.2, duration=200.0)
    assert a.wf_velocity is None


def _decay_rate(ds, t_end=950.0):
    """Decay rate sigma (1/s) of the low-pass filtered surge (4th-order Butterworth at 1/40 Hz,
    zero phase), fitted as A exp(-sigma t) cos(w t + phi) + c."""
    from scipy.optimize import curve_fit
    from scipy.signal import butter, filtfilt

    t = ds["time"].values
    x = ds["motion"].values[:, 0]
    dt = t[1] - t[0]
    bb, aa = butter(4, 1.0 / 40.0, fs=1.0 / dt)
    xl = filtfilt(bb, aa, x)
    sel = (t > 40.0) & (t < t_end)

    def f(t, A, s, w, ph, c):
        return A * np.exp(-s * t) * np.cos(w * t + ph) + c

    p, _ = curve_fit(f, t[sel], xl[sel], p0=[4.0, 0.005, 2 * math.pi / 85.0, 0.0, x[-1]])
    return float(p[1]), float(2 * math.pi / p[2])


def test_current_damping_of_lf_surge_preserved_in_waves(waves_current, current_only,
                                                        tmp_path_factory):
    """(c) Free surge decay (4 m from the static position, 1000 s) with current, linear
    damping and drift excluded.  The LF decay rate is sigma = C V / (M + A11(w_n)) (current
    damping 2 C V, eq. 2.27) plus the decay without current (sigma_0 = 0.00090 1/s, from the
    radiation memory; mostly numerical: 2.9e-5, 2.0e-4, 9.0e-4, 3.8e-3 1/s at dt 0.05, 0.1,
    0.2, 0.4 s, about second order, while the database's B11(w_n) alone gives 7e-6):
    measured sigma - sigma_0 = 0.00561 against 0.00570 (-1.5 %).  In waves
    (Hs 16 m, WF surge velocity std 1.25 m/s) the decay is the offset run minus the run of the
    same seed from the static position (the wave response removed by superposition): with the
    low-frequency relative velocity the decay rate stays (seed 1: -0.9 %; 1500 s runs of seeds
    2, 3: -4.2 %, -2.8 %); with the total velocity the WF velocity adds damping (+35 %)."""
    no_cur = _build(tmp_path_factory, "n", "")
    sig = {}
    period = None
    for key, b, mode in (("none", no_cur, "low_frequency"),
                         ("current", current_only, "low_frequency"),
                         ("waves", waves_current, "low_frequency"),
                         ("waves_total", waves_current, "total")):
        opts = ForcesSpec(exclude=("drift", "damping_linear"), relative_velocity=mode)
        a = assemble(b, seed=1, dt=0.2, duration=100.0, options=opts)
        x0 = a.x0.copy()
        x0[0] += 4.0
        ds = simulate(b, seed=1, duration=1000.0, dt=0.2, ramp=0.0, start_pose=x0, forces=opts)
        if key.startswith("waves"):
            ref = simulate(b, seed=1, duration=1000.0, dt=0.2, ramp=0.0, start_pose=a.x0,
                           forces=opts)
            ds["motion"] = ds["motion"] - ref["motion"]
        sig[key], T = _decay_rate(ds)
        if key == "current":
            period = T
    db = current_only.vessel.database
    wn = 2 * math.pi / period
    a11 = float(np.interp(wn, db["omega"].values,
                          db["added_mass"].sel(influenced_dof="surge",
                                               radiating_dof="surge").values))
    mass = float(current_only.vessel.mass_matrix[0, 0])
    sigma_current = C_CUR * V_CUR / (mass + a11)   # 2 C V / (2 (M + A))
    assert sig["current"] - sig["none"] == pytest.approx(sigma_current, rel=0.05)
    assert sig["waves"] == pytest.approx(sig["current"], rel=0.05)
    assert sig["waves_total"] > 1.15 * sig["current"]


def test_wf_velocity_against_frequency_domain(waves_current):
    """(d) The solver's WF velocity (surge, heave, pitch) has the standard deviation of the
    frequency-domain WF velocity spectrum, sqrt(int w^2 S_x(w) dw) of ``wf_spectrum`` (same
    database, mass, damping, stiffness at the mean position): within 3 % (measured +0.3 %,
    +0.5 %, +0.4 %)."""
    fd = frequency_domain(waves_current)
    w = fd["omega"].values
    S = fd["wf_spectrum"].values
    std_fd = np.sqrt(np.trapezoid(w[:, None] ** 2 * S, w, axis=0))
    a = assemble(waves_current, seed=1, dt=0.2, duration=3600.0, ramp=100.0)
    v = a.wf_velocity[1000:]          # after the ramp (samples every dt/2)
    std_td = v.std(axis=0)
    for k in (0, 2, 4):
        assert std_td[k] == pytest.approx(std_fd[k], rel=0.03), k


def test_relative_velocity_option_parsed_and_checked(tmp_path):
    from floatmoor.core.config import Node
    spec = parse_forces(Node({"relative_velocity": "total"}, file=tmp_path / "s.yaml",
                             path="forces"))
    assert spec.relative_velocity == "total"
    assert parse_forces(Node({}, file=None, path="forces")).relative_velocity == "low_frequency"
    with pytest.raises(SceneError, match="relative_velocity"):
        parse_forces(Node({"relative_velocity": "lf"}, file=None, path="forces"))
