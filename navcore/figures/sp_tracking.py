"""SP Fig. 2.1 redrawn: third-order loop error after a 6-g step, with both phase conversions."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from navcore.figures import register
from navcore.gnss.tracking import (
    distance_to_phase_deg,
    jerk_pulse_error,
    natural_frequency_for_peak_error,
    third_order_loop_step_error,
)
from navcore.papers import sp_tracking as sp
from navcore.units import G0, GPS_L1_WAVELENGTH_M


@register(
    "SP-fig2.1",
    paper="SP",
    reproduces="Fig. 2.1",
    caption="Error of the third-order (Butterworth) carrier loop after a 6-g acceleration step. "
    "Solid: the paper's curve, 17.67 rad/s with 360 deg per foot, peaking at 90 deg. Dashed: the same "
    "loop with the physical L1 conversion (0.1903 m), peaking at 144 deg; dotted: the L1 loop at "
    "22.37 rad/s, which meets the 90 deg limit.",
)
def third_order_step_error_figure() -> Figure:
    t = np.linspace(0.0, 0.8, 1601)
    w_l1 = natural_frequency_for_peak_error(sp.step_deg_s2(GPS_L1_WAVELENGTH_M), sp.IN.peak_limit_deg)
    fig, ax = plt.subplots()
    ax.plot(
        t,
        third_order_loop_step_error(t, sp.step_deg_s2(sp.IN.foot_per_cycle_m), sp.IN.omega0_fig21),
        label="paper: 1 cycle/ft, 17.67 rad/s",
    )
    ax.plot(
        t,
        third_order_loop_step_error(t, sp.step_deg_s2(GPS_L1_WAVELENGTH_M), sp.IN.omega0_fig21),
        "--",
        label="L1 carrier, 17.67 rad/s",
    )
    ax.plot(
        t,
        third_order_loop_step_error(t, sp.step_deg_s2(GPS_L1_WAVELENGTH_M), w_l1),
        ":",
        label=f"L1 carrier, {w_l1:.2f} rad/s",
    )
    ax.axhline(90.0, color="0.5", lw=0.8)
    ax.set_xlabel("time after the step (s)")
    ax.set_ylabel("phase error (deg)")
    ax.legend()
    return fig


@register(
    "SP-step-vs-jerk",
    paper="SP",
    reproduces="new",
    caption="Phase error at 17.67 rad/s (L1 conversion) for the 6-g step and for the 10-g/s jerk held "
    "for 0.6 s that it stands in for: the step's peak is about four times larger.",
)
def step_versus_jerk_figure() -> Figure:
    t = np.linspace(0.0, 1.5, 3001)
    lam = GPS_L1_WAVELENGTH_M
    fig, ax = plt.subplots()
    ax.plot(t, third_order_loop_step_error(t, sp.step_deg_s2(lam), sp.IN.omega0_fig21), label="6-g step")
    J = float(distance_to_phase_deg(sp.IN.jerk_g_per_s * G0, lam))
    ax.plot(
        t,
        jerk_pulse_error(t, J, sp.IN.jerk_duration_s, sp.IN.omega0_fig21),
        "--",
        label="10 g/s jerk for 0.6 s",
    )
    ax.set_xlabel("time (s)")
    ax.set_ylabel("L1 phase error (deg)")
    ax.legend()
    return fig
