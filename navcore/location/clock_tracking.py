r"""Tracking the aircraft clock (emission time :math:`\tau_n`) to improve multilateration.

The aircraft emits a pulse about every :math:`\bar\tau` seconds; the emission times form a
clock process :math:`\tau_n` with increments :math:`\Delta_n = \tau_n - \tau_{n-1} - \bar\tau`
whose covariance is :math:`E[\Delta_n \Delta_m] = 2 \sigma_0^2` for :math:`n = m` and
:math:`\sigma_0^2` otherwise (ATC-10 Eq. 4.5.23, the random-walk-plus-frequency-offset model
:math:`\Delta_n = w_n + A`).

The estimator of ATC-10 Section 4.5 predicts :math:`\tau_n` from
:math:`\hat\tau_{n-1} + \bar\tau` and corrects it with the time-of-arrival residuals
projected off the position directions,

.. math::

    \hat\tau_n &= \hat\tau_{n-1} + \bar\tau \\
        &\quad + \gamma_n \mathbf{1}'(I - P)\left(T_n - k_n - (\hat\tau_{n-1} + \bar\tau) \mathbf{1}\right),

with the gain :math:`\gamma_n = s_n / (\sigma^2 + \beta s_n)`, :math:`s_n` the prior variance
(Eqs. 4.5.16-4.5.25). The error variance is :math:`\sigma^2 \gamma_n`; the position error
has mean square :math:`\sigma^2 (\operatorname{tr}\{(F'F)^{-1}\} + \gamma_n S)` (Eq. 4.5.35
corrected). In steady state :math:`\gamma = \psi(\alpha)/\beta` with
:math:`\alpha = (8/27) \sigma_0^2 \beta / \sigma^2` and :math:`\psi` the real root of a cubic
(Eqs. 4.5.26, 4.5.32-4.5.34). When only three satellites remain, :math:`\tau` is
extrapolated (Eqs. 4.5.27-4.5.30).

All variances are in the square of the time unit of :math:`\sigma`; with :math:`F` built
from unit vectors and :math:`c` = 1 ft/ns (the paper's convention) position variances in
ft² equal the ns² numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    COUNT0,
    NONNEGATIVE,
    POSITIVE,
    as_finite_array,
    check_public,
    require_integer,
    require_nonnegative,
    require_positive,
)
from navcore.trace import implements

__all__ = [
    "GainHistory",
    "TrackerMonteCarlo",
    "TrackingErrors",
    "alpha_parameter",
    "clock_error_variances",
    "convergence_steps",
    "convergence_steps_geometric",
    "gain_recursion",
    "position_mse",
    "psi",
    "psi_cubic_root",
    "psi_large_alpha",
    "psi_small_alpha",
    "simulate_tracker",
    "steady_state_gain",
    "three_satellite_clock_variance",
    "three_satellite_clock_variance_steady",
    "tracking_position_errors",
]


@implements("ATC10 4.5.32")
def alpha_parameter(sigma0: float, sigma: float, beta: float) -> float:
    r""":math:`\alpha = (8/27)\, \sigma_0^2 \beta / \sigma^2` (ATC-10 Eq. 4.5.32).

    Parameters
    ----------
    sigma0 : float
        Standard deviation of the clock increments (a time unit, ``>= 0``).
    sigma : float
        Time-of-arrival noise standard deviation (same unit, ``> 0``).
    beta : float
        :math:`\mathbf{1}'(I - P)\mathbf{1}` (dimensionless, ``>= 0``).

    Returns
    -------
    float
        ``alpha`` (dimensionless).

    Raises
    ------
    ValueError
        If ``sigma`` is not positive or ``sigma0`` or ``beta`` is negative.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.32).

    Examples
    --------
    >>> round(alpha_parameter(5.0, 50.0, 0.0543), 7)
    0.0001609
    """
    require_nonnegative("sigma0", sigma0)
    require_positive("sigma", sigma)
    require_nonnegative("beta", beta)
    return 8.0 / 27.0 * sigma0**2 * beta / sigma**2


@implements("ATC10 4.5.34")
def psi(alpha: np.ndarray | float) -> np.ndarray | float:
    r"""Steady-state gain factor :math:`\psi = \gamma \beta` (ATC-10 Eq. 4.5.34), real cube
    roots.

    .. math::

        \psi(\alpha) = 1.5\, \alpha^{1/3} \Big\{&\sqrt[3]{1 + \sqrt{1 + \alpha}} \\
            &+ \sqrt[3]{1 - \sqrt{1 + \alpha}}\Big\}.

    The second cube root has a negative argument: ``np.cbrt`` returns the real root,
    whereas ``x ** (1/3)`` would return a complex principal root. For large :math:`\alpha`
    the two cube roots nearly cancel, so the algebraically equal form
    :math:`1.5\, \alpha / (\sqrt[3]{a}^2 + \sqrt[3]{a} \sqrt[3]{b} + \sqrt[3]{b}^2)` with
    :math:`a - b = 2 \sqrt{1 + \alpha}` is not needed here; both are accurate to about
    :math:`10^{-12}` for :math:`\alpha \le 10^3`.

    Parameters
    ----------
    alpha : float or ndarray
        ``alpha`` of :func:`alpha_parameter` (``>= 0``).

    Returns
    -------
    float or ndarray
        :math:`\psi` in [0, 1).

    Raises
    ------
    ValueError
        If an ``alpha`` is negative or not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.34).

    Examples
    --------
    >>> round(float(psi(1.61e-2)), 5)
    0.40204
    """
    a = as_finite_array("alpha", alpha)
    if np.any(a < 0):
        raise ValueError("alpha must be >= 0")
    s = np.sqrt(1.0 + a)
    out = 1.5 * np.cbrt(a) * (np.cbrt(1.0 + s) + np.cbrt(1.0 - s))
    return float(out) if out.ndim == 0 else out


def psi_cubic_root(alpha: float) -> float:
    r""":math:`\psi` as the real root in (0, 1) of :math:`x^3 + q x - q = 0`,
    :math:`q = 27 \alpha / 4`.

    Independent of :func:`psi`: uses ``numpy.roots`` (companion-matrix eigenvalues).

    Parameters
    ----------
    alpha : float
        ``alpha`` (``> 0``).

    Returns
    -------
    float
        :math:`\psi`.

    Raises
    ------
    ValueError
        If ``alpha`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.26) (the cubic).

    Examples
    --------
    >>> round(psi_cubic_root(1.61e-2), 5)
    0.40204
    """
    require_positive("alpha", alpha)
    q = 27.0 * alpha / 4.0
    r = np.roots([1.0, 0.0, q, -q])
    real = r[np.abs(r.imag) <= 1e-9 * max(1.0, q)].real
    return float(real[(real > 0) & (real < 1)][0])


@implements("ATC10 4.5.38")
def psi_small_alpha(alpha: np.ndarray | float) -> np.ndarray | float:
    r""":math:`1.5 \cdot 2^{1/3} [\alpha^{1/3} - (\alpha/2)^{2/3}]`, the :math:`\alpha \le 0.3`
    approximation (Eq. 4.5.38).

    Parameters
    ----------
    alpha : float or ndarray
        ``alpha`` (``>= 0``).

    Returns
    -------
    float or ndarray
        Approximate :math:`\psi`.

    Raises
    ------
    ValueError
        If an ``alpha`` is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.38).

    Examples
    --------
    >>> round(float(psi_small_alpha(1.61e-2)), 5), round(float(psi(1.61e-2)), 5)
    (0.4013, 0.40204)
    """
    a = as_finite_array("alpha", alpha)
    out = 1.5 * np.cbrt(2.0) * (np.cbrt(a) - np.cbrt(a / 2.0) ** 2)
    return float(out) if out.ndim == 0 else out


@implements("ATC10 4.5.38")
def psi_large_alpha(alpha: np.ndarray | float) -> np.ndarray | float:
    r""":math:`1 - 4 / (27 \alpha)`, the :math:`\alpha \ge 1` approximation (Eq. 4.5.38).

    Parameters
    ----------
    alpha : float or ndarray
        ``alpha`` (``> 0``).

    Returns
    -------
    float or ndarray
        Approximate :math:`\psi`.

    Raises
    ------
    ValueError
        If an ``alpha`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.38).

    Examples
    --------
    >>> round(float(psi_large_alpha(10.0)), 5), round(float(psi(10.0)), 5)
    (0.98519, 0.98581)
    """
    a = as_finite_array("alpha", alpha)
    if np.any(a <= 0):
        raise ValueError("alpha must be > 0")
    out = 1.0 - 4.0 / (27.0 * a)
    return float(out) if out.ndim == 0 else out


@implements("ATC10 4.5.33")
def steady_state_gain(beta: float, sigma: float, sigma0: float) -> float:
    r"""``gamma = psi(alpha) / beta`` (ATC-10 Eq. 4.5.33).

    Parameters
    ----------
    beta : float
        :math:`\mathbf{1}'(I - P)\mathbf{1}`, the clock's share of the geometry (dimensionless, ``> 0``).
    sigma : float
        Time-of-arrival noise standard deviation (a time unit, e.g. ns; ``> 0``).
    sigma0 : float
        Standard deviation of the clock increments :math:`w_n` and :math:`A` (same time unit, ``>= 0``).

    Returns
    -------
    float
        Steady-state gain ``gamma`` (dimensionless).

    Raises
    ------
    ValueError
        If ``beta`` or ``sigma`` is not positive or ``sigma0`` negative.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.33).

    Examples
    --------
    >>> h = gain_recursion(0.5, 50.0, 5.0, 400)
    >>> round(steady_state_gain(0.5, 50.0, 5.0), 4), round(float(h.gamma[-1]), 4)
    (0.4, 0.4)
    """
    require_positive("beta", beta)
    return float(psi(alpha_parameter(sigma0, sigma, beta))) / beta


@dataclass(frozen=True)
class GainHistory:
    r"""The gain recursion for :math:`n = 0, \dots, N` with :math:`N` = ``n_steps``.

    Attributes
    ----------
    gamma : ndarray
        :math:`\gamma_n`; the clock-error variance is :math:`\sigma^2 \gamma_n`
        (:math:`\gamma_0 = 1/\beta`).
    prior_variance : ndarray
        :math:`s_n`, variance of the predicted clock error; at :math:`n = 0`, where nothing
        is predicted, the least-squares variance :math:`\sigma^2 \gamma_0`.
    cross : ndarray
        :math:`d_n = -E[\Delta_{n+1} \xi_n]`, the correlation of the estimation error with
        the next clock increment (:math:`d_0 = 0`).
    """

    gamma: np.ndarray
    prior_variance: np.ndarray
    cross: np.ndarray


@implements("ATC10 4.5.16", "ATC10 4.5.25")
def gain_recursion(beta: float, sigma: float, sigma0: float, n_steps: int) -> GainHistory:
    r"""Optimal gains of the constrained clock tracker (ATC-10 Eqs. 4.5.16-4.5.25, corrected).

    .. math::

        s_n &= 2 \sigma_0^2 + \sigma^2 \gamma_{n-1} + 2 d_{n-1}, \\
        \gamma_n &= \frac{s_n}{\sigma^2 + \beta s_n}, \\
        a_n &= 1 - \gamma_n \beta, \\
        d_n &= a_n (\sigma_0^2 + d_{n-1}),

    starting from the least-squares :math:`\gamma_0 = 1/\beta`.

    Parameters
    ----------
    beta : float
        :math:`\mathbf{1}'(I - P)\mathbf{1}`, the clock's share of the geometry (dimensionless, ``> 0``).
    sigma : float
        Time-of-arrival noise standard deviation (a time unit, e.g. ns; ``> 0``).
    sigma0 : float
        Standard deviation of the clock increments :math:`w_n` and :math:`A` (same time unit, ``>= 0``).
    n_steps : int
        Number of tracked epochs after the first (``>= 0``, bounded).

    Returns
    -------
    GainHistory
        Gains :math:`\gamma_n` (dimensionless; the clock-error variance is
        :math:`\sigma^2 \gamma_n`), prior variances :math:`s_n` and cross terms :math:`d_n`
        (time unit squared), :math:`n = 0, \dots, N` with :math:`N` = ``n_steps``.

    Raises
    ------
    ValueError
        If ``beta`` or ``sigma`` is not positive, ``sigma0`` negative or ``n_steps`` not a
        non-negative integer.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (4.5.16)-(4.5.25).

    Examples
    --------
    >>> h = gain_recursion(0.5, 50.0, 5.0, 200)
    >>> round(float(h.gamma[0]), 4), round(float(h.gamma[-1]), 4)
    (2.0, 0.4)
    """
    require_positive("beta", beta)
    require_positive("sigma", sigma)
    require_nonnegative("sigma0", sigma0)
    n_steps = require_integer("n_steps", n_steps, minimum=0)
    gamma = np.empty(n_steps + 1)
    prior = np.empty(n_steps + 1)
    cross = np.zeros(n_steps + 1)
    gamma[0] = 1.0 / beta
    s2, q2 = sigma**2, sigma0**2
    prior[0] = s2 * gamma[0]  # no prediction at n = 0: the least-squares variance
    for n in range(1, n_steps + 1):
        s = 2.0 * q2 + s2 * gamma[n - 1] + 2.0 * cross[n - 1]
        prior[n] = s
        gamma[n] = s / (s2 + beta * s)
        cross[n] = (1.0 - gamma[n] * beta) * (q2 + cross[n - 1])
    return GainHistory(gamma=gamma, prior_variance=prior, cross=cross)


def clock_error_variances(beta: float, sigma: float, sigma0: float, gains: ArrayLike) -> NDArray[np.float64]:
    r"""Exact clock-error variances of the constrained tracker for any gain sequence.

    The tracker of ATC-10 Sec. 4.5.2 with gains :math:`\gamma_n` (not necessarily the optimal
    ones of :func:`gain_recursion`) has the clock error
    :math:`\xi_n = \hat\tau_n - \tau_n` with, for the increments
    :math:`\Delta_n = w_n + A` of Eq. (4.5.23),

    .. math::

        \xi_n = a_n (\xi_{n-1} - w_n - A) + \gamma_n \mathbf{1}'(I - P)\boldsymbol\epsilon_n,

        a_n = 1 - \gamma_n \beta,

    starting from the least-squares error (variance :math:`\sigma^2/\beta`) independent of
    :math:`A`. The covariance of :math:`(\xi_n, A)` is propagated exactly. With the optimal
    gains the variances are :math:`\sigma^2 \gamma_n`; a fixed gain shows what the
    recursion buys in the first epochs.

    Parameters
    ----------
    beta : float
        :math:`\mathbf{1}'(I - P)\mathbf{1}` (dimensionless, ``> 0``).
    sigma : float
        Time-of-arrival noise standard deviation (a time unit, ``> 0``).
    sigma0 : float
        Standard deviation of the clock increments :math:`w_n` and of :math:`A` (same unit,
        ``>= 0``).
    gains : array_like
        Gains :math:`\gamma_0, \dots, \gamma_N` (dimensionless; :math:`\gamma_0` is not
        used: epoch 0 is the least-squares fix).

    Returns
    -------
    ndarray
        :math:`\operatorname{Var}(\xi_n)`, :math:`n = 0, \dots, N` (time unit squared).

    Raises
    ------
    ValueError
        If ``beta`` or ``sigma`` is not positive, ``sigma0`` is negative or ``gains`` is not a
        non-empty one-dimensional array of finite numbers.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 4.5.2, Eqs. (4.5.16)-(4.5.25).

    Examples
    --------
    >>> h = gain_recursion(0.5, 50.0, 5.0, 3)
    >>> bool(np.allclose(clock_error_variances(0.5, 50.0, 5.0, h.gamma), 50.0**2 * h.gamma))
    True
    """
    require_positive("beta", beta)
    require_positive("sigma", sigma)
    require_nonnegative("sigma0", sigma0)
    gains = as_finite_array("gains", gains, ndim=1)
    if gains.size == 0:
        raise ValueError("gains must hold at least the epoch-0 gain")
    C = np.array([[sigma**2 / beta, 0.0], [0.0, sigma0**2]])  # n = 0: least squares, A independent
    out = [C[0, 0]]
    for g in gains[1:]:
        a = 1.0 - g * beta
        # xi_n = a (xi_{n-1} - w_n - A) + g 1'(I-P) eps_n
        M = np.array([[a, -a], [0.0, 1.0]])
        C = M @ C @ M.T + np.array([[a * a * sigma0**2 + g * g * sigma**2 * beta, 0.0], [0.0, 0.0]])
        out.append(C[0, 0])
    return np.array(out)


def three_satellite_clock_variance(
    gamma_last: float, cross_last: float, sigma: float, sigma0: float, m: np.ndarray | int
) -> np.ndarray:
    r"""Clock-error variance m epochs after the drop to three satellites (exact, any N).

    :math:`\sigma^2 \gamma_N + \sigma_0^2 (m + m^2) + 2 m d_N`: the extrapolation
    :math:`\hat\tau_{N+m} = \hat\tau_N + m \bar\tau` accumulates the clock increments.

    Parameters
    ----------
    gamma_last : float
        Gain ``gamma_N`` at the last epoch with all satellites.
    cross_last : float
        Cross term ``d_N`` at that epoch (time unit squared).
    sigma : float
        Time-of-arrival noise standard deviation (a time unit, e.g. ns; ``> 0``).
    sigma0 : float
        Standard deviation of the clock increments :math:`w_n` and :math:`A` (same time unit, ``>= 0``).
    m : int or ndarray
        Epochs since the drop (``>= 0``).

    Returns
    -------
    ndarray
        Clock-error variance, time unit squared.

    Raises
    ------
    ValueError
        If ``m`` is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972),
    Eqs. (4.5.27)-(4.5.30) (the exact form for any N).

    Examples
    --------
    >>> h = gain_recursion(0.5, 50.0, 5.0, 400)
    >>> v = three_satellite_clock_variance(h.gamma[-1], h.cross[-1], 50.0, 5.0, [0, 10])
    >>> [round(float(x), 1) for x in v]
    [1000.0, 5750.0]
    """
    mm = as_finite_array("m", m)
    return sigma**2 * gamma_last + sigma0**2 * (mm + mm**2) + 2.0 * mm * cross_last


@implements("ATC10 4.5.27")
def three_satellite_clock_variance_steady(
    beta: float, sigma: float, sigma0: float, m: np.ndarray | int
) -> np.ndarray:
    r"""Eq. 4.5.27: :math:`\sigma^2 \gamma + \sigma_0^2 [(2 - \psi) m / \psi + m^2]` with
    :math:`\gamma = \psi/\beta`.

    Parameters
    ----------
    beta : float
        :math:`\mathbf{1}'(I - P)\mathbf{1}`, the clock's share of the geometry (dimensionless, ``> 0``).
    sigma : float
        Time-of-arrival noise standard deviation (a time unit, e.g. ns; ``> 0``).
    sigma0 : float
        Standard deviation of the clock increments :math:`w_n` and :math:`A` (same time unit, ``>= 0``).
    m : int or ndarray
        Epochs since the drop to three satellites (``>= 0``).

    Returns
    -------
    ndarray
        Clock-error variance, time unit squared.

    Raises
    ------
    ValueError
        If ``m`` is not finite or ``beta`` not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.27).

    Examples
    --------
    >>> v = three_satellite_clock_variance_steady(0.5, 50.0, 5.0, [0, 10])
    >>> [round(float(x), 1) for x in v]
    [1000.0, 5750.0]
    """
    p = float(psi(alpha_parameter(sigma0, sigma, beta)))
    mm = as_finite_array("m", m)
    return sigma**2 * p / beta + sigma0**2 * ((2.0 - p) / p * mm + mm**2)


@implements("ATC10 4.5.35")
def position_mse(
    sigma: float, trace: float, clock_term: float, gamma: np.ndarray | float
) -> np.ndarray | float:
    r""":math:`E|\xi_p|^2 = \sigma^2 (\operatorname{tr}\{(F'F)^{-1}\} + \gamma S)` (ATC-10
    Eq. 4.5.35, corrected).

    For three satellites pass the clock term the caller believes in: the invariant
    :math:`\mathbf{1}'(FF')^{-1} \mathbf{1}` (correct) or the printed
    :math:`\mathbf{1}'(F'F)^{-1} \mathbf{1}` (erratum ATC10-E4.1-three-satellite-clock-term).

    Parameters
    ----------
    sigma : float
        Time-of-arrival noise standard deviation (a time unit; with c = 1 ft/ns, ns gives ft).
    trace : float
        :math:`\operatorname{tr}\{(F'F)^{-1}\}` of the position geometry (dimensionless).
    clock_term : float
        :math:`S`, the clock's contribution to the position error (dimensionless).
    gamma : float or ndarray
        Clock gain(s) :math:`\gamma_n` (dimensionless).

    Returns
    -------
    float or ndarray
        Mean square position error, in the time unit squared (ft² with ns and
        :math:`c` = 1 ft/ns).

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.35) and erratum
    ATC10-E4.1-three-satellite-clock-term.

    Examples
    --------
    >>> round(float(position_mse(50.0, 2.0, 1.5, 0.4)), 1)
    6500.0
    """
    return sigma**2 * (trace + np.asarray(gamma) * clock_term)


def convergence_steps(history: GainHistory, rel: float) -> int:
    r"""First n after which :math:`|\gamma_n - \gamma_\infty| \le \mathrm{rel} \cdot \gamma_\infty` for all
    later n.

    ``gamma_inf`` is taken as the last gain of ``history``.

    Parameters
    ----------
    history : GainHistory
        Output of :func:`gain_recursion` (long enough to have converged).
    rel : float
        Relative tolerance (dimensionless).

    Returns
    -------
    int
        Number of epochs to converge.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 4.5 (the convergence of the gain).

    Examples
    --------
    >>> convergence_steps(gain_recursion(0.5, 50.0, 5.0, 400), 0.1)
    5
    """
    g = history.gamma
    limit = g[-1]
    bad = np.flatnonzero(np.abs(g - limit) > rel * limit)
    return 0 if bad.size == 0 else int(bad[-1] + 1)


def convergence_steps_geometric(psi_value: float, rel: float) -> float:
    r"""Steps for the geometric series :math:`\sum_i (1 - \psi)^i` to come within ``rel`` of
    its limit.

    :math:`n = \log(\mathrm{rel}) / \log(1 - \psi) - 1`; for small :math:`\psi` about
    :math:`2.3 / \psi - 1` (``rel = 0.1``).

    Parameters
    ----------
    psi_value : float
        Steady-state gain factor :math:`\psi`, in (0, 1).
    rel : float
        Relative tolerance, in (0, 1).

    Returns
    -------
    float
        Number of steps (not rounded).

    Raises
    ------
    ValueError
        If ``psi_value`` or ``rel`` is not in (0, 1).

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 4.5 (the convergence estimate).

    Examples
    --------
    >>> round(convergence_steps_geometric(0.1, 0.1), 3)
    20.854
    """
    require_positive("psi_value", psi_value)
    if not 0.0 < psi_value < 1.0:
        raise ValueError(f"psi_value must lie in (0, 1), got {psi_value!r}")
    if not 0.0 < rel < 1.0:
        raise ValueError(f"rel must lie in (0, 1), got {rel!r}")
    return math.log(rel) / math.log1p(-psi_value) - 1.0


@dataclass(frozen=True)
class TrackerMonteCarlo:
    """Empirical second moments of the tracker's errors, per epoch n = 0..N+M.

    Attributes
    ----------
    clock_mse : (N+M+1,) ndarray
        Mean square clock error per epoch (time unit squared).
    position_mse : (N+M+1,) ndarray
        Mean square position error per epoch.
    position_norm_variance : (N+M+1,) ndarray
        Variance of the position error norm per epoch.
    n_runs : int
        Number of runs.
    """

    clock_mse: np.ndarray
    position_mse: np.ndarray
    position_norm_variance: np.ndarray
    n_runs: int


def simulate_tracker(
    F_all: np.ndarray,
    F_three: np.ndarray,
    sigma: float,
    sigma0: float,
    n_last: int,
    m_after: int,
    n_runs: int,
    seed: int,
    tau_bar: float,
    tau_start: float = 12_345.0,
) -> TrackerMonteCarlo:
    r"""Monte Carlo of the whole tracker on simulated clocks and time-of-arrival noise.

    Epoch 0: least squares on all satellites; 1..N: the constrained tracker with the gains of
    :func:`gain_recursion`; N+1..N+M: three satellites, clock extrapolated, position from
    ``F3^-1``. The clock is :math:`\tau_n = \tau_{start} + n \bar\tau + \sum_i w_i + n A` with
    :math:`w_i, A \sim N(0, \sigma_0^2)`; measurement noise :math:`N(0, \sigma^2 I)`. The aircraft track
    is an arbitrary nonrandom sequence (it cancels in the errors because the estimator is
    exact for it); only errors are simulated. Vectorised over runs.

    Parameters
    ----------
    F_all : (K, 3) array
        Geometry of all K satellites (unit direction rows, dimensionless).
    F_three : (3, 3) array
        Geometry of the three satellites that remain.
    sigma : float
        Time-of-arrival noise standard deviation (a time unit, e.g. ns).
    sigma0 : float
        Standard deviation of the clock increments (same unit).
    n_last : int
        Last epoch N with all satellites (``>= 0``).
    m_after : int
        Epochs M with three satellites (``>= 0``).
    n_runs : int
        Monte Carlo runs (``>= 2``).
    seed : int
        Seed of ``numpy.random.default_rng``.
    tau_bar : float
        Nominal emission interval (time unit).
    tau_start : float, default 12345.0
        Emission time at epoch 0 (time unit; it cancels in the errors).

    Returns
    -------
    TrackerMonteCarlo
        Empirical clock and position mean square errors and the variance of the position
        error norm per epoch n = 0..N+M (time unit squared), and the number of runs.

    Raises
    ------
    ValueError
        If a geometry is not finite or a count is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Sec. 4.5 (the Monte Carlo check of
    Eqs. (4.5.16)-(4.5.35)).

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    >>> mc = simulate_tracker(F, F[:3], 50.0, 5.0, 20, 5, 200, seed=1, tau_bar=1.0e6)
    >>> mc.clock_mse.shape, mc.n_runs
    ((26,), 200)
    """
    F = as_finite_array("F_all", F_all)
    F3 = as_finite_array("F_three", F_three)
    require_integer("n_runs", n_runs, minimum=2)
    require_integer("n_last", n_last, minimum=0)
    require_integer("m_after", m_after, minimum=0)
    rng = np.random.default_rng(seed)
    K = F.shape[0]
    ones = np.ones(K)
    L = np.linalg.solve(F.T @ F, F.T)  # (F'F)^-1 F'
    resid = ones - F @ (L @ ones)  # (I - P) 1
    beta = float(resid @ resid)
    hist = gain_recursion(beta, sigma, sigma0, n_last)
    total = n_last + m_after + 1
    clock_mse = np.empty(total)
    pos_mse = np.empty(total)
    pos_var = np.empty(total)
    A = rng.normal(0.0, sigma0, n_runs)
    tau = np.full(n_runs, tau_start)
    rng_track = np.linspace(-1.0, 1.0, 3)

    def record(n: int, tau_hat: np.ndarray, p_err: np.ndarray) -> None:
        e = tau_hat - tau
        clock_mse[n] = np.mean(e**2)
        sq = np.sum(p_err**2, axis=1)
        pos_mse[n] = np.mean(sq)
        pos_var[n] = np.var(np.sqrt(sq))

    tau_hat = np.zeros(n_runs)
    for n in range(total):
        if n > 0:
            tau = tau + tau_bar + rng.normal(0.0, sigma0, n_runs) + A
        track = 1.0e4 * n * rng_track  # nonrandom aircraft displacement p_n - p*
        if n <= n_last:
            z = tau[:, None] + (F @ track)[None, :] + rng.normal(0.0, sigma, (n_runs, K))
            if n == 0:
                tau_hat = (z @ resid) / beta
            else:
                pred = tau_hat + tau_bar
                tau_hat = pred + hist.gamma[n] * ((z - pred[:, None]) @ resid)
            p_hat = (z - tau_hat[:, None]) @ L.T
        else:
            z = tau[:, None] + (F3 @ track)[None, :] + rng.normal(0.0, sigma, (n_runs, 3))
            tau_hat = tau_hat + tau_bar
            p_hat = np.linalg.solve(F3, (z - tau_hat[:, None]).T).T
        record(n, tau_hat, p_hat - track[None, :])
    return TrackerMonteCarlo(
        clock_mse=clock_mse, position_mse=pos_mse, position_norm_variance=pos_var, n_runs=n_runs
    )


class TrackingErrors(NamedTuple):
    """Position errors of multilateration with clock tracking (one row of an ATC-10 Table 4.3).

    The three errors are root-mean-square position errors in the length unit of
    ``c * sigma`` (see :func:`tracking_position_errors`).

    Attributes
    ----------
    alpha : float
        ``alpha`` of Eq. (4.5.32).
    psi : float
        ``psi(alpha)`` of Eq. (4.5.34).
    sd_least_squares : float
        RMS position error of least squares without clock tracking.
    sd_tracking_limit : float
        RMS position error of the tracker in steady state.
    sd_first_three_satellite : float
        RMS position error at the first epoch with three satellites.
    """

    alpha: float
    psi: float
    sd_least_squares: float
    sd_tracking_limit: float
    sd_first_three_satellite: float


@implements("ATC10 4.5.27", "ATC10 4.5.35", "ATC10 Table 4.3")
def tracking_position_errors(
    trace_all: float,
    s_all: float,
    trace_three: float,
    s_three: float,
    beta: float,
    sigma0: float,
    sigma: float,
    *,
    c: float,
    psi_value: float | None = None,
) -> TrackingErrors:
    r"""RMS position errors with clock tracking for any geometry and clock (a Table 4.3 row).

    Parameters
    ----------
    trace_all, s_all : float
        :math:`\operatorname{tr}\{(F'F)^{-1}\}` and the clock-direction term ``S`` of all the satellites in
        view
        (dimensionless, F built from unit line-of-sight vectors; see
        :mod:`navcore.location.multilateration`).
    trace_three, s_three : float
        The same for the three satellites that remain after the others are lost.
    beta : float
        The geometry parameter ``beta`` of ATC-10 Eq. 4.5.19 (dimensionless, ``> 0``).
    sigma0 : float
        Clock random-walk standard deviation per pulse interval (time unit of ``sigma``),
        ``>= 0``.
    sigma : float
        Time-of-arrival noise standard deviation (a time unit, e.g. ns or s), ``> 0``.
    c : float
        Length per time unit of ``sigma``: the speed of light in the units wanted, e.g.
        ``navcore.units.C`` (m/s) with ``sigma`` in seconds for metres, or the ATC-10
        convention ``c = 1`` ft/ns with ``sigma`` in ns (physically 0.98357 ft/ns), which
        makes position errors in ft equal the ns numbers. There is no default: the
        convention is the caller's choice.
    psi_value : float, optional
        Use this steady-state gain factor instead of the exact :math:`\psi(\alpha)` (to
        propagate a printed, rounded :math:`\psi`).

    Returns
    -------
    TrackingErrors
        :math:`\alpha` (Eq. 4.5.32), :math:`\psi` (Eq. 4.5.34), and the RMS position
        errors: least squares without tracking :math:`c \sigma \sqrt{\mathrm{tr} + S/\beta}`,
        the tracking limit :math:`c \sigma \sqrt{\mathrm{tr} + (\psi/\beta) S}` (Eq. 4.5.35
        corrected) and the first three-satellite estimate
        :math:`c \sigma \sqrt{\mathrm{tr}_3 + \gamma_{N+1} S_3}` with
        :math:`\gamma_{N+1} = [\psi + (27/8) \alpha (2/\psi)] / \beta` (Eq. 4.5.27).

    Raises
    ------
    ValueError
        If a trace is not positive, an ``S`` negative, ``beta``, ``sigma`` or ``c`` not
        positive, or ``sigma0`` negative (``sigma0 = 0`` gives :math:`\psi = 0` and no first
        three-satellite estimate, so it is rejected too).


    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Eqs. (4.5.27), (4.5.35) and Table 4.3.

    Examples
    --------
    >>> row = tracking_position_errors(2.0, 1.5, 4.0, 2.0, 0.05, 5.0, 50.0, c=1.0)
    >>> round(row.sd_least_squares, 2), round(row.sd_tracking_limit, 2)
    (282.84, 110.68)
    """
    for name, value in (("trace_all", trace_all), ("trace_three", trace_three)):
        require_positive(name, value)
    for name, value in (("s_all", s_all), ("s_three", s_three)):
        require_nonnegative(name, value)
    require_positive("beta", beta)
    require_positive("sigma0", sigma0)
    require_positive("sigma", sigma)
    require_positive("c", c)
    a = alpha_parameter(sigma0, sigma, beta)
    p = float(psi(a)) if psi_value is None else float(require_positive("psi_value", psi_value))
    scale = c * sigma
    sd0 = scale * math.sqrt(trace_all + s_all / beta)
    sdn = scale * math.sqrt(trace_all + p / beta * s_all)
    gamma_first = (p + 27.0 / 8.0 * a * 2.0 / p) / beta
    sdn1 = scale * math.sqrt(trace_three + gamma_first * s_three)
    return TrackingErrors(a, p, sd0, sdn, sdn1)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "n_steps": COUNT0,
        "n_runs": COUNT,
        "sigma": POSITIVE,
        "sigma0": NONNEGATIVE,
        "beta": POSITIVE,
        "tau_bar": POSITIVE,
        "trace": POSITIVE,
        "clock_term": NONNEGATIVE,
        "rel": POSITIVE,
        "m_after": COUNT0,
        "n_last": COUNT0,
    },
)
