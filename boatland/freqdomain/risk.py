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

    def as_dict(self) -> dict:
        return {"accepted": {"p": self.accept, "access_s": self.access, "text": self.accepted_text()},
                "statistics": self.response.statistics, "p_onset": self.p_onset}


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
