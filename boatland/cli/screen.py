"""``boatland screen``: Wu (2014) slip screening, limiting Hs per (Tp, direction)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from boatland.cli.common import (
    freq_check,
    freq_directions,
    freq_load,
    freq_sea,
    freq_setup,
    scenario_argument,
    screening_options,
    settings_changes,
)
from boatland.cli.guard import in_range, integer, positive
from boatland.outputs import Output
from boatland.errors import BoatlandInputError
from boatland.reproducible import pinned

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    screen = sub.add_parser(
        "screen", help="Wu (2014) slip screening: limiting Hs per (Tp, direction)",
        description="Frequency-domain slip screening (Grøtting 2015, Small Water Plane Area Solutions for Access of "
                    "Offshore Wind Turbines, NTNU, §3.2.1, §3.4; after Wu 2014): slip-margin transfer functions of "
                    "the fender-hinged vessel for downward, upward, left and right slip and roll, their statistics "
                    "in the scenario's spectral shape, and the largest Hs whose incident probability per access is "
                    "accepted, per peak period and relative wave direction. Prints the table and the incident "
                    "probability in the scenario's own sea (both also with --json); -o writes a polar figure (bow up: "
                    "180° head seas at the top, waves from starboard on the right, as in 'boatland report').")
    scenario_argument(screen)
    screening_options(screen)
    screen.add_argument("--tp", type=positive("s", 1e4), nargs="+", metavar="S",
                        help="peak periods: one period TP, or MIN MAX N: N from MIN to MAX [s] (default 3 18 16); with "
                             "--sensitivity one period TP (default the scenario's Tp, else 7)")
    screen.add_argument("--directions", type=integer(1, 3600), metavar="N",
                        help="N relative directions over 360° (default 8: every 45°; with --sensitivity head 180°, "
                             "bow-quartering 135° and beam 90°)")
    screen.add_argument("--shear-sweep", type=positive("s", 1e4), metavar="TP",
                        help="instead of the table over Tp: the limiting Hs at peak period TP against the fender's "
                             "shear stiffness (0.1× … 100× the scenario's, and rigid), per direction; -o draws it")
    screen.add_argument("--current-sweep", type=positive("s", 1e4), nargs="?", const=0.0, metavar="TP",
                        help="instead of the table over Tp: the limiting Hs at peak period TP (default the scenario's "
                             "Tp, else 7) against the tidal current's speed (--speeds) and its direction relative to "
                             "the vessel (every 45°), the waves at the scenario's relative direction; prints which "
                             "side to land with the current on; -o draws it")
    screen.add_argument("--speeds", type=in_range(0.0, 5.0, lo_open=False, unit=" m/s"), nargs="+", metavar="U",
                        help="with --current-sweep: current speeds [m/s] (default 0 0.25 0.5 0.75 1 1.5)")
    screen.add_argument("--sensitivity", action="store_true",
                        help="instead of the table over Tp: what moves the limit — the limiting Hs at one Tp with one "
                             "input at a time at the ends of a sourced range (accepted risk, push, μ_s, the fender's "
                             "shear stiffness and height) and all of them at once, per heading; -o draws tornadoes")
    screen.add_argument("--factors", metavar="LIST",
                        help="with --sensitivity: which inputs to vary, comma-separated, of "
                             "accept,thrust,mu,shear,height (or risk, push, friction, k_t, z; default all)")
    screen.add_argument("--limits", type=Path, metavar="STORE",
                        help="with --sensitivity: a finished ISEE campaign store whose limiting Hs per case (its "
                             "incident definition, the time domain) joins the table as a row, at the same Tp and "
                             "relative headings")
    screen.add_argument("-o", "--output", type=Path, metavar="PNG",
                        help="write a figure: the polar map of the limiting Hs (with --shear-sweep its curves, with "
                             "--sensitivity its tornadoes)")
    screen.set_defaults(func=cmd)


@pinned
def cmd(args) -> int:
    import numpy as np

    from boatland.freqdomain import screening_grid
    from boatland.freqdomain.statistics import one_in, risk_in_words

    freq_check(args)
    if args.speeds is not None and args.current_sweep is None:
        raise BoatlandInputError("--speeds: only with --current-sweep")
    if args.current_sweep is not None:
        if args.sensitivity or args.shear_sweep is not None:
            raise BoatlandInputError("--current-sweep: not with --sensitivity or --shear-sweep (one sweep at a time)")
        return _current_sweep(args)
    if args.sensitivity:
        return _sensitivity(args)
    for flag, value in (("--factors", args.factors), ("--limits", args.limits)):
        if value is not None:
            raise BoatlandInputError(f"{flag}: only with --sensitivity")
    scenario, db = freq_load(args.scenario, [Output("-o", args.output, "figure")], args)
    setup = freq_setup(args, scenario, db)
    if args.tp is None:
        args.tp = [3.0, 18.0, 16]
    if args.directions is None:
        args.directions = 8
    if len(args.tp) == 1:                        # one period: --tp 7 is --tp 7 7 1
        args.tp = [args.tp[0], args.tp[0], 1]
    if len(args.tp) != 3:
        raise BoatlandInputError(f"--tp {' '.join(f'{t:g}' for t in args.tp)}: give one period TP, or MIN MAX N")
    lo, hi, n = args.tp
    if not (0 < lo <= hi and n >= 1 and n == int(n)):
        raise BoatlandInputError(f"--tp {lo:g} {hi:g} {n:g}: need 0 < MIN ≤ MAX and a whole N ≥ 1")
    if args.directions < 1:
        raise BoatlandInputError(f"--directions {args.directions}: need N ≥ 1")
    Tp = np.linspace(lo, hi, int(n))
    beta = np.arange(args.directions) * 360.0 / args.directions
    freq_directions(scenario, db, beta, f"--directions {args.directions} (every {360.0 / args.directions:g}°)")
    sea, _ = freq_sea(scenario)
    depth = scenario.sea.water_depth if scenario.sea is not None else None
    if args.shear_sweep is not None:
        return _shear_sweep(args, scenario, db, setup, beta, sea, depth)
    print(f"screening {scenario.name}: {len(Tp)} peak periods × {len(beta)} headings …", file=sys.stderr, flush=True)
    table = screening_grid(db, setup, Tp, beta, accept=args.accept, statistics=args.statistics, method=args.method,
                           sea=sea, water_depth=depth, access_duration=args.access, mu=args.mu, thrust=args.thrust)
    mu = setup.mu if args.mu is None else args.mu
    thrust = setup.thrust if args.thrust is None else args.thrust
    parts = getattr(scenario.sea.waves, "parts", None) if scenario.sea is not None else None
    own = None
    if parts:        # the incident probability in the scenario's own sea, in the text and in --json
        from boatland.freqdomain import sea_response

        own = sea_response(db, setup.replace(mu=mu, thrust=thrust), parts, water_depth=depth,
                           statistics=table.statistics, method=table.method, access_duration=args.access)
    if args.json:
        from boatland.cli.common import print_json

        out = {"scenario": scenario.name, "database": db.name, "accept": table.accept,
               "statistics": table.statistics, "method": table.method, "mu": mu, "thrust": thrust,
               "roll_limit_deg": setup.roll_limit_deg, "access_duration": args.access, "Tp": table.Tp.tolist(),
               "beta_deg": table.beta_deg.tolist(),
               "Hs_limit": [[None if not np.isfinite(h) else float(h) for h in row] for row in table.Hs],
               "governing": table.governing.tolist(), "captured_variance": table.captured.tolist()}
        if own is not None:
            out["own_sea"] = {
                "parts": [{"kind": p.kind, "Hs": p.Hs, "Tp": p.Tp,
                           "relative_direction_deg": (p.direction_deg - scenario.vessel.heading_deg) % 360}
                          for p in parts],
                "p_access": own.p_access, "p_cycle": own.p_cycle, "cycle_period": own.cycle_period,
                "margins": {m: {"sigma": float(sg), "capacity": float(c),
                                **({} if own.tails is None else {"skewness": float(t[0]),
                                                                 "excess_kurtosis": float(t[1])})}
                            for m, sg, c, t in zip(own.names[:-1], own.sigma, own.capacity[:-1],
                                                   own.tails if own.tails is not None else own.sigma)}}
        print_json(out)
    else:
        print(f"{scenario.name}: limiting Hs [m] of a slip onset (or roll beyond {setup.roll_limit_deg:g}°) at the "
              f"accepted {risk_in_words(table.accept, args.access)} ({table.statistics}, {table.method} hinge; "
              f"μ = {mu:g}, F_b = {thrust / 1e3:g} kN); rows Tp, columns relative direction (180 = head seas)")
        print(table.text())
        modes, counts = np.unique(table.governing[np.isfinite(table.Hs)], return_counts=True)
        print("governing: " + ", ".join(f"{m} {c}" for m, c in zip(modes, counts)))
        if own is not None:
            r = own
            print(f"the scenario's own sea ({', '.join(f'Hs {p.Hs:g} m Tp {p.Tp:g} s' for p in parts)}): incident "
                  f"probability {r.p_access:.3g} per access — {one_in(r.p_access)}, "
                  f"{'above' if r.p_access > table.accept else 'within'} the accepted {one_in(table.accept)} "
                  f"({r.p_cycle:.3g} per {r.cycle_period:g} s cycle); "
                  "σ of the margins " + ", ".join(f"{m} {s / 1e3:.3g} kN" for m, s in zip(r.names[:-1], r.sigma))
                  + "; capacities " + ", ".join(f"{a / 1e3:.3g} kN" for a in r.capacity[:-1]))
            if r.tails is not None:
                g = int(np.argmax(r.per_mode[:-1]))
                print(f"the current's drag skews the margins (second order in the waves; the slip rates count it): "
                      f"the governing {r.names[g]} by "
                      + (f"{r.tails[g, 0]:+.3f}" if abs(r.tails[g, 0]) >= 5e-4 else "less than 0.001")
                      + " (boatland.freqdomain.quadratic_drag)")
        if table.captured.min() < 0.99:
            print(f"note: the database's band holds {100 * table.captured.min():.1f} % of the wave variance at "
                  f"Tp = {table.Tp[np.argmin(table.captured)]:g} s (the rest is left out)")
    if args.output:
        from boatland.freqdomain.figures import plot_limits

        plot_limits(table, args.output, title=f"{scenario.name}: {db.name}, {_sea_shape(scenario)}; push "
                                              f"{thrust / 1e3:g} kN, μ {mu:g}, roll limit {setup.roll_limit_deg:g}°, "
                                              f"{args.access:g} s access")
        if not args.json:
            print(f"wrote {args.output}")
    return 0


def _sea_shape(scenario) -> str:
    """The spectral shape the screening scales ("JONSWAP γ 3.3"), or the default."""
    sea, _ = freq_sea(scenario)
    if sea is None:
        return "JONSWAP spectra"
    return sea.shape.label + (f" γ {sea.gamma:g}" if sea.gamma is not None else "") + " spectra"


def _shear_sweep(args, scenario, db, setup, beta, sea, depth) -> int:
    """``screen --shear-sweep TP``: limiting Hs against the fender's shear stiffness."""
    import numpy as np

    from boatland.freqdomain.screening import shear_sweep
    from boatland.freqdomain.statistics import risk_in_words

    sw = shear_sweep(db, setup, args.shear_sweep, beta, accept=args.accept, statistics=args.statistics,
                     method=args.method, sea=sea, water_depth=depth, access_duration=args.access, mu=args.mu,
                     thrust=args.thrust)
    if args.json:
        print(json.dumps({"scenario": scenario.name, "database": db.name, "Tp": sw.Tp, "accept": sw.table.accept,
                          "statistics": sw.table.statistics, "beta_deg": sw.beta_deg.tolist(),
                          "shear_stiffness": [None if not np.isfinite(k) else float(k) for k in sw.k_t],
                          "Hs_limit": [[None if not np.isfinite(h) else float(h) for h in row] for row in sw.Hs],
                          "governing": sw.governing.tolist()}, indent=2))
    else:
        print(f"{scenario.name}: limiting Hs [m] at Tp = {sw.Tp:g} s at the accepted "
              f"{risk_in_words(sw.table.accept, args.access)} ({sw.table.statistics}) against the fender's shear stiffness per contact "
              f"(the scenario's: {'rigid' if not np.isfinite(setup.shear_stiffness) else f'{setup.shear_stiffness:.3g} N/m'}"
              "); rows k_t, columns relative direction (180 = head seas)")
        print(sw.text())
    if args.output:
        from boatland.freqdomain.figures import plot_shear_sweep

        mu = setup.mu if args.mu is None else args.mu
        thrust = setup.thrust if args.thrust is None else args.thrust
        plot_shear_sweep(sw, args.output, title=f"{scenario.name}: {db.name}, limiting Hs at Tp {sw.Tp:g} s against the fender's "
                                                f"shear stiffness\n{_sea_shape(scenario)}; push {thrust / 1e3:g} kN, "
                                                f"μ {mu:g}; P = {sw.table.accept:g} per {args.access:g} s access "
                                                f"({sw.table.statistics})")
        if not args.json:
            print(f"wrote {args.output}")
    return 0


