r"""AQWA ``.AH1`` hydrodynamic database (+ optional ``.LIS``) → :class:`~boatland.vessel.database.HydroDB`.

Layout of the ``.AH1`` (AQWA-LINE "OPTIONS AHD1" output; notes/hydro-formats.md). Lines starting
with ``*`` are comments (run date, and the frequencies of the low/high-frequency limits). Then::

    nbody ndir nfreq  dir_1 ... dir_ndir            directions [deg], direction of travel
    freq_1 ... freq_nfreq                           [rad/s], several per line
    GENERAL        body  depth  rho  g  ...
    COG / COB      body  x y z                      [m]
    DRAFT          body  T
    DISPLACEMENT   body  V                          [m³]
    MASS           body  6 × 6                      mass matrix about the COG [kg, kg m²]
    HYDSTIFFNESS   body  6 × 6                      restoring about the COG
    ADDEDMASS      body body ifreq  6 × 6           per frequency (6 rows)
    DAMPING        body body ifreq  6 × 6
    ADDEDMASS_LF / DAMPING_LF / ADDEDMASS_HF   body body  6 × 6
    FORCERAO       body idir ifreq  6 amplitudes, then 6 phases [deg] on the next line
    FARFIELD       body idir ifreq  Fx Fy Fz Mx My Mz   far-field (momentum) mean drift [N/m², N·m/m²];
                                                    AQWA fills surge, sway and yaw only

The column layout changed after AQWA 18.2 (a body number in front of GENERAL, directions on the
first line or on the next), so everything is read as a stream of tokens per keyword block, never by
column position.

Mean drift. The ``.LIS`` lists the mean wave drift per unit amplitude squared ("WAVE-DRIFT LOADS FOR UNIT
WAVE AMPLITUDE**2", "(WITH RESPECT TO STRUCTURE COG)"): one table per DOF (``SURGE(X)`` … ``YAW(RZ)``),
the row "DUE TO ... DRIFT", columns of directions, rows of frequencies [rad/s, 3 decimals], values in
N/m² and N·m/m² with 3 significant digits. When it gives heave, roll and pitch too, it is the near-field
(pressure integration) drift of a run with the QTF options (AQTF, CQTF); the ``.AH1`` FARFIELD block is
AQWA's far-field (momentum) drift, surge, sway and yaw, 5 digits. ``drift="auto"`` (default) reads the
``.LIS`` tables when the ``.LIS`` is beside the ``.AH1`` and has them, else the FARFIELD block;
``"pressure"`` / ``"momentum"`` only the one; ``"none"`` neither. Directions and signs as the excitation:
direction of travel, force along the global axes, moments about the COG.

Conventions: AQWA reports A, B, C, X about the centre of gravity, so the reference point is the COG.
Wave directions are directions of travel like boatland's; −180° and 180° are merged and all are
mapped to [0°, 360°). AQWA phases are *lags* (at low ω, heading −180° gives surge phase +90°, where
the surge force of a wave travelling towards −x must lead the crest by −90°): the reader conjugates
to boatland's exp(+iωt) leads.
"""

from __future__ import annotations

import re
from datetime import datetime
from pathlib import Path

import numpy as np

from boatland.errors import HydroDataError
from boatland.hydro._text import TextFile, build_db, find_sibling, normalise_directions
from boatland.vessel.database import HydroDB, Provenance, rigid_body_mass_matrix

__all__ = ["read_aqwa"]

_REQUIRED = ("GENERAL", "HYDSTIFFNESS", "ADDEDMASS", "DAMPING", "FORCERAO")
_KNOWN = _REQUIRED + ("COG", "COB", "DRAFT", "DISPLACEMENT", "MASS", "ADDEDMASS_LF", "DAMPING_LF",
                      "ADDEDMASS_HF", "FIDD", "FARFIELD")


#: ``drift=`` choices (module docstring).
DRIFT_CHOICES = ("auto", "pressure", "momentum", "none")
_DRIFT_DOFS = ("SURGE(X)", "SWAY(Y)", "HEAVE(Z)", "ROLL(RX)", "PITCH(RY)", "YAW(RZ)")


