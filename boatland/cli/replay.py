"""``boatland replay``: a run log (MCAP) into the Rerun viewer."""

from __future__ import annotations

import sys
from pathlib import Path

from boatland.cli.guard import integer
from boatland.outputs import Output, check_outputs

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    rpl = sub.add_parser(
        "replay", help="replay a run log (MCAP) in the Rerun viewer: 3D scene, plots, events",
        description="Read a run log written by 'boatland run' (a truncated log of a killed run is recovered "
                    "up to its last complete second, and what is lost is said) and send it to Rerun with the "
                    "scene and layout of the live stream. Without an option: --save <log>.rrd.")
    rpl.add_argument("log", type=Path, help="run log (.mcap)")
    how = rpl.add_mutually_exclusive_group()
    how.add_argument("--save", type=Path, metavar="RRD", help="write a Rerun file (open it with 'rerun FILE.rrd')")
    how.add_argument("--serve", action="store_true", help="serve to Rerun viewers (prints the URL to open)")
    how.add_argument("--spawn", action="store_true", help="start a Rerun viewer (needs a display)")
    how.add_argument("--connect", metavar="URL", nargs="?", const="", help="send to a Rerun viewer already listening")
    rpl.add_argument("--bind", metavar="ADDR", default="127.0.0.1",
                     help="address the --serve server, or the viewer --spawn starts, listens on (default 127.0.0.1: "
                          "this machine only; 0.0.0.0 opens it to the network, without authentication)")
    rpl.add_argument("--port", type=integer(1, 65535), default=9876, help="port of --serve or --spawn's viewer (default 9876)")
    rpl.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.record.replay import replay

    if args.serve:
        target = "serve"
    elif args.spawn:
        target = "spawn"
    elif args.connect is not None:
        target = f"connect={args.connect}" if args.connect else "connect"
    else:
        target = f"save={args.save or args.log.with_suffix('.rrd')}"
    check_outputs([Output("--save", Path(target[5:]) if target.startswith("save=") else None)], [args.log])
    done = replay(args.log, target, bind=args.bind, port=args.port)
    for note in done.notes:
        print(f"note: {note}", file=sys.stderr)
    log = done.log
    print(f"{args.log}: {len(log.columns)} steps, t = 0 … {log.duration:.2f} s, {len(log.events)} events"
          + ("" if log.complete else " (recovered from a truncated log)"))
    t, what = done.moment
    if done.shown:
        print(f"the viewer shows t = {t:.2f} s: {what}")
    else:
        print(f"look at t = {t:.2f} s: {what} (the viewer opens at the start; drag its time cursor there)")
    if done.kind == "save":
        print(f"wrote {done.where} (open it with 'rerun {done.where}')")
    elif done.kind == "serve":
        from boatland.record.rerun_log import serve_until_interrupted

        serve_until_interrupted(done.where)
    return 0
