"""``floatmoor lines``: decoupled FE line analysis driven by a short OC3-Hywind run (Wang (2016)
chapter 8 workflow) or a harmonic; exit status 2 for bad input, 3 for a numerical failure."""

import warnings
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

from floatmoor.cli import main

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "oc3_hywind.yaml"


@pytest.fixture(scope="module")
def run_file(tmp_path_factory):
    """60 s of OC3-Hywind in Hs 6 m / Tp 10 s head seas (floatmoor.simulate, seed 1), written
    like a `floatmoor run` seed file."""
    from floatmoor.analyses.simulate import simulate

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = simulate(SCENE, seed=1, duration=60.0, transient=20.0, ramp=10.0, dt=0.1)
    path = tmp_path_factory.mktemp("run") / "seed0001.nc"
    ds.to_netcdf(path)
    return path


def test_lines_from_a_run_table_file_and_checks(run_file, tmp_path, capsys):
    out = tmp_path / "lines.nc"
    assert main(["lines", str(SCENE), "--motion", str(run_file), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "DAF" in text and "line1" in text and f"written: {out}" in text
    res = xr.load_dataset(out)
    for v in res.data_vars.values():
        assert "units" in v.attrs and "long_name" in v.attrs
    assert list(res.line.values) == ["line1", "line2", "line3"]
    sel = res.time.values >= 20.0                      # the run's transient is the default
    # independent check of the fairlead track (body rotation, reference pose): the catenary
    # along it reproduces the coupled run's own quasi-static line tension
    qs, ref = res.qs_tension.values[:, sel], res.run_tension.values[:, sel]
    assert np.max(np.abs(qs - ref)) < 1e-4 * ref.max()
    # Wang (2016) eq. 8.1 recomputed from the written series
    fe = res.fe_tension.values[:, sel]
    daf = (fe.max(1) - fe.mean(1)) / (qs.max(1) - qs.mean(1))
    assert np.allclose(res.daf.values, daf, rtol=1e-12)
    assert np.allclose(res.fe_std.values, fe.std(1), rtol=1e-12)
    # physics: same mean tension within 1.5% (the dynamics hardly shift the mean), larger
    # wave-frequency range from drag and inertia (Wang (2016) ch. 8 found DAF > 1 as well)
    assert np.allclose(res.fe_mean.values, res.qs_mean.values, rtol=0.015)
    assert np.all(res.daf.values > 1.0)
    # head seas: lines 2 and 3 (at +-120 deg) are mirror images
    assert res.fe_tension.values[1] == pytest.approx(res.fe_tension.values[2], rel=1e-6)
    # along-line maximum at least the top element tension; grounded length inside the line
    assert np.all(res.max_tension_along_line.values > 0.95 * res.fe_max.values)
    assert np.all((res.grounded_length_min.values > 0.0)
                  & (res.grounded_length_max.values < 902.2))


def test_lines_selection_and_same_numbers_as_the_library(run_file, tmp_path, capsys):
    """--lines picks lines; the FE series equal the library's decoupled_analysis (the same
    line model and default options) for that line."""
    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe import decoupled_analysis

    out = tmp_path / "l2.nc"
    assert main(["lines", str(SCENE), "--motion", str(run_file), "--lines", "line2",
                 "--duration", "40", "--discard", "10", "--out", str(out)]) == 0
    res = xr.load_dataset(out)
    assert list(res.line.values) == ["line2"] and res.time.values[-1] == pytest.approx(40.0)
    run = xr.load_dataset(run_file)
    keep = run.time.values <= 40.0 + 1e-9
    ms = parse_mooring(Node.load(ROOT / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    lib = decoupled_analysis(ms, run.time.values[keep], run.motion.values[keep],
                             lines=["line2"], discard=10.0)
    assert np.allclose(res.fe_tension.values[0], lib.fe_tension.values[0], rtol=1e-9)
    assert res.daf.values[0] == pytest.approx(float(lib.daf.values[0]), rel=1e-9)


def test_lines_harmonic_surge_quasi_static_peak(tmp_path, capsys):
    """--harmonic surge:3:16: the quasi-static maximum of line1 (anchor on +x) is at surge -3 m
    (t = 12 + 16 k s on the 0.1 s grid) and equals the MooringSystem catenary at that pose."""
    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring

    out = tmp_path / "h.nc"
    assert main(["lines", str(SCENE), "--harmonic", "surge:3:16", "--lines", "line1",
                 "--duration", "48", "--out", str(out)]) == 0
    assert "harmonic surge 3 (m) at 16 s" in capsys.readouterr().out
    res = xr.load_dataset(out)
    ms = parse_mooring(Node.load(ROOT / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    t_ref = float(ms.tensions(np.array([-3.0, 0, 0, 0, 0, 0]))["fairlead_tension"][0])
    assert float(res.qs_max.values[0]) == pytest.approx(t_ref, rel=1e-6)
    assert res.attrs["discard_s"] == 32.0           # default: ramp + one period


def _write(p, text):
    p.write_text(text)
    return p


@pytest.mark.parametrize("argv,message", [
    (["--motion", "{tmp}/missing.nc"], "no such file"),
    (["--motion", "{tmp}/nomotion.nc"], "motion(time, dof)"),
    (["--harmonic", "surge:3"], "DOF:AMPLITUDE:PERIOD"),
    (["--harmonic", "twist:3:10"], "unknown DOF"),
    (["--harmonic", "surge:3:10", "--lines", "line9"], "unknown line(s) line9"),
    (["--harmonic", "surge:3:10", "--duration", "20", "--discard", "30"], "not shorter"),
])
def test_bad_input_exit_2(argv, message, tmp_path, capsys):
    xr.Dataset({"x": ("t", np.zeros(3))}).to_netcdf(tmp_path / "nomotion.nc")
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    assert main(["lines", str(SCENE), *argv, "--out", str(tmp_path / "o.nc")]) == 2
    assert message in capsys.readouterr().err


def test_bad_finite_element_option_exit_2(tmp_path, capsys):
    m = yaml.safe_load((ROOT / "vessels" / "oc3_hywind" / "mooring.yaml").read_text())
    m["finite_element"] = {"integrator": "rk45"}
    p = _write(tmp_path / "s.yaml", yaml.safe_dump({"name": "x", "site": {"water_depth": 320.0},
                                                    "mooring": m}))
    assert main(["lines", str(p), "--harmonic", "surge:3:15"]) == 2
    assert "mooring.finite_element.integrator" in capsys.readouterr().err


def test_numerical_failure_exit_3_names_time_line_node_remedy(tmp_path, capsys):
    """The explicit integrator at the 0.1 s body step is far beyond the axial-wave limit of the
    stiff OC3 line (about 3 ms for 20 m elements): it must fail loudly, not write numbers."""
    m = yaml.safe_load((ROOT / "vessels" / "oc3_hywind" / "mooring.yaml").read_text())
    m["finite_element"] = {"integrator": "explicit"}
    p = _write(tmp_path / "s.yaml", yaml.safe_dump({"name": "x", "site": {"water_depth": 320.0},
                                                    "mooring": m}))
    out = tmp_path / "o.nc"
    assert main(["lines", str(p), "--harmonic", "surge:3:15", "--duration", "20",
                 "--discard", "5", "--out", str(out)]) == 3
    err = capsys.readouterr().err
    assert "numerical error" in err and "t = " in err and "line line1" in err
    assert "node" in err and "remedy" in err and "dt" in err
    assert not out.exists()


def test_scene_finite_element_options_reach_the_lines(tmp_path, capsys):
    """``mooring.finite_element`` of the scene sets the FE model of ``floatmoor lines``:
    element count, line step (dt 0.05 s -> 2 steps per 0.1 s sample) and friction."""
    m = yaml.safe_load((ROOT / "vessels" / "oc3_hywind" / "mooring.yaml").read_text())
    m["finite_element"] = {"n_elements": 30, "dt": 0.05,
                           "friction": {"model": "velocity_ramp", "mu_axial": 0.7,
                                        "mu_lateral": 1.0}}
    p = _write(tmp_path / "s.yaml", yaml.safe_dump({"name": "x", "site": {"water_depth": 320.0},
                                                    "mooring": m}))
    out = tmp_path / "o.nc"
    assert main(["lines", str(p), "--harmonic", "sway:3:15", "--lines", "line1",
                 "--duration", "20", "--discard", "5", "--out", str(out)]) == 0
    res = xr.load_dataset(out)
    assert int(res.n_elements.values[0]) == 30 and res.attrs["substeps"] == 2
    assert "velocity_ramp" in res.attrs["friction"]


# -- the decoupled lines are the coupled run's FE lines: current and line types of the scene --
FE_SCENE = ROOT / "scenes" / "floatel_100yr_fe.yaml"


def _fe_current_scene(tmp_path, current=True):
    """The Floatel-like FE scene (scenes/floatel_100yr_fe.yaml), 8 elements per line, a
    moderate sea and a sheared current at 30 deg (or none)."""
    d = yaml.safe_load(FE_SCENE.read_text())
    d["name"] = "fe-current"
    d["vessel"] = str(ROOT / "vessels" / "floatel_like" / "vessel.yaml")
    env = {"name": "sea-current",
           "waves": {"spectrum": "jonswap", "hs": 5.0, "tp": 11.0, "heading_deg": 0.0}}
    if current:
        env["current"] = {"profile": "piecewise_linear", "levels": [[0.0, 1.2], [-150.0, 0.4]],
                          "heading_deg": 30.0}
    d["environment"] = env
    d["mooring"] = yaml.safe_load((ROOT / "vessels" / "floatel_like" / "mooring_fe.yaml")
                                  .read_text())
    d["mooring"]["finite_element"] = {"n_elements": 8}
    d["analysis"] = {"duration": 60.0, "dt": 0.2, "transient": 10.0, "ramp": 10.0, "seeds": 1}
    p = tmp_path / "fe_current.yaml"
    p.write_text(yaml.safe_dump(d))
    return p


def test_lines_reproduce_the_coupled_fe_tension_with_current(tmp_path, capsys):
    """A coupled run with FE lines (floatmoor.simulate) in a sheared current; ``floatmoor lines``
    driven by that run's motion, with the same elements and step, reproduces the coupled FE
    fairlead tension: the decoupled lines see the scene's current and line-type coefficients
    (cdn 2.6 / 1.8 etc. of mooring_fe.yaml).  Reference: the coupled run itself (its FE lines
    see the same fairlead motion; the decoupled track is linear between samples, the coupled
    lines move with the body velocity at the step end: a difference of order dt^2).  The same
    decoupled run without current and with default coefficients (what ``floatmoor lines`` did
    before) is far off.  Direction of the current alone (same line types, same motion, mean
    tension): the current (towards 30 deg) runs along line1 towards its anchor (tangential drag
    pulls the fairlead: higher tension), along line7 towards its fairlead (lower tension) and
    across line6 (lateral drag bows the suspended line: higher tension)."""
    from floatmoor.analyses.simulate import simulate
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.io.scene import load_scene
    from floatmoor.mooring.fe import run_decoupled
    from floatmoor.mooring.fe.body import scene_line_inputs

    p = _fe_current_scene(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = simulate(p, seed=1)
    run = tmp_path / "seed0001.nc"
    ds.to_netcdf(run)
    out = tmp_path / "l.nc"
    names = ["line1", "line6", "line7"]
    assert main(["lines", str(p), "--motion", str(run), "--lines", ",".join(names),
                 "--discard", "0", "--out", str(out)]) == 0
    assert "current on the lines: max 1.2 m/s, heading 30.0 deg" in capsys.readouterr().out
    res = xr.load_dataset(out)
    Tc = ds.line_tension.sel(line=names).values.T          # coupled FE tension (line, time)
    Td = res.fe_tension.values
    err = np.abs(Td - Tc).max(axis=1) / Tc.mean(axis=1)
    # without the scene's current and line types (the decoupled model before)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")   # short run: the statistics-window warnings
        sc = load_scene(p)
    node = sc.mooring_node()
    system = parse_mooring(node, water_depth=sc.site.water_depth,
                           water_density=sc.site.water_density, gravity=sc.site.gravity)
    bare = run_decoupled(system, ds.time.values, ds.motion.values,
                         options=system.line_models.options, lines=names, discard=0.0)
    err_bare = np.abs(bare.fe_tension.values - Tc).max(axis=1) / Tc.mean(axis=1)
    pytest.lines_current = (err, err_bare)
    assert np.all(err < 2e-3), err
    assert np.all(err_bare > 10.0 * err), (err, err_bare)
    # the current alone: the same decoupled lines (scene line types) without current
    types = scene_line_inputs(sc, system)["line_types"]
    assert types["floatel_chain_84"].cdn == 2.6      # mooring_fe.yaml, not the default
    calm = run_decoupled(system, ds.time.values, ds.motion.values,
                         options=system.line_models.options, lines=names, discard=0.0,
                         line_types=types)
    dm = res.fe_mean.values - calm.fe_mean.values
    pytest.lines_current_mean = dm
    assert dm[0] > 0.0 and dm[1] > 0.0 and dm[2] < 0.0, dm
