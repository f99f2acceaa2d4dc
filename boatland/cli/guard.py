"""The edge's guard: argument types that refuse impossible values (one line, exit 2).

The outputs a command writes are checked by :func:`boatland.outputs.check_outputs`, before any work.
"""

from __future__ import annotations

import argparse
import math

from boatland.errors import BoatlandInputError

__all__ = ["finite", "positive", "in_range", "integer", "seed", "OneLineParser", "SEED_MAX", "no_subcommand"]

#: Seeds are stored as signed 64-bit integers (campaign store, run logs).
SEED_MAX = 2 ** 63 - 1


class OneLineParser(argparse.ArgumentParser):
    """An argument parser whose errors are one line (``boatland CMD: error: ...``) and exit status 2."""

    def error(self, message: str):  # noqa: D401 - argparse's API
        self.exit(2, f"{self.prog}: error: {message} (see '{self.prog} --help')\n")


def no_subcommand(parser):
    """The ``func`` of a command group called without its sub-command: usage on stderr, exit status 2."""
    def func(args) -> int:
        import sys

        parser.print_usage(sys.stderr)
        print(f"{parser.prog}: error: a command is needed (see '{parser.prog} --help')", file=sys.stderr)
        return 2
    return func


# ------------------------------------------------------------------------------------ argument types
def finite(text: str) -> float:
    """A finite float (``nan`` and ``inf`` are refused)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text} is not a finite number")
    return value


def in_range(lo: float | None = None, hi: float | None = None, *, lo_open: bool = True, hi_open: bool = False,
             unit: str = ""):
    """Argument type: a finite float in (lo, hi] (bounds and openness configurable)."""
    def parse(text: str) -> float:
        value = finite(text)
        bad_lo = lo is not None and (value <= lo if lo_open else value < lo)
        bad_hi = hi is not None and (value >= hi if hi_open else value > hi)
        if bad_lo or bad_hi:
            left = "(" if lo_open else "["
            right = ")" if hi_open or hi is None else "]"
            raise argparse.ArgumentTypeError(
                f"{text}{unit}: must lie in {left}{'-∞' if lo is None else f'{lo:g}'}, "
                f"{'∞' if hi is None else f'{hi:g}'}{right}")
        return value
    parse.__name__ = "number"
    return parse


def positive(unit: str = "", hi: float | None = None):
    """Argument type: a finite float > 0 (and ≤ ``hi``)."""
    return in_range(0.0, hi, unit=f" {unit}" if unit else "")


def integer(lo: int | None = None, hi: int | None = None):
    """Argument type: an integer in [lo, hi]."""
    def parse(text: str) -> int:
        try:
            value = int(text, 10)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
        if (lo is not None and value < lo) or (hi is not None and value > hi):
            raise argparse.ArgumentTypeError(f"{text}: must lie in {lo if lo is not None else '-∞'} … "
                                             f"{hi if hi is not None else '∞'}")
        return value
    parse.__name__ = "integer"
    return parse


seed = integer(0, SEED_MAX)


def accept_arg(text: str) -> float:
    """Argument type: an accepted probability per access, in (0, 1), or a preset name of Grøtting (2015) Table
    2.1 (:func:`boatland.freqdomain.statistics.accept_probability`)."""
    from boatland.freqdomain.statistics import accept_probability

    try:
        return accept_probability(text)
    except BoatlandInputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


