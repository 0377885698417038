"""SP Figs. 2.6-2.7 redrawn from the jammer-flyby model and the covariance engine."""

from __future__ import annotations

import matplotlib.pyplot as plt
from matplotlib.figure import Figure

from navcore.figures import register, value_bars
from navcore.gnss.constellation import nominal_gps_constellation
from navcore.papers import sp_flyby as fb
from navcore.papers import sp_missions_scenarios as sc
from navcore.units import MINUTE

_ASSUMED = (
    "Assumed (the paper does not publish them): a ground jammer 10 km abeam a straight eastbound "
    "leg flown at 7 km and 200 m/s after two calibration turns, closest approach at 40 min; "
    "free-space propagation; receiver antenna +3 dBic at zenith falling linearly to -5 dBic at "
    "the horizon, -10 dBic towards the jammer; P(Y) code at -163 dBW, N0 = -204 dBW/Hz, "
    "spectral separation Q = 2; the satellites of the nominal 24-satellite constellation above "
    "10 deg. The jammer's radiated power is calibrated so that the loosely coupled blackout "
    "lasts the paper's 20 min. Thresholds are the paper's (Sec. 2.5)."
)


def _blackout_span(ax, system: sc.System, color: str, label: str) -> None:
    s, e = fb._blackout(system, fb.calibrated_erp_dbw())
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
    cn0 = fb.effective_cn0(fb.calibrated_erp_dbw())
    prn = nominal_gps_constellation().prn[fb.channels()]
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
    ax.set_xlim(25, t[-1])
    ax.set_ylim(-5, 40)
    ax.set_xlabel("time (min)")
    ax.set_ylabel("effective C/N0 (dB-Hz)")
    ax.legend(loc="lower left", fontsize=7, ncol=3)
    return fig


@register(
    "SP-fig2.6",
    paper="SP",
    reproduces="Fig. 2.6",
    caption="Fig. 2.6 redrawn: GPS blackout in the jammer flyby by architecture and IMU quality, "
    "from the C/N0 threshold crossings plus the Sec. 2.5 search time at reacquisition. The black "
    "marks are the text's values: 20 min for the loosely coupled receiver (used to calibrate the "
    "jammer power) and 'about 2 min' less for the best tightly coupled system. " + _ASSUMED,
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
        legend={"tab:red": "this book, jammer calibrated to it", "tab:blue": "this book"},
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
    "through the jammer flyby; dots mark the value just before each system's reacquisition, stars "
    "the text's 3300 m (TC 10 nmi/h) and 260 m (TC 1 nmi/h). 22-state loosely and 24-state "
    "tightly coupled filters against the truth model of the missions page (46 states with six "
    "channels), driven by the "
    "flyby's lock table. " + _ASSUMED,
)
def sp_fig2_7() -> Figure:
    runs = fb.flyby_runs()
    before = fb.errors_before_reacquisition()
    erp = fb.calibrated_erp_dbw()
    fig, ax = plt.subplots()
    for s, r in runs.items():
        (line,) = ax.semilogy(r.t / MINUTE, r.horizontal_position, lw=1.0, label=s.label)
        _, end = fb._blackout(s, erp)
        ax.plot((end - 1.0) / MINUTE, before[s.label], "o", color=line.get_color(), ms=5)
        if s.grade in fb.FIG27_M and s.architecture == "tight":
            ax.plot((end - 1.0) / MINUTE, fb.FIG27_M[s.grade], "*", color=line.get_color(), ms=12, mec="k")
    ax.set_xlim(25, r.t[-1] / MINUTE)
    ax.set_xlabel("time (min)")
    ax.set_ylabel("horizontal position error, rss 1-sigma (m)")
    ax.legend(loc="upper left", fontsize=8)
    return fig
