"""``boatland rao``: RAOs of the free and the fender-hinged vessel, hinge-force transfer functions."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from boatland.cli.common import freq_directions, freq_load, freq_sea, scenario_argument
from boatland.cli.guard import finite, positive
from boatland.outputs import Output
from boatland.reproducible import pinned
from boatland.errors import BoatlandInputError

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    rao = sub.add_parser(
        "rao", help="RAOs of the free and the fender-hinged vessel, hinge-force transfer functions",
        description="Free RAO (San Nicolás Méndez 2024, Real-Time Simulation of Service Vessels for Offshore Wind Turbine, DTU, eq. 3.31) and the RAO of the vessel hinged at its fender point(s) "
                    "(Grøtting 2015, Small Water Plane Area Solutions for Access of Offshore Wind Turbines, NTNU, eq. 3.1–3.12, preloaded by the scenario's thrust), the hinge force on the vessel "
                    "(normal, vertical, horizontal, all contacts) and the motion of the free vessel's fender point, "
                    "per unit wave amplitude, in the scenario's relative wave direction.")
    scenario_argument(rao)
    rao.add_argument("--direction", type=finite, metavar="DEG",
                     help="relative wave direction [deg] (180 = head seas; default the scenario's sea, else 180)")
    rao.add_argument("--periods", type=positive("s", 1e4), nargs="+", metavar="T",
                     default=[3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0, 12.0, 15.0, 20.0],
                     help="wave periods of the table [s]")
    rao.add_argument("-o", "--output", type=Path, metavar="PNG", help="write a figure")
    rao.add_argument("--json", action="store_true", help="print the table as JSON")
    rao.add_argument("--compare-open-sea", type=Path, metavar="PNG",
                     help="write a figure of the free heave and pitch RAOs in the open sea and beside the "
                          "monopile (its scattered wave, MacCamy–Fuchs) for headings 0, 45, 90, 135, 180°")
    rao.set_defaults(func=cmd)


@pinned
def cmd(args) -> int:
    import numpy as np

    from boatland.freqdomain import LandingSetup, free_rao, point_map
    from boatland.freqdomain.screening import landed_response

    scenario, db = freq_load(args.scenario, [Output("-o", args.output, "figure"),
                                             Output("--compare-open-sea", args.compare_open_sea, "figure")], args)
    setup = LandingSetup.from_scenario(scenario, db)
    beta = args.direction
    key = "--direction"
    if beta is None:
        beta = freq_sea(scenario)[1]
        key = f"{scenario.source}: sea: relative direction"
        if beta is None:
            beta, key = 180.0, "relative direction (default 180°: no --direction and no sea)"
    freq_directions(scenario, db, beta, key)
    T = np.asarray(args.periods, dtype=float)
    if np.any(T <= 0):
        raise BoatlandInputError(f"--periods: all must be > 0 s, got {args.periods}")
    if np.any(2 * np.pi / T > db.omega[-1]):
        raise BoatlandInputError(f"--periods: {T.min():g} s is shorter than the database {db.name!r} covers "
                                 f"(ω ≤ {db.omega[-1]:g} rad/s: T ≥ {2 * np.pi / db.omega[-1]:.3g} s)")

    def solve(w):
        x = free_rao(db, w, beta, additional_damping=setup.additional_damping)[:, 0]
        h = landed_response(db, setup, w, [beta])            # the time domain's contacts, pile, preload
        bow = x @ point_map(setup.points[0]).T
        F = h.contact_components()[:, 0]                     # (Nw, Np, 3): each contact's own force
        worst = np.take_along_axis(F, np.abs(F).argmax(axis=1)[:, None, :], axis=1)[:, 0]
        return x, bow, h.x[:, 0], worst

    w = 2 * np.pi / T
    x, bow, xh, F = solve(w)
    rows = [{"T": float(t), "omega": float(o), "free_heave": abs(x[i, 2]), "free_pitch_deg": np.degrees(abs(x[i, 4])),
             "free_roll_deg": np.degrees(abs(x[i, 3])), "bow_vertical": abs(bow[i, 2]),
             "hinged_pitch_deg": np.degrees(abs(xh[i, 4])), "hinged_roll_deg": np.degrees(abs(xh[i, 3])),
             "normal_kN": abs(F[i, 0]) / 1e3, "vertical_kN": abs(F[i, 1]) / 1e3, "horizontal_kN": abs(F[i, 2]) / 1e3}
            for i, (t, o) in enumerate(zip(T, w))]
    if args.json:
        print(json.dumps({"scenario": scenario.name, "database": db.name, "beta_deg": beta, "rows": rows},
                         indent=2, default=float))
    else:
        print(f"{scenario.name}: {db.name}, relative wave direction {beta:g}° (180 = head seas), per unit wave "
              f"amplitude; free, and landed (hinged) on {len(setup.points)} fender contact(s) as the time domain "
              f"has them, {setup.thrust / 1e3:g} kN thrust; forces: the most loaded contact")
        print(f"{'T [s]':>6} {'heave':>7} {'pitch':>7} {'roll':>7} {'bow z':>7} | {'pitch':>7} {'roll':>7} | "
              f"{'F_n':>7} {'F_v':>7} {'F_h':>7}")
        print(f"{'':>6} {'free m/m':>7} {'°/m':>7} {'°/m':>7} {'m/m':>7} | {'hinged':>7} {'°/m':>7} | "
              f"{'kN/m':>7} {'kN/m':>7} {'kN/m':>7}")
        for r in rows:
            print(f"{r['T']:6.2f} {r['free_heave']:7.3f} {r['free_pitch_deg']:7.2f} {r['free_roll_deg']:7.2f} "
                  f"{r['bow_vertical']:7.3f} | {r['hinged_pitch_deg']:7.2f} {r['hinged_roll_deg']:7.2f} | "
                  f"{r['normal_kN']:7.1f} {r['vertical_kN']:7.1f} {r['horizontal_kN']:7.1f}")
    if args.output:
        from boatland.freqdomain.figures import plot_raos
        from boatland.scenario.inputs import heading_name

        wf = np.linspace(max(2 * np.pi / 25.0, db.omega[0]), db.omega[-1], 300)  # T ≤ 25 s
        plot_raos(wf, *solve(wf), args.output,
                  title=f"{scenario.name}: {db.name}, {heading_name(beta)} (β = {beta:g}°), landed with a push of "
                        f"{setup.thrust / 1e3:g} kN; per unit wave amplitude")
        if not args.json:
            print(f"wrote {args.output}")
    if args.compare_open_sea:
        _compare_open_sea(scenario, db, setup, args)
    return 0


def _compare_open_sea(scenario, db, setup, args) -> None:
    import numpy as np

    from boatland.freqdomain.figures import plot_pile_comparison
    from boatland.freqdomain.pile import COMPARE_HEADINGS, rao_with_pile

    if scenario.landing is None:
        raise BoatlandInputError(f"{scenario.source}: landing: --compare-open-sea needs the monopile of a [landing]")
    x0, y0, psi = scenario.start_pose()
    px, py = scenario.landing.monopile_position
    wf = np.linspace(max(2 * np.pi / 25.0, db.omega[0]), db.omega[-1], 200)
    if not args.json:                   # the pile's scattered wave over the hull mesh: ~10 s, one call
        print("--compare-open-sea: the pile's scattered wave on the hull, every frequency and heading …",
              file=sys.stderr, flush=True)
    open_sea, near = rao_with_pile(db, wf, (x0 - px, y0 - py), float(np.degrees(psi)),
                                   scenario.landing.monopile_diameter / 2,
                                   additional_damping=setup.additional_damping)
    plot_pile_comparison(wf, open_sea, near, COMPARE_HEADINGS, args.compare_open_sea,
                         title=f"{scenario.name}: {db.name} beside a {scenario.landing.monopile_diameter:g} m "
                               "monopile vs the open sea (free vessel, per unit wave amplitude)")
    if not args.json:
        print(f"wrote {args.compare_open_sea}")
