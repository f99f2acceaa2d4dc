"""The command line: --json wherever a table is printed, exit statuses, flags that exclude each other,
refusals before any work, and the run's verdict output."""

import json
import re
import time
from pathlib import Path

import pytest

from boatland.cli import main

#: The first default landing (ctv24, 80 kN, Hs 1.5 m): it slips within 45 s, which these tests need.
CTV24_LANDING = str(Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml")

SCENARIO_CHECK_KEYS = {"file", "ok", "scenario", "summary", "inputs", "problems", "warnings", "notes"}


def test_no_command_is_a_usage_error(capsys):
    assert main([]) == 2
    err = capsys.readouterr().err
    assert "usage: boatland" in err and "no command given" in err
    assert main(["hydro"]) == 2 and main(["scenario"]) == 2


def test_log_and_no_log_exclude_each_other(capsys):
    assert main(["run", "--log", "x.mcap", "--no-log"]) == 2
    assert "not allowed with argument --log" in capsys.readouterr().err


def test_a_bad_rerun_target_fails_before_anything_runs(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["run", "--rerun", "bogus"]) == 2
    err = capsys.readouterr().err
    assert "--rerun bogus" in err and "running" not in err and list(tmp_path.iterdir()) == []


def test_output_in_a_missing_folder_is_refused_before_the_run(tmp_path, capsys):
    assert main(["run", "-o", str(tmp_path / "out" / "run.h5")]) == 2
    err = capsys.readouterr().err
    assert "the folder" in err and "does not exist" in err and "running" not in err


def test_scenario_check_json(repo_root, tmp_path, capsys):
    assert main(["scenario", "check", str(repo_root / "scenarios" / "ctv_landing.toml"), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out) == SCENARIO_CHECK_KEYS and out["ok"] and out["inputs"]["Hs"] == 0.4
    bad = tmp_path / "bad.toml"
    bad.write_text("[sea]\nkind = 'jonswap'\nHs = -1\nTp = 7\n")
    assert main(["scenario", "check", str(bad), "--json"]) == 2
    out = json.loads(capsys.readouterr().out)
    assert not out["ok"] and {"key": "sea.Hs", "message": "must be > 0, got -1"} in out["problems"]


def test_hydro_list_json(capsys):
    assert main(["hydro", "list", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert [d["name"] for d in out] == ["ctv27", "ctv24", "model2"] and all(d["file"].endswith(".h5") for d in out)
    assert "seed 00" not in json.dumps(out)


def test_screen_json_keeps_the_own_sea_probability(capsys):
    assert main(["screen", "--tp", "6", "8", "2", "--directions", "2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    own = out["own_sea"]
    assert own["parts"] == [{"kind": "jonswap", "Hs": 0.4, "Tp": 7.0, "relative_direction_deg": 180.0}]
    assert 0 <= own["p_access"] <= 1 and own["margins"]
    assert main(["screen", "--tp", "6", "8", "2", "--directions", "2"]) == 0
    assert f"incident probability {own['p_access']:.3g} per access" in capsys.readouterr().out


def test_run_prints_the_verdict_first_and_json_has_events(capsys, tmp_path):
    assert main(["run", CTV24_LANDING, "--duration", "45", "--no-log"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("SLIPPED at t = ") and "JONSWAP Hs 1.5 m, Tp 7 s" in out[0] and "push 80 kN" in out[0]
    noise = re.compile(r"\de-\d+ ?(kN|N|m|s|°)")                   # no 1.2e-05 kN, no 3e-15 m (odds may be 5e-3)
    assert not [ln for ln in out if noise.search(ln)]
    assert not [ln for ln in out if "contact 0:" in ln]           # a symmetric landing: "contacts 0+1"
    assert "settling events hidden: --events all" in "\n".join(out)
    assert main(["run", CTV24_LANDING, "--duration", "45", "--no-log", "--json", "--events", "all"]) == 0
    rep = json.loads(capsys.readouterr().out)
    assert rep["verdict"]["outcome"] == "slipped" and rep["inputs"]["thrust"] == 80e3
    assert rep["events"][0]["settling"] and rep["events"][0]["contacts"] == [0, 1]
    assert rep["events_shown"] == "all" and rep["events_hidden"] == 0


@pytest.mark.parametrize("argv", [["--json"], ["--events", "none"]])
def test_run_options_parse(argv):
    from boatland.cli import _parser

    args = _parser().parse_args(["run", *argv])
    assert args.events in ("waves", "none")


def test_compile_notice_only_when_the_kernels_are_not_cached(monkeypatch, capsys):
    from boatland.cli import common

    assert common.kernels_cached() in (True, False)
    cached = [False]
    monkeypatch.setattr(common, "kernels_cached", lambda: cached[0])
    ticker = common.compile_notice(every=0.05, poll=0.01)
    time.sleep(0.3)
    cached[0] = True                                   # numba has written its cache: the notice ends
    ticker.join(5.0)
    lines = capsys.readouterr().err.strip().splitlines()
    assert lines[0] == "compiling kernels (first run only, about a minute) …"
    assert any(ln.startswith("  … still compiling (") for ln in lines[1:-1]) and lines[-1].startswith("  compiled in ")
    assert not ticker.is_alive()
    assert common.compile_notice() is None and capsys.readouterr().err == ""


@pytest.mark.parametrize("command", [["run"], ["replay"], ["plot"], ["campaign"], ["report"], ["scenario", "check"],
                                     ["hydro", "build"], ["hydro", "import"], ["hydro", "info"], ["irf"], ["rao"],
                                     ["screen"], ["operability"], ["validate"]])
def test_help_prints_no_format_escapes(command, capsys):
    """argparse formats help strings (a "%" is written "%%" there) but not descriptions: neither shows a "%%"."""
    assert main([*command, "--help"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("usage: boatland") and "%%" not in out


def test_run_help_states_the_default_scenario(capsys):
    """``run --help`` describes the trial it runs without a file: the default scenario's vessel, push and sea."""
    from boatland.checks.files import default_scenario_path, load

    sc = load(default_scenario_path())
    assert main(["run", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    (part,) = sc.sea.waves.parts
    said = re.search(r"Without a file: scenarios/(\S+) \(the 27 m CTV (\S+) pushing ([\d.]+) kN in JONSWAP Hs ([\d.]+) m, "
                     r"Tp ([\d.]+) s, head seas\)", text)
    assert said, text
    assert said.group(1) == default_scenario_path().name and said.group(2) == sc.vessel.database
    assert float(said.group(3)) * 1e3 == sc.thrust.force
    assert float(said.group(4)) == part.Hs and float(said.group(5)) == part.Tp and part.kind == "jonswap"
    assert (part.direction_deg - sc.vessel.heading_deg) % 360 == 180.0          # head seas
