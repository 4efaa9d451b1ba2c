"""``floatmoor report``: the verdict over every limit state, the analysis type that follows the
line model (and the DAF of ``floatmoor lines``), the end-of-life capacity, the design codes,
anchor uplift and FLS -- on short storms of the Floatel-like flagship and of the OC3 spar.

Expected numbers are worked out from the result files (scipy's Gumbel fit, as
tests/test_cli_report.py) and the code files' factors, with the source of each factor beside
it: DNV-OS-E301 (2008) table 3.1 (Wang (2016)) class 2 dynamic 1.4 / 2.1 and quasi-static 2.5,
S_C = 0.95 MBS; the chain's end-of-life diameter 84 - 0.4 x 20 = 76 mm (corrosion allowance
0.4 mm/year in the splash and bottom zones, DNV-OS-E301 (2008) table B1 in the code file, over
the default design life of 20 years), MBS x (76/84)^2; API RP 2SK (2005) intact quasi-static
factor of safety 2.0 on S_C = MBS.
"""

import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from scipy import stats

from floatmoor.cli import main

ROOT = Path(__file__).resolve().parents[1]
FLAGSHIP = ROOT / "scenes" / "floatel_100yr.yaml"
OC3 = ROOT / "scenes" / "oc3_hywind.yaml"
EOL = (76.0 / 84.0) ** 2


def _write_seeds(scene_path, seeds, out, **run):
    import floatmoor
    from floatmoor.analyses.runner import seed_file
    from floatmoor.io.scene import load_scene
    out.mkdir(parents=True, exist_ok=True)
    scene = load_scene(scene_path)
    for s in seeds:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = floatmoor.simulate(scene, seed=s, **run)
        ds.to_netcdf(seed_file(out, scene.name, s))
    return out


def run_report(argv, capsys):
    code = main(["report"] + [str(a) for a in argv])
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err
    return code, cap.out, cap.err


def gumbel_p90(folder):
    """Per line: mean tension and the Gumbel 90 % value of the seed maxima (scipy)."""
    mx, mean = {}, {}
    for f in sorted(Path(folder).glob("*.nc")):
        with xr.open_dataset(f) as ds:
            sel = ds["time"].values >= ds.attrs["transient"] - 1e-9
            for j, ln in enumerate(ds["line"].values):
                T = ds["line_tension"].values[sel, j]
                mx.setdefault(str(ln), []).append(T.max())
                mean.setdefault(str(ln), []).append(T.mean())
    out = {}
    for ln in mx:
        loc, scale = stats.gumbel_r.fit(np.array(mx[ln]))
        out[ln] = (float(np.mean(mean[ln])), float(stats.gumbel_r.ppf(0.9, loc, scale)))
    return out


def verdict_rows(stdout):
    """{(limit state, check): status} from the printed verdict lines."""
    rows = {}
    for line in stdout.splitlines():
        for st in ("NOT CHECKED", "PASS", "FAIL"):
            head = line[:31]
            if line[:3] in ("ULS", "ALS", "FLS") and head[19:].startswith(st):
                rows[(line[:3], line[4:19].strip())] = st
    return rows


@pytest.fixture(scope="module")
def flagship(tmp_path_factory):
    base = tmp_path_factory.mktemp("flagship_verdict")
    seeds = _write_seeds(FLAGSHIP, (1, 2, 3), base / "seeds", duration=1500.0)
    return {"base": base, "seeds": seeds}


def test_flagship_default_is_quasi_static_at_end_of_life(flagship, tmp_path, capsys):
    """Quasi-static lines: the quasi-static factors, said so; S_C is the corroded chain's."""
    code, out, _ = run_report([flagship["seeds"], "--out", tmp_path / "r"], capsys)
    assert "analysis: quasi-static -- 12 quasi-static line(s)" in out
    exp = gumbel_p90(flagship["seeds"])
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        c = nc.sel(limit_state="ULS")
        for j, ln in enumerate(c["line"].values):
            mean, p90 = exp[str(ln)]
            design = 2.5 * p90                      # table 3.1, class 2, quasi-static
            s_c_eol = 0.95 * 8.5e6 * EOL            # 6610.1 kN: 84 -> 76 mm over 20 years
            assert float(c["design_tension"].values[j]) == pytest.approx(design, rel=1e-5)
            assert float(c["s_c"].values[j]) == pytest.approx(s_c_eol, rel=1e-9)
            assert float(c["s_c_new"].values[j]) == pytest.approx(0.95 * 8.5e6, rel=1e-12)
            assert float(c["utilisation"].values[j]) == pytest.approx(design / s_c_eol, rel=1e-5)
            assert str(c["analysis"].values[j]) == "quasi-static"
        assert nc.attrs["verdict"] in ("PASS", "FAIL")
    rows = verdict_rows(out)
    assert rows[("FLS", "fatigue")] == "NOT CHECKED"
    assert rows[("ULS", "anchor uplift")] == "PASS"         # the flagship's anchors stay down
    assert rows[("ULS", "anchor load")] == "NOT CHECKED"    # no capacity in the mooring file
    assert ("ULS", "fibre ropes") in rows                   # polyester: the rope checks run
    assert "unverified code values used: line_tension.strength_factor" in out
    assert code == (1 if "FAIL" in rows.values() else 0)
    html = (tmp_path / "r" / "report.html").read_text()
    assert "quasi-static lines" in html and "DNV-OS-E301 Position Mooring, October 2008" in html
    assert "line line" not in html


