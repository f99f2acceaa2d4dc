"""The 3D scene of a trial for the Rerun viewer: hull, monopile, landing struts, fender points, sea patch.

A :class:`Scene` is built from the scenario and database (:func:`scene_from_trial`, live) or from the
metadata of a run log (:func:`scene_from_metadata`, replay: the scenario document stored in the log is
re-read; if its database cannot be found, a box hull and no sea surface are shown, with a note).
Geometry is global (DESIGN.md §2: z up, origin on the mean free surface at the monopile axis) except the
hull and fender points, which are in the body frame and move with the vessel's transform.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Scene", "scene_from_trial", "scene_from_metadata", "scene_metadata", "box_hull", "hull_triangles"]

PILE_TOP, PILE_BOTTOM = 12.0, -20.0   # [m] drawn extent of monopile and struts (z, global)
PATCH_HALF = (24.0, 14.0)           # [m] half sizes of the sea patch around the vessel at rest (x, y)
PATCH_SPACING = 3.0                  # [m]
PATCH_DT = 0.5                       # [s] time between frames of the sea patch


@dataclass(frozen=True, eq=False)
class Scene:
    """Static geometry plus what is needed to draw the sea.

    Attributes
    ----------
    hull_vertices, hull_triangles : (Nv, 3) float32, (Nt, 3) uint32
        Hull in the body frame.
    monopile : (x, y, diameter)
    struts : list of (x, y, diameter)
    fender_points : (Nc, 3)
        Contact points on the fender, body frame.
    start_pose : (x0, y0, psi)
    components : wave components (:class:`~boatland.waves.realisation.Components`) or None
    ramp : callable t -> factor, or None
    notes : list of str
        What could not be rebuilt (replay).
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
    pile: tuple | None = None          # (radius, x, y, water depth) when its scattered wave is in the sea

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
    ``(radius, x, y, depth)`` the total (incident + scattered, MacCamy–Fuchs) field of each component
    (:func:`boatland.waves.diffraction.cylinder_field`), 0 inside the pile."""
    from boatland.waves.synthesis import component_phasors

    if pile is None:
        return component_phasors(cp, X, Y)
    from boatland.waves.diffraction import cylinder_field

    X = np.atleast_1d(np.asarray(X, dtype=float))
    Y = np.atleast_1d(np.asarray(Y, dtype=float))
    radius, px, py, depth = pile
    out = np.zeros((X.size, cp.size), dtype=complex)
    waves = cp.omega > 0
    eta = cylinder_field(X - px, Y - py, np.zeros(X.size), cp.omega[waves], cp.theta[waves], radius, depth,
                         paired=True).eta
    out[:, waves] = np.nan_to_num(np.asarray(eta).reshape(X.size, -1)) * component_phasors(cp, px, py)[:, waves]
    return out


def pile_of(scenario, db, model) -> tuple | None:
    """``(radius, x, y, depth)`` of the pile whose scattered wave the trial feels, or None."""
    p = scenario.pile(db) if model is not None else None
    return None if p is None else (p[0], p[1][0], p[1][1], float(getattr(model, "water_depth", math.inf)))


def hull_triangles(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Quadrilateral panels (triangles repeat their last vertex) → triangles (Nt, 3)."""
    f = np.asarray(faces)
    t1 = f[:, [0, 1, 2]]
    quad = f[:, 3] != f[:, 2]
    t2 = f[quad][:, [0, 2, 3]]
    return np.asarray(vertices, np.float32), np.concatenate([t1, t2]).astype(np.uint32)


def box_hull(length: float = 24.0, beam: float = 9.0, draft: float = 1.4, freeboard: float = 2.0):
    """A simple hull box (body frame, centred on the reference point) when no mesh is known."""
    L, B = length / 2, beam / 2
    v = np.array([[x, y, z] for x in (-L, L) for y in (-B, B) for z in (-draft, freeboard)], np.float32)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tri = [(a, b, c) for a, b, c, d in quads] + [(a, c, d) for a, b, c, d in quads]
    return v, np.array(tri, np.uint32)


def scene_metadata(scenario, contacts) -> dict:
    """The geometry of the landing and fender as JSON-able dict (stored in the run log)."""
    land = scenario.landing
    out = {"fender_points": np.asarray(contacts[0]).reshape(-1, 3).tolist()}
    if land is not None:
        out["monopile"] = [*map(float, land.monopile_position), float(land.monopile_diameter)]
        out["struts"] = [[*map(float, s.position), float(s.diameter)] for s in land.struts]
    return out


def scene_from_trial(scenario, db, start_pose, contacts, *, waves=True) -> Scene:
    """The scene of a trial about to run (or re-read from a log)."""
    from boatland.trial.simulate import wave_start

    geo = scene_metadata(scenario, contacts)
    if db.mesh is not None and db.mesh.n_panels:
        v, tri = hull_triangles(db.mesh.vertices, db.mesh.faces)
    else:
        v, tri = box_hull()
    comps, ramp = None, None
    model = scenario.wave_model(db) if waves else None
    if model is not None:
        dt, n = scenario.time_step(db), scenario.n_steps(db)
        comps = model.realise(scenario.simulation.seed, n * dt)
        t0, T = wave_start(scenario), scenario.simulation.start_ramp
        ramp = _Ramp(t0, T)
    return Scene(hull_vertices=v, hull_triangles=tri, monopile=tuple(geo.get("monopile", (0.0, 0.0, 0.0))),
                 struts=geo.get("struts", []), fender_points=np.asarray(geo["fender_points"]),
                 start_pose=tuple(start_pose), components=comps, ramp=ramp, pile=pile_of(scenario, db, model))


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
        from boatland.model.scenario import scenario_from_dict
        from boatland.scenario_check import resolve_database
        from boatland.trial.simulate import contact_arrays

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            doc = json.loads(meta["scenario"])
            sc = scenario_from_dict(doc, source=meta.get("scenario_source", "<log>"),
                                    base_dir=meta.get("scenario_base_dir") or None)
            db = resolve_database(sc)
            return scene_from_trial(sc, db, start_pose, contact_arrays(sc, db))
    except Exception as exc:  # noqa: BLE001 — any failure to rebuild only costs the hull mesh and the sea
        notes.append(f"scenario of the log not re-readable here ({type(exc).__name__}: {exc}); "
                     "showing a box hull and no sea surface")
    v, tri = box_hull()
    return Scene(hull_vertices=v, hull_triangles=tri, monopile=tuple(geo.get("monopile", (0.0, 0.0, 0.0))),
                 struts=geo.get("struts", []), fender_points=np.asarray(geo.get("fender_points", np.zeros((0, 3)))),
                 start_pose=start_pose, notes=notes)
