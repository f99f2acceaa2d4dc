r"""Each sea state of a site's weather in its own tidal current and wind: the screening's ingredients at nodes of
the flows, interpolated, and each sea state's limit solved from its own (:func:`sea_limits`, the entry for any
weather: without a current or a wind it is :func:`boatland.site.limits.wave_limits`).

The flows reach the landed vessel in three ways:

1. their steady loads — the current's drag at rest, the wind's mean load — set the landed equilibrium: each
   contact's static force :math:`J^0_c`, so the directions its margins are measured in (tilted onto the friction
   circle, :func:`~boatland.freqdomain.screening.slip_directions`) and their capacities :math:`a_{m,c}`
   (a current or wind across the vessel uses friction before the waves do);
2. the wind's gusts swing the vessel in its slow sway–yaw mode: a part of every margin that does not grow with
   the waves (:class:`~boatland.freqdomain.statistics.SlowSwing`: its moments, the linear share λ of its
   damping, its correlations) — at 10 m/s on the beam it takes ctv27's head-sea limit at Tp 7 s from 0.37 m to
   0.04 m;
3. the hull's drag, linearised about the current, damps the motions and so changes the waves' contact forces.

(3) is the costly part (the landed response at every wave frequency and direction), (1) and (2) are cheap (a
static solve and the response on the gusts' grid to one load pattern). And the waves' contact forces hardly
depend on the wind: taking them from the landing without wind moved ctv27's limits by at most 0.64 % for winds
up to 12 m/s from five directions (Tp 5, 7, 10 s; head to beam seas). So:

- at nodes of the **current** (speed every :data:`CURRENT_SPEED_STEP`, relative direction every
  :data:`CURRENT_DIRECTION_STEP`; none at speed 0), without wind, the cross-spectral moments of the contact
  forces and roll, :math:`v = (J_1, \dots, J_{N_p}, \phi)`, in every sea state at every landing
  (:func:`~boatland.site.limits.sea_moments`, per unit :math:`H_s^2`; two spectra where the weather has them):

  .. math:: C_k = \int \omega^k\,\mathrm{Re}\,(v\,v^H)\,S(\omega)\,d\omega, \qquad k = 0, 1, 2;

- at nodes of the current × the **wind** (speed every :data:`WIND_SPEED_STEP`, relative direction every
  :data:`WIND_DIRECTION_STEP`), the landing in both (:func:`flow_setups`): its margins' rows D and capacities a
  (:func:`~boatland.freqdomain.screening.margin_rows`) and its swing (:func:`~boatland.freqdomain.screening.
  slow_swing`);
- per sea state and landing the ingredients are interpolated between the nodes around its current and its wind,
  multilinearly — in the speed's square (the drag is quadratic) and in direction, weights :math:`w_q`:

  .. math:: m_{k,r} = \sum_q w_q\, d_{r,q}^\top C_{k,q}\, d_{r,q}, \quad a_r = \sum_q w_q a_{r,q}, \quad
            \sqrt{m^{swing}_{k,r}} = \sum_q w_q \sqrt{m^{swing}_{k,r,q}}

  (and the covariances alike; the swing's standard deviations are interpolated, as they grow with the gust force,
  :math:`\propto U^2`, from none at speed 0; its λ and correlations are the weighted mean over the nodes that have
  a swing), and its limit is solved from them
  (:func:`~boatland.freqdomain.statistics.limiting_hs`). The limit is a steep function of them (a margin's
  crossing rate goes as :math:`e^{-a^2/2\sigma^2}`) while they are smooth in the flows: interpolating them, not
  the limit, keeps the steepness where it belongs. Measured against the screening in the sea state's very
  current and wind (``tests/site/test_flows.py``): :data:`CURRENT_SPEED_STEP`, :data:`WIND_SPEED_STEP`.

The scenario's own ``[current]`` / ``[wind]`` is replaced by the weather's where the weather has one (their drag
coefficients and the gusts' spectrum kept) and acts in every sea state where it has not. A node where the landing
has no static equilibrium under the push and the flows (:class:`~boatland.landing.law.NoStaticEquilibrium`), or
where the skipper's trim cannot balance their yaw moment (:class:`~boatland.landing.environment.TrimImpossible`),
counts as limit 0: a sea state's limit is that of its other nodes' ingredients times their share of the weight,
and the limits' source says so.
"""

