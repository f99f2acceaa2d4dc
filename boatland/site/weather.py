r"""A site's weather: sea states with their share of the time — a scatter diagram (occurrences) or a hindcast
time series (a regular series of sea states) — read from CSV or netCDF, directions in the site frame
(:mod:`boatland.site.compass`: compass degrees, "from").

CSV (``#`` comment lines allowed; a header row names the columns, in any order):

- ``Hs`` [m], ``Tp`` [s], ``direction_from_deg`` — the total sea: significant height, peak period, the
  compass direction the waves come from;
- a **scatter diagram** has ``occurrence`` (probability, hours or counts ≥ 0; a sum far from 1 is normalised
  with a warning); a **hindcast** has ``time`` instead (ISO 8601, UTC: ``2021-01-31T21:00``; regular steps,
  increasing) — each row then lasts one step;
- optional wind-sea and swell partitions: ``wind_sea_Hs``, ``wind_sea_Tp``, ``wind_sea_direction_from_deg``,
  ``swell_Hs``, ``swell_Tp``, ``swell_direction_from_deg`` (a part with Hs 0 or empty fields is absent) —
  the sea is then judged as two spectra (Grøtting 2015 §3.2.1 eq. 3.41–3.45, :mod:`boatland.site.limits`);
- ``current_speed`` [m/s] and ``current_direction_from_deg`` (compass, where the water comes from — the
  site frame's one convention; an oceanographic "towards" direction is this + 180°): each sea state is judged in
  its own current (:mod:`boatland.site.flows`);
- ``wind_speed`` [m/s] and ``wind_direction_from_deg`` (compass, where the wind comes from, as meteorology gives
  it): each sea state is judged in its own wind (:mod:`boatland.site.flows`). The speed is taken as the 1-hour mean
  at 10 m above the sea that a scenario's ``[wind] speed`` is (:mod:`boatland.loads.wind`) — an assumption for a
  hindcast's hourly 10-m wind (ERA5 and NORA3 give instantaneous or hourly values; a 10-minute mean is about 6 %
  above the hourly one at 10 m/s by the NPD model's averaging-time factor, DNV-RP-C205 (2010) §2.3.2.11 — divide a
  10-minute mean by that to give the hourly one). ERA5 gives ``u10``/``v10``: speed = √(u² + v²), direction
  from = atan2(−u, −v) in compass degrees.

netCDF (netCDF-4, i.e. HDF5, read with h5py): one-dimensional variables over ``time`` with the names above, or
the CF standard names ``sea_surface_wave_significant_height``,
``sea_surface_wave_period_at_variance_spectral_density_maximum`` and ``sea_surface_wave_from_direction``;
``time`` with CF units (``hours since 2021-01-01 00:00:00``; seconds, minutes, hours or days); packed values
(``scale_factor``, ``add_offset``) and missing ones (``_FillValue``, ``missing_value``) read as CF says — a missing
sea state is refused, naming its time.
"""

from __future__ import annotations

import csv
import dataclasses
import math
import re
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from boatland.errors import BoatlandInputError, BoatlandWarning

__all__ = ["PARTS", "Weather", "read_weather"]

SUM_TOLERANCE = 0.01

#: The partitions a weather file may hold (name → column prefix).
PARTS = ("wind_sea", "swell")
#: The current's and the wind's columns (speed [m/s], compass direction it comes from [deg]).
CURRENT = ("current_speed", "current_direction_from_deg")
WIND = ("wind_speed", "wind_direction_from_deg")
FLOWS = {"current": CURRENT, "wind": WIND}
_CF = {"Hs": "sea_surface_wave_significant_height",
       "Tp": "sea_surface_wave_period_at_variance_spectral_density_maximum",
       "direction_from_deg": "sea_surface_wave_from_direction",
       "wind_speed": "wind_speed", "wind_direction_from_deg": "wind_from_direction"}


