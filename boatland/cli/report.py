"""``boatland report``: the one page, decision table, tables and figures of a campaign store."""

from __future__ import annotations

from pathlib import Path

from boatland.cli.guard import accept_arg, in_range
from boatland.outputs import Output, check_outputs

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    rep = sub.add_parser(
        "report", help="one page (report.html), decision table, tables and figures of a finished campaign store",
        description="Print the decision table of a campaign — P(incident within the access) with its Clopper–Pearson "
                    "95 % interval per Hs × Tp × heading, the limiting Hs with its interval, and the seeds an "
                    "interval of --width needs — and write report.html, one self-contained page to decide from "
                    "(opens offline, reads on a phone: the inputs, the incident and the accepted risk in words, the "
                    "decision table and every figure embedded), with decision.md/.csv, the per-case tables "
                    "(cases.csv/.md: P and the mean time to the incident with its χ² interval), the limiting-Hs table "
                    "and figures (P vs Hs, limiting Hs polar with 180° head seas at the top, time-to-incident "
                    "distributions). The frequency-domain screening predicts slip onsets: it is shown beside the "
                    "incident 'first slip' only (--incident \"first slip\"). A rare-event (isee) store gets its "
                    "limiting Hs and per-run estimates (isee_limits, isee_runs) and the page instead.")
    rep.add_argument("store", type=Path, help="campaign store (HDF5) written by 'boatland campaign'")
    rep.add_argument("-o", "--output", type=Path, default=Path("report"), help="folder (default: ./report)")
    rep.add_argument("--incident", help="incident definition of the decision table, limiting Hs and figures "
                                        "(default: the first slip-distance definition; an isee store: its own)")
    rep.add_argument("--target", type=accept_arg, default=0.1, metavar="P",
                     help="accepted probability of the incident within the access, for the limiting Hs: in (0, 1) or a "
                          "preset of Grøtting (2015) Table 2.1 (best = 1.19e-3, conservative, non-conservative); "
                          "report.html states it in words (default 0.1, what a campaign of tens of seeds resolves; an "
                          "isee store has its own, [isee] accept)")
    rep.add_argument("--width", type=in_range(0.0, 1.0, hi_open=True), default=0.2,
                     help="width asked of the 95 %% interval of P near the target: the report says how many seeds "
                          "per case that needs (default 0.2, i.e. ±0.1)")
    rep.add_argument("--json", action="store_true", help="print the decision table and the files written as JSON")
    rep.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.campaign.report import (
        REPORT_FILES,
        isee_incident,
        read_store,
        store_decision,
        write_report,
    )

    check_outputs([Output("-o", args.output, "folder", REPORT_FILES)], [args.store])
    data = read_store(args.store)
    if data["header"].get("method") == "isee":       # no decision table: its limits and runs, and the page
        incident = isee_incident(data, args.incident)
        files = write_report(args.store, args.output, incident=incident)
        if args.json:
            from boatland.cli.common import print_json

            print_json({"method": "isee", "incident": incident, "files": [str(f) for f in files]})
            return 0
        print(f"{args.store}: a rare-event (isee) campaign of P({incident} within the access); its limiting Hs "
              "(at its own [isee] accept) and per-run estimates are in isee_limits.md / isee_runs.md and report.html")
        print(f"wrote {len(files)} files to {args.output}: " + ", ".join(f.name for f in files))
        return 0
    dec = store_decision(args.store, incident=args.incident, target=args.target, width=args.width)
    files = write_report(args.store, args.output, incident=dec.incident, target=args.target, width=args.width)
    if args.json:
        from boatland.cli.common import print_json

        print_json({**dec.as_dict(), "files": [str(f) for f in files]})
        return 0
    print(dec.text())
    print(f"wrote {len(files)} files to {args.output}: " + ", ".join(f.name for f in files))
    return 0
