r"""Mean (second-order) wave drift forces on a vessel at rest: what :attr:`HydroDB.drift` holds, and its
far-field computation with Capytaine.

What the database holds
-----------------------
``HydroDB.drift[i, b, k]`` is the mean force (i = 0, 1, 2) or moment (i = 3, 4, 5) on the vessel at rest
in a regular wave of unit amplitude, frequency ``omega[k]`` and direction of travel ``wave_dir_deg[b]``
[N/m², N·m/m²]: body axes at the mean position, moments about ``ref_point``, DOF order surge … yaw
(:mod:`boatland.conventions`). A regular wave of amplitude :math:`a` pushes with :math:`\bar F_i = D_i a^2`;
a long-crested sea of one-sided spectrum :math:`S(\omega)` with :math:`\bar F_i = 2\int_0^\infty
D_i(\omega, \beta)\,S(\omega)\,d\omega` (Newman 1974). The drift depends on the motions, hence on the mass
properties the RAOs were computed with; the provenance notes say how it was obtained and which DOFs are
meaningful (a note beginning ``"mean drift:"``).

Far field (Maruo 1960; Newman 1967)
-----------------------------------
Far from the body the disturbance (diffraction plus radiation by the body's motions) of the incident wave
:math:`\eta_0 = a\,e^{ik(x\cos\beta + y\sin\beta)}` is an outgoing ring wave of elevation

.. math:: \eta_s \simeq a\,\mathcal A(\theta)\,\frac{e^{ikR}}{\sqrt{kR}}\qquad (e^{-i\omega t}).

The mean horizontal force and yaw moment on the body are minus the mean fluxes of momentum and of angular
momentum through a vertical cylinder of radius :math:`R\to\infty` (Maruo 1960; Newman 1967, with the depth
factor :math:`n = C_g/C = \tfrac12(1 + 2kh/\sinh 2kh)` of finite depth, Mei, Stiassnie & Yue 2005 §11):

.. math::
    \frac{\bar F_x + i\bar F_y}{a^2} &= -\frac{\rho g n}{2k}\int_0^{2\pi}|\mathcal A|^2 e^{i\theta}\,d\theta
        - \frac{\rho g n\sqrt{2\pi}}{k}\,e^{i\beta}\,\mathrm{Re}\!\left[\mathcal A(\beta)\,e^{i\pi/4}\right],\\
    \frac{\bar M_z}{a^2} &= -\frac{\rho g n}{2k^2}\int_0^{2\pi}\mathrm{Im}\!\left[\mathcal A'\,\mathcal A^*\right]d\theta
        - \frac{\rho g n\sqrt{2\pi}}{k^2}\,\mathrm{Re}\!\left[\mathcal A'(\beta)\,e^{-i\pi/4}\right]

(:func:`maruo_newman`; the first terms are the waves the body sends out, the second their interference with
the incident wave in its own direction). They hold for any body, absorbing or not; for a body that absorbs
no energy the optical theorem :math:`\int|\mathcal A|^2 d\theta = -2\sqrt{2\pi}\,\mathrm{Re}[\mathcal
A(\beta)e^{i\pi/4}]` turns the force into :math:`\tfrac{\rho g n}{2k}\int|\mathcal A|^2(e_\beta - e_\theta)
d\theta`, which points down-wave in head and following seas. The far field gives **surge, sway and yaw
only**; heave, roll and pitch drift need the pressure on the hull (near field) and are set to 0 here.
``tests/hydro/test_drift.py`` checks both formulas against the exact fluxes of a field of cylindrical waves
through circles of any radius.

With Capytaine
--------------
Capytaine's indirect method represents the disturbance potential by sources :math:`\sigma` on the hull
panels (and the lid); its Kochin function (:func:`capytaine.post_pro.compute_kochin`)

.. math:: H(\theta) = \frac{1}{4\pi}\iint_S \sigma\,\frac{\cosh k(z+h)}{\cosh kh}\,e^{-ik(x\cos\theta + y\sin\theta)}\,dS

gives the far-field potential :math:`\phi_s \simeq -\frac{k\sqrt{2\pi}}{n\tanh kh}e^{i\pi/4}\,H(\theta)\,
\frac{\cosh k(z+h)}{\cosh kh}\frac{e^{ikR}}{\sqrt{kR}}` (the wave term of the Green function; checked against
Capytaine's own potential at a distant point in the tests), hence with :math:`\eta = (i\omega/g)\phi`
at :math:`z = 0`

.. math:: \mathcal A(\theta) = \sqrt{2\pi}\,\frac{k^2}{n\,\omega}\,e^{-i\pi/4}\,H(\theta).

The disturbance of a freely floating vessel is the diffraction source distribution plus the radiation
distributions times the body motions :math:`\xi_j` (Capytaine 3.0 solves its radiation problems for a unit
displacement amplitude: normal velocity :math:`-i\omega\,\mathbf n\cdot\mathbf d_j`), with the RAOs
:math:`\xi = [-\omega^2(M + A) - i\omega B + C]^{-1}X` (Capytaine's :math:`e^{-i\omega t}`). The Kochin
integral is evaluated here for all problems of a frequency at once (one matrix product; the same formula
as Capytaine's routine), on a uniform grid of :math:`N_\theta \ge 4\lceil kR_{max}\rceil + 128` angles —
the trapezoidal rule is spectrally accurate for periodic integrands band-limited to :math:`|m| \lesssim
kR_{max}` — and, with its analytic θ-derivative, at the wave directions themselves.

Energy check. A body that absorbs no energy (fixed, or floating with radiation damping only) scatters as
much energy as it takes from the incident wave: :math:`\int|\mathcal A|^2 d\theta + 2\sqrt{2\pi}\,
\mathrm{Re}[\mathcal A(\beta)e^{i\pi/4}] = 0`. The drift along the wave direction contains this sum times
:math:`-\rho g n/2k`; its size for the computed far field (:attr:`FarFieldDrift.imbalance`, N/m²) is
therefore the error an unbalanced BEM solution (a bad lid, a coarse mesh, an irregular frequency) puts
into the drift, and the provenance note gives its largest value against the largest drift.

References
----------
- Maruo, H. (1960). The drift of a body floating on waves. J. Ship Research 4(3), 1–10.
- Newman, J.N. (1967). The drift force and moment on ships in waves. J. Ship Research 11(1), 51–60.
- Newman, J.N. (1974). Second-order, slowly-varying forces on vessels in irregular waves. Proc. Int. Symp.
  Dynamics of Marine Vehicles and Structures in Waves, London, 182–186.
- Mei, C.C., Stiassnie, M., Yue, D.K.-P. (2005). Theory and Applications of Ocean Surface Waves, World
  Scientific (far-field identities, drift force on a vertical cylinder).
- Babarit, A., Delhommeau, G. (2015). Theoretical and numerical aspects of the open source BEM solver
  NEMOH. EWTEC 2015 (the Green function whose wave term gives the far-field constant above).
"""

