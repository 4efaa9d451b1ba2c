"""Run a notebook headless for the slow notebook tests (nbformat and nbclient are optional)."""

from __future__ import annotations

import pytest


def run_notebook(path, *, timeout: int):
    """Execute the notebook at ``path`` in its own folder; fail on any error output; return
    the executed notebook (skip when nbformat/nbclient are not installed)."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=timeout, kernel_name="python3",
                                     resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if o.get("output_type") == "error"]
    assert not errors
    return nb
