"""``boatland run``: under its verdict, the odds of this sea against the accepted risk — in the text and in
``--json`` (real subprocesses; the probabilities checked against the screening computed here)."""

import json
import math
import subprocess
import sys

import numpy as np

import pytest

import boatland
from boatland.checks.files import resolve_database
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import sea_response
from boatland.freqdomain.statistics import ACCEPT_PRESETS, rice_rate


def run(*args):
    return subprocess.run([sys.executable, "-m", "boatland", "run", "--no-log", *map(str, args)], capture_output=True,
                          text=True, timeout=300)


def test_json_carries_the_accepted_risk_and_each_incidents_probability():
    r = run("--duration", "40", "--json")
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    risk = out["risk"]
    assert risk["available"] and risk["accepted"]["p"] == ACCEPT_PRESETS["best"] and risk["access_s"] == 1800.0
    assert risk["accepted"]["text"] == "1 access in 840 (1.19e-3 per 30-min access, Grøtting 2015 best estimate)"
    # every incident the trial reports, and the onset, each with its basis
    assert set(risk["incidents"]) == {"first slip", *out["incidents"]}
    assert risk["incidents"]["slide > 0.5 m within 120 s"]["basis"] == "upper bound"
    assert risk["incidents"]["contact loss"] == {"p": None, "basis": "time domain only", "above_accepted": None}
    # the onset probability is the screening's of the scenario's sea, slips only (Rice), recomputed here
    sc = boatland.load_scenario("ctv_landing")
    db = resolve_database(sc)
    resp = sea_response(db, LandingSetup.from_scenario(sc, db, roll_limit_deg=89.0), sc.sea.waves.parts,
                        statistics="rice")
    assert risk["p_onset"] == pytest.approx(resp.p_access, rel=1e-9)
    assert risk["incidents"]["first slip"]["above_accepted"] == (resp.p_access > ACCEPT_PRESETS["best"])
    # roll beyond 5°: Rice on both signs of the roll response
    m0, m2 = resp.m[-1, 0], resp.m[-1, 2]
    p_roll = -np.expm1(-1800.0 * 2 * rice_rate(math.radians(5.0), m0, m2))
    assert risk["incidents"]["roll > 5°"]["p"] == pytest.approx(float(p_roll), abs=1e-12)


def test_text_puts_the_odds_under_the_verdict_and_takes_accept():
    r = run("--duration", "40", "--accept", "non-conservative")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert lines[0].startswith(("HELD", "SLIPPED")) and " this time; a slip onset is expected in 1 of " in lines[1]
    assert "the accepted 1 access in 37 (0.0268 per 30-min access, Grøtting 2015 non-conservative)" in lines[1]
    bad = run("--accept", "often")
    assert bad.returncode == 2 and "--accept" in bad.stderr and "Traceback" not in bad.stderr
