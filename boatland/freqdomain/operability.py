r"""Operability: availability of push-on access over a wave scatter diagram or hindcast table
(Grøtting 2015 §3.2.1 last paragraph, §4.1 Tables 4.2–4.7; Naaijen 2012 downtime analysis).

A sea state i (Hs_i, Tp_i, direction θ_i, occurrence p_i) is *workable* when its Hs does not exceed the
limiting Hs of the screening (:mod:`boatland.freqdomain.screening`) at its own peak period and relative
direction β_i = θ_i − ψ (ψ the vessel's heading, fixed by the landing). The availability is

.. math:: A = \sum_i p_i\,[H_{s,i} \le H_{s,lim}(T_{p,i}, \beta_i)] \Big/ \sum_i p_i ,

and the downtime 1 − A. The limit is computed at each distinct (Tp, β) of the table (no interpolation).

Scatter files (CSV, ``#`` comment lines allowed; a header row names the columns, any order):

- ``Hs`` [m], ``Tp`` [s] — required;
- ``direction_deg`` — the direction the waves travel *towards*, global frame (DESIGN.md §2), or
  ``direction_from_deg`` — the direction they come *from* (the usual hindcast/metocean convention);
  without either, every row gets the ``default_direction_deg`` given to :func:`read_scatter`;
- ``occurrence`` — probability, hours or counts (≥ 0); a sum far from 1 (more than 1 %) is
  normalised with a :class:`~boatland.errors.BoatlandWarning`.
"""

from __future__ import annotations

import csv
import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from boatland.errors import BoatlandInputError, BoatlandWarning
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import slip_transfer
from boatland.freqdomain.statistics import (ACCEPT_PRESETS, ACCESS_DURATION, DEFAULT_STATISTICS, accept_probability, distinct_events,
                                            limiting_hs, response_correlation, spectral_moments)
from boatland.vessel.database import HydroDB
from boatland.sea.spectra import SpectrumPart

__all__ = ["Availability", "ScatterTable", "availability", "read_scatter"]

SUM_TOLERANCE = 0.01


@dataclass(frozen=True, eq=False)
class ScatterTable:
    """Sea states and their occurrence (normalised to sum 1).

    Attributes
    ----------
    Hs, Tp, direction_deg, occurrence : ndarray, shape (n,)
        [m], [s], travel-towards direction in the global frame [deg], probability [-].
    source : str
    """

    Hs: np.ndarray
    Tp: np.ndarray
    direction_deg: np.ndarray
    occurrence: np.ndarray
    source: str = "<table>"

    @classmethod
    def from_arrays(cls, Hs, Tp, direction_deg, occurrence, source: str = "<table>") -> "ScatterTable":
        """Validate and normalise arrays (same checks as :func:`read_scatter`)."""
        cols = [np.atleast_1d(np.asarray(v, dtype=float)) for v in (Hs, Tp, direction_deg, occurrence)]
        n = cols[0].size
        cols = [np.broadcast_to(c, (n,)).copy() if c.size == 1 else c for c in cols]
        for name, c in zip(("Hs", "Tp", "direction_deg", "occurrence"), cols):
            if c.shape != (n,):
                raise BoatlandInputError(f"{source}: column {name!r} has {c.size} values for {n} rows")
            bad = np.flatnonzero(~np.isfinite(c))
            if bad.size:
                raise BoatlandInputError(f"{source}: row {bad[0] + 1}: {name} is not a finite number")
        H, T, d, p = cols
        for name, c in (("Hs", H), ("Tp", T)):
            bad = np.flatnonzero(c <= 0)
            if bad.size:
                raise BoatlandInputError(f"{source}: row {bad[0] + 1}: {name} = {c[bad[0]]:g} must be > 0")
        bad = np.flatnonzero(p < 0)
        if bad.size:
            raise BoatlandInputError(f"{source}: row {bad[0] + 1}: occurrence = {p[bad[0]]:g} is negative "
                                     f"({bad.size} negative row(s)); occurrences are probabilities, hours or "
                                     "counts ≥ 0")
        total = float(p.sum())
        if n == 0 or total <= 0:
            raise BoatlandInputError(f"{source}: no sea states with a positive occurrence")
        if abs(total - 1.0) > SUM_TOLERANCE:
            warnings.warn(f"{source}: occurrences sum to {total:.6g}, not 1: normalised (read as relative "
                          "frequencies, e.g. hours or counts)", BoatlandWarning, stacklevel=3)
        return cls(Hs=H, Tp=T, direction_deg=d % 360.0, occurrence=p / total, source=source)


