"""Campaign throughput: trials/s and simulated steps/s on 1 and 2 local workers, and the wall time of
the Table-4.14-sized study (scenarios/campaigns/table414.toml; issue 7 goal ≤ 2 min on 2 cores with the
state-space option). Runs the real CLI in subprocesses (worker start-up and the store included);
numba caches are warmed first. Prints Markdown."""

from __future__ import annotations

import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def campaign(path: Path, store: Path, workers: int) -> float:
    t = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "boatland", "campaign", str(path), "-o", str(store),
                        "--workers", str(workers)], capture_output=True, text=True)
    if r.returncode:
        raise SystemExit(r.stderr)
    return time.perf_counter() - t


def main() -> None:
    study = REPO / "scenarios" / "campaigns" / "table414.toml"
    demo = REPO / "scenarios" / "campaigns" / "demo.toml"
    print(f"# {platform.machine()}, Python {platform.python_version()}, {time.strftime('%Y-%m-%d')}\n")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        campaign(demo, tmp / "warm.h5", 1)  # numba caches warm
        print("| campaign | trials × access [s] | workers | wall [s] | trials/s | simulated steps/s |")
        print("|---|---|---|---|---|---|")
        for path, trials, seconds in ((demo, 32, 140.0), (study, 72, 1800.0)):
            for workers in (1, 2):
                wall = campaign(path, tmp / f"{path.stem}{workers}.h5", workers)
                steps = trials * seconds / 0.05
                print(f"| {path.stem} | {trials} × {seconds:g} | {workers} | {wall:.1f} | {trials / wall:.2f} | "
                      f"{steps / wall:,.0f} |")


if __name__ == "__main__":
    main()
