"""Events and incidents of a landing trial, extracted from the integrator's per-step contact records.

An *event* is a change of a contact's state between two step starts (modes 0 open, 1 stick, 2 slip,
3 off the landing): contact made / lost, stick → slip (a slip event, Grøtting 2015 §3.3: the fender
starts to slide), slip → stick, slid off the landing. A *slip episode* runs from a stick → slip
event to the next re-stick or loss of contact; its slide is the largest displacement of the fender,
on the landing, from where it was stuck (vertical and horizontal). A contact that touches and slides
before it first catches is still landing: that slide is not a slip episode.

The *slip distance* of an incident is Grøtting's (2015, §4.2, SIMO runs): "the fender point of the
vessel moves more than 10 cm away from its original position" — measured from where the contact
first stuck in the trial (its landing position), so a run of short slides that each stay below the
threshold but creep away from the landing position is an incident too, and so is a fender that
bounces off and lands again elsewhere (:func:`landing_offset`). Incidents: slip distance above a
threshold, roll above a limit, loss of contact, the fender slid off the landing — each reported with
the time it first happens.

Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc
thesis, NTNU.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba
import numpy as np

from boatland.contact.fender import OFF, OPEN, SLIP, STICK

__all__ = ["Event", "SlipEpisode", "SLID_OFF", "extract_events", "slip_episodes", "landing_offset", "track_landing",
           "worst_landing_offset", "first_exceedance", "slip_start_rows", "first_entry", "largest_single_slide",
           "windowed_slide"]

SLID_OFF = "slid off the landing"
KIND = {(OPEN, STICK): "contact made", (OPEN, SLIP): "contact made", (STICK, OPEN): "contact lost",
        (SLIP, OPEN): "contact lost", (STICK, SLIP): "stick→slip", (SLIP, STICK): "slip→stick",
        (STICK, OFF): SLID_OFF, (SLIP, OFF): SLID_OFF, (OPEN, OFF): SLID_OFF,
        (OFF, OPEN): "contact lost", (OFF, STICK): "contact made", (OFF, SLIP): "contact made"}


@dataclass(frozen=True)
class Event:
    """One change of a contact's state at step ``step`` (time ``t``)."""

    t: float
    step: int
    contact: int
    kind: str
    needed: float = 0.0      # stick force that would have held the contact [N]
    available: float = 0.0   # friction available μ(|u|) f_n [N]

    def text(self) -> str:
        extra = ""
        if self.kind == "stick→slip":
            extra = f": needed {self.needed / 1e3:.3g} kN > available {self.available / 1e3:.3g} kN"
        return f"t = {self.t:.2f} s, contact {self.contact}: {self.kind}{extra}"


@dataclass(frozen=True)
class SlipEpisode:
    """A slip from its start to re-stick or loss of contact."""

    contact: int
    t_start: float
    t_end: float
    distance: float                      # largest displacement from where it stuck [m]
    vertical: float                      # signed vertical displacement at that moment [m]
    horizontal: float = 0.0              # signed horizontal displacement at that moment [m]
    ended_by: str = field(default="re-stick")


def extract_events(t, mode, needed, available) -> list[Event]:
    """All state changes of every contact, in time order.

    Parameters
    ----------
    t : (n,)
        Step start times [s].
    mode, needed, available : (n, Nc)
        Per-step records of :func:`boatland.integrate.run_cummins`.
    """
    events = []
    mode = np.asarray(mode)
    t, needed, available = np.asarray(t), np.asarray(needed), np.asarray(available)
    for c in range(mode.shape[1]):
        col = mode[:, c]
        change = np.flatnonzero(col[1:] != col[:-1]) + 1
        columns = (t[change], change, col[change - 1], col[change], needed[change, c], available[change, c])
        events += [Event(float(tk), k, c, KIND[(m0, m1)], float(f_need), float(f_av))
                   for tk, k, m0, m1, f_need, f_av in zip(*(a.tolist() for a in columns))]
    events.sort(key=lambda e: (e.step, e.contact))
    return events


