"""Imported databases with mass properties: a vessel file with a [bem] table, and `hydro import` flags.

Reference data: the floating hemisphere of radius 5 m of tests/data/refdata (bemio_sphere: HydroChrono's
BEMIO file of a WAMIT run, ρ = 1000, ∇ = 261.724 m³, CoG 2 m below the waterline, no mass matrix;
wamit_sphere: WEC-Sim's WAMIT run, reference point at the CoG). A solid sphere's radius of gyration is
√(2/5) a = 3.162 m.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from boatland.hydro import read_hydro
from boatland.hydro.read import read_vessel_file
from boatland.vessel.imported import MassProperties, apply_mass_properties, weight_terms
from boatland.tomlspec import SpecError
from boatland.vessel.files import load_vessel

R_G = math.sqrt(0.4) * 5.0


def vessel_file(tmp_path, bem, inertia="", bem_extra="", name="sphere"):
    text = (f'name = "{name}"\n[bem]\nfile = "{bem}"\n{bem_extra}\n'
            f'[inertia]\n{inertia}\n')
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return path


SOLID = f"r_xx = {R_G}\nr_yy = {R_G}\nr_zz = {R_G}\n"


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=600)


# ---------------------------------------------------------------------- the model
def test_vessel_file_gives_the_bemio_sphere_its_mass(refdata, tmp_path):
    """Mass ρ∇ at the database's own CoG: M is the rigid-body matrix, C is unchanged (the BEMIO file's C
    already holds the weight of ρ∇ at z = −2 m: C44 = ρ g ∇ · 2 m for a sphere, whose metacentre is its
    centre)."""
    raw, _ = read_hydro(refdata / "bemio_sphere" / "sphere.h5")
    assert raw.M is None
    m = raw.rho * raw.disp_vol
    assert raw.C[3, 3] == pytest.approx(m * raw.g * 2.0, rel=1e-3)
    path = vessel_file(tmp_path, refdata / "bemio_sphere" / "sphere.h5", f"mass = {m!r}\ncog = [0.0, 0.0, -2.0]\n"
                       + SOLID)
    db = read_vessel_file(path)
    assert db.name == "sphere"
    assert db.M[0, 0] == m and np.allclose(db.cog, [0, 0, -2])
    assert db.M[3, 3] == pytest.approx(m * R_G ** 2 + m * 4.0)       # parallel axes to the waterline origin
    assert db.M[0, 4] == pytest.approx(m * -2.0)
    assert np.allclose(db.C, raw.C, rtol=0, atol=1e-9 * raw.C[3, 3])
    assert any("mass properties from" in n for n in db.provenance.notes)
    # what `boatland hydro info` reads from the same file
    db2, fmt = read_hydro(path)
    assert fmt == "vessel" and np.array_equal(db2.M, db.M)


def test_defaults_mass_rho_volume_and_the_database_cog(refdata, tmp_path):
    path = vessel_file(tmp_path, refdata / "bemio_sphere" / "sphere.h5", SOLID)
    db = read_vessel_file(path)
    assert db.M[0, 0] == pytest.approx(1000.0 * 261.724)
    assert np.allclose(db.cog, [0, 0, -2])
    notes = " ".join(db.provenance.notes)
    assert "mass = ρ∇ of the database" in notes and "centre of gravity (0.0, 0.0, -2.0) m from the database" in notes


def test_moving_the_cog_moves_the_weight_terms_of_C(refdata, tmp_path):
    """CoG 1 m higher: C44 and C55 fall by m g × 1 m; a CoG 0.5 m forward couples pitch and yaw by m g x_G."""
    raw, _ = read_hydro(refdata / "bemio_sphere" / "sphere.h5")
    m = raw.rho * raw.disp_vol
    db = apply_mass_properties(raw, MassProperties(mass=m, cog=(0.5, 0.0, -1.0), radii=(R_G,) * 3))
    assert db.C[3, 3] == pytest.approx(raw.C[3, 3] - m * raw.g * 1.0, rel=1e-12)
    assert db.C[4, 4] == pytest.approx(raw.C[4, 4] - m * raw.g * 1.0, rel=1e-12)
    assert db.C[3, 5] == pytest.approx(raw.C[3, 5] + m * raw.g * 0.5, rel=1e-12)
    assert db.C[2, 2] == raw.C[2, 2]
    assert any("heel or trim" in n for n in db.provenance.notes)
    W = weight_terms(2.0, (1.0, 2.0, 3.0), 10.0)
    assert (W[3, 3], W[4, 4], W[3, 5], W[4, 5]) == (-60.0, -60.0, 20.0, 40.0)


def test_wamit_sphere_with_its_reference_point_at_the_cog(refdata, tmp_path):
    """WAMIT's reference point is the CoG (z = −2 m): the same mass there leaves C unchanged; ρ from the file."""
    bem = refdata / "wamit_sphere" / "sphere.1"
    path = vessel_file(tmp_path, bem, "cog = [0.0, 0.0, -2.0]\n" + SOLID, bem_extra="rho = 1000.0")
    db = read_vessel_file(path)
    raw, _ = read_hydro(bem, rho=1000.0)
    assert db.rho == 1000.0 and np.allclose(db.ref_point, [0, 0, -2])
    assert db.M[0, 0] == pytest.approx(1000.0 * raw.disp_vol)
    assert db.M[3, 3] == pytest.approx(db.M[0, 0] * R_G ** 2)        # about the CoG itself
    assert np.allclose(db.C, raw.C, rtol=0, atol=1e-9 * raw.C[3, 3])


