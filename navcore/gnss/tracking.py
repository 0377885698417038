r"""Third-order tracking loop: error responses to acceleration steps and jerks.

A third-order phase-lock loop with Butterworth closed-loop poles (loop-filter coefficients
:math:`a_3 = b_3 = 2`) has the closed-loop and error transfer functions

.. math::

    \begin{gathered}
    H(s) = \frac{2\omega_0 s^2 + 2\omega_0^2 s + \omega_0^3}{D(s)},\qquad
    \frac{E(s)}{\Theta(s)} = \frac{s^3}{D(s)},\\
    D(s) = s^3 + 2\omega_0 s^2 + 2\omega_0^2 s + \omega_0^3 = (s+\omega_0)(s^2+\omega_0 s+\omega_0^2).
    \end{gathered}

For an acceleration step of size :math:`R` (input :math:`\theta = R t^2/2`) the tracking
error is :math:`E(s) = R/D(s)`, whose inverse transform is (SP Sec. 2.5, the equation above
Fig. 2.1, with the exponent read as :math:`-\omega_0 t/2`)

.. math::

    \Delta\Phi(t) = \frac{R}{\omega_0^2}\Big[e^{-\omega_0 t}
        + \frac{e^{-\omega_0 t/2}}{\sqrt3}\Big(\sin\tfrac{\sqrt3}{2}\omega_0 t
        - \sqrt3\cos\tfrac{\sqrt3}{2}\omega_0 t\Big)\Big].

Its peak is :math:`f_{\max} R/\omega_0^2` with :math:`f_{\max} = 0.404453` at
:math:`\omega_0 t = 2.05439`. For a jerk of size :math:`J` (input :math:`J t^3/6`) the error is

.. math::

    \frac{J}{\omega_0^3}\Big[1 - e^{-\omega_0 t}
        - \tfrac{2}{\sqrt3}e^{-\omega_0 t/2}\sin\tfrac{\sqrt3}{2}\omega_0 t\Big].

Since the peak error scales as :math:`R/\omega_0^2`, the natural frequency that keeps the
same peak under a smaller (aided) step scales as the square root of the step ratio
(SP Eq. 2.1).

Distances are converted to phase with an explicit wavelength: one cycle (360 degrees) per
``wavelength_m`` metres, so that the convention is visible wherever it is used.

References
----------
.. [SP] G. T. Schmidt and R. E. Phillips, "INS/GPS Integration Architecture Performance
   Comparisons", NATO RTO-EN-SET-116, Sec. 2.5, Fig. 2.1, Eq. (2.1), Table 2.6.
.. [Kaplan] E. D. Kaplan and C. J. Hegarty (eds.), *Understanding GPS: Principles and
   Applications*, 2nd ed., Table 5.6 (loop noise bandwidth of a third-order loop).
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import minimize_scalar

from navcore._validate import (
    NONNEGATIVE,
    POSITIVE,
    as_finite_array,
    check_public,
    require_nonnegative,
    require_positive,
)
from navcore.trace import implements

__all__ = [
    "PEAK_TIME_FACTOR",
    "aided_natural_frequency",
    "distance_to_phase_deg",
    "error_transfer_coefficients",
    "jerk_pulse_error",
    "natural_frequency_for_peak_error",
    "peak_factor",
    "third_order_loop_dynamic_error_bound",
    "third_order_loop_jerk_error",
    "third_order_loop_step_error",
    "third_order_noise_bandwidth_hz",
    "third_order_peak_step_error",
    "wavelength_for_peak_error",
]

Array = NDArray[np.float64]
_S3 = math.sqrt(3.0)


def distance_to_phase_deg(distance_m: ArrayLike, wavelength_m: float) -> Array | float:
    """Convert a distance (or its derivatives) to phase in degrees: 360 deg per wavelength.

    Parameters
    ----------
    distance_m : array_like
        Distance, velocity or acceleration in metres (per second, per second squared).
    wavelength_m : float
        Metres per cycle of the tracked signal (the L1 carrier is 0.1903 m; ``> 0``).

    Returns
    -------
    float or ndarray
        Phase in degrees (per second, per second squared).

    Raises
    ------
    ValueError
        If ``wavelength_m`` is not positive or a distance is not finite.

    Examples
    --------
    >>> float(distance_to_phase_deg(0.5, 2.0))
    90.0
    """
    require_positive("wavelength_m", wavelength_m)
    out = 360.0 * as_finite_array("distance_m", distance_m) / wavelength_m
    return float(out) if out.ndim == 0 else out


def error_transfer_coefficients(omega0: float) -> tuple[Array, Array]:
    r"""Numerator and denominator of :math:`E(s)/\Theta(s) = s^3/D(s)` (highest power first).

    Useful for independent time-domain checks (``scipy.signal.lsim``).

    Parameters
    ----------
    omega0 : float
        Natural frequency, rad/s (``> 0``).

    Returns
    -------
    num : (4,) ndarray
        ``[1, 0, 0, 0]``.
    den : (4,) ndarray
        :math:`[1, 2\omega_0, 2\omega_0^2, \omega_0^3]` (the standard third-order loop).

    Raises
    ------
    ValueError
        If ``omega0`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.1 (third-order tracking loop, Fig. 2.1).

    Examples
    --------
    >>> num, den = error_transfer_coefficients(2.0)
    >>> den.tolist()
    [1.0, 4.0, 8.0, 8.0]
    """
    require_positive("omega0", omega0)
    return np.array([1.0, 0.0, 0.0, 0.0]), np.array([1.0, 2 * omega0, 2 * omega0**2, omega0**3])


def third_order_loop_step_error(t_s: ArrayLike, step: float, omega0: float) -> Array | float:
    """Tracking error of the third-order loop after an acceleration step (SP Sec. 2.5).

    Parameters
    ----------
    t_s : array_like
        Time since the step, s (>= 0).
    step : float
        Step size in phase units per s² (deg/s² gives degrees; m/s² gives metres).
    omega0 : float
        Natural frequency, rad/s.

    Returns
    -------
    float or ndarray
        Error in the units of ``step`` times s²: zero at t = 0 and as t -> infinity.

    Raises
    ------
    ValueError
        If ``omega0`` is not positive or a time is negative or not finite.

    Examples
    --------
    >>> round(float(third_order_loop_step_error(2.05439, 1.0, 1.0)), 6)
    0.404453
    """
    require_positive("omega0", omega0)
    t = as_finite_array("t_s", t_s)
    if np.any(t < 0):
        raise ValueError("t_s must be >= 0")
    tau = omega0 * t
    out = (step / omega0**2) * (
        np.exp(-tau) + np.exp(-tau / 2) / _S3 * (np.sin(_S3 / 2 * tau) - _S3 * np.cos(_S3 / 2 * tau))
    )
    return float(out) if out.ndim == 0 else out


def third_order_loop_jerk_error(t_s: ArrayLike, jerk: float, omega0: float) -> Array | float:
    r"""Tracking error of the third-order loop after a jerk starts at :math:`t = 0` (input
    :math:`J t^3/6`).

    The inverse Laplace transform of :math:`J/(s D(s))`; it settles at :math:`J/\omega_0^3`.

    Parameters
    ----------
    t_s : array_like
        Time since the jerk started, s (>= 0).
    jerk : float
        Jerk in phase units per s³ (deg/s³ gives degrees; m/s³ gives metres).
    omega0 : float
        Natural frequency, rad/s.

    Returns
    -------
    float or ndarray
        Error in the units of ``jerk`` times s³ (degrees or metres as above).

    Raises
    ------
    ValueError
        If ``omega0`` is not positive or a time is negative or not finite.

    Examples
    --------
    The error settles at ``J / omega0^3``:

    >>> round(float(third_order_loop_jerk_error(100.0, 8.0, 2.0)), 6)
    1.0
    """
    require_positive("omega0", omega0)
    t = as_finite_array("t_s", t_s)
    if np.any(t < 0):
        raise ValueError("t_s must be >= 0")
    tau = omega0 * t
    out = (jerk / omega0**3) * (1.0 - np.exp(-tau) - 2.0 / _S3 * np.exp(-tau / 2) * np.sin(_S3 / 2 * tau))
    return float(out) if out.ndim == 0 else out


def jerk_pulse_error(t_s: ArrayLike, jerk: float, duration_s: float, omega0: float) -> Array | float:
    """Error for a jerk lasting ``duration_s`` (acceleration ramps to ``jerk*duration_s``, then holds).

    By linearity: the jerk response minus the same response delayed by the duration.

    Parameters
    ----------
    t_s : array_like
        Time since the jerk started, s (>= 0).
    jerk : float
        Jerk in phase units per s³ (deg/s³ gives degrees; m/s³ gives metres).
    duration_s : float
        How long the jerk lasts, s (>= 0).
    omega0 : float
        Natural frequency, rad/s.

    Returns
    -------
    float or ndarray
        Error in the units of ``jerk`` times s³ (degrees or metres as above).

    Raises
    ------
    ValueError
        If ``duration_s`` or a time is negative, ``omega0`` is not positive, or a time is not
        finite.

    Examples
    --------
    A 2-s jerk: the error grows while it lasts and decays once the acceleration holds.

    >>> [round(float(jerk_pulse_error(t, 1.0, 2.0, 1.0)), 4) for t in (1.0, 2.0, 5.0, 100.0)]
    [0.0986, 0.4454, 0.2642, 0.0]
    """
    require_nonnegative("duration_s", duration_s)
    t = as_finite_array("t_s", t_s)
    late = np.clip(t - duration_s, 0.0, None)
    out = np.asarray(third_order_loop_jerk_error(t, jerk, omega0)) - np.where(
        t > duration_s, third_order_loop_jerk_error(late, jerk, omega0), 0.0
    )
    return float(out) if out.ndim == 0 else out


@cache
def _peak() -> tuple[float, float]:
    res = minimize_scalar(
        lambda tau: -third_order_loop_step_error(tau, 1.0, 1.0),
        bounds=(1.0, 3.5),
        method="bounded",
        options={"xatol": 1e-12},
    )
    return float(-res.fun), float(res.x)


def peak_factor() -> float:
    r""":math:`f_{\max}`: peak of the unit-step error at unit natural frequency (0.404453).

    Returns
    -------
    float
        Peak error of the third-order loop for a unit acceleration step at
        :math:`\omega_0 = 1` rad/s (phase unit per unit of the step times s²).

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.1 (peak error after an acceleration step).

    Examples
    --------
    >>> round(peak_factor(), 6)
    0.404453
    """
    return _peak()[0]


#: :math:`\omega_0 t` at which the third-order loop's error after an acceleration step peaks,
#: dimensionless: the time of the peak that :func:`peak_factor` returns.
PEAK_TIME_FACTOR = _peak()[1]


def third_order_peak_step_error(step: float, omega0: float) -> float:
    r"""Peak tracking error :math:`f_{\max} R/\omega_0^2` for an acceleration step ``R``.

    Parameters
    ----------
    step : float
        Acceleration step (deg/s² gives degrees; m/s² gives metres).
    omega0 : float
        Natural frequency, rad/s (``> 0``).

    Returns
    -------
    float
        Peak error, in the unit of ``step`` times s².

    Raises
    ------
    ValueError
        If ``omega0`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.1.

    Examples
    --------
    >>> round(third_order_peak_step_error(1.0, 1.0), 6)
    0.404453
    """
    require_positive("omega0", omega0)
    return peak_factor() * step / omega0**2


def natural_frequency_for_peak_error(step: float, peak_error: float) -> float:
    """Natural frequency at which the step error peaks at ``peak_error``.

    ``step`` and ``peak_error`` share a unit (deg/s² and deg, or m/s² and m).

    Parameters
    ----------
    step : float
        Acceleration step (``> 0``).
    peak_error : float
        Allowed peak tracking error (``> 0``).

    Returns
    -------
    float
        Natural frequency, rad/s.

    Raises
    ------
    ValueError
        If ``step`` or ``peak_error`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.1.

    Examples
    --------
    >>> w = natural_frequency_for_peak_error(100.0, 10.0)
    >>> round(w, 4), round(third_order_peak_step_error(100.0, w), 6)
    (2.0111, 10.0)
    """
    require_positive("step", step)
    require_positive("peak_error", peak_error)
    return math.sqrt(peak_factor() * step / peak_error)


def wavelength_for_peak_error(accel_mps2: float, omega0: float, peak_deg: float) -> float:
    """Wavelength at which an ``accel_mps2`` step gives a ``peak_deg`` peak at ``omega0``.

    Parameters
    ----------
    accel_mps2 : float
        Acceleration step, m/s² (``> 0``).
    omega0 : float
        Natural frequency, rad/s (``> 0``).
    peak_deg : float
        Peak phase error, deg (``> 0``).

    Returns
    -------
    float
        Wavelength, m per cycle.

    Raises
    ------
    ValueError
        If an argument is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.1.

    Examples
    --------
    >>> lam = wavelength_for_peak_error(9.80665, 10.0, 45.0)
    >>> peak_m = third_order_peak_step_error(9.80665, 10.0)
    >>> round(lam, 4), round(float(distance_to_phase_deg(peak_m, lam)), 6)
    (0.3173, 45.0)
    """
    require_positive("accel_mps2", accel_mps2)
    require_positive("peak_deg", peak_deg)
    return 360.0 * third_order_peak_step_error(accel_mps2, omega0) / peak_deg


@implements("SP 2.1")
def aided_natural_frequency(
    step_aided: ArrayLike, step_unaided: float, omega0_unaided: float
) -> Array | float:
    r"""Natural frequency that keeps the unaided peak error under a smaller aided step (SP Eq. 2.1).

    :math:`\omega_{0,aided} = \sqrt{R_{aided}/R_{unaided}}\,\omega_{0,unaided}`.

    Parameters
    ----------
    step_aided : array_like
        Acceleration step the aided loop sees (``>= 0``; any unit shared with
        ``step_unaided``, e.g. g or m/s²).
    step_unaided : float
        Acceleration step of the unaided loop (``> 0``, same unit).
    omega0_unaided : float
        Natural frequency of the unaided loop, rad/s (``> 0``).

    Returns
    -------
    float or ndarray
        Natural frequency of the aided loop, rad/s.

    Raises
    ------
    ValueError
        If ``step_unaided`` or ``omega0_unaided`` is not positive or a ``step_aided`` is
        negative.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Eq. (2.1).

    Examples
    --------
    >>> round(float(aided_natural_frequency(0.011, 6.0, 18.0)), 4)
    0.7707
    """
    require_positive("step_unaided", step_unaided)
    require_positive("omega0_unaided", omega0_unaided)
    r = as_finite_array("step_aided", step_aided)
    if np.any(r < 0):
        raise ValueError("step_aided must be >= 0")
    out = np.sqrt(r / step_unaided) * omega0_unaided
    return float(out) if out.ndim == 0 else out


def third_order_noise_bandwidth_hz(omega0: float, a3: float = 2.0, b3: float = 2.0) -> float:
    r"""One-sided noise bandwidth (Hz) of a third-order loop with coefficients ``a3``, ``b3``.

    The loop's closed-loop denominator is
    :math:`D(s) = s^3 + b_3\omega_0 s^2 + a_3\omega_0^2 s + \omega_0^3`: ``b3`` multiplies
    the :math:`\omega_0 s^2` term and ``a3`` the :math:`\omega_0^2 s` term (Kaplan's
    convention, Fig. 5.24: the loop filter's gains are :math:`a_3\omega_0^2` and
    :math:`b_3\omega_0`; the Butterworth loop of this module has ``a3 = b3 = 2``). Its noise
    bandwidth is

    :math:`B_n = \omega_0 (a_3 b_3^2 + a_3^2 - b_3) / (4 (a_3 b_3 - 1))`,

    :math:`5\omega_0/6` for the Butterworth loop (Kaplan Table 5.6 uses a3 = 1.1, b3 = 2.4).

    Parameters
    ----------
    omega0 : float
        Loop natural frequency (rad/s), ``> 0``.
    a3 : float, default 2.0
        Coefficient of :math:`\omega_0^2 s` in :math:`D(s)`, ``> 0``.
    b3 : float, default 2.0
        Coefficient of :math:`\omega_0 s^2` in :math:`D(s)`, ``> 0``.

    Returns
    -------
    float
        :math:`B_n` in Hz (one-sided).

    Raises
    ------
    ValueError
        If ``omega0``, ``a3`` or ``b3`` is not positive, or ``a3 * b3 <= 1`` (Routh-Hurwitz:
        the loop is unstable and has no finite noise bandwidth).

    Examples
    --------
    >>> round(third_order_noise_bandwidth_hz(6.0), 6)
    5.0
    >>> round(third_order_noise_bandwidth_hz(1.0, a3=1.1, b3=2.4), 4)
    0.7845
    """
    require_positive("omega0", omega0)
    require_positive("a3", a3)
    require_positive("b3", b3)
    if a3 * b3 <= 1:
        raise ValueError(f"a3*b3 must exceed 1 for a stable loop, got a3={a3!r}, b3={b3!r}")
    return omega0 * (a3 * b3**2 + a3**2 - b3) / (4.0 * (a3 * b3 - 1.0))


@implements("SP Sec. 2.5")
def third_order_loop_dynamic_error_bound(accel: ArrayLike, dt_s: float, omega0: float) -> Array:
    r"""Bound on the third-order loop's tracking error driven by a sampled acceleration history.

    The acceleration the loop must follow, ``accel[k]`` (``(N,)`` or ``(N, m)`` for ``m``
    histories), is held constant over each sample interval, so it is a sum of steps
    :math:`\Delta a_j = a_j - a_{j-1}` at :math:`t_j = j\,\Delta t` (the first from zero). By
    superposition of the step response :math:`e(	au)` (:func:`third_order_loop_step_error`
    per unit step), the error at any time in :math:`[t_k, t_{k+1})` is bounded by

    .. math::

        |\epsilon| \le \sum_{j \le k} |\Delta a_j|\,\max_{	au\in[t_k - t_j,\, t_{k+1} - t_j)} |e(	au)|,

    which is exact for an isolated step (its peak :math:`0.4045\,\Delta a/\omega_0^2` is found
    inside the interval) and an upper bound where steps overlap. A constant acceleration
    (the loop is of type 3) or a smooth one slower than the loop leaves no error.

    Parameters
    ----------
    accel : (N,) or (N, m) array
        Acceleration the loop sees at each sample, in distance units per s² (m/s² gives
        metres of tracking error).
    dt_s : float
        Sample interval, s (``> 0``).
    omega0 : float
        Loop natural frequency, rad/s (``> 0``).

    Returns
    -------
    ndarray
        The bound at each sample (shape of ``accel``), in the distance unit of ``accel``.

    Raises
    ------
    ValueError
        If ``dt_s`` or ``omega0`` is not positive or an acceleration is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.5 (the carrier loop's error after an acceleration step).

    Examples
    --------
    One isolated 1-m/s² step at a loop of 1 rad/s, sampled every 0.5 s: the bound reaches
    the step response's peak 0.4045 m and decays with it.

    >>> b = third_order_loop_dynamic_error_bound([0.0, 1.0] + [1.0] * 30, 0.5, 1.0)
    >>> round(float(b.max()), 4), bool(b[-1] < 0.05)
    (0.4045, True)
    """
    require_positive("dt_s", dt_s)
    require_positive("omega0", omega0)
    a = as_finite_array("accel", accel)
    flat = a.ndim == 1
    a2 = a[:, None] if flat else a.reshape(a.shape[0], -1)
    n = a2.shape[0]
    steps = np.abs(np.diff(a2, axis=0, prepend=0.0))
    # |e| maximised over each interval, sampled finely; the response has decayed below 1e-9 of
    # its peak after 40 / omega0
    n_k = min(n, math.ceil(40.0 / (omega0 * dt_s)) + 1)
    sub = 16
    tau = (np.arange(n_k)[:, None] + np.linspace(0.0, 1.0, sub + 1)[None, :]) * dt_s
    kernel = np.abs(np.asarray(third_order_loop_step_error(tau.ravel(), 1.0, omega0))).reshape(tau.shape)
    kernel = kernel.max(axis=1)
    # the interval that holds the response's peak gets the analytic maximum
    m = int(_peak()[1] / omega0 // dt_s)
    if m < n_k:
        kernel[m] = max(kernel[m], _peak()[0] / omega0**2)
    out = np.stack([np.convolve(steps[:, c], kernel)[:n] for c in range(a2.shape[1])], axis=1)
    return out[:, 0] if flat else out.reshape(a.shape)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "omega0": POSITIVE,
        "dt_s": POSITIVE,
        "omega0_unaided": POSITIVE,
        "wavelength_m": POSITIVE,
        "duration_s": NONNEGATIVE,
        "peak_deg": POSITIVE,
        "peak_error": POSITIVE,
        "a3": POSITIVE,
        "b3": POSITIVE,
    },
)
