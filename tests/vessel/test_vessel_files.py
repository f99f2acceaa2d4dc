"""Vessel files: loading, derived quantities, and every kind of bad input reported with its key."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.tomlspec import SpecError
from boatland.vessel.files import VesselSpec, load_vessel, wavelength

VESSELS = Path(__file__).resolve().parents[2] / "scenarios" / "vessels"

BASE = """
name = "t"
[hull]
length = 24.0
demihull_beam = 2.8
draft = 1.4
separation = 6.2
[inertia]
mass = 90000.0
kg = 2.7
r_xx = 3.3
r_yy = 6.3
[frequencies]
omega_min = 0.04
omega_max = 4.0
d_omega = 0.04
"""


def write(tmp_path, text, name="v.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def edit(text, **repl):
    """Replace ``key = value`` lines (key as written) — ``None`` deletes the line."""
    out = []
    for line in text.splitlines():
        key = line.split("=")[0].strip()
        if key in repl:
            if repl[key] is not None:
                out.append(f"{key} = {repl[key]}")
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def problems_of(tmp_path, text) -> dict[str, str]:
    with pytest.raises(SpecError) as info:
        load_vessel(write(tmp_path, text))
    assert isinstance(info.value, BoatlandInputError)
    return dict(info.value.problems)


# ---------------------------------------------------------------------- good files
def test_shipped_ctv24_file():
    spec = load_vessel(VESSELS / "ctv24.toml")
    assert spec.name == "ctv24"
    assert (spec.length, spec.demihull_beam, spec.draft, spec.separation) == (24.0, 2.8, 1.4, 6.2)
    assert spec.total_mass == 90000.0
    assert spec.cb == pytest.approx(90000.0 / (1025 * 2 * 24 * 2.8 * 1.4))
    assert spec.hull.volume * spec.rho == pytest.approx(spec.total_mass)
    assert np.allclose(spec.cog, [0.0, 0.0, 1.3])
    assert np.allclose(spec.radii_of_gyration, [3.3, 6.3, 6.3])
    assert spec.water_depth == math.inf and spec.lid
    assert spec.omega.size == 125 and spec.omega[0] == pytest.approx(0.04) and spec.omega[-1] == pytest.approx(5.0)
    assert np.allclose(np.diff(spec.omega), 0.04)
    assert spec.wave_dir_deg.tolist() == list(range(0, 360, 5))
    assert spec.solved_directions_deg.tolist() == list(range(0, 181, 5))
    assert spec.panels_per_wavelength() >= 8.0


def test_shipped_model2_file_estimates_izz():
    spec = load_vessel(VESSELS / "model2.toml")
    assert spec.rho == 1000.0 and spec.total_mass == 60.0
    assert spec.separation + spec.demihull_beam == pytest.approx(0.79)  # Table 4.2 breadth
    assert np.allclose(spec.inertia_cog, [3.5, 24.5, 28.0])
    assert any("I_zz not given" in n for n in spec.notes)
    assert 0.35 <= spec.cb <= 0.85
    # frequencies are the full-scale grid scaled by sqrt(10)
    assert spec.omega[-1] == pytest.approx(15.75) and spec.omega.size == 126


def test_mass_matrix_about_the_reference_point():
    spec = load_vessel(VESSELS / "ctv24.toml")
    M = spec.mass_matrix()
    zg = spec.cog[2]
    assert M[0, 0] == spec.total_mass
    assert M[0, 4] == pytest.approx(spec.total_mass * zg)  # surge–pitch coupling from a CoG above the origin
    assert M[3, 3] == pytest.approx(spec.inertia_cog[0] + spec.total_mass * zg ** 2)


def test_defaults_without_mass_use_wigley_cb(tmp_path):
    spec = load_vessel(write(tmp_path, edit(BASE, mass=None)))
    assert spec.cb == pytest.approx(4 / 9) and spec.hull.p == pytest.approx(2.0)
    assert spec.total_mass == pytest.approx(1025 * spec.hull.volume)
    spec = load_vessel(write(tmp_path, edit(BASE, mass=None, separation="6.2\nblock_coefficient = 0.5")))
    assert spec.cb == 0.5


def test_frequency_count_and_finite_depth(tmp_path):
    text = edit(BASE, d_omega=None, omega_max="4.0\nn = 12") + '[environment]\nwater_depth = 30.0\n'
    spec = load_vessel(write(tmp_path, text))
    assert spec.omega.size == 12 and spec.water_depth == 30.0
    assert spec.shortest_wavelength == pytest.approx(wavelength(4.0, 9.81, 30.0))


def test_wavelength_dispersion():
    assert wavelength(1.0, 9.81) == pytest.approx(2 * math.pi * 9.81)
    lam = wavelength(0.5, 9.81, 10.0)
    k = 2 * math.pi / lam
    assert 9.81 * k * math.tanh(k * 10.0) == pytest.approx(0.25, rel=1e-12)


def test_explicit_panel_counts(tmp_path):
    spec = load_vessel(write(tmp_path, BASE + "[mesh]\nn_length = 40\nn_girth = 5\n"))
    counts = spec.panel_counts()
    assert counts.n_half_length == 20 and counts.n_girth == 5 and counts.n_lid >= 1


# ---------------------------------------------------------------------- bad files
def test_unknown_key_did_you_mean(tmp_path):
    found = problems_of(tmp_path, edit(BASE, draft=None, separation="6.2\ndraught = 1.4"))
    assert found["hull.draught"] == "unknown key (did you mean 'draft'?)"
    assert found["hull.draft"].startswith("missing")


def test_unknown_table_did_you_mean(tmp_path):
    found = problems_of(tmp_path, BASE + "[frequency]\nn = 3\n")
    assert "did you mean 'frequencies'" in found["frequency"]


def test_several_problems_reported_at_once(tmp_path):
    text = edit(BASE, draft="-1", kg='"high"', step="x", omega_max="0.01") + "[directions]\nstep_deg = 7\n"
    with pytest.raises(SpecError) as info:
        load_vessel(write(tmp_path, text))
    found = dict(info.value.problems)
    assert found["hull.draft"] == "must be > 0, got -1"
    assert found["inertia.kg"] == "must be a number, got 'high'"
    assert "divide 180" in found["directions.step_deg"]
    assert "frequencies.omega_max" in found
    msg = str(info.value)
    assert msg.splitlines()[0].endswith(f"{len(found)} problems:")
    assert f"{tmp_path / 'v.toml'}: hull.draft: must be > 0, got -1" in msg


def test_malformed_toml_gives_line_and_column(tmp_path):
    text = BASE.replace("kg = 2.7", "kg = 2.7.1")
    with pytest.raises(SpecError) as info:
        load_vessel(write(tmp_path, text))
    line = next(i for i, ln in enumerate(text.splitlines(), 1) if ln.startswith("kg"))
    assert f"line {line}, column" in str(info.value)


def test_negative_draft_names_the_key(tmp_path):
    found = problems_of(tmp_path, edit(BASE, draft="-1.4"))
    assert list(found) == ["hull.draft"]


def test_block_coefficient_out_of_range_names_the_mass(tmp_path):
    found = problems_of(tmp_path, edit(BASE, mass="200000.0"))
    assert list(found) == ["inertia.mass"]
    assert "C_b = m / (2 ρ L b T) = 1.037" in found["inertia.mass"]
    found = problems_of(tmp_path, edit(BASE, mass="40000.0"))
    assert "0.461" not in found["inertia.mass"] and "[0.35, 0.85]" in found["inertia.mass"]


def test_overlapping_demihulls(tmp_path):
    found = problems_of(tmp_path, edit(BASE, separation="2.5"))
    assert list(found) == ["hull.separation"]
    assert "overlap" in found["hull.separation"]


def test_either_or_keys(tmp_path):
    found = problems_of(tmp_path, edit(BASE, r_xx="3.3\ni_xx = 1e6", d_omega="0.04\nn = 100",
                                       separation="6.2\nblock_coefficient = 0.5"))
    assert set(found) == {"inertia.i_xx", "frequencies.d_omega", "hull.block_coefficient"}
    found = problems_of(tmp_path, edit(BASE, r_yy=None, d_omega=None))
    assert set(found) == {"inertia.r_yy", "frequencies.n"}


def test_bad_inertia_type_does_not_also_say_missing(tmp_path):
    found = problems_of(tmp_path, edit(BASE, r_xx='"big"'))
    assert list(found) == ["inertia.r_xx"]


def test_physically_impossible_values(tmp_path):
    found = problems_of(tmp_path, edit(BASE, kg="40.0"))
    assert "unstable in roll" in found["inertia.kg"]
    found = problems_of(tmp_path, edit(BASE, r_xx="20.0", r_yy="6.3\nr_zz = 6.3"))
    assert "triangle" not in found["inertia.r_xx"] and "exceeds the sum" in found["inertia.r_xx"]
    found = problems_of(tmp_path, BASE + '[environment]\nrho = 1.025\nwater_depth = "shallow"\n')
    assert set(found) == {"environment.rho", "environment.water_depth"}


def test_too_coarse_mesh_rejected(tmp_path):
    found = problems_of(tmp_path, BASE + "[mesh]\npanel_size = 2.0\n")
    assert "panels per shortest wavelength" in found["mesh.panel_size"]


def test_direct_construction_is_validated():
    with pytest.raises(SpecError, match="hull.draft: must be > 0"):
        VesselSpec(name="x", length=24, demihull_beam=2.8, draft=-1, separation=6.2, kg=2.7,
                   omega_min=0.1, omega_max=2.0, n_omega=10, r_xx=3, r_yy=6)
    spec = load_vessel(VESSELS / "ctv24.toml")
    with pytest.raises(BoatlandInputError, match="hull.separation"):
        spec.replace(separation=2.0)
    assert spec.replace(panel_size=0.4).panel_counts().n_half_length < spec.panel_counts().n_half_length
