"""The estimation kernel: the one Joseph-form update, the one discretiser and the covariance of a
filter that ignores a measurement bias.

Oracles: the textbook Joseph form written per sample with ``np.eye``; scipy's ``expm`` of Van
Loan's block (tests/_oracles.py); closed forms of the discrete noise of an integrator chain;
a per-row loop over the augmented error state written from its recursion; a seeded Monte
Carlo of the filter and its bias.
"""

from __future__ import annotations

import numpy as np
import pytest
from _oracles import van_loan_expm

from navcore.estimation import biased_filter_error_covariance, discretize, joseph_update, kf_update
from navcore.estimation.discretize import discretize_unchecked


def _spd(rng, n):
    A = rng.standard_normal((n, n))
    return A @ A.T + n * np.eye(n)


def _textbook_joseph(P, K, H, R):
    I_KH = np.eye(P.shape[0]) - K @ H
    return I_KH @ P @ I_KH.T + K @ R @ K.T


def test_joseph_update_batched_equals_the_textbook_form_per_sample():
    rng = np.random.default_rng(7)
    B, n, m = 5, 6, 2
    P = np.stack([_spd(rng, n) for _ in range(B)])
    K = rng.standard_normal((B, n, m))  # any gain
    H = rng.standard_normal((B, m, n))
    R = np.stack([_spd(rng, m) for _ in range(B)])
    got = joseph_update(P, K, H, R)
    for b in range(B):
        ref = _textbook_joseph(P[b], K[b], H[b], R[b])
        np.testing.assert_allclose(got[b], ref, rtol=1e-13, atol=1e-12)
        np.testing.assert_array_equal(joseph_update(P[b], K[b], H[b], R[b]), got[b])  # batched == looped
    np.testing.assert_array_equal(got, np.swapaxes(got, -1, -2))  # exactly symmetric


def test_joseph_update_with_the_optimal_gain_is_the_short_form_and_kf_update_uses_it():
    rng = np.random.default_rng(8)
    P, R = _spd(rng, 4), _spd(rng, 2)
    H = rng.standard_normal((2, 4))
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + R)
    np.testing.assert_allclose(joseph_update(P, K, H, R), (np.eye(4) - K @ H) @ P, rtol=1e-10, atol=1e-12)
    up = kf_update(np.zeros(4), P, np.ones(2), H, R)
    np.testing.assert_array_equal(up.P, joseph_update(P, up.K, H, R))


def test_joseph_update_on_rows_is_the_full_form_with_the_embedded_gain():
    """The gain of a filter on some states of a larger truth: E K, zero on the other rows."""
    rng = np.random.default_rng(9)
    B, n, m = 3, 7, 2
    rows = np.array([0, 2, 3, 5])
    P = np.stack([_spd(rng, n) for _ in range(B)])
    K = rng.standard_normal((B, rows.size, m))
    H = rng.standard_normal((m, n))
    R = _spd(rng, m)
    EK = np.zeros((B, n, m))
    EK[:, rows] = K
    got = joseph_update(P, K, H, R, rows=rows)
    for b in range(B):
        np.testing.assert_allclose(got[b], _textbook_joseph(P[b], EK[b], H, R), rtol=1e-12, atol=1e-11)


def test_joseph_update_rejects_mismatched_shapes_naming_them():
    with pytest.raises(ValueError, match="K must be"):
        joseph_update(np.eye(3), np.ones((2, 1)), np.ones((1, 3)), np.eye(1))


@pytest.mark.parametrize("method", ["van_loan", "nilpotent", "series"])
def test_discretize_integrator_chain_closed_form(method):
    """x''' = w (PSD q): Q_d[i, j] = q dt^(5-i-j) / ((2-i)! (2-j)! (5-i-j)), exact for every method
    (F^3 = 0: the series and the cubic are exact, and so is each quadrature)."""
    q, dt = 0.3, 0.7
    F = np.diag([1.0, 1.0], 1)
    S = np.diag([0.0, 0.0, q])
    fact = [1.0, 1.0, 2.0]
    ref = np.array(
        [
            [q * dt ** (5 - i - j) / (fact[2 - i] * fact[2 - j] * (5 - i - j)) for j in range(3)]
            for i in range(3)
        ]
    )
    Phi, Qd = discretize(F, S, dt, method=method)
    np.testing.assert_allclose(Qd, ref, rtol=1e-13, atol=0)
    np.testing.assert_allclose(Phi, [[1.0, dt, dt * dt / 2], [0.0, 1.0, dt], [0.0, 0.0, 1.0]], rtol=1e-14)


