"""Scenario files: the validated format, all problems at once with key paths, the JSON Schema. (Their checks
against a database: tests/checks/test_physical.py; the scenario on its vessel: tests/landing/test_setup.py.)"""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.scenario.scenario import ScenarioWarning, json_schema, load_scenario, scenario_from_dict
from boatland.scenario.schema import MEMORY_DEFAULT
from boatland.sea.states import RegularWave, SeaState
from boatland.tomlspec import SpecError

from box_vessel import BASE, make  # a CTV-like scenario document and its builder
from boatland.landing.setup import time_step

SCENARIOS = Path(__file__).resolve().parents[2] / "scenarios"
SHIPPED = sorted(SCENARIOS.glob("*.toml"))


def problems_of(changes=None, remove=(), **kw) -> dict[str, str]:
    with pytest.raises(SpecError) as info:
        make(changes, remove, **kw)
    return dict(info.value.problems)


# ---------------------------------------------------------------------------------------- shipped files
@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.name)
def test_every_shipped_scenario_loads(path):
    s = load_scenario(path)
    assert s.name == path.stem
    assert s.simulation.duration > 0 and time_step(s) > 0
    assert s.source == str(path)


def test_shipped_set_is_complete():
    names = {p.stem for p in SHIPPED}
    assert {"ctv_landing", "ctv24_landing", "ctv_regular", "ctv_free_decay", "model2_j01", "model2_j02",
            "model2_j03", "model2_j03_52N", "model2_j04"} <= names


#: Hs of the default trial: at ctv27's limit in head seas at Tp 7 s (README, "Known limit": 0.375 m in the
#: time domain, 0.376 m by the screening, for P(first slip) = 1.19e-3 per 30-min access).
DEFAULT_HS = 0.4


def test_quick_start_trial_is_what_the_issue_says():
    s = load_scenario(SCENARIOS / "ctv_landing.toml")
    assert s.vessel.database == "ctv27" and s.vessel.is_builtin
    assert isinstance(s.sea.waves, SeaState)
    p = s.sea.waves.parts[0]
    assert (p.kind, p.Hs, p.Tp, p.gamma) == ("jonswap", DEFAULT_HS, 7.0, 3.3)
    assert (p.direction_deg - s.vessel.heading_deg) % 360 == 180.0  # head seas
    assert s.thrust.force == 150e3 and (s.fender.mu_s, s.fender.mu_k) == (0.8, 0.7)
    assert (s.fender.shear_stiffness, s.fender.shear_damping_ratio) == (3.0e6, 0.05)
    assert s.landing.monopile_diameter == 6.5 and len(s.landing.struts) == 2
    assert math.dist(s.landing.struts[0].position, s.landing.struts[1].position) == pytest.approx(1.5)
    assert all(pt[2] == 1.9 for pt in s.fender.points)   # mid-height of the bow fender, wet deck 1.4 m to deck 2.4 m
    assert (s.simulation.duration, time_step(s)) == (600.0, 0.05)


@pytest.mark.parametrize("tag, wp, hs, nu, thrust", [("j01", 3.31, 0.125, 0, 123.84), ("j02", 4.44, 0.125, 0, 123.84),
                                                     ("j03", 4.97, 0.1, 0, 123.84), ("j03_52N", 4.97, 0.1, 0, 52.0),
                                                     ("j04", 4.97, 0.1, 15, 123.84)])
def test_model2_trials_follow_seed001(tag, wp, hs, nu, thrust):
    s = load_scenario(SCENARIOS / f"model2_{tag}.toml")
    p = s.sea.waves.parts[0]
    assert p.omega_p == pytest.approx(wp) and p.Hs == hs
    assert abs(180 - (p.direction_deg - s.vessel.heading_deg) % 360) == pytest.approx(nu)
    assert s.thrust.force == thrust
    f = s.fender
    assert (f.mu_k, f.mu_s, f.k_v, f.delta, f.v_ref, f.stiffness, f.damping) == (0.7, 0.9, 0.2, 1.5, 0.2, 500.0, 250.0)
    assert time_step(s) == pytest.approx(p.Tp / 100, rel=1e-4)
    assert s.landing.monopile_diameter == 0.5


