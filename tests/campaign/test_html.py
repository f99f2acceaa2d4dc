"""The report's one page (boatland.campaign.html, report.html) of real small campaigns — a Monte Carlo one
and two rare-event (ISEE) ones — read back with a real HTML parser: self-contained (no script, no link, no
URL but data: and #anchors; every image a PNG that is one of the figure files, byte for byte), readable on a
phone (viewport, tables in scrolling boxes), and every number of its tables the store's, formatted as the
tables of the report format them."""

import base64
import math
import re
import warnings
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path

import pytest

from boatland.campaign.decision import ONSET, SCREENING_NOTE, decision, p_text
from boatland.campaign.labels import axis_label, inputs_from_header, value_text
from boatland.campaign.report import read_store, write_report
from boatland.freqdomain.statistics import DEFAULT_STATISTICS, one_in, risk_in_words

#: No library warning reaches the user of a report (matplotlib's layout warnings included).
pytestmark = pytest.mark.filterwarnings("error::UserWarning")

pytestmark = pytest.mark.slow        # small campaigns run for the pages: not in the quick loop

REPO = Path(__file__).resolve().parents[2]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
SLIP = "slip > 0.1 m"
#: Attributes that can point at something outside the page.
URL_ATTRIBUTES = {"src", "href", "srcset", "action", "formaction", "poster", "data", "background", "cite",
                  "longdesc", "manifest", "xlink:href", "ping", "codebase", "archive", "icon", "lowsrc", "dynsrc"}
#: Elements that load or run something.
FORBIDDEN = {"script", "link", "iframe", "frame", "object", "embed", "base", "applet", "audio", "video", "source",
             "track", "portal"}


class Page(HTMLParser):
    """Every element with its attributes, the ids, the text of each section, the tables (per section: rows of
    (tag, attributes, text) cells) and the inline style."""

    def __init__(self, text: str):
        super().__init__(convert_charrefs=True)
        self.doctype, self.elements, self.ids, self.style = None, [], set(), ""
        self.tables: list[tuple[str | None, list[list[tuple[str, dict, str]]]]] = []
        self.text: dict[str | None, str] = {}
        self._section, self._cell, self._in = None, None, []
        self.feed(text)
        self.close()

    def handle_decl(self, decl):
        self.doctype = decl

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.elements.append((tag, a))
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "section":
            self._section = a.get("id")
        elif tag == "table":
            self.tables.append((self._section, []))
        elif tag == "tr":
            self.tables[-1][1].append([])
        elif tag in ("td", "th"):
            self._cell = [tag, a, ""]
        self._in.append(tag)

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self.tables[-1][1][-1].append(tuple(self._cell))
            self._cell = None
        elif tag == "section":
            self._section = None
        if tag in self._in:
            del self._in[len(self._in) - 1 - self._in[::-1].index(tag):]

    def handle_data(self, data):
        if self._cell is not None:
            self._cell[2] += data
        if self._in and self._in[-1] == "style":
            self.style += data
        self.text[self._section] = self.text.get(self._section, "") + data

    def section_tables(self, sid):
        return [rows for s, rows in self.tables if s == sid]


def check_self_contained(page: Page, files: list[Path]) -> None:
    """No element that loads or runs anything, no URL but ``data:`` and ``#anchors`` (to ids of the page),
    no URL in the style, the phone's viewport, every table in a scrolling box, and every ``<img>`` a PNG that
    is one of the PNG files written, each file exactly once."""
    assert page.doctype.lower() == "doctype html"
    tags = Counter(tag for tag, _ in page.elements)
    assert not FORBIDDEN & set(tags), FORBIDDEN & set(tags)
    for tag, attrs in page.elements:
        for name, value in attrs.items():
            if name in URL_ATTRIBUTES:
                assert value.startswith(("data:", "#")), (tag, name, value[:80])
                if value.startswith("#"):
                    assert value[1:] in page.ids, value
            assert not name.startswith("on"), (tag, name)          # no event handlers either
            assert "url(" not in (value or "").replace(" ", "").lower(), (tag, name)
    style = page.style.lower().replace(" ", "")
    assert "url(" not in style and "@import" not in style and "@font-face" not in style
    assert ("meta", {"name": "viewport", "content": "width=device-width, initial-scale=1"}) in page.elements
    assert "max-width" in style and "overflow-x:auto" in style
    # every table sits in a box that scrolls sideways
    assert tags["table"] == len(page.tables) and tags["table"] <= sum(
        1 for tag, a in page.elements if tag == "div" and a.get("class") == "scroll")
    pngs = [Path(f).read_bytes() for f in files if Path(f).suffix == ".png"]
    images = []
    for tag, attrs in page.elements:
        if tag == "img":
            head, _, data = attrs["src"].partition(",")
            assert head == "data:image/png;base64", head
            raw = base64.b64decode(data, validate=True)
            assert raw.startswith(PNG_SIGNATURE)
            images.append(raw)
            assert attrs.get("alt")
    assert Counter(images) == Counter(pngs) and len(pngs) > 0


