"""A small validator for boatland's TOML input files (vessel files now, scenario files later).

What users of the files get (DESIGN.md §4):

- syntax errors with the line and column (``vessel.toml: line 7, column 12: ...``);
- *every* problem of a file at once, each with its key path (``hull.draft: must be > 0, got -1``);
- unknown keys are errors, with a "did you mean" from :mod:`difflib`;
- wrong types, missing required keys and out-of-range values.

A schema is a :class:`Table` of :class:`Key` (one value), :class:`Vector` (an array of numbers, or of
equal-length rows of numbers), :class:`TableList` (an array of tables, ``[[...]]``) and nested
:class:`Table` entries. :func:`validate` walks a parsed document against it, fills defaults, and
records problems in a :class:`Problems` collector; :meth:`Problems.raise_if_any` raises one :class:`SpecError` (a
:class:`~boatland.errors.BoatlandInputError`) whose message has a summary line and then one line
``file: key.path: problem`` per problem. Cross-field (physical) checks add to the same collector
before it raises, so the user sees everything in one go. :func:`json_schema` exports the same
schema as a JSON Schema (draft 2020-12) for editors, so the file format is defined once.

Example::

    SCHEMA = Table({"hull": Table({"draft": Key(float, required=True, gt=0.0)})})
    problems = Problems("vessel.toml")
    data = validate(parse_toml_file(path), SCHEMA, problems)
    problems.raise_if_any()
"""

from __future__ import annotations

import dataclasses
import difflib
import json
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping

from boatland.errors import BoatlandInputError

