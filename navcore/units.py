"""Physical constants and unit conversions used by the four papers.

Every conversion factor multiplies a value in the named unit to give SI::

    sigma_a = 100 * MICRO_G          # 100 micro-g -> m/s²
    drift = 0.01 * DEG_PER_H         # 0.01 deg/h -> rad/s
    x_nmi = x_m / NMI                # metres -> nautical miles

Constants
---------
C : speed of light in vacuum, m/s (exact, SI definition).
G0 : standard gravity, m/s² (exact, CGPM 1901).
OMEGA_EARTH : Earth rotation rate, rad/s (WGS-84).
WGS84_A, WGS84_F, WGS84_E2 : WGS-84 semi-major axis (m), flattening and first
eccentricity squared.
GPS_L1_HZ : GPS L1 carrier frequency, Hz; GPS_L1_WAVELENGTH_M its wavelength.
GPS_CA_CHIP_RATE_HZ : C/A-code chipping rate; GPS_CA_CHIP_M its chip length in metres.
GPS_P_CHIP_RATE_HZ : P(Y)-code chipping rate; GPS_P_CHIP_M its chip length.

References
----------
.. [1] NIMA TR8350.2, "Department of Defense World Geodetic System 1984", 3rd ed., 2000.
.. [2] IS-GPS-200, "Navstar GPS Space Segment/Navigation User Interfaces".
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from navcore._validate import check_public, require_positive

__all__ = [
    "ARCMIN",
    "ARCSEC",
    "DEG",
    "DEG_PER_H",
    "DEG_PER_H_PER_SQRT_HZ",
    "DEG_PER_S",
    "DEG_PER_SQRT_H",
    "FT",
    "G0",
    "GPS_CA_CHIP_M",
    "GPS_CA_CHIP_RATE_HZ",
    "GPS_L1_HZ",
    "GPS_L1_WAVELENGTH_M",
    "GPS_P_CHIP_M",
    "GPS_P_CHIP_RATE_HZ",
    "HOUR",
    "KM",
    "KNOT",
    "MAX_DB",
    "MICRO_G",
    "MICRO_G_PER_SQRT_HZ",
    "MILE",
    "MILLI_G",
    "MINUTE",
    "MPH",
    "MRAD",
    "M_PER_S_PER_SQRT_H",
    "NMI",
    "NMI_PER_H",
    "OMEGA_EARTH",
    "PPM",
    "WGS84_A",
    "WGS84_B",
    "WGS84_E2",
    "WGS84_F",
    "C",
    "amplitude_ratio_from_db",
    "db_from_amplitude_ratio",
    "db_from_power_ratio",
    "dbw_from_watts",
    "power_ratio_from_db",
    "watts_from_dbw",
]

# --- constants -------------------------------------------------------------------------
C = 299_792_458.0
G0 = 9.806_65
OMEGA_EARTH = 7.292_115e-5
WGS84_A = 6_378_137.0
WGS84_F = 1.0 / 298.257_223_563
WGS84_B = WGS84_A * (1.0 - WGS84_F)
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)

GPS_L1_HZ = 1_575.42e6
GPS_L1_WAVELENGTH_M = C / GPS_L1_HZ
GPS_CA_CHIP_RATE_HZ = 1.023e6
GPS_CA_CHIP_M = C / GPS_CA_CHIP_RATE_HZ
GPS_P_CHIP_RATE_HZ = 10.23e6
GPS_P_CHIP_M = C / GPS_P_CHIP_RATE_HZ

# --- length and speed ------------------------------------------------------------------
FT = 0.3048
NMI = 1852.0
MILE = 1609.344
KM = 1000.0
HOUR = 3600.0
MINUTE = 60.0
MPH = MILE / HOUR
KNOT = NMI / HOUR
NMI_PER_H = NMI / HOUR  # a navigation-grade drift rate is quoted in nmi/h

# --- angle -----------------------------------------------------------------------------
DEG = math.pi / 180.0
ARCMIN = DEG / 60.0
ARCSEC = DEG / 3600.0
MRAD = 1e-3

# --- inertial sensor units -------------------------------------------------------------
MICRO_G = 1e-6 * G0
MILLI_G = 1e-3 * G0
PPM = 1e-6
DEG_PER_H = DEG / HOUR
DEG_PER_S = DEG
DEG_PER_SQRT_H = DEG / math.sqrt(HOUR)  # angle random walk -> rad/sqrt(s)
DEG_PER_H_PER_SQRT_HZ = DEG_PER_H  # root PSD of rate noise: (rad/s)/sqrt(Hz) = rad/sqrt(s)
MICRO_G_PER_SQRT_HZ = MICRO_G  # root PSD of accel noise: (m/s^2)/sqrt(Hz)
M_PER_S_PER_SQRT_H = 1.0 / math.sqrt(HOUR)  # velocity random walk -> m/s/sqrt(s)


# --- decibels --------------------------------------------------------------------------
#: Largest magnitude (dB) a decibel value may have: :math:`10^{3000/10}` is near the largest double.
MAX_DB = 3000.0


def _from_db(name: str, db: ArrayLike, per_decade: float) -> np.ndarray | float:
    arr = np.asarray(db, dtype=float)
    if arr.size and np.max(np.abs(arr)) > MAX_DB:
        raise ValueError(f"{name} must lie in [-{MAX_DB:g}, {MAX_DB:g}] dB (a finite ratio), got {db!r}")
    out = np.power(10.0, arr / per_decade)
    return float(out) if np.ndim(out) == 0 else out


def db_from_power_ratio(ratio: ArrayLike) -> np.ndarray | float:
    """Return ``10 log10(ratio)``, a power ratio in decibels.

    Parameters
    ----------
    ratio : float or array_like
        Power ratio (dimensionless), ``> 0``.

    Returns
    -------
    float or ndarray
        The ratio in dB (a float for scalar input).

    Raises
    ------
    ValueError
        If ``ratio`` is not positive and finite.

    Examples
    --------
    >>> db_from_power_ratio(100.0)
    20.0
    """
    require_positive("ratio", ratio)
    out = 10.0 * np.log10(np.asarray(ratio, dtype=float))
    return float(out) if np.ndim(out) == 0 else out


def power_ratio_from_db(db: ArrayLike) -> np.ndarray | float:
    """Return the power ratio ``10**(db/10)``.

    Parameters
    ----------
    db : float or array_like
        Power ratio in dB, finite, of magnitude at most :data:`MAX_DB`.

    Returns
    -------
    float or ndarray
        The power ratio (dimensionless; a float for scalar input).

    Raises
    ------
    ValueError
        If ``db`` is not finite or its magnitude exceeds :data:`MAX_DB`.

    Examples
    --------
    >>> round(power_ratio_from_db(-3.0), 4)
    0.5012
    """
    return _from_db("db", db, 10.0)


def db_from_amplitude_ratio(ratio: ArrayLike) -> np.ndarray | float:
    """Return ``20 log10(ratio)``, an amplitude (root-power) ratio in decibels.

    Parameters
    ----------
    ratio : float or array_like
        Amplitude ratio (dimensionless), ``> 0``.

    Returns
    -------
    float or ndarray
        The ratio in dB.

    Raises
    ------
    ValueError
        If ``ratio`` is not positive and finite.

    Examples
    --------
    >>> db_from_amplitude_ratio(10.0)
    20.0
    """
    require_positive("ratio", ratio)
    out = 20.0 * np.log10(np.asarray(ratio, dtype=float))
    return float(out) if np.ndim(out) == 0 else out


def amplitude_ratio_from_db(db: ArrayLike) -> np.ndarray | float:
    """Return the amplitude ratio ``10**(db/20)``.

    Parameters
    ----------
    db : float or array_like
        Amplitude ratio in dB, finite, of magnitude at most :data:`MAX_DB`.

    Returns
    -------
    float or ndarray
        The amplitude ratio (dimensionless).

    Raises
    ------
    ValueError
        If ``db`` is not finite or its magnitude exceeds :data:`MAX_DB`.

    Examples
    --------
    >>> amplitude_ratio_from_db(20.0)
    10.0
    """
    return _from_db("db", db, 20.0)


def dbw_from_watts(power_w: ArrayLike) -> np.ndarray | float:
    """Return a power in dBW (decibels relative to 1 W).

    Parameters
    ----------
    power_w : float or array_like
        Power (W), ``> 0``.

    Returns
    -------
    float or ndarray
        The power in dBW.

    Raises
    ------
    ValueError
        If ``power_w`` is not positive and finite.

    Examples
    --------
    >>> dbw_from_watts(1000.0)
    30.0
    """
    require_positive("power_w", power_w)
    return db_from_power_ratio(power_w)


def watts_from_dbw(power_dbw: ArrayLike) -> np.ndarray | float:
    """Return a power in watts from dBW.

    Parameters
    ----------
    power_dbw : float or array_like
        Power in dBW, finite, of magnitude at most :data:`MAX_DB`.

    Returns
    -------
    float or ndarray
        The power (W).

    Raises
    ------
    ValueError
        If ``power_dbw`` is not finite or its magnitude exceeds :data:`MAX_DB`.

    Examples
    --------
    >>> watts_from_dbw(30.0)
    1000.0
    """
    return _from_db("power_dbw", power_dbw, 10.0)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals())