# ------------------------------------------------------------------------------------------ Monte Carlo
@pytest.fixture(scope="module")
def active_store(tmp_path_factory):
    """A finished Monte Carlo store of the default landing where something happens: Hs 0.8 / 1.6 m × head /
    beam seas, 3 seeds, 6 s of full waves each (12 trials, in this process), a name to be escaped."""
    from small_campaign import run_small_campaign

    return run_small_campaign(tmp_path_factory.mktemp("html_campaign"), "active <&> page", [0.8, 1.6],
                              [180.0, 90.0])[1]


CELL = re.compile(r"^([\d.e-]+) \[([\d.e-]+), ([\d.e-]+)\](?: \(screening ([\d.e-]+)\))?$")


def md_rows(path: Path) -> list[list[str]]:
    lines = [ln for ln in path.read_text(encoding="utf-8").splitlines() if ln.startswith("|")]
    return [[c.strip() for c in ln.strip("|").split("|")] for i, ln in enumerate(lines) if i != 1]


@pytest.mark.parametrize("incident, target", [(None, 0.3), (ONSET, 0.1)])
def test_monte_carlo_page(active_store, tmp_path, incident, target):
    files = write_report(active_store, tmp_path, incident=incident, target=target)
    assert files[-1] == tmp_path / "report.html" and not list(tmp_path.glob(".*.part"))
    page = Page((tmp_path / "report.html").read_text(encoding="utf-8"))
    check_self_contained(page, files)

    data = read_store(active_store)
    header, stats = data["header"], data["stats"]
    inc = incident or SLIP
    dec = decision(data, inc, target)
    # title and provenance; the sections in their order
    assert ("h1", {}) in page.elements and header["campaign"] in page.text[None]
    assert active_store.name in page.text[None] and header["boatland_version"] in page.text[None]
    order = [a["id"] for tag, a in page.elements if tag == "section"]
    assert order == ["inputs", "risk", "decision", "sensitivity", "figures"]
    # the inputs the header holds
    inputs = inputs_from_header(header)
    for word in (inputs["vessel"], f"{inputs['thrust'] / 1e3:g} kN", f"{inputs['mu_s']:g} / {inputs['mu_k']:g}",
                 f"{inputs['access']:g} s", "0.8 m, 1.6 m", "180°, 90°"):
        assert word in page.text["inputs"], word
    # the incident by its stored name, the accepted risk in words
    assert f"Incident: {inc} " in page.text["risk"]
    assert risk_in_words(target, inputs["access"]) in page.text["risk"]
    assert (SCREENING_NOTE in page.text["risk"]) == (inc != ONSET)

    # the decision table: every number the store's
    (table,) = page.section_tables("decision")
    head = [t for _, _, t in table[0]]
    assert head[0] == axis_label("sea.Hs")
    seen = set()
    for row in table[1:-1]:
        hs = row[0][2]
        for j, (tag, attrs, text) in enumerate(row[1:], start=1):
            s = stats[int(attrs["data-case"])]
            seen.add(int(s["case"]))
            assert hs == f"{float(s['axis: sea.Hs']):g}"
            assert head[j] == value_text("sea.relative_direction_deg", float(s["axis: sea.relative_direction_deg"]))
            m = CELL.match(text)
            assert m, text
            assert m.group(1, 2, 3) == tuple(p_text(float(s[f'{inc}: {k}'])) for k in ("P", "P lo", "P hi"))
            if inc == ONSET:
                assert m.group(4) == p_text(float(s['screening: P(slip)']))
            else:
                assert m.group(4) is None
            n = int(s["trials"]) - int(s["failed"])
            assert attrs["title"] == f"{int(s[f'{inc}: count'])} of {n} trials"
    assert seen == {int(c) for c in stats["case"]}
    limit = table[-1]
    assert limit[0][2] == f"limiting Hs at P = {target:g} ({one_in(target)})"
    assert [t for _, _, t in limit[1:]] == [dec.sections[0].limits[c].text() for c in dec.sections[0].columns]
    # the same table as decision.md, cell for cell
    assert [[t for _, _, t in row] for row in table] == md_rows(tmp_path / "decision.md")

    # no sensitivity given: the campaign's own (what moves its base's limit, computed beside its trials) is on the
    # page, each factor by name with its limits; the figures are the report's, its tornado among them
    import json

    study = json.loads(read_store(active_store)["sensitivity"])
    assert study["Tp"] == 7.0 and len(study["rows"]) == 6
    for row in study["rows"]:
        assert row["label"] in page.text["sensitivity"]
        for h in row["per_heading"]:
            assert f"{h['low']:.2f}" in page.text["sensitivity"] and f"{h['high']:.2f}" in page.text["sensitivity"]
    assert tmp_path / "sensitivity_tornado.png" in files
    assert sum(1 for tag, _ in page.elements if tag == "img") == len([f for f in files if f.suffix == ".png"])


