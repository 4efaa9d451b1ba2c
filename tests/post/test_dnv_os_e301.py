"""DNV-OS-E301 design checks against hand computations and Wang's (2016) figure 5.9.

Factors: Wang (2016) tables 3.1 (ULS) and 3.2 (ALS), eq. 3.4 and
the remarks under table 3.1.  Every expected number below is worked out by hand in the comment
next to it.
"""

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.post import dnv_os_e301 as dnv
from floatmoor.post.extremes import gumbel_fit

DATA = Path(__file__).parent / "data" / "floatel_fig59.yaml"
WANG2016 = (Path(__file__).resolve().parents[2] / "vessels" / "floatel_like" / "source"
            / "floatel_superior.yaml")
kN = 1e3


def fig59():
    node = Node.load(DATA)
    table = node.child("mimosa_fd_0deg")
    rows = {name: table.list(name) for name in table.keys()}
    return node.float("mbs_kN"), rows


# -- table values -------------------------------------------------------------------------------

@pytest.mark.parametrize("ls, cc, an, gm, gd", [
    ("ULS", 1, "dynamic", 1.10, 1.50),        # Wang (2016) table 3.1 row 1
    ("ULS", 2, "dynamic", 1.40, 2.10),        # row 2
    ("ULS", 1, "quasi-static", 1.70, 1.70),   # row 3 (one value for both components)
    ("ULS", 2, "quasi-static", 2.50, 2.50),   # row 4
    ("ALS", 1, "dynamic", 1.00, 1.10),        # Wang (2016) table 3.2 row 1
    ("ALS", 2, "dynamic", 1.00, 1.25),        # row 2
    ("ALS", 1, "quasi-static", 1.10, 1.10),   # row 3
    ("ALS", 2, "quasi-static", 1.35, 1.35),   # row 4
])
def test_partial_factors_are_the_seed_tables(ls, cc, an, gm, gd):
    f = dnv.partial_factors(ls, cc, an)
    assert (f.gamma_mean, f.gamma_dyn) == (gm, gd)
    assert "2008" in f.source and ("3.1" in f.source if ls == "ULS" else "3.2" in f.source)


def test_edition_and_source_are_stated():
    assert "October 2008" in dnv.EDITION
    for word in ("DNV-OS-E301", "2008", "Ch.2 Sec.2", "table 3.1", "3.2", "0.95"):
        assert word in dnv.SOURCE


# -- hand-computed examples, one per class and analysis type ------------------------------------
# MBS 8500 kN -> S_C = 0.95 * 8500 = 8075 kN.

def check(tm, tmax, ls, cc, an, **kw):
    return dnv.line_check(tm * kN, tmax * kN, 8500 * kN, limit_state=ls, consequence_class=cc,
                          analysis=an, **kw)


def test_uls_class2_dynamic_hand_example():
    # T_mean 2000, T_C 5000 -> T_dyn 3000; design 1.4*2000 + 2.1*3000 = 2800 + 6300 = 9100 kN
    r = check(2000, 5000, "ULS", 2, "dynamic")
    assert r["s_c"] == pytest.approx(8075 * kN)
    assert r["design_tension"] == pytest.approx(9100 * kN)
    assert r["utilisation"] == pytest.approx(9100 / 8075)       # 1.12693
    assert r["margin"] == pytest.approx(-1025 * kN)
    assert not r["passed"]
    assert not r["common_factor_applied"]
    assert r["safety_factor"] == pytest.approx(8500 / 5000)


def test_uls_class1_dynamic_without_common_factor():
    # T_mean 1000 < 2/3 * 3000 = 2000: table factors; 1.1*1000 + 1.5*3000 = 5600 kN
    r = check(1000, 4000, "ULS", 1, "dynamic")
    assert not r["common_factor_applied"]
    assert r["design_tension"] == pytest.approx(5600 * kN)
    assert r["utilisation"] == pytest.approx(5600 / 8075)       # 0.69350
    assert r["passed"]


