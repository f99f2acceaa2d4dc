r"""Spectral parts: one wave system of a sea (:class:`SpectrumPart`) and the spectrum shapes it can have.

A part owns its spectrum — its density S(ω), the band its components are drawn from, the variance of a
frequency bin, its m₀ — through its shape (:data:`SHAPES`, by ``kind``):

==========  ===================  =========================================================================
kind        shape                density (:mod:`boatland.waves.spectra`)
==========  ===================  =========================================================================
"jonswap"   :class:`Jonswap`     JONSWAP (Hasselmann et al. 1973) of Hs, Tp, γ (default 3.3), σ_a, σ_b,
                                 normalised so that 4√m₀ = Hs exactly
"pm"        :class:`PiersonMoskowitz`  Pierson–Moskowitz: JONSWAP with γ = 1
"gaussian"  :class:`GaussianSwell`  a narrow swell peak of width ``sigma_g`` [rad/s] (AQWA's ``GAUS``)
"tma"       :class:`TMA`         JONSWAP × Kitaigorodskii's depth factor (Bouws et al. 1985): the site's
                                 finite depth removes energy, 4√m₀ < Hs
==========  ===================  =========================================================================

A new shape is a class here, registered in :data:`SHAPES`, with its density in :mod:`boatland.waves.spectra`:
scenario files (``sea.kind`` and ``[[sea.parts]] kind``, :mod:`boatland.scenario.schema`), realisations,
the Gaussian sea of the rare-event sampler, the screening and every label then know it.

Checks (errors raise :class:`~boatland.tomlspec.SpecError` naming the field and the valid range, all at
once; doubtful values warn with :class:`SeaStateWarning`): Hs, Tp ≤ 0; γ outside [1, 10] (warning
outside 1–7: measured JONSWAP spectra, Ferreira González 2023 §2.4.1); σ_a, σ_b outside (0, 0.5];
spreading s ≤ 0. Directions are ``direction_deg`` in the global frame, the direction the waves travel
*towards* (:mod:`boatland.conventions`).
"""

from __future__ import annotations

import difflib
import math
import warnings
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from boatland.errors import BoatlandWarning
from boatland.tomlspec import SpecError
from boatland.waves.spectra import (SIGMA_A, SIGMA_B, bin_variance, gaussian_band, gaussian_bin_variance,
                                    gaussian_swell, spectrum_band, spreading_cos2s, tma)

__all__ = ["GAMMA_DEFAULT", "GAMMA_LIMITS", "GAMMA_USUAL", "KINDS", "SHAPES", "GaussianSwell", "Jonswap",
           "PiersonMoskowitz",
           "SeaStateWarning", "SpectralShape", "SpectrumPart", "TMA", "finite_problem", "is_number",
           "positive_problem", "sea_warning", "spectrum_part_problems"]

#: Default peak enhancement of JONSWAP and TMA parts (mean JONSWAP value, Hasselmann et al. 1973).
GAMMA_DEFAULT = 3.3
#: Measured JONSWAP γ lie in this range (Ferreira González 2023 §2.4.1); outside it (but in GAMMA_LIMITS) → warning.
GAMMA_USUAL = (1.0, 7.0)
GAMMA_LIMITS = (1.0, 10.0)


class SeaStateWarning(BoatlandWarning):
    """A wave input that is possible but probably not meant (outside the usual range, breaking, ...)."""


def sea_warning(message: str, stacklevel: int = 4) -> None:
    """Issue ``message`` as a :class:`SeaStateWarning`."""
    warnings.warn(message, SeaStateWarning, stacklevel=stacklevel)


def is_number(x: Any) -> bool:
    """A real number (Python or numpy), not a bool."""
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, (bool, np.bool_))


def positive_problem(out: list, key: str, x: Any, unit: str, what: str, allow_inf: bool = False) -> bool:
    """Append ``(key, message)`` to ``out`` unless ``x`` is a number > 0 (``allow_inf``: or inf); True if it is."""
    if not is_number(x) or not (x > 0) or (math.isinf(x) and not allow_inf) or math.isnan(x):
        rng = "> 0" + (f" {unit}" if unit else "") + (" (inf for deep water)" if allow_inf else "")
        out.append((key, f"must be {rng} ({what}), got {x!r}"))
        return False
    return True


