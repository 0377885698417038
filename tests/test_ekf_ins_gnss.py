"""Tightly coupled feedback EKF pieces (KZL Secs. 3.4-3.5) and the batched Monte Carlo.

Oracles: navcore.estimation.kf_update (one batch Joseph update) for the sequential scalar
updates; van_loan for the Gauss-Legendre discrete noise; scipy's Rotation for the attitude
correction; carrier_phase's single-case builders for the batched Jacobians; S calls of
strapdown_step for the Monte Carlo's chained strapdown. The Monte Carlo
itself is tested against physics in test_ekf_ins_gnss_physics.py.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from navcore import frames as fr
from navcore.estimation import discretize, kf_update
from navcore.gnss.carrier_phase import dd_covariance, double_difference_phase
from navcore.inertial.error_model17 import error_dynamics_17, noise_psd_17, transition_exact
from navcore.inertial.strapdown import NavState, strapdown_step
from navcore.integration.ekf_ins_gnss import (
    _dd_phase_batch,
    _strapdown_rows,
    _transition_and_noise,
    correct_attitude,
    euler_batch,
    euler_jacobian_batch,
    run_monte_carlo,
    sequential_scalar_updates,
)
from navcore.integration.measurement_rows import euler_attitude_rows
from navcore.papers.kzl_scenario import table1_scenario
from navcore.units import DEG, G0


def _spd(rng, n):
    A = rng.normal(size=(n, n))
    return A @ A.T + n * np.eye(n)


def test_sequential_equals_batch_update():
    """Oracle: kf_update with R = diag(r) (sequential scalar processing is exact for diagonal R)."""
    rng = np.random.default_rng(0)
    n, m = 17, 9
    P = _spd(rng, n)
    H = rng.normal(size=(m, n))
    r = rng.uniform(0.5, 2.0, m)
    y = rng.normal(size=m)
    x0 = rng.normal(size=n)
    ref = kf_update(x0, P, y, H, np.diag(r))
    x, Ps = sequential_scalar_updates(x0[None], P[None], y[None], H[None], r)
    np.testing.assert_allclose(x[0], ref.x, atol=1e-10)
    np.testing.assert_allclose(Ps[0], ref.P, atol=1e-10)


def test_whitened_dd_sequential_equals_batch():
    """Oracle: kf_update with the full correlated DD covariance (Cholesky-whitened sequential)."""
    rng = np.random.default_rng(1)
    R = dd_covariance(4, 0.1)
    m = R.shape[0]
    P = _spd(rng, 17)
    H = rng.normal(size=(m, 17))
    y = rng.normal(size=m)
    ref = kf_update(np.zeros(17), P, y, H, R)
    Linv = np.linalg.inv(np.linalg.cholesky(R))
    x, Ps = sequential_scalar_updates(
        np.zeros((1, 17)), P[None], (Linv @ y)[None], (Linv @ H)[None], np.ones(m)
    )
    np.testing.assert_allclose(x[0], ref.x, atol=1e-10)
    np.testing.assert_allclose(Ps[0], ref.P, atol=1e-10)


def test_gauss_legendre_noise_equals_van_loan():
    """Oracle: van_loan (one matrix exponential) for the nilpotent 17-state F."""
    C = fr.dcm_from_euler(0.02, -0.01, np.pi / 2)
    F = error_dynamics_17(C, C @ [0.1, 0.0, -G0])
    GQG = noise_psd_17(1e-2, 1e-3, 1e-5, 1e-6, 0.2, 0.1)
    _, Qd = discretize(F, GQG, 1.0)
    np.testing.assert_allclose(discretize(F, GQG, 1.0, method="nilpotent")[1], Qd, rtol=1e-10, atol=1e-16)
    _, Qd = discretize(F, GQG, 0.7)
    np.testing.assert_allclose(discretize(F, GQG, 0.7, method="nilpotent")[1], Qd, rtol=1e-10, atol=1e-16)


def test_fused_transition_and_noise_equal_van_loan():
    """Oracle: van_loan (one matrix exponential) for the transition and the discrete noise that the
    Monte Carlo's loop forms together from the powers of a batch of F."""
    F = np.stack(
        [
            error_dynamics_17(
                fr.dcm_from_euler(0.02, -0.01, yaw), fr.dcm_from_euler(0.02, -0.01, yaw) @ [0.1, 0, -G0]
            )
            for yaw in (0.3, np.pi / 2)
        ]
    )
    GQG = noise_psd_17(1e-2, 1e-3, 1e-5, 1e-6, 0.2, 0.1)
    for dt in (1.0, 0.7):
        Phi, Qd = _transition_and_noise(F, np.diag(GQG), dt)
        for i in range(2):
            Phi_ref, Qd_ref = discretize(F[i], GQG, dt)
            np.testing.assert_allclose(Phi[i], Phi_ref, rtol=1e-12, atol=1e-14)
            np.testing.assert_allclose(Qd[i], Qd_ref, rtol=1e-10, atol=1e-16)
        np.testing.assert_allclose(Phi, transition_exact(F, dt), rtol=1e-14, atol=1e-15)