def test_uls_class1_dynamic_common_factor_mean_dominated():
    # T_mean 3000 > 2/3 * 1000: common 1.3 on both: 1.3*(3000 + 1000) = 5200 kN
    # (table factors would give 1.1*3000 + 1.5*1000 = 4800 kN)
    r = check(3000, 4000, "ULS", 1, "dynamic")
    assert r["common_factor_applied"]
    assert (r["gamma_mean"], r["gamma_dyn"]) == (1.3, 1.3)
    assert r["design_tension"] == pytest.approx(5200 * kN)


def test_common_factor_as_written_can_lower_the_design_tension():
    # T_mean 2100, T_dyn 3000: 2100 > 2/3*3000 = 2000, so as written 1.3*5100 = 6630 kN,
    # lower than the table factors 1.1*2100 + 1.5*3000 = 2310 + 4500 = 6810 kN.
    r = check(2100, 5100, "ULS", 1, "dynamic")
    assert r["common_factor_applied"]
    assert r["design_tension"] == pytest.approx(6630 * kN)
    c = check(2100, 5100, "ULS", 1, "dynamic", common_factor_rule="conservative")
    assert not c["common_factor_applied"]
    assert c["design_tension"] == pytest.approx(6810 * kN)


def test_common_factor_needs_strictly_greater_mean():
    # T_mean 2000 = 2/3 * 3000 exactly: not applied; 1.1*2000 + 1.5*3000 = 6700 kN
    r = check(2000, 5000, "ULS", 1, "dynamic")
    assert not r["common_factor_applied"]
    assert r["design_tension"] == pytest.approx(6700 * kN)


@pytest.mark.parametrize("ls, cc, an", [("ULS", 2, "dynamic"), ("ULS", 1, "quasi-static"),
                                        ("ALS", 1, "dynamic"), ("ALS", 2, "dynamic")])
def test_common_factor_only_uls_class1_dynamic(ls, cc, an):
    # T_mean 3000 > 2/3 * 1000 everywhere, yet the remark applies to ULS class 1 dynamic only
    r = check(3000, 4000, ls, cc, an)
    assert not r["common_factor_applied"]
    f = dnv.partial_factors(ls, cc, an)
    assert r["design_tension"] == pytest.approx((3000 * f.gamma_mean + 1000 * f.gamma_dyn) * kN)


def test_uls_quasi_static_hand_examples():
    # class 1: 1.7 * (2500 + 2500) = 8500 kN -> u = 8500/8075 = 1.05263, fails
    r = check(2500, 5000, "ULS", 1, "quasi-static")
    assert r["design_tension"] == pytest.approx(8500 * kN)
    assert r["utilisation"] == pytest.approx(1.0526315789)
    assert not r["passed"]
    # class 2: 2.5 * 3000 = 7500 kN -> u = 0.92879, passes
    r = check(1000, 3000, "ULS", 2, "quasi-static")
    assert r["design_tension"] == pytest.approx(7500 * kN)
    assert r["utilisation"] == pytest.approx(7500 / 8075)
    assert r["passed"]


def test_als_hand_examples():
    # class 1 dynamic: 1.0*2000 + 1.1*3000 = 5300 kN
    assert check(2000, 5000, "ALS", 1, "dynamic")["design_tension"] == pytest.approx(5300 * kN)
    # class 2 dynamic: 1.0*2000 + 1.25*3000 = 5750 kN
    assert check(2000, 5000, "ALS", 2, "dynamic")["design_tension"] == pytest.approx(5750 * kN)
    # class 1 quasi-static: 1.1*5000 = 5500 kN; class 2: 1.35*5000 = 6750 kN
    assert check(2000, 5000, "ALS", 1, "quasi-static")["design_tension"] == pytest.approx(5500 * kN)
    assert check(2000, 5000, "ALS", 2, "quasi-static")["design_tension"] == pytest.approx(6750 * kN)


def test_single_point_mooring_factor():
    # second remark under table 3.1: ULS factors x 1.2 -> class 2 dynamic 1.68 / 2.52;
    # 1.68*2000 + 2.52*3000 = 3360 + 7560 = 10920 kN
    f = dnv.partial_factors("ULS", 2, "dynamic", single_point_mooring=True)
    assert (f.gamma_mean, f.gamma_dyn) == pytest.approx((1.68, 2.52))
    r = check(2000, 5000, "ULS", 2, "dynamic", single_point_mooring=True)
    assert r["design_tension"] == pytest.approx(10920 * kN)
    with pytest.raises(SceneError, match="ALS is not applicable"):
        dnv.partial_factors("ALS", 2, "dynamic", single_point_mooring=True)


