"""Events and slip episodes from step records."""

import numpy as np
import pytest

from boatland.trial.events import extract_events, first_exceedance, landing_offset, slip_episodes


def records():
    t = np.arange(10) * 0.1
    mode = np.array([[0, 0], [1, 1], [1, 1], [2, 1], [2, 1], [1, 1], [1, 2], [1, 2], [1, 0], [1, 0]])
    needed = np.zeros((10, 2)); available = np.ones((10, 2)) * 5.0
    needed[3, 0] = 7.0
    tpos = np.zeros((10, 2, 2))
    tpos[3:5, 0, 0] = [0.02, -0.05]   # slides down 5 cm, then re-sticks at step 5
    tpos[5:, 0, 0] = -0.05
    tpos[6:8, 1, 1] = [0.1, 0.3]      # contact 1 slides sideways, then loses contact at step 8
    return t, mode, needed, available, tpos


def test_events_in_time_order_with_forces():
    t, mode, needed, available, _ = records()
    ev = extract_events(t, mode, needed, available)
    kinds = [(e.step, e.contact, e.kind) for e in ev]
    assert kinds == [(1, 0, "contact made"), (1, 1, "contact made"), (3, 0, "stick→slip"), (5, 0, "slip→stick"),
                     (6, 1, "stick→slip"), (8, 1, "contact lost")]
    assert ev[2].needed == 7.0 and ev[2].available == 5.0
    assert "needed 0.007 kN > available 0.005 kN" in ev[2].text()


def test_slip_distance_is_measured_from_where_it_stuck():
    t, mode, _, _, tpos = records()
    eps = slip_episodes(t, mode, tpos)
    assert [(e.contact, e.ended_by) for e in eps] == [(0, "re-stick"), (1, "contact lost")]
    assert [e.t_start for e in eps] == pytest.approx([0.3, 0.6])
    assert np.isclose(eps[0].distance, 0.05) and np.isclose(eps[0].vertical, -0.05)
    assert np.isclose(eps[1].distance, 0.3) and np.isclose(eps[1].horizontal, 0.3)


def test_first_exceedance():
    t = np.arange(5.0)
    assert first_exceedance(t, [0, 0.1, -0.3, 0.5, 0], 0.2) == 2.0
    assert first_exceedance(t, np.zeros(5), 0.2) is None


def test_landing_offset_accumulates_short_slides_and_survives_a_bounce():
    """Grøtting's (2015) incident: the fender point more than a threshold from where it landed. Three
    slides of 4 cm each, with re-sticks between, are three episodes below 5 cm but 12 cm from the
    landing. A bounce (contact lost, made again 3.9 m higher) does not start a new landing position:
    the fender has moved 3.9 m from where it landed."""
    mode = np.array([0, 2, 2, 1, 2, 1, 2, 1, 2, 1, 0, 2, 1, 1])[:, None]
    z = np.array([0, .3, .2, .1, .06, .06, .02, .02, -.02, -.02, 0, 5.0, 4.0, 4.0])
    tpos = np.zeros((14, 1, 2)); tpos[:, 0, 0] = z
    t = np.arange(14.0)
    eps = slip_episodes(t, mode, tpos)
    assert [e.t_start for e in eps] == [4.0, 6.0, 8.0]                # the slide before it caught is landing
    assert max(e.distance for e in eps) == pytest.approx(0.04)
    off = landing_offset(mode, tpos)[:, 0]
    assert np.isnan(off[:3]).all() and np.isnan(off[10])              # open, or touching but not yet caught
    assert off[9] == pytest.approx(0.12)                              # 0.10 → −0.02
    assert off[11:] == pytest.approx([4.9, 3.9, 3.9])                 # after the bounce: from the first landing
    settled = landing_offset(mode, tpos, k_start=5)[:, 0]            # settling until row 5: lands at 0.06
    assert np.isnan(settled[:5]).all() and settled[9] == pytest.approx(0.08)
    assert first_exceedance(t, np.nan_to_num(off), 0.05) == 6.0


# --- the one-pass implementations against the plain loops they replaced (bit for bit) ------------------


def _events_loop(t, mode, needed, available):
    """extract_events as a loop over every change (the former implementation: the oracle)."""
    from boatland.trial.events import KIND, Event

    events = []
    for c in range(mode.shape[1]):
        for k in np.nonzero(mode[1:, c] != mode[:-1, c])[0] + 1:
            events.append(Event(float(t[k]), int(k), c, KIND[(int(mode[k - 1, c]), int(mode[k, c]))],
                                float(needed[k, c]), float(available[k, c])))
    events.sort(key=lambda e: (e.step, e.contact))
    return events


def _episodes_loop(t, mode, tpos):
    """slip_episodes with a scan per episode and np.argmax of np.hypot (the former implementation)."""
    from boatland.contact.fender import OFF, OPEN, SLIP, STICK
    from boatland.trial.events import SlipEpisode

    episodes, n = [], mode.shape[0]
    ended_by = {STICK: "re-stick", OPEN: "contact lost", OFF: "slid off the landing"}
    for c in range(mode.shape[1]):
        m = mode[:, c]
        for k0 in np.flatnonzero((m[1:] == SLIP) & (m[:-1] == STICK)) + 1:
            rest = np.flatnonzero(m[k0:] != SLIP)
            k1, ended = (k0 + int(rest[0]), ended_by[int(m[k0 + rest[0]])]) if rest.size else (n - 1, "end of run")
            d = tpos[k0:k1 + 1, c] - tpos[k0 - 1, c]
            dist = np.hypot(d[:, 0], d[:, 1])
            i = int(np.argmax(dist))
            episodes.append(SlipEpisode(c, float(t[k0]), float(t[k1]), float(dist[i]), float(d[i, 0]),
                                        float(d[i, 1]), ended))
    episodes.sort(key=lambda e: (e.t_start, e.contact))
    return episodes


