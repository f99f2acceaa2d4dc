"""The section builders of :func:`boatland.scenario.scenario.scenario_from_dict`.

Each builder reads one validated section (types, bounds and unknown keys were checked by
:func:`boatland.tomlspec.validate` against :data:`~boatland.scenario.schema.SCENARIO_SCHEMA`),
applies the cross-field rules and the database-free physical checks, adds every problem with its key
path to the shared :class:`Context`, and returns the part (or None when it cannot be built; the
loader raises before using it then). Doubtful values become notes (warnings).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Collection, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from boatland.errors import BoatlandInputError, BoatlandWarning
from boatland.loads.current import Current
from boatland.loads.skipper import Skipper
from boatland.loads.wind import Wind
from boatland.scenario.parts import (Fender, InitialState, Landing, Sea, Simulation, Strut, Thrust,
                                           VesselSetup, derive_position, rotation_2d, unit)
from boatland.scenario.schema import (FENDER_PRESET_ALIASES, FENDER_PRESETS, FENDER_REQUIRED, LANDING_COMPACT, SCENARIO_SCHEMA,
                                            SEA_KIND_KEYS, SEA_KINDS, SHEAR_DAMPING_RATIO_DEFAULT,
                                            SHEAR_STIFFNESS_DEFAULT)
from boatland.sea.spectra import SpectrumPart, spectrum_part_problems
from boatland.sea.states import MeasuredRecord, RegularWave, SeaState
from boatland.tomlspec import Problems, SpecError, did_you_mean

__all__ = ["Context", "fender", "flows", "initial", "landing", "sea", "simulation", "thrust", "vessel"]

#: Fender key defaults when neither the file nor a preset gives them (Stribeck shape of Ferreira
#: González 2023 Table 5.4, no viscous term; the compliant rubber of Grøtting 2015 §3.2.2; a point).
FENDER_DEFAULTS = {"k_v": 0.0, "v_ref": 0.2, "delta": 1.5, "shear_stiffness": SHEAR_STIFFNESS_DEFAULT,
                   "shear_damping_ratio": SHEAR_DAMPING_RATIO_DEFAULT, "width": 0.0}
_FENDER_KEYS = ("stiffness", "damping", "mu_s", "mu_k", "k_v", "v_ref", "delta", "shear_stiffness",
                "shear_damping", "shear_damping_ratio", "width")
#: Ferreira González (2023) §2.5.1: the Stribeck exponent δ lies in [0.5, 2.0].
DELTA_USUAL = (0.5, 2.0)
#: Variance fraction above the "shortest significant period" of a spectrum (dt ≤ that period / 20).
SIGNIFICANT_TAIL = 0.01
#: dt must resolve the shortest significant wave period with this many steps.
STEPS_PER_WAVE_PERIOD = 20
#: Initial rotations beyond this are outside linear hydrodynamics [deg].
MAX_INITIAL_ROTATION_DEG = 30.0
#: Thrust more than this far off the landing's normal makes the fender slide sideways [deg].
THRUST_ANGLE_WARN_DEG = 30.0
_SEA_ENTRIES = SCENARIO_SCHEMA.entries["sea"].entries


@dataclass
class Context:
    """What the builders share: the document as written, the validated values, the problems."""

    doc: Mapping[str, Any]
    data: dict[str, Any]
    problems: Problems
    base_dir: Path
    notes: list[str]

    def raw(self, section: str) -> dict[str, Any]:
        v = self.doc.get(section)
        return v if isinstance(v, dict) else {}

    def add(self, key: str, message: str) -> None:
        """Record a problem unless the key already has one (no second, misleading message)."""
        if not self.problems.has(key):
            self.problems.add(key, message)

    def one_of(self, raw: Mapping, prefix: str, group: tuple[str, ...], why: str) -> None:
        given = [k for k in group if k in raw]
        if not given:
            self.add(prefix + group[0], f"missing: give {' or '.join(prefix + k for k in group)} ({why})")
        elif len(given) > 1:
            self.add(prefix + given[1], f"give either {prefix + given[0]} or {prefix + given[1]}, not both")


# ---------------------------------------------------------------------------------------- landing
def landing(ctx: Context) -> Landing | None:
    if "landing" not in ctx.data:
        return None
    d, raw = ctx.data["landing"], ctx.raw("landing")
    compact = [k for k in LANDING_COMPACT if k in raw]
    form = ", ".join(LANDING_COMPACT)
    if "struts" in raw and compact:
        ctx.add("landing.struts", f"give either [[landing.struts]] or the compact form ({form}), not both")
        return None
    if "struts" not in raw and not compact:
        ctx.add("landing", f"no struts: give {form} (two struts), or [[landing.struts]] tables")
        return None
    for k in LANDING_COMPACT:
        if compact and k not in raw:
            ctx.add(f"landing.{k}", f"missing: the compact landing needs all of {form}")
    if ctx.problems.has("landing"):
        return None
    D, c = d["monopile_diameter"], np.array(d["monopile_position"], dtype=float)
    if compact:
        beta, spacing, dd, off = (d[k] for k in LANDING_COMPACT)
        if off <= dd / 2:
            ctx.add("landing.standoff", f"{off:g} m puts the struts (diameter {dd:g} m) into the pile surface: "
                                        f"must be > strut_diameter / 2 = {dd / 2:g} m (it is measured to the axes)")
            return None
        n = unit(beta)
        port = np.array([n[1], -n[0]])  # the vessel's port side, looking at the landing against n
        centre = c + (D / 2 + off) * n
        bottom, top = d.get("strut_bottom", -math.inf), d.get("strut_top", math.inf)
        if bottom >= top:
            ctx.add("landing.strut_top", f"{top:g} m is not above landing.strut_bottom = {bottom:g} m")
            return None
        struts = tuple(Strut((float(x), float(y)), dd, beta, bottom, top) for x, y in
                       (centre + 0.5 * spacing * port, centre - 0.5 * spacing * port))
        return Landing(monopile_diameter=D, monopile_position=(float(c[0]), float(c[1])), struts=struts,
                       bearing_deg=beta, diffraction=d.get("diffraction"))
    struts = tuple(Strut(tuple(t["position"]), t["diameter"], t["normal_deg"], t.get("bottom", -math.inf),
                         t.get("top", math.inf)) for t in d["struts"])
    for i, st in enumerate(struts):
        if st.bottom >= st.top:
            ctx.add(f"landing.struts[{i}].top", f"{st.top:g} m is not above its bottom {st.bottom:g} m")
        rel = np.array(st.position) - c
        dist = float(np.linalg.norm(rel))
        if dist <= (D + st.diameter) / 2:
            ctx.add(f"landing.struts[{i}].position",
                    f"the strut axis is {dist:.3g} m from the monopile axis: inside or against the pile "
                    f"(pile radius {D / 2:g} m + strut radius {st.diameter / 2:g} m)")
        elif float(rel @ st.normal) <= 0:
            away = math.degrees(math.atan2(rel[1], rel[0])) % 360
            ctx.add(f"landing.struts[{i}].normal_deg",
                    f"{st.normal_deg:g}° points into the monopile: the contact-plane normal points from the "
                    f"landing towards the vessel, away from the pile (here about {away:.0f}°)")
    if ctx.problems.has("landing"):
        return None
    result = Landing(monopile_diameter=D, monopile_position=(float(c[0]), float(c[1])), struts=struts,
                     diffraction=d.get("diffraction"))
    nsum = result.normals.sum(axis=0)
    if np.linalg.norm(nsum) < 1e-9 or np.min(result.normals @ (nsum / np.linalg.norm(nsum))) < 0.2:
        ctx.add("landing.struts", "the contact-plane normals point in very different directions (more than "
                                  "~80° apart): a bow fender cannot face all the struts")
        return None
    return result


# ---------------------------------------------------------------------------------------- fender, thrust
def fender(ctx: Context) -> Fender | None:
    if "fender" not in ctx.data:
        return None
    d, raw = ctx.data["fender"], ctx.raw("fender")
    if "landing" not in ctx.doc:
        ctx.add("fender", "a fender needs a [landing] to push on (omit [fender] for a free-floating run)")
    preset = d.get("preset")
    preset = FENDER_PRESET_ALIASES.get(preset, preset)       # an older name of the same preset
    values: dict[str, Any] = dict(FENDER_DEFAULTS)
    if preset is not None:
        values.update(FENDER_PRESETS[preset])
    elif "preset" not in raw:
        for k in FENDER_REQUIRED:
            if k not in raw:
                ctx.add(f"fender.{k}", f"missing (or give preset = {next(iter(FENDER_PRESETS))!r})")
    values.update({k: d[k] for k in _FENDER_KEYS if k in d})
    if "shear_damping" in raw and "shear_damping_ratio" in raw:
        ctx.add("fender.shear_damping_ratio", "give either fender.shear_damping or fender.shear_damping_ratio, "
                                              "not both")
    elif "shear_damping" in raw:
        values.pop("shear_damping_ratio", None)
    for i, (x, _, z) in enumerate(d.get("points", ())):
        if x <= 0:
            ctx.add(f"fender.points[{i}]", f"x = {x:g} m is behind the reference point (midship for the built-in "
                                           "vessels): the bow fender is at the bow (x > 0)")
        if z <= 0:
            ctx.add(f"fender.points[{i}]", f"z = {z:g} m is at or under the waterline: the fender meets the struts "
                                           "above the water (z > 0)")
    if ctx.problems.has("fender"):
        return None
    if values["mu_k"] > values["mu_s"]:
        key = "fender.mu_k" if "mu_k" in raw else "fender.mu_s"
        ctx.add(key, f"μ_k = {values['mu_k']:g} exceeds μ_s = {values['mu_s']:g}: kinetic friction is at most "
                     "static friction (Ferreira González 2023 eq. 2.76)")
        return None
    if not DELTA_USUAL[0] <= values["delta"] <= DELTA_USUAL[1]:
        ctx.notes.append(f"fender.delta = {values['delta']:g} is outside the range {DELTA_USUAL[0]}–{DELTA_USUAL[1]} "
                         "of Ferreira González 2023 §2.5.1")
    kt = values["shear_stiffness"]
    return Fender(points=tuple(tuple(p) for p in d["points"]), sideways=d["sideways"], preset=preset,
                  shear_stiffness=math.inf if kt == "rigid" else float(kt),
                  shear_damping=float(values["shear_damping"]) if "shear_damping" in values else None,
                  shear_damping_ratio=float(values.get("shear_damping_ratio", 0.0)), width=float(values["width"]),
                  **{k: float(values[k]) for k in ("stiffness", "damping", "mu_s", "mu_k", "k_v", "v_ref", "delta")})


def thrust(ctx: Context) -> Thrust | None:
    if "thrust" not in ctx.data or ctx.problems.has("thrust"):
        return None
    d = ctx.data["thrust"]
    if "fender" not in ctx.doc:
        ctx.notes.append("[thrust] without [fender]: nothing holds the vessel, the thrust accelerates it along x")
    control = Skipper.from_table(d["control"]) if "control" in d else Skipper()
    if control.active and "fender" not in ctx.doc:
        ctx.add("thrust.control.kind", "'hold_force' holds the fender's normal force: it needs a [fender]")
    if control.max_force is not None and control.max_force < control.min_force:
        ctx.add("thrust.control.max_force", f"{control.max_force:g} N is below min_force = {control.min_force:g} N")
    return Thrust(force=d["force"], position=tuple(d["position"]), ramp=d["ramp"],
                  direction_deg=d.get("direction_deg", "trim"), control=control)


# ---------------------------------------------------------------------------------------- current, wind
def flows(ctx: Context, heading: float) -> tuple[Current | None, Wind | None]:
    """The ``[current]`` and ``[wind]`` of the file (directions made global with the vessel's heading)."""
    out = []
    for key, cls in (("current", Current), ("wind", Wind)):
        d = ctx.data.get(key)
        if d is None or ctx.problems.has(key):
            out.append(None)
            continue
        raw = ctx.raw(key)
        ctx.one_of(raw, f"{key}.", ("relative_direction_deg", "direction_deg"),
                   "the direction it moves towards: 180 onto the bow, 90 from starboard")
        if not any(k in d for k in ("relative_direction_deg", "direction_deg")):
            out.append(None)                   # the problem is recorded: nothing to build
            continue
        if "table" in d and any(k in raw for k in ("c_x", "c_y", "c_n")):
            ctx.add(f"{key}.table", f"give either {key}.table or the amplitudes c_x, c_y, c_n, not both")
        t = d.get("table")
        if t is not None:
            a = list(t["angles_deg"])
            if any(len(t[k]) != len(a) for k in ("cx", "cy", "cn")):
                ctx.add(f"{key}.table", "angles_deg, cx, cy and cn must have the same length")
            elif a[0] != 0.0 or a[-1] not in (180.0, 360.0) or any(b <= c for c, b in zip(a, a[1:])):
                ctx.add(f"{key}.table.angles_deg", "must increase from 0 to 180 (port–starboard symmetric) or to 360")
            elif a[-1] == 360.0 and any(t[k][0] != t[k][-1] for k in ("cx", "cy", "cn")):
                ctx.add(f"{key}.table", "the coefficients at 0° and 360° must be equal")
        out.append(cls.from_table(d, heading))
    return out[0], out[1]


# ---------------------------------------------------------------------------------------- vessel
def _database(ctx: Context, name: str, databases: Collection[str] | None) -> Path | None:
    looks_like_path = any(ch in name for ch in "/\\") or Path(name).suffix != ""
    if databases is not None and name in databases:
        return None
    if databases is None and not looks_like_path:
        return None
    p = Path(name).expanduser()
    p = p if p.is_absolute() else ctx.base_dir / p
    if p.exists():
        return p
    if looks_like_path or databases is None:
        ctx.add("vessel.database", f"file not found: {p}")
    else:
        ctx.add("vessel.database", f"{name!r} is neither a built-in database ({', '.join(databases)})"
                                   f"{did_you_mean(name, list(databases))} nor a file ({p} not found)")
    return None


def vessel(ctx: Context, land: Landing | None, fend: Fender | None, thr: Thrust | None,
           databases: Collection[str] | None) -> VesselSetup:
    d = ctx.data.get("vessel", {})
    damping = d.get("damping", {})
    path = _database(ctx, d["database"], databases) if "database" in d else None
    heading_given = "heading_deg" in d
    heading = d["heading_deg"] if heading_given else (land.facing_heading_deg() if land is not None else 0.0)
    position = d.get("position")
    if position is None and "position" not in ctx.raw("vessel"):
        if land is not None and fend is not None and len(fend.points) == len(land.struts):
            position = derive_position(land, fend.points_array[:, :2], heading)
        elif land is not None and "fender" not in ctx.doc:
            ctx.add("vessel.position", "missing: with a [landing] but no [fender] the start position cannot be "
                                       "derived; give vessel.position = [x, y]")
    if land is not None and fend is not None:
        if len(fend.points) != len(land.struts):
            ctx.add("fender.points", f"{len(fend.points)} point(s) for {len(land.struts)} strut(s): give one point "
                                     "per strut (points[i] meets struts[i])")
        elif position is not None and not ctx.problems.has("vessel.heading_deg"):
            _contact_geometry(ctx, land, fend, thr, heading, np.array(position, dtype=float), "position" in d)
    if land is not None and thr is not None:
        _thrust_direction(ctx, land, heading, heading_given)
    zeta = damping.get("roll_critical_fraction", 0.0)
    if zeta > 0.3:
        ctx.notes.append(f"vessel.damping.roll_critical_fraction = {zeta:g} is unusually high (a few per cent to "
                         "~0.15 are usual for viscous roll damping)")
    pos = tuple(float(v) for v in position) if position is not None else (0.0, 0.0)
    return VesselSetup(database=d.get("database", ""), database_path=path, heading_deg=float(heading) % 360.0,
                       position=pos, heading_derived=not heading_given, position_derived="position" not in d,
                       linear_damping=damping.get("linear", (0.0,) * 6),
                       quadratic_damping=damping.get("quadratic", (0.0,) * 6), roll_critical_fraction=zeta)


def _contact_geometry(ctx: Context, land: Landing, fend: Fender, thr: Thrust | None, heading: float,
                      p: np.ndarray, explicit: bool) -> None:
    """Strut normals towards the vessel, no deep start penetration, each fender point on its strut."""
    P = fend.points_array[:, :2] @ rotation_2d(heading).T + p
    static = thr.force / (len(land.struts) * fend.stiffness) if thr is not None else 0.0
    allowed = 2.0 * static + 1e-3
    s = np.array([st.position for st in land.struts], dtype=float)
    for i, st in enumerate(land.struts):
        n = st.normal
        gap = float((P[i] - st.plane_point) @ n)
        if explicit and float((p - s[i]) @ n) <= 0:
            ctx.add(f"landing.struts[{i}].normal_deg",
                    f"{st.normal_deg:g}° points away from the vessel (its reference point is behind the contact "
                    "plane): the normal points from the landing towards the vessel")
            continue
        if explicit and gap < -allowed:
            ctx.add("vessel.position", f"fender.points[{i}] starts {-gap:.3g} m inside the contact plane of "
                                       f"struts[{i}] (more than twice the static compression {static:.3g} m under "
                                       "the thrust): an impact; omit vessel.position to start just touching")
        elif explicit and gap > 1e-6:
            ctx.notes.append(f"fender.points[{i}] starts {gap:.3g} m away from struts[{i}] (no contact at t = 0)")
        z = float(fend.points[i][2])
        if not st.bottom <= z <= st.top:
            ctx.add(f"fender.points[{i}]", f"z = {z:g} m is not on struts[{i}], which runs from z = {st.bottom:g} "
                                           f"to {st.top:g} m")
        t = np.array([-n[1], n[0]])
        off = float((P[i] - s[i]) @ t)
        others = [float(np.linalg.norm(s[j] - s[i])) for j in range(len(s)) if j != i]
        tol = max(st.diameter / 2, 0.5 * min(others)) if others else st.diameter / 2
        if abs(off) > tol + 1e-9:
            ctx.add(f"fender.points[{i}]",
                    f"misses struts[{i}]: {abs(off):.3g} m to the side of the strut axis at t = 0 (at most "
                    f"{tol:.3g} m); points[i] meets struts[i] — in the compact landing struts[0] is on the "
                    "vessel's port side (y > 0)")


def _thrust_direction(ctx: Context, land: Landing, heading: float, heading_given: bool) -> None:
    cos = -float(unit(heading) @ land.mean_normal)
    key = "vessel.heading_deg" if heading_given else "thrust.force"
    facing = math.degrees(math.atan2(land.mean_normal[1], land.mean_normal[0])) % 360
    if cos <= 0:
        ctx.add(key, f"the thrust (along the vessel's x axis, heading {heading:g}°) does not push towards the "
                     f"landing (its struts face {facing:.0f}°)")
    elif math.degrees(math.acos(min(cos, 1.0))) > THRUST_ANGLE_WARN_DEG:
        ctx.notes.append(f"the thrust is {math.degrees(math.acos(cos)):.0f}° off the landing's normal: it pushes "
                         "the fender sideways along the struts")


# ---------------------------------------------------------------------------------------- sea
def sea(ctx: Context, heading: float) -> Sea | None:
    if "sea" not in ctx.data:
        return None
    d, raw = ctx.data["sea"], ctx.raw("sea")
    if "parts" in raw:
        mode = "parts"
        if "kind" in raw:
            ctx.add("sea.kind", "omit kind with [[sea.parts]]: each part has its own kind")
    elif "kind" not in raw:
        ctx.add("sea.kind", f"missing: one of {', '.join(map(repr, SEA_KINDS))}, or [[sea.parts]] for a sum of spectra")
        return None
    elif "kind" not in d:
        return None
    else:
        mode = d["kind"]
    spec = SEA_KIND_KEYS[mode]
    what = "with [[sea.parts]] (spectrum keys go in each part)" if mode == "parts" else f"by kind = {mode!r}"
    for k in raw:
        if k in _SEA_ENTRIES and k not in spec["allowed"]:
            ctx.add(f"sea.{k}", f"not used {what}; its keys: {', '.join(spec['allowed'])}")
    for k in spec["required"]:
        if k not in raw:
            ctx.add(f"sea.{k}", f"missing (needed {what})")
    for group in spec["one_of"]:
        ctx.one_of(raw, "sea.", group, f"for kind = {mode!r}")
    if mode == "parts":
        for i, (pd, praw) in enumerate(zip(d.get("parts", ()), raw.get("parts", ()))):
            ctx.one_of(praw, f"sea.parts[{i}].", ("Tp", "omega_p"), "the peak")
            ctx.one_of(praw, f"sea.parts[{i}].", ("direction_deg", "relative_direction_deg"), "the direction")
    if mode == "none" or ctx.problems.has("sea"):
        return None
    depth = d.get("water_depth")
    h = math.inf if depth is None or isinstance(depth, str) else float(depth)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BoatlandWarning)
        try:
            result = _build_sea(ctx, mode, d, heading, h)
        except SpecError as exc:  # belt and braces: the checks above should have caught it
            for k, m in exc.problems:
                ctx.add(f"sea.{k}" if k else "sea", m)
            return None
    for w in caught:
        if issubclass(w.category, BoatlandWarning):
            ctx.notes.append(f"sea: {w.message}")
        else:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    if result is None:
        return None
    waves, peak, shortest = result
    return Sea(kind=mode, waves=waves, water_depth=None if depth is None else h, peak_period=peak,
               shortest_period=shortest, drift=d.get("drift", "none"))


