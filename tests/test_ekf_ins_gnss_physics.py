"""The batched INS/GPS Monte Carlo against the physics of short, straight flights.

Oracles (none uses the filter's matrices):
* kinematics of a constant acceleration error on a flat, non-rotating Earth: an error that
  is constant in the navigation frame gives velocity errors linear and position errors
  quadratic in time, exactly, in every run;
* the statistics of that error: a body-axis accelerometer bias and scale factor seen
  through a known attitude (scipy's Rotation) give the covariance
  ``sigma_b^2 I + sigma_s^2 C diag(f_b^2) C'``;
* levelling (Titterton & Weston, Sec. 10.2): an accelerometer bias tilts the levelled
  platform by ``b / g`` and the tilt cancels it, so after levelling with calibrated gyros the
  velocity error stays what it was at the start; the track angle of a velocity measured
  with noise ``sigma_v`` at speed ``V`` errs by ``sigma_v / V``;
* a rotation about the down axis changes the heading only (3-2-1 Euler angles);
* seeded sample statistics of many runs, within 4.5 standard errors.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from navcore.inertial.imu import ImuSpec
from navcore.integration.ekf_ins_gnss import GnssNoise, Scenario, run_monte_carlo

G = 9.80665  # standard gravity (the module's G0), m/s^2
RUNS = 3000
SE = 4.5 / np.sqrt(2 * RUNS)  # 4.5 standard errors of a sample RMS, relative


def _scenario(imu, *, velocity, attitude, duration=4.0, init_time=None, gps_rate=1.0, **kw):
    sats = np.array([[2e7, 1e6, -1.5e7], [-1.8e7, 3e6, -1e7], [2e6, 2e7, -1.2e7], [-1e6, -2e7, -1.4e7]])
    K = round(duration * gps_rate)
    args = dict(
        velocity_ned=np.asarray(velocity, dtype=float),
        attitude=np.asarray(attitude, dtype=float),
        duration=duration,
        imu_rate=10.0,
        gps_rate=gps_rate,
        imu=imu,
        sat_pos_ned=np.tile(sats, (K + 1, 1, 1)),
        sat_vel_ned=np.zeros((K + 1, 4, 3)),
        n_visible=np.full(K + 1, 4),
        gnss=GnssNoise(None, None, None, None),
        init_time=init_time,
        pos0_sigma=0.0,
        vel0_sigma=0.0,
        baselines_b=None,
        accel_bias_walk=0.0,
        gyro_bias_walk=0.0,
    )
    return Scenario(**(args | kw))


def _rms(x, axis=0):
    return np.sqrt(np.mean(np.square(x), axis=axis))


def _unaligned():
    """Stand-alone INS from the nominal attitude: accelerometer bias and scale factor, a small
    true heading offset about a heading of 180 deg (so that angle errors must be wrapped); no
    gyro errors, no noise, exact initial position and velocity. The filter models a random walk
    of the accelerometer biases (the true biases are constant)."""
    imu = ImuSpec("test", accel_bias=0.02, accel_scale_factor=2e-3)
    att = np.array([0.1, -0.05, np.pi - 4e-4])  # true headings on both sides of +-180 deg
    sc = _scenario(imu, velocity=[80.0, 60.0, 0.0], attitude=att, heading_sigma=1e-3, accel_bias_walk=1e-3)
    return sc, att, run_monte_carlo(sc, "ins", RUNS, 5, initialise=False)


def _check_unaligned_ins_errors_are_constant_acceleration_kinematics(unaligned):
    """Oracle: kinematics (v = a t, p = a t^2 / 2 per run, exactly) and the covariance of
    a = C (b + s * f_b) with f_b = C' (0, 0, -g) from scipy's Rotation."""
    _sc, att, r = unaligned
    np.testing.assert_array_equal(r.t, [0.0, 1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(r.n_visible, np.full(5, 4))
    assert r.pos_err.shape == r.vel_err.shape == r.att_err.shape == (RUNS, 5, 3)
    np.testing.assert_array_equal(r.pos_err[:, 0], 0.0)
    np.testing.assert_array_equal(r.vel_err[:, 0], 0.0)
    a = r.vel_err[:, 1]
    for k in range(1, 5):
        np.testing.assert_allclose(r.vel_err[:, k], a * k, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(r.pos_err[:, k], a * k**2 / 2, rtol=1e-9, atol=1e-12)
    C = Rotation.from_euler("ZYX", att[::-1]).as_matrix()  # body to NED, 3-2-1
    f_b = C.T @ [0.0, 0.0, -G]
    cov = 0.02**2 * np.eye(3) + (2e-3) ** 2 * C @ np.diag(f_b**2) @ C.T
    W = np.linalg.inv(np.linalg.cholesky(cov))
    ev = np.linalg.eigvalsh(W @ (a.T @ a / RUNS) @ W.T)
    assert np.all(np.abs(np.sqrt(ev) - 1) < SE), ev
    # no gyro error: roll and pitch exact, the heading error is the true offset, constant
    np.testing.assert_allclose(r.att_err[:, :, :2], 0.0, atol=1e-12)
    for k in range(5):
        np.testing.assert_allclose(r.att_err[:, k, 2], r.att_err[:, 0, 2], atol=1e-12)
    assert _rms(r.att_err[:, 0, 2]) == pytest.approx(1e-3, rel=SE)
    assert np.abs(r.att_err).max() < 0.01  # wrapped to (-180, 180] deg, never ~360 deg
    assert abs(np.mean(r.att_err[:, 0, 2])) < 4.5 * 1e-3 / np.sqrt(RUNS)


def _check_unaligned_ins_filter_sigma_matches_truth(unaligned):
    """Oracle: the filter spreads the scale-factor variance evenly over the axes, so its total
    velocity variance from the turn-on errors equals the trace of the true covariance,
    (3 sigma_b^2 + sigma_s^2 g^2) t^2, and position follows as t^4 / 4; the modelled bias random
    walk (PSD q, a triple integrator) adds q t^3 / 3 to each velocity and q t^5 / 20 to each
    position variance. Its heading 1-sigma is the offset's, roll and pitch are 0."""
    _sc, _att, r = unaligned
    t = r.t
    tr_v = (3 * 0.02**2 + (2e-3 * G) ** 2) * t**2
    q = 1e-3**2
    np.testing.assert_allclose(np.sum(r.vel_sigma**2, axis=1), tr_v + q * t**3, rtol=1e-6)
    np.testing.assert_allclose(np.sum(r.pos_sigma**2, axis=1), tr_v * t**2 / 4 + 3 * q * t**5 / 20, rtol=1e-6)
    np.testing.assert_allclose(r.vel_sigma[:, 0], r.vel_sigma[:, 1], rtol=1e-6)
    np.testing.assert_allclose(r.att_sigma[:, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(r.att_sigma[:, 2], 1e-3, rtol=1e-6)
    # the truth agrees: sum of the per-axis mean squares, within sampling error
    assert np.sum(r.rms("vel_err")[-1] ** 2) == pytest.approx(tr_v[-1], rel=2 * SE)
    np.testing.assert_allclose(
        r.horizontal_rms("pos_err"), _rms(np.hypot(r.pos_err[..., 0], r.pos_err[..., 1]))
    )


def _levelled():
    """Stand-alone INS after levelling and gyro calibration with noise-free sensors: a level
    flight on the track angle, accelerometer and gyro biases, noisy initial position,
    velocity and a true heading offset."""
    imu = ImuSpec("test", accel_bias=0.01, gyro_bias=1e-4)
    v = np.array([80.0, 60.0, 0.0])
    sc = _scenario(
        imu,
        velocity=v,
        attitude=[0.0, 0.0, np.arctan2(60.0, 80.0)],
        init_time=60.0,
        pos0_sigma=1.5,
        vel0_sigma=0.05,
        heading_sigma=2e-3,
        duration=3.0,
    )
    return sc, run_monte_carlo(sc, "ins", RUNS, 11)


def _check_levelling_cancels_the_accelerometer_bias(levelled):
    """Oracle: levelling (the tilt b/g cancels the bias; calibrated gyros hold the attitude),
    so velocity and attitude errors keep their initial values and position grows linearly;
    the initial errors have the scenario's spreads, the tilts b/g, the heading the crab
    angle and the track-angle error sigma_v / V."""
    _sc, r = levelled
    for k in range(4):
        np.testing.assert_allclose(r.vel_err[:, k], r.vel_err[:, 0], atol=1e-9)
        np.testing.assert_allclose(r.att_err[:, k], r.att_err[:, 0], atol=1e-10)
        np.testing.assert_allclose(r.pos_err[:, k], r.pos_err[:, 0] + r.vel_err[:, 0] * k, atol=1e-8)
    np.testing.assert_allclose(r.rms("pos_err")[0], 1.5, rtol=SE)
    np.testing.assert_allclose(r.rms("vel_err")[0], 0.05, rtol=SE)
    heading = np.hypot(2e-3, 0.05 / 100.0)
    np.testing.assert_allclose(r.rms("att_err")[0], [0.01 / G, 0.01 / G, heading], rtol=SE)
    # roll and pitch errors come from different bias axes: uncorrelated
    rho = np.corrcoef(r.att_err[:, 0, 0], r.att_err[:, 0, 1])[0, 1]
    assert abs(rho) < 4.5 / np.sqrt(RUNS)


def _check_levelled_filter_sigma_matches_truth(levelled):
    """Oracle: the same levelling physics for the filter's own 1-sigma: velocity stays
    sigma_v (the tilt/bias correlation cancels the bias), position grows as
    sqrt(sigma_p^2 + sigma_v^2 t^2), tilt b/g, heading sqrt(crab^2 + (sigma_v / V)^2)."""
    _sc, r = levelled
    np.testing.assert_allclose(r.vel_sigma, 0.05, rtol=1e-6)
    np.testing.assert_allclose(
        r.pos_sigma, np.sqrt(1.5**2 + 0.05**2 * r.t**2)[:, None] * np.ones(3), rtol=1e-6
    )
    heading = np.hypot(2e-3, 0.05 / 100.0)
    np.testing.assert_allclose(r.att_sigma, np.tile([0.01 / G, 0.01 / G, heading], (4, 1)), rtol=1e-4)


SATS = np.array([[2e7, 1e6, -1.5e7], [-1.8e7, 3e6, -1e7], [2e6, 2e7, -1.2e7], [-1e6, -2e7, -1.4e7]])
SAT_VEL = np.array(
    [[300.0, -2500.0, 800.0], [-1200.0, 900.0, 2000.0], [2800.0, 100.0, -400.0], [0.0, 1500.0, 2500.0]]
)
VISIBLE = np.array([4, 4, 0, 1, 4, 2])  # satellites in view at each epoch: a gap, and one alone
BASELINES = np.array([[1.5, 0.4, 0.0], [-0.3, 1.2, 0.1], [0.2, -0.9, 0.4]])  # three, not the usual two
PHASE_M = 0.005  # undifferenced carrier-phase noise, m
LAMBDA = 299_792_458.0 / 1_575.42e6  # GPS L1 wavelength, m


def _aided():
    """Perfect IMU, no initialisation, GPS at 2 Hz: the errors come from the initial position,
    velocity, clock and heading uncertainty, the clock's random walks and the GPS noises. The
    visibility drops to none, three and two satellites (no update; no attitude rows below
    four; a single DD satellite pair)."""
    sc = _scenario(
        ImuSpec("perfect"),
        velocity=[80.0, 60.0, 0.0],
        attitude=[0.05, 0.02, 0.6],
        duration=2.5,
        gps_rate=2.0,
        sat_pos_ned=np.tile(SATS, (6, 1, 1)),
        sat_vel_ned=np.tile(SAT_VEL, (6, 1, 1)),
        n_visible=VISIBLE,
        gnss=GnssNoise(1.5, 0.1, PHASE_M, 2e-3),
        pos0_sigma=5.0,
        vel0_sigma=0.3,
        heading_sigma=0.01,
        clock_bias_sigma=30.0,
        clock_drift_sigma=1.3,
        clock_phase_walk=3.0,
        clock_drift_walk=1.2,
        baselines_b=BASELINES,
    )
    return sc, {m: run_monte_carlo(sc, m, 2000, 21, initialise=False) for m in ("tc", "tc_att", "tc_dd")}


def _linear_kf_position_velocity(sc):
    """Independent 8-state filter (position, velocity, clock bias and drift; the IMU is perfect,
    so nothing else is uncertain): p' = v, b' = d plus the clock walks; pseudorange rows
    (-u, 0, 1, 0), range-rate rows (0, -u, 0, 1) with u the unit vector to the satellite
    (d range / d position = -u). Posterior by the information form. Returns the 1-sigma of
    position and velocity at each epoch."""
    T, sp, sv = 1.0 / sc.gps_rate, sc.pos0_sigma, sc.vel0_sigma
    qb, qd = sc.clock_phase_walk**2, sc.clock_drift_walk**2
    P = np.diag([sp**2] * 3 + [sv**2] * 3 + [sc.clock_bias_sigma**2, sc.clock_drift_sigma**2])
    Phi = np.eye(8)
    Phi[:3, 3:6] = T * np.eye(3)
    Phi[6, 7] = T
    Q = np.zeros((8, 8))
    Q[6:, 6:] = [[qb * T + qd * T**3 / 3, qd * T**2 / 2], [qd * T**2 / 2, qd * T]]
    out = [np.sqrt(np.diag(P)[:6])]
    for k in range(1, VISIBLE.size):
        P = Phi @ P @ Phi.T + Q
        nu = VISIBLE[k]
        if nu:
            x = sc.velocity_ned * k * T
            u = (SATS[:nu] - x) / np.linalg.norm(SATS[:nu] - x, axis=1, keepdims=True)
            H = np.zeros((2 * nu, 8))
            H[:nu, :3], H[:nu, 6] = -u, 1.0
            H[nu:, 3:6], H[nu:, 7] = -u, 1.0
            Rinv = np.diag([1 / sc.gnss.pseudorange**2] * nu + [1 / sc.gnss.delta_range**2] * nu)
            P = np.linalg.inv(np.linalg.inv(P) + H.T @ Rinv @ H)
        out.append(np.sqrt(np.diag(P)[:6]))
    return np.array(out)


def _check_tightly_coupled_position_velocity_match_linear_filter(aided):
    """Oracle: the independent 8-state linear filter (information form) for the filter's
    1-sigma, and the sample RMS of 2000 runs for the true errors, at every epoch; with a
    perfect IMU and no tilt, the attitude rows (where used) see the heading only."""
    sc, res = aided
    want = _linear_kf_position_velocity(sc)
    for mode, r in res.items():
        np.testing.assert_allclose(r.pos_sigma, want[:, :3], rtol=2e-5, err_msg=mode)
        np.testing.assert_allclose(r.vel_sigma, want[:, 3:], rtol=2e-5, err_msg=mode)
        se = 4.5 / np.sqrt(2 * 2000)
        np.testing.assert_allclose(r.rms("pos_err"), want[:, :3], rtol=se, err_msg=mode)
        np.testing.assert_allclose(r.rms("vel_err"), want[:, 3:], rtol=se, err_msg=mode)
    np.testing.assert_array_equal(res["tc"].n_visible, VISIBLE)
    np.testing.assert_array_equal(res["tc"].t, np.arange(VISIBLE.size) / sc.gps_rate)
    # without attitude information the heading error stays the crab angle
    tc = res["tc"]
    np.testing.assert_allclose(tc.att_sigma[:, 2], 0.01, rtol=1e-6)
    np.testing.assert_allclose(tc.att_err[:, :, 2], tc.att_err[:, :1, 2] * np.ones(6), atol=1e-12)


def _check_attitude_rows_add_heading_information(aided):
    """Oracle: scalar information accumulation for the heading, 1/s^2 = 1/crab^2 + n/sigma_att^2
    after n epochs with at least four satellites (the Euler heading responds one-to-one to a
    rotation about the down axis; roll and pitch have no prior uncertainty and stay exact);
    the sample RMS of the heading error over 2000 runs agrees."""
    sc, res = aided
    r = res["tc_att"]
    n_att = np.cumsum(VISIBLE >= 4) - (VISIBLE[0] >= 4)  # epochs 1.. with four satellites
    want = 1 / np.sqrt(1 / 0.01**2 + n_att / 2e-3**2)
    np.testing.assert_allclose(r.att_sigma[:, 2], want, rtol=1e-6)
    np.testing.assert_allclose(r.att_sigma[:, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(r.rms("att_err")[:, 2], want, rtol=4.5 / np.sqrt(4000))
    np.testing.assert_allclose(r.att_err[:, :, :2], 0.0, atol=1e-9)
    # fewer than four satellites: the heading is not measured, unless the threshold allows it
    low = run_monte_carlo(sc, "tc_att", 50, 21, initialise=False, attitude_min_sats=2)
    n_low = np.cumsum(VISIBLE >= 2) - (VISIBLE[0] >= 2)
    np.testing.assert_allclose(low.att_sigma[:, 2], 1 / np.sqrt(1 / 0.01**2 + n_low / 2e-3**2), rtol=1e-6)


def _dd_heading_information(sc, k):
    """Heading information of one epoch's DD phases: the rows by central finite differences
    of the exact DD geometry under a rotation about the down axis (scipy Rotation), the
    covariance sigma^2 D D' with the differencing matrix D written out (antenna 0 and
    satellite 0 the references)."""
    from navcore.gnss.carrier_phase import double_difference_phase

    nu = VISIBLE[k]
    x = sc.velocity_ned * k / sc.gps_rate
    C = Rotation.from_euler("ZYX", sc.attitude[::-1]).as_matrix()

    def dd(angle):
        R = Rotation.from_rotvec([0.0, 0.0, angle]).as_matrix()
        ant = (R @ C @ BASELINES.T).T
        return np.array(
            [double_difference_phase(SATS[0], SATS[s], x, x + a) for s in range(1, nu) for a in ant]
        )

    h = (dd(1e-6) - dd(-1e-6)) / 2e-6
    nb = BASELINES.shape[0]
    D = np.zeros(((nu - 1) * nb, nu * (nb + 1)))  # undifferenced phases ordered (satellite, antenna)
    for s in range(1, nu):
        for j in range(1, nb + 1):
            row = (s - 1) * nb + (j - 1)
            D[row, s * (nb + 1) + j], D[row, s * (nb + 1)] = 1.0, -1.0
            D[row, j], D[row, 0] = -1.0, 1.0
    R_dd = (2 * np.pi * PHASE_M / LAMBDA) ** 2 * D @ D.T
    return float(h @ np.linalg.solve(R_dd, h))


def _check_double_difference_phases_add_heading_information(aided):
    """Oracle: heading information summed over the epochs with at least two satellites
    (finite-difference DD rows, hand-built DD covariance); the sample RMS over 2000 runs."""
    sc, res = aided
    r = res["tc_dd"]
    info = np.full(VISIBLE.size, 1 / 0.01**2)
    for k in range(1, VISIBLE.size):
        info[k:] += _dd_heading_information(sc, k) if VISIBLE[k] >= 2 else 0.0
    want = 1 / np.sqrt(info)
    assert want[-1] < 0.2 * want[0]  # the DDs do inform the heading
    np.testing.assert_allclose(r.att_sigma[:, 2], want, rtol=3e-3)
    np.testing.assert_allclose(r.rms("att_err")[:, 2], want, rtol=4.5 / np.sqrt(4000))


def test_levelling_with_noisy_sensors():
    """Oracle: the averaging of white sensor noise over the initialisation time T: the tilt
    variance is (b^2 + N_a^2 / T) / g^2; the gyro-bias estimate errs by N_g / sqrt(T), so the
    heading variance grows as crab^2 + (sigma_v / V)^2 + (N_g^2 / T) t^2 + N_g^2 t (the last
    term the angle random walk); the vertical velocity variance as sigma_v^2 + (N_a^2 / T) t^2
    + N_a^2 t; filter 1-sigma and the RMS of 3000 runs. The filter's modelled gyro-bias random
    walk adds q t^3 / 3."""
    imu = ImuSpec("test", accel_bias=0.01, accel_random_walk=0.05, gyro_bias=1e-4, gyro_random_walk=1e-3)
    T0, hs, sv, V = 2.0, 5e-4, 0.02, 100.0  # a short averaging: its gyro-bias error dominates
    sc = _scenario(
        imu,
        velocity=[80.0, 60.0, 0.0],
        attitude=[0.0, 0.0, np.arctan2(60.0, 80.0)],
        init_time=T0,
        pos0_sigma=1.7,
        vel0_sigma=sv,
        heading_sigma=hs,
        duration=3.0,
        gyro_bias_walk=1e-4,
    )
    r = run_monte_carlo(sc, "ins", RUNS, 17)
    tilt = np.sqrt(0.01**2 + 0.05**2 / T0) / G
    heading = np.sqrt(hs**2 + (sv / V) ** 2 + (1e-3**2 / T0) * r.t**2 + 1e-3**2 * r.t)
    np.testing.assert_allclose(r.att_sigma[0, :2], tilt, rtol=1e-4)
    # the filter also models a gyro-bias random walk (PSD q): + q t^3 / 3 (the truth has none)
    np.testing.assert_allclose(r.att_sigma[:, 2], np.sqrt(heading**2 + 1e-4**2 * r.t**3 / 3), rtol=1e-3)
    np.testing.assert_allclose(r.rms("att_err")[0, :2], tilt, rtol=SE)
    np.testing.assert_allclose(r.rms("att_err")[:, 2], heading, rtol=SE)
    # vertical: the bias calibration errs by N_a / sqrt(T) (a velocity error growing as t)
    # and the white noise integrates to a random walk N_a^2 t, on top of the initial sigma_v
    vz = np.sqrt(sv**2 + (0.05**2 / T0) * r.t**2 + 0.05**2 * r.t)
    np.testing.assert_allclose(r.vel_sigma[:, 2], vz, rtol=1e-5)
    np.testing.assert_allclose(r.rms("vel_err")[:, 2], vz, rtol=SE)
    # every error source is zero-mean and independent from run to run, so the heading error
    # averages out over the runs: within 4.5 standard errors of 0 at every epoch
    assert np.all(np.abs(np.mean(r.att_err[:, :, 2], axis=0)) < 4.5 * heading / np.sqrt(RUNS))


def _check_modes_share_the_random_numbers(aided):
    """Oracle: the documented common random numbers: every mode draws the same truth, so the
    errors before the first GPS epoch are identical across modes."""
    _, res = aided
    for name in ("pos_err", "vel_err", "att_err"):
        ref = getattr(res["tc"], name)[:, 0]
        assert np.std(ref) > 0
        for mode in ("tc_att", "tc_dd"):
            np.testing.assert_array_equal(getattr(res[mode], name)[:, 0], ref)


def test_unaligned_gyro_bias_tilts_and_accelerates():
    """Oracle: a gyro bias b_g (1-sigma per axis) turns the attitude by b_g t about every axis;
    on a flat Earth the tilt resolves gravity into a horizontal acceleration g b_g t, so the
    horizontal velocity and position errors grow as g b_g t^2 / 2 and g b_g t^3 / 6, the vertical
    ones stay zero (Titterton & Weston, short-term error propagation); filter 1-sigma and the RMS
    of 3000 runs."""
    sg = 2e-4
    sc = _scenario(ImuSpec("test", gyro_bias=sg), velocity=[80.0, 60.0, 0.0], attitude=[0.0, 0.0, 0.6])
    r = run_monte_carlo(sc, "ins", RUNS, 9, initialise=False)
    t = r.t[:, None]
    att = sg * t * np.ones(3)
    vel = G * sg * t**2 / 2 * np.array([1.0, 1.0, 0.0])
    pos = G * sg * t**3 / 6 * np.array([1.0, 1.0, 0.0])
    np.testing.assert_allclose(r.att_sigma, att, rtol=1e-3)
    np.testing.assert_allclose(r.vel_sigma[:, :2], vel[:, :2], rtol=1e-3)
    np.testing.assert_allclose(r.pos_sigma[:, :2], pos[:, :2], rtol=1e-3)
    # vertical: second order only (the horizontal specific force of the tilted estimate)
    assert np.all(r.vel_sigma[1:, 2] < 1e-3 * vel[1:, 0])
    assert np.all(r.pos_sigma[1:, 2] < 1e-3 * pos[1:, 0])
    np.testing.assert_allclose(r.rms("att_err")[1:], att[1:], rtol=SE)
    np.testing.assert_allclose(r.rms("vel_err")[1:, :2], vel[1:, :2], rtol=SE)
    np.testing.assert_allclose(r.rms("pos_err")[1:, :2], pos[1:, :2], rtol=SE)
    assert np.abs(r.vel_err[..., 2]).max() < 1e-2 * np.abs(r.vel_err[..., :2]).max()  # g (1 - cos tilt)


@pytest.mark.parametrize(
    ("mode", "gnss", "kw", "message"),
    [
        (
            "ins",
            (None, None, None, None),
            {"init_time": None},
            "sc.init_time must be given for an initialising run",
        ),
        ("tc", (None, 0.1, None, None), {}, "sc.gnss.pseudorange must be given for mode 'tc'"),
        ("tc", (1.5, None, None, None), {}, "sc.gnss.delta_range must be given for mode 'tc'"),
        ("tc_att", (1.5, 0.1, None, None), {}, "sc.gnss.attitude must be given for mode 'tc_att'"),
        (
            "tc_dd",
            (1.5, 0.1, None, None),
            {"baselines_b": None},
            "sc.baselines_b must be given for mode 'tc_dd'",
        ),
        ("tc_dd", (1.5, 0.1, None, None), {}, "sc.gnss.phase must be given for mode 'tc_dd'"),
    ],
)
def test_a_missing_scenario_input_is_named(mode, gnss, kw, message):
    """Oracle: the documented needs of each mode (initialising needs an initialisation time;
    code and range-rate updates their noises; attitude rows theirs; double differences the
    antenna baselines and the phase noise): the error names the missing field, as the caller
    reaches it from the scenario, and the mode that needs it."""
    args = {"init_time": 10.0, "baselines_b": np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])} | kw
    sc = _scenario(
        ImuSpec("test"), velocity=[50.0, 0.0, 0.0], attitude=[0.0, 0.0, 0.0], gnss=GnssNoise(*gnss), **args
    )
    with pytest.raises(ValueError, match="^" + re.escape(message) + ", got None$"):
        run_monte_carlo(sc, mode, 2, 0, initialise=mode == "ins")


def test_accelerometer_scale_factor_multiplies_the_specific_force():
    """Oracle: a scale-factor error s scales the sensed specific force, f_sensed = (1 + s) f,
    with s ~ N(0, sigma_s^2) per axis and run. Level and at rest but for the speed, the only
    specific force is -g along the down axis, so the down velocity error after t is -g s t in
    each run: its normalised values must be a sample of N(0, 1) (Kolmogorov-Smirnov, scipy),
    and its mean 0 within 4.5 standard errors. A large sigma_s = 0.15 makes the law of s tell
    (1 + s) f from f / (1 + s), whose mean is sigma_s^2 off and whose law is skewed."""
    from scipy import stats

    sigma_s = 0.15
    sc = _scenario(
        ImuSpec("test", accel_scale_factor=sigma_s),
        velocity=[50.0, 0.0, 0.0],
        attitude=[0.0, 0.0, 0.0],
        duration=1.0,
    )
    r = run_monte_carlo(sc, "ins", RUNS, 23, initialise=False)
    z = r.vel_err[:, 1, 2] / (-G * 1.0 * sigma_s)  # s / sigma_s in each run
    np.testing.assert_allclose(r.vel_err[:, 1, :2], 0.0, atol=1e-9)
    assert abs(np.mean(z)) < 4.5 / np.sqrt(RUNS)
    assert stats.kstest(z, "norm").pvalue > 1e-4


def test_accelerometer_white_noise_is_a_velocity_random_walk():
    """Oracle: white accelerometer noise of root PSD N_a integrates to a velocity random walk,
    variance N_a^2 t per axis (exact for the sampled noise too), and to a position variance
    N_a^2 t^3 / 3 (the filter's continuous model); filter 1-sigma and the RMS of 3000 runs."""
    na = 0.03
    sc = _scenario(
        ImuSpec("test", accel_random_walk=na), velocity=[80.0, 60.0, 0.0], attitude=[0.0, 0.0, 0.6]
    )
    r = run_monte_carlo(sc, "ins", RUNS, 13, initialise=False)
    t = r.t[:, None] * np.ones(3)
    np.testing.assert_allclose(r.vel_sigma, na * np.sqrt(t), rtol=1e-9)
    np.testing.assert_allclose(r.pos_sigma, na * np.sqrt(t**3 / 3), rtol=1e-9)
    np.testing.assert_allclose(r.rms("vel_err")[1:], na * np.sqrt(t[1:]), rtol=SE)
    np.testing.assert_allclose(r.att_err, 0.0, atol=1e-12)


def test_all_errors_on_filter_is_consistent():
    """Oracle: seeded Monte Carlo of the physics (strapdown on simulated sensor outputs with
    every IMU error, geometric ranges, range rates and DD phases, random clock): after
    levelling and with every aiding mode, the RMS over 800 runs of each position, velocity and
    attitude error component matches the filter's 1-sigma at every epoch within 4.5 standard
    errors of an RMS (11 %), so the feedback of every estimated state is right."""
    imu = ImuSpec(
        "test",
        accel_bias=0.01,
        accel_scale_factor=5e-4,
        accel_random_walk=0.01,
        gyro_bias=5e-5,
        gyro_random_walk=2e-4,
    )
    K, n = 10, 800
    sc = _scenario(
        imu,
        velocity=[80.0, 60.0, 0.0],
        attitude=[0.05, 0.02, np.arctan2(60.0, 80.0)],
        duration=5.0,
        gps_rate=2.0,
        sat_pos_ned=np.tile(SATS, (K + 1, 1, 1)),
        sat_vel_ned=np.tile(SAT_VEL, (K + 1, 1, 1)),
        n_visible=np.full(K + 1, 4),
        gnss=GnssNoise(1.0, 0.05, PHASE_M, 1e-3),
        init_time=30.0,
        pos0_sigma=3.0,
        vel0_sigma=0.1,
        heading_sigma=5e-3,
        baselines_b=BASELINES,
        accel_bias_walk=1e-4,
        gyro_bias_walk=1e-6,
    )
    tol = 4.5 / np.sqrt(2 * n)
    for mode in ("tc", "tc_att", "tc_dd"):
        r = run_monte_carlo(sc, mode, n, 3)
        for name, sig in (("pos_err", r.pos_sigma), ("vel_err", r.vel_sigma), ("att_err", r.att_sigma)):
            ratio = r.rms(name)[1:] / sig[1:]
            assert np.all(np.abs(ratio - 1) < tol), (mode, name, ratio)


# mutmut maps each model function to the tests that call it; a module-scoped fixture would be
# attributed to the first test only, so each scenario runs inside one test that makes all checks.


def test_unaligned_scenario():
    """Oracles: constant-acceleration kinematics per run, the bias/scale-factor covariance
    through a scipy attitude, and the filter's total variance against its trace and the
    triple-integrator bias walk (the two checks above)."""
    data = _unaligned()
    _check_unaligned_ins_errors_are_constant_acceleration_kinematics(data)
    _check_unaligned_ins_filter_sigma_matches_truth(data)


def test_levelled_scenario():
    """Oracles: levelling physics (the tilt b/g cancels the bias) for truth and filter 1-sigma,
    the track-angle error sigma_v / V (the two checks above)."""
    data = _levelled()
    _check_levelling_cancels_the_accelerometer_bias(data)
    _check_levelled_filter_sigma_matches_truth(data)


def test_aided_scenario():
    """Oracles: an independent 8-state linear filter for position and velocity, scalar heading
    information from the attitude rows and from finite-difference DD rows, sample RMS over 2000
    runs, and the common random numbers of the modes (the four checks above)."""
    data = _aided()
    _check_tightly_coupled_position_velocity_match_linear_filter(data)
    _check_attitude_rows_add_heading_information(data)
    _check_double_difference_phases_add_heading_information(data)
    _check_modes_share_the_random_numbers(data)
