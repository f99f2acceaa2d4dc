"""Frequency-domain services: RAOs of the free vessel and of the vessel hinged at its fender point,
Wu (2014) slip screening (Grøtting 2015 §3.2.1, §3.4: slip margins, Rayleigh / Rice statistics, limiting
Hs). Operability over a site's weather, built on the screening, is :mod:`boatland.site`.

Service layer (DESIGN.md §3): built on the vessel (:mod:`boatland.vessel`) and the scenario on it
(:mod:`boatland.landing`). The landing as the screening sees it is :mod:`~boatland.freqdomain.landing`, the
statistics of its slip margins and the limiting Hs :mod:`~boatland.freqdomain.statistics`.
"""

from boatland.freqdomain.harmonic import first_harmonic
from boatland.freqdomain.rao import (HingedResponse, excitation_force, free_rao, hinged_rao, impedance,
                                     point_map, preload_stiffness, radiation_coefficients)
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import SeaResponse, SlipTransfer, screening_grid, sea_response, slip_transfer
from boatland.freqdomain.statistics import (ACCEPT_PRESETS, ACCESS_DURATION, LimitTable, MODES, accept_probability,
                                            incident_probability, limiting_hs, rayleigh_exceedance, rice_rate,
                                            spectral_moments, vanmarcke_rate)

__all__ = ["ACCEPT_PRESETS", "ACCESS_DURATION", "MODES", "HingedResponse", "LandingSetup",
           "LimitTable", "SeaResponse", "SlipTransfer", "accept_probability",
           "excitation_force", "first_harmonic", "free_rao", "hinged_rao", "impedance", "incident_probability",
           "limiting_hs", "point_map", "preload_stiffness", "radiation_coefficients", "rayleigh_exceedance",
           "rice_rate", "screening_grid", "sea_response", "slip_transfer", "spectral_moments",
           "vanmarcke_rate"]
