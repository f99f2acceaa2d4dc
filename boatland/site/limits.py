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
JONSWAP of γ = 5. A row without either part is judged as one spectrum.

The margin of a sea state, :math:`H_{lim}/H_s` (> 1 workable), ranks the landings (the best landing is the
one with the largest margin). With one spectrum it is the screening's limit over the sea's Hs, so a scatter
table and a hindcast that lays the same sea states end to end are judged alike.

Relative directions are rounded to :data:`DIRECTION_STEP` (hindcasts give directions to 1° or coarser);
peak periods are used as given. The screening's transfer functions are computed once per scenario, for
every direction any landing needs.

**From the time domain.** The screening predicts the onset of a slip. The incident the field counts — a slide
of tens of centimetres — is judged in the time domain: a rare-event campaign (``method = "isee"`` with an
``accept``) writes its limiting Hs per (Tp, relative direction) to its store (``/isee_limits``).
:class:`LimitsTable` reads it; a sea state's limit is then interpolated linearly in Tp and in direction
between the campaign's cases (its directions mirrored port/starboard when the vessel's database is symmetric;
two table directions more than :data:`MAX_GAP_DEG` apart are not interpolated across), and a sea state outside
the table is *not covered*: counted as not workable, and said. The table is for one spectrum (the campaign's):
a sea state with partitions is judged by its total Hs, Tp and direction.

**In its own current.** A tidal current changes the landed equilibrium (a current across the vessel uses up
friction before the waves do) and damps the motions (:mod:`boatland.loads.current`,
:mod:`boatland.freqdomain.currents`). When the weather has each sea state's current (speed and the compass
direction it comes from; relative to the vessel like the waves), the screening runs at nodes of current speed
and relative direction (:data:`CURRENT_SPEED_STEP`, :data:`CURRENT_DIRECTION_STEP`; the speed 0 node without any
current) for the sea states around each node, and a sea state's limit is interpolated between its four nodes —
linear in U² (the drag is quadratic) and in direction. The scenario's own ``[current]`` is replaced by the
weather's.
"""

from __future__ import annotations

import dataclasses
import math
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

__all__ = ["CURRENT_DIRECTION_STEP", "CURRENT_SPEED_STEP", "DIRECTION_STEP", "MAX_GAP_DEG", "PART_SHAPES",
           "LimitsTable", "SeaLimits", "current_setups", "sea_limits", "table_limits", "wave_limits"]

#: Relative directions are rounded to this [deg]: hindcasts (NORA10, ERA5) give directions to 1° or coarser.
DIRECTION_STEP = 1.0

#: Two directions of a time-domain limits table further apart than this are not interpolated across [deg]: a
#: quarter of the compass (the shipped rare-event campaigns space their directions 30–45° apart).
MAX_GAP_DEG = 90.0

#: The current's nodes: speeds every CURRENT_SPEED_STEP [m/s], relative directions every CURRENT_DIRECTION_STEP
#: [deg]; a sea state's limit is interpolated between the four around its current (linear in the speed's square —
#: the drag is quadratic — and in direction). The steps are a compromise of cost (one screening per node, about
#: 0.5 s for ctv27) and accuracy: against the limit screened in the sea state's own current, 30 seeded currents up
#: to 1.5 m/s, mean error 0.87 %, largest 7.7 % (next to a current without a static equilibrium); with 30° steps
#: 2.8 % and 20 % (tests/site/test_current.py).
CURRENT_SPEED_STEP = 0.25
CURRENT_DIRECTION_STEP = 15.0

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


def _round_direction(beta):
    return np.mod(np.round(np.asarray(beta, dtype=float) / DIRECTION_STEP) * DIRECTION_STEP, 360.0)


def sea_limits(db: HydroDB, setup: LandingSetup, weather: Weather, landings_deg, *, current_setup=None,
               progress=None, **kw) -> SeaLimits:
    """The limit of each of ``weather``'s sea states at each landing (module docstring), each in its own current
    when the weather has one.

    Parameters
    ----------
    db, setup, weather, landings_deg
        As :func:`wave_limits` (``setup``: the scenario as it is, used where the weather has no current).
    current_setup : callable, optional
        ``current_setup(speed, relative_direction_deg) -> LandingSetup``: the landing in that current
        (:func:`current_setups`); required when the weather has a current.
    progress : callable, optional
        ``progress(done, total)`` over the current's nodes.
    **kw
        As :func:`wave_limits`.

    Returns
    -------
    SeaLimits
    """
    L = np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0
    if weather.current is None:
        return wave_limits(db, setup, weather, L, **kw)
    if current_setup is None:
        raise ValueError("the weather has a current: give current_setup (boatland.site.limits.current_setups)")
    return _in_current(db, weather, L, current_setup, progress, kw)


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
    parts = {} if spectra == "one" else weather.parts
    two = np.zeros(n, bool)
    for H, _, _ in parts.values():
        two |= H > 0
    # the (Tp, β, Hs², shape) components of each row × landing: one for a one-spectrum row, one per part else
    comps = []                                      # (row index, Tp, β (n_sel, L), Hs², shape name)
    one = ~two
    if one.any():
        comps.append((np.flatnonzero(one), weather.Tp[one], _round_direction(
            relative_direction(weather.from_deg[one][:, None], L[None, :])), np.ones(int(one.sum())), "sea"))
    for name, (H, T, d) in parts.items():
        rows = np.flatnonzero(two & (H > 0))
        comps.append((rows, T[rows], _round_direction(relative_direction(d[rows][:, None], L[None, :])),
                      H[rows] ** 2, name))
    betas = np.unique(np.concatenate([c[2].ravel() for c in comps]))
    tr = slip_transfer(db, setup, omega=omega, beta_deg=betas, method=method, mu=mu, thrust=thrust)
    depth = db.water_depth if water_depth is None else water_depth
    w = tr.omega
    R = tr.capacity.size
    G = (np.abs(tr.H) ** 2)[..., None] * (w[:, None, None, None] ** np.arange(3))     # (Nw, Nβ, R, 3)
    C = np.einsum("wbi,wbj->wbij", tr.H, tr.H.conj()).real                               # (Nw, Nβ, R, R)
    m = np.zeros((n, L.size, R, 3))
    cov = np.zeros((n, L.size, R, R))
    hs2 = np.where(two, 0.0, 1.0)                    # Σ Hs_p² of two-part rows; one-part rows per unit Hs²
    for rows, T, beta, weight, name in comps:
        shape = sea if name == "sea" else PART_SHAPES[name]
        uT, iT = np.unique(T, return_inverse=True)
        S, wt = unit_spectra(w, uT, sea=shape, water_depth=depth, g=db.g)
        SW = S * wt                                                              # (NT, Nw)
        ib = np.searchsorted(betas, beta)                                        # (n_sel, L)
        for b in np.unique(ib):
            sel_r, sel_l = np.nonzero(ib == b)
            Sw = SW[iT[sel_r]] * weight[sel_r, None]                             # (k, Nw)
            m[rows[sel_r], sel_l] += (Sw @ G[:, b].reshape(w.size, -1)).reshape(-1, R, 3)
            cov[rows[sel_r], sel_l] += (Sw @ C[:, b].reshape(w.size, -1)).reshape(-1, R, R)
        if name != "sea":
            hs2[rows] += weight
    m /= hs2[:, None, None, None]
    cov /= hs2[:, None, None, None]
    keep = distinct_events(m[..., 0], tr.capacity, correlation_matrix(cov), background=tr.background)
    T_row = np.repeat(weather.Tp, L.size)                                        # the sea's cycles (Rayleigh)
    table = limiting_hs(m.reshape(n * L.size, 1, R, 3), tr.capacity, T_row, [0.0], accept=p_acc,
                        statistics=statistics, access_duration=access_duration, method=method, names=tr.names,
                        keep=keep.reshape(n * L.size, 1, R), background=tr.background)
    lim = table.Hs.reshape(n, L.size)
    hs = np.where(two, np.sqrt(hs2), weather.Hs)
    with np.errstate(divide="ignore", invalid="ignore"):
        margin = lim / hs[:, None]
    beta_total = _round_direction(relative_direction(weather.from_deg[:, None], L[None, :]))
    return SeaLimits(Hs_limit=lim, margin=margin, beta_deg=beta_total, governing=table.governing.reshape(n, L.size),
                     two_spectra=two, landings_deg=L, accept=p_acc, access_duration=float(access_duration),
                     statistics=statistics, method=method, mu=float(tr.setup.mu), thrust=float(tr.setup.thrust))


def margin_text(margin: float) -> str:
    """A margin as planners read it: ``"1.35×"``, ``"∞"``."""
    return "∞" if math.isinf(margin) else f"{margin:.2f}×"


@dataclass(frozen=True, eq=False)
class LimitsTable:
    """The limiting Hs of a rare-event campaign per (Tp, relative direction) (module docstring).

    Attributes
    ----------
    Tp : ndarray, shape (NT,)
        Peak periods of its cases [s], increasing.
    beta_deg : ndarray, shape (Nβ,)
        Relative directions [deg] in [0, 360), increasing (mirrored ones included).
    Hs : ndarray, shape (NT, Nβ)
        Limiting Hs [m] (NaN: no case there).
    accept, access : float
        Its accepted probability per access and the access [s].
    incident : str
        Its incident definition, e.g. ``"slide > 0.2 m"``.
    name, store : str
        The campaign and its store.
    thrust, mu : float or None
        The push [N] and μ_s it ran.
    mirrored : bool
        Port/starboard mirrored directions were added.
    vessel : str
        The database its scenario names.
    """

    Tp: np.ndarray
    beta_deg: np.ndarray
    Hs: np.ndarray
    accept: float
    access: float
    incident: str
    name: str
    store: str
    thrust: float | None = None
    mu: float | None = None
    mirrored: bool = False
    vessel: str = ""

    @classmethod
    def read(cls, path, *, symmetric: bool | None = None) -> "LimitsTable":
        """Read a rare-event campaign store's ``/isee_limits``. ``symmetric``: mirror its directions port/starboard
        (None: when the database its inputs name is symmetric, :func:`~boatland.vessel.directions.
        port_starboard_symmetry`).

        Raises
        ------
        BoatlandInputError
            Not a store, no limits in it, its limits not over Tp and direction.
        """
        import json

        from boatland.campaign.report import read_store
        from boatland.errors import BoatlandInputError

        data = read_store(path)
        lim = data.get("isee_limits")
        if lim is None or lim.size == 0:
            raise BoatlandInputError(f"{path}: no limiting Hs in this store (a rare-event campaign, method = "
                                     "\"isee\" with an accept in its [isee] table, writes them)")
        fixed = json.loads(data["header"].get("inputs") or "{}")

        def column(key):
            col = f"axis: {key}"
            if col in lim.dtype.names:
                return np.asarray(lim[col], dtype=float)
            v = fixed.get(key.split(".")[-1])
            return np.full(lim.size, np.nan if v is None else float(v))
        T, b = column("sea.Tp"), np.mod(column("sea.relative_direction_deg"), 360.0)
        if not (np.all(np.isfinite(T)) and np.all(np.isfinite(b))):
            raise BoatlandInputError(f"{path}: its limits are not per peak period and relative direction (its "
                                     "campaign sweeps neither sea.Tp nor sea.relative_direction_deg, or holds "
                                     "them in another form)")
        uT, ub = np.unique(T), np.unique(b)
        H = np.full((uT.size, ub.size), np.nan)
        H[np.searchsorted(uT, T), np.searchsorted(ub, b)] = np.asarray(lim["limiting Hs"], dtype=float)
        if symmetric is None:
            symmetric = _symmetric_vessel(fixed.get("vessel"))
        mirrored = False
        if symmetric:
            mb = np.mod(360.0 - ub, 360.0)
            new = ~np.isin(np.round(mb, 6), np.round(ub, 6))
            if new.any():
                allb = np.concatenate([ub, mb[new]])
                allH = np.concatenate([H, H[:, new]], axis=1)
                order = np.argsort(allb)
                ub, H, mirrored = allb[order], allH[:, order], True
        name = data["plan"].get("name", "") or data["header"].get("campaign", "")
        return cls(Tp=uT, beta_deg=ub, Hs=H, accept=float(lim["accept"][0]),
                   access=float(fixed.get("access") or 1800.0), incident=lim["incident"][0].decode(), name=name,
                   store=str(path), thrust=fixed.get("thrust"), mu=fixed.get("mu_s"), mirrored=mirrored,
                   vessel=str(fixed.get("vessel") or ""))

    def at(self, Tp, beta_deg) -> np.ndarray:
        """The limiting Hs at (Tp, β) (broadcast), linear in Tp and in direction between the cases; NaN outside
        the table (Tp beyond its range, a direction not between two of its directions at most
        :data:`MAX_GAP_DEG` apart)."""
        T = np.asarray(Tp, dtype=float)
        b = np.mod(np.asarray(beta_deg, dtype=float), 360.0)
        T, b = np.broadcast_arrays(T, b)
        # direction: the bracket (j0, j1) and weight, periodic
        nb = self.beta_deg.size
        j1 = np.searchsorted(self.beta_deg, b, side="left") % nb
        j0 = (j1 - 1) % nb
        exact = np.isclose(self.beta_deg[j1], b, atol=1e-9, rtol=0)
        j0 = np.where(exact, j1, j0)
        gap = np.mod(self.beta_deg[j1] - self.beta_deg[j0], 360.0)
        off = np.mod(b - self.beta_deg[j0], 360.0)
        with np.errstate(invalid="ignore", divide="ignore"):
            wb = np.where(gap > 0, off / gap, 0.0)
        ok_b = exact | ((gap <= MAX_GAP_DEG) & (gap > 0))
        # period: linear inside the range
        nt = self.Tp.size
        i1 = np.clip(np.searchsorted(self.Tp, T, side="left"), 0, nt - 1)
        i0 = np.clip(i1 - 1, 0, nt - 1)
        texact = np.isclose(self.Tp[i1], T, rtol=1e-9, atol=0)
        i0 = np.where(texact, i1, i0)
        with np.errstate(invalid="ignore", divide="ignore"):
            wt = np.where(self.Tp[i1] > self.Tp[i0], (T - self.Tp[i0]) / (self.Tp[i1] - self.Tp[i0]), 0.0)
        ok_t = texact | ((T > self.Tp[0]) & (T < self.Tp[-1]))
        H = self.Hs
        h = ((1 - wt) * ((1 - wb) * H[i0, j0] + wb * H[i0, j1]) + wt * ((1 - wb) * H[i1, j0] + wb * H[i1, j1]))
        return np.where(ok_b & ok_t, h, np.nan)

    def describe(self) -> str:
        """One line: what the table is."""
        return (f"time domain ({self.name}, {self.store}): {self.incident}, {self.Tp.size} Tp "
                f"{self.Tp[0]:g}–{self.Tp[-1]:g} s × {self.beta_deg.size} directions"
                + (" (port/starboard mirrored)" if self.mirrored else ""))


def _symmetric_vessel(vessel) -> bool:
    """Whether the database ``vessel`` names (built-in name or path) is port/starboard symmetric; False when it
    cannot be read here."""
    if not vessel:
        return False
    try:
        from boatland.hydro import load_database
        from boatland.vessel.directions import port_starboard_symmetry

        return bool(port_starboard_symmetry(load_database(vessel)).symmetric)
    except Exception:  # noqa: BLE001 - unknown here: no mirroring (the table covers what it covers)
        return False


def table_limits(table: LimitsTable, weather: Weather, landings_deg) -> SeaLimits:
    """The limit of each of ``weather``'s sea states at each landing from a time-domain table (module docstring):
    the total sea's Hs, Tp and direction; not covered → NaN limit, not workable."""
    L = np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0
    beta = _round_direction(relative_direction(weather.from_deg[:, None], L[None, :]))
    lim = table.at(weather.Tp[:, None], beta)
    with np.errstate(invalid="ignore", divide="ignore"):
        margin = lim / weather.Hs[:, None]
    covered = np.isfinite(lim)
    return SeaLimits(Hs_limit=lim, margin=margin, beta_deg=beta,
                     governing=np.full(lim.shape, table.incident, dtype=object), two_spectra=np.zeros(weather.n, bool),
                     landings_deg=L, accept=table.accept, access_duration=table.access, statistics="time domain",
                     method="importance sampling", mu=math.nan if table.mu is None else float(table.mu),
                     thrust=math.nan if table.thrust is None else float(table.thrust), source=table.describe(),
                     covered=covered)


