"""Logging overhead of the recording sinks (issue 6): the default trial alone, with the MCAP log, and
with MCAP + Rerun .rrd, wall time of the whole ``simulate`` call (median of ``--repeat`` runs).

    python bench/bench_record.py [--duration 1800] [--repeat 5] [--kinds none,mcap]

Also reports the time spent inside the sinks (on the main thread, overlapping the kernel's worker thread)
and the file sizes. Figures are quoted in bench/README.md.
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path

from boatland.record.mcap_log import McapLog
from boatland.checks.files import default_scenario_path, load_checked
from boatland.trial.simulate import simulate
from boatland.landing.setup import Setup


class Timed:
    """Wraps a sink and adds up the time spent in its calls."""

    def __init__(self, sink):
        self.sink, self.busy = sink, 0.0  # CPU time of the calling thread

    def __getattr__(self, name):
        fn = getattr(self.sink, name)

        def call(*a):
            t0 = time.thread_time()
            try:
                return fn(*a)
            finally:
                self.busy += time.thread_time() - t0
        return call


class NullSink:
    def start(self, info):
        pass

    def steps(self, block):
        pass

    def finish(self, result):
        pass


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", type=float, default=1800.0)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--kinds", default="none,null sink,mcap,mcap+rrd",
                    help="comma-separated cases to run (default: all four; 'none' is the reference)")
    args = ap.parse_args()
    scenario, db, _ = load_checked(default_scenario_path())
    scenario = scenario.replace({"simulation.duration": args.duration})
    tmp = Path(tempfile.mkdtemp())
    simulate(scenario.replace({"simulation.duration": 30.0}), db, sinks=[McapLog(tmp / "warm.mcap")])  # compile

    def mk(kind):
        if kind == "none":
            return []
        if kind == "null sink":           # the sink machinery of simulate alone (watcher thread, blocks)
            return [Timed(NullSink())]
        sinks = [Timed(McapLog(tmp / "run.mcap"))]
        if kind == "mcap+rrd":
            from boatland.record.rerun_log import RerunLog
            sinks.append(Timed(RerunLog(f"save={tmp / 'run.rrd'}")))
        return sinks

    n = Setup.of(scenario, db).n_steps
    print(f"default trial, {args.duration:g} s simulated, {n} steps; {os.cpu_count()} CPUs; "
          f"load average before {os.getloadavg()[0]:.2f}")
    kinds = tuple(k.strip() for k in args.kinds.split(","))
    if kinds[0] != "none" or not set(kinds) <= {"none", "null sink", "mcap", "mcap+rrd"}:
        ap.error("--kinds: 'none' first, then any of 'null sink', 'mcap', 'mcap+rrd'")
    walls: dict = {k: [] for k in kinds}
    busy: dict = {k: [] for k in kinds}
    for _ in range(args.repeat):          # interleaved, so that a change of machine load hits all three
        for kind in kinds:
            sinks = mk(kind)
            t0 = time.perf_counter()
            simulate(scenario, db, sinks=sinks)
            walls[kind].append(time.perf_counter() - t0)
            busy[kind].append(sum(s.busy for s in sinks))
    base_med, base_min = statistics.median(walls["none"]), min(walls["none"])
    for kind in kinds:
        med, lo = statistics.median(walls[kind]), min(walls[kind])
        sizes = ""
        if kind.startswith("mcap"):
            sizes = f"  mcap {os.path.getsize(tmp / 'run.mcap') / 1e6:.1f} MB"
            if kind == "mcap+rrd":
                sizes += f"  rrd {os.path.getsize(tmp / 'run.rrd') / 1e6:.1f} MB"
        cpu = statistics.median(busy[kind])
        print(f"{kind:10s} wall median {med:6.3f} s ({100 * (med / base_med - 1):+5.1f} %)  min {lo:6.3f} s "
              f"({100 * (lo / base_min - 1):+5.1f} %)  sink CPU {cpu:.3f} s = {1e6 * cpu / n:.1f} µs/step{sizes}")
    print(f"load average after {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
