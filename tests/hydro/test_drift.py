"""Mean wave drift (boatland.hydro.drift): the far-field formulas against exact momentum fluxes, the
Kochin → far-field constant against Capytaine's own potential, the yaw moment against Capytaine's own
far-field routine and against a translated body, and the drift field of HydroDB (validation, subsets,
HDF5, direction completion). The analytic cylinder and the AQWA cross-check are in tests/validation."""

from __future__ import annotations

import logging
import math
import shutil

import h5py
import numpy as np
import pytest
from scipy.special import h1vp, hankel1

from boatland.conventions import PORT_STARBOARD_SIGN
from boatland.errors import HydroDataError
from boatland.hydro.bemio import read_bemio, write_bemio, write_drift
from boatland.hydro.drift import (DRIFT_NOTE, FAR_FIELD_DOFS, add_drift, capytaine_mesh_body, depth_factor,
                                  drift_from_results, maruo_newman)
from boatland.vessel.database import HullMesh
from boatland.vessel.directions import direction_coverage, full_circle_drift, full_circle_excitation

cpt = pytest.importorskip("capytaine")
logging.getLogger("capytaine").setLevel(logging.ERROR)


# ------------------------------------------------------------------ the formulas, exactly
def _field(k, beta, ms, a):
    """Incident plane wave + outgoing cylindrical waves Σ a_m H_m(kR) e^{imθ}: η, ∂η/∂R, ∂η/∂θ at (R, θ)."""
    def at(R, th):
        x = k * R
        eta = np.exp(1j * x * np.cos(th - beta))
        dR = 1j * k * np.cos(th - beta) * eta
        dth = -1j * x * np.sin(th - beta) * eta
        for m, am in zip(ms, a):
            e = np.exp(1j * m * th)
            eta, dR, dth = eta + am * hankel1(m, x) * e, dR + am * k * h1vp(m, x) * e, dth + am * hankel1(m, x) * 1j * m * e
        return eta, dR, dth
    return at


def _fluxes(at, R, k, n, N=4096):
    r"""Exact mean fluxes of horizontal momentum and of angular momentum through the circle of radius R
    (depth-integrated, per ρg): −∮T_i R dθ with T_i = (n/2) Re[∂_iη ∂_nη*/k² + ½(|η|² − |∇η|²/k²) n_i] and
    −(n/2k²) Re ∮ R ∂_θη ∂_Rη* dθ."""
    th = np.arange(N) * 2 * np.pi / N
    eta, dR, dth = at(R, th)
    er, et = np.stack([np.cos(th), np.sin(th)]), np.stack([-np.sin(th), np.cos(th)])
    grad = dR * er + dth / R * et
    T = 0.5 * n * np.real(grad * np.conj(dR) / k ** 2
                          + 0.5 * (np.abs(eta) ** 2 - (np.abs(grad[0]) ** 2 + np.abs(grad[1]) ** 2) / k ** 2) * er)
    F = -T.sum(axis=1) * R * 2 * np.pi / N
    Mz = -0.5 * n / k ** 2 * np.real(np.sum(R * dth * np.conj(dR))) * 2 * np.pi / N
    return F[0], F[1], Mz


