r"""NEMOH v2 / v3 run folder → :class:`~boatland.vessel.database.HydroDB`.

Files read (NEMOH user manuals v2.0 and v3.0; notes/hydro-formats.md):

- ``Nemoh.cal``: ρ, g, water depth (0 = infinite), wave measurement point; per body the degrees of
  freedom (``1 ex ey ez 0 0 0`` translation along e, ``2 ex ey ez x y z`` rotation about axis e
  through point (x, y, z) — that point is the reference point) and the generalised forces; the
  frequency line (v3: ``type N min max``, type 1/2/3 = rad/s, Hz, s; v2: ``N min max`` in rad/s),
  the direction line ``N min max`` [deg], and (v3) the output frequency type.
- ``Results/RadiationCoefficients.tec``: one Tecplot zone per *motion* DOF j; rows
  ``ω  A_1j B_1j  A_2j B_2j ...`` — dimensional, force i due to motion j.
- ``Results/ExcitationForce.tec``: one zone per direction (``beta = ... deg`` in the zone title); rows
  ``ω  |F_1| arg F_1  |F_2| arg F_2 ...``, phases in radians.
- ``Mesh/KH.dat`` (6 × 6 restoring, N/m, N, N·m) and ``Mesh/Hydrostatics.dat`` (centre of buoyancy
  XF/YF/ZF, gravity XG/YG/ZG, displacement [m³], and in v3 the mass).

NEMOH uses exp(−iωt): forces are conjugated to boatland's exp(+iωt) (at ω = 0.02 rad/s NEMOH gives
surge phase −π/2 for β = 0; boatland's convention is +π/2). Coordinates are NEMOH's mesh frame, z = 0
on the calm waterline. Single-body runs only.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from boatland.errors import HydroDataError
from boatland.hydro._text import TextFile, build_db, find_child, normalise_directions
from boatland.vessel.database import HydroDB, Provenance

__all__ = ["read_nemoh"]


def read_nemoh(path: str | Path) -> HydroDB:
    """Read a NEMOH (v2 or v3) run into a :class:`HydroDB`.

    Parameters
    ----------
    path : str or Path
        The run folder (holding ``Nemoh.cal``, ``Mesh/``, ``Results/``), its ``Nemoh.cal``, or a
        ``Results/*.tec`` file. Folder and file names are matched case-insensitively.

    Returns
    -------
    HydroDB
        Dimensional SI database in boatland's exp(+iωt) convention; ``M`` is None (NEMOH does not
        know the inertia; the mass, when ``Hydrostatics.dat`` gives it, is in the provenance notes);
        no ``A_inf``/``A_0`` (NEMOH does not compute them).

    Raises
    ------
    HydroDataError
        A required file is missing or malformed; the message names the file and line.
    """
    path = Path(path)
    folder, cal_path = _locate(path)
    notes: list[str] = []
    cal = _read_cal(TextFile(cal_path, "NEMOH input file Nemoh.cal"))
    notes.append(f"NEMOH {cal.version} Nemoh.cal layout")

    results = find_child(folder, "Results")
    rad_path = find_child(results, "RadiationCoefficients.tec") if results else None
    exc_path = find_child(results, "ExcitationForce.tec") if results else None
    for p, name in ((rad_path, "RadiationCoefficients.tec"), (exc_path, "ExcitationForce.tec")):
        if p is None:
            raise HydroDataError(folder / "Results" / name, None, "file not found; expected NEMOH's results "
                                                                  "(run the solver and postprocessor first)")
    rad_tf = TextFile(rad_path, "NEMOH radiation coefficients (Tecplot)")
    exc_tf = TextFile(exc_path, "NEMOH excitation forces (Tecplot)")
    rad_vars, rad_zones = _read_tec(rad_tf, 1 + 2 * len(cal.forces))
    _, exc_zones = _read_tec(exc_tf, 1 + 2 * len(cal.forces))

    omega, to_omega_note = _omega(rad_vars, cal, rad_tf, rad_zones[0])
    if to_omega_note:
        notes.append(to_omega_note)
    nf = omega.size
    A, B = np.zeros((6, 6, nf)), np.zeros((6, 6, nf))
    if len(rad_zones) != len(cal.dofs):
        raise rad_tf.error(None, f"{len(rad_zones)} zones, but Nemoh.cal lists {len(cal.dofs)} degrees of "
                                 "freedom (one zone per motion DOF expected)")
    for zone in rad_zones:
        mt = re.search(r"body\s+(\d+)\s+in\s+DoF\s+(\d+)", zone.title, flags=re.I)
        if not mt or int(mt.group(1)) != 1 or not 1 <= int(mt.group(2)) <= len(cal.dofs):
            raise rad_tf.error(zone.line, f"zone title {zone.title!r}: expected 'Motion of body 1 in DoF j' "
                                          f"with j in 1..{len(cal.dofs)}")
        _same_frequencies(rad_tf, zone, rad_zones[0])
        j = cal.dofs[int(mt.group(2)) - 1]
        for c, i in enumerate(cal.forces):
            A[i, j] = zone.rows[:, 1 + 2 * c]
            B[i, j] = zone.rows[:, 2 + 2 * c]

    beta_in, X = [], []
    for zone in exc_zones:
        mt = re.search(r"beta\s*=\s*([-+]?[\d.]+(?:[EeDd][-+]?\d+)?)", zone.title, flags=re.I)
        if not mt:
            raise exc_tf.error(zone.line, f"zone title {zone.title!r}: expected 'beta = <direction> deg'")
        _same_frequencies(exc_tf, zone, rad_zones[0], other=rad_tf.path.name)
        beta_in.append(float(mt.group(1).replace("D", "E")))
        amp, phase = zone.rows[:, 1::2], zone.rows[:, 2::2]
        Xz = np.zeros((6, nf), dtype=complex)
        Xz[cal.forces] = (amp * np.exp(-1j * phase)).T          # conjugate: exp(−iωt) → exp(+iωt)
        X.append(Xz)
    X = np.stack(X, axis=1)
    if np.max(np.abs([z.rows[:, 2::2] for z in exc_zones])) > np.pi + 1e-3:
        raise exc_tf.error(None, "excitation phases exceed π: expected radians (NEMOH writes angle(F) in rad)")
    if cal.n_dir is not None and cal.n_dir != len(exc_zones):
        notes.append(f"Nemoh.cal asks for {cal.n_dir} directions, {exc_tf.path.name} has {len(exc_zones)}: "
                     "used the results")
    if cal.n_freq is not None and cal.n_freq != nf:
        notes.append(f"Nemoh.cal asks for {cal.n_freq} frequencies, the results have {nf}: used the results")

    order = np.argsort(omega)
    omega, A, B, X = omega[order], A[..., order], B[..., order], X[..., order]
    beta, keep, groups = normalise_directions(beta_in)
    for g in groups:
        if g.size > 1:
            notes.append(f"directions {', '.join(f'{beta_in[i]:g}°' for i in g)} are the same: kept the first")
    X = X[:, keep]

    C, hyd = _read_mesh_files(folder, notes)
    if cal.ref_point is None:
        ref = np.zeros(3)
        notes.append("no rotation DOF or moment in Nemoh.cal: reference point assumed at the origin")
    else:
        ref = cal.ref_point
    if np.any(cal.wave_point[:2] != ref[:2]):
        notes.append(f"wave measurement point (XEFF, YEFF) = ({cal.wave_point[0]:g}, {cal.wave_point[1]:g}) m: "
                     "excitation phases are referred to it, not to the reference point")
    prov = Provenance(source=str(path), solver="NEMOH", created="", reader="nemoh", notes=tuple(notes))
    return build_db(
        cal_path, omega=omega, A=A, B=B, X=X, wave_dir_deg=beta, C=C, A_inf=None, A_0=None, M=None,
        ref_point=ref, cog=hyd.get("G", np.zeros(3)), cob=hyd.get("F", np.zeros(3)),
        disp_vol=hyd.get("Displacement", 0.0), water_depth=cal.depth, rho=cal.rho, g=cal.g,
        name=folder.resolve().name or "nemoh", provenance=prov,
    )


def _locate(path: Path) -> tuple[Path, Path]:
    """(run folder, Nemoh.cal) from a folder, a .cal file or a Results/*.tec file."""
    if not path.exists():
        raise HydroDataError(path, None, "file or folder not found; expected a NEMOH run folder or its Nemoh.cal")
    if path.is_dir():
        folder = path
    elif path.suffix.lower() == ".cal":
        return path.parent, path
    elif path.suffix.lower() == ".tec" and path.parent.name.lower() == "results":
        folder = path.parent.parent
    else:
        raise HydroDataError(path, None, "not a NEMOH run; expected the run folder, Nemoh.cal, or a Results/*.tec file")
    cal = find_child(folder, "Nemoh.cal")
    if cal is None:
        raise HydroDataError(folder / "Nemoh.cal", None, "file not found; NEMOH results cannot be read without "
                                                         "the run's Nemoh.cal (ρ, g, depth, degrees of freedom)")
    return folder, cal


# ------------------------------------------------------------------------------------ Nemoh.cal
@dataclass
class _Cal:
    rho: float = 0.0
    g: float = 0.0
    depth: float = np.inf
    wave_point: np.ndarray = field(default_factory=lambda: np.zeros(2))
    dofs: list[int] = field(default_factory=list)       # boatland DOF index of each NEMOH motion DOF
    forces: list[int] = field(default_factory=list)     # boatland DOF index of each generalised force
    ref_point: np.ndarray | None = None
    freq_type: int = 1
    out_freq_type: int | None = None
    n_freq: int | None = None
    n_dir: int | None = None
    version: str = "v2"


def _read_cal(tf: TextFile) -> _Cal:
    cal = _Cal()
    entries = []                                        # (line number, value tokens, comment)
    for n, line in enumerate(tf.lines, start=1):
        if line.strip().startswith("---") or not line.strip():
            continue
        value, _, comment = line.partition("!")
        entries.append((n, value.split(), comment.lower()))
    it = iter(entries)

    def take(what: str, count: int | None = None, minimum: int = 1):
        try:
            n, tokens, comment = next(it)
        except StopIteration:
            raise tf.error(None, f"ends early; expected {what}") from None
        if len(tokens) < minimum:
            raise tf.error(n, f"expected {what}, found {len(tokens)} values")
        return n, tokens[:count] if count else tokens, comment

    n, tok, _ = take("ρ [kg/m³]")
    cal.rho = float(tf.numbers(n, tok[:1], what="ρ [kg/m³]")[0])
    n, tok, _ = take("g [m/s²]")
    cal.g = float(tf.numbers(n, tok[:1], what="g [m/s²]")[0])
    n, tok, _ = take("the water depth [m]")
    depth = float(tf.numbers(n, tok[:1], what="the water depth [m] (0 = infinite)")[0])
    cal.depth = np.inf if depth == 0 else abs(depth)
    n, tok, _ = take("the wave measurement point XEFF YEFF", minimum=2)
    cal.wave_point = tf.numbers(n, tok[:2], what="XEFF YEFF")
    n, tok, _ = take("the number of bodies")
    n_bodies = tf.integer(n, tok[0], what="the number of bodies", lo=1)
    if n_bodies != 1:
        raise tf.error(n, f"{n_bodies} bodies: boatland reads single-body NEMOH runs only")
    take("the mesh file name")                          # not needed (may be a Windows path)
    take("the number of mesh points and panels", minimum=2)
    points: list[np.ndarray] = []
    for kind in ("degrees of freedom", "generalised forces"):
        n, tok, _ = take(f"the number of {kind}")
        count = tf.integer(n, tok[0], what=f"the number of {kind}", lo=1, hi=6)
        target = cal.dofs if kind.startswith("deg") else cal.forces
        for _ in range(count):
            n, tok, _ = take(f"a {kind[:-1]} line 'type ex ey ez x y z'", minimum=7)
            target.append(_axis(tf, n, tok, points))
        if len(set(target)) != len(target):
            raise tf.error(n, f"the same {kind[:-1]} is listed twice")
    n, tok, _ = take("the number of lines of additional information")
    for _ in range(tf.integer(n, tok[0], what="the number of additional lines", lo=0)):
        take("an additional information line", minimum=0)
    if points:
        ref = points[0]
        if any(np.max(np.abs(p - ref)) > 1e-9 for p in points):
            raise tf.error(None, "rotations about different points; expected one reference point")
        cal.ref_point = ref
    n, tok, _ = take("the frequency line", minimum=3)
    tok = tok[:4]
    tf.numbers(n, tok, what="numbers on the frequency line")
    if len(tok) == 4:                                   # v3: type N min max; v2: N min max (rad/s)
        cal.version = "v3"
        cal.freq_type = tf.integer(n, tok[0], what="the frequency type (1 rad/s, 2 Hz, 3 s)", lo=1, hi=3)
    cal.n_freq = tf.integer(n, tok[-3], what="the number of frequencies", lo=1)
    n, tok, _ = take("the direction line 'N min max'", minimum=3)
    cal.n_dir = tf.integer(n, tok[0], what="the number of directions", lo=1)
    for n, tok, comment in it:                          # post-processing: only the output frequency type
        if "output freq" in comment and tok:
            cal.out_freq_type = tf.integer(n, tok[0], what="the output frequency type (1 rad/s, 2 Hz, 3 s)",
                                           lo=1, hi=3)
    return cal


def _axis(tf: TextFile, n: int, tok: list[str], points: list) -> int:
    """boatland DOF index of a Nemoh.cal DOF/force line; collects rotation points."""
    kind = tf.integer(n, tok[0], what="the DOF type (1 translation, 2 rotation)", lo=1, hi=2)
    v = tf.numbers(n, tok[1:7], what="axis and point 'ex ey ez x y z'")
    e = v[:3] / max(np.linalg.norm(v[:3]), 1e-300)
    k = int(np.argmax(np.abs(e)))
    if not np.isclose(abs(e[k]), 1.0, atol=1e-9) or e[k] < 0:
        raise tf.error(n, f"direction ({v[0]:g}, {v[1]:g}, {v[2]:g}): expected a positive coordinate axis "
                          "(oblique or generalised modes are not supported)")
    if kind == 2:
        points.append(v[3:6])
    return k + 3 * (kind - 1)


# ------------------------------------------------------------------------------------ Tecplot
@dataclass
class _Zone:
    title: str
    line: int
    rows: np.ndarray              # (N, ncol)
    row_lines: list[int]


def _read_tec(tf: TextFile, ncol: int) -> tuple[list[str], list[_Zone]]:
    """VARIABLES and zones of a NEMOH Tecplot file; every data row must have ``ncol`` numbers."""
    variables: list[str] = []
    zones: list[_Zone] = []
    declared: list[int | None] = []
    rows: list[np.ndarray] = []
    row_lines: list[int] = []

    def close():
        if zones:
            zones[-1].rows = np.array(rows).reshape(-1, ncol)
            zones[-1].row_lines = list(row_lines)

    for n, line in enumerate(tf.lines, start=1):
        s = line.strip()
        if not s:
            continue
        if s.upper().startswith("VARIABLES") or (s.startswith('"') and not zones):
            variables += re.findall(r'"([^"]*)"', s)
            continue
        if s.upper().startswith("ZONE"):
            close()
            mt = re.search(r't\s*=\s*"([^"]*)"', s, flags=re.I)
            size = re.search(r"\bI\s*=\s*(\d+)", s)
            zones.append(_Zone(mt.group(1) if mt else s, n, np.empty((0, ncol)), []))
            declared.append(int(size.group(1)) if size else None)
            rows, row_lines = [], []
            continue
        tokens = s.split()
        if not zones:
            raise tf.error(n, f"data before the first 'Zone' line; expected the {tf.what}")
        if len(tokens) != ncol:
            raise tf.error(n, f"expected {ncol} numbers (ω and {(ncol - 1) // 2} pairs, as Nemoh.cal's "
                              f"forces imply), found {len(tokens)}")
        rows.append(tf.numbers(n, tokens, what="numbers"))
        row_lines.append(n)
    close()
    if not zones:
        raise tf.error(None, f"no 'Zone' found; expected the {tf.what}")
    for zone, size in zip(zones, declared):
        if size is not None and zone.rows.shape[0] != size:
            raise tf.error(zone.line, f"zone {zone.title!r} declares I={size} rows but has {zone.rows.shape[0]} "
                                      "(truncated file?)")
        if zone.rows.shape[0] == 0:
            raise tf.error(zone.line, f"zone {zone.title!r} has no data rows")
        w = zone.rows[:, 0]
        values, counts = np.unique(w, return_counts=True)
        if np.any(counts > 1):
            k = np.flatnonzero(w == values[counts > 1][0])[1]
            raise tf.error(zone.row_lines[k], f"frequency {w[k]:g} appears twice in zone {zone.title!r}")
    return variables, zones


def _same_frequencies(tf: TextFile, zone: _Zone, first: _Zone, other: str | None = None) -> None:
    w, w0 = zone.rows[:, 0], first.rows[:, 0]
    if w.shape != w0.shape or not np.allclose(w, w0, rtol=1e-6):
        k = 0 if w.shape != w0.shape else int(np.argmax(~np.isclose(w, w0, rtol=1e-6)))
        where = f"the first zone of {other}" if other else "the first zone"
        raise tf.error(zone.row_lines[min(k, len(zone.row_lines) - 1)] if zone.row_lines else zone.line,
                       f"zone {zone.title!r} has other frequencies than {where} "
                       f"({w.size} vs {w0.size} rows)")


def _omega(variables: list[str], cal: _Cal, tf: TextFile, zone: _Zone) -> tuple[np.ndarray, str | None]:
    """Angular frequencies [rad/s] from the first column, whatever unit NEMOH wrote it in."""
    label = variables[0].lower() if variables else ""
    if "rad/s" in label:
        unit = 1
    elif "hz" in label:
        unit = 2
    elif "(s)" in label:
        unit = 3
    else:
        unit = cal.out_freq_type or 1
    x = zone.rows[:, 0]
    if np.any(x <= 0):
        k = int(np.argmax(x <= 0))
        raise tf.error(zone.row_lines[k], f"frequency {x[k]:g}: expected values > 0")
    if unit == 1:
        return x.copy(), None
    if unit == 2:
        return 2 * np.pi * x, "first column of the .tec files is in Hz: converted to rad/s"
    return 2 * np.pi / x, "first column of the .tec files is the period [s]: converted to rad/s"


# ------------------------------------------------------------------------------------ Mesh/
def _read_mesh_files(folder: Path, notes: list[str]) -> tuple[np.ndarray, dict]:
    """Restoring matrix from Mesh/KH.dat and centres/volume/mass from Mesh/Hydrostatics.dat."""
    mesh = find_child(folder, "Mesh")
    kh = (find_child(mesh, "KH.dat") or find_child(mesh, "KH_0.dat")) if mesh else None
    if kh is None:
        raise HydroDataError(folder / "Mesh" / "KH.dat", None, "file not found; expected NEMOH's 6×6 "
                                                               "hydrostatic stiffness matrix")
    tf = TextFile(kh, "NEMOH hydrostatic stiffness KH.dat (6×6)")
    rows = [(n, line.split()) for n, line in enumerate(tf.lines, start=1) if line.strip()]
    if len(rows) != 6:
        raise tf.error(None, f"expected 6 rows of 6 numbers, found {len(rows)} rows")
    C = np.zeros((6, 6))
    for k, (n, tokens) in enumerate(rows):
        if len(tokens) != 6:
            raise tf.error(n, f"expected 6 numbers, found {len(tokens)}")
        C[k] = tf.numbers(n, tokens, what="stiffness values")

    hyd: dict = {}
    hp = (find_child(mesh, "Hydrostatics.dat") or find_child(mesh, "Hydrostatics_0.dat")) if mesh else None
    if hp is None:
        notes.append("no Mesh/Hydrostatics.dat: centres of gravity and buoyancy and the volume unknown (set to 0)")
        return C, hyd
    tf = TextFile(hp, "NEMOH Hydrostatics.dat")
    F, G = np.zeros(3), np.zeros(3)
    pat = re.compile(r"([A-Za-z][A-Za-z ]*?)\s*=\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?)")
    for n, line in enumerate(tf.lines, start=1):
        for key, val in pat.findall(line):
            key = key.strip()
            v = float(tf.numbers(n, [val], what=f"a number after {key!r}")[0])
            if len(key) == 2 and key[1] in "FG" and key[0] in "XYZ":
                (F if key[1] == "F" else G)["XYZ".index(key[0])] = v
            elif key.lower() in ("displacement", "mass", "waterplane area"):
                hyd[key.capitalize()] = v
    hyd["F"], hyd["G"] = F, G
    if "Mass" in hyd:
        notes.append(f"mass {hyd['Mass']:.6g} kg from {hp.name}; inertia unknown, so no mass matrix M")
    return C, hyd
