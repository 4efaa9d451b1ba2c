"""Design codes as data: one small example per code file, its utilisations worked out by hand.

Each example: a line of MBS 8500 kN with T_C-mean 2000 kN and T_C 5000 kN (T_C-dyn 3000 kN); the
comment beside each assertion gives the factor, the code file entry it comes from and the
arithmetic.  The factors are those of the files in floatmoor/data/codes; whether a factor is
verified against the standard's text is the file's (and checked below: the unverified values are
listed, as every report using them lists them).
"""

import math

import pytest

from floatmoor.core.errors import SceneError
from floatmoor.post import dnv_os_e301 as dnv
from floatmoor.post.design_codes import available_codes, load_code

kN = 1e3
T_MEAN, T_C, MBS = 2000 * kN, 5000 * kN, 8500 * kN


def u(ls, cc, an, code):
    return float(dnv.line_check(T_MEAN, T_C, MBS, limit_state=ls, consequence_class=cc,
                                analysis=an, code=code)["utilisation"])


def test_shipped_codes_and_aliases():
    keys = [k for k, _ in available_codes()]
    assert keys == ["api-rp-2sk-2005", "dnv-os-e301-2008", "dnv-st-0119-2021"]
    assert load_code("dnv-os-e301").key == "dnv-os-e301-2008"       # the old --standard name
    assert load_code("API-RP-2SK").key == "api-rp-2sk-2005"
    assert load_code("dnv-os-e301-2008").name == "DNV-OS-E301 Position Mooring, October 2008"
    with pytest.raises(SceneError, match="dnv-os-e301-2008"):
        load_code("dnv-os-e301-2015")          # not shipped: could not be confirmed


def test_dnv_os_e301_2008_hand_example():
    code = "dnv-os-e301-2008"
    # S_C = 0.95 x 8500 = 8075 kN (line_tension.strength_factor)
    # ULS class 2 dynamic (line_tension.ULS, Wang (2016) table 3.1): 1.4 x 2000 + 2.1 x 3000
    # = 2800 + 6300 = 9100 kN -> 9100 / 8075 = 1.126935
    assert u("ULS", 2, "dynamic", code) == pytest.approx(9100 / 8075)
    # ULS class 2 quasi-static (table 3.1, one value 2.5): 2.5 x 5000 = 12500 -> 1.547988
    assert u("ULS", 2, "quasi-static", code) == pytest.approx(12500 / 8075)
    # ULS class 1 dynamic: the common factor (remark 1 under table 3.1) needs T_C-mean > 2/3
    # T_C-dyn, strictly; 2000 = 2/3 x 3000 -> the table factors 1.1 x 2000 + 1.5 x 3000 = 6700
    # -> 0.829721
    assert u("ULS", 1, "dynamic", code) == pytest.approx(6700 / 8075)
    # ALS class 2 dynamic (line_tension.ALS, table 3.2): 1.0 x 2000 + 1.25 x 3000 = 5750 -> 0.712074
    assert u("ALS", 2, "dynamic", code) == pytest.approx(5750 / 8075)
    # ALS class 1 quasi-static (table 3.2): 1.1 x 5000 = 5500 -> 0.681115
    assert u("ALS", 1, "quasi-static", code) == pytest.approx(5500 / 8075)
    c = load_code(code)
    # fatigue.safety_factor: 5 up to d_F 0.8, then 5 + 3 (d_F - 0.8) / 0.2: 6.5 at 0.9, 8 at 1
    assert c.fatigue_factor(0.7) == 5.0
    assert c.fatigue_factor(0.9) == pytest.approx(6.5)
    assert c.fatigue_factor(1.0) == pytest.approx(8.0)
    # anchors: the line's ULS factors on the anchor tension, material factor 1.3 (ULS) / 1.0
    f = c.anchor_factors("drag", "ULS", 2, "dynamic")
    assert (f["gamma_mean"], f["gamma_dyn"], f["resistance_factor"]) == (1.4, 2.1, 1.3)
    assert c.anchor_factors("pile", "ALS", 1, "quasi-static")["resistance_factor"] == 1.0
    assert c.uplift_limit_deg("drag", "ULS") == 0.0 and c.uplift_limit_deg("pile", "ULS") is None
    # corrosion allowance of chain (corrosion, table B1 with regular inspection), mm/year
    assert c.corrosion_rates("chain") == {"splash": 0.4, "catenary": 0.3, "bottom": 0.4}
    assert c.corrosion_rates("polyester") == {}
    assert c.end_of_life_capacity
    # verified: the ULS/ALS factors (Wang (2016) tables 3.1, 3.2); not the rest
    unverified = {e.path for e in c.unverified()}
    assert {"line_tension.ULS", "line_tension.ALS", "line_tension.common_factor"}.isdisjoint(
        unverified)
    assert {"line_tension.strength_factor", "fatigue.safety_factor", "corrosion",
            "anchors"} <= unverified


