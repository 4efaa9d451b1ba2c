"""Fatigue core: rainflow (ASTM E1049-85), T-N curves and design equation (DNV 2008), spectral
damage (narrow band, combined spectrum, dual narrow band, Dirlik) against time-domain rainflow."""

import itertools
import math

import numpy as np
import pytest

from floatmoor.post.fatigue import (
    DNV_CURVES,
    TNCurve,
    damage_from_history,
    design_check,
    fatigue_safety_factor,
    rainflow,
    reference_breaking_strength,
    reversals,
)
from floatmoor.post.fatigue.rainflow import rainflow_kernel, reversals_kernel
from floatmoor.post.fatigue.spectral import (
    METHODS,
    bimodal_damage,
    dirlik,
    gaussian_realisation,
    moments,
    narrow_band,
    narrow_band_moments,
)


# -- rainflow ----------------------------------------------------------------------------------
def _histogram(ranges, counts):
    out = {}
    for r, c in zip(ranges, counts):
        out[float(r)] = out.get(float(r), 0.0) + float(c)
    return out


def test_astm_e1049_example_counts():
    # ASTM E1049-85 section 5.4.4, figure 6: the loading -2, 1, -3, 5, -1, 3, -4, 4, -2 gives
    # (range: cycles) 3: 0.5, 4: 1.5, 6: 0.5, 8: 1.0, 9: 0.5 (and none of 1, 2, 5, 7, 10)
    r, m, c = rainflow([-2, 1, -3, 5, -1, 3, -4, 4, -2])
    assert _histogram(r, c) == {3.0: 0.5, 4.0: 1.5, 6.0: 0.5, 8.0: 1.0, 9.0: 0.5}
    # the standard's walk-through: the only full cycle is -1 .. 3 (range 4, mean 1); the
    # range 8 is two half cycles (-3 .. 5 and -4 .. 4)
    full = sorted((float(a), float(b)) for a, b, k in zip(r, m, c) if k == 1.0)
    assert full == [(4.0, 1.0)]
    halves8 = sorted(float(b) for a, b, k in zip(r, m, c) if a == 8.0)
    assert halves8 == [0.0, 1.0]


def test_astm_example_on_a_sampled_history():
    # the same turning points with samples in between and plateaus: same counts
    pts = [-2, 1, -3, 5, -1, 3, -4, 4, -2]
    x = np.concatenate([np.linspace(a, b, 7)[:-1] for a, b in itertools.pairwise(pts)] + [[-2.0]])
    x = np.insert(x, 10, x[10])  # a plateau
    np.testing.assert_allclose(reversals(x), pts)
    r, _, c = rainflow(x)
    assert _histogram(r, c) == {3.0: 0.5, 4.0: 1.5, 6.0: 0.5, 8.0: 1.0, 9.0: 0.5}


def test_rainflow_against_reference_package():
    rf = pytest.importorskip("rainflow")  # independent implementation (optional test dependency)
    rng = np.random.default_rng(7)
    # (from 3 points: the package returns no cycle for a 2-point history, where ASTM step 6
    # counts the residue as a half cycle, as test_kernels_directly_and_edge_cases checks)
    for n in (3, 4, 50, 1001, 20000):
        x = rng.standard_normal(n).cumsum() + rng.standard_normal(n)
        ref = sorted((float(a), float(b), float(k)) for a, b, k, *_ in rf.extract_cycles(x))
        r, m, c = rainflow(x)
        ours = sorted(zip(map(float, r), map(float, m), map(float, c)))
        assert len(ours) == len(ref)
        np.testing.assert_allclose(np.array(ours), np.array(ref), rtol=0, atol=1e-12)


def test_kernels_directly_and_edge_cases():
    x = np.array([1.0, 1.0, 1.0])
    out = np.empty(3)
    assert reversals_kernel(x, out) == 1
    r, _, _ = rainflow(x)
    assert r.size == 0
    rev = np.array([0.0, 2.0])
    buf = [np.empty(2) for _ in range(4)]
    assert rainflow_kernel(rev, 2, *buf) == 1 and buf[1][0] == 2.0 and buf[3][0] == 0.5


def test_damage_from_history_by_hand():
    # one full cycle of range 2 MN between half cycles: the ASTM sequence scaled to MN
    curve = TNCurve(name="t", a_d=316.0, m=3.0)
    x = 1e6 * np.array([-2, 1, -3, 5, -1, 3, -4, 4, -2], float)
    rbs = 8.5e6
    hand = (0.5 * 3 ** 3 + 1.5 * 4 ** 3 + 0.5 * 6 ** 3 + 1.0 * 8 ** 3 + 0.5 * 9 ** 3) \
        * (1e6 / rbs) ** 3 / 316.0
    assert damage_from_history(x, curve, rbs) == pytest.approx(hand, rel=1e-12)


