"""Strapdown mechanization (KZL Eqs. 7-9) and alignment (Eqs. 2-4).

Oracles: closed forms (rest stays at rest; constant body rate gives q0 ⊗ exp(w t / 2);
constant specific force gives x = v0 t + a t^2 / 2), scipy's Rotation for the attitude, and
the geometric definition of roll/pitch for levelling.
"""

from __future__ import annotations

import numpy as np
import pymap3d
import pytest
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from navcore import frames as fr
from navcore.inertial.alignment import heading_from_velocity, levelling, levelling_as_printed
from navcore.inertial.strapdown import (
    MechanizationTerms,
    NavState,
    dcm_from_quat_batch,
    strapdown_interval,
    strapdown_step,
)
from navcore.units import DEG, G0, OMEGA_EARTH, WGS84_A, WGS84_E2


def _run(state, w, f, dt, n, terms=None):
    terms = terms or MechanizationTerms()
    for _ in range(n):
        state = strapdown_step(state, w, f, dt, terms)
    return state


def _level_state(n_runs, yaw=0.0, vel=(0.0, 0.0, 0.0)):
    q = np.tile(fr.quat_from_euler(0.0, 0.0, yaw), (n_runs, 1))
    return NavState(np.zeros((n_runs, 3)), np.tile(vel, (n_runs, 1)).astype(float), q)


def test_stationary_stays_put():
    """Oracle: a level IMU at rest measuring f = [0,0,-g] and w = 0 never moves."""
    s0 = _level_state(3, yaw=np.pi / 2)
    s = _run(s0, np.zeros((3, 3)), np.tile([0, 0, -G0], (3, 1)), 0.01, 1000)
    np.testing.assert_allclose(s.pos, 0.0, atol=1e-12)
    np.testing.assert_allclose(s.vel, 0.0, atol=1e-12)
    np.testing.assert_allclose(s.quat, s0.quat, atol=1e-14)


def test_tilted_stationary_stays_put():
    """Oracle: the specific force of gravity reaction R_n^b [0,0,-g] balances gravity at any attitude."""
    C = fr.dcm_from_euler(0.2, -0.1, 1.0)
    f = C.T @ np.array([0, 0, -G0])
    s0 = NavState(np.zeros((1, 3)), np.zeros((1, 3)), fr.quat_from_euler(0.2, -0.1, 1.0)[None])
    s = _run(s0, np.zeros((1, 3)), f[None], 0.01, 500)
    np.testing.assert_allclose(s.vel, 0.0, atol=1e-11)


def test_constant_rate_closed_form_attitude():
    """Oracle: scipy Rotation — constant body rate w for t gives R0 * exp([w t x])."""
    w = np.array([0.1, -0.2, 0.3])
    s0 = _level_state(1, yaw=0.4)
    s = _run(s0, w[None], np.array([[0, 0, -G0]]), 0.01, 300)
    expected = Rotation.from_euler("ZYX", [0.4, 0, 0]) * Rotation.from_rotvec(w * 3.0)
    np.testing.assert_allclose(dcm_from_quat_batch(s.quat)[0], expected.as_matrix(), atol=1e-12)


def test_constant_specific_force_closed_form():
    """Oracle: x = v0 t + (R f + g) t^2 / 2 for a constant attitude and specific force."""
    f = np.array([[0.5, -0.2, -G0]])
    s0 = _level_state(1, yaw=0.0, vel=(1.0, 2.0, 0.0))
    s = _run(s0, np.zeros((1, 3)), f, 0.01, 100)
    a = np.array([0.5, -0.2, 0.0])
    np.testing.assert_allclose(s.vel[0], np.array([1.0, 2.0, 0.0]) + a, atol=1e-12)
    np.testing.assert_allclose(s.pos[0], np.array([1.0, 2.0, 0.0]) + 0.5 * a, atol=1e-12)


def test_earth_rate_switch_rotates_nav_frame():
    """Oracle: with only Earth rate on and w_ib = w_ie^b (the ECEF spin axis in NED, pymap3d),
    the attitude w.r.t. NED stays constant."""
    lat = 51 * DEG
    terms = MechanizationTerms(earth_rate=True, lat0=lat, h0=0.0)
    w_b = np.array(pymap3d.ecef2nedv(0.0, 0.0, OMEGA_EARTH, lat, 0.0, deg=False))  # body = NED
    s0 = _level_state(1)
    s = _run(s0, w_b[None], np.array([[0, 0, -G0]]), 1.0, 100, terms)
    np.testing.assert_allclose(s.quat, s0.quat, atol=1e-12)


