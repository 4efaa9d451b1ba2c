"""Hostile-input audit of the ``floatmoor`` command.

Runs a few hundred bad inputs -- mutated copies of the example scene, vessel, mooring, metocean,
campaign and scatter files, fibre-rope parameters, MoorDyn files, bad command lines -- each in a
forked child with a time limit and a memory limit, and counts the outcomes:

* ``ok``        a bad input refused with exit 2 and a ``floatmoor: error:`` message naming a
                file or an option (or a good input accepted, or a scenario handled: a stale
                or corrupted result recomputed or refused, naming it);
* ``traceback`` a Python traceback (or exit 1);
* ``hang``      killed at the time limit, or out of memory;
* ``silent``    exit 0 (a bad input accepted);
* ``warned``    exit 0 with a ``floatmoor: warning:`` (a doubtful input accepted, but said so);
* ``stale``     a scenario kept or reported a result that does not belong to its inputs (an
                old sea state taken as done, a corrupted seed taken as done or silently left
                out, a seed lost to two runs in one folder);
* ``other``     anything else (exit 3 for an input error, a message without a file, ...);
* ``broken``    a case whose mutation no longer applies to the shipped files (the audit itself
                needs updating);
* ``skipped``   a scenario this machine cannot run (a tmpfs for the full disk needs root).

The first audit's cases (scene, vessel, mooring, metocean files, command lines) come first,
then the second's: campaign files, scatter files, fibre ropes, MoorDyn/MAP++ sizes, the README's
commands, time steps, errors that used to surface in the workers, and the result-integrity
scenarios (each a short campaign or run: an edited contour, another campaign into the same
folder, a corrupted or truncated result read back, a damaged campaign record, two runs into one
folder, a full disk), which run real analyses (a few minutes in all).

Usage::

    PYTHONPATH=. python benchmarks/hostile_audit.py [--timeout 60] [--mem-mb 1500] [-k WORD] [-v]
                                                    [--no-scenarios]

The forked children share the parent's imports (numpy, xarray, floatmoor), so a case costs
the command's own work only.  Exit status 0 when no case was a traceback, a hang, silent, stale,
other or broken (``warned`` and ``skipped`` are listed but pass).
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import shutil
import signal
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

# -- building the mutated files ---------------------------------------------------------------


def _sub(text: str, key: str, value: str, count: int = 1) -> str:
    """Replace the value of the first ``key:`` (block or flow style) by ``value``."""
    pat = re.compile(r"(\b" + re.escape(key) + r":[ \t]*)(\[[^\n]*?\](?=\s*(#|,|\}|$))|[^,}\n#]*)",
                     re.M)
    new, n = pat.subn(lambda m: m.group(1) + value, text, count=count)
    if n == 0:
        raise KeyError(key)
    return new


class Tree:
    """A temporary copy of the example files; cases write mutated copies into it."""

    def __init__(self, root: Path):
        self.root = root
        for d in ("scenes", "metocean", "campaigns", "vessels/floatel_like",
                  "vessels/oc3_hywind"):
            src = REPO / d
            dst = root / d
            shutil.copytree(src, dst, ignore=shutil.ignore_patterns("source", "*.py", "results"))
        shutil.copy(REPO / "tests" / "io" / "data" / "oc4_moordyn_v1.dat", root / "oc4_moordyn.dat")
        self.n = 0

    def text(self, rel: str) -> str:
        return (self.root / rel).read_text()

    def write(self, rel_like: str, text: str, suffix=".yaml") -> str:
        """Write ``text`` next to ``rel_like`` under a fresh name; return the relative path."""
        self.n += 1
        p = (self.root / rel_like).parent / f"hostile_{self.n:04d}{suffix}"
        if isinstance(text, bytes):
            p.write_bytes(text)
        else:
            p.write_text(text)
        return str(p.relative_to(self.root))

    def scene_with(self, *, vessel=None, mooring=None, environment=None, base="scenes/floatel_100yr.yaml",
                   edit=None) -> str:
        t = self.text(base)
        if vessel:
            t = _sub(t, "vessel", "../" + vessel)
        if mooring:
            t = _sub(t, "mooring", "../" + mooring)
        if environment:
            t = _sub(t, "environment", "../" + environment)
        if edit:
            t = edit(t)
        return self.write(base, t)


BIG400 = "9" * 400
BIG5000 = "9" * 5000
LAUGHS = ("a: &a [1,1,1,1,1,1,1,1,1]\nb: &b [*a,*a,*a,*a,*a,*a,*a,*a,*a]\n"
          "c: &c [*b,*b,*b,*b,*b,*b,*b,*b,*b]\nd: &d [*c,*c,*c,*c,*c,*c,*c,*c,*c]\n"
          "e: &e [*d,*d,*d,*d,*d,*d,*d,*d,*d]\nf: &f [*e,*e,*e,*e,*e,*e,*e,*e,*e]\n"
          "g: &g [*f,*f,*f,*f,*f,*f,*f,*f,*f]\nh: &h [*g,*g,*g,*g,*g,*g,*g,*g,*g]\n")

BAD_NUMBERS = ["-1.0", "0", ".nan", ".inf", "-.inf", "1e400", "abc", "'16'", "[1, 2]", "true",
               "null", BIG400, "{a: 1}", "16 m"]


def cases(tree: Tree):
    """Yield (name, argv, expect) with expect "bad" (must be refused, exit 2) or "ok"."""
    S = "scenes/floatel_100yr.yaml"
    OC3 = "scenes/oc3_hywind.yaml"
    scene_text = tree.text(S)
    yield "control check --quick", ["check", "--quick", S], "ok"

    # -- YAML-level hostility, in the scene file ------------------------------------------
    yaml_bad = {
        "recursive alias": "name: x\nsite: {water_depth: 150.0}\nlevels: &r [*r]\n",
        "recursive alias in analysis": scene_text.replace("seeds: [1, 20]", "seeds: &r [*r]"),
        "billion laughs as value": LAUGHS + "name: x\nsite: {water_depth: *h}\n",
        "billion laughs in seeds": scene_text.replace("analysis:\n", LAUGHS.replace("\n", "\n  ").join(["analysis:\n  ", ""])).replace("seeds: [1, 20]", "seeds: *h"),
        "billion laughs in name": LAUGHS + "name: *h\nsite: {water_depth: 150.0}\n",
        "400-digit int dt": scene_text.replace("dt: 0.1 ", f"dt: {BIG400} "),
        "5000-digit int dt": scene_text.replace("dt: 0.1 ", f"dt: {BIG5000} "),
        "5000-digit int depth": scene_text.replace("water_depth: 150.0", f"water_depth: {BIG5000}"),
        "5000-digit float": scene_text.replace("dt: 0.1 ", f"dt: 0.{BIG5000} "),
        "400-digit seed": scene_text.replace("seeds: [1, 20]", f"seeds: {BIG400}"),
        "long string name": scene_text.replace("name: floatel", "name: " + "x" * 200000 + " floatel"),
        "deep nesting": "name: x\nsite: {water_depth: 150.0}\nanalysis: " + "[" * 5000 + "]" * 5000 + "\n",
        "deep nesting mapping": "name: x\nsite: " + "{a: " * 3000 + "1" + "}" * 3000 + "\n",
        "tabs": "name: x\nsite:\n\twater_depth: 150\n",
        "binary": b"\x00\x01\xff\xfe garbage",
        "latin-1": "name: caf\xe9\nsite: {water_depth: 150.0}\n".encode("latin-1"),
        "empty": "",
        "top list": "- 1\n- 2\n",
        "top scalar": "42\n",
        "duplicate key": scene_text + "site: {water_depth: 150.0}\n",
        "python tag": "name: !!python/object/apply:os.system ['echo hi']\nsite: {water_depth: 150}\n",
        "timestamp": scene_text.replace("dt: 0.1 ", "dt: 2001-12-14 "),
        "binary tag": scene_text.replace("dt: 0.1 ", "dt: !!binary aGVsbG8= "),
        "set tag": scene_text.replace("dt: 0.1 ", "dt: !!set {a, b} "),
        "merge key bomb": LAUGHS + "name: x\nsite: {<<: {water_depth: 150.0}, x: *h}\n",
        "anchor on mapping reused": "base: &b {water_depth: 150.0}\nname: x\nsite: *b\n",
    }
    for name, text in yaml_bad.items():
        yield f"yaml: {name}", ["check", "--quick", tree.write(S, text)], "bad"

    # -- numeric keys of the scene, environment and analysis ------------------------------
    keys = [("water_depth", S), ("water_density", S), ("duration", S), ("dt", S),
            ("transient", S), ("ramp", S)]
    for key, base in keys:
        for v in BAD_NUMBERS:
            if key in ("transient", "ramp") and v in ("0",):
                continue
            t = _sub(tree.text(base), key, v)
            yield f"{key}={v[:12]}", ["check", "--quick", tree.write(base, t)], "bad"
    env = "metocean/heidrun_100yr.yaml"
    for key in ("hs", "tp", "u10", "heading_deg"):
        for v in BAD_NUMBERS + (["3.1416", "1.5708"] if key == "heading_deg" else []):
            if key == "heading_deg" and v in ("0", "-1.0"):
                continue
            e = tree.write(env, _sub(tree.text(env), key, v))
            yield f"env {key}={v[:12]}", ["check", "--quick", tree.scene_with(environment=e)], "bad"
    for name, old, new in [
        ("gamma 100", "gamma: null", "gamma: 100"),
        ("spectrum typo", "spectrum: jonswap", "spectrum: jonswop"),
        ("wind spectrum typo", "spectrum: npd", "spectrum: npdd"),
        ("current levels radians?", "heading_deg: 0.0\n", "heading_deg: 0.0\n", ),
        ("current level above surface", "[[0.0, 0.94]", "[[10.0, 0.94]"),
        ("current level below seabed", "[-50.0, 0.94]", "[-500.0, 0.94]"),
        ("current speed nan", "[-25.0, 0.94]", "[-25.0, .nan]"),
        ("current levels scalar", "levels: [[0.0, 0.94], [-25.0, 0.94], [-50.0, 0.94]]", "levels: 3"),
        ("current levels recursive", "levels: [[0.0, 0.94], [-25.0, 0.94], [-50.0, 0.94]]", "levels: &r [*r]"),
        ("n_frequencies 1e8", "  heading_deg: 0.0\nwind", "  heading_deg: 0.0\n  discretisation: {n_frequencies: 100000000}\nwind"),
        ("n_frequencies 2e6", "  heading_deg: 0.0\nwind", "  heading_deg: 0.0\n  discretisation: {n_frequencies: 2000000}\nwind"),
        ("n_directions 1e6", "  heading_deg: 0.0\nwind", "  heading_deg: 0.0\n  spreading: cos2s\n  spreading_s: 10\n  n_directions: 1000000\nwind"),
        ("n_directions 100000", "  heading_deg: 0.0\nwind", "  heading_deg: 0.0\n  spreading: cos2s\n  spreading_s: 10\n  n_directions: 100000\nwind"),
        ("wind n_frequencies 1e8", "  u10: 36.0", "  u10: 36.0\n  discretisation: {n_frequencies: 100000000}"),
        ("omega_max 1e9", "  heading_deg: 0.0\nwind", "  heading_deg: 0.0\n  discretisation: {omega_max: 1.0e+9}\nwind"),
    ]:
        if old == new:
            continue
        e = tree.write(env, tree.text(env).replace(old, new, 1))
        yield f"env {name}", ["check", "--quick", tree.scene_with(environment=e)], "bad"

    # -- analysis sizes and seeds ----------------------------------------------------------
    for name, old, new in [
        ("dt 1e-9", "dt: 0.1 ", "dt: 1.0e-9 "),
        ("dt 1e-6", "dt: 0.1 ", "dt: 1.0e-6 "),
        ("duration 1e12", "duration: 12000.0", "duration: 1.0e+12"),
        ("duration 1e9", "duration: 12000.0", "duration: 1.0e+9"),
        ("seeds [0, 4294967295]", "seeds: [1, 20]", "seeds: [0, 4294967295]"),
        ("seeds [0, 5000000000]", "seeds: [1, 20]", "seeds: [0, 5000000000]"),
        ("seeds 5000000000", "seeds: [1, 20]", "seeds: 5000000000"),
        ("seeds '1-4294967295'", "seeds: [1, 20]", "seeds: '1-4294967295'"),
        ("seeds '1-99999999999999999999'", "seeds: [1, 20]", "seeds: '1-99999999999999999999'"),
        ("seeds '0-100000000,5'", "seeds: [1, 20]", "seeds: '0-100000000'"),
        ("seeds [-5, 3]", "seeds: [1, 20]", "seeds: [-5, 3]"),
        ("seeds [20, 1]", "seeds: [1, 20]", "seeds: [20, 1]"),
        ("seeds [1, 2, 3]", "seeds: [1, 20]", "seeds: [1, 2, 3]"),
        ("seeds 'a-b'", "seeds: [1, 20]", "seeds: 'a-b'"),
        ("seeds 1.5", "seeds: [1, 20]", "seeds: 1.5"),
        ("seeds huge text", "seeds: [1, 20]", "seeds: '" + ",".join(str(i) for i in range(3000)) + ",1'"),
        ("unknown key analysis", "ramp: 100.0", "ramp: 100.0\n  rampp: 1"),
        ("unknown top key", "analysis:", "analysys: 1\nanalysis:"),
        ("transient > duration", "transient: 1200.0", "transient: 13000.0"),
    ]:
        yield f"analysis {name}", ["check", "--quick", tree.write(S, scene_text.replace(old, new, 1))], "bad"
    # the same size bombs reached through run (must be refused before anything is allocated)
    for name, old, new in [("dt 1e-9", "dt: 0.1 ", "dt: 1.0e-9 "),
                           ("duration 1e12", "duration: 12000.0", "duration: 1.0e+12"),
                           ("seeds [0, 4294967295]", "seeds: [1, 20]", "seeds: [0, 4294967295]")]:
        sc = tree.write(S, scene_text.replace(old, new, 1))
        yield f"run {name}", ["run", sc, "--out", str(tree.root / f"out_{tree.n}")], "bad"

    # -- site -----------------------------------------------------------------------------
    for name, old, new in [("depth 5 (< draft 13)", "water_depth: 150.0", "water_depth: 5.0"),
                           ("depth 12", "water_depth: 150.0", "water_depth: 12.0"),
                           ("depth 3000 vs database", "water_depth: 150.0", "water_depth: 3000.0"),
                           ("density t/m3", "water_density: 1025.0", "water_density: 1.025"),
                           ("density 1e6", "water_density: 1025.0", "water_density: 1.0e+6")]:
        yield f"site {name}", ["check", tree.write(S, scene_text.replace(old, new, 1))], "bad"

    # -- vessel file ------------------------------------------------------------------------
    V = "vessels/floatel_like/vessel.yaml"
    vt = tree.text(V)
    vessel_cases = [
        ("mass in tonnes", "mass: 2.5472e+7", "mass: 2.5472e+4"),
        ("mass x10", "mass: 2.5472e+7", "mass: 2.5472e+8"),
        ("mass 0", "mass: 2.5472e+7", "mass: 0"),
        ("mass negative", "mass: 2.5472e+7", "mass: -2.5472e+7"),
        ("mass string", "mass: 2.5472e+7", "mass: heavy"),
        ("mass 400 digits", "mass: 2.5472e+7", f"mass: {BIG400}"),
        ("CoG above metacentre", "centre_of_gravity: [0.0, 0.0, 7.0]", "centre_of_gravity: [0.0, 0.0, 60.0]"),
        ("CoG z 40", "centre_of_gravity: [0.0, 0.0, 7.0]", "centre_of_gravity: [0.0, 0.0, 40.0]"),
        ("CoG 2 values", "centre_of_gravity: [0.0, 0.0, 7.0]", "centre_of_gravity: [0.0, 7.0]"),
        ("CoG nan", "centre_of_gravity: [0.0, 0.0, 7.0]", "centre_of_gravity: [0.0, 0.0, .nan]"),
        ("inertia negative", "inertia_cg: [2.29248e+10", "inertia_cg: [-2.29248e+10"),
        ("inertia 2 values", "inertia_cg: [2.29248e+10, 2.447859e+10, 3.12032e+10]", "inertia_cg: [2.29248e+10, 2.447859e+10]"),
        ("database missing", "database: database.nc", "database: nothere.nc"),
        ("database is dir", "database: database.nc", "database: ."),
        ("database is yaml", "database: database.nc", "database: vessel.yaml"),
        ("reference point 2", "reference_point: [0.0, 0.0, 0.0]", "reference_point: [0.0, 0.0]"),
        ("damping 5 rows", "  - [0, 0, 0, 0, 0, 2.61e+9]\n", "\n"),
        ("damping negative", "  - [1.5e+6, 0, 0, 0, 0, 0]", "  - [-1.5e+6, 0, 0, 0, 0, 0]"),
        ("wind coeff heading radians", "heading_deg: [0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330]\n  surge: [1543.0",
         "heading_deg: [0, 0.5236, 1.0472, 1.5708, 2.0944, 2.618, 3.1416, 3.6652, 4.1888, 4.7124, 5.236, 5.7596]\n  surge: [1543.0"),
        ("current coeff heading radians", "heading_deg: [0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330]\n  surge: [3.129e+5",
         "heading_deg: [0, 0.5236, 1.0472, 1.5708, 2.0944, 2.618, 3.1416, 3.6652, 4.1888, 4.7124, 5.236, 5.7596]\n  surge: [3.129e+5"),
        ("wind coeff heading not increasing", "heading_deg: [0, 30, 60, 90,", "heading_deg: [0, 60, 30, 90,"),
        ("wind coeff short row", "surge: [1543.0, 1157.25,", "surge: [1157.25,"),
        ("wind coeff nan", "surge: [1543.0,", "surge: [.nan,"),
        ("wind coeff string", "surge: [1543.0,", "surge: [a,"),
        ("no wind coefficients", "wind_coefficients:", "wind_coefficientz:"),
        ("slender typo", "quadratic_drag_per_length:", "quadratic_drag_per_lenght:"),
        ("slender unknown type", "type: pontoon, p1: [-25.25, 45.0", "type: pontoonn, p1: [-25.25, 45.0"),
        ("slender zero length", "p2: [-25.25, -25.5, -4.375]", "p2: [-25.25, -25.5, 14.5]"),
        ("slender negative drag", "c2y: 7687.5", "c2y: -7687.5"),
        ("unknown vessel key", "mass: 2.5472e+7", "mass: 2.5472e+7\nmasss: 1"),
        ("recursive alias", "mass: 2.5472e+7", "mass: &r [*r]"),
        ("billion laughs", "mass: 2.5472e+7", LAUGHS + "mass: *h"),
    ]
    for name, old, new in vessel_cases:
        if old not in vt:
            yield f"vessel {name}", None, "broken"
            continue
        v = tree.write(V, vt.replace(old, new, 1))
        yield f"vessel {name}", ["check", tree.scene_with(vessel=v)], "bad"
    # the vessel with no wind coefficients must be refused by check when wind is on, and the
    # unstable floater by statics too
    v = tree.write(V, vt.replace("centre_of_gravity: [0.0, 0.0, 7.0]", "centre_of_gravity: [0.0, 0.0, 60.0]"))
    yield "statics unstable floater", ["statics", tree.scene_with(vessel=v)], "bad"
    v = tree.write(V, vt.replace("mass: 2.5472e+7", "mass: 2.5472e+4"))
    yield "statics mass in tonnes", ["statics", tree.scene_with(vessel=v)], "bad"

    # -- mooring file -----------------------------------------------------------------------
    M = "vessels/floatel_like/mooring.yaml"
    mt = tree.text(M)
    first_len = re.search(r"\blength: ([0-9.]+)", mt).group(0)
    anchor = re.search(r"anchor: \{[^}]*\}", mt).group(0)
    mooring_cases = [
        ("material chian", "material: chain", "material: chian"),
        ("material polyster", "material: polyester", "material: polyster"),
        ("material number", "material: chain", "material: 3"),
        ("diameter negative", "diameter: 0.084", "diameter: -0.084"),
        ("diameter mm", "diameter: 0.084", "diameter: 84"),
        ("mbs zero", "mbs: 8.5e+6", "mbs: 0"),
        ("mbs string", "mbs: 8.5e+6", "mbs: 8500 kN"),
        ("E nan", "elastic_modulus: 6.004e+10", "elastic_modulus: .nan"),
        ("E 400 digits", "elastic_modulus: 6.004e+10", f"elastic_modulus: {BIG400}"),
        ("density below water", "density: 7850.0", "density: 785.0"),
        ("mass_per_length negative", "mass_per_length: 140.41", "mass_per_length: -140.41"),
        ("unknown line type", "type: floatel_chain_84", "type: floatel_chain_48"),
        ("segment length short", first_len, "length: 10.0"),
        ("segment length 1e9", first_len, "length: 1.0e+9"),
        ("segment length 0", first_len, "length: 0"),
        ("anchor 120 m above seabed", anchor, anchor.replace("}", ", z: -30.0}")),
        ("anchor below seabed", anchor, anchor.replace("}", ", z: -300.0}")),
        ("anchor azimuth radians", anchor, re.sub(r"azimuth_deg: [-0-9.]+", "azimuth_deg: 0.7854", anchor)),
        ("anchor nan", anchor, re.sub(r"radius: [-0-9.]+", "radius: .nan", anchor) if "radius" in anchor else anchor.replace("{", "{x: .nan, ", 1)),
        ("recursive alias", "description:", "x: &r [*r]\ndescription:"),
        ("duplicate key", "description:", "description: a\ndescription:"),
        ("unknown key", "description:", "descripton: a\ndescription:"),
    ]
    for name, old, new in mooring_cases:
        if old == new or old not in mt:
            continue
        m = tree.write(M, mt.replace(old, new, 1))
        yield f"mooring {name}", ["check", tree.scene_with(mooring=m)], "bad"
    names = re.findall(r"name: (line\d+)", mt)
    m = tree.write(M, mt + "failed_lines: [" + ", ".join(names) + "]\n")
    yield "mooring every line failed", ["check", tree.scene_with(mooring=m)], "bad"
    m = tree.write(M, mt + "failed_lines: [nope]\n")
    yield "mooring failed unknown line", ["check", tree.scene_with(mooring=m)], "bad"
    m = tree.write(M, mt.replace(first_len, "length: 10.0", 1))
    yield "statics line too short", ["statics", tree.scene_with(mooring=m)], "bad"

    # -- command lines -----------------------------------------------------------------------
    f = tree.root / "a_file.txt"
    f.write_text("x")
    d = tree.root / "a_dir"
    d.mkdir(exist_ok=True)
    (d / "x.nc").write_text("not netcdf")
    ro = tree.root / "ro_dir"
    ro.mkdir(exist_ok=True)
    short = ["--duration", "30", "--dt", "0.2"]
    cl = [
        ("run --out existing file", ["run", OC3, "--out", str(f)] + short),
        ("run --out file/sub", ["run", OC3, "--out", str(f / "sub")] + short),
        ("run --seeds 1-4294967295", ["run", OC3, "--seeds", "1-4294967295", "--out", str(d / "r1")]),
        ("run --seeds 5000000000", ["run", OC3, "--seeds", "5000000000", "--out", str(d / "r2")]),
        ("run --seeds 1-99999999999999999999", ["run", OC3, "--seeds", "1-99999999999999999999", "--out", str(d / "r3")]),
        ("run --seeds -3", ["run", OC3, "--seeds", "-3", "--out", str(d / "r4")]),
        ("run --seeds 5-1", ["run", OC3, "--seeds", "5-1", "--out", str(d / "r5")]),
        ("run --seeds empty", ["run", OC3, "--seeds", "", "--out", str(d / "r6")]),
        ("run --workers 0", ["run", OC3, "--workers", "0", "--out", str(d / "r7")]),
        ("run --dt 1e-12", ["run", OC3, "--dt", "1e-12", "--out", str(d / "r8")]),
        ("run --duration 1e15", ["run", OC3, "--duration", "1e15", "--out", str(d / "r9")]),
        ("run --dt nan", ["run", OC3, "--dt", "nan", "--out", str(d / "r10")]),
        ("run --lines -1", ["run", OC3, "--lines", "-1", "--seeds", "1", "--out", str(d / "r11")] + ["--duration", "1e15"]),
        ("run missing scene", ["run", "nope.yaml"]),
        ("run scene is dir", ["run", "scenes"]),
        ("report --out existing file", ["report", str(d), "--out", str(f)]),
        ("report on non-result dir", ["report", str(d)]),
        ("report on missing dir", ["report", str(tree.root / "nope")]),
        ("fd --out existing dir", ["fd", OC3, "--out", str(d)]),
        ("fd --out file/sub", ["fd", OC3, "--out", str(f / "sub.nc")]),
        ("statics missing", ["statics", "nope.yaml"]),
        ("environment --seed huge", ["environment", OC3, "--seed", "99999999999999999999999"]),
        ("environment --dt 1e-9", ["environment", OC3, "--dt", "1e-9"]),
        ("environment --duration 1e12", ["environment", OC3, "--duration", "1e12"]),
        ("lines --harmonic surge:5000:15", ["lines", OC3, "--harmonic", "surge:5000:15", "--duration", "20"]),
        ("lines --harmonic pitch:90:15", ["lines", OC3, "--harmonic", "pitch:90:15", "--duration", "20"]),
        ("lines --harmonic heave:500:10", ["lines", OC3, "--harmonic", "heave:500:10", "--duration", "20"]),
        ("lines --harmonic surge:3:0", ["lines", OC3, "--harmonic", "surge:3:0", "--duration", "20"]),
        ("lines --harmonic bad", ["lines", OC3, "--harmonic", "surge:x", "--duration", "20"]),
        ("convergence --dt 0", ["convergence", OC3, "--dt", "0"]),
        ("unknown command", ["frobnicate"]),
        ("check no args", ["check"]),
    ]
    for name, argv in cl:
        yield f"cli {name}", argv, "bad"


# -- the second audit: campaign, scatter, fibre, import files; README commands ----------------

CAMPAIGN = """name: audit
base_scene: ../scenes/floatel_100yr.yaml
sea_states: {list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: 16.0, tp: 18.2}]}
headings: {waves_deg: [0, 45, 90], wind_offset_deg: [0], current_offset_deg: [0, 30]}
conditions: {intact: true, failed_lines: [[line6], [line7]]}
seeds: "1-3"
analysis: {duration: 600.0, dt: 0.2, transient: 100.0}
"""

FIBRE = ("    fibre: {working_curve: {strain: [0.0, 0.01, 0.02, 0.04], "
         "tension_mbs: [0.0, 0.12, 0.28, 0.60]}, dynamic: {alpha: 11.6, beta: 0.40}}\n")


def cases2(tree: Tree):
    """The second audit's one-command cases: (name, argv, expect)."""
    import yaml
    S = "scenes/floatel_100yr.yaml"
    C = "campaigns/audit.yaml"
    (tree.root / C).write_text(CAMPAIGN)
    yield ("campaign control (good file)",
           ["campaign", C, "--dry-run", "--fd-budget", "0.01"], "ok")
    campaign_cases = [
        ("headings in radians", "[0, 45, 90]", "[0, 0.7854, 1.5708, 3.1416]"),
        ("heading range to 6.2832", "[0, 45, 90]", "{start: 0, stop: 6.2832, step: 0.7854}"),
        ("wind offset 3.1416", "wind_offset_deg: [0]", "wind_offset_deg: [3.1416]"),
        ("direction twice [0, 360]", "[0, 45, 90]", "[0, 360]"),
        ("ids collide [0, 0.04, 360]", "[0, 45, 90]", "[0, 0.04, 360]"),
        ("condition twice", "[[line6], [line7]]", "[[line6], [line6]]"),
        ("condition twice reordered", "[[line6], [line7]]", "[[line6, line7], [line7, line6]]"),
        ("sea state twice", "{name: b, hs: 16.0, tp: 18.2}", "{name: b, hs: 10.0, tp: 12.5}"),
        ("contour Hs 16 at Tp 8", "{name: b, hs: 16.0, tp: 18.2}", "{name: b, hs: 16.0, tp: 8.0}"),
        ("gamma 0.5", "{name: a, hs: 10.0, tp: 12.5}", "{name: a, hs: 10.0, tp: 12.5, gamma: 0.5}"),
        ("probability on a sea state", "{name: a, hs: 10.0, tp: 12.5}",
         "{name: a, hs: 10.0, tp: 12.5, probability: 0.1}"),
        ("heading range of a million", "[0, 45, 90]", "{start: 0, stop: 345, step: 0.0001}"),
        ("dt 100 (ms)", "dt: 0.2", "dt: 100"),
        ("duration < transient", "duration: 600.0", "duration: 60.0"),
        ("break at 1500 s of 600 s", "failed_lines: [[line6], [line7]]",
         "line_failure: {lines: [line6], time: 1500.0}"),
        ("break in the transient", "failed_lines: [[line6], [line7]]",
         "line_failure: {lines: [line6], time: 50.0}"),
        ("base_scene a folder", "base_scene: ../scenes/floatel_100yr.yaml", "base_scene: ../scenes"),
        ("base_scene missing", "base_scene: ../scenes/floatel_100yr.yaml", "base_scene: ../nope.yaml"),
        ("unknown line", "[[line6], [line7]]", "[[line66]]"),
        ("every line failed", "[[line6], [line7]]",
         "[[line1, line2, line3, line4, line5, line6, line7, line8, line9, line10, line11, line12]]"),
        ("two seeds", 'seeds: "1-3"', 'seeds: "1-2"'),
        ("scatter diagram", "sea_states: {list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: "
         "16.0, tp: 18.2}]}", "sea_states: {scatter: ../metocean/floatel_like_scatter.yaml}"),
        ("unknown key", "seeds:", "seedz: 1\nseeds:"),
    ]
    for name, old, new in campaign_cases:
        if old not in CAMPAIGN:
            yield f"campaign {name}", None, "broken"
            continue
        yield f"campaign {name}", ["campaign", tree.write(C, CAMPAIGN.replace(old, new, 1)),
                                   "--dry-run"], "bad"
    big = CAMPAIGN.replace("[0, 45, 90]", "{start: 0, stop: 359.9, step: 0.1}").replace(
        "current_offset_deg: [0, 30]", "current_offset_deg: {start: -39, stop: 39, step: 2}")
    big = big.replace("{list: [{name: a, hs: 10.0, tp: 12.5}, {name: b, hs: 16.0, tp: 18.2}]}",
                      "{contour: ../metocean/heidrun_contour.yaml}")
    big = big.replace("conditions: {intact: true, failed_lines: [[line6], [line7]]}",
                      "conditions: {intact: true}")
    yield "campaign 1,008,000 cases", ["campaign", tree.write(C, big), "--out",
                                       str(tree.root / "big_out")], "bad"
    yield "campaign binary garbage", ["campaign", tree.write(C, bytes(range(1, 32)) * 50)], "bad"
    yield "campaign random bytes", ["campaign", tree.write(C, os.urandom(3000))], "bad"
    yield "campaign empty", ["campaign", tree.write(C, "")], "bad"
    yield "campaign --duration 600 < transient 1200", [
        "campaign", "campaigns/floatel_uls_als.yaml", "--duration", "600", "--out",
        str(tree.root / "d600")], "bad"
    yield "campaign --duration 1e15", ["campaign", "campaigns/floatel_uls_als.yaml",
                                       "--duration", "1e15", "--dry-run"], "bad"
    brk = CAMPAIGN.replace("failed_lines: [[line6], [line7]]",
                           "line_failure: {lines: [line6], time: 1500.0}").replace(
        "duration: 600.0", "duration: 3000.0")
    yield "campaign break 1500 s, --duration 600", [
        "campaign", tree.write(C, brk), "--duration", "600", "--out", str(tree.root / "brk")], \
        "bad"
    yield "campaign --seeds 1-4294967295", ["campaign", C, "--seeds", "1-4294967295",
                                            "--dry-run"], "bad"

    # -- scatter files (floatmoor fatigue) --------------------------------------------------
    SC = "metocean/floatel_like_scatter.yaml"
    base = yaml.safe_load((tree.root / SC).read_text())

    def scatter(edit):
        d = yaml.safe_load(yaml.safe_dump(base))
        edit(d)
        return tree.write(SC, yaml.safe_dump(d))

    def move(d, i, j, ii, jj):
        p = [list(r) for r in d["probability"]]
        p[i][j] += p[ii][jj]
        p[ii][jj] = 0.0
        d["probability"] = p

    fat = ["fatigue", S, "--td-cells", "0", "--scatter"]
    scatter_cases = [
        ("gamma 0.5", lambda d: d.update(gamma=0.5)),
        ("gamma 0", lambda d: d.update(gamma=0)),
        ("Hs 3 m at Tp 0.5 s", lambda d: (d.update(tp=[0.5] + d["tp"][1:]), move(d, 1, 0, 1, 3))),
        ("Hs 9 m at Tp 5 s", lambda d: move(d, 4, 1, 4, 6)),
        ("headings in radians", lambda d: d["directions"].update(
            heading_deg=[0, 0.7854, 1.5708, 2.3562, 3.1416, 3.927, 4.7124, 5.4978])),
        ("direction twice", lambda d: d["directions"].update(
            heading_deg=[0, 45, 90, 135, 180, 225, 270, 360])),
        ("tp bins reversed", lambda d: d.update(tp=d["tp"][::-1])),
        ("probabilities sum 0.5", lambda d: d.update(
            probability=[[x / 2 for x in r] for r in d["probability"]])),
        ("negative probability", lambda d: move(d, 0, 0, 0, 1) or d["probability"][0].__setitem__(
            0, -d["probability"][0][0])),
        ("1,000,000 cells", lambda d: d.update(
            hs=[round(0.1 * i, 2) for i in range(1, 101)],
            tp=[round(10 + 0.3 * i, 2) for i in range(1, 101)],
            probability=[[1e-4] * 100 for _ in range(100)], u10=[5.0] * 100,
            directions={"heading_deg": [i * 0.36 + 0.1 for i in range(1000)],
                        "probability": [1e-3] * 1000})),
        ("table shape", lambda d: d.update(probability=d["probability"][:-1])),
        ("u10 in km/h", lambda d: d.update(u10=[x * 3.6 for x in d["u10"]])),
    ]
    for name, edit in scatter_cases:
        yield f"scatter {name}", fat + [scatter(edit)], "bad"
    txt = (tree.root / SC).read_text()
    yield "scatter control character in a comment", fat + [
        tree.write(SC, txt.replace("# Wind:", "# Wind\x07:", 1))], "bad"
    yield "scatter binary", fat + [tree.write(SC, os.urandom(2000))], "bad"
    yield "fatigue --corrosion -0.3 0.4", fat + [SC, "--corrosion", "-0.3", "0.4"], "bad"
    yield "fatigue --corrosion 10 10 (whole diameter)", fat + [SC, "--corrosion", "10", "10"], "bad"
    yield "fatigue --corrosion nan 0.4", fat + [SC, "--corrosion", "nan", "0.4"], "bad"

    # -- fibre ropes in the wrong unit ------------------------------------------------------
    M = "vessels/floatel_like/mooring.yaml"
    mt = tree.text(M)
    anchor = "    source: Wang (2016) table 5.2 (E, MBS, Cd); mass from catalogue fit\n"
    parts = mt.split(anchor)

    def fibre_mooring(entry, on_chain=False):
        k = 0 if on_chain else 1
        pp = list(parts)
        pp[k] += anchor + entry
        pp[1 - k] += anchor
        return tree.write(M, pp[0] + pp[1] + pp[2])

    if len(parts) != 3:
        yield "fibre (mooring file changed)", None, "broken"
    else:
        yield "fibre control (plausible)", ["check", tree.scene_with(
            mooring=fibre_mooring(FIBRE))], "ok"
        for name, old, new in [
                ("strain in percent", "strain: [0.0, 0.01, 0.02, 0.04]", "strain: [0.0, 1.0, 2.0, 4.0]"),
                ("tension in kN", "tension_mbs: [0.0, 0.12, 0.28, 0.60]",
                 "tension_mbs: [0.0, 1020.0, 2380.0, 5100.0]"),
                ("tension in % MBS", "tension_mbs: [0.0, 0.12, 0.28, 0.60]",
                 "tension_mbs: [0.0, 12.0, 28.0, 60.0]"),
                ("beta 40", "beta: 0.40", "beta: 40.0"),
                ("alpha 1e9", "alpha: 11.6", "alpha: 1.0e+9"),
                ("strain step 100 %", "strain: [0.0, 0.01, 0.02, 0.04]", "strain: [0.0, 1.0, 2.0, 3.0]"),
                ("stiff as steel", "strain: [0.0, 0.01, 0.02, 0.04]",
                 "strain: [0.0, 0.0005, 0.001, 0.002]"),
                ("polynomial max_strain 1", "working_curve: {strain: [0.0, 0.01, 0.02, 0.04], "
                 "tension_mbs: [0.0, 0.12, 0.28, 0.60]}", "working_curve: {polynomial: [12.0], "
                 "max_strain: 1.0}")]:
            yield f"fibre {name}", ["check", tree.scene_with(
                mooring=fibre_mooring(FIBRE.replace(old, new)))], "bad"
        yield "fibre polyester curve on a chain type", ["check", tree.scene_with(
            mooring=fibre_mooring(FIBRE, on_chain=True))], "bad"

    # -- MoorDyn / MAP++ -------------------------------------------------------------------
    huge = tree.root / "huge.dat"
    with open(huge, "wb") as f:
        f.truncate(200 * 2**20)
    yield "moordyn 200 MB file", ["import", "moordyn", str(huge), "--out", "m.yaml"], "bad"
    md = (tree.root / "oc4_moordyn.dat").read_text().splitlines()
    i = next(k for k, ln in enumerate(md) if ln.split()[:1] == ["Line"]) + 2
    tok = md[i].split()
    tok[3] = "1000000000"
    seg = tree.write("oc4_moordyn.dat", "\n".join(md[:i] + ["  ".join(tok)] + md[i + 1:]) + "\n",
                     suffix=".dat")
    yield "moordyn NumSegs 1e9", ["import", "moordyn", seg, "--out", "m.yaml"], "bad"
    yield "moordyn binary", ["import", "moordyn", tree.write("oc4_moordyn.dat", os.urandom(3000),
                                                               suffix=".dat"), "--out", "m.yaml"], "bad"
    yield "map file of a MoorDyn file", ["import", "map", "oc4_moordyn.dat", "--out", "m.yaml"], "bad"
    yield "export a mooring file without depth", ["export", "moordyn",
                                                  "vessels/oc3_hywind/mooring.yaml"], "bad"
    yield "import --water-depth -5", ["import", "moordyn", "oc4_moordyn.dat", "--out", "m.yaml",
                                      "--water-depth", "-5"], "bad"

    # -- the README's commands, as written ---------------------------------------------------
    yield "README import moordyn", ["import", "moordyn", "oc4_moordyn.dat", "--out",
                                    str(tree.root / "readme_mooring.yaml")], "ok"
    yield "README export moordyn SCENE", ["export", "moordyn", "scenes/oc3_hywind.yaml",
                                          "--out", str(tree.root / "readme.dat")], "ok"
    yield "README check", ["check", S], "ok"
    yield "README campaign --dry-run", ["campaign", "campaigns/floatel_uls_als.yaml",
                                        "--dry-run"], "ok"

    # -- time steps; errors that used to surface inside the workers --------------------------
    st = tree.text(S)
    yield "check dt: 100 (ms)", ["check", tree.write(S, st.replace("dt: 0.1 ", "dt: 100 "))], "bad"
    yield "run --dt 100", ["run", S, "--dt", "100", "--out", str(tree.root / "dt100")], "bad"
    yield "run --duration 600 < transient", ["run", S, "--duration", "600", "--out",
                                             str(tree.root / "d600r")], "bad"
    V = "vessels/floatel_like/vessel.yaml"
    vt = tree.text(V)
    v1 = tree.write(V, re.sub(r"^mass: .*$", "mass: 1.0", vt, count=1, flags=re.M))
    v0 = tree.write(V, re.sub(r"^mass: .*$", "mass: 0", vt, count=1, flags=re.M))
    c0 = tree.write(M, mt.replace("mass_per_length: 140.41", "mass_per_length: 0.0", 1))
    taut = tree.write(M, mt.replace("length: 1200.0}", "length: 1100.0}", 1))
    calm = st.replace("water_depth: 150.0", "water_depth: 8.0").replace(
        "environment: ../metocean/heidrun_100yr.yaml\n", "")
    run_args = ["--seeds", "1-2", "--duration", "1300"]
    for name, scene in (("vessel mass 1 kg", tree.scene_with(vessel=v1)),
                        ("vessel mass 0", tree.scene_with(vessel=v0)),
                        ("chain mass 0", tree.scene_with(mooring=c0)),
                        ("line taut above MBS at zero offset", tree.scene_with(mooring=taut)),
                        ("water depth above the fairleads", tree.write(S, calm))):
        yield f"run {name}", ["run", scene, "--out", str(tree.root / f"w{tree.n}")] + run_args, "bad"


