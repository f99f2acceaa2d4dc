"""A small validator for boatland's TOML input files (vessel files now, scenario files later).

What users of the files get (DESIGN.md §4):

- syntax errors with the line and column (``vessel.toml: line 7, column 12: ...``);
- *every* problem of a file at once, each with its key path (``hull.draft: must be > 0, got -1``);
- unknown keys are errors, with a "did you mean" from :mod:`difflib`;
- wrong types, missing required keys and out-of-range values.

A schema is a :class:`Table` of :class:`Key` and nested :class:`Table` entries. :func:`validate`
walks a parsed document against it, fills defaults, and records problems in a :class:`Problems`
collector; :meth:`Problems.raise_if_any` raises one :class:`SpecError` (a
:class:`~boatland.errors.BoatlandInputError`) whose message has a summary line and then one line
``file: key.path: problem`` per problem. Cross-field (physical) checks add to the same collector
before it raises, so the user sees everything in one go.

Example::

    SCHEMA = Table({"hull": Table({"draft": Key(float, required=True, gt=0.0)})})
    problems = Problems("vessel.toml")
    data = validate(parse_toml_file(path), SCHEMA, problems)
    problems.raise_if_any()
"""

from __future__ import annotations

import difflib
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping

from boatland.errors import BoatlandInputError

__all__ = ["Key", "Problems", "SpecError", "Table", "parse_toml", "parse_toml_file", "validate"]

_MISSING = object()


class SpecError(BoatlandInputError):
    """Problems found in an input file.

    Attributes
    ----------
    source : str
        The file (as the user named it).
    problems : list of (str, str)
        ``(key_path, message)`` pairs; the key path is ``""`` for problems of the whole file
        (syntax errors).
    """

    def __init__(self, source: str, problems: list[tuple[str, str]]):
        self.source = source
        self.problems = list(problems)
        lines = [f"{source}: {k}: {m}" if k else f"{source}: {m}" for k, m in self.problems]
        if len(lines) == 1:
            text = lines[0]
        else:
            text = f"{source}: {len(lines)} problems:\n" + "\n".join("  " + ln for ln in lines)
        super().__init__(text)

    def keys(self) -> list[str]:
        """The key paths with problems, in the order found."""
        return [k for k, _ in self.problems]


class Problems:
    """Collects ``(key_path, message)`` problems of one file."""

    def __init__(self, source: str | Path):
        self.source = str(source)
        self.items: list[tuple[str, str]] = []

    def add(self, key: str, message: str) -> None:
        self.items.append((key, message))

    def has(self, *prefixes: str) -> bool:
        """True when a problem was recorded at or below any of the key paths ``prefixes``."""
        return any(k == p or k.startswith(p + ".") for k, _ in self.items for p in prefixes)

    def __bool__(self) -> bool:
        return bool(self.items)

    def __len__(self) -> int:
        return len(self.items)

    def raise_if_any(self) -> None:
        if self.items:
            raise SpecError(self.source, self.items)


_TYPE_NAMES = {float: "a number", int: "an integer", str: "a string", bool: "true or false"}


@dataclass(frozen=True)
class Key:
    """One key of a table.

    Parameters
    ----------
    types : type or tuple of types
        Accepted Python types after TOML parsing (``float`` also accepts integers; ``bool`` is never
        accepted as a number).
    required : bool
        A missing key is a problem.
    default : any
        Value used when the key is absent (and not required). Absent without a default → omitted.
    gt, ge, lt, le : float, optional
        Bounds for numbers.
    choices : tuple, optional
        Allowed values (strings).
    check : callable, optional
        ``check(value) -> str | None``: extra test; a returned string is the problem.
    doc : str
        One line for users (shown in JSON-Schema exports later).
    """

    types: type | tuple[type, ...]
    required: bool = False
    default: Any = _MISSING
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    choices: tuple | None = None
    check: Callable[[Any], str | None] | None = None
    doc: str = ""

    def _types(self) -> tuple[type, ...]:
        return self.types if isinstance(self.types, tuple) else (self.types,)

    def describe(self) -> str:
        names = [_TYPE_NAMES.get(t, t.__name__) for t in self._types()]
        return " or ".join(names)

    def convert(self, value: Any) -> tuple[Any, str | None]:
        """The value converted to the key's type, or a problem message."""
        for t in self._types():
            if t is float and isinstance(value, (int, float)) and not isinstance(value, bool):
                v = float(value)
                if not math.isfinite(v):
                    return None, f"must be a finite number, got {value!r}"
                return v, self._range(v)
            if t is int and isinstance(value, int) and not isinstance(value, bool):
                return value, self._range(value)
            if t in (str, bool) and isinstance(value, t):
                if self.choices is not None and value not in self.choices:
                    hint = _did_you_mean(str(value), [str(c) for c in self.choices])
                    return None, (f"must be one of {', '.join(repr(c) for c in self.choices)}, got {value!r}"
                                  + hint)
                return value, None
        return None, f"must be {self.describe()}, got {_show(value)}"

    def _range(self, v: float) -> str | None:
        for bound, op, text in ((self.gt, lambda a, b: a > b, ">"), (self.ge, lambda a, b: a >= b, "≥"),
                                (self.lt, lambda a, b: a < b, "<"), (self.le, lambda a, b: a <= b, "≤")):
            if bound is not None and not op(v, bound):
                return f"must be {text} {bound:g}, got {v:g}"
        return None


