"""Fingerprints of results that a refactor must not change: SHA-256 of every result array of three
shipped trials and of two with their landing turned (headings 270° and 90°: the start pose's rotation
reaches the contacts), and of ``boatland screen --json`` of ``ctv24_landing``, as shipped and turned.

    python bench/fingerprint.py                  # print them (JSON)
    python bench/fingerprint.py --check FILE     # compare with an earlier print; exit 1 on a difference

Hashes are of the arrays' bytes on this machine: numpy and OpenBLAS pick kernels by instruction set,
so compare prints made on the same machine (the redesign of issue 25 kept these equal commit by commit;
the turned cases were added during it, their reference printed by the code before it).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import subprocess
import sys

import numpy as np

TRIALS = (("ctv_landing", 60.0, {}), ("ctv24_landing", 60.0, {}), ("model2_j03", 20.0, {}),
          # rotated landings: the start pose's rotation reaches the contacts (headings 270° and 90°)
          ("ctv24_landing", 30.0, {"landing.bearing_deg": 90.0}), ("ctv_landing", 30.0, {"landing.bearing_deg": 270.0}))


def trial_hashes(name: str, duration: float, changes: dict) -> dict[str, str]:
    import boatland
    from boatland.trial.result import SERIES

    r = boatland.simulate(name, **{"simulation.duration": duration, **changes})
    out = {}
    for key in (*SERIES, "slide", "work"):
        a = getattr(r, key)
        out[key] = None if a is None else hashlib.sha256(np.ascontiguousarray(a).tobytes()).hexdigest()
    report = r.report()
    report["provenance"].pop("wall_time", None)   # the one field that is not a result
    out["report"] = hashlib.sha256(json.dumps(report, sort_keys=True, default=str).encode()).hexdigest()
    return out


def scenario_file(name: str) -> str:
    from boatland.api import scenario_path

    return str(scenario_path(name))


def screen_hash(bearing_deg: float | None = None) -> str:
    """``boatland screen --json`` of ctv24_landing (its landing turned to ``bearing_deg``)."""
    import tempfile
    from pathlib import Path

    path = scenario_file("ctv24_landing")
    with tempfile.TemporaryDirectory() as tmp:
        if bearing_deg is not None:
            text = Path(path).read_text()
            turned = Path(tmp) / "ctv24_landing.toml"      # the same name: the JSON names the scenario
            turned.write_text(text.replace("bearing_deg = 180.0", f"bearing_deg = {bearing_deg}"))
            path = str(turned)
        p = subprocess.run([sys.executable, "-m", "boatland", "screen", path, "--json"], capture_output=True,
                           check=True, cwd=tmp)
    out = p.stdout if bearing_deg is None else p.stdout.replace(path.encode(), b"SCENARIO")   # no temporary path
    return hashlib.sha256(out).hexdigest()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", metavar="FILE", help="an earlier print to compare with")
    args = ap.parse_args()
    got = {f"{name} {duration:g} s" + "".join(f", {k} = {v:g}" for k, v in changes.items()):
           trial_hashes(name, duration, changes) for name, duration, changes in TRIALS}
    got["screen --json ctv24_landing"] = screen_hash()
    got["screen --json ctv24_landing, landing.bearing_deg = 90"] = screen_hash(90.0)
    if args.check is None:
        print(json.dumps(got, indent=1))
        return 0
    with open(args.check, encoding="utf-8") as f:
        ref = json.load(f)
    missing = [k for k in got if k not in ref]
    for k in missing:
        print(f"not in {args.check}: {k}")
    bad = [k for k in ref if ref[k] != got.get(k)]
    for k in bad:
        print(f"DIFFERENT: {k}")
    print("identical" if not bad else f"{len(bad)} of {len(ref)} differ")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
