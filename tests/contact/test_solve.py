"""The small dense algebra of the augmented stick solve, written out without BLAS/LAPACK calls, against
numpy: the Schur-complement products and the pseudo-inverse solve (1–8 stick constraints)."""

import numpy as np
import pytest

from boatland.contact.fender import STICK_DAMPING, _damped_solve, _schur

M_MAX = 8


@pytest.mark.parametrize("m", [1, 2, 3, 4, 8])
def test_schur_products_match_numpy(m):
    """MG = (M+A∞)⁻¹G, W = GᵀMG, rhs = target − Gᵀacc over the first m columns (the rest of the
    buffers is left alone)."""
    rng = np.random.default_rng(m)
    Mt_inv, G = rng.standard_normal((6, 6)), rng.standard_normal((6, M_MAX))
    acc, target = rng.standard_normal(6), rng.standard_normal(M_MAX)
    MG, W, rhs = np.full((6, M_MAX), 7.0), np.full((M_MAX, M_MAX), 7.0), np.full(M_MAX, 7.0)
    _schur(Mt_inv, G, m, acc, target, MG, W, rhs)
    Gm = G[:, :m]
    np.testing.assert_allclose(MG[:, :m], Mt_inv @ Gm, rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(W[:m, :m], Gm.T @ Mt_inv @ Gm, rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(rhs[:m], target[:m] - Gm.T @ acc, rtol=1e-14, atol=1e-14)
    assert (MG[:, m:] == 7.0).all() and (W[m:, :] == 7.0).all() and (rhs[m:] == 7.0).all()


def damped_solve(W, b, m):
    Wb = np.zeros((M_MAX, M_MAX)); Wb[:m, :m] = W
    bb = np.zeros(M_MAX); bb[:m] = b
    y, V = np.zeros(M_MAX), np.zeros((M_MAX, M_MAX))
    _damped_solve(Wb, bb, m, V, y, STICK_DAMPING)
    return y[:m]


def damped_reference(W, b):
    lam, V = np.linalg.eigh(W)
    mu = STICK_DAMPING * np.diag(W).max()
    g = np.where(lam > 1e-12 * lam.max(), lam / (lam ** 2 + mu ** 2), 0.0)
    return V @ (g * (V.T @ b))


@pytest.mark.parametrize("m", [1, 2, 4, 8])
def test_damped_solve_on_a_well_conditioned_system_is_the_solution(m):
    """Condition number κ: the damping changes the solution by at most (ρκ)² relative (in norm)."""
    rng = np.random.default_rng(10 + m)
    A = rng.standard_normal((m, m))
    W = A @ A.T + m * np.eye(m)
    b = rng.standard_normal(m)
    y = damped_solve(W, b, m)
    ref = damped_reference(W, b)
    assert np.linalg.norm(y - ref) <= 1e-9 * np.linalg.norm(ref)   # Cholesky of W² + μ²I (κ ≤ 1/ρ²)
    kappa = np.linalg.cond(W)
    x = np.linalg.solve(W, b)
    assert np.linalg.norm(y - x) <= ((STICK_DAMPING * kappa) ** 2 + 1e-12) * np.linalg.norm(x)


@pytest.mark.parametrize("m", [2, 4, 8])
def test_redundant_constraints_share_equally_and_stay_bounded(m):
    """Two contacts on one plane constrain the same sideways motion: two equal columns of G make
    W = GᵀM⁻¹G singular. The copies' right-hand sides differ (anchors, centripetal terms): the solution
    is the minimum-norm one (equal shares, finite), where (W + εI)⁻¹ gives forces ~ difference / ε."""
    rng = np.random.default_rng(20 + m)
    G = rng.standard_normal((6, m))
    G[:, 1] = G[:, 0]
    Minv = np.linalg.inv(np.diag(rng.uniform(1, 5, 6)) + 0.1)
    W = G.T @ Minv @ G
    W = 0.5 * (W + W.T)
    b = rng.standard_normal(m)
    b[1] = b[0] + 1e-3                      # an inconsistent pair of copies
    y = damped_solve(W, b, m)
    ref = damped_reference(W, b)
    assert np.linalg.norm(y - ref) <= 1e-9 * np.linalg.norm(ref)
    assert y[0] == pytest.approx(y[1], rel=1e-9)
    lam = np.linalg.eigvalsh(W)
    assert np.abs(y).max() < 10 * np.abs(b).max() / lam[lam > 1e-9 * lam.max()].min()


def test_a_nearly_redundant_lever_is_damped():
    """The same two contacts after a small yaw: the columns differ by a lever ℓ. A rigid solve gives
    forces ∝ 1/ℓ; the damped one stays below 1/(2μ) times the right-hand side, μ = ρ max W_kk."""
    G = np.zeros((6, 2))
    G[1, :] = 1.0                            # sideways
    G[5, 0], G[5, 1] = 12.3, 12.3 + 1e-5     # yaw lever: x of the two points differs by 10 µm
    Minv = np.diag([1 / 9e4, 1 / 9e4, 1 / 9e4, 1 / 4e5, 1 / 4e6, 1 / 4e6])
    W = G.T @ Minv @ G
    b = np.array([0.0, 1e-3])
    y = damped_solve(W, b, 2)
    rigid = np.linalg.solve(W, b)
    mu = STICK_DAMPING * np.diag(W).max()
    assert np.abs(rigid).max() > 1e9
    assert np.abs(y).max() <= np.linalg.norm(b) / (2 * mu) * (1 + 1e-9)
