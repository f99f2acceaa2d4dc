"""The run log: an MCAP file written block by block while the trial runs (a :class:`TrialSink`).

The file is framed by the ``mcap`` library's :class:`mcap.writer.Writer` (chunks, message indexes,
summary, CRCs: the chunks', the data section's and the summary's). Every block the simulation hands
over (about one second of simulated time) becomes one chunk with its message indexes, written and
flushed (:meth:`mcap.writer.Writer.flush`) before :meth:`McapLog.steps` returns: a run killed at any
moment leaves a file whose complete chunks hold every block handed over before the kill (the replay
recovers them, :mod:`boatland.record.replay`). :meth:`McapLog.finish` adds the summary section and the
footer, so a finished log is an ordinary indexed MCAP.

The messages of a block are serialised at once by a compiled encoder into an (n, size) byte matrix
(:class:`_Layout`): every step's messages have the same bytes layout, only the values change, so the
per-step cost is the library's framing of the five step messages, not protobuf objects.

Time: ``log_time`` = the run's wall-clock start (whole seconds since the Unix epoch, UTC; metadata
``start_time_ns``, ``start_time``) + the simulated time, so Foxglove's timeline shows when the run was
made; the messages also carry the simulated time ``t``. Angles are logged in degrees
(:data:`~boatland.record.schemas.LOG_FORMAT` 2, :mod:`boatland.record.schemas`).
"""

from __future__ import annotations

import json
import time
from datetime import datetime, timezone
from pathlib import Path

import numba
import numpy as np
from mcap.writer import CompressionType, Writer

from boatland import __version__
from boatland.errors import BoatlandInputError
from boatland.record.columns import BowElevation, Columns, LandingTracker, settle_row, world_pose
from boatland.record.foxglove_scene import arrow_items, arrow_values_compiled, static_scene
from boatland.record.scene import Scene, scene_from_trial, scene_metadata
from boatland.record.schemas import LOG_FORMAT, LOG_LEVEL, RAD2DEG, TOPICS, file_descriptor_set, \
    message_class
from boatland.trial.events import track_landing
from boatland.trial.incidents import IncidentWatch

__all__ = ["McapLog", "PROFILE", "LIBRARY", "METADATA_NAME", "SUMMARY_NAME", "columns_from_block", "block_values",
           "step_events", "end_event"]

PROFILE = ""                      # protobuf messages, no ROS profile
LIBRARY = f"boatland {__version__}"
METADATA_NAME = "boatland.run"    # scenario document, version, seed, dt, start pose, …
SUMMARY_NAME = "boatland.summary"  # Result.summary() at the end of a run
NS = 1_000_000_000
_COMPRESSION = {"lz4": CompressionType.LZ4, "zstd": CompressionType.ZSTD, "": CompressionType.NONE}


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


def _varint(n: int) -> bytes:
    out = bytearray()
    while True:
        b, n = n & 0x7F, n >> 7
        out.append(b | (0x80 if n else 0))
        if not n:
            return bytes(out)


def _compile(items: list) -> tuple[bytearray, list]:
    """Bytes of a fixed-layout protobuf message and the positions of its values: ``items`` are
    ``("const", bytes)``, ``("f8", field)`` (a double), ``("enum", field)`` (one byte, values 0…127),
    ``("timestamp", field)`` (a ``google.protobuf.Timestamp`` with 5-byte varints) and
    ``("msg", field, items)`` (a nested message). Returns (template, [(kind, offset)])."""
    body, where = bytearray(), []
    for kind, *arg in items:
        if kind == "const":
            body += arg[0]
        elif kind == "f8":
            body.append((arg[0] << 3) | 1)
            where.append(("f8", len(body)))
            body += bytes(8)
        elif kind == "enum":
            body.append(arg[0] << 3)
            where.append(("enum", len(body)))
            body += bytes(1)
        elif kind == "timestamp":
            body += bytes([(arg[0] << 3) | 2, 12, 0x08])
            where.append(("timestamp", len(body)))
            body += bytes(5) + b"\x10" + bytes(5)
        else:                                            # a nested message
            sub, sub_where = _compile(arg[1])
            body += bytes([(arg[0] << 3) | 2]) + _varint(len(sub))
            where += [(k, len(body) + o) for k, o in sub_where]
            body += sub
    return body, where


