"""The scenario file format: every key, its type, bounds, default, unit and doc line — defined once.

:mod:`boatland.scenario.scenario` validates files against :data:`SCENARIO_SCHEMA` (plus the cross-field
rules below, which it enforces with key paths) and :func:`json_schema` exports the same definitions
as a JSON Schema (draft 2020-12) for editors. Units are SI; angles are in degrees in keys ending in
``_deg`` (DESIGN.md §2). The rules that depend on other keys (which wave keys belong to which
``sea.kind``, which fender keys a preset supplies, compact vs explicit landing) are data here, used by
both the loader and the JSON-Schema ``if``/``then`` clauses.
"""

from __future__ import annotations

from typing import Any

from boatland.irf.impulse import TAILS, TAPERS
from boatland.loads.current import CURRENT_TABLE
from boatland.loads.skipper import SKIPPER_TABLE
from boatland.loads.wind import WIND_TABLE
from boatland.sea.spectra import SHAPES
from boatland.tomlspec import Key, Table, TableList, Vector
from boatland.tomlspec import json_schema as _json_schema

__all__ = ["DRIFT_MODES", "DT_MAX", "FENDER_PRESETS", "FENDER_PRESET_ALIASES", "FENDER_REQUIRED", "LANDING_COMPACT", "LANDING_COMPACT_OPTIONAL",
           "SCENARIO_SCHEMA", "SHEAR_STIFFNESS_DEFAULT", "SHEAR_DAMPING_RATIO_DEFAULT",
           "SEA_KINDS", "SEA_KIND_KEYS", "SEA_PART_KINDS", "json_schema"]

#: Largest default time step [s] (the default is min(DT_MAX, Tp/100, T_contact/20)).
DT_MAX = 0.05
#: Default radiation memory T_K [s] (full scale; give ~T_K/√λ at model scale λ).
#: ctv27 (the default vessel): its K(t) rings longer than ctv24's (the waves trapped in its narrower tunnel,
#: 3.12 rad/s) — sway and roll 6 % of their peak over the last 10 % at 75 s, within the check at 120 s, below
#: the π/Δω = 157 s its database resolves (and its landed sway–yaw mode damped by the fit there:
#: scenarios/ctv_landing.toml says how narrowly). ctv24 needs only 40 s.
MEMORY_DEFAULT = 120.0
#: Default thrust ramp [s].
THRUST_RAMP_DEFAULT = 10.0
#: Default incident thresholds: slip 0.1 m (Grøtting 2015 §3.3: "slip defined as 10 cm deviation"),
#: roll 10° (the middle of the 5/10/15° limits of Grøtting 2015 §4.1.2).
SLIP_DISTANCE_DEFAULT = (0.1,)
ROLL_LIMIT_DEFAULT = (10.0,)

#: Fender presets: values a ``preset`` fills in (explicit keys override). Ferreira González (2023),
#: Development of a Numerical Approach for the Simulation of Boatlanding Maneuvers, TU Hamburg,
#: Table 5.4 (model scale, Model 2 in the TUHH tank): friction μ_k 0.7, μ_s 0.9, Stribeck k_v 0.2,
#: δ 1.5, v_ref 0.2 m/s; spring c_f 0.5 kN/m, damper d_f 0.25 kN s/m.
#: The tank fender is a rigid stick there (the thesis gives no shear stiffness for it).
FENDER_PRESETS: dict[str, dict[str, float | str]] = {
    "ferreira-gonzalez-2023-table5.4": {"mu_k": 0.7, "mu_s": 0.9, "k_v": 0.2, "delta": 1.5, "v_ref": 0.2,
                                        "stiffness": 500.0, "damping": 250.0, "shear_stiffness": "rigid"},
}
#: Older preset names, still accepted: alias → preset.
FENDER_PRESET_ALIASES = {"seed001-table5.4": "ferreira-gonzalez-2023-table5.4"}
#: Shear stiffness of a full-scale CTV bow fender per contact [N/m]: 3000 kN/m, Wu (2014) as used by
#: Grøtting (2015, §3.2.2, "Fender modelling") for two 8-inch D fenders; damping 5 % of critical (ibid.).
SHEAR_STIFFNESS_DEFAULT = 3.0e6
SHEAR_DAMPING_RATIO_DEFAULT = 0.05
#: Fender keys that must be given when no preset supplies them.
FENDER_REQUIRED = ("stiffness", "damping", "mu_s", "mu_k")

