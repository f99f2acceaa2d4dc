"""The frequency-domain screening against the time-domain Monte Carlo with a current and a wind (issue 27):
P(first slip within a 30-min access) of the default landing (ctv27) at Tp 7 s in head, bow-quartering and beam
seas, with a 1 m/s current on the beam from starboard and with a 10 kn gusty beam wind
(boatland.validation.loads; `boatland validate --case loads-vs-monte-carlo`).

At the two H_s per heading where the screening predicts P = 0.35 and 0.75, 24 seeded 30-min trials each
(master seed 2026): the screening's P inside the trials' Clopper–Pearson 95 % interval.

Measured (2026-12-03) — time domain [95 %] vs screening:

=====================  =======  ======  ===================  =========
load                   heading  H_s     time domain          screening
=====================  =======  ======  ===================  =========
current 1 m/s beam     180°     0.415   10/24 [0.22, 0.63]   0.331
current 1 m/s beam     180°     0.46    20/24 [0.63, 0.95]   0.747
current 1 m/s beam     135°     0.39    14/24 [0.37, 0.78]   0.372
current 1 m/s beam     135°     0.425   20/24 [0.63, 0.95]   0.758
current 1 m/s beam     90°      0.215   4/24 [0.05, 0.37]    0.381  ✗
current 1 m/s beam     90°      0.235   18/24 [0.53, 0.90]   0.783
wind 10 kn beam        180°     0.485   6/24 [0.10, 0.47]   0.337
wind 10 kn beam        180°     0.54    18/24 [0.53, 0.90]   0.736
wind 10 kn beam        135°     0.335   11/24 [0.26, 0.67]   0.341
wind 10 kn beam        135°     0.37    16/24 [0.45, 0.84]   0.736
wind 10 kn beam        90°      0.205   8/24 [0.16, 0.55]    0.391
wind 10 kn beam        90°      0.22    13/24 [0.33, 0.74]   0.722
=====================  =======  ======  ===================  =========

The miss is marked (strict xfail, so that a fix shows): in beam seas the screening's P rises faster with H_s
than the time domain's for ctv27 without any current too (11/24 [0.26, 0.67] against 0.765 at 0.225 m) — on the
safe side. With the beam current in bow-quartering seas the screening sits at the low edge: with 48 other
seeds (master seed 7) 29/48 [0.45, 0.74] against 0.372 and 45/48 [0.83, 0.99] against 0.758 — a limiting H_s
about 5 % high there, the one unsafe bias found (issue 27 leaves it open). The drag's mean load grows with the
waves' motions (boatland.landing.environment.Environment.drag_mean_shift), which the screening counts since
2026-12-03 (it moved this point from 0.360 to 0.372 and the time domain's mean normal forces are matched).
"""

import pytest

from boatland.validation.loads import LOADS, compare

SEEDS = 24
#: Points the screening misses today (load, heading, 0/1 = the lower/higher H_s) — the module docstring.
KNOWN = {("current 1 m/s beam", 90.0, 0)}
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
