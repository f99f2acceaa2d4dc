"""The ``boatland`` command as a user runs it (real subprocesses)."""

import json
import subprocess
import sys

import pytest


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def test_help_lists_commands():
    r = run("--help")
    assert r.returncode == 0 and "hydro" in r.stdout
    r = run("hydro", "--help")
    assert r.returncode == 0 and all(c in r.stdout for c in ("import", "info", "build", "list"))


def test_import_then_info(refdata, tmp_path):
    out = tmp_path / "sphere.h5"
    r = run("hydro", "import", refdata / "bemio_sphere" / "sphere.h5", "-o", out)
    assert r.returncode == 0, r.stderr
    assert "bemio reader" in r.stdout and out.exists()
    r = run("hydro", "info", out, "--json")
    assert r.returncode == 0, r.stderr
    s = json.loads(r.stdout)
    assert s["n_freq"] == 240 and s["omega_max"] == 12.0 and s["has_A_inf"]
    assert 4.0 < s["natural_periods"]["heave"] < 4.8  # C33 = ρgπa², m = ρ⅔πa³, μ ≈ 0.42 → 4.36 s
    assert any("negative damping" in w for w in s["warnings"])


@pytest.mark.parametrize("content, expected", [
    (None, "no such file, and not a built-in vessel"),
    (b"", "not an HDF5/NetCDF file"),
    (b"\x89HDF\r\n\x1a\n" + b"\x00" * 64, "not a readable HDF5 file"),
])
def test_bad_database_is_one_line_exit_2(tmp_path, content, expected):
    path = tmp_path / "db.h5"
    if content is not None:
        path.write_bytes(content)
    r = run("hydro", "info", path)
    assert r.returncode == 2
    assert expected in r.stderr and "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1


def test_import_failure_writes_nothing(tmp_path):
    bad = tmp_path / "bad.1"
    bad.write_text("this is not WAMIT output\n")
    out = tmp_path / "out.h5"
    r = run("hydro", "import", bad, "-o", out)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert not out.exists() and list(tmp_path.iterdir()) == [bad]
