r"""Incident definitions: what counts as an incident of a landing, each one object with its name, its
scenario key and how it is found in a trial.

A definition is a small frozen record with a ``name`` (the same string in every output — the summary, the
verdict, the run log, a campaign store's column, a report's table) and two detectors on a finished trial
(:class:`~boatland.trial.result.Result`):

- :meth:`Incident.first_time` — the first time in the trial after the settling (what ``boatland run``
  reports);
- :meth:`Incident.in_access` — the first time at or after the start of an access (what a rare-event
  campaign estimates, :mod:`boatland.campaign.isee`).

=========================  ===================================  =============================================
definition                 scenario / campaign ``[incidents]``  counts
=========================  ===================================  =============================================
:class:`FirstSlip`         (always, in campaigns)               the first stick → slip of the fender
:class:`SlipDistance`      ``slip_distance = [0.1, …]`` [m]     a fender point farther than d from where it
                                                                landed (Grøtting 2015 §3.3: 10 cm)
:class:`SlideWithin`       ``slide_within = [{distance = 0.5,   the fender slides more than the distance over
                           window = 120.0}, …]`` [m, s]         the tube within any window of that length (an
                                                                operator's criterion: 0.5 m within 2 min)
:class:`RollAbove`         ``roll_limit_deg = [10.0, …]``       roll beyond the limit (Grøtting 2015 §4.1.2)
:class:`ContactLoss`       (always, with a fender)              a contact opens, or slides off the landing
:class:`ContactLossLonger` ``contact_loss_duration = [0.5, …]``  a contact open (or off the landing) for
                           [s]                                  longer than the duration: a bounce, not a
                                                                graze
:class:`SlidOff`           (always, with a fender)              the fender slides off the end of a tube
=========================  ===================================  =============================================

A new definition is a class here with its entry in :data:`FROM_KEY` (and its key in the scenario schema,
:mod:`boatland.scenario.schema`): every trial, campaign, store and report then carries it.
:func:`parse_incident` turns a stored name back into its definition.

References: Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*,
MSc thesis, NTNU — §3.3 (the incident slip distance), §4.1.2 (roll limits).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from boatland.contact.fender import OFF, OPEN, SLIP, STICK
from boatland.trial.events import SLID_OFF, first_entry, first_exceedance, windowed_slide

__all__ = ["FROM_KEY", "IncidentWatch", "ContactLoss", "ContactLossLonger", "FirstSlip", "Incident", "RollAbove", "SlidOff",
           "SlideWithin",
           "SlipDistance", "campaign_incidents", "parse_incident", "trial_incidents"]


class Incident:
    """One incident definition (subclasses are frozen dataclasses): ``name`` and the two detectors.

    A definition with a parameter (a threshold from the ``[incidents]`` table) has one field, the ``key``
    of its table entry and a ``template`` that formats the parameter into its name."""

    #: The ``[incidents]`` key whose values make definitions of this kind (None: not set by a key).
    key: ClassVar[str | None] = None
    #: Its name, with ``{:g}`` for the parameter (a definition without one: the name itself).
    template: ClassVar[str] = ""
    #: What the frequency-domain screening says of it: ``"onset"`` (it is the slip onset the screening
    #: predicts), ``"bounded"`` (it starts with an onset: the onset's probability bounds it from above),
    #: ``"roll"`` (the screening's roll beyond a limit), None (the time domain only).
    screening: ClassVar[str | None] = None

    @property
    def name(self) -> str:
        fields = list(self.__dict__.values())
        return self.template.format(*fields) if fields else self.template

    @classmethod
    def from_value(cls, value) -> "Incident":
        """The definition of one ``[incidents]`` value of :attr:`key`: a number, or a table's numbers in
        the order of the fields (``(distance, window)``)."""
        return cls(*value) if isinstance(value, (tuple, list)) else cls(value)

    def from_row(self, r, k0: int) -> float | None:
        """First time [s] of the incident in trial ``r`` counted from row ``k0`` on (None: not from there):
        a definition that has it gets :meth:`first_time` (from the settling) and :meth:`in_access` (from the
        access's first row) from it."""
        raise NotImplementedError  # pragma: no cover

    def first_time(self, r) -> float | None:
        """First time [s] of the incident in trial ``r`` after its settling (None: it did not happen)."""
        return self.from_row(r, r.settle_row)

    def in_access(self, r, t_access: float) -> float | None:
        """First time [s] of the incident at or after ``t_access`` (None: not in the access)."""
        return self.from_row(r, int(np.searchsorted(r.t, t_access - 1e-9)))

    def __str__(self) -> str:
        return self.name


@dataclass(frozen=True)
class FirstSlip(Incident):
    """The first stick → slip of the fender after the settling (any contact, any distance)."""

    template: ClassVar[str] = "first slip"
    screening: ClassVar[str | None] = "onset"

    def first_time(self, r) -> float | None:
        rows, _ = r.slip_rows
        after = rows[rows >= r.settle_row]
        return float(r.t[after[0]]) if after.size else None

    def in_access(self, r, t_access: float) -> float | None:
        slips = [e.t for e in r.slip_events() if e.t >= t_access - 1e-9]
        return slips[0] if slips else None


@dataclass(frozen=True)
class SlipDistance(Incident):
    """A fender point farther than ``distance`` [m] from where it landed after the settling
    (:meth:`boatland.trial.result.Result.landing_offset`; Grøtting 2015's incident slip distance), from the
    first slip on: before it the fender point's offset is the stuck rubber's elastic shear (a soft rubber
    pushed sideways deflects by centimetres), which is not a slip."""

    distance: float
    key: ClassVar[str] = "slip_distance"
    template: ClassVar[str] = "slip > {:g} m"
    screening: ClassVar[str | None] = "bounded"

    def from_row(self, r, k0: int) -> float | None:
        worst = r.worst_offset
        rows, _ = r.slip_rows
        slipped = rows[rows >= r.settle_row]
        if worst is None or not slipped.size:
            return None
        k0 = max(k0, int(slipped[0]))
        return first_exceedance(r.t[k0:], worst[k0:], self.distance) if k0 < r.t.size else None


@dataclass(frozen=True)
class SlideWithin(Incident):
    """The fender slides more than ``distance`` [m] over the tube within ``window`` [s]: one contact's path
    slid within any window of that length after the settling exceeds the distance
    (:func:`boatland.trial.events.windowed_slide`: the slide of the rubber's anchor, not its elastic shear
    while it sticks; back and forth both count).

    The incident operators count: one wind-farm operator's criterion for a slip incident is a slide of
    more than 0.5 m within 2 minutes (``slide_within = [{distance = 0.5, window = 120.0}]``); Grøtting
    (2015, §3.3) counts 10 cm from the landing point (:class:`SlipDistance`). The millimetres of elastic
    shear of a sticking rubber are neither."""

    distance: float
    window: float
    key: ClassVar[str] = "slide_within"
    template: ClassVar[str] = "slide > {:g} m within {:g} s"
    screening: ClassVar[str | None] = "bounded"

    def from_row(self, r, k0: int) -> float | None:
        """Slides in the steps after row ``k0`` (in an access, the window does not reach back before it)."""
        if r.slide is None or not r.mode.shape[1] or k0 >= r.t.size:
            return None
        return first_exceedance(r.t, windowed_slide(r.t, r.slide, k0, self.window), self.distance)


@dataclass(frozen=True)
class RollAbove(Incident):
    """Roll beyond ``limit_deg`` [deg] (either side)."""

    limit_deg: float
    key: ClassVar[str] = "roll_limit_deg"
    template: ClassVar[str] = "roll > {:g}°"
    screening: ClassVar[str | None] = "roll"

    def from_row(self, r, k0: int) -> float | None:
        t = r.t
        return first_exceedance(t[k0:], r.x[k0:, 3], math.radians(self.limit_deg)) if k0 < t.size else None

    def first_time(self, r) -> float | None:
        """Roll counts from the start of the trial (the settling included)."""
        return self.from_row(r, 0)


@dataclass(frozen=True)
class ContactLoss(Incident):
    """A contact opens after the settling, or slides off the landing."""

    template: ClassVar[str] = "contact loss"

    def first_time(self, r) -> float | None:
        if not r.mode.shape[1]:
            return None
        k0 = r.settle_row
        lost = [t for t in (_entry(r, OPEN, k0), _entry(r, OFF, k0)) if t is not None]
        return min(lost) if lost else None

    def in_access(self, r, t_access: float) -> float | None:
        """Contact lost (or slid off) from ``t_access`` on — or before it, if the trial ended there."""
        lost = [e.t for e in r.events if e.kind in ("contact lost", SLID_OFF)]
        after = [x for x in lost if x >= t_access - 1e-9]
        return after[0] if after else (t_access if lost and r.t[-1] < t_access else None)


@dataclass(frozen=True)
class SlidOff(Incident):
    """The fender slid off the end of a tube (the trial ends there)."""

    template: ClassVar[str] = SLID_OFF

    def first_time(self, r) -> float | None:
        return _entry(r, OFF, 0) if r.mode.shape[1] else None

    def in_access(self, r, t_access: float) -> float | None:
        t = self.first_time(r)
        return None if t is None else max(t, t_access)


@dataclass(frozen=True)
class ContactLossLonger(Incident):
    """A contact open, or off the landing, for longer than ``duration`` [s] at a stretch after the settling:
    the fender bounced off the landing. The incident's time is when the stretch passes the duration."""

    duration: float
    key: ClassVar[str] = "contact_loss_duration"
    template: ClassVar[str] = "contact loss > {:g} s"

    def _times(self, r) -> list[float]:
        """Each stretch's time past the duration, every contact, from the settling on (sorted)."""
        t, out = r.t, []
        for c in range(r.mode.shape[1]):
            lost = np.isin(r.mode[r.settle_row:, c], (OPEN, OFF))
            edges = np.diff(np.concatenate([[False], lost, [False]]).astype(np.int8))
            for a, b in zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)):
                k0 = r.settle_row + a
                k = int(np.searchsorted(t, t[k0] + self.duration, side="right"))
                if k < r.settle_row + b:        # still lost at that step (or beyond the record: not yet)
                    out.append(float(t[k]))
        return sorted(out)

    def first_time(self, r) -> float | None:
        times = self._times(r)
        return times[0] if times else None

    def in_access(self, r, t_access: float) -> float | None:
        times = [x for x in self._times(r) if x >= t_access - 1e-9]
        return times[0] if times else None