# -- result-integrity scenarios ------------------------------------------------------------------

OC3_SHORT = """name: oc3-audit
site: {{water_depth: 320.0}}
vessel: {vessel}
mooring: {mooring}
environment:
  waves: {{spectrum: jonswap, hs: 6.0, tp: 12.0}}
analysis: {{duration: 100.0, dt: 0.1, transient: 20.0, ramp: 10.0, seeds: [1, 3]}}
"""


def _nc_attr(path, name):
    import netCDF4
    with netCDF4.Dataset(path) as nc:
        return nc.getncattr(name)


def _nc_edit(path, name, fn):
    import netCDF4
    import numpy as np
    with netCDF4.Dataset(path, "a") as nc:
        v = nc[name]
        v[...] = fn(np.asarray(v[...]))


def _names_file(status, err, path) -> bool:
    return status == 2 and str(path) in err and "Traceback" not in err


def scen_contour_edited(tree, run):
    """The contour's Hs 10 m -> 14 m after an FD-only campaign: the rerun recomputes that case
    (an old sea state kept as done is stale)."""
    contour = tree.root / "metocean" / "audit_contour.yaml"
    contour.write_text("sea_states:\n  - {name: c1, hs: 10.0, tp: 12.5}\n"
                       "  - {name: c2, hs: 16.0, tp: 18.2}\n")
    camp = tree.root / "campaigns" / "audit_fd.yaml"
    camp.write_text("name: audit-fd\nbase_scene: ../scenes/floatel_100yr.yaml\n"
                    "sea_states: {contour: ../metocean/audit_contour.yaml}\n"
                    "headings: {waves_deg: [0]}\nconditions: {intact: true}\nseeds: \"1-3\"\n"
                    "screening: {time_domain: none}\n")
    out = tree.root / "sc_contour"
    argv = ["campaign", str(camp), "--scheduler", "serial", "--out", str(out)]
    st, o, e = run(argv)
    if st != 0:
        return "other", f"first campaign: exit {st}: {e[-200:]}"
    contour.write_text(contour.read_text().replace("hs: 10.0", "hs: 14.0"))
    st, o, e = run(argv)
    fd = out / "fd" / "ss1_h000p0_wi000p0_cu000p0_intact.nc"
    hs = float(_nc_attr(fd, "hs"))
    if st == 0 and hs == 14.0 and "computed from other inputs" in o:
        return "ok", "the edited sea state recomputed, and said so"
    return "stale", f"exit {st}; the stored FD case has Hs {hs:g} m"


