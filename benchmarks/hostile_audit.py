"""Hostile-input audit of the ``floatmoor`` command.

Runs a few hundred bad inputs -- mutated copies of the example scene, vessel, mooring and
metocean files, and bad command lines -- each in a forked child with a time limit and a memory
limit, and counts the outcomes:

* ``rejected``  exit 2 with a ``floatmoor: error:`` message naming a file or an option;
* ``traceback`` a Python traceback (or exit 1);
* ``hang``      killed at the time limit, or out of memory;
* ``silent``    exit 0 (a bad input accepted);
* ``warned``    exit 0 with a ``floatmoor: warning:`` (a doubtful input accepted, but said so);
* ``other``     anything else (exit 3 for an input error, a message without a file, ...).

Usage::

    PYTHONPATH=. python benchmarks/hostile_audit.py [--timeout 60] [--mem-mb 1500] [-k WORD] [-v]

The forked children share the parent's imports (numpy, xarray, floatmoor), so a case costs
the command's own work only.  Exit status 0 when every case was ``rejected``.
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
        for d in ("scenes", "metocean", "vessels/floatel_like", "vessels/oc3_hywind"):
            src = REPO / d
            dst = root / d
            shutil.copytree(src, dst, ignore=shutil.ignore_patterns("source", "*.py", "results"))
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
        ("damping 5 rows", "  - [0, 0, 0, 0, 0, 0]\n", "\n"),
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
        assert old in vt, name
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
        return "rejected" if status == 0 else "other"
    if status == 0:
        return "warned" if "floatmoor: warning:" in stderr else "silent"
    if status == 2:
        msg = stderr.strip().splitlines()[-1] if stderr.strip() else ""
        if "<scene>" in text or "np.float64" in text or "RuntimeWarning" in text:
            return "other"
        return "rejected" if ("error" in msg) else "other"
    return "other"


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--timeout", type=float, default=60.0)
    p.add_argument("--mem-mb", type=int, default=1500)
    p.add_argument("-k", default=None, help="only cases whose name contains this")
    p.add_argument("-v", action="store_true", help="print every case's last message line")
    p.add_argument("--keep", action="store_true", help="keep the temporary folder")
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
    t_all = time.monotonic()
    n = 0
    for i, (name, argv_, expect) in enumerate(cases(tree)):
        if a.k and a.k not in name:
            continue
        n += 1
        status, out, err, secs = run_case(argv_, tree.root, a.timeout, a.mem_mb, logs, i)
        kind = classify(status, out, err, expect)
        totals[kind] = totals.get(kind, 0) + 1
        last = (err.strip().splitlines() or out.strip().splitlines() or [""])[-1][:160]
        if a.v or kind != "rejected":
            print(f"{kind:10s} {status!s:>7s} {secs:5.1f}s  {name}: {last}", flush=True)
    print(f"\n{n} cases in {time.monotonic() - t_all:.0f} s: " + ", ".join(
        f"{k} {totals.get(k, 0)}" for k in ("rejected", "traceback", "hang", "silent", "warned", "other")))
    if not a.keep:
        shutil.rmtree(tmp, ignore_errors=True)
    else:
        print(f"kept {tmp}")
    return 0 if totals.get("rejected", 0) == n else 1


if __name__ == "__main__":
    sys.exit(main())
