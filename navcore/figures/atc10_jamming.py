"""ATC-10 Figs. 2.1-2.16 redrawn: lower bounds on false and ambiguous locations against J/(P0 B tau)."""

from __future__ import annotations

import functools
import math
from typing import Any

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from navcore.detection import jamming as jm
from navcore.figures import register
from navcore.papers import atc10_jamming as paper
from navcore.papers import atc10_tracking_lists as lists

#: Fraction t of the first-stage rule drawn in Figs. 2.3-2.16 (the paper's sets are lost).
T_VALUES = lists.T_GRID
K1_PDL = paper.K1_PDL_GRID
LOG10_FLOOR = -12.0

#: (figure number, quantity, K, P_DL) for Figs. 2.3-2.16, in the paper's order.
K_FIGURES = (
    (3, "false", 10, 0.88),
    (4, "ambiguous", 10, 0.88),
    (5, "false", 10, 0.999),
    (6, "ambiguous", 10, 0.999),
    (7, "false", 100, 0.88),
    (8, "ambiguous", 100, 0.88),
    (9, "false", 100, 0.999),
    (10, "ambiguous", 100, 0.999),
    (11, "false", 1000, 0.88),
    (12, "ambiguous", 1000, 0.88),
    (13, "ambiguous", 1000, 0.98),
    (14, "false", 1000, 0.98),
    (15, "false", 1000, 0.999),
    (16, "ambiguous", 1000, 0.999),
)

_NAME = {"false": r"$\bar N_{FL}/N_T$", "ambiguous": r"$\bar N_{ADL}/N_T$"}


def log10_bound(quantity: str, x_db: np.ndarray, p_dl: float, k: int, t: float) -> np.ndarray:
    """log10 of N_FL/N_T or N_ADL/N_T at the design point (P_DL, K, t), from the log-domain model."""
    p_d = paper.design_p_d(p_dl, k, t)
    fn = jm.log_false_location_bound if quantity == "false" else jm.log_ambiguous_detection_bound
    return np.asarray(fn(10.0 ** (x_db / 10.0), p_d, k, t, paper.geometry())) / math.log(10.0)


def _level(quantity: str) -> float:
    return paper.level(quantity)


def _axes_common(ax, quantity: str, x_lo: float, x_hi: float) -> None:
    ax.axhline(math.log10(_level(quantity)), color="0.3", lw=0.8, ls="--", label="level")
    ax.set_ylim(LOG10_FLOOR, 0.5)
    ax.set_xlim(x_lo, x_hi)
    ax.set_xlabel(r"$J/(P_0 B \tau)$ [dB]  (ERP = value + 50 dBW)")
    ax.set_ylabel(r"$\log_{10}$ " + _NAME[quantity])
    ax.legend(loc="lower right", fontsize=8)


def _k1_figure(quantity: str) -> Figure:
    fig, ax = plt.subplots()
    x = np.linspace(-25.0, -5.0, 401)
    for p_dl in K1_PDL:
        ax.plot(x, log10_bound(quantity, x, p_dl, 1, 0.0), label=rf"$P_{{DL}}$ = {p_dl}")
    _axes_common(ax, quantity, -25.0, -5.0)
    return fig


@register(
    "ATC10-fig2.1",
    paper="ATC10",
    reproduces="Fig. 2.1",
    caption="Lower bound on the mean number of falsely located aircraft, N_FL/N_T, for K = 1 against "
    "J/(P0 B tau), for P_DL = p_d^4 in {0.88, 0.9, 0.99, 0.999} (the paper names 0.9 and 0.999). "
    "Dashed: 99 % of the supremum 0.9 N_T used as the failure level.",
)
def false_locations_single_pulse() -> Figure:
    return _k1_figure("false")


@register(
    "ATC10-fig2.2",
    paper="ATC10",
    reproduces="Fig. 2.2",
    caption="Lower bound on the mean number of ambiguous detections, N_ADL/N_T, for K = 1 against "
    "J/(P0 B tau), for P_DL in {0.88, 0.9, 0.99, 0.999}. Dashed: the failure level 0.01 N_T.",
)
def ambiguous_detections_single_pulse() -> Figure:
    return _k1_figure("ambiguous")


#: The J/(P0 B tau) axis of Figs. 2.3-2.16 (dB), as the paper draws most of them.
X_AXIS_DB = (-20.0, 80.0)


def varying_range(x: np.ndarray, curves: list[np.ndarray], pad_db: float = 2.0) -> tuple[float, float]:
    """The part of the axis where some curve is above the plot's floor and still changing.

    Each curve rises from below ``LOG10_FLOOR`` to a plateau; the range runs from where the
    first curve comes into view to where the last one flattens (within 0.02 decades of its
    plateau), padded by ``pad_db`` and rounded out to 5 dB, within ``X_AXIS_DB``.
    """
    lo, hi = X_AXIS_DB[1], X_AXIS_DB[0]
    for y in curves:
        moving = (y > LOG10_FLOOR + 0.05) & (y < np.max(y) - 0.02)
        if np.any(moving):
            lo, hi = min(lo, float(x[moving].min())), max(hi, float(x[moving].max()))
    if lo > hi:
        return X_AXIS_DB
    lo = max(X_AXIS_DB[0], 5.0 * math.floor((lo - pad_db) / 5.0))
    hi = min(X_AXIS_DB[1], 5.0 * math.ceil((hi + pad_db) / 5.0))
    return lo, hi


