r"""Campaigns by importance sampling of elementary events (ISEE; Au & Beck 2001): rare slips in minutes,
and the limiting Hs at an accepted risk, from the time domain.

A Monte Carlo campaign needs about :math:`(1.96/0.2)^2/p` trials for ±20 % (95 %) at probability p — 10⁶
accesses at p = 10⁻⁴. Before its first slip the landed vessel is linear and the sea Gaussian, so "a
slip within the access" is a union of half-spaces in the space of the sea's standard-normal
coefficients u (:mod:`boatland.freqdomain.margins`), whose elementary events (one margin exceeded at
one step) have closed-form probabilities. ISEE draws u from the mixture of their conditional
densities (:mod:`boatland.freqdomain.isee`) and weights each sample by :math:`\bar P/N(u)`.

Per sample (:func:`execute_sample`): u drawn for the case's sea at the run's Hs; the linear model's
indicators (:class:`~boatland.freqdomain.margins.Indicators`); and the **full time-domain trial on
exactly that sea** (:class:`~boatland.sea.gaussian.GaussianSea` handed to
:func:`~boatland.trial.simulate.simulate`), whose incidents — first slip, slip distance, roll after a
slip, contact loss — are what is estimated: :math:`\hat P(G) = \bar P\,\overline{1_G/N}` is unbiased for
every incident G inside the sampling domain D. D is the inscribed M-gon of the friction circle with a
guard κ (so that the time domain's slips, whose stuck forces differ from the linear ones by ≲ 0.15
standard deviations of a margin, lie inside it); every row says whether the linear model slipped too,
so a time-domain slip outside the linear first slip is visible.

Access. The time domain starts from rest: thrust ramp, wave ramp (the waves reach full height at
:func:`~boatland.trial.simulate.exposure_start`), then ``settle`` seconds more (the landed roll modes
ring after the ramp), then the access. Incidents count from the access start (:func:`access_incidents`)
in both the estimate and the brute-force checks; the run lasts exposure start + settle + access.

Runs, batches, stopping. A run is one case at one Hs ("level"). Its samples are drawn in batches of
``batch``; after each whole batch the run stops when its estimate of ``incident`` has a coefficient of
variation ≤ ``target_cov`` (and at least ``min_samples``), or at ``max_samples``. Decisions use only
whole batches of samples 0 … n−1 — every sample's u comes from its own seed,
``SeedSequence(master_seed, spawn_key=(ISEE_KEY, case, level, sample))`` — so a store is the same bit for
bit from 1 or N workers or Dask, and a killed campaign resumes to the same result.

Limiting Hs at an accepted probability (``accept``; :func:`limit_fit`). For a fixed spectral shape every
margin's standard deviation is ∝ Hs, so :math:`\log P \approx c - \beta^2/2 \propto -1/H_s^2`. Rice's
bound R(Hs) of the linear model (:meth:`~boatland.freqdomain.margins.LandedMargins.rice_bound`,
analytic at any Hs) has that shape with the right prefactor; the time-domain estimates P_j at the levels
Hs_j fit

.. math:: \log P(H_s) = \log R(H_s) + c_0 + c_1 / H_s^2

(c₁ = 0 with one level; weighted by 1/CoV²). Level 0 is where R = accept; each next level where the fit
says P = accept, until two levels bracket it (or the nearest level's interval holds it) or ``levels``
runs. The interval refits the levels' 95 % bounds in logarithms (:math:`\log\hat P \pm 1.96\,\delta`,
all to the same side: conservative). With ``limit_width`` the search then narrows the limit: while its interval
is wider than ± that fraction, the level nearest the accepted P gets another batch (decided, like everything
here, on whole batches only), so each case gets the samples its own interval needs — the whole scatter to ±3 %
with 40–140 samples a case instead of a fixed CoV's 80–120 (bench/README.md).

Reference: Au, S. K. & Beck, J. L. (2001), *First excursion probabilities for linear systems by very
efficient importance sampling*, Probabilistic Engineering Mechanics 16(3), 193–207; Grøtting, H. (2015),
*Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc thesis, NTNU (Table 2.1:
accepted probabilities per access).
"""

from __future__ import annotations

import json
import math
import time
import traceback
import warnings
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
from scipy.special import ndtri

from boatland.campaign.labels import campaign_inputs
from boatland.campaign.plan import Campaign
from boatland.campaign.executor import Executor, Shared, check_scheduler_address
from boatland.campaign.plan import plan_json
from boatland.campaign.prepare import (case_sensitivity, check_cases, checked_inputs, database_for, memory_key,
                                       worker_context)
from boatland.campaign.runner import completed, incident_names, summary_row
from boatland.campaign.store import INCIDENT_PREFIX, CampaignStore
from boatland.errors import BoatlandInputError
from boatland.freqdomain.isee import IseeEstimate, draw, estimate
from boatland.freqdomain.margins import LandedMargins, landed_margins
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import slip_transfer
from boatland.freqdomain.statistics import (distinct_events, incident_probability, response_correlation,
                                            spectral_moments)
