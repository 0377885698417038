r"""Zakai bandwidth and the multiple-access noise power of PSK signatures (ATC-10 Sec. 3.9, App. F).

The Zakai bandwidth of a unit-energy signal with autocorrelation :math:`R(t)` is
:math:`W = \left[2 \int R(t)^2\, dt\right]^{-1}` (Theorem 3.3). For rectangular-chip PSK
sequences :math:`R` is piecewise linear between multiples of the chip duration, so the
integral is exact from the chip-lag samples :math:`R_k`:

.. math::

    \int R^2\, dt = \tau_c \sum_k \frac{R_k^2 + R_k R_{k+1} + R_{k+1}^2}{3}.

Appendix F shows :math:`E(n^2) = \frac{1}{2 \alpha} \sum_j \int R_{ii} R_{jj}` (Eq. F.6)
and, by Cauchy-Schwarz, :math:`E(n^2) \le \sum_j 1/(4 \alpha \sqrt{W_i W_j})` with equality
when all autocorrelations are equal, giving :math:`(N-1)/(4 \alpha W)` (Eq. 3.9.2).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT0,
    POSITIVE,
    Range,
    check_public,
    require_integer,
    require_positive,
)
from navcore.trace import implements

__all__ = [
    "alternating_sidelobe_autocorrelation",
    "aperiodic_autocorrelation",
    "barker_code",
    "cross_term_noise_power",
    "equal_autocorrelation_noise_power",
    "m_sequence",
    "paper_psk_zakai_bandwidth",
    "piecewise_linear_energy",
    "piecewise_linear_inner",
    "psk_zakai_bandwidth",
    "zakai_bandwidth",
    "zakai_noise_power_bound",
]

FloatArray = NDArray[np.float64]

_BARKER = {
    2: (1, -1),
    3: (1, 1, -1),
    4: (1, 1, -1, 1),
    5: (1, 1, 1, -1, 1),
    7: (1, 1, 1, -1, -1, 1, -1),
    11: (1, 1, 1, -1, -1, -1, 1, -1, -1, 1, -1),
    13: (1, 1, 1, 1, 1, -1, -1, 1, 1, -1, 1, -1, 1),
}
# Primitive polynomial taps (Fibonacci LFSR, x^n + ... ), degree -> feedback taps (1-based).
_MSEQ_TAPS = {3: (3, 2), 4: (4, 3), 5: (5, 3), 6: (6, 5), 7: (7, 6), 8: (8, 6, 5, 4), 9: (9, 5), 10: (10, 7)}


def barker_code(length: int) -> FloatArray:
    r"""The Barker code of the given length (2, 3, 4, 5, 7, 11 or 13) as :math:`\pm 1`.

    Parameters
    ----------
    length : int
        Code length.

    Returns
    -------
    (length,) ndarray
        Chips, +-1.

    Raises
    ------
    ValueError
        If no Barker code has that length.

    Examples
    --------
    >>> barker_code(7).astype(int).tolist()
    [1, 1, 1, -1, -1, 1, -1]
    """
    if length not in _BARKER:
        raise ValueError(f"length must be one of {sorted(_BARKER)}, got {length}")
    return np.array(_BARKER[length], dtype=float)


def m_sequence(degree: int) -> FloatArray:
    r"""A maximal-length sequence of length :math:`2^d - 1` (:math:`d` = ``degree``, 3 to 10) as
    :math:`\pm 1`, from a Fibonacci LFSR.

    Parameters
    ----------
    degree : int
        Register length, 3..10.

    Returns
    -------
    (2^degree - 1,) ndarray
        Chips, +-1.

    Raises
    ------
    ValueError
        If ``degree`` is not in 3..10.

    Examples
    --------
    >>> c = m_sequence(3)
    >>> c.size, int(c.sum())
    (7, -1)
    """
    if degree not in _MSEQ_TAPS:
        raise ValueError(f"degree must be one of {sorted(_MSEQ_TAPS)}, got {degree}")
    taps = _MSEQ_TAPS[degree]
    state = [1] * degree
    out = []
    for _ in range(2**degree - 1):
        out.append(state[-1])
        fb = 0
        for t in taps:
            fb ^= state[t - 1]
        state = [fb, *state[:-1]]
    return 1.0 - 2.0 * np.array(out, dtype=float)


def aperiodic_autocorrelation(code: ArrayLike) -> FloatArray:
    r""":math:`R_k / R_0` of a :math:`\pm 1` (or real) chip sequence at lags
    :math:`-(L-1), \dots, L-1`, unit-peak normalised.

    Parameters
    ----------
    code : array_like
        Chip sequence (dimensionless).

    Returns
    -------
    (2 L - 1,) ndarray
        Normalised aperiodic autocorrelation.

    Raises
    ------
    ValueError
        If ``code`` is empty or all zero.

    Examples
    --------
    >>> aperiodic_autocorrelation(barker_code(3)).round(6).tolist()
    [-0.333333, 0.0, 1.0, 0.0, -0.333333]
    """
    c = np.asarray(code, dtype=float).ravel()
    if c.size < 1:
        raise ValueError("code must be non-empty")
    r = np.correlate(c, c, mode="full")
    if r[c.size - 1] <= 0.0:
        raise ValueError("code must have nonzero energy (not all chips zero)")
    return r / r[c.size - 1]


def _closed(samples: ArrayLike) -> FloatArray:
    s = np.asarray(samples, dtype=float).ravel()
    return np.concatenate([[0.0], s, [0.0]])


def piecewise_linear_energy(samples: ArrayLike, spacing: float) -> float:
    """Exact integral of :math:`R(t)^2` for :math:`R` linear between samples ``spacing`` apart
    and zero outside.

    Parameters
    ----------
    samples : array_like
        Samples of R (dimensionless).
    spacing : float
        Sample spacing, s (``> 0``).

    Returns
    -------
    float
        The integral, s.

    Raises
    ------
    ValueError
        If ``spacing`` is not positive.

    Examples
    --------
    >>> round(piecewise_linear_energy([1.0], 1.0), 6)
    0.666667
    """
    require_positive("spacing", spacing)
    r = _closed(samples)
    return float(spacing * np.sum(r[:-1] ** 2 + r[:-1] * r[1:] + r[1:] ** 2) / 3.0)


def piecewise_linear_inner(f: ArrayLike, g: ArrayLike, spacing: float) -> float:
    """Exact integral of :math:`f(t) g(t)` for two piecewise-linear functions on the same
    sample grid.

    Parameters
    ----------
    f : array_like
        Samples of f.
    g : array_like
        Samples of g (same number).
    spacing : float
        Sample spacing, s (``> 0``).

    Returns
    -------
    float
        The integral, s times the units of f and g.

    Raises
    ------
    ValueError
        If ``spacing`` is not positive or the sample counts differ.

    Examples
    --------
    >>> round(piecewise_linear_inner([1.0], [1.0], 1.0), 6)
    0.666667
    """
    require_positive("spacing", spacing)
    a, b = _closed(f), _closed(g)
    if a.shape != b.shape:
        raise ValueError("f and g must have the same number of samples")
    return float(
        spacing * np.sum(2 * a[:-1] * b[:-1] + a[:-1] * b[1:] + a[1:] * b[:-1] + 2 * a[1:] * b[1:]) / 6.0
    )


def zakai_bandwidth(samples: ArrayLike, spacing: float) -> float:
    r""":math:`W = \left[2 \int R^2\, dt\right]^{-1}` (Theorem 3.3) for a piecewise-linear,
    unit-peak autocorrelation.

    Parameters
    ----------
    samples : array_like
        Samples of R (unit peak).
    spacing : float
        Sample spacing, s (``> 0``).

    Returns
    -------
    float
        Zakai bandwidth, Hz.

    Raises
    ------
    ValueError
        If ``spacing`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Theorem 3.3.

    Examples
    --------
    >>> round(zakai_bandwidth([1.0], 1e-6) / 1e3, 3)
    750.0
    """
    return 1.0 / (2.0 * piecewise_linear_energy(samples, spacing))


def psk_zakai_bandwidth(code: ArrayLike, chip_s: float) -> float:
    """Zakai bandwidth of a rectangular-chip PSK signature with the given chip sequence.

    Parameters
    ----------
    code : array_like
        Chip sequence.
    chip_s : float
        Chip duration, s.

    Returns
    -------
    float
        Zakai bandwidth ``W``, Hz.

    Raises
    ------
    ValueError
        If ``code`` is empty or all zero.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Theorem 3.3 and Sec. 3.9.

    Examples
    --------
    >>> round(psk_zakai_bandwidth(barker_code(13), 1e-6) / 1e3, 2)
    700.28
    """
    return zakai_bandwidth(aperiodic_autocorrelation(code), chip_s)


def alternating_sidelobe_autocorrelation(
    n_chips: int, n_sidelobes: int, first_sign: float = 1.0
) -> FloatArray:
    r"""Idealised 'good' PSK autocorrelation (cf. ATC-10 Fig. 3.11): peak 1, sidelobes
    :math:`\pm 1/L` alternating.

    Parameters
    ----------
    n_chips : int
        Code length ``L`` (``>= 1``).
    n_sidelobes : int
        Number of sidelobes on each side (``>= 0``).
    first_sign : float, default 1.0
        Sign (and scale) of the first sidelobe.

    Returns
    -------
    (2 n_sidelobes + 1,) ndarray
        Normalised autocorrelation at lags :math:`-s, \dots, s` with :math:`s` = ``n_sidelobes``
        (chip units).

    Raises
    ------
    ValueError
        If ``n_chips`` or ``n_sidelobes`` is not a valid integer.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.9 and Fig. 3.11.

    Examples
    --------
    >>> alternating_sidelobe_autocorrelation(4, 2).tolist()
    [-0.25, 0.25, 1.0, 0.25, -0.25]
    """
    require_integer("n_chips", n_chips, minimum=1)
    require_integer("n_sidelobes", n_sidelobes, minimum=0)
    k = np.arange(1, n_sidelobes + 1)
    side = first_sign * (-1.0) ** (k - 1) / n_chips
    return np.concatenate([side[::-1], [1.0], side])


def paper_psk_zakai_bandwidth(chip_s: float, tau_s: float) -> float:
    r"""The printed :math:`W = [(4/3) \tau_c (1 + 2 \tau_c/\tau + 2 (\tau_c/\tau)^2)]^{-1}`
    (Sec. 3.9).

    Parameters
    ----------
    chip_s : float
        Chip duration ``tau_c``, s.
    tau_s : float
        Pulse duration ``tau``, s.

    Returns
    -------
    float
        Zakai bandwidth as printed, Hz.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 3.9.

    Examples
    --------
    >>> round(paper_psk_zakai_bandwidth(1e-6, 1e-4) / 1e3, 3)
    735.15
    """
    r = chip_s / tau_s
    return 1.0 / (4.0 / 3.0 * chip_s * (1.0 + 2.0 * r + 2.0 * r**2))


@implements("ATC10 3.9.2")
def equal_autocorrelation_noise_power(n_aircraft: int, alpha_s: float, zakai_w_hz: float) -> float:
    r""":math:`E(n^2) = (N - 1)/(4 \alpha W)` when all signatures share one autocorrelation
    (Eq. 3.9.2).

    Parameters
    ----------
    n_aircraft : int
        Number of aircraft ``N``.
    alpha_s : float
        Repetition period, s (``> 0``).
    zakai_w_hz : float
        Zakai bandwidth ``W``, Hz (``> 0``).

    Returns
    -------
    float
        Mean cross-term noise power (dimensionless).

    Raises
    ------
    ValueError
        If ``alpha_s`` or ``zakai_w_hz`` is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (3.9.2).

    Examples
    --------
    >>> equal_autocorrelation_noise_power(101, 1.0, 25.0)
    1.0
    """
    require_positive("alpha_s", alpha_s)
    require_positive("zakai_w_hz", zakai_w_hz)
    return (n_aircraft - 1) / (4.0 * alpha_s * zakai_w_hz)


def zakai_noise_power_bound(w_i_hz: float, w_j_hz: ArrayLike, alpha_s: float) -> float:
    r"""Theorem 3.3 (corrected, erratum E3-6): :math:`E(n^2) \le \sum_j 1/(4 \alpha \sqrt{W_i W_j})`.

    Parameters
    ----------
    w_i_hz : float
        Zakai bandwidth of the wanted signature, Hz.
    w_j_hz : array_like
        Zakai bandwidths of the interferers, Hz.
    alpha_s : float
        Repetition period, s.

    Returns
    -------
    float
        Bound on the mean cross-term noise power (dimensionless).

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Theorem 3.3 and erratum E3-6.

    Examples
    --------
    >>> round(zakai_noise_power_bound(25.0, [25.0] * 100, 1.0), 12)
    1.0
    """
    wj = np.asarray(w_j_hz, dtype=float)
    return float(np.sum(1.0 / (4.0 * alpha_s * np.sqrt(w_i_hz * wj))))


@implements("ATC10 F.6")
def cross_term_noise_power(
    code_i: ArrayLike, codes_j: list[ArrayLike], chip_s: float, alpha_s: float
) -> float:
    r""":math:`E(n^2) = \frac{1}{2 \alpha} \sum_j \int R_{ii} R_{jj}` (Eq. F.6), exact for
    rectangular chips.


    Parameters
    ----------
    code_i : array_like
        Chip sequence of the wanted signature.
    codes_j : list of array_like
        Chip sequences of the interfering signatures (same length).
    chip_s : float
        Chip duration, s.
    alpha_s : float
        Repetition period ``alpha``, s.

    Returns
    -------
    float
        Mean cross-term noise power, relative to a unit-peak correlation (dimensionless).

    Raises
    ------
    ValueError
        If a code is empty or the codes differ in length.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Appendix F, Eq. (F.6).

    Examples
    --------
    >>> c = barker_code(7)
    >>> f"{cross_term_noise_power(c, [c, -c], 1e-6, 1.0):.4e}"
    '7.4830e-07'
    """
    if np.size(code_i) < 1:
        raise ValueError("code_i must be non-empty")
    ri = aperiodic_autocorrelation(code_i)
    total = 0.0
    for cj in codes_j:
        rj = aperiodic_autocorrelation(cj)
        if rj.size != ri.size:
            raise ValueError(
                f"codes_j: every code must have the length of code_i ({np.size(code_i)} chips), got one "
                f"whose autocorrelation has {rj.size} lags against {ri.size}"
            )
        total += piecewise_linear_inner(ri, rj, chip_s)
    return total / (2.0 * alpha_s)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "alpha_s": POSITIVE,
        "chip_s": POSITIVE,
        "tau_s": POSITIVE,
        "w_i_hz": POSITIVE,
        "w_j_hz": POSITIVE,
        "zakai_w_hz": POSITIVE,
        "degree": Range(2, 20),
        "length": Range(1, 100000),
        "n_chips": Range(1, 100000),
        "n_aircraft": Range(1.0, None),
        "n_sidelobes": COUNT0,
        "spacing": POSITIVE,
    },
)
