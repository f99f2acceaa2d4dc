"""Excitation force series: interpolation of X(ω, β), phase convention, position lag, heading, ramp.

Phase reference case (DESIGN.md §2, :mod:`boatland.conventions`): the Froude–Krylov heave force of
a floating rectangular box (L × B, draught T, centred on the reference point) in a regular wave
η = a cos(ωt − k·x + φ) is the incident pressure ρ g a e^{−kT} integrated over its bottom,

    X_3(ω, β) = ρ g L B e^{−kT} sinc(k L cosβ / 2) sinc(k B sinβ / 2)      (sinc x = sin x / x),

real and positive for long waves: the heave force is in phase with the crest (→ ρ g A_wp as ω → 0).
"""

import math

import numba
import numpy as np
import pytest

from boatland.waves.excitation import excitation_series, interpolate_excitation, periodic_directions, ramp
from boatland.waves.realisation import Components, concatenate, regular_components
from boatland.waves.synthesis import elevation

RHO, G = 1025.0, 9.81
L, B, T = 20.0, 8.0, 1.5


def box_table(omega=np.linspace(0.05, 3.0, 60), beta_deg=np.arange(0.0, 360.0, 15.0)):
    """X (6, Nb, Nf) of the box: heave Froude–Krylov only (module docstring)."""
    k = omega ** 2 / G
    b = np.radians(beta_deg)[:, None]
    X = np.zeros((6, beta_deg.size, omega.size), complex)
    X[2] = RHO * G * L * B * np.exp(-k * T) * np.sinc(k * L * np.cos(b) / 2 / np.pi) * np.sinc(k * B * np.sin(b) / 2 / np.pi)
    return omega, beta_deg, X


def test_interpolation_is_exact_on_the_grid_linear_between_and_periodic_in_beta():
    rng = np.random.default_rng(0)
    om = np.array([0.2, 0.5, 1.0, 2.0])
    beta = np.array([0.0, 90.0, 180.0, 270.0])
    X = rng.normal(size=(6, 4, 4)) + 1j * rng.normal(size=(6, 4, 4))
    Xc, nb, na = interpolate_excitation(np.array([0.5, 1.0, 2.0]), np.array([90.0, 450.0, -90.0]), om, beta, X)
    assert np.array_equal(Xc, np.stack([X[:, 1, 1], X[:, 1, 2], X[:, 3, 3]], axis=1)) and nb == na == 0
    # midway in ω and across the 270° → 360° ≡ 0° wrap
    Xc, _, _ = interpolate_excitation(np.array([0.75]), np.array([315.0]), om, beta, X)
    ref = 0.25 * (X[:, 3, 1] + X[:, 3, 2] + X[:, 0, 1] + X[:, 0, 2])
    assert np.allclose(Xc[:, 0], ref, rtol=1e-15)
    Xc2, _, _ = interpolate_excitation(np.array([0.75]), np.array([-45.0]), om, beta, X)
    assert np.allclose(Xc2, Xc, rtol=1e-15)
    # outside the band: zero above (counted), held below (counted)
    Xc, nb, na = interpolate_excitation(np.array([0.1, 2.5, 3.0]), np.zeros(3), om, beta, X)
    assert nb == 1 and na == 2 and np.array_equal(Xc[:, 0], X[:, 0, 0]) and np.all(Xc[:, 1:] == 0)


def test_grid_not_starting_at_zero_degrees_wraps_too():
    om = np.array([0.5, 1.0])
    beta = np.array([30.0, 150.0, 270.0])
    X = np.ones((1, 3, 2), complex) * np.array([1.0, 2.0, 3.0])[None, :, None]
    Xc, _, _ = interpolate_excitation(np.array([0.7, 0.7, 0.7]), np.array([0.0, 330.0, 90.0]), om, beta, X)
    assert np.allclose(Xc[0], [1.5, 2.0, 1.5])  # 0° = 270° + 90° of 120°; 330° midway 270°–390°


@pytest.mark.parametrize("beta_deg", [180.0, 0.0, 90.0, 225.0])
def test_long_wave_heaves_a_box_in_phase_with_the_crest(beta_deg):
    om, beta, X = box_table()
    w = om[1]  # a grid frequency: no interpolation error; λ = 2π g / ω² ≈ 6 km
    c = regular_components(2 * 0.7, 2 * math.pi / w, math.radians(beta_deg), math.radians(40.0))
    h = 0.05
    F, _, _ = excitation_series(c, om, beta, X, 0.0, 0.0, 0.0, 0.0, h, 4001)
    eta = elevation(c, 0.0, 0.0, h * np.arange(4001))[:, 0]
    X3 = X[2, int(np.searchsorted(beta, beta_deg)), 1].real
    assert X3 > 0 and X3 == pytest.approx(RHO * G * L * B, rel=2e-3)
    assert np.allclose(F[:, 2], X3 * eta, rtol=0, atol=1e-9 * X3)  # in phase with the crest, not against it
    assert np.all(F[:, [0, 1, 3, 4, 5]] == 0)


