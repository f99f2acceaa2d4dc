"""Issue 14: a corpus of bad inputs over every command. Each case must end with exit status 2, one line
on stderr naming the file or the flag, no traceback, and every input byte-identical afterwards (and
nothing new left in the folder).

Most cases run in this process through ``boatland.cli.main([...])`` (the same code path as the
command, with captured output: the corpus stays fast); a representative subset runs as real
subprocesses. Inputs are generated here from the repository's own files (scenarios, built-in
databases).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from boatland.cli import main

REPO = Path(__file__).resolve().parents[2]
SCEN = REPO / "scenarios" / "ctv_landing.toml"
DB = REPO / "boatland" / "data" / "model2.h5"      # the smaller built-in database file

# --------------------------------------------------------------------------------- the input folder
MUTATIONS = {            # scenario-file edits: (old text, new text, what the message must name)
    "seed_negative": ("seed = 1", "seed = -1", "simulation.seed"),
    "seed_too_big": ("seed = 1", f"seed = {2 ** 63}", "simulation.seed"),
    "duration_nan": ("duration = 600.0", "duration = nan", "simulation.duration"),
    "duration_inf": ("duration = 600.0", "duration = inf", "simulation.duration"),
    "duration_negative": ("duration = 600.0", "duration = -5.0", "simulation.duration"),
    "duration_zero": ("duration = 600.0", "duration = 0.0", "simulation.duration"),
    "duration_huge": ("duration = 600.0", "duration = 1e12", "simulation.duration"),
    "hs_nan": ("Hs = 0.4 ", "Hs = nan ", "sea.Hs"),
    "hs_inf": ("Hs = 0.4 ", "Hs = inf ", "sea.Hs"),
    "hs_breaking": ("Hs = 0.4 ", "Hs = 50.0 ", "Hs"),
    "hs_negative": ("Hs = 0.4 ", "Hs = -1.0 ", "sea.Hs"),
    "hs_text": ("Hs = 0.4 ", "Hs = \"big\" ", "sea.Hs"),
    "tp_zero": ("Tp = 7.0 ", "Tp = 0.0 ", "sea.Tp"),
    "tp_nan": ("Tp = 7.0 ", "Tp = nan ", "sea.Tp"),
    "fender_above_deck": ("[13.84, 0.75, 1.9], [13.84, -0.75, 1.9]", "[13.84, 0.75, 25.0], [13.84, -0.75, 25.0]",
                          "fender.points"),
    "fender_below_keel": ("[13.84, 0.75, 1.9], [13.84, -0.75, 1.9]", "[13.84, 0.75, -5.0], [13.84, -0.75, -5.0]",
                          "fender.points"),
    "fender_nan": ("[13.84, 0.75, 1.9], [13.84, -0.75, 1.9]", "[nan, 0.75, 1.9], [13.84, -0.75, 1.9]", "fender.points"),
    "pile_huge": ("monopile_diameter = 6.5", "monopile_diameter = 1e9", "landing.monopile_diameter"),
    "pile_wide": ("monopile_diameter = 6.5", "monopile_diameter = 25.0", "landing.monopile_diameter"),
    "pile_nan": ("monopile_diameter = 6.5", "monopile_diameter = nan", "landing.monopile_diameter"),
    "thrust_huge": ("force = 150.0e3", "force = 1e12", "thrust.force"),
    "thrust_nan": ("force = 150.0e3", "force = nan", "thrust.force"),
    "thrust_negative": ("force = 150.0e3", "force = -5.0", "thrust.force"),
    "unknown_key": ("[simulation]", "[simulation]\nseeed = 3", "simulation.seeed"),
    "database_missing": ('database = "ctv27"', 'database = "no_such_db.h5"', "vessel.database"),
    "database_unknown": ('database = "ctv27"', 'database = "ctv99"', "vessel.database"),
    "syntax": ("[simulation]", "[simulation\n", "x.toml"),
}
WHOLE = {                # whole-file replacements
    "empty": (b"", "x.toml"),
    "binary": (bytes(range(256)) * 4, "x.toml"),
    "not_toml": (b"this is not a scenario\n", "x.toml"),
}


def _snapshot(folder: Path) -> dict:
    return {str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest() if p.is_file() else "dir"
            for p in sorted(folder.rglob("*"))}


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    """A folder with good and bad inputs of every kind."""
    d = tmp_path_factory.mktemp("inputs")
    text = SCEN.read_text()
    (d / "x.toml").write_text(text)
    for name, (old, new, _) in MUTATIONS.items():
        assert old in text, name
        (d / "bad").mkdir(exist_ok=True)
        (d / "bad" / f"{name}.toml").write_text(text.replace(old, new, 1))
    for name, (data, _) in WHOLE.items():
        (d / "bad" / f"{name}.toml").write_bytes(data)
    shutil.copy(DB, d / "db.h5")
    (d / "garbage.h5").write_bytes(b"\x89HDF\r\n\x1a\n" + b"\x00" * 64)
    (d / "text.mcap").write_text("not a log\n")
    (d / "log.mcap").write_bytes(b"\x89MCAP0\r\n" + os.urandom(300))
    (d / "folder").mkdir()
    (d / "afile.txt").write_text("a file\n")
    (d / "store.h5").write_bytes(b"not a store")
    (d / "scatter.bin").write_bytes(bytes(range(256)) * 8)
    (d / "scatter_empty.csv").write_text("")
    (d / "scatter_text.csv").write_text("Hs;Tp\nbig;small\n")
    (d / "vessel.toml").write_text((REPO / "scenarios" / "vessels" / "model2.toml").read_text())
    (d / "c.toml").write_text('name = "c"\nscenario = "x.toml"\nseeds = 2\naccess = 30.0\n[axes]\n'
                              '"sea.Hs" = [0.3, 0.6]\n')
    (d / "c_hs50.toml").write_text('name = "c"\nscenario = "x.toml"\nseeds = 2\naccess = 30.0\n[axes]\n'
                                   '"sea.Hs" = [0.3, 50.0]\n')
    (d / "c_nan.toml").write_text('name = "c"\nscenario = "x.toml"\nseeds = 2\naccess = nan\n')
    (d / "c_seeds0.toml").write_text('name = "c"\nscenario = "x.toml"\nseeds = 0\n')
    (d / "c_unknown.toml").write_text('name = "c"\nscenario = "x.toml"\nseeds = 2\nseedz = 3\n')
    (d / "c_noscen.toml").write_text('name = "c"\nscenario = "nope.toml"\nseeds = 2\n')
    (d / "c_huge.toml").write_text('name = "c"\nscenario = "x.toml"\nseeds = 2\naccess = 1e11\n')
    import h5py
    import numpy as np

    with h5py.File(d / "empty_store.h5", "w") as f:
        f.attrs["format"] = "boatland-campaign-1"
    with h5py.File(d / "notrials.h5", "w") as f:
        f.attrs["format"] = "boatland-campaign-1"
        f.attrs["plan"] = '{"axes": {}}'
        f.attrs["incidents"] = "first slip"
        f.create_dataset("trials", data=np.zeros(0, dtype=[("trial", "i8")]))
        f.create_dataset("stats", data=np.zeros(0, dtype=[("case", "i8")]))
    return d


def _cases():
    P = "/proc/boatland-x"         # a folder nobody can write in
    run = [
        (["--duration", "nan"], "--duration"), (["--duration", "inf"], "--duration"),
        (["--duration", "-1"], "--duration"), (["--duration", "0"], "--duration"),
        (["--duration", "abc"], "--duration"), (["--duration", "1e9"], "--duration"),
        (["--duration", "0.01"], "--duration"),
        (["--seed", "-1"], "--seed"), (["--seed", "abc"], "--seed"), (["--seed", str(2 ** 64)], "--seed"),
        (["--seed", "1.5"], "--seed"),
        (["-o", f"{P}/x.h5"], "-o"), (["-o", "folder"], "-o"), (["-o", "x.toml"], "-o"),
        (["--log", "x.toml"], "--log"), (["-o", "same.mcap"], "same.mcap"), (["-o", "nodir/x.h5"], "-o"),
        (["--log", f"{P}/x.mcap"], "--log"), (["--log", "folder"], "--log"),
        (["--rerun", f"save={P}/x.rrd"], "--rerun"), (["--rerun", "save=x.toml"], "--rerun"),
        (["--rerun", "save=folder"], "--rerun"), (["--rerun", "bogus"], "--rerun"),
        (["--rerun", "connect=rerun+http://127.0.0.1:1/proxy"], "--rerun"),
        (["--rerun", "serve", "--bind", "not-an-address"], "--bind"), (["--port", "0"], "--port"),
        (["--port", "70000"], "--port"), (["--progress-file", "x.toml"], "--progress-file"),
        (["--no-log", "-o", "x.toml"], "-o"),
    ]
    out = [(f"run {' '.join(a)}", ["run", "x.toml", *a], e) for a, e in run]
    for name, (_, _, key) in MUTATIONS.items():
        for cmd in (["run"], ["scenario", "check"], ["rao"], ["screen"]):
            if name == "duration_huge" and cmd != ["run"]:     # too long to run on this machine: only run refuses
                continue
            out.append((f"{' '.join(cmd)} {name}", [*cmd, f"bad/{name}.toml"], key if cmd != ["scenario", "check"]
                        or name != "syntax" else "x.toml"))
    for name in WHOLE:
        for cmd in (["run"], ["scenario", "check"], ["rao"]):
            out.append((f"{' '.join(cmd)} {name}", [*cmd, f"bad/{name}.toml"], f"{name}.toml"))
    out += [
        ("run missing file", ["run", "nope.toml"], "nope.toml"),
        ("replay missing", ["replay", "nope.mcap"], "nope.mcap"),
        ("replay text", ["replay", "text.mcap"], "text.mcap"),
        ("replay garbage", ["replay", "log.mcap"], "log.mcap"),
        ("replay save itself", ["replay", "log.mcap", "--save", "log.mcap"], "--save"),
        ("replay save proc", ["replay", "log.mcap", "--save", f"{P}/x.rrd"], "--save"),
        ("replay save folder", ["replay", "log.mcap", "--save", "folder"], "--save"),
        ("replay port 0", ["replay", "log.mcap", "--serve", "--port", "0"], "--port"),
        ("replay bind", ["replay", "log.mcap", "--serve", "--bind", "999.1.1.1"], "--bind"),
        ("replay spawn", ["replay", "log.mcap", "--spawn"], "--rerun spawn"),
        ("plot xyz", ["plot", "log.mcap", "-o", "p.xyz"], "-o"),
        ("plot no suffix", ["plot", "log.mcap", "-o", "p"], "-o"),
        ("plot itself", ["plot", "log.mcap", "-o", "log.mcap"], "-o"),
        ("plot folder", ["plot", "log.mcap", "-o", "folder"], "-o"),
        ("plot proc", ["plot", "log.mcap", "-o", f"{P}/p.png"], "-o"),
        ("plot missing", ["plot", "nope.mcap", "-o", "p.png"], "nope.mcap"),
        ("plot text", ["plot", "text.mcap", "-o", "p.png"], "text.mcap"),
        ("campaign missing", ["campaign", "nope.toml"], "nope.toml"),
        ("campaign bad toml", ["campaign", "bad/syntax.toml"], "syntax.toml"),
        ("campaign -o itself", ["campaign", "c.toml", "-o", "c.toml"], "-o"),
        ("campaign -o scenario", ["campaign", "c.toml", "-o", "x.toml"], "-o"),
        ("campaign -o folder", ["campaign", "c.toml", "-o", "folder"], "-o"),
        ("campaign -o proc", ["campaign", "c.toml", "-o", f"{P}/s.h5"], "-o"),
        ("campaign -o nodir", ["campaign", "c.toml", "-o", "nodir/s.h5"], "-o"),
        ("campaign workers 0", ["campaign", "c.toml", "--workers", "0"], "--workers"),
        ("campaign workers -1", ["campaign", "c.toml", "--workers", "-1"], "--workers"),
        ("campaign workers x", ["campaign", "c.toml", "--workers", "x"], "--workers"),
        ("campaign scheduler garbage", ["campaign", "c.toml", "--scheduler", "garbage"], "--scheduler"),
        ("campaign scheduler http", ["campaign", "c.toml", "--scheduler", "http://127.0.0.1:1"], "--scheduler"),
        ("campaign scheduler noport", ["campaign", "c.toml", "--scheduler", "tcp://127.0.0.1"], "--scheduler"),
        ("campaign report file", ["campaign", "c.toml", "--report", "afile.txt"], "--report"),
        ("campaign report proc", ["campaign", "c.toml", "--report", f"{P}/rep"], "--report"),
        ("campaign hs 50", ["campaign", "c_hs50.toml"], "c_hs50.toml"),
        ("campaign duration nan", ["campaign", "c_nan.toml"], "c_nan.toml"),
        ("campaign seeds 0", ["campaign", "c_seeds0.toml"], "c_seeds0.toml"),
        ("campaign unknown key", ["campaign", "c_unknown.toml"], "c_unknown.toml"),
        ("campaign no scenario", ["campaign", "c_noscen.toml"], "c_noscen.toml"),
        ("campaign huge", ["campaign", "c_huge.toml"], "c_huge.toml"),
        ("campaign store not a store", ["campaign", "c.toml", "-o", "store.h5"], "store.h5"),
        ("report missing", ["report", "nope.h5"], "nope.h5"),
        ("report text", ["report", "store.h5", "-o", "rep"], "store.h5"),
        ("report -o itself", ["report", "store.h5", "-o", "store.h5"], "-o"),
        ("report -o file", ["report", "store.h5", "-o", "afile.txt"], "-o"),
        ("report -o proc", ["report", "store.h5", "-o", f"{P}/rep"], "-o"),
        ("report store without trials", ["report", "empty_store.h5", "-o", "rep"], "empty_store.h5"),
        ("report store with 0 trials", ["report", "notrials.h5", "-o", "rep"], "notrials.h5"),
        ("report target 0", ["report", "store.h5", "--target", "0"], "--target"),
        ("report target 1.5", ["report", "store.h5", "--target", "1.5"], "--target"),
        ("report target nan", ["report", "store.h5", "--target", "nan"], "--target"),
        ("import missing", ["hydro", "import", "nope.1", "-o", "o.h5"], "nope.1"),
        ("import -o itself", ["hydro", "import", "db.h5", "-o", "db.h5"], "-o"),
        ("import -o folder", ["hydro", "import", "db.h5", "-o", "folder"], "-o"),
        ("import -o proc", ["hydro", "import", "db.h5", "-o", f"{P}/o.h5"], "-o"),
        ("import rho", ["hydro", "import", "db.h5", "-o", "o.h5", "--rho", "-3"], "--rho"),
        ("import rho nan", ["hydro", "import", "db.h5", "-o", "o.h5", "--rho", "nan"], "--rho"),
        ("import g 0", ["hydro", "import", "db.h5", "-o", "o.h5", "--g", "0"], "--g"),
        ("import g inf", ["hydro", "import", "db.h5", "-o", "o.h5", "--g", "inf"], "--g"),
        ("import garbage", ["hydro", "import", "garbage.h5", "-o", "o.h5"], "garbage.h5"),
        ("import format", ["hydro", "import", "db.h5", "-o", "o.h5", "--format", "bogus"], "--format"),
        ("import no -o", ["hydro", "import", "db.h5"], "-o"),
        ("info missing", ["hydro", "info", "nope.h5"], "nope.h5"),
        ("info garbage", ["hydro", "info", "garbage.h5"], "garbage.h5"),
        ("info text", ["hydro", "info", "afile.txt"], "afile.txt"),
        ("build missing", ["hydro", "build", "nope.toml"], "nope.toml"),
        ("build -o itself", ["hydro", "build", "vessel.toml", "-o", "vessel.toml"], "-o"),
        ("build -o proc", ["hydro", "build", "vessel.toml", "-o", f"{P}/o.h5"], "-o"),
        ("build -o folder", ["hydro", "build", "vessel.toml", "-o", "folder"], "-o"),
        ("build bad vessel", ["hydro", "build", "bad/syntax.toml", "-o", "o.h5"], "syntax.toml"),
        ("irf t-max -1", ["irf", "db.h5", "--t-max", "-1"], "--t-max"),
        ("irf t-max nan", ["irf", "db.h5", "--t-max", "nan"], "--t-max"),
        ("irf t-max inf", ["irf", "db.h5", "--t-max", "inf"], "--t-max"),
        ("irf dt 0", ["irf", "db.h5", "--dt", "0"], "--dt"),
        ("irf dt big", ["irf", "db.h5", "--dt", "100", "--t-max", "50"], "--dt"),
        ("irf band", ["irf", "db.h5", "--band", "5", "1"], "--band"),
        ("irf band nan", ["irf", "db.h5", "--band", "nan", "1"], "--band"),
        ("irf r2", ["irf", "db.h5", "--target-r2", "1.5"], "--target-r2"),
        ("irf order", ["irf", "db.h5", "--max-order", "0"], "--max-order"),
        ("irf plot xyz", ["irf", "db.h5", "--plot", "p.xyz"], "--plot"),
        ("irf plot proc", ["irf", "db.h5", "--plot", f"{P}/p.png"], "--plot"),
        ("irf -o itself", ["irf", "db.h5", "-o", "db.h5"], "-o"),
        ("irf -o proc", ["irf", "db.h5", "-o", f"{P}/o.h5"], "-o"),
        ("irf -o folder", ["irf", "db.h5", "-o", "folder"], "-o"),
        ("irf missing", ["irf", "nope.h5"], "nope.h5"),
        ("irf garbage", ["irf", "garbage.h5", "--no-store"], "garbage.h5"),
        ("rao direction nan", ["rao", "x.toml", "--direction", "nan"], "--direction"),
        ("rao direction inf", ["rao", "x.toml", "--direction", "inf"], "--direction"),
        ("rao periods -1", ["rao", "x.toml", "--periods", "-1"], "--periods"),
        ("rao periods 0", ["rao", "x.toml", "--periods", "0", "3"], "--periods"),
        ("rao -o xyz", ["rao", "x.toml", "-o", "p.xyz"], "-o"),
        ("rao -o itself", ["rao", "x.toml", "-o", "x.toml"], "-o"),
        ("rao compare proc", ["rao", "x.toml", "--compare-open-sea", f"{P}/c.png"], "--compare-open-sea"),
        ("rao same figures", ["rao", "x.toml", "-o", "a.png", "--compare-open-sea", "a.png"], "a.png"),
        ("screen accept 2", ["screen", "x.toml", "--accept", "2"], "--accept"),
        ("screen accept -1", ["screen", "x.toml", "--accept", "-1"], "--accept"),
        ("screen accept word", ["screen", "x.toml", "--accept", "bestest"], "--accept"),
        ("screen access inf", ["screen", "x.toml", "--access", "inf"], "--access"),
        ("screen access 0", ["screen", "x.toml", "--access", "0"], "--access"),
        ("screen mu 0", ["screen", "x.toml", "--mu", "0"], "--mu"),
        ("screen mu nan", ["screen", "x.toml", "--mu", "nan"], "--mu"),
        ("screen thrust -1", ["screen", "x.toml", "--thrust", "-1"], "--thrust"),
        ("screen roll 100", ["screen", "x.toml", "--roll-limit", "100"], "--roll-limit"),
        ("screen tp 0", ["screen", "x.toml", "--tp", "0", "1", "2"], "--tp"),
        ("screen tp order", ["screen", "x.toml", "--tp", "5", "3", "4"], "--tp"),
        ("screen tp n", ["screen", "x.toml", "--tp", "3", "5", "2.5"], "--tp"),
        ("screen directions 0", ["screen", "x.toml", "--directions", "0"], "--directions"),
        ("screen -o xyz", ["screen", "x.toml", "-o", "p.xyz"], "-o"),
        ("operability missing", ["operability", "x.toml", "nope.csv"], "nope.csv"),
        ("operability binary", ["operability", "x.toml", "scatter.bin"], "scatter.bin"),
        ("operability empty", ["operability", "x.toml", "scatter_empty.csv"], "scatter_empty.csv"),
        ("operability text", ["operability", "x.toml", "scatter_text.csv"], "scatter_text.csv"),
        ("operability accept", ["operability", "x.toml", "scatter_text.csv", "--accept", "2"], "--accept"),
        ("operability access", ["operability", "x.toml", "scatter_text.csv", "--access", "inf"], "--access"),
        ("unknown command", ["fly"], "fly"),
        ("scenario check missing", ["scenario", "check", "nope.toml"], "nope.toml"),
        ("validate unknown case", ["validate", "--case", "fly"], "--case fly"),
        ("validate workers 0", ["validate", "--workers", "0"], "--workers"),
        ("validate -o file", ["validate", "--case", "contact-analytic", "-o", "x.toml"], "-o x.toml"),
        ("validate refdata missing", ["validate", "--case", "hulme-hemisphere", "--refdata", "nope"], "--refdata nope"),
    ]
    return out


CASES = _cases()


def test_the_corpus_is_large():
    assert len(CASES) >= 150, len(CASES)


@pytest.mark.slow
@pytest.mark.parametrize("argv, names", [(c[1], c[2]) for c in CASES], ids=[c[0] for c in CASES])
def test_bad_input_is_one_line_exit_2_and_touches_nothing(inputs, monkeypatch, capsys, argv, names):
    monkeypatch.chdir(inputs)
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    before = _snapshot(inputs)
    status = main(argv)
    cap = capsys.readouterr()
    err = cap.err
    if argv[:2] == ["scenario", "check"]:     # its report (every problem, one per line) is its output
        assert status == 2 and "Traceback" not in err + cap.out, cap.out + err
        assert names in cap.out.splitlines()[0] or names in cap.out, cap.out
        assert _snapshot(inputs) == before
        return
    lines = [ln for ln in err.splitlines() if ln.strip() and not ln.startswith("warning:")]
    assert status == 2, err
    assert len(lines) == 1, err
    assert "Traceback" not in err
    assert names in lines[0], lines[0]
    assert _snapshot(inputs) == before


# ------------------------------------------------------------------------------ real subprocesses
SUBSET = ["run --duration nan", "run -o x.toml", "run seed_negative", "run fender_above_deck", "plot xyz",
          "campaign scheduler garbage", "report -o file", "import g 0", "irf -o itself", "screen access inf",
          "operability binary", "rao direction nan", "replay save itself", "campaign hs 50"]


@pytest.mark.slow
@pytest.mark.parametrize("name", SUBSET)
def test_as_a_real_process(inputs, name):
    argv, names = next((c[1], c[2]) for c in CASES if c[0] == name)
    before = _snapshot(inputs)
    r = subprocess.run([sys.executable, "-m", "boatland", *argv], cwd=inputs, capture_output=True, text=True,
                       timeout=120, env={**os.environ, "PYTHONPATH": str(REPO)})
    lines = [ln for ln in r.stderr.splitlines() if ln.strip() and not ln.startswith("warning:")]
    assert r.returncode == 2 and len(lines) == 1 and names in lines[0], r.stderr
    assert "Traceback" not in r.stderr
    assert _snapshot(inputs) == before


def test_a_closed_pipe_is_quiet():
    """``boatland scenario schema | head -1``: no BrokenPipeError, no message."""
    p = subprocess.Popen([sys.executable, "-m", "boatland", "scenario", "schema"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, env={**os.environ, "PYTHONPATH": str(REPO)})
    p.stdout.readline()
    p.stdout.close()
    err = p.stderr.read().decode()
    assert p.wait(timeout=60) in (0, 141) and err == "", err
