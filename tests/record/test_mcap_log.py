"""The run log read back through the mcap reader equals the in-memory result, channel by channel."""

import json
import struct
import zlib
from datetime import datetime, timezone

import numpy as np
import pytest
from mcap.reader import make_reader
from mcap_protobuf.decoder import DecoderFactory

from boatland import __version__
from boatland.record.columns import LandingTracker, world_pose
from boatland.record.schemas import LOG_FORMAT, TOPICS, message_class
from boatland.rigid import rotation_matrix
from boatland.trial.events import landing_offset


def _read(path, topic):
    with open(path, "rb") as f:
        r = make_reader(f, decoder_factories=[DecoderFactory()])
        return [(m.log_time, obj) for _, _, m, obj in r.iter_decoded_messages(topics=[topic], log_time_order=True)]


def test_channels_schemas_counts_and_metadata(recorded):
    r = recorded.result
    with open(recorded.mcap, "rb") as f:
        reader = make_reader(f)
        s = reader.get_summary()
        topics = {c.topic: s.schemas[c.schema_id].name for c in s.channels.values()}
        counts = {s.channels[cid].topic: n for cid, n in s.statistics.channel_message_counts.items()}
        meta = {m.name: m.metadata for m in reader.iter_metadata()}
        assert reader.get_header().library == f"boatland {__version__}"
    assert topics == TOPICS
    n = len(r.t)
    assert counts["/tf"] == counts["/vessel/state"] == counts["/vessel/loads"] == counts["/fender/state"] == n
    assert counts["/fender/forces"] == n and counts["/scene"] == 1
    # the start (schemas, channels, scene), ≥ 1 s of steps per chunk (more when catching up), the end event
    assert 3 <= s.statistics.chunk_count <= int(np.ceil(n / 20)) + 2
    run = meta["boatland.run"]
    assert run["boatland"] == __version__ and int(run["seed"]) == recorded.scenario.simulation.seed
    assert json.loads(run["scenario"])["name"] == "ctv_landing" and run["run_id"] == recorded.run_id
    assert float(run["dt"]) == r.provenance["dt"] and int(run["n_steps"]) == n - 1
    assert json.loads(meta["boatland.summary"]["summary"])["slip_events"] == len(r.slip_starts())


def _epoch(path) -> int:
    """The log time of t = 0 [ns since the Unix epoch] from the run's metadata."""
    with open(path, "rb") as f:
        return int(next(m.metadata for m in make_reader(f).iter_metadata() if m.name == "boatland.run")["start_time_ns"])


