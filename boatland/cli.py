"""The ``boatland`` command (also ``python -m boatland``).

User mistakes (:class:`boatland.errors.BoatlandInputError`) print one line and exit with status 2;
anything else is a bug and keeps its traceback.
"""

from __future__ import annotations

import argparse
import json
import logging
import sys
from pathlib import Path

from boatland import __version__
from boatland.errors import BoatlandInputError

__all__ = ["main"]

DEFAULT_VESSEL = "ctv24"


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    parser = _parser()
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING,
                        format="%(levelname)s: %(message)s")
    if not hasattr(args, "func"):
        parser.print_help()
        return 0
    try:
        return int(args.func(args) or 0)
    except BoatlandInputError as exc:
        print(f"boatland: error: {exc}", file=sys.stderr)
        return exc.exit_status
    except KeyboardInterrupt:
        print("boatland: interrupted", file=sys.stderr)
        return 130


# ---------------------------------------------------------------------------------------- parser
def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="boatland",
        description="Crew transfer vessel on a boat landing: will the fender hold, and if it slips, "
                    "when and how far?",
        epilog="Start with 'boatland run' (the default CTV landing trial), or 'boatland <command> --help'.",
    )
    p.add_argument("--version", action="version", version=f"boatland {__version__}")
    p.add_argument("-v", "--verbose", action="store_true", help="say more about what is being done")
    sub = p.add_subparsers(title="commands", metavar="COMMAND")

    run = sub.add_parser(
        "run", help="run one landing trial from a scenario file (default: the built-in CTV trial)",
        description="Run one landing trial: the vessel pushing its bow fender against the boat landing in "
                    "the scenario's sea, RK4 Cummins integration with stick–slip fender contact. Prints a "
                    "summary: slip events, time to first slip, slip distance, normal forces, motions, "
                    "incidents. Without a file: scenarios/ctv_landing.toml (24 m CTV, JONSWAP Hs 1.5 m, "
                    "80 kN).")
    run.add_argument("scenario", nargs="?", type=Path, help="scenario file (TOML); see 'boatland scenario schema'")
    run.add_argument("--json", action="store_true", help="print the summary as JSON")
    run.add_argument("-o", "--output", type=Path, help="write the time series, events and summary (HDF5)")
    run.add_argument("--duration", type=float, help="override simulation.duration [s]")
    run.add_argument("--seed", type=int, help="override simulation.seed")
    run.set_defaults(func=_cmd_run)

    scen = sub.add_parser("scenario", help="scenario files: validate, JSON Schema",
                          description="Scenario files (TOML): check one without running it, or print the JSON "
                                      "Schema for editors.")
    ssub = scen.add_subparsers(title="scenario commands", metavar="SCENARIO_COMMAND")
    scen.set_defaults(func=lambda a: scen.print_help())
    chk = ssub.add_parser("check", help="validate a scenario file and its physics against the database")
    chk.add_argument("file", type=Path)
    chk.set_defaults(func=_cmd_scenario_check)
    sch = ssub.add_parser("schema", help="print the JSON Schema of scenario files")
    sch.set_defaults(func=lambda a: print(__import__("boatland.scenario_check", fromlist=["x"]).schema_text()))

    hydro = sub.add_parser("hydro", help="hydrodynamic databases: import BEM output, summarise, build",
                           description="Hydrodynamic databases (BEMIO HDF5): import, summarise, build.")
    hsub = hydro.add_subparsers(title="hydro commands", metavar="HYDRO_COMMAND")
    hydro.set_defaults(func=lambda a: hydro.print_help())

    from boatland.hydro import FORMATS

    imp = hsub.add_parser(
        "import", help="convert WAMIT/NEMOH/AQWA/Capytaine/BEMIO output to a boatland database",
        description="Read BEM output, convert units and phase convention to boatland's, and write a "
                    "database (BEMIO HDF5). Accepted inputs:\n  "
                    + "\n  ".join(f"{k:10s} {v}" for k, v in FORMATS.items()),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    imp.add_argument("path", type=Path, help="BEM output file or folder")
    imp.add_argument("-o", "--output", type=Path, required=True, help="database to write (.h5)")
    imp.add_argument("--format", choices=sorted(FORMATS), help="force a reader instead of detecting it")
    imp.add_argument("--rho", type=float, help="water density [kg/m³] for formats that do not store it "
                                               "(WAMIT; default 1025)")
    imp.add_argument("--g", type=float, help="gravity [m/s²] for formats that do not store it")
    imp.add_argument("--name", help="vessel name to store (default: from the file)")
    imp.set_defaults(func=_cmd_import)

    info = hsub.add_parser("info", help="summarise a database: band, directions, natural periods, warnings",
                           description="Summarise a hydrodynamic database (or any BEM output boatland "
                                       "reads): frequency range, directions, heave/roll/pitch natural "
                                       "periods, and warnings (negative damping, missing A∞, "
                                       "irregular-frequency spikes, dropped frequencies).")
    info.add_argument("database", nargs="?", default=DEFAULT_VESSEL,
                      help=f"database file, BEM output, or a built-in vessel name (default: {DEFAULT_VESSEL})")
    info.add_argument("--json", action="store_true", help="print the summary as JSON")
    info.set_defaults(func=_cmd_info)

    build = hsub.add_parser("build", help="compute a catamaran database with Capytaine from a vessel file",
                            description="Build a hydrodynamic database for a parametric catamaran (two "
                                        "Wigley-type demihulls) with Capytaine: radiation and diffraction "
                                        "over the vessel file's frequencies and directions, A∞ and A₀, "
                                        "hydrostatics, mass matrix. Examples: scenarios/vessels/*.toml.")
    build.add_argument("vessel", type=Path, help="vessel file (TOML)")
    build.add_argument("-o", "--output", type=Path, help="database to write (default: <vessel>.h5 beside "
                                                         "the current directory)")
    build.add_argument("--no-progress", action="store_true", help="no progress bar")
    build.set_defaults(func=_cmd_build)

    lst = hsub.add_parser("list", help="list the built-in vessel databases")
    lst.set_defaults(func=_cmd_list)

    irf = sub.add_parser(
        "irf", help="radiation impulse-response functions and state-space fit of a database",
        description="Compute the radiation IRFs K(t) = (2/π)∫B(ω)cos(ωt)dω of a database, check them "
                    "(B and A reconstructed from K, truncation at T_K, Ogilvie's A∞), fit a stable "
                    "state-space model per DOF pair, print the figures and store everything in the "
                    "database file (BEMIO impulse_response_fun / state_space groups).")
    irf.add_argument("database", nargs="?", default=DEFAULT_VESSEL,
                     help=f"database file or built-in vessel name (default: {DEFAULT_VESSEL})")
    irf.add_argument("--t-max", type=float, default=60.0, help="memory length T_K [s] (default 60)")
    irf.add_argument("--dt", type=float, help="time step of K [s] (default min(0.05, π/(3 ω_max)))")
    irf.add_argument("--tail", choices=("auto", "linear", "none", "asymptotic"), default="auto",
                     help="B(ω) above the band: straight to zero over 20%% of ω_max, stop, extrapolate "
                          "∝ ω^-n, or auto (default): linear when the damping has decayed at the top of "
                          "the band, else ω^-n with a note")
    irf.add_argument("--taper", choices=("none", "cosine"), default="none", help="time window on K")
    irf.add_argument("--clean", choices=("clip", "cut", "none"), default="clip",
                     help="negative damping: clip to zero (default), cut the band, or keep")
    irf.add_argument("--band", type=float, nargs=2, metavar=("LO", "HI"),
                     help="frequency band [rad/s] of the round-trip check (default: the whole band)")
    irf.add_argument("--target-r2", type=float,
                     help="state-space fit target R² (default 0.99999: boatland.model.radiation.TARGET_R2)")
    irf.add_argument("--max-order", type=int,
                     help="largest state-space order per pair (default 40: boatland.model.radiation.MAX_ORDER)")
    irf.add_argument("--no-fit", action="store_true", help="skip the state-space fit")
    irf.add_argument("--plot", type=Path, metavar="PNG", help="write a figure of K(t), B and A")
    irf.add_argument("-o", "--output", type=Path,
                     help="write the database with IRFs to this file instead of updating it in place "
                          "(built-in databases are never modified)")
    irf.add_argument("--no-store", action="store_true", help="do not write anything")
    irf.add_argument("--json", action="store_true", help="print the figures as JSON")
    irf.set_defaults(func=_cmd_irf)
    return p


# -------------------------------------------------------------------------------------- commands
def _resolve_db(spec: str):
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


def _cmd_import(args) -> int:
    from boatland.hydro import read_hydro, write_bemio

    db, fmt = read_hydro(args.path, fmt=args.format, rho=args.rho, g=args.g)
    if args.name:
        db = db.replace(name=args.name)
    write_bemio(db, args.output)
    print(f"read {args.path} with the {fmt} reader ({db.n_freq} frequencies, {db.n_dir} direction{'s' if db.n_dir != 1 else ''}); "
          f"wrote {args.output}")
    for note in db.provenance.notes:
        print(f"  note: {note}")
    return 0


def _cmd_info(args) -> int:
    from boatland.hydro.info import summary, summary_text

    db = _resolve_db(args.database)
    if args.json:
        print(json.dumps(summary(db), indent=2))
    else:
        print(summary_text(db))
    return 0


def _cmd_build(args) -> int:
    from boatland.hydro.build import build_from_file

    out = args.output or Path(args.vessel.stem + ".h5")
    db = build_from_file(args.vessel, out, progress=not args.no_progress)
    print(f"wrote {out}: {db.n_freq} frequencies, {db.n_dir} directions, "
          f"{db.mesh.n_panels if db.mesh is not None else 0} panels")
    return 0


def _cmd_irf(args) -> int:
    from boatland.hydro.bemio import write_bemio, write_radiation
    from boatland.hydro.irf_report import irf_summary, irf_table, plot_irf
    from boatland.irf.impulse import IRFSettings
    from boatland.model.radiation import MAX_ORDER, TARGET_R2, default_dt, radiation_memory

    db = _resolve_db(args.database)
    dt = args.dt if args.dt is not None else default_dt(db.omega[-1])
    settings = IRFSettings(t_max=args.t_max, dt=dt, tail=args.tail, taper=args.taper, clean=args.clean,
                           check_band=tuple(args.band) if args.band else None)
    memory = radiation_memory(db, settings, fit=not args.no_fit,
                              target_r2=TARGET_R2 if args.target_r2 is None else args.target_r2,
                              max_order=MAX_ORDER if args.max_order is None else args.max_order)
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


def _cmd_run(args) -> int:
    import warnings

    from boatland.scenario_check import default_scenario_path, load_checked
    from boatland.trial.simulate import BlowUpError, simulate

    path = args.scenario or default_scenario_path()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scenario, db, _ = load_checked(path)
        changes = {}
        if args.duration is not None:
            changes["simulation.duration"] = args.duration
        if args.seed is not None:
            changes["simulation.seed"] = args.seed
        if changes:
            scenario = scenario.replace(changes)
        if not args.json:
            print(f"running {scenario.name}: {scenario.simulation.duration:g} s at dt = {scenario.time_step(db):g} s "
                  f"({scenario.n_steps(db)} steps), {db.name}, radiation {scenario.radiation.method}", file=sys.stderr)
        try:
            result = _simulate_with_bar(simulate, scenario, db, show=not args.json)
        except BlowUpError as exc:
            print(f"boatland: error: {path}: {exc}", file=sys.stderr)
            return 3
    for w in caught:
        if not args.json:
            print(f"warning: {w.message}", file=sys.stderr)
    if args.output:
        result.to_hdf5(args.output)
    if args.json:
        print(json.dumps(result.summary(), indent=2, default=float))
    else:
        print(result.summary_text())
        if args.output:
            print(f"wrote {args.output}")
    return 0


def _simulate_with_bar(simulate, scenario, db, *, show: bool):
    """Run one trial with a progress bar on stderr (simulated seconds; hidden when stderr is not a
    terminal or ``show`` is False)."""
    if not show:
        return simulate(scenario, db)
    from tqdm import tqdm

    dt = scenario.time_step(db)
    with tqdm(total=round(scenario.n_steps(db) * dt, 2), unit="s", unit_scale=False, file=sys.stderr,
              disable=None, leave=False, desc="simulated", dynamic_ncols=True,
              bar_format="{desc} {n:.1f}/{total:.1f} s |{bar}| {elapsed}<{remaining}") as bar:
        def progress(done, total):
            bar.n = round(done * dt, 2)
            bar.refresh()

        return simulate(scenario, db, progress=progress)


def _cmd_scenario_check(args) -> int:
    from boatland.scenario_check import check_file

    report = check_file(args.file)
    print(report.text)
    return report.exit_status


def _cmd_list(args) -> int:
    from boatland.hydro.builtin import BUILTIN, builtin_path

    for name, text in BUILTIN.items():
        print(f"{name:8s} {text}  [{builtin_path(name)}]")
    return 0
