"""``boatland rao`` and ``boatland screen`` as a user runs them (subprocesses):
output, figures, and bad input as one line with exit status 2."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCENARIO = ROOT / "scenarios" / "ctv_landing.toml"


def run(*args):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          timeout=300)


def one_line_error(r, *words):
    assert r.returncode == 2, (r.returncode, r.stderr)
    errors = [ln for ln in r.stderr.splitlines() if ln.startswith("boatland: error:")]
    assert len(errors) == 1 and "Traceback" not in r.stderr, r.stderr
    assert all(w in errors[0] for w in words), errors[0]


def test_help_lists_the_frequency_domain_commands():
    r = run("--help")
    assert r.returncode == 0 and all(c in r.stdout for c in ("rao", "screen", "operability"))


@pytest.mark.slow
def test_rao_table_and_figure(tmp_path):
    png = tmp_path / "rao.png"
    r = run("rao", SCENARIO, "--periods", "5", "20", "-o", png)
    assert r.returncode == 0, r.stderr
    assert "hinged" in r.stdout and png.stat().st_size > 10_000


def test_rao_json_long_waves():
    r = run("rao", "--periods", "30", "--json", "--direction", "0")  # default scenario, long waves
    rows = json.loads(r.stdout)["rows"]
    assert abs(rows[0]["free_heave"] - 1) < 0.01  # heave → 1 for long waves


@pytest.mark.slow
def test_screen_table_and_polar_figure(tmp_path):
    png = tmp_path / "screen.png"
    r = run("screen", SCENARIO, "--tp", "5", "9", "3", "--directions", "4", "--accept", "conservative", "-o", png)
    assert r.returncode == 0, r.stderr
    assert "the accepted 1 access in 50,000 (2e-5 per 30-min access, Grøtting 2015 conservative)" in r.stdout
    assert "governing" in r.stdout and png.stat().st_size > 10_000


@pytest.mark.slow
def test_screen_json():
    r = run("screen", SCENARIO, "--tp", "5", "9", "3", "--directions", "4", "--json", "--statistics", "rice")
    out = json.loads(r.stdout)
    assert out["beta_deg"] == [0.0, 90.0, 180.0, 270.0] and len(out["Hs_limit"]) == 3
    assert all(0 < h < 2 for row in out["Hs_limit"] for h in row)


@pytest.mark.parametrize("accept", ["0", "1.5", "sometimes"])
def test_screen_accept_outside_0_1_exit_2(accept):
    one_line_error(run("screen", SCENARIO, "--accept", accept), "accepted probability")




def test_fender_point_outside_the_hull_exit_2(tmp_path):
    text = SCENARIO.read_text().replace("points = [[13.84, 0.75, 1.9], [13.84, -0.75, 1.9]]",
                                        "points = [[13.84, 0.75, 1.9], [13.84, -9.75, 1.9]]")
    assert "-9.75" in text
    bad = tmp_path / "aft.toml"
    bad.write_text(text)
    r = run("screen", bad)
    assert r.returncode == 2 and "fender.points[1]" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.slow
def test_rao_compare_open_sea_writes_the_figure(tmp_path):
    """Issue 9: free RAOs beside the pile vs the open sea for five headings, as a figure."""
    import subprocess
    import sys
    from pathlib import Path

    scenario = Path(__file__).resolve().parents[2] / "scenarios" / "ctv_landing.toml"
    out = tmp_path / "cmp.png"
    r = subprocess.run([sys.executable, "-m", "boatland", "rao", str(scenario), "--periods", "7",
                        "--compare-open-sea", str(out)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 20000
