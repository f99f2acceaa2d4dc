r"""Sea states as validated, immutable model objects that compile to wave components.

Three kinds of waves, one interface — ``realise(seed, duration) -> Components`` (arrays of
:mod:`boatland.waves.realisation`) and ``excitation(db, ...)`` for the force series:

- :class:`SeaState`: a sum of :class:`~boatland.sea.spectra.SpectrumPart` (JONSWAP / Pierson–Moskowitz /
  TMA, each with its own mean direction and cos-2s spreading — swell plus wind sea, Grøtting 2015
  §4.2.3), realised with a seed (random-frequency rule of :mod:`boatland.waves.realisation`);
- :class:`RegularWave`: one Airy wave (H, T, direction, phase);
- :class:`MeasuredRecord`: a gauge record replayed through its FFT (Ferreira González 2023 §5.2.3).

The excitation of these waves on a vessel is assembled here too (:func:`wave_excitation`: the
database's X on the RK4 half-step grid, the pile's scattered wave added).

Every default is set here, once (the spectral parts': :mod:`boatland.sea.spectra`). Checks (errors raise
:class:`~boatland.tomlspec.SpecError`, a :class:`~boatland.errors.BoatlandInputError`, naming the field
and the valid range, all problems at once; doubtful but possible values warn with
:class:`~boatland.sea.spectra.SeaStateWarning`):

- H, T ≤ 0 → error (the parts' own checks: :func:`boatland.sea.spectra.spectrum_part_problems`);
- steepness past breaking → warning: H/λ (or Hs/λ_p) above Miche's (1944) limit
  :math:`\tanh(kh)/7` (1/7 in deep water);
- water depth ≤ 0, band or component counts that make no sense → error.

Directions are ``direction_deg`` in the global frame, the direction the waves travel *towards*
(:mod:`boatland.conventions`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from pathlib import Path
from typing import Any

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.sea.records import read_elevation_csv
from boatland.sea.spectra import SpectrumPart, finite_problem, is_number, positive_problem, sea_warning
from boatland.tomlspec import SpecError
from boatland.vessel.database import HydroDB
from boatland.vessel.directions import direction_problem, full_circle_excitation
from boatland.waves.dispersion import wavenumber_scalar
from boatland.waves.excitation import excitation_series
from boatland.waves.measured import record_components
from boatland.waves.realisation import (Components, concatenate, n_components_for, part_rng,
                                        random_frequency_components, regular_components)

__all__ = ["AMPLITUDES", "MeasuredRecord", "OUT_OF_BAND_WARN", "RegularWave", "SeaState", "TABULATED_DIRECTIONS",
           "WaveModel", "excitation_table", "pile_table_request", "wave_excitation"]

AMPLITUDES = ("deterministic", "rayleigh")

#: Miche (1944) limiting steepness H/λ = tanh(kh)/7.
BREAKING_STEEPNESS = 1.0 / 7.0
#: Above this share of the wave variance outside the database's band, excitation() warns.
OUT_OF_BAND_WARN = 0.01


def _steepness_warning(what: str, H: float, omega: float, h: float, g: float) -> str | None:
    k = wavenumber_scalar(omega, h, g)
    steep = H * k / (2.0 * math.pi)
    limit = BREAKING_STEEPNESS * (math.tanh(k * h) if math.isfinite(h) else 1.0)
    if steep > limit:
        return (f"{what}: steepness {steep:.3f} (height / wavelength {2 * math.pi / k:.3g} m) is past the "
                f"breaking limit {limit:.3f} (Miche: tanh(kh)/7); linear waves do not describe this sea")
    return None


def _depth_problems(out: list, h: Any, g: Any) -> None:
    positive_problem(out, "water_depth", h, "m", "water depth", allow_inf=True)
    if not is_number(g) or not 9.7 <= g <= 9.9:
        out.append(("g", f"must be the Earth's gravity in m/s² (9.78–9.83), got {g!r}"))


class WaveModel:
    """What every wave model offers: components and the excitation series (shared code)."""

    water_depth: float
    g: float

    def realise(self, seed=None, duration: float | None = None) -> Components:  # pragma: no cover
        raise NotImplementedError

    @property
    def default_ramp_time(self) -> float:  # pragma: no cover
        raise NotImplementedError

    def excitation(self, db: HydroDB, *, seed=None, dt: float, n_steps: int, x0: float = 0.0, y0: float = 0.0,
                   heading_deg: float = 0.0, ramp_time: float | None = None, pile=None) -> np.ndarray:
        """Excitation force series F (2 n_steps + 1, 6) on t = n dt/2 for a vessel in these waves.

        Realises the waves for ``duration = n_steps dt`` and calls :func:`wave_excitation`; warns when
        the database's water depth disagrees with this sea's at its peak frequency. ``ramp_time``
        defaults to :attr:`default_ramp_time`. ``pile``: the :class:`~boatland.sea.pile.Pile` whose
        scattered wave is added (see :func:`wave_excitation`).
        """
        duration = n_steps * dt
        comps = self.realise(seed, duration)
        waves = comps.omega > 0
        if np.any(waves):
            wref = float(comps.omega[waves][np.argmax(comps.a[waves])])
            k_sea = wavenumber_scalar(wref, self.water_depth, self.g)
            k_db = wavenumber_scalar(wref, db.water_depth, db.g)
            if abs(k_db / k_sea - 1.0) > 0.01:
                sea_warning(f"the database {db.name!r} was computed for water depth {db.water_depth:g} m, these waves "
                      f"for {self.water_depth:g} m: wavelengths differ by {100 * abs(k_sea / k_db - 1):.1f} % at "
                      f"ω = {wref:.3g} rad/s", stacklevel=3)
        T_ramp = self.default_ramp_time if ramp_time is None else ramp_time
        return wave_excitation(comps, db, dt=dt, n_steps=n_steps, x0=x0, y0=y0, heading_deg=heading_deg,
                               ramp_time=T_ramp, pile=pile)

    def pile_table_request(self, *, seed=None, dt: float, n_steps: int, x0: float = 0.0, y0: float = 0.0,
                           heading_deg: float = 0.0, pile=None):
        """The ω tables of the pile's scattered wave that :meth:`excitation` with the same arguments
        interpolates, as a :class:`~boatland.sea.pile.TableRequest` (None: none;
        :func:`pile_table_request`). Made once (:func:`~boatland.sea.pile.scattered_tables`;
        a campaign makes those of every case together, :func:`~boatland.sea.pile.make_tables`),
        they serve every trial of the same layout and sea directions, in this process or another
        (:func:`~boatland.sea.pile.remember_tables`)."""
        if pile is None:
            return None
        comps = self.realise(seed, n_steps * dt)
        return pile_table_request(comps, x0=x0, y0=y0, heading_deg=heading_deg, pile=pile)


@dataclass(frozen=True, kw_only=True)
class SeaState(WaveModel):
    r"""An irregular sea: one or more spectral parts, realised with a seed.

    Parameters
    ----------
    parts : SpectrumPart or sequence of SpectrumPart
        The wave systems (e.g. swell + wind sea), each with its own direction and spreading.
    water_depth : float
        Water depth h [m]; ``inf`` (default) for deep water. Sets k_i and the TMA depth factor.
    g : float
        Gravity [m/s²].
    n_components : int
        Minimum number of components per part (default 256); the non-repetition rule may require
        more: N = max(n_components, ⌈max(T_dur, repeat_period) (ω_hi − ω_lo) / 2π⌉)
        (:mod:`boatland.waves.realisation`).
    repeat_period : float
        Shortest record [s] the components must not repeat within (default 600 s), whatever the
        duration asked. The sea is fixed by the seed, the spectrum and these component settings
        (n_components, repeat_period, band_tail, omega_min/max, amplitudes): every record up to
        ``repeat_period`` long is the start of the same sea (a 60-s run is the first minute of the
        600-s run of the same seed). A longer record needs more components to keep the non-repetition
        rule and so draws a different sea: set ``repeat_period`` to the longest duration that must
        share one sea.
    band_tail : float
        Fraction of each part's variance left outside its band, half at each end (default 0.002:
        the realised Hs is 0.999 of the target); :func:`boatland.waves.spectra.spectrum_band`.
    omega_min, omega_max : float or None
        Explicit band [rad/s] for every part instead of the ``band_tail`` rule.
    amplitudes : {"deterministic", "rayleigh"}
        a_i = √(2 S Δω) (default) or Rayleigh-distributed with that mean square.

    Examples
    --------
    >>> sea = SeaState(parts=(SpectrumPart(Hs=1.3, Tp=5.0, direction_deg=0.0, spreading=10.0),
    ...                       SpectrumPart(Hs=1.0, Tp=10.0, kind="pm", direction_deg=45.0)))
    >>> comps = sea.realise(seed=1, duration=1800.0)
    """

    parts: tuple[SpectrumPart, ...]
    water_depth: float = math.inf
    g: float = 9.81
    n_components: int = 256
    repeat_period: float = 600.0
    band_tail: float = 0.002
    omega_min: float | None = None
    omega_max: float | None = None
    amplitudes: str = "deterministic"

    def __post_init__(self):
        parts = (self.parts,) if isinstance(self.parts, SpectrumPart) else tuple(self.parts)
        out: list[tuple[str, str]] = []
        if not parts:
            out.append(("parts", "must hold at least one SpectrumPart"))
        for i, p in enumerate(parts):
            if not isinstance(p, SpectrumPart):
                out.append((f"parts[{i}]", f"must be a SpectrumPart, got {type(p).__name__}"))
        _depth_problems(out, self.water_depth, self.g)
        n = self.n_components
        if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1:
            out.append(("n_components", f"must be an integer ≥ 1 (minimum wave components per part), got {n!r}"))
        if not is_number(self.repeat_period) or not 0.0 < self.repeat_period < math.inf:
            out.append(("repeat_period", "must be a finite time > 0 s (the shortest record the components must "
                                         f"not repeat within), got {self.repeat_period!r}"))
        if not is_number(self.band_tail) or not 0.0 < self.band_tail <= 0.1:
            out.append(("band_tail", "must be in (0, 0.1] (variance fraction outside the band), "
                                     f"got {self.band_tail!r}"))
        lo, hi = self.omega_min, self.omega_max
        if (lo is None) != (hi is None):
            out.append(("omega_min" if lo is None else "omega_max", "give both omega_min and omega_max, or neither"))
        elif lo is not None:
            if positive_problem(out, "omega_min", lo, "rad/s", "lowest wave frequency") and \
                    positive_problem(out, "omega_max", hi, "rad/s", "highest wave frequency") and not hi > lo:
                out.append(("omega_max", f"must be > omega_min = {lo:g} rad/s, got {hi:g}"))
        if self.amplitudes not in AMPLITUDES:
            out.append(("amplitudes", f"must be one of {', '.join(map(repr, AMPLITUDES))}, got {self.amplitudes!r}"))
        if out:
            raise SpecError("sea state", out)
        object.__setattr__(self, "parts", parts)
        object.__setattr__(self, "water_depth", float(self.water_depth))
        object.__setattr__(self, "g", float(self.g))
        object.__setattr__(self, "n_components", int(n))
        object.__setattr__(self, "repeat_period", float(self.repeat_period))
        for i, p in enumerate(parts):
            w = _steepness_warning(f"sea state: parts[{i}] (Hs {p.Hs:g} m, Tp {p.Tp:g} s)", p.Hs, p.omega_p,
                                   self.water_depth, self.g)
            if w:
                sea_warning(w)

    # ------------------------------------------------------------------ spectra
    def spectrum(self, omega) -> np.ndarray:
        """Sum of the parts' S(ω) [m² s/rad]."""
        return sum(p.spectrum(omega, self.water_depth, self.g) for p in self.parts)

    def directional_spectrum(self, omega, theta) -> np.ndarray:
        r"""S(ω, θ) = Σ_p S_p(ω) D_p(θ) [m² s/rad²], shape (len(omega), len(theta)) (θ in rad).

        A long-crested part is a line at its direction and cannot be written as a density: it is left
        out here (see :meth:`spectrum`).
        """
        w = np.atleast_1d(np.asarray(omega, float))
        th = np.atleast_1d(np.asarray(theta, float))
        out = np.zeros((w.size, th.size))
        for p in self.parts:
            if p.spreading is not None:
                out += np.outer(p.spectrum(w, self.water_depth, self.g), p.spreading_function(th))
        return out

    def band(self, part: int = 0) -> tuple[float, float]:
        """Frequency band [rad/s] the components of ``parts[part]`` are drawn from."""
        if self.omega_min is not None:
            return float(self.omega_min), float(self.omega_max)
        return self.parts[part].band(self.band_tail)

    def n_components_for(self, duration: float) -> list[int]:
        """Components per part for a record of ``duration`` seconds: the non-repetition rule over
        max(duration, :attr:`repeat_period`), so every record up to ``repeat_period`` is the same sea."""
        span = max(float(duration), self.repeat_period)
        return [max(self.n_components, n_components_for(span, *self.band(i))) for i in range(len(self.parts))]

    def hm0(self) -> float:
        r""":math:`4\sqrt{m_0}` [m] of the whole spectrum (all parts; < the parts' Hs for TMA in shallow water)."""
        m0 = 0.0
        for p in self.parts:
            m0 += p.m0(self.water_depth, self.g)
        return 4.0 * math.sqrt(m0)

    @property
    def default_ramp_time(self) -> float:
        """Start-up ramp [s]: twice the longest peak period of the parts."""
        return 2.0 * max(p.Tp for p in self.parts)

    # ------------------------------------------------------------------ realisation
    def realise(self, seed=None, duration: float | None = None) -> Components:
        """Seeded wave components for a record of ``duration`` seconds (parts concatenated in order).

        Parameters
        ----------
        seed : int or numpy.random.SeedSequence
            Same seed → bitwise the same components; part p draws from the seed's child p
            (:func:`boatland.waves.realisation.part_rng`).
        duration : float
            Simulated time [s] (> 0): sets the component count by the non-repetition rule.
        """
        if seed is None:
            raise ValueError("an irregular sea needs a seed (int or numpy.random.SeedSequence); "
                             "unseeded waves could not be reproduced")
        if duration is None or not is_number(duration) or not duration > 0 or not math.isfinite(duration):
            raise ValueError(f"duration must be a finite time > 0 s, got {duration!r}")
        out = []
        for i, (p, n) in enumerate(zip(self.parts, self.n_components_for(duration))):
            lo, hi = self.band(i)
            edges = np.linspace(lo, hi, n + 1)
            V = p.bin_variance(edges, self.water_depth, self.g)
            out.append(random_frequency_components(
                edges, V, math.radians(p.direction_deg), p.spreading or 0.0, part_rng(seed, i),
                rayleigh=self.amplitudes == "rayleigh", h=self.water_depth, g=self.g))
        return concatenate(out)


