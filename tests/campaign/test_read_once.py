"""A campaign reads its inputs once: its scenario, campaign file and database are read, hashed and run from
those bytes, so a store never holds results of other inputs than its digest records — even when the scenario
and the database are edited while the campaign starts — and a resume after an edit names the file that
changed. Real processes and files; the edits race the campaign's start."""

import json
import os
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
SCENARIO = REPO / "scenarios" / "ctv_landing.toml"
DATABASE = REPO / "boatland" / "data" / "ctv27.h5"
PUSH = {"a": "150.0e3", "b": "60.0e3"}


def versions(tmp):
    """Two versions of the scenario (push 150 / 60 kN) and of its database (the same data, one more note in
    the file), each ready to be swapped in atomically; the campaign file over them."""
    text = SCENARIO.read_text(encoding="utf-8")
    for v, push in PUSH.items():
        t = text.replace('database = "ctv27"', f'database = "{tmp / "db.h5"}"').replace("force = 150.0e3", f"force = {push}")
        (tmp / f"scenario_{v}.toml").write_text(t, encoding="utf-8")
        shutil.copyfile(DATABASE, tmp / f"db_{v}.h5")
    with h5py.File(tmp / "db_b.h5", "a") as f:
        f.attrs["note"] = "edited"
    camp = tmp / "camp.toml"
    camp.write_text('name = "race"\nscenario = "landing.toml"\nseeds = 2\nmaster_seed = 3\naccess = 10.0\n'
                    '[set]\n"radiation.method" = "state_space"\n[axes]\n"sea.Hs" = [0.5, 1.2]\n'
                    '[incidents]\nslip_distance = [0.05]\n', encoding="utf-8")
    return camp


def use(tmp, scenario, db):
    for src, dst in ((f"scenario_{scenario}.toml", "landing.toml"), (f"db_{db}.h5", "db.h5")):
        shutil.copyfile(tmp / src, tmp / f".{dst}.new")
        os.replace(tmp / f".{dst}.new", tmp / dst)


def campaign(camp, store):
    return subprocess.run([sys.executable, "-m", "boatland", "campaign", str(camp), "-o", str(store), "--workers", "2"],
                          capture_output=True, text=True, timeout=600, cwd=camp.parent,
                          env={**os.environ, "PYTHONPATH": str(REPO)})


def rows(store):
    with h5py.File(store, "r") as f:
        t, attrs = f["trials"][()], dict(f.attrs)
    return {n: t[n] for n in t.dtype.names if n != "wall_time"}, json.loads(attrs["input_digests"])


@pytest.mark.slow
def test_a_store_holds_the_inputs_its_digest_records_however_they_are_edited(tmp_path):
    camp = versions(tmp_path)
    clean = {}
    for v in PUSH:                                   # what each version gives, undisturbed
        use(tmp_path, v, v)
        assert campaign(camp, tmp_path / f"clean_{v}.h5").returncode == 0
        clean[v] = rows(tmp_path / f"clean_{v}.h5")
    assert not np.array_equal(clean["a"][0]["max_normal_force"], clean["b"][0]["max_normal_force"])
    assert clean["a"][1][str(tmp_path / "db.h5")] != clean["b"][1][str(tmp_path / "db.h5")]
    outcomes = []
    for attempt in range(6):
        store = tmp_path / f"raced_{attempt}.h5"
        use(tmp_path, "a", "a")
        stop = threading.Event()

        def edit(k=attempt):                          # swap both files back and forth while the campaign starts
            rng = np.random.default_rng(k)
            until = time.monotonic() + rng.uniform(0.2, 3.0)   # for part of its start, or all of it
            while not stop.is_set() and time.monotonic() < until:
                use(tmp_path, *rng.choice(["a", "b"], 2))
                time.sleep(rng.uniform(0.005, 0.05))
        editor = threading.Thread(target=edit)
        editor.start()
        try:
            r = campaign(camp, store)
        finally:
            stop.set()
            editor.join()
        if r.returncode == 2:                         # it saw a file change under it: nothing ran
            assert "changed while the campaign was reading its inputs" in r.stderr, r.stderr
            assert not store.exists() or "trials" not in h5py.File(store, "r")
            outcomes.append("refused")
            continue
        assert r.returncode == 0, r.stderr
        got, digests = rows(store)
        (v,) = [v for v in PUSH if digests == clean[v][1] or
                digests[f"scenario {tmp_path / 'landing.toml'}"] == clean[v][1][f"scenario {tmp_path / 'landing.toml'}"]]
        for name in got:                              # every trial ran the scenario version the digest names
            a, b = got[name], clean[v][0][name]
            assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), name
        outcomes.append(v)
    print("outcomes:", outcomes)
    assert set(outcomes) - {"refused"}, "no raced campaign ran: the check above saw nothing"
    # a resume after an edit names what changed
    use(tmp_path, "a", "a")
    store = tmp_path / "resume.h5"
    assert campaign(camp, store).returncode == 0
    use(tmp_path, "b", "a")
    r = campaign(camp, store)
    assert r.returncode == 2 and f"before scenario {tmp_path / 'landing.toml'} changed" in r.stderr, r.stderr
    use(tmp_path, "a", "b")
    r = campaign(camp, store)
    assert r.returncode == 2 and f"before {tmp_path / 'db.h5'} changed" in r.stderr, r.stderr