__all__ = ["Key", "Problems", "SpecError", "Table", "TableList", "Vector", "did_you_mean", "json_schema", "parse_toml",
           "parse_toml_file", "read_toml_text", "dump_toml", "key_changes", "validate"]

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
                    hint = did_you_mean(str(value), [str(c) for c in self.choices])
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
    entries : mapping of str to Key, Vector, TableList or Table
    required : bool
        The table itself must be present (otherwise an absent table counts as empty, so its
        defaults apply and its required keys are reported).
    optional : bool
        An absent table is left out of the result: no defaults, no "missing" problems for its keys
        (for sections whose absence means something, e.g. no ``[thrust]`` = no thrust).
    doc : str
    json_extra : mapping, optional
        Extra JSON-Schema keywords for :func:`json_schema` (conditional rules such as
        ``allOf``/``if``/``then`` that the table's own cross-field checks enforce when loading).
    """

    entries: Mapping[str, "Key | Vector | TableList | Table"] = field(default_factory=dict)
    required: bool = False
    optional: bool = False
    doc: str = ""
    json_extra: Mapping[str, Any] | None = None

    def overrides(self) -> "Table":
        """The same keys with no defaults, as an optional table: a file that may override some of them
        (a campaign's ``[incidents]`` over its base scenario's) gives only what it sets."""
        entries = {k: (v.overrides() if isinstance(v, Table) else
                       dataclasses.replace(v, default=_MISSING, required=False) if isinstance(v, (Key, Vector))
                       else v) for k, v in self.entries.items()}
        return dataclasses.replace(self, entries=entries, required=False, optional=True)


@dataclass(frozen=True)
class Vector:
    """An array of numbers (``position = [x, y]``) or of equal-length rows (``points = [[x, y, z], ...]``).

    Parameters
    ----------
    size : int, optional
        Exact number of items; otherwise ``min_size`` to ``max_size``.
    min_size, max_size : int
        Bounds on the number of items when ``size`` is not given.
    row : int, optional
        Each item is itself an array of this many numbers (a list of points).
    scalar : bool
        A single number is also accepted and means a one-item array.
    names : tuple of str, optional
        Names of the items (or of a row's numbers), for messages and the JSON Schema.
    required, default, gt, ge, lt, le, doc
        As for :class:`Key`; bounds apply to every number.

    The validated value is a tuple of floats (or a tuple of tuples of floats).
    """

    size: int | None = None
    min_size: int = 1
    max_size: int | None = None
    row: int | None = None
    scalar: bool = False
    names: tuple[str, ...] | None = None
    required: bool = False
    default: Any = _MISSING
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    doc: str = ""

    def _shape_text(self) -> str:
        names = f"[{', '.join(self.names)}]" if self.names else ""
        if self.row is not None:
            return f"an array of {names} rows" if names else f"an array of {self.row}-number rows"
        if self.size is not None:
            return f"{self.size} numbers {names}".rstrip()
        hi = f"{self.max_size}" if self.max_size is not None else "more"
        return f"an array of {self.min_size} or {hi} numbers" + (" (or one number)" if self.scalar else "")

    def _number(self, x: Any) -> tuple[float | None, str | None]:
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            return None, f"must be a number, got {_show(x)}"
        v = float(x)
        if not math.isfinite(v):
            return None, f"must be a finite number, got {x!r}"
        return v, Key(float, gt=self.gt, ge=self.ge, lt=self.lt, le=self.le)._range(v)

    def convert(self, value: Any, path: str, problems: "Problems") -> Any:
        """The validated tuple, or ``_MISSING`` after recording problems (item problems as ``path[i]``)."""
        if self.scalar and self.row is None and isinstance(value, (int, float)) and not isinstance(value, bool):
            value = [value]
        if not isinstance(value, list):
            problems.add(path, f"must be {self._shape_text()}, got {_show(value)}")
            return _MISSING
        n = len(value)
        if self.size is not None and n != self.size:
            problems.add(path, f"must be {self._shape_text()}, got {n} item{'s' if n != 1 else ''}")
            return _MISSING
        if n < self.min_size or (self.max_size is not None and n > self.max_size):
            problems.add(path, f"must be {self._shape_text()}, got {n} item{'s' if n != 1 else ''}")
            return _MISSING
        out: list[Any] = []
        ok = True
        for i, item in enumerate(value):
            ip = f"{path}[{i}]"
            if self.row is not None:
                if not isinstance(item, list) or len(item) != self.row:
                    what = f"[{', '.join(self.names)}]" if self.names else f"{self.row} numbers"
                    got = f"{len(item)} item(s)" if isinstance(item, list) else _show(item)
                    problems.add(ip, f"must be {what}, got {got}")
                    ok = False
                    continue
                row = []
                for j, x in enumerate(item):
                    v, msg = self._number(x)
                    if msg:
                        name = self.names[j] if self.names else str(j)
                        problems.add(ip, f"{name}: {msg}")
                        ok = False
                    row.append(v)
                out.append(tuple(row))
            else:
                v, msg = self._number(item)
                if msg:
                    problems.add(ip, msg)
                    ok = False
                out.append(v)
        return tuple(out) if ok else _MISSING


@dataclass(frozen=True)
class TableList:
    """An array of tables (``[[landing.struts]]``), each checked against ``table``.

    The validated value is a list of dicts (defaults filled); problems of item ``i`` carry the key
    path ``path[i].key``.
    """

    table: Table
    min_size: int = 1
    max_size: int | None = None
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


def did_you_mean(word: str, options) -> str:
    """`` (did you mean 'x'?)`` for the closest of ``options`` (or a case-insensitive match), or ``""``."""
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
            problems.add(_join(path, key), "unknown key" + (did_you_mean(key, valid) or
                                                              (f"; valid keys here: {', '.join(valid)}" if valid else "")))
    for key, entry in schema.entries.items():
        kp = _join(path, key)
        value = data.get(key, _MISSING)
        if isinstance(entry, Table):
            if value is _MISSING:
                if entry.required:
                    problems.add(kp, "missing table")
                elif entry.optional:
                    continue
                value = {}
            if not isinstance(value, dict):
                problems.add(kp, f"must be a table ([{kp}]), got {_show(value)}")
                continue
            out[key] = validate(value, entry, problems, kp)
            continue
        if isinstance(entry, TableList):
            if value is _MISSING:
                if entry.required:
                    problems.add(kp, f"missing (expected one or more [[{kp}]] tables)")
                continue
            if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
                problems.add(kp, f"must be an array of tables ([[{kp}]]), got {_show(value)}")
                continue
            n = len(value)
            if n < entry.min_size or (entry.max_size is not None and n > entry.max_size):
                hi = f"to {entry.max_size}" if entry.max_size is not None else "or more"
                problems.add(kp, f"must hold {entry.min_size} {hi} [[{kp}]] tables, got {n}")
                continue
            out[key] = [validate(v, entry.table, problems, f"{kp}[{i}]") for i, v in enumerate(value)]
            continue
        if isinstance(entry, Vector):
            if value is _MISSING:
                if entry.required:
                    doc = f": {entry.doc}" if entry.doc else ""
                    problems.add(kp, f"missing (expected {entry._shape_text()}{doc})")
                elif entry.default is not _MISSING:
                    out[key] = entry.default
                continue
            converted = entry.convert(value, kp, problems)
            if converted is not _MISSING:
                out[key] = converted
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


# ---------------------------------------------------------------------------------------- JSON Schema
_JSON_TYPES = {float: "number", int: "integer", str: "string", bool: "boolean"}
_BOUNDS = (("gt", "exclusiveMinimum"), ("ge", "minimum"), ("lt", "exclusiveMaximum"), ("le", "maximum"))


def _bounds(node) -> dict[str, Any]:
    return {js: getattr(node, name) for name, js in _BOUNDS if getattr(node, name) is not None}


def _jsonable(value: Any) -> Any:
    if isinstance(value, tuple):
        return [_jsonable(v) for v in value]
    return value


def _node_schema(node) -> dict[str, Any] | bool:
    if isinstance(node, Table):
        out: dict[str, Any] = {"type": "object"}
        if node.doc:
            out["description"] = node.doc
        out["properties"] = {k: _node_schema(v) for k, v in node.entries.items()}
        required = [k for k, v in node.entries.items() if getattr(v, "required", False)]
        if required:
            out["required"] = required
        out["additionalProperties"] = False
        if node.json_extra:
            out.update(node.json_extra)
        return out
    if isinstance(node, TableList):
        out = {"type": "array", "items": _node_schema(node.table), "minItems": node.min_size}
        if node.max_size is not None:
            out["maxItems"] = node.max_size
        if node.doc:
            out["description"] = node.doc
        return out
    if isinstance(node, Vector):
        number = {"type": "number", **_bounds(node)}
        item: dict[str, Any] = number
        if node.row is not None:
            item = {"type": "array", "items": number, "minItems": node.row, "maxItems": node.row}
        arr: dict[str, Any] = {"type": "array", "items": item}
        if node.size is not None:
            arr["minItems"] = arr["maxItems"] = node.size
        else:
            arr["minItems"] = node.min_size
            if node.max_size is not None:
                arr["maxItems"] = node.max_size
        out = {"anyOf": [number, arr]} if node.scalar and node.row is None else arr
        if node.doc:
            out["description"] = node.doc + (f" [{', '.join(node.names)}]" if node.names else "")
        if node.default is not _MISSING:
            out["default"] = _jsonable(node.default)
        return out
    if isinstance(node, Key):
        branches = []
        for t in node._types():
            b: dict[str, Any] = {"type": _JSON_TYPES.get(t, "string")}
            if t in (float, int):
                b.update(_bounds(node))
            if t in (str, bool) and node.choices is not None:
                b["enum"] = [c for c in node.choices if isinstance(c, t)]
            branches.append(b)
        out = branches[0] if len(branches) == 1 else {"anyOf": branches}
        if node.doc:
            out["description"] = node.doc
        if node.default is not _MISSING and node.default is not None:
            out["default"] = _jsonable(node.default)
        return out
    raise TypeError(f"not a schema node: {node!r}")


def json_schema(schema: Table, *, title: str = "", description: str = "",
                schema_id: str | None = None) -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a TOML format defined by ``schema``.

    Tables become objects with ``additionalProperties: false`` (unknown keys are errors in the
    files too), keys carry their type, bounds, choices, default and doc line (units in the doc),
    :class:`Vector` entries become arrays with item counts, :class:`TableList` arrays of objects.
    Conditional rules a table states in ``json_extra`` are merged in. Checks that need code
    (``Key.check``, cross-field physics) are not expressible and are left to the loader.
    """
    out: dict[str, Any] = {"$schema": "https://json-schema.org/draft/2020-12/schema"}
    if schema_id:
        out["$id"] = schema_id
    if title:
        out["title"] = title
    body = _node_schema(schema)
    if description:
        body["description"] = description
    out.update(body)
    return out


_LINE_COL = re.compile(r"\(at line (\d+), column (\d+)\)")
_EOF = re.compile(r"\(at end of document\)")


def parse_toml(text: str, source: str | Path = "<string>") -> dict[str, Any]:
    """Parse TOML text; a syntax error raises :class:`SpecError` naming the line and column."""
    try:
        return tomllib.loads(text)
    except RecursionError:
        raise SpecError(str(source), [("", "TOML syntax error: tables or arrays nested too deeply")]) from None
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


def read_toml_text(path: str | Path, what: str = "TOML file") -> str:
    """The text of a TOML file, read once (:func:`boatland.inputs.read_text_input`: a regular file of at most
    16 MiB). Missing, unreadable, not a regular file, too large or not UTF-8: :class:`SpecError`."""
    from boatland.inputs import read_text_input

    path = Path(path)
    try:
        return read_text_input(path, what, "toml")
    except BoatlandInputError as exc:
        message = str(exc)
        raise SpecError(str(path), [("", message.removeprefix(f"{path}: "))]) from None


def parse_toml_file(path: str | Path) -> dict[str, Any]:
    """Read and parse a TOML file (missing or unreadable files raise :class:`SpecError`)."""
    return parse_toml(read_toml_text(path), path)


_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _toml_key(key: str) -> str:
    return key if _BARE_KEY.fullmatch(key) else json.dumps(key, ensure_ascii=False)


def _toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)      # a JSON string is a TOML basic string
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_toml_key(k)} = {_toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"{type(v).__name__} has no TOML form")


