"""Figures of ATC-10 Section 3 (multiple-access noise), redrawn from navcore computations."""

from __future__ import annotations

from functools import cache

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import LogLocator, NullLocator

from navcore.detection.multiple_access import (
    MultipleAccessNoise,
    UniformDensity,
    edgeworth_density,
    sample_noise,
)
from navcore.detection.roc_bounds import (
    exponent_from_gaussian_exponent,
    gaussian_roc,
    roc_lower_bound,
    roc_upper_bound,
)
from navcore.detection.zakai import (
    alternating_sidelobe_autocorrelation,
    aperiodic_autocorrelation,
    barker_code,
    m_sequence,
)
from navcore.figures import register
from navcore.papers import atc10_gaussian_comparison as gaussian
from navcore.papers import atc10_multiple_access as m
from navcore.papers import atc10_roc_bounds as roc

ROC_THETAS = np.linspace(0.04, 0.96, 47)
COLORS = {3.0: "C0", 4.0: "C1", 5.0: "C2", 6.0: "C3", 8.0: "C4"}


@cache
def _bounds(name: str, x: float) -> tuple[np.ndarray, ...]:
    noise = m.noise_sec36(name, x)
    ub_f, ub_m = roc_upper_bound(noise, ROC_THETAS)
    lb_f, lb_m = roc_lower_bound(noise, ROC_THETAS)
    return ub_f, ub_m, lb_f, lb_m


def _roc_axes(ax) -> None:
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(1e-6, 1)
    ax.set_ylim(1e-12, 1)
    ax.set_xlabel("miss probability 1 - $p_d$")
    ax.set_ylabel("false-alarm probability $p_f$")


@register(
    "ATC10-fig3.2",
    paper="ATC10",
    reproduces="Fig. 3.2",
    caption="The four amplitude densities of equal second moment b (drawn in units of sqrt(b)). The "
    "paper's figure is lost; C2 is its two-point optimum (Eq. 3.7.1), C1, C3, C4 are the book's choices.",
)
def amplitude_densities() -> Figure:
    fig, ax = plt.subplots()
    u = np.linspace(-3.2, 3.2, 801)
    h = np.sqrt(3.0)
    ax.plot(u, np.where(np.abs(u) <= h, 1 / (2 * h), 0.0), label="C1 uniform")
    ax.vlines([-1, 1], 0, 0.5, color="C1", lw=3, label="C2 two-point (masses 1/2)")
    t = np.sqrt(6.0)
    ax.plot(u, np.clip((t - np.abs(u)) / t**2, 0, None), color="C2", label="C3 triangular")
    ax.plot(u, np.exp(-0.5 * u**2) / np.sqrt(2 * np.pi), color="C3", label="C4 Gaussian")
    ax.set_xlabel("amplitude x / √b")
    ax.set_ylabel("density × √b  (masses for C2)")
    ax.legend(fontsize=8)
    return fig


def _column_limit(x: float) -> float:
    """Lower axis limit for contour x: the decade below the smallest upper-bound or actual value."""
    lo = 1.0
    for name in m.DENSITY_NAMES:
        ub_f, ub_m, _, _ = _bounds(name, x)
        r = gaussian.exact_roc(name, x)
        keep = (r.p_f > 0) & (r.p_miss > 0)
        lo = min(lo, float(np.exp(ub_m.min())), float(np.exp(ub_f.min())))
        lo = min(lo, float(r.p_miss[keep].min()), float(r.p_f[keep].min()))
    return 10.0 ** np.floor(np.log10(lo))


