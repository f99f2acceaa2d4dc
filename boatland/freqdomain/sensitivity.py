r"""What moves the limit: one-at-a-time sensitivity of the screening's limiting Hs (Grøtting 2015).

The limiting significant wave height :math:`H_{s,lim}(T_p, \beta)` of the Wu (2014) / Grøtting (2015)
slip screening (:func:`boatland.freqdomain.screening.screening_grid`) is computed at a base — the
scenario's landing with the screening's options — and again with **one input at a time** moved to
each end of a stated range, all others at the base:

.. math:: H_{s,lim}^{f,\pm}(T_p, \beta) = H_{s,lim}(T_p, \beta;\ x_f = x_f^{\pm},\ x_{g \ne f} = x_g^0)

The inputs (:data:`FACTORS`, each with its range and where the range comes from):

- the accepted probability of an incident per access :math:`P_{facc}` (how often the slip margins'
  peaks or up-crossings may exceed their capacities; Grøtting 2015 Table 2.1);
- the bollard push :math:`F_b` and the static friction coefficient :math:`\mu_s` (the slip capacities
  are :math:`\mu n^\top J^0 - d^\top J^0`, so the limit grows with both; Grøtting 2015 §5.1.1);
- the fender's shear stiffness :math:`k_t` (how much of a roll or yaw moment the two contacts take as a
  couple of opposite tangential forces), changed as :func:`~boatland.freqdomain.screening.shear_sweep`
  changes it: the shear damping keeps its ratio of critical;
- the fender's height: the contacts' z in the vessel frame (the tubes are vertical, so the normals, the
  pile and the vessel's position stay; the lever arms of the contact forces change).

A row "all together" puts, per heading, every factor at its limit-raising end (and at its
limit-lowering end) at once. Rows computed elsewhere — e.g. the time domain's limit for a looser incident
definition than the screening's slip onset ("slip > 0.5 m") from an ISEE campaign — join the table as
:class:`ExtraLimit` (``extra_rows``); this module reads no campaign store (the CLI does).

:func:`figure_tornado` draws one tornado per heading: bars from the base limit to each end, factors
sorted by their swing, the base as a vertical line and the Hs 1.5 m the industry quotes for push-on
access (:data:`HS_PUSH_ON`) as a dashed reference.

``docs/sensitivity_tornado.png`` was drawn by::

    boatland campaign scenarios/campaigns/ctv_slide_limits.toml -o ctv_slide_limits.h5
    boatland screen --sensitivity --limits ctv_slide_limits.h5 -o docs/sensitivity_tornado.png

(the packaged ``ctv_landing``: ctv27, push 150 kN, μ_s 0.8, Tp 7 s, headings 180°, 135°, 90°).

References: Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*,
MSc thesis, NTNU; Ferreira González, D. (2023), *Development of a Numerical Approach for the Simulation of
Boatlanding Maneuvers*, dissertation, TU Hamburg; Wu, M. (2014), *Numerical analysis of docking operation
between service vessels and offshore wind turbines*, Ocean Engineering 91 (as cited by Grøtting 2015).
"""

from __future__ import annotations

import dataclasses
import math
import textwrap
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import screening_grid, shear_sweep
from boatland.freqdomain.statistics import (
    ACCEPT_PRESETS,
    ACCESS_DURATION,
    HS_MAX,
    accept_probability,
    probability_text,
)
from boatland.scenario.inputs import heading_name
from boatland.sea.spectra import SpectrumPart
from boatland.vessel.database import HydroDB

__all__ = [
    "DEFAULT_HEADINGS",
    "FACTORS",
    "FACTOR_ALIASES",
    "FACTOR_KEYS",
    "HS_PUSH_ON",
    "HS_PUSH_ON_SOURCE",
    "ExtraLimit",
    "Factor",
    "Sensitivity",
    "SensitivityRow",
    "factors_named",
    "figure_tornado",
    "plot_tornado",
    "sensitivity",
]


