"""Shared fixtures, and the guard that no validation case is silently skipped.

Reference data live in the repository, ``tests/data/refdata`` (public data nobody on this project
wrote; origin, licence and what each file checks in its README.md).
"""

from __future__ import annotations

from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
REFDATA = Path(__file__).resolve().parent / "data" / "refdata"
VALIDATION = Path(__file__).resolve().parent / "validation"


@pytest.fixture(scope="session")
def refdata() -> Path:
    """Folder of the public reference data in the repository (``tests/data/refdata``)."""
    return REFDATA


@pytest.fixture(scope="session")
def box_db():
    """A synthetic box vessel (:func:`box_vessel.box_vessel_db`) for the scenario, checks and setup tests."""
    from box_vessel import box_vessel_db

    return box_vessel_db()


@pytest.fixture(scope="session")
def repo_root() -> Path:
    """The source checkout (scenario files live in its ``scenarios/``)."""
    return REPO


@pytest.fixture(scope="session")
def small_store(tmp_path_factory):
    """A finished campaign store of the default landing: Hs 0.15 / 0.6 m × head / bow-quartering seas
    (``tests/small_campaign.py``); ``(campaign file, store, JSON the campaign printed)``."""
    from small_campaign import run_small_campaign

    return run_small_campaign(tmp_path_factory.mktemp("small_campaign"), "small", [0.15, 0.6], [180.0, 135.0])


# --- validation cases must run: a skip under tests/validation/ fails the session ---------------------


class ValidationSkips:
    """Collects skipped tests (and skipped modules) under ``tests/validation/``; if the run was otherwise
    green, sets exit status 1 and lists them in the terminal summary. A skipped validation case is a
    reference comparison that did not happen, so it must not pass quietly (xfail is not a skip)."""

    def __init__(self, rootpath: Path):
        self.rootpath = rootpath
        self.skipped: list[tuple[str, str]] = []   # (node id, reason)

    def _note(self, report) -> None:
        if not report.skipped or hasattr(report, "wasxfail"):
            return
        if (self.rootpath / report.nodeid.split("::")[0]).resolve().is_relative_to(VALIDATION):
            reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else str(report.longrepr)
            self.skipped.append((report.nodeid, reason.removeprefix("Skipped: ")))

    def pytest_runtest_logreport(self, report: pytest.TestReport) -> None:
        self._note(report)

    def pytest_collectreport(self, report: pytest.CollectReport) -> None:
        self._note(report)     # module-level skips: pytest.skip(allow_module_level=True), importorskip

    def pytest_sessionfinish(self, session: pytest.Session, exitstatus: int) -> None:
        if self.skipped and exitstatus == pytest.ExitCode.OK:
            session.exitstatus = pytest.ExitCode.TESTS_FAILED

    def pytest_terminal_summary(self, terminalreporter) -> None:
        if self.skipped:
            terminalreporter.section("validation tests skipped: the run fails", sep="=", red=True, bold=True)
            for nodeid, reason in self.skipped:
                terminalreporter.line(f"SKIPPED {nodeid} - {reason}", red=True)


def pytest_configure(config: pytest.Config) -> None:
    config.pluginmanager.register(ValidationSkips(config.rootpath), "boatland-validation-skips")
    # the disk cache (boatland.diskcache) of this session: a fresh folder, never the user's; set before the test
    # modules are imported, so that environments they copy at import time for subprocesses carry it too
    import os
    import tempfile

    config._boatland_cache = tempfile.mkdtemp(prefix="boatland_test_cache_")
    os.environ["BOATLAND_CACHE_DIR"] = config._boatland_cache


def pytest_unconfigure(config: pytest.Config) -> None:
    import shutil

    folder = getattr(config, "_boatland_cache", None)
    if folder:
        shutil.rmtree(folder, ignore_errors=True)
