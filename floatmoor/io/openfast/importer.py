"""OpenFAST floating model (``.fst``) -> floatmoor vessel, mooring and scene files.

Reads (every file as OpenFAST reads it, :mod:`floatmoor.io.openfast.reader`):

* the driver: gravity and water (from v3.1), the feature switches and the module files;
* ElastoDyn and its tower and blade files: every rigid mass (:mod:`.bodies`);
* HydroDyn: the WAMIT root (``PotFile``, relative to the HydroDyn file) and its scaling
  (``WAMITULEN``, water density and gravity), ``PtfmVol0`` and the centre of buoyancy, the
  body reference point, ``AddF0`` and the full 6x6 ``AddCLin``, ``AddBLin`` and ``AddBQuad``,
  filled members (ballast, :mod:`.bodies`), and the waves when HydroDyn holds them (up to
  OpenFAST v3.5);
* SeaState (OpenFAST v4 and later): the waves (:mod:`.seastate`);
* the mooring: MoorDyn v1/v2 (:mod:`floatmoor.io.moordyn`) or MAP++ (:mod:`floatmoor.io.map`);

and writes ``DIR/database.nc``, ``DIR/vessel.yaml`` (with the mass budget,
:mod:`.budget`), ``DIR/mooring.yaml`` and ``DIR/scene.yaml``.  Everything not mapped is listed
with its file and line and what floatmoor does instead (:class:`Unmapped`); the written scene
is then checked as ``floatmoor check`` checks it (:attr:`OpenFASTImport.check`).

Readers tried before this one was written: ``openfast-io`` 5.0.0 (PyPI) reads the driver
strictly by the position of OpenFAST v5 and stops on the v3 and v4 files of every public model
here; the ``FASTInputFile`` reader of openfast_toolbox (label-based; not on PyPI, and the PyPI
package ``welib`` that ships it does not install) drops the rows of a tab-separated
``AddBQuad``.  Neither is used.
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...core.errors import FloatmoorWarning, SceneError
from . import schemas
from .bodies import elastodyn_masses, filled_members, member_geometry, member_volumes
from .budget import mass_budget
from .reader import InputFile
from .seastate import current_unmapped, sea_state, water_values

__all__ = ["OpenFASTImport", "Unmapped", "import_openfast"]


@dataclass(frozen=True, kw_only=True)
class Unmapped:
    """An input floatmoor does not map: its file and line, the key, what it holds and what
    floatmoor does instead."""

    file: Path
    line: int | None
    key: str
    what: str
    instead: str

    def __str__(self) -> str:
        where = f"{self.file.name}" + (f":{self.line}" if self.line else "")
        key = f" {self.key}" if self.key else ""
        return f"{where}{key}: {self.what}" + (f" -- floatmoor: {self.instead}"
                                                if self.instead else "")


@dataclass(frozen=True, kw_only=True)
class OpenFASTImport:
    """Result of :func:`import_openfast`: the files written (what -> path), what was not
    mapped, the conversions made, the mass budget and the verdict of ``floatmoor check`` on the
    written scene (None: it passes; else its message)."""

    files: dict
    unmapped: tuple
    notes: tuple
    budget: object
    check: str | None

    @property
    def runnable(self) -> bool:
        """The scene passes ``floatmoor check`` and its mass budget closes."""
        return self.check is None and self.budget.closes


def _fmt(x):
    from ..mooring_import import fmt
    return fmt(x)


def _matrix_yaml(name, M, comment):
    rows = "\n".join("  - [" + ", ".join(_fmt(v) for v in r) + "]" for r in M)
    return f"# {comment}\n{name}:\n{rows}\n"


def _add(unmapped, f, key, what, instead):
    unmapped.append((f.path, f.line(key), key, what, instead))


def _features(fst: InputFile, unmapped):
    for key, file_key, what, instead in (
            ("CompInflow", "InflowFile", "inflow wind", "no wind (add a wind environment and "
             "wind coefficients)"),
            ("CompAero", "AeroFile", "rotor aerodynamics", "no rotor loads (a rigid body "
             "without thrust)"),
            ("CompServo", "ServoFile", "control and servo (pitch, torque, yaw, structural "
             "controls)", "no controller (the rotor is locked)"),
            ("CompSub", "SubFile", "substructure dynamics (SubDyn)", "a rigid platform"),
            ("CompIce", "IceFile", "ice loads", "no ice loads"),
            ("CompSoil", "SoilFile", "soil", "no soil model"),
            ("MHK", None, "marine hydrokinetic turbine", "a rigid floating body")):
        if fst.has(key) and fst.int(key, 0) != 0:
            name = f" ({fst.text(file_key)})" if file_key and fst.has(file_key) else ""
            _add(unmapped, fst, key, f"{what}: {key} = {fst.text(key)}{name}", instead)
    if fst.int("CompElast", 1) == 2:
        _add(unmapped, fst, "CompElast", "BeamDyn blades (CompElast 2): their masses are "
             "taken from ElastoDyn's blade files", "rigid blades")


def _elastodyn_unmapped(ed: InputFile, unmapped):
    off = [k for k in ("PtfmSgDOF", "PtfmSwDOF", "PtfmHvDOF", "PtfmRDOF", "PtfmPDOF", "PtfmYDOF")
           if ed.has(k) and not ed.flag(k, True)]
    if off:
        unmapped.append((ed.path, ed.line(off[0]), off[0], f"platform DOFs switched off: "
                         f"{', '.join(off)}", "all six rigid-body DOFs are free"))
    flex = [k for k in ("FlapDOF1", "FlapDOF2", "EdgeDOF", "TwFADOF1", "TwFADOF2", "TwSSDOF1",
                        "TwSSDOF2", "DrTrDOF", "GenDOF", "YawDOF", "PitchDOF", "TeetDOF")
            if ed.has(k) and ed.flag(k, False)]
    if flex:
        unmapped.append((ed.path, ed.line(flex[0]), flex[0], f"turbine DOFs {', '.join(flex)} "
                         f"(flexible tower and blades, drivetrain, yaw)",
                         "a rigid turbine locked to the platform"))
    init = [k for k in ("PtfmSurge", "PtfmSway", "PtfmHeave", "PtfmRoll", "PtfmPitch", "PtfmYaw")
            if ed.has(k) and ed.float(k, 0.0) != 0.0]
    if init:
        unmapped.append((ed.path, ed.line(init[0]), init[0], "initial platform displacements "
                         + ", ".join(f"{k} {ed.text(k)}" for k in init),
                         "the analyses start from the equilibrium (or the pose you give)"))
    if ed.has("RotSpeed") and ed.float("RotSpeed", 0.0) != 0.0:
        _add(unmapped, ed, "RotSpeed", f"rotor speed {ed.text('RotSpeed')} rpm",
             "a locked rotor (no gyroscopic moments)")


def _potential_flow(hd: InputFile):
    """Refuse a HydroDyn file without a single WAMIT body."""
    pot = hd.int("PotMod")
    if pot != 1:
        alt = []
        for p in sorted(hd.path.parent.glob("*.dat")):
            if p == hd.path:
                continue
            try:
                t = p.read_text(errors="replace")
            except OSError:
                continue
            if "PotMod" in t and "HydroDyn" in t.splitlines()[0]:
                try:
                    other = InputFile(p, schemas.HYDRODYN, "HydroDyn")
                    if other.has("PotMod") and other.int("PotMod") == 1:
                        alt.append(p.name)
                except SceneError:
                    continue
        hint = ("floatmoor's floater needs a potential-flow (WAMIT) database; "
                + (f"this folder has a HydroDyn file with PotMod 1: import with --hydrodyn "
                   f"{alt[0]}" if alt else "compute one (e.g. with Capytaine) and give a "
                   "HydroDyn file with PotMod 1"))
        raise SceneError(hd.path, hd.where("PotMod"), "PotMod 1 (WAMIT frequency-domain "
                         "coefficients)", hd.text("PotMod"), hint)
    if hd.int("NBody", 1) != 1:
        raise SceneError(hd.path, hd.where("NBody"), "one WAMIT body (floatmoor has one floating "
                         "body)", hd.text("NBody"))
    if hd.float("PtfmRefztRot", 0.0) != 0.0:
        raise SceneError(hd.path, hd.where("PtfmRefztRot"), "0 (a WAMIT body frame aligned with "
                         "the platform's)", hd.text("PtfmRefztRot"),
                         "rotate the WAMIT data into the platform frame first")


def _wamit(hd: InputFile, rho, g, depth, ref, unmapped, notes):
    from ...hydro import read_wamit

    pot = hd.text("PotFile").strip('"')
    root = Path(pot) if Path(pot).is_absolute() else hd.path.parent / pot
    beside = hd.path.parent / Path(pot).name
    if not Path(str(root) + ".1").is_file() and Path(str(beside) + ".1").is_file():
        notes.append(f"WAMIT root {pot} ({hd.where('PotFile')}) not found; {beside.name}.* beside "
                     f"the HydroDyn file used")
        root = beside
    if not Path(str(root) + ".1").is_file():
        raise SceneError(hd.path, hd.where("PotFile"), "the root of WAMIT .1, .3 and .hst files "
                         "(relative to the HydroDyn file)", pot,
                         f"{Path(str(root) + '.1')} not found")
    ulen = hd.float("WAMITULEN", 1.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", FloatmoorWarning)
        ds = read_wamit(root, ulen=ulen, rho=rho, g=g, water_depth=depth, reference_point=ref)
    for w in caught:
        notes.append(f"WAMIT {root.name}: {w.message}")
    if "excitation_force" not in ds.data_vars:
        unmapped.append((hd.path, hd.line("PotFile"), "PotFile", f"WAMIT {root.name}.3 not "
                         f"found (no first-order wave excitation)", "the scene is written "
                         "without waves"))
    else:  # WAMIT writes -180 and +180 deg: identical data, keep one
        keep = ds.wave_direction.values < np.pi - 1e-9
        ds = ds.isel(wave_direction=np.nonzero(keep)[0])
    ds.attrs["source"] = (f"WAMIT {root.name}.1/.3/.hst via {hd.path.name} (WAMITULEN {ulen:g}, "
                          f"rho {rho:g}, g {g:g})")
    ds.attrs["displaced_volume"] = hd.float("PtfmVol0")
    ds.attrs["centre_of_buoyancy"] = [hd.float("PtfmCOBxt", 0.0), hd.float("PtfmCOByt", 0.0),
                                      0.0]
    ds.attrs["reference_point"] = list(ref)
    return ds, root, ulen


def _hydrodyn_unmapped(hd: InputFile, unmapped, root):
    for key, what in (("ExctnMod", "wave-excitation model"), ("RdtnMod", "radiation memory "
                                                                         "model")):
        if hd.has(key):
            v = hd.int(key)
            if v == 0:
                _add(unmapped, hd, key, f"{key} 0 (no {what} in OpenFAST)",
                     f"floatmoor computes the {what.split()[0]} from the WAMIT files")
            elif v == 2:
                _add(unmapped, hd, key, f"{key} 2 (state-space {what})",
                     f"floatmoor computes the {what.split()[0]} from the WAMIT frequency data")
    for key in ("ExctnDisp", "PtfmYMod"):
        if hd.has(key) and hd.int(key, 0) != 0:
            _add(unmapped, hd, key, f"{key} {hd.text(key)} (excitation at the displaced "
                 f"position / large yaw)", "excitation at the undisplaced position")
    second = [(k, hd.int(k)) for k in ("MnDrift", "NewmanApp", "DiffQTF", "SumQTF")
              if hd.has(k) and hd.int(k, 0) != 0]
    for k, v in second:
        has12d = Path(str(root) + ".12d").is_file()
        ext = f"{v}s" if k == "SumQTF" else (f"{v}d" if v >= 10 else f"{v}")
        if k == "SumQTF":
            instead = "no sum-frequency loads"
        elif has12d:
            instead = (f"the database holds the {root.name}.12d QTF and its diagonal as mean "
                       f"drift (used per the scene's drift options)")
        else:
            instead = f"no second-order loads ({root.name}.{ext} is not read)"
        _add(unmapped, hd, k, f"second-order wave loads {k} {v} (WAMIT .{ext})", instead)
    members = member_geometry(hd) if hd.int("NMembers", 0) > 0 else {}
    if members:
        _add(unmapped, hd, "NMembers",
             f"{len(members)} Morison members ({sum(1 for v in members.values() if v[4])} with "
             f"PropPot TRUE: viscous drag only): strip-theory drag and added mass",
             "viscous loads only from the vessel's quadratic_damping (AddBQuad); add "
             "slender_elements for member drag")
    if hd.int("NMGDepths", 0) > 0:
        _add(unmapped, hd, "NMGDepths", f"marine growth ({hd.text('NMGDepths')} depths): its "
             f"mass, buoyancy and drag", "no marine growth (its mass is NOT in the vessel)")
    for key in ("WaveDisp", "AMMod", "HstMod"):
        if hd.has(key) and hd.int(key, 0) != 0:
            _add(unmapped, hd, key, f"{key} {hd.text(key)} (strip-theory option)",
                 "no strip-theory loads")
    return members


def _vessel_yaml(fst, ed, hd, root, ulen, rho, g, ref, items, B, Bq, C, budget):
    plat = items[0]
    pm = items[1:]

    def row3(v):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"

    def mat3(M):
        return "[" + ", ".join(row3(r) for r in M) + "]"

    pm_yaml = "\n".join(
        f"  # {it.source}" + (f"; inertia: {it.inertia_note}" if it.inertia_note else "")
        + f"\n  - {{name: {it.name}, mass: {_fmt(it.mass)}, position: {row3(it.cog)}, "
          f"inertia_cg: {mat3(it.inertia)}}}" for it in pm)
    return (f"# floatmoor vessel imported from {Path(fst.path).name} (OpenFAST): ElastoDyn "
            f"{ed.path.name}, HydroDyn {hd.path.name}.\n"
            f"name: {Path(fst.path).stem}\n"
            f"description: imported from {Path(fst.path).name}\n"
            f"database: database.nc   # WAMIT {root.name}, WAMITULEN {ulen:g}, rho {rho:g}, "
            f"g {g:g}\n"
            f"reference_point: {row3(ref)}   # HydroDyn PtfmRefxt/yt/zt (the WAMIT origin)\n"
            f"# {plat.source}\n"
            f"mass: {_fmt(plat.mass)}   # kg, ElastoDyn PtfmMass\n"
            f"centre_of_gravity: {row3(plat.cog)}   # m, PtfmCMxt/yt/zt\n"
            f"inertia_cg: {mat3(plat.inertia)}   # kg m^2, PtfmRIner/PIner/YIner and products\n"
            f"point_masses:\n{pm_yaml}\n"
            + _matrix_yaml("linear_damping", B, f"HydroDyn AddBLin {hd.where('AddBLin')} "
                           "(N s/m, N s, N m s/rad)")
            + _matrix_yaml("quadratic_damping", Bq, f"HydroDyn AddBQuad {hd.where('AddBQuad')} "
                           "(N s^2/m^2, N s^2, N m s^2/rad^2), the full matrix")
            + _matrix_yaml("additional_stiffness", C, f"HydroDyn AddCLin {hd.where('AddCLin')} "
                           "(N/m, N/rad, N m/m, N m/rad)")
            + budget.yaml(_fmt))


def import_openfast(fst, out_dir, *, model: str = "quasi-static", hydrodyn=None,
                    check: bool = True) -> OpenFASTImport:
    """Import an OpenFAST floating model into ``out_dir`` (created if needed).

    ``hydrodyn``: a HydroDyn file to read instead of the driver's ``HydroFile`` (e.g. the
    potential-flow variant a model ships beside its strip-theory one).  ``check``: check the
    written scene as ``floatmoor check`` does.
    """
    fstf = InputFile(fst, schemas.FST, "OpenFAST driver")
    out = Path(out_dir)
    unmapped_raw: list = []
    notes: list[str] = []
    _features(fstf, unmapped_raw)
    if fstf.int("CompHydro") != 1:
        raise SceneError(fstf.path, fstf.where("CompHydro"), "1 (HydroDyn: the floater's "
                         "hydrodynamics)", fstf.text("CompHydro"))
    ed_path = fstf.file("EDFile")
    if ed_path is None:
        raise SceneError(fstf.path, fstf.where("EDFile"), "an ElastoDyn file", "none")
    ed = InputFile(ed_path, schemas.ELASTODYN, "ElastoDyn")
    hd_path = Path(hydrodyn) if hydrodyn is not None else fstf.file("HydroFile")
    if hd_path is None:
        raise SceneError(fstf.path, fstf.where("HydroFile"), "a HydroDyn file", "none")
    if hydrodyn is not None:
        notes.append(f"HydroDyn file {hd_path.name} given instead of the driver's HydroFile "
                     f"{fstf.text('HydroFile')} ({fstf.where('HydroFile')})")
    hd = InputFile(hd_path, schemas.HYDRODYN, "HydroDyn")
    _potential_flow(hd)
    ss = None
    use_ss = fstf.int("CompSeaSt", 0) == 1 or (not hd.has("WaveMod") and fstf.has("SeaStFile"))
    if use_ss:
        ss_path = fstf.file("SeaStFile")
        if ss_path is None:
            raise SceneError(fstf.path, fstf.where("SeaStFile"), "a SeaState file (the waves of "
                             "OpenFAST v4 files are in SeaState)", fstf.text("SeaStFile", "none"))
        ss = InputFile(ss_path, schemas.SEASTATE, "SeaState")
    waves_file = ss if ss is not None else hd
    rho, depth, g = water_values(waves_file, fstf, ed, notes, unmapped_raw)
    if not waves_file.has("WaveMod"):
        raise SceneError(hd.path, "WaveMod", "the waves in HydroDyn (OpenFAST <= 3.5) or a "
                         "SeaState file in the driver (CompSeaSt 1, SeaStFile)",
                         SceneError.MISSING)
    # --- reference points --------------------------------------------------------------
    ref = [hd.float("PtfmRefxt", 0.0), hd.float("PtfmRefyt", 0.0), hd.float("PtfmRefzt", 0.0)]
    ed_ref = [ed.float("PtfmRefxt", 0.0), ed.float("PtfmRefyt", 0.0), ed.float("PtfmRefzt")]
    if not np.allclose(ed_ref, ref):
        raise SceneError(ed.path, ed.where("PtfmRefzt"), f"the platform reference point of "
                         f"HydroDyn {ref} (the WAMIT origin; the mooring's vessel points are "
                         f"about ElastoDyn's)", ed_ref, "floatmoor has one body reference point")
    # --- sea state ---------------------------------------------------------------------
    waves = sea_state(waves_file, unmapped_raw, fmt=_fmt)
    current_unmapped(waves_file, unmapped_raw)
    # --- masses ------------------------------------------------------------------------
    _elastodyn_unmapped(ed, unmapped_raw)
    items = elastodyn_masses(ed, unmapped_raw)
    items += filled_members(hd, rho)
    # --- hydrodynamics -----------------------------------------------------------------
    out.mkdir(parents=True, exist_ok=True)
    ds, root, ulen = _wamit(hd, rho, g, depth, ref, unmapped_raw, notes)
    from ...hydro import save_database
    save_database(ds, out / "database.nc")
    members = _hydrodyn_unmapped(hd, unmapped_raw, root)
    if hd.leading_numbers("AddF0") >= 6:     # OpenFAST 2.0-2.5: one row of six
        add_f0 = hd.numbers_after("AddF0", 1, 6).ravel()
    else:
        add_f0 = hd.numbers_after("AddF0", 6, 1).ravel()
    if np.any(add_f0):
        _add(unmapped_raw, hd, "AddF0", f"additional preload AddF0 {add_f0.tolist()} (N, N m)",
             "not in the scene: give it as a constant force (floatmoor statics --force); the "
             "mass budget counts it")
    C = hd.numbers_after("AddCLin", 6, 6)
    B = hd.numbers_after("AddBLin", 6, 6)
    Bq = hd.numbers_after("AddBQuad", 6, 6)
    for name, M in (("AddBLin", B), ("AddBQuad", Bq)):
        if np.any(np.diag(M) < 0):
            raise SceneError(hd.path, hd.where(name), "a damping matrix with a non-negative "
                             "diagonal", np.diag(M).tolist())
    # --- mooring -----------------------------------------------------------------------
    files = {"vessel": out / "vessel.yaml", "database": out / "database.nc"}
    comp = fstf.int("CompMooring")
    mooring_vertical = 0.0
    suspects = []
    if comp in (1, 3):
        from ..map import read_model as read_map
        from ..moordyn import read_model as read_md
        mfile = fstf.file("MooringFile")
        if mfile is None:
            raise SceneError(fstf.path, fstf.where("MooringFile"), "a mooring file",
                             fstf.text("MooringFile"))
        reader = read_map if comp == 1 else read_md
        r = reader(mfile, water_depth=depth, water_density=rho, gravity=g, model=model,
                   warn=False)
        for u in r.unmapped:
            m = re.search(r"\(line (\d+)\)", u)
            unmapped_raw.append((Path(mfile), int(m.group(1)) if m else None, "", u, ""))
        (out / "mooring.yaml").write_text(r.yaml_text)
        files["mooring"] = out / "mooring.yaml"
        mooring_vertical = -float(np.asarray(r.system.force(np.zeros(6)), float)[2])
    else:
        _add(unmapped_raw, fstf, "CompMooring", f"CompMooring {comp} ("
             + {0: "no mooring", 2: "FEAMooring", 4: "OrcaFlex"}.get(comp, "unknown") + ")",
             "no mooring imported (its vertical pull is not in the mass budget)")
        suspects.append(("the mooring's vertical pull (CompMooring not imported)", None))
    # --- mass budget -------------------------------------------------------------------
    for u in unmapped_raw:
        if u[2] in ("TwrFile",) or u[2].startswith("BldFile"):
            suspects.append((f"the {'tower' if u[2] == 'TwrFile' else 'blades'} ({u[3]})",
                             None))
    if members:
        extra = sum(member_volumes(hd, members, pot=False).values())
        if extra > 0:
            suspects.append((f"the buoyancy of the Morison members with PropPot FALSE "
                             f"({extra:.6g} m^3)", -rho * extra))
        hull = sum(member_volumes(hd, members, pot=True).values())
        v0 = hd.float("PtfmVol0")
        if hull > 0 and abs(hull - v0) > 0.005 * v0:
            suspects.append((f"PtfmVol0 {v0:g} m^3 ({hd.where('PtfmVol0')}) against the "
                             f"{hull:.6g} m^3 below the still-water line of the HydroDyn members "
                             f"with PropPot TRUE (the same hull)", -rho * (hull - v0)))
    budget = mass_budget(items, volume=hd.float("PtfmVol0"), water_density=rho, gravity=g,
                         mooring_vertical=mooring_vertical, preload_vertical=float(add_f0[2]),
                         suspects=suspects)
    (out / "vessel.yaml").write_text(_vessel_yaml(fstf, ed, hd, root, ulen, rho, g, ref, items,
                                                  B, Bq, C, budget))
    unmapped = tuple(Unmapped(file=Path(f), line=ln, key=k, what=w, instead=i)
                     for f, ln, k, w, i in unmapped_raw)
    for f in (fstf, ed, hd) + ((ss,) if ss is not None else ()):
        notes += f.notes
    # --- scene -------------------------------------------------------------------------
    header = "\n".join(f"#   - {u}" for u in unmapped)
    env = waves if "excitation_force" in ds.data_vars else None
    if waves is not None and env is None:
        notes.append("the sea state is not written: the database has no wave excitation")
    scene = (f"# floatmoor scene imported from {fstf.path.name} (OpenFAST).\n"
             f"# Not mapped (file:line key: what -- what floatmoor does instead):\n{header}\n"
             f"name: {fstf.path.stem}\n"
             f"site: {{water_depth: {_fmt(depth)}, water_density: {_fmt(rho)}, gravity: "
             f"{_fmt(g)}}}   # WtrDpth, WtrDens ({waves_file.path.name} or the driver), "
             f"Gravity\n"
             f"vessel: vessel.yaml\n"
             + ("mooring: mooring.yaml\n" if "mooring" in files else "")
             + (f"environment:\n  name: {fstf.path.stem}-sea-state\n{env}\n" if env else "")
             + f"analysis:\n  duration: 10800.0   # s, a 3-hour storm (the driver's TMax "
             f"{fstf.text('TMax')} s is a turbine simulation's length)\n"
             f"  dt: 0.1   # s, rigid-body step (the driver's DT {fstf.text('DT')} s is for the "
             f"flexible turbine)\n  seeds: 1\n")
    (out / "scene.yaml").write_text(scene)
    files["scene"] = out / "scene.yaml"
    verdict = _check(files["scene"]) if check else None
    if unmapped:
        warnings.warn(f"{fstf.path}: not mapped to floatmoor:\n  - "
                      + "\n  - ".join(str(u) for u in unmapped), FloatmoorWarning, stacklevel=2)
    if not budget.closes:
        warnings.warn(f"{fstf.path}: the mass budget does not close: the imbalance is "
                      f"{100 * budget.fraction:+.3g} % of the buoyancy; "
                      f"{budget.likely_missing()}", FloatmoorWarning, stacklevel=2)
    return OpenFASTImport(files=files, unmapped=unmapped, notes=tuple(notes), budget=budget,
                          check=verdict)


def _check(scene_path) -> str | None:
    """None when the scene passes the checks of ``floatmoor check``; else the message."""
    from ..build import build
    from ..plausibility import check_built
    from ..scene import load_scene

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FloatmoorWarning)
            built = build(load_scene(scene_path))
            check_built(built)
    except SceneError as exc:
        return str(exc)
    return None
