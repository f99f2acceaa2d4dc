"""Port/starboard symmetry of the default ctv24 landing — what lets a limit table over 0–330° run 0–180° only
(scenarios/campaigns/isee_scatter.toml): the database mirrors, and so do the screening's limits."""

from __future__ import annotations

import numpy as np

from boatland.api import load_scenario
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import screening_grid
from boatland.hydro.builtin import load_builtin

#: Sign of each DOF under the mirror y → −y: sway, roll and yaw change sign.
MIRROR = np.array([1, -1, 1, -1, 1, -1])


def test_the_ctv24_database_mirrors_port_and_starboard():
    db = load_builtin("ctv24")
    S = np.outer(MIRROR, MIRROR)
    for name in ("A", "B"):
        a = getattr(db, name)                           # (6, 6, Nf)
        np.testing.assert_allclose(a * S[:, :, None], a, rtol=0, atol=1e-9 * np.abs(a).max())
    np.testing.assert_allclose(db.C * S, db.C, rtol=0, atol=1e-9 * np.abs(db.C).max())
    beta = db.wave_dir_deg
    for k, b in enumerate(beta):                        # X(−β) = S X(β), directions as the database stores them
        j = np.flatnonzero(np.isclose(np.mod(beta, 360.0), np.mod(-b, 360.0)))
        if j.size:
            np.testing.assert_allclose(db.X[:, j[0]], MIRROR[:, None] * db.X[:, k], rtol=0,
                                       atol=1e-6 * np.abs(db.X).max())


def test_the_default_landings_limits_mirror():
    """The screening's limiting Hs at β and 360° − β agree to 1e-9 (the landing's two contacts at ±0.75 m, the
    push on the centreline, no current or wind)."""
    sc = load_scenario("ctv24_landing")
    db = load_builtin("ctv24")
    beta = np.arange(0.0, 360.0, 30.0)
    table = screening_grid(db, LandingSetup.from_scenario(sc, db), [4.0, 7.0, 12.0], beta)
    H = np.asarray(table.Hs)                              # (NT, Nβ)
    mirror = np.mod(360.0 - beta, 360.0)
    idx = [int(np.flatnonzero(np.isclose(beta, m))[0]) for m in mirror]
    np.testing.assert_allclose(H[:, idx], H, rtol=1e-9)
