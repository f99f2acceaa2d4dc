r"""The vessel file: a catamaran CTV described by a few particulars, validated and immutable.

A vessel file (TOML, SI units, angles in ``_deg`` keys) says everything the Capytaine builder
(:mod:`boatland.hydro.build`) needs to make a hydrodynamic database::

    name = "ctv24"

    [hull]                     # two generalized Wigley demihulls (boatland.vessel.wigley)
    length = 24.0              # L, waterline length of a demihull [m]
    demihull_beam = 2.8        # b, waterline beam of one demihull [m]
    draft = 1.4                # T [m]
    separation = 6.2           # s, demihull centreline to centreline [m]
    # block_coefficient = 0.47 # C_b of a demihull; only when [inertia].mass is not given

    [inertia]
    mass = 90000.0             # [kg]; sets C_b = mass / (2 ρ L b T)
    lcg = 0.0                  # centre of gravity forward of midship [m]
    kg = 2.7                   # centre of gravity above the keel [m]
    r_xx = 3.4                 # radii of gyration about the CoG [m] ...
    r_yy = 6.5                 # ... or i_xx, i_yy, i_zz [kg m²]; one of each pair
    # r_zz missing → I_zz = I_xx + I_yy (noted)

    [environment]
    rho = 1025.0               # [kg/m³]
    g = 9.81                   # [m/s²]
    water_depth = "inf"        # "inf" or a depth [m]

    [mesh]
    panel_size = 0.45          # largest panel edge [m] (default: λ(ω_max) / 8) ...
    # n_length = 60            # ... or panels along a demihull, keel-to-waterline, across the lid
    # n_girth = 6
    # n_lid = 6
    lid = true                 # irregular-frequency removal lid

    [frequencies]
    omega_min = 0.04           # [rad/s]
    omega_max = 4.0
    d_omega = 0.04             # or n = 100

    [directions]
    step_deg = 15.0            # solve 0..180°, mirror to 195..345° (port/starboard symmetry)

A CTV hull with a transom stern (:mod:`boatland.vessel.ctv_hull`) is chosen with ``form = "ctv"``::

    [hull]
    form = "ctv"               # "wigley" (default) or "ctv"
    length = 25.5              # waterline length, transom to stem [m]
    demihull_beam = 2.7        # widest waterline beam of a demihull [m]
    draft = 1.71               # at the keel [m]
    separation = 5.87
    section = "chine"          # or "round" (round bilge)
    deadrise_deg = 26.0        # ... and the other form parameters of CTVCatamaran (defaults there)

    [topsides]                 # above the waterline: drawn by the viewers, not in the BEM
    freeboard = 2.4            # deck above the waterline [m]
    tunnel_height = 1.6        # wet deck above the waterline [m]
    flare_deg = 5.0
    stem_rake_deg = 20.0
    deckhouse = [-9.0, 1.0, 6.0, 2.6]   # x_aft, x_fwd, width, height [m]

Its mass is ρ∇ of its lines unless ``inertia.mass`` is given, which must then match ρ∇ within 1 %
(:data:`MASS_TOLERANCE`); ``inertia.lcg`` defaults to the centre of buoyancy (even keel).

Reference point (body origin): midship, centreline, calm waterline; x forward, y to port, z up.
(Midship is halfway between the transom and the waterline stem for the CTV form.)

:func:`load_vessel` reports every problem of a file at once with its key path
(:mod:`boatland.tomlspec`); constructing :class:`VesselSpec` directly runs the same checks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

import numpy as np

from boatland.vessel.ctv_hull import SECTIONS, CTVCatamaran, CTVPanelCounts, ctv_form_problems
from boatland.vessel.wigley import CB_RANGE, PanelCounts, WigleyCatamaran, exponent_for_block_coefficient
from boatland.vessel.database import rigid_body_mass_matrix
from boatland.vessel.imported import ImportedVesselSpec, load_imported
from boatland.tomlspec import Key, Problems, SpecError, Table, Vector, parse_toml_file, validate

__all__ = ["FORMS", "MASS_TOLERANCE", "VESSEL_SCHEMA", "VesselSpec", "load_vessel", "vessel_problems", "wavelength"]

#: Default mesh resolution: largest panel edge = shortest wavelength / this.
DEFAULT_PANELS_PER_WAVELENGTH = 8.0
#: Coarser than this many panels per shortest wavelength is rejected (results would be noise).
MIN_PANELS_PER_WAVELENGTH = 4.0
#: Classic Wigley block coefficient (p = 2), used when neither mass nor C_b is given.
WIGLEY_CB = 4.0 / 9.0
MAX_FREQUENCIES = 2000
#: Hull forms of the vessel file.
FORMS = ("wigley", "ctv")
#: A given mass of a CTV-form hull must equal ρ∇ of its lines within this fraction.
MASS_TOLERANCE = 0.01
#: Form parameters of the CTV hull: VesselSpec field → vessel-file key.
CTV_HULL_KEYS = {n: f"hull.{n}" for n in (
    "section", "deadrise_deg", "bow_deadrise_deg", "chine_beam", "bilge_exponent", "transom_beam",
    "transom_draft", "max_beam_station", "keel_station", "forefoot_station", "entrance_deg")}
CTV_TOPSIDE_KEYS = {n: f"topsides.{n}" for n in (
    "freeboard", "tunnel_height", "flare_deg", "stem_rake_deg", "deckhouse")}
CTV_KEYS = {**CTV_HULL_KEYS, **CTV_TOPSIDE_KEYS}


def _water_depth(v):
    if isinstance(v, str):
        if v.strip().lower() in ("inf", "infinite", "deep"):
            return None
        return f"must be a depth in m or \"inf\", got {v!r}"
    return None if v > 0 else f"must be > 0 or \"inf\", got {v:g}"


#: The vessel file format. Keys map to :class:`VesselSpec` fields by :data:`FIELD_KEYS`.
VESSEL_SCHEMA = Table({
    "name": Key(str, required=True, doc="vessel name"),
    "description": Key(str, default="", doc="free text"),
    "hull": Table({
        "form": Key(str, default="wigley", choices=FORMS,
                    doc="hull form: two generalized Wigley demihulls, or CTV demihulls with a transom"),
        "length": Key(float, required=True, gt=0.0, doc="waterline length L of a demihull [m]"),
        "demihull_beam": Key(float, required=True, gt=0.0, doc="waterline beam b of one demihull [m]"),
        "draft": Key(float, required=True, gt=0.0, doc="draft T [m]"),
        "separation": Key(float, required=True, gt=0.0, doc="demihull centreline to centreline [m]"),
        "block_coefficient": Key(float, gt=0.0, lt=1.0, doc="block coefficient of a demihull (Wigley form, "
                                                           "without inertia.mass)"),
        "section": Key(str, choices=SECTIONS, doc="CTV form: hard-chine or round-bilge sections"),
        "deadrise_deg": Key(float, doc="CTV form: deadrise amidships and aft [deg]"),
        "bow_deadrise_deg": Key(float, doc="CTV form: deadrise at the stem [deg]"),
        "chine_beam": Key(float, doc="CTV form: chine half-breadth / waterline half-breadth"),
        "bilge_exponent": Key(float, doc="CTV form: superellipse exponent of round-bilge sections"),
        "transom_beam": Key(float, doc="CTV form: transom waterline breadth / demihull beam"),
        "transom_draft": Key(float, doc="CTV form: transom immersion / draft"),
        "max_beam_station": Key(float, doc="CTV form: widest waterline, fraction of L from the transom"),
        "keel_station": Key(float, doc="CTV form: keel at full draft from here, fraction of L from the transom"),
        "forefoot_station": Key(float, doc="CTV form: forefoot rises from here, fraction of L from the transom"),
        "entrance_deg": Key(float, doc="CTV form: half-angle of entrance of the waterline [deg]"),
    }, required=True),
    "topsides": Table({
        "freeboard": Key(float, doc="deck above the waterline [m]"),
        "tunnel_height": Key(float, doc="wet deck (tunnel roof) above the waterline [m]"),
        "flare_deg": Key(float, doc="outward flare of the topsides [deg]"),
        "stem_rake_deg": Key(float, doc="forward rake of the stem above the waterline [deg]"),
        "deckhouse": Vector(size=4, names=("x_aft", "x_fwd", "width", "height"),
                            doc="deckhouse box on the deck [m] (width 0: none)"),
    }, optional=True, doc="CTV form: the hull above the waterline, for the viewers (not in the BEM)"),
    "inertia": Table({
        "mass": Key(float, gt=0.0, doc="vessel mass [kg]"),
        "lcg": Key(float, doc="centre of gravity forward of midship [m]; default: above the centre of buoyancy"),
        "kg": Key(float, required=True, ge=0.0, doc="centre of gravity above the keel [m]"),
        **{f"r_{ax}": Key(float, gt=0.0, doc=f"radius of gyration about the CoG, {ax} [m]") for ax in ("xx", "yy", "zz")},
        **{f"i_{ax}": Key(float, gt=0.0, doc=f"moment of inertia about the CoG, {ax} [kg m²]") for ax in ("xx", "yy", "zz")},
    }, required=True),
    "environment": Table({
        "rho": Key(float, default=1025.0, doc="water density [kg/m³]"),
        "g": Key(float, default=9.81, doc="gravity [m/s²]"),
        "water_depth": Key((float, str), default="inf", check=_water_depth, doc="\"inf\" or depth [m]"),
    }),
    "mesh": Table({
        "panel_size": Key(float, gt=0.0, doc="largest panel edge [m]"),
        "n_length": Key(int, ge=4, doc="panels along a demihull (even)"),
        "n_girth": Key(int, ge=2, doc="panels keel to waterline, one side"),
        "n_lid": Key(int, ge=1, doc="lid panels across a demihull"),
        "lid": Key(bool, default=True, doc="irregular-frequency removal lid"),
    }),
    "frequencies": Table({
        "omega_min": Key(float, required=True, gt=0.0, doc="lowest frequency [rad/s]"),
        "omega_max": Key(float, required=True, gt=0.0, doc="highest frequency [rad/s]"),
        "n": Key(int, ge=2, le=MAX_FREQUENCIES, doc="number of frequencies (or d_omega)"),
        "d_omega": Key(float, gt=0.0, doc="frequency step [rad/s] (or n)"),
    }, required=True),
    "directions": Table({
        "step_deg": Key(float, default=15.0, gt=0.0, le=180.0, doc="direction step [deg], divides 180"),
    }),
})

#: VesselSpec field → key path in the vessel file.
FIELD_KEYS = {
    "name": "name", "description": "description",
    "length": "hull.length", "demihull_beam": "hull.demihull_beam", "draft": "hull.draft",
    "separation": "hull.separation", "block_coefficient": "hull.block_coefficient",
    "mass": "inertia.mass", "lcg": "inertia.lcg", "kg": "inertia.kg",
    "r_xx": "inertia.r_xx", "r_yy": "inertia.r_yy", "r_zz": "inertia.r_zz",
    "i_xx": "inertia.i_xx", "i_yy": "inertia.i_yy", "i_zz": "inertia.i_zz",
    "rho": "environment.rho", "g": "environment.g", "water_depth": "environment.water_depth",
    "panel_size": "mesh.panel_size", "n_length": "mesh.n_length", "n_girth": "mesh.n_girth",
    "n_lid": "mesh.n_lid", "lid": "mesh.lid",
    "omega_min": "frequencies.omega_min", "omega_max": "frequencies.omega_max",
    "n_omega": "frequencies.n", "d_omega": "frequencies.d_omega",
    "direction_step_deg": "directions.step_deg", "form": "hull.form",
    **CTV_KEYS,
}


def wavelength(omega: float, g: float, water_depth: float = math.inf) -> float:
    """Linear wavelength [m] at ω from the dispersion relation ω² = g k tanh(k h)."""
    k = omega ** 2 / g
    if math.isfinite(water_depth):
        for _ in range(100):  # Newton on f(k) = g k tanh(kh) − ω²
            th = math.tanh(k * water_depth)
            f = g * k * th - omega ** 2
            df = g * th + g * k * water_depth * (1.0 - th ** 2)
            step = f / df
            k -= step
            if abs(step) < 1e-14 * k:
                break
    return 2.0 * math.pi / k


@dataclass(frozen=True)
class VesselSpec:
    """A catamaran CTV as the vessel file gives it (inputs), with the derived quantities.

    Inputs mirror the vessel file (see the module docstring; units SI). ``None`` means "not given".
    After validation the derived attributes are set:

    Attributes
    ----------
    total_mass : float
        Vessel mass [kg] (given, or ρ × the hull's displaced volume).
    cb : float
        Block coefficient of a demihull (Wigley: from the mass, given, or 4/9; CTV: of its lines).
    lcg_resolved : float
        Centre of gravity forward of midship [m] (given, or the centre of buoyancy's).
    inertia_cog : ndarray, shape (3,)
        Principal moments of inertia about the CoG, I_xx, I_yy, I_zz [kg m²].
    notes : tuple of str
        Assumptions made while resolving the inputs (they go into the database provenance).
    """

    name: str
    length: float
    demihull_beam: float
    draft: float
    separation: float
    kg: float
    omega_min: float
    omega_max: float
    description: str = ""
    block_coefficient: float | None = None
    mass: float | None = None
    lcg: float | None = None
    r_xx: float | None = None
    r_yy: float | None = None
    r_zz: float | None = None
    i_xx: float | None = None
    i_yy: float | None = None
    i_zz: float | None = None
    rho: float = 1025.0
    g: float = 9.81
    water_depth: float = math.inf
    panel_size: float | None = None
    n_length: int | None = None
    n_girth: int | None = None
    n_lid: int | None = None
    lid: bool = True
    n_omega: int | None = None
    d_omega: float | None = None
    direction_step_deg: float = 15.0
    form: str = "wigley"
    section: str | None = None
    deadrise_deg: float | None = None
    bow_deadrise_deg: float | None = None
    chine_beam: float | None = None
    bilge_exponent: float | None = None
    transom_beam: float | None = None
    transom_draft: float | None = None
    max_beam_station: float | None = None
    keel_station: float | None = None
    forefoot_station: float | None = None
    entrance_deg: float | None = None
    freeboard: float | None = None
    tunnel_height: float | None = None
    flare_deg: float | None = None
    stem_rake_deg: float | None = None
    deckhouse: tuple | None = None
    source: str = ""

    total_mass: float = field(init=False, repr=False)
    cb: float = field(init=False, repr=False)
    lcg_resolved: float = field(init=False, repr=False)
    inertia_cog: np.ndarray = field(init=False, repr=False)
    notes: tuple[str, ...] = field(init=False, repr=False)

    def __post_init__(self):
        values = {f.name: getattr(self, f.name) for f in fields(self) if f.init}
        problems = vessel_problems(values)
        if problems:
            raise SpecError(self.source or f"vessel {self.name!r}", problems)
        cb, mass, inertia, notes = _resolve(values)
        object.__setattr__(self, "water_depth", float(self.water_depth))
        object.__setattr__(self, "total_mass", mass)
        object.__setattr__(self, "cb", cb)
        if self.lcg is None:
            lcg = float(_make_hull(values, cb).centre_of_buoyancy[0])
            if self.form == "ctv":
                notes.append(f"lcg not given: {lcg:+.4g} m, above the centre of buoyancy (the vessel floats on "
                             "even keel)")
        else:
            lcg = float(self.lcg)
        object.__setattr__(self, "lcg_resolved", lcg)
        inertia = np.array(inertia, dtype=float)
        inertia.setflags(write=False)
        object.__setattr__(self, "inertia_cog", inertia)
        object.__setattr__(self, "notes", tuple(notes))

    # ------------------------------------------------------------------ derived
    @property
    def hull(self) -> WigleyCatamaran | CTVCatamaran:
        """The hull form: generalized Wigley demihulls with this spec's block coefficient, or the CTV
        demihulls of :mod:`boatland.vessel.ctv_hull` with this spec's form parameters."""
        return _make_hull({f.name: getattr(self, f.name) for f in fields(self) if f.init}, self.cb)

    @property
    def cog(self) -> np.ndarray:
        """Centre of gravity in the body frame (origin midship, centreline, waterline) [m]."""
        return np.array([self.lcg_resolved, 0.0, self.kg - self.draft])

    @property
    def radii_of_gyration(self) -> np.ndarray:
        """Radii of gyration about the CoG, sqrt(I/m) [m]."""
        return np.sqrt(self.inertia_cog / self.total_mass)

    def mass_matrix(self) -> np.ndarray:
        """Rigid-body mass matrix about the reference point (origin), 6×6."""
        return rigid_body_mass_matrix(self.total_mass, self.cog, self.inertia_cog, np.zeros(3))

    @property
    def omega(self) -> np.ndarray:
        """The wave frequencies to solve [rad/s], uniformly spaced."""
        return _omegas(self.omega_min, self.omega_max, self.n_omega, self.d_omega)

    @property
    def solved_directions_deg(self) -> np.ndarray:
        """Directions solved by the BEM, 0..180° [deg]."""
        n = int(round(180.0 / self.direction_step_deg))
        return np.linspace(0.0, 180.0, n + 1)

    @property
    def wave_dir_deg(self) -> np.ndarray:
        """All directions of the database, 0..360° − step [deg] (195..345° by mirror symmetry)."""
        n = int(round(180.0 / self.direction_step_deg))
        return np.linspace(0.0, 360.0, 2 * n + 1)[:-1]

    @property
    def shortest_wavelength(self) -> float:
        """Wavelength at ω_max [m] (finite-depth dispersion when the depth is finite)."""
        return wavelength(self.omega_max, self.g, self.water_depth)

    def panel_counts(self) -> PanelCounts | CTVPanelCounts:
        """Panel counts (Wigley: quarter mesh; CTV: half mesh) from ``panel_size`` or the explicit counts
        (default: λ_min / 8)."""
        return _panel_counts(self.hull, self.shortest_wavelength, self.panel_size, self.n_length,
                             self.n_girth, self.n_lid)

    def panels_per_wavelength(self) -> float:
        """Shortest wavelength over the largest panel edge of the mesh."""
        return self.shortest_wavelength / self.hull.max_panel_size(self.panel_counts())

    def replace(self, **changes: Any) -> "VesselSpec":
        """A new spec with some inputs changed (validated again)."""
        values = {f.name: getattr(self, f.name) for f in fields(self) if f.init}
        values.update(changes)
        return VesselSpec(**values)


def _omegas(omega_min, omega_max, n, d_omega) -> np.ndarray:
    if n is not None:
        return np.linspace(omega_min, omega_max, int(n))
    k = int(math.floor((omega_max - omega_min) / d_omega + 1e-9))
    return omega_min + d_omega * np.arange(k + 1)


def _ctv_params(v: dict) -> dict[str, Any]:
    """The CTV form parameters given in ``v`` (the others take CTVCatamaran's defaults)."""
    out = {k: v[k] for k in CTV_KEYS if v.get(k) is not None}
    if "deckhouse" in out:
        out["deckhouse"] = tuple(out["deckhouse"])
    return out


def _make_hull(v: dict, cb: float | None = None) -> WigleyCatamaran | CTVCatamaran:
    """The hull of inputs ``v`` (``cb``: the Wigley form's block coefficient)."""
    if v.get("form", "wigley") == "ctv":
        return CTVCatamaran(v["length"], v["demihull_beam"], v["draft"], v["separation"], **_ctv_params(v))
    return WigleyCatamaran.from_block_coefficient(v["length"], v["demihull_beam"], v["draft"], v["separation"], cb)


def _resolve(v: dict) -> tuple[float, float, tuple[float, float, float], list[str]]:
    """Block coefficient, mass, inertias and notes from validated inputs."""
    notes: list[str] = []
    L, b, T, rho = v["length"], v["demihull_beam"], v["draft"], v["rho"]
    if v.get("form", "wigley") == "ctv":
        hs = _make_hull(v).hydrostatics()
        cb, mass = hs.block_coefficient, rho * hs.volume
        if v.get("mass") is not None:
            notes.append(f"mass {v['mass']:.6g} kg given; ρ∇ of the lines = {mass:.6g} kg "
                         f"({(v['mass'] - mass) / mass:+.2%})")
            mass = float(v["mass"])
        else:
            notes.append(f"mass = ρ∇ of the lines = {mass:.6g} kg (∇ = {hs.volume:.5g} m³, C_b = {cb:.4f}, "
                         f"C_m = {hs.midship_coefficient:.4f})")
    elif v.get("mass") is not None:
        mass = float(v["mass"])
        cb = mass / (rho * 2.0 * L * b * T)
        notes.append(f"block coefficient C_b = {cb:.4f} of each demihull from the mass "
                     f"(m = ρ 2 C_b L b T), generalized Wigley exponent p = {exponent_for_block_coefficient(cb):.3f}")
    else:
        cb = v["block_coefficient"] if v.get("block_coefficient") is not None else WIGLEY_CB
        mass = rho * 2.0 * cb * L * b * T
        src = "given" if v.get("block_coefficient") is not None else "classic Wigley value 4/9 (no mass given)"
        notes.append(f"block coefficient C_b = {cb:.4f} ({src}); mass = ρ × displaced volume = {mass:.6g} kg")
    inertia = []
    for ax in ("xx", "yy", "zz"):
        r, i = v.get(f"r_{ax}"), v.get(f"i_{ax}")
        inertia.append(float(i) if i is not None else (mass * r * r if r is not None else math.nan))
    if math.isnan(inertia[2]):
        inertia[2] = inertia[0] + inertia[1]
        notes.append(f"I_zz not given: estimated as I_xx + I_yy = {inertia[2]:.6g} kg m² "
                     "(the largest value the triangle inequality of principal moments allows; exact for a flat "
                     "mass distribution, an overestimate for a ship)")
    return cb, mass, (inertia[0], inertia[1], inertia[2]), notes


def vessel_problems(v: dict[str, Any], rejected: frozenset[str] | set[str] = frozenset()) -> list[tuple[str, str]]:
    """All physical and consistency problems of the vessel inputs ``v`` (VesselSpec field names).

    ``rejected`` names fields whose value the file gave but the schema already rejected: checks
    that involve them are skipped (no second, misleading message). Returns ``(key_path, message)``
    pairs with the vessel-file key paths of :data:`FIELD_KEYS`.
    """
    v = {k: (None if k in rejected else x) for k, x in v.items()}
    out: list[tuple[str, str]] = []

    def add(name, msg):
        out.append((FIELD_KEYS.get(name, name), msg))

    def has(*names):
        return all(v.get(n) is not None for n in names)

    def num(name):
        x = v.get(name)
        return None if x is None else float(x)

    # --- single values (the TOML schema checks these too; repeated for direct construction)
    for name in ("length", "demihull_beam", "draft", "separation", "mass", "r_xx", "r_yy", "r_zz",
                 "i_xx", "i_yy", "i_zz", "panel_size", "omega_min", "omega_max", "d_omega", "water_depth"):
        x = v.get(name)
        if x is not None and not (isinstance(x, (int, float)) and x > 0 and (math.isfinite(x) or name == "water_depth")):
            add(name, f"must be > 0, got {x!r}")
            v = {**v, name: None}
    for name in ("lcg", "kg"):
        x = v.get(name)
        if x is not None and not (isinstance(x, (int, float)) and math.isfinite(x)):
            add(name, f"must be a finite number, got {x!r}")
            v = {**v, name: None}
    if has("kg") and v["kg"] < 0:
        add("kg", f"must be ≥ 0 (height of the centre of gravity above the keel), got {v['kg']:g}")
    rho, g = num("rho"), num("g")
    if rho is not None and not 900.0 <= rho <= 1100.0:
        add("rho", f"must be a water density in kg/m³ (fresh 1000, sea 1025), got {rho:g}")
        rho = None
    if g is not None and not 9.7 <= g <= 9.9:
        add("g", f"must be the Earth's gravity in m/s² (9.78–9.83), got {g:g}")

    # --- hull
    if has("separation", "demihull_beam") and v["separation"] <= v["demihull_beam"]:
        add("separation", f"{v['separation']:g} m is not more than hull.demihull_beam = {v['demihull_beam']:g} m: "
                          "the demihulls would overlap (separation is centreline to centreline)")
    if has("length", "demihull_beam") and v["demihull_beam"] >= v["length"] / 2:
        add("demihull_beam", f"{v['demihull_beam']:g} m is not slender (length {v['length']:g} m): "
                             "a demihull needs beam < length / 2")
    form = v.get("form") or "wigley"
    if form not in FORMS:
        add("form", f"must be one of {', '.join(FORMS)}, got {form!r}")
        form = None
    if form == "wigley":
        for name in CTV_KEYS:
            if v.get(name) is not None:
                add(name, 'only for hull.form = "ctv" (the Wigley form has no such parameter)')
    elif form == "ctv":
        if has("block_coefficient"):
            add("block_coefficient", 'only for hull.form = "wigley": the lines of the CTV form set its '
                                     "block coefficient (give inertia.mass, or nothing: ρ∇)")
        # (length, beams and separation are checked below for both forms)
        for name, msg in ctv_form_problems({k: v.get(k) for k in ("length", "demihull_beam", "draft",
                                                                   "separation", *CTV_KEYS)}):
            if name in CTV_KEYS:
                add(name, msg)
    if form == "wigley" and has("mass", "block_coefficient"):
        add("block_coefficient", "give either inertia.mass or hull.block_coefficient, not both "
                                 "(the mass sets the block coefficient)")
    elif form == "wigley" and has("length", "demihull_beam", "draft") and rho is not None:
        L, b, T = v["length"], v["demihull_beam"], v["draft"]
        if has("mass"):
            cb, name = v["mass"] / (rho * 2 * L * b * T), "mass"
            what = (f"{v['mass']:g} kg needs a demihull block coefficient C_b = m / (2 ρ L b T) = {cb:.3f}")
        elif has("block_coefficient"):
            cb, name, what = v["block_coefficient"], "block_coefficient", f"C_b = {v['block_coefficient']:g}"
        else:
            cb, name, what = WIGLEY_CB, None, ""
        if name and not CB_RANGE[0] <= cb <= CB_RANGE[1]:
            add(name, f"{what}, outside the range a Wigley-type demihull can represent "
                      f"[{CB_RANGE[0]}, {CB_RANGE[1]}]; check the mass and hull.length, "
                      "hull.demihull_beam, hull.draft")

    # --- centre of gravity and inertia
    if has("lcg", "length") and abs(v["lcg"]) >= 0.25 * v["length"]:
        add("lcg", f"{v['lcg']:g} m is outside the middle half of the hull (|lcg| < L/4 = {v['length'] / 4:g} m)")
    for ax in ("xx", "yy", "zz"):
        if has(f"r_{ax}", f"i_{ax}"):
            add(f"i_{ax}", f"give either inertia.r_{ax} or inertia.i_{ax}, not both")
        elif (ax != "zz" and v.get(f"r_{ax}") is None and v.get(f"i_{ax}") is None
              and not {f"r_{ax}", f"i_{ax}"} & set(rejected)):
            add(f"r_{ax}", f"missing: give inertia.r_{ax} (radius of gyration about the CoG, m) "
                           f"or inertia.i_{ax} (kg m²)")
    if not out and form == "ctv" and has("mass", "length", "demihull_beam", "draft", "separation") \
            and rho is not None:
        hull = _make_hull(v)
        m_lines = rho * hull.volume
        if abs(v["mass"] - m_lines) > MASS_TOLERANCE * m_lines:
            T_match = _matching_draft(v, rho)
            add("mass", f"{v['mass']:g} kg differs from ρ∇ = {m_lines:.6g} kg of the hull's lines at "
                        f"hull.draft = {v['draft']:g} m by {(v['mass'] - m_lines) / m_lines:+.1%} (more than "
                        f"{MASS_TOLERANCE:.0%}): a floating vessel displaces its mass"
                        + (f"; these form parameters displace it at hull.draft = {T_match:.4g} m" if T_match else "")
                        + " — or leave inertia.mass out (mass = ρ∇)")
    if not out and has("length", "demihull_beam", "draft", "separation", "kg") and rho is not None and g is not None:
        cb, mass, inertia, _ = _resolve({**v, "rho": rho})
        hull = _make_hull(v, cb)
        lcg = v["lcg"] if v.get("lcg") is not None else float(hull.centre_of_buoyancy[0])
        C = hull.restoring(rho, g, mass, (lcg, 0.0, v["kg"] - v["draft"]))
        for i, what in ((3, "roll"), (4, "pitch")):
            if C[i, i] <= 0:
                gm = C[i, i] / (mass * g)
                add("kg", f"{v['kg']:g} m makes the vessel unstable in {what} (GM = {gm:.3g} m ≤ 0)")
        I = inertia
        if all(math.isfinite(x) for x in I):
            for a, b_, c in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
                if I[a] > I[b_] + I[c] * (1 + 1e-9):
                    ax = ("xx", "yy", "zz")[a]
                    name = f"i_{ax}" if v.get(f"i_{ax}") is not None else f"r_{ax}"
                    add(name, f"I_{ax} = {I[a]:.4g} kg m² exceeds the sum of the other two principal moments "
                              f"({I[b_] + I[c]:.4g}): no rigid body has such inertia")

    # --- mesh
    if has("panel_size") and (has("n_length") or has("n_girth") or has("n_lid")):
        add("panel_size", "give either mesh.panel_size or the panel counts (n_length, n_girth, n_lid), not both")
    if has("n_length") and v["n_length"] % 2 and form == "wigley":
        add("n_length", f"must be even (the mesh has fore–aft symmetry), got {v['n_length']}")
    if (has("n_girth") or has("n_lid")) and not has("n_length"):
        add("n_length", "missing: give mesh.n_length with mesh.n_girth / mesh.n_lid")

    # --- frequencies and directions
    if has("n_omega", "d_omega"):
        add("d_omega", "give either frequencies.n or frequencies.d_omega, not both")
    elif not has("n_omega") and not has("d_omega") and not {"n_omega", "d_omega"} & set(rejected):
        add("n_omega", "missing: give frequencies.n (number of frequencies) or frequencies.d_omega (step, rad/s)")
    if has("omega_min", "omega_max"):
        if v["omega_max"] <= v["omega_min"]:
            add("omega_max", f"must be > frequencies.omega_min = {v['omega_min']:g}, got {v['omega_max']:g}")
        elif has("d_omega"):
            n = int(math.floor((v["omega_max"] - v["omega_min"]) / v["d_omega"] + 1e-9)) + 1
            if not 2 <= n <= MAX_FREQUENCIES:
                add("d_omega", f"gives {n} frequencies between omega_min and omega_max; "
                               f"expected 2 to {MAX_FREQUENCIES}")
    if has("direction_step_deg"):
        step = float(v["direction_step_deg"])
        n = 180.0 / step if step > 0 else math.inf
        if not (0 < step <= 180 and abs(n - round(n)) < 1e-9):
            add("direction_step_deg", f"must divide 180° (e.g. 5, 10, 15, 22.5, 30, 45, 90), got {step:g}")
    depth = v.get("water_depth")
    if isinstance(depth, (int, float)) and math.isfinite(depth) and has("draft") and depth <= 1.5 * v["draft"]:
        add("water_depth", f"{depth:g} m leaves less than half a draft under the keel (draft {v['draft']:g} m)")

    # --- mesh resolution against the shortest wave
    if not out and has("omega_max", "length", "demihull_beam", "draft", "separation") and g is not None:
        try:
            spec_like = _mesh_resolution(v, rho or 1025.0, g)
        except (ValueError, ZeroDivisionError):
            spec_like = None
        if spec_like is not None and spec_like[0] < MIN_PANELS_PER_WAVELENGTH:
            ppw, lam, hmax = spec_like
            key = "panel_size" if has("panel_size") else "n_length"
            add(key, f"panels up to {hmax:.3g} m give only {ppw:.1f} panels per shortest wavelength "
                     f"({lam:.3g} m at omega_max): use at most {lam / 6:.3g} m (6 per wavelength) "
                     "or lower frequencies.omega_max")
    return out


def _matching_draft(v: dict, rho: float) -> float | None:
    """The draft at which the CTV form parameters of ``v`` displace ``v["mass"]`` (bisection), or None."""
    def mass_at(T):
        return rho * _make_hull({**v, "draft": T}).volume
    lo, hi = 0.2 * v["draft"], 5.0 * v["draft"]
    try:
        if not mass_at(lo) < v["mass"] < mass_at(hi):
            return None
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if mass_at(mid) < v["mass"] else (lo, mid)
    except ValueError:   # the form parameters do not hold at some draft (e.g. the tunnel above the deck)
        return None
    return 0.5 * (lo + hi)


def _panel_counts(hull, shortest_wavelength: float, panel_size, n_length, n_girth, n_lid):
    """Panel counts from explicit counts (missing ones from the default size) or from a panel size."""
    default = hull.panel_counts(panel_size or shortest_wavelength / DEFAULT_PANELS_PER_WAVELENGTH)
    if n_length is None:
        return default
    if isinstance(hull, CTVCatamaran):
        return hull.counts_from(n_length, n_girth, n_lid, default)
    n_girth = n_girth if n_girth is not None else default.n_girth
    n_lid = n_lid if n_lid is not None else max(1, round(n_girth * hull.demihull_beam / hull.midship_girth()))
    return PanelCounts(n_length // 2, n_girth, n_lid)


def _mesh_resolution(v: dict, rho: float, g: float) -> tuple[float, float, float]:
    """(panels per shortest wavelength, shortest wavelength, largest panel edge) of inputs ``v``."""
    cb, _, _, _ = _resolve({**v, "rho": rho})
    hull = _make_hull(v, cb)
    depth = v.get("water_depth")
    lam = wavelength(v["omega_max"], g, float(depth) if isinstance(depth, (int, float)) else math.inf)
    counts = _panel_counts(hull, lam, v.get("panel_size"), v.get("n_length"), v.get("n_girth"), v.get("n_lid"))
    hmax = hull.max_panel_size(counts)
    return lam / hmax, lam, hmax


def load_vessel(path: str | Path) -> "VesselSpec | ImportedVesselSpec":
    """Read and validate a vessel file: a hull to build (``[hull]``, a :class:`VesselSpec`) or BEM output
    to import with its mass properties (``[bem]``, an
    :class:`~boatland.vessel.imported.ImportedVesselSpec`).

    Raises
    ------
    SpecError (a BoatlandInputError)
        Syntax error (with line and column), or every problem of the file with its key path.
    """
    path = Path(path)
    problems = Problems(path)
    raw = parse_toml_file(path)
    if "bem" in raw:
        if "hull" in raw:
            problems.add("hull", "give either [hull] (a hull boatland builds with Capytaine) or [bem] (BEM output "
                                 "to import), not both")
            problems.raise_if_any()
        spec = load_imported(raw, path, problems)
        problems.raise_if_any()
        return spec
    data = validate(raw, VESSEL_SCHEMA, problems)
    problems.items = [(k, "missing table: give [hull] (a hull boatland builds with Capytaine) or [bem] (BEM output "
                          "to import, with its mass properties)") if (k, m) == ("hull", "missing table") else (k, m)
                      for k, m in problems.items]
    kwargs = _flatten(data)
    rejected = {name for name, key in FIELD_KEYS.items() if problems.has(key)}
    for key, msg in vessel_problems(kwargs, rejected):
        if not problems.has(key):
            problems.add(key, msg)
    problems.raise_if_any()
    kwargs["source"] = str(path)
    return VesselSpec(**kwargs)


def _flatten(data: dict) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for name, key in FIELD_KEYS.items():
        node: Any = data
        for part in key.split("."):
            node = node.get(part) if isinstance(node, dict) else None
        if node is not None:
            out[name] = node
    wd = out.get("water_depth")
    if isinstance(wd, str):
        out["water_depth"] = math.inf
    if "deckhouse" in out:
        out["deckhouse"] = tuple(out["deckhouse"])
    return out