def test_levelling_round_trip_specific_force():
    """Oracle: f^b = R_n^b [0,0,-g] for random roll/pitch; levelling recovers them."""
    rng = np.random.default_rng(2)
    for _ in range(50):
        roll, pitch, yaw = rng.uniform(-1.4, 1.4), rng.uniform(-1.4, 1.4), rng.uniform(-3, 3)
        f = fr.dcm_from_euler(roll, pitch, yaw).T @ [0, 0, -G0]
        r, p = levelling(f)
        assert float(r) == pytest.approx(roll, abs=1e-12)
        assert float(p) == pytest.approx(pitch, abs=1e-12)
        r2, p2 = levelling_as_printed(-f)
        assert float(r2) == pytest.approx(roll, abs=1e-12) and float(p2) == pytest.approx(pitch, abs=1e-12)
        r3, p3 = levelling(-f, convention="gravity-reaction")
        assert float(r3) == pytest.approx(roll, abs=1e-12) and float(p3) == pytest.approx(pitch, abs=1e-12)
    # batched: a (2, 3) stack of specific forces gives two attitudes
    angles = np.array([[0.3, -0.4], [-1.0, 0.7]])  # (roll, pitch) per row
    f = np.stack([fr.dcm_from_euler(r, p, 0.5).T @ [0, 0, -G0] for r, p in angles])
    r, p = levelling(f)
    np.testing.assert_allclose(np.column_stack([r, p]), angles, atol=1e-12)


def test_printed_levelling_fails_for_specific_force():
    """Oracle: a level aircraft (f = [0,0,-g]) has roll 0; the printed Eq. 3 gives 180 deg."""
    roll, pitch = levelling_as_printed([0.0, 0.0, -G0])
    assert abs(float(roll)) == pytest.approx(np.pi)
    assert float(pitch) == 0.0


def test_heading_from_velocity():
    """Oracle: east flight has heading 90 deg, north-west 315 deg (-45)."""
    assert float(heading_from_velocity([0, 110, 0])) == pytest.approx(np.pi / 2)
    assert float(heading_from_velocity([1, -1, 0])) == pytest.approx(-np.pi / 4)
    np.testing.assert_allclose(
        heading_from_velocity([[-3.0, 0.0, 2.0], [0.0, -5.0, 0.0]]), [np.pi, -np.pi / 2]
    )
    with pytest.raises(ValueError, match="v_ned"):
        heading_from_velocity([0, 0, 1])


def test_levelling_rejects_bad_convention():
    with pytest.raises(ValueError, match="convention"):
        levelling([0, 0, -1], convention="down")


# --- ideal sensors in every mechanisation mode (issue 21, error 1) -------------------------

_MODES = [(er, tr, co) for er in (False, True) for tr in (False, True) for co in (False, True)]


def _ideal_sensors_eci(lat, h, v_east, q_bn):
    """Specific force and body rate of a vehicle flying east along a parallel at constant
    height, speed and attitude w.r.t. NED, from its motion in inertial space.

    Oracle geometry (independent of the NED mechanization equations): the vehicle moves on a
    circle of radius rho = (R_E + h) cos(lat) about the polar axis at the inertial rate
    Omega + v_east / rho. Its inertial acceleration is -(Omega + v/rho)^2 rho e_rho, gravity
    g = gravitation + Earth's centrifugal Omega^2 rho e_rho along +down, so the specific force
    is f = -(2 Omega v + v^2 / rho) e_rho - g e_down, with e_rho = [-sin L, 0, -cos L] in NED.
    The NED frame (and the body, fixed in it) turns at (Omega + v/rho) about the polar axis,
    e_z = [cos L, 0, -sin L] in NED.
    """
    _, R_E = fr.radii_of_curvature(lat)
    rho = (R_E + h) * np.cos(lat)
    e_rho = np.array([-np.sin(lat), 0.0, -np.cos(lat)])
    e_z = np.array([np.cos(lat), 0.0, -np.sin(lat)])
    f_n = -(2 * OMEGA_EARTH * v_east + v_east**2 / rho) * e_rho + np.array([0.0, 0.0, -G0])
    w_n = (OMEGA_EARTH + v_east / rho) * e_z
    C_nb = fr.dcm_from_quat(q_bn).T
    return C_nb @ w_n, C_nb @ f_n


