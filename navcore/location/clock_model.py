r"""Stochastic model of a free-running aircraft clock (ATC-10 Appendix G).

The phase error :math:`\tau_n` of the clock (in seconds, after removing the nominal period)
is modelled as an independent-increment component (white frequency noise, a Wiener process)
plus a fractional-Brownian "1/f" (flicker frequency) component with Hurst exponent
:math:`\rho` (``rho_h``):

.. math::

    E[(\tau_n - \tau_0)&(\tau_m - \tau_0)] = \sigma_1^2 \min(m, n) \\
        &+ \frac{\sigma_2^2}{2} \left(m^{2\rho} + n^{2\rho} - |m - n|^{2\rho}\right)

(plus :math:`\bar\tau^2 m n` for the raw second moment), the unnumbered model of ATC-10
Sec. 4.3, with the ":math:`(1/\tau^2)\, mn`" typo read as
:math:`\bar\tau^2 mn` (erratum E4-9). With :math:`\sigma_1 = \sigma_2 = \sigma_0` and
:math:`\rho = 1` it reduces to :math:`\sigma_0^2 (\min(m, n) + m n)`: a random walk plus a
random frequency offset (Eq. 4.3.1).

The Mandelbrot-Van Ness representation of fractional Brownian motion normalises its
variance by :math:`V_0(\rho) = 1 / (\Gamma(2 \rho + 1) \sin(\pi \rho))` (Eq. G.5, corrected
integrand, erratum E4-7); :func:`mandelbrot_van_ness_constant_integral` evaluates the
defining integral numerically as an independent check.

:func:`clock_prediction_variance` is the error of the best linear prediction of the clock
from noisy observations of it, for any such covariance: what a tracker that loses its
observations (ATC-10 Sec. 4.5.3, three satellites; Sec. 4.7) can at best extrapolate.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike
from scipy import integrate, special

from navcore._validate import (
    COUNT,
    NONNEGATIVE,
    POSITIVE,
    Range,
    check_public,
    require_in_range,
    require_integer,
    require_nonnegative,
    require_positive,
    require_symmetric_psd,
)
from navcore.trace import implements

__all__ = [
    "MAX_TAU_MAP_EPOCHS",
    "clock_covariance",
    "clock_increment_covariance",
    "clock_prediction_variance",
    "clock_state_tau_map",
    "mandelbrot_van_ness_constant",
    "mandelbrot_van_ness_constant_integral",
    "sample_clock_paths",
]


@implements("ATC10 G.5")
def mandelbrot_van_ness_constant(rho_h: float) -> float:
    r""":math:`V_0 = 1 / (\Gamma(2 \rho + 1) \sin(\pi \rho))` (ATC-10 Eq. G.5), for
    :math:`0 < \rho < 1` (:math:`\rho` is ``rho_h``).

    Parameters
    ----------
    rho_h : float
        Exponent, strictly in (0, 1).

    Returns
    -------
    float
        :math:`V_0` (dimensionless).

    Raises
    ------
    ValueError
        If ``rho_h`` is not strictly between 0 and 1.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972),
    Appendix G, Eq. (G.5); Mandelbrot & Van Ness, SIAM Review 10 (1968).

    Examples
    --------
    >>> round(float(mandelbrot_van_ness_constant(0.5)), 12)
    1.0
    """
    require_in_range("rho_h", rho_h, 0.0, 1.0)
    if rho_h in (0.0, 1.0):
        raise ValueError("rho_h must lie strictly between 0 and 1")
    return float(1.0 / (special.gamma(2.0 * rho_h + 1.0) * math.sin(math.pi * rho_h)))


@implements("ATC10 G.5")
def mandelbrot_van_ness_constant_integral(rho_h: float) -> float:
    r""":math:`V_0` from its defining integral (ATC-10 Eq. G.5, corrected integrand).

    .. math::

        V_0 &= \frac{1/(2 \rho) + I}{\Gamma(\rho + 1/2)^2}, \\
        I &= \int_0^\infty \left((1 + s)^{\rho - 1/2} - s^{\rho - 1/2}\right)^2 ds

    with :math:`\rho` = ``rho_h``. Numerical quadrature (``scipy.integrate.quad``), the
    independent oracle for
    :func:`mandelbrot_van_ness_constant`.

    Parameters
    ----------
    rho_h : float
        Exponent, in (0, 1).

    Returns
    -------
    float
        :math:`V_0` (dimensionless).

    Raises
    ------
    ValueError
        If ``rho_h`` is outside [0, 1].

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Appendix G, Eq. (G.5).

    Examples
    --------
    >>> round(float(mandelbrot_van_ness_constant_integral(0.7)), 6)
    0.995088
    >>> round(mandelbrot_van_ness_constant(0.7), 6)
    0.995088
    """
    require_in_range("rho_h", rho_h, 0.0, 1.0)
    e = rho_h - 0.5

    def f(s: float) -> float:
        return ((1.0 + s) ** e - s**e) ** 2

    a, _ = integrate.quad(f, 0.0, 1.0, limit=200, epsabs=1e-13, epsrel=1e-11)
    # [1, S] in u = ln s (the integrand decays like s^(2 rho - 3)), then an analytic tail from the
    # expansion (1+s)^e - s^e = s^e [e/s + e(e-1)/(2 s^2) + ...].
    big = 1.0e4
    b, _ = integrate.quad(lambda u: f(math.exp(u)) * math.exp(u), 0.0, math.log(big), limit=200, epsrel=1e-11)
    if e != 0.0:
        a2 = e * (e - 1.0) / 2.0
        b += e**2 * big ** (2 * e - 1) / (1 - 2 * e) + 2 * e * a2 * big ** (2 * e - 2) / (2 - 2 * e)
    return (1.0 / (2.0 * rho_h) + a + b) / special.gamma(rho_h + 0.5) ** 2


@implements("ATC10 Sec. 4.3", "ATC10 4.3.1b")
def clock_covariance(
    n_epochs: int, sigma1: float, sigma2: float, rho_h: float = 1.0, tau_bar: float = 0.0
) -> np.ndarray:
    r"""Second moments :math:`E[(\tau_n - \tau_0)(\tau_m - \tau_0)]`, :math:`n, m = 1, \dots, N`
    with :math:`N` = ``n_epochs`` (ATC-10 Sec. 4.3).

    ``tau_bar = 0`` gives the covariance; a nonzero ``tau_bar`` (:math:`\bar\tau`) adds the mean
    product :math:`\bar\tau^2 m n`. ``rho_h`` (:math:`\rho`) lies in (0, 1]; :math:`\rho = 1` is
    the random-frequency-offset limit.

    Parameters
    ----------
    n_epochs : int
        Number of epochs (``>= 1``).
    sigma1 : float
        Standard deviation of the random-walk increments (a time unit, ``>= 0``).
    sigma2 : float
        Scale of the fractional-Brownian part (same unit, ``>= 0``).
    rho_h : float, default 1.0
        Hurst-like exponent, in (0, 1].
    tau_bar : float, default 0.0
        Mean emission interval (same unit).

    Returns
    -------
    (n_epochs, n_epochs) ndarray
        Second moments, time unit squared.

    Raises
    ------
    ValueError
        If ``n_epochs`` is not a positive integer, ``sigma1`` or ``sigma2`` is negative or
        ``rho_h`` is not in
        (0, 1].

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 4.3 and Eq. (4.3.1b).

    Examples
    --------
    >>> clock_covariance(3, 1.0, 1.0).tolist()
    [[2.0, 3.0, 4.0], [3.0, 6.0, 8.0], [4.0, 8.0, 12.0]]
    """
    n_epochs = require_integer("n_epochs", n_epochs, minimum=1)
    require_nonnegative("sigma1", sigma1)
    require_nonnegative("sigma2", sigma2)
    require_in_range("rho_h", rho_h, 0.0, 1.0)
    if rho_h == 0.0:
        raise ValueError("rho_h must be > 0")
    n = np.arange(1, n_epochs + 1, dtype=float)
    m, k = np.meshgrid(n, n, indexing="ij")
    h2 = 2.0 * rho_h
    fbm = 0.5 * (m**h2 + k**h2 - np.abs(m - k) ** h2)
    return sigma1**2 * np.minimum(m, k) + sigma2**2 * fbm + tau_bar**2 * m * k


@implements("ATC10 4.5.23", "ATC10 4.3.1")
def clock_increment_covariance(n_epochs: int, sigma0: float) -> np.ndarray:
    r"""Covariance of the increments :math:`\Delta_n` for the Eq. 4.3.1 model.

    :math:`2 \sigma_0^2` on the diagonal, :math:`\sigma_0^2` off it.

    Parameters
    ----------
    n_epochs : int
        Number of increments (``>= 1``).
    sigma0 : float
        Standard deviation :math:`\sigma_0` of the clock increments :math:`w_n` and of
        :math:`A` (a time unit, ``>= 0``).

    Returns
    -------
    (n_epochs, n_epochs) ndarray
        Covariance, time unit squared.

    Raises
    ------
    ValueError
        If ``n_epochs`` is not a positive integer or ``sigma0`` negative.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.23).

    Examples
    --------
    >>> clock_increment_covariance(2, 3.0).tolist()
    [[18.0, 9.0], [9.0, 18.0]]
    """
    n_epochs = require_integer("n_epochs", n_epochs, minimum=1)
    require_nonnegative("sigma0", sigma0)
    return sigma0**2 * (np.ones((n_epochs, n_epochs)) + np.eye(n_epochs))


#: Largest ``n_max`` of :func:`clock_state_tau_map`: its map holds ``(n_max + 1)^2`` floats
#: (80 MB at this bound) and its loop costs ``n_max^2`` operations; Sec. 4.5 tracks a few
#: hundred epochs.
MAX_TAU_MAP_EPOCHS = 3_000


@implements("ATC10 4.5.9")
def clock_state_tau_map(n_max: int) -> np.ndarray:
    r"""Clock offsets :math:`\tau_n` of the state model Eq. 4.5.9 as a linear map of the draws.

    The state :math:`(\tau_n, \alpha_n)` starts at :math:`\tau_0 = 0` with :math:`\alpha_0`
    free and evolves as

    .. math::

        \begin{pmatrix} \tau_n \\ \alpha_n \end{pmatrix}
        = \begin{pmatrix} 2 & 1 \\ -1 & 0 \end{pmatrix}
          \begin{pmatrix} \tau_{n-1} \\ \alpha_{n-1} \end{pmatrix}
        + \begin{pmatrix} 1 \\ -1 \end{pmatrix} w_n ,

    propagated exactly for :math:`n = 1, \ldots, n_{\max}`. Row :math:`n` of the result holds
    the coefficients of :math:`(\alpha_0, w_1, \ldots, w_{n_{\max}})` in :math:`\tau_n`, so
    with :math:`\alpha_0` and the :math:`w_n` independent of variance :math:`\sigma_0^2` the
    covariance of the offsets is :math:`\sigma_0^2 M M^\mathsf{T}`, which Sec. 4.5.2 states
    is that of Eq. 4.3.1.

    Parameters
    ----------
    n_max : int
        Last epoch (``>= 0``).

    Returns
    -------
    (n_max + 1, n_max + 1) ndarray
        Row ``n`` (``n = 0..n_max``): the coefficients of ``(alpha_0, w_1, ..., w_n_max)`` in
        :math:`\tau_n`; row 0 is zero.

    Raises
    ------
    TypeError
        If ``n_max`` is not an integer.
    ValueError
        If ``n_max`` is negative or above :data:`MAX_TAU_MAP_EPOCHS`.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.9) and Sec. 4.5.2.

    Examples
    --------
    >>> clock_state_tau_map(3).tolist()
    [[0.0, 0.0, 0.0, 0.0], [1.0, 1.0, 0.0, 0.0], [2.0, 1.0, 1.0, 0.0], [3.0, 1.0, 1.0, 1.0]]
    """
    n_max = require_integer("n_max", n_max, minimum=0)
    if n_max > MAX_TAU_MAP_EPOCHS:
        raise ValueError(
            f"n_max must be at most {MAX_TAU_MAP_EPOCHS} (the map holds (n_max + 1)^2 coefficients), "
            f"got {n_max}"
        )
    T = np.array([[2.0, 1.0], [-1.0, 0.0]])
    B = np.array([1.0, -1.0])
    coef = np.zeros((n_max + 1, n_max + 1))
    state = np.zeros((2, n_max + 1))
    state[1, 0] = 1.0
    for n in range(1, n_max + 1):
        e = np.zeros(n_max + 1)
        e[n] = 1.0
        state = T @ state + np.outer(B, e)
        coef[n] = state[0]
    return coef


def clock_prediction_variance(covariance: ArrayLike, noise_variance: float, n_observed: int) -> float:
    r"""Error variance of the best linear prediction of the last epoch from noisy earlier ones.

    With the clock's second moments :math:`C` over epochs :math:`1, \dots, N` and the
    observations :math:`z_n = \tau_n + v_n`, :math:`n = 1, \dots, N_o` (white noise of variance
    :math:`r`), the linear minimum-mean-square-error predictor of :math:`\tau_N` has the error
    variance

    .. math::

        C_{NN} - \mathbf c^T (C_{oo} + r I)^{-1} \mathbf c, \qquad
        \mathbf c = (C_{nN})_{n \le N_o},

    with :math:`C_{oo}` the block of the observed epochs. :math:`N - N_o` is how far ahead the
    clock is extrapolated.

    Parameters
    ----------
    covariance : (N, N) array_like
        Second moments of the clock over the epochs (e.g. :func:`clock_covariance`), time
        unit squared; symmetric positive semi-definite.
    noise_variance : float
        Variance :math:`r` of each observation's noise (same unit, ``> 0``).
    n_observed : int
        Number :math:`N_o` of observed epochs, ``1 <= n_observed < N``.

    Returns
    -------
    float
        The prediction error variance of the last epoch, time unit squared.

    Raises
    ------
    ValueError
        If ``covariance`` is not a square symmetric positive semi-definite matrix,
        ``noise_variance`` is not positive or ``n_observed`` is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Secs. 4.5.3 and 4.7.

    Examples
    --------
    A random walk of unit steps observed once with unit noise, predicted one step ahead:
    the filtered variance 1/2 plus one step.

    >>> clock_prediction_variance(clock_covariance(2, 1.0, 0.0), 1.0, 1)
    1.5
    """
    C = require_symmetric_psd("covariance", covariance)
    require_positive("noise_variance", noise_variance)
    n_last = require_integer("n_observed", n_observed, minimum=1)
    if n_last >= C.shape[0]:
        raise ValueError(f"n_observed must be less than the {C.shape[0]} epochs of covariance, got {n_last}")
    Czz = C[:n_last, :n_last] + noise_variance * np.eye(n_last)
    c = C[:n_last, -1]
    return float(C[-1, -1] - c @ np.linalg.solve(Czz, c))


def sample_clock_paths(
    n_epochs: int,
    n_paths: int,
    sigma1: float,
    sigma2: float,
    rho_h: float = 1.0,
    seed: int = 0,
) -> np.ndarray:
    r"""Seeded sample paths of :math:`\tau_n - \tau_0 - n \bar\tau`, :math:`n = 1, \dots, N`
    with :math:`N` = ``n_epochs``.

    Exact Gaussian sampling by Cholesky factorisation of :func:`clock_covariance` (a tiny
    diagonal jitter keeps the factorisation stable for the rank-deficient ``rho_h = 1`` case).


    Parameters
    ----------
    n_epochs : int
        Number of epochs (``>= 1``).
    n_paths : int
        Number of paths (``>= 1``).
    sigma1 : float
        Standard deviation of the random-walk increments (a time unit, ``>= 0``).
    sigma2 : float
        Scale of the fractional-Brownian part (same unit, ``>= 0``).
    rho_h : float, default 1.0
        Exponent, in (0, 1].
    seed : int, default 0
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    (n_paths, n_epochs) ndarray
        Clock deviations, time unit.

    Raises
    ------
    ValueError
        As :func:`clock_covariance`, or if ``n_paths`` is not a positive integer.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 4.3.

    Examples
    --------
    >>> sample_clock_paths(5, 3, 1.0, 0.5, seed=2).shape
    (3, 5)
    """
    n_paths = require_integer("n_paths", n_paths, minimum=1)
    C = clock_covariance(n_epochs, sigma1, sigma2, rho_h)
    jitter = 1e-12 * float(np.trace(C)) / C.shape[0]
    L = np.linalg.cholesky(C + jitter * np.eye(C.shape[0]))
    rng = np.random.default_rng(seed)
    return rng.standard_normal((n_paths, C.shape[0])) @ L.T


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "n_epochs": COUNT,
        "n_paths": COUNT,
        "rho_h": Range(0.0, 1.0),
        "sigma0": NONNEGATIVE,
        "sigma1": NONNEGATIVE,
        "sigma2": NONNEGATIVE,
        "tau_bar": POSITIVE,
    },
    # the defining integral has 1/(2 rho): rho_h = 0 is the closed form's limit only
    mandelbrot_van_ness_constant_integral={"ranges": {"rho_h": Range(0.0, 1.0, low_open=True)}},
)
