"""Every registered figure renders, has labelled axes, plots the right data, and is written
deterministically. The data checks (and their oracles) are in ``_figure_oracles.py``."""

from __future__ import annotations

import hashlib
from pathlib import Path

import matplotlib.pyplot as plt
import pytest
from _figure_appearance import check_appearance
from _figure_oracles import CHECKS, scaled

from navcore import figures

FIG_IDS = list(figures.registry())


@pytest.mark.parametrize("fig_id", FIG_IDS)
def test_figure_renders_with_labels(fig_id, tmp_path):
    spec = figures.spec(fig_id)
    assert spec.caption.strip() and spec.reproduces.strip()
    fig = figures.render(fig_id)
    try:
        plot_axes = [ax for ax in fig.axes if ax.has_data() and ax.get_label() != "<colorbar>"]
        for ax in plot_axes:
            if ax.axison:
                # a grid of panels with shared axes labels its outer panels only
                shared = [*ax.get_shared_x_axes().get_siblings(ax), *ax.get_shared_y_axes().get_siblings(ax)]
                labelled = any(a.get_xlabel() or a.get_ylabel() for a in shared)
                assert labelled, f"{fig_id}: an axis without labels"
        # what a reader sees beyond the data (colours, styles, limits, legend, texts): the
        # reviewed appearance recorded in figure_appearance.json
        check_appearance(fig_id, fig)
        paths = figures.write(fig, tmp_path / fig_id)
        assert all(p.stat().st_size > 0 for p in paths)
        # the data it plots, against the model and an oracle; the same check must fail on the
        # data scaled by 1/57 (a check that cannot fail checks nothing)
        data = figures.plotted(fig)
        CHECKS[fig_id](data)
        with pytest.raises(AssertionError):
            CHECKS[fig_id](scaled(data, 1 / 57))
    finally:
        plt.close(fig)


def test_figure_files_are_deterministic(tmp_path):
    """Two writes of the same figure give byte-identical SVG and PNG (no dates, fixed hash salt)."""
    import numpy as np

    def make():
        figures.apply_style()
        fig, ax = plt.subplots()
        ax.plot(np.arange(5), np.arange(5) ** 2, label="x^2")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m^2)")
        ax.legend()
        return fig

    digests = []
    for k in range(2):
        fig = make()
        paths = figures.write(fig, tmp_path / f"f{k}")
        plt.close(fig)
        digests.append([hashlib.sha256(p.read_bytes()).hexdigest() for p in paths])
    assert digests[0] == digests[1]


def test_dotted_ids_keep_their_full_name(tmp_path):
    """Regression: 'X-fig2.16' must be written as X-fig2.16.svg, not X-fig2.svg."""
    fig, ax = plt.subplots()
    ax.plot([0, 1])
    paths = figures.write(fig, tmp_path / "X-fig2.16")
    plt.close(fig)
    assert sorted(p.name for p in paths) == ["X-fig2.16.png", "X-fig2.16.svg"]


def test_register_rejects_bad_specs():
    with pytest.raises(ValueError, match="paper must be one of"):
        figures.register("X", paper="ZZ", reproduces="Fig. 1", caption="c")
    with pytest.raises(ValueError, match="caption"):
        figures.register("X", paper="WF", reproduces="Fig. 1", caption=" ")
    with pytest.raises(ValueError, match="not registered"):
        figures.spec("no-such-figure")


