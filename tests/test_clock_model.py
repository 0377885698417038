"""ATC-10 App. G clock model against quadrature, closed forms and seeded Monte Carlo."""

from __future__ import annotations

import math

import numpy as np
import pytest

from navcore.location.clock_model import (
    clock_covariance,
    clock_increment_covariance,
    clock_state_tau_map,
    mandelbrot_van_ness_constant,
    mandelbrot_van_ness_constant_integral,
    sample_clock_paths,
)


@pytest.mark.parametrize("rho", [0.55, 0.75, 0.9, 0.95])
def test_v0_closed_form_vs_quadrature(rho):
    """Oracle: scipy quad of the defining integral (corrected integrand, erratum E4-7)."""
    assert mandelbrot_van_ness_constant(rho) == pytest.approx(
        mandelbrot_van_ness_constant_integral(rho), rel=1e-7
    )


def test_v0_known_values():
    """Oracles: V0(1/2) = 1 (Brownian motion); for rho != 1/2 the variance constant of the
    Mandelbrot-Van Ness fractional Brownian motion in the form Gamma(2 - 2 rho) cos(pi rho) /
    (pi rho (1 - 2 rho)) (Y. Mishura, *Stochastic Calculus for Fractional Brownian Motion*,
    2008, Sec. 1.1), not a value typed from the catalog."""
    from scipy.special import gamma

    assert mandelbrot_van_ness_constant(0.5) == pytest.approx(1.0, abs=1e-12)
    for rho in (0.1, 0.3, 0.7, 0.9):
        mishura = gamma(2 - 2 * rho) * np.cos(np.pi * rho) / (np.pi * rho * (1 - 2 * rho))
        assert mandelbrot_van_ness_constant(rho) == pytest.approx(mishura, rel=1e-12)


def test_rho_one_reduces_to_eq_4_3_1():
    """Oracle: closed form sigma0^2 (min(m, n) + m n) of Eq. 4.3.1."""
    C = clock_covariance(6, 2.0, 2.0, 1.0)
    n = np.arange(1, 7)
    np.testing.assert_allclose(C, 4.0 * (np.minimum.outer(n, n) + np.outer(n, n)), rtol=1e-12)


def test_increment_covariance_from_path_covariance():
    """Oracle: differencing the path covariance (D C D') gives 2 sigma0^2 / sigma0^2 (Eq. 4.5.23)."""
    C = clock_covariance(8, 3.0, 3.0, 1.0)
    D = np.eye(8) - np.eye(8, k=-1)
    np.testing.assert_allclose(D @ C @ D.T, clock_increment_covariance(8, 3.0), atol=1e-10)


def test_sample_paths_monte_carlo_and_generative_form():
    """Oracle: the generative form of Eq. 4.3.1, sum of w_i plus n A with w_i, A ~ N(0, 1)
    simulated directly (seed 1); the model's seeded paths (rho_h = 1) have the same sample
    covariance within sampling error (40 000 paths: ~1 % per entry; 3 % allowed)."""
    x = sample_clock_paths(20, 40_000, 1.0, 1.0, 1.0, seed=3)
    rng = np.random.default_rng(1)
    w = rng.normal(size=(40_000, 20))
    A = rng.normal(size=(40_000, 1))
    y = np.cumsum(w, axis=1) + np.arange(1, 21) * A
    cy = np.cov(y.T)
    assert np.max(np.abs(np.cov(x.T) - cy) / np.sqrt(np.outer(np.diag(cy), np.diag(cy)))) < 0.03
    assert np.max(np.abs(x.mean(axis=0)) / np.sqrt(np.diag(cy))) < 0.03


def _increment_variance_from_cov(C: np.ndarray, lag: int) -> np.ndarray:
    """Var(x_{n+lag} - x_n), n = 0..N-lag, from the covariance of x_1..x_N (x_0 = 0)."""
    C0 = np.pad(C, ((1, 0), (1, 0)))
    d = np.diag(C0)
    k = np.arange(C0.shape[0] - lag)
    return d[k + lag] + d[k] - 2 * C0[k + lag, k]