def test_regular_wave_force_is_magnitude_times_shifted_cosine_for_ctv24():
    from boatland.hydro.builtin import load_builtin

    db = load_builtin("ctv24")
    a, phase = 0.6, math.radians(-35.0)
    for ib, ifr in ((12, 20), (4, 55), (21, 1)):  # head seas, β = 60°, β = 315° at a low frequency
        w, beta = db.omega[ifr], db.wave_dir_deg[ib]
        c = regular_components(2 * a, 2 * math.pi / w, math.radians(beta), phase)
        t0, h, n = 0.0, 0.025, 8001
        F, nb, na = excitation_series(c, db.omega, db.wave_dir_deg, db.X, 0.0, 0.0, 0.0, t0, h, n)
        t = t0 + h * np.arange(n)
        Xj = db.X[:, ib, ifr]
        ref = a * np.abs(Xj)[None, :] * np.cos(w * t[:, None] + np.angle(Xj)[None, :] + phase)
        assert nb == na == 0
        assert np.max(np.abs(F - ref)) < 1e-6 * a * np.max(np.abs(Xj))
    # the lowest frequency heaves in phase with the crest (built-in database, exp(+iωt))
    assert abs(np.angle(db.X[2, 12, 0])) < 1e-3


def test_vessel_displaced_along_the_wave_lags_by_k_dx():
    om, beta, X = box_table()
    theta = math.radians(30.0)
    c = regular_components(1.0, 2 * math.pi / om[30], theta, 0.0)
    k, w = c.k[0], c.omega[0]
    dx = 17.0
    n, h = 2001, 0.05
    F0, _, _ = excitation_series(c, om, beta, X, 0.0, 0.0, 0.0, 0.0, h, n)
    F1, _, _ = excitation_series(c, om, beta, X, dx * math.cos(theta), dx * math.sin(theta), 0.0, 0.0, h, n)
    t = h * np.arange(n)
    X3 = X[2, 2, 30]
    assert np.allclose(F1[:, 2], 0.5 * abs(X3) * np.cos(w * t + np.angle(X3) - k * dx), atol=1e-9 * abs(X3))
    # the same as the force at the origin a time dx / c later
    lag = k * dx / w
    F0_late, _, _ = excitation_series(c, om, beta, X, 0.0, 0.0, 0.0, -lag, h, n)
    assert np.allclose(F1, F0_late, atol=1e-9 * abs(X3))
    # moving across the wave (perpendicular) changes nothing
    F2, _, _ = excitation_series(c, om, beta, X, -dx * math.sin(theta), dx * math.cos(theta), 0.0, 0.0, h, n)
    assert np.allclose(F2, F0, atol=1e-9 * abs(X3))


def test_heading_only_the_relative_direction_matters():
    rng = np.random.default_rng(3)
    om = np.linspace(0.1, 3.0, 30)
    beta = np.arange(0.0, 360.0, 30.0)
    X = rng.normal(size=(6, 12, 30)) + 1j * rng.normal(size=(6, 12, 30))
    waves = concatenate([regular_components(1.0, 2 * math.pi / w, th, p)
                         for w, th, p in zip(rng.uniform(0.2, 2.8, 9), rng.uniform(0, 2 * math.pi, 9), rng.uniform(0, 6, 9))])
    psi = math.radians(70.0)
    turned = waves._replace(theta=np.mod(waves.theta - psi, 2 * math.pi))
    Fa, _, _ = excitation_series(waves, om, beta, X, 0.0, 0.0, psi, 0.0, 0.1, 500)
    Fb, _, _ = excitation_series(turned, om, beta, X, 0.0, 0.0, 0.0, 0.0, 0.1, 500)
    assert np.allclose(Fa, Fb, rtol=0, atol=1e-11 * np.abs(Fa).max())


