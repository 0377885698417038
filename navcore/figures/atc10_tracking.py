"""Figures of ATC-10 Section 4 (clock tracking and three-satellite coasting)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from navcore.figures import register
from navcore.location.clock_tracking import psi, psi_large_alpha, psi_small_alpha
from navcore.papers import atc10_clock_tracking as clock
from navcore.papers import atc10_tracking_examples as examples
from navcore.papers import atc10_tracking_geometry as m

#: Epochs with all satellites shown in Figs. 4.2-4.3 (the paper's N is not stated).
N_SHOWN = 40
M_SHOWN = 60


@register(
    "ATC10-fig4.1",
    paper="ATC10",
    reproduces="Fig. 4.1",
    caption="psi(alpha), the steady-state reduction factor of the clock-error term (Eq. 4.5.34, real "
    "cube roots), with the small-alpha approximation 1.89[alpha^(1/3) - (alpha/2)^(2/3)] and the "
    "large-alpha approximation 1 - 4/(27 alpha). Markers: the six cases of Table 4.3.",
)
def psi_function() -> Figure:
    a = np.logspace(-6, 2, 400)
    fig, ax = plt.subplots()
    ax.semilogx(a, psi(a), "k-", label="ψ(α), Eq. (4.5.34)")
    small = a <= 1.0
    ax.semilogx(a[small], psi_small_alpha(a[small]), "C0--", label="1.89[α^(1/3) − (α/2)^(2/3)] (α ≤ 0.3)")
    large = a >= 0.2
    ax.semilogx(a[large], psi_large_alpha(a[large]), "C3:", label="1 − 4/(27α) (α ≥ 1)")
    ax.axvspan(0.3, 1.0, color="0.9", zorder=0)
    for ex, mk in (("I", "o"), ("II", "s")):
        b = float(m.TABLE_4_2[ex]["beta"])
        al = np.array([8 / 27 * s0**2 * b / m.IN.sigma_ns**2 for s0 in clock.sigma0_values()])
        ax.plot(al, psi(al), mk, color="C2", mfc="none", label=f"Table 4.3, Example {ex}")
    ax.set_ylim(0, 1.05)
    ax.set_xlabel("α = (8/27) σ₀² β / σ²")
    ax.set_ylabel("ψ(α) = γβ")
    ax.legend(loc="upper left", fontsize=8)
    return fig


def _rms_figure(example: str) -> Figure:
    printed_inputs = m.printed_table_4_2(example)
    corrected = dict(printed_inputs)
    corrected["s_123"] = m.table_4_2_from_geometry(example, m.fitted_radius_ratio())["s_123"]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for s0, c in zip(clock.sigma0_values(), ("C0", "C1", "C3"), strict=True):
        n, rms_p = examples.rms_history_ft(printed_inputs, s0, N_SHOWN, M_SHOWN)
        _, rms_c = examples.rms_history_ft(corrected, s0, N_SHOWN, M_SHOWN)
        ax.plot(n[: N_SHOWN + 1], rms_p[: N_SHOWN + 1], "-", color=c, label=f"σ₀ = {s0:g} ns")
        ax.plot(n[N_SHOWN:], rms_p[N_SHOWN:], "--", color=c)
        ax.plot(n[N_SHOWN:], rms_c[N_SHOWN:], "-", color=c, lw=2.4, alpha=0.55)
    ax.axvline(N_SHOWN, color="0.5", lw=0.8)
    ax.plot([], [], "k--", label="3 satellites, printed Eq. (4.5.30)")
    ax.plot([], [], "k-", lw=2.4, alpha=0.55, label="3 satellites, corrected 1'(FF')⁻¹1")
    ax.set_yscale("log")
    ax.set_xlabel(f"epoch n (τ̄ = 1 s); all satellites up to N = {N_SHOWN}")
    ax.set_ylabel("rms position error (ft)")
    ax.legend(fontsize=8, loc="upper left")
    return fig


@register(
    "ATC10-fig4.2",
    paper="ATC10",
    reproduces="Fig. 4.2",
    caption="rms position error against n for Example I (printed Table 4.2, sigma = 50 ns, c = 1 ft/ns): "
    "least squares at n = 0, optimal clock tracking to the limit, then satellites 1, 2, 3 only from "
    "n = N + 1 (N = 40 assumed; the paper does not state N). Dashed: the printed three-satellite "
    "formula; thick: the rotation-invariant clock term (erratum "
    "ATC10-E4.1-three-satellite-clock-term).",
)
def rms_example_i() -> Figure:
    return _rms_figure("I")


@register(
    "ATC10-fig4.3",
    paper="ATC10",
    reproduces="Fig. 4.3",
    caption="As Fig. 4.2 for Example II. The printed formula overstates the three-satellite error by a "
    "factor 2.5 to 3.5 in rms.",
)
def rms_example_ii() -> Figure:
    return _rms_figure("II")


@register(
    "ATC10-mc-tracker",
    paper="ATC10",
    reproduces="new",
    caption="Seeded Monte Carlo of the whole tracker (10 000 runs, fitted geometry, N = 150 epochs with "
    "all satellites, clock = random walk + random frequency offset) against the recursion's "
    "prediction and the printed three-satellite formula, Example II.",
)
def tracker_monte_carlo() -> Figure:
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ex = "II"
    geo = m.table_4_2_from_geometry(ex, m.fitted_radius_ratio())
    printed_geo = dict(geo)
    printed_geo["s_123"] = geo["s_123_printed"]
    for s0, c in zip((5.0, 50.0), ("C0", "C1"), strict=True):
        mc = clock.tracker_monte_carlo(ex, s0)
        n, pred = examples.rms_history_ft(geo, s0, clock.MC_N_LAST, 1)
        _, pred_p = examples.rms_history_ft(printed_geo, s0, clock.MC_N_LAST, 1)
        sel = np.r_[0:12:1, 12 : clock.MC_N_LAST + 2 : 6, clock.MC_N_LAST + 1]
        ax.plot(n, pred, "-", color=c, label=f"recursion, σ₀ = {s0:g} ns")
        ax.plot(n[sel], np.sqrt(mc.position_mse[sel]), "o", color=c, ms=3.5, mfc="none", label="Monte Carlo")
        ax.plot(n[-1], pred_p[-1], "x", color=c, ms=9, mew=2, label="printed Eq. (4.5.30) at N + 1")
    ax.set_yscale("log")
    ax.set_xlabel("epoch n (drop to three satellites after N = 150)")
    ax.set_ylabel("rms position error (ft)")
    ax.legend(fontsize=8, ncol=2)
    return fig
