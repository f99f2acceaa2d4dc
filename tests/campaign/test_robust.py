"""Issue 14 for campaigns: failed trials are reported and left out; one writer per store; workers die
with the campaign; BLAS threads do not change results. Real processes throughout."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
DECAY = REPO / "scenarios" / "ctv_free_decay.toml"
ENV = {**os.environ, "PYTHONPATH": str(REPO)}


def run(*args, env=None, timeout=600):
    return subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, env=env or ENV)


def blowup_campaign(tmp_path):
    path = tmp_path / "blowup.toml"
    path.write_text(f'name = "blowup"\nscenario = "{DECAY}"\nseeds = 2\naccess = 20.0\n[axes]\n'
                    '"initial.velocity" = [[0.0, 0.0, 0.0], [40.0, 0.0, 0.0]]\n')
    return path


@pytest.mark.slow
def test_a_blown_up_trial_is_reported_failed_and_left_out_of_p(tmp_path):
    camp = blowup_campaign(tmp_path)
    r = run("campaign", camp, "-o", tmp_path / "b.h5", "--workers", "1")
    assert r.returncode == 1, r.stderr
    assert "case 1 (initial.velocity=[40.0, 0.0, 0.0]): 2 of 2 trials failed" in r.stderr
    assert "runaway" in r.stderr and "2 of 4 trials failed" in r.stderr and "Traceback" not in r.stderr
    with h5py.File(tmp_path / "b.h5") as f:
        stats, trials = f["stats"][()], f["trials"][()]
    assert list(trials["status"]) == [0, 0, 2, 2]
    assert list(stats["failed"]) == [0, 2] and list(stats["trials"]) == [2, 2]
    assert stats["first slip: P"][0] == 0.0 and np.isnan(stats["first slip: P"][1])   # no valid trial: no P
    r = run("campaign", camp, "-o", tmp_path / "b.h5", "--allow-failures")             # resumed: nothing to run
    assert r.returncode == 0 and "2 failed" in r.stdout, r.stderr


def long_campaign(tmp_path, name="long", seeds=60):
    path = tmp_path / f"{name}.toml"
    path.write_text(f'name = "{name}"\nscenario = "{DECAY}"\nseeds = {seeds}\naccess = 600.0\n[axes]\n'
                    '"initial.displacement" = [[0.0, 0.0, 0.3], [0.0, 0.0, 0.2]]\n')
    return path


def _wait_for(pred, timeout=120):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if pred():
            return True
        time.sleep(0.05)
    return False


def _children(pid):
    out = []
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                if int((d / "stat").read_text().rsplit(")", 1)[1].split()[1]) == pid:
                    out.append(int(d.name))
            except (OSError, ValueError, IndexError):
                pass
    return out


def _alive(pid):
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
        return state != "Z"
    except OSError:
        return False


@pytest.mark.slow
def test_a_second_campaign_on_the_store_is_refused_and_the_first_finishes_intact(tmp_path):
    camp = long_campaign(tmp_path)
    store = tmp_path / "s.h5"
    first = subprocess.Popen([sys.executable, "-m", "boatland", "campaign", str(camp), "-o", str(store),
                              "--workers", "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=ENV)
    assert _wait_for(lambda: store.with_name("s.h5.lock").exists())
    second = run("campaign", camp, "-o", store, "--workers", "1")
    assert second.returncode == 2 and "another boatland campaign (pid" in second.stderr, second.stderr
    assert len(second.stderr.strip().splitlines()) == 1
    out, err = first.communicate(timeout=600)
    assert first.returncode == 0, err
    with h5py.File(store) as f:
        assert sorted(f["trials"]["trial"]) == list(range(120)) and len(f["stats"]) == 2
    assert not store.with_name("s.h5.lock").exists() and not store.with_name("s.h5.journal").exists()


@pytest.mark.slow
def test_a_lock_left_by_a_killed_campaign_does_not_block(tmp_path):
    camp = long_campaign(tmp_path, "stale")
    store = tmp_path / "t.h5"
    p = subprocess.Popen([sys.executable, "-m", "boatland", "campaign", str(camp), "-o", str(store),
                          "--workers", "1"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENV)
    assert _wait_for(lambda: store.with_name("t.h5.lock").exists())
    p.kill()
    p.wait()
    assert store.with_name("t.h5.lock").exists()                # left behind, its holder dead
    (tmp_path / ".t.h5.abc123.part").write_bytes(b"half a store")  # what a kill during a rewrite leaves
    r = run("campaign", camp, "-o", store, "--workers", "1")
    assert r.returncode == 0, r.stderr
    assert not list(tmp_path.glob(".t.h5.*.part"))


@pytest.mark.slow
@pytest.mark.parametrize("sig", [signal.SIGKILL, signal.SIGTERM])
def test_local_workers_die_with_the_campaign(tmp_path, sig):
    camp = long_campaign(tmp_path, f"orphans{int(sig)}")
    p = subprocess.Popen([sys.executable, "-m", "boatland", "campaign", str(camp), "-o", str(tmp_path / "o.h5"),
                          "--workers", "2"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENV)
    assert _wait_for(lambda: len([c for c in _children(p.pid) if _alive(c)]) >= 2)
    time.sleep(1.0)
    workers = [c for c in _children(p.pid) if _alive(c)]
    p.send_signal(sig)
    p.wait()
    assert _wait_for(lambda: not any(_alive(w) for w in workers), timeout=10), \
        [w for w in workers if _alive(w)]


def _trial_bits(tmp_path, name, threads):
    out = tmp_path / f"{name}.h5"
    env = {**ENV, "OPENBLAS_NUM_THREADS": str(threads), "OMP_NUM_THREADS": str(threads),
           "MKL_NUM_THREADS": str(threads)}
    r = run("run", REPO / "scenarios" / "ctv_landing.toml", "--duration", "60", "--seed", "7", "-o", out,
            "--no-log", "--json", env=env)
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        arrays = {}
        f.visititems(lambda k, v: arrays.__setitem__(k, v[()]) if isinstance(v, h5py.Dataset) else None)
    return arrays


@pytest.mark.slow
def test_blas_threads_do_not_change_a_trial_bit_for_bit(tmp_path):
    one = _trial_bits(tmp_path, "one", 1)
    four = _trial_bits(tmp_path, "four", 4)
    assert one.keys() == four.keys() and len(one) > 5
    for k in one:
        if "wall" in k:
            continue
        a, b = np.asarray(one[k]), np.asarray(four[k])
        if a.dtype.kind == "O":                      # strings (dimension labels): compared as text
            assert a.tolist() == b.tolist(), k
        else:
            assert a.tobytes() == b.tobytes(), k


def test_pinning_makes_a_thread_sensitive_computation_reproducible():
    """On this machine an SVD of a 267 × 134 matrix differs in its last bits between 1 and 8 OpenBLAS
    threads; inside single_threaded() it is the same whatever the process's thread count."""
    from threadpoolctl import threadpool_limits

    from boatland.reproducible import single_threaded

    H = np.random.default_rng(0).standard_normal((267, 134))
    results = []
    for n in (1, 8):
        with threadpool_limits(limits=n):
            with single_threaded():
                results.append(np.linalg.svd(H)[2].tobytes())
    assert results[0] == results[1]


