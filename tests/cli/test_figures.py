"""Every figure command: each axis carries its unit, and the title names the inputs the figure was made
with. The figures are caught as the commands save them (``boatland.plotstyle.save_figure``)."""

import re
from pathlib import Path

import pytest

import boatland.plotstyle
from boatland.cli import main

#: The first default landing (ctv24, 80 kN, Hs 1.5 m): it slips within 45 s, which these tests need.
CTV24_LANDING = str(Path(__file__).resolve().parents[2] / "scenarios" / "ctv24_landing.toml")

UNIT = re.compile(r"\[[^\]]+\]")


@pytest.fixture
def figures(monkeypatch):
    """Figures the command saves, in order (they are still written)."""
    caught = []
    save = boatland.plotstyle.save_figure

    def keep(fig, path, **kw):
        caught.append(fig)
        texts = _texts(fig)                 # read before the figure is closed
        caught[-1] = (fig, texts, [("colorbar" if getattr(a, "_colorbar", None) is not None else a.name,
                                    a.get_xlabel(), a.get_ylabel(), _has_data(a), round(a.get_position().y0, 3))
                                   for a in fig.axes])
        return save(fig, path, **kw)

    monkeypatch.setattr(boatland.plotstyle, "save_figure", keep)
    return caught


def _has_data(ax) -> bool:
    return bool(ax.lines or ax.collections or ax.images)


def _texts(fig) -> str:
    parts = [fig._suptitle.get_text() if fig._suptitle else ""]
    for a in fig.axes:
        parts += [a.get_title(), a.get_title("left"), a.get_title("right")]
    parts += [t.get_text() for t in fig.texts]
    return "\n".join(parts)


def check(caught, *inputs):
    """Every drawn axes has a unit on its value axis (or a neighbour in its row of a grid has it), each
    figure one on a horizontal axis (cartesian) or a labelled radius/colour scale (polar); the titles name
    every input."""
    assert caught, "no figure was saved"
    for fig, texts, axes in caught:
        rows = {row for _, _, y, _, row in axes if UNIT.search(y)}
        for name, xlabel, ylabel, data, row in axes:
            if name == "polar" or not data:
                continue
            assert UNIT.search(ylabel) or row in rows, f"no unit on the y axis {ylabel!r}"
        cart = [a for a in axes if a[0] not in ("polar", "colorbar") and a[3]]
        if cart:
            assert any(UNIT.search(a[1]) for a in cart), "no unit on any x axis"
        else:
            all_text = texts + "".join(a[2] for a in axes) + "".join(
                t.get_text() for t in fig.findobj(lambda o: hasattr(o, "get_text")))
            assert UNIT.search(all_text), "a polar figure without a labelled scale"
        for word in inputs:
            assert word in texts, (word, texts)


@pytest.mark.slow
def test_run_plot(tmp_path, figures, capsys):
    assert main(["run", CTV24_LANDING, "--duration", "45", "-o", str(tmp_path / "r.h5"), "--json"]) == 0
    figures.clear()
    assert main(["plot", str(tmp_path / "r.mcap"), "-o", str(tmp_path / "r.png")]) == 0
    check(figures, "JONSWAP Hs 1.5 m, Tp 7 s", "head seas (180°)", "push 80 kN", "μ_s 0.6", "seed 1", "SLIPPED at t =")
    fig, texts, axes = figures[0]
    assert "Friction utilisation" in texts and "Wave at the bow" in texts
    assert any("needed / available" in a[2] for a in axes)


@pytest.mark.slow
def test_screen_polar_and_shear_sweep(tmp_path, figures):
    assert main(["screen", "--tp", "5", "9", "3", "--directions", "4", "-o", str(tmp_path / "p.png")]) == 0
    check(figures, "ctv_landing", "push 150 kN", "μ 0.8", "1800 s access", "P = 0.00119", "180° = head seas at the top")
    polar = figures[0][0].axes[0]
    assert polar.get_theta_direction() == 1                  # waves from starboard (90°) on the right
    figures.clear()
    assert main(["screen", "--shear-sweep", "7", "--directions", "4", "-o", str(tmp_path / "s.png")]) == 0
    check(figures, "Tp 7 s", "push 150 kN", "μ 0.8")


@pytest.mark.slow
def test_rao_figures(tmp_path, figures):
    assert main(["rao", "--periods", "5", "20", "-o", str(tmp_path / "r.png"),
                 "--compare-open-sea", str(tmp_path / "c.png")]) == 0
    check(figures[:1], "ctv_landing", "head seas", "push of 150 kN")
    check(figures[1:], "ctv_landing", "monopile")


@pytest.mark.slow
def test_irf_figure(tmp_path, figures):
    assert main(["irf", "ctv24", "--no-store", "--no-fit", "--plot", str(tmp_path / "irf.png")]) == 0
    check(figures, "ctv24", "T_K = 60 s", "tail")


def test_report_figures(small_store, tmp_path, figures):
    _, store, _ = small_store
    assert main(["report", str(store), "-o", str(tmp_path / "rep")]) == 0
    # P vs Hs, limiting Hs, time to incident; and what moves the limit (a tornado: factors down its y axis)
    tornado = [f for f in figures if "what moves the limit" in f[1]]
    assert len(figures) == 4 and len(tornado) == 1
    check([f for f in figures if f not in tornado], "small", "push 150 kN", "μ_s 0.8", "3 seeds per case")
    fig, texts, axes = tornado[0]
    assert all(UNIT.search(xlabel) for _, xlabel, _, data, _ in axes if data)
    for word in ("small", "push 150 kN", "μ_s 0.8", "3 seeds per case"):
        assert word in texts, (word, texts)
