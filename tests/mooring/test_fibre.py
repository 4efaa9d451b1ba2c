"""Fibre rope stiffness model: tables against hand computation, the load history (slow cycle),
the dynamic stiffness formula and the line-type keys."""

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.mooring.fibre import (
    POLYESTER_DEFAULT,
    FibreModel,
    dynamic_ea_nb,
    table_inverse_nb,
    table_slope_nb,
    table_value_nb,
)
from floatmoor.mooring.line_types import default_library

MBS = 8.5e6

SIMPLE = FibreModel(working_strain=(0.0, 0.01, 0.03), working_tension_mbs=(0.0, 0.10, 0.40),
                    original_strain=(0.0, 0.02, 0.05), original_tension_mbs=(0.0, 0.10, 0.40),
                    alpha=10.0, beta=0.5)


def test_working_curve_against_hand_computation():
    """Piecewise-linear table: 2 % strain lies halfway between (1 %, 10 %) and (3 %, 40 %),
    T = 25 % MBS; tangent 15 MBS; secant 0.25/0.02 = 12.5 MBS; beyond the table the last
    slope (4 % strain: 40 + 15 = 55 % MBS)."""
    assert SIMPLE.static_tension(0.02, MBS) == pytest.approx(0.25 * MBS)
    assert SIMPLE.static_tension(0.04, MBS) == pytest.approx(0.55 * MBS)
    assert SIMPLE.static_strain(0.25 * MBS, MBS) == pytest.approx(0.02)
    assert SIMPLE.static_ea(0.25 * MBS, MBS) == pytest.approx(15.0 * MBS)
    assert SIMPLE.static_ea(0.05 * MBS, MBS) == pytest.approx(10.0 * MBS)
    assert SIMPLE.secant_ea(0.25 * MBS, MBS) == pytest.approx(12.5 * MBS)
    t = np.array([0.0, 0.1, 0.3]) * MBS
    np.testing.assert_allclose(SIMPLE.static_tension(SIMPLE.static_strain(t, MBS), MBS), t,
                               atol=1e-6)


def test_table_helpers_directly():
    xs, ys = np.array([0.0, 1.0, 3.0]), np.array([0.0, 2.0, 3.0])
    assert table_value_nb(2.0, xs, ys) == pytest.approx(2.5)
    assert table_value_nb(-1.0, xs, ys) == pytest.approx(-2.0)
    assert table_inverse_nb(2.5, xs, ys) == pytest.approx(2.0)
    assert table_slope_nb(0.5, xs, ys) == pytest.approx(2.0)
    assert table_slope_nb(1.0, xs, ys) == pytest.approx(0.5)


def test_dynamic_ea_formula():
    """EA_dyn = MBS (alpha + beta L_m), L_m in % MBS: 10 + 0.5 * 20 = 20 MBS at 20 % MBS."""
    assert SIMPLE.dynamic_ea(0.2 * MBS, MBS) == pytest.approx(20.0 * MBS)
    assert dynamic_ea_nb(0.2 * MBS, MBS, 10.0, 0.5) == pytest.approx(20.0 * MBS)
    assert SIMPLE.dynamic_ea(0.0, MBS) == pytest.approx(10.0 * MBS)
    # MoorPy polyester: EAd = 11.6 MBS + 40 T_mean -> 11.6 + 40 * 0.25 = 21.6 MBS at 25 % MBS
    assert POLYESTER_DEFAULT.dynamic_ea(0.25 * MBS, MBS) == pytest.approx(21.6 * MBS)


def test_bounds():
    lo, up = SIMPLE.lower(), SIMPLE.upper()
    assert lo.bound == "lower" and up.bound == "upper"
    assert lo.dynamic_ea(0.25 * MBS, MBS) == pytest.approx(SIMPLE.static_ea(0.25 * MBS, MBS))
    assert up.dynamic_ea(0.25 * MBS, MBS) == pytest.approx(SIMPLE.dynamic_ea(0.25 * MBS, MBS))
    assert lo.static_tension(0.02, MBS) == SIMPLE.static_tension(0.02, MBS)
    # the preset: the upper bound is stiffer than the lower at working tensions
    for tm in (0.1, 0.2, 0.3):
        assert (POLYESTER_DEFAULT.upper().dynamic_ea(tm * MBS, MBS)
                > POLYESTER_DEFAULT.lower().dynamic_ea(tm * MBS, MBS))


