"""A campaign: a base scenario, axes to sweep, N seeds per case — parsed from TOML into a plan of trials.

File format (``scenarios/campaigns/*.toml``)::

    name = "demo"
    scenario = "../ctv_landing.toml"     # the base scenario, relative to this file
    seeds = 8                            # trials per case (wave seeds)
    master_seed = 20261122               # every trial's seed derives from it (SeedSequence)
    access = 1800.0                      # [s] the access: exposure to the full sea, after the settling
                                         # (thrust on) and the waves' start-up ramp (older files: duration)

    [set]                                # fixed changes to the base scenario (key paths)
    "radiation.method" = "state_space"

    [axes]                               # swept keys (any scenario key path) → values; the cases
    "sea.Hs" = [0.5, 1.0, 1.5]           # are their Cartesian product, in file order
    "sea.relative_direction_deg" = [180.0, 135.0]

    [incidents]                          # incident definitions (Grøtting 2015 §3.3, §4.2)
    slip_distance = [0.1]                # [m] from the landing position
    slide_within = [{distance = 0.5, window = 120.0}]   # [m] slid within [s]
    roll_limit_deg = [10.0]

    [store]
    keep_series = [0]                    # trial numbers whose full time series are stored

    method = "isee"                      # optional: importance sampling of the first slip instead of
                                         # N seeds per case (boatland.campaign.isee); then:
    [isee]
    target_cov = 0.1                     # stop a run when its estimate's CoV reaches this
    accept = "best"                      # optional: find each case's limiting Hs at this probability
    limit_width = 0.03                   # optional: … each to ±3 % (95 %), the samples going where they narrow it

Seeds (DESIGN.md §2): trial ``k`` of every case uses the wave seed
``SeedSequence(master_seed, spawn_key=(k,))`` — the same realisation family across cases (common
random numbers: trends along an axis are not blurred by different seeds), and independent of the
order, the worker count and the executor that runs the trials.
"""

from __future__ import annotations

import functools
import hashlib
import itertools
import json
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from boatland import __version__
from boatland.errors import BoatlandInputError, BoatlandWarning
from boatland.vessel.imported import database_files
from boatland.scenario.scenario import Scenario
from boatland.scenario.schema import SCENARIO_SCHEMA
from boatland.tomlspec import Key, Problems, SpecError, Table, Vector, dump_toml, parse_toml, read_toml_text, validate
from boatland.trial.simulate import exposure_start

__all__ = ["Campaign", "Case", "IseeSettings", "TrialSpec", "load_campaign", "change_campaign", "plan_json", "trial_seed", "file_sha256",
           "CAMPAIGN_SCHEMA", "METHODS"]

#: How a campaign estimates its probabilities: N wave seeds per case, or importance sampling of the
#: elementary events of the first slip (:mod:`boatland.campaign.isee`).
METHODS = ("monte-carlo", "isee")

ISEE_SCHEMA = Table({
    "target_cov": Key(float, default=0.1, gt=0.0, le=1.0,
                      doc="stop a run once the coefficient of variation of its estimate is at most this"),
    "batch": Key(int, default=20, ge=1, le=1000, doc="samples per round (a run stops only after a whole batch)"),
    "min_samples": Key(int, default=40, ge=1, le=100000, doc="samples of a run before it may stop"),
    "max_samples": Key(int, default=2000, ge=1, le=100000, doc="samples of a run at most"),
    "directions": Key(int, default=32, ge=3, le=64, doc="slip directions per contact (the inscribed M-gon)"),
    "kappa": Key(float, default=0.3, ge=0.0, le=3.0,
                 doc="guard of the sampling domain [standard deviations of each margin]"),
    "settle": Key(float, default=30.0, ge=0.0, le=600.0,
                  doc="[s] settling time after the wave ramp before the access (its incidents are counted)"),
    "incident": Key(str, default="first slip", doc="the incident definition the stopping rule and the limiting Hs use"),
    "accept": Key((float, str), doc="accepted probability of the incident per access (or best / conservative / "
                                    "non-conservative): find each case's limiting Hs"),
    "levels": Key(int, default=4, ge=1, le=12, doc="runs along Hs per case at most, for the limiting Hs"),
    "limit_width": Key(float, gt=0.0, lt=1.0,
                       doc="with accept: sample on until the limiting Hs's 95 % interval lies within ± this "
                           "fraction of it (the level nearest the accepted P gets the samples)"),
}, optional=True)