def test_discretize_van_loan_equals_scipy_expm_of_the_block():
    rng = np.random.default_rng(10)
    F = rng.standard_normal((5, 5))
    S = _spd(rng, 5)
    Phi, Qd = discretize(F, S, 0.4)
    Phi_ref, Qd_ref = van_loan_expm(F, S, 0.4)
    np.testing.assert_allclose(Phi, Phi_ref, rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(Qd, 0.5 * (Qd_ref + Qd_ref.T), rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("method", ["van_loan", "nilpotent", "series"])
def test_discretize_batched_equals_looped(method):
    rng = np.random.default_rng(11)
    F = np.triu(rng.standard_normal((4, 5, 5)), 1) * 0.1  # nilpotent: every method applies
    S = np.stack([_spd(rng, 5) for _ in range(4)])
    Phi, Qd = discretize(F, S, 0.5, method=method)
    for b in range(4):
        Phi_b, Qd_b = discretize(F[b], S[b], 0.5, method=method)
        np.testing.assert_allclose(Phi[b], Phi_b, rtol=1e-15, atol=1e-17)
        np.testing.assert_allclose(Qd[b], Qd_b, rtol=1e-15, atol=1e-17)


def test_discretize_methods_agree_on_a_nilpotent_model():
    """A strictly upper-triangular 4x4 F has F^4 = 0: the cubic and the four-node rule are exact."""
    rng = np.random.default_rng(12)
    F = np.triu(rng.standard_normal((4, 4)), 1) * 0.3
    assert not np.linalg.matrix_power(F, 4).any()
    S = np.diag(rng.uniform(0.1, 1.0, 4))
    Phi_vl, Q_vl = discretize(F, S, 1.0)
    Phi_nil, Q_nil = discretize(F, S, 1.0, method="nilpotent")
    np.testing.assert_allclose(Phi_nil, Phi_vl, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(Q_nil, Q_vl, rtol=1e-10, atol=1e-14)


def test_discretize_unchecked_diagonal_noise_is_the_product_with_diag_exactly():
    rng = np.random.default_rng(13)
    F = np.triu(rng.standard_normal((3, 6, 6)), 1) * 0.2
    q = rng.uniform(0.0, 1.0, 6)
    for method in ("nilpotent", "series"):
        full = discretize_unchecked(F, np.diag(q), 1.0, method=method)
        diag = discretize_unchecked(F, q, 1.0, method=method, diagonal=True)
        np.testing.assert_array_equal(diag[1], full[1])
        np.testing.assert_array_equal(diag[0], full[0])


def _sparse_stack(rng, M, B, n):
    """A stack of dense dynamics (|F| dt about 0.3, not nilpotent) with zero rows: states 6-8
    static in every member, state 5 static in member 0 only; diagonal noises leaving states 0,
    2, 6 and 7 undriven (6 and 7 random constants, 8 a random walk)."""
    F = rng.standard_normal((M, 1, n, n)) * 0.1
    F[..., 6:, :] = 0.0
    F[0, :, 5, :] = 0.0
    q = rng.uniform(0.5, 2.0, (M, B, n))
    q[..., [0, 2, 6, 7]] = 0.0
    return F, q


@pytest.mark.parametrize("order", [4, 12])
def test_discretize_unchecked_sparse_series_equals_the_dense_series(order):
    """Oracle: the dense series, ``discretize(F, diag(q), dt, method="series")`` per model and
    noise (``order`` 4), and ``discretize_unchecked`` without ``sparse`` (any ``order``). The
    row-sparse form sums the same terms in another order: equal to round-off, and exactly in
    the unit rows of the static states, the zero rows and columns of the random constants and
    the transition of a stack with no zero row (the same Horner steps, plus zero)."""
    rng = np.random.default_rng(29)
    M, B, n, dt = 4, 3, 9, 1.5
    F, q = _sparse_stack(rng, M, B, n)
    Phi, Qd = discretize_unchecked(F, q, dt, method="series", diagonal=True, sparse=True, order=order)
    assert Phi.shape == (M, 1, n, n) and Qd.shape == (M, B, n, n)
    Phi_d, Qd_d = discretize_unchecked(F, q, dt, method="series", diagonal=True, order=order)
    np.testing.assert_allclose(Phi, Phi_d, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(Qd, Qd_d, rtol=1e-12, atol=1e-15 * np.abs(Qd_d).max())
    for m in range(M):
        for b in range(B):
            if order == 4:
                Phi_1, Qd_1 = discretize(F[m, 0], np.diag(q[m, b]), dt, method="series")
                np.testing.assert_allclose(Phi[m, 0], Phi_1, rtol=1e-12, atol=1e-15)
                np.testing.assert_allclose(Qd[m, b], Qd_1, rtol=1e-12, atol=1e-15 * np.abs(Qd_1).max())
            np.testing.assert_array_equal(Qd[m, b], Qd[m, b].T)
    # exactly: the static states' unit rows, the random constants' zero rows and columns
    np.testing.assert_array_equal(Phi[..., 6:, :], np.broadcast_to(np.eye(n)[6:], (M, 1, 3, n)))
    np.testing.assert_array_equal(Phi[..., 6:, :], Phi_d[..., 6:, :])
    np.testing.assert_array_equal(Phi[0, 0, 5], np.eye(n)[5])
    assert not Qd[..., [6, 7], :].any() and not Qd[..., :, [6, 7]].any()
    assert not Qd_d[..., [6, 7], :].any() and not Qd_d[..., :, [6, 7]].any()
    assert (Qd[..., 8, 8] > 0.0).all()  # the random walk
    # exactly: a stack with no zero row transforms every row, by the dense Horner steps
    F_full = rng.standard_normal((M, 1, n, n)) * 0.1
    full = discretize_unchecked(F_full, q, dt, method="series", diagonal=True, sparse=True, order=order)
    np.testing.assert_array_equal(
        full[0], discretize_unchecked(F_full, q, dt, method="series", diagonal=True, order=order)[0]
    )
    # no driven state: no noise
    none = discretize_unchecked(F, np.zeros_like(q), dt, method="series", diagonal=True, sparse=True)[1]
    assert none.shape == (M, B, n, n) and not none.any()


def test_discretize_unchecked_sparse_is_the_series_with_diagonal_noise_only():
    with pytest.raises(ValueError, match="sparse"):
        discretize_unchecked(
            np.zeros((2, 2)), np.ones(2), 1.0, method="nilpotent", diagonal=True, sparse=True
        )
    with pytest.raises(ValueError, match="sparse"):
        discretize_unchecked(np.zeros((2, 2)), np.eye(2), 1.0, method="series", sparse=True)


def test_discretize_rejects_an_unknown_method_and_a_bad_noise():
    with pytest.raises(ValueError, match="method"):
        discretize(np.zeros((2, 2)), np.eye(2), 1.0, method="euler")
    with pytest.raises(ValueError, match="GQGt"):
        discretize(np.zeros((2, 2)), -np.eye(2), 1.0)


def _augmented_loop(Phi, Q, P0, h, sigma, bias_sigma):
    """The filter and the truth (error and bias) of one row, from the recursion written out."""
    n = Phi.shape[0]
    P = P0.copy()
    C = np.zeros((n + 1, n + 1))
    C[:n, :n] = P0
    C[n, n] = bias_sigma**2
    for s in sigma:
        P = Phi @ P @ Phi.T + Q
        A = np.eye(n + 1)
        A[:n, :n] = Phi
        C = A @ C @ A.T
        C[:n, :n] += Q
        if np.isnan(s):
            continue
        K = P @ h / (h @ P @ h + s * s)
        P = (np.eye(n) - np.outer(K, h)) @ P  # the filter's own (optimal) update
        M = np.eye(n + 1)
        M[:n, :n] -= np.outer(K, h)
        M[:n, n] = -K  # e+ = (I - K h') e - K b - K v
        C = M @ C @ M.T
        C[:n, :n] += s * s * np.outer(K, K)
    return C


def test_biased_filter_error_covariance_equals_the_recursion_per_row():
    rng = np.random.default_rng(14)
    n = 4
    Phi = np.eye(n) + np.diag(np.full(n - 1, 0.5), 1)
    Q = np.diag([0.0, 0.01, 0.0, 1e-4])
    P0 = np.diag([25.0, 1.0, 0.1, 0.01])
    h = np.eye(n)[0]
    sigma = rng.uniform(1.0, 5.0, (3, 40))
    sigma[0, 10:20] = np.nan  # an outage
    sigma[1, :] = np.nan  # never measured
    got = biased_filter_error_covariance(Phi, Q, P0, h, sigma, 3.0)
    for b in range(3):
        ref = _augmented_loop(Phi, Q, P0, h, sigma[b], 3.0)
        np.testing.assert_allclose(got[b], ref, rtol=1e-9, atol=1e-12)


def test_biased_filter_error_covariance_without_bias_is_the_filters_own():
    Phi = np.array([[1.0, 1.0], [0.0, 1.0]])
    Q = np.diag([0.0, 0.01])
    P0 = np.diag([4.0, 1.0])
    sigma = np.full(30, 2.0)
    C = biased_filter_error_covariance(Phi, Q, P0, [1.0, 0.0], sigma, 0.0)[0]
    P = P0
    for s in sigma:
        P = Phi @ P @ Phi.T + Q
        up = kf_update(np.zeros(2), P, [0.0], [[1.0, 0.0]], [[s * s]])
        P = up.P
    np.testing.assert_allclose(C[:2, :2], P, rtol=1e-12)


def test_biased_filter_error_covariance_matches_a_seeded_monte_carlo():
    """The filter run on simulated measurements with a bias it ignores: the sample covariance
    of the final error is within sampling error (20 000 runs) of the exact one."""
    rng = np.random.default_rng(15)
    Phi = np.array([[1.0, 1.0], [0.0, 1.0]])
    Q = np.diag([0.0, 0.04])
    P0 = np.diag([9.0, 1.0])
    h = np.array([1.0, 0.0])
    sigma = np.full(25, 1.5)
    b_sigma = 2.0
    N = 20_000
    x = rng.standard_normal((N, 2)) * np.sqrt(np.diag(P0))
    xh = np.zeros((N, 2))
    bias = b_sigma * rng.standard_normal(N)
    P = P0.copy()
    for s in sigma:
        x = x @ Phi.T + rng.standard_normal((N, 2)) * np.sqrt(np.diag(Q))
        xh = xh @ Phi.T
        P = Phi @ P @ Phi.T + Q
        z = x[:, 0] + bias + s * rng.standard_normal(N)
        K = P @ h / (P[0, 0] + s * s)
        xh = xh + np.outer(z - xh[:, 0], K)
        P = (np.eye(2) - np.outer(K, h)) @ P
    e = x - xh
    C = biased_filter_error_covariance(Phi, Q, P0, h, sigma, b_sigma)[0]
    var_mc = e.var(axis=0)
    se = np.diag(C)[:2] * np.sqrt(2.0 / N)
    assert np.all(np.abs(var_mc - np.diag(C)[:2]) < 4 * se)
    assert np.diag(C)[0] > P[0, 0] * 1.5  # the ignored bias leaves far more error than the filter thinks


def test_joseph_unchecked_scalar_variance_is_the_one_by_one_noise():
    """A single measurement's variance as a scalar: R (K K^T), the same matrix as K [[R]] K^T."""
    from navcore.estimation.kalman import joseph_unchecked

    rng = np.random.default_rng(16)
    P = _spd(rng, 6)
    K = rng.standard_normal((6, 1))
    H = np.eye(6)[:1]
    scalar = joseph_unchecked(P, K, H, 2.5, symmetric=False)
    matrix = joseph_unchecked(P, K, H, np.array([[2.5]]), symmetric=False)
    np.testing.assert_allclose(scalar, matrix, rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(scalar, _textbook_joseph(P, K, H, np.array([[2.5]])), rtol=1e-13)
