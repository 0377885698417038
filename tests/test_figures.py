"""Every registered figure renders, has labelled axes, plots the right data, and is written
deterministically. The data checks (and their oracles) are in ``_figure_oracles.py``."""

from __future__ import annotations

import hashlib

import matplotlib.pyplot as plt
import pytest
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