def finite_problem(out: list, key: str, x: Any, what: str) -> bool:
    """Append ``(key, message)`` to ``out`` unless ``x`` is a finite number; True if it is."""
    if not is_number(x) or not math.isfinite(x):
        out.append((key, f"must be a finite number ({what}), got {x!r}"))
        return False
    return True


# ------------------------------------------------------------------------------------------ shapes
class SpectralShape:
    """A spectrum shape of :class:`SpectrumPart`: its ``kind`` (the scenario's name), a ``label`` for
    people, its density and what follows from it. Stateless; one instance per kind in :data:`SHAPES`.

    The JONSWAP family (:class:`Jonswap`) implements every method from the parts' Hs, Tp, γ, σ_a and σ_b;
    another family overrides :meth:`density`, :meth:`bin_variance`, :meth:`band` and :meth:`m0`."""

    kind: str = ""
    label: str = ""
    #: The site's water depth changes the density (else it is the deep-water one).
    finite_depth: bool = False

    def default_gamma(self) -> float:
        """γ of a part that does not give one."""
        return GAMMA_DEFAULT

    def problems(self, v: dict[str, Any], key) -> list[tuple[str, str]]:
        """Problems of the values ``v`` (SpectrumPart field names) particular to this shape; ``key(name)``
        is the key path of a field."""
        return []

    def depth(self, water_depth: float) -> float:
        """The depth the density uses: the site's for a finite-depth shape, else deep water."""
        return water_depth if self.finite_depth else math.inf

    def density(self, part: "SpectrumPart", omega, water_depth: float = math.inf, g: float = 9.81) -> np.ndarray:
        """S(ω) [m² s/rad]."""
        return tma(omega, part.Hs, part.Tp, part.gamma, part.sigma_a, part.sigma_b, self.depth(water_depth), g)

    def bin_variance(self, part: "SpectrumPart", edges, water_depth: float = math.inf, g: float = 9.81) -> np.ndarray:
        """∫S dω [m²] over each bin of ``edges`` (:func:`boatland.waves.spectra.bin_variance`)."""
        return bin_variance(edges, part.Hs, part.Tp, part.gamma, part.sigma_a, part.sigma_b,
                            self.depth(water_depth), g)

    def band(self, part: "SpectrumPart", tail: float) -> tuple[float, float]:
        """[ω_lo, ω_hi] leaving ``tail``/2 of the variance out at each end
        (:func:`boatland.waves.spectra.spectrum_band`)."""
        return spectrum_band(part.Tp, part.gamma, tail)

    def m0(self, part: "SpectrumPart", water_depth: float = math.inf, g: float = 9.81) -> float:
        """m₀ = ∫S dω [m²]: Hs²/16 by the normalisation in deep water; integrated in finite depth."""
        h = self.depth(water_depth)
        if math.isinf(h):
            return part.Hs ** 2 / 16.0  # exact by the normalisation
        wp = part.omega_p
        edges = np.concatenate([np.linspace(0.05 * wp, 20.0 * wp, 401), [200.0 * wp]])
        return float(np.sum(self.bin_variance(part, edges, water_depth, g)))


class Jonswap(SpectralShape):
    """JONSWAP (Hasselmann et al. 1973; :func:`boatland.waves.spectra.jonswap`)."""

    kind, label = "jonswap", "JONSWAP"

    def problems(self, v, key):
        if v.get("sigma_g") is not None:
            return [(key("sigma_g"), f"is the width of a Gaussian swell (kind = 'gaussian'), not of a {self.label} part")]
        return []


class PiersonMoskowitz(Jonswap):
    """Pierson–Moskowitz: JONSWAP with γ = 1 (:func:`boatland.waves.spectra.pierson_moskowitz`)."""

    kind, label = "pm", "Pierson–Moskowitz"

    def default_gamma(self) -> float:
        return 1.0

    def problems(self, v, key):
        out = super().problems(v, key)
        gamma = v.get("gamma")
        if gamma is not None and is_number(gamma) and GAMMA_LIMITS[0] <= gamma <= GAMMA_LIMITS[1] and gamma != 1.0:
            out.append((key("gamma"), f"a Pierson–Moskowitz part has γ = 1; got {gamma:g} "
                                      "(use kind = 'jonswap' for a peaked spectrum)"))
        return out


