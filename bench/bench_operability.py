"""Operability over a year of hourly hindcast (issue 30): 8,760 sea states (the shipped example's model at 1-h
steps, wind sea + swell) × 3 landings × 2 vessels, end to end as a planner runs it, and where the time goes.

Run: ``python bench/bench_operability.py [--repeat 3]``. Prints Markdown.

1. **End to end**: ``boatland operability ctv_landing ctv24_landing HOURLY.csv --landing 45 --landing 165
   --landing 285 --window 4`` in a subprocess (interpreter start, imports, both scenarios' checks and
   databases, the weather read, both limits tables, windows, the tables printed) — wall time, best and median
   of ``--repeat``; the same with ``--one-spectrum``; with the model's M2 tidal current (1.2 m/s, flood from
   45°, ebb from 225°) — each sea state judged in its own current; with the model's own wind (the one its wind
   sea grows from), and with both (ctv_landing alone: ctv24's database has no topsides for the wind's areas).
2. **In this process** (warm): reading the CSV, the screening's transfer functions for every direction the
   landings need (one per vessel), the limits of every sea state at every landing, the windows.

3. **The pile's scattered wave on the hull** for all the database's directions (the bulk of the transfer
   functions): the field at every panel, frequency and direction, then summed over the panels (as before
   issue 30: :func:`boatland.waves.diffraction.cylinder_field` and an einsum), against the sum made as the
   field is (:func:`boatland.waves.diffraction.scattered_load`, today's
   :func:`boatland.sea.pile.pile_scattered_excitation`), best of ``--repeat``, and their largest difference.
"""

from __future__ import annotations

import argparse
import datetime
import importlib.util
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))

from _timing import cpu_name  # noqa: E402

LANDINGS = ("45", "165", "285")


