"""Radiation memory of a vessel: the IRFs and the state-space fit made from its :class:`HydroDB`.

This is the bridge from the database to the kernels of :mod:`boatland.irf`: it passes
the database's arrays, its A∞ (when the solver gave one) and its length scale ∇^⅓, and bundles the
result. Storage in the database file is in :mod:`boatland.hydro.bemio`.
"""

from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass

import numpy as np

from boatland.diskcache import cache_key, cached
from boatland.irf.impulse import IRF, IRFSettings, compute_irf
from boatland.irf.statespace import PairFit, StateSpace, fit_state_space
from boatland.vessel.database import HydroDB
from boatland.reproducible import single_threaded

__all__ = ["RadiationMemory", "radiation_memory", "memory_damping", "default_dt", "write_memory", "read_memory",
           "padded_state_space", "TARGET_R2", "MAX_ORDER"]

#: Default state-space fit target and order cap. The R² of K(t) is dominated by the large low-frequency
#: damping peak; the damping at a catamaran's heave and pitch resonances is a seventh of that peak, so
#: R² = 0.999 (order ≤ 12) left B33 at resonance 4.5 % low and the CTV free decay by state space 3.7 %
#: (heave) and 5.0 % (pitch) RMS from the convolution. R² = 0.99999 (order ≤ 40): 0.74 % and 0.46 %
#: (measured on ctv24, 60 s decay; tests/integrate/test_cummins.py).
TARGET_R2 = 0.99999
MAX_ORDER = 40


def default_dt(omega_max: float) -> float:
    """Δt_K = min(0.05 s, π / (3 ω_max)): resolves the band and an asymptotic tail to 3 ω_max."""
    return float(min(0.05, np.pi / (3.0 * omega_max)))


@dataclass(frozen=True, eq=False)
class RadiationMemory:
    """K(t) with its provenance and checks, and (optionally) the state-space fit of it."""

    irf: IRF
    state_space: StateSpace | None = None


#: The modules a radiation memory is made by: their source is part of its disk-cache key
#: (:mod:`boatland.diskcache`), so that a change of method makes a new entry.
MEMORY_CODE = ("boatland.irf.impulse", "boatland.irf.quadrature", "boatland.irf.statespace", "boatland.vessel.radiation")


def radiation_memory(db: HydroDB, settings: IRFSettings | None = None, *, fit: bool = True,
                     target_r2: float = TARGET_R2, max_order: int = MAX_ORDER) -> RadiationMemory:
    """Compute the radiation IRFs (and the state-space fit) of ``db``, or read them back from the disk cache
    (:mod:`boatland.diskcache`: keyed by the database's ω, A, B, A∞ and volume, the settings and this code;
    the same bits as computing them).

    Parameters
    ----------
    db : HydroDB
    settings : IRFSettings, optional
        Defaults: T_K = 60 s, Δt_K = 0.05 s (or finer when the band and its tail need it:
        π/Δt_K ≥ 3 ω_max), tail "auto", clip negative damping; ``length_scale`` is set to ∇^⅓.
    fit : bool
        Also fit the state-space model.
    target_r2, max_order : float, int
        For :func:`boatland.irf.statespace.fit_state_space`; defaults :data:`TARGET_R2`, :data:`MAX_ORDER`.
    """
    if settings is None:
        settings = IRFSettings(dt=default_dt(db.omega[-1]))
    if settings.length_scale == 1.0 and db.disp_vol > 0:
        settings = dataclasses.replace(settings, length_scale=float(db.disp_vol ** (1 / 3)))

    def make() -> RadiationMemory:
        with single_threaded():   # K (a matrix product) and the fit (LAPACK): the same bits on any core count
            irf = compute_irf(db.omega, db.A, db.B, db.A_inf, settings)
            ss = fit_state_space(irf, db.omega, db.B, target_r2=target_r2, max_order=max_order) if fit else None
        return RadiationMemory(irf=irf, state_space=ss)

    a_inf = np.zeros(0) if db.A_inf is None else np.asarray(db.A_inf, dtype=float)
    key = cache_key("radiation", (np.asarray(db.omega, dtype=float), np.asarray(db.A, dtype=float),
                                  np.asarray(db.B, dtype=float), a_inf, float(db.disp_vol),
                                  json.dumps(dataclasses.asdict(settings), default=repr), bool(fit),
                                  float(target_r2), int(max_order)), MEMORY_CODE)
    return cached(key, make, write_memory, read_memory)


def write_memory(group, memory: RadiationMemory) -> None:
    """Store ``memory`` exactly (IRFs, settings, checks, notes and the state-space fit) in an HDF5 group
    (read back by :func:`read_memory`; the database file's ``/body1/boatland/irf``)."""
    irf, ss = memory.irf, memory.state_space
    x = group
    x["K"], x["t"], x["A_inf"] = irf.K, irf.t, irf.A_inf
    for key in ("ogilvie_spread", "err_B", "err_A", "truncation"):
        x[key] = getattr(irf, key)
    x["significant"] = irf.significant.astype(np.int8)
    x.attrs["A_inf_source"] = irf.A_inf_source
    x.attrs["settings"] = json.dumps(dataclasses.asdict(irf.settings))
    x.attrs["omega_max_used"] = irf.omega_max_used
    x.attrs["check_band"] = np.asarray(irf.check_band, dtype=float)
    x.attrs["notes"] = json.dumps(list(irf.notes))
    if ss is None:
        return
    A, B, C = padded_state_space(ss)
    xs = x.create_group("state_space")
    xs["A"], xs["B"], xs["C"] = A, B, C
    xs["order"] = ss.orders
    xs["r2"] = ss.r2
    xs["passivity"] = ss.passivity
    xs.attrs["target_r2"] = ss.target_r2
    xs.attrs["max_order"] = ss.max_order
    xs.attrs["notes"] = json.dumps(list(ss.notes))


