"""KZL Sec. 3.6 and Table 1: the simulation scenario, as registered inputs, and its Monte Carlo.

Table 1's IMU block is scrambled by the OCR (numbers and labels on different lines). The
assignment used here keeps both in their printed order and moves the gyro numbers up one
line (the minimal repair):

============  ==================  ======================
sensor        parameter           value
============  ==================  ======================
gyro          bias stability      360 deg/h
gyro          scale factor        10000 ppm
gyro          noise (ARW)         180 deg/h/sqrt(Hz)
accel         bias stability      2400 micro-g
accel         scale factor        10000 ppm
accel         noise (VRW)         1000 micro-g/sqrt(Hz)
============  ==================  ======================

That assignment is a ``convention`` input (:data:`IN` ``gyro_bias_arw``); the swapped reading
(bias 180, ARW 360) is what ``kzl_imu(swapped=True)`` builds, and the ledger shows what each
claim gives under it.

Assumptions the paper does not state are ``assumed`` inputs with a plausible range: the
initialisation averaging time, the crab angle, the GPS measurement noises (code, delta range,
carrier phase, multi-antenna attitude, each with its own range; the initial GPS fix is as noisy
as the code and delta range), the filter's gyro-bias random walk and the length of the short segments of the
satellite visibility schedule (:func:`visibility_schedule`: the paper's is only in its figures;
the satellite counts of its segments, :data:`SCHEDULE_COUNTS`, are the structure the claims refer
to, "the 3-satellite segment"). The sky is the nominal GPS constellation of a declared
convention (``constellation``); the Monte Carlo ensemble size is a declared reading
(``n_runs``). The clock model and the accelerometer-bias random walk are the filter's
(:class:`~navcore.integration.ekf_ins_gnss.Scenario`) and are stated there.
"""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple, cast

import numpy as np

from navcore.claims import InputSet, for_each_band_run, input_cache
from navcore.claims.run_store import RunMemo, RunStore
from navcore.frames import dcm_ecef_to_ned, dcm_from_euler, ecef_to_ned
from navcore.gnss.constellation import nominal_gps_constellation
from navcore.gnss.dop import satellite_priority
from navcore.inertial.imu import ImuSpec, imu_spec_from_published
from navcore.integration.ekf_ins_gnss import (
    GnssNoise,
    Mode,
    MonteCarloResult,
    Scenario,
    batch_group_key,
    monte_carlo_key,
    run_monte_carlo,
    run_monte_carlo_batch,
)
from navcore.units import DEG

__all__ = [
    "IN",
    "N_RUNS",
    "SCHEDULE_COUNTS",
    "SEED",
    "VISIBILITY_SCHEDULE",
    "gnss_noise",
    "initial_fix_sigmas",
    "kzl_imu",
    "monte_carlo",
    "n_runs",
    "table1",
    "table1_attitude",
    "table1_baselines_b",
    "table1_los",
    "table1_scenario",
    "table1_sky",
    "visibility_schedule",
]

