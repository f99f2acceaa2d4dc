"""The recorded quantities of a block of steps, as columns: what the MCAP log stores and Rerun shows.

Both the live sinks (from :class:`~boatland.trial.sink.StepBlock`) and the replay (from an MCAP file)
produce :class:`Columns`, and the Rerun logger consumes only :class:`Columns` — so a replayed log shows
exactly what the live stream showed.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from boatland.trial.events import track_landing
from boatland.trial.result import TrialSeries

__all__ = ["Columns", "LandingTracker", "settle_row", "world_pose", "bow_elevation", "BowElevation"]


@dataclass(frozen=True, eq=False)
class Columns(TrialSeries):
    """Rows of a trial (any consecutive range): its :class:`~boatland.trial.result.TrialSeries` and
    ``slip`` (n, Nc) is the landing offset [m] (NaN while open / not yet caught), ``eta_bow`` (n,) the
    undisturbed wave elevation at the bow [m], ``translation`` (n, 3) and ``quaternion`` (n, 4, xyzw)
    the world pose of the reference point."""

    slip: np.ndarray
    eta_bow: np.ndarray
    translation: np.ndarray
    quaternion: np.ndarray

    def __len__(self) -> int:
        return len(self.t)

    @staticmethod
    def concatenate(parts: list["Columns"]) -> "Columns":
        return Columns(**{f.name: np.concatenate([getattr(p, f.name) for p in parts]) for f in fields(Columns)})


class LandingTracker:
    """Incremental :func:`boatland.trial.events.landing_offset`: feed consecutive blocks of (mode, tpos)
    and get the same distances as the whole-run function (the landing positions carry across blocks)."""

    def __init__(self, n_contacts: int, start_row: int = 0):
        self.anchor = np.full((n_contacts, 2), np.nan)   # landing position of each contact
        self.start_row = int(start_row)                  # rows before it are settling
        self.row = 0                                     # rows fed so far

    def __call__(self, mode: np.ndarray, tpos: np.ndarray) -> np.ndarray:
        out = np.empty(mode.shape)
        track_landing(np.ascontiguousarray(mode, dtype=np.int64), np.ascontiguousarray(tpos, dtype=float),
                      self.anchor, out, max(0, self.start_row - self.row))
        self.row += mode.shape[0]
        return out


def settle_row(info) -> int:
    """Row at which a trial has settled (thrust on, waves beginning): landing positions are taken from it."""
    return int(round(float(info.provenance.get("waves_from", 0.0)) / info.dt))


def world_pose(x: np.ndarray, start_pose) -> tuple[np.ndarray, np.ndarray]:
    """World translation (n, 3) and rotation quaternion (n, 4, xyzw) of the reference point.

    ``x`` (n, 6) is in the local frame of ``start_pose = (x0, y0, psi)`` (DESIGN.md §2); the rotation is
    R = Rz(ψ + yaw) Ry(pitch) Rx(roll), as :func:`boatland.rigid.rotation_matrix`.
    """
    x0, y0, psi = start_pose
    c, s = np.cos(psi), np.sin(psi)
    tr = np.empty((len(x), 3))
    tr[:, 0] = x0 + c * x[:, 0] - s * x[:, 1]
    tr[:, 1] = y0 + s * x[:, 0] + c * x[:, 1]
    tr[:, 2] = x[:, 2]
    hr, hp, hy = 0.5 * x[:, 3], 0.5 * x[:, 4], 0.5 * (x[:, 5] + psi)
    cr, sr, cp, sp, cy, sy = np.cos(hr), np.sin(hr), np.cos(hp), np.sin(hp), np.cos(hy), np.sin(hy)
    q = np.empty((len(x), 4))
    q[:, 0] = sr * cp * cy - cr * sp * sy
    q[:, 1] = cr * sp * cy + sr * cp * sy
    q[:, 2] = cr * cp * sy - sr * sp * cy
    q[:, 3] = cr * cp * cy + sr * sp * sy
    return tr, q


class BowElevation:
    """Wave elevation [m] at the bow (mean of the fender points) at rest, block by block — with the
    pile's scattered wave when the trial has it (:func:`boatland.record.scene.sea_coefficients`) —
    ramped in as the excitation is (:func:`boatland.trial.simulate.wave_ramp`); zeros without waves.

    The components and their coefficients at the bow are prepared once; ``self(k0, k1)`` sums rows
    k0 … k1 − 1 only, so a logger writes each block as soon as the kernel has finished it instead of
    computing the whole run's sea first.
    """

    def __init__(self, info):
        from boatland.record.scene import pile_of, sea_coefficients
        from boatland.trial.simulate import wave_ramp

        self.dt, n = info.dt, info.n_steps
        self.omega = None
        if info.waves is None:
            return
        P = np.asarray(info.contacts[0]).reshape(-1, 3)
        bx, by = (P[:, :2].mean(axis=0) if len(P) else np.zeros(2))
        x0, y0, psi = info.start_pose
        gx, gy = x0 + np.cos(psi) * bx - np.sin(psi) * by, y0 + np.sin(psi) * bx + np.cos(psi) * by
        comps = info.waves.realise(info.scenario.simulation.seed, n * self.dt)
        self.omega = comps.omega
        self.coef = sea_coefficients(comps, gx, gy, pile_of(info.setup, info.waves))
        self.ramp = wave_ramp(info.scenario, self.dt, n)[::2]

    def __call__(self, k0: int, k1: int) -> np.ndarray:
        from boatland.waves.synthesis import harmonic_series

        if self.omega is None:
            return np.zeros(k1 - k0)
        return harmonic_series(self.omega, self.coef, k0 * self.dt, self.dt, k1 - k0)[:, 0] * self.ramp[k0:k1]


def bow_elevation(info) -> np.ndarray:
    """The whole run's :class:`BowElevation` (n_steps + 1,)."""
    return BowElevation(info)(0, info.n_steps + 1)