#: Keys of the compact landing form (two struts generated from the pile); all four are needed.
LANDING_COMPACT = ("bearing_deg", "strut_spacing", "strut_diameter", "standoff")
#: Optional keys of the compact form (the tubes' ends).
LANDING_COMPACT_OPTIONAL = ("strut_bottom", "strut_top")

#: The spectrum shapes of a spectral sea or part (:data:`boatland.sea.spectra.SHAPES`), then the other seas.
SEA_PART_KINDS = tuple(SHAPES)
SEA_KINDS = (*SEA_PART_KINDS, "regular", "measured", "none")
_DIRECTION = ("direction_deg", "relative_direction_deg")


def _spectrum_keys(part: bool) -> dict[str, Any]:
    """The keys of one spectrum (the fields of :class:`boatland.sea.spectra.SpectrumPart` a file gives)."""
    where = "this part" if part else "the sea"
    return {
        "Hs": Key(float, required=part, gt=0.0, doc=f"significant wave height H_m0 of {where} [m]"),
        "Tp": Key(float, gt=0.0, doc="peak period [s] (or omega_p)"),
        "omega_p": Key(float, gt=0.0, doc="peak frequency [rad/s] (or Tp)"),
        "gamma": Key(float, ge=1.0, le=10.0, doc="JONSWAP peak enhancement γ (default 3.3; 1 for pm)"),
        "sigma_a": Key(float, gt=0.0, le=0.5, doc="JONSWAP width below the peak (default 0.07)"),
        "sigma_b": Key(float, gt=0.0, le=0.5, doc="JONSWAP width above the peak (default 0.09)"),
        "spreading": Key(float, gt=0.0, doc="cos-2s spreading exponent s (absent: long-crested)"),
        "sigma_g": Key(float, gt=0.0, doc="width σ of a Gaussian swell [rad/s] (kind 'gaussian')"),
        "direction_deg": Key(float, doc="mean direction the waves travel towards, global frame [deg] "
                                        "(or relative_direction_deg)"),
        "relative_direction_deg": Key(float, doc="direction of travel relative to the vessel's x axis [deg]: "
                                                 "180 = head seas, 0 = following, 90 = towards port"),
    }


#: The keys of a spectral part (one spectrum at [sea], or each [[sea.parts]]).
_SPECTRUM_KEYS = tuple(_spectrum_keys(False))
_SPECTRAL_SEA = ("n_components", "repeat_period", "band_tail", "amplitudes", "drift")
#: How the second-order wave drift loads the vessel (``sea.drift``): none, the mean only, or mean and slowly
#: varying by Newman's approximation (boatland.sea.drift).
DRIFT_MODES = ("none", "mean", "newman")
#: For each ``sea.kind`` (``"parts"`` = a sum of ``[[sea.parts]]``, no kind): the keys allowed at
#: ``[sea]``, the keys required, and the groups of which exactly one is required.
SEA_KIND_KEYS: dict[str, dict[str, tuple]] = {
    **{k: {"allowed": ("kind", *_SPECTRUM_KEYS, *_SPECTRAL_SEA, "water_depth"), "required": ("Hs",),
           "one_of": (("Tp", "omega_p"), _DIRECTION)} for k in SEA_PART_KINDS},
    "regular": {"allowed": ("kind", "H", "T", "phase_deg", *_DIRECTION, "water_depth", "drift"),
                "required": ("H", "T"),
                "one_of": (_DIRECTION,)},
    "measured": {"allowed": ("kind", "file", "column", "time_rtol", "gauge_position", "n_keep", "remove_mean",
                             *_DIRECTION, "water_depth"), "required": ("file",), "one_of": (_DIRECTION,)},
    "none": {"allowed": ("kind", "water_depth"), "required": (), "one_of": ()},
    "parts": {"allowed": ("parts", *_SPECTRAL_SEA, "water_depth"), "required": ("parts",), "one_of": ()},
}
_PART_ONE_OF = (("Tp", "omega_p"), _DIRECTION)
_XYZ = ("x", "y", "z")
_DOF6 = ("surge", "sway", "heave", "roll", "pitch", "yaw")
_PART = Table({"kind": Key(str, default="jonswap", choices=SEA_PART_KINDS,
                           doc="spectrum shape: " + ", ".join(f"'{k}' ({s.label})" for k, s in SHAPES.items())),
               **_spectrum_keys(True)},
              doc="one wave system of a sum (swell, wind sea)",
              json_extra={"allOf": [{"oneOf": [{"required": [a]} for a in g]} for g in _PART_ONE_OF]})


