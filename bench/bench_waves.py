"""Wave timings: realisation, elevation and the excitation force series on the RK4 grid.

Run: ``python bench/bench_waves.py`` (from the repo root; ``--quick`` skips the 10 000 s trials).
Prints Markdown tables (machine, date); figures go to bench/README.md by hand.

1. Goal (issue 4): a 30-min excitation series at dt = 0.05 s (72 001 times with the RK4 half
   steps), 512 components, 6 DOF in < 0.2 s after warm-up.
2. Issue 16: the synthesis cost per simulated second, direct sum against the NUFFT, for 600 s,
   1 800 s and 10 000 s accesses of the default sea (2 n + 1 half steps of dt = 0.05 s, 6 outputs),
   timed side by side in one run; the measured crossover in N against the rule of
   :func:`boatland.waves.synthesis.synthesis_method`; and the full trial of the default scenario
   (state-space radiation) at 600 s and 10 000 s before (direct sum) and after (automatic choice).
"""

from __future__ import annotations

import datetime
import math
import os
import platform
import sys
import time

import numpy as np

from boatland.hydro.builtin import load_builtin
from boatland.sea.spectra import SpectrumPart
from boatland.sea.states import SeaState, excitation_table, wave_excitation
from boatland.waves.excitation import excitation_series
from boatland.waves.realisation import Components
import boatland.waves.excitation as excitation_module
from boatland.checks.files import default_scenario_path, load_checked
from boatland.trial.simulate import simulate
from boatland.waves.excitation import excitation_coefficients
from boatland.waves.synthesis import (elevation_series, harmonic_series, harmonic_sum, synthesis_costs,
                                      synthesis_method)
from _timing import best_of, cpu_name
from boatland.landing.setup import Setup

DT = 0.05


def timed(fn, repeats):
    """Shortest wall and shortest CPU (process) time [s] of ``repeats`` calls (no warm-up here: the
    caller has warmed up). The CPU time is the steadier figure on a shared machine."""
    wall = cpu = float("inf")
    for _ in range(repeats):
        w0, c0 = time.perf_counter(), time.process_time()
        fn()
        cpu = min(cpu, time.process_time() - c0)
        wall = min(wall, time.perf_counter() - w0)
    return np.array([wall, cpu])


