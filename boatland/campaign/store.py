"""The campaign store: one HDF5 file, written as results arrive, crash-safe and resumable.

Layout of ``results.h5``:

- attributes: ``format`` (``boatland-campaign-1``), ``campaign`` (name), ``campaign_digest``,
  ``campaign_file`` (its text), ``plan`` (JSON: axes, cases, seeds, master seed), ``boatland_version``,
  ``n_trials``;
- ``/trials``: one row per finished trial (:data:`ROW_FIELDS` + one column per incident definition),
  sorted by trial number;
- ``/stats``: one row per case (written by :func:`boatland.campaign.runner.run_campaign` at the end);
- ``/series/trial_<n>``: full time series of the trials the campaign keeps.

Crash safety. Every finished trial is first appended as one JSON line to ``results.h5.journal`` and
synced to disk; the HDF5 file is rewritten from scratch into a temporary file and renamed over the
old one (atomic) every few seconds and at the end, after which the journal is emptied. A process
killed at any moment leaves the last complete HDF5 file plus a journal whose complete lines hold every
trial finished since: :meth:`CampaignStore.open` merges both (a trial in both counts once), so a
resumed campaign neither loses nor repeats a trial. JSON keeps every float exactly (shortest
round-trip representation), so rows read back from the journal are bit-identical.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import time
from pathlib import Path

import numpy as np

from boatland import __version__
from boatland.atomic import atomic_path
from boatland.errors import BoatlandInputError

__all__ = ["CampaignStore", "ROW_FIELDS", "FORMAT"]

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
    ("max_slip_distance", "f8", "[m] largest distance of a fender point from where it landed"),
    ("max_single_slide", "f8", "[m] largest single slide"),
    ("max_normal_force", "f8", "[N]"),
    ("min_normal_force", "f8", "[N] smallest normal force while in contact"),
    ("max_roll_deg", "f8", "[deg]"),
    ("max_pitch_deg", "f8", "[deg]"),
    ("contact_fraction", "f8", "share of steps with every contact touching"),
    ("wall_time", "f8", "[s] wall time of the trial (not reproducible: excluded from comparisons)"),
)
INCIDENT_PREFIX = "incident: "


def row_dtype(incident_names) -> np.dtype:
    return np.dtype([(n, t) for n, t, _ in ROW_FIELDS] + [(INCIDENT_PREFIX + n, "f8") for n in incident_names])


class CampaignStore:
    """A store bound to one campaign (by its digest). Use :meth:`open`."""

    def __init__(self, path: Path, header: dict, incident_names: list[str], rows: dict[int, dict]):
        self.path = Path(path)
        self.header = header
        self.incident_names = list(incident_names)
        self.rows = rows                       # trial → row dict
        self.journal = self.path.with_name(self.path.name + ".journal")
        self.series_dir = self.path.with_name(self.path.name + ".series")
        self._last_write = time.monotonic()

    # ------------------------------------------------------------------ opening
    @classmethod
    def open(cls, path: str | Path, header: dict, incident_names: list[str]) -> "CampaignStore":
        """Open (or create) the store for the campaign ``header`` describes; merge any journal.

        Raises
        ------
        BoatlandInputError
            The file is not a campaign store, or belongs to a different campaign (never mixed).
        """
        path = Path(path)
        rows: dict[int, dict] = {}
        if path.exists():
            import h5py

            try:
                with h5py.File(path, "r") as f:
                    fmt = f.attrs.get("format")
                    digest = f.attrs.get("campaign_digest")
                    name = f.attrs.get("campaign")
                    data = f["trials"][()] if "trials" in f else None
            except OSError as exc:
                raise BoatlandInputError(f"{path}: not a readable HDF5 campaign store ({exc})") from None
            if fmt != FORMAT:
                raise BoatlandInputError(f"{path}: not a boatland campaign store (format {fmt!r}); "
                                         "choose another output file")
            if digest != header["campaign_digest"]:
                raise BoatlandInputError(
                    f"{path}: holds results of a different campaign ({name!r}, or this one edited since); "
                    "refusing to mix them — use another output file or delete this one")
            if data is not None:
                for rec in data:
                    row = {k: _py(rec[k]) for k in data.dtype.names}
                    rows[row["trial"]] = row
        store = cls(path, header, incident_names, rows)
        store._merge_journal()
        try:  # fail now, before any trial runs, if results cannot be written here
            with open(store.journal, "a", encoding="utf-8"):
                pass
        except OSError as exc:
            raise BoatlandInputError(f"{path}: cannot write the campaign store here ({exc.strerror or exc})") from None
        return store

    def _merge_journal(self) -> None:
        if not self.journal.exists():
            return
        with open(self.journal, "rb") as fh:
            for line in fh:
                try:
                    rec = json.loads(line)
                except ValueError:        # a line cut by a kill: that trial runs again
                    continue
                if rec.get("campaign_digest") != self.header["campaign_digest"]:
                    continue
                row = rec["row"]
                self.rows.setdefault(int(row["trial"]), row)

    # ------------------------------------------------------------------ writing
    def add(self, row: dict) -> None:
        """Record one finished trial: journal line (synced) now, HDF5 rewrite every few seconds."""
        trial = int(row["trial"])
        if trial in self.rows:
            return
        self.rows[trial] = row
        line = json.dumps({"campaign_digest": self.header["campaign_digest"], "row": row}, allow_nan=True)
        try:
            with open(self.journal, "a", encoding="utf-8") as fh:
                fh.write(line + "\n")
                fh.flush()
                os.fsync(fh.fileno())
            if time.monotonic() - self._last_write > 10.0:
                self.write()
        except OSError as exc:  # disk full, permissions: what is on disk stays valid for a resume
            raise BoatlandInputError(f"{self.path}: writing the results failed ({exc.strerror or exc}); the "
                                     f"{len(self.rows) - 1} trials stored so far are kept — free space or fix "
                                     "the problem and run the same command again to resume") from None

    def write(self, stats: np.ndarray | None = None) -> Path:
        """Rewrite the HDF5 file atomically from everything known, then empty the journal."""
        import h5py

        table = self.table()
        with atomic_path(self.path) as tmp:
            with h5py.File(tmp, "w") as f:
                f.attrs["format"] = FORMAT
                f.attrs["boatland_version"] = __version__
                for k, v in self.header.items():
                    f.attrs[k] = v
                f.create_dataset("trials", data=table, maxshape=(None,), chunks=True)
                f["trials"].attrs["columns"] = json.dumps({n: d for n, _, d in ROW_FIELDS})
                if stats is not None:
                    f.create_dataset("stats", data=stats)
                if self.series_dir.is_dir():
                    for src in sorted(self.series_dir.glob("trial_*.h5")):
                        with h5py.File(src, "r") as s:
                            s.copy(s["/"], f, name=f"series/{src.stem}")
        with open(self.journal, "w", encoding="utf-8") as fh:   # everything is in the HDF5 file now
            fh.flush()
            os.fsync(fh.fileno())
        self._last_write = time.monotonic()
        return self.path

    def finish(self, stats: np.ndarray | None) -> Path:
        """Final write (with the statistics); removes the journal and the series folder."""
        path = self.write(stats)
        self.journal.unlink(missing_ok=True)
        if self.series_dir.is_dir():
            shutil.rmtree(self.series_dir)
        return path

    # ------------------------------------------------------------------ reading
    def table(self) -> np.ndarray:
        """All finished rows as a structured array sorted by trial."""
        dt = row_dtype(self.incident_names)
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
