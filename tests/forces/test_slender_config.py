"""Slender-element input (vessel file section, DNV-RP-C205 table) and the kinematics table."""

from pathlib import Path

import numpy as np
import pytest
import yaml

from floatmoor.core.errors import SceneError
from floatmoor.forces.series import grid_for
from floatmoor.forces.slender import build_kinematics_table, slender_geometry
from floatmoor.forces.slender_config import dnv_rounded_rectangle_cd, parse_slender_elements
from floatmoor.metocean.kinematics import airy_kinematics, wavenumber

ROOT = Path(__file__).resolve().parents[2]
VESSEL = ROOT / "vessels" / "floatel_like" / "vessel.yaml"


def test_dnv_table_reproduces_seed_table_6_2():
    # Wang (2016) table 6.2: (L/D, R/D) -> C_DS, nearest tabulated values
    assert dnv_rounded_rectangle_cd(1.0, 0.24) == 1.2      # column, y
    assert dnv_rounded_rectangle_cd(1.0, 0.21) == 1.2      # column, z
    assert dnv_rounded_rectangle_cd(2.0, 0.347) == 0.4     # pontoon, y
    assert dnv_rounded_rectangle_cd(0.5, 0.214) == 1.6     # pontoon, z
    assert dnv_rounded_rectangle_cd(1.0, 0.25, interpolation="linear") == pytest.approx(
        1.2 + (0.25 - 0.167) / (0.333 - 0.167) * (1.0 - 1.2))
    with pytest.raises(SceneError):
        dnv_rounded_rectangle_cd(-1.0, 0.1)


def test_dnv_route_reproduces_table_6_3():
    """C = 0.5 rho C_D D (eq. 6.3) with the table 6.2 coefficients and the widths of the
    Floatel-like hull (columns 12.5 m across x-flow, 14 m across y-flow; pontoons 8.625 m high,
    14 m wide) gives table 6.3: 7687.5, 8610 / 1768.1, 11480 N s^2/m^3."""
    raw = {
        "dnv_rounded_rectangle": {
            "column": {"y": {"d": 12.5, "l": 12.5, "r": 3.0},     # R/D 0.24 -> 1.2
                       "z": {"d": 14.0, "l": 14.0, "r": 2.94}},   # R/D 0.21 -> 1.2
            "pontoon": {"y": {"d": 8.625, "l": 17.25, "r": 2.993},  # L/D 2, R/D 0.347 -> 0.4
                        "z": {"d": 14.0, "l": 7.0, "r": 3.0}}},     # L/D 0.5, R/D 0.214 -> 1.6
        "elements": [{"name": "c", "type": "column", "p1": [0, 0, 14.5], "p2": [0, 0, -4.375]},
                     {"name": "p", "type": "pontoon", "p1": [0, 45, -8.6875],
                      "p2": [0, -45, -8.6875]}]}
    els = parse_slender_elements(raw, rho=1025.0)
    assert els[0].c2 == pytest.approx((0.0, 7687.5, 8610.0))
    assert els[1].c2 == pytest.approx((0.0, 1768.1, 11480.0), rel=1e-4)


def test_floatel_vessel_file_section():
    raw = yaml.safe_load(VESSEL.read_text())["slender_elements"]
    els = parse_slender_elements(raw, file=VESSEL)
    assert [e.name for e in els] == ["column_1", "column_2", "column_3", "column_4",
                                     "pontoon_1", "pontoon_2"]
    assert els[0].c2 == (0.0, 7687.5, 8610.0)
    assert els[5].c2 == (0.0, 1768.1, 11480.0)
    assert els[4].p1 == (-25.25, 45.0, -8.6875)
    # Wang (2016) eq. 6.5: 4 C_col + 2 C_pont ... with the tuned case b of table 6.4
    tuned = parse_slender_elements(raw, file=VESSEL, scale={"column": (0, 0, 0),
                                                            "pontoon": (0, 1738.33, 11480.0)})
    assert tuned[0].c2 == (0.0, 0.0, 0.0) and tuned[4].c2[1] == 1738.33
    geom = slender_geometry(els, station_spacing=10.0)
    assert list(geom.st_count) == [1, 1, 1, 1, 9, 9]


@pytest.mark.parametrize("raw, key", [
    ({"elements": [{"name": "a", "type": "column", "p1": [0, 0, 1], "p2": [0, 0, -1]}]},
     "slender_elements.elements[0].type"),
    ({"quadratic_drag_per_length": {"column": {"c2y": -1.0}},
      "elements": [{"type": "column", "p1": [0, 0, 1], "p2": [0, 0, -1]}]},
     "slender_elements.quadratic_drag_per_length.column.c2y"),
    ({"elements": [{"p1": [0, 0, 1], "p2": [0, 0, 1]}]}, "slender_elements.elements[0].p2"),
    ({"elements": [{"p1": [0, 0], "p2": [0, 0, 1]}]}, "slender_elements.elements[0].p1"),
    ({"elementz": []}, "slender_elements.elementz"),
])
def test_bad_input_names_file_and_key(raw, key):
    with pytest.raises(SceneError) as exc:
        parse_slender_elements(raw, file="vessel.yaml")
    assert key in str(exc.value) and "vessel.yaml" in str(exc.value)


def test_kinematics_table_fft_against_direct_airy():
    """The FFT-built table (components on a frequency grid, H = 4 h) equals the package's
    direct Airy sum (metocean.kinematics, unstretched at the level z') at its nodes."""
    h = 0.05
    grid = grid_for(0.3, 0.01, h, 200.0)
    rng = np.random.default_rng(3)
    idx = np.arange(5, 5 + 60 * 3, 3)
    w = grid.w0 + idx * grid.dw
    a = rng.uniform(0.05, 0.3, w.size)
    ph = rng.uniform(0, 2 * np.pi, w.size)
    beta = rng.uniform(-0.5, 0.5, w.size)
    depth = 80.0
    k = wavenumber(w, depth)
    st = np.array([[10.0, -5.0], [-30.0, 20.0]])
    tab = build_kinematics_table(w, a, ph, k, beta, st, duration=60.0, H=4 * h, depth=depth,
                                 lev0=-20.0, dlev=2.0, grid=grid)
    levels = tab.lev0 + tab.dlev * np.arange(tab.u.shape[2])
    for i in (0, 37, 150):
        t = i * tab.H
        pts = np.array([[st[s, 0], st[s, 1], z] for s in range(2) for z in levels])
        ref = airy_kinematics(w, a, ph, k, beta, t, pts, water_depth=depth, wheeler=False)
        u = tab.u[i].reshape(-1, 3)
        # points above the instantaneous surface are dry in the reference: compare wet ones
        wet = pts[:, 2] <= ref["eta"][0]
        assert np.allclose(u[wet], ref["velocity"][0][wet], rtol=1e-6, atol=1e-7)  # float32
        assert np.allclose(tab.eta[i], ref["eta"][0][::levels.size], atol=1e-10)
