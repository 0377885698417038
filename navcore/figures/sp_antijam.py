"""SP Section 3 figures: correlation, PGM altitude and J/S (Figs. 3.4-3.5), CEP and A/J (Figs. 3.6-3.8)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from navcore.figures import register
from navcore.gnss.antijam import early_minus_late, ideal_correlation
from navcore.papers import sp_antijam as spj
from navcore.units import NMI


@register(
    "SP-correlation",
    paper="SP",
    reproduces="new",
    caption="Ideal correlation function of Sec. 3.0 and the early-minus-late discriminator with the "
    "paper's half-chip correlator spacing (linear within a quarter chip, zero beyond 1.25 chips).",
)
def correlation_figure() -> Figure:
    tau = np.linspace(-2.0, 2.0, 801)
    fig, ax = plt.subplots()
    ax.plot(tau, ideal_correlation(tau), label=r"$R_c(\tau) = 1 - |\tau|$")
    ax.plot(tau, early_minus_late(tau, 0.5), "--", label="early - late, spacing 1/2 chip")
    ax.set_xlabel(r"code phase error $\tau$ (chips)")
    ax.set_ylabel("normalised output")
    ax.legend()
    return fig


@register(
    "SP-fig3.4",
    paper="SP",
    reproduces="Fig. 3.4",
    caption="PGM altitude profile, reconstructed (the paper's profile is not given): launch 63 nmi from "
    "the target at 9 km, 250 m/s, a linear dive over the last 20 km; the jammer on the ground 5 nmi "
    "before the target.",
)
def pgm_altitude_figure() -> Figure:
    _, x, alt = spj.pgm_trajectory()
    fig, ax = plt.subplots()
    ax.plot(x / NMI, alt / 1000.0)
    ax.axvline(spj.IN.target_range_nmi - spj.IN.jammer_before_target_nmi, color="C3", ls=":", label="jammer")
    ax.set_xlabel("distance from launch (nmi)")
    ax.set_ylabel("altitude (km)")
    ax.legend()
    return fig


@register(
    "SP-fig3.5",
    paper="SP",
    reproduces="Fig. 3.5",
    caption="Free-space J/S along the reconstructed PGM trajectory for a 100-W jammer (P(Y) signal at "
    "-163 dBW, -3 dB antenna gain towards the jammer), with the stated tightly coupled (54 dB) and "
    "deeply integrated (65 dB) code-lock limits.",
)
def pgm_js_figure() -> Figure:
    t, _, _ = spj.pgm_trajectory()
    fig, ax = plt.subplots()
    ax.plot(t, spj.pgm_js_db(100.0), label="100 W")
    ax.axhline(spj.IN.tc_loss_js_db, color="C1", ls="--", label="TC loses lock (54 dB)")
    ax.axhline(spj.IN.di_lock_js_db, color="C2", ls=":", label="DI limit (65 dB)")
    ax.set_xlabel("time from launch (s)")
    ax.set_ylabel("J/S (dB)")
    ax.legend()
    return fig


def _cep_figure(kind: str) -> Figure:
    fig, ax = plt.subplots()
    for arch, style in (("TC", "o-"), ("DI", "s-")):
        cep, seeds = spj.cep_curve(arch, kind)
        ax.loglog(
            spj.POWERS_W,
            cep,
            style,
            label=f"{arch}, {spj.IN.runs} runs per point (seeds {seeds[0]}-{seeds[-1]})",
        )
        ax.loglog(spj.FINE_POWERS_W, spj.model_ceps(arch, kind, spj.FINE_POWERS_W), "-", color="0.6", lw=0.8)
    if kind == "wideband":
        for (arch, p), text in spj.PUBLISHED_CEP.items():
            ax.loglog([p], [float(text)], "kx" if arch == "TC" else "k+", ms=10)
        ax.plot([], [], "kx", label="paper, TC (text)")
        ax.plot([], [], "k+", label="paper, DI (text)")
    ax.set_xlabel("jammer power (W)")
    ax.set_ylabel("CEP at impact (m)")
    ax.legend(fontsize=8)
    return fig


@register(
    "SP-fig3.6",
    paper="SP",
    reproduces="Fig. 3.6",
    caption="CEP at impact against wideband (20 MHz) jammer power, reduced navigator model with the "
    "paper's MEMS IMU, 25 seeded runs per point (grey: the model's exact CEP); crosses are the four CEPs "
    "quoted in the text.",
)
def cep_wideband_figure() -> Figure:
    return _cep_figure("wideband")


@register(
    "SP-fig3.7",
    paper="SP",
    reproduces="Fig. 3.7",
    caption="CEP at impact against narrowband (1 kHz) jammer power, same model and seeds scheme as "
    "Fig. 3.6 (grey: exact CEP); the narrowband jammer's spectral separation factor is Q = 1 "
    "instead of 2.17.",
)
def cep_narrowband_figure() -> Figure:
    return _cep_figure("narrowband")


@register(
    "SP-fig3.8",
    paper="SP",
    reproduces="Fig. 3.8",
    caption="A/J improvement of deep integration (jammer power ratio at equal CEP) from the reduced "
    "model's exact CEP curves; the paper reports at least 15 dB over 6-120 m (wideband).",
)
def aj_improvement_figure() -> Figure:
    cep = np.geomspace(4.0, 150.0, 40)
    fig, ax = plt.subplots()
    for kind, style in (("wideband", "-"), ("narrowband", "--")):
        ax.semilogx(cep, spj.aj_improvement_db(kind, cep), style, label=kind)
    ax.axhline(15.0, color="0.5", lw=0.8, label="paper: at least 15 dB")
    ax.set_xlabel("CEP (m)")
    ax.set_ylabel("A/J improvement (dB)")
    ax.legend()
    return fig
