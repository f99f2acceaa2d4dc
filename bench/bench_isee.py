"""ISEE campaigns (issue 17): rare slips in minutes, the limiting-Hs table, the slip directions.

Usage::

    python bench/bench_isee.py rare        # p ≈ 1e-4 per 30-min access to ±20 % (95 %), 2 workers, vs brute force
    python bench/bench_isee.py rare6       # p ≈ 1e-6 per 30-min access to ±10 % (95 %) (issue 28: ≤ 60 s)
                                           # rare, rare6: [--before CHECKOUT] the same campaign on other code beside
    python bench/bench_isee.py table       # limiting Hs at 1.19e-3 per 30-min access, 8 Tp × 3 directions
    python bench/bench_isee.py scatter     # … the whole scatter: 16 Tp × 12 directions, each to ±3 % (issue 28: ≤ 10 min)
    python bench/bench_isee.py directions  # P(slip) of the linear model: friction circle vs square, M = 4 … 32
    python bench/bench_isee.py screening   # linear ISEE vs the screening's Rayleigh / Rice / Vanmarcke

Each prints a Markdown table; bench/README.md ("ISEE") quotes them with the machine and the date. ``rare``
and ``table`` run the real command (``boatland campaign``, a subprocess: start-up, checks and the linear
models included in the wall time) on all cores of this machine.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import h5py
import numpy as np
from boatland.landing.setup import Setup

REPO = Path(__file__).resolve().parents[1]
BASE = REPO / "scenarios" / "ctv24_landing.toml"   # the figures' vessel (ctv24, 80 kN)
sys.path.insert(0, str(REPO))


def campaign(tmp: Path, name: str, body: str) -> Path:
    path = tmp / f"{name}.toml"
    path.write_text(f'name = "{name}"\nscenario = "{BASE}"\nmethod = "isee"\nmaster_seed = 2026\n{body}')
    return path


def run_cli(camp: Path, store: Path, *extra, code: Path = REPO) -> float:
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "boatland", "campaign", str(camp), "-o", str(store), *extra],
                       capture_output=True, text=True, env={**os.environ, "PYTHONPATH": str(code)},
                       cwd=store.parent)   # not a checkout: `python -m` puts the working folder first on the path
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        raise SystemExit(r.stderr)
    print(r.stdout)
    return wall


def brute_force_time(camp: Path, hs: float, n: int = 40) -> float:
    """Wall seconds per plain time-domain trial on all cores (the brute force's unit cost)."""
    from boatland.campaign.isee import SampleSpec, execute_sample
    from boatland.campaign.executor import Executor
    from boatland.campaign.plan import load_campaign
    from boatland.checks.files import load, resolve_database

    loaders = (load, resolve_database)
    camp = load_campaign(camp, load_scenario=load)
    with Executor("local", os.cpu_count()) as pool:
        list(pool.map(execute_sample, [(camp, SampleSpec(k, 0, 0, hs, k), loaders, True) for k in range(4)]))
        t0 = time.perf_counter()
        rows = list(pool.map(execute_sample, [(camp, SampleSpec(k, 0, 0, hs, k), loaders, True)
                                              for k in range(4, 4 + n)]))
        wall = (time.perf_counter() - t0) / n
    assert all(r["status"] == 0 for r in rows)
    return wall


def rare(hs: float = 0.15, cov: float = 0.102, before: Path | None = None) -> None:
    """``before``: another checkout of the code, whose run of the same campaign is timed right after this one's
    (its store must hold the same estimate: the same samples, bit for bit)."""
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        camp = campaign(tmp, "rare", f"""access = 1800.0
[axes]
"sea.Hs" = [{hs}]
[isee]
target_cov = {cov}
batch = 20
min_samples = 100
max_samples = 4000
""")
        wall = run_cli(camp, tmp / "rare.h5", "--save-worst", "1")
        with h5py.File(tmp / "rare.h5", "r") as f:
            r = f["stats"][0]
            cpu = float(f["trials"]["wall_time"].sum())
        old = None
        if before is not None:
            wall_b = run_cli(camp, tmp / "before.h5", "--save-worst", "1", code=before)
            with h5py.File(tmp / "before.h5", "r") as f:
                rb = f["stats"][0]
                old = (wall_b, float(f["trials"]["wall_time"].sum()), rb["first slip: P"] == r["first slip: P"])
        per = brute_force_time(camp, hs)
    p, lo, hi, cov, n = r["first slip: P"], r["first slip: P lo"], r["first slip: P hi"], r["first slip: CoV"], r["samples"]
    n_bf = math.ceil(norm_z() ** 2 * (1 - p) / ((norm_z() * cov) ** 2 * p))
    print("| | Hs [m] | samples / trials | P(first slip) per 30 min | 95 % interval | wall [s] |")
    print("|---|---|---|---|---|---|")
    print(f"| ISEE (`boatland campaign`, {os.cpu_count()} workers) | {hs} | {n} | {p:.3g} | [{lo:.3g}, {hi:.3g}] "
          f"(±{100 * 1.96 * cov:.1f} %) | {wall:.0f} (samples' CPU {cpu:.0f} s) |")
    if old is not None:
        print(f"| the same, code of {before.name} | {hs} | {n} | {'the same bits' if old[2] else 'DIFFERENT'} | | "
              f"{old[0]:.0f} (samples' CPU {old[1]:.0f} s) |")
    print(f"| brute force, same interval | {hs} | {n_bf:,} | — | ±{100 * norm_z() * cov:.0f} % | {n_bf * per:,.0f} "
          f"(≈ {n_bf * per / 3600:,.0f} h; {per:.3f} s per trial measured) |")
    print(f"\nlinear: {r['linear first slip: P']:.3g} (CoV {r['linear first slip: CoV']:.3f}); largest elementary "
          f"{r['largest elementary P']:.3g}; Rice bound {r['rice bound']:.3g}; screening Rayleigh "
          f"{r['screening rayleigh']:.3g}, Rice {r['screening rice']:.3g}, Vanmarcke {r['screening vanmarcke']:.3g}; "
          f"TD slips outside the linear slip: {r['TD slip outside linear slip']}")


def norm_z() -> float:
    from scipy.stats import norm

    return float(norm.ppf(0.975))


TPS = [4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 12.0]
DIRS = [180.0, 135.0, 90.0]


def table() -> None:
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        camp = campaign(tmp, "table", f"""access = 1800.0
[axes]
"sea.Tp" = {TPS}
"sea.relative_direction_deg" = {DIRS}
[isee]
accept = "best"
target_cov = 0.25
batch = 20
min_samples = 40
max_samples = 400
levels = 3
""")
        wall = run_cli(camp, tmp / "table.h5", "--report", str(tmp / "rep"))
        with h5py.File(tmp / "table.h5", "r") as f:
            lim, runs = f["isee_limits"][()], f["stats"][()]
            cpu = float(f["trials"]["wall_time"].sum())
        out = REPO / "docs" / "isee_limiting_hs_polar.png"
        out.write_bytes((tmp / "rep" / "limiting_hs_polar.png").read_bytes())
    print(f"wall {wall:.0f} s ({os.cpu_count()} workers), samples {int(runs['samples'].sum())}, runs {len(runs)}, "
          f"samples' CPU {cpu:.0f} s; figure {out.relative_to(REPO)}\n")
    print("| Tp [s] | β [deg] | limiting Hs [m] (95 %) | linear [m] | screening Rayleigh / Rice / Vanmarcke [m] | levels | samples |")
    print("|---|---|---|---|---|---|---|")
    for L in lim:
        print(f"| {L['axis: sea.Tp']:g} | {L['axis: sea.relative_direction_deg']:g} | {L['limiting Hs']:.3f} "
              f"[{L['limiting Hs lo']:.3f}, {L['limiting Hs hi']:.3f}] | {L['linear limiting Hs']:.3f} | "
              f"{L['screening rayleigh Hs']:.3f} / {L['screening rice Hs']:.3f} / {L['screening vanmarcke Hs']:.3f} | "
              f"{L['levels']} | {L['samples']} |")


def scatter() -> None:
    """The shipped ``scenarios/campaigns/isee_scatter.toml`` (16 Tp × 0–180°, mirrored to 0–330°) through the CLI."""
    camp = REPO / "boatland" / "scenarios" / "campaigns" / "isee_scatter.toml"
    with tempfile.TemporaryDirectory() as d:
        store = Path(d) / "scatter.h5"
        wall = run_cli(camp, store)
        with h5py.File(store, "r") as f:
            lim, runs = f["isee_limits"][()], f["stats"][()]
            cpu = float(f["trials"]["wall_time"].sum())
    h = lim["limiting Hs"]
    width = np.maximum(h / lim["limiting Hs lo"], lim["limiting Hs hi"] / h) - 1
    print(f"wall {wall:.0f} s ({os.cpu_count()} workers), {len(lim)} cases, samples {int(runs['samples'].sum())} "
          f"(per case {int(lim['samples'].min())}–{int(lim['samples'].max())}), samples' CPU {cpu:.0f} s; every "
          f"95 % interval within ±{100 * float(np.max(width)):.1f} %\n")
    tps = sorted(set(lim["axis: sea.Tp"]))
    betas = sorted(set(lim["axis: sea.relative_direction_deg"]))
    shown = betas + [360.0 - b for b in reversed(betas) if 0.0 < b < 180.0]     # port/starboard mirror
    print("| Tp [s] | " + " | ".join(f"{b:g}°" for b in shown) + " |")
    print("|---|" + "---|" * len(shown))
    for tp in tps:
        row = []
        for b in shown:
            src = b if b <= 180.0 else 360.0 - b
            L = lim[(lim["axis: sea.Tp"] == tp) & (lim["axis: sea.relative_direction_deg"] == src)][0]
            row.append(f"{L['limiting Hs']:.3f}")
        print(f"| {tp:g} | " + " | ".join(row) + " |")


def _linear(hs, rel, access, directions, kappa=0.3, n=400, tp=7.0, gamma=3.3):
    """Linear-model ISEE estimates (no time domain) of the default landing."""
    from boatland.freqdomain.isee import draw, estimate
    from boatland.freqdomain.margins import landed_margins
    from boatland.freqdomain.landing import LandingSetup
    from boatland.freqdomain.screening import sea_response
    from boatland.sea.gaussian import GaussianSea
    from boatland.checks.files import load, resolve_database
    from boatland.trial.simulate import exposure_start

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(BASE).replace({"sea.Hs": hs, "sea.relative_direction_deg": rel, "sea.Tp": tp, "sea.gamma": gamma})
        sc = sc.replace({"simulation.duration": exposure_start(sc) + 30.0 + access})
        db = resolve_database(sc)
        setup = Setup.of(sc, db)
        dt, nst = setup.dt, setup.n_steps
        g = GaussianSea(sea=setup.waves, dt=dt, n_steps=nst)
        setup = LandingSetup.from_scenario(sc, db)
        x0, y0, _ = sc.start_pose()
        lm = landed_margins(db, setup, g, x0=x0, y0=y0, first_step=int(math.ceil((exposure_start(sc) + 30) / dt - 1e-9)),
                            kappa=kappa, directions=directions)
        t0 = time.perf_counter()
        v = {"circle": [], "square": [], "domain": []}
        for s in range(n):
            u, e, lpb = draw(lm, np.random.default_rng(np.random.SeedSequence(11, spawn_key=(s,))))
            ind = lm.indicators(u, e)
            v["circle"].append(ind.first_incident / ind.n_exceeded)
            v["square"].append((ind.square or ind.roll or ind.contact_loss) / ind.n_exceeded)
            v["domain"].append(1.0 / ind.n_exceeded)
        per = (time.perf_counter() - t0) / n
        fd = {st: sea_response(db, setup, sc.sea.waves.parts, statistics=st, access_duration=access).p_access
              for st in ("rayleigh", "rice", "vanmarcke")}
        m = sea_response(db, setup, sc.sea.waves.parts, access_duration=access).m
    est = {k: estimate(x, lpb) for k, x in v.items()}
    i = int(np.argmin(sea_response(db, setup, sc.sea.waves.parts, access_duration=access).capacity[:-1]
                      / np.sqrt(m[:-1, 0])))
    delta = math.sqrt(max(0.0, 1 - m[i, 1] ** 2 / (m[i, 0] * m[i, 2])))
    return est, lm, per, fd, delta


def directions() -> None:
    print("| β [deg] | Hs [m] | M | P circle (CoV) | P square (CoV) | P(D) | circle / D | CoV per sample (circle) | "
          "linear ms/sample |")
    print("|---|---|---|---|---|---|---|---|---|")
    for rel, hs in ((180.0, 0.16), (135.0, 0.085), (90.0, 0.07)):
        for M in (4, 8, 16, 32):
            est, lm, per, _, _ = _linear(hs, rel, 1800.0, M)
            c, q, d = est["circle"], est["square"], est["domain"]
            print(f"| {rel:g} | {hs} | {M} | {c.p:.3g} ({c.cov:.3f}) | {q.p:.3g} ({q.cov:.3f}) | {d.p:.3g} | "
                  f"{c.p / d.p:.2f} | {c.cov * math.sqrt(c.n):.2f} | {1e3 * per:.0f} |")


def screening() -> None:
    print("| sea | β [deg] | Hs [m] | bandwidth δ | ISEE linear (95 %) | screening Rayleigh | Rice | Vanmarcke |")
    print("|---|---|---|---|---|---|---|---|")
    for label, tp, gamma in (("JONSWAP γ 7 (narrow)", 7.0, 7.0), ("JONSWAP γ 3.3", 7.0, 3.3),
                             ("Pierson–Moskowitz (broad)", 7.0, 1.0)):
        for rel, hs in ((180.0, 0.16), (90.0, 0.07)):
            est, lm, per, fd, delta = _linear(hs, rel, 1800.0, 16, tp=tp, gamma=gamma)
            c = est["square"]
            print(f"| {label} | {rel:g} | {hs} | {delta:.2f} | {c.p:.3g} [{c.lo:.3g}, {c.hi:.3g}] | "
                  f"{fd['rayleigh']:.3g} | {fd['rice']:.3g} | {fd['vanmarcke']:.3g} |")


if __name__ == "__main__":
    what = sys.argv[1] if len(sys.argv) > 1 else "rare"
    before = Path(sys.argv[sys.argv.index("--before") + 1]).resolve() if "--before" in sys.argv else None
    {"rare": lambda: rare(before=before), "rare6": lambda: rare(0.129, 0.051, before), "table": table,
     "scatter": scatter, "directions": directions, "screening": screening}[what]()
