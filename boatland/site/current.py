r"""Each sea state of a site's weather in its own tidal current: the screening at nodes of the current, the limit
interpolated between them (:func:`sea_limits`, the entry for any weather: without a current it is
:func:`boatland.site.limits.wave_limits`).

A tidal current changes the landed equilibrium (a current across the vessel uses up
friction before the waves do) and damps the motions (:mod:`boatland.loads.current`,
:mod:`boatland.freqdomain.currents`). When the weather has each sea state's current (speed and the compass
direction it comes from; relative to the vessel like the waves), the screening runs at nodes of current speed
and relative direction (:data:`CURRENT_SPEED_STEP`, :data:`CURRENT_DIRECTION_STEP`; the speed 0 node without any
current) for the sea states around each node, and a sea state's limit is interpolated between its four nodes —
linear in U² (the drag is quadratic) and in direction:

.. math:: H_{lim}(U, \theta) = \sum_{a,b \in \{0,1\}} w_a(U)\, v_b(\theta)\, H_{lim}(u_{k+a}, \vartheta_{j+b}),
          \quad w_1 = \frac{U^2 - u_k^2}{u_{k+1}^2 - u_k^2},\; v_1 = \frac{\theta - \vartheta_j}{\Delta\vartheta},

:math:`w_0 = 1 - w_1`, :math:`v_0 = 1 - v_1`. The scenario's own ``[current]`` is replaced by the weather's. A node
where the landing has no static equilibrium under the push and the current
(:class:`~boatland.landing.law.NoStaticEquilibrium`) has limit 0 there (not workable), said in the limits' source.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from boatland.freqdomain.landing import LandingSetup
from boatland.landing.law import NoStaticEquilibrium
from boatland.site.compass import relative_direction
from boatland.site.limits import SeaLimits, relative_directions, sea_heights, two_spectra_rows, wave_limits
from boatland.site.weather import Weather
from boatland.vessel.database import HydroDB

__all__ = ["CURRENT_DIRECTION_STEP", "CURRENT_SPEED_STEP", "current_setups", "sea_limits"]

#: The current's nodes: speeds every CURRENT_SPEED_STEP [m/s], relative directions every CURRENT_DIRECTION_STEP
#: [deg]; a sea state's limit is interpolated between the four around its current (linear in the speed's square —
#: the drag is quadratic — and in direction). The steps are a compromise of cost (one screening per node, about
#: 0.5 s for ctv27) and accuracy: against the limit screened in the sea state's own current, 30 seeded currents up
#: to 1.5 m/s, mean error 0.87 %, largest 7.7 % (next to a current without a static equilibrium); with 30° steps
#: 2.8 % and 20 % (tests/site/test_current.py).
CURRENT_SPEED_STEP = 0.25
CURRENT_DIRECTION_STEP = 15.0


def sea_limits(db: HydroDB, setup: LandingSetup, weather: Weather, landings_deg, *, current_setup=None,
               progress=None, **kw) -> SeaLimits:
    """The limit of each of ``weather``'s sea states at each landing (module docstring), each in its own current
    when the weather has one.

    Parameters
    ----------
    db, setup, weather, landings_deg
        As :func:`~boatland.site.limits.wave_limits` (``setup``: the scenario as it is, used where the weather
        has no current).
    current_setup : callable, optional
        ``current_setup(speed, relative_direction_deg) -> LandingSetup``: the landing in that current
        (:func:`current_setups`); required when the weather has a current.
    progress : callable, optional
        ``progress(done, total)`` over the current's nodes.
    **kw
        As :func:`~boatland.site.limits.wave_limits`.

    Returns
    -------
    SeaLimits
    """
    L = np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0
    if weather.current is None:
        return wave_limits(db, setup, weather, L, **kw)
    if current_setup is None:
        raise ValueError("the weather has a current: give current_setup (boatland.site.current.current_setups)")
    return _in_current(db, weather, L, current_setup, progress, kw)


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
    t = theta / dT
    j0 = np.floor(t + 1e-9).astype(int)
    wt = np.clip(t - j0, 0.0, 1.0)                                                    # (n, L)
    j0 = j0 % nd
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
        node_setup = current_setup(k * dU, j * dT)       # a scenario that cannot take this current says so here
        try:
            lim = wave_limits(db, node_setup, weather.take(rows), L, **kw)
            node_H, node_gov = lim.Hs_limit, lim.governing
            if base is None:
                base = lim
        except NoStaticEquilibrium as exc:        # the landing cannot hold in this current: limit 0
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
    two = two_spectra_rows(weather, kw.get("spectra", "auto"))
    hs = sea_heights(weather, two)
    with np.errstate(divide="ignore", invalid="ignore"):
        margin = H / hs[:, None]
    beta_total = relative_directions(weather.from_deg, L)
    if base is None:                                   # no node could be screened: the scenario still says who
        base = wave_limits(db, current_setup(0.0, 0.0), weather.take([0]), L, **kw)
    note = (f"; no static equilibrium on the landing in {len(failed)} of these currents, e.g. {failed[0]}: limit 0 "
            "there (not workable), interpolated" if failed else "")
    return dataclasses.replace(
        base, Hs_limit=H, margin=margin, beta_deg=beta_total, governing=gov, two_spectra=two,
        source=f"{base.source}; each sea state in its own current (screened at {len(nodes)} nodes, every "
               f"{dU:g} m/s and {dT:g}°, interpolated){note}")
