"""The landed vessel's margins as linear functions of u (boatland.freqdomain.margins): the FFT series
against the explicit rows of the matrix, the friction circle inside the inscribed M-gon, the bounds of
the linear first slip, and the effect of the number of slip directions."""

import math
import warnings

import numpy as np
import pytest

from boatland.freqdomain.isee import draw, estimate
from boatland.freqdomain.margins import landed_margins
from boatland.freqdomain.landing import LandingSetup
from boatland.sea.gaussian import GaussianSea
from boatland.checks.files import load, resolve_database
from boatland.trial.simulate import exposure_start
from boatland.landing.setup import Setup

REPO = __import__("pathlib").Path(__file__).resolve().parents[2]
CTV24_LANDING = REPO / "scenarios" / "ctv24_landing.toml"   # the figures' vessel (the first default)


def margins(hs, rel, access, directions=16, kappa=0.3):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(CTV24_LANDING).replace(
            {"sea.Hs": hs, "sea.relative_direction_deg": rel})
        sc = sc.replace({"simulation.duration": exposure_start(sc) + 30.0 + access})
        db = resolve_database(sc)
        setup = Setup.of(sc, db)
        dt, n = setup.dt, setup.n_steps
        g = GaussianSea(sea=setup.waves, dt=dt, n_steps=n)
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


def test_the_count_of_exceeded_events_is_the_margins_count(oblique):
    """N(u) is counted without forming the (R, n_t) margins: the same count as theirs, on samples drawn from
    elementary events (many exceedances, the chosen one among them) and on a plain sea at 3× the Hs."""
    lm = oblique
    rng = np.random.default_rng(11)
    for r, k in ((3, 40), (lm.E.shape[0] - 1, 7), (17, lm.n_steps - 1)):
        j = r * lm.n_steps + k
        b, cap = lm.row(j)
        u = rng.standard_normal(lm.dim)
        u += (cap - b @ u) / (b @ b) * b                       # exactly on the chosen event's boundary
        hit = lm.margins(lm.series(u)) > 0
        counted = int(np.count_nonzero(hit)) + (0 if hit.flat[j] else 1)
        assert lm.indicators(u, chosen=j).n_exceeded == counted
        assert lm.indicators(u).n_exceeded == int(np.count_nonzero(hit))
    u = 3.0 * rng.standard_normal(lm.dim)
    n = int(np.count_nonzero(lm.margins(lm.series(u)) > 0))
    assert n > 0 and lm.indicators(u).n_exceeded == n


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


@pytest.mark.slow
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


class OneMargin:
    """The first passage of one margin ζ = Re Σ E A e^{iωt} over the window's steps, as an ISEE problem."""

    def __init__(self, lm, E, a):
        from scipy.special import log_ndtr

        self.lm, self.E, self.a = lm, E, a
        self.dim, self.n = lm.dim, lm.n_steps
        self.log_p = float(log_ndtr(-a / math.sqrt(np.sum(np.abs(E) ** 2))))

    def select(self, U):
        return min(int(U * self.n), self.n - 1), self.log_p + math.log(self.n)

    def row(self, k):
        h = self.E * np.exp(1j * self.lm.omega * (self.lm.steps[k] * self.lm.dt))
        b = np.empty(self.dim)
        b[0::2], b[1::2] = h.real, h.imag
        return b, self.a

    def count(self, u, chosen):
        from boatland.sea.gaussian import grid_series

        c = np.zeros((1, self.lm.n_fft), complex)
        np.add.at(c[0], self.lm.m, self.E * (u[0::2] - 1j * u[1::2]))
        hit = grid_series(c, self.lm.n_fft, int(self.lm.steps[-1]) + 1)[0, self.lm.steps] > self.a
        hit[chosen] = True
        return int(hit.sum())


@pytest.mark.parametrize("gamma", [10.0, 3.3])
def test_one_margin_tracks_rice_where_the_screening_assumes_it(gamma):
    """Where the screening's assumptions hold — one margin, a narrow-band response (bandwidth δ ≈ 0.2) at a
    high level (β ≈ 4.6) — up-crossings do not clump and P(first passage in T) = 1 − exp(−ν⁺T) (Rice 1945):
    ISEE of that margin's first passage over 30 min (discrete steps of 0.05 s) holds Rice's value in its 95 %
    interval. (The whole landing differs from the screening: bench/README.md, "ISEE".)"""
    from boatland.freqdomain.margins import margin_events
    from boatland.freqdomain.statistics import rice_rate

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(CTV24_LANDING).replace({"sea.Hs": 0.16, "sea.gamma": gamma})
        sc = sc.replace({"simulation.duration": exposure_start(sc) + 30.0 + 1800.0})
        db = resolve_database(sc)
        setup = Setup.of(sc, db)
        dt, n = setup.dt, setup.n_steps
        g = GaussianSea(sea=setup.waves, dt=dt, n_steps=n)
        x0, y0, _ = sc.start_pose()
        lm = landed_margins(db, LandingSetup.from_scenario(sc, db), g, x0=x0, y0=y0,
                            first_step=int(math.ceil((exposure_start(sc) + 30.0) / dt - 1e-9)), kappa=0.0)
    # the screening's four margins at μ (down, left, up, right), the least reliable one
    E, a = margin_events(lm.C, lm.static, np.arange(4) * math.pi / 2, lm.mu, lm.roll_limit)
    r = int(np.argmin(a / np.sqrt(np.sum(np.abs(E) ** 2, axis=1))))
    prob = OneMargin(lm, E[r], a[r])
    vals = []
    for s in range(300):
        u, e, lpb = draw(prob, np.random.default_rng(np.random.SeedSequence(4, spawn_key=(s,))))
        vals.append(1.0 / prob.count(u, e))
    est = estimate(vals, lpb)
    m0, _, m2 = lm.spectral_moments(E[r])
    rice = -math.expm1(-lm.duration * float(rice_rate(a[r], m0, m2)))
    print(f"γ {gamma}: ISEE {est.p:.4g} [{est.lo:.4g}, {est.hi:.4g}], Rice {rice:.4g}")
    assert est.lo <= rice <= est.hi and est.cov < 0.05