def test_sensitivity_rows_give_a_table_and_a_tornado(active_store, tmp_path):
    rows = [{"factor": "μ_s", "range_text": "0.5 – 0.9", "source": "a <source>", "base": {"head seas (180°)": 0.7},
             "low": {"head seas (180°)": 0.5, "beam seas (90°)": 0.2}, "high": {"head seas (180°)": 0.9}},
            {"factor": "push", "range": "100 – 300 kN", "source": "Grøtting 2015",
             "low": {"head seas (180°)": 0.45}, "high": {"head seas (180°)": math.inf, "beam seas (90°)": 0.3}}]
    files = write_report(active_store, tmp_path, sensitivity=rows)
    assert tmp_path / "sensitivity_tornado.png" in files
    page = Page((tmp_path / "report.html").read_text(encoding="utf-8"))
    check_self_contained(page, files)
    (table,) = page.section_tables("sensitivity")
    assert [t for _, _, t in table[0]] == ["factor", "range", "source",
                                           "limiting Hs [m] at low / high end: head seas (180°)",
                                           "limiting Hs [m] at low / high end: beam seas (90°)"]
    assert [[t for _, _, t in r] for r in table[1:]] == [
        ["base", "", "", "0.70", "–"],
        ["μ_s", "0.5 – 0.9", "a <source>", "0.50 / 0.90", "0.20 / –"],
        ["push", "100 – 300 kN", "Grøtting 2015", "0.45 / none", "– / 0.30"]]
    tornado = (tmp_path / "sensitivity_tornado.png").read_bytes()
    in_section = [e for e in page.elements if e[0] == "img"]
    assert any(base64.b64decode(a["src"].partition(",")[2]) == tornado for _, a in in_section)


def test_a_bad_sensitivity_row_is_one_clear_error_before_any_file(active_store, tmp_path):
    from boatland.errors import BoatlandInputError

    with pytest.raises(BoatlandInputError, match="sensitivity row 0: needs factor, range_text, source"):
        write_report(active_store, tmp_path / "rep", sensitivity=[{"factor": "μ_s"}])
    assert not (tmp_path / "rep").exists()


# ------------------------------------------------------------------------------------------ rare events
def isee_store(tmp, name, incident):
    from boatland.campaign import load_campaign
    from boatland.campaign.isee import run_isee
    from boatland.checks.files import load, resolve_database

    path = tmp / f"{name}.toml"
    path.write_text(f"""
name = "{name}"
scenario = "{REPO / 'scenarios' / 'ctv24_landing.toml'}"
method = "isee"
master_seed = 17
access = 20.0
[axes]
"sea.relative_direction_deg" = [180.0, 90.0]
[isee]
incident = "{incident}"
target_cov = 0.5
batch = 6
min_samples = 6
max_samples = 12
settle = 10.0
accept = 0.05
levels = 2
""")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        campaign = load_campaign(path, load_scenario=load)
    run_isee(campaign, tmp / f"{name}.h5", loaders=(load, resolve_database), executor="local", workers=1)
    return tmp / f"{name}.h5"


