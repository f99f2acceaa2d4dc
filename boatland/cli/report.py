"""``boatland report``: tables and figures of a campaign store."""

from __future__ import annotations

from pathlib import Path

from boatland.cli.guard import Output, check_outputs, in_range
from boatland.errors import BoatlandInputError

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    rep = sub.add_parser(
        "report", help="tables and figures of a finished campaign store",
        description="Write per-case tables (CSV and Markdown: P(incident) with Clopper–Pearson intervals, mean "
                    "time to the incident with χ² intervals), the limiting Hs table and figures (P vs Hs, "
                    "limiting Hs polar, time-to-incident distributions).")
    rep.add_argument("store", type=Path, help="campaign store (HDF5) written by 'boatland campaign'")
    rep.add_argument("-o", "--output", type=Path, default=Path("report"), help="folder (default: ./report)")
    rep.add_argument("--incident", help="incident definition for limiting Hs and figures (default: the "
                                        "first slip-distance definition)")
    rep.add_argument("--target", type=in_range(0.0, 1.0, hi_open=True), default=0.1,
                     help="accepted probability of the incident within the access (default 0.1)")
    rep.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.campaign.report import write_report

    if not 0.0 < args.target < 1.0:
        raise BoatlandInputError(f"--target must lie in (0, 1), got {args.target}")
    from boatland.campaign.report import REPORT_FILES

    check_outputs([Output("-o", args.output, "folder", REPORT_FILES)], [args.store])
    files = write_report(args.store, args.output, incident=args.incident, target=args.target)
    for f in files:
        print(f"wrote {f}")
    return 0
