"""FE lines advanced in threads (``solver: {threads: N}``, floatmoor/mooring/fe/multi.py
``body_advance_parallel``) against the serial kernel.

Reference: the serial path itself.  Threads change no arithmetic (each line's advance is the
same code on the line's own arrays; the wrench, counters and failure report are summed in the
line order after the threads), so every output must be equal bit for bit: an intact storm, a
storm with a line released (ALS) and a storm whose FE step fails (the same NumericalError).
The thread policy (``auto``, the cap of worker processes) and the scene errors are checked
against their documented rules.
"""

from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numba
import numpy as np
import pytest

from floatmoor.core.errors import NumericalError, SceneError
from floatmoor.io.scene import load_scene
from floatmoor.io.solver_section import (
    SolverSpec,
    available_threads,
    parse_threads,
    run_threads,
    with_thread_cap,
    worker_thread_cap,
)
from floatmoor.solvers.time_domain import assemble, integrate
from tests.solvers.test_time_domain_fe import _built, _scene

ROOT = Path(__file__).resolve().parents[2]
SEA = {"name": "sea", "waves": {"spectrum": "jonswap", "hs": 8.0, "tp": 12.0}}


def _run(path, threads: int, *, duration=40.0, patch=None):
    """A short coupled run of the scene at ``path`` with ``threads``; ``patch(a)`` may change the
    assembly before the run.  Returns the result and the FE counters."""
    b = _built(path)
    a = assemble(b, seed=1, dt=0.2, duration=duration, ramp=10.0, options=b.scene.forces,
                 solver=SolverSpec(threads=threads))
    if patch is not None:
        patch(a)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = integrate(a, built=b)
    return r, a.fe.mooring.counters.copy()


def _assert_same(r1, r2):
    for name in ("motion", "velocity", "line_tension", "anchor_tension"):
        np.testing.assert_array_equal(getattr(r1, name), getattr(r2, name), err_msg=name)
    for k in r1.fe_records:
        np.testing.assert_array_equal(r1.fe_records[k], r2.fe_records[k], err_msg=k)


@pytest.mark.skipif(available_threads() < 2, reason="numba has one thread here")
def test_two_threads_are_bit_identical_to_one(tmp_path):
    """Waves, 8 elements per line, 40 s: motions, tensions, FE records and Newton counters of
    two threads equal those of one bit for bit, and numba's thread count is restored."""
    p = _scene(tmp_path, n_elements=8, environment=SEA)
    before = numba.get_num_threads()
    r1, c1 = _run(p, 1)
    r2, c2 = _run(p, 2)
    assert numba.get_num_threads() == before
    assert r1.info["fe_threads"] == 1 and r2.info["fe_threads"] == 2
    _assert_same(r1, r2)
    np.testing.assert_array_equal(c1, c2)
    assert c1[:, 0].min() > 0 and np.ptp(r1.motion[:, 0]) > 0.01   # the lines worked


@pytest.mark.skipif(available_threads() < 2, reason="numba has one thread here")
def test_threads_with_a_released_line_are_bit_identical(tmp_path):
    """ALS: line6 released at 16 s (``forces.line_failure``); two threads as one."""
    p = _scene(tmp_path, n_elements=8, environment=SEA,
               forces={"line_failure": {"line6": 16.0}})
    r1, c1 = _run(p, 1)
    r2, c2 = _run(p, 2)
    j = r1.line_names.index("line6")
    assert r1.line_tension[-1, j] == 0.0 and r1.line_tension[0, j] > 1e5
    _assert_same(r1, r2)
    np.testing.assert_array_equal(c1, c2)


@pytest.mark.skipif(available_threads() < 2, reason="numba has one thread here")
def test_a_failing_line_step_raises_the_serial_error(tmp_path):
    """Lines 5 and 9 (indices 4 and 8) allowed no Newton iteration: the first step fails; with
    threads the lines after line5 are advanced too, but the error names line5 with the same time
    and node as the serial run (the lowest failing line, where the serial loop stops)."""
    p = _scene(tmp_path, n_elements=8)

    def no_newton(a):
        orig = a.fe.mooring.start

        def start(**kw):
            orig(**kw)
            for i in (4, 8):
                a.fe.mooring.lines[i].maxit = 0
        a.fe.mooring.start = start

    msgs = []
    for threads in (1, 2):
        with pytest.raises(NumericalError) as e:
            _run(p, threads, duration=10.0, patch=no_newton)
        msgs.append(str(e.value))
    assert "line 'line5'" in msgs[0] and "at t = " in msgs[0]
    assert msgs[0] == msgs[1]


