"""The Wigley CTV's landing (scenarios/ctv24_landing.toml, the first default: the screening and operability
tests' figures were measured on it), database and screening set-up."""

import warnings
from pathlib import Path

import pytest

from boatland.freqdomain import LandingSetup
from boatland.checks.files import load_checked

CTV24_LANDING = Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml"


@pytest.fixture(scope="module")
def landing():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(CTV24_LANDING)
    return db, LandingSetup.from_scenario(scenario, db)
