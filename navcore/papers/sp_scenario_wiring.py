"""SP Section 2.6 scenarios: the wiring that the missions and the jammer flyby share.

The five systems of Figs. 2.4-2.8, the truth layout and the error sources of Tables 2.4, 2.5 and
2.8, the covariance runs (one batched pass per architecture, from the mission start or resumed),
the GPS constellation and the cruise's calibration turns. The three mission flights
(:mod:`navcore.papers.sp_mission_flights`) and the jammer flyby
(:mod:`navcore.papers.sp_flyby`) fly on them.

The paper publishes the error budgets (Tables 2.4, 2.5, 2.8), the filter state vectors
(Tables 2.2, 2.3) and the measurement rules (Sec. 2.1-2.2), but not the satellite geometry,
the receiver noise, the clock model or the cruise. Every such number a claim reads is an
input of :data:`IN`, with the locator where the paper prints it or, where it does not, a
nominal value, a plausible range and the reason for both; the ledger evaluates each claim
across those ranges.

Nothing here is a model: the models are :mod:`navcore.inertial.error_dynamics` and
:mod:`navcore.integration.engine`. This module only wires the paper's inputs
into them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from navcore._validate import ModelDomainError
from navcore.claims.inputs import InputSet
from navcore.estimation.layout import StateLayout
from navcore.gnss.architectures import loosely_coupled_layout, tightly_coupled_layout
from navcore.gnss.constellation import Constellation, nominal_gps_constellation
from navcore.inertial.error_dynamics import (
    ClockModel,
    ErrorSources,
    GaussMarkov,
    gravity_tuning_psd,
    gyrocompass_alignment,
    initial_covariance,
    ins_error_layout,
)
from navcore.inertial.imu import ImuSpec
from navcore.inertial.trajectories import Segment, Trajectory
from navcore.integration.engine import CovarianceAnalysis, run_covariance_analysis
from navcore.integration.geometry import satellite_geometry
from navcore.integration.schedules import (
    baro_schedule,
    combine_schedules,
    doppler_schedule,
    loosely_coupled_schedule,
    tightly_coupled_schedule,
    without_step,
)
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
    "IN",
    "SYSTEMS",
    "System",
    "calibration_turns",
    "error_sources",
    "gps_constellation",
    "truth_layout",
]


#: The scenario's inputs that the missions and the flyby share. The section string is the
#: missions' (shared with :mod:`navcore.papers.sp_mission_flights`), so every input keeps its
#: full name ``SP.missions.<name>``.
IN = InputSet("SP", "missions")


# --- assumed: the few unpublished inputs that move the claims (bands) -----------------------
IN.assumed(
    "turn_rate_deg_s",
    1.5,
    low=0.75,
    high=3.0,
    unit="deg/s",
    quantity="rate of the calibration turns of the sequential-outage cruise",
    reason="the paper gives no trajectory; the turns make heading and the gyro errors observable "
    "(how well they are calibrated sets the free-inertial growth). 1.5 deg/s is a standard-rate "
    "turn for a transport; half to twice that covers a gentle to a brisk turn",
)
IN.assumed(
    "first_turn_s",
    240.0,
    low=120.0,
    high=360.0,
    unit="s",
    quantity="straight cruise before the first calibration turn (sequential outage and jammer flyby)",
    reason="the paper gives no trajectory; the book turns first after 4 min, while every signal is "
    "still tracked (the first carrier is lost at 360 s, Sec. 2.6.1), so that the filter sees a "
    "turn with all of GPS; 2-6 min keeps the first turn's start inside that span",
)
IN.assumed(
    "turn_interval_min",
    10.0,
    low=5.0,
    high=20.0,
    unit="min",
    quantity="interval between the calibration turns of the sequential-outage cruise (and the flyby's "
    "two turns)",
    reason="the paper gives no trajectory; a cruise of more than 100 min (Sec. 2.6.1's 20-min outage "
    "and 84-min free-inertial variant) that turns every 5-20 min keeps heading and the gyro errors "
    "observable, like the legs of a racetrack or survey pattern",
)
IN.assumed(
    "turn_angle_deg",
    90.0,
    low=45.0,
    high=180.0,
    unit="deg",
    quantity="heading change of each turn of the missions' profiles (sequential outage, jammer flyby, "
    "helicopter), alternately right and left",
    reason="the paper gives no trajectory; the book zig-zags about a mean course with 90-deg turns. "
    "45-180 deg spans a dogleg to a reversal",
)
IN.assumed(
    "heading_deg",
    0.0,
    low=0.0,
    high=270.0,
    grid=4,
    unit="deg",
    quantity="initial heading of the sequential outage, head-on approach and helicopter missions",
    reason="the paper gives no route; the book starts north. The heading sets the track over the "
    "Earth and against the constellation (and the gyro errors a turn exposes): north, east, south "
    "and west (a grid because the geometry's effect is not monotone)",
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


# --- the scenario the paper does not publish: every constant a claim reads is an input ------
IN.published(
    "step_s",
    1.0,
    locator="Sec. 2.2 ('measurements of pseudo-range and pseudo-range rate ... at a 1-Hz rate')",
    unit="s",
    quantity="covariance time step (the tightly coupled measurement interval)",
)
IN.published(
    "channels",
    4,
    locator="Sec. 2.0 ('there will be four satellites in track')",
    unit="satellites",
    quantity="satellites tracked (sequential outage, head-on approach, helicopter)",
)
IN.assumed(
    "latitude_deg",
    35.0,
    low=30.0,
    high=45.0,
    unit="deg",
    quantity="latitude of the missions",
    reason="the paper gives no location; the US flight-test ranges where such systems are flown "
    "(Eglin 30.5, Edwards and China Lake 35, Patuxent River 38, Wright-Patterson 40 deg N) span "
    "30-45 deg",
)
IN.assumed(
    "longitude_deg",
    -117.0,
    low=-120.0,
    high=-75.0,
    grid=3,
    unit="deg",
    quantity="longitude of the missions (the constellation choice)",
    reason="with the nominal 24-satellite constellation at its fixed epoch, the longitude chooses which "
    "satellites are up and where (the paper's constellation and date are not given); the same US "
    "test ranges span 120-75 deg W; a grid because the geometry's effect is not monotone",
)
IN.assumed(
    "cruise_altitude_m",
    7000.0,
    low=3000.0,
    high=12000.0,
    unit="m",
    quantity="cruise altitude (sequential outage and jammer flyby)",
    reason="not published; 3-12 km spans transport and fighter cruise altitudes (the head-on mission "
    "climbs to the 12 km of its '40,000 ft')",
)
IN.assumed(
    "cruise_speed_mps",
    200.0,
    low=150.0,
    high=250.0,
    unit="m/s",
    quantity="cruise ground speed (sequential outage and jammer flyby)",
    reason="not published; 150-250 m/s spans transport and fighter cruise speeds",
)
IN.assumed(
    "pseudorange_noise_m",
    1.0,
    low=0.5,
    high=3.0,
    unit="m",
    quantity="white pseudorange noise per 1-s measurement",
    reason="Table 2.4 gives it only as 'from receiver tracking loop simulation'; 0.5-3 m spans P(Y) "
    "code receivers of the period at nominal signal levels",
)
IN.assumed(
    "range_rate_noise_mps",
    0.05,
    low=0.02,
    high=0.1,
    unit="m/s",
    quantity="white range-rate noise per 1-s measurement",
    reason="Table 2.4 gives it only as 'from receiver tracking loop simulation'; carrier-derived "
    "range rate over 1 s is good to a few cm/s (0.02-0.1 m/s)",
)
IN.assumed(
    "clock_bias_psd_m2_s",
    0.0036,
    low=0.0036,
    high=0.009,
    unit="m²/s",
    quantity="receiver clock phase (bias) noise PSD",
    reason="Table 2.4 gives the clock's initial errors, not its noise. $S_f = h_0 c^2 / 2$ of an "
    "oven-controlled crystal ($h_0 = 8 \\times 10^{-20}$, nominal) up to a temperature-compensated one "
    "($h_0 = 2 \\times 10^{-19}$): "
    "Brown & Hwang, Table 9.2",
)
IN.assumed(
    "clock_drift_psd_m2_s3",
    7.1e-5,
    low=7.1e-5,
    high=0.0355,
    unit="m²/s³",
    quantity="receiver clock frequency (drift) noise PSD",
    reason="$S_g = 2 \\pi^2 h_{-2} c^2$ of an oven-controlled crystal ($h_{-2} = 4 \\times 10^{-23}$, "
    "nominal) up to a "
    "temperature-compensated one ($h_{-2} = 2 \\times 10^{-20}$): Brown & Hwang, Table 9.2",
)
IN.assumed(
    "mask_deg",
    10.0,
    low=5.0,
    high=15.0,
    unit="deg",
    quantity="elevation mask of the satellite selection",
    reason="not published; receivers of the period used 5-15 deg",
)
IN.published(
    "lc_fix_interval_s",
    10.0,
    locator="Sec. 2.1 ('the integration filter only used the position from the PVA solution, and this "
    "only once every 10 s')",
    unit="s",
    quantity="interval between the loosely coupled filter's position fixes",
)
IN.published(
    "lc_max_ehe_m",
    100.0,
    locator="Sec. 2.1 ('only if the Expected Horizontal Error (EHE) ... was less than 100 m')",
    unit="m",
    quantity="largest expected horizontal error of a position fix the loosely coupled filter takes",
)
IN.assumed(
    "doppler_interval_s",
    1.0,
    low=1.0,
    high=10.0,
    unit="s",
    quantity="interval between the Doppler ground-speed measurements the filter takes",
    reason="Table 2.8 gives the Doppler sensor's errors, not the rate at which the filter takes its "
    "velocity; from every covariance step (1 s, the rate at which its noise is stated) to the loosely "
    "coupled filter's 10 s",
)
IN.assumed(
    "baro_interval_s",
    10.0,
    low=1.0,
    high=10.0,
    unit="s",
    quantity="interval between barometric altitude updates",
    reason="Table 2.4 gives the barometer's errors (3 m noise), not its rate; from the tightly coupled "
    "filter's 1 s to the loosely coupled 10 s",
)
IN.assumed(
    "gps_slots_per_plane",
    4,
    low=4,
    high=5,
    unit="satellites",
    quantity="satellites per orbital plane of the missions' GPS constellation (six planes)",
    reason="the paper names no constellation; 24 satellites, four in each of the six planes, is the "
    "baseline of the GPS performance standard and the constellation of the 1990s; five per plane "
    "(30 satellites) is the size it has had since the 2000s",
)
IN.assumed(
    "walker_phase_deg",
    15.0,
    low=0.0,
    high=30.0,
    grid=3,
    unit="deg",
    quantity="offset of the satellites' argument of latitude from one orbital plane to the next",
    reason="the paper names no constellation and no date; the book flies an evenly phased (Walker-like) "
    "pattern, a stand-in for the almanac (the real slots are unevenly phased). A 24/6/F Walker pattern "
    "offsets the planes by $F \\times 15$ deg: $F = 0, 1, 2$ give 0, 15 and 30 deg; with the longitude it "
    "sets which satellites are up and where; a grid because the geometry's effect is not monotone",
)


def gps_constellation(slots_per_plane: int | None = None) -> Constellation:
    """The GPS constellation of the scenarios: six planes of :data:`IN` ``gps_slots_per_plane``
    satellites (or ``slots_per_plane``), offset by ``walker_phase_deg`` from plane to plane."""
    per_plane = IN.gps_slots_per_plane if slots_per_plane is None else slots_per_plane
    return nominal_gps_constellation(per_plane=per_plane, phase_offset_deg=IN.walker_phase_deg)


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


def truth_layout(*, doppler: bool = False, channels: int | None = None, clock: bool = True) -> StateLayout:
    """Truth states: the 24 tightly coupled states plus everything Table 2.4/2.5 lists that
    the filters do not carry (instrument misalignments, gravity anomaly, clock
    g-sensitivity, per-channel pseudorange and range-rate biases, Doppler errors).

    ``clock=False`` leaves out the user clock (bias, drift, g-sensitivity): in the loosely
    coupled analysis no measurement sees it (the receiver's position solution removes it) and
    no navigation error depends on it, so its states are not carried."""
    extra = [
        "gyro misalignment",
        "accel misalignment",
        "gravity",
        *(("clock g-sensitivity",) if clock else ()),
        "pseudorange bias",
        "range-rate bias",
    ]
    if doppler:
        extra += ["doppler bias", "doppler scale factor", "doppler misalignment"]
    if channels is None:
        channels = IN.channels
    core = tuple(b for b in tightly_coupled_layout().blocks if clock or not b.name.startswith("clock"))
    return StateLayout(core + ins_error_layout(*extra, channels=channels).blocks, "truth")


def error_sources(spec: ImuSpec, doppler: bool = True, clock: bool = True) -> ErrorSources:
    """Table 2.4 (INS-independent) and Table 2.8 errors around one Table 2.5 instrument
    (``doppler=False``: without the Doppler sensor, whose Table 2.8 errors are then not read;
    ``clock=False``: without the user clock, whose Table 2.4 errors and noise are then not read)."""
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
            bias_psd=IN.clock_bias_psd_m2_s,
            drift_psd=IN.clock_drift_psd_m2_s3,
        )
        if clock
        else None,
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


#: A change of a member's a-priori covariance (truth layout) before a run: ``f(P0, layout)``.
AprioriTransform = Callable[[np.ndarray, StateLayout], np.ndarray]


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
    constellation: Constellation | None = None,
    measure_last: bool = True,
) -> dict[System, CovarianceAnalysis]:
    """Run several systems on one trajectory and lock table (one batched pass per
    architecture), from the mission start or resuming from ``resume``'s final covariances.
    ``initial_position=False`` starts without horizontal position error;
    ``lc_pseudorange_noise_m`` replaces the loosely coupled receiver's pseudorange noise;
    ``constellation`` the nominal 24-satellite one; ``measure_last=False`` applies no
    measurement at the last sample (a phase that another resumes from there)."""
    runs = _run_list(
        systems,
        tr,
        code,
        carrier,
        channels,
        doppler=doppler,
        snapshots=snapshots,
        resume=None if resume is None else [resume[s] for s in systems],
        initial_position=initial_position,
        lc_pseudorange_noise_m=lc_pseudorange_noise_m,
        constellation=constellation,
        measure_last=measure_last,
    )
    return dict(zip(systems, runs, strict=True))


def _run_list(
    systems: tuple[System, ...],
    tr: Trajectory,
    code: np.ndarray,
    carrier: np.ndarray,
    channels: np.ndarray,
    *,
    doppler: bool = False,
    snapshots: tuple[int, ...] = (-1,),
    resume: list[CovarianceAnalysis] | None = None,
    initial_position: bool = True,
    lc_pseudorange_noise_m: float | None = None,
    constellation: Constellation | None = None,
    transforms: tuple[AprioriTransform | None, ...] | None = None,
    measure_last: bool = True,
) -> list[CovarianceAnalysis]:
    """:func:`_run` for a list of members (a system may appear several times, each with its
    own ``transforms`` of the a-priori covariance), in the order given."""
    out: dict[int, CovarianceAnalysis] = {}
    con = gps_constellation() if constellation is None else constellation
    geo = satellite_geometry(tr, con, [int(c) for c in channels])
    every = max(1, round(IN.baro_interval_s / tr.dt))
    if transforms is None:
        transforms = (None,) * len(systems)
    for arch in ("loose", "tight"):
        members = [i for i, s in enumerate(systems) if s.architecture == arch]
        if not members:
            continue
        # the loosely coupled analysis carries no user clock: no measurement of it sees one
        tight = arch == "tight"
        truth = truth_layout(doppler=doppler, channels=len(channels), clock=tight)
        baro = baro_schedule(truth, noise_m=tab.IN.barometer_noise_m, every=every)
        dop = (
            doppler_schedule(
                truth, tr, noise_mps=IN.doppler_noise_mps, every=max(1, round(IN.doppler_interval_s / tr.dt))
            )
            if doppler
            else None
        )
        group = [systems[i] for i in members]
        sources = [error_sources(sp_imu_grade(s.grade), doppler, clock=tight) for s in group]
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
                    IN.pseudorange_noise_m if lc_pseudorange_noise_m is None else lc_pseudorange_noise_m
                ),
                pseudorange_bias_sigma=sources[0].pseudorange_bias_sigma,
                interval_steps=max(1, round(IN.lc_fix_interval_s / tr.dt)),
                max_ehe_m=IN.lc_max_ehe_m,
            )
        else:
            gps = tightly_coupled_schedule(
                truth,
                geo,
                code,
                carrier,
                pseudorange_noise=IN.pseudorange_noise_m,
                range_rate_noise=IN.range_rate_noise_mps,
                g_load=np.linalg.norm(tr.f_ned, axis=1) / G0,
            )
        apriori = np.stack(
            [
                _initial_covariance(truth, src, tr)
                if f is None
                else f(_initial_covariance(truth, src, tr), truth)
                for src, f in zip(sources, (transforms[i] for i in members), strict=True)
            ]
        )
        if resume is None:
            P0, Pf0 = apriori.copy(), None
            if not initial_position:
                for i in range(2):
                    j = truth.index("position", i)
                    P0[:, j, :] = 0.0
                    P0[:, :, j] = 0.0
        else:  # a resumed phase starts from the final covariances of the phase before
            trues, filters = [], []
            for i in members:
                true, filt0 = resume[i].final_true, resume[i].final_filter
                if true is None or filt0 is None:
                    raise ValueError("the previous phase kept no final covariance to resume from")
                trues.append(true)
                filters.append(filt0)
            P0, Pf0 = np.stack(trues), np.stack(filters)
        steps = np.zeros(len(tr), dtype=bool)
        steps[::every] = True  # barometer
        if arch == "loose":
            steps[::10] = True
        else:
            steps |= (code | carrier).any(axis=1)
        if doppler:
            steps[:] = True
        schedule = combine_schedules(gps, baro, dop)
        if not measure_last:  # the last sample's measurements belong to the phase resumed from it
            steps[-1] = False
            schedule = without_step(schedule, len(tr) - 1)
        res = run_covariance_analysis(
            tr,
            truth,
            filt,
            sources,
            P0,
            schedule,
            snapshots=snapshots,
            P0_filter=Pf0,
            P0_apriori=apriori,
            measurement_steps=steps,
            filter_added_psd=gravity_tuning_psd(filt, sources[0], float(np.mean(tr.speed))),
        )
        assert isinstance(res, list)  # a stack of initial covariances gives one run each
        out.update(zip(members, res, strict=True))
    return [out[i] for i in range(len(systems))]


def calibration_turn_s() -> float:
    """Duration (s) of one calibration turn: :data:`IN` ``turn_angle_deg`` at ``turn_rate_deg_s``."""
    return IN.turn_angle_deg / IN.turn_rate_deg_s


def calibration_turns(duration_s: float) -> list[Segment]:
    """The cruise's segments: straight for :data:`IN` ``first_turn_s``, then every
    ``turn_interval_min`` a turn of ``turn_angle_deg`` at ``turn_rate_deg_s`` (alternately right
    and left) and straight flight to the next, until ``duration_s`` is covered. The jammer flyby
    flies the first two of them."""
    rate = IN.turn_rate_deg_s
    turn_s = calibration_turn_s()
    interval_s = IN.turn_interval_min * MINUTE
    if turn_s >= interval_s:
        raise ModelDomainError(
            f"turn_angle_deg / turn_rate_deg_s ({turn_s:g} s) must be shorter than turn_interval_min "
            f"({interval_s:g} s)",
            case="a calibration turn outlasts the interval between turns",
        )
    segs: list[Segment] = [Segment(IN.first_turn_s)]
    t = IN.first_turn_s
    sign = 1.0
    while t < duration_s:
        segs.append(Segment(turn_s, turn_rate=sign * rate * DEG))
        segs.append(Segment(interval_s - turn_s))
        t += interval_s
        sign = -sign
    return segs
