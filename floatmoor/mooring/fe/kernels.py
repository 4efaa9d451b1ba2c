"""Numba kernels of the lumped-mass line, gathered from the modules that hold them by concern
(import from here or from the module itself):

* :mod:`.layout`: the column layout of the parameter and state arrays;
* :mod:`.elements`: element geometry, the axial law with its slack transition, element forces
  and tangent blocks, node tangents and mass blocks, bending, elastic energy, and the tension
  estimates of very stiff elements;
* :mod:`.fluid`: current, drag, fluid inertia and clump drag on the nodes;
* :mod:`.seabed`: seabed contact and friction, and the friction state between steps;
* :mod:`.forces`: the nodal forces of a line and their tangent (:func:`line_forces`: the
  passes above in order) and the force scale of the iterations;
* :mod:`.blocks`: the block-tridiagonal (and block-band) algebra of the iteration matrix;
* :mod:`.static_newton`: the static equilibrium of one line;
* :mod:`.gen_alpha`: the generalised-alpha integrator (Newton on the nodal accelerations),
  which sees only state, residual and iteration matrix;
* :mod:`.energy`: the energy audit of the time steps;
* :mod:`.advance`: the advance of a line over a body step (sub-steps, halving, audit), the
  commit of a trial state, the explicit comparison step and the output channels.

Discretisation (lumped mass, as MoorDyn, OrcaFlex, Aqwa eq. 9-45 to 9-74): nodes 0 (anchor) to
``n-1`` (fairlead), element ``j`` joins nodes ``j`` and ``j+1``.  Element tension
``T = T_el(eps) + B d(eps)/dt`` (only while taut), ``eps = l / L0 - 1``.  At node ``i``: half the
mass, net weight and hydrodynamic load of the adjacent elements; the node tangent ``q`` is the
normalised sum of the adjacent element directions; Morison drag
``-k_n |v_n| v_n - k_t |v_t| v_t`` on the velocity relative to the current split along ``q``;
added mass ``m_an (I - q q^T) + m_at q q^T``; seabed springs and friction (see ``config``).

Every kernel writes into preallocated arrays; none allocates.  The kernels take their arrays in
a few bundles (:mod:`.bundles`): the line parameters ``par``, node states (``LineState``) and
the scratch ``w`` (``LineWork``).
"""

from __future__ import annotations

from .advance import (
    accept_trial,
    end_forces,
    explicit_step,
    ga_advance,
    record_into,
)
from .blocks import (
    _inv3,
    _inv3_vals,
    block_band_solve,
    block_tridiag_resolve,
    block_tridiag_solve,
    solve_blocks,
)
from .elements import (
    E0_STIFF,
    _direction_sum,
    _elastic_energy,
    _elem_tension,
    _node_mass_el,
    _set_unit,
    _slack_strain,
    _stiff,
    _tangents_from,
    _tension,
    bar_push,
    bending_forces,
    element_forces,
    element_geometry,
    node_mass,
    node_tangents,
    release_bars,
    start_tension_estimates,
    update_tension_estimates,
)
from .energy import (
    AU_EBAD,
    AU_ETMIN,
    AU_EWORST,
    AU_NBAD,
    AU_NPEN,
    AU_PEN,
    AU_SPLITS,
    AU_TMIN,
    AU_TPEN,
    AU_TTMIN,
    AU_TWORST,
    AU_WORST,
    AUDIT_FLOOR,
    AUDIT_HARD,
    AUDIT_REL,
    PEN_FLOOR,
    PEN_WEIGHTS,
    _largest,
    line_energy,
)
from .fibre_law import (
    EL_FIB,
    EL_LAW,
    fibre_commit,
    fibre_tension,
)
from .fluid import (
    _current,
    _current_scale,
    fluid_forces,
)
from .forces import (
    _line_forces,
    force_tolerances,
    line_forces,
)
from .gen_alpha import (
    NEWTON_THETA,
    NW_FORCE,
    NW_KEEP,
    NW_PREDICT,
    NW_QSTOP,
    NW_TRAPEZ,
    TENSION_TOL,
    correct,
    gen_alpha_step,
    imbalance,
    kinematics,
    predict,
    residual,
)
from .layout import (
    EL_B,
    EL_C1,
    EL_C2,
    EL_C3,
    EL_L0,
    EPS_MACH,
    FR_DISPVEL,
    FR_NONE,
    FR_STATIC,
    FR_VDQ,
    FR_VEL,
    FS_FPREV,
    FS_UPREV,
    N_EL,
    N_FS,
    N_NP,
    N_S,
    NP_CB,
    NP_CS,
    NP_KC,
    NP_KDN,
    NP_KDT,
    NP_KS,
    NP_MAC,
    NP_MAN,
    NP_MASS,
    NP_MAT,
    NP_MD,
    NP_MUA,
    NP_MUL,
    NP_W,
    S_BEND,
    S_CD,
    S_CURC,
    S_CURS,
    S_DC,
    S_RHO,
    S_SBLIFT,
    S_VR,
    S_ZC,
)
from .seabed import (
    D_MEANINGFUL,
    V_MEANINGFUL,
    V_SB,
    _dispvel_coef,
    _dq_g,
    _friction_dirs,
    dq_transition,
    friction_commit,
    friction_decide,
    seabed_forces,
)
from .static_newton import (
    _limit_step,
    _max_move,
    _max_res,
    _res2,
    static_newton,
)

