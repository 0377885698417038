"""Clock tracker of ATC-10 Sec. 4.5: psi, the gain recursion and its Monte Carlo."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from navcore.location.clock_tracking import (
    GainHistory,
    alpha_parameter,
    clock_error_variances,
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
    tracking_position_errors,
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


@pytest.mark.parametrize("gains", ["optimal", "fixed", "random"])
def test_clock_error_variances_vs_brute_force_covariance(gains):
    """Oracle: the tracking error as an explicit linear map of all noise (as above), for the
    optimal gains, a fixed gain and random gains; with the optimal gains it is sigma^2 gamma_n."""
    beta, sigma, sigma0, n = 0.05, 50.0, 20.0, 12
    h = gain_recursion(beta, sigma, sigma0, n)
    g = {
        "optimal": h.gamma,
        "fixed": np.full(n + 1, h.gamma[-1]),
        "random": np.random.default_rng(3).uniform(0.0, 2.0 / beta, n + 1),
    }[gains]
    got = clock_error_variances(beta, sigma, sigma0, g)
    cov = np.zeros((2 * n + 1, 2 * n + 1))
    cov[:n, :n] = sigma0**2 * (np.ones((n, n)) + np.eye(n))
    cov[n:, n:] = sigma**2 * beta * np.eye(n + 1)
    row = np.zeros(2 * n + 1)
    row[n] = 1.0 / beta
    assert got[0] == pytest.approx(sigma**2 / beta, rel=1e-12)
    for k in range(1, n + 1):
        a = 1.0 - g[k] * beta
        row = a * row
        row[k - 1] -= a
        row[n + k] += g[k]
        assert got[k] == pytest.approx(row @ cov @ row, rel=1e-10)
    if gains == "optimal":
        np.testing.assert_allclose(got, sigma**2 * h.gamma, rtol=1e-10)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        ((0.0, 50.0, 5.0, [1.0]), "beta"),
        ((0.5, -1.0, 5.0, [1.0]), "sigma"),
        ((0.5, 50.0, -5.0, [1.0]), "sigma0"),
        ((0.5, 50.0, 5.0, []), "gains"),
        ((0.5, 50.0, 5.0, [[1.0]]), "gains"),
        ((0.5, 50.0, 5.0, [1.0, np.nan]), "gains"),
    ],
)
def test_clock_error_variances_rejects_bad_arguments(args, name):
    with pytest.raises(ValueError, match=name):
        clock_error_variances(*args)


def test_convergence_estimate_vs_geometric():
    """Oracles: brute-force count of the geometric series terms vs the log formula; and the
    definition of convergence_steps (the first n from which every later gain lies within rel
    of the last one) evaluated by a backward scan of the recursion's gains."""
    for p in (0.05, 0.2, 0.5):
        n, s, t = 0, 1.0, 1.0
        while s < 0.9 / p:
            n, t = n + 1, t * (1 - p)
            s += t
        assert abs(convergence_steps_geometric(p, 0.1) - n) <= 1.0
    for beta, sigma0, rel in ((0.0543, 5.0, 0.1), (0.2, 20.0, 0.01), (0.5, 0.5, 0.05)):
        h = gain_recursion(beta, 50.0, sigma0, 3000)
        g_inf, first = h.gamma[-1], h.gamma.size
        while first > 0 and abs(h.gamma[first - 1] - g_inf) <= rel * g_inf:
            first -= 1
        assert convergence_steps(h, rel) == first
    flat = GainHistory(np.full(4, 0.3), np.ones(4), np.zeros(4))
    assert convergence_steps(flat, 0.1) == 0
    step = GainHistory(np.array([1.0, 0.52, 0.48, 0.5]), np.ones(4), np.zeros(4))
    assert convergence_steps(step, 0.05) == 1
    assert convergence_steps(step, 0.03) == 3  # |0.48 - 0.5| > 0.015