def test_value_bars_draws_each_value_its_label_the_printed_mark_and_the_legend():
    """Oracle: the geometry written out by hand. Bars of width 0.7 centred on 0, 1, ...; each
    value printed above its bar (8 pt, 2 pt up); the printed value a black diamond at the bar's
    right edge; the legend's handles in the given colours, then the printed mark's."""
    from matplotlib.colors import to_rgba

    fig, ax = plt.subplots()
    try:
        figures.value_bars(
            ax,
            {"a": 12.0, "b": 7.5, "c": 3.0},
            fmt="{:.1f}",
            printed={"b": 8.0, "c": 2.5},
            printed_label="printed",
            colours={"a": "tab:red"},
            legend={"tab:red": "red", "tab:blue": "blue"},
            log=True,
        )
        bars = ax.patches
        assert [(b.get_x(), b.get_width(), b.get_height()) for b in bars] == [
            (-0.35, 0.7, 12.0),
            (0.65, 0.7, 7.5),
            (1.65, 0.7, 3.0),
        ]
        assert [b.get_facecolor() for b in bars] == [
            to_rgba("tab:red"),
            to_rgba("tab:blue"),
            to_rgba("tab:blue"),
        ]
        labels = [(t.get_text(), t.xy, t.get_ha(), t.get_va(), t.get_fontsize(), t.xyann, t.anncoords)
                  for t in ax.texts]  # fmt: skip
        assert labels == [
            ("12.0", (0, 12.0), "center", "bottom", 8.0, (0, 2), "offset points"),
            ("7.5", (1, 7.5), "center", "bottom", 8.0, (0, 2), "offset points"),
            ("3.0", (2, 3.0), "center", "bottom", 8.0, (0, 2), "offset points"),
        ]
        (marks,) = ax.get_lines()
        assert marks.get_xydata().tolist() == [[1.35, 8.0], [2.35, 2.5]]
        assert (marks.get_marker(), to_rgba(marks.get_color()), marks.get_markersize(), marks.get_linestyle(),
                marks.get_zorder()) == ("D", to_rgba("k"), 6.0, "None", 3)  # fmt: skip
        legend = ax.get_legend()
        assert [t.get_text() for t in legend.get_texts()] == ["red", "blue", "printed"]
        assert all(t.get_fontsize() == 8.0 for t in legend.get_texts())
        assert legend._loc == 1  # "upper right"
        patch_red, patch_blue, mark = legend.legend_handles
        assert (patch_red.get_facecolor(), patch_blue.get_facecolor()) == (
            to_rgba("tab:red"),
            to_rgba("tab:blue"),
        )
        mark_style = (
            mark.get_marker(),
            to_rgba(mark.get_color()),
            mark.get_markersize(),
            mark.get_linestyle(),
        )
        assert mark_style == ("D", to_rgba("k"), 6.0, "None")
        assert [t.get_text() for t in ax.get_xticklabels()] == ["a", "b", "c"]
        assert ax.get_xticks().tolist() == [0, 1, 2]
        assert all(t.get_rotation() == 20.0 for t in ax.get_xticklabels())
        assert (ax.margins()[1], ax.get_yscale()) == (0.12, "log")
    finally:
        plt.close(fig)


def test_value_bars_defaults_blue_this_book_linear_no_marks():
    """Oracle: the defaults by hand: every bar the book's blue, the legend 'this book', no
    printed marks, a linear axis, values formatted with no decimals; printed marks are
    'printed in the paper'."""
    from matplotlib.colors import to_rgba

    fig, ax = plt.subplots()
    try:
        figures.value_bars(ax, {"x": 2.6, "y": 1.2})
        assert [b.get_facecolor() for b in ax.patches] == [to_rgba("tab:blue")] * 2
        assert [t.get_text() for t in ax.texts] == ["3", "1"]
        assert ax.get_lines() == [] and ax.get_yscale() == "linear"
        legend = ax.get_legend()
        assert [t.get_text() for t in legend.get_texts()] == ["this book"]
        assert legend.legend_handles[0].get_facecolor() == to_rgba("tab:blue")
        ax.clear()
        figures.value_bars(ax, {"x": 2.6}, printed={"x": 3.0})
        assert [t.get_text() for t in ax.get_legend().get_texts()] == ["this book", "printed in the paper"]
    finally:
        plt.close(fig)


