"""Databases that do not tabulate the whole circle, as a user meets them on the command line (real
subprocesses): the symmetric half circle is completed and said so; an asymmetric half circle or a
single direction refuses other directions with one line and exit status 2."""

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from boatland.hydro import write_bemio
from boatland.hydro.builtin import load_builtin

SCENARIO = Path(__file__).resolve().parents[1] / "scenarios" / "ctv24_landing.toml"   # ctv24-derived databases


def run(*args):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          timeout=300)


def one_line_error(r, *words):
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    errors = [ln for ln in r.stderr.splitlines() if ln.startswith("boatland: error:")]
    assert len(errors) == 1 and len(r.stderr.strip().splitlines()) == 1 and "Traceback" not in r.stderr, r.stderr
    assert all(w in errors[0] for w in words), errors[0]


@pytest.fixture(scope="module")
def databases(tmp_path_factory):
    """half.h5 (ctv24 on 0–180°), asym.h5 (the same with a 3 % sway–heave coupling in B), one.h5 (180° only)."""
    d = tmp_path_factory.mktemp("db")
    full = load_builtin("ctv24")
    keep = np.flatnonzero(full.wave_dir_deg <= 180.0)
    half = full.replace(X=full.X[:, keep], wave_dir_deg=full.wave_dir_deg[keep])
    B = half.B.copy()
    c = 0.03 * np.sqrt(np.abs(B[1, 1]).max() * np.abs(B[2, 2]).max())
    B[1, 2] += c * np.exp(-half.omega)
    B[2, 1] += c * np.exp(-half.omega)
    one = full.replace(X=full.X[:, [36]], wave_dir_deg=[180.0])
    for name, db in (("half", half), ("asym", half.replace(B=B)), ("one", one)):
        write_bemio(db, d / f"{name}.h5")
    return d


def scenario(databases, tmp_path, db: str, direction: float) -> Path:
    text = SCENARIO.read_text()
    text = text.replace('database = "ctv24"', f'database = "{databases / db}.h5"')
    text = text.replace("relative_direction_deg = 180.0", f"relative_direction_deg = {direction}")
    path = tmp_path / f"{db}_{direction:g}.toml"
    path.write_text(text)
    return path


@pytest.mark.slow
def test_symmetric_half_database_is_completed(databases, tmp_path):
    r = run("scenario", "check", scenario(databases, tmp_path, "half", 225.0))
    assert r.returncode == 0, r.stdout + r.stderr
    m = re.search(r"note: database directions 0–180° every 5°, completed to 360° by port–starboard symmetry "
                  r"\(checked: max coupling ([0-9.e+-]+)\)", r.stdout)
    assert m and float(m.group(1)) < 1e-12, r.stdout       # the mirrored Wigley hull: round-off only
    r = run("hydro", "info", databases / "half.h5")
    assert r.returncode == 0 and "coverage        completed to 360° by port–starboard symmetry" in r.stdout


@pytest.mark.slow
def test_asymmetric_half_database_refuses_outside(databases, tmp_path):
    bad = scenario(databases, tmp_path, "asym", 225.0)
    r = run("scenario", "check", bad)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert r.stdout.splitlines()[0] == (
        f"{bad}: sea.relative_direction_deg: 225° is outside the directions of database '{databases / 'asym.h5'}' "
        "(0–180°, not port–starboard symmetric: sway–heave coupling 3e-2 in B); valid: 0–180°")
    one_line_error(run("rao", bad, "--direction", "90"), "sea.relative_direction_deg: 225° is outside")
    good = scenario(databases, tmp_path, "asym", 135.0)
    r = run("scenario", "check", good)
    assert r.returncode == 0 and "asymmetric (sway–heave coupling 3e-2 in B): directions outside 0–180° refused" \
        in r.stdout
    one_line_error(run("rao", good, "--direction", "225", "--periods", "6"),
                   "--direction: 225° is outside the directions of database", "valid: 0–180°")
    one_line_error(run("screen", good, "--tp", "5", "9", "2"),
                   "--directions 8 (every 45°): 225°, 270°, 315° are outside", "valid: 0–180°")


@pytest.mark.slow
def test_single_direction_database_refuses_others(databases, tmp_path):
    bad = scenario(databases, tmp_path, "one", 170.0)
    one_line_error(run("run", bad, "--duration", "5", "--no-log"),
                   "sea.relative_direction_deg: 170° is outside the directions of database",
                   "(single direction 180°); valid: 180° only")
    good = scenario(databases, tmp_path, "one", 180.0)
    one_line_error(run("rao", good, "--direction", "170", "--periods", "6"), "--direction: 170° is outside")
    r = run("rao", good, "--periods", "6")
    assert r.returncode == 0, r.stderr