@register(
    "ATC10-fig3.3-3.6",
    paper="ATC10",
    reproduces="Figs. 3.3-3.6",
    caption="Bounds to the ROC at N = 1e5, tau/alpha = 2e-5, one row per amplitude density (the "
    "paper's Figs. 3.3 to 3.6) and one column per contour 1/sqrt(3b): upper bound (3.5.13, solid), "
    "actual ROC (dotted; computed exactly) and ROC_g of equal power (Eq. 3.8.3, "
    "thick grey). Each column has its own range, shared down the column; the ROCs are symmetric, so "
    "both axes of a panel cover the same decades. The corrected lower bound (3.5.14) lies below the "
    "range of every panel and is not drawn.",
)
def bounds_grid() -> Figure:
    xs = roc.contours()
    fig, axes = plt.subplots(
        len(m.DENSITY_NAMES), len(xs), figsize=(7.6, 6.4), sharex="col", sharey="col", squeeze=False
    )
    th = np.linspace(0.005, 0.995, 199)
    for j, x in enumerate(xs):
        lim = _column_limit(x)
        lpf_g, lmiss_g = gaussian_roc(th, m.IN.n_sec36 * 2 * m.IN.tau_over_alpha_sec36 * m.b_of_contour(x))
        for i, name in enumerate(m.DENSITY_NAMES):
            ax = axes[i, j]
            ax.plot(np.exp(lmiss_g), np.exp(lpf_g), color="k", lw=2.5, alpha=0.25)
            ub_f, ub_m, _, _ = _bounds(name, x)
            ax.plot(np.exp(ub_m), np.exp(ub_f), "-", color="C0", lw=1.2)
            r = gaussian.exact_roc(name, x)
            keep = (r.p_f > 0) & (r.p_miss > 0)
            ax.plot(r.p_miss[keep], r.p_f[keep], ":", color="k", lw=1.3)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlim(lim, 1)
            ax.set_ylim(lim, 1)
            ax.set_aspect("equal", adjustable="box")
            ax.tick_params(labelsize=7.5, pad=1.5)
            for axis in (ax.xaxis, ax.yaxis):
                axis.set_major_locator(LogLocator(base=10, numticks=4))
                axis.set_minor_locator(NullLocator())
            if i == 0:
                ax.set_title(f"1/√(3b) = {x:g}", fontsize=9.5)
            if j == 0:
                ax.set_ylabel(f"Fig. 3.{3 + i}: {name}\n$p_f$", fontsize=9)
            if i == len(m.DENSITY_NAMES) - 1:
                ax.set_xlabel("$1 - p_d$", fontsize=9)
    handles = [
        Line2D([], [], color="C0", lw=1.2, ls="-", label="upper bound (3.5.13)"),
        Line2D([], [], color="k", lw=1.3, ls=":", label="actual ROC"),
        Line2D([], [], color="k", lw=2.5, alpha=0.25, label="ROC$_g$, Gaussian of equal power"),
    ]
    fig.legend(handles=handles, loc="upper center", ncol=3, fontsize=9, bbox_to_anchor=(0.5, 1.0))
    fig.subplots_adjust(left=0.1, right=0.99, bottom=0.07, top=0.93, wspace=0.5, hspace=0.12)
    return fig


@register(
    "ATC10-fig3.7",
    paper="ATC10",
    reproduces="Fig. 3.7",
    caption="One multiple-access noise component n_ij at successive samples under the optimal "
    "density: zero unless interferer j overlaps, then +a or -a (a realisation with q exaggerated to 0.2).",
)
def two_valued_component() -> Figure:
    rng = np.random.default_rng(3)
    k = np.arange(60)
    on = rng.random(60) < 0.2
    val = np.where(on, rng.choice([-1.0, 1.0], 60), 0.0)
    fig, ax = plt.subplots(figsize=(6.4, 2.6))
    ax.stem(k, val, basefmt="k-")
    ax.set_yticks([-1, 0, 1], ["-a", "0", "+a"])
    ax.set_xlabel("sample index")
    ax.set_ylabel("$n_{ij}$")
    return fig


