"""Shipped scenarios and campaigns by name wherever the command line takes their file (``boatland run
ctv24_landing``, ``boatland campaign demo``), as in Python (``boatland.simulate("ctv_landing")``)."""

import json
from pathlib import Path

import pytest

from boatland.cli import main
from boatland.cli.common import shipped_or_path
from boatland.resources import shipped_names

SCENARIOS = Path(__file__).resolve().parents[2] / "scenarios"


@pytest.mark.parametrize("kind, name, file", [("scenario", "ctv24_landing", SCENARIOS / "ctv24_landing.toml"),
                                              ("scenario", "ctv_landing.toml", SCENARIOS / "ctv_landing.toml"),
                                              ("campaign", "demo", SCENARIOS / "campaigns" / "demo.toml"),
                                              ("campaign", "isee_rare", SCENARIOS / "campaigns" / "isee_rare.toml")])
def test_a_shipped_name_is_its_file(kind, name, file):
    assert shipped_or_path(kind)(name).resolve() == file.resolve()
    assert file.stem in shipped_names(kind)


def test_a_path_wins_over_a_shipped_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "demo").write_text("", encoding="utf-8")
    assert shipped_or_path("campaign")("demo") == Path("demo")
    assert shipped_or_path("scenario")("missing.toml") == Path("missing.toml")   # its loader says it is missing


def test_scenario_check_by_name(capsys):
    assert main(["scenario", "check", "ctv24_landing", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["ok"] and Path(out["file"]).name == "ctv24_landing.toml"


def test_an_unknown_name_lists_the_shipped_ones(capsys):
    assert main(["run", "no_such_landing"]) == 2
    err = capsys.readouterr().err
    assert "no_such_landing: no such file, and not a shipped scenario" in err and "ctv24_landing" in err
    assert main(["campaign", "no_such_campaign"]) == 2
    err = capsys.readouterr().err
    assert "not a shipped campaign" in err and "demo" in err and "Traceback" not in err
