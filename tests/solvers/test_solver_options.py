"""The ``solver:`` options of the time loop (opt-in approximations) against the exact path on the
flagship storm (scenes/floatel_100yr.yaml, seed 1).

Reference: the exact path of the same run (its own accuracy is the business of the model tests
and of the time-step convergence, 0.07 % on the max offset and tension at dt = 0.1 s,
benchmarks/RESULTS.md); an option must stay far below that.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

from floatmoor.analyses.simulate import simulate
from floatmoor.core.errors import SceneError
from floatmoor.io.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def flagship(tmp_path, solver: dict | None) -> Path:
    """The flagship scene with absolute paths and a ``solver`` section."""
    d = yaml.safe_load((ROOT / "scenes" / "floatel_100yr.yaml").read_text())
    for key in ("vessel", "environment", "mooring"):
        d[key] = str((ROOT / "scenes" / d[key]).resolve())
    if solver is not None:
        d["solver"] = solver
    p = tmp_path / "flagship.yaml"
    p.write_text(yaml.safe_dump(d))
    return p


@pytest.fixture(scope="module")
def exact_storm(tmp_path_factory):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return simulate(flagship(tmp_path_factory.mktemp("exact"), None), seed=1,
                        duration=1500.0)


def test_bad_option_is_a_scene_error(tmp_path):
    with pytest.raises(SceneError, match="solver.catenary"):
        load_scene(flagship(tmp_path, {"catenary": "fast"}))
    with pytest.raises(SceneError, match="solver"):
        load_scene(flagship(tmp_path, {"catenery": "predictor"}))
    with pytest.raises(SceneError, match="solver.memory_fit_tol"):
        load_scene(flagship(tmp_path, {"memory": "state_space", "memory_fit_tol": 0.0}))
    spec = load_scene(flagship(tmp_path, {"memory": "state_space", "memory_fit_tol": 1e-3}))
    assert spec.solver.memory_fit_tol == 1e-3 and not spec.solver.is_default


def test_predictor_catenary_against_the_exact_path(tmp_path, exact_storm):
    """``solver: {catenary: predictor}``: 1500 s of the storm; fairlead and anchor tensions
    within 1e-7 of the largest tension and the motion within 1e-6 m / rad of the exact path
    (measured: 3e-10 over 3 hours), i.e. 1e4 times below the time-step error."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = simulate(flagship(tmp_path, {"catenary": "predictor"}), seed=1, duration=1500.0)
    assert ds.attrs["solver"] == "catenary predictor, memory convolution"
    assert "solver" not in exact_storm.attrs
    ref = exact_storm
    tmax = float(ref["line_tension"].max())
    for name in ("line_tension", "anchor_tension"):
        assert float(np.abs(ds[name] - ref[name]).max()) <= 1e-7 * tmax, name
    assert float(np.abs(ds["motion"] - ref["motion"]).max()) <= 1e-6
    assert not np.array_equal(ds["line_tension"].values, ref["line_tension"].values)


def test_state_space_memory_against_the_convolution(tmp_path, exact_storm):
    """``solver: {memory: state_space}`` (both options): every retardation function fitted to
    1 % (L2), and the storm's max offset and max fairlead tension within 0.1 % of the exact
    path (the order of the time-step error at dt = 0.1 s; measured over 3 hours: 1e-5 and
    5e-5, offset standard deviation 7e-4)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = simulate(flagship(tmp_path, {"catenary": "predictor", "memory": "state_space"}),
                      seed=1, duration=1500.0)
    assert ds.attrs["solver"] == "catenary predictor, memory state_space (fit 0.01)"
    assert 0.0 < ds.attrs["memory_fit_error"] <= 0.01
    ref = exact_storm
    sel = ref["time"].values >= 200.0

    def peaks(d):
        m = d["motion"].values[sel]
        return np.hypot(m[:, 0], m[:, 1]).max(), d["line_tension"].values[sel].max()

    for got, want in zip(peaks(ds), peaks(ref)):
        assert got == pytest.approx(want, rel=1e-3)
    assert float(np.abs(ds["line_tension"] - ref["line_tension"]).max()) > 0.0


def test_convergence_command_reports_the_options(tmp_path, capsys):
    """``floatmoor convergence --solver ...``: a row per dt and solver, the options' difference
    from the exact run at the same dt; a malformed option is a usage error (exit 2)."""
    from floatmoor.cli import main

    p = tmp_path / "oc3.yaml"
    oc3 = ROOT / "vessels" / "oc3_hywind"
    p.write_text(f"name: oc3\nsite: {{water_depth: 320.0}}\nvessel: {oc3 / 'vessel.yaml'}\n"
                 f"mooring: {oc3 / 'mooring.yaml'}\n"
                 "environment:\n  waves: {spectrum: jonswap, hs: 6.0, tp: 12.0}\n"
                 "analysis: {duration: 150.0, dt: 0.1, transient: 50.0, ramp: 20.0}\n")
    assert main(["convergence", str(p), "--levels", "2", "--dt0", "0.2",
                 "--solver", "catenary=predictor,memory=state_space"]) == 0
    out = capsys.readouterr().out
    rows = [ln for ln in out.splitlines() if "memory state_space (fit 0.01) (" in ln]
    assert len(rows) == 2
    assert all(float(r.rsplit("(", 1)[1].split()[0]) < 1.0 for r in rows)  # percent
    assert main(["convergence", str(p), "--solver", "memory=fast"]) == 2


@pytest.mark.slow
def test_options_run_without_jit(tmp_path):
    """Both options as plain Python (NUMBA_DISABLE_JIT=1) give the compiled numbers (8 s of
    the storm; about 2 minutes: the setup's statics run as plain Python too)."""
    import os
    import subprocess
    import sys

    p = flagship(tmp_path, {"catenary": "predictor", "memory": "state_space"})
    code = ("import warnings; warnings.simplefilter('ignore')\n"
            "from floatmoor.analyses.simulate import simulate\n"
            f"ds = simulate({str(p)!r}, seed=1, duration=8.0, dt=0.1)\n"
            "print(repr(float(ds['line_tension'].values[-1].sum())), "
            "repr(float(ds['motion'].values[-1, 0])))")
    outs = []
    for flag in ("1", "0"):
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           env=dict(os.environ, NUMBA_DISABLE_JIT=flag), check=True)
        outs.append([float(v) for v in r.stdout.split()])
    np.testing.assert_allclose(outs[0], outs[1], rtol=1e-12)
