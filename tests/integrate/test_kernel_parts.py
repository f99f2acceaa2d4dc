"""Pieces of the RK4 kernel: the stage table and the state-space output ordering."""

import numpy as np

from boatland.integrate.cummins import _A_NEXT, _C2, _output_order


def test_stage_table_is_classic_rk4():
    """Stage times c = 0, ½, ½, 1 (in half steps 0, 1, 1, 2); each stage state is the step start plus
    c_next Δt times the previous stage's derivative (the RK4 tableau's sub-diagonal a = (½, ½, 1))."""
    assert _C2 == (0, 1, 1, 2)
    assert np.allclose(np.array(_C2[1:]) / 2, _A_NEXT)


def test_output_order_lists_each_dofs_states_in_order():
    ss_out = np.array([0, 0, 3, 1, 3, 0, 5], dtype=np.int64)
    order = _output_order(ss_out)
    assert order.shape == (3, 6)
    for d in range(6):
        col = order[:, d]
        assert list(col[col >= 0]) == list(np.flatnonzero(ss_out == d))
        assert (col[len(np.flatnonzero(ss_out == d)):] == -1).all()


def test_output_order_without_states():
    assert (_output_order(np.zeros(0, dtype=np.int64)) == -1).all()
