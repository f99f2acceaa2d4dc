r"""The screening against the time domain with the loads beside the waves: a tidal current and a gusty wind
on the default landing (ctv27, ``scenarios/ctv_landing.toml``).

For head, bow-quartering and beam seas at Tp 7 s, each load at the two H_s where the screening predicts
P = 0.35 and 0.75 of a slip onset within a 30-min access: 24 seeded 30-min trials each (a campaign, which
stores the screening's P of the same scenario — its steady loads in the landed equilibrium, the drag
linearised, the gusts' slow swing — beside its cases). The check of issue 27: the screening's P inside the
Clopper–Pearson 95 % interval of the trials'.

Loads: a 1 m/s current on the beam from starboard (the issue's; ~36 kN on ctv27's demihulls) and a 10 kn
(5.1 m/s) beam wind with NPD gusts. At 20 kn the gusts swing the landed vessel about its bow at ~53 s
(±0.3 m of sway; the time domain and the screening agree on it within 3 %), unloading one tube, then the
other (the screening counts the tubes as two events: boatland.freqdomain.statistics.distinct_events); there
the screening lies inside the time domain's interval at three of the six points and above it, conservative,
at the other three (2026-12-03) — reported here as a record, not judged.
"""

from __future__ import annotations

from boatland.validation.campaigns import (FD_TD_ACCESS, FD_TD_TP, campaign_printer, fd_vs_td_campaign, hs_at_probability,
                                           run_study)
from boatland.validation.case import Case, Check, Context, Outcome

__all__ = ["CASES", "LOADS", "LOADS_RECORD", "loads_scenario_path"]

#: The loads the case judges: (label, keys set on every case).
LOADS = {
    "current 1 m/s beam": {"current.speed": 1.0, "current.relative_direction_deg": 90.0},
    "wind 10 kn beam": {"wind.speed": 5.1, "wind.relative_direction_deg": 90.0},
}
#: Reported, not judged (the module docstring).
LOADS_RECORD = {"wind 20 kn beam": {"wind.speed": 10.3, "wind.relative_direction_deg": 90.0}}
HEADINGS = (180.0, 135.0, 90.0)
TARGETS = (0.35, 0.75)


def loads_scenario_path():
    from boatland.resources import shipped_scenarios

    return shipped_scenarios() / "ctv_landing.toml"


def compare(folder, label: str, changes: dict, heading: float, *, seeds: int = 24, workers: int = 2, progress=None,
            targets=TARGETS) -> list[dict]:
    """One load and heading: the H_s at the screening's ``targets``, the campaign, and per H_s the time domain's
    count and interval beside the screening's P (dicts)."""
    import warnings

    from boatland.checks.files import load, resolve_database

    path = loads_scenario_path()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(path).replace(changes)
        db = resolve_database(sc)
    hs = sorted({hs_at_probability(sc, db, p, access=FD_TD_ACCESS, Tp=FD_TD_TP, heading=heading) for p in targets})
    tag = label.replace(" ", "_").replace("/", "")
    f = fd_vs_td_campaign(folder, heading, hs, seeds=seeds, scenario=path, set_=changes, name=tag)
    _, _, stats = run_study(f, folder / f"{tag}_{heading:g}.h5", workers=workers, progress=progress)
    out = []
    for h, row in zip(hs, stats):
        out.append({"load": label, "heading": heading, "Hs": h, "count": int(row["first slip: count"]), "seeds": seeds,
                    "trials": int(row["trials"]), "failed": int(row["failed"]), "p": float(row["first slip: P"]),
                    "lo": float(row["first slip: P lo"]), "hi": float(row["first slip: P hi"]),
                    "fd": float(row["screening: P(slip)"])})
    return out


