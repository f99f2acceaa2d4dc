"""One landing trial: scenario + hydrodynamic database → integrated motions, contact forces, events.

The service wires the validated :class:`~boatland.scenario.scenario.Scenario` on its vessel
(:class:`~boatland.landing.setup.Setup`: time step, start pose, contacts, wave model, pile) to the kernels:
radiation memory (:mod:`boatland.irf` through :func:`boatland.vessel.radiation.radiation_memory`), the wave
excitation on the RK4 half-step grid (:mod:`boatland.waves`), the thrust ramp, the fender contacts in
the vessel's local frame, and the RK4 Cummins integrator with stick–slip contact
(:func:`boatland.integrate.run_cummins`). It loads nothing from disk: the caller passes the database
(``boatland.checks.files.load_checked`` does both for files).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import replace

import numpy as np

from boatland import __version__
from boatland.checks.memory import check_radiation
from boatland.errors import BoatlandInputError
from boatland.integrate.cummins import OUTCOME_STATUSES
from boatland.landing.setup import Setup
from boatland.reproducible import pinned
from boatland.scenario.inputs import trial_inputs
from boatland.scenario.scenario import Scenario
from boatland.sea.drift import drift_series
from boatland.sea.pile import scattered_tables
from boatland.trial.events import extract_events
from boatland.trial.motion import MotionArrays, compile_motion
from boatland.trial.result import SERIES, Result
from boatland.trial.sink import StepBlock, TrialInfo, TrialSink
from boatland.vessel.database import HydroDB
from boatland.vessel.radiation import RadiationMemory

__all__ = ["simulate", "motion_arrays", "pile_tables", "pile_table_request", "thrust_series", "wave_ramp",
           "wave_start", "exposure_start", "BlowUpError"]

#: Runaway limits: no CTV landing survives these (linear hydrodynamics is meaningless beyond them).
LIMIT_TRANS, LIMIT_ROT = 50.0, np.radians(60.0)


class BlowUpError(RuntimeError):
    """The integration stopped (NaN or runaway): the message says when, the state, the likely cause."""

    def __init__(self, result: Result, cause: str):
        self.result = result
        k = len(result.t) - 1
        x = result.x[k]
        state = (f"surge {x[0]:.3g} m, sway {x[1]:.3g} m, heave {x[2]:.3g} m, roll {np.degrees(x[3]):.3g}°, "
                 f"pitch {np.degrees(x[4]):.3g}°, yaw {np.degrees(x[5]):.3g}°")
        super().__init__(f"integration stopped at t = {result.t[k]:.2f} s: {result.message} ({state}); "
                         f"likely cause: {cause}")


def thrust_series(scenario: Scenario, dt: float, n_steps: int) -> np.ndarray:
    """Push [N] at the half steps, ramped in with a half-cosine over ``thrust.ramp``."""
    t = np.arange(2 * n_steps + 1) * dt / 2
    if scenario.thrust is None:
        return np.zeros_like(t)
    T, ramp = scenario.thrust.force, scenario.thrust.ramp
    r = np.ones_like(t)
    if ramp > 0:                       # the half-cosine where t < ramp (t increases): evaluated there only
        k = int(np.searchsorted(t, ramp, side="left"))
        r[:k] = 0.5 * (1 - np.cos(np.pi * t[:k] / ramp))
    return T * r


def load_ramp(scenario: Scenario, dt: float, n_steps: int) -> np.ndarray:
    """Factor on the current's speed and the wind's force at the half steps: the push's ramp (they build up
    with it, so that the fender is pressed on before they pull it sideways), or 1 without a push."""
    if scenario.thrust is None:
        return np.ones(2 * n_steps + 1)
    return thrust_series(scenario, dt, n_steps) / scenario.thrust.force


def wave_start(scenario: Scenario) -> float:
    """Time [s] at which the waves begin to ramp in: once the thrust is fully on (the tank tests of
    Ferreira González 2023 §4.3.3 pushed the fender on before the waves arrived), else at once."""
    return scenario.thrust.ramp if (scenario.thrust is not None and scenario.fender is not None) else 0.0


def exposure_start(scenario: Scenario) -> float:
    """Time [s] the waves reach full height: :func:`wave_start` plus the waves' start-up ramp — where a
    campaign's exposure (the access) begins."""
    return wave_start(scenario) + (scenario.simulation.start_ramp if scenario.sea is not None else 0.0)


def wave_ramp(scenario: Scenario, dt: float, n_steps: int) -> np.ndarray:
    """Factor on the wave excitation at the half steps: 0 until :func:`wave_start`, then a half-cosine
    over ``simulation.start_ramp``, then 1."""
    t = np.arange(2 * n_steps + 1) * dt / 2 - wave_start(scenario)
    T = scenario.simulation.start_ramp
    if T <= 0:
        return (t >= 0).astype(float)
    r = np.where(t <= 0, 0.0, 1.0)
    k0, k1 = int(np.searchsorted(t, 0.0, side="right")), int(np.searchsorted(t, T, side="left"))
    r[k0:k1] = 0.5 * (1 - np.cos(np.pi * t[k0:k1] / T))   # the half-cosine, evaluated where 0 < t < T only
    return r