#: The registered inputs of the KZL simulation (Table 1 and the book's assumptions).
IN = InputSet("KZL", "scenario")
_T1 = "Table 1"
IN.published(
    "velocity_east_mps", 110.0, locator=_T1 + ", velocity (ENU)", unit="m/s", quantity="east velocity"
)
IN.published(
    "velocity_north_mps", 0.0, locator=_T1 + ", velocity (ENU)", unit="m/s", quantity="north velocity"
)
IN.published("lat_deg", 51.0, locator=_T1 + ", initial position", unit="deg", quantity="latitude")
IN.published("lon_deg", 8.0, locator=_T1 + ", initial position", unit="deg", quantity="longitude")
IN.published("height_m", 3000.0, locator=_T1 + ", initial position", unit="m", quantity="height")
IN.published("roll_deg", 0.0, locator=_T1 + ", angles", unit="deg", quantity="roll")
IN.published("pitch_deg", 0.0, locator=_T1 + ", angles", unit="deg", quantity="pitch")
IN.published("heading_deg", 90.0, locator=_T1 + ", angles", unit="deg", quantity="heading")
IN.published("duration_s", 180.0, locator=_T1 + ", duration", unit="s", quantity="flight duration")
IN.published("gps_rate_hz", 1.0, locator=_T1 + ", GPS update rate", unit="Hz", quantity="GPS rate")
IN.published("imu_rate_hz", 100.0, locator=_T1 + ", IMU update rate", unit="Hz", quantity="IMU rate")
IN.published(
    "elevation_mask_deg", 5.0, locator=_T1 + ", elevation angle", unit="deg", quantity="elevation mask"
)
IN.published(
    "baseline_m", 2.0, locator=_T1 + ", method (baselines of 2 m)", unit="m", quantity="antenna baseline"
)
IN.published(
    "accel_bias_micro_g",
    2400.0,
    locator=_T1 + ", accelerometer bias stability",
    unit="µg",
    quantity="accelerometer bias",
)
IN.published(
    "accel_scale_factor_ppm",
    10000.0,
    locator=_T1 + ", accelerometer scale factor",
    unit="ppm",
    quantity="accelerometer scale factor",
)
IN.published(
    "accel_vrw_micro_g",
    1000.0,
    locator=_T1 + ", accelerometer noise (VRW)",
    unit="µg/√Hz",
    quantity="velocity random walk",
)
IN.published(
    "gyro_scale_factor_ppm",
    10000.0,
    locator=_T1 + ", gyroscope scale factor",
    unit="ppm",
    quantity="gyro scale factor",
)
IN.convention(
    "gyro_bias_arw",
    (360.0, 180.0),
    readings={
        "the gyro numbers moved up one line: bias 360, angle random walk 180": (360.0, 180.0),
        "the two swapped: bias 180, angle random walk 360": (180.0, 360.0),
    },
    reason="Table 1's gyro block is OCR-scrambled: 360 and 180 stand on the lines of 'bias stability' "
    "and 'Accelerometer'; moving the gyro numbers up one line gives bias 360 deg/h, ARW 180 "
    "deg/h/√Hz; the swapped reading exchanges them",
    unit="(deg/h, deg/h/√Hz)",
    quantity="gyro bias stability and angle random walk",
)
IN.assumed(
    "init_time_s",
    300.0,
    low=150.0,
    high=600.0,
    reason="Sec. 3.1 initialises by averaging at rest but gives no duration; 2.5-10 min is the usual "
    "range of a levelling and gyro-bias calibration before take-off",
    unit="s",
    quantity="initialisation averaging time",
)
IN.assumed(
    "crab_angle_deg",
    0.5,
    low=0.1,
    high=1.0,
    reason="Eq. (4) takes the heading from the GPS velocity, blind to the crab angle; 0.1-1 deg is the "
    "crab of a 110 m/s aircraft in 0.2-2 m/s crosswind (the paper gives no wind)",
    unit="deg",
    quantity="1-$\\sigma$ crab angle (heading minus GPS track)",
)
IN.assumed(
    "code_noise_m",
    3.0,
    low=1.5,
    high=6.0,
    reason="the paper gives no GPS noise; 3 m is the 1-$\\sigma$ C/A-code pseudorange noise of an L1 "
    "receiver without multipath (Table 1 corrects the tropospheric and ionospheric delays and "
    "calibrates multipath out), 1.5-6 m a good to a poor low-cost receiver; the initial GPS fix has "
    "the same error per axis (one epoch's code solution)",
    unit="m",
    quantity="1-$\\sigma$ code pseudorange noise (and error of the initial GPS position per axis)",
)
IN.assumed(
    "delta_range_noise_mps",
    0.05,
    low=0.025,
    high=0.1,
    reason="the paper gives no GPS noise; 5 cm/s is the 1-$\\sigma$ $\\delta$ range (Doppler) noise of an "
    "L1 receiver at 1 Hz, 2.5-10 cm/s a good to a poor low-cost receiver; the initial GPS velocity "
    "has the same error per axis",
    unit="m/s",
    quantity="1-$\\sigma$ $\\delta$ range noise (and error of the initial GPS velocity per axis)",
)
IN.assumed(
    "phase_noise_m",
    0.003,
    low=0.0015,
    high=0.006,
    reason="the paper gives no carrier-phase noise (ambiguities resolved, Table 1); 3 mm is the "
    "1-$\\sigma$ undifferenced L1 phase noise of a tracking loop, 1.5-6 mm a good to a poor one",
    unit="m",
    quantity="1-$\\sigma$ undifferenced carrier-phase noise",
)
IN.assumed(
    "attitude_noise_rad",
    0.003,
    low=0.0015,
    high=0.006,
    reason="the paper gives no accuracy of its multi-antenna attitude; 3 mrad (0.17 deg) per Euler "
    "angle is what a few mm of phase noise gives over Table 1's 2-m baselines, 1.5-6 mrad "
    "(0.09-0.34 deg) a good to a poor system",
    unit="rad",
    quantity="1-$\\sigma$ multi-antenna attitude noise per Euler angle",
)
IN.assumed(
    "gyro_bias_walk",
    1e-6,
    low=1e-7,
    high=1e-5,
    reason="the paper gives no filter tuning; the filter models the gyro biases as a random walk "
    "(the truth biases are constant), and its root PSD is a tuning choice: $10^{-6}$ rad/s/$\\sqrt{s}$ "
    "nominal, a decade either way a tighter or a looser filter",
    unit="rad/s/sqrt(s)",
    quantity="gyro-bias random walk of the filter (tuning)",
)
IN.published(
    "antennas",
    3,
    locator=_T1 + ", method ('3 antenna-receiver pairs with baselines of 2 m each')",
    quantity="antennas of the multi-antenna system",
)
IN.published(
    "attitude_min_sats",
    4,
    locator="Sec. 3.6 ('In case of less than 4 satellites in view, the system can not provide "
    "attitude information')",
    quantity="fewest satellites with which the multi-antenna system gives attitude",
)
IN.convention(
    "n_runs",
    30,
    quantity="number of Monte Carlo runs behind the book's Figs. 4-5",
    readings={"30 runs (the book's ensemble)": 30, "60 runs": 60},
    reason="Figs. 4-5 show the errors of one simulated flight and the paper states no ensemble; the "
    "book reads 'the error' as the RMS over seeded runs, whose number the paper leaves open (the "
    "RMS of N runs has a relative standard error of $1/\\sqrt{2 N}$): 30 runs, or 60",
)
IN.convention(
    "constellation",
    (6, 4, 55.0, 15.0),
    quantity="GPS sky (orbital planes, satellites per plane, inclination and phasing of successive "
    "planes in deg)",
    readings={
        "24 satellites, 6 planes of 4 at 55 deg, planes phased 15 deg": (6, 4, 55.0, 15.0),
        "the same planes unphased (0 deg)": (6, 4, 55.0, 0.0),
    },
    reason="Table 1 gives the start time (Oct. 29, 2006, 00:11:27 UTC) but not the almanac of that "
    "day, so the book flies under a stand-in sky: the 24-slot GPS design (6 planes of 4 at 55 deg, "
    "GPS SPS Performance Standard) with its slots evenly spaced; the real slots are not evenly "
    "phased, and the phasing of successive planes is the book's, 15 deg or none",
)
IN.assumed(
    "short_segment_s",
    30.0,
    low=20.0,
    high=40.0,
    reason="the paper shows the satellites in view only in Figs. 4-5 (Table 1: '2-8, as depicted'); "
    "the book's schedule has 8 satellites until four shorter segments of this length each (4, 3, 2, "
    "then 5 satellites) end the 180 s flight; 20-40 s spans the segments of a 3-min plot read by eye",
    unit="s",
    quantity="length of each of the 4-, 3-, 2- and 5-satellite segments of the visibility schedule",
)

