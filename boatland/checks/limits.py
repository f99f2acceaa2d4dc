r"""Limits on inputs that can only be mistakes, and on runs that cannot fit in memory.

The scenario's own validation (:mod:`boatland.scenario.scenario`) and its checks against the database
(:mod:`boatland.checks.physical`) refuse what is wrong in form or inconsistent. These limits
refuse what is well-formed but impossible for a crew transfer vessel at a boat landing, or beyond the
validity of the models, before any computation:

- :func:`document_problems` (the parsed TOML, before the scenario is built): every number finite
  (TOML accepts ``nan`` and ``inf``; only a water depth may be ``inf``), the wave seed a 64-bit
  non-negative integer.
- :func:`scenario_problems` (the scenario with its database):

  * fender points between the keel and :data:`FREEBOARD_FRACTION` of the hull length above the
    waterline (a CTV's bow fender sits at its gunwale, about 1.5–2.5 m up on a 20–27 m hull; the
    database stores the wetted hull only, so the deck height is bounded by this ratio);
  * the monopile no wider than :data:`MAX_PILE_DIAMETER` (the largest monopiles are about 11 m) and
    its MacCamy–Fuchs series short enough to sum (k·a ≤ :data:`MAX_KA` at the database's highest
    frequency);
  * wave heights below Miche's breaking limit at their (peak) wavelength,
    :math:`H k / 2\pi \le \tanh(kh)/7` — the linear (Airy) waves of the model do not exist past it;
  * the thrust below the vessel's weight (:data:`MAX_THRUST_PER_WEIGHT`; CTVs push 0.05–0.2 m g).

- :func:`run_bytes`: the memory a trial's time series take, for the edge to compare with the
  machine's (a run that cannot fit is refused with how to split it).

The edge (:mod:`boatland.checks.files`) calls these where it loads a scenario.
"""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from boatland.waves.dispersion import wavenumber_scalar

__all__ = ["document_problems", "scenario_problems", "run_bytes", "FREEBOARD_FRACTION", "MAX_PILE_DIAMETER",
           "MAX_KA", "MAX_THRUST_PER_WEIGHT", "BREAKING_STEEPNESS", "SEED_MAX", "BYTES_PER_STEP"]

#: Fender points may sit at most this fraction of the hull length above the waterline.
FREEBOARD_FRACTION = 0.15
#: [m] largest monopile diameter (XXL monopiles are about 11 m).
MAX_PILE_DIAMETER = 20.0
#: Largest k·a of the scattered-wave series at the database's highest frequency.
MAX_KA = 500.0
#: Largest bollard push as a multiple of the vessel's weight m g.
MAX_THRUST_PER_WEIGHT = 1.0
#: Miche's (1944) deep-water breaking steepness H/λ = 1/7 (× tanh kh in finite depth).
BREAKING_STEEPNESS = 1.0 / 7.0
#: Wave seeds are stored as signed 64-bit integers.
SEED_MAX = 2 ** 63 - 1
#: Approximate bytes per time step of a trial: outputs and their result copies (x, v, mode, forces,
#: contact positions for two contacts), excitation and thrust at the half steps, the run log's
#: per-block work arrays.
BYTES_PER_STEP = 1200

#: Keys whose value may be ``inf`` (deep water).
_INF_ALLOWED = ("water_depth",)


def document_problems(doc: Mapping[str, Any], prefix: str = "") -> list[tuple[str, str]]:
    """Problems of a parsed scenario document that no later check may trip over: non-finite numbers
    and an out-of-range wave seed. Returns ``(key path, message)`` pairs."""
    out: list[tuple[str, str]] = []

    def walk(value, key):
        if isinstance(value, bool):
            return
        if isinstance(value, float) and not math.isfinite(value):
            if not (math.isinf(value) and value > 0 and key.rsplit(".", 1)[-1] in _INF_ALLOWED):
                out.append((key, f"must be a finite number, got {value}"))
        elif isinstance(value, Mapping):
            for k, v in value.items():
                walk(v, f"{key}.{k}" if key else str(k))
        elif isinstance(value, (list, tuple)):
            for i, v in enumerate(value):
                walk(v, f"{key}[{i}]")

    walk(doc, prefix)
    sim = doc.get("simulation") if isinstance(doc, Mapping) else None
    seed = sim.get("seed") if isinstance(sim, Mapping) else None
    if isinstance(seed, int) and not isinstance(seed, bool) and not 0 <= seed <= SEED_MAX:
        out.append(("simulation.seed", f"must be a whole number in 0 … 2**63 − 1, got {seed}"))
    return out


