r"""Mass properties for an imported hydrodynamic database: the vessel file of a body boatland did not build.

WAMIT, NEMOH and many BEMIO files carry no mass matrix, and a time-domain run needs one. A vessel
file with a ``[bem]`` table instead of a ``[hull]`` names the BEM output and gives the body's mass
properties::

    name = "sphere"

    [bem]
    file = "sphere.h5"             # BEM output `boatland hydro import` reads, relative to this file
    # format = "wamit"             # force a reader
    # rho = 1025.0                 # for formats that do not store it (WAMIT)
    # weight_in_restoring = true   # the database's C holds the weight terms of its own CoG (default)

    [inertia]
    mass = 261.7e3                 # [kg]; default: ρ∇ of the database
    cog = [0.0, 0.0, -2.0]         # centre of gravity in the database's frame [m]; default: its own
    r_xx = 3.16                    # radii of gyration about the CoG [m] ... or i_xx, i_yy, i_zz [kg m²]
    r_yy = 3.16
    r_zz = 3.16                    # missing: I_zz = I_xx + I_yy (noted)

The same checks as a built vessel (:mod:`boatland.vessel.files`) apply, against what the database says
about itself: the mass equals ρ∇ of the database within :data:`MASS_TOLERANCE` (a floating body
displaces its weight), the principal moments of inertia obey the triangle inequality, and the body is
stable in roll and pitch with this centre of gravity (C44, C55 > 0). A centre of gravity off the
vertical through the centre of buoyancy is noted (the body would heel or trim; the database is for
its own waterline).

Restoring
---------
BEM codes report the restoring matrix about the reference point ``o`` with the weight terms of the
centre of gravity they were given (WAMIT ``.hst``, NEMOH ``KH.dat``, AQWA, Capytaine with a centre of
mass; checked on the hemisphere of ``tests/data/refdata``: C44 = m g (z_o − z_G) + ρ g (I_T + ∇ (z_B − z_o))).
The weight terms of a mass m at :math:`r = r_G - o` are

.. math::
    W_{44} = W_{55} = -m g r_z, \qquad W_{46} = m g r_x, \qquad W_{56} = m g r_y,

and the database's C is moved to the vessel file's mass and centre of gravity as
:math:`C = C_{db} - W(m_{db}, r_{G,db}) + W(m, r_G)` (Newman 1977, *Marine Hydrodynamics* §6.16; the
WAMIT User Manual, "hydrostatic restoring"), with :math:`m_{db}` the database's own mass (its mass
matrix, else ρ∇). With ``weight_in_restoring = false`` the database's C is taken as pure hydrostatics
and W(m, r_G) is added.

The mass matrix is :func:`boatland.vessel.database.rigid_body_mass_matrix` about the reference point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from boatland.vessel.database import HydroDB, rigid_body_mass_matrix
from boatland.tomlspec import Key, Problems, SpecError, Table, Vector, validate

__all__ = ["IMPORTED_SCHEMA", "MASS_TOLERANCE", "MassProperties", "apply_mass_properties", "database_files",
           "load_imported", "mass_property_problems", "weight_terms"]

#: The mass must equal ρ∇ of the database within this fraction (as a built CTV's, vessel.MASS_TOLERANCE).
MASS_TOLERANCE = 0.01
#: Horizontal CoG–CoB offset, as a fraction of the body's size (∛∇), above which a note says it heels/trims.
OFFSET_NOTE = 1e-3

_AXES = ("xx", "yy", "zz")

#: The vessel file of an imported database (module docstring).
IMPORTED_SCHEMA = Table({
    "name": Key(str, required=True, doc="vessel name"),
    "description": Key(str, default="", doc="free text"),
    "bem": Table({
        "file": Key(str, required=True, doc="BEM output boatland reads (WAMIT, NEMOH, AQWA, Capytaine, BEMIO), "
                                            "relative to this file"),
        "format": Key(str, choices=("bemio", "wamit", "nemoh", "aqwa", "capytaine"), doc="force a reader"),
        "rho": Key(float, gt=0.0, doc="water density [kg/m³] for formats that do not store it"),
        "g": Key(float, gt=0.0, doc="gravity [m/s²] for formats that do not store it"),
        "weight_in_restoring": Key(bool, default=True,
                                   doc="the database's restoring matrix holds the weight terms of its own centre "
                                       "of gravity (WAMIT, NEMOH, AQWA, Capytaine do)"),
    }, required=True, doc="the BEM output"),
    "inertia": Table({
        "mass": Key(float, gt=0.0, doc="mass [kg]; default ρ∇ of the database"),
        "cog": Vector(size=3, names=("x", "y", "z"), doc="centre of gravity in the database's frame [m]; default "
                                                          "the database's"),
        **{f"r_{ax}": Key(float, gt=0.0, doc=f"radius of gyration about the CoG, {ax} [m]") for ax in _AXES},
        **{f"i_{ax}": Key(float, gt=0.0, doc=f"moment of inertia about the CoG, {ax} [kg m²]") for ax in _AXES},
    }, required=True),
})


@dataclass(frozen=True)
class MassProperties:
    """Mass, centre of gravity and inertia to give a database, as a vessel file or ``hydro import`` flags
    state them (``None``: take the database's, where that is allowed).

    Parameters
    ----------
    mass : float, optional
        [kg]; None: ρ∇ of the database.
    cog : tuple of 3 floats, optional
        Centre of gravity in the database's frame [m]; None: the database's.
    radii, inertia : tuple of 3 (float or None), optional
        Radii of gyration [m] or principal moments [kg m²] about the CoG, xx, yy, zz; one of each pair;
        I_zz may be missing (then I_xx + I_yy).
    weight_in_restoring : bool
        The database's C holds the weight of its own CoG (module docstring).
    keys : dict
        Names of the inputs for messages (vessel-file key paths or command-line flags).
    """

    mass: float | None = None
    cog: tuple | None = None
    radii: tuple = (None, None, None)
    inertia: tuple = (None, None, None)
    weight_in_restoring: bool = True
    keys: dict = field(default_factory=lambda: {
        "mass": "inertia.mass", "cog": "inertia.cog", "weight_in_restoring": "bem.weight_in_restoring",
        **{f"r_{a}": f"inertia.r_{a}" for a in _AXES}, **{f"i_{a}": f"inertia.i_{a}" for a in _AXES}})


@dataclass(frozen=True)
class ImportedVesselSpec:
    """A vessel file with a ``[bem]`` table (module docstring): where the BEM output is and its mass
    properties."""

    name: str
    bem_file: Path
    mass_properties: MassProperties
    description: str = ""
    fmt: str | None = None
    rho: float | None = None
    g: float | None = None
    source: str = ""


def weight_terms(mass: float, r, g: float) -> np.ndarray:
    r"""Weight terms W (6×6) of the restoring matrix for a mass at ``r`` = CoG − reference point."""
    rx, ry, rz = np.asarray(r, dtype=float)
    W = np.zeros((6, 6))
    W[3, 3] = W[4, 4] = -mass * g * rz
    W[3, 5] = mass * g * rx
    W[4, 5] = mass * g * ry
    return W


def _db_mass(db: HydroDB) -> float | None:
    if db.M is not None:
        return float(db.M[0, 0])
    if db.disp_vol > 0:
        return db.rho * db.disp_vol
    return None


def _resolve(db: HydroDB, mp: MassProperties) -> tuple[float, np.ndarray, np.ndarray, list[str]]:
    """(mass, cog, principal inertia about the CoG, notes) of ``mp`` on ``db``."""
    notes = []
    if mp.mass is not None:
        mass = float(mp.mass)
    else:
        mass = db.rho * db.disp_vol
        notes.append(f"mass = ρ∇ of the database = {mass:.6g} kg")
    cog = np.asarray(mp.cog if mp.cog is not None else db.cog, dtype=float)
    if mp.cog is None:
        notes.append(f"centre of gravity {tuple(float(c) for c in cog)} m from the database")
    inertia = []
    for k, ax in enumerate(_AXES):
        r, i = mp.radii[k], mp.inertia[k]
        inertia.append(float(i) if i is not None else (mass * r * r if r is not None else math.nan))
    if math.isnan(inertia[2]):
        inertia[2] = inertia[0] + inertia[1]
        notes.append(f"I_zz not given: estimated as I_xx + I_yy = {inertia[2]:.6g} kg m² (the largest value the "
                     "triangle inequality of principal moments allows)")
    return mass, cog, np.array(inertia), notes


def mass_property_problems(db: HydroDB, mp: MassProperties) -> list[tuple[str, str]]:
    """Every problem of giving ``db`` the mass properties ``mp`` (module docstring), as ``(key, message)``
    with the keys of ``mp.keys``."""
    key = mp.keys
    out: list[tuple[str, str]] = []
    for name, v in (("mass", mp.mass), *((f"r_{a}", mp.radii[k]) for k, a in enumerate(_AXES)),
                    *((f"i_{a}", mp.inertia[k]) for k, a in enumerate(_AXES))):
        if v is not None and not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            out.append((key[name], f"must be a finite number > 0, got {v!r}"))
    if mp.cog is not None and not (len(mp.cog) == 3 and all(math.isfinite(float(c)) for c in mp.cog)):
        out.append((key["cog"], f"expected three finite coordinates [x, y, z] in m, got {mp.cog!r}"))
    for k, ax in enumerate(_AXES):
        if mp.radii[k] is not None and mp.inertia[k] is not None:
            out.append((key[f"i_{ax}"], f"give either {key[f'r_{ax}']} or {key[f'i_{ax}']}, not both"))
        elif ax != "zz" and mp.radii[k] is None and mp.inertia[k] is None:
            out.append((key[f"r_{ax}"], f"missing: give {key[f'r_{ax}']} (radius of gyration about the CoG, m) or "
                                        f"{key[f'i_{ax}']} (kg m²)"))
    if mp.mass is None and db.disp_vol <= 0:
        out.append((key["mass"], f"missing: the database {db.name!r} does not give its displaced volume, so the "
                                 "mass cannot default to ρ∇"))
    if out:
        return out
    mass, cog, inertia, _ = _resolve(db, mp)
    if db.disp_vol > 0:
        m_db = db.rho * db.disp_vol
        if abs(mass - m_db) > MASS_TOLERANCE * m_db:
            out.append((key["mass"], f"{mass:g} kg differs from ρ∇ = {m_db:.6g} kg of the database by "
                                     f"{(mass - m_db) / m_db:+.1%} (more than {MASS_TOLERANCE:.0%}): a floating "
                                     "body displaces its mass; the database is for that waterline"))
    for a, b, c in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        if inertia[a] > (inertia[b] + inertia[c]) * (1 + 1e-9):
            ax = _AXES[a]
            name = key[f"i_{ax}"] if mp.inertia[a] is not None else key[f"r_{ax}"]
            out.append((name, f"I_{ax} = {inertia[a]:.4g} kg m² exceeds the sum of the other two principal "
                              f"moments ({inertia[b] + inertia[c]:.4g}): no rigid body has such inertia"))
    if mp.weight_in_restoring and _db_mass(db) is None:
        out.append((key["weight_in_restoring"], f"the database {db.name!r} says neither its mass nor its displaced "
                                                "volume, so the weight its restoring matrix holds is unknown: set it "
                                                "false if that matrix is pure hydrostatics"))
        return out
    C = restoring_for(db, mass, cog, mp.weight_in_restoring)
    bad = [f"{what} (C{i + 1}{i + 1} = {C[i, i]:.4g} ≤ 0, GM = {C[i, i] / (mass * db.g):.3g} m)"
           for i, what in ((3, "roll"), (4, "pitch")) if C[i, i] <= 0]
    if bad:
        out.append((key["cog"], f"{tuple(float(c) for c in cog)} m makes the body unstable in " + " and in ".join(bad)))
    return out


def restoring_for(db: HydroDB, mass: float, cog, weight_in_restoring: bool = True) -> np.ndarray:
    """The database's restoring matrix moved to ``mass`` at ``cog`` (module docstring)."""
    r = np.asarray(cog, dtype=float) - db.ref_point
    C = np.array(db.C, dtype=float)
    if weight_in_restoring:
        C = C - weight_terms(_db_mass(db), db.cog - db.ref_point, db.g)
    return C + weight_terms(mass, r, db.g)


def apply_mass_properties(db: HydroDB, mp: MassProperties, source: str = "") -> HydroDB:
    """``db`` with the mass matrix, centre of gravity and restoring of ``mp`` (checked first).

    Raises
    ------
    SpecError
        Every problem of :func:`mass_property_problems`, with its key, naming ``source``.
    """
    problems = mass_property_problems(db, mp)
    if problems:
        raise SpecError(source or f"mass properties of {db.name!r}", problems)
    mass, cog, inertia, notes = _resolve(db, mp)
    C = restoring_for(db, mass, cog, mp.weight_in_restoring)
    M = rigid_body_mass_matrix(mass, cog, inertia, db.ref_point)
    what = f" from {source}" if source else ""
    notes = [f"mass properties{what}: mass {mass:.6g} kg, CoG {tuple(round(float(c), 6) for c in cog)} m, "
             f"I_cog {tuple(float(f'{i:.6g}') for i in inertia)} kg m²"
             + ("; replaces the database's own mass matrix" if db.M is not None else ""), *notes]
    dC = np.max(np.abs(C - db.C))
    if dC > 0:
        notes.append(f"restoring moved to this mass and CoG: C44 {db.C[3, 3]:.6g} → {C[3, 3]:.6g}, "
                     f"C55 {db.C[4, 4]:.6g} → {C[4, 4]:.6g}")
    if db.drift is not None and (db.M is None or not np.allclose(M, db.M, rtol=1e-6, atol=1e-9 * mass)
                                 or not np.allclose(C, db.C, rtol=1e-6, atol=1e-9 * max(np.max(np.abs(db.C)), 1.0))):
        notes.append("mean drift kept as the BEM output gives it: it was computed with the motions of the BEM "
                     "run's own mass properties, not these (recompute it with boatland.hydro.drift.add_drift "
                     "when they differ much)")
    size = max(db.disp_vol, 1e-300) ** (1 / 3)
    off = np.hypot(*(cog[:2] - db.cob[:2]))
    if db.disp_vol > 0 and off > OFFSET_NOTE * size:
        notes.append(f"centre of gravity {off:.3g} m off the vertical through the centre of buoyancy: the body would "
                     "heel or trim; the database is for its own waterline, with the weight couplings in C")
    prov = db.provenance
    for n in notes:
        prov = prov.with_note(n)
    return db.replace(M=M, C=C, cog=cog, provenance=prov)


def load_imported(data: dict[str, Any], path: Path, problems: Problems) -> ImportedVesselSpec | None:
    """The :class:`ImportedVesselSpec` of a parsed vessel file with a ``[bem]`` table; its problems go into
    ``problems`` (None when there are any)."""
    d = validate(data, IMPORTED_SCHEMA, problems)
    if problems:
        return None
    bem, inert = d["bem"], d["inertia"]
    mp = MassProperties(mass=inert.get("mass"), cog=tuple(inert["cog"]) if "cog" in inert else None,
                        radii=tuple(inert.get(f"r_{a}") for a in _AXES),
                        inertia=tuple(inert.get(f"i_{a}") for a in _AXES),
                        weight_in_restoring=bem["weight_in_restoring"])
    for k, ax in enumerate(_AXES):
        if mp.radii[k] is not None and mp.inertia[k] is not None:
            problems.add(f"inertia.i_{ax}", f"give either inertia.r_{ax} or inertia.i_{ax}, not both")
        elif ax != "zz" and mp.radii[k] is None and mp.inertia[k] is None and not problems.has(f"inertia.r_{ax}"):
            problems.add(f"inertia.r_{ax}", f"missing: give inertia.r_{ax} (radius of gyration about the CoG, m) "
                                            f"or inertia.i_{ax} (kg m²)")
    file = Path(bem["file"]).expanduser()
    file = file if file.is_absolute() else path.parent / file
    if not file.exists():
        problems.add("bem.file", f"not found: {file}")
    if problems:
        return None
    return ImportedVesselSpec(name=d["name"], description=d.get("description", ""), bem_file=file,
                              mass_properties=mp, fmt=bem.get("format"), rho=bem.get("rho"), g=bem.get("g"),
                              source=str(path))


def database_files(path: str | Path) -> list[Path]:
    """The files a database path reads: itself, and for a ``[bem]`` vessel file also its BEM output (when
    that is one file), so that a campaign store belongs to both."""
    from boatland.tomlspec import parse_toml_file

    path = Path(path)
    out = [path]
    if path.suffix.lower() == ".toml":
        try:
            bem = parse_toml_file(path).get("bem", {})
            file = Path(str(bem.get("file", ""))).expanduser()
        except Exception:  # noqa: BLE001 — an unreadable file is reported by the loading, not here
            return out
        file = file if file.is_absolute() else path.parent / file
        if file.is_file():
            out.append(file)
    return out
