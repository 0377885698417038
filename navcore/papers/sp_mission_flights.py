"""SP Sections 2.6.1, 2.6.3 and 2.6.4: the three mission flights set up for the
covariance-analysis engine.

The sequential outage (the cruise, the loss and reacquisition events of Figs. 2.2-2.4 and its
free-inertial variant), the head-on approach (Fig. 2.8) and the terrain-following helicopter
(Fig. 2.9), with the inputs only they read, and the target-location error of Sec. 2.6.4. They
fly on the shared wiring of :mod:`navcore.papers.sp_scenario_wiring` (systems, error sources,
covariance runs, constellation, calibration turns).

The paper publishes the event times of the sequential outage and the free-inertial spans of
the head-on approach, but not the flight profiles. Every such number a claim reads is an input
of :data:`IN`, with the locator where the paper prints it or, where it does not, a nominal
value, a plausible range and the reason for both; the ledger evaluates each claim across those
ranges. The shapes of the flight profiles (when each turn or climb happens) are the scenario's
design, written out in the trajectory functions and on the missions page.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, fields

import numpy as np

from navcore._validate import ModelDomainError
from navcore.claims import input_cache
from navcore.claims.inputs import InputSet
from navcore.estimation.layout import StateLayout
from navcore.gnss.architectures import tightly_coupled_layout
from navcore.inertial.error_dynamics import ErrorSources, gravity_tuning_psd
from navcore.inertial.trajectories import Segment, Trajectory, fly, trajectory_window
from navcore.integration.engine import CovarianceAnalysis, concatenate_analyses
from navcore.integration.geometry import best_geometry_channels, lock_table, satellite_geometry
from navcore.integration.schedules import baro_schedule, combine_schedules, tightly_coupled_schedule
from navcore.papers import sp_acquisition as spa
from navcore.papers import sp_scenario_wiring as sw
from navcore.papers import sp_tables as tab
from navcore.papers.sp_scenario_wiring import (
    SYSTEMS,
    AprioriTransform,
    System,
    _initial_covariance,
    _run,
    _run_list,
    calibration_turns,
    error_sources,
    gps_constellation,
    truth_layout,
)
from navcore.papers.sp_tables import sp_imu_grade
from navcore.units import DEG, FT, G0, MINUTE

__all__ = [
    "IN",
    "EngineInputs",
    "engine_inputs",
    "head_on_approach",
    "head_on_trajectory",
    "helicopter",
    "helicopter_momentary_carrier_loss",
    "helicopter_trajectory",
    "initial_error_runs",
    "sequential_outage",
    "sequential_outage_events",
    "sequential_outage_trajectory",
    "target_location_sigma",
    "unaided_after_ground_alignment",
]


#: The flights' own inputs. The section string is the wiring's
#: (:mod:`navcore.papers.sp_scenario_wiring`), so every input keeps its full name
#: ``SP.missions.<name>``.
IN = InputSet("SP", "missions")

# --- published (Sec. 2.6) ----------------------------------------------------------------
IN.published(
    "first_carrier_loss_s",
    360.0,
    locator="Sec. 2.6.1 (Figs. 2.2-2.3)",
    unit="s",
    quantity="first carrier loss",
)
IN.published(
    "first_code_loss_s", 1020.0, locator="Sec. 2.6.1 (Figs. 2.2-2.3)", unit="s", quantity="first code loss"
)
IN.published(
    "loss_interval_min",
    3.0,
    locator="Sec. 2.6.1 ('forced at 3-min intervals')",
    unit="min",
    quantity="loss interval",
)
IN.published(
    "outage_min", 20.0, locator="Sec. 2.6.1 ('the 20-min blackout')", unit="min", quantity="total outage"
)
IN.published(
    "free_inertial_min",
    84.0,
    locator="Sec. 2.6.1 ('at the end of 84 min')",
    unit="min",
    quantity="free-inertial span",
)
IN.published(
    "headon_free_loose_s", 159.0, locator="Fig. 2.8", unit="s", quantity="LC free inertial before release"
)
IN.published(
    "headon_free_tight_s", 153.0, locator="Fig. 2.8", unit="s", quantity="TC free inertial before release"
)
IN.published(
    "helicopter_jammed_min", 19.0, locator="Sec. 2.6.4 ('another 19 min')", unit="min", quantity="jammed span"
)

# --- assumed: the unpublished inputs only these flights read (bands) ------------------------
IN.assumed(
    "headon_lc_pseudorange_noise_m",
    1.0,
    low=0.5,
    high=3.0,
    unit="m",
    quantity="pseudorange noise behind the position fix of the head-on mission's loosely coupled receiver",
    reason="Sec. 2.6.3 speaks of 'this particular loosely coupled system' and its receiver is not "
    "published; 0.5-3 m spans P(Y) code receivers of the period. The other missions' receivers read "
    "the white pseudorange noise of Table 2.4, itself assumed over the same range, whose effect "
    "each of their rows shows",
)
IN.assumed(
    "target_bearing_deg",
    45.0,
    low=0.0,
    high=180.0,
    grid=5,
    unit="deg",
    quantity="bearing (from north) of the helicopter's target, level, 8 km away",
    reason="Sec. 2.6.4 gives the distance (8 km), not the direction; the attitude error's "
    "contribution depends on it, so the band covers half a turn (the other half mirrors it); "
    "a grid because the response need not be monotone",
)
IN.convention(
    "velocity_step_pct",
    0.1,
    readings={"a change of more than 0.1 % across the 2 s": 0.1, "a change of more than 1 %": 1.0},
    unit="%",
    quantity="threshold of a step in the velocity error (its fall from 1 s before a code reacquisition "
    "to 1 s after it)",
    reason="Sec. 2.6.1 sees 'a step improvement in velocity' at each tightly coupled reacquisition and "
    "none in the loosely coupled system until the fourth code, but prints no size of a step; the "
    "book's 0.1 % stands against 1 %, both far below the loosely coupled step at the fourth code and "
    "above the change an error growing between fixes makes in 2 s",
)
IN.published(
    "headon_top_altitude_ft",
    40_000.0,
    locator="Sec. 2.6.3 ('the aircraft climbs to 40,000 ft')",
    unit="ft",
    quantity="head-on mission's climb altitude",
)
IN.published(
    "headon_low_altitude_ft",
    200.0,
    locator="Sec. 2.6.3 ('then dives down to 200 ft')",
    unit="ft",
    quantity="head-on mission's low-level altitude",
)
_HEADON = (
    "Sec. 2.6.3 describes the fighter-bomber's flight in words (climb to 40,000 ft, dodge a missile, "
    "dive to 200 ft, climb to a few thousand feet, release) without its speeds, angles or times; "
)
IN.assumed(
    "headon_takeoff_speed_mps",
    160.0,
    low=120.0,
    high=200.0,
    unit="m/s",
    quantity="head-on mission's speed at the start of its climb, after take-off (at 100 m)",
    reason=_HEADON + "a loaded fighter-bomber climbs out at 230-390 kn (120-200 m/s)",
)
IN.assumed(
    "headon_speed_mps",
    280.0,
    low=230.0,
    high=300.0,
    unit="m/s",
    quantity="head-on mission's speed after its accelerating climb, held to release",
    reason=_HEADON + "450-580 kn (230-300 m/s) spans the subsonic cruise and low-level penetration "
    "speeds of fighter-bombers",
)
IN.assumed(
    "headon_acceleration_mps2",
    2.0,
    low=1.0,
    high=4.0,
    unit="m/s²",
    quantity="head-on mission's acceleration from its take-off speed to its cruise speed, in the climb",
    reason=_HEADON + "0.1-0.4 g of longitudinal acceleration spans a fighter-bomber climbing at "
    "military to full power",
)
IN.assumed(
    "headon_climb_angle_deg",
    10.0,
    low=5.0,
    high=20.0,
    unit="deg",
    quantity="head-on mission's climb angle",
    reason=_HEADON + "5-20 deg spans a cruise climb to a steep climb of a loaded fighter-bomber",
)
IN.assumed(
    "headon_dive_angle_deg",
    15.0,
    low=10.0,
    high=30.0,
    unit="deg",
    quantity="head-on mission's dive angle (to the 200 ft of its low-level ingress)",
    reason=_HEADON + "10-30 deg spans a shallow to a steep descent of a fighter-bomber",
)
IN.assumed(
    "headon_pitch_rate_deg_s",
    0.5,
    low=0.25,
    high=1.0,
    unit="deg/s",
    quantity="head-on mission's rate of change of flight-path angle into and out of its climb and dive",
    reason=_HEADON + "0.25-1 deg/s spans gentle to brisk transitions (0.1-0.5 g of normal "
    "acceleration at 280 m/s)",
)
IN.assumed(
    "headon_cruise_s",
    300.0,
    low=120.0,
    high=600.0,
    unit="s",
    quantity="head-on mission's cruise at altitude before the missile",
    reason=_HEADON + "2-10 min at altitude before the missile is dodged",
)
IN.assumed(
    "headon_break_turn_deg_s",
    4.0,
    low=2.0,
    high=8.0,
    unit="deg/s",
    quantity="rate of the head-on mission's break turns (missile evasion)",
    reason=_HEADON + "2-8 deg/s spans the sustained turn rates of a fighter-bomber at 40,000 ft "
    "(bank about 50-80 deg at 280 m/s)",
)
IN.assumed(
    "headon_break_turn_deg",
    80.0,
    low=45.0,
    high=120.0,
    unit="deg",
    quantity="heading change of each of the head-on mission's two break turns (right, then back left)",
    reason=_HEADON + "dodging a missile is a hard turn off the course and back; 45-120 deg each way",
)
IN.assumed(
    "headon_ingress_s",
    600.0,
    low=300.0,
    high=1200.0,
    unit="s",
    quantity="head-on mission's low-level ingress (at 200 ft, before the pop-up)",
    reason=_HEADON + "5-20 min at low level spans an ingress of 80-340 km at 280 m/s",
)
IN.assumed(
    "headon_popup_angle_deg",
    10.0,
    low=5.0,
    high=20.0,
    unit="deg",
    quantity="flight-path angle of the head-on mission's pop-up",
    reason=_HEADON + "a pop-up to 'a few thousand feet' to find the target climbs at 5-20 deg",
)
IN.assumed(
    "headon_popup_pitch_rate_deg_s",
    1.0,
    low=0.5,
    high=2.0,
    unit="deg/s",
    quantity="rate of change of flight-path angle into and out of the head-on mission's pop-up",
    reason=_HEADON + "the pop-up is brisker than the transitions at altitude: 0.5-2 deg/s "
    "(0.25-1 g of normal acceleration at 280 m/s)",
)
IN.assumed(
    "headon_popup_hold_s",
    12.0,
    low=5.0,
    high=30.0,
    unit="s",
    quantity="head-on mission's time at its pop-up angle",
    reason=_HEADON + "with the pop-up angle's range, 5-30 s climbs to 'a few thousand feet' "
    "above the 200-ft ingress",
)
IN.assumed(
    "helicopter_speed_mps",
    40.0,
    low=20.0,
    high=60.0,
    unit="m/s",
    quantity="helicopter ground speed (terrain following)",
    reason="not published; nap-of-the-earth scout flight at 40-120 kn",
)
IN.assumed(
    "helicopter_undulation_period_s",
    60.0,
    low=30.0,
    high=120.0,
    unit="s",
    quantity="period of the helicopter's terrain-following undulation",
    reason="Sec. 2.6.4 says only that the scout flies nap-of-the-earth; at 20-60 m/s, hills 1-5 km "
    "apart give a swing every 30-120 s",
)
IN.assumed(
    "helicopter_path_angle_deg",
    4.0,
    low=2.0,
    high=8.0,
    unit="deg",
    quantity="amplitude of the helicopter's flight-path angle over one terrain-following undulation",
    reason="Sec. 2.6.4 says only that the scout 'closely follows the terrain' with 'high levels of "
    "acceleration and jerk'; at 40 m/s and a 60-s undulation $\\pm 4$ deg gives height swings of about "
    "$\\pm 25$ m; 2-8 deg spans gently rolling to hilly terrain",
)
IN.assumed(
    "helicopter_turn_rate_deg_s",
    3.0,
    low=1.5,
    high=6.0,
    unit="deg/s",
    quantity="rate of the helicopter's turns",
    reason="not published; 3 deg/s is the standard-rate (rate one) turn of instrument flight; half to "
    "twice that spans a gentle to a brisk turn of a scout at 20-60 m/s (bank 3-33 deg)",
)
IN.assumed(
    "helicopter_turn_interval_min",
    5.0,
    low=2.0,
    high=10.0,
    unit="min",
    quantity="time between the helicopter's turns (the first undulation's end after it)",
    reason="not published; a scout following valleys and tree lines changes course every few minutes; "
    "2-10 min over the book's 30-60 min of flight",
)
IN.assumed(
    "helicopter_calibration_min",
    30.0,
    low=15.0,
    high=60.0,
    unit="min",
    quantity="helicopter's GPS-aided flight before the jamming",
    reason="Sec. 2.6.4 keeps GPS 'until on-board estimates of IMU calibration and alignment had reached "
    "steady state', without a time; 15-60 min spans the settling of the filter's calibration states "
    "on the book's trajectory",
)


@dataclass(frozen=True)
class EngineInputs:
    """What the covariance engine is given for one tightly coupled system on the first
    seconds of the sequential outage (for writing one step of it out on the missions page)."""

    trajectory: Trajectory
    truth: StateLayout
    filter: StateLayout
    sources: ErrorSources
    P0: np.ndarray
    schedule: Callable
    filter_added_psd: np.ndarray


def engine_inputs(system: System, seconds: float) -> EngineInputs:
    """The tightly coupled ``system`` on the first ``seconds`` of the sequential-outage mission,
    every code and carrier tracked: its trajectory, truth and filter layouts, error sources,
    a-priori covariance, measurement schedule (pseudoranges and range rates at 1 Hz, the
    barometer) and the filter's tuning, exactly as :func:`sequential_outage` passes them to
    :func:`~navcore.integration.engine.run_covariance_analysis`."""
    if system.architecture != "tight":
        raise ValueError("system must be tightly coupled")
    tr_all = sequential_outage_trajectory(end_free_s())
    tr = trajectory_window(tr_all, 0.0, seconds)
    channels = _channels(end_free_s())
    truth = truth_layout(channels=len(channels))
    geo = satellite_geometry(tr, gps_constellation(), [int(c) for c in channels])
    lock = np.ones((len(tr), len(channels)), dtype=bool)
    every = max(1, round(sw.IN.baro_interval_s / tr.dt))
    src = error_sources(sp_imu_grade(system.grade), False)
    filt = tightly_coupled_layout()
    gps = tightly_coupled_schedule(
        truth,
        geo,
        lock,
        lock,
        pseudorange_noise=sw.IN.pseudorange_noise_m,
        range_rate_noise=sw.IN.range_rate_noise_mps,
        g_load=np.linalg.norm(tr.f_ned, axis=1) / G0,
    )
    baro = baro_schedule(truth, noise_m=tab.IN.barometer_noise_m, every=every)
    return EngineInputs(
        tr,
        truth,
        filt,
        src,
        _initial_covariance(truth, src, tr),
        combine_schedules(gps, baro),
        gravity_tuning_psd(filt, src, float(np.mean(tr.speed))),
    )


# ------------------------------------------------------------------ sequential outage


def sequential_outage_events(
    channels: int = 4,
    first_carrier_loss_s: float | None = None,
    first_code_loss_s: float | None = None,
    interval_s: float | None = None,
    outage_s: float | None = -1.0,
) -> list[tuple[float, int, str, bool]]:
    """Loss and reacquisition events of SP Sec. 2.6.1.

    Carriers are lost one by one at ``interval_s`` from ``first_carrier_loss_s``, codes from
    ``first_code_loss_s``; after ``outage_s`` of total outage the signals come back in the
    inverse order (codes first, last-lost first), at the same interval. ``outage_s=None``
    gives the free-inertial variant (no reacquisition). Times not given are the paper's
    (360 s, 1020 s, 3 min, 20 min: :data:`IN`).
    """
    if first_carrier_loss_s is None:
        first_carrier_loss_s = IN.first_carrier_loss_s
    if first_code_loss_s is None:
        first_code_loss_s = IN.first_code_loss_s
    if interval_s is None:
        interval_s = IN.loss_interval_min * MINUTE
    if outage_s is not None and outage_s < 0:
        outage_s = IN.outage_min * MINUTE
    ev = []
    for c in range(channels):
        ev.append((first_carrier_loss_s + c * interval_s, c, "carrier", False))
        ev.append((first_code_loss_s + c * interval_s, c, "code", False))
    if outage_s is not None:
        t0 = first_code_loss_s + (channels - 1) * interval_s + outage_s
        order = [(c, "code") for c in reversed(range(channels))] + [
            (c, "carrier") for c in reversed(range(channels))
        ]
        for j, (c, kind) in enumerate(order):
            ev.append((t0 + j * interval_s, c, kind, True))
    return ev


@input_cache
def sequential_outage_trajectory(duration_s: float) -> Trajectory:
    """Cruise at constant height and speed from the assumed heading, with a calibration turn
    every :data:`~navcore.papers.sp_scenario_wiring.IN` ``turn_interval_min``
    (:func:`~navcore.papers.sp_scenario_wiring.calibration_turns`: 90 deg every 10 min, alternating
    right and left, nominally), which makes heading and the gyro errors observable."""
    tr = fly(
        calibration_turns(duration_s),
        dt=sw.IN.step_s,
        lat0=sw.IN.latitude_deg * DEG,
        lon0=sw.IN.longitude_deg * DEG,
        h0=sw.IN.cruise_altitude_m,
        speed0=sw.IN.cruise_speed_mps,
        heading0=sw.IN.heading_deg * DEG,
    )
    n = round(duration_s / sw.IN.step_s) + 1
    return Trajectory(*(getattr(tr, f.name)[:n] for f in fields(tr)))


#: Duration of the sequential-outage mission with reacquisition (s): the extent of Figs. 2.2-2.4.
END_S = 104 * MINUTE


def last_code_loss_s() -> float:
    """Time of the fourth code loss (s): 1020 s + 3 x 3 min."""
    return IN.first_code_loss_s + 3 * IN.loss_interval_min * MINUTE


def reacquisition_s() -> float:
    """Time of the first reacquisition (s): the last code loss plus the 20-min outage."""
    return last_code_loss_s() + IN.outage_min * MINUTE


def end_free_s() -> float:
    """End of the free-inertial variant (s): 84 min after the last code loss."""
    return last_code_loss_s() + IN.free_inertial_min * MINUTE


def _phase(systems, tr_full, channels, t0, t1, step, events, resume, measure_last=False):
    """One phase of a mission from ``t0`` to ``t1``. Its last sample is the next phase's first,
    so its measurements belong to one of them only: to the next phase unless ``measure_last``
    (the mission's final phase), so that nothing is applied twice at a boundary and a
    reacquisition at the boundary belongs to the phase that has it."""
    tr = trajectory_window(tr_full, t0, t1, step)
    code, carrier = lock_table(tr.t, len(channels), events)
    return _run(systems, tr, code, carrier, channels, resume=resume, measure_last=measure_last)


def _group(architecture: str) -> tuple[System, ...]:
    return tuple(s for s in SYSTEMS if s.architecture == architecture)


def _channel_key(channels: np.ndarray) -> tuple[int, ...]:
    return tuple(int(c) for c in channels)


@input_cache
def _sequential_common_on(
    architecture: str, channel_key: tuple[int, ...]
) -> tuple[Trajectory, np.ndarray, dict, dict]:
    tr = sequential_outage_trajectory(end_free_s())
    channels = np.array(channel_key)
    ev = sequential_outage_events(len(channels))
    group = _group(architecture)
    a = _phase(group, tr, channels, 0.0, last_code_loss_s(), 1, ev, None)
    b = _phase(group, tr, channels, last_code_loss_s(), reacquisition_s(), 1, ev, a)
    return tr, channels, a, b


def scale_initial_errors(
    position_velocity: float = 1.0, misalignment: float = 1.0, clock_offset_m: float | None = None
) -> AprioriTransform:
    """An a-priori transform: the Table 2.4 initial position and velocity errors scaled by
    ``position_velocity`` and the gyrocompass misalignment by ``misalignment`` (the rows and
    columns of each block, so their correlations with the instrument errors scale too), and the
    initial clock offset set to ``clock_offset_m`` (1 sigma) if given."""

    def f(P: np.ndarray, lay: StateLayout) -> np.ndarray:
        d = np.ones(lay.size)
        for block in ("position", "velocity"):
            d[lay.slice(block)] = position_velocity
        d[lay.slice("misalignment")] = misalignment
        out = P * np.outer(d, d)
        if clock_offset_m is not None:
            i = lay.index("clock bias")
            out[i, :] = out[:, i] = 0.0
            out[i, i] = clock_offset_m**2
        return out

    return f


#: Members of :func:`initial_error_runs`: name -> (position/velocity factor, misalignment factor,
#: clock-offset reading), the factors given as powers of the check's scale.
INITIAL_ERROR_MEMBERS: dict[str, tuple[int, int, str | None]] = {
    "nominal": (0, 0, None),
    "initial errors up": (1, 1, None),
    "initial errors down": (-1, -1, None),
    "misalignment up": (0, 1, None),
    "misalignment down": (0, -1, None),
    "clock offset in ns": (0, 0, "ns"),
}


@input_cache
def initial_error_runs(scale: float) -> dict[str, CovarianceAnalysis]:
    """The tightly coupled 1 nmi/h system through the sequential outage to reacquisition
    (2760 s), once per :data:`INITIAL_ERROR_MEMBERS` entry in one batched run: the Table 2.4
    initial position, velocity and misalignment errors multiplied and divided by ``scale``, the
    misalignment alone, and the clock offset of Table 2.4 read as 5000 ns (1499 m) instead of
    5000 m (Sec. 2.3, Sec. 2.4, Table 2.4)."""
    from navcore.units import C

    tr = sequential_outage_trajectory(end_free_s())
    channels = _channels(end_free_s())
    ev = sequential_outage_events(len(channels))
    system = System("tight", 1.0)
    names = list(INITIAL_ERROR_MEMBERS)
    transforms = tuple(
        scale_initial_errors(
            scale**pv, scale**mis, None if clock is None else tab.IN.clock_initial_offset_m * 1e-9 * C
        )
        for pv, mis, clock in INITIAL_ERROR_MEMBERS.values()
    )
    systems = (system,) * len(names)
    parts: list[list[CovarianceAnalysis]] = []
    for t0, t1 in ((0.0, last_code_loss_s()), (last_code_loss_s(), reacquisition_s())):
        trp = trajectory_window(tr, t0, t1)
        code, carrier = lock_table(trp.t, len(channels), ev)
        parts.append(
            _run_list(
                systems,
                trp,
                code,
                carrier,
                channels,
                resume=parts[-1] if parts else None,
                transforms=transforms,
                measure_last=bool(parts),  # the boundary's measurements belong to the second part
            )
        )
    return {n: concatenate_analyses([a, b]) for n, a, b in zip(names, *parts, strict=True)}


@input_cache
def _sequential_group(architecture: str, free_inertial: bool) -> dict[System, CovarianceAnalysis]:
    return _sequential_group_on(architecture, free_inertial, _channel_key(_channels(end_free_s())))


@input_cache
def _sequential_group_on(
    architecture: str, free_inertial: bool, channel_key: tuple[int, ...]
) -> dict[System, CovarianceAnalysis]:
    tr, channels, a, b = _sequential_common_on(architecture, channel_key)
    ev = sequential_outage_events(len(channels), outage_s=None if free_inertial else -1.0)
    end = end_free_s() if free_inertial else END_S
    c = _phase(_group(architecture), tr, channels, reacquisition_s(), end, 1, ev, b, measure_last=True)
    return {s: concatenate_analyses([a[s], b[s], c[s]]) for s in _group(architecture)}


def sequential_outage(
    free_inertial: bool = False, architecture: str | None = None
) -> dict[System, CovarianceAnalysis]:
    """Run the sequential outage for the five systems (or those of one ``architecture``):
    the 20-min outage with reacquisition (to 104 min) or, with ``free_inertial``, 84 min
    without GPS after the last code loss.

    Each architecture runs (and is cached) separately, so a claim about the tightly coupled
    systems reads only their inputs; the two variants share the mission up to reacquisition."""
    archs = ("loose", "tight") if architecture is None else (architecture,)
    out: dict[System, CovarianceAnalysis] = {}
    for arch in archs:
        out.update(_sequential_group(arch, free_inertial))
    return {s: out[s] for s in SYSTEMS if s in out}


@input_cache
def _channels(duration: float) -> np.ndarray:
    return best_geometry_channels(
        sequential_outage_trajectory(duration),
        gps_constellation(),
        sw.IN.channels,
        sw.IN.mask_deg,
    )


@input_cache
def unaided_after_ground_alignment(initial_position: bool = True) -> dict[System, CovarianceAnalysis]:
    """The tightly coupled systems flying the sequential-outage trajectory for 84 min with no
    GPS at all, from the ground alignment: Table 2.4 initial errors and gyrocompass attitude
    (``initial_position=False`` removes the 600 m horizontal position error)."""
    tr = sequential_outage_trajectory(IN.free_inertial_min * MINUTE)
    channels = _channels(end_free_s())
    ev = [(0.0, c, k, False) for c in range(len(channels)) for k in ("code", "carrier")]
    code, carrier = lock_table(tr.t, len(channels), ev)
    return _run(_group("tight"), tr, code, carrier, channels, initial_position=initial_position)


# ------------------------------------------------------------------ head-on approach


#: Height (m) at which the head-on mission's profile starts (just after take-off).
HEAD_ON_START_HEIGHT_M = 100.0


def head_on_segments() -> list[Segment]:
    """The head-on mission's profile (SP Sec. 2.6.3) from the inputs of :data:`IN`: after
    take-off, pitch up to the climb angle, accelerate to the cruise speed in the climb, climb to
    the printed 40,000 ft and level off, cruise, break turn right and back left (missile
    evasion), push over into the dive, pull out at the printed 200 ft, fly the low-level
    ingress, pop up and run in to release. The climb and the dive last as long as it takes to
    reach the printed altitudes, and the pop-up starts when the loosely coupled receiver loses
    lock, ``headon_free_loose_s`` (159 s, Fig. 2.8) before release: the jammer at the target
    'overwhelms all variations ... as soon as the aircraft climbs above its horizon'.

    Raises
    ------
    ModelDomainError
        If the assumed speeds, acceleration and angles reach the printed altitudes before the
        straight climb or dive starts, the cruise speed is below the take-off speed, or the
        pop-up outlasts the free-inertial span.
    """
    a = IN
    pitch = a.headon_pitch_rate_deg_s * DEG
    climb, dive = a.headon_climb_angle_deg * DEG, a.headon_dive_angle_deg * DEG
    v0, v, acc = a.headon_takeoff_speed_mps, a.headon_speed_mps, a.headon_acceleration_mps2
    top, low = a.headon_top_altitude_ft * FT, a.headon_low_altitude_ft * FT
    accelerate_s = (v - v0) / acc
    # height gained by the pitch-up at v0 and the level-off at v (an arc at constant speed and
    # pitch rate: V / q (1 - cos gamma)) and by the accelerating climb (sin gamma (v0 T + a T^2/2))
    arcs_climb = (v0 + v) / pitch * (1.0 - np.cos(climb))
    accelerating = np.sin(climb) * (v0 * accelerate_s + 0.5 * acc * accelerate_s**2)
    climb_s = (top - HEAD_ON_START_HEIGHT_M - arcs_climb - accelerating) / (v * np.sin(climb))
    dive_s = (top - low - 2.0 * v / pitch * (1.0 - np.cos(dive))) / (v * np.sin(dive))
    popup_rate = a.headon_popup_pitch_rate_deg_s * DEG
    popup_s = 2.0 * a.headon_popup_angle_deg * DEG / popup_rate + a.headon_popup_hold_s
    run_in_s = a.headon_free_loose_s - popup_s
    if min(accelerate_s, climb_s, dive_s, run_in_s) < 0.0:
        raise ModelDomainError(
            f"the head-on profile cannot be flown: acceleration {accelerate_s:.0f} s, straight climb "
            f"{climb_s:.0f} s, dive {dive_s:.0f} s, run-in {run_in_s:.0f} s (headon_* inputs)",
            case="the assumed speeds and angles reach the printed altitudes before the straight climb or "
            "dive, or the pop-up outlasts the free-inertial span",
        )
    turn_s = a.headon_break_turn_deg / a.headon_break_turn_deg_s
    turn = a.headon_break_turn_deg_s * DEG
    return [
        Segment(climb / pitch, path_angle_rate=pitch),  # pitch up into the climb
        Segment(accelerate_s, speed_rate=acc),  # accelerate in the climb
        Segment(float(climb_s)),  # climb to 40,000 ft
        Segment(climb / pitch, path_angle_rate=-pitch),  # level off
        Segment(a.headon_cruise_s),  # cruise
        Segment(turn_s, turn_rate=turn),  # break turn (missile evasion)
        Segment(turn_s, turn_rate=-turn),
        Segment(dive / pitch, path_angle_rate=-pitch),  # push over into the dive
        Segment(float(dive_s)),  # dive
        Segment(dive / pitch, path_angle_rate=pitch),  # pull out at 200 ft
        Segment(a.headon_ingress_s),  # low-level ingress
        Segment(a.headon_popup_angle_deg * DEG / popup_rate, path_angle_rate=popup_rate),  # pop-up
        Segment(a.headon_popup_hold_s),
        Segment(a.headon_popup_angle_deg * DEG / popup_rate, path_angle_rate=-popup_rate),
        Segment(run_in_s),  # run in to release
    ]


def head_on_trajectory() -> Trajectory:
    """Take-off climb to 40,000 ft, a missile-evasion turn, dive to 200 ft, low-level
    ingress, pop-up climb to a few thousand feet and release (:func:`head_on_segments`), from
    the assumed heading."""
    a = IN
    return fly(
        head_on_segments(),
        dt=sw.IN.step_s,
        lat0=sw.IN.latitude_deg * DEG,
        lon0=sw.IN.longitude_deg * DEG,
        h0=HEAD_ON_START_HEIGHT_M,
        speed0=a.headon_takeoff_speed_mps,
        heading0=sw.IN.heading_deg * DEG,
    )


@input_cache
def head_on_approach(
    architecture: str, free_inertial_s: float | None = None
) -> dict[System, CovarianceAnalysis]:
    """All satellites lost together ``free_inertial_s`` before the end (bomb release), for
    the systems of :data:`SYSTEMS` with the given architecture (default: the paper's 159 s
    loosely coupled, 153 s tightly coupled, Fig. 2.8)."""
    if free_inertial_s is None:
        free_inertial_s = IN.headon_free_loose_s if architecture == "loose" else IN.headon_free_tight_s
    tr = head_on_trajectory()
    channels = best_geometry_channels(tr, gps_constellation(), sw.IN.channels, sw.IN.mask_deg)
    return _head_on_on(architecture, free_inertial_s, _channel_key(channels))


@input_cache
def _head_on_on(
    architecture: str, free_inertial_s: float, channel_key: tuple[int, ...]
) -> dict[System, CovarianceAnalysis]:
    tr = head_on_trajectory()
    channels = np.array(channel_key)
    t_loss = tr.t[-1] - free_inertial_s
    ev = [(t_loss, c, k, False) for c in range(len(channels)) for k in ("code", "carrier")]
    code, carrier = lock_table(tr.t, len(channels), ev)
    noise = IN.headon_lc_pseudorange_noise_m if architecture == "loose" else None
    return _run(_group(architecture), tr, code, carrier, channels, lc_pseudorange_noise_m=noise)


# ------------------------------------------------------------------ helicopter


def _helicopter_segments(duration_s: float) -> tuple[list[Segment], np.ndarray]:
    """The helicopter's segments covering ``duration_s`` and the start time (s) of each
    undulation, which begins with a pull-up."""
    a = IN
    period_s = a.helicopter_undulation_period_s
    swing = (1.0, -1.0, -1.0, 1.0)  # the flight-path angle's rate over the quarters of one undulation
    quarter_s = period_s / len(swing)
    pitch_rate = a.helicopter_path_angle_deg / quarter_s * DEG
    turn_rate = a.helicopter_turn_rate_deg_s
    turn_s = sw.IN.turn_angle_deg / turn_rate
    interval_s = a.helicopter_turn_interval_min * MINUTE
    segs: list[Segment] = []
    starts: list[float] = []
    t = 0.0
    sign = 1.0
    since_turn = 0  # undulations flown since the last turn
    while t < duration_s:
        starts.append(t)
        for rate in swing:
            segs.append(Segment(quarter_s, path_angle_rate=rate * pitch_rate))
        t += period_s
        since_turn += 1
        if since_turn * period_s >= interval_s:
            segs.append(Segment(turn_s, turn_rate=sign * turn_rate * DEG))
            sign = -sign
            t += turn_s
            since_turn = 0
    return segs, np.array(starts)


def helicopter_trajectory(duration_s: float) -> Trajectory:
    """Terrain following at constant ground speed from the assumed heading: the flight-path
    angle swings by :data:`IN` ``helicopter_path_angle_deg`` (4 deg) either way with the assumed
    undulation period (60 s: height changes of about +-25 m), and at the end of the first
    undulation after each ``helicopter_turn_interval_min`` (5 min) the helicopter turns by
    ``turn_angle_deg`` (90 deg) at ``helicopter_turn_rate_deg_s`` (3 deg/s), alternately right
    and left."""
    a = IN
    segs, _ = _helicopter_segments(duration_s)
    tr = fly(
        segs,
        dt=sw.IN.step_s,
        lat0=sw.IN.latitude_deg * DEG,
        lon0=sw.IN.longitude_deg * DEG,
        h0=100.0,
        speed0=a.helicopter_speed_mps,
        heading0=sw.IN.heading_deg * DEG,
    )
    n = round(duration_s / sw.IN.step_s) + 1
    return Trajectory(*(getattr(tr, f.name)[:n] for f in fields(tr)))


def helicopter_pull_ups(t: np.ndarray, loss_s: float) -> np.ndarray:
    """Samples of the times ``t`` (s) within ``loss_s`` of the start of an undulation (the start
    of a terrain pull-up) of :func:`helicopter_trajectory`, the start of the flight excluded."""
    t = np.asarray(t, dtype=float)
    _, starts = _helicopter_segments(float(t[-1]))
    k = np.searchsorted(starts, t, side="right") - 1
    return (t - starts[k] < loss_s) & (t > 0.0)


@input_cache
def helicopter(doppler: bool) -> dict[float, CovarianceAnalysis]:
    """Tightly coupled helicopter: GPS until calibration reaches steady state
    (``helicopter_calibration_min``), then 19 min jammed; Doppler throughout if ``doppler``."""
    a = IN
    calibration_min = a.helicopter_calibration_min
    duration = (calibration_min + IN.helicopter_jammed_min) * MINUTE
    tr = helicopter_trajectory(duration)
    channels = best_geometry_channels(tr, gps_constellation(), sw.IN.channels, sw.IN.mask_deg)
    return _helicopter_on(doppler, 0.0, _channel_key(channels))


@input_cache
def _helicopter_on(
    doppler: bool, loss_s: float, channel_key: tuple[int, ...]
) -> dict[float, CovarianceAnalysis]:
    """The helicopter on the satellites ``channel_key``; ``loss_s > 0`` drops every carrier for
    that long at the start of each terrain pull-up (:func:`helicopter_pull_ups`) while GPS is
    tracked."""
    calibration_min = IN.helicopter_calibration_min
    duration = (calibration_min + IN.helicopter_jammed_min) * MINUTE
    tr = helicopter_trajectory(duration)
    channels = np.array(channel_key)
    t_loss = calibration_min * MINUTE
    ev = [(t_loss, c, k, False) for c in range(len(channels)) for k in ("code", "carrier")]
    code, carrier = lock_table(tr.t, len(channels), ev)
    if loss_s > 0.0:
        carrier = carrier & ~helicopter_pull_ups(tr.t, loss_s)[:, None]
    res = _run((System("tight", 10.0), System("tight", 1.0)), tr, code, carrier, channels, doppler=doppler)
    return {s.grade: r for s, r in res.items()}


@input_cache
def helicopter_momentary_carrier_loss(loss_s: float) -> dict[float, CovarianceAnalysis]:
    """The helicopter without Doppler (Sec. 2.6.4) with every carrier dropped for ``loss_s`` at
    the start of each terrain pull-up while GPS is tracked (once an undulation): the "occasional
    momentary loss of carrier lock" imposed, to compare with :func:`helicopter`."""
    a = IN
    calibration_min = a.helicopter_calibration_min
    duration = (calibration_min + IN.helicopter_jammed_min) * MINUTE
    tr = helicopter_trajectory(duration)
    channels = best_geometry_channels(tr, gps_constellation(), sw.IN.channels, sw.IN.mask_deg)
    return _helicopter_on(False, loss_s, _channel_key(channels))


def target_location_sigma(
    result: CovarianceAnalysis, range_m: float | None = None, bearing_deg: float | None = None
) -> float:
    """rss 1-sigma horizontal target-location error at the end of ``result``.

    SP Sec. 2.6.4: :math:`\\delta r_{tgt} = \\delta r + \\delta\\alpha \\times r` with the target
    ``range_m`` away (default the paper's 8 km) at ``bearing_deg`` from north (default the
    assumed 45 deg, the north-east diagonal), level, using the full end covariance of position
    and attitude error.

    The engine's attitude error is the psi angle, :math:`\\hat C = (I - [\\psi\\times])C`; the
    paper's formula reads :math:`\\delta\\alpha` with the opposite sign (:math:`\\hat C r^b = r +
    \\delta\\alpha\\times r`), so the covariance is converted (:math:`\\delta\\alpha = -\\psi`) before
    it enters :func:`~navcore.location.target_location.target_location_covariance`: the located
    target is in error by :math:`\\delta r - \\psi\\times r`.
    """
    from navcore.inertial.error_dynamics import psi_to_attitude_error
    from navcore.location.target_location import target_location_covariance

    if range_m is None:
        range_m = spa.IN.target_range_m  # Sec. 2.6.4 '(8 km)', declared with the acquisition claims
    if bearing_deg is None:
        bearing_deg = IN.target_bearing_deg
    b = np.radians(bearing_deg)
    P = next(iter(result.snapshots.values()))
    lay = result.truth_layout
    T = psi_to_attitude_error(lay)
    P = T @ P @ T  # psi -> dalpha = -psi
    p, a = lay.slice("position"), lay.slice("misalignment")
    r = range_m * np.array([np.cos(b), np.sin(b), 0.0])
    Pt = target_location_covariance(P[p, p], P[a, a], r, P[p, a])
    return float(np.sqrt(Pt[0, 0] + Pt[1, 1]))
