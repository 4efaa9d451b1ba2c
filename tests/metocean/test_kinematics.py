"""Airy kinematics: closed forms, deep/shallow limits, field equations and Wheeler stretching."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from floatmoor.core.constants import GRAVITY as G
from floatmoor.metocean import airy_kinematics, depth_factors, wavenumber

RHO = 1025.0


def one(a=1.5, w=0.6, beta=0.0, phi=0.3, depth=None):
    k = wavenumber(np.array([w]), depth)
    return dict(omega=[w], amplitude=[a], phase=[phi], k=k, direction=[beta]), float(k[0])


def test_wavenumber_limits_and_residual():
    w = np.linspace(0.05, 4.0, 200)
    np.testing.assert_allclose(wavenumber(w), w ** 2 / G, rtol=1e-15)  # deep water
    np.testing.assert_allclose(wavenumber(w, 1e5), w ** 2 / G, rtol=1e-12)
    d = 0.5  # shallow: k d << 1 for low w -> k = w / sqrt(g d) (1 + (kd)^2/6 + ...)
    ws = np.array([0.01, 0.02])
    ks = wavenumber(ws, d)
    np.testing.assert_allclose(ks, ws / math.sqrt(G * d), rtol=(ks.max() * d) ** 2 / 5)
    for wi, d in [(0.3, 50.0), (0.6283, 20.0), (1.2, 320.0), (0.1, 150.0)]:
        kb = brentq(lambda k: G * k * math.tanh(k * d) - wi * wi, 1e-8, 10.0, xtol=1e-15)
        assert float(wavenumber(np.array([wi]), d)[0]) == pytest.approx(kb, rel=1e-12)


def test_deep_water_closed_form():
    # Deep water (e.g. Faltinsen 1990 table 2.1) for eta = a cos(wt - kx + phi):
    # u = a w e^{kz} cos th, w = -a w e^{kz} sin th, du/dt = -a w^2 e^{kz} sin th,
    # dw/dt = -a w^2 e^{kz} cos th, p_dyn = rho g a e^{kz} cos th
    comp, k = one()
    a, w, phi = 1.5, 0.6, 0.3
    pts = np.array([[0.0, 0.0, -5.0], [30.0, 10.0, -40.0], [-7.0, 2.0, -1.6]])  # below troughs
    t = np.array([0.0, 3.7, 11.2])
    r = airy_kinematics(**comp, t=t, points=pts, wheeler=False, rho=RHO)
    for j, tj in enumerate(t):
        th = w * tj - k * pts[:, 0] + phi
        e = np.exp(k * pts[:, 2])
        np.testing.assert_allclose(r["eta"][j], a * np.cos(th), rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose(r["velocity"][j, :, 0], a * w * e * np.cos(th), atol=1e-13)
        np.testing.assert_allclose(r["velocity"][j, :, 1], 0.0, atol=1e-15)
        np.testing.assert_allclose(r["velocity"][j, :, 2], -a * w * e * np.sin(th), atol=1e-13)
        np.testing.assert_allclose(r["acceleration"][j, :, 0], -a * w * w * e * np.sin(th),
                                   atol=1e-13)
        np.testing.assert_allclose(r["acceleration"][j, :, 2], -a * w * w * e * np.cos(th),
                                   atol=1e-13)
        np.testing.assert_allclose(r["pressure"][j], RHO * G * a * e * np.cos(th), rtol=1e-12,
                                   atol=1e-9)


def test_finite_depth_closed_form_with_cosh():
    # Finite depth: ratios cosh k(z+d)/sinh kd etc. evaluated directly with numpy (moderate kd)
    d = 40.0
    comp, k = one(a=1.0, w=0.5, beta=0.7, phi=1.1, depth=d)
    pts = np.array([[3.0, -4.0, -1.0], [0.0, 0.0, -20.0], [10.0, 5.0, -39.9], [1.0, 1.0, -40.0]])
    t = 5.0
    r = airy_kinematics(**comp, t=t, points=pts, water_depth=d, wheeler=False, rho=RHO)
    th = 0.5 * t - k * (pts[:, 0] * math.cos(0.7) + pts[:, 1] * math.sin(0.7)) + 1.1
    z = pts[:, 2]
    ch, sh = np.cosh(k * (z + d)), np.sinh(k * (z + d))
    uh = 0.5 * ch / math.sinh(k * d) * np.cos(th)
    np.testing.assert_allclose(r["velocity"][0, :, 0], uh * math.cos(0.7), rtol=1e-12)
    np.testing.assert_allclose(r["velocity"][0, :, 1], uh * math.sin(0.7), rtol=1e-12)
    np.testing.assert_allclose(r["velocity"][0, :, 2], -0.5 * sh / math.sinh(k * d) * np.sin(th),
                               rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(r["pressure"][0], RHO * G * ch / math.cosh(k * d) * np.cos(th),
                               rtol=1e-12)
    assert r["velocity"][0, 3, 2] == 0.0 or abs(r["velocity"][0, 3, 2]) < 1e-15  # w = 0 at seabed


def test_no_overflow_in_deep_water_and_large_depth_equals_deep():
    # w = 3 rad/s, d = 1000 m: kd = 918, cosh(kd) overflows in a naive evaluation
    pts = np.array([[0.0, 0.0, -0.5], [0.0, 0.0, -3.0]])
    comp_d, k = one(w=3.0, depth=1000.0)
    assert k * 1000.0 > 710
    r = airy_kinematics(**comp_d, t=1.0, points=pts, water_depth=1000.0, wheeler=False)
    comp_inf, _ = one(w=3.0)
    r_inf = airy_kinematics(**comp_inf, t=1.0, points=pts, water_depth=None, wheeler=False)
    for key in ("velocity", "acceleration", "pressure"):
        assert np.all(np.isfinite(r[key]))
        np.testing.assert_allclose(r[key], r_inf[key], rtol=1e-12, atol=1e-14)
    cs, ss, cc = depth_factors(0.9, -2.0, 1e6)
    assert cs == pytest.approx(math.exp(-1.8)) and ss == pytest.approx(math.exp(-1.8))


def test_shallow_water_limit():
    # kd << 1: horizontal velocity ~ uniform over depth, u = a sqrt(g/d) (long-wave theory),
    # vertical velocity linear in (z + d), zero at the seabed.
    d, w, a = 10.0, 0.03, 0.5
    comp, k = one(a=a, w=w, phi=0.0, depth=d)
    assert k * d < 0.05
    pts = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, -5.0], [0.0, 0.0, -10.0]])
    r = airy_kinematics(**comp, t=0.0, points=pts, water_depth=d, wheeler=False)
    u = r["velocity"][0, :, 0]
    np.testing.assert_allclose(u, a * math.sqrt(G / d), rtol=2e-3)


def test_field_equations_by_finite_differences():
    # Independent physics: continuity du/dx + dw/dz = 0; kinematic surface condition
    # w(z=0) = d eta/dt; linearised Euler du/dt = -1/rho dp/dx, dw/dt = -1/rho dp/dz - ...
    # (dynamic pressure only, so dw/dt = -1/rho dp_dyn/dz); Bernoulli p_dyn(z=0) = rho g eta.
    d = 60.0
    rng = np.random.default_rng(5)
    w = np.array([0.4, 0.7, 1.1])
    k = wavenumber(w, d)
    comp = dict(omega=w, amplitude=[0.8, 0.5, 0.2], phase=rng.uniform(0, 6, 3), k=k,
                direction=[0.0, 0.0, 0.0])
    h = 1e-3

    def at(x, z, t):
        r = airy_kinematics(**comp, t=t, points=np.array([[x, 0.0, z]]), water_depth=d,
                            wheeler=False, rho=RHO)
        return {key: v[0, 0] for key, v in r.items()}

    x0, z0, t0 = 12.0, -7.0, 4.0
    c = at(x0, z0, t0)
    dudx = (at(x0 + h, z0, t0)["velocity"][0] - at(x0 - h, z0, t0)["velocity"][0]) / (2 * h)
    dwdz = (at(x0, z0 + h, t0)["velocity"][2] - at(x0, z0 - h, t0)["velocity"][2]) / (2 * h)
    assert dudx + dwdz == pytest.approx(0.0, abs=1e-7)
    dpdx = (at(x0 + h, z0, t0)["pressure"] - at(x0 - h, z0, t0)["pressure"]) / (2 * h)
    dpdz = (at(x0, z0 + h, t0)["pressure"] - at(x0, z0 - h, t0)["pressure"]) / (2 * h)
    assert c["acceleration"][0] == pytest.approx(-dpdx / RHO, rel=1e-6)
    assert c["acceleration"][2] == pytest.approx(-dpdz / RHO, rel=1e-6)
    dudt = (at(x0, z0, t0 + h)["velocity"][0] - at(x0, z0, t0 - h)["velocity"][0]) / (2 * h)
    assert c["acceleration"][0] == pytest.approx(dudt, rel=1e-6)
    s = at(x0, 0.0, t0)
    detadt = (at(x0, 0.0, t0 + h)["eta"] - at(x0, 0.0, t0 - h)["eta"]) / (2 * h)
    assert s["velocity"][2] == pytest.approx(detadt, rel=1e-6)
    assert s["pressure"] == pytest.approx(RHO * G * s["eta"], rel=1e-12)


@pytest.mark.parametrize("depth", [None, 80.0])
def test_wheeler_surface_value_at_instantaneous_surface(depth):
    # Wheeler: z' = (z - eta) d/(d + eta) maps z = eta to z' = 0, so the stretched kinematics at
    # the instantaneous surface equal the linear (unstretched) values at z = 0; the seabed is
    # unchanged; points above the surface are dry (zero).
    rng = np.random.default_rng(2)
    w = np.linspace(0.3, 1.2, 12)
    k = wavenumber(w, depth)
    comp = dict(omega=w, amplitude=rng.uniform(0.1, 0.6, w.size), phase=rng.uniform(0, 6, w.size),
                k=k, direction=rng.uniform(-0.5, 0.5, w.size))
    xy = np.array([[0.0, 0.0], [15.0, -3.0], [40.0, 22.0]])
    seen = []
    for t in (0.0, 7.3, 19.1):
        # linear values at z = 0 (plain numpy, independent of the kernel)
        base = numpy_airy(w, comp["amplitude"], comp["phase"], k, comp["direction"], t,
                          np.c_[xy, np.zeros(3)], depth)
        # the kernel's own eta (bit-identical to what it compares z with for the dry check)
        eta = airy_kinematics(**comp, t=t, points=np.c_[xy, np.full(3, -5.0)], water_depth=depth,
                              wheeler=True)["eta"][0]
        np.testing.assert_allclose(eta, base["eta"], atol=1e-12)
        seen.extend(eta)
        top = airy_kinematics(**comp, t=t, points=np.c_[xy, eta], water_depth=depth, wheeler=True,
                              rho=RHO)
        for key in ("velocity", "acceleration", "pressure"):
            np.testing.assert_allclose(top[key][0], base[key], rtol=1e-11, atol=1e-11)
        above = airy_kinematics(**comp, t=t, points=np.c_[xy, eta + 0.01], water_depth=depth,
                                rho=RHO)
        assert np.all(above["velocity"] == 0.0) and np.all(above["pressure"] == 0.0)
        if depth is not None:
            bed = np.c_[xy, np.full(3, -depth)]
            a = airy_kinematics(**comp, t=t, points=bed, water_depth=depth, wheeler=True)
            b = airy_kinematics(**comp, t=t, points=bed, water_depth=depth, wheeler=False)
            np.testing.assert_allclose(a["velocity"], b["velocity"], rtol=1e-12, atol=1e-14)
            # Wheeler moves a submerged point to z' = (z - eta) d/(d + eta): check one value
            z = -10.0
            p = np.c_[xy[:1], [[z]]]
            s = airy_kinematics(**comp, t=t, points=p, water_depth=depth, wheeler=True)
            zs = (z - eta[0]) * depth / (depth + eta[0])
            u = airy_kinematics(**comp, t=t, points=np.c_[xy[:1], [[zs]]], water_depth=depth,
                                wheeler=False)
            np.testing.assert_allclose(s["velocity"], u["velocity"], rtol=1e-12)
    assert min(seen) < 0.0 < max(seen)  # stretching tested under crests and under troughs


def numpy_airy(w, a, ph, k, beta, t, pts, d):
    """Plain numpy Airy kinematics with cosh/sinh (no stretching, no dry check)."""
    th = w[None, :] * t - k[None, :] * (pts[:, :1] * np.cos(beta) + pts[:, 1:2] * np.sin(beta)) \
        + ph[None, :]
    if d is None:
        cs = ss = cc = np.exp(k * pts[:, 2:3])
    else:
        zz = pts[:, 2:3] + d
        cs = np.cosh(k * zz) / np.sinh(k * d)
        ss = np.sinh(k * zz) / np.sinh(k * d)
        cc = np.cosh(k * zz) / np.cosh(k * d)
    uh = a * w * cs * np.cos(th)
    ah = -a * w * w * cs * np.sin(th)
    vel = np.stack([(uh * np.cos(beta)).sum(1), (uh * np.sin(beta)).sum(1),
                    (-a * w * ss * np.sin(th)).sum(1)], axis=1)
    acc = np.stack([(ah * np.cos(beta)).sum(1), (ah * np.sin(beta)).sum(1),
                    (-a * w * w * ss * np.cos(th)).sum(1)], axis=1)
    return {"velocity": vel, "acceleration": acc, "pressure": RHO * G * (a * cc * np.cos(th)).sum(1),
            "eta": (a * np.cos(th)).sum(1)}


def test_kernel_against_numpy_many_components_and_directions():
    # Plain numpy evaluation (cosh/sinh directly, moderate kd) against the numba kernel.
    d = 150.0
    rng = np.random.default_rng(11)
    n = 40
    w = rng.uniform(0.2, 1.5, n)
    k = wavenumber(w, d)
    a = rng.uniform(0.05, 0.5, n)
    ph = rng.uniform(0, 2 * np.pi, n)
    beta = rng.uniform(-np.pi, np.pi, n)
    pts = np.c_[rng.uniform(-50, 50, 25), rng.uniform(-50, 50, 25), rng.uniform(-149, -3, 25)]
    t = np.array([0.0, 12.5])
    r = airy_kinematics(w, a, ph, k, beta, t, pts, water_depth=d, wheeler=False, rho=RHO)
    for j, tj in enumerate(t):
        th = w[None, :] * tj - k[None, :] * (pts[:, :1] * np.cos(beta) + pts[:, 1:2] * np.sin(beta)) \
            + ph[None, :]
        zz = pts[:, 2:3] + d
        cs = np.cosh(k * zz) / np.sinh(k * d)
        ss = np.sinh(k * zz) / np.sinh(k * d)
        cc = np.cosh(k * zz) / np.cosh(k * d)
        uh = a * w * cs * np.cos(th)
        ah = -a * w * w * cs * np.sin(th)
        np.testing.assert_allclose(r["velocity"][j, :, 0], (uh * np.cos(beta)).sum(1), atol=1e-12)
        np.testing.assert_allclose(r["velocity"][j, :, 1], (uh * np.sin(beta)).sum(1), atol=1e-12)
        np.testing.assert_allclose(r["velocity"][j, :, 2], (-a * w * ss * np.sin(th)).sum(1),
                                   atol=1e-12)
        np.testing.assert_allclose(r["acceleration"][j, :, 0], (ah * np.cos(beta)).sum(1),
                                   atol=1e-12)
        np.testing.assert_allclose(r["acceleration"][j, :, 2],
                                   (-a * w * w * ss * np.cos(th)).sum(1), atol=1e-12)
        np.testing.assert_allclose(r["pressure"][j], RHO * G * (a * cc * np.cos(th)).sum(1),
                                   rtol=1e-11, atol=1e-8)
        np.testing.assert_allclose(r["eta"][j], (a * np.cos(th)).sum(1), atol=1e-12)
