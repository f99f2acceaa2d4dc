"""The live Rerun stream (.rrd) read back with rerun.chunk.RrdReader, and its replay from the MCAP log."""

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc
import pytest
from rerun.chunk import RrdReader

from boatland.record.replay import replay
from boatland.record.rerun_log import TIMELINE
from boatland.record.scene import COLORS, FORCE_SCALE, MODE_COLORS


def contents(path) -> dict:
    """entity → {column: (times [s], values)} of the temporal data, plus static columns under time None."""
    store = RrdReader(str(path)).stream().collect()
    out: dict = {}
    for ch in store.stream():
        rb = ch.to_record_batch()
        ent = out.setdefault(ch.entity_path, {})
        t = None if ch.is_static else rb.column(TIMELINE).cast(pa.int64()).to_numpy() / 1e9
        for name in rb.schema.names:
            if name == TIMELINE or ":" not in name:
                continue
            col = rb.column(name)
            while pa.types.is_list(col.type) or pa.types.is_fixed_size_list(col.type) or pa.types.is_large_list(col.type):
                col = pc.list_flatten(col)
            vals = col.to_numpy(zero_copy_only=False) if not pa.types.is_struct(col.type) else np.array(col.to_pylist(), object)
            key = (name, ch.is_static)
            if key in ent:
                t0, v0 = ent[key]
                ent[key] = (None if t is None else np.concatenate([t0, t]), np.concatenate([v0, vals]))
            else:
                ent[key] = (t, vals)
    return out


@pytest.fixture(scope="module")
def live(recorded):
    return contents(recorded.rrd)


def test_live_stream_entities_timelines_and_values(recorded, live):
    r = recorded.result
    for ent in ("/world/vessel", "/world/vessel/hull", "/world/vessel/fender", "/world/vessel/fender_line",
                "/world/fender_forces", "/world/monopile", "/world/landing/struts", "/world/sea",
                "/plots/motion/heave", "/plots/motion/roll", "/plots/motion/pitch", "/plots/fender/0/normal",
                "/plots/fender/1/available", "/plots/slip/0", "/plots/loads/thrust", "/plots/sea/bow_elevation",
                "/events"):
        assert ent in live, ent
    t, heave = live["/plots/motion/heave"][("Scalars:scalars", False)]
    np.testing.assert_allclose(t, r.t, atol=1e-9)
    np.testing.assert_array_equal(heave, r.x[:, 2])
    np.testing.assert_array_equal(live["/plots/motion/roll"][("Scalars:scalars", False)][1], np.degrees(r.x[:, 3]))
    np.testing.assert_array_equal(live["/plots/fender/1/available"][("Scalars:scalars", False)][1], r.available[:, 1] / 1e3)
    np.testing.assert_array_equal(live["/plots/slip/0"][("Scalars:scalars", False)][1], r.landing_offset()[:, 0])
    tt, tr = live["/world/vessel"][("Transform3D:translation", False)]
    x0, y0, _ = recorded.scenario.start_pose()
    np.testing.assert_allclose(tr.reshape(-1, 3), np.column_stack([x0 + r.x[:, 0], y0 + r.x[:, 1], r.x[:, 2]]),
                               rtol=1e-6, atol=1e-5)                          # float32 in Rerun
    hull = live["/world/vessel/hull"][("Mesh3D:vertex_positions", True)][1].reshape(-1, 3)
    wetted = recorded.db.mesh.vertices
    np.testing.assert_allclose(hull[:len(wetted)], wetted, rtol=1e-6, atol=1e-6)
    hull_colors = live["/world/vessel/hull"][("Mesh3D:vertex_colors", True)][1]
    np.testing.assert_array_equal(np.unique(hull_colors[:len(wetted)]), [_packed(COLORS["antifouling"])])
    if getattr(recorded.db, "topsides", None) is not None:    # the hull above water follows: topsides, deck
        np.testing.assert_allclose(hull[len(wetted):], recorded.db.topsides.vertices, rtol=1e-6, atol=1e-6)
        np.testing.assert_array_equal(np.unique(hull_colors[len(wetted):]), [_packed(COLORS["topsides"])])
    else:
        assert len(hull) == len(wetted)
    # what the viewer draws over time must not be shadowed by static data of the same component
    for ent, comp in (("/world/vessel/fender", "Points3D:colors"), ("/world/sea", "Mesh3D:vertex_positions"),
                      ("/world/fender_forces", "Arrows3D:vectors")):
        assert (comp, False) in live[ent] and (comp, True) not in live[ent], (ent, comp)
    colors = live["/world/vessel/fender"][("Points3D:colors", False)][1].reshape(len(r.t), 2)
    assert len(np.unique(colors)) == 3          # open, stick and slip colours all occur
    np.testing.assert_array_equal(colors, _packed(MODE_COLORS[r.mode]))
    radii = live["/world/vessel/fender"][("Points3D:radii", True)][1]
    assert np.all(radii >= 0.3)                 # visible next to a 24 m hull
    ts, sea = live["/world/sea"][("Mesh3D:vertex_positions", False)]
    assert np.isclose(ts[1] - ts[0], 0.5) and ts[-1] == 60.0
    assert np.ptp(sea.reshape(-1, 3)[:, 2]) > 0.5            # the sea moves (waves from 20 s)
    ta, vec = live["/world/fender_forces"][("Arrows3D:vectors", False)]
    vec = vec.reshape(len(r.t), 2 * r.mode.shape[1], 3)
    np.testing.assert_allclose(np.linalg.norm(vec[:, 0::2], axis=-1), np.abs(r.fn) * FORCE_SCALE, rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(vec[:, 1::2], axis=-1), np.hypot(r.ft[..., 0], r.ft[..., 1]) * FORCE_SCALE,
                               rtol=1e-6, atol=1e-6)        # float32 in Rerun
    arrow_colors = live["/world/fender_forces"][("Arrows3D:colors", False)][1].reshape(len(r.t), -1)
    np.testing.assert_array_equal(arrow_colors, np.repeat(_packed(MODE_COLORS[r.mode]), 2, axis=1))
    np.testing.assert_array_equal(live["/plots/loads/thrust"][("Scalars:scalars", False)][1], r.thrust / 1e3)
    ev_t, ev = live["/events"][("TextLog:text", False)]
    assert [x for x in ev if not x.startswith(("incident", "run "))] == [e.text() for e in r.events]
    assert ev[-1] == "run completed at t = 60.00 s"


