"""The loads beside the waves on the landed vessel (boatland.landing.environment): current statics by the drag
formula, the landed equilibrium under steady loads against the linear solve, the skipper's trim, and a waves-only
landing that is exactly today's."""

import math
import warnings

import numpy as np
import pytest

from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import landed_response
from boatland.landing.setup import Setup
from boatland.trial.simulate import simulate


@pytest.fixture(scope="module")
def default_landing():
    from boatland.checks.files import load
    from boatland.hydro.read import load_database
    from boatland.resources import shipped_scenarios

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load(shipped_scenarios() / "ctv_landing.toml"), load_database("ctv27")


def side_force(setup, r):
    """The tubes' friction on the vessel along the body y axis at the run's end [N]."""
    t_h = np.cross([0.0, 0.0, 1.0], setup.fender.normals_3d)
    return float(np.sum(r.ft[-1, :, 1] * t_h[:, 1]))


def test_a_beam_current_loads_the_fender_by_the_drag_formula(default_landing):
    # a push straight ahead (no trim) and a current too weak to turn the vessel about the bow: the tubes
    # carry ½ ρ c_y A_y U² sideways, within 1 %
    scenario, db = default_landing
    sc = scenario.replace({"sea": None, "simulation.duration": 150.0, "thrust.direction_deg": 0.0,
                           "current.speed": 0.3, "current.relative_direction_deg": 90.0})
    setup = Setup.of(sc, db)
    c = setup.environment.current
    Fy = 0.5 * db.rho * 1.0 * c.area_y * 0.3 ** 2
    assert c.area_y == pytest.approx(70.6, abs=0.1)           # ctv27's two demihulls (boatland.loads.current)
    r = simulate(sc, db)
    assert -side_force(setup, r) == pytest.approx(Fy, rel=0.01)
    assert r.mode[-1].tolist() == [1, 1]


def test_without_the_trim_a_beam_current_turns_the_vessel_about_its_bow(default_landing):
    # two tubes 1.5 m apart hold 150 kN × 0.75 m = 112 kN m of yaw moment; the current's lateral force acts
    # 15.2 m aft of the fender: 7.4 kN, a 0.45 m/s beam current, is all they can hold with the push straight ahead
    scenario, db = default_landing
    out = {}
    for U in (0.4, 0.5):
        sc = scenario.replace({"sea": None, "simulation.duration": 200.0, "thrust.direction_deg": 0.0,
                               "current": {"speed": U, "relative_direction_deg": 90.0}})
        r = simulate(sc, db)
        out[U] = r
        print(f"{U} m/s, push straight ahead: normal forces {r.fn[-1, 0] / 1e3:.0f} / {r.fn[-1, 1] / 1e3:.0f} kN, "
              f"yaw {math.degrees(r.x[-1, 5]):.1f}°")
    assert (out[0.4].mode[out[0.4].t > 20] == 2).any() and out[0.4].fn[-1].max() > 125e3
    assert math.degrees(out[0.4].x[-1, 5]) < -3.0
    assert out[0.5].fn[-1].min() == 0.0 and math.degrees(out[0.5].x[-1, 5]) < -10.0


def test_the_trim_balances_the_yaw_moment_by_hand(default_landing):
    scenario, db = default_landing
    sc = scenario.replace({"current.speed": 1.0, "current.relative_direction_deg": 90.0})
    env = Setup.of(sc, db).environment
    F = env.current_force()
    xf = np.mean(np.asarray(sc.fender.points)[:, 0])
    xT = sc.thrust.position[0]
    s = -(F[5] - xf * F[1]) / (sc.thrust.force * (xT - xf))     # T (x_T − x_f) sin α = −M about the fender
    assert env.push_direction[1] == pytest.approx(s, rel=1e-12)
    assert math.degrees(math.asin(s)) == pytest.approx(-7.9, abs=0.05)
    assert "-7.9° off the bow's axis" in " ".join(env.lines(sc))


@pytest.mark.parametrize("changes", [
    {"current.speed": 1.0, "current.relative_direction_deg": 90.0},
    {"current.speed": 1.0, "current.relative_direction_deg": 180.0},
    {"current.speed": 0.8, "current.relative_direction_deg": 45.0, "wind.speed": 10.0,
     "wind.relative_direction_deg": 120.0, "wind.spectrum": "none"},
])
def test_the_landed_equilibrium_is_the_linear_solve(default_landing, changes):
    # time domain settled under steady loads (no waves) against the frequency domain's static solve
    scenario, db = default_landing
    sc = scenario.replace({"sea": None, "simulation.duration": 200.0, **changes})
    r = simulate(sc, db)
    land = LandingSetup.from_scenario(sc.replace({"sea": scenario.document["sea"]}), db)
    h = landed_response(db, land, np.array([0.5]), np.array([180.0]))
    N = land.normals
    for c in range(2):
        fn = float(N[c] @ h.J_static[c])
        ft_v = h.J_static[c, 2]
        ft_h = float(np.cross([0.0, 0.0, 1.0], N[c]) @ h.J_static[c])
        assert r.fn[-1, c] == pytest.approx(fn, rel=0.005)
        assert r.ft[-1, c, 0] == pytest.approx(ft_v, rel=0.01, abs=0.002 * abs(fn))
        assert r.ft[-1, c, 1] == pytest.approx(ft_h, rel=0.01, abs=0.002 * abs(fn))


def test_waves_only_is_todays_landing(default_landing):
    # no current, wind or drift: the environment is calm, the trial's external force is the waves' excitation
    # alone and its push the ramped constant, and the kernel run with the new inputs at their neutral values
    # (push along x, no controller, no current) gives the same trial bit for bit. (That the arrays equal the
    # code's before these loads existed is bench/fingerprint.py --check bench/fingerprints.json.)
    from boatland.trial.simulate import motion_arrays, thrust_series, wave_ramp

    scenario, db = default_landing
    sc = scenario.replace({"simulation.duration": 60.0})
    setup = Setup.of(sc, db)
    env = setup.environment
    assert env.calm and env.current is None and env.wind_load is None and env.push_direction.tolist() == [1, 0, 0]
    r = simulate(sc, db, setup=setup)
    n, dt = setup.n_steps, setup.dt
    x0, y0, psi = setup.start_pose
    F = setup.waves.excitation(db, seed=sc.simulation.seed, dt=dt, n_steps=n, x0=x0, y0=y0,
                               heading_deg=math.degrees(psi), ramp_time=0.0, pile=setup.pile)
    ramp = wave_ramp(sc, dt, n)
    k = int(np.flatnonzero(ramp != 1.0)[-1]) + 1
    F[:k] *= ramp[:k, None]
    assert np.array_equal(r.F_exc, F[::2])
    T = thrust_series(sc, dt, n)
    assert np.array_equal(r.thrust, T[::2])
    Bv, Bq = setup.additional_damping()
    out = motion_arrays(setup, setup.memory()).run(
        dt, n, F_ext=F, thrust=T, r_p=sc.thrust.position, push_direction=(1.0, 0.0, 0.0), skipper=np.zeros(9),
        current=None, Bv=np.diag(Bv), Bq=np.diag(Bq), contacts=setup.contacts(), limit_trans=50.0,
        limit_rot=math.radians(60.0))
    for key in ("x", "v", "fn", "ft", "mode", "slide"):
        assert np.array_equal(out[key], getattr(r, key)), key