def test_left_correction_removes_n_frame_error():
    """Oracle: scipy Rotation — R_hat = exp([dpsi x]) R; the left correction recovers R exactly,
    the printed right-hand order leaves a residual at heading 90 deg."""
    R_true = Rotation.from_euler("ZYX", [90, 0, 0], degrees=True)
    dpsi = np.array([1.0, -0.5, 2.0]) * DEG
    R_hat = Rotation.from_rotvec(dpsi) * R_true
    q_hat = fr.quat_from_dcm(R_hat.as_matrix())
    q_left = correct_attitude(q_hat[None], dpsi[None], "left")[0]
    q_right = correct_attitude(q_hat[None], dpsi[None], "right")[0]
    err = lambda q: Rotation.from_matrix(fr.dcm_from_quat(q) @ R_true.as_matrix().T).magnitude()
    assert err(q_left) < 1e-12
    # the right-hand order removes the rotation about body axes: R_hat exp(-[dpsi x])
    right = R_hat * Rotation.from_rotvec(-dpsi)
    assert err(q_right) == pytest.approx((right * R_true.inv()).magnitude(), rel=1e-9)
    assert err(q_right) > 0.5 * np.linalg.norm(dpsi)  # heading 90 deg: body and n axes differ
    with pytest.raises(ValueError, match="side"):
        correct_attitude(q_hat[None], dpsi[None], "middle")
    # one quaternion without a batch axis, the default (left) side
    np.testing.assert_allclose(correct_attitude(q_hat, dpsi), q_left, atol=1e-15)


def test_batched_jacobians_match_builders():
    """Oracle: carrier_phase.euler_attitude_rows and double_difference_phase (single-case
    builders), scipy's Rotation for the Euler angles; batches of two axes and of two runs."""
    eul = np.array([[[0.1, -0.2, 1.2], [-0.4, 0.3, -2.9]], [[1.0, 0.05, 0.2], [0.0, -1.2, 3.0]]])
    C = np.array([[fr.dcm_from_euler(*e) for e in row] for row in eul])  # (2, 2, 3, 3)
    J = euler_jacobian_batch(C)
    E = euler_batch(C)
    for i in range(2):
        for j in range(2):
            roll, pitch, _ = fr.euler_from_dcm(C[i, j])
            np.testing.assert_allclose(J[i, j], euler_attitude_rows(C[i, j], roll, pitch)[:, 6:9])
            want = Rotation.from_matrix(C[i, j]).as_euler("ZYX")[::-1]
            np.testing.assert_allclose(E[i, j], want, atol=1e-12)
    pos = np.array([[10.0, 20.0, -3000.0], [-500.0, 80.0, -2500.0]])
    ant = np.array([[[2.0, 0.1, 0.0], [0.0, 2.0, 0.3]], [[1.0, -1.0, 0.2], [-0.5, 1.5, 0.0]]])
    sm, sn = np.array([1e7, 2e6, -2e7]), np.array([-5e6, 1.5e7, -1.8e7])
    got = _dd_phase_batch(pos, ant, sn, sm)
    for i in range(2):
        expect = [double_difference_phase(sm, sn, pos[i], pos[i] + a) for a in ant[i]]
        np.testing.assert_allclose(got[i], expect, atol=1e-9)


def test_bad_mode_rejected():
    with pytest.raises(ValueError, match="mode"):
        run_monte_carlo(table1_scenario(), "loose", 2, 0)


def test_chained_strapdown_equals_one_step_at_a_time():
    # oracle: S calls of strapdown_step (the mechanization of KZL Eqs. 7-9, one IMU interval each)
    rng = np.random.default_rng(7)
    n, steps, dt = 5, 100, 0.01
    w = 1e-2 * rng.normal(size=(n, steps, 3)) + 2e-3
    f = np.array([0.3, -0.2, -G0]) + 0.05 * rng.normal(size=(n, steps, 3))
    q0 = fr.quat_from_rotvec(0.3 * rng.normal(size=(n, 3)))
    pos0, vel0 = rng.normal(size=(n, 3)), 100.0 * rng.normal(size=(n, 3))
    pos, vel, quat, f_n_mean = _strapdown_rows(pos0, vel0, q0, w, f, dt)
    state, f_n = NavState(pos0, vel0, q0), []
    for s in range(steps):
        q_mid = np.array([_mid(state.quat[i], w[i, s] * dt) for i in range(n)])
        f_n.append(np.einsum("nij,nj->ni", np.array([fr.dcm_from_quat(q) for q in q_mid]), f[:, s]))
        state = strapdown_step(state, w[:, s], f[:, s], dt)
    assert np.allclose(pos, state.pos, rtol=1e-12, atol=1e-9)
    assert np.allclose(vel, state.vel, rtol=1e-12, atol=1e-11)
    assert np.allclose(quat, state.quat, rtol=0.0, atol=1e-13)
    assert np.allclose(f_n_mean, np.mean(f_n, axis=0), rtol=0.0, atol=1e-12)


def _mid(q: np.ndarray, rotvec: np.ndarray) -> np.ndarray:
    """The mid-interval attitude of strapdown_step: q times half the body increment."""
    return fr.quat_multiply(q, fr.quat_from_rotvec(0.5 * rotvec))
