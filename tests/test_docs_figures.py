"""The figures in ``docs/`` are the ones ``python docs/make_figures.py`` makes from the shipped scenarios:
each one listed there exists, and its title (the PNG's ``Title`` text chunk, written by
:func:`boatland.plotstyle.save_figure`) names the scenario or campaign and the vessel it was made from; the
Rerun screenshot, which has no title, is named by its caption in the README. Each listed source is shipped."""

import importlib.util
import sys
from pathlib import Path

import pytest
from PIL import Image

from boatland.resources import shipped_names

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("make_figures", ROOT / "docs" / "make_figures.py")
make_figures = importlib.util.module_from_spec(_spec)
sys.modules.setdefault("make_figures", make_figures)        # dataclasses look their module up
_spec.loader.exec_module(make_figures)
FIGURES = make_figures.FIGURES


def test_every_figure_in_docs_is_made_by_the_script():
    pngs = {p.name for p in (ROOT / "docs").glob("*.png")}
    assert pngs == {f.file for f in FIGURES}


@pytest.mark.parametrize("fig", [f for f in FIGURES if f.titled], ids=lambda f: f.file)
def test_title_names_its_scenario_and_vessel(fig):
    title = Image.open(ROOT / "docs" / fig.file).text.get("Title", "")
    for source in fig.source.split(", "):
        assert source in shipped_names("scenario") + shipped_names("campaign"), source
    for name in (*fig.source.split(", "), *fig.vessel.split(", ")):
        assert name in title, (fig.file, name, title)


def test_the_screenshot_is_named_by_its_caption():
    (shot,) = [f for f in FIGURES if not f.titled]
    caption = next(line for line in (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
                   if f"(docs/{shot.file})" in line and line.startswith("!["))
    assert shot.source in caption and shot.vessel in caption, caption


def test_the_viewer_for_the_screenshot_listens_on_loopback_only():
    """The ``rerun`` command binds 0.0.0.0 unless told otherwise: the script tells it 127.0.0.1 (the viewer it
    starts is the one ``tests/record/test_replay_viewer.py`` starts and checks)."""
    import inspect

    src = inspect.getsource(make_figures.screenshot)
    assert '"--bind", "127.0.0.1"' in src and "0.0.0.0" not in src
