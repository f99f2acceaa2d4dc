"""Free and hinged RAOs (boatland.freqdomain.rao): long-wave limits, the hinge condition, Grøtting 2015's
closed form of the hinge reaction, equilibrium, the spring-normal hinge tending to the rigid one, the
static preload."""

from __future__ import annotations

import numpy as np
import pytest

from boatland.freqdomain import (excitation_force, first_harmonic, free_rao, hinged_rao, impedance, point_map,
                                 preload_stiffness, radiation_coefficients)
from boatland.hydro.builtin import load_builtin
from boatland.vessel.database import skew

BOW = np.array([12.3, 0.0, 1.5])     # ctv24's bow fender point, body frame [m]
NORMAL = np.array([-1.0, 0.0, 0.0])  # contact plane ahead of the bow, normal towards the vessel
W = np.array([0.5, 0.9, 1.26, 2.0])  # rad/s
BETA = [135.0, 150.0, 180.0]


@pytest.fixture(scope="module")
def db():
    return load_builtin("ctv24")


def test_free_rao_long_waves_follow_the_surface(db):
    """Long waves: the vessel rides the surface. Heave → 1 in phase with the crest; pitch and roll →
    the wave slope (pitch bow-down positive: θ = −∂η/∂x → i k cos β; roll φ = ∂η/∂y → −i k sin β);
    surge and sway → the orbital excursion −i (cos β, sin β)."""
    w = db.omega[0]
    k = w * w / db.g
    for beta in (0.0, 45.0, 90.0, 180.0):
        x = free_rao(db, w, beta)[0, 0]
        b = np.radians(beta)
        assert abs(x[2] - 1.0) < 1e-3
        assert abs(x[4] - 1j * k * np.cos(b)) < 1e-3 * k
        assert abs(x[3] + 1j * k * np.sin(b)) < 1e-3 * k
        assert abs(x[0] + 1j * np.cos(b)) < 5e-3 and abs(x[1] + 1j * np.sin(b)) < 5e-3


def test_free_rao_is_the_direct_solve_at_database_frequencies(db):
    """San Nicolás Méndez (2024) eq. 3.31 with the database's own arrays (no interpolation at its frequencies)."""
    idx = [3, 22, 60]
    x = free_rao(db, db.omega[idx])
    assert x.shape == (3, db.n_dir, 6)
    for n, i in enumerate(idx):
        w = db.omega[i]
        Z = -w * w * (db.M + db.A[:, :, i]) + 1j * w * db.B[:, :, i] + db.C
        np.testing.assert_allclose(x[n], np.linalg.solve(Z, db.X[:, :, i]).T, rtol=1e-10, atol=1e-14)


def test_interpolation_between_frequencies_and_directions(db):
    """A and B linear in ω; X bilinear on real and imaginary parts in (ω, β)."""
    w = 0.5 * (db.omega[30] + db.omega[31])
    A, B = radiation_coefficients(db, w)
    np.testing.assert_allclose(A[0], 0.5 * (db.A[:, :, 30] + db.A[:, :, 31]))
    np.testing.assert_allclose(B[0], 0.5 * (db.B[:, :, 30] + db.B[:, :, 31]))
    j = int(np.searchsorted(db.wave_dir_deg, 150.0))
    beta = 0.5 * (db.wave_dir_deg[j] + db.wave_dir_deg[j + 1])
    X = excitation_force(db, w, beta)[0, 0]
    expected = 0.25 * (db.X[:, j, 30] + db.X[:, j, 31] + db.X[:, j + 1, 30] + db.X[:, j + 1, 31])
    np.testing.assert_allclose(X, expected, rtol=1e-12)
    # directions wrap around: -30° is 330°
    np.testing.assert_allclose(excitation_force(db, w, -30.0), excitation_force(db, w, 330.0))


def test_frequencies_above_the_band_are_refused(db):
    with pytest.raises(ValueError, match="above the band"):
        free_rao(db, 1.01 * db.omega[-1])
    with pytest.raises(ValueError, match="> 0"):
        free_rao(db, [0.0, 1.0])


