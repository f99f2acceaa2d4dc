r"""The one set of conventions used everywhere in boatland (DESIGN.md §2).

Frames
------
Global frame: earth-fixed, z up, origin on the mean free surface at the monopile axis.
Body frame: x forward (bow), y to port, z up, origin at the hydrodynamic reference point
(for the built-in vessels: midship, centreline, calm waterline).

Degrees of freedom
------------------
Index 0..5 = surge, sway, heave, roll, pitch, yaw (DOF 1..6 in the literature). Rotations are
small angles about the reference point. Matrix entry ``A[i, j]`` is the force in DOF ``i`` due to
motion of DOF ``j``.

Units
-----
SI inside (m, s, kg, N, rad). Scenario and vessel files use SI too, angles in degrees in keys
ending in ``_deg``. Wave directions are stored in degrees (``wave_dir_deg``) because every BEM file
stores them so; they are converted to radians at the edge of each computation.

Wave direction
--------------
``beta`` / ``direction_deg`` is the direction the waves travel *towards*: 0° travels along +x.
Relative to the vessel, ``beta = 180°`` is head seas (waves come from ahead, onto the bow),
``beta = 0°`` following seas, ``beta = 90°`` waves travelling towards port (coming from starboard).
This is the WAMIT / Capytaine / BEMIO definition.

Site frame
----------
Planners, hindcasts and metocean reports give directions in compass degrees from true North, waves, wind and
current where they come *from*, and a landing by its bearing from the tower's axis; scenario files' global
frame has x East and y North. Converted once, in :mod:`boatland.site.compass` (with a picture):
β = (landing bearing − from) mod 360.

Phase (time) convention
-----------------------
boatland uses **exp(+iωt)**, as WAMIT and the BEMIO HDF5 files do. A complex amplitude
:math:`\hat q` means

.. math:: q(t) = \mathrm{Re}\{\hat q\, e^{i\omega t}\} = |\hat q| \cos(\omega t + \arg \hat q),

so the phase is a *lead* over the reference signal. Excitation forces :math:`X(\omega,\beta)` are per
unit wave amplitude, referred to the incident wave elevation at the reference point,
:math:`\eta(t) = \mathrm{Re}\{a\, e^{i\omega t}\}` at :math:`x = y = 0`. Hence a very long wave heaves
a floating body in phase with the crest (``arg X_3 → 0`` as ω → 0), and for a wave travelling
along +x the surge force leads the crest by 90° (``arg X_1 → +π/2``): it follows the fluid
acceleration.

Codes with the other convention, exp(−iωt) (Capytaine, NEMOH), or with phase given as a lag
(AQWA), are converted by complex conjugation in their readers; tests check the known phases above
on every reader.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "DOF_NAMES",
    "DOF_UNITS",
    "N_DOF",
    "PORT_STARBOARD_SIGN",
    "mirror_direction_deg",
]

N_DOF = 6
DOF_NAMES = ("surge", "sway", "heave", "roll", "pitch", "yaw")
DOF_UNITS = ("m", "m", "m", "rad", "rad", "rad")

#: Sign of each DOF under reflection in the xz plane (y → −y). A port/starboard-symmetric hull has
#: ``X_i(−β) = s_i X_i(β)`` and ``A_ij = s_i s_j A_ij`` (so sway, roll, yaw decouple from surge,
#: heave, pitch).
PORT_STARBOARD_SIGN = np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])


def mirror_direction_deg(beta_deg):
    """Direction mirrored in the xz plane, in [0, 360): β → −β."""
    return np.mod(-np.asarray(beta_deg, dtype=float), 360.0)
