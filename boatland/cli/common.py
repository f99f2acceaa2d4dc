"""What several commands share: the default vessel, reading a database or a scenario for a command,
the frequency-domain commands' options and loading."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from boatland.cli.guard import in_range, positive
from boatland.errors import BoatlandInputError

__all__ = ["DEFAULT_VESSEL", "shipped_or_path", "parse_setting", "set_option", "settings_changes",
           "scenario_argument", "screening_options", "freq_load", "freq_sea",
           "freq_check", "freq_setup", "scenario_inputs", "load_guarded", "with_overrides", "check_fits_in_memory",
           "available_memory", "compile_notice", "kernels_cached", "print_json"]

DEFAULT_VESSEL = "ctv27"


def scenario_inputs(scenario) -> list[Path]:
    """The files a loaded scenario reads: itself, its database file, its measured-wave record."""
    files = []
    if scenario.source and not str(scenario.source).startswith("<"):
        files.append(Path(scenario.source))
    if scenario.vessel.database_path is not None:
        from boatland.vessel.imported import database_files

        files += database_files(scenario.vessel.database_path)
    sea = scenario.sea
    if sea is not None and sea.kind == "measured":
        files.append(Path(sea.waves.source))
    return files


def with_overrides(scenario, changes: dict, flags: dict):
    """``scenario.replace(changes)``; a refused value is named by its flag (``flags``: key path → flag),
    not blamed on the file."""
    from boatland.tomlspec import SpecError

    if not changes:
        return scenario
    try:
        return scenario.replace(changes)
    except SpecError as exc:
        show = lambda v: f"{v:g}" if isinstance(v, float) else str(v)  # noqa: E731
        given = ", ".join(f"{flags[k]}{show(v)}" if flags[k].endswith("=") else f"{flags[k]} {show(v)}"
                          for k, v in changes.items())
        why = "; ".join(f"{k}: {m}" if k else m for k, m in exc.problems)
        raise BoatlandInputError(f"{given}: {why}") from None


def load_guarded(path, outputs, extra_inputs=(), changes=None, flags=None, derived=None):
    """Load a scenario for a command: parse and validate it, apply the flags' ``changes``, check the
    outputs against every file it reads (before anything heavy), then read its database and run every
    check (:func:`boatland.checks.files.check_loaded`). Warnings are returned, not printed.

    ``outputs`` is a list of :class:`boatland.outputs.Output` or a callable ``outputs(scenario)``;
    ``derived``, a callable ``derived(scenario) -> (changes, flags)``: changes that depend on the changed
    scenario (``run --access``: the duration from its settling and wave ramp), applied after ``changes``.
    Returns (scenario, db, warnings, setup): ``setup`` the :class:`boatland.landing.setup.Setup` the checks
    looked at.
    """
    import warnings

    from boatland.outputs import check_outputs
    from boatland.checks.files import check_loaded, default_scenario_path, load

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scenario = load(path or default_scenario_path())
        scenario = with_overrides(scenario, changes or {}, flags or {})
        if derived is not None:
            scenario = with_overrides(scenario, *derived(scenario))
        outs = outputs(scenario) if callable(outputs) else outputs
        check_outputs(outs, [*scenario_inputs(scenario), *extra_inputs])
        db, found = check_loaded(scenario)
    return scenario, db, [str(w.message) for w in caught], found.setup


def available_memory() -> int:
    """Memory [bytes] this process can still use (MemAvailable, else physical memory)."""
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    try:
        return int(os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return 1 << 62


def check_fits_in_memory(setup, *, flag: str = "simulation.duration", copies: int = 1) -> None:
    """Refuse a run whose time series cannot fit in memory (``copies`` trials at once), saying how to
    split it (``setup``: :class:`boatland.landing.setup.Setup`)."""
    from boatland.checks.limits import run_bytes

    scenario, n = setup.scenario, setup.n_steps
    nc = len(scenario.fender.points) if scenario.fender is not None else 0
    need = run_bytes(n, nc) * copies
    have = int(0.8 * available_memory())
    if need > have:
        dt = setup.dt
        fit = max(1.0, (have / copies) / run_bytes(1, nc) * dt)
        raise BoatlandInputError(
            f"{flag} {scenario.simulation.duration:g} s: {n} steps of dt = {dt:g} s need about "
            f"{need / 1e9:.3g} GB{f' for {copies} trials at once' if copies > 1 else ''}, more than the "
            f"{have / 1e9:.3g} GB available; split it into runs of at most {fit:.0f} s (other seeds)"
            + (" or use fewer --workers" if copies > 1 else ""))


def shipped_or_path(kind: str):
    """An argparse ``type`` for a scenario (``kind`` "scenario") or campaign ("campaign") file: a path that
    exists, else the name of one shipped with boatland (:func:`boatland.resources.shipped_file`:
    ``ctv24_landing``, ``demo``, with or without ``.toml``), else the path as given (its loader then says
    the file is missing); a bare name that is neither is refused with the shipped names."""
    import argparse

    from boatland.resources import path_or_shipped, shipped_names

    def parse(text: str) -> Path:
        path = Path(text)
        found = path_or_shipped(text, kind)
        if found is not None:
            return found
        if path.suffix or os.sep in text or "/" in text:   # a file's path: its loader says it is missing
            return path
        raise argparse.ArgumentTypeError(f"{text}: no such file, and not a shipped {kind} "
                                         f"({', '.join(shipped_names(kind))})")

    parse.__name__ = f"{kind} file"
    return parse


def parse_setting(text: str, *, campaign: bool = False) -> tuple[str, object]:
    """``KEY=VALUE`` of ``--set``: a key path as in the scenario's TOML (``sea.Hs``, ``fender.mu_s``) — or, with
    ``campaign``, as in the campaign's (``seeds``, ``set.thrust.force``, ``axes.sea.Hs``) — and a TOML value
    (``0.6``, ``[0.1, 0.3]``, ``true``, ``"ctv24"``; a bare word is a string: ``convolution``)."""
    import argparse
    import re
    import tomllib

    key, eq, raw = text.partition("=")
    key, raw = key.strip(), raw.strip()
    path = r"[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)" + ("*" if campaign else "+")
    if not eq or not re.fullmatch(path, key) or not raw:
        example = "seeds=2, access=600, set.thrust.force=100e3, axes.sea.Hs=[0.5,1.0]" if campaign else \
            "sea.Hs=0.6, fender.mu_s=0.5, radiation.method=convolution"
        raise argparse.ArgumentTypeError(f"{text!r}: expected KEY=VALUE with a key path as in the "
                                         f"{'campaign' if campaign else 'scenario'} file, e.g. {example}")
    try:
        value = tomllib.loads(f"v = {raw}")["v"]
    except tomllib.TOMLDecodeError:
        value = raw
    return key, value


def campaign_setting(text: str) -> tuple[str, object]:
    """``--set KEY=VALUE`` of ``boatland campaign`` (:func:`parse_setting` with a campaign's key paths)."""
    return parse_setting(text, campaign=True)


def set_option(cmd) -> None:
    """``--set KEY=VALUE`` (repeatable): change the scenario as its file would, validated the same way."""
    cmd.add_argument("--set", type=parse_setting, action="append", default=[], metavar="KEY=VALUE", dest="settings",
                     help="change a value of the scenario, with its key path as in the file (repeatable): "
                          "--set sea.Hs=0.6 --set sea.relative_direction_deg=150 --set thrust.force=100e3")


def settings_changes(args, changes: dict | None = None, flags: dict | None = None) -> tuple[dict, dict]:
    """The ``changes`` and ``flags`` of :func:`load_guarded` with the command's ``--set`` values added (a flag
    the command has for the same key wins: it is the more specific)."""
    changes, flags = dict(changes or {}), dict(flags or {})
    for key, value in getattr(args, "settings", None) or []:
        if key not in changes:
            changes[key] = value
            flags[key] = f"--set {key}="
    return changes, flags


def scenario_argument(cmd, optional: bool = True) -> None:
    """The positional scenario of ``rao``, ``screen`` and ``operability``: a file or a shipped name, and
    ``--set`` (:func:`set_option`)."""
    set_option(cmd)
    if optional:
        cmd.add_argument("scenario", nargs="?", type=shipped_or_path("scenario"),
                         help="scenario file (TOML) or the name of a shipped one, e.g. ctv24_landing "
                              "(default: ctv_landing)")
    else:
        cmd.add_argument("scenario", type=shipped_or_path("scenario"),
                         help="scenario file (TOML) or the name of a shipped one, e.g. ctv24_landing")


def screening_options(cmd) -> None:
    """The options ``screen`` and ``operability`` share."""
    cmd.add_argument("--accept", default="best", metavar="P",
                     help="accepted probability of an incident per access, in (0, 1), or a preset of Grøtting "
                          "(2015) Table 2.1: best (0.00119), conservative (0.00002), non-conservative (0.02681); "
                          "default best")
    cmd.add_argument("--statistics", choices=("rayleigh", "rice", "vanmarcke"), default="rice",
                     help="Rice up-crossing rates (default: inside the time domain's 95 %% intervals in boatland "
                          "validate's screening-vs-Monte-Carlo case, where Rayleigh's sit below all six), Rayleigh "
                          "peaks, one per Tp (Grøtting 2015), or Rice with Vanmarcke's clumping correction")
    cmd.add_argument("--method", choices=("improved", "wu"), default="improved",
                     help="hinge model: improved = thrust follows the vessel, fender spring normal (Grøtting 2015 "
                          "§3.4); wu = rigid hinge, thrust only a static normal force (§3.2.1); default improved")
    cmd.add_argument("--mu", type=in_range(0.0, 5.0), help="friction coefficient μ (default fender.mu_s)")
    cmd.add_argument("--thrust", type=positive("N"), help="bollard push F_b [N] (default thrust.force)")
    cmd.add_argument("--roll-limit", type=in_range(0.0, 90.0, unit="°"), metavar="DEG",
                     help="roll limit θ_max [deg] (default the largest incidents.roll_limit_deg, else 10)")
    cmd.add_argument("--access", type=positive("s", 1e7), default=1800.0, metavar="S",
                     help="duration of one access t_acc [s] (default 1800)")
    cmd.add_argument("--json", action="store_true", help="print the results as JSON")


def freq_load(path, outputs=(), args=None):
    """Scenario and database for the frequency-domain commands, ``outputs`` guarded (warnings printed), the
    command's ``--set`` values applied (``args``)."""
    changes, flags = settings_changes(args)
    scenario, db, warns, _ = load_guarded(path, outputs, changes=changes, flags=flags)
    for w in warns:
        print(f"warning: {w}", file=sys.stderr)
    return scenario, db


def freq_sea(scenario):
    """(spectral shape, relative direction [deg] or None) of the scenario's sea."""
    waves = scenario.sea.waves if scenario.sea is not None else None
    parts = getattr(waves, "parts", None)
    if not parts:
        direction = getattr(waves, "direction_deg", None)
        return None, None if direction is None else (direction - scenario.vessel.heading_deg) % 360
    return parts[0], (parts[0].direction_deg - scenario.vessel.heading_deg) % 360


def freq_directions(scenario, db, beta, key: str) -> None:
    """Refuse relative directions the database does not cover, naming the option (``key``) that gave them."""
    import numpy as np

    from boatland.vessel.directions import direction_problem

    problem = direction_problem(db, np.atleast_1d(beta), name=repr(scenario.vessel.database or db.name))
    if problem:
        raise BoatlandInputError(f"{key}: {problem}")


def freq_check(args) -> None:
    """Refuse bad screening options before loading anything."""
    from boatland.freqdomain import accept_probability

    try:
        accept_probability(args.accept)
    except BoatlandInputError as exc:
        raise BoatlandInputError(f"--accept {args.accept}: {exc}") from None


def freq_setup(args, scenario, db):
    from boatland.freqdomain import LandingSetup

    return LandingSetup.from_scenario(scenario, db, roll_limit_deg=args.roll_limit)


def kernels_cached() -> bool:
    """Whether numba's on-disk cache holds the kernels every trial compiles first (the stepper and the fender:
    most of the compile time; a missing or stale index means the next trial compiles them, ~30 s). Unknown
    (numba internals changed): True."""
    try:
        from boatland.contact.fender import decide_modes
        from boatland.integrate.cummins import run_cummins

        return all(bool(k._cache._cache_file._load_index()) for k in (run_cummins, decide_modes))
    except Exception:  # noqa: BLE001 - a notice only: never stop a run over it
        return True


def compile_notice(every: float = 15.0, poll: float = 1.0, give_up: float = 900.0):
    """When the kernels have to be compiled before the first trial: one line on stderr, then "… still
    compiling (N s)" every ``every`` seconds and "compiled in N s" once numba's cache holds them (a daemon
    thread that looks every ``poll`` seconds, for at most ``give_up``). Returns that thread (None: cached)."""
    import threading
    import time

    if kernels_cached():
        return None
    print("compiling kernels (first run only, about a minute) …", file=sys.stderr, flush=True)
    t0 = time.monotonic()

    def tick():
        said = t0
        while time.monotonic() - t0 < give_up:
            time.sleep(poll)
            if kernels_cached():
                print(f"  compiled in {time.monotonic() - t0:.0f} s", file=sys.stderr, flush=True)
                return
            if time.monotonic() - said >= every:
                said = time.monotonic()
                print(f"  … still compiling ({said - t0:.0f} s)", file=sys.stderr, flush=True)

    thread = threading.Thread(target=tick, name="boatland-compile-notice", daemon=True)
    thread.start()
    return thread


def _json_safe(obj):
    """NaN and ±inf → None (JSON has no such numbers), numpy scalars → Python, recursively."""
    import math

    if isinstance(obj, dict):
        return {str(k): _json_safe(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json_safe(v) for v in obj]
    if hasattr(obj, "item") and callable(obj.item) and getattr(obj, "ndim", 1) == 0:
        obj = obj.item()
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    if isinstance(obj, Path):
        return str(obj)
    return obj


def print_json(obj) -> None:
    """Print ``obj`` as indented, strict JSON (non-finite numbers as null; text kept as UTF-8)."""
    import json

    print(json.dumps(_json_safe(obj), indent=2, ensure_ascii=False, allow_nan=False, default=str))
