"""Readable names of campaign axes and values: "Hs [m]", "heading (180° = head seas)", "push [kN]" —
for report tables, legends and figure titles instead of raw key paths (``sea.relative_direction_deg``).

:func:`campaign_inputs` is what the report says a campaign held fixed (the base scenario's sea,
push and friction, the seeds per case, the access); the runner stores it in the store's header.
"""

from __future__ import annotations

import json
import re

from boatland.scenario.inputs import heading_name, trial_inputs

__all__ = ["AXES", "axis_name", "axis_label", "axis_unit", "value_text", "campaign_inputs", "fixed_text",
           "HS_KEY", "TP_KEYS", "DIR_KEYS"]

HS_KEY = "sea.Hs"
TP_KEYS = ("sea.Tp",)
DIR_KEYS = ("sea.relative_direction_deg", "sea.direction_deg")

#: key path → (dataset name, label, unit, scale from SI to the unit shown)
AXES = {
    "sea.Hs": ("Hs", "Hs [m]", "m", 1.0),
    "sea.Tp": ("Tp", "Tp [s]", "s", 1.0),
    "sea.gamma": ("gamma", "JONSWAP γ", "1", 1.0),
    "sea.relative_direction_deg": ("heading", "heading (180° = head seas)", "deg", 1.0),
    "sea.direction_deg": ("wave_direction", "wave direction (towards) [°]", "deg", 1.0),
    "thrust.force": ("push", "push [kN]", "kN", 1e-3),
    "fender.mu_s": ("mu_s", "μ_s", "1", 1.0),
    "fender.mu_k": ("mu_k", "μ_k", "1", 1.0),
    "fender.shear_stiffness": ("shear_stiffness", "shear stiffness [kN/m]", "kN/m", 1e-3),
    "fender.stiffness": ("fender_stiffness", "fender stiffness [kN/m]", "kN/m", 1e-3),
    "simulation.duration": ("duration", "duration [s]", "s", 1.0),
    "simulation.dt": ("dt", "dt [s]", "s", 1.0),
}


def axis_name(key: str) -> str:
    """A Python/netCDF name for an axis: ``sea.Hs`` → ``Hs``, ``landing.struts[1].diameter`` →
    ``landing_struts_1_diameter``."""
    if key in AXES:
        return AXES[key][0]
    return re.sub(r"[^0-9A-Za-z_]+", "_", key).strip("_")


def axis_label(key: str) -> str:
    """Column heading / axis label with its unit."""
    if key in AXES:
        return AXES[key][1]
    if key.endswith("_deg"):
        return f"{key.rsplit('.', 1)[-1][:-4]} [°]"
    return key.rsplit(".", 1)[-1]


def axis_unit(key: str) -> str:
    """The unit values of ``key`` are shown in (:func:`value_text`)."""
    if key in AXES:
        return AXES[key][2]
    return "deg" if key.endswith("_deg") else ""


def value_text(key: str, value, *, short: bool = False) -> str:
    """A value of an axis as a reader says it: "Hs 0.5 m", "Tp 7 s", "head seas (180°)", "push 80 kN".
    ``short``: the value with its unit only ("0.5 m", "180°", "80 kN")."""
    if isinstance(value, bytes):
        value = value.decode()
    if not isinstance(value, (int, float)):
        return str(value)
    if key == "sea.relative_direction_deg":
        return f"{value:g}°" if short else f"{heading_name(value)} ({value:g}°)"
    name = axis_label(key).split(" [")[0].split(" (")[0]
    unit = axis_unit(key)
    scale = AXES[key][3] if key in AXES else 1.0
    v = value * scale
    unit_text = "°" if unit == "deg" else ("" if unit in ("", "1") else f" {unit}")
    return f"{v:g}{unit_text}" if short else f"{name} {v:g}{unit_text}"


def campaign_inputs(campaign) -> dict:
    """What a campaign holds fixed: the base scenario's :func:`~boatland.scenario.inputs.trial_inputs`
    (with the campaign's ``[set]``), the seeds per case, the access [s], name and description."""
    from boatland.trial.simulate import exposure_start

    base = campaign.base
    out = trial_inputs(base)
    out.pop("seed", None)
    access = campaign.access if campaign.access is not None else base.simulation.duration - exposure_start(base)
    out.update({"campaign": campaign.name, "description": getattr(campaign, "description", ""),
                "seeds": campaign.seeds if campaign.method != "isee" else None,   # isee: samples, not seeds
                "access": access, "axes": list(campaign.axes)})
    out.pop("duration", None)
    return out


def fixed_text(inputs: dict, axes) -> str:
    """The fixed inputs of a campaign in one phrase, leaving out what its axes sweep:
    "JONSWAP Tp 7 s, head seas (180°); push 80 kN, μ_s 0.6; 4 seeds per case, 120 s access"."""
    if not inputs:
        return ""
    axes = set(axes)
    bits = []
    sea = []
    if inputs.get("Hs") is not None and HS_KEY not in axes:
        sea.append(f"Hs {inputs['Hs']:g} m")
    if inputs.get("Tp") is not None and not axes & set(TP_KEYS):
        sea.append(f"Tp {inputs['Tp']:g} s")
    if inputs.get("relative_direction_deg") is not None and not axes & set(DIR_KEYS):
        sea.append(f"{inputs.get('heading', '')} ({inputs['relative_direction_deg']:g}°)")
    if sea:
        bits.append(", ".join(sea))
    push = []
    if inputs.get("thrust") is not None and "thrust.force" not in axes:
        push.append(f"push {inputs['thrust'] / 1e3:g} kN")
    if inputs.get("mu_s") is not None and "fender.mu_s" not in axes:
        push.append(f"μ_s {inputs['mu_s']:g}")
    if push:
        bits.append(", ".join(push))
    tail = []
    if inputs.get("seeds") is not None:
        tail.append(f"{inputs['seeds']} seeds per case")
    if inputs.get("access") is not None:
        tail.append(f"{inputs['access']:g} s access")
    if tail:
        bits.append(", ".join(tail))
    return "; ".join(bits)


def inputs_from_header(header: dict) -> dict:
    """The campaign's fixed inputs from a store's header (``{}`` for a store written before they were kept)."""
    try:
        return json.loads(header.get("inputs", "{}"))
    except (TypeError, ValueError):
        return {}
