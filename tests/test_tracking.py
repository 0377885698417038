"""Third-order loop responses against independent oracles (sympy, scipy.signal, quadrature)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy import integrate, signal

from navcore.gnss import tracking as trk
from navcore.units import FT, G0, GPS_L1_WAVELENGTH_M


def test_step_error_is_inverse_laplace_transform() -> None:
    """Oracle: sympy inverse Laplace transform of R/((s+w0)(s^2+w0 s+w0^2)) (SP Sec. 2.5)."""
    s, t, w = sp.symbols("s t omega0", positive=True)
    f = sp.lambdify((t, w), sp.inverse_laplace_transform(1 / ((s + w) * (s**2 + w * s + w**2)), s, t))
    tt = np.linspace(0.0, 2.0, 41)
    np.testing.assert_allclose(trk.third_order_loop_step_error(tt, 1.0, 3.0), f(tt, 3.0), atol=1e-14)


def test_step_and_jerk_error_match_lsim() -> None:
    """Oracle: scipy.signal.lsim of E/Theta = s^3/D(s) driven by R t^2/2 and by J t^3/6."""
    w0 = 5.0
    num, den = trk.error_transfer_coefficients(w0)
    t = np.linspace(0.0, 4.0, 40001)
    _, y, _ = signal.lsim((num, den), 0.5 * 2.0 * t**2, t)
    np.testing.assert_allclose(y, trk.third_order_loop_step_error(t, 2.0, w0), atol=1e-8)
    _, yj, _ = signal.lsim((num, den), 3.0 * t**3 / 6, t)
    np.testing.assert_allclose(yj, trk.third_order_loop_jerk_error(t, 3.0, w0), atol=1e-8)


def test_jerk_pulse_matches_lsim() -> None:
    """Oracle: lsim with the acceleration profile ramping for 0.6 s then holding (input by quadrature)."""
    w0, J, T = 4.0, 1.0, 0.6
    t = np.linspace(0.0, 3.0, 30001)
    theta = np.where(t <= T, J * t**3 / 6, J * T**3 / 6 + J * T**2 / 2 * (t - T) + J * T / 2 * (t - T) ** 2)
    num, den = trk.error_transfer_coefficients(w0)
    _, y, _ = signal.lsim((num, den), theta, t)
    np.testing.assert_allclose(y, trk.jerk_pulse_error(t, J, T, w0), atol=1e-8)


def test_peak_factor_against_root_of_derivative() -> None:
    """Oracle: the peak solves exp(-tau/2) = cos(sqrt3 tau/2) + sin(sqrt3 tau/2)/sqrt3 (derivative zero)."""
    from scipy.optimize import brentq

    g = lambda x: (
        math.exp(-x / 2) - math.cos(math.sqrt(3) * x / 2) - math.sin(math.sqrt(3) * x / 2) / math.sqrt(3)
    )
    tau = brentq(g, 1.0, 3.0, xtol=1e-14)
    assert tau == pytest.approx(trk.PEAK_TIME_FACTOR, abs=1e-6)
    assert trk.peak_factor() == pytest.approx(trk.third_order_loop_step_error(tau, 1.0, 1.0), abs=1e-12)
    assert trk.peak_factor() == pytest.approx(0.404453, abs=1e-6)


def test_noise_bandwidth_by_quadrature() -> None:
    """Oracle: Bn = (1/2pi) integral_0^inf |H(jw)|^2 dw for H = 1 - s^3/D (Kaplan's definition)."""
    w0 = 2.0

    def h2(w: float) -> float:
        s = 1j * w
        D = s**3 + 2 * w0 * s**2 + 2 * w0**2 * s + w0**3
        return abs((2 * w0 * s**2 + 2 * w0**2 * s + w0**3) / D) ** 2

    val, _ = integrate.quad(h2, 0, np.inf, limit=400)
    assert val / (2 * math.pi) == pytest.approx(trk.third_order_noise_bandwidth_hz(w0), rel=1e-7)


def test_aided_frequency_and_inverse_functions() -> None:
    """Oracle: the closed relations of Eq. (2.1) and peak = f R / w0^2 used backwards."""
    assert trk.aided_natural_frequency(0.011, 6.0, 18.0) == pytest.approx(math.sqrt(0.011 / 6) * 18)
    R = float(trk.distance_to_phase_deg(6 * G0, GPS_L1_WAVELENGTH_M))
    w = trk.natural_frequency_for_peak_error(R, 90.0)
    assert trk.third_order_peak_step_error(R, w) == pytest.approx(90.0, rel=1e-12)
    assert w == pytest.approx(22.366, abs=1e-3)
    assert trk.wavelength_for_peak_error(6 * G0, 17.67, 90.0) == pytest.approx(FT, abs=3e-4)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: trk.third_order_loop_step_error(1.0, 1.0, -1.0), "omega0"),
        (lambda: trk.third_order_loop_step_error(-1.0, 1.0, 1.0), "t_s"),
        (lambda: trk.distance_to_phase_deg(1.0, 0.0), "wavelength_m"),
        (lambda: trk.aided_natural_frequency(-1.0, 6.0, 18.0), "step_aided"),
        (lambda: trk.natural_frequency_for_peak_error(1.0, 0.0), "peak_error"),
        (lambda: trk.third_order_noise_bandwidth_hz(1.0, 0.5, 1.0), "a3"),
    ],
)
def test_bad_input_raises(call, match) -> None:
    with pytest.raises(ValueError, match=match):
        call()
