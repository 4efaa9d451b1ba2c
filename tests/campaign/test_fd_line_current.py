"""The frequency domain's ``line_current_drag`` in a campaign: the option of the base scene's
``frequency_domain`` section reaches every FD case (case headings of the current, failed lines).

Expected values: the frequency domain run directly on each case's scene
(:func:`floatmoor.campaign.matrix.case_scene`, the scene the case's task builds), with and
without the option.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import xarray as xr
import yaml

from floatmoor.analyses.frequency_domain import frequency_domain_result
from floatmoor.campaign.matrix import build_matrix, case_scene
from floatmoor.campaign.spec import load_campaign
from floatmoor.campaign.tasks import run_fd_cases
from floatmoor.io.build import build

ROOT = Path(__file__).resolve().parents[2]
FLAGSHIP = ROOT / "scenes" / "floatel_100yr.yaml"


def test_campaign_fd_cases_use_the_option(tmp_path):
    src = yaml.safe_load(FLAGSHIP.read_text())
    for k in ("vessel", "environment", "mooring"):
        src[k] = (FLAGSHIP.parent / src[k]).resolve().as_posix()
    src["frequency_domain"] = {"line_current_drag": True}
    base = tmp_path / "base.yaml"
    base.write_text(yaml.safe_dump(src))
    camp = tmp_path / "c.yaml"
    camp.write_text(yaml.safe_dump({
        "name": "lc", "base_scene": base.as_posix(),
        "sea_states": {"list": [{"name": "a", "hs": 12.0, "tp": 15.0}]},
        "headings": {"waves_deg": [30.0], "current_offset_deg": [20.0]},
        "conditions": {"intact": True, "failed_lines": [["line1"]]},
        "seeds": "1-3", "analysis": {"duration": 600.0, "dt": 0.2, "transient": 100.0}}))
    spec = load_campaign(camp)
    cases = build_matrix(spec)
    assert len(cases) == 2
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = run_fd_cases(str(spec.base_scene), cases, dict(spec.analysis), str(tmp_path))
        assert all(o["status"] == "done" for o in out), out
        base_scene = build(base).scene
        for case in cases:
            ds = xr.open_dataset(tmp_path / "fd" / f"{case.id}.nc")
            assert ds.attrs["fd_line_current_drag"] == 1
            scene, failed = case_scene(base_scene, case, dict(spec.analysis))
            assert scene.frequency_domain.line_current_drag is True
            on = frequency_domain_result(build(scene, failed_lines=failed))
            assert on.mean_force_line_current is not None
            np.testing.assert_allclose(ds["mean"].values, on.mean, rtol=0, atol=1e-9)
            np.testing.assert_allclose(ds["tension_static"].values, on.tension_static,
                                       rtol=1e-12, equal_nan=True)
            if failed:
                assert np.isnan(ds["tension_static"].values[0])
            else:
                off = frequency_domain_result(build(scene), line_current_drag=False)
                assert on.mean[0] - off.mean[0] > 1.0    # m: the option moved the case
            # the current heads 50 deg: the lines' drag has a sway part as well
            assert on.mean_force_line_current[1] > 0.2 * on.mean_force_line_current[0] > 0
            ds.close()