@dataclass(frozen=True)
class Factor:
    """One input of the screening and the range it is varied over.

    Attributes
    ----------
    key : str
        Its name on the command line (``--factors``) and in JSON.
    label : str
        What it is, in words.
    low, high : float
        Ends of the range, SI (probability, N, 1, N/m, m); for an ``offset`` factor added to the base.
    offset : bool
        The range is relative to the base value (the fender height: ± m), not absolute.
    source : str
        Where the range comes from (section, table, page), or that it is an assumption.
    short : str
        The source in a few words, for the terminal table.
    """

    key: str
    label: str
    low: float
    high: float
    source: str
    short: str
    offset: bool = False


#: The factors and their ranges, each with its source ("low, high, source").
FACTORS: tuple[Factor, ...] = (
    Factor("accept", "accepted risk", ACCEPT_PRESETS["conservative"], ACCEPT_PRESETS["non-conservative"],
           "Grøtting (2015) §2.3, Table 2.1 (p. 6): accepted probability of a failure during one access, "
           "conservative 0.00002 … non-conservative 0.02681 (best estimate 0.00119); he varies it the same way "
           "in §4.1.3, Table 4.4 (p. 36)",
           "Grøtting 2015 Tab. 2.1"),
    Factor("thrust", "bollard push", 100e3, 300e3,
           "Grøtting (2015) §4.1.1, Table 4.2 and Figures 4.1–4.3 (pp. 32–33): bollard push 100, 200 (his standard "
           "case, Table 4.1 p. 31) and 300 kN; §5.1.1 (p. 51): the availability grows with μ·F_b",
           "Grøtting 2015 §4.1.1"),
    Factor("mu", "friction μ_s", 0.5, 0.9,
           "low: ASSUMPTION, 0.5 for a wet or fouled rubber on steel (Ferreira González 2023 §2.5.1 p. 30: a wet "
           "contact lowers the coefficients, no value given); high: μ_s 0.9 (with "
           "μ_k 0.7), the fender model fitted to the tank landings, Ferreira González (2023) §5.2.3 Table 5.4; "
           "Grøtting (2015) Table 4.1 uses 0.8. The screening predicts the onset of slip, which only μ_s governs "
           "(μ_k does not enter)",
           "low assumed (wet); FG 2023 Tab. 5.4"),
    Factor("shear", "shear stiffness k_t", 0.3e6, 30e6,
           "ASSUMPTION: a decade either side of the only value in the sources, 3000 kN/m per fender (Grøtting "
           "2015 §3.2.2 'Fender modelling', p. 23, after Wu 2014: the fender maker quotes none); the shear "
           "damping keeps its ratio of critical (as boatland screen --shear-sweep)",
           "assumption: 0.1–10 × 3 MN/m"),
    Factor("height", "fender height z", -0.5, 0.5,
           "ctv27's bow fender faces the tubes from its wet deck, 1.4 m (an estimate), to its deck, 2.4 m above "
           "the waterline (scenarios/vessels/ctv27.toml tunnel_height, freeboard; ctv_landing.toml [fender]): "
           "the contact at 1.9 m ± 0.5 m anywhere on that face; for another vessel ± 0.5 m is an assumption",
           "ctv27 fender face 1.4–2.4 m", offset=True),
)

#: The factors' keys, in the order of :data:`FACTORS`.
FACTOR_KEYS = tuple(f.key for f in FACTORS)

#: Relative wave directions of the sensitivity unless told [deg]: head, bow-quartering, beam seas.
DEFAULT_HEADINGS = (180.0, 135.0, 90.0)

#: Hs [m] up to which catamaran work boats are said to do push-on access, and its source.
HS_PUSH_ON = 1.5
HS_PUSH_ON_SOURCE = ("EWEA (2014) in Grøtting (2015) §5.5, p. 55: 'modern catamaran work boats ... able to do "
                     "access in Hs up to 1.5 m' (no Tp, heading or risk attached)")


