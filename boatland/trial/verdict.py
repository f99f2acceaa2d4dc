"""What a trial's reader wants first: did the fender hold — and the events behind the answer, without
repetition or numerical noise.

- :func:`verdict`: one line per trial — the inputs it judged and ``held`` / ``slipped at t = … s, slid
  … m`` / ``slid off`` / ``lost contact`` / ``rolled`` against the incident thresholds (Grøtting 2015
  §4.2: a slip incident is the fender point more than a threshold from where it landed).
- :func:`merge_events`: the contacts' events, one line for the contacts that change the same way at
  the same step (a symmetric landing's two tubes); settling events (before the thrust is on,
  :attr:`~boatland.trial.result.Result.settled_at`) flagged.
- Rounding to physical resolution (:data:`RESOLUTION`): a reported value is never finer than what the
  model resolves; below it a value is 0 (a symmetric head sea gives sway and roll of 1e-15).

Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc
thesis, NTNU.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from boatland.integrate.cummins import OUTCOME_STATUSES
from boatland.trial.events import SLID_OFF, Event
from boatland.trial.incidents import ContactLoss, RollAbove, SlideWithin, SlipDistance, parse_incident
from boatland.scenario.inputs import inputs_text

__all__ = ["Verdict", "verdict", "MergedEvent", "merge_events", "RESOLUTION", "rounded", "fmt_force", "fmt_length",
           "fmt_angle", "fmt_time"]

#: Resolution of reported values by unit: the JSON output keeps this many digits, values below half of
#: it are 0 (text output is coarser: forces 0.1 kN, angles 0.01°, lengths 1 mm, times 0.01 s).
RESOLUTION = {"N": 1.0, "m": 1e-4, "deg": 1e-3, "s": 1e-3, "1": 1e-4}


def rounded(value, unit: str):
    """``value`` rounded to :data:`RESOLUTION` [unit] (None and non-finite values pass through)."""
    if value is None or isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        return value
    res = RESOLUTION[unit]
    digits = max(0, -math.floor(math.log10(res)))
    out = round(round(value / res) * res, digits)
    return 0.0 if out == 0 else out


def fmt_force(f: float | None) -> str:
    """[N] → "12.3 kN" (0.1 kN resolution)."""
    return "–" if f is None else f"{_zero(f / 1e3, 0.05):.1f} kN"


def fmt_length(x: float | None) -> str:
    """[m] → "0.123 m" (1 mm resolution)."""
    return "–" if x is None else f"{_zero(x, 5e-4):.3f} m"


def fmt_angle(deg: float | None) -> str:
    """[deg] → "1.23°" (0.01° resolution)."""
    return "–" if deg is None else f"{_zero(deg, 5e-3):.2f}°"


def fmt_time(t: float | None) -> str:
    """[s] → "t = 12.35 s"."""
    return "–" if t is None else f"t = {t:.2f} s"


def _zero(v: float, floor: float) -> float:
    return 0.0 if abs(v) < floor else v


# --------------------------------------------------------------------------------------------- events
@dataclass(frozen=True)
class MergedEvent:
    """The contacts that changed state the same way at the same step, as one event.

    Attributes
    ----------
    t : float
        Time [s].
    step : int
    kind : str
        "contact made", "contact lost", "stick→slip", "slip→stick", "slid off the landing".
    contacts : tuple of int
    needed, available : tuple of float
        Per contact (same order): the force that would have held it stuck and the friction available [N].
    settling : bool
        Before :attr:`Result.settled_at` (the thrust is still being ramped in; not a slip of the landing).
    """

    t: float
    step: int
    kind: str
    contacts: tuple[int, ...]
    needed: tuple[float, ...]
    available: tuple[float, ...]
    settling: bool

    def who(self) -> str:
        return ("contact " if len(self.contacts) == 1 else "contacts ") + "+".join(map(str, self.contacts))

    def text(self) -> str:
        extra = ""
        if self.kind == "stick→slip":
            fmt = fmt_force
            if [fmt_force(v) for v in self.needed] == [fmt_force(v) for v in self.available]:
                fmt = lambda f: f"{f / 1e3:.2f} kN"     # noqa: E731 - equal at 0.1 kN: show what tipped it
            need = _joined(fmt(v) for v in self.needed)
            have = _joined(fmt(v) for v in self.available)
            extra = f": needed {need} > available {have}"
        return f"t = {self.t:.2f} s, {self.who()}: {self.kind}{extra}" + (" (settling)" if self.settling else "")

    def as_dict(self) -> dict:
        return {"t": rounded(self.t, "s"), "kind": self.kind, "contacts": list(self.contacts),
                "needed": [rounded(v, "N") for v in self.needed],
                "available": [rounded(v, "N") for v in self.available], "settling": self.settling}


def _joined(texts) -> str:
    """"18.3 kN" when all are equal, else "18.3 / 18.1 kN" (per contact)."""
    texts = list(texts)
    if len(set(texts)) == 1:
        return texts[0]
    unit = texts[0].split()[-1]
    return " / ".join(t.split()[0] for t in texts) + f" {unit}"


def merge_events(events: list[Event], settled_at: float = 0.0) -> list[MergedEvent]:
    """Events of all contacts with the same step and kind merged into one (time order kept).

    Parameters
    ----------
    events : list of Event
        :attr:`Result.events` (sorted by step, then contact).
    settled_at : float
        Events before it [s] are flagged ``settling``.
    """
    out: list[MergedEvent] = []
    groups: dict[tuple[int, str], list[Event]] = {}
    order: list[tuple[int, str]] = []
    for e in events:
        key = (e.step, e.kind)
        if key not in groups:
            groups[key] = []
            order.append(key)
        groups[key].append(e)
    for key in order:
        g = groups[key]
        out.append(MergedEvent(t=g[0].t, step=g[0].step, kind=g[0].kind, contacts=tuple(e.contact for e in g),
                               needed=tuple(e.needed for e in g), available=tuple(e.available for e in g),
                               settling=_settling(g[0], settled_at)))
    return out


def _settling(e: Event, settled_at: float) -> bool:
    """Before the landing settled; the re-stick or contact that ends the settling at ``settled_at`` too
    (a stick → slip there is the first slip of the waves, as :meth:`Result.slip_events` counts it)."""
    if e.kind == "stick→slip":
        return e.t < settled_at - 1e-9
    return e.t <= settled_at + 1e-9


# --------------------------------------------------------------------------------------------- verdict
@dataclass(frozen=True)
class Verdict:
    """The answer to "did the fender hold?" for one trial.

    Attributes
    ----------
    outcome : str
        ``"held"``, ``"slipped"`` (a slip incident: past a slip-distance threshold, or a slide within a window), ``"slid off"`` (the landing),
        ``"lost contact"``, ``"rolled"`` (past the smallest roll limit, the fender held) or ``"failed"``
        (the integration stopped: NaN or a runaway).
    headline : str
        "HELD …" / "SLIPPED at t = … s, slid … m (…)" and the like; ``slid`` is the largest distance of a
        fender point from where it landed (the incident distance).
    inputs : dict
        :func:`boatland.scenario.inputs.trial_inputs` of the trial (empty if unknown).
    t : float or None
        When it happened [s]: the start of the slide that crossed the threshold, the slide off, the loss
        of contact, the roll exceedance; None for "held".
    incidents : dict
        Every incident definition → its first time [s] or None.
    """

    outcome: str
    headline: str
    inputs: dict
    t: float | None
    incidents: dict

    @property
    def held(self) -> bool:
        return self.outcome == "held"

    def text(self) -> str:
        """The verdict line: HEADLINE — scenario: inputs."""
        name = self.inputs.get("scenario", "trial")
        what = inputs_text(self.inputs)
        return f"{self.headline} — {name}: {what}" if what else f"{self.headline} — {name}"

    def as_dict(self) -> dict:
        return {"outcome": self.outcome, "held": self.held, "t": rounded(self.t, "s"), "text": self.text(),
                "headline": self.headline}


def verdict(result, summary: dict | None = None) -> Verdict:
    """The verdict of a :class:`~boatland.trial.result.Result` against its incident thresholds
    (``summary``: its :meth:`~boatland.trial.result.Result.summary` when the caller has it)."""
    inputs = dict(result.provenance.get("inputs", {}))
    s = summary if summary is not None else result.summary()
    inc = s["incidents"]
    after = result.settled_at - 1e-9
    if result.status not in OUTCOME_STATUSES:
        return Verdict("failed", f"FAILED: the integration stopped at {fmt_time(float(result.t[-1]))} "
                                 f"({result.message})", inputs, float(result.t[-1]), inc)
    kinds = {k: parse_incident(k) for k in inc}
    slip_names = [k for k, d in kinds.items() if isinstance(d, (SlipDistance, SlideWithin))]
    roll_names = sorted((k for k, d in kinds.items() if isinstance(d, RollAbove)), key=lambda k: kinds[k].limit_deg)
    loss = ContactLoss().name
    slid = s["max_slip_distance"]
    exposure = float(result.t[-1]) - result.settled_at
    others = []

    def also(skip):   # the other kinds of incident (the other slip thresholds are implied)
        rest = [f"{k} at {fmt_time(v)}" for k, v in inc.items()
                if v is not None and k not in skip and k not in slip_names]
        return f"; also {', '.join(rest)}" if rest else ""

    if inc.get(SLID_OFF) is not None:
        t = inc[SLID_OFF]
        head = f"SLID OFF the landing at {fmt_time(t)} after sliding {fmt_length(slid)}" + also({SLID_OFF})
        return Verdict("slid off", head, inputs, t, inc)
    crossed = sorted((k for k in slip_names if inc[k] is not None), key=lambda k: inc[k])
    if crossed:
        first = crossed[0]                            # the earliest slip incident
        t_cross = inc[first]
        ts = result.t[result.slip_rows[0]]           # the stick → slip events' times
        starts = ts[(ts >= after) & (ts <= t_cross + 1e-9)]
        t = float(starts[-1]) if starts.size else t_cross
        head = f"SLIPPED at {fmt_time(t)}, slid {fmt_length(slid)} ({first} at {fmt_time(t_cross)})" + also({first})
        return Verdict("slipped", head, inputs, t, inc)
    if inc.get(loss) is not None:
        t = inc[loss]
        return Verdict("lost contact", f"LOST CONTACT at {fmt_time(t)}" + also({loss}), inputs, t, inc)
    rolled = [k for k in roll_names if inc[k] is not None]
    if rolled:
        t = inc[rolled[0]]
        return Verdict("rolled", f"ROLLED past {kinds[rolled[0]].limit_deg:g}° at {fmt_time(t)} (the fender held)" + also({rolled[0]}),
                       inputs, t, inc)
    n = s["slip_events"]
    # the slip incidents it was judged against, by name (the larger slip distances are implied by the smallest)
    smallest = min((k for k in slip_names if isinstance(kinds[k], SlipDistance)), key=lambda k: kinds[k].distance,
                   default=None)
    limit = "; ".join(k for k in slip_names if k == smallest or isinstance(kinds[k], SlideWithin)) or None
    bits = [f"for {exposure:.0f} s of waves" if exposure > 0 else "throughout"]
    if n:
        bits.append(f"{n} short slip{'s' if n != 1 else ''}, never more than {fmt_length(slid)} from where it "
                    f"landed" + (f" (incidents: {limit})" if limit else ""))
    elif limit:
        bits.append(f"no slip (incidents: {limit})")
    others.append(", ".join(bits))
    return Verdict("held", "HELD " + "; ".join(others), inputs, None, inc)
