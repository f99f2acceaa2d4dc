"""Landing-trial speed: steps per second and real-time factor of the default trial (one core).

Run: ``python bench/bench_trial.py``. Goal (issue 5): ≥ 10 000× real time with state space,
≥ 2 000× with convolution (30–40 s memory), at dt = 0.05 s. Times exclude loading the database;
"integrate" is the RK4 kernel alone, "trial" the whole ``simulate`` (IRFs, waves, events).
"""

from __future__ import annotations

from _timing import best_of

import platform
import numpy as np

from boatland.scenario_check import default_scenario_path, load_checked
from boatland.trial.simulate import contact_arrays, prepare_memory, simulate, thrust_series
from boatland.model.motion import compile_motion



def main():
    import numba

    numba.set_num_threads(1)
    scenario, db, _ = load_checked(default_scenario_path())
    print(f"# {platform.machine()}, Python {platform.python_version()}, {scenario.name}, "
          f"{scenario.simulation.duration:g} s at dt = {scenario.time_step(db):g} s")
    print("| radiation | memory [s] | states or lags × pairs | integrate [s] | steps/s | × real time | trial [s] |")
    print("|---|---|---|---|---|---|---|")
    for method in ("convolution", "state_space"):
        for memory in ((40.0, 60.0) if method == "convolution" else (40.0,)):
            sc = scenario.replace({"radiation.method": method, "radiation.memory": memory})
            dt, n = sc.time_step(db), sc.n_steps(db)
            mem = prepare_memory(sc, db)
            arr = compile_motion(db, mem, dt, method=method, memory_length=memory)
            F = np.zeros((2 * n + 1, 6))
            th = thrust_series(sc, dt, n)
            ct = contact_arrays(sc, db)
            run = lambda: arr.run(dt, n, F_ext=F, thrust=th, r_p=sc.thrust.position, contacts=ct)  # noqa: E731
            t_int = best_of(run, 3)[0]
            t_all = best_of(lambda: simulate(sc, db, memory=mem), 3)[0]
            size = f"{arr.ss_A.shape[0]} states" if method == "state_space" else f"{arr.n_hist} × {arr.pairs_i.size}"
            print(f"| {method} | {memory:g} | {size} | {t_int:.3f} | {n / t_int:,.0f} | "
                  f"{sc.simulation.duration / t_int:,.0f} | {t_all:.3f} |")


if __name__ == "__main__":
    main()
