"""Shared fixtures of the hydro tests: the public WAMIT reference files."""

import os
import warnings
from pathlib import Path

import pytest

REFERENCE = Path(os.environ.get("FLOATMOOR_REFERENCE", "/work/shared/reference"))
VESSELS = Path(__file__).resolve().parents[2] / "vessels"


@pytest.fixture(scope="session")
def oc3_root():
    root = REFERENCE / "OC3_Hywind" / "Spar"
    if not Path(str(root) + ".1").exists():
        pytest.skip("OC3 WAMIT reference files not available")
    return root


@pytest.fixture(scope="session")
def oc4_root():
    root = REFERENCE / "OC4_DeepCwind_semi" / "marin_semi"
    if not Path(str(root) + ".1").exists():
        pytest.skip("OC4 WAMIT reference files not available")
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