def _current_sweep(args) -> int:
    """``screen --current-sweep [TP]``: the limiting Hs against the current's speed and relative direction."""
    import sys

    from boatland.freqdomain.currents import DEFAULT_SPEEDS, current_sweep, plot_current_sweep
    from boatland.freqdomain.statistics import risk_in_words

    scenario, db = freq_load(args.scenario, [Output("-o", args.output, "figure")], args)
    if args.tp is not None or args.directions is not None:
        raise BoatlandInputError("--current-sweep takes its period as its own value (--current-sweep TP) and sweeps "
                                 "the current's directions: not with --tp or --directions")
    sea, _ = freq_sea(scenario)
    Tp = args.current_sweep or (sea.Tp if sea is not None and sea.Tp else 7.0)
    depth = scenario.sea.water_depth if scenario.sea is not None else None
    speeds = tuple(args.speeds) if args.speeds else DEFAULT_SPEEDS
    show = not args.json and sys.stderr.isatty()

    def progress(done, total):
        if show:
            print(f"\rscreening {done}/{total} currents", end="" if done < total else "\n", file=sys.stderr, flush=True)

    sw = current_sweep(db, scenario, Tp, speeds=speeds, accept=args.accept, statistics=args.statistics, sea=sea,
                       water_depth=depth, access_duration=args.access, roll_limit_deg=args.roll_limit,
                       progress=progress)
    if args.json:
        from boatland.cli.common import print_json

        print_json({"scenario": scenario.name, "database": db.name, **sw.as_dict()})
    else:
        print(f"{scenario.name}: limiting Hs [m] at Tp = {sw.Tp:g} s, waves at {sw.wave_deg:g}° relative, at the "
              f"accepted {risk_in_words(sw.accept, args.access)} ({sw.statistics}) against the current; rows speed, "
              "columns the direction it flows towards relative to the vessel (180 = onto the bow, 90 = from "
              "starboard)")
        print(sw.text())
        print("which side to land with the current on (the waves held at the same relative direction):")
        for line in sw.advice():
            print("  " + line)
    if args.output:
        plot_current_sweep(sw, args.output, title=f"{scenario.name}: {db.name}, limiting Hs at Tp {sw.Tp:g} s, waves "
                                                  f"at {sw.wave_deg:g}° against the current\n{_sea_shape(scenario)}; "
                                                  f"P = {sw.accept:g} per {args.access:g} s access ({sw.statistics})")
        if not args.json:
            print(f"wrote {args.output}")
    return 0


