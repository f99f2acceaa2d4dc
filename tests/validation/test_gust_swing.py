"""The landed vessel's slow swing in a gusty beam wind: the screening's linearised response against the time
domain. ctv27 on its landing (scenarios/ctv_landing.toml, no waves) in a 10 m/s beam wind with NPD gusts
(DNV-RP-C205 §2.3.2.11): the gusts excite the landed sway–yaw mode about the bow (~0.118 rad/s, 53 s), damped
by the hull's drag in still water (quadratic, linearised statistically in the frequency domain).

Measured (2026-12-03, the rebuilt ctv27): sway σ 0.292 m over 24 seeded 30-min trials, the screening's 0.299 m
(+2.4 %; on the database before 0.291 m); each tube's normal force σ 15.9 kN; the same resonance frequency. Checked: within 8 % (the trials' mean variance over 24 × ~34 swing
periods has a standard error of ~6 % in σ)."""

import math
import warnings

import numpy as np
import pytest

from boatland.freqdomain.landing import LandingSetup
from boatland.trial.simulate import simulate


@pytest.mark.slow
def test_gust_swing_frequency_domain_against_time_domain():
    from boatland.checks.files import load
    from boatland.hydro.read import load_database
    from boatland.resources import shipped_scenarios

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = load(shipped_scenarios() / "ctv_landing.toml").replace(
            {"wind.speed": 10.0, "wind.relative_direction_deg": 90.0, "sea": None, "simulation.duration": 1900.0})
        db = load_database("ctv27")
    land = LandingSetup.from_scenario(sc.replace({"sea": {"kind": "jonswap", "Hs": 1e-3, "Tp": 7.0,
                                                         "relative_direction_deg": 180.0}}), db)
    w, wt, x, _ = land.gust_response(db)
    fd = math.sqrt(float(np.sum(np.abs(x[:, 1]) ** 2 * land.steady.gust_spectrum(w) * wt)))
    var, fn = [], []
    for seed in range(1, 25):
        r = simulate(sc.replace({"simulation.seed": seed}), db)
        var.append(r.x[r.t > 100, 1].var())
        fn.append(r.fn[r.t > 100].var(axis=0).mean())
    td = math.sqrt(float(np.mean(var)))
    print(f"sway σ: time domain {td:.3f} m (24 seeds), screening {fd:.3f} m; each tube's normal force σ "
          f"{math.sqrt(float(np.mean(fn))) / 1e3:.1f} kN (time domain)")
    assert fd == pytest.approx(td, rel=0.08)