def test_api_rp_2sk_2005_hand_example():
    code = "api-rp-2sk-2005"
    # factor of safety format: design tension FoS x T_C on S_C = 1.0 x MBS = 8500 kN
    # (line_tension.strength_factor 1.0); no consequence classes (the class is not used)
    # intact dynamic FoS 1.67 (line_tension.ULS): 1.67 x 5000 = 8350 -> 0.982353
    assert u("ULS", 2, "dynamic", code) == pytest.approx(1.67 * 5000 / 8500)
    assert u("ULS", 1, "dynamic", code) == pytest.approx(1.67 * 5000 / 8500)
    # intact quasi-static FoS 2.00: 10000 / 8500 = 1.176471
    assert u("ULS", 2, "quasi-static", code) == pytest.approx(10000 / 8500)
    # damaged dynamic FoS 1.25 (line_tension.ALS): 6250 / 8500 = 0.735294
    assert u("ALS", 2, "dynamic", code) == pytest.approx(6250 / 8500)
    # damaged quasi-static FoS 1.43: 7150 / 8500 = 0.841176
    assert u("ALS", 2, "quasi-static", code) == pytest.approx(7150 / 8500)
    c = load_code(code)
    assert c.fatigue_factor(0.99) == 3.0                      # fatigue.safety_factor 3 on life
    # anchors: anchor tension unfactored, holding capacity over the factor of safety
    # (anchors.factor_of_safety): drag intact dynamic 1.5, pile damaged 1.5
    f = c.anchor_factors("drag", "ULS", 2, "dynamic")
    assert (f["gamma_mean"], f["gamma_dyn"], f["resistance_factor"]) == (1.0, 1.0, 1.5)
    assert c.anchor_factors("pile", "ALS", 2, "dynamic")["resistance_factor"] == 1.5
    # nothing in this file is verified against the text of API RP 2SK
    assert all(not e.verified for e in c.entries.values())


def test_dnv_st_0119_2021_hand_example():
    code = "dnv-st-0119-2021"
    # S_C = 0.95 x 8500 = 8075 kN; ULS class 2 (line_tension.ULS): 1.5 x 2000 + 2.2 x 3000
    # = 3000 + 6600 = 9600 -> 1.188854; class 1: 1.3 x 2000 + 1.75 x 3000 = 7850 -> 0.972136
    assert u("ULS", 2, "dynamic", code) == pytest.approx(9600 / 8075)
    assert u("ULS", 1, "dynamic", code) == pytest.approx(7850 / 8075)
    # ALS class 1 (line_tension.ALS): 1.0 x 2000 + 1.1 x 3000 = 5300 -> 0.656347
    assert u("ALS", 1, "dynamic", code) == pytest.approx(5300 / 8075)
    # no common factor in this code: class 1 dynamic keeps the table factors
    assert not dnv.partial_factors("ULS", 1, "dynamic", code=code).common_factor_possible
    # a dynamic analysis only: quasi-static factors are refused
    with pytest.raises(SceneError, match="no quasi-static factors"):
        u("ULS", 2, "quasi-static", code)
    c = load_code(code)
    assert c.fatigue_factor(0.5) == 10.0                     # fatigue.safety_factor
    assert all(not e.verified for e in c.entries.values())


def test_a_code_file_must_give_source_and_verified(tmp_path):
    text = (load_code("dnv-os-e301-2008").file.read_text()
            .replace("  verified: true", "  verified: checked", 1))
    bad = tmp_path / "my-code.yaml"
    bad.write_text(text)
    with pytest.raises(SceneError, match="verified"):
        load_code(bad)
    text = (load_code("dnv-os-e301-2008").file.read_text()
            .replace("gamma_dyn: 2.10", "gamma_dyn: 0.5", 1))
    bad.write_text(text)
    with pytest.raises(SceneError, match="between 1 and 10") as err:
        load_code(bad)
    assert err.value.key == "line_tension.ULS.dynamic.2.gamma_dyn"


def test_a_user_code_file_is_used_as_given(tmp_path):
    # a copy of the DNV file with the ULS class 2 dynamic factors changed to 1.5 / 2.5:
    # 1.5 x 2000 + 2.5 x 3000 = 10500 -> 10500 / 8075
    text = (load_code("dnv-os-e301-2008").file.read_text()
            .replace("2: {gamma_mean: 1.40, gamma_dyn: 2.10}",
                     "2: {gamma_mean: 1.50, gamma_dyn: 2.50}")
            .replace("key: dnv-os-e301-2008", "key: my-code"))
    f = tmp_path / "my-code.yaml"
    f.write_text(text)
    assert u("ULS", 2, "dynamic", str(f)) == pytest.approx(10500 / 8075)
    assert math.isclose(load_code(f).strength_factor, 0.95)
