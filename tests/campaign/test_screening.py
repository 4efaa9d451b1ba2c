"""The FD screening rule on a hand-made utilisation matrix."""

import numpy as np

from floatmoor.campaign.screening import select_cases
from floatmoor.campaign.spec import Screening


def test_within_percent_and_top_n():
    # 5 cases x 2 lines; cases 0-3 ULS, case 4 ALS
    u = np.array([[0.50, 0.10],
                  [0.46, 0.20],
                  [0.40, 0.30],
                  [0.10, 0.29],
                  [0.20, np.nan]])
    ls = ["ULS"] * 4 + ["ALS"]
    keep, why = select_cases(u, ls, Screening(within_percent=10.0, top_per_line=1))
    # line 1 ULS: governing 0.50, within 10 %: >= 0.45 -> cases 0, 1; top 1: case 0
    # line 2 ULS: governing 0.30, >= 0.27 -> cases 2, 3; ALS: case 4 alone governs line 1
    assert keep.tolist() == [True, True, True, True, True]
    assert why[1, 0] == 1 and why[0, 0] == 3 and why[3, 1] == 1 and why[4, 0] == 3
    keep, _ = select_cases(u, ls, Screening(within_percent=0.0, top_per_line=1))
    assert keep.tolist() == [True, False, True, False, True]
    keep, _ = select_cases(u, ls, Screening(within_percent=0.0, top_per_line=2))
    assert keep.tolist() == [True, True, True, True, True]
    assert not select_cases(u, ls, Screening(time_domain="none"))[0].any()
    assert select_cases(u, ls, Screening(time_domain="all"))[0].all()