def motion_arrays(setup: Setup, memory: RadiationMemory) -> MotionArrays:
    """The kernel arrays of the scenario's radiation method, memory length and time step
    (:func:`boatland.trial.motion.compile_motion`): the same for every seed, so a campaign compiles them once
    per case and passes them to :func:`simulate` (``arrays``)."""
    rad = setup.scenario.radiation
    try:
        return compile_motion(setup.db, memory, setup.dt, method=rad.method, memory_length=rad.memory)
    except ValueError as exc:  # a state-space pole too fast for dt: the scenario's choice, not a bug
        raise BoatlandInputError(f"{setup.source}: simulation.dt: {exc}") from None


def pile_tables(setup: Setup) -> list:
    """The ω tables of the pile's scattered wave a trial of ``scenario`` interpolates
    (:class:`boatland.sea.pile.ScatteredTable`; none without waves, a pile or for a
    short-crested sea). They depend on the layout and the sea's directions, not on the seed: a campaign
    makes those of all its cases once (:func:`pile_table_request`,
    :func:`boatland.sea.pile.make_tables`) and ships them to its workers
    (:func:`boatland.sea.pile.remember_tables`)."""
    request = pile_table_request(setup)
    return [] if request is None else scattered_tables(setup.db, *request)


def pile_table_request(setup: Setup):
    """The arguments of the tables :func:`pile_tables` makes (:class:`boatland.sea.pile.TableRequest`),
    or None: a campaign asks every case and makes the tables of a layout together
    (:func:`boatland.sea.pile.make_tables`)."""
    if setup.waves is None or setup.pile is None:
        return None
    x0, y0, psi = setup.start_pose
    return setup.waves.pile_table_request(seed=setup.scenario.simulation.seed, dt=setup.dt, n_steps=setup.n_steps,
                                          x0=x0, y0=y0, heading_deg=float(np.degrees(psi)), pile=setup.pile)