def current_setups(scenario, db: HydroDB, *, roll_limit_deg: float | None = None):
    """``at(speed, relative_direction_deg) -> LandingSetup``: the scenario's landing in that current (its own
    ``[current]`` replaced; speed 0: none at all), made once per node."""
    made: dict = {}

    def at(speed: float, relative_deg: float) -> LandingSetup:
        key = (round(float(speed), 9), round(float(relative_deg) % 360.0, 9) if speed > 0 else 0.0)
        if key not in made:
            sc = scenario.replace({"current": None} if key[0] == 0 else
                                  {"current.speed": key[0], "current.relative_direction_deg": key[1],
                                   "current.direction_deg": None})
            made[key] = LandingSetup.from_scenario(sc, db, roll_limit_deg=roll_limit_deg)
        return made[key]
    return at


def _in_current(db: HydroDB, weather: Weather, L: np.ndarray, current_setup, progress, kw) -> SeaLimits:
    """:func:`sea_limits` of a weather with a current (module docstring)."""
    U, frm = weather.current
    n = weather.n
    theta = np.mod(relative_direction(frm[:, None], L[None, :]), 360.0)              # (n, L), towards
    dU, dT = CURRENT_SPEED_STEP, CURRENT_DIRECTION_STEP
    nd = int(round(360.0 / dT))
    k0 = np.floor(U / dU + 1e-9).astype(int)
    u0, u1 = k0 * dU, (k0 + 1) * dU
    wu = np.clip((U ** 2 - u0 ** 2) / (u1 ** 2 - u0 ** 2), 0.0, 1.0)                 # (n,)
    j0 = np.floor(theta / dT + 1e-9).astype(int) % nd
    wt = np.clip((theta - j0 * dT) / dT, 0.0, 1.0)                                    # (n, L)
    corners = []                                   # (k (n,), j (n, L), weight (n, L))
    for dk, dj, w in ((0, 0, (1 - wu)[:, None] * (1 - wt)), (0, 1, (1 - wu)[:, None] * wt),
                      (1, 0, wu[:, None] * (1 - wt)), (1, 1, wu[:, None] * wt)):
        k = np.broadcast_to((k0 + dk)[:, None], wt.shape)
        j = np.where(k == 0, 0, (j0 + dj) % nd)                                       # speed 0: one node
        corners.append((k, j, w))
    nodes = sorted({(int(k), int(j)) for k, j, w in corners for k, j in zip(k[w > 0], j[w > 0])})
    current_setup(0.0, 0.0).near_pile(db)     # the pile's wave for every direction, once: each node's table reads it
    H = np.zeros((n, L.size))
    best_w = np.full((n, L.size), -1.0)
    gov = np.empty((n, L.size), dtype=object)
    base = None
    failed: list[str] = []
    for done, (k, j) in enumerate(nodes, 1):
        need = np.zeros((n, L.size), bool)
        for ck, cj, w in corners:
            need |= (ck == k) & (cj == j) & (w > 0)
        rows = np.flatnonzero(need.any(axis=1))
        try:
            lim = wave_limits(db, current_setup(k * dU, j * dT), weather.take(rows), L, **kw)
            node_H, node_gov = lim.Hs_limit, lim.governing
            if base is None:
                base = lim
        except ValueError as exc:        # no static equilibrium on the landing in this current: limit 0
            failed.append(f"{k * dU:g} m/s towards {j * dT:g}° ({exc})")
            node_H = np.zeros((rows.size, L.size))
            node_gov = np.full((rows.size, L.size), "no static equilibrium", dtype=object)
        for ck, cj, w in corners:
            m = (ck[rows] == k) & (cj[rows] == j) & (w[rows] > 0)
            r, c = np.nonzero(m)
            H[rows[r], c] += w[rows[r], c] * node_H[r, c]
            better = w[rows[r], c] > best_w[rows[r], c]
            best_w[rows[r][better], c[better]] = w[rows[r], c][better]
            gov[rows[r][better], c[better]] = node_gov[r[better], c[better]]
        if progress is not None:
            progress(done, len(nodes))
    two = np.zeros(n, bool)
    if kw.get("spectra", "auto") != "one":
        for Hp, _, _ in weather.parts.values():
            two |= Hp > 0
    hs = weather.Hs.copy()
    if two.any():
        hs[two] = np.sqrt(sum(np.where(two, Hp, 0.0) ** 2 for Hp, _, _ in weather.parts.values()))[two]
    with np.errstate(divide="ignore", invalid="ignore"):
        margin = H / hs[:, None]
    beta_total = _round_direction(relative_direction(weather.from_deg[:, None], L[None, :]))
    if base is None:                                   # no node could be screened: the scenario still says who
        base = wave_limits(db, current_setup(0.0, 0.0), weather.take([0]), L, **kw)
    note = (f"; no static equilibrium on the landing in {len(failed)} of these currents, e.g. {failed[0]}: limit 0 "
            "there (not workable), interpolated" if failed else "")
    return dataclasses.replace(
        base, Hs_limit=H, margin=margin, beta_deg=beta_total, governing=gov, two_spectra=two,
        source=f"{base.source}; each sea state in its own current (screened at {len(nodes)} nodes, every "
               f"{dU:g} m/s and {dT:g}°, interpolated){note}")
