r"""Capytaine NetCDF dataset (2.x and 3.0) → :class:`~boatland.vessel.database.HydroDB`.

Layout (Capytaine docs, "Outputs": ``assemble_dataset`` / ``export_dataset``; notes/hydro-formats.md):
``added_mass`` and ``radiation_damping`` over (frequency, ``radiating_dof``, ``influenced_dof``) in
any order (2.3 writes radiating first, 3.0 influenced first: the reader goes by dimension *names*);
``excitation_force`` or ``diffraction_force`` + ``Froude_Krylov_force`` over (frequency,
``wave_direction`` [rad], ``influenced_dof``), complex values split over a ``complex`` dimension with
labels ``re``/``im`` in files; ``hydrostatic_stiffness`` and ``inertia_matrix`` over
(``influenced_dof``, ``radiating_dof``), both about the rotation centre; scalars ``rho``, ``g``,
``water_depth`` (``inf`` for deep water); Capytaine 3 adds ``rotation_center``, ``center_of_mass``,
``center_of_buoyancy`` and ``disp_mass``, and may hold ω = 0 and ω = ∞ rows.

Capytaine uses exp(−iωt): forces are conjugated to boatland's exp(+iωt). ``A[i, j]`` = force in the
*influenced* DOF i due to motion of the *radiating* DOF j. Frequencies with NaN anywhere (finite
depth at the lowest ω) are dropped and listed in the provenance notes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from boatland.conventions import DOF_NAMES
from boatland.errors import BoatlandInputError, HydroDataError
from boatland.inputs import open_input
from boatland.hydro._text import build_db, normalise_directions
from boatland.vessel.database import HydroDB, Provenance

__all__ = ["read_capytaine"]

_FREQ_DIMS = ("omega", "freq", "period", "wavenumber", "wavelength")
_READ_ERRORS = (OSError, RuntimeError, ValueError, KeyError, TypeError, IndexError)


def read_capytaine(path: str | Path, *, ref_point=None) -> HydroDB:
    """Read a Capytaine dataset written to NetCDF (NetCDF3 or NetCDF4/HDF5) into a :class:`HydroDB`.

    Parameters
    ----------
    path : str or Path
        A ``.nc`` file from ``cpt.export_dataset`` or ``separate_complex_values(ds).to_netcdf``.
    ref_point : array_like, shape (3,), optional
        The rotation centre the coefficients were computed about [m], for datasets that do not store
        it (Capytaine 2.x). Must agree with ``rotation_center`` when the dataset has one.

    Returns
    -------
    HydroDB
        Dimensional SI, exp(+iωt), ω ascending; ``A_inf``/``A_0`` from the ω = ∞ / ω = 0 rows when
        present; ``M`` from ``inertia_matrix`` when present (about the rotation centre).

    Raises
    ------
    HydroDataError
        The file is missing or unreadable, or a variable is missing, misshaped or NaN where it
        cannot be dropped; the message names the file and the variable.
    """
    from boatland.resources import require

    xr = require("xarray", "reading a Capytaine NetCDF file")
    require("netCDF4", "reading a Capytaine NetCDF file")
    path = Path(path)
    if not path.is_file():
        raise HydroDataError(path, None, "file not found; expected a Capytaine NetCDF dataset (.nc)")
    try:
        with open_input(path, "Capytaine NetCDF dataset", "hdf5") as fh:
            magic = fh.read(4)
    except BoatlandInputError as exc:
        raise HydroDataError(path, None, str(exc).removeprefix(f"{path}: ")) from None
    # Classic NetCDF (CDF1/CDF2) through scipy: the netCDF-C library reads a truncated classic file
    # without complaint (missing data come back as fill values); scipy's reader refuses it.
    engine = "scipy" if magic in (b"CDF\x01", b"CDF\x02") else None
    try:
        with xr.open_dataset(path, engine=engine) as handle:
            ds = handle.load()
    except _READ_ERRORS as exc:
        raise HydroDataError(path, None, f"cannot be read as NetCDF ({exc.__class__.__name__}: {str(exc)[:100]}); "
                                         "expected a Capytaine dataset (damaged or truncated file?)") from None
    return _from_dataset(ds, path, ref_point)


def _from_dataset(ds, path: Path, ref_given=None) -> HydroDB:
    notes: list[str] = []

    def bad(name, message):
        return HydroDataError(path, name, message)

    for name in ("added_mass", "radiation_damping"):
        if name not in ds:
            raise bad(name, "variable missing; expected a Capytaine dataset with radiation results")
    am = ds["added_mass"]
    fdim = next((d for d in am.dims if d in _FREQ_DIMS), None)
    if fdim is None or "radiating_dof" not in am.dims or "influenced_dof" not in am.dims:
        raise bad("added_mass", f"dimensions {am.dims}; expected a frequency dimension ({', '.join(_FREQ_DIMS)}), "
                                "radiating_dof and influenced_dof")
    omega = _omega(ds, fdim, bad)
    rad_idx = _dof_index(ds["radiating_dof"].values, "radiating_dof", bad)
    inf_idx = _dof_index(ds["influenced_dof"].values, "influenced_dof", bad)
    missing = [DOF_NAMES[k] for k in range(6) if k not in rad_idx or k not in inf_idx]
    if missing:
        notes.append(f"DOFs not in the dataset set to zero: {', '.join(missing)}")

    def matrix(name, dims, optional=False):
        if name not in ds:
            if optional:
                return None
            raise bad(name, "variable missing")
        da = _squeeze(ds[name], name, dims, bad)
        vals = _complex(da, name, bad).transpose(*dims).values
        if len(dims) == 2 and not np.all(np.isfinite(vals)):
            raise bad(name, f"{int(np.count_nonzero(~np.isfinite(vals)))} value(s) are NaN or infinite; "
                            "expected finite numbers")
        out = np.zeros((6, 6) + vals.shape[2:], dtype=vals.dtype)
        out[np.ix_(inf_idx, rad_idx)] = vals
        return out

    A = matrix("added_mass", ("influenced_dof", "radiating_dof", fdim))
    B = matrix("radiation_damping", ("influenced_dof", "radiating_dof", fdim))
    X, beta_rad = _excitation(ds, fdim, inf_idx, bad, notes)

    # ω = 0 and ω = ∞ rows: the limits, not frequencies of the band
    A_0 = A_inf = None
    special = (omega == 0) | np.isinf(omega)
    for k in np.flatnonzero(special):
        lim = A[:, :, k]
        label = "ω = 0" if omega[k] == 0 else "ω = ∞"
        if np.all(np.isfinite(lim)):
            if omega[k] == 0:
                A_0 = lim
            else:
                A_inf = lim
        else:
            notes.append(f"added mass at {label} has NaN: not used")
    keep = ~special
    if np.any(omega < 0):
        raise bad(fdim, f"negative frequency {omega[omega < 0][0]:g} rad/s")
    nan = keep & ~(np.all(np.isfinite(A), axis=(0, 1)) & np.all(np.isfinite(B), axis=(0, 1))
                   & np.all(np.isfinite(X), axis=(0, 1)))
    if np.any(nan):
        notes.append(f"dropped {int(nan.sum())} frequencies with NaN: "
                     + ", ".join(f"{w:.4g}" for w in omega[nan]) + " rad/s")
    keep &= ~nan
    omega, A, B, X = omega[keep], A[..., keep], B[..., keep], X[..., keep]
    order = np.argsort(omega, kind="stable")
    omega, A, B, X = omega[order], A[..., order], B[..., order], X[..., order]
    if np.any(np.diff(omega) == 0):
        w = omega[np.flatnonzero(np.diff(omega) == 0)[0]]
        raise bad(fdim, f"frequency {w:g} rad/s appears twice; expected each frequency once")

    beta, first, groups = normalise_directions(np.rad2deg(beta_rad))
    for grp in groups:
        if grp.size > 1:
            notes.append(f"directions {', '.join(f'{np.rad2deg(beta_rad[i]):g}°' for i in grp)} are the same: "
                         "kept the first")
    X = X[:, first]

    C = matrix("hydrostatic_stiffness", ("influenced_dof", "radiating_dof"), optional=True)
    if C is None:
        raise bad("hydrostatic_stiffness", "variable missing; compute the hydrostatics in Capytaine "
                                           "(body.hydrostatic_stiffness) before solving")
    M = matrix("inertia_matrix", ("influenced_dof", "radiating_dof"), optional=True)
    if M is None:
        notes.append("no inertia_matrix in the dataset: mass matrix unknown")
    elif missing:
        notes.append("inertia_matrix does not cover all 6 DOFs: mass matrix not used")
        M = None
    elif M[0, 0] > 0:
        M = 0.5 * (M + M.T)               # Capytaine's is symmetric up to round-off

    rho, g = _scalar(ds, "rho", bad), _scalar(ds, "g", bad)
    depth = _scalar(ds, "water_depth", bad)
    speed = _scalar(ds, "forward_speed", bad, required=False)
    if speed:
        raise bad("forward_speed", f"{speed:g} m/s; boatland needs zero-speed coefficients")
    ref = _point(ds, "rotation_center", bad)
    if ref_given is not None:
        ref_given = np.asarray(ref_given, dtype=float).reshape(-1)
        if ref_given.shape != (3,) or not np.all(np.isfinite(ref_given)):
            raise bad("ref_point", f"expected 3 finite coordinates [m], got {ref_given}")
        if ref is not None and not np.allclose(ref, ref_given, atol=1e-9):
            raise bad("rotation_center", f"{ref} in the dataset, but ref_point={ref_given} was passed")
        if ref is None:
            notes.append(f"reference point {tuple(ref_given)} given by the caller (not stored in the dataset)")
        ref = ref_given
    if ref is None:
        ref = np.zeros(3)
        notes.append("rotation centre not stored in the dataset: reference point assumed at (0, 0, 0) "
                     "(pass ref_point=...)")
    cog = _point(ds, "center_of_mass", bad)
    if cog is None:
        cog = np.zeros(3)
        notes.append("centre of mass not stored in the dataset: set to (0, 0, 0)")
    cob = _point(ds, "center_of_buoyancy", bad)
    if cob is None:
        cob = np.zeros(3)
    disp_mass = _scalar(ds, "disp_mass", bad, required=False)
    vol = disp_mass / rho if disp_mass is not None else 0.0
    if disp_mass is None:
        notes.append("displaced volume not stored in the dataset (0)")
    version = ds.attrs.get("capytaine_version", "")
    if version:
        notes.append(f"Capytaine {version}")
    name = next((str(ds[k].values) for k in ("body_name", "body") if k in ds.coords or k in ds), path.stem)
    prov = Provenance(source=str(path), solver="CAPYTAINE", reader="capytaine",
                      created=str(ds.attrs.get("creation_of_dataset", ds.attrs.get("start_of_computation", ""))),
                      notes=tuple(notes))
    return build_db(
        path, omega=omega, A=A, B=B, X=X, wave_dir_deg=beta, C=C, A_inf=A_inf, A_0=A_0, M=M,
        ref_point=ref, cog=cog, cob=cob, disp_vol=vol, water_depth=np.inf if depth <= 0 else depth,
        rho=rho, g=g, name=name, provenance=prov,
    )


def _omega(ds, fdim: str, bad) -> np.ndarray:
    """Angular frequencies [rad/s] along the frequency dimension ``fdim``."""
    if "omega" in ds.coords and ds["omega"].dims == (fdim,):
        w = np.asarray(ds["omega"].values, dtype=float)
    elif fdim == "freq":
        w = 2 * np.pi * np.asarray(ds["freq"].values, dtype=float)
    elif fdim == "period":
        T = np.asarray(ds["period"].values, dtype=float)
        with np.errstate(divide="ignore"):
            w = np.where(T == 0, np.inf, 2 * np.pi / np.where(T == 0, 1.0, T))
    else:
        raise bad(fdim, "no 'omega' coordinate to convert this frequency dimension; expected an omega coordinate")
    if np.any(np.isnan(w)):
        raise bad(fdim, "NaN frequency; expected numbers")
    return w


def _dof_index(labels, dim: str, bad) -> list[int]:
    """boatland DOF index of each Capytaine DOF name (``Surge`` or ``body__Surge``)."""
    names = [str(v).split("__")[-1].strip().lower() for v in np.asarray(labels).reshape(-1)]
    prefixes = {str(v).split("__")[0] for v in np.asarray(labels).reshape(-1) if "__" in str(v)}
    if len(prefixes) > 1:
        raise bad(dim, f"DOFs of several bodies ({', '.join(sorted(prefixes))}); boatland reads one body")
    known = [n.lower() for n in DOF_NAMES]
    unknown = [str(v) for v, n in zip(np.asarray(labels).reshape(-1), names) if n not in known]
    if unknown or len(set(names)) != len(names):
        raise bad(dim, f"DOFs {list(map(str, labels))}; expected rigid-body DOFs named "
                       f"{', '.join(d.capitalize() for d in DOF_NAMES)}, each once")
    return [known.index(n) for n in names]


def _squeeze(da, name: str, dims: tuple, bad):
    """Drop extra length-1 dimensions; refuse extra dimensions with several values."""
    for d in da.dims:
        if d in dims or d == "complex":
            continue
        if da.sizes[d] != 1:
            raise bad(name, f"has {da.sizes[d]} values of {d!r}; select one (ds.sel({d}=...)) before saving")
        da = da.isel({d: 0}, drop=True)
    for d in dims:
        if d not in da.dims:
            raise bad(name, f"dimensions {da.dims}; expected {dims}")
    return da


def _complex(da, name: str, bad):
    """Merge a ``complex`` dimension with labels re/im into complex values."""
    if "complex" not in da.dims:
        return da
    labels = [str(v) for v in da["complex"].values] if "complex" in da.coords else []
    if sorted(labels) != ["im", "re"]:
        raise bad(name, f"'complex' dimension labelled {labels}; expected 're' and 'im'")
    return da.sel(complex="re") + 1j * da.sel(complex="im")


def _excitation(ds, fdim: str, inf_idx: list[int], bad, notes: list[str]):
    """X (6, Nb, Nf) conjugated to exp(+iωt), and the directions [rad]."""
    dims = ("influenced_dof", "wave_direction", fdim)
    if "excitation_force" in ds:
        Xc = _complex(_squeeze(ds["excitation_force"], "excitation_force", dims, bad), "excitation_force", bad)
    elif "diffraction_force" in ds and "Froude_Krylov_force" in ds:
        parts = [_complex(_squeeze(ds[n], n, dims, bad), n, bad) for n in ("diffraction_force", "Froude_Krylov_force")]
        Xc = parts[0] + parts[1]
        notes.append("excitation = diffraction_force + Froude_Krylov_force")
    else:
        raise bad("excitation_force", "variable missing (and no diffraction_force + Froude_Krylov_force); "
                                      "expected diffraction results")
    vals = np.conj(Xc.transpose(*dims).values)                       # exp(−iωt) → exp(+iωt)
    X = np.zeros((6,) + vals.shape[1:], dtype=complex)
    X[inf_idx] = vals
    beta = np.asarray(ds["wave_direction"].values, dtype=float).reshape(-1)
    if not np.all(np.isfinite(beta)):
        raise bad("wave_direction", "NaN direction; expected radians")
    units = str(ds["wave_direction"].attrs.get("units", "rad")).lower()
    if units.startswith("deg"):
        beta = np.deg2rad(beta)
    return X, beta


def _scalar(ds, name: str, bad, required: bool = True) -> float | None:
    if name in ds.coords or name in ds:
        vals = np.asarray(ds[name].values).reshape(-1)
    elif name in ds.attrs:
        vals = np.asarray(ds.attrs[name]).reshape(-1)
    else:
        if required:
            raise bad(name, "missing; expected it as a coordinate, variable or attribute")
        return None
    try:
        vals = vals.astype(float)
    except (TypeError, ValueError):
        raise bad(name, f"expected a number, got {vals[:1]!r}") from None
    if vals.size != 1 or np.isnan(vals[0]):
        raise bad(name, f"expected one number, got {vals.size} value(s) {vals[:3]}")
    return float(vals[0])


def _point(ds, name: str, bad) -> np.ndarray | None:
    if name in ds.coords or name in ds:
        v = np.asarray(ds[name].values, dtype=float).reshape(-1)
    elif name in ds.attrs:
        v = np.asarray(ds.attrs[name], dtype=float).reshape(-1)
    else:
        return None
    if v.shape != (3,) or not np.all(np.isfinite(v)):
        raise bad(name, f"expected 3 finite coordinates, got {v}")
    return v
