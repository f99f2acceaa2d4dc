"""One meaning of duration: a campaign's ``access`` is the exposure to the full sea after the settling and the
wave ramp (``duration`` is its older name, accepted with a warning); a scenario's ``simulation.duration`` is the
whole trial; ``boatland run --access`` runs a trial whose access is that long."""

import json
import warnings
from pathlib import Path

import pytest

from boatland.checks.files import load
from boatland.cli import main
from boatland.errors import BoatlandWarning
from boatland.campaign.plan import load_campaign
from boatland.tomlspec import SpecError
from boatland.trial.simulate import exposure_start

REPO = Path(__file__).resolve().parents[2]
BASE = REPO / "scenarios" / "ctv24_landing.toml"


def _file(tmp_path, body):
    path = tmp_path / "c.toml"
    path.write_text(f'name = "c"\nscenario = "{BASE}"\nseeds = 2\n{body}\n[axes]\n"sea.Hs" = [0.3]\n', encoding="utf-8")
    return path


def test_access_is_the_exposure_after_settling_and_ramp(tmp_path):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        c = load_campaign(_file(tmp_path, "access = 100.0"), load_scenario=load)
    sc = c.scenario_for(c.trials()[0])
    assert c.access == 100.0 and sc.simulation.duration == exposure_start(sc) + 100.0 > 100.0


def test_duration_is_the_older_name_and_says_so(tmp_path):
    with pytest.warns(BoatlandWarning, match=r"duration = 100: the access .* write access = 100"):
        c = load_campaign(_file(tmp_path, "duration = 100.0"), load_scenario=load)
    assert c.access == 100.0


def test_both_names_are_refused(tmp_path):
    with pytest.raises(SpecError, match="give access only"):
        load_campaign(_file(tmp_path, "access = 100.0\nduration = 100.0"), load_scenario=load)


def test_every_shipped_campaign_says_access():
    for path in (REPO / "scenarios" / "campaigns").glob("*.toml"):
        text = path.read_text(encoding="utf-8")
        assert "\naccess = " in text and "\nduration = " not in text, path.name


def test_run_access(capsys):
    assert main(["run", "ctv24_landing", "--access", "30", "--no-log", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["inputs"]["duration"] == pytest.approx(exposure_start(load(BASE)) + 30.0)
    assert main(["run", "ctv24_landing", "--access", "30", "--no-log"]) == 0
    assert "34 s of settling and wave ramp, then 30 s of the full sea (the access)" in capsys.readouterr().err
