"""The 3-D scene of a run log for Foxglove: a static ``foxglove.SceneUpdate`` and the fender force arrows.

Foxglove's 3D panel draws ``foxglove.SceneUpdate`` messages in the frames of ``/tf``
(``world`` → ``vessel``). A run log has two SceneUpdate channels (:mod:`boatland.record.schemas`):

- ``/scene``, once at the start: the hull (``hull/wetted`` in antifouling red; ``hull/topsides`` light
  grey when the database has topsides and deck), ``fender`` (the fender lines, black rubber), all in
  the ``vessel`` frame (``frame_locked``: they move with the vessel); ``monopile``, ``landing/tubes``
  (vertical cylinders from each tube's bottom to its top) and ``sea`` (a translucent sheet at the mean
  water level) in ``world``. Colours: :data:`boatland.record.scene.COLORS`.
- ``/fender/forces``, every step: one entity ``fender_forces`` (``world``) with two arrows per contact —
  the normal force and the friction on the vessel, from the contact point, 1 m per 10 kN
  (:data:`~boatland.record.scene.FORCE_SCALE`), coloured by the contact's state (open grey, stick green,
  slip red, off the landing purple; :data:`~boatland.record.scene.MODE_COLORS`); an arrow without force is
  transparent. Every step's message has the same size: it is written by the compiled step encoder
  (:class:`boatland.record.mcap_log._Layout`) from :func:`arrow_items` and :func:`arrow_values_compiled`.

``boatland/record/foxglove_layout.json`` is a Foxglove layout for these logs (3D panel looking at the
bow and the landing, plots, the event log; :func:`foxglove_layout`): import it in Foxglove (Layouts →
Import from file). Regenerate it with ``python -m boatland.record.foxglove_scene``.
"""

from __future__ import annotations

from importlib import resources

import numba
import numpy as np

from boatland.record.scene import COLORS, FENDER_RADIUS, FORCE_SCALE, MODE_COLORS, PATCH_HALF, PILE_BOTTOM, \
    PILE_TOP, Scene, fender_forces
from boatland.record.schemas import message_class

__all__ = ["static_scene", "arrow_items", "arrow_values", "arrow_values_compiled", "ARROW_FIELDS", "layout_path",
           "foxglove_layout", "SHAFT_DIAMETER",
           "HEAD_DIAMETER"]

SHAFT_DIAMETER, HEAD_DIAMETER = 0.08, 0.22   # [m] of the force arrows
HEAD_LENGTH = 0.35                          # [m], at most 40 % of the arrow
#: The doubles of one arrow, in the order :func:`arrow_items` writes them.
ARROW_FIELDS = ("x", "y", "z", "qx", "qy", "qz", "qw", "shaft_length", "shaft_diameter", "head_length",
                "head_diameter", "r", "g", "b", "a")


def layout_path():
    """Path of the shipped Foxglove layout file (``foxglove_layout.json``, :func:`foxglove_layout` of the
    default scenario's two contacts)."""
    return resources.files("boatland.record") / "foxglove_layout.json"


def _hex(c) -> str:
    return "#" + "".join(f"{int(v):02x}" for v in c[:3])