from __future__ import annotations

import math
import sys
import time
from typing import NamedTuple, Sequence

import numpy as np

from boatland.errors import HydroDataError
from boatland.vessel.database import HydroDB

__all__ = ["FAR_FIELD_DOFS", "DRIFT_NOTE", "FarFieldDrift", "add_drift", "capytaine_mesh_body", "depth_factor",
           "drift_from_results", "far_field_amplitude", "far_field_note", "imbalance_text", "maruo_newman",
           "solve_frequency"]

#: DOFs (surge, sway, yaw) the far-field method gives; the others are 0.
FAR_FIELD_DOFS = (0, 1, 5)
#: How every provenance note about the mean drift begins.
DRIFT_NOTE = "mean drift:"
#: Capytaine's DOF names in boatland's DOF order.
_CPT_DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")
#: kh above which the water is deep (Capytaine's own switch in its Kochin function).
_DEEP_KH = 20.0


def depth_factor(k: float, depth: float) -> tuple[float, float]:
    r"""``(n, tanh kh)``: the ratio :math:`n = C_g/C = \tfrac12(1 + 2kh/\sinh 2kh)` and :math:`\tanh kh`
    (``(0.5, 1.0)`` in deep water, kh ≥ 20 or ``depth = inf``)."""
    kh = k * depth
    if not np.isfinite(kh) or kh >= _DEEP_KH:
        return 0.5, 1.0
    return 0.5 * (1.0 + 2.0 * kh / math.sinh(2.0 * kh)), math.tanh(kh)


