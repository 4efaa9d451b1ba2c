"""``analysis.fibre_stiffness``: ``floatmoor run`` of both bounds into two sub-folders and
``floatmoor report`` taking the governing one with both shown; bad values are SceneErrors."""

import warnings

import numpy as np
import pytest
import xarray as xr

from floatmoor.cli import main
from floatmoor.core.errors import SceneError
from floatmoor.io.scene import load_scene
from tests.solvers.test_fibre_dynamics import FL, fibre_mooring

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")


def _scene(tmp_path, fibre_stiffness="both"):
    p = tmp_path / "scene.yaml"
    p.write_text(f"name: fibre-bounds\nsite: {{water_depth: 150.0}}\n"
                 f"vessel: {FL / 'vessel.yaml'}\nmooring: {fibre_mooring(tmp_path)}\n"
                 "environment:\n  waves: {spectrum: jonswap, hs: 10.0, tp: 13.0}\n"
                 "analysis: {duration: 300.0, dt: 0.2, transient: 100.0, ramp: 50.0, "
                 f"seeds: [1, 3], fibre_stiffness: {fibre_stiffness}}}\n")
    return p


def test_bad_value_is_a_scene_error(tmp_path):
    with pytest.raises(SceneError, match="fibre_stiffness"):
        load_scene(_scene(tmp_path, "middle"))
    assert load_scene(_scene(tmp_path, "lower")).analysis.fibre_bounds == ("lower",)


def test_run_both_bounds_and_report_the_governing(tmp_path, capsys):
    scene = _scene(tmp_path)
    out = tmp_path / "res"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["run", str(scene), "--out", str(out), "--workers", "1"]) == 0
    std = {}
    for b in ("lower", "upper"):
        files = sorted((out / f"fibre_{b}").glob("*.nc"))
        assert len(files) == 3
        with xr.open_dataset(files[0]) as ds:
            assert ds.attrs["fibre_stiffness"] == b
            t = ds["time"].values
            std[b] = ds["line_tension"].values[t > 100.0].std(axis=0)
    # the stiffer upper bound gives larger dynamic tensions on the most loaded lines
    i = int(np.argmax(std["upper"]))
    assert std["upper"][i] > std["lower"][i]
    capsys.readouterr()
    rep = tmp_path / "rep"
    status = main(["report", str(out), "--out", str(rep)])
    assert status in (0, 1)
    text = capsys.readouterr().out
    util = {}
    for b in ("lower", "upper"):
        with xr.open_dataset(rep / f"fibre_{b}" / "summary.nc") as nc:
            util[b] = float(nc["utilisation"].sel(limit_state="ULS").max())
        assert (rep / f"fibre_{b}" / "report.html").is_file()
    gov = max(util, key=util.get)
    md = (rep / "fibre_bounds.md").read_text()
    assert f"| {gov} (governing) | {util[gov]:.3f}" in md
    other = "lower" if gov == "upper" else "upper"
    assert f"| {other} | {util[other]:.3f}" in md
    assert f"governing: {gov}" in text
    csv = (rep / "fibre_bounds.csv").read_text().splitlines()
    assert csv[0] == "line,utilisation_lower,utilisation_upper,governing_bound"
    assert len(csv) == 1 + 12


def test_fd_command_runs_both_bounds(tmp_path, capsys):
    """``floatmoor fd`` of a scene with ``fibre_stiffness: both``: both tables, two files, the
    governing bound = the smaller safety factor of the two files; the same mean position."""
    scene = _scene(tmp_path)
    out = tmp_path / "fd.nc"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["fd", str(scene), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    sf, mean = {}, {}
    for b in ("lower", "upper"):
        assert f"fibre stiffness bound: {b}" in text
        with xr.open_dataset(tmp_path / f"fd_{b}.nc") as ds:
            assert ds.attrs["fibre_stiffness"] == b
            sf[b] = float(np.nanmin(ds["safety_factor"].values))
            mean[b] = ds["mean"].values.copy()
    np.testing.assert_allclose(mean["lower"], mean["upper"], rtol=1e-9, atol=1e-9)
    assert sf["lower"] != sf["upper"]
    assert f"governing: {min(sf, key=sf.get)}" in text


def test_campaign_runs_every_condition_at_both_bounds(tmp_path):
    """A campaign on a base scene with ``fibre_stiffness: both``: every condition twice (lower,
    upper); the case's scene and built mooring carry its bound, and the FD of the two cases
    differ in the tensions but share the mean position (same working curve)."""
    from floatmoor.campaign.matrix import build_matrix
    from floatmoor.campaign.spec import load_campaign
    from floatmoor.campaign.tasks import _built_for
    scene = _scene(tmp_path)
    c = tmp_path / "c.yaml"
    c.write_text(f"name: c\nbase_scene: {scene}\nsea_states: {{list: [{{hs: 10.0, tp: 13.0}}]}}\n"
                 "headings: {waves_deg: [0]}\nconditions: {intact: true, failed_lines: [line7]}\n"
                 "seeds: \"1-3\"\n")
    spec = load_campaign(c)
    assert [k.name for k in spec.conditions] == [
        "intact_fibre-lower", "intact_fibre-upper", "failed-line7_fibre-lower",
        "failed-line7_fibre-upper"]
    cases = build_matrix(spec)
    assert len(cases) == 4 and len({k.id for k in cases}) == 4
    fd = {}
    for case in cases[:2]:
        built, _ = _built_for(str(scene), case, {})
        b = case.condition.fibre_bound
        assert built.scene.analysis.fibre_stiffness == b
        assert {m.bound for m in built.mooring.fibre_segments.models} == {b}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            import floatmoor
            fd[b] = floatmoor.frequency_domain(built)
    np.testing.assert_allclose(fd["lower"]["mean"].values, fd["upper"]["mean"].values,
                               rtol=1e-9, atol=1e-9)
    assert not np.allclose(fd["lower"]["tension_std_wf"].values,
                           fd["upper"]["tension_std_wf"].values, rtol=1e-3)


def test_campaign_report_reads_the_bound_tagged_conditions():
    """The campaign report finds the failed lines of a condition name with a bound tag (an
    end-to-end campaign with both bounds ran in the session that added it: report OK)."""
    from floatmoor.campaign.report import _condition_lines
    assert _condition_lines("intact_fibre-upper") == []
    assert _condition_lines("failed-line7_fibre-lower") == ["line7"]
    assert _condition_lines("break-line1+line2-t100_fibre-upper") == ["line1", "line2"]
    assert _condition_lines("failed-line7") == ["line7"]