def _entry(r, mode: int, k_start: int) -> float | None:
    k = first_entry(r.mode, mode, k_start)
    return None if k < 0 else float(r.t[k])


#: ``[incidents]`` key → the definition its values make (one per value).
FROM_KEY = {cls.key: cls for cls in (SlipDistance, SlideWithin, RollAbove, ContactLossLonger)}

#: Names of the definitions without a parameter.
_FIXED = {d.name: d for d in (FirstSlip(), ContactLoss(), SlidOff())}
#: A name with a parameter → its definition: each template with its ``{:g}`` matched.
_PARAMETERISED = tuple((re.compile(re.escape(cls.template).replace(re.escape("{:g}"), r"(\S+)")), cls)
                       for cls in FROM_KEY.values())


def _keyed(incidents: Mapping | object | None) -> list[Incident]:
    """The definitions of an ``[incidents]`` table (a mapping, or the scenario's
    :class:`~boatland.scenario.parts.Incidents`), in the order of :data:`FROM_KEY`; a trial without one
    counts slips over 0.1 m (Grøtting 2015)."""
    if incidents is None:
        return [SlipDistance(0.1)]
    values = incidents if isinstance(incidents, Mapping) else incidents.values
    return [FROM_KEY[key].from_value(v) for key in FROM_KEY for v in values.get(key, ())]


