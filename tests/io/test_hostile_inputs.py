"""Hostile and careless input beyond the scene files (the second audit,
``benchmarks/hostile_audit.py``): fatigue scatter files, fibre-rope parameters, MoorDyn/MAP++
files, import/export depths, time steps that cannot resolve the sea state, inputs that used to
fail inside the workers, result files read back by a resume, a folder in use and a full disk.
Each case asserts the exit status and that the message names the file (or option) and the key,
without a traceback."""

from __future__ import annotations

import os
import re
import shutil
import time
from pathlib import Path

import numpy as np
import pytest
import yaml

from floatmoor.cli import main

pytestmark = pytest.mark.filterwarnings("ignore::floatmoor.core.errors.FloatmoorWarning")

ROOT = Path(__file__).resolve().parents[2]
SCATTER = ROOT / "metocean" / "floatel_like_scatter.yaml"
FLOATEL = ROOT / "scenes" / "floatel_100yr.yaml"
OC3 = ROOT / "vessels" / "oc3_hywind"


def _cli(argv, capsys):
    code = main([str(a) for a in argv])
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err + cap.out
    return code, cap.err, cap.out


# -- scatter files (floatmoor fatigue) ----------------------------------------------------------
def _scatter(tmp_path, edit, name="scatter.yaml"):
    d = yaml.safe_load(SCATTER.read_text())
    edit(d)
    p = tmp_path / name
    p.write_text(yaml.safe_dump(d))
    return p


def _move(d, i, j, ii, jj):
    """Move the probability of cell (ii, jj) onto cell (i, j) (the sum stays 1)."""
    p = [list(r) for r in d["probability"]]
    p[i][j] += p[ii][jj]
    p[ii][jj] = 0.0
    d["probability"] = p


SCATTER_CASES = {
    "gamma 0.5": (lambda d: d.update(gamma=0.5), "gamma", ">= 1"),
    "Hs 3 m at Tp 0.5 s": (lambda d: (d.update(tp=[0.5] + d["tp"][1:]), _move(d, 1, 0, 1, 3)),
                           "probability[1][0] (hs 3 m, tp 0.5 s)", "does not break"),
    "Hs 9 m at Tp 5 s": (lambda d: _move(d, 4, 1, 4, 6), "probability[4][1] (hs 9 m, tp 5 s)",
                         "does not break"),
    "headings in radians": (lambda d: d["directions"].update(
        heading_deg=[0, 0.7854, 1.5708, 2.3562, 3.1416, 3.927, 4.7124, 5.4978]),
        "directions.heading_deg", "radians"),
    "the same direction twice": (lambda d: d["directions"].update(
        heading_deg=[0, 45, 90, 135, 180, 225, 270, 360]), "directions.heading_deg",
        "same direction"),
    "Tp bins not increasing": (lambda d: d.update(tp=d["tp"][::-1]), "tp", "increasing"),
    "a million sea states": (lambda d: d.update(
        hs=[round(0.1 * i, 2) for i in range(1, 101)],
        tp=[round(10 + 0.3 * i, 2) for i in range(1, 101)],
        probability=[[1e-4] * 100 for _ in range(100)], u10=[5.0] * 100,
        directions={"heading_deg": list(range(0, 360, 4)), "probability": [1 / 90] * 90}),
        "probability", "at most 20,000 sea states"),
}


@pytest.mark.parametrize("case", sorted(SCATTER_CASES))
def test_scatter_mistakes_are_refused(case, tmp_path, capsys):
    edit, key, words = SCATTER_CASES[case]
    p = _scatter(tmp_path, edit)
    t0 = time.monotonic()
    code, err, _ = _cli(["fatigue", FLOATEL, "--scatter", p, "--td-cells", "0"], capsys)
    assert code == 2 and f"{p}: {key}" in err and words in err, err
    assert time.monotonic() - t0 < 30.0


