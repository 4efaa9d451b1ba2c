"""FE line specifications from the quasi-static mooring description (``LineDef`` of
:class:`floatmoor.mooring.MooringSystem`, as built by the ``mooring:`` section parser), so a
scene can switch lines to ``model: finite-element`` without a second description.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace

import numpy as np

from ...core.frames import rotation_matrix_into
from ..line_types import STEEL_DENSITY, LineType
from ..system import LineDef, MooringSystem
from .config import FELineSpec, FESegment, Friction, PointBody, Seabed

__all__ = ["spec_from_linedef", "specs_from_system", "MAX_ELEMENTS"]

MAX_ELEMENTS = 20000
"""Largest element count of one FE line (checked before its arrays are allocated; the
flagship's lines have 50-132, a 1 km line at 0.1 m elements 10,000)."""


def spec_from_linedef(line: LineDef, *, water_depth: float, pose=None,
                      element_length: float = 20.0, n_elements: int | None = None,
                      line_types: Mapping[str, LineType] | None = None,
                      friction: Friction | None = None, seabed: Seabed | None = None,
                      internal_damping: float = 0.0, water_density: float = 1025.0,
                      gravity: float = 9.80665, **current) -> FELineSpec:
    """FE specification of one quasi-static line.

    Parameters
    ----------
    line : LineDef
        Anchor (earth), fairlead (body axes), segments from the anchor.
    water_depth : float
        m.
    pose : (6,), optional
        Body pose for the initial fairlead position (default zero).
    element_length : float
        Target element length, m: each segment gets ``max(1, round(L / element_length))``.
    n_elements : int or sequence of int, optional
        Elements of the whole line instead (overrides ``element_length``): shared among the
        segments in proportion to their lengths (largest remainder, at least one each); a
        sequence gives the elements of each segment, anchor to fairlead (a mesh refined where
        the line bends: the flagship's top chain, benchmarks/RESULTS.md "A mesh by segment").
    line_types : mapping, optional
        Line types by name for the hydrodynamic coefficients (``cdn, cdt, can, cat``); a
        segment whose type is missing keeps the ``LineType`` defaults.  Mass, diameter, EA,
        the fibre model and the submerged weight always come from the segment.
    friction : Friction, optional
        Default: no friction when ``line.cb`` is 0, else the velocity ramp with ``cb`` as axial
        and lateral coefficient.
    seabed : Seabed, optional
        Default: MoorDyn-like springs at ``water_depth``.
    internal_damping : float
        Axial damping of every segment (N s, or ``-zeta``).
    **current
        ``current_z``, ``current_speed``, ``current_heading`` passed on to :class:`FELineSpec`.

    Notes
    -----
    A point load ``P`` at a joint becomes a clump of steel (``P > 0``: mass ``P / (g (1 - rho /
    7850))``, volume ``mass / 7850``) or a massless buoy of volume ``-P / (rho g)`` (``P < 0``):
    the submerged weight is exact, the inertia an assumption.
    """
    pose = np.zeros(6) if pose is None else np.asarray(pose, float)
    R = np.zeros((3, 3))
    rotation_matrix_into(pose[3], pose[4], pose[5], R)
    fair = pose[:3] + R @ np.asarray(line.fairlead, float)
    segs = []
    bodies = []
    node = 0
    try:
        counts = element_counts([s.length for s in line.segments],
                                element_length=element_length, n_elements=n_elements)
    except ValueError:
        from ...core.errors import SceneError
        raise SceneError(None, "finite_element.n_elements",
                         f"one element count per segment ({len(line.segments)} for line "
                         f"{line.name!r}, anchor to fairlead)", list(n_elements),
                         "a list of counts applies to every FE line; give one integer "
                         "per line for lines of different segment counts") from None
    n_line = sum(counts)
    if n_line > MAX_ELEMENTS:
        from ...core.errors import SceneError
        raise SceneError(None, "finite_element.element_length" if n_elements is None
                         else "finite_element.n_elements",
                         f"at most {MAX_ELEMENTS:,} elements per line (a line of "
                         f"{sum(s.length for s in line.segments):g} m)",
                         element_length if n_elements is None else
                         (n_elements if np.isscalar(n_elements) else list(n_elements)),
                         f"{n_line:,} elements for line {line.name!r}")
    for k, s in enumerate(line.segments):
        base = (line_types or {}).get(s.line_type)
        mass = (s.mass_per_length if s.mass_per_length > 0
                else (base.mass_per_length if base else 0.0))
        d = s.diameter if s.diameter > 0 else (base.diameter if base else 0.0)
        vol = max(mass - s.w / gravity, 0.0) / water_density
        kw = dict(name=s.line_type or f"{line.name}_seg{k}",
                  material=base.material if base else "user",
                  diameter=d, mass_per_length=mass, displaced_volume=vol, ea=s.ea,
                  ea_dynamic=s.ea_dynamic if s.ea_dynamic else s.ea, mbs=s.mbs,
                  fibre=getattr(s, "fibre", None))
        lt = replace(base, **kw) if base is not None else LineType(**kw)
        n = counts[k]
        segs.append(FESegment(line_type=lt, length=s.length, n_elements=n,
                              internal_damping=internal_damping))
        node += n
        if k < len(line.segments) - 1 and s.point_load != 0.0:
            P = s.point_load
            if P > 0.0:
                m = P / (gravity * (1.0 - water_density / STEEL_DENSITY))
                bodies.append(PointBody(node=node, mass=m, volume=m / STEEL_DENSITY))
            else:
                bodies.append(PointBody(node=node, mass=0.0, volume=-P / (water_density * gravity)))
    if friction is None:
        friction = (Friction(model="velocity_ramp", mu_axial=line.cb, mu_lateral=line.cb)
                    if line.cb > 0 else Friction())
    return FELineSpec(name=line.name, anchor=tuple(map(float, line.anchor)),
                      fairlead=tuple(map(float, fair)), segments=tuple(segs),
                      seabed=seabed or Seabed(depth=water_depth), friction=friction,
                      point_bodies=tuple(bodies), water_density=water_density, gravity=gravity,
                      **current)


def element_counts(lengths, *, element_length: float = 20.0,
                   n_elements: int | Sequence[int] | None = None) -> list[int]:
    """Elements of each segment of ``lengths`` (m, anchor to fairlead): ``n_elements`` per
    segment when it is a sequence (ValueError when its length is not the segments'),
    :func:`split_elements` of it when it is an integer, else ``max(1, round(L /
    element_length))`` each (the rules of :func:`spec_from_linedef`)."""
    if n_elements is None:
        return [max(1, int(round(L / element_length))) for L in lengths]
    if np.isscalar(n_elements):
        return split_elements(lengths, n_elements)
    counts = [int(v) for v in n_elements]
    if len(counts) != len(lengths):
        raise ValueError(f"{len(counts)} element counts for {len(lengths)} segments")
    return counts


def split_elements(lengths, n_total: int) -> list[int]:
    """``n_total`` elements shared among segments of ``lengths`` in proportion (largest
    remainder), at least one per segment."""
    lengths = np.asarray(lengths, float)
    n_total = max(int(n_total), lengths.size)
    share = lengths / lengths.sum() * n_total
    n = np.maximum(np.floor(share).astype(int), 1)
    while n.sum() < n_total:
        n[int(np.argmax(share - n))] += 1
    while n.sum() > n_total:
        cand = np.where(n > 1, share - n, np.inf)
        n[int(np.argmin(cand))] -= 1
    return [int(v) for v in n]


def specs_from_system(system: MooringSystem, *, pose=None, **kw) -> list[FELineSpec]:
    """:func:`spec_from_linedef` for every active line of a :class:`MooringSystem`."""
    return [spec_from_linedef(l, water_depth=system.water_depth, pose=pose,
                              water_density=system.water_density, gravity=system.gravity, **kw)
            for l, a in zip(system.lines, system.active) if a]


