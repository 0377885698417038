r"""A nominal GPS constellation and line-of-sight geometry.

Orbits are circular with the nominal GPS elements: semi-major axis 26 559.7 km, inclination
55 deg, six planes (A-F) 60 deg apart in right ascension of the ascending node, four slots
per plane. The in-plane phasing of the four slots and the between-plane offset follow a
Walker-like 24/6/1 pattern (slots 90 deg apart, successive planes offset by 15 deg); this
is a stated, reproducible geometry, not an almanac of any particular day.

Satellite positions are computed in ECEF by rotating the inertial circular-orbit position
by the Earth rotation angle :math:`\omega_e t`.

References
----------
.. [1] IS-GPS-200 / SPS Performance Standard (2020), Sec. 3.2 (nominal 24-slot
   constellation, 55 deg inclination, semi-major axis 26 559.7 km).
.. [2] P. D. Groves (2013), Sec. 8.5.2 (satellite position from orbital elements).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    LATITUDE,
    LONGITUDE,
    POSITIVE,
    Range,
    as_finite_array,
    check_public,
    require_in_range,
    require_integer,
)
from navcore.frames import dcm_ecef_to_ned, geodetic_to_ecef
from navcore.units import DEG, OMEGA_EARTH

__all__ = [
    "EARTH_MU",
    "GPS_INCLINATION_RAD",
    "GPS_SEMI_MAJOR_AXIS_M",
    "Constellation",
    "elevation_azimuth",
    "line_of_sight",
    "nominal_gps_constellation",
    "visible",
]

#: Semi-major axis of the nominal GPS orbits, m: 26 559.7 km (the SPS Performance Standard's
#: nominal constellation).
GPS_SEMI_MAJOR_AXIS_M = 26_559_700.0
#: Inclination of the nominal GPS orbital planes, rad: 55 deg (the SPS Performance Standard's
#: nominal constellation).
GPS_INCLINATION_RAD = 55.0 * DEG
#: Earth's gravitational parameter :math:`GM`, m³/s²: the WGS-84 value
#: :math:`3.986\,004\,418 \times 10^{14}` m³/s² (NIMA TR8350.2).
EARTH_MU = 3.986_004_418e14


@dataclass(frozen=True)
class Constellation:
    """Circular-orbit constellation.

    Attributes
    ----------
    raan : (N,) array
        Right ascension of the ascending node at t = 0 (rad).
    arg_lat0 : (N,) array
        Argument of latitude at t = 0 (rad).
    inclination : float
        Orbit inclination (rad).
    radius : float
        Orbit radius (m).
    prn : (N,) int array
        Satellite labels.
    """

    raan: NDArray[np.float64]
    arg_lat0: NDArray[np.float64]
    inclination: float
    radius: float
    prn: NDArray[np.int64]

    @property
    def mean_motion(self) -> float:
        """Orbital angular rate ``sqrt(mu / r^3)`` (rad/s)."""
        return float(np.sqrt(EARTH_MU / self.radius**3))

    def positions_ecef(self, t: ArrayLike) -> NDArray[np.float64]:
        """ECEF satellite positions (m) at times ``t`` (s): shape ``(..., N, 3)``."""
        t = np.asarray(t, dtype=float)[..., None]
        u = self.arg_lat0 + self.mean_motion * t  # argument of latitude
        lon_node = self.raan - OMEGA_EARTH * t  # node longitude in the rotating frame
        ci, si = np.cos(self.inclination), np.sin(self.inclination)
        cu, su = np.cos(u), np.sin(u)
        cO, sO = np.cos(lon_node), np.sin(lon_node)
        x = self.radius * (cu * cO - su * ci * sO)
        y = self.radius * (cu * sO + su * ci * cO)
        z = self.radius * (su * si)
        return np.stack([x, y, z], axis=-1)

    def velocities_ecef(self, t: ArrayLike, dt: float = 0.5) -> NDArray[np.float64]:
        """ECEF satellite velocities (m/s) by central difference of :meth:`positions_ecef`."""
        t = np.asarray(t, dtype=float)
        return (self.positions_ecef(t + dt) - self.positions_ecef(t - dt)) / (2 * dt)


def nominal_gps_constellation(
    n_planes: int = 6,
    per_plane: int = 4,
    phase_offset_deg: float = 15.0,
    raan0_deg: float = 0.0,
    inclination_deg: float | None = None,
) -> Constellation:
    """The nominal 24-satellite GPS constellation as a Walker-like pattern.

    Parameters
    ----------
    n_planes : int, default 6
        Number of orbital planes (``>= 1``).
    per_plane : int, default 4
        Slots per plane (``>= 1``).
    phase_offset_deg : float, default 15.0
        Argument-of-latitude offset between successive planes, deg.
    raan0_deg : float, default 0.0
        Right ascension of plane A at t = 0, deg, to rotate the whole pattern.
    inclination_deg : float or None, default None
        Orbit inclination, deg; ``None`` takes the GPS nominal 55 deg (:data:`GPS_INCLINATION_RAD`).

    Returns
    -------
    Constellation
        Circular orbits at the GPS inclination (55 deg) and semi-major axis, PRNs 1..N.

    Raises
    ------
    ValueError
        If ``n_planes`` or ``per_plane`` is not a positive integer.

    Notes
    -----
    A stand-in for the almanac the papers used (Schmidt & Phillips simulate a 24-satellite
    constellation); the real slots are not evenly phased.

    Examples
    --------
    >>> c = nominal_gps_constellation()
    >>> c.prn.size, c.positions_ecef(0.0).shape
    (24, (24, 3))
    """
    require_integer("n_planes", n_planes, minimum=1)
    require_integer("per_plane", per_plane, minimum=1)
    planes = np.repeat(np.arange(n_planes), per_plane)
    slots = np.tile(np.arange(per_plane), n_planes)
    raan = (raan0_deg * DEG + planes * 2 * np.pi / n_planes) % (2 * np.pi)
    arg = (slots * 2 * np.pi / per_plane + planes * phase_offset_deg * DEG) % (2 * np.pi)
    inc = GPS_INCLINATION_RAD if inclination_deg is None else inclination_deg * DEG
    return Constellation(raan, arg, inc, GPS_SEMI_MAJOR_AXIS_M, np.arange(1, planes.size + 1))


def line_of_sight(r_user: ArrayLike, r_sat: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Unit line-of-sight vectors from user to satellites and the ranges.

    Parameters
    ----------
    r_user : (3,) array
        User ECEF position, m.
    r_sat : (N, 3) array
        Satellite ECEF positions, m.

    Returns
    -------
    u : (N, 3) ndarray
        Unit vectors user -> satellite (ECEF).
    rho : (N,) ndarray
        Geometric ranges, m.

    Raises
    ------
    ValueError
        If a position is not finite.

    Examples
    --------
    >>> u, rho = line_of_sight([0.0, 0.0, 0.0], [[3.0, 4.0, 0.0]])
    >>> u.tolist(), rho.tolist()
    ([[0.6, 0.8, 0.0]], [5.0])
    """
    d = as_finite_array("r_sat", r_sat) - as_finite_array("r_user", r_user)
    rho = np.linalg.norm(d, axis=-1)
    return d / rho[..., None], rho


