"""The notebooks without a test of their own run headless, and what they print still shows what
they are there to show.

Slow (about 2 minutes on the 2-core sandbox, mostly the three 12000 s storms of the FD/TD
notebook); skipped without the optional ``notebooks`` extra (nbformat, nbclient, ipykernel).

* ``fd_vs_td``, reduced to 2 seeds (``FD_VS_TD_SEEDS``): the FD mean surge is the static
  equilibrium under the mean loads and the TD mean the time average of the storms under the same
  loads, so they agree within the sampling error of 2 x 3 hours (surge LF std 2.4 m, Tz ~100 s:
  ~200 LF cycles, ~0.2 m) plus the gust's share of the quadratic wind force (5 % of the wind
  force: ~0.2 m): 5 %; the WF surge is linear in both, so its significant amplitudes agree
  within the sampling error of the std of ~1300 WF cycles (~2 %): 8 %; the mirror-image lines 6
  and 7 of the head-seas scene print the same TD mean tension.
* ``fe_line_convergence``: its converged settings (80 elements, dt 0.025 s) are within 0.2 % of
  the notebook's finer reference in tension range, and the dynamic amplification is above 1.
* ``seabed_friction``: the FE statics with transverse seabed friction against the closed form of
  Lu (2012) (``transverse_friction_static``) within 0.5 % in fairlead tension and sway force.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.notebooks import run_notebook

ROOT = Path(__file__).resolve().parents[1]
NB = ROOT / "notebooks"


def _text(nb) -> str:
    return "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code"
                   for o in c.get("outputs", []))


def _row(text: str, start: str) -> list[float]:
    line = next(ln for ln in text.splitlines() if ln.startswith(start))
    return [float(x) for x in re.findall(r"-?\d+\.\d+", line[len(start):])]


@pytest.mark.slow  # reason: three 12000 s storms (about 1 minute)
def test_fd_vs_td_notebook_with_two_seeds(monkeypatch):
    monkeypatch.setenv("FD_VS_TD_SEEDS", "2")
    text = _text(run_notebook(NB / "fd_vs_td.ipynb", timeout=1800))
    # columns: max, mean, LFmax-mean, LFmax, WFsig
    fd = _row(text, "floatmoor FD (eq. 2.49)")
    td = _row(text, "floatmoor TD (2 seeds, G90)")
    assert abs(td[1] / fd[1] - 1.0) < 0.05, (fd, td)
    assert abs(td[4] / fd[4] - 1.0) < 0.08, (fd, td)
    # line table: FD static ... TD mean is the 7th number of a row
    l6, l7 = _row(text, "line6 "), _row(text, "line7 ")
    assert l6[:7] == l7[:7], (l6, l7)


@pytest.mark.slow  # reason: 16 prescribed-motion runs and a reference (about 10 s)
def test_fe_line_convergence_notebook():
    text = _text(run_notebook(NB / "fe_line_convergence.ipynb", timeout=900))
    rows = [ln.split() for ln in text.splitlines() if re.match(r"\s+\d+\s+0\.\d{3}\s", ln)]
    assert len(rows) == 16, text
    finest = next(r for r in rows if r[0] == "80" and r[1] == "0.025")
    assert float(finest[2]) < 0.2, finest          # range error, %
    daf = float(re.search(r"DAF \(FE 40 elements.*?\): ([\d.]+)", text).group(1))
    assert daf > 1.0


@pytest.mark.slow  # reason: 18 prescribed-motion runs and 6 statics (about 10 s)
def test_seabed_friction_notebook_against_the_closed_form():
    text = _text(run_notebook(NB / "seabed_friction.ipynb", timeout=900))
    rows = [r for r in (ln.split() for ln in text.splitlines())
            if len(r) == 10 and r[2] == "/" and r[6] == "/"]
    assert len(rows) == 6, text
    for r in rows:
        # Y, T_FE, /, T_analytic, err %, Fy_FE, /, Fy_analytic, err %, Fy no friction
        assert abs(float(r[4])) < 0.5 and abs(float(r[8])) < 0.5, r


@pytest.mark.slow  # reason: MoorDyn on a 132-segment line for 2400 s (about 2-3 minutes)
def test_fe_slack_line_moordyn_notebook(monkeypatch):
    """The slack-line notebook, shortened to 2400 s (``FE_SLACK_DURATION``): floatmoor's
    fairlead and anchor mean, std and max within 5 % of MoorDyn's (the issue's tolerance; over
    the notebook's 5000 s and the benchmark's 3 hours they agree within 1 %)."""
    pytest.importorskip("moordyn")
    monkeypatch.setenv("FE_SLACK_DURATION", "2400")
    text = _text(run_notebook(NB / "fe_slack_line_moordyn.ipynb", timeout=1800))
    for what in ("fairlead", "anchor"):
        md = _row(text, f"{what} MoorDyn")
        fm = _row(text, f"{what} floatmoor")
        for a, b in zip(fm[:3], md[:3]):
            assert abs(a / b - 1.0) < 0.05, (what, fm, md)
