r"""Tidal current: a uniform flow dragging the submerged hull, the hull's own motion included.

``[current] speed``, ``relative_direction_deg`` (or ``direction_deg``, global) in the sea's convention: the
direction the water moves *towards* — 180° onto the bow (a head current), 90° towards port (a current from
starboard). The load is the drag law of :mod:`boatland.loads.drag` with the relative velocity of the
water at the centroid of the underwater lateral area, evaluated at every RK4 stage
(:func:`boatland.loads.drag.add_drag`): the current also damps the hull's slow motions.

Default coefficients (:data:`DEFAULTS`), for any vessel whose database has its hull mesh (ctv27, ctv24,
model2), the cross-flow form :math:`C_X = c_x\cos\theta|\cos\theta|`, :math:`C_Y = c_y\sin\theta|\sin\theta|`
(Faltinsen 1990, *Sea Loads on Ships and Offshore Structures*, §6.4: the cross-flow principle), with

- A_y the two demihulls' underwater lateral silhouettes added (ctv27: 2 × 35.3 = 70.6 m²; no shielding of
  the down-stream hull: an overestimate of a catamaran's side load, on the safe side for friction), A_x
  their frontal silhouettes (ctv27: 7.3 m²), L the waterline length, the forces at the lateral area's
  centroid (ctv27: 1.36 m aft of the reference point, 0.77 m below the waterline);
- c_y = 1.0: the cross-flow drag coefficient of a ship section without bilge keels at B/(2T) ≈ 0.8 (ctv27's
  demihulls: 2.7/(2 × 1.71) = 0.79) lies between about 0.8 and 1.2 (Faltinsen 1990 §6.4); 1.0 is that
  range's middle — an assumption until a model test of the vessel gives its own;
- c_x = 0.05: skin friction of the wetted surface by the ITTC-1957 line at 1 m/s (ctv27: Re = 2.1e7,
  C_F = 0.0026, 115 m² wetted, form factor 1.2 assumed), referred to the frontal area — an estimate;
- c_n = 0: no yaw moment besides the lateral force's lever (the Munk moment of potential flow is left out;
  give c_n, or a table, to include it).

A measured table (``[current.table]``, e.g. from a model test or CFD) replaces the shape.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.loads.drag import DragLoad, crossflow_table, drag_keys, geometry_from, global_direction, table_from
from boatland.tomlspec import Key, Table

__all__ = ["CURRENT_TABLE", "DEFAULTS", "Current", "side_words"]

DEFAULTS = {"c_x": 0.05, "c_y": 1.0, "c_n": 0.0,
            "source": "cross-flow principle (Faltinsen 1990 §6.4), c_x 0.05 (ITTC-1957 friction), c_y 1.0, c_n 0 "
                      "(boatland.loads.current)"}

#: ``[current]`` of a scenario file.
CURRENT_TABLE = Table({
    "speed": Key(float, required=True, ge=0.0, doc="current speed, uniform over the draught [m/s]"),
    "direction_deg": Key(float, doc="global direction the water flows towards [deg] (or relative_direction_deg)"),
    "relative_direction_deg": Key(float, doc="direction the water flows towards relative to the vessel's x axis "
                                             "[deg]: 180 = onto the bow, 90 = towards port (from starboard)"),
    **drag_keys("current", DEFAULTS),
}, optional=True, doc="a uniform tidal current dragging the submerged hull (absent: none)")


@dataclass(frozen=True, kw_only=True, eq=False)
class Current:
    """A scenario's current: ``speed`` [m/s] towards the global ``direction_deg``, and the keys that
    override the vessel-derived drag (``values``: the validated table)."""

    speed: float
    direction_deg: float
    values: dict

    @classmethod
    def from_table(cls, t: dict, heading_deg: float) -> "Current":
        return cls(speed=float(t["speed"]), direction_deg=global_direction(t, heading_deg), values=dict(t))

    def velocity_local(self, heading_deg: float) -> np.ndarray:
        """The water's velocity (3,) in the vessel's start axes (heading ``heading_deg``) [m/s]."""
        a = math.radians(self.direction_deg - heading_deg)
        c, s = math.cos(a), math.sin(a)
        c, s = (0.0 if abs(c) < 1e-15 else c), (0.0 if abs(s) < 1e-15 else s)
        return np.array([self.speed * c, self.speed * s, 0.0])

    def load(self, db) -> DragLoad:
        """The drag load on the vessel of ``db`` (a HydroDB: its hull mesh and water density).

        Raises
        ------
        ValueError
            The database has no mesh and the file did not give the areas (the message names the keys).
        """
        mesh = db.mesh
        geo = geometry_from(self.values, None if mesh is None else mesh.vertices, None if mesh is None else mesh.faces,
                            what="current", per_hull=True)
        return DragLoad(rho=float(db.rho), **table_from(self.values, crossflow_table, DEFAULTS, "given"), **geo)

    def text(self, heading_deg: float) -> str:
        rel = (self.direction_deg - heading_deg) % 360.0
        return f"current {self.speed:g} m/s towards {rel:.0f}° relative ({side_words(rel)})"


def side_words(rel: float, short: bool = False) -> str:
    """Words for a flow's direction relative to the bow (the direction it moves towards, degrees):
    "onto the bow", "from astern", "on the beam from starboard", "quartering from port" …; ``short``: one word
    or two for axis labels ("onto bow", "stbd beam" …)."""
    rel = rel % 360.0
    if 157.5 <= rel <= 202.5:
        return "onto bow" if short else "onto the bow"
    if rel <= 22.5 or rel >= 337.5:
        return "from astern"
    stbd = rel < 180
    if short:
        side = "stbd" if stbd else "port"
        if 67.5 <= rel <= 112.5 or 247.5 <= rel <= 292.5:
            return f"{side} beam"
        return f"{side} bow" if 90 < rel < 270 else f"{side} qtr"
    side = "from starboard" if stbd else "from port"
    if 67.5 <= rel <= 112.5 or 247.5 <= rel <= 292.5:
        return f"on the beam {side}"
    # moving aft (90° < rel < 270°): it comes from forward, on the bow; else from aft, on the quarter
    return f"{'on the bow' if 90 < rel < 270 else 'on the quarter'} {side}"
