"""The disk cache (boatland.diskcache): results read back are the bits computed; anything odd is a miss."""

from __future__ import annotations

import os
import subprocess
import sys

import h5py
import numpy as np
import pytest

from boatland import diskcache
from boatland.irf.impulse import IRFSettings


@pytest.fixture()
def cache(tmp_path, monkeypatch):
    folder = tmp_path / "cache"
    monkeypatch.setenv(diskcache.ENV, str(folder))
    return folder


def _memory(box_db):
    from boatland.vessel.radiation import radiation_memory

    return radiation_memory(box_db, IRFSettings(t_max=20.0, dt=0.05))


def _same_memory(a, b):
    for name in ("K", "t", "A_inf", "ogilvie_spread", "err_B", "err_A", "truncation", "significant"):
        assert getattr(a.irf, name).tobytes() == getattr(b.irf, name).tobytes(), name
    assert a.irf.settings == b.irf.settings and a.irf.notes == b.irf.notes
    assert a.state_space.pairs.keys() == b.state_space.pairs.keys()
    for k, f in a.state_space.pairs.items():
        g = b.state_space.pairs[k]
        assert (f.A.tobytes(), f.B.tobytes(), f.C.tobytes(), f.r2) == (g.A.tobytes(), g.B.tobytes(), g.C.tobytes(), g.r2)
    assert a.state_space.passivity.tobytes() == b.state_space.passivity.tobytes()


def _no_compute(monkeypatch):
    import boatland.vessel.radiation as rad

    def refuse(*a, **k):
        raise AssertionError("computed although the cache holds it")

    monkeypatch.setattr(rad, "compute_irf", refuse)


def test_memory_read_back_is_the_computed_one(box_db, cache, monkeypatch):
    monkeypatch.setenv(diskcache.ENV, "off")
    fresh = _memory(box_db)
    assert diskcache.cache_dir() is None and not cache.exists()
    monkeypatch.setenv(diskcache.ENV, str(cache))
    first = _memory(box_db)                          # a miss: computed and stored
    entries = list(cache.glob("radiation-*.h5"))
    assert len(entries) == 1
    _no_compute(monkeypatch)
    second = _memory(box_db)                         # a hit
    _same_memory(fresh, first)
    _same_memory(fresh, second)


def test_other_settings_are_another_entry(box_db, cache):
    from boatland.vessel.radiation import radiation_memory

    _memory(box_db)
    radiation_memory(box_db, IRFSettings(t_max=25.0, dt=0.05))
    assert len(list(cache.glob("radiation-*.h5"))) == 2