def test_control_character_in_a_scatter_comment(tmp_path, capsys):
    p = tmp_path / "ctl.yaml"
    p.write_text(SCATTER.read_text().replace("# Wind:", "# Wind\x07:", 1))
    code, err, _ = _cli(["fatigue", FLOATEL, "--scatter", p, "--td-cells", "0"], capsys)
    assert code == 2 and f"{p}: line " in err and "control character #x07" in err, err


@pytest.mark.parametrize("rates,words", [(["-0.3", "0.4"], ">= 0 mm/year"),
                                         (["10", "10"], "leaves some of the 84 mm diameter")])
def test_corrosion_allowance_refused(rates, words, capsys):
    code, err, _ = _cli(["fatigue", FLOATEL, "--scatter", SCATTER, "--td-cells", "0",
                         "--corrosion", *rates], capsys)
    assert code == 2 and f"{FLOATEL}: corrosion (--corrosion" in err and words in err, err


# -- fibre ropes in the wrong unit -------------------------------------------------------------
FIBRE = ("    fibre: {working_curve: {strain: [0.0, 0.01, 0.02, 0.04], "
         "tension_mbs: [0.0, 0.12, 0.28, 0.60]}, dynamic: {alpha: 11.6, beta: 0.40}}\n")
FIBRE_CASES = {
    "strain in percent": ("strain: [0.0, 0.01, 0.02, 0.04]", "strain: [0.0, 1.0, 2.0, 4.0]",
                          "working_curve.strain", "percent"),
    "tension in kN": ("tension_mbs: [0.0, 0.12, 0.28, 0.60]",
                      "tension_mbs: [0.0, 1020.0, 2380.0, 5100.0]", "working_curve.tension_mbs",
                      "kN"),
    "a curve as stiff as steel": ("strain: [0.0, 0.01, 0.02, 0.04]",
                                  "strain: [0.0, 0.0005, 0.001, 0.002]", "working_curve.strain",
                                  "secant stiffness"),
    "beta 40 (per unit of mean load)": ("beta: 0.40", "beta: 40.0", "dynamic.beta",
                                        "beta 0.4 per %"),
    "alpha 1e9 (an EA in N)": ("alpha: 11.6", "alpha: 1.0e+9", "dynamic.alpha", "an EA in N"),
    "a strain step of 100 %": ("strain: [0.0, 0.01, 0.02, 0.04]",
                               "strain: [0.0, 1.0, 2.0, 3.0]", "working_curve.strain",
                               "fraction"),
}


def _fibre_scene(tmp_path, entry_edit=lambda t: t, on_chain=False):
    text = (ROOT / "vessels" / "floatel_like" / "mooring.yaml").read_text()
    anchor = "    source: Wang (2016) table 5.2 (E, MBS, Cd); mass from catalogue fit\n"
    parts = text.split(anchor)
    assert len(parts) == 3, "two line types with a source line"
    k = 0 if on_chain else 1
    parts[k] += anchor + entry_edit(FIBRE)
    parts[1 - k] += anchor
    m = tmp_path / "fibre_mooring.yaml"
    m.write_text(parts[0] + parts[1] + parts[2])
    scene = FLOATEL.read_text()
    scene = scene.replace("../vessels/floatel_like/mooring.yaml", m.as_posix())
    scene = scene.replace("../vessels/", (ROOT / "vessels").as_posix() + "/")
    scene = scene.replace("../metocean/", (ROOT / "metocean").as_posix() + "/")
    p = tmp_path / "fibre_scene.yaml"
    p.write_text(scene)
    return p, m


def test_a_plausible_fibre_rope_passes(tmp_path, capsys):
    p, _ = _fibre_scene(tmp_path)
    code, err, _ = _cli(["check", p], capsys)
    assert code == 0, err


@pytest.mark.parametrize("case", sorted(FIBRE_CASES))
def test_fibre_parameters_in_the_wrong_unit_are_refused(case, tmp_path, capsys):
    old, new, key, words = FIBRE_CASES[case]
    p, m = _fibre_scene(tmp_path, lambda t: t.replace(old, new))
    code, err, _ = _cli(["check", p], capsys)
    assert code == 2 and str(m) in err and f"fibre.{key}" in err and words in err, err