def test_pinning_scans_the_libraries_again_after_an_import(tmp_path, monkeypatch):
    """The loaded libraries are found once and again after any import (a new BLAS or OpenMP runtime
    comes with one): every pool is at one thread inside, back to its limit after."""
    from threadpoolctl import threadpool_info

    import boatland.reproducible as rep

    before = [p["num_threads"] for p in threadpool_info()]
    with rep.single_threaded():
        assert all(p["num_threads"] == 1 for p in threadpool_info())
    first = rep._controller()
    assert rep._controller() is first                       # nothing imported since: no new scan
    (tmp_path / "freshly_imported_module.py").write_text("X = 1\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    __import__("freshly_imported_module")
    assert rep._controller() is not first
    with rep.single_threaded():
        assert all(p["num_threads"] == 1 for p in threadpool_info())
    assert [p["num_threads"] for p in threadpool_info()] == before


@pytest.fixture
def small_disk(tmp_path):
    """A real 1 MiB filesystem (tmpfs; needs root), nearly full."""
    mnt = tmp_path / "disk"
    mnt.mkdir()
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(mnt)], capture_output=True).returncode:
        pytest.skip("cannot mount a small tmpfs here (needs root)")
    try:
        (mnt / "filler").write_bytes(b"\0" * (1024 * 1024 - 40 * 1024))
        yield mnt
    finally:
        subprocess.run(["umount", "-l", str(mnt)], capture_output=True)


@pytest.mark.slow
def test_a_full_disk_stops_the_campaign_with_one_line_and_keeps_what_is_stored(tmp_path, small_disk):
    camp = long_campaign(tmp_path, "full", seeds=100)
    store = small_disk / "f.h5"
    t0 = time.monotonic()
    r = run("campaign", camp, "-o", store, "--workers", "2")
    assert r.returncode == 2 and "Traceback" not in r.stderr, r.stderr
    lines = [ln for ln in r.stderr.splitlines() if ln.startswith("boatland: error:")]
    assert len(lines) == 1 and str(store) in lines[0] and "run the same command again" in lines[0], r.stderr
    journal = store.with_name("f.h5.journal")
    kept = sum(1 for _ in open(journal)) if journal.exists() else 0
    assert 0 < kept < 200, kept                                # stopped early, what finished is on disk
    assert not list(small_disk.glob(".f.h5.*.part"))
    print(f"stopped after {time.monotonic() - t0:.1f} s with {kept} trials in the journal")
