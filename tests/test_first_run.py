"""First run from an empty numba cache: a scene compiles only the kernels it uses, each once.

The first command of the README (the flagship storm) pays for every numba compilation before
its first seed result; a second type specialisation of a kernel, or a kernel the scene does not
use, costs seconds there (benchmarks/RESULTS.md, "First run").  These tests run in a fresh
process with an empty cache directory (NUMBA_CACHE_DIR) and record numba's compile events.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

RECORDER = """
import json, sys
from numba.core import event
compiled = []
class Listener(event.Listener):
    def on_start(self, ev):
        pass
    def on_end(self, ev):
        f = ev.data["dispatcher"].py_func
        compiled.append([f.__module__ + "." + f.__qualname__, str(ev.data["args"])])
event.register("numba:compile", Listener())
"""


def _run(code, tmp_path):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba_cache"),
               PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    env.pop("NUMBA_DISABLE_JIT", None)
    out = subprocess.run([sys.executable, "-W", "ignore", "-c", RECORDER + code], env=env,
                         cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_no_strips_compiles_no_strip_code(tmp_path):
    """A kernel given the strips bundle of a run without strips (NoStrips) compiles the empty
    choice of strips_into, not the slender-element kernels."""
    compiled = _run("""
import numpy as np
from numba import njit
from floatmoor.forces.slender_kernels import strips_into
from floatmoor.forces.terms import empty_strips

@njit
def f(sl, out):
    if sl.on:
        strips_into(0, np.zeros(6), np.zeros(6), sl, np.zeros((3, 3)), np.zeros(6), out)
    return sl.on

out = np.zeros(6)
assert f(empty_strips(), out) is False and not out.any()
print(json.dumps(compiled))
""", tmp_path)
    names = [c[0] for c in compiled]
    assert any(n.endswith("strips_into_typed.<locals>.nothing") for n in names), names
    assert not [n for n in names if n.rsplit(".", 1)[-1].startswith("slender_")], names


def test_fibre_step_without_tracking_compiles_no_fibre_code(tmp_path):
    """A kernel given the fibre bundle of a run without fibre tracking (NoFibre) compiles the
    empty choice of fibre_step, not the fibre update and its table look-ups."""
    compiled = _run("""
import numpy as np
from numba import njit
from floatmoor.mooring.fibre_system import fibre_step, no_fibre_track

@njit
def f(fib, line_out):
    fibre_step(fib, None, np.ones(1, np.bool_), line_out)
    return fib.on

out = np.zeros((1, 10))
assert f(no_fibre_track(), out) is False and not out.any()
print(json.dumps(compiled))
""", tmp_path)
    names = [c[0] for c in compiled]
    assert any(n.endswith("_fibre_step_typed.<locals>.nothing") for n in names), names
    assert not [n for n in names if n.startswith("floatmoor.mooring.fibre")
                and "_fibre_step_typed" not in n], names


def test_line_forces_choose_on_the_bundle_type():
    """The exact and the predictor-corrector catenary solves of the time loop are chosen on the
    type of the lines bundle (Lines, PredictorLines): an exact run's kernel has no
    predictor-corrector code, and lines_bundle makes the predictor bundle only for a tolerance
    > 0.  (Typing only, nothing is compiled.)"""
    import numpy as np
    from numba import typeof

    from floatmoor.mooring.fibre_system import FibreTrack, NoFibre, _fibre_step_typed
    from floatmoor.solvers.td_bundles import Lines, PredictorLines, lines_bundle, no_lines
    from floatmoor.solvers.td_kernel import _line_forces_typed

    base = no_lines()
    exact = lines_bundle(*base[:7], 0.0)
    pred = lines_bundle(*base[:7], 1e-4)
    assert type(exact) is Lines and type(pred) is PredictorLines and pred.step_tol == 1e-4
    assert typeof(exact) != typeof(pred)
    assert _line_forces_typed(None, None, typeof(exact), None, None).__name__ == "exact"
    assert _line_forces_typed(None, None, typeof(pred), None, None).__name__ == "predictor"
    assert isinstance(base.fibre, NoFibre)
    assert _fibre_step_typed(typeof(base.fibre), None, None, None).__name__ == "nothing"
    z = np.zeros(0)
    track = FibreTrack(True, 0.1, np.zeros(0, np.int64), np.zeros(0, np.int64), z, z, z, z, z,
                       np.zeros(0, np.bool_), np.zeros(0, np.int64), np.zeros((0, 2)),
                       np.zeros((0, 2)), z, np.zeros(1))
    assert _fibre_step_typed(typeof(track), None, None, None).__name__ == "update"


@pytest.mark.slow
def test_flagship_compiles_each_kernel_once_and_no_strip_code(tmp_path):
    """The flagship scene (no slender elements, exact catenary solves, no fibre rope), 300 s of
    storm from an empty cache: every numba function is compiled for one signature only, and no
    slender-element, predictor-corrector or fibre kernel."""
    compiled = _run("""