class TMA(Jonswap):
    """TMA: JONSWAP in finite depth (Bouws et al. 1985; :func:`boatland.waves.spectra.tma`)."""

    kind, label = "tma", "TMA"
    finite_depth = True


class GaussianSwell(SpectralShape):
    """A swell: a Gaussian peak of width ``sigma_g`` [rad/s] at ω_p (:func:`boatland.waves.spectra.gaussian_swell`),
    4√m₀ = Hs exactly; deep water."""

    kind, label = "gaussian", "Gaussian swell"

    def problems(self, v, key):
        s = v.get("sigma_g")
        if s is None:
            return [(key("sigma_g"), "missing: a Gaussian swell needs its width σ [rad/s] (e.g. 0.05)")]
        if not is_number(s) or not 0 < s < math.pi / v.get("Tp", math.inf):
            return [(key("sigma_g"), f"must be > 0 and below ω_p/2 (a swell is narrow), got {s!r}")]
        return []

    def density(self, part, omega, water_depth=math.inf, g=9.81):
        return gaussian_swell(omega, part.Hs, part.Tp, part.sigma_g)

    def bin_variance(self, part, edges, water_depth=math.inf, g=9.81):
        return gaussian_bin_variance(edges, part.Hs, part.Tp, part.sigma_g)

    def band(self, part, tail):
        return gaussian_band(part.Tp, part.sigma_g, tail)

    def m0(self, part, water_depth=math.inf, g=9.81):
        return part.Hs ** 2 / 16.0


#: The shapes a part can have, by ``kind``.
SHAPES: dict[str, SpectralShape] = {s.kind: s for s in (Jonswap(), PiersonMoskowitz(), TMA(), GaussianSwell())}
#: Their kinds.
KINDS = tuple(SHAPES)


def spectrum_part_problems(v: dict[str, Any], prefix: str = "") -> tuple[list[tuple[str, str]], list[str]]:
    """Problems and warnings of one spectral part's values (SpectrumPart field names).

    Returns ``(problems, warnings)``: problems as ``(key_path, message)`` with ``prefix`` prepended to
    the field name (e.g. ``"sea.parts[1]."``), warnings as one-line texts — so a scenario loader can
    report every problem of a file at once before building the object.
    """
    out: list[tuple[str, str]] = []
    warn: list[str] = []
    key = (lambda name: f"{prefix}{name}")
    kind = v.get("kind", "jonswap")
    if kind not in SHAPES:
        close = difflib.get_close_matches(str(kind), KINDS, n=1)
        out.append((key("kind"), f"must be one of {', '.join(map(repr, KINDS))}, got {kind!r}"
                    + (f" (did you mean {close[0]!r}?)" if close else "")))
    positive_problem(out, key("Hs"), v.get("Hs"), "m", "significant wave height")
    positive_problem(out, key("Tp"), v.get("Tp"), "s", "peak period")
    gamma = v.get("gamma")
    own = SHAPES[kind].problems(v, key) if kind in SHAPES else []
    if gamma is not None:
        if not is_number(gamma) or not GAMMA_LIMITS[0] <= gamma <= GAMMA_LIMITS[1]:
            out.append((key("gamma"), f"must be in [{GAMMA_LIMITS[0]:g}, {GAMMA_LIMITS[1]:g}] (JONSWAP peak "
                                      f"enhancement; 1 = Pierson–Moskowitz, 3.3 = mean JONSWAP), got {gamma!r}"))
        elif not any(k == key("gamma") for k, _ in own) and gamma > GAMMA_USUAL[1]:
            warn.append(f"{key('gamma')} = {gamma:g} is outside the usual range {GAMMA_USUAL[0]:g}–"
                        f"{GAMMA_USUAL[1]:g} of measured JONSWAP spectra")
    out += own
    for name in ("sigma_a", "sigma_b"):
        x = v.get(name, SIGMA_A if name == "sigma_a" else SIGMA_B)
        if not is_number(x) or not 0.0 < x <= 0.5:
            out.append((key(name), f"must be in (0, 0.5] (JONSWAP spectral width; usual "
                                   f"{SIGMA_A if name == 'sigma_a' else SIGMA_B}), got {x!r}"))
    finite_problem(out, key("direction_deg"), v.get("direction_deg", 0.0), "direction the waves travel towards [deg]")
    s = v.get("spreading")
    if s is not None and (not is_number(s) or not (s > 0) or not math.isfinite(s)):
        out.append((key("spreading"), f"must be > 0 (cos-2s spreading exponent, e.g. 10 for wind sea) or "
                                      f"absent for long-crested waves, got {s!r}"))
    return out, warn


