"""Retardation functions: analytic pair and the OC3 / OC4 databases."""

import numpy as np
import pytest

from floatmoor.core.errors import FloatmoorWarning
from floatmoor.hydro import (
    consistency_report,
    cutoff_time,
    fit_infinite_frequency_added_mass,
    format_consistency,
    reconstruct_from_retardation,
    retardation_function,
)
from floatmoor.hydro.retardation import filon_cos, filon_sin

# Analytic pair: K(t) = a exp(-b t) cos(c t).  Closed forms (Laplace transform of K):
#   B(w) = int_0^inf K cos(w t) dt = (a/2) [ b / (b^2 + (w-c)^2) + b / (b^2 + (w+c)^2) ]
#   int_0^inf K sin(w t) dt = (a/2) [ (w-c) / (b^2 + (w-c)^2) + (w+c) / (b^2 + (w+c)^2) ]
#   A(w) - A_inf = -(1/w) int_0^inf K sin(w t) dt       (Ogilvie)
a, b, c = 2.0, 0.4, 1.2


def B_exact(w):
    return 0.5 * a * (b / (b ** 2 + (w - c) ** 2) + b / (b ** 2 + (w + c) ** 2))


def S_exact(w):
    return 0.5 * a * ((w - c) / (b ** 2 + (w - c) ** 2) + (w + c) / (b ** 2 + (w + c) ** 2))


def test_filon_rules_are_exact_for_linear_functions():
    x = np.linspace(0.0, 3.0, 7)
    f = 2.0 + 0.5 * x
    y = np.array([0.0, 0.3, 7.0])
    # int (2 + x/2) cos(y x) dx closed form
    def F(xx, yy):
        if yy == 0:
            return 2 * xx + xx ** 2 / 4
        return (2 + xx / 2) * np.sin(yy * xx) / yy + 0.5 * np.cos(yy * xx) / yy ** 2
    exact = np.array([F(3.0, yy) - F(0.0, yy) for yy in y])
    np.testing.assert_allclose(filon_cos(x, f, y), exact, rtol=1e-12, atol=1e-12)
    def G(xx, yy):
        return -(2 + xx / 2) * np.cos(yy * xx) / yy + 0.5 * np.sin(yy * xx) / yy ** 2
    exact = np.array([0.0] + [G(3.0, yy) - G(0.0, yy) for yy in y[1:]])
    np.testing.assert_allclose(filon_sin(x, f, y), exact, rtol=1e-12, atol=1e-12)


def test_analytic_pair_recovers_K_and_A_inf():
    # grid like a diffraction run (0 .. 5 rad/s step 0.05), with the w = 0 sample
    w = np.arange(0.0, 5.0001, 0.05)
    t = np.arange(0.0, 60.0, 0.02)
    K = retardation_function(w, B_exact(w), t)
    K_ex = a * np.exp(-b * t) * np.cos(c * t)
    assert np.max(np.abs(K - K_ex)) < 0.01 * a  # within 1 % of the peak K(0) = a
    # A_inf = 1.5 (same order as a(w)); fit over the band from A(w) samples
    w1 = w[1:]
    a_inf = 1.5
    A = a_inf - S_exact(w1) / w1
    fit = fit_infinite_frequency_added_mass(w1, A, t, K, band=(0.2, 2.0))
    assert fit == pytest.approx(a_inf, rel=0.01)
    A_rec, B_rec = reconstruct_from_retardation(t, K, w1, a_inf)
    band = (w1 >= 0.2) & (w1 <= 2.0)
    assert np.max(np.abs(B_rec - B_exact(w1))[band]) < 0.01 * B_exact(w1).max()
    assert np.max(np.abs(A_rec - A)[band]) < 0.01 * np.max(np.abs(A - a_inf))


def test_tail_model_matters_and_helps():
    # Without the w^-2 tail the same grid loses about 5 % of K(0): the tail model is doing work.
    w = np.arange(0.0, 5.0001, 0.05)
    t = np.array([0.0, 0.5, 1.0])
    K_ex = a * np.exp(-b * t) * np.cos(c * t)
    err_tail = np.max(np.abs(retardation_function(w, B_exact(w), t) - K_ex))
    err_none = np.max(np.abs(retardation_function(w, B_exact(w), t, tail="none") - K_ex))
    assert err_none > 0.03 * a
    assert err_tail < 0.2 * err_none