def _sea_json_rules() -> dict[str, Any]:
    every = sorted({k for spec in SEA_KIND_KEYS.values() for k in spec["allowed"]})
    rules = []
    for kind, spec in SEA_KIND_KEYS.items():
        cond = ({"required": ["parts"]} if kind == "parts" else
                {"properties": {"kind": {"const": kind}}, "required": ["kind"]})
        then: dict[str, Any] = {"properties": {k: False for k in every if k not in spec["allowed"]}}
        if spec["required"]:
            then["required"] = list(spec["required"])
        if spec["one_of"]:
            then["allOf"] = [{"oneOf": [{"required": [a]} for a in g]} for g in spec["one_of"]]
        rules.append({"if": cond, "then": then})
    return {"anyOf": [{"required": ["kind"]}, {"required": ["parts"]}], "allOf": rules}


def _fender_json_rules() -> dict[str, Any]:
    return {"if": {"not": {"required": ["preset"]}}, "then": {"required": list(FENDER_REQUIRED)}}


def _landing_json_rules() -> dict[str, Any]:
    return {"oneOf": [{"required": ["struts"],
                       "properties": {k: False for k in LANDING_COMPACT + LANDING_COMPACT_OPTIONAL}},
                      {"required": list(LANDING_COMPACT), "properties": {"struts": False}}]}


