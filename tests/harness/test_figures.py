"""The figure checker (harness/figures.py) on made-up figures: each rule it states is broken
once and found; a figure that keeps them passes; a written PNG is a palette image.  And every
figure a run of the scenes writes: checked (strict), captioned, in reading order."""
from __future__ import annotations

import os

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from PIL import Image

from linkrepro.harness import figures

X = np.linspace(0.0, 360.0, 73)


def drawn(fig):
    return figures.problems(fig, figures.draw(fig).get_renderer())


def clean():
    fig = figures.new_figure(6.4, 3.6)
    ax = fig.add_subplot()
    for k, engine in enumerate(("legacy", "port_printed", "port_corrected")):
        ax.plot(X, np.sin(np.radians(X)) + 0.2 * k, label=engine, **figures.ENGINE_STYLE[engine])
    ax.set_xlabel("crank angle (deg)")
    ax.set_ylabel("slider displacement (in)")
    ax.set_title("a clean figure")
    ax.set_ylim(-1.2, 2.8)
    ax.legend(loc="upper left", ncols=3)
    fig.subplots_adjust(left=0.12, right=0.97, bottom=0.15, top=0.9)
    return fig, ax


def test_a_clean_figure_passes(tmp_path):
    fig, _ = clean()
    assert drawn(fig) == []
    path = figures.save(fig, tmp_path / "clean.png", "A clean figure: three sines, in words")
    assert figures.caption_of(path) == "A clean figure: three sines, in words"
    with pytest.raises(ValueError, match="caption"):
        figures.save(fig, tmp_path / "bare.png", " ")
    with Image.open(path) as image:
        assert image.mode == "P" and image.size == (int(6.4 * figures.DPI), int(3.6 * figures.DPI))


@pytest.mark.parametrize("breaks, found", [
    (lambda fig, ax: ax.tick_params(labelsize=7), "at 7 pt"),
    (lambda fig, ax: fig.set_figwidth(13), "13.0 in wide"),
    (lambda fig, ax: ax.text(180, 0.0, "a note on the curve", fontsize=9), "px of data"),
    (lambda fig, ax: ax.legend(loc="center"), "px of data"),
    (lambda fig, ax: ax.set_ylabel("deflection (in, rad)"), "several units"),
    (lambda fig, ax: ax.set_xlabel(""), "without a x label"),
    (lambda fig, ax: fig.text(0.5, 0.93, "over the title", ha="center", fontsize=10), "over"),
    (lambda fig, ax: fig.text(0.5, 0.9, "two lines\nover the title", ha="center", fontsize=10), "'two lines"),
    (lambda fig, ax: (ax.plot(X, 0 * X + 2.0, color="tab:blue", label="legacy again"), ax.legend(loc="upper left")),
     "look alike"),
])
def test_each_rule_broken_is_found(breaks, found):
    fig, ax = clean()
    breaks(fig, ax)
    assert any(found in problem for problem in drawn(fig)), drawn(fig)


def test_strict_mode_raises_and_otherwise_warns(tmp_path, monkeypatch):
    fig, ax = clean()
    ax.tick_params(labelsize=6)
    monkeypatch.setenv(figures.STRICT_ENV, "1")
    with pytest.raises(figures.FigureError, match="at 6 pt"):
        figures.save(fig, tmp_path / "small.png", "small")
    monkeypatch.delenv(figures.STRICT_ENV)
    with pytest.warns(figures.FigureWarning, match="at 6 pt"):
        figures.save(fig, tmp_path / "small.png", "small")


def test_a_curve_far_off_scale_is_checked_within_its_axes():
    # a spike of 1e15 (the 1991 loads at a dead centre) beyond the y-limits: the check samples
    # only what the axes show (it once sampled the whole curve, 1e14 pixels long, every 2 px)
    fig, ax = clean()
    spike = np.where(np.abs(X - 340.0) < 1.0, 1e15, np.sin(np.radians(X)))
    ax.plot(X, spike, color="tab:red", label="a spike")
    ax.legend(loc="upper left", ncols=2)
    assert drawn(fig) == []
    ax.text(335.0, 2.2, "on", fontsize=9)
    assert any("px of data" in problem for problem in drawn(fig))


