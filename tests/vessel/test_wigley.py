"""Generalized Wigley catamaran: closed-form hydrostatics and panel meshes."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate

from boatland.vessel.wigley import (
    PanelCounts,
    WigleyCatamaran,
    clustered,
    exponent_for_block_coefficient,
    merge_vertices,
    mesh_volume,
    mirror_panels,
    panel_normals_areas,
)

CTV = WigleyCatamaran.from_block_coefficient(24.0, 2.8, 1.4, 6.2, 0.4667)


def test_block_coefficient_and_exponent():
    assert exponent_for_block_coefficient(4 / 9) == pytest.approx(2.0)
    for cb in (0.35, 0.5, 0.85):
        hull = WigleyCatamaran.from_block_coefficient(10, 1, 0.5, 3, cb)
        assert hull.block_coefficient == pytest.approx(cb, rel=1e-12)


@pytest.mark.parametrize("p", [1.5, 2.0, 3.7])
def test_closed_form_hydrostatics_against_quadrature(p):
    """Volume, centre of buoyancy and waterplane moments vs direct numerical integration of the offsets."""
    hull = WigleyCatamaran(20.0, 2.0, 1.2, 5.0, p)
    L, T, s = hull.length, hull.draft, hull.separation
    demi_vol = integrate.dblquad(lambda z, x: 2 * hull.half_breadth(x, z), -L / 2, L / 2, -T, 0.0)[0]
    demi_zmom = integrate.dblquad(lambda z, x: 2 * z * hull.half_breadth(x, z), -L / 2, L / 2, -T, 0.0)[0]
    assert hull.volume == pytest.approx(2 * demi_vol, rel=1e-8)
    assert hull.centre_of_buoyancy[2] == pytest.approx(demi_zmom / demi_vol, rel=1e-8)
    eta = lambda x: hull.half_breadth(x, 0.0)  # noqa: E731
    area = integrate.quad(lambda x: 2 * eta(x), -L / 2, L / 2)[0]
    # ∫ y² dy over [s/2 − η, s/2 + η], both demihulls
    i_t = 2 * integrate.quad(lambda x: ((s / 2 + eta(x)) ** 3 - (s / 2 - eta(x)) ** 3) / 3, -L / 2, L / 2)[0]
    i_l = 2 * integrate.quad(lambda x: 2 * eta(x) * x ** 2, -L / 2, L / 2)[0]
    assert hull.waterplane_area == pytest.approx(2 * area, rel=1e-8)
    assert hull.waterplane_inertia[0] == pytest.approx(i_t, rel=1e-8)
    assert hull.waterplane_inertia[1] == pytest.approx(i_l, rel=1e-8)


def test_classic_wigley_centre_of_buoyancy():
    assert WigleyCatamaran(10, 1, 1, 3, 2.0).centre_of_buoyancy[2] == pytest.approx(-3 / 8)


def test_overlapping_demihulls_rejected():
    with pytest.raises(ValueError, match="overlap"):
        WigleyCatamaran(10, 2.0, 1.0, 1.5)


def test_clustered_spacing():
    u = clustered(10)
    assert u[0] == 0.0 and u[-1] == 1.0 and np.all(np.diff(u) > 0)
    assert np.diff(u)[-1] < 0.5 * np.diff(u)[0]  # finer at the bow / waterline end


def test_mesh_volume_converges_to_closed_form():
    """Second-order convergence of the panel volume (divergence theorem) to 2 C_b L b T."""
    errors = []
    for n in (4, 8, 16, 32):
        m = CTV.mesh(PanelCounts(n, n // 2, 1))
        errors.append(abs(mesh_volume(m.vertices, m.faces) / CTV.volume - 1))
    errors = np.array(errors)
    assert errors[-1] < 2e-3
    rates = errors[:-1] / errors[1:]
    assert np.all(rates > 3.5), rates  # halving the panel size divides the error by ~4


def _level(hull, pts):
    """F = (y − y_c)² − η(x, z)²: negative inside a demihull, positive outside."""
    x, y, z = np.moveaxis(pts, -1, 0)
    yc = np.sign(y) * hull.separation / 2
    return (y - yc) ** 2 - hull.half_breadth(x, z) ** 2


def test_normals_point_out_of_the_hull():
    """Each panel normal has a positive component along ∇F, the outward normal of the exact surface."""
    m = CTV.mesh(PanelCounts(12, 6, 1))
    n, area, centre = panel_normals_areas(m.vertices, m.faces)
    assert np.all(area > 0)
    h = 1e-6
    grad = np.stack([(_level(CTV, centre + h * e) - _level(CTV, centre - h * e)) / (2 * h) for e in np.eye(3)], axis=1)
    cos = np.sum(n * grad, axis=1) / np.linalg.norm(grad, axis=1)
    assert np.all(cos > 0.5), cos.min()


def test_full_mesh_is_watertight_below_the_waterline():
    """Every edge off the waterline is shared by exactly two panels, once in each direction
    (consistent orientation, shared vertices merged)."""
    m = CTV.mesh(PanelCounts(10, 5, 1))
    edges = {}
    for f in m.faces:
        ring = [v for k, v in enumerate(f) if k < 3 or v != f[2]]
        for a, b in zip(ring, ring[1:] + ring[:1]):
            edges[(a, b)] = edges.get((a, b), 0) + 1
    z = m.vertices[:, 2]
    for (a, b), count in edges.items():
        assert count == 1
        if not (z[a] == 0.0 and z[b] == 0.0):
            assert (b, a) in edges


def test_quarter_and_mirrors():
    v, f = CTV.quarter_panels(8, 4)
    assert np.all(v[:, 0] >= 0) and np.all(v[:, 1] > 0)
    assert f.shape == (2 * 8 * 4, 4)
    v2, f2 = mirror_panels(v, f, axis=1)
    assert mesh_volume(v2, f2) == pytest.approx(2 * mesh_volume(v, f), rel=1e-12)
    full = CTV.mesh(PanelCounts(8, 4, 1))
    assert full.n_panels == 4 * f.shape[0]
    mirrored = full.vertices * np.array([-1.0, -1.0, 1.0])
    assert {tuple(np.round(p, 9)) for p in mirrored} == {tuple(np.round(p, 9)) for p in full.vertices}


def test_panel_counts_respect_the_size():
    for h in (0.3, 0.5, 1.0):
        counts = CTV.panel_counts(h)
        assert CTV.max_panel_size(counts) <= h
    assert CTV.panel_counts(0.5).n_half_length > CTV.panel_counts(1.0).n_half_length


def test_merge_vertices_drops_degenerate_faces():
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 0], [0, 0, 0.0]])
    vv, ff = merge_vertices(v, np.array([[0, 1, 2, 3], [0, 4, 1, 1]]))
    assert len(vv) == 3 and ff.tolist() == [[0, 1, 2, 2]]
