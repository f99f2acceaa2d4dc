"""The 3D scene of a trial for the viewers: hull, monopile, landing tubes, fender lines, force arrows, sea.

The hull is the database's wetted mesh plus, when the database has it, its part above the waterline —
topsides, deck, deckhouse (``db.topsides``, a :class:`~boatland.vessel.database.HullMesh`); a database
without a mesh shows a box. The wetted part is drawn in dark antifouling red, the topsides light grey,
the sea translucent blue (:data:`COLORS`).

A :class:`Scene` is built from the scenario and database (:func:`scene_from_trial`, live) or from the
metadata of a run log (:func:`scene_from_metadata`, replay: the scenario document stored in the log is
re-read; if its database cannot be found, a box hull and no sea surface are shown, with a note).
Geometry is global (DESIGN.md §2: z up, origin on the mean free surface at the monopile axis) except the
hull and the fender lines, which are in the body frame and move with the vessel's transform. Both
viewers draw the same :class:`Scene`: Rerun (:mod:`boatland.record.rerun_log`) and Foxglove
(:mod:`boatland.record.foxglove_scene`).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

__all__ = ["Scene", "ContactGeometry", "scene_from_trial", "scene_from_metadata", "scene_metadata", "box_hull",
           "hull_geometry", "hull_parts", "hull_triangles", "fender_forces", "COLORS", "MODE_COLORS",
           "SERIES", "SERIES_LIGHT", "FORCE_SCALE"]

PILE_TOP, PILE_BOTTOM = 12.0, -20.0   # [m] drawn extent of the monopile, and of tubes without ends (z, global)
PATCH_HALF = (24.0, 14.0)           # [m] half sizes of the sea patch around the vessel at rest (x, y)
PATCH_SPACING = 3.0                  # [m]
PATCH_DT = 0.5                       # [s] time between frames of the sea patch
FORCE_SCALE = 1e-4                   # [m/N] length of the force arrows: 1 m per 10 kN
CAMERA_OFFSET = (-12.0, 30.0, 14.0)   # [m] eye − target, vessel axes (aft, to port, up): :meth:`Scene.camera`
FENDER_RADIUS = 0.18                 # [m] drawn radius of the fender lines (a 300–400 mm rubber bow fender)

#: RGBA colours (0–255) of the scene, shared by both viewers.
COLORS = {
    "antifouling": (128, 38, 32, 255),     # wetted hull: the dark red of antifouling paint
    "topsides": (226, 228, 230, 255),      # hull above the waterline, deck: light grey / white
    "sea": (30, 105, 170, 110),            # translucent sea
    "monopile": (235, 190, 30, 255),       # the transition piece's safety yellow
    "tube": (165, 170, 175, 255),          # galvanised landing tubes
    "fender": (40, 40, 40, 255),           # black rubber (overridden by the contact state while it runs)
    "sky": (176, 196, 214, 255),           # background of the 3D view
}
#: Colours of the plotted series (matplotlib's tab10 and the light half of its tab20 pairs): per contact k,
#: ``needed`` is ``SERIES[k]`` and ``available`` its light pair ``SERIES_LIGHT[k]``, so each contact's two
#: lines read as one pair and no two series of a plot share a colour.
SERIES = np.array([[31, 119, 180], [255, 127, 14], [44, 160, 44], [214, 39, 40], [148, 103, 189],
                   [140, 86, 75], [227, 119, 194], [127, 127, 127], [188, 189, 34], [23, 190, 207]], np.uint8)
SERIES_LIGHT = np.array([[174, 199, 232], [255, 187, 120], [152, 223, 138], [255, 152, 150], [197, 176, 213],
                         [196, 156, 148], [247, 182, 210], [199, 199, 199], [219, 219, 141], [158, 218, 229]],
                        np.uint8)
#: Colours of the contact states (index = mode): open, stick, slip, off the landing.
MODE_COLORS = np.array([[150, 150, 150, 255], [40, 190, 60, 255], [230, 40, 40, 255],
                        [120, 0, 160, 255]], np.uint8)


class ContactGeometry(NamedTuple):
    """The fender contacts' geometry, local frame (the fields of :class:`boatland.contact.fender.Contacts`
    the viewers need): line centres ``P`` (Nc, 3) and unit directions ``D`` (Nc, 3), body frame; half
    widths ``HW`` (Nc,); tube axis points ``AX`` (Nc, 3) at z = 0, radii ``RT`` (Nc,) (inf: a plate
    with normal ``N0``), ends ``ZB``, ``ZT`` (Nc,); rest normals ``N0`` (Nc, 3)."""

    P: np.ndarray
    D: np.ndarray
    HW: np.ndarray
    AX: np.ndarray
    RT: np.ndarray
    ZB: np.ndarray
    ZT: np.ndarray
    N0: np.ndarray

    @classmethod
    def of(cls, contacts) -> "ContactGeometry":
        """From a :class:`~boatland.contact.fender.Contacts` (or its metadata dict / None: no contacts)."""
        if contacts is None:
            e3, e = np.zeros((0, 3)), np.zeros(0)
            return cls(e3, e3, e, e3, e, e, e, e3)
        get = contacts.get if isinstance(contacts, dict) else lambda k: getattr(contacts, k)
        return cls(*(np.asarray(get(k), float).reshape((-1, 3) if k in ("P", "D", "AX", "N0") else (-1,))
                     for k in cls._fields))

    def to_json(self) -> dict:
        return {k: np.asarray(v).tolist() for k, v in self._asdict().items()}

    @property
    def lines(self) -> np.ndarray:
        """End points (Nc, 2, 3) of the fender lines, body frame."""
        h = (self.HW[:, None] * self.D)[:, None, :]
        return self.P[:, None, :] + np.concatenate([-h, h], axis=1)


@dataclass(frozen=True, eq=False)
class Scene:
    """Static geometry plus what is needed to draw the sea.

    Attributes
    ----------
    hull_vertices, hull_triangles : (Nv, 3) float32, (Nt, 3) uint32
        Hull in the body frame: the wetted part's vertices first, then the topsides'.
    monopile : (x, y, diameter)
    struts : list of (x, y, diameter, bottom, top)
        Landing tubes, global; ``bottom``, ``top`` the drawn ends (±inf clipped to the pile's extent).
    fender_points : (Nc, 3)
        Contact points (fender line centres) on the fender, body frame.
    start_pose : (x0, y0, psi)
    components : wave components (:class:`~boatland.waves.realisation.Components`) or None
    ramp : callable t -> factor, or None
    notes : list of str
        What could not be rebuilt (replay).
    pile : Pile or None
        The pile whose scattered wave is in the sea (:class:`boatland.sea.pile.Pile`).
    hull_wetted : int
        Number of vertices of the wetted (below-waterline) part, the first ones of ``hull_vertices``.
    contacts : ContactGeometry
        Fender lines and tubes as the contact model sees them (local frame; no contacts: empty).
    """

    hull_vertices: np.ndarray
    hull_triangles: np.ndarray
    monopile: tuple
    struts: list
    fender_points: np.ndarray
    start_pose: tuple
    components: object = None
    ramp: object = None
    notes: list = field(default_factory=list)
    pile: object = None                # the Pile when its scattered wave is in the sea
    hull_wetted: int = -1              # -1: all of the hull
    contacts: ContactGeometry = field(default_factory=lambda: ContactGeometry.of(None))

    def __post_init__(self):
        if self.hull_wetted < 0:
            object.__setattr__(self, "hull_wetted", len(self.hull_vertices))

    @property
    def hull_colors(self) -> np.ndarray:
        """(Nv, 4) uint8 vertex colours: antifouling below the waterline, topsides above."""
        c = np.empty((len(self.hull_vertices), 4), np.uint8)
        c[:self.hull_wetted] = COLORS["antifouling"]
        c[self.hull_wetted:] = COLORS["topsides"]
        return c

    @property
    def fender_lines(self) -> np.ndarray:
        """End points (Nc, 2, 3) of the fender lines, body frame (a zero-length line at each contact point
        when the contact geometry is unknown)."""
        if len(self.contacts.P) == len(self.fender_points):
            return self.contacts.lines
        p = np.asarray(self.fender_points, float).reshape(-1, 1, 3)
        return np.concatenate([p, p], axis=1)

    def to_world(self, p: np.ndarray) -> np.ndarray:
        """Points (..., 3) of the local frame (the start pose's) in the global frame."""
        x0, y0, psi = self.start_pose
        c, s = math.cos(psi), math.sin(psi)
        p = np.asarray(p, float)
        out = np.empty(p.shape)
        out[..., 0] = x0 + c * p[..., 0] - s * p[..., 1]
        out[..., 1] = y0 + s * p[..., 0] + c * p[..., 1]
        out[..., 2] = p[..., 2]
        return out

    def camera(self) -> tuple[np.ndarray, np.ndarray]:
        """Default viewpoint ``(eye, target)``, global [m]: from above the vessel's port side, aft of the
        bow, looking at a point halfway between the vessel's reference point and its bow, so that the
        vessel, its fender, the landing tubes and the pile are all in view."""
        bow = self.to_world(np.mean(self.fender_points, axis=0)) if len(self.fender_points) else \
            self.to_world(np.array([12.0, 0.0, 1.5]))
        target = 0.5 * (bow + self.to_world(np.zeros(3)))
        target[2] = 0.5 * bow[2]
        psi = self.start_pose[2]
        c, s = math.cos(psi), math.sin(psi)
        back, side, up = CAMERA_OFFSET                # body-frame offset of the eye from the target
        eye = target + np.array([c * back - s * side, s * back + c * side, up])
        return eye, target

    def patch_grid(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Global x, y (P,) of the sea-patch vertices and its triangles (T, 3), around the rest position."""
        x0, y0, _ = self.start_pose
        xs = np.arange(-PATCH_HALF[0], PATCH_HALF[0] + 1e-9, PATCH_SPACING) + x0
        ys = np.arange(-PATCH_HALF[1], PATCH_HALF[1] + 1e-9, PATCH_SPACING) + y0
        X, Y = np.meshgrid(xs, ys, indexing="ij")
        nx, ny = X.shape
        k = np.arange(nx * ny).reshape(nx, ny)
        a, b, c, d = k[:-1, :-1].ravel(), k[1:, :-1].ravel(), k[1:, 1:].ravel(), k[:-1, 1:].ravel()
        tri = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)]).astype(np.uint32)
        return X.ravel(), Y.ravel(), tri

    def sea_frames(self, t: np.ndarray) -> np.ndarray | None:
        """Elevation (len(t), P) of the patch vertices at the times ``t`` (a uniform grid), or None."""
        if self.components is None or len(t) == 0:
            return None
        from boatland.waves.synthesis import harmonic_series

        cp = self.components
        if "_coef" not in self.__dict__:       # complex amplitudes at the patch vertices, computed once
            X, Y, _ = self.patch_grid()
            object.__setattr__(self, "_coef", sea_coefficients(cp, X, Y, self.pile))
        h = float(t[1] - t[0]) if len(t) > 1 else 1.0
        eta = harmonic_series(cp.omega, self.__dict__["_coef"], float(t[0]), h, len(t))
        return eta * self.ramp(np.asarray(t))[:, None]


def sea_coefficients(cp, X, Y, pile=None) -> np.ndarray:
    r"""Complex elevation amplitudes (P, N) of the wave components at global points (X, Y):
    :math:`a_i e^{i(\varphi_i - k_i(x\cos\theta_i + y\sin\theta_i))}` in the open sea; beside a pile
    (:class:`boatland.sea.pile.Pile`) the total (incident + scattered, MacCamy–Fuchs) field of each component
    (:func:`boatland.waves.diffraction.cylinder_field`), 0 inside the pile."""
    from boatland.waves.synthesis import component_phasors

    if pile is None:
        return component_phasors(cp, X, Y)
    from boatland.waves.diffraction import cylinder_field

    X = np.atleast_1d(np.asarray(X, dtype=float))
    Y = np.atleast_1d(np.asarray(Y, dtype=float))
    radius, (px, py), depth = pile
    out = np.zeros((X.size, cp.size), dtype=complex)
    waves = cp.omega > 0
    eta = cylinder_field(X - px, Y - py, np.zeros(X.size), cp.omega[waves], cp.theta[waves], radius, depth,
                         paired=True).eta
    out[:, waves] = np.nan_to_num(np.asarray(eta).reshape(X.size, -1)) * component_phasors(cp, px, py)[:, waves]
    return out


def pile_of(setup, model):
    """The :class:`~boatland.sea.pile.Pile` whose scattered wave the trial feels (:attr:`Setup.pile`) in the
    waves ``model`` (their water depth), or None."""
    p = setup.pile if model is not None else None
    return None if p is None else p._replace(water_depth=float(getattr(model, "water_depth", math.inf)))


def hull_triangles(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Quadrilateral panels (triangles repeat their last vertex) → triangles (Nt, 3)."""
    f = np.asarray(faces)
    t1 = f[:, [0, 1, 2]]
    quad = f[:, 3] != f[:, 2]
    t2 = f[quad][:, [0, 2, 3]]
    return np.asarray(vertices, np.float32), np.concatenate([t1, t2]).astype(np.uint32)


def hull_parts(db) -> tuple[np.ndarray, np.ndarray, int]:
    """Vertices (Nv, 3) float32 and triangles (Nt, 3) uint32 of the hull to draw, body frame, and the
    number of wetted vertices (the first ones): the wetted mesh of ``db`` and its topsides (``db.topsides``:
    topsides, deck, deckhouse) when it has them, else :func:`box_hull`."""
    wet = getattr(db, "mesh", None)
    parts = [m for m in (wet, getattr(db, "topsides", None)) if m is not None and m.n_panels]
    if not parts:
        v, tri = box_hull()
        return v, tri, len(v) // 2
    verts, tris, base = [], [], 0
    for m in parts:
        v, t = hull_triangles(m.vertices, m.faces)
        verts.append(v)
        tris.append(t + base)
        base += len(v)
    n_wet = len(verts[0]) if wet is not None and wet.n_panels else 0
    return np.concatenate(verts).astype(np.float32), np.concatenate(tris).astype(np.uint32), n_wet


def hull_geometry(db) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (Nv, 3) float32 and triangles (Nt, 3) uint32 of the hull to draw, body frame: the wetted
    mesh and the topsides of ``db`` when it has them, else :func:`box_hull` (:func:`hull_parts`)."""
    v, tri, _ = hull_parts(db)
    return v, tri


def box_hull(length: float = 24.0, beam: float = 9.0, draft: float = 1.4, freeboard: float = 2.0):
    """A simple hull (body frame, centred on the reference point) when no mesh is known: two boxes, the
    part below the waterline (its 8 vertices first) and the part above."""
    L, B = length / 2, beam / 2
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    verts, tris = [], []
    for k, (z0, z1) in enumerate(((-draft, 0.0), (0.0, freeboard))):
        verts += [[x, y, z] for x in (-L, L) for y in (-B, B) for z in (z0, z1)]
        tris += [(8 * k + a, 8 * k + b, 8 * k + c) for a, b, c, d in quads]
        tris += [(8 * k + a, 8 * k + c, 8 * k + d) for a, b, c, d in quads]
    return np.array(verts, np.float32), np.array(tris, np.uint32)


def _finite_or(v: float, default: float) -> float:
    return float(v) if math.isfinite(v) else default


def scene_metadata(scenario, contacts) -> dict:
    """The geometry of the landing and fender as JSON-able dict (stored in the run log): fender points,
    monopile ``[x, y, d]``, tubes ``[x, y, d, bottom, top]`` (drawn ends), the contact geometry."""
    land = scenario.landing
    out = {"fender_points": np.asarray(contacts[0]).reshape(-1, 3).tolist()}
    if land is not None:
        out["monopile"] = [*map(float, land.monopile_position), float(land.monopile_diameter)]
        out["struts"] = [[*map(float, s.position), float(s.diameter), _finite_or(s.bottom, PILE_BOTTOM),
                          _finite_or(s.top, PILE_TOP)] for s in land.struts]
    if hasattr(contacts, "_fields"):
        out["contacts"] = ContactGeometry.of(contacts).to_json()
    return out


def _struts(geo: dict) -> list:
    """Tubes of the scene metadata as (x, y, d, bottom, top); logs before the tube ends were stored get
    the drawn extent of the pile."""
    return [tuple(s) if len(s) >= 5 else (*s[:3], PILE_BOTTOM, PILE_TOP) for s in geo.get("struts", [])]


def scene_from_trial(setup, contacts=None, *, waves=True, start_pose=None) -> Scene:
    """The scene of a trial about to run (or re-read from a log) from its :class:`~boatland.landing.setup.Setup`
    (``contacts``: the kernel's, :meth:`Setup.contacts` by default; ``start_pose``: the setup's by default);
    ``waves=False``: no sea surface."""
    from boatland.trial.simulate import wave_start

    scenario, db = setup.scenario, setup.db
    start_pose = setup.start_pose if start_pose is None else start_pose
    geo = scene_metadata(scenario, setup.contacts() if contacts is None else contacts)
    v, tri, n_wet = hull_parts(db)
    comps, ramp = None, None
    model = setup.waves if waves else None
    if model is not None:
        dt, n = setup.dt, setup.n_steps
        comps = model.realise(scenario.simulation.seed, n * dt)
        t0, T = wave_start(scenario), scenario.simulation.start_ramp
        ramp = _Ramp(t0, T)
    return Scene(hull_vertices=v, hull_triangles=tri, monopile=tuple(geo.get("monopile", (0.0, 0.0, 0.0))),
                 struts=_struts(geo), fender_points=np.asarray(geo["fender_points"]),
                 start_pose=tuple(start_pose), components=comps, ramp=ramp, pile=pile_of(setup, model),
                 hull_wetted=n_wet, contacts=ContactGeometry.of(geo.get("contacts")))


@dataclass(frozen=True)
class _Ramp:
    """:func:`boatland.trial.simulate.wave_ramp` as a function of time."""

    t0: float
    T: float

    def __call__(self, t):
        t = np.asarray(t, float) - self.t0
        if self.T <= 0:
            return (t >= 0).astype(float)
        return np.where(t <= 0, 0.0, np.where(t < self.T, 0.5 * (1 - np.cos(np.pi * np.clip(t, 0, self.T) / self.T)), 1.0))


def scene_from_metadata(meta: dict) -> Scene:
    """The scene of a logged run: from its scenario document if that (and its database) can be re-read,
    else from the geometry stored in the log with a box hull and no sea (saying so in ``notes``)."""
    import warnings

    start_pose = tuple(json.loads(meta.get("start_pose", "[0, 0, 0]")))
    geo = json.loads(meta.get("scene", "{}"))
    notes = []
    try:
        from boatland.scenario.scenario import scenario_from_dict
        from boatland.checks.files import resolve_database
        from boatland.landing.setup import Setup

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            doc = json.loads(meta["scenario"])
            sc = scenario_from_dict(doc, source=meta.get("scenario_source", "<log>"),
                                    base_dir=meta.get("scenario_base_dir") or None)
            return scene_from_trial(Setup.of(sc, resolve_database(sc)), start_pose=start_pose)
    except Exception as exc:  # noqa: BLE001 — any failure to rebuild only costs the hull mesh and the sea
        notes.append(f"scenario of the log not re-readable here ({type(exc).__name__}: {exc}); "
                     "showing a box hull and no sea surface")
    v, tri = box_hull()
    return Scene(hull_vertices=v, hull_triangles=tri, monopile=tuple(geo.get("monopile", (0.0, 0.0, 0.0))),
                 struts=_struts(geo), fender_points=np.asarray(geo.get("fender_points", np.zeros((0, 3)))),
                 start_pose=start_pose, notes=notes, hull_wetted=len(v) // 2,
                 contacts=ContactGeometry.of(geo.get("contacts")))


def fender_forces(scene: Scene, x: np.ndarray, fn: np.ndarray, ft: np.ndarray) -> tuple[np.ndarray, ...]:
    r"""The fender forces on the vessel as arrows, global frame: contact points and force vectors.

    The contact point Q of each fender line is its point closest to the tube axis (clamped to the line),
    as in :mod:`boatland.contact.fender`; the normal force acts along the contact normal n (the
    fender face's, or the tube surface's where the tube meets the end of the line; a plate's ``N0``)
    and the friction along :math:`(e_z, t_h = e_z \times n)`.

    Parameters
    ----------
    scene : Scene
        Its ``contacts`` (local frame) and ``start_pose``.
    x : (n, 6)
        Motions (local frame; rad).
    fn : (n, Nc)
        Normal forces [N].
    ft : (n, Nc, 2)
        Friction (vertical, horizontal) [N].

    Returns
    -------
    origins, normal, friction : (n, Nc, 3)
        Contact points [m] and the normal and friction force vectors [N], global frame.
    """
    g = scene.contacts
    n, nc = len(x), len(g.P)
    if nc == 0:
        e = np.zeros((n, 0, 3))
        return e, e, e
    R = _rotations(x[:, 3], x[:, 4], x[:, 5])                   # (n, 3, 3) body → local
    cen = x[:, None, :3] + np.einsum("nij,cj->nci", R, g.P)      # fender line centres (n, Nc, 3)
    d = np.einsum("nij,cj->nci", R, g.D)
    tube = np.isfinite(g.RT)
    d2 = d[..., 0] ** 2 + d[..., 1] ** 2
    with np.errstate(invalid="ignore", divide="ignore"):
        su = np.where(tube & (d2 > 0), -((cen[..., 0] - g.AX[:, 0]) * d[..., 0]
                                         + (cen[..., 1] - g.AX[:, 1]) * d[..., 1]) / d2, 0.0)
    s = np.clip(su, -g.HW, g.HW)
    Q = cen + s[..., None] * d
    b = np.stack([g.D[:, 1], -g.D[:, 0], np.zeros(nc)], axis=1)   # d × e_z: the fender face's outward normal
    m = np.einsum("nij,cj->nci", R, b)[..., :2]
    m /= np.linalg.norm(m, axis=-1, keepdims=True)
    front = (g.AX[:, 0] - Q[..., 0]) * m[..., 0] + (g.AX[:, 1] - Q[..., 1]) * m[..., 1]
    h = Q[..., :2] - g.AX[:, :2]
    with np.errstate(invalid="ignore", divide="ignore"):
        radial = h / np.linalg.norm(h, axis=-1, keepdims=True)
    face = (np.abs(su) <= g.HW) | (front <= 0)
    nrm = np.where(face[..., None], -m, radial)
    nrm = np.where(tube[None, :, None], nrm, g.N0[None, :, :2])  # a plate: its normal
    normal = np.zeros((n, nc, 3))
    normal[..., :2] = nrm * fn[..., None]
    friction = np.zeros((n, nc, 3))
    friction[..., 0] = -nrm[..., 1] * ft[..., 1]
    friction[..., 1] = nrm[..., 0] * ft[..., 1]
    friction[..., 2] = ft[..., 0]
    rot = np.zeros((3, 3))
    psi = scene.start_pose[2]
    rot[:2, :2] = [[math.cos(psi), -math.sin(psi)], [math.sin(psi), math.cos(psi)]]
    rot[2, 2] = 1.0
    return scene.to_world(Q), normal @ rot.T, friction @ rot.T


def _rotations(phi, theta, psi) -> np.ndarray:
    """(n, 3, 3) body → local rotations R = Rz(ψ) Ry(θ) Rx(φ) (:func:`boatland.rigid.rotation_matrix`)."""
    cf, sf, ct, st, cp, sp = np.cos(phi), np.sin(phi), np.cos(theta), np.sin(theta), np.cos(psi), np.sin(psi)
    R = np.empty((len(phi), 3, 3))
    R[:, 0, 0], R[:, 0, 1], R[:, 0, 2] = cp * ct, cp * st * sf - sp * cf, cp * st * cf + sp * sf
    R[:, 1, 0], R[:, 1, 1], R[:, 1, 2] = sp * ct, sp * st * sf + cp * cf, sp * st * cf - cp * sf
    R[:, 2, 0], R[:, 2, 1], R[:, 2, 2] = -st, ct * sf, ct * cf
    return R