def trial_incidents(incidents, contacts: bool = True) -> tuple[Incident, ...]:
    """What a trial reports (:meth:`boatland.trial.result.Result.incident_times`): each slip distance and
    roll limit, then — with contacts — contact loss and sliding off the landing."""
    fixed = [ContactLoss(), SlidOff()] if contacts else []
    return tuple(_keyed(incidents) + fixed)


def campaign_incidents(incidents, fender: bool = True) -> tuple[Incident, ...]:
    """What a campaign counts per trial (its store's columns): the first slip, each slip distance and roll
    limit, and — with a fender — contact loss (sliding off the landing is one)."""
    return (FirstSlip(), *_keyed(incidents), *((ContactLoss(),) if fender else ()))


def parse_incident(name: str) -> Incident:
    """The definition a name stands for (``"slip > 0.1 m"`` → ``SlipDistance(0.1)``): stores and run logs
    keep names.

    Raises
    ------
    ValueError
        Not the name of a definition.
    """
    if name in _FIXED:
        return _FIXED[name]
    for pattern, cls in _PARAMETERISED:
        m = pattern.fullmatch(name)
        if m:
            try:
                return cls(*(float(g) for g in m.groups()))
            except ValueError:
                break
    raise ValueError(f"{name!r} is not the name of an incident definition")


