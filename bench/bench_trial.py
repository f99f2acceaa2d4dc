"""Landing-trial speed: steps per second (one core) and real-time factor of the RK4 kernel.

Run: ``python bench/bench_trial.py``. Goal (issue 5): at dt = 0.05 s, ≥ 10 000× real time with the
state-space radiation, ≥ 2 000× with convolution of 30 s memory, for the trial of the first default,
``scenarios/ctv24_landing.toml`` (the Wigley ctv24, whose radiation memory decays within 40 s and whose
bow geometry the contact variants below are built on; the default ctv27 rings for 75 s). Three tables:

1. that trial (600 s of JONSWAP waves, two contacts): convolution with 30 s memory (the goal)
   and 40 s (the scenario's), state space; "kernel" is :meth:`MotionArrays.run` on the trial's own
   wave excitation, "simulate" the whole service (waves, kernel, events; IRFs reused);
2. kernel cost against the convolution memory length (10–30 s truncate the 40 s IRF);
3. kernel cost against the number of fender contacts (1, 2, 4), every row a real landing: the trial
   completes (no runaway), with the share of steps in which every contact touches and the slip events
   printed beside.

Every case is prepared first, then all are timed round-robin for ``ROUNDS`` rounds and each keeps its
shortest time (after a warm-up: numba compiled and cached). The machine is a shared VM whose speed
drifts by up to 2× over tens of seconds; interleaving gives every row the same chance of a fast phase.
"""

from __future__ import annotations

import platform
import time

import numpy as np

from pathlib import Path

from boatland.checks.files import load_checked
from boatland.landing.setup import Setup
from boatland.trial.motion import compile_motion
from boatland.trial.simulate import LIMIT_ROT, LIMIT_TRANS, simulate, thrust_series, wave_ramp

ROUNDS = 12
CTV24_LANDING = Path(__file__).resolve().parents[1] / "scenarios" / "ctv24_landing.toml"
IRF_MEMORY = 40.0  # [s] ctv24's IRF has not decayed by 30 s (6 % left in yaw): shorter memories truncate it


def trial_inputs(sc, db, memory):
    """Kernel arrays and keyword arguments of the scenario's trial, waves included (as ``simulate``)."""
    setup = Setup.of(sc, db)
    dt, n = setup.dt, setup.n_steps
    arr = compile_motion(db, memory, dt, method=sc.radiation.method, memory_length=sc.radiation.memory)
    x0, y0, psi = sc.start_pose()
    F = setup.waves.excitation(db, seed=sc.simulation.seed, dt=dt, n_steps=n, x0=x0, y0=y0,
                               heading_deg=float(np.degrees(psi)), ramp_time=0.0)
    F *= wave_ramp(sc, dt, n)[:, None]
    Bv, Bq = setup.additional_damping()
    kw = dict(F_ext=F, thrust=thrust_series(sc, dt, n), r_p=sc.thrust.position, x0=sc.initial.displacement,
              v0=sc.initial.velocity, Bv=np.diag(Bv), Bq=np.diag(Bq), contacts=setup.contacts(),
              limit_trans=LIMIT_TRANS, limit_rot=LIMIT_ROT)
    return arr, dt, n, kw


_MEMORIES: dict = {}  # radiation memories by (method, IRF length), shared by the rows


def radiation(sc, db, method, memory):
    """The scenario with this radiation method and memory, and its radiation memory (IRF over at least
    ``IRF_MEMORY``, fitted for the state space)."""
    sc = sc.replace({"radiation.method": method, "radiation.memory": memory})
    key = (method, max(memory, IRF_MEMORY))
    if key not in _MEMORIES:
        _MEMORIES[key] = Setup.of(sc.replace({"radiation.memory": key[1]}), db).memory()
    return sc, _MEMORIES[key]


class Case:
    """One timed kernel run of a scenario's trial: shortest time over the rounds, last result."""

    def __init__(self, sc, mem, db):
        self.arr, self.dt, self.n, self.kw = trial_inputs(sc, db, mem)
        self.out = self.run()  # warm-up: compile or load from the cache
        self.best = float("inf")

    def run(self):
        return self.arr.run(self.dt, self.n, **self.kw)

    def time(self):
        t0 = time.perf_counter()
        self.out = self.run()
        self.best = min(self.best, time.perf_counter() - t0)