def _packed(rgba) -> np.ndarray:
    """Rerun's packed colours (0xRRGGBBAA as uint32) of (..., 4) uint8 RGBA."""
    c = np.asarray(rgba, np.uint32)
    return (c[..., 0] << 24) | (c[..., 1] << 16) | (c[..., 2] << 8) | c[..., 3]


def test_default_blueprint_has_a_camera_on_the_landing_and_the_plot_views(recorded):
    """The layout a viewer opens with: a 3D view whose eye looks at the bow and the landing from the
    vessel's port side, and time-series views that name thrust and the bow elevation."""
    import rerun.blueprint as rrb

    from boatland.record.rerun_log import blueprint
    from boatland.record.scene import scene_from_trial
    from boatland.landing.setup import Setup

    sc, db = recorded.scenario, recorded.db
    scene = scene_from_trial(Setup.of(sc, db), waves=False)
    eye, target = scene.camera()
    bow = scene.to_world(scene.fender_points.mean(axis=0))
    x0, y0, psi = sc.start_pose()
    assert x0 < target[0] < bow[0] and eye[2] > 5.0                     # between the vessel and its bow, from above
    side = -np.sin(psi) * (eye[0] - target[0]) + np.cos(psi) * (eye[1] - target[1])
    assert side > 10.0                                                  # from the port side
    views = {}

    def walk(node):
        for child in getattr(node, "contents", []) or []:
            walk(child)
        if isinstance(node, (rrb.Spatial3DView, rrb.TimeSeriesView, rrb.TextLogView)):
            views[node.name] = node
    walk(blueprint(2, scene).root_container)
    assert any(isinstance(v, rrb.Spatial3DView) for v in views.values())
    titles = [str(k) for k in views]
    assert any("Thrust" in t for t in titles) and any("wave at the bow" in t for t in titles)
    assert any("Friction needed vs available" in t for t in titles) and any("[deg]" in t for t in titles)
    assert any(isinstance(v, rrb.TextLogView) for v in views.values())


def test_replay_of_the_mcap_equals_the_live_stream(recorded, live, tmp_path):
    out = tmp_path / "replay.rrd"
    done = replay(recorded.mcap, f"save={out}")
    assert done.notes == [] and done.log.complete
    again = contents(out)
    assert again.keys() == live.keys()
    for ent, cols in live.items():
        for key, (t, v) in cols.items():
            if ent == "/__properties" or key[0].startswith("RecordingInfo"):
                continue
            t2, v2 = again[ent][key]
            if t is not None:
                np.testing.assert_allclose(t2, t, atol=1e-9, err_msg=ent)
            if v.dtype.kind == "f":
                tol = 1e-9 if ent == "/world/sea" else 0
                np.testing.assert_allclose(v2, v, rtol=0, atol=tol, err_msg=f"{ent} {key}")
            else:
                assert list(v2) == list(v), (ent, key)