# --------------------------------------------------------------------------------------- results
@dataclass(frozen=True)
class ExtraLimit:
    """A limit computed elsewhere that joins the table as a row, e.g. the time domain's limiting Hs for an
    incident definition looser than the screening's slip onset.

    Attributes
    ----------
    label : str
        What the limit is (``"slip > 0.5 m (time domain, ISEE)"``); the row's high-end text.
    source : str
        Where it comes from (a store's path and campaign).
    limits : tuple of (float, float)
        (relative heading [deg], limiting Hs [m]) pairs; a mapping is accepted. Headings of the
        sensitivity without a value get NaN.
    key : str
        The row's key (default ``"incident"``).
    short : str
        The source in a few words.
    """

    label: str
    source: str
    limits: tuple = ()
    key: str = "incident"
    short: str = ""

    def __post_init__(self):
        pairs = self.limits.items() if isinstance(self.limits, Mapping) else self.limits
        object.__setattr__(self, "limits", tuple((float(b), float(h)) for b, h in pairs))

    def at(self, beta: float) -> float:
        """The limit at relative heading ``beta`` [deg] (NaN if none)."""
        for b, h in self.limits:
            if abs((b - beta + 180.0) % 360.0 - 180.0) < 1e-6:
                return h
        return math.nan


@dataclass(frozen=True)
class SensitivityRow:
    """One row of the sensitivity: a factor at the ends of its range, the limiting Hs per heading.

    Attributes
    ----------
    factor : str
        Key (:data:`FACTOR_KEYS`, ``"all"`` for all together, or an extra row's key).
    label : str
        The factor in words.
    base_text, low_text, high_text : str
        Its value at the base and at the two ends (``"150 kN"``, ``"100 kN"``, ``"300 kN"``).
    source : str
        Where the range comes from (:attr:`Factor.source`); ``short`` in a few words.
    beta_deg : tuple of float
        Relative wave directions [deg] (180 = head seas).
    base, low, high : tuple of float
        Limiting Hs [m] per heading at the base and with the factor at its low / high end (inf above
        :data:`~boatland.freqdomain.statistics.HS_MAX`, NaN where not known).
    detail : tuple of str
        Per heading, what the row's ends were there (the "all together" row: which end of each factor).
    """

    factor: str
    label: str
    base_text: str
    low_text: str
    high_text: str
    source: str
    short: str
    beta_deg: tuple
    base: tuple
    low: tuple
    high: tuple
    detail: tuple = ()

    @property
    def range_text(self) -> str:
        """``"100 kN – 300 kN"``."""
        return f"{self.low_text} – {self.high_text}"

    def swing(self, j: int) -> float:
        """How far the limit moves at heading ``j`` relative to the base: (max − min)/base of base, low, high."""
        v = [x for x in (self.base[j], self.low[j], self.high[j]) if np.isfinite(x)]
        if not v or not np.isfinite(self.base[j]) or self.base[j] <= 0:
            return math.inf if any(np.isinf(x) for x in (self.low[j], self.high[j])) else 0.0
        if any(np.isinf(x) for x in (self.low[j], self.high[j])):
            return math.inf
        return (max(v) - min(v)) / self.base[j]

    def cell(self, j: int) -> str:
        """``"0.25–0.75 (×0.67–×2.00)"`` at heading ``j``: the limit at the low and high ends, and as multiples
        of the base."""
        def hs(x):
            return "n/a" if math.isnan(x) else (f">{HS_MAX:g}" if math.isinf(x) else f"{x:.2f}")

        def times(x):
            b = self.base[j]
            if math.isnan(x) or not (np.isfinite(b) and b > 0):
                return "n/a"
            return "×∞" if math.isinf(x) else f"×{x / b:.2f}"
        if math.isnan(self.low[j]) and math.isnan(self.high[j]):
            return "–"
        return f"{hs(self.low[j])}–{hs(self.high[j])} ({times(self.low[j])}–{times(self.high[j])})"

    def as_dict(self) -> dict:
        """JSON-able (non-finite numbers as None)."""
        def num(x):
            return float(x) if np.isfinite(x) else None
        return {"factor": self.factor, "label": self.label, "base_value": self.base_text, "low_value": self.low_text,
                "high_value": self.high_text, "range": self.range_text, "source": self.source,
                "source_short": self.short,
                "per_heading": [{"beta_deg": float(b), "base": num(self.base[j]), "low": num(self.low[j]),
                                 "high": num(self.high[j]),
                                 **({"detail": self.detail[j]} if self.detail else {})}
                                for j, b in enumerate(self.beta_deg)]}


