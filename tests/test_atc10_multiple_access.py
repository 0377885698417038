"""Cross-checks of the ATC-10 Section 3 computations used by the ledger and the book pages."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate

from navcore.detection.multiple_access import MultipleAccessNoise
from navcore.detection.roc_bounds import roc_lower_bound, roc_upper_bound
from navcore.detection.zakai import m_sequence
from navcore.papers import atc10_gaussian_comparison as gaussian
from navcore.papers import atc10_multiple_access as m
from navcore.papers import atc10_zakai_bandwidth as zakai


def _compound_binomial_exact(values, weights, n_interferers, q, step=1e-4, half_range=4.0):
    """Exact law of the sum of Binomial(n, q) i.i.d. draws from a point-mass density on a
    ``step`` grid, by the generating function (1 - q + q phi)^n evaluated with an FFT.

    Independent of the Chernoff/Gallager code and of the stratified Monte Carlo: it uses only
    the definition of the multiple-access noise (each of n interferers overlaps with
    probability q and adds an independent amplitude). Returns the grid and the probabilities.
    """
    n_grid = round(2 * half_range / step)
    idx = np.round(np.asarray(values) / step).astype(int)
    pmf = np.zeros(n_grid)
    np.add.at(pmf, idx % n_grid, np.asarray(weights) / np.sum(weights))
    law = np.fft.ifft(np.exp(n_interferers * np.log1p(q * (np.fft.fft(pmf) - 1.0)))).real
    k = np.arange(n_grid)
    grid = np.where(k >= n_grid // 2, k - n_grid, k) * step
    order = np.argsort(grid)
    return grid[order], law[order]


def test_psk_bounds_bracket_exact_roc():
    """Oracle: the exact ROC of the PSK multiple-access noise from its generating function
    (FFT on the 1e-4 amplitude grid the density lives on), not the module's Monte Carlo.

    The Chernoff upper bounds (3.5.13) lie above it and the Gallager lower bounds below it at
    every PSK_BOUND_THETAS threshold; the module's stratified Monte Carlo ROC (the book's and
    the ledger's) agrees with it within 4 standard errors.
    """
    d = m.psk_density()
    noise = MultipleAccessNoise(m.IN.n_sec36, m.IN.tau_over_alpha_sec36, d)
    grid, law = _compound_binomial_exact(d.values, d.weights, noise.n_interferers, noise.q)
    assert law.sum() == pytest.approx(1.0, abs=1e-12) and law.min() > -1e-13  # FFT round-off
    th = m.PSK_BOUND_THETAS
    p_f = np.array([law[grid > t + 1e-9].sum() for t in th])  # false alarm: noise above theta
    p_miss = np.array([law[grid < t - 1.0 - 1e-9].sum() for t in th])  # miss: 1 + noise below theta
    ub_f, ub_m = m.psk_chernoff()
    lb_f, lb_m = roc_lower_bound(noise, th)
    assert np.all(p_f <= np.exp(ub_f)) and np.all(p_miss <= np.exp(ub_m))
    assert np.all(np.exp(lb_f) <= p_f) and np.all(np.exp(lb_m) <= p_miss)
    r = gaussian.psk_roc()
    idx = [int(np.argmin(np.abs(gaussian.THETA_GRID - t))) for t in th]
    np.testing.assert_array_less(np.abs(r.p_f[idx] - p_f), 4 * r.p_f_se[idx])
    np.testing.assert_array_less(np.abs(r.p_miss[idx] - p_miss), 4 * r.p_miss_se[idx])


def test_bounds_bracket_actual_roc_at_section_36_values():
    """Oracle: the exact actual ROC (binomial mixtures of two-point, Irwin-Hall and Gaussian sums);
    the Chernoff and Gallager bounds bracket it."""
    th = np.linspace(0.2, 0.8, 4)
    for name in m.DENSITY_NAMES:
        for x in (4.0, 6.0):
            r = gaussian.exact_roc(name, x)
            idx = [int(np.argmin(np.abs(gaussian.THETA_GRID - t))) for t in th]
            tt = gaussian.THETA_GRID[idx]
            noise = m.noise_sec36(name, x)
            ub_f, ub_m = roc_upper_bound(noise, tt)
            lb_f, lb_m = roc_lower_bound(noise, tt)
            assert np.all(r.p_f[idx] <= np.exp(ub_f) + 4 * r.p_f_se[idx])
            assert np.all(np.exp(lb_f) <= r.p_f[idx] + 4 * r.p_f_se[idx])
            assert np.all(r.p_miss[idx] <= np.exp(ub_m) + 4 * r.p_miss_se[idx])
            assert np.all(np.exp(lb_m) <= r.p_miss[idx] + 4 * r.p_miss_se[idx])


def test_worked_example_values():
    """Oracles: exact rational arithmetic of p = (N - 1)/(B alpha) from the printed N = 2e5 and
    B alpha = 1e7; Exp of (3.8.16) as the large-N quasi-optimal exponent with theta eliminated,
    solved here numerically (brentq on N q a sinh(x) = theta with a^2 N q = p, then
    rho theta - N ln(1 - q + q cosh x)); and the exact (N - 1)-interferer optimum within 1e-3."""
    from fractions import Fraction

    from scipy import optimize

    assert m.worked_example_power() == float(Fraction(199_999, 10**7))
    n, r = 200_000, 1e-5
    q = 2 * r
    exp_g = 0.25 / m.worked_example_power()  # a = theta = 0.5, Exp_g = a^2 / p as the example writes it
    p = 1e-3  # any power: Exp depends on theta and p only through Exp_g = theta^2 / (2 p)
    theta = np.sqrt(2 * p * exp_g)
    a = np.sqrt(p / (n * q))
    x = optimize.brentq(lambda z: n * q * a * np.sinh(z) - theta, 0.0, 60.0, xtol=1e-15, rtol=1e-15)
    large_n = x / a * theta - n * np.log1p(q * (np.cosh(x) - 1.0))
    assert gaussian.worked_example_exp() == pytest.approx(large_n, rel=1e-10)
    a1 = np.sqrt(p / ((n - 1) * q))  # the exact optimum: N - 1 interferers of the same total power
    dmu = lambda rho: (n - 1) * q * a1 * np.sinh(rho * a1) / (1 - q + q * np.cosh(rho * a1)) - theta
    rho = optimize.brentq(dmu, 0.0, 1e4, xtol=1e-14, rtol=1e-15)
    exact = rho * theta - (n - 1) * np.log1p(q * (np.cosh(rho * a1) - 1.0))
    assert gaussian.worked_example_exp() == pytest.approx(exact, rel=1e-3)


def _w_chip_msequence_brute_force(degree: int) -> float:
    """Brute force: correlate the sampled chip waveform and integrate R(t)^2 by Simpson's rule."""
    c = m_sequence(degree)
    over = 4
    s = np.repeat(c, over) / np.sqrt(c.size)  # chip = 1 s, unit energy
    r = np.concatenate([[0.0], np.correlate(s, s, mode="full") / over, [0.0]])  # exact at the samples
    t = np.arange(r.size) / over
    energy = integrate.simpson(r**2, x=t)  # exact for a square of a linear function per chip pair
    return 1.0 / (2.0 * energy)


def test_msequence_bandwidth_against_brute_force():
    """Oracle: brute-force integration of the chip waveform, formerly the claim's oracle."""
    assert (
        abs(zakai.w_chip_msequence() / _w_chip_msequence_brute_force(m.IN.nominal("msequence_degree")) - 1)
        < 1e-9
    )


def test_gaussian_beaten_at_lowest_contour_by_exact_mixture():
    """Oracle: the exact Gaussian-C mixture beats ROC_g at 1/sqrt(3b) = 3 (the statement fails there)."""
    # both return the truth of "ROC_g always more optimistic": false at the lowest contour
    assert m.gaussian_beaten_at_low_snr_oracle() is False
    assert gaussian.gaussian_always_more_optimistic() is False
