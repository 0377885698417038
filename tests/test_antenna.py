"""Tests of navcore.detection.antenna against closed forms."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import trapezoid
from scipy.optimize import brentq
from scipy.special import j0

from navcore import units
from navcore.detection import antenna


def test_gain_diameter_roundtrip() -> None:
    """Oracle: D = (lambda/pi) sqrt(G/eta) inverts G = eta (pi D/lambda)^2."""
    d = np.array([0.3, 1.0, 5.0])
    g = antenna.dish_gain(d, 1.6e9, 0.6)
    np.testing.assert_allclose(antenna.dish_diameter(g, 1.6e9, 0.6), d, rtol=1e-14)


def _aperture_pattern(u: np.ndarray, taper: int) -> np.ndarray:
    """Far-field amplitude of a circular aperture with illumination (1 - rho^2)^taper, by
    quadrature of the Fraunhofer integral int_0^1 f(rho) J0(u rho) rho d rho (u = k a sin theta)."""
    rho, w = np.polynomial.legendre.leggauss(200)
    rho, w = 0.5 * (rho + 1.0), 0.5 * w
    f = (1.0 - rho**2) ** taper
    return (j0(np.outer(u, rho)) * (f * rho)) @ w


def test_dish_gain_from_aperture_diffraction() -> None:
    """Oracle: directivity 4 pi |E(0)|^2 / int |E|^2 dOmega of a uniformly illuminated circular
    aperture (Fraunhofer diffraction, forward hemisphere, quadrature), 20 wavelengths across;
    the dish gain is the aperture efficiency times it (uniform illumination: efficiency 1)."""
    f_hz = 1.6e9
    lam = units.C / f_hz
    d = 20.0 * lam
    ka = np.pi * d / lam
    theta = np.linspace(0.0, np.pi / 2, 20_001)
    e2 = _aperture_pattern(ka * np.sin(theta), 0) ** 2
    e0 = _aperture_pattern(np.array([0.0]), 0)[0] ** 2
    omega = 2 * np.pi * trapezoid(e2 * np.sin(theta), theta)
    directivity = 4 * np.pi * e0 / omega
    assert float(antenna.dish_gain(d, f_hz, 1.0)) == pytest.approx(directivity, rel=5e-3)
    assert float(antenna.dish_gain(d, f_hz, 0.6)) == pytest.approx(0.6 * directivity, rel=5e-3)


def test_dish_beamwidth_rule_between_uniform_and_tapered_apertures() -> None:
    """Oracle: half-power widths of the diffraction patterns (quadrature + brentq): a uniform
    aperture gives 58.9 lambda/D deg, a (1 - rho^2) taper 72.8 lambda/D deg; the rule's 70
    lambda/D ('tapered illumination') lies between, close to the taper."""
    f_hz = 1.6e9
    lam = units.C / f_hz
    d = 1.0

    def hpbw_factor(taper: int) -> float:
        e0 = _aperture_pattern(np.array([0.0]), taper)[0]
        u_half = brentq(lambda u: _aperture_pattern(np.array([u]), taper)[0] ** 2 - 0.5 * e0**2, 0.1, 3.0)
        return float(np.degrees(2 * u_half / np.pi))  # theta_hp = 2 u / (k a) = (2 u / pi) lambda / D

    lo, hi = hpbw_factor(0), hpbw_factor(1)
    assert lo == pytest.approx(58.9, abs=0.1) and hi == pytest.approx(72.8, abs=0.1)
    factor = float(antenna.dish_beamwidth_deg(d, f_hz)) * d / lam
    assert lo < factor < hi
    assert factor == pytest.approx(hi, rel=0.05)


def test_rule_constants_and_wavelength_scaling() -> None:
    """Oracle: the two rules of thumb with the constants the module documents (half-power
    beamwidth 70 lambda/D degrees for a tapered dish; G = 27000 / theta^2 for a pencil beam, theta
    in degrees), evaluated at non-round inputs: they pin the conventions, which no physics fixes
    exactly (the diffraction tests above bracket the first); lambda = c / f with c = 299 792 458
    m/s typed here; the rf power as the watt ratio ERP / G converted back to dB."""
    for d, f_hz in ((0.37, 2.3e9), (4.1, 9.4e8)):
        lam = 299_792_458.0 / f_hz
        assert float(antenna.dish_beamwidth_deg(d, f_hz)) == pytest.approx(70.0 * lam / d, rel=1e-14)
        assert float(antenna.dish_beamwidth_deg(d, f_hz, factor_deg=58.9)) == pytest.approx(
            58.9 * lam / d, rel=1e-14
        )
        assert float(antenna.dish_gain(d, f_hz, 0.55)) == pytest.approx(
            0.55 * (np.pi * d / lam) ** 2, rel=1e-14
        )
    for theta in (2.5, 17.0, 190.0):  # 190 deg: a gain below 1 is still a valid input
        assert float(antenna.beamwidth_from_gain_deg(27000.0 / theta**2)) == pytest.approx(theta, rel=1e-14)
    erp_w, gain = 10**4.37, 10**1.82
    assert float(antenna.rf_power_dbw(43.7, 18.2)) == pytest.approx(10 * np.log10(erp_w / gain), abs=1e-12)


def test_rf_power_and_validation() -> None:
    """Oracle: dB arithmetic; ValueError for bad efficiency and diameter."""
    assert float(antenna.rf_power_dbw(40.0, 25.0)) == 15.0
    with pytest.raises(ValueError):
        antenna.dish_gain(1.0, 1.6e9, 1.5)
    with pytest.raises(ValueError):
        antenna.dish_beamwidth_deg(-1.0, 1.6e9)
