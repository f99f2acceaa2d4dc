"""A scenario against its vessel's database (boatland.checks.physical): every problem and warning with its
key path, on a synthetic box vessel whose dimensions make the expected figures easy to check."""

import pytest

from boatland.checks.physical import check_against
from boatland.landing.setup import Setup
from boatland.scenario.scenario import ScenarioWarning
from boatland.tomlspec import SpecError

from box_vessel import make  # a CTV-like scenario on the box vessel (fixture box_db)


# ---------------------------------------------------------------------------------------- database checks
def test_clean_against_a_matching_database(box_db):
    check = check_against(Setup.of(make(), box_db))
    assert check.ok, check.problems
    assert any("fender contact" in n for n in check.notes)


def test_dt_too_large_for_the_fender(box_db):
    check = check_against(Setup.of(make({"fender.stiffness": 1e8}), box_db))
    found = dict(check.problems)
    assert "too large for the fender" in found["simulation.dt"]
    with pytest.raises(SpecError, match="simulation.dt"):
        check.raise_if_problems("t.toml")


def test_fender_not_at_the_bow_or_outside_the_beam(box_db):
    s = make({"fender.points": [[5.0, 0.75, 1.5], [5.0, -0.75, 1.5]]})
    found = dict(check_against(Setup.of(s, box_db)).problems)
    assert "not at the bow" in found["fender.points[0]"]
    s = make({"fender.points": [[12.3, 5.0, 1.5], [12.3, 3.5, 1.5]], "landing.strut_spacing": 1.5})
    problems = check_against(Setup.of(s, box_db)).problems
    assert ("fender.points[0]", "y = 5 m is outside the hull's beam (y = -4.5 … 4.5 m)") in problems
    s = make({"fender.points": [[16.0, 0.75, 1.5], [16.0, -0.75, 1.5]]})
    assert "ahead of the stem" in dict(check_against(Setup.of(s, box_db)).problems)["fender.points[0]"]


def test_hull_inside_the_monopile(box_db):
    s = make({"vessel.position": [-10.0, 0.0]}, remove=("fender", "thrust"))
    problems = check_against(Setup.of(s, box_db)).problems
    assert ("vessel.position", "the hull reaches 3.25 m into the monopile at t = 0") in problems
    assert any(k == "vessel.position" and "overlaps struts[0]" in m for k, m in problems)
    assert check_against(Setup.of(make({"vessel.position": [-17.0, 0.0]}, remove=("fender", "thrust")), box_db)).ok


def test_waves_above_the_database_band(box_db):
    s = make({"sea": {"kind": "regular", "H": 0.2, "T": 1.0, "direction_deg": 180.0}, "simulation.dt": 0.01})
    assert "above the database's highest frequency" in dict(check_against(Setup.of(s, box_db)).problems)["sea.T"]
    with pytest.warns(ScenarioWarning, match="breaking limit"):
        s = make({"sea.Tp": 2.0, "simulation.dt": 0.01})
    warns = dict(check_against(Setup.of(s, box_db)).warnings)
    assert "of the wave variance lies above" in warns["sea"]


def test_memory_longer_than_the_database_resolves(box_db):
    warns = dict(check_against(Setup.of(make({"radiation": {"memory": 60.0}}), box_db)).warnings)
    assert "π/Δω = 31.4 s" in warns["radiation.memory"]