def _direction(d: Mapping, heading: float) -> float:
    return float(d["direction_deg"]) if "direction_deg" in d else float(heading + d["relative_direction_deg"])


#: The fields of a spectral part a scenario gives as they are (Hs, γ, σ, spreading, ... — those a new shape
#: adds too); Tp and the direction are derived from their alternatives (omega_p, relative_direction_deg).
_PART_FIELDS = tuple(f.name for f in dataclasses.fields(SpectrumPart) if f.name not in ("Tp", "kind", "direction_deg"))


def _part(ctx: Context, d: Mapping, kind: str, prefix: str, heading: float) -> SpectrumPart | None:
    values = {"Tp": d["Tp"] if "Tp" in d else 2 * math.pi / d["omega_p"], "kind": kind,
              "direction_deg": _direction(d, heading), **{k: d[k] for k in _PART_FIELDS if d.get(k) is not None}}
    problems, _ = spectrum_part_problems(values, prefix)
    for key, msg in problems:
        name = key[len(prefix):]
        if name == "Tp" and "omega_p" in d:
            name = "omega_p"
        if name == "direction_deg" and "relative_direction_deg" in d:
            name = "relative_direction_deg"
        ctx.add(prefix + name, msg)
    return None if problems else SpectrumPart(**values)


def _build_sea(ctx: Context, mode: str, d: Mapping, heading: float, h: float):
    """(waves, peak period, shortest significant period), or None after recording problems."""
    if mode == "regular":
        w = RegularWave(H=d["H"], T=d["T"], direction_deg=_direction(d, heading), phase_deg=d.get("phase_deg", 0.0),
                        water_depth=h)
        return w, w.T, w.T
    if mode == "measured":
        return _measured(ctx, d, heading, h)
    if mode == "parts":
        parts = [_part(ctx, p, p["kind"], f"sea.parts[{i}].", heading) for i, p in enumerate(d["parts"])]
    else:
        parts = [_part(ctx, d, mode, "sea.", heading)]
    if any(p is None for p in parts):
        return None
    opts = {k: d[k] for k in ("n_components", "repeat_period", "band_tail", "amplitudes") if k in d}
    s = SeaState(parts=tuple(parts), water_depth=h, **opts)
    shortest = min(2 * math.pi / p.band(2 * SIGNIFICANT_TAIL)[1] for p in s.parts)
    return s, min(p.Tp for p in s.parts), shortest


