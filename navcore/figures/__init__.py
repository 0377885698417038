"""The figure registry: every reproduced figure is a function of navcore results.

A figure is a function returning a :class:`matplotlib.figure.Figure`, registered with
:func:`register` in a module of this package (one module per paper or section; modules are
discovered, so adding one never edits a shared list)::

    from navcore.figures import register

    @register("SP-fig2.1", paper="SP", reproduces="Fig. 2.1",
              caption="Third-order loop error after a 1 g acceleration step ...")
    def tracking_loop_step_error() -> Figure:
        ...

``python -m navcore figures`` (or ``nox -s figures``) writes every registered figure to
``figures/<id>.svg`` and ``figures/<id>.png`` with deterministic metadata, and the book
shows the same figures through :func:`navcore.book.show_figure`.
"""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

# No backend is forced here: a notebook kernel keeps its inline backend (so glued figures
# render as images), and a headless script gets matplotlib's default, Agg.
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from navcore.claims.declarations import PAPERS

__all__ = [
    "STYLE",
    "FigureSpec",
    "PlottedAxes",
    "Series",
    "apply_style",
    "plotted",
    "register",
    "registry",
    "render",
    "render_data",
    "spec",
    "value_bars",
    "write",
    "write_all",
]

STYLE: dict[str, Any] = {
    "figure.figsize": (6.4, 4.0),
    "figure.dpi": 110,
    "savefig.dpi": 160,
    "savefig.bbox": "tight",
    "font.size": 10,
    "axes.grid": True,
    "grid.alpha": 0.35,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "legend.frameon": False,
    "svg.hashsalt": "navcore",
    "svg.fonttype": "path",
    "lines.linewidth": 1.6,
}


def apply_style() -> None:
    """Apply the book's matplotlib style (idempotent).

    Updates :data:`matplotlib.rcParams` with :data:`STYLE`: figure size and resolution,
    grid, no top or right spine, deterministic SVG output.

    Returns
    -------
    None
        The style is global to the process.

    Examples
    --------
    >>> apply_style()
    >>> plt.rcParams["svg.hashsalt"], plt.rcParams["axes.spines.top"]
    ('navcore', False)
    """
    plt.rcParams.update(STYLE)  # type: ignore[arg-type]  # matplotlib types the keys as literals


