"""Vectorised catenary: element-by-element identity with the scalar call, broadcasting, errors,
failed elements, and MoorPy on a sample."""

import math
import warnings

import numpy as np
import pytest

from floatmoor.core.errors import ConvergenceError
from floatmoor.mooring import CatenaryBatch, CatenaryResult, catenary, catenary_batch
from floatmoor.mooring.catenary import STATUS_MESSAGES


def spread(n, seed=7):
    """Lines in every regime (as in test_catenary's random cases): slack with a grounded part,
    taut around the chord, steep, very slack (H = 0), some free-hanging (no seabed)."""
    rng = np.random.default_rng(seed)
    L = rng.uniform(100, 1500, n)
    zf = rng.uniform(0.05, 0.95, n) * L
    xmax = np.sqrt(np.maximum(L * L - zf * zf, 1.0))
    regime = np.arange(n) % 4
    u = rng.uniform(size=n)
    xf = np.select([regime == 0, regime == 1, regime == 2],
                   [(0.3 + 0.69 * u) * xmax, (0.99 + 0.02 * u) * xmax, 0.3 * u * xmax],
                   (0.7 + 0.299 * u) * (L - zf))
    w = rng.uniform(50, 5000, n)
    ea = 10 ** rng.uniform(7, 10, n)
    cb = np.array([0.0, 0.5, 1.0, 0.0])[rng.integers(4, size=n)]
    seabed = rng.uniform(size=n) >= 0.2
    return xf, zf, L, ea, w, cb, seabed


FIELDS = ("HF", "VF", "HA", "VA", "grounded_length")


def test_batch_equals_scalar_bit_for_bit():
    """Every element is the scalar call's answer to the last bit (same kernel, same inputs)."""
    xf, zf, L, ea, w, cb, seabed = spread(400)
    b = catenary(xf, zf, L, ea, w, cb, seabed=seabed)
    assert isinstance(b, CatenaryBatch) and b.shape == (400,)
    assert b.ok.all()
    for i in range(400):
        r = catenary(float(xf[i]), float(zf[i]), float(L[i]), float(ea[i]), float(w[i]),
                     float(cb[i]), seabed=bool(seabed[i]))
        for f in FIELDS:
            assert getattr(b, f)[i] == getattr(r, f), (i, f)
        assert np.array_equal(b.stiffness[i], r.stiffness)
        assert b.iterations[i] == r.iterations
        assert b.fairlead_tension[i] == r.fairlead_tension
        assert b.anchor_tension[i] == r.anchor_tension


def test_warm_start_per_element_equals_scalar():
    xf = np.array([848.0, 849.0, 850.0])
    r0 = catenary(848.67, 250.0, 902.2, 384.243e6, 698.09)
    b = catenary(xf, 250.0, 902.2, 384.243e6, 698.09, hf0=r0.HF, vf0=r0.VF)
    for i, x in enumerate(xf):
        r = catenary(float(x), 250.0, 902.2, 384.243e6, 698.09, hf0=r0.HF, vf0=r0.VF)
        assert (b.HF[i], b.VF[i], b.iterations[i]) == (r.HF, r.VF, r.iterations)


def test_scalar_inputs_keep_the_scalar_result():
    r = catenary(848.67, 250.0, 902.2, 384.243e6, 698.09, np.float64(0.1))
    assert isinstance(r, CatenaryResult) and isinstance(r.HF, float)
    r0d = catenary(np.array(848.67), 250.0, 902.2, 384.243e6, 698.09, 0.1)
    assert isinstance(r0d, CatenaryResult) and r0d.HF == r.HF
    # catenary_batch itself always returns arrays, here of shape ()
    b = catenary_batch(848.67, 250.0, 902.2, 384.243e6, 698.09, 0.1)
    assert b.shape == () and b.HF == r.HF and np.array_equal(b.stiffness, r.stiffness)


def test_broadcasting_shapes_and_values():
    """A design chart: line length down the rows, fairlead offset across the columns; each
    element equals the 1-D batch of the same inputs."""
    L = np.linspace(880.0, 960.0, 5)[:, None]
    x = np.linspace(800.0, 870.0, 8)[None, :]
    b = catenary(x, 250.0, L, 384.243e6, 698.09, 0.5)
    assert b.shape == (5, 8)
    assert b.HF.shape == b.VF.shape == b.status.shape == (5, 8)
    assert b.stiffness.shape == (5, 8, 2, 2)
    assert b.inputs["length"].shape == (5, 8)
    row = catenary(x[0], 250.0, float(L[3, 0]), 384.243e6, 698.09, 0.5)
    assert np.array_equal(b.HF[3], row.HF) and np.array_equal(b.stiffness[3], row.stiffness)
    # physics of the chart: more offset or shorter line -> more horizontal tension
    assert np.all(np.diff(b.HF, axis=1) > 0) and np.all(np.diff(b.HF, axis=0) < 0)
    # seabed as an array broadcasts too; a length-1 array is a batch of one
    s = catenary(500.0, 100.0, 700.0, 1e9, 1500.0, seabed=np.array([True, False]))
    assert s.grounded_length[0] > 0 and s.grounded_length[1] == 0 and s.VA[1] < 0
    one = catenary(np.array([848.67]), 250.0, 902.2, 384.243e6, 698.09)
    assert one.shape == (1,)
    one.result(0).profile(11)  # a one-element result gives the scalar object and its profile


