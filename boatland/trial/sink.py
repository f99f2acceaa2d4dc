"""Where a running trial reports to: the sink interface the recording edge implements.

:func:`boatland.trial.simulate.simulate` runs the kernel in a worker thread (it releases the GIL) and,
while it runs, hands every finished block of steps to its sinks — so a logger writes the run as it
goes (a killed run keeps what was written) and its cost overlaps the integration on another core.

A sink gets, in order: :meth:`TrialSink.start` once with :class:`TrialInfo`; :meth:`TrialSink.steps`
with consecutive :class:`StepBlock` s covering every step (a whole number of blocks of about one second
of simulated time each — more than one when the sink is behind the kernel — the last one shorter); :meth:`TrialSink.finish` once with the :class:`~boatland.trial.result.Result`
(also when the integration stopped early: ``result.status != 0``). If the trial fails before the
kernel starts, nothing is called; if a sink raises, the trial stops with that error.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np

from boatland.landing.setup import Setup
from boatland.vessel.database import HydroDB
from boatland.scenario.scenario import Scenario
from boatland.trial.events import Event
from boatland.trial.result import TrialSeries

__all__ = ["TrialInfo", "StepBlock", "TrialSink"]


@dataclass(frozen=True, eq=False)
class TrialInfo:
    """What a sink needs before the first step.

    Attributes
    ----------
    setup : Setup
        The scenario on its vessel (:class:`boatland.landing.setup.Setup`); ``scenario``, ``db``, ``dt``,
        ``n_steps`` and ``start_pose`` are read from it — the start pose (x0, y0, psi) is the global
        position [m] of the reference point at rest and the heading [rad]: the local frame of the arrays
        (x, tpos) (DESIGN.md §2).
    contacts : tuple
        ``(P, S, N, TH, CF, DF, MU, sideways)`` in the local frame (body points, plane points, normals,
        horizontal tangents, ...), as the kernel gets them.
    waves : object or None
        The waves of the trial (the scenario's, :attr:`Setup.waves`, or those it was given) — e.g. for the
        elevation at the bow.
    provenance : dict
        boatland version, scenario name and hash, seed, dt, radiation method, ...
    """

    setup: Setup
    contacts: tuple
    waves: object
    provenance: dict = field(default_factory=dict)

    @property
    def scenario(self) -> Scenario:
        return self.setup.scenario

    @property
    def db(self) -> HydroDB:
        return self.setup.db

    @property
    def dt(self) -> float:
        return self.setup.dt

    @property
    def n_steps(self) -> int:
        return self.setup.n_steps

    @property
    def start_pose(self) -> tuple:
        return self.setup.start_pose


@dataclass(frozen=True, eq=False)
class StepBlock(TrialSeries):
    """Rows ``k0`` … ``k1 − 1`` of the trial, final: a :class:`~boatland.trial.result.TrialSeries` of
    read-only views (copy what you keep past the call).

    ``events`` are the contact events whose step lies in this block (state changes from the row
    before ``k0``), in time order.
    """

    k0: int = 0
    k1: int = 0
    events: list[Event] = field(default_factory=list)
    #: (n, Nc, 2) the slide over the tube in each row's step [m] (:attr:`~boatland.trial.result.Result.slide`).
    slide: np.ndarray | None = None


@runtime_checkable
class TrialSink(Protocol):
    """Receives a trial as it runs (see the module docstring for the call order)."""

    def start(self, info: TrialInfo) -> None: ...

    def steps(self, block: StepBlock) -> None: ...

    def finish(self, result) -> None: ...