from __future__ import annotations

import numpy as np

from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import default_omega, margin_rows, slow_swing
from boatland.freqdomain.statistics import (ACCEPT_PRESETS, ACCESS_DURATION, DEFAULT_STATISTICS, SlowSwing,
                                            accept_probability, correlation_matrix, distinct_events, limiting_hs,
                                            response_names)
from boatland.landing.law import NoStaticEquilibrium
from boatland.sea.spectra import SpectrumPart
from boatland.site.compass import relative_direction
from boatland.site.limits import (SeaLimits, needed_directions, relative_directions, sea_heights, sea_moments,
                                  two_spectra_rows, wave_limits)
from boatland.site.weather import Weather
from boatland.vessel.database import HydroDB

__all__ = ["CURRENT_DIRECTION_STEP", "CURRENT_SPEED_STEP", "WIND_DIRECTION_STEP", "WIND_SPEED_STEP", "flow_setups",
           "sea_limits"]

#: The current's nodes: speeds every CURRENT_SPEED_STEP [m/s], relative directions every CURRENT_DIRECTION_STEP
#: [deg]. A node costs a landed response over the wave frequencies and directions (about 0.1 s for ctv27 once its
#: pile tables are made). Against the screening in the sea state's own current, 30 seeded currents up to 1.5 m/s
#: (tests/site/test_flows.py): mean error 0.09 %, largest 0.51 %.
CURRENT_SPEED_STEP = 0.25
CURRENT_DIRECTION_STEP = 15.0
#: The wind's nodes: speeds every WIND_SPEED_STEP [m/s], relative directions every WIND_DIRECTION_STEP [deg]. A
#: node costs the landing's statics and its swing in the gusts (about 0.09 s for ctv27). Against the screening in
#: the sea state's own wind, 30 seeded winds up to 12 m/s (tests/site/test_flows.py): mean error 0.35 %, largest
#: 1.9 % (with 15° steps 0.51 % and 3.8 %); with a current as well, 8 seeded pairs: 0.60 % and 3.3 %.
WIND_SPEED_STEP = 2.5
WIND_DIRECTION_STEP = 10.0
#: Cells (sea state × landing) whose limits are solved together, between two words of progress.
SOLVE_BLOCK = 4096


def flow_setups(scenario, db: HydroDB, *, roll_limit_deg: float | None = None):
    """``at(current, wind) -> LandingSetup``: the scenario's landing in a current and a wind, each ``(speed [m/s],
    relative direction it flows towards [deg])`` or None for the scenario's own (speed 0: none at all), made once
    per pair. May raise :class:`~boatland.landing.law.NoStaticEquilibrium`."""
    made: dict = {}

    def key_of(flow):
        if flow is None:
            return None
        speed, rel = (float(v) for v in flow)
        return (round(speed, 9), round(rel % 360.0, 9) if speed > 0 else 0.0)

    def at(current=None, wind=None) -> LandingSetup:
        key = (key_of(current), key_of(wind))
        if key not in made:
            changes = {}
            for what, k in zip(("current", "wind"), key):
                if k is None:
                    continue
                changes.update({what: None} if k[0] == 0 else
                               {f"{what}.speed": k[0], f"{what}.relative_direction_deg": k[1],
                                f"{what}.direction_deg": None})
            sc = scenario.replace(changes) if changes else scenario
            made[key] = LandingSetup.from_scenario(sc, db, roll_limit_deg=roll_limit_deg)
        return made[key]
    return at