def test_bad_shapes_and_values_name_the_argument_and_index():
    with pytest.raises(ValueError, match=r"do not broadcast.*xf \(3,\).*length \(4,\)"):
        catenary(np.ones(3), 1.0, np.full(4, 10.0), 1e8, 100.0)
    with pytest.raises(ValueError, match=r"length must be > 0: 1 of 3 .* index \(1,\): length=-5.0"):
        catenary(np.array([10.0, 11.0, 12.0]), 1.0, np.array([20.0, -5.0, 20.0]), 1e8, 100.0)
    with pytest.raises(ValueError, match=r"xf must be >= 0.*index \(0, 1\)"):
        catenary(np.array([[1.0, -1.0]]), 1.0, 20.0, 1e8, 100.0)
    with pytest.raises(ValueError, match=r"w must be finite"):
        catenary(np.array([10.0, 11.0]), 1.0, 20.0, 1e8, np.array([100.0, np.nan]))
    with pytest.raises(ValueError, match=r"zf must be >= 0 where seabed"):
        catenary(np.array([10.0, 11.0]), -1.0, 20.0, 1e8, 100.0, seabed=np.array([False, True]))
    with pytest.raises(ValueError, match=r"seabed must be a bool"):
        catenary(np.array([10.0]), 1.0, 20.0, 1e8, 100.0, seabed=np.array([1]))
    with pytest.raises(ValueError, match=r"ea must be a real number"):
        catenary(np.array([10.0]), 1.0, 20.0, "1e8", 100.0)
    # the fairlead below the anchor is fine for a line in the water column
    r = catenary(np.array([10.0]), -1.0, 20.0, 1e8, 100.0, seabed=False)
    assert r.ok.all()


def test_failed_elements_are_nan_with_status_and_check_raises():
    """A NaN warm start makes that element fail (as the scalar call raises for it); the others
    are solved, the failed one is NaN with its status; check() names its index."""
    hf0 = np.array([0.0, 1.0, 0.0])
    vf0 = np.array([0.0, np.nan, 0.0])
    b = catenary(np.array([300.0, 300.0, 310.0]), 50.0, 400.0, 1e8, 100.0, hf0=hf0, vf0=vf0)
    assert b.ok.tolist() == [True, False, True]
    assert b.status[1] in STATUS_MESSAGES and b.status[1] != 0
    assert np.isnan(b.HF[1]) and np.isnan(b.stiffness[1]).all() and b.iterations[1] == -1
    assert b.HF[0] == catenary(300.0, 50.0, 400.0, 1e8, 100.0).HF
    with pytest.raises(ConvergenceError, match=r"element \(1,\) \(1 of 3 failed\).*xf=300.0"):
        b.check()
    with pytest.raises(ConvergenceError):
        b.result(1)
    with pytest.raises(ConvergenceError):  # the scalar call of that element raises
        catenary(300.0, 50.0, 400.0, 1e8, 100.0, hf0=1.0, vf0=float("nan"))
    assert catenary(np.array([300.0]), 50.0, 400.0, 1e8, 100.0).check().ok.all()


def test_batch_against_moorpy_sample():
    """MoorPy's catenary() (Hall et al., NREL; FAST v7 formulation) on a sample of the spread:
    end forces within 0.1 % of the fairlead tension (its Tol = 1e-10 here); the shapes MoorPy
    returns below the seabed (see test_catenary) are left out and counted."""
    mp = pytest.importorskip("moorpy.Catenary")
    xf, zf, L, ea, w, cb, seabed = spread(200, seed=3)
    b = catenary(xf, zf, L, ea, w, cb, seabed=seabed).check()
    worst, compared = 0.0, 0
    for i in range(200):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fAH, fAV, _, _, info = mp.catenary(xf[i], zf[i], L[i], ea[i], w[i],
                                               CB=cb[i] if seabed[i] else -1e9, Tol=1e-10,
                                               MaxIter=200)
        if seabed[i] and fAV < -1e-6 * math.hypot(fAH, fAV):
            continue
        err = max(abs(b.HF[i] - info["HF"]), abs(b.VF[i] - info["VF"]),
                  abs(b.HA[i] - abs(fAH)), abs(b.VA[i] - fAV)) / b.fairlead_tension[i]
        worst = max(worst, err)
        compared += 1
    assert compared >= 190
    assert worst < 1e-3


def test_batch_runs_without_jit():
    """The batch loop also runs as plain Python (NUMBA_DISABLE_JIT=1)."""
    import os
    import subprocess
    import sys
    code = ("import numpy as np; from floatmoor.mooring import catenary; "
            "r = catenary(np.array([800.0, 848.67]), 250.0, 902.2, 384.243e6, 698.09, 0.001); "
            "print(repr(r.HF.tolist()))")
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         check=True)
    hf = eval(out.stdout.strip())
    ref = catenary(np.array([800.0, 848.67]), 250.0, 902.2, 384.243e6, 698.09, 0.001).HF
    np.testing.assert_allclose(hf, ref, rtol=1e-12)
