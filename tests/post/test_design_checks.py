"""Anchor, offset and fibre-rope checks from per-seed statistics, by hand.

The per-seed statistics are written here (3 seeds, 2 lines), the characteristic values
recomputed with scipy's Gumbel fit (90 % fractile of the seed maxima), and the factors taken from
the code files with their source beside them.
"""

import numpy as np
import pytest
import xarray as xr
from scipy import stats

from floatmoor.io.mooring_design import AnchorSpec, MooringDesign
from floatmoor.post.design_checks import anchor_checks, characteristic, characteristic_min
from floatmoor.post.design_codes import load_code

MAXIMA = np.array([3.0e6, 3.2e6, 3.5e6])


def _stats(uplift_b=(0.0, 0.0, 2.0)):
    seeds = [1, 2, 3]
    lines = ["a", "b"]
    z = np.zeros((3, 2))
    data = {
        "anchor_tension_max": (("seed", "line"), np.stack([MAXIMA, MAXIMA * 0.5], axis=1)),
        "anchor_tension_mean": (("seed", "line"), np.stack([np.full(3, 1.0e6),
                                                           np.full(3, 0.6e6)], axis=1)),
        "anchor_h_max": (("seed", "line"), np.stack([MAXIMA, MAXIMA * 0.5], axis=1)),
        "anchor_v_max": (("seed", "line"), z.copy()),
        "uplift_deg_max": (("seed", "line"), np.stack([np.zeros(3), np.array(uplift_b)], axis=1)),
        "grounded_length_min": (("seed", "line"), z + 50.0),
        "grounded_length_at_max_offset": (("seed", "line"), z + 60.0),
        "rope_tension_min": (("seed", "line"), z * np.nan),
        "rope_seabed_length_max": (("seed", "line"), z * np.nan),
        "offset_max": (("seed",), np.array([10.0, 11.0, 12.5])),
    }
    return xr.Dataset(data, coords={"seed": seeds, "line": lines})


def p90(x):
    return float(stats.gumbel_r.ppf(0.9, *stats.gumbel_r.fit(np.asarray(x, float))))


def test_characteristic_values():
    assert characteristic([0.0, 0.0, 0.0]) == 0.0                      # no uplift in any seed
    assert characteristic([0.0, 0.0, 2.0], at_least_max=True) >= 2.0
    assert characteristic(MAXIMA) == pytest.approx(p90(MAXIMA), rel=1e-6)
    assert np.isnan(characteristic([np.nan, np.nan]))
    # minima: the smaller of the lower fractile (Gumbel of -x) and the smallest seen
    x = np.array([400.0, 380.0, 420.0])
    assert characteristic_min(x) == pytest.approx(min(-p90(-x), 380.0), rel=1e-6)


def test_anchor_load_dnv_os_e301_2008():
    """DNV-OS-E301 (2008): the line's ULS factors (class 2 dynamic 1.4 / 2.1, Wang (2016) table
    3.1) on the anchor tension, the holding capacity over the material factor 1.3 (anchors,
    code file): u = (1.4 T_mean + 2.1 (T_C - T_mean)) x 1.3 / capacity."""
    design = MooringDesign(anchors={"a": AnchorSpec(type="drag", capacity=10.0e6)})
    r = anchor_checks(_stats(), design, load_code("dnv-os-e301-2008"), limit_state="ULS",
                      consequence_class=2, analysis="dynamic")
    tc = p90(MAXIMA)
    d = 1.4 * 1.0e6 + 2.1 * (tc - 1.0e6)
    a = r.sel(line="a")
    assert float(a["t_c"]) == pytest.approx(tc, rel=1e-6)
    assert float(a["design_load"]) == pytest.approx(d, rel=1e-6)
    assert float(a["utilisation"]) == pytest.approx(d * 1.3 / 10.0e6, rel=1e-6)
    assert bool(a["load_checked"]) and bool(a["load_passed"]) == (d * 1.3 <= 10.0e6)
    b = r.sel(line="b")                          # no capacity: not checked; no type: drag
    assert not bool(b["load_checked"]) and str(b["anchor_type"].values) == "drag"
    assert not bool(b["anchor_type_given"])
    # uplift: 2 deg in one seed of line b, a drag anchor allows none (anchors.uplift)
    assert float(b["uplift_c"]) >= 2.0 and float(b["uplift_limit"]) == 0.0
    assert not bool(b["uplift_passed"]) and bool(a["uplift_passed"])


def test_anchor_uplift_allowed_by_the_mooring_file_and_pile_anchors():
    design = MooringDesign(anchors={"b": AnchorSpec(uplift_deg=5.0)})
    r = anchor_checks(_stats(uplift_b=(0.0, 1.0, 2.0)), design, load_code("dnv-os-e301-2008"),
                      limit_state="ALS", consequence_class=1, analysis="quasi-static")
    assert float(r["uplift_limit"].sel(line="b")) == 5.0
    assert bool(r["uplift_passed"].sel(line="b"))
    design = MooringDesign(anchors={"b": AnchorSpec(type="pile")})
    r = anchor_checks(_stats(), design, load_code("dnv-os-e301-2008"), limit_state="ULS",
                      consequence_class=2, analysis="dynamic")
    assert np.isnan(float(r["uplift_limit"].sel(line="b")))     # designed for uplift
    assert bool(r["uplift_passed"].sel(line="b"))


def test_anchor_load_api_rp_2sk_2005():
    """API RP 2SK (2005): the anchor tension unfactored against the holding capacity over the
    factor of safety of the anchor type (anchors.factor_of_safety: drag intact dynamic 1.5,
    suction damaged quasi-static 1.5): u = FoS T_C / capacity."""
    design = MooringDesign(anchors={"a": AnchorSpec(type="drag", capacity=10.0e6),
                                    "b": AnchorSpec(type="suction", capacity=4.0e6)})
    code = load_code("api-rp-2sk-2005")
    r = anchor_checks(_stats(), design, code, limit_state="ULS", consequence_class=2,
                      analysis="dynamic")
    assert float(r["utilisation"].sel(line="a")) == pytest.approx(1.5 * p90(MAXIMA) / 10.0e6,
                                                                  rel=1e-6)
    r = anchor_checks(_stats(), design, code, limit_state="ALS", consequence_class=2,
                      analysis="quasi-static")
    assert float(r["utilisation"].sel(line="b")) == pytest.approx(
        1.5 * p90(MAXIMA * 0.5) / 4.0e6, rel=1e-6)


def test_per_line_analysis_of_anchors():
    """One analysis per line (FE and quasi-static lines): each anchor takes its line's factors
    (class 2: dynamic 1.4 / 2.1, quasi-static 2.5 / 2.5)."""
    design = MooringDesign(anchors={"a": AnchorSpec(capacity=10.0e6),
                                    "b": AnchorSpec(capacity=10.0e6)})
    r = anchor_checks(_stats(), design, load_code("dnv-os-e301-2008"), limit_state="ULS",
                      consequence_class=2, analysis=["dynamic", "quasi-static"])
    assert (float(r["gamma_mean"].sel(line="a")), float(r["gamma_dyn"].sel(line="a"))) == (1.4,
                                                                                           2.1)
    assert float(r["gamma_mean"].sel(line="b")) == 2.5
    assert float(r["design_load"].sel(line="b")) == pytest.approx(2.5 * p90(MAXIMA * 0.5),
                                                                  rel=1e-6)
