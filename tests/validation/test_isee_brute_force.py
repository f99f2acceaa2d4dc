r"""ISEE against brute force: the time domain's P(first slip within the access) of the default CTV
(scenarios/ctv24_landing.toml, the first default) in head and in beam seas, estimated by importance sampling of elementary
events (Au & Beck 2001; boatland.campaign.isee) and by ≥ 2000 plain time-domain trials on Gaussian seas of
the same spectrum (the same grid, u ~ N(0, I)) — where brute force is affordable, p ≈ 0.1 and 0.01 — and at
p ≈ 1e-3 in head seas by a two-stage brute force (the time domain run only on the plain samples the linear
model puts in the sampling domain).

Au, S. K. & Beck, J. L. (2001), First excursion probabilities for linear systems by very efficient
importance sampling, Probabilistic Engineering Mechanics 16(3), 193–207.

Access 60 s after the 30 s settling (the 30-min access of the planner changes only the level, not the
method; 60 s keeps 2000 trials affordable): head seas Hs 0.27 / 0.225 m, beam seas 0.107 / 0.089 m for
p ≈ 0.1 / 0.01 (Tp 7 s; from the linear model). Checked: the two 95 % intervals overlap (Clopper–Pearson
for the brute force); every brute-force slip lies inside the ISEE sampling domain (the estimator's support:
otherwise it would be biased low). Printed beside: how many trials the linear model and the time domain
disagree on (measured: head 9 of 182 slips at p ≈ 0.1, 0 of 25 at 0.01; beam 28 of 201 at 0.1 — near-threshold
peaks that the ≲ 0.15 σ difference of the stuck forces flips either way; the guard κ = 0.3 σ covers them).

A known gap (measured 2026-12-03, on the rebuilt ctv24): the sampling domain D is the linear model's events in
the access; a trial that slips in the 30-s settling before it (at full wave height) leaves the stuck landing
the linear model describes, and may slip again in the access outside D — beam seas at p ≈ 0.1: 1 of 2000
plain trials (of 200 slips), a bias of 0.5 % of P. The test holds that this is the only way out of D and that
it stays below 1 % of the slips; widening D over the settling would close it.

Cost (2 cores, both used): head ≈ 3 min, beam ≈ 3 min (2 × 2000 plain trials + 2 ISEE runs of ≤ 400
samples each, ≈ 0.09 s per 124-s trial) — the beam case runs with ``-m slow``.

A slide incident (the last test): P(slide > 0.2 m within 60 s in a 60-s access) of the default landing
(scenarios/ctv_landing.toml: ctv27, 150 kN, μ_s 0.8) in head seas. A slide starts with a slip, so it lies inside
the sampling domain D of the first slip and the estimator :math:`\bar P\,\overline{1_G/N}` is unbiased for it
too; checked the same way (the intervals overlap, every brute-force slide inside D, brute force P in 0.01–0.2).
Measured (Hs 0.7 m, 2026-12-02): brute force 74/1500 = 0.049 [0.039, 0.062], ISEE 0.043 [0.035, 0.051] (CoV 0.10,
340 samples).
"""

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from boatland.campaign.isee import SampleSpec, execute_sample, run_estimates, trial_number
from boatland.campaign.plan import load_campaign
from boatland.campaign.executor import Executor
from boatland.campaign.stats import clopper_pearson
from boatland.campaign.store import row_dtype
from boatland.campaign.isee import ISEE_FIELDS
from boatland.campaign.runner import incident_names
from boatland.checks.files import load, resolve_database

REPO = Path(__file__).resolve().parents[2]
LOADERS = (load, resolve_database)
N_PLAIN = 2000
SEAS = {"head": (180.0, (0.27, 0.225)), "beam": (90.0, (0.107, 0.089))}


def campaign(tmp_path, name, direction, hs):
    path = tmp_path / f"{name}.toml"
    path.write_text(f"""
name = "{name}"
scenario = "{REPO / 'scenarios' / 'ctv24_landing.toml'}"
method = "isee"
master_seed = 2026
access = 60.0
[axes]
"sea.Hs" = [{", ".join(str(h) for h in hs)}]
"sea.relative_direction_deg" = [{direction}]
[isee]
target_cov = 0.08
batch = 20
min_samples = 100
max_samples = 400
""")
    return path


def rows_of(dicts, names):
    dt = row_dtype(names, ISEE_FIELDS)
    out = np.zeros(len(dicts), dtype=dt)
    for i, d in enumerate(sorted(dicts, key=lambda r: r["trial"])):
        for n in dt.names:
            v = d.get(n, math.nan if dt[n].kind == "f" else 0)
            out[i][n] = v.encode()[:200] if isinstance(v, str) else v
    return out


