"""Wave kinematics option: the particle velocity enters the drag exactly like a current, the
particle acceleration gives the Morison inertia (rho V l)(1 + Ca) a normal to the line; a
regular wave run against the same run without waves."""

import math

import numpy as np
import pytest

from floatmoor.metocean.kinematics import wavenumber
from floatmoor.metocean.realisation import WaveRealisation
from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.bundles import new_work
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import OC3, oc3_spec


def _forces(line, r, v, wk):
    n = line.n_nodes
    f = np.zeros((n, 3))
    K.line_forces(r, v, line.fs, line.params(fric=0, wk=wk), False, 0.0, 0.0, f, new_work(n))
    return f


def test_wave_velocity_acts_like_a_current_and_acceleration_gives_morison_inertia():
    u = 0.4
    cur = FELine(oc3_spec(n=20, current_z=(-400.0, 10.0), current_speed=(u, u),
                          current_heading=math.pi / 2))
    line = FELine(oc3_spec(n=20))
    line.solve_static()
    r = line.r.copy()
    v = np.zeros_like(r)
    wk = np.zeros((line.n_nodes, 6))
    wk[:, 1] = u
    assert np.allclose(_forces(line, r, v, wk), _forces(cur, r, v, np.zeros_like(wk)),
                       rtol=1e-12, atol=1e-9)
    # acceleration along y (normal to the line plane): (rho V l)(1 + Ca) a at an interior node
    a = 0.3
    wk[:] = 0.0
    wk[:, 4] = a
    df = _forces(line, r, v, wk) - _forces(line, r, v, 0 * wk)
    le = OC3["length"] / 20
    m_disp = 1025.0 * math.pi * 0.09 ** 2 / 4 * le
    assert df[10, 1] == pytest.approx(m_disp * (1.0 + 1.0) * a, rel=1e-12)


def test_regular_wave_adds_wave_frequency_tension():
    """A regular wave (amplitude 4 m, 15 s) along the line, fairlead fixed at 70 m depth: the
    fairlead tension varies at the wave period (drag and inertia on the upper line, where the
    particle velocity is still ~0.5 m/s); zero-amplitude waves change nothing."""
    w = 2 * math.pi / 15.0
    k = wavenumber(np.array([w]), 320.0)
    res = {}
    for amp in (0.0, 4.0):
        wav = WaveRealisation(omega=np.array([w]), amplitude=np.array([amp]),
                              phase=np.zeros(1), direction=np.zeros(1), k=k, water_depth=320.0,
                              domega=0.01)
        line = FELine(oc3_spec(n=30), waves=wav)
        line.solve_static()
        line.start()
        ds = run_prescribed(line, HarmonicMotion(amplitude=(0, 0, 0), period=15.0), 60.0, 0.1)
        T = ds.fairlead_tension.values[ds.time.values > 30.0]
        res[amp] = T
    assert np.ptp(res[0.0]) < 1.0
    assert np.ptp(res[4.0]) > 100.0
    spec = np.abs(np.fft.rfft(res[4.0] - res[4.0].mean()))
    f = np.fft.rfftfreq(res[4.0].size, 0.1)
    assert f[np.argmax(spec)] == pytest.approx(1 / 15.0, abs=0.01)
