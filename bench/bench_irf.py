"""Radiation memory timings: IRFs (all 36 pairs) + state-space fit for the built-in vessels.

Run: ``python bench/bench_irf.py``. Goal (issue 3): IRFs + fit of the CTV database < 1 s.
Prints a Markdown table; copy it to bench/README.md with the machine and date.
"""

from __future__ import annotations

from _timing import best_of

import platform

from boatland.hydro.builtin import load_builtin
from boatland.vessel.radiation import radiation_memory



def main():
    print(f"# {platform.machine()}, Python {platform.python_version()}")
    print("| vessel | ω × pairs | K(t) samples | IRF [s] | IRF + state space [s] | states |")
    print("|---|---|---|---|---|---|")
    for name in ("ctv24", "model2"):
        db = load_builtin(name)
        t_irf, mem = best_of(lambda: radiation_memory(db, fit=False))
        t_all, mem = best_of(lambda: radiation_memory(db))
        print(f"| {name} | {db.n_freq} × {int(mem.irf.significant.sum())} | {mem.irf.t.size} | {t_irf:.3f} | "
              f"{t_all:.3f} | {mem.state_space.n_states} |")


if __name__ == "__main__":
    main()
