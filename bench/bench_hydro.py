"""Hydrodynamic database I/O timings: each reader on the public reference data, and BEMIO write/read.

Run: ``python bench/bench_hydro.py`` (from the repo root; the files are the test suite's tests/data/refdata).
Origin and licences of the files: tests/data/refdata/README.md.
Figures go to bench/README.md by hand, with the machine and date.
"""

from __future__ import annotations

from _timing import best_of

import platform
import tempfile
from pathlib import Path

from boatland.hydro import read_hydro, write_bemio

REF = Path(__file__).resolve().parents[1] / "tests" / "data" / "refdata"
CASES = {
    "wamit sphere (420 ω)": REF / "wamit_sphere" / "sphere.1",
    "nemoh sphere (420 ω)": REF / "nemoh_sphere",
    "capytaine sphere (420 ω)": REF / "capytaine_sphere" / "sphere_hydrodynamics.nc",
    "aqwa cylinder (50 ω, 3 β)": REF / "aqwa_cylinder" / "cylinder.AH1",
    "bemio sphere (240 ω)": REF / "bemio_sphere" / "sphere.h5",
}



def main():
    print(f"# {platform.processor() or platform.machine()}, Python {platform.python_version()}")
    print("| case | read [ms] |")
    print("|---|---|")
    for name, path in CASES.items():
        print(f"| {name} | {1e3 * best_of(lambda: read_hydro(path))[0]:.1f} |")
    try:
        from boatland.hydro.builtin import load_builtin
    except ImportError:
        return
    for name in ("ctv24", "model2"):
        db = load_builtin(name)
        with tempfile.TemporaryDirectory() as tmp:
            p = Path(tmp) / "db.h5"
            tw = best_of(lambda: write_bemio(db, p))[0]
            tr = best_of(lambda: read_hydro(p))[0]
        print(f"| {name} write / read ({db.n_freq} ω, {db.n_dir} β) | {1e3 * tw:.1f} / {1e3 * tr:.1f} |")


if __name__ == "__main__":
    main()
