"""The campaign store: one HDF5 file, written as results arrive, crash-safe and resumable.

Layout of ``results.h5``:

- attributes: ``format`` (``boatland-campaign-1``), ``campaign`` (name), ``campaign_digest``,
  ``campaign_file`` (its text), ``plan`` (JSON: axes, cases, seeds, master seed), ``boatland_version``,
  ``n_trials``;
- ``/trials``: one row per finished trial (:data:`ROW_FIELDS` + one column per incident definition),
  sorted by trial number;
- ``/stats``: one row per case (written by :func:`boatland.campaign.runner.run_campaign` at the end);
- a campaign by importance sampling (``method = "isee"``, :mod:`boatland.campaign.isee`) has one row per
  sample in ``/trials`` with its extra columns (:data:`boatland.campaign.isee.ISEE_FIELDS`), its
  estimates per run in ``/isee_runs`` and its limiting Hs per case in ``/isee_limits``;
- ``/series/trial_<n>``: full time series of the trials the campaign keeps (netCDF-4 groups:
  ``xarray.open_dataset(store, group="series/trial_000003")``, as ``boatland run -o`` writes them).

Crash safety. Every finished trial is first appended as one JSON line to ``results.h5.journal`` and
synced to disk; the HDF5 file is rewritten from scratch into a temporary file and renamed over the
old one (atomic) every few seconds and at the end, after which the journal is emptied. A process
killed at any moment leaves the last complete HDF5 file plus a journal whose complete lines hold every
trial finished since: :meth:`CampaignStore.open` merges both (a trial in both counts once), so a
resumed campaign neither loses nor repeats a trial. JSON keeps every float exactly (shortest
round-trip representation), so rows read back from the journal are bit-identical. A journal line that
is not a complete row of this campaign (cut by a kill, or damaged) is skipped: that trial runs again.

One writer. :meth:`CampaignStore.open` takes an exclusive advisory lock (``flock``) on
``results.h5.lock`` beside the store and holds it until :meth:`CampaignStore.close`; a second campaign
on the same store is refused with the holder's pid. The kernel drops the lock when its holder dies (a
killed campaign leaves no stale lock: the next one takes it and clears the ``.part`` files an
interrupted rewrite left). Local filesystems only: ``flock`` over NFS may not exclude.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import socket
import time
import warnings
from pathlib import Path

import numpy as np

from boatland import __version__
from boatland.atomic import atomic_hdf5, remove_stale_parts
from boatland.inputs import HDF5_DAMAGE, damage_text, open_hdf5
from boatland.errors import BoatlandInputError, BoatlandWarning

__all__ = ["CampaignStore", "StoreLock", "ROW_FIELDS", "FORMAT"]

FORMAT = "boatland-campaign-1"

#: Fixed columns of a trial row: (name, numpy type, meaning). Times are measured from the moment the
#: waves start (after the thrust ramp); NaN = did not happen.
ROW_FIELDS = (
    ("trial", "i8", "trial number = case × seeds + seed index"),
    ("case", "i8", "case number"),
    ("seed_index", "i8", "seed index within the case"),
    ("seed", "i8", "wave seed"),
    ("status", "i8", "0 completed; 1 NaN, 2 runaway (integration stopped); -1 the trial failed"),
    ("message", "S200", "status message or the error"),
    ("exposure", "f8", "[s] time at risk: from the waves' start to the end of the trial"),
    ("time_to_first_slip", "f8", "[s] first stick→slip after the waves start"),
    ("slip_events", "i8", "number of stick→slip events"),
    ("max_slip_distance", "f8", "[m] largest distance of a fender point from where it landed, from the first slip on "
                               "(0: no slip; before it the offset is the rubber's elastic shear)"),
    ("max_single_slide", "f8", "[m] largest single slide"),
    ("max_normal_force", "f8", "[N]"),
    ("min_normal_force", "f8", "[N] smallest normal force while in contact after the settling"),
    ("max_roll_deg", "f8", "[deg]"),
    ("max_pitch_deg", "f8", "[deg]"),
    ("contact_fraction", "f8", "share of steps with every contact touching"),
    ("wall_time", "f8", "[s] wall time of the trial (not reproducible: excluded from comparisons)"),
)
INCIDENT_PREFIX = "incident: "


#: Side files are opened without following a symbolic link planted at their name (ELOOP instead).
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)


def _append(path: Path, text: str) -> None:
    """Append ``text`` to ``path`` and sync it — never through a symbolic link at ``path``."""
    fd = os.open(path, os.O_WRONLY | os.O_APPEND | os.O_CREAT | _NOFOLLOW | getattr(os, "O_CLOEXEC", 0), 0o644)
    with os.fdopen(fd, "a", encoding="utf-8") as fh:
        fh.write(text)
        fh.flush()
        os.fsync(fh.fileno())


class StoreLock:
    """Exclusive advisory lock of a store: ``flock`` on ``<store>.lock`` beside the store's real path (its
    folder resolved: one lock however the folder is reached), holding the holder's pid."""

    def __init__(self, store: Path):
        self.store = Path(store)
        self.path = self.store.with_name(self.store.name + ".lock")
        self.fd: int | None = None

    def acquire(self) -> None:
        """Take the lock or raise :class:`BoatlandInputError` naming the holder."""
        try:
            import fcntl
        except ImportError:          # not POSIX: no lock (one campaign per store is then the user's care)
            return
        while True:
            try:
                fd = os.open(self.path, os.O_RDWR | os.O_CREAT | _NOFOLLOW | getattr(os, "O_CLOEXEC", 0), 0o644)
            except OSError as exc:
                if self.path.is_symlink():
                    raise BoatlandInputError(f"{self.path}: is a symbolic link; boatland never writes through one "
                                             "— remove it") from None
                raise BoatlandInputError(f"{self.store}: cannot write the campaign store here "
                                         f"({exc.strerror or exc})") from None
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                holder = os.pread(fd, 200, 0).decode(errors="replace").strip() or "unknown"
                os.close(fd)
                raise BoatlandInputError(f"{self.store}: another boatland campaign (pid {holder}) is writing this "
                                         "store; wait for it to finish, or give another -o") from None
            try:   # the holder before us may have removed the file as it finished: lock the one at the path
                same = os.fstat(fd).st_ino == os.stat(self.path).st_ino
            except FileNotFoundError:
                same = False
            if same:
                break
            os.close(fd)
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()} on {socket.gethostname()}\n".encode(), 0)
        self.fd = fd

    def release(self) -> None:
        if self.fd is None:
            return
        try:
            self.path.unlink()
        except FileNotFoundError:
            pass
        os.close(self.fd)        # closing drops the flock
        self.fd = None


