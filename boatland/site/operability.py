r"""Operability of a turbine's landings over a site's weather: availability per landing, with the best landing
chosen per sea state, per month and per year, and weather windows (Grøtting 2015 §4.1, Tables 4.2–4.7: the
availability of access from a 1957–2010 NORA10 hindcast, all year and per winter).

For a vessel (a scenario) and landings at compass bearings φ_1 … φ_L, each sea state i of weight w_i (its
occurrence, or one step of a hindcast) gets a margin M_il = H_lim,il / H_s,i at each landing
(:func:`boatland.site.flows.sea_limits`). Then

.. math:: A_l = \sum_i w_i [M_{il} \ge 1], \qquad A_{best} = \sum_i w_i [\max_l M_{il} \ge 1] \ge \max_l A_l ,

the skipper choosing per sea state the landing with the largest margin (:attr:`Operability.best_landing`); the
gain of choosing is :math:`A_{best} - \max_l A_l`. A hindcast gives the same per calendar month and year and
the weather windows of the best choice and of each landing (:mod:`boatland.site.windows`). Several vessels or
push settings over the same weather: one :class:`Operability` each, side by side (:func:`side_by_side`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.statistics import risk_in_words
from boatland.site.flows import sea_limits
from boatland.site.limits import SeaLimits
from boatland.site.tables import LimitsTable, table_limits
from boatland.site.weather import FLOWS, Weather
from boatland.site.windows import Persistence, persistence
from boatland.vessel.database import HydroDB

__all__ = ["MONTHS", "Operability", "operability", "side_by_side", "table_operability"]

MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")


@dataclass(frozen=True, eq=False)
class Operability:
    """One vessel's access over a site's weather.

    Attributes
    ----------
    name : str
        The scenario's name.
    weather : Weather
    limits : SeaLimits
        Per sea state and landing.
    window_hours : float or None
        The access window asked for (hindcasts).
    windows : tuple of Persistence
        Per landing, then the best choice (hindcasts with a window; else empty).
    """

    name: str
    weather: Weather
    limits: SeaLimits
    window_hours: float | None = None
    windows: tuple = ()

    @property
    def landings_deg(self) -> np.ndarray:
        return self.limits.landings_deg

    @property
    def best_landing(self) -> np.ndarray:
        """(n,) index of the landing with the largest margin per sea state (the first of equals; a landing outside
        a time-domain table is never the best of one inside)."""
        return np.argmax(np.nan_to_num(self.limits.margin, nan=-np.inf), axis=1)

    @property
    def workable(self) -> np.ndarray:
        """(n, L + 1) bool: each landing, then the best choice."""
        w = self.limits.workable
        return np.concatenate([w, w.any(axis=1, keepdims=True)], axis=1)

    def availability(self, mask=None) -> np.ndarray:
        """(L + 1,) availability of each landing, then of the best choice, over the rows in ``mask`` (NaN: no
        rows)."""
        wt = self.weather.weight if mask is None else np.where(mask, self.weather.weight, 0.0)
        total = wt.sum()
        if total <= 0:
            return np.full(self.landings_deg.size + 1, math.nan)
        return (wt[:, None] * self.workable).sum(axis=0) / total

    @property
    def not_covered(self) -> float:
        """Share of the time whose sea state lies outside a time-domain table at every landing (0 for the
        screening, which judges every sea state)."""
        cov = self.limits.covered
        if cov is None:
            return 0.0
        return float(self.weather.weight[~cov.any(axis=1)].sum())

    @property
    def gain(self) -> float:
        """A_best − max_l A_l: what choosing the landing per sea state adds."""
        a = self.availability()
        return float(a[-1] - a[:-1].max())

    def monthly(self) -> np.ndarray:
        """(12, L + 1) availability per calendar month (NaN: a month the hindcast lacks; all NaN: a scatter)."""
        months = self.weather.months
        if months is None:
            return np.full((12, self.landings_deg.size + 1), math.nan)
        return np.stack([self.availability(months == m) for m in range(1, 13)])

    def yearly(self) -> dict:
        """{year: (L + 1,) availability} of a hindcast (empty for a scatter)."""
        years = self.weather.years
        if years is None:
            return {}
        return {int(y): self.availability(years == y) for y in np.unique(years)}

    def window_monthly(self) -> np.ndarray:
        """(12, L + 1) probability of a window per calendar month of its start (NaN without windows)."""
        if not self.windows:
            return np.full((12, self.landings_deg.size + 1), math.nan)
        months = self.weather.months
        return np.array([[p.probability(months == m) for p in self.windows] for m in range(1, 13)])

    def headers(self) -> list[str]:
        """Column names: each landing, then ``best``."""
        return [f"landing {b:g}°" for b in self.landings_deg] + ["best"]

    def as_dict(self) -> dict:
        """Everything for ``--json``."""
        lim = self.limits
        a = self.availability()
        judged = np.isfinite(lim.margin).any(axis=1)       # a sea state outside a table at every landing: none best
        out = {
            "scenario": self.name, "weather": self.weather.source, "sea_states": self.weather.n,
            "hindcast": self.weather.time is not None, "step_hours": self.weather.step_hours,
            "two_spectra_sea_states": int(lim.two_spectra.sum()),
            "landings_deg": lim.landings_deg.tolist(), "accept": lim.accept, "access_s": lim.access_duration,
            "statistics": lim.statistics, "method": lim.method, "mu": lim.mu, "thrust": lim.thrust,
            "limits": lim.source, "not_covered": self.not_covered,
            "availability": dict(zip(self.headers(), a.tolist())), "gain_of_choosing": self.gain,
            "best_landing_share": [float(self.weather.weight[(self.best_landing == j) & judged].sum())
                                   for j in range(lim.landings_deg.size)],
            "not_used": [c for what, cols in FLOWS.items() if getattr(self.weather, what) is not None
                         for c in cols] if lim.covered is not None else [],
        }
        if self.weather.time is not None:
            mon = self.monthly()
            out["monthly"] = {MONTHS[m]: dict(zip(self.headers(), mon[m].tolist())) for m in range(12)
                              if not np.all(np.isnan(mon[m]))}
            out["yearly"] = {str(y): dict(zip(self.headers(), v.tolist())) for y, v in self.yearly().items()}
        if self.windows:
            wm = self.window_monthly()
            out["window"] = {
                "hours": self.window_hours,
                "probability": dict(zip(self.headers(), [p.probability() for p in self.windows])),
                "monthly": {MONTHS[m]: dict(zip(self.headers(), wm[m].tolist())) for m in range(12)
                            if not np.all(np.isnan(wm[m]))},
                "wait_hours_median_p90": dict(zip(self.headers(), [list(p.wait_quantiles()) for p in self.windows])),
                "censored": dict(zip(self.headers(), [p.censored() for p in self.windows])),
            }
        return out

    def text(self) -> str:
        """The tables a planner reads: availability per landing and best, per month (hindcast), windows."""
        lim = self.limits
        head = self.headers()
        lines = [f"{self.name} over {self.weather.describe()}",
                 f"  limits: {lim.source}",
                 f"  μ = {lim.mu:g}, F_b = {lim.thrust / 1e3:g} kN, accepted risk {risk_in_words(lim.accept, lim.access_duration)}"
                 + (f", {lim.statistics}, {lim.method} hinge" if lim.covered is None else "")
                 + (f"; {int(lim.two_spectra.sum()):,} sea states judged as wind sea + swell" if lim.two_spectra.any()
                    else "")]
        if lim.covered is not None:
            lines.append(f"  {100 * self.not_covered:.1f} % of the time outside the table (counted as not workable)"
                         + ("; the total sea judged (the table is for one spectrum)" if self.weather.parts else "")
                         + "".join(f"; the weather's {what} not used (the table is its campaign's)"
                                   for what in FLOWS if getattr(self.weather, what) is not None))
        width = max(12, *(len(h) + 2 for h in head))
        row = "  {:<10}" + "".join(f"{{:>{width}}}" for _ in head)
        lines.append(row.format("", *head))
        pct = [f"{100 * v:.1f} %" for v in self.availability()]
        lines.append(row.format("all", *pct))
        if self.weather.time is not None:
            for m, v in enumerate(self.monthly()):
                if not np.all(np.isnan(v)):
                    lines.append(row.format(MONTHS[m], *[f"{100 * x:.1f} %" for x in v]))
            years = self.yearly()
            if len(years) > 1:
                for y, v in years.items():
                    lines.append(row.format(str(y), *[f"{100 * x:.1f} %" for x in v]))
        lines.append(f"  choosing the landing per sea state adds {100 * self.gain:.1f} points over the best single "
                     "landing")
        if self.windows:
            lines.append(f"  a {self.window_hours:g}-h window (transfer out, work, transfer back; workable throughout):")
            lines.append(row.format("P(window)", *[f"{100 * p.probability():.1f} %" for p in self.windows]))
            med = [p.wait_quantiles((0.5,))[0] for p in self.windows]
            p90 = [p.wait_quantiles((0.9,))[0] for p in self.windows]
            lines.append(row.format("wait 50 %", *[_hours(x) for x in med]))
            lines.append(row.format("wait 90 %", *[_hours(x) for x in p90]))
        return "\n".join(lines)


def _hours(h: float) -> str:
    if math.isnan(h):
        return "–"
    if math.isinf(h):
        return "> record"
    return f"{h:.0f} h" if h < 48 else f"{h / 24:.1f} d"


def operability(db: HydroDB, setup: LandingSetup, weather: Weather, landings_deg, *, name: str = "vessel",
                window_hours: float | None = None, **limits_kw) -> Operability:
    """The vessel's access at the landings ``landings_deg`` (compass bearings) over ``weather`` (module
    docstring), judged by the screening; ``window_hours`` the access window of a hindcast; ``limits_kw`` as
    :func:`boatland.site.flows.sea_limits` (``flow_setup`` when the weather has a current or a wind)."""
    return _judged(name, weather, sea_limits(db, setup, weather, landings_deg, **limits_kw), window_hours)


def table_operability(table: LimitsTable, weather: Weather, landings_deg, *, name: str | None = None,
                      window_hours: float | None = None) -> Operability:
    """The same judged by a time-domain limits table (:class:`~boatland.site.tables.LimitsTable`: a rare-event
    campaign's limiting Hs for its incident, e.g. a slide)."""
    return _judged(name or f"{table.name} ({table.incident}, time domain)", weather,
                   table_limits(table, weather, landings_deg), window_hours)


def _judged(name: str, weather: Weather, lim: SeaLimits, window_hours: float | None) -> Operability:
    windows: tuple[Persistence, ...] = ()
    if window_hours is not None and weather.time is not None:
        ok = lim.workable
        cols = [ok[:, j] for j in range(ok.shape[1])] + [ok.any(axis=1)]
        windows = tuple(persistence(c, weather.step_hours, window_hours) for c in cols)
    return Operability(name=name, weather=weather, limits=lim, window_hours=window_hours, windows=windows)


def side_by_side(results: list[Operability]) -> str:
    """Several vessels / settings over the same weather: one row each — availability of each landing and of
    the best choice, the gain of choosing, and the window probability and median wait of the best choice."""
    head = results[0].headers()
    cols = head + ["gain"] + (["P(window)", "wait 50 %"] if results[0].windows else [])
    width = max(12, *(len(h) + 2 for h in cols))
    name_w = max(10, *(len(r.name) + 2 for r in results))
    fmt = f"{{:<{name_w}}}" + "".join(f"{{:>{width}}}" for _ in cols)
    lines = [fmt.format("scenario", *cols)]
    for r in results:
        vals = [f"{100 * v:.1f} %" for v in r.availability()] + [f"+{100 * r.gain:.1f}"]
        if r.windows:
            vals += [f"{100 * r.windows[-1].probability():.1f} %", _hours(r.windows[-1].wait_quantiles((0.5,))[0])]
        lines.append(fmt.format(r.name, *vals))
    return "\n".join(lines)
