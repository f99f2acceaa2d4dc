"""Scenario files as a user gives them: resolve the vessel's database, run every check, report.

The file format (:mod:`boatland.scenario.scenario`) validates a file without touching any database; this
module adds what needs one — the built-in names (:data:`boatland.hydro.builtin.BUILTIN`, so an unknown
name gets a "did you mean" with the other problems), reading the database, and :func:`boatland.checks.check`
— and formats the result for ``boatland scenario check``.

For the CLI::

    boatland scenario schema       → print(schema_text())
    boatland scenario check FILE   → report = check_file(FILE); print(report.text); exit report.exit_status
    boatland run [FILE]            → scenario, db, check = load_checked(FILE or default_scenario_path())

Beside the format's validation, every load runs the limits of :mod:`boatland.checks.limits` (values that
can only be mistakes): :func:`load` on the parsed document, :func:`check_loaded` with the database.
"""

from __future__ import annotations

import json
import warnings
from dataclasses import dataclass
from pathlib import Path

from boatland.checks import ScenarioCheck, check
from boatland.checks.limits import document_problems
from boatland.errors import BoatlandInputError, BoatlandWarning
from boatland.hydro.builtin import BUILTIN, load_builtin
from boatland.hydro.read import load_database
from boatland.resources import shipped_scenarios
from boatland.scenario.inputs import trial_inputs
from boatland.scenario.scenario import Scenario, ScenarioWarning, load_scenario
from boatland.scenario.schema import json_schema
from boatland.tomlspec import SpecError, parse_toml_file
from boatland.vessel.database import HydroDB

__all__ = ["CheckReport", "DEFAULT_SCENARIO", "check_file", "check_loaded", "default_scenario_path", "load",
           "load_checked", "resolve_database", "schema_text"]

#: The Quick-start trial ``boatland run`` uses without an argument (in ``scenarios/``).
DEFAULT_SCENARIO = "ctv_landing.toml"


def schema_text() -> str:
    """The JSON Schema of scenario files, as indented JSON text."""
    return json.dumps(json_schema(), indent=2, ensure_ascii=False)


def default_scenario_path() -> Path:
    """The default trial ``ctv_landing.toml``, shipped in the package (``boatland/scenarios/``; the
    checkout's ``scenarios/`` is a link to it), so an installed wheel finds it without the sources.

    Raises
    ------
    BoatlandInputError
        When the package was installed without its data (a broken install).
    """
    path = shipped_scenarios() / DEFAULT_SCENARIO
    if not path.is_file():
        raise BoatlandInputError(f"the default scenario is not available ({path} not found); give a scenario file")
    return path


def load(path: str | Path) -> Scenario:
    """:func:`load_scenario` knowing the built-in database names (unknown names are problems), with the
    document limits of :func:`boatland.checks.limits.document_problems` (non-finite numbers, seed range).

    Raises
    ------
    SpecError
        Every problem of the file with its key path.
    """
    doc = parse_toml_file(path)
    early = document_problems(doc)
    if not early:
        return load_scenario(path, databases=BUILTIN)
    problems = list(early)
    try:   # the other problems of the file too, as far as validation gets past these
        load_scenario(path, databases=BUILTIN)
    except SpecError as exc:
        problems += [p for p in exc.problems if p not in problems]
    except (KeyError, TypeError, ValueError):  # validation tripped over a value refused above
        pass
    raise SpecError(str(path), problems)


def resolve_database(scenario: Scenario) -> HydroDB:
    """The hydrodynamic database ``scenario.vessel.database`` names (built-in or a file).

    Raises
    ------
    SpecError
        The database cannot be read (key ``vessel.database``).
    """
    v = scenario.vessel
    try:
        return load_builtin(v.database) if v.database_path is None else load_database(v.database_path)
    except SpecError:
        raise
    except BoatlandInputError as exc:
        raise SpecError(scenario.source, [("vessel.database", str(exc))]) from None


def load_checked(path: str | Path) -> tuple[Scenario, HydroDB, ScenarioCheck]:
    """Load a scenario, read its database and run every check; what ``boatland run`` starts with.

    Warnings of the checks are issued as :class:`ScenarioWarning` (the CLI shows them).

    Raises
    ------
    SpecError
        Any problem of the file, of its database, or of the two together (all with key paths).
    """
    scenario = load(path)
    db, found = check_loaded(scenario)
    return scenario, db, found