def test_a_tick_outside_a_log_view_is_not_counted():
    """matplotlib decides which ticks it draws in the axis's scale: on a log axis viewing 0.16 to
    6e16, the tick at 1e-2 is not drawn, and its label (left where the view's edge would put it,
    under the neighbouring panel's last label) is no text over another."""
    fig = figures.new_figure(11.0, 4.0)
    axes = fig.subplots(1, 2, sharey=True)
    for ax in axes:
        ax.loglog([1.0, 1e16], [1e-15, 1.0], "o")
        ax.set_xlabel("condition")
    axes[0].set_ylabel("relative error")
    fig.subplots_adjust(left=0.07, right=0.97, bottom=0.15, top=0.9, wspace=0.04)
    renderer = figures.draw(fig).get_renderer()
    assert figures.problems(fig, renderer) == []
    outside = [tick.label1 for tick in axes[0].xaxis.get_major_ticks() if tick.get_loc() < axes[0].get_xlim()[0]]
    assert outside and all(label.get_text() for label in outside)
    assert not {id(label) for label in outside} & set(renderer.drawn)


def test_the_checks_need_the_renderer_that_notes_the_texts():
    fig, _ = clean()
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    with pytest.raises(TypeError, match="figures.draw"):
        figures.problems(fig, canvas.get_renderer())


#: every scene whose figures this project's harness draws (rahman1991-example's are its own tests')
SCENES = ["ali1977-table1", "ali1977-table2", "ali1977-table3", "ali1977-appendixA", "ali1977-case3-convergence",
          "ali1977-conditioning", "rahman1996-table5_1", "rahman1996-table5_2", "rahman1996-table5_3",
          "rahman1996-table5_4", "rahman1996-table5_5", "rahman1996-table5_6", "rahman1996-table5_7",
          "rahman1996-figures"]


def test_every_figure_of_a_run_passed_the_checks_and_has_a_caption(tmp_path):
    """Run the scenes with the checks strict (conftest): a figure that broke a rule would have
    failed the run; every PNG was written by figures.save (a caption in words, a palette), reads
    in a column of the page, and the scenes' folders hold their figures in reading order; the run's
    report.html, every published table on it, keeps within html_report.PAGE_BUDGET with room to spare."""
    from linkrepro.harness.cli import main
    assert os.environ.get(figures.STRICT_ENV)
    assert main(["reproduce", "--skip-readings", *SCENES, "--out", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.rglob("*.png"))
    assert {p.parent.name for p in pngs} == set(SCENES) - {"rahman1996-table5_1"}    # Table 5.1: rows of text
    for png in pngs:
        assert len(figures.caption_of(png).split()) >= 20, png
        with Image.open(png) as image:
            assert image.mode == "P" and image.width <= figures.MAX_WIDTH_IN * figures.DPI, png
    assert [p.name for p in sorted((tmp_path / "ali1977-appendixA").glob("*.png"))] == [
        "case1.png", "case2.png", "case3.png"]
    # the page of every published table and 18 of a full run's 22 figures leaves the budget room for the
    # sections this run leaves out (bench, arithmetic, elastodynamics, the multibody scenes, rahman1991-example:
    # 0.36 MB of a full run's 1.39 MB page, measured 2026-11-28)
    from linkrepro.harness.html_report import PAGE_BUDGET
    assert (tmp_path / "report.html").stat().st_size <= PAGE_BUDGET - 400_000


def test_a_run_whose_figure_breaks_a_rule_fails(tmp_path, monkeypatch):
    """The check above can fail: with every text declared too small, the same run raises."""
    from linkrepro.harness.cli import main
    monkeypatch.setattr(figures, "MIN_TEXT_PT", 30.0)
    with pytest.raises(figures.FigureError, match=r"text .* at \d+ pt"):
        main(["reproduce", "--skip-readings", "rahman1996-table5_2", "--out", str(tmp_path)])
