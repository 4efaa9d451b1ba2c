"""The sea state of an OpenFAST model, from SeaState (OpenFAST v4 and later) or from HydroDyn
(the waves were in HydroDyn up to v3.5), as a floatmoor ``environment`` mapping.

Mapped: ``WaveMod 2`` (JONSWAP or Pierson-Moskowitz spectrum) with ``WaveHs``, ``WaveTp``,
``WavePkShp`` (``DEFAULT``: the IEC 61400-3 rule, floatmoor's ``gamma: null`` rule, the same
formula), ``WaveDir`` and ``WaveNDAmp``.  Refused at import: a sea state that cannot exist for
the wave model that uses it (``WaveHs <= 0``, ``WaveTp <= 0``, ``WavePkShp`` outside 1-7).
Listed as not mapped: other wave models (regular, white noise, user or external), the
directional spreading (HydroDyn's ``COS2S`` is cos^2s(theta - mean), floatmoor's cos2s is
cos^2s((theta - mean)/2)), the seeds, the frequency cut-offs, the second-order wave kinematics
and the current.
"""

from __future__ import annotations

import math

from ...core.errors import SceneError
from .reader import InputFile

__all__ = ["sea_state"]

_WAVE_MODELS = {0: "still water", 1: "regular waves", 2: "JONSWAP/Pierson-Moskowitz spectrum",
                3: "white-noise spectrum", 4: "user-defined spectrum",
                5: "externally generated wave elevation", 6: "externally generated kinematics",
                7: "user-defined wave components"}


def _wave_model(f: InputFile) -> int:
    t = f.text("WaveMod").strip('"').upper()
    if t.startswith("1P"):
        return 1
    return f.int("WaveMod")


def sea_state(f: InputFile, unmapped, *, fmt):
    """The ``waves:`` mapping text of the file's sea state (None for still water or an
    unmapped wave model); what is not mapped goes to ``unmapped`` as (file, line, key, what,
    instead)."""
    wm = _wave_model(f)
    where = f"{f.what} {f.path.name}"
    if wm in (1, 2, 3):
        hs = f.float("WaveHs")
        if not hs > 0.0:
            raise SceneError(f.path, f.where("WaveHs"), f"a significant wave height > 0 m (the "
                             f"{_WAVE_MODELS[wm]} of WaveMod {wm} uses it)", f.text("WaveHs"),
                             "a sea state that cannot exist is refused at import")
    if wm in (1, 2):
        tp = f.float("WaveTp")
        if not tp > 0.0:
            raise SceneError(f.path, f.where("WaveTp"), f"a peak period > 0 s (the "
                             f"{_WAVE_MODELS[wm]} of WaveMod {wm} uses it)", f.text("WaveTp"),
                             "a sea state that cannot exist is refused at import")
    if wm == 0:
        return None
    if wm != 2:
        unmapped.append((f.path, f.line("WaveMod"), "WaveMod",
                         f"WaveMod {f.text('WaveMod')} ({_WAVE_MODELS.get(wm, 'unknown')})",
                         "the scene is written without waves (floatmoor's waves are spectra: "
                         "give an environment with a JONSWAP sea state)"))
        return None
    gamma_txt = "null"
    gamma_note = "WavePkShp DEFAULT: the IEC 61400-3 / DNV-RP-C205 rule (null)"
    if not f.is_default("WavePkShp"):
        gamma = f.float("WavePkShp")
        if not 1.0 <= gamma <= 7.0:
            raise SceneError(f.path, f.where("WavePkShp"), "a JONSWAP peak-shape parameter "
                             "from 1 to 7 (OpenFAST's range) or DEFAULT", f.text("WavePkShp"))
        gamma_txt = fmt(gamma)
        gamma_note = f"WavePkShp {gamma:g}"
    head = f.float("WaveDir", 0.0)
    nd = f.flag("WaveNDAmp", False)
    spread = ""
    if f.int("WaveDirMod", 0) == 1 and f.int("WaveNDir", 1) > 1:
        unmapped.append((f.path, f.line("WaveDirMod"), "WaveDirMod",
                         f"directional spreading WaveDirMod 1 (HydroDyn's COS2S, cos^2s(theta - "
                         f"mean) over WaveDirRange {f.text('WaveDirRange', '-')} deg, "
                         f"WaveDirSpread {f.text('WaveDirSpread', '-')}, WaveNDir "
                         f"{f.text('WaveNDir', '-')})", "long-crested waves (floatmoor's cos2s is "
                         "cos^2s((theta - mean)/2), another function: set it in the scene)"))
    text = (f"  waves: {{spectrum: jonswap, hs: {fmt(f.float('WaveHs'))}, "
            f"tp: {fmt(f.float('WaveTp'))}, gamma: {gamma_txt}, heading_deg: {fmt(head)}, "
            f"random_amplitudes: {'true' if nd else 'false'}{spread}}}"
            f"   # {where}: WaveMod 2, WaveHs {f.where('WaveHs')}, WaveTp, WaveDir, WaveNDAmp; "
            f"{gamma_note}")
    seeds = [f.text(k, "-") for k in ("WaveSeed(1)", "WaveSeed(2)")]
    unmapped.append((f.path, f.line("WaveSeed(1)"), "WaveSeed",
                     f"wave seeds {seeds[0]}, {seeds[1]}",
                     "floatmoor draws its own phases (analysis.seeds)"))
    for key in ("WvLowCOff", "WvHiCOff"):
        if f.has(key):
            unmapped.append((f.path, f.line(key), key, f"{key} = {f.text(key)} rad/s",
                             "floatmoor's discretisation of the spectrum (environment waves "
                             "discretisation)"))
    if f.has("WaveTMax"):
        unmapped.append((f.path, f.line("WaveTMax"), "WaveTMax",
                         f"WaveTMax {f.text('WaveTMax')} s, WaveDT {f.text('WaveDT', '-')} s",
                         "the scene's analysis duration and floatmoor's wave discretisation"))
    for key in ("WvDiffQTF", "WvSumQTF"):
        if f.has(key) and f.flag(key, False):
            unmapped.append((f.path, f.line(key), key, f"{key} TRUE (second-order wave "
                             "kinematics)", "first-order (linear) wave kinematics"))
    return text


