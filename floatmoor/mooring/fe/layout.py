"""Column layout of the FE line arrays and the constants shared by the line kernels.

The kernels (:mod:`.elements`, :mod:`.fluid`, :mod:`.seabed`, :mod:`.forces`, :mod:`.blocks`,
:mod:`.static_newton`, :mod:`.energy`, :mod:`.gen_alpha`, :mod:`.advance`; :mod:`.kernels`
gathers them) read the line parameters through these column numbers: ``P`` (n, N_NP) node
parameters, ``E`` (n-1, N_EL) element parameters, ``S`` (N_S + fibre records) line scalars,
``fs`` (n, N_FS) friction state.  Built by :class:`.line.FELine`.
"""

from __future__ import annotations

from .fibre_law import EL_FIB, EL_LAW  # noqa: F401  (element columns 5, 6 of fibre elements)

# node parameter columns
NP_MASS, NP_W, NP_KDN, NP_KDT, NP_MAN, NP_MAT, NP_KC, NP_MAC, NP_KS, NP_CS, NP_MUA, NP_MUL, \
    NP_MD, NP_CB = range(14)
N_NP = 14
# element parameter columns; EL_LAW (0: the polynomial law C1..C3) and EL_FIB (offset of the
# fibre record in S) of fibre elements: see fibre_law
EL_L0, EL_C1, EL_C2, EL_C3, EL_B = range(5)
N_EL = 7
# scalar parameters
S_ZC, S_VR, S_CD, S_CURC, S_CURS, S_RHO, S_DC, S_BEND, S_SBLIFT = range(9)
N_S = 9
# friction codes (see config.FRICTION_MODELS); 3 = static displacement ramp
FR_NONE, FR_VEL, FR_DISPVEL, FR_STATIC, FR_VDQ = 0, 1, 2, 3, 4
# friction state columns: c_axial, c_lateral, v_prev_axial, v_prev_lateral, ref_x, ref_y,
# branch_axial, branch_lateral (model of Lu 2012: 0 stick, +-1 sliding direction in this step).
# The double-quadratic velocity ramp (FR_VDQ) keeps the horizontal speed (m/s) and the
# transition factor f of the last accepted step in columns FS_UPREV and FS_FPREV.  Column
# FS_EM, FS_TM, FS_KD (8-10) of row j: mean strain of the fibre element j, its working-curve
# tension and dynamic stiffness (fibre_law).
N_FS = 11
FS_UPREV, FS_FPREV = 0, 1
EPS_MACH = 2.220446049250313e-16

KERNEL_JIT = {"cache": True, "_nrt": False}
"""numba options of the FE step kernels (the line kernel's force, step and advance functions,
the lanes' passes): cached, and no reference counting (``_nrt=False``, as the quasi-static
kernels' ``td_kernel.INTERNAL``).  With it numba emits an atomic increment and decrement of an
array's reference count for every array argument and every array taken out of a bundle
(``lanes_forces.forces_into`` had about 100 of each per call, ``lanes_step.block_step`` 140):
10 % of the flagship's lanes replay in a ``perf`` profile (2026-11-28).  These kernels
allocate nothing and return no array (their arrays are the bundles', made in Python), and numba
refuses to compile an allocation under ``_nrt=False``, so one added later fails loudly.  A
kernel that reads a typed list (``multi``) keeps the reference counts."""