from boatland.freqdomain.statistics import limiting_hs as fd_limiting_hs
from boatland.landing.setup import Setup
from boatland.sea.gaussian import GaussianSea
from boatland.sea.spectra import SHAPES
from boatland.sea.states import SeaState
from boatland.reproducible import single_threaded
from boatland.trial.incidents import parse_incident
from boatland.trial.simulate import exposure_start

__all__ = ["ISEE_FIELDS", "ISEE_KEY", "LevelModel", "SampleSpec", "access_incidents", "execute_sample",
           "level_model", "level_scenario", "limit_fit", "run_estimates", "run_isee", "sample_seed", "trial_number",
           "worst_samples", "rerun_sample"]

#: First element of every sample's spawn key (keeps ISEE streams apart from the Monte Carlo seeds).
ISEE_KEY = 0x15EE
#: Last element of a sample's gust stream's spawn key (:func:`sample_gust_seed`; ASCII "GU").
GUST_KEY = 0x4755
#: Trial numbers: ((case × MAX_LEVELS) + level) × MAX_SAMPLES + sample.
MAX_LEVELS, MAX_SAMPLES = 16, 100_000
CONFIDENCE = 0.95
LINEAR = ("linear first slip", "linear square", "linear first incident")

#: The store's extra columns of an ISEE campaign (name, numpy type, meaning).
ISEE_FIELDS = (
    ("level", "i8", "ISEE: the run's level along Hs (0, 1, …)"),
    ("hs", "f8", "ISEE: [m] significant wave height of the run"),
    ("isee_event", "i8", "ISEE: the elementary event the sample was drawn from (margin × steps + step)"),
    ("isee_margin", "S16", "ISEE: its margin (contact c, direction d, or roll±)"),
    ("isee_t", "f8", "[s] its time from the access start"),
    ("isee_n", "i8", "ISEE: N(u), elementary events of the sampling domain exceeded (≥ 1)"),
    ("isee_log_pbar", "f8", "ISEE: log of the sum of the elementary probabilities (the weight is exp(this)/N)"),
    ("lin_first_slip", "i8", "linear model: |f_t| > μ f_n at some step of the access (1/0)"),
    ("lin_square", "i8", "linear model: one of the screening's four margins at μ exceeded (1/0)"),
    ("lin_first_incident", "i8", "linear model: slip, contact loss or roll beyond the limit (1/0)"),
    ("lin_t_first_slip", "f8", "[s] the linear first slip, from the access start"),
    ("events", "S200", "the trial's first events in the access: time from its start, kind, contact"),
)


def trial_number(case: int, level: int, sample: int) -> int:
    return (case * MAX_LEVELS + level) * MAX_SAMPLES + sample


def sample_gust_seed(scenario, ss: np.random.SeedSequence) -> int | None:
    """The seed of a sample's wind gusts: a child stream of the sample's seed sequence ``ss``, so that every
    sample meets its own gusts (the sampler draws the waves only; the gusts are plain Monte Carlo within it);
    None without gusty wind — the scenario's seed then, which changes nothing."""
    if scenario.wind is None or not scenario.wind.gusty:
        return None
    child = np.random.SeedSequence(ss.entropy, spawn_key=(*ss.spawn_key, GUST_KEY))
    return int(child.generate_state(1, dtype=np.uint32)[0])


def sample_seed(master_seed: int, case: int, level: int, sample: int, plain: bool = False) -> np.random.SeedSequence:
    """The seed sequence of one sample (module docstring); ``plain``: of a plain Monte Carlo sample of the same
    sea (:func:`execute_sample`), a stream of its own."""
    return np.random.SeedSequence(master_seed, spawn_key=(ISEE_KEY + int(plain), case, level, sample))


@dataclass(frozen=True)
class SampleSpec:
    """One sample: its store row ``trial``, case, level, the level's Hs and the sample number."""

    trial: int
    case: int
    level: int
    hs: float
    sample: int


# ------------------------------------------------------------------------------------ one case at one Hs
def _has_hs(campaign: Campaign) -> bool:
    sea = campaign.base.sea
    return sea is not None and "Hs" in (campaign.base.document.get("sea") or {})


def level_scenario(campaign: Campaign, case: int, hs: float | None):
    """The case's scenario at significant wave height ``hs`` (None: the case's own), lasting exposure start +
    settle + access."""
    changes = dict(campaign.cases[case].values)
    if hs is not None:
        changes["sea.Hs"] = float(hs)
    sc = campaign.base.replace(changes) if changes else campaign.base
    access = campaign.access if campaign.access is not None else sc.simulation.duration - exposure_start(sc)
    if not access > 0:
        raise BoatlandInputError(f"{campaign.source}: duration: the access must be > 0 s (the scenario ends before "
                                 "the waves reach full height)")
    return sc.replace({"simulation.duration": exposure_start(sc) + campaign.isee.settle + access})


@dataclass(frozen=True, eq=False)
class LevelModel:
    """What the samples of one run share: the scenario at the run's Hs, the sea's grid, the linear
    margins and the access start ``t_access`` [s]; ``setup`` the scenario on its vessel."""

    scenario: object
    sea: GaussianSea
    margins: LandedMargins
    t_access: float
    setup: Setup