def isee_run(pool, camp, case, hs, names, incident="first slip", cov=0.08, most=400):
    """ISEE samples of one level in batches of 20 until the estimate's CoV is ``cov`` (after ≥ 100) or ``most``
    samples, as run_isee decides on a level: (estimate, rows)."""
    isee = []
    while True:
        start = len(isee)
        specs = [SampleSpec(trial_number(case, 0, k), case, 0, hs, k) for k in range(start, start + 20)]
        isee += list(pool.map(execute_sample, [(camp, s, LOADERS) for s in specs]))
        est = run_estimates(rows_of(isee, names), names)[incident]
        if (len(isee) >= 100 and est.cov <= cov) or len(isee) >= most:
            return est, rows_of(isee, names)


def plain_runs(pool, camp, case, hs, names, samples):
    """Plain Monte Carlo samples (u ~ N(0, I)) ``samples`` of one level: their rows."""
    return rows_of(list(pool.map(execute_sample, [
        (camp, SampleSpec(trial_number(case, 0, k), case, 0, hs, k), LOADERS, True) for k in samples])), names)


def compare(tmp_path, which):
    """(campaign file, [(Hs, ISEE estimate, ISEE rows, plain rows) per level])."""
    direction, levels = SEAS[which]
    src = campaign(tmp_path, which, direction, levels)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        camp = load_campaign(src, load_scenario=load)
    names = ["first slip"]
    out = []
    with Executor("local", 2) as pool:
        for case, hs in enumerate(levels):
            est, isee = isee_run(pool, camp, case, hs, names, cov=camp.isee.target_cov)
            out.append((hs, est, isee, plain_runs(pool, camp, case, hs, names, range(N_PLAIN))))
    return src, out


def slipped_before_the_access(src, case, hs, k) -> bool:
    """Whether plain sample k slipped in the settling window before the access (after the waves reached full
    height): the time domain then leaves the stuck landed state the linear model describes."""
    from boatland.campaign.isee import level_model, sample_seed
    from boatland.trial.simulate import simulate

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        camp = load_campaign(src, load_scenario=load)
        db = resolve_database(camp.base)
        model = level_model(camp, case, hs, db)
        u = np.random.default_rng(sample_seed(camp.master_seed, case, 0, k, True)).standard_normal(model.margins.dim)
        r = simulate(model.scenario, db, waves=model.sea.with_u(u), setup=model.setup)
    starts = r.t[r.slip_rows[0]]
    return bool(np.any((starts >= r.exposure_from) & (starts < model.t_access)))


def check(results, which, src=None):
    for case, (hs, est, isee, plain) in enumerate(results):
        assert (plain["status"] == 0).all() and (isee["status"] == 0).all()
        slip = np.isfinite(plain["incident: first slip"])
        p, lo, hi = clopper_pearson(int(slip.sum()), len(plain))
        print(f"{which} Hs {hs}: brute force {p:.4g} [{lo:.4g}, {hi:.4g}] ({int(slip.sum())}/{len(plain)}); "
              f"ISEE {est.p:.4g} [{est.lo:.4g}, {est.hi:.4g}] CoV {est.cov:.3f} ({est.n} samples); "
              f"linear slips {int(plain['lin_first_slip'].sum())}, TD slips outside D "
              f"{int(np.sum(slip & (plain['isee_n'] == 0)))}, TD/linear disagree "
              f"{int(np.sum(slip != (plain['lin_first_slip'] == 1)))}")
        assert max(lo, est.lo) <= min(hi, est.hi), "the 95 % intervals do not overlap"
        # every time-domain slip lies inside D — but for a trial that slipped in the settling before the access:
        # the linear model knows only the stuck landing, so such a trial can slip again outside D (a known gap,
        # module docstring); it must be the only way out of D, and rare
        outside = np.flatnonzero(slip & (plain["isee_n"] == 0))
        assert all(slipped_before_the_access(src, case, hs, int(plain["seed_index"][i])) for i in outside), \
            "a time-domain slip outside the sampling domain without a slip before the access"
        assert outside.size <= 0.01 * slip.sum(), "slips after a slip in the settling: more than 1 % of the slips"
        assert 0.003 < p < 0.3


@pytest.mark.slow
def test_head_seas_against_brute_force(tmp_path):
    src, results = compare(tmp_path, "head")
    check(results, "head", src)


@pytest.mark.slow
def test_beam_seas_against_brute_force(tmp_path):
    src, results = compare(tmp_path, "beam")
    check(results, "beam", src)


# ------------------------------------------------------------------------ p ≈ 1e-3: a two-stage brute force
RARE_HS = 0.19       # head seas, Tp 7 s, 60-s access: p ≈ 1e-3 (log p linear in 1/Hs² through the levels above)
N_RARE = 80_000


def in_sampling_domain(src: str, start: int, stop: int) -> list[int]:
    """The plain samples start … stop−1 (their own seeds, as ``execute_sample(plain=True)`` draws them) that
    exceed an elementary event of the sampling domain D in the linear model (0.7 ms each)."""
    from boatland.campaign.isee import level_model, sample_seed

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        camp = load_campaign(src, load_scenario=load)
        lm = level_model(camp, 0, RARE_HS, resolve_database(camp.base)).margins
    return [k for k in range(start, stop)
            if lm.indicators(np.random.default_rng(sample_seed(camp.master_seed, 0, 0, k, True))
                             .standard_normal(lm.dim)).n_exceeded > 0]


