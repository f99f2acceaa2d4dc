"""The vessel: its hydrodynamic database and what is derived from it alone.

- :mod:`~boatland.vessel.database` — :class:`HydroDB`, the frequency-domain coefficients, mass and hull mesh;
- :mod:`~boatland.vessel.directions` — which wave directions a database covers, port–starboard symmetry;
- :mod:`~boatland.vessel.radiation` — the radiation memory (IRFs, state-space fit) of a database;
- :mod:`~boatland.vessel.files` — vessel files (a hull to build with Capytaine);
  :mod:`~boatland.vessel.imported` — vessel files naming imported BEM output, with their mass properties;
- :mod:`~boatland.vessel.wigley`, :mod:`~boatland.vessel.ctv_hull` — the hull lines and panel meshes.

Reading and writing databases is :mod:`boatland.hydro`, one layer up.
"""

from boatland.vessel.database import HullMesh, HydroDB, Provenance

__all__ = ["HullMesh", "HydroDB", "Provenance"]
