r"""Build a hydrodynamic database for a parametric catamaran with Capytaine 3.0.

:func:`build_database` turns a :class:`~boatland.vessel.files.VesselSpec` into a
:class:`~boatland.vessel.database.HydroDB`; :func:`build_from_file` does it for a vessel file and
writes the BEMIO HDF5 database (atomically).

Numerics, chosen deliberately
-----------------------------
- **Mesh**: the hull form of the vessel file. The generalized Wigley catamaran of
  :mod:`boatland.vessel.wigley` is fore–aft symmetric: only a quarter is meshed — the port demihull's
  forebody — and Capytaine is told about both symmetry planes with nested
  :class:`capytaine.ReflectionSymmetricMesh` (``xOz`` inside, ``yOz`` outside), which cuts the
  influence matrices to four independent blocks; its centre of gravity need not be symmetric (it
  enters only M and C). The CTV form of :mod:`boatland.vessel.ctv_hull` (transom stern) is symmetric
  port–starboard only: the whole port demihull is meshed, transom included, with one ``xOz``
  reflection (two blocks, each twice as large: about four times the ctv24 cost for the same panel
  size). The part above the waterline (topsides, deck) goes into the database for the viewers only.
  Panel size: by default the largest panel edge is
  λ(ω_max)/8, i.e. at least 8 panels per shortest wavelength (Capytaine itself warns below ~5.7 for
  square panels: face radius > λ/8); the vessel file may set it or the panel counts, and fewer than
  4 panels per wavelength is refused (:mod:`boatland.vessel.files`). The figure is recorded in the
  provenance notes.
- **Lid** (irregular-frequency removal): Capytaine's lid generator (``generate_lid``) on the symmetric
  part of the mesh, square panels of side b/n_lid (``mesh.n_lid`` of the vessel file). The generator keeps
  only the panels that lie wholly inside the waterline, so the lid stops short of the hull (it covers
  about 85 % of the waterplane). A lid that covers the whole waterplane and meets the hull — boatland's
  own until 2026-12 — is wrong: with its edge on the hull panels the solution fails Haskind's relation by
  up to 16 % of the peak heave damping and 273 % of sway's, 2–5 % in the landing band (ctv27: B33 at 2 rad/s
  36.7 vs 21.6 kN s/m with Capytaine's lid and 21.3 without a lid; ``tests/hydro/test_builtin.py`` holds the
  relation). It sits
  at ``z = −min(0.05 T, d/2)``, where ``d`` is the deepest lid that still
  pushes the first irregular frequency of the lid-covered interior above ω_max (Capytaine's
  rectangular-box estimate, :meth:`AbstractMesh.lowest_lid_position`); not at ``z = 0``, where
  Capytaine would switch its Green-function singularity treatment with a warning.
- **Frequencies**: the vessel file's uniform grid. The top of the band should be where the
  radiation damping has decayed (IRFs); the ratio ``|B33(ω_max)| / max |B33|`` (and the largest
  value in the top 10 % of the band) is written into the provenance notes. Catamarans decay slowly
  and with wiggles (waves trapped between the demihulls), so that figure matters to the IRF step.
- **Limits**: in deep water, radiation problems at ω = 0 (A_0) and ω = ∞ (A_inf) are solved too.
  In finite depth Capytaine 3.0 has no ω = ∞ Green function; limits that fail are skipped with a note
  (A_inf is then estimated downstream from Ogilvie's relation).
- **Directions**: 0..180° are solved; 195..345° follow from port/starboard symmetry,
  :math:`X_i(-\beta) = s_i X_i(\beta)` with :data:`boatland.conventions.PORT_STARBOARD_SIGN`.
- **Mean drift** (``drift=True``, the default): the far-field (Maruo–Newman) surge, sway and yaw drift of
  the free-floating vessel from the Kochin functions of the same solves (:mod:`boatland.hydro.drift`),
  0..180° and mirrored like X; heave, roll and pitch drift are 0 (not computed).
- **Conventions**: Capytaine's complex amplitudes are exp(−iωt); excitation forces
  (Froude–Krylov + diffraction) are conjugated to boatland's exp(+iωt)
  (:mod:`boatland.conventions`). Capytaine's incident wave is referred to the origin = the
  reference point, and its wave direction is the direction of travel, as boatland's.
- **Restoring**: Capytaine's rigid-body hydrostatic stiffness with the vessel's mass and centre of
  gravity (hydrostatics plus the weight terms), cross-checked against the closed-form values of
  :class:`~boatland.vessel.wigley.WigleyCatamaran` or the quadrature of the lines of
  :class:`~boatland.vessel.ctv_hull.CTVCatamaran` (difference noted).
"""

