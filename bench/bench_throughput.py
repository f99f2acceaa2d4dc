"""Campaigns at the kernel's speed (issue 16): kernel-only, full-trial and campaign steps/s, side by side
in one run, for 600, 1,800 and 10,000-s accesses on 1 and 2 workers — the last row of 2 workers is the
seed-002 study size end to end (72 trials × 10,000 s, 9 sea states; SIMO: 45 min per sea state).

Run: ``python bench/bench_throughput.py [--accesses 600 1800 10000] [--rounds 2] [--repeat 1] [--before CHECKOUT]``
(``--before``: every campaign row again with another checkout, e.g. ``git archive ba34c7f`` unpacked,
right after it — before/after in the same run). Prints Markdown.

The study: ``scenarios/campaigns/table414.toml``'s shape — ctv24, 80 kN, Hs 0.3 m, Tp 5/7/9 s ×
180/135/90° (9 sea states), 8 seeds (72 trials), state-space memory, the pile's scattered wave —
with its ``access`` (the exposure after the 20 s settling and the 2 Tp wave ramp) set to
each access. Steps are every step a trial integrates (settling and ramp included), dt = 0.05 s.

1. **Per trial, this process, one core**: the first seed of each of the 9 cases, timed round-robin
   (kernel, trial, next case, …) for ``--rounds`` rounds, best per case; steps/s = Σ steps / Σ best.
   *kernel*: :meth:`MotionArrays.run` on the trial's own inputs (as :func:`simulate` makes them: the
   excitation with the pile's scattered wave, the wave ramp, thrust, contacts); *trial*: what a campaign
   worker does per trial — :func:`boatland.campaign.runner.execute_trial` with its case's
   :class:`boatland.campaign.prepare.CaseData` (scenario, waves, kernel, events, episodes, summary row).
2. **Where a 10,000-s trial's time goes**: cProfile of one ``execute_trial`` (the largest access asked).
3. **Campaigns**: the ``boatland campaign`` CLI in a subprocess (start-up, imports, checks, the
   once-per-campaign preparation, workers, store, screening, statistics — end to end) on 1 and 2 local
   workers, fresh store each time; wall, the CPU time of the whole process tree, and the ratio of its
   steps/s to 1× / 2× the kernel-only steps/s measured right before and right after it (one call of
   three cases' kernels — Tp 5 s head, 7 s 135°, 9 s beam — their mean: this VM's speed drifts by up to
   2× over minutes, so part 1's rate is not the campaign's): with one core busy (this process alone),
   and per core with both busy (the same calls in this process and a fork at once — what a core gives
   a worker while the other works too). ``--repeat N``: N rows per code, interleaved; the median and
   spread of the ratios.

The machine is shared: the load average is printed before and after every row, CPU time beside wall,
and (Linux) the share of the machine's CPU time the hypervisor took for others during the campaign
("host steal", ``/proc/stat``).
"""

from __future__ import annotations

import argparse
import cProfile
import datetime
import os
import platform
import pstats
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from _timing import cpu_name
from boatland.landing.setup import Setup

REPO = Path(__file__).resolve().parents[1]
STUDY = REPO / "scenarios" / "campaigns" / "table414.toml"


def study_file(tmp: Path, access: float, seeds: int = 8) -> Path:
    """table414.toml with its ``access`` set (and ``seeds``), its scenario path made absolute."""
    text = STUDY.read_text(encoding="utf-8")
    text = re.sub(r"(?m)^access = [^#\n]*", f"access = {access:g}  ", text)
    text = re.sub(r"(?m)^seeds = .*$", f"seeds = {seeds}", text)
    text = text.replace('"../ctv24_landing.toml"', f'"{(STUDY.parent / "../ctv24_landing.toml").resolve()}"')
    path = tmp / f"study_{access:g}_{seeds}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def load():
    from boatland.checks.files import load as load_scenario, resolve_database

    return load_scenario, resolve_database