@dataclass(frozen=True)
class Table:
    """A TOML table: its keys and sub-tables.

    Parameters
    ----------
    entries : mapping of str to Key or Table
    required : bool
        The table itself must be present (otherwise an absent table counts as empty, so its
        defaults apply and its required keys are reported).
    doc : str
    """

    entries: Mapping[str, "Key | Table"] = field(default_factory=dict)
    required: bool = False
    doc: str = ""


def _show(value: Any) -> str:
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "an array"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return repr(value)
    return f"{value!r} ({type(value).__name__})" if not isinstance(value, (int, float)) else repr(value)


def _did_you_mean(word: str, options) -> str:
    close = difflib.get_close_matches(word, list(options), n=1, cutoff=0.6)
    if not close:
        lower = {o.lower(): o for o in options}
        close = [lower[word.lower()]] if word.lower() in lower else []
    return f" (did you mean {close[0]!r}?)" if close else ""


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def validate(data: Mapping[str, Any], schema: Table, problems: Problems, path: str = "") -> dict[str, Any]:
    """Check ``data`` against ``schema``; return the values with defaults filled in.

    Keys with problems are left out of the result (so later cross-field checks can skip them).
    Every problem goes into ``problems`` with its dotted key path.
    """
    out: dict[str, Any] = {}
    for key, value in data.items():
        if key not in schema.entries:
            valid = list(schema.entries)
            problems.add(_join(path, key), "unknown key" + (_did_you_mean(key, valid) or
                                                              (f"; valid keys here: {', '.join(valid)}" if valid else "")))
    for key, entry in schema.entries.items():
        kp = _join(path, key)
        value = data.get(key, _MISSING)
        if isinstance(entry, Table):
            if value is _MISSING:
                if entry.required:
                    problems.add(kp, "missing table")
                value = {}
            if not isinstance(value, dict):
                problems.add(kp, f"must be a table ([{kp}]), got {_show(value)}")
                continue
            out[key] = validate(value, entry, problems, kp)
            continue
        if value is _MISSING:
            if entry.required:
                problems.add(kp, f"missing (expected {entry.describe()}{': ' + entry.doc if entry.doc else ''})")
            elif entry.default is not _MISSING:
                out[key] = entry.default
            continue
        converted, problem = entry.convert(value)
        if problem is None and entry.check is not None:
            problem = entry.check(converted)
        if problem is not None:
            problems.add(kp, problem)
        else:
            out[key] = converted
    return out


_LINE_COL = re.compile(r"\(at line (\d+), column (\d+)\)")
_EOF = re.compile(r"\(at end of document\)")


def parse_toml(text: str, source: str | Path = "<string>") -> dict[str, Any]:
    """Parse TOML text; a syntax error raises :class:`SpecError` naming the line and column."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = _LINE_COL.search(msg)
        if m:
            where = f"line {m.group(1)}, column {m.group(2)}"
            msg = _LINE_COL.sub("", msg).strip()
        elif _EOF.search(msg):
            where = "end of file"
            msg = _EOF.sub("", msg).strip()
        else:
            where = ""
        text_msg = f"{where}: TOML syntax error: {msg}" if where else f"TOML syntax error: {msg}"
        raise SpecError(str(source), [("", text_msg)]) from None


def parse_toml_file(path: str | Path) -> dict[str, Any]:
    """Read and parse a TOML file (missing or unreadable files raise :class:`SpecError`)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SpecError(str(path), [("", "file not found")]) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise SpecError(str(path), [("", f"cannot be read ({exc.__class__.__name__}: {exc})")]) from None
    return parse_toml(text, path)