def test_finite_element_lines_get_the_dynamic_factors(flagship, tmp_path, capsys):
    """Results whose lines are marked finite-element (the line_model variable a coupled FE run
    writes) are checked with the dynamic factors 1.4 / 2.1 (table 3.1, class 2)."""
    d = tmp_path / "fe"
    d.mkdir()
    for f in flagship["seeds"].glob("*.nc"):
        with xr.open_dataset(f) as ds:
            ds = ds.load()
        ds["line_model"] = ("line", np.array(["finite-element"] * ds.sizes["line"]))
        ds.to_netcdf(d / f.name)
    code, out, _ = run_report([d, "--out", tmp_path / "r"], capsys)
    assert "analysis: dynamic -- 12 finite-element line(s)" in out
    exp = gumbel_p90(flagship["seeds"])
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        c = nc.sel(limit_state="ULS")
        for j, ln in enumerate(c["line"].values):
            mean, p90 = exp[str(ln)]
            assert float(c["design_tension"].values[j]) == pytest.approx(
                1.4 * mean + 2.1 * (p90 - mean), rel=1e-5)


def test_daf_of_floatmoor_lines_and_override(flagship, tmp_path, capsys):
    """A DAF file of floatmoor lines (its netCDF: daf(line)) gives the lines it covers
    T_C-dyn x DAF and the dynamic factors; --analysis dynamic without DAF is an override."""
    daf_nc = tmp_path / "daf.nc"
    assert main(["lines", str(FLAGSHIP), "--harmonic", "surge:3:15", "--lines", "line7",
                 "--duration", "45", "--out", str(daf_nc)]) == 0
    capsys.readouterr()
    with xr.open_dataset(daf_nc) as ds:
        daf7 = float(ds["daf"].sel(line="line7"))
    assert np.isfinite(daf7) and daf7 > 0
    code, out, _ = run_report([flagship["seeds"], "--daf", daf_nc, "--out", tmp_path / "r"],
                              capsys)
    assert "analysis: dynamic and quasi-static (per line)" in out
    exp = gumbel_p90(flagship["seeds"])
    mean, p90 = exp["line7"]
    applied = max(daf7, 1.0)
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        c = nc.sel(limit_state="ULS", line="line7")
        assert float(c["daf_measured"]) == pytest.approx(daf7)
        assert float(c["daf_applied"]) == pytest.approx(applied)
        assert str(c["analysis"].values) == "dynamic"
        assert float(c["design_tension"]) == pytest.approx(
            1.4 * mean + 2.1 * applied * (p90 - mean), rel=1e-5)
        c6 = nc.sel(limit_state="ULS", line="line6")     # not in the DAF file: quasi-static
        assert str(c6["analysis"].values) == "quasi-static"
        assert float(c6["design_tension"]) == pytest.approx(2.5 * exp["line6"][1], rel=1e-5)
    # the same DAF as a CSV file (columns line, daf); a DAF below 1 is applied as 1
    csv = tmp_path / "daf.csv"
    csv.write_text("line,daf,note\nline7,0.8,a DAF below 1\n")
    code, out, _ = run_report([flagship["seeds"], "--daf", csv, "--out", tmp_path / "r2"],
                              capsys)
    with xr.open_dataset(tmp_path / "r2" / "summary.nc") as nc:
        c = nc.sel(limit_state="ULS", line="line7")
        assert float(c["daf_applied"]) == 1.0
        assert float(c["design_tension"]) == pytest.approx(1.4 * mean + 2.1 * (p90 - mean),
                                                           rel=1e-5)
    # an override is printed as one
    code, out, _ = run_report([flagship["seeds"], "--analysis", "dynamic", "--out",
                               tmp_path / "r3"], capsys)
    assert "(OVERRIDE) -- OVERRIDE: dynamic-analysis factors given" in out
    assert "dynamic factors on quasi-static tensions" in out


