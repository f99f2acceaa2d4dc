"""A landing with three tubes (a fender line on each): the scenario on its vessel (boatland.landing) is one
adapter for any number of contacts — it runs as a trial, in the frequency-domain screening and in a
rare-event campaign, and the time domain and the screening agree on its static contact forces."""

from pathlib import Path

import h5py
import numpy as np
import pytest

from boatland.campaign.isee import run_isee
from boatland.campaign.plan import load_campaign
from boatland.checks import check
from boatland.checks.files import load, load_checked, resolve_database
from boatland.contact.fender import STICK
from boatland.freqdomain.landing import LandingSetup
from boatland.freqdomain.screening import screening_grid, slip_transfer
from boatland.landing.setup import Setup
from boatland.trial.simulate import simulate

REPO = Path(__file__).resolve().parents[2]
TUBES_Y = (1.0, 0.0, -1.0)          # [m] three tubes 1 m apart on the landing's face (bearing 180°)


def three_tube_scenario(path: Path, Hs: float = 0.3) -> Path:
    """The default landing (ctv27, 150 kN, μ_s 0.8) on three tubes instead of two: the struts given
    explicitly, one fender point and line per tube (the bow fender ends at |y| = 2.94 m)."""
    text = (REPO / "scenarios" / "ctv_landing.toml").read_text()
    head, rest = text.split("[landing]", 1)
    rest = rest.split("[fender]", 1)[1]
    struts = "".join(f"""
[[landing.struts]]
position = [-4.45, {y}]
diameter = 0.35
normal_deg = 180.0
bottom = -4.0
top = 6.0
""" for y in TUBES_Y)
    landing = f"""[landing]
monopile_diameter = 6.5
monopile_position = [0.0, 0.0]
{struts}
[fender]
points = [{", ".join(f"[13.84, {y}, 1.9]" for y in TUBES_Y)}]
width = 3.88
"""
    fender_rest = "\n".join(line for line in rest.splitlines()
                            if not line.startswith(("points =", "width =")))
    body = head + landing + fender_rest
    body = body.replace("Hs = 0.4 ", f"Hs = {Hs} ").replace('name = "ctv_landing"', 'name = "three_tubes"')
    body = "\n".join(line for line in body.splitlines() if not line.startswith("dt = "))  # the default rule: the
    path.write_text(body)
    return path


@pytest.fixture(scope="module")
def three(tmp_path_factory):
    path = three_tube_scenario(tmp_path_factory.mktemp("three") / "three_tubes.toml")
    scenario, db, _ = load_checked(path)
    return path, scenario.replace({"simulation.duration": 90.0}), db


def test_three_tubes_are_three_contacts_in_the_checks_the_trial_and_the_screening(three):
    _, sc, db = three
    assert len(sc.landing.struts) == 3 and len(sc.fender.points) == 3
    assert check(sc, db, memory=True).ok
    setup = Setup.of(sc, db)
    assert setup.contacts()[0].shape[0] == 3 and setup.contact_law().n_points == 3
    r = simulate(sc, db, setup=setup)
    assert r.completed and r.mode.shape[1] == 3 and r.fn.shape == (len(r.t), 3)
    calm = sc.replace({"sea": None, "simulation.duration": 60.0})
    rc = simulate(calm, db)
    assert np.all(rc.mode[-1] == STICK)                              # all three hold the push
    land = LandingSetup.from_scenario(sc, db)
    tr = slip_transfer(db, land, beta_deg=[180.0, 135.0])
    assert land.n_points == 3 and tr.H.shape[-1] == 4 * 3 + 1     # four margins per contact, then roll
    # the screening's static normal forces are the time domain's at rest (the same adapter, three contacts)
    np.testing.assert_allclose(tr.N_static, rc.fn[-1], rtol=2e-3)
    assert tr.N_static.sum() == pytest.approx(150e3, rel=0.02)     # they share the push
    table = screening_grid(db, land, [7.0], [180.0, 135.0])
    assert np.all(np.isfinite(table.Hs) & (table.Hs > 0))


def test_three_tubes_in_a_rare_event_campaign(three, tmp_path):
    path, _, _ = three
    camp = tmp_path / "rare.toml"
    camp.write_text(f"""
name = "three_rare"
scenario = "{path}"
method = "isee"
master_seed = 5
access = 60.0
[axes]
"sea.Hs" = [0.35]
[isee]
target_cov = 0.5
batch = 4
min_samples = 8
max_samples = 8
settle = 10.0
""")
    campaign = load_campaign(camp, load_scenario=load)
    store = run_isee(campaign, tmp_path / "rare.h5", loaders=(load, resolve_database), workers=1)
    t = store.table()
    assert t.size == 8 and np.all(t["status"] == 0)                # every sample ran in the time domain
    assert np.all(t["isee_n"] >= 1)                                  # each inside the linear first-slip domain
    with h5py.File(tmp_path / "rare.h5", "r") as f:
        stats = f["stats"][()]
    p, lo, hi = (float(stats[f"first slip: {k}"][0]) for k in ("P", "P lo", "P hi"))
    assert 0 <= lo <= p <= hi <= 1 and 0 < p < 0.1                  # rare in a 60-s access at Hs 0.35 m, head seas