def step_items(n_contacts: int) -> dict:
    """The fixed layouts of a step's messages, by topic (:data:`~boatland.record.schemas.STEP_TOPICS`)."""
    f8 = lambda first, k: [("f8", first + i) for i in range(k)]  # noqa: E731
    contact = ("msg", 2, [("enum", 1)] + f8(2, 8))
    return {
        "/tf": [("timestamp", 1), ("const", b"\x12\x05world\x1a\x06vessel"), ("msg", 4, f8(1, 3)),
                ("msg", 5, f8(1, 4))],
        "/vessel/state": f8(1, 13),
        "/vessel/loads": f8(1, 9),
        "/fender/state": f8(1, 1) + [contact] * n_contacts,
        "/fender/forces": arrow_items(n_contacts),
    }


class _Layout:
    """Byte layout of the payloads of one step, all topics of :data:`STEP_TOPICS` side by side.

    Every step's payloads have the same size, so a block of ``n`` steps is an (n, size) byte matrix: the
    template holds the constant bytes (protobuf tags, lengths, frame names) and per block only the
    values are scattered in — doubles, enums, timestamps — a handful of array operations (:meth:`fill`)
    or one compiled pass (:meth:`encode`) for the whole block. ``spans`` gives each topic's
    ``(start, end)`` in a row.
    """

    def __init__(self, n_contacts: int):
        row, dpos, epos, tspos, self.spans = bytearray(), [], [], [], {}
        for topic, items in step_items(n_contacts).items():
            body, where = _compile(items)
            start = len(row)
            self.spans[topic] = (start, start + len(body))
            for kind, off in where:
                {"f8": dpos, "enum": epos, "timestamp": tspos}[kind].append(start + off)
            row += body
        self.template = np.frombuffer(bytes(row), np.uint8)
        self.size = len(row)
        self.dpos = np.asarray(dpos, dtype=np.int64)
        self.dpos8 = (self.dpos[:, None] + np.arange(8)).ravel()
        self.epos = np.asarray(epos, dtype=np.int64)
        self.tspos = np.asarray(tspos, dtype=np.int64)

    def fill(self, t_ns: np.ndarray, doubles: np.ndarray, enums: np.ndarray) -> np.ndarray:
        """(n, size) bytes of ``n`` steps: log times ``t_ns`` (n,), ``doubles`` (n, K) in field order,
        ``enums`` (n, Nc)."""
        n = len(t_ns)
        rec = np.tile(self.template, (n, 1))
        rec[:, self.dpos8] = doubles.view(np.uint8).reshape(n, -1)
        rec[:, self.epos] = enums
        sec, nsec = _padded_varint(t_ns // NS), _padded_varint(t_ns % NS)
        for p in self.tspos:
            rec[:, p:p + 5] = sec
            rec[:, p + 6:p + 11] = nsec
        return rec

    def encode(self, t_ns: np.ndarray, block, slip: np.ndarray, eta: np.ndarray, start_pose,
               extra: np.ndarray) -> np.ndarray:
        """Same bytes as ``fill(t_ns, *block_values(columns, extra))``, compiled: the hot path. ``extra``
        (n, Ke): the doubles after the fender state's (the force arrows, :func:`arrow_values`)."""
        out = np.empty((len(t_ns), self.size), np.uint8)
        x0, y0, psi = start_pose
        _encode_steps(out, self.template, self.dpos, self.epos, self.tspos, t_ns, block.t, block.x, block.v,
                      block.F_exc, block.thrust, eta, block.fn, block.ft, block.needed, block.available, slip,
                      block.tpos, block.mode, float(x0), float(y0), float(psi), np.ascontiguousarray(extra))
        return out


@numba.njit(cache=True)
def _put(out, i, pos, value, scratch):
    """The 8 little-endian bytes of ``value`` at ``out[i, pos:pos+8]``."""
    scratch[0] = value
    b = scratch.view(np.uint8)
    for j in range(8):
        out[i, pos + j] = b[j]


@numba.njit(cache=True)
def _encode_steps(out, template, dpos, epos, tspos, t_ns, t, x, v, F, thrust, eta, fn, ft, needed, available, slip,
                  tp, mode, x0, y0, psi, extra):  # pragma: no cover - compiled
    """Fill ``out`` (n, size) with the payloads of n steps: :meth:`_Layout.fill` of :func:`block_values`
    in one compiled pass (pose as :func:`~boatland.record.columns.world_pose`, angles in degrees)."""
    n, nc = mode.shape
    f8 = np.empty(1, np.float64)
    vals = np.empty(dpos.size)
    base = 30 + 8 * nc
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
        for k in range(3):
            vals[8 + k] = x[i, k]
            vals[11 + k] = x[i, 3 + k] * RAD2DEG
            vals[14 + k] = v[i, k]
            vals[17 + k] = v[i, 3 + k] * RAD2DEG
        for k in range(6):
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
        for k in range(extra.shape[1]):
            vals[base + k] = extra[i, k]
        for k in range(dpos.size):
            _put(out, i, dpos[k], vals[k], f8)
        sec, nsec = t_ns[i] // 1_000_000_000, t_ns[i] % 1_000_000_000
        for p in tspos:
            for j in range(5):
                more = 0x80 if j < 4 else 0
                out[i, p + j] = ((sec >> (7 * j)) & 0x7F) | more
                out[i, p + 6 + j] = ((nsec >> (7 * j)) & 0x7F) | more


def block_values(c: Columns, extra: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The doubles of the step messages in field order, (n, K) — angles in degrees — and the contact
    modes (n, Nc) uint8; ``extra`` (n, Ke) are appended (the force arrows)."""
    n, nc = c.mode.shape
    per_contact = np.stack([c.fn, c.ft[:, :, 0], c.ft[:, :, 1], c.needed, c.available, c.slip,
                            c.tpos[:, :, 0], c.tpos[:, :, 1]], axis=2).reshape(n, 8 * nc)
    t = c.t[:, None]
    x, v = np.array(c.x, float), np.array(c.v, float)
    x[:, 3:] *= RAD2DEG
    v[:, 3:] *= RAD2DEG
    parts = [c.translation, c.quaternion, t, x, v, t, c.thrust[:, None], c.F_exc, c.eta_bow[:, None], t, per_contact]
    if extra is not None:
        parts.append(extra)
    return np.concatenate(parts, axis=1, dtype="<f8"), c.mode.astype(np.uint8)


class McapLog:
    """Writes a trial to ``path`` as it runs (implements :class:`~boatland.trial.sink.TrialSink`).

    Parameters
    ----------
    path : str or Path
        The ``.mcap`` file; replaced if it exists.
    compression : {"lz4", "zstd", ""}
        Chunk compression: lz4 (default) is several times faster per block than zstd, for files a few
        per cent larger (the doubles of the states hardly compress).
    run_id : str, optional
        Stored in the metadata; the replay uses it as Rerun recording id (give the live Rerun stream
        the same one).
    start_time : float, optional
        The run's start [s since the Unix epoch, UTC], the origin of the log times (rounded down to a
        whole second); default: the wall clock when the trial starts.

    Notes
    -----
    Loss on a crash: each :meth:`steps` call writes its block as a complete chunk with its message
    indexes and flushes the file before returning, so a killed run keeps every block handed over before
    it was killed (the block being written at that moment, at most about 1 s of simulated time, may be
    lost). The sea at the bow is summed per block (:class:`~boatland.record.columns.BowElevation`), so
    the first block is written as soon as the kernel has finished it.
    """

    def __init__(self, path: str | Path, *, compression: str = "lz4", run_id: str = "",
                 start_time: float | None = None):
        self.path = Path(path)
        self.run_id = run_id
        if compression not in _COMPRESSION:
            raise ValueError(f"compression: expected 'lz4', 'zstd' or '', got {compression!r}")
        self.compression = compression
        self.start_time = start_time
        self._f = self._writer = None
        self.info = None

    # --------------------------------------------------------------------------- sink interface
    def start(self, info) -> None:
        self.info = info
        try:
            self._f = open(self.path, "wb")
        except OSError as exc:
            raise BoatlandInputError(f"{self.path}: cannot write the run log: {exc.strerror}") from None
        start = time.time() if self.start_time is None else float(self.start_time)
        self.epoch = int(start) * NS                  # log_time of t = 0
        nc = np.asarray(info.contacts[0]).reshape(-1, 3).shape[0]
        self._anchor = np.full((nc, 2), np.nan)      # landing positions carried across blocks
        self._eta = BowElevation(info)               # the sea at the bow, summed block by block
        self._incidents = IncidentWatch(info.scenario.incidents, settle_row(info))
        self._scene: Scene = scene_from_trial(info.setup, info.contacts, waves=False)
        self._log_cls = message_class("foxglove.Log")
        self._layout = _Layout(nc)
        self._seq = 0
        try:
            self._begin()
        except OSError as exc:
            self._abandon(exc)

    def _begin(self) -> None:
        """The file's start: header, schemas, channels, metadata and the static scene, flushed."""
        w = self._writer = Writer(self._f, chunk_size=1 << 62, compression=_COMPRESSION[self.compression],
                                  enable_crcs=True, enable_data_crcs=True)
        w.start(profile=PROFILE, library=LIBRARY)
        schema_ids = {name: w.register_schema(name, "protobuf", file_descriptor_set(name))
                      for name in dict.fromkeys(TOPICS.values())}
        self._ids = {topic: w.register_channel(topic, "protobuf", schema_ids[name]) for topic, name in TOPICS.items()}
        self._spans = [(self._ids[topic], a, b) for topic, (a, b) in self._layout.spans.items()]
        stamp = datetime.fromtimestamp(self.epoch // NS, timezone.utc).isoformat()
        w.add_metadata(METADATA_NAME, {k: str(v) for k, v in (run_metadata(self.info) | {
            "run_id": self.run_id, "log_format": LOG_FORMAT, "start_time_ns": self.epoch, "start_time": stamp,
        }).items()})
        # the first chunk: schemas, channels and the static scene, on disk before the kernel starts
        w.add_message(self._ids["/scene"], self.epoch, static_scene(self._scene, self.epoch), self.epoch, 0)
        w.flush()

    def steps(self, block) -> None:
        try:
            self._steps(block)
        except OSError as exc:
            self._abandon(exc)

    def _abandon(self, exc: OSError):
        """A write failed (a full disk, a file-size limit): close and remove the partial log — a log that
        ends mid-block is not left under its name — and raise the error naming it."""
        try:
            if self._f is not None:
                self._f.close()
        except OSError:
            pass
        self._writer = self._f = None
        self.path.unlink(missing_ok=True)
        raise OSError(exc.errno, exc.strerror, str(self.path)) from None

    def _steps(self, block) -> None:
        slip = np.empty(block.mode.shape)
        track_landing(block.mode, block.tpos, self._anchor, slip, max(0, settle_row(self.info) - block.k0))
        t_ns = np.rint(np.asarray(block.t) * NS).astype(np.int64) + self.epoch
        arrows = arrow_values_compiled(self._scene, block.x, block.fn, block.ft, block.mode)
        rows = self._layout.encode(t_ns, block, slip, self._eta(block.k0, block.k1), self.info.start_pose, arrows)
        buf, size, add, seq = rows.tobytes(), self._layout.size, self._writer.add_message, self._seq
        for i, t in enumerate(t_ns.tolist()):
            base = i * size
            for cid, a, b in self._spans:
                add(cid, t, buf[base + a:base + b], t, seq + i)
        self._seq += len(t_ns)
        if block.events or self._incidents.pending:
            self._events(step_events(block, slip, self._incidents))
        self._writer.flush()

    def finish(self, result) -> None:
        if self._writer is None:
            return
        try:
            self._events([end_event(result)])
            self._writer.flush()
            self._writer.add_metadata(SUMMARY_NAME, {"summary": json.dumps(result.summary(), default=float)})
            self._close()
        except OSError as exc:
            self._abandon(exc)

    def close(self) -> None:
        """Finish the file without a result (e.g. after an error elsewhere): still a valid MCAP."""
        if self._writer is not None:
            try:
                self._close()
            except OSError as exc:
                self._abandon(exc)

    # --------------------------------------------------------------------------------- writing
    def _events(self, events) -> None:
        """A few events ``(t_ns from the start, level, text)`` as ``foxglove.Log`` messages."""
        cid = self._ids["/events"]
        for t_ns, level, text in events:
            t = self.epoch + int(t_ns)
            m = self._log_cls(level=LOG_LEVEL[level], message=text, name="boatland")
            m.timestamp.seconds, m.timestamp.nanos = divmod(t, NS)
            self._writer.add_message(cid, t, m.SerializeToString(), t, self._seq)

    def _close(self) -> None:
        self._writer.finish()
        self._f.close()
        self._writer = self._f = None


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


def step_events(block, slip, incidents: IncidentWatch) -> list[tuple[int, str, str]]:
    """Events of a block as ``(t_ns, level, text)``: contact events, then first incidents (``slip``: the
    block's landing offsets)."""
    events = [(round(e.t * NS), "WARNING" if e.kind == "stick→slip" else "INFO", e.text()) for e in block.events]
    return events + [(round(ti * NS), "WARNING", text) for ti, text in incidents(block, slip)]


def end_event(result) -> tuple[int, str, str]:
    """The closing event of a run: completed, or why it stopped."""
    t_end = float(result.t[-1]) if len(result.t) else 0.0
    return round(t_end * NS), "INFO" if result.status == 0 else "ERROR", f"run {result.message} at t = {t_end:.2f} s"