def test_small_and_large_alpha_approximations_are_the_series_of_the_cubic():
    """Oracle: the real root of x^3 + q x - q = 0 (q = 27 alpha / 4) by numpy.roots. For small
    q the root is t - t^2/3 + O(t^4) with t = q^(1/3), so Eq. 4.5.38's small-alpha form errs by
    about t^4/81 (relative q/81); for large q it is 1 - 1/q + O(1/q^2), so the large-alpha form
    errs by about 3/q^2. Any other coefficient leaves an error orders of magnitude larger."""
    for a in (1e-9, 1e-7, 1e-5):
        q = 27 * a / 4
        assert psi_small_alpha(a) == pytest.approx(psi_cubic_root(a), rel=q / 20)
    for a in (1e3, 1e4):
        q = 27 * a / 4
        assert psi_large_alpha(a) == pytest.approx(psi_cubic_root(a), abs=6 / q**2)
    np.testing.assert_allclose(
        psi_small_alpha(np.array([1e-9, 1e-7])), [psi_cubic_root(1e-9), psi_cubic_root(1e-7)]
    )


def _lines_of_sight(seed, n, lift):
    """n random unit lines of sight, biased towards the zenith by ``lift`` (seeded)."""
    U = np.random.default_rng(seed).normal(size=(n, 3)) + np.array([0.0, 0.0, lift])
    return U / np.linalg.norm(U, axis=1, keepdims=True)


def _clock_split(U):
    """Oracle side of the clock/position split, by numpy least squares: g = (F'F)^-1 F' 1 and
    beta = 1'1 - 1'F g, the part of the clock column that the geometry cannot absorb."""
    ones = np.ones(len(U))
    g = np.linalg.solve(U.T @ U, U.T @ ones)
    return g, float(ones @ ones - ones @ U @ g)


def test_tracker_position_error_norm_variance():
    """Oracle: independent Gaussian sampling (seed 2, 10^6 draws) of the position error with
    covariance sigma^2 [(F'F)^-1 + gamma_n g g'], g = (F'F)^-1 F' 1 (the clock error enters
    the position through g and is uncorrelated with the projected noise), for Var|xi_p| at the
    first epoch, in steady state and after the drop to three satellites (sigma^2 (F3)^-1
    (F3)^-T + v_m h h', h = F3^-1 1). 20 000 tracker runs: standard error about 1 %."""
    U = _lines_of_sight(0, 6, 3.0)
    sigma, sigma0, N = 50.0, 10.0, 30
    mc = simulate_tracker(U, U[:3], sigma, sigma0, N, 4, 20_000, seed=7, tau_bar=3.0)
    g, beta = _clock_split(U)
    h = gain_recursion(beta, sigma, sigma0, N)
    F3inv = np.linalg.inv(U[:3])
    hv = F3inv @ np.ones(3)
    v3 = three_satellite_clock_variance(h.gamma[-1], h.cross[-1], sigma, sigma0, np.arange(1, 5))
    draws = np.random.default_rng(2).standard_normal((1_000_000, 3))
    cases = [(0, sigma**2 * (np.linalg.inv(U.T @ U) + h.gamma[0] * np.outer(g, g)))]
    cases.append((N, sigma**2 * (np.linalg.inv(U.T @ U) + h.gamma[N] * np.outer(g, g))))
    cases.append((N + 2, sigma**2 * F3inv @ F3inv.T + v3[1] * np.outer(hv, hv)))
    for n, P in cases:
        norms = np.linalg.norm(draws @ np.linalg.cholesky(P).T, axis=1)
        assert mc.position_norm_variance[n] == pytest.approx(np.var(norms), rel=0.05), n
        assert mc.position_mse[n] == pytest.approx(np.trace(P), rel=0.05), n
    assert mc.n_runs == 20_000 and mc.clock_mse.shape == (N + 5,)


