"""The time-domain kernel called directly on hand-built bundles (no scene): a damped linear
oscillator against its closed form, the per-term force record, and the named status codes."""

from __future__ import annotations

import math

import numpy as np

from floatmoor.forces.base import KernelAssembly
from floatmoor.solvers.td_bundles import Body, new_outputs, no_lines
from floatmoor.solvers.td_kernel import STATUS_GUARD, STATUS_NAMES, STATUS_OK, td_kernel

M, K, B = 2.0e6, 8.0e5, 1.6e5  # heave mass (kg), stiffness (N/m), damping (N s/m)


def _run(n_steps, dt, guard=1e3):
    asm = KernelAssembly(n_samples=2 * n_steps + 1, sample_dt=0.5 * dt)
    C = np.zeros((6, 6))
    D = np.zeros((6, 6))
    C[2, 2] = K
    D[2, 2] = B
    asm.add_restoring("spring", np.zeros(6), C)
    asm.add_damping("dashpot", D)
    inertia = np.eye(6) * M
    x0 = np.array([0.0, 0.0, 1.0, 0.0, 0.0, 0.0])
    body = Body(n_steps, dt, inertia, np.linalg.inv(inertia), x0, np.zeros(6),
                np.array([1e3, 1e3, guard, 1.0, 1.0, 1.0]), 10.0, True)
    out = new_outputs(n_steps, 0, len(asm.part_names), record_parts=True)
    td_kernel(body, asm.force_terms(), no_lines(), out)
    return asm, out


def _closed_form(t):
    """Free decay from x = 1 at rest: x = exp(-z w t) (cos wd t + z w / wd sin wd t)."""
    w = math.sqrt(K / M)
    z = B / (2.0 * math.sqrt(K * M))
    wd = w * math.sqrt(1.0 - z * z)
    return np.exp(-z * w * t) * (np.cos(wd * t) + z * w / wd * np.sin(wd * t))


def test_damped_oscillator_against_closed_form():
    dt, n = 0.05, 1200
    asm, out = _run(n, dt)
    assert out.status[0] == STATUS_OK
    t = np.arange(n + 1) * dt
    # RK4 at w dt = 0.03: global error ~ (w dt)^4 w t, far below 1e-6
    np.testing.assert_allclose(out.motion[:, 2], _closed_form(t), atol=1e-7)
    # the record holds one row per term, in kind order, with the force of that term
    assert asm.part_names == ["spring", "dashpot"]
    np.testing.assert_allclose(out.parts[:, 0, 2], -K * out.motion[:, 2], rtol=1e-12)
    np.testing.assert_allclose(out.parts[:, 1, 2], -B * out.velocity[:, 2], rtol=1e-12,
                               atol=1e-9)


def test_guard_status_names_step_and_dof():
    """The heave guard |x - x0| <= 0.5 m is first exceeded where the closed form drops below
    0.5: the kernel stops there with STATUS_GUARD, the step and the DOF."""
    dt, n = 0.05, 1200
    _, out = _run(n, dt, guard=0.5)
    t = np.arange(n + 1) * dt
    first = int(np.argmax(_closed_form(t) < 0.5))
    assert STATUS_NAMES[int(out.status[0])] == "guard" and out.status[0] == STATUS_GUARD
    assert out.status[1] == first and out.status[2] == 2
