"""Reading users' wave records: a CSV time series of elevation at a gauge (Ferreira González 2023 §5.2.3).

CSV format
    Two columns, time [s] and elevation [m] (or more, choosing the elevation column); comma,
    semicolon or whitespace separated; an optional header line; ``#`` starts a comment. The time
    step must be uniform (each step within ``rtol`` of the median step), the samples in order,
    without gaps or NaN; every violation is reported as one line naming the file and line.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.waves.measured import check_uniform_time

__all__ = ["read_elevation_csv"]

_SPLIT = re.compile(r"[,;\s]+")


def read_elevation_csv(path, column: int = 1, rtol: float = 0.01) -> tuple[np.ndarray, np.ndarray]:
    """Read a gauge record: returns (t [s], η [m]) after checking it (module docstring).

    Parameters
    ----------
    path : str or Path
        The CSV file.
    column : int
        0-based column of the elevation (time is column 0).
    rtol : float
        Allowed relative deviation of each time step from the median step.

    Raises
    ------
    BoatlandInputError
        ``file: line n: what is wrong; what is valid`` — unreadable numbers, NaN/inf, too few
        columns, non-increasing or non-uniform time, gaps (missing samples), fewer than 4 samples.
    """
    path = Path(path)
    from boatland.inputs import read_input

    raw = read_input(path, "wave record", "text")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise BoatlandInputError(f"{path}: not a text (UTF-8) file; "
                                 "expected a CSV of time [s], elevation [m]") from None
    times, values, lines = [], [], []
    seen_data = False
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        fields = [f for f in _SPLIT.split(line) if f]
        if len(fields) <= column:
            raise BoatlandInputError(f"{path}: line {lineno}: {len(fields)} column(s); expected at least "
                                     f"{column + 1} (time [s], ..., elevation [m] in column {column + 1})")
        try:
            t, eta = float(fields[0]), float(fields[column])
        except ValueError:
            if not seen_data:
                seen_data = True  # the one optional header line
                continue
            raise BoatlandInputError(f"{path}: line {lineno}: {line[:60]!r} is not two numbers "
                                     "(time [s], elevation [m]); only the first line may be a header") from None
        seen_data = True
        for name, v, text_v in (("time", t, fields[0]), ("elevation", eta, fields[column])):
            if not math.isfinite(v):
                raise BoatlandInputError(f"{path}: line {lineno}: {name} is {text_v}; every sample must be a "
                                         "finite number (fill or cut gaps before replay)")
        times.append(t)
        values.append(eta)
        lines.append(lineno)
    if len(times) < 4:
        raise BoatlandInputError(f"{path}: {len(times)} sample(s); a wave record needs at least 4 "
                                 "(time [s], elevation [m] per line)")
    t = np.array(times)
    check_uniform_time(t, rtol, source=str(path), lines=lines)
    return t, np.array(values)
