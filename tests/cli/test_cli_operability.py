"""``boatland operability`` as a planner runs it (subprocesses): a hindcast at three landings with windows, two
vessels side by side, the figure, JSON, a scatter, and bad input as one line with exit status 2."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HINDCAST = ROOT / "scenarios" / "example_hindcast.csv"
SCATTER = ROOT / "scenarios" / "scatter_north_sea.csv"


def run(*args):
    return subprocess.run([sys.executable, "-m", "boatland", "operability", *map(str, args)], capture_output=True,
                          text=True, timeout=600)


def one_line_error(r, *words):
    assert r.returncode == 2, (r.returncode, r.stderr)
    errors = [ln for ln in r.stderr.splitlines() if ln.startswith(("boatland: error:", "boatland operability: error:"))]
    assert len(errors) == 1 and "Traceback" not in r.stderr, r.stderr
    assert all(w in errors[0] for w in words), errors[0]


@pytest.mark.slow
def test_two_vessels_three_landings_a_hindcast(tmp_path):
    png = tmp_path / "op.png"
    r = run("ctv_landing", "ctv24_landing", HINDCAST, "--landing", "45", "--landing", "165", "--landing", "285",
            "--window", "6", "-o", png)
    assert r.returncode == 0, r.stderr
    for words in ("ctv_landing over", "ctv24_landing over", "landing 45°", "landing 285°", "best", "Jan", "Dec",
                  "a 6-h window", "P(window)", "wait 50 %", "judged as wind sea + swell", "scenario"):
        assert words in r.stdout, words
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 20_000
    assert "screening ctv_landing over" in r.stderr


@pytest.mark.slow
def test_json_matches_the_table():
    r = run("ctv_landing", HINDCAST, "--landing", "45", "--landing", "225", "--json")
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    res = out["results"][0]
    assert out["landings_deg"] == [45.0, 225.0] and res["sea_states"] == 2920 and res["hindcast"]
    a = res["availability"]
    assert set(a) == {"landing 45°", "landing 225°", "best"} and a["best"] >= max(a["landing 45°"], a["landing 225°"])
    assert res["window"]["hours"] == 4.0 and res["two_spectra_sea_states"] == 2920
    assert res["gain_of_choosing"] == pytest.approx(a["best"] - max(a["landing 45°"], a["landing 225°"]))
    r1 = run("ctv_landing", HINDCAST, "--landing", "45", "--landing", "225", "--one-spectrum", "--json")
    one = json.loads(r1.stdout)["results"][0]
    assert one["two_spectra_sea_states"] == 0 and one["availability"] != a


@pytest.mark.slow
def test_scatter_with_the_scenarios_landing():
    r = run("ctv_landing", SCATTER, "--json", "--mu", "0.8", "--thrust", "150e3")
    assert r.returncode == 0, r.stderr
    res = json.loads(r.stdout)["results"][0]
    assert res["landings_deg"] == [270.0] and not res["hindcast"] and "window" not in res   # heading 0° (East)
    assert 0 < res["availability"]["best"] < 1 and res["sea_states"] > 100 and res["mu"] == 0.8


@pytest.mark.slow
def test_hours_as_occurrences_warn_and_run(tmp_path):
    hours = tmp_path / "hours.csv"
    hours.write_text("Hs,Tp,direction_from_deg,occurrence\n0.1,7,0,300\n2.0,8,0,100\n")
    r = run("ctv_landing", hours)
    assert r.returncode == 0, r.stderr
    assert "normalised" in r.stderr and "75.0 %" in r.stdout


@pytest.mark.parametrize("args, words", [
    (["ctv_landing", "{bad}"], ("bad.csv", "line 3", "negative")),
    (["ctv_landing", "{hc}", "--landing", "400"], ("--landing",)),
    (["ctv_landing", "{hc}", "--landing", "90", "--landing", "90"], ("--landing", "twice")),
    (["ctv_landing", "{hc}", "--window", "0"], ("--window",)),
    (["ctv_landing", "ctv_landing", "{hc}"], ("given twice",)),
    (["ctv_landing", "{hc}", "-o", "{hc}"], ("-o", "is the input")),
    (["ctv_landing"], ("required", "WEATHER")),
])
def test_bad_input_is_one_line(tmp_path, args, words):
    bad = tmp_path / "bad.csv"
    bad.write_text("Hs,Tp,direction_from_deg,occurrence\n1,7,180,0.5\n1,8,180,-0.5\n")
    hc = tmp_path / "hc.csv"
    hc.write_text(HINDCAST.read_text(encoding="utf-8"))
    r = run(*[a.format(bad=bad, hc=hc) for a in args])
    if "required" in words:
        assert r.returncode == 2 and all(w in r.stderr for w in words) and "Traceback" not in r.stderr
        return
    one_line_error(r, *words)
    assert hc.read_text(encoding="utf-8") == HINDCAST.read_text(encoding="utf-8")


def _windy(tmp_path, rows=24):
    """The example's first ``rows`` sea states with the wind its wind sea grows from (the generator's model wind,
    docs/make_example_hindcast.py) — written as a planner's hindcast with wind columns."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_example_hindcast", ROOT / "docs" / "make_example_hindcast.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    lines = [ln for ln in mod.make(wind=True).splitlines() if not ln.startswith("#")]
    p = tmp_path / "windy.csv"
    p.write_text("\n".join(lines[:rows + 1]) + "\n")
    return p


@pytest.mark.slow
def test_each_sea_state_in_its_own_wind(tmp_path):
    """The wind columns are used (not named as unused), the source says so, progress is shown; a vessel whose
    database cannot take a wind (ctv24: no topsides to measure the areas on) is refused in one line before any
    vessel's work, naming the keys that would do."""
    w = _windy(tmp_path)
    r = run("ctv_landing", w, "--landing", "45", "--landing", "225", "--json")
    assert r.returncode == 0, r.stderr
    res = json.loads(r.stdout)["results"][0]
    assert "own wind" in res["limits"] and res["not_used"] == []
    assert "in each sea state's own wind" in r.stderr and "the flows' nodes, then the limits" in r.stderr
    r = run("ctv_landing", "ctv24_landing", w, "--landing", "45")
    one_line_error(r, "ctv24_landing.toml", "topsides", "wind.area_x")
    assert "the flows' nodes" not in r.stderr
