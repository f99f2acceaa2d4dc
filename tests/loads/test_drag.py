"""The drag law of current and wind on the hull (boatland.loads.drag): silhouettes measured on meshes, the
load of a uniform flow by hand, the hull's own motion in the relative velocity, coefficient tables."""

import math

import numpy as np
import pytest

from boatland.loads.drag import DragLoad, DragTable, add_drag, crossflow_table, geometry_from, linear_table, silhouette
from boatland.rigid import rotation_matrix


def box(L=10.0, B=2.0, T=1.0, x0=0.0, y0=0.0):
    """A closed box mesh (quads), x in [x0 − L/2, x0 + L/2], y in [y0 − B/2, y0 + B/2], z in [−T, 0]."""
    xs, ys, zs = (x0 - L / 2, x0 + L / 2), (y0 - B / 2, y0 + B / 2), (-T, 0.0)
    V = np.array([[x, y, z] for x in xs for y in ys for z in zs])
    idx = lambda i, j, k: 4 * i + 2 * j + k  # noqa: E731
    F = [[idx(0, 0, 0), idx(0, 1, 0), idx(0, 1, 1), idx(0, 0, 1)], [idx(1, 0, 0), idx(1, 0, 1), idx(1, 1, 1), idx(1, 1, 0)],
         [idx(0, 0, 0), idx(0, 0, 1), idx(1, 0, 1), idx(1, 0, 0)], [idx(0, 1, 0), idx(1, 1, 0), idx(1, 1, 1), idx(0, 1, 1)],
         [idx(0, 0, 0), idx(1, 0, 0), idx(1, 1, 0), idx(0, 1, 0)], [idx(0, 0, 1), idx(0, 1, 1), idx(1, 1, 1), idx(1, 0, 1)]]
    return V, np.array(F)


def test_silhouette_of_a_box_is_its_side_and_its_front():
    V, F = box(10.0, 2.0, 1.0, x0=1.0)
    a, c = silhouette(V, F, 1)
    assert a == pytest.approx(10.0, rel=0.01) and c[0] == pytest.approx(1.0, abs=0.03) and c[2] == pytest.approx(-0.5, abs=0.03)
    a, c = silhouette(V, F, 0)
    assert a == pytest.approx(2.0, rel=0.01)
    a, c, strips = silhouette(V, F, 1, strips=4)
    assert strips[:, 2].sum() == pytest.approx(a) and np.allclose(strips[:, 2], a / 4, rtol=0.02)
    assert np.allclose(strips[:, 0], [-2.75, -0.25, 2.25, 4.75], atol=0.03)


def test_two_demihulls_add_their_silhouettes():
    V1, F1 = box(10.0, 2.0, 1.0, y0=3.0)
    V2, F2 = box(10.0, 2.0, 1.0, y0=-3.0)
    V, F = np.vstack([V1, V2]), np.vstack([F1, F2 + len(V1)])
    g = geometry_from({}, V, F, what="current", per_hull=True)
    assert g["area_y"] == pytest.approx(20.0, rel=0.01) and g["area_x"] == pytest.approx(4.0, rel=0.01)
    assert g["centroid"][1] == 0.0 and g["strips"][:, 2].sum() == pytest.approx(1.0)
    with pytest.raises(ValueError, match="give current.area_x, current.area_y, current.length, current.centroid"):
        geometry_from({}, None, None, what="current", per_hull=True)