@dataclass(frozen=True, eq=False)
class Sensitivity:
    """The rows of :func:`sensitivity` and what they were computed for.

    Attributes
    ----------
    Tp : float
        Peak period [s].
    beta_deg : tuple of float
        Relative wave directions [deg].
    base : tuple of float
        Limiting Hs [m] per heading at the base (= ``boatland screen``'s).
    base_text : str
        The base in words (risk, push, μ_s, k_t, fender z).
    rows : tuple of SensitivityRow
        One per factor and extra row, sorted by their largest swing over the headings (largest first);
        then the "all together" row (``factor == "all"``) when more than one factor was varied.
    accept : float
    statistics, method : str
    access_duration : float
    notes : tuple of str
        What a reader should know: a base value outside its factor's range (the absolute ranges are
        full-scale CTV values; a model-scale landing needs its own :class:`Factor` ranges).
    """

    Tp: float
    beta_deg: tuple
    base: tuple
    base_text: str
    rows: tuple
    accept: float
    statistics: str
    method: str
    access_duration: float = ACCESS_DURATION
    notes: tuple = ()

    @property
    def factor_rows(self) -> tuple:
        """The rows without "all together"."""
        return tuple(r for r in self.rows if r.factor != "all")

    @property
    def together(self) -> SensitivityRow | None:
        """The "all together" row, if any."""
        return next((r for r in self.rows if r.factor == "all"), None)

    def text(self) -> str:
        """The table as aligned text: factor, range, source, then per heading the limits at the low and high
        ends as "low–high (×a–×b)" of the base."""
        heads = [f"{b:g}° {_short_heading(b)}" for b in self.beta_deg]
        width = [max(len("factor"), *(len(r.label) for r in self.rows)),
                 max(len("range"), *(len(r.range_text) for r in self.rows)),
                 max(len("source"), *(len(r.short) for r in self.rows))]
        cells = [[r.cell(j) for j in range(len(self.beta_deg))] for r in self.rows]
        cw = [max(len(h), *(len(c[j]) for c in cells)) for j, h in enumerate(heads)]

        def line(a, b, c, per):
            return "  ".join([f"{a:<{width[0]}}", f"{b:<{width[1]}}", f"{c:<{width[2]}}",
                              *(f"{x:<{cw[j]}}" for j, x in enumerate(per))]).rstrip()
        out = [line("factor", "range", "source", heads),
               line("base", "", "", [f"{h:.2f}" if np.isfinite(h) else f">{HS_MAX:g}" for h in self.base])]
        out += [line(r.label, r.range_text, r.short, c) for r, c in zip(self.rows, cells)]
        together = self.together
        if together is not None and together.detail:
            if len(set(together.detail)) == 1:
                out.append(f"all together (every heading): {together.detail[0]}")
            else:
                out += [f"all together at {b:g}°: {d}" for b, d in zip(self.beta_deg, together.detail, strict=True)]
        return "\n".join(out)

    def with_extra(self, extra: ExtraLimit) -> "Sensitivity":
        """The same table with a row computed elsewhere (:class:`ExtraLimit`), placed by its swing before
        "all together" (which it does not join)."""
        rows = [*self.factor_rows, _extra_row(extra, self.beta_deg, self.base)]
        rows.sort(key=lambda r: -max(_finite_swing(r, j) for j in range(len(self.beta_deg))))
        together = self.together
        return dataclasses.replace(self, rows=tuple(rows + ([together] if together is not None else [])))

    @classmethod
    def from_dict(cls, d: Mapping) -> "Sensitivity":
        """Back from :meth:`as_dict` (a campaign store keeps it as JSON); a limit stored as null is NaN."""
        def nums(row, key):
            return tuple(math.nan if p[key] is None else float(p[key]) for p in row["per_heading"])

        rows = tuple(SensitivityRow(
            factor=r["factor"], label=r["label"], base_text=r["base_value"], low_text=r["low_value"],
            high_text=r["high_value"], source=r["source"], short=r["source_short"],
            beta_deg=tuple(float(p["beta_deg"]) for p in r["per_heading"]), base=nums(r, "base"),
            low=nums(r, "low"), high=nums(r, "high"),
            detail=tuple(p["detail"] for p in r["per_heading"]) if all("detail" in p for p in r["per_heading"])
            else ()) for r in d["rows"])
        return cls(Tp=float(d["Tp"]), beta_deg=tuple(float(b) for b in d["beta_deg"]),
                   base=tuple(math.nan if h is None else float(h) for h in d["base"]), base_text=d["base_text"],
                   rows=rows, accept=float(d["accept"]), statistics=d["statistics"], method=d["method"],
                   access_duration=float(d["access_duration"]), notes=tuple(d.get("notes", ())))

    def as_dict(self) -> dict:
        """JSON-able."""
        return {"Tp": self.Tp, "beta_deg": list(self.beta_deg),
                "base": [float(h) if np.isfinite(h) else None for h in self.base], "base_text": self.base_text,
                "accept": self.accept, "statistics": self.statistics, "method": self.method,
                "access_duration": self.access_duration, "notes": list(self.notes), "hs_push_on": HS_PUSH_ON,
                "hs_push_on_source": HS_PUSH_ON_SOURCE, "rows": [r.as_dict() for r in self.rows]}