def test_a_polyester_curve_on_a_chain_type_is_refused(tmp_path, capsys):
    p, m = _fibre_scene(tmp_path, on_chain=True)
    code, err, _ = _cli(["check", p], capsys)
    assert code == 2 and f"{m}: line_types.floatel_chain_84.fibre" in err
    assert "chain line type" in err, err


# -- MoorDyn, MAP++: sizes and depths ----------------------------------------------------------
def test_a_huge_moordyn_file_is_refused_before_reading(tmp_path, capsys):
    import resource
    p = tmp_path / "huge.dat"
    with open(p, "wb") as f:       # 200 MB, sparse: the size alone must refuse it
        f.truncate(200 * 2**20)
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    code, err, _ = _cli(["import", "moordyn", p, "--out", tmp_path / "m.yaml"], capsys)
    assert code == 2 and f"{p}: expected an input file of at most 16 MiB" in err, err
    assert "200.0 MiB" in err
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before < 100_000  # kB


def test_moordyn_segments_bounded(tmp_path, capsys):
    src = (ROOT / "tests" / "io" / "data" / "oc4_moordyn_v1.dat").read_text()
    lines = src.splitlines()
    i = next(k for k, ln in enumerate(lines) if ln.split()[:1] == ["Line"]) + 2
    tok = lines[i].split()
    tok[3] = "1000000000"
    lines[i] = "  ".join(tok)
    p = tmp_path / "segs.dat"
    p.write_text("\n".join(lines) + "\n")
    code, err, _ = _cli(["import", "moordyn", p, "--out", tmp_path / "m.yaml"], capsys)
    assert code == 2 and f"{p}: line {i + 1}" in err and "from 1 to 10,000" in err, err


def test_export_of_a_mooring_file_takes_the_depth_from_its_anchors(tmp_path, capsys):
    m = ROOT / "vessels" / "oc3_hywind" / "mooring.yaml"
    code, err, _ = _cli(["export", "moordyn", m, "--out", tmp_path / "a.dat"], capsys)
    assert code == 2 and f"{m}: expected a scene, or a mooring file with --water-depth" in err
    assert "--water-depth M" in err
    code, err, out = _cli(["export", "moordyn", ROOT / "scenes" / "oc3_hywind.yaml", "--out",
                           tmp_path / "b.dat"], capsys)
    assert code == 0, err
    # every anchor with its z: the depth is the deepest anchor's
    from floatmoor.commands.export import load_system
    sys_ = load_system(ROOT / "scenes" / "oc3_hywind.yaml")
    text = "lines:\n" + "".join(
        f"  - name: {ln.name}\n    anchor: {{x: {ln.anchor[0]:.6f}, y: {ln.anchor[1]:.6f}, "
        f"z: {ln.anchor[2]:.6f}}}\n    fairlead: [{ln.fairlead[0]}, {ln.fairlead[1]}, "
        f"{ln.fairlead[2]}]\n" for ln in sys_.lines)
    body = m.read_text()
    lines_at = body.index("lines:")
    defaults = body[:lines_at]
    z = tmp_path / "zmooring.yaml"
    z.write_text(defaults + text)
    code, err, out = _cli(["export", "moordyn", z, "--out", tmp_path / "c.dat"], capsys)
    assert code == 0, err
    assert "water depth 320 m: the depth of the deepest anchor" in out


# -- time steps, and errors that used to surface inside the workers -----------------------------
def _tree(tmp_path):
    for d in ("scenes", "metocean", "vessels/floatel_like"):
        shutil.copytree(ROOT / d, tmp_path / d, ignore=shutil.ignore_patterns("source", "*.py"))
    return tmp_path


def _mutate(root, rel, old, new, name):
    text = (root / rel).read_text()
    assert old in text, old
    p = (root / rel).parent / name
    p.write_text(text.replace(old, new, 1))
    return p