# ---------------------------------------------------------------------- the checks of a built vessel
@pytest.mark.parametrize("inertia, key, text", [
    ("mass = 523448.0\n" + SOLID, "inertia.mass", "differs from ρ∇ = 261724 kg of the database by +100.0%"),
    ("cog = [0.0, 0.0, 6.0]\n" + SOLID, "inertia.cog", "unstable in roll"),
    (f"r_xx = 9.0\nr_yy = {R_G}\nr_zz = {R_G}\n", "inertia.r_xx", "exceeds the sum of the other two"),
    (f"r_xx = {R_G}\nr_zz = {R_G}\n", "inertia.r_yy", "missing"),
    (f"r_xx = {R_G}\ni_xx = 1e6\nr_yy = {R_G}\n", "inertia.i_xx", "not both"),
])
def test_bad_mass_properties_name_their_key(refdata, tmp_path, inertia, key, text):
    path = vessel_file(tmp_path, refdata / "bemio_sphere" / "sphere.h5", inertia)
    with pytest.raises(SpecError) as info:
        read_vessel_file(path)
    found = dict(info.value.problems)
    assert key in found and text in found[key], found


def test_bad_vessel_files(refdata, tmp_path):
    path = vessel_file(tmp_path, tmp_path / "nothing.h5", SOLID)
    with pytest.raises(SpecError) as info:
        load_vessel(path)
    assert dict(info.value.problems)["bem.file"].startswith("not found:")
    path = tmp_path / "both.toml"
    path.write_text('name = "x"\n[hull]\nlength = 1.0\n[bem]\nfile = "a.h5"\n[inertia]\nr_xx = 1.0\n')
    with pytest.raises(SpecError, match=r"hull: give either \[hull\]"):
        load_vessel(path)
    path.write_text('name = "x"\n[inertia]\nr_xx = 1.0\n')
    with pytest.raises(SpecError, match=r"hull: missing table: give \[hull\]"):
        load_vessel(path)


# ---------------------------------------------------------------------- as a user runs it
DECAY = """name = "sphere_decay"
description = "an imported hemisphere released from 0.5 m of heave"
[simulation]
duration = 20.0
dt = 0.02
[vessel]
database = "sphere.toml"
heading_deg = 0.0
position = [0.0, 0.0]
[radiation]
method = "convolution"
memory = 15.0
[initial]
displacement = [0.0, 0.0, 0.5]
"""


