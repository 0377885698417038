"""SP Figs. 2.2-2.10 redrawn from the covariance-analysis engine, and the grade calibration."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from navcore.figures import register, value_bars
from navcore.papers import sp_mission_flights as sc
from navcore.papers import sp_missions as spm
from navcore.papers.sp_tables import GRADE_LABELS_NMI_PER_H

_ASSUMED = (
    "Trajectory, satellites, receiver noise, clock and filter tuning are the book's assumptions "
    "(listed on the missions page)."
)


def _events(ax, reacquisition: bool = True) -> None:
    """Dotted lines at the Sec. 2.6.1 events: carrier losses (orange), code losses (red) and,
    unless ``reacquisition`` is false (the free-inertial variant), code reacquisitions (green)."""
    events = sc.sequential_outage_events(outage_s=-1.0 if reacquisition else None)
    for t, _, kind, back in events:
        if kind == "carrier" and not back:
            ax.axvline(t / 60, color="tab:orange", lw=0.6, ls=":")
        elif kind == "code":
            ax.axvline(t / 60, color="tab:green" if back else "tab:red", lw=0.6, ls=":")


def _velocity_figure(label: str) -> Figure:
    res = {s.label: r for s, r in sc.sequential_outage(False).items()}[label]
    fig, ax = plt.subplots()
    ax.semilogy(res.t / 60, res.horizontal_velocity, label=f"{label}: true")
    fv = np.sqrt(res.filter_var[:, 3] + res.filter_var[:, 4])
    ax.semilogy(res.t / 60, fv, "--", lw=0.8, label=f"{label}: filter's own")
    _events(ax)
    ax.set_xlabel("time (min)")
    ax.set_ylabel("horizontal velocity error, rss 1-sigma (m/s)")
    ax.legend(loc="upper right")
    return fig


@register(
    "SP-fig2.2",
    paper="SP",
    reproduces="Fig. 2.2",
    caption="Horizontal velocity error of the loosely coupled 1 nmi/h system in the sequential "
    "outage: carriers lost at 6, 9, 12, 15 min (orange), codes at 17-26 min (red), codes back "
    "from 46 min (green). Solid: true error; dashed: what the 22-state filter believes. " + _ASSUMED,
)
def sp_fig2_2() -> Figure:
    return _velocity_figure("LC 1 nmi/h")


@register(
    "SP-fig2.3",
    paper="SP",
    reproduces="Fig. 2.3",
    caption="As Fig. 2.2 for the tightly coupled 1 nmi/h system (24-state filter). " + _ASSUMED,
)
def sp_fig2_3() -> Figure:
    return _velocity_figure("TC 1 nmi/h")


def _bars(values: dict[str, float], ylabel: str, published: dict[str, float] | None = None) -> Figure:
    fig, ax = plt.subplots()
    value_bars(ax, values, printed=published, printed_label="printed in the text", log=True)
    ax.set_ylabel(ylabel)
    return fig


@register(
    "SP-fig2.4",
    paper="SP",
    reproduces="Fig. 2.4",
    caption="Horizontal position error (rss 1-sigma) of the five systems at code reacquisition, "
    "after the 20-min total outage of the sequential-outage mission. " + _ASSUMED,
)
def sp_fig2_4() -> Figure:
    return _bars(spm.sequential_errors(False), "horizontal position error at reacquisition (m)")


@register(
    "SP-fig2.5",
    paper="SP",
    reproduces="Fig. 2.5",
    caption="Horizontal position error (rss 1-sigma) 84 min after the last code loss (free "
    "inertial), with the two values the text prints (1131 m for 1 nmi/h, close to 18000 m for "
    "10 nmi/h). " + _ASSUMED,
)
def sp_fig2_5() -> Figure:
    from navcore import ledger

    pub = {
        "TC 1 nmi/h": float(ledger.claim("SP-sec2.6.1-84min-1nmi").published),
        "TC 10 nmi/h": float(ledger.claim("SP-sec2.6.1-84min-10nmi").published),
    }
    return _bars(spm.sequential_errors(True), "horizontal position error after 84 min (m)", pub)


@register(
    "SP-seq-position",
    paper="SP",
    reproduces="new",
    caption="Horizontal position error of the five systems through the free-inertial variant "
    "of the sequential outage (GPS lost step by step from 6 min, none after 26 min). The "
    "Schuler oscillation (84.4 min) is visible in every curve. " + _ASSUMED,
)
def sp_seq_position() -> Figure:
    fig, ax = plt.subplots()
    for s, r in sc.sequential_outage(True).items():
        ax.semilogy(r.t / 60, r.horizontal_position, label=s.label)
    _events(ax, reacquisition=False)
    ax.set_xlabel("time (min)")
    ax.set_ylabel("horizontal position error, rss 1-sigma (m)")
    ax.legend()
    return fig


@register(
    "SP-fig2.8",
    paper="SP",
    reproduces="Fig. 2.8",
    caption="Horizontal position error at bomb release in the head-on approach: all satellites "
    "lost 159 s (loosely coupled) or 153 s (tightly coupled) before release, the times the text "
    "prints. Climb to about 40,000 ft, break turn, dive to low level, pop-up. " + _ASSUMED,
)
def sp_fig2_8() -> Figure:
    vals = {}
    for arch in ("loose", "tight"):
        for s, r in sc.head_on_approach(arch).items():
            vals[s.label] = float(r.horizontal_position[-1])
    return _bars(vals, "horizontal position error at release (m)")


def _heli_figure(doppler_cases: tuple[bool, ...]) -> Figure:
    fig, ax = plt.subplots()
    nb = 2 * len(doppler_cases)
    width = 0.8 / nb
    x = np.arange(2)
    bars = []
    for d in doppler_cases:
        res = sc.helicopter(d)
        tag = "INS/GPS + Doppler" if d else "INS/GPS"
        bars.append(
            (f"{tag}: helicopter position", [float(res[g].horizontal_position[-1]) for g in (10.0, 1.0)])
        )
        bars.append((f"{tag}: target location", [sc.target_location_sigma(res[g]) for g in (10.0, 1.0)]))
    for i, (lab, vals) in enumerate(bars):
        xs = x + (i - (nb - 1) / 2) * width
        ax.bar(xs, vals, width, label=lab)
        for xi, v in zip(xs, vals, strict=True):
            ax.annotate(f"{v:.0f}", (xi, v), ha="center", va="bottom", fontsize=7)
    ax.set_xticks(x, ["10 nmi/h", "1 nmi/h"])
    ax.set_yscale("log")
    ax.set_ylabel("horizontal error after 19 min without GPS (m)")
    ax.legend(fontsize=8)
    return fig


@register(
    "SP-fig2.9",
    paper="SP",
    reproduces="Fig. 2.9",
    caption="Helicopter position and target-location (8 km) error 19 min after GPS loss, without "
    "Doppler aiding, tightly coupled 10 and 1 nmi/h. Terrain following at 40 m/s after 30 min of "
    "GPS-aided calibration. " + _ASSUMED,
)
def sp_fig2_9() -> Figure:
    return _heli_figure((False,))


@register(
    "SP-fig2.10",
    paper="SP",
    reproduces="Fig. 2.10",
    caption="As Fig. 2.9, and with Doppler ground-speed aiding (Table 2.8 errors, 0.1 m/s noise "
    "assumed). " + _ASSUMED,
)
def sp_fig2_10() -> Figure:
    return _heli_figure((False, True))


@register(
    "SP-grade-calibration",
    paper="SP",
    reproduces="new",
    caption="1-hour unaided CEP of each Table 2.5 column (stationary, 45 deg latitude, "
    "gyrocompass-aligned) against the grade label. Only the 10 nmi/h column meets its label; the "
    "others give about a third of theirs, in the right ratios.",
)
def sp_grade_calibration() -> Figure:
    cep = spm.grade_cep_nmi()
    fig, ax = plt.subplots()
    g = np.array(GRADE_LABELS_NMI_PER_H)
    ax.loglog(g, [cep[x] for x in g], "o-", label="Table 2.5 column, 1-h CEP")
    ax.loglog(g, g, "k--", lw=0.8, label="label = 1-h error")
    ax.loglog(g, g / 3, "k:", lw=0.8, label="label / 3")
    ax.set_xlabel("grade label (nmi/h)")
    ax.set_ylabel("1-h unaided CEP (nmi)")
    ax.legend()
    return fig
