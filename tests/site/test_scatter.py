"""Operability over a scatter diagram (boatland.site with a scatter Weather): availability on the built-in CTV
grows with μ·F_b and changes little with water depth (Grøtting 2015 §4.1.1, §4.1.4, Tables 4.2 and 4.5); a
scatter and a hindcast that lays its occurrences end to end agree."""

from __future__ import annotations

import numpy as np
import pytest

from boatland.errors import BoatlandWarning
from boatland.sea.spectra import SpectrumPart
from boatland.site import Weather, operability, read_weather
from tests.site.conftest import SCATTER

HEADING0 = 270.0      # ctv24's landing (global bearing 180°, heading 0°) as a compass bearing


@pytest.fixture(scope="module")
def fine_scatter():
    """A smooth synthetic table with fine Hs bins (2 cm), so the availability is not stepped by the bins."""
    H, T, D = np.meshgrid(np.arange(0.02, 1.0, 0.02), [4.0, 5.0, 6.0, 7.0, 8.0, 10.0, 12.0], np.arange(0, 360, 45.0),
                          indexing="ij")
    occ = np.exp(-H / 0.3) * np.exp(-0.5 * ((T - 6.0) / 2.0) ** 2)
    return Weather.scatter(H.ravel(), T.ravel(), D.ravel(), occ.ravel() / occ.sum(), source="fine")


@pytest.mark.slow
def test_availability_grows_with_mu_times_thrust(landing, fine_scatter):
    """Grøtting 2015 Table 4.2: availability depends strongly on μ·F_b. Measured on ctv24's landing
    (each contact on its own, the compliant fender, the pile's scattered wave; all headings): 0.255 (48 kN),
    0.358 (64 kN), 0.559 (120 kN), 0.741 (200 kN)."""
    db, s = landing
    a = [operability(db, s, fine_scatter, [HEADING0], mu=mu, thrust=F).availability()[0]
         for mu, F in ((0.6, 80e3), (0.8, 80e3), (0.8, 150e3), (0.8, 250e3))]
    assert np.all(np.diff(a) > 0.05), a
    assert 0.2 < a[0] < 0.32 and a[-1] > 0.7


def test_availability_changes_little_with_water_depth(landing, fine_scatter):
    """Grøtting (2015) Table 4.5 (TMA: 0.370 / 0.358 / 0.350 at 15 / 30 / 60 m, 7.5 % apart). Here the depth
    enters through the TMA spectrum only (ctv24's coefficients are deep-water): measured 0.282 / 0.259 /
    0.255 / 0.255 at 15 / 30 / 60 m / deep — shallower water, slightly more availability, far less
    than the μ·F_b effect above."""
    db, s = landing
    tma = SpectrumPart(Hs=1.0, Tp=8.0, kind="tma")
    a = {h: operability(db, s, fine_scatter, [HEADING0], sea=tma, water_depth=h).availability()[0]
         for h in (15.0, 30.0, 60.0, np.inf)}
    assert a[15.0] >= a[30.0] >= a[60.0] >= a[np.inf] - 1e-12
    assert (a[15.0] - a[60.0]) / a[60.0] < 0.15
    assert abs(a[60.0] - a[np.inf]) < 0.01


def test_availability_is_the_workable_occurrence(landing):
    db, s = landing
    # from 270° (West) on the landing at 270°: following sea; from 0° (North): waves from port
    sc = Weather.scatter([0.05, 0.05, 3.0], [7.0, 7.0, 7.0], [270.0, 0.0, 270.0], [0.5, 0.3, 0.2])
    a = operability(db, s, sc, [HEADING0])
    assert a.workable[:, 0].tolist() == [True, True, False] and a.availability()[0] == pytest.approx(0.8)
    assert a.limits.beta_deg[:, 0].tolist() == [0.0, 270.0, 0.0]


def test_scatter_and_hindcast_agree_when_the_occurrences_are_laid_end_to_end(landing):
    """A scatter with integer occurrences (hours) and the hindcast that repeats each sea state for its hours:
    the same sea states workable, the same availability (to round-off of the sums)."""
    db, s = landing
    rng = np.random.default_rng(11)
    m = 60
    H, T, D = rng.uniform(0.05, 0.6, m), np.round(rng.uniform(3.0, 12.0, m), 1), rng.integers(0, 360, m)
    hours = rng.integers(1, 30, m)
    with pytest.warns(BoatlandWarning, match="normalised"):
        sc = Weather.scatter(H, T, D, hours)
    rows = np.repeat(np.arange(m), hours)
    t = np.datetime64("2021-03-01T00:00") + np.arange(rows.size).astype("timedelta64[h]")
    series = Weather.series(t, H[rows], T[rows], D[rows])
    L = [30.0, 150.0, 270.0]
    a, b = operability(db, s, sc, L), operability(db, s, series, L)
    assert 0.1 < a.availability()[-1] < 0.9
    np.testing.assert_array_equal(a.workable[rows], b.workable)
    np.testing.assert_allclose(a.availability(), b.availability(), rtol=1e-12, atol=0)


def test_shipped_scatter_reads_and_sums_to_one():
    sc = read_weather(SCATTER)
    assert sc.n > 100 and abs(sc.weight.sum() - 1) < 1e-12 and sc.time is None
    raw = np.loadtxt(SCATTER, delimiter=",", comments="#", skiprows=8)
    np.testing.assert_array_equal(sc.from_deg, raw[:, 2] % 360)     # compass "from", as read
