"""KZL Sec. 3.6, the stand-alone IMU numbers, from the linear covariance-analysis engine.

The chapter's seeded Monte Carlo (:mod:`navcore.papers.kzl_simulation`) runs the nonlinear
100 Hz strapdown of KZL Sec. 3.2 on 30 sampled IMUs. This module asks the same questions of
the engine built for SP Sec. 2.6 (:func:`~navcore.integration.engine.run_covariance_analysis`):
the psi-angle error model with Earth rate, transport rate and Schuler coupling, the KZL
Table 1 consumer-grade IMU as an :class:`~navcore.inertial.imu.ImuSpec`, the Table 1 flight
(110 m/s east at 51 deg N, 3 km), and an initial covariance that encodes the KZL Sec. 3.1
initialisation:

- levelling (Eqs. 2-3) ties the tilt to the horizontal accelerometer bias
  (:func:`~navcore.inertial.error_dynamics.levelling_alignment`), plus the averaged
  accelerometer noise;
- the heading comes from the GPS velocity (Eq. 4), independent, with the assumed 0.5 deg crab
  angle and the velocity noise of the Monte Carlo;
- the gyro bias is calibrated by averaging at rest
  (:func:`~navcore.inertial.imu.gyro_bias_calibrated_at_rest`) over the assumed averaging
  time (an assumed input, 150-600 s).

Without initialisation the attitude starts at its nominal value (only the crab angle is
unknown) and the sensor errors are the full Table 1 values. The engine gives the exact
1-sigma of the linear model, with no sampling error, so it checks the Monte Carlo and the
Monte Carlo checks the linearisation. A run takes milliseconds.
"""

from __future__ import annotations

import numpy as np

from navcore.claims import Claim, input_cache, printed, prose, with_quotes
from navcore.inertial.error_dynamics import (
    ErrorSources,
    initial_covariance,
    ins_error_layout,
    levelling_alignment,
)
from navcore.inertial.imu import gyro_bias_calibrated_at_rest
from navcore.inertial.trajectories import straight_and_level
from navcore.integration.engine import CovarianceAnalysis, run_covariance_analysis
from navcore.papers.kzl_quotes import QUOTES
from navcore.papers.kzl_scenario import IN, initial_fix_sigmas, kzl_imu
from navcore.papers.kzl_simulation import PAGE3
from navcore.units import DEG, G0

__all__ = [
    "CLAIMS",
    "standalone_covariance",
    "standalone_sigma",
]


def _accel_random_walk() -> float:
    """The Table 1 accelerometer's velocity random walk (m/s/sqrt(s)); the IMU must state it."""
    vrw = kzl_imu().accel_random_walk
    if vrw is None:
        raise ValueError("the KZL IMU has no accelerometer random walk")
    return vrw


@input_cache
def standalone_covariance(initialise: bool = True, init_time: float | None = None) -> CovarianceAnalysis:
    """Covariance analysis of the Table 1 flight flown on the INS alone for 180 s (1 s steps).

    Parameters
    ----------
    initialise : bool
        KZL Sec. 3.1 initialisation (levelling, GPS heading, gyro-bias calibration at rest)
        or none (nominal attitude, uncompensated sensors).
    init_time : float or None
        Averaging time of the initialisation (s); ``None`` reads the assumed input
        ``init_time_s`` (the paper does not give it).
    """
    # error states of the stand-alone INS: navigation errors and every Table 1 sensor error
    layout = ins_error_layout(
        "position",
        "velocity",
        "misalignment",
        "gyro bias",
        "gyro scale factor",
        "accel bias",
        "accel scale factor",
        name="KZL stand-alone INS",
    )
    lat, lon = IN.lat_deg * DEG, IN.lon_deg * DEG
    ve, vn = IN.velocity_east_mps, IN.velocity_north_mps
    speed = float(np.hypot(ve, vn))
    tr = straight_and_level(
        IN.duration_s,
        speed=speed,
        heading=float(np.arctan2(ve, vn)),
        dt=1.0 / IN.gps_rate_hz,  # the GPS epochs of Table 1, at which the claims read the errors
        lat0=lat,
        lon0=lon,
        h0=IN.height_m,
    )
    imu = kzl_imu()
    heading_sigma = IN.crab_angle_deg * DEG
    init_s = 0.0
    if initialise:
        init_s = IN.init_time_s if init_time is None else init_time
        imu = gyro_bias_calibrated_at_rest(imu, init_s)
    src = ErrorSources(imu=imu)
    pos0_sigma, vel0_sigma = initial_fix_sigmas()
    P0 = initial_covariance(
        layout,
        src,
        position_sigma=(pos0_sigma,) * 3,
        velocity_sigma=(vel0_sigma,) * 3,
        attitude_sigma=(0.0, 0.0, heading_sigma),
    )
    if initialise:
        P0 = levelling_alignment(
            P0,
            layout,
            # Eq. 4 on a velocity with noise vel0_sigma per axis, on top of the crab angle
            heading_sigma=float(np.hypot(heading_sigma, vel0_sigma / speed)),
            lat=lat,
            C_bn=tr.C_bn[0],
            tilt_noise_sigma=_accel_random_walk() / (G0 * np.sqrt(init_s)),
        )
    result = run_covariance_analysis(tr, layout, layout, src, P0, vertical_channel=False)
    assert not isinstance(result, list)  # one initial covariance, one run
    return result