@register(
    "ATC10-fig3.8",
    paper="ATC10",
    reproduces="Fig. 3.8",
    caption="ROC_g (Eq. 3.8.3): Gaussian noise of power N (2 tau/alpha) b, N = 1e5, tau/alpha = 2e-5, "
    "for the same contours 1/sqrt(3b) as Figs. 3.3-3.6.",
)
def gaussian_rocs() -> Figure:
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    th = np.linspace(0.01, 0.99, 197)
    for x in roc.contours():
        p = m.IN.n_sec36 * 2 * m.IN.tau_over_alpha_sec36 * m.b_of_contour(x)
        lpf, lmiss = gaussian_roc(th, p)
        ax.plot(np.exp(lmiss), np.exp(lpf), color=COLORS[x], label=f"1/√(3b) = {x:g}")
    _roc_axes(ax)
    ax.legend(fontsize=8)
    return fig


@register(
    "ATC10-fig3.9",
    paper="ATC10",
    reproduces="Fig. 3.9",
    caption="Exp against N for Exp_g = 4 (Eq. 3.8.16), for tau/alpha = 1e-6, 1e-5, 1e-4 (the printed "
    "values are not legible in the source).",
)
def exp_vs_n() -> Figure:
    fig, ax = plt.subplots()
    n = np.logspace(2, 9, 300)
    for r in (1e-6, 1e-5, 1e-4):
        ax.semilogx(n, exponent_from_gaussian_exponent(n, r, m.IN.exp_g_fig39), label=f"τ/α = {r:g}")
    ax.axhline(m.IN.exp_g_fig39, color="k", lw=0.8, ls="--", label="Exp_g")
    ax.axvline(1e5, color="0.5", lw=0.8, ls=":")
    ax.set_xlabel("number of aircraft N")
    ax.set_ylabel("Exp")
    ax.legend(fontsize=8)
    return fig


@register(
    "ATC10-fig3.10",
    paper="ATC10",
    reproduces="Fig. 3.10",
    caption="Exp against Exp_g for tau/alpha = 1e-5 (Eq. 3.8.16) and several N; the marker is the "
    "worked example (N = 2e5, Exp_g = 12.5).",
)
def exp_vs_expg() -> Figure:
    fig, ax = plt.subplots()
    g = np.linspace(0.01, 20, 200)
    for n in (1e4, 1e5, 2e5, 1e6, 1e7):
        ax.plot(g, exponent_from_gaussian_exponent(n, m.IN.tau_over_alpha_fig310, g), label=f"N = {n:g}")
    ax.plot(g, g, "k--", lw=0.8, label="Exp = Exp_g")
    ax.plot([m.worked_example_exp_g()], [gaussian.worked_example_exp()], "ko")
    ax.set_xlabel("Exp_g")
    ax.set_ylabel("Exp")
    ax.legend(fontsize=8)
    return fig


@register(
    "ATC10-fig3.11",
    paper="ATC10",
    reproduces="Fig. 3.11",
    caption="Autocorrelations of PSK sequences: the idealised 'good' autocorrelation (sidelobes "
    "alternating at +-tau_c/tau, L = 13) that reproduces the printed W, the Barker-13 code and a "
    "31-chip m-sequence (aperiodic).",
)
def psk_autocorrelations() -> Figure:
    fig, ax = plt.subplots()
    ideal = alternating_sidelobe_autocorrelation(13, 14)
    ax.plot(np.arange(-14, 15), ideal, "-", label="idealised, L = 13")
    rb = aperiodic_autocorrelation(barker_code(13))
    ax.plot(np.arange(-12, 13), rb, "-", label="Barker 13")
    rm = aperiodic_autocorrelation(m_sequence(5))
    ax.plot(np.arange(-30, 31), rm, "-", lw=1, label="m-sequence 31")
    ax.set_xlabel("lag t / τ_c")
    ax.set_ylabel("R(t)")
    ax.legend(fontsize=8)
    return fig


