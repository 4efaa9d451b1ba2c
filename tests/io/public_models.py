"""The public OpenFAST floating models of ``tests/data/openfast`` laid out as published.

Each model is a folder tree as in its source repository (the ``.fst`` refers to its other files
by relative paths such as ``../5MW_Baseline/HydroData/Spar``).  The repository stores each file
once: the OC3 and OC4 files the vessels already hold (``vessels/*/source``) are not copied
again, the IEA-15 OpenFAST v4 file set stores only the files that differ from the v3 set, and
the WAMIT ``.3`` files are stored gzip-compressed.  :func:`lay_out` writes a model's tree into a
folder, every file byte for byte as published (the ``.3`` files decompressed), and returns the
path of its ``.fst``: the import reads the unmodified files.

Provenance and licences: ``tests/data/openfast/README.md``.
"""

from __future__ import annotations

import gzip
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "openfast"

_OC3 = "glue-codes/openfast/5MW_OC3Spar_DLL_WTurb_WavesIrr"
_OC4 = "glue-codes/openfast/5MW_OC4Semi_WSt_WavesWN"
_HD = "glue-codes/openfast/5MW_Baseline/HydroData"
_IEA15 = "OpenFAST/IEA-15-240-RWT-UMaineSemi"


def _tree(folder: str, layout_prefix: str = "") -> list[tuple[str, Path]]:
    """Every file under ``DATA/folder`` as (path in the layout, source)."""
    base = DATA / folder
    return [(layout_prefix + str(p.relative_to(base)), p) for p in sorted(base.rglob("*"))
            if p.is_file() and p.name != "LICENSE"]


def _vessel_sources(vessel: str, case: str, hydro: tuple[str, ...]) -> list[tuple[str, Path]]:
    src = ROOT / "vessels" / vessel / "source"
    out = []
    for p in sorted(src.iterdir()):
        if p.name in hydro:
            out.append((f"{_HD}/{p.name}", p))
        elif p.suffix in (".fst", ".dat"):
            out.append((f"{case}/{p.name}", p))
    return out


def _rtest_shared():
    return [(path, src) for path, src in _tree("r-test")
            if path.startswith("glue-codes/openfast/5MW_Baseline/NRELOffshrBsline5MW_Blade")]


def _rtest_case(case: str, hydro_root: str):
    return ([(p, s) for p, s in _tree("r-test") if p.startswith(case + "/")]
            + [(p, s) for p, s in _tree("r-test") if p.startswith(f"{_HD}/{hydro_root}.")]
            + _rtest_shared())


MODELS = {
    # OpenFAST r-test (Sept 2024, OpenFAST v4 file formats, waves in SeaState)
    "oc3-hywind": {
        "fst": f"{_OC3}/5MW_OC3Spar_DLL_WTurb_WavesIrr.fst",
        "files": lambda: (_vessel_sources("oc3_hywind", _OC3, ("Spar.1", "Spar.3", "Spar.hst"))
                          + [(p, s) for p, s in _tree("r-test") if p.startswith(_OC3 + "/")]
                          + _rtest_shared()),
    },
    "oc4-deepcwind": {
        "fst": f"{_OC4}/5MW_OC4Semi_WSt_WavesWN.fst",
        "files": lambda: (_vessel_sources("oc4_semi", _OC4,
                                          ("marin_semi.1", "marin_semi.hst", "marin_semi.12d"))
                          + [(p, s) for p, s in _tree("r-test") if p.startswith(_OC4 + "/")]
                          + _rtest_shared()),
    },
    "itibarge": {
        "fst": "glue-codes/openfast/5MW_ITIBarge_DLL_WTurb_WavesIrr/"
               "5MW_ITIBarge_DLL_WTurb_WavesIrr.fst",
        "files": lambda: _rtest_case("glue-codes/openfast/5MW_ITIBarge_DLL_WTurb_WavesIrr",
                                     "Barge"),
    },
    "mit-nrel-tlp": {
        "fst": "glue-codes/openfast/5MW_TLP_DLL_WTurb_WavesIrr_WavesMulti/"
               "5MW_TLP_DLL_WTurb_WavesIrr_WavesMulti.fst",
        "files": lambda: _rtest_case("glue-codes/openfast/5MW_TLP_DLL_WTurb_WavesIrr_WavesMulti",
                                     "tlpmit"),
    },
    # IEA Wind TCP Task 37: IEA-15-240-RWT on the UMaine VolturnUS-S, OpenFAST v3 files
    # (waves in HydroDyn) and OpenFAST v4 files (waves in SeaState)
    "iea15-volturnus-v3": {
        "fst": f"{_IEA15}/IEA-15-240-RWT-UMaineSemi.fst",
        "files": lambda: _tree("IEA-15-240-RWT"),
    },
    "iea15-volturnus-v4": {
        "fst": f"{_IEA15}/IEA-15-240-RWT-UMaineSemi.fst",
        "files": lambda: ([(p, s) for p, s in _tree("IEA-15-240-RWT")
                           if not (DATA / "IEA-15-240-RWT-v4" / p).is_file()]
                          + _tree("IEA-15-240-RWT-v4")),
    },
    # IEA-22-280-RWT on its semi-submersible (its .fst names the strip-theory HydroDyn file;
    # the potential-flow one is IEA-22-280-RWT-Semi_HydroDyn_PotMod.dat)
    "iea22-semi": {
        "fst": "OpenFAST/IEA-22-280-RWT-Semi/IEA-22-280-RWT-Semi.fst",
        "files": lambda: _tree("IEA-22-280-RWT"),
    },
}