@dataclass(frozen=True, eq=False)
class Weather:
    """Sea states with their share of the time.

    Attributes
    ----------
    Hs, Tp, from_deg : ndarray, shape (n,)
        The total sea: [m], [s], compass direction it comes from [deg].
    weight : ndarray, shape (n,)
        Share of the time (sums to 1).
    time : ndarray of datetime64[s], shape (n,), or None
        Start of each sea state of a hindcast (regular steps); None for a scatter diagram.
    step_hours : float or None
        The hindcast's step [h].
    parts : dict
        Partitions present (``"wind_sea"``, ``"swell"``) → (Hs, Tp, from_deg) arrays (n,); Hs 0 where a row
        has none.
    current, wind : tuple of ndarray or None
        (speed [m/s], compass direction it comes from [deg]) per row, when the weather has them.
    source : str
    """

    Hs: np.ndarray
    Tp: np.ndarray
    from_deg: np.ndarray
    weight: np.ndarray
    time: np.ndarray | None = None
    step_hours: float | None = None
    parts: dict = field(default_factory=dict)
    current: tuple | None = None
    wind: tuple | None = None
    source: str = "<weather>"

    @property
    def n(self) -> int:
        return int(self.Hs.size)

    @property
    def months(self) -> np.ndarray | None:
        """Calendar month (1–12) of each row of a hindcast; None for a scatter."""
        if self.time is None:
            return None
        return self.time.astype("datetime64[M]").astype(int) % 12 + 1

    @property
    def years(self) -> np.ndarray | None:
        """Calendar year of each row of a hindcast; None for a scatter."""
        if self.time is None:
            return None
        return self.time.astype("datetime64[Y]").astype(int) + 1970

    @classmethod
    def scatter(cls, Hs, Tp, from_deg, occurrence, source: str = "<scatter>", parts=None, current=None,
                wind=None, lines=None) -> "Weather":
        """A scatter diagram from arrays (checked as a file's rows; occurrences normalised; ``lines``: each row's
        line in its file, for the messages)."""
        H, T, d, p = _columns(source, Hs=Hs, Tp=Tp, direction_from_deg=from_deg, occurrence=occurrence)
        if np.any(p < 0):
            i = int(np.flatnonzero(p < 0)[0])
            raise BoatlandInputError(f"{source}: row {i + 1}: occurrence = {p[i]:g} is negative; occurrences are "
                                     "probabilities, hours or counts ≥ 0")
        total = float(p.sum())
        if total <= 0:
            raise BoatlandInputError(f"{source}: no sea states with a positive occurrence")
        if abs(total - 1.0) > SUM_TOLERANCE:
            warnings.warn(f"{source}: occurrences sum to {total:.6g}, not 1: normalised (read as relative "
                          "frequencies, e.g. hours or counts)", BoatlandWarning, stacklevel=2)
        return cls(Hs=H, Tp=T, from_deg=d % 360.0, weight=p / total, parts=_parts(source, parts, H.size, lines),
                   current=_flow(source, "current", current, H.size, lines),
                   wind=_flow(source, "wind", wind, H.size, lines), source=source)

    @classmethod
    def series(cls, time, Hs, Tp, from_deg, source: str = "<hindcast>", parts=None, current=None,
               wind=None, lines=None) -> "Weather":
        """A hindcast from arrays: ``time`` (datetime64 or ISO strings), regular and increasing (``lines``: each
        row's line in its file, for the messages)."""
        t = np.asarray(time).astype("datetime64[s]")
        H, T, d = _columns(source, Hs=Hs, Tp=Tp, direction_from_deg=from_deg)
        if t.shape != H.shape:
            raise BoatlandInputError(f"{source}: {t.size} times for {H.size} sea states")
        step = _regular_step(source, t, lines)
        return cls(Hs=H, Tp=T, from_deg=d % 360.0, weight=np.full(H.size, 1.0 / H.size), time=t,
                   step_hours=step / 3600.0, parts=_parts(source, parts, H.size, lines),
                   current=_flow(source, "current", current, H.size, lines),
                   wind=_flow(source, "wind", wind, H.size, lines), source=source)

    def rotated(self, angle_deg: float) -> "Weather":
        """Every direction turned by ``angle_deg`` (the site turned; for tests of the compass)."""
        parts = {k: (h, t, (d + angle_deg) % 360.0) for k, (h, t, d) in self.parts.items()}
        turned = {k: None if f is None else (f[0], (f[1] + angle_deg) % 360.0)
                  for k, f in (("current", self.current), ("wind", self.wind))}
        return dataclasses.replace(self, from_deg=(self.from_deg + angle_deg) % 360.0, parts=parts, **turned)

    def take(self, rows) -> "Weather":
        """The sea states ``rows`` (indices) alone, as a scatter of their weights (for judging a subset)."""
        i = np.asarray(rows, dtype=int)
        parts = {k: tuple(a[i] for a in v) for k, v in self.parts.items()}
        flows = {k: None if f is None else tuple(a[i] for a in f) for k, f in (("current", self.current),
                                                                                  ("wind", self.wind))}
        return dataclasses.replace(self, Hs=self.Hs[i], Tp=self.Tp[i], from_deg=self.from_deg[i],
                                   weight=self.weight[i], time=None if self.time is None else self.time[i],
                                   parts=parts, **flows)

    def describe(self) -> str:
        """One line: what the weather is."""
        if self.time is None:
            return f"{self.source} (scatter diagram, {self.n:,} sea states)"
        a, b = (str(x.astype("datetime64[D]")) for x in (self.time[0], self.time[-1]))
        return f"{self.source} ({self.n:,} sea states every {self.step_hours:g} h, {a} – {b})"


