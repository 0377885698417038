"""IMU specification helpers and the SP Table 2.5 grades against hand conversions."""

from __future__ import annotations

import math

import numpy as np
import pytest

from navcore.inertial.imu import (
    ImuSpec,
    angle_random_walk_deg_per_sqrt_h,
    gyro_bias_calibrated_at_rest,
    imu_spec_from_published,
    noise_only,
    velocity_random_walk_m_per_s_per_sqrt_h,
)
from navcore.papers.sp_tables import sp_imu_grades, table_2_4, table_2_8
from navcore.units import DEG_PER_H, DEG_PER_H_PER_SQRT_HZ


def test_random_walk_conversions_by_hand():
    """Oracle: 1 deg/h/sqrt(Hz) = 1/60 deg/sqrt(h); 1 micro-g/sqrt(Hz) = 9.80665e-6*60 m/s/sqrt(h)."""
    assert angle_random_walk_deg_per_sqrt_h(4.7) == pytest.approx(4.7 / 60, rel=1e-12)
    assert velocity_random_walk_m_per_s_per_sqrt_h(56.0) == pytest.approx(56 * 9.80665e-6 * 60, rel=1e-12)
    with pytest.raises(ValueError, match="root_psd"):
        angle_random_walk_deg_per_sqrt_h(-1.0)


def test_sp_grades_si_values():
    """Oracle: hand conversions of Table 2.5 entries (deg/h -> rad/s, micro-g -> m/s^2)."""
    g = sp_imu_grades()
    assert set(g) == {10.0, 1.0, 0.5, 0.2}
    assert g[10.0].gyro_bias == pytest.approx(0.11 * math.pi / 180 / 3600)
    assert g[1.0].accel_bias == pytest.approx(37e-6 * 9.80665)
    assert g[0.2].gyro_random_walk == pytest.approx(0.03 * math.pi / 180 / 3600)
    assert g[0.5].accel_misalignment == pytest.approx(1.5 * math.pi / 180 / 3600)
    n = noise_only(g[10.0])
    assert n.gyro_bias == 0.0 and n.gyro_random_walk == g[10.0].gyro_random_walk


def test_table_2_4_and_2_8_conversions():
    """Oracle: 1e-2 ppm x c = 2.998 m/s; 0.1 nmi/h = 0.05144 m/s."""
    t = table_2_4()
    assert t["clock initial drift"].si == pytest.approx(2.99792458, rel=1e-9)
    assert t["gravity (Markov) distance"].si == 37_000.0
    assert table_2_8().bias_horizontal == pytest.approx(185.2 / 3600, rel=1e-12)
    assert table_2_8().misalignment == pytest.approx(2e-3)


def test_calibrated_gyro_bias_matches_averaged_white_noise():
    """Oracle: seeded Monte Carlo of the mean of white rate noise (root PSD N) over T seconds."""
    spec = ImuSpec("x", gyro_bias=360 * DEG_PER_H, gyro_random_walk=180 * DEG_PER_H_PER_SQRT_HZ)
    T, dt = 300.0, 0.01
    rng = np.random.default_rng(7)
    samples = spec.gyro_random_walk / np.sqrt(dt) * rng.standard_normal((2000, round(T / dt)))
    residual = samples.mean(axis=1)
    got = gyro_bias_calibrated_at_rest(spec, T)
    assert got.gyro_bias == pytest.approx(residual.std(), rel=4 / np.sqrt(2 * 2000))
    assert got.gyro_random_walk == spec.gyro_random_walk
    with pytest.raises(ValueError, match="averaging_time"):
        gyro_bias_calibrated_at_rest(spec, 0.0)