# ---------------------------------------------------------------------------------------- errors
def test_unknown_keys_get_did_you_mean_with_key_path():
    doc = copy.deepcopy(BASE)
    doc["fender"]["stifness"] = doc["fender"].pop("stiffness")
    doc["thurst"] = doc.pop("thrust")
    with pytest.raises(SpecError) as info:
        scenario_from_dict(doc, source="t.toml")
    found = dict(info.value.problems)
    assert found["fender.stifness"] == "unknown key (did you mean 'stiffness'?)"
    assert found["thurst"] == "unknown key (did you mean 'thrust'?)"
    assert found["fender.stiffness"].startswith("missing")


def test_five_problems_are_reported_at_once(tmp_path):
    text = """
name = "bad"
[simulation]
duration = 60.0
dt = 90.0
[vessel]
databse = "ctv24"
[landing]
monopile_diameter = 6.5
bearing_deg = 180.0
strut_spacing = 1.5
strut_diameter = 0.35
standoff = 1.2
[fender]
points = [[12.3, 0.75, 1.5], [12.3, -0.75, -0.2]]
stiffness = 1e6
damping = 4e4
mu_s = 0.6
mu_k = 0.5
[sea]
kind = "jonswap"
Hs = -1.5
Tp = 7.0
relative_direction_deg = 180.0
[initial]
rotation_deg = [0.0, 45.0, 0.0]
"""
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(SpecError) as info:
        load_scenario(path)
    err = info.value
    assert set(err.keys()) == {"vessel.databse", "fender.points[1]", "sea.Hs", "initial.rotation_deg[1]",
                               "simulation.dt"}
    lines = str(err).splitlines()
    assert lines[0] == f"{path}: 5 problems:"
    assert any("vessel.databse: unknown key (did you mean 'database'?)" in ln for ln in lines)
    assert isinstance(err, BoatlandInputError) and err.exit_status == 2


def test_dt_too_large_for_the_waves_is_a_problem():
    found = problems_of({"simulation.dt": 0.2})
    assert "too large for the waves" in found["simulation.dt"] and "dt ≤ 0.117 s" in found["simulation.dt"]


