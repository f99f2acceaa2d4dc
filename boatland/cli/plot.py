"""``boatland plot``: the report figure of a run log."""

from __future__ import annotations

import sys
from pathlib import Path

from boatland.cli.guard import Output, check_outputs

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    plo = sub.add_parser(
        "plot", help="figure of a run log: motions, fender forces vs available friction, slip distance",
        description="Plot the main time series of a run log (MCAP) for a report: heave/roll/pitch, fender "
                    "normal force with the friction needed to stick and the friction available, slip distance "
                    "from the landing position, with slip starts and incidents marked.")
    plo.add_argument("log", type=Path, help="run log (.mcap)")
    plo.add_argument("-o", "--output", type=Path, help="figure file (.png, .pdf, .svg; default <log>.png)")
    plo.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.record.plot import plot_run
    from boatland.record.reader import read_run_log

    out = args.output or args.log.with_suffix(".png")
    check_outputs([Output("-o", out, "figure")], [args.log])
    log = read_run_log(args.log)
    for note in log.notes:
        print(f"note: {note}", file=sys.stderr)
    out = plot_run(log, out)
    print(f"wrote {out}")
    return 0
