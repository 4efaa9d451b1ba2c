"""Scheduling of the default run over two test processes (pytest-xdist ``--dist loadgroup``).

Every test file is one group (as ``--dist loadfile``: a file's tests run in one process), except
the files that run the coupled finite-element time domain (:mod:`floatmoor.solvers.fe_coupling`
and the SIMD-lane kernels under it).  From an empty numba cache those kernels take 150-250 s to
compile, and with one group per file both processes reached such a file at about the same time
and compiled them side by side (measured on a clean clone, 2026-11-28: 154 s and 248 s of
``fe_coupling`` compilation in the two processes; pytest 617 s in all).  The files below form
one group, which runs first in one process; the other process meanwhile takes the other files.

The list was found by recording which tests call ``fe_coupling.run`` (a scratch plugin over
the whole default run).  A file missing from it still passes; its process then
compiles the kernels again.  ``-n 0`` runs everything in one process in file order.
"""

from __future__ import annotations

import collections

import pytest

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


def _file(item) -> str:
    return item.nodeid.split("::", 1)[0]


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """Group every test by its file (the coupled-FE files in one group) and put the groups in
    the order the processes take them: the coupled-FE group first, then the files by their
    number of tests, largest first (xdist's own order for ``loadfile``).  Runs before xdist's
    hook, which turns the ``xdist_group`` marks into the node-id suffix its scheduler reads."""
    # the controller has --dist; xdist's workers run with dist "no" and its flag loadgroup
    if config.getoption("dist", "no") != "loadgroup" and not getattr(config.option,
                                                                    "loadgroup", False):
        return
    groups = collections.defaultdict(list)
    for item in items:
        f = _file(item)
        name = FE_COUPLED if f in FE_COUPLED_FILES else f
        item.add_marker(pytest.mark.xdist_group(name))
        groups[name].append(item)
    order = sorted(groups, key=lambda g: (g != FE_COUPLED, -len(groups[g])))
    items[:] = [item for g in order for item in groups[g]]