def scen_other_campaign(tree, run):
    """A second campaign (another name and sea state) with --out at the first's folder: refused;
    with --force its case is computed (the first's FD result for another sea state reused is
    stale)."""
    base_out = tree.root / "sc_contour"
    if not base_out.is_dir():
        return "skipped", "needs the contour scenario's folder"
    camp = tree.root / "campaigns" / "audit_other.yaml"
    camp.write_text("name: audit-other\nbase_scene: ../scenes/floatel_100yr.yaml\n"
                    "sea_states: {list: [{name: x, hs: 12.0, tp: 15.0}]}\n"
                    "headings: {waves_deg: [0]}\nconditions: {intact: true}\nseeds: \"1-3\"\n"
                    "screening: {time_domain: none}\n")
    argv = ["campaign", str(camp), "--scheduler", "serial", "--out", str(base_out)]
    st, o, e = run(argv)
    if not _names_file(st, e, camp) or "--force" not in e:
        return ("silent" if st == 0 else "other"), f"exit {st}: {e[-200:]}"
    st, o, e = run(argv + ["--force"])
    hs = float(_nc_attr(base_out / "fd" / "ss1_h000p0_wi000p0_cu000p0_intact.nc", "hs"))
    if st == 0 and hs == 12.0:
        return "ok", "refused; with --force the case computed for its own sea state"
    return "stale", f"--force: exit {st}, the FD case has Hs {hs:g} m (expected 12)"