def level_model(campaign: Campaign, case: int, hs: float | None, db, reference: LandedMargins | None = None,
                hs_reference: float | None = None) -> LevelModel:
    """The :class:`LevelModel` of ``case`` at ``hs``; with a ``reference`` model of the same case at
    ``hs_reference`` its margins are scaled (:meth:`LandedMargins.scaled`) instead of solved again."""
    sc = level_scenario(campaign, case, hs)
    setup = Setup.of(sc, db)
    waves = setup.waves
    if not isinstance(waves, SeaState):
        raise BoatlandInputError(f"{campaign.source}: method isee needs a spectral sea (spectral parts: "
                                 f"{', '.join(s.label for s in SHAPES.values())}); "
                                 f"case {case} has {type(waves).__name__}")
    dt, n = setup.dt, setup.n_steps
    sea = GaussianSea(sea=waves, dt=dt, n_steps=n)
    t_a = exposure_start(sc) + campaign.isee.settle
    if reference is not None and hs_reference is not None and hs is not None:
        margins = reference.scaled(hs / hs_reference)
    else:
        landing = LandingSetup.from_scenario(sc, db, setup=setup)
        x0, y0, _ = setup.start_pose
        margins = landed_margins(db, landing, sea, x0=x0, y0=y0, first_step=int(math.ceil(t_a / dt - 1e-9)),
                                 kappa=campaign.isee.kappa, directions=campaign.isee.directions)
    return LevelModel(scenario=sc, sea=sea, margins=margins, t_access=float(margins.steps[0] * dt), setup=setup)


def _case_hs(campaign: Campaign, case: int) -> float | None:
    if not _has_hs(campaign):
        return None
    sc = campaign.base.replace(dict(campaign.cases[case].values)) if campaign.cases[case].values else campaign.base
    return float(sc.sea.waves.parts[0].Hs)


def _models(ctx: dict, campaign: Campaign, case: int, hs: float, loaders) -> LevelModel:
    """The run's model, cached per process: the case's margins are solved once (at its own Hs) and scaled."""
    key = (case, float(hs))
    cache = ctx.setdefault("isee", {})
    if key not in cache:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            db = database_for(level_scenario(campaign, case, None), ctx["db"], loaders[1])
            ref = cache.get(("ref", case))
            if ref is None:
                h0 = _case_hs(campaign, case)
                ref = (level_model(campaign, case, h0, db), h0)
                cache[("ref", case)] = ref
            if ref[1] is None or float(hs) == ref[1]:
                model = ref[0]
            else:
                model = level_model(campaign, case, hs, db, ref[0].margins, ref[1])
        cache[key] = model
    return cache[key]


# ------------------------------------------------------------------------------------ one sample
def access_incidents(result, t_access: float, names) -> dict[str, float]:
    """Time [s] from the access start of each incident definition's first occurrence in the access
    (NaN: none; :meth:`boatland.trial.incidents.Incident.in_access`): the first stick→slip at or after
    ``t_access``; slip distance or roll beyond its limit at some step from ``t_access`` on; contact lost
    (or slid off the landing) from ``t_access`` on — or before it, if the trial ended there."""
    out: dict[str, float] = {}
    for name in names:
        v = parse_incident(name).in_access(result, t_access)
        out[name] = math.nan if v is None else max(0.0, float(v) - t_access)
    return out


def _events_text(result, t_access: float) -> str:
    ev = [e for e in result.events if e.t >= t_access - 1e-9]
    return "; ".join(f"{e.t - t_access:.2f} {e.kind} c{e.contact}" for e in ev[:6])[:200]