def sea_limits(db: HydroDB, setup: LandingSetup, weather: Weather, landings_deg, *, flow_setup=None,
               progress=None, accept=ACCEPT_PRESETS["best"], statistics: str = DEFAULT_STATISTICS,
               method: str = "improved", sea: SpectrumPart | None = None, water_depth: float | None = None,
               access_duration: float = ACCESS_DURATION, mu: float | None = None, thrust: float | None = None,
               spectra: str = "auto", omega=None) -> SeaLimits:
    """The limit of each of ``weather``'s sea states at each landing (module docstring), each in its own current
    and wind when the weather has them.

    Parameters
    ----------
    db, setup, weather, landings_deg
        As :func:`~boatland.site.limits.wave_limits` (``setup``: the scenario as it is, used where the weather
        has neither a current nor a wind).
    flow_setup : callable, optional
        ``flow_setup(current, wind) -> LandingSetup`` (:func:`flow_setups`); required when the weather has a
        current or a wind.
    progress : callable, optional
        ``progress(done, total)`` over the nodes, then the blocks of sea states whose limits are solved.
    accept, statistics, method, sea, water_depth, access_duration, mu, thrust, spectra, omega
        As :func:`~boatland.site.limits.wave_limits`.

    Returns
    -------
    SeaLimits
    """
    L = np.atleast_1d(np.asarray(landings_deg, dtype=float)) % 360.0
    kw = dict(accept=accept, statistics=statistics, method=method, sea=sea, water_depth=water_depth,
              access_duration=access_duration, mu=mu, thrust=thrust, spectra=spectra, omega=omega)
    if weather.current is None and weather.wind is None:
        return wave_limits(db, setup, weather, L, **kw)
    if flow_setup is None:
        raise ValueError("the weather has a current or a wind: give flow_setup (boatland.site.flows.flow_setups)")
    if method != "improved":
        raise ValueError(f"method {method!r}: a sea state's own current and wind are for the 'improved' hinge")
    return _in_flows(db, weather, L, flow_setup, progress, kw)


def _corners(flow, L: np.ndarray, speed_step: float, direction_step: float):
    """The four nodes around each sea state's flow at each landing: [(speed index (n, L), direction index (n, L),
    weight (n, L))] — linear in the speed's square and in the relative direction (towards); at speed 0 one node.
    Without the flow: the scenario's own, one node (index −1) of weight 1."""
    n = L.size
    if flow is None:
        return None
    U, frm = flow
    shape = (U.size, n)
    theta = np.mod(relative_direction(frm[:, None], L[None, :]), 360.0)
    nd = int(round(360.0 / direction_step))
    k0 = np.floor(U / speed_step + 1e-9).astype(int)
    u0, u1 = k0 * speed_step, (k0 + 1) * speed_step
    wu = np.clip((U ** 2 - u0 ** 2) / (u1 ** 2 - u0 ** 2), 0.0, 1.0)[:, None]
    t = theta / direction_step
    j0 = np.floor(t + 1e-9).astype(int)
    wt = np.clip(t - j0, 0.0, 1.0)
    j0 = j0 % nd
    out = []
    for dk, dj, w in ((0, 0, (1 - wu) * (1 - wt)), (0, 1, (1 - wu) * wt), (1, 0, wu * (1 - wt)), (1, 1, wu * wt)):
        k = np.broadcast_to((k0 + dk)[:, None], shape)
        out.append((k, np.where(k == 0, 0, (j0 + dj) % nd), w))
    return out


