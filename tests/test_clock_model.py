"""ATC-10 App. G clock model against quadrature, closed forms and seeded Monte Carlo."""

from __future__ import annotations

import numpy as np
import pytest

from navcore.location.clock_model import (
    clock_covariance,
    clock_increment_covariance,
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
    """Oracle: sample covariance of seeded paths; the generative form sum w_i + n A (Eq. 4.3.1)."""
    x = sample_clock_paths(20, 40_000, 1.0, 1.0, 1.0, seed=3)
    C = clock_covariance(20, 1.0, 1.0, 1.0)
    assert np.max(np.abs(np.cov(x.T) - C) / np.sqrt(np.outer(np.diag(C), np.diag(C)))) < 0.03
    rng = np.random.default_rng(1)
    w = rng.normal(size=(40_000, 20))
    A = rng.normal(size=(40_000, 1))
    y = np.cumsum(w, axis=1) + np.arange(1, 21) * A
    assert np.max(np.abs(np.cov(y.T) - C) / np.sqrt(np.outer(np.diag(C), np.diag(C)))) < 0.03


def test_fbm_variance_scaling():
    """Oracle: Var = s1^2 n + s2^2 n^(2 rho) on the diagonal."""
    C = clock_covariance(50, 1.0, 0.5, 0.8)
    n = np.arange(1, 51)
    np.testing.assert_allclose(np.diag(C), n + 0.25 * n**1.6, rtol=1e-12)


def test_bad_input_raises():
    with pytest.raises(ValueError, match="rho_h"):
        mandelbrot_van_ness_constant(1.0)
    with pytest.raises(ValueError, match="sigma1"):
        clock_covariance(3, -1.0, 1.0)
