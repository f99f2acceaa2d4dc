r"""The risk of one sea state in words: the frequency-domain screening's probability per access of a slip
onset and of roll beyond a limit, against the accepted risk — what ``boatland run`` prints under its verdict,
so that one trial's luck ("HELD this time") is read beside the odds of the sea it was run in.

The screening (:func:`boatland.freqdomain.screening.sea_response`; Grøtting 2015 §3.2.1, §3.4 with Rice's
up-crossings, :data:`~boatland.freqdomain.statistics.DEFAULT_STATISTICS`) predicts **onsets**: the first
time a contact's friction margin or the roll angle is exceeded,

.. math:: P_{acc} = 1 - \exp\Big(-t_{acc} \sum_i \nu_i\Big), \qquad
          \nu_i = \frac{1}{2\pi}\sqrt{\frac{m_{2,i}}{m_{0,i}}}\; e^{-a_i^2 / 2 m_{0,i}}

(each margin's up-crossing rate of its capacity :math:`a_i`; roll at ±θ). A slide of some distance starts
with an onset, so the onset probability bounds every slip-distance or slide incident from above; how much
lower they are only the time domain tells (a Monte Carlo or rare-event campaign, ``boatland campaign``).

Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc thesis,
NTNU; Rice, S. O. (1945), Mathematical analysis of random noise, *Bell Syst. Tech. J.* 24, 46–156.
"""

from __future__ import annotations

from dataclasses import dataclass

from boatland.errors import BoatlandInputError
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import SeaResponse, sea_response
from boatland.freqdomain.statistics import (ACCESS_DURATION, DEFAULT_STATISTICS, accept_probability, access_text,
                                            one_in, probability_text, risk_in_words)

__all__ = ["SeaRisk", "sea_risk"]


@dataclass(frozen=True, eq=False)
class SeaRisk:
    """The screening's probabilities per access in one sea, and the accepted risk.

    Attributes
    ----------
    accept : float
        Accepted probability of an incident per access.
    access : float
        The access [s] (Grøtting 2015: 30 min).
    response : SeaResponse
        The screening in this sea (its statistics, spectral moments, rates).
    """

    accept: float
    access: float
    response: SeaResponse

    @property
    def p_onset(self) -> float:
        """P(slip onset within the access)."""
        return self.response.p_slip()

    def p_roll_above(self, limit_deg: float) -> float:
        """P(roll beyond ±limit within the access)."""
        return self.response.p_roll_above(limit_deg)

    def accepted_text(self) -> str:
        """"1 access in 840 (1.19e-3 per 30-min access, Grøtting 2015 best estimate)"."""
        return risk_in_words(self.accept, self.access)

    def odds_text(self, p: float, what: str) -> str:
        """"a slip onset is expected in 1 of 200 such 30-min accesses (5e-3) — above the accepted 1 access in 840
        (1.19e-3 per 30-min access, Grøtting 2015 best estimate)"."""
        if p <= 0.0:
            return f"{what}: not expected in this sea (screening)"
        side = "above" if p > self.accept else "within"
        return (f"{what} is expected in {one_in(p).replace('1 in ', '1 of ')} such {access_text(self.access)}es "
                f"({probability_text(p)}) — {side} the accepted {self.accepted_text()}")

    def of(self, incident) -> tuple[float | None, str]:
        """One incident definition's probability per access and what it is — ``"estimate"`` (the slip onset,
        roll beyond a limit), ``"upper bound"`` (a slip or slide incident: it starts with an onset) or
        ``"time domain only"`` (p None) — by the definition's ``screening`` attribute
        (:class:`boatland.trial.incidents.Incident`)."""
        kind = getattr(incident, "screening", None)
        if kind == "onset":
            return self.p_onset, "estimate"
        if kind == "bounded":
            return self.p_onset, "upper bound"
        if kind == "roll":
            return self.p_roll_above(incident.limit_deg), "estimate"
        return None, "time domain only"

    def rows(self, incidents) -> list[tuple[str, float | None, str, bool | None]]:
        """``(name, p, basis, above the accepted risk)`` of the first slip and each definition; "above" is
        None where the figure decides nothing (time domain only, or a bound above the accepted risk)."""
        out = []
        for d in (_FIRST_SLIP, *incidents):
            p, basis = self.of(d)
            above = None if p is None or (basis == "upper bound" and p > self.accept) else p > self.accept
            out.append((d.name, p, basis, above))
        return out

    def headline(self, outcome: str) -> str:
        """"HELD this time; a slip onset is expected in …" — a trial's ``outcome`` beside this sea's odds."""
        return f"{outcome.upper()} this time; " + self.odds_text(self.p_onset, "a slip onset")

    def lines(self, incidents, outcome: str) -> list[str]:
        """The headline, then each incident's probability per access (text, indented for a summary)."""
        lines = [f"  {self.headline(outcome)}",
                 f"  per {access_text(self.access)} in this sea (frequency-domain screening, "
                 f"{self.response.statistics.capitalize()}):"]
        for name, p, basis, _ in self.rows(incidents):
            if p is None:
                lines.append(f"    {name:29s} time domain only (boatland campaign)")
                continue
            value = f"{'≤ ' if basis == 'upper bound' else ''}{probability_text(p)} ({one_in(p)})"
            note = ("  the onset bounds it; a campaign tells how much lower" if basis == "upper bound" else
                    f"  {'above' if p > self.accept else 'within'} the accepted {one_in(self.accept)}")
            lines.append(f"    {name:29s} {value:22s}{note}")
        return lines

    def as_dict(self, incidents=(), outcome: str | None = None) -> dict:
        """JSON-able: the accepted risk, the statistics, the onset's probability and each incident's."""
        out = {"accepted": {"p": self.accept, "access_s": self.access, "text": self.accepted_text()},
               "statistics": self.response.statistics, "access_s": self.access, "p_onset": self.p_onset,
               "incidents": {name: {"p": p, "basis": basis, "above_accepted": above}
                             for name, p, basis, above in self.rows(incidents)}}
        if outcome is not None:
            out["headline"] = self.headline(outcome)
        return out


class _Onset:
    """The slip onset as an incident the screening estimates (its name as a campaign counts it)."""

    name = "first slip"
    screening = "onset"


_FIRST_SLIP = _Onset()


def sea_risk(scenario, db, *, setup=None, accept="best", access: float = ACCESS_DURATION,
             statistics: str = DEFAULT_STATISTICS) -> SeaRisk:
    """The screening's view of a scenario's own sea (:func:`~boatland.freqdomain.screening.sea_response`).

    Parameters
    ----------
    scenario, db
        A validated scenario with a landing, a fender, a thrust and a spectral sea, and its database.
    setup : Setup, optional
        ``Setup.of(scenario, db)`` when at hand.
    accept : float or str
        The accepted probability per access, or a preset of Grøtting (2015) Table 2.1 (default "best").
    access : float
        The access [s].

    Raises
    ------
    BoatlandInputError
        No spectral sea (regular waves, a measured record, calm water), or no landing, fender or thrust.
    """
    sea = scenario.sea
    parts = getattr(getattr(sea, "waves", None), "parts", None)
    if not parts:
        raise BoatlandInputError(f"{scenario.source}: the screening needs a spectral sea ([sea] with Hs and Tp)")
    landing = LandingSetup.from_scenario(scenario, db, setup=setup)
    waves = getattr(setup, "waves", None)
    resp = sea_response(db, landing, parts, access_duration=access, statistics=statistics,
                        water_depth=getattr(waves, "water_depth", None))
    return SeaRisk(accept=accept_probability(accept), access=float(access), response=resp)