#: Satellites in view, segment by segment, in the book's visibility schedule: 8, then 4, 3, 2 and
#: 5 in segments of ``short_segment_s`` each that end the flight. The counts are the segments the
#: claims name (Sec. 3.6: 'four or more', 'two or three'; Table 1: 2-8); the paper's schedule is
#: only in Figs. 4-5.
SCHEDULE_COUNTS = (8, 4, 3, 2, 5)

SEED = 20061029


def _schedule(segment_s: float, duration_s: float) -> tuple[tuple[float, int], ...]:
    n_short = len(SCHEDULE_COUNTS) - 1
    short = tuple((duration_s - (n_short - i) * segment_s, n) for i, n in enumerate(SCHEDULE_COUNTS[1:]))
    return ((0.0, SCHEDULE_COUNTS[0]), *short)


def visibility_schedule() -> tuple[tuple[float, int], ...]:
    """The visibility schedule, (start time s, satellites tracked) per segment: 8 satellites from
    the start, then :data:`SCHEDULE_COUNTS`' other counts in segments of the assumed
    ``short_segment_s`` that end the Table 1 flight (reads both inputs)."""
    return _schedule(IN.short_segment_s, IN.duration_s)


#: The schedule at the nominal inputs, (start time s, satellites tracked): 8 -> 4 -> 3 -> 2 -> 5 at
#: 0, 60, 90, 120, 150 s. For figure captions and labels; the claims read :func:`visibility_schedule`.
VISIBILITY_SCHEDULE = _schedule(IN.nominal("short_segment_s"), IN.nominal("duration_s"))


