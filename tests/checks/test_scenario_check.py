"""The scenario edge: built-in names, reading the database, every check, the report for `boatland scenario check`."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from boatland.tomlspec import SpecError
from boatland.checks.files import (check_file, default_scenario_path, load, load_checked, resolve_database,
                                     schema_text)
from boatland.landing.setup import Setup

SCENARIOS = Path(__file__).resolve().parents[2] / "scenarios"
SHIPPED = sorted(SCENARIOS.glob("*.toml"))


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.name)
def test_every_shipped_scenario_checks_clean_against_its_database(path):
    report = check_file(path)
    assert report.ok, report.text
    assert report.exit_status == 0
    assert report.text.startswith(f"{path}: OK: {path.stem} (")


def test_default_scenario_is_the_quick_start_trial():
    assert default_scenario_path().resolve() == (SCENARIOS / "ctv_landing.toml").resolve()   # scenarios/ links to the package
    scenario, db, check = load_checked(default_scenario_path())
    assert db.name and check.ok
    assert Setup.of(scenario, db).dt == 0.05


def test_problems_give_exit_status_2_and_one_line_each(tmp_path):
    text = (SCENARIOS / "ctv_landing.toml").read_text()
    text = text.replace("Hs = 0.4 ", "Hs = -0.4 ").replace('database = "ctv27"', 'database = "ctv72"')
    path = tmp_path / "bad.toml"
    path.write_text(text)
    report = check_file(path)
    assert not report.ok and report.exit_status == 2
    keys = [k for k, _ in report.problems]
    assert sorted(keys) == ["sea.Hs", "vessel.database"]
    assert "did you mean 'ctv27'" in report.text
    assert report.text.splitlines()[0] == f"{path}: 2 problems:"


def test_database_checks_run_after_loading(tmp_path):
    text = (SCENARIOS / "ctv_landing.toml").read_text()
    text = text.replace("stiffness = 1.0e6", "stiffness = 1.0e9")
    path = tmp_path / "stiff.toml"
    path.write_text(text)
    report = check_file(path)
    assert [k for k, _ in report.problems] == ["simulation.dt"]
    assert "too large for the fender" in report.text
    with pytest.raises(SpecError, match="simulation.dt"):
        load_checked(path)


def test_missing_or_unreadable_database_file(tmp_path):
    text = (SCENARIOS / "ctv_free_decay.toml").read_text().replace('"ctv24"', '"vessels/mine.h5"')
    path = tmp_path / "s.toml"
    path.write_text(text)
    report = check_file(path)
    assert report.problems[0][0] == "vessel.database" and "file not found" in report.text
    (tmp_path / "vessels").mkdir()
    (tmp_path / "vessels" / "mine.h5").write_text("not hdf5")
    scenario = load(path)
    with pytest.raises(SpecError) as info:
        resolve_database(scenario)
    assert info.value.keys() == ["vessel.database"]


def test_syntax_error_report(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text("[simulation\nduration = 1\n")
    report = check_file(path)
    assert report.exit_status == 2 and "line 1, column" in report.text


def test_schema_text_is_json():
    schema = json.loads(schema_text())
    assert schema["title"] == "boatland scenario"
    assert set(schema["properties"]) >= {"simulation", "vessel", "landing", "fender", "thrust", "sea"}


def test_a_built_in_vessel_is_taken_by_its_name_whatever_is_in_the_working_directory(tmp_path, monkeypatch):
    """``database = "ctv27"`` is the built-in vessel: a file or folder of that name where the command runs
    does not take its place (a path in a scenario is resolved against the scenario's folder)."""
    from boatland.checks.files import check_file

    monkeypatch.chdir(tmp_path)
    (tmp_path / "ctv27").mkdir()
    (tmp_path / "ctv24").write_text("not a database")
    for name in ("ctv_landing.toml", "ctv24_landing.toml"):
        report = check_file(SCENARIOS / name)
        assert report.ok, report.text
