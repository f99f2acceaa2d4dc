"""``boatland scenario check FILE`` and ``boatland scenario schema``."""

from __future__ import annotations


from boatland.cli.common import shipped_or_path
from boatland.cli.guard import no_subcommand

__all__ = ["add_parser", "check", "schema"]


def add_parser(sub) -> None:
    scen = sub.add_parser("scenario", help="scenario files: validate, JSON Schema",
                          description="Scenario files (TOML): check one without running it, or print the JSON "
                                      "Schema for editors.")
    ssub = scen.add_subparsers(title="scenario commands", metavar="SCENARIO_COMMAND")
    scen.set_defaults(func=no_subcommand(scen))
    chk = ssub.add_parser("check", help="validate a scenario file and its physics against the database")
    chk.add_argument("file", type=shipped_or_path("scenario"), help="scenario file (TOML) or a shipped name")
    chk.add_argument("--json", action="store_true",
                     help="print the result as JSON: ok, problems with their key paths, warnings, notes, inputs")
    chk.set_defaults(func=check)
    sch = ssub.add_parser("schema", help="print the JSON Schema of scenario files")
    sch.set_defaults(func=schema)


def check(args) -> int:
    from boatland.checks.files import check_file

    report = check_file(args.file)
    if args.json:
        from boatland.cli.common import print_json

        print_json(report.as_dict())
    else:
        print(report.text)
    return report.exit_status


def schema(args) -> int:
    from boatland.checks.files import schema_text

    print(schema_text())
    return 0
