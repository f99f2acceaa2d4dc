"""Weather windows and waiting times (boatland.site.windows) against a hand-made series with known windows, and
against an independent count (a plain loop) on the shipped example hindcast."""

import math

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.site import persistence, run_lengths

#              0  1  2  3  4  5  6  7  8  9 10 11
SERIES = np.array([1, 1, 1, 0, 1, 1, 0, 0, 1, 1, 1, 1], bool)


def test_run_lengths_by_hand():
    assert run_lengths(SERIES).tolist() == [3, 2, 1, 0, 2, 1, 0, 0, 4, 3, 2, 1]


def test_known_windows():
    # 3-h steps, a 6-h window = 2 records: starts at 0, 1, 4, 8, 9, 10 (11 is too near the end)
    p = persistence(SERIES, 3.0, 6.0)
    assert p.records == 2
    assert np.flatnonzero(p.starts).tolist() == [0, 1, 4, 8, 9, 10]
    assert p.probability() == pytest.approx(6 / 11)
    # waits [h]: to the next start at or after each record
    assert p.wait_hours[:11].tolist() == [0, 0, 6, 3, 0, 9, 6, 3, 0, 0, 0] and math.isnan(p.wait_hours[11])
    assert p.censored() == pytest.approx(1 / 12)
    # a 7-h window needs 3 records (⌈7/3⌉): starts at 0, 8, 9
    q = persistence(SERIES, 3.0, 7.0)
    assert q.records == 3 and np.flatnonzero(q.starts).tolist() == [0, 8, 9]
    # a window as long as one step: every workable record
    assert persistence(SERIES, 3.0, 3.0).starts.tolist() == SERIES.tolist()


def test_no_window_at_all_is_censored_not_zero():
    p = persistence(np.zeros(10, bool), 1.0, 2.0)
    assert p.probability() == 0.0 and p.censored() == 1.0
    assert p.wait_quantiles((0.5,)) == (math.inf,)


@pytest.mark.parametrize("hours", [0.0, -1.0, math.inf])
def test_a_window_must_be_positive(hours):
    with pytest.raises(BoatlandInputError, match="must be > 0 h"):
        persistence(SERIES, 1.0, hours)


def _count(ok, k):
    """Independent count: for every start with k records left, look at the k records (a plain loop); the wait
    by walking forward."""
    n = len(ok)
    starts = [i + k <= n and all(ok[i:i + k]) for i in range(n)]
    waits = []
    for i in range(n):
        j = next((j for j in range(i, n) if starts[j]), None)
        waits.append(None if j is None else j - i)
    return starts, waits


@pytest.mark.parametrize("hours", [3.0, 4.0, 12.0, 24.0])
def test_shipped_example_against_an_independent_count(landing27, hours):
    from boatland.site import operability, read_weather
    from tests.site.conftest import HINDCAST

    db, s = landing27
    w = read_weather(HINDCAST)
    op = operability(db, s, w, [45.0, 165.0, 285.0], window_hours=hours)
    for j, p in enumerate(op.windows):
        ok = op.workable[:, j].tolist()
        k = math.ceil(hours / w.step_hours)
        starts, waits = _count(ok, k)
        assert p.starts.tolist() == starts
        usable = len(ok) - (k - 1)
        assert p.probability() == pytest.approx(sum(starts[:usable]) / usable, abs=0, rel=1e-15)
        assert [None if math.isnan(x) else x for x in p.wait_hours.tolist()] == \
            [None if x is None else x * w.step_hours for x in waits]
    # the example is a test that can fail: some windows, some waits
    best = op.windows[-1]
    assert 0 < best.probability() < 1 and np.nanmax(best.wait_hours) > 24