def standalone_sigma(block: str, initialise: bool = True, init_time: float | None = None) -> np.ndarray:
    """1-sigma of ``block`` at 180 s (per axis): position m, velocity m/s, misalignment deg."""
    res = standalone_covariance(initialise, init_time)
    s = res.sigma(block)[res.at(IN.duration_s)]
    return s / DEG if block == "misalignment" else s


_C16 = printed("3", why="the paper prints an integer bound")
_C17 = printed("20", why="the paper prints an integer bound")
_ABOUT = prose("about", why="'about 1 km and 15 m/s after 3 minutes', read per horizontal axis")

_NOTE_INIT = (
    "Exact $1\\sigma$ of the linearised model (no sampling error): covariance analysis with the SP "
    "Sec. 2.6 engine ($\\psi$-angle model, Earth and transport rate), 1 s steps, the Table 1 IMU and "
    "flight. Initialisation: levelling correlated with the accelerometer bias, GPS heading with "
    "the assumed crab angle (0.5 deg, range 0.1-1), gyro bias calibrated at rest over the assumed "
    "averaging time (300 s, range 150-600); the band spans both ranges."
)

CLAIMS = [
    Claim(
        id="KZL-sec3.6-heading-with-init-covariance",
        aliases=("KZL-c16-covariance",),
        locator="Sec. 3.6",
        quantity="stand-alone IMU heading error after 180 s with initialisation (covariance engine)",
        published=_C16[0],
        relation="<",
        unit="deg",
        kind="reproduction",
        compute=lambda: float(standalone_sigma("misalignment")[2]),
        tolerance=_C16[1],
        expected_status="consistent",
        note=_NOTE_INIT + " The Monte Carlo RMS of the same flight is KZL-sec3.6-heading-with-init.",
        discussed_in=PAGE3,
        table="standalone-covariance",
    ),
    Claim(
        id="KZL-sec3.6-heading-without-init-covariance",
        aliases=("KZL-c17-covariance",),
        locator="Sec. 3.6",
        quantity="stand-alone IMU heading error after 180 s without initialisation (covariance engine)",
        published=_C17[0],
        relation=">",
        unit="deg",
        kind="reproduction",
        compute=lambda: float(standalone_sigma("misalignment", initialise=False)[2]),
        tolerance=_C17[1],
        expected_status="consistent",
        note="Exact $1\\sigma$ of the linearised model (SP Sec. 2.6 engine) with no initialisation: "
        "nominal attitude, only the assumed crab angle (0.1-1 deg) unknown, the full Table 1 gyro "
        "bias (360 deg/h) as a random constant: about 18 deg across the band, against 'larger than 20' "
        "read with its trailing zero not significant (above 15 deg). Above 20 deg would need an initial "
        "heading uncertainty of about 9 deg ($1\\sigma$) instead of the assumed 0.1-1 deg, which the "
        "model keeps from the Eq. (4) GPS-velocity heading even here; 'without initialization' may "
        "remove that heading too (the closed form $\\sqrt{(b t)^2 + N^2 t + \\sigma_0^2}$ agrees to "
        "0.1 %). One printed number, two claims: the Monte Carlo RMS is KZL-sec3.6-heading-without-init.",
        discussed_in=PAGE3,
        table="standalone-covariance",
    ),
    Claim(
        id="KZL-fig5-ins-position-covariance",
        aliases=("KZL-c22-position-covariance",),
        locator="Sec. 3.6, discussion of Fig. 5",
        quantity="stand-alone IMU position error after 3 min, per horizontal axis (covariance engine)",
        published=1.0,
        unit="km",
        kind="reproduction",
        compute=lambda: float(standalone_sigma("position")[0]) / 1000.0,
        tolerance=_ABOUT,
        expected_status="consistent",
        note=_NOTE_INIT + " 'About 1 km' read per horizontal axis (north shown; east agrees "
        "to 0.1 %). The Monte Carlo RMS is KZL-fig5-ins-position. The tolerance is the prose 'about'; the "
        "averaging time is an assumed input whose band decides.",
        discussed_in=PAGE3,
        table="standalone-covariance",
    ),
    Claim(
        id="KZL-fig5-ins-velocity-covariance",
        aliases=("KZL-c22-velocity-covariance",),
        locator="Sec. 3.6, discussion of Fig. 5",
        quantity="stand-alone IMU velocity error after 3 min, per horizontal axis (covariance engine)",
        published=15.0,
        unit="m/s",
        kind="reproduction",
        compute=lambda: float(standalone_sigma("velocity")[0]),
        tolerance=_ABOUT,
        expected_status="consistent",
        note=_NOTE_INIT + " Angle random walk ($g N \\sqrt{t^3/3}$) and the calibration residual of the "
        "gyro bias ($g b t^2/2$, $b = N / \\sqrt{T_{init}}$) add in quadrature. The Monte Carlo RMS is "
        "KZL-fig5-ins-velocity. The tolerance is the prose 'about'; the averaging time is an assumed "
        "input whose band decides.",
        discussed_in=PAGE3,
        table="standalone-covariance",
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
