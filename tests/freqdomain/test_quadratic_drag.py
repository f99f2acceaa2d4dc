"""The hull drag's second-order response (boatland.freqdomain.quadratic_drag) and the Hermite tail it feeds
(boatland.freqdomain.statistics.hermite_level): the algebra against closed forms and sampled Gaussians, the
landed ctv27 in a beam current against a finer grid, and nothing changed without a current."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import ndtr

from boatland.freqdomain.quadratic_drag import QuadraticDrag, quadratic_form, quadratic_form_cumulants
from boatland.freqdomain.statistics import hermite_level, incident_probability


def _random_form(rng, d):
    b = rng.normal(size=d)
    A = rng.normal(size=(d, d)) * 0.15
    return b, 0.5 * (A + A.T)


def test_cumulants_of_a_gaussian_quadratic_form_match_samples():
    rng = np.random.default_rng(1)
    b, M = _random_form(rng, 6)
    k2, k3, k4 = quadratic_form_cumulants(b, M)
    xi = rng.normal(size=(2_000_000, 6))
    x = xi @ b + np.einsum("ni,ij,nj->n", xi, M, xi) - np.trace(M)
    c = x - x.mean()
    s2, s3, s4 = (c ** 2).mean(), (c ** 3).mean(), (c ** 4).mean() - 3 * (c ** 2).mean() ** 2
    assert abs(x.mean()) < 5 * math.sqrt(k2 / x.size)
    assert s2 == pytest.approx(k2, rel=0.01)
    assert s3 == pytest.approx(k3, rel=0.05)
    assert s4 == pytest.approx(k4, rel=0.15)


def test_the_real_form_is_the_complex_one():
    """Re(hᵀA) + Re(AᵀPA) + AᵀQĀ with A = c + is equals bᵀξ + ξᵀMξ, ξ = (c, s), for any A."""
    rng = np.random.default_rng(2)
    n = 5
    h = rng.normal(size=n) + 1j * rng.normal(size=n)
    P = rng.normal(size=(n, n)) + 1j * rng.normal(size=(n, n))
    P = P + P.T
    Q = rng.normal(size=(n, n)) + 1j * rng.normal(size=(n, n))
    Q = Q + Q.conj().T
    b, M = quadratic_form(h, P, Q)
    np.testing.assert_allclose(M, M.T)
    for _ in range(5):
        c, s = rng.normal(size=n), rng.normal(size=n)
        A = c + 1j * s
        want = (h @ A).real + (A @ P @ A).real + (A @ Q @ A.conj()).real
        xi = np.concatenate([c, s])
        assert b @ xi + xi @ M @ xi == pytest.approx(want, rel=1e-12)


def _synthetic(answer_of, omega, motions_y, kappa=2.0e4, top=20.0):
    """A QuadraticDrag on one sway pattern with a given answer R(Ω) of its one response (and a roll column)."""
    step = 2
    grid = np.arange(0.0, top, step * (omega[1] - omega[0]))
    ans = np.zeros((grid.size, 1, 2), dtype=complex)
    ans[:, 0, 0] = answer_of(grid)
    return QuadraticDrag(patterns=np.array([[0.0, 1.0, 0.0, 0.0, 0.0, 0.0]]), kappa=np.array([kappa]), step=step,
                         omega=omega, answer_omega=grid, answer=ans, top=float(grid[-1]))


@pytest.mark.parametrize("tau", [0.0, 0.7])
def test_the_volterra_kernels_give_the_square_of_the_velocity_delayed(tau):
    r"""With R(Ω) = r e^{−iΩτ} the second-order part is κ r (v(t − τ)² − σ²) exactly, so for the response
    X = a v(t) + κ r (v(t−τ)² − σ²): κ₂ = a²σ² + 2κ²r²σ⁴, κ₃ = 6a²κr ρ²σ⁴ + 8κ³r³σ⁶ (Isserlis), ρ the
    velocity's correlation at lag τ — the sum and difference kernels, their phases and their halves."""
    omega = np.linspace(0.05, 6.0, 600)
    S = np.exp(-0.5 * ((omega - 1.0) / 0.25) ** 2)                   # a narrow sea, variance weights
    wt = np.gradient(omega)
    W = (S * wt)[None, :] * 1e-3
    x_sway = 0.4 / (1.0 + 0.3j * omega)                              # some motion per unit wave
    motions = np.zeros((omega.size, 1, 6), dtype=complex)
    motions[:, 0, 1] = x_sway
    V = 1j * omega * x_sway
    a, r, kap = 3.0e4, 0.6, 2.0e4
    H = np.zeros((omega.size, 1, 2), dtype=complex)
    H[:, 0, 0] = a * V                                               # the linear part: a·v(t)
    qd = _synthetic(lambda g: r * np.exp(-1j * g * tau), omega, motions, kappa=kap)
    # the same band selection as the model: compare on its components
    f, comp = qd.components(W, np.concatenate([H[..., :1], V[:, None, None]], axis=-1))
    sig2 = float(np.sum(np.abs(comp[:, 1]) ** 2))                      # Var v = Σ |V_n|² (unit A components)
    rho = float(np.sum(np.abs(comp[:, 1]) ** 2 * np.cos(f * tau))) / sig2
    k2 = a * a * sig2 + 2 * (kap * r) ** 2 * sig2 ** 2
    k3 = 6 * a * a * kap * r * rho ** 2 * sig2 ** 2 + 8 * (kap * r) ** 3 * sig2 ** 3
    skew = qd.tails(W, H, motions)[0, 0]
    assert skew == pytest.approx(k3 / k2 ** 1.5, rel=2e-3)


