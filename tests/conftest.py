"""Scheduling of the default run over two test processes (pytest-xdist ``--dist loadfile``).

Every test file is one unit of work (a file's tests run in one process), except the files that
run the coupled finite-element time domain (:mod:`floatmoor.solvers.fe_coupling` and the
SIMD-lane kernels under it).  From an empty numba cache those kernels take 150-250 s to compile,
and with one unit per file both processes reached such a file at about the same time and
compiled them side by side (measured on a clean clone, 2026-11-28: 154 s and 248 s of
``fe_coupling`` compilation in the two processes; pytest 617 s in all).  The files below form
one unit, which runs first in one process; the other process meanwhile takes the other files.

xdist's own ``loadgroup`` would do this with marks, but xdist 3.8 renames the node ids through
an attribute pytest 9 no longer reads (the groups silently do not form); hence a scheduler of
our own (:func:`pytest_xdist_make_scheduler`: ``loadfile`` with the group as one scope) and the
order of the units set in the workers' collection (:func:`pytest_collection_modifyitems`,
with ``--no-loadscope-reorder``).

The list was found by recording which tests call ``fe_coupling.run`` (a scratch plugin over
the whole default run).  A file missing from it still passes; its process then compiles the
kernels again.  :func:`pytest_configure` keeps the list honest: a test of a file not in it
that runs the coupled FE time domain gets a :class:`FECoupledFileWarning` naming the file (in
the warnings summary; :class:`_FECouplingWatch` wraps the module's ``run`` when it is
imported).  ``-n 0`` runs everything in one process in file order.
"""

from __future__ import annotations

import collections
import sys
import warnings

FE_COUPLED = "fe-coupled"
FE_COUPLED_FILES = (
    "tests/io/test_example_scenes.py",     # `floatmoor check` of the FE scene runs its lines
    "tests/io/test_import_moordyn.py",
    "tests/solvers/test_fe_lanes.py",
    "tests/solvers/test_fe_stages.py",
    "tests/solvers/test_fe_threads.py",
    "tests/solvers/test_time_domain_fe.py",
    "tests/test_bit_identity.py",
    "tests/test_cli_lines.py",
    "tests/test_simulate.py",
)


def _scope(nodeid: str) -> str:
    f = nodeid.split("::", 1)[0]
    return FE_COUPLED if f in FE_COUPLED_FILES else f


def pytest_xdist_make_scheduler(config, log):
    """``--dist loadfile`` with the coupled-FE files as one scope."""
    if config.getoption("dist", "no") != "loadfile":
        return None
    from xdist.scheduler import LoadFileScheduling

    class _FileScheduling(LoadFileScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return _scope(nodeid)

    return _FileScheduling(config, log)


def pytest_collection_modifyitems(config, items):
    """In xdist's workers (their collection gives the controller its order): the coupled-FE
    scope first, then the files by their number of tests, largest first (xdist's own order,
    which ``--no-loadscope-reorder`` turns off)."""
    if not hasattr(config, "workerinput"):
        return
    groups = collections.defaultdict(list)
    for item in items:
        groups[_scope(item.nodeid)].append(item)
    order = sorted(groups, key=lambda g: (g != FE_COUPLED, -len(groups[g])))
    items[:] = [item for g in order for item in groups[g]]


class FECoupledFileWarning(UserWarning):
    """A test file that runs the coupled FE time domain is missing from FE_COUPLED_FILES."""


def _wrap_run(mod) -> None:
    """Replace ``mod.run`` (``fe_coupling``) by a wrapper that warns when the running test's
    file is not in :data:`FE_COUPLED_FILES`.  ``time_domain`` imports ``run`` from the module
    at each call, so the wrapper is what it gets."""
    plain = mod.run

    def run(*args, **kwargs):
        import os
        current = os.environ.get("PYTEST_CURRENT_TEST", "")
        path = current.split("::", 1)[0]
        if path and path not in FE_COUPLED_FILES:
            warnings.warn(f"{path} runs the coupled FE time domain (fe_coupling.run) but is "
                          "not in tests/conftest.py FE_COUPLED_FILES: from an empty numba "
                          "cache its process compiles the FE kernels again",
                          FECoupledFileWarning, stacklevel=2)
        return plain(*args, **kwargs)

    mod.run = run


class _FECouplingWatch:
    """A meta-path finder that wraps ``fe_coupling.run`` (:func:`_wrap_run`) when the module is
    first imported, whichever test imports it."""

    NAME = "floatmoor.solvers.fe_coupling"

    def find_spec(self, name, path=None, target=None):
        if name != self.NAME:
            return None
        import importlib.util
        sys.meta_path.remove(self)
        try:
            spec = importlib.util.find_spec(name)
        finally:
            sys.meta_path.insert(0, self)
        if spec is None or spec.loader is None:
            return spec
        plain_exec = spec.loader.exec_module

        def exec_module(module):
            plain_exec(module)
            _wrap_run(module)

        spec.loader.exec_module = exec_module
        return spec


def pytest_configure(config):
    if "floatmoor.solvers.fe_coupling" in sys.modules:
        _wrap_run(sys.modules["floatmoor.solvers.fe_coupling"])
    else:
        sys.meta_path.insert(0, _FECouplingWatch())
