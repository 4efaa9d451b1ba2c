"""The line kernel's force evaluation through the vectorised passes of ``mooring/fe/flat.py``
gives the general passes' numbers to the bit.

``forces._line_forces`` takes the flat passes for a line without fibre law, clump drag or wave
accelerations (``forces.flat_kind``).  The reference here is the composition
of the general functions it replaces (``element_geometry``, ``_tangents_from``,
``element_forces``, ``fluid_forces``, ``seabed_forces``), called on copies of the same inputs;
every output (forces, tensions, element directions, node tangents, diagonal and off-diagonal
tangent blocks) must be equal bit for bit.  States: the OC3 line (internal damping, seabed
contact; also in a sheared current oblique to the line) at rest and perturbed at random, with slack elements (an element shortened to a
thousandth), nodes moving both ways through the seabed, wave particle velocities at the nodes,
and without internal damping; with and without the tangent.
"""

import numpy as np
import pytest

from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe.elements import (
    _tangents_from,
    element_forces,
    element_geometry,
)
from floatmoor.mooring.fe.fluid import fluid_forces
from floatmoor.mooring.fe.forces import _line_forces, flat_kind
from floatmoor.mooring.fe.layout import EL_B, NP_KC
from floatmoor.mooring.fe.seabed import seabed_forces

from .conftest import oc3_spec


def _reference(r, v, fs, par, want_jac, cK, cC, w):
    """The general passes of ``_line_forces`` on copies of the work arrays."""
    el = np.zeros_like(w.el)
    q = np.zeros_like(w.q)
    tens = np.zeros_like(w.tens)
    Dg = np.zeros_like(w.Dg)
    Of = np.zeros_like(w.Of)
    f = np.zeros_like(r)
    element_geometry(r, el)
    _tangents_from(el, q)
    element_forces(v, fs, par.P, par.E, par.S, el, want_jac, cK, cC, False, w.act, tens, f,
                   Dg, Of)
    fluid_forces(r, v, q, par.P, par.S, par.cur_z, par.cur_u, par.wk, want_jac, cC, f, Dg)
    seabed_forces(r, v, q, fs, par.P, par.S, par.fric, want_jac, cK, cC, f, Dg)
    return f, tens, el, q, Dg, Of


def _states(line, rng, n_random=60):
    r0 = line.r.copy()
    yield r0, np.zeros_like(r0)
    for k in range(n_random):
        r = r0 + rng.normal(scale=0.05, size=r0.shape)
        v = rng.normal(scale=0.3, size=r0.shape)
        if k % 4 == 1:
            j = 3 + k % 20
            r[j + 1] = r[j] + 1e-3 * (r[j + 1] - r[j])      # a slack element
        if k % 5 == 2:
            v[:, 2] = np.where(np.arange(r.shape[0]) % 2, 0.005, -0.005)  # seabed damping zone
        yield r, v


CURRENT = dict(current_z=(-320.0, -200.0, -100.0, 0.0), current_speed=(0.3, 0.5, 0.8, 1.1),
               current_heading=0.6)


@pytest.mark.parametrize("damping,current", [(-0.8, False), (0.0, False), (-0.8, True)])
def test_flat_passes_are_the_general_passes_bit_for_bit(damping, current):
    line = FELine(oc3_spec(n=40, damping=damping, **(CURRENT if current else {})))
    line.solve_static()
    line.start()
    b = line.bundle
    par, w = b.par, b.work
    # (the flat passes apply to this line; with damping 0 the elements have B = 0)
    assert flat_kind(par.P, par.E, par.wk, par.cur_z) == 3
    assert (par.E[:, EL_B] != 0.0).all() == (damping != 0.0)
    assert not (par.P[:, NP_KC] > 0.0).any()
    rng = np.random.default_rng(7)
    fs = b.now.fs
    for i, (r, v) in enumerate(_states(line, rng)):
        par.wk[:, :3] = rng.normal(scale=0.5, size=(r.shape[0], 3)) if i % 3 == 2 else 0.0
        for want_jac in (True, False):
            ref = _reference(r, v, fs, par, want_jac, 0.0021, 0.043, w)
            f = np.zeros_like(r)
            _line_forces(r, v, fs, par, want_jac, 0.0021, 0.043, f, w, False)
            got = (f, w.tens, w.el, w.q, w.Dg, w.Of)
            names = ("f", "tens", "el", "q", "Dg", "Of") if want_jac else ("f", "tens", "el", "q")
            for name, a, bb in zip(names, ref, got):
                assert np.array_equal(a, bb, equal_nan=True), (i, want_jac, name,
                                                               np.abs(a - bb).max())
    par.wk[:] = 0.0


