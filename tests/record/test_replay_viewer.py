"""``boatland replay --connect`` leaves a real Rerun viewer (on a virtual display, Mesa's software Vulkan where
there is no GPU) at the moment worth looking at: the first slip, else the most loaded moment — its time
cursor there, paused — with the layout this version draws (not one the viewer remembered)."""

import os
import shutil
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from boatland.record.reader import read_run_log
from boatland.record.replay import waves_from
from boatland.record.rerun_log import TIMELINE, key_moment, wait_listening

REPO = Path(__file__).resolve().parents[2]
ENV = {**os.environ, "PYTHONPATH": str(REPO), "WGPU_BACKEND": os.environ.get("WGPU_BACKEND", "vulkan")}


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def run(*args):
    r = subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], capture_output=True, text=True, env=ENV,
                       timeout=600)
    assert r.returncode == 0, r.stderr
    return r


@pytest.fixture(scope="module")
def viewer(tmp_path_factory):
    """A Rerun viewer listening on 127.0.0.1 (its state in a folder of its own); its URL."""
    port = free_port()
    home = tmp_path_factory.mktemp("viewer-home")
    p = subprocess.Popen(["xvfb-run", "-a", "-s", "-screen 0 3840x2160x24", shutil.which("rerun"), "--bind", "127.0.0.1",
                          "--port", str(port), "--window-size", "1600x900"], env={**ENV, "HOME": str(home)},
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        assert wait_listening("127.0.0.1", port, timeout=60.0), "the Rerun viewer did not start"
        yield f"rerun+http://127.0.0.1:{port}/proxy"
    finally:
        os.killpg(p.pid, 9)
        p.wait(10)


def cursor(url):
    from rerun.experimental import ViewerClient

    state = ViewerClient.connect(url).get_state()
    (rec,) = [r for r in state.recordings if r.store_id == state.active_recording]
    assert rec.current_timeline == TIMELINE
    return rec.current_time / 1e9, state


@pytest.mark.slow
def test_replay_leaves_the_viewer_at_the_first_slip(tmp_path, viewer):
    log = tmp_path / "slips.mcap"
    run("run", "ctv24_landing", "--duration", "90", "--log", log)      # Hs 1.5 m on the 80 kN Wigley: it slips
    r = run("replay", log, "--connect", viewer)
    data = read_run_log(log)
    settled = waves_from(data.metadata)
    slips = [t for t, _, text in data.events if "stick→slip" in text and t >= settled]
    t, what = key_moment(data.columns, settled)
    assert slips and t == pytest.approx(slips[0], abs=1e-9) and what.startswith("the first slip")
    assert f"the viewer shows t = {t:.2f} s: the first slip" in r.stdout
    at, state = cursor(viewer)
    assert at == pytest.approx(t, abs=1e-6)
    names = {v.name for v in state.views}                          # this version's layout, not a remembered one
    assert {"Landing", "Events", "Friction needed vs available, per contact [kN]"} <= names


@pytest.mark.slow
def test_a_run_that_holds_opens_at_its_most_loaded_moment(tmp_path, viewer):
    log = tmp_path / "holds.mcap"
    run("run", "--duration", "60", "--set", "sea.Hs=0.3", "--log", log)
    r = run("replay", log, "--connect", viewer)
    data = read_run_log(log)
    c, settled = data.columns, waves_from(data.metadata)
    t, what = key_moment(c, settled)
    after = c.t >= settled
    use = np.where(c.available > 0, c.needed / np.where(c.available > 0, c.available, 1.0), 0.0)[after]
    assert not (c.mode[after] == 2).any() and what.startswith("the most loaded moment")
    assert c.t[after][np.argmax(use.max(axis=1))] == t
    assert f"the viewer shows t = {t:.2f} s: the most loaded moment" in r.stdout
    assert cursor(viewer)[0] == pytest.approx(t, abs=1e-6)
