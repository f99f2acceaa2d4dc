"""A landed CTV rolls on its rubber fender: the frequency domain's roll of the vessel held by the fender's
normal and shear springs equals the time domain's in a beam sea.

Two rigidly stuck contacts 1.5 m apart would lock roll (σ_roll = 0 in both domains, the roll moment
taken by opposite vertical stick forces); Ferreira González (2023, §5.2.3) saw the tank model roll while
its soft fender stuck, and Grøtting (2015, §3.2.2) models the fender's shear stiffness (3000 kN/m, after
Wu 2014). The Wigley CTV on its landing (scenarios/ctv24_landing.toml, the first default, on which the figures
below were measured) in a JONSWAP sea Hs 0.04 m, Tp 7 s, beam on
(90°): stuck throughout, so the time domain is the linear system of the frequency domain.

Time domain: four wave seeds × 1800 s of full sea (after the settling and the waves' start-up ramp),
σ of roll, of each contact's vertical force and of heave pooled over the four records — the sampling
error of one 1800 s record is a few per cent (measured: ratios 0.98–1.02 between seeds). Frequency domain:
:func:`boatland.freqdomain.screening.landed_response` with the same contacts, pile diffraction and
spectrum, σ² = ∫|H|²S dω. Measured σ_TD/σ_FD (2026-12-03, the rebuilt ctv24): roll 1.001 (σ_roll 0.052°),
vertical forces 1.001 / 1.000, heave 0.997.

Grøtting, H. (2015), MSc thesis, NTNU; Ferreira González, D. (2023), Dr.-Ing. dissertation, TU Hamburg.
"""

import numpy as np
import pytest

from boatland.campaign.plan import trial_seed
from boatland.contact.fender import STICK
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import landed_response
from pathlib import Path

from boatland.checks.files import load_checked
from boatland.landing.setup import Setup
from boatland.trial.simulate import exposure_start, simulate

HS, TP, BETA, ACCESS, SEEDS = 0.04, 7.0, 90.0, 1800.0, 4
CTV24_LANDING = Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml"   # the figures' vessel


@pytest.fixture(scope="module")
def beam():
    sc, db, _ = load_checked(CTV24_LANDING)
    s = sc.replace({"sea.Hs": HS, "sea.Tp": TP, "sea.relative_direction_deg": BETA})
    return s.replace({"simulation.duration": exposure_start(s) + ACCESS}), db


@pytest.mark.slow
def test_landed_roll_is_not_locked_and_matches_the_time_domain(beam):
    s, db = beam
    memory = Setup.of(s, db).memory()
    sums = np.zeros(4)
    for k in range(SEEDS):
        r = simulate(s.replace({"simulation.seed": trial_seed(13, k)}), db, memory=memory)
        full = r.t >= r.exposure_from
        assert np.all(r.mode[full] == STICK)                  # the linear case: stuck throughout
        y = np.column_stack([r.x[full, 3], r.ft[full, 0, 0], r.ft[full, 1, 0], r.x[full, 2]])
        sums += ((y - y.mean(axis=0)) ** 2).mean(axis=0)
    td = np.sqrt(sums / SEEDS)
    setup = LandingSetup.from_scenario(s, db)
    w = np.linspace(0.05, db.omega[-1], 1200)
    resp = landed_response(db, setup, w, [BETA])
    S = s.sea.waves.parts[0].spectrum(w)
    sigma = lambda H: np.sqrt(np.trapezoid(np.abs(H) ** 2 * S, w))  # noqa: E731
    fd = np.array([sigma(resp.x[:, 0, 3]), sigma(resp.J[:, 0, 0, 2]), sigma(resp.J[:, 0, 1, 2]),
                   sigma(resp.x[:, 0, 2])])
    assert fd[0] > np.radians(0.01)                           # roll is not locked: σ_roll 0.052° here
    np.testing.assert_allclose(td, fd, rtol=0.05)
