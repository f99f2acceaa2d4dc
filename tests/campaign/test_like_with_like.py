"""Like with like: the frequency-domain screening predicts slip onsets, so every table shows its P only
beside the time domain's P(first slip), labelled; a table of another incident (a slip distance) shows
time-domain figures only and says why; every column names the incident it is of — the decision table
(text, Markdown, CSV), the per-case tables and the figure P vs Hs, on a real (small) campaign store."""

import csv
import math

import numpy as np
import pytest

from boatland.campaign.decision import ONSET, SCREENING_NOTE, decision, p_text
from boatland.campaign.report import (
    figure_p_vs_hs,
    read_store,
    store_decision,
    write_report,
)
from boatland.campaign.stats import clopper_pearson

SLIP = "slip > 0.1 m"


def two_incidents(screening):
    """A store's ``data`` (as ``read_store`` gives it) with two cases and the incidents first slip and a
    slip distance, their counts different; ``screening``: the screening's P(first slip) per case."""
    incs = {ONSET: (2, 3), SLIP: (0, 1)}
    fields = [("case", "i8"), ("label", "S200"), ("trials", "i8"), ("failed", "i8"), ("screening: P(slip)", "f8"),
              ("screening: note", "S200"), ("axis: sea.Hs", "f8")]
    fields += [(f"{n}: {k}", "i8" if k == "count" else "f8") for n in incs
               for k in ("count", "P", "P lo", "P hi", "mean time", "mean lo", "mean hi")]
    stats = np.zeros(2, dtype=fields)
    for i in range(2):
        stats[i]["case"], stats[i]["trials"], stats[i]["axis: sea.Hs"] = i, 4, 0.5 * (i + 1)
        stats[i]["screening: P(slip)"] = screening[i]
        for n, counts in incs.items():
            stats[i][f"{n}: count"] = counts[i]
            stats[i][f"{n}: P"], stats[i][f"{n}: P lo"], stats[i][f"{n}: P hi"] = clopper_pearson(counts[i], 4)
    return {"stats": stats, "plan": {"name": "two", "axes": {"sea.Hs": [0.5, 1.0]}, "seeds": 4},
            "header": {"campaign": "two", "incidents": "\n".join(incs)}, "trials": np.zeros(0)}


def test_the_screening_stands_beside_first_slip_only():
    data = two_incidents([0.31, 0.87])
    onset, slip = decision(data, ONSET), decision(data, SLIP)
    assert onset.screening_beside and not slip.screening_beside
    for case, (hs, scr) in enumerate(zip((0.5, 1.0), (0.31, 0.87))):
        assert onset.sections[0].cells[(hs, ())].text(screening=True).endswith(f"(screening {p_text(scr)})")
        assert "screening" not in slip.table_lines(slip.sections[0], markdown=True)[2 + case]
    # each table's legend names its incident; the slip distance's says why the screening is not there
    assert f"P({ONSET} within the access)" in onset.legend() and "screening" in onset.legend()
    assert f"P({SLIP} within the access)" in slip.legend() and SCREENING_NOTE in slip.legend()
    assert SCREENING_NOTE in slip.markdown() and SCREENING_NOTE in slip.text()
    assert SCREENING_NOTE not in onset.markdown()
    # JSON: the screening's figure keyed by the incident it is of, whatever the table is about
    assert slip.as_dict()["sections"][0]["cells"][1][0]["screening_P_first_slip"] == 0.87
    assert "screening_P" not in slip.as_dict()["sections"][0]["cells"][1][0]


def md_table(path):
    """The first Markdown table of a file: header and rows (cells stripped)."""
    lines = [ln for ln in path.read_text(encoding="utf-8").splitlines() if ln.startswith("|")]
    cells = [[c.strip() for c in ln.strip("|").split("|")] for ln in lines]
    return cells[0], cells[2:]


def incident_of(header: str, names) -> str | None:
    """The incident a "P(…)" column header names (None: not a column of P)."""
    for n in names:
        if f"P({n})" in header:
            return n
    return None


@pytest.mark.slow        # a campaign run for the store (shared with test_report)
def test_report_tables_name_the_incident_of_every_column(small_store, tmp_path):
    _, store, _ = small_store
    data = read_store(store)
    stats = data["stats"]
    names = data["header"]["incidents"].split("\n")
    assert ONSET in names and SLIP in names
    screening = [p_text(v) for v in stats["screening: P(slip)"]]
    for inc in (SLIP, ONSET):
        out = tmp_path / inc.replace(" ", "_").replace(">", "gt")
        write_report(store, out, incident=inc, figures=False)

        # cases.md: the screening named by its incident, right after the time domain's P(first slip)
        head, rows = md_table(out / "cases.md")
        i = head.index(f"screening P({ONSET})")
        assert head[i - 1] == f"P({ONSET})" and "screening P(slip)" not in head
        assert [r[i] for r in rows] == screening
        p_cols = [h for h in head if h.startswith("P(")]
        assert p_cols == [f"P({n})" for n in names]          # every P column names its incident
        assert head[-1] == f"mean time to {inc}"

        # cases.csv: the screening's column says which incident it predicts
        with open(out / "cases.csv", newline="", encoding="utf-8") as fh:
            header = next(csv.reader(fh))
        assert f"screening: P({ONSET}) (frequency domain)" in header
        assert "screening: P(slip) (frequency domain)" not in header

        # decision.csv: P columns name the table's incident; the screening's column only for first slip
        with open(out / "decision.csv", newline="", encoding="utf-8") as fh:
            rows_csv = list(csv.DictReader(fh))
        cols = list(rows_csv[0])
        assert [c for c in cols if c.startswith("P(")] == [f"P({inc})", f"P({inc}) lo", f"P({inc}) hi"]
        scr_cols = [c for c in cols if "screening" in c]
        if inc == ONSET:
            assert scr_cols == [f"screening P({ONSET}) (frequency domain)"]
            by_case = {(float(r["Hs [m]"]), float(r["heading (180° = head seas)"])): r[scr_cols[0]] for r in rows_csv}
            for s in stats:
                got = by_case[(float(s["axis: sea.Hs"]), float(s["axis: sea.relative_direction_deg"]))]
                assert got == f"{float(s['screening: P(slip)']):.4g}"        # as the CSV writes numbers
        else:
            assert scr_cols == []

        # decision.md: a cell holds the screening only in the table of first slip, and says so
        head, rows = md_table(out / "decision.md")
        cells = [c for r in rows if not r[0].startswith("limiting") for c in r[1:]]
        text = (out / "decision.md").read_text(encoding="utf-8")
        assert f"P({inc} within the access)" in text
        if inc == ONSET:
            assert all("(screening " in c for c in cells) and SCREENING_NOTE not in text
        else:
            assert not any("screening" in c for c in cells) and SCREENING_NOTE in text

        # the terminal's table likewise
        dec = store_decision(store, incident=inc)
        assert ("(screening " in dec.text()) == (inc == ONSET)


@pytest.mark.slow
def test_the_figure_draws_the_screening_beside_first_slip_only(small_store):
    _, store, _ = small_store
    for inc in (SLIP, ONSET):
        fig = figure_p_vs_hs(store_decision(store, incident=inc))
        labels = [t.get_text() for leg in fig.legends for t in leg.get_texts()]
        drawn = any("screening" in t for t in labels)
        finite = any(math.isfinite(v) for v in read_store(store)["stats"]["screening: P(slip)"])
        assert drawn == (inc == ONSET and finite), (inc, labels)