@pytest.mark.parametrize("depth", [np.inf, 3.0])
def test_maruo_newman_equals_the_exact_fluxes_through_any_circle(depth):
    """A field of an incident wave and outgoing cylindrical waves carries the same momentum and angular
    momentum through every circle (no body between them); the far-field formulas, in terms of the
    amplitude 𝒜(θ) = √(2/π) e^{−iπ/4} Σ a_m (−i)^m e^{imθ}, must equal those fluxes exactly."""
    rng = np.random.default_rng(7)
    k, beta = 0.7, 0.6
    ms = np.arange(-6, 7)
    a = 0.3 * (rng.normal(size=ms.size) + 1j * rng.normal(size=ms.size))
    n, _ = depth_factor(k, depth)
    exact = [_fluxes(_field(k, beta, ms, a), R, k, n) for R in (3.0, 12.0, 40.0)]
    assert np.allclose(exact, exact[0], rtol=1e-10, atol=0)

    def amp(th, deriv=False):
        th = np.asarray(th, dtype=float)[..., None]
        c = np.sqrt(2 / np.pi) * np.exp(-0.25j * np.pi) * a * (-1j) ** ms * (1j * ms if deriv else 1.0)
        return np.sum(c * np.exp(1j * ms * th), axis=-1)

    N = 256
    th = 2 * np.pi * np.arange(N) / N
    got = maruo_newman(amp(th), amp(th, True), amp(beta), amp(beta, True), beta, k, depth, rho=1.0, g=1.0)
    assert np.allclose(got, exact[0], rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("depth", [np.inf, 6.0])
def test_kochin_gives_capytaines_far_field_potential(depth):
    r"""φ_s(R, θ, z) → −k√(2π)/(n tanh kh) e^{iπ/4} H(θ) f(z) e^{ikR}/√(kR): the constant of the module
    docstring, against Capytaine's own potential at kR = 300 (1/kR corrections: < 1 % of the largest)."""
    mesh = cpt.mesh_vertical_cylinder(length=4.0, radius=1.0, center=(0.3, 0.2, -1.0), resolution=(3, 16, 6)).immersed_part()
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs())
    solver = cpt.BEMSolver()
    res = solver.solve(cpt.DiffractionProblem(body=body, omega=1.5, wave_direction=0.4, water_depth=depth),
                       keep_details=True)
    k = res.wavenumber
    R, z, th = 300.0 / k, -0.5, np.array([0.0, 1.0, 2.5, 4.0])
    phi = solver.compute_potential(np.stack([R * np.cos(th), R * np.sin(th), z * np.ones(4)], axis=1), res)
    H = cpt.post_pro.compute_kochin(res, th)
    n, tanh = depth_factor(k, depth)
    f = np.exp(k * z) if np.isinf(depth) else np.cosh(k * (z + depth)) / np.cosh(k * depth)
    far = -k * math.sqrt(2 * math.pi) / (n * tanh) * np.exp(0.25j * np.pi) * H * f * np.exp(1j * k * R) / math.sqrt(k * R)
    assert np.abs(phi - far).max() <= 0.01 * np.abs(far).max()


def _box(center=(1.5, 0.8, -1.0), yaw=0.4):
    mesh = cpt.mesh_parallelepiped(size=(6, 2, 2), center=(0, 0, -1.0), resolution=(18, 6, 6)).immersed_part()
    c, s = math.cos(yaw), math.sin(yaw)
    mesh = mesh.rotated_with_matrix(np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]]))
    return mesh.translated((center[0], center[1], 0.0))


def _fixed_drift(mesh, omegas, betas, depth=np.inf):
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs())
    solver = cpt.BEMSolver()
    out = []
    for w in omegas:
        res = solver.solve_all([cpt.DiffractionProblem(body=body, omega=w, wave_direction=b, water_depth=depth)
                                for b in betas], keep_details=True, progress_bar=False)
        out.append(drift_from_results([], res, None, None)[0])
    return np.stack(out, axis=-1)                    # (6, Nb, Nf)


def test_fixed_body_agrees_with_capytaines_own_far_field_routine():
    """capytaine.post_pro.far_field_mean_drift_force (an independent implementation of Maruo's and Newman's
    formulas, with its own θ grid and finite-difference derivative) for a fixed box yawed and off the origin:
    surge, sway and yaw agree to 1e-3 of the largest value."""
    xr = pytest.importorskip("xarray")
    mesh = _box()
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, 0)))
    omegas, betas = [1.5, 2.5], [0.3, 2.0]
    ds = cpt.BEMSolver().fill_dataset(xr.Dataset(coords={"omega": omegas, "wave_direction": betas,
                                                         "radiating_dof": list(body.dofs),
                                                         "theta": np.linspace(0, 2 * np.pi, 721)}), body)
    fixed = xr.zeros_like(ds["excitation_force"]).rename({"influenced_dof": "radiating_dof"})
    theirs = cpt.post_pro.far_field_mean_drift_force(fixed, ds)
    ours = _fixed_drift(mesh, omegas, betas)
    for i, name in zip(FAR_FIELD_DOFS, ("drift_force_surge", "drift_force_sway", "drift_force_yaw")):
        diag = np.stack([np.diagonal(theirs[name].values[k]).real for k in range(2)], axis=-1)   # (Nb, Nf)
        assert np.allclose(ours[i], diag, rtol=0, atol=1e-3 * np.abs(diag).max()), name


