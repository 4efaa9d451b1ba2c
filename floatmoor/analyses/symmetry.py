"""Symmetry check of a scene: lines that are mirror images in a symmetric scene must carry
mirror-image tensions.

A scene whose waves, wind and current all travel along one heading (or its opposite) is
symmetric about the vertical plane through the origin along that heading, as far as its
inputs go; two mooring lines whose anchors and fairleads are mirror images about that plane
and whose segments are the same are then mirror images, and so must be their tensions, to
round-off, in any run.  A difference beyond round-off means that something breaks the symmetry
where the user did not expect it (a hull database or a mass matrix that is not symmetric, a
mistyped coordinate) or that the solution itself is wrong: the finite-element lines of the
Floatel-like flagship once drifted apart by 8 % after a snap load because their time steps
created energy (:mod:`floatmoor.mooring.fe.selfcheck`).

:func:`mirror_pairs` finds the pairs, :func:`symmetry_check` compares them over a short run
(``floatmoor check``).  Over a whole storm the tensions of mirror lines can drift apart from
round-off differences of the body motion when a slack line snaps taut on a frictionless seabed
(a 1e-12 m difference grows to 1e4 N in one snap, at any time step: the dynamics of a slack
chain are that sensitive), so the check uses a short run, before any such event.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["symmetry_plane", "mirror_pairs", "symmetry_check", "SYMMETRY_RTOL"]

SYMMETRY_RTOL = 1e-6
"""Largest difference of mirror lines' tensions over the run, relative to the largest tension,
counted as round-off."""

_TOL_M = 1e-6   # m: coordinates equal


def symmetry_plane(environment) -> float | None:
    """Heading (rad) of the vertical symmetry plane of an environment through the origin: the
    common heading of its waves (every wave system), wind and current (opposite headings share
    a plane), or None when they do not share one.  A calm environment (none of the three) gives 0 (x-z plane):
    every plane through the origin is then a symmetry plane of the loads."""
    heads = []
    for part in ("waves", "wind", "current", "wave_systems"):
        c = getattr(environment, part, None)
        for item in (c if isinstance(c, (list, tuple)) else [c]):
            h = getattr(item, "heading", None)
            if h is not None:
                heads.append(float(h) % math.pi)
    if not heads:
        return 0.0
    h0 = heads[0]
    for h in heads[1:]:
        d = abs(h - h0) % math.pi
        if min(d, math.pi - d) > 1e-9:
            return None
    return h0


def _mirror(p, heading):
    """Mirror image of the point ``p`` (3,) about the vertical plane along ``heading``."""
    c, s = math.cos(2.0 * heading), math.sin(2.0 * heading)
    x, y, z = (float(v) for v in p)
    return np.array([c * x + s * y, s * x - c * y, z])


def mirror_pairs(system, heading: float) -> list[tuple[str, str]]:
    """Pairs of lines of a :class:`~floatmoor.mooring.MooringSystem` that are mirror images of
    each other about the vertical plane through the origin along ``heading`` (rad): anchor and
    fairlead mirrored within 1 um, the same segments (type, length, weight, stiffness, point
    loads) and friction.  A line that is its own mirror image is left out."""
    pairs = []
    used = set()
    for i, a in enumerate(system.lines):
        if a.name in used:
            continue
        ma = _mirror(a.anchor, heading)
        mf = _mirror(a.fairlead, heading)
        for b in system.lines[i + 1:]:
            if b.name in used:
                continue
            if (np.allclose(ma, b.anchor, atol=_TOL_M, rtol=0)
                    and np.allclose(mf, b.fairlead, atol=_TOL_M, rtol=0)
                    and a.segments == b.segments and a.cb == b.cb
                    and a.anchor_on_seabed == b.anchor_on_seabed):
                pairs.append((a.name, b.name))
                used.update((a.name, b.name))
                break
    return pairs


def symmetry_check(built, *, duration: float = 200.0, seed: int | None = None) -> dict:
    """Run a short storm of a built scene and compare the fairlead tensions of its mirror
    lines (:func:`mirror_pairs` about the environment's plane, :func:`symmetry_plane`).

    Returns ``{"plane_deg", "pairs", "differences" (largest relative difference per pair),
    "duration", "ok"}``; ``pairs`` empty (and ``ok`` True) when the scene has no symmetric
    environment or no mirror lines (``reason`` says which)."""
    from .simulate import simulate

    sc = built.scene
    out = {"plane_deg": None, "pairs": [], "differences": [], "duration": 0.0, "ok": True,
           "reason": ""}
    if built.mooring is None:
        out["reason"] = "no mooring"
        return out
    h = symmetry_plane(sc.environment)
    if h is None:
        out["reason"] = "waves, wind and current do not share a heading"
        return out
    active = [n for n, a in zip(built.mooring.names, built.mooring.active) if a] \
        if hasattr(built.mooring, "active") else list(built.mooring.names)
    pairs = [(a, b) for a, b in mirror_pairs(built.mooring, h) if a in active and b in active]
    out["plane_deg"] = math.degrees(h)
    if not pairs:
        out["reason"] = "no mirror-image lines"
        return out
    an = sc.analysis
    dur = min(float(duration) + an.ramp, an.duration)
    import warnings

    from ..core.errors import FloatmoorWarning
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FloatmoorWarning)
        ds = simulate(built, seed=seed, duration=dur)
    T = ds.line_tension
    names = [str(n) for n in ds.line.values]
    tmax = float(np.nanmax(np.abs(T.values)))
    diffs = []
    for a, b in pairs:
        d = np.abs(T.values[:, names.index(a)] - T.values[:, names.index(b)])
        diffs.append(float(np.nanmax(d)) / tmax if tmax > 0 else 0.0)
    out.update(pairs=pairs, differences=diffs, duration=dur,
               ok=all(d <= SYMMETRY_RTOL for d in diffs))
    return out