def slip_episodes(t, mode, tpos) -> list[SlipEpisode]:
    """Slip episodes (stick → slip until re-stick, loss of contact or sliding off) of every contact;
    ``tpos`` (n, Nc, 2) the fenders' (vertical, horizontal) positions on the landing. An episode still
    running at the end is closed there. One pass over the record per contact (the ends of all slip
    runs are found at once), so the cost is linear in the record whatever the number of episodes."""
    episodes = []
    mode = np.asarray(mode)
    tpos = np.ascontiguousarray(tpos, dtype=float)
    ended_by = {STICK: "re-stick", OPEN: "contact lost", OFF: "slid off the landing"}
    for c in range(mode.shape[1]):
        m = mode[:, c]
        starts, k1, closed = _slip_runs(m)
        if not starts.size:
            continue
        dist, dv, dh = _largest_slides(tpos, c, starts, k1)
        why = [ended_by[int(x)] if ok else "end of run" for x, ok in zip(m[k1].tolist(), closed.tolist())]
        episodes += [SlipEpisode(c, float(ts), float(te), di, v, h, e) for ts, te, di, v, h, e in
                     zip(t[starts].tolist(), t[k1].tolist(), dist.tolist(), dv.tolist(), dh.tolist(), why)]
    episodes.sort(key=lambda e: (e.t_start, e.contact))
    return episodes


def _slip_runs(m):
    """The slip episodes of one contact's mode column ``m`` (n,): their first rows (stick → slip), the rows
    that end them (the first row after the slip run, or the last row while still sliding) and whether
    they ended before the record did."""
    sliding = m == SLIP
    starts = np.flatnonzero(sliding[1:] & (m[:-1] == STICK)) + 1
    ends = np.flatnonzero(sliding[:-1] & ~sliding[1:]) + 1        # first row after each slip run
    j_end = np.searchsorted(ends, starts)
    closed = j_end < ends.size
    k1 = np.full(starts.size, m.shape[0] - 1)
    k1[closed] = ends[j_end[closed]]
    return starts, k1, closed


def largest_single_slide(mode, tpos, k_start: int = 0) -> float:
    """The largest :attr:`SlipEpisode.distance` of the slip episodes that start at or after row ``k_start``
    (0.0 without any), from the records without building the episodes — as ``max`` over
    :func:`slip_episodes` in their order: NaN if the first of them is NaN, else NaN-free."""
    mode = np.asarray(mode)
    tpos = np.ascontiguousarray(tpos, dtype=float)
    rows, contacts, dists = [], [], []
    for c in range(mode.shape[1]):
        starts, k1, _ = _slip_runs(mode[:, c])
        keep = starts >= k_start
        if keep.any():
            rows.append(starts[keep])
            contacts.append(np.full(int(keep.sum()), c))
            dists.append(_largest_slides(tpos, c, starts[keep], k1[keep])[0])
    if not rows:
        return 0.0
    d = np.concatenate(dists)[np.lexsort((np.concatenate(contacts), np.concatenate(rows)))]
    return float(d[0]) if np.isnan(d[0]) else float(np.nanmax(d))


@numba.njit(cache=True)
def slip_start_rows(mode):  # pragma: no cover - compiled
    """The rows of ``mode`` (n, Nc) at which one or more contacts go from stick to slip (the steps of the
    stick → slip events, in order) and how many contacts do: ``(rows, counts)``."""
    n, nc = mode.shape
    rows = np.empty(n, dtype=np.int64)
    counts = np.empty(n, dtype=np.int64)
    m = 0
    for k in range(1, n):
        count = 0
        for c in range(nc):
            if mode[k, c] == SLIP and mode[k - 1, c] == STICK:
                count += 1
        if count:
            rows[m] = k
            counts[m] = count
            m += 1
    return rows[:m].copy(), counts[:m].copy()


@numba.njit(cache=True)
def first_entry(mode, target, k_start):  # pragma: no cover - compiled
    """The first row k ≥ max(``k_start``, 1) at which a contact enters mode ``target`` (``mode[k, c] ==
    target != mode[k − 1, c]``: the step of the first such event, e.g. contact lost for OPEN, slid off for
    OFF); −1 if none."""
    n, nc = mode.shape
    for k in range(max(k_start, 1), n):
        for c in range(nc):
            if mode[k, c] == target and mode[k - 1, c] != target:
                return k
    return -1


