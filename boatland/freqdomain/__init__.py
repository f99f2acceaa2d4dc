"""Frequency-domain services: RAOs of the free vessel and of the vessel hinged at its fender point.

Service layer (DESIGN.md §3): built on the hydrodynamic database of :mod:`boatland.model`; the
screening tools of Wu (2014) / seed 002 §3.2.1 (slip margins, Rayleigh peaks, limiting Hs) will join
them here.
"""

from boatland.freqdomain.harmonic import first_harmonic
from boatland.freqdomain.rao import (HingedResponse, excitation_force, free_rao, hinged_rao, impedance,
                                     point_map, preload_stiffness, radiation_coefficients)

__all__ = ["HingedResponse", "excitation_force", "first_harmonic", "free_rao", "hinged_rao", "impedance",
           "point_map", "preload_stiffness", "radiation_coefficients"]
