"""Incident definitions (boatland.trial.incidents): names are the store keys and parse back; each one is
found in a hand-made trial where its time is known, after the settling and within an access."""


import numpy as np
import pytest

from boatland.contact.fender import OFF, OPEN, SLIP, STICK
from boatland.scenario.parts import Incidents
from boatland.trial.events import windowed_slide
from boatland.trial.incidents import (ContactLoss, ContactLossLonger, FirstSlip, RollAbove, SlideWithin, SlidOff,
                                      SlipDistance, campaign_incidents, parse_incident, trial_incidents)
from boatland.trial.result import Result


def trial(mode, z, roll_deg=None, settled_at=2.0, slide=None):
    """A one-contact trial at t = 0, 1, 2, …: its modes, the fender point's height on the tube, its roll and
    the slide over the tube in each step (default: the fender point's steps while it slips)."""
    mode = np.asarray(mode, dtype=np.int64)[:, None]
    n = mode.shape[0]
    tpos = np.zeros((n, 1, 2))
    tpos[:, 0, 0] = z
    x = np.zeros((n, 6))
    if roll_deg is not None:
        x[:, 3] = np.radians(roll_deg)
    zeros = np.zeros((n, 1))
    if slide is None:
        slide = np.zeros((n, 1, 2))
        slide[1:, 0, 0] = np.where(mode[1:, 0] == SLIP, np.diff(tpos[:, 0, 0]), 0.0)
    return Result(t=np.arange(float(n)), x=x, v=np.zeros((n, 6)), F_exc=np.zeros((n, 6)), thrust=np.zeros(n),
                  mode=mode, fn=zeros, ft=np.zeros((n, 1, 2)), needed=zeros, available=zeros, tpos=tpos, slide=slide,
                  provenance={"waves_from": settled_at}, incidents=Incidents({"slip_distance": (0.1, 0.3),
                                                                              "roll_limit_deg": (5.0,)}))


def test_names_are_the_store_keys_and_parse_back():
    for d in (FirstSlip(), SlipDistance(0.1), SlipDistance(0.25), RollAbove(5.0), ContactLoss(), SlidOff(),
              SlideWithin(0.5, 120.0), SlideWithin(0.05, 7.5)):
        assert parse_incident(d.name) == d
    assert SlideWithin(0.5, 120.0).name == "slide > 0.5 m within 120 s"
    assert SlipDistance(0.1).name == "slip > 0.1 m" and RollAbove(10.0).name == "roll > 10°"
    assert ContactLoss().name == "contact loss" and SlidOff().name == "slid off the landing"
    for bad in ("slip > x m", "slip > 0.1", "falls over"):
        with pytest.raises(ValueError, match="not the name of an incident"):
            parse_incident(bad)


def test_a_trial_and_a_campaign_count_these_definitions():
    inc = Incidents({"slip_distance": (0.1, 0.3), "roll_limit_deg": (5.0, 10.0)})
    assert [d.name for d in trial_incidents(inc)] == ["slip > 0.1 m", "slip > 0.3 m", "roll > 5°", "roll > 10°",
                                                      "contact loss", "slid off the landing"]
    assert [d.name for d in trial_incidents(inc, contacts=False)][-1] == "roll > 10°"
    assert [d.name for d in campaign_incidents(inc)] == ["first slip", "slip > 0.1 m", "slip > 0.3 m", "roll > 5°",
                                                         "roll > 10°", "contact loss"]
    assert [d.name for d in trial_incidents(None)] == ["slip > 0.1 m", "contact loss", "slid off the landing"]


def test_each_definition_is_found_where_it_happens():
    """Lands at t = 2 (after the settling), slides 0.15 m from t = 4 to 6, sticks, slides 0.2 m more from
    t = 8, loses contact at t = 11; rolls past 5° at t = 9."""
    mode = [0, 1, 1, 1, SLIP, SLIP, STICK, STICK, SLIP, SLIP, STICK, OPEN, OPEN]
    z = [0, 0, 0, 0, -0.05, -0.15, -0.15, -0.15, -0.25, -0.35, -0.35, -0.35, -0.35]
    roll = [0, 0, 0, 0, 1, 2, 3, 4, 4.5, 6, 4, 2, 0]
    r = trial(mode, z, roll)
    assert r.incident_times() == {"slip > 0.1 m": 5.0, "slip > 0.3 m": 9.0, "roll > 5°": 9.0, "contact loss": 11.0,
                                  "slid off the landing": None}
    assert FirstSlip().first_time(r) == 4.0
    # within an access from t = 6: the second slide's onset, its exceedances, the contact lost
    assert FirstSlip().in_access(r, 6.0) == 8.0
    assert SlipDistance(0.1).in_access(r, 6.0) == 6.0 and SlipDistance(0.3).in_access(r, 6.0) == 9.0
    assert RollAbove(5.0).in_access(r, 10.0) is None and ContactLoss().in_access(r, 6.0) == 11.0