def _hull(db) -> tuple[float, float] | None:
    """(length, draft) of the wetted hull mesh, or None without a mesh."""
    if db.mesh is None:
        return None
    v = np.asarray(db.mesh.vertices)
    return float(v[:, 0].max() - v[:, 0].min()), float(-v[:, 2].min())


def _breaking(what: str, H: float, omega: float, h: float, g: float, height: str) -> tuple[str, str] | None:
    k = wavenumber_scalar(omega, h, g)
    limit = BREAKING_STEEPNESS * (math.tanh(k * h) if math.isfinite(h) else 1.0)
    if H * k / (2 * math.pi) <= limit:
        return None
    H_max = limit * 2 * math.pi / k
    return (what, f"{height} {H:g} m at a wavelength of {2 * math.pi / k:.3g} m is past the breaking limit "
                  f"(Miche: H/λ ≤ tanh(kh)/7, here {height} ≤ {H_max:.3g} m); the model's linear waves do not "
                  "exist there")


def scenario_problems(scenario, db) -> list[tuple[str, str]]:
    """Problems of a scenario with its database that can only be mistakes (module docstring).

    Parameters
    ----------
    scenario : Scenario
    db : HydroDB

    Returns
    -------
    list of (str, str)
        ``(key path, message)``; empty when every limit holds.
    """
    out: list[tuple[str, str]] = []
    hull = _hull(db)
    if scenario.fender is not None and hull is not None:
        length, draft = hull
        top = FREEBOARD_FRACTION * length
        for i, p in enumerate(scenario.fender.points):
            z = float(p[2])
            if z < -draft:
                out.append((f"fender.points[{i}]", f"z = {z:g} m is below the keel of {db.name!r} (draft {draft:g} m)"))
            elif z > top:
                out.append((f"fender.points[{i}]", f"z = {z:g} m above the waterline is higher than the deck of a "
                                                   f"{length:.3g} m hull can be (at most {top:.3g} m = "
                                                   f"{FREEBOARD_FRACTION:g} × its length; CTV bow fenders sit at "
                                                   "the gunwale)"))
    g = float(db.g)
    depth = scenario.sea.water_depth if scenario.sea is not None and scenario.sea.water_depth is not None \
        else float(db.water_depth)
    land = scenario.landing
    if land is not None:
        D = float(land.monopile_diameter)
        if D > MAX_PILE_DIAMETER:
            out.append(("landing.monopile_diameter", f"{D:g} m is wider than any monopile (at most "
                                                     f"{MAX_PILE_DIAMETER:g} m; the largest are about 11 m)"))
        else:
            ka = wavenumber_scalar(float(db.omega[-1]), depth, g) * D / 2
            if ka > MAX_KA:
                out.append(("landing.monopile_diameter", f"{D:g} m gives k·a = {ka:.3g} at the database's highest "
                                                         f"frequency; the scattered-wave series is valid to k·a ≤ "
                                                         f"{MAX_KA:g}"))
    sea = scenario.sea
    if sea is not None:
        w = sea.waves
        parts = getattr(w, "parts", None)
        if parts:
            key = "sea" if len(parts) == 1 else "sea.parts[{}]"
            for i, p in enumerate(parts):
                h = depth if math.isfinite(depth) else math.inf
                prob = _breaking(f"{key.format(i)}.Hs", float(p.Hs), float(p.omega_p), h, g, "Hs")
                if prob:
                    out.append(prob)
        elif sea.kind == "regular":
            prob = _breaking("sea.H", float(w.H), 2 * math.pi / float(w.T), depth, g, "H")
            if prob:
                out.append(prob)
    if scenario.thrust is not None and db.M is not None:
        weight = float(db.M[0, 0]) * g
        F = float(scenario.thrust.force)
        if F > MAX_THRUST_PER_WEIGHT * weight:
            out.append(("thrust.force", f"{F:g} N is more than the vessel's weight m g = {weight:.4g} N; no "
                                        "propulsion pushes that (CTVs push 0.05–0.2 m g)"))
    return out


def run_bytes(n_steps: int, n_contacts: int = 2) -> int:
    """Approximate memory [bytes] of one trial's time series (:data:`BYTES_PER_STEP` scaled by the
    number of contacts)."""
    return int(n_steps) * (BYTES_PER_STEP + 150 * max(0, n_contacts - 2))