def test_a_legend_over_the_data_moves_to_a_free_place_or_below_the_axes():
    """Oracle: hand-made figures. Lines along the top and the bottom leave only the centre right
    free (the first free place in the book's order of corners); points everywhere leave none,
    and the legend goes below the axes, centred, 0.14 of the axes' height down."""
    import numpy as np

    figures.apply_style()
    fig, ax = plt.subplots()
    x = np.linspace(0.0, 1.0, 50)
    ax.plot(x, np.ones(50), label="top")
    ax.plot(x, np.zeros(50), label="bottom")
    ax.set_ylim(-0.1, 1.1)
    legend = ax.legend(loc="upper right")
    fig.canvas.draw()
    assert figures._covered(ax, legend) == 1
    figures.tidy_legends(fig)
    assert legend._loc == 7 and figures._covered(ax, legend) == 0  # "center right"
    plt.close(fig)

    fig, ax = plt.subplots()
    g = np.linspace(0.0, 1.0, 40)
    grid_x, grid_y = np.meshgrid(g, g)
    ax.scatter(grid_x.ravel(), grid_y.ravel(), s=2, label="everywhere")
    legend = ax.legend()
    figures.tidy_legends(fig)
    assert legend._loc == 9  # "upper center"
    np.testing.assert_allclose(legend.get_bbox_to_anchor().bounds[:2], ax.transAxes.transform((0.5, -0.14)))
    plt.close(fig)


def test_covered_counts_lines_bars_texts_and_points_under_the_legend():
    """Oracle: by hand, a legend in the upper right corner over one line, a one-point line, one
    bar, one text and two of four points: 6; an empty line and a hidden one, drawn first, count
    nothing, and a point level with the legend but left of it is not under it."""
    fig, ax = plt.subplots()
    try:
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.plot([], [], label="empty")
        (hidden,) = ax.plot([0.9, 0.95], [0.9, 0.9], label="hidden")
        hidden.set_visible(False)
        ax.plot([0.9, 0.95], [0.95, 0.95], label="line")
        ax.plot([0.93], [0.94], "o", label="one point")
        ax.bar([0.9], [0.97], width=0.02, label="bar")
        ax.text(0.9, 0.93, "text")
        # two points under the legend; one level with it but to its left; one far away
        ax.scatter([0.92, 0.94, 0.1, 0.1], [0.96, 0.96, 0.96, 0.1], label="points")
        legend = ax.legend(loc="upper right")
        fig.canvas.draw()
        assert figures._covered(ax, legend) == 6
        figures.tidy_legends(fig)
        assert legend._loc != 1
    finally:
        plt.close(fig)


def test_write_all_writes_the_figures_asked_for_and_refuses_an_unknown_id(tmp_path):
    """Oracle: the file names by hand, an SVG and a PNG per id in the order asked, each
    non-empty, and every figure closed afterwards."""
    before = plt.get_fignums()
    paths = figures.write_all(tmp_path / "out", only=["KZL-fig1", "SP-architectures"])
    assert [p.name for p in paths] == [
        "KZL-fig1.svg",
        "KZL-fig1.png",
        "SP-architectures.svg",
        "SP-architectures.png",
    ]
    assert all(p.parent == tmp_path / "out" and p.stat().st_size > 0 for p in paths)
    assert plt.get_fignums() == before
    with pytest.raises(ValueError, match="not registered"):
        figures.write_all(tmp_path, only=["no-such-figure"])


def test_register_records_the_spec_and_refuses_a_second_function_under_one_id(monkeypatch):
    """Oracle: the FigureSpec written out by hand; registering the same function again (a
    module imported twice) is allowed, another function under the same id is not."""
    monkeypatch.setattr(figures, "_REGISTRY", dict(figures._REGISTRY))

    def draw():
        return plt.figure()

    assert figures.register("KZL-test", paper="KZL", reproduces="Fig. 9", caption="c")(draw) is draw
    assert figures._REGISTRY["KZL-test"] == figures.FigureSpec("KZL-test", "KZL", "Fig. 9", "c", draw)
    figures.register("KZL-test", paper="KZL", reproduces="Fig. 9", caption="c")(draw)

    def other():
        return plt.figure()

    with pytest.raises(ValueError, match="registered twice"):
        figures.register("KZL-test", paper="KZL", reproduces="Fig. 9", caption="c")(other)
    with pytest.raises(ValueError, match="registered twice"):
        figures.register("KZL-fig1", paper="KZL", reproduces="Fig. 1", caption="c")(other)