def n_runs() -> int:
    """The Monte Carlo ensemble size (the reading of ``n_runs`` used)."""
    return int(IN.n_runs)


#: The nominal ensemble size (for tolerances fixed before any value is computed, and captions).
N_RUNS = int(IN.nominal("n_runs"))


def table1() -> dict:
    """Table 1 as a dict in the units printed (velocity ENU m/s, degrees, metres, seconds, Hz)."""
    return {
        "velocity_enu_mps": (IN.velocity_east_mps, IN.velocity_north_mps, 0.0),
        "lat_deg": IN.lat_deg,
        "lon_deg": IN.lon_deg,
        "height_m": IN.height_m,
        "attitude_deg": (IN.roll_deg, IN.pitch_deg, IN.heading_deg),
        "duration_s": IN.duration_s,
        "gps_rate_hz": IN.gps_rate_hz,
        "imu_rate_hz": IN.imu_rate_hz,
        "elevation_mask_deg": IN.elevation_mask_deg,
        "baseline_m": IN.baseline_m,
        "n_antennas": IN.antennas,
        "satellites_in_view": (2, 8),
    }


def kzl_imu(swapped: bool = False) -> ImuSpec:
    """The Table 1 consumer-grade IMU (``swapped``: the other reading of the gyro block)."""
    bias, arw = IN.gyro_bias_arw
    if swapped:
        bias, arw = arw, bias
    return imu_spec_from_published(
        "KZL Table 1 consumer-grade MEMS" + (", gyro bias and ARW swapped" if swapped else ""),
        accel_bias_micro_g=IN.accel_bias_micro_g,
        accel_scale_factor_ppm=IN.accel_scale_factor_ppm,
        accel_misalignment_arcsec=0.0,  # Table 1 lists no misalignment
        accel_random_walk_micro_g_per_sqrt_hz=IN.accel_vrw_micro_g,
        gyro_bias_deg_per_h=bias,
        gyro_scale_factor_ppm=IN.gyro_scale_factor_ppm,
        gyro_misalignment_arcsec=0.0,
        gyro_random_walk_deg_per_h_per_sqrt_hz=arw,
        source="KZL Table 1 (OCR-scrambled; gyro values moved up one line)",
    )


