"""``boatland operability``: access of one or more vessels at a turbine's landings over a site's weather — a
scatter diagram or a hindcast (:mod:`boatland.site`)."""

from __future__ import annotations

import sys
from pathlib import Path

from boatland.cli.common import freq_check, print_json, screening_options, set_option, shipped_or_path
from boatland.cli.guard import in_range, positive
from boatland.errors import BoatlandInputError
from boatland.outputs import Output
from boatland.reproducible import pinned

__all__ = ["DEFAULT_WINDOW_HOURS", "STORE_SUFFIXES", "add_parser", "cmd"]

#: A SCENARIO argument with one of these suffixes is a campaign store (its time-domain limits).
STORE_SUFFIXES = (".h5", ".hdf5")

#: The access window of a hindcast when none is asked for [h]. An assumption: a short visit — the transfer
#: out, about three hours of work, the transfer back (say so, or give --window).
DEFAULT_WINDOW_HOURS = 4.0


def add_parser(sub) -> None:
    op = sub.add_parser(
        "operability", help="access at a turbine's landings over a scatter diagram or a hindcast",
        description="Availability of push-on access (Grøtting 2015, Small Water Plane Area Solutions for Access of "
                    "Offshore Wind Turbines, NTNU, §4.1) at each of a turbine's boat landings and with the best "
                    "landing chosen per sea state: the share of the time whose sea state is below the screening's "
                    "limit at its own peak period and direction (wind sea + swell as two spectra when the weather "
                    "has the partitions). A hindcast adds availability per month and year, and weather windows: the "
                    "probability that an access window (transfer out, work, transfer back) is workable throughout, "
                    "and the waiting time for one. Several scenarios (vessels, push settings) are compared side by "
                    "side over the same weather. Directions are compass degrees from true North: the waves come "
                    "FROM direction_from_deg; a landing's bearing is the direction from the tower's axis to it "
                    "(the vessel heads the opposite way). WEATHER: CSV (time or occurrence, Hs, Tp, "
                    "direction_from_deg; optionally wind-sea and swell partitions, current_speed and "
                    "current_direction_from_deg, wind_speed (1-hour mean at 10 m) and wind_direction_from_deg — each "
                    "sea state is then judged in its own current and wind; see scenarios/example_hindcast.csv) or "
                    "netCDF-4.")
    set_option(op)
    op.add_argument("scenarios", nargs="+", type=shipped_or_path("scenario"), metavar="SCENARIO",
                    help="scenario file (TOML) or the name of a shipped one, e.g. ctv_landing, judged by the screening "
                         "(a slip onset) — or the store (.h5) of a rare-event campaign with an accept (method = "
                         "\"isee\"), judged by its time-domain limits for its incident, e.g. a slide; several: side "
                         "by side")
    op.add_argument("weather", type=Path, metavar="WEATHER",
                    help="scatter diagram or hindcast (CSV or netCDF), e.g. scenarios/example_hindcast.csv")
    op.add_argument("--landing", type=in_range(0.0, 360.0, lo_open=False, hi_open=True, unit="°"), action="append",
                    metavar="DEG",
                    dest="landings",
                    help="compass bearing of a boat landing from the tower's axis [deg], repeatable (a turbine with "
                         "two or three landings); default the first scenario's landing (its vessel heading + 180°)")
    op.add_argument("--window", type=positive("h", 24 * 366), metavar="HOURS",
                    help=f"access window of a hindcast [h]: transfer out, work, transfer back, workable throughout "
                         f"(default {DEFAULT_WINDOW_HOURS:g} h, an assumption: a short visit)")
    op.add_argument("--one-spectrum", action="store_true",
                    help="judge every sea state as one spectrum of its total Hs, Tp and direction even when the "
                         "weather has wind-sea and swell partitions (Grøtting 2015 found +31 %% availability with two)")
    op.add_argument("-o", "--output", type=Path, metavar="FIGURE",
                    help="write the figure (availability per month, windows; PNG, SVG or PDF)")
    screening_options(op)
    op.set_defaults(func=cmd)


