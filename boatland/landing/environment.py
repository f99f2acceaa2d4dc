r"""The loads beside the first-order waves on a scenario's vessel, resolved once: :class:`Environment`.

What a scenario's ``[current]``, ``[wind]``, ``sea.drift`` and ``[thrust]`` (its direction and the skipper's
control) become on its vessel — the drag loads with their areas measured on the vessel's meshes
(:mod:`boatland.loads.current`, :mod:`boatland.loads.wind`), the drift mode (:mod:`boatland.sea.drift`),
the push's direction and controller (:mod:`boatland.loads.skipper`) — for the time domain
(:func:`boatland.trial.simulate.simulate`) and, as a :class:`~boatland.landing.law.SteadyLoad`, for the
frequency domain's landed equilibrium (:meth:`Environment.steady_load`):

.. math::
    F^s = F_{cur}(x^0, \dot x = 0) + \bar F_{wind} + \bar F_{drift}, \qquad
    K^s = -\frac{\partial F_{cur}}{\partial x}, \qquad B^s = -\frac{\partial F_{cur}}{\partial \dot x}

— the current's drag linearised about the vessel at rest (its damping of the hull's motions, and the turn of
its force and lever with the hull's rotations), by central differences of the kernel's own evaluation
(:func:`boatland.loads.drag.add_drag`). The wind and drift act on the start pose in the time domain, so they
add no stiffness there or here.
"""

from __future__ import annotations

import dataclasses
import math
import weakref
from dataclasses import dataclass

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.landing.law import NoStaticEquilibrium, SteadyLoad
from boatland.loads.current import Current
from boatland.loads.drag import DragLoad, add_drag
from boatland.rigid import rotation_matrix

__all__ = ["Environment", "TrimImpossible"]

#: Drag loads per database and scenario table (measuring a CTV's silhouettes takes ~0.3 s; a campaign asks
#: for the same ones for every trial).
_LOADS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
#: Still water: the hull's drag (the current's law at zero speed) that damps the slow motions of wind and drift.
STILL_WATER = Current(speed=0.0, direction_deg=0.0, values={})
#: Central-difference steps of the linearisation: velocity [m/s, rad/s] and rotation [rad].
_DV, _DX = 1e-4, 1e-6


#: Keys of a current or wind that describe the flow, not the vessel's drag: the DragLoad does not depend on them.
_FLOW_KEYS = frozenset({"speed", "direction_deg", "relative_direction_deg"})


def _cached_load(db, what: str, spec) -> DragLoad:
    """The drag load of ``spec`` on ``db``'s hull, made once per vessel and drag description (the flow's speed and
    direction do not enter it: a site's currents share one)."""
    per_db = _LOADS.setdefault(db, {})
    key = (what, repr(sorted((k, v) for k, v in spec.values.items() if k not in _FLOW_KEYS)))
    if key not in per_db:
        per_db[key] = spec.load(db)
    return per_db[key]


class TrimImpossible(BoatlandInputError, NoStaticEquilibrium):
    """The skipper's trim cannot balance the steady yaw moment (:meth:`Environment.trim`): for one scenario a bad
    input (one line, exit status 2); where the flows vary from sea state to sea state (a site's weather,
    :mod:`boatland.site.flows`), a current and wind the landing cannot be held in, like no static equilibrium."""


