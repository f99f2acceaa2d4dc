"""The notebook API: ``boatland.simulate`` / ``load_scenario`` with changes as key paths, lazy exports."""

import subprocess
import sys
from pathlib import Path

import pytest

import boatland
from boatland.errors import BoatlandInputError
from boatland.tomlspec import SpecError

ROOT = Path(__file__).resolve().parents[1]


def test_exports_are_lazy():
    code = "import boatland, sys; print('boatland.trial.simulate' in sys.modules, 'numba' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["False", "False"]
    assert {"simulate", "load_scenario", "open_store", "Result"} <= set(boatland.__all__)
    with pytest.raises(AttributeError):
        boatland.nothing_here


def test_changes_as_keywords_dunder_or_dict():
    a = boatland.load_scenario("ctv_landing", **{"sea.Hs": 0.7})
    b = boatland.load_scenario("ctv_landing", sea__Hs=0.7)
    c = boatland.load_scenario(changes={"sea.Hs": 0.7})
    assert a.sea.waves.parts[0].Hs == b.sea.waves.parts[0].Hs == c.sea.waves.parts[0].Hs == 0.7
    assert boatland.load_scenario(a, **{"thrust.force": 6e4}).thrust.force == 6e4
    with pytest.raises(TypeError, match="given twice"):
        boatland.load_scenario(changes={"sea.Hs": 1.0}, sea__Hs=2.0)


def test_problems_come_all_at_once_with_key_paths():
    with pytest.raises(SpecError) as err:
        boatland.load_scenario(**{"sea.Hs": -1.0, "fender.mu_s": "x"})
    assert {k for k, _ in err.value.problems} == {"sea.Hs", "fender.mu_s"}
    with pytest.raises(BoatlandInputError, match="not a shipped scenario"):
        boatland.load_scenario("no_such_scenario")


@pytest.mark.slow
def test_simulate_returns_a_result_with_verdict_and_dataset(tmp_path):
    r = boatland.simulate("ctv_landing", simulation__duration=40.0, **{"sea.Hs": 0.1}, log=tmp_path / "r.mcap")
    assert isinstance(r, boatland.Result)
    assert r.verdict().held and r.inputs["Hs"] == 0.1
    ds = r.to_xarray()
    assert ds.attrs["input_Hs_m"] == 0.1 and ds.sizes["time"] == len(r.t)
    assert (tmp_path / "r.mcap").stat().st_size > 1000


@pytest.mark.slow
def test_campaign_returns_what_the_command_stores(tmp_path):
    """``boatland.campaign('demo', seeds=2)`` (as the issue's one-liner, in a fresh process and folder) returns the
    Dataset of the store ``boatland campaign demo --set seeds=2`` writes: equal in everything but wall times."""
    xr = pytest.importorskip("xarray")
    api, cli = tmp_path / "api", tmp_path / "cli"
    api.mkdir(), cli.mkdir()
    code = ("import boatland; ds = boatland.campaign('demo', seeds=2, progress=False); "
            "ds.drop_vars('wall_time').to_netcdf('ds.nc')")
    subprocess.run([sys.executable, "-c", code], cwd=api, check=True, capture_output=True, text=True)
    assert (api / "demo.h5").is_file()                              # the command's default store, in the cwd
    subprocess.run([sys.executable, "-m", "boatland", "campaign", "demo", "--set", "seeds=2"], cwd=cli, check=True,
                   capture_output=True, text=True)
    stored = boatland.open_store(cli / "demo.h5").drop_vars("wall_time")
    with xr.open_dataset(api / "ds.nc") as returned:
        xr.testing.assert_identical(returned.load(), stored)
    assert stored.sizes["trial"] == 16 and stored.attrs["seeds_per_case"] == 2
    assert stored.attrs["campaign_file"].startswith(f"# {boatland.api.campaign_path('demo')}, changed: seeds = 2\n")


@pytest.mark.slow
def test_campaign_resumes_its_store_and_refuses_another_campaigns(tmp_path):
    doc = {"name": "tiny", "scenario": "ctv_landing", "seeds": 1, "access": 5.0,
           "set": {"radiation.method": "state_space"}, "axes": {"sea.Hs": [0.3, 0.6]}}
    seen = []
    ds = boatland.campaign(doc, store=tmp_path / "t.h5", progress=lambda done, total: seen.append((done, total)))
    assert seen[0] == (0, 2) and seen[-1] == (2, 2) and list(ds.Hs.values) == [0.3, 0.6]
    seen.clear()
    again = boatland.campaign(doc, store=tmp_path / "t.h5", progress=lambda d, t: seen.append((d, t)))
    assert seen == [(2, 2)] and again.drop_vars("wall_time").identical(ds.drop_vars("wall_time"))
    with pytest.raises(BoatlandInputError, match="holds results of .tiny. before campaign <campaign tiny> changed"):
        boatland.campaign(doc, store=tmp_path / "t.h5", changes={"set.thrust.force": 100e3}, progress=False)
    with pytest.raises(BoatlandInputError, match="an output never replaces an input"):
        boatland.campaign(doc, store=boatland.api.scenario_path("ctv_landing"), progress=False)
    with pytest.raises(SpecError, match="seeds: must be ≥ 1"):
        boatland.campaign(doc, seeds=0)
    with pytest.raises(BoatlandInputError, match="not a shipped campaign"):
        boatland.campaign("no_such_campaign")
    assert not list(tmp_path.glob("*.h5.*")) and sorted(p.name for p in tmp_path.iterdir()) == ["t.h5"]


@pytest.mark.slow
def test_operability_is_what_the_command_prints():
    """``boatland.operability`` judges as ``boatland operability`` does (the same JSON numbers)."""
    import json

    hindcast = ROOT / "scenarios" / "example_hindcast.csv"
    op = boatland.operability("ctv_landing", hindcast, landings=[45, 165, 285], **{"thrust.force": 200e3})
    r = subprocess.run([sys.executable, "-m", "boatland", "operability", "ctv_landing", str(hindcast), "--landing",
                        "45", "--landing", "165", "--landing", "285", "--set", "thrust.force=200e3", "--json"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    cli = json.loads(r.stdout)["results"][0]
    assert list(cli["availability"].values()) == op.availability().tolist()
    assert cli["thrust"] == 200e3 and cli["window"]["hours"] == 4.0
    assert cli["window"]["probability"]["best"] == op.windows[-1].probability()
