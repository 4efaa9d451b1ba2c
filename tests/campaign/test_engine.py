"""Campaign engine: serial against a 2-worker Dask LocalCluster, killed worker, resume,
half-written files, numerical failures; mirror symmetry of the Floatel-like mooring; report."""

import os
import signal
from pathlib import Path

import netCDF4
import numpy as np
import pytest

from floatmoor.campaign import store
from floatmoor.campaign.engine import run_campaign
from floatmoor.campaign.report import analyse, write_report

HERE = Path(__file__).parent
pytest.importorskip("dask.distributed")


def _files(d):
    d = Path(d)
    return sorted(str(p.relative_to(d)) for p in d.rglob("*.nc")
                  if p.parts[len(d.parts)] in ("fd", "td", "series"))


@pytest.fixture(scope="module")
def tiny_runs(tmp_path_factory):
    """The tiny campaign (2 sea states x 3 headings x intact + line 6 failed x 3 seeds of 600 s),
    every case in the time domain, serially and on a 2-worker LocalCluster."""
    a = tmp_path_factory.mktemp("serial")
    b = tmp_path_factory.mktemp("dask2")
    ra = run_campaign(HERE / "tiny_all.yaml", a, scheduler="serial", echo=None)
    rb = run_campaign(HERE / "tiny_all.yaml", b, scheduler="local", workers=2, echo=None)
    return a, b, ra, rb


@pytest.mark.slow  # two runs of 12 FD cases and 36 storms: about 1.5 min on 2 cores
def test_serial_and_two_workers_bit_identical(tiny_runs):
    a, b, ra, rb = tiny_runs
    assert not ra.failed and not rb.failed
    assert ra.ran == rb.ran == {"fd": 12, "td": 36}
    # the Dask workers warmed up before their first task (the serial process does not): the
    # files below are identical all the same
    assert ra.warmup == [] and len(rb.warmup) == 2
    assert not any(w["error"] for w in rb.warmup)
    fa, fb = _files(a), _files(b)
    assert fa == fb and len(fa) == 12 + 36
    for f in fa:
        assert (Path(a) / f).read_bytes() == (Path(b) / f).read_bytes(), f
    xa, xb = analyse(a), analyse(b)
    np.testing.assert_array_equal(xa["u_td"], xb["u_td"])
    np.testing.assert_array_equal(xa["u_fd"], xb["u_fd"])
    assert [g["case"] for g in xa["governing"]] == [g["case"] for g in xb["governing"]]
    assert [g["t_c_low"] for g in xa["governing"]] == [g["t_c_low"] for g in xb["governing"]]


@pytest.mark.slow
def test_mirror_symmetry_and_screening_keeps_the_governing_case(tiny_runs):
    """The Floatel-like mooring is symmetric about x (line azimuths 39, 45, 51, 129, ... 321 deg:
    line k mirrors to line 13 - k) and so is the hull: waves, wind and current towards 30 deg
    must give the line results of 330 deg with the lines mirrored, and sway, roll and yaw
    mirrored (max <-> -min), to round-off.  The TD governing case of every line is among the
    cases the FD screening rule keeps (the campaign ran every case in TD to check this)."""
    a = tiny_runs[0]
    for ss in (1, 2):
        for cond in ("intact", "failed-line6"):
            for seed in (1, 2, 3):
                p = store.storm_path(a, f"ss{ss}_h030p0_wi000p0_cu000p0_{cond}", seed)
                q = store.storm_path(a, f"ss{ss}_h330p0_wi000p0_cu000p0_{cond}", seed)
                if cond != "intact":
                    continue  # line 6 failed mirrors to line 7 failed: not in the matrix
                with netCDF4.Dataset(p) as x, netCDF4.Dataset(q) as y:
                    t1 = x["line_tension_max"][:]
                    t2 = y["line_tension_max"][:][::-1]
                    np.testing.assert_allclose(t1, t2, rtol=1e-9)
                    sign = np.array([1, -1, 1, -1, 1, -1])
                    mx, mn = x["motion_max"][:], y["motion_min"][:]
                    my = y["motion_max"][:]
                    mirrored = np.where(sign > 0, my, -mn)
                    np.testing.assert_allclose(mx, mirrored, rtol=1e-9, atol=1e-9)
    r = analyse(a)
    assert r["screened"].sum() < len(r["ids"])  # the rule does screen some out
    for g in r["governing"]:
        assert g["in_screening"], g
    gov = {(g["limit_state"], g["line"]): g for g in r["governing"]}
    assert gov[("ULS", "line7")]["wave_heading_deg"] == 30.0
    assert gov[("ULS", "line6")]["wave_heading_deg"] == 330.0
    assert gov[("ULS", "line7")]["utilisation"] == pytest.approx(
        gov[("ULS", "line6")]["utilisation"], rel=1e-9)


