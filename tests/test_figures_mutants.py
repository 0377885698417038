"""The figure helpers on hand-made inputs the registered figures never give them (issue 31,
mutation testing of ``navcore.figures``).

The registered figures' data and appearance are checked in ``test_figures.py``; the helpers
below also meet inputs no registered figure draws (a colour bar, an image, a span's height, a
patch that is neither a rectangle nor a polygon, a contour whose smallest value is of one kind
or another), and a mutant that changes only those cases survives the figure checks. Each test
is a table of small cases whose expected values are written out by hand.
"""

from __future__ import annotations

from collections.abc import Callable
from types import SimpleNamespace
from typing import Any

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.patches import Circle, Rectangle

from navcore import figures
from navcore.figures import atc10_multiple_access as ma_figures


def _image_with_colour_bar(fig: Any, ax: Any) -> None:
    image = ax.imshow(np.arange(6.0).reshape(2, 3), extent=(0.0, 3.0, 0.0, 2.0), label="field")
    fig.colorbar(image)
    ax.set_title("image")


def _colour_bar_between_two_axes(fig: Any, ax: Any) -> None:
    ax.plot([0.0, 1.0], [2.0, 3.0], label="first")
    fig.colorbar(ax.imshow(np.ones((2, 2)), label="field"))
    later = fig.add_axes((0.1, 0.1, 0.2, 0.2))
    later.plot([4.0, 5.0], [6.0, 7.0], label="second")
    later.set_title("later")


def _bars_only(fig: Any, ax: Any) -> None:
    ax.bar([0.0, 1.0], [7.0, 8.0], label="counts")


def _span_and_polygon(fig: Any, ax: Any) -> None:
    ax.axvspan(0.2, 0.4, label="span")
    ax.fill([0.0, 1.0, 1.0], [0.0, 0.0, 2.0], label="triangle")


def _circle_then_rectangle(fig: Any, ax: Any) -> None:
    ax.add_patch(Circle((0.0, 0.0), 1.0, label="circle"))
    ax.add_patch(Rectangle((1.0, 2.0), 3.0, 4.0, label="box"))


def _labels_and_scales(fig: Any, ax: Any) -> None:
    ax.plot([1.0, 10.0], [1.0, 2.0], label="line")
    ax.set_title("a title")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (s)")
    ax.set_xscale("log")


#: (name, what is drawn, expected per axes: title, labels, scales, and each series as
#: (kind, label, x, y)). The expected values are written out by hand.
PLOTTED_CASES: list[tuple[str, Callable[[Any, Any], None], list[dict[str, Any]]]] = [
    (
        # a colour bar is not a data axes; an image reads as its extent and its array
        "image with a colour bar",
        _image_with_colour_bar,
        [
            {
                "title": "image",
                "series": [("image", "field", [0.0, 3.0, 0.0, 2.0], [[0.0, 1.0, 2.0], [3.0, 4.0, 5.0]])],
            }
        ],
    ),
    (
        # an axes drawn after a colour bar is still read
        "colour bar between two axes",
        _colour_bar_between_two_axes,
        [
            {
                "series": [
                    ("line", "first", [0.0, 1.0], [2.0, 3.0]),
                    ("image", "field", [-0.5, 1.5, 1.5, -0.5], [[1.0, 1.0], [1.0, 1.0]]),
                ]
            },
            {"title": "later", "series": [("line", "second", [4.0, 5.0], [6.0, 7.0])]},
        ],
    ),
    (
        # a bar is read once, as a bar, never again as a patch
        "bars only",
        _bars_only,
        [{"series": [("bars", "counts", [0.0, 1.0], [7.0, 8.0])]}],
    ),
    (
        # a vertical span covers the axes' height: y from 0 to 1 (axes coordinates)
        "span and polygon",
        _span_and_polygon,
        [
            {
                "series": [
                    ("patch", "span", [0.2, 0.4, 0.4, 0.2], [0.0, 0.0, 1.0, 1.0]),
                    ("patch", "triangle", [0.0, 1.0, 1.0, 0.0], [0.0, 0.0, 2.0, 0.0]),
                ]
            }
        ],
    ),
    (
        # a patch of another shape is skipped, and the patches after it are still read
        "circle then rectangle",
        _circle_then_rectangle,
        [{"series": [("patch", "box", [1.0, 4.0, 4.0, 1.0], [2.0, 2.0, 6.0, 6.0])]}],
    ),
    (
        "labels and scales",
        _labels_and_scales,
        [
            {
                "title": "a title",
                "xlabel": "x (m)",
                "ylabel": "y (s)",
                "xscale": "log",
                "yscale": "linear",
                "series": [("line", "line", [1.0, 10.0], [1.0, 2.0])],
            }
        ],
    ),
]


