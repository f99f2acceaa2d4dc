"""The Wigley CTV's landing (scenarios/ctv24_landing.toml, the first default: the trial tests' figures were
measured on it) and its database, shared by the trial tests."""

from pathlib import Path

import pytest

from boatland.checks.files import load_checked

CTV24_LANDING = Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml"


@pytest.fixture(scope="module")
def landing():
    scenario, db, _ = load_checked(CTV24_LANDING)
    return scenario, db
