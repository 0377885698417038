"""Strapdown mechanization (KZL Eqs. 7-9) and alignment (Eqs. 2-4).

Oracles: closed forms (rest stays at rest; constant body rate gives q0 ⊗ exp(w t / 2);
constant specific force gives x = v0 t + a t^2 / 2), scipy's Rotation for the attitude, and
the geometric definition of roll/pitch for levelling.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from navcore import frames as fr
from navcore.inertial.alignment import heading_from_velocity, levelling, levelling_as_printed
from navcore.inertial.strapdown import (
    MechanizationTerms,
    NavState,
    dcm_from_quat_batch,
    earth_rate_ned,
    strapdown_interval,
    strapdown_step,
)
from navcore.units import DEG, G0, OMEGA_EARTH


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


def test_quaternion_norm_preserved():
    """Oracle: |q| = 1 (the update multiplies unit quaternions and renormalises)."""
    rng = np.random.default_rng(1)
    s = _level_state(4)
    for _ in range(200):
        s = strapdown_step(s, rng.normal(size=(4, 3)), rng.normal(size=(4, 3)), 0.01)
    np.testing.assert_allclose(np.linalg.norm(s.quat, axis=-1), 1.0, atol=1e-14)


def test_constant_specific_force_closed_form():
    """Oracle: x = v0 t + (R f + g) t^2 / 2 for a constant attitude and specific force."""
    f = np.array([[0.5, -0.2, -G0]])
    s0 = _level_state(1, yaw=0.0, vel=(1.0, 2.0, 0.0))
    s = _run(s0, np.zeros((1, 3)), f, 0.01, 100)
    a = np.array([0.5, -0.2, 0.0])
    np.testing.assert_allclose(s.vel[0], np.array([1.0, 2.0, 0.0]) + a, atol=1e-12)
    np.testing.assert_allclose(s.pos[0], np.array([1.0, 2.0, 0.0]) + 0.5 * a, atol=1e-12)


def test_earth_rate_switch_rotates_nav_frame():
    """Oracle: with only Earth rate on and w_ib = w_ie^b, the attitude w.r.t. NED stays constant."""
    lat = 51 * DEG
    terms = MechanizationTerms(earth_rate=True, lat0=lat, h0=0.0)
    w_b = earth_rate_ned(lat)  # level, north-pointing: body = NED
    s0 = _level_state(1)
    s = _run(s0, w_b[None], np.array([[0, 0, -G0]]), 1.0, 100, terms)
    np.testing.assert_allclose(s.quat, s0.quat, atol=1e-12)
    assert np.linalg.norm(earth_rate_ned(lat)) == pytest.approx(OMEGA_EARTH)


def test_coriolis_switch_magnitude():
    """Oracle: closed form (2 w_ie + w_en) x v for 110 m/s east at 51 N after one short step."""
    lat = 51 * DEG
    terms = MechanizationTerms(coriolis=True, lat0=lat, h0=3000.0)
    s0 = _level_state(1, yaw=np.pi / 2, vel=(0.0, 110.0, 0.0))
    s = strapdown_step(s0, np.zeros((1, 3)), np.array([[0, 0, -G0]]), 1e-3, terms)
    acc = (s.vel[0] - s0.vel[0]) / 1e-3
    _, R_E = fr.radii_of_curvature(lat)
    w_en = np.array([110 / (R_E + 3000), 0.0, -110 * np.tan(lat) / (R_E + 3000)])
    expected = -np.cross(2 * earth_rate_ned(lat) + w_en, [0, 110, 0])
    np.testing.assert_allclose(acc, expected, rtol=1e-9)


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


def test_printed_levelling_fails_for_specific_force():
    """Oracle: a level aircraft (f = [0,0,-g]) has roll 0; the printed Eq. 3 gives 180 deg."""
    roll, pitch = levelling_as_printed([0.0, 0.0, -G0])
    assert abs(float(roll)) == pytest.approx(np.pi)
    assert float(pitch) == 0.0


def test_heading_from_velocity():
    """Oracle: east flight has heading 90 deg, north-west 315 deg (-45)."""
    assert float(heading_from_velocity([0, 110, 0])) == pytest.approx(np.pi / 2)
    assert float(heading_from_velocity([1, -1, 0])) == pytest.approx(-np.pi / 4)
    with pytest.raises(ValueError, match="v_ned"):
        heading_from_velocity([0, 0, 1])


def test_levelling_rejects_bad_convention():
    with pytest.raises(ValueError, match="convention"):
        levelling([0, 0, -1], convention="down")


def test_interval_equals_stepwise():
    """Oracle: S sequential calls of strapdown_step (the scan version must agree to rounding)."""
    rng = np.random.default_rng(5)
    n, S = 4, 100
    w = 0.05 * rng.normal(size=(n, S, 3))
    f = rng.normal(size=(n, S, 3)) + np.array([0, 0, -G0])
    s0 = NavState(
        rng.normal(size=(n, 3)), rng.normal(size=(n, 3)), fr.quat_normalize(rng.normal(size=(n, 4)))
    )
    s = s0
    for i in range(S):
        s = strapdown_step(s, w[:, i], f[:, i], 0.01)
    s_fast, f_n = strapdown_interval(s0, w, f, 0.01)
    np.testing.assert_allclose(s_fast.pos, s.pos, atol=1e-11)
    np.testing.assert_allclose(s_fast.vel, s.vel, atol=1e-12)
    np.testing.assert_allclose(np.abs(np.sum(s_fast.quat * s.quat, axis=-1)), 1.0, atol=1e-13)
    assert f_n.shape == (n, S, 3)


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
    w_ie = earth_rate_ned(lat)
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
