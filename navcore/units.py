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
#: Speed of light in vacuum, m/s: 299 792 458 m/s exactly (the SI definition of the metre).
C = 299_792_458.0
#: Standard gravity :math:`g_0`, m/s²: 9.806 65 m/s² exactly (3rd CGPM, 1901).
G0 = 9.806_65
#: Earth's rotation rate, rad/s: the WGS-84 value :math:`7.292\,115 \times 10^{-5}` rad/s
#: (NIMA TR8350.2).
OMEGA_EARTH = 7.292_115e-5
#: WGS-84 semi-major axis :math:`a`, m: 6 378 137 m (a defining parameter of WGS-84, NIMA TR8350.2).
WGS84_A = 6_378_137.0
#: WGS-84 flattening :math:`f = 1/298.257\,223\,563` (a defining parameter, NIMA
#: TR8350.2), dimensionless.
WGS84_F = 1.0 / 298.257_223_563
#: WGS-84 semi-minor axis :math:`b = a(1 - f)`, m, derived from :data:`WGS84_A` and :data:`WGS84_F`.
WGS84_B = WGS84_A * (1.0 - WGS84_F)
#: WGS-84 first eccentricity squared :math:`e^2 = f(2 - f)`, dimensionless, derived from
#: :data:`WGS84_F`.
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)

#: GPS L1 carrier frequency :math:`f_{L1}`, Hz: 1575.42 MHz, 154 times the 10.23 MHz
#: fundamental (IS-GPS-200).
GPS_L1_HZ = 1_575.42e6
#: GPS L1 carrier wavelength :math:`c/f_{L1}`, m, derived from :data:`C` and :data:`GPS_L1_HZ`.
GPS_L1_WAVELENGTH_M = C / GPS_L1_HZ
#: GPS C/A-code chipping rate, chips/s (Hz): 1.023 MHz (IS-GPS-200).
GPS_CA_CHIP_RATE_HZ = 1.023e6
#: Length of one C/A-code chip, m: :data:`C` divided by :data:`GPS_CA_CHIP_RATE_HZ`.
GPS_CA_CHIP_M = C / GPS_CA_CHIP_RATE_HZ
#: GPS P(Y)-code chipping rate, chips/s (Hz): 10.23 MHz (IS-GPS-200).
GPS_P_CHIP_RATE_HZ = 10.23e6
#: Length of one P(Y)-code chip, m: :data:`C` divided by :data:`GPS_P_CHIP_RATE_HZ`.
GPS_P_CHIP_M = C / GPS_P_CHIP_RATE_HZ

# --- length and speed ------------------------------------------------------------------
#: One international foot, in metres: 0.3048 m exactly (1959 agreement).
FT = 0.3048
#: One international nautical mile, in metres: 1852 m exactly.
NMI = 1852.0
#: One international statute mile, in metres: 5280 ft, 1609.344 m exactly.
MILE = 1609.344
#: One kilometre, in metres.
KM = 1000.0
#: One hour, in seconds.
HOUR = 3600.0
#: One minute, in seconds.
MINUTE = 60.0
#: One mile per hour, in m/s (:data:`MILE` / :data:`HOUR`).
MPH = MILE / HOUR
#: One knot (one nautical mile per hour), in m/s (:data:`NMI` / :data:`HOUR`).
KNOT = NMI / HOUR
#: One nautical mile per hour, in m/s: the same value as :data:`KNOT`, the unit in which a
#: navigation-grade inertial system's position drift rate is quoted.
NMI_PER_H = NMI / HOUR

# --- angle -----------------------------------------------------------------------------
#: One degree, in radians (:math:`\pi/180`).
DEG = math.pi / 180.0
#: One minute of arc, in radians (:data:`DEG` / 60).
ARCMIN = DEG / 60.0
#: One second of arc, in radians (:data:`DEG` / 3600).
ARCSEC = DEG / 3600.0
#: One milliradian, in radians (:math:`10^{-3}` rad).
MRAD = 1e-3

# --- inertial sensor units -------------------------------------------------------------
#: One micro-g, in m/s²: :math:`10^{-6}\,g_0` (:data:`G0`), the unit of accelerometer bias.
MICRO_G = 1e-6 * G0
#: One milli-g, in m/s²: :math:`10^{-3}\,g_0` (:data:`G0`).
MILLI_G = 1e-3 * G0
#: One part per million (:math:`10^{-6}`), dimensionless: the unit of a scale-factor error.
PPM = 1e-6
#: One degree per hour, in rad/s: the unit of gyro drift (bias).
DEG_PER_H = DEG / HOUR
#: One degree per second, in rad/s.
DEG_PER_S = DEG
#: One degree per root hour, in :math:`\mathrm{rad}/\sqrt{\mathrm{s}}`: the unit of a gyro's
#: angle random walk.
DEG_PER_SQRT_H = DEG / math.sqrt(HOUR)
#: One degree per hour per root hertz, in :math:`(\mathrm{rad/s})/\sqrt{\mathrm{Hz}} =
#: \mathrm{rad}/\sqrt{\mathrm{s}}`: the unit of a gyro's rate-noise root spectral density
#: (numerically equal to :data:`DEG_PER_H`).
DEG_PER_H_PER_SQRT_HZ = DEG_PER_H
#: One micro-g per root hertz, in :math:`(\mathrm{m/s^2})/\sqrt{\mathrm{Hz}}`: the unit of an
#: accelerometer's noise root spectral density (numerically equal to :data:`MICRO_G`).
MICRO_G_PER_SQRT_HZ = MICRO_G
#: One metre per second per root hour, in :math:`(\mathrm{m/s})/\sqrt{\mathrm{s}}`: the unit
#: of an accelerometer's velocity random walk (:math:`1/\sqrt{3600}`).
M_PER_S_PER_SQRT_H = 1.0 / math.sqrt(HOUR)


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