@dataclass(frozen=True, kw_only=True)
class RegularWave(WaveModel):
    r"""A regular (Airy) wave: η(0, 0, t) = (H/2) cos(2π t / T + phase).

    Parameters
    ----------
    H : float
        Wave height, crest to trough [m] (> 0).
    T : float
        Period [s] (> 0).
    direction_deg : float
        Direction of travel, global frame [deg].
    phase_deg : float
        Phase at the global origin [deg] (0: a crest at the origin at t = 0).
    water_depth, g : float
        Depth [m] (``inf`` deep) and gravity [m/s²].
    """

    H: float
    T: float
    direction_deg: float = 0.0
    phase_deg: float = 0.0
    water_depth: float = math.inf
    g: float = 9.81

    def __post_init__(self):
        out: list[tuple[str, str]] = []
        positive_problem(out, "H", self.H, "m", "wave height, crest to trough")
        positive_problem(out, "T", self.T, "s", "wave period")
        finite_problem(out, "direction_deg", self.direction_deg, "direction the wave travels towards [deg]")
        finite_problem(out, "phase_deg", self.phase_deg, "phase at the global origin [deg]")
        _depth_problems(out, self.water_depth, self.g)
        if out:
            raise SpecError("regular wave", out)
        for f in fields(self):
            object.__setattr__(self, f.name, float(getattr(self, f.name)))
        w = _steepness_warning(f"regular wave (H {self.H:g} m, T {self.T:g} s)", self.H, self.omega,
                               self.water_depth, self.g)
        if w:
            sea_warning(w)

    @property
    def omega(self) -> float:
        return 2.0 * math.pi / self.T

    @property
    def default_ramp_time(self) -> float:
        """Start-up ramp [s]: two periods."""
        return 2.0 * self.T

    def realise(self, seed=None, duration: float | None = None) -> Components:
        """The one component (``seed`` and ``duration`` are ignored: a regular wave is deterministic)."""
        return regular_components(self.H, self.T, math.radians(self.direction_deg), math.radians(self.phase_deg),
                                  self.water_depth, self.g)


