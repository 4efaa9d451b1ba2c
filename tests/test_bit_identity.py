"""Bit-identity of the flagship results across restructurings of the kernels.

The digests in ``tests/data/bit_identity.json`` were computed on the code before the kernel
inputs were regrouped into bundles (commit 56ba94c, numba 0.68, this machine kind): a
restructuring that changes no arithmetic must reproduce every stored array to the last bit.
A deliberate change of numbers (a model fix) regenerates the file with
``python tests/test_bit_identity.py --write`` and says why in its commit.

Cases (all from the shipped scenes, seed 1):

* ``qs``: the quasi-static flagship storm (``scenes/floatel_100yr.yaml``), full 12000 s;
* ``qs_forces``: the same scene, 1500 s, with the force of every model recorded;
* ``slender``: slender-element viscous drift (``notebooks/viscous_drift/case2.yaml``), 1500 s;
* ``correction``: the correction formula (``notebooks/viscous_drift/case5.yaml``), 1500 s;
* ``fe``: the coupled finite-element flagship (``scenes/floatel_100yr_fe.yaml``), 1500 s;
* ``fd``: the frequency-domain analysis of the flagship scene (every variable of the Dataset).
"""

from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
DATA = Path(__file__).resolve().parent / "data" / "bit_identity.json"

CASES = {
    "qs": ("scenes/floatel_100yr.yaml", {}),
    "qs_forces": ("scenes/floatel_100yr.yaml", {"duration": 1500.0, "record_forces": True}),
    "slender": ("notebooks/viscous_drift/case2.yaml", {"duration": 1500.0}),
    "correction": ("notebooks/viscous_drift/case5.yaml", {"duration": 1500.0}),
    "fe": ("scenes/floatel_100yr_fe.yaml", {"duration": 1500.0}),
    "fd": ("scenes/floatel_100yr.yaml", None),
}


def digest(ds) -> dict:
    """sha256 (first 16 hex digits) of the bytes of every numeric variable of ``ds``."""
    out = {}
    for name in sorted(ds.data_vars):
        a = np.ascontiguousarray(ds[name].values)
        if a.dtype.kind in "fciub":
            out[name] = hashlib.sha256(a.tobytes()).hexdigest()[:16]
    return out


def compute(case: str) -> dict:
    import warnings

    import floatmoor
    path, kw = CASES[case]
    scene = floatmoor.load_scene(ROOT / path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        if kw is None:
            return digest(floatmoor.frequency_domain(scene))
        return digest(floatmoor.simulate(scene, seed=1, **kw))


@pytest.mark.parametrize("case", list(CASES))
def test_bit_identical(case):
    stored = json.loads(DATA.read_text())[case]
    got = compute(case)
    assert set(got) == set(stored), f"{case}: variables differ"
    changed = [k for k in stored if got[k] != stored[k]]
    assert not changed, f"{case}: not bit-identical: {changed}"


if __name__ == "__main__":
    if "--write" in sys.argv:
        DATA.write_text(json.dumps({c: compute(c) for c in CASES}, indent=1) + "\n")
        print(f"wrote {DATA}")
