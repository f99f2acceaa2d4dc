"""Heave and pitch RAOs of the default CTV (ctv27: transom stern, hard chine) beside the Wigley ctv24,
and the vertical force each needs at its bow fender when landed.

Rerun from the source checkout (writes docs/rao_ctv27_vs_ctv24.png and prints the table it draws)::

    python docs/rao_ctv27_vs_ctv24.py

Free RAOs: :func:`boatland.freqdomain.free_rao` of the built-in databases in the open sea, head
(180°) and bow-quartering (135°) seas. Landed: each vessel in its own landing scenario
(scenarios/ctv_landing.toml for ctv27 at 150 kN, scenarios/ctv24_landing.toml for ctv24 at 80 kN), the
time domain's contacts beside the pile (:func:`boatland.freqdomain.screening.landed_response`): the
vertical force of the more loaded contact per metre of wave amplitude, and the same over the contact's
friction capacity μ_s F_b / 2 (the share of the grip one metre of wave amplitude uses).
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from boatland.freqdomain import LandingSetup, free_rao  # noqa: E402
from boatland.freqdomain.screening import landed_response  # noqa: E402
from boatland.checks.files import load_checked  # noqa: E402
from boatland.plotstyle import save_figure  # noqa: E402

T = np.linspace(3.0, 15.0, 121)
W = 2 * np.pi / T
VESSELS = (("ctv27 (transom, hard chine)", "ctv_landing.toml", "C0"),
           ("ctv24 (Wigley)", "ctv24_landing.toml", "C1"))


def curves(scenario_file: str):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(ROOT / "scenarios" / scenario_file)
    setup = LandingSetup.from_scenario(scenario, db)
    out = {"db": db, "scenario": scenario}
    for beta in (180.0, 135.0):
        x = free_rao(db, W, beta)[:, 0]
        out[f"heave {beta:g}"] = np.abs(x[:, 2])
        out[f"pitch {beta:g}"] = np.degrees(np.abs(x[:, 4]))
    h = landed_response(db, setup, W, [180.0])
    F = h.contact_components()[:, 0]                 # (Nw, Np, 3): normal, vertical, horizontal
    fz = np.abs(F[:, :, 1]).max(axis=1)
    out["vertical kN"] = fz / 1e3
    capacity = scenario.fender.mu_s * scenario.thrust.force / len(scenario.fender.points)
    out["vertical / capacity"] = fz / capacity
    return out


def main(path: Path = ROOT / "docs" / "rao_ctv27_vs_ctv24.png") -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = [(label, color, curves(f)) for label, f, color in VESSELS]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    for label, color, c in data:
        for beta, ls in ((180.0, "-"), (135.0, "--")):
            ax[0].plot(T, c[f"heave {beta:g}"], ls, color=color, label=f"{label}, {beta:g}°")
            ax[1].plot(T, c[f"pitch {beta:g}"], ls, color=color, label=f"{label}, {beta:g}°")
        sc = c["scenario"]
        ax[2].plot(T, c["vertical kN"], color=color,
                   label=f"{label}: {sc.thrust.force / 1e3:g} kN, μ_s {sc.fender.mu_s:g}")
    ax[0].set(xlabel="wave period T [s]", ylabel="heave / wave amplitude [m/m]", title="free heave RAO")
    ax[1].set(xlabel="wave period T [s]", ylabel="pitch / wave amplitude [deg/m]", title="free pitch RAO")
    ax[2].set(xlabel="wave period T [s]", ylabel="vertical contact force [kN per m of amplitude]",
              title="landed: vertical force at the fender, head seas")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle("Default CTV (ctv27) vs the Wigley ctv24 — open sea RAOs; landed beside the pile in each "
                 "vessel's own landing scenario (ctv_landing, ctv24_landing)", fontsize=10)
    fig.tight_layout()
    save_figure(fig, path)
    print(f"wrote {path}")
    print(f"{'T [s]':>6} " + " ".join(f"{lab.split()[0] + ' ' + k:>22}" for lab, _, _ in data
                                     for k in ("heave180", "pitch180", "Fz kN/m", "Fz/cap")))
    for t in (5.0, 6.0, 7.0, 8.0, 10.0, 12.0):
        i = int(np.argmin(np.abs(T - t)))
        row = []
        for _, _, c in data:
            row += [c["heave 180"][i], c["pitch 180"][i], c["vertical kN"][i], c["vertical / capacity"][i]]
        print(f"{t:6.1f} " + " ".join(f"{v:22.3f}" for v in row))


if __name__ == "__main__":
    main()
