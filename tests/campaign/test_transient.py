"""Transient ALS in a campaign: a line breaking at a time during the storm (``conditions:
line_failure``) runs through the campaign, the line's tension is zero from the break on, and the
report checks the case as ALS, with the ALS partial safety factors of DNV (2008) (Ch.2 Sec.2,
as reproduced in Wang (2016) table 3.2: consequence class 2, dynamic analysis, gamma_mean 1.00,
gamma_dyn 1.25) against the ULS factors of the intact case (Wang (2016) table 3.1: 1.40, 2.10),
and leaves the broken line out of the check."""

from pathlib import Path

import netCDF4
import numpy as np
import pytest

from floatmoor.campaign import store
from floatmoor.campaign.engine import run_campaign
from floatmoor.campaign.report import analyse, write_report
from floatmoor.post.extremes import gumbel_fit

HERE = Path(__file__).parent
BREAK = "ss1_h000p0_wi000p0_cu000p0_break-line6-t150"
INTACT = "ss1_h000p0_wi000p0_cu000p0_intact"


@pytest.fixture(scope="module")
def transient_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("transient")
    r = run_campaign(HERE / "transient.yaml", out, scheduler="serial", echo=None)
    return out, r


def test_transient_condition_runs_and_breaks_the_line(transient_run):
    out, r = transient_run
    assert not r.failed and r.ran == {"fd": 2, "td": 6}
    rows = store.Manifest(out).latest()
    assert rows[("td", BREAK, 1)]["limit_state"] == "ALS"
    assert rows[("td", INTACT, 1)]["limit_state"] == "ULS"
    j = store.read_record(out)["lines"].index("line6")
    for seed in (1, 2, 3):
        with netCDF4.Dataset(store.storm_path(out, BREAK, seed)) as nc:
            t = nc["time_line_tension"][:]
            T = nc["line_tension"][:, j]
            assert nc.getncattr("case_limit_state") == "ALS"
            assert "failed_lines" not in nc.ncattrs()  # present until it breaks
        assert np.all(T[t < 150.0] > 1e5)       # carrying load before the break
        assert np.all(T[t > 150.0 + 0.5] == 0.0)  # none after (dt 0.5 s)
    # the FD screens the transient case with the line failed (no transient in the FD)
    with netCDF4.Dataset(store.fd_path(out, BREAK)) as nc:
        assert bool(nc["line_failed"][j])
        assert nc["tension_max_total"][j] == 0.0 or not np.isfinite(nc["tension_max_total"][j])


def test_report_checks_transient_case_as_als(transient_run):
    out, _ = transient_run
    a = analyse(out)
    lines = a["lines"]
    j6 = lines.index("line6")
    ib, ii = a["ids"].index(BREAK), a["ids"].index(INTACT)
    assert np.isnan(a["u_td"][ib, j6])            # the broken line is not checked
    assert np.isfinite(np.delete(a["u_td"][ib], j6)).all()
    assert np.isfinite(a["u_td"][ii]).all()          # intact: every line checked
    als = [g for g in a["governing"] if g["limit_state"] == "ALS"]
    uls = [g for g in a["governing"] if g["limit_state"] == "ULS"]
    assert {g["case"] for g in als} == {BREAK} and {g["case"] for g in uls} == {INTACT}
    assert len(als) == len(lines) - 1 and "line6" not in {g["line"] for g in als}
    assert all((g["gamma_mean"], g["gamma_dyn"]) == (1.00, 1.25) for g in als)
    assert all((g["gamma_mean"], g["gamma_dyn"]) == (1.40, 2.10) for g in uls)
    # the design equation by hand from the stored seed maxima: T_C the 90 % fractile of the
    # Gumbel fit (maximum likelihood) of the maxima, T_C-mean the mean of the seeds' means,
    # T_d = gamma_mean T_C-mean + gamma_dyn (T_C - T_C-mean), u = T_d / (0.95 MBS)
    for g in als:
        j = lines.index(g["line"])
        mx, mean, mbs = [], [], None
        for seed in (1, 2, 3):
            with netCDF4.Dataset(store.storm_path(out, BREAK, seed)) as nc:
                mx.append(float(nc["line_tension_max"][j]))
                mean.append(float(nc["line_tension_mean"][j]))
                mbs = float(nc["mbs"][j])
        with pytest.warns(UserWarning, match="only 3 maxima"):
            t_c = gumbel_fit(np.array(mx), method="mle").fractile(0.9)
        t_m = float(np.mean(mean))
        # S_C at the end of life: the Floatel-like chain 84 -> 76 mm (0.4 mm/year in the
        # splash and bottom zones over the default 20 years, DNV-OS-E301 (2008) table B1 in the
        # code file), MBS x (76/84)^2; the new line's utilisation on 0.95 MBS
        u = (1.00 * t_m + 1.25 * (t_c - t_m)) / (0.95 * mbs * (76 / 84) ** 2)
        assert g["utilisation"] == pytest.approx(u, rel=1e-12)
        assert g["utilisation_new"] == pytest.approx(u * (76 / 84) ** 2, rel=1e-12)
    report = write_report(out)
    md = (Path(out) / "report" / "report.md").read_text()
    assert "break-line6-t150" in md and report["governing"]


