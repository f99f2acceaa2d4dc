"""Operability judged by a rare-event campaign's time-domain limits (boatland.site.tables.LimitsTable): a real
ISEE campaign store (ctv24, 2 Tp × 3 headings, a short access: seconds), read back; the table's limits at its
cases, linear between them, mirrored port/starboard, not covered outside; the CLI with the store beside the
screening."""

import json
import subprocess
import sys

import numpy as np
import pytest

from boatland.site import LimitsTable, Weather, table_operability
from small_campaign import isee_file
from tests.site.conftest import CTV24_LANDING, HINDCAST

pytestmark = pytest.mark.slow        # a real campaign in a real process


def run(*args):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          timeout=900)


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("limits")
    camp = isee_file(tmp, "site_limits", axes='"sea.Tp" = [6.0, 9.0]\n"sea.relative_direction_deg" = [180.0, 135.0, 90.0]',
                     seed=30)
    r = run("campaign", camp, "-o", tmp / "limits.h5")
    assert r.returncode == 0, r.stderr
    return tmp / "limits.h5"


def test_the_table_is_the_stores(store):
    import h5py

    t = LimitsTable.read(store)
    with h5py.File(store, "r") as f:
        lim = f["isee_limits"][()]
    assert t.incident == "first slip" and t.accept == 0.05 and t.access == 20.0 and t.thrust == 80e3
    assert t.Tp.tolist() == [6.0, 9.0] and t.mirrored and t.beta_deg.tolist() == [90.0, 135.0, 180.0, 225.0, 270.0]
    for row in lim:
        T, b = row["axis: sea.Tp"], row["axis: sea.relative_direction_deg"]
        assert t.at(T, b) == row["limiting Hs"] and t.at(T, 360.0 - b) == row["limiting Hs"]
    assert np.isfinite(t.Hs).all()


def test_a_store_sweeping_more_than_tp_and_direction_is_refused(store, tmp_path):
    """A campaign that also sweeps the push gives several limits per (Tp, direction): not one table."""
    import shutil

    import h5py

    from boatland.errors import BoatlandInputError

    other = tmp_path / "two_pushes.h5"
    shutil.copyfile(store, other)
    with h5py.File(other, "r+") as f:                  # an in-place edit (drops boatland's checksum trailer)
        lim = f["isee_limits"][()]
        names = list(lim.dtype.names) + ["axis: thrust.force"]
        new = np.zeros(2 * lim.size, dtype=[(n, lim.dtype[n]) if n in lim.dtype.names else (n, "f8") for n in names])
        for n in lim.dtype.names:
            new[n] = np.concatenate([lim[n], lim[n]])
        new["axis: thrust.force"] = [60e3] * lim.size + [100e3] * lim.size
        del f["isee_limits"]
        f["isee_limits"] = new
    with pytest.raises(BoatlandInputError, match="sweeps thrust.force besides Tp and direction"):
        LimitsTable.read(other)


def test_between_the_cases_linear_and_outside_not_covered(store):
    t = LimitsTable.read(store)
    h = t.Hs
    # Tp 7 s (a third of the way), heading 157.5° (half way from 135° to 180°)
    want = (2 / 3) * (0.5 * h[0, 1] + 0.5 * h[0, 2]) + (1 / 3) * (0.5 * h[1, 1] + 0.5 * h[1, 2])
    assert t.at(7.0, 157.5) == pytest.approx(want, rel=1e-12)
    assert np.isnan(t.at(5.0, 180.0)) and np.isnan(t.at(10.0, 180.0))          # beyond its periods
    assert np.isnan(t.at(7.0, 30.0)) and np.isnan(t.at(7.0, 0.0))              # following seas: not in it
    # a weather of three seas at a landing at 0°: from 180° (head, inside), from 0° (following: outside)
    w = Weather.scatter([0.05, 0.05, 5.0], [7.0, 7.0, 7.0], [180.0, 0.0, 180.0], [0.5, 0.3, 0.2])
    op = table_operability(t, w, [0.0])
    assert op.limits.covered[:, 0].tolist() == [True, False, True]
    assert op.workable[:, 0].tolist() == [True, False, False]
    assert op.not_covered == pytest.approx(0.3) and op.availability()[0] == pytest.approx(0.5)
    assert "30.0 % of the time outside the table" in op.text()


def test_inside_the_table_the_time_domain_and_the_screening_judge_alike(store, landing):
    """Sea states inside the table (Tp 6–9 s, head to beam at a landing at 0°): the availability by the time
    domain's first-slip limits (interpolated) and by the screening's onset at the same risk per the same access
    differ by little — the ISEE limits lie within a few % of the screening's (tests/campaign/test_isee.py)."""
    from boatland.site import operability

    db, s = landing
    t = LimitsTable.read(store)
    rng = np.random.default_rng(2)
    n = 600
    w = Weather.scatter(rng.uniform(0.03, 0.45, n), rng.uniform(6.0, 9.0, n), rng.uniform(90.0, 270.0, n).round(),
                        np.full(n, 1 / n))
    td = table_operability(t, w, [0.0])
    fd = operability(db, s, w, [0.0], accept=0.05, access_duration=20.0)
    assert td.not_covered == 0
    a_td, a_fd = td.availability()[0], fd.availability()[0]
    assert 0.2 < a_fd < 0.8 and abs(a_td - a_fd) < 0.05, (a_td, a_fd)  # measured: 0.358, 0.343
    agree = (td.workable[:, 0] == fd.workable[:, 0]).mean()
    assert agree > 0.9, agree                                                 # measured: 0.985


def test_the_cli_puts_the_store_beside_the_screening(store):
    r = run("operability", CTV24_LANDING, store, HINDCAST, "--landing", "45", "--landing", "225", "--accept", "0.05",
            "--access", "20", "--json")
    assert r.returncode == 0, r.stderr
    a, b = json.loads(r.stdout)["results"]
    assert a["limits"].startswith("frequency-domain screening") and b["limits"].startswith("time domain (site_limits")
    assert b["accept"] == a["accept"] == 0.05 and b["not_covered"] > 0.5 and a["not_covered"] == 0
    assert b["scenario"] == "site_limits (first slip, time domain)"
    r = run("operability", store, HINDCAST)
    assert r.returncode == 2 and "--landing: give the landings' compass bearings" in r.stderr
