"""Double-difference carrier phase and its noise covariance against independent oracles (mpmath, by hand)."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from navcore.gnss.carrier_phase import dd_covariance, double_difference_phase
from navcore.units import GPS_L1_WAVELENGTH_M


def _dd_mp(sm, sn, a0, ai, lam) -> float:
    """KZL Eq. 15 from exact ranges: (2 pi / lam) [(|sn - ai| - |sn - a0|) - (|sm - ai| - |sm - a0|)]."""
    mpmath.mp.dps = 40

    def rng(s, a):
        return mpmath.sqrt(
            sum((mpmath.mpf(float(x)) - mpmath.mpf(float(y))) ** 2 for x, y in zip(s, a, strict=True))
        )

    dd = (rng(sn, ai) - rng(sn, a0)) - (rng(sm, ai) - rng(sm, a0))
    return float(2 * mpmath.pi / mpmath.mpf(lam) * dd)


@pytest.mark.parametrize("lam", [GPS_L1_WAVELENGTH_M, 0.25])
def test_double_difference_phase_against_extended_precision_ranges(lam: float) -> None:
    """Oracle: the four ranges (~2e7 m) and their double difference in 40-digit arithmetic
    (mpmath), for seeded satellites and antennas 1-3 m apart near the Earth's surface, at the
    L1 wavelength (the default) and another; also a batch of epochs (leading axis)."""
    rng = np.random.default_rng(6)
    user = np.array([4.0e6, 3.0e6, 3.5e6])
    sats = rng.normal(0, 1.5e7, (6, 3)) + 2.2e7 * user / np.linalg.norm(user)
    base = rng.normal(0, 1.5, (6, 3))
    for k in range(5):
        sm, sn, a0, ai = sats[0], sats[k + 1], user, user + base[k]
        expected = _dd_mp(sm, sn, a0, ai, lam)
        if lam == GPS_L1_WAVELENGTH_M:
            got = double_difference_phase(sm, sn, a0, ai)
        else:
            got = double_difference_phase(sm, sn, a0, ai, wavelength=lam)
        assert float(got) == pytest.approx(expected, abs=1e-8)
    batch = double_difference_phase(sats[[0] * 5], sats[1:], np.tile(user, (5, 1)), user + base[:5], lam)
    np.testing.assert_allclose(
        batch, [_dd_mp(sats[0], sats[k + 1], user, user + base[k], lam) for k in range(5)], rtol=0, atol=1e-8
    )
    with pytest.raises(ValueError, match="coincide"):
        double_difference_phase(sats[0], user, user, user)


@pytest.mark.parametrize(("nu", "k"), [(2, 1), (4, 2), (5, 3)])
def test_dd_covariance_from_shared_undifferenced_phases(nu: int, k: int) -> None:
    """Oracle: the covariance of two double differences, by hand from KZL Eq. 15. DD(s, a) =
    phi(s, a) - phi(s, 0) - phi(0, a) + phi(0, 0) (satellite 0 and antenna 0 the masters) with
    independent phases of variance sigma^2, so Cov(DD(s, a), DD(s', a')) counts the shared
    terms: sigma^2 [(s = s' and a = a') + (s = s') + (a = a') + 1]."""
    sigma = 0.3
    rows = [(s, a) for s in range(1, nu) for a in range(1, k + 1)]
    expected = np.array(
        [[sigma**2 * ((s == t and a == b) + (s == t) + (a == b) + 1) for t, b in rows] for s, a in rows]
    )
    np.testing.assert_allclose(dd_covariance(nu, sigma, n_baselines=k), expected, rtol=1e-14)
    if k == 2:
        np.testing.assert_allclose(dd_covariance(nu, sigma), expected, rtol=1e-14)