def read_aqwa(path: str | Path, drift: str = "auto") -> HydroDB:
    """Read an AQWA ``.AH1`` file (single body) into a :class:`HydroDB`.

    Parameters
    ----------
    path : str or Path
        The ``.AH1`` file, or the ``.LIS`` beside it. The ``.LIS`` is optional and used only for what
        the ``.AH1`` lacks (the mass and inertia when there is no MASS block), to check the unit
        system is kg, m, and for its mean drift tables.
    drift : {"auto", "pressure", "momentum", "none"}
        Which mean drift fills ``HydroDB.drift`` (module docstring): the ``.LIS`` tables, the ``.AH1``
        FARFIELD block, the first of these present (``"auto"``), or none. A provenance note says which.

    Returns
    -------
    HydroDB
        Dimensional SI, exp(+iωt), reference point = COG; ``M`` from the MASS block; ``A_inf`` from
        ADDEDMASS_HF and ``A_0`` from ADDEDMASS_LF (AQWA's values at a high and a low frequency,
        noted in the provenance).

    Raises
    ------
    HydroDataError
        Missing or malformed file; the message names the file and the line.
    """
    path = Path(path)
    if drift not in DRIFT_CHOICES:
        raise HydroDataError(path, "drift", f"unknown choice {drift!r}; expected one of {', '.join(DRIFT_CHOICES)}")
    if path.suffix.lower() not in (".ah1", ".lis"):
        raise HydroDataError(path, None, "not an AQWA file; expected the .AH1 (or the .LIS beside it)")
    ah1 = path if path.suffix.lower() == ".ah1" else find_sibling(path, ".AH1")
    if ah1 is None:
        raise HydroDataError(path.with_suffix(".AH1"), None, "file not found; expected the AQWA .AH1 "
                                                             "hydrodynamic database beside the .LIS")
    tf = TextFile(ah1, "AQWA .AH1 hydrodynamic database")
    lis_path = find_sibling(ah1, ".LIS")
    lis = TextFile(lis_path, "AQWA .LIS listing") if lis_path is not None else None
    notes: list[str] = []
    comments, header, blocks = _split(tf)

    nbody, ndir, nf = (header.integer(w, lo=1) for w in ("the number of bodies", "the number of directions",
                                                         "the number of frequencies"))
    if nbody != 1:
        raise header.error(f"{nbody} bodies: boatland reads single-body AQWA files only")
    beta_in = header.floats(ndir, "the wave directions [deg]")
    omega = header.floats(nf, "the wave frequencies [rad/s]")
    header.done("the directions and frequencies")
    _check_frequencies(tf, header, omega)

    for key in _REQUIRED:
        if key not in blocks:
            raise tf.error(None, f"no {key} block; expected an AQWA .AH1 file with {', '.join(_REQUIRED)}")
    depth, rho, g = _general(blocks["GENERAL"])
    cog = _vector(blocks, "COG", 3, notes, "centre of gravity")
    cob = _vector(blocks, "COB", 3, notes, "centre of buoyancy")
    vol = float(_vector(blocks, "DISPLACEMENT", 1, notes, "displaced volume")[0])
    C = _matrix(blocks["HYDSTIFFNESS"], 1)
    A = np.stack(_per_frequency(blocks["ADDEDMASS"], nf), axis=-1)
    B = np.stack(_per_frequency(blocks["DAMPING"], nf), axis=-1)
    X = _excitation(blocks["FORCERAO"], ndir, nf)

    if _lis_units(lis, notes) is False:
        raise HydroDataError(lis.path, "unit system", "not 'kg, m': boatland reads AQWA results in SI units only")
    M = _mass(blocks, lis, cog, notes)
    lf, hf = _limit_frequencies(comments)
    A_inf = A_0 = None
    if "ADDEDMASS_HF" in blocks:
        A_inf = _matrix(blocks["ADDEDMASS_HF"], 2)
        notes.append(f"A_inf is AQWA's high-frequency added mass (ADDEDMASS_HF) at {hf or 'an unstated'} rad/s, "
                     "not an ω = ∞ solution")
    if "ADDEDMASS_LF" in blocks:
        A_0 = _matrix(blocks["ADDEDMASS_LF"], 2)
        notes.append(f"A_0 is AQWA's low-frequency added mass (ADDEDMASS_LF) at {lf or 'an unstated'} rad/s")
    ignored = sorted(set(blocks) - set(_KNOWN))
    if ignored:
        notes.append(f"blocks not read: {', '.join(ignored)}")
    if "FIDD" in blocks and np.any(_floats_lenient(blocks["FIDD"])[1:] != 0):
        notes.append("FIDD block has non-zero values: not included in B")

    D = _mean_drift(drift, blocks, lis, beta_in, omega, ndir, nf, notes)
    order = np.argsort(omega)
    if np.any(order != np.arange(nf)):
        notes.append("frequencies sorted ascending")
    omega, A, B, X = omega[order], A[..., order], B[..., order], X[..., order]
    beta, keep, groups = normalise_directions(beta_in)
    for grp in groups:
        if grp.size > 1:
            diff = np.max(np.abs(X[:, grp] - X[:, grp[:1]])) / max(np.max(np.abs(X[:, grp[:1]])), 1e-30)
            notes.append(f"directions {', '.join(f'{beta_in[i]:g}°' for i in grp)} are the same: kept "
                         f"{beta_in[grp[0]]:g}° (max difference {diff:.2g} of the largest force)")
            if D is not None:
                diff = np.max(np.abs(D[:, grp] - D[:, grp[:1]])) / max(np.max(np.abs(D[:, grp[:1]])), 1e-30)
                notes.append(f"mean drift at {', '.join(f'{beta_in[i]:g}°' for i in grp)}: kept {beta_in[grp[0]]:g}° "
                             f"(max difference {diff:.2g} of the largest)")
    if not np.allclose(beta, beta_in[keep]):
        notes.append("wave directions mapped to [0°, 360°) and sorted")
    X = X[:, keep]
    if D is not None:
        D = D[:, keep][..., order]

    prov = Provenance(source=str(path), solver="AQWA", created=_created(comments), reader="aqwa",
                      notes=tuple(notes))
    return build_db(
        ah1, omega=omega, A=A, B=B, X=X, wave_dir_deg=beta, C=C, A_inf=A_inf, A_0=A_0, M=M,
        ref_point=cog, cog=cog, cob=cob, disp_vol=vol, water_depth=depth, rho=rho, g=g,
        name=ah1.stem, provenance=prov, drift=D,
    )


