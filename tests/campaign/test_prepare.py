"""Work done once per campaign (issue 16): the radiation memory checked once, the kernel arrays and the
pile's scattered-wave tables made once per case and shipped to the workers — the same trials, bit for bit,
as a worker that makes everything itself. In-process; the executors' own tests (1 and 2 local workers,
a real Dask cluster) are in test_runner.py."""

import pickle

import numpy as np
import pytest

import boatland.campaign.prepare as prepare
import boatland.checks.memory
import boatland.sea.pile as pd
import boatland.trial.simulate as sim
from boatland.campaign.plan import load_campaign
from boatland.campaign.prepare import CasePreparation, campaign_tables, check_cases, prepare_cases, start_background
from boatland.campaign.runner import execute_trial, run_campaign
from boatland.checks.files import load, resolve_database
from boatland.landing.setup import Setup

from test_runner import campaign_file, same, summaries

LOADERS = (load, resolve_database)


def made_again(*args, **kwargs):
    raise AssertionError("made again")


def bits(row):
    return {k: np.float64(v).tobytes() if isinstance(v, float) else v for k, v in row.items() if k != "wall_time"}


@pytest.fixture
def mini(tmp_path, monkeypatch):
    monkeypatch.setattr(prepare, "_CHECKED", {})
    monkeypatch.setattr(prepare, "_WORKER", {})
    path = campaign_file(tmp_path, seeds=2, duration=30.0)
    return path, load_campaign(path, load_scenario=load)


@pytest.mark.slow
def test_check_cases_makes_each_memory_once_per_campaign(mini, monkeypatch):
    path, campaign = mini
    calls = []
    real = Setup.memory
    monkeypatch.setattr(Setup, "memory", lambda *a: calls.append(a) or real(*a))
    first = check_cases(campaign, resolve_database)
    assert check_cases(campaign, resolve_database) == first and len(calls) == 1   # four cases, one memory
    changed = path.with_name("changed.toml")
    changed.write_text(path.read_text().replace("master_seed = 11", "master_seed = 12"))
    check_cases(load_campaign(changed, load_scenario=load), resolve_database)
    assert len(calls) == 2                                          # another campaign is checked again


@pytest.mark.slow
def test_shipped_case_data_gives_the_trial_a_worker_makes_itself(mini, monkeypatch):
    path, campaign = mini
    check_cases(campaign, resolve_database)
    shared = prepare_cases(campaign, resolve_database)
    assert sorted(shared) == [0, 1, 2, 3] and all(len(d.tables) == 1 for d in shared.values())
    assert shared[0].tables[0] is shared[2].tables[0]            # same direction (Hs differs): one table
    spec = campaign.trials()[3]                                     # case 1, second seed
    own = execute_trial(campaign, spec, LOADERS)                    # memory, check, arrays, tables: its own
    monkeypatch.setattr(prepare, "_WORKER", {})
    monkeypatch.setattr(pd, "_TABLES", {})
    monkeypatch.setattr(Setup, "memory", made_again)
    monkeypatch.setattr(boatland.checks.memory, "check_radiation", made_again)
    monkeypatch.setattr(sim, "compile_motion", made_again)
    monkeypatch.setattr(pd, "_scattered_columns", made_again)
    shipped = execute_trial(pickle.loads(pickle.dumps(campaign)), spec, LOADERS, None,
                            pickle.loads(pickle.dumps(shared[spec.case])))
    assert shipped["status"] == 0 and bits(shipped) == bits(own)


@pytest.mark.slow
def test_a_case_that_cannot_be_prepared_runs_as_before(mini, tmp_path, monkeypatch):
    """Its trials make everything themselves (and would meet and record the same error): the store is the
    same as with every case prepared."""
    path, campaign = mini
    run_campaign(campaign, tmp_path / "all.h5", loaders=LOADERS, workers=1)
    real = sim.pile_tables

    def refuse_case_2(setup):                                       # Hs 0.8 m, head seas
        sea = setup.scenario.document["sea"]
        if (sea["Hs"], sea["relative_direction_deg"]) == (0.8, 180.0):
            raise RuntimeError("cannot prepare")
        return real(setup)

    monkeypatch.setattr(sim, "pile_tables", refuse_case_2)
    monkeypatch.setattr(prepare, "_WORKER", {})
    monkeypatch.setattr(pd, "_TABLES", {})
    assert sorted(prepare_cases(campaign, resolve_database)) == [0, 1, 3]
    run_campaign(campaign, tmp_path / "some.h5", loaders=LOADERS, workers=1)
    same(summaries(tmp_path / "all.h5"), summaries(tmp_path / "some.h5"))


@pytest.mark.slow
def test_the_tables_of_every_case_are_made_together_beside_the_checks(mini, monkeypatch, tmp_path):
    """The campaign's pile tables (its two wave directions) come from one pass of the series in the
    background process (a real forked process, started before the checks); the campaign's own process
    then makes none, and they are the tables it would have made itself, bit for bit. (An empty disk cache,
    then none: the making is what is counted.)"""
    path, campaign = mini
    monkeypatch.setenv("BOATLAND_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(pd, "_TABLES", {})
    background = start_background(campaign, LOADERS, "local", 2)
    try:
        made = background.tables()
        passes = []
        columns = pd._scattered_columns
        monkeypatch.setattr(pd, "_scattered_columns", lambda db, layout, k, th: passes.append(len(th)) or
                            columns(db, layout, k, th))
        monkeypatch.setenv("BOATLAND_CACHE_DIR", "off")     # made here, not read back from the background's
        own = campaign_tables(campaign, resolve_database)
        assert passes == [2] and len(made) == len(own) == 2
        assert [(t.key, t.reduced.tobytes()) for t in made] == [(t.key, t.reduced.tobytes()) for t in own]
        monkeypatch.setattr(pd, "_TABLES", {})
        monkeypatch.setattr(pd, "_scattered_columns", made_again)
        check_cases(campaign, resolve_database)
        prepared = CasePreparation(campaign, resolve_database, background)
        data = [prepared.get(case) for case in range(4)]
        assert all(d is not None and len(d.tables) == 1 for d in data)
    finally:
        background.close()


def test_warnings_the_cases_share_are_one_line():
    """A warning every case gives (its vessel's, typically) is printed once with the cases that gave it."""
    from boatland.campaign.prepare import _grouped

    same = "radiation.method: slightly negative damping in the landed sway mode"
    warns = [(i, f"case {i} (Tp={i})", same) for i in range(24)] + [(3, "case 3 (Tp=3)", "sea.Hs: high")]
    assert _grouped(warns, 24) == (f"cases 0–23 (all 24): {same}", "case 3 (Tp=3): sea.Hs: high")
    assert _grouped([(0, "case 0", same), (2, "case 2", same)], 4) == (f"cases 0, 2 (2 of 4): {same}",)