@pytest.mark.parametrize(
    ("draw", "expected"), [c[1:] for c in PLOTTED_CASES], ids=[c[0] for c in PLOTTED_CASES]
)
def test_plotted_reads_each_kind_of_artist_once(draw, expected):
    """Oracle: by hand (the coordinates drawn, a polygon's closing vertex as matplotlib's
    ``fill`` stores it). :func:`navcore.figures.plotted` returns one entry per data axes (no
    colour bar), with its title, axis labels and scales, and every series once."""
    fig, ax = plt.subplots()
    try:
        draw(fig, ax)
        data = figures.plotted(fig)
    finally:
        plt.close(fig)
    assert len(data) == len(expected)
    for axes, want in zip(data, expected, strict=True):
        for key in ("title", "xlabel", "ylabel", "xscale", "yscale"):
            if key in want:
                assert getattr(axes, key) == want[key], key
        got = [(s.kind, s.label, s.x.tolist(), s.y.tolist()) for s in axes.series]
        assert got == want["series"]


def _fake_model(monkeypatch, densities: dict[str, tuple[list[float], ...]]) -> None:
    """Replace the model behind :func:`_column_limit` by hand-made values per density:
    (upper bound p_f, upper bound 1 - p_d, actual p_f, actual 1 - p_d); the bounds as
    probabilities (the figure module reads their logarithms)."""
    bounds = {name: tuple(np.log(np.array(v[:2]))) for name, v in densities.items()}
    rocs = {name: SimpleNamespace(p_f=np.array(v[2]), p_miss=np.array(v[3])) for name, v in densities.items()}
    monkeypatch.setattr(ma_figures, "m", SimpleNamespace(DENSITY_NAMES=tuple(densities)))
    monkeypatch.setattr(ma_figures, "gaussian", SimpleNamespace(exact_roc=lambda name, x: rocs[name]))
    monkeypatch.setattr(ma_figures, "_bounds", lambda name, x: (*bounds[name], None, None))


_FLAT = ([0.5, 0.2], [0.5, 0.2], [0.3, 0.02], [0.02, 0.3])

#: (case, densities as in _fake_model, the axis limit): the decade below the smallest value
#: drawn, over every density; an actual-ROC point with p_f = 0 or 1 - p_d = 0 is not drawn
#: (a log axis cannot show it) and does not count.
COLUMN_LIMIT_CASES = [
    ("all above 1e-2", {"C1": _FLAT}, 1e-2),
    ("upper bound's miss smallest", {"C1": _FLAT, "C2": ([0.5], [3e-5], [0.3], [0.02])}, 1e-5),
    ("upper bound's p_f smallest", {"C1": ([4e-7], [0.5], [0.3], [0.02]), "C2": _FLAT}, 1e-7),
    ("actual miss smallest", {"C1": _FLAT, "C2": ([0.5], [0.5], [0.3, 0.1], [0.2, 6e-4])}, 1e-4),
    ("actual p_f smallest", {"C1": ([0.5], [0.5], [0.1, 2e-9], [0.2, 0.3]), "C2": _FLAT}, 1e-9),
    ("a zero p_f is not drawn", {"C1": ([0.5], [0.5], [0.0, 0.3], [1e-9, 0.02])}, 1e-2),
    ("a zero miss is not drawn", {"C1": ([0.5], [0.5], [1e-9, 0.3], [0.0, 0.02])}, 1e-2),
]


@pytest.mark.parametrize(
    ("densities", "limit"), [c[1:] for c in COLUMN_LIMIT_CASES], ids=[c[0] for c in COLUMN_LIMIT_CASES]
)
def test_column_limit_is_the_decade_below_the_smallest_value_drawn(monkeypatch, densities, limit):
    """Oracle: by hand, 10^floor(log10(min)) of the values listed, each case making a different
    one of the four kinds (upper bound or actual ROC, p_f or miss) the smallest, or offering a
    zero that the figure cannot draw. ATC-10 Figs. 3.3-3.6 share this limit down a column."""
    _fake_model(monkeypatch, densities)
    assert ma_figures._column_limit(3.0) == pytest.approx(limit, rel=1e-12)


#: (range where the curves change, the J/(P0 B tau) axis drawn): the whole paper axis
#: (-20 dB to 80 dB) when that range is wider than half of it (50 dB), else that range.
K_FIGURE_RANGES = [
    ((0.0, 40.0), (0.0, 40.0)),
    ((-20.0, 30.0), (-20.0, 30.0)),
    ((0.0, 55.0), (-20.0, 80.0)),
]


