r"""Acquisition search time over a code-phase by Doppler uncertainty region.

A receiver reacquiring a satellite searches cells of code phase (size :math:`\Delta r`) and
frequency (size :math:`\Delta v` in range rate), dwelling :math:`T` in each. Searching the
:math:`\pm k\sigma` region takes (SP Sec. 2.5, the :math:`\Delta T` formula)

.. math::

    \Delta T = T\,\Big\lceil \frac{2k\sigma_{rng}}{\Delta r}\Big\rceil
                 \Big\lceil \frac{2k\sigma_{rng\text{-}rate}}{\Delta v}\Big\rceil ,

with at least one cell in each dimension. With a 20-ms dwell the frequency cell is
:math:`1/T = 50` Hz, which is :math:`50\lambda_{L1} = 9.5` m/s of range rate.

References
----------
.. [SP] G. T. Schmidt and R. E. Phillips, "INS/GPS Integration Architecture Performance
   Comparisons", NATO RTO-EN-SET-116, Sec. 2.5 and 2.6.2, Table 2.7.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import log_ndtr

from navcore._validate import (
    COUNT,
    NONNEGATIVE,
    POSITIVE,
    as_finite_array,
    check_public,
    require_integer,
    require_positive,
)
from navcore.trace import implements

__all__ = [
    "doppler_cell_hz",
    "probability_outside_sigma_box",
    "range_rate_from_doppler",
    "search_cells",
    "search_time",
    "search_time_from_cells",
]

Array = NDArray[np.float64]


@implements("SP Table 2.7")
def search_cells(sigma: ArrayLike, cell: float, n_sigma: float = 1.0) -> Array | int:
    r"""Number of cells covering :math:`\pm n_\sigma \sigma` (:math:`n_\sigma` = ``n_sigma``):
    :math:`\lceil 2 n_\sigma \sigma / \mathrm{cell} \rceil`, at least 1.

    Parameters
    ----------
    sigma : array_like
        1-:math:`\sigma` uncertainty (``>= 0``; m, m/s or Hz, the unit of ``cell``).
    cell : float
        Cell width (``> 0``), same unit.
    n_sigma : float, default 1.0
        Half-width of the search region in sigmas (``> 0``).

    Returns
    -------
    int or ndarray of int
        Number of cells.

    Raises
    ------
    ValueError
        If ``cell`` or ``n_sigma`` is not positive or a ``sigma`` is negative.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Table 2.7 (the brackets of the search-time formula read as ceilings).

    Examples
    --------
    >>> search_cells(1230.0, 30.0), search_cells(4.0, 10.0)
    (82, 1)
    """
    require_positive("cell", cell)
    require_positive("n_sigma", n_sigma)
    s = as_finite_array("sigma", sigma)
    if np.any(s < 0):
        raise ValueError("sigma must be >= 0")
    n = np.maximum(1, np.ceil(2.0 * n_sigma * s / cell - 1e-12)).astype(int)
    return int(n) if n.ndim == 0 else n


def search_time_from_cells(
    n_range: ArrayLike, n_doppler: ArrayLike = 1, dwell_s: float = 0.020
) -> Array | float:
    """Search time: dwell per cell times the number of code-phase and Doppler cells.

    Parameters
    ----------
    n_range : array_like
        Number of code-phase cells (``>= 1``).
    n_doppler : array_like, default 1
        Number of Doppler cells (``>= 1``).
    dwell_s : float, default 0.020
        Dwell per cell, s (``> 0``).

    Returns
    -------
    float or ndarray
        Search time, s.

    Raises
    ------
    ValueError
        If ``dwell_s`` is not positive or a cell count is below 1.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.5.

    Examples
    --------
    >>> round(float(search_time_from_cells(82, 1, 0.02)), 3)
    1.64
    """
    require_positive("dwell_s", dwell_s)
    nr = as_finite_array("n_range", n_range)
    nd = as_finite_array("n_doppler", n_doppler)
    if np.any(nr < 1) or np.any(nd < 1):
        raise ValueError("n_range and n_doppler must be >= 1")
    out = dwell_s * nr * nd
    return float(out) if out.ndim == 0 else out


@implements("SP Sec. 2.5")
def search_time(
    sigma_range_m: ArrayLike,
    sigma_range_rate_mps: ArrayLike,
    *,
    dwell_s: float,
    range_cell_m: float,
    rate_cell_mps: float,
    n_sigma: float = 1.0,
) -> Array | float:
    r"""Time to search the :math:`\pm n_\sigma \sigma` region (SP Sec. 2.5 :math:`\Delta T`, brackets
    read as ceilings).

    Parameters
    ----------
    sigma_range_m : array_like
        1-:math:`\sigma` range uncertainty, m (``>= 0``).
    sigma_range_rate_mps : array_like
        1-:math:`\sigma` range-rate uncertainty, m/s (``>= 0``).
    dwell_s : float
        Dwell per cell, s (``> 0``).
    range_cell_m : float
        Code-phase cell, m (``> 0``).
    rate_cell_mps : float
        Range-rate cell, m/s (``> 0``).
    n_sigma : float, default 1.0
        Half-width of the search region in sigmas.

    Returns
    -------
    float or ndarray
        Search time, s.

    Raises
    ------
    ValueError
        If a cell, the dwell or ``n_sigma`` is not positive or an uncertainty negative.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.5 and Table 2.7.

    Examples
    --------
    >>> round(search_time(1230.0, 4.0, dwell_s=0.020, range_cell_m=30.0, rate_cell_mps=10.0), 3)
    1.64
    """
    nr = search_cells(sigma_range_m, range_cell_m, n_sigma)
    nd = search_cells(sigma_range_rate_mps, rate_cell_mps, n_sigma)
    return search_time_from_cells(nr, nd, dwell_s)


@implements("SP Sec. 2.5")
def doppler_cell_hz(dwell_s: float) -> float:
    """Frequency cell of a coherent dwell: ``1/T``.

    Parameters
    ----------
    dwell_s : float
        Coherent dwell, s (``> 0``).

    Returns
    -------
    float
        Doppler cell width, Hz.

    Raises
    ------
    ValueError
        If ``dwell_s`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.5 (acquisition search).

    Examples
    --------
    >>> doppler_cell_hz(0.02)
    50.0
    """
    require_positive("dwell_s", dwell_s)
    return 1.0 / dwell_s


def range_rate_from_doppler(doppler_hz: ArrayLike, wavelength_m: float) -> Array | float:
    r"""Range rate corresponding to a Doppler shift: :math:`f \lambda`.

    Parameters
    ----------
    doppler_hz : array_like
        Doppler shift, Hz.
    wavelength_m : float
        Carrier wavelength, m (``> 0``).

    Returns
    -------
    float or ndarray
        Range rate, m/s.

    Raises
    ------
    ValueError
        If ``wavelength_m`` is not positive or a shift is not finite.

    Examples
    --------
    >>> round(float(range_rate_from_doppler(50.0, 0.2)), 6)
    10.0
    """
    require_positive("wavelength_m", wavelength_m)
    out = as_finite_array("doppler_hz", doppler_hz) * wavelength_m
    return float(out) if out.ndim == 0 else out


def probability_outside_sigma_box(n_dims: int = 1, k: float = 1.0) -> float:
    r"""Probability that an n-D standard Gaussian falls outside the :math:`\pm k \sigma` box.

    :math:`1 - (1 - 2\Phi(-k))^n`, evaluated as :math:`1 - (1 - 2\Phi(-k))^n`.

    Parameters
    ----------
    n_dims : int, default 1
        Number of independent dimensions (``>= 1``).
    k : float, default 1.0
        Half-width of the box in standard deviations (``> 0``).

    Returns
    -------
    float
        Probability in [0, 1].

    Raises
    ------
    ValueError
        If ``n_dims`` is not a positive integer or ``k`` is not positive.

    Notes
    -----
    The chance that a :math:`\pm 1 \sigma` search region of Schmidt & Phillips, Sec. 2.5, misses the
    signal.

    Examples
    --------
    >>> round(probability_outside_sigma_box(1), 4), round(probability_outside_sigma_box(2), 4)
    (0.3173, 0.5339)
    """
    n = require_integer("n_dims", n_dims, minimum=1)
    require_positive("k", k)
    two_tail = 2.0 * math.exp(float(log_ndtr(-k)))
    return -math.expm1(n * math.log1p(-two_tail))


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "dwell_s": POSITIVE,
        "wavelength_m": POSITIVE,
        "n_dims": COUNT,
        "k": NONNEGATIVE,
        "n_sigma": POSITIVE,
        "range_cell_m": POSITIVE,
        "rate_cell_mps": POSITIVE,
        "cell": POSITIVE,
        "sigma": NONNEGATIVE,
        "sigma_range_m": NONNEGATIVE,
        "sigma_range_rate_mps": NONNEGATIVE,
    },
)
