"""`boatland run` writes its log (and .rrd), `boatland replay` and `boatland plot` read it; bad input is one line."""

import struct

import numpy as np
import pytest
from mcap.writer import Writer

from boatland.cli import main
from boatland.record.plot import PANELS, figure_of_run
from boatland.record.reader import read_run_log


@pytest.mark.slow
def test_run_writes_the_log_next_to_the_output_and_an_rrd(tmp_path, capsys):
    rrd = tmp_path / "live.rrd"
    assert main(["run", "--duration", "25", "-o", str(tmp_path / "trial.h5"), "--rerun", f"save={rrd}"]) == 0
    out = capsys.readouterr().out
    log = tmp_path / "trial.mcap"
    assert log.exists() and rrd.exists() and f"wrote {log}" in out and f"wrote {rrd}" in out
    assert read_run_log(log).duration == 25.0


@pytest.mark.slow
def test_run_default_log_name_in_the_current_directory_and_no_log(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["run", "--duration", "2", "--json"]) == 0
    assert (tmp_path / "ctv_landing.mcap").exists()
    (tmp_path / "ctv_landing.mcap").unlink()
    assert main(["run", "--duration", "2", "--json", "--no-log"]) == 0
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_replay_and_plot(recorded, tmp_path, capsys):
    out = tmp_path / "r.rrd"
    assert main(["replay", str(recorded.mcap), "--save", str(out)]) == 0
    assert out.stat().st_size > 10_000 and "1201 steps" in capsys.readouterr().out
    png = tmp_path / "fig.png"
    assert main(["plot", str(recorded.mcap), "-o", str(png)]) == 0
    head = png.read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    w, h = struct.unpack(">II", head[16:24])
    assert w > 800 and h > 600
    fig = figure_of_run(read_run_log(recorded.mcap))
    titles = [a.get_title() for a in fig.axes]
    assert [next(t for t in titles if t.startswith(p)) for p in PANELS]
    slip = fig.axes[PANELS.index("Slip distance")]
    assert len(slip.lines) >= 2 and any(np.nanmax(ln.get_ydata()) > 0.1 for ln in slip.lines)


@pytest.mark.slow
def test_replay_of_a_truncated_log_says_what_was_lost(recorded, tmp_path, capsys):
    bad = tmp_path / "cut.mcap"
    data = recorded.mcap.read_bytes()
    bad.write_bytes(data[:len(data) // 2])
    assert main(["replay", str(bad), "--save", str(tmp_path / "cut.rrd")]) == 0
    cap = capsys.readouterr()
    assert "note:" in cap.err and "truncated log" in cap.err and "is lost" in cap.err
    assert "recovered" in cap.out and (tmp_path / "cut.rrd").exists()


def _foreign_mcap(path):
    with open(path, "wb") as f:
        w = Writer(f)
        w.start(profile="", library="someone-else 1.0")
        sid = w.register_schema("other.Thing", "jsonschema", b"{}")
        cid = w.register_channel("/thing", "json", sid)
        w.add_message(cid, log_time=0, publish_time=0, data=b"{}")
        w.finish()


@pytest.mark.parametrize("command", ["replay", "plot"])
@pytest.mark.parametrize("kind", ["text", "foreign", "empty", "missing"])
def test_bad_input_is_one_line_exit_2(tmp_path, capsys, command, kind):
    path = tmp_path / "x.mcap"
    if kind == "text":
        path.write_text("not a log\n")
    elif kind == "foreign":
        _foreign_mcap(path)
    elif kind == "empty":
        path.write_bytes(b"\x89MCAP0\r\n")
    assert main([command, str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith(f"boatland: error: {path}") and "\n" not in err and "Traceback" not in err
    expected = {"text": "not an MCAP file", "foreign": "not a boatland run log", "empty": "nothing to recover",
                "missing": "no such file"}[kind]
    assert expected in err


def test_absent_viewer_is_an_error_before_the_run(tmp_path, capsys, monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    monkeypatch.chdir(tmp_path)
    assert main(["run", "--duration", "2", "--rerun", "connect=rerun+http://127.0.0.1:1/proxy"]) == 2
    assert "no Rerun viewer listening" in capsys.readouterr().err
    assert main(["run", "--duration", "2", "--rerun", "spawn"]) == 2
    assert "no display" in capsys.readouterr().err
    assert main(["replay", "x.mcap", "--spawn"]) == 2
    assert list(tmp_path.iterdir()) == []             # nothing written
