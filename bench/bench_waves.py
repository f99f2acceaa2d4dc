"""Wave timings: realisation, elevation and the excitation force series on the RK4 grid.

Run: ``python bench/bench_waves.py`` (from the repo root). Prints a Markdown table (machine, date);
figures go to bench/README.md by hand. Goal (issue 4): a 30-min excitation series at dt = 0.05 s
(72 001 times with the RK4 half steps), 512 components, 6 DOF in < 0.2 s after warm-up.
"""

from __future__ import annotations

import datetime
import math
import os
import platform

import numpy as np

from boatland.hydro.builtin import load_builtin
from boatland.model.seastate import SeaState, SpectrumPart, excitation_table, wave_excitation
from boatland.waves.excitation import excitation_series
from boatland.waves.realisation import Components
from boatland.waves.synthesis import elevation_series
from _timing import best_of, cpu_name





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

    print(f"# {cpu_name()}, {os.cpu_count()} CPU, Python {platform.python_version()}, numpy {np.__version__}, "
          f"{datetime.date.today().isoformat()} (best of 5 after warm-up)")
    print()
    print("| case (30 min, dt = 0.05 s → 72 001 times incl. RK4 half steps) | components | time [ms] |")
    print("|---|---|---|")
    print(f"| excitation series, 6 DOF, ctv24 X(ω, β) (goal < 200 ms) | {N} | {1e3 * t_exc:.1f} |")
    print(f"| JONSWAP realisation (Hs 1.5 m, Tp 7 s, s = 10), non-repetition rule | {c.size} | {1e3 * t_real:.2f} |")
    print(f"| elevation at one point | {c.size} | {1e3 * t_eta:.1f} |")
    print(f"| realisation + excitation series (`wave_excitation`) | {c.size} | {1e3 * t_full:.1f} |")


if __name__ == "__main__":
    main()