def execute_sample(campaign: Campaign, spec: SampleSpec, loaders, plain: bool = False, dbs: dict | None = None) -> dict:
    """One ISEE sample of ``campaign``: draw u, the linear indicators, the time-domain
    trial on exactly that sea; its store row (status −1 and the error if it failed; never raises).

    ``plain``: a plain Monte Carlo sample of the same Gaussian sea instead, u ~ N(0, I) (the brute force
    the estimator is checked against): ``isee_event`` −1, ``isee_log_pbar`` NaN, ``isee_n`` the elementary
    events of D it exceeds (0 if none: then the linear model sees no slip, and a time-domain incident there
    would lie outside the sampling domain). ``dbs``: the databases by key as the campaign read them (a Dask
    worker never reads the files; local workers inherit them)."""
    from boatland.checks.memory import check_radiation
    from boatland.trial.simulate import BlowUpError, motion_arrays, simulate

    wall0 = time.perf_counter()
    row = {"trial": spec.trial, "case": spec.case, "seed_index": spec.sample, "level": spec.level, "hs": spec.hs}
    ss = sample_seed(0, 0, 0, 0)
    with single_threaded():
        try:
            ctx = worker_context(campaign, loaders)
            for key, db in (dbs or {}).items():    # as the campaign read them (Dask): never the files again
                ctx["db"].setdefault(key, db)
            names = incident_names(campaign)
            ss = sample_seed(campaign.master_seed, spec.case, spec.level, spec.sample, plain)
            model = _models(ctx, campaign, spec.case, spec.hs, loaders)
            lm = model.margins
            if plain:
                u, e, log_pbar = np.random.default_rng(ss).standard_normal(lm.dim), -1, math.nan
                ind = lm.indicators(u)
                r, k = -1, 0
            else:
                u, e, log_pbar = draw(lm, np.random.default_rng(ss))
                ind = lm.indicators(u, e)
                r, k = divmod(e, lm.n_steps)
            row.update({"isee_event": int(e), "isee_margin": lm.names[r] if r >= 0 else "",
                        "isee_t": float(lm.steps[k] * lm.dt - model.t_access) if r >= 0 else math.nan,
                        "isee_n": ind.n_exceeded,
                        "isee_log_pbar": float(log_pbar), "lin_first_slip": int(ind.first_slip),
                        "lin_square": int(ind.square), "lin_first_incident": int(ind.first_incident),
                        "lin_t_first_slip": ind.t_first_slip - model.t_access})
            sc = model.scenario
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                dbkey = sc.vessel.database_key
                db = ctx["db"][dbkey]
                mkey = memory_key(dbkey, sc.radiation)
                setup = Setup.of(sc, db, model.setup)
                if mkey not in ctx["memory"]:
                    ctx["memory"][mkey] = setup.memory()
                if spec.case not in ctx["checked"]:
                    check_radiation(setup, ctx["memory"][mkey])
                    ctx["checked"].add(spec.case)
                akey = (mkey, setup.dt)
                if akey not in ctx["arrays"]:                # the kernel's arrays: the same for every sample
                    ctx["arrays"][akey] = motion_arrays(setup, ctx["memory"][mkey])
                try:
                    result = simulate(sc, db, arrays=ctx["arrays"][akey], waves=model.sea.with_u(u), setup=setup,
                                      gust_seed=sample_gust_seed(sc, ss))
                except BlowUpError as exc:
                    result = exc.result
            row.update(_sample_row(result, model.t_access, names))
        except Exception as exc:  # a failing sample is recorded, never aborts the campaign
            last = traceback.extract_tb(exc.__traceback__)[-1] if exc.__traceback__ else None
            where = f" ({Path(last.filename).name}:{last.lineno})" if last else ""
            row.update({"status": -1, "message": f"{type(exc).__name__}: {exc}{where}"[:200]})
    state = ss.generate_state(2, dtype=np.uint32)
    row["seed"] = int((int(state[0]) << 31) ^ int(state[1]))
    row["wall_time"] = time.perf_counter() - wall0
    return row


def _sample_row(result, t_access: float, names) -> dict:

    row = summary_row(result, t_access, result.t[-1], names)
    times = access_incidents(result, t_access, names)
    for name in names:
        row[INCIDENT_PREFIX + name] = times[name]
    row["time_to_first_slip"] = times.get("first slip", math.nan)
    row["events"] = _events_text(result, t_access)
    return row


# ------------------------------------------------------------------------------------ estimates
def run_estimates(rows: np.ndarray, names, confidence: float = CONFIDENCE) -> dict[str, IseeEstimate]:
    """The estimates of one run from its (completed) sample rows: every incident definition, the linear
    model's first slip, square and first incident, and the sampling domain D itself."""
    if rows.size == 0:
        return {}
    n_ex = rows["isee_n"].astype(float)
    log_pbar = float(rows["isee_log_pbar"][0])
    out = {"domain": estimate(1.0 / n_ex, log_pbar, confidence)}
    for name in names:
        out[name] = estimate(np.isfinite(rows[INCIDENT_PREFIX + name]) / n_ex, log_pbar, confidence)
    for name, col in zip(LINEAR, ("lin_first_slip", "lin_square", "lin_first_incident")):
        out[name] = estimate(rows[col] / n_ex, log_pbar, confidence)
    return out


def _completed(rows: np.ndarray) -> np.ndarray:

    return rows[completed(rows)] if rows.size else rows


def _log_bounds(est: IseeEstimate, z: float) -> tuple[float, float, float]:
    """(log P, log lower, log upper) by the delta method in logarithms (log P̂ ± z δ)."""
    lp = math.log(est.p)
    w = z * est.cov if math.isfinite(est.cov) else math.inf
    return lp, lp - w, lp + w


