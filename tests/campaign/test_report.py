"""The report of a real (small) campaign store: files, readable tables, figures with units and inputs,
the store as an xarray Dataset; the campaign's own summary and its resume message."""

import contextlib
import io
import json

import numpy as np
import pytest

from boatland.campaign import open_store
from boatland.campaign.report import (figure_limiting_polar, figure_p_vs_hs, figure_time_to_incident, read_store,
                                      store_decision, write_report)
from boatland.cli import main

pytestmark = pytest.mark.slow        # a campaign run for the report: not in the quick loop (pytest -m "not slow")


def test_the_campaign_prints_its_decision_table(small_store):
    _, store, out = small_store
    assert out["trials"] == 12 and out["failed"] == 0 and out["resumed_from"] == 0
    dec = out["decision"]
    assert dec["incident"] == "slip > 0.1 m" and dec["seeds_per_case"] == 3
    assert [c["label"] for c in dec["sections"][0]["columns"]] == ["head seas (180°)",
                                                                    "bow-quartering seas from starboard (135°)"]
    assert all(lim["text"] for lim in dec["sections"][0]["limiting_hs"])


def test_a_second_run_says_it_resumes(small_store, capsys):
    camp, store, _ = small_store
    assert main(["campaign", str(camp), "-o", str(store), "--workers", "1"]) == 0
    cap = capsys.readouterr()
    assert "resuming: 12 of 12 trials already in the store" in cap.err
    assert "P(slip > 0.1 m within the access)" in cap.out and "limiting Hs at P = 0.1" in cap.out
    assert "(0 run now, 12 from before)" in cap.out


def test_report_files_and_json(small_store, tmp_path, capsys):
    _, store, _ = small_store
    assert main(["report", str(store), "-o", str(tmp_path / "rep"), "--json", "--width", "0.3"]) == 0
    out = json.loads(capsys.readouterr().out)
    names = {p.name for p in (tmp_path / "rep").iterdir()}
    assert {"decision.md", "decision.csv", "cases.md", "cases.csv", "limiting_hs.md", "p_vs_hs.png",
            "limiting_hs_polar.png", "time_to_incident.png"} <= names
    assert out["width"] == 0.3 and out["seeds_needed"] > 3 and len(out["files"]) == len(names)
    md = (tmp_path / "rep" / "cases.md").read_text()
    assert "sea.Hs" not in md and "| Hs [m] |" in md and "inf" not in md
    assert "first slip: mean time [s]" in (tmp_path / "rep" / "cases.csv").read_text().splitlines()[0]


def _units(label: str) -> bool:
    return "[" in label and "]" in label


def test_report_figures_have_units_legends_and_the_inputs(small_store):
    _, store, _ = small_store
    dec = store_decision(store)
    for fig in (figure_p_vs_hs(dec), figure_time_to_incident(read_store(store), dec)):
        ax = fig.axes[0]
        assert _units(ax.get_xlabel()) and _units(ax.get_ylabel())
        for word in ("small", "Tp 7 s", "push 150 kN", "μ_s 0.8", "3 seeds per case", "6 s access"):
            assert word in ax.get_title(), (word, ax.get_title())
        labels = [t.get_text() for leg in fig.legends + [a.get_legend() for a in fig.axes if a.get_legend()]
                  for t in leg.get_texts()]
        assert (labels or not ax.lines) and not [t for t in labels if "sea." in t or "=" in t.replace("P = ", "")]
    fig = figure_limiting_polar(dec)
    ax = fig.axes[0]
    assert ax.get_theta_offset() == pytest.approx(1.5 * np.pi) and ax.get_theta_direction() == 1  # 180° at the top
    texts = [t.get_text() for t in fig.findobj(lambda o: hasattr(o, "get_text"))]
    assert any("limiting Hs [m]" in t for t in texts) and "push 150 kN" in ax.get_title()


def test_store_as_xarray(small_store):
    _, store, _ = small_store
    ds = open_store(store)
    names = read_store(store)["header"]["incidents"].split("\n")
    assert dict(ds.sizes) == {"trial": 12, "case": 4, "incident": len(names)}
    assert list(ds.incident.values) == names
    assert ds.Hs.attrs["key"] == "sea.Hs" and ds.Hs.units == "m" and ds.heading.units == "deg"
    assert ds.time_to_incident.units == "s" and ds.P.dims == ("case", "incident")
    grid = open_store(store, grid=True)
    p = grid.P.sel(incident="slip > 0.1 m")
    assert p.dims == ("Hs", "heading") and p.shape == (2, 2)
    row = ds.sel(case=int(ds.case[(ds.Hs == 0.6) & (ds.heading == 135.0)][0]))
    assert float(p.sel(Hs=0.6, heading=135.0)) == float(row.P.sel(incident="slip > 0.1 m"))
    assert json.loads(ds.attrs["inputs"])["thrust"] == 150e3
    with contextlib.redirect_stdout(io.StringIO()):
        files = write_report(store, store.parent / "rep2", figures=False)
    assert all(f.suffix in (".md", ".csv", ".html") for f in files)        # tables and the page, no figure
