r"""Lower bounds on false and ambiguous aircraft locations under barrage jamming (ATC-10 Sec. 2).

Four satellites receive each aircraft's pulse; each of :math:`4 N_T` matched filters
declares a pulse in a sample when it crosses a threshold set for a per-sample detection
probability :math:`p_d` (false-alarm probability :math:`p_f`,
:mod:`navcore.detection.neyman_pearson`). A *list* for aircraft :math:`i` in one repetition
segment is non-empty when a consistent quadruplet of declarations exists. Over :math:`K`
segments the first stage decides "aircraft present" when **more than** :math:`K t` of the
:math:`K` lists are non-empty (ATC-10 Sec. 2.4, (A.11), (B.1)).

Models, with their equations:

* the Chernoff exponent of that rule, maximised over :math:`\nu` in closed form,
  :math:`E(t, q) = D(t \,\|\, q)` for :math:`t < q` and 0 otherwise, with :math:`q = p_d^4`
  (App. A, (A.12)-(A.18)), so :math:`P_{DL} = 1 - e^{-K E}` (Eq. 2.4.2); at :math:`t = 0` it
  is exactly :math:`1 - (1 - q)^K`;
* (B.6) and (C.14):

  .. math::

      F(p_f) &= [1 - (1 - p_f)^{2 B \alpha}] \\
      &\quad \times [1 - (1 - p_f)^{4 B \beta}]^3, \\
      G(p_f) &= [1 - (1 - p_f)^{2 B \alpha}] \\
      &\quad \times [1 - (1 - p_f)^{n_v}]^3, \\
      n_v &= \frac{8 B}{3} \frac{v \alpha}{c};

* :math:`N_{FL} / N_T = (1 - N/N_T) F^{K t + 1}` (Eq. 2.5.5) and
  :math:`N_{ADL} / N_T = \frac12 (N/N_T) P_{DL} G^{K - 1} F` (Eq. 2.5.12 as corrected);
* the jammer-to-signal ratio :math:`x = J / (P_0 B \tau)` at which a bound reaches a level,
  and the jammer ERP :math:`10 \log_{10}(x P_0 \tau B)` dBW.

All probabilities are carried as natural logarithms: :math:`(1 - p)^n` with
:math:`n = 2 \times 10^7` and :math:`p = 10^{-20}` and products of 999 factors stay exact
where direct evaluation returns 0, 1 or ``-inf``.

"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import optimize, special, stats

from navcore import units
from navcore._validate import (
    COUNT,
    OPEN_PROBABILITY,
    POSITIVE,
    Range,
    as_finite_array,
    check_public,
    require_positive,
)
from navcore.detection.neyman_pearson import detection_index_from_jammer_ratio, log_false_alarm_probability
from navcore.trace import implements

__all__ = [
    "SurveillanceGeometry",
    "binary_divergence",
    "detection_lower_bound",
    "empty_list_rule_detection_probability",
    "filter_detection_probability_for_bound",
    "jammer_erp_dbw",
    "jammer_ratio_threshold_db",
    "list_probability_for_detection_bound",
    "list_rule_detection_probability",
    "list_rule_exponent",
    "list_rule_optimal_nu",
    "log1mexp",
    "log_ambiguous_detection_bound",
    "log_ambiguous_detection_ceiling",
    "log_ambiguous_list_factor",
    "log_detection_lower_bound",
    "log_false_list_factor",
    "log_false_location_bound",
    "log_false_location_ceiling",
    "log_one_minus_power",
]

FloatArray = NDArray[np.float64]

_LOG_TINY = -30.0  # below this ln u, ln(1 - e^-u) = ln u - u/2 to double precision
_LOG_HUGE = 700.0  # above this ln u, e^-u is 0 and ln(1 - e^-u) = 0


@dataclass(frozen=True)
class SurveillanceGeometry:
    r"""System parameters of the satellite multilateration surveillance (ATC-10 Sec. 2).

    Every field is required: the paper's scenario is the preset
    ``navcore.papers.atc10_jamming.geometry()``, built from its published inputs.

    Parameters
    ----------
    bandwidth_hz : float
        Signal bandwidth ``B``; the matched filters are sampled at ``2B`` samples/s.
    repetition_s : float
        Repetition period ``alpha`` of an aircraft's pulse.
    differential_delay_s : float
        Largest differential delay ``beta`` between satellites.
    max_speed_m_s : float
        Largest aircraft speed ``v``.
    airborne_fraction : float
        ``N / N_T``, the fraction of the ``N_T`` aircraft codes that are airborne.
    pulse_energy_j : float
        Signal pulse energy :math:`E = P_0 \tau`.
    """

    bandwidth_hz: float
    repetition_s: float
    differential_delay_s: float
    max_speed_m_s: float
    airborne_fraction: float
    pulse_energy_j: float

    def __post_init__(self) -> None:
        for name in (
            "bandwidth_hz",
            "repetition_s",
            "differential_delay_s",
            "max_speed_m_s",
            "pulse_energy_j",
        ):
            require_positive(name, getattr(self, name))
        if not 0.0 < self.airborne_fraction < 1.0:
            raise ValueError("airborne_fraction must lie strictly between 0 and 1")

    @property
    def samples_per_period(self) -> float:
        r""":math:`2 B \alpha`: samples in one repetition period (B.6)."""
        return 2.0 * self.bandwidth_hz * self.repetition_s

    @property
    def samples_per_delay_window(self) -> float:
        r""":math:`4 B \beta`: samples in a window of radius ``beta`` (B.6)."""
        return 4.0 * self.bandwidth_hz * self.differential_delay_s

    @property
    def samples_per_track_window(self) -> float:
        r""":math:`(8 B / 3)\, v \alpha / c`: samples in a window of radius :math:`(2/3)\, v \alpha / c`
        (C.14).

        Not an integer (23.86 for the paper's values); it is used as a real exponent.
        """
        return 8.0 / 3.0 * self.bandwidth_hz * self.max_speed_m_s * self.repetition_s / units.C

    @property
    def energy_bandwidth_dbw(self) -> float:
        r""":math:`10 \log_{10}(P_0 \tau B)` in dBW: the ERP of a jammer at ``x = 1``."""
        return 10.0 * math.log10(self.pulse_energy_j * self.bandwidth_hz)


def log1mexp(a: ArrayLike) -> FloatArray:
    """``ln(1 - exp(-a))`` for ``a >= 0``, accurate everywhere (Maechler 2012).

    Parameters
    ----------
    a : array_like
        Argument (``>= 0``; ``inf`` allowed).

    Returns
    -------
    ndarray
        ``ln(1 - exp(-a))`` (``-inf`` at 0).

    Raises
    ------
    ValueError
        If an element is NaN or negative.

    References
    ----------
    Maechler, M., "Accurately Computing ``log(1 - exp(-|a|))``", R package Rmpfr vignette (2012).

    Examples
    --------
    >>> float(log1mexp(1e-20))
    -46.051701859880914
    """
    arr = np.asarray(a, dtype=float)
    if np.any(np.isnan(arr)) or np.any(arr < 0.0):
        raise ValueError("a must be >= 0 (inf allowed)")
    small = arr <= math.log(2.0)
    with np.errstate(divide="ignore"):
        lo = np.log(-np.expm1(-np.where(small, arr, 1.0)))
    hi = np.log1p(-np.exp(-np.minimum(np.where(small, 1.0, arr), 700.0)))
    return np.where(small, lo, hi)


def _log1mexp_of_log(log_u: FloatArray) -> FloatArray:
    """``ln(1 - exp(-u))`` given ``ln u`` (any real), without underflow or overflow."""
    tiny = log_u < _LOG_TINY
    u = np.exp(np.clip(log_u, _LOG_TINY, _LOG_HUGE))
    mid = log1mexp(u)
    # For u < e^-30: ln(1 - e^-u) = ln u - u/2 + O(u^2); u/2 < 5e-14 relative to |ln u| > 30.
    small = log_u - 0.5 * np.exp(np.clip(log_u, -700.0, _LOG_TINY))
    return np.where(tiny, small, mid)


def log_one_minus_power(log_p: ArrayLike, n: float) -> FloatArray:
    """``ln(1 - (1 - p)**n)`` from ``ln p``, for ``0 < p < 1`` and real ``n > 0``.

    With ``u = -n ln(1 - p)`` the result is ``ln(1 - e^-u)``; ``ln u`` is formed as
    ``ln n + ln p + ln(-ln(1 - p) / p)`` so that neither ``p`` nor ``u`` under- or overflows.

    Parameters
    ----------
    log_p : array_like
        ``ln p`` (``< 0``).
    n : float
        Exponent (``> 0``, need not be an integer).

    Returns
    -------
    ndarray
        ``ln(1 - (1 - p)**n)``.

    Raises
    ------
    ValueError
        If a ``log_p`` is not negative or ``n`` not positive.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(log_one_minus_power(np.log(1e-20), 2e7)), 4)
    -29.2405
    """
    lp = as_finite_array("log_p", log_p)
    if np.any(lp >= 0.0):
        raise ValueError("log_p must be < 0 (p < 1)")
    require_positive("n", n)
    p = np.exp(np.maximum(lp, -700.0))
    # ln(-log1p(-p)/p): series p/2 + 5p^2/24 for small p, direct otherwise.
    ratio = np.where(
        lp < -20.0,
        p / 2.0,
        np.log(-np.log1p(-np.where(lp < -20.0, 0.5, p)) / np.where(lp < -20.0, 0.5, p)),
    )
    log_u = math.log(n) + lp + ratio
    return _log1mexp_of_log(log_u)


def binary_divergence(t: ArrayLike, q: ArrayLike) -> FloatArray:
    """Kullback-Leibler divergence ``D(t || q)`` of Bernoulli(t) from Bernoulli(q).

    Parameters
    ----------
    t : array_like
        Probability, in [0, 1].
    q : array_like
        Probability, strictly in (0, 1).

    Returns
    -------
    ndarray
        Divergence, nats.

    Raises
    ------
    ValueError
        If ``t`` is outside [0, 1] or ``q`` outside (0, 1).

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972),
    Appendix A (the Chernoff exponent, Eqs. (A.15)-(A.18)).

    Examples
    --------
    >>> [round(float(binary_divergence(t, 0.5)), 6) for t in (0.0, 0.5)]
    [0.693147, 0.0]
    """
    tt = as_finite_array("t", t)
    qq = as_finite_array("q", q)
    if np.any((tt < 0) | (tt > 1)):
        raise ValueError("t must lie in [0, 1]")
    if np.any((qq <= 0) | (qq >= 1)):
        raise ValueError("q must lie strictly between 0 and 1")
    return special.xlogy(tt, tt / qq) + special.xlogy(1.0 - tt, (1.0 - tt) / (1.0 - qq))


@implements("ATC10 A.15", "ATC10 A.16", "ATC10 A.17", "ATC10 A.18")
def list_rule_exponent(t: ArrayLike, q: ArrayLike) -> FloatArray:
    r""":math:`\max_{\nu \ge 0} [\nu (1 - t) - \ln((1 - q) e^\nu + q)]` in closed form (ATC-10 (A.15)-(A.18)).

    Equals ``D(t || q)`` when ``t < q`` and 0 when ``t >= q`` (the maximiser is then
    ``nu = 0`` and the Chernoff bound is vacuous). At ``t = 0`` it is ``-ln(1 - q)``.

    Parameters
    ----------
    t : array_like
        Fraction of the rule, in [0, 1].
    q : array_like
        Per-list probability, in (0, 1).

    Returns
    -------
    ndarray
        Chernoff exponent ``E(t, q)``, nats.

    Raises
    ------
    ValueError
        If ``t`` or ``q`` is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (A.15)-(A.18).

    Examples
    --------
    >>> round(float(list_rule_exponent(0.0, 0.5)), 12)
    0.69314718056
    """
    tt = as_finite_array("t", t)
    qq = as_finite_array("q", q)
    return np.where(tt < qq, binary_divergence(np.minimum(tt, qq), qq), 0.0)


def list_rule_optimal_nu(t: ArrayLike, q: ArrayLike) -> FloatArray:
    r"""The maximising :math:`\nu^* = \ln[(1 - t) q / (t (1 - q))]` for ``0 < t < q``.

    0 for ``t >= q`` and ``+inf`` at ``t = 0``.

    Parameters
    ----------
    t : array_like
        Fraction of the rule, in [0, 1].
    q : array_like
        Per-list probability, in (0, 1).

    Returns
    -------
    ndarray
        :math:`\nu^*` (dimensionless).

    Raises
    ------
    ValueError
        If an input is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (A.15)-(A.16).

    Examples
    --------
    >>> round(float(list_rule_optimal_nu(0.25, 0.5)), 6), float(list_rule_optimal_nu(0.75, 0.5))
    (1.098612, 0.0)
    """
    tt = as_finite_array("t", t)
    qq = as_finite_array("q", q)
    with np.errstate(divide="ignore"):
        nu = np.log((1.0 - tt) * qq) - np.log(tt * (1.0 - qq))
    return np.where(tt < qq, nu, 0.0)


@implements("ATC10 2.4.1", "ATC10 2.4.2")
def log_detection_lower_bound(p_d: ArrayLike, k: int, t: ArrayLike = 0.0) -> FloatArray:
    r""":math:`\ln P_{DL}` with :math:`P_{DL} = 1 - \exp(-K E(t, p_d^4))` (ATC-10 Eqs. 2.4.1-2.4.2, (A.17)).

    ``P_DL`` lower-bounds the probability that more than ``K t`` of ``K`` lists are non-empty
    when the aircraft is present; at ``t = 0`` it equals that probability exactly.

    Parameters
    ----------
    p_d : array_like
        Per-sample detection probability, in (0, 1).
    k : int
        Number of segments (``>= 1``).
    t : array_like, default 0.0
        Fraction of the rule.

    Returns
    -------
    ndarray
        :math:`\ln P_{DL}`.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or a probability is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (2.4.1)-(2.4.2), (A.17).

    Examples
    --------
    >>> import math
    >>> round(math.exp(float(log_detection_lower_bound(0.5, 1))), 12)
    0.0625
    """
    q = as_finite_array("p_d", p_d) ** 4
    k = _require_count(k)
    return log1mexp(k * list_rule_exponent(t, q))


@implements("ATC10 2.4.2")
def detection_lower_bound(p_d: ArrayLike, k: int, t: ArrayLike = 0.0) -> FloatArray:
    r""":math:`P_{DL} = 1 - \exp(-K E(t, p_d^4))` (ATC-10 Eq. 2.4.2); ``p_d**4`` for ``K = 1``.

    Parameters
    ----------
    p_d : array_like
        Per-sample detection probability, in (0, 1).
    k : int
        Number of segments (``>= 1``).
    t : array_like, default 0.0
        Fraction in the rule "more than ``K t`` lists non-empty".

    Returns
    -------
    ndarray
        Lower bound on the probability of declaring the aircraft present.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or a probability is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (2.4.2).

    Examples
    --------
    >>> round(float(detection_lower_bound(0.5, 1)), 12)
    0.0625
    """
    q = as_finite_array("p_d", p_d) ** 4
    k = _require_count(k)
    return -np.expm1(-k * list_rule_exponent(t, q))


@implements("ATC10 A.11")
def list_rule_detection_probability(q: ArrayLike, k: int, t: float = 0.0) -> FloatArray:
    """Exact ``P(more than K t of K lists non-empty)`` for i.i.d. lists.

    Each list is non-empty with probability ``q`` (the rule of ATC-10 (A.11)); a binomial
    survival function.

    Parameters
    ----------
    q : array_like
        Probability that one list is non-empty, in [0, 1].
    k : int
        Number of lists (``>= 1``).
    t : float, default 0.0
        Fraction of the rule.

    Returns
    -------
    ndarray
        Detection probability.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or ``q`` not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (A.11).

    Examples
    --------
    >>> round(float(list_rule_detection_probability(0.5, 2)), 6)
    0.75
    """
    k = _require_count(k)
    return stats.binom.sf(math.floor(k * t), k, as_finite_array("q", q))


def empty_list_rule_detection_probability(q: ArrayLike, k: int, t: float = 0.0) -> FloatArray:
    r"""The rule under the paper's literal (A.9)/(A.10): "H1 if at most ``K t`` lists are empty".

    That is :math:`P(K_0 \le K t)` with :math:`K_0 \sim \mathrm{Binomial}(K, 1 - q)`. Kept to show that it is
    not the
    rule the bounds use (at ``t = 0`` it is ``q**K``).

    Parameters
    ----------
    q : array_like
        Probability that one list is non-empty, in [0, 1].
    k : int
        Number of lists (``>= 1``).
    t : float, default 0.0
        Fraction of the rule.

    Returns
    -------
    ndarray
        Detection probability.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or ``q`` not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (A.9)-(A.10).

    Examples
    --------
    >>> round(float(empty_list_rule_detection_probability(0.5, 3)), 6)
    0.125
    """
    k = _require_count(k)
    return stats.binom.cdf(math.floor(k * t), k, 1.0 - as_finite_array("q", q))


@implements("ATC10 2.4.2")
def list_probability_for_detection_bound(p_dl: float, k: int, t: float = 0.0) -> float:
    r"""Per-list probability ``q = p_d**4`` at which ``P_DL`` of Eq. (2.4.2) equals ``p_dl``.

    Closed form at ``t = 0``: ``q = 1 - (1 - P_DL)**(1/K)``; for ``t > 0`` the root of
    :math:`K D(t \,\|\, q) = -\ln(1 - P_{DL})` on ``(t, 1)``.

    Parameters
    ----------
    p_dl : float
        Required lower bound on the detection probability, in (0, 1).
    k : int
        Number of segments (``>= 1``).
    t : float, default 0.0
        Fraction of the rule, in [0, 1).

    Returns
    -------
    float
        Per-list probability ``q``.

    Raises
    ------
    ValueError
        If ``p_dl`` is not in (0, 1), ``t`` not in [0, 1) or ``k`` not a positive integer.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (2.4.2).

    Examples
    --------
    >>> round(list_probability_for_detection_bound(0.75, 2), 6)
    0.5
    """
    if not 0.0 < p_dl < 1.0:
        raise ValueError("p_dl must lie strictly between 0 and 1")
    k = _require_count(k)
    if not 0.0 <= t < 1.0:
        raise ValueError("t must lie in [0, 1)")
    target = -math.log1p(-p_dl) / k
    if t == 0.0:
        return float(-math.expm1(-target))
    f = lambda q: float(binary_divergence(t, q)) - target
    hi = 1.0 - 1e-16
    return float(optimize.brentq(f, t, hi, xtol=1e-15, rtol=1e-15))


def filter_detection_probability_for_bound(p_dl: float, k: int, t: float = 0.0) -> float:
    """Per-sample ``p_d = q**(1/4)`` needed for ``P_DL = p_dl`` (four filters per list).

    Parameters
    ----------
    p_dl : float
        Required lower bound on the detection probability, in (0, 1).
    k : int
        Number of segments (``>= 1``).
    t : float, default 0.0
        Fraction of the rule, in [0, 1).

    Returns
    -------
    float
        Per-sample detection probability.

    Raises
    ------
    ValueError
        As :func:`list_probability_for_detection_bound`.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (2.4.2) inverted.

    Examples
    --------
    >>> round(filter_detection_probability_for_bound(0.0625, 1), 6)
    0.5
    """
    return list_probability_for_detection_bound(p_dl, k, t) ** 0.25


def _require_count(k: int) -> int:
    if int(k) != k or k < 1:
        raise ValueError("k must be a positive integer")
    return int(k)


def log_false_list_factor(log_pf: ArrayLike, geometry: SurveillanceGeometry) -> FloatArray:
    r""":math:`\ln F(p_f)`, :math:`F = [1 - (1 - p_f)^{2 B \alpha}]\, [1 - (1 - p_f)^{4 B \beta}]^3` (B.6).

    ``F`` lower-bounds the probability that a list is non-empty from noise alone.

    Parameters
    ----------
    log_pf : array_like
        Natural logarithm of the per-sample false-alarm probability (``< 0``).
    geometry : SurveillanceGeometry
        System parameters (sample counts per window).

    Returns
    -------
    ndarray
        ``ln F``.

    Raises
    ------
    ValueError
        If a ``log_pf`` is not negative.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (B.6).

    Examples
    --------
    >>> import numpy as np
    >>> g = SurveillanceGeometry(bandwidth_hz=1e7, repetition_s=1.0, differential_delay_s=0.03,
    ...                          max_speed_m_s=300.0, airborne_fraction=0.5, pulse_energy_j=1e-2)
    >>> round(float(log_false_list_factor(np.log(1e-9), g)), 3)
    -24.1
    """
    return log_one_minus_power(log_pf, geometry.samples_per_period) + 3.0 * log_one_minus_power(
        log_pf, geometry.samples_per_delay_window
    )


def log_ambiguous_list_factor(log_pf: ArrayLike, geometry: SurveillanceGeometry) -> FloatArray:
    r""":math:`\ln G(p_f)`, :math:`G = [1 - (1 - p_f)^{2 B \alpha}]\, [1 - (1 - p_f)^{n_v}]^3` (C.14).

    Parameters
    ----------
    log_pf : array_like
        Natural logarithm of the per-sample false-alarm probability (``< 0``).
    geometry : SurveillanceGeometry
        System parameters (sample counts per window).

    Returns
    -------
    ndarray
        ``ln G``.

    Raises
    ------
    ValueError
        If a ``log_pf`` is not negative.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (C.14).

    Examples
    --------
    >>> import numpy as np
    >>> g = SurveillanceGeometry(bandwidth_hz=1e7, repetition_s=1.0, differential_delay_s=0.03,
    ...                          max_speed_m_s=300.0, airborne_fraction=0.5, pulse_energy_j=1e-2)
    >>> round(float(log_ambiguous_list_factor(np.log(1e-9), g)), 3)
    -56.239
    """
    return log_one_minus_power(log_pf, geometry.samples_per_period) + 3.0 * log_one_minus_power(
        log_pf, geometry.samples_per_track_window
    )


def _log_pf(jammer_ratio: ArrayLike, p_d: float) -> FloatArray:
    return log_false_alarm_probability(p_d, detection_index_from_jammer_ratio(jammer_ratio))


@implements("ATC10 2.5.5")
def log_false_location_bound(
    jammer_ratio: ArrayLike, p_d: float, k: int, t: float, geometry: SurveillanceGeometry
) -> FloatArray:
    r""":math:`\ln(N_{FL} / N_T) = \ln(1 - N/N_T) + (K t + 1) \ln F(p_f)` (ATC-10 Eqs. 2.5.5, 2.8.3).

    Parameters
    ----------
    jammer_ratio : array_like
        :math:`x = J / (P_0 B \tau)`, linear.
    p_d : float
        Per-sample detection probability the filters are designed for.
    k : int
        Number of segments (lists) in the first-stage decision.
    t : float
        Fraction in the rule "more than ``K t`` lists non-empty"; ``K t + 1`` is used as a
        real exponent, as printed (``floor(K t) + 1`` would be the tighter count).
    geometry : SurveillanceGeometry
        System parameters (no default: a paper's scenario is a preset of its paper module).

    Returns
    -------
    ndarray
        Natural log of the lower bound on false locations per aircraft, ``N_FL / N_T``.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or a probability is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Eqs. (2.5.5) and (2.8.3).

    Examples
    --------
    >>> g = SurveillanceGeometry(bandwidth_hz=1e7, repetition_s=1.0, differential_delay_s=0.03,
    ...                          max_speed_m_s=300.0, airborne_fraction=0.5, pulse_energy_j=1e-2)
    >>> [round(float(log_false_location_bound(x, 0.9, 2, 0.0, g)), 3) for x in (0.01, 1.0)]
    [-106.3, -0.693]
    """
    g = geometry
    k = _require_count(k)
    log_f = log_false_list_factor(_log_pf(jammer_ratio, p_d), g)
    return math.log1p(-g.airborne_fraction) + (k * t + 1.0) * log_f


@implements("ATC10 2.5.12")
def log_ambiguous_detection_bound(
    jammer_ratio: ArrayLike, p_d: float, k: int, t: float, geometry: SurveillanceGeometry
) -> FloatArray:
    r"""Natural log of the lower bound on ambiguous locations per aircraft, :math:`\ln(N_{ADL} / N_T)`.

    .. math::

        \ln\frac{N_{ADL}}{N_T} &= \ln\frac{N}{2 N_T} + \ln P_{DL} \\
        &\quad + (K - 1) \ln G(p_f) + \ln F(p_f)

    ATC-10 Eqs. 2.5.12, 2.7.3, 2.8.4; :math:`P_{DL} = p_d^4` at :math:`K = 1`.

    Parameters
    ----------
    jammer_ratio : array_like
        :math:`x = J / (P_0 B \tau)`, linear.
    p_d : float
        Per-sample detection probability the filters are designed for, in (0, 1).
    k : int
        Number of segments (lists) in the first-stage decision (``>= 1``).
    t : float
        Fraction in the rule "more than ``K t`` lists non-empty", in [0, 1).
    geometry : SurveillanceGeometry
        System parameters (bandwidth in Hz, periods in s, speed in m/s, pulse energy in J).

    Returns
    -------
    ndarray
        Natural log of the lower bound on ambiguous locations per aircraft.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or a probability is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (2.5.12) (as corrected), (2.7.3), (2.8.4).

    Examples
    --------
    >>> g = SurveillanceGeometry(bandwidth_hz=1e7, repetition_s=1.0, differential_delay_s=0.03,
    ...                          max_speed_m_s=300.0, airborne_fraction=0.5, pulse_energy_j=1e-2)
    >>> round(float(log_ambiguous_detection_bound(1e3, 0.9, 2, 0.0, g)), 3)
    -1.512
    """
    g = geometry
    k = _require_count(k)
    log_pf = _log_pf(jammer_ratio, p_d)
    log_pdl = float(log_detection_lower_bound(p_d, k, t))
    return (
        math.log(0.5 * g.airborne_fraction)
        + log_pdl
        + (k - 1) * log_ambiguous_list_factor(log_pf, g)
        + log_false_list_factor(log_pf, g)
    )


def log_false_location_ceiling(p_d: float, k: int, t: float, geometry: SurveillanceGeometry) -> float:
    r"""Limit of :func:`log_false_location_bound` as ``J -> inf`` (:math:`p_f \to p_d`).

    Parameters
    ----------
    p_d : float
        Per-sample detection probability the filters are designed for, in (0, 1).
    k : int
        Number of segments (lists) in the first-stage decision (``>= 1``).
    t : float
        Fraction in the rule "more than ``K t`` lists non-empty", in [0, 1).
    geometry : SurveillanceGeometry
        System parameters (bandwidth in Hz, periods in s, speed in m/s, pulse energy in J).

    Returns
    -------
    float
        Natural log of the supremum of ``N_FL / N_T``.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or ``p_d`` is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (2.5.5).

    Examples
    --------
    >>> g = SurveillanceGeometry(bandwidth_hz=1e7, repetition_s=1.0, differential_delay_s=0.03,
    ...                          max_speed_m_s=300.0, airborne_fraction=0.5, pulse_energy_j=1e-2)
    >>> round(log_false_location_ceiling(0.9, 2, 0.0, g), 4)
    -0.6931
    """
    g = geometry
    log_f = log_false_list_factor(math.log(p_d), g)
    return float(math.log1p(-g.airborne_fraction) + (_require_count(k) * t + 1.0) * log_f)


def log_ambiguous_detection_ceiling(p_d: float, k: int, t: float, geometry: SurveillanceGeometry) -> float:
    r"""Limit of :func:`log_ambiguous_detection_bound` as ``J -> inf`` (:math:`p_f \to p_d`).

    Parameters
    ----------
    p_d : float
        Per-sample detection probability the filters are designed for, in (0, 1).
    k : int
        Number of segments (lists) in the first-stage decision (``>= 1``).
    t : float
        Fraction in the rule "more than ``K t`` lists non-empty", in [0, 1).
    geometry : SurveillanceGeometry
        System parameters (bandwidth in Hz, periods in s, speed in m/s, pulse energy in J).

    Returns
    -------
    float
        Natural log of the supremum of ``N_ADL / N_T``.

    Raises
    ------
    ValueError
        If ``k`` is not a positive integer or ``p_d`` is out of range.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (2.5.12).

    Examples
    --------
    >>> g = SurveillanceGeometry(bandwidth_hz=1e7, repetition_s=1.0, differential_delay_s=0.03,
    ...                          max_speed_m_s=300.0, airborne_fraction=0.5, pulse_energy_j=1e-2)
    >>> round(log_ambiguous_detection_ceiling(0.9, 2, 0.0, g), 3)
    -1.512
    """
    g = geometry
    k = _require_count(k)
    lp = math.log(p_d)
    return float(
        math.log(0.5 * g.airborne_fraction)
        + float(log_detection_lower_bound(p_d, k, t))
        + (k - 1) * log_ambiguous_list_factor(lp, g)
        + log_false_list_factor(lp, g)
    )


@implements("ATC10 2.5.5", "ATC10 2.5.12")
def jammer_ratio_threshold_db(
    quantity: str,
    level: float,
    p_d: float,
    k: int,
    t: float,
    geometry: SurveillanceGeometry,
    *,
    lower_db: float = -60.0,
    upper_db: float = 160.0,
) -> float:
    r""":math:`10 \log_{10}(J / (P_0 B \tau))` at which a bound reaches ``level * N_T``.

    Parameters
    ----------
    quantity : {"false", "ambiguous"}
        ``N_FL`` (Eq. 2.5.5) or ``N_ADL`` (Eq. 2.5.12).
    level : float
        Target as a fraction of ``N_T`` (the paper: 0.01 for ``N_ADL``; ``N_FL`` only
        approaches its supremum ``1 - N/N_T``, so use a fraction of that).
    p_d : float
        Per-sample detection probability, as in :func:`log_false_location_bound`.
    k : int
        Number of segments (lists).
    t : float
        Fraction in the rule "more than ``K t`` lists non-empty".
    geometry : SurveillanceGeometry
        System parameters.
    lower_db, upper_db : float
        The bracket (dB) searched for the threshold.

    Returns
    -------
    float
        The ratio in dB, or ``inf`` when the bound's ceiling (``J -> inf``) is at or below
        ``level``: no jammer power reaches it.

    Raises
    ------
    ValueError
        If ``quantity`` is unknown, ``level`` is not positive, or the bracket does not
        contain the threshold.

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Eqs. (2.5.5) and (2.5.12), Table 2.1.

    Examples
    --------
    >>> g = SurveillanceGeometry(bandwidth_hz=1e7, repetition_s=1.0, differential_delay_s=0.03,
    ...                          max_speed_m_s=300.0, airborne_fraction=0.5, pulse_energy_j=1e-2)
    >>> x_db = jammer_ratio_threshold_db("ambiguous", 0.01, 0.9, 2, 0.0, g)
    >>> round(x_db, 2)
    -10.67
    """
    if quantity not in ("false", "ambiguous"):
        raise ValueError("quantity must be 'false' or 'ambiguous'")
    if not level > 0.0:
        raise ValueError("level must be > 0")
    g = geometry
    bound = log_false_location_bound if quantity == "false" else log_ambiguous_detection_bound
    ceiling = (log_false_location_ceiling if quantity == "false" else log_ambiguous_detection_ceiling)(
        p_d, k, t, g
    )
    target = math.log(level)
    if ceiling <= target:
        return math.inf

    def f(x_db: float) -> float:
        return float(bound(10.0 ** (x_db / 10.0), p_d, k, t, g)) - target

    if f(upper_db) <= 0.0:
        return math.inf
    if f(lower_db) >= 0.0:
        raise ValueError(f"the bound already exceeds the level at {lower_db} dB; lower lower_db")
    return float(optimize.brentq(f, lower_db, upper_db, xtol=1e-10, rtol=1e-14))


def jammer_erp_dbw(jammer_ratio_db: ArrayLike, pulse_energy_j: float, bandwidth_hz: float) -> FloatArray:
    r"""Jammer ERP ``J`` in dBW from :math:`10 \log_{10}(J / (P_0 \tau B))` (ATC-10 Sec. 2.7, Table 2.1).

    Parameters
    ----------
    jammer_ratio_db : array_like
        :math:`10 \log_{10}(J / (P_0 \tau B))`, dB.
    pulse_energy_j : float
        Signal pulse energy :math:`P_0 \tau`, J (``> 0``).
    bandwidth_hz : float
        Bandwidth ``B``, Hz (``> 0``).

    Returns
    -------
    ndarray
        Jammer ERP, dBW.

    Raises
    ------
    ValueError
        If ``pulse_energy_j`` or ``bandwidth_hz`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 2.7, Table 2.1.

    Examples
    --------
    >>> float(jammer_erp_dbw(-16.0, 10e-3, 10e6))
    34.0
    """
    require_positive("pulse_energy_j", pulse_energy_j)
    require_positive("bandwidth_hz", bandwidth_hz)
    return np.asarray(jammer_ratio_db, float) + 10.0 * np.log10(pulse_energy_j * bandwidth_hz)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "p_d": OPEN_PROBABILITY,
        "p_dl": OPEN_PROBABILITY,
        "q": OPEN_PROBABILITY,
        "t": Range(0.0, 1.0, high_open=True),
        "k": COUNT,
        "level": POSITIVE,
        "n": POSITIVE,
        "airborne_fraction": Range(0.0, 1.0, low_open=True),
        "bandwidth_hz": POSITIVE,
        "pulse_energy_j": POSITIVE,
        "repetition_s": POSITIVE,
        "differential_delay_s": POSITIVE,
        "max_speed_m_s": POSITIVE,
    },
    jammer_erp_dbw={"allow_inf": ("jammer_ratio_db",)},
)
