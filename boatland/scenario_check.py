"""Scenario files at the edge: resolve the vessel's database, run every check, report.

The model (:mod:`boatland.model.scenario`) validates a file without touching any database; this
module adds what needs one — the built-in names (:data:`boatland.hydro.builtin.BUILTIN`, so an unknown
name gets a "did you mean" with the other problems), reading the database, and
:meth:`Scenario.check_against` — and formats the result for ``boatland scenario check``.

For the CLI::

    boatland scenario schema       → print(schema_text())
    boatland scenario check FILE   → report = check_file(FILE); print(report.text); exit report.exit_status
    boatland run [FILE]            → scenario, db, check = load_checked(FILE or default_scenario_path())

Beside the model's validation and :meth:`Scenario.check_against`, every load runs the limits of
:mod:`boatland.model.limits` (values that can only be mistakes): :func:`load` on the parsed document,
:func:`check_loaded` with the database.
"""

from __future__ import annotations

import json
import warnings
from dataclasses import dataclass
from pathlib import Path

from boatland.errors import BoatlandInputError, BoatlandWarning
from boatland.hydro import read_hydro
from boatland.hydro.builtin import BUILTIN, load_builtin
from boatland.model.hydrodb import HydroDB
from boatland.model.landed import check_memory
from boatland.resources import shipped_scenarios
from boatland.model.limits import document_problems, scenario_problems
from boatland.model.scenario import Scenario, ScenarioWarning, load_scenario
from boatland.model.scenario_checks import ScenarioCheck
from boatland.model.scenario_schema import json_schema
from boatland.model.tomlspec import SpecError
from boatland.trial.simulate import prepare_memory

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
    document limits of :func:`boatland.model.limits.document_problems` (non-finite numbers, seed range).

    Raises
    ------
    SpecError
        Every problem of the file with its key path.
    """
    from boatland.model.tomlspec import parse_toml_file

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
        if v.database_path is None:
            return load_builtin(v.database)
        db, _ = read_hydro(v.database_path)
        return db
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
    db, check = check_loaded(scenario)
    return scenario, db, check


def check_loaded(scenario: Scenario) -> tuple[HydroDB, ScenarioCheck]:
    """Read the database of a loaded scenario and run every check against it: what :func:`load_checked`
    does after :func:`load` (an edge that must look at the scenario first, e.g. to guard its outputs,
    calls the two itself). Warnings are issued as :class:`ScenarioWarning`.

    Raises
    ------
    SpecError
        Problems of the scenario with its database, and the limits of
        :func:`boatland.model.limits.scenario_problems`.
    """
    db = resolve_database(scenario)
    check = scenario.check_against(db)
    problems = list(check.problems) + [p for p in scenario_problems(scenario, db) if p not in check.problems]
    if problems:
        raise SpecError(scenario.source, problems)
    for key, msg in check.warnings:
        warnings.warn(f"{scenario.source}: {key}: {msg}", ScenarioWarning, stacklevel=2)
    return db, check


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
            parts.append(" + ".join(f"{p.kind.upper() if p.kind != 'jonswap' else 'JONSWAP'} Hs {p.Hs:g} m "
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


def _with_memory_check(scenario: Scenario, db: HydroDB, check: ScenarioCheck) -> ScenarioCheck:
    """Add the radiation memory's check at the landed natural modes (:func:`boatland.model.landed.check_memory`)."""
    memory = prepare_memory(scenario, db)
    mc = check_memory(scenario, db, memory, scenario.time_step(db))
    return ScenarioCheck(problems=check.problems + mc.problems, warnings=check.warnings + mc.warnings,
                         notes=check.notes + mc.notes)


def check_file(path: str | Path) -> CheckReport:
    """Validate a scenario file against its database without running it; never raises for user mistakes."""
    source = str(path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BoatlandWarning)
        try:
            scenario = load(path)
            db = resolve_database(scenario)
            check = scenario.check_against(db)
            limits = [p for p in scenario_problems(scenario, db) if p not in check.problems]
            if limits:
                check = ScenarioCheck(problems=check.problems + tuple(limits), warnings=check.warnings,
                                      notes=check.notes)
            if check.ok and db.M is not None:
                check = _with_memory_check(scenario, db, check)
        except SpecError as exc:
            return CheckReport(ok=False, problems=tuple(exc.problems), warnings=(), notes=(), text=str(exc),
                               source=source)
        except BoatlandInputError as exc:
            return CheckReport(ok=False, problems=(("", str(exc)),), warnings=(), notes=(), text=str(exc),
                               source=source)
    load_warnings = [str(w.message) for w in caught if issubclass(w.category, BoatlandWarning)]
    warns = tuple(load_warnings) + tuple(f"{source}: {k}: {m}" for k, m in check.warnings)
    if not check.ok:
        text = str(SpecError(source, list(check.problems)))
    else:
        text = f"{source}: OK: {scenario.name} ({_summary(scenario)})"
    lines = [text] + [f"  warning: {w}" for w in warns] + [f"  note: {n}" for n in check.notes]
    from boatland.trial.inputs import trial_inputs

    return CheckReport(ok=check.ok, problems=check.problems, warnings=warns, notes=check.notes,
                       text="\n".join(lines), source=source, scenario=scenario.name, summary=_summary(scenario),
                       inputs=trial_inputs(scenario))