@register(
    "ATC10-ma-tails",
    paper="ATC10",
    reproduces="new",
    caption="Density of the multiple-access noise for the uniform C at N = 1e5, tau/alpha = 2e-5 "
    "(1/sqrt(3b) = 5): seeded Monte Carlo (10^6 samples) against Theorem 3.1's Gaussian limit and the "
    "Edgeworth expansion (E.15) with the lambda_4 term.",
)
def noise_tails() -> Figure:
    b = m.b_of_contour(5.0)
    noise = MultipleAccessNoise(m.IN.n_sec36, m.IN.tau_over_alpha_sec36, UniformDensity(b))
    x = sample_noise(noise, 1_000_000, np.random.default_rng(8))
    sig = np.sqrt(noise.power)
    edges = np.linspace(-6 * sig, 6 * sig, 121)
    h, _ = np.histogram(x, edges, density=True)
    c = 0.5 * (edges[1:] + edges[:-1])
    fig, ax = plt.subplots()
    ax.semilogy(c / sig, h * sig, "k.", ms=3, label="Monte Carlo")
    ax.semilogy(c / sig, edgeworth_density(noise, c, terms=0, use_n=False) * sig, label="Gaussian limit")
    ed = edgeworth_density(noise, c, terms=2, use_n=False) * sig
    ax.semilogy(c[ed > 0] / sig, ed[ed > 0], label="Edgeworth (λ4 term)")
    ax.set_ylim(1e-7, 1)
    ax.set_xlabel("n / σ")
    ax.set_ylabel("density × σ")
    ax.legend(fontsize=8)
    return fig


@register(
    "ATC10-ma-actual-vs-gaussian",
    paper="ATC10",
    reproduces="new",
    caption="Actual ROCs (computed exactly, N = 1e5, tau/alpha = 2e-5) against "
    "ROC_g of equal power, at 1/sqrt(3b) = 3, 5 and 8, and the simulated 32-chip PSK signatures "
    "(1/sqrt(3b) about 7.9) with their Chernoff upper bound.",
)
def actual_vs_gaussian() -> Figure:
    fig, axes = plt.subplots(1, 2, figsize=(9.6, 4.2))
    ax = axes[0]
    th = gaussian.THETA_GRID
    styles = dict(zip(m.DENSITY_NAMES, ("-", "--", "-.", ":"), strict=True))
    for x in (3.0, 5.0, 8.0):
        p = m.IN.n_sec36 * 2 * m.IN.tau_over_alpha_sec36 * m.b_of_contour(x)
        lpf, lmiss = gaussian_roc(th, p)
        ax.plot(np.exp(lmiss), np.exp(lpf), color="k", lw=2.5, alpha=0.35)
        for name in m.DENSITY_NAMES:
            r = gaussian.exact_roc(name, x)
            keep = (r.p_f > 0) & (r.p_miss > 0)
            ax.plot(r.p_miss[keep], r.p_f[keep], styles[name], color=COLORS[x], lw=1)
    _roc_axes(ax)
    ax.set_ylim(1e-10, 1)
    for name in m.DENSITY_NAMES:
        ax.plot([], [], styles[name], color="0.3", label=name)
    ax.plot([], [], color="k", lw=2.5, alpha=0.35, label="ROC_g")
    ax.legend(fontsize=7, loc="lower left")
    ax.set_title("contours 3 (blue), 5 (green), 8 (purple)", fontsize=9)
    ax = axes[1]
    r = gaussian.psk_roc()
    keep = (r.p_f > 0) & (r.p_miss > 0)
    ax.plot(r.p_miss[keep], r.p_f[keep], "C0-", label="PSK, Monte Carlo")
    lpf, lmiss = m.psk_chernoff()
    ax.plot(np.exp(lmiss), np.exp(lpf), "C0o--", ms=4, label="Chernoff upper bound")
    lpf, lmiss = gaussian_roc(
        th, m.IN.n_sec36 * 2 * m.IN.tau_over_alpha_sec36 / (3 * gaussian.psk_contour() ** 2)
    )
    ax.plot(np.exp(lmiss), np.exp(lpf), "k-", lw=2.5, alpha=0.35, label="ROC_g, same power")
    _roc_axes(ax)
    ax.set_ylim(1e-10, 1)
    ax.legend(fontsize=7, loc="lower left")
    ax.set_title("32-chip random PSK signatures", fontsize=9)
    return fig