def check_loaded(scenario: Scenario) -> tuple[HydroDB, ScenarioCheck]:
    """Read the database of a loaded scenario and run every check against it: what :func:`load_checked`
    does after :func:`load` (an edge that must look at the scenario first, e.g. to guard its outputs,
    calls the two itself). Warnings are issued as :class:`ScenarioWarning`.

    Raises
    ------
    SpecError
        Problems of the scenario with its database, and the limits of
        :func:`boatland.checks.limits.scenario_problems`.
    """
    db = resolve_database(scenario)
    found = check(scenario, db)
    found.raise_if_problems(scenario.source)
    for key, msg in found.warnings:
        warnings.warn(f"{scenario.source}: {key}: {msg}", ScenarioWarning, stacklevel=2)
    return db, found


@dataclass(frozen=True)
class CheckReport:
    """What ``boatland scenario check FILE`` prints, and its exit status (0 clean or warnings only, 2 problems)."""

    ok: bool
    problems: tuple[tuple[str, str], ...]
    warnings: tuple[str, ...]
    notes: tuple[str, ...]
    text: str
    source: str = ""
    scenario: str | None = None
    summary: str = ""
    inputs: dict | None = None

    @property
    def exit_status(self) -> int:
        return 0 if self.ok else BoatlandInputError.exit_status

    def as_dict(self) -> dict:
        """``boatland scenario check --json``: verdict, problems with their key paths, warnings, notes."""
        return {"file": self.source, "ok": self.ok, "scenario": self.scenario, "summary": self.summary,
                "inputs": self.inputs, "problems": [{"key": k, "message": m} for k, m in self.problems],
                "warnings": list(self.warnings), "notes": list(self.notes)}


def _summary(s: Scenario) -> str:
    parts = [f"vessel {s.vessel.database}"]
    if s.sea is None:
        parts.append("calm water")
    else:
        w = s.sea.waves
        if s.sea.kind == "regular":
            parts.append(f"regular H {w.H:g} m T {w.T:g} s")
        elif s.sea.kind == "measured":
            parts.append(f"measured record {w.source}")
        else:
            parts.append(" + ".join(f"{p.shape.label} Hs {p.Hs:g} m "
                                    f"Tp {p.Tp:.3g} s" for p in w.parts))
    if s.landing is not None:
        parts.append(f"{len(s.landing.struts)} strut(s) on a {s.landing.monopile_diameter:g} m pile")
    parts.append(f"fender {'×' + str(len(s.fender.points)) if s.fender else 'none'}")
    if s.thrust is None:
        parts.append("no thrust")
    else:
        f = s.thrust.force
        parts.append(f"thrust {f / 1e3:g} kN" if f >= 1e3 else f"thrust {f:g} N")
    parts.append(f"{s.simulation.duration:g} s")
    return ", ".join(parts)


def check_file(path: str | Path) -> CheckReport:
    """Validate a scenario file against its database without running it; never raises for user mistakes."""
    source = str(path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BoatlandWarning)
        try:
            scenario = load(path)
            db = resolve_database(scenario)
            found = check(scenario, db, memory=True)
        except SpecError as exc:
            return CheckReport(ok=False, problems=tuple(exc.problems), warnings=(), notes=(), text=str(exc),
                               source=source)
        except BoatlandInputError as exc:
            return CheckReport(ok=False, problems=(("", str(exc)),), warnings=(), notes=(), text=str(exc),
                               source=source)
    load_warnings = [str(w.message) for w in caught if issubclass(w.category, BoatlandWarning)]
    warns = tuple(load_warnings) + tuple(f"{source}: {k}: {m}" for k, m in found.warnings)
    if not found.ok:
        text = str(SpecError(source, list(found.problems)))
    else:
        text = f"{source}: OK: {scenario.name} ({_summary(scenario)})"
    lines = [text] + [f"  warning: {w}" for w in warns] + [f"  note: {n}" for n in found.notes]
    return CheckReport(ok=found.ok, problems=found.problems, warnings=warns, notes=found.notes,
                       text="\n".join(lines), source=source, scenario=scenario.name, summary=_summary(scenario),
                       inputs=trial_inputs(scenario))