def _short_heading(b: float) -> str:
    name = heading_name(b)
    return {"head seas": "head", "following seas": "following"}.get(name, name.split(" seas")[0])


# --------------------------------------------------------------------------------------- computation
#: Other names a factor answers to (``--factors push,risk``).
FACTOR_ALIASES = {"risk": "accept", "push": "thrust", "friction": "mu", "mu_s": "mu", "k_t": "shear", "z": "height"}


def factors_named(names) -> tuple[Factor, ...]:
    """The :data:`FACTORS` of the given keys (or :data:`FACTOR_ALIASES`), in the order given; :class:`Factor`
    objects pass through; None: all.

    Raises
    ------
    BoatlandInputError
        An unknown name, or none at all.
    """
    if names is None:
        return FACTORS
    out = []
    for f in names:
        if isinstance(f, Factor):
            hit = f
        else:
            key = str(f).strip().lower()
            key = FACTOR_ALIASES.get(key, key)
            hit = next((g for g in FACTORS if g.key == key), None)
            if hit is None:
                raise BoatlandInputError(f"unknown factor {str(f)!r}: use one or more of {', '.join(FACTOR_KEYS)}")
        if hit not in out:
            out.append(hit)
    if not out:
        raise BoatlandInputError(f"no factor to vary: use one or more of {', '.join(FACTOR_KEYS)}")
    return tuple(out)


def _value_text(key: str, v, setup: LandingSetup) -> str:
    """A factor's value as the table shows it (``"300 kN"``, ``"1.4 m"``)."""
    if key == "accept":
        return probability_text(v)
    if key == "thrust":
        return f"{v / 1e3:g} kN"
    if key == "mu":
        return f"{v:g}"
    if key == "shear":
        k = setup.shear_stiffness if v is None else v
        return "rigid" if not math.isfinite(k) else f"{k / 1e6:g} MN/m"
    if key == "height":
        z = setup.points[:, 2] + v
        return f"{z[0]:g} m" if np.allclose(z, z[0]) else "/".join(f"{x:g}" for x in z) + " m"
    return f"{v:g}"


#: How a value is named where the factor's label is not beside it.
_NAMES = {"accept": "P", "thrust": "push", "mu": "μ_s", "shear": "k_t", "height": "fender z"}


def _named(key: str, v, setup: LandingSetup) -> str:
    return f"{_NAMES.get(key, key)} {_value_text(key, v, setup)}"