def test_malformed_toml_names_line_and_column(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text('name = "x"\n[simulation]\nduration = = 5\n')
    with pytest.raises(SpecError, match=r"broken\.toml: line 3, column 12: TOML syntax error"):
        load_scenario(path)


@pytest.mark.parametrize("changes, key, text", [
    ({"sea.Hs": -1.0}, "sea.Hs", "must be > 0"),
    ({"fender.points": [[-3.0, 0.75, 1.5], [12.3, -0.75, 1.5]]}, "fender.points[0]", "behind the reference point"),
    ({"fender.points": [[12.3, 0.75, 1.5], [12.3, -0.75, -0.1]]}, "fender.points[1]", "under the waterline"),
    ({"fender.mu_k": 0.8}, "fender.mu_k", "exceeds μ_s"),
    ({"landing.standoff": 0.1}, "landing.standoff", "into the pile surface"),
    ({"vessel.heading_deg": 180.0}, "vessel.heading_deg", "does not push towards the landing"),
    ({"sea.gamma": 12.0}, "sea.gamma", "≤ 10"),
    ({"simulation.dt": 200.0}, "simulation.dt", "not smaller than simulation.duration"),
    ({"fender.points": [[12.3, 0.75, 1.5]]}, "fender.points", "1 point(s) for 2 strut(s)"),
    ({"fender.points": [[12.3, 3.0, 1.5], [12.3, -0.75, 1.5]]}, "fender.points[0]", "misses struts[0]"),
])
def test_impossible_values_are_rejected_with_their_key(changes, key, text):
    found = problems_of(changes)
    assert key in found, found
    assert text in found[key]


def test_strut_normal_pointing_into_the_pile_is_rejected():
    landing = {"monopile_diameter": 6.5,
               "struts": [{"position": [-4.45, 0.75], "diameter": 0.35, "normal_deg": 0.0},
                          {"position": [-4.45, -0.75], "diameter": 0.35, "normal_deg": 180.0}]}
    found = problems_of({"landing": landing})
    assert "points into the monopile" in found["landing.struts[0].normal_deg"]


def test_strut_normal_pointing_away_from_the_vessel_is_rejected():
    # struts beside the pile with normals along +y (away from the pile), but the vessel placed at −x
    landing = {"monopile_diameter": 6.5,
               "struts": [{"position": [0.75, 4.45], "diameter": 0.35, "normal_deg": 90.0},
                          {"position": [-0.75, 4.45], "diameter": 0.35, "normal_deg": 90.0}]}
    found = problems_of({"landing": landing, "vessel.position": [-20.0, 0.0], "vessel.heading_deg": 270.0})
    assert "points away from the vessel" in found["landing.struts[0].normal_deg"]


def test_starting_inside_the_struts_is_rejected():
    found = problems_of({"vessel.position": [-16.0, 0.0]})
    assert "inside the contact plane" in found["vessel.position"]


def test_compact_and_explicit_landing_are_exclusive_and_compact_needs_all_keys():
    found = problems_of({"landing.struts": [{"position": [-4.45, 0.0], "diameter": 0.35, "normal_deg": 180.0}]})
    assert "not both" in found["landing.struts"]
    doc = copy.deepcopy(BASE)
    del doc["landing"]["standoff"]
    with pytest.raises(SpecError) as info:
        scenario_from_dict(doc)
    assert dict(info.value.problems)["landing.standoff"].startswith("missing")


def test_sea_keys_must_belong_to_the_kind():
    found = problems_of({"sea": {"kind": "regular", "H": 1.0, "T": 6.0, "Hs": 1.0, "direction_deg": 0.0}})
    assert "not used by kind = 'regular'" in found["sea.Hs"]
    found = problems_of({"sea": {"kind": "jonswap", "Hs": 1.0, "Tp": 6.0, "omega_p": 1.0, "direction_deg": 0.0}})
    assert found["sea.omega_p"] == "give either sea.Tp or sea.omega_p, not both"
    found = problems_of({"sea": {"kind": "jonswap", "Hs": 1.0, "Tp": 6.0}})
    assert found["sea.direction_deg"].startswith("missing: give sea.direction_deg or sea.relative_direction_deg")
    found = problems_of({"sea": {"Hs": 1.0}})
    assert found["sea.kind"].startswith("missing")


def test_unknown_builtin_database_gets_did_you_mean(tmp_path):
    found = problems_of({"vessel.database": "ctv42"}, databases=("ctv24", "model2"), base_dir=tmp_path)
    assert "did you mean 'ctv24'" in found["vessel.database"]
    found = problems_of({"vessel.database": "db/missing.h5"}, base_dir=tmp_path)
    assert found["vessel.database"].startswith("file not found")
    (tmp_path / "mine.h5").write_bytes(b"")
    s = make({"vessel.database": "mine.h5"}, base_dir=tmp_path)
    assert s.vessel.database_path == tmp_path / "mine.h5" and not s.vessel.is_builtin


# ---------------------------------------------------------------------------------------- derived values
def test_derived_start_pose_touches_the_struts():
    s = make()
    assert s.vessel.heading_derived and s.vessel.heading_deg == 0.0
    x, y, psi = s.start_pose()
    # struts at x = −(3.25 + 1.2), contact planes 0.175 m further out, fender at body x = 12.3
    assert (x, y, psi) == (pytest.approx(-4.45 - 0.175 - 12.3), pytest.approx(0.0), 0.0)
    assert s.landing.struts[0].position[1] > 0  # struts[0] on the vessel's port side


def test_derived_pose_for_a_rotated_landing():
    s = make({"landing.bearing_deg": 195.0})
    assert s.vessel.heading_deg == pytest.approx(15.0)
    R = np.array([[math.cos(math.radians(15)), -math.sin(math.radians(15))],
                  [math.sin(math.radians(15)), math.cos(math.radians(15))]])
    P = s.fender.points_array[:, :2] @ R.T + np.array(s.vessel.position)
    gaps = [(P[i] - st.plane_point) @ st.normal for i, st in enumerate(s.landing.struts)]
    assert gaps == [pytest.approx(0.0, abs=1e-12)] * 2
    # relative directions follow the derived heading
    assert s.sea.waves.parts[0].direction_deg == pytest.approx(195.0)


def test_defaults_are_filled_once():
    s = make(remove=("simulation.dt", "thrust", "sea"))
    assert s.simulation.dt is None and time_step(s) == 0.05
    assert s.simulation.start_ramp == 0.0 and s.thrust is None and s.sea is None
    assert s.radiation.method == "state_space" and s.radiation.memory == MEMORY_DEFAULT
    assert s.incidents.slip_distance == (0.1,) and s.incidents.roll_limit_deg == (10.0,)
    assert (s.fender.k_v, s.fender.v_ref, s.fender.delta, s.fender.sideways) == (0.0, 0.2, 1.5, True)
    assert np.array_equal(s.initial.displacement, np.zeros(6))
    s = make({"sea.Tp": 3.0}, remove=("simulation.dt",))
    assert time_step(s) == pytest.approx(0.03) and s.simulation.start_ramp == 6.0


@pytest.mark.parametrize("name", ["ferreira-gonzalez-2023-table5.4", "seed001-table5.4"])
def test_preset_fills_and_explicit_keys_override(name):
    """Ferreira González (2023) Table 5.4, under its name and its older alias (stored by its name)."""
    s = make({"fender": {"preset": name, "points": BASE["fender"]["points"], "mu_s": 1.0}})
    assert (s.fender.mu_s, s.fender.mu_k, s.fender.stiffness, s.fender.preset) == \
        (1.0, 0.7, 500.0, "ferreira-gonzalez-2023-table5.4")
    assert s.fender.mu(0.0) == pytest.approx(1.0)
    assert s.fender.mu(10.0) == pytest.approx(0.7 + 0.2 * 10.0)


def test_initial_state_is_converted_to_si():
    s = make({"initial": {"displacement": [0.0, 0.0, 0.3], "rotation_deg": [0.0, 2.0, 0.0],
                          "angular_velocity_deg": [1.0, 0.0, 0.0]}})
    assert s.initial.displacement == pytest.approx([0, 0, 0.3, 0, math.radians(2), 0])
    assert s.initial.velocity == pytest.approx([0, 0, 0, math.radians(1), 0, 0])


def test_sum_of_spectra_and_regular_and_calm():
    s = make({"sea": {"parts": [{"Hs": 1.0, "Tp": 10.0, "kind": "pm", "direction_deg": 45.0},
                                {"Hs": 1.2, "omega_p": 2.0, "relative_direction_deg": 180.0, "spreading": 10.0}]}},
             remove=("simulation.dt",))
    a, b = s.sea.waves.parts
    assert (a.kind, a.gamma, a.direction_deg) == ("pm", 1.0, 45.0)
    assert (b.Tp, b.direction_deg, b.spreading) == (pytest.approx(2 * math.pi / 2.0), 180.0, 10.0)
    assert s.sea.kind == "parts" and time_step(s) == pytest.approx(b.Tp / 100)
    s = make({"sea": {"kind": "regular", "H": 0.5, "T": 6.0, "direction_deg": 135.0}})
    assert isinstance(s.sea.waves, RegularWave) and s.sea.waves.direction_deg == 135.0
    assert make({"sea": {"kind": "none"}}).sea is None


def test_measured_record(tmp_path):
    t = np.arange(0, 198, 0.1)  # 33 periods: the peak falls on an FFT bin
    eta = 0.5 * np.cos(2 * np.pi * t / 6.0)
    (tmp_path / "gauge.csv").write_text("\n".join(f"{a:.3f},{b:.6f}" for a, b in zip(t, eta)))
    s = make({"sea": {"kind": "measured", "file": "gauge.csv", "direction_deg": 180.0, "n_keep": 20}},
             base_dir=tmp_path)
    assert s.sea.peak_period == pytest.approx(6.0, rel=1e-3) and s.sea.waves.n_components == 20
    found = problems_of({"sea": {"kind": "measured", "file": "nope.csv", "direction_deg": 0.0}}, base_dir=tmp_path)
    assert found["sea.file"].startswith("file not found")


def test_replace_revalidates_with_key_paths():
    s = make()
    t = s.replace({"sea.Hs": 2.0, "simulation.seed": 7, "thrust": None})
    assert t.sea.waves.parts[0].Hs == 2.0 and t.simulation.seed == 7 and t.thrust is None
    assert s.sea.waves.parts[0].Hs == 1.5  # the original is unchanged
    assert t.digest() != s.digest() and s.digest() == make().digest()
    with pytest.raises(SpecError) as info:
        s.replace({"sea.Hs": -2.0})
    assert info.value.keys() == ["sea.Hs"]


def test_doubtful_values_warn():
    with pytest.warns(ScenarioWarning, match="outside the range 0.5–2"):
        s = make({"fender.delta": 3.0})
    assert any("fender.delta" in w for w in s.warnings)


# ---------------------------------------------------------------------------------------- JSON Schema
def _mini_validate(schema, doc, path="$") -> list[str]:
    """A tiny JSON-Schema checker for the keywords json_schema() emits (used when jsonschema is absent)."""
    if schema is True:
        return []
    if schema is False:
        return [f"{path}: not allowed"]
    errs: list[str] = []
    t = schema.get("type")
    types = {"object": dict, "array": list, "string": str, "boolean": bool}
    if t in types and not isinstance(doc, types[t]):
        return [f"{path}: not {t}"]
    if t in ("number", "integer") and (isinstance(doc, bool) or not isinstance(doc, (int, float))
                                       or (t == "integer" and not isinstance(doc, int))):
        return [f"{path}: not {t}"]
    for kw, ok in (("minimum", lambda a, b: a >= b), ("maximum", lambda a, b: a <= b),
                   ("exclusiveMinimum", lambda a, b: a > b), ("exclusiveMaximum", lambda a, b: a < b)):
        if kw in schema and isinstance(doc, (int, float)) and not ok(doc, schema[kw]):
            errs.append(f"{path}: {kw}")
    if "enum" in schema and doc not in schema["enum"]:
        errs.append(f"{path}: enum")
    if "const" in schema and doc != schema["const"]:
        errs.append(f"{path}: const")
    if isinstance(doc, dict):
        props = schema.get("properties", {})
        errs += [f"{path}.{k}: required" for k in schema.get("required", []) if k not in doc]
        for k, v in doc.items():
            if k in props:
                errs += _mini_validate(props[k], v, f"{path}.{k}")
            elif schema.get("additionalProperties") is False:
                errs.append(f"{path}.{k}: additional property")
    if isinstance(doc, list):
        if len(doc) < schema.get("minItems", 0) or len(doc) > schema.get("maxItems", math.inf):
            errs.append(f"{path}: item count")
        if "items" in schema:
            for i, v in enumerate(doc):
                errs += _mini_validate(schema["items"], v, f"{path}[{i}]")
    for sub in schema.get("allOf", []):
        errs += _mini_validate(sub, doc, path)
    if "anyOf" in schema and all(_mini_validate(s, doc, path) for s in schema["anyOf"]):
        errs.append(f"{path}: anyOf")
    if "oneOf" in schema and sum(not _mini_validate(s, doc, path) for s in schema["oneOf"]) != 1:
        errs.append(f"{path}: oneOf")
    if "not" in schema and not _mini_validate(schema["not"], doc, path):
        errs.append(f"{path}: not")
    if "if" in schema and not _mini_validate(schema["if"], doc, path):
        errs += _mini_validate(schema.get("then", True), doc, path)
    return errs


def _validators():
    out = [lambda doc: _mini_validate(json_schema(), doc)]
    try:
        import jsonschema
    except ImportError:
        return out
    jsonschema.Draft202012Validator.check_schema(json_schema())
    v = jsonschema.Draft202012Validator(json_schema())
    out.append(lambda doc: [e.message for e in v.iter_errors(doc)])
    return out


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.name)
def test_json_schema_accepts_every_shipped_scenario(path):
    import tomllib

    doc = tomllib.loads(path.read_text(encoding="utf-8"))
    for validate in _validators():
        assert validate(doc) == []


def test_json_schema_rejects_unknown_keys_and_kind_mismatches():
    bad = copy.deepcopy(BASE)
    bad["fender"]["stifness"] = 1.0
    wrong_kind = copy.deepcopy(BASE)
    wrong_kind["sea"]["H"] = 1.0
    for validate in _validators():
        assert validate(BASE) == []
        assert validate(bad)
        assert validate(wrong_kind)


def test_json_schema_carries_docs_units_and_defaults():
    schema = json_schema()
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    sim = schema["properties"]["simulation"]
    assert sim["required"] == ["duration"] and "[s]" in sim["properties"]["duration"]["description"]
    assert schema["properties"]["radiation"]["properties"]["memory"]["default"] == MEMORY_DEFAULT
    assert schema["properties"]["fender"]["properties"]["points"]["items"]["minItems"] == 3
    json.dumps(schema)  # serialisable