def far_field_amplitude(H: np.ndarray, omega: float, k: float, depth: float) -> np.ndarray:
    r"""Far-field elevation amplitude :math:`\mathcal A(\theta)` of a Capytaine Kochin function ``H``
    (module docstring): :math:`\mathcal A = \sqrt{2\pi}\,k^2/(n\omega)\,e^{-i\pi/4} H`, per unit incident
    amplitude, Capytaine's :math:`e^{-i\omega t}`."""
    n, _ = depth_factor(k, depth)
    return math.sqrt(2.0 * math.pi) * k * k / (n * omega) * np.exp(-0.25j * math.pi) * np.asarray(H)


def maruo_newman(A: np.ndarray, dA: np.ndarray, A_beta, dA_beta, beta, k: float, depth: float,
                 rho: float, g: float) -> np.ndarray:
    r"""Mean drift force and yaw moment from the far-field amplitude (Maruo 1960; Newman 1967).

    Parameters
    ----------
    A, dA : ndarray of complex, shape (Nθ, ...)
        :math:`\mathcal A(\theta)` and :math:`\mathcal A'(\theta)` on the uniform grid
        :math:`\theta_j = 2\pi j/N_\theta` (trailing axes: one per problem).
    A_beta, dA_beta : array_like of complex, shape (...)
        :math:`\mathcal A` and :math:`\mathcal A'` at each problem's wave direction.
    beta : array_like, shape (...)
        Wave directions [rad], direction of travel.
    k : float
        Wavenumber [1/m].
    depth : float
        Water depth [m] (``inf``: deep).
    rho, g : float

    Returns
    -------
    ndarray, shape (3, ...)
        :math:`\bar F_x, \bar F_y` [N/m²] and :math:`\bar M_z` about the origin of the polar coordinates
        [N·m/m²], per unit incident amplitude squared (module docstring).
    """
    A, dA = np.asarray(A), np.asarray(dA)
    n_theta = A.shape[0]
    theta = 2.0 * np.pi * np.arange(n_theta) / n_theta
    shape = (n_theta,) + (1,) * (A.ndim - 1)
    w = 2.0 * np.pi / n_theta
    e = np.exp(1j * theta).reshape(shape)
    n, _ = depth_factor(k, depth)
    scale = rho * g * n
    beta = np.asarray(beta, dtype=float)
    cross = np.real(np.asarray(A_beta) * np.exp(0.25j * np.pi))
    F = (-scale / (2.0 * k) * w * np.sum(np.abs(A) ** 2 * e, axis=0)
         - scale * math.sqrt(2.0 * math.pi) / k * np.exp(1j * beta) * cross)
    Mz = (-scale / (2.0 * k * k) * w * np.sum(np.imag(dA * np.conj(A)), axis=0)
          - scale * math.sqrt(2.0 * math.pi) / (k * k) * np.real(np.asarray(dA_beta) * np.exp(-0.25j * np.pi)))
    return np.stack([F.real, F.imag, Mz])


