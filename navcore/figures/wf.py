"""WF figures: Figs. 1-2 (velocity-accuracy improvement) and the book's worked example."""

from __future__ import annotations

from typing import Any

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from navcore.figures import apply_style, register
from navcore.papers import wf_aperture_velocity, wf_assessment, wf_inputs
from navcore.papers import wf_example as ex
from navcore.units import MICRO_G

_COLOURS = {0.0: "C0", 0.2: "C1", 2.0: "C2"}


def _axis_ug(ax: plt.Axes) -> None:
    ax.set_xscale("log")
    ax.set_xlabel(r"accelerometer resolution $\sigma_a$ at 50 Hz (m/s$^2$)")
    ax.set_ylabel(r"$20\log_{10}(\sigma_D/\sigma_{DN})$ (dB)")
    sec = ax.secondary_xaxis("top", functions=(_to_micro_g, _from_micro_g))
    sec.set_xlabel(r"$\sigma_a$ ($\mu g$)")


def _to_micro_g(x: Any) -> Any:
    return x / MICRO_G


def _from_micro_g(x: Any) -> Any:
    return x * MICRO_G


@register(
    "WF-fig1",
    paper="WF",
    reproduces="Fig. 1",
    caption="Velocity-accuracy improvement bound with the local accelerometer and no GPS, for "
    "sigma_T = 0, 0.2 and 2 m/s. Per-axis sigma_D from the middle term of Eq. (23); steady-state "
    "filters; sigma_L = 200 sigma_a; tau P_N tau^T = sigma_N^2 I (erratum WF-E2); axis 10 um/s^2 to "
    "10 mm/s^2 as stated in Sec. IV.D.",
)
def improvement_without_gps() -> Figure:
    apply_style()
    c = wf_assessment.improvement_curves()
    fig, ax = plt.subplots()
    for st in wf_inputs.sigma_t_values():
        ax.plot(c["sigma_a"], c[(st, 0)], color=_COLOURS[st], label=rf"$\sigma_T$ = {st:g} m/s")
    ax.plot(
        [wf_inputs.sigma_a_example()],
        [wf_assessment.improvement_db(wf_inputs.sigma_a_example(), 2.0)],
        "kx",
        label=r"100 $\mu g$",
    )
    _axis_ug(ax)
    ax.legend()
    return fig


@register(
    "WF-fig2",
    paper="WF",
    reproduces="Fig. 2",
    caption="As Fig. 1 with the aperture-acquired GPS Doppler update: lines 1 satellite, circles 3 "
    "satellites (H_G of Eq. (25) with the exact f_L1/c, sigma_G = 1 Hz; for sigma_T = 0 the "
    "3-satellite curve coincides with the 1-satellite line and is not drawn), dashed: Fig. 1 (no GPS). "
    "Right panel: the axis extended to 1 m/s^2, where GPS starts to matter.",
)
def improvement_with_gps() -> Figure:
    apply_style()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.0), sharey=True)
    for ax, c in zip(
        axes,
        (
            wf_assessment.improvement_curves(),
            wf_assessment.improvement_curves(wf_inputs.IN.sigma_a_low, wf_inputs.IN.sigma_a_poor_max, 41),
        ),
        strict=True,
    ):
        for st in wf_inputs.sigma_t_values():
            col = _COLOURS[st]
            ax.plot(c["sigma_a"], c[(st, 1)], color=col, label=rf"$\sigma_T$ = {st:g} m/s, 1 sat")
            if st > 0:
                ax.plot(c["sigma_a"][::3], c[(st, 3)][::3], "o", mfc="none", color=col, label="3 sat")
            ax.plot(c["sigma_a"], c[(st, 0)], "--", lw=0.9, color=col)
        _axis_ug(ax)
    axes[0].set_title("stated range")
    axes[1].set_title("extended range")
    axes[1].axvspan(wf_inputs.IN.sigma_a_high, wf_inputs.IN.sigma_a_poor_max, color="0.9", zorder=0)
    axes[0].legend(fontsize=8)
    return fig


@register(
    "WF-example",
    paper="WF",
    reproduces="new",
    caption="Worked example: emitter position estimates (20 seeded trials, book geometry, 1 Hz "
    "frequency noise, 3 Hz narrowband wing-tip vibration of 0.1 m RMS) with the true, the "
    "navigation-only and the federated aperture velocity (100 ug accelerometer). Right: vertical "
    "aperture-velocity error of one trial.",
)
def worked_example() -> Figure:
    apply_style()
    r = ex.run()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.0))
    styles = {"navigation": ("C3", "x"), "federated": ("C2", "o"), "true": ("k", ".")}
    for case in ("navigation", "federated", "true"):
        e = r["errors"][case]
        col, mk = styles[case]
        ax.plot(e[:, 0], e[:, 1], mk, color=col, mfc="none", label=f"{case} velocity")
    ax.set_xlabel("east error of the emitter estimate (m)")
    ax.set_ylabel("north error (m)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend()
    for case in ("navigation", "federated"):
        bx.plot(r["t"], r["vel_err"][case][0, :, 2], color=styles[case][0], label=case)
    bx.set_xlabel("time (s)")
    bx.set_ylabel("vertical aperture-velocity error (m/s)")
    # the navigation trace fills the whole panel: the legend sits above it, never over the data
    bx.legend(loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=2, frameon=False, borderaxespad=0.2)
    return fig


@register(
    "WF-sensitivity",
    paper="WF",
    reproduces="new",
    caption="Position sensitivity |df/dp| divided by the printed bound (f0/c) 2|v|/R of Eq. (9) over "
    "2000 seeded random geometries: it never exceeds 1/2.",
)
def position_bound_ratio() -> Figure:
    apply_style()
    ratios = wf_aperture_velocity.position_bound_ratios()
    fig, ax = plt.subplots(figsize=(6.4, 3.2))
    ax.hist(ratios, bins=np.linspace(0, 0.55, 45).tolist(), color="C0")
    ax.axvline(0.5, color="k", ls="--", lw=1)
    ax.set_xlabel(r"$\|\partial f/\partial \mathbf{p}\|$ / printed bound")
    ax.set_ylabel("number of geometries")
    return fig