#: The scenario file format.
SCENARIO_SCHEMA = Table({
    "name": Key(str, doc="scenario name (default: the file name without .toml)"),
    "description": Key(str, default="", doc="free text"),
    "simulation": Table({
        "duration": Key(float, required=True, gt=0.0, doc="simulated time [s]"),
        "dt": Key(float, gt=0.0, doc=f"RK4 time step [s]; default min({DT_MAX} s, Tp/100 of the shortest "
                                     "peak period, fastest fender contact period/20)"),
        "seed": Key(int, default=0, ge=0, doc="seed of the random wave phases (same seed, same sea)"),
        "start_ramp": Key(float, ge=0.0, doc="half-cosine start-up ramp of the waves [s]; default the "
                                             "sea's: 2 Tp (2 T for regular waves)"),
    }, required=True, doc="time stepping"),
    "vessel": Table({
        "database": Key(str, default="ctv27", doc="built-in hydrodynamic database ('ctv27', 'ctv24', 'model2') or a "
                                                  "path to one (any BEM output boatland reads, or a vessel file "
                                                  "with a [bem] table and mass properties), relative to the "
                                                  "scenario file"),
        "heading_deg": Key(float, doc="global direction of the vessel's x axis (bow) [deg]; default: the "
                                      "bow points at the landing (0 without a landing)"),
        "position": Vector(size=2, names=("x", "y"), doc="global position of the reference point at t = 0 "
                                                           "[m]; default: the fender just touches the struts "
                                                           "(the origin without a landing)"),
        "damping": Table({
            "linear": Vector(size=6, ge=0.0, names=_DOF6, default=(0.0,) * 6,
                             doc="additional linear damping per DOF [N s/m, N m s/rad]"),
            "quadratic": Vector(size=6, ge=0.0, names=_DOF6, default=(0.0,) * 6,
                                doc="additional quadratic damping per DOF [N s²/m², N m s²/rad²]"),
            "roll_critical_fraction": Key(float, default=0.0, ge=0.0, lt=1.0,
                                          doc="extra linear roll damping as a fraction ζ of critical: "
                                              "B44 += 2 ζ sqrt((M44 + A44(ω44)) C44)"),
        }, doc="additional (viscous) damping"),
    }, doc="the vessel and where it starts"),
    "radiation": Table({
        "method": Key(str, default="state_space", choices=("convolution", "state_space"),
                      doc="radiation memory: the fitted state-space system of K(t) (passive; fast), or the "
                          "convolution of K(t) itself"),
        "memory": Key(float, default=MEMORY_DEFAULT, gt=0.0, doc="memory length T_K of K(t) [s]"),
        "tail": Key(str, default="auto", choices=TAILS, doc="how B(ω) continues above the database's band"),
        "taper": Key(str, default="none", choices=TAPERS, doc="time window on K(t)"),
    }, doc="radiation memory (Cummins)"),
    "landing": Table({
        "monopile_diameter": Key(float, required=True, gt=0.0, doc="monopile diameter at the waterline [m]"),
        "monopile_position": Vector(size=2, names=("x", "y"), default=(0.0, 0.0),
                                    doc="global position of the monopile axis [m]"),
        "diffraction": Key(bool, doc="add the pile's scattered wave (MacCamy–Fuchs) to what the vessel feels: "
                                     "its Froude–Krylov force on the hull panels (default: on when the "
                                     "database has a hull mesh)"),
        "bearing_deg": Key(float, doc="compact form: global direction from the pile axis to the landing "
                                      "(the side it faces) [deg]"),
        "strut_spacing": Key(float, gt=0.0, doc="compact form: distance between the two strut axes [m]"),
        "strut_diameter": Key(float, gt=0.0, doc="compact form: strut (tube) diameter [m]"),
        "standoff": Key(float, gt=0.0, doc="compact form: distance from the pile surface to the strut axes, "
                                           "along bearing_deg [m]"),
        "strut_bottom": Key(float, doc="compact form: lower end of the tubes, global z [m] (default: unbounded)"),
        "strut_top": Key(float, doc="compact form: upper end of the tubes, global z [m] (default: unbounded)"),
        "struts": TableList(Table({
            "position": Vector(size=2, names=("x", "y"), required=True, doc="global position of the strut axis [m]"),
            "diameter": Key(float, required=True, gt=0.0, doc="strut diameter [m]"),
            "normal_deg": Key(float, required=True, doc="horizontal direction from the landing towards the "
                                                        "vessel at this strut, global [deg]"),
            "bottom": Key(float, doc="lower end of the tube, global z [m] (default: unbounded)"),
            "top": Key(float, doc="upper end of the tube, global z [m] (default: unbounded)"),
        }, doc="one vertical strut (tube) of the boat landing"), min_size=1,
            doc="explicit form: the struts; struts[i] meets fender.points[i]"),
    }, optional=True, json_extra=_landing_json_rules(),
        doc="the boat landing on the monopile: compact (bearing_deg, strut_spacing, strut_diameter, "
            "standoff) or explicit [[landing.struts]]"),
    "fender": Table({
        "preset": Key(str, choices=(*FENDER_PRESETS, *FENDER_PRESET_ALIASES),
                      doc="fill the values of a published set (explicit keys override); "
                          "'ferreira-gonzalez-2023-table5.4' = Ferreira González (2023) Table 5.4, the TUHH tank "
                          "fender of Model 2 (older name: 'seed001-table5.4')"),
        "points": Vector(row=3, min_size=1, names=_XYZ, required=True,
                         doc="contact points in the body frame [m], one per strut (points[i] meets struts[i])"),
        "stiffness": Key(float, gt=0.0, doc="normal spring c_f per contact [N/m]"),
        "damping": Key(float, ge=0.0, doc="normal damper d_f per contact [N s/m]"),
        "shear_stiffness": Key((float, str), gt=0.0, choices=("rigid",),
                               doc="shear stiffness k_t of the rubber per contact, vertically and along the "
                                   f"tube [N/m], or \"rigid\" (a rigid stick); default {SHEAR_STIFFNESS_DEFAULT:g} "
                                   "(Wu 2014, as used by Grøtting 2015)"),
        "shear_damping": Key(float, ge=0.0, doc="shear damping c_t per contact [N s/m] (default: "
                                                "shear_damping_ratio of critical)"),
        "shear_damping_ratio": Key(float, ge=0.0, lt=1.0,
                                   doc="shear damping as a fraction ζ of critical, c_t = 2 ζ √(k_t m_eff) with "
                                       "m_eff the vessel's effective mass at the contact, vertically; default "
                                       f"{SHEAR_DAMPING_RATIO_DEFAULT:g} (Grøtting 2015)"),
        "width": Key(float, ge=0.0, doc="length of the fender line at each contact, along the body y axis [m] "
                                        "(default 0: a point); a tube beyond its end is off the landing"),
        "mu_s": Key(float, gt=0.0, le=2.0, doc="static friction coefficient μ_s"),
        "mu_k": Key(float, gt=0.0, le=2.0, doc="kinetic friction coefficient μ_k (≤ μ_s)"),
        "k_v": Key(float, ge=0.0, doc="Stribeck viscous constant k_v [s/m] (default 0)"),
        "v_ref": Key(float, gt=0.0, doc="Stribeck reference velocity v_ref [m/s] (default 0.2)"),
        "delta": Key(float, gt=0.0, doc="Stribeck exponent δ (default 1.5; Ferreira González 2023: 0.5–2)"),
        "sideways": Key(bool, default=True, doc="friction also horizontally along the contact plane"),
    }, optional=True, json_extra=_fender_json_rules(),
        doc="bow fender contact (absent: free floating); "
            "μ(v) = μ_k + (μ_s − μ_k) exp(−(|v|/v_ref)^δ) + k_v |v|"),
    "thrust": Table({
        "force": Key(float, required=True, gt=0.0, doc="bollard push [N] (the nominal push when a controller acts)"),
        "position": Vector(size=3, names=_XYZ, required=True, doc="propulsor position, body frame [m]"),
        "ramp": Key(float, default=THRUST_RAMP_DEFAULT, ge=0.0, doc="ramp-in time [s] (also of the current and "
                                                                    "the wind)"),
        "direction_deg": Key((float, str), default="trim", ge=-60.0, le=60.0, choices=("trim",),
                             doc="direction of the push in the vessel's horizontal plane, from its x axis towards "
                                 "port [deg], or \"trim\" (default): the angle whose side force balances the steady "
                                 "yaw moment of current, wind and drift about the fender — the skipper steering the "
                                 "jets to hold the bow (0 without them)"),
        "control": SKIPPER_TABLE,
    }, optional=True, doc="propeller thrust pushing the fender on (absent: no thrust)"),
    "sea": Table({
        "kind": Key(str, choices=SEA_KINDS, doc=", ".join(f"'{k}' ({s.label})" for k, s in SHAPES.items())
                    + ", 'regular', 'measured' or 'none' (calm); omit it with [[sea.parts]]"),
        **_spectrum_keys(False),
        "n_components": Key(int, ge=1, doc="minimum wave components per spectral part (default 256)"),
        "repeat_period": Key(float, gt=0.0, doc="shortest record the components do not repeat within [s] "
                                                "(default 600): the seed, the spectrum and the component keys fix "
                                                "the sea, so every run up to this long is the start of the same "
                                                "sea; a longer run draws more components (another sea)"),
        "band_tail": Key(float, gt=0.0, le=0.1, doc="variance fraction left outside each part's band "
                                                    "(default 0.002)"),
        "amplitudes": Key(str, choices=("deterministic", "rayleigh"), doc="component amplitudes "
                                                                          "(default deterministic)"),
        "H": Key(float, gt=0.0, doc="regular: wave height, crest to trough [m]"),
        "T": Key(float, gt=0.0, doc="regular: wave period [s]"),
        "phase_deg": Key(float, doc="regular: phase at the global origin [deg] (0: crest at t = 0)"),
        "file": Key(str, doc="measured: CSV of time [s], elevation [m], relative to the scenario file"),
        "column": Key(int, ge=1, doc="measured: 0-based column of the elevation (default 1)"),
        "time_rtol": Key(float, gt=0.0, doc="measured: allowed relative deviation of a time step (default 0.01)"),
        "gauge_position": Vector(size=2, names=("x", "y"), doc="measured: global gauge position [m] (default origin)"),
        "n_keep": Key(int, ge=1, doc="measured: keep the N largest components (Ferreira González 2023: 20; default all)"),
        "remove_mean": Key(bool, doc="measured: drop the record's mean (default true)"),
        "water_depth": Key((float, str), gt=0.0, choices=("inf",),
                           doc="site water depth [m] or \"inf\"; default the database's"),
        "parts": TableList(_PART, min_size=1, doc="a sum of spectra (swell + wind sea), each with its own "
                                                  "direction"),
        "drift": Key(str, choices=DRIFT_MODES, doc="second-order wave drift: 'none' (default), 'mean', or 'newman' "
                                                   "(mean and slowly varying, Newman's approximation); needs the "
                                                   "database's mean drift coefficients"),
    }, optional=True, json_extra=_sea_json_rules(), doc="waves (absent: calm water)"),
    "current": CURRENT_TABLE,
    "wind": WIND_TABLE,
    "initial": Table({
        "displacement": Vector(size=3, names=("surge", "sway", "heave"), default=(0.0,) * 3,
                               doc="initial translation [m]"),
        "rotation_deg": Vector(size=3, names=("roll", "pitch", "yaw"), default=(0.0,) * 3,
                               doc="initial rotation [deg]"),
        "velocity": Vector(size=3, names=("surge", "sway", "heave"), default=(0.0,) * 3,
                           doc="initial velocity [m/s]"),
        "angular_velocity_deg": Vector(size=3, names=("roll", "pitch", "yaw"), default=(0.0,) * 3,
                                       doc="initial angular velocity [deg/s]"),
    }, doc="initial state relative to the start pose (free decay)"),
    "incidents": Table({
        "slip_distance": Vector(min_size=1, scalar=True, gt=0.0, default=SLIP_DISTANCE_DEFAULT,
                                doc="slip distance thresholds [m] (one or several)"),
        "roll_limit_deg": Vector(min_size=1, scalar=True, gt=0.0, lt=90.0, default=ROLL_LIMIT_DEFAULT,
                                 doc="roll angle limits [deg] (one or several)"),
        "contact_loss_duration": Vector(min_size=1, scalar=True, gt=0.0,
                                        doc="a contact lost for longer than this [s] (one or several; absent: none)"),
        "slide_within": TableList(Table({
            "distance": Key(float, required=True, gt=0.0, doc="[m] path the fender slides over the tube"),
            "window": Key(float, required=True, gt=0.0, doc="[s] within any window of this length"),
        }), doc="slides of more than `distance` within `window` seconds, e.g. [{distance = 0.5, window = 120.0}] "
                "(one operator's criterion; absent: none)"),
    }, doc="incident definitions reported by a trial"),
    "output": Table({
        "file": Key(str, doc="time series file to write (HDF5), relative to the working directory"),
        "log": Key(str, doc="run log (MCAP) to write, relative to the working directory"),
        "decimate": Key(int, default=1, ge=1, doc="keep every n-th step in the outputs"),
    }, doc="what to write"),
}, doc="a boatland scenario: one landing trial (or free-floating run)")


def json_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of scenario files, for editors (``boatland scenario schema``).

    Generated from :data:`SCENARIO_SCHEMA` and the rule tables of this module; physical checks
    (dt against the fender and the waves, geometry) need code and stay in the loader.
    """
    return _json_schema(SCENARIO_SCHEMA, title="boatland scenario",
                        description="A boatland scenario file (TOML): a CTV pushing its bow fender on a "
                                    "boat landing in waves. SI units; angles in keys ending in _deg.")
