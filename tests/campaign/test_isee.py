"""ISEE campaigns end to end (boatland.campaign.isee): the same store from 1 or 2 local workers and from
a real Dask cluster, resume after SIGKILL, the limiting-Hs search, the report, the heaviest samples'
run logs, bad input. Real processes throughout (boatland CLI, dask scheduler and workers)."""

import html
import math
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest
from small_campaign import isee_file

pytestmark = pytest.mark.slow        # rare-event campaigns in real processes: not in the quick loop (pytest -m "not slow")

REPO = Path(__file__).resolve().parents[2]
BASE = REPO / "scenarios" / "ctv24_landing.toml"   # measured on ctv24 (the first default)
#: The ``dask`` command of this Python's environment (on PATH or not).


def run(*args, timeout=900):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          timeout=timeout)


def same(a, b):
    assert a.keys() == b.keys()
    for name in a:
        x, y = a[name], b[name]
        assert x.dtype == y.dtype and x.shape == y.shape, name
        assert x.tobytes() == y.tobytes(), name      # bit for bit (NaN included)


def summaries(store):
    """Everything in the store but the wall times (not reproducible)."""
    with h5py.File(store, "r") as f:
        t, stats = f["trials"][()], f["stats"][()]
        lim = f["isee_limits"][()] if "isee_limits" in f else None
    cols = {n: t[n] for n in t.dtype.names if n != "wall_time"}
    cols.update({f"stats/{n}": stats[n] for n in stats.dtype.names if n != "wall time"})
    if lim is not None:
        cols.update({f"limits/{n}": lim[n] for n in lim.dtype.names})
    return cols


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("isee")
    camp = isee_file(tmp)
    r = run("campaign", camp, "-o", tmp / "one.h5", "--workers", "1", "--report", tmp / "rep", "--save-worst", "2")
    assert r.returncode == 0, r.stderr
    return camp, tmp / "one.h5", r


def test_one_and_two_local_workers_give_the_same_store(reference, tmp_path):
    camp, one, _ = reference
    r = run("campaign", camp, "-o", tmp_path / "two.h5", "--workers", "2")
    assert r.returncode == 0, r.stderr
    same(summaries(one), summaries(tmp_path / "two.h5"))


def test_the_store_holds_samples_runs_and_limits(reference):
    camp, one, r = reference
    with h5py.File(one, "r") as f:
        t, runs, lim = f["trials"][()], f["stats"][()], f["isee_limits"][()]
        assert f.attrs["method"] == "isee"
    assert (t["status"] == 0).all() and (t["isee_n"] >= 1).all()
    # whole batches per run, every run between min and max samples, levels in order along the search
    for c in (0, 1):
        lv = runs[runs["case"] == c]
        assert list(lv["level"]) == list(range(len(lv))) and 1 <= len(lv) <= 3
        assert ((lv["samples"] % 6 == 0) & (lv["samples"] >= 12) & (lv["samples"] <= 30)).all()
        assert sorted(set(t["hs"][t["case"] == c])) == sorted(lv["hs"])
    # weights: P̄/N; the estimate from the rows is the stored one
    r0 = runs[0]
    rows = t[(t["case"] == r0["case"]) & (t["level"] == r0["level"])]
    w = np.exp(rows["isee_log_pbar"]) / rows["isee_n"]
    assert np.mean(w * np.isfinite(rows["incident: first slip"])) == pytest.approx(r0["first slip: P"], rel=1e-12)
    # the linear first incident lies between its bounds: the largest single elementary probability and Rice's
    for r_ in runs:
        assert r_["largest elementary P"] <= r_["linear first incident: P hi"]
        assert r_["linear first incident: P lo"] <= r_["rice bound"]
    # the time domain's first slip is the linear model's (beside the guard's margin) in nearly every sample
    agree = np.mean(np.isfinite(t["incident: first slip"]) == (t["lin_first_slip"] == 1))
    assert agree > 0.9
    # limiting Hs: inside its interval, beside the linear model's and the screening's; narrowed to ±limit_width
    # (2 %) unless the level that gets the samples (nearest the accepted P) ran to max_samples
    for L in lim:
        assert L["limiting Hs lo"] <= L["limiting Hs"] <= L["limiting Hs hi"]
        lv = runs[runs["case"] == L["case"]]
        nearest = lv[np.argmin(np.abs(np.log(lv["first slip: P"] / 0.05)))]
        width = max(L["limiting Hs"] / L["limiting Hs lo"], L["limiting Hs hi"] / L["limiting Hs"]) - 1
        assert width <= 0.02 or nearest["samples"] == 30, (width, nearest["samples"])
        assert 0.5 < L["limiting Hs"] / L["linear limiting Hs"] < 2 and math.isfinite(L["screening rayleigh Hs"])
    assert "limiting Hs" in r.stdout and "P(first slip)" in r.stdout


