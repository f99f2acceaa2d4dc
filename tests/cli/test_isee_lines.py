"""The ISEE limit lines of ``boatland campaign``: an interval end or a limit not found is said in words, never NaN."""

import math

import numpy as np

from boatland.cli.campaign import _limit_interval, _no_limit_why


def test_an_open_interval_end_is_named_by_the_levels_searched():
    levels = np.array([0.12, 0.14])
    text = _limit_interval({"limiting Hs lo": 0.1245, "limiting Hs hi": math.nan}, levels)
    assert text.startswith("[0.1245, > 0.42]") and "beyond ×3 of the levels searched" in text and "nan" not in text
    assert _limit_interval({"limiting Hs lo": math.nan, "limiting Hs hi": 0.15}, levels).startswith("[< 0.04, 0.15]")
    assert _limit_interval({"limiting Hs lo": 0.1245, "limiting Hs hi": 0.15}, levels) == "[0.1245, 0.15]"


def test_a_limit_not_found_says_where_it_was_looked_for():
    why = _no_limit_why(np.array([0.12, 0.14]))
    assert "between Hs 0.04 and 0.42 m" in why and "nan" not in why
