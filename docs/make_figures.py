"""Make every figure in ``docs/`` from the shipped scenarios and campaigns, with the code of this checkout.

Run from the source checkout (a few minutes on two cores; the rare-event polar a few more)::

    python docs/make_figures.py            # all of them
    python docs/make_figures.py run_plot   # the ones whose file name contains a word given

Each figure is made by the command line a user would type (``FIGURES``: the file, the shipped scenario or
campaign and the vessel it is made from, the commands), in a temporary folder, then copied into ``docs/``.
Every matplotlib figure carries its title in the PNG's ``Title`` text chunk
(:func:`boatland.plotstyle.save_figure`); ``tests/test_docs_figures.py`` checks that each title names the
scenario (or campaign) and the vessel listed here. The Rerun screenshot has no title: its caption in the
README names them, and the test checks that instead. It is the viewer as ``boatland replay --connect`` leaves
it (the time cursor on the first slip), rendered on a virtual display (``xvfb-run``; on a machine without a
GPU, Mesa's software Vulkan driver — Debian's ``mesa-vulkan-drivers`` — with ``WGPU_BACKEND=vulkan``). ``rao_ctv27_vs_ctv24.png`` has a script of its own
(``docs/rao_ctv27_vs_ctv24.py``), run from here too.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent


@dataclass(frozen=True)
class Figure:
    """One figure of ``docs/``: ``file``; ``source`` the shipped scenario or campaign its title names and
    ``vessel`` the built-in database; ``commands`` what makes it, each an argv of ``boatland`` (or, first
    word ``python``, of Python; ``viewer LOG OUT``: :func:`screenshot`) with ``{tmp}`` (a scratch folder) and
    ``{out}`` (the file)."""

    file: str
    source: str
    vessel: str
    commands: tuple[tuple[str, ...], ...]
    produced: str = "{out}"          # where the last command leaves it ({tmp}/… for a report's figure)
    titled: bool = True              # a matplotlib figure with its title in the PNG


FIGURES = (
    Figure("screen_polar.png", "ctv_landing", "ctv27", (("screen", "ctv_landing", "-o", "{out}"),)),
    Figure("rao_open_sea_vs_pile.png", "ctv_landing", "ctv27",
           (("rao", "ctv_landing", "--compare-open-sea", "{out}"),)),
    Figure("limiting_hs_vs_shear_stiffness.png", "ctv24_landing", "ctv24",
           (("screen", "ctv24_landing", "--shear-sweep", "7", "--directions", "8", "-o", "{out}"),)),
    Figure("current_sweep.png", "ctv_landing", "ctv27", (("screen", "ctv_landing", "--current-sweep", "7", "-o", "{out}"),)),
    Figure("sensitivity_tornado.png", "ctv_landing", "ctv27", (("screen", "ctv_landing", "--sensitivity", "-o", "{out}"),)),
    Figure("run_plot.png", "ctv24_landing", "ctv24",
           (("run", "ctv24_landing", "--log", "{tmp}/run.mcap"), ("plot", "{tmp}/run.mcap", "-o", "{out}"))),
    Figure("p_vs_hs.png", "demo", "ctv27",
           (("campaign", "demo", "-o", "{tmp}/demo.h5", "--report", "{tmp}/report"),), "{tmp}/report/p_vs_hs.png"),
    Figure("limiting_hs_polar.png", "demo", "ctv27",
           (("campaign", "demo", "-o", "{tmp}/demo.h5", "--report", "{tmp}/report"),),
           "{tmp}/report/limiting_hs_polar.png"),
    Figure("isee_limiting_hs_polar.png", "isee_limits", "ctv24",
           (("campaign", "isee_limits", "-o", "{tmp}/isee.h5", "--report", "{tmp}/report"),),
           "{tmp}/report/limiting_hs_polar.png"),
    Figure("rerun_scene.png", "ctv_landing", "ctv27",
           (("run", "ctv_landing", "--log", "{tmp}/run.mcap"), ("viewer", "{tmp}/run.mcap", "{out}")), titled=False),
    Figure("operability_example.png", "ctv_landing, ctv24_landing", "ctv27, ctv24",
           (("operability", "ctv_landing", "ctv24_landing", "scenarios/example_hindcast.csv", "--landing", "45",
             "--landing", "165", "--landing", "285", "-o", "{out}"),)),
    Figure("rao_ctv27_vs_ctv24.png", "ctv_landing, ctv24_landing", "ctv27, ctv24",
           (("python", "docs/rao_ctv27_vs_ctv24.py"),), "docs/rao_ctv27_vs_ctv24.png"),
)


def _argv(cmd: tuple[str, ...], tmp: Path, out: Path) -> list[str]:
    words = [w.format(tmp=tmp, out=out) for w in cmd]
    if words[0] == "python":
        return [sys.executable, *words[1:]]
    return [sys.executable, "-m", "boatland", *words]


def screenshot(log: str, out: str, env: dict, size: str = "1600x900") -> None:
    """A Rerun viewer on a virtual display (its server on loopback, a free port) shows the replay of ``log`` as
    ``boatland replay --connect`` leaves it; its screenshot goes to ``out``. The display is larger than the
    window, so that the virtual pointer (at the display's centre) hovers over nothing."""
    import socket

    from boatland.record.rerun_log import wait_listening

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    url = f"rerun+http://127.0.0.1:{port}/proxy"
    env = dict(env, WGPU_BACKEND=env.get("WGPU_BACKEND", "vulkan"))
    viewer = subprocess.Popen(["xvfb-run", "-a", "-s", "-screen 0 3840x2160x24", shutil.which("rerun") or "rerun",
                               "--bind", "127.0.0.1", "--port", str(port), "--window-size", size],
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        if not wait_listening("127.0.0.1", port, timeout=60.0):
            raise OSError("the Rerun viewer did not start")
        subprocess.run([sys.executable, "-m", "boatland", "replay", log, "--connect", url], cwd=ROOT, env=env,
                       check=True, stdout=subprocess.DEVNULL)
        code = (f"from rerun.experimental import ViewerClient; import time; time.sleep(3); "
                f"ViewerClient.connect({url!r}).save_screenshot({out!r})")
        subprocess.run([sys.executable, "-c", code], env=env, check=True)
    finally:
        os.killpg(viewer.pid, 15)
        viewer.wait(10)


def make(fig: Figure) -> float:
    """Make ``fig`` into ``docs/``; returns the seconds it took."""
    t0 = time.perf_counter()
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    with tempfile.TemporaryDirectory(prefix="boatland-docs-") as tmp:
        tmp = Path(tmp)
        out = tmp / fig.file
        for cmd in fig.commands:
            if cmd[0] == "viewer":
                screenshot(*(w.format(tmp=tmp, out=out) for w in cmd[1:]), env)
            else:
                subprocess.run(_argv(cmd, tmp, out), cwd=ROOT, env=env, check=True, stdout=subprocess.DEVNULL)
        made = Path(fig.produced.format(tmp=tmp, out=out))
        made = made if made.is_absolute() else ROOT / made
        if made != DOCS / fig.file:
            shutil.copyfile(made, DOCS / fig.file)
    return time.perf_counter() - t0


def main(argv: list[str]) -> int:
    chosen = [f for f in FIGURES if not argv or any(w in f.file for w in argv)]
    if not chosen:
        print(f"no figure matches {' '.join(argv)}; the figures: {', '.join(f.file for f in FIGURES)}", file=sys.stderr)
        return 2
    failed = []
    for fig in chosen:
        print(f"{fig.file}: {fig.source} ({fig.vessel}) …", file=sys.stderr, flush=True)
        try:
            print(f"  {make(fig):.0f} s", file=sys.stderr)
        except (subprocess.CalledProcessError, OSError) as exc:     # the others are still made
            failed.append(fig.file)
            print(f"  failed: {exc}", file=sys.stderr)
    if failed:
        print(f"not made (the files in docs/ are the earlier ones): {', '.join(failed)}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
