"""Stiff and extreme cases: 100-year storm, a taut polyester mooring, a very slack mooring.

Each runs without NaN or stops with a clear NumericalError.  The default run simulates a short
window; the slow test sweeps dt to find the largest stable step of each case (the numbers are
recorded in benchmarks/RESULTS.md by ``benchmarks/bench_time_domain.py --extreme``).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from floatmoor.analyses.simulate import simulate
from floatmoor.core.errors import NumericalError

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")

ROOT = Path(__file__).resolve().parents[2]
FL = ROOT / "vessels" / "floatel_like"
ENV = ROOT / "metocean" / "heidrun_100yr.yaml"


def extreme_scene(tmp_path: Path, kind: str) -> Path:
    """Scene file of one case: ``storm`` (the Floatel-like mooring), ``taut`` (12 polyester
    lines of 400 m, 1 % stretched at rest), ``slack`` (anchors 100 m closer: 100 m of extra
    chain on the seabed, a fraction of the pretension)."""
    assert (FL / "database.nc").is_file(), "the shipped floatel_like database is missing"
    moor = yaml.safe_load((FL / "mooring.yaml").read_text())
    for line in moor["lines"]:
        fx, fy, fz = line["fairlead"]
        ax, ay = line["anchor"]["x"], line["anchor"]["y"]
        az = math.atan2(ay - fy, ax - fx)
        if kind == "taut":
            L = 400.0
            chord = L * 1.01
            h = math.sqrt(chord ** 2 - (150.0 + fz) ** 2)
            line["anchor"] = {"x": round(fx + h * math.cos(az), 3),
                              "y": round(fy + h * math.sin(az), 3)}
            line["segments"] = [{"type": "floatel_polyester_185", "length": L}]
        elif kind == "slack":
            r = math.hypot(ax - fx, ay - fy) - 100.0
            line["anchor"] = {"x": round(fx + r * math.cos(az), 3),
                              "y": round(fy + r * math.sin(az), 3)}
    p = tmp_path / f"{kind}.yaml"
    scene = {"name": f"floatel-{kind}", "site": {"water_depth": 150.0},
             "vessel": str(FL / "vessel.yaml"), "environment": str(ENV), "mooring": moor,
             "analysis": {"duration": 600.0, "dt": 0.1, "transient": 100.0, "ramp": 100.0}}
    p.write_text(yaml.safe_dump(scene, sort_keys=False))
    return p


def _run(path, dt, duration):
    try:
        ds = simulate(path, seed=1, dt=dt, duration=duration)
    except NumericalError as exc:
        return None, exc
    return ds, None


@pytest.mark.parametrize("kind", ["storm", "taut", "slack"])
def test_extreme_cases_run_or_fail_clearly(tmp_path, kind):
    """Hs 16 m / Tp 18.2 s, 100-year wind and current, 400 s at dt 0.1 s: finite results (or a
    NumericalError naming time and DOF/line, never NaN)."""
    ds, exc = _run(extreme_scene(tmp_path, kind), 0.1, 400.0)
    if exc is not None:
        assert " at t = " in str(exc) and "Likely remedy" in str(exc)
        return
    assert np.all(np.isfinite(ds["motion"].values))
    assert np.all(np.isfinite(ds["line_tension"].values))
    T = ds["line_tension"].values
    if kind == "taut":   # polyester 1 % stretched: pretension about EA * 0.01 = 1.7 MN
        assert 1.2e6 < T[0].mean() < 2.2e6
    if kind == "slack":  # less pretension than the calibrated system (946 kN per line)
        assert T[0].mean() < 0.8 * 946e3


@pytest.mark.slow  # reason: 3 cases x 6 time steps x 1200 s (15-60 s depending on load)
@pytest.mark.parametrize("kind", ["storm", "taut", "slack"])
def test_largest_stable_dt(tmp_path, kind):
    """The largest dt (of 0.1 ... 1.6 s) that runs and keeps the max tension within 5 % of the
    dt = 0.05 s run; every larger dt either runs or fails with a clear error."""
    path = extreme_scene(tmp_path, kind)
    ref, exc = _run(path, 0.05, 1200.0)
    assert exc is None, exc
    t_ref = ref["line_tension"].values.max()
    best = None
    for dt in (0.1, 0.2, 0.4, 0.8, 1.6):
        ds, exc = _run(path, dt, 1200.0)
        if exc is not None:
            assert " at t = " in str(exc) or "stability limit" in str(exc)
            continue
        if abs(ds["line_tension"].values.max() / t_ref - 1.0) < 0.05:
            best = dt
    assert best is not None and best >= 0.1
