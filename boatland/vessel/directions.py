r"""Which wave directions a hydrodynamic database covers, and its completion by port–starboard symmetry.

A BEM run gives the excitation X(ω, β) at the directions it was asked for. Three cases:

full circle
    The directions go round the circle (:func:`boatland.waves.excitation.periodic_directions`: the
    wrap-around gap 360° − (β_last − β_first) is no larger than the largest step): X is interpolated
    periodically in β.
half circle of a symmetric hull
    WAMIT, AQWA and NEMOH users of a port–starboard symmetric hull usually compute 0–180° only (or
    any half circle on one side, 180–360°, −180–0°). Reflection in the hull's xz plane (y → −y)
    maps the problem of direction β onto that of −β (≡ 360° − β) and changes the sign of the
    antisymmetric DOFs, so for a hull symmetric about its centre plane (Newman 1977, *Marine
    Hydrodynamics*, MIT Press, on the symmetry relations of the added-mass, damping and exciting-force
    coefficients; Faltinsen 1990, *Sea Loads on Ships and Offshore Structures*, ch. 3: with lateral
    symmetry sway, roll and yaw uncouple from surge, heave and pitch)

    .. math::
        X_j(360° - \beta) = s_j\,X_j(\beta), \qquad
        A_{ij} = B_{ij} = C_{ij} = M_{ij} = 0 \ \text{for } s_i s_j = -1, \qquad
        s = (+1, -1, +1, -1, +1, -1)

    (:data:`boatland.conventions.PORT_STARBOARD_SIGN`; DOF order surge … yaw). The table is then
    completed to the circle with the mirrored directions — **only when the database shows the
    symmetry** (:func:`port_starboard_symmetry`: no surge/heave/pitch–sway/roll/yaw coupling in A(ω),
    B(ω), A∞, A₀, C, M, and X(−β) = s X(β) wherever the table holds both β and −β, e.g. at 0° and
    180°, within :data:`SYMMETRY_RTOL`).
an interval, or a single direction
    Anything else — an asymmetric half circle, a quarter circle, one direction — is known on
    [β_first, β_last] only; other directions are refused (:func:`direction_problem`) and the
    kernel returns NaN for them rather than a number interpolated across the uncovered arc.

The database object itself is never changed: :func:`full_circle_excitation` builds the completed
table for :func:`boatland.sea.states.excitation_table`, the one place the time domain and the
frequency domain take X from. The mean drift (``HydroDB.drift``, real, same layout) obeys the same
reflection, :math:`D_j(360° - \beta) = s_j D_j(\beta)`; :func:`full_circle_drift` completes it on the
same directions as X.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from boatland.conventions import DOF_NAMES, PORT_STARBOARD_SIGN
from boatland.vessel.database import HydroDB
from boatland.waves.excitation import DIRECTION_ATOL_DEG, PERIODIC_STEP_RTOL, periodic_directions

__all__ = ["DirectionCoverage", "SYMMETRY_RTOL", "Symmetry", "direction_coverage", "direction_problem",
           "full_circle_drift", "full_circle_excitation", "port_starboard_symmetry"]

#: Largest relative port–starboard asymmetry (:func:`port_starboard_symmetry`) for which a half-circle
#: database is completed by mirroring. Well above round-off: BEM text output keeps 5–7 significant
#: digits, and a symmetric mesh solved without using its symmetry leaves "zero" couplings at the
#: solver's round-off (ctv24, mirrored by construction: 2e-15). Well below what matters: the mirrored
#: X is then wrong by at most this fraction of the largest force or moment, far less than a BEM's
#: panel-discretisation error (typically a few per cent), while a hull that is really asymmetric
#: (heeled, an appendage on one side, a mesh that is not mirrored) is expected to couple its
#: symmetric and antisymmetric DOFs at the per-cent level.
SYMMETRY_RTOL = 1e-3

_SYM = (0, 2, 4)    # surge, heave, pitch: s = +1
_ANTI = (1, 3, 5)   # sway, roll, yaw: s = −1


def _sci(x: float) -> str:
    """1.3e-16 → '1e-16', 0.03 → '3e-2', 0 → '0'."""
    if x == 0:
        return "0"
    if not np.isfinite(x):
        return str(x)
    m, e = f"{x:.0e}".split("e")
    return f"{m}e{int(e)}"


def _deg(b: float) -> str:
    return f"{b:.10g}"


@dataclass(frozen=True)
class Symmetry:
    """Result of :func:`port_starboard_symmetry`.

    Attributes
    ----------
    coupling : float
        Largest relative asymmetry found (0 for an exactly mirrored database).
    what, where : str
        What it was and where, e.g. ``"sway–heave coupling"``, ``"in B"`` or ``"sway excitation"``,
        ``"at 0°"``.
    """

    coupling: float
    what: str = ""
    where: str = ""

    @property
    def symmetric(self) -> bool:
        """True when ``coupling`` ≤ :data:`SYMMETRY_RTOL`."""
        return bool(self.coupling <= SYMMETRY_RTOL)

    @property
    def text(self) -> str:
        """E.g. ``"sway–heave coupling 3e-2 in B"``."""
        return " ".join(t for t in (self.what, _sci(self.coupling), self.where) if t)


def _matrix_asymmetry(T: np.ndarray) -> tuple[float, int, int]:
    r"""Largest :math:`\max_\omega|T_{ij}| / \sqrt{d_i d_j}` over symmetric–antisymmetric pairs (i, j).

    :math:`d_i = \max_\omega |T_{ii}|` (a correlation-like, unit-free ratio, ≤ 1 for a positive
    semi-definite T); a DOF without a diagonal term (no surge, sway or yaw restoring) takes the
    largest diagonal of its kind (translation or rotation), so the ratio keeps its units right.
    """
    T = np.abs(np.asarray(T, dtype=float))
    T = T if T.ndim == 3 else T[:, :, None]
    peak = T.max(axis=2)                       # (6, 6)
    d = np.diag(peak).copy()
    for kind in (slice(0, 3), slice(3, 6)):
        d[kind] = np.where(d[kind] > 0, d[kind], d[kind].max())
    best, where = 0.0, (1, 0)
    for i in range(6):
        for j in range(6):
            if (i in _SYM) == (j in _SYM) or peak[i, j] == 0:
                continue
            scale = np.sqrt(d[i] * d[j])
            r = peak[i, j] / scale if scale > 0 else np.inf
            if r > best:
                best, where = float(r), (i, j)
    return best, *where


def _mirror_pairs(beta_deg: np.ndarray) -> list[tuple[int, int]]:
    """Index pairs (k, l) with β_l ≡ −β_k (mod 360°) in the table (k = l at 0° and 180°)."""
    b = np.mod(np.asarray(beta_deg, dtype=float), 360.0)
    m = np.mod(-b, 360.0)
    diff = np.abs(np.mod(m[:, None] - b[None, :] + 180.0, 360.0) - 180.0)
    return [(int(k), int(l)) for k, l in zip(*np.nonzero(diff <= DIRECTION_ATOL_DEG))]


def port_starboard_symmetry(db: HydroDB) -> Symmetry:
    r"""How far ``db`` is from a port–starboard symmetric hull (module docstring).

    Checks, each as a ratio that is 0 for an exactly symmetric hull:

    - A(ω), B(ω), A∞, A₀, C, M: the coupling of a symmetric DOF i (surge, heave, pitch) with an
      antisymmetric one j (sway, roll, yaw), :math:`\max_\omega|T_{ij}| / \sqrt{d_i d_j}` with d the
      largest diagonal terms (:func:`_matrix_asymmetry`);
    - X wherever the table holds both β and −β (at least 0° and 180° for a 0–180° table): its part
      that breaks the mirror, :math:`\max_\omega \tfrac12|X_j(-\beta) - s_j X_j(\beta)|` (at 0° and
      180° simply the sway, roll and yaw excitation), over the largest |X| of the same kind (forces
      or moments) in the whole table.

    Returns
    -------
    Symmetry
        The largest ratio and where it is; ``symmetric`` when it is ≤ :data:`SYMMETRY_RTOL`.
    """
    best = Symmetry(0.0)
    for name in ("A", "B", "A_inf", "A_0", "C", "M"):
        T = getattr(db, name)
        if T is None:
            continue
        r, i, j = _matrix_asymmetry(T)
        if r > best.coupling:
            anti, sym = (i, j) if i in _ANTI else (j, i)
            best = Symmetry(r, f"{DOF_NAMES[anti]}–{DOF_NAMES[sym]} coupling", f"in {name}")
    X = np.asarray(db.X)
    scale = np.empty(6)
    scale[:3] = np.abs(X[:3]).max()
    scale[3:] = np.abs(X[3:]).max()
    for k, l in _mirror_pairs(db.wave_dir_deg):
        dev = 0.5 * np.abs(X[:, l, :] - PORT_STARBOARD_SIGN[:, None] * X[:, k, :]).max(axis=1)   # (6,)
        ratio = np.where(scale > 0, dev / np.where(scale > 0, scale, 1.0), np.where(dev > 0, np.inf, 0.0))
        j = int(np.argmax(ratio))
        if ratio[j] > best.coupling:
            b_l, b_k = db.wave_dir_deg[l], db.wave_dir_deg[k]
            at = f"at {_deg(b_l)}°" if k == l else f"at {_deg(b_l)}° against {_deg(b_k)}° mirrored"
            best = Symmetry(float(ratio[j]), f"{DOF_NAMES[j]} excitation", at)
    return best


def _unique_turn(b: np.ndarray) -> np.ndarray:
    """Directions mapped to [0, 360), sorted, duplicates (within the tolerance, across 0/360) merged."""
    b = np.sort(np.mod(b, 360.0))
    b = np.where(b >= 360.0 - DIRECTION_ATOL_DEG, 0.0, b)
    b = np.sort(b)
    keep = np.concatenate([[True], np.diff(b) > DIRECTION_ATOL_DEG])
    return b[keep]


def _largest_step(b: np.ndarray) -> tuple[float, float, float]:
    """(size, from, to) of the largest step between directions sorted in [0, 360), the wrap included."""
    ext = np.append(b, b[0] + 360.0)
    k = int(np.argmax(np.diff(ext)))
    return float(ext[k + 1] - ext[k]), float(ext[k]), float(np.mod(ext[k + 1], 360.0))


@dataclass(frozen=True)
class DirectionCoverage:
    """Which directions a database's excitation is known for (:func:`direction_coverage`).

    Attributes
    ----------
    kind : {"full", "mirrored", "interval", "single"}
        Full circle as tabulated; full circle after port–starboard completion; [first, last] only;
        one direction.
    first, last : float
        First and last tabulated direction [deg].
    n : int
        Number of tabulated directions.
    step : float or None
        The step between tabulated directions when uniform [deg].
    symmetry : Symmetry or None
        The port–starboard check, made when mirroring would close the circle.
    why : str
        Why an interval is not completed ("" for the other kinds).
    """

    kind: str
    first: float
    last: float
    n: int
    step: float | None
    symmetry: Symmetry | None = None
    why: str = ""

    @property
    def periodic(self) -> bool:
        """The excitation is known all round the circle (as tabulated or completed)."""
        return self.kind in ("full", "mirrored")

    @property
    def span(self) -> str:
        """The tabulated directions, e.g. ``"0–180°"`` or ``"180°"``."""
        return f"{_deg(self.first)}°" if self.n == 1 else f"{_deg(self.first)}–{_deg(self.last)}°"

    @property
    def valid(self) -> str:
        """The directions that may be asked for, as text."""
        if self.periodic:
            return "any direction"
        return f"{_deg(self.first)}° only" if self.kind == "single" else self.span

    def covers(self, beta_deg) -> np.ndarray:
        """Whether each direction [deg, any turn] is covered (within :data:`DIRECTION_ATOL_DEG`)."""
        b = np.atleast_1d(np.asarray(beta_deg, dtype=float))
        if self.periodic:
            return np.ones(b.shape, dtype=bool)
        t = self.first - DIRECTION_ATOL_DEG + np.mod(b - self.first + DIRECTION_ATOL_DEG, 360.0)
        return t <= self.last + DIRECTION_ATOL_DEG

    def covers_arc(self, lo: float, hi: float) -> bool:
        """Whether every direction from ``lo`` to ``hi`` ≥ lo (counter-clockwise) [deg] is covered."""
        if self.periodic:
            return True
        if hi - lo >= 360.0:
            return False
        t = self.first - DIRECTION_ATOL_DEG + np.mod(lo - self.first + DIRECTION_ATOL_DEG, 360.0)
        return bool(t + (hi - lo) <= self.last + DIRECTION_ATOL_DEG)

    @property
    def reason(self) -> str:
        """Why directions outside are refused, for messages (e.g. ``"0–180°, not port–starboard symmetric:
        sway–heave coupling 3e-2 in B"``)."""
        if self.kind == "single":
            return f"single direction {_deg(self.first)}°"
        if self.symmetry is not None and not self.symmetry.symmetric:
            return f"{self.span}, not port–starboard symmetric: {self.symmetry.text}"
        return f"{self.span}, {self.why}" if self.why else self.span

    @property
    def case(self) -> str:
        """Which case applies, without the table (e.g. ``"full circle"``), for ``boatland hydro info``."""
        if self.kind == "full":
            return "full circle"
        if self.kind == "mirrored":
            return (f"completed to 360° by port–starboard symmetry (checked: max coupling "
                    f"{_sci(self.symmetry.coupling)})")
        if self.kind == "single":
            return f"single direction {self.span}: other directions refused"
        if self.symmetry is not None:
            return f"asymmetric ({self.symmetry.text}): directions outside {self.span} refused"
        return f"{self.why}: directions outside {self.span} refused"

    def describe(self) -> str:
        """One line for ``boatland scenario check``, e.g. ``"database directions 0–180° every 5°, completed
        to 360° by port–starboard symmetry (checked: max coupling 2e-15)"``."""
        if self.kind == "single":
            return f"database with a {self.case}"
        every = f" every {self.step:g}°" if self.step is not None and self.n > 2 else ""
        return f"database directions {self.span}{every}{':' if self.kind == 'full' else ','} {self.case}"

    def refusal(self, what: str, name: str) -> str:
        """The one-line message for ``what`` (e.g. ``"225°"``) outside these directions of database ``name``."""
        return f"{what} outside the directions of database {name} ({self.reason}); valid: {self.valid}"


def direction_coverage(db: HydroDB) -> DirectionCoverage:
    """Which directions ``db``'s excitation covers: full circle, mirrored half circle, interval or single.

    The half circle is completed (kind ``"mirrored"``) when the tabulated directions together with
    their mirror images −β go round the circle with no step (the wrap-around included) larger than the
    table's own largest step — the completed table is no coarser than the computed one — and
    :func:`port_starboard_symmetry` finds the hull symmetric; the symmetry is checked only then.
    """
    beta = np.asarray(db.wave_dir_deg, dtype=float)
    steps = np.diff(beta)
    step = float(steps[0]) if steps.size and np.allclose(steps, steps[0], rtol=0, atol=1e-6) else None
    base = dict(first=float(beta[0]), last=float(beta[-1]), n=int(beta.size), step=step)
    if periodic_directions(beta):
        return DirectionCoverage(kind="full", **base)
    if beta.size == 1:
        return DirectionCoverage(kind="single", **base)
    gap, lo, hi = _largest_step(_unique_turn(np.concatenate([beta, -beta])))
    if gap > (1.0 + PERIODIC_STEP_RTOL) * float(steps.max()):
        return DirectionCoverage(kind="interval", **base,
                                 why=f"with its port–starboard mirror it still has a {gap:.4g}° gap, "
                                     f"{_deg(lo)}–{_deg(hi)}°")
    sym = port_starboard_symmetry(db)
    return DirectionCoverage(kind="mirrored" if sym.symmetric else "interval", symmetry=sym, **base)


def full_circle_excitation(db: HydroDB, coverage: DirectionCoverage | None = None) -> tuple[np.ndarray, np.ndarray]:
    r"""(beta_deg, X) of ``db``, completed to the circle by :math:`X_j(-\beta) = s_j X_j(\beta)` when it is
    a checked symmetric half circle (:func:`direction_coverage` kind ``"mirrored"``); otherwise the
    database's own table.

    The completed table holds every tabulated direction (mapped to [0, 360°)) and the mirror image of
    each one whose mirror is not tabulated, sorted; where both are tabulated the table's own value is
    kept (they agree within :data:`SYMMETRY_RTOL`: checked).

    Returns
    -------
    beta_deg : ndarray, shape (Nb',)
        Directions [deg], increasing (in [0, 360) when completed).
    X : ndarray of complex, shape (6, Nb', Nf)
    """
    return _completed(db, np.asarray(db.X, dtype=complex), coverage or direction_coverage(db))


def full_circle_drift(db: HydroDB, coverage: DirectionCoverage | None = None) -> tuple[np.ndarray, np.ndarray] | None:
    r"""(beta_deg, drift) of ``db``, completed to the circle like :func:`full_circle_excitation`, by
    :math:`D_j(-\beta) = s_j D_j(\beta)` (a mirrored wave pushes the mirrored body with the mirrored mean
    force); None when the database has no mean drift.

    Returns
    -------
    beta_deg : ndarray, shape (Nb',)
        The same directions as :func:`full_circle_excitation` gives.
    drift : ndarray, shape (6, Nb', Nf)
    """
    if db.drift is None:
        return None
    return _completed(db, np.asarray(db.drift, dtype=float), coverage or direction_coverage(db))


def _completed(db: HydroDB, T: np.ndarray, cov: DirectionCoverage) -> tuple[np.ndarray, np.ndarray]:
    """The (6, Nb, Nf) table ``T`` of ``db``'s directions completed by mirroring when ``cov`` says so."""
    beta = np.asarray(db.wave_dir_deg, dtype=float)
    if cov.kind != "mirrored":
        return beta, T
    b = np.mod(beta, 360.0)
    b = np.where(b >= 360.0 - DIRECTION_ATOL_DEG, 0.0, b)
    m = np.mod(-beta, 360.0)
    m = np.where(m >= 360.0 - DIRECTION_ATOL_DEG, 0.0, m)
    dist = np.abs(np.mod(m[:, None] - b[None, :] + 180.0, 360.0) - 180.0)
    new = ~np.any(dist <= DIRECTION_ATOL_DEG, axis=1)
    all_b = np.concatenate([b, m[new]])
    all_T = np.concatenate([T, PORT_STARBOARD_SIGN[:, None, None] * T[:, new, :]], axis=1)
    order = np.argsort(all_b, kind="stable")
    return all_b[order], all_T[:, order, :]


def direction_problem(db: HydroDB, directions, *, name: str | None = None,
                      coverage: DirectionCoverage | None = None) -> str | None:
    """The problem, as one line, when ``db`` does not cover ``directions``; None when it does.

    Parameters
    ----------
    db : HydroDB
    directions : iterable
        Relative wave directions [deg] a sea or a computation will use: each a number, or a pair
        ``(lo, hi)`` with hi ≥ lo for the arc from lo to hi (counter-clockwise; hi − lo ≥ 360: the
        whole circle).
    name : str, optional
        How to name the database (the file as the user gave it); default ``repr(db.name)``.
    coverage : DirectionCoverage, optional
        ``direction_coverage(db)`` when already known.

    Returns
    -------
    str or None
        E.g. ``"225°, 270° are outside the directions of database 'x.h5' (0–180°, not port–starboard
        symmetric: sway–heave coupling 3e-2 in B); valid: 0–180°"``.
    """
    cov = coverage or direction_coverage(db)
    if cov.periodic:
        return None
    items = list(directions) if np.ndim(directions) else [directions]
    points = np.array([float(d) for d in items if np.ndim(d) == 0])
    bad: list[str] = []
    for b in np.mod(points[~cov.covers(points)], 360.0) if points.size else ():
        text = f"{_deg(float(b))}°"
        if text not in bad:
            bad.append(text)
    for d in items:
        if np.ndim(d) == 0:
            continue
        lo, hi = (float(v) for v in d)
        if not cov.covers_arc(lo, hi):
            bad.append("the whole circle" if hi - lo >= 360.0 else
                       f"{_deg(float(np.mod(lo, 360.0)))}–{_deg(float(np.mod(hi, 360.0)))}°")
    if not bad:
        return None
    shown = ", ".join(bad[:6]) + (f" and {len(bad) - 6} more" if len(bad) > 6 else "")
    return cov.refusal(f"{shown} {'is' if len(bad) == 1 else 'are'}", name or repr(db.name))
