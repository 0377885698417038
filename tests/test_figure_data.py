"""The data a figure plots (issue 31, item 3): every registered figure has a data check, the
extraction reads what matplotlib drew, and a planted change in a figure's code fails its check.

The checks themselves run in ``test_figures.py`` on each rendered figure (one render per
figure); their oracles are named in ``_figure_oracles.py``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pytest
from _figure_oracles import CHECKS, scaled

from navcore import figures


def test_every_registered_figure_has_a_data_check():
    assert sorted(figures.registry()) == sorted(CHECKS)


def test_plotted_reads_lines_bars_segments_patches_and_texts():
    """Oracle: a hand-made figure and the arrays written out by hand."""
    fig, (ax, bx) = plt.subplots(1, 2)
    try:
        ax.plot([1.0, 2.0, 3.0], [4.0, 5.0, 6.0], label="model")
        ax.axhline(2.5, label="level")
        ax.bar([0.0, 1.0], [7.0, 8.0], label="counts")
        ax.vlines([-1.0, 1.0], 0.0, 0.5, label="masses")
        ax.axvspan(0.2, 0.4, label="span")
        ax.annotate("7", (0.0, 7.0))
        ax.set_xlabel("x (m)")
        ax.set_yscale("log")
        bx.imshow(np.arange(6.0).reshape(2, 3))
        bx.set_title("image")
        data = figures.plotted(fig)
    finally:
        plt.close(fig)
    first, second = data
    assert (first.xlabel, first.yscale, first.texts) == ("x (m)", "log", ("7",))
    assert first.get("model").y.tolist() == [4.0, 5.0, 6.0]
    assert first.get("level").y.tolist() == [2.5, 2.5]
    assert first.get("counts", kind="bars").x.tolist() == [0.0, 1.0]
    assert first.get("counts").y.tolist() == [7.0, 8.0]
    masses = first.get("masses")
    assert (masses.kind, masses.x.tolist(), masses.y.tolist()) == (
        "segments",
        [-1, -1, 1, 1],
        [0, 0.5, 0, 0.5],
    )
    span = first.get("span")
    assert span.kind == "patch" and (span.x.min(), span.x.max()) == (0.2, 0.4)
    (image,) = second.of_kind("image")
    assert second.title == "image" and image.y.tolist() == [[0, 1, 2], [3, 4, 5]]
    with pytest.raises(KeyError, match="0 series labelled 'nope'"):
        first.get("nope")


def test_a_line_57_times_too_small_fails_its_figure_check(monkeypatch):
    """The planted bug of issue 31: SP Fig. 2.1's loop error drawn 57 times too small (the
    figure's code divides the model's error by 57). Its check recomputes the curve from the
    library and compares it with the printed 90 deg peak: it fails."""
    import navcore.figures.sp_tracking as fig_module

    real = fig_module.third_order_loop_step_error
    monkeypatch.setattr(fig_module, "third_order_loop_step_error", lambda *a, **k: real(*a, **k) / 57)
    data = figures.render_data("SP-fig2.1")
    with pytest.raises(AssertionError, match="Not equal to tolerance"):
        CHECKS["SP-fig2.1"](data)
    monkeypatch.undo()
    CHECKS["SP-fig2.1"](figures.render_data("SP-fig2.1"))


def test_every_check_fails_on_scaled_data_of_a_synthetic_kind():
    """scaled() multiplies every ordinate and every number a text prints."""
    axes = figures.PlottedAxes(
        "t", "x", "y", "linear", "linear",
        series=(figures.Series("line", "a", np.array([1.0]), np.array([57.0])),),
        texts=("17 states, 100 Hz",),
    )  # fmt: skip
    (out,) = scaled([axes], 1 / 57)
    assert out.series[0].y.tolist() == [1.0] and out.texts == ("0.298246 states, 1.75439 Hz",)


def test_masked_values_are_read_as_nan_and_integers_as_floats():
    """Oracle: by hand; a masked entry (a gap matplotlib does not draw) reads as NaN, never as a
    fill value, for integer and float data alike."""
    ints = figures._floats(np.ma.masked_array([1, 2, 3], mask=[False, True, False]))
    floats = figures._floats(np.ma.masked_array([1.5, 2.5], mask=[True, False]))
    assert ints.dtype == np.float64 and floats.dtype == np.float64
    np.testing.assert_array_equal(ints, [1.0, np.nan, 3.0])
    np.testing.assert_array_equal(floats, [np.nan, 2.5])
    assert figures._floats([1, 2]).tolist() == [1.0, 2.0]


def test_a_segment_reads_as_its_two_ends_and_an_empty_collection_as_nothing():
    """Oracle: by hand; a three-point segment (a polyline in a LineCollection) reads as its first
    and last points; ``vlines`` of no values reads as an empty series."""
    from matplotlib.collections import LineCollection

    fig, ax = plt.subplots()
    try:
        ax.add_collection(LineCollection([[(0.0, 1.0), (2.0, 3.0), (4.0, 5.0)]], label="polyline"))
        ax.vlines([], 0.0, 1.0, label="none")
        (axes,) = figures.plotted(fig)
    finally:
        plt.close(fig)
    poly = axes.get("polyline")
    assert (poly.kind, poly.x.tolist(), poly.y.tolist()) == ("segments", [0.0, 4.0], [1.0, 5.0])
    none = axes.get("none")
    assert (none.kind, none.x.tolist(), none.y.tolist()) == ("segments", [], [])


def test_a_scatter_reads_as_its_points():
    """Oracle: by hand; a scatter's offsets are its points, in order."""
    fig, ax = plt.subplots()
    try:
        ax.scatter([1.0, 2.0, 3.0], [4.0, 5.0, 6.0], label="dots")
        (axes,) = figures.plotted(fig)
    finally:
        plt.close(fig)
    dots = axes.get("dots")
    assert (dots.kind, dots.x.tolist(), dots.y.tolist()) == ("points", [1.0, 2.0, 3.0], [4.0, 5.0, 6.0])