from floatmoor.analyses.simulate import simulate
from floatmoor.io.scene import load_scene
simulate(load_scene("scenes/floatel_100yr.yaml"), seed=1, duration=300.0)
print(json.dumps(compiled))
""", tmp_path)
    names = [c[0] for c in compiled]
    assert "floatmoor.solvers.td_kernel.td_steps" in names
    assert "floatmoor.mooring.system.system_force_kernel" in names
    twice = sorted({n for n in names if names.count(n) > 1 and n.startswith("floatmoor.")})
    assert not twice, [c for c in compiled if c[0] in twice]
    assert not [n for n in names if n.rsplit(".", 1)[-1].startswith("slender_")], names
    assert "floatmoor.mooring.catenary_step.system_force_step_kernel" not in names, names
    assert not [n for n in names if n.startswith("floatmoor.mooring.fibre")
                and not n.endswith("_fibre_step_typed.<locals>.nothing")], names


@pytest.mark.slow
def test_seed_batch_compiles_the_time_loop_once(tmp_path):
    """Two seeds on two worker processes from an empty cache: one worker compiles the time loop
    and the other loads it from numba's cache once it is there (run_seeds' compile-once
    start-up), instead of both compiling the same kernels at the same time; the statics
    kernels the parent compiles when it checks the scene are not compiled again.  Compile
    events are recorded per process (the workers are forked with the listener)."""
    log = tmp_path / "events"
    log.mkdir()
    out = _run(f"""
import os
from numba.core import event
class PerProcess(event.Listener):
    def on_start(self, ev):
        pass
    def on_end(self, ev):
        f = ev.data["dispatcher"].py_func
        with open(os.path.join({str(log)!r}, str(os.getpid())), "a") as fh:
            fh.write(f.__module__ + "." + f.__qualname__ + "\\n")
event.register("numba:compile", PerProcess())
from floatmoor.analyses.runner import run_seeds
res = run_seeds("scenes/floatel_100yr.yaml", [1, 2], {str(tmp_path / "out")!r}, workers=2,
                overrides={{"duration": 1500.0}}, echo=None, progress=False)
print(json.dumps([o.status for o in res.outcomes]))
""", tmp_path)
    assert out == ["done", "done"]
    per_process = {p.name: p.read_text().split() for p in log.iterdir()}
    loops = [pid for pid, names in per_process.items()
             if "floatmoor.solvers.td_kernel.td_steps" in names]
    assert len(loops) == 1, per_process
    # no floatmoor kernel compiled in two processes: the parent compiles the statics kernels
    # when it checks the scene before any seed starts (they are then in the cache), one worker
    # the time loop, the other loads everything
    seen: dict[str, str] = {}
    for pid, names in per_process.items():
        for n in set(names):
            if n.startswith("floatmoor.solvers.") or n.startswith("floatmoor.mooring."):
                assert n not in seen, (n, seen.get(n), pid, per_process)
                seen[n] = pid