# ------------------------------------------------------------------------------------ tokens
class _Block:
    """The numbers of one keyword block (or the header) as a token stream with line numbers."""

    def __init__(self, tf: TextFile, name: str, line: int, items: list[tuple[str, int]]):
        self.tf, self.name, self.line, self.items, self.pos = tf, name, line, items, 0

    def error(self, message: str, at: int | None = None) -> HydroDataError:
        if at is None:
            at = self.items[min(self.pos, len(self.items) - 1)][1] if self.items else self.line
        return self.tf.error(at, f"{self.name}: {message}")

    def _take(self, k: int, what: str) -> list[tuple[str, int]]:
        if self.pos + k > len(self.items):
            last = self.items[-1][1] if self.items else self.line
            raise self.error(f"ends early; expected {what} (truncated file?)", at=last)
        out = self.items[self.pos:self.pos + k]
        self.pos += k
        return out

    def integer(self, what: str, lo: int | None = None, hi: int | None = None) -> int:
        (tok, n), = self._take(1, what)
        return self.tf.integer(n, tok, what=f"{what} in {self.name}", lo=lo, hi=hi)

    def floats(self, k: int, what: str) -> np.ndarray:
        items = self._take(k, f"{k} values for {what}")
        out = np.empty(k)
        for idx, (tok, n) in enumerate(items):
            out[idx] = self.tf.numbers(n, [tok], what=f"{what} in {self.name}")[0]
        return out

    def done(self, what: str) -> None:
        if self.pos < len(self.items):
            tok, n = self.items[self.pos]
            raise self.tf.error(n, f"{self.name}: unexpected value {tok!r} after {what}")


def _split(tf: TextFile) -> tuple[list[str], _Block, dict[str, _Block]]:
    """Comment lines, the header token stream, and the keyword blocks."""
    comments: list[str] = []
    header: list[tuple[str, int]] = []
    blocks: dict[str, _Block] = {}
    current = None
    for n, line in enumerate(tf.lines, start=1):
        s = line.strip()
        if not s:
            continue
        if s.startswith("*"):
            if current is None and not header:
                comments.append(s.lstrip("* "))
                continue
            raise tf.error(n, "comment line inside the data; expected comments only at the top")
        first = s.split()[0]
        if re.fullmatch(r"[A-Z][A-Z0-9_]+", first):
            if not header:
                raise tf.error(n, f"found {first!r} where the header 'nbody ndir nfreq directions...' "
                                  "belongs; expected an AQWA .AH1 file")
            if first in blocks:
                raise tf.error(n, f"second {first} block (first on line {blocks[first].line})")
            current = blocks[first] = _Block(tf, first, n, [])
            rest = s.split()[1:]
            current.items += [(t, n) for t in rest]
            continue
        items = [(t, n) for t in s.split()]
        if current is None:
            header += items
        else:
            current.items += items
    if not header:
        raise tf.error(None, "no header line 'nbody ndir nfreq directions...'; expected an AQWA .AH1 file")
    return comments, _Block(tf, "header", header[0][1], header), blocks


