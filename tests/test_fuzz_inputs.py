"""Damaged files never end in a traceback: 1,200 seeded byte flips and truncations of a run log (MCAP), a
campaign store and a hydrodynamic database (both HDF5, as boatland writes them) are each read as a command
reads them — every one is read or refused with one :class:`~boatland.errors.BoatlandInputError` (which the
command line prints as one line naming the file). Run in a process of its own: a reader that crashed the
interpreter (the HDF5 library can, on a damaged file it parses) fails this test instead of the suite."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
ENV = {**os.environ, "PYTHONPATH": str(REPO)}
CASES = 400          # per file: 1,200 in all

FUZZ = r'''
import collections, json, sys, traceback, warnings
from pathlib import Path
import numpy as np
from boatland.errors import BoatlandInputError
warnings.simplefilter("ignore")

def read(kind, p):
    if kind == "log":
        from boatland.record.reader import read_run_log
        read_run_log(p)
    elif kind == "store":
        from boatland.campaign.report import read_store
        read_store(p)
    else:
        from boatland.hydro.read import read_hydro
        read_hydro(p)

folder, cases = Path(sys.argv[1]), int(sys.argv[2])
out = {}
for seed, (kind, name) in enumerate((("log", "run.mcap"), ("store", "store.h5"), ("database", "db.h5"))):
    data = (folder / name).read_bytes()
    rng = np.random.default_rng(seed)
    bad, refused = collections.Counter(), 0
    target = folder / f"damaged_{name}"
    for _ in range(cases):
        b = bytearray(data)
        if rng.random() < 0.3:
            b = b[:int(rng.integers(0, len(b)))]
        else:
            for _ in range(int(rng.integers(1, 5))):
                b[int(rng.integers(0, len(b)))] ^= int(rng.integers(1, 256))
        target.write_bytes(bytes(b))
        try:
            read(kind, target)
        except BoatlandInputError as exc:
            refused += 1
            assert "\n" not in str(exc).strip() or kind == "database", str(exc)
        except Exception as exc:
            tb = traceback.extract_tb(exc.__traceback__)[-1]
            bad[f"{type(exc).__name__} at {Path(tb.filename).name}:{tb.lineno}: {str(exc)[:80]}"] += 1
    out[kind] = {"cases": cases, "refused": refused, "tracebacks": dict(bad)}
print(json.dumps(out))
'''


@pytest.mark.slow
def test_a_thousand_damaged_files_and_not_one_traceback(tmp_path):
    def boatland(*args):
        r = subprocess.run([sys.executable, "-m", "boatland", *map(str, args)], cwd=tmp_path, capture_output=True,
                           text=True, timeout=600, env=ENV)
        assert r.returncode == 0, r.stderr

    boatland("run", "--duration", "60", "--log", "run.mcap")
    boatland("campaign", "demo", "--set", "seeds=1", "--set", "access=10", "-o", "store.h5")
    boatland("hydro", "import", REPO / "boatland" / "data" / "ctv24.h5", "-o", "db.h5")
    r = subprocess.run([sys.executable, "-c", FUZZ, str(tmp_path), str(CASES)], capture_output=True, text=True,
                       timeout=1200, env=ENV)
    assert r.returncode == 0, r.stderr[-3000:]
    found = json.loads(r.stdout)
    print(found)
    assert sum(v["cases"] for v in found.values()) >= 1000
    assert all(not v["tracebacks"] for v in found.values()), found
    assert all(v["refused"] > 0 for v in found.values())          # the damage was seen, not only read past
