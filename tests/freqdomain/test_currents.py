"""The screening with a tidal current (boatland.freqdomain.currents, boatland.landing.environment): what the
statics say — a sideways current uses friction capacity, one along the vessel changes the normal force — in the
limiting Hs and the margins, and `boatland screen --current-sweep`."""

import json
import subprocess
import sys
import warnings

import numpy as np
import pytest

from boatland.freqdomain.currents import current_sweep
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import screening_grid, slip_transfer
from boatland.landing.setup import Setup


@pytest.fixture(scope="module")
def default_landing():
    from boatland.checks.files import load
    from boatland.hydro.read import load_database
    from boatland.resources import shipped_scenarios

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load(shipped_scenarios() / "ctv_landing.toml"), load_database("ctv27")


def limit(sc, db, beta):
    return float(screening_grid(db, LandingSetup.from_scenario(sc, db), [7.0], [beta]).Hs[0, 0])


def test_a_beam_current_lowers_the_limits(default_landing):
    # the skipper trims the push against the current's yaw moment (it takes 57 % of the side load at 1 m/s), the
    # fender carries the rest and the current's roll moment loads one tube's vertical friction more than the
    # other's; its drag damps the sway–yaw–roll response. On ctv27 at Tp 7 s (screening, Rice, 1.19e-3 per access):
    # head seas 0.374 → 0.299 m at 1 m/s and 0.180 m at 1.5 m/s; beam seas 0.155 → 0.154 m at 1 m/s (the damping
    # and the friction it uses nearly balance; tests/validation/test_loads_vs_monte_carlo.py for the time domain)
    # and 0.097 m at 1.5 m/s (measured 2026-12-03, the friction circle in the margins); without the trim 0.3 m/s
    # halves every limit (the tubes hold the yaw moment alone)
    sc, db = default_landing
    beam = {"current": {"speed": 1.5, "relative_direction_deg": 90.0}}
    for beta, speed, fall in ((180.0, 1.0, 0.15), (180.0, 1.5, 0.4), (90.0, 1.5, 0.25)):
        calm = limit(sc, db, beta)
        with_current = limit(sc.replace({"current": {"speed": speed, "relative_direction_deg": 90.0}}), db, beta)
        print(f"{beta:g}°, Tp 7 s: limiting Hs {calm:.3f} m without current, {with_current:.3f} m in {speed:g} m/s "
              "on the beam")
        assert with_current < (1 - fall) * calm
    untrimmed = sc.replace({"current": {"speed": 0.3, "relative_direction_deg": 90.0}, "thrust.direction_deg": 0.0})
    assert limit(untrimmed, db, 90.0) < 0.6 * limit(sc, db, 90.0)
    assert limit(sc.replace(beam), db, 90.0) > limit(untrimmed, db, 90.0)


def test_a_current_along_the_vessel_moves_the_normal_force_as_the_statics_say(default_landing):
    # from astern (towards 0°) it pushes the fender on by ½ ρ A_x c_x U², onto the bow (180°) it pulls it off by
    # as much; the head-sea margins' capacity (μ N) and the limit follow
    sc, db = default_landing
    out = {}
    for name, rel in (("astern", 0.0), ("bow", 180.0)):
        s = sc.replace({"current": {"speed": 1.5, "relative_direction_deg": rel}})
        env = Setup.of(s, db).environment
        c = env.current
        Fx = 0.5 * db.rho * c.area_x * c.coefficients[0] * 1.5 ** 2
        tr = slip_transfer(db, LandingSetup.from_scenario(s, db), beta_deg=[180.0])
        out[name] = (tr.N_static.sum(), tr.capacity[:-1].min(), Fx)
    base = slip_transfer(db, LandingSetup.from_scenario(sc, db), beta_deg=[180.0])
    N0 = base.N_static.sum()
    assert out["astern"][0] - N0 == pytest.approx(out["astern"][2], rel=0.02)
    assert N0 - out["bow"][0] == pytest.approx(out["bow"][2], rel=0.02)
    assert out["astern"][1] > base.capacity[:-1].min() > out["bow"][1]
    print(f"head seas: N {N0 / 1e3:.2f} kN; 1.5 m/s from astern {out['astern'][0] / 1e3:.2f} kN, onto the bow "
          f"{out['bow'][0] / 1e3:.2f} kN (½ρA_x c_x U² = {out['astern'][2]:.0f} N)")


def test_current_sweep_and_the_side_to_land_on(default_landing):
    sc, db = default_landing
    sw = current_sweep(db, sc, 7.0, speeds=(0.0, 1.0), directions_deg=(0.0, 90.0, 180.0, 270.0))
    assert np.all(sw.Hs[0] == sw.Hs[0, 0])                       # no current: one landing
    assert sw.Hs[1, 1] < sw.Hs[1, 0] and sw.Hs[1, 1] == pytest.approx(sw.Hs[1, 3], rel=1e-6)  # symmetric beams
    advice = sw.advice()
    assert len(advice) == 1 and "worst on the beam (90°) or 270° (either side)" in advice[0]


def test_screen_current_sweep_cli(tmp_path):
    out = tmp_path / "sweep.png"
    r = subprocess.run([sys.executable, "-m", "boatland", "screen", "--current-sweep", "7", "--speeds", "0", "0.5",
                        "--json", "-o", str(out)], capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    assert d["speeds"] == [0.0, 0.5] and len(d["current_relative_direction_deg"]) == 8 and d["advice"]
    assert out.stat().st_size > 10_000
    bad = subprocess.run([sys.executable, "-m", "boatland", "screen", "--speeds", "1"], capture_output=True,
                         text=True, timeout=120, cwd=tmp_path)
    assert bad.returncode == 2 and bad.stderr.strip().count("\n") == 0 and "--speeds: only with --current-sweep" in bad.stderr
