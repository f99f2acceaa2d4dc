"""Validated, immutable model objects (hydrodynamic database, vessel, ...)."""

from boatland.model.hydrodb import HullMesh, HydroDB, Provenance, rigid_body_mass_matrix

__all__ = ["HullMesh", "HydroDB", "Provenance", "rigid_body_mass_matrix"]