def sensitivity(db: HydroDB, setup: LandingSetup, Tp: float, beta_deg=DEFAULT_HEADINGS, *, factors=None,
                accept=ACCEPT_PRESETS["best"], statistics: str | None = None, method: str = "improved",
                sea: SpectrumPart | None = None, water_depth: float | None = None,
                access_duration: float = ACCESS_DURATION, omega=None, mu: float | None = None,
                thrust: float | None = None, extra_rows: Sequence[ExtraLimit] = (),
                progress: Callable[[int, int], None] | None = None) -> Sensitivity:
    r"""One-at-a-time sensitivity of the limiting Hs of the slip screening (module docstring).

    Parameters
    ----------
    db : HydroDB
    setup : LandingSetup
        The landing at its base (:meth:`LandingSetup.from_scenario`).
    Tp : float
        Peak period [s].
    beta_deg : array_like, shape (Nβ,)
        Relative wave directions [deg] (default :data:`DEFAULT_HEADINGS`: 180°, 135°, 90°).
    factors : sequence of str or Factor, optional
        Which factors to vary (keys of :data:`FACTOR_KEYS` or own :class:`Factor` objects with a key of
        theirs); default all of :data:`FACTORS`.
    accept : float or str
        The base's accepted probability per access (or a Grøtting 2015 Table 2.1 preset name).
    statistics : {"rayleigh", "rice", "vanmarcke"}, optional
        Default: :func:`~boatland.freqdomain.screening.screening_grid`'s.
    method, sea, water_depth, access_duration, omega
        As :func:`~boatland.freqdomain.screening.screening_grid`.
    mu, thrust : float, optional
        The base's μ_s and push [N] (default the setup's).
    extra_rows : sequence of ExtraLimit
        Limits computed elsewhere, each a row from the base (the screening's slip onset) to its value;
        not part of "all together".
    progress : callable, optional
        ``progress(done, total)`` after each screening.

    Returns
    -------
    Sensitivity

    Raises
    ------
    BoatlandInputError
        Unknown factor, a bad Tp, no heading, a bad accepted probability.
    """
    fs = factors_named(factors)
    try:
        Tp = float(Tp)
    except (TypeError, ValueError):
        raise BoatlandInputError(f"peak period Tp = {Tp!r}: need a finite number > 0 [s]") from None
    if not (math.isfinite(Tp) and Tp > 0):
        raise BoatlandInputError(f"peak period Tp = {Tp!r}: need a finite number > 0 [s]")
    beta = np.atleast_1d(np.asarray(beta_deg, dtype=float))
    if beta.ndim != 1 or beta.size == 0 or not np.all(np.isfinite(beta)):
        raise BoatlandInputError(f"headings {beta_deg!r}: need one or more finite relative directions [deg]")
    p0 = accept_probability(accept)
    known = {"accept", "thrust", "mu", "shear", "height"}
    for f in fs:
        if f.key not in known:
            raise BoatlandInputError(f"factor {f.key!r}: the screening can vary only {', '.join(sorted(known))}")
    base_v = {"accept": p0, "thrust": setup.thrust if thrust is None else float(thrust),
              "mu": setup.mu if mu is None else float(mu), "shear": None, "height": 0.0}
    kw = {"method": method, "sea": sea, "water_depth": water_depth, "access_duration": access_duration,
          "omega": omega, **({} if statistics is None else {"statistics": statistics})}
    used = {}
    n_total = 1 + 2 * len(fs) + (2 * beta.size if len(fs) > 1 else 0)
    done = [0]

    failed = []

    def limits(values: dict, b, what: str | None = None) -> np.ndarray:
        """The limits at ``values``; for an end (``what``) a landing the screening cannot solve (no static
        equilibrium under the push …) is a recorded failure, NaN, not an aborted table."""
        s = setup
        if values["height"]:
            s = s.replace(points=s.points + np.array([0.0, 0.0, values["height"]]))
        common = dict(accept=values["accept"], mu=values["mu"], thrust=values["thrust"], **kw)
        try:
            if values["shear"] is None:
                table = screening_grid(db, s, [Tp], b, **common)
            else:
                table = shear_sweep(db, s, Tp, b, k_t=[values["shear"]], **common).table
            used["statistics"] = table.statistics
            hs = table.Hs[0]
        except ValueError as exc:
            if what is None:
                raise
            failed.append(f"{what}: no limit ({exc})")
            hs = np.full(len(b), np.nan)
        done[0] += 1
        if progress is not None:
            progress(done[0], n_total)
        return np.asarray(hs, dtype=float)

    def ends(f: Factor):
        lo, hi = (base_v[f.key] + f.low, base_v[f.key] + f.high) if f.offset else (f.low, f.high)
        return lo, hi

    base = limits(base_v, beta)
    rows, at = [], {}
    for f in fs:
        lo, hi = ends(f)
        h_lo = limits({**base_v, f.key: lo}, beta, f"{f.label} {_value_text(f.key, lo, setup)}")
        h_hi = limits({**base_v, f.key: hi}, beta, f"{f.label} {_value_text(f.key, hi, setup)}")
        at[f.key] = (lo, hi, h_lo, h_hi)
        rows.append(SensitivityRow(
            factor=f.key, label=f.label, base_text=_value_text(f.key, base_v[f.key], setup),
            low_text=_value_text(f.key, lo, setup), high_text=_value_text(f.key, hi, setup), source=f.source,
            short=f.short, beta_deg=tuple(beta.tolist()), base=tuple(base.tolist()), low=tuple(h_lo.tolist()),
            high=tuple(h_hi.tolist())))
    rows += [_extra_row(x, tuple(beta.tolist()), tuple(base.tolist())) for x in extra_rows]
    rows.sort(key=lambda r: -max(_finite_swing(r, j) for j in range(beta.size)))
    if len(fs) > 1:
        rows.append(_together(fs, at, base_v, base, beta, limits, setup))
    notes = tuple(f"the base {f.label} {_value_text(f.key, base_v[f.key], setup)} lies outside its range "
                  f"{_value_text(f.key, f.low, setup)} – {_value_text(f.key, f.high, setup)} ({f.short})"
                  for f in fs if not f.offset and base_v[f.key] is not None
                  and not f.low <= base_v[f.key] <= f.high) + tuple(failed)
    return Sensitivity(Tp=float(Tp), beta_deg=tuple(beta.tolist()), base=tuple(base.tolist()), notes=notes,
                       base_text=", ".join(_named(f.key, base_v[f.key], setup) for f in FACTORS),
                       rows=tuple(rows), accept=p0, statistics=used["statistics"], method=method,
                       access_duration=float(access_duration))