def _check_frequencies(tf: TextFile, header: _Block, omega: np.ndarray) -> None:
    lines = [n for _, n in header.items[-omega.size:]]
    if np.any(omega <= 0):
        k = int(np.argmax(omega <= 0))
        raise tf.error(lines[k], f"header: frequency {omega[k]:g} rad/s; expected values > 0")
    values, counts = np.unique(omega, return_counts=True)
    if np.any(counts > 1):
        k = np.flatnonzero(omega == values[counts > 1][0])[1]
        raise tf.error(lines[k], f"header: frequency {omega[k]:g} rad/s appears twice")


def _general(block: _Block) -> tuple[float, float, float]:
    """Depth, ρ, g from GENERAL (with or without the leading body number)."""
    if len(block.items) >= 4 and re.fullmatch(r"\d+", block.items[0][0]):
        block.integer("the body number", lo=1, hi=1)
    depth, rho, g = block.floats(3, "depth, ρ and g")
    if not 9.7 <= g <= 9.9 or not 900.0 <= rho <= 1100.0 or depth <= 0:
        raise block.error(f"depth {depth:g}, ρ {rho:g}, g {g:g}: expected SI units (kg, m: ρ ≈ 1000–1030 kg/m³, "
                          "g ≈ 9.81 m/s², depth > 0)", at=block.line)
    return depth, rho, g


def _vector(blocks: dict, key: str, k: int, notes: list[str], what: str) -> np.ndarray:
    if key not in blocks:
        notes.append(f"no {key} block: {what} unknown (set to 0)")
        return np.zeros(k)
    block = blocks[key]
    block.integer("the body number", lo=1, hi=1)
    v = block.floats(k, what)
    block.done(what)
    return v


def _matrix(block: _Block, n_index: int) -> np.ndarray:
    for w in ("the body number", "the second body number")[:n_index]:
        block.integer(w, lo=1, hi=1)
    M = block.floats(36, "a 6×6 matrix").reshape(6, 6)
    block.done("the 6×6 matrix")
    return M


def _per_frequency(block: _Block, nf: int) -> list[np.ndarray]:
    """ADDEDMASS / DAMPING: one 6×6 per frequency index, each exactly once."""
    out: list[np.ndarray | None] = [None] * nf
    for _ in range(nf):
        block.integer("the body number", lo=1, hi=1)
        block.integer("the second body number", lo=1, hi=1)
        line = block.items[min(block.pos, len(block.items) - 1)][1]
        k = block.integer("the frequency index", lo=1, hi=nf) - 1
        if out[k] is not None:
            raise block.error(f"frequency index {k + 1} appears twice", at=line)
        out[k] = block.floats(36, f"the 6×6 matrix at frequency {k + 1}").reshape(6, 6)
    block.done(f"{nf} frequencies")
    return out


def _records(block: _Block, ndir: int, nf: int):
    """The (direction, frequency) indices of the ``ndir × nf`` records of a block (body, direction and frequency
    numbers, then the record's values, read by the caller), each pair once."""
    seen = np.zeros((ndir, nf), dtype=bool)
    for _ in range(ndir * nf):
        block.integer("the body number", lo=1, hi=1)
        line = block.items[min(block.pos, len(block.items) - 1)][1]
        d = block.integer("the direction index", lo=1, hi=ndir) - 1
        k = block.integer("the frequency index", lo=1, hi=nf) - 1
        if seen[d, k]:
            raise block.error(f"direction {d + 1}, frequency {k + 1} appears twice", at=line)
        seen[d, k] = True
        yield d, k
    block.done(f"{ndir} directions × {nf} frequencies")


def _excitation(block: _Block, ndir: int, nf: int) -> np.ndarray:
    """FORCERAO → X (6, ndir, nf), conjugated from AQWA's phase lags to boatland's leads."""
    X = np.zeros((6, ndir, nf), dtype=complex)
    for d, k in _records(block, ndir, nf):
        amp = block.floats(6, "6 force amplitudes")
        phase = block.floats(6, "6 phases [deg]")
        X[:, d, k] = amp * np.exp(-1j * np.deg2rad(phase))
    return X