# -- T-N curves and the design equation ----------------------------------------------------------
def test_tn_constants_and_design_equation_by_hand():
    # DNV (2008) Ch.2 Sec.2 S-N curves of chain, stress range in MPa: stud chain a_D = 1.2e11,
    # studless chain a_D = 6.0e10, m = 3.0 (the published values as reproduced by DNV's qats
    # example "DNVGL-OS-E301 curve for studless chain" and the aceengineer DNV-OS-E301 mooring
    # fatigue calculator, docs/REFERENCES.md); nominal area of the two legs 2 pi d^2 / 4
    assert (DNV_CURVES["chain_studlink"].a_d, DNV_CURVES["chain_studlink"].m) == (1.2e11, 3.0)
    assert (DNV_CURVES["chain_studless"].a_d, DNV_CURVES["chain_studless"].m) == (6.0e10, 3.0)
    assert DNV_CURVES["chain_studless"].basis == "stress"
    # API RP 2SK (2005) T-N curves (tension range over the RBS): studlink 1000, studless 316,
    # m = 3 -- formerly shipped under the DNV names
    assert (DNV_CURVES["api_chain_studlink"].a_d, DNV_CURVES["api_chain_studlink"].m) == (1000.0, 3.0)
    assert (DNV_CURVES["api_chain_studless"].a_d, DNV_CURVES["api_chain_studless"].m) == (316.0, 3.0)
    # the rope constants are the API RP 2SK curves at the mean load ratio 0.3:
    # log10 a_D = 3.20 - 2.79 * 0.3 = 2.363 -> 230.7; 3.25 - 3.43 * 0.3 = 2.221 -> 166.3
    assert DNV_CURVES["wire_six_strand"].a_d == pytest.approx(10 ** (3.20 - 2.79 * 0.3), rel=3e-3)
    assert DNV_CURVES["wire_spiral_strand"].a_d == pytest.approx(10 ** (3.25 - 3.43 * 0.3),
                                                                 rel=3e-3)
    assert DNV_CURVES["wire_six_strand"].m == 4.09 and DNV_CURVES["wire_spiral_strand"].m == 5.05
    # API studless chain, MBS 8500 kN, range 1000 kN: s = 1/8.5, n = 316 * 8.5^3 = 194,063.5
    assert DNV_CURVES["api_chain_studless"].cycles_to_failure(1.0 / 8.5) == pytest.approx(194063.5)
    # corrosion: 84 mm chain, 0.3 mm/year over 20 years -> 84 - 0.5*0.3*20 = 81 mm,
    # RBS = 8500 kN * (81/84)^2 = 7903.7 kN
    rbs = reference_breaking_strength(8.5e6, 0.084, DNV_CURVES["api_chain_studless"],
                                      rate_mm_per_year=0.3, design_life_years=20.0)
    assert rbs == pytest.approx(8.5e6 * (81.0 / 84.0) ** 2) and rbs / 1e3 == pytest.approx(
        7903.70, abs=0.01)
    # DNV studless chain on the same 81 mm: A = 2 pi 81^2 / 4 = 10,306.0 mm^2; a range of
    # 1000 kN is 97.031 MPa, n = 6.0e10 / 97.031^3 = 65,678 cycles (by hand); the MBS is not used
    area = reference_breaking_strength(float("nan"), 0.084, DNV_CURVES["chain_studless"],
                                       rate_mm_per_year=0.3, design_life_years=20.0)
    assert area == pytest.approx(2 * math.pi * 81.0 ** 2 / 4) and area == pytest.approx(
        10306.0, abs=0.05)
    assert DNV_CURVES["chain_studless"].damage([1.0e6], [1.0], area) == pytest.approx(
        1.0 / 65678.0, rel=1e-4)
    assert reference_breaking_strength(8.5e6, 0.185, DNV_CURVES["polyester"],
                                       rate_mm_per_year=0.3, design_life_years=20.0) == 8.5e6
    # fatigue safety factor of DNV-OS-E301 (2008): 5 up to d_F = 0.8, then 5 + 3 (d_F - 0.8)/0.2:
    # 5 + 3 * 0.1 / 0.2 = 6.5 at 0.9, 8 at 1.0 (the range 5 to 8 of the standard; code file)
    assert fatigue_safety_factor(0.5) == 5.0
    assert fatigue_safety_factor(0.8) == 5.0
    assert fatigue_safety_factor(0.9) == pytest.approx(6.5)
    assert fatigue_safety_factor(1.0) == pytest.approx(8.0)
    assert fatigue_safety_factor(float("nan")) == 5.0
    # API RP 2SK (2005): a constant factor of safety 3 on the fatigue life (code file)
    assert fatigue_safety_factor(0.95, code="api-rp-2sk-2005") == 3.0
    # design equation 1 - gamma_F d_C >= 0: 0.01/year over 20 years, gamma 5 -> 1 - 1.0 = 0: ok
    c = design_check(0.01, 20.0, 5.0)
    assert c["d_c"] == pytest.approx(0.2) and c["life"] == pytest.approx(100.0)
    assert c["ok"] and c["allowed_life"] == pytest.approx(20.0)
    assert not design_check(0.0101, 20.0, 5.0)["ok"]


