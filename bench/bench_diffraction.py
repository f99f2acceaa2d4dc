"""Pile diffraction timing: the scattered-wave Froude–Krylov correction X_s of a hull near a monopile.

Run: ``python bench/bench_diffraction.py`` (from the repo root). Prints a Markdown table (machine,
date); figures go to bench/README.md by hand. Goal (issue 9): 1,500 panels × 100 ω × 8 directions
in < 2 s after warm-up.
"""

from __future__ import annotations

import datetime
import os
import platform

import numpy as np

from boatland.hydro.builtin import load_builtin
from boatland.vessel.wigley import PanelCounts, WigleyCatamaran
from boatland.vessel.database import HydroDB
from boatland.sea.pile import pile_scattered_excitation
from boatland.waves.diffraction import cylinder_field
from _timing import best_of, cpu_name




def goal_db() -> HydroDB:
    """CTV-like catamaran with 1,512 wetted panels, 100 ω (0.05–5 rad/s), 8 directions."""
    hull = WigleyCatamaran(length=24.0, demihull_beam=2.8, draft=1.4, separation=6.2, p=2.156)
    mesh = hull.mesh(PanelCounts(n_half_length=27, n_girth=7, n_lid=4))
    nf, nb = 100, 8
    z6 = np.zeros((6, 6, nf))
    return HydroDB(omega=np.linspace(0.05, 5.0, nf), A=z6, B=z6, X=np.zeros((6, nb, nf), complex),
                   wave_dir_deg=np.arange(nb) * 45.0, C=np.zeros((6, 6)), mesh=mesh, name="bench")


def main():
    a = 3.25  # 6.5 m monopile
    pos, psi = (-(a + 1.0 + 12.0), 0.0), 0.0
    rows = []
    db = goal_db()
    t, Xs = best_of(lambda: pile_scattered_excitation(db, pos, psi, a), n=5)
    rows.append((f"X_s, {db.mesh.n_panels} panels × {db.n_freq} ω × {db.n_dir} β, deep water (goal < 2 s)", t))
    t, _ = best_of(lambda: pile_scattered_excitation(db, pos, psi, a, water_depth=25.0), n=5)
    rows.append(("same, h = 25 m", t))
    ctv = load_builtin("ctv24")
    t, _ = best_of(lambda: pile_scattered_excitation(ctv, pos, psi, a), n=2)
    rows.append((f"X_s, ctv24: {ctv.mesh.n_panels} panels × {ctv.n_freq} ω × {ctv.n_dir} β", t))
    g = np.linspace(-60, 60, 241)
    X, Y = np.meshgrid(g, g)
    t, _ = best_of(lambda: cylinder_field(X.ravel(), Y.ravel(), np.zeros(X.size), [1.2], [0.0], a), n=5)
    rows.append((f"surface elevation on a {X.size:,}-point grid, one ω and β", t))

    print(f"Machine: {cpu_name()}, {os.cpu_count()} CPU, Python {platform.python_version()}; "
          f"{datetime.date.today().isoformat()}\n")
    print("| case | time [s] |\n|---|---|")
    for name, t in rows:
        print(f"| {name} | {t:.3f} |")


if __name__ == "__main__":
    main()