def _columns(source: str, **cols) -> list[np.ndarray]:
    arrays = [np.atleast_1d(np.asarray(v, dtype=float)) for v in cols.values()]
    n = arrays[0].size
    out = []
    for (name, _), a in zip(cols.items(), arrays):
        if a.size == 1 and n != 1:
            a = np.full(n, float(a[0]))
        if a.shape != (n,):
            raise BoatlandInputError(f"{source}: column {name!r} has {a.size} values for {n} rows")
        bad = np.flatnonzero(~np.isfinite(a))
        if bad.size:
            raise BoatlandInputError(f"{source}: row {bad[0] + 1}: {name} is not a finite number")
        if name in ("Hs", "Tp") and np.any(a <= 0):
            i = int(np.flatnonzero(a <= 0)[0])
            raise BoatlandInputError(f"{source}: row {i + 1}: {name} = {a[i]:g} must be > 0")
        out.append(a)
    if n == 0:
        raise BoatlandInputError(f"{source}: no sea states")
    return out


def _where(i: int, lines) -> str:
    """Where row ``i`` is: its file line when known, else its row number."""
    return f"line {lines[i]}" if lines is not None else f"row {i + 1}"


def _parts(source: str, parts, n: int, lines=None) -> dict:
    out = {}
    for name, cols in (parts or {}).items():
        if name not in PARTS:
            raise BoatlandInputError(f"{source}: unknown partition {name!r}: use {', '.join(PARTS)}")
        H, T, d = (np.atleast_1d(np.asarray(c, dtype=float)) for c in cols)
        if not (H.shape == T.shape == d.shape == (n,)):
            raise BoatlandInputError(f"{source}: partition {name!r} has {H.size} rows for {n}")
        absent = ~np.isfinite(H) | (H <= 0)
        for col, a in ((f"{name}_Tp", T), (f"{name}_direction_from_deg", d)):
            bad = np.flatnonzero(~absent & (~np.isfinite(a) | ((a <= 0) if col.endswith("Tp") else False)))
            if bad.size:
                raise BoatlandInputError(f"{source}: {_where(int(bad[0]), lines)}: {col} = {a[bad[0]]:g} is not valid for a "
                                         f"part with {name}_Hs = {H[bad[0]]:g} (a peak period > 0, a direction)")
        out[name] = (np.where(absent, 0.0, H), np.where(absent, 1.0, T), np.where(absent, 0.0, d) % 360.0)
    return out


