"""`floatmoor statics`: prints equilibrium, per-line tensions and stiffness for both reference
systems; bad input ends in exit status 2 without a traceback."""

from pathlib import Path

import pytest
import xarray as xr

from floatmoor.cli import main

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.filterwarnings("ignore::floatmoor.FloatmoorWarning")
@pytest.mark.parametrize("scene,n_lines", [("scenes/oc3_hywind.yaml", 3), ("scenes/floatel_100yr.yaml", 12)])
def test_statics_prints_both_reference_systems(scene, n_lines, capsys, tmp_path):
    out_nc = tmp_path / "st.nc"
    code = main(["statics", str(ROOT / scene), "--curve", "0,90", "--max-offset", "30",
                 "--out", str(out_nc)])
    out = capsys.readouterr().out
    assert code == 0
    assert "Static equilibrium" in out and "mooring stiffness" in out and "Restoring curves" in out
    assert sum(1 for ln in out.splitlines() if ln.strip().startswith("line")) >= n_lines
    ds = xr.open_dataset(out_nc)
    assert ds.sizes["line"] == n_lines and "curve_restoring_force" in ds
    ds.close()


def test_statics_unknown_failed_line_is_a_scene_error(capsys):
    code = main(["statics", str(ROOT / "scenes/floatel_100yr.yaml"), "--fail", "line99"])
    err = capsys.readouterr().err
    assert code == 2
    assert "line99" in err and "Traceback" not in err


def test_statics_bad_force_argument(capsys):
    code = main(["statics", str(ROOT / "scenes/oc3_hywind.yaml"), "--force", "1,2,3"])
    assert code == 2
    assert "expected 6 comma-separated numbers" in capsys.readouterr().err
