"""Third-order loop responses against independent oracles (sympy, scipy.signal, quadrature)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy import integrate, signal

from navcore.gnss import tracking as trk
from navcore.units import G0, GPS_L1_WAVELENGTH_M


def test_step_error_is_inverse_laplace_transform() -> None:
    """Oracle: sympy inverse Laplace transform of R/((s+w0)(s^2+w0 s+w0^2)) (SP Sec. 2.5)."""
    s, t, w = sp.symbols("s t omega0", positive=True)
    f = sp.lambdify((t, w), sp.inverse_laplace_transform(1 / ((s + w) * (s**2 + w * s + w**2)), s, t))
    tt = np.linspace(0.0, 2.0, 41)
    np.testing.assert_allclose(trk.third_order_loop_step_error(tt, 1.0, 3.0), f(tt, 3.0), atol=1e-14)


def _error_system(w0: float) -> tuple[np.ndarray, np.ndarray]:
    """E/Theta = s^3/D(s), D from its poles -w0 and w0 exp(+-2 pi i/3) (numpy.poly), not the module."""
    poles = w0 * np.array([-1.0, np.exp(2j * np.pi / 3), np.exp(-2j * np.pi / 3)])
    return np.array([1.0, 0.0, 0.0, 0.0]), np.real(np.poly(poles))


def test_error_transfer_coefficients_from_poles() -> None:
    """Oracle: numpy.poly of the closed-loop poles (s + w0)(s^2 + w0 s + w0^2)."""
    for w0 in (0.7, 3.0):
        num, den = trk.error_transfer_coefficients(w0)
        ref_num, ref_den = _error_system(w0)
        np.testing.assert_allclose(num, ref_num, atol=0)
        np.testing.assert_allclose(den, ref_den, rtol=1e-14)


def test_step_and_jerk_error_match_lsim() -> None:
    """Oracle: scipy.signal.lsim of E/Theta = s^3/D(s) driven by R t^2/2 and by J t^3/6."""
    w0 = 5.0
    num, den = _error_system(w0)
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
    num, den = _error_system(w0)
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


@pytest.mark.parametrize(("w0", "a3", "b3"), [(2.0, 2.0, 2.0), (1.3, 1.1, 2.4), (0.8, 3.0, 0.5)])
def test_noise_bandwidth_by_quadrature(w0: float, a3: float, b3: float) -> None:
    """Oracle: Bn = (1/2pi) integral_0^inf |H(jw)|^2 dw for H = 1 - s^3/D (Kaplan's definition),
    D = s^3 + b3 w0 s^2 + a3 w0^2 s + w0^3 (Kaplan Fig. 5.24: loop-filter gains a3 w0^2 and
    b3 w0), for the Butterworth loop, Kaplan's Table 5.6 coefficients (Bn = 0.7845 w0) and an
    asymmetric pair. The docstring had a3 and b3 swapped in D(s); with a3 on the s^2 term the
    Table 5.6 pair gives 1.153 w0 by this quadrature, not 0.7845 w0."""

    def h2(w: float) -> float:
        s = 1j * w
        D = s**3 + b3 * w0 * s**2 + a3 * w0**2 * s + w0**3
        return abs((b3 * w0 * s**2 + a3 * w0**2 * s + w0**3) / D) ** 2

    val, _ = integrate.quad(h2, 0, np.inf, limit=400)
    assert val / (2 * math.pi) == pytest.approx(trk.third_order_noise_bandwidth_hz(w0, a3, b3), rel=1e-7)


def _lsim_peak(step: float, w0: float) -> float:
    """Peak |error| of the loop after an acceleration step, by scipy.signal.lsim on a fine grid."""
    t = np.linspace(0.0, 8.0 / w0, 8001)
    _, y, _ = signal.lsim(_error_system(w0), 0.5 * step * t**2, t)
    return float(np.max(np.abs(y)))


def test_aided_frequency_keeps_the_unaided_peak() -> None:
    """Oracle: scipy.signal.lsim. The aided loop at the returned natural frequency, driven by
    the smaller aided step, peaks at the same error as the unaided loop under its step
    (SP Eq. 2.1's purpose), for steps 0.011 g and 0.5 g against 6 g at 18 rad/s."""
    unaided = _lsim_peak(6 * G0, 18.0)
    w = trk.aided_natural_frequency(np.array([0.011, 0.5]), 6.0, 18.0)
    assert w.shape == (2,)
    for step, wa in zip((0.011, 0.5), w, strict=True):
        assert _lsim_peak(step * G0, wa) == pytest.approx(unaided, rel=1e-5)


def test_inverse_functions_reach_the_requested_peak() -> None:
    """Oracle: scipy.signal.lsim peaks. The natural frequency for a 90-deg peak under a 6-g
    step (in L1 carrier degrees) gives a 90-deg lsim peak; the wavelength for a 90-deg peak
    at 17.67 rad/s gives a 90-deg lsim peak when the metre peak is converted to degrees at
    that wavelength (360 deg per wavelength); the peak error equals the lsim peak."""
    R = 6 * G0 * 360.0 / GPS_L1_WAVELENGTH_M  # deg/s^2
    assert float(trk.distance_to_phase_deg(6 * G0, GPS_L1_WAVELENGTH_M)) == pytest.approx(R, rel=1e-15)
    w = trk.natural_frequency_for_peak_error(R, 90.0)
    assert _lsim_peak(R, w) == pytest.approx(90.0, rel=1e-5)
    assert trk.third_order_peak_step_error(R, 7.0) == pytest.approx(_lsim_peak(R, 7.0), rel=1e-5)
    lam = trk.wavelength_for_peak_error(6 * G0, 17.67, 90.0)
    assert _lsim_peak(6 * G0, 17.67) * 360.0 / lam == pytest.approx(90.0, rel=1e-5)


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


def test_scalar_inputs_give_floats_and_arrays_give_arrays() -> None:
    """Contract (documented 'float or ndarray'): scalar time in, Python float out; array in,
    array out of the same shape, equal elementwise to the scalar calls (sympy's inverse
    Laplace transform above is the oracle of the values)."""
    t = np.array([0.3, 1.7])
    for f in (
        lambda x: trk.third_order_loop_step_error(x, 2.0, 3.0),
        lambda x: trk.third_order_loop_jerk_error(x, 2.0, 3.0),
        lambda x: trk.jerk_pulse_error(x, 2.0, 1.0, 3.0),
        lambda x: trk.distance_to_phase_deg(x, 0.2),
        lambda x: trk.aided_natural_frequency(x, 6.0, 18.0),
    ):
        assert isinstance(f(0.3), float)
        arr = f(t)
        assert isinstance(arr, np.ndarray) and arr.shape == (2,)
        np.testing.assert_allclose(arr, [f(0.3), f(1.7)], rtol=1e-15)
    assert trk.distance_to_phase_deg(0.05, 0.2) == pytest.approx(90.0, rel=1e-15)  # a quarter wavelength


def test_default_coefficients_and_the_stability_boundary() -> None:
    """Oracle: quadrature of |H|^2 for the default (Butterworth, a3 = b3 = 2) loop, 5 w0/6;
    at a3 b3 = 1 the loop is marginally stable (Routh-Hurwitz) and is rejected; a negative time
    is rejected by the jerk response too."""

    def h2(w: float, w0: float = 1.7) -> float:
        s = 1j * w
        return (
            abs((2 * w0 * s**2 + 2 * w0**2 * s + w0**3) / (s**3 + 2 * w0 * s**2 + 2 * w0**2 * s + w0**3)) ** 2
        )

    val, _ = integrate.quad(h2, 0, np.inf, limit=400)
    assert trk.third_order_noise_bandwidth_hz(1.7) == pytest.approx(val / (2 * math.pi), rel=1e-7)
    with pytest.raises(ValueError, match="a3"):
        trk.third_order_noise_bandwidth_hz(1.0, 0.5, 2.0)
    with pytest.raises(ValueError, match="t_s"):
        trk.third_order_loop_jerk_error(np.array([1.0, -0.1]), 1.0, 1.0)