@pytest.mark.parametrize("damage", ["truncated", "foreign key", "not hdf5", "empty"])
def test_damaged_entry_is_a_miss_and_rewritten(box_db, cache, damage):
    good = _memory(box_db)
    (entry,) = cache.glob("radiation-*.h5")
    if damage == "truncated":
        data = entry.read_bytes()
        entry.write_bytes(data[: len(data) // 2])
    elif damage == "foreign key":
        with h5py.File(entry, "r+") as f:
            f.attrs["boatland_cache_key"] = "radiation-someone-else"
    elif damage == "not hdf5":
        entry.write_text("not an entry\n")
    else:
        entry.write_bytes(b"")
    again = _memory(box_db)
    _same_memory(good, again)
    with h5py.File(entry, "r") as f:                # rewritten whole
        assert f.attrs["boatland_cache_key"] == entry.stem


def test_fifo_and_symlink_entries_are_misses_and_never_followed(box_db, cache, tmp_path):
    good = _memory(box_db)
    (entry,) = cache.glob("radiation-*.h5")
    entry.unlink()
    os.mkfifo(entry)                                  # reading it would block: it must not be opened
    _same_memory(good, _memory(box_db))
    assert entry.is_file() and not entry.is_symlink()
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me\n")
    entry.unlink()
    entry.symlink_to(victim)
    _same_memory(good, _memory(box_db))
    assert victim.read_text() == "keep me\n"          # the symlink was replaced, not written through
    assert entry.is_file() and not entry.is_symlink()


def test_off_and_unusable_folders_compute_without_a_word(box_db, tmp_path, monkeypatch):
    for value in ("", "off", "NONE"):
        monkeypatch.setenv(diskcache.ENV, value)
        assert diskcache.cache_dir() is None
    blocker = tmp_path / "a_file"
    blocker.write_text("x")
    monkeypatch.setenv(diskcache.ENV, str(blocker / "cache"))   # cannot be made: no cache
    assert diskcache.cache_dir() is None
    assert _memory(box_db).state_space is not None


def test_key_names_content_code_and_machine():
    a = np.arange(6.0)
    k = diskcache.cache_key("x", (a, 1.0, "s"), ("boatland.atomic",))
    assert k == diskcache.cache_key("x", (a.copy(), 1.0, "s"), ("boatland.atomic",))
    b = a.copy()
    b[3] = np.nextafter(b[3], 10)
    assert k != diskcache.cache_key("x", (b, 1.0, "s"), ("boatland.atomic",))
    assert k != diskcache.cache_key("x", (a.astype(np.float32), 1.0, "s"), ("boatland.atomic",))
    assert k != diskcache.cache_key("x", (a, 1.0, "s"), ("boatland.atomic", "boatland.rk4"))
    assert k != diskcache.cache_key("y", (a, 1.0, "s"), ("boatland.atomic",))


def test_the_folder_is_kept_below_its_size(cache, monkeypatch):
    def write(f, v):
        f["v"] = v

    for i in range(6):
        diskcache.store(f"t-{i}", np.zeros(20_000), write)       # ~160 kB each
        os.utime(cache / f"t-{i}.h5", (1e9 + i, 1e9 + i))
    monkeypatch.setattr(diskcache, "MAX_BYTES", 500_000)
    diskcache.store("t-new", np.zeros(20_000), write)
    left = sorted(p.stem for p in cache.glob("*.h5"))
    assert "t-new" in left and "t-0" not in left and "t-5" in left
    assert sum(p.stat().st_size for p in cache.glob("*.h5")) <= 500_000


def test_pile_tables_read_back_from_disk(cache, monkeypatch):
    from boatland.hydro.builtin import load_builtin
    import boatland.sea.pile as pile

    db = load_builtin("ctv24")
    args = (db, (-20.0, 0.0), 0.0, 3.25, np.array([np.pi, 0.75 * np.pi]))
    made = pile.scattered_tables(*args)
    assert len(list(cache.glob("pile-table-*.h5"))) == 2
    monkeypatch.setattr(pile, "_TABLES", {})                       # a new process: nothing in memory

    def refuse(*a, **k):
        raise AssertionError("computed although the cache holds it")

    monkeypatch.setattr(pile, "_scattered_columns", refuse)
    again = pile.scattered_tables(*args)
    for a, b in zip(made, again):
        assert a.key == b.key and a.d == b.d
        assert a.grid.tobytes() == b.grid.tobytes() and a.reduced.tobytes() == b.reduced.tobytes()


WRITER = r"""
import sys, numpy as np
from boatland import diskcache
def write(f, v):
    f["v"] = v
for i in range(40):
    diskcache.store("shared", np.full(50_000, float(sys.argv[1])), write)
"""


def test_concurrent_writers_leave_whole_entries(cache):
    """Two processes store the same entry 40 times each while this one reads it: every read is a whole
    entry of one writer or a miss, never half a file."""
    env = dict(os.environ, **{diskcache.ENV: str(cache)})
    procs = [subprocess.Popen([sys.executable, "-c", WRITER, str(v)], env=env) for v in (1.0, 2.0)]
    seen = set()
    while any(p.poll() is None for p in procs):
        v = diskcache.lookup("shared", lambda f: f["v"][()])
        if v is not None:
            assert v.size == 50_000 and np.unique(v).size == 1
            seen.add(float(v[0]))
    assert all(p.wait() == 0 for p in procs)
    final = diskcache.lookup("shared", lambda f: f["v"][()])
    assert final is not None and float(final[0]) in (1.0, 2.0)
    assert not list(cache.glob(".*.part"))
