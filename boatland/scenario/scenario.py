r"""Scenario files: one landing trial (or a free-floating run), validated and immutable.

A scenario (TOML, SI units, angles in ``_deg`` keys; the format is :mod:`boatland.scenario.schema`,
exported as a JSON Schema by :func:`json_schema`)::

    name = "ctv_landing"
    [simulation]
    duration = 600.0            # [s]
    dt = 0.05                   # [s]; default min(0.05 s, Tp/100, fender contact period/20)
    seed = 1
    [vessel]
    database = "ctv27"          # built-in name or a path relative to this file
    # heading_deg, position: default bow on the landing, fender just touching the struts
    [landing]
    monopile_diameter = 6.5
    bearing_deg = 180.0         # the landing faces -x; struts[0] is on the vessel's port side
    strut_spacing = 1.5
    strut_diameter = 0.35
    standoff = 1.2              # pile surface to strut axes
    [fender]
    points = [[12.3, 0.75, 1.5], [12.3, -0.75, 1.5]]   # body frame, points[i] meets struts[i]
    stiffness = 1.0e6
    damping = 4.0e4
    mu_s = 0.6
    mu_k = 0.5
    [thrust]
    force = 80e3
    position = [-10.5, 0.0, -0.9]
    [sea]
    kind = "jonswap"
    Hs = 1.5
    Tp = 7.0
    relative_direction_deg = 180.0                       # head seas

:func:`load_scenario` reads a file and reports **every** problem at once, each with its key path
(``fender.points[1]: ...``), unknown keys with a "did you mean", syntax errors with line and column,
and physical nonsense that needs no database (negative Hs, dt too large for the waves, a fender
behind midship or under water, a strut normal pointing into the pile or away from the vessel,
thrust pushing away from the landing). Checks that need the vessel's hydrodynamic database (fender at
the bow of the hull, dt against the fender's contact period, waves within the database's band, hull
clear of the monopile) are :func:`boatland.checks.check`, called by whoever loads the database.
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import re
import warnings
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from boatland.errors import BoatlandWarning
from boatland.scenario.parts import (Fender, Incidents, InitialState, Landing, Output, Radiation, Sea,
                                           Simulation, Thrust, VesselSetup)
from boatland.loads.current import Current
from boatland.loads.wind import Wind
from boatland.scenario.schema import SCENARIO_SCHEMA, json_schema
from boatland.tomlspec import Problems, SpecError, did_you_mean, parse_toml_file, validate

__all__ = ["Scenario", "ScenarioWarning", "SpecError", "did_you_mean", "json_schema", "load_scenario",
           "scenario_from_dict"]


class ScenarioWarning(BoatlandWarning):
    """A scenario value that is possible but probably not meant."""


@dataclass(frozen=True, kw_only=True, eq=False)
class Scenario:
    """One validated scenario. Build it with :func:`load_scenario` or :func:`scenario_from_dict`.

    Attributes
    ----------
    name, description : str
    simulation : Simulation
    vessel : VesselSetup
    radiation : Radiation
    landing : Landing or None
        None: no monopile (free floating in open water).
    fender : Fender or None
        None: no contact.
    thrust : Thrust or None
        None: no thrust.
    sea : Sea or None
        None: calm water.
    current : Current or None
        A uniform current (:mod:`boatland.loads.current`); None: none.
    wind : Wind or None
        Wind with gusts (:mod:`boatland.loads.wind`); None: none.
    initial : InitialState
    incidents : Incidents
    output : Output
    source : str
        The file (or ``"<dict>"``).
    base_dir : Path
        Folder relative paths of the file are resolved against.
    document : dict
        The document as written (for :meth:`replace`, :meth:`digest` and provenance).
    warnings : tuple of str
        Doubtful values found when loading (also issued as :class:`ScenarioWarning`).
    """

    name: str
    description: str
    simulation: Simulation
    vessel: VesselSetup
    radiation: Radiation
    landing: Landing | None
    fender: Fender | None
    thrust: Thrust | None
    sea: Sea | None
    initial: InitialState
    incidents: Incidents
    output: Output
    current: Current | None = None
    wind: Wind | None = None
    source: str = "<dict>"
    base_dir: Path = field(default_factory=Path.cwd)
    document: Mapping[str, Any] = field(default_factory=dict, repr=False)
    warnings: tuple[str, ...] = ()
    databases: tuple[str, ...] | None = field(default=None, repr=False)

    # ------------------------------------------------------------------ derived values
    def start_pose(self) -> tuple[float, float, float]:
        """(x [m], y [m], heading ψ [rad]) of the reference point at t = 0, before ``initial`` is added.

        What needs the vessel's database too (the time step, the contacts, the wave model, the pile) is
        :meth:`boatland.landing.setup.Setup.of`."""
        x, y = self.vessel.position
        return float(x), float(y), math.radians(self.vessel.heading_deg)

    # ------------------------------------------------------------------ variants
    def replace(self, changes: Mapping[str, Any]) -> "Scenario":
        """A new scenario with some keys changed, validated again like a file.

        ``changes`` maps key paths as in the file (``"sea.Hs"``, ``"thrust.force"``,
        ``"landing.struts[1].diameter"``) to TOML values; ``None`` removes a key (or a whole table:
        ``{"thrust": None}``). Example: ``s.replace({"sea.Hs": 2.0, "simulation.seed": 7})``.
        """
        doc = copy.deepcopy(dict(self.document))
        for path, value in changes.items():
            _set_path(doc, path, value)
        return scenario_from_dict(doc, source=self.source, base_dir=self.base_dir, databases=self.databases)

    def digest(self) -> str:
        """SHA-256 of the document as written (canonical JSON) and the database it names: for provenance."""
        text = json.dumps(self.document, sort_keys=True, default=str)
        db = str(self.vessel.database_path) if self.vessel.database_path else self.vessel.database
        return hashlib.sha256(f"{text}\n{db}".encode()).hexdigest()


_PATH_PART = re.compile(r"([^.\[\]]+)((?:\[\d+\])*)")


def _set_path(doc: dict, path: str, value: Any) -> None:
    parts = path.split(".")
    node: Any = doc
    for depth, part in enumerate(parts):
        m = _PATH_PART.fullmatch(part)
        if not m:
            raise ValueError(f"not a key path: {path!r}")
        key, idx = m.group(1), [int(i) for i in re.findall(r"\[(\d+)\]", m.group(2))]
        last = depth == len(parts) - 1
        if last and not idx:
            if value is None:
                node.pop(key, None)
            else:
                node[key] = value
            return
        if key not in node:
            if idx:
                raise KeyError(f"{path}: no {key!r} in the scenario")
            node[key] = {}
        node = node[key]
        for j, i in enumerate(idx):
            if last and j == len(idx) - 1:
                node[i] = value
                return
            node = node[i]


# ---------------------------------------------------------------------------------------- loading
def load_scenario(path: str | Path, *, databases: Collection[str] | None = None) -> Scenario:
    """Read and validate a scenario file.

    Parameters
    ----------
    path : str or Path
        The TOML file.
    databases : collection of str, optional
        Names of the built-in databases (the edge passes ``boatland.hydro.builtin.BUILTIN``): a
        ``vessel.database`` that is neither one of them nor an existing file is then a problem
        with a "did you mean". Without it, any bare name is accepted as built-in.

    Raises
    ------
    SpecError (a BoatlandInputError)
        A syntax error (line and column), or every problem of the file with its key path.
    """
    path = Path(path)
    doc = parse_toml_file(path)
    return scenario_from_dict(doc, source=str(path), base_dir=path.resolve().parent, databases=databases,
                              default_name=path.stem)


def scenario_from_dict(doc: Mapping[str, Any], *, source: str = "<dict>", base_dir: str | Path | None = None,
                       databases: Collection[str] | None = None, default_name: str = "scenario") -> Scenario:
    """Validate a parsed scenario document (what :func:`tomllib.loads` returns) into a :class:`Scenario`.

    ``base_dir`` resolves relative paths (default: the working directory). Raises :class:`SpecError`
    with every problem; issues :class:`ScenarioWarning` for doubtful values.
    """
    from boatland.scenario import build as sec

    base = Path(base_dir) if base_dir is not None else Path.cwd()
    problems = Problems(source)
    data = validate(doc, SCENARIO_SCHEMA, problems)
    ctx = sec.Context(doc=doc, data=data, problems=problems, base_dir=base, notes=[])
    landing = sec.landing(ctx)
    fender = sec.fender(ctx)
    thrust = sec.thrust(ctx)
    vessel = sec.vessel(ctx, landing, fender, thrust, databases)
    sea = sec.sea(ctx, vessel.heading_deg if vessel is not None else 0.0)
    current, wind = sec.flows(ctx, vessel.heading_deg if vessel is not None else 0.0)
    simulation = sec.simulation(ctx, sea, thrust)
    initial = sec.initial(ctx)
    problems.raise_if_any()
    for note in ctx.notes:
        warnings.warn(f"{source}: {note}", ScenarioWarning, stacklevel=3)
    s = data.get("incidents", {})
    o = data.get("output", {})
    r = data["radiation"]
    return Scenario(
        name=data.get("name", default_name), description=data.get("description", ""), simulation=simulation,
        vessel=vessel, radiation=Radiation(method=r["method"], memory=r["memory"], tail=r["tail"], taper=r["taper"]),
        landing=landing, fender=fender, thrust=thrust, sea=sea, initial=initial, current=current, wind=wind,
        incidents=Incidents.from_table(s),
        output=Output(file=o.get("file"), log=o.get("log"), decimate=o["decimate"]),
        source=source, base_dir=base, document=copy.deepcopy(dict(doc)), warnings=tuple(ctx.notes),
        databases=tuple(databases) if databases is not None else None)
