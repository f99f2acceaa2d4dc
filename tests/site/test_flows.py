"""Each sea state in its own current and wind (boatland.site.flows): on a node the limit is the screening's in
that current or wind, with neither the scenario's without; between nodes within a measured interpolation error;
the flows turn with the site; read from CSV and netCDF."""

import dataclasses

import h5py
import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.freqdomain import LandingSetup, screening_grid
from boatland.site import Weather, flow_setups, operability, read_weather, sea_limits
from boatland.site.flows import CURRENT_DIRECTION_STEP, CURRENT_SPEED_STEP, WIND_DIRECTION_STEP, WIND_SPEED_STEP

pytestmark = pytest.mark.slow          # a landed response per node of the flows: seconds to tens of seconds


@pytest.fixture(scope="module")
def ctv27():
    import warnings

    from boatland.checks.files import load_checked
    from tests.site.conftest import CTV27_LANDING

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc, db, _ = load_checked(CTV27_LANDING)
    return sc, db


def _exact(sc, db, Tp, beta, current=None, wind=None):
    """The screening's limit in exactly this current and wind (the scenario's [current] / [wind] set so)."""
    changes = {}
    if current is not None:
        changes.update({"current.speed": current[0], "current.relative_direction_deg": current[1]})
    if wind is not None:
        changes["wind"] = {"speed": wind[0], "relative_direction_deg": wind[1]}
    s = LandingSetup.from_scenario(sc.replace(changes) if changes else sc, db)
    return screening_grid(db, s, [Tp], [beta]).Hs[0, 0]


def _judged(sc, db, w, landings):
    return sea_limits(db, LandingSetup.from_scenario(sc, db), w, landings, flow_setup=flow_setups(sc, db))


def test_on_the_nodes_and_without_flows(ctv27):
    sc, db = ctv27
    # landing at 180° (vessel heading North); waves from 0° (head); a current from 90° (East: it flows towards
    # West, towards port — relative 90°) at 0.5 m/s, and none; a wind from 90° at 5 m/s, and none
    calm = _exact(sc, db, 7.0, 180.0)
    w = Weather.scatter([0.3, 0.3], [7.0, 7.0], [0.0, 0.0], [0.5, 0.5], current=([0.5, 0.0], [90.0, 90.0]))
    lim = _judged(sc, db, w, [180.0])
    assert lim.Hs_limit[0, 0] == pytest.approx(_exact(sc, db, 7.0, 180.0, current=(0.5, 90.0)), rel=1e-9)
    assert lim.Hs_limit[1, 0] == pytest.approx(calm, rel=1e-9)
    assert lim.Hs_limit[0, 0] < calm                       # a beam current takes friction from the waves
    assert "own current" in lim.source
    w = Weather.scatter([0.3, 0.3], [7.0, 7.0], [0.0, 0.0], [0.5, 0.5], wind=([5.0, 0.0], [90.0, 90.0]))
    lim = _judged(sc, db, w, [180.0])
    # the waves' contact forces are the landing's without wind (module docstring): within 0.7 % on a node
    assert lim.Hs_limit[0, 0] == pytest.approx(_exact(sc, db, 7.0, 180.0, wind=(5.0, 90.0)), rel=7e-3)
    assert lim.Hs_limit[1, 0] == pytest.approx(calm, rel=1e-9)
    assert lim.Hs_limit[0, 0] < 0.95 * calm                # the gusts swing the landed vessel
    assert "own wind" in lim.source


def _between(sc, db, which, seed=9, n=30):
    """``n`` seeded flows of ``which`` in any direction, waves head-on at Tp 5–9 s: the limit interpolated between
    the nodes against the screening in that very flow; (relative errors, speeds)."""
    rng = np.random.default_rng(seed)
    Tp = rng.uniform(5, 9, n).round(1)
    top = {"current": 1.5, "wind": 12.0}[which]
    U, rel = rng.uniform(0.05 * top, top, n).round(2), rng.uniform(0, 360, n).round(1)
    # landing at 0°: a flow from φ moves towards relative (0 − φ) mod 360 → φ = −rel
    w = Weather.scatter(np.full(n, 0.3), Tp, np.full(n, 180.0), np.full(n, 1 / n), **{which: (U, np.mod(-rel, 360.0))})
    lim = _judged(sc, db, w, [0.0])
    exact = np.array([_exact(sc, db, float(t), 180.0, **{which: (float(u), float(r))}) for t, u, r in zip(Tp, U, rel)])
    return np.abs(lim.Hs_limit[:, 0] / exact - 1)


