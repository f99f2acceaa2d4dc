r"""Parametric catamaran hull: two generalized Wigley demihulls, closed-form offsets and panels.

Each demihull (centreline at :math:`y = \pm s/2`) has the half-breadth

.. math:: \eta(x, z) = \frac{b}{2}\left(1 - \left|\frac{2x}{L}\right|^p\right)\left(1 - \left|\frac{z}{T}\right|^p\right),
          \qquad -\tfrac{L}{2} \le x \le \tfrac{L}{2},\; -T \le z \le 0,

so :math:`y = \pm s/2 \pm \eta`. ``p = 2`` is the classic Wigley hull (Wigley 1934; the ITTC
benchmark of Journée 1992). Because both factors integrate to ``p/(p+1)``, the block coefficient is

.. math:: C_b = \frac{\nabla_{demihull}}{L b T} = \left(\frac{p}{p+1}\right)^2 ,
          \qquad p = \frac{\sqrt{C_b}}{1 - \sqrt{C_b}},

and every hydrostatic quantity has a closed form (:class:`WigleyCatamaran`), which the tests use to
check the panel meshes and the builder uses to check Capytaine.

Frame: the body frame of :mod:`boatland.conventions` with its origin at midship, on the centreline
between the demihulls, in the calm waterline (x forward, y to port, z up).

Panels
------
The hull is fore–aft and port–starboard symmetric, so the BEM needs only a *quarter*: the part
``x ≥ 0`` of the port demihull (both its sides). Stations are clustered towards the bow (and, by
the mirror, the stern) and waterlines towards the free surface, with the blended cosine map
:func:`clustered` (end panels about 2.6 times smaller than the largest ones), where the hull
curvature and the wave pressure gradients are largest. Waterline levels are spaced along the girth
of the midship section (not along z), so bottom panels are not stretched. Faces are
quadrilaterals ``[a, b, c, d]`` counter-clockwise seen from the water (normal out of the hull); a
triangle repeats its last vertex (the :class:`~boatland.vessel.database.HullMesh` convention).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from boatland.vessel.database import HullMesh

__all__ = [
    "CB_RANGE",
    "PanelCounts",
    "WigleyCatamaran",
    "clustered",
    "exponent_for_block_coefficient",
    "mesh_volume",
    "mirror_panels",
    "merge_vertices",
    "panel_normals_areas",
]

#: Block coefficients the generalized Wigley form represents sensibly: p from 1.45 (fine, V-shaped
#: ends and sections) to 11.8 (almost a box). Outside it the "demihull" is no longer a ship hull.
CB_RANGE = (0.35, 0.85)

#: Weight of the sine part in :func:`clustered` (0 = uniform, 1 = full half-cosine).
CLUSTERING = 0.5


def exponent_for_block_coefficient(cb: float) -> float:
    """Exponent p of the generalized Wigley form with block coefficient ``cb = (p/(p+1))²``."""
    if not 0.0 < cb < 1.0:
        raise ValueError(f"block coefficient must be in (0, 1), got {cb!r}")
    s = math.sqrt(cb)
    return s / (1.0 - s)


def clustered(n: int, alpha: float = CLUSTERING) -> np.ndarray:
    r"""``n + 1`` points on [0, 1], denser towards 1: :math:`u(t) = (1-\alpha)t + \alpha\sin(\pi t/2)`.

    The spacing near ``u = 1`` is :math:`(1-\alpha)/(1-\alpha+\alpha\pi/2)` of the spacing near 0
    (0.39 for α = 0.5). End points are exact.
    """
    t = np.linspace(0.0, 1.0, n + 1)
    u = (1.0 - alpha) * t + alpha * np.sin(0.5 * np.pi * t)
    u[0], u[-1] = 0.0, 1.0
    return u


#: Largest spacing of :func:`clustered` relative to the uniform spacing 1/n.
MAX_SPACING_FACTOR = (1.0 - CLUSTERING) + CLUSTERING * np.pi / 2


class PanelCounts(NamedTuple):
    """Panel counts of the quarter mesh.

    Attributes
    ----------
    n_half_length : int
        Panels along half a demihull (midship to bow); the full length has twice as many.
    n_girth : int
        Panels from keel to waterline on one side of a demihull.
    n_lid : int
        Lid panels across a demihull's waterplane.
    """

    n_half_length: int
    n_girth: int
    n_lid: int


@dataclass(frozen=True)
class WigleyCatamaran:
    """Two identical generalized Wigley demihulls side by side.

    Parameters
    ----------
    length : float
        Waterline length L of each demihull [m].
    demihull_beam : float
        Waterline beam b of each demihull [m].
    draft : float
        Draft T [m].
    separation : float
        Distance s between the demihull centrelines [m]; must exceed ``demihull_beam``.
    p : float
        Exponent of the form (2 = classic Wigley). See :func:`exponent_for_block_coefficient`.
    """

    length: float
    demihull_beam: float
    draft: float
    separation: float
    p: float = 2.0

    def __post_init__(self):
        for name in ("length", "demihull_beam", "draft", "separation", "p"):
            v = float(getattr(self, name))
            if not (math.isfinite(v) and v > 0):
                raise ValueError(f"{name} must be a finite number > 0, got {v!r}")
            object.__setattr__(self, name, v)
        if self.separation <= self.demihull_beam:
            raise ValueError(f"separation {self.separation} m must exceed the demihull beam "
                             f"{self.demihull_beam} m (the demihulls would overlap)")

    @classmethod
    def from_block_coefficient(cls, length: float, demihull_beam: float, draft: float,
                               separation: float, block_coefficient: float) -> "WigleyCatamaran":
        """The catamaran whose demihulls have block coefficient ``block_coefficient``."""
        return cls(length, demihull_beam, draft, separation, exponent_for_block_coefficient(block_coefficient))

    # ------------------------------------------------------------------ offsets
    def half_breadth(self, x, z) -> np.ndarray:
        """Half-breadth η(x, z) of a demihull about its own centreline [m] (0 outside the hull)."""
        x = np.asarray(x, dtype=float)
        z = np.asarray(z, dtype=float)
        fx = 1.0 - np.abs(2.0 * x / self.length) ** self.p
        fz = 1.0 - np.abs(z / self.draft) ** self.p
        return 0.5 * self.demihull_beam * np.clip(fx, 0.0, None) * np.clip(fz, 0.0, None)

    # ------------------------------------------------------------------ closed-form hydrostatics
    @property
    def _f1(self) -> float:  # ∫_0^1 (1 - u^p) du
        return self.p / (self.p + 1.0)

    @property
    def block_coefficient(self) -> float:
        """Block coefficient of a demihull, (p/(p+1))²."""
        return self._f1 ** 2

    @property
    def overall_beam(self) -> float:
        """Waterline breadth over both demihulls, s + b [m]."""
        return self.separation + self.demihull_beam

    @property
    def volume(self) -> float:
        """Displaced volume of both demihulls, 2 C_b L b T [m³]."""
        return 2.0 * self.block_coefficient * self.length * self.demihull_beam * self.draft

    @property
    def waterplane_area(self) -> float:
        """Waterplane area of both demihulls, 2 L b p/(p+1) [m²]."""
        return 2.0 * self.length * self.demihull_beam * self._f1

    @property
    def centre_of_buoyancy(self) -> np.ndarray:
        """Centre of buoyancy (0, 0, −T (p+1)/(2(p+2))) [m] (−3T/8 for the classic Wigley)."""
        p = self.p
        return np.array([0.0, 0.0, -self.draft * (p + 1.0) / (2.0 * (p + 2.0))])

    @property
    def waterplane_inertia(self) -> tuple[float, float]:
        r"""Second moments of the waterplane area about the x and y axes, (I_T, I_L) [m⁴].

        .. math::
            I_T = 2\int \left[2\eta\,(s/2)^2 + \tfrac{2}{3}\eta^3\right] dx, \qquad
            I_L = 2\int 2\eta\, x^2\, dx, \qquad \eta = \eta(x, 0).
        """
        p, L, b, s = self.p, self.length, self.demihull_beam, self.separation
        int_eta = 0.5 * b * L * self._f1
        j3 = 1.0 - 3.0 / (p + 1.0) + 3.0 / (2.0 * p + 1.0) - 1.0 / (3.0 * p + 1.0)  # ∫_0^1 (1-u^p)^3 du
        int_eta3 = (0.5 * b) ** 3 * L * j3
        I_T = 2.0 * (2.0 * int_eta * (0.5 * s) ** 2 + (2.0 / 3.0) * int_eta3)
        I_L = 2.0 * 2.0 * 0.5 * b * (L ** 3 / 4.0) * (1.0 / 3.0 - 1.0 / (p + 3.0))
        return I_T, I_L

    def restoring(self, rho: float, g: float, mass: float, cog) -> np.ndarray:
        r"""Closed-form linear restoring matrix about the origin (hydrostatics + weight), 6×6.

        .. math::
            C_{33} = \rho g A_{wp}, \quad
            C_{44} = \rho g (I_T + \nabla z_B) - m g z_G, \quad
            C_{55} = \rho g (I_L + \nabla z_B) - m g z_G,

        plus the weight couplings :math:`C_{46} = -\rho g \nabla x_B + m g x_G` and
        :math:`C_{56} = -\rho g \nabla y_B + m g y_G` (as Capytaine and WAMIT report them). Waterplane
        moments vanish by symmetry.
        """
        xg, yg, zg = np.asarray(cog, dtype=float)
        V = self.volume
        xb, yb, zb = self.centre_of_buoyancy
        I_T, I_L = self.waterplane_inertia
        C = np.zeros((6, 6))
        C[2, 2] = rho * g * self.waterplane_area
        C[3, 3] = rho * g * (I_T + V * zb) - mass * g * zg
        C[4, 4] = rho * g * (I_L + V * zb) - mass * g * zg
        C[3, 5] = -rho * g * V * xb + mass * g * xg
        C[4, 5] = -rho * g * V * yb + mass * g * yg
        return C

    # ------------------------------------------------------------------ panel layout
    def midship_girth(self) -> float:
        """Arc length of one side of the midship section, keel to waterline [m]."""
        return float(self._girth_table()[1][-1])

    def _girth_table(self, n: int = 4001):
        z = -self.draft * (1.0 - np.linspace(0.0, 1.0, n))  # keel → waterline
        y = self.half_breadth(0.0, z)
        s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(y), np.diff(z)))])
        return z, s

    def stations(self, n_half_length: int) -> np.ndarray:
        """``n_half_length + 1`` stations from midship (x = 0) to the bow (x = L/2), bow-clustered."""
        return 0.5 * self.length * clustered(n_half_length)

    def waterlines(self, n_girth: int) -> np.ndarray:
        """``n_girth + 1`` levels from the keel (z = −T) to the waterline (z = 0), equal in midship
        girth after the free-surface clustering of :func:`clustered`."""
        z_tab, s_tab = self._girth_table()
        z = np.interp(clustered(n_girth) * s_tab[-1], s_tab, z_tab)
        z[0], z[-1] = -self.draft, 0.0
        return z

    def panel_counts(self, panel_size: float) -> PanelCounts:
        """Fewest panels whose largest edge along the length, the girth and the lid is ≤ ``panel_size``."""
        h = float(panel_size)
        if not h > 0:
            raise ValueError(f"panel_size must be > 0, got {panel_size!r}")
        n_half = max(2, math.ceil(MAX_SPACING_FACTOR * 0.5 * self.length / h))
        n_girth = max(2, math.ceil(MAX_SPACING_FACTOR * self.midship_girth() / h))
        n_lid = max(1, math.ceil(self.demihull_beam / h))
        return PanelCounts(n_half, n_girth, n_lid)

    def max_panel_size(self, counts: PanelCounts) -> float:
        """Largest panel edge of the quarter mesh with ``counts`` (hull and lid) [m]."""
        n_half, n_girth, n_lid = counts
        return max(MAX_SPACING_FACTOR * 0.5 * self.length / n_half,
                   MAX_SPACING_FACTOR * self.midship_girth() / n_girth,
                   self.demihull_beam / max(n_lid, 1))

    def quarter_panels(self, n_half_length: int, n_girth: int) -> tuple[np.ndarray, np.ndarray]:
        """Panels of the port demihull's forebody (x ≥ 0, y > 0, both sides of the demihull).

        Returns
        -------
        vertices : ndarray, shape (Nv, 3)
        faces : ndarray of int, shape (Np, 4)
            ``2 * n_half_length * n_girth`` quadrilaterals, normals out of the hull.
        """
        xs = self.stations(n_half_length)
        zs = self.waterlines(n_girth)
        X, Z = np.meshgrid(xs, zs, indexing="ij")
        eta = self.half_breadth(X, Z)
        nz1 = n_girth + 1
        verts, faces = [], []
        for side in (+1.0, -1.0):
            base = sum(len(v) for v in verts)
            verts.append(np.stack([X, 0.5 * self.separation + side * eta, Z], axis=-1).reshape(-1, 3))
            i, k = np.meshgrid(np.arange(n_half_length), np.arange(n_girth), indexing="ij")
            a = (base + i * nz1 + k).reshape(-1)
            b = a + nz1
            # Outer (+η) side: [a, a+1, b+1, b] has normal +y; inner (−η) side is reversed.
            quad = [a, a + 1, b + 1, b] if side > 0 else [a, b, b + 1, a + 1]
            faces.append(np.stack(quad, axis=-1))
        return merge_vertices(np.concatenate(verts), np.concatenate(faces))

    def mesh(self, counts: PanelCounts) -> HullMesh:
        """Full wetted hull (both demihulls, both sides, no lid) as a :class:`HullMesh`."""
        v, f = self.quarter_panels(counts.n_half_length, counts.n_girth)
        v, f = mirror_panels(v, f, axis=1)   # port → both demihulls
        v, f = mirror_panels(v, f, axis=0)   # forebody → whole length
        return HullMesh(v, f)


# ---------------------------------------------------------------------- panel utilities
def _canonical(faces: np.ndarray) -> np.ndarray:
    """Faces with repeated vertices rewritten as triangles ``[a, b, c, c]`` (drops < 3 distinct)."""
    out = []
    for f in np.asarray(faces, dtype=np.int64):
        uniq = [v for k, v in enumerate(f) if v not in f[:k]]
        if len(uniq) == 4:
            out.append(uniq)
        elif len(uniq) == 3:
            out.append(uniq + [uniq[-1]])
    return np.array(out, dtype=np.int64).reshape(-1, 4)


def merge_vertices(vertices, faces, *, tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """Merge vertices closer than ``tol`` × the mesh size and drop the unused ones.

    Faces that collapse to a triangle become ``[a, b, c, c]``; faces with fewer than three distinct
    vertices are dropped.
    """
    v = np.asarray(vertices, dtype=float)
    scale = max(float(np.max(np.abs(v))) if v.size else 1.0, 1e-300)
    key = np.round(v / (tol * scale)).astype(np.int64)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    f = _canonical(inverse[np.asarray(faces, dtype=np.int64)])
    used = np.unique(f)
    remap = np.full(len(first), -1, dtype=np.int64)
    remap[used] = np.arange(used.size)
    return v[first[used]], remap[f]


def _reversed(faces: np.ndarray) -> np.ndarray:
    """Faces with the opposite orientation, keeping a triangle's repeated vertex last."""
    f = np.asarray(faces, dtype=np.int64)
    out = f[:, [0, 3, 2, 1]].copy()
    tri = f[:, 2] == f[:, 3]
    out[tri] = f[tri][:, [0, 2, 1, 1]]
    return out