def scen_run_seed_corrupted(tree, run):
    """A finished seed with NaN tensions written into it: the rerun computes it again (not
    'already done'), and the report of a folder holding it refuses it naming the file."""
    scene = tree.root / "scenes" / "oc3_audit.yaml"
    scene.write_text(OC3_SHORT.format(vessel=REPO / "vessels/oc3_hywind/vessel.yaml",
                                      mooring=REPO / "vessels/oc3_hywind/mooring.yaml"))
    out = tree.root / "sc_run"
    argv = ["run", str(scene), "--out", str(out), "--workers", "1"]
    st, o, e = run(argv)
    if st != 0:
        return "other", f"first run: exit {st}: {e[-200:]}"
    f = out / "oc3-audit_seed0002.nc"
    nan_line = lambda a: __import__("numpy").where(  # noqa: E731
        __import__("numpy").arange(a.shape[1]) == 1, float("nan"), a)
    _nc_edit(f, "line_tension", nan_line)
    st, o, e = run(["report", str(out), "--out", str(tree.root / "sc_run_report")])
    if not _names_file(st, e, f):
        return ("stale" if st in (0, 1) else "other"), f"report: exit {st}: {e[-200:]}"
    st, o, e = run(argv)
    if st == 0 and "seed 2: " in o and "holds values no finished run writes" in o \
            and "line2 tension" in o:
        return "ok", "the report refuses it naming the file; the rerun computes it again"
    return "stale", f"rerun: exit {st}; {o[-300:]}"