def slips(out) -> int:
    """Slip events: a contact that starts to slide."""
    m = out["mode"]
    return int(np.sum((m[1:] == 2) & (m[:-1] != 2)))


def size(arr) -> str:
    return f"{arr.n_states} states" if not arr.conv else f"{arr.n_hist} × {arr.pairs_i.size}"


def main():
    import numba

    numba.set_num_threads(1)
    scenario, db, _ = load_checked(CTV24_LANDING)
    T = scenario.simulation.duration
    print(f"# {platform.machine()}, Python {platform.python_version()}, numba {numba.__version__}, "
          f"{scenario.name}: {T:g} s at dt = {Setup.of(scenario, db).dt:g} s, one core, best of {ROUNDS}\n")
    default, by_memory, by_contacts, sims = {}, {}, {}, {}
    for method, memory in (("convolution", 30.0), ("convolution", 40.0), ("state_space", 40.0)):
        sims[method, memory] = radiation(scenario, db, method, memory)
        default[method, memory] = Case(*sims[method, memory], db)
    for memory in (10.0, 20.0, 30.0, 40.0, 60.0):
        by_memory[memory] = Case(*radiation(scenario, db, "convolution", memory), db)
    for label, sc_c in contact_variants(scenario):
        for method in ("convolution", "state_space"):
            by_contacts[label, method] = Case(*radiation(sc_c, db, method, 40.0), db)
    cases = [*default.values(), *by_memory.values(), *by_contacts.values()]
    t_sim = {k: float("inf") for k in sims}
    for r in range(ROUNDS):
        for case in cases:
            case.time()
        if r < 3:
            for k, (sc, mem) in sims.items():
                t0 = time.perf_counter()
                simulate(sc, db, memory=mem)
                t_sim[k] = min(t_sim[k], time.perf_counter() - t0)

    def figures(case):
        t, n = case.best, case.n
        return f"{t:.3f} | {n / t:,.0f} | {T / t:,.0f} | {t / n * 1e6:.2f}"

    print("| radiation | memory [s] | lags × pairs or states | kernel [s] | steps/s | × real time | µs/step "
          "| simulate [s] | slip events |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (method, memory), case in default.items():
        print(f"| {method} | {memory:g} | {size(case.arr)} | {figures(case)} | {t_sim[method, memory]:.3f} "
              f"| {slips(case.out)} |")

    print("\nConvolution: kernel cost against the memory length (ctv24 trial)\n")
    print("| memory [s] | lags × pairs | kernel [s] | steps/s | × real time | µs/step |")
    print("|---|---|---|---|---|---|")
    for memory, case in by_memory.items():
        print(f"| {memory:g} | {size(case.arr)} | {figures(case)} |")

    print("\nKernel cost against the number of fender contacts (ctv24 trial otherwise)\n")
    print("| contacts | radiation | kernel [s] | steps/s | × real time | µs/step | status | all in touch "
          "| slip events |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (label, method), case in by_contacts.items():
        touching = float(np.mean((case.out["mode"] != 0).all(axis=1)))
        print(f"| {label} | {method} 40 s | {figures(case)} | {case.out['message']} | {touching:.1%} "
              f"| {slips(case.out)} |")


def contact_variants(scenario):
    """1 contact (one tube on the centreline), 2 (the scenario: two tubes 1.5 m apart) and 4 (the two
    tubes each touched at two fender heights, 1.5 m and 0.6 m above the waterline)."""
    landing = {"monopile_diameter": 6.5, "monopile_position": [0.0, 0.0]}
    x_tube = -(6.5 / 2 + 1.2)  # the compact landing's tube axes: pile radius + standoff, facing −x

    def tube(y):
        return {"position": [x_tube, y], "diameter": 0.35, "normal_deg": 180.0}

    one = scenario.replace({"landing": dict(landing, struts=[tube(0.0)]), "fender.points": [[12.3, 0.0, 1.5]]})
    four = scenario.replace({
        "landing": dict(landing, struts=[tube(0.75), tube(-0.75), tube(0.75), tube(-0.75)]),
        "fender.points": [[12.3, 0.75, 1.5], [12.3, -0.75, 1.5], [12.3, 0.75, 0.6], [12.3, -0.75, 0.6]]})
    return (("1", one), ("2", scenario), ("4", four))


if __name__ == "__main__":
    main()