def test_translated_body_same_force_moment_shifted():
    """The same box moved by (dx, dy): the drift force is unchanged and the yaw moment about the origin grows
    by dx F_y − dy F_x — the derivative term of Newman's yaw formula, checked against the forces."""
    omegas, betas, d = [1.2, 2.2], [0.0, 0.9, 2.4], (4.0, -2.5)
    here = _fixed_drift(_box(), omegas, betas)
    there = _fixed_drift(_box(center=(1.5 + d[0], 0.8 + d[1])), omegas, betas)
    scale = np.abs(here[:2]).max()
    assert np.allclose(there[:2], here[:2], rtol=0, atol=2e-3 * scale)
    assert np.allclose(there[5], here[5] + d[0] * here[1] - d[1] * here[0], rtol=0, atol=2e-3 * scale * 6)
    assert np.all(here[[2, 3, 4]] == 0)


def test_energy_check_passes_a_good_solution_and_flags_a_bad_one():
    """The optical theorem holds for a fixed box to the panel error (≤ 2 % of the drift in each direction);
    sources scaled by 10 % (a wrong solution) break it by about a tenth of the scattered energy."""
    mesh = _box()
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs())
    res = cpt.BEMSolver().solve_all([cpt.DiffractionProblem(body=body, omega=2.0, wave_direction=b) for b in (0.0, 2.0)],
                                    keep_details=True, progress_bar=False)
    good = drift_from_results([], res, None, None)
    assert np.all(good.imbalance <= 0.02 * np.hypot(*good.drift[:2]))
    for r in res:
        r.sources = 1.1 * r.sources
    bad = drift_from_results([], res, None, None)
    assert np.all(bad.imbalance >= 0.05 * np.hypot(*bad.drift[:2])) and np.all(bad.imbalance > 5 * good.imbalance)


# ------------------------------------------------------------------ add_drift on a database
@pytest.fixture(scope="module")
def aqwa_cylinder(refdata):
    """The AQWA cylinder (r 0.35 m, draught 0.63 m, 3 m water) at 5 frequencies above its heave resonance, with
    its wetted hull panels attached (WEC-Sim, Apache-2.0; tests/data/refdata/README.md)."""
    from boatland.hydro.aqwa import read_aqwa

    db = read_aqwa(refdata / "aqwa_cylinder" / "cylinder.AH1", drift="none")
    keep = slice(19, 24)
    db = db.replace(omega=db.omega[keep], A=db.A[..., keep], B=db.B[..., keep], X=db.X[..., keep])
    v, f = cylinder_panels(0.35, 0.63, 32, 8, 3)
    return db.replace(mesh=HullMesh(v, f))


def cylinder_panels(a, T, n_theta, n_z, n_r):
    """Wetted panels of a vertical circular cylinder (radius a, draught T, closed bottom), normals out into the
    water, finer towards the waterline; quads (a triangle repeats its last vertex)."""
    th = 2 * np.pi * np.arange(n_theta) / n_theta
    z = -T * (1 - np.sin(np.linspace(0, 1, n_z + 1) * np.pi / 2))
    v = [[a * math.cos(t), a * math.sin(t), zz] for zz in z for t in th]
    f = [[i * n_theta + j, i * n_theta + (j + 1) % n_theta, (i + 1) * n_theta + (j + 1) % n_theta, (i + 1) * n_theta + j]
         for i in range(n_z) for j in range(n_theta)]
    ring = lambda q, j: j % n_theta if q == 0 else len_side + (q - 1) * n_theta + j % n_theta  # noqa: E731
    len_side = len(v)
    for r in a * np.linspace(1, 0, n_r + 1)[1:-1]:
        v += [[r * math.cos(t), r * math.sin(t), -T] for t in th]
    v.append([0.0, 0.0, -T])
    c = len(v) - 1
    for q in range(n_r - 1):
        f += [[ring(q, j), ring(q + 1, j), ring(q + 1, j + 1), ring(q, j + 1)] for j in range(n_theta)]
    f += [[ring(n_r - 1, j), c, ring(n_r - 1, j + 1), ring(n_r - 1, j + 1)] for j in range(n_theta)]
    return np.array(v), np.array(f)


def test_add_drift_from_the_database_mesh(aqwa_cylinder):
    db = add_drift(aqwa_cylinder, progress=False)
    assert db.drift.shape == (6, 2, 5) and np.all(np.isfinite(db.drift))
    assert np.all(db.drift[[2, 3, 4]] == 0)
    assert np.all(db.drift[0, 0] > 0) and np.all(db.drift[0, 1] < 0)          # down-wave, 0° and 180°
    assert np.allclose(db.drift[0, 0], -db.drift[0, 1], rtol=1e-6)             # axisymmetric body
    note = db.provenance.notes[-1]
    assert note.startswith(DRIFT_NOTE) and "surge, sway and yaw only" in note and "and a lid" in note
    assert "energy check (optical theorem)" in note
    for name in ("A", "B", "X", "C", "M", "omega", "wave_dir_deg"):
        assert np.array_equal(getattr(db, name), getattr(aqwa_cylinder, name))  # nothing else changes
    # the same with an explicit body (no lid): the lid changes nothing away from irregular frequencies
    body = capytaine_mesh_body(aqwa_cylinder, lid=False)
    assert body.lid_mesh is None
    plain = add_drift(aqwa_cylinder, body=body, progress=False)
    assert np.allclose(plain.drift, db.drift, rtol=0.02, atol=1e-9)