def test_log_times_start_at_the_wall_clock_start_of_the_run(recorded):
    """Foxglove's timeline shows when the run was made (not 1970): log time = start (whole s) + t."""
    with open(recorded.mcap, "rb") as f:
        reader = make_reader(f)
        run = next(m.metadata for m in reader.iter_metadata() if m.name == "boatland.run")
        stats = reader.get_summary().statistics
    epoch = int(run["start_time_ns"])
    assert int(run["log_format"]) == LOG_FORMAT == 2 and epoch % 10**9 == 0
    made = recorded.mcap.stat().st_mtime
    assert made - 600 < epoch / 1e9 <= made                         # the test session's own run, minutes ago
    assert datetime.fromisoformat(run["start_time"]) == datetime.fromtimestamp(epoch // 10**9, timezone.utc)
    assert stats.message_start_time == epoch and stats.message_end_time == epoch + round(recorded.result.t[-1] * 1e9)


def test_step_values_equal_the_result(recorded):
    r = recorded.result
    n = len(r.t)
    epoch = _epoch(recorded.mcap)
    st = _read(recorded.mcap, "/vessel/state")
    assert [t for t, _ in st] == [epoch + round(t * 1e9) for t in r.t]
    np.testing.assert_array_equal([m.t for _, m in st], r.t)
    x = np.array([[m.surge, m.sway, m.heave, m.roll_deg, m.pitch_deg, m.yaw_deg] for _, m in st])
    v = np.array([[m.u, m.v, m.w, m.p_deg_s, m.q_deg_s, m.r_deg_s] for _, m in st])
    np.testing.assert_array_equal(x[:, :3], r.x[:, :3])
    np.testing.assert_array_equal(v[:, :3], r.v[:, :3])
    np.testing.assert_array_equal(x[:, 3:], np.degrees(r.x[:, 3:]))       # angles in degrees, same bits
    np.testing.assert_array_equal(v[:, 3:], np.degrees(r.v[:, 3:]))
    assert 0.5 < np.abs(x[:, 4]).max() < 20.0                             # pitch of a few degrees, not radians
    ld = [m for _, m in _read(recorded.mcap, "/vessel/loads")]
    np.testing.assert_array_equal([m.thrust for m in ld], r.thrust)
    np.testing.assert_array_equal([[m.F_surge, m.F_sway, m.F_heave, m.M_roll, m.M_pitch, m.M_yaw] for m in ld], r.F_exc)
    eta = np.array([m.wave_elevation_bow for m in ld])
    assert np.all(eta[r.t < 20.0] == 0.0) and 0.2 < np.abs(eta).max() < 2.0        # waves start at 20 s (thrust ramp)
    fs = [m for _, m in _read(recorded.mcap, "/fender/state")]
    assert len(fs) == n and all(len(m.contacts) == 2 for m in fs)
    get = lambda f: np.array([[getattr(c, f) for c in m.contacts] for m in fs])  # noqa: E731
    np.testing.assert_array_equal(get("mode"), r.mode)
    np.testing.assert_array_equal(get("normal_force"), r.fn)
    np.testing.assert_array_equal(np.stack([get("friction_vertical"), get("friction_horizontal")], 2), r.ft)
    np.testing.assert_array_equal(get("needed"), r.needed)
    np.testing.assert_array_equal(get("available"), r.available)
    np.testing.assert_array_equal(np.stack([get("plane_vertical"), get("plane_horizontal")], 2), r.tpos)
    np.testing.assert_array_equal(get("slip_distance"), r.landing_offset())       # NaN where not landed
    assert np.nanmax(get("slip_distance")) > 0.1


def test_pose_is_the_world_pose(recorded):
    r = recorded.result
    tf = _read(recorded.mcap, "/tf")
    m = tf[-1][1]
    assert (m.parent_frame_id, m.child_frame_id) == ("world", "vessel")
    assert m.timestamp.seconds * 10**9 + m.timestamp.nanos == tf[-1][0] == _epoch(recorded.mcap) + round(r.t[-1] * 1e9)
    x0, y0, psi = recorded.scenario.start_pose()
    q = np.array([m.rotation.x, m.rotation.y, m.rotation.z, m.rotation.w])
    from scipy.spatial.transform import Rotation
    R = Rotation.from_quat(q).as_matrix()
    np.testing.assert_allclose(R, rotation_matrix(r.x[-1, 3], r.x[-1, 4], psi + r.x[-1, 5]), atol=1e-12)
    np.testing.assert_allclose([m.translation.x, m.translation.y, m.translation.z],
                               [x0 + r.x[-1, 0], y0 + r.x[-1, 1], r.x[-1, 2]], atol=1e-12)   # heading 0


def test_events_are_the_result_events_incidents_and_the_end(recorded):
    r = recorded.result
    ev = [(t, m) for t, m in _read(recorded.mcap, "/events")]
    texts = [m.message for _, m in ev]
    contact = [x for x in texts if not x.startswith(("incident", "run "))]
    assert contact == [e.text() for e in r.events]
    levels = {m.message: m.level for _, m in ev}
    Log = message_class("foxglove.Log")
    assert all(levels[e.text()] == Log.WARNING for e in r.slip_events())
    incidents = {x.split(": ")[1].split(" at")[0]: float(x.split("t = ")[1].split(" s")[0])
                 for x in texts if x.startswith("incident")}
    expected = {k: v for k, v in r.incident_times().items() if v is not None and k != "contact loss"}
    assert incidents.keys() == expected.keys() and all(abs(incidents[k] - expected[k]) < 1e-9 for k in expected)
    assert texts[-1] == "run completed at t = 60.00 s"


def test_landing_tracker_matches_the_whole_run_function(recorded):
    r = recorded.result
    rng = np.random.default_rng(0)
    cuts = np.sort(rng.choice(np.arange(1, len(r.t)), 40, replace=False))
    tr = LandingTracker(r.mode.shape[1])
    parts = [tr(r.mode[a:b], r.tpos[a:b]) for a, b in zip(np.r_[0, cuts], np.r_[cuts, len(r.t)])]
    np.testing.assert_array_equal(np.concatenate(parts), landing_offset(r.mode, r.tpos))


def test_compiled_encoder_equals_the_readable_layout(recorded):
    """The hot path (one compiled pass) writes the same bytes as the numpy reference of the layout."""
    from types import SimpleNamespace

    from boatland.record.columns import Columns
    from boatland.record.foxglove_scene import arrow_values
    from boatland.record.mcap_log import NS, _Layout, block_values
    from boatland.record.scene import scene_from_trial
    from boatland.landing.setup import Setup

    r = recorded.result
    k0, k1 = 600, 620
    blk = SimpleNamespace(**{f: getattr(r, f)[k0:k1] for f in ("t", "x", "v", "F_exc", "thrust", "mode", "fn", "ft",
                                                                 "needed", "available", "tpos")})
    slip = r.landing_offset()[k0:k1]
    eta = np.linspace(-1, 1, 20)
    pose = (-16.925, 3.0, 0.3)
    tr, q = world_pose(blk.x, pose)
    c = Columns(**vars(blk), slip=slip, eta_bow=eta, translation=tr, quaternion=q)
    scene = scene_from_trial(Setup.of(recorded.scenario, recorded.db), start_pose=pose, waves=False)
    arrows = arrow_values(scene, blk.x, blk.fn, blk.ft, blk.mode)
    lay = _Layout(2)
    t_ns = np.rint(blk.t * NS).astype(np.int64) + 1_790_000_000 * NS      # log times of a run in 2026
    rows = lay.encode(t_ns, blk, slip, eta, pose, arrows)
    np.testing.assert_array_equal(rows, lay.fill(t_ns, *block_values(c, arrows)))
    # and every payload is the protobuf message its schema describes
    (a, b), (a2, b2) = lay.spans["/vessel/state"], lay.spans["/fender/forces"]
    st = message_class("boatland.VesselState").FromString(rows[3, a:b].tobytes())
    assert (st.t, st.roll_deg, st.q_deg_s) == (blk.t[3], np.degrees(blk.x[3, 3]), np.degrees(blk.v[3, 4]))
    up = message_class("foxglove.SceneUpdate").FromString(rows[3, a2:b2].tobytes())
    (e,) = up.entities
    assert e.id == "fender_forces" and e.frame_id == "world" and len(e.arrows) == 4
    assert e.timestamp.seconds * NS + e.timestamp.nanos == t_ns[3]
    tr, q = world_pose(np.zeros((1, 6)), (1.0, 2.0, np.pi / 2))
    np.testing.assert_allclose(q[0], [0, 0, np.sqrt(0.5), np.sqrt(0.5)])


def test_rerun_reads_the_log_as_pose_and_events(recorded):
    """What 'rerun run.mcap' shows: the Foxglove schemas become Transform3D and TextLog."""
    from rerun.chunk import McapReader

    store = McapReader(str(recorded.mcap), timeline_type="duration").stream().collect()
    cols = {}
    for ch in store.stream():
        cols.setdefault(ch.entity_path, set()).update(ch.to_record_batch().schema.names)
    assert any(c.startswith("Transform3D:translation") for c in cols["/tf"])
    assert any(c.startswith("TextLog:text") for c in cols["/events"])
    assert any("boatland.FenderState" in c for c in cols["/fender/state"])


def test_crcs_are_written_and_pass_the_mcap_readers_validation(recorded):
    """Chunk, data-section and summary CRCs non-zero and right: the mcap library's readers with
    ``validate_crcs=True`` read the whole file, and the summary CRC is recomputed as the spec defines it
    (CRC-32 from the summary section's start through the footer's summary_offset_start)."""
    from mcap.reader import NonSeekingReader
    from mcap.records import Chunk, DataEnd, Footer
    from mcap.stream_reader import StreamReader

    data = recorded.mcap.read_bytes()
    n = len(recorded.result.t)
    with open(recorded.mcap, "rb") as f:                 # seeking reader: chunk CRCs of every chunk read
        assert sum(1 for _ in make_reader(f, validate_crcs=True).iter_messages(topics=["/tf"])) == n
    with open(recorded.mcap, "rb") as f:                 # linear reader: chunk and data-section CRCs
        assert sum(1 for _ in NonSeekingReader(f, validate_crcs=True).iter_messages(topics=["/tf"])) == n
    with open(recorded.mcap, "rb") as f:
        recs = list(StreamReader(f, emit_chunks=True, validate_crcs=True).records)
    chunks = [r for r in recs if isinstance(r, Chunk)]
    (end,), (footer,) = [r for r in recs if isinstance(r, DataEnd)], [r for r in recs if isinstance(r, Footer)]
    assert chunks and all(c.uncompressed_crc != 0 for c in chunks)
    assert end.data_section_crc != 0 and footer.summary_crc != 0
    crc_from = footer.summary_start
    foot = data.rindex(struct.pack("<BQ", 0x02, 20), crc_from)        # the footer record (opcode 2, 20 bytes)
    assert foot == len(data) - 8 - 9 - 20
    assert zlib.crc32(data[crc_from:foot + 9 + 16]) == footer.summary_crc
    end_at = data.rindex(struct.pack("<BQ", 0x0F, 4), 0, crc_from)     # the data-end record
    assert zlib.crc32(data[:end_at]) == end.data_section_crc


@pytest.mark.parametrize("where", ["chunk", "data section"])
def test_a_flipped_byte_fails_the_crc_validation(recorded, tmp_path, where):
    """The CRCs are checked, not only present: one flipped bit in a chunk's records fails it."""
    from mcap.reader import NonSeekingReader
    from mcap.stream_reader import CRCValidationError

    with open(recorded.mcap, "rb") as f:
        ci = make_reader(f).get_summary().chunk_indexes[3]
    data = bytearray(recorded.mcap.read_bytes())
    at = ci.chunk_start_offset + ci.chunk_length - 40 if where == "chunk" else \
        ci.chunk_start_offset + ci.chunk_length + ci.message_index_length - 3  # a message index's last offset
    data[at] ^= 0x01
    bad = tmp_path / "bad.mcap"
    bad.write_bytes(bytes(data))
    record = {"chunk": "Chunk", "data section": "DataEnd"}[where]
    with open(bad, "rb") as f, pytest.raises(CRCValidationError, match=f"crc validation failed in {record}"):
        for _ in NonSeekingReader(f, validate_crcs=True).iter_messages():
            pass


def test_a_format_1_log_reads_like_format_2(recorded, tmp_path):
    """Logs written before format 2 (radians, log time = simulated time, no ``log_format``) still read:
    the recorded log rewritten the old way reads back to the same columns and events."""
    from mcap.writer import Writer

    from boatland.record.reader import read_run_log
    from boatland.record.schemas import ANGLE_FIELDS, VESSEL_STATE_FIELDS

    r = recorded.result
    epoch = _epoch(recorded.mcap)
    State = message_class("boatland.VesselState")
    old = tmp_path / "v1.mcap"
    with open(recorded.mcap, "rb") as f, open(old, "wb") as out:
        reader = make_reader(f)
        s = reader.get_summary()
        w = Writer(out)
        w.start(profile="", library=reader.get_header().library)
        sid = {i: w.register_schema(sc.name, sc.encoding, sc.data) for i, sc in s.schemas.items()}
        cid = {i: w.register_channel(c.topic, c.message_encoding, sid[c.schema_id]) for i, c in s.channels.items()}
        for m in reader.iter_metadata():
            meta = dict(m.metadata)
            for key in ("log_format", "start_time_ns", "start_time"):
                meta.pop(key, None)
            w.add_metadata(m.name, meta)
        k = 0
        for _, ch, msg in reader.iter_messages(log_time_order=False):
            data = msg.data
            if ch.topic == "/vessel/state":                   # radians, as format 1 wrote them
                st = State.FromString(data)
                for j, field in enumerate(VESSEL_STATE_FIELDS):
                    if j in ANGLE_FIELDS:
                        setattr(st, field, r.x[k, j - 1] if j < 7 else r.v[k, j - 7])
                data, k = st.SerializeToString(), k + 1
            w.add_message(cid[ch.id], msg.log_time - epoch, data, msg.publish_time - epoch, msg.sequence)
        w.finish()
    assert k == len(r.t)
    v1, v2 = read_run_log(old), read_run_log(recorded.mcap)
    assert v1.complete and "log_format" not in v1.metadata and int(v2.metadata["log_format"]) == 2
    np.testing.assert_array_equal(v1.columns.t, r.t)
    np.testing.assert_array_equal(v1.columns.x, r.x)                        # the radians as written
    np.testing.assert_array_equal(v1.columns.v, r.v)
    np.testing.assert_array_max_ulp(v2.columns.x, r.x, maxulp=1)          # through degrees: ≤ 1 ulp
    np.testing.assert_array_max_ulp(v2.columns.v, r.v, maxulp=1)
    assert v1.events == v2.events and v1.events[-1][0] == r.t[-1]           # event times from t = 0 in both
