"""Rigid masses of an OpenFAST floating model: every ElastoDyn mass and the HydroDyn ballast.

ElastoDyn (positions in its platform frame at zero pose: x downwind, z up from the mean sea
level; ``ElastoDyn_IO.f90`` and the ElastoDyn input-file documentation):

* platform: ``PtfmMass`` at ``PtfmCMxt/yt/zt``, inertia ``PtfmRIner/PIner/YIner`` and the
  products ``PtfmXYIner`` ... (``= -int(xy dm)``, the tensor's off-diagonal terms);
* tower: ``TMassDen`` x ``AdjTwMa`` of the tower file at the ``TwrNodes`` element midpoints from
  ``TowerBsHt`` to ``TowerHt`` (as ElastoDyn lumps it; its summary's Tower Mass);
* yaw bearing: ``YawBrMass`` at the tower top;
* nacelle: ``NacMass`` at ``NacCMxn/yn``, ``TowerHt + NacCMzn``; ``NacYIner`` is about the yaw
  axis (ElastoDyn gives the nacelle no roll or pitch inertia of its own);
* hub: ``HubMass`` at ``HubCM`` downwind of the rotor apex along the shaft, ``HubIner`` about
  the shaft; generator: ``GenIner`` about the shaft (its mass is in the nacelle's);
* blades: ``BMassDen`` x ``AdjBlMs`` of the blade files at the ``BldNodes`` element midpoints
  from ``HubRad`` to ``TipRad``, coned by ``PreCone``, plus ``TipMass``, blades at 0, 120,
  240 deg azimuth.  The rotor is taken locked (floatmoor's body is rigid).

HydroDyn: filled members (``NFillGroups``: ballast water or other fill) as the fluid inside
each member below its group's ``FillFSLoc``, inner diameter ``PropD - 2 PropThck`` tapered
between the member's joints, integrated in slices along the member.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...core.errors import SceneError
from . import schemas
from .reader import InputFile, split_words

__all__ = ["RigidMass", "elastodyn_masses", "filled_members", "member_geometry",
           "member_volumes", "combine"]


@dataclass(frozen=True, kw_only=True)
class RigidMass:
    """A rigid mass: kg, CoG (3,) m, 3x3 inertia about its CoG (kg m^2), and where it comes
    from (file and line) for the vessel file's comments and the mass budget."""

    name: str
    mass: float
    cog: np.ndarray
    inertia: np.ndarray
    source: str
    inertia_note: str = ""
    extra: dict = field(default_factory=dict)


def combine(items):
    """Total mass, CoG and inertia about the total CoG of a list of :class:`RigidMass`."""
    m = sum(it.mass for it in items)
    if m <= 0:
        return 0.0, np.zeros(3), np.zeros((3, 3))
    c = sum(it.mass * np.asarray(it.cog, float) for it in items) / m
    I = np.zeros((3, 3))
    for it in items:
        d = np.asarray(it.cog, float) - c
        I += np.asarray(it.inertia, float) + it.mass * (np.dot(d, d) * np.eye(3) - np.outer(d, d))
    return float(m), c, I


def _points(name, pts, masses, source, note=""):
    pts = np.asarray(pts, float)
    masses = np.asarray(masses, float)
    mt = float(masses.sum())
    c = masses @ pts / mt
    d = pts - c
    I = np.eye(3) * float(masses @ (d * d).sum(axis=1)) - (d.T * masses) @ d
    return RigidMass(name=name, mass=mt, cog=c, inertia=I, source=source, inertia_note=note)


def _lumped(frac, dens, length, nodes):
    """ElastoDyn's discretisation: ``nodes`` equal elements, the density interpolated linearly
    at their midpoints; returns (midpoint distances from the root, element masses)."""
    d = length / nodes
    x = d * (np.arange(nodes) + 0.5)
    return x, np.interp(x / length, frac, dens) * d


def _column(f: InputFile, title: str, wanted: str, fallback: int) -> int:
    """Index of the column ``wanted`` in the header line after the section ``title``."""
    for i, t in enumerate(f.lines):
        if title.upper() in t.upper() and t.strip().startswith("-"):
            words = [w.upper() for w in split_words(f.lines[i + 1])] if i + 1 < len(f.lines) else []
            if wanted.upper() in words:
                return words.index(wanted.upper())
            break
    return fallback


