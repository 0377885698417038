"""Tests of navcore.location.emitter (WF Eqs. (1)-(9)) against independent oracles."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from navcore.location.emitter import (
    doppler_frequency,
    doppler_gradient_position,
    doppler_gradient_velocity,
    doppler_jacobian_emitter,
    emitter_gauss_newton,
    linearized_location_error,
    location_error_covariance,
    position_sensitivity_bound,
    signal_model_error,
    velocity_to_position_sensitivity_ratio,
)
from navcore.units import C

F0 = 10e9


def _arc(M: int = 200, speed: float = 200.0, rate_deg: float = 2.0, duration: float = 120.0):
    t = np.linspace(0.0, duration, M)
    psi = np.deg2rad(rate_deg) * t
    radius = speed / np.deg2rad(rate_deg)
    pos = np.column_stack([radius * np.sin(psi), radius * (1 - np.cos(psi)), np.full(M, 8000.0)])
    vel = np.column_stack([speed * np.cos(psi), speed * np.sin(psi), np.zeros(M)])
    return pos, vel


EMITTER = np.array([20_000.0, 35_000.0, 0.0])


def test_doppler_sign_and_perpendicular():
    """Oracle: first-order Doppler by hand: closing at v gives f0 (1 + v/c); v perpendicular gives f0."""
    f = doppler_frequency(F0, [1000.0, 0, 0], [[0.0, 0, 0], [0.0, 0, 0]], [[100.0, 0, 0], [0.0, 100.0, 0]])
    assert f[0] == pytest.approx(F0 * (1 + 100.0 / C), rel=1e-15)
    assert f[1] == pytest.approx(F0, rel=1e-15)


def test_gradients_match_sympy():
    """Oracle: sympy differentiation of WF Eq. (1) w.r.t. aperture velocity, position and emitter."""
    px, py, pz, vx, vy, vz, ex, ey, ez, f0 = sp.symbols("px py pz vx vy vz ex ey ez f0", real=True)
    rel = sp.Matrix([ex - px, ey - py, ez - pz])
    R = sp.sqrt(rel.dot(rel))
    f = f0 + f0 / C * sp.Matrix([vx, vy, vz]).dot(rel) / R
    vals = {
        px: 100.0,
        py: -300.0,
        pz: 8000.0,
        vx: 190.0,
        vy: 40.0,
        vz: -3.0,
        ex: 20000.0,
        ey: 35000.0,
        ez: 0.0,
        f0: F0,
    }
    gv = [float(sp.diff(f, s).subs(vals)) for s in (vx, vy, vz)]
    gp = [float(sp.diff(f, s).subs(vals)) for s in (px, py, pz)]
    ge = [float(sp.diff(f, s).subs(vals)) for s in (ex, ey, ez, f0)]
    p, v, e = np.array([100.0, -300, 8000]), np.array([190.0, 40, -3]), np.array([20000.0, 35000, 0])
    np.testing.assert_allclose(doppler_gradient_velocity(F0, e, p)[0], gv, rtol=1e-12)
    np.testing.assert_allclose(doppler_gradient_position(F0, e, p, v)[0], gp, rtol=1e-9)
    np.testing.assert_allclose(doppler_jacobian_emitter(F0, e, p, v)[0], ge, rtol=1e-9)


@settings(max_examples=50, deadline=None)
@given(st.integers(min_value=0, max_value=2**32 - 1))
def test_sensitivity_norms_and_bound(seed):
    """Oracle: central finite differences of WF Eq. (1); Eq. (8) equality and Eq. (9) bound (tight to 1/2)."""
    rng = np.random.default_rng(seed)
    p = rng.normal(0, 5000, 3)
    e = p + rng.normal(0, 30000, 3)
    v = rng.normal(0, 200, 3)
    f0 = 1.0  # f is linear in f0: a 1 Hz carrier keeps the differences free of round-off
    fd_v = [
        (doppler_frequency(f0, e, p, v + d) - doppler_frequency(f0, e, p, v - d))[0] / 2 for d in np.eye(3)
    ]
    np.testing.assert_allclose(doppler_gradient_velocity(f0, e, p)[0], fd_v, rtol=1e-6, atol=1e-6 * f0 / C)
    h = 10.0  # m; truncation error (h/R)^2 ~ 1e-7, round-off ~1e-6 relative
    fd_p = [
        (doppler_frequency(f0, e, p + h * d, v) - doppler_frequency(f0, e, p - h * d, v))[0] / (2 * h)
        for d in np.eye(3)
    ]
    np.testing.assert_allclose(
        doppler_gradient_position(f0, e, p, v)[0], fd_p, rtol=1e-4, atol=1e-4 * float(np.linalg.norm(fd_p))
    )
    gv = np.linalg.norm(doppler_gradient_velocity(F0, e, p)[0])
    assert gv == pytest.approx(F0 / C, rel=1e-12)
    gp = np.linalg.norm(doppler_gradient_position(F0, e, p, v)[0])
    R = np.linalg.norm(e - p)
    assert gp <= 0.5 * position_sensitivity_bound(F0, np.linalg.norm(v), R) * (1 + 1e-12)


def test_printed_bound_is_twice_the_attained_maximum():
    """Oracle: central finite differences of WF Eq. (1) with the velocity across the line of
    sight, where ||df/dp|| attains its maximum (f0/c)|v|/R: the printed Eq. (9) bound
    (f0/c) 2|v|/R is exactly twice it (checking only '<=' let a doubled bound pass)."""
    p, v = np.zeros(3), np.array([0.0, 180.0, -60.0])
    e = np.array([40_000.0, 0.0, 0.0])  # line of sight along x, v across it
    f0, h = 1.0, 10.0
    fd_p = np.array(
        [
            (doppler_frequency(f0, e, p + h * d, v) - doppler_frequency(f0, e, p - h * d, v))[0] / (2 * h)
            for d in np.eye(3)
        ]
    )
    attained = float(np.linalg.norm(fd_p))
    bound = float(position_sensitivity_bound(f0, np.linalg.norm(v), 40_000.0))
    assert bound == pytest.approx(2.0 * attained, rel=1e-6)


def test_total_differential_is_second_order_accurate():
    """Oracle: WF Eq. (1) evaluated directly; the residual of Eq. (7) falls as the square of the step."""
    p, e, v = np.array([100.0, -300, 8000]), np.array([20000.0, 35000, 0]), np.array([190.0, 40, -3])
    dp, dv = np.array([300.0, -200.0, 100.0]), np.array([5.0, 2.0, -4.0])
    f0 = 1.0  # f is linear in f0: a 1 Hz carrier keeps the differences free of round-off

    def residual(h):
        df = doppler_frequency(f0, e, p + h * dp, v + h * dv)[0] - doppler_frequency(f0, e, p, v)[0]
        gv, gp = doppler_gradient_velocity(f0, e, p)[0], doppler_gradient_position(f0, e, p, v)[0]
        return abs(df - (gv @ (h * dv) + gp @ (h * dp)))

    assert residual(1.0) < 0.05 * abs(doppler_gradient_velocity(f0, e, p)[0] @ dv)
    assert residual(1.0) / residual(0.1) == pytest.approx(100.0, rel=0.05)


def test_constant_position_error_translates_the_estimate():
    """Oracle: WF Eq. (1) depends on p^e - p only, so a constant aperture-position error d moves the
    first-order estimate of Eq. (6) by exactly d (the frequency estimate does not move)."""
    pos, vel = _arc()
    H = doppler_jacobian_emitter(F0, EMITTER, pos, vel)
    d = np.array([1.0, -2.0, 0.5])
    ft = signal_model_error(F0, EMITTER, pos, vel, pos + d, vel)  # exact, not linearised
    np.testing.assert_allclose(linearized_location_error(H, ft), np.r_[d, 0.0], atol=1e-3)


def test_ratio():
    """Oracle: finite differences of WF Eq. (1): ||df/dv|| over twice the attained maximum of
    ||df/dp|| (the printed Eq. (9) bound), at |v| = 200 m/s and R = 40 km (100 s)."""
    p, v, e, f0 = np.zeros(3), np.array([0.0, 200.0, 0.0]), np.array([40_000.0, 0.0, 0.0]), 1.0

    def fd(dp, dv):
        return (doppler_frequency(f0, e, p + dp, v + dv) - doppler_frequency(f0, e, p - dp, v - dv))[0] / 2

    g_v = np.linalg.norm([fd(0 * d, d) for d in np.eye(3)])
    g_p = np.linalg.norm([fd(10.0 * d, 0 * d) / 10.0 for d in np.eye(3)])
    expected = g_v / (2 * g_p)
    assert expected == pytest.approx(100.0, rel=1e-6)
    assert velocity_to_position_sensitivity_ratio(200.0, 40_000.0) == pytest.approx(expected, rel=1e-6)


def test_gauss_newton_recovers_truth_and_normal_equation():
    """Oracle: noise-free synthetic data generated by WF Eq. (1) must be fitted exactly (WF Eq. (3) = 0)."""
    pos, vel = _arc()
    m = doppler_frequency(F0, EMITTER, pos, vel)
    res = emitter_gauss_newton(m, pos, vel, [EMITTER[0] + 2000, EMITTER[1] - 1500, 0.0, F0 + 50.0])
    assert res.converged
    np.testing.assert_allclose(res.estimate[:3], EMITTER, atol=1e-3)
    assert abs(res.estimate[3] - F0) < 1e-4
    # round-off floor: f ~ 1e10 Hz is resolved to ~2e-6 Hz
    assert np.linalg.norm(res.normal_equation) < 1e-3


def test_linearized_error_matches_nonlinear():
    """Oracle: the nonlinear Gauss-Newton solution with aperture-velocity errors (WF Eq. (6) first order)."""
    rng = np.random.default_rng(7)
    pos, vel = _arc()
    m = doppler_frequency(F0, EMITTER, pos, vel) + rng.normal(0, 0.5, len(pos))
    vel_hat = vel + rng.normal(0, 0.05, vel.shape)
    truth = np.r_[EMITTER, F0]
    res = emitter_gauss_newton(m, pos, vel_hat, truth)
    H = doppler_jacobian_emitter(F0, EMITTER, pos, vel_hat)
    e = m - doppler_frequency(F0, EMITTER, pos, vel)
    ft = signal_model_error(F0, EMITTER, pos, vel, pos, vel_hat)
    lin = linearized_location_error(H, e + ft)
    np.testing.assert_allclose(res.estimate - truth, lin, rtol=0.02, atol=1e-3)


def test_location_covariance_gls_identity():
    """Oracle: with W = Sigma^-1 the WLS covariance equals (H^T Sigma^-1 H)^-1 (Gauss-Markov)."""
    rng = np.random.default_rng(3)
    H = rng.normal(size=(30, 4))
    s = rng.uniform(0.5, 2.0, 30)
    cov = location_error_covariance(H, np.diag(s**2), np.diag(1 / s**2))
    np.testing.assert_allclose(cov, np.linalg.inv(H.T @ np.diag(1 / s**2) @ H), rtol=1e-10)


def test_bad_input_raises():
    """Validation: names the parameter."""
    with pytest.raises(ValueError, match="f0"):
        doppler_frequency(-1.0, EMITTER, [0.0, 0, 0], [1.0, 0, 0])
    with pytest.raises(ValueError, match="position"):
        doppler_frequency(F0, EMITTER, EMITTER, [1.0, 0, 0])


def test_weighted_error_and_covariance_against_lstsq():
    """Oracle: weighted least squares by numpy.linalg.lstsq on the whitened system
    (W^(1/2) H) x = W^(1/2) e, column by column for the map G; the covariance of the error is
    G Sigma G' for a non-diagonal Sigma and a weight that is not Sigma^-1 (a full matrix, a
    vector meaning a diagonal, and the default identity)."""
    rng = np.random.default_rng(8)
    M, n = 25, 4
    H = rng.normal(size=(M, n))
    A = rng.normal(size=(M, M))
    Sigma = A @ A.T / M + np.eye(M)
    B = rng.normal(size=(M, M))
    weights = {"full": B @ B.T / M + 0.5 * np.eye(M), "vector": rng.uniform(0.2, 3.0, M), "identity": None}
    e = rng.normal(size=(M, 3))
    for W in weights.values():
        Wm = np.eye(M) if W is None else (np.diag(W) if np.ndim(W) == 1 else W)
        Wh = np.linalg.cholesky(Wm).T  # Wh' Wh = W
        G = np.linalg.lstsq(Wh @ H, Wh, rcond=None)[0]
        np.testing.assert_allclose(linearized_location_error(H, e, W), G @ e, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(
            linearized_location_error(H, e[:, 0], W), G @ e[:, 0], rtol=1e-9, atol=1e-12
        )
        cov = location_error_covariance(H, Sigma, W)
        np.testing.assert_allclose(cov, G @ Sigma @ G.T, rtol=1e-9, atol=1e-14)
        np.testing.assert_array_equal(cov, cov.T)


def test_weighted_gauss_newton_with_one_outlier():
    """Oracle: noise-free WF Eq. (1) data with one sample corrupted by 50 Hz: with zero weight
    on it (a vector of weights) the fit recovers the emitter exactly; unweighted it does not,
    and the reported normal equation H'W r vanishes at the weighted solution."""
    pos, vel = _arc()
    m = doppler_frequency(F0, EMITTER, pos, vel)
    m[17] += 50.0
    w = np.ones(len(m))
    w[17] = 1e-12
    start = [EMITTER[0] + 1500, EMITTER[1] - 1000, 0.0, F0 + 20.0]
    res = emitter_gauss_newton(m, pos, vel, start, w)
    assert res.converged and 1 < res.iterations < 20
    np.testing.assert_allclose(res.estimate[:3], EMITTER, atol=1e-2)
    assert np.linalg.norm(res.normal_equation) < 1e-3
    plain = emitter_gauss_newton(m, pos, vel, start)
    assert np.linalg.norm(plain.estimate[:3] - EMITTER) > 1.0