def _ideal_sensors_mode(terms, lat, h, v_east, q_bn):
    """The sensors a mode's world model attributes to constant NED velocity and attitude.

    Each switched-off term is a rotation or acceleration that world does not have: the
    body rate is w_in^n of the switched-on rates, the specific force is -g plus the
    switched-on Coriolis/transport acceleration (the continuous equations of the module
    docstring with dv/dt = 0 and dq/dt = 0). With every switch on this is the inertial
    physics of `_ideal_sensors_eci` (checked in the test).
    """
    v = np.array([0.0, v_east, 0.0])
    w_ie = np.array(pymap3d.ecef2nedv(0.0, 0.0, OMEGA_EARTH, lat, 0.0, deg=False))
    _, R_E = fr.radii_of_curvature(lat)
    w_en = np.array([v_east / (R_E + h), 0.0, -v_east * np.tan(lat) / (R_E + h)])
    w_n = terms.earth_rate * w_ie + terms.transport_rate * w_en
    f_n = np.array([0.0, 0.0, -G0]) + terms.coriolis * np.cross(2 * w_ie + w_en, v)
    C_nb = fr.dcm_from_quat(q_bn).T
    return C_nb @ w_n, C_nb @ f_n


@pytest.mark.parametrize(("earth", "transport", "coriolis"), _MODES)
@pytest.mark.parametrize(
    ("lat_deg", "v_east", "dt", "duration"),
    [(50.0, 0.0, 1.0, 300.0), (45.0, 250.0, 1.0, 300.0)],
    ids=["stationary", "flight-east-250mps"],
)
def test_ideal_sensors_every_mode_no_drift(earth, transport, coriolis, lat_deg, v_east, dt, duration):
    """Oracle: constant velocity along a parallel at constant attitude w.r.t. NED solves the
    continuous mechanization exactly, so ideal sensors must give zero drift at any dt.

    The sensors come from inertial-space geometry (all switches on) or from the mode's own
    world model (see `_ideal_sensors_mode`). Before the mid-interval attitude included the
    navigation frame's half-rotation, every mode with a rotating navigation frame drifted:
    8 to 20 m in 5 min at dt = 1 s (the drift is proportional to dt).
    """
    lat, h = lat_deg * DEG, 3000.0
    terms = MechanizationTerms(earth_rate=earth, transport_rate=transport, coriolis=coriolis, lat0=lat, h0=h)
    q_bn = fr.quat_from_euler(0.1, -0.05, 1.2)  # a non-level attitude, fixed w.r.t. NED
    w_b, f_b = _ideal_sensors_mode(terms, lat, h, v_east, q_bn)
    if earth and transport and coriolis:
        w_eci, f_eci = _ideal_sensors_eci(lat, h, v_east, q_bn)
        np.testing.assert_allclose(w_b, w_eci, rtol=1e-12, atol=1e-20)
        np.testing.assert_allclose(f_b, f_eci, rtol=1e-12, atol=1e-15)
    s0 = NavState(np.zeros((1, 3)), np.array([[0.0, v_east, 0.0]]), q_bn[None])
    n = round(duration / dt)
    s = _run(s0, w_b[None], f_b[None], dt, n, terms)
    np.testing.assert_allclose(s.pos[0], [0.0, v_east * n * dt, 0.0], rtol=0, atol=1e-6)
    np.testing.assert_allclose(s.vel[0], [0.0, v_east, 0.0], rtol=0, atol=1e-9)
    assert abs(float(np.sum(s.quat[0] * q_bn))) == pytest.approx(1.0, abs=1e-13)


# --- exact physics of piecewise-constant sensors (flat Earth) and of the rotating Earth ----


