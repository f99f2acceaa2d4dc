"""Pieces of the RK4 kernel: the stage table and the state-space memory, discretised exactly, in its modal layout."""

import numpy as np
import pytest

from boatland import rk4
from boatland.integrate.cummins import _A_NEXT, _C2, _ss_advance, _ss_history
from boatland.trial.motion import hold_discretisation, modal_layout


def test_stage_table_is_classic_rk4():
    """The integrator reads the tableau of :mod:`boatland.rk4`: stage times c = 0, ½, ½, 1 (in half steps
    0, 1, 1, 2); each stage state is the step start plus a Δt times the previous stage's derivative."""
    assert _C2 == rk4.C_HALF_STEPS == (0, 1, 1, 2)
    assert _A_NEXT == rk4.A_NEXT and np.allclose(np.array(_C2[1:]) / 2, _A_NEXT)


def _toy_system():
    """Seven states on four pairs: a real pole, complex pairs (partners neighbours), outputs 0, 0, 3, 5;
    per state (φ, φ', γ₀, γ₁) and the output coefficients at c = 0, ½, 1."""
    E = np.array([[0.9, 0.0, 0.1, 0.05], [0.8, 0.2, 0.3, -0.1], [0.8, -0.2, 0.02, 0.4], [0.95, 0.0, 0.7, 0.2],
                  [0.85, 0.15, -0.3, 0.6], [0.85, -0.15, 0.1, 0.1], [0.6, 0.0, 1.1, -0.5]])
    P = np.array([[0.9, 0.8, 0.7], [-1.1, -1.0, -0.9], [0.4, 0.5, 0.6], [1.3, 1.2, 1.1], [0.6, 0.7, 0.8],
                  [-0.8, -0.7, -0.6], [0.2, 0.1, 0.05]])
    s_in = np.array([0, 4, 4, 2, 1, 1, 5], dtype=np.int64)
    s_out = np.array([0, 0, 0, 3, 3, 3, 5], dtype=np.int64)
    pair = np.array([-1, 2, 1, -1, 5, 4, -1], dtype=np.int64)
    return E, P, s_in, s_out, pair


def test_modal_layout_keeps_each_states_arithmetic_bit_for_bit():
    """The state-space advance in the kernel's layout equals the plain state-by-state evaluation exactly
    (same operations in the same order); its history sums equal the plain sums to round-off (they may
    be reassociated into SIMD lanes); the guards stay zero."""
    E, P, s_in, s_out, pair = _toy_system()
    ss_E, ss_P, seg, rows = modal_layout(E, P, s_in, s_out, pair)
    assert ss_E.shape == (5, 9) and ss_P.shape == (3, 9)
    assert rows.tolist() == [[1, 3], [4, 0], [4, 0], [4, 3], [7, 0], [7, 1]]
    covered = np.concatenate([np.arange(a, b) for a, b, _ in seg])
    assert np.array_equal(covered, np.arange(1, 8))                       # every state once, in order
    assert all((s_in[a - 1:b - 1] == j).all() for a, b, j in seg)          # one input per run
    rng = np.random.default_rng(7)
    z, v_n, v = rng.normal(size=7), rng.normal(size=6), rng.normal(size=6)
    zp = np.concatenate([[0.0], z, [0.0]])
    z_next = np.full(9, np.nan)
    z_next[[0, -1]] = 0.0
    _ss_advance(zp, z_next, ss_E, seg, v_n, v)
    ref = np.empty(7)
    for s in range(7):
        acc = E[s, 0] * z[s]
        if pair[s] >= 0:
            acc += E[s, 1] * z[pair[s]]
        ref[s] = (acc + E[s, 2] * v_n[s_in[s]]) + E[s, 3] * v[s_in[s]]
    assert np.array_equal(z_next[1:-1], ref)
    H = np.full((3, 6), np.nan)
    _ss_history(zp, ss_P, rows, H)
    H_ref = np.zeros((3, 6))
    for s in range(7):
        H_ref[:, s_out[s]] += P[s] * z[s]
    assert np.allclose(H, H_ref, rtol=1e-14, atol=1e-15)
    assert np.all(ss_E[:, [0, -1]] == 0.0) and np.all(ss_P[:, [0, -1]] == 0.0)


def test_hold_discretisation_is_exact():
    """A real pole against the closed form Φ = e^{ph}, Γ₀ + Γ₁ = (e^{ph} − 1)/p, Γ₁ = (e^{ph} − 1 − ph)/(p²h);
    a complex pair against an ODE solution for a velocity linear over the step."""
    p, b, h = -0.7, 1.3, 0.05
    Phi, g0, g1 = hold_discretisation(np.array([[p]]), np.array([b]), h)
    e = np.exp(p * h)
    assert Phi[0, 0] == pytest.approx(e, rel=1e-14)
    assert g0[0] + g1[0] == pytest.approx(b * (e - 1) / p, rel=1e-12)
    assert g1[0] == pytest.approx(b * (e - 1 - p * h) / (p * p * h), rel=1e-9)
    from scipy.integrate import solve_ivp

    a = np.array([[-0.3, 2.0], [-2.0, -0.3]])
    bb = np.array([1.0, 0.0])
    h = 0.4
    Phi, g0, g1 = hold_discretisation(a, bb, h)
    z0, u0, u1 = np.array([0.2, -0.5]), 0.7, -1.1
    sol = solve_ivp(lambda t, z: a @ z + bb * (u0 + (u1 - u0) * t / h), (0, h), z0, rtol=1e-12, atol=1e-14)
    assert np.allclose(Phi @ z0 + g0 * u0 + g1 * u1, sol.y[:, -1], rtol=1e-9, atol=1e-12)


def test_modal_layout_refuses_what_the_kernel_cannot_read():
    E, P, s_in, s_out, pair = _toy_system()
    with pytest.raises(ValueError, match="grouped by output DOF"):
        modal_layout(E, P, s_in, s_out[::-1].copy(), pair)
    far = pair.copy()
    far[1], far[2] = 5, 4
    with pytest.raises(ValueError, match="neighbour"):
        modal_layout(E, P, s_in, s_out, far)


def test_modal_layout_without_states():
    e = np.zeros(0, dtype=np.int64)
    ss_E, ss_P, seg, rows = modal_layout(np.zeros((0, 4)), np.zeros((0, 3)), e, e, e)
    assert ss_E.shape == (5, 2) and ss_P.shape == (3, 2) and seg.shape == (0, 3) and (rows[:, 1] == 0).all()