CAMPAIGN_SCHEMA = Table({
    "name": Key(str, required=True, doc="campaign name"),
    "description": Key(str, default="", doc="one line shown in reports"),
    "scenario": Key(str, required=True, doc="base scenario file, relative to the campaign file"),
    "method": Key(str, default="monte-carlo", choices=METHODS,
                  doc="monte-carlo: N wave seeds per case; isee: importance sampling of the first slip"),
    "seeds": Key(int, ge=1, le=100000, doc="trials (wave seeds) per case (monte-carlo; required there)"),
    "master_seed": Key(int, default=0, ge=0, doc="master seed of every trial's wave seed"),
    "access": Key((int, float), gt=0.0, doc="[s] the access: the exposure to the full sea that the incidents "
                                            "count over; every trial runs its settling and wave ramp first, then "
                                            "this long"),
    "duration": Key((int, float), gt=0.0, doc="[s] the older name of access (the same value; a scenario's "
                                              "simulation.duration is the whole trial)"),
    "set": Table({}, optional=True, doc="fixed changes to the base scenario: key path → value"),
    "axes": Table({}, optional=True, doc="swept key paths → lists of values"),
    "incidents": SCENARIO_SCHEMA.entries["incidents"].overrides(),   # the scenario's keys, replacing its values
    "store": Table({
        "keep_series": Vector(scalar=True, ge=0.0, doc="trial numbers whose full time series are stored"),
    }, optional=True),
    "isee": ISEE_SCHEMA,
})


@dataclass(frozen=True)
class IseeSettings:
    """The ``[isee]`` table of a campaign (:data:`ISEE_SCHEMA` has the meaning of each field); ``accept``
    is a probability in (0, 1) or None."""

    target_cov: float = 0.1
    batch: int = 20
    min_samples: int = 40
    max_samples: int = 2000
    directions: int = 32
    kappa: float = 0.3
    settle: float = 30.0
    incident: str = "first slip"
    accept: float | None = None
    levels: int = 4
    limit_width: float | None = None


def file_sha256(path: str | Path) -> str:
    """SHA-256 of a file's bytes (hex); "missing" for a file that is not there."""
    h = hashlib.sha256()
    try:
        with open(path, "rb") as fh:
            for block in iter(lambda: fh.read(1 << 20), b""):
                h.update(block)
    except FileNotFoundError:
        return "missing"
    return h.hexdigest()


def trial_seed(master_seed: int, seed_index: int) -> int:
    """Wave seed of the ``seed_index``-th trial of every case: 63 bits of
    ``SeedSequence(master_seed, spawn_key=(seed_index,))``."""
    state = np.random.SeedSequence(master_seed, spawn_key=(seed_index,)).generate_state(2, dtype=np.uint32)
    return int((int(state[0]) << 31) ^ int(state[1]))


@dataclass(frozen=True)
class Case:
    """One point of the sweep: ``values`` maps each axis key path to its value here."""

    index: int
    values: dict

    def label(self) -> str:
        return ", ".join(f"{k}={v:g}" if isinstance(v, (int, float)) else f"{k}={v}" for k, v in self.values.items())


@dataclass(frozen=True)
class TrialSpec:
    """One trial: ``trial`` = case × seeds + seed_index (its row in the store)."""

    trial: int
    case: int
    seed_index: int
    seed: int