def _exact_flat_earth(q0, v0, p0, w, f, dt, g):
    """Oracle: the exact motion over a flat, non-rotating Earth of a body whose rate and
    specific force are constant over each interval (scipy Rotation for the attitude,
    Gauss-Legendre quadrature of R(t) f for velocity and position; nothing from navcore).

    Returns the end attitude matrix, velocity, position and each interval's mean NED
    specific force. Over one interval R(s) = R_k exp([w_k x] s), so
    v_{k+1} = v_k + R_k int_0^dt exp([w_k x] s) f_k ds + g dt e_D and
    p_{k+1} = p_k + v_k dt + R_k int_0^dt (dt - s) exp([w_k x] s) f_k ds + g dt^2/2 e_D.
    """
    x, wq = np.polynomial.legendre.leggauss(8)
    s_nodes, s_w = 0.5 * dt * (x + 1), 0.5 * dt * wq
    R = Rotation.from_quat(np.roll(q0, -1))
    v, p = np.array(v0, float), np.array(p0, float)
    down = np.array([0.0, 0.0, g])
    f_mean = np.zeros((len(w), 3))
    for k in range(len(w)):
        Rs = R * Rotation.from_rotvec(np.outer(s_nodes, w[k]))
        fs = Rs.apply(f[k])  # (8, 3) specific force in NED at the nodes
        dv = s_w @ fs
        dp = (s_w * (dt - s_nodes)) @ fs
        f_mean[k] = dv / dt
        p = p + v * dt + dp + 0.5 * down * dt**2
        v = v + dv + down * dt
        R = R * Rotation.from_rotvec(w[k] * dt)
    return R.as_matrix(), v, p, f_mean


def test_step_and_interval_match_exact_piecewise_motion():
    """Oracle: `_exact_flat_earth` (exact integration of piecewise-constant, non-commuting
    body rates and anisotropic specific forces from a non-level start; scipy Rotation and
    quadrature). Both the step-by-step mechanization and the vectorised scan must follow it
    to the midpoint/trapezoid truncation error (about 7e-8 m/s and 5e-8 m here; a dropped
    half-increment or a transposed rotation gives 1e-3), keep |q| = 1, and the scan's
    per-interval NED specific force must equal the interval mean of R(t) f (to (w dt)^2 |f| / 24,
    2e-6 m/s^2 for the largest rates drawn here)."""
    rng = np.random.default_rng(11)
    n, S, dt, g = 3, 128, 0.002, 9.79
    w = 0.3 * rng.normal(size=(n, S, 3))
    f = 2.0 * rng.normal(size=(n, S, 3)) + np.array([0.4, -0.3, -g])
    q0 = fr.quat_normalize(rng.normal(size=(n, 4)))
    v0 = 50.0 * rng.normal(size=(n, 3))
    p0 = 100.0 * rng.normal(size=(n, 3))
    s0 = NavState(p0, v0, q0)
    s = s0
    for i in range(S):
        s = strapdown_step(s, w[:, i], f[:, i], dt, MechanizationTerms(gravity=g))
    s_fast, f_n = strapdown_interval(s0, w, f, dt, gravity=g)
    for run in range(n):
        C, v, p, f_mean = _exact_flat_earth(q0[run], v0[run], p0[run], w[run], f[run], dt, g)
        for got in (s, s_fast):
            np.testing.assert_allclose(dcm_from_quat_batch(got.quat)[run], C, rtol=0, atol=1e-12)
            np.testing.assert_allclose(got.vel[run], v, rtol=0, atol=2e-7)
            np.testing.assert_allclose(got.pos[run], p, rtol=0, atol=2e-7)
            assert np.linalg.norm(got.quat[run]) == pytest.approx(1.0, abs=1e-14)
        np.testing.assert_allclose(f_n[run], f_mean, rtol=0, atol=5e-6)


def _c_ne(lat, lon):
    """NED-to-ECEF rotation from pymap3d's ENU unit vectors (columns north, east, down)."""
    n = np.array(pymap3d.enu2uvw(0.0, 1.0, 0.0, lat, lon, deg=False))
    e = np.array(pymap3d.enu2uvw(1.0, 0.0, 0.0, lat, lon, deg=False))
    u = np.array(pymap3d.enu2uvw(0.0, 0.0, 1.0, lat, lon, deg=False))
    return np.column_stack([n, e, -u])