def _increment_variance_from_paths(x: np.ndarray, lag: int) -> np.ndarray:
    """Sample Var(x_{n+lag} - x_n), n = 0..N-lag, over paths x_1..x_N (x_0 = 0)."""
    x0 = np.column_stack([np.zeros(x.shape[0]), x])
    return np.var(x0[:, lag:] - x0[:, :-lag], axis=0)


@pytest.mark.parametrize(("s1", "s2", "rho"), [(0.6, 1.3, 0.8), (1.1, 0.4, 0.3), (0.0, 2.0, 0.65)])
def test_covariance_has_stationary_self_similar_increments(s1, s2, rho):
    """Oracle: the defining properties of the two components, not the covariance formula.
    A Wiener process and an independent fractional Brownian motion of Hurst index rho, both
    zero at n = 0, have stationary increments with Var(x_{n+k} - x_n) = s1^2 k + s2^2 k^(2 rho)
    for every n (Mandelbrot & Van Ness 1968). Checked on the covariance (exactly) for lags
    1-7 from every epoch, and the raw second moment adds the mean product tau_bar^2 n m."""
    C = clock_covariance(12, s1, s2, rho)
    for lag in range(1, 8):
        np.testing.assert_allclose(
            _increment_variance_from_cov(C, lag), s1**2 * lag + s2**2 * lag ** (2 * rho), rtol=1e-12
        )
    n = np.arange(1, 13)
    np.testing.assert_allclose(
        clock_covariance(12, s1, s2, rho, tau_bar=0.7) - C, 0.49 * np.outer(n, n), rtol=1e-12
    )


@pytest.mark.parametrize(("s1", "s2", "rho"), [(0.6, 1.3, 0.8), (1.1, 0.4, 0.3)])
def test_sample_paths_have_the_stated_increment_statistics(s1, s2, rho):
    """Oracle: the same defining property, Var(x_{n+k} - x_n) = s1^2 k + s2^2 k^(2 rho), measured
    on 40 000 seeded paths (relative standard error of a variance 0.7 %; 4 % allowed), and zero
    mean. The default seed is 0 (a call without one equals seed=0)."""
    x = sample_clock_paths(15, 40_000, s1, s2, rho, seed=5)
    assert x.shape == (40_000, 15)
    for lag in (1, 3, 8):
        expected = s1**2 * lag + s2**2 * lag ** (2 * rho)
        np.testing.assert_allclose(_increment_variance_from_paths(x, lag), expected, rtol=0.04)
    assert np.max(np.abs(x.mean(axis=0)) / x.std(axis=0)) < 0.03
    np.testing.assert_array_equal(
        sample_clock_paths(4, 3, s1, s2, rho), sample_clock_paths(4, 3, s1, s2, rho, seed=0)
    )


def test_bad_input_raises():
    with pytest.raises(ValueError, match="rho_h"):
        mandelbrot_van_ness_constant(1.0)
    with pytest.raises(ValueError, match="sigma1"):
        clock_covariance(3, -1.0, 1.0)


def test_sample_paths_pure_frequency_offset_and_default_exponent():
    """Oracle: Eq. 4.3.1 with no random walk (sigma1 = 0, rho_h = 1): x_n = n A, so every path
    is a straight line through the origin (x_n / n the same for all n) with Var A = sigma2^2;
    the rank-one covariance must still be sampled. The default exponent is rho_h = 1."""
    x = sample_clock_paths(8, 20_000, 0.0, 1.5, 1.0, seed=4)
    slopes = x / np.arange(1, 9)
    np.testing.assert_allclose(slopes, slopes[:, :1] * np.ones((1, 8)), rtol=0, atol=1e-4)
    assert np.var(slopes[:, 0]) == pytest.approx(1.5**2, rel=0.04)
    np.testing.assert_array_equal(
        sample_clock_paths(5, 4, 0.7, 0.4, seed=9), sample_clock_paths(5, 4, 0.7, 0.4, 1.0, seed=9)
    )
    assert sample_clock_paths(5, 1, 0.7, 0.4, seed=9).shape == (1, 5)  # a single path is valid


