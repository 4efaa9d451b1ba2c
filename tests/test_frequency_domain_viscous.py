"""Viscous drift in the frequency domain: the correction formula (Wang (2016) eq. 6.6)
feeds the FD mean and slow drift, its extra damping the FD linear damping; slender elements
carry their current load in the FD as in the TD (the same model), and the FD says loudly that
their viscous wave drift is not in it (a FloatmoorWarning).

Expected values: eq. 6.6 written out by hand below (Stansberg et al. 2015 as quoted in Wang (2016)
section 6.2) integrated over the scene's wave spectrum with the FD mean drift formula
F = 2 int f(w) S(w) dw (Wang (2016) eq. 2.37); the time domain's Newman drift model (an independent
path: the realised wave components, F = sum a_i^2 f(w_i)) for the FD-TD agreement.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

from floatmoor.analyses.frequency_domain import frequency_domain
from floatmoor.core.errors import FloatmoorWarning, SceneError

ROOT = Path(__file__).resolve().parents[1]
FLOATEL = ROOT / "vessels" / "floatel_like"
HS, TP, U = 16.0, 18.2, 0.94
ENV = {"waves": {"spectrum": "jonswap", "hs": HS, "tp": TP, "heading_deg": 0.0},
       "current": {"profile": "piecewise_linear", "levels": [[0.0, U], [-50.0, U]],
                   "heading_deg": 0.0}}
CF = {"model": "correction_formula", "column_diameters": [12.5, 12.5, 12.5, 12.5],
      "main_column_diameter": 12.5}


def _scene(tmp_path, name, viscous=None, env=ENV, fd=None):
    sc = {"name": name, "site": {"water_depth": 150.0, "water_density": 1025.0},
          "vessel": str(FLOATEL / "vessel.yaml"), "mooring": str(FLOATEL / "mooring.yaml"),
          "environment": env,
          "analysis": {"duration": 12000.0, "dt": 0.1, "transient": 1200.0, "ramp": 100.0}}
    if viscous is not None:
        sc["forces"] = {"viscous_drift": viscous}
    if fd is not None:
        sc["frequency_domain"] = fd
    p = tmp_path / f"{name}.yaml"
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    return p


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fd_visc")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        pot = frequency_domain(_scene(tmp, "pot"))
        cf = frequency_domain(_scene(tmp, "cf", CF))
    return tmp, pot, cf


def _hand_eq_6_6(ds, db, *, u, band=None):
    """2 int f(w) S(w) dw with f = f_pot (1 + Cp U) + B (G U + Hs), B = B0 k p sum(d_i),
    k = w^2/g, p = exp(-1.25 (k D0)^2): Cp 0.25 s/m, G 10 s, B0 1000 N/m^3, sum(d) 50 m,
    D0 12.5 m (Wang (2016) eq. 6.6), on the FD's frequency grid; f_pot the database's surge
    coefficient at 0 deg, linearly interpolated."""
    w = ds.omega.values
    S = ds.wave_spectrum.values
    i0 = int(np.argmin(np.abs(db.wave_direction.values)))
    f_pot_db = db.mean_drift_force.isel(wave_direction=i0).sel(influenced_dof="surge").values
    f_pot = np.interp(w, db.omega.values, f_pot_db)
    k = w ** 2 / 9.80665
    B = 1000.0 * k * np.exp(-1.25 * (k * 12.5) ** 2) * 50.0
    f = f_pot * (1.0 + 0.25 * u) + B * (10.0 * u + HS)
    if band is not None:  # only the frequencies band[0] <= w <= band[1]
        S = np.where((w >= band[0]) & (w <= band[1]), S, 0.0)
    return 2.0 * np.trapezoid(f * S, w), 2.0 * np.trapezoid(f_pot * S, w)


def test_fd_mean_surge_drift_is_eq_6_6_over_the_spectrum(runs):
    import xarray as xr
    _, pot, cf = runs
    db = xr.load_dataset(FLOATEL / "database.nc")
    assert abs(cf["mean"].values[5]) < 1e-9  # head seas on a symmetric semi: yaw 0
    hand, hand_pot = _hand_eq_6_6(cf, db, u=U)
    # potential drift unchanged by the wiring
    assert pot.mean_force_drift.values[0] == pytest.approx(hand_pot, rel=1e-6)
    # B(w) is linear-interpolated from the database grid (step 0.025 rad/s) in the FD and exact
    # here: 0.1 % covers that (measured 2e-5)
    assert cf.mean_force_drift.values[0] == pytest.approx(hand, rel=1e-3)
    assert cf.mean_force_drift.values[0] > 1.5 * pot.mean_force_drift.values[0]
    assert cf.attrs["viscous_drift_model"] == "correction_formula"
    assert pot.attrs["viscous_drift_model"] == "none"
    # the slow drift (Newman) sees the corrected coefficients too: larger drift force spectrum
    # and LF surge motion; the WF motion is untouched (potential flow RAOs)
    assert cf.lf_drift_force_spectrum.values[1:, 0].sum() > \
        1.5 * pot.lf_drift_force_spectrum.values[1:, 0].sum()
    assert cf.lf_std.values[0] > pot.lf_std.values[0]
    # (the mooring stiffness at the new mean position moves it by 0.2 %)
    assert cf.wf_std.values[0] == pytest.approx(pot.wf_std.values[0], rel=0.01)
    assert cf["mean"].values[0] > pot["mean"].values[0]


def test_fd_correction_without_current_is_f_pot_plus_b_hs(tmp_path):
    import xarray as xr
    env = {"waves": ENV["waves"]}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        ds = frequency_domain(_scene(tmp_path, "cf0", CF, env=env))
    hand, _ = _hand_eq_6_6(ds, xr.load_dataset(FLOATEL / "database.nc"), u=0.0)
    assert ds.mean_force_drift.values[0] == pytest.approx(hand, rel=1e-3)


def test_fd_and_td_see_the_same_corrected_mean_drift(runs):
    """The TD Newman drift model of the same scene (assembled, not integrated): its mean force
    sum a_i^2 f(w_i) over the realised components against the FD's 2 int f S dw.  The
    realisation keeps only 0.204-1.590 rad/s (S > 1e-3 S_max, floatmoor.metocean.realisation)
    and the semi's surge drift coefficients grow with frequency: that band holds 98.3 % of the
    potential and 99.0 % of the corrected FD mean drift (measured).  So: TD against eq. 6.6 by
    hand over the realised band within 0.3 %, and against the FD (whole database range) within
    2.5 %."""
    import xarray as xr

    from floatmoor.io.build import build
    from floatmoor.io.scene import load_scene
    from floatmoor.solvers.time_domain import assemble
    tmp, pot, cf = runs
    db = xr.load_dataset(FLOATEL / "database.nc")
    for path, fd, corrected in ((tmp / "cf.yaml", cf, True), (tmp / "pot.yaml", pot, False)):
        sc = load_scene(path)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FloatmoorWarning)
            a = assemble(build(sc), seed=1, dt=0.1, duration=10800.0, ramp=100.0,
                         options=sc.forces, models=["drift_newman"])
        m = a.models["drift_newman"]
        td_mean = m.mean_force()[0]
        wr = a.waves.realisation.omega
        half = 0.5 * (wr[-1] - wr[0]) / (wr.size - 1)
        band = (wr[0] - half, wr[-1] + half)
        hand, hand_pot = _hand_eq_6_6(fd, db, u=U, band=band)
        assert td_mean == pytest.approx(hand if corrected else hand_pot, rel=3e-3)
        assert td_mean == pytest.approx(fd.mean_force_drift.values[0], rel=0.025)
        # the series itself averages to that mean over the record
        assert m.series[:, 0].mean() == pytest.approx(td_mean, rel=0.02)


def test_fd_extra_damping_raises_surge_sway_linear_damping(tmp_path, runs):
    _, _, cf = runs
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        ds = frequency_domain(_scene(tmp_path, "cfd", {**CF, "extra_damping": 1.0}))

    def linear(d):
        return (d.lf_damping.values - d.equivalent_quadratic_damping.values
                - d.lf_damping_wind.values - d.lf_damping_current.values
                - d.lf_damping_wave_drift.values)
    # vessel file: 1.5e6 N s/m in surge and sway; +100 % -> 3.0e6 (Wang (2016) table 6.10)
    assert linear(cf)[0, 0] == pytest.approx(1.5e6, rel=1e-9)
    assert linear(ds)[0, 0] == pytest.approx(3.0e6, rel=1e-9)
    assert linear(ds)[1, 1] == pytest.approx(3.0e6, rel=1e-9)
    assert ds.lf_std.values[0] < cf.lf_std.values[0]
    assert ds.mean_force_drift.values[0] == pytest.approx(cf.mean_force_drift.values[0],
                                                           rel=1e-12)


def test_fd_slender_elements_carry_the_current_as_in_the_time_domain(tmp_path, runs):
    """With slender elements the FD uses the models of the TD: the hull current coefficients
    zeroed in the DOFs the strips carry (double counting, Wang (2016) section 6.1.2) and the
    strips' current load at rest, whose mean forces equal the TD models' static-start forces
    (``mean_force``) of the same scene; a warning says the viscous wave drift is not in it."""
    from floatmoor.io.build import build
    from floatmoor.solvers.time_domain import assemble
    _, pot, _ = runs
    p = _scene(tmp_path, "se", {"model": "slender_elements"})
    with pytest.warns(FloatmoorWarning, match="not their viscous wave drift"):
        ds = frequency_domain(p)
    assert "no viscous wave drift" in ds.attrs["viscous_drift_model"]
    assert "slender_elements" in ds.attrs["notes"]
    assert abs(ds["mean"].values[5]) < 1e-9  # head seas: the TD's start heading
    built = build(p)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        a = assemble(built, seed=1, dt=0.2, duration=10.0, options=built.scene.forces)
    for name in ("current", "slender_elements"):
        td = a.models[name].mean_force()
        fd = ds.mean_force_model.sel(model=name).values
        np.testing.assert_allclose(fd, td, rtol=1e-9, atol=1e-6 * np.abs(td).max())
    # the strips carry the surge current force (the hull's is zeroed there), of the size of the
    # hull coefficients' C V^2 (3.129e5 N s^2/m^2 x 0.94^2 = 276 kN, vessel.yaml)
    assert ds.mean_force_current.values[0] == 0.0
    strips = ds.mean_force_model.sel(model="slender_elements").values[0]
    assert 0.5 * pot.mean_force_current.values[0] < strips < 2.0 * pot.mean_force_current.values[0]
    # and their LF damping joins the current's (LF surge damping above the potential case's)
    assert ds.lf_damping.values[0, 0] > pot.lf_damping.values[0, 0]


def test_fd_qtf_drift_with_correction_formula_is_refused(tmp_path):
    p = _scene(tmp_path, "cfq", CF, fd={"drift": "qtf"})
    with pytest.raises(SceneError, match="frequency_domain.drift"):
        frequency_domain(p)
