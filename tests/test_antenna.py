"""Tests of navcore.detection.antenna against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from navcore import units
from navcore.detection import antenna


def test_gain_diameter_roundtrip() -> None:
    """Oracle: D = (lambda/pi) sqrt(G/eta) inverts G = eta (pi D/lambda)^2."""
    d = np.array([0.3, 1.0, 5.0])
    g = antenna.dish_gain(d, 1.6e9, 0.6)
    np.testing.assert_allclose(antenna.dish_diameter(g, 1.6e9, 0.6), d, rtol=1e-14)


def test_one_metre_dish_hand_value() -> None:
    """Oracle: hand computation, lambda = c / 1.6 GHz = 0.18737 m, eta = 0.6."""
    lam = units.C / 1.6e9
    assert float(antenna.dish_gain(1.0, 1.6e9, 0.6)) == pytest.approx(0.6 * (np.pi / lam) ** 2, rel=1e-14)
    assert float(antenna.dish_beamwidth_deg(1.0, 1.6e9)) == pytest.approx(70 * lam, rel=1e-14)


def test_beamwidth_rules_agree_roughly() -> None:
    """Oracle: the two textbook beamwidth rules agree within 10 % for eta = 0.6."""
    d = 2 * units.FT
    g = float(antenna.dish_gain(d, 1.6e9, 0.6))
    assert float(antenna.beamwidth_from_gain_deg(g)) == pytest.approx(
        float(antenna.dish_beamwidth_deg(d, 1.6e9)), rel=0.1
    )


def test_rf_power_and_validation() -> None:
    """Oracle: dB arithmetic; ValueError for bad efficiency and diameter."""
    assert float(antenna.rf_power_dbw(40.0, 25.0)) == 15.0
    with pytest.raises(ValueError):
        antenna.dish_gain(1.0, 1.6e9, 1.5)
    with pytest.raises(ValueError):
        antenna.dish_beamwidth_deg(-1.0, 1.6e9)
