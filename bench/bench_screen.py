"""Screening timings: the limiting-Hs table of Wu's frequency-domain method for 32 Tp × 8 directions.

Run: ``python bench/bench_screen.py`` (from the repo root). Prints a Markdown table (machine, date);
figures go to bench/README.md by hand. Goal (issue 8): a limiting-Hs table for 32 Tp × 8 directions
in < 2 s — everything from the hydrodynamic database on: hinged RAO (600 frequencies × 8 directions,
with the static preload), slip margins, spectral moments (32 JONSWAP spectra), vectorised bisection.
"""

from __future__ import annotations

import datetime
import os
import platform
import warnings

import numpy as np

from boatland.freqdomain import LandingSetup, limiting_hs, screening_grid, slip_transfer, spectral_moments
from boatland.checks.files import default_scenario_path, load_checked
from _timing import best_of, cpu_name




def main():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(default_scenario_path())
    setup = LandingSetup.from_scenario(scenario, db)
    Tp = np.linspace(3.0, 18.0, 32)
    beta = np.arange(8) * 45.0
    print(f"{datetime.date.today()}, {cpu_name()}, {os.cpu_count()} CPUs, Python {platform.python_version()}, "
          f"numpy {np.__version__}; {scenario.name} ({db.name}, {len(setup.points)} contacts), "
          f"{Tp.size} Tp × {beta.size} directions, 600 frequencies; best of 5 after warm-up\n")
    print("| method | statistics | whole table [s] | of which RAO + margins [s] | moments [s] | limits [s] | "
          "min / max limiting Hs [m] |")
    print("|---|---|---|---|---|---|---|")
    for method in ("improved", "wu"):
        t_tr, tr = best_of(lambda: slip_transfer(db, setup, beta_deg=beta, method=method))
        t_m, (m, _) = best_of(lambda: spectral_moments(tr, Tp))
        for statistics in ("rayleigh", "rice", "vanmarcke"):
            t_all, tab = best_of(lambda: screening_grid(db, setup, Tp, beta, statistics=statistics, method=method))
            t_lim, _ = best_of(lambda: limiting_hs(m, tr.capacity, Tp, beta, statistics=statistics))
            print(f"| {method} | {statistics} | {t_all:.3f} | {t_tr:.3f} | {t_m:.4f} | {t_lim:.4f} | "
                  f"{np.min(tab.Hs):.3f} / {np.max(tab.Hs):.3f} |")


if __name__ == "__main__":
    main()