@pytest.mark.parametrize(("n_observed", "ahead"), [(1, 1), (5, 3), (20, 10)])
def test_clock_prediction_variance_is_the_kalman_prediction_of_a_random_walk(n_observed, ahead):
    """Oracle: for a random walk (sigma2 = 0) the best linear predictor is the scalar Kalman
    filter: filter the n_observed observations, then add one step variance per epoch ahead."""
    from navcore.location.clock_model import clock_prediction_variance

    q, r = 2.0, 3.0
    p = 0.0  # tau_0 = 0 is known
    for _ in range(n_observed):
        p += q
        p = p * r / (p + r)
    want = p + ahead * q
    C = clock_covariance(n_observed + ahead, math.sqrt(q), 0.0)
    assert clock_prediction_variance(C, r, n_observed) == pytest.approx(want, rel=1e-12)


def test_clock_prediction_variance_rejects_bad_arguments():
    from navcore.location.clock_model import clock_prediction_variance

    C = clock_covariance(4, 1.0, 1.0, 0.8)
    for args, name in (
        ((C, 0.0, 2), "noise_variance"),
        ((C, 1.0, 4), "n_observed"),
        ((C, 1.0, 0), "n_observed"),
        ((-C, 1.0, 2), "covariance"),
        ((C[:3], 1.0, 2), "covariance"),
    ):
        with pytest.raises(ValueError, match=name):
            clock_prediction_variance(*args)


def test_clock_state_tau_map_is_the_unrolled_recursion():
    """Oracle: the state model (4.5.9) unrolled by hand, tau_n = n alpha_0 + w_1 + ... + w_n
    (tau_1 = alpha_0 + w_1, alpha_1 = -w_1, tau_2 = 2 alpha_0 + w_1 + w_2, ...), and a seeded
    simulation of the scalar recursion tau_n = 2 tau_{n-1} + alpha_{n-1} + w_n,
    alpha_n = -tau_{n-1} - w_n; its covariance is (4.3.1b), min(m, n) + m n."""
    n_max = 12
    coef = clock_state_tau_map(n_max)
    want = np.zeros((n_max + 1, n_max + 1))
    for n in range(1, n_max + 1):
        want[n, 0] = n
        want[n, 1 : n + 1] = 1.0
    np.testing.assert_array_equal(coef, want)
    rng = np.random.default_rng(459)
    draws = rng.normal(size=n_max + 1)  # (alpha_0, w_1, ..., w_n_max)
    tau, alpha, path = 0.0, draws[0], [0.0]
    for n in range(1, n_max + 1):
        tau, alpha = 2 * tau + alpha + draws[n], -tau - draws[n]
        path.append(tau)
    np.testing.assert_allclose(coef @ draws, path, rtol=1e-12, atol=1e-12)
    m, k = np.meshgrid(np.arange(n_max + 1), np.arange(n_max + 1), indexing="ij")
    np.testing.assert_allclose(coef @ coef.T, np.minimum(m, k) + m * k, rtol=1e-12)


@pytest.mark.parametrize(
    ("bad", "error"),
    [(-1, ValueError), (2.5, TypeError), (True, TypeError), (3001, ValueError), (10**9, ValueError)],
)
def test_clock_state_tau_map_rejects_bad_n_max(bad, error):
    """Oracle: the documented boundary (a non-negative integer), named as the caller spelled it."""
    with pytest.raises(error, match="n_max"):
        clock_state_tau_map(bad)