def scen_campaign_results(tree, run):
    """A short campaign with storms; then, on copies of its folder: a truncated storm file, a
    NaN maximum, sign-flipped tensions, a 0-byte and a truncated campaign.json: the report
    refuses each naming the file (a seed silently dropped from the Gumbel fit is stale); the
    resume of the NaN copy recomputes that storm."""
    out = tree.root / "sc_campaign"
    argv = ["campaign", "campaigns/mini.yaml", "--scheduler", "serial", "--duration", "150",
            "--seeds", "1-3", "--out", str(out)]
    mini = (REPO / "tests" / "campaign" / "mini.yaml").read_text().replace(
        "../../scenes/", "../scenes/")
    (tree.root / "campaigns" / "mini.yaml").write_text(mini)
    st, o, e = run(argv)
    if st != 0:
        return "other", f"campaign: exit {st}: {e[-200:]}"
    case = "ss1_h000p0_wi000p0_cu000p0_intact"
    outcomes = []
    for name, damage in [
            ("truncated storm", lambda d: (d / "td" / case / "seed0002.nc").write_bytes(
                (d / "td" / case / "seed0002.nc").read_bytes()[:3000])),
            ("NaN maximum", lambda d: _nc_edit(d / "td" / case / "seed0002.nc",
                                               "line_tension_max", lambda a: a * float("nan"))),
            ("sign-flipped", lambda d: [_nc_edit(d / "td" / case / "seed0002.nc", k,
                                                 lambda a: -a) for k in
                                        ("line_tension_max", "line_tension_mean",
                                         "line_tension_min")]),
            ("0-byte campaign.json", lambda d: (d / "campaign.json").write_bytes(b"")),
            ("truncated campaign.json", lambda d: (d / "campaign.json").write_bytes(
                (d / "campaign.json").read_bytes()[:200]))]:
        copy = tree.root / f"sc_campaign_{len(outcomes)}"
        shutil.copytree(out, copy)
        damage(copy)
        bad = copy / ("campaign.json" if "json" in name else f"td/{case}/seed0002.nc")
        st, o, e = run(["report", str(copy), "--out", str(copy / "rep")])
        outcomes.append((name, _names_file(st, e, bad), st, e))
    resume_copy = tree.root / "sc_campaign_1"
    st, o, e = run(argv[:-1] + [str(resume_copy)])
    ok_resume = st == 0 and "TD: 1 result(s) unusable" in o
    failed = [f"{n} (exit {s}: {e.strip().splitlines()[-1][:120] if e.strip() else ''})"
              for n, good, s, e in outcomes if not good]
    if failed or not ok_resume:
        return "stale", "; ".join(failed) + ("" if ok_resume else f"; resume: exit {st}")
    return "ok", "each damaged result refused naming the file; the resume recomputes"


