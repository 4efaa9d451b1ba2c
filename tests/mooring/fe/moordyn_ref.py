"""Run one OC3 line in MoorDyn (PyPI package ``moordyn``, MoorDyn-C v2) with a prescribed
fairlead track.  Used only by the optional comparison tests and the benchmark.

MoorDyn's Python API (``moordyn.Create(file)``, ``moordyn.Init(system, x, v)``,
``moordyn.Step(system, x, v, t, dt) -> forces``): ``x, v`` are the positions and velocities
of the coupled points, earth axes; the returned forces are the forces of the lines on the
coupled points.  Input-file conventions (docs/inputs.rst of FloatingArrayDesign/MoorDyn):
Cd on the frontal area d l, CdAx on the surface area pi d l, BA/-zeta a damping ratio when
negative; options g, rho, WtrDpth, kBot (Pa/m), cBot (Pa s/m).
"""

from __future__ import annotations

import os
import tempfile

import numpy as np

TEMPLATE = """--------------------- MoorDyn Input File ------------------------------------
One OC3-Hywind line (floatmoor FE verification)
---------------------- LINE TYPES -----------------------------------------------------
TypeName   Diam    Mass/m     EA      BA/-zeta    EI    Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)     (N-s/-)     (N-m^2) (-)  (-)    (-)     (-)
main       0.09    77.7066    {ea:.6e} {ba}        0.0   1.6    1.0    0.1     0.0
---------------------- POINTS ---------------------------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
(#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed     853.87  0.0   -320.0  0      0       0      0
2     Coupled   5.2     0.0   -70.0   0      0       0      0
---------------------- LINES ----------------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (ID)     (ID)      (m)       (-)      (-)
1     main       1        2        902.2     {nseg}       -
---------------------- OPTIONS --------------------------------------------------------
{dtm}    dtM
9.80665  g
1025.0   rho
320.0    WtrDpth
3.0e6    kBot
3.0e5    cBot
1.0      dtIC
120.0    TmaxIC
0.0001   threshIC
0        writeLog
1        disableOutput
1        disableOutTime
------------------------- need this line ----------------------------------------------
"""


def run_moordyn(motion, t_end, dt, *, nseg=20, dtm=1e-3, ea=384.243e6, ba=-0.8, timing=False):
    """Fairlead force history (N, (nt, 3)) and times of MoorDyn for the OC3 line 1 with the
    fairlead at (5.2, 0, -70) + ``motion(t)[0]``.  Returns ``(t, F)``; ``F`` is the force of the
    line on the fairlead.  With ``timing`` also the wall time of the time steps alone (s, the
    initial-condition solve excluded)."""
    import time

    import moordyn

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "oc3_line.dat")
        with open(path, "w") as fh:
            fh.write(TEMPLATE.format(ea=ea, ba=ba, nseg=nseg, dtm=dtm))
        cwd = os.getcwd()
        os.chdir(d)
        try:
            system = moordyn.Create(path)
            x0 = np.array([5.2, 0.0, -70.0])
            moordyn.Init(system, x0.tolist(), [0.0, 0.0, 0.0])
            n = int(round(t_end / dt))
            t_out = np.zeros(n + 1)
            F = np.zeros((n + 1, 3))
            t0 = time.perf_counter()
            for k in range(1, n + 1):
                t = k * dt
                dsp, vel = motion(t)
                f = moordyn.Step(system, (x0 + dsp).tolist(), list(map(float, vel)), t - dt, dt)
                t_out[k] = t
                F[k] = f
            wall = time.perf_counter() - t0
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    if timing:
        return t_out[1:], F[1:], wall
    return t_out[1:], F[1:]