@pytest.mark.parametrize("case, words", [
    ("other_scene", "the DAF of scene"), ("unknown_line", "line99"), ("huge", "(0, 10]"),
    ("no_column", "columns line, daf"), ("selfcheck_failed", "self-check passed")])
def test_bad_daf_files_exit_2(flagship, tmp_path, capsys, case, words):
    f = tmp_path / "daf.csv"
    if case == "selfcheck_failed":
        # a DAF of an FE line whose self-check failed (a wrong answer) is refused
        f = tmp_path / "daf.nc"
        xr.Dataset({"daf": ("line", [1.1]),
                    "selfcheck": ("line", ["tension along the line 12500 kN above the bound"])},
                   coords={"line": ["line7"]},
                   attrs={"scene_name": "floatel-like-100yr-head-seas"}).to_netcdf(f)
    elif case == "other_scene":
        f = tmp_path / "daf.nc"
        xr.Dataset({"daf": ("line", [1.1])}, coords={"line": ["line7"]},
                   attrs={"title": "floatmoor decoupled FE line analysis of another-scene"}
                   ).to_netcdf(f)
    elif case == "unknown_line":
        f.write_text("line,daf\nline99,1.1\n")
    elif case == "huge":
        f.write_text("line,daf\nline7,50\n")
    else:
        f.write_text("name,factor\nline7,1.1\n")
    code, out, err = run_report([flagship["seeds"], "--daf", f, "--out", tmp_path / "r"],
                                capsys)
    assert code == 2 and err.startswith("floatmoor: error:") and words in err


def test_api_rp_2sk_and_dnv_st_0119(flagship, tmp_path, capsys):
    """API RP 2SK (2005): factor of safety 2.0 (intact, quasi-static) on S_C = MBS (end of
    life); DNV-ST-0119 has no quasi-static factors: quasi-static lines are refused."""
    code, out, _ = run_report([flagship["seeds"], "--code", "api-rp-2sk-2005", "--out",
                               tmp_path / "r"], capsys)
    assert "API RP 2SK Design and Analysis of Stationkeeping Systems for Floating Structures, " \
           "3rd edition, October 2005 (no consequence classes)" in out
    exp = gumbel_p90(flagship["seeds"])
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        c = nc.sel(limit_state="ULS", line="line7")
        assert float(c["utilisation"]) == pytest.approx(2.0 * exp["line7"][1]
                                                        / (8.5e6 * EOL), rel=1e-5)
    assert "unverified code values used:" in out and "line_tension.ULS" in out
    code, out, err = run_report([flagship["seeds"], "--code", "dnv-st-0119-2021", "--out",
                                 tmp_path / "r2"], capsys)
    assert code == 2 and "gives no quasi-static factors" in err and "--daf" in err
    code, out, err = run_report([flagship["seeds"], "--code", "dnv-os-e301-2021", "--out",
                                 tmp_path / "r3"], capsys)
    assert code == 2 and "dnv-os-e301-2008" in err


def test_fls_failure_fails_the_verdict(flagship, tmp_path, capsys):
    """A fatigue result whose check fails makes the verdict FAIL and the exit status 1
    (two sea states of a scatter, a design life of 200 years: far beyond the fatigue life)."""
    scatter = tmp_path / "scatter.yaml"
    scatter.write_text("name: two-cells\nsource: test\nspectrum: jonswap\ngamma: null\ncells:\n"
                       "  - {hs: 5.0, tp: 11.0, heading_deg: 45.0, probability: 0.5}\n"
                       "  - {hs: 7.0, tp: 13.0, heading_deg: 90.0, probability: 0.5}\n")
    fat = tmp_path / "fatigue.nc"
    assert main(["fatigue", str(FLAGSHIP), "--scatter", str(scatter), "--td-cells", "0",
                 "--design-life", "200", "--out", str(fat), "--quiet"]) == 0
    capsys.readouterr()
    code, out, _ = run_report([flagship["seeds"], "--fatigue", fat, "--out", tmp_path / "r"],
                              capsys)
    assert code == 1
    assert verdict_rows(out)[("FLS", "fatigue")] == "FAIL"
    assert "FLS fatigue" in out.split("verdict:")[1]
    with xr.open_dataset(fat) as ds:
        d_f = ds["d_f"].values
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        g = nc["fls_gamma_f"].values
    # the report's fatigue factor: 5 + 3 (d_F - 0.8)/0.2 above 0.8 (code file), 5 below
    np.testing.assert_allclose(g, np.where(d_f > 0.8, 5 + 3 * (np.minimum(d_f, 1) - 0.8) / 0.2,
                                           5.0))