@dataclass(frozen=True, eq=False)
class Campaign:
    """A validated campaign (see the module docstring).

    Attributes
    ----------
    name, description, source : str
    scenario_path : Path
        The base scenario file.
    base : Scenario
        The base scenario with ``[set]``, ``duration`` and ``[incidents]`` applied.
    axes : dict[str, list]
    seeds, master_seed : int
    keep_series : tuple of int
    document : dict
        The campaign as parsed, with its changes applied (its digest identifies the campaign in a store).
    text : str
        The campaign as read: the file's text, or — changed (``boatland campaign --set``,
        :func:`boatland.api.campaign`) or given as a dict — the document that runs as TOML, headed by what
        it came from (a store records it).
    access : float or None
        The exposure of every trial to the full sea [s] (``duration``); None: the base scenario's
        duration is the whole run.
    method : {"monte-carlo", "isee"}
    isee : IseeSettings
        Settings of ``method = "isee"`` (defaults when the file has no ``[isee]``).
    """

    name: str
    description: str
    source: str
    scenario_path: Path
    base: Scenario
    axes: dict
    seeds: int
    master_seed: int
    keep_series: tuple
    document: dict
    text: str = ""
    scenario_digest: str = ""      # the base scenario as its file gave it (before [set], [incidents])
    access: float | None = None
    _exposure: dict = field(default_factory=dict, repr=False)   # case → exposure_start (scenario_for)
    method: str = "monte-carlo"
    isee: IseeSettings = IseeSettings()

    def with_method(self, method: str) -> "Campaign":
        """The same campaign estimated by ``method`` (the CLI's ``--method``; part of :meth:`digest`)."""
        import dataclasses

        if method not in METHODS:
            raise SpecError(self.source, [("method", f"must be one of {', '.join(METHODS)}, got {method!r}")])
        if method == "monte-carlo" and "seeds" not in self.document:
            raise SpecError(self.source, [("seeds", "missing: a monte-carlo campaign runs this many trials per case")])
        return dataclasses.replace(self, method=method)

    @property
    def cases(self) -> list[Case]:
        keys = list(self.axes)
        return [Case(i, dict(zip(keys, combo)))
                for i, combo in enumerate(itertools.product(*(self.axes[k] for k in keys)))]

    @property
    def n_trials(self) -> int:
        return len(self.cases) * self.seeds

    def trials(self) -> list[TrialSpec]:
        return [TrialSpec(c * self.seeds + k, c, k, trial_seed(self.master_seed, k))
                for c in range(len(self.cases)) for k in range(self.seeds)]

    def scenario_for(self, spec: TrialSpec) -> Scenario:
        """The trial's scenario: the base with its case's axis values and its seed (and the duration of its
        settling, wave ramp and the access) — validated once, as a file."""
        changes = dict(self.cases[spec.case].values)
        changes["simulation.seed"] = spec.seed
        if self.access is not None:
            if spec.case not in self._exposure:         # the settling and ramp: the same for every seed
                self._exposure[spec.case] = exposure_start(self.base.replace(changes))
            changes["simulation.duration"] = self._exposure[spec.case] + self.access
        return self.base.replace(changes)

    @property
    def from_file(self) -> bool:
        """Read from a campaign file (``source`` is its path), not given as a dict."""
        return not self.source.startswith("<")

    @functools.cached_property
    def identity(self) -> str:
        """SHA-256 of the plan that runs (the document, the base scenario, the method) — without the files
        it reads (:meth:`digest` adds them): a worker's key for the campaign it holds."""
        text = json.dumps(self.document, sort_keys=True, default=str)
        return hashlib.sha256(f"{text}\n{self.base.digest()}\n{self.method}".encode()).hexdigest()

    def input_files(self) -> list[Path]:
        """Every file the campaign reads: the campaign file (when it came from one), the base scenario, and
        the database files and measured-wave records of the base and of every case."""
        files = [Path(self.source)] if self.from_file else []
        files.append(Path(self.scenario_path))
        with warnings.catch_warnings():      # the cases' warnings are the checks' to tell
            warnings.simplefilter("ignore")
            scenarios = [self.base] + [self.base.replace(dict(c.values)) for c in self.cases if c.values]
        for sc in scenarios:
            if sc.vessel.database_path is not None:
                files += database_files(sc.vessel.database_path)
            if sc.sea is not None and sc.sea.kind == "measured":
                files.append(Path(sc.sea.waves.source))
        out: list[Path] = []
        for f in files:
            if f.resolve() not in [o.resolve() for o in out]:
                out.append(f)
        return out

    def input_digests(self) -> dict[str, str]:
        """SHA-256 of each input as it is now, by name: the campaign (its document as it runs), the base
        scenario (as its file gave it, before the campaign's changes: :meth:`Scenario.digest`) and every other file :meth:`input_files` lists — what a
        store records, so that a resume refused for changed inputs names them."""
        out = {f"campaign {self.source}": hashlib.sha256(
                   json.dumps(self.document, sort_keys=True, default=str).encode()).hexdigest(),
               f"scenario {self.scenario_path}": self.scenario_digest or self.base.digest()}
        out.update({str(p): file_sha256(p) for p in self.input_files()[1 + self.from_file:]})
        return out

    def digest(self, digests: dict[str, str] | None = None) -> str:
        """SHA-256 of what a store belongs to: the campaign file's content, the base scenario's, and the
        contents (SHA-256) of every file they read (:meth:`input_files`: database, measured-wave record) —
        a resume never mixes results of changed inputs. ``digests``: :meth:`input_digests` already taken
        (the files are then not read again)."""
        text = json.dumps(self.document, sort_keys=True, default=str)
        shas = digests if digests is not None else self.input_digests()
        files = "\n".join(f"{p.name} {shas[str(p)]}" for p in self.input_files()[1 + self.from_file:])
        method = "" if self.method == "monte-carlo" else f"\nmethod {self.method}"
        return hashlib.sha256(f"{text}\n{self.base.digest()}\n{files}{method}".encode()).hexdigest()