def initial_fix_sigmas() -> tuple[float, float]:
    """Errors of the initial GPS fix per axis, position (m) and velocity (m/s): the assumed code and
    delta-range noises (the fix is one epoch's GPS solution, as noisy as the receiver)."""
    return IN.code_noise_m, IN.delta_range_noise_mps


def gnss_noise(mode: str = "all") -> GnssNoise:
    """The assumed GPS noises that ``mode`` uses; a noise the mode never uses is ``None``."""
    if mode == "ins":
        return GnssNoise(pseudorange=None, delta_range=None, phase=None, attitude=None)
    return GnssNoise(
        pseudorange=IN.code_noise_m,
        delta_range=IN.delta_range_noise_mps,
        phase=IN.phase_noise_m if mode in ("tc_dd", "all") else None,
        attitude=IN.attitude_noise_rad if mode in ("tc_att", "all") else None,
    )


def table1_baselines_b() -> np.ndarray:
    """Baselines A0->A1, A0->A2 in body axes (m): Table 1's 2 m along the body x and y axes.

    Table 1 gives the length and the antennas (3 antenna-receiver pairs, so one baseline from the
    master antenna to each of the others); the orthogonal layout along the body axes is the book's.
    """
    b = IN.baseline_m
    return b * np.eye(3)[: IN.antennas - 1]


@input_cache
def table1_sky() -> tuple[np.ndarray, np.ndarray]:
    """Satellite positions and velocities (NED of the start point) in tracking priority, per epoch.

    The nominal 24-satellite constellation at its epoch 0 (the paper's start time, Oct. 29,
    2006, 00:11:27 UTC, is not used: the almanac of that day is not in the paper), seen from
    the Table 1 start point above the Table 1 elevation mask.
    """
    lat, lon, h = IN.lat_deg * DEG, IN.lon_deg * DEG, IN.height_m
    K = round(IN.duration_s * IN.gps_rate_hz)
    t = np.arange(K + 1) / IN.gps_rate_hz
    n_planes, per_plane, inclination_deg, phasing_deg = IN.constellation
    const = nominal_gps_constellation(
        n_planes, per_plane, phase_offset_deg=phasing_deg, inclination_deg=inclination_deg
    )
    prio = satellite_priority(const.positions_ecef(0.0), lat, lon, h, mask=IN.elevation_mask_deg * DEG)
    pos_e = const.positions_ecef(t)[:, prio]
    vel_e = const.velocities_ecef(t)[:, prio]
    return ecef_to_ned(pos_e, lat, lon, h), vel_e @ dcm_ecef_to_ned(lat, lon).T


def table1_attitude() -> np.ndarray:
    """Body-to-NED DCM of the Table 1 attitude (roll 0, pitch 0, heading 90 deg)."""
    return dcm_from_euler(IN.roll_deg * DEG, IN.pitch_deg * DEG, IN.heading_deg * DEG)


def table1_los(nu: int, k: int = 0) -> np.ndarray:
    """Unit LOS (NED) of the first ``nu`` satellites in priority order at epoch ``k``."""
    sats = table1_sky()[0][k, :nu]
    d = sats - np.array([0.0, 0.0, 0.0])
    return d / np.linalg.norm(d, axis=1, keepdims=True)