def test_between_the_current_nodes(ctv27):
    """30 seeded currents up to 1.5 m/s: measured mean error 0.09 %, largest 0.51 % (the limit itself interpolated
    between the same nodes, as before the ingredients were: 0.87 % and 7.7 %)."""
    err = _between(*ctv27, "current")
    assert err.mean() < 0.002 and err.max() < 0.01, (err.mean(), err.max())


def test_between_the_wind_nodes(ctv27):
    """30 seeded winds up to 12 m/s: measured mean error 0.35 %, largest 1.9 % (with 15° between directions 0.51 %
    and 3.8 %; the limit falls from 0.38 to 0.18 m over these winds)."""
    err = _between(*ctv27, "wind")
    assert err.mean() < 0.005 and err.max() < 0.025, (err.mean(), err.max())


def test_current_and_wind_together(ctv27):
    """Both in each sea state: 8 seeded pairs against the screening in both. Measured: mean 0.60 %, largest 3.3 %
    (0.15 m/s of current with a 6 m/s wind: the current's drag damps the wind's swing in proportion to its speed,
    while the nodes are interpolated in its square — on the safe side, 0.343 m against 0.354 m)."""
    sc, db = ctv27
    rng = np.random.default_rng(5)
    n = 8
    Uc, rc = rng.uniform(0.1, 1.0, n).round(2), rng.uniform(0, 360, n).round(1)
    Uw, rw = rng.uniform(1.0, 10.0, n).round(2), rng.uniform(0, 360, n).round(1)
    w = Weather.scatter(np.full(n, 0.3), np.full(n, 7.0), np.full(n, 180.0), np.full(n, 1 / n),
                        current=(Uc, np.mod(-rc, 360.0)), wind=(Uw, np.mod(-rw, 360.0)))
    lim = _judged(sc, db, w, [0.0])
    exact = np.array([_exact(sc, db, 7.0, 180.0, current=(float(a), float(b)), wind=(float(c), float(d)))
                      for a, b, c, d in zip(Uc, rc, Uw, rw)])
    err = np.abs(lim.Hs_limit[:, 0] / exact - 1)
    assert err.mean() < 0.01 and err.max() < 0.04, (err.mean(), err.max())
    assert "own current and wind" in lim.source


def test_the_flows_turn_with_the_site(ctv27):
    sc, db = ctv27
    rng = np.random.default_rng(4)
    n = 60
    t = np.datetime64("2021-06-01T00:00") + np.arange(n).astype("timedelta64[h]")
    w = Weather.series(t, rng.uniform(0.05, 0.45, n), rng.uniform(4.0, 10.0, n), rng.integers(0, 360, n),
                       current=(rng.uniform(0.0, 1.2, n).round(2), rng.integers(0, 360, n)),
                       wind=(rng.uniform(0.0, 12.0, n).round(1), rng.integers(0, 360, n)))
    s = LandingSetup.from_scenario(sc, db)
    a = operability(db, s, w, [30.0, 210.0], flow_setup=flow_setups(sc, db))
    b = operability(db, s, w.rotated(71.0), [101.0, 281.0], flow_setup=flow_setups(sc, db))
    assert 0.05 < a.availability()[-1] < 0.95
    np.testing.assert_array_equal(a.workable, b.workable)
    np.testing.assert_allclose(a.limits.Hs_limit, b.limits.Hs_limit, rtol=1e-12)
    # the current matters both ways: it takes friction (a current across the vessel) or damps the motions and
    # adds to the push; so does a wind (from astern it presses the fender on), but mostly its gusts swing the vessel
    still = operability(db, s, dataclasses.replace(w, wind=None), [30.0, 210.0], flow_setup=flow_setups(sc, db))
    calm = operability(db, s, dataclasses.replace(w, current=None, wind=None), [30.0, 210.0])
    lower = (still.limits.Hs_limit < calm.limits.Hs_limit).mean()
    assert 0.1 < lower < 0.9, lower
    windy = np.broadcast_to(w.wind[0][:, None] > 3.0, a.limits.Hs_limit.shape)
    lower_w = (a.limits.Hs_limit < still.limits.Hs_limit)[windy].mean()
    assert 0.8 < lower_w < 1.0, lower_w            # measured: lower in 93 % of the windy judgements


def test_a_flow_just_below_north_interpolates_to_the_0_degree_node(ctv27):
    """A relative direction a hair below 360° belongs to the last interval, nearly all at 0°."""
    sc, db = ctv27
    for what in ("current", "wind"):
        speed = {"current": 0.5, "wind": 6.0}[what]
        w = Weather.scatter([0.3, 0.3], [7.0, 7.0], [180.0, 180.0], [0.5, 0.5],
                            **{what: ([speed, speed], [1e-9, 0.0])})   # at the landing at 0°: towards 359.999…°, 0°
        lim = _judged(sc, db, w, [0.0])
        assert lim.Hs_limit[0, 0] == pytest.approx(lim.Hs_limit[1, 0], rel=1e-6)


