r"""WAMIT output (``.1``, ``.3``, ``.hst``, ``.out``) → :class:`~boatland.vessel.database.HydroDB`.

Format (WAMIT User Manual v7, ch. 4 "Output"; notes/hydro-formats.md):

- ``.1``  ``PER I J Abar [Bbar]``: added mass and damping; ``PER = -1`` is ω = 0 (A₀, no B),
  ``PER = 0`` is ω = ∞ (A∞, no B), otherwise PER is the wave period [s]. Entries that are zero may
  be left out.
- ``.3``  ``PER BETA I Mod Pha Re Im``: diffraction excitation, β in degrees (direction of travel).
- ``.hst`` ``I J Cbar``: hydrostatic and gravitational restoring.
- ``.out`` (optional): gravity, length scale ULEN, water depth, body position, volumes, centres.
- ``.8`` / ``.9`` (optional) ``PER BETA1 BETA2 I Mod Pha Re Im``: mean drift forces by momentum
  conservation (far field: I = 1, 2, 6 only) and by pressure integration (near field: I = 1..6, and
  I = −4, −5, −6 for the moments in body-fixed axes, which are not read: the positive modes are in the
  mean-position axes, as X and the ``.8``). Only rows with BETA1 = BETA2 (unidirectional waves) are
  read; the mean drift is the real part ``Re`` (WAMIT User Manual v7, §4.8–4.9). When both files exist
  the ``.9`` is used by default (it gives all six DOFs); ``drift="momentum"`` takes the ``.8``, which is
  often the more accurate in surge, sway and yaw; ``drift="none"`` reads neither.

Every file may start with a one-line text header (WEC-Sim's do, OpenFAST's do not): both are read.

Units: WAMIT stores everything non-dimensional with ρ, g and ULEN = L. With ``k = 3, 4, 5`` for
translation–translation, mixed and rotation–rotation pairs and ``m = k − 1`` for ``C``,
``m = 2`` (forces) or ``3`` (moments) for ``X``:

.. math::
    A = \bar A \rho L^k, \qquad B = \bar B \rho \omega L^k, \qquad
    C = \bar C \rho g L^{m}, \qquad X = \bar X \rho g L^{m}, \qquad
    \bar F = \bar F_{wamit}\,\rho g L^{m - 1}

(the mean drift per unit wave amplitude squared, :math:`m - 1 = 1` for forces, 2 for moments).

WAMIT uses exp(+iωt) with phases referred to the incident wave at the origin of its global frame,
which is boatland's convention: no conjugation. Points (reference point, centres) are reported in a
frame with z = 0 on the calm waterline: WAMIT's body-frame coordinates shifted by ZBODY.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path

import numpy as np

from boatland.conventions import DOF_NAMES
from boatland.errors import HydroDataError
from boatland.hydro._text import TextFile, build_db, find_sibling, is_number, normalise_directions
from boatland.vessel.database import HydroDB, Provenance

__all__ = ["read_wamit"]

_SUFFIXES = (".1", ".3", ".hst", ".out", ".8", ".9")
#: ``drift=`` choices: mean drift file used, in order of preference.
DRIFT_FILES = {"auto": (".9", ".8"), "pressure": (".9",), "momentum": (".8",), "none": ()}
RHO_DEFAULT = 1025.0
G_DEFAULT = 9.81

#: Exponent k of the length scale in A and B for DOF pair (i, j): 3 + (i rotational) + (j rotational).
_K = 3 + (np.arange(6)[:, None] >= 3) + (np.arange(6)[None, :] >= 3)


def read_wamit(path: str | Path, rho: float | None = None, g: float | None = None,
               drift: str = "auto") -> HydroDB:
    """Read a WAMIT run (``.1`` + ``.3`` + ``.hst``, optional ``.out``, ``.8``, ``.9``) into a :class:`HydroDB`.

    Parameters
    ----------
    path : str or Path
        Any of the run's ``.1``, ``.3``, ``.hst``, ``.out``, ``.8`` or ``.9`` files; the others are found
        beside it by their common stem.
    rho : float, optional
        Water density [kg/m³]. WAMIT files do not store it; default 1025 (with a provenance note).
    g : float, optional
        Gravity [m/s²], used only when there is no ``.out`` file (the ``.out`` value is the one
        WAMIT non-dimensionalised with); default 9.81 with a note.
    drift : {"auto", "pressure", "momentum", "none"}
        Which mean drift file fills ``HydroDB.drift`` when it is beside the run: ``"auto"`` the ``.9``
        (pressure integration, six DOFs) else the ``.8`` (momentum conservation: surge, sway, yaw; the
        others 0); ``"pressure"`` / ``"momentum"`` only that one; ``"none"`` neither. A provenance note
        says which was read.

    Returns
    -------
    HydroDB
        Dimensional SI database, exp(+iωt), ω ascending; ``A_0``/``A_inf`` from the PER = −1 / 0
        rows when present; ``M`` is None (WAMIT output holds no mass matrix).

    Raises
    ------
    HydroDataError
        A file is missing (``.1`` and ``.3`` are required, ``.hst`` unless the ``.out`` has the
        restoring coefficients) or malformed; the message names the file and line.
    """
    path = Path(path)
    if drift not in DRIFT_FILES:
        raise HydroDataError(path, "drift", f"unknown choice {drift!r}; expected one of {', '.join(DRIFT_FILES)}")
    if path.suffix.lower() not in _SUFFIXES:
        raise HydroDataError(path, None, f"not a WAMIT output file; expected one of {', '.join(_SUFFIXES)}")
    if not path.exists():
        raise HydroDataError(path, None, "file not found")
    files = {s: find_sibling(path, s) for s in _SUFFIXES}
    notes: list[str] = []
    stem = path.with_suffix("")

    if files[".out"] is not None:
        out = _read_out(TextFile(files[".out"], "WAMIT .out log"))
    else:
        out = _OutInfo()
        notes.append(f"no {stem.name}.out beside the run: length scale ULEN = 1, water depth infinite, "
                     "reference point, centres and volume unknown (set to 0)")
    if out.g is None:
        out.g = G_DEFAULT if g is None else float(g)
        if g is None:
            notes.append(f"gravity not known without the .out: assumed g = {G_DEFAULT} m/s² (pass g=...)")
    elif g is not None and not np.isclose(g, out.g, rtol=1e-6):
        notes.append(f"g = {g} passed but {files['.out'].name} says {out.g}: used the .out value "
                     "(WAMIT non-dimensionalised with it)")
    if rho is None:
        rho = RHO_DEFAULT
        notes.append("ρ not stored in WAMIT files: assumed 1025 kg/m³ (pass rho=...)")
    rho, gg, L = float(rho), float(out.g), float(out.ulen)
    if not (np.isfinite(rho) and rho > 0):
        raise HydroDataError(path, "rho", f"expected a density > 0 kg/m³, got {rho!r}")

    for suffix, what in ((".1", "WAMIT .1 file (added mass and damping)"),
                         (".3", "WAMIT .3 file (diffraction excitation forces)")):
        if files[suffix] is None:
            raise HydroDataError(stem.with_suffix(suffix), None, f"file not found; expected the {what} "
                                                                 f"beside {path.name}")
    rad = _read_radiation(TextFile(files[".1"], "WAMIT .1 file (added mass and damping)"))
    periods = np.array(sorted(rad.periods, key=lambda T: -T))          # ω ascending
    omega = 2 * np.pi / periods
    exc = _read_excitation(TextFile(files[".3"], "WAMIT .3 file (diffraction excitation forces)"), periods)

    if files[".hst"] is not None:
        Cbar = _read_hst(TextFile(files[".hst"], "WAMIT .hst file (hydrostatic restoring)"))
    elif out.Cbar is not None:
        Cbar = out.Cbar
        notes.append(f"no {stem.name}.hst: restoring coefficients taken from the .out")
    else:
        raise HydroDataError(stem.with_suffix(".hst"), None, "file not found; expected the WAMIT .hst file "
                                                             "(hydrostatic restoring), and the .out has none")

    A = np.stack([rad.A[T] for T in periods], axis=-1) * rho * L ** _K[:, :, None]
    B = np.stack([rad.B[T] for T in periods], axis=-1) * rho * omega * L ** _K[:, :, None]
    A_inf = None if rad.A_inf is None else rad.A_inf * rho * L ** _K
    A_0 = None if rad.A_0 is None else rad.A_0 * rho * L ** _K
    C = Cbar * rho * gg * L ** (_K - 1)
    m = np.where(np.arange(6) >= 3, 3, 2)
    X = exc.Xbar * rho * gg * L ** m[:, None, None]
    beta, keep, groups = normalise_directions(exc.beta)
    X = _merge_directions(X, beta, keep, groups, exc.beta, notes)
    mean_drift = None
    for suffix in DRIFT_FILES[drift]:
        if files[suffix] is not None:
            mean_drift = _read_drift(TextFile(files[suffix], _DRIFT_WHAT[suffix]), periods, exc.beta, notes)
            mean_drift = mean_drift[:, keep] * rho * gg * L ** (m[:, None, None] - 1)
            break

    notes += out.notes
    if out.ulen_missing and files[".out"] is not None:
        notes.append("no 'Length scale' in the .out: ULEN = 1 assumed")
    z0 = np.array([0.0, 0.0, out.body_pos[2]])
    prov = Provenance(source=str(path), solver="WAMIT", created=out.created or rad.created,
                      reader="wamit", notes=tuple(notes))
    return build_db(
        path, omega=omega, A=A, B=B, X=X, wave_dir_deg=beta, C=C, A_inf=A_inf, A_0=A_0, M=None,
        ref_point=z0, cog=out.cog + z0, cob=out.cob + z0, disp_vol=out.volume,
        water_depth=out.depth, rho=rho, g=gg, name=stem.name, provenance=prov, drift=mean_drift,
    )


# --------------------------------------------------------------------------------------- .out
@dataclass
class _OutInfo:
    g: float | None = None
    ulen: float = 1.0
    ulen_missing: bool = True
    depth: float = np.inf
    volume: float = 0.0
    cog: np.ndarray = field(default_factory=lambda: np.zeros(3))
    cob: np.ndarray = field(default_factory=lambda: np.zeros(3))
    body_pos: np.ndarray = field(default_factory=lambda: np.zeros(4))   # XBODY YBODY ZBODY PHIBODY
    Cbar: np.ndarray | None = None
    created: str = ""
    notes: list[str] = field(default_factory=list)


_NUM = r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?)"
_OUT_PATTERNS = {
    "g": re.compile(r"Gravity:\s*" + _NUM),
    "ulen": re.compile(r"Length scale:\s*" + _NUM),
    "depth": re.compile(r"Water depth:\s*(\S+)"),
    "volume": re.compile(r"Volumes \(VOLX,VOLY,VOLZ\):\s*" + r"\s+".join([_NUM] * 3)),
    "cob": re.compile(r"Center of Buoyancy \(Xb,Yb,Zb\):\s*" + r"\s+".join([_NUM] * 3)),
    "cog": re.compile(r"Center of Gravity\s+\(Xg,Yg,Zg\):\s*" + r"\s+".join([_NUM] * 3)),
    "body": re.compile(r"XBODY =\s*" + _NUM + r"\s+YBODY =\s*" + _NUM + r"\s+ZBODY =\s*" + _NUM
                       + r"\s+PHIBODY =\s*" + _NUM),
    "date": re.compile(r"POTEN run date and starting time:\s*(\S+)\s*--\s*(\S+)"),
    "C": re.compile(r"C\((\d),(\d)\)(?:,C\(\d,\d\))*:\s*(.*)$"),
}


def _read_out(tf: TextFile) -> _OutInfo:
    """Scalars and centres from the ``.out`` log (the first occurrence of each; one body only)."""
    info = _OutInfo()
    n_bodies = 0
    Cbar = np.zeros((6, 6))
    found_C = False
    for n, line in enumerate(tf.lines, start=1):
        if "Output from  WAMIT" in line or "Wave period" in line:
            break                                    # the header is over; the rest is per frequency
        for key, pat in _OUT_PATTERNS.items():
            mt = pat.search(line)
            if not mt:
                continue
            if key == "date":
                info.created = _iso_date(mt.group(1), mt.group(2))
            elif key == "depth":
                text = mt.group(1).lower()
                info.depth = np.inf if text.startswith("inf") else float(tf.numbers(n, [text], what="a depth")[0])
            elif key == "C":
                i, j0 = int(mt.group(1)) - 1, int(mt.group(2)) - 1
                vals = tf.numbers(n, mt.group(3).split(), what="restoring coefficients")
                for j, v in zip(range(j0, 6), vals):
                    Cbar[i, j] = Cbar[j, i] = v
                found_C = True
            else:
                vals = tf.numbers(n, list(mt.groups()), what=f"numbers after {pat.pattern.split(':')[0][:20]!r}")
                if key == "body":
                    n_bodies += 1
                    if n_bodies == 1:
                        info.body_pos = vals
                elif key == "g":
                    info.g = float(vals[0])
                elif key == "ulen":
                    info.ulen, info.ulen_missing = float(vals[0]), False
                elif key == "volume":
                    info.volume = float(vals[2])
                else:
                    setattr(info, key, vals)
    if n_bodies > 1:
        raise tf.error(None, f"{n_bodies} bodies in this run; boatland reads single-body WAMIT runs only")
    if found_C:
        info.Cbar = Cbar
    if info.g is not None and info.g <= 0:
        raise tf.error(None, f"gravity = {info.g} must be > 0")
    if info.ulen <= 0:
        raise tf.error(None, f"length scale ULEN = {info.ulen} must be > 0")
    x, y, _, phi = info.body_pos
    if x or y:
        info.notes.append(f"XBODY, YBODY = {x:g}, {y:g} m: excitation phases are referred to WAMIT's global "
                          "origin, not to the reference point")
    if phi:
        info.notes.append(f"PHIBODY = {phi:g}°: wave headings are relative to WAMIT's global x axis, "
                          "not the body's")
    return info


def _iso_date(day: str, time: str) -> str:
    try:
        return datetime.strptime(f"{day} {time}", "%d-%b-%Y %H:%M:%S").isoformat()
    except ValueError:
        return f"{day} {time}"


# --------------------------------------------------------------------------------------- .1 / .3 / .hst
@dataclass
class _Radiation:
    A: dict = field(default_factory=dict)          # period → (6, 6) Abar
    B: dict = field(default_factory=dict)          # period → (6, 6) Bbar
    A_inf: np.ndarray | None = None
    A_0: np.ndarray | None = None
    created: str = ""

    @property
    def periods(self):
        return list(self.A)


def _data_lines(tf: TextFile):
    """(line number, tokens) of the data lines: blank lines skipped, a text header on line 1 allowed."""
    for n, line in enumerate(tf.lines, start=1):
        tokens = line.split()
        if not tokens:
            continue
        if n == 1 and not is_number(tokens[0]):
            continue                                 # "WAMIT Numeric Output -- Filename ..." header
        yield n, tokens


def _header_date(tf: TextFile) -> str:
    mt = re.search(r"(\d{1,2}-[A-Za-z]{3}-\d{4})\s+(\d{2}:\d{2}:\d{2})", tf.lines[0]) if tf.lines else None
    return _iso_date(mt.group(1), mt.group(2)) if mt else ""


def _dof(tf: TextFile, n: int, token: str, what: str) -> int:
    k = tf.integer(n, token, what=what, lo=1)
    if k > 6:
        raise tf.error(n, f"{what} = {k}: multi-body or generalised-mode WAMIT runs are not supported "
                          "(expected 1..6)")
    return k - 1


def _read_radiation(tf: TextFile) -> _Radiation:
    rad = _Radiation(created=_header_date(tf))
    seen: dict[tuple, int] = {}
    for n, tokens in _data_lines(tf):
        if len(tokens) not in (4, 5):
            raise tf.error(n, f"expected 'PER I J Abar Bbar' (4 or 5 columns), found {len(tokens)} columns")
        per = float(tf.numbers(n, tokens[:1], what="a period PER")[0])
        i, j = _dof(tf, n, tokens[1], "I"), _dof(tf, n, tokens[2], "J")
        vals = tf.numbers(n, tokens[3:], what="added mass and damping")
        key = (per, i, j)
        if key in seen:
            raise tf.error(n, f"duplicate entry PER={per:g}, I={i + 1}, J={j + 1} (first on line {seen[key]}); "
                              "each frequency must appear once")
        seen[key] = n
        if per == -1.0 or per == 0.0:
            target = "A_0" if per == -1.0 else "A_inf"
            if getattr(rad, target) is None:
                setattr(rad, target, np.zeros((6, 6)))
            getattr(rad, target)[i, j] = vals[0]
        elif per > 0:
            if len(vals) != 2:
                raise tf.error(n, f"expected 'PER I J Abar Bbar' with the damping Bbar at PER={per:g}, "
                                  "found 4 columns")
            if per not in rad.A:
                rad.A[per], rad.B[per] = np.zeros((6, 6)), np.zeros((6, 6))
            rad.A[per][i, j], rad.B[per][i, j] = vals
        else:
            raise tf.error(n, f"period PER = {per:g}: expected a period > 0 s, -1 (ω = 0) or 0 (ω = ∞)")
    if not rad.A:
        raise tf.error(None, "no data rows at a finite frequency; expected lines 'PER I J Abar Bbar'")
    return rad


@dataclass
class _Excitation:
    Xbar: np.ndarray          # (6, Nb_in, Nf) complex
    beta: np.ndarray          # (Nb_in,) deg, as in the file


def _read_excitation(tf: TextFile, periods: np.ndarray) -> _Excitation:
    rows = []
    for n, tokens in _data_lines(tf):
        if len(tokens) != 7:
            raise tf.error(n, f"expected 'PER BETA I Mod Pha Re Im' (7 columns), found {len(tokens)} columns")
        per, beta = tf.numbers(n, tokens[:2], what="PER and BETA")
        i = _dof(tf, n, tokens[2], "I")
        re_, im_ = tf.numbers(n, tokens[5:7], what="Re and Im of the excitation")
        tf.numbers(n, tokens[3:5], what="Mod and Pha of the excitation")
        rows.append((n, per, beta, i, re_ + 1j * im_))
    if not rows:
        raise tf.error(None, "no data rows; expected lines 'PER BETA I Mod Pha Re Im'")
    betas = list(dict.fromkeys(r[2] for r in rows))          # in order of appearance
    b_index = {b: k for k, b in enumerate(betas)}
    Xbar = np.zeros((6, len(betas), periods.size), dtype=complex)
    filled = np.zeros((len(betas), periods.size), dtype=bool)
    seen: dict[tuple, int] = {}
    for n, per, beta, i, x in rows:
        k = np.flatnonzero(np.isclose(periods, per, rtol=1e-6, atol=0))
        if k.size != 1:
            raise tf.error(n, f"period PER = {per:g} s is not among the .1 file's periods; the .1 and .3 "
                              "files must come from the same run")
        b = b_index[beta]
        key = (int(k[0]), b, i)
        if key in seen:
            raise tf.error(n, f"duplicate entry PER={per:g}, BETA={beta:g}, I={i + 1} (first on line {seen[key]})")
        seen[key] = n
        Xbar[i, b, k[0]] = x
        filled[b, k[0]] = True
    if not filled.all():
        b, k = np.argwhere(~filled)[0]
        raise tf.error(rows[-1][0], f"the data end here without excitation at PER = {periods[k]:g} s, "
                                    f"BETA = {betas[b]:g}°, which the .1 file has (truncated file, or .1 and "
                                    ".3 from different runs?)")
    return _Excitation(Xbar=Xbar, beta=np.array(betas))


_DRIFT_WHAT = {".8": "WAMIT .8 file (mean drift forces, momentum conservation)",
               ".9": "WAMIT .9 file (mean drift forces, pressure integration)"}


def _read_drift(tf: TextFile, periods: np.ndarray, betas_x, notes: list[str]) -> np.ndarray:
    """Mean drift (6, Nb_in, Nf), non-dimensional, at the ``.3`` file's directions ``betas_x`` (as in that
    file) and the ``.1`` file's ``periods``; DOFs the file does not give are 0."""
    rows, skipped_pairs, body_fixed = [], 0, 0
    for n, tokens in _data_lines(tf):
        if len(tokens) != 8:
            raise tf.error(n, f"expected 'PER BETA1 BETA2 I Mod Pha Re Im' (8 columns), found {len(tokens)} columns")
        per, b1, b2 = tf.numbers(n, tokens[:3], what="PER, BETA1 and BETA2")
        i = tf.integer(n, tokens[3], what="I")
        tf.numbers(n, tokens[4:6], what="Mod and Pha of the drift force")
        re_ = tf.numbers(n, tokens[6:7], what="Re of the drift force")[0]
        tf.numbers(n, tokens[7:8], what="Im of the drift force")
        if b1 != b2:
            skipped_pairs += 1
            continue
        if i < 0:
            body_fixed += 1
            continue
        if not 1 <= i <= 6:
            raise tf.error(n, f"I = {i}: multi-body or generalised-mode WAMIT runs are not supported (expected 1..6)")
        rows.append((n, per, b1, i - 1, re_))
    if not rows:
        raise tf.error(None, "no data rows with BETA1 = BETA2; expected lines 'PER BETA1 BETA2 I Mod Pha Re Im' "
                             "(run WAMIT with IOPTN(8/9) = 1 for unidirectional drift)")
    betas = list(betas_x)
    D = np.zeros((6, len(betas), periods.size))
    filled = np.zeros((len(betas), periods.size), dtype=bool)
    dofs, seen = set(), {}
    for n, per, beta, i, value in rows:
        k = np.flatnonzero(np.isclose(periods, per, rtol=1e-6, atol=0))
        if k.size != 1:
            raise tf.error(n, f"period PER = {per:g} s is not among the .1 file's periods; the drift and "
                              "radiation files must come from the same run")
        b = [j for j, bx in enumerate(betas) if abs(bx - beta) <= 1e-6 * max(1.0, abs(beta))]
        if not b:
            raise tf.error(n, f"BETA = {beta:g}° is not among the .3 file's directions "
                              f"({', '.join(f'{x:g}' for x in betas)}°)")
        key = (int(k[0]), b[0], i)
        if key in seen:
            raise tf.error(n, f"duplicate entry PER={per:g}, BETA={beta:g}, I={i + 1} (first on line {seen[key]})")
        seen[key] = n
        D[i, b[0], k[0]] = value
        filled[b[0], k[0]] = True
        dofs.add(i)
    if not filled.all():
        b, k = np.argwhere(~filled)[0]
        raise tf.error(rows[-1][0], f"the data end here without drift at PER = {periods[k]:g} s, BETA = "
                                    f"{betas[b]:g}°, which the .1 and .3 files have (truncated file, or files "
                                    "from different runs?)")
    method = "pressure integration (near field)" if tf.path.suffix == ".9" else "momentum conservation (far field)"
    given = ", ".join(DOF_NAMES[i] for i in sorted(dofs))
    zero = [DOF_NAMES[i] for i in range(6) if i not in dofs]
    notes.append(f"mean drift: WAMIT {method} from {tf.path.name}, real part of the BETA1 = BETA2 rows, in "
                 f"mean-position axes; DOFs given: {given}"
                 + (f"; {', '.join(zero)} not in the file (0)" if zero else "")
                 + (f"; {body_fixed} body-fixed moment rows (I < 0) not read" if body_fixed else "")
                 + (f"; {skipped_pairs} bidirectional rows (BETA1 ≠ BETA2) not read" if skipped_pairs else ""))
    return D


def _read_hst(tf: TextFile) -> np.ndarray:
    C = np.zeros((6, 6))
    for n, tokens in _data_lines(tf):
        if len(tokens) != 3:
            raise tf.error(n, f"expected 'I J Cbar' (3 columns), found {len(tokens)} columns")
        i, j = _dof(tf, n, tokens[0], "I"), _dof(tf, n, tokens[1], "J")
        C[i, j] = tf.numbers(n, tokens[2:], what="a restoring coefficient")[0]
    return C


def _merge_directions(X, beta, keep, groups, beta_in, notes) -> np.ndarray:
    """Keep one copy of directions that are the same modulo 360°, after checking the copies agree."""
    for g in groups:
        if g.size > 1:
            spread = np.max(np.abs(X[:, g] - X[:, g[:1]]))
            scale = max(np.max(np.abs(X[:, g[:1]])), 1e-30)
            notes.append(f"directions {', '.join(f'{beta_in[i]:g}°' for i in g)} are the same: kept one "
                         f"(max difference {spread / scale:.2g} of the largest force)")
    if not np.allclose(beta, np.asarray(beta_in, dtype=float)[keep]):
        notes.append("wave directions mapped to [0°, 360°) and sorted")
    return X[:, keep]
