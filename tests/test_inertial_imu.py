"""IMU specification helpers and the SP Table 2.5 grades against hand conversions."""

from __future__ import annotations

import math

import pytest

from navcore.inertial.imu import (
    angle_random_walk_deg_per_sqrt_h,
    noise_only,
    velocity_random_walk_m_per_s_per_sqrt_h,
)
from navcore.papers.sp_tables import sp_imu_grades, table_2_4, table_2_8


def test_random_walk_conversions_by_hand():
    """Oracle: 1 deg/h/sqrt(Hz) = 1/60 deg/sqrt(h); 1 micro-g/sqrt(Hz) = 9.80665e-6*60 m/s/sqrt(h)."""
    assert angle_random_walk_deg_per_sqrt_h(4.7) == pytest.approx(0.078333, rel=1e-4)
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
