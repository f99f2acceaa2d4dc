"""What several commands share: the default vessel, reading a database or a scenario for a command,
the frequency-domain commands' options and loading."""

from __future__ import annotations

import sys
from pathlib import Path

from boatland.errors import BoatlandInputError

__all__ = ["DEFAULT_VESSEL", "resolve_db", "scenario_argument", "screening_options", "freq_load", "freq_sea",
           "freq_check", "freq_setup"]

DEFAULT_VESSEL = "ctv24"


def resolve_db(spec: str):
    """A database from a path (any supported format) or a built-in vessel name."""
    from boatland.hydro import read_hydro

    path = Path(spec)
    if path.exists():
        return read_hydro(path)[0]
    from boatland.hydro.builtin import BUILTIN, load_builtin

    if spec in BUILTIN:
        return load_builtin(spec)
    raise BoatlandInputError(f"{spec}: no such file, and not a built-in vessel "
                             f"(built-in: {', '.join(sorted(BUILTIN))})")


def scenario_argument(cmd, optional: bool = True) -> None:
    """The positional scenario file of ``rao``, ``screen`` and ``operability``."""
    if optional:
        cmd.add_argument("scenario", nargs="?", type=Path,
                         help="scenario file (TOML; default: scenarios/ctv_landing.toml)")
    else:
        cmd.add_argument("scenario", type=Path, help="scenario file (TOML)")


def screening_options(cmd) -> None:
    """The options ``screen`` and ``operability`` share."""
    cmd.add_argument("--accept", default="best", metavar="P",
                     help="accepted probability of an incident per access, in (0, 1), or a preset of seed 002 "
                          "Table 2.1: best (0.00119), conservative (0.00002), non-conservative (0.02681); "
                          "default best")
    cmd.add_argument("--statistics", choices=("rayleigh", "rice", "vanmarcke"), default="rayleigh",
                     help="Rayleigh peaks, one per Tp (seed 002), or Rice up-crossing rates (optionally with "
                          "Vanmarcke's clumping correction); default rayleigh")
    cmd.add_argument("--method", choices=("improved", "wu"), default="improved",
                     help="hinge model: improved = thrust follows the vessel, fender spring normal (seed 002 "
                          "§3.4); wu = rigid hinge, thrust only a static normal force (§3.2.1); default improved")
    cmd.add_argument("--mu", type=float, help="friction coefficient μ (default fender.mu_s)")
    cmd.add_argument("--thrust", type=float, help="bollard push F_b [N] (default thrust.force)")
    cmd.add_argument("--roll-limit", type=float, metavar="DEG",
                     help="roll limit θ_max [deg] (default the largest incidents.roll_limit_deg, else 10)")
    cmd.add_argument("--access", type=float, default=1800.0, metavar="S",
                     help="duration of one access t_acc [s] (default 1800)")
    cmd.add_argument("--json", action="store_true", help="print the results as JSON")


def freq_load(path):
    """Scenario, database and their landing for the frequency-domain commands (warnings printed)."""
    import warnings

    from boatland.scenario_check import default_scenario_path, load_checked

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scenario, db, _ = load_checked(path or default_scenario_path())
    for w in caught:
        print(f"warning: {w.message}", file=sys.stderr)
    return scenario, db


def freq_sea(scenario):
    """(spectral shape, relative direction [deg] or None) of the scenario's sea."""
    waves = scenario.sea.waves if scenario.sea is not None else None
    parts = getattr(waves, "parts", None)
    if not parts:
        direction = getattr(waves, "direction_deg", None)
        return None, None if direction is None else (direction - scenario.vessel.heading_deg) % 360
    return parts[0], (parts[0].direction_deg - scenario.vessel.heading_deg) % 360


def freq_check(args) -> None:
    """Refuse bad screening options before loading anything."""
    from boatland.freqdomain import accept_probability

    accept_probability(args.accept)
    for name, value in (("--mu", args.mu), ("--thrust", args.thrust), ("--access", args.access),
                        ("--roll-limit", args.roll_limit)):
        if value is not None and not value > 0:
            raise BoatlandInputError(f"{name} {value:g}: must be > 0")


def freq_setup(args, scenario, db):
    from boatland.freqdomain import LandingSetup

    return LandingSetup.from_scenario(scenario, db, roll_limit_deg=args.roll_limit)
