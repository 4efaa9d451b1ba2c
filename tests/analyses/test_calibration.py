"""The calibrated Floatel-like scene reproduces the drivers Wang (2016) publishes.

Expected numbers, all from Wang (2016) (its tables as data:
vessels/floatel_like/source/floatel_superior.yaml): LF surge mass 2.5603e7 kg (section 5.4.3,
eq. 5.2); WF surge standard deviation 3.27 m (table 5.8, MIMOSA "WF sig"); mean surge offsets
4.31 m waves only, 6.42 m wind only, 1.3089 m current only (table 7.2); restoring force
9,500 kN at 30 m (section 5.4.2).  Each within 1 % in the committed calibrated scene.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import floatmoor
from floatmoor.analyses.calibration import (
    Targets,
    calibrate_floatel,
    restoring_force_at,
    scale_database,
    single_environment_means,
    targets_from_source,
)

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "floatel_100yr_calibrated.yaml"
VESSEL = ROOT / "vessels" / "floatel_calibrated" / "vessel.yaml"
MOORING = ROOT / "vessels" / "floatel_like" / "mooring.yaml"
SOURCE = ROOT / "vessels" / "floatel_like" / "source" / "floatel_superior.yaml"
ENV = {"waves": {"spectrum": "jonswap", "hs": 16.0, "tp": 18.2, "gamma": None, "heading_deg": 0.0},
       "wind": {"spectrum": "npd", "u10": 36.0, "heading_deg": 0.0},
       "current": {"profile": "piecewise_linear",
                   "levels": [[0.0, 0.94], [-25.0, 0.94], [-50.0, 0.94]], "heading_deg": 0.0}}


def test_targets_are_the_published_numbers():
    t = targets_from_source(SOURCE)
    assert t == Targets()  # the defaults restate the data file's numbers
    assert (t.lf_surge_mass, t.wf_surge_std) == (2.5603e7, 3.27)
    assert (t.wave_only_mean_surge, t.wind_only_mean_surge, t.current_only_mean_surge) == (
        4.31, 6.42, 1.3089)


def test_wf_sig_of_the_tables_is_the_standard_deviation():
    """Wang (2016) table 5.8, MIMOSA: max 49.27 = mean 12.52 + LF max 30.2 + 2 x 3.27 (eq. 2.49
    with X_sig = 2 sigma, eq. 2.42), so the tabled 'WF sig' 3.27 m is sigma; with sigma = 3.27/2
    the sum would be 45.99 m."""
    import yaml
    mx, mean, lf_max, wf = yaml.safe_load(SOURCE.read_text())["results"]["surge_motion_m"]["mimosa"]
    assert abs(mean + lf_max + 2.0 * wf - mx) < 0.02
    assert abs(mean + lf_max + wf - mx) > 3.0


def test_scale_database_scales_only_what_it_names():
    with xr.open_dataset(ROOT / "vessels" / "floatel_like" / "database.nc") as ds:
        db = ds.load()
    out = scale_database(db, added_mass_surge=0.5, excitation_surge=0.25, drift=2.0)
    ss = {"influenced_dof": "surge", "radiating_dof": "surge"}
    np.testing.assert_allclose(out.added_mass.sel(ss), 0.5 * db.added_mass.sel(ss))
    np.testing.assert_allclose(out.radiation_damping.sel(ss), 0.5 * db.radiation_damping.sel(ss))
    sh = {"influenced_dof": "heave", "radiating_dof": "surge"}
    np.testing.assert_array_equal(out.added_mass.sel(sh), db.added_mass.sel(sh))
    np.testing.assert_allclose(out.excitation_force.sel(influenced_dof="surge"),
                               0.25 * db.excitation_force.sel(influenced_dof="surge"))
    np.testing.assert_array_equal(out.excitation_force.sel(influenced_dof="pitch"),
                                  db.excitation_force.sel(influenced_dof="pitch"))
    np.testing.assert_allclose(out.mean_drift_force, 2.0 * db.mean_drift_force)
    assert out.attrs["calibration_factors"] == [0.5, 0.25, 2.0]


def test_calibrated_scene_loads_and_its_fd_table_prints():
    scene = floatmoor.load_scene(SCENE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fd = floatmoor.frequency_domain(scene)
    text = floatmoor.format_fd_table(fd)
    assert "MAXIMUM LINE TENSIONS" in text and "line7" in text and "surge" in text
    # the FD LF surge mass is the published one (m + A11 at the lowest database frequency)
    assert float(fd.lf_mass.sel(dof="surge", dof2="surge")) == pytest.approx(2.5603e7, rel=1e-3)


def test_calibrated_scene_reproduces_the_calibrated_quantities_to_one_percent():
    got = single_environment_means(VESSEL, MOORING, ENV)
    assert got["waves"] == pytest.approx(4.31, rel=0.01)        # table 7.2 waves only
    assert got["wind"] == pytest.approx(6.42, rel=0.01)         # table 7.2 wind only
    assert got["current"] == pytest.approx(1.3089, rel=0.01)    # table 7.2 current only
    assert got["wf_std"] == pytest.approx(3.27, rel=0.01)       # table 5.8 WF sig (sigma)
    assert got["lf_mass"] == pytest.approx(2.5603e7, rel=0.01)  # section 5.4.3
    # section 5.4.2: 9,500 kN at 30 m (the mooring is the Floatel-like one, unchanged)
    assert restoring_force_at(MOORING, VESSEL, 30.0) == pytest.approx(9.5e6, rel=0.01)


def test_calibration_function_regenerates_the_committed_vessel(tmp_path):
    """calibrate_floatel from the Floatel-like vessel gives the committed factors."""
    res = calibrate_floatel(ROOT / "vessels" / "floatel_like" / "vessel.yaml", MOORING,
                            ROOT / "scenes" / "floatel_100yr.yaml", tmp_path,
                            targets=targets_from_source(SOURCE))
    with xr.open_dataset(ROOT / "vessels" / "floatel_calibrated" / "database.nc") as ds:
        committed = list(ds.attrs["calibration_factors"])
    np.testing.assert_allclose([res.added_mass_surge, res.excitation_surge, res.drift],
                               committed, rtol=1e-6)
    import yaml
    vessel = yaml.safe_load(VESSEL.read_text())
    # wind 1543 and current 3.129e5 N s^2/m^2: the Floatel-like surge coefficients at 0 deg
    assert vessel["wind_coefficients"]["surge"][0] == pytest.approx(1543.0 * res.wind, rel=1e-6)
    assert vessel["current_coefficients"]["surge"][0] == pytest.approx(3.129e5 * res.current,
                                                                       rel=1e-6)
    for key, target in (("waves", 4.31), ("wind", 6.42), ("current", 1.3089), ("wf_std", 3.27)):
        assert res.achieved[key] == pytest.approx(target, rel=0.005)
    assert (tmp_path / "vessel.yaml").is_file() and (tmp_path / "database.nc").is_file()
