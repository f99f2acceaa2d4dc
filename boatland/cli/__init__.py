"""The ``boatland`` command (also ``python -m boatland``): one module per command.

Each command module has ``add_parser(sub)`` (its argparse sub-command) and ``cmd(args)`` (the work,
returning the exit status). User mistakes (:class:`boatland.errors.BoatlandInputError`) print one line
and exit with status 2; anything else is a bug and keeps its traceback.
"""

from __future__ import annotations

import logging
import os
import sys

from boatland import __version__
from boatland.errors import BoatlandInputError

__all__ = ["main"]

#: Command modules in the order ``boatland --help`` lists them.
COMMANDS = ("run", "replay", "plot", "campaign", "report", "scenario", "hydro", "irf", "rao", "screen",
            "operability", "validate")


def _one_line_warning(message, category, filename, lineno, file=None, line=None):
    """boatland's own warnings (a scenario's, a database's) as one line on stderr, ``warning: …`` — not Python's
    file, line and source; everyone else's as Python prints them."""
    import warnings

    from boatland.errors import BoatlandWarning

    if issubclass(category, BoatlandWarning):
        print(f"warning: {message}", file=file or sys.stderr)
    else:
        sys.stderr.write(warnings.formatwarning(message, category, filename, lineno, line))


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit status.

    0 done; 2 a user mistake (no command included) or an environment failure (unwritable path, disk full, out of memory:
    one line, no traceback); 3 a trial blew up; 1 some campaign trials failed; 130 interrupted;
    141 the reader of the output went away (e.g. ``| head``), quietly.
    """
    parser = _parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:           # --help, --version, or a one-line argument error
        return exc.code if isinstance(exc.code, int) else 2
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING,
                        format="%(levelname)s: %(message)s")
    import warnings

    # numba says this while compiling the kernel's gate (a sleep in object mode, by design): not for users
    warnings.filterwarnings("ignore", message="Code running in object mode won't allow parallel execution")
    warnings.showwarning = _one_line_warning
    _no_kill_on_file_size()
    if not hasattr(args, "func"):
        parser.print_usage(sys.stderr)
        _error("no command given; start with 'boatland run', or see 'boatland --help'")
        return 2
    try:
        return int(args.func(args) or 0)
    except BoatlandInputError as exc:
        _error(_one_line(exc))
        return exc.exit_status
    except KeyboardInterrupt:
        print("boatland: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        _silence_stdout()
        return 141
    except MemoryError:
        _error("out of memory; shorten the run (simulation.duration) or split it into several runs")
        return 2
    except OSError as exc:              # the environment: unwritable path, disk full, ...
        import errno

        where = f"{exc.filename}: " if exc.filename else ""
        what = exc.strerror or (str(exc).splitlines()[0] if str(exc) else type(exc).__name__)
        if exc.errno in (errno.ENOSPC, errno.EFBIG, getattr(errno, "EDQUOT", -1)):
            _error(f"no space left writing {exc.filename or 'an output'} ({what}); nothing else lost — its "
                   "temporary file is removed, earlier outputs and finished campaign trials are kept")
        else:
            _error(f"{where}{what}")
        return 2


def _no_kill_on_file_size() -> None:
    """A file-size limit (``ulimit -f``) would kill the process with SIGXFSZ mid-write (and dump core):
    ignored, a write past the limit fails with EFBIG instead, which the writer reports in one line and
    cleans up after, like a full disk."""
    import signal

    if hasattr(signal, "SIGXFSZ"):
        try:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        except (OSError, ValueError):      # not the main thread (an embedding program): its own choice
            pass


def _one_line(exc: BoatlandInputError) -> str:
    """The error as one line: a file's several problems joined with "; " (all of them, at once)."""
    problems = getattr(exc, "problems", None)
    if problems and len(problems) > 1:
        text = f"{exc.source}: {len(problems)} problems: " + "; ".join(f"{k}: {m}" if k else m for k, m in problems)
    else:
        text = str(exc)
    return " ".join(part.strip() for part in text.splitlines() if part.strip())


def _error(message: str) -> None:
    try:
        print(f"boatland: error: {message}", file=sys.stderr)
    except (BrokenPipeError, OSError):
        pass


def _silence_stdout() -> None:
    """After a broken pipe: point stdout at /dev/null so the interpreter's last flush stays quiet."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # a captured stdout (tests) has no descriptor
        pass


def _parser():
    import importlib

    from boatland.cli.guard import OneLineParser

    p = OneLineParser(
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