def limit_fit(hs, est, log_rice, target: float, z: float = ndtri(0.5 + CONFIDENCE / 2)):
    r"""Limiting Hs at probability ``target`` from estimates at levels ``hs`` (module docstring):
    :math:`\log P = \log R(H_s) + c_0 + c_1/H_s^2` through the levels with P > 0.

    Parameters
    ----------
    hs : sequence of float
    est : sequence of IseeEstimate
    log_rice : callable
        log R(Hs).
    target : float

    Returns
    -------
    (h, lo, hi) : floats
        The limiting Hs and its interval (refits of the levels' lower / upper bounds); NaN where no level
        has an incident or no Hs reaches the target within ±×3 of the levels.
    """
    pts = [(h, _log_bounds(e, z), e.cov) for h, e in zip(hs, est) if e.p > 0 and math.isfinite(e.cov)]
    if not pts:
        return math.nan, math.nan, math.nan
    h = np.array([p[0] for p in pts])
    w = np.array([1.0 / max(p[2], 1e-3) ** 2 for p in pts])
    lr = np.array([log_rice(x) for x in h])

    def solve(logp):
        y = logp - lr
        if h.size == 1 or np.ptp(1.0 / h ** 2) < 1e-12 * np.max(1.0 / h ** 2):
            c0, c1 = float(np.average(y, weights=w)), 0.0
        else:
            A = np.column_stack([np.ones_like(h), 1.0 / h ** 2]) * np.sqrt(w)[:, None]
            c0, c1 = np.linalg.lstsq(A, y * np.sqrt(w), rcond=None)[0]
        f = lambda x: log_rice(x) + c0 + c1 / x ** 2 - math.log(target)  # noqa: E731
        lo, hi = math.log(h.min() / 3), math.log(h.max() * 3)
        flo, fhi = f(math.exp(lo)), f(math.exp(hi))
        if not (flo < 0 < fhi):
            return math.nan
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            if f(math.exp(mid)) > 0:
                hi = mid
            else:
                lo = mid
        return math.exp(0.5 * (lo + hi))

    return (solve(np.array([p[1][0] for p in pts])), solve(np.array([p[1][2] for p in pts])),
            solve(np.array([p[1][1] for p in pts])))


def _rice_curve(ref: LandedMargins, hs_ref: float):
    cache: dict = {}

    def log_rice(h):
        key = float(h)
        if key not in cache:
            cache[key] = math.log(max(ref.scaled(h / hs_ref).rice_bound(), 1e-300))
        return cache[key]
    return log_rice


def _first_level(log_rice, target: float, hs_ref: float) -> float:
    lo, hi = math.log(hs_ref / 50), math.log(hs_ref * 50)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if log_rice(math.exp(mid)) > math.log(target):
            hi = mid
        else:
            lo = mid
    return round(math.exp(0.5 * (lo + hi)), 6)


@dataclass
class _Level:
    hs: float
    done: bool = False
    n: int = 0                      # whole batches decided on
    est: IseeEstimate | None = None
    cap: int = 0                    # a narrowed search's extra samples: the level runs on to at least n + cap


def _level_state(level: _Level, rows: np.ndarray, settings, names, incident) -> list[int]:
    """Advance a level over the whole batches it has; return the sample numbers to run next (none: done)."""
    B = settings.batch
    have = set(int(s) for s in rows["seed_index"]) if rows.size else set()
    while not level.done:
        nxt = list(range(level.n, min(level.n + B, settings.max_samples)))
        missing = [s for s in nxt if s not in have]
        if missing:
            return missing
        level.n = nxt[-1] + 1
        sel = _completed(rows[rows["seed_index"] < level.n]) if rows.size else rows
        est = run_estimates(sel, names)[incident] if sel.size else None
        level.est = est
        if level.n >= settings.max_samples or (est is not None and level.n >= max(settings.min_samples, level.cap)
                                               and est.cov <= settings.target_cov):
            level.done = True
    return []


def _narrow(levels: list[_Level], log_rice, settings) -> bool:
    """With ``limit_width``: when the limiting Hs's interval is wider than ±width, reopen the level nearest
    the accepted P for one more batch (True); False when it is narrow enough or no level can grow."""
    ok = [lv for lv in levels if lv.est is not None and lv.est.p > 0 and math.isfinite(lv.est.cov)]
    if settings.limit_width is None or not ok:
        return False
    h, lo, hi = limit_fit([lv.hs for lv in ok], [lv.est for lv in ok], log_rice, settings.accept)
    if math.isfinite(h) and math.isfinite(lo) and math.isfinite(hi) and \
            max(h / lo - 1.0, hi / h - 1.0) <= settings.limit_width:
        return False
    grow = [lv for lv in ok if lv.n < settings.max_samples]
    if not grow:
        return False
    nearest = min(grow, key=lambda lv: abs(math.log(lv.est.p / settings.accept)))
    nearest.cap, nearest.done = nearest.n + settings.batch, False
    return True


def _next_level(levels: list[_Level], log_rice, target: float, max_levels: int) -> float | None:
    """The Hs of the next level of a limiting-Hs search, or None when it is done (module docstring)."""
    ok = [lv for lv in levels if lv.est is not None and lv.est.p > 0 and math.isfinite(lv.est.cov)]
    if len(levels) >= max_levels:
        return None
    if not ok:
        return round(levels[-1].hs * 1.15, 6)
    ps = [lv.est.p for lv in ok]
    if len(ok) >= 2 and min(ps) <= target <= max(ps):
        return None
    nearest = min(ok, key=lambda lv: abs(math.log(lv.est.p / target)))
    z = ndtri(0.5 + CONFIDENCE / 2)
    _, llo, lhi = _log_bounds(nearest.est, z)
    if len(ok) >= 2 and llo <= math.log(target) <= lhi:
        return None
    h, _, _ = limit_fit([lv.hs for lv in ok], [lv.est for lv in ok], log_rice, target)
    if not math.isfinite(h):
        h = nearest.hs * (1.15 if nearest.est.p < target else 0.87)
    h = min(max(h, 0.7 * nearest.hs), 1.4 * nearest.hs)
    if any(abs(h / lv.hs - 1) < 0.002 for lv in levels):
        return None
    return round(h, 6)


