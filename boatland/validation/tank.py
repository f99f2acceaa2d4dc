r"""Ferreira González (2023): the catamaran *Model 2* in the tank, sea states J01–J04 (Table 5.3).

In the tank the model pushed its bow fender on the landing of a cylinder in JONSWAP waves. What the
dissertation *states* (there are no numeric time series, only figures):

- §4.3.3, Fig. 4.20 (J03: H_s = 0.1 m, ω_p = 4.97 rad/s, head seas): with 123.84 N of thrust the fender
  *remained fixed*; with 52 N it slipped at t_s ≈ 16 s — "after a sudden movement upwards the fender
  slides again downwards but stays fixed at a higher position than before".
- §5.2.3 (Fig. 5.22, 5.23) and Appendix A.2 (Fig. A.2, A.3): the simulated and measured motions "fairly
  agree"; for J04 (ν = 15°) the tank model showed "small roll motions during the whole measurement";
  for J01 and J02 the text says only that "the vertical displacement of the fender is not represented
  exactly" — whether the fender held or slipped there, and with which thrust, is not stated.

So J03's two thrusts are judged (slip or hold over a tank-length record, and the direction of the
52 N slip), and J01, J02 and J04 are reported without a verdict. Each run uses its scenario file
(``scenarios/model2_j0*.toml``, which states its sources and assumptions) over several wave seeds; an
*incident* is a fender point more than 1 cm from where it landed (Grøtting's 10 cm at the model's
1:10 scale). The thesis shows one record per run and does not state its length; its figures span the
first few tens of seconds, so a tank record is taken as 40 s of waves.

Incident rate by maximum likelihood with censoring (Grøtting 2015 §3.3): λ̂ = incidents / total time at
risk, and P(a record of T s holds) = e^{−λ̂T}.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from boatland.validation.case import Case, Check, Context, Outcome

__all__ = ["LIMIT", "RECORD", "RUNS", "TankRun", "tank_runs", "first_incidents", "rate", "CASES"]

LIMIT = 0.01       # [m] Grøtting's 10 cm at 1:10
RECORD = 40.0      # [s] of waves: a tank-length record
HOLD_SHARE, SLIP_SHARE = 0.7, 0.8    # the tank's outcome in at least this share of the seeds
#: (scenario file, label, what the dissertation states)
RUNS = (
    ("model2_j01.toml", "J01, 123.84 N", None),
    ("model2_j02.toml", "J02, 123.84 N", None),
    ("model2_j03.toml", "J03, 123.84 N", "hold"),
    ("model2_j03_52N.toml", "J03, 52 N", "slip"),
    ("model2_j04.toml", "J04 (ν = 15°), 123.84 N", None),
)


@dataclass(frozen=True)
class TankRun:
    """One scenario over seeds: first-incident times after the waves start (inf: none) and per seed the
    fender's mean vertical displacement on the tubes from where it landed (t from the waves' start)."""

    label: str
    times: np.ndarray
    exposure: float
    t: list
    dz: list
    roll_std_deg: np.ndarray
    thrust: float


def first_incidents(path, seeds, limit: float = LIMIT, duration: float | None = None) -> TankRun:
    """Run the scenario file ``path`` for each seed; the first time a fender point is more than ``limit``
    from where it landed, counted from the start of the waves (:func:`boatland.trial.simulate.wave_start`)."""
    from boatland.checks.files import load_checked
    from boatland.landing.setup import Setup
    from boatland.trial.simulate import simulate, wave_start

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(path)
    changes = {"incidents.slip_distance": [limit]}
    if duration is not None:
        changes["simulation.duration"] = duration
    scenario = scenario.replace(changes)
    memory = Setup.of(scenario, db).memory()
    t0 = wave_start(scenario)
    times, ts, dzs, rolls = [], [], [], []
    for seed in seeds:
        r = simulate(scenario.replace({"simulation.seed": seed}), db, memory=memory)
        if not r.completed:
            raise RuntimeError(f"{Path(path).name}, seed {seed}: {r.message}")
        t = r.incident_times()[f"slip > {limit:g} m"]
        times.append(np.inf if t is None else t - t0)
        k = int(np.searchsorted(r.t, r.settled_at - 1e-9))
        ts.append(r.t[k:] - t0)
        dzs.append((r.tpos[k:, :, 0] - r.tpos[k, :, 0]).mean(axis=1))
        rolls.append(np.degrees(np.std(r.x[r.t >= r.exposure_from, 3])))
    return TankRun(Path(path).stem, np.array(times), scenario.simulation.duration - t0, ts, dzs, np.array(rolls),
                   scenario.thrust.force)


def rate(times, exposure) -> float:
    """Censored exponential MLE of the incident rate: incidents / total time at risk [1/s]."""
    hit = np.isfinite(times)
    return float(hit.sum() / np.sum(np.where(hit, times, exposure)))


def tank_runs(scenarios: Path, seeds: dict, duration: float | None = None, progress=print) -> dict:
    """Every run of :data:`RUNS` from the folder ``scenarios`` over its seeds (``seeds``: label → seeds):
    ``{label: TankRun}``."""
    out = {}
    for file, label, _ in RUNS:
        progress(f"  tank: {label}, {len(seeds[label])} seeds")
        out[label] = first_incidents(Path(scenarios) / file, seeds[label], duration=duration)
    return out


def _slip_shape(run: TankRun, record: float = RECORD):
    """For each seed with an incident within ``record``: (its first excursion beyond the limit was upward,
    the fender rests higher 10 s after it than where it landed)."""
    out = []
    for t_inc, t, dz in zip(run.times, run.t, run.dz):
        if not np.isfinite(t_inc) or t_inc > record:
            continue
        k = int(np.searchsorted(t, t_inc - 1e-9))
        later = np.nonzero(t >= t_inc + 10.0)[0]
        rest = dz[later[0]] if later.size else dz[-1]
        out.append((bool(dz[min(k, dz.size - 1)] > 0), bool(rest > 0)))
    return out


def run_tank(ctx: Context) -> Outcome:
    """Case model2-tank: the five Model 2 scenario files over seeds, against what the dissertation states."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    judged, other = (10, 3) if ctx.quick else (10, 10)
    seeds = {label: range(1, (judged if stated else other) + 1) for _, label, stated in RUNS}
    duration = None
    if ctx.quick:
        duration = 3.0 + RECORD + 12.0      # thrust ramp, a tank record and the 10 s after a slip
    runs = tank_runs(ctx.scenarios, seeds, duration=duration, progress=ctx.progress)
    checks = []
    for _, label, stated in RUNS:
        run = runs[label]
        n_seeds = len(seeds[label])
        within = int(np.sum(run.times <= RECORD))
        lam = rate(run.times, run.exposure)
        over = f"; over {run.exposure:.0f} s: {int(np.isfinite(run.times).sum())}/{n_seeds}, λ̂ = {lam:.3g}/s, " \
               f"P(hold {RECORD:g} s) = e^(−λ̂·{RECORD:g}) = {np.exp(-lam * RECORD):.2f}"
        measured = f"incident within {RECORD:g} s in {within}/{n_seeds} seeds{over}"
        if stated == "hold":
            need = int(np.ceil(HOLD_SHARE * n_seeds))
            checks.append(Check(f"{label}: the fender held (Fig. 4.20)", measured,
                                f"holds {RECORD:g} s in ≥ {need}/{n_seeds}", bool(n_seeds - within >= need),
                                float(within / n_seeds), 1 - HOLD_SHARE))
        elif stated == "slip":
            need = int(np.ceil(SLIP_SHARE * n_seeds))
            checks.append(Check(f"{label}: the fender slipped, at t ≈ 16 s (Fig. 4.20)",
                                measured + (f"; median time {np.median(run.times[np.isfinite(run.times)]):.1f} s"
                                            if np.isfinite(run.times).any() else ""),
                                f"slips within {RECORD:g} s in ≥ {need}/{n_seeds}", bool(within >= need),
                                float(within / n_seeds), SLIP_SHARE))
            shape = _slip_shape(run)
            up = sum(s[0] for s in shape)
            higher = sum(s[1] for s in shape)
            n = len(shape)
            checks.append(Check(f"{label}: \"a sudden movement upwards\" (§4.3.3): the first excursion beyond "
                                f"{100 * LIMIT:g} cm is upward", f"{up}/{n} slipping seeds", "more than half",
                                bool(n and up > n / 2)))
            checks.append(Check(f"{label}: \"stays fixed at a higher position than before\" (§4.3.3): the "
                                "fender 10 s after the slip is above where it landed", f"{higher}/{n} slipping seeds",
                                "more than half", bool(n and higher > n / 2)))
        else:
            extra = f"; σ_roll {np.mean(run.roll_std_deg):.3f}° (mean over seeds)" if "J04" in label else ""
            checks.append(Check(f"{label}: outcome not stated in the dissertation", measured + extra,
                                "none stated", None))
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.0), constrained_layout=True)
    labels = [label for _, label, _ in RUNS]
    p40 = [np.mean(runs[lab].times <= RECORD) for lab in labels]
    pall = [np.mean(np.isfinite(runs[lab].times)) for lab in labels]
    x = np.arange(len(labels))
    ax[0].bar(x - 0.2, p40, 0.4, label=f"incident within {RECORD:g} s (a tank record)")
    ax[0].bar(x + 0.2, pall, 0.4, label=f"incident within {runs[labels[0]].exposure:.0f} s")
    for i, (_, _, stated) in enumerate(RUNS):
        ax[0].text(i, 1.04, {"hold": "tank: held", "slip": "tank: slipped", None: "not stated"}[stated],
                   ha="center", fontsize=8)
    ax[0].set_xticks(x, [lab.replace(", ", "\n") for lab in labels], fontsize=8)
    ax[0].set_ylim(0, 1.3)
    ax[0].set_yticks(np.linspace(0, 1, 6))
    ax[0].set_ylabel(f"share of the seeds with a slip > {100 * LIMIT:g} cm")
    ax[0].legend(fontsize=7, loc="upper center", ncol=2)
    for lab, color in (("J03, 123.84 N", "C0"), ("J03, 52 N", "C3")):
        run = runs[lab]
        for k in range(min(3, len(run.t))):
            ax[1].plot(run.t[k], 100 * run.dz[k], color=color, lw=0.8, alpha=0.9 - 0.25 * k,
                       label=lab if k == 0 else None)
    ax[1].axvline(16.0, color="k", ls=":", lw=0.8, label="tank: 52 N slipped at ≈ 16 s")
    ax[1].set_xlim(0, RECORD + 10)
    ax[1].set_xlabel("t from the waves' start [s]")
    ax[1].set_ylabel("fender height on the tubes from landing [cm]")
    ax[1].set_title("J03, seeds 1–3")
    for a in ax:
        a.grid(alpha=0.3)
    ax[1].legend(fontsize=7)
    name = ctx.save(fig, "model2_tank_runs.png")
    judged = [k for k in checks if k.passed is not None]
    return Outcome(
        checks, f"{sum(k.passed for k in judged)}/{len(judged)} stated outcomes reproduced", name,
        ["The dissertation gives no numeric time series (figures only), so the motions and fender displacements "
         "of §5.2.3 and Appendix A.2 cannot be compared number by number; what its text states is compared "
         "above. Its thrust is stated for J03 only (Fig. 4.20); the J01, J02 and J04 scenario files use "
         "123.84 N, an assumption. The time of the tank's slip (t ≈ 16 s) is on the tank record's clock, "
         "whose origin relative to the waves' arrival is not stated: shown in the figure, not judged."],
        settings=(f"10 seeds for the judged J03 runs, 3 for the others, {duration:g} s per trial (--quick)"
                  if ctx.quick else "10 seeds per run, each scenario's full 190 s"))