def test_sliding_off_is_contact_loss_and_its_own_incident():
    r = trial([0, 1, 1, SLIP, SLIP, OFF], [0, 0, 0, -0.2, -0.6, -0.9])
    assert r.incident_times()["slid off the landing"] == 5.0 and r.incident_times()["contact loss"] == 5.0
    assert SlidOff().in_access(r, 10.0) == 10.0 and ContactLoss().in_access(r, 10.0) == 10.0   # ended before


def test_slips_while_settling_are_not_incidents():
    r = trial([0, SLIP, SLIP, 1, 1, 1], [0, 0.2, 0.5, 0.5, 0.5, 0.5], settled_at=3.0)
    assert FirstSlip().first_time(r) is None and r.incident_times()["slip > 0.1 m"] is None
    assert np.all(r.worst_offset == 0.0)                           # landed at t = 3 where it stuck


def test_a_contact_lost_longer_than_a_duration():
    """Open at t = 5 for one second (a graze), then from t = 8 to 11 (a bounce): with a 1.5-s definition
    only the bounce counts, at the first step past 8 + 1.5 s; an access from t = 11 sees none."""
    mode = [0, 1, 1, 1, 1, OPEN, 1, 1, OPEN, OPEN, OPEN, 1, 1, 1]
    r = trial(mode, np.zeros(len(mode)))
    d = ContactLossLonger(1.5)
    assert d.name == "contact loss > 1.5 s" and parse_incident(d.name) == d
    assert d.first_time(r) == 10.0 and ContactLoss().first_time(r) == 5.0
    assert d.in_access(r, 9.0) == 10.0 and d.in_access(r, 11.0) is None
    assert ContactLossLonger(3.0).first_time(r) is None                   # 3 s at most: not longer
    inc = Incidents({"slip_distance": (0.1,), "contact_loss_duration": (1.5,)})
    assert "contact loss > 1.5 s" in [x.name for x in campaign_incidents(inc)]


def test_a_new_definition_reaches_the_trial_and_the_campaign_from_the_files(tmp_path):
    """``[incidents] contact_loss_duration`` in a scenario (or a campaign file) is all a user writes."""
    import boatland
    from boatland.campaign.plan import load_campaign
    from boatland.campaign.runner import incident_names
    from boatland.checks.files import load

    r = boatland.simulate("ctv_landing", **{"incidents.contact_loss_duration": [0.5], "simulation.duration": 40.0})
    assert "contact loss > 0.5 s" in r.incident_times() and "contact loss > 0.5 s" in r.report()["incidents"]
    camp = tmp_path / "c.toml"
    camp.write_text(f'''name = "c"
scenario = "{boatland.api.scenario_path("ctv_landing")}"
seeds = 1
[incidents]
contact_loss_duration = [0.5, 2.0]
''')
    names = incident_names(load_campaign(camp, load_scenario=load))
    assert names[-2:] == ["contact loss > 2 s", "contact loss"] and "contact loss > 0.5 s" in names


def sliding(times, steps, n=400, settled_at=10.0):
    """A one-contact trial (t = 0 … n−1 s) stuck from t = 5 s, slipping at ``times`` by ``steps`` [m] down the tube."""
    mode = np.full(n, STICK)
    mode[:5] = OPEN
    z = np.zeros(n)
    for t, dz in zip(times, steps):
        mode[t] = SLIP
        z[t:] += dz
    return trial(mode, z, settled_at=settled_at)


def test_a_slide_within_a_window_counts_the_slides_inside_it():
    """Two slides of 0.3 m: 100 s apart they are 0.6 m within 120 s (an incident when the second ends),
    200 s apart never more than 0.3 m within 120 s; back and forth is a slide too (the path, not the net);
    slides before the settling or the access do not count."""
    d = SlideWithin(0.5, 120.0)
    r = sliding([50, 150], [-0.3, -0.3])
    assert d.first_time(r) == 150.0
    assert np.isclose(windowed_slide(r.t, r.slide, r.settle_row, 120.0).max(), 0.6)
    assert d.first_time(sliding([50, 250], [-0.3, -0.3])) is None
    assert np.isclose(windowed_slide(r.t, sliding([50, 250], [-0.3, -0.3]).slide, 10, 120.0).max(), 0.3)
    assert d.first_time(sliding([50, 169], [-0.3, -0.3])) == 169.0     # 119 s apart: inside
    assert d.first_time(sliding([50, 171], [-0.3, -0.3])) is None      # 121 s apart: not
    assert d.first_time(sliding([50, 80], [-0.3, 0.3])) == 80.0        # down and back up
    assert SlipDistance(0.1).first_time(sliding([50, 80], [-0.3, 0.3])) == 50.0
    assert d.first_time(sliding([8, 50], [-0.3, -0.3])) is None        # the first while settling
    assert d.in_access(r, 100.0) is None and d.in_access(r, 40.0) == 150.0
    assert SlideWithin(0.5, 60.0).first_time(r) is None


