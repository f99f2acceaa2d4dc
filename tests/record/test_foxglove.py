"""What Foxglove shows of a run log: the static 3-D scene (``/scene``), the fender force arrows
(``/fender/forces``) and the shipped layout, all read back from the recorded file."""

import pytest
import json

import numpy as np
from mcap.reader import make_reader
from mcap_protobuf.decoder import DecoderFactory

from boatland.record.foxglove_scene import foxglove_layout, layout_path
from boatland.record.scene import COLORS, FORCE_SCALE, MODE_COLORS, PILE_BOTTOM, PILE_TOP
from boatland.record.schemas import TOPICS, message_class
from boatland.landing.setup import Setup


def _messages(path, topic):
    with open(path, "rb") as f:
        r = make_reader(f, decoder_factories=[DecoderFactory()])
        return [(m.log_time, obj) for _, _, m, obj in r.iter_decoded_messages(topics=[topic], log_time_order=True)]


def _rgba(c):
    return np.array([c.r, c.g, c.b, c.a])


def test_static_scene_hull_pile_tubes_fender_and_sea(recorded):
    (t, up), = _messages(recorded.mcap, "/scene")                    # once, at the start of the run
    assert t == _messages(recorded.mcap, "/tf")[0][0]
    ents = {e.id: e for e in up.entities}
    db, sc = recorded.db, recorded.scenario
    has_topsides = getattr(db, "topsides", None) is not None
    assert set(ents) == {"hull/wetted", "fender", "monopile", "landing/tubes", "sea"} | (
        {"hull/topsides"} if has_topsides else set())
    # hull and fender move with the vessel; the landing and the sea are global
    assert {k: (e.frame_id, e.frame_locked) for k, e in ents.items() if k.startswith(("hull", "fender"))} == \
        {k: ("vessel", True) for k in ents if k.startswith(("hull", "fender"))}
    assert all(ents[k].frame_id == "world" for k in ("monopile", "landing/tubes", "sea"))
    (wet,) = ents["hull/wetted"].triangles
    pts = np.array([[p.x, p.y, p.z] for p in wet.points])
    np.testing.assert_allclose(pts, db.mesh.vertices, rtol=1e-6, atol=1e-6)  # float32 like the Rerun mesh
    assert len(wet.indices) % 3 == 0 and max(wet.indices) == len(pts) - 1
    assert pts[:, 2].max() <= 1e-6                                         # the wetted part is below the waterline
    if has_topsides:
        (top,) = ents["hull/topsides"].triangles
        np.testing.assert_allclose([[p.x, p.y, p.z] for p in top.points], db.topsides.vertices, rtol=1e-6, atol=1e-6)
    # colours that separate the hull from the sea: opaque antifouling red vs translucent blue
    hull_c, sea_c = _rgba(wet.color), _rgba(ents["sea"].cubes[0].color)
    np.testing.assert_allclose(hull_c * 255, COLORS["antifouling"])
    assert hull_c[3] == 1.0 and sea_c[3] < 0.6 and hull_c[0] > sea_c[0] + 0.2 and sea_c[2] > hull_c[2] + 0.2
    (pile,) = ents["monopile"].cylinders
    land = sc.landing
    assert (pile.pose.position.x, pile.pose.position.y) == tuple(land.monopile_position)
    assert pile.size.x == pile.size.y == land.monopile_diameter and pile.size.z == PILE_TOP - PILE_BOTTOM
    tubes = ents["landing/tubes"].cylinders
    assert len(tubes) == len(land.struts)
    for c, s in zip(tubes, land.struts):
        assert (c.pose.position.x, c.pose.position.y, c.size.x) == (*s.position, s.diameter)
        top, bottom = (s.top if np.isfinite(s.top) else PILE_TOP), (s.bottom if np.isfinite(s.bottom) else PILE_BOTTOM)
        assert c.pose.position.z == 0.5 * (top + bottom) and c.size.z == top - bottom > 0   # the tube's real ends
    (ln,) = ents["fender"].lines
    ends = np.array([[p.x, p.y, p.z] for p in ln.points]).reshape(-1, 2, 3)
    P = np.asarray(Setup.of(sc, db).contacts()[0]).reshape(-1, 3)
    np.testing.assert_allclose(ends.mean(axis=1), P, atol=1e-12)          # one line per contact, centred on it


