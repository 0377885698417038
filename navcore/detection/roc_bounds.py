r"""Bounds to the receiver operating characteristic in multiple-access noise (ATC-10 Secs. 3.5-3.8).

The detector decides "signal present" when the matched-filter sample :math:`y = R + n`
exceeds a threshold :math:`\theta`, with :math:`R = 1` (signal at its peak) or 0. Thus

.. math::

    p_f &= P(n \ge \theta), \\
    1 - p_d &= P(n < \theta - 1) = P(-n > 1 - \theta).

All bounds take a *cumulant generating function* object with ``cgf(s)``, ``cgf_d1(s)`` and
``cgf_d2(s)`` (e.g. :class:`navcore.detection.multiple_access.MultipleAccessNoise`) and
return natural logarithms of probabilities, so that exponents of hundreds stay finite.

* :func:`chernoff_log_tail`: :math:`\ln P(S \ge t) \le \min_{r \ge 0} [\mu(r) - r t]`
  (Eqs. 3.5.5-3.5.13), with the optimum found by bracketing and Brent's method on
  :math:`\mu'(r) = t`.
* :func:`gallager_log_tail_lower`: the tilted-Chebyshev lower bound that Eq. (3.5.14)
  intends, as corrected:
  :math:`\ln P(S \ge t) \ge -\ln 2 + \mu(r_1) - r_1 t - 2 r_1 \sqrt{2 \mu''(r_1)}`, where
  :math:`\mu'(r_1) - \sqrt{2 \mu''(r_1)} = t`.
* closed forms for the two-point (quasi-optimal) density, Eqs. (3.7.20)-(3.7.27);
* the Gaussian ROC (3.8.3), its Chernoff bound (3.8.7)-(3.8.9) and
  :math:`\mathrm{Exp}(N, \tau/\alpha, \mathrm{Exp}_g)` (3.8.16);
* :func:`best_pf_at_pd`: the operating point of a tabulated ROC, the smallest :math:`p_f`
  among the thresholds that reach a required :math:`p_d` (how Sec. 3.8 compares detectors).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import special

from navcore._validate import (
    NONNEGATIVE,
    POSITIVE,
    Range,
    as_finite_array,
    check_public,
    require_positive,
    require_probability,
)
from navcore.trace import implements

__all__ = [
    "CumulantGenerating",
    "NegatedCGF",
    "TailBound",
    "best_pf_at_pd",
    "best_pf_index_at_pd",
    "chernoff_log_tail",
    "chernoff_log_tails",
    "exponent_from_gaussian_exponent",
    "exponent_from_gaussian_exponent_large_n",
    "gallager_log_tail_lower",
    "gallager_log_tails_lower",
    "gated_cosh_log_curvature",
    "gaussian_chernoff_exponent",
    "gaussian_roc",
    "quasi_optimal_amplitude",
    "quasi_optimal_chernoff_parameter",
    "quasi_optimal_exponent",
    "quasi_optimal_exponent_approx",
    "roc_lower_bound",
    "roc_upper_bound",
]

FloatArray = NDArray[np.float64]


@runtime_checkable
class CumulantGenerating(Protocol):
    def cgf(self, s: ArrayLike) -> FloatArray: ...
    def cgf_d1(self, s: ArrayLike) -> FloatArray: ...
    def cgf_d2(self, s: ArrayLike) -> FloatArray: ...


@dataclass(frozen=True)
class NegatedCGF:
    r"""The CGF of :math:`-S` from that of :math:`S`: :math:`\tilde\mu(g) = \mu(-g)` (used for
    the :math:`p_d` side, Eq. 3.5.9).

    Attributes
    ----------
    base : CumulantGenerating
        The CGF of S.
    """

    base: CumulantGenerating

    def cgf(self, s: ArrayLike) -> FloatArray:
        return self.base.cgf(-np.asarray(s, dtype=float))

    def cgf_d1(self, s: ArrayLike) -> FloatArray:
        return -self.base.cgf_d1(-np.asarray(s, dtype=float))

    def cgf_d2(self, s: ArrayLike) -> FloatArray:
        return self.base.cgf_d2(-np.asarray(s, dtype=float))


@dataclass(frozen=True)
class TailBound:
    """A bound on ln P(S >= t) with the tilt parameter that produced it.

    Attributes
    ----------
    log_p : float
        Natural log of the bound on ``P(S >= t)``.
    parameter : float
        The tilt that produced it.
    """

    log_p: float
    parameter: float


def _solve_increasing(fun, targets: ArrayLike, r_max: float = 1e7) -> FloatArray:
    """Vectorised root of fun(r) = target over r >= 0, for fun increasing (at least up to the root).

    r = 0 where fun(0) >= target; otherwise the first doubling bracket [r, 2r] (from 1e-3)
    that crosses the target, then 70 bisection steps (relative precision 2^-70). NaN where
    fun stays below the target up to ``r_max``.
    """
    t = np.atleast_1d(np.asarray(targets, dtype=float))
    at_zero = fun(np.zeros_like(t)) >= t
    lo = np.zeros_like(t)
    hi = np.full_like(t, 1e-3)
    open_ = ~at_zero
    bracketed = np.zeros_like(t, dtype=bool)
    while np.any(open_) and np.min(hi[open_]) <= r_max:
        fh = fun(np.where(open_, hi, 1e-3))
        cross = open_ & np.isfinite(fh) & (fh >= t)
        bracketed |= cross
        open_ &= ~cross & np.isfinite(fh) & (hi <= r_max)
        lo = np.where(open_, hi, lo)
        hi = np.where(open_, 2.0 * hi, hi)
    work = bracketed.copy()
    a, b = np.where(work, lo, 0.0), np.where(work, hi, 1.0)
    for _ in range(70):
        mid = 0.5 * (a + b)
        below = fun(mid) < t
        a = np.where(below, mid, a)
        b = np.where(below, b, mid)
    out = np.where(at_zero, 0.0, np.where(bracketed, 0.5 * (a + b), np.nan))
    return out


def chernoff_log_tails(cgf: CumulantGenerating, t: ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Chernoff bounds on ``ln P(S >= t)`` for many thresholds at once (ATC-10 Eqs. 3.5.5-3.5.7).

    The vectorised form of :func:`chernoff_log_tail`: for each threshold the optimal tilt
    ``r* >= 0`` solves :math:`\mu'(r) = t` (``r* = 0``, a bound of 1, for ``t <= E S``) and the bound
    is :math:`\mu(r^*) - r^* t`. Where :math:`\mu'(r)` never reaches ``t`` the tail is empty: the bound is
    ``-inf`` and the tilt ``inf``.

    Parameters
    ----------
    cgf : CumulantGenerating
        Object with ``cgf(s)``, ``cgf_d1(s)`` and ``cgf_d2(s)`` of the noise sum S.
    t : array_like
        Thresholds (units of S); finite. A scalar is treated as one threshold.

    Returns
    -------
    log_p : ndarray
        Natural log of the bound on ``P(S >= t)`` for each threshold (1-D, ``<= 0``).
    r : ndarray
        The optimal tilt ``r*`` for each threshold (inverse units of S).

    Raises
    ------
    TypeError
        If ``cgf`` does not provide the three cumulant methods, or ``t`` is not numeric.
    ValueError
        If ``t`` holds NaN or infinity.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (3.5.5)-(3.5.7).

    Examples
    --------
    >>> from navcore.detection.multiple_access import MultipleAccessNoise, UniformDensity
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> log_p, r = chernoff_log_tails(noise, [0.0, 0.5])
    >>> [round(float(v), 4) for v in log_p], [round(float(v), 4) for v in r]
    ([0.0, -0.2046], [0.0, 0.7969])
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    r = _solve_increasing(cgf.cgf_d1, t)
    found = np.isfinite(r)
    rr = np.where(found, r, 0.0)
    logp = np.where(found, cgf.cgf(rr) - rr * t, -np.inf)
    return logp, np.where(found, r, np.inf)


def gallager_log_tails_lower(cgf: CumulantGenerating, t: ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Lower bounds on ``ln P(S >= t)`` for many thresholds at once (ATC-10 Eq. 3.5.14 as corrected).

    The vectorised form of :func:`gallager_log_tail_lower`: for each threshold the tilt ``r1``
    solves :math:`\mu'(r_1) - \sqrt{2 \mu''(r_1)} = t` and the bound is
    :math:`-\ln 2 + \mu(r_1) - r_1 t - 2 r_1 \sqrt{2 \mu''(r_1)}` (erratum E3-1: the printed exponent mixes
    the Chernoff optimum with ``r1``, omits the logarithm and adds the last term). Where no
    tilt reaches ``t`` the bound is ``-inf`` and the tilt ``inf``.

    Parameters
    ----------
    cgf : CumulantGenerating
        Object with ``cgf(s)``, ``cgf_d1(s)`` and ``cgf_d2(s)`` of the noise sum S.
    t : array_like
        Thresholds (units of S); finite. A scalar is treated as one threshold.

    Returns
    -------
    log_p : ndarray
        Natural log of the lower bound on ``P(S >= t)`` for each threshold (1-D).
    r1 : ndarray
        The tilt for each threshold (inverse units of S).

    Raises
    ------
    TypeError
        If ``cgf`` does not provide the three cumulant methods, or ``t`` is not numeric.
    ValueError
        If ``t`` holds NaN or infinity.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.5.14).

    Examples
    --------
    >>> from navcore.detection.multiple_access import MultipleAccessNoise, UniformDensity
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> lower, _ = gallager_log_tails_lower(noise, [0.5])
    >>> upper, _ = chernoff_log_tails(noise, [0.5])
    >>> bool(lower[0] <= upper[0])
    True
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))

    def lhs(r: FloatArray) -> FloatArray:
        return cgf.cgf_d1(r) - np.sqrt(2.0 * cgf.cgf_d2(r))

    r1 = _solve_increasing(lhs, t)
    found = np.isfinite(r1)
    rr = np.where(found, r1, 0.0)
    logp = -np.log(2.0) + cgf.cgf(rr) - rr * t - 2.0 * rr * np.sqrt(2.0 * cgf.cgf_d2(rr))
    return np.where(found, logp, -np.inf), np.where(found, r1, np.inf)


@implements("ATC10 3.5.5", "ATC10 3.5.6", "ATC10 3.5.7")
def chernoff_log_tail(cgf: CumulantGenerating, t: float) -> TailBound:
    r"""Chernoff bound :math:`\ln P(S \ge t) \le \mu(r^*) - r^* t`, :math:`r^* \ge 0` optimal
    (ATC-10 Eqs. 3.5.5-3.5.7).

    :math:`\mu` is convex, so :math:`\mu(r) - r t` is minimised where :math:`\mu'(r) = t`; for
    :math:`t \le E S` the minimum is at :math:`r = 0` (the bound is 1). If :math:`\mu'(r)`
    never reaches :math:`t` the tail is empty (``-inf``).

    Parameters
    ----------
    cgf : CumulantGenerating
        Object with ``cgf(s)``, ``cgf_d1(s)`` and ``cgf_d2(s)`` of the noise sum S.
    t : float
        Threshold (units of S).

    Returns
    -------
    TailBound
        ``log_p``, the natural log of the bound, and the optimal tilt ``parameter``
        :math:`r^*`.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (3.5.5)-(3.5.7).

    Examples
    --------
    >>> from navcore.detection.multiple_access import MultipleAccessNoise, UniformDensity
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> b = chernoff_log_tail(noise, 0.5)
    >>> round(b.log_p, 4), round(b.parameter, 4)
    (-0.2046, 0.7969)
    """
    logp, r = chernoff_log_tails(cgf, [t])
    return TailBound(float(logp[0]), float(r[0]))


@implements("ATC10 3.5.14")
def gallager_log_tail_lower(cgf: CumulantGenerating, t: float) -> TailBound:
    r"""Tilted-Chebyshev lower bound on ``ln P(S >= t)`` (Eq. 3.5.14 as corrected, erratum E3-1).

    Tilt by r1 chosen so that :math:`\mu'(r_1) - \sqrt{2 \mu''(r_1)} = t`. Under the tilted law S has
    mean :math:`\mu'(r_1)` and variance :math:`\mu''(r_1)`; by Chebyshev it lies in
    :math:`(t, t + 2 \sqrt{2 \mu''})` with probability >= 1/2, and there the likelihood ratio is at
    least :math:`\exp(\mu(r_1) - r_1 (t + 2 \sqrt{2 \mu''(r_1)}))`.

    Parameters
    ----------
    cgf : CumulantGenerating
        Object with ``cgf(s)``, ``cgf_d1(s)`` and ``cgf_d2(s)`` of the noise sum S.
    t : float
        Threshold (units of S).

    Returns
    -------
    TailBound
        ``log_p``, the natural log of the lower bound, and the tilt ``parameter`` r1.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.5.14) and erratum E3-1.

    Examples
    --------
    >>> from navcore.detection.multiple_access import MultipleAccessNoise, UniformDensity
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> lower = gallager_log_tail_lower(noise, 0.5).log_p
    >>> round(lower, 4), lower <= chernoff_log_tail(noise, 0.5).log_p
    (-9.1678, True)
    """
    logp, r = gallager_log_tails_lower(cgf, [t])
    return TailBound(float(logp[0]), float(r[0]))


@implements("ATC10 3.5.13")
def roc_upper_bound(cgf: CumulantGenerating, theta: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Worst-case ROC (Eq. 3.5.13): ln upper bounds to ``p_f`` and to ``1 - p_d``.

    Parameters
    ----------
    cgf : CumulantGenerating
        Object with ``cgf(s)``, ``cgf_d1(s)`` and ``cgf_d2(s)`` of the noise sum S.
    theta : array_like
        Thresholds (relative to the unit peak).

    Returns
    -------
    log_pf : ndarray
        ln of the upper bound to ``p_f``.
    log_miss : ndarray
        ln of the upper bound to ``1 - p_d``.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.5.13).

    Examples
    --------
    >>> from navcore.detection.multiple_access import MultipleAccessNoise, UniformDensity
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> lpf, lmiss = roc_upper_bound(noise, [0.5])
    >>> round(float(lpf[0]), 4)
    -0.2046
    """
    th = np.atleast_1d(np.asarray(theta, dtype=float))
    return chernoff_log_tails(cgf, th)[0], chernoff_log_tails(NegatedCGF(cgf), 1.0 - th)[0]


