"""KZL stand-alone IMU from the covariance engine, against independent oracles.

Oracles: the seeded nonlinear strapdown Monte Carlo of the same flight (a different model:
100 Hz quaternion mechanization on a flat Earth, sampled IMU errors), the closed-form growth
of a gyro bias and angle random walk, and a seeded Monte Carlo of averaging white noise.
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.inertial.error_dynamics import (
    ErrorSources,
    error_dynamics,
    initial_covariance,
    ins_error_layout,
    levelling_alignment,
)
from navcore.inertial.imu import ImuSpec, gyro_bias_calibrated_at_rest
from navcore.papers import kzl_covariance as kc
from navcore.papers.kzl_scenario import IN, N_RUNS, kzl_imu, monte_carlo
from navcore.papers.kzl_simulation import heading_closed_form_deg, t_end
from navcore.units import DEG, DEG_PER_H, DEG_PER_H_PER_SQRT_HZ, G0, MICRO_G


def test_calibrated_gyro_bias_matches_averaged_white_noise():
    """Oracle: seeded Monte Carlo of the mean of white rate noise (root PSD N) over T seconds."""
    spec = ImuSpec("x", gyro_bias=360 * DEG_PER_H, gyro_random_walk=180 * DEG_PER_H_PER_SQRT_HZ)
    T, dt = 300.0, 0.01
    rng = np.random.default_rng(7)
    samples = spec.gyro_random_walk / np.sqrt(dt) * rng.standard_normal((2000, round(T / dt)))
    residual = samples.mean(axis=1)
    got = gyro_bias_calibrated_at_rest(spec, T).gyro_bias
    assert got == pytest.approx(residual.std(), rel=4 / np.sqrt(2 * 2000))
    assert gyro_bias_calibrated_at_rest(spec, T).gyro_random_walk == spec.gyro_random_walk


def test_calibrated_gyro_bias_rejects_bad_time():
    with pytest.raises(ValueError, match="averaging_time"):
        gyro_bias_calibrated_at_rest(kzl_imu(), 0.0)


def test_levelling_cancels_tilt_and_keeps_heading_independent():
    """Oracle: at rest the levelled INS has zero horizontal velocity-error rate for every
    accelerometer bias the covariance admits (rows of F P vanish), and the heading error is
    the external one, uncorrelated with the sensors."""
    lay = ins_error_layout("position", "velocity", "misalignment", "gyro drift", "accel bias")
    spec = ImuSpec("x", gyro_bias=10 * DEG_PER_H, accel_bias=2400 * MICRO_G)
    P0 = initial_covariance(lay, ErrorSources(imu=spec))
    P = levelling_alignment(P0, lay, heading_sigma=0.5 * DEG, lat=51 * DEG)
    F = error_dynamics(lay, f_ned=(0, 0, -G0), C_bn=np.eye(3), lat=51 * DEG)
    FP, scale = F @ P, np.abs(F) @ np.abs(P)
    for row in (3, 4):
        assert np.all(np.abs(FP[row]) <= 1e-12 * np.max(scale[row]))
    a = lay.slice("misalignment")
    assert np.sqrt(P[a, a][2, 2]) == pytest.approx(0.5 * DEG, rel=1e-12)
    assert np.all(P[a.start + 2, lay.slice("gyro drift")] == 0.0)
    assert np.sqrt(P[a, a][0, 0]) == pytest.approx(2400 * MICRO_G / G0, rel=1e-12)
    with pytest.raises(ValueError, match="heading_sigma"):
        levelling_alignment(P0, lay, heading_sigma=-1.0, lat=0.0)


@pytest.mark.parametrize("initialise", [True, False])
def test_heading_follows_the_closed_form(initialise):
    """Oracle: sqrt((b t)^2 + N^2 t + sigma0^2) for a constant bias b and angle random walk N."""
    got = kc.standalone_sigma("misalignment", initialise)[2]
    want = heading_closed_form_deg(180.0, calibrated=initialise)
    assert got == pytest.approx(want, rel=2e-3)


def test_engine_agrees_with_the_strapdown_monte_carlo():
    """Oracle: the nonlinear 100 Hz strapdown Monte Carlo of the same flight. Its RMS over
    N_RUNS runs has a relative standard error 1/sqrt(2 N); allow three of them."""
    tol = 3 / np.sqrt(2 * N_RUNS)
    T_END = t_end()
    mc = monte_carlo("ins")
    for block, name in (("position", "pos_err"), ("velocity", "vel_err")):
        engine = kc.standalone_sigma(block)[:2]
        assert mc.rms(name)[T_END, :2] == pytest.approx(engine, rel=tol), block
    assert mc.rms("att_err")[T_END, 2] / DEG == pytest.approx(kc.standalone_sigma("misalignment")[2], rel=tol)
    mc_raw = monte_carlo("ins", False)
    assert mc_raw.rms("att_err")[T_END, 2] / DEG == pytest.approx(
        kc.standalone_sigma("misalignment", False)[2], rel=tol
    )


def test_longer_averaging_gives_smaller_errors():
    """The calibration residual N/sqrt(T) falls with T, and so does every 180-s error."""
    lo, hi = IN.input("init_time_s").low, IN.input("init_time_s").high
    short, nominal, long = (kc.standalone_sigma("velocity", True, t)[0] for t in (lo, IN.init_time_s, hi))
    assert short > nominal > long