# ------------------------------------------------------------------------------------------ the part
@dataclass(frozen=True, kw_only=True)
class SpectrumPart:
    r"""One spectral wave system with its shape, direction and spreading.

    Parameters
    ----------
    Hs : float
        Significant wave height H_m0 [m] (> 0). For ``"tma"`` the deep-water JONSWAP height (the finite-
        depth spectrum carries less energy; :func:`boatland.waves.spectra.tma`).
    Tp : float
        Peak period [s] (> 0).
    kind : str
        Spectrum shape, a key of :data:`SHAPES` (``"jonswap"``, ``"pm"``, ``"tma"``).
    gamma : float or None
        Peak enhancement γ in [1, 10] (warning outside 1–7); default the shape's (3.3; 1 for PM).
    sigma_a, sigma_b : float
        Spectral widths below / above the peak (0.07, 0.09).
    direction_deg : float
        Mean direction the waves travel towards, global frame [deg].
    spreading : float or None
        cos-2s spreading exponent s > 0 (short-crested), or None for long-crested waves (default).
    sigma_g : float or None
        Width σ of a Gaussian swell [rad/s] (``"gaussian"`` only).
    """

    Hs: float
    Tp: float
    kind: str = "jonswap"
    gamma: float | None = None
    sigma_a: float = SIGMA_A
    sigma_b: float = SIGMA_B
    direction_deg: float = 0.0
    spreading: float | None = None
    sigma_g: float | None = None

    def __post_init__(self):
        values = {f.name: getattr(self, f.name) for f in fields(self)}
        problems, warns = spectrum_part_problems(values)
        if problems:
            raise SpecError("sea state", problems)
        for w in warns:
            sea_warning(f"sea state: {w}")
        gamma = self.gamma if self.gamma is not None else self.shape.default_gamma()
        for name, value in (("Hs", self.Hs), ("Tp", self.Tp), ("gamma", gamma), ("sigma_a", self.sigma_a),
                            ("sigma_b", self.sigma_b), ("direction_deg", self.direction_deg)):
            object.__setattr__(self, name, float(value))
        for name in ("spreading", "sigma_g"):
            if getattr(self, name) is not None:
                object.__setattr__(self, name, float(getattr(self, name)))

    @property
    def shape(self) -> SpectralShape:
        """Its :class:`SpectralShape`."""
        return SHAPES[self.kind]

    @property
    def omega_p(self) -> float:
        """Peak frequency ω_p = 2π/Tp [rad/s]."""
        return 2.0 * math.pi / self.Tp

    def spectrum(self, omega, water_depth: float = math.inf, g: float = 9.81) -> np.ndarray:
        """S(ω) [m² s/rad] (the depth only matters for a finite-depth shape)."""
        return self.shape.density(self, omega, water_depth, g)

    def bin_variance(self, edges, water_depth: float = math.inf, g: float = 9.81) -> np.ndarray:
        """∫S dω [m²] over each frequency bin of ``edges`` [rad/s]."""
        return self.shape.bin_variance(self, edges, water_depth, g)

    def band(self, tail: float = 0.002) -> tuple[float, float]:
        """[ω_lo, ω_hi] [rad/s] leaving a fraction ``tail``/2 of the variance out at each end."""
        return self.shape.band(self, tail)

    def m0(self, water_depth: float = math.inf, g: float = 9.81) -> float:
        """Variance m₀ [m²] of the elevation."""
        return self.shape.m0(self, water_depth, g)

    def spreading_function(self, theta) -> np.ndarray:
        """D(θ) [1/rad] about ``direction_deg`` (θ in rad, global frame); requires a spreading."""
        if self.spreading is None:
            raise ValueError("a long-crested part has no spreading function (all energy at direction_deg)")
        return spreading_cos2s(theta, math.radians(self.direction_deg), self.spreading)