def _measured(ctx: Context, d: Mapping, heading: float, h: float):
    p = Path(d["file"]).expanduser()
    p = p if p.is_absolute() else ctx.base_dir / p
    if not p.is_file():
        ctx.add("sea.file", f"file not found: {p}")
        return None
    gx, gy = d.get("gauge_position", (0.0, 0.0))
    try:
        rec = MeasuredRecord.from_csv(p, column=d.get("column", 1), time_rtol=d.get("time_rtol", 0.01),
                                      gauge_x=gx, gauge_y=gy, direction_deg=_direction(d, heading),
                                      n_components=d.get("n_keep"), remove_mean=d.get("remove_mean", True),
                                      water_depth=h)
    except BoatlandInputError as exc:
        ctx.add("sea.file", str(exc))
        return None
    c = rec.realise()
    waves = c.omega > 0
    if not np.any(waves):
        ctx.add("sea.file", f"{p}: the record has no waves (constant elevation)")
        return None
    w, var = c.omega[waves], c.a[waves] ** 2
    order = np.argsort(w)
    cum = np.cumsum(var[order]) / np.sum(var)
    w99 = float(w[order][min(np.searchsorted(cum, 1 - SIGNIFICANT_TAIL), w.size - 1)])
    return rec, 2 * math.pi / float(w[np.argmax(var)]), 2 * math.pi / w99


