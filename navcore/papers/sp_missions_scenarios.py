"""SP Section 2.6 missions set up for the covariance-analysis engine.

The paper publishes the error budgets (Tables 2.4, 2.5, 2.8), the filter state vectors
(Tables 2.2, 2.3), the measurement rules (Sec. 2.1-2.2) and the event times of the
sequential outage, but not the trajectories, the satellite geometry, the receiver noise, the
clock model or the jammer. Every such input is collected in :class:`Assumptions` with the
value used here; the book prints it next to each figure.

Nothing here is a model: the models are :mod:`navcore.inertial.error_dynamics` and
:mod:`navcore.estimation.covariance_analysis`. This module only wires the paper's inputs
into them.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from navcore.estimation.covariance_analysis import (
    CovarianceAnalysis,
    baro_schedule,
    best_geometry_channels,
    combine_schedules,
    concatenate_analyses,
    doppler_schedule,
    lock_table,
    loosely_coupled_schedule,
    run_covariance_analysis,
    satellite_geometry,
    tightly_coupled_schedule,
)
from navcore.estimation.layout import StateLayout
from navcore.gnss.architectures import loosely_coupled_layout, tightly_coupled_layout
from navcore.gnss.constellation import nominal_gps_constellation
from navcore.inertial.error_dynamics import (
    ClockModel,
    ErrorSources,
    GaussMarkov,
    gyrocompass_alignment,
    initial_covariance,
    ins_error_layout,
)
from navcore.inertial.imu import ImuSpec
from navcore.inertial.trajectories import Segment, Trajectory, fly
from navcore.ledger import input_cache
from navcore.ledger.inputs import InputSet
from navcore.papers import sp_acquisition as spa
from navcore.papers import sp_tables as tab
from navcore.papers.sp_tables import (
    DopplerErrorModel,
    barometer_markov,
    gravity_markov,
    sp_imu_grade,
    table_2_8,
)
from navcore.units import DEG, G0, MINUTE

__all__ = [
    "ASSUMED",
    "IN",
    "SYSTEMS",
    "Assumptions",
    "System",
    "error_sources",
    "head_on_approach",
    "head_on_trajectory",
    "helicopter",
    "helicopter_trajectory",
    "sequential_outage",
    "sequential_outage_events",
    "sequential_outage_trajectory",
    "target_location_sigma",
    "truth_layout",
    "unaided_after_ground_alignment",
]


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

# --- assumed: the few unpublished inputs that move the claims (bands) -----------------------
IN.assumed(
    "turn_rate_deg_s",
    1.5,
    low=0.75,
    high=3.0,
    unit="deg/s",
    quantity="rate of the 90-deg calibration turns of the sequential-outage cruise",
    reason="the paper gives no trajectory; the turns make heading and the gyro errors observable "
    "(how well they are calibrated sets the free-inertial growth). 1.5 deg/s is a standard-rate "
    "turn for a transport; half to twice that covers a gentle to a brisk turn",
)
IN.assumed(
    "headon_lc_pseudorange_noise_m",
    1.0,
    low=0.5,
    high=3.0,
    unit="m",
    quantity="pseudorange noise behind the position fix of the head-on mission's loosely coupled receiver",
    reason="Sec. 2.6.3 speaks of 'this particular loosely coupled system' and its receiver is not "
    "published; 0.5-3 m spans P(Y) code receivers of the period. Elsewhere the pseudorange noise "
    "is fixed at 1 m: it moves no other claim (the 84-min 1 nmi/h error is 883-886 m for 0.5-3 m)",
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
IN.assumed(
    "doppler_noise_mps",
    0.1,
    low=0.03,
    high=0.3,
    unit="m/s",
    quantity="white noise of the Doppler ground-speed sensor, per axis and 1-s sample",
    reason="Table 2.8 gives bias, scale factor and misalignment but no noise; 0.03-0.3 m/s per "
    "second spans Doppler velocity sensors of the period",
)


@dataclass(frozen=True)
class Assumptions:
    """Scenario design the paper does not publish, fixed in this book (printed on the page).

    They define the scenarios rather than enter the ledger as inputs: the assumed inputs that
    move the claims are declared in :data:`IN` with their ranges.
    """

    latitude_deg: float = 35.0
    longitude_deg: float = -117.0
    cruise_altitude_m: float = 7000.0
    cruise_speed_mps: float = 200.0
    pseudorange_noise_m: float = 1.0
    range_rate_noise_mps: float = 0.05
    clock_bias_psd_m2_s: float = 0.0036
    clock_drift_psd_m2_s3: float = 7.1e-5
    channels: int = 4
    mask_deg: float = 10.0
    step_s: float = 1.0
    helicopter_speed_mps: float = 40.0
    helicopter_calibration_min: float = 30.0
    baro_interval_s: float = 10.0

    def table(self) -> list[tuple[str, float]]:
        """``[(field, value), ...]`` for printing."""
        return [(f.name, getattr(self, f.name)) for f in fields(self)]


ASSUMED = Assumptions()


@dataclass(frozen=True)
class System:
    """A navigation system of Sec. 2.6: architecture and IMU quality (nmi/h)."""

    architecture: str  # "loose" or "tight"
    grade: float

    @property
    def label(self) -> str:
        return f"{'LC' if self.architecture == 'loose' else 'TC'} {self.grade:g} nmi/h"


#: The five systems of Figs. 2.4-2.8: the loosely coupled 1 nmi/h and four tightly coupled.
SYSTEMS: tuple[System, ...] = (
    System("loose", 1.0),
    System("tight", 10.0),
    System("tight", 1.0),
    System("tight", 0.5),
    System("tight", 0.2),
)


def _final(covariance: np.ndarray | None) -> np.ndarray:
    """A run's final covariance, which a resumed phase starts from (every run keeps one)."""
    if covariance is None:
        raise ValueError("the previous phase kept no final covariance to resume from")
    return covariance