def padded_state_space(ss: StateSpace) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The per-pair fits as BEMIO lays them out: A (6, 6, n, n), B (6, 6, n, 1), C (6, 6, 1, n), each pair's
    system zero-padded to the largest order n (:attr:`StateSpace.orders` tells each one's)."""
    n = max([f.order for f in ss.pairs.values()] + [1])
    A = np.zeros((6, 6, n, n)); B = np.zeros((6, 6, n, 1)); C = np.zeros((6, 6, 1, n))
    for (i, j), f in ss.pairs.items():
        k = f.order
        A[i, j, :k, :k], B[i, j, :k, 0], C[i, j, 0, :k] = f.A, f.B, f.C
    return A, B, C


def read_memory(group) -> RadiationMemory:
    """The :class:`RadiationMemory` :func:`write_memory` stored in an HDF5 group."""
    x = group
    settings = json.loads(x.attrs["settings"])
    if settings.get("check_band") is not None:
        settings["check_band"] = tuple(settings["check_band"])
    irf = IRF(t=x["t"][()], K=x["K"][()], A_inf=x["A_inf"][()], A_inf_source=str(x.attrs["A_inf_source"]),
              ogilvie_spread=x["ogilvie_spread"][()], err_B=x["err_B"][()], err_A=x["err_A"][()],
              truncation=x["truncation"][()], significant=x["significant"][()].astype(bool),
              settings=IRFSettings(**settings), omega_max_used=float(x.attrs["omega_max_used"]),
              notes=tuple(json.loads(x.attrs["notes"])), check_band=tuple(x.attrs["check_band"]))
    ss = None
    if "state_space" in x:
        xs = x["state_space"]
        order, r2 = xs["order"][()], xs["r2"][()]
        A, B, C = xs["A"][()], xs["B"][()], xs["C"][()]
        pairs = {}
        for i in range(6):
            for j in range(6):
                k = int(order[i, j])
                if irf.significant[i, j]:
                    pairs[(i, j)] = PairFit(A[i, j, :k, :k], B[i, j, :k, 0], C[i, j, 0, :k], float(r2[i, j]))
        ss = StateSpace(pairs=pairs, target_r2=float(xs.attrs["target_r2"]), max_order=int(xs.attrs["max_order"]),
                        passivity=xs["passivity"][()], notes=tuple(json.loads(xs.attrs["notes"])))
    return RadiationMemory(irf=irf, state_space=ss)


def memory_damping(memory: RadiationMemory, omega, *, method: str = "convolution", dt: float | None = None,
                   memory_length: float | None = None) -> np.ndarray:
    r"""The radiation damping the time domain actually applies, rebuilt from the memory it uses.

    For motions :math:`\dot x = \mathrm{Re}\{V e^{i\omega t}\}` the memory force is
    :math:`\mathrm{Re}\{(B_{mem}(\omega) + i\omega(A_{mem}(\omega) - A_\infty))V e^{i\omega t}\}`; this
    returns :math:`B_{mem}`:

    - ``"convolution"`` — the kernel's trapezoid sum over the lags kept (:mod:`boatland.integrate.cummins`),
      :math:`B_{mem}(\omega) = \Delta t\,[\tfrac12 K(0) + \sum_{\ell=1}^{L-1} K(\ell\Delta t)\cos\omega\ell\Delta t
      + \tfrac12 K(L\Delta t)\cos\omega L\Delta t]`, :math:`L\Delta t = T_K` (K as stored: tail, taper);
    - ``"state_space"`` — :math:`\mathrm{Re}\,C(i\omega I - A)^{-1}B` of each fitted pair
      (:func:`boatland.irf.statespace.frequency_response`).

    Truncating K(t) without a taper where it has not decayed makes :math:`B_{mem}` oscillate about the
    true B with an amplitude of about :math:`|K(T_K)|/\omega` — negative where B is small (slow modes).

    Parameters
    ----------
    memory : RadiationMemory
    omega : array_like, shape (Nw,)
        Frequencies [rad/s].
    method : {"convolution", "state_space"}
    dt : float, optional
        Time step of the convolution [s] (default the IRF's own step).
    memory_length : float, optional
        T_K of the convolution [s] (default the IRF's length).

    Returns
    -------
    ndarray, shape (Nw, 6, 6)
    """
    from boatland.irf.statespace import frequency_response

    w = np.atleast_1d(np.asarray(omega, dtype=float))
    out = np.zeros((w.size, 6, 6))
    if method == "state_space":
        if memory.state_space is None:
            raise ValueError("no state-space fit in this radiation memory")
        for (i, j), fit in memory.state_space.pairs.items():
            out[:, i, j] = frequency_response(fit, w).real
        return out
    irf = memory.irf
    h = float(irf.t[1] - irf.t[0]) if dt is None else float(dt)
    T_K = float(irf.t[-1]) if memory_length is None else float(memory_length)
    lags = np.arange(int(round(T_K / h)) + 1) * h
    wts = np.ones(lags.size)
    wts[0] = wts[-1] = 0.5
    c = np.cos(w[:, None] * lags[None, :]) * (wts * h)[None, :]            # (Nw, L+1)
    for i in range(6):
        for j in range(6):
            if irf.significant[i, j]:
                out[:, i, j] = c @ np.interp(lags, irf.t, irf.K[i, j], right=0.0)
    return out