def elevation_azimuth(
    r_user: ArrayLike, r_sat: ArrayLike, lat: float, lon: float, *, deg: bool = False
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    r"""Elevation and azimuth of satellites seen from ``r_user`` at (lat, lon).

    Parameters
    ----------
    r_user : (3,) array
        User ECEF position, m.
    r_sat : (N, 3) array
        Satellite ECEF positions, m.
    lat : float
        User geodetic latitude, rad (deg with ``deg=True``).
    lon : float
        User longitude, rad (deg with ``deg=True``).
    deg : bool, default False
        Angles in degrees, in and out.

    Returns
    -------
    el : (N,) ndarray
        Elevation, rad (deg with ``deg=True``).
    az : (N,) ndarray
        Azimuth from north, in :math:`[0, 2\pi)` rad (deg with ``deg=True``).

    Raises
    ------
    ValueError
        If a position is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.frames import geodetic_to_ecef
    >>> r = geodetic_to_ecef(0.0, 0.0, 0.0)
    >>> el, az = elevation_azimuth(r, [r * 4.0, r + [1.0e7, 1.0e7, 0.0]], 0.0, 0.0)
    >>> np.round(np.degrees(el), 3).tolist(), np.round(np.degrees(az), 3).tolist()
    ([90.0, 45.0], [0.0, 90.0])
    """
    u, _ = line_of_sight(r_user, r_sat)
    ned = u @ dcm_ecef_to_ned(lat, lon, deg=deg).T
    el = np.arcsin(np.clip(-ned[..., 2], -1.0, 1.0))
    az = np.arctan2(ned[..., 1], ned[..., 0]) % (2 * np.pi)
    return (np.degrees(el), np.degrees(az)) if deg else (el, az)


def visible(
    constellation: Constellation,
    t: float,
    lat: float,
    lon: float,
    h: float,
    mask_deg: float = 5.0,
    *,
    deg: bool = False,
) -> NDArray[np.bool_]:
    """Mask of satellites above ``mask_deg`` elevation at time ``t`` from (lat, lon, h).

    Parameters
    ----------
    constellation : Constellation
        Satellite orbits.
    t : float
        Time, s.
    lat : float
        Latitude, rad (deg with ``deg=True``).
    lon : float
        Longitude, rad (deg with ``deg=True``).
    h : float
        Height, m.
    mask_deg : float, default 5.0
        Elevation mask, deg (in [-90, 90]; degrees whatever ``deg``, as its name says).
    deg : bool, default False
        ``lat`` and ``lon`` in degrees.

    Returns
    -------
    (N,) bool ndarray
        ``True`` for satellites at or above the mask.

    Raises
    ------
    ValueError
        If ``mask_deg`` is outside [-90, 90].

    Examples
    --------
    >>> int(visible(nominal_gps_constellation(), 0.0, 0.7, 0.0, 0.0).sum()) >= 4
    True
    """
    require_in_range("mask_deg", mask_deg, -90.0, 90.0)
    r_user = geodetic_to_ecef(lat, lon, h, deg=deg)
    el, _ = elevation_azimuth(r_user, constellation.positions_ecef(t), lat, lon, deg=deg)
    return el >= (mask_deg if deg else mask_deg * DEG)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "n_planes": Range(1, 1000),
        "per_plane": Range(1, 1000),
        "radius": POSITIVE,
        "mask_deg": Range(-90.0, 90.0),
        "lat": LATITUDE,
        "lon": LONGITUDE,
    },
)