def test_ramp_is_smooth_and_reaches_one():
    T_ramp = 10.0
    t = np.linspace(-1, 15, 1601)
    r = ramp(t, T_ramp)
    assert r[t <= 0].max() == 0.0 and np.all(r[t >= T_ramp] == 1.0)
    assert np.all(np.diff(r) >= 0) and ramp(5.0, T_ramp) == pytest.approx(0.5)
    slope = np.diff(r) / np.diff(t)
    assert np.max(np.abs(np.diff(slope))) < 1e-3  # continuous slope (half-cosine: zero at both ends)
    assert np.all(ramp(t, 0.0) == 1.0)
    om, beta, X = box_table()
    c = regular_components(1.0, 2 * math.pi / om[10], 0.0, 0.0)
    F, _, _ = excitation_series(c, om, beta, X, 0.0, 0.0, 0.0, 0.0, 0.05, 401, T_ramp)
    F1, _, _ = excitation_series(c, om, beta, X, 0.0, 0.0, 0.0, 0.0, 0.05, 401)
    assert F[0, 2] == 0.0 and np.array_equal(F[200:], F1[200:])
    assert np.allclose(F[:200, 2], F1[:200, 2] * ramp(0.05 * np.arange(200), T_ramp), rtol=1e-15)


@pytest.mark.parametrize("threads", [1, 2])
def test_excitation_does_not_depend_on_thread_count(threads):
    rng = np.random.default_rng(1)
    om, beta, X = box_table()
    N = 64
    c = Components(rng.uniform(0.1, 2.9, N), np.zeros(N), rng.uniform(0, 0.1, N), rng.uniform(0, 6.28, N),
                   rng.uniform(0, 6.28, N))
    ref, _, _ = excitation_series(c, om, beta, X, 3.0, 4.0, 0.2, 0.0, 0.025, 3001)
    if threads > numba.config.NUMBA_NUM_THREADS:
        pytest.skip(f"numba has only {numba.config.NUMBA_NUM_THREADS} thread(s) here")
    old = numba.get_num_threads()
    try:
        numba.set_num_threads(threads)
        F, _, _ = excitation_series(c, om, beta, X, 3.0, 4.0, 0.2, 0.0, 0.025, 3001)
    finally:
        numba.set_num_threads(old)
    assert np.array_equal(F, ref)


@pytest.mark.parametrize("beta, periodic", [
    (np.arange(0.0, 360.0, 5.0), True),
    (np.arange(0.0, 181.0, 5.0), False),          # a half circle: 180° gap against 5° steps
    (np.arange(0.0, 361.0, 30.0), True),          # 0 … 360 inclusive
    (np.array([0.0, 180.0]), True),               # the gap equals the step
    (np.array([0.0, 51.43, 102.86, 154.29, 205.71, 257.14, 308.57]), True),  # 360/7 printed to 2 decimals
    (np.array([30.0, 150.0, 270.0]), True),
    (np.array([0.0, 90.0, 180.0]), False),
    (np.array([180.0]), False),
])
def test_periodic_directions(beta, periodic):
    assert periodic_directions(beta) is periodic


def test_a_half_circle_table_is_not_wrapped_nan_outside():
    """0–180° is known on 0–180° only: never interpolated from 180° back to 360° (sway would be 0 there)."""
    rng = np.random.default_rng(1)
    om = np.array([0.5, 1.0, 2.0])
    beta = np.arange(0.0, 181.0, 45.0)
    X = rng.normal(size=(6, beta.size, 3)) + 1j * rng.normal(size=(6, beta.size, 3))
    bc = np.array([0.0, 22.5, 180.0, 180.0 + 1e-12, -1e-12, 360.0, -360.0, 225.0, 270.0, 315.0, 180.1, -0.1])
    Xc, _, _ = interpolate_excitation(np.full(bc.size, 1.0), bc, om, beta, X)
    inside = np.array([True] * 7 + [False] * 5)
    assert np.all(np.isnan(Xc[:, ~inside])) and np.all(np.isfinite(Xc[:, inside]))
    assert np.array_equal(Xc[:, 0], X[:, 0, 1]) and np.allclose(Xc[:, 1], 0.5 * (X[:, 0, 1] + X[:, 1, 1]))
    assert np.allclose(Xc[:, 2:4], X[:, -1:, 1], rtol=1e-12) and np.allclose(Xc[:, 4:7], X[:, :1, 1], rtol=1e-12)
    # the caller may still ask for the periodic use explicitly
    Xp, _, _ = interpolate_excitation(np.array([1.0]), np.array([270.0]), om, beta, X, periodic=True)
    assert np.allclose(Xp[:, 0], 0.5 * (X[:, -1, 1] + X[:, 0, 1]))


def test_a_single_direction_is_used_at_that_direction_only():
    om = np.array([0.5, 1.0])
    X = np.ones((6, 1, 2), complex)
    bc = np.array([180.0, -180.0, 540.0, 180.0 + 1e-10, 170.0, 0.0])
    Xc, _, _ = interpolate_excitation(np.full(bc.size, 0.7), bc, om, np.array([180.0]), X)
    assert np.all(Xc[:, :4] == 1.0) and np.all(np.isnan(Xc[:, 4:]))
