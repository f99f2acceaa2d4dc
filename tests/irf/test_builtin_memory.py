"""Radiation memory of the shipped vessels with default settings: consistent, stable, passive.

Measured figures (round-trip errors per pair, orders, R²) are printed by ``boatland irf ctv24``
and listed in the issue notes; here they are bounded so a regression shows.
"""

import numpy as np
import pytest

from boatland.hydro.builtin import load_builtin
from boatland.vessel.radiation import radiation_memory


@pytest.fixture(scope="module", params=["ctv24", "model2"])
def memory(request):
    db = load_builtin(request.param)
    return db, radiation_memory(db)


def test_every_fit_is_stable_and_passive(memory):
    db, mem = memory
    ss = mem.state_space
    assert ss.pairs and all(f.stable for f in ss.pairs.values())
    assert np.nanmin(ss.passivity) >= -0.01
    assert min(f.r2 for f in ss.pairs.values()) >= 0.99


def test_coupled_pairs_follow_the_hull_symmetries(memory):
    """Port/starboard symmetry: {surge, heave, pitch} never couple with {sway, roll, yaw}. The generalized
    Wigley hull is also fore–aft symmetric (x → −x: surge, pitch, yaw odd; sway, heave, roll even), so
    heave–pitch and sway–yaw decouple too; surge–pitch and sway–roll remain."""
    _, mem = memory
    sig = mem.irf.significant
    assert sig[0, 4] and sig[1, 3]
    assert not (sig[2, 4] or sig[1, 5] or sig[3, 5] or sig[0, 2])
    across = [(i, j) for i in (0, 2, 4) for j in (1, 3, 5)]
    assert not any(sig[i, j] or sig[j, i] for i, j in across)


def test_round_trip_of_every_significant_pair(memory):
    """Measured (5 rad/s band, 2026-11-21): B within 0.55–3.99 %, A within 0.40–4.92 % (relative L2 over
    the band; worst: sway–roll and yaw, where the trapped-wave resonances between the demihulls make K
    ring), K(T_K)/max K ≤ 1.6 %. Bounds are regression guards a little above those figures."""
    _, mem = memory
    sig = mem.irf.significant
    assert np.max(mem.irf.err_B[sig]) < 0.05
    assert np.max(mem.irf.err_A[sig]) < 0.06
    assert np.max(mem.irf.truncation[sig]) < 0.05
