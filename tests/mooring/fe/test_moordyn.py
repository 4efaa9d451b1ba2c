"""OC3 line under harmonic fairlead motion against MoorDyn (PyPI ``moordyn``, MoorDyn-C v2,
explicit RK2 at dtM = 1 ms) with the same line: 20 segments, Cd 1.6, Ca 1.0, CdAx 0.1 (on pi d),
CaAx 0, seabed kBot 3e6 Pa/m and cBot 3e5 Pa s/m, internal damping BA given explicitly in N s
(0.8 of the critical damping of one element's axial mode, our ``-0.8``).  MoorDyn computes the
line weight with g = 9.81 (its log prints w = 698.333 N/m), so our line uses g = 9.81 here.

Measured (floatmoor generalised-alpha, dt = 0.05 s; last period of four): mean tension
+0.032 / +0.035 / +0.023 / +0.006 %, tension range +1.42 / +1.35 / +0.33 / +0.49 % (sway 1 m 5 s,
sway 3 m 15 s, surge 3 m 15 s, heave 1.5 m 7 s; the sway ranges are small: 2.2 and 3.0 kN)."""

import math

import numpy as np
import pytest

from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import oc3_spec

moordyn = pytest.importorskip("moordyn")

N_SEG = 20
BA = 0.8 * 2.0 * math.sqrt(384.243e6 * 77.7066) * 902.2 / N_SEG

CASES = [((0.0, 1.0, 0.0), 5.0), ((0.0, 3.0, 0.0), 15.0), ((-3.0, 0.0, 0.0), 15.0),
         ((0.0, 0.0, 1.5), 7.0)]


@pytest.mark.parametrize("amp,period", CASES, ids=["sway1m5s", "sway3m15s", "surge3m15s",
                                                    "heave1.5m7s"])
def test_harmonic_fairlead_motion_against_moordyn(amp, period):
    from .moordyn_ref import run_moordyn
    m = HarmonicMotion(amplitude=amp, period=period, ramp=period)
    t_end = 4.0 * period
    t_md, F_md = run_moordyn(m, t_end, 0.05, nseg=N_SEG, ba=BA)
    T_md = np.linalg.norm(F_md, axis=1)[t_md > t_end - period + 1e-9]
    spec = oc3_spec(n=N_SEG, damping=BA)
    spec = type(spec)(**{**spec.__dict__, "gravity": 9.81})
    line = FELine(spec)
    line.solve_static()
    line.start()
    ds = run_prescribed(line, m, t_end, 0.05)
    T = ds.fairlead_tension.values[ds.time.values > t_end - period + 1e-9]
    assert T.mean() == pytest.approx(T_md.mean(), rel=5e-3)
    assert np.ptp(T) == pytest.approx(np.ptp(T_md), rel=5e-2)