@pytest.mark.parametrize("theta", [0.0, 30.0, 90.0, 135.0, 180.0, 270.0])
def test_uniform_flow_by_hand(theta):
    rho, Ax, Ay, L, U = 1025.0, 5.0, 60.0, 25.0, 1.3
    c = np.array([-1.5, 0.0, -0.8])
    strips = np.array([[-8.0, -0.7, 0.3], [0.0, -0.8, 0.4], [6.5, -0.9, 0.3]])
    strips[:, 0] += c[0] - strips[:, 0] @ strips[:, 2]
    strips[:, 1] += c[2] - strips[:, 1] @ strips[:, 2]
    load = DragLoad(rho, Ax, Ay, L, c, crossflow_table(0.05, 1.0, 0.1, source="t"), strips, "crossflow", (0.05, 1.0, 0.1))
    t = math.radians(theta)
    F = load.body_load((U * math.cos(t), U * math.sin(t)))
    ct, st = math.cos(t), math.sin(t)
    fx = 0.5 * rho * Ax * 0.05 * U * U * ct * abs(ct)
    fy = 0.5 * rho * Ay * 1.0 * U * U * st * abs(st)
    nz = -0.5 * rho * Ay * L * 0.1 * U * U * math.sin(2 * t)
    assert F[0] == pytest.approx(fx, abs=1e-9 * rho * Ay) and F[1] == pytest.approx(fy, abs=1e-9 * rho * Ay)
    assert F[2] == 0.0
    M = np.cross(c, [fx, fy, 0.0])
    assert np.allclose(F[3:], M + [0.0, 0.0, nz], atol=1e-6 * rho * Ay * L)
    # the same law as a table (linear in the angle between 5° points): close, not equal
    tab = DragLoad(rho, Ax, Ay, L, c, crossflow_table(0.05, 1.0, 0.1, source="t"), strips, "table")
    assert np.allclose(tab.body_load((U * ct, U * st)), F, rtol=0.02, atol=1e-3 * rho * Ay)


def test_a_hull_moving_with_the_flow_feels_nothing_and_against_it_twice_the_speed():
    load = DragLoad(1025.0, 5.0, 60.0, 25.0, np.zeros(3), crossflow_table(0.05, 1.0, source="t"), None, "crossflow",
                    (0.05, 1.0, 0.0))
    tab, par = load.kernel()
    U = np.array([0.0, 0.8, 0.0])
    F = np.zeros(6)
    add_drag(np.eye(3), np.array([0.0, 0.8, 0.0, 0.0, 0.0, 0.0]), U, 1.0, tab, par, load.strips, F)
    assert np.all(F == 0.0)
    F1, F2 = np.zeros(6), np.zeros(6)
    add_drag(np.eye(3), np.zeros(6), U, 1.0, tab, par, load.strips, F1)
    add_drag(np.eye(3), np.array([0.0, -0.8, 0.0, 0.0, 0.0, 0.0]), U, 1.0, tab, par, load.strips, F2)
    assert F2[1] == pytest.approx(4 * F1[1])
    # yawing the hull by 90° turns a beam flow into a flow along it: the force is the longitudinal law
    F3 = np.zeros(6)
    add_drag(rotation_matrix(0.0, 0.0, math.pi / 2), np.zeros(6), U, 1.0, tab, par, load.strips, F3)
    assert F3[1] == pytest.approx(0.5 * 1025.0 * 5.0 * 0.05 * 0.64, rel=1e-9) and abs(F3[0]) < 1e-9


def test_tables_are_periodic_and_symmetric():
    t = DragTable.from_half([0.0, 90.0, 180.0], [-0.6, 0.0, 0.7], [0.0, 0.9, 0.0], [0.0, 0.1, 0.0])
    cx, cy, cn = t.at([45.0, 270.0, 360.0 + 90.0, -90.0])
    assert cx[0] == pytest.approx(-0.3) and cy[1] == pytest.approx(-0.9) and cy[2] == pytest.approx(0.9)
    assert cy[3] == pytest.approx(-0.9) and cn[1] == pytest.approx(-0.1)
    with pytest.raises(ValueError, match="periodic"):
        DragTable([0.0, 180.0, 360.0], [1.0, 0.0, 0.5], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    lin = linear_table(0.7, 0.825, source="t")
    assert lin.at(180.0)[0] == pytest.approx(-0.7) and lin.at(90.0)[1] == pytest.approx(0.825)