def _tower(ed: InputFile, unmapped):
    twr = ed.file("TwrFile")
    if twr is None or not twr.is_file():
        unmapped.append((ed.path, ed.line("TwrFile"), "TwrFile",
                         f"tower file {twr.name if twr else '(none)'} not found: the tower mass is "
                         f"NOT in the vessel", "add the tower as a point mass in vessel.yaml"))
        return None
    tf = InputFile(twr, schemas.ELASTODYN_TOWER, "ElastoDyn tower")
    n = tf.int("NTwInpSt")
    col = _column(tf, "DISTRIBUTED TOWER PROPERTIES", "TMassDen", 1)
    tab = tf.section_rows("DISTRIBUTED TOWER PROPERTIES", n, col + 1)
    base, top = ed.float("TowerBsHt"), ed.float("TowerHt")
    adj = tf.float("AdjTwMa", 1.0)
    h, m = _lumped(tab[:, 0], tab[:, col] * adj, top - base, ed.int("TwrNodes"))
    pts = np.column_stack([np.zeros_like(h), np.zeros_like(h), base + h])
    return _points("tower", pts, m,
                   f"ElastoDyn tower file {twr.name}: TMassDen x AdjTwMa {adj:g} at the "
                   f"{ed.int('TwrNodes')} TwrNodes midpoints from TowerBsHt {base:g} to TowerHt "
                   f"{top:g} m", "a line mass on the tower axis")


def _blades(ed: InputFile, apex, shaft, unmapped):
    nb = ed.int("NumBl")
    files = [ed.file(f"BldFile({k + 1})") for k in range(nb)]
    miss = [(k, f) for k, f in enumerate(files) if f is None or not f.is_file()]
    if miss:
        k, f = miss[0]
        unmapped.append((ed.path, ed.line(f"BldFile({k + 1})"), f"BldFile({k + 1})",
                         f"blade file {f.name if f else '(none)'} not found: the blade masses "
                         f"are NOT in the vessel", "add the rotor as a point mass in vessel.yaml"))
        return None
    hub_r, tip_r = ed.float("HubRad"), ed.float("TipRad")
    e_up = np.array([-shaft[2], 0.0, shaft[0]])   # in the rotor plane, up
    e_y = np.array([0.0, 1.0, 0.0])
    pts, mass = [], []
    adjs = []
    for k, bf in enumerate(files):
        b = InputFile(bf, schemas.ELASTODYN_BLADE, "ElastoDyn blade")
        col = _column(b, "DISTRIBUTED BLADE PROPERTIES", "BMassDen", 3)
        tab = b.section_rows("DISTRIBUTED BLADE PROPERTIES", b.int("NBlInpSt"), col + 1)
        adj = b.float("AdjBlMs", 1.0)
        adjs.append(adj)
        r, m = _lumped(tab[:, 0], tab[:, col] * adj, tip_r - hub_r, ed.int("BldNodes"))
        beta = math.radians(ed.float(f"PreCone({k + 1})", 0.0))
        psi = 2.0 * math.pi * k / nb
        axis = (math.cos(beta) * (math.cos(psi) * e_up + math.sin(psi) * e_y)
                + math.sin(beta) * shaft)
        radii, masses = list(hub_r + r), list(m)
        tip = ed.float(f"TipMass({k + 1})", 0.0)
        if tip:
            radii.append(tip_r)
            masses.append(tip)
        pts += [np.asarray(apex) + ri * axis for ri in radii]
        mass += masses
    return _points("blades", pts, mass,
                   f"ElastoDyn blade files ({', '.join(sorted({f.name for f in files}))}): "
                   f"BMassDen x AdjBlMs at the {ed.int('BldNodes')} BldNodes midpoints from HubRad "
                   f"{hub_r:g} to TipRad {tip_r:g} m, PreCone, TipMass; {nb} blades at 0, "
                   f"{360 // nb}, ... deg azimuth (rigid, locked rotor)")


