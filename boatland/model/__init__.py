"""Validated, immutable model objects (hydrodynamic database, vessel, ...)."""

from boatland.model.hull import WigleyCatamaran
from boatland.model.hydrodb import HullMesh, HydroDB, Provenance, rigid_body_mass_matrix
from boatland.model.vessel import VesselSpec, load_vessel

__all__ = ["HullMesh", "HydroDB", "Provenance", "VesselSpec", "WigleyCatamaran", "load_vessel",
           "rigid_body_mass_matrix"]