def foxglove_layout(n_contacts: int = 2, scene: Scene | None = None) -> dict:
    """A Foxglove layout (the JSON of *Layouts → Import from file*) for a run log: a 3D panel (left) on
    ``/scene`` and ``/fender/forces`` in the ``world`` frame, looking at the bow and the landing
    (``scene.camera()``, when given); plots (right) of heave and the wave at the bow, roll and pitch
    [deg], the fender's normal force and available friction per contact [N], thrust [N] and slip distance
    [m], all against the log time; the event log (``/events``) at the bottom.

    Panel configurations follow Foxglove's saved layouts (``configById``, ``layout`` split tree); every
    plotted path is ``<topic>.<field>`` of :mod:`boatland.record.schemas`."""
    def plot(title, *paths):
        return {"paths": [{"value": v, "enabled": True, "timestampMethod": "receiveTime", "label": label}
                          for v, label in paths],
                "showLegend": True, "legendDisplay": "floating", "showXAxisLabels": True, "showYAxisLabels": True,
                "isSynced": True, "xAxisVal": "timestamp", "foxglovePanelTitle": title}

    contact = lambda k, f: f"/fender/state.contacts[{k}].{f}"  # noqa: E731
    camera = {"perspective": True, "distance": 35.0, "phi": 60.0, "thetaOffset": 120.0,
              "target": [0.0, 0.0, 0.0], "targetOffset": [-10.0, 0.0, 0.0], "targetOrientation": [0, 0, 0, 1],
              "fovy": 45.0, "near": 0.5, "far": 5000.0}
    if scene is not None:
        eye, target = scene.camera()
        d = eye - target
        dist = float(np.linalg.norm(d))
        camera.update(distance=round(dist, 2), phi=round(float(np.degrees(np.arccos(d[2] / dist))), 2),
                      thetaOffset=round(float(np.degrees(np.arctan2(d[1], d[0]))), 2),
                      targetOffset=[round(float(v), 3) for v in target])
    config = {
        "3D!landing": {
            "cameraState": camera, "followMode": "follow-none", "followTf": "world",
            "scene": {"backgroundColor": _hex(COLORS["sky"]), "enableStats": False},
            "transforms": {"frame:world": {"visible": False}, "frame:vessel": {"visible": True}},
            "topics": {"/scene": {"visible": True}, "/fender/forces": {"visible": True}},
            "layers": {"grid": {"layerId": "foxglove.Grid", "visible": False}},
            "foxglovePanelTitle": "Landing",
        },
        "Plot!heave": plot("Heave and wave at the bow [m]", ("/vessel/state.heave", "heave [m]"),
                           ("/vessel/loads.wave_elevation_bow", "wave at the bow [m]")),
        "Plot!angles": plot("Roll, pitch [deg]", ("/vessel/state.roll_deg", "roll [deg]"),
                            ("/vessel/state.pitch_deg", "pitch [deg]")),
        "Plot!fender": plot("Fender: normal force and available friction [N]",
                            *[(contact(k, f), f"contact {k} {f.replace('_', ' ')} [N]")
                              for k in range(n_contacts) for f in ("normal_force", "available")]),
        "Plot!thrust": plot("Thrust [N]", ("/vessel/loads.thrust", "thrust [N]")),
        "Plot!slip": plot("Slip distance from the landing [m]",
                          *[(contact(k, "slip_distance"), f"contact {k} [m]") for k in range(n_contacts)]),
        "RosOut!events": {"searchTerms": [], "minLogLevel": 1, "topicToRender": "/events",
                          "foxglovePanelTitle": "Events"},
    }
    column = lambda *ids: ids[0] if len(ids) == 1 else {  # noqa: E731
        "first": ids[0], "second": column(*ids[1:]), "direction": "column", "splitPercentage": 100 / len(ids)}
    return {"configById": config, "globalVariables": {}, "userNodes": {}, "playbackConfig": {"speed": 1.0},
            "layout": {"first": "3D!landing", "second": column("Plot!heave", "Plot!angles", "Plot!fender",
                                                                "Plot!thrust", "Plot!slip", "RosOut!events"),
                       "direction": "row", "splitPercentage": 60}}


def _rgba(c, msg) -> None:
    msg.r, msg.g, msg.b, msg.a = (float(v) / 255.0 for v in c)


def _timestamp(msg, t_ns: int) -> None:
    msg.seconds, msg.nanos = divmod(int(t_ns), 1_000_000_000)