def truth_layout(*, doppler: bool = False, channels: int = ASSUMED.channels) -> StateLayout:
    """Truth states: the 24 tightly coupled states plus everything Table 2.4/2.5 lists that
    the filters do not carry (instrument misalignments, gravity anomaly, clock
    g-sensitivity, per-channel pseudorange and range-rate biases, Doppler errors)."""
    extra = [
        "gyro misalignment",
        "accel misalignment",
        "gravity",
        "clock g-sensitivity",
        "pseudorange bias",
        "range-rate bias",
    ]
    if doppler:
        extra += ["doppler bias", "doppler scale factor", "doppler misalignment"]
    return StateLayout(
        tightly_coupled_layout().blocks + ins_error_layout(*extra, channels=channels).blocks, "truth"
    )


def error_sources(spec: ImuSpec, doppler: bool = True) -> ErrorSources:
    """Table 2.4 (INS-independent) and Table 2.8 errors around one Table 2.5 instrument
    (``doppler=False``: without the Doppler sensor, whose Table 2.8 errors are then not read)."""
    t = tab.table_2_4()
    grav, baro = gravity_markov(), barometer_markov()
    dop = table_2_8() if doppler else DopplerErrorModel(0.0, 0.0, 0.0, 0.0, 0.0)
    return ErrorSources(
        imu=spec,
        gravity=GaussMarkov(grav.sigma, grav.distance_constant_m),
        altimeter=GaussMarkov(baro.sigma, baro.distance_constant_m),
        clock=ClockModel(
            bias_sigma=t["clock initial offset"].si,
            drift_sigma=t["clock initial drift"].si,
            g_sensitivity_sigma=t["clock g-sensitive drift"].si,
            bias_psd=ASSUMED.clock_bias_psd_m2_s,
            drift_psd=ASSUMED.clock_drift_psd_m2_s3,
        ),
        pseudorange_bias_sigma=t["pseudorange bias"].si,
        range_rate_bias_sigma=t["range-rate bias"].si,
        doppler_bias=(dop.bias_horizontal, dop.bias_horizontal, dop.bias_vertical),
        doppler_scale_factor=(
            dop.scale_factor_horizontal,
            dop.scale_factor_horizontal,
            dop.scale_factor_vertical,
        ),
        doppler_misalignment=dop.misalignment,
    )


