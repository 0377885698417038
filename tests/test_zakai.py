"""Tests of navcore.detection.zakai against brute-force integration and Monte Carlo."""

from __future__ import annotations

import numpy as np
import pytest

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
    r = np.correlate(s, s, mode="full") * dt
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
    """Oracle: catalogued values for Barker-13 and the 1023-chip m-sequence; m-sequence balance."""
    assert psk_zakai_bandwidth(barker_code(13), 1.0) * 4 / 3 == pytest.approx(0.9337, abs=1e-4)
    m = m_sequence(10)
    assert m.size == 1023 and m.sum() == -1  # one more -1 (ones in the LFSR) than +1
    assert psk_zakai_bandwidth(m, 1.0) * 4 / 3 == pytest.approx(0.7509, abs=1e-4)


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
    same = cross_term_noise_power(ci, [ci] * 5, chip, alpha)
    assert same == pytest.approx(equal_autocorrelation_noise_power(6, alpha, wi), rel=1e-12)
