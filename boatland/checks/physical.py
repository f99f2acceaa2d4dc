r"""Physical checks of a scenario that need the vessel's hydrodynamic database.

:func:`check_against` looks at a :class:`~boatland.landing.setup.Setup` (the scenario on its vessel) before
any computation; :func:`boatland.checks.check` runs it with the other checks. Problems carry the
scenario's key paths:

- the database has a mass matrix (the time domain needs M);
- the fender is at the bow: every contact point within the front 20 % of the hull's length (from the
  hull mesh), at most 10 % of the length ahead of the stem, and within the hull's beam;
- dt resolves the fender: ``dt ≤ T_c / 20`` with T_c the period of the fastest contact mode
  (:func:`boatland.landing.contacts.contact_period`); the waves' band is checked when loading (no database needed);
- the hull is clear of the monopile and the struts at t = 0; the water is deeper than the draft;
- roll damping as a fraction of critical needs roll restoring.

Warnings: wave energy above the database's highest frequency (its excitation would be taken as zero),
a database computed for another water depth, a radiation memory longer than the database's
frequency step resolves (π/Δω), no A∞ or no hull mesh.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.landing.contacts import STEPS_PER_CONTACT_PERIOD, STEPS_PER_SHEAR_PERIOD
from boatland.landing.setup import Setup
from boatland.scenario.parts import rotation_2d
from boatland.sea.states import OUT_OF_BAND_WARN, MeasuredRecord, RegularWave
from boatland.tomlspec import SpecError
from boatland.vessel.database import HydroDB, roll_critical_damping
from boatland.vessel.directions import direction_coverage

__all__ = ["ScenarioCheck", "check_against"]

#: The fender must sit in this front fraction of the hull's length ...
BOW_FRACTION = 0.2
#: ... and at most this fraction of the length ahead of the stem (fender depth, bow overhang).
AHEAD_FRACTION = 0.1


@dataclass(frozen=True)
class ScenarioCheck:
    """Result of :func:`check_against`.

    Attributes
    ----------
    problems : tuple of (str, str)
        ``(key_path, message)``: the scenario cannot run with this database.
    warnings : tuple of (str, str)
        ``(key_path, message)``: it can, but probably not as meant.
    notes : tuple of str
        What was derived (time step, contact period, start pose) for the user to see.
    setup : Setup or None
        The scenario on its vessel the checks looked at (:func:`boatland.checks.check`): a run can start
        from it instead of deriving it again.
    """

    problems: tuple[tuple[str, str], ...]
    warnings: tuple[tuple[str, str], ...]
    notes: tuple[str, ...]
    setup: Setup | None = field(default=None, compare=False, repr=False)

    @property
    def ok(self) -> bool:
        return not self.problems

    def raise_if_problems(self, source: str) -> None:
        """Raise the problems as one :class:`SpecError` naming ``source`` (the scenario file)."""
        if self.problems:
            raise SpecError(source, list(self.problems))


def _variance_share_above(waves, omega_max: float) -> float:
    if isinstance(waves, RegularWave):
        return 1.0 if waves.omega > omega_max else 0.0
    if isinstance(waves, MeasuredRecord):
        c = waves.realise()
        v = c.a ** 2
        return float(v[c.omega > omega_max].sum() / max(v.sum(), 1e-300))
    wp = min(p.omega_p for p in waves.parts)
    w = np.linspace(1e-3 * wp, max(40.0 * wp, 2 * omega_max), 20001)
    S = waves.spectrum(w)
    total = np.trapezoid(S, w)       # numpy's, the same sum as scipy's (scipy.integrate: 0.23 s to import)
    return float(np.trapezoid(np.where(w > omega_max, S, 0.0), w) / total) if total > 0 else 0.0


def check_against(setup: Setup) -> ScenarioCheck:
    """Check a scenario against its database, through its :class:`~boatland.landing.setup.Setup`."""
    scenario, db = setup.scenario, setup.db
    problems: list[tuple[str, str]] = []
    warns: list[tuple[str, str]] = []
    notes: list[str] = []
    v = scenario.vessel
    if db.M is None:
        problems.append(("vessel.database", f"the database {db.name!r} has no mass matrix M; a time-domain run "
                                            "needs mass, centre of gravity and inertia"))
    if db.A_inf is None:
        warns.append(("vessel.database", "the database has no infinite-frequency added mass A∞; it is estimated "
                                         "from Ogilvie's relation (sensitive to the top of the band)"))
    mesh = db.mesh.vertices if db.mesh is not None else None
    if mesh is None:
        warns.append(("vessel.database", "the database has no hull mesh: fender position and monopile clearance "
                                         "are not checked against the hull"))
    if scenario.landing is not None and (v.position_derived or v.heading_derived):
        pos_how = " (derived: fender just touching)" if v.position_derived else ""
        head_how = " (derived: bow on the landing)" if v.heading_derived else ""
        notes.append(f"start pose: position ({v.position[0]:.3f}, {v.position[1]:.3f}) m{pos_how}, "
                     f"heading {v.heading_deg:g}°{head_how}")
    if scenario.fender is not None and mesh is not None:
        problems += _fender_on_bow(scenario.fender, mesh, db.name)
    if scenario.landing is not None and scenario.landing.diffraction and mesh is None:
        problems.append(("landing.diffraction", f"the database {db.name!r} has no hull mesh to integrate the "
                                                "pile's scattered wave over: set diffraction = false, or use a "
                                                "database built by 'boatland hydro build' (it stores the mesh)"))
    elif setup.pile is not None:
        notes.append("monopile diffraction: the pile's scattered wave (MacCamy–Fuchs) acts on the hull panels")
    dt = setup.dt
    rule = "" if scenario.simulation.dt is not None else " (default rule: min(0.05 s, Tp/100, T_contact/20))"
    notes.append(f"time step dt = {dt:.5g} s{rule}, {setup.n_steps} steps")
    if setup.contact_period is not None:
        cp = setup.contact_period
        f = scenario.fender
        notes.append(f"fender contact: fastest normal mode period {cp.period:.4g} s; effective mass along the normal "
                     + ", ".join(f"{m:.4g} kg" for m in cp.m_eff) + "; T_f = 2π√(m_eff/c_f) = "
                     + ", ".join(f"{t:.4g} s" for t in cp.undamped))
        if setup.fender.lumped:
            notes.append(f"fender geometry: the static compression under the thrust, "
                         f"{setup.fender.compression:.3g} m, reaches past the tubes' "
                         "axes: c_f is a lumped spring, and the fender pushes on a flat plate at the tubes' front "
                         "along the landing's normal (the contact plane of Ferreira González 2023)")
        if f.rigid:
            notes.append("fender shear: rigid stick (the needed stick force is solved with the motion)")
        else:
            notes.append(f"fender shear: k_t = {f.shear_stiffness:.4g} N/m, c_t = "
                         + ", ".join(f"{c:.4g}" for c in cp.shear_damping) + " N s/m per contact"
                         + ("" if f.shear_damping is not None else
                            f" ({f.shear_damping_ratio:g} of critical on {min(cp.m_eff_vertical):.4g} kg)")
                         + f"; fastest stuck mode period {cp.shear_period:.4g} s")
        limit = cp.dt_limit
        if dt > limit * (1 + 1e-9):
            which = (f"its fastest normal contact mode has period {cp.period:.3g} s (c_f = {f.stiffness:g} N/m, "
                     f"d_f = {f.damping:g} N s/m, effective mass {min(cp.m_eff):.4g} kg): period / "
                     f"{STEPS_PER_CONTACT_PERIOD}" if limit == cp.period / STEPS_PER_CONTACT_PERIOD else
                     f"its stuck shear mode has period {cp.shear_period:.3g} s (k_t = {f.shear_stiffness:g} N/m): "
                     f"period / {STEPS_PER_SHEAR_PERIOD}")
            problems.append(("simulation.dt", f"{dt:g} s is too large for the fender: {which}; use dt ≤ {limit:.3g} s"))
    if scenario.sea is not None:
        problems_w, warns_w = _waves_in_band(setup)
        problems += problems_w
        warns += warns_w
    if scenario.landing is not None and mesh is not None:
        problems += _clearance(scenario, db.mesh, setup.start_pose)
    depth = scenario.sea.water_depth if scenario.sea is not None and scenario.sea.water_depth is not None \
        else db.water_depth
    if mesh is not None and depth <= -float(mesh[:, 2].min()):
        problems.append(("sea.water_depth", f"{depth:g} m is not deeper than the vessel's draft "
                                            f"{-float(mesh[:, 2].min()):g} m"))
    dw = float(np.min(np.diff(db.omega)))
    if scenario.radiation.memory > math.pi / dw * (1 + 1e-9):
        warns.append(("radiation.memory", f"{scenario.radiation.memory:g} s is longer than the database's frequency "
                                          f"step resolves (π/Δω = {math.pi / dw:.3g} s): K(t) beyond that is not "
                                          "reliable"))
    if v.roll_critical_fraction > 0:
        try:
            notes.append(f"roll damping: {v.roll_critical_fraction:g} of critical = "
                         f"{v.roll_critical_fraction * roll_critical_damping(db):.4g} N m s/rad added to B44")
        except BoatlandInputError as exc:
            problems.append(("vessel.damping.roll_critical_fraction", str(exc)))
    problems += _sea_directions(scenario, db, notes)
    return ScenarioCheck(problems=tuple(problems), warnings=tuple(warns), notes=tuple(notes))


def _fender_on_bow(fender, mesh: np.ndarray, name: str) -> list[tuple[str, str]]:
    out = []
    x0, x1 = float(mesh[:, 0].min()), float(mesh[:, 0].max())
    y0, y1 = float(mesh[:, 1].min()), float(mesh[:, 1].max())
    L = x1 - x0
    front = x1 - BOW_FRACTION * L
    for i, (x, y, _) in enumerate(fender.points):
        key = f"fender.points[{i}]"
        if x < front:
            out.append((key, f"x = {x:g} m is not at the bow: the hull of {name!r} spans x = {x0:g} … {x1:g} m, "
                             f"its front {100 * BOW_FRACTION:g} % starts at x = {front:g} m"))
        elif x > x1 + AHEAD_FRACTION * L:
            out.append((key, f"x = {x:g} m is {x - x1:.3g} m ahead of the stem of {name!r} (x = {x1:g} m): more than "
                             f"{100 * AHEAD_FRACTION:g} % of the hull length"))
        if not y0 <= y <= y1:
            out.append((key, f"y = {y:g} m is outside the hull's beam (y = {y0:g} … {y1:g} m)"))
    return out


def _waves_in_band(setup: Setup):
    scenario, db = setup.scenario, setup.db
    problems, warns = [], []
    waves = setup.waves
    w_max = float(db.omega[-1])
    share = _variance_share_above(waves, w_max)
    if isinstance(waves, RegularWave):
        if share > 0:
            problems.append(("sea.T", f"the wave (ω = {waves.omega:.3g} rad/s) is above the database's highest "
                                      f"frequency {w_max:g} rad/s: its excitation would be taken as zero"))
    elif share > OUT_OF_BAND_WARN:
        warns.append(("sea", f"{100 * share:.1f} % of the wave variance lies above the database's highest frequency "
                             f"{w_max:g} rad/s; its excitation is taken as zero"))
    given = scenario.sea.water_depth
    if given is not None and not (given == db.water_depth or
                                  (math.isfinite(given) and abs(given / db.water_depth - 1) < 0.01)):
        warns.append(("sea.water_depth", f"{given:g} m, but the database {db.name!r} was computed for "
                                         f"{db.water_depth:g} m"))
    return problems, warns


def _footprint_distance(c: np.ndarray, xy: np.ndarray, faces: np.ndarray) -> float:
    """Horizontal distance from point ``c`` to the hull's footprint (panels projected on the xy plane); 0 inside."""
    a = xy[faces]                      # (Np, 4, 2)
    b = np.roll(a, -1, axis=1)
    e = b - a
    t = np.clip(np.einsum("pkj,pkj->pk", c - a, e) / np.maximum(np.einsum("pkj,pkj->pk", e, e), 1e-300), 0, 1)
    d_edges = float(np.min(np.linalg.norm(a + t[..., None] * e - c, axis=-1)))
    cross = e[..., 0] * (c[1] - a[..., 1]) - e[..., 1] * (c[0] - a[..., 0])   # (Np, 4)
    area = 0.5 * np.abs(np.sum(a[..., 0] * b[..., 1] - b[..., 0] * a[..., 1], axis=1))
    inside = (area > 1e-12) & (np.all(cross >= 0, axis=1) | np.all(cross <= 0, axis=1))
    return 0.0 if np.any(inside) else d_edges