def _packed():
    """The OC3 mooring's three lines (25 m elements) packed for the multi-line kernels."""
    from floatmoor.core.config import Node
    from floatmoor.io.mooring_section import parse_mooring
    from floatmoor.mooring.fe.body import FEMooring
    from floatmoor.mooring.fe.from_system import specs_from_system

    ms = parse_mooring(Node.load(ROOT / "vessels" / "oc3_hywind" / "mooring.yaml"),
                       water_depth=320.0)
    fm = FEMooring(specs_from_system(ms, element_length=25.0), ms.fairleads, fast=True)
    fm.solve_static(np.zeros(6))
    fm.start()
    return fm


@pytest.mark.parametrize("slots", [2, 3, 5])
def test_parallel_kernel_any_slot_count(slots):
    """``body_advance_parallel`` with 2, 3 (one line per slot) and 5 slots (more slots than
    lines) gives the serial kernel's wrench, end forces, counters and states bit for bit, and
    the same output channels of the accepted states (written in the threads), which are those
    of ``record_into`` called afterwards on each line's accepted state."""
    from floatmoor.mooring.fe import kernels as K
    from floatmoor.mooring.fe.line import FELine
    from floatmoor.mooring.fe.multi import (
        ParallelLines,
        SerialLines,
        advance_lines,
        body_accept,
    )

    out = []
    for mode in (SerialLines(np.zeros(3, np.int64), 1, np.zeros((3, 16))),
                 ParallelLines(np.zeros(3, np.int64), slots, np.zeros((3, 16)))):
        fm = _packed()
        body, lines = fm._packed
        Q = []
        for k in range(1, 21):
            w = 2 * np.pi / 12.0
            t = 0.2 * k
            pose = np.array([3 * np.sin(w * t), 2 * np.sin(w * t + 1), 0.3 * np.sin(w * t),
                             0.01 * np.sin(w * t), -0.02 * np.sin(w * t), 0.02 * np.sin(w * t)])
            vel = w * np.array([3 * np.cos(w * t), 2 * np.cos(w * t + 1), 0.3 * np.cos(w * t),
                                0.01 * np.cos(w * t), -0.02 * np.cos(w * t),
                                0.02 * np.cos(w * t)])
            assert advance_lines(mode, t, 0.2, 1, FELine.MAX_SPLIT, pose, vel, body, lines) == 0
            Q.append(body.Q.copy())
            body_accept(body.on, lines)
        out.append((np.array(Q), body.forces.copy(), body.counters.copy(),
                    [ln.now.r.copy() for ln in lines], mode.recs.copy()))
        for i, ln in enumerate(lines):
            rec = np.zeros(13)
            K.record_into(ln.now.r, ln.now.f, ln.work.tens, ln.par.S[K.S_ZC], ln.par.s_nodes,
                          rec)
            np.testing.assert_array_equal(mode.recs[i, :13], rec)
    (Qa, fa, ca, ra, reca), (Qb, fb, cb, rb, recb) = out
    np.testing.assert_array_equal(reca, recb)
    np.testing.assert_array_equal(Qa, Qb)
    np.testing.assert_array_equal(fa, fb)
    np.testing.assert_array_equal(ca, cb)
    for x, y in zip(ra, rb):
        np.testing.assert_array_equal(x, y)
    assert ca[:, 0].min() > 0


_NOJIT = """
import numpy as np
from tests.solvers.test_fe_threads import _packed
from floatmoor.mooring.fe.line import FELine
from floatmoor.mooring.fe.multi import ParallelLines, advance_lines, body_accept
fm = _packed()
body, lines = fm._packed
mode = ParallelLines(np.zeros(3, np.int64), 2, np.zeros((3, 16)))
for k in range(1, 4):
    pose = np.array([0.5 * k, 0.2 * k, 0.0, 0.0, 0.0, 0.01 * k])
    vel = np.array([2.5, 1.0, 0.0, 0.0, 0.0, 0.05])
    assert advance_lines(mode, 0.2 * k, 0.2, 1, FELine.MAX_SPLIT, pose, vel, body, lines) == 0
    body_accept(body.on, lines)
print(" ".join(repr(float(x)) for x in body.Q))
"""