@numba.njit(cache=True)
def _largest_slides(tpos, c, starts, ends):  # pragma: no cover - compiled
    """For each slip run [k0, k1] of contact ``c`` (``tpos`` (n, Nc, 2)): the largest displacement from where
    it stuck (row k0 − 1) and its (vertical, horizontal) parts at that row — the first row of the largest
    (NaN: the first NaN), as ``np.argmax`` of ``np.hypot``."""
    m = starts.size
    dist, dv, dh = np.empty(m), np.empty(m), np.empty(m)
    for e in range(m):
        k0, k1 = starts[e], ends[e]
        r0, r1 = tpos[k0 - 1, c, 0], tpos[k0 - 1, c, 1]
        best, kb = -np.inf, k0
        for k in range(k0, k1 + 1):
            v = math.hypot(tpos[k, c, 0] - r0, tpos[k, c, 1] - r1)
            if np.isnan(v):
                kb = k
                break
            if v > best:
                best, kb = v, k
        dist[e] = math.hypot(tpos[kb, c, 0] - r0, tpos[kb, c, 1] - r1)
        dv[e] = tpos[kb, c, 0] - r0
        dh[e] = tpos[kb, c, 1] - r1
    return dist, dv, dh


@numba.njit(cache=True)
def column_abs_max(x):  # pragma: no cover - compiled
    """Largest |x| of each column of ``x`` (n, m), NaN where the column has a NaN: ``np.max(np.abs(x), axis=0)``
    in one pass without the temporary (m zeros for n = 0)."""
    n, m = x.shape
    out = np.zeros(m)
    nan = np.zeros(m, dtype=np.bool_)
    for k in range(n):
        for j in range(m):
            v = abs(x[k, j])
            if v > out[j]:
                out[j] = v
            elif v != v:
                nan[j] = True
    for j in range(m):
        if nan[j]:
            out[j] = np.nan
    return out


@numba.njit(cache=True)
def all_touching_fraction(mode):  # pragma: no cover - compiled
    """Fraction of the rows of ``mode`` (n, Nc) in which every contact touches (mode > 0):
    ``(mode > 0).all(axis=1).mean()`` (NaN for n = 0)."""
    n, nc = mode.shape
    count = 0
    for k in range(n):
        ok = True
        for c in range(nc):
            if mode[k, c] <= 0:
                ok = False
                break
        if ok:
            count += 1
    return count / n if n else np.nan


def worst_landing_offset(mode, tpos, k_start: int = 0) -> np.ndarray:
    """Largest :func:`landing_offset` over the contacts at each step (0 where none has landed): (n,) —
    the row maxima of :func:`landing_offset` (NaN as 0) in one compiled pass, without the (n, Nc) offsets."""
    mode = np.asarray(mode)
    if not np.issubdtype(mode.dtype, np.integer):
        mode = mode.astype(np.int64)
    return _worst_offset(mode, np.ascontiguousarray(tpos, dtype=float), int(k_start))


@numba.njit(cache=True)
def _worst_offset(mode, tpos, k_start):  # pragma: no cover - compiled
    """Per row, the largest offset of :func:`track_landing` over the contacts (0 where none has landed)."""
    n, nc = mode.shape
    out = np.zeros(n)
    for c in range(nc):
        a0, a1 = np.nan, np.nan
        for k in range(max(k_start, 0), n):
            m = mode[k, c]
            if np.isnan(a0) and m == STICK:
                a0 = tpos[k, c, 0]
                a1 = tpos[k, c, 1]
            if (m == STICK or m == SLIP) and not np.isnan(a0):
                v = np.hypot(tpos[k, c, 0] - a0, tpos[k, c, 1] - a1)
                if v > out[k]:
                    out[k] = v
    return out


