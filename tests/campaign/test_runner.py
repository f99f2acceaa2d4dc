"""Campaigns end to end: the same store from 1 or 2 local workers and from a real Dask cluster; resume
after SIGKILL; bad input. Real processes throughout (boatland CLI, dask scheduler and workers)."""

import subprocess
import sys
import time
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
BASE = REPO / "scenarios" / "ctv_landing.toml"


def campaign_file(tmp_path, name="mini", seeds=3, duration=40.0, method="state_space", extra=""):
    path = tmp_path / f"{name}.toml"
    path.write_text(f"""
name = "{name}"
scenario = "{BASE}"
seeds = {seeds}
master_seed = 11
access = {duration}
[set]
"radiation.method" = "{method}"
[axes]
"sea.Hs" = [0.3, 0.8]
"sea.relative_direction_deg" = [180.0, 90.0]
[incidents]
slip_distance = [0.05]
slide_within = [{{distance = 0.05, window = 20.0}}]
{extra}
""")
    return path


def run(*args, timeout=600, env=None):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, env=env)


#: The ``dask`` command of this Python's environment (on PATH or not).


def summaries(store):
    """The trial rows without the wall time (the only column that is not reproducible)."""
    with h5py.File(store, "r") as f:
        t = f["trials"][()]
        stats = f["stats"][()]
    cols = {n: t[n] for n in t.dtype.names if n != "wall_time"}
    cols.update({f"stats/{n}": stats[n] for n in stats.dtype.names})
    return cols


def same(a, b):
    assert a.keys() == b.keys()
    for name in a:
        x, y = a[name], b[name]
        assert x.dtype == y.dtype and x.shape == y.shape, name
        assert x.tobytes() == y.tobytes(), name      # bit for bit (NaN included)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("ref")
    camp = campaign_file(tmp)
    r = run("campaign", camp, "-o", tmp / "one.h5", "--workers", "1")
    assert r.returncode == 0, r.stderr
    return camp, tmp / "one.h5"


@pytest.mark.slow
def test_one_and_two_local_workers_give_the_same_store(reference, tmp_path):
    camp, one = reference
    r = run("campaign", camp, "-o", tmp_path / "two.h5", "--workers", "2")
    assert r.returncode == 0, r.stderr
    same(summaries(one), summaries(tmp_path / "two.h5"))
    rows = summaries(one)
    assert len(rows["trial"]) == 12 and sorted(rows["trial"]) == list(range(12)) and (rows["status"] == 0).all()
    assert len(set(rows["seed"])) == 3                           # common seeds across the 4 cases


@pytest.mark.slow
def test_blas_thread_counts_give_the_same_store(reference, tmp_path):
    """OPENBLAS_NUM_THREADS (and OMP_NUM_THREADS) 4 with two workers: the same store as 1 worker with the
    machine's default — every trial pins BLAS to one thread (boatland.reproducible)."""
    camp, one = reference
    env = {**__import__("os").environ, "OPENBLAS_NUM_THREADS": "4", "OMP_NUM_THREADS": "4"}
    r = run("campaign", camp, "-o", tmp_path / "four.h5", "--workers", "2", env=env)
    assert r.returncode == 0, r.stderr
    same(summaries(one), summaries(tmp_path / "four.h5"))


@pytest.mark.slow
def test_a_real_dask_cluster_gives_the_same_store(reference, tmp_path, dask_cluster):
    camp, one = reference
    r = run("campaign", camp, "-o", tmp_path / "dask.h5", "--scheduler", dask_cluster)
    assert r.returncode == 0, r.stderr
    same(summaries(one), summaries(tmp_path / "dask.h5"))


