"""A scenario on a synthetic box vessel, shared by the tests of the scenario format, its checks and its setup:
``make(changes, remove)`` builds a CTV-like landing trial from a parsed document; ``box_db`` is a 24 m ×
9 m × 1.4 m, 90 t vessel with a box hull mesh whose figures are easy to check by hand (the ``box_db``
fixture of tests/conftest.py)."""

from __future__ import annotations

import copy

import numpy as np

from boatland.scenario.scenario import Scenario, scenario_from_dict
from boatland.vessel.database import HullMesh, HydroDB, rigid_body_mass_matrix

# A CTV-like landing trial as a parsed document (what tomllib returns).
BASE = {
    "name": "t",
    "simulation": {"duration": 100.0, "dt": 0.05, "seed": 3},
    "vessel": {"database": "box"},
    "landing": {"monopile_diameter": 6.5, "bearing_deg": 180.0, "strut_spacing": 1.5, "strut_diameter": 0.35,
                "standoff": 1.2},
    "fender": {"points": [[12.3, 0.75, 1.5], [12.3, -0.75, 1.5]], "stiffness": 1.0e6, "damping": 4.0e4,
               "mu_s": 0.6, "mu_k": 0.5},
    "thrust": {"force": 80e3, "position": [-10.5, 0.0, -0.9]},
    "sea": {"kind": "jonswap", "Hs": 1.5, "Tp": 7.0, "relative_direction_deg": 180.0},
}


def make(changes=None, remove=(), **kw) -> Scenario:
    doc = copy.deepcopy(BASE)
    for path in remove:
        sec, _, key = path.partition(".")
        if key:
            doc[sec].pop(key)
        else:
            doc.pop(sec)
    for path, value in (changes or {}).items():
        sec, _, key = path.partition(".")
        if key:
            doc.setdefault(sec, {})[key] = value
        else:
            doc[sec] = value
    return scenario_from_dict(doc, source="t.toml", **kw)


def box_vessel_db() -> HydroDB:
    """A synthetic 24 m × 9 m × 1.4 m, 90 t vessel (box hull mesh), enough for the geometric and dt checks."""
    omega = np.arange(1, 51) * 0.1
    nf = omega.size
    A = np.broadcast_to(np.diag([5e3, 6e4, 8e4, 7e5, 1.5e6, 2.7e6])[:, :, None], (6, 6, nf)).copy()
    B = np.broadcast_to(np.diag([1e3, 1e4, 1e5, 1e5, 1e6, 1e6])[:, :, None], (6, 6, nf)) * np.exp(-omega)
    M = rigid_body_mass_matrix(9e4, (0.0, 0.0, 1.3), (1.1e6, 3.6e6, 3.6e6))
    C = np.diag([0.0, 0.0, 1.3e6, 1.1e7, 1.5e8, 0.0])
    v = np.array([[x, y, z] for x in (-12, 12) for y in (-4.5, 4.5) for z in (-1.4, 0.0)], float)
    faces = np.array([[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]])
    return HydroDB(omega=omega, A=A, B=B, X=np.zeros((6, 2, nf), complex), wave_dir_deg=[0.0, 180.0], C=C,
                   A_inf=A[:, :, -1], M=M, disp_vol=9e4 / 1025, name="box", mesh=HullMesh(v, faces))