@dataclass(frozen=True, kw_only=True, eq=False)
class MeasuredRecord(WaveModel):
    r"""A wave gauge record replayed through its FFT (Ferreira González 2023 §5.2.3; :mod:`boatland.waves.measured`).

    Usually made with :meth:`from_csv`. Simulation time 0 is the first sample; the replay repeats
    with the record length (:meth:`realise` warns when the duration exceeds it).

    Parameters
    ----------
    eta : ndarray, shape (M,)
        Elevation samples [m], uniformly spaced, finite.
    dt : float
        Sample step [s].
    gauge_x, gauge_y : float
        Gauge position in the global frame [m].
    direction_deg : float
        Direction the recorded (long-crested) waves travel towards, global frame [deg].
    n_components : int or None
        Keep the N largest components (Ferreira González 2023 kept 20), or all (None, default: exact replay).
    remove_mean : bool
        Drop the record's mean (a water level, not a wave); default True.
    water_depth, g : float
        Depth [m] and gravity [m/s²] (for moving the record from the gauge to the vessel).
    source : str
        Where the record came from (file name), for messages.
    """

    eta: np.ndarray
    dt: float
    gauge_x: float = 0.0
    gauge_y: float = 0.0
    direction_deg: float = 0.0
    n_components: int | None = None
    remove_mean: bool = True
    water_depth: float = math.inf
    g: float = 9.81
    source: str = "wave record"

    def __post_init__(self):
        out: list[tuple[str, str]] = []
        eta = np.asarray(self.eta, dtype=float).reshape(-1) if np.ndim(self.eta) else np.zeros(0)
        if eta.size < 4:
            out.append(("eta", f"must hold at least 4 samples, got {eta.size}"))
        elif not np.all(np.isfinite(eta)):
            i = int(np.flatnonzero(~np.isfinite(eta))[0])
            out.append(("eta", f"sample {i} is {eta[i]}; every sample must be finite"))
        positive_problem(out, "dt", self.dt, "s", "sample step")
        for name in ("gauge_x", "gauge_y", "direction_deg"):
            finite_problem(out, name, getattr(self, name), "gauge position [m]" if name != "direction_deg" else
                    "direction the waves travel towards [deg]")
        n = self.n_components
        if n is not None and (not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1):
            out.append(("n_components", f"must be an integer ≥ 1 or None for all, got {n!r}"))
        _depth_problems(out, self.water_depth, self.g)
        if out:
            raise SpecError(self.source, out)
        eta = eta.copy()
        eta.setflags(write=False)
        object.__setattr__(self, "eta", eta)
        for name in ("dt", "gauge_x", "gauge_y", "direction_deg", "water_depth", "g"):
            object.__setattr__(self, name, float(getattr(self, name)))

    @classmethod
    def from_csv(cls, path, *, column: int = 1, time_rtol: float = 0.01, **kwargs) -> "MeasuredRecord":
        """Read a CSV of time [s], elevation [m] (:func:`boatland.sea.records.read_elevation_csv`).

        ``column`` is the 0-based elevation column; ``time_rtol`` the allowed relative deviation of a
        time step from the median. Other keywords are fields of this class.
        """
        t, eta = read_elevation_csv(path, column=column, rtol=time_rtol)
        return cls(eta=eta, dt=float((t[-1] - t[0]) / (t.size - 1)), source=str(Path(path)), **kwargs)

    @property
    def length(self) -> float:
        """Record length M Δt [s] (the replay's period)."""
        return self.eta.size * self.dt

    @property
    def default_ramp_time(self) -> float:
        """Start-up ramp [s]: two periods of the largest component."""
        c = self.realise()
        waves = c.omega > 0
        if not np.any(waves):
            return 0.0
        return 2.0 * 2.0 * math.pi / float(c.omega[waves][np.argmax(c.a[waves])])

    def realise(self, seed=None, duration: float | None = None) -> Components:
        """The record's components, phases at the global origin (``seed`` is ignored)."""
        if duration is not None and duration > self.length * (1 + 1e-9):
            sea_warning(f"{self.source}: the simulation ({duration:g} s) is longer than the record ({self.length:g} s); "
                  "the replay repeats the record periodically", stacklevel=3)
        return record_components(self.eta, self.dt, self.gauge_x, self.gauge_y, math.radians(self.direction_deg),
                                 self.n_components, self.remove_mean, self.water_depth, self.g)