def kernel_inputs(scenario, db, arrays):
    """The kernel call of :func:`boatland.trial.simulate.simulate` for this scenario (same inputs)."""
    from boatland.landing.setup import Setup
    from boatland.trial.simulate import LIMIT_ROT, LIMIT_TRANS, thrust_series, wave_ramp

    setup = Setup.of(scenario, db)
    dt, n = setup.dt, setup.n_steps
    x0, y0, psi = scenario.start_pose()
    F = setup.waves.excitation(db, seed=scenario.simulation.seed, dt=dt, n_steps=n, x0=x0, y0=y0,
                               heading_deg=float(np.degrees(psi)), ramp_time=0.0, pile=setup.pile)
    F *= wave_ramp(scenario, dt, n)[:, None]
    Bv, Bq = setup.additional_damping()
    kw = dict(F_ext=F, thrust=thrust_series(scenario, dt, n), r_p=scenario.thrust.position,
              x0=scenario.initial.displacement, v0=scenario.initial.velocity, Bv=np.diag(Bv), Bq=np.diag(Bq),
              contacts=setup.contacts(), limit_trans=LIMIT_TRANS, limit_rot=LIMIT_ROT)
    return lambda: arrays.run(dt, n, **kw), n


def timed(fn):
    """(wall, CPU) seconds of one call."""
    w, c = time.perf_counter(), time.process_time()
    fn()
    return time.perf_counter() - w, time.process_time() - c


def per_trial(path: Path, rounds: int):
    """Kernel-only and full-trial (wall, CPU, steps) over the first seed of every case; best per case."""
    from boatland.campaign.plan import load_campaign
    from boatland.campaign.prepare import check_cases, prepare_cases
    from boatland.campaign.runner import execute_trial

    loaders = load()
    campaign = load_campaign(path, load_scenario=loaders[0])
    check_cases(campaign, loaders[1])
    shared = prepare_cases(campaign, loaders[1])
    db = loaders[1](campaign.base)
    specs = [campaign.trials()[c * campaign.seeds] for c in range(len(campaign.cases))]
    runs = []
    for spec in specs:
        sc = campaign.scenario_for(spec)
        kernel, n = kernel_inputs(sc, db, shared[spec.case].arrays)
        trial = lambda spec=spec: execute_trial(campaign, spec, loaders, None, shared[spec.case])  # noqa: E731
        kernel(), trial()                                    # warm: compiled, cached, tables in place
        runs.append([kernel, trial, n, [np.inf, np.inf], [np.inf, np.inf]])
    for _ in range(rounds):
        for run in runs:
            for i in (0, 1):
                w, c = timed(run[i])
                run[3][i], run[4][i] = min(run[3][i], w), min(run[4][i], c)
    steps = sum(r[2] for r in runs)
    wall = [sum(r[3][i] for r in runs) for i in (0, 1)]
    cpu = [sum(r[4][i] for r in runs) for i in (0, 1)]
    return steps, wall, cpu, (campaign, specs[-1], loaders, shared[specs[-1].case]), [(r[0], r[2]) for r in runs]


def kernel_rate(kernels) -> float:
    """Kernel-only steps/s (wall) of one call of each kernel: the machine's speed right now, one core busy."""
    steps = sum(n for _, n in kernels)
    return steps / sum(timed(k)[0] for k, _ in kernels)


def kernel_pair_rate(kernels) -> float:
    """Steps/s per process of the same calls in two processes at once (this one and a fork): what each
    core gives when both are busy, as in a campaign on two workers."""
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:                                            # the child: its rate to the pipe, then out
        try:
            os.write(w, np.float64(kernel_rate(kernels)).tobytes())
        finally:
            os._exit(0)
    own = kernel_rate(kernels)
    os.waitpid(pid, 0)
    other = float(np.frombuffer(os.read(r, 8))[0])
    os.close(r), os.close(w)
    return 0.5 * (own + other)


