"""Clock tracker of ATC-10 Sec. 4.5: psi, the gain recursion and its Monte Carlo."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from navcore.location.clock_tracking import (
    alpha_parameter,
    convergence_steps,
    convergence_steps_geometric,
    gain_recursion,
    position_mse,
    psi,
    psi_cubic_root,
    psi_large_alpha,
    psi_small_alpha,
    simulate_tracker,
    steady_state_gain,
    three_satellite_clock_variance,
    three_satellite_clock_variance_steady,
)


@pytest.mark.parametrize("alpha", np.logspace(-8, 3, 12))
def test_psi_is_real_root_of_cubic(alpha):
    """Oracle: numpy.roots of x^3 + q x - q (q = 27 alpha / 4), companion-matrix eigenvalues."""
    assert psi(alpha) == pytest.approx(psi_cubic_root(alpha), rel=1e-9)


def test_psi_known_values_and_real():
    """Oracle: scipy brentq on the cubic x^3 + q x - q = 0 (q = 27 alpha / 4, Eq. 4.5.25c)
    at the book's alpha = 1.61e-2 (instead of a value typed from the catalog), and a check
    that the result is real."""
    from scipy.optimize import brentq

    q = 27 * 1.61e-2 / 4
    assert psi(1.61e-2) == pytest.approx(brentq(lambda x: x**3 + q * x - q, 0.0, 1.0, xtol=1e-15), abs=1e-12)
    assert isinstance(psi(1e-3), float)
    # the principal complex cube root would give a complex number
    s = np.sqrt(1 + 1.61e-2)
    naive = 1.5 * (1.61e-2) ** (1 / 3) * ((1 + s) ** (1 / 3) + complex(1 - s) ** (1 / 3))
    assert abs(naive.imag) > 0.01


def test_cubic_derivation_sympy():
    """Oracle: sympy: the steady state of s = sigma^2 g/(1 - g b) + ... gives the cubic of Eq. 4.5.25c."""
    g, b, s2, q2 = sp.symbols("gamma beta sigma2 sigma02", positive=True)
    # steady state: g s2 / (1 - g b) = g s2 + 2 q2 / (g b)
    eq = sp.together(g * s2 / (1 - g * b) - g * s2 - 2 * q2 / (g * b))
    num = sp.factor(sp.numer(eq))
    cubic = g**3 + 2 * q2 / (s2 * b) * g - 2 * q2 / (s2 * b**2)
    assert sp.simplify(num / cubic).free_symbols <= {b, s2, q2}


def test_approximations_on_their_domains():
    """Oracle: the exact psi; the two approximations of Eq. 4.5.38 within 6 % on their stated ranges."""
    small = np.logspace(-8, np.log10(0.3), 40)
    large = np.logspace(0, 3, 40)
    assert np.max(np.abs(psi_small_alpha(small) / psi(small) - 1)) < 0.06
    assert np.max(np.abs(psi_large_alpha(large) / psi(large) - 1)) < 0.06


@pytest.mark.parametrize("beta", [0.0543, 0.00355])
@pytest.mark.parametrize("sigma0", [5.0, 50.0, 500.0])
def test_recursion_fixed_point(beta, sigma0):
    """Oracle: the closed-form fixed point psi(alpha)/beta (Eq. 4.5.33)."""
    h = gain_recursion(beta, 50.0, sigma0, 4000)
    assert h.gamma[-1] == pytest.approx(steady_state_gain(beta, 50.0, sigma0), rel=1e-8)
    # steady-state three-satellite formula = exact form with converged gamma_N, d_N
    m = np.arange(1, 20)
    np.testing.assert_allclose(
        three_satellite_clock_variance(h.gamma[-1], h.cross[-1], 50.0, sigma0, m),
        three_satellite_clock_variance_steady(beta, 50.0, sigma0, m),
        rtol=1e-8,
    )


def test_recursion_vs_brute_force_covariance():
    """Oracle: the tracking error as an explicit linear map of all noise, covariance by matrix products."""
    beta, sigma, sigma0, n = 0.05, 50.0, 20.0, 12
    h = gain_recursion(beta, sigma, sigma0, n)
    # error xi_n = a_n (xi_{n-1} - Delta_n) + gamma_n e_n, Var e_n = sigma^2 beta; noise vector
    # [Delta_1..Delta_n, e_0..e_n], xi_0 = e_0 / beta
    cov = np.zeros((2 * n + 1, 2 * n + 1))
    cov[:n, :n] = sigma0**2 * (np.ones((n, n)) + np.eye(n))
    cov[n:, n:] = sigma**2 * beta * np.eye(n + 1)
    row = np.zeros(2 * n + 1)
    row[n] = 1.0 / beta
    for k in range(1, n + 1):
        a = 1.0 - h.gamma[k] * beta
        row = a * row
        row[k - 1] -= a
        row[n + k] += h.gamma[k]
        assert row @ cov @ row == pytest.approx(sigma**2 * h.gamma[k], rel=1e-10)


def test_convergence_estimate_vs_geometric():
    """Oracle: brute-force count of the geometric series terms vs log formula."""
    for p in (0.05, 0.2, 0.5):
        n, s, t = 0, 1.0, 1.0
        while s < 0.9 / p:
            n, t = n + 1, t * (1 - p)
            s += t
        assert abs(convergence_steps_geometric(p, 0.1) - n) <= 1.0
    h = gain_recursion(0.0543, 50.0, 5.0, 3000)
    assert convergence_steps(h, 0.1) == 10


def test_tracker_monte_carlo_matches_recursion():
    """Oracle: seeded Monte Carlo (20 000 runs) of the full tracker against the recursion."""
    rng = np.random.default_rng(0)
    U = rng.normal(size=(6, 3)) + np.array([0.0, 0.0, 3.0])
    U /= np.linalg.norm(U, axis=1, keepdims=True)
    sigma, sigma0, N = 50.0, 10.0, 40
    mc = simulate_tracker(U, U[:3], sigma, sigma0, N, 10, 20_000, seed=11, tau_bar=1.0e9)
    ones = np.ones(6)
    beta = float(ones @ ones - ones @ U @ np.linalg.solve(U.T @ U, U.T @ ones))
    h = gain_recursion(beta, sigma, sigma0, N)
    tr = np.trace(np.linalg.inv(U.T @ U))
    S = float(np.sum(np.linalg.solve(U.T @ U, U.T @ ones) ** 2))
    np.testing.assert_allclose(mc.clock_mse[: N + 1], sigma**2 * h.gamma, rtol=0.05)
    np.testing.assert_allclose(mc.position_mse[: N + 1], position_mse(sigma, tr, S, h.gamma), rtol=0.05)
    m = np.arange(1, 11)
    v3 = three_satellite_clock_variance(h.gamma[-1], h.cross[-1], sigma, sigma0, m)
    F3 = U[:3]
    S3 = float(np.ones(3) @ np.linalg.solve(F3 @ F3.T, np.ones(3)))
    tr3 = np.trace(np.linalg.inv(F3.T @ F3))
    np.testing.assert_allclose(mc.clock_mse[N + 1 :], v3, rtol=0.05)
    np.testing.assert_allclose(mc.position_mse[N + 1 :], sigma**2 * tr3 + v3 * S3, rtol=0.05)


def test_alpha_and_bad_input():
    assert alpha_parameter(5.0, 50.0, 0.0543) == pytest.approx(1.609e-4, rel=1e-3)
    with pytest.raises(ValueError, match="alpha"):
        psi(-1.0)
    with pytest.raises(ValueError, match="beta"):
        gain_recursion(0.0, 50.0, 5.0, 3)
