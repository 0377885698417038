"""What a reader sees of each registered figure beyond its data: the reviewed appearance.

:func:`appearance` lists, per axes, its title, axis labels, scales and limits, the style of
every line, collection and patch (colour, line style and width, marker, face colour, order),
every text (string, position, size, alignment, colour), the tick labels, the minor ticks and
the legend (entries, place, columns, size), and the figure's size. The data themselves are
checked against the model and the oracles in ``_figure_oracles.py``; this is the rest.

The oracle is the appearance reviewed when the figure was last changed on purpose, recorded
in ``figure_appearance.json``. A change in a figure's code that changes what a reader sees (a
colour, a dashed line drawn solid, a limit, a legend moved over the data, a label) fails the
comparison; after a deliberate change, ``NAVCORE_UPDATE_APPEARANCE=1`` rewrites the record of
the figures rendered, and the diff of the record is what a reviewer reads.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.colors import to_hex

RECORD = Path(__file__).with_name("figure_appearance.json")


def _num(x: Any) -> Any:
    """A float to 6 significant digits (limits and positions are computed: rounding keeps the
    record stable across platforms while any visible change shows)."""
    x = float(x)
    return float(f"{x:.6g}") if np.isfinite(x) else str(x)


def _colour(c: Any) -> Any:
    if isinstance(c, str):
        return to_hex(c, keep_alpha=True)
    arr = np.asarray(c, dtype=float)
    if arr.ndim == 2:
        return [to_hex(row, keep_alpha=True) for row in arr[:3]]
    return to_hex(arr, keep_alpha=True)


def _legend(legend: Any) -> dict[str, Any] | None:
    if legend is None:
        return None
    anchor = legend._bbox_to_anchor
    return {
        "entries": [t.get_text() for t in legend.get_texts()],
        "loc": legend._loc,
        "ncols": legend._ncols,
        "fontsize": _num(legend.prop.get_size()),
        "frame": legend.get_frame_on(),
        "title": legend.get_title().get_text(),
        "anchor": None if anchor is None else [_num(v) for v in anchor.bounds],
    }


def _axes(ax: Any) -> dict[str, Any]:
    lines = [
        {
            "label": str(line.get_label()),
            "colour": _colour(line.get_color()),
            "ls": str(line.get_linestyle()),
            "drawstyle": str(line.get_drawstyle()),
            "lw": _num(line.get_linewidth()),
            "marker": str(line.get_marker()),
            "ms": _num(line.get_markersize()),
            "mfc": _colour(line.get_markerfacecolor()),
            "alpha": line.get_alpha(),
            "zorder": _num(line.get_zorder()),
            "visible": line.get_visible(),
        }
        for line in ax.get_lines()
    ]
    collections = [
        {
            "label": str(coll.get_label()),
            "face": _colour(coll.get_facecolor()) if len(coll.get_facecolor()) else None,
            "edge": _colour(coll.get_edgecolor()) if len(coll.get_edgecolor()) else None,
            "lw": [_num(w) for w in np.ravel(coll.get_linewidth())[:3]],
            "ls": str(coll.get_linestyle()[:1]),
            "sizes": [_num(s) for s in np.ravel(coll.get_sizes())[:3]]
            if hasattr(coll, "get_sizes")
            else None,
            "alpha": coll.get_alpha(),
            "zorder": _num(coll.get_zorder()),
        }
        for coll in ax.collections
    ]
    patches = [
        {
            "label": str(p.get_label()),
            "face": _colour(p.get_facecolor()),
            "edge": _colour(p.get_edgecolor()),
            "lw": _num(p.get_linewidth()),
            "ls": str(p.get_linestyle()),
            "alpha": p.get_alpha(),
            "zorder": _num(p.get_zorder()),
        }
        for p in ax.patches
    ]
    texts = [
        {
            "text": t.get_text(),
            "at": [_num(v) for v in t.get_position()],
            "size": _num(t.get_fontsize()),
            "ha": t.get_ha(),
            "va": t.get_va(),
            "colour": _colour(t.get_color()),
            "rotation": _num(t.get_rotation()),
        }
        for t in ax.texts
    ]
    return {
        "title": ax.get_title(),
        "title_size": _num(ax.title.get_fontsize()),
        "xlabel": ax.get_xlabel(),
        "ylabel": ax.get_ylabel(),
        "scales": [ax.get_xscale(), ax.get_yscale()],
        "limits": [_num(v) for v in (*ax.get_xlim(), *ax.get_ylim())],
        "axis": ax.axison,
        "aspect": str(ax.get_aspect()),
        "xticklabels": [t.get_text() for t in ax.get_xticklabels()],
        "yticklabels": [t.get_text() for t in ax.get_yticklabels()],
        "minor_ticks": [
            [_num(v) for v in ax.xaxis.get_minorticklocs()],
            [_num(v) for v in ax.yaxis.get_minorticklocs()],
        ],
        "lines": lines,
        "collections": collections,
        "patches": patches,
        "texts": texts,
        "legend": _legend(ax.get_legend()),
        "secondary": [
            [child.get_xlabel(), child.get_ylabel(), [t.get_text() for t in child.get_xticklabels()]]
            for child in ax.child_axes
        ],
    }


def appearance(fig: Any) -> dict[str, Any]:
    """The appearance of a rendered figure, as JSON-able lists and numbers."""
    fig.canvas.draw()
    return {
        "size": [_num(v) for v in fig.get_size_inches()],
        "suptitle": fig._suptitle.get_text() if fig._suptitle is not None else "",
        "axes": [_axes(ax) for ax in fig.axes],
    }


def check_appearance(fig_id: str, fig: Any) -> None:
    """Compare a rendered figure with its recorded appearance (or record it when asked)."""
    seen = json.loads(json.dumps(appearance(fig)))
    record = json.loads(RECORD.read_text()) if RECORD.exists() else {}
    if os.environ.get("NAVCORE_UPDATE_APPEARANCE") == "1":
        record[fig_id] = seen
        RECORD.write_text(json.dumps(dict(sorted(record.items())), indent=1, ensure_ascii=False) + "\n")
        return
    assert fig_id in record, f"{fig_id}: no recorded appearance (NAVCORE_UPDATE_APPEARANCE=1 records it)"
    expected = record[fig_id]
    for key in ("size", "suptitle"):
        assert seen[key] == expected[key], (fig_id, key, seen[key], expected[key])
    assert len(seen["axes"]) == len(expected["axes"]), fig_id
    for i, (a, b) in enumerate(zip(seen["axes"], expected["axes"], strict=True)):
        for key in b:
            assert a[key] == b[key], (fig_id, f"axes {i}", key, a[key], b[key])