def test_point_map_is_the_rigid_body_translation():
    """G x = x₁₋₃ + θ × r, and Gᵀ f = [f; r × f] (Grøtting 2015 eq. 3.3, 3.7)."""
    rng = np.random.default_rng(1)
    r, x, f = rng.normal(size=3), rng.normal(size=6), rng.normal(size=3)
    G = point_map(r)
    np.testing.assert_allclose(G @ x, x[:3] + np.cross(x[3:], r))
    np.testing.assert_allclose(G.T @ f, np.concatenate([f, np.cross(r, f)]))


@pytest.mark.parametrize("points", [BOW, [[12.3, 0.75, 1.5], [12.3, -0.75, 1.5]]], ids=["one", "two"])
def test_rigid_hinge_point_does_not_move(db, points):
    h = hinged_rao(db, W, points, beta_deg=BETA)
    scale = np.max(np.abs(h.x[..., :3]))
    assert np.max(np.abs(h.point_motion())) < 1e-10 * scale
    assert np.max(np.abs(h.J)) > 1e4  # and it takes a force to hold it


def test_rigid_hinge_reaction_is_seed002_closed_form(db):
    r"""Grøtting (2015) eq. 3.11–3.12: P₁ = H (F₂ − Q F₁) − F₁, H = (G₁₁Q + G₁₂)(G₂₁Q + G₂₂ − QG₁₁Q − QG₁₂)⁻¹,
    Q = S(r_p); and eq. 3.9/3.33 for the motions: r₂ = (G₂₁Q + G₂₂)⁻¹(F₂ + Q P₁), r₁ = Q r₂."""
    h = hinged_rao(db, W, BOW, beta_deg=BETA)
    Z = impedance(db, W)
    X = excitation_force(db, W, BETA)
    Q = skew(BOW)
    for i in range(W.size):
        G11, G12, G21, G22 = Z[i, :3, :3], Z[i, :3, 3:], Z[i, 3:, :3], Z[i, 3:, 3:]
        H = (G11 @ Q + G12) @ np.linalg.inv(G21 @ Q + G22 - Q @ G11 @ Q - Q @ G12)
        for b in range(len(BETA)):
            F1, F2 = X[i, b, :3], X[i, b, 3:]
            P1 = H @ (F2 - Q @ F1) - F1
            r2 = np.linalg.solve(G21 @ Q + G22, F2 + Q @ P1)
            np.testing.assert_allclose(h.J[i, b, 0], P1, rtol=1e-8, atol=1e-8 * np.abs(P1).max())
            np.testing.assert_allclose(h.x[i, b], np.concatenate([Q @ r2, r2]), rtol=1e-8,
                                       atol=1e-8 * np.abs(r2).max())


def test_hinged_motion_is_in_equilibrium_with_the_reaction(db):
    """Z x = X + Σ Gᵀ J (with the preload stiffness: (Z − K_g) x = X + Σ Gᵀ J); the spring normal
    carries J·n = −(k + iωd) n·G x and the point does not move tangentially."""
    pts = np.array([[12.3, 0.75, 1.5], [12.3, -0.75, 1.5]])
    k, d = 1.0e6, 4.0e4
    h = hinged_rao(db, W, pts, beta_deg=BETA, normal=NORMAL, stiffness=k, damping=d, thrust=80e3,
                   thrust_position=[-10.5, 0.0, -0.9])
    Kg = preload_stiffness(80e3, [-10.5, 0.0, -0.9], h.J_static, pts)
    Z = impedance(db, W) - Kg
    X = excitation_force(db, W, BETA)
    gen = sum(np.einsum("kd,wbk->wbd", point_map(p), h.J[:, :, c]) for c, p in enumerate(pts))
    lhs = np.einsum("wde,wbe->wbd", Z, h.x)
    np.testing.assert_allclose(lhs, X + gen, rtol=1e-9, atol=1e-9 * np.abs(X).max())
    comp = h.contact_components()                      # (normal, vertical, horizontal)
    motion = np.einsum("ak,wbpk->wbpa", np.stack([NORMAL, [0, 0, 1.0], [0, -1.0, 0]]), h.point_motion())
    np.testing.assert_allclose(comp[..., 0], -(k + 1j * d * W[:, None, None]) * motion[..., 0], rtol=1e-9)
    assert np.max(np.abs(motion[..., 1:])) < 1e-10 * np.max(np.abs(motion[..., 0]))
    # two points on one plane pinned sideways: the split is indeterminate, shared equally (as the time domain)
    # (where the sideways load is zero — head seas — both are round-off of the forces' scale)
    np.testing.assert_allclose(comp[:, :, 0, 2], comp[:, :, 1, 2], rtol=1e-8, atol=1e-14 * np.abs(comp).max())