@pytest.fixture(scope="module")
def isee_stores(tmp_path_factory):
    """Two finished rare-event stores of ctv24 (head and beam seas, ≤ 12 samples per run, 2 levels): one of the
    first slip, one of a slip distance."""
    tmp = tmp_path_factory.mktemp("html_isee")
    return {ONSET: isee_store(tmp, "onset", ONSET), SLIP: isee_store(tmp, "slip", SLIP)}


def g(v, digits=3):
    v = float(v)
    return "–" if not math.isfinite(v) else f"{v:.{digits}g}"


@pytest.mark.parametrize("incident", [ONSET, SLIP])
def test_isee_page(isee_stores, tmp_path, incident):
    store = isee_stores[incident]
    files = write_report(store, tmp_path)
    assert files[-1].name == "report.html"
    page = Page(files[-1].read_text(encoding="utf-8"))
    check_self_contained(page, files)
    data = read_store(store)
    runs, lim = data["stats"], data["isee_limits"]
    assert f"Incident: {incident} " in page.text["risk"]
    assert risk_in_words(float(lim["accept"][0]), 20.0) in page.text["risk"]
    limits, estimates = page.section_tables("decision")

    # per case: the limiting Hs with its interval (and, for the onset only, the linear model's and the screening's)
    head = [t for _, _, t in limits[0]]
    assert head[2] == f"limiting Hs [m] ({incident}) [95 %]"
    assert any("screening" in h for h in head) == (incident == ONSET)
    assert any("linear" in h for h in head) == (incident == ONSET)
    for row, L in zip(limits[1:], lim, strict=True):
        cells = [t for _, _, t in row]
        assert cells[0] == str(int(L["case"]))
        assert cells[1] == value_text("sea.relative_direction_deg", float(L["axis: sea.relative_direction_deg"]),
                                      short=True)
        if math.isfinite(L["limiting Hs"]):
            assert cells[2] == f"{g(L['limiting Hs'], 4)} [{g(L['limiting Hs lo'], 4)}, {g(L['limiting Hs hi'], 4)}]"
        else:
            assert cells[2].startswith("not found")
        if incident == ONSET:
            assert cells[3] == (f"{g(L['linear limiting Hs'], 4)} [{g(L['linear limiting Hs lo'], 4)}, "
                                f"{g(L['linear limiting Hs hi'], 4)}]")
            assert head[4] == f"screening [m] ({ONSET}, {DEFAULT_STATISTICS})"
            assert cells[4] == g(L[f"screening {DEFAULT_STATISTICS} Hs"], 4)
        assert cells[-2:] == [str(int(L["levels"])), str(int(L["samples"]))]

    # per run: the estimate of the campaign's incident with its interval
    head = [t for _, _, t in estimates[0]]
    assert head[4] == f"P({incident}) [95 %]"
    assert any("screening" in h for h in head) == (incident == ONSET)
    for row, r in zip(estimates[1:], runs, strict=True):
        cells = [t for _, _, t in row]
        assert cells[2] == g(r["hs"], 4) and cells[3].startswith(str(int(r["samples"])))
        assert cells[4] == f"{g(r[f'{incident}: P'])} [{g(r[f'{incident}: P lo'])}, {g(r[f'{incident}: P hi'])}]"
        assert cells[5] == g(r[f"{incident}: CoV"], 2)
        if incident == ONSET:
            assert cells[6:] == [g(r["linear first slip: P"]), g(r[f"screening {DEFAULT_STATISTICS}"])]
    # what moves the limit: the campaign's own sensitivity (stored beside its samples); a slide or slip incident's
    # limits join it as the incident definition's row, each heading's value as the store has it
    sens = page.text["sensitivity"]
    found = [float(L["limiting Hs"]) for L in lim if math.isfinite(L["limiting Hs"])]
    assert "bollard push" in sens and "sensitivity_tornado.png" in [f.name for f in files]
    assert found and ("incident definition" in sens) == (incident != ONSET)
    if incident != ONSET:
        assert all(f"{h:.2f}" in sens for h in found)
    # the tables of the report name the incident of every column likewise
    md = (tmp_path / "isee_limits.md").read_text(encoding="utf-8")
    assert f"limiting Hs [m] ({incident})" in md and f"screening Rayleigh [m] ({ONSET})" in md