def test_hermite_level_is_the_identity_for_a_gaussian_and_monotone():
    r = np.linspace(-2.0, 5.0, 71)
    np.testing.assert_array_equal(hermite_level(r, 0.0, 0.0), r)
    u = hermite_level(r, 0.15, 0.05)
    assert np.all(np.diff(u) > 0)
    assert np.all(u[r > 2] < r[r > 2])           # a positive skewness: the upper tail is reached more often


def test_hermite_level_gives_the_tail_of_a_quadratic_form():
    """The tail probability Φ(−u(r)) of Winterstein's model against 4 million samples of a skewed Gaussian
    quadratic form, at 2.5–3.5 σ (skewness 0.2: ten times the drag's at ctv27's landing limits)."""
    rng = np.random.default_rng(3)
    d = 40
    b = rng.normal(size=d)
    A = rng.normal(size=(d, d))
    M = 0.5 * (A + A.T)
    k = quadratic_form_cumulants(b, M)
    M *= 0.2 / (k[1] / k[0] ** 1.5)              # scale the quadratic part to a skewness of about 0.2
    k = quadratic_form_cumulants(b, M)
    skew, exk = k[1] / k[0] ** 1.5, k[2] / k[0] ** 2
    lam, vec = np.linalg.eigh(M)
    bb = vec.T @ b
    n = 4_000_000
    x = np.zeros(n)
    for i in range(d):                             # in the eigenbasis: a sum of independent terms
        z = rng.normal(size=n)
        x += bb[i] * z + lam[i] * (z * z - 1.0)
    x /= math.sqrt(k[0])
    for r in (2.5, 3.0, 3.5):
        p_mc = float(np.mean(x > r))
        p_h = float(ndtr(-hermite_level(r, skew, exk)))
        p_g = float(ndtr(-r))
        assert abs(p_h / p_mc - 1) < 0.06, (r, p_mc, p_h, p_g)
        assert abs(p_g / p_mc - 1) > 0.2           # where the Gaussian is visibly wrong


def test_incident_probability_maps_the_capacity_by_the_hermite_level():
    m = np.array([[[[4.0, 2.0, 1.5], [1.0, 1.0, 1.0]]]])            # two responses (the last "roll")
    cap = np.array([7.0, 2.5])
    tails = np.array([[[[0.05, 0.01], [0.3, 0.0]]]])
    _, _, nu0 = incident_probability(1.0, m, cap, [7.0], statistics="rice")
    _, _, nu = incident_probability(1.0, m, cap, [7.0], statistics="rice", tails=tails)
    u = hermite_level(7.0 / 2.0, 0.05, 0.01)
    assert nu[0, 0, 0] / nu0[0, 0, 0] == pytest.approx(math.exp(0.5 * (3.5 ** 2 - u * u)), rel=1e-12)
    assert nu[0, 0, 1] == nu0[0, 0, 1]            # roll keeps its own
    # second order: at Hs 2 the skewness is twice, the excess kurtosis four times the unit sea's
    _, _, nu2 = incident_probability(2.0, m, cap, [7.0], statistics="rice", tails=tails)
    u2 = hermite_level(7.0 / 4.0, 0.10, 0.04)
    _, _, g2 = incident_probability(2.0, m, cap, [7.0], statistics="rice")
    assert nu2[0, 0, 0] / g2[0, 0, 0] == pytest.approx(math.exp(0.5 * (1.75 ** 2 - u2 * u2)), rel=1e-12)


