"""Each sea state in its own current (boatland.site.current): on a node the limit is the
screening's in that current, with no current the scenario's without one, between nodes within a measured
interpolation error; the current turns with the site; read from CSV."""

import dataclasses

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.freqdomain import LandingSetup, screening_grid
from boatland.site import Weather, current_setups, operability, read_weather, sea_limits
from boatland.site.current import CURRENT_DIRECTION_STEP, CURRENT_SPEED_STEP

pytestmark = pytest.mark.slow          # a screening per node of the current: tens of seconds


@pytest.fixture(scope="module")
def ctv27():
    import warnings

    from boatland.checks.files import load_checked
    from tests.site.conftest import CTV27_LANDING

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc, db, _ = load_checked(CTV27_LANDING)
    return sc, db


def _exact(sc, db, U, rel, Tp, beta):
    """The screening's limit in exactly this current (the scenario's [current] set so)."""
    s = LandingSetup.from_scenario(sc.replace({"current.speed": U, "current.relative_direction_deg": rel}), db)
    return screening_grid(db, s, [Tp], [beta]).Hs[0, 0]


def test_on_the_nodes_and_without_current(ctv27):
    sc, db = ctv27
    # landing at 180° (vessel heading North); waves from 0° (head); currents from 90° (East: it flows towards
    # West, towards port — relative 90°) at 0.5 m/s, and none
    w = Weather.scatter([0.3, 0.3], [7.0, 7.0], [0.0, 0.0], [0.5, 0.5], current=([0.5, 0.0], [90.0, 90.0]))
    lim = sea_limits(db, LandingSetup.from_scenario(sc, db), w, [180.0], current_setup=current_setups(sc, db))
    assert lim.Hs_limit[0, 0] == pytest.approx(_exact(sc, db, 0.5, 90.0, 7.0, 180.0), rel=1e-9)
    calm = screening_grid(db, LandingSetup.from_scenario(sc, db), [7.0], [180.0]).Hs[0, 0]
    assert lim.Hs_limit[1, 0] == pytest.approx(calm, rel=1e-9)
    assert lim.Hs_limit[0, 0] < calm                       # a beam current takes friction from the waves
    assert "own current" in lim.source


def test_between_the_nodes(ctv27):
    """30 seeded currents up to 1.5 m/s in any direction: the limit interpolated between the nodes against the
    screening in that very current. Measured: mean error 0.87 %, largest 7.7 % (1.3 m/s towards 45.5°, next to the
    node 1.5 m/s towards 60° where the landing has no static equilibrium and the limit is taken as 0)."""
    sc, db = ctv27
    rng = np.random.default_rng(9)
    n = 30
    U, rel = rng.uniform(0.05, 1.5, n).round(2), rng.uniform(0, 360, n).round(1)
    # landing at 0°: a current from φ flows towards relative (0 − φ) mod 360 → φ = −rel
    w = Weather.scatter(np.full(n, 0.3), np.full(n, 7.0), np.full(n, 180.0), np.full(n, 1 / n),
                        current=(U, np.mod(-rel, 360.0)))
    lim = sea_limits(db, LandingSetup.from_scenario(sc, db), w, [0.0], current_setup=current_setups(sc, db))
    exact = np.array([_exact(sc, db, float(u), float(r), 7.0, 180.0) for u, r in zip(U, rel)])
    err = np.abs(lim.Hs_limit[:, 0] / exact - 1)
    assert err.mean() < 0.01 and err.max() < 0.08, (err.mean(), err.max())
    assert "no static equilibrium on the landing in" in lim.source and "1.5 m/s towards 60°" in lim.source