def test_parallel_kernel_runs_without_jit():
    """The parallel kernel (and its dispatch) also runs as plain Python (NUMBA_DISABLE_JIT=1)
    and gives the numbers of the compiled kernel."""
    vals = []
    for flag in ("1", "0"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=flag, PYTHONPATH=str(ROOT))
        out = subprocess.run([sys.executable, "-c", _NOJIT], env=env, cwd=ROOT,
                             capture_output=True, text=True, check=True)
        vals.append([float(x) for x in out.stdout.strip().splitlines()[-1].split()])
    assert np.allclose(vals[0], vals[1], rtol=1e-9, atol=1e-9 * np.abs(vals[1]).max())
    assert np.abs(vals[1]).max() > 1e5


# -- the option ------------------------------------------------------------------------------
def _flagship(tmp_path, solver) -> Path:
    import yaml
    d = yaml.safe_load((ROOT / "scenes" / "floatel_100yr_fe.yaml").read_text())
    for key in ("vessel", "environment", "mooring"):
        d[key] = str((ROOT / "scenes" / d[key]).resolve())
    d["solver"] = solver
    p = tmp_path / "fe.yaml"
    p.write_text(yaml.safe_dump(d))
    return p


@pytest.mark.parametrize("bad", [0, -2, 1.5, "many", True, None, [2]])
def test_bad_threads_is_a_scene_error(tmp_path, bad):
    with pytest.raises(SceneError, match="solver.threads") as e:
        load_scene(_flagship(tmp_path, {"threads": bad}))
    assert "a positive integer or auto" in str(e.value)


def test_threads_option_and_its_caps(tmp_path):
    """``threads: 2`` and ``auto`` read from the scene (still the exact path: no approximation);
    ``auto`` is numba's pool, a number is at most the pool; a process among W workers takes at
    most cores // W threads (at least 1), a campaign task 1; a command-line value replaces the
    scene's before the cap."""
    sc = load_scene(_flagship(tmp_path, {"threads": 2}))
    assert sc.solver.threads == 2 and sc.solver.is_default
    assert "threads 2" in sc.describe()
    auto = load_scene(_flagship(tmp_path, {"threads": "auto"})).solver
    pool = available_threads()
    assert run_threads(auto) == pool == numba.config.NUMBA_NUM_THREADS
    assert run_threads(SolverSpec(threads=10 * pool)) == pool
    assert run_threads(None) == 1 and run_threads(SolverSpec()) == 1
    cores = len(os.sched_getaffinity(0))
    assert worker_thread_cap(1) == cores and worker_thread_cap(10 * cores) == 1
    assert worker_thread_cap(2) == max(1, cores // 2)
    assert with_thread_cap(None, 4) is None
    assert with_thread_cap(sc.solver, 1).threads == 1
    assert with_thread_cap(sc.solver, 8).threads == min(2, pool)
    assert with_thread_cap(None, 8, threads="auto").threads == pool
    assert with_thread_cap(sc.solver, 8, threads=1).threads == 1
    assert dataclasses.replace(sc.solver, threads=1) == SolverSpec(threads=1)
    assert parse_threads("3") == 3 and parse_threads("auto") == "auto"


def test_run_command_threads_flag(tmp_path, capsys):
    """``floatmoor run --threads``: a bad value is a usage error (exit 2); a good one runs and
    the result file records the threads used: ``auto`` takes one thread for lines that fit the
    SIMD lanes (the same node count: the lanes on one thread beat the lines in threads,
    benchmarks/RESULTS.md), the pool (at most the workers' cap) for lines that do not."""
    import xarray as xr

    from floatmoor.cli import main

    p = _scene(tmp_path, n_elements=4, name="thr",
               analysis={"duration": 6.0, "dt": 0.2, "transient": 2.0, "ramp": 2.0,
                         "seeds": 1})
    assert main(["run", str(p), "--threads", "0", "--out", str(tmp_path / "x")]) == 2
    assert "expected an integer >= 1 or auto" in capsys.readouterr().err
    out = tmp_path / "out"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["run", str(p), "--out", str(out), "--workers", "1",
                     "--threads", "auto"]) == 0
    with xr.open_dataset(next(out.glob("*.nc"))) as ds:
        assert ds.attrs["fe_threads"] == 1
    # lines of different node counts do not fit one lane group: auto is the pool
    from types import SimpleNamespace as NS

    from floatmoor.solvers.fe_coupling import auto_threads
    mixed = [NS(n_nodes=51, integrator="generalized_alpha"),
             NS(n_nodes=41, integrator="generalized_alpha")]
    assert auto_threads(mixed, 2) == 2


