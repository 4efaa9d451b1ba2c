"""FE lines as SIMD lanes (:mod:`floatmoor.mooring.fe.lanes`) against the line-by-line kernel.

Expected: every lane bit for bit the line it holds, advanced alone by
:func:`~floatmoor.mooring.fe.kernels.ga_advance` with the same fairlead motion (the lanes do
the same arithmetic, operation for operation): fairlead forces of every step, element tensions,
the final states (positions, velocities, accelerations, forces, friction and fibre state), the
Newton iterations and halvings, and the energy audit (whose start energy the lanes, like the
line kernel, take from the previous advance).  Cases: a grounded chain's slack snap
(halvings by the energy audit and by Newton), seabed friction (three models), bending, a fibre
rope (two-component law), current, the force-stop iteration; lanes of one block with
different motions, and a block with dummy lanes.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from floatmoor.mooring.fe import FELine, Friction
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.lanes import LW, accepted_rows, build_group, store_states
from floatmoor.mooring.fe.lanes_advance import accept, block_advance

from .conftest import oc3_spec
from .test_bending import _beam
from .test_fibre_fe import _taut
from .test_selfcheck import SNAP, _grounded_chain


def _harmonic(amp, period, phase=0.0):
    w = 2.0 * math.pi / period

    def motion(t):
        s = min(t / period, 1.0)          # one period of ramp
        ds = 1.0 / period if t < period else 0.0
        a = np.asarray(amp, float)
        return (s * a * math.sin(w * t + phase),
                a * (ds * math.sin(w * t + phase) + s * w * math.cos(w * t + phase)))
    return motion


def _snap(t):
    d, v = SNAP(t)
    return np.asarray(d, float) - np.array([1.5, 0.0, 0.0]), np.asarray(v, float)


def _run_lines(lines, motions, dt, steps):
    """Each line alone: ga_advance and accept_trial, as the multi-line kernels do."""
    r0 = [ln.r[-1].copy() for ln in lines]
    F = np.zeros((steps, len(lines), 3))
    T = np.zeros((steps, len(lines), lines[0].n_nodes - 1))
    its = np.zeros((len(lines), 2))
    for k in range(1, steps + 1):
        t = k * dt
        for i, ln in enumerate(lines):
            b = ln.bundle
            d, v = motions[i](t)
            b.work.stats[:] = 0.0
            st = K.ga_advance(t, dt, 1, ln.MAX_SPLIT, np.ascontiguousarray(r0[i] + d),
                              np.ascontiguousarray(v), b.now, b.trial, b.step, b.par, b.work)
            assert st == 0, (k, i, st)
            its[i] += b.work.stats
            K.accept_trial(b)
            F[k - 1, i] = b.now.f[-1]
            T[k - 1, i] = b.work.tens
    return F, T, its


def _run_lanes(lines, motions, dt, steps):
    """The same lines as lanes of one group, block by block."""
    bl = [ln.bundle for ln in lines]
    g = build_group([b.par for b in bl], [b.now for b in bl])
    nl = len(lines)
    n = lines[0].n_nodes
    nb = g.state0.r.shape[0]
    on = np.zeros(nb * LW, dtype=np.bool_)
    on[:nl] = True
    r0 = [ln.r[-1].copy() for ln in lines]
    F = np.zeros((steps, nl, 3))
    T = np.zeros((steps, nl, n - 1))
    fair = g.work.fair
    for k in range(1, steps + 1):
        t = k * dt
        for p in range(nb * LW):
            i = p if p < nl else (p // LW) * LW
            d, v = motions[i](t)
            for c in range(3):
                fair[p // LW, (9 + c) * LW + p % LW] = r0[i][c] + d[c]
                fair[p // LW, (12 + c) * LW + p % LW] = v[c]
        for b in range(nb):
            block_advance(b, n, t, dt, 1, FELine.MAX_SPLIT, g, on)
        assert not (g.work.status[:nl] < 0).any(), (k, g.work.status)
        for b in range(nb):
            accept(b, n, g, on)
        f = accepted_rows(g, "f").reshape(nb, n, 3, LW)
        tens = g.work.tens.reshape(nb, n - 1, LW)
        for p in range(nl):
            F[k - 1, p] = f[p // LW, n - 1, :, p % LW]
            T[k - 1, p] = tens[p // LW, :, p % LW]
    # the advances after the first started from the energy their predecessors stored
    assert (g.work.eacc.reshape(nb, 5, LW)[:, 0, :].ravel()[:nl] == 1.0).all()
    states = {}
    for name, kk in (("r", 3), ("v", 3), ("a", 3), ("f", 3), ("fs", K.N_FS)):
        x = accepted_rows(g, name).reshape(nb, n, kk, LW)
        states[name] = [x[p // LW, :, :, p % LW] for p in range(nl)]
    # the accepted states as store_states copies them out (each block's accepted buffer:
    # after an odd number of steps the second one)
    assert set(g.cur.tolist()) == {steps % 2}
    out = [type(ln.bundle.now)(*[np.full_like(a, np.nan) for a in ln.bundle.now]) for ln in lines]
    store_states(g, out)
    for name in ("r", "v", "a", "f", "fs"):
        for i in range(nl):
            np.testing.assert_array_equal(getattr(out[i], name), states[name][i])
    return F, T, g.work.stats[:nl].copy(), states, g.work.audit[:nl].copy()


def _compare(make, motions, dt, steps):
    a = make()
    Fa, Ta, its_a = _run_lines(a, motions, dt, steps)
    b = make()
    Fb, Tb, its_b, states, audit = _run_lanes(b, motions, dt, steps)
    np.testing.assert_array_equal(Fb, Fa)
    np.testing.assert_array_equal(Tb, Ta)
    np.testing.assert_array_equal(its_b, its_a)
    for i, ln in enumerate(a):
        for name, attr in (("r", "r"), ("v", "v"), ("a", "a"), ("f", "fn"), ("fs", "fs")):
            np.testing.assert_array_equal(states[name][i], getattr(ln, attr), err_msg=name)
        np.testing.assert_array_equal(audit[i], ln.work.audit)
    return a, its_a


def _started(line, **kw):
    line.solve_static()
    line.start(**kw)
    return line


def test_slack_snap_with_audit_halvings():
    def make():
        return [_grounded_chain() for _ in range(2)]
    lines, its = _compare(make, [_snap, _harmonic((-1.0, 0.5, 0.0), 8.0)], 0.1, 300)
    assert lines[0].work.audit[K.AU_SPLITS] > 0        # the audit halved steps here
    assert its[0, 1] > 0


@pytest.mark.parametrize("model", ["velocity_ramp", "displacement_velocity_ramp",
                                   "velocity_ramp_double_quadratic"])
def test_seabed_friction(model):
    fr = Friction(model=model, mu_axial=0.7, mu_lateral=1.0)

    def make():
        return [_started(FELine(oc3_spec(n=20, friction=fr))) for _ in range(3)]
    motions = [_harmonic((-3.0, 0.0, 0.0), 15.0), _harmonic((2.0, 3.0, 0.0), 11.0),
               _harmonic((0.0, -4.0, 1.0), 9.0)]
    _compare(make, motions, 0.2, 150)


def test_bending():
    def make():
        return [_started(_beam(n=20, drag=True)) for _ in range(2)]
    _compare(make, [_harmonic((0.0, 0.0, 1.0), 6.0), _harmonic((-0.2, 0.5, 0.0), 8.0)], 0.05, 200)


def test_fibre_rope():
    def make():
        return [_started(_taut(0.01, n=10)) for _ in range(2)]
    _compare(make, [_harmonic((1.0, 0.0, 0.0), 10.0), _harmonic((0.5, 0.0, 0.5), 7.0)], 0.1, 200)


@pytest.mark.parametrize("newton", ["exact", "force"])
def test_current_and_newton_modes(newton):
    spec = oc3_spec(n=20, current_z=(-320.0, 0.0), current_speed=(0.3, 1.2),
                    current_heading=0.7)

    def make():
        return [_started(FELine(spec), newton=newton) for _ in range(5)]   # two blocks
    motions = [_harmonic((-3.0 + i, 1.0 * i, 0.5), 10.0 + i) for i in range(5)]
    _compare(make, motions, 0.1, 200)


# a current profile of uneven levels that the suspended nodes cross as the fairlead heaves
LEVELS = (-320.0, -300.0, -262.0, -200.0, -151.0, -110.0, -86.0, -71.5, -69.0, -40.0, 0.0)
SPEEDS = (0.1, 0.15, 0.3, 0.28, 0.5, 0.61, 0.7, 0.9, 0.95, 1.1, 1.3)


def test_current_of_many_levels():
    """Lanes against lines with a current of eleven uneven levels: the lanes' look-up from each
    node's last interval (lanes_forces.current_lookup) gives the line kernel's numbers."""
    spec = oc3_spec(n=20, current_z=LEVELS, current_speed=SPEEDS, current_heading=0.3)

    def make():
        return [_started(FELine(spec)) for _ in range(3)]
    motions = [_harmonic((1.0 + i, 0.5 * i, 2.5 + i), 8.0 + i) for i in range(3)]
    _compare(make, motions, 0.1, 150)


def test_current_lookup_against_the_scalar_lookup():
    """lanes_forces.current_lookup + current_fix against fluid._current (the line kernel's
    look-up) lane by lane, bit for bit: profiles of eleven, two, one and no levels; levels on
    the profile's levels, outside it, NaN; the second call from the first call's intervals
    (nodes moved a little: most found in their last interval, the memo path) and the third
    after a jump (every node misses)."""
    from floatmoor.mooring.fe.fluid import _current, _current_scale
    from floatmoor.mooring.fe.lanes_forces import current_fix, current_lookup

    profiles = [(LEVELS, SPEEDS), ((-320.0, 0.0), (0.3, 1.2)), ((-50.0,), (0.4,)), ((), ())]
    lines = [_started(FELine(oc3_spec(n=20, current_z=z, current_speed=u))) for z, u in profiles]
    g = build_group([ln.bundle.par for ln in lines], [ln.bundle.now for ln in lines])
    n = lines[0].n_nodes
    rng = np.random.default_rng(7)
    z = rng.uniform(-335.0, 5.0, (n, LW))
    z[:11, 0] = LEVELS                       # exactly on the levels
    z[11, :] = np.nan
    z[12, :] = -320.0
    r = np.zeros((1, n * 3 * LW))
    rv = r.reshape(1, n, 3, LW)
    w = g.work
    li = np.zeros_like(w.li)                 # every lane running (live)
    misses = []
    for step in (None, 1e-3, 60.0):
        if step is not None:
            z = z + rng.uniform(-step, step, z.shape)
        rv[0, :, 2, :] = z
        current_lookup(0, n, r, g.par.cur_c, w.cmemo, w.uc, li, w.cmiss)
        misses.append(w.cmiss[0].copy())
        current_fix(0, n, r, g.par.cur_z, g.par.cur_u, g.par.cur_n, g.par.cur_c, w.cmemo, w.uc,
                    li, w.cmiss)
        uc = w.uc.reshape(1, n, LW)[0]
        for l, (cz, cu) in enumerate(profiles):
            cz = np.asarray(cz, float)
            cu = np.asarray(cu, float)
            sc = _current_scale(cz)
            want = np.array([_current(z[i, l], cz, cu, sc) for i in range(n)])
            np.testing.assert_array_equal(uc[:, l], want)
    # first call: every node inside the eleven- and two-level profiles misses (NaN memo), a
    # NaN level misses in every lane; second: only few of them (the memo path ran)
    assert misses[0][0] > 10 and misses[0][1] > 10
    assert misses[1][0] < misses[0][0] / 2 and misses[1][1] <= 2
    assert misses[2][0] > misses[1][0]
