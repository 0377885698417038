"""Tests of navcore.detection.zakai against brute-force integration and Monte Carlo."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from navcore.detection.zakai import (
    alternating_sidelobe_autocorrelation,
    aperiodic_autocorrelation,
    barker_code,
    cross_term_noise_power,
    equal_autocorrelation_noise_power,
    m_sequence,
    paper_psk_zakai_bandwidth,
    piecewise_linear_energy,
    piecewise_linear_inner,
    psk_zakai_bandwidth,
    zakai_bandwidth,
    zakai_noise_power_bound,
)


def _brute_autocorr_energy(code, chip, oversample=400):
    """Brute force: sample the rectangular-chip waveform finely and integrate R^2 by Riemann sums."""
    c = np.asarray(code, float)
    dt = chip / oversample
    s = np.repeat(c, oversample) / np.sqrt(c.size * chip)
    r = signal.correlate(s, s, mode="full", method="fft") * dt
    return np.sum(r**2) * dt


def test_piecewise_linear_energy_matches_brute_force():
    """Oracle: fine-grid Riemann integration of the chip waveform's autocorrelation."""
    code = barker_code(7)
    exact = piecewise_linear_energy(aperiodic_autocorrelation(code), 1e-7)
    assert exact == pytest.approx(_brute_autocorr_energy(code, 1e-7), rel=1e-4)


def test_alternating_sidelobes_reproduce_printed_bracket():
    """Oracle: the printed closed form 1 + 2r + 2r^2 (Sec. 3.9) for L+1 alternating sidelobes."""
    for n in (13, 100):
        r = 1 / n
        w = zakai_bandwidth(alternating_sidelobe_autocorrelation(n, n + 1), 1.0)
        assert w == pytest.approx(paper_psk_zakai_bandwidth(1.0, float(n)), rel=1e-12)
        w_consistent = zakai_bandwidth(alternating_sidelobe_autocorrelation(n, n - 1), 1.0)
        assert 1 / (w_consistent * 4 / 3) == pytest.approx(1 + 2 * r, rel=1e-12)


def test_real_codes_zakai_bandwidth():
    """Oracle: fine-grid Riemann integration of the chip waveforms' autocorrelation (brute force),
    for Barker-13 and a 127-chip m-sequence, at two chip durations."""
    for code in (barker_code(13), m_sequence(7)):
        for chip in (1.0, 2e-7):
            brute = 1.0 / (2.0 * _brute_autocorr_energy(code, chip, oversample=200))
            assert psk_zakai_bandwidth(code, chip) == pytest.approx(brute, rel=2e-4)


@pytest.mark.parametrize("degree", range(3, 11))
def test_m_sequences_are_maximal_length(degree):
    """Oracles: the defining property of a maximal-length sequence (period 2^n - 1, one more -1
    than +1 chips, a two-valued periodic autocorrelation: L at lag 0, -1 at every other lag, by an
    explicit circular correlation), and scipy.signal.max_len_seq for the same primitive
    polynomial and initial fill, chip for chip."""
    m = m_sequence(degree)
    L = 2**degree - 1
    assert m.shape == (L,) and set(np.unique(m)) == {-1.0, 1.0} and m.sum() == -1
    periodic = np.array([m @ np.roll(m, k) for k in range(L)])
    assert periodic[0] == L and np.all(periodic[1:] == -1)
    # the same register in scipy: primitive polynomial x^n + x^a (+ ...) + 1, all-ones fill,
    # read from the last stage; scipy lists the feedback taps as n - a
    poly = {3: (2,), 4: (3,), 5: (3,), 6: (5,), 7: (6,), 8: (6, 5, 4), 9: (5,), 10: (7,)}[degree]
    bits, _ = signal.max_len_seq(degree, state=np.ones(degree), taps=[degree - a for a in poly])
    np.testing.assert_array_equal(m, 1.0 - 2.0 * bits)


@pytest.mark.parametrize("length", [2, 3, 4, 5, 7, 11, 13])
def test_barker_codes_have_unit_sidelobes(length):
    """Oracle: the defining property of a Barker code, |sum_i c_i c_{i+k}| <= 1 for every k != 0,
    by explicit sums, and a peak equal to the length."""
    c = barker_code(length)
    assert c.shape == (length,) and c.dtype == np.float64 and set(np.unique(c)) <= {-1.0, 1.0}
    side = [abs(sum(c[i] * c[i + k] for i in range(length - k))) for k in range(1, length)]
    assert max(side) <= 1.0 and c @ c == length
    np.testing.assert_allclose(
        aperiodic_autocorrelation(c)[length - 1 :], [c[: length - k] @ c[k:] / length for k in range(length)]
    )


