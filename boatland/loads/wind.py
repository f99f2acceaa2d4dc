r"""Wind on the topsides: a mean speed with gusts, dragging the hull above the waterline.

``[wind] speed`` is the 1-hour mean wind speed :math:`U_0` at 10 m above the sea, ``relative_direction_deg``
(or ``direction_deg``, global) the direction the air moves *towards*, in the sea's convention (180° onto the
bow). The load is the drag law of :mod:`boatland.loads.drag` on the above-water areas, with the wind at the
height :math:`z_c` of their centroid (the NPD / Frøya model, DNV-RP-C205 (2010) §2.3.2.11, ISO 19901-1):

.. math::
    U(z) = U_0\left[1 + C\ln\frac{z}{10}\right], \qquad C = 5.73\cdot10^{-2}\sqrt{1 + 0.148\,U_0},

    S(f) = \frac{320\,(U_0/10)^2\,(z/10)^{0.45}}{\left(1 + \tilde f^{\,n}\right)^{5/(3n)}}, \qquad
    \tilde f = 172\,f\,(z/10)^{2/3}(U_0/10)^{-3/4}, \quad n = 0.468

(S in m²/s² per Hz, f in Hz). The gusts u(t) are a Gaussian process with that spectrum, synthesised with
seeded random phases (:func:`gust_series`, its own random stream of the trial's seed, so that the sea of a
seed does not change when wind is added); the force is :math:`F(t) = F_1\,(U(z_c) + u(t))\,|U(z_c) + u(t)|`
with :math:`F_1` the load of a unit wind from the mean direction. Left out, and said so: the hull's own
velocity in the relative wind (≤ 0.1 m/s on a landed vessel against winds of metres per second), gusts
across the mean direction and their spatial coherence over the vessel (gusts are hundreds of metres long at
the periods a landed vessel feels).

Default coefficients (:data:`DEFAULTS`): Fossen (2011), *Handbook of Marine Craft Hydrodynamics and Motion
Control*, Wiley, ch. 10, wind on a vessel at rest, :math:`C_X = c_x\cos\theta`, :math:`C_Y = c_y\sin\theta`
with c_x ∈ [0.50, 0.90], c_y ∈ [0.70, 0.95]: the ranges' middles, c_x = 0.7 and c_y = 0.825; c_n = 0 (the
yaw moment is the lateral force's lever about the centroid of the lateral area: ctv27's deckhouse stands aft,
1.2 m aft of the reference point). Areas measured on the vessel's topsides mesh above the waterline (ctv27:
lateral 88.2 m², frontal 33.7 m², centroid 1.94 m above the waterline). Air density 1.225 kg/m³ (ISO 2533
standard atmosphere at sea level, 15 °C).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.loads.drag import DragLoad, drag_keys, geometry_from, global_direction, linear_table, table_from
from boatland.tomlspec import Key, Table

__all__ = ["DEFAULTS", "RHO_AIR", "SPECTRA", "WIND_TABLE", "Wind", "gust_series", "mean_speed", "npd_spectrum"]

#: Air density [kg/m³]: ISO 2533 standard atmosphere at sea level (15 °C, 101.325 kPa).
RHO_AIR = 1.225
DEFAULTS = {"c_x": 0.7, "c_y": 0.825, "c_n": 0.0,
            "source": "Fossen (2011) ch. 10 wind coefficients of a vessel at rest, the middles of c_x 0.50–0.90 and "
                      "c_y 0.70–0.95 (boatland.loads.wind)"}
SPECTRA = ("npd", "none")
#: Highest gust frequency synthesised [Hz]: the NPD spectrum at 2 Hz holds < 0.5 % of the variance at 10 m/s,
#: and a landed CTV's slowest contact modes are below 1 Hz.
F_MAX = 2.0
#: Gust frequencies are spaced 1/GUST_RECORD [Hz] (whatever the trial's length up to it): a seed gives the
#: same gusts for any duration up to an hour and any time step.
GUST_RECORD = 3600.0
#: Samples per second of the gusts' synthesis grid (:func:`gust_series`).
GUST_RATE = 32
#: The wind's random stream: the trial's seed and this key (ASCII "WIND").
STREAM = 0x57494E44

#: ``[wind]`` of a scenario file.
WIND_TABLE = Table({
    "speed": Key(float, required=True, ge=0.0, doc="1-hour mean wind speed U_0 at 10 m above the sea [m/s]"),
    "direction_deg": Key(float, doc="global direction the air moves towards [deg] (or relative_direction_deg)"),
    "relative_direction_deg": Key(float, doc="direction the air moves towards relative to the vessel's x axis "
                                             "[deg]: 180 = onto the bow, 90 = towards port"),
    "spectrum": Key(str, default="npd", choices=SPECTRA, doc="gusts: 'npd' (NPD/Frøya, DNV-RP-C205 §2.3.2.11) or "
                                                             "'none' (the mean wind only)"),
    **drag_keys("wind", DEFAULTS),
}, optional=True, doc="wind on the topsides, with gusts (absent: none)")


def mean_speed(U0: float, z: float) -> float:
    """1-hour mean wind speed [m/s] at height z [m] (NPD profile, module docstring)."""
    C = 5.73e-2 * math.sqrt(1.0 + 0.148 * U0)
    return U0 * (1.0 + C * math.log(max(z, 1.0) / 10.0))


def npd_spectrum(f, U0: float, z: float) -> np.ndarray:
    """NPD (Frøya) gust spectrum S(f) [m²/s² per Hz] at height z for the 1-hour mean U_0 at 10 m."""
    f = np.asarray(f, dtype=float)
    n = 0.468
    ft = 172.0 * f * (z / 10.0) ** (2.0 / 3.0) * (U0 / 10.0) ** -0.75
    return 320.0 * (U0 / 10.0) ** 2 * (z / 10.0) ** 0.45 / (1.0 + ft ** n) ** (5.0 / (3.0 * n))


def gust_series(U0: float, z: float, seed: int, dt: float, n_steps: int) -> np.ndarray:
    r"""Gusts u(t) [m/s] at the half steps t = k Δt/2, k = 0 … 2 n_steps.

    Components at :math:`f_k = k/T_g` up to :data:`F_MAX` (T_g = :data:`GUST_RECORD`, or the trial's length
    in whole seconds when longer) of amplitude :math:`\sqrt{2 S(f_k)\,\Delta f}` and uniform random phases
    from the seed's wind stream, summed by an inverse FFT on a grid of 1/:data:`GUST_RATE` s and interpolated
    linearly to the half steps (amplitude error below 1.3 % at 2 Hz, 0.1 % at 0.5 Hz). The series is the same
    for any time step and any duration up to T_g.
    """
    h = dt / 2.0
    m = 2 * n_steps + 1
    T_g = max(GUST_RECORD, float(math.ceil(m * h)))
    N = int(round(T_g * GUST_RATE))
    K = int(F_MAX * T_g)
    rng = np.random.default_rng([int(seed), STREAM])
    phase = rng.uniform(0.0, 2.0 * np.pi, size=K)
    fk = np.arange(1, K + 1) / T_g
    amp = np.sqrt(2.0 * npd_spectrum(fk, U0, z) / T_g)
    X = np.zeros(N // 2 + 1, dtype=complex)
    X[1:K + 1] = 0.5 * N * amp * np.exp(1j * phase)
    u = np.fft.irfft(X, N)
    t = np.arange(m) * h
    return np.interp(t, np.arange(N) / GUST_RATE, u)


@dataclass(frozen=True, kw_only=True, eq=False)
class Wind:
    """A scenario's wind: ``speed`` U_0 [m/s] towards the global ``direction_deg``, the gust ``spectrum``, and
    the keys overriding the vessel-derived drag (``values``)."""

    speed: float
    direction_deg: float
    spectrum: str
    values: dict

    @classmethod
    def from_table(cls, t: dict, heading_deg: float) -> "Wind":
        return cls(speed=float(t["speed"]), direction_deg=global_direction(t, heading_deg),
                   spectrum=t.get("spectrum", "npd"), values=dict(t))

    @property
    def gusty(self) -> bool:
        """Whether the wind has gusts (a spectrum and a speed)."""
        return self.spectrum != "none" and self.speed > 0

    def load(self, db) -> DragLoad:
        """The drag load on the vessel of ``db`` (its topsides mesh above the waterline; air density).

        Raises
        ------
        ValueError
            The database has no topsides and the file did not give the areas (the message names the keys).
        """
        top = getattr(db, "topsides", None)
        geo = geometry_from(self.values, None if top is None else top.vertices, None if top is None else top.faces,
                            what="wind", per_hull=False, z_min=0.0)
        return DragLoad(rho=RHO_AIR, **table_from(self.values, linear_table, DEFAULTS, "given"), **geo)

    def force_series(self, load: DragLoad, heading_deg: float, seed: int, dt: float, n_steps: int) -> np.ndarray:
        """The wind's generalised force (2 n_steps + 1, 6) at the half steps, in the vessel's start axes."""
        z = max(float(load.centroid[2]), 1.0)
        u = np.full(2 * n_steps + 1, mean_speed(self.speed, z))
        if self.gusty:
            u += gust_series(self.speed, z, seed, dt, n_steps)
        return np.outer(u * np.abs(u), self.unit_force(load, heading_deg))

    def unit_force(self, load: DragLoad, heading_deg: float) -> np.ndarray:
        """The load (6,) of a wind of 1 m/s from the mean direction, in the vessel's start axes: F_1."""
        a = math.radians(self.direction_deg - heading_deg)
        return load.body_load((math.cos(a), math.sin(a)))

    def gust_variance(self, load: DragLoad) -> float:
        """σ_u² [m²/s²] of the synthesised gusts at the centroid's height (the discrete sum of
        :func:`gust_series` for records up to an hour), 0 without gusts."""
        if not self.gusty:
            return 0.0
        z = max(float(load.centroid[2]), 1.0)
        fk = np.arange(1, int(F_MAX * GUST_RECORD) + 1) / GUST_RECORD
        return float(np.sum(npd_spectrum(fk, self.speed, z)) / GUST_RECORD)

    def mean_force(self, load: DragLoad, heading_deg: float) -> np.ndarray:
        r"""The time-averaged wind load (6,) in the vessel's start axes: :math:`F_1\,(U(z_c)^2 + \sigma_u^2)`,
        the mean of :math:`F_1 (U + u)|U + u|` for gusts smaller than the mean speed."""
        U = mean_speed(self.speed, max(float(load.centroid[2]), 1.0))
        return self.unit_force(load, heading_deg) * (U * U + self.gust_variance(load))

    def gust_spectrum(self, load: DragLoad):
        r"""The one-sided spectrum [per rad/s] of :math:`g(t) = 2U(z_c)\,u(t)`, the gusts' force per unit
        F_1 linearised about the mean (:math:`S_g(\omega) = 4U^2 S(\omega/2\pi)/2\pi`, zero above
        :data:`F_MAX`); None without gusts."""
        if not self.gusty:
            return None
        z = max(float(load.centroid[2]), 1.0)
        U = mean_speed(self.speed, z)
        U0 = self.speed

        def S(omega):
            f = np.asarray(omega, dtype=float) / (2 * np.pi)
            return np.where((f > 0) & (f <= F_MAX), 4 * U * U * npd_spectrum(np.maximum(f, 1e-12), U0, z) / (2 * np.pi),
                            0.0)
        return S

    def text(self, heading_deg: float) -> str:
        rel = (self.direction_deg - heading_deg) % 360.0
        kn = self.speed / 0.514444
        return f"wind {self.speed:g} m/s ({kn:.0f} kn) towards {rel:.0f}° relative" + \
            (", gusts NPD" if self.spectrum == "npd" else ", no gusts")