def test_characteristic_strength():
    assert dnv.characteristic_strength(8500 * kN) == pytest.approx(8075 * kN)
    assert dnv.characteristic_strength(1000.0, 0.9) == pytest.approx(900.0)


@pytest.mark.parametrize("kwargs, key", [
    (dict(limit_state="SLS"), "limit_state"),
    (dict(consequence_class=3), "consequence_class"),
    (dict(analysis="static"), "analysis"),
])
def test_bad_options_raise_scene_error(kwargs, key):
    args = dict(limit_state="ULS", consequence_class=2, analysis="dynamic") | kwargs
    with pytest.raises(SceneError) as err:
        dnv.partial_factors(**args)
    assert err.value.key == key


def test_bad_tensions_raise():
    with pytest.raises(SceneError, match="t_max"):
        dnv.line_check(3e6, 2e6, 8.5e6)          # max below mean
    with pytest.raises(SceneError, match="mbs"):
        dnv.line_check(1e6, 2e6, -1.0)
    with pytest.raises(SceneError, match="t_mean"):
        dnv.line_check(np.nan, 2e6, 8.5e6)


# -- Wang's (2016) figure 5.9 ----------------------------------------------------------------------

def test_figure_5_9_safety_factor_column_reproduced():
    """SF = MBS / max_tot (Wang (2016) eq. 3.3) to the 2 decimals MIMOSA prints, for all 12 lines,
    e.g. line 7: 8500 / 4762.9 = 1.7846 -> 1.78."""
    mbs, rows = fig59()
    assert len(rows) == 12
    for name, row in rows.items():
        max_tot, sf = row[6], row[7]
        assert round(dnv.simple_safety_factor(mbs, max_tot), 2) == pytest.approx(sf, abs=1e-9), name
    sfs = dnv.simple_safety_factor(mbs, np.array([r[6] for r in rows.values()]))
    assert list(rows)[int(np.argmin(sfs))] == "line_7"       # Wang (2016): line 7, lowest SF 1.78


def test_figure_5_9_copy_matches_floatel_source_data():
    ref = Node.load(WANG2016).child("results").child("mimosa_fd_0deg")
    _, rows = fig59()
    for name, row in rows.items():
        assert ref.list(name) == row


def test_check_lines_on_figure_5_9():
    """ULS class 2 dynamic with T_C-mean = static and T_C = max_tot of figure 5.9.

    Line 7 by hand: 1.4*1730.2 + 2.1*(4762.9 - 1730.2) = 2422.28 + 6368.67 = 8790.95 kN,
    u = 8790.95 / 8075 = 1.08866 (fails); line 1: 1.4*684.3 + 2.1*1111.5 = 958.02 + 2334.15
    = 3292.17 kN, u = 0.40770.
    """
    mbs, rows = fig59()
    names = list(rows)
    static = np.array([r[0] for r in rows.values()]) * kN
    max_tot = np.array([r[6] for r in rows.values()]) * kN
    ds = dnv.check_lines(names, mbs * kN, uls_mean=static, uls_max=max_tot,
                         consequence_class=2, analysis="dynamic")
    u = ds["utilisation"].sel(limit_state="ULS")
    assert float(u.sel(line="line_7")) == pytest.approx(8790.95 / 8075)
    assert float(u.sel(line="line_1")) == pytest.approx(3292.17 / 8075)
    assert ds.attrs["governing_line"] == "line_7"
    assert str(ds["governing_line"].sel(limit_state="ULS").item()) == "line_7"
    assert bool(ds["governing"].sel(limit_state="ULS", line="line_7"))
    assert int(ds["governing"].sum()) == 1
    assert not bool(ds["passed"].sel(limit_state="ULS", line="line_7"))
    assert ds.attrs["all_passed"] == 0
    sf = ds["safety_factor"].sel(limit_state="ULS").values
    np.testing.assert_allclose(np.round(sf, 2), [r[7] for r in rows.values()])
    for name, var in ds.data_vars.items():
        if name != "governing_line":
            assert "units" in var.attrs and "long_name" in var.attrs, name