def synthesis_table(scenario, db):
    """Direct sum against NUFFT for the default sea's excitation, 6 outputs, on the RK4 half steps."""
    waves = Setup.of(scenario, db).waves
    omega, beta, X = excitation_table(db)
    x0, y0, psi = scenario.start_pose()
    harmonic_series(np.array([1.0]), np.ones((6, 1)), 0.0, 0.1, 100, method="nufft")  # warm-up (compile)
    harmonic_sum(np.array([1.0]), np.ones((6, 1)), 0.0, 0.1, 100)
    print("| access [s] | components N | half steps n | direct wall / CPU [s] | NUFFT wall / CPU [s] "
          "| direct per sim. s [ms] (CPU) | NUFFT per sim. s [ms] (CPU) | speed-up (CPU) | auto picks "
          "| max abs. diff / RMS |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for duration in (600.0, 1800.0, 10_000.0):
        comps = waves.realise(scenario.simulation.seed, duration)
        c, _, _ = excitation_coefficients(comps, omega, beta, X, x0, y0, psi)
        n = 2 * int(round(duration / DT)) + 1
        rounds, direct_rounds = (5, 3) if duration < 5000 else (3, 1)
        t_d = t_f = np.full(2, np.inf)
        for r in range(rounds):                       # interleaved: both see the same machine phases
            if r < direct_rounds:
                t_d = np.minimum(t_d, timed(lambda: harmonic_series(comps.omega, c, 0.0, DT / 2, n, "direct"), 1))
            t_f = np.minimum(t_f, timed(lambda: harmonic_series(comps.omega, c, 0.0, DT / 2, n, "nufft"), 1))
        yd = harmonic_series(comps.omega, c, 0.0, DT / 2, n, "direct")
        yf = harmonic_series(comps.omega, c, 0.0, DT / 2, n, "nufft")
        err = np.max(np.max(np.abs(yf - yd), axis=0) / np.sqrt(np.mean(yd ** 2, axis=0)))
        print(f"| {duration:,.0f} | {comps.size:,} | {n:,} | {t_d[0]:.3f} / {t_d[1]:.3f} | {t_f[0]:.4f} / {t_f[1]:.4f} "
              f"| {1e3 * t_d[1] / duration:.3f} | {1e3 * t_f[1] / duration:.4f} | {t_d[1] / t_f[1]:.0f}× "
              f"| {synthesis_method(comps.size, n, 6)} | {err:.1e} |")


def crossover_table():
    """Smallest N (of a doubling ladder) at which the NUFFT is measured faster (CPU time), against the rule."""
    rng = np.random.default_rng(0)
    ladder = [4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096]
    print("| outputs m | times n | measured: NUFFT faster from N | rule: NUFFT from N |")
    print("|---|---|---|---|")
    for m in (1, 6):
        for n in (1_001, 10_001, 100_001):
            measured = "> 4096"
            for N in ladder:
                w = np.sort(rng.uniform(0.4, 2.8, N))
                c = rng.normal(size=(m, N)) + 1j * rng.normal(size=(m, N))
                td = tf = float("inf")
                for _ in range(5 if n * N * m < 5e7 else 2):
                    td = min(td, timed(lambda: harmonic_sum(w, c, 0.0, DT / 2, n), 1)[1])
                    tf = min(tf, timed(lambda: harmonic_series(w, c, 0.0, DT / 2, n, "nufft"), 1)[1])
                if tf < td:
                    measured = str(N)
                    break
            rule = next((N for N in range(1, 100_000) if synthesis_method(N, n, m) == "nufft"), None)
            print(f"| {m} | {n:,} | {measured} | {rule} |")


def trial_table(scenario, db, durations):
    """Whole ``simulate`` (state space, pile on) before (direct sum) and after (automatic choice)."""
    print("| duration [s] | steps | components | before: direct, wall / CPU [s] | after: auto, wall / CPU [s] "
          "| saved CPU [s] | speed-up (CPU) |")
    print("|---|---|---|---|---|---|---|")
    for duration in durations:
        sc = scenario.replace({"radiation.method": "state_space", "simulation.duration": duration})
        memory = Setup.of(sc, db).memory()
        n_comp = Setup.of(sc, db).waves.realise(sc.simulation.seed, duration).size
        simulate(sc, db, memory=memory)                                   # warm-up: pile table, compile
        before = after = np.full(2, np.inf)
        for _ in range(3 if duration < 5000 else 2):
            excitation_module.harmonic_series = lambda *a: harmonic_sum(*a)
            try:
                before = np.minimum(before, timed(lambda: simulate(sc, db, memory=memory), 1))
            finally:
                excitation_module.harmonic_series = harmonic_series
            after = np.minimum(after, timed(lambda: simulate(sc, db, memory=memory), 1))
        n = int(round(duration / DT))
        print(f"| {duration:,.0f} | {n:,} | {n_comp:,} | {before[0]:.2f} / {before[1]:.2f} | {after[0]:.2f} / "
              f"{after[1]:.2f} | {before[1] - after[1]:.2f} | {before[1] / after[1]:.1f}× |")


def main():
    duration, dt = 1800.0, 0.05
    n_steps = int(round(duration / dt))
    n_t = 2 * n_steps + 1
    db = load_builtin("ctv24")
    omega, beta, X = excitation_table(db)

    rng = np.random.default_rng(0)
    N = 512
    w = np.sort(rng.uniform(0.4, 3.9, N))
    comps = Components(w, w ** 2 / db.g, rng.uniform(0.0, 0.05, N), rng.uniform(0.0, 2 * math.pi, N),
                       rng.uniform(0.0, 2 * math.pi, N))
    t_exc = best_of(lambda: excitation_series(comps, omega, beta, X, 3.0, -2.0, 0.3, 0.0, 0.5 * dt, n_t, 14.0))[0]

    sea = SeaState(parts=SpectrumPart(Hs=1.5, Tp=7.0, spreading=10.0, direction_deg=180.0))
    t_real = best_of(lambda: sea.realise(1, duration))[0]
    c = sea.realise(1, duration)
    t_eta = best_of(lambda: elevation_series(c, 0.0, 0.0, 0.0, 0.5 * dt, n_t))[0]
    t_full = best_of(lambda: wave_excitation(sea.realise(1, duration), db, dt=dt, n_steps=n_steps,
                                             ramp_time=sea.default_ramp_time))[0]

    import numba
    import scipy

    print(f"# {cpu_name()}, {os.cpu_count()} CPU, Python {platform.python_version()}, numpy {np.__version__}, "
          f"scipy {scipy.__version__}, numba {numba.__version__}, {datetime.date.today().isoformat()}, "
          f"load average {os.getloadavg()[0]:.1f} at start (best of 5 after warm-up)")
    print()
    print("| case (30 min, dt = 0.05 s → 72 001 times incl. RK4 half steps) | components | time [ms] |")
    print("|---|---|---|")
    print(f"| excitation series, 6 DOF, ctv24 X(ω, β) (goal < 200 ms) | {N} | {1e3 * t_exc:.1f} |")
    print(f"| JONSWAP realisation (Hs 1.5 m, Tp 7 s, s = 10), non-repetition rule | {c.size} | {1e3 * t_real:.2f} |")
    print(f"| elevation at one point | {c.size} | {1e3 * t_eta:.1f} |")
    print(f"| realisation + excitation series (`wave_excitation`) | {c.size} | {1e3 * t_full:.1f} |")

    scenario, db_s, _ = load_checked(default_scenario_path())
    print("\nSynthesis of the default sea's excitation (6 outputs, RK4 half steps of dt = 0.05 s), "
          "direct sum against NUFFT\n")
    synthesis_table(scenario, db_s)
    print("\nCrossover (random ω in 0.4–2.8 rad/s, h = 0.025 s)\n")
    crossover_table()
    d, f = synthesis_costs(402, 24_001, 6)
    print(f"\n(cost estimate of the rule for the 600 s trial: direct {1e3 * d:.1f} ms, NUFFT {1e3 * f:.1f} ms)")
    print("\nWhole trial, default scenario, state-space radiation, pile diffraction on\n")
    trial_table(scenario, db_s, (600.0,) if "--quick" in sys.argv else (600.0, 10_000.0))
    print(f"\n(load average {os.getloadavg()[0]:.1f} at the end)")


if __name__ == "__main__":
    main()
