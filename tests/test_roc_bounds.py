"""Tests of navcore.detection.roc_bounds against exact tails, Monte Carlo and closed forms."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import optimize, special

from navcore.detection.multiple_access import (
    GaussianDensity,
    MultipleAccessNoise,
    PointMassDensity,
    TriangularDensity,
    UniformDensity,
    gaussian_mixture_exact_tail,
    stratified_tail,
    two_point_density,
    two_point_exact_tail,
)
from navcore.detection.roc_bounds import (
    NegatedCGF,
    chernoff_log_tail,
    exponent_from_gaussian_exponent,
    exponent_from_gaussian_exponent_large_n,
    gallager_log_tail_lower,
    gaussian_chernoff_exponent,
    gaussian_roc,
    quasi_optimal_chernoff_parameter,
    quasi_optimal_exponent,
    quasi_optimal_exponent_approx,
    roc_lower_bound,
    roc_upper_bound,
)

N, TA = 100_000, 2e-5


def _noise(dens):
    return MultipleAccessNoise(N, TA, dens)


def test_chernoff_optimum_matches_bounded_scalar_minimisation():
    """Oracle: scipy.optimize.minimize_scalar of mu(r) - r t on a bracket."""
    noise = _noise(UniformDensity(1 / 75))
    for t in (0.2, 0.5, 0.8):
        res = optimize.minimize_scalar(
            lambda r, t=t: float(noise.cgf(r)) - r * t,
            bounds=(0, 200),
            method="bounded",
            options={"xatol": 1e-10},
        )
        b = chernoff_log_tail(noise, t)
        assert b.log_p == pytest.approx(res.fun, abs=1e-8)
    assert chernoff_log_tail(noise, -0.1).log_p == 0.0


def test_chernoff_infinite_when_support_cannot_reach():
    """Oracle: a bounded sum cannot exceed (N-1) max|x|."""
    small = MultipleAccessNoise(3, 0.25, PointMassDensity((-1.0, 1.0), (0.5, 0.5)))
    assert chernoff_log_tail(small, 2.5).log_p == -np.inf


@pytest.mark.parametrize("x", [3, 5, 6])
@pytest.mark.parametrize("kind", ["two-point", "uniform", "triangular", "Gaussian"])
def test_bounds_bracket_monte_carlo_exact_rates(x, kind):
    """Oracle: seeded stratified Monte Carlo (and exact sums for the two-point and Gaussian C).

    The Chernoff upper bound must never be below the simulated rate beyond 4 standard errors,
    and the corrected Gallager lower bound never above it.
    """
    b = 1 / (3 * x**2)
    dens = {
        "two-point": two_point_density(b),
        "uniform": UniformDensity(b),
        "triangular": TriangularDensity(b),
        "Gaussian": GaussianDensity(b),
    }[kind]
    noise = _noise(dens)
    th = np.array([0.3, 0.5, 0.7])
    est = stratified_tail(noise, th, 4000, np.random.default_rng(x))
    ub_f, ub_m = roc_upper_bound(noise, th)
    lb_f, lb_m = roc_lower_bound(noise, th)
    assert np.all(est.upper <= np.exp(ub_f) + 4 * est.upper_se)
    assert np.all(np.exp(lb_f) <= est.upper + 4 * est.upper_se)
    mest = stratified_tail(noise, 1 - th, 4000, np.random.default_rng(x + 100))
    miss, se = mest.lower, mest.lower_se
    assert np.all(miss <= np.exp(ub_m) + 4 * se)
    assert np.all(np.exp(lb_m) <= miss + 4 * se)
    if kind == "two-point":
        exact = two_point_exact_tail(np.sqrt(b), N - 1, 2 * TA, th)
    elif kind == "Gaussian":
        exact = gaussian_mixture_exact_tail(b, N - 1, 2 * TA, th)
    else:
        return
    assert np.all(np.exp(lb_f) <= exact) and np.all(exact <= np.exp(ub_f))


def test_gallager_bound_on_gaussian_against_exact_q_function():
    """Oracle: Q(t/sigma) for a Gaussian sum (many interferers, each Gaussian): lb <= Q <= ub."""
    noise = MultipleAccessNoise(2_000_000, 0.25, GaussianDensity(1e-6))
    var = noise.power
    for t in (0.5, 1.0, 1.5):
        exact = special.log_ndtr(-t / np.sqrt(var))
        assert gallager_log_tail_lower(noise, t).log_p <= exact <= chernoff_log_tail(noise, t).log_p


def test_negated_cgf_is_mirror_for_symmetric_density():
    """Oracle: symmetry of C implies mu(-s) = mu(s)."""
    noise = _noise(TriangularDensity(0.01))
    neg = NegatedCGF(noise)
    s = np.array([0.3, 3.0])
    np.testing.assert_allclose(neg.cgf(s), noise.cgf(s))
    np.testing.assert_allclose(neg.cgf_d1(s), -noise.cgf_d1(-s))


@pytest.mark.parametrize(("x", "theta"), [(3, 0.3), (3, 0.5), (3, 0.7), (5, 0.5), (5, 0.7)])
def test_quasi_optimal_closed_form_matches_numerical_chernoff(x, theta):
    """Oracle: the numerical Chernoff optimum for the two-point density (Eqs. 3.7.23-3.7.24)."""
    b = 1 / (3 * x**2)
    noise = _noise(two_point_density(b))
    p = noise.power
    num = chernoff_log_tail(noise, theta)
    assert quasi_optimal_chernoff_parameter(theta, p, N, TA) == pytest.approx(num.parameter, rel=1e-7)
    assert quasi_optimal_exponent(theta, p, N, TA) == pytest.approx(-num.log_p, rel=1e-9)
    assert quasi_optimal_exponent_approx(theta, p, N, TA) == pytest.approx(-num.log_p, rel=1e-5)


def test_gaussian_roc_and_its_chernoff_bound():
    """Oracle: scipy.special.erfc (Eq. 3.8.1) and Q(x) <= exp(-x^2/2)."""
    p = 4 / 75
    lpf, lmiss = gaussian_roc(np.array([0.5]), p)
    assert np.exp(lpf[0]) == pytest.approx(0.5 * special.erfc(0.5 / np.sqrt(2 * p)), rel=1e-12)
    assert np.exp(lpf[0]) == pytest.approx(1.519e-2, rel=2e-3)
    th = np.linspace(0.05, 0.95, 19)
    lpf, lmiss = gaussian_roc(th, p)
    assert np.all(lpf <= -gaussian_chernoff_exponent(th, p))
    assert np.all(lmiss <= -gaussian_chernoff_exponent(1 - th, p))


def test_exponent_from_gaussian_matches_closed_form_and_limits():
    """Oracles: the exact quasi-optimal exponent (3.7.24) and the large-N series."""
    # Eliminate theta: Exp_g = theta^2 / (2p) with the paper's N (not N-1) in the power.
    n, ta, g = 200_000, 1e-5, 12.5
    p = 0.02
    theta = np.sqrt(2 * p * g)
    exact = quasi_optimal_exponent(theta, p * (n - 1) / n, n, ta)
    assert exponent_from_gaussian_exponent(n, ta, g) == pytest.approx(exact, rel=1e-3)
    assert exponent_from_gaussian_exponent(2e5, 1e-5, 12.5) == pytest.approx(9.7021, abs=1e-3)
    assert exponent_from_gaussian_exponent(1e5, 1e-5, 4) == pytest.approx(3.3024, abs=1e-3)
    big = exponent_from_gaussian_exponent(1e8, 1e-5, 4.0)
    assert big == pytest.approx(exponent_from_gaussian_exponent_large_n(1e8, 1e-5, 4.0), abs=1e-5)
    grid_n = np.logspace(2, 9, 60)[:, None]
    grid_g = np.linspace(0.1, 30, 40)[None, :]
    e = exponent_from_gaussian_exponent(grid_n, 1e-5, grid_g)
    assert np.all(e <= grid_g + 1e-7)
    assert np.all(np.diff(e, axis=0) > 0)