def test_lines_outside_the_flat_passes_take_the_general_ones():
    """A wave acceleration or a clump weight turns the flat fluid passes off (``flat_kind``):
    the fluid inertia and the clump drag are only in the general pass; an element with a fibre
    law turns the element passes off."""
    line = FELine(oc3_spec(n=20))
    line.solve_static()
    line.start()
    par = line.bundle.par
    assert flat_kind(par.P, par.E, par.wk, par.cur_z) == 3
    wk = par.wk.copy()
    wk[5, 4] = 0.1
    assert flat_kind(par.P, par.E, wk, par.cur_z) == 1
    P = par.P.copy()
    P[3, NP_KC] = 10.0
    assert flat_kind(P, par.E, par.wk, par.cur_z) == 1
    # a current profile is looked up node by node (flat.current_speeds), then the flat drag
    assert flat_kind(par.P, par.E, par.wk, np.array([-320.0, 0.0])) == 3
    from floatmoor.mooring.fe.fibre_law import EL_LAW
    E = par.E.copy()
    E[2, EL_LAW] = 1.0
    assert flat_kind(par.P, E, par.wk, par.cur_z) == 2


def test_flat_energy_terms_sum_to_line_energy_bit_for_bit():
    """The energy audit's vectorised terms (``flat.energy_terms``) summed in the audit's order
    (``flat.energy_sums``) are ``energy.line_energy`` of the state (geometry given), bit for
    bit: the OC3 line perturbed at random, with slack elements and nodes in and out of the
    seabed, with and without internal damping at the fairlead's element."""
    from floatmoor.mooring.fe.energy import line_energy
    from floatmoor.mooring.fe.flat import energy_sums, energy_terms, flat
    from floatmoor.mooring.fe.layout import S_DC, S_ZC

    rng = np.random.default_rng(11)
    for damping in (-0.8, 0.0):
        line = FELine(oc3_spec(n=40, damping=damping))
        line.solve_static()
        line.start()
        b = line.bundle
        par, w = b.par, b.work
        for i, (r, v) in enumerate(_states(line, rng, n_random=40)):
            f = rng.normal(scale=1e4, size=r.shape)
            element_geometry(r, w.el)
            _tangents_from(w.el, w.q)
            ref = line_energy(r, v, f, par.P, par.E, par.S, w.el, w.q, False)
            energy_terms(flat(r), flat(v), flat(f), flat(par.P), flat(par.E), flat(w.el),
                         flat(w.q), par.S[S_ZC], par.S[S_DC], flat(w.ew))
            got = energy_sums(r, v, par.P, par.E, w.el, w.ew)
            assert all(np.array_equal(a, bb) for a, bb in zip(ref, got)), (damping, i, ref, got)


def test_node_tangents_as_the_general_function_also_at_degenerate_elements():
    """``flat.node_tangents`` (interior nodes vectorised, the rest redone node by node) gives
    ``elements._tangents_from`` to the bit, also next to an element of zero length (left out
    of the sum), at two opposite elements (zero sum: the tangent (1, 0, 0)) and next to an
    element with NaN geometry."""
    from floatmoor.mooring.fe.flat import node_tangents

    rng = np.random.default_rng(5)
    n = 12
    for case in range(4):
        el = rng.normal(size=(n - 1, 4))
        el[:, :3] /= np.linalg.norm(el[:, :3], axis=1)[:, None]
        el[:, 3] = rng.uniform(1.0, 20.0, n - 1)
        if case == 1:
            el[4, :] = [np.nan, np.nan, np.nan, 0.0]      # zero length
        if case == 2:
            el[6, :3] = -el[5, :3]                         # opposite: the sum vanishes
        if case == 3:
            el[2, :] = np.nan
        q1 = np.zeros((n, 3))
        q2 = np.zeros((n, 3))
        _tangents_from(el, q1)
        node_tangents(el, q2)
        assert np.array_equal(q1, q2, equal_nan=True), case


def test_flat_view_and_contiguity_without_reference_counting():
    """``flat.flat`` and ``flat.c_contiguous`` in a kernel compiled without reference counting
    (``layout.KERNEL_JIT``, as the FE kernels are): the 1-D view shares the data of a
    C-contiguous array; for an array type of layout 'A' the strides are checked at run time:
    a contiguous one is viewed, a strided one (every other column) is refused with a
    ValueError as numpy's ``reshape`` would have to copy; ``c_contiguous`` agrees with numpy's
    flag on both."""
    from numba import njit

    from floatmoor.mooring.fe.flat import c_contiguous, flat
    from floatmoor.mooring.fe.layout import KERNEL_JIT

    @njit(**KERNEL_JIT)
    def _double_first(a):
        v = flat(a)
        v[0] *= 2.0
        return v.shape[0]

    @njit(**KERNEL_JIT)
    def _contig(a):
        return c_contiguous(a)

    a = np.arange(12.0).reshape(4, 3)
    assert _double_first(a) == 12 and a[0, 0] == 0.0
    a[0, 0] = 1.5
    assert _double_first(a) == 12 and a[0, 0] == 3.0
    assert _contig(a)
    strided = np.arange(24.0).reshape(4, 6)[:, ::2]      # layout 'A', not contiguous
    assert not strided.flags.c_contiguous and not _contig(strided)
    with pytest.raises(ValueError, match="not C-contiguous"):
        _double_first(strided)

    @njit(**KERNEL_JIT)
    def _all_columns(a):
        # a slice of every column: an array type of layout 'A' over contiguous data
        s = a[:, 0:a.shape[1]]
        return c_contiguous(s), flat(s).shape[0], c_contiguous(a[:, 0:1])

    ok, size, part = _all_columns(np.arange(24.0).reshape(4, 6))
    assert ok and size == 24 and not part