def test_published_units_convert_to_si():
    """Oracle: hand unit conversions, each field a distinct value: 1 micro-g = 9.80665e-6
    m/s^2, 1 ppm = 1e-6, 1 arcsec = pi/648000 rad, 1 deg/h = pi/648000 rad/s, 1 deg/h/sqrt(Hz)
    = pi/648000 rad/sqrt(s), 1 micro-g/sqrt(Hz) = 9.80665e-6 m/s/sqrt(s)."""
    arc = math.pi / 648_000
    s = imu_spec_from_published(
        "grade",
        accel_bias_micro_g=100.0,
        accel_scale_factor_ppm=200.0,
        accel_misalignment_arcsec=3.0,
        accel_random_walk_micro_g_per_sqrt_hz=40.0,
        gyro_bias_deg_per_h=0.5,
        gyro_scale_factor_ppm=60.0,
        gyro_misalignment_arcsec=7.0,
        gyro_random_walk_deg_per_h_per_sqrt_hz=0.08,
        source="table",
    )
    assert s.accel_bias == pytest.approx(100.0 * 9.80665e-6, rel=1e-12)
    assert s.accel_scale_factor == pytest.approx(200e-6, rel=1e-12)
    assert s.accel_misalignment == pytest.approx(3.0 * arc, rel=1e-12)
    assert s.accel_random_walk == pytest.approx(40.0 * 9.80665e-6, rel=1e-12)
    assert s.gyro_bias == pytest.approx(0.5 * arc, rel=1e-12)
    assert s.gyro_scale_factor == pytest.approx(60e-6, rel=1e-12)
    assert s.gyro_misalignment == pytest.approx(7.0 * arc, rel=1e-12)
    assert s.gyro_random_walk == pytest.approx(0.08 * arc, rel=1e-12)
    assert (s.name, s.source) == ("grade", "table")


def test_scaled_and_noise_only_specs():
    """Oracle: the definitions: scaling multiplies every error by the factor (each field a
    distinct value, so a field lost or swapped shows); the noise-only instrument keeps the
    two random walks and nothing else."""
    values = dict(  # distinct, and within each source's plausible range (IMU_SPEC_LIMITS)
        gyro_bias=0.001,
        gyro_scale_factor=0.002,
        gyro_misalignment=0.003,
        gyro_random_walk=0.0004,
        accel_bias=0.005,
        accel_scale_factor=0.006,
        accel_misalignment=0.007,
        accel_random_walk=0.008,
    )
    spec = ImuSpec("base", source="src", **values)
    half = spec.scaled(0.5)
    for k, v in values.items():
        assert getattr(half, k) == 0.5 * v, k
    assert half.name == "base x 0.5" and half.source == "src"
    assert spec.scaled(3.0, name="tripled").name == "tripled"
    n = noise_only(spec)
    assert (n.gyro_random_walk, n.accel_random_walk) == (0.0004, 0.008)
    for k in values:
        if "random_walk" not in k:
            assert getattr(n, k) == 0.0, k
    assert n.source == "src" and n.name == "base (noise only)"
    with pytest.raises(ValueError, match="factor"):
        spec.scaled(-1.0)


def test_bad_input_rejects_negative_sigmas():
    """Every 1-sigma and root PSD of a spec must be >= 0 (the name and source are text)."""
    for field in ("gyro_bias", "accel_misalignment", "accel_random_walk"):
        with pytest.raises(ValueError, match=field):
            ImuSpec("x", **{field: -1e-6})


def test_implausible_values_are_unit_mistakes():
    """Issue 30, case 10: 1 rad/s of gyro bias is 206 000 deg/h, a value typed in deg/h; each
    source has a limit beyond any sensor (IMU_SPEC_LIMITS) and the message names the field and
    the unit it was probably given in. A value just below the limit is accepted."""
    from navcore.inertial.imu import IMU_SPEC_LIMITS
    from navcore.units import DEG_PER_H

    with pytest.raises(ValueError, match=r"ImuSpec\.gyro_bias must be <= 0\.1 rad/s .*DEG_PER_H"):
        ImuSpec("x", gyro_bias=1.0)
    for field, (limit, _) in IMU_SPEC_LIMITS.items():
        ImuSpec("ok", **{field: limit})
        with pytest.raises(ValueError, match=rf"ImuSpec\.{field} must be <="):
            ImuSpec("bad", **{field: 1.01 * limit})
    assert ImuSpec("consumer", gyro_bias=1000 * DEG_PER_H).gyro_bias < IMU_SPEC_LIMITS["gyro_bias"][0]