def test_doppler_close_to_the_emitter():
    """Oracle: first-order Doppler by hand half a metre from the emitter (any positive range is
    valid): closing at v along the line of sight gives f0 (1 + v/c)."""
    f = doppler_frequency(F0, [0.5, 0.0, 0.0], [[0.0, 0.0, 0.0]], [[30.0, 0.0, 0.0]])
    assert f[0] == pytest.approx(F0 * (1 + 30.0 / C), rel=1e-15)


def test_track_and_emitter_shapes_are_checked():
    """Contract: apertures are (M, 3) (or one (3,) position) and the emitter a (3,) vector."""
    with pytest.raises(ValueError, match="position must have shape"):
        doppler_frequency(F0, EMITTER, np.zeros((4, 2)), np.ones((4, 3)))
    with pytest.raises(ValueError, match="emitter"):
        doppler_frequency(F0, EMITTER[None, :], np.zeros((4, 3)), np.ones((4, 3)))


def test_level_turn_track_is_a_circle_flown_at_constant_speed():
    """Oracle: geometry of the turn: every position lies on the circle of radius v/omega about
    (0, r, h), the speed is v throughout, the velocity is tangent to the circle, and the heading
    advances by omega t (the velocity's angle, from atan2)."""
    from navcore.location.emitter import level_turn_track

    v, h, rate, duration = 150.0, 5000.0, -3.0, 100.0
    t, p, vel = level_turn_track(v, h, 51, rate, duration)
    w = np.deg2rad(rate)
    r = v / w
    centre = np.array([0.0, r, h])
    assert np.allclose(np.linalg.norm(p - centre, axis=1), abs(r), rtol=1e-12)
    assert np.allclose(np.linalg.norm(vel, axis=1), v, rtol=1e-12)
    assert np.allclose(np.sum((p - centre) * vel, axis=1), 0.0, atol=1e-6)
    heading = np.unwrap(np.arctan2(vel[:, 1], vel[:, 0]))
    assert np.allclose(heading, w * t, atol=1e-12)
    assert np.allclose(t, np.linspace(0.0, duration, 51)) and np.all(p[:, 2] == h)
    # the positions are the integral of the velocities (trapezoid rule, fine sampling)
    t, p, vel = level_turn_track(v, h, 20001, rate, duration)
    integral = np.concatenate([[0.0], np.cumsum(0.5 * (vel[1:, 1] + vel[:-1, 1]) * np.diff(t))])
    assert np.allclose(p[:, 1], integral, atol=1e-3)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        ((0.0, 1.0, 5, 2.0, 10.0), "speed"),
        ((100.0, np.nan, 5, 2.0, 10.0), "altitude"),
        ((100.0, 1.0, 1, 2.0, 10.0), "n_samples"),
        ((100.0, 1.0, 5, 0.0, 10.0), "turn_rate_deg_s"),
        ((100.0, 1.0, 5, 2.0, -1.0), "duration"),
    ],
)
def test_level_turn_track_rejects_bad_arguments(args, name):
    from navcore.location.emitter import level_turn_track

    with pytest.raises(ValueError, match=name):
        level_turn_track(*args)
