"""HydroDB: validation, immutability, rigid-body mass matrix, natural periods, diagnostics."""

import numpy as np
import pytest

from boatland.errors import HydroDataError
from boatland.vessel.database import HydroDB, HullMesh, rigid_body_mass_matrix, skew


def make_db(nf=20, nb=3, **kw):
    w = np.linspace(0.2, 4.0, nf)
    A = np.zeros((6, 6, nf)) + np.eye(6)[:, :, None] * 1e3
    B = np.zeros((6, 6, nf)) + np.eye(6)[:, :, None] * (np.exp(-(w - 1.0) ** 2))[None, None, :] * 1e3
    X = np.ones((6, nb, nf), complex)
    args = dict(omega=w, A=A, B=B, X=X, wave_dir_deg=np.linspace(0, 180, nb), C=np.diag([0, 0, 1e5, 1e5, 1e5, 0.0]),
                M=rigid_body_mass_matrix(1e4, (0, 0, 0.5), (1e4, 2e4, 2e4)), disp_vol=10.0)
    args.update(kw)
    return HydroDB(**args)


def test_arrays_are_read_only_and_validated():
    db = make_db()
    with pytest.raises(ValueError):
        db.A[0, 0, 0] = 1.0
    with pytest.raises(HydroDataError, match="strictly increasing"):
        make_db(omega=np.array([0.1, 0.3, 0.2] + list(np.linspace(0.4, 2, 17))))
    with pytest.raises(HydroDataError, match=r"B: expected shape \(6, 6, 20\)"):
        make_db(B=np.zeros((6, 6, 19)))
    bad = np.zeros((6, 6, 20)); bad[2, 2, 4] = np.nan
    with pytest.raises(HydroDataError, match="A: 1 value"):
        make_db(A=bad)
    with pytest.raises(HydroDataError, match="ω = 0"):
        make_db(omega=np.linspace(0.0, 4.0, 20))
    with pytest.raises(HydroDataError, match="rho"):
        make_db(rho=-1.0)


def test_rigid_body_mass_matrix_matches_momentum():
    """Kinetic energy ½ vᵀMv of a point-mass cloud equals that of the 6×6 matrix (parallel-axis theorem)."""
    rng = np.random.default_rng(1)
    pts = rng.normal(size=(50, 3)) + [1.0, -0.5, 2.0]
    m = rng.uniform(1, 2, 50)
    cog = (m[:, None] * pts).sum(0) / m.sum()
    r = pts - cog
    I_cg = sum(mi * (ri @ ri * np.eye(3) - np.outer(ri, ri)) for mi, ri in zip(m, r))
    ref = np.array([0.3, 0.1, -0.4])
    M = rigid_body_mass_matrix(m.sum(), cog, I_cg, ref)
    v, om = rng.normal(size=3), rng.normal(size=3)
    vel = v + np.cross(om, pts - ref)
    T_points = 0.5 * (m * (vel ** 2).sum(1)).sum()
    nu = np.concatenate([v, om])
    assert np.isclose(0.5 * nu @ M @ nu, T_points, rtol=1e-12)
    assert np.allclose(skew([1, 2, 3]) @ [4, 5, 6], np.cross([1, 2, 3], [4, 5, 6]))


def test_natural_period_of_constant_added_mass():
    db = make_db()
    T = db.natural_periods()
    assert np.isclose(T["heave"], 2 * np.pi * np.sqrt((1e4 + 1e3) / 1e5), rtol=1e-9)
    assert T["roll"] > 0 and T["pitch"] > 0
    assert make_db(C=np.zeros((6, 6))).natural_periods()["heave"] is None


def test_diagnostics_flags_negative_damping_and_missing_a_inf():
    B = make_db().B.copy()
    B[2, 2, -3:] = -50.0
    msgs = make_db(B=B).diagnostics()
    assert any("negative damping B[heave]" in m for m in msgs)
    assert any("A∞" in m for m in msgs)
    assert not any("negative damping" in m for m in make_db(A_inf=np.eye(6)).diagnostics())


def test_hull_mesh_validation():
    with pytest.raises(HydroDataError, match="mesh.faces"):
        HullMesh(np.zeros((3, 3)), np.array([[0, 1, 2, 5]]))


def test_diagnostics_flags_an_irregular_frequency_spike_not_a_smooth_peak():
    smooth = make_db(nf=80)
    assert not any("sharp peaks" in m for m in smooth.diagnostics())
    B = smooth.B.copy()
    B[2, 2, 50] *= 4.0  # one sample far from both neighbours: the signature of an irregular frequency
    msgs = make_db(nf=80, B=B).diagnostics()
    assert any("sharp peaks in B[heave]" in m and f"{smooth.omega[50]:.3g}" in m for m in msgs)