def test_the_elastic_shear_of_a_stuck_fender_is_not_a_slip():
    """A soft rubber stuck on the tube: its fender point moves 0.2 m (shear) without a slide — no slip
    incident, the summary says shear deflection; after a slip the offset counts."""
    n = 60
    mode = np.full(n, STICK)
    z = np.minimum(np.arange(n) * 0.01, 0.2)
    r = trial(mode, z)
    s = r.summary()
    assert s["slip_events"] == 0 and s["max_slip_distance"] == 0.0 and np.isclose(s["max_shear_deflection"], 0.18)
    assert r.incident_times()["slip > 0.1 m"] is None and r.verdict().held
    assert "shear deflection" in r.summary_text() and "slip distance" not in r.summary_text()
    mode[40] = SLIP
    r = trial(mode, np.arange(n) * 0.01)        # the fender point still moving when it slips at t = 40 s
    assert r.incident_times()["slip > 0.1 m"] == 40.0 and SlideWithin(0.005, 5.0).first_time(r) == 40.0
    assert not r.verdict().held


def test_slide_within_from_a_scenario_reaches_the_trial_and_a_campaign(tmp_path):
    import boatland
    from boatland.campaign.plan import load_campaign
    from boatland.campaign.runner import incident_names
    from boatland.checks.files import load
    from boatland.tomlspec import SpecError

    r = boatland.simulate("ctv_landing", **{"incidents.slide_within": [{"window": 60.0, "distance": 0.2}],
                                            "simulation.duration": 40.0})
    assert "slide > 0.2 m within 60 s" in r.report()["incidents"]
    assert "slide > 0.2 m within 60 s" in r.verdict().text()     # held: judged against it, by name
    camp = tmp_path / "c.toml"
    camp.write_text(f'''name = "c"
scenario = "{boatland.api.scenario_path("ctv_landing")}"
seeds = 1
[incidents]
slide_within = [{{distance = 0.5, window = 120.0}}, {{distance = 0.1, window = 30.0}}]
''')
    names = incident_names(load_campaign(camp, load_scenario=load))
    assert "slide > 0.5 m within 120 s" in names and "slide > 0.1 m within 30 s" in names
    camp.write_text(camp.read_text().replace("window = 30.0", "window = -30.0"))
    with pytest.raises(SpecError, match=r"slide_within\[1\]\.window"):
        load_campaign(camp, load_scenario=load)


def test_the_watch_of_a_running_trial_finds_what_the_finished_trial_does():
    """A run log's incidents, found block by block as the trial runs (boatland.trial.incidents.IncidentWatch),
    are the finished trial's — slip distances from the first slip on, slides within windows that span blocks,
    roll — for blocks of any length."""
    import boatland
    from boatland.trial.events import track_landing
    from boatland.trial.result import SERIES
    from boatland.trial.sink import StepBlock
    from boatland.trial.incidents import IncidentWatch

    r = boatland.simulate("ctv_landing", **{"sea.Hs": 0.5, "sea.relative_direction_deg": 90.0,
                                            "simulation.duration": 320.0, "incidents.roll_limit_deg": [0.5, 40.0],
                                            "incidents.slide_within": [{"distance": 0.1, "window": 120.0},
                                                                       {"distance": 0.05, "window": 2.0}]})
    expected = {k: v for k, v in r.incident_times().items() if v is not None and k in
                {d.name for d in r.incident_definitions if isinstance(d, (SlipDistance, SlideWithin, RollAbove))}}
    assert {"slip > 0.1 m", "slide > 0.1 m within 120 s", "roll > 0.5°"} <= expected.keys()   # it slips and slides
    for size in (1, 7, 20, 333, len(r.t)):
        watch = IncidentWatch(r.incidents, r.settle_row)
        anchor = np.full((r.mode.shape[1], 2), np.nan)
        found = {}
        for k0 in range(0, len(r.t), size):
            k1 = min(k0 + size, len(r.t))
            block = StepBlock(k0=k0, k1=k1, **{n: getattr(r, n)[k0:k1] for n in SERIES}, slide=r.slide[k0:k1])
            offsets = np.empty(block.mode.shape)
            track_landing(block.mode, block.tpos, anchor, offsets, max(0, r.settle_row - k0))
            for t, text in watch(block, offsets):
                found[text.split(": ", 1)[1].rsplit(" at t = ", 1)[0]] = t
        assert found == expected, size
