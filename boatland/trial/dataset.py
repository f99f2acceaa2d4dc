"""A trial as a labelled ``xarray.Dataset`` (:meth:`boatland.trial.result.Result.to_xarray`): what a
notebook works with and what ``boatland run -o FILE`` writes (netCDF-4, :mod:`boatland.netcdf_h5`).

Named dimensions ``time``, ``dof``, ``contact``, ``tangent``, ``event``, ``episode``; every variable has
a short ``long_name`` (a plot's axis label) and CF ``units`` — none on the three variables over ``dof``,
whose units differ per DOF (the coordinate ``dof_units`` names them) —, the longer explanation in
``comment``; the trial's inputs (sea, direction, push, μ), its verdict, summary and
provenance are attributes. Variables are named for what they are (``normal_force``, not the kernel's
``fn``); ``result_field`` names the :class:`~boatland.trial.result.Result` array each one holds.
"""

from __future__ import annotations

import json

import numpy as np

from boatland import __version__
from boatland.conventions import DOF_NAMES, DOF_UNITS
from boatland.trial.incidents import RollAbove, SlipDistance

__all__ = ["result_dataset", "result_parts", "TANGENTS", "MODE_MEANINGS"]

#: The two tangential directions of a contact on its tube.
TANGENTS = ("vertical", "horizontal")
#: ``contact_mode`` values.
MODE_MEANINGS = "open stick slip off_the_landing"

_WAVE_FORCE_UNITS = ("N", "N", "N", "N m", "N m", "N m")


def _flat_inputs(inputs: dict) -> dict:
    """Inputs as netCDF attributes: scalars only, None left out, units in the name where not SI-obvious."""
    rename = {"thrust": "thrust_N", "shear_stiffness": "shear_stiffness_N_per_m", "duration": "duration_s",
              "Hs": "Hs_m", "Tp": "Tp_s", "H": "H_m", "T": "T_s"}
    out = {}
    for k, v in inputs.items():
        if v is None or isinstance(v, (dict, list)):
            continue
        out[f"input_{rename.get(k, k)}"] = v
    return out


def result_dataset(r):
    """The :class:`~boatland.trial.result.Result` ``r`` as an ``xarray.Dataset`` (see
    :meth:`~boatland.trial.result.Result.to_xarray`)."""
    from boatland.resources import require

    xr = require("xarray", "Result.to_xarray")
    var, coords, attrs = result_parts(r)
    return xr.Dataset(var, coords=coords, attrs=attrs)