def _extra_row(x: ExtraLimit, beta: tuple, base: tuple) -> SensitivityRow:
    """The row of a limit computed elsewhere: from the base (the screening's slip onset) to its value."""
    return SensitivityRow(factor=x.key, label="incident definition" if x.key == "incident" else x.key,
                          base_text="onset (screening)", low_text="onset (screening)", high_text=x.label,
                          source=x.source, short=x.short or x.source[:40], beta_deg=beta, base=base, low=base,
                          high=tuple(x.at(b) for b in beta))


def _finite_swing(row: SensitivityRow, j: int) -> float:
    s = row.swing(j)
    return 1e9 if math.isinf(s) else s


def _together(fs, at, base_v, base, beta, limits, setup) -> SensitivityRow:
    """Per heading, every factor at its limit-raising end (high) and at its limit-lowering end (low) at once
    (the base value where neither end raises / lowers the limit there)."""
    best, worst, detail_hi, detail_lo = [], [], [], []
    for j, b in enumerate(beta):
        up, down = dict(base_v), dict(base_v)
        for f in fs:
            lo, hi, h_lo, h_hi = at[f.key]
            choices = [(base[j], base_v[f.key]), (h_lo[j], lo), (h_hi[j], hi)]
            ok = [c for c in choices if not math.isnan(c[0])]
            up[f.key] = max(ok, key=lambda c: c[0])[1]
            down[f.key] = min(ok, key=lambda c: c[0])[1]
        best.append(float(limits(up, [b], f"all raising at {b:g}°")[0]))
        worst.append(float(limits(down, [b], f"all lowering at {b:g}°")[0]))
        detail_hi.append(", ".join(_named(f.key, up[f.key], setup) for f in fs))
        detail_lo.append(", ".join(_named(f.key, down[f.key], setup) for f in fs))
    detail = tuple(f"raising: {h}; lowering: {lo}" for h, lo in zip(detail_hi, detail_lo, strict=True))
    return SensitivityRow(
        factor="all", label="all together", base_text="base", low_text="all lowering",
        high_text="all raising", short="the ranges above",
        source="every factor above at once, per heading at the end of its range that lowers / raises the limit "
               "there (the base value where neither does)",
        beta_deg=tuple(float(b) for b in beta), base=tuple(float(h) for h in base), low=tuple(worst),
        high=tuple(best), detail=detail)