@pytest.mark.slow
@pytest.mark.skipif(available_threads() < 2, reason="numba has one thread here")
def test_one_thread_compiles_no_parallel_kernel(tmp_path):
    """From an empty numba cache, a one-thread FE run compiles the serial kernel (the lines as
    lanes) and not the parallel one (compile seconds only for scenes that ask for threads); a
    two-thread run after it compiles the parallel kernel, each kernel for one signature."""
    from tests.test_first_run import _run

    first, second = _run("""
from floatmoor.analyses.simulate import simulate
from floatmoor.io.solver_section import SolverSpec
simulate("scenes/floatel_100yr_fe.yaml", seed=1, duration=2.0)
n1 = len(compiled)
simulate("scenes/floatel_100yr_fe.yaml", seed=1, duration=2.0, solver=SolverSpec(threads=2))
print(json.dumps([compiled[:n1], compiled[n1:]]))
""", tmp_path)
    names1 = [c[0] for c in first]
    names2 = [c[0] for c in second]
    multi = "floatmoor.mooring.fe.multi."
    assert "floatmoor.mooring.fe.lanes_body.lanes_body_step" in names1
    assert multi + "body_advance_parallel" not in names1
    assert names2.count(multi + "body_advance_parallel") == 1
    assert multi + "body_advance" not in names2


@pytest.mark.slow
@pytest.mark.skipif(available_threads() < 2, reason="numba has one thread here")
def test_two_threads_compiled_first_give_the_one_thread_result(tmp_path):
    """From an empty numba cache, a two-thread FE run compiled before any one-thread run gives
    the one-thread run's tensions bit for bit.  The parallel kernel once lost the lines'
    accepts when it was compiled first in a process (the advance and the accept inlined into
    its ``prange`` body): the lines never moved, 1666 kN of maximum tension in 60 s against
    2809 kN, while the tests that compiled the serial kernel first passed.  Without the fix the
    tensions of this 3 s run stay at their start values."""
    from tests.test_first_run import _run

    two, one = _run("""
from floatmoor.analyses.simulate import simulate
from floatmoor.io.solver_section import SolverSpec
two = simulate("scenes/floatel_100yr_fe.yaml", seed=1, duration=3.0, solver=SolverSpec(threads=2))
one = simulate("scenes/floatel_100yr_fe.yaml", seed=1, duration=3.0)
print(json.dumps([two.line_tension.values.tolist(), one.line_tension.values.tolist()]))
""", tmp_path)
    two = np.array(two)
    one = np.array(one)
    np.testing.assert_array_equal(two, one)
    # the lines move: the tensions change from their start values
    assert np.abs(one[-1] - one[0]).max() > 1.0


def test_wait_policy_spins_only_on_idle_cores():
    """The OpenMP wait of the FE threads: a bounded spin when the threads find idle cores
    (measured on the idle 2-core machine: 2 threads 1.57x faster than one, passive threads no
    faster), sleeping threads when other work holds the cores (measured with two busy processes
    on the 2 cores: a 900 s run took 41 s spinning against 5 s with one thread and 3.6-6.5 s
    passive; benchmarks/RESULTS.md)."""
    from floatmoor.solvers.fe_coupling import GOMP_SPINCOUNT, idle_cores, wait_policy

    assert wait_policy(2, 2.0) == ("GOMP_SPINCOUNT", GOMP_SPINCOUNT)
    assert wait_policy(2, 1.8) == ("GOMP_SPINCOUNT", GOMP_SPINCOUNT)
    assert wait_policy(2, 1.7) == ("OMP_WAIT_POLICY", "PASSIVE")
    assert wait_policy(2, 0.3) == ("OMP_WAIT_POLICY", "PASSIVE")
    assert wait_policy(4, 2.0) == ("OMP_WAIT_POLICY", "PASSIVE")
    assert wait_policy(2, None) == ("OMP_WAIT_POLICY", "PASSIVE")
    idle = idle_cores(0.05)
    assert idle is None or 0.0 <= idle <= (os.cpu_count() or 1) + 1e-9