@implements("ATC10 3.5.14")
def roc_lower_bound(cgf: CumulantGenerating, theta: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Best-case ROC (Eq. 3.5.14 corrected): ln lower bounds to ``p_f`` and to ``1 - p_d``.

    Parameters
    ----------
    cgf : CumulantGenerating
        Object with ``cgf(s)``, ``cgf_d1(s)`` and ``cgf_d2(s)`` of the noise sum S.
    theta : array_like
        Thresholds (relative to the unit peak).

    Returns
    -------
    log_pf : ndarray
        ln of the lower bound to ``p_f``.
    log_miss : ndarray
        ln of the lower bound to ``1 - p_d``.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.5.14) and erratum E3-1.

    Examples
    --------
    >>> from navcore.detection.multiple_access import MultipleAccessNoise, UniformDensity
    >>> noise = MultipleAccessNoise(100, 0.01, UniformDensity(0.3))
    >>> lpf, lmiss = roc_lower_bound(noise, [0.5])
    >>> round(float(lpf[0]), 4)
    -9.1678
    """
    th = np.atleast_1d(np.asarray(theta, dtype=float))
    return gallager_log_tails_lower(cgf, th)[0], gallager_log_tails_lower(NegatedCGF(cgf), 1.0 - th)[0]


@implements("ATC10 3.7.1")
def quasi_optimal_amplitude(power: float, n_aircraft: int, tau_over_alpha: float) -> float:
    r""":math:`a = \sqrt{p \alpha / ((N-1)\, 2 \tau)}`: the atoms +-a of the optimal density (Eq. 3.7.1).

    Parameters
    ----------
    power : float
        Total cross-term noise power ``p`` (``> 0``).
    n_aircraft : int
        Number of aircraft :math:`N` (``>= 2``).
    tau_over_alpha : float
        :math:`\tau/\alpha` (dimensionless).

    Returns
    -------
    float
        Atom amplitude ``a`` (relative to the unit peak).

    Raises
    ------
    ValueError
        If ``power`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.7.1).

    Examples
    --------
    >>> round(quasi_optimal_amplitude(0.05, 100, 0.01), 6)
    0.15891
    """
    require_positive("power", power)
    return float(np.sqrt(power / ((n_aircraft - 1) * 2.0 * tau_over_alpha)))


@implements("ATC10 3.7.23")
def quasi_optimal_chernoff_parameter(
    theta: ArrayLike, power: float, n_aircraft: int, tau_over_alpha: float
) -> FloatArray:
    r"""Closed-form optimal :math:`\rho` for the two-point density (Eq. 3.7.23, with
    :math:`1 - 2 \tau/\alpha`).

    Solves :math:`A \sinh x - B \cosh x = C` with :math:`x = \rho a`, :math:`A = (N-1) q a`,
    :math:`B = \theta q`, :math:`C = \theta (1 - q)`:
    :math:`x = \operatorname{asinh}(C / \sqrt{A^2 - B^2}) + \operatorname{atanh}(B / A)`.

    Parameters
    ----------
    theta : array_like
        Detection threshold, relative to the unit signal peak.
    power : float
        Noise power ``p`` per interferer, relative to the unit peak (``> 0``).
    n_aircraft : int
        Number of aircraft :math:`N`.
    tau_over_alpha : float
        Pulse duration over repetition period, :math:`\tau/\alpha` (dimensionless).

    Returns
    -------
    ndarray
        Optimal Chernoff parameter :math:`\rho`.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.7.23).

    Examples
    --------
    >>> round(float(quasi_optimal_chernoff_parameter(0.5, 0.05, 100, 0.01)), 4)
    7.9187
    """
    th = np.asarray(theta, dtype=float)
    q = 2.0 * tau_over_alpha
    a = quasi_optimal_amplitude(power, n_aircraft, tau_over_alpha)
    big_a = (n_aircraft - 1) * q * a
    big_b = th * q
    x = np.arcsinh(th * (1.0 - q) / np.sqrt(big_a**2 - big_b**2)) + np.arctanh(big_b / big_a)
    return x / a


@implements("ATC10 3.7.21", "ATC10 3.7.25")
def quasi_optimal_exponent(
    theta: ArrayLike, power: float, n_aircraft: int, tau_over_alpha: float
) -> FloatArray:
    r""":math:`\mathrm{Exp}_f = \rho \theta - (N-1) \ln(1 - q + q \cosh(\rho a))` at the optimal
    :math:`\rho` (Eqs. 3.7.21, 3.7.24).

    :math:`\mathrm{Exp}_d` is the same function of :math:`1 - \theta` (Eq. 3.7.25).

    Parameters
    ----------
    theta : array_like
        Detection threshold, relative to the unit signal peak.
    power : float
        Noise power ``p`` per interferer, relative to the unit peak (``> 0``).
    n_aircraft : int
        Number of aircraft :math:`N`.
    tau_over_alpha : float
        Pulse duration over repetition period, :math:`\tau/\alpha` (dimensionless).

    Returns
    -------
    ndarray
        Chernoff exponent of the false-alarm probability, nats.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (3.7.21), (3.7.24)-(3.7.25).

    Examples
    --------
    >>> round(float(quasi_optimal_exponent(0.5, 0.05, 100, 0.01)), 4)
    2.1895
    """
    th = np.asarray(theta, dtype=float)
    q = 2.0 * tau_over_alpha
    a = quasi_optimal_amplitude(power, n_aircraft, tau_over_alpha)
    rho = quasi_optimal_chernoff_parameter(th, power, n_aircraft, tau_over_alpha)
    x = rho * a
    return rho * th - (n_aircraft - 1) * np.log1p(
        2.0 * q * np.sinh(0.5 * x) ** 2
    )  # cosh x - 1 = 2 sinh^2(x/2)


def quasi_optimal_exponent_approx(
    theta: ArrayLike, power: float, n_aircraft: int, tau_over_alpha: float
) -> FloatArray:
    r"""The large-N approximation (3.7.26)/(3.7.27).

    N for N-1, the atanh term and ``1 - q`` in the ratio dropped:
    :math:`\mathrm{Exp}_f \approx \theta \sqrt{N q / p}\, \operatorname{asinh}(u) - N \ln(1 - q + q \sqrt{1 +
    u^2})`,
    :math:`u = \theta / \sqrt{N q p}`.

    Parameters
    ----------
    theta : array_like
        Detection threshold, relative to the unit signal peak.
    power : float
        Noise power ``p`` per interferer, relative to the unit peak (``> 0``).
    n_aircraft : int
        Number of aircraft :math:`N`.
    tau_over_alpha : float
        Pulse duration over repetition period, :math:`\tau/\alpha` (dimensionless).

    Returns
    -------
    ndarray
        Approximate exponent, nats.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (3.7.26)-(3.7.27).

    Examples
    --------
    >>> round(float(quasi_optimal_exponent_approx(0.5, 0.05, 100, 0.01)), 4)
    2.1912
    """
    th = np.asarray(theta, dtype=float)
    q = 2.0 * tau_over_alpha
    u = th / np.sqrt(n_aircraft * q * power)
    return th * np.sqrt(n_aircraft * q / power) * np.arcsinh(u) - n_aircraft * np.log1p(
        q * (np.sqrt(1.0 + u**2) - 1.0)
    )


def _roc_points(p_f: ArrayLike, p_miss: ArrayLike, pd_min: float) -> tuple[FloatArray, FloatArray]:
    """Check a tabulated ROC and a required detection probability at the boundary."""
    pf = as_finite_array("p_f", p_f, ndim=1)
    miss = as_finite_array("p_miss", p_miss, ndim=1)
    if pf.size == 0 or pf.shape != miss.shape:
        raise ValueError(
            f"p_f and p_miss must be non-empty and of one length, got {pf.shape} and {miss.shape}"
        )
    require_probability("p_f", pf)
    require_probability("p_miss", miss)
    require_probability("pd_min", pd_min)
    return pf, miss


def best_pf_index_at_pd(p_f: ArrayLike, p_miss: ArrayLike, pd_min: float) -> int | None:
    r"""Index of the threshold with the smallest :math:`p_f` among those with :math:`p_d \ge` ``pd_min``.

    A tabulated ROC lists, per threshold, the false-alarm probability :math:`p_f` and the miss
    probability :math:`1 - p_d`. The operating point for a required detection probability is
    the threshold that reaches it with the fewest false alarms (ATC-10 Sec. 3.8 compares
    detectors at :math:`p_d` = 0.9 this way).

    Parameters
    ----------
    p_f : array_like
        False-alarm probability at each threshold, in [0, 1].
    p_miss : array_like
        Miss probability :math:`1 - p_d` at each threshold, in [0, 1]; same length.
    pd_min : float
        Required detection probability, in [0, 1].

    Returns
    -------
    int or None
        The index, or ``None`` when no threshold reaches ``pd_min``.

    Raises
    ------
    ValueError
        If a probability is outside [0, 1] or the arrays are empty or of different lengths.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.8.

    Examples
    --------
    >>> best_pf_index_at_pd([0.3, 0.1, 0.01], [0.01, 0.05, 0.4], 0.9)
    1
    >>> best_pf_index_at_pd([0.3, 0.1], [0.2, 0.5], 0.9) is None
    True
    """
    pf, miss = _roc_points(p_f, p_miss, pd_min)
    ok = np.flatnonzero(miss <= 1.0 - pd_min)
    return int(ok[np.argmin(pf[ok])]) if ok.size else None


def best_pf_at_pd(p_f: ArrayLike, p_miss: ArrayLike, pd_min: float) -> float:
    r"""The smallest :math:`p_f` over the thresholds with :math:`p_d \ge` ``pd_min``.

    Parameters
    ----------
    p_f : array_like
        False-alarm probability at each threshold, in [0, 1].
    p_miss : array_like
        Miss probability :math:`1 - p_d` at each threshold, in [0, 1]; same length.
    pd_min : float
        Required detection probability, in [0, 1].

    Returns
    -------
    float
        That :math:`p_f` (the one at :func:`best_pf_index_at_pd`), or NaN when no threshold
        reaches ``pd_min``.

    Raises
    ------
    ValueError
        As :func:`best_pf_index_at_pd`.

    Examples
    --------
    >>> best_pf_at_pd([0.3, 0.1, 0.01], [0.01, 0.05, 0.4], 0.9)
    0.1
    """
    j = best_pf_index_at_pd(p_f, p_miss, pd_min)
    return float("nan") if j is None else float(np.asarray(p_f, dtype=float)[j])


@implements("ATC10 3.8.3")
def gaussian_roc(theta: ArrayLike, power: float) -> tuple[FloatArray, FloatArray]:
    r""":math:`\mathrm{ROC}_g` (Eq. 3.8.3) in logs: :math:`(\ln p_f, \ln(1 - p_d))`.

    Parameters
    ----------
    theta : array_like
        Threshold (relative to the unit peak).
    power : float
        Gaussian noise power ``p`` (``> 0``).

    Returns
    -------
    log_pf : ndarray
        :math:`\ln p_f = \ln Q(\theta / \sqrt{p})`.
    log_miss : ndarray
        :math:`\ln(1 - p_d) = \ln Q((1 - \theta) / \sqrt{p})`.

    Raises
    ------
    ValueError
        If ``power`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.8.3).

    Examples
    --------
    >>> lpf, lmiss = gaussian_roc(0.5, 0.05)
    >>> round(float(lpf), 4), round(float(lmiss), 4)
    (-4.3682, -4.3682)
    """
    require_positive("power", power)
    th = np.asarray(theta, dtype=float)
    s = np.sqrt(power)
    return special.log_ndtr(-th / s), special.log_ndtr(-(1.0 - th) / s)


@implements("ATC10 3.8.8", "ATC10 3.8.5", "ATC10 3.8.6", "ATC10 3.8.7")
def gaussian_chernoff_exponent(threshold: ArrayLike, power: float) -> FloatArray:
    r""":math:`\mathrm{Exp}_{fg} = \theta^2/(2p)` (Eq. 3.8.8); the optimal tilt is
    :math:`\mu = \theta/p` (Eqs. 3.8.5-3.8.7).

    Parameters
    ----------
    threshold : array_like
        Threshold ``theta`` (relative to the unit peak).
    power : float
        Gaussian noise power ``p`` (``> 0``).

    Returns
    -------
    ndarray
        Chernoff exponent, nats.

    Raises
    ------
    ValueError
        If ``power`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (3.8.5)-(3.8.8).

    Examples
    --------
    >>> round(float(gaussian_chernoff_exponent(0.5, 0.05)), 6)
    2.5
    """
    require_positive("power", power)
    return np.asarray(threshold, dtype=float) ** 2 / (2.0 * power)


@implements("ATC10 3.8.16")
def exponent_from_gaussian_exponent(
    n_aircraft: ArrayLike, tau_over_alpha: ArrayLike, exp_g: ArrayLike
) -> FloatArray:
    r""":math:`\mathrm{Exp}(N, \tau/\alpha, \mathrm{Exp}_g)` of Eq. (3.8.16) (with
    :math:`\mathrm{Exp}_g/(N \tau/\alpha)`, erratum E3-9).

    .. math::

        \mathrm{Exp} &= \sqrt{4 N (\tau/\alpha) \mathrm{Exp}_g}\, \operatorname{asinh}\sqrt{u} \\
            &\quad - N \ln\left(1 - 2\tau/\alpha + (2\tau/\alpha) \sqrt{1 + u}\right),

    :math:`\theta` eliminated through :math:`\mathrm{Exp}_g = \theta^2/(2p)`.


    Parameters
    ----------
    n_aircraft : array_like
        Number of aircraft :math:`N`.
    tau_over_alpha : array_like
        :math:`\tau/\alpha` (dimensionless).
    exp_g : array_like
        Gaussian exponent :math:`\mathrm{Exp}_g` (nats).

    Returns
    -------
    ndarray
        Exponent of the quasi-optimal density, nats.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.8.16) and erratum E3-9.

    Examples
    --------
    >>> round(float(exponent_from_gaussian_exponent(100, 0.01, 2.5)), 4)
    2.1912
    """
    n = np.asarray(n_aircraft, dtype=float)
    r = np.asarray(tau_over_alpha, dtype=float)
    g = np.asarray(exp_g, dtype=float)
    u = g / (n * r)
    return np.sqrt(4.0 * n * r * g) * np.arcsinh(np.sqrt(u)) - n * np.log1p(
        2.0 * r * (np.sqrt(1.0 + u) - 1.0)
    )


def exponent_from_gaussian_exponent_large_n(
    n_aircraft: ArrayLike, tau_over_alpha: ArrayLike, exp_g: ArrayLike
) -> FloatArray:
    r"""First-order large-N expansion of (3.8.16): :math:`\mathrm{Exp}_g - \mathrm{Exp}_g^2 (1 - 6
    \tau/\alpha) / (12 N \tau/\alpha)`.

    Parameters
    ----------
    n_aircraft : array_like
        Number of aircraft :math:`N`.
    tau_over_alpha : array_like
        :math:`\tau/\alpha` (dimensionless).
    exp_g : array_like
        Gaussian exponent (nats).

    Returns
    -------
    ndarray
        Approximate exponent, nats.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.8.16) (expanded).

    Examples
    --------
    >>> round(float(exponent_from_gaussian_exponent_large_n(100, 0.01, 2.5)), 4)
    2.0104
    """
    n = np.asarray(n_aircraft, dtype=float)
    r = np.asarray(tau_over_alpha, dtype=float)
    g = np.asarray(exp_g, dtype=float)
    return g - g**2 * (1.0 - 6.0 * r) / (12.0 * n * r)


@implements("ATC10 3.7.15")
def gated_cosh_log_curvature(x: ArrayLike, q: float) -> FloatArray:
    r"""Second derivative in :math:`\beta` of :math:`\ln(1 - q + q \cosh\sqrt{\beta})` at
    :math:`\beta = x^2` (the convexity the proof of Theorem 3.2 invokes, ATC-10 Eq. 3.7.15).

    The proof of Theorem 3.2 needs :math:`\ln(1 - q + q \cosh(\rho \sqrt{\beta}))` convex in
    the power :math:`\beta` of one interferer; at :math:`\rho = 1` (the curvature at another
    :math:`\rho` is this one at :math:`x = \rho \sqrt{\beta}`, times :math:`\rho^4`) it is
    convex where this second derivative is positive. It is positive at the operating points and
    turns negative for large :math:`x`, where the function grows as :math:`\sqrt{\beta}`. The
    derivative is taken symbolically (sympy) and evaluated with mpmath, so :math:`\cosh`
    does not overflow at large :math:`x`.

    Parameters
    ----------
    x : array_like
        Points :math:`x = \sqrt{\beta}` (1-D, finite).
    q : float
        Probability that a cross term is non-zero, :math:`q = 2 \tau / \alpha`
        (``0 <= q <= 1``).

    Returns
    -------
    ndarray
        The second derivative at each ``x``.

    Raises
    ------
    ValueError
        If ``x`` is not a finite 1-D array or ``q`` is not a probability.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Theorem 3.2, Eq. (3.7.15).

    Examples
    --------
    >>> g2 = gated_cosh_log_curvature([1.0, 20.0], 4e-5)
    >>> bool(g2[0] > 0), bool(g2[1] < 0)
    (True, True)
    """
    import sympy as sp

    xs = as_finite_array("x", x, ndim=1)
    require_probability("q", q)
    bsym, qs = sp.symbols("beta q", positive=True)
    g = sp.log(1 - qs + qs * sp.cosh(sp.sqrt(bsym)))
    f = sp.lambdify((bsym, qs), sp.diff(g, bsym, 2), "mpmath")
    return np.array([float(f(float(x) ** 2, q)) for x in xs])


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        # q = 2 tau/alpha is the probability that a cross term is non-zero (Eq. 3.7.1)
        "tau_over_alpha": Range(0.0, 0.5, low_open=True),
        "n_aircraft": Range(1.0, None),
        "power": POSITIVE,
        "exp_g": NONNEGATIVE,
    },
)