def _as_bits(items):
    return [tuple(np.float64(v).tobytes() if isinstance(v, float) else v for v in vars(e).values()) for e in items]


@pytest.mark.parametrize("seed", range(6))
def test_one_pass_events_episodes_and_offsets_equal_the_loops_bit_for_bit(seed):
    """Random records of 2–3 contacts (all four modes, runs of every length, slips still running at the
    end, NaN positions, ties): events, episodes and the worst landing offset are the former loops' values
    bit for bit."""
    from boatland.trial.events import worst_landing_offset

    rng = np.random.default_rng(seed)
    n, nc = 3000, 2 + seed % 2
    runs = rng.integers(1, 40, size=n)
    mode = np.repeat(rng.choice(4, size=n, p=[0.1, 0.45, 0.4, 0.05]), runs)[:n].reshape(-1, 1)
    mode = np.column_stack([np.roll(mode[:, 0], 17 * c) for c in range(nc)]).astype(np.int64)
    mode[-5:, 0] = 2                                                 # a slip still running at the end
    t = np.arange(n) * 0.05
    tpos = np.round(rng.normal(size=(n, nc, 2)), 2)                 # rounded: equal distances (ties) happen
    tpos[rng.integers(0, n, 5), 0, rng.integers(0, 2, 5)] = np.nan
    needed, available = rng.normal(size=(n, nc)), rng.normal(size=(n, nc))
    assert _as_bits(extract_events(t, mode, needed, available)) == _as_bits(_events_loop(t, mode, needed, available))
    assert _as_bits(slip_episodes(t, mode, tpos)) == _as_bits(_episodes_loop(t, mode, tpos))
    off = landing_offset(mode, tpos, k_start=7)
    expected = np.where(np.isnan(off), 0.0, off).max(axis=1)
    assert worst_landing_offset(mode, tpos, k_start=7).tobytes() == expected.tobytes()


def test_column_abs_max_and_touching_fraction_are_the_numpy_reductions():
    """The summary's compiled passes (issue 16) give numpy's values: NaN where a column has one."""
    from boatland.trial.events import all_touching_fraction, column_abs_max

    rng = np.random.default_rng(4)
    x = rng.normal(size=(1001, 6))
    assert np.array_equal(column_abs_max(x), np.max(np.abs(x), axis=0))
    x[[0, 500, 1000], [1, 3, 5]] = np.nan
    assert np.array_equal(column_abs_max(x), np.max(np.abs(x), axis=0), equal_nan=True)
    for nc in (1, 2, 3):
        mode = rng.integers(0, 4, size=(999, nc))
        assert all_touching_fraction(mode) == (mode > 0).all(axis=1).mean()


@pytest.mark.parametrize("seed", range(6))
def test_the_summary_read_from_the_records_equals_the_one_from_the_events_bit_for_bit(seed):
    """What the summary and the verdict read from the mode records without building events or episodes
    (issue 16: a campaign's trial has thousands) is what the event and episode lists give, bit for bit:
    the stick → slip steps and their contact counts, the first entry into open / off the landing after
    a row, and the largest single slide after a row — NaN where the first such episode's is NaN, as
    Python's ``max`` over the episodes in order."""
    from boatland.contact.fender import OFF, OPEN
    from boatland.trial.events import SLID_OFF, first_entry, largest_single_slide, slip_start_rows

    rng = np.random.default_rng(100 + seed)
    n, nc = 3000, 1 + seed % 3
    runs = rng.integers(1, 40, size=n)
    base = np.repeat(rng.choice(4, size=n, p=[0.1, 0.45, 0.4, 0.05]), runs)[:n]
    mode = np.column_stack([np.roll(base, 23 * c) for c in range(nc)]).astype(np.int64)
    t = np.arange(n) * 0.05
    tpos = np.round(rng.normal(size=(n, nc, 2)), 2)
    if seed % 2:                                                       # NaN positions inside some episodes
        tpos[rng.integers(0, n, 20), rng.integers(0, nc, 20), rng.integers(0, 2, 20)] = np.nan
    events = extract_events(t, mode, np.zeros((n, nc)), np.zeros((n, nc)))
    episodes = slip_episodes(t, mode, tpos)
    rows, counts = slip_start_rows(mode)
    slips = [e for e in events if e.kind == "stick→slip"]
    assert rows.tolist() == sorted({e.step for e in slips})
    assert counts.tolist() == [sum(e.step == k for e in slips) for k in rows.tolist()]
    for k0 in (0, 1, 517, n - 1, n):
        for target, kinds in ((OPEN, ("contact lost",)), (OFF, (SLID_OFF,))):
            steps = [e.step for e in events if e.kind in kinds and e.step >= k0]
            assert first_entry(mode, target, k0) == (min(steps) if steps else -1)
        expected = max((e.distance for e in episodes if e.t_start >= t[min(k0, n - 1)] - 1e-9 and k0 < n),
                       default=0.0)
        got = largest_single_slide(mode, tpos, k0)
        assert np.float64(got).tobytes() == np.float64(expected).tobytes()
    first = episodes[0]                                               # its slide NaN: the whole max is NaN
    tpos[int(round(first.t_start / 0.05)), first.contact, 0] = np.nan
    assert np.isnan(slip_episodes(t, mode, tpos)[0].distance) and np.isnan(largest_single_slide(mode, tpos, 0))
