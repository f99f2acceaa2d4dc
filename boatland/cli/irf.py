"""``boatland irf``: radiation impulse-response functions and state-space fit of a database."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from boatland.cli.common import DEFAULT_VESSEL
from boatland.cli.guard import in_range, integer, positive
from boatland.outputs import Output, check_outputs, same_file
from boatland.errors import BoatlandInputError

__all__ = ["add_parser", "cmd"]


#: Memory lengths T_K [s] tried in turn when --t-max is not given (the scenario's default first).
T_MAX_DEFAULTS = (60.0, 120.0, 240.0, 480.0)


def add_parser(sub) -> None:
    irf = sub.add_parser(
        "irf", help="radiation impulse-response functions and state-space fit of a database",
        description="Compute the radiation IRFs K(t) = (2/π)∫B(ω)cos(ωt)dω of a database, check them "
                    "(B and A reconstructed from K, truncation at T_K, Ogilvie's A∞), fit a stable "
                    "state-space model per DOF pair, print the figures and store everything in the "
                    "database file (BEMIO impulse_response_fun / state_space groups).")
    irf.add_argument("database", nargs="?", default=DEFAULT_VESSEL,
                     help=f"database file or built-in vessel name (default: {DEFAULT_VESSEL})")
    irf.add_argument("--t-max", type=positive("s", 1e5),
                     help=f"memory length T_K [s] (default {T_MAX_DEFAULTS[0]:g}, doubled up to "
                          f"{T_MAX_DEFAULTS[-1]:g} while K has not decayed by it, saying so: ctv27 rings for 75 s)")
    irf.add_argument("--dt", type=positive("s", 1e3), help="time step of K [s] (default min(0.05, π/(3 ω_max)))")
    irf.add_argument("--tail", choices=("auto", "linear", "none", "asymptotic"), default="auto",
                     help="B(ω) above the band: straight to zero over 20%% of ω_max, stop, extrapolate "
                          "∝ ω^-n, or auto (default): linear when the damping has decayed at the top of "
                          "the band, else ω^-n with a note")
    irf.add_argument("--taper", choices=("none", "cosine"), default="none", help="time window on K")
    irf.add_argument("--clean", choices=("clip", "cut", "none"), default="clip",
                     help="negative damping: clip to zero (default), cut the band, or keep")
    irf.add_argument("--band", type=in_range(0.0, None, lo_open=False), nargs=2, metavar=("LO", "HI"),
                     help="frequency band [rad/s] of the round-trip check (default: the whole band)")
    irf.add_argument("--target-r2", type=in_range(0.0, 1.0, hi_open=True),
                     help="state-space fit target R² (default 0.99999: boatland.vessel.radiation.TARGET_R2)")
    irf.add_argument("--max-order", type=integer(2, 200),
                     help="largest state-space order per pair (default 40: boatland.vessel.radiation.MAX_ORDER)")
    irf.add_argument("--no-fit", action="store_true", help="skip the state-space fit")
    irf.add_argument("--plot", type=Path, metavar="PNG", help="write a figure of K(t), B and A")
    irf.add_argument("-o", "--output", type=Path,
                     help="write the database with IRFs to this file instead of updating it in place "
                          "(built-in databases are never modified)")
    irf.add_argument("--no-store", action="store_true", help="do not write anything")
    irf.add_argument("--json", action="store_true", help="print the figures as JSON")
    irf.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.hydro.bemio import write_bemio, write_radiation
    from boatland.hydro.irf_report import irf_summary, irf_table, plot_irf
    from boatland.irf.impulse import IRFNotDecayed, IRFSettings
    from boatland.vessel.radiation import MAX_ORDER, TARGET_R2, default_dt, radiation_memory

    is_file = Path(args.database).exists()
    if args.band and not args.band[0] < args.band[1]:
        raise BoatlandInputError(f"--band {args.band[0]:g} {args.band[1]:g}: need LO < HI [rad/s]")
    if args.output is not None and is_file and same_file(args.output, Path(args.database)):
        raise BoatlandInputError(f"-o {args.output}: is the input database; leave out -o to store the IRFs in it")
    outs = [Output("--plot", args.plot, "figure")]
    if not args.no_store:
        outs.append(Output("-o", args.output))
    check_outputs(outs, [Path(args.database)] if is_file else [])
    if not args.no_store and args.output is None and is_file:     # stored in place: it must be writable
        check_outputs([Output("the database (stored in place)", Path(args.database))])
    from boatland.hydro import load_database

    db = load_database(args.database)
    lengths = T_MAX_DEFAULTS if args.t_max is None else (args.t_max,)
    if args.dt is not None and args.dt >= lengths[0]:
        raise BoatlandInputError(f"--dt {args.dt:g}: must be smaller than --t-max {lengths[0]:g} s")
    dt = args.dt if args.dt is not None else default_dt(db.omega[-1])
    for t_max in lengths:
        try:
            settings = IRFSettings(t_max=t_max, dt=dt, tail=args.tail, taper=args.taper, clean=args.clean,
                                   check_band=tuple(args.band) if args.band else None)
        except BoatlandInputError as exc:
            raise BoatlandInputError(f"--t-max {t_max:g} / --dt {dt:g}: {exc}") from None
        try:
            memory = radiation_memory(db, settings, fit=not args.no_fit,
                                      target_r2=TARGET_R2 if args.target_r2 is None else args.target_r2,
                                      max_order=MAX_ORDER if args.max_order is None else args.max_order)
            break
        except IRFNotDecayed as exc:
            if t_max == lengths[-1]:
                raise
            print(f"note: T_K = {t_max:g} s is too short (K[{exc.pair}] has not decayed by it); trying "
                  f"{2 * t_max:g} s", file=sys.stderr)
    print(json.dumps(irf_summary(memory), indent=2) if args.json else irf_table(memory))
    if args.plot:
        plot_irf(db, memory, args.plot)
        if not args.json:
            print(f"wrote {args.plot}")
    if args.no_store:
        return 0
    target = args.output
    if target is None:
        if not Path(args.database).exists():
            if not args.json:
                print("built-in database: nothing stored (use -o FILE to write a copy with the IRFs)")
            return 0
        target = Path(args.database)
        from boatland.hydro import detect_format

        if detect_format(target) != "bemio":
            raise BoatlandInputError(f"{target}: not a BEMIO database; import it first "
                                     "('boatland hydro import') or give -o FILE")
    else:
        write_bemio(db, target)
    write_radiation(target, memory, db.rho)
    if not args.json:
        print(f"stored IRFs{'' if args.no_fit else ' and state-space fit'} in {target}")
    return 0