@input_cache
def table1_scenario(
    mode: str = "all", initialise: bool = True, swapped: bool = False, imu: ImuSpec | None = None
) -> Scenario:
    """The Table 1 flight with the nominal constellation, the schedule and the assumed noises.

    Only the inputs that ``mode`` uses are read (and so recorded): the stand-alone INS reads no
    GPS noise, the uninitialised INS no averaging time. ``imu`` overrides the Table 1 IMU (for
    what-if studies outside the ledger).
    """
    ve, vn = IN.velocity_east_mps, IN.velocity_north_mps  # level flight (Sec. 3.6): no vertical velocity
    sat_pos, sat_vel = table1_sky()
    pos0_sigma, vel0_sigma = initial_fix_sigmas()
    K = sat_pos.shape[0] - 1
    t = np.arange(K + 1) / IN.gps_rate_hz
    n_vis = np.zeros(K + 1, dtype=np.int64)
    for start, n in visibility_schedule():
        n_vis[t >= start] = n
    return Scenario(
        velocity_ned=np.array([vn, ve, 0.0]),
        attitude=np.array([IN.roll_deg, IN.pitch_deg, IN.heading_deg]) * DEG,
        duration=IN.duration_s,
        imu_rate=IN.imu_rate_hz,
        gps_rate=IN.gps_rate_hz,
        imu=kzl_imu(swapped) if imu is None else imu,
        sat_pos_ned=sat_pos,
        sat_vel_ned=sat_vel,
        n_visible=n_vis,
        gnss=gnss_noise(mode),
        init_time=IN.init_time_s if initialise else None,
        heading_sigma=IN.crab_angle_deg * DEG,
        pos0_sigma=pos0_sigma,
        vel0_sigma=vel0_sigma,
        gyro_bias_walk=IN.gyro_bias_walk,
        # every mode draws the phase noise of every antenna (common random numbers), so every
        # mode reads the antennas
        baselines_b=table1_baselines_b(),
    )


#: The disk store of the runs (:class:`~navcore.claims.run_store.RunStore`, in the system temporary
#: directory): a run's file is keyed on the sources of every module the Monte Carlo depends on, this
#: module's included, and on the run's arguments (:func:`~navcore.integration.ekf_ins_gnss.monte_carlo_key`).
_STORE = RunStore(
    "navcore-kzl-mc",
    modules=(
        "navcore.integration.ekf_ins_gnss",
        "navcore.frames",
        "navcore.gnss.carrier_phase",
        "navcore.gnss.constellation",
        "navcore.inertial.alignment",
        "navcore.inertial.error_model17",
        "navcore.inertial.imu",
        "navcore.inertial.strapdown",
        "navcore.estimation.discretize",
        __name__,
    ),
)

#: Monte Carlo runs made or read in this process, by
#: :func:`~navcore.integration.ekf_ins_gnss.monte_carlo_key` (the 1024 most recently used; a
#: :class:`~navcore.claims.run_store.RunMemo` before :data:`_STORE`). A band's corners that differ
#: only in inputs a configuration never reads, and the claims that read the same configuration at
#: the same inputs, share one run (the input cache above it is keyed on every input a configuration
#: reads, so it cannot tell that a mode ignores one of them); a batched band keeps its runs here too.
_RUNS: RunMemo[MonteCarloResult] = RunMemo(_STORE, MonteCarloResult, size=1024)


class _RunArguments(NamedTuple):
    """One configuration's run: its scenario, ensemble size, extra arguments, key and label (the
    readable prefix of its file name in the store)."""

    scenario: Scenario
    runs: int
    extra: dict[str, int]
    key: str
    label: str


def _run_arguments(mode: str, initialise: bool, imu_name: str) -> _RunArguments:
    """The scenario, the ensemble size, the extra arguments and the key
    (:func:`~navcore.integration.ekf_ins_gnss.monte_carlo_key`) of one configuration's run, from
    the inputs (every input :func:`monte_carlo` reads is read here)."""
    sc = table1_scenario(mode, initialise, imu_name == "swapped")
    # Eq. (12)'s attitude rows need the multi-antenna attitude, which Sec. 3.6 says needs 4 satellites
    extra = {"attitude_min_sats": int(IN.attitude_min_sats)} if mode in ("tc_att", "all") else {}
    runs = n_runs()
    key = monte_carlo_key(sc, cast(Mode, mode), runs, SEED, initialise=initialise, **extra)
    return _RunArguments(sc, runs, extra, key, f"{mode}-{initialise}")


def _echo(result: MonteCarloResult, sc: Scenario) -> MonteCarloResult:
    """``result`` echoing ``sc``'s schedule (the stand-alone INS shares runs across schedules)."""
    if not np.array_equal(result.n_visible, sc.n_visible):
        result = replace(result, n_visible=np.asarray(sc.n_visible))
    return result


