"""Fingerprints of results that a refactor must not change: SHA-256 of every result array of three
shipped trials and of ``boatland screen --json`` of ``ctv24_landing``.

    python bench/fingerprint.py                  # print them (JSON)
    python bench/fingerprint.py --check FILE     # compare with an earlier print; exit 1 on a difference

Hashes are of the arrays' bytes on this machine: numpy and OpenBLAS pick kernels by instruction set,
so compare prints made on the same machine (the redesign of issue 25 kept these equal commit by commit).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import subprocess
import sys

import numpy as np

TRIALS = (("ctv_landing", 60.0), ("ctv24_landing", 60.0), ("model2_j03", 20.0))


def trial_hashes(name: str, duration: float) -> dict[str, str]:
    import boatland
    from boatland.trial.result import SERIES

    r = boatland.simulate(name, **{"simulation.duration": duration})
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


def screen_hash() -> str:
    p = subprocess.run([sys.executable, "-m", "boatland", "screen", scenario_file("ctv24_landing"), "--json"],
                       capture_output=True, check=True)
    return hashlib.sha256(p.stdout).hexdigest()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", metavar="FILE", help="an earlier print to compare with")
    args = ap.parse_args()
    got = {f"{name} {duration:g} s": trial_hashes(name, duration) for name, duration in TRIALS}
    got["screen --json ctv24_landing"] = screen_hash()
    if args.check is None:
        print(json.dumps(got, indent=1))
        return 0
    with open(args.check, encoding="utf-8") as f:
        ref = json.load(f)
    bad = [k for k in ref if ref[k] != got.get(k)]
    for k in bad:
        print(f"DIFFERENT: {k}")
    print("identical" if not bad else f"{len(bad)} of {len(ref)} differ")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
