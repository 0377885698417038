"""Constrained LMMSE with a nonrandom nuisance vector (ATC-10 App. H) against brute force and Monte Carlo."""

from __future__ import annotations

import numpy as np
import pytest

from navcore.estimation.lmmse import (
    lmmse_with_nuisance,
    lmmse_with_nuisance_information_form,
    scalar_nuisance_gain,
)


def _problem(seed: int = 0, r: int = 7, p: int = 2, q: int = 3):
    rng = np.random.default_rng(seed)
    F = rng.normal(size=(r, p))
    G = rng.normal(size=(r, q))
    A = rng.normal(size=(p, p))
    P_x = A @ A.T + 0.5 * np.eye(p)
    B = rng.normal(size=(r, r))
    P_n = B @ B.T / r + 0.3 * np.eye(r)
    mu_x = rng.normal(size=p)
    mu_n = rng.normal(size=r)
    return F, G, mu_x, P_x, mu_n, P_n


def _kkt_gain(F, G, P_x, P_n):
    """Brute force: for each row a of the gain, minimise E(a'z - x_i)^2 = a'P_z a - 2 a'P_zx[:, i]
    + const subject to G'a = 0 (the estimate must not depend on the nuisance y), by the KKT
    linear system; P_z = P_n + F P_x F', P_zx = F P_x."""
    P_z = P_n + F @ P_x @ F.T
    P_zx = F @ P_x
    r, q = G.shape
    kkt = np.block([[P_z, G], [G.T, np.zeros((q, q))]])
    rows = [np.linalg.solve(kkt, np.concatenate([P_zx[:, i], np.zeros(q)]))[:r] for i in range(F.shape[1])]
    return np.array(rows)