_bending = bending_forces   # the name of the bending kernel before the split

__all__ = [
    "accept_trial", "end_forces", "explicit_step", "ga_advance", "record_into", "_inv3",
    "_inv3_vals", "block_band_solve", "block_tridiag_resolve", "block_tridiag_solve",
    "solve_blocks", "E0_STIFF", "_direction_sum", "_elastic_energy", "_elem_tension",
    "_node_mass_el", "_set_unit", "_slack_strain", "_stiff", "_tangents_from", "_tension",
    "bar_push", "bending_forces", "element_forces", "element_geometry", "node_mass",
    "node_tangents", "release_bars", "start_tension_estimates", "update_tension_estimates",
    "AU_EBAD", "AU_ETMIN", "AU_EWORST", "AU_NBAD", "AU_NPEN", "AU_PEN", "AU_SPLITS", "AU_TMIN",
    "AU_TPEN", "AU_TTMIN", "AU_TWORST", "AU_WORST", "AUDIT_FLOOR", "AUDIT_HARD", "AUDIT_REL",
    "PEN_FLOOR", "PEN_WEIGHTS", "_largest", "line_energy", "EL_FIB", "EL_LAW", "fibre_commit",
    "fibre_tension", "_current", "_current_scale", "fluid_forces", "_line_forces",
    "force_tolerances", "line_forces", "NEWTON_THETA", "NW_KEEP", "NW_PREDICT", "NW_FORCE", "NW_QSTOP", "NW_TRAPEZ", "TENSION_TOL", "imbalance",
    "correct", "gen_alpha_step", "kinematics", "predict", "residual", "EL_B", "EL_C1", "EL_C2",
    "EL_C3", "EL_L0", "EPS_MACH", "FR_DISPVEL", "FR_NONE", "FR_STATIC", "FR_VDQ", "FR_VEL",
    "FS_FPREV", "FS_UPREV", "N_EL", "N_FS", "N_NP", "N_S", "NP_CB", "NP_CS", "NP_KC", "NP_KDN",
    "NP_KDT", "NP_KS", "NP_MAC", "NP_MAN", "NP_MASS", "NP_MAT", "NP_MD", "NP_MUA", "NP_MUL",
    "NP_W", "S_BEND", "S_CD", "S_CURC", "S_CURS", "S_DC", "S_RHO", "S_SBLIFT", "S_VR", "S_ZC",
    "D_MEANINGFUL", "V_MEANINGFUL", "V_SB", "_dispvel_coef", "_dq_g", "_friction_dirs",
    "dq_transition", "friction_commit", "friction_decide", "seabed_forces", "_limit_step",
    "_max_move", "_max_res", "_res2", "static_newton", "_bending",
]