def elastodyn_masses(ed: InputFile, unmapped):
    """Every rigid mass of an ElastoDyn file (see the module docstring); what cannot be
    mapped is appended to ``unmapped`` as (file, line, key, what, instead)."""
    out = []
    I = np.diag([ed.float("PtfmRIner"), ed.float("PtfmPIner"), ed.float("PtfmYIner")])
    for (i, j), key in (((0, 1), "PtfmXYIner"), ((1, 2), "PtfmYZIner"), ((0, 2), "PtfmXZIner")):
        I[i, j] = I[j, i] = ed.float(key, 0.0)
    out.append(RigidMass(name="platform", mass=ed.float("PtfmMass"),
                         cog=np.array([ed.float("PtfmCMxt", 0.0), ed.float("PtfmCMyt", 0.0),
                                       ed.float("PtfmCMzt")]), inertia=I,
                         source=f"ElastoDyn {ed.path.name} {ed.where('PtfmMass')}, PtfmCMxt/yt/zt, "
                                f"PtfmRIner/PIner/YIner" + (", PtfmXYIner/YZIner/XZIner"
                                                            if ed.has("PtfmXYIner") else "")))
    top = ed.float("TowerHt")
    tilt = math.radians(ed.float("ShftTilt"))
    shaft = np.array([math.cos(tilt), 0.0, math.sin(tilt)])  # downwind along the shaft
    oh = ed.float("OverHang")
    apex = np.array([0.0, 0.0, top + ed.float("Twr2Shft")]) + oh * shaft
    tower = _tower(ed, unmapped)
    if tower is not None:
        out.append(tower)
    ybm = ed.float("YawBrMass")
    if ybm:
        out.append(RigidMass(name="yaw_bearing", mass=ybm, cog=np.array([0.0, 0.0, top]),
                             inertia=np.zeros((3, 3)),
                             source=f"ElastoDyn {ed.path.name} {ed.where('YawBrMass')} at the tower top "
                                    f"(TowerHt {top:g} m)"))
    nm = ed.float("NacMass")
    nac = np.array([ed.float("NacCMxn"), ed.float("NacCMyn", 0.0), top + ed.float("NacCMzn")])
    nyi = ed.float("NacYIner") - nm * (nac[0] ** 2 + nac[1] ** 2)
    if nyi < -1e-6 * max(ed.float("NacYIner"), 1.0):
        raise SceneError(ed.path, ed.where("NacYIner"), f"the nacelle inertia about the yaw axis, "
                         f"at least NacMass (NacCMxn^2 + NacCMyn^2) = "
                         f"{nm * (nac[0] ** 2 + nac[1] ** 2):.6g} kg m^2", ed.text("NacYIner"))
    if nm:
        out.append(RigidMass(name="nacelle", mass=nm, cog=nac,
                             inertia=np.diag([0.0, 0.0, max(nyi, 0.0)]),
                             source=f"ElastoDyn {ed.path.name} {ed.where('NacMass')} at NacCMxn/yn, TowerHt + "
                                    f"NacCMzn", inertia_note="NacYIner less m r^2 (about the yaw "
                                                             "axis in ElastoDyn)"))
    hub = apex + ed.float("HubCM", 0.0) * shaft
    hm = ed.float("HubMass")
    hub_I = ed.float("HubIner") * np.outer(shaft, shaft)
    if hm:
        out.append(RigidMass(name="hub", mass=hm, cog=hub, inertia=hub_I,
                             source=f"ElastoDyn {ed.path.name} {ed.where('HubMass')} at HubCM from the rotor apex "
                                    f"(OverHang, ShftTilt, Twr2Shft)",
                             inertia_note="HubIner about the shaft"))
    gi = ed.float("GenIner", 0.0)
    if gi and hm:  # the generator's inertia about the shaft (no mass of its own), with the hub
        out[-1] = RigidMass(name="hub", mass=hm, cog=hub,
                            inertia=hub_I + gi * np.outer(shaft, shaft),
                            source=out[-1].source + f"; GenIner {gi:g} kg m^2 about the shaft "
                                                    f"(the generator turns with the body)",
                            inertia_note="HubIner + GenIner about the shaft")
    blades = _blades(ed, apex, shaft, unmapped)
    if blades is not None:
        out.append(blades)
    for key in ("PBrIner(1)", "BlPIner(1)"):
        if ed.has(key) and ed.float(key, 0.0):
            unmapped.append((ed.path, ed.line(key), key, f"{key} = {ed.text(key)} kg m^2 "
                             f"(pitch inertia about each blade's pitch axis)",
                             "not in the rigid body (small against the rotor's inertia)"))
    if ed.has("Furling") and ed.flag("Furling", False):
        unmapped.append((ed.path, ed.line("Furling"), "Furling", "a furling turbine (FurlFile "
                         "masses: tail and furl structure)", "not in the vessel"))
    return out


# ------------------------------------------------------------------------------------------------
# HydroDyn members
# ------------------------------------------------------------------------------------------------
def _header(f: InputFile, count_key: str):
    i = f.line(count_key)
    return [w.upper() for w in split_words(f.lines[i])] if i is not None and i < len(f.lines) else []


def _col(header, name, fallback):
    return header.index(name.upper()) if name.upper() in header else fallback


