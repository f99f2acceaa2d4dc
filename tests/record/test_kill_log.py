"""Issue 14: a run killed with SIGKILL keeps in its log what the kernel had integrated (measured from the
kernel's own step counter, ``boatland run --progress-file``, not from the log)."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from boatland.record.reader import read_run_log

REPO = Path(__file__).resolve().parents[2]
#: What a kill may lose: one block (1 s). The log writes every block as soon as the kernel has finished it
#: (the sea at the bow is summed per block), and the kernel starts a step only while it is at most one
#: block ahead of what the sinks have taken (its gate, boatland.integrate.run_cummins) — so the file holds
#: everything integrated but the block in progress.
MAX_LOSS = 1.0


def _kill_once(tmp_path: Path, delay: float):
    log, prog = tmp_path / "k.mcap", tmp_path / "k.prog"
    for f in (log, prog):
        f.unlink(missing_ok=True)
    p = subprocess.Popen([sys.executable, "-m", "boatland", "run", str(REPO / "scenarios" / "ctv_landing.toml"),
                          "--duration", "3600", "--log", str(log), "--progress-file", str(prog), "--json"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                         env={**os.environ, "PYTHONPATH": str(REPO)})
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline and p.poll() is None:
        if prog.exists() and prog.read_text().strip() not in ("", "0"):
            break
        time.sleep(0.01)
    time.sleep(delay)
    p.send_signal(signal.SIGKILL)
    p.wait()
    # the counter is the number of final rows: the kernel had integrated to the time of the last, row p − 1
    kernel = (int(prog.read_text().strip()) - 1) * 0.05  # [s] integrated when it was killed (dt = 0.05 s)
    return kernel, read_run_log(log).duration


@pytest.mark.slow
def test_sigkill_at_three_random_moments_loses_little_of_what_was_integrated(tmp_path):
    rng = np.random.default_rng(14)
    losses = []
    for delay in rng.uniform(0.05, 1.5, 3):
        kernel, logged = _kill_once(tmp_path, float(delay))
        assert 0 < kernel < 3600, kernel                   # killed while integrating
        losses.append(kernel - logged)
    print("kernel − log [s]:", [f"{x:.2f}" for x in losses])
    assert all(-0.05 <= x <= MAX_LOSS + 1e-9 for x in losses), losses
