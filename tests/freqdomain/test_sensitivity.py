"""``boatland.freqdomain.sensitivity`` and ``boatland screen --sensitivity`` on the packaged default landing
(ctv_landing: ctv27, 150 kN, μ_s 0.8, Tp 7 s): real screenings, checked by what the physics says must hold
— not by stored outputs."""

import json
import math
import warnings

import numpy as np
import pytest

from boatland.checks.files import default_scenario_path, load_checked
from boatland.cli import main
from boatland.errors import BoatlandInputError
from boatland.freqdomain import LandingSetup, screening_grid
from boatland.freqdomain.sensitivity import (
    DEFAULT_HEADINGS,
    FACTORS,
    ExtraLimit,
    Factor,
    sensitivity,
)

TP = 7.0
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def default_landing():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario, db, _ = load_checked(default_scenario_path())
    return scenario, db, LandingSetup.from_scenario(scenario, db)


@pytest.fixture(scope="module")
def result(default_landing):
    _, db, setup = default_landing
    return sensitivity(db, setup, TP)


def row(result, key):
    return next(r for r in result.rows if r.factor == key)


def test_the_base_is_the_screens_limit(default_landing, result):
    _, db, setup = default_landing
    table = screening_grid(db, setup, [TP], list(DEFAULT_HEADINGS), accept="best", statistics=result.statistics)
    assert result.beta_deg == DEFAULT_HEADINGS
    np.testing.assert_allclose(result.base, table.Hs[0], rtol=1e-12)
    assert all(r.base == result.base for r in result.rows)


@pytest.mark.parametrize("key", ["thrust", "mu", "accept"])
def test_more_push_friction_or_tolerated_risk_raises_the_limit(result, key):
    r = row(result, key)
    for lo, base, hi in zip(r.low, r.base, r.high, strict=True):
        assert lo < base < hi, (key, lo, base, hi)


def test_a_stiffer_fender_holds_less_in_beam_seas(result):
    """Stiff rubber makes the two contacts take the roll moment as a couple of opposite vertical forces."""
    r = row(result, "shear")
    j = DEFAULT_HEADINGS.index(90.0)
    assert r.high[j] < r.base[j] < r.low[j]


def test_all_favourable_bounds_every_single_factor(result):
    together = result.together
    assert together is not None and together.factor == "all" and result.rows[-1] is together
    for r in result.factor_rows:
        for j in range(len(result.beta_deg)):
            assert together.high[j] >= max(r.low[j], r.high[j]) * (1 - 1e-9), (r.factor, j)
            assert together.low[j] <= min(r.low[j], r.high[j]) * (1 + 1e-9), (r.factor, j)
    assert len(together.detail) == len(result.beta_deg)


def test_rows_are_sorted_by_their_swing(result):
    swings = [max(r.swing(j) for j in range(len(result.beta_deg))) for r in result.factor_rows]
    assert swings == sorted(swings, reverse=True)


def test_every_range_says_where_it_comes_from():
    for f in FACTORS:
        assert f.low < f.high and f.short
        assert any(w in f.source for w in ("Table", "§", "ASSUMPTION", "assumption")), f.key
    assert "ASSUMPTION" in next(f for f in FACTORS if f.key == "shear").source


def test_a_zero_height_change_reproduces_the_base(default_landing):
    """The fender-height path (contact points moved in z) is the base when it moves them by nothing."""
    _, db, setup = default_landing
    none = Factor("height", "fender height z", 0.0, 0.0, "test", "test", offset=True)
    r = sensitivity(db, setup, TP, [180.0], factors=[none])
    assert r.rows[0].low == r.rows[0].high == r.base and r.together is None


def test_an_extra_row_runs_from_the_base_to_its_limit(default_landing):
    _, db, setup = default_landing
    extra = ExtraLimit("slide > 0.5 m within 120 s (time domain)", "test store", {180.0: 0.9, 135.0: 0.6})
    r = sensitivity(db, setup, TP, factors=["thrust", "mu"], extra_rows=[extra])
    inc = row(r, "incident")
    assert inc.low == r.base and inc.high[:2] == (0.9, 0.6) and math.isnan(inc.high[2])
    own = sensitivity(db, setup, TP, factors=["thrust", "mu"])
    assert r.together.high == own.together.high       # computed elsewhere: not part of "all together"


