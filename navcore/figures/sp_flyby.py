"""SP Figs. 2.6-2.7 redrawn from the jammer-flyby model and the covariance engine."""

from __future__ import annotations

import matplotlib.pyplot as plt
from matplotlib.figure import Figure

from navcore.figures import register, value_bars
from navcore.papers import sp_flyby as fb
from navcore.papers import sp_scenario_wiring as sc
from navcore.units import MINUTE

_ASSUMED = (
    "Assumed (the paper does not publish them, see the flyby page for the values and their ranges): "
    "a ground jammer abeam a straight eastbound leg flown after two calibration turns, closest "
    "approach at the flight's midpoint; free-space propagation; an upward-looking antenna whose gain "
    "falls from the zenith to the horizon; seven satellites of a 30-satellite constellation. The "
    "jammer's strength is fitted so that the loosely coupled blackout lasts the paper's 20 min. "
    "Thresholds, bandwidths and the search rule are the paper's (Sec. 2.5), the thresholds read as "
    "C/N0 in dB-Hz (the book's reading; the flyby page also gives the other, a ratio in each loop's "
    "own noise bandwidth)."
)


def _blackout_span(ax, system: sc.System, color: str, label: str) -> None:
    s, e = fb._blackout_s(system)
    ax.axvspan(s / MINUTE, e / MINUTE, color=color, alpha=0.12, label=label)


@register(
    "SP-flyby-cn0",
    paper="SP",
    reproduces="new",
    caption="Effective C/N0 of each tracked satellite along the flyby (not in the paper), with the "
    "Sec. 2.5 thresholds: code lost below 18 dB-Hz and back above 21 dB-Hz, carrier 19 and 22 "
    "dB-Hz. Shaded: the loosely coupled blackout (fewer than four codes) and the tightly coupled "
    "one (no code at all). " + _ASSUMED,
)
def sp_flyby_cn0() -> Figure:
    tr = fb.flyby_trajectory()
    cn0 = fb.effective_cn0(fb.calibrated_jammer_db())
    prn = fb.constellation().prn[fb.channels()]
    fig, ax = plt.subplots()
    t = tr.t / MINUTE
    for c in range(cn0.shape[1]):
        ax.plot(t, cn0[:, c], lw=1.0, label=f"PRN {prn[c]}")
    for y, ls, lab in (
        (fb.IN.code_loss_dbhz, "--", "code loss 18"),
        (fb.IN.code_reacquisition_dbhz, "-.", "code reacquisition 21"),
        (fb.IN.carrier_loss_dbhz, ":", "carrier loss 19 / back 22"),
    ):
        ax.axhline(y, color="k", lw=0.8, ls=ls, label=lab)
    ax.axhline(fb.IN.carrier_reacquisition_dbhz, color="k", lw=0.8, ls=":")
    _blackout_span(ax, sc.SYSTEMS[0], "tab:red", "LC blackout")
    _blackout_span(ax, sc.SYSTEMS[1], "tab:blue", "TC blackout")
    t_ca = fb.IN.closest_approach_min
    ax.set_xlim(t_ca - 20, t_ca + 25)
    ax.set_ylim(-5, 50)
    ax.set_xlabel("time (min)")
    ax.set_ylabel("effective $C/N_0$ (dB-Hz)")
    ax.legend(loc="lower left", fontsize=7, ncol=3)
    return fig


@register(
    "SP-fig2.6",
    paper="SP",
    reproduces="Fig. 2.6",
    caption="Fig. 2.6 redrawn: GPS blackout in the jammer flyby by architecture and IMU quality, "
    "from the Sec. 2.5 loss and reacquisition rules plus the search time at reacquisition. The "
    "black marks are the text's values: 20 min for the loosely coupled receiver (to which the "
    "jammer's strength is fitted) and 'about 2 min' less for the best tightly coupled system. " + _ASSUMED,
)
def sp_fig2_6() -> Figure:
    b = fb.blackouts_min()
    labels = list(b)
    fig, ax = plt.subplots()
    value_bars(
        ax,
        b,
        fmt="{:.2f}",
        colours={labels[0]: "tab:red"},
        legend={"tab:red": "this book, jammer fitted to it", "tab:blue": "this book"},
        printed={labels[0]: fb.LC_BLACKOUT_MIN, labels[-1]: fb.LC_BLACKOUT_MIN - fb.BLACKOUT_REDUCTION_MIN},
        printed_label="text: 20 min; about 2 min less",
    )
    ax.set_ylabel("blackout (min)")
    ax.set_ylim(0, 32)
    return fig


@register(
    "SP-fig2.7",
    paper="SP",
    reproduces="Fig. 2.7",
    caption="Fig. 2.7 redrawn: true horizontal position error (rss 1-sigma) of the five systems "
    "through the jammer flyby; dots mark the value just before the reacquisition that ends each "
    "system's blackout, stars the text's 3300 m (TC 10 nmi/h) and 260 m (TC 1 nmi/h). 22-state "
    "loosely and 24-state tightly coupled filters against the truth model of the missions page "
    "(48 states with seven channels), driven by the flyby's lock tables. " + _ASSUMED,
)
def sp_fig2_7() -> Figure:
    runs = fb.flyby_runs()
    before = fb.errors_before_reacquisition()
    fig, ax = plt.subplots()
    for s, r in runs.items():
        (line,) = ax.semilogy(r.t / MINUTE, r.horizontal_position, lw=1.0, label=s.label)
        start, end, k = fb._ending_return(s)
        at = r.t[k - 1] if k is not None else start  # the sample the value is read at
        ax.plot(at / MINUTE, before[s.label], "o", color=line.get_color(), ms=5)
        if s.grade in fb.FIG27_M and s.architecture == "tight":
            ax.plot(end / MINUTE, fb.FIG27_M[s.grade], "*", color=line.get_color(), ms=12, mec="k")
    t_ca = fb.IN.closest_approach_min
    ax.set_xlim(t_ca - 20, r.t[-1] / MINUTE)
    ax.set_xlabel("time (min)")
    ax.set_ylabel("horizontal position error, rss 1-sigma (m)")
    ax.legend(loc="upper left", fontsize=8)
    return fig
