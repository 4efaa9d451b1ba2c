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
* ``fe``: the coupled finite-element flagship (``scenes/floatel_100yr_fe.yaml``), 1500 s, with
  the FE lines' ``newton: exact`` iteration and the ``solver: {fe_stages: catenary}`` stages
  (the default until 2026-11-28) set explicitly (the default, a 1 um position
  stop; since 2026-11-27 from the fairlead's trapezoidal predictor, whose digest was written on
  an x86-64-v3 machine only, so an x86-64-v4 machine skips it with the table's note);
* ``fe_force``: the same with the opt-in ``newton: force`` iteration (a stop in force terms,
  which moves the FE answer within the stop's bound; its digest was written on an x86-64-v3
  machine only, so an x86-64-v4 machine skips it with the table's note);
* ``fe_linear``: the same scene as the shipped file runs it (``newton: exact``, the default
  ``fe_stages: linear`` since 2026-11-28; written on an x86-64-v3 machine only, like ``fe``);
* ``fe_linear`` solves the FE lines' stiffness at every step (``solver:
  {fe_stiffness_interval: 0}``), as the code did when its digest was written (the default
  since 2026-11-28 is every 1.0 s, compared with every step in tests/solvers/test_fe_stages.py);
* the three ``fe`` cases run the mesh their digests were written with, 50 elements per line
  shared by length (23 / 22 / 5), given as ``n_elements: 50``: the shipped file gives the
  elements per segment since 2026-11-28 ([12, 26, 12], a mesh study, benchmarks/RESULTS.md),
  a change of the scene, not of the code, which these digests guard;
* ``fd``: the frequency-domain analysis of the flagship scene (every variable of the Dataset).

The bits depend on the machine's vector instruction set, not only on the code: numpy picks its
SIMD kernels (sin, cos, exp of the wave realisation, reductions) at run time, and the same code
gives other digests on an x86-64-v4 machine (AVX-512) than on an x86-64-v3 one (AVX2).  The
file therefore keeps one table of digests per machine kind (:func:`machine_kind`), each written
on a machine of that kind (``--write`` rewrites the current kind's table and keeps the others).
A kind without a table, or a case missing from its table (a deliberate change of numbers made
on a machine of another kind, which cannot regenerate this one: the table's ``_note`` says
which and why), is skipped with that reason; every other case must be bit-identical.  A table's
``_added`` lists variables added to a case after its digests were written (their values cannot
be compared on that kind; every stored variable still must be).
"""

from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path

import numpy as np
import pytest

if __package__ in (None, ""):   # run as a script: python tests/test_bit_identity.py --write
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.fe_flagship import with_fe_options  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
DATA = Path(__file__).resolve().parent / "data" / "bit_identity.json"

CASES = {
    "qs": ("scenes/floatel_100yr.yaml", {}),
    "qs_forces": ("scenes/floatel_100yr.yaml", {"duration": 1500.0, "record_forces": True}),
    "slender": ("notebooks/viscous_drift/case2.yaml", {"duration": 1500.0}),
    "correction": ("notebooks/viscous_drift/case5.yaml", {"duration": 1500.0}),
    "fe": ("scenes/floatel_100yr_fe.yaml",
           {"duration": 1500.0, "fe": {"newton": "exact", "n_elements": 50},
            "solver": {"fe_stages": "catenary"}}),
    "fe_force": ("scenes/floatel_100yr_fe.yaml",
                 {"duration": 1500.0, "fe": {"newton": "force", "n_elements": 50},
                  "solver": {"fe_stages": "catenary"}}),
    "fe_linear": ("scenes/floatel_100yr_fe.yaml", {"duration": 1500.0,
                                                   "fe": {"n_elements": 50},
                                                   "solver": {"fe_stiffness_interval": 0.0}}),
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
    if kw is not None and "fe" in kw:
        kw = dict(kw)
        scene = with_fe_options(scene, **kw.pop("fe"))
    if kw is not None and "solver" in kw:
        from floatmoor.io.solver_section import SolverSpec
        kw = dict(kw)
        kw["solver"] = SolverSpec(**kw["solver"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        if kw is None:
            return digest(floatmoor.frequency_domain(scene))
        return digest(floatmoor.simulate(scene, seed=1, **kw))


def machine_kind() -> str:
    """The vector instruction level numpy dispatches to: ``x86-64-v4`` (AVX-512),
    ``x86-64-v3`` (AVX2), ``x86-64-v2``, or the machine's architecture name elsewhere."""
    import platform
    try:
        from numpy._core._multiarray_umath import __cpu_features__ as f
    except ImportError:  # pragma: no cover - numpy < 2
        from numpy.core._multiarray_umath import __cpu_features__ as f
    for level in ("X86_V4", "X86_V3", "X86_V2"):
        if f.get(level):
            return "x86-64-" + level[-2:].lower()
    return platform.machine()


def stored_tables() -> dict:
    return json.loads(DATA.read_text())


@pytest.mark.parametrize("case", list(CASES))
def test_bit_identical(case):
    kind = machine_kind()
    tables = stored_tables()
    table = tables.get(kind)
    if table is None:
        pytest.skip(f"no digests stored for machine kind {kind} (stored: "
                    f"{', '.join(k for k in tables if not k.startswith('_'))}); run "
                    "`python tests/test_bit_identity.py --write` on one")
    if case not in table:
        pytest.skip(f"{case}: no digest for machine kind {kind}: "
                    f"{table.get('_note', 'not stored')}")
    stored = table[case]
    got = compute(case)
    added = set(table.get("_added", {}).get(case, ()))
    assert set(got) == set(stored) | added, f"{case}: variables differ"
    changed = [k for k in stored if got[k] != stored[k]]
    assert not changed, f"{case}: not bit-identical on {kind}: {changed}"


def test_every_kind_has_a_table_of_the_current_cases():
    """The file is well formed: one table per machine kind, each naming only known cases."""
    tables = stored_tables()
    assert tables, "no digests stored"
    for kind, table in tables.items():
        if kind.startswith("_"):
            continue
        assert set(table) - {"_note", "_added"} <= set(CASES), (kind, set(table))


if __name__ == "__main__":
    if "--write" in sys.argv:
        tables = stored_tables() if DATA.exists() else {}
        kind = machine_kind()
        tables[kind] = {c: compute(c) for c in CASES}
        DATA.write_text(json.dumps(tables, indent=1) + "\n")
        print(f"wrote the {kind} digests into {DATA}")