def _sensitivity(args) -> int:
    """``screen --sensitivity``: the limiting Hs at one Tp, one input at a time
    (:func:`boatland.freqdomain.sensitivity.sensitivity`); text, --json, -o tornadoes."""
    import sys
    import time

    import numpy as np

    from boatland.cli.common import load_guarded, print_json
    from boatland.freqdomain.sensitivity import (
        DEFAULT_HEADINGS,
        factors_named,
        plot_tornado,
        sensitivity,
    )
    from boatland.freqdomain.statistics import access_text, risk_in_words

    if args.shear_sweep is not None:
        raise BoatlandInputError("--sensitivity and --shear-sweep: choose one")
    factors = None
    if args.factors is not None:
        factors = [f for f in args.factors.split(",") if f.strip()]
        try:
            factors_named(factors)
        except BoatlandInputError as exc:
            raise BoatlandInputError(f"--factors {args.factors}: {exc}") from None
    tp = args.tp
    if tp is not None and not (len(tp) == 1 or (len(tp) == 3 and tp[0] == tp[1] and tp[2] == 1)):
        raise BoatlandInputError(f"--tp {' '.join(f'{t:g}' for t in tp)}: --sensitivity takes one peak period "
                                 "(--tp TP)")
    changes, flags = settings_changes(args)
    scenario, db, warns, _ = load_guarded(args.scenario, [Output("-o", args.output, "figure")],
                                          extra_inputs=[args.limits] if args.limits else (), changes=changes,
                                          flags=flags)
    for w in warns:
        print(f"warning: {w}", file=sys.stderr)
    setup = freq_setup(args, scenario, db)
    sea, _ = freq_sea(scenario)
    Tp = float(tp[0]) if tp is not None else (float(sea.Tp) if sea is not None else 7.0)
    if args.directions is None:
        beta, key = np.array(DEFAULT_HEADINGS), "headings 180°, 135°, 90°"
    else:
        beta = np.arange(args.directions) * 360.0 / args.directions
        key = f"--directions {args.directions} (every {360.0 / args.directions:g}°)"
    freq_directions(scenario, db, beta, key)
    extra = [_store_limits(args.limits, Tp, beta, args.accept, setup, args)] if args.limits else []
    start, shown = time.monotonic(), [0.0]

    def progress(done, total):
        t = time.monotonic() - start
        if t > 2.0 and t - shown[0] > 2.0 and done < total:
            shown[0] = t
            print(f"sensitivity: {done} of {total} screenings ({t:.0f} s)", file=sys.stderr, flush=True)

    result = sensitivity(db, setup, Tp, beta, factors=factors, accept=args.accept, statistics=args.statistics,
                         method=args.method, sea=sea, water_depth=scenario.sea.water_depth if scenario.sea else None,
                         access_duration=args.access, mu=args.mu, thrust=args.thrust, extra_rows=extra,
                         progress=progress)
    for note in result.notes:
        print(f"warning: {note}", file=sys.stderr)
    if args.json:
        print_json({"scenario": scenario.name, "database": db.name, **result.as_dict()})
    else:
        print(f"{scenario.name}: limiting Hs [m] at Tp {Tp:g} s, one input at a time at the ends of its range "
              f"(base: {result.base_text}; per {access_text(args.access)}, {result.statistics}, {result.method} hinge); "
              "per heading: the limit at the low – high end (× the base)")
        print(f"accepted at the base: {risk_in_words(result.accept, args.access)}")
        print(result.text())
    if args.output:
        plot_tornado(result, args.output, title=f"{scenario.name} ({db.name}, {_sea_shape(scenario)}): limiting Hs "
                                                f"at Tp {Tp:g} s, one input at a time")
        if not args.json:
            print(f"wrote {args.output}")
    return 0


