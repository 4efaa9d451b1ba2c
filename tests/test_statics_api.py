"""Scene-level statics: build(scene) -> equilibrium and restoring curves.

Independent checks:
* OC3-Hywind: the public displaced volume (8029.21 m^3, HydroDyn PtfmVol0) and masses (platform
  7,466,330 kg + tower 249,718 + nacelle 240,000 + rotor 110,000 = 8,066,048 kg) leave a net
  buoyancy that the three lines must carry; MAP++ (.MAP.sum, reference/OC3_Hywind) gives
  V = 535,728 N per line at the zero pose.  So the still-water equilibrium must sit at heave ~ 0
  with the MAP++ fairlead tension 911,089 N (g = 9.81 there; 9.80665 here: 0.03 % apart).
* Floatel-like: head-sea symmetry (sway, roll, yaw zero), and a failed line moves the body
  away from it (ALS).
"""

import numpy as np
import pytest

import floatmoor
from floatmoor import SceneError
from floatmoor.io.build import build

ROOT = __import__("pathlib").Path(__file__).resolve().parents[1]


def oc3_scene(tmp_path):
    p = tmp_path / "oc3.yaml"
    p.write_text(f"""name: oc3
site: {{water_depth: 320.0}}
vessel: {ROOT / 'vessels/oc3_hywind/vessel.yaml'}
mooring: {ROOT / 'vessels/oc3_hywind/mooring.yaml'}
""")
    return p


@pytest.mark.filterwarnings("ignore::floatmoor.FloatmoorWarning")
def test_oc3_net_buoyancy_matches_map_vertical_load(tmp_path):
    b = build(oc3_scene(tmp_path))
    assert b.displaced_volume == pytest.approx(8029.21)
    assert b.static_force[2] == pytest.approx(3 * 535728.0, rel=1e-3)
    res = floatmoor.equilibrium(b)
    assert abs(res.pose[2]) < 0.01                      # m: floats at its design draft
    t = res.tensions["fairlead_tension"].values
    np.testing.assert_allclose(t, 911089.0, rtol=1e-3)  # MAP++ .sum value


@pytest.mark.filterwarnings("ignore::floatmoor.FloatmoorWarning")
def test_floatel_head_sea_symmetry_and_line_failure():
    scene = ROOT / "scenes/floatel_100yr.yaml"
    intact = floatmoor.equilibrium(scene, external_force=[2.0e6, 0, 0, 0, 0, 0])
    assert intact.pose[0] > 0.0
    assert abs(intact.pose[1]) < 1e-6 and abs(intact.pose[3]) < 1e-8 and abs(intact.pose[5]) < 1e-8
    failed = floatmoor.equilibrium(scene, external_force=[2.0e6, 0, 0, 0, 0, 0],
                                   failed_lines=["line7"])
    assert failed.pose[0] > intact.pose[0]              # less restoring: larger offset
    assert abs(failed.pose[1]) > 0.1                    # asymmetric system: it moves sideways
    ds = floatmoor.restoring_curves(scene, headings_deg=[0.0, 180.0], offsets=[0.0, 10.0, 30.0])
    f = ds["restoring_force"].values
    assert np.all(np.diff(f, axis=1) > 0)               # stiffening with offset
    np.testing.assert_allclose(f[0], f[1], rtol=1e-6, atol=1e-3)  # fore-aft symmetric layout


def test_build_refuses_unknown_failed_line():
    with pytest.raises(SceneError, match="line7x"):
        build(ROOT / "scenes/floatel_100yr.yaml", failed_lines=["line7x"])


def test_failed_lines_keep_the_line_model_choice(tmp_path):
    # the FE/quasi-static choice parsed from the mooring file survives line removal (ALS)
    b = build(ROOT / "scenes/floatel_100yr.yaml")
    failed = build(ROOT / "scenes/floatel_100yr.yaml", failed_lines=["line7"])
    assert b.mooring.line_models is not None
    assert failed.mooring.line_models is b.mooring.line_models or \
        failed.mooring.line_models == b.mooring.line_models
    assert failed.mooring.with_dynamic_ea().line_models == failed.mooring.line_models
