"""Deprecated: the names ``boatland.model`` exported before the redesign (0.1), kept for one release.

The middle floor now lives in rooms named after what they hold — :mod:`boatland.vessel` (the database,
its directions, radiation memory, vessel files, hull lines), :mod:`boatland.sea` (spectral parts, sea
states, the pile's scattered wave), :mod:`boatland.scenario` (the file format), :mod:`boatland.landing`
(the scenario on its vessel), :mod:`boatland.checks` (what refuses or warns before a run). Import from
there; ``from boatland.model import HydroDB`` still works, with a :class:`DeprecationWarning`.
"""

import importlib
import warnings

#: Old name → (new module, name).
_MOVED = {
    "HullMesh": ("boatland.vessel.database", "HullMesh"),
    "HydroDB": ("boatland.vessel.database", "HydroDB"),
    "Provenance": ("boatland.vessel.database", "Provenance"),
    "rigid_body_mass_matrix": ("boatland.vessel.database", "rigid_body_mass_matrix"),
    "WigleyCatamaran": ("boatland.vessel.wigley", "WigleyCatamaran"),
    "VesselSpec": ("boatland.vessel.files", "VesselSpec"),
    "load_vessel": ("boatland.vessel.files", "load_vessel"),
    "MeasuredRecord": ("boatland.sea.states", "MeasuredRecord"),
    "RegularWave": ("boatland.sea.states", "RegularWave"),
    "SeaState": ("boatland.sea.states", "SeaState"),
    "SpectrumPart": ("boatland.sea.states", "SpectrumPart"),
    "Scenario": ("boatland.scenario.scenario", "Scenario"),
    "load_scenario": ("boatland.scenario.scenario", "load_scenario"),
}

__all__ = sorted(_MOVED)


def __getattr__(name: str):
    if name not in _MOVED:
        raise AttributeError(f"module 'boatland.model' has no attribute {name!r}")
    module, attr = _MOVED[name]
    warnings.warn(f"boatland.model.{name} moved to {module}.{attr} (boatland.model goes in the next release)",
                  DeprecationWarning, stacklevel=2)
    return getattr(importlib.import_module(module), attr)
