"""The landed vessel's margins as linear functions of u (boatland.freqdomain.margins): the FFT series
against the explicit rows of the matrix, the friction circle inside the inscribed M-gon, the bounds of
the linear first slip, and the effect of the number of slip directions."""

import math
import warnings

import numpy as np
import pytest

from boatland.freqdomain.isee import draw, estimate
from boatland.freqdomain.margins import landed_margins
from boatland.freqdomain.screening import LandingSetup
from boatland.model.gaussian_sea import GaussianSea
from boatland.scenario_check import load, resolve_database
from boatland.trial.simulate import exposure_start

REPO = __import__("pathlib").Path(__file__).resolve().parents[2]


def margins(hs, rel, access, directions=16, kappa=0.3):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(REPO / "scenarios" / "ctv_landing.toml").replace(
            {"sea.Hs": hs, "sea.relative_direction_deg": rel})
        sc = sc.replace({"simulation.duration": exposure_start(sc) + 30.0 + access})
        db = resolve_database(sc)
        dt, n = sc.time_step(db), sc.n_steps(db)
        g = GaussianSea(sea=sc.wave_model(db), dt=dt, n_steps=n)
        x0, y0, _ = sc.start_pose()
        k0 = int(math.ceil((exposure_start(sc) + 30.0) / dt - 1e-9))
        return landed_margins(db, LandingSetup.from_scenario(sc, db), g, x0=x0, y0=y0, first_step=k0,
                              kappa=kappa, directions=directions)


@pytest.fixture(scope="module")
def oblique():
    return margins(0.25, 150.0, 120.0)


def test_fft_series_equals_the_explicit_rows(oblique):
    lm = oblique
    u = np.random.default_rng(3).standard_normal(lm.dim)
    g = lm.margins(lm.series(u))
    for r in (0, 5, 21, lm.E.shape[0] - 1):
        B = lm.rows(r, 100, 400)
        np.testing.assert_allclose(B @ u - lm.a[r] + lm.kappa * lm.s[r], g[r, 100:400], rtol=0, atol=1e-9 * lm.s[r])
        b, cap = lm.row(r * lm.n_steps + 250)
        np.testing.assert_array_equal(b, B[150])
        assert cap == lm.a[r] - lm.kappa * lm.s[r]
    # every row has the margin's standard deviation (a stationary sea)
    assert np.linalg.norm(lm.rows(7, 0, 50), axis=1) == pytest.approx(np.full(50, lm.s[7]), rel=1e-12)


def test_the_friction_circle_lies_inside_the_inscribed_polygon(oblique):
    """Unconditioned seas at 1.6× the Hs: whenever the linear model leaves the friction circle, a margin of the
    M-gon at μ cos(π/M) is exceeded at that step (κ = 0); the screening's square is inside the circle."""
    lm = oblique.scaled(1.6)
    lm0 = margins(0.25 * 1.6, 150.0, 120.0, kappa=0.0)
    rng = np.random.default_rng(5)
    slips = 0
    for _ in range(60):
        u = rng.standard_normal(lm.dim)
        y = lm0.series(u)
        npt = lm0.n_points
        circle = (np.hypot(y[1:3 * npt:3], y[2:3 * npt:3]) > lm0.mu * y[0:3 * npt:3]).any(axis=0)
        gon = (lm0.margins(y)[:-2] > 0).any(axis=0)
        assert np.all(gon[circle])
        ind = lm0.indicators(u)
        assert ind.first_slip == bool(circle.any()) and (not ind.square or ind.first_slip)
        slips += ind.first_slip
    assert slips >= 10


def test_linear_first_slip_lies_between_its_bounds_and_tracks_the_directions():
    lm = margins(0.1, 135.0, 600.0)
    vals = {k: [] for k in ("circle", "square", "domain")}
    for s in range(300):
        u, e, lpb = draw(lm, np.random.default_rng(np.random.SeedSequence(2, spawn_key=(s,))))
        ind = lm.indicators(u, e)
        vals["circle"].append(ind.first_slip / ind.n_exceeded)
        vals["square"].append(ind.square / ind.n_exceeded)
        vals["domain"].append(1.0 / ind.n_exceeded)
    est = {k: estimate(v, lpb) for k, v in vals.items()}
    lower, upper = lm.largest_event_probability(), lm.rice_bound()
    print({k: (e.p, e.cov) for k, e in est.items()}, lower, upper)
    assert lower < est["circle"].lo and est["circle"].hi < upper
    assert est["square"].p <= est["circle"].p <= est["domain"].p
    assert est["circle"].cov < 0.15
