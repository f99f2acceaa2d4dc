"""Issue 14: nothing listens on every interface unless asked; Rerun's server binds 127.0.0.1 by default, and
a port in use is an error before any work. Checked with ``ss -ltnp`` against real processes."""

import os
import re
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
ENV = {**os.environ, "PYTHONPATH": str(REPO)}
pytestmark = pytest.mark.skipif(shutil.which("ss") is None, reason="needs ss (iproute2)")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def listeners(pids):
    """(address, port) of the TCP sockets the processes ``pids`` listen on."""
    out = subprocess.run(["ss", "-ltnpH"], capture_output=True, text=True).stdout
    found = []
    for line in out.splitlines():
        owners = {int(p) for p in re.findall(r"pid=(\d+)", line)}
        if owners & set(pids):
            local = line.split()[3]
            addr, _, port = local.rpartition(":")
            found.append((addr.strip("[]"), int(port)))
    return found


def family(pid):
    kids = [pid]
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                if int((d / "stat").read_text().rsplit(")", 1)[1].split()[1]) == pid:
                    kids.append(int(d.name))
            except (OSError, ValueError, IndexError):
                pass
    return kids


def watch(args, seconds=120):
    """Run ``boatland ARGS`` and collect its (and its children's) listening sockets until it ends."""
    p = subprocess.Popen([sys.executable, "-m", "boatland", *map(str, args)], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True, env=ENV)
    seen = set()
    deadline = time.monotonic() + seconds
    while p.poll() is None and time.monotonic() < deadline:
        seen.update(listeners(family(p.pid)))
        time.sleep(0.05)
    out, err = p.communicate(timeout=60)
    return p.returncode, out, err, seen


@pytest.mark.slow
def test_rerun_serve_listens_on_loopback_only(tmp_path):
    port = free_port()
    code, out, err, seen = watch(["run", "--duration", "120", "--no-log", "--rerun", "serve", "--port", port])
    assert code == 0, err
    assert ("127.0.0.1", port) in seen and all(a in ("127.0.0.1", "::1") for a, _ in seen), seen
    assert f"rerun+http://127.0.0.1:{port}/proxy" in err


@pytest.mark.slow
def test_the_bind_asked_for_is_the_one_used(tmp_path):
    """``--bind`` is honoured as given — shown with another loopback address, so that the suite itself never
    listens beyond this machine — and an address that is not this machine's is refused before the run."""
    port = free_port()
    code, out, err, seen = watch(["run", "--duration", "60", "--no-log", "--rerun", "serve", "--port", port,
                                  "--bind", "127.0.0.2"])
    assert code == 0, err
    assert ("127.0.0.2", port) in seen and all(a == "127.0.0.2" for a, _ in seen), seen
    assert "without authentication" not in err                    # loopback: this machine only, no warning
    # 192.0.2.1 is TEST-NET-1 (RFC 5737): no machine's address
    r = subprocess.run([sys.executable, "-m", "boatland", "run", "--no-log", "--rerun", "serve", "--port", str(port),
                        "--bind", "192.0.2.1"], capture_output=True, text=True, env=ENV, timeout=120)
    assert r.returncode == 2 and "192.0.2.1" in r.stderr and "Traceback" not in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and not r.stdout


def test_a_bind_beyond_this_machine_warns():
    """What a user who asks for ``--bind 0.0.0.0`` is told (the listener itself is not opened here)."""
    from boatland.record.rerun_log import exposure_warning

    text = exposure_warning("0.0.0.0", 9876, "serving")
    assert text.startswith("warning: rerun: serving on 0.0.0.0:9876 without authentication")
    assert exposure_warning("::", 9876, "serving") is not None
    assert all(exposure_warning(a, 9876, "serving") is None for a in ("127.0.0.1", "127.0.0.2", "::1"))


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("xvfb-run") is None, reason="needs xvfb-run (a display for the viewer)")
def test_the_viewer_spawn_starts_listens_on_loopback_only(tmp_path):
    """``--rerun spawn`` starts a native viewer (under a virtual display here); ``rerun.spawn`` would start it
    on 0.0.0.0 (the ``rerun`` command's default bind), boatland starts it on 127.0.0.1 — every listener
    on the run's port, and every Rerun viewer's, is on loopback."""
    port = free_port()
    p = subprocess.Popen(["xvfb-run", "-a", sys.executable, "-m", "boatland", "run", "--duration", "5", "--no-log",
                          "--rerun", "spawn", "--port", str(port)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         stdin=subprocess.DEVNULL, text=True, env=ENV)
    seen = set()
    try:
        deadline = time.monotonic() + 120
        while p.poll() is None and time.monotonic() < deadline:
            out = subprocess.run(["ss", "-ltnpH"], capture_output=True, text=True).stdout
            for line in out.splitlines():                       # on the run's port, or a Rerun viewer's
                addr, _, pt = line.split()[3].rpartition(":")
                if int(pt) == port or '(("rerun",' in line:
                    seen.add(addr.strip("[]"))
            time.sleep(0.05)
        out, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
        subprocess.run(["pkill", "-f", f"--port {port}"], capture_output=True)   # the detached viewer, if left
    assert p.returncode == 0, err
    assert "HELD" in out and seen == {"127.0.0.1"}, (seen, err[-2000:])


def test_a_busy_port_is_an_error_before_the_run(tmp_path):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        r = subprocess.run([sys.executable, "-m", "boatland", "run", "--duration", "5", "--no-log", "--rerun",
                            "serve", "--port", str(port)], capture_output=True, text=True, env=ENV, cwd=tmp_path,
                           stdin=subprocess.DEVNULL)
    assert r.returncode == 2 and f"--port {port}" in r.stderr and "in use" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and "running" not in r.stderr


@pytest.mark.slow
def test_replay_serve_and_a_campaign_open_nothing_wider(tmp_path):
    log = tmp_path / "r.mcap"
    assert subprocess.run([sys.executable, "-m", "boatland", "run", "--duration", "10", "--log", str(log),
                           "--json"], capture_output=True, env=ENV).returncode == 0
    port = free_port()
    code, out, err, seen = watch(["replay", log, "--serve", "--port", port])
    assert code == 0, err
    assert seen <= {("127.0.0.1", port)}, seen
    camp = tmp_path / "c.toml"
    camp.write_text(f'name = "c"\nscenario = "{REPO / "scenarios" / "ctv_free_decay.toml"}"\nseeds = 6\n'
                    'access = 300.0\n')
    code, out, err, seen = watch(["campaign", camp, "-o", tmp_path / "c.h5", "--workers", "2"])
    assert code == 0, err
    assert seen == set(), seen