def _kochin_matrices(mesh, k: float, depth: float, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    r"""Z, dZ/dθ (Nθ, N_faces): :math:`H(\theta) = Z\sigma`, the Kochin integral of
    :func:`capytaine.post_pro.compute_kochin` (about the origin) for any source vector σ."""
    c = mesh.faces_centers
    kh = k * depth
    if np.isfinite(kh) and kh < _DEEP_KH:
        cih = np.cosh(k * (c[:, 2] + depth)) / np.cosh(kh)
    else:
        cih = np.exp(k * c[:, 2])
    ct, st = np.cos(theta)[:, None], np.sin(theta)[:, None]
    x, y = c[None, :, 0], c[None, :, 1]
    Z = (cih * mesh.faces_areas / (4.0 * np.pi))[None, :] * np.exp(-1j * k * (x * ct + y * st))
    dZ = -1j * k * (-x * st + y * ct) * Z
    return Z, dZ


class FarFieldDrift(NamedTuple):
    """Result of :func:`drift_from_results` at one frequency (Nb wave directions)."""

    drift: np.ndarray
    """(6, Nb) mean force and moment per unit amplitude squared [N/m², N·m/m²]; heave, roll, pitch 0."""
    xi: np.ndarray
    """(6, Nb) complex RAOs used, exp(−iωt) (zeros for a fixed body)."""
    X: np.ndarray
    """(6, Nb) complex excitation (Froude–Krylov + diffraction), exp(−iωt)."""
    imbalance: np.ndarray
    r"""(Nb,) energy check [N/m²]: :math:`\frac{\rho g n}{2k}\left|\int|\mathcal A|^2 d\theta +
    2\sqrt{2\pi}\,\mathrm{Re}[\mathcal A(\beta)e^{i\pi/4}]\right|`, zero for an exact solution of a body
    that absorbs no energy (the optical theorem, module docstring); it is the error that a violation of
    energy conservation puts into the drift along the wave direction, so it compares with the drift."""


def drift_from_results(radiation: Sequence, diffraction: Sequence, M: np.ndarray, C: np.ndarray,
                       ref_point=(0.0, 0.0, 0.0)) -> FarFieldDrift:
    r"""Far-field mean drift of a freely floating body from Capytaine results at one frequency.

    Parameters
    ----------
    radiation : sequence of capytaine RadiationResult
        The six rigid-body radiation problems (DOFs ``Surge`` … ``Yaw`` about ``ref_point``, in that order),
        solved with ``keep_details=True`` (the indirect method keeps the sources). Empty: the body is held
        fixed.
    diffraction : sequence of capytaine DiffractionResult
        The diffraction problems, same frequency and body, ``keep_details=True``.
    M, C : ndarray, shape (6, 6)
        Mass and restoring matrices about ``ref_point`` (ignored for a fixed body).
    ref_point : array_like, shape (3,)
        Point the yaw moment is taken about (the radiation DOFs' rotation centre).

    Returns
    -------
    FarFieldDrift
        ``drift`` (6, Nb): surge, sway and yaw filled, heave, roll and pitch 0 (module docstring); ``xi`` the
        RAOs and ``X`` the excitation used (exp(−iωt)); ``imbalance`` (Nb,) the energy check [N/m²].
    """
    from capytaine.bem.airy_waves import froude_krylov_force

    first = diffraction[0]
    if any(getattr(r, "sources", None) is None for r in (*radiation, *diffraction)):
        nan = np.full((6, len(diffraction)), np.nan)
        return FarFieldDrift(nan, nan + 0j, nan + 0j, nan[0])   # a failed problem (Capytaine: NaN forces)
    omega, k, depth, rho, g = (float(first.omega), float(first.wavenumber), float(first.water_depth),
                               float(first.rho), float(first.g))
    mesh = first.body.mesh_including_lid
    nb = len(diffraction)
    sources = np.stack([np.asarray(r.sources) for r in diffraction], axis=1)          # (N, Nb)
    X = np.empty((6, nb), dtype=complex)
    for b, r in enumerate(diffraction):
        fk = froude_krylov_force(r.problem)
        X[:, b] = [complex(r.forces[d]) + complex(fk[d]) for d in _CPT_DOFS]
    xi = np.zeros((6, nb), dtype=complex)
    if radiation:
        A = np.array([[r.added_mass[d] for r in radiation] for d in _CPT_DOFS], dtype=float)
        B = np.array([[r.radiation_damping[d] for r in radiation] for d in _CPT_DOFS], dtype=float)
        Z = -omega ** 2 * (np.asarray(M) + A) - 1j * omega * B + np.asarray(C)
        xi = np.linalg.solve(Z, X)
        rad_sources = np.stack([np.asarray(r.sources) for r in radiation], axis=1)    # (N, 6)
        sources = sources + rad_sources @ xi           # radiation problems: unit displacement amplitude
    R_max = float(np.max(np.hypot(mesh.faces_centers[:, 0], mesh.faces_centers[:, 1])))
    n_theta = 4 * math.ceil(k * R_max) + 128
    theta = 2.0 * np.pi * np.arange(n_theta) / n_theta
    beta = np.array([float(r.problem.wave_direction) for r in diffraction])
    Zg, dZg = _kochin_matrices(mesh, k, depth, theta)
    Zb, dZb = _kochin_matrices(mesh, k, depth, beta)
    amp = lambda H: far_field_amplitude(H, omega, k, depth)  # noqa: E731
    A_grid, dA_grid = amp(Zg @ sources), amp(dZg @ sources)
    A_beta, dA_beta = amp(np.sum(Zb * sources.T, axis=1)), amp(np.sum(dZb * sources.T, axis=1))
    Fx, Fy, Mz = maruo_newman(A_grid, dA_grid, A_beta, dA_beta, beta, k, depth, rho, g)
    x0, y0 = float(ref_point[0]), float(ref_point[1])
    drift = np.zeros((6, nb))
    drift[0], drift[1], drift[5] = Fx, Fy, Mz - (x0 * Fy - y0 * Fx)
    n, _ = depth_factor(k, depth)
    balance = (2.0 * np.pi / n_theta * np.sum(np.abs(A_grid) ** 2, axis=0)
               + 2.0 * math.sqrt(2.0 * math.pi) * np.real(A_beta * np.exp(0.25j * np.pi)))
    return FarFieldDrift(drift, xi, X, rho * g * n / (2.0 * k) * np.abs(balance))


def imbalance_text(imbalance: np.ndarray, drift: np.ndarray) -> str:
    """One phrase for the provenance: the largest energy imbalance against the largest horizontal drift."""
    worst = float(np.nanmax(imbalance))
    scale = float(np.nanmax(np.abs(drift[:2]))) if np.any(drift[:2]) else 0.0
    rel = f" ({worst / scale:.1%} of the largest surge or sway drift)" if scale > 0 else ""
    return (f"energy check (optical theorem): the far field's imbalance is worth at most {worst:.3g} N/m² of "
            f"drift along the waves{rel}")


def far_field_note(n_panels: int, lid: bool, seconds: float | None = None, extra: str = "") -> str:
    """The provenance note of a far-field drift computed here (method, DOFs, mesh, cost)."""
    cost = f"; {seconds:.0f} s" if seconds is not None else ""
    return (f"{DRIFT_NOTE} far-field (Maruo 1960, Newman 1967 yaw) from the Kochin functions of Capytaine "
            f"diffraction and radiation sources on {n_panels} panels{' and a lid' if lid else ' (no lid)'}, "
            "body free-floating with the RAOs of M, C and Capytaine's A, B, X (no viscous damping); "
            "surge, sway and yaw only — heave, roll and pitch drift set to 0 (not computed)"
            + (f"; {extra}" if extra else "") + cost)


def _cpt_faces(faces: np.ndarray) -> list[list[int]]:
    """HullMesh quads (a triangle repeats its last vertex) → Capytaine face lists."""
    return [list(f[:3]) if f[2] == f[3] else list(f) for f in np.asarray(faces).tolist()]


def capytaine_mesh_body(db: HydroDB, *, lid: bool = True):
    """A Capytaine floating body of ``db``'s wetted hull mesh (6 rigid DOFs about ``ref_point``), with an
    irregular-frequency lid from Capytaine's generator at ``min(0.05 T, d/2)`` below the waterline, d the
    deepest lid that keeps the first irregular frequency above the band (Capytaine's estimate, as
    :func:`boatland.hydro.build.lid_depth`).

    The mesh vertices are taken in the frame of the BEM input (as the builder stores them: reference point
    at the origin). No symmetry is used: a hull built by :mod:`boatland.hydro.build` is solved faster from
    its vessel file (``add_drift(db, body=capytaine_body(spec)[0])``, :func:`boatland.hydro.build.capytaine_body`),
    and :func:`boatland.hydro.build.build_database` computes the drift with the build anyway.

    Raises
    ------
    HydroDataError
        The database has no hull mesh.
    """
    import capytaine as cpt

    if db.mesh is None:
        raise HydroDataError(db.provenance.source or db.name, "mesh",
                             "no hull mesh in the database: the far-field drift needs the wetted hull panels "
                             "(databases built by boatland hydro build have them), or pass body=")
    mesh = cpt.Mesh(db.mesh.vertices, _cpt_faces(db.mesh.faces), name=db.name)
    lid_mesh = None
    if lid:
        with np.errstate(invalid="ignore"):              # NaN: any lid depth keeps them above the band
            deepest = -float(mesh.lowest_lid_position(float(db.omega[-1]), g=db.g))
        draft = -float(np.min(mesh.vertices[:, 2]))
        depth = min(0.05 * draft, 0.5 * deepest) if np.isfinite(deepest) and deepest > 0 else 0.05 * draft
        lid_mesh = mesh.generate_lid(z=-depth)
        if lid_mesh.nb_faces == 0:
            lid_mesh = None
    return cpt.FloatingBody(mesh=mesh, lid_mesh=lid_mesh,
                            dofs=cpt.rigid_body_dofs(rotation_center=tuple(float(c) for c in db.ref_point)),
                            name=db.name)


def add_drift(db: HydroDB, *, body=None, progress: bool = True) -> HydroDB:
    r"""``db`` with its far-field mean drift (surge, sway, yaw) computed by Capytaine.

    Solves the six radiation problems and one diffraction problem per direction of ``db`` at each of its
    frequencies (one LU decomposition per frequency, as :func:`boatland.hydro.build.build_database`), and
    evaluates the Maruo–Newman far-field formulas of the module docstring for the freely floating vessel:
    RAOs from the database's ``M`` and ``C`` with Capytaine's own A, B and X of the same solve (so that
    motions and sources agree; their largest difference from the database's A, B, X is noted, with the energy
    check of :attr:`FarFieldDrift.imbalance`). Costs about as much as building the database (ctv27:
    8.4 min on 2 cores for 125 frequencies × 72 directions).

    Parameters
    ----------
    db : HydroDB
        The database; needs ``M`` and, unless ``body`` is given, the hull ``mesh``.
    body : capytaine.FloatingBody, optional
        The body to solve, with six rigid DOFs about ``db.ref_point`` (for a built vessel
        ``boatland.hydro.build.capytaine_body(spec)[0]``: the builder's symmetric mesh and lid; its
        two half-size blocks cost about a quarter of the full mesh's LU). Default:
        :func:`capytaine_mesh_body` of ``db``.
    progress : bool
        Progress bar over the frequencies (only when stderr is a terminal).

    Returns
    -------
    HydroDB
        ``db`` with ``drift`` set and a provenance note (``"mean drift: far-field ..."``).

    Raises
    ------
    HydroDataError
        No mass matrix, or no mesh and no body; BoatlandInputError when Capytaine is not installed.
    """
    from boatland.resources import require

    cpt = require("capytaine", "computing mean drift forces (boatland.hydro.drift)")
    from tqdm import tqdm

    if db.M is None:
        raise HydroDataError(db.provenance.source or db.name, "M",
                             "no mass matrix: the drift of a floating vessel needs its motions; give the mass "
                             "properties first (a [bem] vessel file)")
    t0 = time.perf_counter()
    if body is None:
        body = capytaine_mesh_body(db)
    solver = cpt.BEMSolver()
    beta = np.deg2rad(db.wave_dir_deg)
    drift = np.full((6, db.n_dir, db.n_freq), np.nan)
    imbalance = np.full((db.n_dir, db.n_freq), np.nan)
    dev = np.zeros(3)
    bar = tqdm(db.omega, desc=f"{db.name}: mean drift", unit="ω", leave=False,
               disable=not (progress and sys.stderr.isatty()))
    log = _quiet()
    try:
        for k, w in enumerate(bar):
            rad, dif = solve_frequency(cpt, solver, body, float(w), beta, db.rho, db.g, db.water_depth)
            drift[:, :, k], _, X, imbalance[:, k] = drift_from_results(rad, dif, db.M, db.C, db.ref_point)
            A = np.array([[r.added_mass[d] for r in rad] for d in _CPT_DOFS])
            B = np.array([[r.radiation_damping[d] for r in rad] for d in _CPT_DOFS])
            for j, (mine, theirs) in enumerate(((A, db.A[:, :, k]), (B, db.B[:, :, k]), (np.conj(X), db.X[:, :, k]))):
                dev[j] = max(dev[j], float(np.max(np.abs(mine - theirs))))
    finally:
        bar.close()
        log()
    if not np.all(np.isfinite(drift)):
        bad = db.omega[~np.all(np.isfinite(drift), axis=(0, 1))]
        raise HydroDataError(db.provenance.source or db.name, "drift",
                             f"Capytaine failed at {bad.size} frequencies ({', '.join(f'{w:.4g}' for w in bad[:5])} "
                             "rad/s): no drift table")
    n_panels = int(body.mesh.nb_faces)
    dev /= [max(float(np.max(np.abs(T))), 1e-300) for T in (db.A, db.B, db.X)]
    extra = (f"largest difference of Capytaine's A, B, X from the database's: {dev[0]:.1e}, {dev[1]:.1e}, "
             f"{dev[2]:.1e} of the largest term of the band; " + imbalance_text(imbalance, drift))
    note = far_field_note(n_panels, body.lid_mesh is not None, time.perf_counter() - t0, extra)
    return db.replace(drift=drift, provenance=db.provenance.with_note(note))


def solve_frequency(cpt, solver, body, omega: float, betas_rad, rho: float, g: float, depth: float):
    """The six radiation results and the diffraction results at ``betas_rad`` of one frequency, in one
    ``solve_all`` (one LU decomposition), with the sources kept (``keep_details=True``)."""
    from capytaine.tools.block_circulant_matrices import NestedBlockCirculantMatrix

    common = dict(body=body, omega=omega, rho=rho, g=g, water_depth=depth)
    rad = [cpt.RadiationProblem(radiating_dof=d, **common) for d in _CPT_DOFS]
    dif = [cpt.DiffractionProblem(wave_direction=float(b), **common) for b in betas_rad]
    results = solver.solve_all(rad + dif, progress_bar=False, keep_details=True)
    # see boatland.hydro.build._solve: Capytaine 3.0.0 memoises the influence matrices of every frequency
    NestedBlockCirculantMatrix.to_BlockCirculantMatrix.cache_clear()
    return results[:len(rad)], results[len(rad):]


def _quiet():
    """Raise Capytaine's logger to ERROR; returns the function that restores it."""
    import logging

    log = logging.getLogger("capytaine")
    old = log.level
    log.setLevel(max(logging.ERROR, old))
    return lambda: log.setLevel(old)