def result_parts(r) -> tuple[dict, dict, dict]:
    """The dataset of :func:`result_dataset` as plain parts, ``(data_vars, coords, attrs)`` with
    name → ``(dims, data, attrs)`` — what :func:`boatland.netcdf_h5.write_parts` writes without xarray."""
    nc = r.mode.shape[1]
    t = np.asarray(r.t, dtype=float)
    var = {}

    def put(name, dims, data, units, long_name, field=None, comment=None, **attrs):
        a = {"long_name": long_name, **attrs} if units is None else {"units": units, "long_name": long_name, **attrs}
        if comment:
            a["comment"] = comment
        if field:
            a["result_field"] = field
        var[name] = (dims, np.asarray(data), a)

    mixed = "units per DOF in the coordinate dof_units ({}); the variables surge … yaw carry their own"
    put("motion", ("time", "dof"), r.x, None, "motion", "x", f"of the reference point; {mixed.format('m, rad')}")
    put("velocity", ("time", "dof"), r.v, None, "velocity", "v", f"of the reference point; {mixed.format('m/s, rad/s')}")
    put("wave_force", ("time", "dof"), r.F_exc, None, "wave excitation force", "F_exc", mixed.format("N, N m"))
    for i, (name, unit) in enumerate(zip(DOF_NAMES, DOF_UNITS)):
        if unit == "rad":
            put(name, ("time",), np.degrees(r.x[:, i]), "deg", name, comment="of the reference point")
        else:
            put(name, ("time",), r.x[:, i], unit, name, comment="of the reference point")
    put("thrust", ("time",), r.thrust, "N", "push", "thrust", "along the vessel's x axis")
    put("contact_mode", ("time", "contact"), r.mode.astype(np.int64), "1", "contact state", "mode",
        "at the step start", flag_values=np.arange(4, dtype=np.int64), flag_meanings=MODE_MEANINGS)
    put("normal_force", ("time", "contact"), r.fn, "N", "normal force", "fn", "on the fender")
    put("friction_force", ("time", "contact", "tangent"), r.ft, "N", "friction force", "ft",
        "friction (shear) force on the vessel along the tube")
    put("friction_needed", ("time", "contact"), r.needed, "N", "friction needed", "needed",
        "friction force that would hold the contact stuck")
    put("friction_available", ("time", "contact"), r.available, "N", "friction available", "available",
        "mu_s f_n stuck, mu(|u|) f_n sliding")
    with np.errstate(divide="ignore", invalid="ignore"):
        util = np.where(r.available > 0, r.needed / np.where(r.available > 0, r.available, 1.0), np.nan)
    put("friction_utilisation", ("time", "contact"), util, "1", "friction utilisation",
        comment="friction needed / available (NaN out of contact); above 1 the contact slips")
    put("landing_position", ("time", "contact", "tangent"), r.tpos, "m", "position on the landing", "tpos",
        "contact height; fender centre along the landing")
    put("slip_distance", ("time", "contact"), r.landing_offset() if nc else np.zeros((len(t), 0)), "m",
        "slip distance", comment="distance of the fender point from where it landed after the settling (NaN: not "
                                 "landed)")
    if r.slide is not None:
        put("slide", ("time", "contact", "tangent"), r.slide, "m", "slide in the step", "slide",
            "sliding over the tube during the step")
    if r.work is not None:
        put("friction_work", ("time", "contact"), r.work, "J", "friction work", "work",
            "friction work of the step (never positive)")
    ev = r.events
    put("event_time", ("event",), [e.t for e in ev], "s", "event time")
    put("event_contact", ("event",), np.array([e.contact for e in ev], dtype=np.int64), "1", "contact")
    put("event_kind", ("event",), np.array([e.kind for e in ev], dtype=object), "1", "event", comment="what changed")
    put("event_needed", ("event",), [e.needed for e in ev], "N", "friction needed",
        comment="friction force that would have held it")
    put("event_available", ("event",), [e.available for e in ev], "N", "friction available")
    ep = r.episodes
    put("episode_contact", ("episode",), np.array([e.contact for e in ep], dtype=np.int64), "1", "contact")
    put("episode_start", ("episode",), [e.t_start for e in ep], "s", "slip start")
    put("episode_end", ("episode",), [e.t_end for e in ep], "s", "slip end", comment="re-stick, loss of contact or end")
    put("episode_distance", ("episode",), [e.distance for e in ep], "m", "largest slide",
        comment="largest slide from where it stuck")
    put("episode_vertical", ("episode",), [e.vertical for e in ep], "m", "vertical slide",
        comment="vertical slide at that moment")
    put("episode_horizontal", ("episode",), [e.horizontal for e in ep], "m", "horizontal slide",
        comment="horizontal slide at that moment")
    put("episode_ended_by", ("episode",), np.array([e.ended_by for e in ep], dtype=object), "1", "ended by",
        comment="how it ended")
    coords = {
        "time": ("time", t, {"units": "s", "long_name": "time", "axis": "T"}),
        "dof": ("dof", np.array(DOF_NAMES, dtype=object), {"long_name": "degree of freedom"}),
        "dof_units": ("dof", np.array(DOF_UNITS, dtype=object), {"long_name": "unit of the DOF"}),
        "contact": ("contact", np.arange(nc, dtype=np.int64),
                    {"long_name": "contact", "comment": "fender point / landing tube, in the scenario's order"}),
        "tangent": ("tangent", np.array(TANGENTS, dtype=object), {"long_name": "direction on the tube"}),
        "event": ("event", np.arange(len(ev), dtype=np.int64), {"long_name": "event number"}),
        "episode": ("episode", np.arange(len(ep), dtype=np.int64), {"long_name": "slip episode number"}),
    }
    v = r.verdict()
    inc = r.incidents
    attrs = {
        "title": f"boatland landing trial: {r.provenance.get('scenario', 'trial')}",
        "Conventions": "CF-1.10",
        "source": f"boatland {__version__}",
        "verdict": v.text(), "outcome": v.outcome,
        "status": r.message, "status_code": int(r.status),
        "settled_at_s": r.settled_at, "exposure_from_s": r.exposure_from,
        **_flat_inputs(r.inputs),
        "incident_slip_distance_m": np.asarray(inc.slip_distance if inc else (0.1,), dtype=float),
        "incident_roll_limit_deg": np.asarray(inc.roll_limit_deg if inc else (), dtype=float),
        "incident_other": ", ".join(d.name for d in r.incident_definitions
                                    if not isinstance(d, (SlipDistance, RollAbove))),
        "inputs": json.dumps(r.inputs, default=float),
        "summary": json.dumps(r.summary(), default=float),
        "provenance": json.dumps(r.provenance, default=str),
    }
    attrs = {k: a for k, a in attrs.items() if a is not None and not (isinstance(a, np.ndarray) and a.size == 0)}
    return var, coords, attrs
