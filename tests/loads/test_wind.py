"""Wind (boatland.loads.wind): the NPD profile and gust spectrum of DNV-RP-C205 §2.3.2.11 by hand, seeded gusts
that do not depend on the time step, and the mean wind force on the landed vessel by the drag formula."""

import math

import numpy as np
import pytest

from boatland.landing.setup import Setup
from boatland.loads.wind import GUST_RECORD, RHO_AIR, gust_series, mean_speed, npd_spectrum
from boatland.trial.simulate import simulate


def test_npd_profile_and_spectrum_by_hand():
    U0 = 10.0
    assert mean_speed(U0, 10.0) == U0
    C = 5.73e-2 * math.sqrt(1 + 0.148 * U0)
    assert mean_speed(U0, 2.0) == pytest.approx(U0 * (1 + C * math.log(0.2)))
    f = 0.01
    ft = 172 * f * 1.0 * 1.0
    assert npd_spectrum(f, U0, 10.0) == pytest.approx(320 / (1 + ft ** 0.468) ** (5 / (3 * 0.468)))


def test_gusts_are_seeded_and_the_same_for_any_step():
    a = gust_series(10.0, 2.0, 7, 0.05, 12000)
    b = gust_series(10.0, 2.0, 7, 0.02, 30000)
    assert np.array_equal(a, gust_series(10.0, 2.0, 7, 0.05, 12000))
    assert np.max(np.abs(a[::2] - b[::5])) < 1e-9
    assert not np.allclose(a, gust_series(10.0, 2.0, 8, 0.05, 12000))
    # the variance of an hour is the spectrum's up to 2 Hz (the synthesis' discrete sum)
    u = gust_series(10.0, 2.0, 1, 0.05, int(GUST_RECORD / 0.05))
    fk = np.arange(1, int(2.0 * GUST_RECORD) + 1) / GUST_RECORD
    assert u.var() == pytest.approx(np.sum(npd_spectrum(fk, 10.0, 2.0)) / GUST_RECORD, rel=0.02)


def test_mean_wind_force_on_the_landed_vessel_by_hand(default_landing):
    # a steady beam wind without gusts: the fender carries ½ ρ_a A_y c_y U(z_c)² sideways less the push's
    # side component (the skipper's trim balances the yaw moment), within 1 %
    scenario, db = default_landing
    sc = scenario.replace({"sea": None, "simulation.duration": 150.0, "wind.speed": 12.0,
                           "wind.relative_direction_deg": 90.0, "wind.spectrum": "none"})
    setup = Setup.of(sc, db)
    env = setup.environment
    load = env.wind_load
    U = mean_speed(12.0, load.centroid[2])
    Fy = 0.5 * RHO_AIR * load.area_y * 0.825 * U * U
    assert env.mean_wind()[1] == pytest.approx(Fy, rel=1e-9)
    r = simulate(sc, db)
    t_h = np.cross([0.0, 0.0, 1.0], setup.fender.normals_3d)          # each contact's horizontal tangent
    side = float(np.sum(r.ft[-1, :, 1] * t_h[:, 1]))   # the tubes' friction on the vessel, along y
    T = r.thrust[-1] * env.push_direction[1]
    assert -side == pytest.approx(Fy + T, rel=0.01)
    assert r.fn[-1, 0] == pytest.approx(r.fn[-1, 1], rel=0.01)   # trimmed: the tubes share the push


def test_a_gust_seed_changes_the_gusts_only(default_landing):
    """simulate(gust_seed=…): the gusts of another seed on the same sea (a rare-event sample's own gusts);
    the scenario's own seed given explicitly changes nothing, bit for bit, and is recorded."""
    scenario, db = default_landing
    sc = scenario.replace({"simulation.duration": 60.0, "wind.speed": 10.0, "wind.relative_direction_deg": 90.0})
    plain = simulate(sc, db)
    same = simulate(sc, db, gust_seed=sc.simulation.seed)
    other = simulate(sc, db, gust_seed=sc.simulation.seed + 1)
    assert np.array_equal(plain.x, same.x) and same.provenance["gust_seed"] == sc.simulation.seed
    assert "gust_seed" not in plain.provenance
    assert not np.allclose(plain.x[-1], other.x[-1])
    # the waves are the same: the sea's excitation does not depend on the gusts' seed
    calm = sc.replace({"wind": None})
    assert np.array_equal(simulate(calm, db, gust_seed=123).x, simulate(calm, db).x)
