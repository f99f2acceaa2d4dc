"""Write an xarray Dataset as netCDF-4 (HDF5 with dimension scales) through h5py.

``xarray.open_dataset`` (netCDF4 engine) opens what :func:`write_dataset` writes with its named
dimensions, coordinates, units and attributes, and ``h5py`` reads it as plain HDF5. Writing through h5py
rather than ``Dataset.to_netcdf`` keeps one HDF5 library in the writing process (campaign workers),
writes into a group of an open file (the campaign store), and is faster (a 600 s trial: 0.13 s
against 0.18–0.22 s warm, 0.87 s with the netCDF library's first import; same size, 1.2 MB).

Every dimension must have a coordinate (it becomes the HDF5 dimension scale). Strings are stored as
variable-length UTF-8; ``bool`` attributes as 0/1; ``None`` attributes are left out.

Copying such a group with ``h5py.Group.copy`` breaks its dimension scales for the netCDF library (the
copied scales keep references to the originals): :func:`copy_group` rebuilds them.
"""

from __future__ import annotations

import numpy as np

__all__ = ["write_dataset", "copy_group"]

#: HDF5 dimension-scale bookkeeping attributes (rebuilt, never copied).
_SCALE_ATTRS = frozenset({"CLASS", "NAME", "DIMENSION_LIST", "REFERENCE_LIST", "_Netcdf4Dimid", "_Netcdf4Coordinates"})


def _attr(value):
    if isinstance(value, (bool, np.bool_)):
        return int(value)
    return value


def _put(group, name: str, data: np.ndarray, attrs: dict, compress: bool):
    import h5py

    data = np.asarray(data)
    if data.dtype.kind in "OUS":
        values = np.array([v.decode() if isinstance(v, bytes) else str(v) for v in data.ravel()],
                          dtype=object).reshape(data.shape)
        ds = group.create_dataset(name, data=values, dtype=h5py.string_dtype())
    elif compress and data.size > 1024:
        ds = group.create_dataset(name, data=data, compression="gzip", shuffle=True)
    else:
        ds = group.create_dataset(name, data=data)
    for k, v in attrs.items():
        if v is not None:
            ds.attrs[k] = _attr(v)
    return ds


def write_dataset(ds, group, *, compress: bool = True) -> None:
    """Write ``ds`` (an ``xarray.Dataset``) into ``group`` (an open ``h5py.File`` or group created with
    ``track_order=True``) as netCDF-4.

    Parameters
    ----------
    ds : xarray.Dataset
        Every dimension has a coordinate of the same name.
    group : h5py.Group
    compress : bool
        gzip + shuffle for arrays above 1024 elements.
    """
    missing = [d for d in ds.dims if d not in ds.coords]
    if missing:
        raise ValueError(f"dimensions without a coordinate: {', '.join(missing)}")
    scales = {}
    for d in ds.dims:
        c = ds[d]
        scales[d] = _put(group, d, c.values, dict(c.attrs), compress)
        scales[d].make_scale(d)
    names = [n for n in ds.coords if n not in ds.dims] + list(ds.data_vars)
    coords = [n for n in ds.coords if n not in ds.dims]
    for name in names:
        v = ds[name]
        attrs = dict(v.attrs)
        if name in ds.data_vars and coords:      # non-index coordinates (e.g. per-DOF units) go with the data
            related = [c for c in coords if set(ds[c].dims) <= set(v.dims)]
            if related:
                attrs["coordinates"] = " ".join(related)
        h = _put(group, name, v.values, attrs, compress)
        for i, dim in enumerate(v.dims):
            h.dims[i].attach_scale(scales[dim])
    for k, v in ds.attrs.items():
        if v is not None:
            group.attrs[k] = _attr(v)


def copy_group(src, dst) -> None:
    """Copy a group :func:`write_dataset` wrote (``src``) into the empty group ``dst``, rebuilding the
    dimension scales so the copy opens with ``xarray.open_dataset(file, group=...)`` too."""
    for k, v in src.attrs.items():
        dst.attrs[k] = v
    datasets = {n: o for n, o in src.items() if hasattr(o, "dtype")}
    scales = {n for n, o in datasets.items() if o.attrs.get("CLASS") in (b"DIMENSION_SCALE", "DIMENSION_SCALE")}
    made = {}
    order = sorted(datasets, key=lambda n: n not in scales)
    for name in order:
        o = datasets[name]
        kw = {"compression": o.compression, "shuffle": o.shuffle} if o.compression else {}
        h = dst.create_dataset(name, data=o[()], dtype=o.dtype, **kw)
        for k, v in o.attrs.items():
            if k not in _SCALE_ATTRS:
                h.attrs[k] = v
        if name in scales:
            h.make_scale(name)
            made[name] = h
    for name in order:
        if name in scales:
            continue
        o = datasets[name]
        for i, dim in enumerate(o.dims):
            for scale in dim.values():
                target = scale.name.rsplit("/", 1)[-1]
                if target in made:
                    dst[name].dims[i].attach_scale(made[target])
    for name, o in src.items():
        if not hasattr(o, "dtype"):
            copy_group(o, dst.create_group(name, track_order=True))
