"""The frequency-domain line dynamics notebook runs headless (about 1-2 minutes on the 2-core
sandbox: 16 time-domain runs of the OC3 line and 4 of two Floatel-like lines; the coupled FE
storms are read from notebooks/data/fd_line_dynamics, precomputed by
benchmarks/fd_vs_coupled_storms.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.notebooks import run_notebook

ROOT = Path(__file__).resolve().parents[3]
NOTEBOOK = ROOT / "notebooks" / "fd_line_dynamics.ipynb"


@pytest.mark.slow  # reason: 20 time-domain FE line runs (1-2 minutes)
def test_fd_line_dynamics_notebook_runs():
    nb = run_notebook(NOTEBOOK, timeout=1800)
    text = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code"
                   for o in c.get("outputs", []))
    assert "sigma 1.50 m: TD" in text and "line1: WF tension std" in text
    assert "coupled FE storms" in text and "FD at TD pose" in text
