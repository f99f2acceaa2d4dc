"""Shipped scenario files and optional dependencies (boatland.resources)."""

from __future__ import annotations

from pathlib import Path

import pytest

import boatland
from boatland.errors import BoatlandInputError
from boatland.resources import require, shipped_scenarios


def test_the_scenarios_ship_inside_the_package():
    """The default trial, the vessel files and the campaigns live in the package (what a wheel installs);
    the checkout's scenarios/ is the same folder."""
    folder = shipped_scenarios()
    assert folder == Path(boatland.__file__).parent / "scenarios"
    assert (folder / "ctv_landing.toml").is_file() and (folder / "vessels" / "ctv24.toml").is_file()
    assert (folder / "campaigns" / "demo.toml").is_file()
    checkout = Path(boatland.__file__).resolve().parents[1] / "scenarios"
    assert checkout.resolve() == folder.resolve()


def test_a_missing_optional_dependency_names_the_extra():
    with pytest.raises(BoatlandInputError, match=r"^boatland hydro build needs no_such_module_xyz, an optional "
                                                 r"dependency: pip install 'boatland\[all\]'$"):
        require("no_such_module_xyz", "boatland hydro build")
    with pytest.raises(BoatlandInputError, match=r"pip install 'boatland\[xarray\]'"):
        import sys

        saved = sys.modules.get("xarray")
        sys.modules["xarray"] = None          # as if not installed: import raises ImportError
        try:
            require("xarray", "Result.to_xarray")
        finally:
            if saved is None:
                del sys.modules["xarray"]
            else:
                sys.modules["xarray"] = saved


@pytest.mark.parametrize("path", sorted((shipped_scenarios() / "campaigns").glob("*.toml")), ids=lambda p: p.stem)
def test_every_shipped_campaign_loads_and_checks(path):
    """Each shipped campaign file is valid and every case passes the checks `boatland run` makes."""
    from boatland.campaign.plan import load_campaign
    from boatland.campaign.prepare import check_cases
    from boatland.checks.files import load, resolve_database

    campaign = load_campaign(path, load_scenario=load)
    assert campaign.n_trials > 0 or campaign.method == "isee"
    check_cases(campaign, resolve_database)
