"""Pieces of the RK4 kernel: the stage table and the state-space memory in its modal layout."""

import numpy as np
import pytest

from boatland import rk4
from boatland.integrate.cummins import _A_NEXT, _C2, _state_space
from boatland.trial.motion import modal_layout


def test_stage_table_is_classic_rk4():
    """The integrator reads the tableau of :mod:`boatland.rk4`: stage times c = 0, ½, ½, 1 (in half steps
    0, 1, 1, 2); each stage state is the step start plus a Δt times the previous stage's derivative."""
    assert _C2 == rk4.C_HALF_STEPS == (0, 1, 1, 2)
    assert _A_NEXT == rk4.A_NEXT and np.allclose(np.array(_C2[1:]) / 2, _A_NEXT)


def _toy_system():
    """Seven states on four pairs: a real pole, complex pairs (partners neighbours), outputs 0, 0, 3, 5."""
    A2 = np.array([[-1.0, 0.0], [-0.3, 2.0], [-0.3, -2.0], [-0.5, 0.0], [-0.2, 1.5], [-0.2, -1.5], [-4.0, 0.0]])
    B = np.array([1.0, 0.5, -0.25, 2.0, 0.7, 0.1, 3.0])
    C = np.array([0.9, -1.1, 0.4, 1.3, 0.6, -0.8, 0.2])
    s_in = np.array([0, 4, 4, 2, 1, 1, 5], dtype=np.int64)
    s_out = np.array([0, 0, 0, 3, 3, 3, 5], dtype=np.int64)
    pair = np.array([-1, 2, 1, -1, 5, 4, -1], dtype=np.int64)
    return A2, B, C, s_in, s_out, pair


def _dense(A2, B, C, s_in, s_out, pair, z, v, F):
    """The modal system written out state by state in the kernel's order of operations."""
    kz = np.empty_like(z)
    for s in range(z.size):
        acc = A2[s, 0] * z[s] + B[s] * v[s_in[s]]
        if pair[s] >= 0:
            acc += A2[s, 1] * z[pair[s]]
        kz[s] = acc
    F = F.copy()
    for s in range(z.size):
        F[s_out[s]] -= C[s] * z[s]
    return kz, F


def test_modal_layout_keeps_each_states_arithmetic_bit_for_bit():
    """The kernel's state-space step in its layout equals the plain state-by-state evaluation exactly
    (same operations in the same order); the guards stay zero."""
    A2, B, C, s_in, s_out, pair = _toy_system()
    ss_A, ss_B, ss_C, seg, rows = modal_layout(A2, B, C, s_in, s_out, pair)
    assert ss_A.shape == (3, 9)
    assert rows.tolist() == [[1, 3], [4, 0], [4, 0], [4, 3], [7, 0], [7, 1]]
    covered = np.concatenate([np.arange(a, b) for a, b, _ in seg])
    assert np.array_equal(covered, np.arange(1, 8))                       # every state once, in order
    assert all((s_in[a - 1:b - 1] == j).all() for a, b, j in seg)          # one input per run
    rng = np.random.default_rng(7)
    z, v, F = rng.normal(size=7), rng.normal(size=6), rng.normal(size=6)
    zp = np.concatenate([[0.0], z, [0.0]])
    kz = np.full((4, 9), np.nan)
    Fk = F.copy()
    _state_space(v, zp, ss_A, ss_B, ss_C, seg, rows, 2, kz, Fk)
    kz_ref, F_ref = _dense(A2, B, C, s_in, s_out, pair, z, v, F)
    assert np.array_equal(kz[2, 1:-1], kz_ref) and np.array_equal(Fk, F_ref)
    assert np.all(ss_A[:, [0, -1]] == 0.0) and np.all(ss_B[[0, -1]] == 0.0) and np.all(ss_C[[0, -1]] == 0.0)


def test_modal_layout_refuses_what_the_kernel_cannot_read():
    A2, B, C, s_in, s_out, pair = _toy_system()
    with pytest.raises(ValueError, match="grouped by output DOF"):
        modal_layout(A2, B, C, s_in, s_out[::-1].copy(), pair)
    far = pair.copy()
    far[1], far[2] = 5, 4
    with pytest.raises(ValueError, match="neighbour"):
        modal_layout(A2, B, C, s_in, s_out, far)


def test_modal_layout_without_states():
    e = np.zeros(0, dtype=np.int64)
    ss_A, ss_B, ss_C, seg, rows = modal_layout(np.zeros((0, 2)), np.zeros(0), np.zeros(0), e, e, e)
    assert ss_A.shape == (3, 2) and seg.shape == (0, 3) and (rows[:, 1] == 0).all()