def run_loads(ctx: Context) -> Outcome:
    """Case loads-vs-monte-carlo."""
    seeds = 12 if ctx.quick else 24
    headings = (180.0,) if ctx.quick else HEADINGS
    checks, rows = [], []
    for label, changes in {**LOADS, **({} if ctx.quick else LOADS_RECORD)}.items():
        judged = label in LOADS
        for d in headings:
            for r in compare(ctx.work, label, changes, d, seeds=seeds, workers=ctx.workers,
                             progress=campaign_printer(ctx, f"{label}, {d:g}°"),
                             targets=(0.5,) if ctx.quick else TARGETS):
                rows.append(r)
                inside = r["failed"] == 0 and r["trials"] == seeds and r["lo"] <= r["fd"] <= r["hi"]
                checks.append(Check(f"{label}, {d:g}°, H_s {r['Hs']:g} m: screening P(slip in 30 min)",
                                    f"TD {r['count']}/{seeds} [{r['lo']:.2f}, {r['hi']:.2f}], screening {r['fd']:.3f}",
                                    "inside the 95 % interval" if judged else "record", inside if judged else None,
                                    r["fd"], None))
    inside = sum(bool(c.passed) for c in checks if c.passed is not None)
    judged = sum(c.passed is not None for c in checks)
    name = ctx.save(_figure(rows, seeds), "loads_vs_monte_carlo.png")
    return Outcome(checks, f"{inside}/{judged} inside", name,
                   ["The wave heights are where the screening predicts P = 0.35 and 0.75 per 30 min with the load, "
                    "rounded to 5 mm. With many points at 95 % each, one outside in a run is chance; several on one "
                    "side is a bias (the module docstring says which are known)."],
                   settings=f"ctv27 (scenarios/ctv_landing.toml), {seeds} seeds × 30 min per point"
                            + (" (--quick: head seas, one H_s, 12 seeds)" if ctx.quick else ""))


def _figure(rows: list[dict], seeds: int):
    """Per load and heading: the time domain's P with its 95 % interval (bars) and the screening's (crosses)."""
    from boatland.plotstyle import pyplot

    plt = pyplot()
    labels = list(dict.fromkeys(r["load"] for r in rows))
    fig, axes = plt.subplots(1, len(labels), figsize=(4.2 * len(labels), 3.8), constrained_layout=True, squeeze=False)
    for ax, label in zip(axes[0], labels):
        for i, d in enumerate(HEADINGS):
            sel = [r for r in rows if r["load"] == label and r["heading"] == d]
            if not sel:
                continue
            h = [r["Hs"] for r in sel]
            ax.errorbar(h, [r["p"] for r in sel], yerr=[[r["p"] - r["lo"] for r in sel], [r["hi"] - r["p"] for r in sel]],
                        fmt="o", color=f"C{i}", capsize=3, label=f"{d:g}°: time domain")
            ax.plot(h, [r["fd"] for r in sel], "x", color=f"C{i}", ms=8, mew=2, label=f"{d:g}°: screening")
        ax.set(xlabel="H_s [m]", ylabel="P(first slip within 30 min)", ylim=(-0.02, 1.02), title=label)
        ax.title.set_fontsize(9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(f"ctv27, Tp {FD_TD_TP:g} s: screening vs Monte Carlo ({seeds} seeds per point)", fontsize=10)
    return fig


CASES = [
    Case("loads-vs-monte-carlo", "Screening vs Monte Carlo with a current and a wind",
         "The screening of Grøtting, H. (2015), NTNU MSc thesis, §3.2.1, §3.4 (after Wu 2014), extended with steady "
         "loads in its landed equilibrium; the time domain's Monte Carlo as the reference (issue 27).",
         "For head, bow-quartering and beam seas at T_p 7 s on the default landing (ctv27), a 1 m/s beam current and a "
         "10 kn gusty beam wind, each at the two H_s where the screening predicts P = 0.35 and 0.75 of a slip within "
         "a 30-min access: 24 seeded 30-min trials per point.",
         "whether the screening's P lies inside the Clopper–Pearson 95 % interval of the trials' P",
         "inside the 95 % interval", run_loads, scenario_files=("ctv_landing.toml",),
         quick="head seas, one H_s (P = 0.5), 12 seeds (full: 3 headings × 2 H_s × 24 seeds per load, and the 20 kn "
               "wind as a record)",
         cite="Grøtting (2015) §3.4; issue 27"),
]
