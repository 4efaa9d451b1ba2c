"""OpenFAST floating models (``.fst``) -> floatmoor vessel, mooring and scene files.

Reads the driver file, ElastoDyn (platform mass and inertia, nacelle, hub, tower and blades), HydroDyn
(WAMIT root, ``WAMITULEN``, reference point, additional preload, linear and quadratic damping and
stiffness), SeaState (the sea state) and the mooring file (MoorDyn via
:mod:`floatmoor.io.moordyn` or MAP++ via :mod:`floatmoor.io.map`), and writes

* ``DIR/database.nc``: the WAMIT ``.1``, ``.3`` and ``.hst`` files (:func:`floatmoor.hydro.read_wamit`);
* ``DIR/vessel.yaml``, ``DIR/mooring.yaml`` and ``DIR/scene.yaml``.

The OpenFAST files are read by keyword (``value Name - description`` lines, matrices of six
rows after their name), not by position: the released ``openfast_io`` readers (4.2.1 and 5.0.0)
read these inputs by position and fail on, or silently misread, the files of the OpenFAST
regression tests of September 2024 (5.0.0 reads the SeaState ``WaveHs`` from the ``WaveTp``
line; both stop on the ``.fst``, ElastoDyn and HydroDyn files), which is why they are not used.

The tower and the blades are rigid point masses lumped at ElastoDyn's analysis nodes from their
ElastoDyn files (tested against the masses and rotor inertia of ElastoDyn's summary file).

Not mapped, and listed in one warning: the tower and blade masses when their ElastoDyn files
are not found, the hub's offset from the apex, aerodynamics, control, the Morison members and
filled members (ballast water) of HydroDyn, second-order wave loads, currents, wave models
other than JONSWAP, and the waves altogether when the WAMIT ``.3`` file is missing.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core.errors import FloatmoorWarning, SceneError

__all__ = ["OpenFASTImport", "import_openfast", "read_keyed"]


def read_keyed(path):
    """``{Name: (value text, line number)}`` of an OpenFAST input file, and its lines."""
    path = Path(path)
    if not path.is_file():
        raise SceneError(path, "", "an existing OpenFAST input file", "no such file")
    lines = path.read_text(encoding="utf-8", errors="replace").replace("\r", "").split("\n")
    out = {}
    for n, text in enumerate(lines, start=1):
        tok = text.split()
        if len(tok) >= 2 and not text.lstrip().startswith("--") and tok[1][:1].isalpha():
            out.setdefault(tok[1], (tok[0], n))
    return out, lines


class _File:
    def __init__(self, path):
        self.path = Path(path)
        self.keys, self.lines = read_keyed(self.path)

    def raw(self, name, default=None):
        if name not in self.keys:
            if default is not None:
                return default
            raise SceneError(self.path, name, f"a line 'value {name} - description'",
                             SceneError.MISSING)
        return self.keys[name][0].strip('"')

    def float(self, name, default=None):
        v = self.raw(name, None if default is None else str(default))
        try:
            return float(v)
        except ValueError:
            n = self.keys[name][1] if name in self.keys else 0
            raise SceneError(self.path, f"line {n} ({name})", "a number", v) from None

    def is_default(self, name):
        return name in self.keys and self.raw(name).upper() == "DEFAULT"

    def file(self, name):
        v = self.raw(name)
        return None if v.lower() in ("unused", "none", "") else (self.path.parent / v)

    def matrix(self, name, nrow=6):
        """The 6 x 6 (or 6 x 1) table whose first row ends with ``name``."""
        n = self.keys[name][1] if name in self.keys else None
        if n is None:  # the first row has six values before the name
            for i, text in enumerate(self.lines, start=1):
                tok = text.split()
                if name in tok:
                    n = i
                    break
        if n is None:
            raise SceneError(self.path, name, f"the {name} table", SceneError.MISSING)
        rows = []
        for i in range(nrow):
            text = self.lines[n - 1 + i].split()
            vals = []
            for t in text:
                try:
                    vals.append(float(t))
                except ValueError:
                    break
            rows.append((vals, n + i))
        width = len(rows[0][0])
        for vals, ln in rows:
            if len(vals) != width or width not in (1, 6):
                raise SceneError(self.path, f"line {ln} ({name})", f"{width if width in (1, 6) else 6}"
                                 " numbers in each row of the table", len(vals))
        return np.array([r for r, _ in rows])


def _station_table(f: _File, count_key: str, header: str, ncol: int):
    """The distributed-property table of an ElastoDyn tower or blade file (after the section
    line containing ``header``, two header lines, then ``count_key`` rows)."""
    n = int(f.float(count_key))
    start = next((i for i, t in enumerate(f.lines) if header in t.upper()), None)
    if start is None:
        raise SceneError(f.path, header, f"a {header} section", SceneError.MISSING)
    rows = []
    for k in range(n):
        ln = start + 3 + k
        tok = f.lines[ln].split() if ln < len(f.lines) else []
        if len(tok) < ncol:
            raise SceneError(f.path, f"line {ln + 1}", f"{ncol} or more numbers ({count_key} = "
                             f"{n} rows after the {header} header)", " ".join(tok) or "nothing")
        try:
            rows.append([float(t) for t in tok[:ncol]])
        except ValueError:
            raise SceneError(f.path, f"line {ln + 1}", "numbers", " ".join(tok)) from None
    return np.array(rows)


def _lumped(frac, dens, length, nodes):
    """ElastoDyn's discretisation: ``nodes`` equal elements, the density interpolated linearly
    at their midpoints; returns (midpoint distances from the root, element masses)."""
    d = length / nodes
    x = d * (np.arange(nodes) + 0.5)
    return x, np.interp(x / length, frac, dens) * d


def _tower_and_blades(ed: _File, apex, shaft, unmapped):
    """Point masses of the tower and of the blades from their ElastoDyn files, lumped at
    ElastoDyn's analysis nodes (the sums its summary file prints as Tower Mass, blade Mass and
    Rotor Inertia); a missing file is listed in ``unmapped``."""
    out = []
    twr = ed.file("TwrFile") if "TwrFile" in ed.keys else None
    if twr is None or not twr.is_file():
        unmapped.append(f"tower mass and inertia: ElastoDyn TwrFile "
                        f"{twr.name if twr else '(absent)'} not found -- add it as a point mass "
                        f"in vessel.yaml")
    else:
        tf = _File(twr)
        tab = _station_table(tf, "NTwInpSt", "DISTRIBUTED TOWER PROPERTIES", 2)
        base = ed.float("TowerBsHt")
        h, m = _lumped(tab[:, 0], tab[:, 1] * tf.float("AdjTwMa", 1.0),
                       ed.float("TowerHt") - base, int(ed.float("TwrNodes")))
        hc = float(h @ m / m.sum())
        i_fa = float(m @ (h - hc) ** 2)
        out.append(("tower", float(m.sum()), [0.0, 0.0, base + hc],
                    np.diag([i_fa, i_fa, 0.0]),
                    (f"ElastoDyn {twr.name}: TMassDen x AdjTwMa lumped at the TwrNodes midpoints "
                    f"from TowerBsHt to TowerHt (rigid tower)")))
    nb = int(ed.float("NumBl", 3.0))
    files = [ed.file(f"BldFile({k + 1})") for k in range(nb)]
    if any(f is None or not f.is_file() for f in files):
        miss = next(f for f in files if f is None or not f.is_file())
        unmapped.append(f"blade mass and inertia: ElastoDyn blade file "
                        f"{miss.name if miss else '(absent)'} not found -- add the blades as a "
                        f"point mass in vessel.yaml")
        return out
    hub_r, tip_r = ed.float("HubRad"), ed.float("TipRad")
    e_up = np.array([-shaft[2], 0.0, shaft[0]])   # in the rotor plane, up
    e_y = np.array([0.0, 1.0, 0.0])
    pts, mass = [], []
    for k, bf in enumerate(files):
        b = _File(bf)
        tab = _station_table(b, "NBlInpSt", "DISTRIBUTED BLADE PROPERTIES", 4)
        r, m = _lumped(tab[:, 0], tab[:, 3] * b.float("AdjBlMs", 1.0), tip_r - hub_r,
                       int(ed.float("BldNodes")))
        beta = math.radians(ed.float(f"PreCone({k + 1})", 0.0))
        psi = 2.0 * math.pi * k / nb
        axis = math.cos(beta) * (math.cos(psi) * e_up + math.sin(psi) * e_y) + math.sin(beta) * shaft
        radii = list(hub_r + r)
        masses = list(m)
        tip = ed.float(f"TipMass({k + 1})", 0.0)
        if tip:
            radii.append(tip_r)
            masses.append(tip)
        pts += [np.asarray(apex) + ri * axis for ri in radii]
        mass += masses
    pts, mass = np.array(pts), np.array(mass)
    mt = float(mass.sum())
    c = mass @ pts / mt
    d = pts - c
    inertia = np.eye(3) * float(mass @ (d * d).sum(axis=1)) - (d.T * mass) @ d
    out.append(("blades", mt, c.tolist(), inertia,
                (f"ElastoDyn blade files: BMassDen x AdjBlMs lumped at the BldNodes midpoints "
                f"from HubRad to TipRad, PreCone, TipMass; {nb} blades at 0, 360/{nb}, ... deg "
                f"azimuth (rigid rotor)")))
    return out


@dataclass(frozen=True, kw_only=True)
class OpenFASTImport:
    """Files written by :func:`import_openfast` (``files``: what -> path) and the list of what
    was not mapped."""

    files: dict
    unmapped: tuple
    notes: tuple


def _y(x):
    from .mooring_import import fmt
    return fmt(x)


def _matrix_yaml(name, M, comment):
    rows = "\n".join("  - [" + ", ".join(_y(v) for v in r) + "]" for r in M)
    return f"# {comment}\n{name}:\n{rows}\n"


def import_openfast(fst, out_dir, *, model: str = "quasi-static") -> OpenFASTImport:
    """Import an OpenFAST floating model into ``out_dir`` (created if needed)."""
    from ..hydro import read_wamit, save_database

    fst_f = _File(fst)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    unmapped, notes = [], []
    g = fst_f.float("Gravity")
    rho = fst_f.float("WtrDens")
    depth = fst_f.float("WtrDpth")
    for key, what in (("CompAero", "aerodynamics"), ("CompServo", "control"),
                      ("CompInflow", "inflow wind")):
        if key in fst_f.keys and fst_f.float(key) != 0:
            unmapped.append(f"{what} ({key} = {fst_f.raw(key)}): a rigid body without rotor "
                            f"loads in floatmoor")
    # --- ElastoDyn -------------------------------------------------------------------------
    ed = _File(fst_f.file("EDFile"))
    mass = ed.float("PtfmMass")
    cog = [ed.float("PtfmCMxt", 0.0), ed.float("PtfmCMyt", 0.0), ed.float("PtfmCMzt")]
    I = np.diag([ed.float("PtfmRIner"), ed.float("PtfmPIner"), ed.float("PtfmYIner")])
    I[0, 1] = I[1, 0] = ed.float("PtfmXYIner", 0.0)
    I[1, 2] = I[2, 1] = ed.float("PtfmYZIner", 0.0)
    I[0, 2] = I[2, 0] = ed.float("PtfmXZIner", 0.0)
    zref = ed.float("PtfmRefzt", 0.0)
    th, t2s = ed.float("TowerHt"), ed.float("Twr2Shft")
    oh, tilt = ed.float("OverHang"), math.radians(ed.float("ShftTilt"))
    apex = [oh * math.cos(tilt), 0.0, th + t2s + oh * math.sin(tilt)]
    nac = [ed.float("NacCMxn"), ed.float("NacCMyn", 0.0), th + ed.float("NacCMzn")]
    nm = ed.float("NacMass")
    # NacYIner is about the yaw axis: about the nacelle CoG subtract m (x^2 + y^2)
    nyi = ed.float("NacYIner") - nm * (nac[0] ** 2 + nac[1] ** 2)
    a = np.array([math.cos(tilt), 0.0, math.sin(tilt)])  # shaft axis, apex = top + OverHang a
    hub_I = ed.float("HubIner") * np.outer(a, a)
    pm = [("nacelle", nm, nac, np.diag([0.0, 0.0, nyi]),
           ("ElastoDyn NacMass at NacCMxn, NacCMyn, TowerHt + NacCMzn; NacYIner less m r^2 "
            "(about the yaw axis in ElastoDyn)")),
          ("hub", ed.float("HubMass"), apex, hub_I,
           ("ElastoDyn HubMass at the rotor apex (OverHang, ShftTilt, TowerHt + Twr2Shft), "
            "HubIner about the shaft"))]
    if ed.float("HubCM", 0.0):
        unmapped.append(f"HubCM = {ed.raw('HubCM')} m: the hub mass is put at the apex")
    pm += _tower_and_blades(ed, apex, a, unmapped)
    # --- HydroDyn --------------------------------------------------------------------------
    hd = _File(fst_f.file("HydroFile"))
    if hd.float("NBody", 1.0) != 1:
        raise SceneError(hd.path, "NBody", "one WAMIT body (floatmoor has one floating body)",
                         hd.raw("NBody"))
    pot = hd.raw("PotFile")
    root = hd.path.parent / pot
    if not root.with_suffix(".1").is_file():
        alt = hd.path.parent / Path(pot).name
        if alt.with_suffix(".1").is_file():
            notes.append(f"WAMIT root {pot} not found; {alt.name}.* beside the HydroDyn file used")
            root = alt
        else:
            raise SceneError(hd.path, f"line {hd.keys['PotFile'][1]} (PotFile)",
                             "the root of WAMIT .1, .3 and .hst files", pot, "not found")
    ulen = hd.float("WAMITULEN", 1.0)
    ref = [hd.float("PtfmRefxt", 0.0), hd.float("PtfmRefyt", 0.0), hd.float("PtfmRefzt", 0.0)]
    if hd.float("PtfmRefztRot", 0.0):
        unmapped.append("PtfmRefztRot: a rotated WAMIT body frame")
    ds = read_wamit(root, ulen=ulen, rho=rho, g=g, water_depth=depth)
    no_excitation = "excitation_force" not in ds.data_vars
    if no_excitation:
        unmapped.append(f"WAMIT {Path(root).name}.3 not found: the database has no wave "
                        f"excitation, so the scene is written without waves")
    else:  # WAMIT writes -180 and +180 deg: identical data, keep one
        keep = ds.wave_direction.values < np.pi - 1e-9
        ds = ds.isel(wave_direction=np.nonzero(keep)[0])
    ds.attrs["source"] = f"WAMIT {Path(root).name}.1/.3/.hst via {hd.path.name}"
    ds.attrs["displaced_volume"] = hd.float("PtfmVol0")
    ds.attrs["reference_point"] = ref
    save_database(ds, out / "database.nc")
    add_f0 = hd.matrix("AddF0", 6).ravel()
    if np.any(add_f0):
        unmapped.append(f"AddF0 preload {add_f0.tolist()}: give it as a constant force "
                        f"(floatmoor statics --force)")
    C = hd.matrix("AddCLin")
    B = hd.matrix("AddBLin")
    Bq = hd.matrix("AddBQuad")
    for key in ("MnDrift", "NewmanApp", "DiffQTF", "SumQTF"):
        if key in hd.keys and hd.float(key) != 0:
            unmapped.append(f"HydroDyn {key} = {hd.raw(key)}: second-order loads (floatmoor "
                            f"takes drift from the database; see its frequency-domain options)")
    if "NFillGroups" in hd.keys and hd.float("NFillGroups") > 0:
        unmapped.append(f"HydroDyn filled members ({hd.raw('NFillGroups')} fill groups, e.g. "
                        f"ballast water): their mass is NOT in the vessel (ElastoDyn PtfmMass "
                        f"excludes it) -- add it to vessel.yaml before any analysis")
    if "NMembers" in hd.keys and hd.float("NMembers") > 0:
        unmapped.append(f"HydroDyn Morison members ({hd.raw('NMembers')}): strip-theory "
                        f"viscous loads are not imported")
    # --- vessel.yaml -----------------------------------------------------------------------
    pm_yaml = "\n".join(
        f"  # {c}\n  - {{name: {n}, mass: {_y(m)}, position: [{', '.join(_y(v) for v in p)}], "
        f"inertia_cg: [{', '.join('[' + ', '.join(_y(v) for v in r) + ']' for r in Ii)}]}}"
        for n, m, p, Ii, c in pm)
    vessel = (f"# floatmoor vessel imported from {Path(fst).name} (OpenFAST): ElastoDyn "
              f"{ed.path.name}, HydroDyn {hd.path.name}.\n"
              f"name: {Path(fst).stem}\n"
              f"description: imported from {Path(fst).name}\n"
              f"database: database.nc   # WAMIT {Path(root).name}, WAMITULEN {ulen:g}, rho "
              f"{rho:g}, g {g:g}\n"
              f"reference_point: [{', '.join(_y(v) for v in ref)}]   # HydroDyn PtfmRefxt/yt/zt "
              f"(ElastoDyn PtfmRefzt {zref:g})\n"
              f"mass: {_y(mass)}   # ElastoDyn PtfmMass\n"
              f"centre_of_gravity: [{', '.join(_y(v) for v in cog)}]   # PtfmCMxt/yt/zt\n"
              f"inertia_cg: [{', '.join('[' + ', '.join(_y(v) for v in r) + ']' for r in I)}]"
              f"   # PtfmRIner/PIner/YIner and the products of inertia\n"
              f"point_masses:\n{pm_yaml}\n"
              + _matrix_yaml("linear_damping", B, "HydroDyn AddBLin (N s/m, N m s/rad)")
              + _matrix_yaml("quadratic_damping", Bq, "HydroDyn AddBQuad")
              + _matrix_yaml("additional_stiffness", C, "HydroDyn AddCLin (N/m, N m/rad)"))
    (out / "vessel.yaml").write_text(vessel)
    # --- mooring ---------------------------------------------------------------------------
    comp = int(fst_f.float("CompMooring"))
    mfile = fst_f.file("MooringFile")
    files = {"vessel": out / "vessel.yaml", "database": out / "database.nc"}
    if comp in (1, 3):
        if comp == 1:
            from .map import read_model
        else:
            from .moordyn import read_model
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FloatmoorWarning)  # listed below with the rest
            r = read_model(mfile, water_depth=depth, water_density=rho, gravity=g, model=model)
        unmapped += [f"mooring: {u}" for u in r.unmapped]
        (out / "mooring.yaml").write_text(r.yaml_text)
        files["mooring"] = out / "mooring.yaml"
    elif comp != 0:
        unmapped.append(f"CompMooring = {comp} (FEAMooring or OrcaFlex): no mooring imported")
    # --- SeaState -> environment -------------------------------------------------------------
    env = None
    if ("SeaStFile" in fst_f.keys and fst_f.file("SeaStFile") is not None
            and not no_excitation):
        ss = _File(fst_f.file("SeaStFile"))
        wm_raw = ss.raw("WaveMod").upper()
        wm = 1 if wm_raw.startswith("1P") else int(ss.float("WaveMod"))
        if wm == 2:
            hs, tp = ss.float("WaveHs"), ss.float("WaveTp")
            head = ss.float("WaveDir", 0.0)
            gamma = "null" if ss.is_default("WavePkShp") else _y(ss.float("WavePkShp"))
            nd = ss.raw("WaveNDAmp", "FALSE").upper().startswith("T")
            env = (f"  waves: {{spectrum: jonswap, hs: {_y(hs)}, tp: {_y(tp)}, gamma: {gamma}, "
                   f"heading_deg: {_y(head)}, random_amplitudes: {'true' if nd else 'false'}}}"
                   f"   # SeaState WaveMod 2 (JONSWAP), WaveHs, WaveTp, WaveDir, WaveNDAmp; "
                   f"WavePkShp DEFAULT = the IEC 61400-3 / DNV-RP-C205 gamma rule (null)")
            if ss.float("WaveDirMod", 0.0):
                unmapped.append("SeaState directional spreading (WaveDirMod): not mapped (the "
                                "scene has long-crested waves)")
            unmapped.append(f"SeaState seeds {ss.raw('WaveSeed(1)', '-')}, "
                            f"{ss.raw('WaveSeed(2)', '-')}: floatmoor uses its own seeds")
        elif wm != 0:
            unmapped.append(f"SeaState WaveMod {wm_raw} (only 2, JONSWAP, is mapped): the scene "
                            f"is calm")
        if ss.float("CurrMod", 0.0):
            unmapped.append("SeaState current (CurrMod): not mapped")
    tmax = fst_f.float("TMax")
    scene = (f"# floatmoor scene imported from {Path(fst).name} (OpenFAST).  Rotor and wind loads "
             f"are not modelled.\n"
             f"name: {Path(fst).stem}\n"
             f"site: {{water_depth: {_y(depth)}, water_density: {_y(rho)}, gravity: {_y(g)}}}"
             f"   # .fst WtrDpth, WtrDens, Gravity\n"
             f"vessel: vessel.yaml\n"
             + ("mooring: mooring.yaml\n" if "mooring" in files else "")
             + (f"environment:\n  name: {Path(fst).stem}-seastate\n{env}\n" if env else "")
             + f"analysis:\n  duration: {_y(tmax)}   # .fst TMax\n"
             f"  dt: 0.1   # s, rigid-body step (the .fst DT {fst_f.raw('DT')} s is for the "
             f"flexible turbine)\n  seeds: 1\n")
    (out / "scene.yaml").write_text(scene)
    files["scene"] = out / "scene.yaml"
    warnings.warn(f"{fst}: not mapped to floatmoor:\n  - " + "\n  - ".join(unmapped),
                  FloatmoorWarning, stacklevel=2)
    return OpenFASTImport(files=files, unmapped=tuple(unmapped), notes=tuple(notes))
