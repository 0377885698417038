"""Tests of navcore.detection.multiple_access against independent oracles."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy import integrate, stats

from navcore.detection.multiple_access import (
    GaussianDensity,
    LogMGFDensity,
    MultipleAccessNoise,
    TriangularDensity,
    UniformDensity,
    cumulants_from_raw_moments,
    edgeworth_tail,
    gaussian_mixture_exact_tail,
    psk_amplitude_samples,
    sample_noise,
    stratified_tail,
    tabulated_density,
    two_point_density,
    two_point_exact_tail,
)
from navcore.detection.zakai import aperiodic_autocorrelation, piecewise_linear_inner

B = 1.0 / 75.0
DENSITIES = [two_point_density(B), UniformDensity(B), TriangularDensity(B), GaussianDensity(B)]


@pytest.mark.parametrize("dens", DENSITIES, ids=lambda d: d.name)
def test_log_mgf_and_derivatives_match_quadrature(dens):
    """Oracle: numerical integration of e^{sx} C(x) (scipy.integrate.quad) or direct sums."""
    s = np.array([0.0, 0.7, 5.0, 23.0])
    if dens.name == "two-point":
        a = np.sqrt(B)
        m0 = np.cosh(s * a)
        m1 = a * np.sinh(s * a)
        m2 = a**2 * np.cosh(s * a)
    else:
        if dens.name == "uniform":
            h = np.sqrt(3 * B)
            pdf, lo, hi = (lambda x: 1 / (2 * h)), -h, h
        elif dens.name == "triangular":
            h = np.sqrt(6 * B)
            pdf, lo, hi = (lambda x: (h - abs(x)) / h**2), -h, h
        else:
            pdf, lo, hi = (lambda x: stats.norm.pdf(x, scale=np.sqrt(B))), -12 * np.sqrt(B), 12 * np.sqrt(B)
        m0, m1, m2 = (
            np.array(
                [
                    integrate.quad(
                        lambda x, si=si, k=k: x**k * np.exp(si * x) * pdf(x),
                        lo,
                        hi,
                        epsabs=1e-12,
                        epsrel=1e-10,
                        points=[0.0],
                        limit=200,
                    )[0]
                    for si in s
                ]
            )
            for k in (0, 1, 2)
        )
    np.testing.assert_allclose(dens.log_mgf(s), np.log(m0), rtol=1e-9, atol=1e-13)
    np.testing.assert_allclose(dens.dlog_mgf(s), m1 / m0, rtol=1e-8, atol=1e-14)
    np.testing.assert_allclose(dens.d2_ratio(s), m2 / m0, rtol=1e-8)
    assert dens.second_moment == pytest.approx(B, rel=1e-12)


def test_tabulated_and_logmgf_densities_agree_with_closed_form():
    """Oracle: the closed-form uniform density (Gauss-Legendre is exact for this smooth integrand)."""
    u = UniformDensity(B)
    h = u.half_width
    tab = tabulated_density(lambda x: np.full_like(x, 1 / (2 * h)), -h, h, n=60)
    lg = LogMGFDensity(u.log_mgf)
    s = np.array([0.5, 4.0, 12.0])
    np.testing.assert_allclose(tab.log_mgf(s), u.log_mgf(s), rtol=1e-10)
    np.testing.assert_allclose(lg.dlog_mgf(s), u.dlog_mgf(s), rtol=1e-6)
    np.testing.assert_allclose(lg.d2_ratio(s), u.d2_ratio(s), rtol=1e-5)


def test_power_formula_is_second_moment_of_bernoulli_gated_sum():
    """Oracle: sympy expansion of E(sum_j B_j X_j)^2 for independent Bernoulli(q) gates (Eq. 3.4.10)."""
    q, m1, m2, k = sp.symbols("q m1 m2 k", positive=True)
    var_one = q * m2 - (q * m1) ** 2
    second = sp.expand(k * var_one + (k * q * m1) ** 2)
    printed = sp.expand(k * q * m2 + (q * k * m1) ** 2 - q**2 * k * m1**2)
    assert sp.simplify(second - printed) == 0


def test_cumulants_against_monte_carlo_and_sympy():
    """Oracles: sympy series of ln(1-q+q cosh) and a seeded Monte Carlo (2e6 samples)."""
    s, q, a = sp.symbols("s q a", positive=True)
    series = sp.series(sp.log(1 - q + q * sp.cosh(a * s)), s, 0, 7).removeO()
    k4 = sp.simplify(series.coeff(s, 4) * sp.factorial(4))
    assert sp.simplify(k4 - (q * a**4 - 3 * q**2 * a**4)) == 0
    noise = MultipleAccessNoise(100_000, 2e-5, UniformDensity(B))
    kap = noise.cumulants(4)
    x = sample_noise(noise, 2_000_000, np.random.default_rng(11))
    assert x.var() == pytest.approx(kap[1], rel=0.01)
    k4_mc = np.mean(x**4) - 3 * np.mean(x**2) ** 2
    assert k4_mc == pytest.approx(kap[3], rel=0.06)
    np.testing.assert_allclose(cumulants_from_raw_moments([1.0, 2.0, 5.0]), [1.0, 1.0, 1.0])  # Poisson(1)


def test_char_fn_matches_empirical_characteristic_function():
    """Oracle: empirical E exp(jvn) of a seeded Monte Carlo (Eq. 3.4.6)."""
    noise = MultipleAccessNoise(100_000, 2e-5, two_point_density(B))
    x = sample_noise(noise, 400_000, np.random.default_rng(3))
    v = np.array([1.0, 4.0, 9.0])
    emp = np.exp(1j * v[:, None] * x).mean(axis=1)
    np.testing.assert_allclose(noise.char_fn(v), emp, atol=4e-3)
    assert noise.mean == 0.0
    assert noise.power == pytest.approx(99_999 * 4e-5 * B)


@pytest.mark.parametrize("which", ["two-point", "Gaussian"])
def test_stratified_monte_carlo_matches_exact_tails(which):
    """Oracles: exact compound-binomial tail (two-point) and exact Gaussian mixture."""
    dens = two_point_density(B) if which == "two-point" else GaussianDensity(B)
    noise = MultipleAccessNoise(100_000, 2e-5, dens)
    t = np.array([0.3, 0.5, 0.7])
    est = stratified_tail(noise, t, 20_000, np.random.default_rng(5))
    exact = (
        two_point_exact_tail(np.sqrt(B), 99_999, 4e-5, t)
        if which == "two-point"
        else gaussian_mixture_exact_tail(B, 99_999, 4e-5, t)
    )
    assert np.all(np.abs(est.upper - exact) < 4 * est.upper_se + 1e-12)
    assert np.all(np.abs(est.lower - exact) < 4 * est.lower_se + 1e-12)


def test_edgeworth_improves_on_gaussian_limit_at_large_n_q():
    """Oracle: exact Gaussian-mixture tail; Theorem 3.1 and the lambda_4 term of (E.15)."""
    t = np.array([0.1, 0.15])
    for n in (1_000_000, 10_000_000):
        noise = MultipleAccessNoise(n, 2e-5, GaussianDensity(B))
        exact = gaussian_mixture_exact_tail(B, n - 1, 4e-5, t * np.sqrt(n / 1e5))
        g0 = edgeworth_tail(noise, t * np.sqrt(n / 1e5), terms=0, use_n=False)
        g2 = edgeworth_tail(noise, t * np.sqrt(n / 1e5), terms=2, use_n=False)
        assert np.all(np.abs(g2 - exact) < np.abs(g0 - exact))


def test_psk_amplitude_second_moment_and_kurtosis():
    """Oracle: Eq. (F.5) averaged over random interferer codes, computed by navcore.detection.zakai."""
    rng = np.random.default_rng(7)
    code = rng.choice([-1.0, 1.0], 64)
    x = psk_amplitude_samples(code, 200_000, rng)
    # (F.5): E[n_ij^2 | overlap] = (1/(4 tau)) int R_ii E[R_jj]; E[R_jj] is the unit triangle of one chip.
    r_ii = aperiodic_autocorrelation(code)
    tri = np.zeros_like(r_ii)
    tri[63] = 1.0
    oracle = piecewise_linear_inner(r_ii, tri, 1.0) / (4 * 64)
    assert np.mean(x**2) == pytest.approx(oracle, rel=0.02)
    assert oracle == pytest.approx(1 / (6 * 64), rel=0.15)
    assert abs(np.mean(x)) < 5 * x.std() / np.sqrt(x.size)
    assert np.mean(x**4) / np.mean(x**2) ** 2 > 4.0


def test_bad_inputs_raise():
    with pytest.raises(ValueError, match="b"):
        UniformDensity(-1.0)
    with pytest.raises(ValueError, match="n_aircraft"):
        MultipleAccessNoise(1, 1e-5, GaussianDensity(1.0))
