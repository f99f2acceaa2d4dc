r"""A Gaussian sea driven by standard-normal coefficients u on a fixed frequency grid.

The rare-event estimators (:mod:`boatland.freqdomain.isee`, :mod:`boatland.campaign.isee`) need the sea
as an explicit function of a vector of independent standard-normal variables, so that every response
of the landed (linear) vessel is a linear function of it and the time-domain trial can be run on
*exactly* the same sea. For a spectrum of long-crested parts p (:class:`~boatland.sea.states.SeaState`),

.. math::
    \eta(0, 0, t) = \sum_i \sigma_i\left(u_{2i}\cos\omega_i t + u_{2i+1}\sin\omega_i t\right),
    \qquad \sigma_i^2 = \int_{m_i\Delta\omega}^{(m_i+1)\Delta\omega} S_{p(i)}(\omega)\,d\omega ,

the spectral representation of a stationary Gaussian process with random amplitudes (Shinozuka &
Deodatis 1991, *Appl. Mech. Rev.* 44(4), 191–204; Tucker, Challenor & Carter 1984): with u ~ N(0, I),
η is exactly Gaussian and :math:`E[\eta^2] = \sum_i \sigma_i^2` is the spectrum's variance in its band.
As wave components (:class:`~boatland.waves.realisation.Components`, η = Σ a cos(ωt − k·x + φ)):
:math:`a_i e^{i\varphi_i} = \sigma_i (u_{2i} - i\,u_{2i+1})`.

Frequency grid (deterministic — no random jitter)
    :math:`\omega_i = (m_i + \tfrac12)\Delta\omega`, :math:`\Delta\omega = 2\pi/(n_{fft}\Delta t)` with
    :math:`n_{fft} \ge n_{steps} + 1` (a length with small prime factors), for the integer m_i whose bins
    cover each part's band (:meth:`SeaState.band`). So :math:`\Delta\omega \le 2\pi/T_{dur}`: the record
    repeats only after :math:`n_{fft}\Delta t \ge T_{dur}` (the non-repetition rule of
    :mod:`boatland.waves.realisation`; the component count follows from the record length), and every
    response on the integrator's grid :math:`t_k = k\Delta t` is one inverse FFT of length n_fft,
    because :math:`\omega_i t_k = \pi k/n_{fft} + 2\pi m_i k/n_{fft}`.
Directions
    One per long-crested part (its own mean direction; swell + wind sea). Short-crested parts
    (cos-2s spreading) are refused: spreading would need a direction grid per frequency and as many
    more coefficients.
Amplitudes
    The Gaussian model itself (the random amplitudes come from u); ``SeaState.amplitudes`` is not used.

Conventions: :mod:`boatland.conventions` (global frame, direction of travel, exp(+iωt)).
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.sea.states import SeaState, WaveModel
from boatland.waves.dispersion import wavenumber
from boatland.waves.realisation import Components

__all__ = ["GaussianSea", "fft_length", "grid_series"]


def fft_length(n: int) -> int:
    """Smallest integer ≥ n whose prime factors are 2, 3 and 5 (a fast FFT length)."""
    n = max(1, int(n))
    best = 1 << (n - 1).bit_length()
    p5 = 1
    while p5 < best:
        p35 = p5
        while p35 < best:
            m = p35
            while m < n:
                m *= 2
            best = min(best, m)
            p35 *= 3
        p5 *= 5
    return best


@dataclass(frozen=True, kw_only=True, eq=False)
class GaussianSea(WaveModel):
    r"""A sea of long-crested spectral parts on a fixed frequency grid, driven by coefficients u.

    Parameters
    ----------
    sea : SeaState
        The spectrum: its parts (kind, Hs, Tp, γ, σ_a, σ_b, direction — long-crested), band rule, water
        depth and g.
    dt : float
        Integrator step Δt [s]: the grid's Δω = 2π/(n_fft Δt) is commensurate with it.
    n_steps : int
        Steps of the record (0 … n_steps Δt): n_fft ≥ n_steps + 1.
    u : ndarray, shape (2N,), optional
        Standard-normal coefficients (:attr:`n_coefficients`); needed by :meth:`realise`.

    Attributes
    ----------
    n_fft : int
    delta_omega : float
        Δω [rad/s].
    m : ndarray of int, shape (N,)
        Grid index of each component: ω_i = (m_i + ½)Δω.
    omega, sigma, theta, k : ndarray, shape (N,)
        Frequency [rad/s], standard deviation σ_i [m], direction of travel [rad] (global) and wave
        number [rad/m] of each component.
    part : ndarray of int, shape (N,)
        The spectral part each component belongs to.

    Raises
    ------
    BoatlandInputError
        A short-crested part, a bad step or step count, or u of the wrong shape or not finite.
    """

    sea: SeaState
    dt: float
    n_steps: int
    u: np.ndarray | None = None

    def __post_init__(self):
        if not isinstance(self.sea, SeaState):
            raise BoatlandInputError(f"GaussianSea needs a SeaState (spectral parts), got {type(self.sea).__name__}")
        spread = [i for i, p in enumerate(self.sea.parts) if p.spreading is not None]
        if spread:
            raise BoatlandInputError(f"sea.parts[{spread[0]}]: a Gaussian sea driven by coefficients supports "
                                     "long-crested parts only (each with its own direction); remove 'spreading'")
        if not (isinstance(self.dt, (int, float)) and math.isfinite(self.dt) and self.dt > 0):
            raise BoatlandInputError(f"GaussianSea: dt must be a finite step > 0 s, got {self.dt!r}")
        if not isinstance(self.n_steps, (int, np.integer)) or isinstance(self.n_steps, bool) or self.n_steps < 1:
            raise BoatlandInputError(f"GaussianSea: n_steps must be an integer ≥ 1, got {self.n_steps!r}")
        object.__setattr__(self, "dt", float(self.dt))
        object.__setattr__(self, "n_steps", int(self.n_steps))
        if "omega" not in self.__dict__:
            self._build_grid()
        if self.u is not None:
            object.__setattr__(self, "u", self._check_u(self.u))

    def _build_grid(self) -> None:
        n_fft = fft_length(self.n_steps + 1)
        dw = 2.0 * math.pi / (n_fft * self.dt)
        ms, sig, th, parts = [], [], [], []
        for i, p in enumerate(self.sea.parts):
            lo, hi = self.sea.band(i)
            m = np.arange(int(math.floor(lo / dw)), int(math.ceil(hi / dw)))
            edges = np.append(m, m[-1] + 1) * dw
            V = p.bin_variance(edges, self.sea.water_depth, self.sea.g)
            ms.append(m)
            sig.append(np.sqrt(np.maximum(V, 0.0)))
            th.append(np.full(m.size, math.radians(p.direction_deg) % (2.0 * math.pi)))
            parts.append(np.full(m.size, i))
        m = np.concatenate(ms)
        omega = (m + 0.5) * dw
        for name, value in (("n_fft", n_fft), ("delta_omega", dw), ("m", m), ("omega", omega),
                            ("sigma", np.concatenate(sig)), ("theta", np.concatenate(th)),
                            ("k", wavenumber(omega, self.sea.water_depth, self.sea.g)),
                            ("part", np.concatenate(parts))):
            if isinstance(value, np.ndarray):
                value.setflags(write=False)
            object.__setattr__(self, name, value)

    def _check_u(self, u) -> np.ndarray:
        u = np.array(u, dtype=float).reshape(-1)
        if u.size != self.n_coefficients:
            raise BoatlandInputError(f"GaussianSea: u has {u.size} coefficients, the grid has "
                                     f"{self.n_coefficients} (2 per component)")
        if not np.all(np.isfinite(u)):
            raise BoatlandInputError("GaussianSea: u must be finite")
        u.setflags(write=False)
        return u

    # ------------------------------------------------------------------ what WaveModel needs
    @property
    def water_depth(self) -> float:
        return self.sea.water_depth

    @property
    def g(self) -> float:
        return self.sea.g

    @property
    def default_ramp_time(self) -> float:
        return self.sea.default_ramp_time

    # ------------------------------------------------------------------ the grid
    @property
    def size(self) -> int:
        """Number of components N."""
        return int(self.omega.size)

    @property
    def n_coefficients(self) -> int:
        """Number of standard-normal coefficients, 2N."""
        return 2 * self.size

    @property
    def period(self) -> float:
        """n_fft Δt [s]: the record repeats after this time."""
        return self.n_fft * self.dt

    def with_u(self, u) -> "GaussianSea":
        """The same grid driven by ``u`` (shape (2N,)); the grid is not computed again."""
        new = object.__new__(GaussianSea)
        new.__dict__.update(self.__dict__)
        object.__setattr__(new, "u", self._check_u(u))
        return new

    def amplitudes(self, u=None) -> np.ndarray:
        r"""Complex amplitudes :math:`A_i = a_i e^{i\varphi_i} = \sigma_i(u_{2i} - i u_{2i+1})`, shape (N,)
        (η at the global origin is :math:`\mathrm{Re}\sum A_i e^{i\omega_i t}`)."""
        u = self._u(u)
        return self.sigma * (u[0::2] - 1j * u[1::2])

    def components(self, u=None) -> Components:
        """The wave components of coefficients ``u`` (default: this sea's)."""
        A = self.amplitudes(u)
        return Components(self.omega.copy(), self.k.copy(), np.abs(A), self.theta.copy(), np.angle(A))

    def realise(self, seed=None, duration: float | None = None) -> Components:
        """The components of this sea's ``u`` (``seed`` is not used: u is the randomness).

        Raises
        ------
        ValueError
            No ``u``, or ``duration`` beyond the record's period :attr:`period` (it would repeat).
        """
        if self.u is None:
            raise ValueError("this GaussianSea has no coefficients u: use with_u(u)")
        if duration is not None and duration > self.period * (1.0 + 1e-12):
            raise ValueError(f"duration {duration:g} s is longer than the Gaussian sea's period {self.period:g} s "
                             f"(its grid was made for {self.n_steps} steps of {self.dt:g} s)")
        return self.components()

    def elevation_series(self, u=None) -> np.ndarray:
        r"""η(0, 0, t_k) at t_k = kΔt, k = 0 … n_steps, by one inverse FFT (module docstring)."""
        c = np.zeros(self.n_fft, dtype=complex)
        np.add.at(c, self.m, self.amplitudes(u))
        return grid_series(c[None, :], self.n_fft, self.n_steps + 1)[0]

    def digest(self) -> str:
        """SHA-256 of the grid and u (provenance of a trial run on this sea)."""
        h = hashlib.sha256()
        for a in (self.omega, self.sigma, self.theta, self.u if self.u is not None else np.zeros(0)):
            h.update(np.ascontiguousarray(a, dtype=float).tobytes())
        return h.hexdigest()

    def _u(self, u) -> np.ndarray:
        if u is None:
            if self.u is None:
                raise ValueError("this GaussianSea has no coefficients u")
            return self.u
        return self._check_u(u)


def grid_series(c: np.ndarray, n_fft: int, n: int) -> np.ndarray:
    r"""Real series :math:`y_j(t_k) = \mathrm{Re}\{e^{i\pi k/n_{fft}}\sum_m c_{jm} e^{2\pi i mk/n_{fft}}\}`,
    k = 0 … n−1: the sums :math:`\mathrm{Re}\sum_i C_i e^{i\omega_i t_k}` of a :class:`GaussianSea`'s grid
    (:math:`\omega_i = (m_i + \tfrac12)\Delta\omega`) with the coefficients gathered by grid index,
    ``c`` (J, n_fft) complex. numpy's FFT (pocketfft) is serial: the result does not depend on threads."""
    z = np.fft.ifft(c, axis=-1)[:, :n] * n_fft
    k = np.arange(n)
    return (z * np.exp(1j * math.pi * k / n_fft)).real