@dataclass(frozen=True, eq=False)
class Environment:
    """The loads beside the waves of one scenario on its vessel (module docstring).

    Attributes
    ----------
    heading_deg : float
        The vessel's start heading (the local frame's x axis) [deg].
    current : DragLoad or None
    current_velocity : ndarray, shape (3,)
        The water's velocity in the local frame [m/s].
    wind : Wind or None
        The scenario's wind (:class:`boatland.loads.wind.Wind`) and ``wind_load`` its DragLoad.
    drift : str
        "none", "mean" or "newman".
    push_direction : ndarray, shape (3,)
        Unit direction of the push, body frame.
    skipper : Skipper or None
        The push controller (None: a constant push).
    """

    heading_deg: float
    current: DragLoad | None
    current_velocity: np.ndarray
    wind: object
    wind_load: DragLoad | None
    drift: str
    push_direction: np.ndarray
    skipper: object

    @classmethod
    def of(cls, scenario, db) -> "Environment":
        """The environment of ``scenario`` on the vessel of ``db``.

        Raises
        ------
        BoatlandInputError
            A load the database cannot carry: no mesh to measure areas on (names the keys to give), no drift
            coefficients for ``sea.drift``.
        """
        heading = float(scenario.vessel.heading_deg)
        cur = wload = None
        U = np.zeros(3)
        drift = scenario.sea.drift if scenario.sea is not None else "none"
        try:
            if scenario.current is not None:
                cur = _cached_load(db, "current", scenario.current)
                U = scenario.current.velocity_local(heading)
            if scenario.wind is not None and scenario.wind.speed > 0:
                wload = _cached_load(db, "wind", scenario.wind)
        except ValueError as exc:
            raise BoatlandInputError(f"{scenario.source}: {exc}") from None
        if cur is None and (wload is not None or drift != "none"):
            # slow loads without a current: the hull's drag in still water still damps the slow motions they
            # excite (the landed sway–yaw swing); without a hull mesh to measure it on, none (said in lines())
            try:
                cur = _cached_load(db, "current", STILL_WATER)
            except ValueError:
                cur = None
        if drift != "none" and getattr(db, "drift", None) is None:
            raise BoatlandInputError(f"{scenario.source}: sea.drift = {drift!r}: the database {db.name!r} has no mean "
                                     "drift coefficients (import a BEM output with them, e.g. WAMIT .8/.9 or AQWA, or "
                                     "add them to a Capytaine-built database: boatland.hydro.drift); or drift = 'none'")
        thr = scenario.thrust
        sk = thr.control if thr is not None and thr.control.active else None
        env = cls(heading_deg=heading, current=cur, current_velocity=U, wind=scenario.wind if wload else None,
                  wind_load=wload, drift=drift, push_direction=np.array([1.0, 0.0, 0.0]), skipper=sk)
        if thr is None:
            return env
        if not thr.trimmed:
            a = math.radians(float(thr.direction_deg))
            e_T = np.array([1.0, 0.0, 0.0]) if a == 0.0 else np.array([math.cos(a), math.sin(a), 0.0])
        else:
            e_T = env.trim(scenario)
        return dataclasses.replace(env, push_direction=e_T)

    def trim(self, scenario) -> np.ndarray:
        r"""The skipper's push direction against the steady yaw moment: the angle α whose side force balances
        the moment of current and mean wind about the middle of the fender points
        :math:`r_f`, so that the two tubes share the push equally,

        .. math:: T\left[(x_T - x_f)\sin\alpha - (y_T - y_f)\cos\alpha\right] + M^s_z - (x_f F^s_y - y_f F^s_x) = 0

        (exactly (1, 0, 0) without steady loads). An assumption about the skipper — he steers the waterjets to
        hold the bow — stated in the scenario keys' docs.

        Raises
        ------
        TrimImpossible
            The push cannot balance the moment within ±60° (a :class:`~boatland.errors.BoatlandInputError`).
        """
        F = self.current_force() + self.mean_wind()
        thr = scenario.thrust
        if not np.any(F) or scenario.fender is None:
            return np.array([1.0, 0.0, 0.0])
        xf, yf = np.mean(np.asarray(scenario.fender.points, dtype=float)[:, :2], axis=0)
        xT, yT = float(thr.position[0]), float(thr.position[1])
        M = F[5] - (xf * F[1] - yf * F[0])
        # T[(xT − xf) sin α − (yT − yf) cos α] = −M: A sin α + B cos α = c
        A, B, c = (xT - xf), -(yT - yf), -M / thr.force
        r = math.hypot(A, B)
        if r == 0.0 or abs(c) > r * math.sin(math.radians(60.0)):
            raise TrimImpossible(f"{scenario.source}: thrust.direction_deg = 'trim': the push of {thr.force / 1e3:g} kN "
                                 f"cannot balance the steady yaw moment {M / 1e3:.0f} kN m of the current and wind "
                                 "about the fender within ±60°: push harder, or give thrust.direction_deg")
        phi, s = math.atan2(B, A), math.asin(c / r)
        wrap = lambda a: (a + math.pi) % (2 * math.pi) - math.pi  # noqa: E731
        a = min((wrap(s - phi), wrap(math.pi - s - phi)), key=abs)   # the solution nearer straight ahead
        return np.array([math.cos(a), math.sin(a), 0.0])

    @property
    def calm(self) -> bool:
        """No current, wind or drift, a constant push straight ahead: the waves-only landing."""
        return (self.current is None and self.wind_load is None and self.drift == "none" and self.skipper is None
                and self.push_direction[0] == 1.0)

    def kernel_current(self):
        """(U, DragLoad) for :meth:`boatland.trial.motion.MotionArrays.run` (None without a current)."""
        return None if self.current is None else (self.current_velocity, self.current)

    def current_force(self, x=None, v=None) -> np.ndarray:
        """The current's generalised force (6,) in the local frame at displacement ``x`` and velocity ``v``
        (default: at rest in the start pose), as the kernel evaluates it."""
        F = np.zeros(6)
        if self.current is None:
            return F
        x = np.zeros(6) if x is None else np.asarray(x, dtype=float)
        v = np.zeros(6) if v is None else np.asarray(v, dtype=float)
        tab, par = self.current.kernel()
        add_drag(rotation_matrix(x[3], x[4], x[5]), v, self.current_velocity, 1.0, tab, par, self.current.strips, F)
        return F

    def current_damping(self, x0=None) -> np.ndarray:
        r""":math:`B^s = -\partial F_{cur}/\partial \dot x` (6, 6) at rest (central differences of the kernel's
        evaluation); zeros without a current."""
        B = np.zeros((6, 6))
        if self.current is None:
            return B
        x = np.zeros(6) if x0 is None else np.asarray(x0, dtype=float)
        for j in range(6):
            e = np.zeros(6)
            e[j] = _DV
            B[:, j] = -(self.current_force(x, e) - self.current_force(x, -e)) / (2 * _DV)
        return B

    @property
    def linearisable(self) -> bool:
        """The hull's drag is the cross-flow form, whose damping :meth:`drag_damping` linearises statistically."""
        return self.current is not None and self.current.form == "crossflow"

    def strip_maps(self) -> np.ndarray:
        """(n, 2, 6): for each strip of the current's load, the maps of the vessel's velocity (6,) to the strip's
        longitudinal and transverse velocity, :math:`g_x = (1, 0, 0, 0, z_i, -y_c)`, :math:`g_y = (0, 1, 0, -z_i,
        0, x_i)` (small rotations)."""
        st = self.current.strips
        yc = float(self.current.centroid[1])
        G = np.zeros((st.shape[0], 2, 6))
        G[:, 0, 0], G[:, 0, 4], G[:, 0, 5] = 1.0, st[:, 1], -yc
        G[:, 1, 1], G[:, 1, 3], G[:, 1, 5] = 1.0, -st[:, 1], st[:, 0]
        return G

    def strip_coefficients(self) -> np.ndarray:
        r"""(n, 2): each strip's :math:`k_{a,i} = \tfrac12\rho A_a c_a s_i` of the cross-flow drag
        :math:`k\,w|w|` along the hull (a = x) and across it (a = y), :class:`~boatland.loads.drag.DragLoad`."""
        c = self.current
        return np.stack([0.5 * c.rho * c.area_x * c.coefficients[0] * c.strips[:, 2],
                         0.5 * c.rho * c.area_y * c.coefficients[1] * c.strips[:, 2]], axis=1)

    def drag_quadratic(self, sigma) -> np.ndarray:
        r"""The cross-flow drag's second-order coefficients (n, 2) when each strip's relative velocity is
        Gaussian about the current's with standard deviations ``sigma`` (n, 2) [m/s]: the drag
        :math:`f(w) = k\,w|w|` expanded in Hermite polynomials of the fluctuation :math:`u = w - \mu`,

        .. math:: f(w) \approx E f + E f'\,u + \tfrac12 E f''\,(u^2 - \sigma^2), \qquad
                  \tfrac12 E f'' = k\,(2\Phi(\mu/\sigma) - 1)

        — the equivalent statistical quadratization of Spanos, P. D. & Donley, M. G. (1991), *Equivalent
        statistical quadratization for nonlinear systems*, J. Eng. Mech. 117(6), 1289–1310, whose linear term
        is :meth:`drag_damping`'s :math:`2kE|w|` and whose mean is :meth:`drag_mean_shift`'s. In a current
        stronger than the motions (μ ≫ σ) the coefficient is k sgn μ and the expansion is the drag itself,
        :math:`k(\mu - v)^2`; across a flow at rest (μ = 0) it is 0 (the drag is odd there). σ = 0 gives k sgn μ.
        """
        from scipy.special import ndtr

        mu = np.broadcast_to(self.current_velocity[:2], (self.strip_maps().shape[0], 2))
        sig = np.asarray(sigma, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            c2 = np.where(sig > 0, 2.0 * ndtr(mu / np.where(sig > 0, sig, 1.0)) - 1.0, np.sign(mu))
        return self.strip_coefficients() * c2

    def drag_damping(self, sigma) -> np.ndarray:
        r"""The cross-flow drag's equivalent linear damping (6, 6) when each strip's relative velocity is
        Gaussian about the current's, with standard deviations ``sigma`` (n, 2) [m/s] (longitudinal,
        transverse): :math:`B = \sum_i \sum_{a} 2k_{a,i}\,E|w_{a,i}|\;g_{a,i} g_{a,i}^\top`,
        :math:`E|w| = \sigma\sqrt{2/\pi}\,e^{-\mu^2/2\sigma^2} + \mu\,\mathrm{erf}(\mu/\sqrt2\sigma)` —
        Gaussian equivalent linearisation of :math:`k w|w|` (e.g. Borgman 1969; Wolfram 1999) — for the
        :class:`~boatland.loads.drag.DragLoad` "crossflow" form; σ = 0 gives the derivative at the mean flow."""
        from scipy.special import erf

        G = self.strip_maps()
        mu = np.abs(self.current_velocity[:2])                  # body = local at rest
        k = self.strip_coefficients()
        sig = np.asarray(sigma, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            Ew = np.where(sig > 0, sig * np.sqrt(2 / np.pi) * np.exp(-0.5 * (mu / np.where(sig > 0, sig, 1.0)) ** 2)
                          + mu * erf(mu / (np.sqrt(2) * np.where(sig > 0, sig, 1.0))), mu)
        return np.einsum("ia,iaj,iak->jk", 2 * k * Ew, G, G)

    def drag_mean_shift(self, sigma) -> np.ndarray:
        r"""The change (6,) of the cross-flow drag's mean load when each strip's relative velocity fluctuates
        about the current's with standard deviations ``sigma`` (n, 2): :math:`\sum_i \sum_a k_{a,i}
        (E[w|w|] - \mu|\mu|)\,g_{a,i}`, :math:`E[w|w|] = (\mu^2 + \sigma^2)(2\Phi(\mu/\sigma) - 1) +
        2\mu\sigma\,\varphi(\mu/\sigma)` for a Gaussian w — the waves' motions make the drag's mean larger
        (for a strong current by :math:`k\sigma^2`), unequally along the hull."""
        from scipy.stats import norm

        G = self.strip_maps()
        mu = np.broadcast_to(self.current_velocity[:2], (G.shape[0], 2))     # body = local at rest, signed
        k = self.strip_coefficients()
        sig = np.asarray(sigma, dtype=float)
        safe = np.where(sig > 0, sig, 1.0)
        r = mu / safe
        E = np.where(sig > 0, (mu * mu + sig * sig) * (2 * norm.cdf(r) - 1) + 2 * mu * sig * norm.pdf(r), mu * np.abs(mu))
        return np.einsum("ia,iaj->j", k * (E - mu * np.abs(mu)), G)

    def mean_wind(self) -> np.ndarray:
        """The mean wind load (6,) in the local frame."""
        return np.zeros(6) if self.wind_load is None else self.wind.mean_force(self.wind_load, self.heading_deg)

    def steady_load(self, x0=None) -> SteadyLoad | None:
        """The steady loads as the frequency domain takes them (module docstring), linearised about ``x0``
        (default the start pose); the sea's mean drift is added per sea
        (:meth:`boatland.freqdomain.landing.LandingSetup.with_drift`). None when there is nothing steady besides
        the push."""
        F = self.current_force(x0) + self.mean_wind()
        K = np.zeros((6, 6))
        B = self.current_damping(x0)
        if self.current is not None:
            x = np.zeros(6) if x0 is None else np.asarray(x0, dtype=float)
            for j in range(3, 6):              # translations do not move a uniform current's load
                e = np.zeros(6)
                e[j] = _DX
                K[:, j] = -(self.current_force(x + e) - self.current_force(x - e)) / (2 * _DX)
        pattern = spectrum = None
        if self.wind_load is not None and self.wind.spectrum != "none":
            pattern = self.wind.unit_force(self.wind_load, self.heading_deg)
            spectrum = self.wind.gust_spectrum(self.wind_load)
        if not np.any(F) and not np.any(K) and not np.any(B):
            return None
        return SteadyLoad(force=F, stiffness=K, damping=B, gust_pattern=pattern, gust_spectrum=spectrum)

    def lines(self, scenario) -> list[str]:
        """One line per load beside the waves, for the run's header and reports."""
        out = []
        h = self.heading_deg
        if self.current is not None and scenario.current is not None:
            F = self.current_force()
            out.append(f"{scenario.current.text(h)}: {F[0] / 1e3:+.1f} kN surge, {F[1] / 1e3:+.1f} kN sway at rest")
        elif self.current is not None:
            out.append("hull drag in still water (damps the slow motions of wind and drift)")
        elif self.wind_load is not None or self.drift != "none":
            out.append("no hull drag (no hull mesh to measure it on: give [current] speed = 0 with its areas)")
        if self.wind_load is not None:
            F = self.mean_wind()
            out.append(f"{self.wind.text(h)}: mean {F[0] / 1e3:+.1f} kN surge, {F[1] / 1e3:+.1f} kN sway")
        if self.drift != "none":
            out.append(f"wave drift: {self.drift}")
        if self.skipper is not None:
            out.append(self.skipper.text())
        if self.push_direction[0] != 1.0:
            a = math.degrees(math.atan2(self.push_direction[1], self.push_direction[0]))
            how = " (the skipper's trim against the yaw moment)" if scenario.thrust.trimmed else ""
            out.append(f"push {a:+.1f}° off the bow's axis{how}")
        return out