def lay_out(name: str, folder) -> Path:
    """Write the model ``name`` (a key of :data:`MODELS`) into ``folder`` as published; return
    the path of its ``.fst``."""
    folder = Path(folder)
    model = MODELS[name]
    for rel, src in model["files"]():
        if rel.endswith(".gz"):
            dest = folder / rel[:-3]
            dest.parent.mkdir(parents=True, exist_ok=True)
            with gzip.open(src, "rb") as f_in, open(dest, "wb") as f_out:
                shutil.copyfileobj(f_in, f_out)
        else:
            dest = folder / rel
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(src, dest)
    return folder / model["fst"]


def natural_periods(built, pose_stiffness=None):
    """Undamped natural periods (s) of a built scene's six rigid-body modes, in DOF order
    (each mode assigned to the DOF that dominates its shape): the eigenvalues of
    K - w^2 (M + A(w)), with the database's added mass A at each mode's own frequency (fixed
    point), K the vessel's total restoring plus ``pose_stiffness`` (the mooring's 6x6
    stiffness at the equilibrium)."""
    import numpy as np
    import scipy.linalg

    v = built.vessel
    K = np.asarray(v.total_restoring, float).copy()
    if pose_stiffness is not None:
        K = K + np.asarray(pose_stiffness, float)
    K = 0.5 * (K + K.T)
    M = np.asarray(v.mass_matrix, float)
    db = v.database
    omega = db["omega"].values
    A = db["added_mass"].values  # (omega, radiating, influenced)

    def added(w):
        if w <= omega[0]:
            return A[0]
        if w >= omega[-1]:
            return A[-1]
        k = np.searchsorted(omega, w)
        t = (w - omega[k - 1]) / (omega[k] - omega[k - 1])
        return (1 - t) * A[k - 1] + t * A[k]

    periods = np.zeros(6)
    # start every DOF at 0.05 rad/s, iterate the eigenproblem at each mode's frequency
    w_dof = np.full(6, 0.3)
    for _ in range(30):
        new = np.zeros(6)
        for dof in range(6):
            Mt = M + added(w_dof[dof])
            Mt = 0.5 * (Mt + Mt.T)
            lam, vec = scipy.linalg.eigh(K, Mt)
            # the mode in which ``dof`` dominates (kinetic-energy share)
            share = np.abs(vec) * np.sqrt(np.abs(np.diag(Mt)))[:, None]
            share = share / share.sum(axis=0)
            j = int(np.argmax(share[dof]))
            new[dof] = np.sqrt(max(lam[j], 0.0))
        if np.allclose(new, w_dof, rtol=1e-6):
            break
        w_dof = new
    periods = 2 * np.pi / w_dof
    return periods
