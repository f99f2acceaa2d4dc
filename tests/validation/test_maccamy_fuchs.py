"""MacCamy–Fuchs diffraction by a bottom-mounted circular cylinder (boatland.waves.diffraction).

References
----------
- MacCamy, R.C. & Fuchs, R.A. (1954), *Wave forces on piles: a diffraction theory*, Beach Erosion
  Board Tech. Memo 69: the closed-form horizontal force and the run-up (their Fig. 5.1).
- San Nicolás Méndez (2024) (DTU thesis) §3.1–3.2 (eq. 3.13–3.23, run-up Fig. 3.4, 13 terms for ka ≤ 4 at 1e-6,
  Fig. 3.5) and §4.1 (arc plate of 40° at d/a = 2, h/a = 4: closed form eq. 4.1–4.4 against a
  low-order panel method eq. 4.5, Figs. 4.4–4.5).
- Ferreira González (2023) (TUHH) §2.4.1 eq. 2.37–2.44 (the same solution in exp(−iωt)).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from boatland.vessel.wigley import panel_normals_areas
from boatland.waves.diffraction import (arc_plate_force, cylinder_field, n_terms, pile_force,
                                        scattering_coefficients)

G, RHO = 9.81, 1025.0


def omega_for(ka, a, h=math.inf):
    """ω giving k·a = ka in depth h (ω² = g k tanh kh)."""
    k = ka / a
    return math.sqrt(G * k * (math.tanh(k * h) if math.isfinite(h) else 1.0))


def cylinder_panels(a, h, n_theta, n_z, theta1=0.0, theta2=2 * math.pi):
    """Flat quads on r = a (or an arc), −h ≤ z ≤ 0, normal +e_r (out of the cylinder, into the fluid)."""
    closed = math.isclose(theta2 - theta1, 2 * math.pi)
    nt = n_theta if closed else n_theta + 1
    th = theta1 + (theta2 - theta1) * np.arange(nt) / n_theta
    zz = np.linspace(-h, 0.0, n_z + 1)
    T, Zg = np.meshgrid(th, zz, indexing="ij")
    v = np.column_stack([a * np.cos(T).ravel(), a * np.sin(T).ravel(), Zg.ravel()])
    idx = lambda i, j: (i % nt) * (n_z + 1) + j  # noqa: E731
    faces = [[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]
             for i in range(n_theta) for j in range(n_z)]
    return panel_normals_areas(v, np.array(faces))


# ---------------------------------------------------------------------- truncation
def test_truncation_rule_matches_seed_000():
    """San Nicolás Méndez (2024) §3.2.1: 13 orders for ka = 4 at 1e-6 (elevation). The rule adds the velocity factor
    (1 + m/ka), one order more; and a longer series changes nothing beyond tol."""
    assert n_terms(4.0, 1e-6) == 14
    assert list(n_terms([0.5, 1.0, 2.0, 4.0, 8.0])) == [6, 8, 10, 14, 20]
    a, ka = 1.0, 4.0
    th = np.linspace(0, 2 * np.pi, 73)
    r = np.array([1.0, 1.5, 3.0])
    R, T = np.meshgrid(r, th)
    pts = (R.ravel() * np.cos(T.ravel()), R.ravel() * np.sin(T.ravel()), np.zeros(R.size))
    w = omega_for(ka, a)
    ref = cylinder_field(*pts, [w], [0.3], a, part="scattered", velocity=True, tol=1e-14)
    got = cylinder_field(*pts, [w], [0.3], a, part="scattered", velocity=True, tol=1e-6)
    assert np.max(np.abs(got.eta - ref.eta)) < 3e-6
    assert np.max(np.abs(got.u - ref.u)) / w < 3e-6  # velocity per unit amplitude scales with ω


# ---------------------------------------------------------------------- convention and far field
def test_phase_convention_matches_synthesis():
    """Incident part = the elevation of boatland.waves.synthesis (exp(+iωt), phase at the origin,
    direction of travel): Re{η̂ e^{iωt}} = Σ a cos(ωt − k·x + φ) at any point and time."""
    from boatland.waves.realisation import regular_components
    from boatland.waves.synthesis import elevation

    T, beta = 7.0, 0.4
    w = 2 * math.pi / T
    x, y = np.array([30.0, -20.0, 0.0]), np.array([5.0, 40.0, -12.0])
    t = np.linspace(0.0, T, 9)
    f = cylinder_field(x, y, np.zeros(3), [w], [beta], 3.0, part="incident", velocity=True)
    ref = elevation(regular_components(2.0, T, beta), x, y, t)  # (T, P), unit amplitude
    np.testing.assert_allclose(np.real(f.eta[None, :, 0, 0] * np.exp(1j * w * t)[:, None]), ref, atol=1e-12)
    # horizontal particle velocity in phase with the crest, along the direction of travel (deep water: ω η)
    np.testing.assert_allclose(f.u[0, :, 0, 0], w * np.cos(beta) * f.eta[:, 0, 0], rtol=1e-12)
    np.testing.assert_allclose(f.p[:, 0, 0], RHO * G * f.eta[:, 0, 0])  # p = ρ g e^{kz} η at z = 0


@pytest.mark.parametrize("ka", [0.5, 1.0, 2.0])
def test_far_field_decays_like_inverse_sqrt_kr(ka):
    """|η_s| √(kr) → the constant far-field amplitude (San Nicolás Méndez 2024 eq. 3.17), upstream and to the side;
    so the total field tends to the incident one."""
    a = 1.0
    w = omega_for(ka, a)
    k = ka / a
    for ang in (np.pi, np.pi / 2, 3 * np.pi / 4):  # up-wave, side, oblique
        r = np.array([200.0, 400.0, 800.0, 1600.0, 3200.0]) / k
        f = cylinder_field(r * np.cos(ang), r * np.sin(ang), np.zeros(r.size), [w], [0.0], a, part="scattered")
        s = np.abs(f.eta[:, 0, 0]) * np.sqrt(k * r)
        assert np.ptp(s) / s[-1] < 0.02, s
        tot = cylinder_field(r * np.cos(ang), r * np.sin(ang), np.zeros(r.size), [w], [0.0], a)
        inc = cylinder_field(r * np.cos(ang), r * np.sin(ang), np.zeros(r.size), [w], [0.0], a, part="incident")
        err = np.abs(tot.eta - inc.eta)[:, 0, 0]
        np.testing.assert_allclose(err[-1] * 4.0, err[0], rtol=0.02)  # r × 16 → error / 4
        assert err[-1] < 0.05


# ---------------------------------------------------------------------- wall: no flux, run-up, force
@pytest.mark.parametrize("ka", [0.5, 1.0, 2.0, 4.0])
def test_run_up_symmetric_and_no_flux(ka):
    """Run-up |η(a, θ)| (MacCamy & Fuchs 1954 Fig. 5.1, San Nicolás Méndez 2024 Fig. 3.4): symmetric about the
    direction of travel; zero radial velocity on the wall (San Nicolás Méndez 2024 eq. 3.8)."""
    a = 2.0
    w = omega_for(ka, a)
    th = np.linspace(0, 2 * np.pi, 361)[:-1]
    f = cylinder_field(a * np.cos(th), a * np.sin(th), np.zeros(th.size), [w], [0.0], a, velocity=True)
    ru = np.abs(f.eta[:, 0, 0])
    np.testing.assert_allclose(ru[1:], ru[1:][::-1], atol=1e-12)
    ur = f.u[0, :, 0, 0] * np.cos(th) + f.u[1, :, 0, 0] * np.sin(th)
    assert np.max(np.abs(ur)) < 3e-6 * w
    # up-wave face (θ = π) runs up more than the lee (θ = 0)
    assert ru[180] > ru[0]


def test_run_up_tends_to_one_for_long_waves():
    """Long waves are barely disturbed: max |η(a, θ)| − 1 = O(ka) → 0 (San Nicolás Méndez 2024 §3.2)."""
    a = 1.0
    th = np.linspace(0, 2 * np.pi, 181)
    dev = []
    for ka in (0.5, 0.1, 0.02):
        f = cylinder_field(a * np.cos(th), a * np.sin(th), np.zeros(th.size), [omega_for(ka, a)], [0.0], a)
        dev.append(np.max(np.abs(np.abs(f.eta) - 1.0)))
    assert dev[0] < 0.5 and dev[1] < 0.12 and dev[2] < 0.025
    assert dev[0] > dev[1] > dev[2]


@pytest.mark.parametrize("h_over_a", [4.0, math.inf])
@pytest.mark.parametrize("ka", [0.5, 1.0, 2.0, 4.0])
def test_series_force_equals_closed_form(ka, h_over_a):
    """−∮ p n_x dS of the series pressure = 4ρg tanh(kh)/(k² H₁⁽²⁾′(ka)) (MacCamy & Fuchs 1954)."""
    a = 1.0
    h = h_over_a * a
    w = omega_for(ka, a, h)
    k = ka / a
    th = (np.arange(720) + 0.5) * 2 * np.pi / 720
    f = cylinder_field(a * np.cos(th), a * np.sin(th), np.zeros(th.size), [w], [0.0], a, h)
    depth = math.tanh(k * h) / k if math.isfinite(h) else 1.0 / k  # ∫ Z dz
    F = -RHO * G * depth * a * np.sum(f.eta[:, 0, 0] * np.cos(th)) * 2 * np.pi / th.size
    Fc = pile_force([w], a, h)[0]
    assert abs(F - Fc) < 1e-9 * abs(Fc)


def test_closed_form_force_long_wave_limit():
    """ka → 0: inertia force with C_M = 2, 2iπρg a² tanh kh, leading the crest by 90°."""
    a, h = 1.0, 4.0
    w = omega_for(0.005, a, h)
    F = pile_force([w], a, h)[0]
    k = 0.005
    np.testing.assert_allclose(F, 2j * math.pi * RHO * G * a * a * math.tanh(k * h), rtol=1e-3)


def test_panel_force_on_meshed_cylinder_converges():
    """Panel integration (San Nicolás Méndez 2024 eq. 4.5, pressure at centroids) of the total pressure on a meshed
    cylinder → the closed-form force, second order in the panel size."""
    a, h = 1.0, 4.0
    for ka in (1.0, 4.0):
        w = omega_for(ka, a, h)
        Fc = pile_force([w], a, h)[0]
        errs = []
        for n in (16, 32, 64, 128):
            nrm, area, c = cylinder_panels(a, h, n, n // 2)
            # centroids of flat chords lie inside r = a: put them on the wall (the pressure's radius)
            rc = np.hypot(c[:, 0], c[:, 1])
            f = cylinder_field(c[:, 0] * a / rc, c[:, 1] * a / rc, c[:, 2], [w], [0.0], a, h)
            F = -np.sum(f.p[:, 0, 0] * nrm[:, 0] * area)
            errs.append(abs(F - Fc) / abs(Fc))
        assert errs[3] < 0.005 and all(e0 / e1 > 3.5 for e0, e1 in zip(errs, errs[1:])), errs


# ---------------------------------------------------------------------- arc plate (San Nicolás Méndez 2024 §4.1)
def arc_panel_force(a, d, t1, t2, h, w, n, part):
    """x-force ∫ p n_x dS on the arc plate from about n flat panels of aspect ≈ 1 (San Nicolás Méndez 2024 eq. 4.5)."""
    n_theta = max(2, round(math.sqrt(n * d * (t2 - t1) / h)))
    nrm, area, c = cylinder_panels(d, h, n_theta, max(2, round(n / n_theta)), t1, t2)
    f = cylinder_field(c[:, 0], c[:, 1], c[:, 2], [w], [0.0], a, h, part=part)
    return np.sum(f.p[:, 0, 0] * nrm[:, 0] * area)


@pytest.mark.parametrize("centre_deg", [180.0, 0.0])  # in front of the pile (up-wave) and behind it
def test_arc_plate_closed_form_against_panels(centre_deg):
    """San Nicolás Méndez (2024) §4.1: 40° bottom-mounted arc at d/a = 2, h/a = 4; scattered and Froude–Krylov x-forces
    from the closed form (eq. 4.1–4.4) and from N flat panels converge as N grows (Figs. 4.4–4.5),
    faster for long waves."""
    a, d, h = 1.0, 2.0, 4.0
    t1 = math.radians(centre_deg - 20.0)
    t2 = math.radians(centre_deg + 20.0)
    for part in ("scattered", "incident"):
        for ka in (0.5, 2.0, 4.0):
            w = omega_for(ka, a, h)
            Fc = arc_plate_force([w], a, d, t1, t2, h, part=part)[0]
            err = [abs(arc_panel_force(a, d, t1, t2, h, w, n, part) - Fc) / abs(Fc) for n in (100, 200, 400, 800)]
            assert err[0] > err[1] > err[2] > err[3], (part, ka, err)
            assert err[3] < 0.005, (part, ka, err)


def test_arc_plate_shelter():
    """Behind the pile the scattered wave opposes the Froude–Krylov force (shelter, San Nicolás Méndez 2024 Fig. 4.2):
    |F⁰ + Fˢ| < |F⁰| for ka in [0.8, 4] behind (below, the difference is < 0.3 % either way);
    in front, long waves (ka < 1) are amplified."""
    a, d, h = 1.0, 2.0, 4.0
    ka = np.linspace(0.8, 4.0, 33)
    w = [omega_for(x, a, h) for x in ka]
    back = np.radians([-20.0, 20.0])
    front = np.radians([160.0, 200.0])
    F0b = arc_plate_force(w, a, d, *back, h, part="incident")
    Fsb = arc_plate_force(w, a, d, *back, h, part="scattered")
    assert np.all(np.abs(F0b + Fsb) < np.abs(F0b))
    w = [omega_for(x, a, h) for x in np.linspace(0.1, 0.9, 9)]
    F0f = arc_plate_force(w, a, d, *front, h, part="incident")
    Fsf = arc_plate_force(w, a, d, *front, h, part="scattered")
    assert np.all(np.abs(F0f + Fsf) > np.abs(F0f))


def test_scattering_coefficients_small_ka():
    """A_0 ≈ −iπ(ka)²/4 · … and A_1 = O((ka)²): the pile hardly scatters long waves."""
    A = scattering_coefficients(0.01, 3)
    assert np.all(np.abs(A) < 1e-3)


def test_paired_components_equal_grid():
    """``paired=True`` (wave components (ω_i, θ_i)) = the diagonal of the ω × β grid."""
    x, y, z = np.array([5.0, -7.0, 3.0]), np.array([1.0, 4.0, -9.0]), np.array([0.0, -1.0, -2.0])
    om, be = np.array([0.5, 1.0, 1.7, 2.5]), np.array([0.1, 2.0, -1.0, 3.0])
    i = np.arange(4)
    for h in (math.inf, 20.0):
        full = cylinder_field(x, y, z, om, be, 2.0, h, velocity=True)
        pr = cylinder_field(x, y, z, om, be, 2.0, h, velocity=True, paired=True)
        np.testing.assert_allclose(pr.p, full.p[:, i, i], rtol=1e-13)
        np.testing.assert_allclose(pr.u, full.u[:, :, i, i], rtol=1e-13)


@pytest.mark.parametrize("ka", [0.01, 0.5, 4.0, 8.0])
def test_recurrence_matches_scipy_hankel(ka):
    """Hankel functions by forward recurrence (module docstring) = scipy's H_m^(2) summed directly
    (San Nicolás Méndez 2024 eq. 3.23), near the wall and further out, incl. tiny ka (large Y_m)."""
    from scipy import special

    a = 1.0
    th = np.linspace(0.0, 2 * np.pi, 37)
    for r in (1.0, 1.3, 4.0, 30.0):
        f = cylinder_field(r * np.cos(th), r * np.sin(th), np.zeros(th.size), [omega_for(ka, a)], [0.0], a,
                           part="scattered")
        M = int(n_terms(ka))
        m = np.arange(M + 1)
        ref = (scattering_coefficients(ka, M)[None, :] * special.hankel2(m, ka * r)[None, :]
               * np.cos(np.outer(th, m))).sum(axis=1)
        np.testing.assert_allclose(f.eta[:, 0, 0], ref, rtol=1e-10, atol=1e-14)
