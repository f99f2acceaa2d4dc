"""The run log: an MCAP file written block by block while the trial runs (a :class:`TrialSink`).

Every block the simulation hands over (about one second of simulated time) becomes one (lz4) chunk with
its message indexes, written and flushed before :meth:`McapLog.steps` returns: a run killed at any
moment leaves a file whose complete chunks hold every block handed over before the kill (the replay
recovers them, :mod:`boatland.record.replay`). :meth:`McapLog.finish` adds the summary section
(statistics, chunk indexes) and the footer, so a finished log is an ordinary indexed MCAP.

Messages are serialised with numpy (:class:`boatland.record.schemas.Encoder`) and the chunk records are
assembled as arrays: the per-step cost is a few array operations per block, not Python objects.
"""

from __future__ import annotations

import json
import struct
import zlib
from pathlib import Path

import lz4.frame
import numba
import numpy as np
import zstandard
from mcap.records import (Channel, DataEnd, Footer, Header, Metadata, MetadataIndex, Schema,
                          Statistics, SummaryOffset)
from mcap.data_stream import RecordBuilder
from mcap.opcode import Opcode

from boatland import __version__
from boatland.errors import BoatlandInputError
from boatland.record.columns import BowElevation, Columns, LandingTracker, settle_row, world_pose
from boatland.trial.events import track_landing
from boatland.record.scene import scene_metadata
from boatland.record.schemas import LOG_LEVEL, TOPICS, file_descriptor_set, message_class

__all__ = ["McapLog", "PROFILE", "LIBRARY", "METADATA_NAME", "SUMMARY_NAME", "columns_from_block", "block_values", "step_events", "end_event",
           "IncidentWatch"]

MAGIC = b"\x89MCAP0\r\n"
PROFILE = ""                      # protobuf messages, no ROS profile
LIBRARY = f"boatland {__version__}"
METADATA_NAME = "boatland.run"    # scenario document, version, seed, dt, start pose, …
SUMMARY_NAME = "boatland.summary"  # Result.summary() at the end of a run
NS = 1_000_000_000


def columns_from_block(block, info, tracker: LandingTracker, eta_bow: np.ndarray) -> Columns:
    """:class:`Columns` of one :class:`~boatland.trial.sink.StepBlock` (``tracker`` carries the landing
    positions from block to block; ``eta_bow`` is the bow elevation of the block's rows)."""
    tr, q = world_pose(block.x, info.start_pose)
    return Columns(t=np.asarray(block.t), x=block.x, v=block.v, F_exc=block.F_exc, thrust=block.thrust,
                   mode=block.mode, fn=block.fn, ft=block.ft, needed=block.needed, available=block.available,
                   tpos=block.tpos, slip=tracker(block.mode, block.tpos), eta_bow=eta_bow,
                   translation=tr, quaternion=q)


def _padded_varint(values: np.ndarray, width: int = 5) -> np.ndarray:
    """(n, width) bytes: non-negative integers < 2**(7 width) as fixed-width varints (continuation bits
    set on all but the last byte; protobuf parsers accept such non-minimal varints)."""
    shifts = np.arange(0, 7 * width, 7, dtype=np.int64)
    out = ((values[:, None] >> shifts) & 0x7F).astype(np.uint8)
    out[:, :-1] |= 0x80
    return out