def value_bars(
    ax: Any,
    values: dict[str, float],
    *,
    fmt: str = "{:.0f}",
    printed: dict[str, float] | None = None,
    printed_label: str = "printed in the paper",
    colours: dict[str, str] | None = None,
    legend: dict[str, str] | None = None,
    log: bool = False,
) -> None:
    """Bars of the book's values, each labelled with its value, and the paper's printed values.

    The printed values are black diamonds drawn at the right edge of their bar, so a printed
    value close to the computed one never strikes through the bar's value label (centred
    above the bar). The legend is built from explicit handles, so its colours are the bars'.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Axes to draw on.
    values : dict of str to float
        Bar label to the book's value, in drawing order.
    fmt : str
        Format of the value labels.
    printed : dict of str to float, optional
        Bar label to the value the paper prints (bars without one get no mark).
    printed_label : str
        Legend text of the printed marks.
    colours : dict of str to str, optional
        Bar label to colour (default: the book's blue for every bar).
    legend : dict of str to str, optional
        Colour to legend text, one entry per colour used (default: blue is "this book").
    log : bool
        Logarithmic value axis.

    Returns
    -------
    None
        The bars, labels, marks and legend are drawn on ``ax``.

    Examples
    --------
    >>> fig, ax = plt.subplots()
    >>> value_bars(ax, {"loose": 12.0, "tight": 7.5}, fmt="{:.1f}", printed={"tight": 8.0})
    >>> len(ax.patches), [t.get_text() for t in ax.texts]
    (2, ['12.0', '7.5'])
    >>> plt.close(fig)
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    labels = list(values)
    colours = colours or {}
    bar_colours = [colours.get(k, "tab:blue") for k in labels]
    width = 0.7
    ax.bar(range(len(labels)), [values[k] for k in labels], width=width, color=bar_colours)
    if log:
        ax.set_yscale("log")
    for i, k in enumerate(labels):
        ax.annotate(
            fmt.format(values[k]),
            (i, values[k]),
            ha="center",
            va="bottom",
            fontsize=8,
            xytext=(0, 2),
            textcoords="offset points",
        )
    handles: list[Any] = [Patch(color=c, label=t) for c, t in (legend or {"tab:blue": "this book"}).items()]
    if printed:
        xs = [i + width / 2 for i, k in enumerate(labels) if k in printed]
        ys = [printed[k] for k in labels if k in printed]
        ax.plot(xs, ys, "D", color="k", ms=6, ls="none", zorder=3)
        handles.append(Line2D([], [], marker="D", color="k", ls="none", ms=6, label=printed_label))
    ax.set_xticks(range(len(labels)), labels, rotation=20)
    ax.margins(y=0.12)
    ax.legend(handles=handles, loc="upper right", fontsize=8)


@dataclass(frozen=True)
class FigureSpec:
    """A registered figure.

    Attributes
    ----------
    id : str
        File stem and glue name, e.g. ``"SP-fig2.1"``.
    paper : str
        Paper key.
    reproduces : str
        The paper figure it reproduces (``"Fig. 2.1"``), or ``"new"`` for a figure the
        paper does not have (an end-to-end example, a Monte Carlo check).
    caption : str
        What it shows, which paper figure it reproduces and what was assumed.
    func : callable
        Returns the figure.

    Examples
    --------
    >>> s = spec("KZL-fig1")
    >>> s.paper, s.reproduces
    ('KZL', 'Fig. 1')
    """

    id: str
    paper: str
    reproduces: str
    caption: str
    func: Callable[[], Figure]


_REGISTRY: dict[str, FigureSpec] = {}


def register(
    fig_id: str, *, paper: str, reproduces: str, caption: str
) -> Callable[[Callable[[], Figure]], Callable[[], Figure]]:
    """Decorator registering a figure function under ``fig_id``.

    Parameters
    ----------
    fig_id : str
        File stem and glue name, starting with the paper key (``"SP-fig2.1"``); unique.
    paper : str
        Paper key, one of :data:`~navcore.claims.declarations.PAPERS`.
    reproduces : str
        The paper figure it reproduces (``"Fig. 2.1"``), or ``"new"``.
    caption : str
        What the figure shows, which paper figure it reproduces and what was assumed; not
        empty.

    Returns
    -------
    callable
        A decorator that records a :class:`FigureSpec` and returns the function unchanged;
        it raises ``ValueError`` if another function already has ``fig_id``.

    Raises
    ------
    ValueError
        If ``paper`` is unknown or ``caption`` is empty.

    Examples
    --------
    Above a figure function, ``@register("SP-fig2.1", paper="SP", reproduces="Fig. 2.1",
    caption=...)`` records it; the arguments are checked when the decorator is made:

    >>> register("XY-fig1", paper="XY", reproduces="new", caption="a figure")
    Traceback (most recent call last):
    ...
    ValueError: paper must be one of ['WF', 'SP', 'ATC10', 'KZL'], got 'XY'
    """
    if paper not in PAPERS:
        raise ValueError(f"paper must be one of {list(PAPERS)}, got {paper!r}")
    if not caption.strip():
        raise ValueError(f"caption must say what figure {fig_id!r} shows")

    def deco(func: Callable[[], Figure]) -> Callable[[], Figure]:
        if fig_id in _REGISTRY and _REGISTRY[fig_id].func.__qualname__ != func.__qualname__:
            raise ValueError(f"figure id {fig_id!r} is registered twice")
        _REGISTRY[fig_id] = FigureSpec(fig_id, paper, reproduces, caption, func)
        return func

    return deco


@cache
def _discover(paper: str | None = None) -> None:
    """Import the figure modules (of one paper, plus the shared ``diagrams`` module)."""
    for m in pkgutil.iter_modules(__path__):
        if m.name.startswith("_"):
            continue
        if paper is not None and m.name != "diagrams" and m.name.split("_", 1)[0].upper() != paper:
            continue
        importlib.import_module(f"{__name__}.{m.name}")


def registry() -> dict[str, FigureSpec]:
    """All registered figures, by id, in id order.

    Imports every figure module of the package first (nothing is drawn).

    Returns
    -------
    dict of str to FigureSpec
        Each figure's id to its :class:`FigureSpec`, sorted by id.

    Examples
    --------
    >>> figures = registry()
    >>> "KZL-fig1" in figures, all(fid == s.id for fid, s in figures.items())
    (True, True)
    """
    _discover()
    return dict(sorted(_REGISTRY.items()))


def spec(fig_id: str) -> FigureSpec:
    """The registered figure ``fig_id`` (imports only its paper's figure modules).

    Parameters
    ----------
    fig_id : str
        The figure's id (``"KZL-fig1"``).

    Returns
    -------
    FigureSpec
        Its registration (nothing is drawn).

    Raises
    ------
    ValueError
        If no figure has that id.

    Examples
    --------
    >>> spec("KZL-fig1").caption == registry()["KZL-fig1"].caption
    True
    """
    key = fig_id.split("-", 1)[0]
    if key in PAPERS:
        _discover(key)
        if fig_id in _REGISTRY:
            return _REGISTRY[fig_id]
    reg = registry()
    if fig_id not in reg:
        raise ValueError(f"fig_id {fig_id!r} is not registered; known: {sorted(reg)}")
    return reg[fig_id]


def render(fig_id: str) -> Figure:
    """Build the figure ``fig_id`` with the book's style.

    Applies :func:`apply_style`, calls the figure's function (which computes what it
    shows) and moves any legend that covers data (:func:`tidy_legends`).

    Parameters
    ----------
    fig_id : str
        The figure's id (``"KZL-fig1"``).

    Returns
    -------
    matplotlib.figure.Figure
        The figure; the caller closes it.

    Raises
    ------
    ValueError
        If no figure has that id.
    TypeError
        If the figure's function does not return a matplotlib figure.

    Examples
    --------
    >>> fig = render("KZL-fig1")  # a block diagram: quick to draw
    >>> type(fig).__name__
    'Figure'
    >>> plt.close(fig)
    """
    apply_style()
    fig = spec(fig_id).func()
    if not isinstance(fig, Figure):
        raise TypeError(f"figure function for {fig_id!r} must return a matplotlib Figure")
    tidy_legends(fig)
    return fig


_LEGEND_LOCS = (
    "upper right",
    "upper left",
    "lower left",
    "lower right",
    "center right",
    "center left",
    "upper center",
    "lower center",
)


def _covered(ax, legend) -> int:
    """How many of the axes' data points, bar tops and text labels the legend's box covers."""
    box = legend.get_window_extent().padded(2)
    count = 0
    for line in ax.get_lines():
        if not line.get_visible() or len(line.get_xydata()) == 0:
            continue
        path = line.get_transform().transform_path(line.get_path())
        count += int(path.intersects_bbox(box, filled=False))
    for patch in ax.patches:
        count += int(box.overlaps(patch.get_window_extent()))
    for text in ax.texts:
        count += int(box.overlaps(text.get_window_extent()))
    for coll in ax.collections:
        offsets = coll.get_offsets()
        if len(offsets):
            pts = coll.get_offset_transform().transform(offsets)
            inside = (
                (pts[:, 0] >= box.x0) & (pts[:, 0] <= box.x1) & (pts[:, 1] >= box.y0) & (pts[:, 1] <= box.y1)
            )
            count += int(inside.sum())
    return count


def tidy_legends(fig: Figure) -> None:
    """The book's one rule for legends: never over the data.

    A legend that covers data points, bars or value labels moves to the corner of its axes
    that covers none; if every corner covers some, it goes below the axes.
    """
    legends: list[tuple[Any, Any]] = [(ax, ax.get_legend()) for ax in fig.axes if ax.get_legend() is not None]
    if not legends:
        return
    fig.canvas.draw()
    for ax, legend in legends:
        if _covered(ax, legend) == 0:
            continue
        for loc in _LEGEND_LOCS:
            legend.set_loc(loc)
            legend.set_bbox_to_anchor(None)
            fig.canvas.draw()
            if _covered(ax, legend) == 0:
                break
        else:
            legend.set_loc("upper center")
            legend.set_bbox_to_anchor((0.5, -0.14), transform=ax.transAxes)


# ---------------------------------------------------------------------------------------
# the data a figure plots


@dataclass(frozen=True)
class Series:
    """One data series drawn on an axes, in the axes' data coordinates.

    Attributes
    ----------
    kind : str
        ``"line"`` (a line or markers, :meth:`~matplotlib.axes.Axes.plot`, ``axhline``),
        ``"points"`` (a scatter), ``"segments"`` (``vlines``, error bars, stems: the
        segments' end points in order, ``x[2 i]`` to ``x[2 i + 1]``), ``"bars"`` (bar
        centres and heights, a histogram's too), ``"patch"`` (a span or polygon: its
        vertices) or ``"image"`` (``y`` holds the image, ``x`` its extent).
    label : str
        The artist's label (matplotlib's ``_child<n>`` for an unlabelled one).
    x, y : numpy.ndarray
        Its coordinates as floats.
    """

    kind: str
    label: str
    x: np.ndarray
    y: np.ndarray


@dataclass(frozen=True)
class PlottedAxes:
    """What one axes of a figure shows: its labels, scales, data series and texts.

    Attributes
    ----------
    title, xlabel, ylabel : str
        The axes' title and axis labels.
    xscale, yscale : str
        ``"linear"``, ``"log"``, ...
    series : tuple of Series
        Every data series, lines first (in drawing order), then collections, bars, patches
        and images.
    texts : tuple of str
        The texts drawn on the axes (annotations, value labels, a diagram's boxes).
    """

    title: str
    xlabel: str
    ylabel: str
    xscale: str
    yscale: str
    series: tuple[Series, ...] = field(default_factory=tuple)
    texts: tuple[str, ...] = field(default_factory=tuple)

    def of_kind(self, kind: str) -> list[Series]:
        """The series of one kind (``"line"``, ``"bars"``, ...), in drawing order."""
        return [s for s in self.series if s.kind == kind]

    def get(self, label: str, kind: str | None = None) -> Series:
        """The one series with this label (and kind, if given).

        Raises
        ------
        KeyError
            If no series, or more than one, has the label; the message lists the labels.
        """
        found = [s for s in self.series if s.label == label and (kind is None or s.kind == kind)]
        if len(found) != 1:
            raise KeyError(
                f"{len(found)} series labelled {label!r}; labels: {sorted({s.label for s in self.series})}"
            )
        return found[0]


def _floats(values: Any) -> np.ndarray:
    return np.asarray(np.ma.filled(np.ma.asarray(values, dtype=float), np.nan), dtype=float)


def _axes_data(ax: Any) -> PlottedAxes:
    from matplotlib.collections import LineCollection, PathCollection
    from matplotlib.container import BarContainer
    from matplotlib.image import AxesImage
    from matplotlib.patches import Polygon, Rectangle

    series: list[Series] = []
    for line in ax.get_lines():
        x, y = line.get_data(orig=True)
        series.append(Series("line", str(line.get_label()), _floats(np.ravel(x)), _floats(np.ravel(y))))
    for coll in ax.collections:
        if isinstance(coll, LineCollection):
            ends = [np.asarray(seg, dtype=float)[[0, -1]] for seg in coll.get_segments() if len(seg)]
            pts = np.concatenate(ends) if ends else np.empty((0, 2))
            series.append(Series("segments", str(coll.get_label()), pts[:, 0], pts[:, 1]))
        elif isinstance(coll, PathCollection):
            offsets = _floats(coll.get_offsets()).reshape(-1, 2)
            series.append(Series("points", str(coll.get_label()), offsets[:, 0], offsets[:, 1]))
    in_containers: set[int] = set()
    for container in ax.containers:
        if isinstance(container, BarContainer):
            bars = list(container.patches)
            in_containers.update(id(b) for b in bars)
            x = _floats([b.get_x() + b.get_width() / 2 for b in bars])
            h = _floats([b.get_height() for b in bars])
            series.append(Series("bars", str(container.get_label()), x, h))
    for patch in ax.patches:
        if id(patch) in in_containers:
            continue
        if isinstance(patch, Rectangle):
            x0, y0 = patch.get_x(), patch.get_y()
            x1, y1 = x0 + patch.get_width(), y0 + patch.get_height()
            xy = _floats([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
        elif isinstance(patch, Polygon):
            xy = _floats(patch.get_xy())
        else:
            continue
        series.append(Series("patch", str(patch.get_label()), xy[:, 0], xy[:, 1]))
    for image in ax.get_images():
        if isinstance(image, AxesImage):
            series.append(
                Series(
                    "image", str(image.get_label()), _floats(image.get_extent()), _floats(image.get_array())
                )
            )
    return PlottedAxes(
        title=ax.get_title(),
        xlabel=ax.get_xlabel(),
        ylabel=ax.get_ylabel(),
        xscale=ax.get_xscale(),
        yscale=ax.get_yscale(),
        series=tuple(series),
        texts=tuple(t.get_text() for t in ax.texts),
    )


def plotted(fig: Figure) -> tuple[PlottedAxes, ...]:
    """The data a figure plots, axes by axes: what a test compares with the model.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        A rendered figure.

    Returns
    -------
    tuple of PlottedAxes
        One per axes of ``fig`` that is not a colour bar or a secondary axis, in the figure's
        order (``fig.axes``): its labels, scales, every data series (:class:`Series`) and its
        texts.

    Examples
    --------
    >>> fig, ax = plt.subplots()
    >>> _ = ax.plot([1.0, 2.0], [3.0, 4.0], label="model")
    >>> _ = ax.bar([0.0, 1.0], [5.0, 6.0], label="counts")
    >>> (axes,) = plotted(fig)
    >>> axes.get("model").y.tolist(), axes.get("counts").y.tolist()
    ([3.0, 4.0], [5.0, 6.0])
    >>> plt.close(fig)
    """
    out = []
    for ax in fig.axes:
        if ax.get_label() == "<colorbar>" or type(ax).__name__ == "SecondaryAxis":
            continue
        out.append(_axes_data(ax))
    return tuple(out)


def render_data(fig_id: str) -> tuple[PlottedAxes, ...]:
    """Render a registered figure and return the data it plots (:func:`plotted`); closes it.

    Parameters
    ----------
    fig_id : str
        The figure's id (``"SP-fig2.1"``).

    Returns
    -------
    tuple of PlottedAxes
        The figure's axes and their data series.

    Raises
    ------
    ValueError
        If no figure has that id.
    """
    fig = render(fig_id)
    try:
        return plotted(fig)
    finally:
        plt.close(fig)


def write(fig: Figure, stem: Path) -> list[Path]:
    """Save ``fig`` as ``stem.svg`` and ``stem.png`` with deterministic metadata.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure to save (left open).
    stem : pathlib.Path
        Folder and file name without suffix; a dot in the name is kept (``"ATC10-fig2.16"``).
        The folder is created if needed.

    Returns
    -------
    list of pathlib.Path
        The SVG and the PNG file written.

    Examples
    --------
    >>> import tempfile
    >>> fig, ax = plt.subplots()
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     print([p.name for p in write(fig, Path(tmp) / "ATC10-fig2.16")])
    ['ATC10-fig2.16.svg', 'ATC10-fig2.16.png']
    >>> plt.close(fig)
    """
    stem.parent.mkdir(parents=True, exist_ok=True)
    # ids such as "ATC10-fig2.16" contain dots: append the suffix, never replace one
    svg = stem.parent / f"{stem.name}.svg"
    png = stem.parent / f"{stem.name}.png"
    fig.savefig(svg, format="svg", metadata={"Date": None})
    fig.savefig(png, format="png", metadata={"Software": None})
    return [svg, png]


def write_all(out: Path | str = "figures", only: Iterable[str] | None = None) -> list[Path]:
    """Write every registered figure (or those in ``only``) to the folder ``out``.

    Each figure is rendered (:func:`render`), written (:func:`write`) and closed; writing
    every figure computes every figure's model, which takes minutes.

    Parameters
    ----------
    out : pathlib.Path or str, optional
        The folder (created if needed).
    only : iterable of str or None, optional
        The ids to write; ``None`` for every registered figure.

    Returns
    -------
    list of pathlib.Path
        The files written, an SVG and a PNG per figure, in the order of the ids.

    Raises
    ------
    ValueError
        If an id in ``only`` is not registered.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     print([p.name for p in write_all(tmp, only=["KZL-fig1"])])
    ['KZL-fig1.svg', 'KZL-fig1.png']
    """
    out = Path(out)
    ids = list(only) if only is not None else list(registry())
    written: list[Path] = []
    for fig_id in ids:
        fig = render(fig_id)
        written += write(fig, out / fig_id)
        plt.close(fig)
    return written