@pytest.mark.slow
def test_head_seas_at_one_in_a_thousand_against_a_two_stage_brute_force(tmp_path):
    """p ≈ 1e-3, where 80,000 plain time-domain trials would take an hour: every plain sample's linear model
    (0.7 ms) says whether it lies in the sampling domain D, and only those (0.3 %) run the time domain. Outside
    D the time domain does not slip: checked by the full brute force at p ≈ 0.1 and 0.01 above (no slip
    outside D but after a slip in the settling, ≤ 1 % of the slips). Measured (2026-12-03, 35 s): brute force
    80/80,000 = 1.0e-3 [7.9e-4, 1.24e-3] (276 samples in D), ISEE 9.1e-4 [7.7e-4, 1.05e-3] (CoV 0.079,
    180 samples); at Hs 0.197 m 117/60,000 = 1.95e-3 against ISEE 1.96e-3."""
    src = campaign(tmp_path, "rare", 180.0, (RARE_HS,))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        camp = load_campaign(src, load_scenario=load)
    names = ["first slip"]
    with Executor("local", 2) as pool:
        est, _ = isee_run(pool, camp, 0, RARE_HS, names)
        chunks = [(str(src), a, min(a + 5000, N_RARE)) for a in range(0, N_RARE, 5000)]
        in_d = [k for part in pool.map(in_sampling_domain, chunks) for k in part]
        plain = plain_runs(pool, camp, 0, RARE_HS, names, in_d)
    assert (plain["status"] == 0).all() and (plain["isee_n"] > 0).all()   # the same samples, inside D
    hits = int(np.isfinite(plain["incident: first slip"]).sum())
    p, lo, hi = clopper_pearson(hits, N_RARE)
    print(f"head Hs {RARE_HS}: brute force {p:.3g} [{lo:.3g}, {hi:.3g}] ({hits}/{N_RARE}, {len(in_d)} in D); ISEE "
          f"{est.p:.3g} [{est.lo:.3g}, {est.hi:.3g}] CoV {est.cov:.3f} ({est.n} samples)")
    assert max(lo, est.lo) <= min(hi, est.hi), "the 95 % intervals do not overlap"
    assert 3e-4 < p < 3e-3, "brute force outside the range this check is for"


# ------------------------------------------------------------------------ a slide incident
INCIDENT = "slide > 0.2 m within 60 s"
N_SLIDE = 1500
SLIDE_HS = 0.7   # head seas, Tp 7 s: P(slide) ≈ 0.08, P(first slip) ≈ 0.27 in 60 s (200 plain trials)


def slide_campaign(tmp_path):
    path = tmp_path / "slide.toml"
    path.write_text(f"""
name = "slide"
scenario = "{REPO / 'scenarios' / 'ctv_landing.toml'}"
method = "isee"
master_seed = 2026
access = 60.0
[set]
"sea.Tp" = 7.0
[axes]
"sea.Hs" = [{SLIDE_HS}]
"sea.relative_direction_deg" = [180.0]
[incidents]
slide_within = [{{distance = 0.2, window = 60.0}}]
[isee]
incident = "{INCIDENT}"
target_cov = 0.1
batch = 20
min_samples = 100
max_samples = 600
""")
    return path


@pytest.mark.slow
def test_a_slide_incident_against_brute_force(tmp_path):
    src = slide_campaign(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        camp = load_campaign(src, load_scenario=load)
    names = incident_names(camp)
    assert INCIDENT in names
    with Executor("local", 2) as pool:
        est, _ = isee_run(pool, camp, 0, SLIDE_HS, names, INCIDENT, cov=0.1, most=600)
        plain = plain_runs(pool, camp, 0, SLIDE_HS, names, range(N_SLIDE))
    assert (plain["status"] == 0).all()
    hit = np.isfinite(plain[f"incident: {INCIDENT}"])
    slip = np.isfinite(plain["incident: first slip"])   # in the access (a slide may go on from a slip before it)
    p, lo, hi = clopper_pearson(int(hit.sum()), len(plain))
    print(f"Hs {SLIDE_HS}: brute force P({INCIDENT}) {p:.4g} [{lo:.4g}, {hi:.4g}] ({int(hit.sum())}/{len(plain)}; first slip "
          f"{int(slip.sum())}); ISEE {est.p:.4g} [{est.lo:.4g}, {est.hi:.4g}] CoV {est.cov:.3f} ({est.n} samples)")
    assert not np.any(hit & (plain["isee_n"] == 0)), "a time-domain slide outside the sampling domain"
    assert 0.01 < p < 0.2, "brute force outside the range where the comparison discriminates"
    assert max(lo, est.lo) <= min(hi, est.hi), "the 95 % intervals do not overlap"
