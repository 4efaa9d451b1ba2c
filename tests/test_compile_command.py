"""``floatmoor compile``: the kernels of the scenes' storms compiled ahead of their first run.

The slow test runs the command in a fresh process with an empty numba cache on the flagship's
quasi-static and finite-element scenes, then, in new processes, checks that a coupled FE storm
compiles nothing (numba's compile events, recorded by tests/test_first_run.py's helper) and that the
command finds nothing left to compile.  Before the FE lines' typed list was built by cached
kernels, every new process compiled numba's own list helpers (``_make_list``, ``_append``)
before its first FE storm: this test fails on that.
"""

import os
import subprocess
import sys
from pathlib import Path

import pytest

from floatmoor.cli import main
from tests.test_first_run import _run

ROOT = Path(__file__).resolve().parents[1]
QS = "scenes/floatel_100yr.yaml"
FE = "scenes/floatel_100yr_fe.yaml"


def _env(cache):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache),
               PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    env.pop("NUMBA_DISABLE_JIT", None)
    return env


def _floatmoor(args, cache):
    out = subprocess.run([sys.executable, "-m", "floatmoor", *args], env=_env(cache), cwd=ROOT,
                         capture_output=True, text=True, timeout=1200)
    assert out.returncode == 0, out.stderr[-3000:]
    return out.stdout


FE_STORM = """
import warnings
from floatmoor.analyses.simulate import simulate
warnings.simplefilter("ignore")
simulate("scenes/floatel_100yr_fe.yaml", duration=60.0, transient=0.0)
print(json.dumps(compiled))
"""


@pytest.mark.slow  # reason: compiles the QS and FE storm kernels from an empty cache (~1.5 min)
def test_compile_then_storms_compile_nothing(tmp_path):
    cache = tmp_path / "numba_cache"  # the folder tests/test_first_run.py::_run uses
    first = _floatmoor(["compile", QS, FE], cache)
    assert f"{QS}: " in first and "kernels compiled in" in first, first
    assert f"{FE}: " in first
    # a new process on the same cache, numba's compile events recorded
    assert _run(FE_STORM, tmp_path) == []
    again = _floatmoor(["compile", QS, FE], cache)
    assert again.count("nothing to compile (loaded from the cache)") == 2, again


def test_a_bad_scene_stops_before_anything_is_compiled(tmp_path, capsys):
    good = ROOT / QS
    missing = tmp_path / "nope.yaml"
    assert main(["compile", str(good), str(missing)]) == 2
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err
    assert cap.err.startswith("floatmoor: error: ") and str(missing) in cap.err, cap.err
    assert "compiled" not in cap.out
