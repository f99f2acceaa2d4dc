"""``boatland campaign``: a Monte Carlo slip-probability campaign into a resumable store."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from boatland.errors import BoatlandInputError

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    camp = sub.add_parser(
        "campaign", help="Monte Carlo slip-probability campaign: many trials over a sweep, into a resumable store",
        description="Run every trial of a campaign file (a base scenario, axes to sweep, N seeds per case) on "
                    "local worker processes or a Dask cluster. Results go to an HDF5 store as they arrive; "
                    "running the same command again resumes where it stopped (no trial lost or run twice). "
                    "Example: boatland campaign scenarios/campaigns/demo.toml")
    camp.add_argument("campaign", type=Path, help="campaign file (TOML); see scenarios/campaigns/")
    camp.add_argument("-o", "--output", type=Path, help="store (HDF5; default: <campaign name>.h5 here)")
    camp.add_argument("--workers", type=int, help="local worker processes (default: all cores)")
    camp.add_argument("--scheduler", metavar="URL", help="run on a Dask scheduler (tcp://host:port) instead")
    camp.add_argument("--report", type=Path, metavar="DIR", help="also write the report into DIR at the end")
    camp.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.campaign import load_campaign, run_campaign
    from boatland.campaign.report import write_report
    from boatland.scenario_check import load, resolve_database

    if args.workers is not None and args.workers < 1:
        raise BoatlandInputError(f"--workers must be ≥ 1, got {args.workers}")
    campaign = load_campaign(args.campaign, load_scenario=load)
    store = args.output or Path(f"{campaign.name}.h5")
    where = f"Dask scheduler {args.scheduler}" if args.scheduler else \
        f"{args.workers or os.cpu_count()} local worker process(es)"
    print(f"campaign {campaign.name}: {len(campaign.cases)} cases × {campaign.seeds} seeds = {campaign.n_trials} "
          f"trials of {campaign.base.simulation.duration:g} s on {where} → {store}", file=sys.stderr)
    from tqdm import tqdm

    with tqdm(total=campaign.n_trials, unit="trial", file=sys.stderr, disable=None, dynamic_ncols=True) as bar:
        def progress(done, total):
            bar.n = done
            bar.refresh()

        result = run_campaign(campaign, store, loaders=(load, resolve_database),
                              executor="dask" if args.scheduler else "local", workers=args.workers,
                              scheduler=args.scheduler, progress=progress)
    table = result.table()
    failed = int((table["status"] < 0).sum())
    print(f"wrote {store}: {len(table)} trials" + (f", {failed} failed (see their message column)" if failed else ""))
    if args.report:
        files = write_report(store, args.report)
        print(f"wrote {len(files)} report files to {args.report}")
    return 0
