"""Shared fixtures. Reference data comes from ../shared/refdata (public data; see its notes/refdata.md)."""

from __future__ import annotations

from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
REFDATA = REPO.parent / "shared" / "refdata"


@pytest.fixture(scope="session")
def refdata() -> Path:
    """Folder of the public reference data; skips the test with a reason when it is not there."""
    if not REFDATA.is_dir():
        pytest.skip(f"reference data not found at {REFDATA} (expected ../shared/refdata beside the repo)")
    return REFDATA


@pytest.fixture(scope="session")
def repo_root() -> Path:
    """The source checkout (scenario files live in its ``scenarios/``)."""
    return REPO
