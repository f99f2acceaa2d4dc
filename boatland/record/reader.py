"""Reading a boatland run log (MCAP) back: columns, events, metadata — recovering a truncated file.

The file is read linearly (records in order, chunk and data-section CRCs checked), so a log whose
writer was killed reads up to its last complete chunk; :attr:`RunLog.notes` then says what is missing.
Files that are not MCAP, or MCAP files written by another program, raise
:class:`~boatland.errors.BoatlandInputError` with one line.

Both log formats are read (:data:`~boatland.record.schemas.LOG_FORMAT`): 2 (angles in degrees, log
times from the run's wall-clock start ``start_time_ns``) and 1 (radians, log time = simulated time);
:class:`RunLog` holds SI units (radians) and simulated times either way.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.inputs import open_input
from boatland.record.columns import Columns
from boatland.record.schemas import ANGLE_FIELDS, CONTACT_FIELDS, LOG_LEVEL, RAD2DEG, TOPICS, VESSEL_LOADS_FIELDS, \
    VESSEL_STATE_FIELDS, message_class

__all__ = ["RunLog", "read_run_log"]

MAGIC = b"\x89MCAP0\r\n"
#: Channels every log has (format 1 on); format 2 adds ``/scene`` and ``/fender/forces`` for Foxglove.
REQUIRED = ("/tf", "/events", "/vessel/state", "/vessel/loads", "/fender/state")
_LEVEL_NAME = {v: k for k, v in LOG_LEVEL.items()}


@dataclass(frozen=True, eq=False)
class RunLog:
    """A run log read back.

    Attributes
    ----------
    path : Path
    columns : Columns
        Every complete step in the file.
    events : list of (t [s], level, text)
    metadata : dict
        The ``boatland.run`` record (scenario document, version, seed, dt, start pose, geometry, log
        format, start time).
    summary : dict or None
        ``Result.summary()`` when the run finished writing its log.
    complete : bool
        The file has its summary and footer (the writer finished).
    notes : list of str
        What was recovered / lost (truncated file).
    """

    path: Path
    columns: Columns
    events: list
    metadata: dict
    summary: dict | None
    complete: bool
    notes: list = field(default_factory=list)

    @property
    def duration(self) -> float:
        return float(self.columns.t[-1]) if len(self.columns) else 0.0

    @property
    def planned_duration(self) -> float | None:
        try:
            return int(self.metadata["n_steps"]) * float(self.metadata["dt"])
        except (KeyError, ValueError):
            return None


def _records(path: Path):
    """Yield (record, error) of the file in order; stops at the first unreadable record."""
    import struct

    from mcap.exceptions import McapError
    from mcap.stream_reader import StreamReader
    from zstandard import ZstdError as zstd_error

    with open_input(path, "run log", "mcap") as f:
        reader = StreamReader(f, skip_magic=False, emit_chunks=False, validate_crcs=True)
        try:
            for rec in reader.records:
                yield rec, None
        except (McapError, EOFError, ValueError, struct.error, zstd_error, RuntimeError) as exc:  # the readable
            # part ends here (RuntimeError: lz4's, on a damaged chunk)
            yield None, exc


def read_run_log(path: str | Path) -> RunLog:
    """Read a run log written by :class:`~boatland.record.mcap_log.McapLog` (finished or truncated).

    Raises
    ------
    BoatlandInputError
        Not a file, not an MCAP file, an MCAP file from another program, or nothing recoverable.
    """
    from mcap.records import Channel, Footer, Header, Message, Metadata, Schema

    path = Path(path)
    with open_input(path, "run log", "mcap") as f:
        head = f.read(8)
    if head != MAGIC:
        raise BoatlandInputError(f"{path}: not an MCAP file (it does not start with the MCAP magic bytes)")
    header, schemas, channels, meta, data = None, {}, {}, {}, {}
    complete, error = False, None
    for rec, err in _records(path):
        if err is not None:
            error = err
            break
        if isinstance(rec, Message):
            data.setdefault(rec.channel_id, []).append((rec.log_time, rec.data))
        elif isinstance(rec, Header):
            header = rec
        elif isinstance(rec, Schema):
            schemas[rec.id] = rec
        elif isinstance(rec, Channel):
            channels[rec.id] = rec
        elif isinstance(rec, Metadata):
            meta[rec.name] = dict(rec.metadata)
        elif isinstance(rec, Footer):
            complete = True
    library = header.library if header is not None else ""
    if library.startswith("boatland") and "boatland.run" not in meta and not complete:
        raise BoatlandInputError(f"{path}: a boatland run log cut before its first record was complete "
                                 f"({path.stat().st_size} bytes; the run was stopped at its start): nothing to recover")
    if header is None and not complete and error is not None:
        raise BoatlandInputError(f"{path}: an MCAP file cut in its header ({path.stat().st_size} bytes): "
                                 "nothing to recover")
    if not library.startswith("boatland") or "boatland.run" not in meta:
        raise BoatlandInputError(f"{path}: an MCAP file, but not a boatland run log (written by "
                                 f"{library or 'an unknown program'!r}; topics: "
                                 f"{', '.join(sorted(c.topic for c in channels.values())) or 'none'})")
    by_topic = {c.topic: data.get(cid, []) for cid, c in channels.items()
                if c.topic in TOPICS and schemas.get(c.schema_id) and schemas[c.schema_id].name == TOPICS[c.topic]}
    missing = [t for t in REQUIRED if t not in by_topic]
    if missing and not complete and not channels:
        raise BoatlandInputError(f"{path}: truncated before the first complete block: nothing to recover")
    if missing:
        raise BoatlandInputError(f"{path}: a boatland log without the channels {', '.join(missing)}")
    run = meta["boatland.run"]
    fmt = int(run.get("log_format", 1))
    epoch = int(run.get("start_time_ns", 0)) if fmt >= 2 else 0
    columns = _columns(by_topic, int(run.get("n_contacts", 0)), degrees=fmt >= 2)
    notes = []
    if not complete:
        why = ": no summary or footer"
        if error is not None and str(error):
            why += f", unreadable after the last complete record ({type(error).__name__}: {error})"
        planned = int(run["n_steps"]) * float(run["dt"])
        end = float(columns.t[-1]) if len(columns) else 0.0
        notes.append(f"{path}: truncated log (the writer did not finish{why}); recovered {len(columns)} steps, "
                     f"t = 0 … {end:.2f} s of the planned {planned:g} s — anything after {end:.2f} s is lost")
        if not len(columns):
            raise BoatlandInputError(f"{path}: truncated before the first complete block: nothing to recover")
    events = []
    Log = message_class("foxglove.Log")
    for t_ns, raw in by_topic["/events"]:
        m = Log.FromString(raw)
        events.append(((t_ns - epoch) / 1e9, _LEVEL_NAME.get(m.level, "UNKNOWN"), m.message))
    summary = None
    if "boatland.summary" in meta:        # metadata records carry no CRC: damage shows as bad JSON
        try:
            summary = json.loads(meta["boatland.summary"]["summary"])
        except (ValueError, TypeError, KeyError):
            notes.append(f"{path}: the run's summary record is damaged; left out (the steps and events are intact)")
    for key in ("scenario", "start_pose", "scene", "provenance"):
        try:
            json.loads(run.get(key) or "null")
        except (ValueError, TypeError):
            raise BoatlandInputError(f"{path}: damaged — its run metadata ({key}) is not JSON; the log cannot be "
                                     "replayed") from None
    return RunLog(path=path, columns=columns, events=events, metadata=run, summary=summary, complete=complete,
                  notes=notes)


def _doubles(rows: list, cls_name: str, names: tuple) -> np.ndarray:
    """(n, len(names)) doubles of fixed-layout messages (every field written): a numpy view of the bytes
    when the layout is ours, else decoded field by field with protobuf."""
    n, k = len(rows), len(names)
    size = 9 * k
    if n == 0:
        return np.zeros((0, k))
    if all(len(r) == size for _, r in rows):
        b = np.frombuffer(b"".join(r for _, r in rows), np.uint8).reshape(n, k, 9)
        if np.array_equal(b[0, :, 0], (np.arange(1, k + 1) << 3) | 1):
            return np.ascontiguousarray(b[:, :, 1:]).view("<f8").reshape(n, k)
    cls = message_class(cls_name)
    return np.array([[getattr(m, f) for f in names] for m in (cls.FromString(r) for _, r in rows)]).reshape(n, k)


def _columns(by_topic: dict, nc: int, degrees: bool) -> Columns:
    """The steps as :class:`Columns` (SI: angles back in radians when ``degrees``)."""
    n = min(len(by_topic[t]) for t in ("/tf", "/vessel/state", "/vessel/loads", "/fender/state"))
    st = _doubles(by_topic["/vessel/state"][:n], "boatland.VesselState", VESSEL_STATE_FIELDS)
    if degrees:
        st[:, ANGLE_FIELDS] /= RAD2DEG            # the writer's x · RAD2DEG undone to ≤ 1 ulp
    ld = _doubles(by_topic["/vessel/loads"][:n], "boatland.VesselLoads", VESSEL_LOADS_FIELDS)
    TF = message_class("foxglove.FrameTransform")
    FS = message_class("boatland.FenderState")
    tr, q = np.empty((n, 3)), np.empty((n, 4))
    for i, (_, raw) in enumerate(by_topic["/tf"][:n]):
        m = TF.FromString(raw)
        tr[i] = m.translation.x, m.translation.y, m.translation.z
        q[i] = m.rotation.x, m.rotation.y, m.rotation.z, m.rotation.w
    mode = np.zeros((n, nc), np.int64)
    vals = np.empty((n, nc, len(CONTACT_FIELDS)))
    for i, (_, raw) in enumerate(by_topic["/fender/state"][:n]):
        for c, ct in enumerate(FS.FromString(raw).contacts):
            mode[i, c] = ct.mode
            vals[i, c] = [getattr(ct, f) for f in CONTACT_FIELDS]
    return Columns(t=st[:, 0], x=st[:, 1:7], v=st[:, 7:13], F_exc=ld[:, 2:8], thrust=ld[:, 1], mode=mode,
                   fn=vals[:, :, 0], ft=vals[:, :, 1:3], needed=vals[:, :, 3], available=vals[:, :, 4],
                   tpos=vals[:, :, 6:8], slip=vals[:, :, 5], eta_bow=ld[:, 8], translation=tr, quaternion=q)