def test_dt_in_milliseconds_refused_at_check(tmp_path, capsys):
    root = _tree(tmp_path)
    p = _mutate(root, "scenes/floatel_100yr.yaml", "dt: 0.1 ", "dt: 100 ", "ms.yaml")
    code, err, _ = _cli(["check", "--quick", p], capsys)
    assert code == 2 and f"{p}: analysis.dt" in err and "resolves the sea state" in err, err


WORKER_CASES = {
    "vessel of 1 kg": ("vessels/floatel_like/vessel.yaml", r"^mass: .*$", "mass: 1.0", "vessel",
                       "mass"),
    "chain of no mass": ("vessels/floatel_like/mooring.yaml", "mass_per_length: 140.41",
                         "mass_per_length: 0.0", "mooring",
                         "line_types.floatel_chain_84.mass_per_length"),
    "a line taut above its MBS at zero offset": ("vessels/floatel_like/mooring.yaml",
                                                 "length: 1200.0}", "length: 1100.0}", "mooring",
                                                 "lines[0].segments"),
}


@pytest.mark.parametrize("case", sorted(WORKER_CASES))
def test_input_errors_are_scene_errors_before_any_seed(case, tmp_path, capsys):
    rel, old, new, ref, key = WORKER_CASES[case]
    root = _tree(tmp_path)
    text = (root / rel).read_text()
    bad = root / rel.replace(".yaml", "_bad.yaml")
    bad.write_text(re.sub(old, new, text, count=1, flags=re.M) if old.startswith("^")
                   else text.replace(old, new, 1))
    scene = _mutate(root, "scenes/floatel_100yr.yaml", f"{ref}.yaml", f"{ref}_bad.yaml",
                    "bad_scene.yaml")
    out = tmp_path / "out"
    code, err, _ = _cli(["run", scene, "--seeds", "1-2", "--duration", "1300", "--out", out],
                        capsys)
    assert code == 2 and f"{bad}: {key}" in err, err
    assert not list(out.glob("*.nc")) and not list(out.glob("*.error.txt"))


def test_water_depth_above_the_fairleads(tmp_path, capsys):
    """A water depth of 8 m (the fairleads are 8.7 m down) in a calm scene: refused before any
    seed."""
    root = _tree(tmp_path)
    text = (root / "scenes/floatel_100yr.yaml").read_text()
    text = text.replace("water_depth: 150.0", "water_depth: 8.0")
    text = text.replace("environment: ../metocean/heidrun_100yr.yaml\n", "")
    p = root / "scenes" / "shallow.yaml"
    p.write_text(text)
    code, err, _ = _cli(["run", p, "--seeds", "1", "--duration", "1300", "--out",
                         tmp_path / "out"], capsys)
    m = root / "vessels" / "floatel_like" / "mooring.yaml"
    assert code == 2 and f"{m}: lines[0].anchor: expected an anchor below its fairlead" in err
    assert "site.water_depth" in err and "water depth 8 m" in err, err
    assert not (tmp_path / "out").exists()


# -- floatmoor run: results read back, a folder in use, a full disk -----------------------------
def _oc3(tmp_path, name="oc3.yaml"):
    p = tmp_path / name
    p.write_text(f"name: oc3-short\nsite: {{water_depth: 320.0}}\n"
                 f"vessel: {OC3 / 'vessel.yaml'}\nmooring: {OC3 / 'mooring.yaml'}\n"
                 "environment:\n  waves: {spectrum: jonswap, hs: 6.0, tp: 12.0}\n"
                 "analysis: {duration: 100.0, dt: 0.1, transient: 20.0, ramp: 10.0, "
                 "seeds: [1, 2]}\n")
    return p


def _edit_nc(path, name, fn):
    import netCDF4
    with netCDF4.Dataset(path, "a") as nc:
        v = nc[name]
        a = np.asarray(v[...])
        v[...] = fn(a)


