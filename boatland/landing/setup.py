r"""One scenario on its vessel, with everything derived from the pair computed once: :class:`Setup`.

A trial, the screening, the checks and a campaign all start from the same derived values — the time
step, the number of steps, the start pose, the fender on the landing in the vessel's axes (with the
contact dynamics that bound the time step), the wave model adapted to the database and the monopile whose
scattered wave the vessel feels. :meth:`Setup.of` makes them once; everything downstream reads them from
the :class:`Setup`, which also gives, when asked, the kernel's contacts, the linear contact law, the
additional damping and the radiation memory.

The time step rule (when the file gives none) is

.. math:: \Delta t = \min\left(0.05\ \mathrm{s},\ \frac{T_{p,min}}{100},\ \frac{T_c}{20},\ \frac{T_{shear}}{8}\right)

with T_p,min the shortest peak period of the sea (Ferreira González 2023 §5.2.3 used Tp/100), T_c the
period of the fastest normal contact mode and T_shear that of the stuck rubber's fastest mode
(:class:`boatland.landing.contacts.ContactPeriod`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from boatland.contact.fender import Contacts, no_contacts
from boatland.irf.impulse import IRFSettings
from boatland.landing.contacts import ContactPeriod, FenderOnLanding, fender_on_landing
from boatland.landing.environment import Environment
from boatland.landing.law import ContactLaw
from boatland.scenario.schema import DT_MAX
from boatland.sea.pile import Pile
from boatland.vessel.database import HydroDB, roll_critical_damping
from boatland.vessel.radiation import RadiationMemory, default_dt, radiation_memory

__all__ = ["Setup", "additional_damping", "time_step"]


def time_step(scenario, period: ContactPeriod | None = None) -> float:
    """The RK4 step [s]: ``simulation.dt`` if given, else the default rule of the module docstring (the
    contact terms only with a ``period``)."""
    if scenario.simulation.dt is not None:
        return scenario.simulation.dt
    dt = DT_MAX
    if scenario.sea is not None:
        dt = min(dt, scenario.sea.peak_period / 100.0)
    if period is not None:
        dt = min(dt, period.dt_limit)
    return float(dt)


def additional_damping(scenario, db: HydroDB) -> tuple[np.ndarray, np.ndarray]:
    r"""(B_v, B_q): 6×6 diagonal additional linear and quadratic damping of the scenario's vessel.

    ``vessel.damping.roll_critical_fraction`` ζ adds :math:`B_{44} = 2\zeta\sqrt{(M_{44} +
    A_{44}(\omega_{44}))\,C_{44}}` to the given linear roll damping
    (:func:`boatland.vessel.database.roll_critical_damping`).
    """
    Bv = np.diag(np.array(scenario.vessel.linear_damping, dtype=float))
    Bq = np.diag(np.array(scenario.vessel.quadratic_damping, dtype=float))
    zeta = scenario.vessel.roll_critical_fraction
    if zeta > 0:
        Bv[3, 3] += zeta * roll_critical_damping(db)
    return Bv, Bq


@dataclass(frozen=True, eq=False)
class Setup:
    """A scenario on its vessel (:meth:`Setup.of`).

    Attributes
    ----------
    scenario : boatland.scenario.scenario.Scenario
    db : HydroDB
    dt : float
        RK4 step [s] (:func:`time_step`).
    n_steps : int
        Steps covering ``simulation.duration``: ceil(duration / dt).
    start_pose : (float, float, float)
        (x [m], y [m], heading ψ [rad]) of the reference point at t = 0 (before ``initial``).
    fender : FenderOnLanding or None
        The fender on the landing in the vessel's axes; None without a landing or fender.
    waves : wave model or None
        The sea adapted to ``db`` (its water depth unless the file gave one); None in calm water.
    pile : Pile or None
        The monopile whose scattered wave the vessel feels (:class:`boatland.sea.pile.Pile`: radius, axis,
        the sea's water depth): ``landing.diffraction``, by default on when ``db`` has a hull mesh (and
        there are waves).
    environment : Environment
        The loads beside the waves: current, wind, wave drift, the push's direction and the skipper's
        control (:class:`boatland.landing.environment.Environment`).
    """

    scenario: object
    db: HydroDB
    dt: float
    n_steps: int
    start_pose: tuple[float, float, float]
    fender: FenderOnLanding | None
    waves: object
    pile: Pile | None
    environment: Environment

    @classmethod
    def of(cls, scenario, db: HydroDB, given: "Setup | None" = None) -> "Setup":
        """The setup of ``scenario`` on the vessel of ``db``; ``given``: one already made, checked to be
        theirs. A database without a mass matrix gives no contact dynamics (the checks refuse it for a
        run; the time step then follows the sea alone).

        Raises
        ------
        ValueError
            ``given`` was made from another scenario or database.
        """
        if given is not None:
            if given.scenario is not scenario or given.db is not db:
                raise ValueError("the setup given was made from another scenario or database")
            return given
        pose = scenario.start_pose()
        fender = fender_on_landing(scenario, db, pose)
        dt = time_step(scenario, fender.period if fender is not None else None)
        n = int(math.ceil(scenario.simulation.duration / dt - 1e-9))
        waves = None if scenario.sea is None else scenario.sea.model(db)
        return cls(scenario=scenario, db=db, dt=dt, n_steps=n, start_pose=pose, fender=fender, waves=waves,
                   pile=_pile(scenario, db, waves), environment=Environment.of(scenario, db))

    @property
    def source(self) -> str:
        return self.scenario.source

    @property
    def contact_period(self) -> ContactPeriod | None:
        """The fender's contact dynamics (None without a fender, or a database without a mass matrix)."""
        return None if self.fender is None else self.fender.period

    def additional_damping(self) -> tuple[np.ndarray, np.ndarray]:
        """(B_v, B_q) of :func:`additional_damping`."""
        return additional_damping(self.scenario, self.db)

    def contacts(self) -> Contacts:
        """The kernel's contacts (:meth:`FenderOnLanding.kernel_contacts`; none without a fender)."""
        return no_contacts() if self.fender is None else self.fender.kernel_contacts()

    def contact_law(self) -> ContactLaw | None:
        """The frequency domain's contact law (:meth:`FenderOnLanding.contact_law`; None without a fender)."""
        return None if self.fender is None else self.fender.contact_law()

    def irf_settings(self) -> IRFSettings:
        """K(t) over the scenario's memory length, Δt_K for the database's band, its tail and taper."""
        rad = self.scenario.radiation
        return IRFSettings(t_max=rad.memory, dt=default_dt(self.db.omega[-1]), tail=rad.tail, taper=rad.taper)

    def memory(self) -> RadiationMemory:
        """The radiation memory the scenario asks for: IRFs (and the state-space fit for ``state_space``),
        computed on every call (a second or so: keep the result; campaigns share one per database and
        radiation settings)."""
        return radiation_memory(self.db, self.irf_settings(), fit=self.scenario.radiation.method == "state_space")


def _pile(scenario, db: HydroDB, waves) -> Pile | None:
    L = scenario.landing
    if L is None or scenario.sea is None:
        return None
    on = L.diffraction if L.diffraction is not None else db.mesh is not None
    return Pile(L.monopile_diameter / 2, tuple(L.monopile_position), waves.water_depth) if on else None
