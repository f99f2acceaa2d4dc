r"""Weather windows and waiting times (persistence) of a workable/unworkable hindcast series.

An access needs a **window**: the crew transferred out, the work, the crew transferred back — N hours during
which the vessel can land at every moment (the return transfer may be needed early, e.g. to take a casualty
off, so the sea must stay workable throughout — as DNV-OS-H101, *Marine operations, general*, treats a
weather-restricted operation: workable over its whole reference period). On a regular series of step Δt a window of N hours starting at record i
is available when records i … i + k − 1 are all workable, k = ⌈N/Δt⌉.

- **Window probability** P(N): the share of start times (records with k records left) at which a window of
  N hours is available — per calendar month of its start, and over the whole series (Naaijen, TU Delft OE4630
  lecture notes on workability and persistence; Graham 1982, "The parameterisation and prediction of wave height
  and wind speed persistence statistics for oil industry operational planning purposes", Coastal Eng. 6).
- **Waiting time** from each record: the time until the next start of an available window (0 when one starts
  there). Records with no window before the series ends are *censored*: counted, not given a wait.

Run lengths by one backward pass: r_i = r_{i+1} + 1 when record i is workable, else 0; a window starts at i
when r_i ≥ k. The next start at or after i by a backward minimum.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError

__all__ = ["Persistence", "persistence", "run_lengths"]


def run_lengths(ok: np.ndarray) -> np.ndarray:
    """r_i: the number of consecutive True from record i on (0 where ``ok[i]`` is False)."""
    ok = np.asarray(ok, dtype=bool)
    n = ok.size
    # index of the first False at or after i (n when none): runs end there
    idx = np.where(~ok, np.arange(n), n)
    first_false = np.minimum.accumulate(idx[::-1])[::-1]
    return first_false - np.arange(n)


@dataclass(frozen=True, eq=False)
class Persistence:
    """Windows of ``window_hours`` in a series of step ``step_hours``.

    Attributes
    ----------
    window_hours, step_hours : float
    records : int
        k = ⌈N/Δt⌉ records per window.
    starts : ndarray of bool, shape (n,)
        A window is available starting at each record (False for the last k − 1 records: too near the end).
    wait_hours : ndarray, shape (n,)
        Waiting time from each record to the next window start [h] (NaN: censored, none before the end).
    """

    window_hours: float
    step_hours: float
    records: int
    starts: np.ndarray
    wait_hours: np.ndarray

    @property
    def usable(self) -> np.ndarray:
        """Records a window can start at (k records left)."""
        u = np.ones(self.starts.size, bool)
        if self.records > 1:
            u[-(self.records - 1):] = False
        return u

    def probability(self, mask=None) -> float:
        """Share of the usable start records (within ``mask``) at which a window is available (NaN: none)."""
        u = self.usable if mask is None else self.usable & mask
        return float(self.starts[u].mean()) if u.any() else math.nan

    def wait_quantiles(self, q=(0.5, 0.9), mask=None) -> tuple:
        """Quantiles of the waiting time [h] over the records (within ``mask``), censored ones counted as longer
        than any (so a quantile they reach is inf); NaN without records."""
        w = self.wait_hours if mask is None else self.wait_hours[mask]
        if w.size == 0:
            return tuple(math.nan for _ in q)
        w = np.where(np.isnan(w), np.inf, w)
        return tuple(float(np.quantile(w, x, method="inverted_cdf")) for x in q)

    def censored(self, mask=None) -> float:
        """Share of records (within ``mask``) with no window before the series ends."""
        w = self.wait_hours if mask is None else self.wait_hours[mask]
        return float(np.isnan(w).mean()) if w.size else math.nan


def persistence(workable, step_hours: float, window_hours: float) -> Persistence:
    """Windows of ``window_hours`` and waiting times in the regular series ``workable`` (module docstring).

    Raises
    ------
    BoatlandInputError
        A window not longer than 0 h.
    """
    if not window_hours > 0 or not math.isfinite(window_hours):
        raise BoatlandInputError(f"window of {window_hours:g} h: must be > 0 h (transfer out, work, transfer back)")
    ok = np.asarray(workable, dtype=bool)
    n = ok.size
    k = max(1, math.ceil(window_hours / step_hours - 1e-9))
    starts = run_lengths(ok) >= k
    idx = np.where(starts, np.arange(n), n)
    nxt = np.minimum.accumulate(idx[::-1])[::-1]                     # next start at or after i (n: none)
    wait = np.where(nxt < n, (nxt - np.arange(n)) * step_hours, np.nan)
    return Persistence(window_hours=float(window_hours), step_hours=float(step_hours), records=k, starts=starts,
                       wait_hours=wait)
