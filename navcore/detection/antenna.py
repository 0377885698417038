r"""Parabolic-dish antenna relations for jammer hardware (ATC-10 Table 1.1).

The gain of a dish of diameter ``D`` with aperture efficiency ``eta`` at wavelength
:math:`\lambda = c / f` is :math:`G = \eta (\pi D / \lambda)^2`; its half-power beamwidth is about
:math:`k \lambda / D` degrees with ``k = 70`` (a common rule for a tapered illumination). The
radiated power needed for an effective radiated power ``ERP`` is ``ERP / G``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore import units
from navcore._validate import POSITIVE, Range, as_finite_array, check_public, require_positive
from navcore.trace import implements

__all__ = [
    "beamwidth_from_gain_deg",
    "dish_beamwidth_deg",
    "dish_diameter",
    "dish_gain",
    "rf_power_dbw",
]

FloatArray = NDArray[np.float64]


def _wavelength(frequency_hz: float) -> float:
    require_positive("frequency_hz", frequency_hz)
    return units.C / frequency_hz


def _efficiency(efficiency: float) -> float:
    if not 0.0 < efficiency <= 1.0:
        raise ValueError("efficiency must lie in (0, 1]")
    return efficiency


@implements("ATC10 Table 1.1")
def dish_gain(diameter_m: ArrayLike, frequency_hz: float, efficiency: float) -> FloatArray:
    r"""Linear gain :math:`\eta (\pi D / \lambda)^2` of a parabolic dish.

    Parameters
    ----------
    diameter_m : array_like
        Dish diameter, m (``> 0``).
    frequency_hz : float
        Carrier frequency, Hz (``> 0``).
    efficiency : float
        Aperture efficiency, in (0, 1].

    Returns
    -------
    ndarray
        Linear gain (dimensionless).

    Raises
    ------
    ValueError
        If the diameter or frequency is not positive or the efficiency not in (0, 1].

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Table 1.1.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(10 * np.log10(dish_gain(2 * 0.3048, 1.6e9, 0.6))), 2)
    17.97
    """
    d = as_finite_array("diameter_m", diameter_m)
    if np.any(d <= 0):
        raise ValueError("diameter_m must be > 0")
    return _efficiency(efficiency) * (np.pi * d / _wavelength(frequency_hz)) ** 2


@implements("ATC10 Table 1.1")
def dish_diameter(gain: ArrayLike, frequency_hz: float, efficiency: float) -> FloatArray:
    r"""Diameter :math:`(\lambda / \pi) \sqrt{G / \eta}` giving linear gain ``G``.

    Parameters
    ----------
    gain : array_like
        Linear gain (``> 0``).
    frequency_hz : float
        Carrier frequency, Hz (``> 0``).
    efficiency : float
        Aperture efficiency ``eta``, in (0, 1].

    Returns
    -------
    ndarray
        Diameter, m.

    Raises
    ------
    ValueError
        If the gain or frequency is not positive or the efficiency not in (0, 1].

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Table 1.1.

    Examples
    --------
    >>> round(float(dish_diameter(dish_gain(0.6096, 1.6e9, 0.6), 1.6e9, 0.6)), 6)
    0.6096
    """
    g = as_finite_array("gain", gain)
    if np.any(g <= 0):
        raise ValueError("gain must be > 0")
    return _wavelength(frequency_hz) / np.pi * np.sqrt(g / _efficiency(efficiency))


@implements("ATC10 Table 1.1")
def dish_beamwidth_deg(diameter_m: ArrayLike, frequency_hz: float, factor_deg: float = 70.0) -> FloatArray:
    r"""Half-power beamwidth :math:`k \lambda / D` in degrees, :math:`k` = ``factor_deg`` (70 by default).

    Parameters
    ----------
    diameter_m : array_like
        Dish diameter, m (``> 0``).
    frequency_hz : float
        Carrier frequency, Hz (``> 0``).
    factor_deg : float, default 70.0
        Beamwidth factor, deg (``> 0``).

    Returns
    -------
    ndarray
        Half-power beamwidth, deg.

    Raises
    ------
    ValueError
        If an argument is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Table 1.1.

    Examples
    --------
    >>> round(float(dish_beamwidth_deg(2 * 0.3048, 1.6e9)), 2)
    21.52
    """
    d = as_finite_array("diameter_m", diameter_m)
    if np.any(d <= 0):
        raise ValueError("diameter_m must be > 0")
    require_positive("factor_deg", factor_deg)
    return factor_deg * _wavelength(frequency_hz) / d


def beamwidth_from_gain_deg(gain: ArrayLike, constant_deg2: float = 27000.0) -> FloatArray:
    r"""Pencil-beam rule ``theta = sqrt(C / G)`` degrees (:math:`G \approx C / \theta^2`).

    Parameters
    ----------
    gain : array_like
        Linear antenna gain (``> 0``).
    constant_deg2 : float, default 27000.0
        The rule's constant ``C`` in square degrees (``> 0``): 41 253 (the square degrees of a
        sphere) for an ideal beam that radiates all its power inside its half-power cone;
        practical dishes, with their sidelobes and tapered illumination, lie between about 26 000
        and 33 000.

    Returns
    -------
    ndarray
        Half-power beamwidth, deg.

    Raises
    ------
    ValueError
        If a gain or the constant is not positive.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Table 1.1 (antenna sizes).

    Examples
    --------
    >>> round(float(beamwidth_from_gain_deg(100.0)), 3)
    16.432
    >>> round(float(beamwidth_from_gain_deg(100.0, constant_deg2=41253.0)), 3)
    20.311
    """
    g = as_finite_array("gain", gain)
    if np.any(g <= 0):
        raise ValueError("gain must be > 0")
    require_positive("constant_deg2", constant_deg2)
    return np.sqrt(constant_deg2 / g)


@implements("ATC10 Table 1.1")
def rf_power_dbw(erp_dbw: ArrayLike, gain_db: ArrayLike) -> FloatArray:
    """Transmitter rf power ``ERP - G`` in dBW for an ERP in dBW and an antenna gain in dB.

    Parameters
    ----------
    erp_dbw : array_like
        Effective radiated power, dBW.
    gain_db : array_like
        Antenna gain, dB.

    Returns
    -------
    ndarray
        Transmitter power, dBW.

    Raises
    ------
    ValueError
        If an input is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Table 1.1.

    Examples
    --------
    >>> float(rf_power_dbw(33.0, 18.0))
    15.0
    """
    return as_finite_array("erp_dbw", erp_dbw) - as_finite_array("gain_db", gain_db)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "diameter_m": POSITIVE,
        "efficiency": Range(0.0, 1.0, low_open=True),
        "frequency_hz": POSITIVE,
        "gain": POSITIVE,
        "factor_deg": POSITIVE,
        "constant_deg2": POSITIVE,
    },
)