def _gravity_tuning(filt: StateLayout, sources: ErrorSources, speed: float) -> np.ndarray:
    """Filter tuning for the unmodelled gravity anomaly: white acceleration noise with the
    low-frequency PSD ``2 sigma^2 tau`` of the Gauss-Markov process (``tau = d / v``)."""
    q = np.zeros(filt.size)
    gm = sources.gravity
    if gm is not None and speed > 0:
        q[filt.slice("velocity")] = 2 * gm.sigma**2 * gm.distance_constant_m / speed
    return q


def _initial_covariance(truth: StateLayout, sources: ErrorSources, tr: Trajectory) -> np.ndarray:
    t = tab.table_2_4()
    ph = t["initial position (horizontal)"].si
    P0 = initial_covariance(
        truth,
        sources,
        position_sigma=(ph, ph, t["initial position (vertical)"].si),
        velocity_sigma=(t["initial velocity"].si,) * 3,
    )
    return gyrocompass_alignment(P0, truth, lat=float(tr.lat[0]), C_bn=tr.C_bn[0])


def _slice(tr: Trajectory, t0: float, t1: float, step: int = 1) -> Trajectory:
    """Samples of ``tr`` from ``t0`` to ``t1`` (inclusive), every ``step``-th."""
    i0 = int(np.argmin(np.abs(tr.t - t0)))
    i1 = int(np.argmin(np.abs(tr.t - t1)))
    sl = slice(i0, i1 + 1, step)
    return Trajectory(*(getattr(tr, f.name)[sl] for f in fields(tr)))