def test_force_arrows_every_step_coloured_by_the_contact_state(recorded):
    r = recorded.result
    msgs = _messages(recorded.mcap, "/fender/forces")
    tf = _messages(recorded.mcap, "/tf")
    assert [t for t, _ in msgs] == [t for t, _ in tf]                      # one per step
    nc = r.mode.shape[1]
    arrows = [e.arrows for _, up in msgs for e in up.entities]
    assert len(arrows) == len(r.t) and all(len(a) == 2 * nc for a in arrows)
    color = np.array([[_rgba(a[2 * c].color) for c in range(nc)] for a in arrows])          # (n, Nc, 4)
    friction_color = np.array([[_rgba(a[2 * c + 1].color) for c in range(nc)] for a in arrows])
    np.testing.assert_allclose(color[..., :3] * 255, MODE_COLORS[r.mode][..., :3], atol=1e-9)
    np.testing.assert_array_equal(friction_color[..., :3], color[..., :3])
    assert {1, 2} <= set(np.unique(r.mode))                                # both stick and slip occur
    # normal arrows: length |f_n| · FORCE_SCALE, pointing horizontally from the contact towards the vessel
    length = np.array([[a[2 * c].shaft_length + a[2 * c].head_length for c in range(nc)] for a in arrows])
    np.testing.assert_allclose(length, np.abs(r.fn) * FORCE_SCALE, rtol=1e-12, atol=1e-12)
    on = r.fn > 1e3
    assert on.mean() > 0.5 and np.all(color[..., 3][on] == 1.0) and np.all(color[..., 3][r.fn == 0] == 0.0)
    q = np.array([[[a[2 * c].pose.orientation.x, a[2 * c].pose.orientation.y, a[2 * c].pose.orientation.z,
                    a[2 * c].pose.orientation.w] for c in range(nc)] for a in arrows])
    from scipy.spatial.transform import Rotation
    direction = Rotation.from_quat(q.reshape(-1, 4)).apply([1.0, 0.0, 0.0]).reshape(q.shape[:2] + (3,))
    x0, _, psi = recorded.scenario.start_pose()
    assert np.all(direction[on][:, 0] * np.cos(psi) < -0.9)               # pushed back, away from the pile
    # friction arrows: |f_t| · FORCE_SCALE
    fl = np.array([[a[2 * c + 1].shaft_length + a[2 * c + 1].head_length for c in range(nc)] for a in arrows])
    np.testing.assert_allclose(fl, np.hypot(r.ft[..., 0], r.ft[..., 1]) * FORCE_SCALE, rtol=1e-9, atol=1e-12)


@pytest.mark.slow
def test_compiled_arrows_equal_the_readable_reference(recorded):
    """The run log's compiled arrows (hot path) equal the numpy reference over the whole run, and for
    a start pose with a heading (rotation into the global frame)."""
    from boatland.record.foxglove_scene import arrow_values, arrow_values_compiled
    from boatland.record.scene import scene_from_trial

    r, sc, db = recorded.result, recorded.scenario, recorded.db
    for pose in (sc.start_pose(), (-3.0, 4.0, 0.7)):
        scene = scene_from_trial(Setup.of(sc, db), start_pose=pose, waves=False)
        ref = arrow_values(scene, r.x, r.fn, r.ft, r.mode)
        np.testing.assert_allclose(arrow_values_compiled(scene, r.x, r.fn, r.ft, r.mode), ref, rtol=1e-12, atol=1e-12)
        assert np.isfinite(ref).all()


def test_shipped_layout_is_the_generated_one_and_names_real_fields(recorded):
    shipped = json.loads(layout_path().read_text())
    assert shipped.keys() >= {"configById", "layout", "globalVariables", "userNodes", "playbackConfig"}
    # the shipped file is foxglove_layout() of the default scenario (regenerated, not hand-edited)
    from boatland.record.scene import scene_from_trial

    sc, db = recorded.scenario, recorded.db
    scene = scene_from_trial(Setup.of(sc, db), waves=False)
    assert shipped == json.loads(json.dumps(foxglove_layout(len(scene.fender_points), scene)))
    cfg = shipped["configById"]
    panels = set()

    def walk(node):
        if isinstance(node, str):
            panels.add(node)
        else:
            assert node["direction"] in ("row", "column")
            walk(node["first"]), walk(node["second"])
    walk(shipped["layout"])
    assert panels == set(cfg)
    three_d = cfg["3D!landing"]
    assert three_d["topics"].keys() == {t for t, s in TOPICS.items() if s == "foxglove.SceneUpdate"}
    # every plotted path is <topic>.<field>[.<field>] of a topic in the log, with a numeric field
    paths = [p["value"] for k, c in cfg.items() if k.startswith("Plot!") for p in c["paths"]]
    assert len(paths) >= 8
    with open(recorded.mcap, "rb") as f:
        logged = {c.topic for c in make_reader(f).get_summary().channels.values()}
    for path in paths:
        topic, _, fields = path.partition(".")
        assert topic in logged, path
        msg = message_class(TOPICS[topic])()
        for part in fields.split("."):
            name, _, index = part.partition("[")
            assert name in msg.DESCRIPTOR.fields_by_name, path
            sub = getattr(msg, name)
            if index:
                msg = sub.add()
            elif hasattr(sub, "DESCRIPTOR"):
                msg = sub
            else:
                assert isinstance(sub, float), path
    assert "/events" == cfg["RosOut!events"]["topicToRender"]
