"""``boatland plot``: the report figure of a run log."""

from __future__ import annotations

import sys
from pathlib import Path

from boatland.cli.guard import integer
from boatland.outputs import Output, check_outputs

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    plo = sub.add_parser(
        "plot", help="figure of a run log: wave at the bow, motions, friction utilisation, forces, slip distance",
        description="Plot a run log (MCAP) for a report: the wave elevation at the bow and heave, roll and pitch, "
                    "the friction utilisation of each contact (friction needed to stick / available; it slips at "
                    "1), normal forces, the slip distance from where the fender landed with the incident "
                    "thresholds; the settling shaded, slip starts ticked, incidents labelled, and the inputs and "
                    "the verdict in the title.")
    plo.add_argument("log", type=Path, help="run log (.mcap)")
    plo.add_argument("-o", "--output", type=Path, help="figure file (.png, .pdf, .svg; default <log>.png)")
    plo.add_argument("--dpi", type=integer(30, 600), default=110, help="resolution of raster figures (default 110)")
    plo.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.record.plot import plot_run
    from boatland.record.reader import read_run_log

    out = args.output or args.log.with_suffix(".png")
    check_outputs([Output("-o", out, "figure")], [args.log])
    log = read_run_log(args.log)
    for note in log.notes:
        print(f"note: {note}", file=sys.stderr)
    out = plot_run(log, out, dpi=args.dpi)
    print(f"wrote {out}")
    return 0
