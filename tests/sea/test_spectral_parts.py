"""Spectral parts own their spectrum through their shape (boatland.sea.spectra): the JONSWAP family as
before, and the Gaussian swell added as one shape, one density and one scenario key."""

import math

import numpy as np
import pytest

from boatland.sea.spectra import SHAPES, SpectrumPart
from boatland.sea.states import SeaState
from boatland.tomlspec import SpecError


@pytest.mark.parametrize("kind", sorted(SHAPES))
def test_every_shape_has_its_variance_in_its_band_and_its_bins(kind):
    extra = {"sigma_g": 0.05} if kind == "gaussian" else {}
    p = SpectrumPart(Hs=1.2, Tp=9.0, kind=kind, **extra)
    lo, hi = p.band(0.002)
    assert 0 < lo < p.omega_p < hi
    w = np.linspace(1e-4, 40 * p.omega_p, 400001)
    m0 = np.trapezoid(p.spectrum(w), w)
    assert 4 * math.sqrt(m0) == pytest.approx(1.2, rel=1e-6) and p.m0() == pytest.approx(m0, rel=1e-6)
    edges = np.linspace(lo, hi, 301)
    assert p.bin_variance(edges).sum() == pytest.approx(m0 * (1 - 0.002), rel=2e-3)   # the band's share
    assert SHAPES[kind].label and SHAPES[kind].kind == kind


def test_a_gaussian_swell_is_a_narrow_peak_and_needs_its_width():
    p = SpectrumPart(Hs=1.0, Tp=12.0, kind="gaussian", sigma_g=0.04)
    w = np.array([p.omega_p - 0.04, p.omega_p, p.omega_p + 0.04])
    S = p.spectrum(w)
    assert S[0] == pytest.approx(S[2]) and S[0] / S[1] == pytest.approx(math.exp(-0.5))
    with pytest.raises(SpecError, match="sigma_g: missing"):
        SpectrumPart(Hs=1.0, Tp=12.0, kind="gaussian")
    with pytest.raises(SpecError, match="sigma_g: is the width of a Gaussian swell"):
        SpectrumPart(Hs=1.0, Tp=12.0, kind="jonswap", sigma_g=0.04)


def test_a_wind_sea_with_a_gaussian_swell_realises_both():
    sea = SeaState(parts=(SpectrumPart(Hs=1.0, Tp=6.0), SpectrumPart(Hs=0.8, Tp=13.0, kind="gaussian", sigma_g=0.03,
                                                                      direction_deg=40.0)))
    assert sea.hm0() == pytest.approx(math.hypot(1.0, 0.8), rel=1e-9)
    c = sea.realise(seed=3, duration=600.0)
    swell = np.isclose(c.theta, math.radians(40.0))
    assert 4 * math.sqrt(0.5 * np.sum(c.a[swell] ** 2)) == pytest.approx(0.8, rel=2e-3)
    assert np.all(np.abs(c.omega[swell] - 2 * math.pi / 13.0) < 4 * 0.03)


def test_a_scenario_with_a_gaussian_swell_runs_and_is_screened():
    """The new shape reaches the scenario file, the trial, the screening and the labels without touching them."""
    from boatland.checks.files import default_scenario_path, load_checked
    from boatland.freqdomain.landing import LandingSetup
    from boatland.freqdomain.screening import sea_response
    from boatland.trial.simulate import simulate

    sc, db, _ = load_checked(default_scenario_path())
    sc = sc.replace({"sea": {"kind": "gaussian", "Hs": 0.3, "Tp": 11.0, "sigma_g": 0.04, "relative_direction_deg": 180.0},
                     "simulation.duration": 40.0})
    assert sc.sea.waves.parts[0].kind == "gaussian"
    r = simulate(sc, db)
    assert r.completed and "Gaussian swell" in r.inputs["sea"]
    resp = sea_response(db, LandingSetup.from_scenario(sc, db), sc.sea.waves.parts, access_duration=1800.0)
    assert 0.0 <= resp.p_access <= 1.0
