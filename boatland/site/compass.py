r"""The site frame: compass directions as planners, hindcasts and metocean reports give them, turned into
the vessel's relative wave direction once, here (DESIGN.md §2).

Every direction a planner types or a weather file holds is **nautical**: degrees clockwise from true
North, and for waves, wind and current the direction they come **from** (a "westerly" comes from 270°).
A turbine's boat landing is given by its **bearing**: the compass direction from the tower's axis to the
landing — where it stands on the tower, the way its ladder faces. The vessel pushes on it bow first, so it
heads the opposite way (a landing at 270°, on the tower's west side, is approached heading East, 090°)::

                        N (0°)         waves from North (↓) travel South
                          |
                          ▼   vessel heading 180° (South): the waves come from astern,
                          ═   a following sea (β = 0°) — the landing at bearing 0°
          W (270°) ───── (●) ───── E (90°)         ● the tower
                          ═   the landing at bearing 180°
                          ▲   vessel heading 0° (North): the waves meet its bow,
                          |   a head sea (β = 180°)
                        S (180°)

The relative direction the screening and the time domain use (:mod:`boatland.conventions`: where the waves
travel *towards*, in the vessel's frame; 180° head seas, 90° towards port) of a sea from :math:`\phi_w` on
the landing at bearing :math:`\phi_L` is

.. math:: \beta = (\phi_L - \phi_w) \bmod 360^\circ ,

so turning the site (every direction and every landing by the same angle) changes nothing. For a landing at
0° (facing North): waves from 0/90/180/270° are following (β 0°), from port (270°: travelling towards
starboard), head (180°) and from starboard (90°); for a landing at 180° (the vessel heading North) they
are head, from starboard, following and from port.

The global frame of scenario files (origin at the tower's axis, :math:`x` East, :math:`y` North — so a
compass bearing :math:`\phi` is the global angle :math:`90^\circ - \phi`): a direction *from* :math:`\phi_w`
travels *towards* the global angle :math:`270^\circ - \phi_w`; a landing at bearing :math:`\phi_L` has the
scenario's ``landing.bearing_deg`` :math:`= 90^\circ - \phi_L` and the vessel the heading
:math:`270^\circ - \phi_L`.
"""

from __future__ import annotations

import numpy as np

__all__ = ["global_bearing", "landing_bearing", "relative_direction", "towards_global"]


def relative_direction(from_deg, landing_deg):
    r"""The relative direction β [deg] in [0, 360) (towards, vessel frame; 180° head seas) of waves (or wind,
    or current) coming from the compass direction ``from_deg`` at a landing at compass bearing ``landing_deg``:
    :math:`\beta = (\phi_L - \phi_w) \bmod 360`. Arrays broadcast."""
    return np.mod(np.asarray(landing_deg, dtype=float) - np.asarray(from_deg, dtype=float), 360.0)


def towards_global(from_deg):
    r"""The global direction [deg] (towards, from +x = East counterclockwise) of something coming from the
    compass direction ``from_deg``: :math:`(270^\circ - \phi) \bmod 360`."""
    return np.mod(270.0 - np.asarray(from_deg, dtype=float), 360.0)


def global_bearing(landing_deg):
    r"""A scenario's ``landing.bearing_deg`` (global, from +x counterclockwise) of the landing at compass
    bearing ``landing_deg``: :math:`(90^\circ - \phi_L) \bmod 360`."""
    return np.mod(90.0 - np.asarray(landing_deg, dtype=float), 360.0)


def landing_bearing(heading_deg):
    r"""The compass bearing of the landing a vessel with global heading ``heading_deg`` (the scenario's
    ``vessel.heading_deg``) is pushed on: the landing lies ahead of its bow, so its global bearing from the
    tower is the heading + 180°, the compass bearing :math:`(270^\circ - \psi) \bmod 360`."""
    return np.mod(270.0 - np.asarray(heading_deg, dtype=float), 360.0)
