"""``boatland hydro import | info | build | list``: hydrodynamic databases."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from boatland.cli.common import DEFAULT_VESSEL
from boatland.cli.guard import finite, no_subcommand, positive
from boatland.outputs import Output, check_outputs
from boatland.errors import BoatlandInputError

__all__ = ["add_parser", "cmd_import", "cmd_info", "cmd_build", "cmd_list"]


def add_parser(sub) -> None:
    hydro = sub.add_parser("hydro", help="hydrodynamic databases: import BEM output, summarise, build",
                           description="Hydrodynamic databases (BEMIO HDF5): import, summarise, build.")
    hsub = hydro.add_subparsers(title="hydro commands", metavar="HYDRO_COMMAND")
    hydro.set_defaults(func=no_subcommand(hydro))

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
    imp.add_argument("--rho", type=positive("kg/m³", 1e5), help="water density [kg/m³] for formats that do not store it "
                                               "(WAMIT; default 1025)")
    imp.add_argument("--g", type=positive("m/s²", 1e3), help="gravity [m/s²] for formats that do not store it")
    imp.add_argument("--name", help="vessel name to store (default: from the file)")
    mass = imp.add_argument_group(
        "mass properties", "for BEM output without a mass matrix (WAMIT, NEMOH, most BEMIO files): the checks of "
                           "a vessel file's [inertia] (mass = ρ∇ within 1 %, stable in roll and pitch, possible "
                           "inertia); the restoring matrix is moved to this mass and centre of gravity")
    mass.add_argument("--mass", type=positive("kg"), metavar="KG", help="mass [kg] (default: ρ∇ of the database)")
    mass.add_argument("--cog", type=finite, nargs=3, metavar=("X", "Y", "Z"),
                      help="centre of gravity in the database's frame [m] (default: the database's)")
    rad = mass.add_mutually_exclusive_group()
    rad.add_argument("--radii", type=positive("m"), nargs=3, metavar=("RXX", "RYY", "RZZ"),
                     help="radii of gyration about the centre of gravity [m]")
    rad.add_argument("--inertia", type=positive("kg m²"), nargs=3, metavar=("IXX", "IYY", "IZZ"),
                     help="principal moments of inertia about the centre of gravity [kg m²]")
    mass.add_argument("--hydrostatic-restoring", action="store_true",
                      help="the file's restoring matrix is pure hydrostatics (no weight terms of its own centre of "
                           "gravity, which WAMIT, NEMOH, AQWA and Capytaine include)")
    imp.set_defaults(func=cmd_import)

    info = hsub.add_parser("info", help="summarise a database: band, directions, natural periods, warnings",
                           description="Summarise a hydrodynamic database (or any BEM output boatland "
                                       "reads): frequency range, directions, heave/roll/pitch natural "
                                       "periods, and warnings (negative damping, missing A∞, "
                                       "irregular-frequency spikes, dropped frequencies).")
    info.add_argument("database", nargs="?", default=DEFAULT_VESSEL,
                      help=f"database file, BEM output, or a built-in vessel name (default: {DEFAULT_VESSEL})")
    info.add_argument("--json", action="store_true", help="print the summary as JSON")
    info.set_defaults(func=cmd_info)

    bld = hsub.add_parser("build", help="compute a catamaran database with Capytaine from a vessel file",
                          description="Build a hydrodynamic database for a parametric catamaran (a CTV hull "
                                      "with a transom, hard chine or round bilge, or two Wigley-type "
                                      "demihulls) with Capytaine: radiation and diffraction over the vessel "
                                      "file's frequencies and directions, A∞ and A₀, hydrostatics, mass "
                                      "matrix, and the hull above water for the viewers. A vessel file with "
                                      "a [bem] table instead writes its BEM output with the file's mass "
                                      "properties (no Capytaine). Examples: scenarios/vessels/*.toml.")
    bld.add_argument("vessel", type=Path, help="vessel file (TOML)")
    bld.add_argument("-o", "--output", type=Path, help="database to write (default: <vessel>.h5 beside "
                                                       "the current directory)")
    bld.add_argument("--no-progress", action="store_true", help="no progress bar")
    bld.set_defaults(func=cmd_build)

    lst = hsub.add_parser("list", help="list the built-in vessel databases")
    lst.add_argument("--json", action="store_true", help="print the list as JSON (name, description, file)")
    lst.set_defaults(func=cmd_list)


def cmd_import(args) -> int:
    from boatland.hydro import read_hydro, write_bemio

    check_outputs([Output("-o", args.output)], [args.path])
    db, fmt = read_hydro(args.path, fmt=args.format, rho=args.rho, g=args.g)
    given = [f for f in ("mass", "cog", "radii", "inertia") if getattr(args, f) is not None]
    if given or args.hydrostatic_restoring:
        from boatland.vessel.imported import MassProperties, apply_mass_properties

        if args.radii is None and args.inertia is None:
            raise BoatlandInputError("--radii or --inertia: missing: the mass properties need the body's inertia "
                                     "(radii of gyration or principal moments about its centre of gravity)")
        keys = {"mass": "--mass", "cog": "--cog", "weight_in_restoring": "--hydrostatic-restoring",
                **{f"r_{a}": f"--radii ({a})" for a in ("xx", "yy", "zz")},
                **{f"i_{a}": f"--inertia ({a})" for a in ("xx", "yy", "zz")}}
        mp = MassProperties(mass=args.mass, cog=tuple(args.cog) if args.cog else None,
                            radii=tuple(args.radii) if args.radii else (None,) * 3,
                            inertia=tuple(args.inertia) if args.inertia else (None,) * 3,
                            weight_in_restoring=not args.hydrostatic_restoring, keys=keys)
        db = apply_mass_properties(db, mp, source="the command line")
    if args.name:
        db = db.replace(name=args.name)
    write_bemio(db, args.output)
    print(f"read {args.path} with the {fmt} reader ({db.n_freq} frequencies, {db.n_dir} direction{'s' if db.n_dir != 1 else ''}); "
          f"wrote {args.output}")
    for note in db.provenance.notes:
        print(f"  note: {note}")
    return 0


def cmd_info(args) -> int:
    from boatland.hydro.info import summary, summary_text

    from boatland.hydro import load_database

    db = load_database(args.database)
    if args.json:
        print(json.dumps(summary(db), indent=2))
    else:
        print(summary_text(db))
    return 0


def cmd_build(args) -> int:
    from boatland.hydro.build import build_from_file

    out = args.output or Path(args.vessel.stem + ".h5")
    check_outputs([Output("-o", out)], [args.vessel])
    db = build_from_file(args.vessel, out, progress=not args.no_progress)
    print(f"wrote {out}: {db.n_freq} frequencies, {db.n_dir} directions, "
          f"{db.mesh.n_panels if db.mesh is not None else 0} panels")
    return 0


def cmd_list(args) -> int:
    from boatland.hydro.builtin import BUILTIN, builtin_path

    if args.json:
        from boatland.cli.common import print_json

        print_json([{"name": name, "description": text, "file": str(builtin_path(name))}
                    for name, text in BUILTIN.items()])
        return 0
    for name, text in BUILTIN.items():
        print(f"{name:8s} {text}  [{builtin_path(name)}]")
    return 0
