"""The landings the site tests judge: ctv24's (the Wigley CTV, scenarios/ctv24_landing.toml — the figures of the
scatter tests were measured on it) and ctv27's (scenarios/ctv_landing.toml, the default scenario)."""

import warnings
from pathlib import Path

import pytest

from boatland.checks.files import load_checked
from boatland.freqdomain import LandingSetup

ROOT = Path(__file__).resolve().parents[2]
CTV24_LANDING = ROOT / "scenarios" / "ctv24_landing.toml"
CTV27_LANDING = ROOT / "scenarios" / "ctv_landing.toml"
HINDCAST = ROOT / "scenarios" / "example_hindcast.csv"
SCATTER = ROOT / "scenarios" / "scatter_north_sea.csv"


def _landing(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(path)
    return db, LandingSetup.from_scenario(scenario, db)


@pytest.fixture(scope="module")
def landing():
    return _landing(CTV24_LANDING)


@pytest.fixture(scope="module")
def landing27():
    return _landing(CTV27_LANDING)
