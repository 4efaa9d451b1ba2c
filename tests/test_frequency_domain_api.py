"""User API floatmoor.frequency_domain: scene -> Dataset, maxima, tension columns.

Expected values: hand computation (written out below), Wang (2016) figure 5.9 (copied into
FIGURE_5_9 from vessels/floatel_like/source/floatel_superior.yaml), statics of the same scene
(floatmoor.equilibrium), symmetry of head seas on symmetric hulls and moorings.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import floatmoor
from floatmoor.analyses.fd_dataset import VARIABLES, format_table, to_dataset
from floatmoor.analyses.fd_maxima import combine_maxima, safety_factor, tension_columns
from floatmoor.analyses.frequency_domain import FDOptions, frequency_domain, frequency_domain_result
from floatmoor.core.errors import SceneError

ROOT = Path(__file__).resolve().parents[1]
OC3 = ROOT / "vessels" / "oc3_hywind"
FLOATEL = ROOT / "vessels" / "floatel_like"

# Wang (2016) figure 5.9 (MIMOSA, 0 deg), kN: static, std LF, max LF, WF base, std WF, max WF,
# max total, safety factor (copied from Wang (2016); also in
# vessels/floatel_like/source/floatel_superior.yaml)
FIGURE_5_9 = [
    [684.3, 102.1, 322.6, 953.5, 205.2, 842.3, 1795.8, 4.73],
    [715.9, 100.1, 335.2, 958.6, 173.9, 713.1, 1671.7, 5.08],
    [773.7, 86.0, 305.9, 966.5, 137.1, 567.8, 1534.4, 5.54],
    [1358.6, 209.0, 1077.6, 2176.3, 153.9, 611.8, 2788.1, 3.05],
    [1547.7, 329.7, 1798.4, 2954.9, 220.1, 864.0, 3818.9, 2.23],
    [1703.9, 431.4, 2418.5, 3634.0, 272.0, 1072.7, 4706.6, 1.81],
    [1730.2, 438.2, 2446.2, 3687.0, 272.8, 1075.9, 4762.9, 1.78],
    [1568.5, 337.6, 1829.7, 3005.6, 221.1, 867.5, 3873.1, 2.19],
    [1373.6, 216.0, 1109.2, 2220.5, 154.5, 613.5, 2834.0, 3.00],
    [780.9, 85.2, 302.1, 972.2, 137.0, 566.4, 1538.6, 5.52],
    [718.4, 99.8, 331.1, 959.1, 173.4, 710.7, 1669.8, 5.09],
    [683.7, 100.4, 316.2, 948.5, 204.4, 839.4, 1787.9, 4.75],
]


def _scene(tmp_path, vessel_dir, depth, environment, name="fd-test", forces=None):
    sc = {"name": name, "site": {"water_depth": depth, "water_density": 1025.0},
          "vessel": str(vessel_dir / "vessel.yaml"), "mooring": str(vessel_dir / "mooring.yaml"),
          "environment": environment}
    if forces is not None:
        sc["forces"] = forces
    p = tmp_path / "scene.yaml"
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    return p


OC3_ENV = {"waves": {"spectrum": "jonswap", "hs": 6.0, "tp": 10.0, "heading_deg": 0.0},
           "current": {"profile": "piecewise_linear", "levels": [[0.0, 0.5], [-50.0, 0.5]],
                       "heading_deg": 0.0}}
FLOATEL_ENV = {
    "waves": {"spectrum": "jonswap", "hs": 16.0, "tp": 18.2, "heading_deg": 0.0},
    "wind": {"spectrum": "npd", "u10": 36.0, "heading_deg": 0.0},
    "current": {"profile": "piecewise_linear", "levels": [[0.0, 0.94], [-50.0, 0.94]],
                "heading_deg": 0.0}}


@pytest.fixture(scope="module")
def oc3(tmp_path_factory):
    p = _scene(tmp_path_factory.mktemp("oc3"), OC3, 320.0, OC3_ENV, "oc3",
               forces={"exclude": ["current"]})
    return p, frequency_domain(p)


def test_current_without_coefficients_is_refused_as_in_the_time_domain(tmp_path):
    """The OC3 vessel file has no current coefficients: a scene with current is refused by the
    frequency domain as by the time domain (the same current model), naming the key; excluded
    in the forces section, both run without it."""
    p = _scene(tmp_path, OC3, 320.0, OC3_ENV, "oc3-current")
    with pytest.raises(SceneError, match="current_coefficients"):
        frequency_domain(p)
    with pytest.raises(SceneError, match="current_coefficients"):
        floatmoor.simulate(p, seed=1, duration=20.0, dt=0.1)


def test_every_variable_has_units_and_long_name(oc3):
    _, ds = oc3
    for name, var in ds.variables.items():
        if name in ("dof", "dof2", "line", "complex", "lf_mode"):
            continue
        assert "units" in var.attrs and "long_name" in var.attrs, name


def test_oc3_head_seas_symmetry_and_combination(oc3):
    _, ds = oc3
    wf = ds["wf_std"].values
    assert wf[0] > 0.1 and wf[2] > 0.0
    # head seas on an axisymmetric spar: no sway, roll, yaw response
    assert wf[1] < 1e-6 * wf[0] and wf[3] < 1e-6 * wf[4] and wf[5] < 1e-6
    # no drift data in the OC3 database and no wind: no LF excitation
    assert "no wave drift force" in ds.attrs["notes"]
    assert ds.attrs["drift_method"] == "none"
    assert "current" not in ds.attrs["models"]  # excluded (forces: exclude), as in the TD
    assert np.all(ds["lf_std"].values < 1e-9)
    # eq. 2.49 by hand on the dataset's own columns
    exc = np.maximum(ds.lf_max + ds.wf_sig, ds.wf_max + ds.lf_sig)
    np.testing.assert_allclose(ds.max_total, ds["mean"] + exc)
    # figure 5.9 identities: max total = WF base + max WF, SF = MBS / max total
    np.testing.assert_allclose(ds.tension_max_total, ds.tension_wf_base + ds.tension_max_wf)
    np.testing.assert_allclose(ds.safety_factor, ds.mbs / ds.tension_max_total)
    assert "MAXIMUM LINE TENSIONS" in format_table(ds)


def test_oc3_mean_offset_matches_statics(oc3):
    """The mean position equals the statics of the same scene under the dataset's own mean
    loads; the current force is C V^2 of the vessel file (OC3 has none -> zero)."""
    path, ds = oc3
    f = ds.mean_force_wind.values + ds.mean_force_current.values + ds.mean_force_drift.values
    eq = floatmoor.equilibrium(path, external_force=f)
    np.testing.assert_allclose(ds["mean"].values, eq.pose, atol=1e-6)


def test_tension_std_is_gradient_projection(oc3):
    """The WF tension std equals |g . H|^2 S integrated, g the tension gradient (recomputed
    here from the dataset's RAOs and spectrum), and the gradient matches a forward difference
    of the catenary tensions."""
    from floatmoor.io.build import build
    path, ds = oc3
    H = ds.rao.values[..., 0] + 1j * ds.rao.values[..., 1]
    g = ds.tension_gradient.values
    S = ds.wave_spectrum.values
    w = ds.omega.values
    std = np.sqrt(np.trapezoid(np.abs(H @ g.T) ** 2 * S[:, None], w, axis=0))
    np.testing.assert_allclose(ds.tension_std_wf.values, std, rtol=1e-10)
    moor = build(path).mooring
    p = ds["mean"].values
    dp = np.array([0.05, 0, 0, 0, 0, 0])
    fwd = (moor.tensions(p + dp)["fairlead_tension"].values
           - moor.tensions(p)["fairlead_tension"].values) / 0.05
    np.testing.assert_allclose(g[:, 0], fwd, rtol=2e-2, atol=10.0)


def test_options_and_errors(tmp_path, oc3):
    path, _ = oc3
    with pytest.raises(SceneError, match="tension_model"):
        frequency_domain(path, tension_model="fully_dynamic")
    with pytest.raises(SceneError, match="drift"):
        frequency_domain(path, drift="qtf")  # the OC3 database has no QTF
    with pytest.raises(TypeError, match="unknown frequency-domain option"):
        frequency_domain(path, durration=3600.0)
    with pytest.raises(SceneError, match="duration"):
        FDOptions(duration=-1.0)
    sc = {"name": "no-mooring", "site": {"water_depth": 320.0},
          "vessel": str(OC3 / "vessel.yaml")}
    p = tmp_path / "nomoor.yaml"
    p.write_text(yaml.safe_dump(sc))
    with pytest.raises(SceneError, match="mooring"):
        frequency_domain(p)


def test_shorter_duration_gives_smaller_maxima(oc3):
    path, ds = oc3
    ds1 = frequency_domain(path, duration=3600.0)
    np.testing.assert_allclose(ds1.wf_std, ds.wf_std)
    n3, n1 = ds.wf_n_cycles.values[0], ds1.wf_n_cycles.values[0]
    assert n3 == pytest.approx(3 * n1)
    assert ds1.wf_max.values[0] == pytest.approx(ds.wf_std.values[0] * math.sqrt(2 * math.log(n1)))


def test_package_function_and_result_object(oc3):
    """``floatmoor.frequency_domain`` is the plain function; the computation alone
    (``frequency_domain_result``, numpy arrays) turned into a Dataset by the variable table gives
    the same numbers, and the table names every variable of the Dataset once, with units."""
    path, ds = oc3
    assert floatmoor.frequency_domain is frequency_domain
    res = frequency_domain_result(path)
    assert isinstance(res.mean, np.ndarray) and res.solution.rao.shape == (ds.sizes["omega"], 6)
    ds2 = to_dataset(res)
    # the variables of tension_model: dynamic are absent from a quasi-static result
    names = [v.name for v in VARIABLES if v.values(res) is not None]
    assert names == list(ds2.data_vars) == list(ds.data_vars)
    for name in ds.data_vars:
        np.testing.assert_array_equal(ds2[name].values, ds[name].values, err_msg=name)
        assert ds2[name].attrs["units"] and ds2[name].attrs["long_name"], name
    assert ds2["lf_drift_force_spectrum"].attrs["long_name"].startswith(
        f"slowly varying wave drift force spectrum ({res.drift_method},")


# -- hand computations -------------------------------------------------------------------------
def test_rayleigh_and_combination_by_hand():
    # static 1000 kN; LF std 100 kN, Tz 100 s; WF std 50 kN, Tz 10 s; 3 hours:
    # N_LF = 10800/100 = 108, ln 108 = 4.682131, max LF = 100 sqrt(2 x 4.682131) = 306.0108
    # N_WF = 1080, ln 1080 = 6.984716, max WF = 50 sqrt(2 x 6.984716) = 186.8785
    # branch 1: 306.0108 + 2 x 50 = 406.0108 > branch 2: 186.8785 + 2 x 100 = 386.8785
    # max total = 1406.0108, WF base = 1406.0108 - 186.8785 = 1219.1323, SF = 8500/1406.0108
    c = tension_columns(np.array([1000.0]), np.array([100.0]), np.array([100.0]),
                        np.array([50.0]), np.array([10.0]), np.array([8500.0]), 10800.0)
    assert c["max_lf"][0] == pytest.approx(306.0108, abs=1e-3)
    assert c["max_wf"][0] == pytest.approx(186.8785, abs=1e-3)
    assert c["max_total"][0] == pytest.approx(1406.0108, abs=1e-3)
    assert c["wf_base"][0] == pytest.approx(1219.1323, abs=1e-3)
    assert c["safety_factor"][0] == pytest.approx(6.045473, abs=1e-5)
    assert c["branch"][0] == 1
    # table 5.8 (MIMOSA surge): mean 12.52, LF max 30.2, WF sig 3.27 -> 45.99 by branch 1
    # (MIMOSA reports 49.27, i.e. its combination is not eq. 2.49 applied to these three)
    mx, mn, br = combine_maxima(12.52, 0.0, 30.2, 3.27, 0.0)
    assert mx == pytest.approx(45.99) and mn == pytest.approx(-20.95) and br == 1
    mx, _, br = combine_maxima(0.0, 2.0, 3.0, 1.0, 5.0)  # 3 + 1 = 4 < 5 + 2 = 7
    assert mx == pytest.approx(7.0) and br == 2


def test_figure_5_9_safety_factor_column_from_max_total():
    t = np.array(FIGURE_5_9)
    sf = safety_factor(8500.0, t[:, 6])
    np.testing.assert_allclose(np.round(sf, 2), t[:, 7], atol=1e-9)
    assert sf[6] == pytest.approx(8500 / 4762.9)
    # and the eq. 2.60 identity our WF-base column follows: max total = WF base + max WF
    np.testing.assert_allclose(t[:, 3] + t[:, 5], t[:, 6], atol=0.11)


def test_figure_5_9_matches_floatel_source_data():
    ref = FLOATEL / "source" / "floatel_superior.yaml"
    data = yaml.safe_load(ref.read_text())["results"]["mimosa_fd_0deg"]
    np.testing.assert_allclose([data[f"line_{i + 1}"] for i in range(12)], FIGURE_5_9)


# -- the Floatel-like semi (its vessel file may not be committed yet) --------------------------
@pytest.fixture(scope="module")
def floatel(tmp_path_factory):
    if not (FLOATEL / "vessel.yaml").is_file() or not (FLOATEL / "database.nc").is_file():
        pytest.skip("vessels/floatel_like/vessel.yaml or database.nc not present")
    p = _scene(tmp_path_factory.mktemp("floatel"), FLOATEL, 150.0, FLOATEL_ENV, "floatel")
    return frequency_domain(p)


def test_floatel_head_seas_line_symmetry(floatel):
    ds = floatel
    t = ds.tension_max_total.values
    # lines numbered anticlockwise in 4 groups of 3, mirror pairs about the x axis
    for i, j in [(0, 11), (1, 10), (2, 9), (3, 8), (4, 7), (5, 6)]:
        assert t[i] == pytest.approx(t[j], rel=1e-6)
    assert np.argmin(ds.safety_factor.values) in (5, 6)  # lines 6/7 most loaded, as figure 5.9
    assert ds["mean"].values[0] > 0 and ds.lf_std.values[0] > 0
    assert abs(ds["mean"].values[1]) < 1e-6 and ds.wf_std.values[1] < 1e-6 * ds.wf_std.values[0]


def test_floatel_lf_period_consistent_with_mass_and_stiffness(floatel):
    ds = floatel
    K = ds.stiffness.values
    hz, vt = [0, 1, 5], [2, 3, 4]
    Kc = K[np.ix_(hz, hz)] - K[np.ix_(hz, vt)] @ np.linalg.solve(K[np.ix_(vt, vt)],
                                                                 K[np.ix_(vt, hz)])
    t_surge = 2 * math.pi * math.sqrt(ds.lf_mass.values[0, 0] / Kc[0, 0])
    assert t_surge == pytest.approx(ds.lf_natural_period.values.max(), rel=0.02)
    # the LF surge response is dominated by the resonance: Tz within 30 % of it
    assert ds.lf_tz.values[0] == pytest.approx(t_surge, rel=0.3)


# -- FD against TD in the linear limit (needs the time-domain solver) -------------------------
def test_fd_against_td_linear_limit(tmp_path):
    """OC3 spar, small JONSWAP waves, no wind/current/drift (the OC3 database has none): the
    TD WF standard deviation of surge and heave (20 seeds of 3000 s after a 600 s transient)
    within 3 % of the FD value (the linear-limit check: time domain against frequency domain)."""
    from floatmoor.analyses.simulate import simulate as run

    env = {"waves": {"spectrum": "jonswap", "hs": 1.0, "tp": 10.0, "heading_deg": 0.0}}
    sc = {"name": "fd-vs-td", "site": {"water_depth": 320.0, "water_density": 1025.0},
          "vessel": str(OC3 / "vessel.yaml"), "mooring": str(OC3 / "mooring.yaml"),
          "environment": env,
          "analysis": {"duration": 3600.0, "dt": 0.1, "transient": 600.0, "ramp": 100.0}}
    p = tmp_path / "scene.yaml"
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    fd = frequency_domain(p)
    stds = []
    for seed in range(1, 21):
        res = run(p, seed=seed)
        keep = res["time"].values >= 600.0
        x = res["motion"].values[keep]
        stds.append(np.std(x, axis=0))
    td = np.mean(stds, axis=0)
    for k in (0, 2):  # surge, heave: WF std within 3 %
        assert td[k] == pytest.approx(fd.wf_std.values[k], rel=0.03)


# -- the fd subcommand ---------------------------------------------------------------------------
def test_fd_command_prints_table_and_writes_netcdf(oc3, tmp_path, capsys):
    import argparse

    import xarray as xr

    from floatmoor.commands import fd as fd_cmd
    path, ds = oc3
    p = argparse.ArgumentParser()
    fd_cmd.add_arguments(p)
    out = tmp_path / "fd.nc"
    args = p.parse_args([str(path), "--out", str(out), "--duration", "3600"])
    assert fd_cmd.run(args) == 0
    text = capsys.readouterr().out
    assert "MAXIMUM LINE TENSIONS" in text and "surge" in text
    assert all(str(n) in text for n in ds.line.values)
    back = xr.load_dataset(out)
    assert back.attrs["duration"] == 3600.0
    np.testing.assert_allclose(back.wf_std.values, ds.wf_std.values)
    assert back.tension_max_total.attrs["units"] == "N"


def test_oc4_qtf_and_newman_agree_at_zero_difference_frequency():
    """OC4 semi (WAMIT QTF; its mean drift is the QTF diagonal): the slowly varying surge drift
    spectrum from the full QTF equals Newman's at mu = 0 and departs from it as mu grows."""
    from floatmoor.analyses.fd_loads import interp0, qtf_function
    from floatmoor.hydro.database import interpolate_heading, load_database
    from floatmoor.metocean.spectra import jonswap
    from floatmoor.solvers.frequency_domain import newman_drift_spectrum, qtf_drift_spectrum
    path = ROOT / "vessels" / "oc4_semi" / "database.nc"
    if not path.is_file():
        pytest.skip("vessels/oc4_semi/database.nc not present")
    db = load_database(path)
    w = np.linspace(0.25, 3.0, 551)
    S = jonswap(w, 6.0, 10.0, 3.3)
    C = interp0(w, db.omega.values, np.nan_to_num(interpolate_heading(db, "mean_drift_force", 0.0)))
    mu = np.array([0.0, 0.2])
    a = newman_drift_spectrum(w, S, C, mu)[:, 0, 0]
    b = qtf_drift_spectrum(w, S, qtf_function(db, 0.0, np.eye(6)), mu)[:, 0, 0]
    assert b[0] == pytest.approx(a[0], rel=0.01)
    assert abs(b[1] / a[1] - 1.0) > 0.05


def test_relative_flow_damping_against_the_closed_form():
    """The wind and current models' damping ``-dF/dv`` (central differences of their force,
    used by both domains) against the closed form of F = T(yaw) C(theta - yaw) |U e - v|^2 at
    v = 0: B[:, j] = T (2 U C e_j - U C' n_j), e = (cos, sin) and n = (sin, -cos) of the flow
    heading, C' the slope of the (piecewise linear) table on the segment holding theta - yaw,
    for an oblique flow and a non-zero yaw."""
    from floatmoor.analyses.fd_loads import rot6
    from floatmoor.forces.environment import flow_damping
    h = np.radians(np.arange(0.0, 360.0, 30.0))
    coef = np.zeros((h.size, 6))
    coef[:, 0] = 1500.0 * np.cos(h) * np.abs(np.cos(h))
    coef[:, 1] = 900.0 * np.sin(h) * np.abs(np.sin(h))
    coef[:, 3] = -2.0e4 * np.sin(h)
    coef[:, 5] = 4.0e4 * np.sin(2 * h)
    U, heading, yaw = 30.0, math.radians(40.0), math.radians(3.0)
    rel = heading - yaw                          # 37 deg: inside the 30-60 deg segment
    f = (rel - h[1]) / (h[2] - h[1])
    C = rot6(yaw) @ ((1 - f) * coef[1] + f * coef[2])
    dC = rot6(yaw) @ ((coef[2] - coef[1]) / (h[2] - h[1]))
    e = np.array([math.cos(heading), math.sin(heading)])
    n = np.array([math.sin(heading), -math.cos(heading)])
    expected = 2.0 * U * np.outer(C, e) - U * np.outer(dC, n)
    B = flow_damping(U, heading, h, coef, yaw=yaw)
    np.testing.assert_allclose(B[:, :2], expected, rtol=1e-6, atol=1e-9 * np.abs(expected).max())
    assert np.all(B[:, 2:] == 0.0)
    assert np.all(flow_damping(0.0, heading, h, coef, yaw=yaw) == 0.0)


def test_failed_line_is_nan_and_neighbour_takes_more(tmp_path, oc3):
    """ALS: with line 1 of the OC3 spar removed the mean offset grows and the failed line's
    columns are NaN (it carries nothing)."""
    from floatmoor.io.build import build
    path, ds = oc3
    ds_f = frequency_domain(build(path, failed_lines=["line1"]))
    j = list(ds_f.line.values).index("line1")
    assert bool(ds_f.line_failed.values[j])
    assert np.isnan(ds_f.tension_max_total.values[j]) and np.isnan(ds_f.safety_factor.values[j])
    others = [k for k in range(ds_f.sizes["line"]) if k != j]
    assert np.all(np.isfinite(ds_f.tension_max_total.values[others]))
    assert abs(ds_f["mean"].values[0] - ds["mean"].values[0]) > 0.5  # the spar drifts off


def test_scene_section_sets_options_and_cli_main(tmp_path, capsys):
    """A scene's frequency_domain: section is used (duration), and `floatmoor fd` runs through
    the registered command with exit status 0 (2 for a scene without a mooring)."""
    from floatmoor.cli import main
    sc = {"name": "oc3-fd-section", "site": {"water_depth": 320.0},
          "vessel": str(OC3 / "vessel.yaml"), "mooring": str(OC3 / "mooring.yaml"),
          "environment": OC3_ENV, "forces": {"exclude": ["current"]},
          "frequency_domain": {"duration": 3600.0, "lf_cutoff_period": 25.0}}
    p = tmp_path / "scene.yaml"
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    ds = frequency_domain(p)
    assert ds.attrs["duration"] == 3600.0
    assert ds.attrs["lf_cutoff_frequency"] == pytest.approx(2 * math.pi / 25.0)
    assert frequency_domain(p, duration=7200.0).attrs["duration"] == 7200.0  # keyword wins
    assert main(["fd", str(p)]) == 0
    assert "MAXIMUM LINE TENSIONS" in capsys.readouterr().out
    del sc["mooring"]
    p.write_text(yaml.safe_dump(sc, sort_keys=False))
    assert main(["fd", str(p)]) == 2
    assert "mooring" in capsys.readouterr().err


def test_catenary_check_tends_to_linear_combination_for_small_waves(tmp_path):
    """tension_max_total_catenary -> tension_max_total as the sea state vanishes; the relative
    gap is a second-order effect, so it scales with the excursion (about with Hs)."""
    gaps = []
    for hs in (6.0, 0.5):
        env = {"waves": {"spectrum": "jonswap", "hs": hs, "tp": 10.0, "heading_deg": 0.0}}
        ds = frequency_domain(_scene(tmp_path, OC3, 320.0, env, f"oc3-{hs}"))
        lin = ds.tension_max_total.values - ds.tension_static.values
        cat = ds.tension_max_total_catenary.values - ds.tension_static.values
        gaps.append(np.max(np.abs(cat / lin - 1.0)))
    assert gaps[1] < 0.01
    assert 6.0 < gaps[0] / gaps[1] < 20.0  # Hs ratio 12


def test_floatel_wave_drift_damping_option(floatel, tmp_path):
    """With wave drift damping switched on the LF surge damping grows by the Aranha term and the
    LF surge std falls; the WF and mean results do not change."""
    p = _scene(tmp_path, FLOATEL, 150.0, FLOATEL_ENV, "floatel-wdd")
    ds = frequency_domain(p, wave_drift_damping=True)
    b = ds.lf_damping_wave_drift.values[0, 0]
    assert b > 0.0 and floatel.lf_damping_wave_drift.values[0, 0] == 0.0
    assert ds.lf_damping.values[0, 0] == pytest.approx(floatel.lf_damping.values[0, 0] + b)
    assert ds.lf_std.values[0] < floatel.lf_std.values[0]
    np.testing.assert_allclose(ds.wf_std.values, floatel.wf_std.values, rtol=1e-12)
    np.testing.assert_allclose(ds["mean"].values, floatel["mean"].values, atol=1e-9)
