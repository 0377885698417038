"""Tests of navcore.detection.neyman_pearson against independent oracles."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from scipy import special, stats

from navcore.detection import neyman_pearson as np_


def _mp_log_q(z: float) -> float:
    """Oracle: ln Q(z) from mpmath's erfc at 60 digits."""
    with mpmath.workdps(60):
        return float(mpmath.log(mpmath.erfc(mpmath.mpf(z) / mpmath.sqrt(2)) / 2))


@pytest.mark.parametrize("x_db", [-30.0, -24.0, -20.0, -10.0, 0.0, 20.0])
@pytest.mark.parametrize("p_d", [0.2145, 0.661, 0.9685, 0.99975])
def test_log_false_alarm_matches_mpmath(x_db: float, p_d: float) -> None:
    """Oracle: 60-digit mpmath evaluation of Q(d - Phi^{-1}(p_d)), including ~1e-45 tails."""
    d = float(np_.detection_index_from_jammer_ratio(10 ** (x_db / 10)))
    with mpmath.workdps(60):
        z = mpmath.mpf(d) - mpmath.sqrt(2) * mpmath.erfinv(2 * mpmath.mpf(p_d) - 1)
    expected = _mp_log_q(float(z))
    got = float(np_.log_false_alarm_probability(p_d, d))
    assert got == pytest.approx(expected, rel=1e-12, abs=1e-14)


def test_tiny_false_alarm_is_not_zero() -> None:
    """Oracle: mpmath. At x = -24 dB and p_d = 0.88^(1/4) p_f is ~1e-45, where 0.5-0.5 erf gives 0."""
    p_d = 0.88**0.25
    d = float(np_.detection_index_from_jammer_ratio(10 ** (-24 / 10)))
    pf = float(np_.false_alarm_probability(p_d, d))
    z = d - stats.norm.ppf(p_d)
    assert 1e-46 < pf < 1e-43
    assert np.log(pf) == pytest.approx(_mp_log_q(z), rel=1e-12)


def test_direct_gaussian_threshold_and_paper_erf_form() -> None:
    """Oracle: the threshold fixed by p_d (scipy.stats.norm.sf) and App. D's erf form (D.17)."""
    p_d, x = 0.9, 10 ** (-1.5)
    d = float(np_.detection_index_from_jammer_ratio(x))
    eta = float(np_.threshold_from_detection_probability(p_d, d))
    assert stats.norm.sf(eta - d) == pytest.approx(p_d, rel=1e-12)
    phi = float(np_.erf_parameter_from_detection_probability(p_d))
    d17 = 0.5 - 0.5 * special.erf(np.sqrt(0.5 / x) - phi)
    assert float(np_.false_alarm_probability(p_d, d)) == pytest.approx(stats.norm.sf(eta), rel=1e-12)
    assert float(np_.false_alarm_probability(p_d, d)) == pytest.approx(d17, rel=1e-9)


def test_detection_probability_and_threshold_against_scipy() -> None:
    """Oracle: scipy.stats.norm (sf, logsf, isf) and scipy.special.erfinv, for signals on either
    side of the threshold and deep in the tail."""
    for th, d in ((0.0, 0.0), (1.0, 3.0), (2.5, -0.7), (40.0, 1.5), (-3.0, 2.0)):
        assert float(np_.log_detection_probability(th, d)) == pytest.approx(
            stats.norm.logsf(th - d), rel=1e-13
        )
        assert float(np_.detection_probability(th, d)) == pytest.approx(
            stats.norm.sf(th - d), rel=1e-12, abs=1e-320
        )
    for p_d in (0.1, 0.5, 0.97, 0.999999):
        for d in (0.0, 2.0, 7.5):
            assert float(np_.threshold_from_detection_probability(p_d, d)) == pytest.approx(
                d + stats.norm.isf(p_d), rel=1e-13, abs=1e-13
            )
        assert float(np_.erf_parameter_from_detection_probability(p_d)) == pytest.approx(
            special.erfinv(2 * p_d - 1), rel=1e-12, abs=1e-15
        )
    assert float(np_.detection_index_from_jammer_ratio(0.04)) == pytest.approx(5.0, rel=1e-15)


def test_limits() -> None:
    """Oracle: the limits p_f -> 0 (strong signal) and p_f -> p_d (d -> 0)."""
    assert float(np_.false_alarm_probability(0.8, 0.0)) == pytest.approx(0.8, rel=1e-14)
    assert float(np_.log_false_alarm_probability(0.8, 100.0)) < -4000


@pytest.mark.parametrize(
    ("fn", "args"),
    [
        (np_.log_false_alarm_probability, (1.0, 1.0)),
        (np_.log_false_alarm_probability, (0.5, -1.0)),
        (np_.detection_index_from_jammer_ratio, (0.0,)),
        (np_.erf_parameter_from_detection_probability, (np.nan,)),
    ],
)
def test_bad_input_raises(fn, args) -> None:
    """Oracle: the validation contract (ValueError naming the parameter)."""
    with pytest.raises(ValueError):
        fn(*args)