# -- spectral damage against rainflow ------------------------------------------------------------
def _bump(w, w0, rel, var):
    s = rel * w0
    return var * np.exp(-0.5 * ((w - w0) / s) ** 2) / (s * math.sqrt(2.0 * math.pi))


W = np.linspace(0.0, 20.0, 40001)


def _td_damage(S, duration, seed, m=3.0, a_d=1.0):
    _, x = gaussian_realisation(W, S, duration, 1.0 / 40.0, seed=seed)
    r, _, c = rainflow(x)
    return float(np.sum(c * r ** m) / a_d), x


def test_realisation_has_the_spectrum_variance():
    S = _bump(W, 2 * math.pi, 0.05, 4.0)
    _, x = gaussian_realisation(W, S, 2000.0, 0.05, seed=3)
    assert np.var(x) == pytest.approx(4.0, rel=0.01)


@pytest.mark.parametrize("m", [3.0, 4.09])
def test_narrow_band_closed_form_against_rainflow(m):
    # narrow-band Gaussian process (Gaussian bump, 3 % relative width at 1 Hz), 2e5 cycles:
    # rainflow damage within 3 % of D = nu0 T (2 sqrt 2 sigma)^m Gamma(1 + m/2) / a_D
    # (ranges over the breaking strength: sigma = 0.05 RBS here, RBS = 1)
    var = 0.05 ** 2
    S = _bump(W, 2 * math.pi, 0.03, var)
    T = 2.0e5
    d_td, _ = _td_damage(S, T, seed=1, m=m, a_d=316.0)
    sigma = math.sqrt(var)
    closed = 1.0 * T * (2 * math.sqrt(2) * sigma) ** m * math.gamma(1 + m / 2) / 316.0
    assert d_td == pytest.approx(closed, rel=0.03)
    mom = moments(W, S)
    assert narrow_band_moments(mom[0], mom[2], T, 316.0, m) == pytest.approx(closed, rel=2e-3)
    assert narrow_band(sigma, 1.0, T, 316.0, m) == pytest.approx(closed, rel=1e-12)
    # Dirlik tends to the narrow band for a narrow spectrum
    assert float(dirlik(mom, T, 316.0, m)) == pytest.approx(closed, rel=0.02)


def test_rbs_scaling_of_moments():
    S = _bump(W, 1.0, 0.1, 4.0e10)
    np.testing.assert_allclose(moments(W, S, rbs=2.0e5), moments(W, S) / 4.0e10)


# Bimodal LF + WF: variance ratio sigma_L^2/sigma_W^2, frequency ratio f_W/f_L and relative
# width of the WF band spanning the Floatel-like tensions (FD: sigma_L/sigma_W about 0.66-1.7,
# Tz 97 s / 16.5 s = 5.9; the WF tension of a JONSWAP sea through the RAOs is a broad band).
# The LF band is a Gaussian bump of 10 % relative width.
BIMODAL = [(0.25, 5.0, 0.08), (0.45, 6.0, 0.08), (1.0, 5.0, 0.08), (1.0, 10.0, 0.08),
           (4.0, 5.0, 0.08), (4.0, 10.0, 0.08),
           (0.45, 6.0, 0.2), (2.8, 6.0, 0.2), (0.45, 6.0, 0.3), (2.8, 6.0, 0.3)]


def bimodal_table(cases=BIMODAL, lf_cycles=4000, m=3.0, seed=2):
    """(variance ratio, frequency ratio, WF width, {method: FD / TD}) for each case."""
    rows = []
    for k, (vr, fr, width) in enumerate(cases):
        w_w = 2 * math.pi
        SL, SW = _bump(W, w_w / fr, 0.1, vr), _bump(W, w_w, width, 1.0)
        T = lf_cycles * fr
        d_td, _ = _td_damage(SL + SW, T, seed=seed + k, m=m)
        ml, mw = moments(W, SL), moments(W, SW)
        rows.append((vr, fr, width, {meth: float(bimodal_damage(meth, ml, mw, T, 1.0, m)) / d_td
                                     for meth in METHODS}))
    return rows