def _run(
    systems: tuple[System, ...],
    tr: Trajectory,
    code: np.ndarray,
    carrier: np.ndarray,
    channels: np.ndarray,
    *,
    doppler: bool = False,
    snapshots: tuple[int, ...] = (-1,),
    resume: dict[System, CovarianceAnalysis] | None = None,
    initial_position: bool = True,
    lc_pseudorange_noise_m: float | None = None,
) -> dict[System, CovarianceAnalysis]:
    """Run several systems on one trajectory and lock table (one batched pass per
    architecture), from the mission start or resuming from ``resume``'s final covariances.
    ``initial_position=False`` starts without horizontal position error;
    ``lc_pseudorange_noise_m`` replaces the loosely coupled receiver's pseudorange noise."""
    out: dict[System, CovarianceAnalysis] = {}
    truth = truth_layout(doppler=doppler, channels=len(channels))
    geo = satellite_geometry(tr, nominal_gps_constellation(), [int(c) for c in channels])
    every = max(1, round(ASSUMED.baro_interval_s / tr.dt))
    baro = baro_schedule(truth, noise_m=tab.IN.barometer_noise_m, every=every)
    dop = doppler_schedule(truth, tr, noise_mps=IN.doppler_noise_mps) if doppler else None
    for arch in ("loose", "tight"):
        group = [s for s in systems if s.architecture == arch]
        if not group:
            continue
        sources = [error_sources(sp_imu_grade(s.grade), doppler) for s in group]
        filt = loosely_coupled_layout() if arch == "loose" else tightly_coupled_layout()
        if doppler:
            filt = StateLayout(
                filt.blocks + ins_error_layout("doppler bias", "doppler scale factor").blocks, filt.name
            )
        if arch == "loose":
            gps = loosely_coupled_schedule(
                truth,
                geo,
                code,
                pseudorange_noise=(
                    ASSUMED.pseudorange_noise_m if lc_pseudorange_noise_m is None else lc_pseudorange_noise_m
                ),
                pseudorange_bias_sigma=sources[0].pseudorange_bias_sigma,
            )
        else:
            gps = tightly_coupled_schedule(
                truth,
                geo,
                code,
                carrier,
                pseudorange_noise=ASSUMED.pseudorange_noise_m,
                range_rate_noise=ASSUMED.range_rate_noise_mps,
                g_load=np.linalg.norm(tr.f_ned, axis=1) / G0,
            )
        apriori = np.stack([_initial_covariance(truth, src, tr) for src in sources])
        if resume is None:
            P0, Pf0 = apriori.copy(), None
            if not initial_position:
                for i in range(2):
                    j = truth.index("position", i)
                    P0[:, j, :] = 0.0
                    P0[:, :, j] = 0.0
        else:
            P0 = np.stack([_final(resume[s].final_true) for s in group])
            Pf0 = np.stack([_final(resume[s].final_filter) for s in group])
        steps = np.zeros(len(tr), dtype=bool)
        steps[::every] = True  # barometer
        if arch == "loose":
            steps[::10] = True
        else:
            steps |= (code | carrier).any(axis=1)
        if doppler:
            steps[:] = True
        res = run_covariance_analysis(
            tr,
            truth,
            filt,
            sources,
            P0,
            combine_schedules(gps, baro, dop),
            snapshots=snapshots,
            P0_filter=Pf0,
            P0_apriori=apriori,
            measurement_steps=steps,
            filter_added_psd=_gravity_tuning(filt, sources[0], float(np.mean(tr.speed))),
        )
        assert isinstance(res, list)  # a stack of initial covariances gives one run each
        out.update(zip(group, res, strict=True))
    return out


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
    """Cruise at constant height and speed with a 90-degree coordinated turn every 10 min
    (alternating left and right), which makes heading and the gyro errors observable."""
    a = ASSUMED
    rate = IN.turn_rate_deg_s
    turn_s = 90.0 / rate
    segs: list[Segment] = [Segment(240.0)]
    t = 240.0
    sign = 1.0
    while t < duration_s:
        segs.append(Segment(turn_s, turn_rate=sign * rate * DEG))
        segs.append(Segment(600.0 - turn_s))
        t += 600.0
        sign = -sign
    tr = fly(
        segs,
        dt=a.step_s,
        lat0=a.latitude_deg * DEG,
        lon0=a.longitude_deg * DEG,
        h0=a.cruise_altitude_m,
        speed0=a.cruise_speed_mps,
    )
    n = round(duration_s / a.step_s) + 1
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


def _phase(systems, tr_full, channels, t0, t1, step, events, resume):
    tr = _slice(tr_full, t0, t1, step)
    code, carrier = lock_table(tr.t, len(channels), events)
    return _run(systems, tr, code, carrier, channels, resume=resume)


def _group(architecture: str) -> tuple[System, ...]:
    return tuple(s for s in SYSTEMS if s.architecture == architecture)


@input_cache
def _sequential_common(architecture: str) -> tuple[Trajectory, np.ndarray, dict, dict]:
    tr = sequential_outage_trajectory(end_free_s())
    channels = _channels(end_free_s())
    ev = sequential_outage_events(len(channels))
    group = _group(architecture)
    a = _phase(group, tr, channels, 0.0, last_code_loss_s(), 1, ev, None)
    b = _phase(group, tr, channels, last_code_loss_s(), reacquisition_s(), 1, ev, a)
    return tr, channels, a, b


@input_cache
def _sequential_group(architecture: str, free_inertial: bool) -> dict[System, CovarianceAnalysis]:
    tr, channels, a, b = _sequential_common(architecture)
    ev = sequential_outage_events(len(channels), outage_s=None if free_inertial else -1.0)
    end = end_free_s() if free_inertial else END_S
    c = _phase(_group(architecture), tr, channels, reacquisition_s(), end, 1, ev, b)
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
        nominal_gps_constellation(),
        ASSUMED.channels,
        ASSUMED.mask_deg,
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