def test_stacked_shapes():
    w = np.arange(0.05, 3.0, 0.05)
    Bs = np.stack([B_exact(w), 2 * B_exact(w)])[None]  # (1, 2, n_w)
    K = retardation_function(w, Bs, np.linspace(0, 10, 11))
    assert K.shape == (1, 2, 11)
    np.testing.assert_allclose(K[0, 1], 2 * K[0, 0])


def test_cutoff_time_of_exponential_decay():
    t = np.linspace(0, 100, 10001)
    K = np.exp(-0.2 * t)
    # |K| < 1 % of the peak after t = ln(100) / 0.2 = 23.03 s
    assert cutoff_time(t, K, 0.01) == pytest.approx(np.log(100) / 0.2, abs=0.02)


@pytest.mark.parametrize("which", ["oc3", "oc4"])
def test_wamit_databases_reconstruct_within_2_percent(which, oc3_db, oc4_db):
    ds = oc3_db if which == "oc3" else oc4_db
    with pytest.warns(FloatmoorWarning) if which == "oc3" else _nowarn():
        rep = consistency_report(ds, band=(0.2, 2.0))
    errA = rep.max_rel_error_added_mass.values
    errB = rep.max_rel_error_damping.values
    assert np.nanmax(errA) < 0.02
    assert np.nanmax(errB) < 0.02
    # every physically present diagonal term was checked (OC3 yaw is numerical noise -> NaN)
    live = [0, 1, 2, 3, 4] if which == "oc3" else [0, 1, 2, 3, 4, 5]
    assert np.all(np.isfinite(np.diag(errA)[live]))
    text = format_consistency(rep)
    assert "surge-surge" in text and "heave-heave" in text
    # fitted A_inf (Ogilvie least squares) against WAMIT's infinite-frequency rows
    rep2 = consistency_report(ds.drop_vars("infinite_frequency_added_mass"), band=(0.2, 2.0))
    assert bool(rep2.a_inf_fitted)
    d_fit = np.diag(rep2.infinite_frequency_added_mass.values)[live]
    d_db = np.diag(ds.infinite_frequency_added_mass.values)[live]
    np.testing.assert_allclose(d_fit, d_db, rtol=0.01)


def test_report_warns_about_spikes_and_undecayed_damping(oc4_db):
    ds = oc4_db.copy(deep=True)
    k = 200
    ds.radiation_damping.values[k, 2, 2] *= 10.0  # an irregular-frequency-like spike in heave
    ds.radiation_damping.values[-1, 0, 0] = ds.radiation_damping.values[:, 0, 0].max()
    with pytest.warns(FloatmoorWarning) as rec:
        rep = consistency_report(ds)
    msgs = " ".join(str(r.message) for r in rec)
    assert "radiation_damping[heave,heave] has a spike" in msgs
    assert "radiation_damping[surge,surge] has not decayed" in msgs
    assert "spike" in rep.attrs["warnings"]


class _nowarn:
    def __enter__(self):
        import warnings
        self._c = warnings.catch_warnings()
        self._c.__enter__()
        warnings.simplefilter("error", FloatmoorWarning)

    def __exit__(self, *exc):
        return self._c.__exit__(*exc)


def test_report_prints_the_limitations_recorded_with_the_database(oc4_db):
    from floatmoor.hydro import format_consistency
    ds = oc4_db.copy(deep=True)
    ds.attrs["limitations"] = "first known limit\nsecond known limit"
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        rep = consistency_report(ds)
        ds.attrs.pop("limitations")
        plain = format_consistency(consistency_report(ds))
    text = format_consistency(rep)
    assert "database limitations" in text
    assert "  first known limit" in text and "  second known limit" in text
    assert "database limitations" not in plain


def test_floatel_database_records_its_frequency_range_limitation():
    from floatmoor.hydro import load_database

    from .conftest import VESSELS
    ds = load_database(VESSELS / "floatel_like" / "database.nc")
    assert float(ds.omega.max()) == pytest.approx(2.5)
    assert "2.5 rad/s" in ds.attrs["limitations"]
