"""The shared input-validation helpers of floatmoor.core.errors."""

import math
import pickle

import pytest

from floatmoor.core.errors import SceneError, argument_error, check_positive


def test_argument_error_names_the_argument_and_no_file():
    e = argument_error("cutoff", "a cut-off frequency > 0 in Hz", -1.0)
    assert isinstance(e, SceneError) and e.file is None
    assert str(e) == "(given in Python): cutoff: expected a cut-off frequency > 0 in Hz, found -1.0"
    missing = argument_error("hs", "a number > 0")
    assert missing.found is SceneError.MISSING and "key is missing" in str(missing)
    back = pickle.loads(pickle.dumps(e))      # crosses worker processes unchanged
    assert str(back) == str(e)


@pytest.mark.parametrize("value, expected", [(2, 2.0), ("0.5", 0.5), (1e-300, 1e-300)])
def test_check_positive_returns_a_float(value, expected):
    v = check_positive(value, "waves.hs")
    assert isinstance(v, float) and v == expected


@pytest.mark.parametrize("value", [0, -1.0, math.nan, math.inf, -math.inf, "x", None, [1.0]])
def test_check_positive_rejects(value):
    with pytest.raises(SceneError) as info:
        check_positive(value, "waves.tp")
    assert info.value.key == "waves.tp" and info.value.expected == "a number > 0"