def head_on_trajectory() -> Trajectory:
    """Take-off climb to 40,000 ft, a missile-evasion turn, dive to 200 ft, low-level
    ingress, pop-up climb to about 3,000 ft and release (times in :data:`HEAD_ON_TIMES`)."""
    a = ASSUMED
    segs = [
        Segment(20.0, path_angle_rate=0.5 * DEG),  # rotate to a 10 deg climb
        Segment(60.0, speed_rate=2.0),  # accelerate in the climb
        Segment(183.0),  # climb to about 40,000 ft
        Segment(20.0, path_angle_rate=-0.5 * DEG),  # level off
        Segment(300.0),  # cruise
        Segment(20.0, turn_rate=4.0 * DEG),  # break turn (missile evasion)
        Segment(20.0, turn_rate=-4.0 * DEG),
        Segment(30.0, path_angle_rate=-0.5 * DEG),  # push over into a 15 deg dive
        Segment(135.0),  # dive
        Segment(30.0, path_angle_rate=0.5 * DEG),  # pull out near 200 ft
        Segment(600.0),  # low-level ingress
        Segment(10.0, path_angle_rate=1.0 * DEG),  # pop-up
        Segment(12.0),
        Segment(10.0, path_angle_rate=-1.0 * DEG),
        Segment(130.0),  # run in to release
    ]
    return fly(
        segs, dt=a.step_s, lat0=a.latitude_deg * DEG, lon0=a.longitude_deg * DEG, h0=100.0, speed0=160.0
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
    channels = best_geometry_channels(tr, nominal_gps_constellation(), ASSUMED.channels, ASSUMED.mask_deg)
    t_loss = tr.t[-1] - free_inertial_s
    ev = [(t_loss, c, k, False) for c in range(len(channels)) for k in ("code", "carrier")]
    code, carrier = lock_table(tr.t, len(channels), ev)
    noise = IN.headon_lc_pseudorange_noise_m if architecture == "loose" else None
    return _run(_group(architecture), tr, code, carrier, channels, lc_pseudorange_noise_m=noise)


# ------------------------------------------------------------------ helicopter


def helicopter_trajectory(duration_s: float) -> Trajectory:
    """Terrain following at constant ground speed: the flight-path angle swings +-4 deg
    with a 60-s period (height changes of about +-25 m), plus a 90-degree turn every 5 min."""
    a = ASSUMED
    segs: list[Segment] = []
    t = 0.0
    sign = 1.0
    k = 0
    while t < duration_s:
        for rate in (1.0, -1.0, -1.0, 1.0):  # one 60-s terrain undulation
            segs.append(Segment(15.0, path_angle_rate=rate * 4.0 / 15.0 * DEG))
        t += 60.0
        k += 1
        if k % 5 == 0:
            segs.append(Segment(30.0, turn_rate=sign * 3.0 * DEG))
            sign = -sign
            t += 30.0
    tr = fly(
        segs,
        dt=a.step_s,
        lat0=a.latitude_deg * DEG,
        lon0=a.longitude_deg * DEG,
        h0=100.0,
        speed0=a.helicopter_speed_mps,
    )
    n = round(duration_s / a.step_s) + 1
    return Trajectory(*(getattr(tr, f.name)[:n] for f in fields(tr)))


@input_cache
def helicopter(doppler: bool) -> dict[float, CovarianceAnalysis]:
    """Tightly coupled helicopter: GPS until calibration reaches steady state
    (``helicopter_calibration_min``), then 19 min jammed; Doppler throughout if ``doppler``."""
    a = ASSUMED
    calibration_min = a.helicopter_calibration_min
    duration = (calibration_min + IN.helicopter_jammed_min) * MINUTE
    tr = helicopter_trajectory(duration)
    channels = best_geometry_channels(tr, nominal_gps_constellation(), a.channels, a.mask_deg)
    t_loss = calibration_min * MINUTE
    ev = [(t_loss, c, k, False) for c in range(len(channels)) for k in ("code", "carrier")]
    code, carrier = lock_table(tr.t, len(channels), ev)
    res = _run((System("tight", 10.0), System("tight", 1.0)), tr, code, carrier, channels, doppler=doppler)
    return {s.grade: r for s, r in res.items()}


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
