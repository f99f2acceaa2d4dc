"""The default landing scenario and its database, shared by the trial tests."""

import pytest

from boatland.scenario_check import default_scenario_path, load_checked


@pytest.fixture(scope="module")
def landing():
    scenario, db, _ = load_checked(default_scenario_path())
    return scenario, db