def read_scatter(path: str | Path, *, default_direction_deg: float | None = None) -> ScatterTable:
    """Read a scatter diagram / hindcast table from CSV (format: module docstring).

    Raises
    ------
    BoatlandInputError
        One line naming the file and the row or column: missing columns, non-numbers, Hs or Tp ≤ 0,
        negative occurrences, nothing left.
    """
    path = Path(path)
    from boatland.inputs import read_input

    text = read_input(path, "scatter table", "text").decode("utf-8")      # not UTF-8: the caller names the byte
    lines = [(i + 1, ln) for i, ln in enumerate(text.splitlines()) if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise BoatlandInputError(f"{path}: empty scatter table (need a header row Hs,Tp,direction_deg,occurrence)")
    rows = list(csv.reader([ln for _, ln in lines]))
    header = [h.strip() for h in rows[0]]
    need = ("Hs", "Tp", "occurrence")
    missing = [k for k in need if k not in header]
    if missing:
        raise BoatlandInputError(f"{path}: line {lines[0][0]}: missing column(s) {', '.join(missing)} in the header "
                                 f"{','.join(header)!r} (need Hs, Tp, occurrence and direction_deg or "
                                 "direction_from_deg)")
    dir_col = "direction_deg" if "direction_deg" in header else (
        "direction_from_deg" if "direction_from_deg" in header else None)
    if dir_col is None and default_direction_deg is None:
        raise BoatlandInputError(f"{path}: line {lines[0][0]}: no direction_deg (towards) or direction_from_deg "
                                 "column and no default direction given")
    cols = {k: [] for k in (*need, "dir")}
    for (lineno, _), row in zip(lines[1:], rows[1:]):
        if len(row) != len(header):
            raise BoatlandInputError(f"{path}: line {lineno}: {len(row)} fields for {len(header)} columns")
        rec = dict(zip(header, (c.strip() for c in row)))
        for k in need + ((dir_col,) if dir_col else ()):
            try:
                v = float(rec[k])
            except ValueError:
                raise BoatlandInputError(f"{path}: line {lineno}: {k} = {rec[k]!r} is not a number") from None
            if not math.isfinite(v):
                raise BoatlandInputError(f"{path}: line {lineno}: {k} = {rec[k]!r} is not finite")
            if k in ("Hs", "Tp") and v <= 0:
                raise BoatlandInputError(f"{path}: line {lineno}: {k} = {v:g} must be > 0")
            if k == "occurrence" and v < 0:
                raise BoatlandInputError(f"{path}: line {lineno}: occurrence = {v:g} is negative; occurrences are "
                                         "probabilities, hours or counts ≥ 0")
            cols["dir" if k == dir_col else k].append(v)
        if dir_col is None:
            cols["dir"].append(default_direction_deg)
    d = np.asarray(cols["dir"], dtype=float)
    if dir_col == "direction_from_deg":
        d = d + 180.0
    return ScatterTable.from_arrays(cols["Hs"], cols["Tp"], d, cols["occurrence"], source=str(path))


@dataclass(frozen=True, eq=False)
class Availability:
    """Availability of access over a scatter table.

    Attributes
    ----------
    availability : float
        Workable share of the time, A.
    workable : ndarray of bool, shape (n,)
        Per sea state.
    Hs_limit : ndarray, shape (n,)
        Limiting Hs of each row's (Tp, β) [m].
    beta_deg : ndarray, shape (n,)
        Relative wave direction of each row [deg].
    scatter : ScatterTable
    accept : float
    statistics, method : str
    mu, thrust : float
    """

    availability: float
    workable: np.ndarray
    Hs_limit: np.ndarray
    beta_deg: np.ndarray
    scatter: ScatterTable
    accept: float
    statistics: str
    method: str
    mu: float
    thrust: float

    @property
    def downtime(self) -> float:
        """1 − A."""
        return 1.0 - self.availability


def availability(db: HydroDB, setup: LandingSetup, scatter: ScatterTable, *, accept=ACCEPT_PRESETS["best"],
                 statistics: str = DEFAULT_STATISTICS, method: str = "improved", sea: SpectrumPart | None = None,
                 water_depth: float | None = None, access_duration: float = ACCESS_DURATION,
                 mu: float | None = None, thrust: float | None = None, omega=None) -> Availability:
    r"""Availability of push-on access over ``scatter`` (Grøtting 2015 §4.1, Tables 4.2–4.7).

    :math:`A = \sum_i p_i [H_{s,i} \le H_{s,lim}(T_{p,i}, \theta_i - \psi)]`, the limit from
    :func:`~boatland.freqdomain.statistics.limiting_hs` at each distinct (Tp, β) of the table.

    Parameters
    ----------
    db : HydroDB
    setup : LandingSetup
        Vessel on its landing; its ``heading_deg`` turns the table's directions into relative ones.
    scatter : ScatterTable
    accept, statistics, method, sea, water_depth, access_duration, omega
        As :func:`~boatland.freqdomain.screening.screening_grid`.
    mu, thrust : float, optional
        Override the setup's μ and F_b [N].

    Returns
    -------
    Availability
    """
    p_acc = accept_probability(accept)
    beta = np.round((scatter.direction_deg - setup.heading_deg) % 360.0, 6)
    ub, ib = np.unique(beta, return_inverse=True)
    ut, it = np.unique(scatter.Tp, return_inverse=True)
    tr = slip_transfer(db, setup, omega=omega, beta_deg=ub, method=method, mu=mu, thrust=thrust)
    h = db.water_depth if water_depth is None else water_depth
    m, captured = spectral_moments(tr, ut, sea=sea, water_depth=h, g=db.g)
    keep = distinct_events(m[..., 0], tr.capacity, response_correlation(tr, ut, sea=sea, water_depth=h, g=db.g),
                           background=tr.background)
    table = limiting_hs(m, tr.capacity, ut, ub, accept=p_acc, statistics=statistics,
                        access_duration=access_duration, method=method, captured=captured, names=tr.names,
                        keep=keep, background=tr.background)
    lim = table.Hs[it, ib]
    ok = scatter.Hs <= lim
    return Availability(availability=float(scatter.occurrence[ok].sum()), workable=ok, Hs_limit=lim, beta_deg=beta,
                        scatter=scatter, accept=p_acc, statistics=statistics, method=method,
                        mu=tr.setup.mu, thrust=tr.setup.thrust)