def test_a_node_the_landing_cannot_be_held_in_is_limit_0_not_an_abort(ctv27):
    """At 2.5 m/s of beam current and a 10 m/s beam wind the skipper's trim cannot balance the yaw moment (the
    scenario's thrust.direction_deg = 'trim'): that node counts as limit 0, said; the other sea states are judged."""
    sc, db = ctv27
    w = Weather.scatter([0.3, 0.3], [7.0, 7.0], [180.0, 180.0], [0.5, 0.5], current=([0.5, 2.3], [270.0, 270.0]),
                        wind=([5.0, 12.0], [270.0, 270.0]))
    lim = _judged(sc, db, w, [0.0])
    assert lim.Hs_limit[1, 0] == 0.0 and lim.Hs_limit[0, 0] > 0.2
    assert "cannot be held" in lim.source and "cannot balance the steady yaw moment" in lim.source


def test_a_scenario_that_cannot_take_a_flow_says_so(ctv27):
    """A configuration error (here: no hull mesh to measure the current's areas on) is that error, not a
    'no static equilibrium' limit of 0."""
    sc, db = ctv27
    bare = db.replace(mesh=None)
    w = Weather.scatter([0.3], [7.0], [180.0], [1.0], current=([0.6], [90.0]))
    with pytest.raises((BoatlandInputError, ValueError), match="mesh"):
        sea_limits(bare, LandingSetup.from_scenario(sc, db), w, [0.0], flow_setup=flow_setups(sc, bare))


@pytest.mark.parametrize("what", ["current", "wind"])
def test_the_flows_from_csv(tmp_path, what):
    speed, direction = f"{what}_speed", f"{what}_direction_from_deg"
    p = tmp_path / "c.csv"
    p.write_text(f"time,Hs,Tp,direction_from_deg,{speed},{direction}\n"
                 "2021-01-01T00:00,0.5,6,270,0.8,45\n2021-01-01T01:00,0.6,6,270,0.0,0\n")
    w = read_weather(p)
    assert getattr(w, what)[0].tolist() == [0.8, 0.0] and getattr(w, what)[1].tolist() == [45.0, 0.0]
    assert w.rotated(10.0).take([0]).__getattribute__(what)[1].tolist() == [55.0]
    p.write_text(f"Hs,Tp,direction_from_deg,occurrence,{speed}\n0.5,6,270,1,0.8\n")
    with pytest.raises(BoatlandInputError, match=f"the {what} needs both {speed} and {direction}"):
        read_weather(p)
    p.write_text(f"Hs,Tp,direction_from_deg,occurrence,{speed},{direction}\n0.5,6,270,1,-1,0\n")
    with pytest.raises(BoatlandInputError, match=f"line 2: {speed} = -1"):
        read_weather(p)
    p.write_text(f"Hs,Tp,direction_from_deg,occurrence,{speed},{direction}\n0.5,6,270,1,,0\n")
    with pytest.raises(BoatlandInputError, match=f"line 2: the {what}'s speed or direction is empty"):
        read_weather(p)


def test_the_wind_from_netcdf_by_its_cf_names(tmp_path):
    """The CF standard names ``wind_speed`` and ``wind_from_direction`` (the ones ERA5's converters write)."""
    p = tmp_path / "w.nc"
    with h5py.File(p, "w") as f:
        t = f.create_dataset("time", data=np.array([0.0, 1.0]))
        t.attrs["units"] = "hours since 2021-01-01 00:00:00"
        for name, v in (("hs", [0.5, 0.6]), ("tp", [6.0, 6.0]), ("mwd", [270.0, 270.0]), ("ws", [8.0, 3.0]),
                        ("wd", [200.0, 10.0])):
            f.create_dataset(name, data=np.array(v))
        for name, std in (("hs", "sea_surface_wave_significant_height"),
                          ("tp", "sea_surface_wave_period_at_variance_spectral_density_maximum"),
                          ("mwd", "sea_surface_wave_from_direction"), ("ws", "wind_speed"),
                          ("wd", "wind_from_direction")):
            f[name].attrs["standard_name"] = std
    w = read_weather(p)
    assert w.wind[0].tolist() == [8.0, 3.0] and w.wind[1].tolist() == [200.0, 10.0] and w.current is None


def test_the_readme_says_the_steps_the_code_takes():
    from tests.site.conftest import ROOT

    readme = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    assert f"current every {CURRENT_SPEED_STEP:g} m/s and {CURRENT_DIRECTION_STEP:g}°" in readme
    assert f"wind every {WIND_SPEED_STEP:g} m/s and {WIND_DIRECTION_STEP:g}°" in readme
