"""The notebook API: ``boatland.simulate`` / ``load_scenario`` with changes as key paths, lazy exports."""

import subprocess
import sys

import pytest

import boatland
from boatland.errors import BoatlandInputError
from boatland.tomlspec import SpecError


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
