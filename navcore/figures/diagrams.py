"""Structural figures: the papers' block diagrams, drawn from the models they describe.

Every quantity on a diagram is read from navcore: state counts from the state layouts,
rates from the scenario inputs, the cascade's update interval and EHE limit from the
covariance engine's loosely coupled schedule.
"""

from __future__ import annotations

import inspect
from typing import cast

from matplotlib.figure import Figure

from navcore import diagrams
from navcore.figures import register

__all__: list[str] = []


@register(
    "KZL-fig1",
    paper="KZL",
    reproduces="Fig. 1",
    caption="Simplified inertial navigation system (redraws KZL Fig. 1): IMU angular rates and specific "
    "forces feed the strapdown attitude, velocity and position updates, with the gravity model and the "
    "Earth and transport rates fed back from position and velocity. The IMU rate is the Table 1 scenario's.",
)
def kzl_ins_block_diagram() -> Figure:
    from navcore.papers.kzl_scenario import IN

    return diagrams.ins_block_diagram(imu_rate_hz=cast(float, IN.imu_rate_hz))


@register(
    "KZL-fig2",
    paper="KZL",
    reproduces="Fig. 2",
    caption="Simplified GNSS receiver (redraws KZL Fig. 2): correlators driven by replica carrier and code, "
    "carrier and code tracking loops, and the navigation processor that turns code phase and carrier "
    "phase/Doppler into position, velocity and time at the Table 1 GPS rate.",
)
def kzl_gnss_receiver_diagram() -> Figure:
    from navcore.papers.kzl_scenario import IN

    return diagrams.gnss_receiver_block_diagram(nav_rate_hz=cast(float, IN.gps_rate_hz))


@register(
    "KZL-fig3",
    paper="KZL",
    reproduces="Fig. 3",
    caption="Tightly coupled indirect feedback GNSS/INS integration (redraws KZL Fig. 3): predicted minus "
    "measured pseudorange and delta range drive the error-state Kalman filter, whose position, velocity "
    "and attitude corrections and sensor-error estimates are fed back. State count from the 17-state "
    "layout of navcore.inertial.error_model17; rates from the Table 1 scenario.",
)
def kzl_tightly_coupled_diagram() -> Figure:
    from navcore.inertial.error_model17 import ERROR_LAYOUT_17
    from navcore.papers.kzl_scenario import IN

    return diagrams.tightly_coupled_feedback_diagram(
        n_states=ERROR_LAYOUT_17.size,
        imu_rate_hz=cast(float, IN.imu_rate_hz),
        gnss_rate_hz=cast(float, IN.gps_rate_hz),
    )


@register(
    "ATC10-fig3.1",
    paper="ATC10",
    reproduces="Fig. 3.1",
    caption="Receiver structure for the detector matched to aircraft i's signature (redraws ATC-10 "
    "Fig. 3.1): mixing with the phase-synchronised carrier, low-pass filtering, the matched filter "
    "h(t) = S_i(tau - t) of Eq. (3.3.3) and the binary threshold decision on the sampled output.",
)
def atc10_matched_filter_receiver() -> Figure:
    return diagrams.matched_filter_receiver_diagram("i")


@register(
    "SP-architectures",
    paper="SP",
    reproduces="new",
    caption="Loosely coupled, tightly coupled and deeply integrated INS/GPS side by side, as Secs. 2.1, "
    "2.2 and 3 describe them in words (the paper has no such figure). State counts come from the layouts "
    "of Tables 2.1-2.3 (navcore.gnss.architectures); the cascade's update interval and EHE limit are "
    "those Sec. 2.1 prints; the minimum number of satellites is the number of "
    "unknowns of a pseudorange fix (position and clock bias).",
)
def sp_integration_architectures() -> Figure:
    from navcore.gnss.architectures import (
        CLOCK,
        PVA,
        loosely_coupled_layout,
        receiver_pva_layout,
        tightly_coupled_layout,
    )
    from navcore.integration.schedules import tightly_coupled_schedule
    from navcore.papers.sp_scenario_wiring import IN as SCENARIO

    tight = inspect.signature(tightly_coupled_schedule).parameters
    return diagrams.integration_architectures_diagram(
        receiver_states=receiver_pva_layout().size,
        loose_states=loosely_coupled_layout().size,
        tight_states=tightly_coupled_layout().size,
        loose_update_s=SCENARIO.lc_fix_interval_s,
        ehe_limit_m=SCENARIO.lc_max_ehe_m,
        tight_rate_hz=1.0 / (tight["every"].default * SCENARIO.step_s),
        min_satellites=PVA.block("position").size + CLOCK.block("clock bias").size,
    )
