"""A full disk, met as a file-size limit (``ulimit -f``), by every writer: one line naming the file, exit 2, no
core dump, no hang, nothing partial left under the final name (nor a temporary file), the inputs unchanged —
and a campaign's finished trials kept for the resume. Real processes under a real limit."""

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
ENV = {**os.environ, "PYTHONPATH": str(REPO)}


def limited(kib: int, *args, cwd):
    """``boatland ARGS`` with its files limited to ``kib`` KiB; (exit status, stderr lines, seconds)."""
    argv = " ".join(f"'{a}'" for a in map(str, args))
    t0 = time.monotonic()
    r = subprocess.run(["bash", "-c", f"ulimit -f {kib}; exec {sys.executable} -m boatland {argv}"], cwd=cwd,
                       capture_output=True, text=True, timeout=120, env=ENV)
    return r.returncode, [ln for ln in r.stderr.splitlines() if ln.startswith("boatland: error")], time.monotonic() - t0


def run(*args, cwd):
    r = subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], cwd=cwd, capture_output=True, text=True,
                       timeout=600, env=ENV)
    assert r.returncode == 0, r.stderr
    return r


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    """A run log and a campaign store to read back under the limit."""
    tmp = tmp_path_factory.mktemp("space")
    run("run", "--duration", "60", "--log", "run.mcap", cwd=tmp)
    run("campaign", "demo", "--set", "seeds=1", "--set", "access=10", "-o", "store.h5", cwd=tmp)
    return tmp


@pytest.mark.slow
@pytest.mark.parametrize("kib, argv, out", [
    (200, ["run", "--duration", "600", "--no-log", "-o", "x.h5"], "x.h5"),
    (100, ["run", "--duration", "600", "--log", "x.mcap"], "x.mcap"),
    (100, ["run", "--duration", "300", "--no-log", "--rerun", "save=x.rrd"], "x.rrd"),
    (100, ["replay", "{made}/run.mcap", "--save", "x.rrd"], "x.rrd"),
    (20, ["plot", "{made}/run.mcap", "-o", "x.png"], "x.png"),
    (100, ["hydro", "import", str(REPO / "boatland" / "data" / "ctv24.h5"), "-o", "x.h5"], "x.h5"),
    (30, ["report", "{made}/store.h5", "-o", "rep"], "rep/p_vs_hs.png"),
], ids=lambda v: v if isinstance(v, str) else None)
def test_every_writer_stops_in_one_line_and_leaves_nothing_partial(made, tmp_path, kib, argv, out):
    before = {p: p.read_bytes() for p in made.iterdir()}
    status, errors, seconds = limited(kib, *(a.format(made=made) for a in argv), cwd=tmp_path)
    assert status == 2 and len(errors) == 1, (status, errors)
    assert f"no space left writing {out} (File too large)" in errors[0], errors[0]
    assert seconds < 60 and not (tmp_path / out).exists()       # no hang (a bound, not a timing)
    assert not [p for p in tmp_path.rglob("*") if p.name.endswith(".part") or p.name.startswith("core")]
    assert {p: p.read_bytes() for p in made.iterdir()} == before            # inputs untouched


@pytest.mark.slow
def test_a_database_written_in_place_stays_as_it_was(tmp_path):
    db = tmp_path / "db.h5"
    shutil.copyfile(REPO / "boatland" / "data" / "ctv24.h5", db)
    before = db.read_bytes()
    status, errors, _ = limited(len(before) // 1024 - 1, "irf", db, cwd=tmp_path)
    assert status == 2 and len(errors) == 1 and "no space left writing" in errors[0] and str(db) in errors[0], errors
    assert db.read_bytes() == before and not list(tmp_path.glob(".*.part"))


@pytest.mark.slow
def test_a_campaign_keeps_its_finished_trials_and_resumes(tmp_path):
    status, errors, _ = limited(12, "campaign", "demo", "--set", "seeds=2", "-o", "c.h5", cwd=tmp_path)
    assert status == 2 and len(errors) == 1 and "the 16 finished trials are kept in c.h5.journal" in errors[0], errors
    assert not (tmp_path / "c.h5").exists() and not list(tmp_path.glob(".*.part"))
    r = run("campaign", "demo", "--set", "seeds=2", "-o", "c.h5", cwd=tmp_path)
    assert "16 trials (0 run now, 16 from before)" in r.stdout


@pytest.mark.slow
def test_a_database_build_stops_in_one_line(tmp_path):
    """``hydro build`` (Capytaine; a coarse ctv24: 0.5 m panels, 9 frequencies, 90° directions, ~15 s)."""
    import re

    text = (REPO / "boatland" / "scenarios" / "vessels" / "ctv24.toml").read_text(encoding="utf-8")
    for old, new in (("lid = true", "lid = true\npanel_size = 0.5"), ("omega_min = 0.04", "omega_min = 0.48"),
                     ("omega_max = 5.0", "omega_max = 2.40"), ("d_omega = 0.04", "d_omega = 0.24"),
                     ("step_deg = 5.0", "step_deg = 90.0")):
        text = re.sub(re.escape(old), new, text)
    (tmp_path / "coarse.toml").write_text(text, encoding="utf-8")
    status, errors, _ = limited(50, "hydro", "build", "coarse.toml", "-o", "x.h5", "--no-progress", cwd=tmp_path)
    assert status == 2 and len(errors) == 1 and "no space left writing x.h5 (File too large)" in errors[0], errors
    assert sorted(p.name for p in tmp_path.iterdir()) == ["coarse.toml"]