@pytest.mark.slow
def test_imported_sphere_runs_from_a_scenario_file_alone(refdata, tmp_path):
    """`boatland run` of a scenario whose vessel.database is a vessel file naming BEM output with no mass
    matrix (HydroChrono's BEMIO sphere, mass and radii given in the vessel file): `scenario check` passes,
    the run completes on that database, and the heave released from 0.5 m decays with the database's
    natural period T = 2π √((m + A33(ω_n)) / C33) (4.365 s; tests/test_cli.py's import gives the same).

    Measured (2026-12-01): zero down-crossings 4.345–4.348 s apart after the first cycle (−0.4 % from the
    undamped natural period: the free decay sees A33(ω) and B33(ω) over the band, not A33 at ω_n alone);
    peaks 0.318, 0.173, 0.096, 0.053 m (ratio 0.55 per cycle, ζ ≈ 0.096). Tolerance 2 %: the gap between a
    damped decay's crossing period and the undamped natural period at this ζ, with margin.
    """
    import h5py

    m = 1000.0 * 261.724
    vessel = vessel_file(tmp_path, refdata / "bemio_sphere" / "sphere.h5",
                         f"mass = {m}\ncog = [0.0, 0.0, -2.0]\n" + SOLID)
    scen = tmp_path / "decay.toml"
    scen.write_text(DECAY, encoding="utf-8")
    r = run("scenario", "check", scen)
    assert r.returncode == 0, r.stderr
    r = run("run", scen, "--json", "--no-log", "-o", tmp_path / "run.h5")
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    assert out["status"] == "completed" and out["provenance"]["database"] == "sphere"
    assert out["max_motions"]["heave [m]"] == pytest.approx(0.5)
    with h5py.File(tmp_path / "run.h5") as f:                 # the run's time series (CF dataset)
        t, z = f["time"][:], f["heave"][:]
    assert t[-1] == pytest.approx(20.0)
    down = np.flatnonzero((z[:-1] > 0) & (z[1:] <= 0))
    crossings = t[down] - z[down] * (t[down + 1] - t[down]) / (z[down + 1] - z[down])
    assert crossings.size >= 4
    period = float(np.mean(np.diff(crossings[1:])))
    T_n = read_vessel_file(vessel).natural_periods()["heave"]
    assert period == pytest.approx(T_n, rel=0.02), (period, T_n)
    peaks = z[1:-1][(z[1:-1] > z[:-2]) & (z[1:-1] >= z[2:])]
    assert peaks.size >= 3 and np.all(np.diff(peaks) < 0) and peaks[-1] < 0.5 * peaks[0]


def test_hull_vessel_file_as_a_database_says_build_it_first(repo_root, tmp_path):
    scen = tmp_path / "decay.toml"
    scen.write_text(DECAY.replace('"sphere.toml"', f'"{repo_root / "scenarios" / "vessels" / "ctv24.toml"}"'))
    r = run("run", scen, "--no-log")
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and "build it first" in r.stderr


def test_hydro_import_flags_and_hydro_build_of_a_vessel_file(refdata, tmp_path):
    bem = refdata / "bemio_sphere" / "sphere.h5"
    out = tmp_path / "with_mass.h5"
    r = run("hydro", "import", bem, "-o", out, "--cog", "0", "0", "-2", "--radii", R_G, R_G, R_G)
    assert r.returncode == 0, r.stderr
    db, _ = read_hydro(out)
    assert db.M is not None and db.M[0, 0] == pytest.approx(1000.0 * 261.724)
    r = run("hydro", "import", bem, "-o", tmp_path / "bad.h5", "--mass", "1000", "--radii", R_G, R_G, R_G)
    assert r.returncode == 2 and "--mass: 1000 kg differs from ρ∇" in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and not (tmp_path / "bad.h5").exists()
    r = run("hydro", "import", bem, "-o", tmp_path / "bad.h5", "--mass", "261724")
    assert r.returncode == 2 and "--radii or --inertia: missing" in r.stderr
    path = vessel_file(tmp_path, bem, SOLID)
    built = tmp_path / "built.h5"
    r = run("hydro", "build", path, "-o", built)
    assert r.returncode == 0, r.stderr
    assert np.array_equal(read_hydro(built)[0].M, read_vessel_file(path).M)