def static_scene(scene: Scene, t_ns: int) -> bytes:
    """The serialised ``foxglove.SceneUpdate`` of the static scene (see the module docstring), stamped
    ``t_ns`` (the log time of the run's start)."""
    SceneUpdate = message_class("foxglove.SceneUpdate")
    up = SceneUpdate()

    def entity(eid: str, frame: str):
        e = up.entities.add(id=eid, frame_id=frame, frame_locked=frame == "vessel")
        _timestamp(e.timestamp, t_ns)
        return e

    def triangles(e, v, tri, color):
        t = e.triangles.add()
        t.pose.orientation.w = 1.0
        for p in np.asarray(v, float):
            t.points.add(x=p[0], y=p[1], z=p[2])
        t.indices.extend(np.asarray(tri, np.uint32).ravel().tolist())
        _rgba(color, t.color)

    nw = scene.hull_wetted
    v, tri = scene.hull_vertices, np.asarray(scene.hull_triangles, np.int64)
    wet = np.all(tri < nw, axis=1)
    if wet.any():
        triangles(entity("hull/wetted", "vessel"), v[:nw], tri[wet], COLORS["antifouling"])
    if (~wet).any():
        triangles(entity("hull/topsides", "vessel"), v[nw:], tri[~wet] - nw, COLORS["topsides"])
    lines = scene.fender_lines
    if len(lines):
        ln = entity("fender", "vessel").lines.add(type=2, thickness=2 * FENDER_RADIUS)   # LINE_LIST
        ln.pose.orientation.w = 1.0
        for p in lines.reshape(-1, 3):
            ln.points.add(x=p[0], y=p[1], z=p[2])
        _rgba(COLORS["fender"], ln.color)

    def cylinder(e, x, y, d, z0, z1, color):
        c = e.cylinders.add(bottom_scale=1.0, top_scale=1.0)
        c.pose.position.x, c.pose.position.y, c.pose.position.z = x, y, 0.5 * (z0 + z1)
        c.pose.orientation.w = 1.0
        c.size.x, c.size.y, c.size.z = d, d, z1 - z0
        _rgba(color, c.color)

    mx, my, md = scene.monopile
    if md > 0:
        cylinder(entity("monopile", "world"), mx, my, md, PILE_BOTTOM, PILE_TOP, COLORS["monopile"])
    if scene.struts:
        e = entity("landing/tubes", "world")
        for x, y, d, bottom, top in scene.struts:
            cylinder(e, x, y, d, bottom, top, COLORS["tube"])
    sea = entity("sea", "world").cubes.add()
    x0, y0, psi = scene.start_pose
    sea.pose.position.x, sea.pose.position.y, sea.pose.position.z = x0, y0, -0.01
    sea.pose.orientation.z, sea.pose.orientation.w = np.sin(psi / 2), np.cos(psi / 2)
    sea.size.x, sea.size.y, sea.size.z = 2 * PATCH_HALF[0], 2 * PATCH_HALF[1], 0.02
    _rgba(COLORS["sea"], sea.color)
    return up.SerializeToString()


def arrow_items(n_contacts: int) -> list:
    """Fixed layout of one step's ``foxglove.SceneUpdate`` on ``/fender/forces`` for the step encoder:
    items ``("const", bytes)``, ``("f8", field)``, ``("timestamp", field)``, ``("msg", field, items)``."""
    f8 = lambda *fields: [("f8", k) for k in fields]  # noqa: E731
    pose = ("msg", 1, [("msg", 1, f8(1, 2, 3)), ("msg", 2, f8(1, 2, 3, 4))])
    arrow = ("msg", 7, [pose] + f8(2, 3, 4, 5) + [("msg", 6, f8(1, 2, 3, 4))])
    entity = [("timestamp", 1), ("const", b"\x12\x05world"), ("const", b"\x1a\x0dfender_forces")]
    return [("msg", 2, entity + [arrow] * (2 * n_contacts))]


