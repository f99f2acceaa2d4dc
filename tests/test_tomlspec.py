"""The TOML validation helper: all problems at once, with key paths, did-you-mean, line/column."""

from __future__ import annotations

import pytest

from boatland.errors import BoatlandInputError
from boatland.tomlspec import Key, Problems, SpecError, Table, parse_toml, parse_toml_file, validate

SCHEMA = Table({
    "name": Key(str, required=True),
    "sea": Table({
        "hs": Key(float, required=True, gt=0.0),
        "tp": Key(float, default=8.0, gt=0.0),
        "spectrum": Key(str, default="jonswap", choices=("jonswap", "pm", "tma")),
        "seed": Key(int, ge=0),
        "long_crested": Key(bool, default=True),
    }, required=True),
})


def check(text, source="s.toml"):
    problems = Problems(source)
    data = validate(parse_toml(text, source), SCHEMA, problems)
    return data, problems


def test_valid_document_gets_defaults_and_types():
    data, problems = check('name = "a"\n[sea]\nhs = 2\n')
    assert not problems
    assert data == {"name": "a", "sea": {"hs": 2.0, "tp": 8.0, "spectrum": "jonswap", "long_crested": True}}
    assert isinstance(data["sea"]["hs"], float)


def test_unknown_key_suggests_the_closest():
    _, problems = check('name = "a"\n[sea]\nhs = 2\ntpp = 9\n')
    assert problems.items == [("sea.tpp", "unknown key (did you mean 'tp'?)")]


def test_unknown_key_without_close_match_lists_the_valid_ones():
    _, problems = check('name = "a"\nzzz = 1\n[sea]\nhs = 2\n')
    key, msg = problems.items[0]
    assert key == "zzz" and "valid keys here: name, sea" in msg


def test_all_problems_at_once_with_key_paths():
    text = 'nam = "a"\n[sea]\nhs = -1\ntp = "long"\nspectrum = "jonswp"\nseed = 1.5\nlong_crested = 1\n'
    _, problems = check(text)
    found = dict(problems.items)
    assert set(found) == {"nam", "name", "sea.hs", "sea.tp", "sea.spectrum", "sea.seed", "sea.long_crested"}
    assert "did you mean 'name'" in found["nam"]
    assert found["name"].startswith("missing")
    assert found["sea.hs"] == "must be > 0, got -1"
    assert found["sea.tp"] == "must be a number, got 'long'"
    assert "did you mean 'jonswap'" in found["sea.spectrum"]
    assert found["sea.seed"].startswith("must be an integer")
    assert found["sea.long_crested"].startswith("must be true or false")
    with pytest.raises(SpecError) as info:
        problems.raise_if_any()
    err = info.value
    assert isinstance(err, BoatlandInputError)
    lines = str(err).splitlines()
    assert lines[0] == "s.toml: 7 problems:"
    assert "  s.toml: sea.hs: must be > 0, got -1" in lines
    assert err.keys()[0] == "nam"


def test_single_problem_is_one_line():
    _, problems = check('name = "a"\n[sea]\nhs = 0\n')
    with pytest.raises(SpecError, match=r"^s\.toml: sea\.hs: must be > 0, got 0$"):
        problems.raise_if_any()


def test_booleans_are_not_numbers_and_nan_is_rejected():
    _, problems = check('name = "a"\n[sea]\nhs = true\ntp = nan\n')
    found = dict(problems.items)
    assert found["sea.hs"] == "must be a number, got true"
    assert "finite" in found["sea.tp"]


def test_missing_required_table_and_table_type():
    _, problems = check('name = "a"\n')
    assert ("sea", "missing table") in problems.items
    assert problems.has("sea") and problems.has("sea.hs") and not problems.has("name")
    _, problems = check('name = "a"\nsea = 3\n')
    assert problems.items == [("sea", "must be a table ([sea]), got 3")]


def test_syntax_error_names_line_and_column():
    with pytest.raises(SpecError) as info:
        parse_toml('name = "a"\n[sea]\nhs = = 2\n', "bad.toml")
    msg = str(info.value)
    assert msg.startswith("bad.toml: line 3, column 6: TOML syntax error")
    assert "\n" not in msg


def test_missing_file(tmp_path):
    with pytest.raises(SpecError, match="no such file \\(the TOML file\\)"):
        parse_toml_file(tmp_path / "nope.toml")


def test_dump_toml_round_trips_every_shipped_file():
    import tomllib

    from boatland.resources import shipped_file, shipped_names
    from boatland.tomlspec import dump_toml

    files = [shipped_file(n) for n in shipped_names()] + [shipped_file(n, "campaign") for n in shipped_names("campaign")]
    assert len(files) > 10
    for f in files:
        doc = tomllib.loads(f.read_text(encoding="utf-8"))
        assert tomllib.loads(dump_toml(doc)) == doc, f
    odd = {"a b": 1, "x": float("inf"), "t": {"sea.Hs": [0.5, 1.0], "q": 'say "hi"\n', "n": {"deep": True}}}
    assert tomllib.loads(dump_toml(odd)) == odd
