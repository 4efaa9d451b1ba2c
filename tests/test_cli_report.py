"""``floatmoor report``: from real ``floatmoor.simulate`` seeds of the OC3-Hywind scene to the
HTML/Markdown/CSV/netCDF report, exit status 0/1/2, ALS and FD beside TD.

The expected numbers are recomputed here from the netCDF files independently of floatmoor.post:
per-seed maxima over t >= the ``transient`` attribute, Gumbel fit by scipy.stats.gumbel_r.fit
(maximum likelihood), MPM = loc, 90 % value = gumbel_r.ppf(0.9), and the DNV-OS-E301 (2008)
design equation with the factors of Wang (2016) table 3.1 and S_C = 0.95 MBS.  The OC3 lines
are quasi-static, so the default factors are the quasi-static ones (class 2: 2.5 on T_C); the
line type (material user) takes no corrosion allowance, so S_C is the new line's.
"""

import base64
import shutil
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from scipy import stats

from floatmoor.cli import main

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "oc3_hywind.yaml"
RUN = dict(duration=500.0, transient=100.0, ramp=50.0, dt=0.2)   # 400 s of statistics
INTACT_SEEDS = (1, 2, 3, 4, 5)
ALS_SEEDS = (1, 2, 3)


def _write_seeds(scene_path, seeds, out):
    import warnings

    import floatmoor
    from floatmoor.analyses.runner import seed_file
    from floatmoor.io.scene import load_scene

    out.mkdir(parents=True, exist_ok=True)
    scene = load_scene(scene_path)
    for s in seeds:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = floatmoor.simulate(scene, seed=s, **RUN)
        ds.to_netcdf(seed_file(out, scene.name, s))
    return out


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    """Intact seeds, ALS seeds (line1 broken at 150 s by forces.line_failure), an FD file."""
    base = tmp_path_factory.mktemp("report_cli")
    intact = _write_seeds(SCENE, INTACT_SEEDS, base / "intact")
    text = SCENE.read_text().replace("../vessels", str(ROOT / "vessels"))
    text = text.replace("name: oc3-hywind-hs6-tp10", "name: oc3-hywind-line1-failed")
    als_scene = base / "oc3_als.yaml"
    als_scene.write_text(text + "forces: {line_failure: {line1: 150.0}}\n")
    als = _write_seeds(als_scene, ALS_SEEDS, base / "als")
    import warnings

    from floatmoor.analyses.frequency_domain import frequency_domain
    from floatmoor.commands.fd import to_netcdf
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fd = to_netcdf(frequency_domain(SCENE), base / "fd.nc")
    return {"base": base, "intact": intact, "als": als, "fd": fd, "als_scene": als_scene}


class _Parser(HTMLParser):
    def __init__(self):
        super().__init__()
        self.tables, self.imgs, self.links, self._t, self._row = {}, [], [], None, None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "table":
            self._t = a.get("id")
            self.tables[self._t] = []
        elif tag == "tr" and self._t is not None:
            self._row = {"class": a.get("class"), "cells": [], "classes": []}
            self.tables[self._t].append(self._row)
        elif tag in ("td", "th") and self._row is not None:
            self._row["cells"].append("")
            self._row["classes"].append(a.get("class"))
        elif tag == "img":
            self.imgs.append(a)
        for k in ("src", "href"):
            if k in a and tag != "img":
                self.links.append(a[k])

    def handle_endtag(self, tag):
        if tag == "table":
            self._t = None
        elif tag == "tr":
            self._row = None

    def handle_data(self, data):
        if self._row is not None and self._row["cells"]:
            self._row["cells"][-1] += data


def parse(path):
    p = _Parser()
    p.feed(Path(path).read_text(encoding="utf-8"))
    return p


def line_rows(table):
    return {r["cells"][0]: r for r in table if r["cells"] and r["cells"][0] not in ("line", "DOF")}