def test_f5_identity_and_cauchy_schwarz_bound():
    """Oracle: brute-force cross-correlation energy int X_ij^2 = int R_ii R_jj (App. F) and Theorem 3.3."""
    rng = np.random.default_rng(1)
    L, chip, alpha = 31, 1.0, 1.0
    ci = rng.choice([-1.0, 1.0], L)
    cjs = [rng.choice([-1.0, 1.0], L) for _ in range(5)]
    for cj in cjs:
        x = np.correlate(ci, cj, mode="full") / L
        assert piecewise_linear_energy(x, chip) == pytest.approx(
            piecewise_linear_inner(aperiodic_autocorrelation(ci), aperiodic_autocorrelation(cj), chip),
            rel=1e-12,
        )
    power = cross_term_noise_power(ci, cjs, chip, alpha)
    wi = psk_zakai_bandwidth(ci, chip)
    wj = [psk_zakai_bandwidth(c, chip) for c in cjs]
    assert power <= zakai_noise_power_bound(wi, wj, alpha)
    # Cauchy-Schwarz holds with equality when every autocorrelation is the same
    same = cross_term_noise_power(ci, [ci] * 5, chip, alpha)
    assert same == pytest.approx(equal_autocorrelation_noise_power(6, alpha, wi), rel=1e-12)
    assert zakai_noise_power_bound(wi, [wi] * 5, alpha) == pytest.approx(same, rel=1e-12)


def test_cross_term_power_matches_waveform_integration():
    """Oracle: (1/(2 alpha)) sum_j int X_ij(t)^2 dt with the cross-correlations X_ij of the
    sampled chip waveforms integrated by Riemann sums (Eq. F.6 from the waveforms, not from the
    autocorrelations), and the sum over j of 1/(4 alpha sqrt(W_i W_j)) written out."""
    rng = np.random.default_rng(4)
    L, chip, alpha, over = 11, 2e-6, 0.5, 200
    ci = rng.choice([-1.0, 1.0], L)
    cjs = [rng.choice([-1.0, 1.0], L) for _ in range(3)]
    dt = chip / over

    def wave(c):
        return np.repeat(c, over) / np.sqrt(L * chip)

    brute = sum(np.sum((np.correlate(wave(ci), wave(cj), mode="full") * dt) ** 2) * dt for cj in cjs) / (
        2 * alpha
    )
    assert cross_term_noise_power(ci, cjs, chip, alpha) == pytest.approx(brute, rel=1e-3, abs=0)
    wi, wj = 3.0e5, np.array([2.0e5, 4.5e5, 8.0e5])
    assert zakai_noise_power_bound(wi, wj, alpha) == pytest.approx(
        sum(1 / (4 * alpha * np.sqrt(wi * w)) for w in wj), rel=1e-14, abs=0
    )
    assert equal_autocorrelation_noise_power(7, alpha, wi) == pytest.approx(
        6 / (4 * alpha * wi), rel=1e-14, abs=0
    )


def test_piecewise_linear_integrals_match_quadrature():
    """Oracle: Simpson's rule on each interval (exact for the piecewise-quadratic products) of
    the piecewise-linear interpolants (np.interp), zero outside the samples, spacing 0.37."""
    f = np.array([0.3, -1.2, 2.0, 0.7])
    g = np.array([1.1, 0.4, -0.5, 2.2])
    h = 0.37
    grid = h * np.arange(-1, 5)

    def simpson(fun):
        a, b = grid[:-1], grid[1:]
        return float(np.sum((b - a) / 6 * (fun(a) + 4 * fun(0.5 * (a + b)) + fun(b))))

    def interp(y):
        return lambda t: np.interp(t, grid, np.concatenate([[0.0], y, [0.0]]))

    fi, gi = interp(f), interp(g)
    inner = simpson(lambda t: fi(t) * gi(t))
    energy = simpson(lambda t: fi(t) ** 2)
    assert piecewise_linear_inner(f, g, h) == pytest.approx(inner, rel=1e-12)
    assert piecewise_linear_energy(f, h) == pytest.approx(energy, rel=1e-12)
    assert zakai_bandwidth(f, h) == pytest.approx(1 / (2 * energy), rel=1e-12)
    assert paper_psk_zakai_bandwidth(2.0, 10.0) == pytest.approx(
        1 / (4 / 3 * 2.0 * (1 + 0.4 + 0.08)), rel=1e-14
    )
    np.testing.assert_allclose(
        alternating_sidelobe_autocorrelation(5, 3, -2.0), [-0.4, 0.4, -0.4, 1.0, -0.4, 0.4, -0.4]
    )


def test_autocorrelation_of_short_and_scaled_codes():
    """Oracle: explicit sums: one chip has R = [1]; a scaled code has the same normalised
    autocorrelation; a code of zero energy is rejected."""
    np.testing.assert_array_equal(aperiodic_autocorrelation([1.0]), [1.0])
    np.testing.assert_allclose(aperiodic_autocorrelation([0.5, 0.5]), [0.5, 1.0, 0.5], rtol=1e-15)
    with pytest.raises(ValueError):
        aperiodic_autocorrelation([0.0, 0.0])