@input_cache
def _monte_carlo(mode: str, initialise: bool, imu_name: str) -> MonteCarloResult:
    sc, runs, extra, key, label = _run_arguments(mode, initialise, imu_name)
    result = _RUNS.get_or_run(
        key,
        label,
        lambda: run_monte_carlo(sc, cast(Mode, mode), runs, SEED, initialise=initialise, **extra),
    )
    return _echo(result, sc)


#: Most rows (band runs x Monte Carlo runs) of one batched call: a band's runs are split into
#: calls of at most this many rows (a row's numbers do not depend on the split). Sixteen 30-run
#: TC Monte Carlos took 9.2 s of CPU one call each, 6.9 s in calls of 60 rows, 5.6-6.1 s of 120,
#: 6.2 s of 240 and 6.9 s of 480 (larger arrays cost page faults: system time 0.1-0.7 s at 120
#: rows, 1.2 s at 480).
_BATCH_ROWS = 240


def monte_carlo(mode: str, initialise: bool = True, imu_name: str = "table1") -> MonteCarloResult:
    """Cached seeded Monte Carlo (:func:`n_runs` runs) of one configuration of the Table 1 scenario.

    Keyed on the values of the inputs it reads (so the ledger's bands re-run it across the
    assumed ranges), and below that on the run's complete arguments
    (:func:`~navcore.integration.ekf_ins_gnss.monte_carlo_key`): every claim and every band corner
    that asks for the same run in this process shares one computation. Inside a band the ledger
    announces (:func:`~navcore.claims.inputs.for_each_band_run`), the first call makes every run of the
    batch at once (:func:`~navcore.integration.ekf_ins_gnss.run_monte_carlo_batch`, which gives each
    run the numbers it gets alone) and stores them for the band's later calls. The arrays of the
    result are read-only. Results are also kept on disk (a :class:`~navcore.claims.run_store.RunStore`
    in the system temporary directory, under a key hashed from the sources of every module involved
    and from the scenario), so that the
    chapter's notebooks, the ledger page and the tests share one computation per code version
    and input values. Set ``NAVCORE_NO_DISK_CACHE=1`` to recompute.
    """
    if imu_name not in ("table1", "swapped"):
        raise ValueError(f"imu_name must be 'table1' or 'swapped', got {imu_name!r}")
    ahead = for_each_band_run(
        ("KZL Monte Carlo", mode, initialise, imu_name), lambda: _run_arguments(mode, initialise, imu_name)
    )
    if ahead:
        # the band's runs that no memo or disk holds, in batched calls: one per group of scenarios
        # that can share arrays (the same ensemble size, attitude threshold and batch_group_key),
        # split at _BATCH_ROWS rows
        results = _RUNS.get_or_run_batched(
            [args for _, args in ahead],
            key=lambda args: args.key,
            label=lambda args: args.label,
            group=lambda args: (
                args.runs,
                args.extra.get("attitude_min_sats", 4),
                batch_group_key(args.scenario),
            ),
            rows=lambda args: args.runs,
            run_batch=lambda chunk: run_monte_carlo_batch(
                [args.scenario for args in chunk],
                cast(Mode, mode),
                chunk[0].runs,
                SEED,
                initialise=initialise,
                attitude_min_sats=chunk[0].extra.get("attitude_min_sats", 4),
            ),
            rows_per_call=_BATCH_ROWS,
        )
        _monte_carlo.prime(  # type: ignore[attr-defined]
            [
                (reads, _echo(result, args.scenario))
                for (reads, args), result in zip(ahead, results, strict=True)
            ],
            mode,
            initialise,
            imu_name,
        )
    return _monte_carlo(mode, initialise, imu_name)


monte_carlo.cache_clear = _monte_carlo.cache_clear  # type: ignore[attr-defined]