def _changed_inputs(theirs, ours) -> str:
    """The inputs whose SHA-256 differ between a store's ``input_digests`` and this campaign's ("" if the
    store predates them, or the campaign itself differs beyond its inputs' contents)."""
    try:
        a = json.loads(theirs.decode() if isinstance(theirs, bytes) else theirs)
        b = json.loads(ours)
    except (TypeError, ValueError, AttributeError):
        return ""
    if not isinstance(a, dict) or not isinstance(b, dict) or set(a) != set(b):
        return ""
    names = [k for k in b if a[k] != b[k]]
    return " and ".join(names)


def _fits(row: dict, dt: np.dtype) -> bool:
    """Whether a journal row's values fit the store's columns (numbers where numbers go)."""
    out = np.zeros(1, dtype=dt)
    try:
        for name in dt.names:
            value = row.get(name, math.nan if dt[name].kind == "f" else 0)
            if dt[name].kind in "fi" and (isinstance(value, (str, bytes, bool, list, dict)) or value is None):
                return False
            out[0][name] = value.encode()[:200] if isinstance(value, str) else value
    except (ValueError, TypeError, OverflowError):
        return False
    return True


def row_dtype(incident_names, extra_fields=()) -> np.dtype:
    """Columns of ``/trials``: :data:`ROW_FIELDS`, one per incident definition, then ``extra_fields``
    ((name, numpy type, meaning) of a method's own columns)."""
    return np.dtype([(n, t) for n, t, _ in ROW_FIELDS] + [(INCIDENT_PREFIX + n, "f8") for n in incident_names]
                    + [(n, t) for n, t, _ in extra_fields])


