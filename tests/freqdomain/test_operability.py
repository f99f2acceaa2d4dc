"""Operability over a scatter table (boatland.freqdomain.operability): availability on the built-in CTV
grows with μ·F_b and changes little with water depth (Grøtting 2015 §4.1.1, §4.1.4, Tables 4.2 and 4.5);
the CSV reader's errors and normalisation."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from boatland.errors import BoatlandInputError, BoatlandWarning
from boatland.freqdomain import ScatterTable, availability, read_scatter
from boatland.sea.spectra import SpectrumPart

SHIPPED = Path(__file__).resolve().parents[2] / "scenarios" / "scatter_north_sea.csv"


@pytest.fixture(scope="module")
def fine_scatter():
    """A smooth synthetic table with fine Hs bins (2 cm), so the availability is not stepped by the bins."""
    H, T, D = np.meshgrid(np.arange(0.02, 1.0, 0.02), [4.0, 5.0, 6.0, 7.0, 8.0, 10.0, 12.0], np.arange(0, 360, 45.0),
                          indexing="ij")
    occ = np.exp(-H / 0.3) * np.exp(-0.5 * ((T - 6.0) / 2.0) ** 2)
    return ScatterTable.from_arrays(H.ravel(), T.ravel(), D.ravel(), occ.ravel() / occ.sum(), source="fine")


@pytest.mark.slow
def test_availability_grows_with_mu_times_thrust(landing, fine_scatter):
    """Grøtting 2015 Table 4.2: availability depends strongly on μ·F_b. Measured on ctv24's landing
    (each contact on its own, the compliant fender, the pile's scattered wave; all headings): 0.255 (48 kN),
    0.358 (64 kN), 0.559 (120 kN), 0.741 (200 kN)."""
    db, s = landing
    a = [availability(db, s, fine_scatter, mu=mu, thrust=F).availability
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
    a = {h: availability(db, s, fine_scatter, sea=tma, water_depth=h).availability for h in (15.0, 30.0, 60.0, np.inf)}
    assert a[15.0] >= a[30.0] >= a[60.0] >= a[np.inf] - 1e-12
    assert (a[15.0] - a[60.0]) / a[60.0] < 0.15
    assert abs(a[60.0] - a[np.inf]) < 0.01


def test_availability_is_the_workable_occurrence(landing):
    db, s = landing
    sc = ScatterTable.from_arrays([0.05, 0.05, 3.0], [7.0, 7.0, 7.0], [180.0, 90.0, 180.0], [0.5, 0.3, 0.2])
    a = availability(db, s, sc)
    assert list(a.workable) == [True, True, False] and a.availability == pytest.approx(0.8)
    assert np.allclose(a.beta_deg, [180.0, 90.0, 180.0])  # heading 0: relative = global
    assert a.downtime == pytest.approx(0.2)


def test_shipped_scatter_reads_and_sums_to_one():
    sc = read_scatter(SHIPPED)
    assert sc.Hs.size > 100 and abs(sc.occurrence.sum() - 1) < 1e-12
    raw = np.loadtxt(SHIPPED, delimiter=",", comments="#", skiprows=8)
    np.testing.assert_allclose(sc.direction_deg, (raw[:, 2] + 180.0) % 360)  # from → towards


def write(tmp_path, text, name="s.csv"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_negative_occurrence_is_an_error_naming_the_line(tmp_path):
    p = write(tmp_path, "# c\nHs,Tp,direction_deg,occurrence\n1,7,180,0.6\n1.5,8,180,-0.1\n")
    with pytest.raises(BoatlandInputError, match=r"s\.csv: line 4: occurrence = -0\.1 is negative"):
        read_scatter(p)


def test_sum_far_from_one_is_normalised_with_a_warning(tmp_path):
    p = write(tmp_path, "Hs,Tp,direction_deg,occurrence\n1,7,180,300\n1.5,8,180,100\n")
    with pytest.warns(BoatlandWarning, match="sum to 400"):
        sc = read_scatter(p)
    np.testing.assert_allclose(sc.occurrence, [0.75, 0.25])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_scatter(write(tmp_path, "Hs,Tp,direction_deg,occurrence\n1,7,180,0.7\n1.5,8,180,0.3001\n", "ok.csv"))


@pytest.mark.parametrize("text, match", [
    ("Hs,Tp,occurrence\n1,7,1\n", "no direction_deg"),
    ("Hs,direction_deg,occurrence\n1,7,1\n", "missing column.*Tp"),
    ("Hs,Tp,direction_deg,occurrence\n1,x,180,1\n", "line 2: Tp = 'x' is not a number"),
    ("Hs,Tp,direction_deg,occurrence\n1,7,180\n", "line 2: 3 fields for 4 columns"),
    ("Hs,Tp,direction_deg,occurrence\n0,7,180,1\n", "line 2: Hs = 0 must be > 0"),
    ("Hs,Tp,direction_deg,occurrence\n1,7,180,0\n", "no sea states with a positive occurrence"),
    ("# only a comment\n", "empty scatter table"),
])
def test_bad_scatter_tables(tmp_path, text, match):
    with pytest.raises(BoatlandInputError, match=match):
        read_scatter(write(tmp_path, text))


def test_missing_file(tmp_path):
    with pytest.raises(BoatlandInputError, match="no such file \\(the scatter table\\)"):
        read_scatter(tmp_path / "nope.csv")