def test_spring_normal_tends_to_the_rigid_hinge(db):
    rigid = hinged_rao(db, W, BOW, beta_deg=BETA, normal=NORMAL)
    errors = []
    for k in (1e6, 1e8, 1e10, 1e12):
        soft = hinged_rao(db, W, BOW, beta_deg=BETA, normal=NORMAL, stiffness=k, damping=4e4)
        errors.append(np.max(np.abs(soft.J - rigid.J)) / np.max(np.abs(rigid.J)))
        x_err = np.max(np.abs(soft.x - rigid.x)) / np.max(np.abs(rigid.x))
    assert errors[0] > 1e-2                        # a real fender is not rigid: 1 MN/m moves the reaction
    assert all(b < a / 10 for a, b in zip(errors, errors[1:]))  # ~1/k
    assert errors[-1] < 1e-6 and x_err < 1e-6


def test_static_preload_matches_seed002_eq361(db):
    """Rigid hinge at the bow, thrust below it: the static vertical force F_zc of Grøtting 2015 eq. 3.56–3.61
    (thrust along global x). hinged_rao also tilts the thrust with the static pitch (§3.4 neglects it:
    under 1 % here) — its static state is in equilibrium with the preload stiffness included."""
    T, rT = 80e3, np.array([-10.5, 0.0, -0.9])
    h = hinged_rao(db, 1.0, BOW, beta_deg=180.0, thrust=T, thrust_position=rT)
    C = db.C
    xp = BOW[0]
    M5 = T * (rT[2] - BOW[2])      # pitch moment of the thrust and the normal reaction, about the reference point
    r5 = M5 / (C[4, 2] * xp + C[4, 4] + xp * (C[2, 2] * xp + C[2, 4]))         # eq. 3.60
    F_zc = (C[2, 2] * xp + C[2, 4]) * r5                                        # eq. 3.61
    assert h.J_static[0, 0] == pytest.approx(-T, rel=1e-9)
    assert h.J_static[0, 2] == pytest.approx(F_zc, rel=1e-2)
    assert h.x_static[4] == pytest.approx(r5, rel=1e-2)
    # (C − K_g) x⁰ = F_T + Gᵀ J⁰ and G x⁰ = 0
    F_T = T * np.concatenate([[1.0, 0.0, 0.0], np.cross(rT, [1.0, 0.0, 0.0])])
    Kg = preload_stiffness(T, rT, h.J_static, [BOW])
    G = point_map(BOW)
    np.testing.assert_allclose((C - Kg) @ h.x_static, F_T + G.T @ h.J_static[0], atol=1e-9 * T * xp)
    assert np.max(np.abs(G @ h.x_static)) < 1e-12
    # without thrust there is no preload
    h0 = hinged_rao(db, 1.0, BOW, beta_deg=180.0)
    assert not h0.J_static.any() and not h0.x_static.any()


def test_thrust_the_hinge_cannot_hold_is_refused(db):
    """An off-centre single point: the thrust on the centreline has a yaw moment about it, and nothing
    resists yaw about the point (no restoring in yaw)."""
    with pytest.raises(ValueError, match="cannot hold the thrust"):
        hinged_rao(db, 1.0, [12.3, 0.75, 1.5], normal=NORMAL, stiffness=1e6, thrust=80e3,
                   thrust_position=[-10.5, 0.0, -0.9])
    with pytest.raises(ValueError, match="normal"):
        hinged_rao(db, 1.0, BOW, stiffness=1e6)


def test_first_harmonic_recovers_amplitude_and_phase():
    w = 0.9
    t = np.arange(0.0, 200.0, 0.05)
    c = 3.0 * np.exp(1j * 0.7)
    y = 5.0 + 0.01 * t + (c * np.exp(1j * w * t)).real
    assert first_harmonic(t, y, w) == pytest.approx(c, rel=1e-10)
    with pytest.raises(ValueError, match="shorter"):
        first_harmonic(t[:100], y[:100], w)
