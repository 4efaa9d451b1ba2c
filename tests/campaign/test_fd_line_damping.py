"""The frequency domain's ``line_damping: fe`` in a campaign: the option of the base scene's
``frequency_domain`` section reaches every FD case (an intact case and one with a failed line,
whose FE line is not built).

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
FLAGSHIP_FE = ROOT / "scenes" / "floatel_100yr_fe.yaml"


def test_campaign_fd_cases_use_the_option(tmp_path):
    src = yaml.safe_load(FLAGSHIP_FE.read_text())
    for k in ("vessel", "environment", "mooring"):
        src[k] = (FLAGSHIP_FE.parent / src[k]).resolve().as_posix()
    src["frequency_domain"] = {"line_damping": "fe"}
    base = tmp_path / "base.yaml"
    base.write_text(yaml.safe_dump(src))
    camp = tmp_path / "c.yaml"
    camp.write_text(yaml.safe_dump({
        "name": "ld", "base_scene": base.as_posix(),
        "sea_states": {"list": [{"name": "a", "hs": 12.0, "tp": 15.0}]},
        "headings": {"waves_deg": [30.0]},
        "conditions": {"intact": True, "failed_lines": [["line6"]]},
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
            scene, failed = case_scene(base_scene, case, dict(spec.analysis))
            assert scene.frequency_domain.line_damping == "fe"
            assert ds.attrs["fd_line_damping"] == "fe"
            on = frequency_domain_result(build(scene, failed_lines=failed))
            off = frequency_domain_result(build(scene, failed_lines=failed), line_damping="none")
            assert on.lf_damping_mooring is not None and off.lf_damping_mooring is None
            np.testing.assert_allclose(ds["max_total"].values, on.max_total, rtol=1e-12)
            np.testing.assert_allclose(ds["tension_max_total"].values, on.tension_max_total,
                                       rtol=1e-12, equal_nan=True)
            # the line damping lowers the LF surge and sway (the waves head 30 deg)
            assert on.lf_std[0] < 0.9 * off.lf_std[0] and on.lf_std[1] < 0.9 * off.lf_std[1]
            if failed:
                assert np.isnan(on.fairlead_damping[5]).all()
                assert np.isfinite(on.fairlead_damping[0]).all()
            ds.close()
