"""tests/conftest.py fails a run in which a test under tests/validation/ was skipped.

Each case builds a small project in a temporary folder — this repository's own ``tests/conftest.py``
copied unchanged, and tests that pass, skip or fail — and runs pytest on it in a subprocess; the
exit status and the printed summary are what CI sees.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

CONFTEST = Path(__file__).resolve().parent / "conftest.py"
HEADER = "validation tests skipped: the run fails"


def run_pytest(tmp_path: Path, files: dict[str, str]) -> subprocess.CompletedProcess:
    (tmp_path / "pytest.ini").write_text("[pytest]\n")          # the root: nothing above it is read
    (tmp_path / "tests" / "validation").mkdir(parents=True)
    shutil.copy(CONFTEST, tmp_path / "tests" / "conftest.py")
    for name, body in files.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(body))
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST_")}
    return subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-rs", "tests"],
                          cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)


PASS = "def test_ok():\n    assert True\n"


@pytest.mark.parametrize("body, nodeid, reason", [
    ('import pytest\n\ndef test_case():\n    pytest.skip("reference data not found")\n',
     "tests/validation/test_case.py::test_case", "reference data not found"),
    ('import pytest\n\n@pytest.mark.skipif(True, reason="solver missing")\ndef test_case():\n    pass\n',
     "tests/validation/test_case.py::test_case", "solver missing"),
    ('import pytest\n\nnot_here = pytest.importorskip("boatland_no_such_module")\n\ndef test_case():\n    pass\n',
     "tests/validation/test_case.py", "boatland_no_such_module"),
], ids=["skip-call", "skipif-mark", "module-importorskip"])
def test_a_skipped_validation_test_fails_the_run_and_is_named(tmp_path, body, nodeid, reason):
    r = run_pytest(tmp_path, {"tests/validation/test_ok.py": PASS, "tests/validation/test_case.py": body})
    assert r.returncode == pytest.ExitCode.TESTS_FAILED, r.stdout + r.stderr
    summary = r.stdout[r.stdout.index(HEADER):]
    assert f"SKIPPED {nodeid} - " in summary and reason in summary


def test_skips_elsewhere_and_xfail_leave_the_run_green(tmp_path):
    r = run_pytest(tmp_path, {
        "tests/validation/test_ok.py": PASS,
        "tests/validation/test_known.py": 'import pytest\n\n@pytest.mark.xfail(reason="known")\n'
                                          "def test_known():\n    assert False\n",
        "tests/waves/test_threads.py": 'import pytest\n\ndef test_threads():\n    pytest.skip("one thread")\n',
    })
    assert r.returncode == pytest.ExitCode.OK, r.stdout + r.stderr
    assert "1 passed, 1 skipped, 1 xfailed" in r.stdout and HEADER not in r.stdout


def test_a_failure_stays_a_failure(tmp_path):
    r = run_pytest(tmp_path, {"tests/validation/test_bad.py": "def test_bad():\n    assert 1 == 2\n",
                              "tests/validation/test_skip.py": 'import pytest\n\ndef test_s():\n    pytest.skip("x")\n'})
    assert r.returncode == pytest.ExitCode.TESTS_FAILED and "1 failed, 1 skipped" in r.stdout
    assert HEADER in r.stdout