def _flow(source: str, what: str, flow, n: int, lines=None):
    """The current's or the wind's (speed, compass from) per row, checked."""
    if flow is None:
        return None
    U, d = (np.atleast_1d(np.asarray(c, dtype=float)) for c in flow)
    if not (U.shape == d.shape == (n,)):
        raise BoatlandInputError(f"{source}: the {what} has {U.size} rows for {n}")
    bad = np.flatnonzero(~np.isfinite(U) | (U < 0) | ~np.isfinite(d))
    if bad.size:
        i = int(bad[0])
        speed, direction = FLOWS[what]
        raise BoatlandInputError(f"{source}: {_where(i, lines)}: {speed} = {U[i]:g}, {direction} = "
                                 f"{d[i]:g}: need a speed ≥ 0 m/s and a direction")
    return U, d % 360.0


def _regular_step(source: str, t: np.ndarray, lines=None) -> float:
    if t.size < 2:
        raise BoatlandInputError(f"{source}: a hindcast needs at least two times")
    dt = np.diff(t).astype(np.int64)
    steps, counts = np.unique(dt, return_counts=True)
    step = int(steps[np.argmax(counts)])                # the series' own step: the most common one
    bad = np.flatnonzero(dt != step)
    if step <= 0 or bad.size:
        i = 0 if step <= 0 else int(bad[0])
        where = _where(i + 1, lines)
        raise BoatlandInputError(f"{source}: {where}: time {t[i + 1]} is {dt[i] / 3600:g} h after the previous one, "
                                 f"not {step / 3600:g} h: a hindcast must be a regular, increasing series (fill or "
                                 "cut the gap)")
    return float(step)


def read_weather(path: str | Path) -> Weather:
    """Read a scatter diagram or a hindcast (format: module docstring): ``.nc``/``.nc4`` netCDF-4, else CSV.

    Raises
    ------
    BoatlandInputError
        One line naming the file and the line, column or variable.
    """
    path = Path(path)
    if path.suffix.lower() in (".nc", ".nc4", ".netcdf"):
        return _read_netcdf(path)
    return _read_csv(path)