@pytest.mark.slow
def test_a_lost_dask_worker_costs_no_trial(reference, tmp_path, dask_cluster):
    """One of the two Dask worker processes SIGKILLed mid-campaign (its nanny starts another), five times: every
    campaign finishes without a word of the loss, and its store equals the uninterrupted one bit for bit."""
    import os
    import signal

    from distributed import Client

    camp, one = reference
    rng = np.random.default_rng(7)
    with Client(dask_cluster, timeout=30, set_as_default=False) as client:
        for k in range(5):
            store = tmp_path / f"lost_{k}.h5"
            journal = store.with_name(store.name + ".journal")
            p = subprocess.Popen([sys.executable, "-m", "boatland", "campaign", str(camp), "-o", str(store),
                                  "--scheduler", dask_cluster], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            target = int(rng.integers(1, 7))              # trials on disk before the kill
            deadline = time.monotonic() + 120
            while p.poll() is None and time.monotonic() < deadline and \
                    (sum(1 for _ in open(journal)) if journal.exists() else 0) < target:
                time.sleep(0.01)
            pids = sorted(client.run(os.getpid).values())         # the worker processes (not their nannies)
            killed = p.poll() is None
            if killed:
                os.kill(pids[int(rng.integers(len(pids)))], signal.SIGKILL)
            out, err = p.communicate(timeout=600)
            assert p.returncode == 0 and "Traceback" not in err, err
            same(summaries(one), summaries(store))
            assert killed, "the campaign ended before the kill: nothing was tested"
            deadline = time.monotonic() + 60                # the nanny's new worker joins before the next round
            while len(client.scheduler_info()["workers"]) < 2 and time.monotonic() < deadline:
                time.sleep(0.2)


@pytest.mark.slow
def test_unreachable_scheduler_is_a_clear_error(reference, unused_port):
    camp, _ = reference
    t0 = time.monotonic()
    r = run("campaign", camp, "-o", Path(camp).with_suffix(".x.h5"), "--scheduler", f"tcp://127.0.0.1:{unused_port}")
    assert r.returncode == 2 and "no Dask scheduler answered" in r.stderr and "Traceback" not in r.stderr
    assert time.monotonic() - t0 < 60


@pytest.mark.slow
def test_resume_after_sigkill_equals_an_uninterrupted_run(tmp_path, sigkill_campaign):
    """Killed with SIGKILL at random moments, then run to the end: the same store as one uninterrupted
    run, bit for bit in the summaries, every trial once."""
    camp = campaign_file(tmp_path, name="killed", seeds=4, duration=1200.0, method="state_space")
    clean = tmp_path / "clean.h5"
    assert run("campaign", camp, "-o", clean, "--workers", "1").returncode == 0
    store = tmp_path / "killed.h5"
    partial = sigkill_campaign(camp, store, kills=4, seed=3, total=16)
    r = run("campaign", camp, "-o", store, "--workers", "1")
    assert r.returncode == 0, r.stderr
    print("trials on disk after each kill:", partial)
    assert any(0 < n < 16 for n in partial), partial          # at least one kill landed mid-campaign
    same(summaries(clean), summaries(store))
    assert not store.with_name(store.name + ".journal").exists()


@pytest.mark.slow
def test_a_store_of_another_campaign_is_refused(reference, tmp_path):
    _, one = reference
    other = campaign_file(tmp_path, name="other", seeds=2)
    r = run("campaign", other, "-o", one)
    assert r.returncode == 2 and "different campaign" in r.stderr and "refusing to mix" in r.stderr


@pytest.mark.parametrize("extra, expected", [
    ('[axes]\n"sea.Hss" = [1.0]', "axes.sea.Hss: unknown key (did you mean 'Hs'?)"),
    ('[axes]\n"sea.Tp" = []', "axes.sea.Tp: must be a non-empty list"),
    ('seedz = 3', "seedz: unknown key"),
])
def test_bad_campaign_files_are_one_clear_error(tmp_path, extra, expected):
    path = tmp_path / "bad.toml"
    text = campaign_file(tmp_path).read_text()
    if extra.startswith("[axes]"):
        text = text.replace('[axes]\n', extra + "\n", 1)
    else:
        text = extra + "\n" + text
    path.write_text(text)
    r = run("campaign", path, "-o", tmp_path / "bad.h5")
    assert r.returncode == 2 and expected in r.stderr and "Traceback" not in r.stderr, r.stderr


def test_a_campaign_the_checks_refuse_stops_the_background_work_started_before_them(tmp_path):
    """The CLI starts the pile's tables and the frequency-domain screening before its checks (issue 16: on
    the core they leave idle); when a case fails them the user sees what a refused campaign always gave —
    one clear line, exit 2 — and no process of the campaign is left (the CLI stops the background
    process; it would also die with its parent, PR_SET_PDEATHSIG)."""
    path = campaign_file(tmp_path, name="refused_by_checks", seeds=2)
    path.write_text(path.read_text().replace("[axes]\n", '[axes]\n"simulation.dt" = [0.05, 0.5]\n', 1))
    r = run("campaign", path, "-o", tmp_path / "refused.h5", "--workers", "2", timeout=120)
    assert r.returncode == 2 and "simulation.dt" in r.stderr and "too large" in r.stderr, r.stderr
    assert "Traceback" not in r.stderr
    left = subprocess.run(["pgrep", "-f", str(path)], capture_output=True, text=True)
    assert left.stdout.strip() == "", left.stdout


@pytest.mark.slow
def test_report_writes_tables_and_figures(reference, tmp_path):
    _, one = reference
    r = run("report", one, "-o", tmp_path / "rep", "--target", "0.5")
    assert r.returncode == 0, r.stderr
    names = {p.name for p in (tmp_path / "rep").iterdir()}
    assert {"cases.csv", "cases.md", "limiting_hs.csv", "p_vs_hs.png", "limiting_hs_polar.png",
            "time_to_incident.png"} <= names
    header = (tmp_path / "rep" / "cases.csv").read_text().splitlines()[0]
    assert "slip > 0.05 m: P lo" in header and "first slip: mean time [s]" in header
    assert "screening: P(first slip) (frequency domain)" in header      # Grøtting 2015 Tables 4.14–4.15 side by side


@pytest.mark.slow
def test_an_unwritable_store_fails_before_any_trial(reference, tmp_path):
    camp, _ = reference
    blocker = tmp_path / "a_file"
    blocker.write_text("not a folder")
    r = run("campaign", camp, "-o", blocker / "store.h5")
    assert r.returncode == 2 and f"-o {blocker / 'store.h5'}: {blocker} is a file, not a folder" in r.stderr
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1


SLIDE = "slide > 0.05 m within 20 s"


@pytest.mark.slow
def test_a_slide_incident_is_counted_and_reported(reference, tmp_path):
    """The campaign's ``slide_within`` is a column of the store like every incident: a slide comes with (or
    after) a first slip, and the report's table names it."""
    _, store = reference
    from boatland.campaign.report import read_store

    data = read_store(store)
    t, stats, names = data["trials"], data["stats"], data["header"]["incidents"].split("\n")
    assert SLIDE in names and f"{SLIDE}: count" in stats.dtype.names
    slide, slip = t[f"incident: {SLIDE}"], t["incident: first slip"]
    assert np.isfinite(slide).any() and not np.isfinite(slide).all()     # the sweep sees slides and trials without
    assert np.all(np.isfinite(slip[np.isfinite(slide)])) and np.all(slip[np.isfinite(slide)] <= slide[np.isfinite(slide)])
    assert stats[f"{SLIDE}: count"].sum() == np.isfinite(slide).sum() <= np.isfinite(slip).sum()
    r = run("report", store, "-o", tmp_path / "rep", "--incident", SLIDE)
    assert r.returncode == 0, r.stderr
    assert f"P({SLIDE} within the access)" in r.stdout