def test_check_lines_uls_and_als_with_failed_line():
    # 3 lines, MBS 1000 kN (S_C 950). ULS class 1 dynamic: line a 300/600 -> Tm 300 > 2/3*300:
    # common 1.3*600 = 780, u = 0.82105. ALS: line a failed (NaN); line b 400/850 -> 1.0*400 +
    # 1.1*450 = 895, u = 0.94211 (passes); line c 200/500 -> 200 + 1.1*300 = 530, u = 0.55789.
    ds = dnv.check_lines(["a", "b", "c"], 1000 * kN,
                         uls_mean=np.array([300, 250, 150]) * kN,
                         uls_max=np.array([600, 550, 400]) * kN,
                         als_mean=np.array([np.nan, 400, 200]) * kN,
                         als_max=np.array([np.nan, 850, 500]) * kN,
                         consequence_class=1, analysis="dynamic")
    uls = ds.sel(limit_state="ULS")
    assert float(uls["utilisation"].sel(line="a")) == pytest.approx(780 / 950)
    assert bool(uls["common_factor_applied"].sel(line="a"))
    als = ds.sel(limit_state="ALS")
    assert not bool(als["checked"].sel(line="a"))
    assert np.isnan(float(als["utilisation"].sel(line="a")))
    assert float(als["design_tension"].sel(line="b")) == pytest.approx(895 * kN)
    assert float(als["utilisation"].sel(line="c")) == pytest.approx(530 / 950)
    assert bool(als["passed"].sel(line="b"))
    assert str(als["governing_line"].item()) == "b"
    assert ds.attrs["governing_limit_state"] == "ALS"
    assert ds.attrs["all_passed"] == 1
    # the Dataset writes to netCDF
    ds2 = ds.copy()
    ds2["governing_line"] = ds2["governing_line"].astype(str)
    assert isinstance(ds2.to_netcdf(), (bytes, memoryview))


def test_check_lines_rejects_wrong_shapes_and_nan_uls():
    with pytest.raises(SceneError, match="uls_mean"):
        dnv.check_lines([1, 2], 1e6, uls_mean=[1.0], uls_max=[2.0, 3.0])
    with pytest.raises(SceneError, match="finite ULS"):
        dnv.check_lines([1, 2], 1e6, uls_mean=[1.0, np.nan], uls_max=[2.0, 3.0])
    with pytest.raises(SceneError, match="ALS"):
        dnv.check_lines([1, 2], 1e6, uls_mean=[1.0, 1.0], uls_max=[2.0, 3.0],
                        als_mean=[1.0, 1.0])


def test_characteristic_tensions_from_seeds():
    rng = np.random.default_rng(7)
    lines = ["L1", "L2"]
    maxima = np.stack([3e6 + 2e5 * rng.gumbel(size=20), 2e6 + 1e5 * rng.gumbel(size=20)], axis=1)
    means = np.stack([np.full(20, 1.7e6), np.full(20, 1.2e6)], axis=1) + 1e3 * rng.normal(size=(20, 2))
    smax = xr.DataArray(maxima, dims=("seed", "line"), coords={"line": lines},
                        attrs={"units": "N"})
    smean = xr.DataArray(means, dims=("seed", "line"), coords={"line": lines})
    ds = dnv.characteristic_tensions(smax, smean)
    for j, name in enumerate(lines):
        fit = gumbel_fit(maxima[:, j])
        # closed form of the 90 % fractile: loc - scale ln(-ln 0.9) = loc + 2.250367 scale
        assert float(ds["t_c"].sel(line=name)) == pytest.approx(fit.loc + 2.2503673273 * fit.scale)
        assert float(ds["t_c_mean"].sel(line=name)) == pytest.approx(means[:, j].mean())
        assert float(ds["t_c_dyn"].sel(line=name)) == pytest.approx(
            float(ds["t_c"].sel(line=name)) - means[:, j].mean())
        assert float(ds["gumbel_mpm"].sel(line=name)) == pytest.approx(fit.loc)
    assert ds.attrs["n_seeds"] == 20
    with pytest.raises(SceneError, match="seed_max"):
        dnv.characteristic_tensions(smax.rename(seed="run"), smean)