# --------------------------------------------------------------------------------------- figure
def figure_tornado(result: Sensitivity, *, title: str = ""):
    """One tornado per heading: for each factor a bar from the base limit to the limit at its low end
    (light) and at its high end (dark), factors sorted by their swing at that heading (largest on top), the
    "all together" row at the bottom (hatched), the base as a vertical line and :data:`HS_PUSH_ON` dashed.
    Returns the matplotlib Figure."""
    from matplotlib.patches import Patch

    from boatland.plotstyle import pyplot

    plt = pyplot()
    light, dark = "#9ecae1", "#2171b5"
    nb = len(result.beta_deg)
    ncol = min(nb, 3)
    nrow = math.ceil(nb / ncol)
    n_rows = len(result.rows)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.6 * ncol + 1.2, (0.5 * n_rows + 1.3) * nrow + 0.9),
                             squeeze=False, constrained_layout=True)
    finite = [x for r in result.rows for x in (*r.low, *r.high, *r.base) if np.isfinite(x)]
    top = max([HS_PUSH_ON, *finite]) * 1.1
    for j, b in enumerate(result.beta_deg):
        ax = axes[j // ncol][j % ncol]
        base = result.base[j]
        rows = sorted(result.factor_rows, key=lambda r: _finite_swing(r, j))        # largest on top
        if result.together is not None:
            rows = [result.together, *rows]
        for y, r in enumerate(rows):
            hatch = "//" if r.factor == "all" else None
            ends = sorted(((r.low[j], light), (r.high[j], dark)),       # the longer bar first: both stay seen
                          key=lambda e: -abs(e[0] - base) if np.isfinite(e[0] - base) else -math.inf)
            if np.isfinite(base) and any(math.isnan(v) for v in (r.low[j], r.high[j])):
                ax.text(base, y, "  not found at this heading" if r.factor not in FACTOR_KEYS else "  n/a",
                        fontsize=6.5, va="center", color="0.3", style="italic")   # not "no effect": unknown
            for value, shade in ends:
                if math.isnan(value) or not np.isfinite(base):
                    continue
                v = min(value, top)
                ax.barh(y, v - base, left=base, height=0.6, color=shade, hatch=hatch, edgecolor="0.3", lw=0.5)
                if abs(v - base) >= 0.03 * top:                  # a number where the bar is long enough for one
                    ax.text(v, y + 0.32, f"{value:.2f}" if np.isfinite(value) else f">{HS_MAX:g}", fontsize=6,
                            ha="center", va="bottom", color="0.2")
        ax.set_yticks(range(len(rows)))
        ax.set_yticklabels([f"{r.label}\n" + ("all at once" if r.factor == "all" else
                                               textwrap.fill(r.range_text, 30, break_on_hyphens=False))
                            for r in rows], fontsize=7.5)
        if np.isfinite(base):
            ax.axvline(base, color="k", lw=1.2)
            ax.text(base, len(rows) - 0.35, f" base {base:.2f} m", fontsize=7.5, va="bottom")
        ax.axvline(HS_PUSH_ON, color="0.35", ls="--", lw=1)
        ax.text(HS_PUSH_ON, (len(rows) - 1) / 2, f"Hs {HS_PUSH_ON:g} m quoted for push-on access (EWEA 2014)",
                fontsize=6.5, rotation=90, ha="right", va="center", color="0.25")
        ax.set_xlim(0, top)
        ax.set_ylim(-0.6, len(rows) + 0.45)
        ax.set_xlabel("limiting Hs [m]")
        ax.set_title(f"{b:g}° ({heading_name(b)})", fontsize=9)
        ax.grid(axis="x", alpha=0.3)
    for k in range(nb, nrow * ncol):
        axes[k // ncol][k % ncol].set_visible(False)
    handles = [Patch(facecolor=light, edgecolor="0.3", label="factor at its low end"),
               Patch(facecolor=dark, edgecolor="0.3", label="factor at its high end"),
               Patch(facecolor="white", edgecolor="0.3", hatch="//", label="all together: every factor at its limit-lowering / -raising end (per heading)")]
    fig.legend(handles=handles, loc="outside lower center", ncol=3, fontsize=7.5, frameon=False)
    head = title or f"limiting Hs at Tp {result.Tp:g} s, one factor at a time"
    fig.suptitle(f"{head}\nbase: {result.base_text}; {result.statistics} statistics, {result.method} hinge",
                 fontsize=8.5)
    return fig


def plot_tornado(result: Sensitivity, path: str | Path, *, title: str = "", dpi: int = 100) -> Path:
    """Save :func:`figure_tornado` to ``path`` (format from the suffix)."""
    from boatland.plotstyle import save_figure

    return save_figure(figure_tornado(result, title=title), path, dpi=dpi)