def mirror_panels(vertices, faces, axis: int) -> tuple[np.ndarray, np.ndarray]:
    """Panels plus their mirror image in the plane ``coordinate[axis] = 0`` (orientation kept
    outward), with the vertices on the plane merged."""
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces, dtype=np.int64)
    vm = v.copy()
    vm[:, axis] *= -1.0
    return merge_vertices(np.concatenate([v, vm]), np.concatenate([f, _reversed(f) + len(v)]))


def panel_normals_areas(vertices, faces) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit normals, areas and centroids of the panels (each quad split into two triangles)."""
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces, dtype=np.int64)
    p0, p1, p2, p3 = (v[f[:, k]] for k in range(4))
    n1 = 0.5 * np.cross(p1 - p0, p2 - p0)
    n2 = 0.5 * np.cross(p2 - p0, p3 - p0)
    nvec = n1 + n2
    area = np.linalg.norm(nvec, axis=1)
    a1, a2 = np.linalg.norm(n1, axis=1), np.linalg.norm(n2, axis=1)
    c1, c2 = (p0 + p1 + p2) / 3.0, (p0 + p2 + p3) / 3.0
    w = np.where(a1 + a2 > 0, a1 + a2, 1.0)[:, None]
    centre = (a1[:, None] * c1 + a2[:, None] * c2) / w
    return nvec / np.where(area > 0, area, 1.0)[:, None], area, centre


def mesh_volume(vertices, faces) -> float:
    r"""Volume enclosed by the panels and the plane z = 0 (divergence theorem).

    :math:`\nabla = \oint z\, n_z\, dS` over the wetted panels with normals out of the hull; the
    waterplane (z = 0) adds nothing. Exact for the piecewise-planar (two triangles per quad) surface.
    """
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces, dtype=np.int64)
    p0, p1, p2, p3 = (v[f[:, k]] for k in range(4))
    vol = 0.0
    for a, b, c in ((p0, p1, p2), (p0, p2, p3)):
        nz = 0.5 * np.cross(b - a, c - a)[:, 2]
        vol += np.sum(nz * (a[:, 2] + b[:, 2] + c[:, 2]) / 3.0)
    return float(vol)