def test_bimodal_methods_against_rainflow():
    rows = bimodal_table()
    print("\n var ratio  f ratio  WF width" + "".join(f"{m:>18s}" for m in METHODS))
    for vr, fr, width, res in rows:
        print(f"{vr:10.2f} {fr:8.1f} {width:9.2f} " + "".join(f"{res[m]:18.3f}" for m in METHODS))
    for vr, fr, width, res in rows:
        case = (vr, fr, width, res)
        # combined spectrum: conservative (DNV 2008)
        assert res["combined_spectrum"] >= 1.0, case
        # the simple summation of the two narrow-band damages is non-conservative
        assert res["simple_summation"] < 1.0, case
        # Dirlik: within 12 % (slightly non-conservative for bimodal tension)
        assert abs(res["dirlik"] - 1.0) < 0.12, case
        if width < 0.1:
            # dual narrow band: within 10 % for a narrow WF band (its assumption)
            assert abs(res["dual_narrow_band"] - 1.0) < 0.10, case
        else:
            # broad WF band: the dual narrow band turns conservative (up to about 25 %)
            assert 0.95 < res["dual_narrow_band"] < 1.30, case


@pytest.mark.slow  # long realisations: 2e6 cycles of the narrow-band process (about 30 s)
def test_narrow_band_long_realisation():
    var = 0.05 ** 2
    S = _bump(W, 2 * math.pi, 0.02, var)
    T = 2.0e6
    d_td, _ = _td_damage(S, T, seed=11)
    closed = T * (2 * math.sqrt(2) * 0.05) ** 3 * math.gamma(2.5)
    assert d_td == pytest.approx(closed, rel=0.01)


# -- T-N curves from the line-type library ---------------------------------------------------------
def test_curves_from_the_line_type_library(tmp_path):
    from floatmoor.core.errors import SceneError
    from floatmoor.mooring.line_types import default_library
    from floatmoor.post.fatigue import curve_for

    lib = default_library()
    lt, _ = lib.get("chain_studlink_R4", diameter=0.084)
    assert curve_for(lt).name == "chain_studlink"
    lt, _ = lib.get("wire_spiral_strand", diameter=0.1)
    assert (curve_for(lt).a_d, curve_for(lt).m) == (166.0, 5.05)
    f = tmp_path / "types.yaml"
    f.write_text(
        "line_types:\n"
        "  kenter: {family: chain_studless, grade: R4, tn_curve: connecting_link}\n"
        "  my_chain: {material: chain, diameter: 0.1, mass_per_length: 200.0, density: 7850.0,\n"
        "             ea: 8.0e+8, mbs: 9.0e+6, tn_a_d: 500.0, tn_m: 3.2}\n"
        "  plain: {material: chain, diameter: 0.1, mass_per_length: 200.0, density: 7850.0,\n"
        "          ea: 8.0e+8, mbs: 9.0e+6}\n"
        "  half: {material: chain, diameter: 0.1, mass_per_length: 200.0, density: 7850.0,\n"
        "         ea: 8.0e+8, mbs: 9.0e+6, tn_a_d: 500.0}\n"
        "  odd: {material: chain, diameter: 0.1, mass_per_length: 200.0, density: 7850.0,\n"
        "        ea: 8.0e+8, mbs: 9.0e+6, tn_curve: nylon}\n"
        "  steel_user: {material: user, diameter: 0.1, mass_per_length: 200.0, density: 7850.0,\n"
        "               ea: 8.0e+8, mbs: 9.0e+6}\n")
    lib = lib.extended_from_file(f)
    c = curve_for(lib.get("kenter", diameter=0.084)[0])
    assert (c.a_d, c.m) == (178.0, 3.0)
    c = curve_for(lib.get("my_chain")[0])
    assert (c.a_d, c.m, c.corrodes) == (500.0, 3.2, True) and "user" in c.source
    assert curve_for(lib.get("plain")[0]).name == "chain_studless"
    with pytest.raises(SceneError, match="tn_m"):
        lib.get("half")
    with pytest.raises(SceneError, match="T-N curve"):
        curve_for(lib.get("odd")[0])
    with pytest.raises(SceneError, match="T-N curve"):
        curve_for(lib.get("steel_user")[0])