@pytest.fixture(scope="module")
def short_oc3(tmp_path_factory):
    """The OC3 spar with its three lines 8.2 m shorter (894 m instead of 902.2 m: 10.6 m on the
    seabed at rest instead of 135 m, by the catenary); the storm lifts the anchors."""
    base = tmp_path_factory.mktemp("short_oc3")
    moor = (ROOT / "vessels" / "oc3_hywind" / "mooring.yaml").read_text()
    moor = moor.replace("{type: oc3_line, length: 902.2}", "{type: oc3_line, length: 894.0}")
    (base / "mooring.yaml").write_text(moor)
    text = OC3.read_text().replace("../vessels/oc3_hywind/vessel.yaml",
                                   str(ROOT / "vessels" / "oc3_hywind" / "vessel.yaml"))
    text = text.replace("../vessels/oc3_hywind/mooring.yaml", "mooring.yaml")
    text = text.replace("name: oc3-hywind-hs6-tp10", "name: oc3-short-lines")
    (base / "scene.yaml").write_text(text)
    return _write_seeds(base / "scene.yaml", (1, 2, 3), base / "seeds", duration=500.0,
                        transient=100.0, ramp=50.0, dt=0.2)


def test_a_short_line_lifts_its_anchor(short_oc3, tmp_path, capsys):
    code, out, _ = run_report([short_oc3, "--out", tmp_path / "r"], capsys)
    assert code == 1
    rows = verdict_rows(out)
    assert rows[("ULS", "anchor uplift")] == "FAIL"
    assert "the anchor lifts" in out and "drag assumed" in out
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        up = nc["anchor_uls_uplift_c"].values
        assert np.nanmax(up) > 0.0
        assert np.all(nc["anchor_uls_uplift_limit"].values == 0.0)
        assert not bool(np.all(nc["anchor_uls_uplift_passed"].values))
    # a pile anchor is designed for uplift: no limit, the check passes
    moor = short_oc3.parent / "mooring.yaml"
    moor.write_text(moor.read_text().replace("defaults:\n", "defaults:\n  anchor_type: pile\n"))
    code, out, _ = run_report([short_oc3, "--out", tmp_path / "r2"], capsys)
    assert verdict_rows(out)[("ULS", "anchor uplift")] == "PASS"
    assert "pile, no limit" in out


def test_offset_limits_and_points(short_oc3, tmp_path, capsys):
    """Scene limits (they change no analysis: the seeds are reused): a radial offset limit
    below the characteristic offset fails, a per-direction one above it passes; a point on the
    body is reported with its characteristic excursions, and fails its limit.  By hand: the
    per-seed maxima of hypot(surge, sway) over the window, their Gumbel 90 % value (scipy),
    over the limit; the point's earth position x + Rz(yaw) Ry(pitch) Rx(roll) r."""
    scene = short_oc3.parent / "scene.yaml"
    scene.write_text(scene.read_text() + (
        "limits:\n"
        "  offset:\n"
        "    - {name: riser, max: 1.0}\n"
        "    - {name: watch, directions_deg: [0, 90, 180, 270], max: [50, 60, 50, 60]}\n"
        "  points:\n"
        "    - {name: deck_edge, position: [10.0, 0.0, 20.0], max_horizontal: 0.5}\n"))
    code, out, _ = run_report([short_oc3, "--out", tmp_path / "r"], capsys)
    assert code == 1
    assert verdict_rows(out)[("ULS", "offsets")] == "FAIL"
    assert "FAIL: offset riser, point deck_edge" in out
    off_max, pt_max = [], []
    r = np.array([10.0, 0.0, 20.0])
    for f in sorted(short_oc3.glob("*.nc")):
        with xr.open_dataset(f) as ds:
            sel = ds["time"].values >= ds.attrs["transient"] - 1e-9
            m = ds["motion"].values[sel]
        off_max.append(np.hypot(m[:, 0], m[:, 1]).max())
        h = []
        for x in m:
            cr, sr, cp, sp, cy, sy = (np.cos(x[3]), np.sin(x[3]), np.cos(x[4]), np.sin(x[4]),
                                      np.cos(x[5]), np.sin(x[5]))
            Rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
            Ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
            Rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
            d = x[:3] + Rz @ Ry @ Rx @ r - r
            h.append(np.hypot(d[0], d[1]))
        pt_max.append(max(h))
    p90 = stats.gumbel_r.ppf(0.9, *stats.gumbel_r.fit(np.array(off_max)))
    ph = stats.gumbel_r.ppf(0.9, *stats.gumbel_r.fit(np.array(pt_max)))
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        ratio = nc["offsets_uls_ratio_c"].values
        assert ratio[0] == pytest.approx(p90 / 1.0, rel=2e-4)       # radial 1 m
        assert ratio[1] < 0.1 and bool(nc["offsets_uls_passed"].values[1])
        assert float(nc["points_uls_horizontal_c"].values[0]) == pytest.approx(ph, rel=2e-4)
        assert not bool(nc["points_uls_passed"].values[0])
    html = (tmp_path / "r" / "report.html").read_text()
    assert 'id="offset_limits_uls"' in html and 'id="points_uls"' in html