def profile_trial(campaign, spec, loaders, shared):
    """Share of one execute_trial's time per stage (cProfile, cumulative)."""
    from boatland.campaign.runner import execute_trial

    prof = cProfile.Profile()
    prof.enable()
    execute_trial(campaign, spec, loaders, None, shared)
    prof.disable()
    stats = pstats.Stats(prof).stats
    total = max(v[3] for (f, _, name), v in stats.items() if name == "execute_trial")

    def cum(file_part, name):
        return sum(v[3] for (f, _, nm), v in stats.items() if nm == name and file_part in f)

    parts = [("kernel (run_cummins)", cum("integrate/cummins", "run_cummins")),
             ("wave excitation (NUFFT, pile tables looked up)", cum("sea/states", "excitation")),
             ("events + slip episodes", cum("trial/events", "extract_events") + cum("trial/events", "slip_episodes")),
             ("summary row (incidents, offsets)", cum("campaign/runner", "summary_row")),
             ("scenario of the trial (validated)", cum("campaign/plan", "scenario_for")),
             ("thrust, ramp, contacts", cum("trial/simulate", "thrust_series") + cum("trial/simulate", "wave_ramp")
              + cum("landing/setup", "contacts"))]
    parts.append(("rest", total - sum(p for _, p in parts)))
    return total, parts


def campaign(path: Path, store: Path, workers: int, code: Path = REPO):
    """(wall, CPU of the process tree) of the real CLI of the checkout ``code``."""
    env = dict(os.environ, PYTHONPATH=str(code))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "boatland", "campaign", str(path), "-o", str(store),
                        "--workers", str(workers)], capture_output=True, text=True, env=env, cwd=str(code))
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode:
        raise SystemExit(r.stderr)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def load_text() -> str:
    return "/".join(f"{x:.1f}" for x in os.getloadavg())


def cpu_ticks() -> tuple[int, int] | None:
    """(all, steal) CPU ticks of the machine since boot (Linux ``/proc/stat``; None elsewhere): *steal* is
    the time the hypervisor ran something else while this guest's vCPUs wanted to run."""
    try:
        with open("/proc/stat", encoding="ascii") as f:
            ticks = [int(v) for v in f.readline().split()[1:9]]
    except (OSError, ValueError):
        return None
    return sum(ticks), ticks[7]