def load_campaign(source: str | Path | dict, *, load_scenario, changes: dict | None = None,
                  changed_by: str = "") -> Campaign:
    """Read and validate a campaign file (or document), with changes; every problem at once, with key paths.

    Parameters
    ----------
    source : str, Path or dict
        A campaign file, or its document as a dict (its ``scenario`` relative to the working directory).
    load_scenario : callable
        ``load_scenario(path) -> Scenario`` for the base scenario (the edge passes its loader, which
        knows the built-in databases).
    changes : dict, optional
        Key path → value (:func:`change_campaign`: ``seeds``, ``access``, ``set.thrust.force``,
        ``axes.sea.Hs``, ``isee.accept``; None removes the key), validated as the file is.
    changed_by : str
        How a refused change is named (``"--set "``: ``--set seeds=0: …``); default the key path.

    Raises
    ------
    SpecError
        Unknown keys (with a "did you mean"), wrong types, empty axes, an axis or ``[set]`` key that
        is not a scenario key or a value the scenario rejects — each named by its key path.
    """
    if isinstance(source, dict):
        doc = json.loads(json.dumps(source))         # a copy of plain values (a dict of dicts and lists)
        path = Path.cwd() / "<dict>"
        label = f"<campaign {doc.get('name', '')!s}>".replace(" >", ">")
        text = None
    else:
        path = Path(source)
        label = str(path)
        text = read_toml_text(path)
        doc = parse_toml(text, path)
    if changes:
        doc = change_campaign(doc, changes, label, changed_by)
    if text is None or changes:
        said = ", ".join(f"{k} = {v!r}" for k, v in (changes or {}).items())
        text = (f"# {label}" + (f", changed: {said}" if said else "") + "\n" + dump_toml(doc))
    try:
        return _campaign(doc, path, label, text, load_scenario)
    except SpecError as exc:
        if not changes:
            raise
        raise SpecError(exc.source, [(_blamed(k, changes, changed_by), m) for k, m in exc.problems]) from None


def change_campaign(doc: dict, changes: dict, source: str = "", changed_by: str = "") -> dict:
    """The campaign document with key-path changes: a top-level key (``seeds``, ``access``, ``master_seed``,
    ``method``, ``name``), a key of a table (``isee.accept``, ``store.keep_series``,
    ``incidents.slip_distance``), or a scenario key path in ``[set]`` or ``[axes]`` (``set.thrust.force``,
    ``axes.sea.Hs``: the rest of the path is the one key). ``None`` removes the key.

    Raises
    ------
    SpecError
        A path into a key that is not a table.
    """
    out = json.loads(json.dumps(doc))
    for key, value in changes.items():
        head, dot, rest = key.partition(".")
        if head in ("set", "axes") and dot:
            parts = [head, rest]
        else:
            parts = key.split(".")
        table = out
        for i, part in enumerate(parts[:-1]):
            table = table.setdefault(part, {})
            if not isinstance(table, dict):
                raise SpecError(source, [(f"{changed_by}{key}", f"{'.'.join(parts[:i + 1])} is not a table")])
        if value is None:
            table.pop(parts[-1], None)
        else:
            table[parts[-1]] = value
    return out


def _blamed(key: str, changes: dict, changed_by: str) -> str:
    """A problem's key path, named as the change that made it (``--set seeds``) where one did."""
    for k in changes:
        if key == k or key.startswith(k + ".") or k.startswith(key + ".") and key:
            return f"{changed_by}{key}" if changed_by else key
    return key


