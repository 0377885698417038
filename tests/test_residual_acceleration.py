"""Residual acceleration and Gaussian sphere radii against independent oracles."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import chi2, norm

from navcore.inertial import residual_acceleration as ra


@pytest.mark.parametrize(("dim", "p"), [(1, 0.6827), (2, 0.5), (3, 0.5), (3, 0.9), (3, 0.99)])
def test_isotropic_radius_is_chi_quantile(dim: int, p: float) -> None:
    """Oracle: scipy.stats.chi2.ppf (isotropic case: |x|^2/s^2 is chi-square with dim d.o.f.)."""
    s = 3.7
    assert ra.sphere_radius(s**2 * np.eye(dim), p) == pytest.approx(s * np.sqrt(chi2.ppf(p, dim)), rel=1e-9)


def test_one_dimensional_probability_is_erf() -> None:
    """Oracle: P(|x| <= r) = 2 Phi(r/s) - 1 for a rank-one covariance in 3-D (scipy.stats.norm)."""
    v = np.array([1.0, 2.0, 2.0]) / 3.0
    cov = 4.0 * np.outer(v, v)
    assert ra.sphere_probability(cov, 3.0) == pytest.approx(2 * norm.cdf(1.5) - 1, abs=1e-12)


@pytest.mark.parametrize(
    "eig", [(1.0, 0.1, 0.01), (1.0, 1.0, 1e-4), (1.0, 1e-4, 1e-4), (2.0, 1.0, 0.5), (1.0, 0.3)]
)
def test_anisotropic_radius_against_monte_carlo(eig: tuple[float, ...]) -> None:
    """Oracle: seeded Monte Carlo (seed 7, 1e6 draws; quantile sampling error about 0.1 %)."""
    rng = np.random.default_rng(7)
    Q, _ = np.linalg.qr(rng.standard_normal((len(eig), len(eig))))
    cov = Q @ np.diag(eig) @ Q.T
    cov = 0.5 * (cov + cov.T)
    x = rng.standard_normal((1_000_000, len(eig))) * np.sqrt(eig)
    mc = np.quantile(np.linalg.norm(x, axis=1), 0.9)
    assert ra.sphere_radius(cov, 0.9) == pytest.approx(mc, rel=4e-3)


@pytest.mark.parametrize("p", [0.5, 0.9])
def test_monte_carlo_helper_against_chi_and_normal_quantiles(p: float) -> None:
    """Oracles: scipy.stats. An isotropic 3-D covariance s^2 I has radius s sqrt(chi2_3(p));
    a rank-one covariance lam v v^T (v oblique) has sqrt(lam) Phi^-1((1 + p)/2). The helper's
    2e5 draws give the quantile to about 0.3 % (1 sigma); 1.5 % allowed. Different seeds give
    different draws."""
    s = 2.0
    r_iso = ra.sphere_radius_monte_carlo(s**2 * np.eye(3), p, n=200_000, seed=4)
    assert r_iso == pytest.approx(s * np.sqrt(chi2.ppf(p, 3)), rel=0.015)
    v = np.array([2.0, -1.0, 2.0]) / 3.0
    r_one = ra.sphere_radius_monte_carlo(9.0 * np.outer(v, v), p, n=200_000, seed=5)
    assert r_one == pytest.approx(3.0 * norm.ppf((1 + p) / 2), rel=0.015)
    assert ra.sphere_radius_monte_carlo(np.eye(3), p, n=1000, seed=1) != ra.sphere_radius_monte_carlo(
        np.eye(3), p, n=1000, seed=2
    )


def test_monte_carlo_helper_documented_defaults() -> None:
    """Oracle: the documented defaults (p = 0.9, n = 200000, seed 0): a call without them
    is the call with them, and is within 1.5 % of the chi quantile."""
    cov = np.diag([1.0, 0.5, 0.1])
    r = ra.sphere_radius_monte_carlo(cov)
    assert r == ra.sphere_radius_monte_carlo(cov, 0.9, n=200_000, seed=0)
    assert ra.sphere_radius_monte_carlo(np.eye(3)) == pytest.approx(np.sqrt(chi2.ppf(0.9, 3)), rel=0.015)


def test_sphere_probability_against_chi_square() -> None:
    """Oracle: scipy.stats.chi2.cdf for isotropic covariances in 2-D and 3-D; radius 0 encloses
    nothing."""
    for dim in (2, 3):
        for r in (0.5, 1.7, 4.0):
            assert ra.sphere_probability(2.25 * np.eye(dim), r) == pytest.approx(
                chi2.cdf((r / 1.5) ** 2, dim), abs=1e-10
            )
    assert ra.sphere_probability(np.eye(3), 0.0) == 0.0


def test_sensitivity_matches_cross_product() -> None:
    """Oracle: numpy.cross (delta theta x a) and the elementwise scale-factor product."""
    rng = np.random.default_rng(1)
    a = rng.standard_normal(3)
    x = rng.standard_normal(6)
    H = ra.scale_factor_misalignment_sensitivity(a, convention="cross")
    np.testing.assert_allclose(H @ x, x[:3] * a + np.cross(x[3:], a), atol=1e-14)
    Hp = ra.scale_factor_misalignment_sensitivity(a, convention="printed")
    np.testing.assert_allclose(Hp @ x, x[:3] * a + np.cross(a, x[3:]), atol=1e-14)


def test_covariance_eigenstructure_closed_form() -> None:
    """Oracle: eigenvalues sigma_sf^2 and sigma_sf^2 + 3 sigma_mis^2 (twice) for a = (1,1,1)."""
    ssf, smis = 2e-4, 1e-4
    H = ra.scale_factor_misalignment_sensitivity()
    C = ra.residual_acceleration_covariance(H, np.diag([ssf**2] * 3 + [smis**2] * 3))
    np.testing.assert_allclose(
        np.linalg.eigvalsh(C), [ssf**2, ssf**2 + 3 * smis**2, ssf**2 + 3 * smis**2], rtol=1e-12
    )


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: ra.sphere_radius(np.eye(3), 1.5), "p"),
        (lambda: ra.sphere_radius(np.eye(4), 0.5), "cov"),
        (lambda: ra.sphere_radius(np.zeros((3, 3)), 0.5), "cov"),
        (lambda: ra.sphere_probability(np.eye(3), -1.0), "radius"),
        (lambda: ra.scale_factor_misalignment_sensitivity((1, 1)), "accel"),
        (lambda: ra.scale_factor_misalignment_sensitivity(convention="other"), "convention"),
        (lambda: ra.residual_acceleration_covariance(np.ones((3, 5)), np.eye(6)), "sensitivity"),
    ],
)
def test_bad_input_raises(call, match) -> None:
    with pytest.raises(ValueError, match=match):
        call()


def test_r90_from_apriori_errors_matches_a_sampled_residual() -> None:
    """Oracles: (1) with no misalignment the residual is sf times the unit step on each axis, so
    the radius is the chi(3) 90 % quantile (sqrt of chi2.ppf(0.9, 3)) times sf; (2) a seeded
    Monte Carlo (400000 draws, seed 7) of diag(sf) a + a x theta written with numpy's cross
    product, whose sample 90 % quantile of the norm agrees within 1 % (about 4 standard errors)."""
    from navcore.units import ARCSEC, PPM

    assert ra.r90_from_apriori_ppm(40.0, 0.0) == pytest.approx(40.0 * np.sqrt(chi2.ppf(0.9, 3)), rel=1e-9)
    rng = np.random.default_rng(7)
    sf_ppm, mis_arcsec, a = 35.0, 8.0, np.array([1.0, 1.0, 1.0])
    sf = rng.standard_normal((400_000, 3)) * sf_ppm * PPM
    theta = rng.standard_normal((400_000, 3)) * mis_arcsec * ARCSEC
    residual = sf * a + np.cross(a, theta)
    sampled = np.quantile(np.linalg.norm(residual, axis=1), 0.9) / PPM
    assert ra.r90_from_apriori_ppm(sf_ppm, mis_arcsec) == pytest.approx(sampled, rel=0.01)
    with pytest.raises(ValueError, match="sf_ppm"):
        ra.r90_from_apriori_ppm(-1.0, 0.0)
