"""Replay a run log (MCAP) into Rerun with the scene and layout of the live stream.

The log is read with :func:`boatland.record.reader.read_run_log` (a truncated log is recovered up to its
last complete block, and the loss is reported) and written through the same
:class:`~boatland.record.rerun_log.RerunView` as the live stream, so both give the same entities and
values.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from boatland.record.mcap_log import NS
from boatland.record.reader import RunLog, read_run_log
from boatland.record.rerun_log import DEFAULT_BIND, DEFAULT_PORT, RerunView, check_target, key_moment, open_stream, \
    show_moment
from boatland.record.scene import scene_from_metadata

__all__ = ["replay", "Replayed", "waves_from"]


@dataclass(frozen=True, eq=False)
class Replayed:
    """What :func:`replay` did: the log read, the open stream, the target kind and where it went
    (file path or server URL), notes on what was recovered or could not be rebuilt, the moment worth
    looking at (:func:`~boatland.record.rerun_log.key_moment`: time [s], what it is) and whether the
    viewer's time cursor was moved there (``spawn``, ``connect``)."""

    log: RunLog
    stream: object
    kind: str
    where: str | None
    notes: list
    moment: tuple = (0.0, "the start")
    shown: bool = False


def replay(path: str | Path, target: str, *, quiet: bool = False, bind: str = DEFAULT_BIND,
           port: int = DEFAULT_PORT) -> Replayed:
    """Send the run log ``path`` to a Rerun ``target`` (``save=PATH``, ``serve``, ``spawn``, ``connect[=URL]``).

    ``bind``, ``port``: where a ``serve`` target listens (default 127.0.0.1:9876).

    Returns
    -------
    Replayed
        File targets are closed (footer written); a ``serve`` target stays up while the process lives.

    Raises
    ------
    BoatlandInputError
        Not a boatland run log, nothing recoverable, or an unusable target.
    """
    check_target(target, bind=bind, port=port)     # an unusable target fails before the log is read
    log = read_run_log(path)
    nc = log.columns.mode.shape[1]
    scene = scene_from_metadata(log.metadata)
    rec, kind, where, file = open_stream(target, recording_id=log.metadata.get("run_id") or None, n_contacts=nc,
                                         quiet=quiet, bind=bind, port=port, scene=scene)
    view = RerunView(rec, scene, nc)
    view.static()
    view.columns(log.columns)
    view.events([(round(t * NS), level, text) for t, level, text in log.events])
    rec.flush()
    if kind in ("save", "spawn", "connect"):
        rec.disconnect()
    if file is not None:
        file.close()           # complete, or an OSError naming it (nothing left under its name)
    moment = key_moment(log.columns, waves_from(log.metadata))
    shown = kind in ("spawn", "connect") and show_moment(where, moment[0])
    return Replayed(log, rec, kind, where, list(log.notes) + list(scene.notes), moment, shown)


def waves_from(metadata: dict) -> float:
    """When the run's settling ended (its waves began) [s], from the log's provenance; 0 if not recorded."""
    import json

    prov = metadata.get("provenance") or {}
    try:
        prov = json.loads(prov) if isinstance(prov, str) else prov
        return float(prov.get("waves_from", 0.0))
    except (ValueError, TypeError, AttributeError):
        return 0.0
