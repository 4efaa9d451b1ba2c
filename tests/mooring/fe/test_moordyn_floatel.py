"""The Floatel-like flagship's slack windward line (line 1: chain 1200 m + polyester 1200 m +
chain 250 m, 150 m depth, about 1100 m of chain on the seabed, the scene's 0.94 m/s current on
the line) driven by the fairlead track of a quasi-static flagship storm, in floatmoor and in
MoorDyn (PyPI ``moordyn``, MoorDyn-C v2, RK4 at dtM 2 ms: its RK2 is unstable on an undamped
line) with identical inputs (tests/mooring/fe/moordyn_floatel.py: the same line written by
floatmoor's MoorDyn exporter, the same current profile, MoorDyn's seabed law in both, no
friction, no internal damping, both fed the start-of-step position and chord velocity of one
piecewise-linear fairlead track).  floatmoor: 132 elements, generalised-alpha at the coupling
step 0.1 s with its energy audit.

Before the audit, this line's elements switched between slack and taut within the 0.1 s steps
when the current pushed the slack grounded chain and it snapped taut again, the steps created
energy and the line reported 10-12 MN along its length while its fairlead stayed below 4 MN.

Measured over the 3-hour window of seed 19 (benchmarks/verify_fe_floatel_moordyn.py,
2026-11-27): fairlead mean +0.2 %, std -0.7 %, max -0.4 %; anchor mean +0.1 %, std -0.4 %,
max -0.2 % (floatmoor against MoorDyn).  This test runs 2400 s of seed 1 (1200 s of statistics)
and asks for the issue's 5 % on the fairlead mean, std and maximum and on the anchor's.
"""

from __future__ import annotations

import numpy as np
import pytest

moordyn = pytest.importorskip("moordyn")

pytestmark = pytest.mark.slow   # MoorDyn: about 2-3 min of CPU for 2400 s of 132 segments


def test_slack_line_with_current_against_moordyn():
    from .moordyn_floatel import (
        case,
        fairlead_track,
        run_floatmoor,
        run_moordyn,
        statistics,
        storm_track,
    )

    c = case("line1", current=True)
    t, poses, transient = storm_track(seed=1, duration=2400.0)
    r, x = fairlead_track(c, t, poses)
    window = t >= transient
    Tf_md, Ta_md, _ = run_moordyn(c, t, r, dtm=2e-3)
    Tf, Ta, Tm, _, line = run_floatmoor(c, t, x, pose0=poses[0])
    for mine, ref in ((Tf, Tf_md), (Ta, Ta_md)):
        a, b = statistics(mine, window), statistics(ref, window)
        for k in ("mean", "std", "max"):
            assert a[k] == pytest.approx(b[k], rel=0.05), (k, a, b)
    # the answer keeps its bounds: no step left creating energy, nothing along the line
    # beyond the fairlead tension plus the weight of the line over the water depth
    assert line.audit["energy_unresolved_steps"] == 0
    assert np.max(Tm[window]) <= np.max(Tf[window]) + 1197.2 * 150.0
