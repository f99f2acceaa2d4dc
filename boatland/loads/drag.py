r"""Drag of a steady flow on the hull: the force law shared by current (water) and wind (air).

A flow of velocity :math:`w` relative to the vessel (horizontal, body axes :math:`w_x, w_y`; moving
*towards* the angle :math:`\theta = \operatorname{atan2}(w_y, w_x)` from the bow, the convention of the
sea's ``relative_direction_deg``: 180° onto the bow, 90° towards port) loads the hull with

.. math::
    F_x = \tfrac12\rho\,|w|^2 A_x\,C_X(\theta), \qquad
    F_y = \tfrac12\rho\,|w|^2 A_y\,C_Y(\theta), \qquad
    N_z = \tfrac12\rho\,|w|^2 A_y L\,C_N(\theta),

in body axes, the forces acting at the centroid :math:`r_c` of the projected area (so that they also
heel and trim the vessel and turn it by their lever), :math:`N_z` an extra yaw moment. This is the
coefficient form of OCIMF (1994), *Prediction of Wind and Current Loads on VLCCs*, 2nd ed., and of
Fossen (2011), *Handbook of Marine Craft Hydrodynamics and Motion Control*, Wiley, ch. 10
(environmental forces: wind and current coefficients per angle of attack), with A_x the frontal and
A_y the lateral projected area and L the length.

The coefficients are tables over the angle (:class:`DragTable`), interpolated linearly and periodically;
two families of defaults are provided, each with a stated source:

- :func:`crossflow_table` — the cross-flow principle (Faltinsen 1990, *Sea Loads on Ships and Offshore
  Structures*, Cambridge, §6.4 "Current forces": each component of the flow loads the hull by its own
  square): :math:`C_X = c_x \cos\theta|\cos\theta|`, :math:`C_Y = c_y \sin\theta|\sin\theta|`;
- :func:`linear_table` — Fossen's (2011) wind coefficients for a vessel at rest:
  :math:`C_X = c_x\cos\theta`, :math:`C_Y = c_y\sin\theta` (written for the direction the air moves
  towards, so that the force points down-wind).

:func:`silhouette` measures the projected areas and their centroids of a panel mesh (the wetted hull for
current, the topsides for wind). :func:`add_drag` is the kernel's evaluation at one RK4 stage: the
relative velocity includes the hull's own motion at the centroid (:math:`w = U - \dot x - \omega\times
R r_c`), the forces rotate with the hull.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from boatland.rigid import angular_velocity, euler_moment
from boatland.tomlspec import Key, Table, Vector

__all__ = ["DragTable", "DragLoad", "add_drag", "crossflow_table", "drag_keys", "geometry_from", "global_direction",
           "linear_table", "silhouette", "table_from"]

#: Angular resolution of the default tables [deg].
TABLE_STEP_DEG = 5.0


@dataclass(frozen=True, eq=False)
class DragTable:
    """Coefficients C_X, C_Y, C_N per angle θ of the relative flow (direction it moves towards, from the bow).

    Attributes
    ----------
    angles_deg : ndarray, shape (n,)
        Angles [deg], increasing, spanning [0, 360] (the last equal to the first plus 360).
    cx, cy, cn : ndarray, shape (n,)
        Coefficients at those angles (periodic: the first and last rows are equal).
    source : str
        Where they come from (a citation, or "given in <file>").
    """

    angles_deg: np.ndarray
    cx: np.ndarray
    cy: np.ndarray
    cn: np.ndarray
    source: str = ""

    def __post_init__(self):
        a = np.asarray(self.angles_deg, dtype=float)
        rows = [np.asarray(c, dtype=float) for c in (self.cx, self.cy, self.cn)]
        if a.ndim != 1 or a.size < 2 or any(r.shape != a.shape for r in rows):
            raise ValueError(f"angles_deg, cx, cy, cn must be 1-D of one length, got {a.shape} and "
                             f"{[r.shape for r in rows]}")
        if not (np.all(np.isfinite(a)) and all(np.all(np.isfinite(r)) for r in rows)):
            raise ValueError("angles_deg, cx, cy, cn must be finite")
        if np.any(np.diff(a) <= 0) or a[0] != 0.0 or a[-1] != 360.0:
            raise ValueError(f"angles_deg must increase from 0 to 360 (periodic), got {a[0]:g} … {a[-1]:g}")
        if any(r[0] != r[-1] for r in rows):
            raise ValueError("the coefficients at 0° and 360° must be equal (periodic)")
        object.__setattr__(self, "angles_deg", a)
        object.__setattr__(self, "cx", rows[0])
        object.__setattr__(self, "cy", rows[1])
        object.__setattr__(self, "cn", rows[2])

    @classmethod
    def from_half(cls, angles_deg, cx, cy, cn, source: str = "") -> "DragTable":
        """A port–starboard symmetric table from 0…180° (C_X even, C_Y and C_N odd in θ)."""
        a = np.asarray(angles_deg, dtype=float)
        cx, cy, cn = (np.asarray(c, dtype=float) for c in (cx, cy, cn))
        if a.ndim != 1 or a[0] != 0.0 or a[-1] != 180.0 or np.any(np.diff(a) <= 0):
            raise ValueError(f"angles_deg must increase from 0 to 180, got {a}")
        if cy.shape != a.shape or cx.shape != a.shape or cn.shape != a.shape:
            raise ValueError("angles_deg, cx, cy, cn must be of one length")
        full = np.concatenate([a, 360.0 - a[-2::-1]])
        return cls(full, np.concatenate([cx, cx[-2::-1]]), np.concatenate([cy, -cy[-2::-1]]),
                   np.concatenate([cn, -cn[-2::-1]]), source)

    def at(self, theta_deg) -> np.ndarray:
        """(C_X, C_Y, C_N) at angles [deg] (linear, periodic), shape (3, ...)."""
        t = np.mod(np.asarray(theta_deg, dtype=float), 360.0)
        return np.array([np.interp(t, self.angles_deg, c) for c in (self.cx, self.cy, self.cn)])

    def kernel_table(self) -> np.ndarray:
        """(4, n): angles [rad] and C_X, C_Y, C_N, for :func:`add_drag`."""
        return np.ascontiguousarray(np.stack([np.radians(self.angles_deg), self.cx, self.cy, self.cn]))


def crossflow_table(c_x: float, c_y: float, c_n: float = 0.0, *, source: str,
                    step_deg: float = TABLE_STEP_DEG) -> DragTable:
    r"""Cross-flow coefficients (Faltinsen 1990 §6.4): :math:`C_X = c_x\cos\theta|\cos\theta|`,
    :math:`C_Y = c_y\sin\theta|\sin\theta|`, :math:`C_N = -c_n\sin 2\theta` (a Munk-type moment turning
    the vessel broadside, Newman 1977 §4.13, when c_n > 0)."""
    a = np.arange(0.0, 360.0 + step_deg / 2, step_deg)
    t = np.radians(a)
    c, s = _exact(np.cos(t)), _exact(np.sin(t))
    return DragTable(a, c_x * c * np.abs(c), c_y * s * np.abs(s), -c_n * _exact(np.sin(2 * t)), source)


def linear_table(c_x: float, c_y: float, c_n: float = 0.0, *, source: str,
                 step_deg: float = TABLE_STEP_DEG) -> DragTable:
    r"""Fossen's (2011) wind coefficients of a vessel at rest, for the direction the air moves towards:
    :math:`C_X = c_x\cos\theta`, :math:`C_Y = c_y\sin\theta`, :math:`C_N = -c_n\sin 2\theta`."""
    a = np.arange(0.0, 360.0 + step_deg / 2, step_deg)
    t = np.radians(a)
    return DragTable(a, c_x * _exact(np.cos(t)), c_y * _exact(np.sin(t)), -c_n * _exact(np.sin(2 * t)), source)


def _exact(v: np.ndarray) -> np.ndarray:
    """cos/sin values with the 1e-16 residues at multiples of 90° set to 0 (and the ends periodic)."""
    v = np.where(np.abs(v) < 1e-12, 0.0, v)
    v[-1] = v[0]
    return v


#: Strips of the hull along x that the drag is evaluated on (each with its own relative velocity): the
#: hull's yaw rate loads the bow and stern in opposite directions, so the drag damps a swing about the bow
#: as a strip integral (Faltinsen 1990 §6.4) does, not as a single point at the centroid would.
STRIPS = 8
#: Forms of the coefficients (:class:`DragLoad`).
FORMS = ("crossflow", "table")


@dataclass(frozen=True, eq=False)
class DragLoad:
    r"""One flow's load on the vessel: density, areas, length, the strips it acts on and its coefficients.

    The load of a relative flow :math:`w_i` at strip i (body axes) is the module docstring's law on the
    strip's share :math:`s_i` of the areas, acting at the strip's centroid :math:`(x_i, y_c, z_i)`:

    - ``form = "crossflow"``: :math:`F_{x,i} = \tfrac12\rho A_x s_i c_x w_x|w_x|`,
      :math:`F_{y,i} = \tfrac12\rho A_y s_i c_y w_y|w_y|`, :math:`N_i = -\rho A_y L s_i c_n w_x w_y`
      (:func:`crossflow_table` written without the angle);
    - ``form = "table"``: the coefficients of ``table`` at the strip's angle of the flow.

    In a uniform flow both are the law of the module docstring at the centroid of the lateral area.

    Attributes
    ----------
    rho : float
        Fluid density [kg/m³].
    area_x, area_y : float
        Frontal and lateral projected areas A_x, A_y [m²].
    length : float
        Reference length L of the yaw coefficient [m].
    centroid : ndarray, shape (3,)
        Centroid of the lateral area, body frame [m] (the strips' area-weighted mean).
    table : DragTable
        The coefficients per angle (for ``crossflow`` the table of c_x, c_y, c_n, for the record).
    strips : ndarray, shape (n, 3)
        Each strip's x, z [m] and share of the areas (summing to 1).
    form : str
        "crossflow" or "table".
    coefficients : tuple of float
        (c_x, c_y, c_n) of the cross-flow form.
    """

    rho: float
    area_x: float
    area_y: float
    length: float
    centroid: np.ndarray
    table: DragTable
    strips: np.ndarray = None
    form: str = "table"
    coefficients: tuple = (0.0, 0.0, 0.0)

    def __post_init__(self):
        c = np.asarray(self.centroid, dtype=float).reshape(3)
        object.__setattr__(self, "centroid", c)
        st = np.array([[c[0], c[2], 1.0]]) if self.strips is None else np.asarray(self.strips, dtype=float)
        if st.ndim != 2 or st.shape[1] != 3 or abs(st[:, 2].sum() - 1.0) > 1e-9 or np.any(st[:, 2] < 0):
            raise ValueError("strips must be (n, 3) rows of x, z and a share ≥ 0, the shares summing to 1")
        object.__setattr__(self, "strips", st)
        if self.form not in FORMS:
            raise ValueError(f"form must be one of {FORMS}, got {self.form!r}")

    def body_load(self, w_body) -> np.ndarray:
        r"""Generalised force (6,) about the reference point, body axes, of a uniform relative flow
        ``w_body`` (w_x, w_y) [m/s] (the hull at rest)."""
        F = np.zeros(6)
        tab, par = self.kernel()
        add_drag(np.eye(3), np.zeros(6), np.array([float(w_body[0]), float(w_body[1]), 0.0]), 1.0, tab, par,
                 self.strips, F)
        return F

    def kernel(self) -> tuple[np.ndarray, np.ndarray]:
        """(table (4, n), par (8,)): the arrays of :func:`add_drag` — par = (form: 0 crossflow / 1 table,
        ½ρA_x, ½ρA_y, ½ρA_yL, c_x, c_y, c_n, y_c); the strips are :attr:`strips`."""
        h = 0.5 * self.rho
        par = np.array([0.0 if self.form == "crossflow" else 1.0, h * self.area_x, h * self.area_y,
                        h * self.area_y * self.length, *self.coefficients, self.centroid[1]])
        return self.table.kernel_table(), par


@njit(cache=True, _nrt=False, forceinline=True)
def _interp_periodic(tab, row, a):
    """Linear interpolation of ``tab[row]`` at angle ``a`` ∈ [0, 2π] on the angles ``tab[0]`` (a search:
    the tables are short)."""
    n = tab.shape[1]
    k = 0
    while k < n - 2 and tab[0, k + 1] <= a:
        k += 1
    a0, a1 = tab[0, k], tab[0, k + 1]
    s = (a - a0) / (a1 - a0)
    return tab[row, k] + s * (tab[row, k + 1] - tab[row, k])


@njit(cache=True, _nrt=False, forceinline=True)
def add_drag(R, v, U, s, tab, par, strips, F):
    r"""Add to ``F`` (6, local frame) the drag load of a flow ``s U`` (``U`` (3,): its local-frame velocity,
    only x, y used; ``s`` a factor, e.g. its start-up ramp) on the hull moving with ``v`` (6) and rotated by
    ``R``, at one RK4 stage, strip by strip (:class:`DragLoad`).

    At strip i, body point :math:`r_i = (x_i, y_c, z_i)`, :math:`p = R r_i`: the relative velocity
    :math:`w = sU - (\dot x_{1:3} + \omega\times p)` (horizontal part), its body components
    :math:`R^\top w`; the strip's body forces rotate back with R and act at p, its yaw moment about the body
    z axis.
    """
    yc = par[7]
    table = par[0] != 0.0
    ox, oy, oz, _, _, _ = angular_velocity(R, v)
    Fx = Fy = Fz = Mx = My = Mz = 0.0
    for i in range(strips.shape[0]):
        sh = strips[i, 2]
        if sh == 0.0:
            continue
        xb, zb = strips[i, 0], strips[i, 1]
        rx = R[0, 0] * xb + R[0, 1] * yc + R[0, 2] * zb
        ry = R[1, 0] * xb + R[1, 1] * yc + R[1, 2] * zb
        rz = R[2, 0] * xb + R[2, 1] * yc + R[2, 2] * zb
        wx = s * U[0] - (v[0] + oy * rz - oz * ry)
        wy = s * U[1] - (v[1] + oz * rx - ox * rz)
        bx = R[0, 0] * wx + R[1, 0] * wy
        by = R[0, 1] * wx + R[1, 1] * wy
        if table:
            q = bx * bx + by * by
            if q == 0.0:
                continue
            a = np.arctan2(by, bx)
            if a < 0.0:
                a += 2.0 * np.pi
            fx = sh * par[1] * q * _interp_periodic(tab, 1, a)
            fy = sh * par[2] * q * _interp_periodic(tab, 2, a)
            nz = sh * par[3] * q * _interp_periodic(tab, 3, a)
        else:
            fx = sh * par[1] * par[4] * bx * abs(bx)
            fy = sh * par[2] * par[5] * by * abs(by)
            nz = -2.0 * sh * par[3] * par[6] * bx * by
        # body (fx, fy, 0) in the local frame, at p, and the yaw moment about the body z axis
        gx = fx * R[0, 0] + fy * R[0, 1]
        gy = fx * R[1, 0] + fy * R[1, 1]
        gz = fx * R[2, 0] + fy * R[2, 1]
        Fx += gx
        Fy += gy
        Fz += gz
        Mx += ry * gz - rz * gy + R[0, 2] * nz
        My += rz * gx - rx * gz + R[1, 2] * nz
        Mz += rx * gy - ry * gx + R[2, 2] * nz
    # the strips' moments summed in the local frame, then about the Euler axes once (the projection is linear)
    F[0] += Fx
    F[1] += Fy
    F[2] += Fz
    q4, q5, q6 = euler_moment(R, Mx, My, Mz)
    F[3] += q4
    F[4] += q5
    F[5] += q6


def silhouette(vertices, faces, normal_axis: int, *, cell: float = 0.05, z_max: float | None = None,
               z_min: float | None = None, strips: int = 0):
    """Projected area [m²] of a panel mesh on the plane normal to body axis ``normal_axis`` (0: frontal,
    the y–z plane; 1: lateral, the x–z plane), and the centroid of that area (3,) in the body frame
    (the coordinate along the axis: the area-weighted mean of the panels facing it). With ``strips`` > 0
    (lateral only) also the area split into that many strips of equal length along x: (strips, 3) rows of
    (x, z, area) — each strip's centroid and area.

    The union of the projected panels, rasterised on square cells of ``cell`` [m] (the area converges as
    the cell shrinks; 5 cm measures a 27 m CTV's areas to well under 1 %); ``z_min``/``z_max`` clip the
    projection (e.g. above the waterline only).
    """
    V = np.asarray(vertices, dtype=float)
    Fc = np.asarray(faces, dtype=np.int64)
    axes = [a for a in range(3) if a != normal_axis]          # the plane's axes: (y, z) or (x, z)
    P = V[:, axes]
    lo = P.min(axis=0)
    hi = P.max(axis=0)
    if z_min is not None:
        lo[1] = max(lo[1], z_min)
    if z_max is not None:
        hi[1] = min(hi[1], z_max)
    if not np.all(hi > lo):
        return (0.0, np.zeros(3), np.zeros((strips, 3))) if strips else (0.0, np.zeros(3))
    nu = int(np.ceil((hi[0] - lo[0]) / cell))
    nv = int(np.ceil((hi[1] - lo[1]) / cell))
    uc = lo[0] + (np.arange(nu) + 0.5) * cell
    vc = lo[1] + (np.arange(nv) + 0.5) * cell
    filled = np.zeros((nu, nv), dtype=bool)
    for quad in Fc:
        for tri in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
            a, b, c = P[tri[0]], P[tri[1]], P[tri[2]]
            det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
            if abs(det) < 1e-14:
                continue
            i0 = max(int(np.searchsorted(uc, min(a[0], b[0], c[0]))), 0)
            i1 = int(np.searchsorted(uc, max(a[0], b[0], c[0]), side="right"))
            j0 = max(int(np.searchsorted(vc, min(a[1], b[1], c[1]))), 0)
            j1 = int(np.searchsorted(vc, max(a[1], b[1], c[1]), side="right"))
            if i1 <= i0 or j1 <= j0:
                continue
            U, W = np.meshgrid(uc[i0:i1], vc[j0:j1], indexing="ij")
            l1 = ((b[0] - U) * (c[1] - W) - (c[0] - U) * (b[1] - W)) / det
            l2 = ((c[0] - U) * (a[1] - W) - (a[0] - U) * (c[1] - W)) / det
            inside = (l1 >= -1e-12) & (l2 >= -1e-12) & (1.0 - l1 - l2 >= -1e-12)
            filled[i0:i1, j0:j1] |= inside
    area = float(filled.sum()) * cell * cell
    centroid = np.zeros(3)
    if area > 0:
        U, W = np.meshgrid(uc, vc, indexing="ij")
        centroid[axes[0]] = float(U[filled].mean())
        centroid[axes[1]] = float(W[filled].mean())
        # along the viewing axis: the mean of the panels' centres (where the flow meets the hull)
        centroid[normal_axis] = float(V[Fc].mean(axis=1)[:, normal_axis].mean())
    if not strips:
        return area, centroid
    U, W = np.meshgrid(uc, vc, indexing="ij")
    edges = np.linspace(lo[0], hi[0], strips + 1)
    rows = np.zeros((strips, 3))
    for i in range(strips):
        sel = filled & (U >= edges[i]) & (U < edges[i + 1] if i < strips - 1 else U <= edges[i + 1])
        n = int(sel.sum())
        rows[i] = (U[sel].mean(), W[sel].mean(), n * cell * cell) if n else (0.5 * (edges[i] + edges[i + 1]), 0.0, 0.0)
    return area, centroid, rows


def drag_keys(what: str, defaults: dict) -> dict:
    """The scenario keys of one flow's load on the hull (``what``: "current", "wind"): the areas, length,
    centroid and coefficients that override the defaults derived from the vessel (``defaults``: the
    default coefficients c_x, c_y, c_n, quoted in the docs)."""
    return {
        "area_x": Key(float, gt=0.0, doc=f"frontal projected area A_x of the {what}'s load [m²] (default: measured "
                                         "on the vessel's mesh)"),
        "area_y": Key(float, gt=0.0, doc="lateral projected area A_y [m²] (default: measured on the vessel's mesh)"),
        "length": Key(float, gt=0.0, doc="reference length L of the yaw coefficient [m] (default: the mesh's length)"),
        "centroid": Vector(size=3, names=("x", "y", "z"), doc="where the forces act, body frame [m] (default: the "
                                                              "centroid of the lateral area)"),
        "c_x": Key(float, doc=f"C_X at 0° (default {defaults['c_x']:g}; the shape: module boatland.loads.{what})"),
        "c_y": Key(float, doc=f"C_Y at 90° (default {defaults['c_y']:g})"),
        "c_n": Key(float, doc=f"yaw coefficient amplitude (default {defaults['c_n']:g})"),
        "table": Table({
            "angles_deg": Vector(min_size=2, required=True, ge=0.0, le=360.0,
                                 doc="angles of the relative flow, direction towards, from the bow [deg]: 0 … 180 "
                                     "(port–starboard symmetric) or 0 … 360"),
            "cx": Vector(min_size=2, required=True, doc="C_X at the angles"),
            "cy": Vector(min_size=2, required=True, doc="C_Y at the angles"),
            "cn": Vector(min_size=2, required=True, doc="C_N at the angles"),
        }, optional=True, doc="coefficients per angle (replace c_x, c_y, c_n), e.g. a model test's"),
    }


def global_direction(values: dict, heading_deg: float) -> float:
    """The global direction [deg, 0 … 360) a flow moves towards, from a validated ``[current]``/``[wind]`` table:
    its ``direction_deg``, else the vessel's heading plus its ``relative_direction_deg`` (the loader requires
    one of them)."""
    d = values["direction_deg"] if "direction_deg" in values else heading_deg + values["relative_direction_deg"]
    return float(d) % 360.0


def table_from(values: dict, shape, defaults: dict, source: str) -> dict:
    """The coefficients of a validated ``[current]``/``[wind]`` table as :class:`DragLoad` fields (``table``,
    ``form``, ``coefficients``): its ``table`` if given (form "table"), else ``shape(c_x, c_y, c_n)`` with the
    given or default amplitudes (form "crossflow" for :func:`crossflow_table`, written without the angle in
    the kernel).

    Raises
    ------
    ValueError
        A table :class:`DragTable` refuses (the scenario loader names the key before it gets here).
    """
    t = values.get("table")
    if t is not None:
        a = np.asarray(t["angles_deg"], dtype=float)
        if a[-1] == 180.0:
            tab = DragTable.from_half(a, t["cx"], t["cy"], t["cn"], source=f"{source}: table")
        else:
            tab = DragTable(a, t["cx"], t["cy"], t["cn"], source=f"{source}: table")
        return {"table": tab, "form": "table"}
    c = tuple(float(values.get(k, defaults[k])) for k in ("c_x", "c_y", "c_n"))
    given = any(k in values for k in ("c_x", "c_y", "c_n"))
    tab = shape(*c, source=source if given else defaults["source"])
    if shape is crossflow_table:
        return {"table": tab, "form": "crossflow", "coefficients": c}
    return {"table": tab, "form": "table"}


def geometry_from(values: dict, vertices, faces, *, what: str, per_hull: bool, z_min=None, z_max=None) -> dict:
    """Areas, length, centroid and strips of a load (:class:`DragLoad` fields): the given values, the rest
    measured on a mesh by :func:`silhouette` (``per_hull``: the two demihulls' silhouettes added — no shielding
    of the down-stream hull, which overestimates a catamaran's lateral load a little). Without a mesh, one
    strip at the given centroid.

    Raises
    ------
    ValueError
        No mesh to measure and a value missing (names the keys to give).
    """
    need = [k for k in ("area_x", "area_y", "length") if k not in values]
    out = {k: values[k] for k in ("area_x", "area_y", "length") if k in values}
    given_c = np.asarray(values["centroid"], dtype=float) if "centroid" in values else None
    if (need or given_c is None) and vertices is None:
        missing = need + (["centroid"] if given_c is None else [])
        raise ValueError(f"the vessel's database has no {'hull mesh' if what == 'current' else 'topsides mesh'} to "
                         f"measure the {what}'s areas on: give {', '.join(f'{what}.{k}' for k in missing)}")
    if vertices is None:
        return {**out, "centroid": given_c, "strips": np.array([[given_c[0], given_c[2], 1.0]])}
    V, Fc = np.asarray(vertices, dtype=float), np.asarray(faces, dtype=np.int64)
    groups = [Fc]
    if per_hull:
        cy = V[Fc].mean(axis=1)[:, 1]
        groups = [g for g in (Fc[cy > 0], Fc[cy < 0]) if len(g)]
    lat = [silhouette(V, g, 1, z_min=z_min, z_max=z_max, strips=STRIPS) for g in groups]
    front = [silhouette(V, g, 0, z_min=z_min, z_max=z_max) for g in groups]
    A_y = sum(a for a, _, _ in lat)
    rows = sum(r[:, 2:3] * np.c_[r[:, :2], np.ones(len(r))] for _, _, r in lat)   # area-weighted x, z; area
    area = rows[:, 2]
    strips = np.c_[rows[:, 0] / np.where(area > 0, area, 1.0), rows[:, 1] / np.where(area > 0, area, 1.0), area / A_y]
    out.setdefault("area_x", sum(a for a, _ in front))
    out.setdefault("area_y", A_y)
    out.setdefault("length", float(V[:, 0].max() - V[:, 0].min()))
    c = sum(a * r for a, r, _ in lat) / A_y
    if per_hull:
        c[1] = 0.0
    if given_c is not None:                 # a given centroid moves the strips with it
        strips[:, 0] += given_c[0] - c[0]
        strips[:, 1] += given_c[2] - c[2]
        c = given_c
    return {**out, "centroid": c, "strips": strips}