def test_add_drift_needs_mass_and_mesh(aqwa_cylinder):
    with pytest.raises(HydroDataError, match="M: no mass matrix"):
        add_drift(aqwa_cylinder.replace(M=None))
    with pytest.raises(HydroDataError, match="mesh: no hull mesh in the database"):
        add_drift(aqwa_cylinder.replace(mesh=None))


# ------------------------------------------------------------------ the HydroDB field
@pytest.fixture(scope="module")
def ctv24():
    from boatland.hydro.builtin import load_builtin

    return load_builtin("ctv24")


def _with_drift(db, seed=3):
    """``db`` with a drift table that has the port–starboard symmetry of the hull."""
    rng = np.random.default_rng(seed)
    half = db.wave_dir_deg <= 180.0
    D = np.zeros((6, db.n_dir, db.n_freq))
    D[:, half] = rng.normal(size=(6, int(half.sum()), db.n_freq))
    D[np.ix_([1, 3, 5], [0, int(half.sum()) - 1])] = 0.0                 # sway, roll, yaw vanish at 0° and 180°
    for b in np.flatnonzero(~half):
        D[:, b] = PORT_STARBOARD_SIGN[:, None] * D[:, int(np.flatnonzero(np.isclose(db.wave_dir_deg, 360 - db.wave_dir_deg[b]))[0])]
    return db.replace(drift=D, provenance=db.provenance.with_note(f"{DRIFT_NOTE} test table"))


def test_drift_is_validated(ctv24):
    with pytest.raises(HydroDataError, match=r"drift: expected shape \(6, 72, 125\), got \(6, 72, 124\)"):
        ctv24.replace(drift=np.zeros((6, 72, 124)))
    bad = np.zeros((6, 72, 125))
    bad[0, 3, 7] = np.inf
    with pytest.raises(HydroDataError, match="drift: 1 value"):
        ctv24.replace(drift=bad)
    db = _with_drift(ctv24)
    with pytest.raises(ValueError):
        db.drift[0, 0, 0] = 1.0                                                  # read-only like the others


def test_replace_carries_drift_to_subsets_and_drops_it_otherwise(ctv24):
    db = _with_drift(ctv24)
    keep = np.flatnonzero(db.wave_dir_deg <= 180.0)
    half = db.replace(X=db.X[:, keep], wave_dir_deg=db.wave_dir_deg[keep])
    assert np.array_equal(half.drift, db.drift[:, keep]) and half.provenance == db.provenance
    k = np.arange(10, 40, 3)
    band = db.replace(omega=db.omega[k], A=db.A[..., k], B=db.B[..., k], X=db.X[..., k])
    assert np.array_equal(band.drift, db.drift[..., k])
    # 360° is 0°: the other half circle, written 180 … 360, still finds its drift
    k2 = np.flatnonzero(db.wave_dir_deg >= 180.0)
    other = db.replace(X=np.concatenate([db.X[:, k2], db.X[:, :1]], axis=1),
                       wave_dir_deg=np.append(db.wave_dir_deg[k2], 360.0))
    assert np.array_equal(other.drift, np.concatenate([db.drift[:, k2], db.drift[:, :1]], axis=1))
    moved = db.replace(X=db.X[:, keep], wave_dir_deg=db.wave_dir_deg[keep] + 1.0)
    assert moved.drift is None and "mean drift dropped" in moved.provenance.notes[-1]
    # replacing X alone (e.g. the pile's scattered wave added) keeps the table
    assert np.array_equal(db.replace(X=2 * db.X).drift, db.drift)