# ---------------------------------------------------------------------------------------- time, initial state
def simulation(ctx: Context, sea_: Sea | None, thr: Thrust | None) -> Simulation | None:
    d = ctx.data.get("simulation", {})
    if "duration" not in d:
        return None
    duration, dt = d["duration"], d.get("dt")
    if dt is not None and dt >= duration:
        ctx.add("simulation.dt", f"{dt:g} s is not smaller than simulation.duration = {duration:g} s")
    elif dt is not None and sea_ is not None and dt > sea_.shortest_period / STEPS_PER_WAVE_PERIOD:
        T = sea_.shortest_period
        ctx.add("simulation.dt", f"{dt:g} s is too large for the waves: their shortest significant period is "
                                 f"{T:.3g} s ({100 * SIGNIFICANT_TAIL:g} % of the wave variance lies above "
                                 f"{2 * math.pi / T:.3g} rad/s); use dt ≤ {T / STEPS_PER_WAVE_PERIOD:.3g} s "
                                 f"(period / {STEPS_PER_WAVE_PERIOD})")
    ramp = d["start_ramp"] if "start_ramp" in d else (sea_.waves.default_ramp_time if sea_ is not None else 0.0)
    if ramp >= duration and sea_ is not None:
        ctx.notes.append(f"simulation.start_ramp = {ramp:g} s is not shorter than the duration {duration:g} s: "
                         "the waves never reach full height")
    if thr is not None and thr.ramp >= duration:
        ctx.notes.append(f"thrust.ramp = {thr.ramp:g} s is not shorter than the duration {duration:g} s: the "
                         "thrust never reaches its full value")
    if sea_ is not None and sea_.kind == "measured" and duration > sea_.waves.length:
        ctx.notes.append(f"the simulation ({duration:g} s) is longer than the wave record ({sea_.waves.length:g} s): "
                         "the replay repeats the record")
    return Simulation(duration=duration, dt=dt, seed=d.get("seed", 0), start_ramp=float(ramp))


def initial(ctx: Context) -> InitialState:
    d = ctx.data.get("initial", {})
    for i, a in enumerate(d.get("rotation_deg", ())):
        if abs(a) > MAX_INITIAL_ROTATION_DEG:
            ctx.add(f"initial.rotation_deg[{i}]", f"{a:g}° is beyond the small angles of linear hydrodynamics "
                                                  f"(at most ±{MAX_INITIAL_ROTATION_DEG:g}°)")
    rot = np.radians(d.get("rotation_deg", (0.0,) * 3))
    omega = np.radians(d.get("angular_velocity_deg", (0.0,) * 3))
    return InitialState(displacement=np.concatenate([d.get("displacement", (0.0,) * 3), rot]),
                        velocity=np.concatenate([d.get("velocity", (0.0,) * 3), omega]))
