"""The coupled FE flagship keeps every bound of the FE self-check, and ``floatmoor lines`` driven
by the coupled run's own motion gives the coupled run's line tensions.

The same lines (``scenes/floatel_100yr_fe.yaml``: 12 lines of 50 elements, the scene's current
on the lines) driven by the same body motion: the decoupled run differs from the coupled one
only by the coupling (the coupled run's lines see the fairlead at the end of each body step,
the decoupled ones the recorded motion, linear in between), so their statistics agree closely.
Measured over the 3-hour window of seed 19 (2026-11-27): every line's fairlead mean, std and
maximum within 0.03 % (docs/FE_LINES.md); here 1500 s of seed 1 (300 s of statistics after a
1200 s transient), within 0.5 %.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

pytestmark = pytest.mark.slow   # a coupled FE storm and 12 decoupled lines: about 2-4 minutes

ROOT = Path(__file__).resolve().parents[3]


def test_coupled_flagship_keeps_the_bounds_and_lines_reproduces_it(tmp_path, capsys):
    import floatmoor
    from floatmoor.cli import main

    scene = ROOT / "scenes" / "floatel_100yr_fe.yaml"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = floatmoor.simulate(floatmoor.load_scene(scene), seed=1, duration=1500.0)
    assert not [w for w in caught if "self-check" in str(w.message)]
    assert list(ds["selfcheck"].values) == ["ok"] * 12
    assert np.all(ds["selfcheck_tension_ratio"].values < 1.0)
    motion = tmp_path / "seed0001.nc"
    ds.to_netcdf(motion)
    out = tmp_path / "lines.nc"
    assert main(["lines", str(scene), "--motion", str(motion), "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "self-check: ok" in text
    import xarray as xr
    with xr.open_dataset(out) as res:
        res = res.load()
    sel = ds.time.values >= ds.attrs["transient"]
    for j, name in enumerate(ds.line.values):
        coupled = ds.line_tension.values[sel, j]
        k = list(res.line.values).index(name)
        assert float(res.fe_mean.values[k]) == pytest.approx(coupled.mean(), rel=5e-3)
        assert float(res.fe_std.values[k]) == pytest.approx(coupled.std(), rel=5e-3)
        assert float(res.fe_max.values[k]) == pytest.approx(coupled.max(), rel=5e-3)
        assert str(res.selfcheck.values[k]) == "ok"
