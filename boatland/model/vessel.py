r"""The vessel file: a catamaran CTV described by a few particulars, validated and immutable.

A vessel file (TOML, SI units, angles in ``_deg`` keys) says everything the Capytaine builder
(:mod:`boatland.hydro.build`) needs to make a hydrodynamic database::

    name = "ctv24"

    [hull]                     # two generalized Wigley demihulls (boatland.model.hull)
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

Reference point (body origin): midship, centreline, calm waterline; x forward, y to port, z up.

:func:`load_vessel` reports every problem of a file at once with its key path
(:mod:`boatland.model.tomlspec`); constructing :class:`VesselSpec` directly runs the same checks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

import numpy as np

from boatland.model.hull import CB_RANGE, PanelCounts, WigleyCatamaran, exponent_for_block_coefficient
from boatland.model.hydrodb import rigid_body_mass_matrix
from boatland.model.tomlspec import Key, Problems, SpecError, Table, parse_toml_file, validate

__all__ = ["VESSEL_SCHEMA", "VesselSpec", "load_vessel", "vessel_problems", "wavelength"]

#: Default mesh resolution: largest panel edge = shortest wavelength / this.
DEFAULT_PANELS_PER_WAVELENGTH = 8.0
#: Coarser than this many panels per shortest wavelength is rejected (results would be noise).
MIN_PANELS_PER_WAVELENGTH = 4.0
#: Classic Wigley block coefficient (p = 2), used when neither mass nor C_b is given.
WIGLEY_CB = 4.0 / 9.0
MAX_FREQUENCIES = 2000


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
        "length": Key(float, required=True, gt=0.0, doc="waterline length L of a demihull [m]"),
        "demihull_beam": Key(float, required=True, gt=0.0, doc="waterline beam b of one demihull [m]"),
        "draft": Key(float, required=True, gt=0.0, doc="draft T [m]"),
        "separation": Key(float, required=True, gt=0.0, doc="demihull centreline to centreline [m]"),
        "block_coefficient": Key(float, gt=0.0, lt=1.0, doc="block coefficient of a demihull (without inertia.mass)"),
    }, required=True),
    "inertia": Table({
        "mass": Key(float, gt=0.0, doc="vessel mass [kg]"),
        "lcg": Key(float, default=0.0, doc="centre of gravity forward of midship [m]"),
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
    "direction_step_deg": "directions.step_deg",
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
        Block coefficient of a demihull (from the mass, given, or 4/9).
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
    lcg: float = 0.0
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
    source: str = ""

    total_mass: float = field(init=False, repr=False)
    cb: float = field(init=False, repr=False)
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
        inertia = np.array(inertia, dtype=float)
        inertia.setflags(write=False)
        object.__setattr__(self, "inertia_cog", inertia)
        object.__setattr__(self, "notes", tuple(notes))

    # ------------------------------------------------------------------ derived
    @property
    def hull(self) -> WigleyCatamaran:
        """The hull form (generalized Wigley demihulls with this spec's block coefficient)."""
        return WigleyCatamaran.from_block_coefficient(self.length, self.demihull_beam, self.draft,
                                                      self.separation, self.cb)

    @property
    def cog(self) -> np.ndarray:
        """Centre of gravity in the body frame (origin midship, centreline, waterline) [m]."""
        return np.array([self.lcg, 0.0, self.kg - self.draft])

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

    def panel_counts(self) -> PanelCounts:
        """Quarter-mesh panel counts from ``panel_size`` or the explicit counts (default: λ_min / 8)."""
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


def _resolve(v: dict) -> tuple[float, float, tuple[float, float, float], list[str]]:
    """Block coefficient, mass, inertias and notes from validated inputs."""
    notes: list[str] = []
    L, b, T, rho = v["length"], v["demihull_beam"], v["draft"], v["rho"]
    if v.get("mass") is not None:
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
    if has("mass", "block_coefficient"):
        add("block_coefficient", "give either inertia.mass or hull.block_coefficient, not both "
                                 "(the mass sets the block coefficient)")
    elif has("length", "demihull_beam", "draft") and rho is not None:
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
    if not out and has("length", "demihull_beam", "draft", "separation", "kg") and rho is not None and g is not None:
        cb, mass, inertia, _ = _resolve({**v, "rho": rho})
        hull = WigleyCatamaran.from_block_coefficient(v["length"], v["demihull_beam"], v["draft"],
                                                      v["separation"], cb)
        C = hull.restoring(rho, g, mass, (v.get("lcg") or 0.0, 0.0, v["kg"] - v["draft"]))
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
    if has("n_length") and v["n_length"] % 2:
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


def _panel_counts(hull: WigleyCatamaran, shortest_wavelength: float, panel_size, n_length, n_girth, n_lid) -> PanelCounts:
    """Panel counts from explicit counts (missing ones from the default size) or from a panel size."""
    default = hull.panel_counts(panel_size or shortest_wavelength / DEFAULT_PANELS_PER_WAVELENGTH)
    if n_length is None:
        return default
    n_girth = n_girth if n_girth is not None else default.n_girth
    n_lid = n_lid if n_lid is not None else max(1, round(n_girth * hull.demihull_beam / hull.midship_girth()))
    return PanelCounts(n_length // 2, n_girth, n_lid)


def _mesh_resolution(v: dict, rho: float, g: float) -> tuple[float, float, float]:
    """(panels per shortest wavelength, shortest wavelength, largest panel edge) of inputs ``v``."""
    cb, _, _, _ = _resolve({**v, "rho": rho})
    hull = WigleyCatamaran.from_block_coefficient(v["length"], v["demihull_beam"], v["draft"], v["separation"], cb)
    depth = v.get("water_depth")
    lam = wavelength(v["omega_max"], g, float(depth) if isinstance(depth, (int, float)) else math.inf)
    counts = _panel_counts(hull, lam, v.get("panel_size"), v.get("n_length"), v.get("n_girth"), v.get("n_lid"))
    hmax = hull.max_panel_size(counts)
    return lam / hmax, lam, hmax


def load_vessel(path: str | Path) -> VesselSpec:
    """Read and validate a vessel file.

    Raises
    ------
    SpecError (a BoatlandInputError)
        Syntax error (with line and column), or every problem of the file with its key path.
    """
    path = Path(path)
    problems = Problems(path)
    data = validate(parse_toml_file(path), VESSEL_SCHEMA, problems)
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
    return out
