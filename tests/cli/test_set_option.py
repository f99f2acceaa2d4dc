"""``--set KEY=VALUE`` on the commands that take a scenario: the value as the file would give it, validated
the same way, refused in one line naming the setting."""

import argparse
import json

import numpy as np
import pytest

from boatland.cli import main
from boatland.cli.common import parse_setting


@pytest.mark.parametrize("text, key, value", [("sea.Hs=0.6", "sea.Hs", 0.6), ("sea.Tp=7", "sea.Tp", 7),
                                              ("radiation.method=convolution", "radiation.method", "convolution"),
                                              ('vessel.database="ctv24"', "vessel.database", "ctv24"),
                                              ("incidents.slip_distance=[0.1, 0.3]", "incidents.slip_distance", [0.1, 0.3]),
                                              ("fender.sideways=false", "fender.sideways", False)])
def test_a_setting_is_a_key_path_and_a_toml_value(text, key, value):
    assert parse_setting(text) == (key, value)


@pytest.mark.parametrize("text", ["sea.Hs", "Hs=0.6", "sea.Hs=", "=0.6", "sea..Hs=1"])
def test_a_malformed_setting_is_refused(text):
    with pytest.raises(argparse.ArgumentTypeError, match="expected KEY=VALUE"):
        parse_setting(text)


def test_run_takes_settings_and_the_specific_flag_wins(capsys):
    assert main(["run", "ctv24_landing", "--set", "sea.Hs=0.2", "--set", "sea.relative_direction_deg=150",
                 "--set", "simulation.duration=500", "--duration", "30", "--no-log", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["inputs"]["Hs"] == 0.2 and out["inputs"]["relative_direction_deg"] == 150.0
    assert out["inputs"]["duration"] == 30.0


def test_a_refused_value_names_the_setting(capsys):
    assert main(["run", "ctv24_landing", "--set", "sea.Hs=-1", "--no-log"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1] == "boatland: error: --set sea.Hs=-1: sea.Hs: must be > 0, got -1"
    assert main(["screen", "ctv24_landing", "--set", "fender.nosuch=1"]) == 2
    assert "--set fender.nosuch=1: fender.nosuch: unknown key" in capsys.readouterr().err


def test_screen_takes_settings(capsys):
    assert main(["screen", "ctv24_landing", "--json"]) == 0
    base = json.loads(capsys.readouterr().out)
    assert main(["screen", "ctv24_landing", "--set", "thrust.force=120e3", "--json"]) == 0
    more = json.loads(capsys.readouterr().out)
    assert base["thrust"] == 80e3 and more["thrust"] == 120e3
    # a harder push holds in higher seas (Grøtting 2015 §5.5: the limit grows with μ F_b) in every cell
    lo, hi = np.array(base["Hs_limit"], dtype=float), np.array(more["Hs_limit"], dtype=float)
    assert lo.shape == hi.shape and np.all(hi[np.isfinite(lo)] > lo[np.isfinite(lo)])


@pytest.mark.parametrize("setting, said", [
    ("seeds=0", "demo.toml: --set seeds: must be ≥ 1, got 0"),
    ("sneeds=2", "demo.toml: --set sneeds: unknown key (did you mean 'seeds'?)"),
    ("set.sea.Hs=-1", "demo.toml: --set set.sea.Hs: must be > 0, got -1"),
    ("axes.sea.Hs=[]", "demo.toml: --set axes.sea.Hs: must be a non-empty list of values"),
    ("seeds.x=1", "demo.toml: --set seeds.x: seeds is not a table"),
])
def test_a_campaign_setting_is_validated_as_the_file_and_named(setting, said, tmp_path, capsys):
    assert main(["campaign", "demo", "--set", setting, "-o", str(tmp_path / "d.h5")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("boatland: error: ") and err[0].endswith(said)
    assert not list(tmp_path.iterdir())


def test_a_campaign_setting_may_be_a_top_level_key():
    assert parse_setting("seeds=2", campaign=True) == ("seeds", 2)
    assert parse_setting("axes.sea.Hs=[0.5, 1.0]", campaign=True) == ("axes.sea.Hs", [0.5, 1.0])
    with pytest.raises(argparse.ArgumentTypeError, match="as in the campaign file, e.g. seeds=2"):
        parse_setting("seeds", campaign=True)
