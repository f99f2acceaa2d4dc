"""boatland — will the crew transfer vessel's fender hold on the boat landing, and if it slips, when
and how far?

Layers (each imports only from those below it; checked by import-linter in CI):

1. kernels: :mod:`boatland.irf`, :mod:`boatland.contact`, :mod:`boatland.integrate`, :mod:`boatland.waves`
2. model: :mod:`boatland.model` (validated, immutable data: hydrodynamic database, vessel, ...)
3. services: simulation (trial), frequency-domain RAOs (freqdomain); campaigns (coming)
4. edges: :mod:`boatland.hydro` (BEM readers / writers / builder), :mod:`boatland.cli`
"""

__version__ = "0.1.0"
