"""Shared fixtures of the hydro tests: the public WAMIT reference files.

The files are part of the repository (vessels/<vessel>/source/, OpenFAST r-test, Apache-2.0; see
the README there). A missing file is a test failure, not a skip.
"""

import warnings
from pathlib import Path

import pytest

VESSELS = Path(__file__).resolve().parents[2] / "vessels"


@pytest.fixture(scope="session")
def oc3_root():
    root = VESSELS / "oc3_hywind" / "source" / "Spar"
    if not Path(str(root) + ".1").exists():
        pytest.fail(f"OC3 WAMIT reference file {root}.1 missing from the repository")
    return root


@pytest.fixture(scope="session")
def oc4_root():
    root = VESSELS / "oc4_semi" / "source" / "marin_semi"
    if not Path(str(root) + ".1").exists():
        pytest.fail(f"OC4 WAMIT reference file {root}.1 missing from the repository")
    return root


@pytest.fixture(scope="session")
def oc3_db(oc3_root):
    from floatmoor.hydro import read_wamit
    return read_wamit(oc3_root)


@pytest.fixture(scope="session")
def oc4_db(oc4_root):
    from floatmoor.hydro import read_wamit
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # no .3 file: expected warning
        return read_wamit(oc4_root)