def test_the_store_opens_as_a_dataset_of_samples_runs_and_limits(reference):
    pytest.importorskip("xarray")
    from boatland.campaign import open_store

    _, one, _ = reference
    ds = open_store(one)
    with h5py.File(one, "r") as f:
        t, runs, lim = f["trials"][()], f["stats"][()], f["isee_limits"][()]
    assert ds.attrs["method"] == "isee" and ds.sizes["trial"] == len(t) and ds.sizes["run"] == len(runs)
    assert list(ds.case.values) == list(lim["case"]) and list(ds["run case"].values) == list(runs["case"])
    assert np.array_equal(ds["first slip: P"].values, runs["first slip: P"])
    assert np.array_equal(ds["limiting Hs"].values, lim["limiting Hs"], equal_nan=True)
    assert np.array_equal(ds.isee_log_pbar.values, t["isee_log_pbar"])
    slip = ds.time_to_incident.sel(incident="first slip").values
    assert np.array_equal(slip, t["incident: first slip"], equal_nan=True)


def test_report_and_heaviest_samples(reference):
    camp, one, r = reference
    rep = one.parent / "rep"
    for name in ("isee_runs.csv", "isee_runs.md", "isee_limits.csv", "isee_limits.md", "p_vs_hs.png",
                 "limiting_hs_polar.png"):
        assert (rep / name).stat().st_size > 100, name
    # the report is about the campaign's own incident ([isee] incident: first slip), not the Monte Carlo
    # reports' default (the first slip-distance definition)
    assert (rep / "isee_runs.md").read_text().startswith("# ISEE runs: P(first slip within the access)")
    logs = sorted((one.parent / "one.h5.worst").glob("sample_*.mcap"))
    assert len(logs) == 2
    from boatland.record.reader import read_run_log

    log = read_run_log(logs[0])
    trial = int(logs[0].stem.split("_")[1])
    with h5py.File(one, "r") as f:
        t = f["trials"][()]
    row = t[t["trial"] == trial][0]
    # the log is the whole trial on the sample's sea, with its events
    assert log.complete and abs(log.duration - (20.0 + 14.0 + 10.0 + 20.0)) < 0.06
    assert log.summary["provenance"]["waves"].startswith("GaussianSea ")
    slips = [t for t, _, text in log.events if "stick→slip" in text and t >= 44.0 - 1e-9]
    if np.isfinite(row["incident: first slip"]):
        assert slips and slips[0] - 44.0 == pytest.approx(row["incident: first slip"], abs=1e-9)
    else:
        assert not slips
    assert str(logs[0]) in r.stdout


def test_a_real_dask_cluster_gives_the_same_store(reference, tmp_path, dask_cluster):
    camp, one, _ = reference
    r = run("campaign", camp, "-o", tmp_path / "dask.h5", "--scheduler", dask_cluster)
    assert r.returncode == 0, r.stderr
    same(summaries(one), summaries(tmp_path / "dask.h5"))


def test_resume_after_sigkill_equals_an_uninterrupted_run(reference, tmp_path, sigkill_campaign):
    camp, one, _ = reference
    store = tmp_path / "killed.h5"
    partial = sigkill_campaign(camp, store, kills=3, seed=4, total=len(summaries(one)["trial"]), wait=180.0)
    r = run("campaign", camp, "-o", store, "--workers", "1")
    assert r.returncode == 0, r.stderr
    print("samples on disk after each kill:", partial)
    assert any(0 < n < len(summaries(one)["trial"]) for n in partial), partial
    same(summaries(one), summaries(store))