@pytest.mark.parametrize(
    ("moving", "drawn"), K_FIGURE_RANGES, ids=[f"{w[1] - w[0]:g} dB" for w, _ in K_FIGURE_RANGES]
)
def test_k_figure_draws_the_paper_axis_only_when_the_curves_change_over_more_than_half_of_it(
    monkeypatch, moving, drawn
):
    """Oracle: the rule of ATC-10 Figs. 2.3-2.16 as the book draws them, by hand: a figure whose
    curves all change within half the paper's axis (at most 50 dB of -20 to 80 dB) is drawn on
    that part only (40 dB, and exactly 50 dB), a wider one on the whole axis (55 dB). The
    curves are replaced by flat ones and the range where they change is given, so that only
    the rule is tested."""
    from navcore.figures import atc10_jamming as jam_figures

    monkeypatch.setattr(jam_figures, "varying_range", lambda x, curves: moving)
    monkeypatch.setattr(jam_figures, "log10_bound", lambda quantity, x, p_dl, k, t: np.full_like(x, -3.0))
    fig = jam_figures._k_figure("false", 10, 0.88)
    try:
        assert fig.axes[0].get_xlim() == pytest.approx(drawn, abs=1e-12)
        (axes,) = figures.plotted(fig)
    finally:
        plt.close(fig)
    curves = [s for s in axes.of_kind("line") if s.label != "level"]
    assert len(curves) == 5  # one per t
    for curve in curves:
        assert (curve.x[0], curve.x[-1]) == pytest.approx(drawn, abs=1e-12)


#: (figure id, its paper): ids with one dash and with two, of three papers.
SPEC_CASES = [("KZL-fig1", "KZL"), ("ATC10-ma-tails", "ATC10"), ("SP-fig2.1", "SP")]


def test_spec_reads_only_its_papers_figure_modules(monkeypatch):
    """Oracle: the contract of :func:`navcore.figures.spec`, by hand: a figure is found
    through its own paper's modules (the paper key is the id up to its first dash), never by
    importing every figure module (the whole registry); an unknown id is refused with the
    known ones listed."""
    papers: list[str | None] = []
    discover = figures._discover
    monkeypatch.setattr(figures, "_discover", lambda paper=None: (papers.append(paper), discover(paper))[1])
    monkeypatch.setattr(figures, "registry", lambda: pytest.fail("spec read the whole registry"))
    for fig_id, paper in SPEC_CASES:
        found = figures.spec(fig_id)
        assert (found.id, found.paper) == (fig_id, paper)
    assert papers == [paper for _, paper in SPEC_CASES]
    monkeypatch.undo()
    for unknown in ("KZL-fig99", "XY-fig1", "nodash"):
        with pytest.raises(ValueError, match=rf"fig_id '{unknown}' is not registered; known: \[.*'KZL-fig1'"):
            figures.spec(unknown)


def test_write_creates_the_folders_and_leaves_out_the_date_and_the_software_version(tmp_path):
    """Oracle: the files read back, by hand: :func:`navcore.figures.write` creates missing
    folders (two levels here), keeps the dot of an id, and writes no date into the SVG and no
    matplotlib version into the PNG (the book's two builds must give the same bytes). A second
    write into the same folder succeeds."""
    from PIL import Image

    fig, ax = plt.subplots()
    try:
        ax.plot([0.0, 1.0], [0.0, 1.0])
        stem = tmp_path / "new" / "deeper" / "ATC10-fig2.16"
        svg, png = figures.write(fig, stem)
        assert figures.write(fig, stem) == [svg, png]
    finally:
        plt.close(fig)
    assert (svg.name, png.name, svg.parent) == ("ATC10-fig2.16.svg", "ATC10-fig2.16.png", stem.parent)
    text = svg.read_text(encoding="utf-8")
    assert text.startswith("<?xml") and "<svg" in text and "dc:date" not in text
    with Image.open(png) as image:
        assert image.format == "PNG" and "Software" not in image.text


def test_tidy_legends_moves_every_covering_legend_of_a_figure():
    """Oracle: hand-made panels, by hand: in three panels side by side, the first legend covers
    nothing and stays in the upper right; the second and the third each cover a line through
    the upper right corner, and each moves to the upper left, the next place in the book's
    order of corners (a legend that moves does not end the tidying of the others)."""
    figures.apply_style()
    fig, axes = plt.subplots(1, 3, figsize=(9.0, 3.0))
    try:
        legends = []
        for i, ax in enumerate(axes):
            ax.set_xlim(0.0, 1.0)
            ax.set_ylim(0.0, 1.0)
            y = 0.05 if i == 0 else 0.95  # along the bottom, or through the upper right corner
            ax.plot([0.6, 1.0], [y, y], label=f"line {i}")
            legends.append(ax.legend(loc="upper right"))
        figures.tidy_legends(fig)
        assert [legend._loc for legend in legends] == [1, 2, 2]  # upper right, upper left
        fig.canvas.draw()
        assert [figures._covered(ax, legend) for ax, legend in zip(axes, legends, strict=True)] == [0, 0, 0]
    finally:
        plt.close(fig)