def test_write_all_by_default_writes_every_registered_figure_to_figures(tmp_path, monkeypatch):
    """Oracle: the defaults by hand, the folder ``figures`` of the working directory and every
    registered figure (here a registry of one)."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(figures, "registry", lambda: {"KZL-fig1": figures.spec("KZL-fig1")})
    paths = figures.write_all()
    assert paths == [Path("figures") / "KZL-fig1.svg", Path("figures") / "KZL-fig1.png"]
    assert all((tmp_path / p).stat().st_size > 0 for p in paths)


def test_the_micro_g_axis_functions_are_each_others_inverse():
    """Oracle: 1 ug = 9.80665e-6 m/s^2 (the standard gravity) by hand; matplotlib's secondary
    axis needs the forward and inverse functions to be each other's inverse."""
    import numpy as np

    from navcore.figures import wf as wf_figures

    x = np.array([1e-5, 9.80665e-4, 1.0])
    np.testing.assert_allclose(wf_figures._to_micro_g(x), x / 9.80665e-6, rtol=1e-12)
    np.testing.assert_allclose(wf_figures._from_micro_g(wf_figures._to_micro_g(x)), x, rtol=1e-12)


def test_varying_range_runs_from_the_first_curve_in_view_to_the_last_flattening():
    """Oracle: a synthetic curve on a 0.1 dB grid, thresholds placed by hand. It is in view
    (more than 0.05 decades above the floor) from 12 dB, and within 0.02 decades of its plateau
    from 38.1 dB on: padded by 2 dB and rounded out to 5 dB the range is 10 to 40 dB. The
    points exactly at 0.05 above the floor (11.9 dB) and exactly 0.02 below the plateau
    (38.1 dB) are outside; the curve stays within a decade of the floor up to 17 dB."""
    import numpy as np

    from navcore.figures.atc10_jamming import LOG10_FLOOR, X_AXIS_DB, varying_range

    x = np.round(np.arange(-20.0, 80.05, 0.1), 10)
    y = np.full_like(x, LOG10_FLOOR - 1.0)
    y[np.isclose(x, 11.9)] = LOG10_FLOOR + 0.05
    y[(x > 11.95) & (x < 16.95)] = LOG10_FLOOR + 0.06
    ramp = (x > 16.95) & (x < 38.05)
    y[ramp] = np.linspace(LOG10_FLOOR + 1.1, -0.03, ramp.sum())
    y[np.isclose(x, 38.1)] = 0.0 - 0.02
    y[x > 38.15] = 0.0
    assert varying_range(x, [y]) == (10.0, 40.0)
    assert varying_range(x, [y], pad_db=3.0) == (5.0, 45.0)
    # a curve that moves at one point only: that point, padded
    step = np.where(x < 29.95, LOG10_FLOOR - 1.0, 0.0)
    step[np.isclose(x, 30.0)] = -1.0
    assert varying_range(x, [step]) == (25.0, 35.0)
    # a flat curve never moves: the whole axis
    assert varying_range(x, [np.zeros_like(x)]) == X_AXIS_DB
    # padding beyond the axis is clipped to it
    assert varying_range(x, [y], pad_db=40.0) == X_AXIS_DB


def test_covered_counts_a_point_within_two_pixels_of_the_legend_and_not_beyond():
    """Oracle: points placed by hand in display pixels, 1.5 px and 2.5 px left of the legend's
    box: the first counts (the box is padded by 2 px), the second does not."""
    fig, ax = plt.subplots()
    try:
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.plot([0.0, 0.1], [0.0, 0.1], label="far away")
        legend = ax.legend(loc="upper right")
        fig.canvas.draw()
        box = legend.get_window_extent()
        to_data = ax.transData.inverted()
        near, beyond = (to_data.transform((box.x0 - d, (box.y0 + box.y1) / 2)) for d in (1.5, 2.5))
        ax.scatter([beyond[0]], [beyond[1]])
        fig.canvas.draw()
        assert figures._covered(ax, legend) == 0
        ax.scatter([near[0]], [near[1]])
        fig.canvas.draw()
        assert figures._covered(ax, legend) == 1
    finally:
        plt.close(fig)
