"""What a trial was run with, in the words its reader uses: the sea state, where the waves come from,
the push and the friction — the inputs a verdict, a figure title or a dataset's attributes name.

Directions follow DESIGN.md §2: ``relative_direction_deg`` is where the waves travel *towards*,
relative to the bow; 180° = head seas (waves onto the bow), 90° = waves travelling towards port (they
come from starboard).
"""

from __future__ import annotations

import math

__all__ = ["trial_inputs", "inputs_text", "heading_name", "short_inputs_text"]


def heading_name(relative_deg: float | None) -> str:
    """Plain name of a relative wave direction: "head seas", "bow-quartering seas from starboard", ...

    Parameters
    ----------
    relative_deg : float or None
        Relative direction the waves travel towards [deg] (180 = head seas); None: no waves.
    """
    if relative_deg is None or not math.isfinite(relative_deg):
        return "no waves"
    r = relative_deg % 360.0
    a = min(r, 360.0 - r)             # 0 following … 180 head
    if a >= 157.5:
        return "head seas"
    if a <= 22.5:
        return "following seas"
    side = "starboard" if 0.0 < r < 180.0 else "port"    # travelling towards port: they come from starboard
    kind = "bow-quartering" if a > 112.5 else ("beam" if a >= 67.5 else "stern-quartering")
    return f"{kind} seas from {side}"


def _sea(scenario) -> dict:
    sea = scenario.sea
    heading = scenario.vessel.heading_deg
    if sea is None:
        return {"sea": "calm water", "Hs": None, "Tp": None, "relative_direction_deg": None}
    w = sea.waves
    rel = lambda d: round((d - heading) % 360.0, 6)          # noqa: E731
    if sea.kind == "regular":
        return {"sea": f"regular H {w.H:g} m, T {w.T:g} s", "H": w.H, "T": w.T, "Hs": None, "Tp": None,
                "relative_direction_deg": rel(w.direction_deg)}
    if sea.kind == "measured":
        return {"sea": f"measured record {w.source}", "Hs": None, "Tp": None,
                "relative_direction_deg": rel(w.direction_deg)}
    parts = w.parts
    text = " + ".join(f"{p.shape.label} Hs {p.Hs:.3g} m, Tp {p.Tp:.3g} s" for p in parts)
    out = {"sea": text, "Hs": parts[0].Hs if len(parts) == 1 else math.sqrt(sum(p.Hs ** 2 for p in parts)),
           "Tp": parts[0].Tp, "relative_direction_deg": rel(parts[0].direction_deg)}
    if parts[0].gamma is not None:
        out["gamma"] = parts[0].gamma
    return out


def trial_inputs(scenario) -> dict:
    """The inputs of a trial a reader judges its outcome by (JSON-able, SI units).

    Parameters
    ----------
    scenario : Scenario

    Returns
    -------
    dict
        ``scenario``, ``vessel``, ``sea`` (text), ``Hs`` [m] and ``Tp`` [s] (the first spectrum's; the
        combined Hs of a sum; None for regular, measured or calm seas, which give ``H``/``T`` or only the
        text), ``relative_direction_deg`` and ``heading`` (its name), ``thrust`` [N], ``mu_s``, ``mu_k``,
        ``shear_stiffness`` [N/m per contact] (None: rigid stick), ``seed``, ``duration`` [s]; when given,
        ``current`` and ``wind`` (``speed`` [m/s], ``relative_direction_deg`` towards), ``drift``, ``skipper``
        and ``push_direction_deg``.
    """
    out = {"scenario": scenario.name, "vessel": scenario.vessel.database}
    out.update(_sea(scenario))
    out["heading"] = heading_name(out["relative_direction_deg"])
    out["thrust"] = scenario.thrust.force if scenario.thrust is not None else None
    f = scenario.fender
    out["mu_s"] = f.mu_s if f is not None else None
    out["mu_k"] = f.mu_k if f is not None else None
    out["shear_stiffness"] = None if f is None or f.rigid else f.shear_stiffness
    out["seed"] = scenario.simulation.seed
    out["duration"] = scenario.simulation.duration
    heading = scenario.vessel.heading_deg
    for key in ("current", "wind"):          # only when given: the waves-only inputs stay as they were
        flow = getattr(scenario, key)
        if flow is not None:
            out[key] = {"speed": flow.speed, "relative_direction_deg": round((flow.direction_deg - heading) % 360.0, 9)}
    if scenario.sea is not None and scenario.sea.drift != "none":
        out["drift"] = scenario.sea.drift
    thr = scenario.thrust
    if thr is not None and thr.control.active:
        out["skipper"] = thr.control.kind
    if thr is not None and not thr.trimmed:
        out["push_direction_deg"] = float(thr.direction_deg)
    return out


def _force(f: float) -> str:
    return f"{f / 1e3:g} kN" if abs(f) >= 1e3 else f"{f:g} N"


def short_inputs_text(inputs: dict) -> str:
    """The sea, direction, push and friction in one short phrase (figure titles)."""
    if not inputs:
        return ""
    parts = [inputs.get("sea", "")]
    rel = inputs.get("relative_direction_deg")
    if rel is not None:
        parts.append(f"{inputs.get('heading', heading_name(rel))} ({rel:g}°)")
    push = [f"push {_force(inputs['thrust'])}" if inputs.get("thrust") is not None else "no push"]
    if inputs.get("skipper") == "hold_force":
        push[0] += " (held by the skipper)"
    if inputs.get("mu_s") is not None:
        push.append(f"μ_s {inputs['mu_s']:g}")
    flows = [f"{k} {inputs[k]['speed']:g} m/s towards {inputs[k]['relative_direction_deg']:g}°"
             for k in ("current", "wind") if k in inputs]
    if inputs.get("drift"):
        flows.append(f"wave drift {inputs['drift']}")
    return ", ".join(p for p in parts if p) + "; " + ", ".join(push) + ("; " + ", ".join(flows) if flows else "")


def inputs_text(inputs: dict) -> str:
    """:func:`short_inputs_text` with μ_k, the seed and the duration: the inputs of a verdict line."""
    if not inputs:
        return ""
    text = short_inputs_text(inputs)
    if inputs.get("mu_k") is not None:
        text = text.replace(f"μ_s {inputs['mu_s']:g}", f"μ_s {inputs['mu_s']:g} / μ_k {inputs['mu_k']:g}")
    extra = []
    if inputs.get("seed") is not None:
        extra.append(f"seed {inputs['seed']}")
    if inputs.get("duration") is not None:
        extra.append(f"{inputs['duration']:g} s")
    return text + ("; " + ", ".join(extra) if extra else "")
