r"""The hydrodynamic database: one vessel's linear frequency-domain hydrodynamics.

Everything the time-domain and frequency-domain services need about the hull in waves lives in one
typed, validated, immutable :class:`HydroDB`. Readers of BEM output (WAMIT, NEMOH, AQWA, Capytaine,
BEMIO HDF5) and the Capytaine builder all produce it; the BEMIO HDF5 writer stores it.

Equation of motion it serves (Cummins 1962; San Nicolás Méndez 2024 eq. 3.37):

.. math::
    (M + A_\infty)\ddot x + \int_0^t K(t-\tau)\dot x(\tau)\,d\tau + C x = F_{exc}(t) + \dots,
    \qquad K(t) = \frac{2}{\pi}\int_0^\infty B(\omega)\cos\omega t\,d\omega

and, in the frequency domain (San Nicolás Méndez 2024 eq. 3.31),

.. math:: \left[-\omega^2 (M + A(\omega)) + i\omega B(\omega) + C\right]\hat x = X(\omega,\beta)\,a .

Phase convention, frames, DOF order and wave direction: see :mod:`boatland.conventions`
(exp(+iωt), phase = lead over the incident crest at the reference point).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from boatland.conventions import DOF_NAMES, N_DOF
from boatland.errors import BoatlandInputError, HydroDataError
from boatland.irf.impulse import describe_spikes

__all__ = ["HydroDB", "HullMesh", "Provenance", "rigid_body_mass_matrix", "roll_critical_damping", "skew"]

#: The largest entry a mass matrix may have (kg, kg·m², kg·m): an assumption, far above any vessel boatland is
#: for (a CTV's is ~1e5 kg and ~1e7 kg·m²; a supertanker's mass 5e8 kg) — beyond it an input is a mistake.
MASS_LIMIT = 1e12


def _frozen(a, dtype=float) -> np.ndarray:
    arr = np.array(a, dtype=dtype, copy=True)
    arr.setflags(write=False)
    return arr


def skew(r) -> np.ndarray:
    """Cross-product matrix ``S(r)`` with ``S(r) @ v == np.cross(r, v)``."""
    rx, ry, rz = np.asarray(r, dtype=float)
    return np.array([[0.0, -rz, ry], [rz, 0.0, -rx], [-ry, rx, 0.0]])


def rigid_body_mass_matrix(mass: float, cog, inertia_cog, ref_point=(0.0, 0.0, 0.0)) -> np.ndarray:
    r"""6×6 rigid-body mass matrix about ``ref_point``.

    .. math::
        M = \begin{bmatrix} m I & -m S(r) \\ m S(r) & I_G + m (r^\top r\, I - r r^\top) \end{bmatrix},
        \qquad r = r_G - r_{ref}

    (Fossen 2011, *Handbook of Marine Craft Hydrodynamics*, eq. 3.44 and the parallel-axis theorem).

    Parameters
    ----------
    mass : float
        Mass m [kg].
    cog : array_like, shape (3,)
        Centre of gravity in the body frame [m].
    inertia_cog : array_like, shape (3, 3) or (3,)
        Inertia tensor about the centre of gravity [kg m²] (a 3-vector means its diagonal).
    ref_point : array_like, shape (3,)
        Point the matrix is taken about [m].
    """
    inertia = np.asarray(inertia_cog, dtype=float)
    if inertia.shape == (3,):
        inertia = np.diag(inertia)
    r = np.asarray(cog, dtype=float) - np.asarray(ref_point, dtype=float)
    S = skew(r)
    M = np.zeros((6, 6))
    M[:3, :3] = mass * np.eye(3)
    M[:3, 3:] = -mass * S
    M[3:, :3] = mass * S
    M[3:, 3:] = inertia + mass * (r @ r * np.eye(3) - np.outer(r, r))
    return M


@dataclass(frozen=True, eq=False)
class HullMesh:
    """Wetted hull panels in the body frame (for diffraction forces and the 3D view).

    Parameters
    ----------
    vertices : ndarray, shape (Nv, 3)
        Vertex coordinates [m], body frame.
    faces : ndarray of int, shape (Np, 4)
        Vertex indices of each quadrilateral panel, counter-clockwise seen from the water (normal out
        of the hull into the fluid); a triangle repeats its last vertex.
    """

    vertices: np.ndarray
    faces: np.ndarray

    def __post_init__(self):
        v = np.asarray(self.vertices, dtype=float)
        f = np.asarray(self.faces)
        if v.ndim != 2 or v.shape[1] != 3 or not np.all(np.isfinite(v)):
            raise HydroDataError(None, "mesh.vertices", f"expected a finite (Nv, 3) array, got shape {v.shape}")
        if f.ndim != 2 or f.shape[1] != 4 or (f.size and (f.min() < 0 or f.max() >= len(v))):
            raise HydroDataError(None, "mesh.faces", f"expected (Np, 4) vertex indices in [0, {len(v)}), got shape {f.shape}")
        object.__setattr__(self, "vertices", _frozen(v))
        object.__setattr__(self, "faces", _frozen(f, dtype=np.int64))

    @property
    def n_panels(self) -> int:
        return int(self.faces.shape[0])


@dataclass(frozen=True)
class Provenance:
    """Where a database came from.

    Attributes
    ----------
    source : str
        The file (or builder input) it was made from.
    solver : str
        The BEM code that computed it (``"WAMIT"``, ``"NEMOH"``, ``"AQWA"``, ``"CAPYTAINE"``, ...).
    created : str
        When the BEM data was computed or imported (ISO 8601), as far as known.
    reader : str
        The boatland reader or builder that produced this object.
    notes : tuple of str
        What the reader or builder changed or assumed (dropped frequencies, assumed ρ, ...).
    """

    source: str = ""
    solver: str = ""
    created: str = ""
    reader: str = ""
    notes: tuple[str, ...] = ()

    def with_note(self, note: str) -> "Provenance":
        return dataclasses.replace(self, notes=self.notes + (note,))


@dataclass(frozen=True, eq=False)
class HydroDB:
    r"""Linear frequency-domain hydrodynamics of one rigid vessel (6 DOF), dimensional, SI.

    Parameters
    ----------
    omega : ndarray, shape (Nf,)
        Wave frequencies [rad/s], finite, > 0, strictly increasing.
    A, B : ndarray, shape (6, 6, Nf)
        Added mass and radiation damping about ``ref_point`` (kg, kg·m, kg·m² and N·s/m, ...).
        ``A[i, j, k]``: force in DOF i due to motion of DOF j at ``omega[k]``.
    X : ndarray of complex, shape (6, Nb, Nf)
        Excitation force per unit wave amplitude [N/m, N·m/m], exp(+iωt) convention, referred to the
        incident elevation at the reference point (:mod:`boatland.conventions`).
    wave_dir_deg : ndarray, shape (Nb,)
        Wave directions β [deg], direction of travel, strictly increasing.
    C : ndarray, shape (6, 6)
        Linear restoring matrix about ``ref_point``: hydrostatics plus the gravity terms of the
        vessel's weight (as WAMIT, NEMOH, AQWA and Capytaine report it when given the centre of
        gravity).
    A_inf, A_0 : ndarray, shape (6, 6), optional
        Added mass at ω = ∞ and ω = 0, when the solver computed them.
    M : ndarray, shape (6, 6), optional
        Rigid-body mass matrix about ``ref_point`` (see :func:`rigid_body_mass_matrix`); None when the
        source does not say.
    ref_point, cog, cob : ndarray, shape (3,)
        Reference point (about which A, B, C, X, M are given), centre of gravity and centre of
        buoyancy [m], in the frame of the BEM input: x, y as the solver's, z = 0 on the calm waterline.
        The simulation's body frame (:mod:`boatland.conventions`) has its origin at ``ref_point``.
    disp_vol : float
        Displaced volume [m³].
    water_depth : float
        Water depth [m]; ``inf`` for deep water.
    rho, g : float
        Water density [kg/m³] and gravity [m/s²] of the computation.
    name : str
        Vessel name.
    provenance : Provenance
        Source file, solver, dates, and notes on what readers changed.
    mesh : HullMesh, optional
        Wetted hull panels (stored by the builder; needed for pile diffraction).
    topsides : HullMesh, optional
        The hull above the waterline (topsides, deck, deckhouse) in the body frame, for the viewers
        only (:mod:`boatland.record.scene`); no computation uses it.
    drift : ndarray, shape (6, Nb, Nf), optional
        Mean (second-order) wave drift force and moment per unit wave amplitude squared [N/m², N·m/m²] on
        the vessel at rest, at ``wave_dir_deg`` and ``omega`` (same layout as ``X``), body axes at the mean
        position, moments about ``ref_point``: a regular wave of amplitude a pushes with ``drift * a**2``.
        None when the source has none. How it was obtained and which DOFs are meaningful (far-field
        methods give surge, sway and yaw only, the others 0) is in a provenance note beginning
        ``"mean drift:"``; see :mod:`boatland.hydro.drift`. :meth:`replace` carries it to a subset of the
        frequencies or directions.
    """

    omega: np.ndarray
    A: np.ndarray
    B: np.ndarray
    X: np.ndarray
    wave_dir_deg: np.ndarray
    C: np.ndarray
    A_inf: np.ndarray | None = None
    A_0: np.ndarray | None = None
    M: np.ndarray | None = None
    ref_point: np.ndarray = field(default_factory=lambda: np.zeros(3))
    cog: np.ndarray = field(default_factory=lambda: np.zeros(3))
    cob: np.ndarray = field(default_factory=lambda: np.zeros(3))
    disp_vol: float = 0.0
    water_depth: float = np.inf
    rho: float = 1025.0
    g: float = 9.81
    name: str = "vessel"
    provenance: Provenance = field(default_factory=Provenance)
    mesh: HullMesh | None = None
    topsides: HullMesh | None = None
    drift: np.ndarray | None = None

    def __post_init__(self):
        src = self.provenance.source or None

        def bad(where, msg):
            return HydroDataError(src, where, msg)

        omega = np.asarray(self.omega, dtype=float)
        if omega.ndim != 1 or omega.size < 2:
            raise bad("omega", f"expected at least 2 frequencies in a 1-D array, got shape {omega.shape}")
        if not np.all(np.isfinite(omega)) or omega[0] <= 0:
            raise bad("omega", "frequencies must be finite and > 0 (ω = 0 and ω = ∞ belong in A_0 and A_inf)")
        if np.any(np.diff(omega) <= 0):
            k = int(np.argmax(np.diff(omega) <= 0))
            raise bad("omega", f"frequencies must be strictly increasing; omega[{k}] = {omega[k]:.6g} "
                               f"is followed by {omega[k + 1]:.6g}")
        nf = omega.size
        beta = np.asarray(self.wave_dir_deg, dtype=float).reshape(-1)
        if beta.size < 1 or not np.all(np.isfinite(beta)) or np.any(np.diff(beta) <= 0):
            raise bad("wave_dir_deg", "expected one or more finite, strictly increasing directions [deg]")
        nb = beta.size

        def check(name, value, shape, dtype=float, optional=False):
            if value is None:
                if optional:
                    return None
                raise bad(name, f"missing; expected shape {shape}")
            arr = np.asarray(value, dtype=dtype)
            if arr.shape != shape:
                raise bad(name, f"expected shape {shape}, got {arr.shape}")
            if not np.all(np.isfinite(arr)):
                n = int(np.count_nonzero(~np.isfinite(arr)))
                raise bad(name, f"{n} value(s) are NaN or infinite; expected finite numbers")
            return _frozen(arr, dtype)

        object.__setattr__(self, "omega", _frozen(omega))
        object.__setattr__(self, "wave_dir_deg", _frozen(beta))
        object.__setattr__(self, "A", check("A", self.A, (N_DOF, N_DOF, nf)))
        object.__setattr__(self, "B", check("B", self.B, (N_DOF, N_DOF, nf)))
        object.__setattr__(self, "X", check("X", self.X, (N_DOF, nb, nf), dtype=complex))
        object.__setattr__(self, "C", check("C", self.C, (N_DOF, N_DOF)))
        for name in ("A_inf", "A_0", "M"):
            object.__setattr__(self, name, check(name, getattr(self, name), (N_DOF, N_DOF), optional=True))
        object.__setattr__(self, "drift", check("drift", self.drift, (N_DOF, nb, nf), optional=True))
        for name in ("ref_point", "cog", "cob"):
            object.__setattr__(self, name, check(name, np.reshape(getattr(self, name), -1), (3,)))
        for name, lo in (("rho", 0.0), ("g", 0.0), ("water_depth", 0.0)):
            v = float(getattr(self, name))
            if not v > lo or np.isnan(v) or (name != "water_depth" and not np.isfinite(v)):
                raise bad(name, f"expected a number > {lo:g}, got {v!r}")
            object.__setattr__(self, name, v)
        dv = float(self.disp_vol)
        if not np.isfinite(dv) or dv < 0:
            raise bad("disp_vol", f"expected a finite volume ≥ 0, got {dv!r}")
        object.__setattr__(self, "disp_vol", dv)
        if self.M is not None and not (self.M[0, 0] > 0 and np.allclose(self.M, self.M.T, rtol=1e-9, atol=1e-9 * abs(self.M[0, 0]))):
            raise bad("M", "the mass matrix must be symmetric with a positive mass")
        if self.M is not None and np.max(np.abs(self.M)) > MASS_LIMIT:
            raise bad("M", f"entries up to {np.max(np.abs(self.M)):.3g}: beyond {MASS_LIMIT:.0e} (kg, kg·m², kg·m) no "
                           "vessel's mass matrix reaches — a unit error or a damaged file?")

    # ------------------------------------------------------------------ derived quantities
    @property
    def n_freq(self) -> int:
        return int(self.omega.size)

    @property
    def n_dir(self) -> int:
        return int(self.wave_dir_deg.size)

    @property
    def mass(self) -> float | None:
        """Vessel mass [kg] from ``M``, or None when the mass matrix is unknown."""
        return None if self.M is None else float(self.M[0, 0])

    def replace(self, **changes: Any) -> "HydroDB":
        """A new database with some fields changed (validated again).

        The mean drift follows a change of ``omega`` or ``wave_dir_deg`` that does not give ``drift``: it is
        taken at the new frequencies and directions when the table holds every one of them (directions
        modulo 360°, e.g. a half circle cut out of a full one); otherwise it is dropped (None) with a
        provenance note, since nothing can be said about frequencies or directions it was not computed at.
        """
        if self.drift is not None and "drift" not in changes and ("omega" in changes or "wave_dir_deg" in changes):
            drift, note = _carried_drift(self, changes.get("omega", self.omega), changes.get("wave_dir_deg", self.wave_dir_deg))
            changes["drift"] = drift
            if note:
                changes["provenance"] = changes.get("provenance", self.provenance).with_note(note)
        return dataclasses.replace(self, **changes)

    def natural_periods(self, dofs=(2, 3, 4)) -> dict[str, float | None]:
        r"""Undamped natural periods of single DOFs from M, A(ω) and C.

        Solves :math:`T = 2\pi\sqrt{(M_{ii} + A_{ii}(2\pi/T))/C_{ii}}` by fixed-point iteration on the
        frequency-dependent added mass (linear interpolation in ω; A∞ above the band, the lowest
        value below it). Uncoupled: the usual first estimate (Naaijen 2012, "natural periods").

        Without a mass matrix the heave mass is taken as ρ∇ (exact for a freely floating body in
        equilibrium); roll and pitch then need the inertia and are not given.

        Returns
        -------
        dict
            ``{"heave": T3, "roll": T4, "pitch": T5}`` [s]; None where ``C_ii ≤ 0`` (no restoring)
            or the inertia is unknown.
        """
        out: dict[str, float | None] = {}
        for i in dofs:
            name = DOF_NAMES[i]
            if self.M is not None:
                m = self.M[i, i]
            elif i < 3 and self.disp_vol > 0:
                m = self.rho * self.disp_vol
            else:
                m = 0.0
            if self.C[i, i] <= 0 or m <= 0:
                out[name] = None
                continue
            a_hi = self.A_inf[i, i] if self.A_inf is not None else self.A[i, i, -1]
            w = np.sqrt(self.C[i, i] / (m + a_hi))
            for _ in range(200):
                a = np.interp(w, self.omega, self.A[i, i], left=self.A[i, i, 0], right=a_hi)
                w_new = np.sqrt(self.C[i, i] / max(m + a, 1e-12 * m))
                if abs(w_new - w) < 1e-10 * w:
                    w = w_new
                    break
                w = 0.5 * (w + w_new)
            out[name] = float(2 * np.pi / w)
        return out

    def diagnostics(self) -> list[str]:
        """Warnings a user should see before trusting this database (one line each).

        Checks: negative radiation damping on the diagonal (beyond round-off), missing A∞ or A₀,
        irregular-frequency spikes in the diagonal damping, a damping band that stops before B has
        decayed, and the notes the reader left (dropped NaN frequencies, assumptions).
        """
        warnings: list[str] = []
        B = self.B
        for i in range(N_DOF):
            bmax = np.max(np.abs(B[i, i]))
            if bmax == 0:
                continue
            neg = B[i, i] < -1e-6 * bmax
            if np.any(neg):
                w = self.omega[neg]
                warnings.append(f"negative damping B[{DOF_NAMES[i]}] at {neg.sum()} frequencies "
                                f"({w.min():.3g}–{w.max():.3g} rad/s), min {B[i, i].min():.3g}")
            spikes = describe_spikes(DOF_NAMES[i], self.omega, B[i, i])
            if spikes:
                warnings.append(spikes)
            tail = abs(B[i, i, -1]) / bmax
            if tail > 0.05 and i in (2, 3, 4):
                warnings.append(f"B[{DOF_NAMES[i]}] has not decayed at the top of the band "
                                f"(B(ω_max)/max B = {tail:.2f}): extend the band for IRFs")
        if self.A_inf is None:
            warnings.append("no infinite-frequency added mass A∞ in the source: it will be estimated from "
                            "Ogilvie's relation (sensitive to the top of the band)")
        if self.M is None:
            warnings.append("no mass matrix in the source: give mass, centre of gravity and inertia before "
                            "a time-domain run")
        warnings.extend(self.provenance.notes)
        return warnings


def _carried_drift(db: HydroDB, omega, wave_dir_deg) -> tuple[np.ndarray | None, str]:
    """``db.drift`` at the frequencies ``omega`` and directions ``wave_dir_deg`` of a replaced database, or
    (None, why) when the table does not hold them all."""
    w_old, w_new = db.omega, np.asarray(omega, dtype=float).reshape(-1)
    b_old = np.mod(db.wave_dir_deg, 360.0)
    b_new = np.mod(np.asarray(wave_dir_deg, dtype=float).reshape(-1), 360.0)
    dw = np.abs(w_new[:, None] - w_old[None, :])
    db_ = np.abs(np.mod(b_new[:, None] - b_old[None, :] + 180.0, 360.0) - 180.0)
    found_w = dw <= 1e-9 * np.maximum(np.abs(w_new[:, None]), 1e-300)
    found_b = db_ <= 1e-6
    if found_w.any(axis=1).all() and found_b.any(axis=1).all():
        return db.drift[:, np.argmax(found_b, axis=1)][:, :, np.argmax(found_w, axis=1)], ""
    return None, ("mean drift dropped: the database was given frequencies or directions its drift table "
                  "does not hold (pass drift= with them)")


def roll_critical_damping(db: HydroDB) -> float:
    r"""Critical roll damping :math:`2\sqrt{(M_{44} + A_{44}(\omega_{44}))\,C_{44}}` [N m s/rad] of ``db``.

    ω_44 is the undamped roll natural frequency (:meth:`HydroDB.natural_periods`: A_44 taken at ω_44
    by fixed-point iteration).

    Raises
    ------
    BoatlandInputError
        No mass matrix, or no roll restoring (C44 ≤ 0).
    """
    T = db.natural_periods(dofs=(3,)).get("roll") if db.M is not None else None
    if T is None:
        raise BoatlandInputError(f"database {db.name!r}: no roll natural period (mass matrix missing or C44 ≤ 0), "
                                 "so vessel.damping.roll_critical_fraction cannot be turned into a damping")
    w = 2 * math.pi / T
    a_hi = db.A_inf[3, 3] if db.A_inf is not None else db.A[3, 3, -1]
    A44 = float(np.interp(w, db.omega, db.A[3, 3], left=db.A[3, 3, 0], right=a_hi))
    return 2.0 * math.sqrt((db.M[3, 3] + A44) * db.C[3, 3])
