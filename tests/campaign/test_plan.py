"""Campaign plans: changes by key path (``boatland campaign --set``, ``boatland.campaign(**changes)``), a campaign
given as a document, and what a store records of it."""

import tomllib
import warnings

import pytest

from boatland.campaign.plan import change_campaign, load_campaign
from boatland.checks.files import load
from boatland.resources import shipped_file
from boatland.tomlspec import SpecError

DEMO = shipped_file("demo", "campaign")


def demo(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_campaign(DEMO, load_scenario=load, **kw)


def test_a_change_goes_where_its_key_path_says():
    doc = tomllib.loads(DEMO.read_text(encoding="utf-8"))
    out = change_campaign(doc, {"seeds": 2, "set.thrust.force": 100e3, "axes.sea.Hs": [0.5],
                                "isee.accept": "best", "incidents.slip_distance": [0.3], "master_seed": None})
    assert out["seeds"] == 2 and out["set"]["thrust.force"] == 100e3 and out["axes"]["sea.Hs"] == [0.5]
    assert out["isee"] == {"accept": "best"} and out["incidents"]["slip_distance"] == [0.3]
    assert "master_seed" not in out and doc["seeds"] == 4 and "thrust.force" not in doc["set"]   # a copy
    with pytest.raises(SpecError, match="seeds is not a table"):
        change_campaign(doc, {"seeds.x": 1})


def test_a_changed_campaign_is_another_campaign_and_records_what_runs():
    plain, changed = demo(), demo(changes={"seeds": 2, "axes.sea.Hs": [0.5]})
    assert changed.n_trials == 4 and plain.n_trials == 32
    assert changed.digest() != plain.digest() and changed.identity != plain.identity
    assert plain.text == DEMO.read_text(encoding="utf-8")             # unchanged: the file as read
    head, body = changed.text.split("\n", 1)
    assert head == f"# {DEMO}, changed: seeds = 2, axes.sea.Hs = [0.5]"
    assert tomllib.loads(body) == changed.document                  # changed: the document that runs
    assert demo(changes={"seeds": 2, "axes.sea.Hs": [0.5]}).digest() == changed.digest()


def test_a_refused_change_is_named_as_the_change():
    with pytest.raises(SpecError) as err:
        demo(changes={"seeds": 0, "access": -1}, changed_by="--set ")
    assert set(err.value.keys()) == {"--set seeds", "--set access"}
    with pytest.raises(SpecError) as err:
        demo(changes={"set.sea.Hs": -1.0, "axes.sea.Tp": [0.0]}, changed_by="--set ")
    assert err.value.keys() == ["--set set.sea.Hs"]                 # the axes are checked on a valid base
    with pytest.raises(SpecError) as err:
        demo(changes={"seeds": 0})
    assert err.value.keys() == ["seeds"]


def test_a_campaign_document_runs_as_its_file_would(tmp_path, monkeypatch):
    doc = tomllib.loads(DEMO.read_text(encoding="utf-8"))
    doc["scenario"] = str(shipped_file("ctv_landing"))
    monkeypatch.chdir(tmp_path)
    as_dict = load_campaign(doc, load_scenario=load)
    assert as_dict.source == "<campaign demo>" and not as_dict.from_file
    assert as_dict.input_files()[0] == shipped_file("ctv_landing").resolve()
    assert as_dict.identity == demo(changes={"scenario": doc["scenario"]}).identity
    assert tomllib.loads(as_dict.text.split("\n", 1)[1]) == doc
    doc["scenario"] = "nowhere.toml"                               # relative to the working directory
    with pytest.raises(SpecError, match=f"<campaign demo>: scenario: no such file: {tmp_path / 'nowhere.toml'}"):
        load_campaign(doc, load_scenario=load)
