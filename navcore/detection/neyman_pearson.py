r"""Neyman-Pearson detection of a known signal in white Gaussian noise (ATC-10 App. D).

A matched filter with unit-energy impulse response sees a sample :math:`y` that is Gaussian
with variance :math:`J/B` (jammer power :math:`J` spread over the bandwidth :math:`B`) and
mean :math:`\sqrt{E}` when the signal of energy :math:`E = P_0 \tau` is present at its peak,
or mean 0 when it is absent. After normalising by the noise standard deviation the
detection index is (ATC-10 App. D convention)

.. math::

    d = \sqrt{E B / J} = \left(\frac{J}{P_0 B \tau}\right)^{-1/2},

and the likelihood-ratio test is a threshold on :math:`y`. Fixing the per-sample detection
probability :math:`p_d` fixes the threshold, and then (ATC-10 Eqs. (2.7.1), (D.17))

.. math::

    p_f = Q\left(d - \Phi^{-1}(p_d)\right),

where :math:`Q` is the Gaussian upper tail. The paper writes this as
:math:`\frac12 - \frac12 \operatorname{erf}\left(\sqrt{P_0 B \tau / (2 J)} - \phi\right)`
with :math:`\phi = \operatorname{erf}^{-1}(2 p_d - 1)`.

In navcore's SNR convention (signal energy over the one-sided noise density per pulse,
:math:`\chi = E/N_0`, stated once in :mod:`navcore.detection.pulse_detection`) the coherent
detection index is :math:`d = \sqrt{2 \chi}`: the results here are those of
:func:`navcore.detection.pulse_detection.pulse_detection_probability` with ``coherent=True``
at :math:`\chi = d^2 / 2 = E B / (2 J)`, i.e. ATC-10 takes the noise density
:math:`N_0 = 2 J / B`.

Everything is evaluated in the log domain with ``scipy.special.log_ndtr``, so tail
probabilities such as :math:`10^{-45}` (or :math:`10^{-300}`) are computed to full relative
precision instead of cancelling to zero as ``0.5 - 0.5 * erf(z)`` does.

"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import special

from navcore._validate import OPEN_PROBABILITY, as_finite_array, check_public
from navcore.trace import implements

__all__ = [
    "detection_index_from_jammer_ratio",
    "detection_probability",
    "erf_parameter_from_detection_probability",
    "false_alarm_probability",
    "log_detection_probability",
    "log_false_alarm_probability",
    "threshold_from_detection_probability",
]

FloatArray = NDArray[np.float64]


def _open_probability(p: ArrayLike, name: str) -> FloatArray:
    arr = as_finite_array(name, p)
    if np.any((arr <= 0.0) | (arr >= 1.0)):
        raise ValueError(f"{name} must lie strictly between 0 and 1")
    return arr


@implements("ATC10 D.7", "ATC10 D.8")
def detection_index_from_jammer_ratio(jammer_ratio: ArrayLike) -> FloatArray:
    r"""Detection index :math:`d = (J / (P_0 B \tau))^{-1/2}` of the matched-filter sample.

    Parameters
    ----------
    jammer_ratio : array_like
        :math:`x = J / (P_0 B \tau)` (linear, > 0), jammer power over the signal energy-bandwidth
        product.

    Returns
    -------
    ndarray
        The mean-to-standard-deviation ratio of the filter output under "signal present",
        with the output noise variance ``J/B`` of ATC-10 App. D (Eqs. D.7-D.8). A one-sided
        noise-density convention would give ``sqrt(2)`` times this value.

    Raises
    ------
    ValueError
        If a jammer ratio is not positive or not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Appendix D, Eqs. (D.7)-(D.8).

    Examples
    --------
    >>> float(detection_index_from_jammer_ratio(0.01))
    10.0
    """
    x = as_finite_array("jammer_ratio", jammer_ratio)
    if np.any(x <= 0.0):
        raise ValueError("jammer_ratio must be > 0")
    return 1.0 / np.sqrt(x)


def threshold_from_detection_probability(p_d: ArrayLike, d: ArrayLike) -> FloatArray:
    r"""Normalised threshold ``eta`` with :math:`P(d + n > \eta) = p_d`, i.e. ``eta = d - Phi^{-1}(p_d)``.

    Parameters
    ----------
    p_d : array_like
        Detection probability, in (0, 1).
    d : array_like
        Normalised signal amplitude.

    Returns
    -------
    ndarray
        Threshold (in units of the noise standard deviation).

    Raises
    ------
    ValueError
        If an input is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Appendix D (the Neyman-Pearson threshold).

    Examples
    --------
    >>> round(float(threshold_from_detection_probability(0.5, 4.0)), 6)
    4.0
    """
    pd = _open_probability(p_d, "p_d")
    dd = as_finite_array("d", d)
    return dd - special.ndtri(pd)


@implements("ATC10 2.7.2")
def erf_parameter_from_detection_probability(p_d: ArrayLike) -> FloatArray:
    r"""The paper's ``phi`` with :math:`p_d = \tfrac12 + \tfrac12 \operatorname{erf}(\phi)` (ATC-10 Eq. 2.7.2,
    D.13-D.15).

    Parameters
    ----------
    p_d : array_like
        Detection probability, in (0, 1).

    Returns
    -------
    ndarray
        :math:`\phi = \operatorname{erf}^{-1}(2 p_d - 1)` (dimensionless).

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (2.7.2) and Eqs. (D.13)-(D.15).

    Examples
    --------
    >>> round(float(erf_parameter_from_detection_probability(0.88)), 6)
    0.830841
    """
    pd = _open_probability(p_d, "p_d")
    return special.ndtri(pd) / np.sqrt(2.0)


@implements("ATC10 2.7.1")
def log_false_alarm_probability(p_d: ArrayLike, d: ArrayLike) -> FloatArray:
    r"""Natural log of ``p_f = Q(d - Phi^{-1}(p_d))`` (ATC-10 Eqs. 2.7.1, D.16-D.17).

    Parameters
    ----------
    p_d : array_like
        Per-sample detection probability, in (0, 1).
    d : array_like
        Detection index (see :func:`detection_index_from_jammer_ratio`), >= 0.

    Returns
    -------
    ndarray
        :math:`\ln p_f`, accurate to full relative precision however small ``p_f`` is.

    Raises
    ------
    ValueError
        If ``d`` is negative or an input is not finite.

    Examples
    --------
    >>> round(float(np.exp(log_false_alarm_probability(0.5, 0.0))), 12)
    0.5
    """
    pd = _open_probability(p_d, "p_d")
    dd = as_finite_array("d", d)
    if np.any(dd < 0.0):
        raise ValueError("d must be >= 0")
    return special.log_ndtr(special.ndtri(pd) - dd)


@implements("ATC10 D.17")
def false_alarm_probability(p_d: ArrayLike, d: ArrayLike) -> FloatArray:
    """``p_f = Q(d - Phi^{-1}(p_d))`` (ATC-10 Eq. D.17); see :func:`log_false_alarm_probability`.

    Parameters
    ----------
    p_d : array_like
        Detection probability the threshold is set for, in (0, 1).
    d : array_like
        Normalised signal amplitude (signal-to-noise ratio in amplitude).

    Returns
    -------
    ndarray
        False-alarm probability.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (D.17).

    Examples
    --------
    >>> f"{float(false_alarm_probability(0.5, 4.0)):.4e}"
    '3.1671e-05'
    """
    return np.exp(log_false_alarm_probability(p_d, d))


def log_detection_probability(threshold: ArrayLike, d: ArrayLike) -> FloatArray:
    """``ln P(d + n > threshold)`` for unit-variance Gaussian ``n`` (``ln Q(threshold - d)``).

    With ``d = 0`` it is the log false-alarm probability of the same threshold.

    Parameters
    ----------
    threshold : array_like
        Normalised threshold.
    d : array_like
        Normalised signal amplitude.

    Returns
    -------
    ndarray
        Natural log of the probability (finite far into the tail).

    Raises
    ------
    ValueError
        If an input is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Appendix D.

    Examples
    --------
    >>> round(float(log_detection_probability(40.0, 0.0)), 2)
    -804.61
    """
    th = as_finite_array("threshold", threshold)
    dd = as_finite_array("d", d)
    return special.log_ndtr(dd - th)


def detection_probability(threshold: ArrayLike, d: ArrayLike) -> FloatArray:
    """``P(d + n > threshold) = Q(threshold - d)``; see :func:`log_detection_probability`.

    Parameters
    ----------
    threshold : array_like
        Normalised threshold (in units of the noise standard deviation).
    d : array_like
        Normalised signal amplitude (same unit).

    Returns
    -------
    ndarray
        Detection probability.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Appendix D.

    Examples
    --------
    >>> round(float(detection_probability(0.0, 0.0)), 6), round(float(detection_probability(1.0, 3.0)), 6)
    (0.5, 0.97725)
    """
    return np.exp(log_detection_probability(threshold, d))


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals(), {"p_d": OPEN_PROBABILITY})