def _clearance(scenario, mesh, start_pose) -> list[tuple[str, str]]:
    """The wetted hull (its footprint) must be clear of the monopile and the struts at t = 0."""
    out = []
    x, y, psi = start_pose
    q0 = scenario.initial.displacement
    p = np.array([x, y]) + rotation_2d(math.degrees(psi)) @ q0[:2]
    xy = mesh.vertices[:, :2] @ rotation_2d(math.degrees(psi + q0[5])).T + p
    land = scenario.landing
    key = "vessel.position" if not scenario.vessel.position_derived else "landing"
    R_pile = land.monopile_diameter / 2
    d = _footprint_distance(np.asarray(land.monopile_position, float), xy, mesh.faces)
    if d < R_pile:
        out.append((key, f"the hull reaches {R_pile - d:.3g} m into the monopile at t = 0"))
    for i, st in enumerate(land.struts):
        ds = _footprint_distance(np.asarray(st.position, float), xy, mesh.faces)
        if ds < st.diameter / 2:
            out.append((key, f"the hull overlaps struts[{i}] at t = 0 (by {st.diameter / 2 - ds:.3g} m): the "
                             "fender points must be ahead of the hull"))
    return out


def _sea_directions(scenario, db: HydroDB, notes: list[str]) -> list[tuple[str, str]]:
    """The sea's directions relative to the vessel against those the database covers (the database's
    case goes to ``notes``: full circle, completed by port–starboard symmetry, interval, single).

    Each wave system's relative direction is its direction minus the vessel's heading; a short-crested
    one (cos-2s spreading, :func:`boatland.waves.spectra.spreading_cos2s`, whose cos^2s(u/2) is
    positive on the whole circle and whose stratified realisation reaches far into the tails) needs
    the whole circle. Problems are keyed by the direction key as written (or the spreading).
    """
    cov = direction_coverage(db)
    notes.append(cov.describe())
    if scenario.sea is None or cov.periodic:
        return []
    raw = scenario.document.get("sea", {})
    waves = scenario.sea.waves
    if "parts" in raw:
        systems = [(f"sea.parts[{i}].", p, raw["parts"][i]) for i, p in enumerate(waves.parts)]
    else:
        systems = [("sea.", waves.parts[0] if hasattr(waves, "parts") else waves, raw)]
    name = repr(scenario.vessel.database or db.name)
    heading = scenario.vessel.heading_deg
    out = []
    for prefix, w, r in systems:
        rel = (w.direction_deg - heading) % 360.0
        if getattr(w, "spreading", None) is not None:
            what = (f"short-crested waves (cos-2s, s = {w.spreading:g}) about {rel:.10g}° spread over the whole "
                    "circle, which is")
            out.append((prefix + "spreading", cov.refusal(what, name) + " for long-crested waves (no spreading)"))
        elif not cov.covers(rel)[0]:
            if "relative_direction_deg" in r:
                out.append((prefix + "relative_direction_deg", cov.refusal(f"{rel:.10g}° is", name)))
            else:
                what = f"{w.direction_deg:.10g}° ({rel:.10g}° relative to the vessel's heading {heading:.10g}°) is"
                out.append((prefix + "direction_deg", cov.refusal(what, name)))
    return out