def arrow_values_compiled(scene: Scene, x, fn, ft, mode) -> np.ndarray:
    """:func:`arrow_values` in one compiled pass (the run log's hot path: a block of 20 steps costs
    about a microsecond per step instead of a hundred numpy calls); equal to it to round-off."""
    g = scene.contacts
    n, nc = np.shape(fn)
    out = np.empty((n, nc * 2 * len(ARROW_FIELDS)))
    if nc and len(g.P) == nc:
        _arrow_rows(out, g.P, g.D, g.HW, g.AX, g.RT, g.N0, np.ascontiguousarray(x, float), np.asarray(fn, float),
                    np.asarray(ft, float), np.asarray(mode, np.int64), *map(float, scene.start_pose),
                    MODE_COLORS / 255.0, FORCE_SCALE, SHAFT_DIAMETER, HEAD_DIAMETER, HEAD_LENGTH)
        return out
    return arrow_values(scene, x, fn, ft, mode)


@numba.njit(cache=True)
def _arrow_rows(out, P, D, HW, AX, RT, N0, x, fn, ft, mode, x0, y0, psi0, colors, scale, shaft_d, head_d,
                head_len):  # pragma: no cover - compiled
    """Fill ``out`` (n, Nc·2·15) with :func:`arrow_values` row by row: the contact point and force
    directions of :func:`~boatland.record.scene.fender_forces`, then the arrow of each force."""
    n, nc = fn.shape
    c0, s0 = np.cos(psi0), np.sin(psi0)
    R = np.empty((3, 3))
    F = np.empty((2, 3))
    for i in range(n):
        cf, sf, ct, st = np.cos(x[i, 3]), np.sin(x[i, 3]), np.cos(x[i, 4]), np.sin(x[i, 4])
        cp, sp = np.cos(x[i, 5]), np.sin(x[i, 5])
        R[0, 0], R[0, 1], R[0, 2] = cp * ct, cp * st * sf - sp * cf, cp * st * cf + sp * sf
        R[1, 0], R[1, 1], R[1, 2] = sp * ct, sp * st * sf + cp * cf, sp * st * cf - cp * sf
        R[2, 0], R[2, 1], R[2, 2] = -st, ct * sf, ct * cf
        for c in range(nc):
            cen = np.empty(3)
            d = np.empty(3)
            for a in range(3):
                cen[a] = x[i, a] + R[a, 0] * P[c, 0] + R[a, 1] * P[c, 1] + R[a, 2] * P[c, 2]
                d[a] = R[a, 0] * D[c, 0] + R[a, 1] * D[c, 1] + R[a, 2] * D[c, 2]
            tube = np.isfinite(RT[c])
            d2 = d[0] ** 2 + d[1] ** 2
            su = 0.0
            if tube and d2 > 0:
                su = -((cen[0] - AX[c, 0]) * d[0] + (cen[1] - AX[c, 1]) * d[1]) / d2
            s = min(max(su, -HW[c]), HW[c])
            Q = cen + s * d
            m0 = R[0, 0] * D[c, 1] - R[0, 1] * D[c, 0]
            m1 = R[1, 0] * D[c, 1] - R[1, 1] * D[c, 0]
            mn = np.sqrt(m0 * m0 + m1 * m1)
            m0, m1 = m0 / mn, m1 / mn
            if not tube:
                n0, n1 = N0[c, 0], N0[c, 1]
            elif abs(su) <= HW[c] or (AX[c, 0] - Q[0]) * m0 + (AX[c, 1] - Q[1]) * m1 <= 0:
                n0, n1 = -m0, -m1
            else:
                h0, h1 = Q[0] - AX[c, 0], Q[1] - AX[c, 1]
                hn = np.sqrt(h0 * h0 + h1 * h1)
                n0, n1 = h0 / hn, h1 / hn
            F[0, 0], F[0, 1], F[0, 2] = n0 * fn[i, c], n1 * fn[i, c], 0.0
            F[1, 0], F[1, 1], F[1, 2] = -n1 * ft[i, c, 1], n0 * ft[i, c, 1], ft[i, c, 0]
            qx, qy = x0 + c0 * Q[0] - s0 * Q[1], y0 + s0 * Q[0] + c0 * Q[1]
            for k in range(2):
                fx, fy = c0 * F[k, 0] - s0 * F[k, 1], s0 * F[k, 0] + c0 * F[k, 1]
                fz = F[k, 2]
                L = np.sqrt(fx * fx + fy * fy + fz * fz) * scale
                u0, u1, u2 = 1.0, 0.0, 0.0
                if L > 0:
                    u0, u1, u2 = fx * scale / L, fy * scale / L, fz * scale / L
                q0, q1, q2, q3 = 0.0, -u2, u1, 1.0 + u0
                if q3 < 1e-9:
                    q0, q1, q2, q3 = 0.0, 0.0, 1.0, 0.0
                qn = np.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
                head = min(head_len, 0.4 * L)
                b = (2 * c + k) * 15
                out[i, b], out[i, b + 1], out[i, b + 2] = qx, qy, Q[2]
                out[i, b + 3], out[i, b + 4], out[i, b + 5], out[i, b + 6] = q0 / qn, q1 / qn, q2 / qn, q3 / qn
                out[i, b + 7], out[i, b + 8], out[i, b + 9], out[i, b + 10] = L - head, shaft_d, head, head_d
                col = colors[mode[i, c]]
                out[i, b + 11], out[i, b + 12], out[i, b + 13] = col[0], col[1], col[2]
                out[i, b + 14] = 1.0 if L > 1e-3 else 0.0