from __future__ import annotations

import contextlib
import functools
import logging
import math
import sys
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Iterator

import numpy as np

from boatland.conventions import PORT_STARBOARD_SIGN, mirror_direction_deg
from boatland.hydro.drift import drift_from_results, far_field_note, imbalance_text
from boatland.vessel.ctv_hull import CTVCatamaran
from boatland.vessel.wigley import WigleyCatamaran
from boatland.vessel.database import HydroDB, Provenance
from boatland.vessel.files import VesselSpec, load_vessel

__all__ = ["build_database", "build_from_file", "capytaine_body", "lid_depth", "mirror_directions", "SOLVER"]

#: Capytaine's DOF names in boatland's DOF order (conventions.DOF_NAMES).
CPT_DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")
#: Solver name recorded in the provenance.
SOLVER = "CAPYTAINE 3.0.0"
#: Fraction of the band treated as "the top" in the damping-decay figure.
TOP_FRACTION = 0.1
#: Damping-decay figure above which a warning note is added.
DECAY_LIMIT = 0.05


@contextlib.contextmanager
def _quiet_capytaine(level: int = logging.ERROR) -> Iterator[None]:
    """Raise the level of Capytaine's own logger while building (mesh-quality and wavelength
    warnings are expected and handled here); the root logger is left alone."""
    log = logging.getLogger("capytaine")
    old = log.level
    log.setLevel(max(level, old))
    try:
        yield
    finally:
        log.setLevel(old)


def lid_depth(hull: WigleyCatamaran | CTVCatamaran, omega_max: float, g: float) -> float:
    r"""Depth of the irregular-frequency lid below the waterline [m], > 0.

    The first irregular frequency of a box of waterplane :math:`L \times b` closed by a lid at depth
    :math:`d` is :math:`\omega = \sqrt{\pi g q / \tanh(\pi d q)}`, :math:`q = \sqrt{L^{-2} + b^{-2}}`
    (Capytaine's estimate). It exceeds ω_max when :math:`d < \mathrm{artanh}(\pi g q/\omega_{max}^2)/(\pi q)`
    (any d when the argument is ≥ 1). The lid is put at ``min(0.05 T, d/2)``.
    """
    q = math.hypot(1.0 / hull.length, 1.0 / hull.demihull_beam)
    arg = math.pi * g * q / omega_max ** 2
    d_max = math.atanh(arg) / (math.pi * q) if arg < 1.0 else math.inf
    return min(0.05 * hull.draft, 0.5 * d_max)


