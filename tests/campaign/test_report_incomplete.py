"""A campaign whose cases sent to the time domain lack finished storms gets no design verdict.

The screening sends a case to the time domain because it may govern; while such a case has
fewer than 3 finished seeds (its storms failed, or have not run yet), the checks of the other
cases cannot stand for the design.  Before, the report then said "PASS for the checks made"
(exit status 0) and counted the missing cases in one summary sentence: a wrong PASS when the
missing case governs (e.g. an ALS condition whose storms fail because the remaining lines find
no equilibrium).  Now the limit state carries an INCOMPLETE line naming the cases, the verdict
is INCOMPLETE unless a check fails, and ``floatmoor report`` exits with status 1.
"""

from floatmoor.campaign.report import _verdict
from floatmoor.post.verdict import FAIL, INCOMPLETE, NOT_CHECKED, PASS, VerdictLine, overall


def test_overall_incomplete_between_fail_and_pass():
    ok = VerdictLine("ULS", "line tension", PASS, 0.8)
    nc = VerdictLine("FLS", "fatigue", NOT_CHECKED)
    inc = VerdictLine("ALS", "storms", INCOMPLETE, governing="c1")
    bad = VerdictLine("ULS", "anchor load", FAIL, 1.2)
    assert overall([ok, nc])[0] == PASS
    st, text = overall([ok, nc, inc])
    assert st == INCOMPLETE and "ALS storms" in text and "no design verdict" in text
    assert overall([ok, inc, bad])[0] == FAIL       # a failing check still fails the design


def test_campaign_verdict_names_the_cases_without_storms():
    governing = [{"limit_state": "ULS", "utilisation": 0.5, "passed": True, "line": "line1",
                  "case": "ss1_intact", "t_c": 1e6, "t_c_mean": 5e5, "design_tension": 1.1e6,
                  "s_c": 2e6, "s_c_new": 2e6}]
    states = ["ULS", "ALS", "ALS"]
    other = {"anchors": {}, "offsets": {}, "fibre": {}}
    lines = _verdict(governing, states, other, None,
                     {"ULS": [], "ALS": ["ss1_failed-line4", "ss2_failed-line4"]})
    inc = [v for v in lines if v.status == INCOMPLETE]
    assert len(inc) == 1 and inc[0].limit_state == "ALS"
    assert "2 case(s)" in inc[0].text and "ss1_failed-line4, ss2_failed-line4" in inc[0].text
    assert overall(lines)[0] == INCOMPLETE
    # every case finished: the same checks give PASS for the checks made
    lines = _verdict(governing, ["ULS"], other, None, {"ULS": [], "ALS": []})
    assert overall(lines)[0] == PASS


def test_cases_without_design_statistics_leave_the_other_checks_incomplete():
    """Anchor, offset and fibre checks made on some cases while others' storms carry no design
    statistics (results of an older floatmoor): INCOMPLETE naming those cases, not a PASS of
    the cases that had them."""
    governing = [{"limit_state": "ULS", "utilisation": 0.5, "passed": True, "line": "line1",
                  "case": "ss1_intact", "t_c": 1e6, "t_c_mean": 5e5, "design_tension": 1.1e6,
                  "s_c": 2e6, "s_c_new": 2e6}]
    other = {"anchors": {"ULS": None}, "offsets": {}, "fibre": {},
             "missing": {"ULS": ["ss2_intact"], "ALS": []}}
    lines = _verdict(governing, ["ULS"], other, {"limits": None}, {"ULS": [], "ALS": []})
    inc = [v for v in lines if v.status == INCOMPLETE]
    assert len(inc) == 1 and inc[0].check == "design stats" and "ss2_intact" in inc[0].text
    assert overall(lines)[0] == INCOMPLETE