@pytest.mark.parametrize("name,fn,words", [
    ("line_tension", lambda a: np.where(np.arange(a.shape[1]) == 1, np.nan, a), "finite values"),
    ("line_tension", lambda a: -a, "tensions >= 0"),
    ("motion", lambda a: np.where(np.arange(a.shape[0])[:, None] == 5, np.inf, a),
     "finite values"),
])
def test_a_corrupted_seed_is_computed_again_not_taken_as_done(tmp_path, capsys, name, fn,
                                                               words):
    """A finished seed later corrupted in place (NaN or infinite values, sign-flipped tensions;
    the file still readable): the rerun computes it again and says why, the table lists every
    line, and the numbers are those of the first run."""
    import xarray as xr
    scene = _oc3(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--workers", "1"]) == 0
    capsys.readouterr()
    f = sorted(out.glob("*_seed0001.nc"))[0]
    with xr.open_dataset(f) as ds:
        before = ds["line_tension"].values.copy()
    _edit_nc(f, name, fn)
    code, err, text = _cli(["run", scene, "--out", out, "--workers", "1"], capsys)
    assert code == 0, err
    assert f"seed 1: {f.name} holds values no finished run writes ({name}: expected {words}" \
        in text, text
    assert "seed 2: already done" in text
    assert all(f"line{i} tension" in text for i in (1, 2, 3))
    with xr.open_dataset(f) as ds:
        np.testing.assert_array_equal(ds["line_tension"].values, before)


def test_a_second_run_into_a_folder_in_use_is_refused(tmp_path, capsys):
    import fcntl

    from floatmoor.analyses.folder_lock import LOCK_NAME
    out = tmp_path / "busy"
    out.mkdir()
    fd = os.open(out / LOCK_NAME, os.O_RDWR | os.O_CREAT)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        os.write(fd, b"pid 4242 (floatmoor run oc3.yaml, since 2026-01-01 00:00:00)\n")
        code, err, _ = _cli(["run", _oc3(tmp_path), "--out", out], capsys)
    finally:
        os.close(fd)
    assert code == 2 and f"{out}: expected an output folder that no other floatmoor" in err
    assert "pid 4242 (floatmoor run oc3.yaml" in err and "another --out" in err, err
    assert not list(out.glob("*.nc"))


def test_a_full_disk_is_reported_as_such(tmp_path, capsys, monkeypatch):
    """ENOSPC simulated (the real thing, a small tmpfs, is tests/test_faults.py): the disk is
    full when seed 2 is written; the run stops saying so (exit 2, the folder and the free
    space named), seed 1 is kept, seed 2 listed to compute again; no *.tmp left."""
    from floatmoor.analyses import folder_lock

    real = folder_lock.check_free_space

    def full_for_seed_2(folder, need, what):
        if "seed0002" in what:
            raise folder_lock.DiskFull(folder, f"no space left on the device for {what} "
                                       f"({need / 1e6:.3g} MB needed, 0 MB free)")
        return real(folder, need, what)

    monkeypatch.setattr(folder_lock, "check_free_space", full_for_seed_2)
    # the seeds run in worker processes, which see the patch only if forked (Linux's default);
    # after a threaded FE run in this test process (tests/solvers/test_fe_threads.py before it
    # in the same pytest worker) the runner spawns them instead: keep fork here (the seeds of
    # this quasi-static scene do not use numba's thread pool)
    from floatmoor.analyses import runner
    monkeypatch.setattr(runner, "_worker_context", lambda: None)
    out = tmp_path / "out"
    code, err, text = _cli(["run", _oc3(tmp_path), "--out", out, "--workers", "1"], capsys)
    assert code == 2 and f"floatmoor: error: {out}: no space left on the device" in err, err
    assert "1 seed(s) finished and kept, 1 not computed" in err
    assert len(list(out.glob("*_seed0001.nc"))) == 1 and not list(out.glob("*seed0002*"))
    assert (out / "interrupted.txt").read_text().split(":")[1].split() == ["2"]
    assert not list(out.glob("*.tmp"))