# --------------------------------------------------------------------------------------- ctv27 in a current
@pytest.fixture(scope="module")
def ctv27():
    import warnings

    from boatland.checks.files import load
    from boatland.hydro.read import load_database
    from boatland.resources import shipped_scenarios

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load(shipped_scenarios() / "ctv_landing.toml").replace(
            {"sea.Tp": 7.0, "sea.relative_direction_deg": 135.0}), load_database("ctv27")


def _sea(sc, db, hs, **changes):
    from boatland.freqdomain.landing import LandingSetup
    from boatland.freqdomain.screening import sea_response

    sc = sc.replace({"sea.Hs": hs, **changes})
    return sea_response(db, LandingSetup.from_scenario(sc, db), sc.sea.waves.parts, access_duration=1800.0)


BEAM_CURRENT = {"current": {"speed": 1.0, "relative_direction_deg": 90.0}}


def test_a_beam_current_skews_the_governing_margin_towards_a_slip(ctv27):
    """Bow-quartering seas, 1 m/s on the beam (the validation's case, tests/validation/test_loads_vs_monte_carlo.py):
    the governing margin (contact 1 slipping up) is skewed towards the slip, second order in the waves (its
    skewness grows as H_s), and its slip rate rises by the Hermite tail. Measured 2026-12-03: skewness 0.013 /
    0.019 / 0.025 at H_s 0.2 / 0.3 / 0.385 m (the drag's own linearisation makes it grow a little slower than
    H_s), P per 30 min 0.367 → 0.425 at 0.385 m (the slip rate ×1.21); the time domain's skewness
    (tests/validation/test_drag_skewness.py): 0.012 / 0.020 at 0.2 / 0.3 m."""
    sc, db = ctv27
    sc = sc.replace(BEAM_CURRENT)
    r = {hs: _sea(sc, db, hs) for hs in (0.2, 0.3, 0.385)}
    gov = int(np.argmax(r[0.385].per_mode[:-1]))
    assert r[0.385].names[gov] == "up 1"
    skew = {hs: float(x.tails[gov, 0]) for hs, x in r.items()}
    print(skew)
    assert 0.015 < skew[0.385] < 0.04
    assert 1.2 < skew[0.3] / skew[0.2] < 1.5 + 0.05                # second order: ∝ H_s, a little less
    assert abs(r[0.385].tails[-1]).max() == 0.0                     # roll keeps its Gaussian
    # the rate: the Hermite level at the margin's own σ
    x = r[0.385]
    u = hermite_level(x.capacity[gov] / x.sigma[gov], *x.tails[gov])
    gauss = math.sqrt(x.m[gov, 2] / x.m[gov, 0]) / (2 * math.pi) * math.exp(-0.5 * (x.capacity[gov] / x.sigma[gov]) ** 2)
    assert x.per_mode[gov] / gauss == pytest.approx(math.exp(0.5 * ((x.capacity[gov] / x.sigma[gov]) ** 2 - u * u)),
                                                    rel=1e-9)
    assert x.per_mode[gov] / gauss > 1.15


def test_the_second_order_grid_is_fine_enough(ctv27, monkeypatch):
    """Halving the second-order grid's step, or keeping ten times more of the spectrum's tails, moves the
    margins' skewness by less than 1 % (module docstring)."""
    import boatland.freqdomain.quadratic_drag as qd

    sc, db = ctv27
    sc = sc.replace(BEAM_CURRENT)
    base = _sea(sc, db, 0.385).tails[:-1, 0]
    monkeypatch.setattr(qd, "STEP", qd.STEP / 2)
    fine = _sea(sc, db, 0.385).tails[:-1, 0]
    monkeypatch.setattr(qd, "STEP", qd.STEP * 2)
    monkeypatch.setattr(qd, "BAND_CUT", qd.BAND_CUT / 10)
    wide = _sea(sc, db, 0.385).tails[:-1, 0]
    big = np.abs(base) > 0.01
    np.testing.assert_allclose(fine[big], base[big], rtol=0.01)
    np.testing.assert_allclose(wide[big], base[big], rtol=0.01)


def test_without_a_current_the_screening_is_gaussian(ctv27):
    """No current (or only the hull's drag in still water under a wind, which is odd in the motions): no
    second-order part, the screening as before."""
    sc, db = ctv27
    assert _sea(sc, db, 0.385).tails is None
    assert _sea(sc, db, 0.385, **{"wind": {"speed": 5.1, "relative_direction_deg": 90.0}}).tails is None
