"""Acquisition search time and Gaussian box probabilities against independent oracles."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import norm

from navcore.gnss import acquisition as acq


@pytest.mark.parametrize("k", [1.0, 2.5])
def test_search_time_by_brute_force_enumeration(k: float) -> None:
    """Oracle: enumerate the cell centres of the +-k sigma region one by one (SP Sec. 2.5 Delta T)."""

    def cells(half: float, width: float) -> int:
        n, x = 0, -half
        while True:
            n += 1
            x += width
            if x >= half - 1e-9:
                return n

    for sr, sv in [(75.0, 0.1), (1230.0, 4.0), (630.0, 9.0), (15.0, 0.0), (1000.0, 12.0)]:
        expected = 0.020 * cells(k * sr, 30.0) * cells(k * sv, 10.0)
        got = acq.search_time(sr, sv, dwell_s=0.020, range_cell_m=30.0, rate_cell_mps=10.0, n_sigma=k)
        assert got == pytest.approx(expected)
        assert acq.search_cells(sr, 30.0, k) == cells(k * sr, 30.0)
    t = acq.search_time(
        np.array([75.0, 1230.0]), 4.0, dwell_s=0.05, range_cell_m=30.0, rate_cell_mps=10.0, n_sigma=k
    )
    np.testing.assert_allclose(
        t,
        [
            0.05 * cells(k * 75.0, 30.0) * cells(k * 4.0, 10.0),
            0.05 * cells(k * 1230.0, 30.0) * cells(k * 4.0, 10.0),
        ],
    )


def test_vectorised_cells() -> None:
    np.testing.assert_array_equal(acq.search_cells(np.array([0.0, 15.0, 15.1, 30.0]), 30.0), [1, 1, 2, 2])


def test_box_probability_against_scipy_norm() -> None:
    """Oracle: binomial expansion of 1 - (1 - q)^n with q = 2 norm.sf(k) (scipy.stats.norm)."""
    for n in (1, 2, 3):
        for k in (0.5, 1.0, 3.0, 8.0):
            q = 2 * norm.sf(k)
            expected = sum(math.comb(n, j) * (-1) ** (j + 1) * q**j for j in range(1, n + 1))
            assert acq.probability_outside_sigma_box(n, k) == pytest.approx(expected, rel=1e-9, abs=1e-300)


def test_box_probability_far_tail_keeps_precision() -> None:
    """Oracle: for large k, 1-(1-2Phi(-k))^n ~ 2 n Phi(-k) (Mills-ratio regime; scipy.stats.norm.sf)."""
    assert acq.probability_outside_sigma_box(2, 10.0) == pytest.approx(4 * norm.sf(10.0), rel=1e-9)


def test_doppler_conversions() -> None:
    assert acq.doppler_cell_hz(0.020) == pytest.approx(50.0)
    assert acq.range_rate_from_doppler(50.0, 0.19029367279836487) == pytest.approx(9.5147, abs=1e-4)
    assert math.isclose(acq.search_time_from_cells(82), 1.64)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: acq.search_cells(-1.0, 30.0), "sigma"),
        (lambda: acq.search_cells(1.0, 0.0), "cell"),
        (lambda: acq.search_time_from_cells(0), "n_range"),
        (lambda: acq.search_time(1.0, 1.0, dwell_s=-1, range_cell_m=30.0, rate_cell_mps=10.0), "dwell_s"),
        (lambda: acq.probability_outside_sigma_box(0), "n_dims"),
        (lambda: acq.range_rate_from_doppler(1.0, 0.0), "wavelength_m"),
    ],
)
def test_bad_input_raises(call, match) -> None:
    with pytest.raises(ValueError, match=match):
        call()


def test_defaults_and_return_types() -> None:
    """Oracles: scipy.stats.norm for the default box (one dimension, +-1 sigma: 2 Phi(-1));
    hand products for the conversions; scalars give floats, arrays give arrays."""
    assert acq.probability_outside_sigma_box() == pytest.approx(2 * norm.sf(1.0), rel=1e-12)
    assert acq.probability_outside_sigma_box(3) == pytest.approx(1 - (1 - 2 * norm.sf(1.0)) ** 3, rel=1e-12)
    assert isinstance(acq.range_rate_from_doppler(50.0, 0.2), float)
    np.testing.assert_allclose(acq.range_rate_from_doppler(np.array([50.0, -25.0]), 0.2), [10.0, -5.0])
    assert isinstance(acq.search_time_from_cells(82), float)
    np.testing.assert_allclose(
        acq.search_time_from_cells(np.array([2, 3]), np.array([4, 1]), 0.5), [4.0, 1.5]
    )
    with pytest.raises(ValueError, match="n_doppler"):
        acq.search_time_from_cells(3, 0.5)