def test_full_circle_drift_mirrors_like_the_excitation(ctv24):
    db = _with_drift(ctv24)
    keep = np.flatnonzero(db.wave_dir_deg <= 180.0)
    half = db.replace(X=db.X[:, keep], wave_dir_deg=db.wave_dir_deg[keep])
    cov = direction_coverage(half)
    assert cov.kind == "mirrored"
    beta, D = full_circle_drift(half, cov)
    assert np.array_equal(beta, full_circle_excitation(half, cov)[0])
    assert np.array_equal(beta, db.wave_dir_deg) and np.allclose(D, db.drift, rtol=0, atol=0)
    assert full_circle_drift(ctv24.replace(drift=None)) is None


def test_hdf5_round_trip_old_files_and_write_drift(ctv24, refdata, tmp_path):
    db = _with_drift(ctv24)
    write_bemio(db, tmp_path / "d.h5")
    back = read_bemio(tmp_path / "d.h5")
    assert np.array_equal(back.drift, db.drift) and back.provenance == db.provenance
    # a database without drift writes no dataset and reads back None; an old file (HydroChrono's) too
    write_bemio(ctv24.replace(drift=None), tmp_path / "none.h5")
    with h5py.File(tmp_path / "none.h5") as f:
        assert "body1/boatland/drift" not in f
    assert read_bemio(tmp_path / "none.h5").drift is None
    assert read_bemio(refdata / "bemio_sphere" / "sphere.h5").drift is None
    # write_drift adds the table to an existing file and touches nothing else
    write_drift(tmp_path / "none.h5", db)
    with h5py.File(tmp_path / "none.h5") as f, h5py.File(tmp_path / "d.h5") as g:
        names = []
        f.visit(names.append)
        for name in names:
            if isinstance(f[name], h5py.Dataset):
                assert np.array_equal(f[name][()], g[name][()]), name
    assert np.array_equal(read_bemio(tmp_path / "none.h5").drift, db.drift)
    with pytest.raises(HydroDataError, match="frequencies or directions"):
        k = np.arange(5)
        write_drift(tmp_path / "none.h5", db.replace(omega=db.omega[k], A=db.A[..., k], B=db.B[..., k], X=db.X[..., k]))


def test_wec_sim_mean_drift_groups_are_read(refdata, tmp_path):
    """WEC-Sim's layout (writeBEMIOH5.m): /body1/hydro_coeffs/mean_drift/<method>/val, normalised by ρg. No
    public BEMIO file with mean drift was found, so the group is added to a copy of HydroChrono's sphere.h5."""
    path = tmp_path / "sphere.h5"
    shutil.copy(refdata / "bemio_sphere" / "sphere.h5", path)
    path.chmod(0o644)
    base = read_bemio(path)
    val = np.linspace(0.0, 1.0, 6 * base.n_freq).reshape(6, 1, base.n_freq)
    with h5py.File(path, "r+") as f:
        f["body1/hydro_coeffs/mean_drift/pressure_integration/val"] = 2 * val
        f["body1/hydro_coeffs/mean_drift/momentum_conservation/val"] = val
    db = read_bemio(path)
    assert np.allclose(db.drift, val * base.rho * base.g, rtol=1e-15)
    assert any("momentum_conservation" in n and "not used: pressure_integration" in n for n in db.provenance.notes)
    with h5py.File(path, "r+") as f:
        del f["body1/hydro_coeffs/mean_drift/momentum_conservation/val"]
        del f["body1/hydro_coeffs/mean_drift/pressure_integration/val"]
        f["body1/hydro_coeffs/mean_drift/control_surface/val"] = val[:, :, :-1]
    with pytest.raises(HydroDataError, match=r"mean_drift: expected shape \(6, 1, 240\)"):
        read_bemio(path)


def test_other_mass_properties_are_noted(refdata):
    """A BEM drift was computed with the BEM run's own motions: giving the database other mass properties
    keeps the table and says so."""
    from boatland.hydro.aqwa import read_aqwa
    from boatland.vessel.imported import MassProperties, apply_mass_properties

    db = read_aqwa(refdata / "aqwa_cylinder" / "cylinder.AH1")          # COG on the waterline: GM < 0
    low = apply_mass_properties(db, MassProperties(mass=db.mass, cog=(0.0, 0.0, -0.4), radii=(0.3, 0.3, 0.3)))
    assert np.array_equal(low.drift, db.drift)
    assert any(n.startswith("mean drift kept as the BEM output gives it") for n in low.provenance.notes)
    again = apply_mass_properties(low, MassProperties(mass=low.mass, cog=(0.0, 0.0, -0.4), radii=(0.3, 0.3, 0.3)))
    assert sum(n.startswith("mean drift kept") for n in again.provenance.notes) == 1      # same M, C: no new note
