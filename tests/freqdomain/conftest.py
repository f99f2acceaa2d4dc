"""The default landing (database and screening set-up), shared by the screening and operability tests."""

import warnings

import pytest

from boatland.freqdomain import LandingSetup
from boatland.scenario_check import default_scenario_path, load_checked


@pytest.fixture(scope="module")
def landing():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(default_scenario_path())
    return db, LandingSetup.from_scenario(scenario, db)