def _ecef_oracle(lat, lon, h, v_n, C_bn, w_b, f_b, g, dt):
    """Oracle: Newton's law in Earth-fixed axes, integrated with scipy (DOP853, rtol 1e-13):
    r'' = C_be(t) f_b + g e_down(r) - 2 Omega x r' (gravity plus centrifugal is g along the
    local geodetic down, as the mechanization assumes), the body turning at w_b w.r.t.
    inertial space, C_be(t) = Rz(-Omega t) C_be(0) exp([w_b x] t); pymap3d for the geodesy
    (geodetic <-> ECEF, the local NED axes). Returns the NED distance travelled (quadrature
    of the NED velocity), the end NED velocity and the end body-to-NED matrix."""
    r0 = np.array(pymap3d.geodetic2ecef(lat, lon, h, deg=False))
    M0 = _c_ne(lat, lon)
    C_be0 = M0 @ C_bn

    def C_be(t):
        return (
            Rotation.from_rotvec([0, 0, -OMEGA_EARTH * t]).as_matrix()
            @ C_be0
            @ Rotation.from_rotvec(w_b * t).as_matrix()
        )

    def rhs(t, y):
        r, rd = y[:3], y[3:]
        la, lo, _ = pymap3d.ecef2geodetic(*r, deg=False)
        down = -np.array(pymap3d.enu2uvw(0.0, 0.0, 1.0, la, lo, deg=False))
        return np.concatenate([rd, C_be(t) @ f_b + g * down - 2 * np.cross([0, 0, OMEGA_EARTH], rd)])

    y0 = np.concatenate([r0, M0 @ v_n])
    sol = solve_ivp(rhs, (0, dt), y0, method="DOP853", rtol=1e-13, atol=1e-10, dense_output=True)
    x, wq = np.polynomial.legendre.leggauss(8)
    travelled = np.zeros(3)
    for t, wt in zip(0.5 * dt * (x + 1), wq, strict=True):
        y = sol.sol(t)
        la, lo, _ = pymap3d.ecef2geodetic(*y[:3], deg=False)
        travelled += 0.5 * dt * wt * (_c_ne(la, lo).T @ y[3:])
    la1, lo1, _ = pymap3d.ecef2geodetic(*sol.y[:3, -1], deg=False)
    M1 = _c_ne(la1, lo1)
    return travelled, M1.T @ sol.y[3:, -1], M1.T @ C_be(dt)


@pytest.mark.parametrize(
    ("pos0", "v_n"),
    [((30e3, 0.0, -8000.0), (180.0, -140.0, 6.0)), ((-60e3, 5e3, 1000.0), (-90.0, 220.0, -4.0))],
    ids=["north-west-climb", "south-east-descent"],
)
def test_step_with_every_term_matches_earth_fixed_newton(pos0, v_n):
    """Oracle: `_ecef_oracle` (Newton in Earth-fixed axes with Coriolis, pymap3d geodesy,
    scipy integration) for one 1-ms step from a state away from the NED origin (north offset
    and height change, so latitude and height come from the position), with a general NED
    velocity, a non-level attitude, a body rate and an anisotropic specific force.

    Agreement: 3e-11 m, 7e-11 m/s, 2e-13 rad here (the one-step truncation). Leaving out
    Coriolis changes the velocity by 1.5e-5 m/s, the transport or Earth rate the attitude by
    3e-8 rad; a north velocity, a latitude or a height off by the origin's offset is seen too.
    """
    lat0, h0, g = 0.8, 2000.0, 9.79
    pos0, v_n = np.array(pos0), np.array(v_n)
    h = h0 - pos0[2]
    R_N0 = WGS84_A * (1 - WGS84_E2) / (1 - WGS84_E2 * np.sin(lat0) ** 2) ** 1.5  # meridian radius
    lat = lat0 + pos0[0] / (R_N0 + h)  # the documented curvilinear north coordinate
    C_bn = Rotation.from_euler("ZYX", [2.0, -0.15, 0.25]).as_matrix()
    w_b, f_b = np.array([0.02, -0.03, 0.05]), np.array([0.8, -0.5, -9.6])
    dt = 1e-3
    travelled, v1, C1 = _ecef_oracle(lat, 0.3, h, v_n, C_bn, w_b, f_b, g, dt)
    terms = MechanizationTerms(
        earth_rate=True, transport_rate=True, coriolis=True, gravity=g, lat0=lat0, h0=h0
    )
    q0 = np.roll(Rotation.from_matrix(C_bn).as_quat(), 1)
    s1 = strapdown_step(NavState(pos0[None], v_n[None], q0[None]), w_b[None], f_b[None], dt, terms)
    np.testing.assert_allclose(s1.pos[0] - pos0, travelled, rtol=0, atol=1e-10)
    np.testing.assert_allclose(s1.vel[0], v1, rtol=0, atol=2e-10)
    E = dcm_from_quat_batch(s1.quat)[0] @ C1.T
    np.testing.assert_allclose(E, np.eye(3), rtol=0, atol=1e-12)