def _in_flows(db: HydroDB, weather: Weather, L: np.ndarray, flow_setup, progress, kw) -> SeaLimits:
    """:func:`sea_limits` of a weather with a current or a wind (module docstring)."""
    n, nL = weather.n, L.size
    p_acc = accept_probability(kw["accept"])
    own = [(np.full((n, nL), -1), np.zeros((n, nL), int), np.ones((n, nL)))]
    cur = _corners(weather.current, L, CURRENT_SPEED_STEP, CURRENT_DIRECTION_STEP) or own
    wnd = _corners(weather.wind, L, WIND_SPEED_STEP, WIND_DIRECTION_STEP) or own

    def flow_of(k, j, speed_step, direction_step):
        return None if k < 0 else (k * speed_step, j * direction_step)

    # the nodes each sea state × landing needs: (current node, wind node) → cells and weights
    pairs: dict = {}
    for ck, cj, cw in cur:
        for wk, wj, ww in wnd:
            w = cw * ww
            r, c = np.nonzero(w > 0)
            if not r.size:
                continue
            keys = np.stack([ck[r, c], cj[r, c], wk[r, c], wj[r, c]], axis=1)
            uniq, inv = np.unique(keys, axis=0, return_inverse=True)
            for q, key in enumerate(map(tuple, uniq)):
                sel = inv.ravel() == q
                pairs.setdefault(key, []).append((r[sel], c[sel], w[r[sel], c[sel]]))
    currents = sorted({k[:2] for k in pairs})
    N = n * nL
    blocks = -(-N // SOLVE_BLOCK)
    total = len(currents) + len(pairs) + blocks
    done = 0

    def tick():
        nonlocal done
        done += 1
        if progress is not None:
            progress(done, total)
    base = flow_setup(None, None)
    base.near_pile(db)         # the pile's wave for every direction, once: each node's tables read it
    omega = default_omega(db) if kw["omega"] is None else np.asarray(kw["omega"], dtype=float)
    depth = db.water_depth if kw["water_depth"] is None else kw["water_depth"]
    mu, thrust = kw["mu"], kw["thrust"]

    def adjusted(s: LandingSetup) -> LandingSetup:
        if mu is None and thrust is None:
            return s
        return s.replace(mu=s.mu if mu is None else mu, thrust=s.thrust if thrust is None else thrust)

    R = 4 * base.n_points + 1
    M = np.zeros((n, nL, R, 3))
    COV = np.zeros((n, nL, R, R))
    CAP = np.zeros((n, nL, R))
    SQ = np.zeros((n, nL, R, 3))               # Σ w √m of the swing's moments (its σ scales as the force: U²)
    SW = np.zeros((n, nL))                     # Σ w of the nodes with a swing (λ and correlations are theirs)
    LAM = np.zeros((n, nL))
    COR = np.zeros((n, nL, R, R))
    failed_w = np.zeros((n, nL))
    failed: list[str] = []
    swing_any = False
    names = response_names(R)
    for ck, cj in currents:
        current = flow_of(ck, cj, CURRENT_SPEED_STEP, CURRENT_DIRECTION_STEP)
        mine = {k: v for k, v in pairs.items() if k[:2] == (ck, cj)}
        rows = np.unique(np.concatenate([r for v in mine.values() for r, _, _ in v]))
        where = np.full(n, -1)
        where[rows] = np.arange(rows.size)
        wave = None
        try:
            # the waves' contact forces at this current, without the weather's wind (the scenario's own where the
            # weather has none)
            s_c = adjusted(flow_setup(current, None if weather.wind is None else (0.0, 0.0)))
            sub = weather.take(rows)
            r = s_c.response(db, omega, needed_directions(sub, L, kw["spectra"]))
            V = np.concatenate([r.J.reshape(*r.J.shape[:2], -1), r.x[..., 3:4]], axis=-1)      # (Nw, Nβ, 3Np + 1)
            _, C, _ = sea_moments(sub, L, r.omega, V, r.beta_deg, spectra=kw["spectra"], sea=kw["sea"],
                                  water_depth=depth, g=db.g, cross_orders=(0, 1, 2))
            wave = C
        except NoStaticEquilibrium as exc:
            failed.append(_where(current, None, exc))
        tick()
        for (_, _, wk, wj), cells in mine.items():
            wind = flow_of(wk, wj, WIND_SPEED_STEP, WIND_DIRECTION_STEP)
            # one entry per cell: two corners can be one node (at speed 0 the directions are one node)
            flat = np.concatenate([c[0] * nL + c[1] for c in cells])
            cell, inv = np.unique(flat, return_inverse=True)
            ww = np.bincount(inv.ravel(), weights=np.concatenate([c[2] for c in cells]))
            rr, ll = cell // nL, cell % nL
            try:
                if wave is None:                       # no equilibrium in this current: said above
                    raise NoStaticEquilibrium
                s = adjusted(flow_setup(current, wind))
                J0 = s.response(db, omega[:1], np.array([0.0])).J_static
                D, a = margin_rows(s, J0)
                swing = slow_swing(db, s, J0)
            except NoStaticEquilibrium as exc:
                if wave is not None:
                    failed.append(_where(current, wind, exc))
                failed_w[rr, ll] += ww                 # (cells unique: += is safe)
                tick()
                continue
            Dm = _margin_map(D)                                   # (R, 3Np + 1)
            Cq = wave[where[rr], ll]                              # (k, K, K, 3)
            M[rr, ll] += ww[:, None, None] * np.einsum("rk,nkjo,rj->nro", Dm, Cq, Dm)
            COV[rr, ll] += ww[:, None, None] * np.einsum("ik,nkj,lj->nil", Dm, Cq[..., 0], Dm)
            CAP[rr, ll] += ww[:, None] * a[None]
            if swing is not None:
                swing_any = True
                SQ[rr, ll] += ww[:, None, None] * np.sqrt(np.maximum(swing.moments, 0.0))[None]
                SW[rr, ll] += ww
                LAM[rr, ll] += ww * swing.linear_share
                COR[rr, ll] += ww[:, None, None] * swing.correlation[None]
            tick()
    healthy = 1.0 - failed_w
    ok = healthy > 1e-12
    scale = np.where(ok, 1.0 / np.where(ok, healthy, 1.0), 0.0)
    M *= scale[..., None, None]
    COV *= scale[..., None, None]
    CAP *= scale[..., None]
    BG = (SQ * scale[..., None, None]) ** 2
    has = SW > 1e-12
    LAM = np.where(has, LAM / np.where(has, SW, 1.0), 1.0)
    COR = np.where(has[..., None, None], COR / np.where(has, SW, 1.0)[..., None, None], 1.0)
    keep = distinct_events(M[..., 0], CAP, correlation_matrix(COV),
                           background=SlowSwing(BG, LAM, COR) if swing_any else None).reshape(N, 1, R)
    M, CAP, BG, LAM, COR = M.reshape(N, 1, R, 3), CAP.reshape(N, 1, R), BG.reshape(N, 1, R, 3), LAM.reshape(N, 1), \
        COR.reshape(N, 1, R, R)
    T_row = np.repeat(weather.Tp, nL)
    Hs, governing = np.empty(N), np.empty(N, dtype=object)
    for b in range(blocks):            # each cell solved on its own: in blocks, to say how far it is
        i = slice(b * SOLVE_BLOCK, min(N, (b + 1) * SOLVE_BLOCK))
        table = limiting_hs(M[i], CAP[i], T_row[i], [0.0], accept=p_acc, statistics=kw["statistics"],
                            access_duration=kw["access_duration"], method=kw["method"], names=names, keep=keep[i],
                            background=SlowSwing(BG[i], LAM[i], COR[i]) if swing_any else None)
        Hs[i], governing[i] = table.Hs[:, 0], table.governing[:, 0]
        tick()
    H = np.where(ok, Hs.reshape(n, nL) * healthy, 0.0)
    gov = np.where(ok, governing.reshape(n, nL), "no static equilibrium").astype(object)
    two = two_spectra_rows(weather, kw["spectra"])
    hs = sea_heights(weather, two)
    with np.errstate(divide="ignore", invalid="ignore"):
        margin = H / hs[:, None]
    what = " and ".join(w for w, f in (("current", weather.current), ("wind", weather.wind)) if f is not None)
    steps = "; ".join(s for s, f in ((f"current every {CURRENT_SPEED_STEP:g} m/s and {CURRENT_DIRECTION_STEP:g}°",
                                      weather.current),
                                     (f"wind every {WIND_SPEED_STEP:g} m/s and {WIND_DIRECTION_STEP:g}°", weather.wind))
                      if f is not None)
    note = (f"; the landing cannot be held (no static equilibrium, or no trim against the yaw moment) at "
            f"{len(failed)} of these nodes, e.g. {failed[0]}: limit 0 there, the sea state's limit scaled by its "
            "other nodes' weight" if failed else "")
    return SeaLimits(Hs_limit=H, margin=margin, beta_deg=relative_directions(weather.from_deg, L), governing=gov,
                     two_spectra=two, landings_deg=L, accept=p_acc, access_duration=float(kw["access_duration"]),
                     statistics=kw["statistics"], method=kw["method"], mu=float(adjusted(base).mu),
                     thrust=float(adjusted(base).thrust),
                     source=f"frequency-domain screening: a slip onset (or roll beyond its limit); each sea state in "
                            f"its own {what} (nodes: {steps}; {len(currents)} current and {len(pairs)} current × wind "
                            f"nodes, the ingredients interpolated){note}")


def _margin_map(D: np.ndarray) -> np.ndarray:
    """(4 Np + 1, 3 Np + 1): the margins and roll as rows acting on v = (J_1, …, J_Np, roll)."""
    n_p = D.shape[0]
    out = np.zeros((4 * n_p + 1, 3 * n_p + 1))
    for c in range(n_p):
        out[4 * c:4 * c + 4, 3 * c:3 * c + 3] = D[c]
    out[-1, -1] = 1.0
    return out


def _where(current, wind, exc) -> str:
    """A node in words, for the limits' source."""
    parts = [f"current {current[0]:g} m/s towards {current[1]:g}°" if current else "",
             f"wind {wind[0]:g} m/s towards {wind[1]:g}°" if wind else ""]
    said = ", ".join(p for p in parts if p) or "the scenario's own flows"
    return f"{said} ({exc})"