class CampaignStore:
    """A store bound to one campaign (by its digest). Use :meth:`open`."""

    def __init__(self, path: Path, header: dict, incident_names: list[str], rows: dict[int, dict],
                 lock: StoreLock | None = None, extra_fields=()):
        self.path = Path(path)
        self.extra_fields = tuple(extra_fields)
        self.lock = lock
        self.header = header
        self.incident_names = list(incident_names)
        self.rows = rows                       # trial → row dict
        self.journal = self.path.with_name(self.path.name + ".journal")
        self.series_dir = self.path.with_name(self.path.name + ".series")
        self._last_write = time.monotonic()

    # ------------------------------------------------------------------ opening
    @classmethod
    def open(cls, path: str | Path, header: dict, incident_names: list[str], extra_fields=()) -> "CampaignStore":
        """Open (or create) the store for the campaign ``header`` describes; merge any journal.
        ``extra_fields``: (name, numpy type, meaning) of a method's own columns of ``/trials``.

        Raises
        ------
        BoatlandInputError
            The file is not a campaign store, belongs to a different campaign (never mixed), or another
            campaign holds its lock.
        """
        path = Path(path)
        rows: dict[int, dict] = {}
        if not path.parent.is_dir():
            raise BoatlandInputError(f"{path}: cannot write the campaign store here (no folder {path.parent})")
        for p in (path, *(path.with_name(path.name + s) for s in (".lock", ".journal"))):
            if p.is_symlink():
                raise BoatlandInputError(f"{p}: is a symbolic link; boatland never writes a store or its side "
                                         "files through one — remove it, or give another -o")
        lock = StoreLock(Path(os.path.realpath(path.parent)) / path.name)   # one lock however it is reached
        lock.acquire()
        try:
            store = cls._open_locked(path, header, incident_names, rows, lock, extra_fields)
        except BaseException:
            lock.release()
            raise
        return store

    @classmethod
    def _open_locked(cls, path, header, incident_names, rows, lock, extra_fields=()) -> "CampaignStore":
        remove_stale_parts(path)      # left by a rewrite that was killed (only we can be writing now)
        if path.exists():

            try:
                with open_hdf5(path, "campaign store") as f:
                    fmt = f.attrs.get("format")
                    digest = f.attrs.get("campaign_digest")
                    name = f.attrs.get("campaign")
                    theirs = f.attrs.get("input_digests")
                    data = f["trials"][()] if "trials" in f else None
            except BoatlandInputError:
                raise
            except HDF5_DAMAGE as exc:
                raise BoatlandInputError(f"{path}: not a readable campaign store ({damage_text(exc)}); choose "
                                         "another output file") from None
            if fmt != FORMAT:
                raise BoatlandInputError(f"{path}: not a boatland campaign store (format {fmt!r}); "
                                         "choose another output file")
            if digest != header["campaign_digest"]:
                changed = _changed_inputs(theirs, header.get("input_digests"))
                if changed:
                    raise BoatlandInputError(
                        f"{path}: holds results of {name!r} before {changed} changed; refusing to mix them — put it "
                        "back, or use another output file (or delete this one)")
                raise BoatlandInputError(
                    f"{path}: holds results of a different campaign ({name!r}, or this one since its campaign file, "
                    "scenario, database or wave record changed); "
                    "refusing to mix them — use another output file or delete this one")
            if data is not None:
                if data.dtype.names is None or "trial" not in data.dtype.names:
                    raise BoatlandInputError(f"{path}: its /trials table is damaged; choose another output file")
                for rec in data:
                    row = {k: _py(rec[k]) for k in data.dtype.names}
                    rows[row["trial"]] = row
        store = cls(path, header, incident_names, rows, lock, extra_fields)
        store._merge_journal()
        try:  # fail now, before any trial runs, if results cannot be written here
            _append(store.journal, "")
        except OSError as exc:
            raise BoatlandInputError(f"{path}: cannot write the campaign store here ({exc.strerror or exc})") from None
        return store

    def _merge_journal(self) -> None:
        """The journal's rows of this campaign into :attr:`rows`; a line cut by a kill, damaged, of another
        campaign or with values of the wrong type is left out (its trial runs again), and said once."""
        if not self.journal.exists():
            return
        names = {n for n, _, _ in ROW_FIELDS + self.extra_fields}
        n_trials = int(self.header.get("n_trials", 0))
        dt = row_dtype(self.incident_names, self.extra_fields)
        left_out = 0
        with os.fdopen(os.open(self.journal, os.O_RDONLY | _NOFOLLOW | getattr(os, "O_NONBLOCK", 0)), "rb") as fh:
            for line in fh:
                try:
                    rec = json.loads(line)
                except ValueError:
                    left_out += 1
                    continue
                row = rec.get("row") if isinstance(rec, dict) else None
                if rec is None or not isinstance(rec, dict) or rec.get("campaign_digest") != self.header["campaign_digest"] \
                        or not isinstance(row, dict) or not names <= set(row) or not _fits(row, dt):
                    left_out += 1
                    continue
                trial = row["trial"]
                if not isinstance(trial, int) or isinstance(trial, bool) or trial < 0 or (n_trials and trial >= n_trials):
                    left_out += 1
                    continue
                self.rows.setdefault(trial, row)
        if left_out:
            warnings.warn(f"{self.journal}: {left_out} line(s) damaged or of another campaign left out (their trials "
                          "run again)", BoatlandWarning, stacklevel=3)

    # ------------------------------------------------------------------ writing
    def add(self, row: dict) -> None:
        """Record one finished trial: journal line (synced) now, HDF5 rewrite every few seconds."""
        trial = int(row["trial"])
        if trial in self.rows:
            return
        self.rows[trial] = row
        line = json.dumps({"campaign_digest": self.header["campaign_digest"], "row": row}, allow_nan=True)
        try:
            _append(self.journal, line + "\n")
            if time.monotonic() - self._last_write > 10.0:
                self.write()
        except OSError as exc:  # disk full, permissions: what is on disk stays valid for a resume
            raise BoatlandInputError(f"{self.path}: writing the results failed ({exc.strerror or exc}); the "
                                     f"{len(self.rows) - 1} trials stored so far are kept — free space or fix "
                                     "the problem and run the same command again to resume") from None

    def write(self, stats: np.ndarray | None = None, datasets: dict | None = None) -> Path:
        """Rewrite the HDF5 file atomically from everything known, then empty the journal.
        ``datasets``: further named arrays to write beside ``/stats`` (e.g. ``isee_runs``).

        Raises
        ------
        BoatlandInputError
            Not enough free space, or the write failed: the store on disk and the journal are intact
            (a resume continues from them).
        """
        table = self.table()
        series = sorted(self.series_dir.glob("trial_*.h5")) if self.series_dir.is_dir() else []
        need = 2 * (table.nbytes + sum(p.stat().st_size for p in series)) + (1 << 20)
        free = shutil.disk_usage(self.path.parent).free
        if free < need:
            raise BoatlandInputError(
                f"{self.path}: not enough free space to write the store ({free / 1e6:.3g} MB free, about "
                f"{need / 1e6:.3g} MB needed); the {len(self.rows)} finished trials are kept in {self.journal.name}: "
                "free space and run the same command again")
        try:
            self._write(table, stats, series, datasets or {})
        except OSError as exc:
            raise BoatlandInputError(
                f"{self.path}: writing the store failed ({exc.strerror or exc}); the {len(self.rows)} finished "
                f"trials are kept in {self.journal.name}: fix that and run the same command again") from None
        self._last_write = time.monotonic()
        return self.path

    def _write(self, table, stats, series, datasets) -> None:
        import h5py

        from boatland.netcdf_h5 import copy_group

        with atomic_hdf5(self.path, track_order=True) as f:
            f.attrs["format"] = FORMAT
            f.attrs["boatland_version"] = __version__
            for k, v in self.header.items():
                f.attrs[k] = v
            f.create_dataset("trials", data=table, maxshape=(None,), chunks=True)
            f["trials"].attrs["columns"] = json.dumps({n: d for n, _, d in ROW_FIELDS + self.extra_fields})
            if stats is not None:
                f.create_dataset("stats", data=stats)
            for name, data in datasets.items():
                f.create_dataset(name, data=data)
            for src in series:     # netCDF-4 groups: xarray.open_dataset(store, group="series/trial_…")
                with h5py.File(src, "r") as s:
                    copy_group(s, f.require_group("series").create_group(src.stem, track_order=True))
        fd = os.open(self.journal, os.O_WRONLY | os.O_TRUNC | os.O_CREAT | _NOFOLLOW, 0o644)   # all in the HDF5 file now
        try:
            os.fsync(fd)
        finally:
            os.close(fd)

    def finish(self, stats: np.ndarray | None, datasets: dict | None = None) -> Path:
        """Final write (with the statistics); removes the journal and the series folder."""
        path = self.write(stats, datasets)
        self.journal.unlink(missing_ok=True)
        if self.series_dir.is_dir():
            shutil.rmtree(self.series_dir)
        return path

    def close(self) -> None:
        """Release the store's lock (another campaign may then open it)."""
        if self.lock is not None:
            self.lock.release()

    # ------------------------------------------------------------------ reading
    def table(self) -> np.ndarray:
        """All finished rows as a structured array sorted by trial."""
        dt = row_dtype(self.incident_names, self.extra_fields)
        out = np.zeros(len(self.rows), dtype=dt)
        for i, trial in enumerate(sorted(self.rows)):
            row = self.rows[trial]
            for name in dt.names:
                value = row.get(name, math.nan if dt[name].kind == "f" else 0)
                out[i][name] = value.encode()[:200] if isinstance(value, str) else value
        return out

    def done(self) -> set[int]:
        return set(self.rows)


def _py(value):
    """numpy scalar → plain Python (bytes → str) for a row dict."""
    if isinstance(value, bytes):
        return value.decode(errors="replace")
    if isinstance(value, np.generic):
        return value.item()
    return value
