"""Events and incidents of a landing trial, extracted from the integrator's per-step contact records.

An *event* is a change of a contact's state between two step starts (modes 0 open, 1 stick, 2 slip):
contact made / lost, stick → slip (a slip event, seed 002 §3.3: the fender starts to slide),
slip → stick. A *slip episode* runs from a stick → slip event to the next re-stick or loss of
contact; its slide is the largest displacement of the fender point, in the contact plane, from where
it was stuck (vertical and horizontal along the plane). A contact that touches and slides before it
first catches is still landing: that slide is not a slip episode.

The *slip distance* of an incident is seed 002's (§4.2, SIMO runs): "the fender point of the vessel
moves more than 10 cm away from its original position" — measured from where the contact first
stuck after it was made (its landing position), so a run of short slides that each stay below the
threshold but creep away from the landing position is an incident too (:func:`landing_offset`).
Incidents: slip distance above a threshold, roll above a limit, loss of contact — each reported with
the time it first happens.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from boatland.contact.fender import OPEN, SLIP, STICK

__all__ = ["Event", "SlipEpisode", "extract_events", "slip_episodes", "landing_offset", "first_exceedance"]

KIND = {(OPEN, STICK): "contact made", (OPEN, SLIP): "contact made", (STICK, OPEN): "contact lost",
        (SLIP, OPEN): "contact lost", (STICK, SLIP): "stick→slip", (SLIP, STICK): "slip→stick"}


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
    for c in range(mode.shape[1]):
        change = np.nonzero(mode[1:, c] != mode[:-1, c])[0] + 1
        for k in change:
            kind = KIND[(int(mode[k - 1, c]), int(mode[k, c]))]
            events.append(Event(float(t[k]), int(k), c, kind, float(needed[k, c]), float(available[k, c])))
    events.sort(key=lambda e: (e.step, e.contact))
    return events


def slip_episodes(t, mode, tpos) -> list[SlipEpisode]:
    """Slip episodes (stick → slip until re-stick or loss of contact) of every contact; ``tpos``
    (n, Nc, 2) the fender points' (vertical, horizontal) position in the contact plane. An episode
    still running at the end is closed there."""
    episodes = []
    mode = np.asarray(mode)
    n = mode.shape[0]
    for c in range(mode.shape[1]):
        starts = np.nonzero((mode[1:, c] == SLIP) & (mode[:-1, c] == STICK))[0] + 1
        for k0 in starts:
            origin = tpos[k0 - 1, c]
            after = np.nonzero(mode[k0:, c] != SLIP)[0]
            k1 = k0 + int(after[0]) if after.size else n - 1
            ended = "end of run" if not after.size else ("re-stick" if mode[k1, c] == STICK else "contact lost")
            d = tpos[k0:k1 + 1, c] - origin
            dist = np.hypot(d[:, 0], d[:, 1])
            j = int(np.argmax(dist))
            episodes.append(SlipEpisode(c, float(t[k0]), float(t[k1]), float(dist[j]), float(d[j, 0]),
                                        float(d[j, 1]), ended))
    episodes.sort(key=lambda e: (e.t_start, e.contact))
    return episodes


def landing_offset(mode, tpos) -> np.ndarray:
    """Distance [m] of each fender point from its landing position, per step: (n, Nc).

    The landing position of a contact is where it first stuck after it was made; it holds until the
    contact is lost (a new landing then has a new one). NaN while the contact is open or has not yet
    caught. This is seed 002's incident slip distance (fender point "more than 10 cm away from its
    original position").
    """
    mode = np.asarray(mode)
    tpos = np.asarray(tpos)
    out = np.full(mode.shape, np.nan)
    nc = mode.shape[1]
    for c in range(nc):
        edges = np.flatnonzero(np.diff(np.r_[0, (mode[:, c] != OPEN).astype(np.int8), 0]))
        for s0, s1 in zip(edges[::2], edges[1::2]):      # contact spells: steps [s0, s1) in touch
            stuck = np.flatnonzero(mode[s0:s1, c] == STICK)
            if stuck.size:
                k0 = s0 + stuck[0]                        # first stick of the spell = the landing position
                d = tpos[k0:s1, c] - tpos[k0, c]
                out[k0:s1, c] = np.hypot(d[:, 0], d[:, 1])
    return out


def first_exceedance(t, values, limit) -> float | None:
    """Time at which |values| first exceeds ``limit`` (None if never)."""
    over = np.nonzero(np.abs(np.asarray(values)) > limit)[0]
    return float(t[over[0]]) if over.size else None