class _Layout:
    """Byte layout of the message records of one step, all topics of :data:`STEP_TOPICS` side by side.

    Every step's records have the same size, so a block of ``n`` steps is an (n, size) byte matrix:
    the template holds the constant bytes (opcodes, lengths, channel ids, protobuf tags) and per block
    only the values are scattered in — doubles, enums, sequence numbers, times — a handful of array
    operations for the whole block.
    """

    def __init__(self, n_contacts: int, ids: dict):
        f8 = lambda first, k: [("f8", first + i) for i in range(k)]  # noqa: E731
        vec3 = [("const", b"\x22\x1b")] + f8(1, 3)                  # translation: 3 × 9 bytes
        quat = [("const", b"\x2a\x24")] + f8(1, 4)                  # rotation: 4 × 9 bytes
        contact = [("const", bytes([(2 << 3) | 2, 1 + 1 + 9 * 8])), ("enum", 1)] + f8(2, 8)
        payloads = {
            "/tf": [("timestamp", 1), ("const", b"\x12\x05world\x1a\x06vessel")] + vec3 + quat,
            "/vessel/state": f8(1, 13),
            "/vessel/loads": f8(1, 9),
            "/fender/state": f8(1, 1) + contact * n_contacts,
        }
        row, dpos, epos, seqpos, timepos, self.offsets = bytearray(), [], [], [], [], {}
        for topic, payload in payloads.items():
            start = len(row)
            self.offsets[ids[topic]] = start
            body = bytearray()
            for kind, val in payload:
                if kind == "const":
                    body += val
                elif kind == "f8":
                    body += bytes([(val << 3) | 1])
                    dpos.append(start + 31 + len(body))
                    body += bytes(8)
                elif kind == "enum":                     # values 0…127: one byte
                    body += bytes([val << 3])
                    epos.append(start + 31 + len(body))
                    body += bytes(1)
                elif kind == "timestamp":                # google.protobuf.Timestamp, 5-byte varints
                    body += bytes([(val << 3) | 2, 12, 0x08])
                    self.tpos = start + 31 + len(body)
                    body += bytes(5) + b"\x10" + bytes(5)
            row += struct.pack("<BQHIQQ", Opcode.MESSAGE, 22 + len(body), ids[topic], 0, 0, 0) + body
            seqpos += range(start + 11, start + 15)
            timepos += range(start + 15, start + 31)
        self.template = np.frombuffer(bytes(row), np.uint8)
        self.size = len(row)
        self.dpos = np.asarray(dpos, dtype=np.int64)
        self.dpos8 = (self.dpos[:, None] + np.arange(8)).ravel()
        self.epos = np.asarray(epos, dtype=np.int64)
        self.seqpos = np.asarray(seqpos, dtype=np.int64)
        self.timepos = np.asarray(timepos, dtype=np.int64)
        self.n_topics = len(payloads)

    def fill(self, seq0: int, t_ns: np.ndarray, doubles: np.ndarray, enums: np.ndarray) -> np.ndarray:
        """(n, size) bytes of ``n`` steps: ``doubles`` (n, K) in field order, ``enums`` (n, Nc)."""
        n = len(t_ns)
        rec = np.tile(self.template, (n, 1))
        seq = np.arange(seq0, seq0 + n, dtype="<u4").view(np.uint8).reshape(n, 4)
        rec[:, self.seqpos] = np.tile(seq, (1, self.n_topics))
        tb = t_ns.astype("<u8").view(np.uint8).reshape(n, 8)
        rec[:, self.timepos] = np.tile(tb, (1, 2 * self.n_topics))
        rec[:, self.dpos8] = doubles.view(np.uint8).reshape(n, -1)
        rec[:, self.epos] = enums
        rec[:, self.tpos:self.tpos + 5] = _padded_varint(t_ns // NS)
        rec[:, self.tpos + 6:self.tpos + 11] = _padded_varint(t_ns % NS)
        return rec

    def encode(self, seq0: int, t_ns: np.ndarray, block, slip: np.ndarray, eta: np.ndarray, start_pose) -> np.ndarray:
        """Same bytes as ``fill(seq0, t_ns, *block_values(columns))``, compiled: the hot path."""
        out = np.empty((len(t_ns), self.size), np.uint8)
        x0, y0, psi = start_pose
        _encode_steps(out, self.template, self.dpos, self.epos, self.seqpos, self.timepos, self.tpos, seq0, t_ns,
                      block.t, block.x, block.v, block.F_exc, block.thrust, eta, block.fn, block.ft, block.needed,
                      block.available, slip, block.tpos, block.mode, float(x0), float(y0), float(psi))
        return out


STEP_TOPICS = ("/tf", "/vessel/state", "/vessel/loads", "/fender/state")


@numba.njit(cache=True)
def _put(out, i, pos, value, scratch):
    """The 8 little-endian bytes of ``value`` at ``out[i, pos:pos+8]``."""
    scratch[0] = value
    b = scratch.view(np.uint8)
    for j in range(8):
        out[i, pos + j] = b[j]


@numba.njit(cache=True)
def _encode_steps(out, template, dpos, epos, seqpos, timepos, tpos, seq0, t_ns, t, x, v, F, thrust, eta, fn, ft,
                  needed, available, slip, tp, mode, x0, y0, psi):  # pragma: no cover - compiled
    """Fill ``out`` (n, size) with the message records of n steps: :meth:`_Layout.fill` of
    :func:`block_values` in one compiled pass (pose as :func:`~boatland.record.columns.world_pose`)."""
    n, nc = mode.shape
    f8 = np.empty(1, np.float64)
    i8 = np.empty(1, np.int64)
    vals = np.empty(dpos.size)
    cpsi, spsi = np.cos(psi), np.sin(psi)
    for i in range(n):
        out[i, :] = template
        vals[0] = x0 + cpsi * x[i, 0] - spsi * x[i, 1]
        vals[1] = y0 + spsi * x[i, 0] + cpsi * x[i, 1]
        vals[2] = x[i, 2]
        hr, hp, hy = 0.5 * x[i, 3], 0.5 * x[i, 4], 0.5 * (x[i, 5] + psi)
        cr, sr, cp, sp, cy, sy = np.cos(hr), np.sin(hr), np.cos(hp), np.sin(hp), np.cos(hy), np.sin(hy)
        vals[3] = sr * cp * cy - cr * sp * sy
        vals[4] = cr * sp * cy + sr * cp * sy
        vals[5] = cr * cp * sy - sr * sp * cy
        vals[6] = cr * cp * cy + sr * sp * sy
        vals[7] = t[i]
        for k in range(6):
            vals[8 + k] = x[i, k]
            vals[14 + k] = v[i, k]
            vals[22 + k] = F[i, k]
        vals[20] = t[i]
        vals[21] = thrust[i]
        vals[28] = eta[i]
        vals[29] = t[i]
        for c in range(nc):
            b = 30 + 8 * c
            vals[b], vals[b + 1], vals[b + 2] = fn[i, c], ft[i, c, 0], ft[i, c, 1]
            vals[b + 3], vals[b + 4], vals[b + 5] = needed[i, c], available[i, c], slip[i, c]
            vals[b + 6], vals[b + 7] = tp[i, c, 0], tp[i, c, 1]
            out[i, epos[c]] = mode[i, c]
        for k in range(dpos.size):
            _put(out, i, dpos[k], vals[k], f8)
        seq = seq0 + i
        for j in range(seqpos.size):
            out[i, seqpos[j]] = (seq >> (8 * (j % 4))) & 0xFF
        i8[0] = t_ns[i]
        tb = i8.view(np.uint8)
        for j in range(timepos.size):
            out[i, timepos[j]] = tb[j % 8]
        sec, nsec = t_ns[i] // 1_000_000_000, t_ns[i] % 1_000_000_000
        for j in range(5):
            more = 0x80 if j < 4 else 0
            out[i, tpos + j] = ((sec >> (7 * j)) & 0x7F) | more
            out[i, tpos + 6 + j] = ((nsec >> (7 * j)) & 0x7F) | more


def block_values(c: Columns) -> tuple[np.ndarray, np.ndarray]:
    """The doubles of the step messages in field order, (n, K), and the contact modes (n, Nc) uint8."""
    n, nc = c.mode.shape
    per_contact = np.stack([c.fn, c.ft[:, :, 0], c.ft[:, :, 1], c.needed, c.available, c.slip,
                            c.tpos[:, :, 0], c.tpos[:, :, 1]], axis=2).reshape(n, 8 * nc)
    t = c.t[:, None]
    V = np.concatenate([c.translation, c.quaternion, t, c.x, c.v, t, c.thrust[:, None], c.F_exc,
                        c.eta_bow[:, None], t, per_contact], axis=1, dtype="<f8")
    return V, c.mode.astype(np.uint8)


class McapLog:
    """Writes a trial to ``path`` as it runs (implements :class:`~boatland.trial.sink.TrialSink`).

    Parameters
    ----------
    path : str or Path
        The ``.mcap`` file; replaced if it exists.
    compression : {"lz4", "zstd", ""}
        Chunk compression: lz4 (default) is about 5 µs per block against 25 µs for zstd level 1, for
        files 3 % larger (the doubles of the states hardly compress).
    run_id : str, optional
        Stored in the metadata; the replay uses it as Rerun recording id (give the live Rerun stream
        the same one).

    Notes
    -----
    Loss on a crash: each :meth:`steps` call writes its block as complete chunk + indexes and flushes
    the file before returning, so a killed run keeps every block handed over before it was killed
    (the block being written at that moment, at most about 1 s of simulated time, may be lost). The
    sea at the bow is summed per block (:class:`~boatland.record.columns.BowElevation`), so the first
    block is written as soon as the kernel has finished it.
    """

    def __init__(self, path: str | Path, *, compression: str = "lz4", run_id: str = ""):
        self.path = Path(path)
        self.run_id = run_id
        self.compression = compression
        if compression not in ("lz4", "zstd", ""):
            raise ValueError(f"compression: expected 'lz4', 'zstd' or '', got {compression!r}")
        self._compress = {"lz4": lz4.frame.compress, "zstd": zstandard.ZstdCompressor(level=1).compress,
                          "": None}[compression]
        self._f = None
        self.info = None

    # --------------------------------------------------------------------------- sink interface
    def start(self, info) -> None:
        self.info = info
        try:
            self._f = open(self.path, "wb")
        except OSError as exc:
            raise BoatlandInputError(f"{self.path}: cannot write the run log: {exc.strerror}") from None
        self._pos = 0
        self._chunk_indexes: list[bytes] = []
        self._meta_indexes: list[MetadataIndex] = []
        self._counts = {topic: 0 for topic in TOPICS}
        self._t_range = [None, None]
        nc = np.asarray(info.contacts[0]).reshape(-1, 3).shape[0]
        self._anchor = np.full((nc, 2), np.nan)      # landing positions carried across blocks
        self._eta = BowElevation(info)   # the sea at the bow, summed block by block
        self._incidents = IncidentWatch(info.scenario)
        self._log_cls = message_class("foxglove.Log")
        b = RecordBuilder()
        Header(profile=PROFILE, library=LIBRARY).write(b)
        self._schemas, self._channels = [], []
        for i, (topic, name) in enumerate(TOPICS.items(), 1):
            s = Schema(id=i, name=name, encoding="protobuf", data=file_descriptor_set(name))
            ch = Channel(id=i, topic=topic, message_encoding="protobuf", schema_id=i, metadata={})
            s.write(b)
            ch.write(b)
            self._schemas.append(s)
            self._channels.append(ch)
        self._ids = {topic: i for i, topic in enumerate(TOPICS, 1)}
        self._layout = _Layout(nc, self._ids)
        self._step_offsets = np.array([self._layout.offsets[self._ids[t]] for t in STEP_TOPICS], "<u8")
        self._mi_cache: dict = {}
        self._write(MAGIC)
        self._write(b.end())
        self._metadata(METADATA_NAME, run_metadata(info) | {"run_id": self.run_id})
        self._f.flush()

    def steps(self, block) -> None:
        slip = np.empty(block.mode.shape)
        worst = track_landing(block.mode, block.tpos, self._anchor, slip, max(0, settle_row(self.info) - block.k0))
        t_ns = np.rint(np.asarray(block.t) * NS).astype(np.int64)
        rows = self._layout.encode(self._counts["/tf"], t_ns, block, slip, self._eta(block.k0, block.k1),
                                   self.info.start_pose)
        events = [] if not block.events and not self._incidents.may_fire(worst, block.x) else \
            step_events(block, block.t, block.x, slip, self._incidents)
        if events:
            self._write_chunk([(STEP_TOPICS, t_ns, rows),
                               ("/events", np.array([e[0] for e in events], np.int64), self._log_records(events))])
        else:
            self._write_steps_chunk(t_ns, rows)

    def finish(self, result) -> None:
        if self._f is None:
            return
        t_end, level, text = end_event(result)
        self._write_chunk([("/events", np.array([t_end], np.int64), self._log_records([(t_end, level, text)]))])
        self._metadata(SUMMARY_NAME, {"summary": json.dumps(result.summary(), default=float)})
        self._close()

    def close(self) -> None:
        """Finish the file without a result (e.g. after an error elsewhere): still a valid MCAP."""
        if self._f is not None:
            self._close()

    # --------------------------------------------------------------------------------- writing
    def _write(self, data) -> None:
        self._f.write(data)
        self._pos += len(data)

    def _metadata(self, name: str, meta: dict) -> None:
        b = RecordBuilder()
        Metadata(name=name, metadata={k: str(v) for k, v in meta.items()}).write(b)
        data = b.end()
        self._meta_indexes.append(MetadataIndex(offset=self._pos, length=len(data), name=name))
        self._write(data)

    def _log_records(self, events) -> list[bytes]:
        """Message records (header + foxglove.Log) of a few events ``(t_ns, level, text)``."""
        out = []
        cid, seq = self._ids["/events"], self._counts["/events"]
        for i, (t_ns, level, text) in enumerate(events):
            m = self._log_cls(level=LOG_LEVEL[level], message=text, name="boatland")
            m.timestamp.seconds, m.timestamp.nanos = divmod(int(t_ns), NS)
            data = m.SerializeToString()
            out.append(struct.pack("<BQHIQQ", Opcode.MESSAGE, 22 + len(data), cid, seq + i, t_ns, t_ns) + data)
        return out

    def _write_steps_chunk(self, t_ns: np.ndarray, rows: np.ndarray) -> None:
        """The common case of :meth:`_write_chunk`: a block of steps without events, with the message
        indexes of the four step channels built as one structured array (cached layout per block size)."""
        n, size = rows.shape
        mi = self._mi_cache.get(n)
        if mi is None:
            dt = np.dtype([("op", "u1"), ("len", "<u8"), ("cid", "<u2"), ("nb", "<u4"),
                           ("e", [("t", "<u8"), ("o", "<u8")], (n,))])
            mi = np.zeros(len(STEP_TOPICS), dt)
            mi["op"], mi["len"], mi["nb"] = Opcode.MESSAGE_INDEX, 6 + 16 * n, 16 * n
            mi["cid"] = [self._ids[t] for t in STEP_TOPICS]
            mi["e"]["o"] = size * np.arange(n, dtype="<u8")[None, :] + self._step_offsets[:, None]
            self._mi_cache[n] = mi
        mi["e"]["t"] = t_ns[None, :]
        for name in STEP_TOPICS:
            self._counts[name] += n
        raw = rows.data
        data = self._compress(raw) if self._compress else bytes(raw)
        t_lo, t_hi = int(t_ns[0]), int(t_ns[-1])
        comp = self.compression.encode()
        body = (struct.pack("<QQQI", t_lo, t_hi, rows.size, zlib.crc32(raw)) + struct.pack("<I", len(comp))
                + comp + struct.pack("<Q", len(data)))
        chunk_start = self._pos
        mi_start = chunk_start + 9 + len(body) + len(data)
        self._write(struct.pack("<BQ", Opcode.CHUNK, len(body) + len(data)) + body + data + mi.tobytes())
        rec_len = 15 + 16 * n
        offsets = b"".join(struct.pack("<HQ", self._ids[t], mi_start + j * rec_len) for j, t in enumerate(STEP_TOPICS))
        ci = (struct.pack("<QQQQI", t_lo, t_hi, chunk_start, mi_start - chunk_start, len(offsets)) + offsets
              + struct.pack("<QI", len(STEP_TOPICS) * rec_len, len(comp)) + comp
              + struct.pack("<QQ", len(data), rows.size))
        self._chunk_indexes.append(struct.pack("<BQ", Opcode.CHUNK_INDEX, len(ci)) + ci)
        self._t_range = [t_lo if self._t_range[0] is None else min(self._t_range[0], t_lo),
                         t_hi if self._t_range[1] is None else max(self._t_range[1], t_hi)]
        self._f.flush()

    def _write_chunk(self, recs: list) -> None:
        """One chunk holding ``recs`` = [(topic, log times (n,), records (n, size) array or list of bytes)],
        then its message indexes; flushed."""
        parts, index_recs, offset = [], [], 0
        t_lo = min(int(t[0]) for _, t, _ in recs)     # times are in order within each group
        t_hi = max(int(t[-1]) for _, t, _ in recs)
        for topic, times, rec in recs:
            n = len(times)
            if isinstance(rec, list):                  # a few events
                sizes = np.array([len(r) for r in rec])
                parts.append(b"".join(rec))
                idx = np.empty((n, 2), "<u8")
                idx[:, 0] = times
                idx[:, 1] = offset + np.concatenate([[0], np.cumsum(sizes)[:-1]])
                index_recs.append((self._ids[topic], idx))
                self._counts[topic] += n
                offset += int(sizes.sum())
                continue
            parts.append(rec.tobytes())                # the step topics: one row of records per step
            idx = np.empty((len(topic), n, 2), "<u8")
            idx[:, :, 0] = times
            idx[:, :, 1] = (offset + rec.shape[1] * np.arange(n, dtype="<u8"))[None, :] + self._step_offsets[:, None]
            for j, name in enumerate(topic):
                index_recs.append((self._ids[name], idx[j]))
                self._counts[name] += n
            offset += rec.size
        records = b"".join(parts)
        data = self._compress(records) if self._compress else records
        comp = self.compression.encode()
        body = (struct.pack("<QQQI", t_lo, t_hi, len(records), zlib.crc32(records)) + struct.pack("<I", len(comp))
                + comp + struct.pack("<Q", len(data)))
        chunk_start = self._pos
        out = [struct.pack("<BQ", Opcode.CHUNK, len(body) + len(data)), body, data]
        mi_offsets, mi_start = {}, chunk_start + 9 + len(body) + len(data)
        pos = mi_start
        for cid, idx in index_recs:
            nb = 16 * len(idx)
            mi_offsets[cid] = pos
            out.append(struct.pack("<BQHI", Opcode.MESSAGE_INDEX, 6 + nb, cid, nb))
            out.append(idx.tobytes())
            pos += 15 + nb
        self._write(b"".join(out))
        offsets = b"".join(struct.pack("<HQ", cid, off) for cid, off in mi_offsets.items())
        ci = (struct.pack("<QQQQI", t_lo, t_hi, chunk_start, mi_start - chunk_start, len(offsets)) + offsets
              + struct.pack("<QI", pos - mi_start, len(comp)) + comp + struct.pack("<QQ", len(data), len(records)))
        self._chunk_indexes.append(struct.pack("<BQ", Opcode.CHUNK_INDEX, len(ci)) + ci)
        self._t_range = [t_lo if self._t_range[0] is None else min(self._t_range[0], t_lo),
                         t_hi if self._t_range[1] is None else max(self._t_range[1], t_hi)]
        self._f.flush()

    def _close(self) -> None:
        b = RecordBuilder()
        DataEnd(data_section_crc=0).write(b)
        self._write(b.end())
        summary_start = self._pos
        groups = []

        def group(opcode, records):
            if not records:
                return
            start = self._pos
            if isinstance(records[0], bytes):          # chunk indexes, serialised as they were written
                self._write(b"".join(records))
            else:
                for r in records:
                    r.write(b)
                self._write(b.end())
            groups.append(SummaryOffset(group_opcode=opcode, group_start=start, group_length=self._pos - start))

        group(Opcode.SCHEMA, self._schemas)
        group(Opcode.CHANNEL, self._channels)
        group(Opcode.STATISTICS, [Statistics(
            message_count=sum(self._counts.values()), schema_count=len(self._schemas),
            channel_count=len(self._channels), attachment_count=0, metadata_count=len(self._meta_indexes),
            chunk_count=len(self._chunk_indexes), message_start_time=self._t_range[0] or 0,
            message_end_time=self._t_range[1] or 0,
            channel_message_counts={self._ids[t]: n for t, n in self._counts.items()})])
        group(Opcode.METADATA_INDEX, self._meta_indexes)
        group(Opcode.CHUNK_INDEX, self._chunk_indexes)
        offset_start = self._pos
        for g in groups:
            g.write(b)
        Footer(summary_start=summary_start, summary_offset_start=offset_start, summary_crc=0).write(b)
        self._write(b.end())
        self._write(MAGIC)
        self._f.close()
        self._f = None


def run_metadata(info) -> dict:
    """The metadata record of a run: scenario (document as JSON, source, base directory), version, seed…"""
    sc = info.scenario
    return {"boatland": __version__, "scenario_name": sc.name, "scenario": json.dumps(sc.document, default=str),
            "scenario_source": str(sc.source), "scenario_base_dir": str(sc.base_dir or ""),
            "scenario_sha256": sc.digest(), "database": info.db.name, "seed": sc.simulation.seed,
            "dt": repr(float(info.dt)), "n_steps": info.n_steps, "start_pose": json.dumps(list(map(float, info.start_pose))),
            "n_contacts": np.asarray(info.contacts[0]).reshape(-1, 3).shape[0],
            "provenance": json.dumps(info.provenance, default=str),
            "scene": json.dumps(scene_metadata(sc, info.contacts))}


def step_events(block, t, x, slip, incidents: "IncidentWatch") -> list[tuple[int, str, str]]:
    """Events of a block as ``(t_ns, level, text)``: contact events, then first incidents."""
    events = [(round(e.t * NS), "WARNING" if e.kind == "stick→slip" else "INFO", e.text()) for e in block.events]
    return events + [(round(ti * NS), "WARNING", text) for ti, text in incidents(t, x, slip)]


def end_event(result) -> tuple[int, str, str]:
    """The closing event of a run: completed, or why it stopped."""
    t_end = float(result.t[-1]) if len(result.t) else 0.0
    return round(t_end * NS), "INFO" if result.status == 0 else "ERROR", f"run {result.message} at t = {t_end:.2f} s"


class IncidentWatch:
    """First exceedances of the scenario's incident definitions, found block by block (slip distance over
    a threshold, roll over a limit; contact loss is already a contact event)."""

    def __init__(self, scenario):
        inc = scenario.incidents
        self.slip = list(inc.slip_distance) if inc is not None else [0.1]
        self.roll = list(inc.roll_limit_deg) if inc is not None else []
        self.done: set = set()

    def may_fire(self, worst_slip: float, x: np.ndarray) -> bool:
        """Cheap pre-check: could a pending incident be in this block (largest slip, motions)?"""
        pending_slip = [lim for lim in self.slip if f"slip > {lim:g} m" not in self.done]
        if pending_slip and worst_slip > min(pending_slip):
            return True
        pending_roll = [lim for lim in self.roll if f"roll > {lim:g}°" not in self.done]
        return bool(pending_roll) and np.degrees(np.abs(x[:, 3]).max()) > min(pending_roll)

    def __call__(self, t, x, slip) -> list[tuple[float, str]]:
        out = []
        if len(self.done) == len(self.slip) + len(self.roll):
            return out
        if slip.shape[1] and len(self.done) < len(self.slip):
            worst = np.fmax.reduce(slip, axis=1)          # NaN (not landed) only where all are NaN
            for lim in self.slip:
                key = f"slip > {lim:g} m"
                if key not in self.done and (k := np.nonzero(worst > lim)[0]).size:
                    self.done.add(key)
                    out.append((float(t[k[0]]), f"incident: {key} at t = {t[k[0]]:.2f} s"))
        roll_max = np.degrees(np.abs(x[:, 3]).max()) if self.roll else 0.0
        for lim in self.roll:
            key = f"roll > {lim:g}°"
            if roll_max > lim and key not in self.done and (k := np.nonzero(np.abs(x[:, 3]) > np.radians(lim))[0]).size:
                self.done.add(key)
                out.append((float(t[k[0]]), f"incident: {key} at t = {t[k[0]]:.2f} s"))
        return out
