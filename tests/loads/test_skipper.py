"""The skipper's throttle (boatland.loads.skipper): the discrete PI controller on the fender's normal force —
its delay, rate limit, range and anti-windup by hand, and on the landed vessel in the time domain."""

import numpy as np
import pytest

from boatland.loads.skipper import Skipper, skipper_measure, skipper_state, skipper_thrust
from boatland.trial.simulate import simulate


def drive(sk: Skipper, force, ramp, dt, measured):
    """The pushes the controller gives for the normal forces ``measured`` (one per step)."""
    par = sk.kernel(force, ramp, dt)
    n = len(measured)
    ff = np.full(2 * n + 1, force)
    buf, st = skipper_state(par)
    out = []
    for k in range(n):
        held, T = skipper_thrust(k, ff, par, buf, st)
        out.append(T)
        skipper_measure(k, np.array([measured[k] / 2, measured[k] / 2]), buf, st)
    return np.array(out), par


def test_delay_gain_and_rate_by_hand():
    dt = 0.1
    sk = Skipper(kind="hold_force", gain=0.5, integral_time=1e9, delay=0.7, rate=1e4, max_force=1e6)
    N = np.full(60, 150e3)
    N[20:] = 140e3                              # the bow lets go of 10 kN at step 20
    T, par = drive(sk, 150e3, 0.0, dt, N)
    d = int(par[2])
    assert d == 7
    assert np.all(T[:20 + d] == 150e3)          # nothing before the delay has passed
    assert T[20 + d] == pytest.approx(150e3 + 1e3)             # rate-limited: 10 kN/s × 0.1 s
    assert T[-1] == pytest.approx(150e3 + 0.5 * 10e3)         # then the proportional answer, 0.5 × 10 kN
    assert np.max(np.abs(np.diff(T))) <= 1e3 + 1e-6


def test_range_and_anti_windup():
    dt = 0.1
    sk = Skipper(kind="hold_force", gain=1.0, integral_time=2.0, delay=0.1, rate=1e9, max_force=160e3, min_force=0.0)
    N = np.full(400, 100e3)                     # a normal force far below the target: the push saturates
    T, _ = drive(sk, 150e3, 0.0, dt, np.r_[N, np.full(100, 150e3)])
    assert T.max() == 160e3 and np.all(T[10:400] == 160e3)
    # no wind-up: once the force is back at the target the push returns at once (not after unwinding the
    # 40 s of saturation an unguarded integral would have stored)
    assert np.all(T[-90:] == pytest.approx(150e3, rel=1e-12))


def test_constant_is_no_controller():
    assert not Skipper().active and np.all(Skipper().kernel(150e3, 20.0, 0.05) == 0.0)


def test_the_skipper_holds_the_fender_force_on_the_landed_vessel(default_landing):
    # no waves: the controller pushes until the fender carries the target, within the rate limit
    scenario, db = default_landing
    sc = scenario.replace({"sea": None, "simulation.duration": 120.0, "thrust.control.kind": "hold_force",
                                 "thrust.control.target": 170e3, "thrust.control.rate": 2e4,
                                 "thrust.control.integral_time": 5.0})
    r = simulate(sc, db)
    late = r.t > 90
    assert r.fn[late].sum(axis=1).mean() == pytest.approx(170e3, rel=0.01)
    assert r.thrust[r.t < 20].max() <= 150e3 + 1e-6            # the ramp as a constant push
    dT = np.diff(r.thrust[r.t >= 20]) / (r.t[1] - r.t[0])
    assert np.max(np.abs(dT)) <= 2e4 * (1 + 1e-9)
    assert r.thrust[-1] == pytest.approx(170e3, rel=0.02)
    # and the constant push leaves 150 kN on the fender
    r0 = simulate(scenario.replace({"sea": None, "simulation.duration": 120.0}), db)
    assert r0.fn[r0.t > 90].sum(axis=1).mean() == pytest.approx(150e3, rel=0.001)