def steal_text(t0, t1) -> str:
    if t0 is None or t1 is None or t1[0] <= t0[0]:
        return "–"
    return f"{100 * (t1[1] - t0[1]) / (t1[0] - t0[0]):.1f} %"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--accesses", type=float, nargs="+", default=[600.0, 1800.0, 10000.0])
    ap.add_argument("--rounds", type=int, default=2, help="rounds of the per-trial timing (best per case)")
    ap.add_argument("--seeds", type=int, default=8, help="seeds per case of the campaigns (8: 72 trials)")
    ap.add_argument("--workers", type=int, nargs="*", default=[1, 2], help="campaign rows (none: per trial only)")
    ap.add_argument("--repeat", type=int, default=1,
                    help="campaign rows per code, interleaved with --before's (this VM's speed drifts: the spread "
                         "of the ratio over repeats is the honest figure)")
    ap.add_argument("--before", type=Path, metavar="CHECKOUT",
                    help="also run each campaign with this checkout of boatland (e.g. an older commit), right after")
    args = ap.parse_args()
    import numba
    import scipy

    numba.set_num_threads(1)
    print(f"# {cpu_name()}, {os.cpu_count()} CPU, Python {platform.python_version()}, numpy {np.__version__}, "
          f"scipy {scipy.__version__}, numba {numba.__version__}, {datetime.date.today().isoformat()}, "
          f"load average {load_text()} (1/5/15 min) at start\n")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        campaign(study_file(tmp, 30.0, 1), tmp / "warm.h5", 2)          # numba caches warm
        if args.before:
            campaign(study_file(tmp, 30.0, 1), tmp / "warm_before.h5", 2, args.before)
        profile, kernels = None, {}
        print("| access [s] | steps per trial (mean) | kernel steps/s (CPU) | trial steps/s (CPU) "
              "| trial / kernel (CPU) | trial cost per simulated s [ms] (CPU) | load |")
        print("|---|---|---|---|---|---|---|")
        for access in args.accesses:
            path = study_file(tmp, access, args.seeds)
            load0 = load_text()
            steps, wall, cpu, last, runs = per_trial(path, args.rounds)
            kernels[access] = runs[::4]                          # Tp 5 s head, Tp 7 s 135°, Tp 9 s beam
            sim_s = steps * 0.05
            print(f"| {access:,.0f} | {steps / 9:,.0f} | {steps / wall[0]:,.0f} ({steps / cpu[0]:,.0f}) | "
                  f"{steps / wall[1]:,.0f} ({steps / cpu[1]:,.0f}) | {wall[0] / wall[1]:.2f} ({cpu[0] / cpu[1]:.2f}) | "
                  f"{1e3 * wall[1] / sim_s:.3f} ({1e3 * cpu[1] / sim_s:.3f}) | {load0} → {load_text()} |", flush=True)
            if access == max(args.accesses):
                profile = (access, profile_trial(*last))
        if profile is not None:
            access, (total, parts) = profile
            print(f"\nOne trial of the {access:,.0f}-s access (last case: Tp 9 s, beam seas), cProfile, "
                  f"{total:.2f} s in all:\n")
            print("| stage | time [s] | share |")
            print("|---|---|---|")
            for name, t in parts:
                print(f"| {name} | {t:.3f} | {100 * t / total:.1f} % |")
        print("\n| access [s] | trials × steps | workers | code | wall [s] | CPU [s] | campaign steps/s | "
              "kernel steps/s, one core busy: before → after | per core, both busy: before → after | "
              "÷ (workers × kernel, one busy) | ÷ (workers × kernel, both busy) | host steal | load |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        codes = [("this", REPO)] + ([(f"before: {args.before.name}", args.before)] if args.before else [])
        from boatland.campaign.plan import load_campaign

        ratios: dict = {}
        for access in args.accesses:
            path = study_file(tmp, access, args.seeds)
            c = load_campaign(path, load_scenario=load()[0])
            db = load()[1](c.base)
            steps = sum(Setup.of(c.scenario_for(s), db).n_steps for s in c.trials())
            for workers in args.workers:
                for row, (label, code) in enumerate([lc for _ in range(args.repeat) for lc in codes]):
                    load0 = load_text()
                    ks = kernels[access]                            # the machine's speed drifts: bracket
                    before, pair0 = kernel_rate(ks), kernel_pair_rate(ks)
                    ticks0 = cpu_ticks()
                    wall, cpu = campaign(path, tmp / f"c{access:g}_{workers}_{row}.h5", workers, code)
                    steal = steal_text(ticks0, cpu_ticks())
                    after, pair1 = kernel_rate(ks), kernel_pair_rate(ks)
                    rate, k_one = steps / wall, 0.5 * (before + after)
                    k_both = 0.5 * (pair0 + pair1) if workers > 1 else k_one
                    ratios.setdefault((access, workers, label), []).append(
                        (rate / (workers * k_one), rate / (workers * k_both), wall))
                    print(f"| {access:,.0f} | {c.n_trials} × {steps / c.n_trials:,.0f} | {workers} | {label} | "
                          f"{wall:.1f} | {cpu:.1f} | {rate:,.0f} | {before:,.0f} → {after:,.0f} | "
                          f"{pair0:,.0f} → {pair1:,.0f} | {100 * rate / (workers * k_one):.0f} % | "
                          f"{100 * rate / (workers * k_both):.0f} % | {steal} | {load0} → {load_text()} |", flush=True)
        if args.repeat > 1:
            print("\n| access [s] | workers | code | rows | ÷ (workers × kernel, one busy): median (min – max) "
                  "| ÷ (workers × kernel, both busy): median (min – max) | wall [s]: median (min – max) |")
            print("|---|---|---|---|---|---|---|")

            def spread(x, f="{:.0f}", scale=100.0):
                return f"{f.format(scale * np.median(x))} ({f.format(scale * x.min())} – {f.format(scale * x.max())})"

            for (access, workers, label), v in ratios.items():
                one, both, w = np.array(v).T
                print(f"| {access:,.0f} | {workers} | {label} | {len(w)} | {spread(one)} % | {spread(both)} % | "
                      f"{spread(w, '{:.1f}', 1.0)} |")


if __name__ == "__main__":
    main()
