"""The verdict's FE self-check line: FAIL when a finite-element line of a seed broke a bound of
its self-check (its tensions are not to be used), PASS when every one kept them, NOT CHECKED for
FE results written without the self-check, absent for quasi-static results."""

import numpy as np
import xarray as xr

from floatmoor.post.verdict import FAIL, NOT_CHECKED, PASS, fe_selfcheck_line, overall


def _seed(seed, models, checks=None):
    ds = xr.Dataset({"line_model": ("line", np.array(models))},
                    coords={"line": [f"line{i + 1}" for i in range(len(models))]},
                    attrs={"seed": seed})
    if checks is not None:
        ds["selfcheck"] = ("line", np.array(checks))
    return ds


def test_quasi_static_results_have_no_fe_line():
    assert fe_selfcheck_line([_seed(1, ["quasi-static", "quasi-static"])]) is None


def test_every_fe_line_ok_passes():
    v = fe_selfcheck_line([_seed(s, ["finite-element", "quasi-static"], ["ok", "-"])
                           for s in (1, 2, 3)])
    assert v.status == PASS and "3 seed(s)" in v.text


def test_a_broken_bound_fails_the_verdict():
    bad = "tension along the line 12518 kN above the bound 4300 kN"
    res = [_seed(1, ["finite-element"] * 2, ["ok", "ok"]),
           _seed(2, ["finite-element"] * 2, ["ok", bad])]
    v = fe_selfcheck_line(res)
    assert v.status == FAIL and "seed 2 line2" in v.text and "12518 kN" in v.text
    assert overall([v])[0] == FAIL


def test_fe_results_without_the_self_check_are_not_checked():
    v = fe_selfcheck_line([_seed(1, ["finite-element"])])
    assert v.status == NOT_CHECKED and "rerun" in v.text
