"""The logged sea (bow elevation, 3D patch) includes the monopile's scattered wave (issue 9)."""

import numpy as np
import pytest

from boatland.record.scene import sea_coefficients
from boatland.sea.pile import Pile
from boatland.waves.diffraction import cylinder_field
from boatland.waves.realisation import regular_components


@pytest.fixture
def wave():
    return regular_components(0.5, 7.0, np.radians(180.0), phase=0.3)


def test_open_sea_is_the_incident_wave(wave):
    x, y = np.array([-20.0, 5.0]), np.array([3.0, -7.0])
    c = sea_coefficients(wave, x, y, None)
    expected = wave.a * np.exp(1j * (wave.phi - wave.k * (x * np.cos(wave.theta) + y * np.sin(wave.theta))))
    np.testing.assert_allclose(c[:, 0], expected, rtol=1e-14)


def test_beside_the_pile_it_is_the_total_field_and_far_away_the_incident(wave):
    a, px, py = 3.25, 10.0, -4.0
    pile = Pile(a, (px, py), np.inf)
    # up-wave face of the pile (waves travel towards −x: the face at +x): the run-up of MacCamy–Fuchs
    x, y = np.array([px + a + 1e-9]), np.array([py])
    c = sea_coefficients(wave, x, y, pile)
    runup = np.abs(cylinder_field(np.array([a + 1e-9]), np.zeros(1), np.zeros(1), wave.omega, wave.theta, a,
                                  paired=True).eta).ravel()[0]
    assert abs(c[0, 0]) == pytest.approx(wave.a[0] * runup, rel=1e-9) and runup > 1.05
    far = sea_coefficients(wave, np.array([px]), np.array([py + 3000.0]), pile)
    open_sea = sea_coefficients(wave, np.array([px]), np.array([py + 3000.0]), None)
    assert abs(far[0, 0] - open_sea[0, 0]) < 0.05 * wave.a[0]       # scattered ~ 1/√(kr) far away
    inside = sea_coefficients(wave, np.array([px]), np.array([py]), pile)
    assert inside[0, 0] == 0