@pytest.mark.slow
def test_report_files_and_cli(tiny_runs, capsys):
    from floatmoor.cli import main
    a = tiny_runs[0]
    status = main(["report", str(a)])
    out = capsys.readouterr().out
    assert "ULS governing line" in out and "ALS governing line" in out
    # the verdict of the same checks as floatmoor report; the exit status follows it
    assert "ULS line tension" in out and "ULS anchor uplift" in out and "verdict:" in out
    assert status == (1 if "verdict: FAIL" in out else 0)
    rd = Path(a) / "report"
    for f in ("report.html", "report.md", "governing.csv", "td_cases.csv", "summary.nc"):
        assert (rd / f).is_file()
    rows = (rd / "governing.csv").read_text().splitlines()
    assert len(rows) == 1 + 12 + 11  # ULS every line, ALS every line but the failed line6


@pytest.mark.slow  # 12 FD cases and 24 storms on 2 workers, one of them killed
def test_killed_worker_campaign_completes(tmp_path):
    import logging

    from dask.distributed import Client, LocalCluster
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=":0", silence_logs=logging.ERROR)
    client = Client(cluster)
    killed = []

    def kill_one(outcome):
        if outcome["kind"] == "td" and not killed:
            pids = client.run(os.getpid)
            pid = min(pids.values())
            os.kill(pid, signal.SIGKILL)
            killed.append(pid)

    try:
        r = run_campaign(HERE / "tiny.yaml", tmp_path, client=client, echo=None,
                         on_outcome=kill_one)
    finally:
        client.close()
        cluster.close()
    assert killed
    latest = store.Manifest(tmp_path).latest()
    td = [v for k, v in latest.items() if k[0] == "td"]
    assert len(td) == r.n_td_cases * 3 and all(v["status"] == "done" for v in td)
    assert not r.failed


