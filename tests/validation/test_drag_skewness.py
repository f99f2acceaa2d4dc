"""The screening's skewness of the friction margin in a current (boatland.freqdomain.quadratic_drag: the drag's
square, second order in the waves) against the time domain's, where the kernel evaluates the drag k w|w| on
the moving hull exactly.

ctv27 (scenarios/ctv_landing.toml) at Tp 7 s in bow-quartering seas (135°) with 1 m/s on the beam: contact 1's
up-slip margin −(μ f_n + f_v) over 96 seeded 30-min records (up to a record's first slip). Measured
2026-12-03 — time domain [± its bootstrap standard error] vs screening:

======  =================  ==========  ==============================
H_s     with the current   screening   without the current (both ~0)
======  =================  ==========  ==============================
0.2 m   +0.012 ± 0.003     +0.013      −0.003 ± 0.004
0.3 m   +0.020 ± 0.003     +0.019      −0.001 ± 0.004
======  =================  ==========  ==============================

(At 0.385 m, where 40 % of the records end at an early slip, cutting them there biases the time domain's
figure low: +0.018 with, −0.016 without the current.)
"""

import math
import warnings

import numpy as np
import pytest

SEEDS = 96
MU = 0.8


def _time_domain(sc, db, seeds):
    from scipy.stats import skew
    from stuck_margins import up_margin_records

    z = up_margin_records(sc, db, seeds, mu=MU)
    rng = np.random.default_rng(0)
    boot = [skew(np.concatenate([z[i] for i in rng.integers(0, len(z), len(z))])) for _ in range(100)]
    return float(skew(np.concatenate(z))), float(np.std(boot))


@pytest.mark.slow
@pytest.mark.parametrize("hs", [0.2, 0.3])
def test_the_margins_skewness_in_a_beam_current_is_the_time_domains(hs):
    from boatland.checks.files import load, resolve_database
    from boatland.freqdomain.landing import LandingSetup
    from boatland.freqdomain.screening import sea_response
    from boatland.resources import shipped_scenarios

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(shipped_scenarios() / "ctv_landing.toml").replace(
            {"sea.Hs": hs, "sea.Tp": 7.0, "sea.relative_direction_deg": 135.0, "simulation.duration": 1834.0,
             "current": {"speed": 1.0, "relative_direction_deg": 90.0}})
        db = resolve_database(sc)
        fd = sea_response(db, LandingSetup.from_scenario(sc, db), sc.sea.waves.parts, access_duration=1800.0)
        td, se = _time_domain(sc, db, SEEDS)
    g = fd.names.index("up 1")
    print(f"H_s {hs} m: time domain {td:+.4f} ± {se:.4f}, screening {fd.tails[g, 0]:+.4f}")
    assert td > 2 * se                                        # the current skews it, visibly
    assert abs(td - fd.tails[g, 0]) < max(3 * se, 0.006)
    assert math.isfinite(fd.p_access)
