"""The kernel with the loads beside the waves: µs per RK4 step of the default trial (ctv27, state space, 30 min
of JONSWAP Hs 0.4 m head seas) with a current, a wind, the wave drift and the skipper's controller, one at a
time and all four — side by side with another checkout of the code (``--before``: the same trial, waves only,
in that code), round-robin in one run.

Run: ``python bench/bench_loads.py [--before CHECKOUT] [--rounds 5]``. Each row runs in its own process per
round (numba cached, one thread), the trial twice there and its best kept; "kernel" is the time inside
:meth:`MotionArrays.run` (the RK4 loop), "simulate" the whole call (waves, gusts, drift series, kernel, events).
Prints Markdown; the rows' medians over the rounds.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

#: Rows: label → scenario changes (the loads), in this code.
ROWS = {
    "waves only": {},
    "current 1 m/s beam": {"current": {"speed": 1.0, "relative_direction_deg": 90.0}},
    "wind 20 kn beam, gusts": {"wind": {"speed": 10.3, "relative_direction_deg": 90.0}},
    "drift (Newman)": {"sea.drift": "newman"},
    "skipper (hold force)": {"thrust.control": {"kind": "hold_force"}},
    "current, wind and skipper": {"current": {"speed": 1.0, "relative_direction_deg": 90.0},
                                  "wind": {"speed": 10.3, "relative_direction_deg": 90.0},
                                  "thrust.control": {"kind": "hold_force"}},
    "all four": {"current": {"speed": 1.0, "relative_direction_deg": 90.0},
                 "wind": {"speed": 10.3, "relative_direction_deg": 90.0}, "sea.drift": "newman",
                 "thrust.control": {"kind": "hold_force"}},
}

WORKER = r"""
import json, sys, time, warnings
warnings.simplefilter("ignore")
import numba
numba.set_num_threads(1)
from boatland.checks.files import load
from boatland.hydro.read import load_database
from boatland.resources import shipped_scenarios
from boatland.trial import motion
from boatland.trial.simulate import simulate
changes = json.loads(sys.argv[1])
sc = load(shipped_scenarios() / "ctv_landing.toml").replace({"simulation.duration": 1800.0, **changes})
db = load_database("ctv27")
if changes.get("sea.drift", "none") != "none" and getattr(db, "drift", None) is None:
    print(json.dumps(None)); sys.exit(0)
inner = []
run = motion.MotionArrays.run
def timed(self, *a, **k):
    t0 = time.perf_counter(); out = run(self, *a, **k); inner.append(time.perf_counter() - t0); return out
motion.MotionArrays.run = timed
from boatland.landing.setup import Setup
from boatland.trial.simulate import motion_arrays
setup = Setup.of(sc, db)
arr = motion_arrays(setup, setup.memory())
best_k = best_s = float("inf")
for _ in range(3):
    inner.clear()
    t0 = time.perf_counter(); simulate(sc, db, arrays=arr, setup=setup); best_s = min(best_s, time.perf_counter() - t0)
    best_k = min(best_k, inner[-1])
print(json.dumps({"kernel": best_k / setup.n_steps * 1e6, "simulate": best_s, "steps": setup.n_steps}))
"""


def measure(code: Path, changes: dict):
    env = {**os.environ, "PYTHONPATH": str(code), "NUMBA_NUM_THREADS": "1", "OMP_NUM_THREADS": "1",
           "OPENBLAS_NUM_THREADS": "1"}
    r = subprocess.run([sys.executable, "-c", WORKER, json.dumps(changes)], capture_output=True, text=True, env=env,
                       cwd=code, timeout=1800)
    if r.returncode != 0:
        raise RuntimeError(r.stderr[-2000:])
    return json.loads(r.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--before", type=Path, metavar="CHECKOUT", help="another checkout: its waves-only row beside ours")
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    rows = [("this", REPO, label, ch) for label, ch in ROWS.items()]
    if args.before:
        rows.insert(0, (f"before: {args.before.name}", args.before.resolve(), "waves only", {}))
    for code, path, _, ch in rows:                       # warm-up: compile or load numba's cache
        measure(path, ch)
    got = {i: [] for i in range(len(rows))}
    for _ in range(args.rounds):
        for i, (_, path, _, ch) in enumerate(rows):
            got[i].append(measure(path, ch))
    import numba

    print(f"# {platform.machine()}, Python {platform.python_version()}, numba {numba.__version__}, one core; "
          f"ctv_landing 1800 s (36,000 steps at 0.05 s), state space; median of {args.rounds} rounds of best-of-3\n")
    print("| code | loads | kernel µs/step | steps/s | vs waves only (this code) | simulate [s] |")
    print("|---|---|---|---|---|---|")
    base = None
    for i, (code, _, label, _) in enumerate(rows):
        if got[i][0] is None:
            print(f"| {code} | {label} | – (the database has no drift coefficients) | | | |")
            continue
        k = statistics.median(g["kernel"] for g in got[i])
        s = statistics.median(g["simulate"] for g in got[i])
        if code == "this" and label == "waves only":
            base = k
        rel = f"{(k / base - 1) * 100:+.1f} %" if base and code == "this" else ""
        print(f"| {code} | {label} | {k:.2f} | {1e6 / k:,.0f} | {rel} | {s:.3f} |")


if __name__ == "__main__":
    main()
