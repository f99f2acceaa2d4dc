"""``boatland operability``: availability of access over a scatter diagram / hindcast table."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from boatland.errors import BoatlandInputError
from boatland.reproducible import pinned
from boatland.cli.common import (freq_check, freq_directions, freq_load, freq_sea, freq_setup, scenario_argument,
                                  screening_options)

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    op = sub.add_parser(
        "operability", help="availability of access over a wave scatter diagram / hindcast table",
        description="Availability of push-on access (Grøtting 2015, Small Water Plane Area Solutions for Access of Offshore Wind Turbines, NTNU, §4.1): the share of the time whose sea state "
                    "(Hs, Tp, direction) is below the screening's limiting Hs. SCATTER is a CSV with columns Hs, "
                    "Tp, direction_deg (towards, global) or direction_from_deg, occurrence; see "
                    "scenarios/scatter_north_sea.csv.")
    scenario_argument(op, optional=False)
    op.add_argument("scatter", type=Path, help="scatter table (CSV)")
    screening_options(op)
    op.set_defaults(func=cmd)


@pinned
def cmd(args) -> int:
    import warnings

    from boatland.errors import BoatlandWarning
    from boatland.freqdomain import availability, read_scatter

    freq_check(args)
    from boatland.inputs import check_input

    check_input(args.scatter, "scatter table", "text")      # a FIFO or device refused before the model loads
    scenario, db = freq_load(args.scenario, (), args)
    setup = freq_setup(args, scenario, db)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BoatlandWarning)
        try:
            scatter = read_scatter(args.scatter)
        except UnicodeDecodeError as exc:
            raise BoatlandInputError(f"{args.scatter}: not a text CSV file (byte {exc.start} is not UTF-8)") from None
    for w in caught:
        print(f"warning: {w.message}", file=sys.stderr)
    freq_directions(scenario, db, (scatter.direction_deg - setup.heading_deg) % 360.0,
                    f"{args.scatter}: direction (relative to the vessel's heading {setup.heading_deg:g}°)")
    sea, _ = freq_sea(scenario)
    depth = scenario.sea.water_depth if scenario.sea is not None else None
    print(f"screening {scenario.name} over the {scatter.direction_deg.size} sea states of {args.scatter} …",
          file=sys.stderr, flush=True)
    a = availability(db, setup, scatter, accept=args.accept, statistics=args.statistics, method=args.method,
                     sea=sea, water_depth=depth, access_duration=args.access, mu=args.mu, thrust=args.thrust)
    if args.json:
        print(json.dumps({"scenario": scenario.name, "scatter": str(args.scatter), "availability": a.availability,
                          "downtime": a.downtime, "accept": a.accept, "statistics": a.statistics,
                          "method": a.method, "mu": a.mu, "thrust": a.thrust, "sea_states": int(a.workable.size),
                          "workable_sea_states": int(a.workable.sum())}, indent=2))
    else:
        print(f"{scenario.name} over {args.scatter} ({a.workable.size} sea states): availability "
              f"{100 * a.availability:.1f} % (downtime {100 * a.downtime:.1f} %)")
        print(f"  μ = {a.mu:g}, F_b = {a.thrust / 1e3:g} kN (μ·F_b = {a.mu * a.thrust / 1e3:g} kN), "
              f"P_acc = {a.accept:g} per {args.access:g} s access, {a.statistics}, {a.method} hinge")
    return 0
