"""A log whose writer died: recovered up to its last complete block (≤ 1 s of simulated time lost)."""

import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.record.reader import read_run_log


def _chunks(path):
    from mcap.reader import make_reader

    with open(path, "rb") as f:
        return make_reader(f).get_summary().chunk_indexes


def _epoch(path) -> int:
    """Log time of t = 0 [ns] (the run's wall-clock start, metadata ``start_time_ns``)."""
    from mcap.reader import make_reader

    with open(path, "rb") as f:
        return int(next(m.metadata for m in make_reader(f).iter_metadata() if m.name == "boatland.run")["start_time_ns"])


def _chunk_ends(path) -> list[int]:
    """Byte offsets where each block (chunk + its message indexes) ends, from the finished file's index."""
    return [ci.chunk_start_offset + ci.chunk_length + ci.message_index_length for ci in _chunks(path)]


@pytest.mark.parametrize("where", ["at a block boundary", "inside a block"])
def test_a_cut_file_keeps_every_complete_block(recorded, tmp_path, where):
    data = recorded.mcap.read_bytes()
    ends = _chunk_ends(recorded.mcap)
    chunks = _chunks(recorded.mcap)
    # keep the blocks up to 25 s of the 60 s run (a block is 1 s, or several when the logger caught up)
    epoch = _epoch(recorded.mcap)
    k = next(i for i, c in enumerate(chunks) if c.message_end_time - epoch >= 24.9e9) + 1
    cut = ends[k - 1] if where == "at a block boundary" else (ends[k - 1] + ends[k]) // 2
    bad = tmp_path / "cut.mcap"
    bad.write_bytes(data[:cut])
    log = read_run_log(bad)
    r = recorded.result
    n = int(round((chunks[k - 1].message_end_time - epoch) / 1e9 / 0.05)) + 1
    assert not log.complete and len(log.columns) == n
    np.testing.assert_array_equal(log.columns.t, r.t[:n])
    np.testing.assert_array_equal(log.columns.x[:, :3], r.x[:n, :3])
    np.testing.assert_array_max_ulp(log.columns.x[:, 3:], r.x[:n, 3:], maxulp=1)   # logged in degrees
    np.testing.assert_array_equal(log.columns.fn, r.fn[:n])
    assert "truncated log" in log.notes[0] and f"{r.t[n - 1]:.2f}" in log.notes[0] and "60 s" in log.notes[0]
    assert log.summary is None


@pytest.mark.parametrize("chunk", [0, 1], ids=["in the start chunk (schemas, scene)", "in the first block"])
def test_a_file_cut_before_the_first_block_is_an_input_error(recorded, tmp_path, chunk):
    bad = tmp_path / "head.mcap"
    bad.write_bytes(recorded.mcap.read_bytes()[:_chunks(recorded.mcap)[chunk].chunk_start_offset + 100])
    with pytest.raises(BoatlandInputError, match="nothing to recover"):
        read_run_log(bad)


@pytest.mark.slow
def test_sigkill_mid_run_leaves_a_recoverable_log(tmp_path):
    """A real run (1 h simulated, several seconds of wall time) killed with SIGKILL once its log is growing."""
    log = tmp_path / "killed.mcap"
    proc = subprocess.Popen([sys.executable, "-m", "boatland", "run", "--duration", "3600", "--log", str(log),
                             "--json"], cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and (not log.exists() or log.stat().st_size < 1_000_000):
            time.sleep(0.02)
        assert log.exists() and proc.poll() is None, "the run ended before it could be killed"
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    assert proc.returncode == -signal.SIGKILL
    size = log.stat().st_size
    rec = read_run_log(log)
    c = rec.columns
    assert not rec.complete and len(c) >= 20 and rec.planned_duration == 3600.0
    np.testing.assert_allclose(np.diff(c.t), 0.05, atol=1e-9)           # every step from t = 0, none missing
    assert c.t[0] == 0.0 and len(c) % 20 == 0                           # whole blocks of 1 s
    # what is lost relative to the bytes on disk: at most the one block being written when killed
    blocks_on_disk = _count_chunk_starts(log) - 1                       # the first chunk: schemas and scene
    assert blocks_on_disk - len(c) // 20 <= 1, (blocks_on_disk, len(c))
    assert f"{c.t[-1]:.2f}" in rec.notes[0] and size > 0


def _count_chunk_starts(path) -> int:
    """Chunk records whose start is in the file (complete or not), counted by walking the records."""
    import struct

    data = path.read_bytes()
    pos, n = 8, 0
    while pos + 9 <= len(data):
        op, length = struct.unpack_from("<BQ", data, pos)
        if op == 0x06:
            n += 1
        pos += 9 + length
    return n
