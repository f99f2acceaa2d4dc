"""The default landing (ctv27, scenarios/ctv_landing.toml) and its database, for the loads' tests."""

import warnings

import pytest


@pytest.fixture(scope="session")
def default_landing():
    """(scenario, database) of the shipped default trial."""
    from boatland.checks.files import load
    from boatland.hydro.read import load_database
    from boatland.resources import shipped_scenarios

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load(shipped_scenarios() / "ctv_landing.toml"), load_database("ctv27")
