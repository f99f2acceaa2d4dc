"""``boatland validate`` as a user (and CI) runs it: real subprocesses, the report read back from disk.

- ``--quick -o DIR --json``: the report names every case of the registry with its reference and its
  tolerance, a verdict per case in the summary and in its section, the date, version, commit and machine,
  and every figure it shows exists as a PNG; the exit status is 0 exactly when every case passed, and the
  JSON on stdout says the same as the report.
- A forced miss: Hulme's table in a temporary copy of the reference data is made 5 % wrong; the case is
  reported as MISS (summary, section, the failing check) with its numbers, not dropped, and the exit
  status is 1.
- Bad input is one line and exit status 2.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from boatland.validation import all_cases
from boatland.validation.hemisphere import BEMIO_FILE, HULME_FILE

PNG = b"\x89PNG\r\n\x1a\n"


def validate(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "boatland", "validate", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd, timeout=3600)


def section(report: str, title: str) -> str:
    """The report's section of the case titled ``title`` (up to the next section)."""
    start = report.index(f". {title} — ")
    end = report.find("\n## ", start)
    return report[start:] if end < 0 else report[start:end]


@pytest.fixture(scope="module")
def quick(tmp_path_factory):
    out = tmp_path_factory.mktemp("validation")
    r = validate("--quick", "-o", out, "--json")
    return r, out, (out / "README.md").read_text(encoding="utf-8") if (out / "README.md").is_file() else ""


@pytest.mark.slow
def test_quick_report_names_every_case_with_its_reference_and_tolerance(quick):
    r, out, report = quick
    assert report, r.stderr[-3000:]
    data = json.loads(r.stdout)
    cases = all_cases()
    assert [c["name"] for c in data["cases"]] == [c.name for c in cases]
    summary = report[report.index("## Summary"):report.index("<a id=")]
    verdicts = {c["name"]: c["verdict"] for c in data["cases"]}
    for c in cases:
        text = section(report, c.title)
        assert f"**Reference.** {c.reference}" in text, c.name
        assert f"**Tolerance.** {c.tolerance}." in text, c.name
        assert f"— **{verdicts[c.name]}**" in text.splitlines()[0], c.name
        row = next(line for line in summary.splitlines() if "(#case-" in line and f"-{c.name})" in line)
        assert f"**{verdicts[c.name]}**" in row and c.tolerance.replace("|", "\\|") in row and c.cite in row, row
        assert "| check | measured | tolerance | verdict |" in text, c.name
    assert set(verdicts.values()) <= {"PASS", "MISS"}, verdicts                 # ERROR would be a bug
    assert r.returncode == (0 if set(verdicts.values()) == {"PASS"} else 1), (r.returncode, verdicts)
    assert data["passed"] == (r.returncode == 0)


@pytest.mark.slow
def test_quick_report_has_date_version_commit_machine_and_figures(quick):
    r, out, report = quick
    head = report.split("## Summary")[0]
    data = json.loads(r.stdout)
    m = data["machine"]
    for key in ("date", "boatland", "commit", "platform", "cpu"):
        assert str(m[key]) in head, key
    assert f"{m['cpus']} CPUs" in head and "validate --quick" in head
    figures = [line[line.index("](") + 2:-1] for line in report.splitlines() if line.startswith("![")]
    assert len(figures) == len(all_cases())
    for name in figures:
        assert (out / name).read_bytes()[:8] == PNG, name
    for c in data["cases"]:
        assert c["wall_time_s"] > 0 and f"wall time {c['wall_time_s']:.1f} s" in section(report, c["title"])


def test_a_case_that_misses_its_tolerance_is_reported_as_miss(tmp_path):
    ref = tmp_path / "refdata"
    for f in (HULME_FILE, BEMIO_FILE):
        (ref / f).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(Path(__file__).resolve().parents[1] / "data" / "refdata" / f, ref / f)
    table = np.loadtxt(ref / HULME_FILE, comments="#")
    table[:, 1] *= 1.05                                             # Hulme's μ made 5 % wrong
    np.savetxt(ref / HULME_FILE, table, fmt="%.4f", header="kA mu lambda (deliberately wrong copy)")
    out = tmp_path / "report"
    r = validate("--case", "hulme-hemisphere", "--refdata", ref, "-o", out)
    assert r.returncode == 1, r.stderr
    report = (out / "README.md").read_text(encoding="utf-8")
    case = next(c for c in all_cases() if c.name == "hulme-hemisphere")
    text = section(report, case.title)
    assert text.splitlines()[0].endswith("— **MISS**")
    mu = next(line for line in text.splitlines() if line.startswith("| added mass μ"))
    assert mu.endswith("| **MISS** |")
    measured = float(mu.split("|")[2].strip().rstrip(" %"))
    assert measured > 4.0                                            # ≈ 5 %, beyond the 0.5 % tolerance
    lam = next(line for line in text.splitlines() if line.startswith("| damping λ"))
    assert lam.endswith("| **PASS** |")                              # the untouched column still passes
    assert "**0 PASS, 1 MISS, 0 ERROR** of 1 cases" in report
    assert "hulme-hemisphere" in r.stdout and "MISS" in r.stdout


@pytest.mark.parametrize("args, message", [
    (["--case", "no-such-case"], "--case no-such-case: no such case; use one of hulme-hemisphere"),
    (["--case", "hulme-hemisphere", "--refdata", "{tmp}/missing"], "--refdata {tmp}/missing: not a folder"),
    (["--case", "bem-codes", "--refdata", "{tmp}/partial"], "wamit_sphere/sphere.1 is missing (case bem-codes)"),
    (["--case", "hulme-hemisphere", "--refdata", "{tmp}/partial", "-o", "{tmp}/partial/out"],
     "inside the reference data folder"),
    (["--workers", "0"], "--workers"),
], ids=["unknown-case", "refdata-missing", "refdata-incomplete", "output-inside-refdata", "workers"])
def test_bad_input_is_one_line_and_exit_2(tmp_path, args, message):
    partial = tmp_path / "partial"
    for f in (HULME_FILE, BEMIO_FILE):
        (partial / f).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(Path(__file__).resolve().parents[1] / "data" / "refdata" / f, partial / f)
    args = [a.replace("{tmp}", str(tmp_path)) for a in args]
    r = validate(*args, "-o", tmp_path / "report") if "-o" not in args else validate(*args)
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in r.stderr, r.stderr
    assert message.replace("{tmp}", str(tmp_path)) in lines[0], lines[0]
    assert not (tmp_path / "report" / "README.md").exists()
