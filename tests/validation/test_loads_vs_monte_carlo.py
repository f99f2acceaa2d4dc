"""The frequency-domain screening against the time-domain Monte Carlo with a current and a wind (issue 27):
P(first slip within a 30-min access) of the default landing (ctv27) at Tp 7 s in head, bow-quartering and beam
seas, with a 1 m/s current on the beam from starboard and with a 10 kn gusty beam wind
(boatland.validation.loads; `boatland validate --case loads-vs-monte-carlo`).

At the two H_s per heading where the screening predicts P = 0.35 and 0.75, 24 seeded 30-min trials each
(master seed 2026): the screening's P inside the trials' Clopper–Pearson 95 % interval.

Measured (2026-12-03, the rebuilt ctv27 and the friction circle in the screening's margins) — time domain
[95 %] vs screening:

=====================  =======  ======  ===================  =========
load                   heading  H_s     time domain          screening
=====================  =======  ======  ===================  =========
current 1 m/s beam     180°     0.41    7/24 [0.13, 0.51]    0.333
current 1 m/s beam     180°     0.455   19/24 [0.58, 0.93]   0.753
current 1 m/s beam     135°     0.385   12/24 [0.29, 0.71]   0.355
current 1 m/s beam     135°     0.42    18/24 [0.53, 0.90]   0.744
current 1 m/s beam     90°      0.21    4/24 [0.05, 0.37]    0.338
current 1 m/s beam     90°      0.23    15/24 [0.41, 0.81]   0.747
wind 10 kn beam        180°     0.49    8/24 [0.16, 0.55]    0.364
wind 10 kn beam        180°     0.545   18/24 [0.53, 0.90]   0.760
wind 10 kn beam        135°     0.34    10/24 [0.22, 0.63]   0.373
wind 10 kn beam        135°     0.375   19/24 [0.58, 0.93]   0.763
wind 10 kn beam        90°      0.2     4/24 [0.05, 0.37]    0.301
wind 10 kn beam        90°      0.22    13/24 [0.33, 0.74]   0.732
=====================  =======  ======  ===================  =========

All twelve inside. Two changes brought the current's points in (before them the beam point at the lower H_s
lay above its interval, 0.381 against 4/24, and the bow-quartering ones at the low edge): the shipped
databases rebuilt with a lid clear of the hull (boatland/hydro/build.py), and the margins tilted onto the
friction circle by the side load the current puts on the tubes (boatland.freqdomain.screening.slip_directions:
0.372 → 0.428 at 135°, H_s 0.39 m, where the exact outcrossing rate of the Gaussian forces through the friction
cone gives 0.42). With the current in bow-quartering seas a bias remains, smaller: 48 other seeds (master seed
7) give 26/48 [0.39, 0.69] against 0.355 at 0.385 m and 43/48 [0.77, 0.97] against 0.744 at 0.42 m — both just
below, a limiting H_s about 4 % high (5 % before), the one unsafe bias found (open). The margins' mean, σ and
zero-crossing period agree with the time domain's within 2 %; damping the slow landed mode in both domains
leaves the time domain's count unchanged; but the governing vertical margin's tail is heavier than a Gaussian's
with the current: on 96 records (47 slipped: 0.49 [0.39, 0.59] against 0.355) it crosses mean − 2.5σ / 3σ / 3.3σ
1.17 / 1.28 / 1.42 times as often as the Gaussian with its own moments (without the current 1.01 / 1.08 / 1.10),
enough for the gap. The drag's quadratic term makes it: the same mean side load from 2 m/s with c_y 0.25 (half
the relative nonlinearity) roughly halves the excess (1.08 / 1.20 / 1.22), and there the screening's 0.256 meets
the time domain's 25/96. The drag's mean
load grows with the waves' motions (boatland.landing.environment.Environment.drag_mean_shift), which the
screening counts.
"""

import pytest

from boatland.validation.loads import LOADS, compare

SEEDS = 24
#: Points the screening misses today (load, heading, 0/1 = the lower/higher H_s) — none since 2026-12-03 (the
#: module docstring); a miss found later is marked here as a strict xfail, so that its fix shows.
KNOWN: set = set()
_DONE: dict = {}


def rows(tmp_path_factory, label, heading):
    key = (label, heading)
    if key not in _DONE:
        folder = tmp_path_factory.mktemp(f"loads_{heading:g}")
        _DONE[key] = compare(folder, label, LOADS[label], heading, seeds=SEEDS, workers=2)
    return _DONE[key]


def cases():
    for label in LOADS:
        for heading in (180.0, 135.0, 90.0):
            for i in (0, 1):
                marks = [pytest.mark.slow]
                if (label, heading, i) in KNOWN:
                    marks.append(pytest.mark.xfail(strict=True, reason="a known miss of the screening (module docstring)"))
                yield pytest.param(label, heading, i, marks=marks, id=f"{label.split()[0]}-{heading:g}-{i}")


@pytest.mark.parametrize("label, heading, i", list(cases()))
def test_screening_probability_lies_in_the_monte_carlo_interval(tmp_path_factory, label, heading, i):
    r = rows(tmp_path_factory, label, heading)[i]
    report = (f"{label}, {heading:g}°, H_s {r['Hs']:g} m: time domain {r['count']}/{SEEDS} [{r['lo']:.2f}, "
              f"{r['hi']:.2f}], screening {r['fd']:.3f}")
    print(report)
    assert r["failed"] == 0 and r["trials"] == SEEDS, report
    assert r["lo"] <= r["fd"] <= r["hi"], report