def member_geometry(hd: InputFile):
    """Members of a HydroDyn file: ``{id: (p1, p2, (D1, t1), (D2, t2), prop_pot, line)}``."""
    joints = {}
    hj = _header(hd, "NJoints")
    for ln, w in hd.table("NJoints", min_cols=4):
        try:
            joints[w[_col(hj, "JointID", 0)]] = np.array([float(w[_col(hj, "Jointxi", 1)]),
                                                          float(w[_col(hj, "Jointyi", 2)]),
                                                          float(w[_col(hj, "Jointzi", 3)])])
        except ValueError:
            raise SceneError(hd.path, f"line {ln}", "a joint row (JointID x y z ...)",
                             " ".join(w)) from None
    props = {}
    for ln, w in hd.table("NPropSets", min_cols=3):
        try:
            props[w[0]] = (float(w[1]), float(w[2]))
        except ValueError:
            raise SceneError(hd.path, f"line {ln}", "a property row (PropSetID PropD PropThck)",
                             " ".join(w)) from None
    hm = _header(hd, "NMembers")
    members = {}
    for ln, w in hd.table("NMembers", min_cols=5):
        mid = w[_col(hm, "MemberID", 0)]
        j1, j2 = w[_col(hm, "MJointID1", 1)], w[_col(hm, "MJointID2", 2)]
        p1, p2 = w[_col(hm, "MPropSetID1", 3)], w[_col(hm, "MPropSetID2", 4)]
        for j in (j1, j2):
            if j not in joints:
                raise SceneError(hd.path, f"line {ln}", f"a joint of the joint table "
                                 f"({', '.join(joints)})", j)
        for p in (p1, p2):
            if p not in props:
                raise SceneError(hd.path, f"line {ln}", f"a property set of the table "
                                 f"({', '.join(props)})", p)
        k = _col(hm, "PropPot", len(w) - 1)
        pot = k < len(w) and w[k].upper().startswith("T")
        members[mid] = (joints[j1], joints[j2], props[p1], props[p2], pot, ln)
    return members


def _slices(p1, p2, d1, d2, z_top, n=400):
    """Slices of a tapered cylinder below ``z_top``: (centres (n, 3), volumes (n,), radii (n,),
    axis) -- the part of each slice whose centre lies below ``z_top``."""
    L = float(np.linalg.norm(p2 - p1))
    axis = (p2 - p1) / L if L > 0 else np.array([0.0, 0.0, 1.0])
    s = (np.arange(n) + 0.5) / n
    c = p1 + np.outer(s, p2 - p1)
    r = 0.5 * (d1 + (d2 - d1) * s)
    vol = math.pi * r ** 2 * (L / n)
    keep = c[:, 2] <= z_top
    return c[keep], vol[keep], r[keep], axis


def member_volumes(hd: InputFile, members, *, pot: bool | None = None):
    """Displaced volume below the still-water line of the members (outer diameter), those with
    ``PropPot`` equal to ``pot`` (all when None): {id: volume m^3}."""
    out = {}
    for mid, (a, b, (d1, _t1), (d2, _t2), is_pot, _ln) in members.items():
        if pot is not None and is_pot != pot:
            continue
        _c, v, _r, _ax = _slices(a, b, d1, d2, 0.0)
        out[mid] = float(v.sum())
    return out


def filled_members(hd: InputFile, water_density: float):
    """The fill of each HydroDyn fill group as a :class:`RigidMass` (see the module
    docstring)."""
    groups = hd.table("NFillGroups", min_cols=4)
    if not groups:
        return []
    members = member_geometry(hd)
    out = []
    for g, (ln, w) in enumerate(groups, start=1):
        try:
            n = int(w[0])
            ids = w[1:1 + n]
            z_fs = float(w[1 + n])
            dens_t = w[2 + n]
        except (ValueError, IndexError):
            raise SceneError(hd.path, f"line {ln}", "a fill-group row (FillNumM, that many "
                             "member IDs, FillFSLoc, FillDens)", " ".join(w)) from None
        dens = water_density if dens_t.upper().strip('"') == "DEFAULT" else float(dens_t)
        pts, vols, inertia = [], [], np.zeros((3, 3))
        for mid in ids:
            if mid not in members:
                raise SceneError(hd.path, f"line {ln}", f"a member ID of the member table "
                                 f"({', '.join(members)})", mid)
            a, b, (d1, t1), (d2, t2), _pot, _mln = members[mid]
            c, v, r, axis = _slices(a, b, d1 - 2 * t1, d2 - 2 * t2, z_fs)
            if not v.size:
                continue
            pts.append(c)
            vols.append(v)
            # each slice a thin disc: m r^2/2 about the axis, m r^2/4 across (about its centre)
            m = dens * v
            Ia = float(np.sum(m * r ** 2 / 2))
            It = float(np.sum(m * r ** 2 / 4))
            inertia += It * np.eye(3) + (Ia - It) * np.outer(axis, axis)
        if not pts:
            continue
        c = np.vstack(pts)
        m = dens * np.concatenate(vols)
        mt = float(m.sum())
        cg = m @ c / mt
        d = c - cg
        inertia += np.eye(3) * float(m @ (d * d).sum(axis=1)) - (d.T * m) @ d
        out.append(RigidMass(
            name=f"fill_group_{g}", mass=mt, cog=cg, inertia=inertia,
            source=(f"HydroDyn {hd.path.name} line {ln}: fill group {g}, members "
                    f"{' '.join(ids)} filled to FillFSLoc {z_fs:g} m with FillDens {dens:g} "
                    f"kg/m^3 (inner diameter PropD - 2 PropThck)"),
            inertia_note="solid fill (its free surface is not modelled)",
            extra={"free_surface_z": z_fs, "density": dens, "members": ids}))
    return out