def test_report_consequence_class_flag_overrides_the_campaign(transient_run, capsys):
    """``floatmoor report DIR --consequence-class 1`` on a campaign of class 2: the class 1
    factors (Wang (2016) table 3.2: ALS 1.00, 1.10) are used and the report says it overrode
    the campaign's; without the flag the campaign's class 2 applies and the report says so."""
    from floatmoor.cli import main
    out, _ = transient_run
    a = analyse(out, consequence_class=1)
    als = [g for g in a["governing"] if g["limit_state"] == "ALS"]
    assert als and all((g["gamma_mean"], g["gamma_dyn"]) == (1.00, 1.10) for g in als)
    b = analyse(out)
    # the same stored tensions, a smaller dynamic factor: every ALS utilisation lower
    u2 = {g["line"]: g["utilisation"] for g in b["governing"] if g["limit_state"] == "ALS"}
    assert all(g["utilisation"] < u2[g["line"]] for g in als)
    rd = Path(out) / "report_cc1"
    main(["report", str(out), "--consequence-class", "1", "--out", str(rd)])
    text = capsys.readouterr().out
    assert "consequence class 1 instead of the campaign's 2" in text
    assert "consequence class 1 instead of the campaign's 2" in (rd / "report.md").read_text()
    with netCDF4.Dataset(rd / "summary.nc") as nc:
        assert nc.getncattr("consequence_class") == 1
    main(["report", str(out), "--out", str(Path(out) / "report_cc2")])
    text = capsys.readouterr().out
    assert "consequence class 2, dynamic analysis (of the campaign file)" in text
    # the campaign file's analysis: dynamic on quasi-static lines, an override said so
    assert "dynamic (OVERRIDE) -- OVERRIDE: dynamic-analysis factors given" in text
    assert "ALS line tension" in text and "verdict:" in text


def test_report_takes_the_code_of_the_campaign(transient_run, tmp_path):
    """A campaign whose file names API RP 2SK (2005): the report checks with its factors of
    safety (damaged, dynamic: 1.25 on T_C; code file api-rp-2sk-2005) on S_C = MBS at the end
    of life, and names the code (the record here is the transient campaign's with the code
    changed, as a campaign file with design: {standard: api-rp-2sk-2005} writes it)."""
    import json
    import shutil
    out, _ = transient_run
    d = tmp_path / "api"
    shutil.copytree(out, d)
    rec = json.loads((d / "campaign.json").read_text())
    rec["design"]["standard"] = "api-rp-2sk-2005"
    (d / "campaign.json").write_text(json.dumps(rec))
    a = analyse(d)
    assert a["design"].code.key == "api-rp-2sk-2005" and not a["design"].overridden
    lines = a["lines"]
    for g in (g for g in a["governing"] if g["limit_state"] == "ALS"):
        j = lines.index(g["line"])
        mx, mbs = [], None
        for seed in (1, 2, 3):
            with netCDF4.Dataset(store.storm_path(d, BREAK, seed)) as nc:
                mx.append(float(nc["line_tension_max"][j]))
                mbs = float(nc["mbs"][j])
        with pytest.warns(UserWarning, match="only 3 maxima"):
            t_c = gumbel_fit(np.array(mx), method="mle").fractile(0.9)
        assert g["utilisation"] == pytest.approx(1.25 * t_c / (mbs * (76 / 84) ** 2),
                                                 rel=1e-9)
    r = write_report(d, tmp_path / "rep")
    assert r["summary_lines"][0].startswith("API RP 2SK")
