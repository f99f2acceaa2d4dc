"""BEMIO HDF5: the interchange format of WEC-Sim, HydroChrono and BEMRosetta — boatland's database file.

Layout (notes/hydro-formats.md). Hydrodynamic arrays are stored normalised as BEMIO expects:
A/ρ, B/(ρω), C/(ρg), X/(ρg), with the WAMIT phase convention exp(+iωt) (the same as boatland's).
Scalars are stored with shape (1, 1) and vectors as columns, as the files MATLAB's BEMIO writes.

boatland's extras live under ``/body1/boatland/`` where other readers ignore them:

- ``mass_matrix`` (6, 6): rigid-body mass matrix about the reference point;
- ``ref_point`` (3,);
- ``A0`` (6, 6): zero-frequency added mass, when known;
- ``exact/{A, B, C, X_re, X_im, A_inf}``: the dimensional arrays bit for bit (normalising and
  un-normalising is not exact in floating point); used only while they agree with the BEMIO arrays,
  so a file edited by another tool is read from its BEMIO arrays;
- ``mesh/{vertices, faces}``: wetted hull panels;
- ``topsides/{vertices, faces}``: the hull above the waterline (topsides, deck, deckhouse), drawn by
  the viewers only;
- ``drift`` (6, Nh, Nf): the mean wave drift force and moment per unit amplitude squared
  [N/m², N·m/m²] (:mod:`boatland.hydro.drift`), when the database has it; absent: None;
- attributes ``name``, ``provenance_*``.

Mean drift from other tools is read from WEC-Sim's groups ``/body1/hydro_coeffs/mean_drift/<method>/val``
(6, Nh, Nf), normalised by ρg like the excitation (WEC-Sim ``writeBEMIOH5.m``, ``readBEMIOH5.m``), the
method being ``momentum_conservation``, ``control_surface`` or ``pressure_integration``; the first present
in that order is used (a note says which). boatland writes its drift only under its own extras: the
database does not record the method as data, so it cannot name WEC-Sim's group for it.

Other groups present in a file (IRFs, state-space fits) are left for :mod:`boatland.irf` to read and
write; rewriting a database with :func:`write_bemio` keeps nothing else.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from boatland import __version__
from boatland.atomic import atomic_hdf5
from boatland.errors import BoatlandInputError, HydroDataError
from boatland.inputs import HDF5_DAMAGE, damage_text, open_hdf5
from boatland.vessel.database import HullMesh, HydroDB, Provenance
from boatland.vessel.radiation import padded_state_space, read_memory, write_memory

__all__ = ["read_bemio", "write_bemio", "is_bemio", "write_drift", "write_radiation", "read_radiation"]

_HC = "body1/hydro_coeffs"
_EXTRA = "body1/boatland"


def is_bemio(path: Path) -> bool:
    """True when ``path`` is an HDF5 file with the BEMIO ``/body1/hydro_coeffs`` group."""

    try:
        with open_hdf5(path, "BEMIO database") as f:
            return _HC in f
    except OSError:
        return False


def write_bemio(db: HydroDB, path: str | Path) -> Path:
    """Write ``db`` to ``path`` (BEMIO HDF5 plus boatland extras), atomically.

    Parameters
    ----------
    db : HydroDB
        The database.
    path : str or Path
        Target file; replaced only when the whole file has been written.
    """

    path = Path(path)
    rho, g, w = db.rho, db.g, db.omega
    col = lambda a: np.asarray(a, dtype=float).reshape(-1, 1)  # noqa: E731
    scalar = lambda v: np.array([[float(v)]])  # noqa: E731
    with atomic_hdf5(path) as f:
        _store = _compressed_store(f)
        f["bem_data/code"] = np.bytes_(db.provenance.solver or "unknown")
        sp = f.create_group("simulation_parameters")
        sp["g"] = scalar(g)
        sp["rho"] = scalar(rho)
        sp["w"] = col(w)
        sp["T"] = col(2 * np.pi / w)
        sp["water_depth"] = np.bytes_("infinite") if np.isinf(db.water_depth) else scalar(db.water_depth)
        sp["wave_dir"] = col(db.wave_dir_deg)
        sp["scaled"] = scalar(0)
        pr = f.create_group("body1/properties")
        pr["name"] = np.bytes_(db.name)
        pr["cg"] = col(db.cog)
        pr["cb"] = col(db.cob)
        pr["disp_vol"] = scalar(db.disp_vol)
        pr["body_number"] = scalar(1)
        pr["dof"] = scalar(6)
        pr["dof_start"] = scalar(1)
        pr["dof_end"] = scalar(6)
        hc = f.create_group(_HC)
        hc["linear_restoring_stiffness"] = db.C / (rho * g)
        _store(hc, "added_mass/all", db.A / rho)
        if db.A_inf is not None:
            hc["added_mass/inf_freq"] = db.A_inf / rho
        _store(hc, "radiation_damping/all", db.B / (rho * w))
        Xn = db.X / (rho * g)
        for key, val in (("re", Xn.real), ("im", Xn.imag), ("mag", np.abs(Xn)), ("phase", np.angle(Xn))):
            _store(hc, f"excitation/{key}", val)
        ex = f.create_group(_EXTRA)
        ex.attrs["name"] = db.name
        ex.attrs["boatland_version"] = __version__
        for key in ("source", "solver", "created", "reader"):
            ex.attrs[f"provenance_{key}"] = getattr(db.provenance, key)
        ex.attrs["provenance_notes"] = json.dumps(list(db.provenance.notes))
        ex["ref_point"] = db.ref_point
        ex["water_depth"] = db.water_depth
        if db.M is not None:
            ex["mass_matrix"] = db.M
        if db.A_0 is not None:
            ex["A0"] = db.A_0
        exact = ex.create_group("exact")
        for key, val in (("A", db.A), ("B", db.B), ("C", db.C), ("X_re", db.X.real), ("X_im", db.X.imag)):
            _store(exact, key, val)
        if db.A_inf is not None:
            exact["A_inf"] = db.A_inf
        if db.mesh is not None:
            _store(ex, "mesh/vertices", db.mesh.vertices)
            _store(ex, "mesh/faces", db.mesh.faces)
        if db.topsides is not None:
            _store(ex, "topsides/vertices", db.topsides.vertices)
            _store(ex, "topsides/faces", db.topsides.faces)
        if db.drift is not None:
            _store(ex, "drift", db.drift)
    return path


def _compressed_store(f):
    """Writer of datasets: arrays of more than 4096 values get the standard gzip + shuffle filters
    (read transparently by HDF5 in MATLAB, WEC-Sim, HydroChrono, BEMRosetta); small ones are plain."""

    def store(group, name, value):
        value = np.asarray(value)
        if value.size > 4096:
            group.create_dataset(name, data=value, compression="gzip", compression_opts=4, shuffle=True)
        else:
            group[name] = value

    return store


def read_bemio(path: str | Path) -> HydroDB:
    """Read a BEMIO HDF5 file (boatland's own, WEC-Sim's or HydroChrono's) into a :class:`HydroDB`.

    Raises
    ------
    HydroDataError
        The file is missing, not HDF5, lacks a required dataset, or holds arrays of the wrong shape
        or with NaN, or is damaged anywhere — the message names the file and, where it can, the dataset.
    """
    path = Path(path)
    try:
        return _read_bemio(path)
    except HydroDataError as exc:
        if exc.source is None:        # from an object made of the file's arrays (a hull mesh): name the file
            raise HydroDataError(path, exc.where, exc.message) from None
        raise
    except BoatlandInputError:
        raise
    except HDF5_DAMAGE as exc:
        raise HydroDataError(path, None, f"damaged ({damage_text(exc)}); expected a BEMIO database") from None


def _read_bemio(path: Path) -> HydroDB:
    """:func:`read_bemio`'s reading (its errors other than :class:`HydroDataError` are damage)."""
    if not path.exists():
        raise HydroDataError(path, None, "file not found")
    try:
        f = open_hdf5(path, "BEMIO database")
    except BoatlandInputError as exc:
        raise HydroDataError(path, None, str(exc).removeprefix(f"{path}: ")) from None
    except OSError as exc:
        raise HydroDataError(path, None, f"not a readable HDF5 file ({exc.__class__.__name__}: "
                                         f"{str(exc).split('(')[0].strip()}); expected a BEMIO database") from None
    with f:
        def get(name, required=True):
            if name not in f:
                if required:
                    raise HydroDataError(path, f"/{name}", "dataset missing; expected a BEMIO HDF5 database "
                                                            "(WEC-Sim/BEMIO layout)")
                return None
            try:
                return f[name][()]
            except Exception as exc:  # corrupted chunk, truncated file
                raise HydroDataError(path, f"/{name}", f"cannot be read ({exc}); the file is damaged") from None

        def num(name, required=True):
            v = get(name, required)
            if v is None:
                return None
            try:
                return np.asarray(v, dtype=float)
            except (TypeError, ValueError):
                raise HydroDataError(path, f"/{name}", f"expected numbers, got {v!r:.60}") from None

        def one(name):
            v = num(name).reshape(-1)
            if v.size != 1:
                raise HydroDataError(path, f"/{name}", f"expected one number, got {v.size}")
            return float(v[0])

        rho = one("simulation_parameters/rho")
        g = one("simulation_parameters/g")
        w = num("simulation_parameters/w").reshape(-1)
        beta = num("simulation_parameters/wave_dir").reshape(-1)
        depth_raw = get("simulation_parameters/water_depth", required=False)
        water_depth = _depth(depth_raw, path)

        has_exact = f"{_EXTRA}/exact/A" in f
        A = num(f"{_HC}/added_mass/all")
        Bn = num(f"{_HC}/radiation_damping/all")
        C = num(f"{_HC}/linear_restoring_stiffness")
        re, im = num(f"{_HC}/excitation/re"), num(f"{_HC}/excitation/im")
        A_inf = num(f"{_HC}/added_mass/inf_freq", required=False)
        nf, nb = w.size, beta.size
        for name, arr, shape in (("added_mass/all", A, (6, 6, nf)), ("radiation_damping/all", Bn, (6, 6, nf)),
                                 ("linear_restoring_stiffness", C, (6, 6)), ("excitation/re", re, (6, nb, nf)),
                                 ("excitation/im", im, (6, nb, nf))):
            if arr.shape != shape:
                raise HydroDataError(path, f"/{_HC}/{name}", f"expected shape {shape} "
                                     f"(from {nf} frequencies and {nb} directions), got {arr.shape}")
        A, B, C, X = A * rho, Bn * rho * w, C * rho * g, (re + 1j * im) * rho * g
        A_inf = None if A_inf is None else A_inf * rho
        notes: list[str] = []
        if has_exact:
            eA, eB, eC = num(f"{_EXTRA}/exact/A"), num(f"{_EXTRA}/exact/B"), num(f"{_EXTRA}/exact/C")
            eX = num(f"{_EXTRA}/exact/X_re") + 1j * num(f"{_EXTRA}/exact/X_im")
            eAi = num(f"{_EXTRA}/exact/A_inf", required=False)
            pairs = [(eA, A), (eB, B), (eC, C), (eX, X)] + ([(eAi, A_inf)] if A_inf is not None else [])
            if all(e.shape == a.shape and np.allclose(e, a, rtol=1e-10, atol=1e-12 * max(np.max(np.abs(a)), 1.0))
                   for e, a in pairs) and (eAi is None) == (A_inf is None):
                A, B, C, X, A_inf = eA, eB, eC, eX, eAi
            else:
                notes.append("boatland's exact copy disagrees with the BEMIO arrays (edited by another tool?): "
                             "used the BEMIO arrays")

        drift = _drift(num, f, path, rho, g, notes)
        if drift is not None and drift.shape != (6, nb, nf):
            where = f"/{_EXTRA}/drift" if f"{_EXTRA}/drift" in f else f"/{_HC}/mean_drift"
            raise HydroDataError(path, where, f"expected shape {(6, nb, nf)} (from {nf} frequencies and {nb} "
                                              f"directions), got {drift.shape}")
        M = num(f"{_EXTRA}/mass_matrix", required=False)
        A0 = num(f"{_EXTRA}/A0", required=False)
        ref = num(f"{_EXTRA}/ref_point", required=False)
        cg = num("body1/properties/cg", required=False)
        cb = num("body1/properties/cb", required=False)
        vol = num("body1/properties/disp_vol", required=False)
        if f"{_EXTRA}/water_depth" in f:
            water_depth = float(num(f"{_EXTRA}/water_depth"))
        ex = f[_EXTRA].attrs if _EXTRA in f else {}
        code = get("bem_data/code", required=False)
        solver = _text(code) if code is not None else ""
        name = ex.get("name", None) or _text(get("body1/properties/name", required=False) or b"body1")
        prov = Provenance(
            source=str(ex.get("provenance_source", path)),
            solver=str(ex.get("provenance_solver", solver)),
            created=str(ex.get("provenance_created", "")),
            reader=str(ex.get("provenance_reader", "bemio")),
            notes=tuple(_notes(ex.get("provenance_notes", "[]"), path)) + tuple(notes),
        )
        mesh = topsides = None
        if f"{_EXTRA}/mesh/vertices" in f:
            mesh = HullMesh(num(f"{_EXTRA}/mesh/vertices"), get(f"{_EXTRA}/mesh/faces"))
        if f"{_EXTRA}/topsides/vertices" in f:
            topsides = HullMesh(num(f"{_EXTRA}/topsides/vertices"), get(f"{_EXTRA}/topsides/faces"))
    try:
        return HydroDB(
            omega=w, A=A, B=B, X=X, wave_dir_deg=beta, C=C, A_inf=A_inf, A_0=A0, M=M,
            ref_point=np.zeros(3) if ref is None else ref,
            cog=np.zeros(3) if cg is None else cg.reshape(-1),
            cob=np.zeros(3) if cb is None else cb.reshape(-1),
            disp_vol=0.0 if vol is None else float(vol.reshape(-1)[0]),
            water_depth=water_depth, rho=rho, g=g, name=str(name), provenance=prov, mesh=mesh,
            topsides=topsides, drift=drift,
        )
    except HydroDataError as exc:
        raise HydroDataError(path, exc.where, exc.message) from None


def _notes(text, path: Path) -> list[str]:
    """The provenance notes stored as a JSON list of strings."""
    try:
        notes = json.loads(text)
    except (TypeError, ValueError):
        raise HydroDataError(path, f"/{_EXTRA}", "its provenance_notes attribute is not JSON") from None
    if not isinstance(notes, list):
        raise HydroDataError(path, f"/{_EXTRA}", "its provenance_notes attribute is not a list")
    return [str(n) for n in notes]


#: WEC-Sim's mean-drift groups, in the order they are preferred, and what each method gives.
_MEAN_DRIFT = (("momentum_conservation", "far-field momentum conservation"),
               ("control_surface", "control-surface integration"),
               ("pressure_integration", "near-field pressure integration"))


def _drift(num, f, path, rho: float, g: float, notes: list[str]):
    """The mean drift of the file (dimensional), boatland's own copy first, else WEC-Sim's groups; or None."""
    if f"{_EXTRA}/drift" in f:
        return num(f"{_EXTRA}/drift")
    for key, what in _MEAN_DRIFT:
        name = f"{_HC}/mean_drift/{key}/val"
        if name in f:
            others = [k for k, _ in _MEAN_DRIFT if k != key and f"{_HC}/mean_drift/{k}/val" in f]
            notes.append(f"mean drift: read from /{name} ({what}, stored by BEMIO as drift/(ρg)); which DOFs are "
                         "meaningful depends on the method (momentum conservation gives surge, sway and yaw only)"
                         + (f"; also in the file, not used: {', '.join(others)}" if others else ""))
            return num(name) * rho * g
    return None


def _text(v) -> str:
    if isinstance(v, bytes):
        return v.decode(errors="replace")
    if isinstance(v, np.ndarray):
        return _text(v.reshape(-1)[0]) if v.size else ""
    return str(v)


def _depth(raw, path) -> float:
    if raw is None:
        return np.inf
    if isinstance(raw, (bytes, str)) or (isinstance(raw, np.ndarray) and raw.dtype.kind in "SUO"):
        text = _text(raw).strip().lower()
        if text in ("infinite", "inf"):
            return np.inf
        try:
            return float(text)
        except ValueError:
            raise HydroDataError(path, "/simulation_parameters/water_depth",
                                 f"expected a depth in m or 'infinite', got {text!r}") from None
    d = float(np.asarray(raw, dtype=float).reshape(-1)[0])
    return np.inf if d <= 0 else d


def write_drift(path: str | Path, db: HydroDB) -> Path:
    """Store ``db``'s mean drift and provenance notes in the existing database file ``path``, atomically,
    leaving every other dataset as it is (for adding drift to a shipped database without rewriting it).

    Raises
    ------
    HydroDataError
        ``db`` has no drift, or the file holds another grid of frequencies or directions.
    """


    path = Path(path)
    if db.drift is None:
        raise HydroDataError(path, "drift", "the database has no mean drift to store")
    with atomic_hdf5(path, "r+") as f:
        w = np.asarray(f["simulation_parameters/w"][()], dtype=float).reshape(-1)
        beta = np.asarray(f["simulation_parameters/wave_dir"][()], dtype=float).reshape(-1)
        if w.shape != db.omega.shape or not np.allclose(w, db.omega, rtol=1e-12, atol=0) \
                or beta.shape != db.wave_dir_deg.shape or not np.allclose(beta, db.wave_dir_deg, rtol=0, atol=1e-9):
            raise HydroDataError(path, "/simulation_parameters", "the file's frequencies or directions are not "
                                                                 "the database's: write the whole database instead")
        ex = f.require_group(_EXTRA)
        if "drift" in ex:
            del ex["drift"]
        _compressed_store(f)(ex, "drift", db.drift)
        ex.attrs["provenance_notes"] = json.dumps(list(db.provenance.notes))
    return path


# ------------------------------------------------------------------------- radiation memory
_IRF = f"{_HC}/radiation_damping/impulse_response_fun"
_SS = f"{_HC}/radiation_damping/state_space"
_XIRF = f"{_EXTRA}/irf"


def write_radiation(path: str | Path, memory, rho: float) -> Path:
    """Store IRFs and the state-space fit in an existing database file, atomically.

    BEMIO groups (read by WEC-Sim, HydroChrono): ``impulse_response_fun/{K (6,6,Nt) K/ρ, t, w}`` and
    ``state_space/{A,B,C,D}/all, it, r2t`` (C and D divided by ρ, orders padded to the largest).
    Exact values, settings, checks and notes under ``/body1/boatland/irf``.
    """


    path = Path(path)
    irf, ss = memory.irf, memory.state_space
    with atomic_hdf5(path, "r+") as f:
        for grp in (_IRF, _SS, _XIRF):
            if grp in f:
                del f[grp]
        f[f"{_IRF}/K"] = irf.K / rho
        f[f"{_IRF}/t"] = irf.t.reshape(-1, 1)
        f[f"{_IRF}/w"] = np.asarray(irf.check_band, dtype=float).reshape(-1, 1)
        write_memory(f.create_group(_XIRF), memory)
        if ss is not None:
            A, B, C = padded_state_space(ss)
            f[f"{_SS}/A/all"], f[f"{_SS}/B/all"], f[f"{_SS}/C/all"] = A, B, C / rho
            f[f"{_SS}/D/all"] = np.zeros((6, 6))
            f[f"{_SS}/it"] = ss.orders.astype(float)
            f[f"{_SS}/r2t"] = np.nan_to_num(ss.r2, nan=0.0)
    return path


def read_radiation(path: str | Path):
    """The :class:`boatland.vessel.radiation.RadiationMemory` stored by :func:`write_radiation`, or None.

    Only boatland's own (exact) copy is read; IRFs from other tools are recomputed from B(ω).
    """
    import h5py

    with h5py.File(path, "r") as f:
        return read_memory(f[_XIRF]) if _XIRF in f else None
