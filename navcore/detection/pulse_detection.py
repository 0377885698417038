r"""Detection of N pulses in white Gaussian noise: threshold from Pfa, Pd from SNR, Swerling 0-IV.

SNR convention (navcore's one convention for detection)
-------------------------------------------------------
``snr`` is the **signal-to-noise ratio per pulse**, :math:`\chi = E/N_0`: the pulse's signal
energy :math:`E` over the one-sided noise power spectral density :math:`N_0`. At the output
of a filter matched to the pulse, sampled at the peak, the complex sample is
:math:`y = s + n` with :math:`|s|^2/\sigma^2 = \chi`, where :math:`\sigma^2 = E|n|^2` is the
total noise power of the in-phase and quadrature components together. This is the
single-pulse SNR of Marcum's and Swerling's tables, of Albersheim's and Shnidman's
equations and of most radar texts; for a fluctuating target it is the mean over the
fluctuation. A linear power ratio, not decibels (``units.power_ratio_from_db`` converts).

Detectors:

- **noncoherent** (square law): :math:`T = \sum_{k=1}^N |y_k|^2/\sigma^2`. Under noise alone
  :math:`2T` is chi-square with :math:`2N` degrees of freedom; with a steady target it is
  noncentral chi-square with noncentrality :math:`2N\chi`, so that
  :math:`P_d = Q_N(\sqrt{2N\chi}, \sqrt{2\tau})`, the generalised Marcum Q function, computed
  as scipy's noncentral chi-square survival function.
- **coherent** (phase known): :math:`T = \mathrm{Re}\{\sum_k y_k e^{-j\phi}\}/\sqrt{N\sigma^2/2}`
  is Gaussian with unit variance and mean :math:`d = \sqrt{2N\chi}`, the *detection index*:
  :math:`P_d = Q(Q^{-1}(P_{fa}) - d)`.

Target fluctuation (Swerling 1960), for the noncoherent detector: 0 steady; I and III
scan to scan (one cross-section for the N pulses), II and IV pulse to pulse (independent
per pulse); I and II Rayleigh amplitude (cross-section exponential, chi-square with 2
degrees of freedom), III and IV one dominant scatterer (chi-square with 4). The cases have
closed forms (Swerling 0 through the Marcum Q function; I, II, IV as finite sums of
incomplete gamma functions, derived from their moment-generating functions); case III
for N > 1 is integrated numerically over its cross-section.

ATC-10's convention
-------------------
ATC-10 (App. D, :mod:`navcore.detection.neyman_pearson`) writes a coherent detection index
:math:`d = \sqrt{E B / J}`, with :math:`J/B` the output noise variance of its unit-energy
matched filter. It is this module's coherent :math:`d = \sqrt{2\chi}`: ATC-10's detection
probabilities are navcore's at :math:`\chi = d^2/2 = EB/(2J)`, i.e. ATC-10 takes the noise
density :math:`N_0 = 2J/B`. Reading :math:`J/B` as the one-sided density :math:`N_0` instead
gives :math:`\chi = EB/J` and an index :math:`\sqrt 2` larger. The mapping is exact: at the
false-alarm probability ATC-10 pairs with a detection probability :math:`P_D` and an index
:math:`d`, this module's coherent detection probability at :math:`\chi = d^2/2` is :math:`P_D`
(to :math:`10^{-9}` relative); at :math:`\chi = d^2` it is larger.

References
----------
.. [1] J. I. Marcum, "A statistical theory of target detection by pulsed radar", IRE Trans.
   IT-6 (1960) 59-144.
.. [2] P. Swerling, "Probability of detection for fluctuating targets", IRE Trans. IT-6
   (1960) 269-308.
.. [3] M. A. Richards, Fundamentals of Radar Signal Processing, 2nd ed. (2014), Ch. 6.
.. [4] D. A. Shnidman, "Determination of required SNR values", IEEE Trans. AES 38(3) (2002).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import optimize, special, stats

from navcore._validate import NONNEGATIVE, OPEN_PROBABILITY, Range, check_public

__all__ = [
    "SWERLING_CASES",
    "detection_threshold",
    "false_alarm_probability_for_threshold",
    "pulse_detection_probability",
    "required_snr",
]

Array = NDArray[np.float64]

#: The Swerling cases: 0 (steady), 1 and 3 (scan to scan), 2 and 4 (pulse to pulse).
SWERLING_CASES = (0, 1, 2, 3, 4)

_LEGENDRE = np.polynomial.legendre.leggauss(96)


def _case(swerling: int, coherent: bool) -> int:
    if isinstance(swerling, bool) or swerling not in SWERLING_CASES:
        raise ValueError(f"swerling must be one of {list(SWERLING_CASES)}, got {swerling!r}")
    if coherent and swerling != 0:
        raise ValueError(
            "swerling must be 0 with coherent=True: coherent detection is modelled for a steady "
            f"target (its phase known), got swerling={swerling}"
        )
    return int(swerling)


def detection_threshold(p_fa: ArrayLike, n_pulses: int = 1, *, coherent: bool = False) -> Array:
    r"""Threshold that noise alone exceeds with probability ``p_fa``.

    Parameters
    ----------
    p_fa : float or array
        False-alarm probability per test, in (0, 1).
    n_pulses : int, default 1
        Number of pulses integrated (``>= 1``).
    coherent : bool, default False
        Coherent detector (threshold on the normalised real statistic, a standard normal
        under noise); otherwise the square-law sum :math:`\sum_k |y_k|^2 / \sigma^2`
        (under noise a gamma distribution with shape ``n_pulses``).

    Returns
    -------
    ndarray
        Threshold: in noise standard deviations (coherent), or in units of the noise power
        per pulse (noncoherent).

    Raises
    ------
    ValueError
        If ``p_fa`` is not in (0, 1) or ``n_pulses`` is not a positive integer.

    References
    ----------
    Richards (2014), Sec. 6.2 and 6.3 (module reference 3).

    Examples
    --------
    >>> round(float(detection_threshold(1e-6)), 4)  # -ln(1e-6) for one pulse
    13.8155
    >>> round(float(detection_threshold(1e-6, coherent=True)), 4)
    4.7534
    """
    pfa = np.asarray(p_fa, dtype=float)
    if coherent:
        return np.asarray(-special.ndtri(pfa))  # Q^-1(p_fa), exact for tiny p_fa
    return np.asarray(special.gammainccinv(n_pulses, pfa))


def false_alarm_probability_for_threshold(
    threshold: ArrayLike, n_pulses: int = 1, *, coherent: bool = False
) -> Array:
    """False-alarm probability of a threshold (the inverse of :func:`detection_threshold`).

    Parameters
    ----------
    threshold : float or array
        Threshold in the units of :func:`detection_threshold` (``>= 0`` when noncoherent).
    n_pulses : int, default 1
        Number of pulses integrated (``>= 1``).
    coherent : bool, default False
        Coherent detector.

    Returns
    -------
    ndarray
        Probability that noise alone exceeds the threshold.

    Raises
    ------
    ValueError
        If the threshold is not finite, or negative for the noncoherent detector.

    Examples
    --------
    >>> round(float(false_alarm_probability_for_threshold(detection_threshold(1e-4, 8), 8)), 12)
    0.0001
    """
    t = np.asarray(threshold, dtype=float)
    if coherent:
        return np.asarray(special.ndtr(-t))
    if np.any(t < 0):
        raise ValueError("threshold must be >= 0 for the noncoherent (square-law) detector")
    return np.asarray(special.gammaincc(n_pulses, t))


def _swerling1(chi: Array, tau: Array, n: int) -> Array:
    b = 1.0 + n * chi  # the MGF of T is (1 + s)^(1 - n) / (1 + b s)
    if n == 1:
        return np.exp(-tau / b)
    r = 1.0 + 1.0 / (n * chi)  # = b / (n chi)
    # Pd = 1 - P(n-1, tau) + r^(n-1) P(n-1, tau / r) exp(-tau / b)  (Richards, Eq. 6.55),
    # with the product taken in logs so that large n does not overflow
    log_term = (n - 1) * np.log(r) + np.log(special.gammainc(n - 1, tau / r)) - tau / b
    return special.gammaincc(n - 1, tau) + np.exp(log_term)


def _swerling3(chi: Array, tau: Array, n: int) -> Array:
    b = 1.0 + n * chi / 2.0  # T = G1 + G2, G1 ~ Gamma(n - 2, 1), G2 ~ Gamma(2, b)
    if n == 1:  # MGF (1 + s) / (1 + b s)^2: a mixture of Gamma(1, b) and Gamma(2, b)
        return np.exp(-tau / b) / b + (1.0 - 1.0 / b) * special.gammaincc(2, tau / b)
    tail2 = special.gammaincc(2, tau / b)
    if n == 2:
        return tail2
    # P(G1 + G2 > tau) = P(G2 > tau) + int_0^tau f_G2(u) P(G1 > tau - u) du (Gauss-Legendre)
    x, w = _LEGENDRE
    u = 0.5 * tau[..., None] * (x + 1.0)
    f2 = u * np.exp(-u / b[..., None]) / b[..., None] ** 2
    inner = np.sum(w * f2 * special.gammaincc(n - 2, tau[..., None] - u), axis=-1)
    return tail2 + 0.5 * tau * inner


def _swerling4(chi: Array, tau: Array, n: int) -> Array:
    a = 1.0 + chi / 2.0
    # per pulse MGF (1 + s) / (1 + a s)^2 = (1/a)/(1 + a s) + (1 - 1/a)/(1 + a s)^2, so T is a
    # binomial(n, 1/a) mixture of Gamma(2n - j, a), j = 0..n
    j = np.arange(n + 1)
    weights = stats.binom.pmf(j, n, (1.0 / a)[..., None])
    return np.sum(weights * special.gammaincc(2 * n - j, (tau / a)[..., None]), axis=-1)


def pulse_detection_probability(
    snr: ArrayLike,
    p_fa: ArrayLike,
    n_pulses: int = 1,
    *,
    swerling: int = 0,
    coherent: bool = False,
) -> Array:
    """Detection probability of ``n_pulses`` pulses at SNR ``snr`` per pulse and false-alarm ``p_fa``.

    Parameters
    ----------
    snr : float or array
        Signal-to-noise ratio per pulse, ``E/N0`` (linear power ratio, ``>= 0``; the mean
        over the fluctuation for a Swerling target). See the module docstring for the
        convention.
    p_fa : float or array
        False-alarm probability, in (0, 1); broadcasts against ``snr``.
    n_pulses : int, default 1
        Number of pulses integrated (``>= 1``).
    swerling : {0, 1, 2, 3, 4}, default 0
        Target fluctuation model (0: steady).
    coherent : bool, default False
        Coherent integration of a steady target (``swerling=0``) instead of the square-law
        (noncoherent) sum.

    Returns
    -------
    ndarray
        Detection probability.

    Raises
    ------
    ValueError
        If ``snr`` is negative, ``p_fa`` outside (0, 1), ``n_pulses`` not a positive
        integer, ``swerling`` not 0-4, or ``coherent`` asked for a fluctuating target.

    References
    ----------
    Marcum (1960) and Swerling (1960), module references 1-2; Richards (2014), Ch. 6.

    Examples
    --------
    >>> round(float(pulse_detection_probability(10 ** 1.32, 1e-6)), 3)  # 13.2 dB, one pulse
    0.902
    >>> round(float(pulse_detection_probability(10 ** 1.32, 1e-6, swerling=1)), 3)  # 1e-6 ** (1 / (1 + snr))
    0.532
    """
    case = _case(swerling, coherent)
    chi, pfa = np.broadcast_arrays(np.asarray(snr, dtype=float), np.asarray(p_fa, dtype=float))
    n = int(n_pulses)
    if coherent:
        return np.asarray(special.ndtr(np.sqrt(2.0 * n * chi) + special.ndtri(pfa)))
    tau = np.asarray(special.gammainccinv(n, pfa))
    if case == 0:
        return np.asarray(stats.ncx2.sf(2.0 * tau, 2 * n, 2.0 * n * chi))
    if case == 2:
        return np.asarray(special.gammaincc(n, tau / (1.0 + chi)))
    with np.errstate(divide="ignore"):  # chi = 0 leaves the target at the false-alarm rate
        safe = np.where(chi > 0, chi, 1.0)
        if case == 1:
            pd = _swerling1(safe, tau, n)
        elif case == 3:
            pd = _swerling3(safe, tau, n)
        else:
            pd = _swerling4(safe, tau, n)
    return np.asarray(np.clip(np.where(chi > 0, pd, pfa), 0.0, 1.0))


def required_snr(
    p_d: ArrayLike,
    p_fa: ArrayLike,
    n_pulses: int = 1,
    *,
    swerling: int = 0,
    coherent: bool = False,
) -> Array:
    r"""SNR per pulse that reaches detection probability ``p_d`` at false-alarm probability ``p_fa``.


    Parameters
    ----------
    p_d : float or array
        Detection probability, in (0, 1) and above ``p_fa``.
    p_fa : float or array
        False-alarm probability, in (0, 1); broadcasts against ``p_d``.
    n_pulses : int, default 1
        Number of pulses integrated (``>= 1``).
    swerling : {0, 1, 2, 3, 4}, default 0
        Target fluctuation model.
    coherent : bool, default False
        Coherent integration of a steady target.

    Returns
    -------
    ndarray
        SNR per pulse, :math:`E/N_0` (linear; :math:`10 \log_{10}` of it in dB).

    Raises
    ------
    ValueError
        If a probability is outside (0, 1) or ``p_d <= p_fa``, or the options are invalid.

    Notes
    -----
    The inverse of :func:`pulse_detection_probability` in the SNR, by Brent's method on
    the SNR in dB (to :math:`10^{-10}` dB). The coherent case is closed form:
    :math:`(Q^{-1}(p_{fa}) - Q^{-1}(p_d))^2 / (2 N)`.

    Examples
    --------
    >>> round(10 * float(np.log10(required_snr(0.9, 1e-6))), 2)  # the textbook 13.2 dB
    13.18
    """
    _case(swerling, coherent)
    pd, pfa = np.broadcast_arrays(np.asarray(p_d, dtype=float), np.asarray(p_fa, dtype=float))
    if np.any(pd <= pfa):
        raise ValueError("p_d must be larger than p_fa (a detector at SNR 0 already reaches p_fa)")
    n = int(n_pulses)
    if coherent:
        return np.asarray((special.ndtri(pd) - special.ndtri(pfa)) ** 2 / (2.0 * n))
    out = np.empty(pd.shape)
    for idx in np.ndindex(pd.shape):
        target, false_alarm = float(pd[idx]), float(pfa[idx])

        def gap(snr_db: float, target: float = target, false_alarm: float = false_alarm) -> float:
            chi = 10.0 ** (snr_db / 10.0)
            return float(pulse_detection_probability(chi, false_alarm, n, swerling=swerling)) - target

        lo, hi = -60.0, 20.0
        while gap(hi) < 0.0:
            if hi > 200.0:
                raise ValueError(f"p_d = {target} is not reached below an SNR of 200 dB")
            hi += 20.0
        out[idx] = 10.0 ** (optimize.brentq(gap, lo, hi, xtol=1e-10) / 10.0)
    return out


check_public(
    globals(),
    {"p_fa": OPEN_PROBABILITY, "p_d": OPEN_PROBABILITY, "snr": NONNEGATIVE, "n_pulses": Range(1, 100_000)},
)
