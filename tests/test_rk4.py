"""The RK4 tableau (boatland.rk4) is classic RK4, and the integrator's written-out update is it."""

import numpy as np
import pytest

from boatland import rk4
from boatland.trial.motion import MotionArrays


def test_the_tableau_is_consistent_and_fourth_order():
    A, b, c = np.array(rk4.A), np.array(rk4.B), np.array(rk4.C)
    assert A.shape == (rk4.STAGES, rk4.STAGES) and np.all(np.triu(A) == 0)     # explicit
    assert b.sum() == pytest.approx(1.0, abs=1e-15)
    np.testing.assert_allclose(A.sum(axis=1), c, atol=1e-15)                 # row sums are the nodes
    # the order conditions up to 4 (Hairer, Nørsett & Wanner 1993, Table II.2.1)
    for lhs, rhs in ((b @ c, 1 / 2), (b @ c ** 2, 1 / 3), (b @ A @ c, 1 / 6), (b @ c ** 3, 1 / 4),
                     (b @ (c * (A @ c)), 1 / 8), (b @ A @ c ** 2, 1 / 12), (b @ A @ A @ c, 1 / 24)):
        assert lhs == pytest.approx(rhs, abs=1e-15)


def test_the_kernels_views_are_the_tableaus():
    assert rk4.A_NEXT == (0.5, 0.5, 1.0)                       # a chain: each stage reads only the one before
    assert rk4.C_HALF_STEPS == (0, 1, 1, 2)
    A = np.array(rk4.A)
    assert all(A[s, :s - 1].sum() == 0 for s in range(2, rk4.STAGES))


def test_one_step_of_the_integrator_is_the_tableau():
    """x'' = −(C/M) x + F/M, one step from a state with velocity: the kernel's ``dt / 6 (k0 + 2k1 + 2k2 + k3)``
    equals y + dt Σ b_s k_s with k_s from the tableau, to round-off."""
    M = np.diag([2.0, 3.0, 4.0, 5.0, 6.0, 7.0])
    C = np.diag([8.0, 9.0, 10.0, 11.0, 12.0, 13.0])
    x0, v0, dt = np.linspace(0.1, 0.6, 6), np.linspace(-0.3, 0.2, 6), 0.07
    out = MotionArrays.without_memory(M, C).run(dt, 1, x0=x0, v0=v0)
    f = lambda y: np.concatenate([y[6:], -np.linalg.solve(M, C @ y[:6])])   # noqa: E731
    y, k = np.concatenate([x0, v0]), []
    for s in range(rk4.STAGES):
        k.append(f(y + dt * sum(rk4.A[s][j] * k[j] for j in range(s))))
    y1 = y + dt * sum(b * ks for b, ks in zip(rk4.B, k))
    np.testing.assert_allclose(np.concatenate([out["x"][1], out["v"][1]]), y1, rtol=1e-14, atol=1e-16)