def current_unmapped(f: InputFile, unmapped):
    """The current of a SeaState/HydroDyn file, listed when it is not zero."""
    if not f.has("CurrMod") or f.int("CurrMod", 0) == 0:
        return
    speeds = [f.float(k, 0.0, default_word=0.0) for k in ("CurrSSV0", "CurrNSV0", "CurrDIV")]
    if any(abs(v) > 0 for v in speeds) or f.int("CurrMod") != 1:
        unmapped.append((f.path, f.line("CurrMod"), "CurrMod",
                         f"current CurrMod {f.text('CurrMod')} (sub-surface {speeds[0]:g}, "
                         f"near-surface {speeds[1]:g}, depth-independent {speeds[2]:g} m/s)",
                         "the scene has no current: add an environment current profile"))


def water_values(f: InputFile, fst: InputFile, ed: InputFile, notes, unmapped):
    """Water density and depth (this file's, else the driver's) and gravity (the driver's from
    v3.1, ElastoDyn's before)."""
    def pick(key, what):
        own = None
        if f.has(key) and not f.is_default(key):
            own = f.float(key)
        drv = fst.float(key) if fst.has(key) else None
        if own is None and drv is None:
            raise SceneError(f.path, key, f"the {what} in {f.path.name} or in the driver "
                             f"{fst.path.name}", SceneError.MISSING)
        if own is not None and drv is not None and not math.isclose(own, drv, rel_tol=1e-9):
            unmapped.append((f.path, f.line(key), key, f"{key} {own:g} here, {drv:g} in "
                             f"{fst.path.name} (OpenFAST gives MoorDyn and MAP++ the driver's "
                             f"value unless their own options set it)",
                             f"the scene's site and mooring use {own:g} ({f.path.name})"))
        return own if own is not None else drv
    rho = pick("WtrDens", "water density")
    depth = pick("WtrDpth", "water depth")
    if fst.has("Gravity"):
        g = fst.float("Gravity")
    elif ed.has("Gravity"):
        g = ed.float("Gravity")
        notes.append(f"gravity {g:g} m/s^2 from ElastoDyn {ed.where('Gravity')} (OpenFAST < 3.1)")
    else:
        raise SceneError(fst.path, "Gravity", "the gravity in the driver (OpenFAST >= 3.1) or in "
                         "ElastoDyn (before)", SceneError.MISSING)
    if f.has("MSL2SWL") and not f.is_default("MSL2SWL") and f.float("MSL2SWL") != 0.0:
        unmapped.append((f.path, f.line("MSL2SWL"), "MSL2SWL", f"MSL2SWL {f.text('MSL2SWL')} m",
                         "the still-water level is the mean sea level"))
    return rho, depth, g