# ------------------------------------------------------------------------------------ the campaign
def run_isee(campaign: Campaign, store_path: str | Path, *, loaders, executor: str = "local",
             workers: int | None = None, scheduler: str | None = None, progress=None,
             connect_timeout: float = 10.0) -> CampaignStore:
    """Run (or resume) an ISEE campaign into the store at ``store_path`` (module docstring).

    Parameters are those of :func:`boatland.campaign.runner.run_campaign`; ``progress(done, estimate)`` is
    called after each sample with the samples done and the samples expected so far.

    Returns
    -------
    CampaignStore
        Finished: every sample's row, ``/stats`` (one row per run) and ``/isee_limits`` (with ``accept``).
    """

    s = campaign.isee
    names = incident_names(campaign)
    if s.incident not in names:
        raise BoatlandInputError(f"{campaign.source}: isee.incident = {s.incident!r} is not one of the campaign's "
                                 f"incidents: {', '.join(names)}")
    if s.accept is not None and not _has_hs(campaign):
        raise BoatlandInputError(f"{campaign.source}: isee.accept needs a sea with one spectrum (sea.Hs) to search "
                                 "the limiting Hs along")
    if executor == "dask":
        check_scheduler_address(scheduler)
    check_cases(campaign, loaders[1])
    digest, digests, dbs = checked_inputs(campaign, loaders[1])    # of what the samples run on
    header = {
        "campaign": campaign.name, "campaign_digest": digest, "input_digests": json.dumps(digests),
        "campaign_file": campaign.text,
        "plan": plan_json(campaign), "n_trials": len(campaign.cases) * MAX_LEVELS * MAX_SAMPLES,
        "incidents": "\n".join(names), "method": "isee", "isee": json.dumps(asdict(s)),
        "inputs": json.dumps(campaign_inputs(campaign), default=float),   # for the report's inputs and titles
    }
    store = CampaignStore.open(store_path, header, names, ISEE_FIELDS)
    try:
        with single_threaded():      # prepared here before the workers fork: they inherit it
            ctx = worker_context(campaign, loaders)
            ctx["db"].update(dbs)    # the databases the checks read: never the files again
            refs = {c.index: _models(ctx, campaign, c.index, _case_hs(campaign, c.index) or 0.0, loaders)
                    for c in campaign.cases}
        curves = {c: _rice_curve(m.margins, _case_hs(campaign, c)) for c, m in refs.items()
                  if _case_hs(campaign, c) is not None}
        levels: dict[int, list[_Level]] = {}
        for c, m in refs.items():
            if m.margins.static_slip:
                levels[c] = []
            elif s.accept is not None:
                levels[c] = [_Level(_first_level(curves[c], s.accept, _case_hs(campaign, c)))]
            else:
                levels[c] = [_Level(_case_hs(campaign, c) or 0.0)]
        with Executor(executor, workers, scheduler, connect_timeout) as pool:
            while True:
                table = store.table()
                tasks = []
                for c, lvls in levels.items():
                    while lvls:
                        pending = None          # the first open level with samples to run
                        for k, lv in enumerate(lvls):
                            if not lv.done:
                                rows = table[(table["case"] == c) & (table["level"] == k)] if table.size else table
                                todo = _level_state(lv, rows, s, names, s.incident)
                                if todo:
                                    pending = (k, todo)
                                    break
                        if pending is not None:
                            k, todo = pending
                            tasks += [SampleSpec(trial_number(c, k, q), c, k, lvls[k].hs, q) for q in todo]
                            break
                        if s.accept is None:
                            break
                        h = _next_level(lvls, curves[c], s.accept, s.levels)
                        if h is not None:
                            lvls.append(_Level(h))
                        elif not _narrow(lvls, curves[c], s):     # narrow enough (or nothing can grow)
                            break
                if not tasks:
                    break
                total = len(store.rows) + len(tasks)
                dask = executor == "dask"      # its workers get the databases read here, once each
                for row in pool.map(execute_sample, [(Shared("campaign", campaign), t, loaders, False,
                                                      Shared("dbs", dbs) if dask else None) for t in tasks]):
                    store.add(row)
                    if progress:
                        progress(len(store.rows), total)
        table = store.table()
        with single_threaded():
            runs, limits = _summaries(campaign, table, levels, refs, curves, names, loaders)
        extra = {"sensitivity": case_sensitivity(campaign, loaders)}
        store.finish(runs, {**extra, "isee_limits": limits} if limits is not None else extra)
    finally:
        store.close()
    return store