def scen_two_runs(tree, run):
    """Two ``floatmoor run`` into one folder: the second refused while the first writes; the
    first keeps every seed."""
    import subprocess
    scene = tree.root / "scenes" / "oc3_audit.yaml"
    if not scene.is_file():
        scene.write_text(OC3_SHORT.format(vessel=REPO / "vessels/oc3_hywind/vessel.yaml",
                                          mooring=REPO / "vessels/oc3_hywind/mooring.yaml"))
    out = tree.root / "sc_two"
    cmd = [sys.executable, "-m", "floatmoor", "run", str(scene), "--out", str(out), "--seeds",
           "1-30", "--workers", "2"]
    first = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             env=dict(os.environ, PYTHONPATH=str(REPO)))
    try:
        lock = out / ".floatmoor.lock"
        t0 = time.monotonic()
        while not (lock.is_file() and lock.read_text().strip()) and time.monotonic() - t0 < 120:
            time.sleep(0.1)
        st, o, e = run(cmd[3:])
        running = first.poll() is None
        first.communicate(timeout=600)
    finally:
        if first.poll() is None:
            first.kill()
    n = len(list(out.glob("*.nc")))
    if not running:
        return "skipped", "the first run ended before the second started"
    if st == 2 and f"pid {first.pid}" in e and first.returncode == 0 and n == 30:
        return "ok", "the second refused naming the first; the first kept all 30 seeds"
    return ("stale" if n < 30 else "other"), f"second: exit {st}; first: exit " \
        f"{first.returncode}, {n} of 30 seeds"


