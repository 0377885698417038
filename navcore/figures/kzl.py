"""KZL figures: Figs. 4 and 5 redrawn from the seeded Monte Carlo, and the stand-alone budget."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib import ticker
from matplotlib.figure import Figure

from navcore.figures import register
from navcore.papers.kzl_scenario import N_RUNS, VISIBILITY_SCHEDULE, monte_carlo
from navcore.units import DEG

CONFIGS = (
    ("ins", "stand-alone IMU (initialised)", "tab:gray", "-"),
    ("tc", "tightly coupled", "black", "--"),
    ("tc_att", "TC + multi-antenna attitude", "tab:blue", ":"),
    ("tc_dd", "TC + DD carrier phase", "tab:red", "-"),
)


def _shade_satellites(ax, t_end: float = 180.0) -> None:
    starts = [s for s, _ in VISIBILITY_SCHEDULE] + [t_end]
    for (s, n), e in zip(VISIBILITY_SCHEDULE, starts[1:], strict=True):
        if n < 4:
            ax.axvspan(s, e, color="tab:orange", alpha=0.12 if n == 3 else 0.22, lw=0)


def _plain_log_ticks(ax) -> None:
    """Log axis labelled at 1, 2 and 5 per decade in plain decimals (0.05, 0.1, 0.2, ...), no
    minor labels: matplotlib's default crowds a short log axis with 2×10⁻¹, 3×10⁻¹, ..."""
    ax.yaxis.set_major_locator(ticker.LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
    ax.yaxis.set_major_formatter(ticker.FuncFormatter(lambda v, _pos: f"{v:g}"))
    ax.yaxis.set_minor_locator(ticker.LogLocator(base=10.0, subs=[float(k) for k in range(2, 10)]))
    ax.yaxis.set_minor_formatter(ticker.NullFormatter())


def _sat_strip(ax) -> None:
    r = monte_carlo("tc")
    ax.step(r.t, r.n_visible, where="post", color="tab:orange")
    ax.set_ylabel("satellites")
    ax.set_ylim(0, 9)
    ax.set_xlabel("time (s)")


@register(
    "KZL-fig4",
    paper="KZL",
    reproduces="Fig. 4",
    caption=f"Roll, pitch and heading errors (RMS over {N_RUNS} seeded runs, solid/dashed/dotted by "
    "configuration; thin lines: the filter's 1-sigma) of the stand-alone initialised IMU and the three "
    "tightly coupled filters in the Table 1 flight. Satellite schedule 8-4-3-2-5 assumed (shaded: fewer "
    "than 4); noises assumed (3 m code, 5 cm/s delta range, 3 mm phase, 0.17 deg Euler attitude). "
    "Dash-dotted green line: the 0.5 deg pointing requirement of Sec. 1.",
)
def attitude_errors() -> Figure:
    fig, axes = plt.subplots(4, 1, figsize=(7.0, 8.5), sharex=True, height_ratios=[3, 3, 3, 1])
    names = ("roll", "pitch", "heading")
    for mode, label, color, ls in CONFIGS:
        r = monte_carlo(mode)
        rms = r.rms("att_err") / DEG
        for i, ax in enumerate(axes[:3]):
            ax.semilogy(r.t[1:], rms[1:, i], color=color, ls=ls, label=label)
            ax.semilogy(r.t[1:], r.att_sigma[1:, i] / DEG, color=color, lw=0.7, alpha=0.7)
    for i, ax in enumerate(axes[:3]):
        ax.set_ylabel(f"{names[i]} error (deg)")
        _plain_log_ticks(ax)
        _shade_satellites(ax)
        ax.axhline(0.5, color="green", lw=0.8, ls="-.")
    # above the top panel: inside it, the legend covered the stand-alone curve and the requirement line
    axes[0].legend(fontsize=8, ncol=2, loc="lower center", bbox_to_anchor=(0.5, 1.02), frameon=False)
    _sat_strip(axes[3])
    fig.tight_layout()
    return fig


@register(
    "KZL-fig5",
    paper="KZL",
    reproduces="Fig. 5",
    caption=f"Horizontal position, horizontal velocity and total attitude errors (RMS over {N_RUNS} "
    "seeded runs; thin lines: filter 1-sigma) of the three tightly coupled filters. The stand-alone "
    "IMU is left out, as in the paper (about 1 km and 15 m/s per axis after 3 min). Same assumptions "
    "as Fig. 4.",
)
def navigation_errors() -> Figure:
    fig, axes = plt.subplots(4, 1, figsize=(7.0, 8.5), sharex=True, height_ratios=[3, 3, 3, 1])
    for mode, label, color, ls in CONFIGS[1:]:
        r = monte_carlo(mode)
        axes[0].semilogy(r.t[1:], r.horizontal_rms("pos_err")[1:], color=color, ls=ls, label=label)
        axes[0].semilogy(r.t[1:], np.hypot(*r.pos_sigma[1:, :2].T), color=color, lw=0.7, alpha=0.7)
        axes[1].semilogy(r.t[1:], r.horizontal_rms("vel_err")[1:], color=color, ls=ls)
        axes[1].semilogy(r.t[1:], np.hypot(*r.vel_sigma[1:, :2].T), color=color, lw=0.7, alpha=0.7)
        att = np.sqrt(np.mean(np.sum(r.att_err**2, axis=-1), axis=0)) / DEG
        axes[2].semilogy(r.t[1:], att[1:], color=color, ls=ls)
        axes[2].semilogy(
            r.t[1:], np.linalg.norm(r.att_sigma[1:], axis=-1) / DEG, color=color, lw=0.7, alpha=0.7
        )
    axes[0].set_ylabel("horizontal position (m)")
    axes[1].set_ylabel("horizontal velocity (m/s)")
    axes[2].set_ylabel("attitude, RSS of 3 angles (deg)")
    for ax in axes[:3]:
        _plain_log_ticks(ax)
        _shade_satellites(ax)
    axes[0].legend(fontsize=8, ncol=3, loc="lower center", bbox_to_anchor=(0.5, 1.02), frameon=False)
    _sat_strip(axes[3])
    fig.tight_layout()
    return fig


@register(
    "KZL-standalone",
    paper="KZL",
    reproduces="new",
    caption=f"Stand-alone IMU heading error (RMS over {N_RUNS} runs) with and without initialisation, "
    "against the closed-form 1-sigma sqrt((b t)^2 + N^2 t + sigma0^2) with the Table 1 gyro bias "
    "(uncalibrated) or the 300 s calibration residual N/sqrt(300 s). The paper's 3 deg and 20 deg "
    "statements are marked.",
)
def standalone_heading() -> Figure:
    from navcore.papers.kzl_simulation import heading_closed_form_deg

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for init, color, label in ((True, "tab:blue", "initialised"), (False, "tab:red", "no initialisation")):
        r = monte_carlo("ins", init)
        ax.plot(r.t, r.rms("att_err")[:, 2] / DEG, color=color, label=f"Monte Carlo, {label}")
        cf = [heading_closed_form_deg(t, calibrated=init) for t in r.t]
        ax.plot(r.t, cf, color=color, ls="--", lw=1.0, label=f"closed form, {label}")
    ax.axhline(20, color="k", lw=0.8, ls=":")
    ax.axhline(3, color="k", lw=0.8, ls=":")
    ax.text(2, 20.4, "paper: > 20 deg", fontsize=8)
    ax.text(2, 3.4, "paper: < 3 deg", fontsize=8)
    ax.set_ylim(0, 22.5)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("heading error (deg)")
    # The legend goes under the axes: inside, any corner meets a curve or a marked level.
    ax.legend(fontsize=8, ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False)
    fig.tight_layout()
    return fig
