"""The run store of ``benchmarks/bench_fe_moordyn.py``: a stored run is reused only while
everything that produced it is unchanged (the task, the fairlead track, our sources), and a
reused run is the run itself (its tensions and CPU time bit for bit)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="module")
def bench():
    spec = importlib.util.spec_from_file_location("bench_fe_moordyn",
                                                  ROOT / "benchmarks" / "bench_fe_moordyn.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod          # its dataclasses look their module up there
    try:
        spec.loader.exec_module(mod)
        yield mod
    finally:
        sys.modules.pop(spec.name, None)


def _track(bench, amplitude=3.0):
    from floatmoor.mooring.fe.prescribed import HarmonicMotion
    return bench.short_track(HarmonicMotion(amplitude=(-amplitude, 0.0, 0.0), period=15.0,
                                            ramp=5.0), 10.0, 5.0)


def test_a_stored_run_is_reused_only_while_its_inputs_are_unchanged(bench, tmp_path,
                                                                   monkeypatch):
    case = "oc3-harmonic"
    task = ("fm", 10, 1, "exact")
    monkeypatch.setitem(bench._TRACKS, case, [_track(bench)])
    runner = bench.Runner(case, jobs=1, store=str(tmp_path))
    (T1, cpu1), = runner.run([(0, task)])
    assert len(list(tmp_path.glob("*.npz"))) == 1
    (T2, cpu2), = runner.run([(0, task)])            # from the store: the same run
    assert np.array_equal(T1, T2) and cpu1 == cpu2
    (T3, _), = runner.run([(0, task)], fresh=True)    # a timing repeat: run again, same answer
    assert np.array_equal(T1, T3)
    assert len(list(tmp_path.glob("*.npz"))) == 1     # not stored twice
    # another setting, another track, other sources: a new run each, never the stored one
    runner.run([(0, ("fm", 10, 2, "exact"))])
    assert len(list(tmp_path.glob("*.npz"))) == 2
    monkeypatch.setitem(bench._TRACKS, case, [_track(bench, amplitude=2.0)])
    (T4, _), = runner.run([(0, task)])
    assert len(list(tmp_path.glob("*.npz"))) == 3 and not np.array_equal(T1, T4)
    monkeypatch.setitem(bench._TRACKS, case, [_track(bench)])
    monkeypatch.setattr(bench, "_SOURCES", "an edited floatmoor")
    runner.run([(0, task)])
    assert len(list(tmp_path.glob("*.npz"))) == 4


def test_moordyn_runs_are_keyed_by_the_text_moordyn_is_given(bench, monkeypatch):
    case = "oc3-harmonic"
    monkeypatch.setitem(bench._TRACKS, case, [_track(bench)])
    k = bench._task_key(case, 0, ("md", 20, 2e-3, "RK2"))
    assert k == bench._task_key(case, 0, ("md", 20, 2e-3, "RK2"))
    assert k != bench._task_key(case, 0, ("md", 20, 1e-3, "RK2"))
    monkeypatch.setattr(bench, "BA_OC3", bench.BA_OC3 * 1.01)     # in MoorDyn's input file
    assert k != bench._task_key(case, 0, ("md", 20, 2e-3, "RK2"))


def test_moordyn_runs_are_keyed_by_the_code_that_steps_them(bench, monkeypatch):
    """The 2026-11-27 bug (MoorDyn fed the end-of-step state) lived in the stepping loop, not in
    MoorDyn's input: a run stored before such a fix must not be reused after it."""
    case = "oc3-harmonic"
    monkeypatch.setitem(bench._TRACKS, case, [_track(bench)])
    k = bench._task_key(case, 0, ("md", 20, 2e-3, "RK2"))
    real = bench.inspect.getsource

    def edited(obj):
        return real(obj) + ("# edited" if obj is bench.run_moordyn else "")

    monkeypatch.setattr(bench.inspect, "getsource", edited)
    assert k != bench._task_key(case, 0, ("md", 20, 2e-3, "RK2"))