def scen_full_disk(tree, run):
    """``floatmoor run`` onto a small tmpfs: the disk reported full (exit 2), finished seeds
    kept."""
    import subprocess
    disk = tree.root / "disk"
    disk.mkdir()
    scene = tree.root / "scenes" / "oc3_audit.yaml"
    if not scene.is_file():
        scene.write_text(OC3_SHORT.format(vessel=REPO / "vessels/oc3_hywind/vessel.yaml",
                                          mooring=REPO / "vessels/oc3_hywind/mooring.yaml"))
    probe = tree.root / "sc_probe"     # the size of one seed file
    run(["run", str(scene), "--out", str(probe), "--seeds", "1", "--workers", "1"])
    seeds = sorted(probe.glob("*.nc"))
    one = seeds[0].stat().st_size if seeds else 150_000
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={int(1.5 * one) // 1024}k", "tmpfs",
                        str(disk)], capture_output=True)
    if r.returncode != 0:
        return "skipped", "no tmpfs (needs root)"
    try:
        out = disk / "out"
        st, o, e = run(["run", str(scene), "--out", str(out), "--workers", "1"])
        if st == 2 and "no space left on the device" in e and "Traceback" not in e:
            return "ok", f"reported full; {len(list(out.glob('*.nc')))} seed(s) kept"
        return ("silent" if st == 0 else "other"), f"exit {st}: {e[-200:]}"
    finally:
        subprocess.run(["umount", "-l", str(disk)])


