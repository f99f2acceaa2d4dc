"""Text table and figure of a vessel's radiation memory (``boatland irf``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from boatland.irf.impulse import pair_name
from boatland.irf.statespace import frequency_response
from boatland.vessel.database import HydroDB
from boatland.vessel.radiation import RadiationMemory

__all__ = ["irf_table", "irf_summary", "plot_irf", "figure_irf"]


def _pairs(memory):
    sig = memory.irf.significant
    return [(i, j) for i in range(6) for j in range(i, 6) if sig[i, j]]


def irf_summary(memory: RadiationMemory) -> dict:
    """JSON-able figures per significant pair (upper triangle) and the settings."""
    irf, ss = memory.irf, memory.state_space
    rows = []
    for i, j in _pairs(memory):
        row = {"pair": pair_name(i, j), "i": i, "j": j, "err_B": irf.err_B[i, j], "err_A": irf.err_A[i, j],
               "truncation": irf.truncation[i, j], "ogilvie_spread": irf.ogilvie_spread[i, j]}
        if ss is not None and (i, j) in ss.pairs:
            fit = ss.pairs[(i, j)]
            row.update(order=fit.order, r2=fit.r2, stable=fit.stable,
                       passivity=None if np.isnan(ss.passivity[i, j]) else float(ss.passivity[i, j]))
        rows.append({k: (float(v) if isinstance(v, (np.floating, float)) else v) for k, v in row.items()})
    return {"settings": irf.settings.__dict__, "t_max": float(irf.t[-1]), "dt": float(irf.t[1] - irf.t[0]),
            "A_inf_source": irf.A_inf_source, "omega_max_used": irf.omega_max_used,
            "check_band": list(irf.check_band), "pairs": rows, "notes": list(irf.notes),
            "state_space_notes": [] if ss is None else list(ss.notes),
            "n_states": None if ss is None else ss.n_states}


def irf_table(memory: RadiationMemory) -> str:
    """The per-pair consistency and fit table for a terminal."""
    s = irf_summary(memory)
    st = s["settings"]
    lines = [f"IRF: T_K = {s['t_max']:g} s, Δt_K = {s['dt']:g} s, tail {st['tail']}, taper {st['taper']}, "
             f"clean {st['clean']}, highest ω used {s['omega_max_used']:.3g} rad/s; A∞ from the "
             f"{s['A_inf_source']}",
             f"round trip over {s['check_band'][0]:.3g}–{s['check_band'][1]:.3g} rad/s (relative L2):",
             f"  {'pair':14s} {'B err':>8s} {'A err':>8s} {'K(T_K)':>8s} {'A∞ spread':>9s}"
             + (f" {'order':>5s} {'R²':>9s} {'passive':>8s}" if memory.state_space is not None else "")]
    for r in s["pairs"]:
        line = (f"  {r['pair']:14s} {100 * r['err_B']:7.2f}% {100 * r['err_A']:7.2f}% "
                f"{100 * r['truncation']:7.2f}% {100 * r['ogilvie_spread']:8.2f}%")
        if "order" in r:
            pas = "–" if r["passivity"] is None else ("yes" if r["passivity"] >= -0.01 else f"{100 * r['passivity']:.1f}%")
            line += f" {r['order']:5d} {r['r2']:9.6f} {pas:>8s}"
        lines.append(line)
    if s["n_states"] is not None:
        lines.append(f"state space: {s['n_states']} states in all, every pole in the left half-plane")
    for n in s["notes"] + s["state_space_notes"]:
        lines.append(f"  note: {n}")
    return "\n".join(lines)


def _units(i: int) -> tuple[str, str, str]:
    """Units of K, B and A of the diagonal pair (i, i): translation or rotation."""
    if i < 3:
        return "N/m", "N s/m", "kg"
    return "N m/rad", "N m s/rad", "kg m²/rad"


def plot_irf(db: HydroDB, memory: RadiationMemory, path: str | Path) -> Path:
    """Save :func:`figure_irf` to ``path``."""
    from boatland.plotstyle import save_figure

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    return save_figure(figure_irf(db, memory), path)


def figure_irf(db: HydroDB, memory: RadiationMemory):
    """Figure: K(t) of the coupled pairs; B and A reconstructed from K (and the fit) against the input,
    one row per DOF with its units; the title names the database and the memory's settings."""
    from boatland.irf.quadrature import cos_transform, sin_transform
    from boatland.plotstyle import pyplot

    plt = pyplot()
    irf, ss = memory.irf, memory.state_space
    pairs = _pairs(memory)
    diag = [p for p in pairs if p[0] == p[1]]
    fig, axes = plt.subplots(len(diag), 3, figsize=(13, 2.5 * len(diag) + 0.6), squeeze=False)
    w = db.omega
    for row, (i, _) in enumerate(diag):
        ax_k, ax_b, ax_a = axes[row]
        uk, ub, ua = _units(i)
        ax_k.plot(irf.t, irf.K[i, i], lw=1.2, label=f"K {pair_name(i, i)}")
        for (a, b) in pairs:
            if a != b and i in (a, b) and a == min(a, b) and a == i:
                unit = _units(a)[0] if (a < 3) == (b < 3) else ("N/rad" if a < 3 else "N")
                ax_k.plot(irf.t, irf.K[a, b], lw=0.9, ls="--", label=f"K {pair_name(a, b)} (coupling) [{unit}]")
        ax_k.set_ylabel(f"{pair_name(i, i)}\nK [{uk}]")
        ax_k.legend(fontsize=7, loc="upper right")
        ax_b.plot(w, db.B[i, i], "k", lw=1.5, label="B input")
        ax_b.plot(w, cos_transform(irf.t, irf.K[i, i], w), "C1--", lw=1.2, label="from K")
        ax_b.set_ylabel(f"B [{ub}]")
        ax_a.plot(w, db.A[i, i], "k", lw=1.5, label="A input")
        ax_a.plot(w, irf.A_inf[i, i] - sin_transform(irf.t, irf.K[i, i], w) / w, "C1--", lw=1.2, label="from K")
        ax_a.axhline(irf.A_inf[i, i], color="0.6", lw=0.8, ls=":", label="A∞")
        ax_a.set_ylabel(f"A [{ua}]")
        if ss is not None and (i, i) in ss.pairs:
            fit = ss.pairs[(i, i)]
            H = frequency_response(fit, w)
            ax_b.plot(w, H.real, "C2:", lw=1.2, label=f"state space (order {fit.order}, R² {fit.r2:.6f})")
            ax_a.plot(w, irf.A_inf[i, i] + H.imag / w, "C2:", lw=1.2, label="state space")
        ax_b.legend(fontsize=7)
        ax_a.legend(fontsize=7)
        for a in (ax_k, ax_b, ax_a):
            a.grid(alpha=0.3)
    axes[0, 0].set_title("impulse response K(t)")
    axes[0, 1].set_title("damping B(ω)")
    axes[0, 2].set_title("added mass A(ω)")
    axes[-1, 0].set_xlabel("t [s]")
    axes[-1, 1].set_xlabel("ω [rad/s]")
    axes[-1, 2].set_xlabel("ω [rad/s]")
    st = irf.settings
    fig.suptitle(f"{db.name}: radiation memory — T_K = {irf.t[-1]:g} s, Δt_K = {irf.t[1] - irf.t[0]:g} s, tail "
                 f"{st.tail}, taper {st.taper}; A∞ from the {irf.A_inf_source}", fontsize=10)
    fig.tight_layout()
    return fig