def test_slow_cycle_reproduces_the_working_curve():
    """Load along the original curve to 40 % MBS (5 % strain), unload and reload: the rope
    follows the working curve shifted by the permanent strain 5 % - 3 % = 2 %, hand computed:
    at 4 % strain T = f_w(2 %) = 25 % MBS; slack below 2 %; reloading past 5 % follows the
    original curve again."""
    up = np.linspace(0.0, 0.05, 11)
    down = np.linspace(0.05, 0.0, 11)[1:]
    again = np.linspace(0.0, 0.06, 13)[1:]
    path = np.concatenate([up, down, again])
    t = SIMPLE.quasi_static_path(path, MBS)
    assert SIMPLE.permanent_strain(0.4 * MBS, MBS) == pytest.approx(0.02)
    np.testing.assert_allclose(t[:11], MBS * np.interp(up, [0, 0.02, 0.05], [0, 0.1, 0.4]))
    i4 = 11 + 1  # 4.5 %, then 4 %
    assert path[i4] == pytest.approx(0.04)
    assert t[i4] == pytest.approx(0.25 * MBS)
    assert np.all(t[11:][(path[11:] <= 0.02) & (np.arange(len(path) - 11) < 10)] == 0.0)
    # unloading and reloading below the largest strain give the same tensions (no hysteresis)
    rel = again <= 0.05
    shifted = MBS * np.interp(again[rel] - 0.02, [0, 0.01, 0.03], [0, 0.1, 0.4], left=0.0)
    np.testing.assert_allclose(t[21:][rel], shifted, atol=1e-6)
    assert t[-1] == pytest.approx(MBS * (0.4 + 0.01 * 0.3 / 0.03))  # original curve beyond 5 %


def test_validation():
    with pytest.raises(ValueError, match="start at"):
        FibreModel(working_strain=(0.01, 0.02), working_tension_mbs=(0.0, 0.1), alpha=1, beta=0)
    with pytest.raises(ValueError, match="increase"):
        FibreModel(working_strain=(0.0, 0.02, 0.01), working_tension_mbs=(0.0, 0.1, 0.2),
                   alpha=1, beta=0)
    with pytest.raises(ValueError, match="alpha"):
        FibreModel(working_strain=(0.0, 0.02), working_tension_mbs=(0.0, 0.1), alpha=0, beta=0)
    with pytest.raises(ValueError, match="bound"):
        FibreModel(working_strain=(0.0, 0.02), working_tension_mbs=(0.0, 0.1), alpha=1, beta=0,
                   bound="middle")


def test_line_type_keys():
    lib = default_library()
    plain, _ = lib.get("polyester", diameter=0.185)
    assert plain.fibre is None
    assert lib.get("polyester_fibre", diameter=0.185)[0].fibre is POLYESTER_DEFAULT  # shipped
    user = Node({
        "poly_preset": {"family": "polyester", "fibre": "polyester_default"},
        "poly_own": {"family": "polyester", "fibre": {
            "working_curve": {"strain": [0, 0.01, 0.03], "tension_mbs": [0, 0.1, 0.4]},
            "dynamic": {"alpha": 10.0, "beta": 0.5}}},
        "poly_mixed": {"family": "polyester", "fibre": {"preset": "polyester_default",
                                                        "dynamic": {"alpha": 15, "beta": 0.2}}},
        "bad_name": {"family": "polyester", "fibre": "nylon_default"},
        "bad_curve": {"family": "polyester", "fibre": {
            "working_curve": {"strain": [0, 0.02, 0.01], "tension_mbs": [0, 0.1, 0.4]},
            "dynamic": {"alpha": 10.0, "beta": 0.5}}},
        "no_dynamic": {"family": "polyester", "fibre": {
            "working_curve": {"strain": [0, 0.01], "tension_mbs": [0, 0.1]}}},
        "typo": {"family": "polyester", "fibre": {"preset": "polyester_default", "alfa": 3}},
        "bedded": {"family": "polyester", "fibre": {"preset": "polyester_default",
                                                    "max_tension_mbs": 0.3}},
        "bad_tmax": {"family": "polyester", "fibre": {"preset": "polyester_default",
                                                      "max_tension_mbs": 1.5}},
    }, "types.yaml")
    lib2 = lib.extended(user)
    assert lib2.get("poly_preset", diameter=0.185)[0].fibre is POLYESTER_DEFAULT
    own = lib2.get("poly_own", diameter=0.185)[0].fibre
    assert own.working_tension_mbs == (0.0, 0.1, 0.4) and own.alpha == 10.0
    mixed = lib2.get("poly_mixed", diameter=0.185)[0].fibre
    assert mixed.alpha == 15.0 and mixed.working_strain == POLYESTER_DEFAULT.working_strain
    with pytest.raises(SceneError, match="polyester_default"):
        lib2.get("bad_name", diameter=0.185)
    with pytest.raises(SceneError, match="increasing"):
        lib2.get("bad_curve", diameter=0.185)
    with pytest.raises(SceneError, match="dynamic"):
        lib2.get("no_dynamic", diameter=0.185)
    with pytest.raises(SceneError, match="alfa"):
        lib2.get("typo", diameter=0.185)
    bedded = lib2.get("bedded", diameter=0.185)[0].fibre
    # polyester_default after 30 % MBS: original curve 4.1 % - working curve 2.125 % = 1.975 %
    assert bedded.length_factor(MBS) == pytest.approx(1.0 + (0.04 + 0.01 / 0.10 * 0.01)
                                                      - (0.02 + 0.02 / 0.08 * 0.005))
    with pytest.raises(SceneError, match="max_tension_mbs"):
        lib2.get("bad_tmax", diameter=0.185)


