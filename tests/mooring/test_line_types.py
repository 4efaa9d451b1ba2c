"""Line types: published chain formulas, submerged weight convention, library handling."""

import math

import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.mooring.line_types import CHAIN_GRADES, chain, default_library, polyester, wire_rope


def test_chain_mbs_against_dnv_formula_values():
    """DNV-OS-E302 breaking load 76 mm: R3 4,884 kN, R4 6,001 kN (c d^2 (44 - 0.08 d));
    grade factors R3 0.0223 ... R5 0.0320."""
    assert chain(0.076, "R3").mbs == pytest.approx(4884e3, rel=1e-3)
    assert chain(0.076, "R4").mbs == pytest.approx(6001e3, rel=1e-3)
    mbs = [chain(0.1, g).mbs for g in ("R3", "R3S", "R4", "R4S", "R5")]
    assert mbs == sorted(mbs)
    assert chain(0.1, "R4", studlink=True).mbs == chain(0.1, "R4").mbs  # same formula
    assert set(CHAIN_GRADES) == {"R3", "R3S", "R4", "R4S", "R5"}


def test_chain_mass_ea_and_submerged_weight():
    c = chain(0.084, "R4")
    assert c.mass_per_length == pytest.approx(0.0199 * 84 ** 2)
    assert c.ea == pytest.approx(0.854e8 * 0.084 ** 2 * 1e3)
    assert chain(0.084, studlink=True).mass_per_length == pytest.approx(0.0219 * 84 ** 2)
    # steel: w = m g (1 - rho_w / rho_steel)
    assert c.submerged_weight(1025.0, 9.80665) == pytest.approx(
        c.mass_per_length * 9.80665 * (1 - 1025.0 / 7850.0))


def test_wire_and_polyester():
    p = polyester(0.185)
    assert p.mbs == pytest.approx(8556e3, rel=1e-3)  # Wang (2016) table 5.2 gives 8,500 kN
    assert p.ea_dynamic > p.ea
    assert 0 < p.submerged_weight() < 0.3 * p.mass_per_length * 9.80665
    w6, ws = wire_rope(0.08), wire_rope(0.08, "spiral_strand")
    assert ws.ea > w6.ea and ws.mbs > w6.mbs
    with pytest.raises(ValueError):
        wire_rope(0.08, "eight_strand")


def test_library_unknown_name_and_user_types(tmp_path):
    lib = default_library()
    assert "chain_studless_R3S" in lib and "wire_spiral_strand" in lib
    with pytest.raises(SceneError, match="chain_studless_R4"):
        lib.get("chain_R4", diameter=0.1)
    user = Node({"t": {"diameter": 0.1, "mass_per_length": 50.0, "volumetric_diameter": 0.1,
                       "elastic_modulus": 1e11, "mbs": 1e6},
                 "bad": {"diameter": 0.1, "mass_per_length": 50.0, "ea": 1e8, "mbs": 1e6}},
                "types.yaml")
    lib2 = lib.extended(user)
    lt, w = lib2.get("t")
    assert w is None
    assert lt.ea == pytest.approx(1e11 * math.pi * 0.01 / 4)
    assert lt.submerged_weight(1025.0, 9.81) == pytest.approx((50 - 1025 * math.pi * 0.01 / 4) * 9.81)
    with pytest.raises(SceneError, match="bad.displaced_volume.*exactly one"):
        lib2.get("bad")
