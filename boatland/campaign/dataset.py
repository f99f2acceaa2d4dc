"""A campaign store as an ``xarray.Dataset``: every trial row and every case's statistics, with named
dimensions ``trial``, ``case`` and ``incident``, readable axis coordinates and units.

>>> ds = open_store("demo.h5")                                # doctest: +SKIP
>>> ds.P.sel(incident="slip > 0.1 m")                         # per case  # doctest: +SKIP
>>> open_store("demo.h5", grid=True).P                        # Hs × heading × incident  # doctest: +SKIP
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from boatland.campaign.labels import AXES, axis_label, axis_name, inputs_from_header
from boatland.campaign.store import INCIDENT_PREFIX, ROW_FIELDS

__all__ = ["open_store"]

_STAT_VARS = (("count", "count", "1", "trials with the incident"),
              ("P", "P", "1", "P(incident within the access) = count / completed trials"),
              ("P lo", "P_lo", "1", "Clopper–Pearson 95 % lower bound of P"),
              ("P hi", "P_hi", "1", "Clopper–Pearson 95 % upper bound of P"),
              ("mean time", "mean_time", "s", "mean time to the incident (exponential; inf: none seen)"),
              ("mean lo", "mean_time_lo", "s", "χ² 95 % lower bound of the mean time"),
              ("mean hi", "mean_time_hi", "s", "χ² 95 % upper bound of the mean time"))


def _unit(description: str) -> str:
    return description[1:description.index("]")] if description.startswith("[") else "1"


def _text(a) -> np.ndarray:
    return np.array([v.decode(errors="replace") if isinstance(v, bytes) else str(v) for v in a], dtype=object)


def open_store(path: str | Path, *, grid: bool = False):
    """Read a finished campaign store as an ``xarray.Dataset``.

    Parameters
    ----------
    path : path
        The HDF5 store ``boatland campaign`` wrote.
    grid : bool
        Unstack the ``case`` dimension into the campaign's axes (``Hs``, ``heading``, ...), so that the
        case statistics become arrays over the sweep (the trial table keeps its ``trial`` dimension).

    Returns
    -------
    xarray.Dataset
        Dimensions ``trial`` (one row per finished trial: ``case_index``, ``seed``, ``status``, the summary
        figures and ``time_to_incident`` (trial, incident) [s], NaN = none), ``case`` (``label``, one
        coordinate per axis named by :func:`boatland.campaign.labels.axis_name` with its key path in
        ``key``, ``trials``, ``failed``, ``screening_P``, and per ``incident``: ``count``, ``P``, ``P_lo``,
        ``P_hi``, ``mean_time``, ``mean_time_lo``, ``mean_time_hi``); the campaign's plan, fixed inputs
        and file as attributes.

        An ISEE store (``method = "isee"``): ``trial`` is one row per sample (with its ``isee_*`` and
        ``lin_*`` columns), ``run`` one row per run (a case at one Hs: ``case``, ``level``, ``hs``, ``samples``
        and every estimate of ``/stats`` under its own name, e.g. ``"first slip: P"``), and with an accepted
        risk ``case`` one row per case of ``/isee_limits`` (``"limiting Hs"`` and its interval).

    Raises
    ------
    BoatlandInputError
        Not a finished campaign store (one line).
    """
    from boatland.campaign.report import read_store
    from boatland.resources import require

    xr = require("xarray", "a campaign store as an xarray Dataset")

    data = read_store(path)
    trials, stats, plan, header = data["trials"], data["stats"], data["plan"], data["header"]
    names = header["incidents"].split("\n")
    desc = {n: d for n, _, d in ROW_FIELDS}
    tv = {}
    for name in trials.dtype.names:
        if name.startswith(INCIDENT_PREFIX) or name == "trial":
            continue
        values = trials[name]
        values = _text(values) if values.dtype.kind == "S" else values
        var = "case_index" if name == "case" else name
        tv[var] = ("trial", values, {"units": _unit(desc.get(name, "")), "long_name": desc.get(name, name)})
    tti = np.stack([trials[INCIDENT_PREFIX + n] for n in names], axis=1) if len(trials) else np.zeros((0, len(names)))
    tv["time_to_incident"] = (("trial", "incident"), tti,
                              {"units": "s", "long_name": "time from the waves' full height to the incident (NaN: none)"})
    if header.get("method") == "isee":
        return _isee_dataset(xr, data, tv, names)
    cv = {"label": ("case", _text(stats["label"]), {"long_name": "case: its axis values"}),
          "trials": ("case", stats["trials"], {"units": "1", "long_name": "trials run"}),
          "failed": ("case", stats["failed"], {"units": "1", "long_name": "failed trials (left out)"}),
          "screening_P": ("case", stats["screening: P(slip)"],
                          {"units": "1", "long_name": "frequency-domain screening: P(slip within the access)"}),
          "screening_note": ("case", _text(stats["screening: note"]), {"long_name": "why there is no screening P"})}
    for field, var, unit, long in _STAT_VARS:
        cv[var] = (("case", "incident"), np.stack([stats[f"{n}: {field}"] for n in names], axis=1),
                   {"units": unit, "long_name": long})
    coords = {"trial": ("trial", trials["trial"], {"long_name": "trial number = case × seeds + seed index"}),
              "case": ("case", stats["case"], {"long_name": "case number"}),
              "incident": ("incident", np.array(names, dtype=object), {"long_name": "incident definition"})}
    axis_names = []
    for key in plan["axes"]:
        name = axis_name(key)
        axis_names.append(name)
        unit = AXES[key][2] if key in AXES else ("deg" if key.endswith("_deg") else "")
        scale = AXES[key][3] if key in AXES else 1.0
        coords[name] = ("case", stats[f"axis: {key}"] * scale, {"key": key, "long_name": axis_label(key),
                                                                "units": unit or "1"})
    attrs = {"campaign": str(header.get("campaign", "")), "n_trials": int(header.get("n_trials", len(trials))),
             "seeds_per_case": int(plan.get("seeds", 0)), "master_seed": int(plan.get("master_seed", 0)),
             "axes": json.dumps(plan["axes"]), "plan": header.get("plan", ""),
             "inputs": json.dumps(inputs_from_header(header)), "campaign_file": header.get("campaign_file", ""),
             "boatland_version": str(header.get("boatland_version", ""))}
    ds = xr.Dataset({**tv, **cv}, coords=coords, attrs=attrs)
    if grid and axis_names:
        ds = ds.set_index(case=axis_names).unstack("case") if len(axis_names) > 1 else \
            ds.swap_dims(case=axis_names[0]).drop_vars("case")
    return ds


def _table_vars(table: np.ndarray, dim: str) -> dict:
    """Every column of a structured array as a variable over ``dim`` (text decoded), named as in the store."""
    return {name: (dim, _text(table[name]) if table[name].dtype.kind == "S" else table[name])
            for name in table.dtype.names}


def _isee_dataset(xr, data: dict, tv: dict, names: list[str]):
    """The Dataset of an ISEE store: samples (``trial``), runs (``run``), limits (``case``)."""
    trials, header = data["trials"], data["header"]
    runs = _table_vars(data["stats"], "run")
    coords = {"trial": ("trial", trials["trial"], {"long_name": "sample number (case, level, sample)"}),
              "run": ("run", np.arange(len(data["stats"])), {"long_name": "run: one case at one Hs"}),
              "incident": ("incident", np.array(names, dtype=object), {"long_name": "incident definition"})}
    limits = data.get("isee_limits")
    if limits is not None:
        coords["case"] = ("case", limits["case"], {"long_name": "case number"})
    taken = set(tv) | set(coords)
    variables = {**tv, **{f"run {k}" if k in taken else k: v for k, v in runs.items()}}
    if limits is not None:
        taken |= set(variables)
        variables.update({f"limit {k}" if k in taken else k: v
                          for k, v in _table_vars(limits, "case").items() if k != "case"})
    attrs = {"campaign": str(header.get("campaign", "")), "method": "isee", "isee": header.get("isee", ""),
             "plan": header.get("plan", ""), "inputs": json.dumps(inputs_from_header(header)),
             "campaign_file": header.get("campaign_file", ""),
             "boatland_version": str(header.get("boatland_version", ""))}
    return xr.Dataset(variables, coords=coords, attrs=attrs)