def _mean_drift(choice: str, blocks: dict, lis: TextFile | None, beta_in: np.ndarray, omega: np.ndarray,
                ndir: int, nf: int, notes: list[str]) -> np.ndarray | None:
    """Mean drift (6, ndir, nf) in the file's direction and frequency order, from the .LIS tables or the
    FARFIELD block as ``choice`` says (module docstring); None when neither is there or asked for."""
    if choice in ("auto", "pressure") and lis is not None:
        D = _lis_drift(lis, beta_in, omega)
        if D is not None:
            near = np.any(D[2:5] != 0)
            notes.append(f"mean drift: the wave-drift tables of {lis.path.name} ("
                         + ("near-field pressure integration: all six DOFs" if near else
                            "surge, sway and yaw only; heave, roll, pitch 0")
                         + "), 3 significant digits, moments about the COG")
            return D
    if choice in ("auto", "momentum") and "FARFIELD" in blocks:
        D = _farfield(blocks["FARFIELD"], ndir, nf)
        notes.append("mean drift: the FARFIELD block of the .AH1 (AQWA's far-field momentum method): surge, sway "
                     "and yaw only — heave, roll and pitch drift 0 (not computed), moments about the COG")
        return D
    if choice == "pressure":
        notes.append("mean drift: none read (no wave-drift tables in a .LIS beside the .AH1)")
    return None


def _farfield(block: _Block, ndir: int, nf: int) -> np.ndarray:
    """FARFIELD → (6, ndir, nf): per (direction, frequency) index Fx Fy Fz Mx My Mz."""
    D = np.zeros((6, ndir, nf))
    for d, k in _records(block, ndir, nf):
        D[:, d, k] = block.floats(6, "6 mean drift forces and moments")
    return D


def _lis_drift(lis: TextFile, beta_in: np.ndarray, omega: np.ndarray) -> np.ndarray | None:
    """The .LIS wave-drift tables of structure 1 → (6, ndir, nf) at the .AH1's directions and frequencies;
    None when the listing has none."""
    lines = lis.lines
    D = np.full((6, beta_in.size, omega.size), np.nan)
    found = False
    n = 0
    while n < len(lines):
        if "W A V E - D R I F T" not in lines[n]:
            n += 1
            continue
        head = n
        n += 1
        dirs = None
        while n < len(lines) and dirs is None:
            if "DUE TO" in lines[n] and "RADIANS/SEC" in lines[n]:
                tokens = lines[n].split("(RADIANS/SEC)", 1)[1].split()
                dirs = lis.numbers(n + 1, tokens, what="wave directions [deg]")
            n += 1
        while n < len(lines) and _rule(lines[n]):
            n += 1
        if n >= len(lines) or lines[n].strip() != "DRIFT":
            continue                                   # forces due to something else (none in the files seen)
        n += 1
        while n < len(lines) and _rule(lines[n]):
            n += 1
        label = lines[n].strip() if n < len(lines) else ""
        if label not in _DRIFT_DOFS:
            raise lis.error(n + 1, f"wave-drift table (line {head + 1}): expected one of {', '.join(_DRIFT_DOFS)}, "
                                   f"found {label!r:.30}")
        i = _DRIFT_DOFS.index(label)
        cols = []
        for b in dirs:
            match = np.flatnonzero(np.abs(beta_in - b) <= 0.05)
            if match.size != 1:
                raise lis.error(n + 1, f"wave-drift table: direction {b:g}° is not one of the .AH1's "
                                       f"({', '.join(f'{x:g}' for x in beta_in)}°)")
            cols.append(int(match[0]))
        n += 1
        while n < len(lines):
            tokens = lines[n].split()
            if len(tokens) != 1 + len(dirs) or not _looks_numeric(tokens):
                break
            vals = lis.numbers(n + 1, tokens, what="a frequency and mean drift values")
            k = np.flatnonzero(np.abs(omega - vals[0]) <= 5.001e-4)
            if k.size != 1:
                raise lis.error(n + 1, f"wave-drift table: frequency {vals[0]:g} rad/s is not one of the .AH1's")
            D[i, cols, k[0]] = vals[1:]
            found = True
            n += 1
    if not found:
        return None
    if np.any(np.isnan(D)):
        i, b, k = np.argwhere(np.isnan(D))[0]
        raise lis.error(None, f"wave-drift tables: no {_DRIFT_DOFS[i]} value at {beta_in[b]:g}°, "
                              f"{omega[k]:.4g} rad/s (truncated listing?)")
    return D