def test_bad_input_is_refused(default_landing):
    _, db, setup = default_landing
    with pytest.raises(BoatlandInputError, match="unknown factor 'wind'"):
        sensitivity(db, setup, TP, factors=["thrust", "wind"])
    for tp in (0.0, -7.0, math.nan, math.inf):
        with pytest.raises(BoatlandInputError, match="Tp"):
            sensitivity(db, setup, tp)


# ------------------------------------------------------------------------------------------ the command
def _store(path, limits):
    """A finished ISEE campaign store holding only what ``--limits`` reads (a real campaign takes minutes)."""
    import h5py

    from boatland.campaign.store import FORMAT

    with h5py.File(path, "w") as f:
        f.attrs["format"] = FORMAT
        f.attrs["plan"] = json.dumps({"name": "test_limits", "axes": {"sea.relative_direction_deg": list(limits)}})
        f.attrs["incidents"] = "first slip\nslide > 0.5 m within 120 s"
        f.attrs["inputs"] = json.dumps({"Tp": TP, "thrust": 150e3, "mu_s": 0.8})
        f["trials"] = np.zeros(1, dtype=[("case", "i8")])
        f["stats"] = np.zeros(1, dtype=[("case", "i8")])
        lim = np.zeros(len(limits), dtype=[("case", "i8"), ("axis: sea.relative_direction_deg", "f8"),
                                           ("accept", "f8"), ("incident", "S40"), ("limiting Hs", "f8")])
        lim["case"] = np.arange(len(limits))
        lim["axis: sea.relative_direction_deg"] = list(limits)
        lim["accept"] = 0.00119
        lim["incident"] = b"slide > 0.5 m within 120 s"
        lim["limiting Hs"] = list(limits.values())
        f["isee_limits"] = lim


@pytest.mark.slow
def test_cli_json_figure_and_store_row(default_landing, tmp_path, capsys):
    _, db, setup = default_landing
    store, png = tmp_path / "limits.h5", tmp_path / "tornado.png"
    _store(store, {180.0: 0.9, 135.0: 0.6, 90.0: 0.35})
    assert main(["screen", "--sensitivity", "--json", "-o", str(png), "--limits", str(store)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["Tp"] == TP and out["beta_deg"] == list(DEFAULT_HEADINGS)
    table = screening_grid(db, setup, [TP], list(DEFAULT_HEADINGS), statistics=out["statistics"])
    np.testing.assert_allclose(out["base"], table.Hs[0], rtol=1e-12)
    keys = [r["factor"] for r in out["rows"]]
    assert sorted(keys) == sorted(["accept", "thrust", "mu", "shear", "height", "incident", "all"])
    inc = next(r for r in out["rows"] if r["factor"] == "incident")
    assert [h["high"] for h in inc["per_heading"]] == [0.9, 0.6, 0.35] and "slide > 0.5 m" in inc["range"]
    assert all(r["source"] for r in out["rows"])
    assert png.read_bytes()[:8] == PNG_SIGNATURE


@pytest.mark.slow
def test_cli_text_table(capsys):
    assert main(["screen", "--sensitivity", "--factors", "push,mu", "--tp", "7"]) == 0
    text = capsys.readouterr().out
    assert "Tp 7 s" in text and "bollard push" in text and "friction μ_s" in text and "all together" in text
    assert "shear stiffness" not in text and "×" in text


@pytest.mark.parametrize("args, words", [
    (["--factors", "push,wind"], ["--factors push,wind", "unknown factor 'wind'"]),
    (["--tp", "5", "9", "3"], ["--tp 5 9 3", "one peak period"]),
    (["--tp", "0"], ["--tp"]),
    (["--shear-sweep", "7"], ["--shear-sweep"]),
])
def test_cli_bad_input_is_one_line(args, words, capsys):
    assert main(["screen", "--sensitivity", *args]) == 2
    err = [ln for ln in capsys.readouterr().err.splitlines() if "error:" in ln]
    assert len(err) == 1 and all(w in err[0] for w in words), err


def test_cli_factors_only_with_sensitivity(capsys):
    assert main(["screen", "--factors", "mu"]) == 2
    assert "only with --sensitivity" in capsys.readouterr().err


def test_a_base_outside_a_range_is_noted(default_landing):
    _, db, setup = default_landing
    r = sensitivity(db, setup, TP, [180.0], factors=["push"], thrust=80e3)
    assert len(r.notes) == 1 and "80 kN lies outside its range 100 kN – 300 kN" in r.notes[0]
    assert r.rows[0].low[0] > r.base[0]                 # both ends push harder than the base: both raise it
