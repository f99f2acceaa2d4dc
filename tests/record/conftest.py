"""One short default trial recorded live (MCAP + .rrd), shared by the recording tests."""

import uuid
import warnings
from dataclasses import dataclass
from pathlib import Path

import pytest

from boatland.record.mcap_log import McapLog
from boatland.record.rerun_log import RerunLog
from boatland.checks.files import default_scenario_path, load_checked
from boatland.trial.simulate import simulate


@dataclass
class Recorded:
    result: object
    mcap: Path
    rrd: Path
    run_id: str
    scenario: object
    db: object


@pytest.fixture(scope="session")
def landing():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(default_scenario_path())
    return scenario, db


@pytest.fixture(scope="session")
def recorded(landing, tmp_path_factory) -> Recorded:
    """The default trial shortened to 60 s (waves from 20 s) in the sea operators quote as the limit of
    push-on transfers, Hs 1.5 m (Grøtting 2015) — four times this landing's head-sea limit (README "Known
    limit"), so that the minute has slips beyond 0.1 m — logged to MCAP and .rrd."""
    scenario, db = landing
    sc = scenario.replace({"simulation.duration": 60.0, "sea.Hs": 1.5})
    d = tmp_path_factory.mktemp("recorded")
    run_id = str(uuid.uuid4())
    result = simulate(sc, db, sinks=[McapLog(d / "run.mcap", run_id=run_id),
                                     RerunLog(f"save={d / 'live.rrd'}", recording_id=run_id, quiet=True)])
    return Recorded(result, d / "run.mcap", d / "live.rrd", run_id, sc, db)
