"""Trajectory generator (coordinated turns, climbs) against closed-form point-mass kinematics.

Oracle: the analytic acceleration of a point mass at speed V whose heading and flight-path
angle change at chi_dot and gamma_dot, a = V chi_dot cos(gamma) e_h + V gamma_dot e_v
(e_h the horizontal normal, e_v the pitch-down normal of the velocity), minus gravity; a
coordinated turn has no body-y component of this specific force (Etkin, *Dynamics of
Atmospheric Flight*, steady coordinated turn).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from navcore.inertial.trajectories import (
    Segment,
    euler_to_dcm_stack,
    fly,
    straight_and_level,
    trajectory_window,
)
from navcore.units import G0, WGS84_A


def _analytic_specific_force(V, chi, gam, chi_dot, gam_dot):
    e_h = np.stack([-np.sin(chi), np.cos(chi), np.zeros_like(chi)], -1)
    e_v = np.stack([-np.sin(gam) * np.cos(chi), -np.sin(gam) * np.sin(chi), -np.cos(gam)], -1)
    a = (V * chi_dot * np.cos(gam))[:, None] * e_h + (V * gam_dot)[:, None] * e_v
    return a - np.array([0.0, 0.0, G0])


@pytest.mark.parametrize(
    ("chi_dot", "gam0", "gam_dot"),
    [
        (0.03, 0.2, 0.0),
        (-0.03, -0.25, 0.0),
        (0.05, 0.0, 0.0),
        (0.03, 0.1, 0.004),
        (-0.02, 0.1, -0.01),
        (0.02, 0.0, -0.0505),
    ],
    ids=[
        "climbing-turn",
        "diving-turn-left",
        "level-turn",
        "pull-up-in-turn",
        "push-over-in-turn",
        "negative-g",
    ],
)
def test_coordinated_turn_has_no_side_force(chi_dot, gam0, gam_dot):
    """Oracle: body-y of the analytic specific force is zero. The old bank angle
    tan(phi) = V chi_dot cos(gamma) / g left 0.100 m/s^2 at 200 m/s, 0.03 rad/s, 0.2 rad.
    The last case pushes over hard enough for a slightly negative lift (-0.3 m/s^2 at the
    start, g cos(gamma) + V gamma_dot < 0): the bank then leans the other way."""
    V, dt = 200.0, 0.1
    tr = fly(
        [Segment(60.0, turn_rate=chi_dot, path_angle_rate=gam_dot)],
        dt=dt,
        speed0=V,
        path_angle0=gam0,
        h0=10000.0,
    )
    t = tr.t[1:-1]  # interior samples (the generator's central differences are exact there)
    chi, gam = chi_dot * t, gam0 + gam_dot * t
    f_n = _analytic_specific_force(np.full(t.size, V), chi, gam, chi_dot, gam_dot)
    y_body = tr.C_bn[1:-1, :, 1]  # body y axis in NED
    side = np.einsum("ni,ni->n", y_body, f_n)
    np.testing.assert_allclose(side, 0.0, atol=1e-9)
    # and the generator's own (numerically differentiated) specific force agrees with the oracle
    # to the central-difference error V chi_dot^3 dt^2 / 6 (4.2e-5 m/s^2 at most here)
    np.testing.assert_allclose(tr.f_ned[1:-1], f_n, atol=1e-4)
    # the body x axis lies along the velocity
    x_body = tr.C_bn[:, :, 0]
    np.testing.assert_allclose(x_body, tr.vel_ned / V, atol=1e-12)


def test_issue_climbing_turn_bank_angle():
    """Oracle: tan(phi) = V chi_dot / g for a turn at constant flight-path angle (hand formula)."""
    tr = fly([Segment(10.0, turn_rate=0.03)], dt=1.0, speed0=200.0, path_angle0=0.2)
    roll = np.arctan2(tr.C_bn[:, 2, 1], tr.C_bn[:, 2, 2])  # C[2,1] = cos(pitch) sin(roll)
    np.testing.assert_allclose(roll, np.arctan(200.0 * 0.03 / G0), atol=1e-12)


def test_straight_flight_has_wings_level():
    """Oracle: no turn means no bank, also while pitching (lift stays in the vertical plane)."""
    tr = fly([Segment(20.0, path_angle_rate=0.01), Segment(20.0, path_angle_rate=-0.02)], speed0=150.0)
    np.testing.assert_allclose(tr.C_bn[:, 2, 1], 0.0, atol=1e-15)


def test_body_rate_of_a_steady_climbing_turn():
    """Oracle: Euler-angle kinematics (Etkin): with constant roll phi and pitch gamma and a
    heading rate chi_dot, the body rate relative to NED is
    chi_dot [-sin(gamma), cos(gamma) sin(phi), cos(gamma) cos(phi)] (body axes),
    phi = atan(V chi_dot / g) for the coordinated turn."""
    V, chi_dot, gam = 180.0, -0.04, 0.15
    tr = fly([Segment(30.0, turn_rate=chi_dot)], dt=0.05, speed0=V, path_angle0=gam, heading0=0.7)
    phi = np.arctan(V * chi_dot / G0)
    w = chi_dot * np.array([-np.sin(gam), np.cos(gam) * np.sin(phi), np.cos(gam) * np.cos(phi)])
    # the generator differentiates C_bn centrally: relative error (chi_dot dt)^2 / 6 = 7e-7
    np.testing.assert_allclose(tr.omega_nb_b[1:-1], np.tile(w, (len(tr) - 2, 1)), rtol=0, atol=5e-8)
    assert tr.dt == pytest.approx(0.05)
    np.testing.assert_allclose(tr.speed, V, rtol=1e-12)


def test_turn_path_and_geodetic_position_closed_forms():
    """Oracles: a turn at constant speed, heading rate and flight-path angle is a helix:
    north = V cos(gamma) (sin chi - sin chi0) / chi_dot, east = -V cos(gamma) (cos chi -
    cos chi0) / chi_dot, height gain V sin(gamma) t (trapezoid error O(dt^2)); on the spherical
    Earth of the module a flight due north at constant height changes latitude by
    V t / (a + h), one due east along the parallel longitude by V t / ((a + h) cos L)."""
    V, chi_dot, gam, chi0, h0 = 150.0, 0.02, -0.05, 0.3, 9000.0
    tr = fly([Segment(100.0, turn_rate=chi_dot)], dt=0.01, speed0=V, path_angle0=gam, heading0=chi0, h0=h0)
    chi = chi0 + chi_dot * tr.t
    north = V * np.cos(gam) * (np.sin(chi) - np.sin(chi0)) / chi_dot
    east = -V * np.cos(gam) * (np.cos(chi) - np.cos(chi0)) / chi_dot
    np.testing.assert_allclose(tr.pos_ned[:, 0], north, rtol=0, atol=1e-4)
    np.testing.assert_allclose(tr.pos_ned[:, 1], east, rtol=0, atol=1e-4)
    np.testing.assert_allclose(tr.h, h0 + V * np.sin(gam) * tr.t, rtol=0, atol=1e-8)
    lat0, lon0, h = 0.6, -1.1, 2000.0
    tn = fly([Segment(200.0)], speed0=V, heading0=0.0, lat0=lat0, lon0=lon0, h0=h)
    np.testing.assert_allclose(tn.lat, lat0 + V * tn.t / (WGS84_A + h), rtol=1e-13)
    np.testing.assert_allclose(tn.lon, lon0, rtol=1e-13)
    te = fly([Segment(200.0)], speed0=V, heading0=np.pi / 2, lat0=lat0, lon0=lon0, h0=h)
    np.testing.assert_allclose(te.lon, lon0 + V * te.t / ((WGS84_A + h) * np.cos(lat0)), rtol=1e-12)
    np.testing.assert_allclose(te.lat, lat0, atol=1e-12)
    assert len(te) == 201


def test_accelerating_multi_segment_flight():
    """Oracle: point-mass kinematics with the along-track acceleration V_dot added to the
    analytic specific force (V_dot along the velocity); the bank angle of the last sample
    belongs to the last segment's turn rate, tan(phi) = V chi_dot / g, and the speed
    is V0 + V_dot t."""
    V0, a = 120.0, 1.5
    segs = [Segment(20.0, speed_rate=a, turn_rate=0.01), Segment(20.0, speed_rate=-a, turn_rate=-0.03)]
    tr = fly(segs, dt=0.1, speed0=V0, path_angle0=0.05, heading0=-0.4)
    V = np.where(tr.t <= 20.0, V0 + a * tr.t, V0 + a * 20.0 - a * (tr.t - 20.0))
    np.testing.assert_allclose(tr.speed, V, rtol=1e-12)
    chi = np.where(tr.t <= 20.0, -0.4 + 0.01 * tr.t, -0.4 + 0.2 - 0.03 * (tr.t - 20.0))
    chi_dot = np.where(tr.t < 20.0, 0.01, -0.03)
    v_dot = np.where(tr.t < 20.0, a, -a)
    gam = np.full_like(tr.t, 0.05)
    f = _analytic_specific_force(V, chi, gam, chi_dot, 0.0 * gam)
    f += v_dot[:, None] * tr.vel_ned / V[:, None]
    inner = (np.abs(tr.t - 20.0) > 0.15) & (tr.t > 0.05) & (tr.t < tr.t[-1] - 0.05)
    np.testing.assert_allclose(tr.f_ned[inner], f[inner], rtol=0, atol=1e-4)
    roll = np.arctan2(tr.C_bn[:, 2, 1], tr.C_bn[:, 2, 2])
    assert roll[-1] == pytest.approx(np.arctan(V[-1] * -0.03 / G0), abs=1e-12)
    assert roll[0] == pytest.approx(np.arctan(V0 * 0.01 / G0), abs=1e-12)


def test_euler_to_dcm_stack_against_scipy():
    """Oracle: scipy Rotation, intrinsic 'ZYX' = yaw, pitch, roll (body to NED)."""
    rng = np.random.default_rng(3)
    roll, pitch, yaw = rng.uniform(-1.5, 1.5, size=(3, 5))
    ref = Rotation.from_euler("ZYX", np.column_stack([yaw, pitch, roll])).as_matrix()
    np.testing.assert_allclose(euler_to_dcm_stack(roll, pitch, yaw), ref, rtol=0, atol=1e-15)
    # scalar angles give one matrix
    np.testing.assert_allclose(euler_to_dcm_stack(roll[0], pitch[0], yaw[0]), ref[0], rtol=0, atol=1e-15)


def test_fly_rejects_impossible_flights():
    """The speed may reach zero but not go below; the height may reach -500 m, not less."""
    fly([Segment(10.0, speed_rate=-10.0)], speed0=100.0)  # ends at exactly 0 m/s
    with pytest.raises(ValueError, match="speed"):
        fly([Segment(10.5, speed_rate=-10.0)], speed0=100.0, dt=0.5)
    fly([Segment(10.0)], speed0=50.0, path_angle0=-np.pi / 2, h0=0.0)  # ends at -500 m
    with pytest.raises(ValueError, match="below"):
        fly([Segment(10.0)], speed0=50.05, path_angle0=-np.pi / 2, h0=0.0)  # ends at -500.5 m
    with pytest.raises(ValueError, match="segments"):
        fly([])


def test_long_north_east_flight_follows_the_rhumb_line():
    """Oracle: the rhumb line (constant heading psi on the module's sphere of radius a + h),
    lon = lon0 + tan(psi) [ln tan(pi/4 + L/2) - ln tan(pi/4 + L0/2)]: one hour north-east at
    250 m/s from 50 deg N, sampled every 10 s, within 1e-8 rad (6 cm). Dividing the east
    distance by the final cos(lat) instead would put the aircraft 47 km too far east."""
    V, psi, lat0, lon0, h0 = 250.0, np.pi / 4, np.radians(50.0), 0.3, 9000.0
    tr = straight_and_level(3600.0, speed=V, heading=psi, dt=10.0, lat0=lat0, lon0=lon0, h0=h0)
    lat = lat0 + V * tr.t * np.cos(psi) / (WGS84_A + h0)
    rhumb = lon0 + np.tan(psi) * (np.log(np.tan(np.pi / 4 + lat / 2)) - np.log(np.tan(np.pi / 4 + lat0 / 2)))
    np.testing.assert_allclose(tr.lat, lat, rtol=0, atol=1e-13)
    np.testing.assert_allclose(tr.lon, rhumb, rtol=0, atol=1e-8)


def test_straight_and_level_closed_form_and_defaults():
    """Oracle: constant velocity V [cos psi, sin psi, 0] at constant height: position V t
    along the heading; on the module's sphere the latitude advances by the north arc
    (V t cos psi) / (a + h) and the longitude follows the rhumb line,
    lon0 + tan(psi) [ln tan(pi/4 + L/2) - ln tan(pi/4 + L0/2)]. The documented defaults
    (speed, heading, position 0, dt = 1 s) make a vehicle at rest at (0, 0, 0)."""
    V, psi, dt, lat0, lon0, h0 = 80.0, 2.2, 0.5, -0.4, 2.0, 1500.0
    tr = straight_and_level(20.0, speed=V, heading=psi, dt=dt, lat0=lat0, lon0=lon0, h0=h0)
    np.testing.assert_allclose(tr.t, np.arange(41) * dt, rtol=0, atol=1e-12)
    np.testing.assert_allclose(
        tr.vel_ned, np.tile([V * np.cos(psi), V * np.sin(psi), 0.0], (41, 1)), atol=1e-12
    )
    np.testing.assert_allclose(
        tr.pos_ned[:, :2], np.outer(tr.t, [V * np.cos(psi), V * np.sin(psi)]), atol=1e-9
    )
    np.testing.assert_allclose(tr.h, h0, rtol=0, atol=1e-9)
    np.testing.assert_allclose(tr.lat, lat0 + V * tr.t * np.cos(psi) / (WGS84_A + h0), rtol=0, atol=1e-13)
    lat = lat0 + V * tr.t * np.cos(psi) / (WGS84_A + h0)
    rhumb = lon0 + np.tan(psi) * (np.log(np.tan(np.pi / 4 + lat / 2)) - np.log(np.tan(np.pi / 4 + lat0 / 2)))
    np.testing.assert_allclose(tr.lon, rhumb, rtol=0, atol=1e-13)
    np.testing.assert_allclose(tr.f_ned, np.tile([0.0, 0.0, -G0], (41, 1)), atol=1e-12)
    rest = straight_and_level(5.0)
    assert rest.dt == 1.0 and len(rest) == 6
    for a in (rest.lat, rest.lon, rest.h, rest.pos_ned, rest.vel_ned, rest.omega_nb_b):
        np.testing.assert_array_equal(a, 0.0)
    np.testing.assert_allclose(rest.C_bn, np.tile(np.eye(3), (6, 1, 1)), atol=0)
    rest2 = fly([Segment(5.0)])
    np.testing.assert_array_equal(np.c_[rest2.lat, rest2.lon, rest2.h, rest2.speed], 0.0)


def test_latitude_is_integrated_along_a_path_that_climbs_after_a_leg_north():
    """Oracle: the path integral L = L0 + int v_N / (a + h) dt of the analytic flight, by
    scipy's adaptive ODE solver (rtol 1e-12) on the segments' own kinematics: 1000 s north
    at 250 m/s and 1000 m, a 20-s pull-up to a 10 deg climb, then 230 s of climb (about
    10 km higher). The generator's trapezoid rule on 1-s samples is within 5e-9 rad (it
    converges as dt^2); dividing the whole north distance by the current a + h instead put
    the aircraft 460 m south of where it is (7.2e-5 rad)."""
    from scipy.integrate import solve_ivp

    V, h0, lat0, r = 250.0, 1000.0, 0.7, np.radians(0.5)
    segs = [Segment(1000.0), Segment(20.0, path_angle_rate=r), Segment(230.0)]
    tr = fly(segs, speed0=V, heading0=0.0, lat0=lat0, h0=h0, dt=1.0)

    def gamma(t):
        return r * np.clip(t - 1000.0, 0.0, 20.0)

    def rhs(t, y):
        g = gamma(t)
        return [V * np.cos(g) / (WGS84_A + y[1]), V * np.sin(g)]

    sol = solve_ivp(rhs, (0.0, tr.t[-1]), [lat0, h0], t_eval=tr.t, rtol=1e-12, atol=1e-14, max_step=1.0)
    assert tr.h[-1] - h0 > 9000.0
    np.testing.assert_allclose(tr.h, sol.y[1], rtol=0, atol=0.01)
    np.testing.assert_allclose(tr.lat, sol.y[0], rtol=0, atol=1e-8)  # 6 cm


def test_trajectory_window_slices_every_field_alike() -> None:
    """Oracle: numpy slicing by hand of each field with the indices of the nearest samples
    (t = 0, 0.5, ..., 30 s; 3.1 s -> index 6, 20.2 s -> index 40), every 4th sample."""
    tr = fly([Segment(10.0), Segment(20.0, turn_rate=0.02)], dt=0.5, speed0=80.0)
    w = trajectory_window(tr, 3.1, 20.2, step=4)
    for name in ("t", "lat", "lon", "h", "pos_ned", "vel_ned", "f_ned", "C_bn", "omega_nb_b"):
        np.testing.assert_array_equal(getattr(w, name), getattr(tr, name)[6:41:4])
    assert w.t[0] == 3.0 and w.t[-1] == 19.0
    assert len(trajectory_window(tr, 0.0, 30.0)) == len(tr)
    with pytest.raises(ValueError, match="step"):
        trajectory_window(tr, 0.0, 1.0, step=0)
