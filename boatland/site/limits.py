r"""The limit of every sea state of a site's weather at each of a turbine's landings: the frequency-domain
screening (:mod:`boatland.freqdomain.screening`) at the sea state's own peak period and relative direction,
one sea of one spectrum — or of two, wind sea and swell, when the weather holds the partitions.

**One spectrum.** A sea state (Hs, Tp, from φ_w) at the landing at bearing φ_L is judged at its relative
direction β = φ_L − φ_w (:mod:`boatland.site.compass`): its limit is the screening's limiting Hs at (Tp, β) —
the largest Hs whose incident probability per access is accepted (:func:`~boatland.freqdomain.statistics.
limiting_hs`) — and the sea state is workable when Hs ≤ H_lim.

**Two spectra** (Grøtting 2015 §3.2.1 eq. 3.41–3.45, after Wu 2014). Wind sea and swell are independent
Gaussian seas; each response's spectral moments are the sum of the parts',

.. math:: m_k = \sum_p H_{s,p}^2\, m_k^{(1)}(T_{p,p}, \beta_p), \qquad
          m_k^{(1)}(T_p, \beta) = \int \omega^k |H(\omega, \beta)|^2 S_1(\omega \mid T_p)\,d\omega ,

(and so their covariances), :math:`S_1` the part's spectrum at Hs = 1 m. The limit is that of the combined
sea scaled as a whole, its mix kept: the moments per unit :math:`H_{s}^2 = \sum_p H_{s,p}^2` go into the same
bisection, and the sea state is workable when its :math:`H_s \le H_{lim}`. Shapes (Grøtting 2015, Appendix,
``doublespec.m`` and §4.2 — the SIMA runs): the wind sea a Pierson–Moskowitz spectrum (γ = 1), the swell a
JONSWAP of γ = 5. A row without either part, or whose parts do not add up to its Hs (within
:data:`PARTS_TOLERANCE`: a part missing), is judged as one spectrum of its total.

The margin of a sea state, :math:`H_{lim}/H_s` (> 1 workable), ranks the landings (the best landing is the
one with the largest margin). With one spectrum it is the screening's limit over the sea's Hs, so a scatter
table and a hindcast that lays the same sea states end to end are judged alike.

Relative directions are rounded to :data:`DIRECTION_STEP` (hindcasts give directions to 1° or coarser);
peak periods are used as given. The screening's transfer functions are computed once per scenario, for
every direction any landing needs.

A time-domain table in place of the screening is :mod:`boatland.site.tables`; each sea state in its own current,
:mod:`boatland.site.flows`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import slip_transfer
from boatland.freqdomain.statistics import (ACCEPT_PRESETS, ACCESS_DURATION, DEFAULT_STATISTICS, accept_probability,
                                            correlation_matrix, distinct_events, limiting_hs, unit_spectra)
from boatland.sea.spectra import SpectrumPart
from boatland.site.compass import relative_direction
from boatland.site.weather import Weather
from boatland.vessel.database import HydroDB

__all__ = ["DIRECTION_STEP", "PARTS_TOLERANCE", "PART_SHAPES", "SeaLimits", "needed_directions", "relative_directions",
           "sea_heights", "sea_moments", "two_spectra_rows", "wave_limits"]

#: Relative directions are rounded to this [deg]: hindcasts (NORA10, ERA5) give directions to 1° or coarser.
DIRECTION_STEP = 1.0

#: A row's partitions must add up to its total Hs within this (relative, √ΣHs_p² against Hs) to be judged as two
#: spectra; else a part is missing (a gap in the partitioned data) and the row is judged as one spectrum of its total.
PARTS_TOLERANCE = 0.1

#: The partitions' spectral shapes (Grøtting 2015, Appendix ``doublespec.m``: gmaW = 1, gmaS = 5).
PART_SHAPES = {"wind_sea": SpectrumPart(Hs=1.0, Tp=6.0, kind="pm"),
               "swell": SpectrumPart(Hs=1.0, Tp=10.0, kind="jonswap", gamma=5.0)}


@dataclass(frozen=True, eq=False)
class SeaLimits:
    """Limits of every sea state at every landing.

    Attributes
    ----------
    Hs_limit : ndarray, shape (n, L)
        The sea state's limiting Hs [m] (of the combined sea, its mix kept, when it has two parts; inf above
        the screening's ceiling, 0 when the fender slips without waves).
    margin : ndarray, shape (n, L)
        H_lim / H_s: > 1 workable.
    beta_deg : ndarray, shape (n, L)
        The relative direction of the (total) sea [deg].
    governing : ndarray of str, shape (n, L)
        The response that dominates at the limit.
    two_spectra : ndarray of bool, shape (n,)
        Judged as wind sea and swell.
    landings_deg : ndarray, shape (L,)
    accept, access_duration : float
    statistics, method : str
    mu, thrust : float
    source : str
        Where the limits come from, in words (the screening and its incident, or a time-domain table).
    covered : ndarray of bool, shape (n, L), optional
        Sea states inside a time-domain table (None: the screening judges every one).
    """

    Hs_limit: np.ndarray
    margin: np.ndarray
    beta_deg: np.ndarray
    governing: np.ndarray
    two_spectra: np.ndarray
    landings_deg: np.ndarray
    accept: float
    access_duration: float
    statistics: str
    method: str
    mu: float
    thrust: float
    source: str = "frequency-domain screening: a slip onset (or roll beyond its limit)"
    covered: np.ndarray | None = None

    @property
    def workable(self) -> np.ndarray:
        """(n, L) bool: Hs ≤ H_lim (False outside a time-domain table)."""
        with np.errstate(invalid="ignore"):
            return self.margin >= 1.0


def two_spectra_rows(weather: Weather, spectra: str = "auto") -> np.ndarray:
    """(n,) bool: the rows judged as wind sea + swell — those with partitions whose heights add up to the row's
    Hs within :data:`PARTS_TOLERANCE` (a row with a part missing would otherwise drop part of its sea, on the unsafe
    side); none with ``spectra="one"``."""
    if spectra == "one" or not weather.parts:
        return np.zeros(weather.n, bool)
    sum2 = sum(np.where(H > 0, H, 0.0) ** 2 for H, _, _ in weather.parts.values())
    return (sum2 > 0) & (np.abs(np.sqrt(sum2) - weather.Hs) <= PARTS_TOLERANCE * weather.Hs)


def relative_directions(from_deg, landings_deg) -> np.ndarray:
    """(n, L): the relative direction (:func:`~boatland.site.compass.relative_direction`) of waves from each of
    ``from_deg`` (n,) at each landing of ``landings_deg`` (L,), rounded to :data:`DIRECTION_STEP`, in [0, 360)."""
    beta = relative_direction(np.asarray(from_deg, dtype=float)[:, None],
                              np.asarray(landings_deg, dtype=float)[None, :])
    return np.mod(np.round(beta / DIRECTION_STEP) * DIRECTION_STEP, 360.0)


def sea_heights(weather: Weather, two: np.ndarray) -> np.ndarray:
    """(n,) the Hs each sea state is judged by: √ΣHs_p² of its parts where it is judged as two spectra (``two``),
    else its total Hs."""
    sum2 = sum(np.where(H > 0, H, 0.0) ** 2 for H, _, _ in weather.parts.values()) if weather.parts else 0.0
    return np.where(two, np.sqrt(sum2), weather.Hs)


def _components(weather: Weather, L: np.ndarray, spectra: str):
    """The (rows, Tp, β (n_sel, L), Hs², shape name) components of each row × landing: one for a one-spectrum row,
    one per part else; and the two-spectra rows."""
    parts = {} if spectra == "one" else weather.parts
    two = two_spectra_rows(weather, spectra)
    comps = []
    one = ~two
    if one.any():
        comps.append((np.flatnonzero(one), weather.Tp[one], relative_directions(weather.from_deg[one], L),
                      np.ones(int(one.sum())), "sea"))
    for name, (H, T, d) in parts.items():
        rows = np.flatnonzero(two & (H > 0))
        comps.append((rows, T[rows], relative_directions(d[rows], L), H[rows] ** 2, name))
    return comps, two


def needed_directions(weather: Weather, landings_deg, spectra: str = "auto") -> np.ndarray:
    """The relative directions (rounded, unique) at which the weather's seas meet the landings: those the transfer
    functions are needed at."""
    comps, _ = _components(weather, np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0, spectra)
    return np.unique(np.concatenate([c[2].ravel() for c in comps]))


def sea_moments(weather: Weather, landings_deg, omega, H, beta_deg, *, spectra: str = "auto",
                sea: SpectrumPart | None = None, water_depth: float, g: float, cross_orders=(0,)):
    r"""Spectral moments of K responses in every sea state at every landing, per unit :math:`H_s^2` of the sea
    (module docstring: a sum over its parts for two spectra).

    Parameters
    ----------
    weather, landings_deg
    omega : ndarray, shape (Nw,)
    H : ndarray of complex, shape (Nw, Nβ, K)
        The responses' transfer functions at the relative directions ``beta_deg`` (Nβ,), which hold every one
        the weather meets at the landings (:func:`needed_directions`).
    cross_orders : tuple of int
        The orders k of the cross moments returned.

    Returns
    -------
    m : ndarray, shape (n, L, K, 3)
        :math:`m_k = \int \omega^k |H|^2 S\,d\omega`, k = 0, 1, 2.
    cross : ndarray, shape (n, L, K, K, len(cross_orders))
        :math:`\int \omega^k\,\mathrm{Re}(H_i H_j^*)\,S\,d\omega` (k = 0: the covariances).
    two : ndarray of bool, shape (n,)
        The rows judged as two spectra.
    """
    L = np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0
    comps, two = _components(weather, L, spectra)
    n, w, betas = weather.n, np.asarray(omega), np.asarray(beta_deg)
    K = H.shape[-1]
    orders = np.asarray(cross_orders)
    wk = w[:, None, None] ** np.arange(3)                                             # (Nw, 1, 3)
    wo = w[:, None, None, None] ** orders                                              # (Nw, 1, 1, O)
    m = np.zeros((n, L.size, K, 3))
    cross = np.zeros((n, L.size, K, K, orders.size))
    hs2 = np.where(two, 0.0, 1.0)                    # Σ Hs_p² of two-part rows; one-part rows per unit Hs²
    made: dict = {}                                  # per direction: |H|² ω^k and Re(H_i H_j*) ω^k, (Nw, ·)

    def products(b):
        if b not in made:
            h = H[:, b]
            made[b] = ((np.abs(h) ** 2)[..., None] * wk).reshape(w.size, -1), \
                (np.einsum("wi,wj->wij", h, h.conj()).real[..., None] * wo).reshape(w.size, -1)
        return made[b]

    for rows, T, beta, weight, name in comps:
        shape = sea if name == "sea" else PART_SHAPES[name]
        uT, iT = np.unique(T, return_inverse=True)
        S, wt = unit_spectra(w, uT, sea=shape, water_depth=water_depth, g=g)
        SW = S * wt                                                              # (NT, Nw)
        ib = np.searchsorted(betas, beta)                                        # (n_sel, L)
        order = np.argsort(ib, axis=None, kind="stable")                         # the cells of each direction,
        flat = ib.ravel()[order]                                                 # row-major within it
        for g_cells in np.split(order, np.flatnonzero(np.diff(flat)) + 1):
            sel_r, sel_l = np.unravel_index(g_cells, ib.shape)
            Gb, Cb = products(int(ib[sel_r[0], sel_l[0]]))
            Sw = SW[iT[sel_r]] * weight[sel_r, None]                             # (k, Nw)
            m[rows[sel_r], sel_l] += (Sw @ Gb).reshape(-1, K, 3)
            cross[rows[sel_r], sel_l] += (Sw @ Cb).reshape(-1, K, K, orders.size)
        if name != "sea":
            hs2[rows] += weight
    return m / hs2[:, None, None, None], cross / hs2[:, None, None, None, None], two


def wave_limits(db: HydroDB, setup: LandingSetup, weather: Weather, landings_deg, *,
                accept=ACCEPT_PRESETS["best"], statistics: str = DEFAULT_STATISTICS, method: str = "improved",
                sea: SpectrumPart | None = None, water_depth: float | None = None,
                access_duration: float = ACCESS_DURATION, mu: float | None = None, thrust: float | None = None,
                spectra: str = "auto", omega=None) -> SeaLimits:
    """The limit of each of ``weather``'s sea states at each landing (module docstring), the landing ``setup``
    as it is (its own current and wind, if any, in every sea state).

    Parameters
    ----------
    db, setup
        The vessel on its landing (the landing's own geometry; its compass bearing is ``landings_deg``).
    weather : Weather
    landings_deg : array_like, shape (L,)
        Compass bearings of the landings (from the tower's axis) [deg].
    accept, statistics, method, access_duration, mu, thrust, omega
        As :func:`~boatland.freqdomain.screening.screening_grid`.
    sea : SpectrumPart, optional
        The shape of a one-spectrum sea (default JONSWAP γ 3.3).
    water_depth : float, optional
        For a TMA shape (default the database's).
    spectra : {"auto", "one"}
        ``"auto"``: two spectra where the weather has partitions; ``"one"``: every sea state one spectrum of
        its total Hs, Tp and direction.

    Returns
    -------
    SeaLimits
    """
    if spectra not in ("auto", "one"):
        raise ValueError(f"spectra {spectra!r}: use 'auto' or 'one'")
    p_acc = accept_probability(accept)
    L = np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0
    n = weather.n
    tr = slip_transfer(db, setup, omega=omega, beta_deg=needed_directions(weather, L, spectra), method=method, mu=mu,
                       thrust=thrust)
    depth = db.water_depth if water_depth is None else water_depth
    m, cross, two = sea_moments(weather, L, tr.omega, tr.H, tr.beta_deg, spectra=spectra, sea=sea, water_depth=depth,
                                g=db.g)
    cov = cross[..., 0]
    R = tr.capacity.size
    keep = distinct_events(m[..., 0], tr.capacity, correlation_matrix(cov), background=tr.background)
    T_row = np.repeat(weather.Tp, L.size)                                        # the sea's cycles (Rayleigh)
    table = limiting_hs(m.reshape(n * L.size, 1, R, 3), tr.capacity, T_row, [0.0], accept=p_acc,
                        statistics=statistics, access_duration=access_duration, method=method, names=tr.names,
                        keep=keep.reshape(n * L.size, 1, R), background=tr.background)
    lim = table.Hs.reshape(n, L.size)
    hs = sea_heights(weather, two)
    with np.errstate(divide="ignore", invalid="ignore"):
        margin = lim / hs[:, None]
    beta_total = relative_directions(weather.from_deg, L)
    return SeaLimits(Hs_limit=lim, margin=margin, beta_deg=beta_total, governing=table.governing.reshape(n, L.size),
                     two_spectra=two, landings_deg=L, accept=p_acc, access_duration=float(access_duration),
                     statistics=statistics, method=method, mu=float(tr.setup.mu), thrust=float(tr.setup.thrust))
