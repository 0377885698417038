"""Double-difference carrier phase against ranges computed in 40-digit arithmetic (mpmath)."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from navcore.gnss.carrier_phase import double_difference_phase
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
