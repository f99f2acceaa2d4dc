"""The frequency-domain screening against the time-domain Monte Carlo with a current and a wind (issue 27):
P(first slip within a 30-min access) of the default landing (ctv27) at Tp 7 s in head, bow-quartering and beam
seas, with a 1 m/s current on the beam from starboard and with a 10 kn gusty beam wind
(boatland.validation.loads; `boatland validate --case loads-vs-monte-carlo`).

At the two H_s per heading where the screening predicts P = 0.35 and 0.75, 24 seeded 30-min trials each
(master seed 2026): the screening's P inside the trials' Clopper–Pearson 95 % interval.

Measured (2026-12-03, after three changes of that day: the drag's square in the screening,
boatland.freqdomain.quadratic_drag; the time domain's point loads about the Euler axes, boatland.rigid.euler_moment;
the tubes counted as separate events when the gusts' swing loads them in turn,
boatland.freqdomain.statistics.distinct_events) — time domain [95 %] vs screening:

=====================  =======  ======  ===================  =========
load                   heading  H_s     time domain          screening
=====================  =======  ======  ===================  =========
current 1 m/s beam     180°     0.41    7/24 [0.13, 0.51]    0.335
current 1 m/s beam     180°     0.455   18/24 [0.53, 0.90]   0.756
current 1 m/s beam     135°     0.38    8/24 [0.16, 0.55]    0.371
current 1 m/s beam     135°     0.415   15/24 [0.41, 0.81]   0.762
current 1 m/s beam     90°      0.21    4/24 [0.05, 0.37]    0.348
current 1 m/s beam     90°      0.23    14/24 [0.37, 0.78]   0.759
wind 10 kn beam        180°     0.465   7/24 [0.13, 0.51]    0.346
wind 10 kn beam        180°     0.515   18/24 [0.53, 0.90]   0.767
wind 10 kn beam        135°     0.335   9/24 [0.19, 0.59]    0.331
wind 10 kn beam        135°     0.37    16/24 [0.45, 0.84]   0.726
wind 10 kn beam        90°      0.2     5/24 [0.07, 0.42]    0.304
wind 10 kn beam        90°      0.22    13/24 [0.33, 0.74]   0.737
=====================  =======  ======  ===================  =========

All twelve inside. With more seeds per point for the current (the same H_s; master seed 7 × 48 and 11 × 96,
pooled with the 24 above into 168):

=======  ======  =========  ===========  ============  =============================
heading  H_s     screening  48 (seed 7)  96 (seed 11)  all 168 [95 %]
=======  ======  =========  ===========  ============  =============================
180°     0.41    0.335      20/48        24/96         51/168 = 0.30 [0.24, 0.38]
180°     0.455   0.756      36/48        70/96         124/168 = 0.74 [0.66, 0.80]
135°     0.38    0.371      19/48        33/96         60/168 = 0.36 [0.28, 0.43]
135°     0.415   0.762      39/48        64/96         118/168 = 0.70 [0.63, 0.77]
90°      0.21    0.348      15/48        17/96         36/168 = 0.21 [0.15, 0.28]
90°      0.23    0.759      34/48        58/96         106/168 = 0.63 [0.55, 0.70]
=======  ======  =========  ===========  ============  =============================

Head and bow-quartering seas inside; beam on, the screening is conservative, outside the pooled intervals (it
counts more slips: a limiting H_s about 3 % low). Before the time domain's fix its kernel skewed the margins by
a spurious second-order roll moment (yaw × the fender's pitch moment): with the current it made slips more
frequent at 135° (26/48 against 0.355), with the gusty wind in head seas less frequent (at H_s 0.49 m 31/96
slipped, 50/96 after the fix; seeds 500–595), and the screening, which had counted the two tubes' identical wave margins as one event,
matched the latter by chance; the gusts' swing unloads the tubes in turn, so they are two.
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
