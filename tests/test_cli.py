"""The ``boatland`` command as a user runs it (real subprocesses)."""

import json
import subprocess
import sys
from pathlib import Path

import pytest


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def test_help_lists_commands():
    r = run("--help")
    assert r.returncode == 0 and "hydro" in r.stdout
    r = run("hydro", "--help")
    assert r.returncode == 0 and all(c in r.stdout for c in ("import", "info", "build", "list"))


def test_irf_help_states_the_library_fit_defaults():
    from boatland.vessel.radiation import MAX_ORDER, TARGET_R2

    r = run("irf", "--help")
    text = " ".join(r.stdout.split())
    assert r.returncode == 0
    assert f"default {TARGET_R2:g}" in text and f"default {MAX_ORDER}" in text


def test_irf_without_arguments_works_on_the_default_vessel():
    """ctv27 rings for 75 s: without --t-max the memory is lengthened until K has decayed (60 → 120 s), saying so."""
    r = run("irf", "--no-store", "--no-fit", "--json")
    assert r.returncode == 0, r.stderr
    assert "T_K = 60 s is too short" in r.stderr and "trying 120 s" in r.stderr
    assert json.loads(r.stdout)["settings"]["t_max"] == 120.0


def test_import_then_info(refdata, tmp_path):
    out = tmp_path / "sphere.h5"
    r = run("hydro", "import", refdata / "bemio_sphere" / "sphere.h5", "-o", out)
    assert r.returncode == 0, r.stderr
    assert "bemio reader" in r.stdout and out.exists()
    r = run("hydro", "info", out, "--json")
    assert r.returncode == 0, r.stderr
    s = json.loads(r.stdout)
    assert s["n_freq"] == 240 and abs(s["omega_max"] - 12.0) < 1e-4 and s["has_A_inf"]
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


@pytest.mark.slow
def test_irf_stores_bemio_groups_and_plot(refdata, tmp_path):
    import h5py

    from boatland.hydro.bemio import read_radiation

    db = tmp_path / "sphere.h5"
    assert run("hydro", "import", refdata / "bemio_sphere" / "sphere.h5", "-o", db).returncode == 0
    png = tmp_path / "irf.png"
    r = run("irf", db, "--t-max", "15", "--band", "0.3", "5", "--plot", png)
    assert r.returncode == 0, r.stderr
    assert "heave" in r.stdout and "stored IRFs and state-space fit" in r.stdout
    assert png.stat().st_size > 10_000
    with h5py.File(db) as f:
        K = f["body1/hydro_coeffs/radiation_damping/impulse_response_fun/K"]
        assert K.shape[:2] == (6, 6) and abs(K[2, 2, 0] - 96.70) < 0.5
        assert f["body1/hydro_coeffs/radiation_damping/state_space/it"][2, 2] <= 6
    mem = read_radiation(db)
    assert mem.state_space.pairs[(2, 2)].r2 >= 0.99


def test_irf_bad_settings_exit_2(refdata, tmp_path):
    db = tmp_path / "sphere.h5"
    run("hydro", "import", refdata / "bemio_sphere" / "sphere.h5", "-o", db)
    r = run("irf", db, "--t-max", "2")
    assert r.returncode == 2 and "increase t_max" in r.stderr and "Traceback" not in r.stderr


SCENARIOS = sorted((Path(__file__).resolve().parents[1] / "scenarios").glob("*.toml"))


@pytest.mark.slow
@pytest.mark.parametrize("scenario", SCENARIOS, ids=lambda p: p.stem)
def test_every_shipped_scenario_runs_shortened(scenario, tmp_path):
    """Each scenario file checks clean and runs 30 s (after its thrust ramp) through the real CLI."""
    r = run("scenario", "check", scenario)
    assert r.returncode == 0, r.stdout + r.stderr
    out = tmp_path / "run.h5"
    r = run("run", scenario, "--duration", "40", "--json", "-o", out)
    assert r.returncode == 0, r.stderr
    s = json.loads(r.stdout)
    assert s["status"] == "completed" and s["duration"] == pytest.approx(40.0, abs=0.1)
    import h5py

    with h5py.File(out) as f:          # netCDF-4: named variables with dimension scales
        assert f["motion"].shape[1] == 6 and f["time"][-1] == pytest.approx(40.0, abs=0.1)
        assert json.loads(f.attrs["summary"])["slip_events"] == s["slip_events"]


def test_bad_scenario_is_one_message_exit_2(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[simulation]\nduration = -5\n[sea]\nkind = "jonswap"\nHs = -1\nTp = 7\n[vesel]\n')
    r = run("run", bad)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert "simulation.duration" in r.stderr and "sea.Hs" in r.stderr and "did you mean" in r.stderr
