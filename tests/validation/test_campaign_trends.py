"""Monte Carlo trends on the CTV (Grøtting 2015 §4.2, Table 4.14): P(slip) rises with Hs and falls with
thrust; beam and quartering seas slip far more than head seas at the same Hs.

Measured (2026-12-01, the compliant fender of issue 13, 10 min of full sea per trial, 6 seeds per case) —
printed by the test: at Hs 0.25 m the first slip comes in 1/6 trials in head seas (at 577 s), 6/6 in
quartering (mean 16 s) and 6/6 in beam seas (mean 3 s); slides beyond 0.1 m from the landing position
only in beam seas (2/6; the rubber holds most slips to a few centimetres).
"""

from pathlib import Path

import pytest

from boatland.campaign.runner import completed
from boatland.validation.campaigns import TRENDS_SET, mean_first_time, run_study, write_campaign
from boatland.validation.campaigns import p_incident as _p_incident

BASE = Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml"   # the figures' vessel (the first default)


def study(tmp_path, axes: dict, name: str):
    """A campaign of the base scenario, 6 seeds × 10 min (boatland.validation.campaigns: the code of
    `boatland validate`'s grotting-trends case)."""
    f = write_campaign(tmp_path / "campaigns" / f"{name}.toml", name, BASE, seeds=6, master_seed=77, access=600.0,
                       set_=TRENDS_SET, axes=axes, incidents={"slip_distance": [0.1]})
    c, t, _ = run_study(f, tmp_path / f"{name}.h5", workers=2)
    ok = completed(t)                                  # completed, or ended sliding off the landing (an outcome)
    assert ok.all(), [(int(r["trial"]), r["message"]) for r in t[~ok]]
    return c, t


def p_incident(c, t, name="slip > 0.1 m"):
    return _p_incident(c, t, name)


@pytest.mark.slow
def test_p_slip_rises_with_hs_and_falls_with_thrust(tmp_path):
    hs_values = (0.2, 0.4, 0.6, 0.8)
    c, t = study(tmp_path, {"sea.Hs": list(hs_values), "thrust.force": [80e3, 160e3]}, "hs_thrust")
    p = p_incident(c, t)
    print("P(slip > 0.1 m in 10 min):", {k: round(float(v), 2) for k, v in p.items()})
    for thrust in (80e3, 160e3):
        ps = [p[(hs, thrust)] for hs in hs_values]
        assert ps == sorted(ps) and ps[-1] > ps[0], (thrust, ps)
    assert all(p[(hs, 160e3)] <= p[(hs, 80e3)] for hs in hs_values)
    assert sum(p[(hs, 160e3)] for hs in hs_values) < sum(p[(hs, 80e3)] for hs in hs_values)


@pytest.mark.slow
def test_beam_and_quartering_seas_slip_far_more_than_head_seas(tmp_path):
    c, t = study(tmp_path, {"sea.Hs": [0.25], "sea.relative_direction_deg": [180.0, 135.0, 90.0]}, "heading")
    p = p_incident(c, t, "first slip")
    mean_t = {int(k[1]): v for k, v in mean_first_time(c, t, "first slip", 600.0).items()}
    print("P(first slip in 10 min):", p, "mean time to it (censored at 600 s):", mean_t,
          "P(slip > 0.1 m):", p_incident(c, t))
    assert p[(0.25, 135.0)] > p[(0.25, 180.0)] and p[(0.25, 90.0)] > p[(0.25, 180.0)]
    assert mean_t[135] < 0.5 * mean_t[180] and mean_t[90] < 0.5 * mean_t[180]
