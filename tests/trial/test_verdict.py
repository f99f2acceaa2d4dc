"""The verdict of a trial, events merged across contacts, values rounded to what the model resolves."""

import json

import numpy as np
import pytest

from boatland.trial.events import Event
from boatland.scenario.inputs import heading_name, inputs_text
from boatland.trial.simulate import simulate
from boatland.trial.verdict import fmt_angle, fmt_force, fmt_length, merge_events, rounded


@pytest.fixture(scope="module")
def slipped(landing):
    scenario, db = landing
    return simulate(scenario.replace({"simulation.duration": 45.0}), db)


@pytest.fixture(scope="module")
def held(landing):
    scenario, db = landing
    return simulate(scenario.replace({"simulation.duration": 45.0, "sea.Hs": 0.1}), db)


def test_verdict_names_the_inputs_and_when_and_how_far_it_slipped(slipped):
    v = slipped.verdict()
    assert v.outcome == "slipped" and not v.held
    first = slipped.slip_events()[0].t
    assert v.t == pytest.approx(first)                    # the slide that crossed 0.1 m started at the first slip
    line = v.text()
    assert line.startswith(f"SLIPPED at t = {first:.2f} s, slid ")
    assert "(slip > 0.1 m at t = " in line
    for word in ("JONSWAP Hs 1.5 m, Tp 7 s", "head seas (180°)", "push 80 kN", "μ_s 0.6 / μ_k 0.5", "seed 1"):
        assert word in line, word
    assert "\n" not in line
    assert slipped.summary_text().splitlines()[0] == line         # the verdict comes first


def test_a_calm_landing_is_held(held):
    v = held.verdict()
    assert v.outcome == "held" and v.held and v.t is None
    assert v.text().startswith("HELD for 25 s of waves") and "Hs 0.1 m" in v.text()


def test_symmetric_contacts_are_one_event_and_settling_is_hidden(slipped):
    raw = slipped.events
    merged = slipped.merged_events("all")
    assert len(merged) == len(raw) / 2                   # head seas on a symmetric landing: the tubes act together
    assert all(e.contacts == (0, 1) for e in merged)
    assert all(e.text().count("contacts 0+1") == 1 for e in merged)
    waves = slipped.merged_events()
    assert waves and all(not e.settling and e.t >= slipped.settled_at for e in waves)
    assert len(waves) < len(merged)
    text = slipped.summary_text()
    assert "(settling)" not in text and "settling events hidden: --events all" in text
    assert "(settling)" in slipped.summary_text("all")
    s = slipped.summary()
    assert s["slip_events"] == len(slipped.slip_starts()) == s["contact_slip_events"] / 2


def test_merge_keeps_different_contacts_apart():
    ev = [Event(1.0, 10, 0, "stick→slip", 2e3, 1e3), Event(1.0, 10, 1, "stick→slip", 2.2e3, 1e3),
          Event(1.0, 10, 1, "contact lost"), Event(2.0, 20, 1, "stick→slip", 5e3, 4e3)]
    m = merge_events(ev, settled_at=0.5)
    assert [(e.step, e.kind, e.contacts) for e in m] == [(10, "stick→slip", (0, 1)), (10, "contact lost", (1,)),
                                                         (20, "stick→slip", (1,))]
    assert "needed 2.0 / 2.2 kN > available 1.0 kN" in m[0].text()
    assert m[1].text() == "t = 1.00 s, contact 1: contact lost"


def test_no_noise_digits():
    assert rounded(3.04e-15, "m") == 0.0 and rounded(31.450000000000003, "s") == 31.45
    assert rounded(66808.178, "N") == 66808.0 and rounded(None, "N") is None
    assert fmt_force(11.8) == "0.0 kN" and fmt_force(18_349.0) == "18.3 kN"
    assert fmt_angle(1.99e-12) == "0.00°" and fmt_length(-1e-16) == "0.000 m"


def test_json_report_has_verdict_inputs_and_events_without_noise(slipped):
    rep = json.loads(json.dumps(slipped.report()))
    assert rep["verdict"]["outcome"] == "slipped" and rep["inputs"]["Hs"] == 1.5
    assert rep["inputs"]["thrust"] == 80e3 and rep["inputs"]["mu_s"] == 0.6
    assert rep["max_motions"]["sway [m]"] == 0.0 and rep["max_motions"]["roll [deg]"] == 0.0
    assert rep["events"] and all(e["contacts"] == [0, 1] and not e["settling"] for e in rep["events"])
    assert rep["events_hidden"] > 0
    assert len(slipped.report("all")["events"]) == len(rep["events"]) + rep["events_hidden"]


@pytest.mark.parametrize("rel, name", [(180, "head seas"), (135, "bow-quartering seas from starboard"),
                                       (225, "bow-quartering seas from port"), (90, "beam seas from starboard"),
                                       (45, "stern-quartering seas from starboard"), (0, "following seas"),
                                       (None, "no waves")])
def test_heading_names(rel, name):
    assert heading_name(rel) == name


def test_inputs_text_of_a_rigid_tank_trial():
    text = inputs_text({"scenario": "t", "sea": "regular H 0.1 m, T 1.2 s", "relative_direction_deg": 180.0,
                        "heading": "head seas", "thrust": 52.0, "mu_s": 0.9, "mu_k": 0.7, "seed": 3, "duration": 40.0})
    assert text == "regular H 0.1 m, T 1.2 s, head seas (180°); push 52 N, μ_s 0.9 / μ_k 0.7; seed 3, 40 s"
    assert np.isfinite(0.0)