@pinned
def simulate(scenario: Scenario, db: HydroDB, *, memory: RadiationMemory | None = None,
             arrays: MotionArrays | None = None, progress: Callable[[int, int], None] | None = None,
             sinks: Sequence[TrialSink] = (), progress_every: float = 0.1, waves=None,
             setup: Setup | None = None, gust_seed: int | None = None) -> Result:
    r"""Run one landing trial.

    Equation of motion (DESIGN.md §1; Cummins 1962, San Nicolás Méndez 2024 eq. 3.40; contact: Ferreira González 2023 §2.5, §3.4):

    .. math::
        (M + A_\infty)\ddot x + \int_0^t K(t-\tau)\dot x\,d\tau + B_v\dot x + B_q|\dot x|\dot x + C x
            = F_{exc}(t) + F_T(t) + \sum_c F_c

    Parameters
    ----------
    scenario : Scenario
        Validated scenario (its database checks are the caller's: :func:`boatland.checks.check`).
    db : HydroDB
        The vessel's database (with a mass matrix).
    memory : RadiationMemory, optional
        Reuse IRFs / state-space fit across trials of a campaign (must match the scenario's settings;
        the caller checks it once with :func:`boatland.checks.memory.check_radiation`). Without it (and
        without ``arrays``) the memory is made and checked here.
    arrays : MotionArrays, optional
        The kernel arrays compiled from the scenario's checked memory (:func:`motion_arrays`), reused
        across trials; given, ``memory`` is not used.
    progress : callable, optional
        ``progress(steps_done, n_steps)``, called every ``progress_every`` seconds while the kernel runs
        (it runs in a worker thread with the GIL released) — e.g. to drive a progress bar; 0 calls it at
        every look at the kernel's step counter (each few hundred µs).
    sinks : sequence of TrialSink
        Receive the trial as it runs, in blocks of about one second of simulated time
        (:mod:`boatland.trial.sink`): a logger writes while the kernel integrates.
    waves : wave model, optional
        Waves to use instead of the scenario's sea (:attr:`Setup.waves`), with the same interface
        (``excitation``, ``realise``) — e.g. a :class:`~boatland.sea.gaussian.GaussianSea` driven by
        given standard-normal coefficients, so that the trial runs on exactly the sea a rare-event
        sampler chose (:mod:`boatland.campaign.isee`). The scenario still sets everything else (its
        sea's ramp, the monopile's scattered wave). Its ``digest()`` goes into the provenance.
    setup : Setup, optional
        ``Setup.of(scenario, db)``, when the caller has made it already.
    gust_seed : int, optional
        Seed of the wind's gusts (:func:`boatland.loads.wind.gust_series`) instead of the scenario's seed:
        a rare-event sample, whose sea is not drawn from the scenario's seed, gives its own
        (:func:`boatland.campaign.isee.sample_gust_seed`). Recorded in the provenance when given.

    Returns
    -------
    Result
        Labelled time series, events, slip episodes, summary, provenance.

    Raises
    ------
    BlowUpError
        NaN or runaway motion: the partial result is attached, nothing pretends success.
    """
    wall0 = time.perf_counter()
    if db.M is None:
        raise BoatlandInputError(f"database {db.name!r} has no mass matrix M: a time-domain run needs it")
    setup = Setup.of(scenario, db, setup)
    dt, n = setup.dt, setup.n_steps
    if arrays is None:
        if memory is None:
            memory = setup.memory()
            check_radiation(setup, memory)
        arrays = motion_arrays(setup, memory)
    x0g, y0g, psi = setup.start_pose
    override = waves is not None
    if not override:
        waves = setup.waves
    elif scenario.sea is None:
        raise BoatlandInputError(f"{scenario.source}: waves given for a scenario without a sea: its [sea] sets the "
                                 "ramp and the pile's scattered wave")
    env = setup.environment
    if waves is None:
        F = np.zeros((2 * n + 1, 6))
    else:
        F = waves.excitation(db, seed=scenario.simulation.seed, dt=dt, n_steps=n, x0=x0g, y0=y0g,
                             heading_deg=float(np.degrees(psi)), ramp_time=0.0, pile=setup.pile)
        r = wave_ramp(scenario, dt, n)
        k = int(np.flatnonzero(r != 1.0)[-1]) + 1 if np.any(r != 1.0) else 0   # rows after k: × 1 (unchanged)
        F[:k] *= r[:k, None]
        if env.drift != "none":
            F += drift_series(env.drift, db, waves.realise(scenario.simulation.seed, n * dt), dt=dt, n_steps=n,
                              x0=x0g, y0=y0g, heading_deg=float(np.degrees(psi)), ramp=r)
    if env.wind_load is not None:
        F += env.wind.force_series(env.wind_load, env.heading_deg,
                                   scenario.simulation.seed if gust_seed is None else gust_seed, dt, n) \
            * load_ramp(scenario, dt, n)[:, None]
    thrust = thrust_series(scenario, dt, n)
    Bv, Bq = setup.additional_damping()
    contacts = setup.contacts()
    r_p = scenario.thrust.position if scenario.thrust is not None else (0.0, 0.0, 0.0)
    kwargs = dict(F_ext=F, thrust=thrust, r_p=r_p, x0=scenario.initial.displacement, v0=scenario.initial.velocity,
                  Bv=np.diag(Bv), Bq=np.diag(Bq), contacts=contacts, limit_trans=LIMIT_TRANS, limit_rot=LIMIT_ROT)
    if not env.calm:
        kwargs.update(push_direction=env.push_direction, current=env.kernel_current(),
                      skipper=None if env.skipper is None else env.skipper.kernel(scenario.thrust.force,
                                                                                 scenario.thrust.ramp, dt))
        if env.current is not None:     # the speed × √ramp: the drag grows with the push, their ratio fixed
            kwargs["current_ramp"] = np.sqrt(load_ramp(scenario, dt, n))
    provenance = {
        "boatland": __version__, "scenario": scenario.name, "scenario_sha256": scenario.digest(),
        "database": db.name, "seed": scenario.simulation.seed,
        **({} if gust_seed is None else {"gust_seed": gust_seed}), "dt": dt, "steps": n,
        "radiation": scenario.radiation.method, "memory": scenario.radiation.memory,
        "waves_from": wave_start(scenario), "wave_ramp": scenario.simulation.start_ramp if waves is not None else 0.0,
        "inputs": trial_inputs(scenario),
    }
    if override:
        provenance["waves"] = f"{type(waves).__name__} {waves.digest()}" if hasattr(waves, "digest") \
            else type(waves).__name__
    if progress is None and not sinks:
        out = arrays.run(dt, n, **kwargs)
    else:
        info = TrialInfo(setup=setup, contacts=contacts, waves=waves, provenance=dict(provenance))
        out = _run_watched(arrays, dt, n, kwargs, progress, sinks, info, F, thrust, progress_every)
    t = out["t"]
    k = len(t)
    provenance["wall_time"] = time.perf_counter() - wall0
    result = Result(t=t, x=out["x"], v=out["v"], F_exc=F[0:2 * k:2], thrust=out["thrust"],
                    mode=out["mode"], fn=out["fn"], ft=out["ft"], needed=out["needed"],
                    available=out["available"], tpos=out["tpos"], slide=out["slide"], work=out["work"],
                    status=out["status"], message=out["message"], provenance=provenance,
                    incidents=scenario.incidents)
    for sink in sinks:
        sink.finish(result)
    if out["status"] not in OUTCOME_STATUSES:
        raise BlowUpError(result, _likely_cause(setup, result))
    return result


