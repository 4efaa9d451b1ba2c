"""The fibre-rope stiffness notebook runs headless (reduced to 600 s time-domain seeds).

Slow: 4 cases x (frequency domain + one 600 s storm of the Floatel-like semi), about 1 minute
on the 2-core sandbox. Expected: no error; the load-dependent cases share their mean offset
(same working curve), which is larger than the constant-EA one (the working curve of
``polyester_default`` is softer than the constant 20.3 MBS at these mean loads), and the upper
bound's FD maximum tension exceeds the lower bound's (stiffer dynamics).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.notebooks import run_notebook

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks" / "fibre_rope_stiffness.ipynb"


@pytest.mark.slow  # reason: 4 frequency-domain runs and 4 storms (about 1 minute)
def test_fibre_rope_stiffness_notebook_runs(monkeypatch):
    monkeypatch.setenv("FLOATMOOR_NB_DURATION", "600")
    nb = run_notebook(NOTEBOOK, timeout=1200)
    text = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code"
                   for o in c.get("outputs", []))
    rows = {}
    for case in ("constant", "static-dynamic", "load-dependent, lower", "load-dependent, upper"):
        found = re.findall(rf"^{re.escape(case)}\s+(line\d+)?\s*([-\d. ]+)$", text, re.M)
        assert len(found) == 2, case  # the surge row and the tension row
        rows[case] = [[float(x) for x in f[1].split()] for f in found]
    surge = {k: v[0] for k, v in rows.items()}
    tension = {k: v[1] for k, v in rows.items()}
    assert surge["load-dependent, lower"][0] == surge["load-dependent, upper"][0]
    assert surge["load-dependent, upper"][0] > surge["constant"][0]
    assert tension["load-dependent, upper"][3] > tension["load-dependent, lower"][3]