def expected_from_files(folder):
    """Per line: mean, Gumbel MPM and 90 % (N) from the netCDF files, via scipy."""
    maxima, means, mbs = {}, {}, None
    for f in sorted(Path(folder).glob("*.nc")):
        with xr.open_dataset(f) as ds:
            t = ds["time"].values
            sel = t >= ds.attrs["transient"] - 1e-9
            for j, line in enumerate(ds["line"].values):
                T = ds["line_tension"].values[sel, j]
                maxima.setdefault(str(line), []).append(T.max())
                means.setdefault(str(line), []).append(T.mean())
            mbs = ds["mbs"].values.copy()
    out = {}
    for j, line in enumerate(maxima):
        loc, scale = stats.gumbel_r.fit(np.array(maxima[line]))
        out[line] = {"mean": np.mean(means[line]), "mpm": loc,
                     "p90": stats.gumbel_r.ppf(0.9, loc, scale), "mbs": mbs[j]}
    return out


def run_report(argv, capsys):
    code = main(["report"] + [str(a) for a in argv])
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err
    return code, cap.out, cap.err


@pytest.fixture(scope="module")
def intact_report(data, tmp_path_factory):
    out = tmp_path_factory.mktemp("intact_report")
    code = main(["report", str(data["intact"]), "--standard", "dnv-os-e301",
                 "--consequence-class", "2", "--out", str(out)])
    return code, out