def _k_figure(quantity: str, k: int, p_dl: float) -> Figure:
    fig, ax = plt.subplots()
    bounds = {t: lambda x, t=t: log10_bound(quantity, x, p_dl, k, t) for t in T_VALUES}
    x = np.linspace(*X_AXIS_DB, 501)
    x_lo, x_hi = varying_range(x, [bound(x) for bound in bounds.values()])
    # a figure whose curves all change within half the paper's axis is drawn on that part
    # only (Figs. 2.4 and 2.5 would otherwise squeeze everything into the first 20 dB)
    if x_hi - x_lo > 0.5 * (X_AXIS_DB[1] - X_AXIS_DB[0]):
        x_lo, x_hi = X_AXIS_DB
    x = np.linspace(x_lo, x_hi, 501)
    for t, bound in bounds.items():
        p_d = paper.design_p_d(p_dl, k, t)
        ax.plot(x, bound(x), label=rf"$t$ = {t:g}, $p_d$ = {p_d:.3f}")
    _axes_common(ax, quantity, x_lo, x_hi)
    ax.set_title(rf"$K$ = {k}, $P_{{DL}}$ = {p_dl}", fontsize=10)
    return fig


for _n, _q, _k, _p in K_FIGURES:
    # registered at import: the drawing itself is the module-level _k_figure, called when drawn
    _f: Any = functools.partial(_k_figure, _q, _k, _p)
    _f.__qualname__ = f"fig2_{_n}"
    _f.__name__ = f"fig2_{_n}"
    register(
        f"ATC10-fig2.{_n}",
        paper="ATC10",
        reproduces=f"Fig. 2.{_n}",
        caption=f"Lower bound {'N_FL' if _q == 'false' else 'N_ADL'}/N_T against J/(P0 B tau) "
        f"for K = {_k} and P_DL = {_p}, with t in {{0, 0.05, 0.1, 0.2, 0.3}} and p_d re-solved "
        "from Eq. (2.4.2) for each t (assumed: the paper's (p_d, t) sets are lost). Dashed: "
        + ("99 % of the supremum 0.9 N_T." if _q == "false" else "the failure level 0.01 N_T."),
    )(_f)


@register(
    "ATC10-mc-lists",
    paper="ATC10",
    reproduces="new",
    caption="Seeded Monte Carlo of the first stage at reduced size (200 filter-1 samples per segment, "
    "windows of 11 samples, 1000 trials, P_DL = 0.9): simulated false-alarm and detection rates of the "
    "K-list rule (markers, with 1-sigma bars) against the bounds F^(Kt+1) of (B.11) and P_DL of (2.4.2) "
    "(lines). Triangles: no event in 1000 trials (rate below about 1e-3).",
)
def list_rule_monte_carlo() -> Figure:
    from navcore.detection import jamming_monte_carlo as mc

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.0, 3.8))
    for i, r in enumerate(mc.simulate()):
        colour = f"C{i}"
        label = rf"$K$ = {r.k}, $t$ = {r.t:.2g}"
        hit = r.false_alarm > 0
        ax1.semilogy(mc.X_DB, r.false_alarm_bound, "-", color=colour, label=label + " bound")
        ax1.errorbar(
            mc.X_DB[hit],
            r.false_alarm[hit],
            yerr=mc.binomial_sigma(r.false_alarm[hit], r.trials),
            fmt="o",
            color=colour,
            ms=4,
            capsize=2,
        )
        ax1.plot(mc.X_DB[~hit], np.full((~hit).sum(), 1.0 / r.trials), "v", color=colour, ms=5, alpha=0.6)
        ax2.errorbar(
            mc.X_DB + 0.1 * (i - 1),
            r.detection,
            yerr=mc.binomial_sigma(r.detection, r.trials),
            fmt="o",
            color=colour,
            ms=4,
            capsize=2,
            label=label + " simulated",
        )
        ax2.axhline(r.detection_bound, color=colour, lw=1.0, ls="--")
    ax1.set_ylim(1e-6, 1.5)
    ax1.set_xlabel(r"$J/(P_0 B \tau)$ [dB]")
    ax1.set_ylabel("first-stage false-alarm probability")
    ax1.legend(fontsize=7, loc="lower right")
    ax2.set_ylim(0.85, 1.005)
    ax2.set_xlabel(r"$J/(P_0 B \tau)$ [dB]")
    ax2.set_ylabel(r"first-stage detection probability (dashed: $P_{DL}$)")
    ax2.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    return fig