def _rule(line: str) -> bool:
    """A blank line or a line of dashes (table rules)."""
    return set(line.strip()) <= {"-", " "}


def _looks_numeric(tokens: list[str]) -> bool:
    try:
        [float(t) for t in tokens]
    except ValueError:
        return False
    return True


def _floats_lenient(block: _Block) -> np.ndarray:
    vals = []
    for tok, _ in block.items:
        try:
            vals.append(float(tok))
        except ValueError:
            pass
    return np.array(vals)


def _limit_frequencies(comments: list[str]) -> tuple[str | None, str | None]:
    """The low and high frequencies of the *_LF / *_HF blocks, from the header comment."""
    text = " ".join(comments).upper().replace("- ", "-")
    lf = re.search(r"LOW-?\s*FREQUENCY\s*\(\s*([\d.]+)\s*RAD/S", text)
    hf = re.search(r"HIGH-?\s*FREQUENCY\s*\(\s*([\d.]+)\s*RAD/S", text)
    return (lf.group(1) if lf else None), (hf.group(1) if hf else None)


def _created(comments: list[str]) -> str:
    """ISO date of the run from ``DATE:dd/mm/yy TIME:hh:mm:ss`` (AQWA writes day/month/year)."""
    mt = re.search(r"DATE:\s*(\d{2}/\d{2}/\d{2})\s+TIME:\s*(\d{2}:\d{2}:\d{2})", " ".join(comments))
    if not mt:
        return ""
    try:
        return datetime.strptime(f"{mt.group(1)} {mt.group(2)}", "%d/%m/%y %H:%M:%S").isoformat()
    except ValueError:
        return f"{mt.group(1)} {mt.group(2)}"


# ------------------------------------------------------------------------------------ mass
def _mass(blocks: dict, lis: TextFile | None, cog: np.ndarray, notes: list[str]) -> np.ndarray | None:
    """Rigid-body mass matrix about the COG (= the reference point)."""
    if "MASS" in blocks:
        Mf = _matrix(blocks["MASS"], 1)
        mass, inertia = Mf[0, 0], Mf[3:, 3:]
        if mass <= 0:
            raise blocks["MASS"].error(f"mass {mass:g} kg; expected > 0", at=blocks["MASS"].line)
        M = rigid_body_mass_matrix(mass, cog, inertia, ref_point=cog)
        off = max(np.max(np.abs(Mf[:3, 3:])), np.max(np.abs(Mf[:3, :3] - mass * np.eye(3))))
        if off > 1e-6 * mass:
            notes.append("MASS block is not a rigid-body mass matrix about the COG: used its mass and inertia only")
        return M
    found = _lis_mass(lis) if lis is not None else None
    if found is None:
        notes.append("no MASS block (and none in a .LIS): mass matrix unknown")
        return None
    mass, inertia = found
    notes.append(f"mass and inertia from {lis.path.name} (no MASS block in the .AH1)")
    return rigid_body_mass_matrix(mass, cog, inertia, ref_point=cog)


def _lis_units(lis: TextFile | None, notes: list[str]) -> bool | None:
    """True/False when the .LIS states the unit system is/is not kg, m; None when unknown."""
    if lis is None:
        notes.append("no .LIS beside the .AH1: SI units (kg, m) assumed")
        return None
    for line in lis.lines[:200]:
        if "Unit System" in line:
            return bool(re.search(r"kg,\s*m\b", line))
    return None


def _lis_mass(lis: TextFile) -> tuple[float, np.ndarray] | None:
    """Total mass and inertia matrix of structure 1 from the .LIS 'MASS AND INERTIA' table."""
    num = r"[-+]?\d*\.?\d+(?:[EeDd][-+]?\d+)?"
    mass = inertia = None
    lines = lis.lines
    for n, line in enumerate(lines):
        mt = re.search(r"T O T A L\s+\d+\s+(" + num + ")", line)
        if mt and mass is None:
            mass = float(mt.group(1))
        if "INERTIA MATRIX" in line and mass is not None:
            rows = [line.split("INERTIA MATRIX")[1]]
            rows += [s for s in lines[n + 1:n + 8] if s.strip()][:2]
            try:
                inertia = np.array([[float(t) for t in r.split()[:3]] for r in rows])
            except ValueError:
                return None
            break
    if mass is None or inertia is None or inertia.shape != (3, 3):
        return None
    return mass, inertia
