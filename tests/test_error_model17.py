"""17-state error model (KZL Eqs. 1, 5, 10, 11) and the observation Jacobians (Eqs. 13, 17).

Oracles: central finite differences of the *nonlinear* mechanization and measurement
models (the true and the computed state evaluated separately, scipy's expm/logm for the
attitude perturbation); scipy's expm and navcore's van_loan for the transition; the
geometric null vector (heading error in level flight) for observability.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
from _oracles import van_loan_expm

from navcore import frames as fr
from navcore.estimation import discretize
from navcore.gnss.carrier_phase import dd_covariance, double_difference_phase
from navcore.gnss.measurements import pseudorange, pseudorange_rate
from navcore.inertial.error_model17 import (
    ERROR_LAYOUT_17,
    code_doppler_rows,
    error_dynamics_17,
    noise_psd_17,
    observability_rank,
    skew_paper,
    transition_exact,
    transition_first_order,
)
from navcore.integration.measurement_rows import (
    attitude_observation_rows_count,
    dd_observation_rows,
    dd_observation_rows_count,
    euler_attitude_rows,
    tc_dd_observation_matrix,
)
from navcore.units import G0, GPS_L1_WAVELENGTH_M

L = ERROR_LAYOUT_17
RNG = np.random.default_rng(7)
C_TRUE = fr.dcm_from_euler(0.1, -0.05, 1.3)
F_B = np.array([0.3, -0.2, -G0])  # true specific force (body)
EPS = 1e-6

#: KZL Table 1: three antennas, 2 m baselines (laid along the body x and y axes).
BASELINES_B = np.array([[2.0, 0.0, 0.0], [0.0, 2.0, 0.0]])


def _vee(M):
    return np.array([M[2, 1], M[0, 2], M[1, 0]])


def _perturbed(dpsi):
    return scipy.linalg.expm(fr.skew(dpsi)) @ C_TRUE


def test_layout_has_17_states_in_eq1_order():
    """Oracle: KZL Eq. 1 lists 3+3+3+3+3+2 states in this order."""
    assert L.size == 17
    assert L.table() == [
        ("position", 3),
        ("velocity", 3),
        ("misalignment", 3),
        ("accel bias", 3),
        ("gyro bias", 3),
        ("clock bias", 1),
        ("clock drift", 1),
    ]


def test_F23_is_printed_eq11_matrix():
    """Oracle: the explicit matrix printed in KZL Eq. 11."""
    a = np.array([1.0, 2.0, 3.0])
    an, ae, ad = a
    printed = np.array([[0, ad, -ae], [-ad, 0, an], [ae, -an, 0]])
    F = error_dynamics_17(np.eye(3), a)
    np.testing.assert_array_equal(F[L.slice("velocity"), L.slice("misalignment")], printed)
    np.testing.assert_array_equal(skew_paper(a), printed)


def _dvdot(dpsi, dba):
    """Nonlinear velocity-error rate: R_hat f_hat - R f, with f_hat = f - dba."""
    return _perturbed(dpsi) @ (F_B - dba) - C_TRUE @ F_B


def test_velocity_rows_match_finite_differences():
    """Oracle: central differences of R_hat f_hat - R f w.r.t. dpsi and d b_a."""
    F = error_dynamics_17(C_TRUE, C_TRUE @ F_B)
    J_psi = np.column_stack(
        [(_dvdot(EPS * e, 0 * e) - _dvdot(-EPS * e, 0 * e)) / (2 * EPS) for e in np.eye(3)]
    )
    J_ba = np.column_stack(
        [(_dvdot(0 * e, EPS * e) - _dvdot(0 * e, -EPS * e)) / (2 * EPS) for e in np.eye(3)]
    )
    np.testing.assert_allclose(F[L.slice("velocity"), L.slice("misalignment")], J_psi, atol=1e-7)
    np.testing.assert_allclose(F[L.slice("velocity"), L.slice("accel bias")], J_ba, atol=1e-7)


def test_attitude_rows_match_finite_differences():
    """Oracle: integrate true and computed attitude (w_hat = w - d b_g) over h, take logm(R_hat R^T)."""
    w = np.array([0.01, -0.02, 0.03])
    h = 1e-4
    F = error_dynamics_17(C_TRUE, C_TRUE @ F_B)
    cols = []
    for e in np.eye(3):
        dbg = 1e-3 * e
        R1 = C_TRUE @ scipy.linalg.expm(fr.skew(w * h))
        Rh1 = C_TRUE @ scipy.linalg.expm(fr.skew((w - dbg) * h))
        cols.append(_vee(np.real(scipy.linalg.logm(Rh1 @ R1.T))) / h / 1e-3)
    np.testing.assert_allclose(
        F[L.slice("misalignment"), L.slice("gyro bias")], np.column_stack(cols), atol=1e-5
    )


def test_transition_series_terminates():
    """Oracle: scipy expm equals the cubic polynomial (F^4 = 0, KZL Eq. 5)."""
    F = error_dynamics_17(C_TRUE, C_TRUE @ F_B)
    assert np.abs(np.linalg.matrix_power(F, 4)).max() == 0.0
    np.testing.assert_allclose(transition_exact(F, 1.0), scipy.linalg.expm(F), atol=1e-12)
    Phi_vl, _ = discretize(F, noise_psd_17(1e-2, 1e-3), 1.0)
    np.testing.assert_allclose(transition_exact(F, 1.0), Phi_vl, atol=1e-12)
    # KZL Eq. 6 keeps only the first-order coupling: a tilt moves the velocity error by
    # |f| T per rad (exactly, as e^{FT} does) but the position error not at all, where the
    # exact transition has |f| T^2 / 2 (hand closed forms, level attitude, f = -g down)
    F_lev = error_dynamics_17(np.eye(3), [0.0, 0.0, -G0])
    T = 2.0
    first, exact = transition_first_order(F_lev, T), scipy.linalg.expm(F_lev * T)
    psi_n = L.index("misalignment", 0)
    vel_e, pos_e = L.index("velocity", 1), L.index("position", 1)
    assert first[vel_e, psi_n] == pytest.approx(G0 * T, rel=1e-15)
    assert exact[vel_e, psi_n] == pytest.approx(G0 * T, rel=1e-12)
    assert first[pos_e, psi_n] == 0.0
    assert exact[pos_e, psi_n] == pytest.approx(G0 * T**2 / 2, rel=1e-12)
    np.testing.assert_array_equal(np.diag(first), 1.0)
    np.testing.assert_array_equal(first[L.slice("position"), L.slice("velocity")], T * np.eye(3))


def test_code_doppler_rows_match_finite_differences():
    """Oracle: central differences of navcore.gnss.measurements pseudorange / rate (predicted - true)."""
    r = np.array([100.0, -50.0, -3000.0])
    v = np.array([0.0, 110.0, 0.0])
    sats = RNG.normal(size=(3, 3)) * 1.5e7 + np.array([0, 0, -2e7])
    vsat = RNG.normal(size=(3, 3)) * 3e3
    u = (sats - r) / np.linalg.norm(sats - r, axis=1, keepdims=True)
    H = code_doppler_rows(u)
    for i, e in enumerate(np.eye(3)):
        # steps of 1 m and 1 mm/s: ranges are ~2e7 m, so smaller steps lose digits to cancellation
        d_rho = (pseudorange(r + e, sats) - pseudorange(r - e, sats)) / 2.0
        d_rate = (
            pseudorange_rate(r, v + 1e-3 * e, sats, vsat) - pseudorange_rate(r, v - 1e-3 * e, sats, vsat)
        ) / (2e-3)
        np.testing.assert_allclose(H[0::2, L.slice("position")][:, i], d_rho, atol=1e-6)
        np.testing.assert_allclose(H[1::2, L.slice("velocity")][:, i], d_rate, atol=1e-6)
    np.testing.assert_array_equal(H[0::2, L.index("clock bias")], 1.0)
    np.testing.assert_array_equal(H[1::2, L.index("clock drift")], 1.0)


def test_euler_rows_match_finite_differences():
    """Oracle: central differences of euler_from_dcm(expm([dpsi x]) R) (KZL Eq. 12 observation)."""
    roll, pitch, _ = fr.euler_from_dcm(C_TRUE)
    H = euler_attitude_rows(C_TRUE, roll, pitch)[:, L.slice("misalignment")]
    J = np.column_stack(
        [
            (
                np.array(fr.euler_from_dcm(_perturbed(EPS * e)))
                - np.array(fr.euler_from_dcm(_perturbed(-EPS * e)))
            )
            / (2 * EPS)
            for e in np.eye(3)
        ]
    )
    np.testing.assert_allclose(H, J, atol=1e-8)


def test_dd_rows_match_finite_differences():
    """Oracle: central differences of the exact DD phase (KZL Eq. 15) with antennas at r + R_hat l."""
    r = np.array([0.0, 0.0, -3000.0])
    sats = np.array([[1.2e7, 5e6, -1.8e7], [-8e6, 1.4e7, -1.6e7], [3e6, -1.5e7, -1.9e7]])
    u = (sats - r) / np.linalg.norm(sats - r, axis=1, keepdims=True)

    def dd(dpsi, n):
        C = _perturbed(dpsi)
        return np.array([double_difference_phase(sats[0], sats[n], r, r + C @ b) for b in BASELINES_B])

    for n in (1, 2):
        H = dd_observation_rows(u[0], u[n], C_TRUE, BASELINES_B)[:, L.slice("misalignment")]
        J = np.column_stack([(dd(1e-5 * e, n) - dd(-1e-5 * e, n)) / 2e-5 for e in np.eye(3)])
        np.testing.assert_allclose(H, J, rtol=1e-5, atol=1e-5)  # plane-wave Jacobian: O(|b|/rho)
    # plane-wave form of Eq. 15
    dd0 = double_difference_phase(sats[0], sats[1], r, r + C_TRUE @ BASELINES_B[0])
    plane = 2 * np.pi / GPS_L1_WAVELENGTH_M * (u[0] - u[1]) @ C_TRUE @ BASELINES_B[0]
    assert float(dd0) == pytest.approx(float(plane), abs=1e-5)


def test_row_counts_follow_printed_formulas():
    """Oracle: the printed formulas (3 + 2 nu) and (2 + 4 (nu - 1)) (KZL Sec. 3.4)."""
    for nu in range(1, 9):
        assert attitude_observation_rows_count(nu) == 3 + 2 * nu
        assert dd_observation_rows_count(nu) == 2 + 4 * (nu - 1)


def test_dd_covariance_by_differencing():
    """Oracle: sample covariance of simulated undifferenced phases, differenced by hand."""
    rng = np.random.default_rng(3)
    sigma, nu = 0.1, 3
    phi = rng.normal(scale=sigma, size=(200_000, nu, 3))  # (sample, satellite, antenna)
    dd = np.stack(
        [(phi[:, s, a] - phi[:, s, 0]) - (phi[:, 0, a] - phi[:, 0, 0]) for s in (1, 2) for a in (1, 2)],
        axis=1,
    )
    np.testing.assert_allclose(np.cov(dd.T), dd_covariance(nu, sigma), atol=2e-3 * 4 * sigma**2 * 10)


def test_heading_unobservable_without_attitude_aiding():
    """Oracle: in level unaccelerated flight a heading error does not change any velocity, so
    e_heading is in the null space of the TC observability matrix; DD aiding removes it."""
    C = fr.dcm_from_euler(0, 0, np.pi / 2)
    F = error_dynamics_17(C, [0, 0, -G0])
    u = np.array([[0.3, 0.4, -0.866], [-0.5, 0.2, -0.84], [0.1, -0.7, -0.7], [0.8, 0.1, -0.59]])
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    H = code_doppler_rows(u)
    e = np.zeros(17)
    e[L.index("misalignment", 2)] = 1.0
    for k in range(17):
        assert np.abs(H @ np.linalg.matrix_power(F, k) @ e).max() == 0.0
    assert observability_rank(F, H) < 17
    assert observability_rank(F, tc_dd_observation_matrix(u, C, BASELINES_B)) == 17


def test_noise_psd_closed_form_growth():
    """Oracle: closed forms of integrated white noise (scipy Van Loan, free fall so that the
    tilt does not feed the velocity, non-level attitude): white accelerometer noise q_a and an
    accelerometer-bias random walk q_ba give velocity variance q_a t + q_ba t^3/3 and position
    variance q_a t^3/3 + q_ba t^5/20; the gyro pair gives psi variance q_g t + q_bg t^3/3;
    the clock bias has q_cb t + q_cd t^3/3 and the drift q_cd t (every root PSD distinct)."""
    qa, qg, qba, qbg, qcd, qcb = 0.02, 0.003, 4e-4, 5e-6, 0.07, 0.6
    Q = noise_psd_17(np.sqrt(qa), np.sqrt(qg), np.sqrt(qba), np.sqrt(qbg), np.sqrt(qcd), np.sqrt(qcb))
    F = error_dynamics_17(C_TRUE, [0.0, 0.0, 0.0])
    t = 30.0
    _, Qd = van_loan_expm(F, Q, t)
    d = np.diag(Qd)
    np.testing.assert_allclose(d[L.slice("velocity")], qa * t + qba * t**3 / 3, rtol=1e-10)
    np.testing.assert_allclose(d[L.slice("position")], qa * t**3 / 3 + qba * t**5 / 20, rtol=1e-10)
    np.testing.assert_allclose(d[L.slice("misalignment")], qg * t + qbg * t**3 / 3, rtol=1e-10)
    np.testing.assert_allclose(d[L.slice("accel bias")], qba * t, rtol=1e-12)
    np.testing.assert_allclose(d[L.slice("gyro bias")], qbg * t, rtol=1e-12)
    assert d[L.index("clock bias")] == pytest.approx(qcb * t + qcd * t**3 / 3, rel=1e-10)
    assert d[L.index("clock drift")] == pytest.approx(qcd * t, rel=1e-12)
    # without the optional walks the biases are random constants and the clock is noiseless
    d0 = np.diag(noise_psd_17(0.1, 0.01))
    np.testing.assert_array_equal(d0[L.slice("velocity")], 0.1**2)
    np.testing.assert_array_equal(d0[L.slice("misalignment")], 0.01**2)
    assert np.all(d0[L.slice("accel bias").start :] == 0.0)
    with pytest.raises(ValueError, match="gyro_noise"):
        noise_psd_17(0.1, -1.0)


def test_batched_dynamics_match_finite_differences():
    """Oracle: the central differences of the nonlinear velocity-error rate (as in
    test_velocity_rows_match_finite_differences) for each of two attitudes and forces
    given as a batch."""
    Cs = np.stack([C_TRUE, fr.dcm_from_euler(-0.4, 0.2, -2.5)])
    fb = np.stack([F_B, np.array([1.0, 0.5, -8.0])])
    F = error_dynamics_17(Cs, np.einsum("nij,nj->ni", Cs, fb))
    assert F.shape == (2, 17, 17)
    for k in range(2):

        def dvdot(dpsi, dba, k=k):
            return scipy.linalg.expm(fr.skew(dpsi)) @ Cs[k] @ (fb[k] - dba) - Cs[k] @ fb[k]

        J_psi = np.column_stack(
            [(dvdot(EPS * e, 0 * e) - dvdot(-EPS * e, 0 * e)) / (2 * EPS) for e in np.eye(3)]
        )
        J_ba = np.column_stack(
            [(dvdot(0 * e, EPS * e) - dvdot(0 * e, -EPS * e)) / (2 * EPS) for e in np.eye(3)]
        )
        np.testing.assert_allclose(F[k][L.slice("velocity"), L.slice("misalignment")], J_psi, atol=1e-7)
        np.testing.assert_allclose(F[k][L.slice("velocity"), L.slice("accel bias")], J_ba, atol=1e-7)
        np.testing.assert_allclose(F[k][L.slice("misalignment"), L.slice("gyro bias")], -Cs[k], atol=0)


def test_observability_rank_of_hand_systems():
    """Oracle: hand analysis. A double integrator is observable from position (rank 2) but
    not from velocity (rank 1); a zero measurement observes nothing (rank 0); two decoupled
    integrators seen through their sum have rank 1."""
    F = [[0.0, 1.0], [0.0, 0.0]]
    assert observability_rank(F, [[1.0, 0.0]]) == 2
    assert observability_rank(F, [[0.0, 1.0]]) == 1
    assert observability_rank(F, [[0.0, 0.0]]) == 0
    assert observability_rank(np.zeros((2, 2)), [[1.0, 1.0]]) == 1
    # units do not matter: rows are normalised (a 1e6 against a 1e-6 scale)
    assert observability_rank(np.zeros((2, 2)), [[1e6, 0.0], [0.0, 1e-6]]) == 2
    # two unit rows at angle t have singular values sqrt(1 +- cos t): their ratio tan(t/2)
    # = 0.07 counts as a second dimension for rtol 0.05, not for rtol 0.1
    t = 2 * np.arctan(0.07)
    H = [[1.0, 0.0], [np.cos(t), np.sin(t)]]
    assert observability_rank(np.zeros((2, 2)), H, rtol=0.05) == 2
    assert observability_rank(np.zeros((2, 2)), H, rtol=0.1) == 1
