"""Validated, immutable model objects (hydrodynamic database, vessel, sea states, radiation memory, scenario)."""

from boatland.model.hull import WigleyCatamaran
from boatland.model.hydrodb import HullMesh, HydroDB, Provenance, rigid_body_mass_matrix
from boatland.model.seastate import MeasuredRecord, RegularWave, SeaState, SpectrumPart
from boatland.model.scenario import Scenario, load_scenario
from boatland.model.vessel import VesselSpec, load_vessel

__all__ = ["HullMesh", "HydroDB", "MeasuredRecord", "Provenance", "RegularWave", "Scenario", "SeaState",
           "SpectrumPart", "VesselSpec", "WigleyCatamaran", "load_scenario", "load_vessel", "rigid_body_mass_matrix"]