def _summaries(campaign, table, levels, refs, curves, names, loaders):
    """The ``/stats`` table (one row per run) and ``/isee_limits`` (one row per case, with ``accept``)."""
    s = campaign.isee
    z = ndtri(0.5 + CONFIDENCE / 2)
    ests = ["domain", *names, *LINEAR]
    fields = [("case", "i8"), ("level", "i8"), ("label", "S200"), ("hs", "f8"), ("samples", "i8"), ("failed", "i8"),
              ("static slip", "i8")]
    for c in campaign.axes:
        fields.append((f"axis: {c}", "f8"))
    for n in ests:
        fields += [(f"{n}: hits", "i8"), (f"{n}: P", "f8"), (f"{n}: CoV", "f8"), (f"{n}: P lo", "f8"),
                   (f"{n}: P hi", "f8")]
    fields += [("largest elementary P", "f8"), ("rice bound", "f8"), ("screening rayleigh", "f8"),
               ("screening rice", "f8"), ("screening vanmarcke", "f8"), ("TD slip outside linear slip", "i8"),
               ("wall time", "f8")]
    out = []
    per_case: dict[int, list] = {}
    dbs: dict = {}
    for case in campaign.cases:
        c = case.index
        lvls = levels[c] or [_Level(_case_hs(campaign, c) or 0.0)]
        for j, lv in enumerate(lvls):
            r = np.zeros((), dtype=fields)
            r["case"], r["level"], r["label"], r["hs"] = c, j, case.label().encode()[:200], lv.hs
            for k, v in case.values.items():
                r[f"axis: {k}"] = float(v) if isinstance(v, (int, float)) else math.nan
            rows = table[(table["case"] == c) & (table["level"] == j)] if table.size else table
            rows = rows[rows["seed_index"] < lv.n] if rows.size else rows
            ok = _completed(rows)
            r["samples"], r["failed"] = len(rows), len(rows) - len(ok)
            r["static slip"] = int(not levels[c])
            if not levels[c]:
                for n in ests:
                    r[f"{n}: P"] = r[f"{n}: P lo"] = r[f"{n}: P hi"] = 1.0
            e = run_estimates(ok, names) if ok.size else {}
            for n in ests:
                if n in e:
                    r[f"{n}: hits"], r[f"{n}: P"], r[f"{n}: CoV"] = e[n].hits, e[n].p, e[n].cov
                    r[f"{n}: P lo"], r[f"{n}: P hi"] = e[n].lo, e[n].hi
            m = refs[c].margins
            h0 = _case_hs(campaign, c)
            lm = m.scaled(lv.hs / h0) if h0 else m
            r["largest elementary P"], r["rice bound"] = lm.largest_event_probability(), lm.rice_bound()
            if ok.size:
                r["TD slip outside linear slip"] = int(np.sum(np.isfinite(ok[INCIDENT_PREFIX + "first slip"])
                                                          & (ok["lin_first_slip"] == 0)))
                r["wall time"] = float(ok["wall_time"].sum())
            for st in ("rayleigh", "rice", "vanmarcke"):
                r[f"screening {st}"] = _screening_p(campaign, c, lv.hs if h0 else None, st, loaders, dbs)
            out.append(r)
            per_case.setdefault(c, []).append((lv, e))
    runs = np.array(out, dtype=fields)
    if s.accept is None:
        return runs, None
    lf = [("case", "i8"), ("label", "S200")] + [(f"axis: {k}", "f8") for k in campaign.axes] + [
        ("accept", "f8"), ("incident", "S40"), ("levels", "i8"), ("samples", "i8"),
        ("limiting Hs", "f8"), ("limiting Hs lo", "f8"), ("limiting Hs hi", "f8"),
        ("linear limiting Hs", "f8"), ("linear limiting Hs lo", "f8"), ("linear limiting Hs hi", "f8"),
        ("screening rayleigh Hs", "f8"), ("screening rice Hs", "f8"), ("screening vanmarcke Hs", "f8")]
    lim = np.zeros(len(campaign.cases), dtype=lf)
    for case in campaign.cases:
        c = case.index
        L = lim[c]
        L["case"], L["label"], L["accept"], L["incident"] = c, case.label().encode()[:200], s.accept, s.incident.encode()
        for k, v in case.values.items():
            L[f"axis: {k}"] = float(v) if isinstance(v, (int, float)) else math.nan
        got = per_case.get(c, [])
        L["levels"] = len(levels[c])
        L["samples"] = int(sum(lv.n for lv, _ in got)) if levels[c] else 0
        if not levels[c]:
            L["limiting Hs"] = L["limiting Hs lo"] = L["limiting Hs hi"] = 0.0
            L["linear limiting Hs"] = L["linear limiting Hs lo"] = L["linear limiting Hs hi"] = 0.0
        else:
            hs = [lv.hs for lv, _ in got]
            L["limiting Hs"], L["limiting Hs lo"], L["limiting Hs hi"] = limit_fit(
                hs, [e[s.incident] if e else IseeEstimate(0, math.inf, 0, 0, 0, 0) for _, e in got], curves[c], s.accept, z)
            lin = "linear first slip" if s.incident == "first slip" else "linear first incident"
            L["linear limiting Hs"], L["linear limiting Hs lo"], L["linear limiting Hs hi"] = limit_fit(
                hs, [e[lin] if e else IseeEstimate(0, math.inf, 0, 0, 0, 0) for _, e in got],
                curves[c], s.accept, z)
        for st in ("rayleigh", "rice", "vanmarcke"):
            L[f"screening {st} Hs"] = _screening_limit(campaign, c, st, loaders, dbs)
    return runs, lim