def arrow_values(scene: Scene, x, fn, ft, mode) -> np.ndarray:
    r"""(n, 2 Nc × 15) doubles of :func:`arrow_items`: per contact its normal-force arrow, then its
    friction arrow (:data:`ARROW_FIELDS` each), from :func:`~boatland.record.scene.fender_forces`.

    Each arrow starts at the contact point and points along the force F, length
    :math:`L = |F|\,` :data:`~boatland.record.scene.FORCE_SCALE`; its orientation is the shortest rotation
    of the x axis onto :math:`u = F/|F|`, the quaternion :math:`(0, -u_z, u_y, 1 + u_x)` normalised (half
    a turn about z when :math:`u = -e_x`). The readable reference of :func:`arrow_values_compiled`."""
    origin, normal, friction = fender_forces(scene, x, fn, ft)
    n, nc = fn.shape
    out = np.empty((n, nc, 2, len(ARROW_FIELDS)))
    color = MODE_COLORS[np.asarray(mode, np.int64)] / 255.0          # (n, Nc, 4)
    for k, F in enumerate((normal, friction)):
        L = np.linalg.norm(F, axis=-1) * FORCE_SCALE
        with np.errstate(invalid="ignore", divide="ignore"):
            u = np.where(L[..., None] > 0, F * FORCE_SCALE / L[..., None], [1.0, 0.0, 0.0])
        q = np.stack([np.zeros_like(L), -u[..., 2], u[..., 1], 1.0 + u[..., 0]], axis=-1)  # x axis → u
        back = q[..., 3] < 1e-9                                       # u = −x: half a turn about z
        q[back] = [0.0, 0.0, 1.0, 0.0]
        q /= np.linalg.norm(q, axis=-1, keepdims=True)
        head = np.minimum(HEAD_LENGTH, 0.4 * L)
        a = out[:, :, k]
        a[..., 0:3], a[..., 3:7] = origin, q
        a[..., 7], a[..., 8], a[..., 9], a[..., 10] = L - head, SHAFT_DIAMETER, head, HEAD_DIAMETER
        a[..., 11:14] = color[..., :3]
        a[..., 14] = np.where(L > 1e-3, 1.0, 0.0)
    return out.reshape(n, -1)


if __name__ == "__main__":      # regenerate the shipped layout from the default scenario's scene
    import json
    import warnings

    from boatland.record.scene import scene_from_trial
    from boatland.checks.files import default_scenario_path, load_checked
    from boatland.landing.setup import Setup

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        _sc, _db, _ = load_checked(default_scenario_path())
    _scene = scene_from_trial(Setup.of(_sc, _db), waves=False)
    _path = layout_path()
    _path.write_text(json.dumps(foxglove_layout(len(_scene.fender_points), _scene), indent=2) + "\n")
    print(f"wrote {_path}")