def _campaign(doc: dict, path: Path, source: str, text: str, load_scenario) -> Campaign:
    """The validated campaign of the document ``doc`` (its ``scenario`` relative to ``path``'s folder)."""
    problems = Problems(source)
    raw_set, raw_axes = doc.get("set", {}), doc.get("axes", {})
    data = validate({k: v for k, v in doc.items() if k not in ("set", "axes")}, CAMPAIGN_SCHEMA, problems)
    for name, table in (("set", raw_set), ("axes", raw_axes)):
        if not isinstance(table, dict):
            problems.add(name, f"must be a table of key paths, got {type(table).__name__}")
    method = data.get("method", "monte-carlo")
    if "access" in data and "duration" in data:
        problems.add("duration", "give access only (duration is its older name)")
    if "duration" in data and "access" not in data:
        warnings.warn(f"{source}: duration = {data['duration']:g}: the access (the exposure after the settling and "
                      f"the wave ramp); write access = {data['duration']:g} — a scenario's simulation.duration is "
                      "the whole trial", BoatlandWarning, stacklevel=3)
    if method == "monte-carlo" and "seeds" not in data and not problems.has("seeds"):
        problems.add("seeds", "missing: a monte-carlo campaign runs this many trials (wave seeds) per case")
    isee = _isee_settings(data.get("isee") or {}, problems)
    problems.raise_if_any()
    base_path = (path.parent / data["scenario"]).resolve()
    if not base_path.is_file():
        raise SpecError(source, [("scenario", f"no such file: {base_path}")])
    try:
        scenario = load_scenario(base_path)
    except SpecError as exc:
        raise SpecError(source, [("scenario", f"the base scenario has problems:\n{exc}")]) from None
    changes: dict[str, Any] = dict(raw_set)
    for key, values in (data.get("incidents") or {}).items():
        changes[f"incidents.{key}"] = list(values)   # numbers or tables, as validated; the scenario checks them again
    base = _apply(scenario, changes, problems, "set")
    if base is None:                  # the axes are checked on a valid base
        problems.raise_if_any()
    axes: dict[str, list] = {}
    for key, values in raw_axes.items():
        if not isinstance(values, list) or not values:
            problems.add(f"axes.{key}", "must be a non-empty list of values")
            continue
        if key == "simulation.seed":
            problems.add(f"axes.{key}", "seeds come from 'seeds' and 'master_seed', not from an axis")
            continue
        for v in values:  # every value must make a valid scenario
            if _apply(base, {key: v}, problems, f"axes.{key}") is None:
                break
        axes[key] = list(values)
    problems.raise_if_any()
    keep = tuple(int(v) for v in np.atleast_1d((data.get("store") or {}).get("keep_series", [])))
    n_trials = int(np.prod([len(v) for v in axes.values()])) * int(data.get("seeds", 1))
    bad = [k for k in keep if k >= n_trials]
    if bad:
        raise SpecError(source, [("store.keep_series", f"trial numbers {bad} do not exist (0 … {n_trials - 1})")])
    access = data.get("access", data.get("duration"))      # "duration": its older name
    return Campaign(name=data["name"], description=data.get("description", ""), source=source,
                    scenario_path=base_path, base=base, axes=axes, seeds=int(data.get("seeds", 1)),
                    master_seed=int(data.get("master_seed", 0)), keep_series=keep, document=doc, text=text,
                    scenario_digest=scenario.digest(),
                    access=None if access is None else float(access), method=method, isee=isee)


def _isee_settings(d: dict, problems: Problems) -> IseeSettings:
    """The validated ``[isee]`` table (its problems into ``problems``)."""
    values = {k: v for k, v in d.items() if k in IseeSettings.__dataclass_fields__}
    accept = values.pop("accept", None)
    if accept is not None:
        from boatland.freqdomain.statistics import accept_probability

        try:
            values["accept"] = accept_probability(accept)
        except BoatlandInputError as exc:
            problems.add("isee.accept", str(exc))
    if values.get("min_samples", 40) > values.get("max_samples", 2000):
        problems.add("isee.min_samples", f"must be ≤ isee.max_samples = {values.get('max_samples', 2000)}")
    if values.get("limit_width") is not None and accept is None:
        problems.add("isee.limit_width", "needs isee.accept (the probability whose limiting Hs it narrows)")
    return IseeSettings(**values)


def _apply(scenario: Scenario, changes: dict, problems: Problems, where: str) -> Scenario | None:
    if not changes:
        return scenario
    try:
        return scenario.replace(changes)
    except SpecError as exc:
        for key, msg in exc.problems:  # name the campaign's key: axes.<path>, or set.<path> for [set]
            problems.add(where if where.startswith("axes.") or not key else f"{where}.{key}", msg)
    except (KeyError, ValueError, TypeError, IndexError) as exc:
        problems.add(where, f"{exc}")
    return None


def plan_json(campaign: Campaign) -> str:
    """The plan as JSON for a store's header: name, base scenario, seeds, axes, the cases' values, the
    boatland version."""
    return json.dumps({"name": campaign.name, "scenario": str(campaign.scenario_path), "seeds": campaign.seeds,
                       "master_seed": campaign.master_seed, "axes": campaign.axes,
                       "cases": [c.values for c in campaign.cases], "boatland": __version__}, default=str)