def _read_csv(path: Path) -> Weather:
    from boatland.inputs import read_input

    raw = read_input(path, "weather file", "text")
    try:
        text = raw.decode("utf-8-sig")            # a byte-order mark (as spreadsheets write) is not a column
    except UnicodeDecodeError as exc:
        raise BoatlandInputError(f"{path}: not a text CSV file (byte {exc.start} is not UTF-8)") from None
    lines = [(i + 1, ln) for i, ln in enumerate(text.splitlines()) if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise BoatlandInputError(f"{path}: empty weather file (need a header row, e.g. "
                                 "time,Hs,Tp,direction_from_deg or Hs,Tp,direction_from_deg,occurrence)")
    rows = list(csv.reader([ln for _, ln in lines]))
    header = [h.strip() for h in rows[0]]
    at = f"{path}: line {lines[0][0]}"
    if "direction_deg" in header and "direction_from_deg" not in header:
        raise BoatlandInputError(f"{at}: column 'direction_deg' (global, towards) is not read: give "
                                 "direction_from_deg, compass degrees from true North where the waves come from")
    kind = "time" if "time" in header else "occurrence" if "occurrence" in header else None
    need = ["Hs", "Tp", "direction_from_deg"]
    missing = [k for k in need if k not in header]
    if missing or kind is None or ("time" in header and "occurrence" in header):
        what = (f"missing column(s) {', '.join(missing)}" if missing else
                "both time and occurrence" if kind else "neither time (a hindcast) nor occurrence (a scatter)")
        raise BoatlandInputError(f"{at}: {what} in the header {','.join(header)!r} (need Hs, Tp, "
                                 "direction_from_deg and time or occurrence)")
    if len(set(header)) != len(header):
        dup = next(h for h in header if header.count(h) > 1)
        raise BoatlandInputError(f"{at}: column {dup!r} appears twice")
    part_cols = {p: (f"{p}_Hs", f"{p}_Tp", f"{p}_direction_from_deg") for p in PARTS if f"{p}_Hs" in header}
    for p, cols in part_cols.items():
        if any(c not in header for c in cols):
            raise BoatlandInputError(f"{at}: partition {p}: need all of {', '.join(cols)}")
    flow_cols = {}
    for what, cols in FLOWS.items():
        present = [c for c in cols if c in header]
        if present and len(present) != len(cols):
            raise BoatlandInputError(f"{at}: the {what} needs both {' and '.join(cols)}")
        if present:
            flow_cols[what] = cols
    numeric = need + ([] if kind == "time" else ["occurrence"]) + [c for cs in part_cols.values() for c in cs] \
        + [c for cs in flow_cols.values() for c in cs]
    idx = {h: i for i, h in enumerate(header)}
    n = len(rows) - 1
    data = {k: np.empty(n) for k in numeric}
    times = []
    optional = {c for cs in part_cols.values() for c in cs} | {c for cs in flow_cols.values() for c in cs}
    for r, ((lineno, _), row) in enumerate(zip(lines[1:], rows[1:])):
        if len(row) != len(header):
            raise BoatlandInputError(f"{path}: line {lineno}: {len(row)} fields for {len(header)} columns")
        for k in numeric:
            s = row[idx[k]].strip()
            if not s and k in optional:
                data[k][r] = math.nan
                continue
            try:
                v = float(s)
            except ValueError:
                raise BoatlandInputError(f"{path}: line {lineno}: {k} = {s!r} is not a number") from None
            if not math.isfinite(v):
                raise BoatlandInputError(f"{path}: line {lineno}: {k} = {s!r} is not finite")
            if k in ("Hs", "Tp") and v <= 0:
                raise BoatlandInputError(f"{path}: line {lineno}: {k} = {v:g} must be > 0")
            if k == "occurrence" and v < 0:
                raise BoatlandInputError(f"{path}: line {lineno}: occurrence = {v:g} is negative; occurrences are "
                                         "probabilities, hours or counts ≥ 0")
            data[k][r] = v
        if kind == "time":
            times.append(_time(path, lineno, row[idx["time"]]))
    parts = {p: tuple(data[c] for c in cols) for p, cols in part_cols.items()}
    flows = {}
    for what, cols in flow_cols.items():
        flows[what] = tuple(data[c] for c in cols)
        bad = np.flatnonzero(~np.isfinite(flows[what][0]) | ~np.isfinite(flows[what][1]))
        if bad.size:
            raise BoatlandInputError(f"{path}: line {lines[bad[0] + 1][0]}: the {what}'s speed or direction is empty")
    at_line = [ln for ln, _ in lines[1:]]
    if kind == "occurrence":
        return Weather.scatter(data["Hs"], data["Tp"], data["direction_from_deg"], data["occurrence"],
                               source=str(path), parts=parts, lines=at_line, **flows)
    t = np.array(times, dtype="datetime64[s]")
    return Weather.series(t, data["Hs"], data["Tp"], data["direction_from_deg"], source=str(path), parts=parts,
                          lines=at_line, **flows)


_ISO = re.compile(r"^\d{4}-\d{2}-\d{2}([T ]\d{2}(:\d{2}(:\d{2}(\.\d+)?)?)?)?Z?$")


def _time(path, lineno: int, text: str) -> np.datetime64:
    s = text.strip()
    if not _ISO.match(s):
        raise BoatlandInputError(f"{path}: line {lineno}: time {s!r} is not an ISO 8601 UTC time like "
                                 "2021-01-31T21:00 (no time-zone offsets: give UTC)")
    try:
        return np.datetime64(s.rstrip("Z").replace(" ", "T"), "s")
    except ValueError:
        raise BoatlandInputError(f"{path}: line {lineno}: time {s!r} is not a valid date") from None


_UNITS = {"second": 1, "seconds": 1, "s": 1, "minute": 60, "minutes": 60, "min": 60, "hour": 3600, "hours": 3600,
          "h": 3600, "day": 86400, "days": 86400, "d": 86400}


def _read_netcdf(path: Path) -> Weather:
    from boatland.inputs import open_hdf5

    with open_hdf5(path, "weather file") as f:
        def find(name: str, required: bool = True):
            if name in f and hasattr(f[name], "shape"):
                return f[name]
            std = _CF.get(name)
            for v in f.values():
                if std is not None and hasattr(v, "shape") and _attr(v, "standard_name") == std:
                    return v
            if required:
                raise BoatlandInputError(f"{path}: no variable {name!r}" + (f" (or standard_name {std!r})" if std
                                                                             else "") + " in the netCDF file")
            return None

        tv = find("time")
        units = _attr(tv, "units")
        m = re.match(r"^\s*(\w+)\s+since\s+(\d{4}-\d{2}-\d{2})(?:[T ](\d{2}:\d{2}(?::\d{2})?))?", units or "")
        if not m or m.group(1).lower() not in _UNITS:
            raise BoatlandInputError(f"{path}: variable 'time': units {units!r} are not CF time units like "
                                     "'hours since 2021-01-01 00:00:00'")
        calendar = str(_attr(tv, "calendar") or "standard").lower()
        if calendar not in ("standard", "gregorian", "proleptic_gregorian"):
            raise BoatlandInputError(f"{path}: variable 'time': calendar {calendar!r} is not read (give times in the "
                                     "standard, Gregorian calendar)")
        origin = np.datetime64(m.group(2) + "T" + (m.group(3) or "00:00"), "s")
        tvals = _decoded(tv)
        if not np.all(np.isfinite(tvals)):
            raise BoatlandInputError(f"{path}: variable 'time' has missing values")
        t = origin + np.round(tvals * _UNITS[m.group(1).lower()]).astype(np.int64).astype("timedelta64[s]")
        cols = {}
        for k in ("Hs", "Tp", "direction_from_deg"):
            var = find(k)
            v = _decoded(var)
            if v.size != t.size:
                raise BoatlandInputError(f"{path}: variable {k!r} has {v.size} values for {t.size} times")
            bad = np.flatnonzero(~np.isfinite(v))
            if bad.size:
                raise BoatlandInputError(f"{path}: variable {var.name.lstrip('/')!r} ({k}) has no value at time "
                                         f"{t[bad[0]]} ({bad.size} missing in all): fill or cut the gap")
            cols[k] = v
        parts = {}
        for p in PARTS:
            vs = [find(f"{p}_{c}", required=False) for c in ("Hs", "Tp", "direction_from_deg")]
            if any(v is not None for v in vs):
                if any(v is None for v in vs):
                    raise BoatlandInputError(f"{path}: partition {p}: need {p}_Hs, {p}_Tp and "
                                             f"{p}_direction_from_deg")
                parts[p] = tuple(_decoded(v) for v in vs)
        flows = {}
        for what, names in FLOWS.items():
            vs = [find(c, required=False) for c in names]
            if any(v is not None for v in vs) and any(v is None for v in vs):
                raise BoatlandInputError(f"{path}: the {what} needs both {' and '.join(names)}")
            if vs[0] is not None:
                flows[what] = tuple(_decoded(v) for v in vs)
                bad = np.flatnonzero(~np.isfinite(flows[what][0]) | ~np.isfinite(flows[what][1]))
                if bad.size:
                    raise BoatlandInputError(f"{path}: the {what} has no value at time {t[bad[0]]} ({bad.size} missing "
                                             "in all): fill or cut the gap")
    return Weather.series(t, cols["Hs"], cols["Tp"], cols["direction_from_deg"], source=str(path), parts=parts,
                          **flows)


def _decoded(var) -> np.ndarray:
    """A netCDF variable's values as CF says to read them: ``_FillValue`` / ``missing_value`` → NaN, then
    ``scale_factor`` and ``add_offset`` (packed integers, as ERA5 files are)."""
    raw = np.asarray(var[()]).ravel()
    v = raw.astype(float)
    for key in ("_FillValue", "missing_value"):
        fill = var.attrs.get(key)
        if fill is not None:
            for f in np.atleast_1d(fill):
                v[raw == f] = np.nan
    scale, offset = var.attrs.get("scale_factor"), var.attrs.get("add_offset")
    if scale is not None:
        v = v * float(np.atleast_1d(scale)[0])
    if offset is not None:
        v = v + float(np.atleast_1d(offset)[0])
    return v


def _attr(var, name: str):
    v = var.attrs.get(name)
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.ndarray) and v.size == 1:
        v = v.item()
        return v.decode("utf-8", "replace") if isinstance(v, bytes) else v
    return v