def hourly_year(folder: Path, tide: bool = False, wind: bool = False) -> Path:
    spec = importlib.util.spec_from_file_location("make_example_hindcast", REPO / "docs" / "make_example_hindcast.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    path = folder / f"hourly_2021{'_tide' if tide else ''}{'_wind' if wind else ''}.csv"
    path.write_text(mod.make(1, tide=tide, wind=wind), encoding="utf-8")
    return path


def end_to_end(code: Path, weather: Path, *extra: str, scenarios=("ctv_landing", "ctv24_landing")) -> float:
    args = [sys.executable, "-m", "boatland", "operability", *scenarios, str(weather),
            *sum((["--landing", b] for b in LANDINGS), []), "--window", "4", *extra]
    env = {**os.environ, "PYTHONPATH": str(code)}
    t = time.perf_counter()
    r = subprocess.run(args, capture_output=True, text=True, env=env, cwd=code, timeout=1200)
    wall = time.perf_counter() - t
    if r.returncode != 0:
        raise SystemExit(r.stderr)
    return wall


def in_process(weather: Path) -> list[tuple[str, float]]:
    import warnings

    import numpy as np

    from boatland.checks.files import load_checked
    from boatland.freqdomain import LandingSetup, slip_transfer
    from boatland.site import operability, read_weather, sea_limits
    from boatland.site.limits import relative_directions

    rows = []
    t = time.perf_counter()
    w = read_weather(weather)
    rows.append((f"read the CSV ({w.n:,} rows)", time.perf_counter() - t))
    for name in ("ctv_landing", "ctv24_landing"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sc, db, _ = load_checked(REPO / "scenarios" / f"{name}.toml")
        s = LandingSetup.from_scenario(sc, db)
        landings = [float(x) for x in LANDINGS]
        betas = np.unique(np.concatenate([relative_directions(d, landings).ravel()
                                          for d in [w.from_deg] + [p[2] for p in w.parts.values()]]))
        slip_transfer(db, s, beta_deg=betas)                         # warm (numba) — then each step timed on a
        t = time.perf_counter()                                      # fresh copy (no pile table made for it yet)
        slip_transfer(db.replace(), s, beta_deg=betas)
        rows.append((f"{name}: transfer functions at {len(betas)} directions (the pile's wave included)",
                     time.perf_counter() - t))
        t = time.perf_counter()
        sea_limits(db.replace(), s, w, [float(x) for x in LANDINGS])
        rows.append((f"{name}: limits of {w.n:,} × {len(LANDINGS)} sea states (transfer functions included)",
                     time.perf_counter() - t))
        t = time.perf_counter()
        operability(db.replace(), s, w, [float(x) for x in LANDINGS], window_hours=4.0)
        rows.append((f"{name}: operability (limits, month by month, 4-h windows)", time.perf_counter() - t))
    return rows


def pile_table(repeat: int) -> list[tuple[str, str]]:
    import warnings

    import numpy as np

    from boatland.checks.files import load_checked
    from boatland.sea.pile import hull_panels_global, pile_scattered_excitation
    from boatland.vessel.wigley import panel_normals_areas
    from boatland.waves.diffraction import cylinder_field
    from boatland.waves.dispersion import wavenumber

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc, db, _ = load_checked(REPO / "scenarios" / "ctv_landing.toml")
    pos, heading, radius, depth = (-20.0, 0.0), 0.0, 3.25, 30.0

    n, area, c = panel_normals_areas(db.mesh.vertices, db.mesh.faces)      # the wetted panels, as the pile's
    keep = (area > 0) & (c[:, 2] < 0)                                      # module takes them
    r = c[keep] - db.ref_point[None, :]
    N = np.concatenate([n[keep], np.cross(r, n[keep])], axis=1) * area[keep][:, None]
    xg = hull_panels_global(db, pos, heading)

    def old():
        theta = np.radians(db.wave_dir_deg + heading)
        field = cylinder_field(xg[:, 0], xg[:, 1], xg[:, 2], db.omega, theta, radius, depth, g=db.g, rho=db.rho,
                               part="scattered")
        F = -np.einsum("pfd,pj->jdf", field.p, N, optimize=True)
        k = wavenumber(db.omega, depth, db.g)
        return F * np.exp(1j * np.outer(pos[0] * np.cos(theta) + pos[1] * np.sin(theta), k))[None]

    def new():
        return pile_scattered_excitation(db, pos, heading, radius, depth)

    times = {}
    out = {}
    for f in (old, new):
        f()
    for _ in range(repeat):
        for f in (old, new):
            t = time.perf_counter()
            out[f.__name__] = f()
            times[f.__name__] = min(times.get(f.__name__, 1e9), time.perf_counter() - t)
    diff = float(np.max(np.abs(out["old"] - out["new"])) / np.max(np.abs(out["old"])))
    P = N.shape[0]
    return [(f"field ({P} panels × {db.omega.size} ω × {db.n_dir} directions), then summed", f"{times['old']:.2f}"),
            ("summed as it is made (scattered_load)", f"{times['new']:.2f}"),
            ("largest difference / largest value", f"{diff:.1e}")]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    print(f"# {cpu_name()}, {os.cpu_count()} CPU, Python {platform.python_version()}, "
          f"{datetime.date.today().isoformat()}, load average {'/'.join(f'{x:.1f}' for x in os.getloadavg())}\n")
    with tempfile.TemporaryDirectory() as tmp:
        weather = hourly_year(Path(tmp))
        end_to_end(REPO, weather)                                   # numba caches warm
        print("| spectra | wall [s]: best | median | runs |")
        print("|---|---|---|---|")
        for extra, what in (((), "two (wind sea + swell)"), (("--one-spectrum",), "one")):
            walls = [end_to_end(REPO, weather, *extra) for _ in range(args.repeat)]
            print(f"| {what} | {min(walls):.2f} | {statistics.median(walls):.2f} | {len(walls)} |")
        tidal = hourly_year(Path(tmp), tide=True)
        walls = [end_to_end(REPO, tidal) for _ in range(max(1, args.repeat // 2))]
        print(f"| two, each sea state in its M2 tidal current (1.2 m/s) | {min(walls):.2f} | "
              f"{statistics.median(walls):.2f} | {len(walls)} |")
        # ctv24's database has no topsides to measure the wind's areas on: the windy rows are ctv27's alone
        for tide, what in ((False, "its own wind"), (True, "its own wind and M2 tidal current")):
            windy = hourly_year(Path(tmp), tide=tide, wind=True)
            walls = [end_to_end(REPO, windy, scenarios=("ctv_landing",)) for _ in range(max(1, args.repeat // 2))]
            print(f"| two, each sea state in {what} (ctv_landing alone) | {min(walls):.2f} | "
                  f"{statistics.median(walls):.2f} | {len(walls)} |")
        print()
        print("| step (this process, warm) | s |")
        print("|---|---|")
        for what, s in in_process(weather):
            print(f"| {what} | {s:.2f} |")
        print()
        print("| pile's scattered wave, ctv27, all directions | s (best) |")
        print("|---|---|")
        for what, s in pile_table(args.repeat):
            print(f"| {what} | {s} |")


if __name__ == "__main__":
    main()