def _run_watched(arrays, dt: float, n: int, kwargs: dict, progress, sinks, info: TrialInfo, F, thrust,
                 progress_every: float = 0.1) -> dict:
    """Run the kernel in a worker thread; meanwhile report its step counter to ``progress`` (every
    ``progress_every`` s) and hand each finished block of about one second of simulated time to the
    sinks as soon as the counter passes its end (the counter is read every few hundred µs). When the
    sinks fall behind the kernel, every finished block is handed over in one call (a whole number of
    blocks) so that they catch up."""
    counter = np.zeros(1, dtype=np.int64)
    block = max(1, int(round(1.0 / dt)))
    # the kernel may run at most one block ahead of what the sinks have taken (a killed run loses ≤ 1 s):
    # it waits having written row sent + block − 1, integrated to that row's time, while the sinks hold
    # the rows before ``sent`` — and the block it waits for is complete
    gate = np.array([block - 1 if sinks else n], dtype=np.int64)
    live = arrays.allocate_outputs(n, kwargs["contacts"][0].shape[0])
    box: dict = {}

    def work():
        try:
            box["out"] = arrays.run(dt, n, progress=counter, out=live, gate=gate, **kwargs)
        except BaseException as exc:  # handed to the caller's thread below
            box["error"] = exc

    for sink in sinks:
        sink.start(info)
    sent = 0                       # rows handed to the sinks so far
    shown = -1.0
    worker = threading.Thread(target=work, name="boatland-trial", daemon=True)
    worker.start()
    while True:
        alive = worker.is_alive()
        done = int(counter[0])     # rows below the count are final
        if progress is not None and time.perf_counter() - shown >= progress_every:
            progress(done, n)
            shown = time.perf_counter()
        if sinks and done - sent >= block:   # all finished whole blocks at once: a logger behind catches up
            k1 = sent + (done - sent) // block * block
            _send(sinks, live, F, thrust, dt, sent, k1)
            sent = k1
            gate[0] = sent + block - 1       # the sinks have it: let the kernel run one more block
            continue
        if not alive:
            break
        worker.join(0.1 if not sinks and progress_every >= 0.1 else 2e-4)
    if "error" in box:
        raise box["error"]
    out = box["out"]
    rows = len(out["t"])
    for k0 in range(sent, rows, block):
        _send(sinks, live, F, thrust, dt, k0, min(k0 + block, rows))
    if progress is not None:
        progress(n if out["status"] == 0 else rows - 1, n)
    return out


#: The kernel outputs a :class:`StepBlock` carries (the per-step friction work stays in the Result).
_BLOCK_SERIES = (frozenset(SERIES) - {"t", "F_exc", "thrust"}) | {"slide"}


def _send(sinks, live: dict, F, thrust, dt: float, k0: int, k1: int) -> None:
    """One block of final rows [k0, k1) with its events to every sink."""
    lo = max(k0 - 1, 0)
    t = np.arange(lo, k1) * dt
    events = [replace(e, step=e.step + lo) for e in extract_events(t, live["mode"][lo:k1], live["needed"][lo:k1],
                                                                     live["available"][lo:k1])]
    views = {k: a[k0:k1] for k, a in live.items() if k in _BLOCK_SERIES}
    for a in views.values():
        a.flags.writeable = False
    blk = StepBlock(k0=k0, k1=k1, t=t[k0 - lo:], F_exc=F[2 * k0:2 * k1:2], thrust=live["thrust"][k0:k1],
                    events=events, **views)
    for sink in sinks:
        sink.steps(blk)


def _likely_cause(setup: Setup, result) -> str:
    x = result.x[-1]
    dt, db = setup.dt, setup.db
    cp = setup.contact_period
    if cp is not None:
        if dt > 2 * cp.dt_limit:
            return (f"dt = {dt:g} s is large for the fender's contact modes (normal {cp.period:.3g} s, stuck shear "
                    f"{cp.shear_period:.3g} s): use dt ≤ {cp.dt_limit:.3g} s or a softer fender")
    if abs(x[3]) > LIMIT_ROT or abs(x[4]) > LIMIT_ROT:
        return "capsizing rotation: check the restoring matrix (C44, C55) and the centre of gravity"
    if np.any(np.diag(db.C)[2:5] <= 0):
        return "no hydrostatic restoring in heave/roll/pitch (C_ii ≤ 0) in the database"
    return "an unstable radiation memory or excitation far above the database band; try radiation.method = 'convolution' and a smaller dt"
