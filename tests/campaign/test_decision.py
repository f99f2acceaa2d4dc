"""The decision table: P [interval] pivoted by Hs × Tp × heading, readable names, the limiting Hs with its
interval and flags, the screening and other estimators beside each cell, the seeds advice."""

import math

import numpy as np
import pytest

from boatland.campaign.decision import decision, other_estimates
from boatland.campaign.stats import clopper_pearson

INC = "slip > 0.1 m"


def fake_store(counts, seeds=4, extra=None):
    """A store's ``data`` as :func:`boatland.campaign.report.read_store` gives it: cases over Hs × Tp ×
    heading × push with ``counts[(hs, tp, heading, push)]`` incidents of ``seeds``."""
    axes = {"sea.Hs": sorted({k[0] for k in counts}), "sea.Tp": sorted({k[1] for k in counts}),
            "sea.relative_direction_deg": sorted({k[2] for k in counts}), "thrust.force": sorted({k[3] for k in counts})}
    fields = [("case", "i8"), ("label", "S200"), ("trials", "i8"), ("failed", "i8"), ("screening: P(slip)", "f8"),
              ("screening: note", "S200")] + [(f"axis: {a}", "f8") for a in axes]
    fields += [(f"{INC}: {k}", "i8" if k == "count" else "f8")
               for k in ("count", "P", "P lo", "P hi", "mean time", "mean lo", "mean hi")]
    fields += [(n, "f8") for n in (extra or {})]
    stats = np.zeros(len(counts), dtype=fields)
    for i, (key, k) in enumerate(sorted(counts.items())):
        r = stats[i]
        r["case"], r["trials"], r["screening: P(slip)"] = i, seeds, 0.5
        for a, v in zip(axes, key):
            r[f"axis: {a}"] = v
        r[f"{INC}: count"] = k
        r[f"{INC}: P"], r[f"{INC}: P lo"], r[f"{INC}: P hi"] = clopper_pearson(k, seeds)
        for n, values in (extra or {}).items():
            r[n] = values[i]
    plan = {"name": "fake", "axes": axes, "seeds": seeds}
    header = {"campaign": "fake", "incidents": INC, "inputs": '{"Tp": 7.0, "thrust": 80000.0, "mu_s": 0.6, '
              '"seeds": 4, "access": 1800.0, "heading": "head seas", "relative_direction_deg": 180.0}'}
    return {"stats": stats, "plan": plan, "header": header, "trials": np.zeros(0)}


def counts_demo():
    out = {}
    for push in (60e3, 80e3):
        for hs, k in zip((0.25, 0.5, 0.75, 1.0), (0, 3, 4, 4)):
            for d in (180.0, 135.0):
                for tp in (6.0, 8.0):
                    out[(hs, tp, d, push)] = k if push == 80e3 else min(4, k + 1)
    return out


def test_pivot_rows_hs_columns_tp_heading_sections_push():
    dec = decision(fake_store(counts_demo()), INC, 0.1)
    assert [s.fixed for s in dec.sections] == [{"thrust.force": 60e3}, {"thrust.force": 80e3}]
    s = dec.sections[1]
    assert s.rows == [0.25, 0.5, 0.75, 1.0]
    assert s.columns[0] == (6.0, 180.0)                  # head seas first
    assert s.column_text(s.columns[0]) == "Tp 6 s, head seas (180°)"
    assert s.title() == "push 80 kN"
    cell = s.cells[(0.5, (6.0, 180.0))]
    assert (cell.k, cell.n) == (3, 4) and cell.text() == "0.75 [0.19, 0.99]"     # a slip distance: no screening
    assert cell.text(screening=True) == "0.75 [0.19, 0.99] (screening 0.50)"    # as in the table of first slip
    md = dec.markdown()
    assert "| Hs [m] | Tp 6 s, head seas (180°) |" in md and "## push 60 kN" in md
    assert "sea.relative_direction_deg" not in md and "sea.Hs" not in md and "inf" not in md
    assert "rows Hs [m]; columns Tp [s] × heading (180° = head seas)" in md


def test_limiting_hs_with_interval_and_flags_at_the_ends_of_the_sweep():
    dec = decision(fake_store(counts_demo()), INC, 0.1)
    lim = dec.sections[1].limits[(6.0, 180.0)]
    assert lim.estimate.where == "inside" and lim.lower.where == "below"
    assert lim.text().startswith("0.283 m [< 0.25, ")
    low = dec.sections[0].limits[(6.0, 180.0)]          # 60 kN: 1 of 4 at the lowest Hs already
    assert low.estimate.where == "below" and low.text() == "< 0.25 m (below the sweep)"
    never = decision(fake_store({(0.25, 7.0, 180.0, 8e4): 0, (0.5, 7.0, 180.0, 8e4): 0}), INC, 0.1)
    assert never.sections[0].limits[(7.0, 180.0)].text() == "> 0.5 m (above the sweep)"
    assert "limiting Hs at P = 0.1" in dec.text()


def test_seeds_advice_for_the_width_asked():
    dec = decision(fake_store(counts_demo()), INC, 0.1, width=0.2)
    assert dec.widest == pytest.approx(max(h - lo for lo, h in (clopper_pearson(k, 4)[1:] for k in (0, 1, 3, 4))))
    assert dec.seeds_needed == 42
    assert "run about 42 seeds per case" in dec.advice() and "4 seeds per case" in dec.advice()
    assert decision(fake_store(counts_demo(), seeds=4), INC, 0.1, width=0.9).advice().count("enough") == 1


def test_other_estimates_appear_beside_the_monte_carlo():
    """The hook for other estimators (e.g. rare-event sampling): columns '<incident>: P (<method>)'."""
    counts = {(0.25, 7.0, 180.0, 8e4): 0, (0.5, 7.0, 180.0, 8e4): 3}
    extra = {f"{INC}: P (isee)": [0.004, 0.6], f"{INC}: P lo (isee)": [0.001, 0.5], f"{INC}: P hi (isee)": [0.01, 0.7]}
    data = fake_store(counts, extra=extra)
    assert set(other_estimates(data["stats"], INC)) == {"isee"}
    dec = decision(data, INC, 0.1)
    # the screening (slip onsets) is not beside this incident, a slip distance; the other estimate is of it
    assert dec.sections[0].cells[(0.25, (7.0, 180.0))].text() == "0.00 [0.00, 0.60] (isee 4e-3 [1e-3, 0.01])"   # rare: not "0.00"
    d = dec.as_dict()
    assert d["sections"][0]["cells"][1][0]["other_estimates"]["isee"]["P"] == 0.6
    assert not math.isnan(d["sections"][0]["cells"][1][0]["P_lo"])
