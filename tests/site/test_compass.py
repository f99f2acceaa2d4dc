"""The site frame (boatland.site.compass): compass "from" directions and landing bearings give the relative
directions DESIGN.md §2 defines, and turning the whole site changes nothing — checked through the screening's
own limits, not only the formula."""

import numpy as np
import pytest

from boatland.freqdomain import screening_grid
from boatland.site import Weather, global_bearing, landing_bearing, operability, relative_direction, towards_global
from boatland.site import sea_limits


def test_a_wave_from_north_meets_the_bow_of_a_vessel_heading_north():
    # the landing at bearing 180° (the tower's south side): the vessel heads North (global heading 90°)
    assert float(landing_bearing(90.0)) == 180.0
    assert float(relative_direction(0.0, 180.0)) == 180.0            # from North: head sea
    # and the global frame agrees: waves from North travel towards −y (global 270°); the vessel heads +y (90°)
    assert float(towards_global(0.0)) == 270.0
    assert float((towards_global(0.0) - 90.0) % 360) == 180.0
    # the scenario's landing.bearing_deg of that landing is −y (270°) and the vessel heads the opposite way
    assert float(global_bearing(180.0)) == 270.0


@pytest.mark.parametrize("landing_deg, seas", [
    (180.0, {0: 180.0, 90: 90.0, 180: 0.0, 270: 270.0}),    # vessel heading North: head, from starboard, following, from port
    (0.0, {0: 0.0, 90: 270.0, 180: 180.0, 270: 90.0}),      # the landing facing North (vessel heading South)
])
def test_the_four_quarters(landing_deg, seas):
    for from_deg, beta in seas.items():
        assert float(relative_direction(from_deg, landing_deg)) == beta


def test_the_shipped_example_documents_the_quarters_as_computed(landing):
    """The example's header says: on a landing at 180°, waves from 0/90/180/270° are head / beam (from starboard)
    / following / beam (from port). The limits of those four seas are the screening's at β 180/90/0/270 — the
    directions the screening and the time domain define (180° head, 90° towards port)."""
    from tests.site.conftest import HINDCAST

    header = HINDCAST.read_text(encoding="utf-8").split("\ntime,")[0]
    assert "landing at bearing 180°" in header and "from 0° are head" in header and "from 180° following" in header
    db, s = landing
    w = Weather.scatter([0.2] * 4, [7.0] * 4, [0.0, 90.0, 180.0, 270.0], [0.25] * 4)
    lim = sea_limits(db, s, w, [180.0])
    assert lim.beta_deg[:, 0].tolist() == [180.0, 90.0, 0.0, 270.0]
    table = screening_grid(db, s, [7.0], [180.0, 90.0, 0.0, 270.0])
    np.testing.assert_allclose(lim.Hs_limit[:, 0], table.Hs[0], rtol=1e-9)


@pytest.mark.parametrize("angle", [37.3, 90.0, 211.0, -55.5])
def test_turning_the_site_changes_nothing(landing, angle):
    """A hindcast and its landings turned together by any angle: identical availability, month by month, and
    identical windows."""
    db, s = landing
    rng = np.random.default_rng(7)
    n = 400
    t = np.datetime64("2021-01-01T00:00") + np.arange(n).astype("timedelta64[h]") * 3
    w = Weather.series(t, rng.uniform(0.05, 0.5, n), rng.uniform(3.0, 12.0, n), rng.integers(0, 360, n),
                       parts={"wind_sea": (rng.uniform(0.0, 0.3, n), rng.uniform(3.0, 6.0, n), rng.integers(0, 360, n)),
                              "swell": (rng.uniform(0.0, 0.3, n), rng.uniform(8.0, 12.0, n), rng.integers(0, 360, n))})
    landings = np.array([20.0, 140.0, 260.0])
    a = operability(db, s, w, landings, window_hours=6.0)
    b = operability(db, s, w.rotated(angle), (landings + angle) % 360.0, window_hours=6.0)
    assert 0.05 < a.availability()[-1] < 0.95                      # a test that can fail: some of each
    np.testing.assert_array_equal(a.limits.beta_deg, b.limits.beta_deg)
    np.testing.assert_array_equal(a.workable, b.workable)
    np.testing.assert_array_equal(a.availability(), b.availability())
    np.testing.assert_array_equal(a.monthly(), b.monthly())
    assert [p.probability() for p in a.windows] == [p.probability() for p in b.windows]