def _fd_case(campaign, c, loaders, dbs):
    """The screening's view of case ``c``, cached: (spectral moments for Hs = 1 (1, 1, R, 3), capacities, Tp,
    relative direction, access, the margins that are events of their own) — one long-crested spectral part
    only (else None). Margins correlated at ρ ≥ 0.99 (the two contacts' in head seas) count once, as in
    ``boatland screen`` (:func:`boatland.freqdomain.statistics.distinct_events`)."""
    key = ("fd", c)
    if key not in dbs:
        dbs[key] = None
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                sc = level_scenario(campaign, c, None)
                db = database_for(sc, dbs, loaders[1])
                setup = Setup.of(sc, db)
                landing = LandingSetup.from_scenario(sc, db, setup=setup)
                parts = sc.sea.waves.parts
                if len(parts) == 1 and parts[0].spreading is None:
                    p = parts[0]
                    beta = (p.direction_deg - landing.heading_deg) % 360.0
                    tr = slip_transfer(db, landing, beta_deg=[beta])
                    h = setup.waves.water_depth
                    m, _ = spectral_moments(tr, [p.Tp], sea=p, water_depth=h, g=db.g)
                    keep = distinct_events(m[..., 0], tr.capacity,
                                           response_correlation(tr, [p.Tp], sea=p, water_depth=h, g=db.g),
                                           background=tr.background)
                    dbs[key] = (m, tr.capacity, p.Tp, beta, _access(campaign, sc), keep, tr.background)
        except Exception:  # noqa: BLE001 — the screening is a comparison; NaN where it cannot answer
            dbs[key] = None
    return dbs[key]


def _access(campaign, sc) -> float:
    return sc.simulation.duration - exposure_start(sc) - campaign.isee.settle


def _screening_p(campaign, c, hs, statistics, loaders, dbs) -> float:
    """The frequency-domain screening's P(slip or roll within the access) of the run at ``hs`` (four
    margins per contact at μ, Grøtting 2015 §3.2.1, :func:`boatland.freqdomain.statistics.incident_probability`)."""
    fd = _fd_case(campaign, c, loaders, dbs)
    if fd is None or hs is None:
        return math.nan
    m, cap, tp, _, access, keep, bg = fd
    return float(incident_probability(hs, m, cap, [tp], statistics=statistics, access_duration=access,
                                      keep=keep, background=bg)[1][0, 0])


def _screening_limit(campaign, c, statistics, loaders, dbs) -> float:
    """The screening's limiting Hs of the case at ``accept`` (:func:`boatland.freqdomain.statistics.limiting_hs`)."""
    fd = _fd_case(campaign, c, loaders, dbs)
    if fd is None:
        return math.nan
    m, cap, tp, beta, access, keep, bg = fd
    return float(fd_limiting_hs(m, cap, [tp], [beta], accept=campaign.isee.accept, statistics=statistics,
                                access_duration=access, keep=keep, background=bg).Hs[0, 0])


# ------------------------------------------------------------------------------------ looking at samples
def worst_samples(table: np.ndarray, incident: str, n: int) -> list[int]:
    """Trial numbers of the ``n`` heaviest samples: the largest contributions :math:`\\bar P 1_G/N` to the
    estimate of ``incident`` (those with the incident first, then by weight)."""
    if n <= 0 or table.size == 0:
        return []
    t = _completed(table)
    w = np.exp(t["isee_log_pbar"]) / t["isee_n"]
    hit = np.isfinite(t[INCIDENT_PREFIX + incident])
    order = np.lexsort((t["trial"], -w, ~hit))
    return [int(x) for x in t["trial"][order[:n]]]


def rerun_sample(campaign: Campaign, row, loaders, sinks=()):
    """Run the sample of a store ``row`` (its case, level, Hs, sample number) again, exactly, with ``sinks``
    (e.g. a run log): the same u from the same seed, the same sea, the same trial. Returns the Result."""
    from boatland.trial.simulate import BlowUpError, simulate

    ctx = {"db": {}, "memory": {}, "checked": set(), "campaign": campaign}
    with single_threaded():
        model = _models(ctx, campaign, int(row["case"]), float(row["hs"]), loaders)
        lm = model.margins
        ss = sample_seed(campaign.master_seed, int(row["case"]), int(row["level"]), int(row["seed_index"]))
        u, e, _ = draw(lm, np.random.default_rng(ss))
        if e != int(row["isee_event"]):
            raise BoatlandInputError(f"sample {int(row['trial'])}: drawn again it is not the stored one (event {e} ≠ "
                                     f"{int(row['isee_event'])}): inputs changed since the campaign ran")
        sc, setup = model.scenario, model.setup
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                return simulate(sc, setup.db, memory=setup.memory(), waves=model.sea.with_u(u), sinks=sinks,
                                setup=setup, gust_seed=sample_gust_seed(sc, ss))
            except BlowUpError as exc:
                return exc.result
