"""Rigid-body kinematics of the kernels (boatland.rigid): the point loads' generalised forces are the virtual
work of the Euler angles, the angular velocity goes through the same axes, and the time domain's friction
margin is Gaussian however the sway is damped."""

from __future__ import annotations

import math

import numpy as np
import pytest

from boatland.rigid import add_point_force, angular_velocity, euler_moment, rotation_matrix


def _point(q, r):
    return q[:3] + rotation_matrix(q[3], q[4], q[5]) @ r


@pytest.mark.parametrize("angles", [(0.0, 0.0, 0.0), (0.05, -0.03, 0.4), (-0.3, 0.2, -1.2)])
def test_point_force_is_the_virtual_work_of_the_coordinates(angles):
    """Q_j = F · ∂p/∂q_j for p = x + R(φ, θ, ψ) r (central differences), at small and large angles."""
    rng = np.random.default_rng(5)
    q = np.r_[rng.normal(size=3), angles]
    r, d = rng.normal(size=3) * 5, rng.normal(size=3)
    f = 3.0e4
    R = rotation_matrix(*q[3:])
    p = R @ r
    out = np.zeros(6)
    add_point_force(R, p[0], p[1], p[2], d[0], d[1], d[2], f, out)
    h = 1e-6
    for j in range(6):
        e = np.zeros(6)
        e[j] = h
        dp = (_point(q + e, r) - _point(q - e, r)) / (2 * h)
        assert out[j] == pytest.approx(f * d @ dp, rel=1e-7, abs=1e-6 * f)


def test_first_order_terms_of_the_euler_axes():
    """To first order Q_φ = M_x + ψ M_y − θ M_z, Q_θ = M_y − ψ M_x, Q_ψ = M_z (the preload stiffness's terms)."""
    M = np.array([2.0e5, -1.4e5, 0.8e5])
    phi, theta, psi = 1e-4, -2e-4, 3e-4
    q = euler_moment(rotation_matrix(phi, theta, psi), *M)
    assert q[0] == pytest.approx(M[0] + psi * M[1] - theta * M[2], abs=1e-6 * abs(M).max())
    assert q[1] == pytest.approx(M[1] - psi * M[0], abs=1e-6 * abs(M).max())
    assert q[2] == M[2]


def test_angular_velocity_and_the_turning_axes():
    """ω from the Euler rates equals the axial vector of Ṙ Rᵀ, and d(ω)/dt − T q̈ the axes' own turning term,
    along a smooth path of the angles (central differences)."""
    def path(t):
        return np.array([0.2 * math.sin(1.3 * t), -0.1 * math.cos(0.7 * t), 0.5 * math.sin(0.4 * t + 0.3)])

    def rates(t, h=1e-5):
        return (path(t + h) - path(t - h)) / (2 * h)

    t, h = 0.8, 1e-5
    ang, rt = path(t), rates(t)
    R = rotation_matrix(*ang)
    v = np.r_[np.zeros(3), rt]
    w = np.array(angular_velocity(R, v)[:3])
    Rd = (rotation_matrix(*path(t + h)) - rotation_matrix(*path(t - h))) / (2 * h)
    W = Rd @ R.T
    np.testing.assert_allclose(w, [W[2, 1], W[0, 2], W[1, 0]], rtol=1e-6, atol=1e-9)

    def omega(tt):
        return np.array(angular_velocity(rotation_matrix(*path(tt)), np.r_[np.zeros(3), rates(tt)])[:3])

    qdd = (rates(t + 1e-4) - rates(t - 1e-4)) / 2e-4
    wdot = (omega(t + 1e-4) - omega(t - 1e-4)) / 2e-4
    T_qdd = np.array(angular_velocity(R, np.r_[np.zeros(3), qdd])[:3])
    np.testing.assert_allclose(wdot - T_qdd, angular_velocity(R, v)[3:], rtol=1e-4, atol=1e-7)


@pytest.mark.slow
def test_a_linear_sway_damping_leaves_the_friction_margin_gaussian():
    """The default landing (ctv27) at 135°, Hs 0.3 m, with an extra linear sway damping of 72 kN s/m (the
    drag's of a 1 m/s current): 48 × 30 min, contact 1's up-slip margin −(μ f_n + f_v) has the skewness of a
    Gaussian within its sampling error (0.005). Measured 2026-12-03: −0.004; with the moments about the fixed
    axes it was +0.026 (+0.004 without the damping) — yaw turned the fender's pitch moment into roll."""
    import warnings

    from scipy.stats import skew

    from stuck_margins import up_margin_records

    from boatland.checks.files import load, resolve_database
    from boatland.resources import shipped_scenarios

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(shipped_scenarios() / "ctv_landing.toml").replace(
            {"sea.Hs": 0.3, "sea.Tp": 7.0, "sea.relative_direction_deg": 135.0, "simulation.duration": 1834.0,
             "vessel.damping.linear": [0.0, 72e3, 0.0, 0.0, 0.0, 0.0]})
        z = up_margin_records(sc, resolve_database(sc), 48)
    g = float(skew(np.concatenate(z)))
    print(f"skewness of the up-slip margin: {g:+.4f}")
    assert abs(g) < 0.015