SCENARIOS = [("campaign contour edited (Hs 10 -> 14)", scen_contour_edited),
             ("another campaign into the first's folder", scen_other_campaign),
             ("run seed corrupted in place (NaN)", scen_run_seed_corrupted),
             ("campaign results damaged (truncated, NaN, sign, campaign.json)",
              scen_campaign_results),
             ("two runs into one folder", scen_two_runs),
             ("full disk", scen_full_disk)]


# -- running ------------------------------------------------------------------------------------

def run_case(argv, cwd: Path, timeout: float, mem_mb: int, out_dir: Path, idx: int):
    """Fork a child running ``floatmoor.cli.main(argv)``; return (status, stdout, stderr, s)."""
    from floatmoor.cli import main

    out = out_dir / f"{idx:04d}.out"
    err = out_dir / f"{idx:04d}.err"
    t0 = time.monotonic()
    pid = os.fork()
    if pid == 0:  # child
        code = 1
        try:
            os.setpgid(0, 0)
            os.chdir(cwd)
            if mem_mb:
                limit = mem_mb * 2**20
                resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
            fo = os.open(out, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
            fe = os.open(err, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
            os.dup2(fo, 1)
            os.dup2(fe, 2)
            sys.stdout = os.fdopen(1, "w", buffering=1)
            sys.stderr = os.fdopen(2, "w", buffering=1)
            os.environ["FLOATMOOR_AUDIT"] = "1"
            code = main(argv)
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 1
        except MemoryError:
            sys.stderr.write("Traceback: MemoryError\n")
            code = 137
        except BaseException:
            import traceback
            traceback.print_exc()
            code = 1
        finally:
            try:
                sys.stdout.flush()
                sys.stderr.flush()
            except Exception:
                pass
            os._exit(code if isinstance(code, int) else 1)
    status = None
    while True:
        wpid, st = os.waitpid(pid, os.WNOHANG)
        if wpid:
            status = os.waitstatus_to_exitcode(st)
            break
        if time.monotonic() - t0 > timeout:
            try:
                os.killpg(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            os.waitpid(pid, 0)
            status = "timeout"
            break
        time.sleep(0.05)
    return status, out.read_text(errors="replace"), err.read_text(errors="replace"), time.monotonic() - t0


def classify(status, stdout, stderr, expect):
    text = stdout + stderr
    if status == "timeout" or status == 137 or "MemoryError" in text or (
            isinstance(status, int) and status < 0):
        return "hang"
    if "Traceback" in text or status == 1:
        return "traceback"
    if expect == "ok":
        return "ok" if status == 0 else "other"
    if status == 0:
        return "warned" if "floatmoor: warning:" in stderr else "silent"
    if status == 2:
        msg = stderr.strip().splitlines()[-1] if stderr.strip() else ""
        if "<scene>" in text or "np.float64" in text or "RuntimeWarning" in text:
            return "other"
        return "ok" if ("error" in msg) else "other"
    return "other"


KINDS = ("ok", "traceback", "hang", "silent", "warned", "stale", "other", "broken", "skipped")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--timeout", type=float, default=60.0)
    p.add_argument("--mem-mb", type=int, default=1500)
    p.add_argument("-k", default=None, help="only cases whose name contains this")
    p.add_argument("-v", action="store_true", help="print every case's last message line")
    p.add_argument("--keep", action="store_true", help="keep the temporary folder")
    p.add_argument("--no-scenarios", action="store_true",
                   help="leave out the result-integrity scenarios (they run analyses)")
    a = p.parse_args(argv)
    import warnings
    warnings.simplefilter("ignore")
    import numpy  # noqa: F401  (imported once, shared by the forked children)
    import xarray  # noqa: F401

    import floatmoor.cli  # noqa: F401
    from floatmoor.hydro import load_vessel  # noqa: F401
    from floatmoor.io.scene import load_scene  # noqa: F401
    warnings.resetwarnings()
    tmp = Path(tempfile.mkdtemp(prefix="floatmoor_audit_"))
    tree = Tree(tmp / "tree")
    logs = tmp / "logs"
    logs.mkdir()
    totals: dict[str, int] = {}
    by_audit: dict[str, dict[str, int]] = {"first": {}, "second": {}}
    t_all = time.monotonic()
    n = 0

    def count(kind, which):
        totals[kind] = totals.get(kind, 0) + 1
        by_audit[which][kind] = by_audit[which].get(kind, 0) + 1

    idx = 0
    for which, gen in (("first", cases(tree)), ("second", cases2(tree))):
        for name, argv_, expect in gen:
            idx += 1
            if a.k and a.k not in name:
                continue
            n += 1
            if argv_ is None:
                count("broken", which)
                print(f"{'broken':10s} {'-':>7s}   -    {name}: the mutation no longer applies",
                      flush=True)
                continue
            status, out, err, secs = run_case(argv_, tree.root, a.timeout, a.mem_mb, logs, idx)
            kind = classify(status, out, err, expect)
            count(kind, which)
            last = (err.strip().splitlines() or out.strip().splitlines() or [""])[-1][:160]
            if a.v or kind != "ok":
                print(f"{kind:10s} {status!s:>7s} {secs:5.1f}s  {name}: {last}", flush=True)
    if not a.no_scenarios:
        for name, fn in SCENARIOS:
            if a.k and a.k not in name:
                continue
            n += 1
            t0 = time.monotonic()

            def run(argv_, timeout=900.0):
                nonlocal idx
                idx += 1
                st, out, err, _ = run_case(argv_, tree.root, timeout, None, logs, idx)
                return st, out, err
            try:
                kind, detail = fn(tree, run)
            except Exception as exc:  # noqa: BLE001 - the audit reports, it does not stop
                kind, detail = "other", f"the scenario failed: {type(exc).__name__}: {exc}"
            count(kind, "second")
            print(f"{kind:10s} {'-':>7s} {time.monotonic() - t0:5.1f}s  scenario {name}: "
                  f"{detail[:200]}", flush=True)
    print(f"\n{n} cases in {time.monotonic() - t_all:.0f} s: " + ", ".join(
        f"{k} {totals.get(k, 0)}" for k in KINDS))
    for which in ("first", "second"):
        t = by_audit[which]
        if t:
            print(f"  {which} audit's cases ({sum(t.values())}): " + ", ".join(
                f"{k} {t.get(k, 0)}" for k in KINDS if t.get(k, 0)))
    if not a.keep:
        shutil.rmtree(tmp, ignore_errors=True)
    else:
        print(f"kept {tmp}")
    bad = sum(v for k, v in totals.items() if k not in ("ok", "skipped", "warned"))
    return 0 if bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