def test_tracker_monte_carlo_matches_recursion():
    """Oracle: seeded Monte Carlo (20 000 runs) of the full tracker against the recursion."""
    U = _lines_of_sight(0, 6, 3.0)
    sigma, sigma0, N = 50.0, 10.0, 40
    mc = simulate_tracker(U, U[:3], sigma, sigma0, N, 10, 20_000, seed=11, tau_bar=1.0e9)
    g, beta = _clock_split(U)
    h = gain_recursion(beta, sigma, sigma0, N)
    tr = np.trace(np.linalg.inv(U.T @ U))
    S = float(g @ g)
    np.testing.assert_allclose(mc.clock_mse[: N + 1], sigma**2 * h.gamma, rtol=0.05)
    np.testing.assert_allclose(mc.position_mse[: N + 1], position_mse(sigma, tr, S, h.gamma), rtol=0.05)
    m = np.arange(1, 11)
    v3 = three_satellite_clock_variance(h.gamma[-1], h.cross[-1], sigma, sigma0, m)
    F3 = U[:3]
    S3 = float(np.ones(3) @ np.linalg.solve(F3 @ F3.T, np.ones(3)))
    tr3 = np.trace(np.linalg.inv(F3.T @ F3))
    np.testing.assert_allclose(mc.clock_mse[N + 1 :], v3, rtol=0.05)
    np.testing.assert_allclose(mc.position_mse[N + 1 :], sigma**2 * tr3 + v3 * S3, rtol=0.05)


def test_alpha_is_the_cubic_coefficient_of_the_steady_state():
    """Oracle: sympy's steady-state cubic (test_cubic_derivation_sympy) in x = gamma beta:
    x^3 + (2 sigma0^2 beta / sigma^2)(x - 1) = 0, solved with numpy.roots; psi of the model's
    alpha is its real root in (0, 1), and alpha scales as sigma0^2 beta / sigma^2."""
    for sigma0, sigma, beta in ((5.0, 50.0, 0.0543), (30.0, 20.0, 0.4), (1.0, 3.0, 2.5)):
        k = 2 * sigma0**2 * beta / sigma**2
        r = np.roots([1.0, 0.0, k, -k])
        root = float(r[np.abs(r.imag) < 1e-9].real[0])
        assert psi(alpha_parameter(sigma0, sigma, beta)) == pytest.approx(root, rel=1e-10)
        assert steady_state_gain(beta, sigma, sigma0) == pytest.approx(root / beta, rel=1e-10)
    assert alpha_parameter(10.0, 50.0, 0.0543) == pytest.approx(4 * alpha_parameter(5.0, 50.0, 0.0543))


def test_bad_input():
    with pytest.raises(ValueError, match="alpha"):
        psi(-1.0)
    with pytest.raises(ValueError, match="beta"):
        gain_recursion(0.0, 50.0, 5.0, 3)


def test_table_row_errors_against_the_tracker_monte_carlo():
    """Oracle: the seeded Monte Carlo of the whole tracker (simulated clocks and arrival-time
    noise, 20 000 runs, standard error about 1 %): the least-squares error at epoch 0, the
    steady-state tracking error (epoch 80, the gain changing by < 1e-6 per step) and the first
    three-satellite error (epoch 81), each times c = 2 length units per time unit; the
    geometry terms (traces, S, beta) are computed here from F with numpy. The alpha and psi
    of the row are the cubic's coefficient and root (numpy.roots), and passing that psi
    explicitly changes nothing."""
    U = _lines_of_sight(4, 5, 2.5)
    F3 = U[[0, 2, 4]]
    sigma, sigma0, N = 40.0, 6.0, 80
    g, beta = _clock_split(U)
    tr, S = float(np.trace(np.linalg.inv(U.T @ U))), float(g @ g)
    tr3 = float(np.trace(np.linalg.inv(F3.T @ F3)))
    S3 = float(np.ones(3) @ np.linalg.solve(F3 @ F3.T, np.ones(3)))
    h = gain_recursion(beta, sigma, sigma0, N)
    assert abs(h.gamma[-1] / h.gamma[-2] - 1) < 1e-6  # converged well within the 1 % statistics
    row = tracking_position_errors(tr, S, tr3, S3, beta, sigma0, sigma, c=2.0)
    mc = simulate_tracker(U, F3, sigma, sigma0, N, 1, 20_000, seed=5, tau_bar=2.0)
    assert row.sd_least_squares**2 == pytest.approx(4 * mc.position_mse[0], rel=0.04)
    assert row.sd_tracking_limit**2 == pytest.approx(4 * mc.position_mse[N], rel=0.04)
    assert row.sd_first_three_satellite**2 == pytest.approx(4 * mc.position_mse[N + 1], rel=0.04)
    k = 2 * sigma0**2 * beta / sigma**2
    r = np.roots([1.0, 0.0, k, -k])
    root = float(r[np.abs(r.imag) < 1e-9].real[0])
    assert row.psi == pytest.approx(root, rel=1e-10)
    assert 27 * row.alpha / 4 == pytest.approx(k, rel=1e-12)
    assert tracking_position_errors(
        tr, S, tr3, S3, beta, sigma0, sigma, c=2.0, psi_value=root
    ) == pytest.approx(row, rel=1e-9)