def test_information_forms_equal_brute_force_covariance():
    """Oracle: the error covariance of the brute-force (KKT) constrained gain A, computed from
    the model z = F x + G y + n: e = (A F - I)(x - mu_x) + A (n - mu_n), so
    P = (A F - I) P_x (A F - I)' + A P_n A'. Both the direct (H.16)/(H.8) and the information
    forms (H.21)/(H.22) must equal it; and the x gain ignores y (H G = 0), the y gain is
    unbiased for y (K G = I)."""
    F, G, mu_x, P_x, mu_n, P_n = _problem()
    est = lmmse_with_nuisance(F, G, mu_x, P_x, mu_n, P_n)
    Px, Py = lmmse_with_nuisance_information_form(F, G, P_x, P_n)
    A = _kkt_gain(F, G, P_x, P_n)
    I = np.eye(F.shape[1])
    want = (A @ F - I) @ P_x @ (A @ F - I).T + A @ P_n @ A.T
    np.testing.assert_allclose(est.P_x_err, want, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(Px, want, rtol=1e-9, atol=1e-12)
    # y: generalized least squares on z - F mu_x with the noise n + F (x - mu_x)
    W = np.linalg.inv(P_n + F @ P_x @ F.T)
    P_gls = np.linalg.inv(G.T @ W @ G)
    np.testing.assert_allclose(est.P_y_err, P_gls, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(Py, P_gls, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(est.K, P_gls @ G.T @ W, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(est.K @ G, np.eye(G.shape[1]), atol=1e-10)
    np.testing.assert_allclose(est.H @ G, 0.0, atol=1e-10)


def test_gain_is_brute_force_constrained_minimum():
    """Oracle: minimise E|Az + b - x|^2 subject to A G = 0 by a KKT linear system (row by row)."""
    F, G, mu_x, P_x, mu_n, P_n = _problem(1)
    est = lmmse_with_nuisance(F, G, mu_x, P_x, mu_n, P_n)
    np.testing.assert_allclose(est.H, _kkt_gain(F, G, P_x, P_n), rtol=1e-9, atol=1e-11)


def test_monte_carlo_errors():
    """Oracle: seeded Monte Carlo (200 000 draws) of the error means and covariances."""
    F, G, mu_x, P_x, mu_n, P_n = _problem(2)
    est = lmmse_with_nuisance(F, G, mu_x, P_x, mu_n, P_n)
    rng = np.random.default_rng(7)
    n = 200_000
    x = mu_x + rng.normal(size=(n, 2)) @ np.linalg.cholesky(P_x).T
    noise = mu_n + rng.normal(size=(n, 7)) @ np.linalg.cholesky(P_n).T
    y = np.array([3.0, -20.0, 1e3])  # nonrandom, arbitrary
    z = x @ F.T + y @ G.T + noise
    xh, yh = est.estimate(z)
    ex, ey = xh - x, yh - y
    assert np.all(np.abs(ex.mean(axis=0)) < 4 * np.sqrt(np.diag(est.P_x_err) / n))
    assert np.all(np.abs(ey.mean(axis=0)) < 4 * np.sqrt(np.diag(est.P_y_err) / n))
    np.testing.assert_allclose(np.cov(ex.T), est.P_x_err, rtol=0.02, atol=0.01 * np.abs(est.P_x_err).max())
    np.testing.assert_allclose(np.cov(ey.T), est.P_y_err, rtol=0.02, atol=0.01 * np.abs(est.P_y_err).max())


def test_scalar_corollary_gain_corrected_numerator():
    """Oracle: the brute-force (KKT) constrained gain for scalar x and white noise, which is
    gamma f'(I - P_G) with P_G the projector onto the columns of G; its error variance, from the
    model, is sigma^2 gamma (erratum E4-10: the printed numerator sigma^2 is off)."""
    rng = np.random.default_rng(5)
    G = rng.normal(size=(6, 3))
    f = rng.normal(size=6)
    sigma, sigma_x = 2.0, 3.0
    gamma = scalar_nuisance_gain(f, G, sigma, sigma_x)
    A = _kkt_gain(f[:, None], G, np.array([[sigma_x**2]]), sigma**2 * np.eye(6))[0]
    PG = G @ np.linalg.pinv(G)
    np.testing.assert_allclose(A, gamma * f @ (np.eye(6) - PG), rtol=1e-10)
    err_var = (A @ f - 1) ** 2 * sigma_x**2 + sigma**2 * A @ A
    assert sigma**2 * gamma == pytest.approx(err_var, rel=1e-10)
    est = lmmse_with_nuisance(f[:, None], G, [0.0], [[sigma_x**2]], np.zeros(6), sigma**2 * np.eye(6))
    np.testing.assert_allclose(est.H[0], A, rtol=1e-10)
    printed_gamma = sigma**2 / (sigma**2 + sigma_x**2 * f @ (np.eye(6) - PG) @ f)
    assert abs(printed_gamma - gamma) > 1e-3


def test_section4_clock_estimate_is_gls_position():
    """Oracle: with F = 1 and G = satellite matrix, y_hat equals (G'G)^-1 G'(z - x_hat) (Eq. H.27)."""
    rng = np.random.default_rng(9)
    U = rng.normal(size=(6, 3))
    U /= np.linalg.norm(U, axis=1, keepdims=True)
    est = lmmse_with_nuisance(np.ones((6, 1)), U, [0.0], [[400.0]], np.zeros(6), 2500.0 * np.eye(6))
    z = rng.normal(size=6) * 50
    xh, yh = est.estimate(z)
    np.testing.assert_allclose(yh, np.linalg.solve(U.T @ U, U.T @ (z - xh[0])), rtol=1e-9)


def test_bad_input_raises():
    F, G, mu_x, P_x, mu_n, P_n = _problem()
    with pytest.raises(ValueError, match="column rank"):
        lmmse_with_nuisance(F, np.hstack([G, G[:, :1]]), mu_x, P_x, mu_n, P_n)
    with pytest.raises(ValueError, match="positive definite"):
        lmmse_with_nuisance(F, G, mu_x, 0 * P_x, mu_n, 0 * P_n)