def test_the_current_turns_with_the_site(ctv27):
    sc, db = ctv27
    rng = np.random.default_rng(4)
    n = 120
    t = np.datetime64("2021-06-01T00:00") + np.arange(n).astype("timedelta64[h]")
    w = Weather.series(t, rng.uniform(0.05, 0.45, n), rng.uniform(4.0, 10.0, n), rng.integers(0, 360, n),
                       current=(rng.uniform(0.0, 1.2, n).round(2), rng.integers(0, 360, n)))
    s = LandingSetup.from_scenario(sc, db)
    a = operability(db, s, w, [30.0, 210.0], current_setup=current_setups(sc, db))
    b = operability(db, s, w.rotated(71.0), [101.0, 281.0], current_setup=current_setups(sc, db))
    assert 0.05 < a.availability()[-1] < 0.95
    np.testing.assert_array_equal(a.workable, b.workable)
    np.testing.assert_allclose(a.limits.Hs_limit, b.limits.Hs_limit, rtol=1e-12)
    # the current matters both ways: it takes friction (a current across the vessel) or damps the motions and
    # adds to the push (measured here: lower in 33 % of the 240, higher in the rest)
    still = operability(db, s, dataclasses.replace(w, current=None), [30.0, 210.0])
    lower = (a.limits.Hs_limit < still.limits.Hs_limit).mean()
    assert 0.1 < lower < 0.9, lower


def test_a_current_just_below_north_interpolates_to_the_0_degree_node(ctv27):
    """A relative current direction a hair below 360° belongs to the 345°–0° interval, nearly all at 0°."""
    sc, db = ctv27
    w = Weather.scatter([0.3, 0.3], [7.0, 7.0], [180.0, 180.0], [0.5, 0.5],
                        current=([0.5, 0.5], [1e-9, 0.0]))             # at the landing at 0°: towards 359.999…°, 0°
    lim = sea_limits(db, LandingSetup.from_scenario(sc, db), w, [0.0], current_setup=current_setups(sc, db))
    assert lim.Hs_limit[0, 0] == pytest.approx(lim.Hs_limit[1, 0], rel=1e-6)


def test_a_scenario_that_cannot_take_a_current_says_so(ctv27):
    """A configuration error (here: no hull mesh to measure the current's areas on) is that error, not a
    'no static equilibrium' limit of 0."""
    sc, db = ctv27
    bare = db.replace(mesh=None)
    w = Weather.scatter([0.3], [7.0], [180.0], [1.0], current=([0.6], [90.0]))
    with pytest.raises((BoatlandInputError, ValueError), match="mesh"):
        sea_limits(bare, LandingSetup.from_scenario(sc, db), w, [0.0], current_setup=current_setups(sc, bare))


def test_the_current_from_csv(tmp_path):
    p = tmp_path / "c.csv"
    p.write_text("time,Hs,Tp,direction_from_deg,current_speed,current_direction_from_deg\n"
                 "2021-01-01T00:00,0.5,6,270,0.8,45\n2021-01-01T01:00,0.6,6,270,0.0,0\n")
    w = read_weather(p)
    assert w.current[0].tolist() == [0.8, 0.0] and w.current[1].tolist() == [45.0, 0.0]
    p.write_text("Hs,Tp,direction_from_deg,occurrence,current_speed\n0.5,6,270,1,0.8\n")
    with pytest.raises(BoatlandInputError, match="the current needs both current_speed and current_direction_from_deg"):
        read_weather(p)
    p.write_text("Hs,Tp,direction_from_deg,occurrence,current_speed,current_direction_from_deg\n0.5,6,270,1,-1,0\n")
    with pytest.raises(BoatlandInputError, match="line 2: current_speed = -1"):
        read_weather(p)
    p.write_text("Hs,Tp,direction_from_deg,occurrence,current_speed,current_direction_from_deg\n0.5,6,270,1,,0\n")
    with pytest.raises(BoatlandInputError, match="line 2: the current's speed or direction is empty"):
        read_weather(p)


def test_the_readme_says_the_steps_the_code_takes():
    from tests.site.conftest import ROOT

    readme = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    assert f"nodes every {CURRENT_SPEED_STEP:g} m/s and {CURRENT_DIRECTION_STEP:g}° of relative direction" in readme