@functools.lru_cache(maxsize=1)
def _exact_mirror_mesh_class():
    """A :class:`capytaine.Mesh` whose mirror images are exact.

    Capytaine 3.0's ``Mesh.mirrored`` reverses each face as ``f[::-1]``, ``[a, b, c, d] → [d, c, b, a]``.
    Capytaine splits a quadrilateral into the triangles (0, 1, 2) and (0, 2, 3) for its area and centroid,
    so the mirrored face is split along the *other* diagonal: for non-planar quadrilaterals (every panel
    of a doubly curved hull) the mirrored half is not the mirror image of the reference half, and the
    symmetric solve couples port/starboard-symmetric and antisymmetric motions at ~1e-5 (measured here:
    sway–surge 5e-6, roll–pitch 2e-5 of the diagonal terms). Reversing as ``[a, d, c, b]`` keeps vertex 0
    and the split diagonal; the decoupling is then exact to round-off (1e-16), as with an unsymmetric
    full mesh. Methods that build new meshes from this one keep the class, so the lid joined to the hull
    and the clipped meshes of the hydrostatics mirror exactly too.
    """
    import capytaine as cpt

    class ExactMirrorMesh(cpt.Mesh):
        @classmethod
        def like(cls, mesh):
            faces = [list(f[:3]) if f[2] == f[3] else list(f) for f in mesh.faces.tolist()]
            return cls(mesh.vertices, faces, faces_metadata=mesh.faces_metadata,
                       quadrature_method=mesh.quadrature_method, name=mesh.name, auto_clean=False, auto_check=False)

        def mirrored(self, plane, *, name=None):
            vertices = self.vertices.copy()
            vertices[:, {"xOz": 1, "yOz": 0}[plane]] *= -1.0
            faces = [[f[0], f[2], f[1]] if f[2] == f[3] else [f[0], f[3], f[2], f[1]] for f in self.faces.tolist()]
            return ExactMirrorMesh(vertices, faces, faces_metadata=self.faces_metadata,
                                   quadrature_method=self.quadrature_method, name=name,
                                   auto_clean=False, auto_check=False)

        def copy(self, *, faces_metadata=None, name=None):
            return ExactMirrorMesh.like(super().copy(faces_metadata=faces_metadata, name=name))

        def join_meshes(self, *meshes, return_masks=False, name=None, symmetry_warning_detail=""):
            out = super().join_meshes(*meshes, return_masks=return_masks, name=name,
                                      symmetry_warning_detail=symmetry_warning_detail)
            return (ExactMirrorMesh.like(out[0]), out[1]) if return_masks else ExactMirrorMesh.like(out)

        def clipped(self, *, origin, normal, name=None):
            return ExactMirrorMesh.like(super().clipped(origin=origin, normal=normal, name=name))

    return ExactMirrorMesh


def _symmetric(cpt, vertices, faces, planes=("xOz", "yOz")):
    """Quarter panels → nested ReflectionSymmetricMesh (xOz inside, yOz outside); half panels with
    ``planes=("xOz",)`` → one ReflectionSymmetricMesh."""
    mesh = _exact_mirror_mesh_class()(vertices, faces)
    for plane in planes:
        mesh = cpt.ReflectionSymmetricMesh(half=mesh, plane=plane)
    return mesh


def _bem_panels(hull, counts):
    """(hull panels, symmetry planes) of the part of ``hull`` the BEM meshes."""
    if isinstance(hull, CTVCatamaran):
        return hull.half_panels(counts), ("xOz",)
    return hull.quarter_panels(counts.n_half_length, counts.n_girth), ("xOz", "yOz")


def capytaine_body(spec: VesselSpec):
    """The Capytaine floating body of ``spec``: the symmetric part of its mesh (Wigley: a quarter with
    both symmetries; CTV: a half with port–starboard symmetry), Capytaine's lid (square panels of side
    b/n_lid, clear of the hull), 6 rigid DOFs.

    Returns
    -------
    body : capytaine.FloatingBody
    counts : PanelCounts or CTVPanelCounts
    z_lid : float or None
        Lid height (negative), None without a lid.
    """
    import capytaine as cpt

    hull = spec.hull
    counts = spec.panel_counts()
    z_lid = -lid_depth(hull, spec.omega_max, spec.g) if spec.lid else None
    (hv, hf), planes = _bem_panels(hull, counts)
    with _quiet_capytaine():
        mesh = _symmetric(cpt, hv, hf, planes)
        # a square panel of side a has Capytaine's face radius a/√2
        lid = (mesh.generate_lid(z=z_lid, faces_max_radius=hull.demihull_beam / counts.n_lid / math.sqrt(2.0))
               if z_lid is not None else None)
        body = cpt.FloatingBody(mesh=mesh, lid_mesh=lid, dofs=cpt.rigid_body_dofs(rotation_center=(0.0, 0.0, 0.0)),
                                center_of_mass=tuple(spec.cog), mass=spec.total_mass, name=spec.name)
    return body, counts, z_lid