CASES = [
    Case("model2-tank", "Ferreira González (2023) Model 2 tank runs J01–J04: slip or hold",
         "Ferreira González, D. (2023), *Development of a Numerical Approach for the Simulation of Boatlanding "
         "Maneuvers*, Dr.-Ing. dissertation, TU Hamburg: Table 5.3 (sea states J01–J04), Table 5.4 (fender "
         "model), §4.3.3 and Fig. 4.20 (J03 at 123.84 N held, at 52 N slipped at t ≈ 16 s, upwards, and "
         "rested higher), §5.2.3, Fig. 5.22–5.23 and Appendix A.2, Fig. A.2–A.3 (J01, J02, J04).",
         "The five scenario files `scenarios/model2_j01.toml` … `model2_j04.toml` (model scale, the built-in "
         "`model2` database, rigid stick with the Table 5.4 fender) over several wave seeds; first time a "
         "fender point is more than 1 cm from where it landed, counted from the waves' start; the fender's "
         "height on the tubes around the first slip.",
         "share of seeds with the stated outcome within a 40 s tank record; direction of the slip",
         "the tank's outcome in ≥ 70 % (hold) / ≥ 80 % (slip) of the seeds", run_tank,
         scenario_files=tuple(f for f, _, _ in RUNS),
         quick="3 seeds for J01, J02, J04, and 55 s per trial (full: 10 seeds each, 190 s)",
         cite="Ferreira González (2023), Tables 5.3–5.4, Fig. 4.20"),
]
