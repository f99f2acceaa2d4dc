"""``boatland screen``: Wu (2014) slip screening, limiting Hs per (Tp, direction)."""

from __future__ import annotations

import json
from pathlib import Path

from boatland.reproducible import pinned
from boatland.cli.common import (freq_check, freq_directions, freq_load, freq_sea, freq_setup, scenario_argument,
                                  screening_options)
from boatland.cli.guard import Output, integer, positive
from boatland.errors import BoatlandInputError

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
    screen.add_argument("--tp", type=positive("s", 1e4), nargs=3, metavar=("MIN", "MAX", "N"), default=[3.0, 18.0, 16],
                        help="peak periods: N from MIN to MAX [s] (default 3 18 16)")
    screen.add_argument("--directions", type=integer(1, 3600), default=8, metavar="N",
                        help="N relative directions over 360° (default 8: every 45°)")
    screen.add_argument("--shear-sweep", type=positive("s", 1e4), metavar="TP",
                        help="instead of the table over Tp: the limiting Hs at peak period TP against the fender's "
                             "shear stiffness (0.1× … 100× the scenario's, and rigid), per direction; -o draws it")
    screen.add_argument("-o", "--output", type=Path, metavar="PNG", help="write a polar figure of the limiting Hs")
    screen.set_defaults(func=cmd)


@pinned
def cmd(args) -> int:
    import numpy as np

    from boatland.freqdomain import screening_grid

    freq_check(args)
    scenario, db = freq_load(args.scenario, [Output("-o", args.output, "figure")])
    setup = freq_setup(args, scenario, db)
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
                "margins": {m: {"sigma": float(sg), "capacity": float(c)}
                            for m, sg, c in zip(own.names[:-1], own.sigma, own.capacity[:-1])}}
        print_json(out)
    else:
        print(f"{scenario.name}: limiting Hs [m] for P_acc = {table.accept:g} per {args.access:g} s access "
              f"({table.statistics}, {table.method} hinge; μ = {mu:g}, F_b = {thrust / 1e3:g} kN, "
              f"θ_max = {setup.roll_limit_deg:g}°); rows Tp, columns relative direction (180 = head seas)")
        print(table.text())
        modes, counts = np.unique(table.governing[np.isfinite(table.Hs)], return_counts=True)
        print("governing: " + ", ".join(f"{m} {c}" for m, c in zip(modes, counts)))
        if own is not None:
            r = own
            print(f"the scenario's own sea ({', '.join(f'Hs {p.Hs:g} m Tp {p.Tp:g} s' for p in parts)}): incident "
                  f"probability {r.p_access:.3g} per access ({r.p_cycle:.3g} per {r.cycle_period:g} s cycle); "
                  "σ of the margins " + ", ".join(f"{m} {s / 1e3:.3g} kN" for m, s in zip(r.names[:-1], r.sigma))
                  + "; capacities " + ", ".join(f"{a / 1e3:.3g} kN" for a in r.capacity[:-1]))
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
        print(f"{scenario.name}: limiting Hs [m] at Tp = {sw.Tp:g} s for P_acc = {sw.table.accept:g} per "
              f"{args.access:g} s access ({sw.table.statistics}) against the fender's shear stiffness per contact "
              f"(the scenario's: {'rigid' if not np.isfinite(setup.shear_stiffness) else f'{setup.shear_stiffness:.3g} N/m'}"
              "); rows k_t, columns relative direction (180 = head seas)")
        print(sw.text())
    if args.output:
        from boatland.freqdomain.figures import plot_shear_sweep

        mu = setup.mu if args.mu is None else args.mu
        thrust = setup.thrust if args.thrust is None else args.thrust
        plot_shear_sweep(sw, args.output, title=f"{scenario.name}: limiting Hs at Tp {sw.Tp:g} s against the fender's "
                                                f"shear stiffness\n{_sea_shape(scenario)}; push {thrust / 1e3:g} kN, "
                                                f"μ {mu:g}; P = {sw.table.accept:g} per {args.access:g} s access "
                                                f"({sw.table.statistics})")
        if not args.json:
            print(f"wrote {args.output}")
    return 0