class IncidentWatch:
    """The first time of each incident definition a trial reports, found as the trial runs, block by block
    (what a run log writes the moment it happens): slip distance (from the first slip on), slide within a
    window, roll; contact loss and sliding off are contact events already. The times equal
    :meth:`boatland.trial.result.Result.incident_times` of the finished trial.

    Parameters
    ----------
    incidents : Incidents or None
        The scenario's ``[incidents]`` (:func:`trial_incidents`).
    settle_row : int
        The trial's settling row (:attr:`boatland.trial.result.Result.settle_row`).
    """

    def __init__(self, incidents, settle_row: int):
        defs = trial_incidents(incidents)
        self.slip = [d for d in defs if isinstance(d, SlipDistance)]
        self.slide = [d for d in defs if isinstance(d, SlideWithin)]
        self.roll = [d for d in defs if isinstance(d, RollAbove)]
        self.k_settle = int(settle_row)
        self.done: set = set()
        self.first_slip: int | None = None         # the row of the first stick → slip after the settling
        self._prev = None                          # the last row's modes (the stick → slip across blocks)
        self._t = np.empty(0)                      # times and each contact's path slid so far, the rows a
        self._path = np.empty((0, 0))              # window may still reach back to
        self._carry = None

    @property
    def pending(self) -> bool:
        return len(self.done) < len(self.slip) + len(self.slide) + len(self.roll)

    def __call__(self, block, offsets) -> list[tuple[float, str]]:
        """``(t, "incident: NAME at t = … s")`` of the definitions first met in ``block`` (a
        :class:`~boatland.trial.sink.StepBlock`); ``offsets`` (n, Nc) its landing offsets [m]
        (:func:`boatland.trial.events.track_landing`)."""
        t = np.asarray(block.t)
        k0 = int(block.k0)
        mode = np.asarray(block.mode)
        ks = max(self.k_settle - k0, 0)             # the block's first row after the settling
        if self.first_slip is None and mode.shape[1]:
            prev = np.vstack([self._prev if self._prev is not None else mode[:1], mode])
            onset = np.flatnonzero(((prev[1:] == SLIP) & (prev[:-1] == STICK)).any(axis=1))
            onset = onset[onset >= ks]
            if onset.size:
                self.first_slip = k0 + int(onset[0])
        if mode.shape[0]:
            self._prev = mode[-1:].copy()
        out = []
        if self.slip and self.first_slip is not None and mode.shape[1]:
            a = max(self.first_slip - k0, 0)
            worst = np.fmax.reduce(np.asarray(offsets)[a:], axis=1) if a < t.size else np.empty(0)
            for d in self.slip:
                if d.name not in self.done and (k := np.flatnonzero(worst > d.distance)).size:
                    self.done.add(d.name)
                    out.append((float(t[a + k[0]]), d.name))
        if self.slide and block.slide is not None and mode.shape[1]:
            out += self._slides(block, t, k0)
        for d in self.roll:
            if d.name not in self.done and (k := np.flatnonzero(np.abs(block.x[:, 3]) > math.radians(d.limit_deg))).size:
                self.done.add(d.name)
                out.append((float(t[k[0]]), d.name))
        return [(ti, f"incident: {name} at t = {ti:.2f} s") for ti, name in sorted(out)]

    def _slides(self, block, t, k0: int) -> list[tuple[float, str]]:
        """:class:`SlideWithin` over the rows so far (:func:`boatland.trial.events.windowed_slide`'s sums)."""
        step = np.hypot(block.slide[..., 0], block.slide[..., 1])
        step = np.where((k0 + np.arange(t.size) > self.k_settle)[:, None], step, 0.0)
        carry = self._carry if self._carry is not None else np.zeros(step.shape[1])
        path = carry + np.cumsum(step, axis=0)
        self._carry = path[-1].copy() if t.size else carry
        # the rows a window may reach back to, and this block (the path is 0 up to the settling)
        ts = np.concatenate([self._t, t]) if len(self._t) else t
        ps = np.concatenate([self._path, path]) if len(self._path) else path
        out = []
        for d in self.slide:
            if d.name in self.done:
                continue
            lo = np.searchsorted(ts, t - d.window - 1e-9 * max(1.0, d.window))
            w = (path - ps[lo]).max(axis=1)
            if (k := np.flatnonzero(w > d.distance)).size:
                self.done.add(d.name)
                out.append((float(t[k[0]]), d.name))
        reach = max((d.window for d in self.slide), default=0.0)
        keep = ts >= ts[-1] - reach - 1.0 if ts.size else np.zeros(0, bool)
        self._t, self._path = ts[keep], ps[keep]
        return out
