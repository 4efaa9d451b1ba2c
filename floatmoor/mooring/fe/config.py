"""Configuration of finite-element (lumped-mass) mooring lines: segments, point bodies, seabed,
friction models.

All objects are frozen keyword-only dataclasses in SI units.  They hold names, units and
validation; :class:`floatmoor.mooring.fe.line.FELine` turns them into plain arrays once.

Friction models are registered by name in :data:`FRICTION_MODELS`:

``none``
    No seabed friction.
``velocity_ramp``
    Coulomb friction with a quadratic transition in the sliding speed (ANSYS 2013, Aqwa theory
    manual sec. 9.7, eq. 9-60 to 9-66): ``F = -N f(u / v_R) (mu_a v_a a + mu_l v_l b) / u`` with
    ``u`` the horizontal speed, ``v_a, v_l`` its axial and lateral components, ``a, b`` the
    axial and lateral unit vectors on the seabed and ``f(x) = 2x - x^2`` for ``x < 1``, 1
    beyond (the single-parameter transition with ``f(0) = 0, f(1) = 1, f'(1) = 0``).  With
    ``mu_a = mu_l`` the force opposes the velocity with magnitude ``mu N f``.  The ramp velocity
    defaults to ``v_R = D / T_z`` (nominal diameter over the zero-crossing period).  NOTE: the
    seed text gives the equations only as figures; the exact factor in eq. 9-63 could not be
    read (the ramp velocity can be given explicitly).  This model has no memory: the same
    ``f`` whether the speed grows or falls (see ``velocity_ramp_double_quadratic``).
``velocity_ramp_double_quadratic``
    As ``velocity_ramp`` (same force direction, axial and lateral coefficients and ``v_R``),
    with the double-quadratic transition that ANSYS (2013, Aqwa) introduces "to smooth the
    variation of friction when the magnitude of node velocity decreases compared to the
    previous time step" (eq. 9-65, figure 9.10).  RECONSTRUCTED, NOT TRANSCRIBED: eq. 9-65 is a
    figure in the seed and was not found in any public source searched (Aqwa theory manual
    pages, Ostergaard et al., OrcaFlex/MoorDyn documentation; 2026-11-21).  The form used is
    the one fixed by the constraints stated in words: (i) from rest and while the speed grows
    the transition is eq. 9-64, ``f = 2x - x^2`` (``f(0) = 0, f(1) = 1, f'(1) = 0``), ``f = 1``
    for ``x = u / v_R >= 1``; (ii) a second quadratic is used when the speed is lower than at
    the previous (accepted) time step; (iii) ``f`` varies continuously in time ("smooth the
    variation").  Each branch is the quadratic through the state of the previous step
    ``(x_p, f_p)`` with its vertex at the end it runs to: loading (``x >= x_p``)
    ``f = 1 - (1 - f_p) ((1 - x) / (1 - x_p))^2`` (vertex (1, 1), the mirror of
    ``f'(1) = 0``), unloading (``x < x_p``) ``f = f_p (x / x_p)^2`` (vertex (0, 0): the friction
    fades out with zero slope as the node comes to rest, which is the smoothing of the velocity
    reversal).  From full sliding the unloading branch is ``x^2``, the point reflection of
    ``2x - x^2``: the two quadratics of the figure.  Since a quadratic with a given vertex is
    fixed by one point, anchoring at the previous step is the same as anchoring at the last
    turning point while the speed changes monotonically (hysteresis loops between the
    envelopes ``x^2`` and ``2x - x^2``, slopes bounded by ``4 mu N / v_R``).  Memory: the speed
    and ``f`` of the last accepted step per node (reset when the node leaves the seabed).  The
    rule uses the speed magnitude, as the seed does: a velocity that reverses within one step
    without passing near rest keeps its friction level (use steps that resolve the reversal).
``displacement_velocity_ramp``
    Lu (2012, sec. 2.2.2 and figure 8): per direction (axial, lateral) a signed
    coefficient ``c`` in [-1, 1]; nodes slower than 1e-8 m/s keep the previous ``c`` (stick);
    otherwise ``c`` is the larger of the velocity ramp ``v / C_v`` and, once the displacement
    from the last reversal position exceeds 1e-4 m, the displacement ramp ``d / C_d``; ``c``
    does not fall below its previous value unless the node reverses, and a reversal resets the
    reference position.  ``F_k = -mu_k N c_k``.

Statics always use the displacement ramp of Lu (2012) sec. 2.2.1 (``C_d``: friction grows
with the displacement from the reference (start) position up to ``mu N``) when the friction
model is not ``none``; the ramp is the quadratic ``2x - x^2`` of ``x = d / C_d`` instead of
Lu's (2012) straight line, so that Newton does not stall on its kink.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ...core.constants import GRAVITY, RHO_WATER
from ...core.errors import SceneError
from ..line_types import LineType

__all__ = ["FESegment", "PointBody", "Seabed", "Friction", "FRICTION_MODELS", "SEABED_MODELS",
           "FELineSpec"]

FRICTION_MODELS = {"none": 0, "velocity_ramp": 1, "displacement_velocity_ramp": 2,
                   "velocity_ramp_double_quadratic": 4}
"""Registry: friction model name -> kernel code (the code never appears in user input)."""

SEABED_MODELS = ("springs", "mud_layer")


def _pos(name, value, *, allow_zero=False):
    v = float(value)
    if not math.isfinite(v) or (v < 0.0 if allow_zero else v <= 0.0):
        raise SceneError(None, name, "a finite number " + (">= 0" if allow_zero else "> 0"), value)
    return v


@dataclass(frozen=True, kw_only=True)
class FESegment:
    """A homogeneous segment of a FE line, numbered from the anchor.

    Parameters
    ----------
    line_type : LineType
        Properties: mass, displaced volume, EA (``ea_dynamic`` is used in dynamics), diameter and
        the drag / added-mass coefficients ``cdn, cdt, can, cat`` on the nominal diameter.
    length : float
        Unstretched length, m.
    n_elements : int
        Number of elements (>= 1).
    tension_poly : tuple of float, optional
        Nonlinear axial law for fibre ropes: ``T = c1 eps + c2 eps^2 + c3 eps^3`` (N), overriding
        ``EA``.  Empty: linear ``T = EA eps``.
    internal_damping : float
        Axial internal damping ``B`` (N s): damping force ``B d(eps)/dt`` (MoorDyn's BA); a
        negative value ``-zeta`` gives ``zeta`` times the critical damping of one element's axial
        mode, ``B = zeta 2 sqrt(EA m) l`` (see :meth:`damping_coefficient`).
    bending_stiffness : float
        EI, N m^2 (optional; 0 for chain, wire and fibre mooring lines): discrete elastica
        energy ``EI / L_mean (1 - cos theta)`` at every interior node, pinned ends.
    """

    line_type: LineType
    length: float
    n_elements: int
    tension_poly: tuple = ()
    internal_damping: float = 0.0
    bending_stiffness: float = 0.0

    def __post_init__(self):
        _pos("segment.length", self.length)
        _pos("segment.bending_stiffness", self.bending_stiffness, allow_zero=True)
        if int(self.n_elements) != self.n_elements or self.n_elements < 1:
            raise SceneError(None, "segment.n_elements", "an integer >= 1", self.n_elements)
        if len(self.tension_poly) > 3:
            raise SceneError(None, "segment.tension_poly", "up to 3 coefficients (N)",
                             self.tension_poly)

    def damping_coefficient(self, ea: float) -> float:
        """Internal damping ``B`` (N s) of this segment; ``-zeta`` -> ``zeta * 2 sqrt(EA m) l``
        with ``l`` the element length (critical damping of a two-mass axial element is
        ``2 sqrt(k m_e)``, ``k = EA / l``, ``m_e = m l``, times ``l`` to turn N s/m into the
        strain-rate coefficient)."""
        b = float(self.internal_damping)
        if b >= 0.0:
            return b
        le = self.length / self.n_elements
        return -b * 2.0 * math.sqrt(ea * self.line_type.mass_per_length) * le


@dataclass(frozen=True, kw_only=True)
class PointBody:
    """Clump weight or buoy attached at a node.

    ``node`` counts from the anchor (0) to the fairlead; ``mass`` (kg), ``volume`` (m^3),
    ``cda`` drag coefficient times projected area (m^2), ``ca`` added-mass coefficient on the
    displaced volume.
    """

    node: int
    mass: float = 0.0
    volume: float = 0.0
    cda: float = 0.0
    ca: float = 0.0


@dataclass(frozen=True, kw_only=True)
class Seabed:
    """Flat seabed at ``z = -depth`` with vertical contact springs at the nodes.

    ``model="springs"``: contact when a node is below the seabed; force per unit line length
    ``k pen - c dz/dt`` with ``stiffness`` (N/m per m of line, e.g. MoorDyn's kbot x D) and
    ``damping`` (N s/m per m of line).

    ``model="mud_layer"`` (ANSYS 2013, Aqwa eq. 9-58/9-59): an artificial mud layer of thickness
    ``mud_depth`` above the seabed; a node below its top gets ``m_net g pen / mud_depth`` (the
    net weight is carried when the node reaches the seabed) and critical damping
    ``2 sqrt(k M)`` with ``M`` the structural plus added mass of the node.

    The spring force starts with zero slope (a cubic over the first ``d`` of penetration, ``d``
    the larger of half the static penetration and ``contact_smoothing``, m, default half the
    largest nominal diameter of the line) and the damping is faded in over the same depth, so
    that Newton does not stall on touchdown impacts at body-sized time steps (the static
    penetration grows to about ``sqrt(d w / (2 k))``: 7.6 mm instead of 2.6 mm for the OC3
    line; 0 gives the plain spring beyond half the static penetration).

    The damping acts on a node moving into the seabed (default); with ``lift_off_damping`` it
    acts both ways, also on a node lifting off (MoorDyn's contact law).  The converged line is
    the same (OC3 line, 160 elements: the fairlead tension within 0.005 %), but on a coarse
    line it damps the bouncing of the touchdown node (period ~0.6-1.3 s for 40-80 elements on
    the OC3 line, excited at every landing), which otherwise carries most of the error of a
    0.1 s step (benchmarks/RESULTS.md).
    """

    depth: float
    model: str = "springs"
    stiffness: float = 3.0e6 * 0.09
    damping: float = 3.0e5 * 0.09
    mud_depth: float = 0.1
    contact_smoothing: float | None = None
    lift_off_damping: bool = False

    def __post_init__(self):
        _pos("seabed.depth", self.depth)
        if self.model not in SEABED_MODELS:
            raise SceneError(None, "seabed.model", "one of: " + ", ".join(SEABED_MODELS),
                             self.model)
        _pos("seabed.stiffness", self.stiffness)
        _pos("seabed.damping", self.damping, allow_zero=True)
        _pos("seabed.mud_depth", self.mud_depth)
        if self.contact_smoothing is not None:
            _pos("seabed.contact_smoothing", self.contact_smoothing, allow_zero=True)
        if not isinstance(self.lift_off_damping, bool):
            raise SceneError(None, "seabed.lift_off_damping", "true or false",
                             self.lift_off_damping)


@dataclass(frozen=True, kw_only=True)
class Friction:
    """Seabed friction: model name (see :data:`FRICTION_MODELS`), axial and lateral Coulomb
    coefficients, and the ramps.

    ``ramp_velocity`` (m/s, velocity ramp ``v_R`` / ``C_v``): default ``D / zero_crossing_period``
    with ``D`` the largest nominal diameter of the line.  ``ramp_displacement`` (m, ``C_d``):
    default the nominal radius ``D / 2`` (Lu 2012, sec. 2.2.1).
    """

    model: str = "none"
    mu_axial: float = 0.0
    mu_lateral: float = 0.0
    ramp_velocity: float | None = None
    zero_crossing_period: float = 10.0
    ramp_displacement: float | None = None

    def __post_init__(self):
        if self.model not in FRICTION_MODELS:
            raise SceneError(None, "friction.model", "one of: " + ", ".join(FRICTION_MODELS),
                             self.model)
        _pos("friction.mu_axial", self.mu_axial, allow_zero=True)
        _pos("friction.mu_lateral", self.mu_lateral, allow_zero=True)
        _pos("friction.zero_crossing_period", self.zero_crossing_period)
        if self.ramp_velocity is not None:
            _pos("friction.ramp_velocity", self.ramp_velocity)
        if self.ramp_displacement is not None:
            _pos("friction.ramp_displacement", self.ramp_displacement)


@dataclass(frozen=True, kw_only=True)
class FELineSpec:
    """A FE mooring line between a fixed anchor and a fairlead (earth coordinates, m).

    Parameters
    ----------
    name : str
    anchor, fairlead : tuple of 3 float
        Earth coordinates (z up, mean water line at 0) of the ends; the fairlead position is the
        initial (static) one.
    segments : tuple of FESegment
        From the anchor to the fairlead.
    seabed : Seabed
    friction : Friction
    point_bodies : tuple of PointBody
    current_z, current_speed : tuple of float
        Piecewise-linear current profile (z up, increasing; m/s), empty for no current.
    current_heading : float
        Direction of travel of the current, rad from +x to +y.
    water_density, gravity : float
    """

    name: str
    anchor: tuple
    fairlead: tuple
    segments: tuple
    seabed: Seabed
    friction: Friction = field(default_factory=Friction)
    point_bodies: tuple = ()
    current_z: tuple = ()
    current_speed: tuple = ()
    current_heading: float = 0.0
    water_density: float = RHO_WATER
    gravity: float = GRAVITY

    def __post_init__(self):
        if len(self.segments) == 0:
            raise SceneError(None, f"{self.name}.segments", "at least one segment", self.segments)
        for k, key in ((self.anchor, "anchor"), (self.fairlead, "fairlead")):
            if len(k) != 3 or not all(math.isfinite(float(c)) for c in k):
                raise SceneError(None, f"{self.name}.{key}", "3 finite coordinates (m)", k)
        if len(self.current_z) != len(self.current_speed):
            raise SceneError(None, f"{self.name}.current", "as many speeds as levels",
                             (self.current_z, self.current_speed))
        n_nodes = sum(s.n_elements for s in self.segments) + 1
        for pb in self.point_bodies:
            if not (0 < pb.node < n_nodes - 1):
                raise SceneError(None, f"{self.name}.point_bodies.node",
                                 f"an interior node 1..{n_nodes - 2}", pb.node)

    @property
    def n_elements(self) -> int:
        return sum(s.n_elements for s in self.segments)

    @property
    def length(self) -> float:
        return sum(s.length for s in self.segments)