@pytest.mark.parametrize("old, new, args, expected", [
    ("accept = 0.05", "accept = 2.0", (), "isee.accept"),
    ("levels = 3", 'levels = 3\nincident = "slip > 9 m"', (), "isee.incident"),
    ("levels = 3", "levels = 3\ndirections = 2", (), "isee.directions"),
    ("levels = 3", "levels = 3", ("--method", "monte-carlo"), "seeds"),
    ("accept = 0.05", "", (), "isee.limit_width"),
])
def test_bad_isee_campaigns_are_one_clear_error(tmp_path, old, new, args, expected):
    camp = isee_file(tmp_path)
    camp.write_text(camp.read_text().replace(old, new))
    r = run("campaign", camp, "-o", tmp_path / "x.h5", *args)
    assert r.returncode == 2 and expected in r.stderr and "Traceback" not in r.stderr, r.stderr
    assert not (tmp_path / "x.h5").exists()


def test_save_worst_needs_isee(tmp_path):
    camp = tmp_path / "mc.toml"
    camp.write_text(f'name = "mc"\nscenario = "{BASE}"\nseeds = 2\naccess = 10.0\n')
    r = run("campaign", camp, "-o", tmp_path / "mc.h5", "--save-worst", "3")
    assert r.returncode == 2 and "--save-worst" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.parametrize("method", ["monte-carlo", "isee"])
def test_the_operators_slide_incident_runs_and_is_reported(tmp_path, method):
    """The default scenario's ``slide > 0.5 m within 120 s`` (one operator's criterion) through a Monte Carlo
    and a rare-event campaign, in a beam sea where the fender slides: a column of the store, a share of the
    accesses with a slide (a slide starts with a slip: never more than the first slip's), and its name in the
    report's table and page."""
    name = "slide > 0.5 m within 120 s"
    camp = tmp_path / "slide.toml"
    camp.write_text(f"""
name = "slide"
scenario = "{REPO / 'scenarios' / 'ctv_landing.toml'}"
method = "{method}"
master_seed = 3
access = 150.0
{"seeds = 12" if method == "monte-carlo" else ""}
[set]
"sea.Hs" = 0.8
"sea.Tp" = 7.0
"sea.relative_direction_deg" = 90.0
{'''[isee]
incident = "slide > 0.5 m within 120 s"
batch = 6
min_samples = 12
max_samples = 12''' if method == "isee" else ""}
""")
    r = run("campaign", camp, "-o", tmp_path / "s.h5", "--report", tmp_path / "rep")
    assert r.returncode == 0, r.stderr
    from boatland.campaign.report import read_store

    data = read_store(tmp_path / "s.h5")
    assert name in data["header"]["incidents"].split("\n")
    stats = data["stats"]
    p, onset = float(stats[f"{name}: P"][0]), float(stats["first slip: P"][0])
    assert 0.0 < p <= onset
    page = (tmp_path / "rep" / "report.html").read_text(encoding="utf-8")
    table = (tmp_path / "rep" / ("isee_runs.md" if method == "isee" else "cases.md")).read_text(encoding="utf-8")
    assert name in table and html.escape(name) in page


def test_every_sample_meets_its_own_gusts():
    """A gusty wind in a rare-event campaign: each sample's gusts come from a child stream of its own seed
    (different across samples, the same when drawn again); without gusts the scenario's seed stays."""
    from boatland.campaign.isee import sample_gust_seed, sample_seed
    from boatland.scenario.scenario import load_scenario

    scenario = load_scenario(REPO / "scenarios" / "ctv_landing.toml")
    gusty = scenario.replace({"wind.speed": 10.0, "wind.relative_direction_deg": 90.0})
    steady = gusty.replace({"wind.spectrum": "none"})
    seeds = [sample_gust_seed(gusty, sample_seed(17, 0, 0, k)) for k in range(50)]
    assert len(set(seeds)) == 50 and seeds[3] == sample_gust_seed(gusty, sample_seed(17, 0, 0, 3))
    assert sample_gust_seed(gusty, sample_seed(17, 0, 1, 3)) != seeds[3]
    assert sample_gust_seed(steady, sample_seed(17, 0, 0, 3)) is None
    assert sample_gust_seed(scenario, sample_seed(17, 0, 0, 3)) is None
