"""The scenario keys of the loads beside the waves: [current], [wind], sea.drift, thrust.direction_deg and
thrust.control — what is accepted, and one clear problem per bad value, named by its key."""

import pytest

from box_vessel import make
from boatland.scenario.scenario import SpecError


def problems(changes, remove=()):
    with pytest.raises(SpecError) as e:
        make(changes, remove)
    return dict(e.value.problems)


def test_the_loads_are_read():
    s = make({"current": {"speed": 1.2, "relative_direction_deg": 90.0},
              "wind": {"speed": 10.0, "direction_deg": 45.0, "spectrum": "none"},
              "sea.drift": "newman", "thrust.direction_deg": -5.0,
              "thrust.control": {"kind": "hold_force", "gain": 0.3, "delay": 1.0}})
    assert s.current.speed == 1.2 and s.current.direction_deg == (s.vessel.heading_deg + 90.0) % 360
    assert s.wind.direction_deg == 45.0 and s.wind.spectrum == "none"
    assert s.sea.drift == "newman" and s.thrust.direction_deg == -5.0 and not s.thrust.trimmed
    assert s.thrust.control.active and s.thrust.control.gain == 0.3
    base = make()
    assert base.current is None and base.wind is None and base.sea.drift == "none" and base.thrust.trimmed
    assert not base.thrust.control.active


@pytest.mark.parametrize("changes, key, words", [
    ({"current": {"speed": 1.0}}, "current.relative_direction_deg", "missing"),
    ({"current": {"speed": 1.0, "relative_direction_deg": 90.0, "direction_deg": 0.0}}, "current.direction_deg",
     "not both"),
    ({"current": {"speed": -1.0, "relative_direction_deg": 90.0}}, "current.speed", "≥ 0"),
    ({"wind": {"speed": 5.0, "relative_direction_deg": 90.0, "spectrum": "api"}}, "wind.spectrum", "'npd'"),
    ({"wind": {"speed": 5.0, "relative_direction_deg": 90.0, "table": {"angles_deg": [0.0, 90.0],
                                                                       "cx": [1.0, 0.0], "cy": [0.0, 1.0],
                                                                       "cn": [0.0, 0.0]}}},
     "wind.table.angles_deg", "0 to 180"),
    ({"sea.drift": "second"}, "sea.drift", "'newman'"),
    ({"thrust.direction_deg": 75.0}, "thrust.direction_deg", "≤ 60"),
    ({"thrust.direction_deg": "steer"}, "thrust.direction_deg", "'trim'"),
    ({"thrust.control": {"kind": "pid"}}, "thrust.control.kind", "'hold_force'"),
    ({"thrust.control": {"kind": "hold_force", "max_force": 1e4, "min_force": 2e4}}, "thrust.control.max_force",
     "below min_force"),
])
def test_bad_values_are_named(changes, key, words):
    p = problems(changes)
    assert key in p and words in p[key], p


def test_a_controller_needs_a_fender():
    p = problems({"thrust.control": {"kind": "hold_force"}}, remove=("fender",))
    assert "thrust.control.kind" in p
