"""The live Rerun stream (.rrd) read back with rerun.chunk.RrdReader, and its replay from the MCAP log."""

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc
import pytest
from rerun.chunk import RrdReader

from boatland.record.replay import replay
from boatland.record.rerun_log import TIMELINE


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
    for ent in ("/world/vessel", "/world/vessel/hull", "/world/vessel/fender", "/world/monopile",
                "/world/landing/struts", "/world/sea", "/plots/motion/heave", "/plots/motion/roll",
                "/plots/motion/pitch", "/plots/fender/0/normal", "/plots/fender/1/available", "/plots/slip/0",
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
    np.testing.assert_allclose(hull, recorded.db.mesh.vertices, rtol=1e-6, atol=1e-6)
    colors = live["/world/vessel/fender"][("Points3D:colors", False)][1].reshape(len(r.t), 2)
    assert len(np.unique(colors)) == 3          # open, stick and slip colours all occur
    ts, sea = live["/world/sea"][("Mesh3D:vertex_positions", False)]
    assert np.isclose(ts[1] - ts[0], 0.5) and ts[-1] == 60.0
    ev_t, ev = live["/events"][("TextLog:text", False)]
    assert [x for x in ev if not x.startswith(("incident", "run "))] == [e.text() for e in r.events]
    assert ev[-1] == "run completed at t = 60.00 s"


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