@pytest.mark.slow  # 3 coupled FE storms of the flagship (and the FE kernels' first compile)
def test_coupled_finite_element_lines_get_the_dynamic_factors(tmp_path, capsys):
    """The flagship with its 12 lines as finite-element lines coupled to the floater: the
    report takes the dynamic-analysis factors (table 3.1, class 2: 1.4 / 2.1) and says why."""
    fe_scene = ROOT / "scenes" / "floatel_100yr_fe.yaml"
    seeds = _write_seeds(fe_scene, (1, 2, 3), tmp_path / "fe", duration=1500.0)
    code, out, _ = run_report([seeds, "--out", tmp_path / "r"], capsys)
    assert "analysis: dynamic -- 12 finite-element line(s): the line dynamics are in the " \
           "tension" in out
    exp = gumbel_p90(seeds)
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        c = nc.sel(limit_state="ULS")
        assert set(map(str, c["analysis"].values)) == {"dynamic"}
        for j, ln in enumerate(c["line"].values):
            mean, p90 = exp[str(ln)]
            assert float(c["design_tension"].values[j]) == pytest.approx(
                1.4 * mean + 2.1 * (p90 - mean), rel=1e-5)
    assert ("ULS", "anchor uplift") in verdict_rows(out)


@pytest.mark.slow  # the full fatigue analysis of the flagship's scatter diagram (about 2 min)
def test_the_fls_failing_example_exits_1(flagship, tmp_path, capsys):
    """The example that used to print "all lines pass" and exit 0: floatmoor fatigue on the
    flagship's scatter, then the report with --fatigue (and --fd): FLS FAIL, exit 1."""
    fat = tmp_path / "fatigue.nc"
    assert main(["fatigue", str(FLAGSHIP), "--scatter",
                 str(ROOT / "metocean" / "floatel_like_scatter.yaml"), "--out", str(fat),
                 "--quiet"]) == 0
    fd = tmp_path / "fd.nc"
    assert main(["fd", str(FLAGSHIP), "--out", str(fd)]) == 0
    capsys.readouterr()
    code, out, _ = run_report([flagship["seeds"], "--consequence-class", "2", "--fd", fd,
                               "--fatigue", fat, "--out", tmp_path / "r"], capsys)
    assert code == 1
    assert verdict_rows(out)[("FLS", "fatigue")] == "FAIL"
    assert "FLS fatigue" in out.split("verdict:")[1]


def test_without_the_scene_file_the_scene_checks_are_not_checked(flagship, tmp_path, capsys):
    """Results whose scene file is gone: the line tension is checked on the new line's capacity
    (the corrosion zones need the mooring), which cannot make a PASS of a code that asks for the
    end-of-life capacity; the checks that need the scene are NOT CHECKED; the report says why."""
    d = tmp_path / "moved"
    d.mkdir()
    for f in flagship["seeds"].glob("*.nc"):
        with xr.open_dataset(f) as ds:
            ds = ds.load()
        ds.attrs["scene_file"] = str(tmp_path / "gone.yaml")
        ds.to_netcdf(d / f.name)
    code, out, _ = run_report([d, "--out", tmp_path / "r"], capsys)
    rows = verdict_rows(out)
    assert rows[("ULS", "anchor uplift")] == "NOT CHECKED"
    assert rows[("ULS", "offsets")] == "NOT CHECKED"
    assert "gone.yaml' of the results was not found" in out
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        c = nc.sel(limit_state="ULS")
        np.testing.assert_allclose(c["s_c"].values, 0.95 * 8.5e6)
    # the new line's check is made, but the code asks for the corroded capacity: not a PASS
    assert rows[("ULS", "line tension")] in ("NOT CHECKED", "FAIL")
    if rows[("ULS", "line tension")] == "NOT CHECKED":
        assert "the new line passes, but the end-of-life capacity needs the mooring file" in out