def test_polynomial_curve_is_sampled_into_the_table():
    """T/MBS = 10 eps + 100 eps^2: at 2 % strain 0.2 + 0.04 = 0.24 (hand computation); the
    41-point table (spacing h = 0.002) interpolates it at 2.1 %, midway between nodes, within
    the linear-interpolation error c2 h^2 / 4 = 1e-4 MBS."""
    lib = default_library().extended(Node({
        "p": {"family": "polyester", "fibre": {
            "working_curve": {"polynomial": [10.0, 100.0], "max_strain": 0.08},
            "dynamic": {"alpha": 12.0, "beta": 0.4}}},
        "bad": {"family": "polyester", "fibre": {
            "working_curve": {"polynomial": [10.0, -200.0], "max_strain": 0.08},
            "dynamic": {"alpha": 12.0, "beta": 0.4}}}}, "types.yaml"))
    f = lib.get("p", diameter=0.185)[0].fibre
    assert f.static_tension(0.02, MBS) == pytest.approx(0.24 * MBS, rel=1e-12)
    assert f.static_tension(0.021, MBS) / MBS == pytest.approx(0.21 + 100 * 0.021 ** 2, abs=1.01e-4)
    with pytest.raises(SceneError, match="increasing"):
        lib.get("bad", diameter=0.185)


def test_quasi_static_and_fe_lookups_agree_at_the_nodes():
    """One convention for every fibre table lookup: at an interior node the slope is the right
    derivative (the segment above the node), the value the node's own.  The FE law
    (fibre_law._pl, on the record packed in the FE ``S`` array) used to take the left segment
    and the quasi-static table_slope_nb the right one.  Expected slopes by hand from the
    polyester preset's table: (y[i+1] - y[i]) / (x[i+1] - x[i]); left of a node the segment
    below."""
    from floatmoor.mooring.fe.fibre_law import _pl, fibre_record
    xs, ys = POLYESTER_DEFAULT.working_arrays()
    rec = fibre_record(POLYESTER_DEFAULT, 1.0, 300.0)     # MBS 1: the tensions are ys
    n = xs.size
    for i in range(n):
        right = (ys[min(i, n - 2) + 1] - ys[min(i, n - 2)]) / (xs[min(i, n - 2) + 1] - xs[min(i, n - 2)])
        y_fe, d_fe = _pl(rec, 4, 4 + n, n, xs[i])
        assert d_fe == right and table_slope_nb(xs[i], xs, ys) == right
        assert y_fe == pytest.approx(ys[i], rel=1e-15, abs=1e-15)
        if 0 < i < n - 1:
            left = (ys[i] - ys[i - 1]) / (xs[i] - xs[i - 1])
            x = xs[i] - 1e-9
            assert _pl(rec, 4, 4 + n, n, x)[1] == left == table_slope_nb(x, xs, ys)
            assert left != right                          # the test sees the convention