def dump_toml(doc: dict[str, Any]) -> str:
    """A parsed TOML document (:func:`parse_toml`) as TOML text: top-level values, then one ``[table]`` per
    top-level table (deeper tables inline). ``parse_toml(dump_toml(d)) == d`` for every ``d`` of strings,
    numbers, booleans, lists and tables (dates are not written)."""
    lines = [f"{_toml_key(k)} = {_toml_value(v)}" for k, v in doc.items() if not isinstance(v, dict)]
    for k, table in doc.items():
        if isinstance(table, dict):
            lines += ["", f"[{_toml_key(k)}]"] + [f"{_toml_key(kk)} = {_toml_value(v)}" for kk, v in table.items()]
    return "\n".join(lines) + "\n"


def key_changes(changes: Mapping[str, Any] | None, overrides: Mapping[str, Any]) -> dict[str, Any]:
    """Key path → value from a ``changes`` mapping and keyword ``overrides`` (dots written as double
    underscores: ``sea__Hs=1.0`` is ``"sea.Hs"``), as the notebook API takes them.

    Raises
    ------
    TypeError
        A key path given both ways.
    """
    out = dict(changes or {})
    for key, value in overrides.items():
        path = key.replace("__", ".")
        if path in out:
            raise TypeError(f"{path!r} is given twice (in changes and as a keyword)")
        out[path] = value
    return out
