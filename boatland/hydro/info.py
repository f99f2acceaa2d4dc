"""A readable summary of a hydrodynamic database (``boatland hydro info``)."""

from __future__ import annotations

import numpy as np

from boatland.vessel.database import HydroDB
from boatland.vessel.directions import direction_coverage

__all__ = ["summary", "summary_text"]


def summary(db: HydroDB) -> dict:
    """Key facts of ``db`` as plain JSON-able data.

    Returns
    -------
    dict
        name, solver, source, frequency band and count, directions and their coverage
        (:func:`boatland.vessel.directions.direction_coverage`: kind and text), depth, ρ, g, mass, volume,
        centre of gravity, A∞/A₀ availability, heave/roll/pitch natural periods (s, None where not
        defined), panel count, whether it has mean drift coefficients, and the warnings of
        :meth:`HydroDB.diagnostics`.
    """
    w = db.omega
    beta = db.wave_dir_deg
    steps = np.unique(np.round(np.diff(beta), 6)) if beta.size > 1 else np.array([])
    coverage = direction_coverage(db)
    return {
        "name": db.name,
        "solver": db.provenance.solver,
        "source": db.provenance.source,
        "reader": db.provenance.reader,
        "created": db.provenance.created,
        "n_freq": db.n_freq,
        "omega_min": float(w[0]),
        "omega_max": float(w[-1]),
        "d_omega_max": float(np.max(np.diff(w))),
        "n_dir": db.n_dir,
        "wave_dir_deg": [float(b) for b in beta],
        "dir_step_deg": float(steps[0]) if steps.size == 1 else None,
        "dir_coverage": {"kind": coverage.kind, "text": coverage.case},
        "water_depth": None if np.isinf(db.water_depth) else db.water_depth,
        "rho": db.rho,
        "g": db.g,
        "mass": db.mass,
        "disp_vol": db.disp_vol,
        "cog": [float(c) for c in db.cog],
        "ref_point": [float(c) for c in db.ref_point],
        "has_A_inf": db.A_inf is not None,
        "has_A_0": db.A_0 is not None,
        "natural_periods": db.natural_periods(),
        "n_panels": None if db.mesh is None else db.mesh.n_panels,
        "has_drift": db.drift is not None,
        "warnings": db.diagnostics(),
    }


def summary_text(db: HydroDB) -> str:
    """:func:`summary` laid out for a terminal."""
    s = summary(db)
    w0, w1 = s["omega_min"], s["omega_max"]
    beta = s["wave_dir_deg"]
    if s["dir_step_deg"] is not None and len(beta) > 2:
        dirs = f"{len(beta)} from {beta[0]:g}° to {beta[-1]:g}° every {s['dir_step_deg']:g}°"
    else:
        dirs = f"{len(beta)}: " + ", ".join(f"{b:g}°" for b in beta)
    depth = "infinite" if s["water_depth"] is None else f"{s['water_depth']:g} m"
    mass = "unknown" if s["mass"] is None else f"{s['mass'] / 1000:.4g} t"
    periods = "  ".join(f"{k} {v:.2f} s" if v is not None else f"{k} –" for k, v in s["natural_periods"].items())
    lines = [
        f"{s['name']} — {s['solver'] or 'unknown solver'} database",
        f"  source          {s['source']}  (read by {s['reader']}{', ' + s['created'] if s['created'] else ''})",
        f"  frequencies     {s['n_freq']} from {w0:.4g} to {w1:.4g} rad/s (largest step {s['d_omega_max']:.3g} rad/s; "
        f"periods {2 * np.pi / w1:.3g}–{2 * np.pi / w0:.4g} s)",
        f"  directions      {dirs}",
        f"  coverage        {s['dir_coverage']['text']}",
        f"  water           depth {depth}, ρ {s['rho']:g} kg/m³, g {s['g']:g} m/s²",
        f"  mass            {mass}, displaced volume {s['disp_vol']:.4g} m³, "
        f"CoG ({', '.join(f'{c:.3g}' for c in s['cog'])}) m",
        f"  A∞ / A₀         {'from the solver' if s['has_A_inf'] else 'missing'} / "
        f"{'from the solver' if s['has_A_0'] else 'missing'}",
        f"  natural periods {periods}  (uncoupled, from M, A(ω), C)",
    ]
    if s["n_panels"] is not None:
        lines.append(f"  hull mesh       {s['n_panels']} panels")
    if s["has_drift"]:
        how = next((n[len("mean drift:"):].strip() for n in reversed(db.provenance.notes)
                    if n.startswith("mean drift:")), "source not noted")
        lines.append(f"  mean drift      {how[:100]}{'…' if len(how) > 100 else ''}")
    else:
        lines.append("  mean drift      none")
    if s["warnings"]:
        lines.append("warnings:")
        lines.extend(f"  - {w}" for w in s["warnings"])
    return "\n".join(lines)
