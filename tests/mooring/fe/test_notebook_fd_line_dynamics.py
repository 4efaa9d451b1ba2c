"""The frequency-domain line dynamics notebook runs headless (about 1-2 minutes on the 2-core
sandbox: 16 time-domain runs of the OC3 line and 4 of two Floatel-like lines)."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
NOTEBOOK = ROOT / "notebooks" / "fd_line_dynamics.ipynb"


@pytest.mark.slow  # reason: 20 time-domain FE line runs (1-2 minutes)
def test_fd_line_dynamics_notebook_runs():
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=1800, kernel_name="python3",
                                     resources={"metadata": {"path": str(NOTEBOOK.parent)}})
    client.execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if o.get("output_type") == "error"]
    assert not errors
    text = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code"
                   for o in c.get("outputs", []))
    assert "sigma 1.50 m: TD" in text and "line1: WF tension std" in text