# ---------------------------------------------------------------------- excitation
def excitation_table(db: HydroDB) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""(omega, beta_deg, X) of a database for :func:`boatland.waves.excitation.excitation_series`.

    The one place the time domain (:func:`wave_excitation`) and the frequency domain
    (:func:`boatland.freqdomain.rao.excitation_force`) take X from. Two steps:

    - directions: a half-circle table of a hull the database shows port–starboard symmetric is
      completed to the circle by :math:`X_j(360° - \beta) = s_j X_j(\beta)`
      (:func:`boatland.vessel.directions.full_circle_excitation`); any other table is returned
      as it is, and :func:`~boatland.waves.excitation.interpolate_excitation` then uses it
      periodically only if it goes round the circle (NaN outside otherwise; users get a message
      first from :func:`boatland.vessel.directions.direction_problem`);
    - frequencies: prepends ω = 0 with the exact long-wave limit :math:`X(0, \beta) = C_{:,2}` (0-based
      heave column of the restoring matrix: a wave much longer than the vessel is a slow rise of the
      water level, which pushes like a heave displacement of −a; real, in phase with the crest, the
      same for every β), so the low end interpolates towards it instead of holding X(ω_min).
    """
    omega = np.asarray(db.omega, float)
    beta, X = full_circle_excitation(db)
    if omega[0] > 0:
        X0 = np.broadcast_to(np.asarray(db.C, float)[:, 2][:, None, None], (X.shape[0], X.shape[1], 1))
        omega = np.concatenate([[0.0], omega])
        X = np.concatenate([X0.astype(complex), X], axis=2)
    return omega, np.asarray(beta, float), X


#: Seas of at most this many distinct directions get the pile's scattered wave from cached ω tables
#: (:func:`boatland.sea.pile.pile_scattered_interpolated`); more (short-crested) exactly.
TABULATED_DIRECTIONS = 8


def _pile_layout(components: Components, x0: float, y0: float, pile):
    """(radius, position relative to the pile axis, depth or None for deep water, mask of the
    components with ω > 0, whether their X^s comes from the ω tables) for a :class:`~boatland.sea.pile.Pile`."""
    waves = components.omega > 0
    tabulated = np.unique(components.theta[waves]).size <= TABULATED_DIRECTIONS   # long-crested: cached ω tables
    depth = pile.water_depth
    return pile.radius, pile.offset(x0, y0), None if math.isinf(depth) else depth, waves, tabulated


def pile_table_request(components: Components, *, x0: float = 0.0, y0: float = 0.0, heading_deg: float = 0.0,
                       pile=None):
    """The ω tables of the pile's scattered wave that :func:`wave_excitation` with the same arguments
    interpolates, as the arguments of :func:`boatland.sea.pile.scattered_tables`
    (:class:`~boatland.sea.pile.TableRequest`); None without a pile or for a sea of more
    than :data:`TABULATED_DIRECTIONS` directions (its scattered wave is summed exactly)."""
    if pile is None:
        return None
    from boatland.sea.pile import TableRequest

    radius, position, depth, waves, tabulated = _pile_layout(components, x0, y0, pile)
    if not tabulated or not np.any(waves):
        return None
    return TableRequest(position, heading_deg, radius, components.theta[waves], depth)


def wave_excitation(components: Components, db: HydroDB, *, dt: float, n_steps: int, x0: float = 0.0,
                    y0: float = 0.0, heading_deg: float = 0.0, ramp_time: float = 0.0, pile=None) -> np.ndarray:
    r"""Excitation force series on the RK4 grid t_n = n Δt/2, n = 0..2 n_steps, body frame.

    .. math::
        F(t) = r(t)\sum_i a_i\,\mathrm{Re}\{X(\omega_i, \theta_i - \psi)\,
               e^{i(\omega_i t - k_i(x_0\cos\theta_i + y_0\sin\theta_i) + \varphi_i)}\}

    (:mod:`boatland.waves.excitation`; X from :func:`excitation_table`). Warns
    (:class:`SeaStateWarning`) when components above the database's ω_max — whose force is taken as
    zero — carry more than 1 % of the wave variance.

    Parameters
    ----------
    components : Components
        The waves (:meth:`SeaState.realise` and friends).
    db : HydroDB
        The vessel's database.
    dt : float
        Integrator step [s].
    n_steps : int
        Number of steps: the series has 2 n_steps + 1 rows.
    x0, y0 : float
        Reference point of the vessel in the global frame [m].
    heading_deg : float
        Heading ψ of the vessel's x axis in the global frame [deg].
    ramp_time : float
        Half-cosine start-up ramp [s] (0 = none).
    pile : Pile, optional
        A bottom-mounted monopile (:class:`boatland.sea.pile.Pile`): the Froude–Krylov force of its scattered wave (MacCamy–Fuchs) on the
        hull panels is added at every component (San Nicolás Méndez 2024 eq. 3.21–3.22, 4.5) — from a cached ω table
        for long-crested seas (:func:`boatland.sea.pile.pile_scattered_interpolated`),
        else exactly (:func:`~boatland.sea.pile.pile_scattered_components`). The vessel's
        own scattering of the pile's wave is neglected, as in San Nicolás Méndez 2024.

    Returns
    -------
    ndarray, shape (2 n_steps + 1, 6)

    Raises
    ------
    BoatlandInputError
        A component's direction relative to the vessel is outside the database's directions (a
        database that does not go round the circle and is not a symmetric half circle:
        :func:`boatland.vessel.directions.direction_problem`).
    """
    if not (is_number(dt) and dt > 0 and math.isfinite(dt)):
        raise ValueError(f"dt must be a finite time step > 0 s, got {dt!r}")
    if not isinstance(n_steps, (int, np.integer)) or n_steps < 0:
        raise ValueError(f"n_steps must be an integer ≥ 0, got {n_steps!r}")
    if not (is_number(ramp_time) and ramp_time >= 0 and math.isfinite(ramp_time)):
        raise ValueError(f"ramp_time must be a finite time ≥ 0 s, got {ramp_time!r}")
    for name, v in (("x0", x0), ("y0", y0), ("heading_deg", heading_deg)):
        if not (is_number(v) and math.isfinite(v)):
            raise ValueError(f"{name} must be a finite number, got {v!r}")
    rel = np.unique(np.mod(np.degrees(components.theta) - heading_deg, 360.0))
    problem = direction_problem(db, rel)
    if problem:
        raise BoatlandInputError(f"wave directions relative to the vessel (heading {heading_deg:g}°): {problem}")
    omega, beta, X = excitation_table(db)
    X_extra = None
    if pile is not None:
        from boatland.sea.pile import pile_scattered_components, pile_scattered_interpolated

        radius, position, depth, waves, tabulated = _pile_layout(components, x0, y0, pile)
        scattered = pile_scattered_interpolated if tabulated else pile_scattered_components
        X_extra = np.zeros((6, components.size), dtype=complex)
        X_extra[:, waves] = scattered(db, position, heading_deg, radius, components.omega[waves],
                                      components.theta[waves], depth)
    F, _, n_above = excitation_series(components, omega, beta, X, float(x0), float(y0),
                                      math.radians(heading_deg), 0.0, 0.5 * dt, 2 * int(n_steps) + 1,
                                      float(ramp_time), X_extra)
    if n_above:
        above = components.omega > omega[-1]
        share = float(np.sum(components.a[above] ** 2) / max(np.sum(components.a ** 2), 1e-300))
        if share > OUT_OF_BAND_WARN:
            sea_warning(f"{n_above} of {components.size} wave components ({100 * share:.1f} % of the wave variance) lie "
                  f"above the database's highest frequency {omega[-1]:g} rad/s; their excitation is taken as zero "
                  f"(extend the database's band or lower omega_max)", stacklevel=3)
    return F
