"""The monopile's scattered wave in the excitation series (issue 9 wiring): ``landing.diffraction``
adds exactly X^s(ω, θ) a e^{iφ} to each component's force, on by default when the hull mesh exists."""

import math

import numpy as np
import pytest

from boatland.freqdomain.harmonic import first_harmonic
from boatland.sea.pile import pile_scattered_components
from boatland.checks.files import default_scenario_path, load_checked
from boatland.checks.physical import check_against
from boatland.landing.setup import Setup


@pytest.fixture(scope="module")
def regular():
    sc, db, _ = load_checked(default_scenario_path())
    sc = sc.replace({"sea": {"kind": "regular", "H": 0.2, "T": 6.0, "relative_direction_deg": 135.0},
                     "simulation.duration": 120.0})
    return sc, db


def test_diffraction_is_on_by_default_with_a_hull_mesh_and_can_be_switched_off(regular):
    sc, db = regular
    assert db.mesh is not None and Setup.of(sc, db).pile == (3.25, (0.0, 0.0), math.inf)
    assert Setup.of(sc.replace({"landing.diffraction": False}), db).pile is None
    check = check_against(Setup.of(sc.replace({"landing.diffraction": True}), db.replace(mesh=None)))
    assert any(k == "landing.diffraction" and "no hull mesh" in m for k, m in check.problems)


def test_the_added_force_is_the_scattered_wave_force_of_the_component(regular):
    sc, db = regular
    x0, y0, psi = sc.start_pose()
    dt, n = 0.05, 2400
    waves = Setup.of(sc, db).waves
    kw = dict(seed=1, dt=dt, n_steps=n, x0=x0, y0=y0, heading_deg=float(np.degrees(psi)), ramp_time=0.0)
    F0 = waves.excitation(db, **kw)
    F1 = waves.excitation(db, pile=Setup.of(sc, db).pile, **kw)
    comp = waves.realise(1, n * dt)
    w, th, a, phi, k = comp.omega[0], comp.theta[0], comp.a[0], comp.phi[0], comp.k[0]
    Xs = pile_scattered_components(db, (x0, y0), np.degrees(psi), 3.25, [w], [th])[:, 0]
    expected = Xs * a * np.exp(1j * (phi - k * (x0 * np.cos(th) + y0 * np.sin(th))))
    t = np.arange(2 * n + 1) * dt / 2
    for d in (0, 1, 2, 4):   # 135°: surge, sway, heave, pitch all feel the pile
        got = first_harmonic(t, F1[:, d] - F0[:, d], w, periods=10)
        assert abs(got - expected[d]) <= 2e-3 * abs(expected[d]), (d, got, expected[d])
    assert np.abs(expected[[0, 2, 4]]).min() > 0.02 * np.abs(F0[:, [0, 2, 4]]).max(axis=0).min()