def test_intact_report_tables_images_numbers(data, intact_report):
    code, out = intact_report
    assert code == 0
    for name in ("report.html", "report.md", "summary.csv", "summary.nc"):
        assert (out / name).stat().st_size > 500
    p = parse(out / "report.html")
    assert set(p.tables) == {"verdict", "governing", "environment", "analysis", "meta",
                             "lines_uls", "capacity", "anchors_uls", "offsets", "code_values"}
    # four plots, embedded PNGs, no link to the network (nor anything external)
    assert len(p.imgs) == 4
    for img in p.imgs:
        assert img["src"].startswith("data:image/png;base64,")
        assert base64.b64decode(img["src"].split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    assert all(u.startswith("data:") for u in p.links)
    html_text = (out / "report.html").read_text()
    assert "http://" not in html_text and "https://" not in html_text
    meta = {r["cells"][0]: r["cells"][1] for r in p.tables["meta"]}
    assert meta["scene"] == "oc3-hywind-hs6-tp10"
    assert meta["seeds"].startswith(f"{len(INTACT_SEEDS)}:")
    assert "October 2008" in meta["edition"] and "Ch.2 Sec.2" in meta["standard"]
    assert meta["statistics window"].startswith("100 - 500")
    assert meta["software"].startswith("floatmoor ")
    # numbers equal to the recomputation from the files (HTML rounds to 0.1 kN / 0.001)
    exp = expected_from_files(data["intact"])
    rows = line_rows(p.tables["lines_uls"])
    assert set(rows) == set(exp)
    util = {}
    for line, e in exp.items():
        cells = rows[line]["cells"]
        assert float(cells[1]) == pytest.approx(e["mean"] / 1e3, abs=0.051)
        assert float(cells[4]) == pytest.approx(e["mpm"] / 1e3, abs=0.051 + 1e-5 * e["mpm"] / 1e3)
        assert float(cells[5]) == pytest.approx(e["p90"] / 1e3, abs=0.051 + 1e-5 * e["p90"] / 1e3)
        design = 2.5 * e["p90"]         # table 3.1, class 2, quasi-static (quasi-static lines)
        util[line] = design / (0.95 * e["mbs"])
        assert float(cells[13]) == pytest.approx(util[line], abs=6e-4)
        assert cells[14] == "PASS"
    gov = [r["cells"][0] for r in rows.values() if r["class"] == "governing"]
    assert gov == [max(util, key=util.get)]
    offsets = line_rows(p.tables["offsets"])
    assert {"horizontal offset", "surge", "sway", "heave", "roll", "pitch", "yaw"} <= set(offsets)
    md = (out / "report.md").read_text()
    assert "| line |" in md and "(gumbel_governing.png)" in md


def test_stdout_summary_and_csv(data, tmp_path, capsys):
    code, stdout, _ = run_report([data["intact"], "--out", tmp_path / "r"], capsys)
    assert code == 0
    exp = expected_from_files(data["intact"])
    csv = (tmp_path / "r" / "summary.csv").read_text().strip().splitlines()
    head = csv[0].split(",")
    gov = [r.split(",")[1] for r in csv[1:] if r.split(",")[head.index("governing[1]")] == "1"]
    assert gov and f"ULS line tension   PASS        {gov[0]}:" in stdout
    assert "analysis: quasi-static -- 3 quasi-static line(s)" in stdout
    for check in ("ALS line tension   NOT CHECKED", "FLS fatigue        NOT CHECKED",
                  "ULS anchor uplift  PASS", "ULS anchor load    NOT CHECKED",
                  "ULS offsets        NOT CHECKED"):
        assert check in stdout
    assert "verdict: PASS for the checks made; not checked: ALS line tension, FLS fatigue" \
        in stdout
    assert str(tmp_path / "r" / "report.html") in stdout
    for r in csv[1:]:
        v = r.split(",")
        assert float(v[head.index("gumbel_p90[N]")]) == pytest.approx(exp[v[1]]["p90"], rel=1e-5)


def test_default_out_is_results_dir_report(data, tmp_path, capsys):
    d = tmp_path / "res"
    shutil.copytree(data["intact"], d)
    code, stdout, _ = run_report([d], capsys)
    assert code == 0 and (d / "report" / "report.html").exists()


def test_exit_1_when_a_line_fails(data, tmp_path, capsys):
    """MBS lowered in the files below the design tension: exit 1, FAIL in the table."""
    d = tmp_path / "weak"
    d.mkdir()
    for f in data["intact"].glob("*.nc"):
        with xr.open_dataset(f) as ds:
            ds = ds.load()
        ds["mbs"] = ds["mbs"] * 0.2                 # 1200 kN: S_C 1140 kN < design ~1300 kN
        ds.to_netcdf(d / f.name)
    code, stdout, _ = run_report([d, "--out", tmp_path / "r"], capsys)
    assert code == 1
    assert "FAIL" in stdout and "exit status 1" in stdout
    p = parse(tmp_path / "r" / "report.html")
    assert any(r["cells"][14] == "FAIL" for r in line_rows(p.tables["lines_uls"]).values())


def test_failed_seed_is_listed_and_left_out(data, tmp_path, capsys):
    d = tmp_path / "res"
    shutil.copytree(data["intact"], d)
    (d / "oc3-hywind-hs6-tp10_seed0009.error.txt").write_text(
        "NumericalError: NaN in surge at t = 12.3 s\n\nTraceback ...\n")
    code, stdout, _ = run_report([d, "--out", tmp_path / "r"], capsys)
    assert code == 0
    assert "1 failed seed(s) left out: seed 9" in stdout
    meta = {r["cells"][0]: r["cells"][1] for r in parse(tmp_path / "r" / "report.html").tables["meta"]}
    assert meta["failed seeds (left out)"].startswith("seed 9: NumericalError")
    assert meta["seeds"].startswith(f"{len(INTACT_SEEDS)}:")


def test_other_netcdf_files_are_skipped_with_a_warning(data, tmp_path, capsys):
    d = tmp_path / "res"
    shutil.copytree(data["intact"], d)
    shutil.copy(data["fd"], d / "fd.nc")
    code, stdout, stderr = run_report([d, "--out", tmp_path / "r"], capsys)
    assert code == 0
    assert "ignored 1 netCDF file(s)" in stderr and "fd.nc" in stderr
    assert f"({len(INTACT_SEEDS)} seeds from" in stdout


def test_mbs_from_the_scene_when_the_results_lack_it(data, intact_report, tmp_path, capsys):
    d = tmp_path / "nombs"
    d.mkdir()
    for f in data["intact"].glob("*.nc"):
        with xr.open_dataset(f) as ds:
            ds.drop_vars("mbs").load().to_netcdf(d / f.name)
    code, _, _ = run_report([d, "--out", tmp_path / "r"], capsys)
    assert code == 0
    a = np.loadtxt(intact_report[1] / "summary.csv", delimiter=",", skiprows=1, usecols=range(2, 17))
    b = np.loadtxt(tmp_path / "r" / "summary.csv", delimiter=",", skiprows=1, usecols=range(2, 17))
    np.testing.assert_allclose(a, b, rtol=1e-12)
    meta = {r["cells"][0]: r["cells"][1] for r in parse(tmp_path / "r" / "report.html").tables["meta"]}
    assert meta["MBS from"].startswith("scene mooring")


def test_als_from_a_second_results_dir(data, tmp_path, capsys):
    code, stdout, _ = run_report([data["intact"], "--als-dir", data["als"], "--out",
                                  tmp_path / "r"], capsys)
    assert code in (0, 1)
    assert "ALS line tension" in stdout and "failed: line1" in stdout
    assert "ALS anchor uplift" in stdout
    p = parse(tmp_path / "r" / "report.html")
    assert {"lines_uls", "lines_als", "anchors_als"} <= set(p.tables)
    rows = line_rows(p.tables["lines_als"])
    assert rows["line1"]["cells"][14] == "failed line"
    assert [r["cells"][0] for r in rows.values() if r["class"] == "governing"] != ["line1"]
    meta = {r["cells"][0]: r["cells"][1] for r in p.tables["meta"]}
    assert meta["ALS failed line(s)"] == "line1"
    # ALS T_C of line2 = Gumbel 90 % of its ALS seed maxima (scipy), window after transient
    exp = expected_from_files(data["als"])
    assert float(rows["line2"]["cells"][8]) == pytest.approx(exp["line2"]["p90"] / 1e3,
                                                             abs=0.051 + 1e-5 * exp["line2"]["p90"] / 1e3)
    assert float(rows["line2"]["cells"][4]) == pytest.approx(exp["line2"]["mpm"] / 1e3,
                                                             abs=0.051 + 1e-5 * exp["line2"]["mpm"] / 1e3)
    assert float(rows["line2"]["cells"][1]) == pytest.approx(exp["line2"]["mean"] / 1e3, abs=0.051)
    assert rows["line1"]["cells"][1] == ""                  # the failed line has no statistics
    # the same with the failed line named
    code2, _, _ = run_report([data["intact"], "--als-dir", data["als"], "--failed-line", "line1",
                              "--out", tmp_path / "r2"], capsys)
    assert code2 == code


def test_fd_beside_td(data, tmp_path, capsys):
    code, _, _ = run_report([data["intact"], "--fd", data["fd"], "--out", tmp_path / "r"], capsys)
    assert code == 0
    p = parse(tmp_path / "r" / "report.html")
    assert {"fd_lines", "fd_offsets"} <= set(p.tables)
    with xr.open_dataset(data["fd"]) as fd:
        fd = fd.load()
    rows = line_rows(p.tables["fd_lines"])
    exp = expected_from_files(data["intact"])
    for j, line in enumerate(fd["line"].values):
        cells = rows[str(line)]["cells"]
        assert float(cells[2]) == pytest.approx(fd["tension_static"].values[j] / 1e3, abs=0.051)
        assert float(cells[3]) == pytest.approx(exp[str(line)]["mpm"] / 1e3, abs=0.06)
        assert float(cells[5]) == pytest.approx(fd["tension_max_total"].values[j] / 1e3, abs=0.051)
        assert float(cells[8]) == pytest.approx(fd["safety_factor"].values[j], abs=0.0051)
    off = line_rows(p.tables["fd_offsets"])
    assert float(off["surge"]["cells"][6]) == pytest.approx(fd["max_total"].values[0], abs=5e-4)
    with xr.open_dataset(tmp_path / "r" / "summary.nc") as nc:
        np.testing.assert_allclose(nc["fd_tension_max_total"].values,
                                   fd["tension_max_total"].values)


@pytest.mark.parametrize("case", ["missing", "empty", "only_errors", "mixed", "not_a_result",
                                  "failed_line_without_als", "unknown_failed_line", "fd_missing",
                                  "fd_other_scene", "duplicate_seed"])
def test_bad_input_exits_2_without_traceback(case, data, tmp_path, capsys):
    d = tmp_path / "res"
    argv = [d]
    if case == "missing":
        pass
    elif case == "empty":
        d.mkdir()
    elif case == "only_errors":
        d.mkdir()
        (d / "x_seed0001.error.txt").write_text("NumericalError: boom\n")
    else:
        shutil.copytree(data["intact"], d)
        if case == "mixed":
            shutil.copy(next(data["als"].glob("*.nc")), d)
        elif case == "not_a_result":          # only a non-result netCDF file in the folder
            for f in d.glob("*.nc"):
                f.unlink()
            shutil.copy(data["fd"], d / "fd.nc")
        elif case == "failed_line_without_als":
            argv += ["--failed-line", "line1"]
        elif case == "unknown_failed_line":
            argv += ["--als-dir", data["als"], "--failed-line", "line9"]
        elif case == "fd_missing":
            argv += ["--fd", tmp_path / "nope.nc"]
        elif case == "fd_other_scene":
            with xr.open_dataset(data["fd"]) as fd:
                fd = fd.load()
            fd.attrs["scene_name"] = "another-scene"
            fd.to_netcdf(tmp_path / "fd2.nc")
            argv += ["--fd", tmp_path / "fd2.nc"]
        elif case == "duplicate_seed":
            f = next(d.glob("*.nc"))
            shutil.copy(f, d / ("copy_" + f.name))
    code, stdout, stderr = run_report(argv + ["--out", tmp_path / "r"], capsys)
    assert code == 2, (stdout, stderr)
    assert stderr.startswith("floatmoor: error:")
    assert not (tmp_path / "r" / "report.html").exists()
    expected_words = {"missing": "no such folder", "empty": "found 'none'",
                      "only_errors": "1 failed seed", "mixed": "one scene",
                      "not_a_result": "only other netCDF files: fd.nc", "failed_line_without_als": "--als-dir",
                      "unknown_failed_line": "line9", "fd_missing": "no such file",
                      "fd_other_scene": "another-scene", "duplicate_seed": "more than once"}
    assert expected_words[case] in stderr


def test_quasi_static_class_1_factors(data, tmp_path, capsys):
    """Wang (2016) table 3.1, consequence class 1, quasi-static: one factor 1.70 on the total."""
    code, stdout, _ = run_report([data["intact"], "--consequence-class", "1", "--analysis",
                                  "quasi-static", "--out", tmp_path / "r"], capsys)
    assert code == 0 and "consequence class 1" in stdout
    assert "analysis: quasi-static -- quasi-static given (--analysis quasi-static), as the " \
        "line model gives" in stdout and "OVERRIDE" not in stdout
    exp = expected_from_files(data["intact"])
    rows = line_rows(parse(tmp_path / "r" / "report.html").tables["lines_uls"])
    for line, e in exp.items():
        cells = rows[line]["cells"]
        assert cells[10] == "1.70" and cells[11] == "1.70"
        assert float(cells[13]) == pytest.approx(1.7 * e["p90"] / (0.95 * e["mbs"]), abs=6e-4)