def _store_limits(path, Tp, beta, accept, setup, args):
    """The time domain's limiting Hs per heading at ``Tp`` from an ISEE campaign store
    (:func:`boatland.campaign.report.isee_limits_at`) as an :class:`~boatland.freqdomain.sensitivity.ExtraLimit`,
    refused when its accepted risk is not the screening's, with a warning when its push or μ_s are not."""
    import math
    import sys

    from boatland.campaign.report import isee_limits_at, read_store
    from boatland.freqdomain import accept_probability

    try:
        data = read_store(path)
    except BoatlandInputError as exc:
        raise BoatlandInputError(f"--limits {exc}") from None
    lim = data.get("isee_limits")
    if lim is None or lim.size == 0:
        raise BoatlandInputError(f"--limits {path}: no limiting Hs in this store (an ISEE campaign with an accept "
                                 "in its [isee] table writes them)")
    p = accept_probability(accept)
    if not math.isclose(float(lim["accept"][0]), p, rel_tol=1e-6):
        raise BoatlandInputError(f"--limits {path}: its limits are at P = {lim['accept'][0]:g} per access, the "
                                 f"screening's at {p:g}; give --accept {lim['accept'][0]:g}")
    extra = isee_limits_at(data, Tp, beta, path)
    if extra is None:
        raise BoatlandInputError(f"--limits {path}: no case at Tp {Tp:g} s and relative heading "
                                 f"{', '.join(f'{x:g}°' for x in beta)} in its isee_limits")
    fixed = json.loads(data["header"].get("inputs") or "{}")
    push, mu = args.thrust or setup.thrust, args.mu or setup.mu
    if fixed.get("thrust") not in (None, push) or fixed.get("mu_s") not in (None, mu):
        print(f"warning: --limits {path}: its campaign ran push {fixed.get('thrust', 0) / 1e3:g} kN, μ_s "
              f"{fixed.get('mu_s')}, the screening's base {push / 1e3:g} kN, μ_s {mu:g}", file=sys.stderr)
    return extra