"""Per-seed design statistics (anchors, ropes, points) against an evaluation at every sample.

The design statistics evaluate the quasi-static catenary of each line only at candidate samples
(the tautest and slackest states, refined to the local extremum); here every sample of a short
storm of the Floatel-like flagship (12 chain-polyester-chain lines) is evaluated and the extremes
compared.  The rope tension at the lower end of the polyester (the joint 1200 m from the anchor)
is checked against the catenary's own tension profile there, and the submerged weights against
the line types of the mooring file (mass - rho V over 7850 / 1380 kg/m^3).
"""

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import floatmoor
from floatmoor.core.errors import SceneError
from floatmoor.core.frames import rotation_matrix
from floatmoor.io.build import build
from floatmoor.io.scene import load_scene
from floatmoor.post.design_statistics import points_earth, seed_design_statistics

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"
G, RHO = 9.80665, 1025.0
W_CHAIN = (140.41 - RHO * 140.41 / 7850.0) * G        # N/m, floatel_chain_84
W_POLY = (22.59 - RHO * 22.59 / 1380.0) * G            # N/m, floatel_polyester_185
W_ABOVE_ROPE_BOTTOM = 1200.0 * W_POLY + 250.0 * W_CHAIN


def test_points_earth_is_the_frames_rotation():
    rng = np.random.default_rng(3)
    motion = rng.normal(size=(5, 6)) * [5, 5, 2, 0.1, 0.1, 0.5]
    pts = rng.normal(size=(3, 3)) * 30
    got = points_earth(motion, pts)
    for t in range(5):
        R = rotation_matrix(*motion[t, 3:])
        np.testing.assert_allclose(got[t], motion[t, :3] + pts @ R.T, rtol=0, atol=1e-12)


@pytest.fixture(scope="module")
def storm():
    scene = load_scene(SCENE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = floatmoor.simulate(scene, seed=3, duration=500.0, transient=200.0, ramp=100.0)
    return scene, build(scene).mooring, ds


def test_candidates_find_the_extremes_of_every_sample(storm):
    scene, mooring, ds = storm
    st = seed_design_statistics(ds, mooring, start=200.0)
    sel = ds["time"].values >= 200.0 - 1e-9
    motion = ds["motion"].values[sel]
    n = mooring.n_lines
    H, V, LB, HF, VF = (np.empty((motion.shape[0], n)) for _ in range(5))
    for k, pose in enumerate(motion):
        r = mooring.tensions(pose)
        H[k], V[k] = r["horizontal_anchor"].values, r["vertical_anchor"].values
        LB[k] = r["grounded_length"].values
        HF[k], VF[k] = r["horizontal_fairlead"].values, r["vertical_fairlead"].values
    # the candidates are a small part of the samples
    assert st["n_evaluated"] < motion.shape[0] / 10
    np.testing.assert_allclose(st["anchor_h_max"], H.max(axis=0), rtol=1e-12)
    np.testing.assert_allclose(st["anchor_v_max"], V.max(axis=0), rtol=0, atol=1e-6)
    up = np.degrees(np.arctan2(np.maximum(V, 0.0), H)).max(axis=0)
    np.testing.assert_allclose(st["uplift_deg_max"], up, rtol=0, atol=1e-9)
    np.testing.assert_allclose(st["grounded_length_min"], LB.min(axis=0), rtol=1e-12)
    i_off = int(np.argmax(np.hypot(motion[:, 0], motion[:, 1])))
    np.testing.assert_allclose(st["grounded_length_at_max_offset"], LB[i_off], rtol=1e-12)
    # rope: the tension at the lower end of the polyester, from the weights of the line types
    rope_t = np.hypot(HF, np.maximum(VF - W_ABOVE_ROPE_BOTTOM, 0.0)).min(axis=0)
    np.testing.assert_allclose(st["rope_tension_min"], rope_t, rtol=1e-9)
    np.testing.assert_allclose(st["rope_seabed_length_max"],
                               np.maximum(LB - 1200.0, 0.0).max(axis=0), rtol=1e-9, atol=1e-9)
    # the mooring reproduces the recorded fairlead tensions
    assert np.nanmax(st["recompute_difference"]) < 1e-9
    # the anchor tension statistics are the recorded series'
    A = ds["anchor_tension"].values[sel]
    np.testing.assert_allclose(st["anchor_tension_max"], A.max(axis=0))
    np.testing.assert_allclose(st["anchor_tension_mean"], A.mean(axis=0))


def test_rope_tension_formula_is_the_catenary_profile(storm):
    """hypot(H, V_f - W_above) at the joint equals the catenary's tension profile there for a
    suspended joint (line 7, the tautest, at the largest offset of the storm)."""
    _, mooring, ds = storm
    i = int(np.argmax(np.hypot(ds["motion"].values[:, 0], ds["motion"].values[:, 1])))
    pose = ds["motion"].values[i]
    r = mooring.tensions(pose)
    j = mooring.names.index("line7")
    hf, vf = float(r["horizontal_fairlead"].values[j]), float(r["vertical_fairlead"].values[j])
    assert vf - W_ABOVE_ROPE_BOTTOM > 0                       # the joint is off the seabed
    prof = mooring.line_profile("line7", pose, n_per_segment=201)
    k = int(np.argmin(np.abs(prof["s"] - 1200.0)))
    assert prof["s"][k] == pytest.approx(1200.0, abs=1e-6)
    assert prof["tension"][k] == pytest.approx(math.hypot(hf, vf - W_ABOVE_ROPE_BOTTOM),
                                               rel=1e-6)


def test_a_changed_mooring_is_refused(storm, tmp_path):
    """Lines 5 m shorter than in the run: the recomputed fairlead tension is off, SceneError."""
    scene, _, ds = storm
    text = (ROOT / "vessels" / "floatel_like" / "mooring.yaml").read_text()
    text = text.replace("{type: floatel_chain_84, length: 1200.0}",
                        "{type: floatel_chain_84, length: 1195.0}")
    (tmp_path / "mooring.yaml").write_text(text)
    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring
    m = parse_mooring(Node.load(tmp_path / "mooring.yaml"), water_depth=150.0)
    with pytest.raises(SceneError, match="changed since the run"):
        seed_design_statistics(ds, m, start=200.0)