@pinned
def cmd(args) -> int:
    import warnings

    import numpy as np

    from boatland.cli.common import load_guarded, settings_changes
    from boatland.errors import BoatlandWarning
    from boatland.freqdomain import LandingSetup
    from boatland.inputs import check_input
    from boatland.outputs import check_outputs
    from boatland.site import (LimitsTable, flow_setups, landing_bearing, operability, read_weather,
                               relative_direction, side_by_side, table_operability)
    from boatland.vessel.directions import direction_problem

    freq_check(args)
    check_input(args.weather, "weather file", "text")       # a FIFO or device refused before the models load
    names = [str(s) for s in args.scenarios]
    if len(set(names)) != len(names):
        raise BoatlandInputError(f"scenario {next(n for n in names if names.count(n) > 1)} is given twice")
    check_outputs([Output("-o", args.output, "figure")], [args.weather, *args.scenarios])
    with warnings.catch_warnings(record=True) as caught:            # the weather before the models: cheap
        warnings.simplefilter("always", BoatlandWarning)
        weather = read_weather(args.weather)
    for w in caught:
        print(f"warning: {w.message}", file=sys.stderr)
    changes, flags = settings_changes(args)
    loaded = []                 # (scenario, db) of a scenario, or (None, LimitsTable) of a limits store
    for path in args.scenarios:
        if Path(path).suffix.lower() in STORE_SUFFIXES:
            table = LimitsTable.read(path)
            if args.mu is not None or args.thrust is not None:
                print(f"warning: --mu/--thrust do not apply to {path}: its limits are for the push "
                      f"{(table.thrust or 0) / 1e3:g} kN and μ_s {table.mu} its campaign ran", file=sys.stderr)
            loaded.append((None, table))
            continue
        scenario, db, warns, _ = load_guarded(path, [Output("-o", args.output, "figure")], [args.weather],
                                              changes=changes, flags=flags)
        for w in warns:
            print(f"warning: {w}", file=sys.stderr)
        loaded.append((scenario, db))
    if not args.landings and all(sc is None for sc, _ in loaded):
        raise BoatlandInputError("--landing: give the landings' compass bearings (a limits store does not say where "
                                 "its landing is on the tower)")
    first = next(sc for sc, _ in loaded if sc is not None) if not args.landings else None
    landings = np.array(args.landings if args.landings else [float(landing_bearing(first.vessel.heading_deg))],
                        dtype=float)
    if len(set(np.round(landings, 6))) != landings.size:
        raise BoatlandInputError("--landing: the same bearing is given twice")
    window = args.window if args.window is not None else DEFAULT_WINDOW_HOURS
    in_flows = {}                   # each scenario's landing in the weather's flows (boatland.site.flows)
    if weather.current is not None or weather.wind is not None:
        # a scenario that cannot take the weather's flows (no hull or topsides to measure their areas on) says so
        # now, before any vessel's work
        from boatland.landing.law import NoStaticEquilibrium

        for scenario, db in loaded:
            if scenario is not None:
                in_flows[id(scenario)] = flow_setups(scenario, db, roll_limit_deg=args.roll_limit)
                try:
                    in_flows[id(scenario)](None if weather.current is None else (0.5, 90.0),
                                            None if weather.wind is None else (5.0, 90.0))
                except NoStaticEquilibrium:       # physics, not a bad input: judged node by node below
                    pass
    froms = [weather.from_deg] + ([] if args.one_spectrum else [d[h > 0] for h, _, d in weather.parts.values()])
    results = []
    for scenario, db in loaded:
        if scenario is None:
            print(f"judging {weather.describe()} by {db.describe()} at {landings.size} landing(s) …",
                  file=sys.stderr, flush=True)
            results.append(table_operability(db, weather, landings, window_hours=window))
            continue
        beta = relative_direction(np.concatenate(froms)[:, None], landings[None, :]).ravel()
        problem = direction_problem(db, np.unique(np.round(beta, 6)), name=repr(scenario.vessel.database or db.name))
        if problem:
            raise BoatlandInputError(f"{args.weather}: directions at the landings {', '.join(f'{b:g}°' for b in landings)}: "
                                     f"{problem}")
        setup = LandingSetup.from_scenario(scenario, db, roll_limit_deg=args.roll_limit)
        waves = scenario.sea.waves if scenario.sea is not None else None
        parts = getattr(waves, "parts", None)
        flows = " and ".join(w for w in ("current", "wind") if getattr(weather, w) is not None)
        print(f"screening {scenario.name} over {weather.describe()} at {landings.size} landing(s)"
              + (f" in each sea state's own {flows}" if flows else "") + " …", file=sys.stderr, flush=True)
        extra = {}
        if flows:
            extra = {"flow_setup": in_flows[id(scenario)],
                     "progress": _progress(scenario.name)}
            for what in ("current", "wind"):
                if getattr(weather, what) is not None and getattr(scenario, what) is not None:
                    print(f"note: {scenario.name}'s own [{what}] speed and direction are replaced by {args.weather}'s "
                          "(its drag coefficients kept)", file=sys.stderr)
        results.append(operability(
            db, setup, weather, landings, name=scenario.name, window_hours=window, **extra,
            accept=args.accept, statistics=args.statistics, method=args.method, sea=parts[0] if parts else None,
            water_depth=scenario.sea.water_depth if scenario.sea is not None else None,
            access_duration=args.access, mu=args.mu, thrust=args.thrust,
            spectra="one" if args.one_spectrum else "auto"))
    if args.output is not None:
        from boatland.site.figures import plot_operability

        who = ", ".join(f"{sc.name} ({sc.vessel.database})" if sc is not None else f"{t.name} ({t.vessel})"
                        for sc, t in loaded)
        lim = results[0].limits
        plot_operability(results, args.output, title=(
            f"{who}: access at the landings {', '.join(f'{b:g}°' for b in landings)} over {Path(weather.source).name}"
            f"\nP_acc {lim.accept:g} per {lim.access_duration:g} s access; push and μ as in each"))
    if args.json:
        print_json({"weather": weather.source, "landings_deg": landings.tolist(),
                    "results": [r.as_dict() for r in results]})
        return 0
    for r in results:
        print(r.text())
        print()
    if len(results) > 1:
        print(side_by_side(results))
    if args.output is not None:
        print(f"figure: {args.output}")
    return 0


def _progress(name: str):
    """``progress(done, total)`` of the flows' nodes and the limits' blocks: a line on stderr about every 10 %."""
    import time

    t0 = time.monotonic()
    said = [0]

    def tick(done: int, total: int) -> None:
        if done == total or done - said[0] >= max(1, total // 10):
            said[0] = done
            print(f"  {name}: {done}/{total} (the flows' nodes, then the limits) ({time.monotonic() - t0:.0f} s)",
                  file=sys.stderr, flush=True)
    return tick
