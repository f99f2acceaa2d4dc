"""Start-up of a campaign: the time from launching ``boatland campaign`` to the start of its first trial.

Each row launches the real CLI in a fresh process (imports, the campaign and scenario files, the checks,
the radiation memory, the pile's tables, the store, the workers) with ``execute_trial`` wrapped to note
the moment the first trial starts (in the worker), and stops there. The disk cache
(:mod:`boatland.diskcache`) off, cold (an empty folder: the run makes and stores the memory and the tables)
and warm (a repeated campaign); ``--before CHECKOUT`` adds the same campaign on another checkout of the code
(its own cache folder, warm if it has one). Rows run round-robin; the best of ``--rounds`` is kept
(the VM's speed drifts).

Run: ``python bench/bench_startup.py [--before CHECKOUT] [--rounds 5]``.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from datetime import date
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))
from _timing import cpu_name  # noqa: E402

CHILD = r"""
import os, sys, time
import boatland.campaign.runner as runner
def first(*a, **k):
    with open(os.environ["BENCH_FIRST_TRIAL"], "w") as f:
        f.write(repr(time.time()))
    os._exit(0)                                  # the worker: enough measured
runner.execute_trial = first
from boatland.cli import main
sys.argv = ["boatland"] + sys.argv[1:]
sys.exit(main())
"""


def first_trial(code: Path, campaign: Path, cache: str, work: Path) -> float:
    """Seconds from launch to the first trial's start (NaN if none started)."""
    mark = work / "first.txt"
    mark.unlink(missing_ok=True)
    for p in work.glob("s.h5*"):
        shutil.rmtree(p) if p.is_dir() else p.unlink()
    env = dict(os.environ, PYTHONPATH=str(code), BENCH_FIRST_TRIAL=str(mark), BOATLAND_CACHE_DIR=cache)
    t0 = time.time()
    subprocess.run([sys.executable, "-c", CHILD, "campaign", str(campaign), "-o", str(work / "s.h5")], cwd=work,
                   env=env, capture_output=True, text=True, timeout=600)
    return float(mark.read_text()) - t0 if mark.exists() else float("nan")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--before", type=Path, metavar="CHECKOUT", help="another checkout of the code, beside this one")
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    work = Path(tempfile.mkdtemp(prefix="bench_startup_"))
    demo = REPO / "boatland" / "scenarios" / "campaigns" / "demo.toml"
    long_demo = work / "demo600.toml"
    text = demo.read_text(encoding="utf-8").replace('scenario = "../ctv_landing.toml"',
                                                    f'scenario = "{demo.parent.parent / "ctv_landing.toml"}"')
    long_demo.write_text("\n".join("access = 600.0" if ln.startswith("access =") else ln
                                   for ln in text.splitlines()) + "\n", encoding="utf-8")
    warm = str(work / "warm")
    rows = []
    for name, camp in (("demo (140 s)", demo), ("demo at 600 s", long_demo)):
        if args.before:
            rows.append((f"before ({args.before.name})", args.before.resolve(), name, camp, "before"))
        rows += [("this", REPO, name, camp, "off"), ("this", REPO, name, camp, "cold"),
                 ("this", REPO, name, camp, "warm")]
    first_trial(REPO, demo, warm, work)                     # numba's own cache compiled; the warm folder filled
    first_trial(REPO, long_demo, warm, work)
    if args.before:
        first_trial(args.before.resolve(), demo, str(work / "before"), work)
    best = {i: float("inf") for i in range(len(rows))}
    for _ in range(args.rounds):
        for i, (_, code, _, camp, mode) in enumerate(rows):
            if mode == "cold":
                shutil.rmtree(work / "cold", ignore_errors=True)
            cache = {"off": "off", "cold": str(work / "cold"), "warm": warm, "before": str(work / "before")}[mode]
            best[i] = min(best[i], first_trial(code, camp, cache, work))
    print(f"# Campaign start-up — {date.today()}, {cpu_name()}, {os.cpu_count()} cores, best of {args.rounds}\n")
    print("| code | campaign | disk cache | first trial starts after [s] |")
    print("|---|---|---|---|")
    for i, (code_name, _, name, _, mode) in enumerate(rows):
        print(f"| {code_name} | {name} | {'(none)' if mode == 'before' else mode} | {best[i]:.2f} |")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