def test_interrupted_campaign_resumes_only_missing(tmp_path):
    """Interrupted after 2 storms; a finished file then truncated (half-written) and a stray
    temp file: the rerun runs the 2 missing storms and the damaged one, and nothing else."""
    seen = []

    def interrupt(o):
        if o["kind"] == "td":
            seen.append(o)
            if len(seen) == 2:
                raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_campaign(HERE / "mini.yaml", tmp_path, scheduler="serial", echo=None,
                     on_outcome=interrupt)
    done = [p for p in _files(tmp_path) if p.startswith("td")]
    assert len(done) == 2
    victim = Path(tmp_path) / done[0]
    victim.write_bytes(victim.read_bytes()[: victim.stat().st_size // 2])
    (Path(tmp_path) / "td" / "stray.nc.tmp").write_bytes(b"partial")
    r = run_campaign(HERE / "mini.yaml", tmp_path, scheduler="serial", echo=None)
    assert r.ran == {"td": 3} and r.skipped == {"fd": 1, "td": 1}
    assert not (Path(tmp_path) / "td" / "stray.nc.tmp").exists()
    with netCDF4.Dataset(victim) as nc:
        assert nc["line_tension"].shape[0] == 1501
    r = run_campaign(HERE / "mini.yaml", tmp_path, scheduler="serial", echo=None, verify=True)
    assert r.ran == {} and r.skipped == {"fd": 1, "td": 4}


def test_numerical_error_recorded_and_others_finish(tmp_path):
    """With lines 4-9 failed nothing holds the unit against the environment towards +x: there
    is no static equilibrium to start from (NumericalError in the TD, ConvergenceError in the
    FD); its FD case and 3 storms are recorded as failed with the message (the case goes to the
    TD although its FD failed: it cannot be screened out); the intact storms finish."""
    r = run_campaign(HERE / "failing.yaml", tmp_path, scheduler="serial", echo=None)
    rows = store.Manifest(tmp_path).latest()
    bad = [v for k, v in rows.items() if k[0] == "td" and "failed-line4" in k[1]]
    good = [v for k, v in rows.items() if k[0] == "td" and k[1].endswith("intact")]
    assert len(bad) == 3 and all(v["status"] == "failed" for v in bad)
    assert all(v["error"].startswith("NumericalError") and "equilibrium" in v["error"]
               for v in bad)
    fd_bad = [v for k, v in rows.items() if k[0] == "fd" and "failed-line4" in k[1]]
    assert fd_bad[0]["status"] == "failed" and "ConvergenceError" in fd_bad[0]["error"]
    assert len(good) == 3 and all(v["status"] == "done" for v in good)
    assert sum(1 for f in r.failed if f[0] == "td") == 3 and r.n_td_cases == 2
    a = write_report(tmp_path)  # a report with a failed case still works
    assert [g["limit_state"] for g in a["governing"]] == ["ULS"] * 12
    # ... but gives no design verdict: the ALS case the campaign sent to the time domain has
    # no finished storm (it was "PASS for the checks made" before)
    inc = [v for v in a["verdict"] if v.status == "INCOMPLETE"]
    assert len(inc) == 1 and inc[0].limit_state == "ALS"
    assert "ss1_h000p0_wi000p0_cu000p0_failed-line4" in inc[0].text
    assert a["overall"][0] in ("INCOMPLETE", "FAIL")
    from floatmoor.cli import main
    assert main(["report", str(tmp_path)]) == 1


@pytest.mark.slow  # 12 storms of 300 s in a worker process: about 40 s on the loaded machine
def test_statistics_mode_keeps_series_of_governing_case(tmp_path):
    """Statistics-only storms (a few kB) for every storm; the governing case is rerun from its
    seeds with full series, whose maxima are the statistics' maxima (same storm, bit for bit in
    float64 before the float32 rounding of the stored series)."""
    r = run_campaign(HERE / "mini_stats.yaml", tmp_path, scheduler="serial", echo=None)
    assert r.ran == {"fd": 1, "td": 4, "series": 4}
    case = "ss1_h000p0_wi000p0_cu000p0_intact"
    for seed in (1, 2, 3, 4):
        with netCDF4.Dataset(store.storm_path(tmp_path, case, seed)) as st, \
                netCDF4.Dataset(store.storm_path(tmp_path, case, seed, "series")) as se:
            assert "line_tension" not in st.variables
            np.testing.assert_array_equal(st["line_tension_max"][:], se["line_tension_max"][:])
            t = se["time_line_tension"][:]
            T = se["line_tension"][:][t >= 50.0].max(axis=0)
            np.testing.assert_allclose(T, st["line_tension_max"][:], rtol=6e-8)
        assert store.storm_path(tmp_path, case, seed).stat().st_size < 60_000


def test_resume_recomputes_after_an_edited_base_scene(tmp_path):
    """Every stored result carries the fingerprint of its inputs (base scene and the files it
    reads, by content; the case; the code): after the mooring file behind the same base-scene
    path is edited, a resume into the same folder computes every result again and says why
    (naming the mooring); the unedited scene resumes without running anything."""
    root = HERE.parents[1]
    work = tmp_path / "inputs"
    work.mkdir()
    mooring = work / "mooring.yaml"
    mooring.write_text((root / "vessels/floatel_like/mooring.yaml").read_text())
    scene = (root / "scenes/floatel_100yr.yaml").read_text()
    scene = scene.replace("../vessels/floatel_like/vessel.yaml",
                          str(root / "vessels/floatel_like/vessel.yaml"))
    scene = scene.replace("../metocean/heidrun_100yr.yaml",
                          str(root / "metocean/heidrun_100yr.yaml"))
    scene = scene.replace("../vessels/floatel_like/mooring.yaml", "mooring.yaml")
    (work / "base.yaml").write_text(scene)
    camp = (HERE / "mini.yaml").read_text()
    camp = camp.replace("../../scenes/floatel_100yr.yaml", "base.yaml")
    camp = camp.replace("seeds: \"1-4\"", "seeds: \"1-3\"").replace("duration: 300.0", "duration: 100.0")
    (work / "mini.yaml").write_text(camp)
    out = tmp_path / "out"
    r = run_campaign(work / "mini.yaml", out, scheduler="serial", echo=None)
    assert r.ran == {"fd": 1, "td": 3}
    assert store.read_record(out)["base_inputs"]["mooring"]
    r = run_campaign(work / "mini.yaml", out, scheduler="serial", echo=None)
    assert r.ran == {}
    case = "ss1_h000p0_wi000p0_cu000p0_intact"
    with netCDF4.Dataset(store.storm_path(out, case, 1)) as nc:
        before = np.asarray(nc["line_tension_max"][:])
    # the first segment of the first line 1 m longer: another mooring behind the same path
    mooring.write_text(_lengthen_first_segment(mooring.read_text()))
    said = []
    r = run_campaign(work / "mini.yaml", out, scheduler="serial", echo=said.append)
    assert r.ran == {"fd": 1, "td": 3} and not r.failed
    text = "\n".join(said)
    assert "FD: 1 result(s) computed from other inputs (differ in: mooring)" in text, text
    assert "TD: 3 result(s) computed from other inputs (differ in: mooring)" in text, text
    with netCDF4.Dataset(store.storm_path(out, case, 1)) as nc:
        assert not np.array_equal(before, np.asarray(nc["line_tension_max"][:]))
    r = run_campaign(work / "mini.yaml", out, scheduler="serial", echo=None)
    assert r.ran == {}


def _lengthen_first_segment(text):
    import re
    m = re.search(r"(\{type: \w+, length:\s*)([0-9.]+)", text)
    assert m, "the mooring file has a segment length"
    return text[:m.start(2)] + f"{float(m.group(2)) + 1.0}" + text[m.end(2):]
