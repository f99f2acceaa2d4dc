"""Time domain against frequency domain in irregular waves: the standard deviations of the stuck fender's
contact forces in a JONSWAP sea equal the spectral integrals of the hinge-reaction transfer functions,
:math:`\\sigma^2 = \\int_0^\\infty |\\hat J(\\omega)|^2 S(\\omega)\\,d\\omega` (Grøtting 2015 eq. 3.29–3.32) —
the quantity the Wu screening is built on (boatland.freqdomain.screening).

Time domain: scenarios/ctv24_landing.toml (ctv24, the first default, two contacts, 80 kN, head seas, Tp 7 s) with Hs 0.1 m
and μ_s = μ_k = 2, k_v = 0 so the fender never slips (the linear stuck case), 1800 s, seeds 1 and 2;
statistics of the summed normal and vertical contact forces after t = 100 s (thrust ramp 20 s, wave ramp
2 Tp, state-space radiation memory). Frequency domain: the landed vessel with the same contacts
(:func:`boatland.freqdomain.screening.landed_response`: the fender's normal spring–damper and the rubber's
shear spring–damper, the thrust preload), summed over the contacts, in the same spectrum.

Tolerance: 3 standard errors of a standard deviation estimated from a Gaussian record of length T,
:math:`SE(\\hat\\sigma)/\\sigma = \\tfrac12\\sqrt{(2\\pi/T)\\int S_r^2\\,d\\omega}\\,/\\int S_r\\,d\\omega` with
:math:`S_r = |\\hat J|^2 S` the force's spectrum (3.9 % normal, 4.0 % vertical here: a 30-min record is ~120 independent
samples of this narrow-band force). Measured: σ_TD/σ_FD = 0.996 (normal) and 0.996 (vertical) for seed 1,
0.956 and 0.961 for seed 2 (≈ 1 SE); the static forces agree within 0.01 %.
"""

import warnings

import numpy as np
import pytest

from boatland.freqdomain import LandingSetup
from boatland.freqdomain.screening import default_omega, landed_response
from pathlib import Path

from boatland.checks.files import load, resolve_database
from boatland.trial.simulate import simulate

T_START = 100.0  # [s] transients left out
CTV24_LANDING = Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml"   # the figures' vessel


@pytest.fixture(scope="module")
def case():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        base = load(CTV24_LANDING)
        db = resolve_database(base)
    s = base.replace({"sea.Hs": 0.1, "fender.mu_s": 2.0, "fender.mu_k": 2.0, "fender.k_v": 0.0,
                      "simulation.duration": 1800.0, "landing.diffraction": False})  # open sea, as the FD side
    setup = LandingSetup.from_scenario(s, db)
    w = default_omega(db)
    h = landed_response(db, setup, w, [180.0])
    Sr = np.abs(h.contact_components()[:, 0].sum(axis=1)) ** 2 * s.sea.waves.parts[0].spectrum(w)[:, None]
    wt = np.gradient(w)
    sigma = np.sqrt(Sr.T @ wt)                                   # (normal, vertical, horizontal)
    rel_se = 0.5 * np.sqrt(2 * np.pi / (1800.0 - T_START) * ((Sr ** 2).T @ wt)) / (Sr.T @ wt)
    return db, s, sigma, rel_se, h.contact_components(static=True).sum(axis=0)


@pytest.mark.parametrize("seed", [1, 2])
def test_stuck_fender_force_sigma_is_the_spectral_integral(case, seed):
    db, s, sigma, rel_se, static = case
    r = simulate(s.replace({"simulation.seed": seed}), db)
    keep = r.t > T_START
    assert np.all(r.mode[keep] == r.mode[keep][0, 0]), "the fender must stay stuck (linear case)"
    fn, fv = r.fn[keep].sum(axis=1), r.ft[keep, :, 0].sum(axis=1)
    for name, x, k in (("normal", fn, 0), ("vertical", fv, 1)):
        ratio = x.std() / sigma[k]
        assert abs(ratio - 1) < 3 * rel_se[k], f"{name}: σ_TD/σ_FD = {ratio:.4f}, 3 SE = {3 * rel_se[k]:.4f}"
    np.testing.assert_allclose([fn.mean(), fv.mean()], static[:2], rtol=1e-3)