def test_tracker_monte_carlo_with_small_noises_is_unbiased_and_reproducible():
    """Oracle: the recursion's variances (itself checked against the explicit linear map
    above) for a tracker whose arrival-time noise (0.4) and clock increments (0.3) are small,
    so that any bias of the simulated noises or of the clock's frequency offset (of order one
    time unit) would dominate the mean square errors; 20 000 runs, 5 %. The same seed gives
    the same result."""
    U = _lines_of_sight(3, 5, 2.5)
    sigma, sigma0, N = 0.4, 0.3, 12
    mc = simulate_tracker(U, U[:3], sigma, sigma0, N, 3, 20_000, seed=2, tau_bar=1.0)
    g, beta = _clock_split(U)
    h = gain_recursion(beta, sigma, sigma0, N)
    np.testing.assert_allclose(mc.clock_mse[: N + 1], sigma**2 * h.gamma, rtol=0.05)
    tr, S = float(np.trace(np.linalg.inv(U.T @ U))), float(g @ g)
    np.testing.assert_allclose(mc.position_mse[: N + 1], sigma**2 * (tr + h.gamma * S), rtol=0.05)
    v3 = three_satellite_clock_variance(h.gamma[-1], h.cross[-1], sigma, sigma0, np.arange(1, 4))
    np.testing.assert_allclose(mc.clock_mse[N + 1 :], v3, rtol=0.05)
    F3inv = np.linalg.inv(U[:3])
    hv = F3inv @ np.ones(3)
    np.testing.assert_allclose(
        mc.position_mse[N + 1 :], sigma**2 * np.trace(F3inv @ F3inv.T) + v3 * (hv @ hv), rtol=0.05
    )
    again = simulate_tracker(U, U[:3], sigma, sigma0, N, 3, 200, seed=2, tau_bar=1.0)
    np.testing.assert_array_equal(
        again.clock_mse, simulate_tracker(U, U[:3], sigma, sigma0, N, 3, 200, seed=2, tau_bar=1.0).clock_mse
    )


def test_convergence_boundaries():
    """Oracles by hand with exactly representable numbers: a gain exactly rel away from the
    limit counts as converged ("within"); the geometric estimate needs psi and rel in (0, 1)."""
    h = GainHistory(np.array([1.0, 0.625, 0.5]), np.ones(3), np.zeros(3))
    assert convergence_steps(h, 0.25) == 1  # |0.625 - 0.5| = 0.125 = 0.25 * 0.5 exactly
    for bad in (1.0, 1.5):
        with pytest.raises(ValueError, match="psi_value"):
            convergence_steps_geometric(bad, 0.1)
        with pytest.raises(ValueError, match="rel"):
            convergence_steps_geometric(0.3, bad)
    assert convergence_steps_geometric(0.999, 0.999) == pytest.approx(
        math.log(0.999) / math.log(0.001) - 1.0, rel=1e-12
    )