@numba.njit(cache=True)
def track_landing(mode, tpos, anchor, out, k_start):  # pragma: no cover - compiled
    """Landing offsets of a block of rows, carrying the landing positions across blocks: fills ``out``
    (n, Nc) and updates ``anchor`` (Nc, 2) in place (NaN until the contact first sticks at or after row
    ``k_start`` of the block; earlier rows are settling, NaN); returns the largest offset in the block
    (−1: none). See :func:`landing_offset`."""
    n, nc = mode.shape
    worst = -1.0
    for c in range(nc):
        for k in range(n):
            m = mode[k, c]
            if k < k_start:
                out[k, c] = np.nan
                continue
            if np.isnan(anchor[c, 0]) and m == STICK:
                anchor[c, 0] = tpos[k, c, 0]
                anchor[c, 1] = tpos[k, c, 1]
            if (m == STICK or m == SLIP) and not np.isnan(anchor[c, 0]):
                out[k, c] = np.hypot(tpos[k, c, 0] - anchor[c, 0], tpos[k, c, 1] - anchor[c, 1])
                worst = max(worst, out[k, c])
            else:
                out[k, c] = np.nan
    return worst


def landing_offset(mode, tpos, k_start: int = 0) -> np.ndarray:
    """Distance [m] of each fender point from its landing position, per step: (n, Nc).

    The landing position of a contact is where it first stuck at or after row ``k_start`` — the end of
    the settling, when the thrust is on and the waves begin (:attr:`Result.settled_at`); it holds for
    the rest of the trial — through bounces and short losses of contact, so a fender that lands again
    elsewhere has slid by that much. NaN while the contact is open, has not yet caught, or settles.
    This is Grøtting's (2015) incident slip distance (fender point "more than 10 cm away from its
    original position").
    """
    mode = np.ascontiguousarray(mode, dtype=np.int64)
    out = np.empty(mode.shape)
    track_landing(mode, np.ascontiguousarray(tpos, dtype=float), np.full((mode.shape[1], 2), np.nan), out,
                  int(k_start))
    return out


def windowed_slide(t, slide, k_start: int, window: float) -> np.ndarray:
    r"""The largest distance one contact slid over the tube within the last ``window`` seconds, per row:
    (n,), 0 before ``k_start``.

    .. math:: W_k = \max_c \sum_{j:\, t_k - T < t_j \le t_k,\; j > k_0} \lVert s_{j,c} \rVert

    with :math:`s_{j,c}` the slide of contact c over the tube in the step that ends at row j (the rubber's
    anchor of a compliant fender, the contact point of the rigid stick: :attr:`Result.slide`; the elastic
    shear of a stuck rubber is not a slide and does not count), T the window and :math:`k_0` = ``k_start``
    (slides in steps ending at or before it do not count). It is the path slid, not the net displacement: a
    fender that slides 0.3 m down and 0.3 m back up within the window has slid 0.6 m over the tube.
    Prefix sums and a moving window start: O(n · Nc).
    """
    t = np.ascontiguousarray(t, dtype=float)
    if slide is None or np.asarray(slide).shape[1] == 0:
        return np.zeros(t.size)
    return _windowed_slide(t, np.ascontiguousarray(slide, dtype=float), int(max(k_start, 0)), float(window))


@numba.njit(cache=True)
def _windowed_slide(t, slide, k_start, window):  # pragma: no cover - compiled
    n, nc = slide.shape[0], slide.shape[1]
    out = np.zeros(n)
    path = np.zeros(n)                      # the contact's path slid up to each row (from k_start on)
    for c in range(nc):
        acc = 0.0
        for k in range(n):
            if k > k_start:
                acc += math.hypot(slide[k, c, 0], slide[k, c, 1])
            path[k] = acc
        j = 0
        for k in range(k_start, n):
            lo = t[k] - window - 1e-9 * max(1.0, window)
            while t[j] < lo:                 # first row at or after t_k − T: the window's slides end after it
                j += 1
            w = path[k] - path[max(j, k_start)]
            if w > out[k]:
                out[k] = w
    return out


def first_exceedance(t, values, limit) -> float | None:
    """Time at which |values| first exceeds ``limit`` (None if never)."""
    over = np.nonzero(np.abs(np.asarray(values)) > limit)[0]
    return float(t[over[0]]) if over.size else None
