"""The energy audit starts a line's advance from the energy its previous advance computed for
the state it ended in (``LineWork.energy``) instead of evaluating the accepted state again.

Expected: the same numbers to the bit.  Independent of the reuse: the audit's figures of the
accepted state evaluated from scratch (:func:`~floatmoor.mooring.fe.energy.line_energy` from
the positions, ``geom`` True) and a run that forgets the stored figures before every step.  The
case is the slack snap of the self-check tests (a grounded chain pulled slack and snapped taut
at 0.1 s steps: steps halved by the audit, sub-steps of several sizes), with the default and
the force-stop iterations; the coupled flagship's digests (tests/test_bit_identity.py) cover
the multi-line kernels.
"""

from __future__ import annotations

import numpy as np
import pytest

from floatmoor.mooring.fe import kernels as K

from .test_selfcheck import SNAP, _grounded_chain


def _run(newton, forget, steps=300, dt=0.1):
    line = _grounded_chain()
    line.start(newton=newton)
    rows = []
    for k in range(1, steps + 1):
        t = k * dt
        d, vel = SNAP(t)
        rf = np.array([line.spec.fairlead[0] + d[0] - 1.5, d[1], line.spec.fairlead[2] + d[2]])
        if forget:
            line.work.energy[:] = 0.0
        F = line.step(t, dt, rf, np.asarray(vel, float))
        rows.append(np.concatenate([F, line.work.tens]))
    return line, np.array(rows)


@pytest.mark.parametrize("newton", ["exact", "force"])
def test_reused_energy_is_the_accepted_states_own(newton):
    line, rows = _run(newton, forget=False)
    au = line.audit
    assert au["energy_halvings"] > 0          # the audit did halve steps in this run
    e = line.work.energy
    assert e[1, 0] == 1.0
    P, E, S = line.P, line.E_dynamic, line.S
    el = np.zeros((line.n_nodes - 1, 4))
    q = np.zeros((line.n_nodes, 3))
    en, pw, bud, wsum, _, _ = K.line_energy(line.r, line.v, line.fn, P, E, S, el, q, True)
    assert (e[1, 1], e[1, 2], e[1, 3], e[1, 4]) == (en, pw, bud, wsum)
    line2, rows2 = _run(newton, forget=True)
    np.testing.assert_array_equal(rows, rows2)
    np.testing.assert_array_equal(line.work.audit, line2.work.audit)
    np.testing.assert_array_equal(line.r, line2.r)


def test_start_forgets_the_stored_energy():
    line, _ = _run("exact", forget=False, steps=5)
    assert line.work.energy[1, 0] == 1.0
    line.start()
    assert not line.work.energy.any()