def mirror_directions(X_half: np.ndarray, beta_half_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    r"""Complete 0..180° excitation to 0..360° by port/starboard symmetry.

    :math:`X_i(360° - \beta) = s_i X_i(\beta)` with :data:`PORT_STARBOARD_SIGN` ``s``; the mean drift
    (real, same layout) follows the same rule.

    Parameters
    ----------
    X_half : ndarray, shape (6, Nb, Nf)
        Excitation at ``beta_half_deg``, which must run from 0 to 180° inclusive.
    beta_half_deg : ndarray, shape (Nb,)

    Returns
    -------
    X : ndarray, shape (6, 2 Nb − 2, Nf)
    beta_deg : ndarray, shape (2 Nb − 2,), increasing from 0 to < 360
    """
    beta = np.asarray(beta_half_deg, dtype=float)
    if not (np.isclose(beta[0], 0.0) and np.isclose(beta[-1], 180.0)):
        raise ValueError("directions must run from 0 to 180°")
    inner = slice(beta.size - 2, 0, -1)  # 165 … 15 → mirrored 195 … 345
    X_m = PORT_STARBOARD_SIGN[:, None, None] * X_half[:, inner, :]
    return np.concatenate([X_half, X_m], axis=1), np.concatenate([beta, mirror_direction_deg(beta[inner])])


def _problems(cpt, body, omega, betas_rad, rho, g, depth):
    common = dict(body=body, omega=omega, rho=rho, g=g, water_depth=depth)
    rad = [cpt.RadiationProblem(radiating_dof=d, **common) for d in CPT_DOFS]
    dif = [cpt.DiffractionProblem(wave_direction=float(b), **common) for b in betas_rad]
    return rad, dif


def _solve(cpt, solver, body, omega, betas_rad, rho, g, depth, M=None, C=None):
    """A, B (6, 6), X (6, Nb) (exp(+iωt)) and, when the mass and restoring matrices ``M``, ``C`` are given,
    the far-field mean drift of the free-floating body (a :class:`boatland.hydro.drift.FarFieldDrift`; else
    None) at one frequency; one ``solve_all`` so that Capytaine reuses the LU-decomposed influence matrix for all
    problems. Failed problems give NaN."""
    from capytaine.bem.airy_waves import froude_krylov_force

    from capytaine.tools.block_circulant_matrices import NestedBlockCirculantMatrix

    rad, dif = _problems(cpt, body, omega, betas_rad, rho, g, depth)
    with_drift = M is not None and len(dif) > 0
    results = solver.solve_all(rad + dif, progress_bar=False, keep_details=with_drift)
    # Capytaine 3.0.0 memoises NestedBlockCirculantMatrix.to_BlockCirculantMatrix with a class-level
    # lru_cache (128 entries) that keeps every frequency's influence matrices alive: ~0.75 GB per
    # frequency for a 3700-panel quarter-symmetric hull (measured), an OOM kill within a band.
    NestedBlockCirculantMatrix.to_BlockCirculantMatrix.cache_clear()
    A = np.empty((6, 6))
    B = np.empty((6, 6))
    for j, res in enumerate(results[:len(rad)]):
        for i, d in enumerate(CPT_DOFS):
            A[i, j] = res.added_mass[d]
            B[i, j] = res.radiation_damping[d]
    X = np.empty((6, len(dif)), dtype=complex)
    for k, (pb, res) in enumerate(zip(dif, results[len(rad):])):
        fk = froude_krylov_force(pb)
        for i, d in enumerate(CPT_DOFS):
            X[i, k] = np.conj(complex(res.forces[d]) + complex(fk[d]))  # exp(−iωt) → exp(+iωt)
    far = drift_from_results(results[:len(rad)], results[len(rad):], M, C) if with_drift else None
    return A, B, X, far


def build_database(spec: VesselSpec, *, progress: bool = True, drift: bool = True) -> HydroDB:
    """Solve the radiation and diffraction problems of ``spec`` with Capytaine; return the database.

    Parameters
    ----------
    spec : VesselSpec
        The vessel (hull, mass properties, environment, mesh, frequencies, directions).
    progress : bool
        Show a progress bar over the frequencies (only when stderr is a terminal).
    drift : bool
        Also compute the far-field mean drift (surge, sway, yaw) of the free-floating vessel from the same
        solves (:mod:`boatland.hydro.drift`): the sources are kept and their Kochin functions evaluated,
        which adds a few per cent to the build time (noted in the provenance). False leaves ``drift`` None.
        The far field's energy balance (optical theorem) is in the note.

    Returns
    -------
    HydroDB
        A, B at every frequency, X for 0..360°, A_inf and A_0 (deep water), C, M, the mean drift, the full
        wetted hull mesh, and provenance notes saying how it was computed.
    """
    from tqdm import tqdm

    from boatland.resources import require

    cpt = require("capytaine", "building a hydrodynamic database (boatland hydro build)")
    t0 = time.perf_counter()
    rho, g, depth = spec.rho, spec.g, spec.water_depth
    hull = spec.hull
    omegas = spec.omega
    beta_half = spec.solved_directions_deg
    betas_rad = np.deg2rad(beta_half)
    body, counts, z_lid = capytaine_body(spec)
    solver = cpt.BEMSolver()
    nf, nb = omegas.size, beta_half.size
    A = np.full((6, 6, nf), np.nan)
    B = np.full((6, 6, nf), np.nan)
    X_half = np.full((6, nb, nf), np.nan + 0j)
    D_half = np.full((6, nb, nf), np.nan) if drift else None
    imbalance = np.full((nb, nf), np.nan)
    notes: list[str] = []

    bar = tqdm(omegas, desc=f"{spec.name}: Capytaine", unit="ω", leave=False,
               disable=not (progress and sys.stderr.isatty()))
    with _quiet_capytaine():
        C_cpt = body.compute_hydrostatic_stiffness(rho=rho, g=g)
        C = np.array(C_cpt.sel(influenced_dof=list(CPT_DOFS), radiating_dof=list(CPT_DOFS)).values, dtype=float)
        M = spec.mass_matrix()
        for k, w in enumerate(bar):
            A[:, :, k], B[:, :, k], X_half[:, :, k], d = _solve(cpt, solver, body, float(w), betas_rad, rho, g, depth,
                                                                *((M, C) if drift else ()))
            if drift:
                D_half[:, :, k], imbalance[:, k] = d.drift, d.imbalance
        limits = {}
        for name, w in (("A_0", 0.0), ("A_inf", np.inf)):
            # Capytaine's solve_all turns a failed problem into NaN (finite depth has no ω = 0 limit)
            a_lim = _solve(cpt, solver, body, w, [], rho, g, depth)[0]
            if not np.all(np.isfinite(a_lim)):
                notes.append(f"{name} not computed: Capytaine returned NaN at ω = {w} in water depth {depth:g} m")
                a_lim = None
            limits[name] = a_lim
        volume = float(body.volume)
        cob = np.asarray(body.center_of_buoyancy, dtype=float)
    bar.close()

    good = np.all(np.isfinite(A), axis=(0, 1)) & np.all(np.isfinite(B), axis=(0, 1)) & np.all(np.isfinite(X_half), axis=(0, 1))
    if drift:
        good &= np.all(np.isfinite(D_half), axis=(0, 1))
    if not np.all(good):
        bad = omegas[~good]
        notes.append(f"dropped {bad.size} frequencies where Capytaine failed (NaN): "
                     + ", ".join(f"{w:.4g}" for w in bad[:10]) + (" …" if bad.size > 10 else "") + " rad/s")
        omegas, A, B, X_half = omegas[good], A[:, :, good], B[:, :, good], X_half[:, :, good]
        D_half = D_half[:, :, good] if drift else None
        imbalance = imbalance[:, good]
    X, beta = mirror_directions(X_half, beta_half)
    D = mirror_directions(D_half, beta_half)[0] if drift else None

    seconds = time.perf_counter() - t0
    notes = _notes(spec, hull, counts, body, z_lid, omegas, B, C, volume, seconds) + notes
    if drift:
        n_panels = int(body.mesh.nb_faces)
        notes.append(far_field_note(n_panels, z_lid is not None, extra="computed with the build from the same "
                                    "solves (0–180° solved, the rest mirrored: D_i(−β) = s_i D_i(β)); "
                                    + imbalance_text(imbalance, D)))
    prov = Provenance(source=spec.source or f"VesselSpec {spec.name!r}", solver=SOLVER,
                      created=datetime.now(timezone.utc).isoformat(timespec="seconds"),
                      reader="boatland.hydro.build", notes=tuple(notes))
    return HydroDB(
        omega=omegas, A=A, B=B, X=X, wave_dir_deg=beta, C=C, A_inf=limits["A_inf"], A_0=limits["A_0"],
        M=M, ref_point=np.zeros(3), cog=spec.cog, cob=cob, disp_vol=volume,
        water_depth=depth, rho=rho, g=g, name=spec.name, provenance=prov, mesh=hull.mesh(counts),
        topsides=hull.topsides() if isinstance(hull, CTVCatamaran) else None, drift=D,
    )


def _decay(omegas: np.ndarray, b33: np.ndarray) -> tuple[float, float]:
    peak = float(np.max(np.abs(b33)))
    if peak == 0:
        return 0.0, 0.0
    top = omegas >= omegas[-1] - TOP_FRACTION * (omegas[-1] - omegas[0])
    return abs(float(b33[-1])) / peak, float(np.max(np.abs(b33[top]))) / peak


def _hull_text(hull) -> str:
    if isinstance(hull, CTVCatamaran):
        hs = hull.hydrostatics()
        sec = (f"hard-chine sections (deadrise {hull.deadrise_deg:g}° aft, {hull.bow_deadrise_deg:g}° at the stem)"
               if hull.section == "chine" else f"round-bilge sections (exponent {hull.bilge_exponent:g})")
        return (f"hull: two CTV demihulls with a transom stern L = {hull.length:g} m, b = {hull.demihull_beam:g} m, "
                f"T = {hull.draft:g} m, separation {hull.separation:g} m, {sec}, transom {hull.transom_beam:g} b "
                f"wide and {hull.transom_draft:g} T deep, entrance half-angle {hull.entrance_deg:g}° "
                f"(C_b = {hs.block_coefficient:.4f}, LCB {hs.cob[0]:+.3f} m, LCF {hs.lcf:+.3f} m)")
    return (f"hull: two generalized Wigley demihulls L = {hull.length:g} m, b = {hull.demihull_beam:g} m, "
            f"T = {hull.draft:g} m, separation {hull.separation:g} m, p = {hull.p:.4g} "
            f"(C_b = {hull.block_coefficient:.4f})")


def _notes(spec: VesselSpec, hull, counts, body, z_lid, omegas, B, C, volume, seconds) -> list[str]:
    n_hull = int(body.mesh.nb_faces)            # the whole mesh's panels (the symmetric parts mirrored)
    n_lid = int(body.lid_mesh.nb_faces) if body.lid_mesh is not None else 0
    quarter = not isinstance(hull, CTVCatamaran)
    layout = (f"{counts.n_length} from transom to stem, {counts.n_girth} keel to waterline, "
              f"{counts.n_transom} across a transom" if isinstance(hull, CTVCatamaran) else
              f"{counts.n_half_length} per half-length, {counts.n_girth} keel to waterline")
    notes = [
        _hull_text(hull) + f"; mass {spec.total_mass:.6g} kg, CoG {tuple(round(float(c), 4) for c in spec.cog)} m, "
        f"I_cog {tuple(float(f'{i:.6g}') for i in spec.inertia_cog)} kg m²",
        *spec.notes,
        f"mesh: {n_hull} hull panels ({layout}), "
        + (f"{n_lid} lid panels at z = {z_lid:.4g} m (Capytaine's lid generator, clear of the hull; irregular "
           "frequencies removed: sharp features in A, B, X "
           "are the waves trapped between the demihulls, physical in potential flow)"
           if z_lid is not None else "no lid (irregular frequencies not removed)")
        + f"; {'quarter mesh with xOz and yOz' if quarter else 'half mesh with xOz'} symmetry; "
        f"{spec.panels_per_wavelength():.1f} panels per shortest "
        f"wavelength ({spec.shortest_wavelength:.3g} m at {spec.omega_max:g} rad/s)",
        f"frequencies: {omegas.size} from {omegas[0]:.4g} to {omegas[-1]:.4g} rad/s"
        + (f", Δω = {np.diff(omegas).mean():.4g} rad/s (IRFs resolved to π/Δω = {np.pi / np.diff(omegas).mean():.3g} s)"
           if omegas.size > 1 else ""),
        f"directions: {spec.direction_step_deg:g}° steps; 0–180° solved, the rest mirrored "
        "(port/starboard symmetry, X_i(−β) = s_i X_i(β))",
    ]
    xb = float(hull.centre_of_buoyancy[0])
    if abs(spec.cog[0] - xb) > 1e-6 * hull.length:
        notes.append(f"centre of gravity {spec.cog[0] - xb:+.4g} m from the centre of buoyancy: the real vessel "
                     "trims; the database is for the even-keel waterline, with the weight couplings in C")
    end, top = _decay(omegas, B[2, 2])
    notes.append(f"heave damping at ω_max: |B33(ω_max)| / max |B33| = {end:.3f}; largest in the top "
                 f"{TOP_FRACTION:.0%} of the band {top:.3f}"
                 + ("" if max(end, top) <= DECAY_LIMIT else
                    f" — above {DECAY_LIMIT:.0%}: the IRF needs a tail model beyond ω_max (catamaran damping "
                    "decays slowly, with wiggles from waves trapped between the demihulls)"))
    C_ref = hull.restoring(spec.rho, spec.g, spec.total_mass, spec.cog)
    rel = {n: (C[i, i] - C_ref[i, i]) / C_ref[i, i] for n, i in (("C33", 2), ("C44", 3), ("C55", 4))}
    if C_ref[2, 4] != 0.0:
        rel["C35"] = (C[2, 4] - C_ref[2, 4]) / C_ref[2, 4]
    notes.append(f"hydrostatics: panel mesh vs {'quadrature of the lines' if isinstance(hull, CTVCatamaran) else 'closed form'}: volume "
                 f"{(volume - hull.volume) / hull.volume:+.2%}, "
                 + ", ".join(f"{n} {r:+.2%}" for n, r in rel.items())
                 + f"; mass − ρ·volume = {spec.total_mass - spec.rho * volume:+.4g} kg (mesh discretisation)")
    notes.append(f"solved in {seconds:.0f} s with {SOLVER} (Delhommeau Green function, indirect method)")
    return notes


def build_from_file(path: str | Path, out_path: str | Path, progress: bool = True) -> HydroDB:
    """Build the database of the vessel file ``path`` and write it to ``out_path`` (BEMIO HDF5, atomic).

    A vessel file with a ``[bem]`` table is not solved: its BEM output is read and given the file's mass
    properties (:func:`boatland.hydro.read.database_of`).

    Returns
    -------
    HydroDB
        The database written.

    Raises
    ------
    BoatlandInputError
        The vessel file has problems (all listed, with key paths).
    """
    from boatland.hydro.bemio import write_bemio
    from boatland.hydro.read import database_of
    from boatland.vessel.imported import ImportedVesselSpec

    spec = load_vessel(path)
    db = database_of(spec) if isinstance(spec, ImportedVesselSpec) else build_database(spec, progress=progress)
    write_bemio(db, out_path)
    return db
