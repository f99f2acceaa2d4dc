"""The ``boatland`` command (also ``python -m boatland``): one module per command.

Each command module has ``add_parser(sub)`` (its argparse sub-command) and ``cmd(args)`` (the work,
returning the exit status). User mistakes (:class:`boatland.errors.BoatlandInputError`) print one line
and exit with status 2; anything else is a bug and keeps its traceback.
"""

from __future__ import annotations

import argparse
import logging
import sys

from boatland import __version__
from boatland.errors import BoatlandInputError

__all__ = ["main"]

#: Command modules in the order ``boatland --help`` lists them.
COMMANDS = ("run", "replay", "plot", "campaign", "report", "scenario", "hydro", "irf", "rao", "screen",
            "operability")


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


def _parser() -> argparse.ArgumentParser:
    import importlib

    p = argparse.ArgumentParser(
        prog="boatland",
        description="Crew transfer vessel on a boat landing: will the fender hold, and if it slips, "
                    "when and how far?",
        epilog="Start with 'boatland run' (the default CTV landing trial), or 'boatland <command> --help'.",
    )
    p.add_argument("--version", action="version", version=f"boatland {__version__}")
    p.add_argument("-v", "--verbose", action="store_true", help="say more about what is being done")
    sub = p.add_subparsers(title="commands", metavar="COMMAND")
    for name in COMMANDS:
        importlib.import_module(f"boatland.cli.{name}").add_parser(sub)
    return p
