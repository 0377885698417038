r"""Satellite multilateration geometry: unit vectors, the matrix F and its invariants.

An aircraft's pulse is received by :math:`K` satellites; the times of arrival are linear
(after linearisation) in the aircraft position :math:`p` and the unknown emission time
:math:`\tau`,

.. math::

    T = k + \tau \mathbf{1} + F (p - p^*) + \epsilon, \qquad F = U / c,

where the rows of :math:`U` are unit vectors from the satellites to the aircraft (ATC-10
Eq. 4.2.3). navcore's lines of sight point the other way, from the aircraft (the receiver)
to each satellite (:func:`line_of_sight_matrix`, as everywhere in navcore), so
:math:`F = -U/c`; every quantity below is quadratic in :math:`F` and does not see the sign.
All the quality measures of the constellation are functions of the projector
:math:`P = F (F'F)^{-1} F'` onto the column space of :math:`F`:

* :math:`\beta = K - \mathbf{1}'P\mathbf{1} = \mathbf{1}'(I - P)\mathbf{1}` (Eq. 4.5.2, with
  the "K minus" reading of the printed ":math:`K^{-1}`", see the book's ATC-10 erratum on
  the definition of :math:`\beta`);
* :math:`\operatorname{tr}\{(F'F)^{-1}\}` (the position-only dilution);
* the clock-direction term :math:`S = \mathbf{1}'F(F'F)^{-2} F'\mathbf{1}`; for
  :math:`K = 3` it equals the rotation invariant :math:`\mathbf{1}'(FF')^{-1} \mathbf{1}`;
* the dilution :math:`k^2 = \operatorname{tr}\{(F'F)^{-1}\} + S / \beta` (Eqs. 4.1.1-4.1.2,
  4.6.2), which ATC-10
  calls the geometric dilution: it is the position dilution of precision (PDOP) of the
  time-of-arrival solution, with the emission time in the role of a receiver clock
  (:func:`position_dilution`; :func:`navcore.gnss.dop.dop_from_lines_of_sight` gives the
  same PDOP with HDOP, VDOP, TDOP and GDOP).

The geometry depends only on the ratio of the orbit radius to the Earth radius for a
spherical Earth; functions take radii in metres (any common unit works).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from navcore._validate import (
    LATITUDE,
    LONGITUDE,
    POSITIVE,
    Angle,
    as_finite_array,
    check_public,
    require_in_range,
    require_positive,
)
from navcore.trace import implements

__all__ = [
    "EARTH_MEAN_RADIUS_M",
    "GM_EARTH_M3_S2",
    "SIDEREAL_DAY_S",
    "ConstellationParameters",
    "beta_parameter",
    "clock_direction_term",
    "constellation_parameters",
    "frame_dependent_clock_term",
    "line_of_sight_matrix",
    "most_widely_spaced_triplet",
    "position_dilution",
    "position_dilution_covariance",
    "position_on_sphere",
    "position_trace",
    "synchronous_orbit_radius",
    "zenith_angles",
]

#: IUGG mean Earth radius (spherical Earth model), m.
EARTH_MEAN_RADIUS_M = 6_371_000.0
#: WGS-84 Earth gravitational constant GM, m³/s².
GM_EARTH_M3_S2 = 3.986004418e14
#: Sidereal day, s.
SIDEREAL_DAY_S = 86_164.0905


def synchronous_orbit_radius(gm: float = GM_EARTH_M3_S2, period_s: float = SIDEREAL_DAY_S) -> float:
    """Radius of a circular orbit whose period is one sidereal day (Kepler's third law).

    Parameters
    ----------
    gm : float, default GM_EARTH_M3_S2
        Gravitational parameter, m³/s² (``> 0``).
    period_s : float, default SIDEREAL_DAY_S
        Orbital period, s (``> 0``).

    Returns
    -------
    float
        Orbit radius, m.

    Raises
    ------
    ValueError
        If ``gm`` or ``period_s`` is not positive.

    Examples
    --------
    >>> round(synchronous_orbit_radius() / 1e3, 1)
    42164.2
    """
    require_positive("gm", gm)
    require_positive("period_s", period_s)
    return float(np.cbrt(gm * period_s**2 / (4.0 * math.pi**2)))


def position_on_sphere(
    lat: np.ndarray | float, lon: np.ndarray | float, radius: float, *, deg: bool = False
) -> np.ndarray:
    """Earth-centred Cartesian position at geocentric latitude/longitude on a sphere.

    Longitudes are east-positive. A synchronous satellite whose sub-satellite point is
    (lat, lon) sits at ``position_on_sphere(lat, lon, r_orbit)``.

    Parameters
    ----------
    lat : float or ndarray
        Geocentric latitude, rad (deg with ``deg=True``).
    lon : float or ndarray
        Longitude east, rad (deg with ``deg=True``).
    radius : float
        Sphere radius, m (``> 0``).
    deg : bool, default False
        The angles are in degrees.

    Returns
    -------
    (..., 3) ndarray
        Position, m.

    Raises
    ------
    ValueError
        If ``radius`` is not positive or an angle is not finite.

    Examples
    --------
    >>> (position_on_sphere(0.0, 90.0, 2.0, deg=True).round(12) + 0.0).tolist()
    [0.0, 2.0, 0.0]
    """
    require_positive("radius", radius)
    # the public-API check has made sure both angles are finite numbers
    if deg:
        lat, lon = np.radians(lat), np.radians(lon)
    return radius * np.stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)], axis=-1)


@implements("ATC10 4.2.2")
def line_of_sight_matrix(aircraft: np.ndarray, satellites: np.ndarray) -> np.ndarray:
    """Unit lines of sight from the aircraft to each satellite, one per row (K x 3).

    navcore's convention (receiver first, vectors from the receiver to the satellites, as
    :func:`navcore.gnss.constellation.line_of_sight`). With c = 1, minus this matrix is the
    matrix F of ATC-10 Eq. 4.2.2c (rows from the satellites to the aircraft); the sign is
    irrelevant to every invariant of this module, which are quadratic in F.

    Parameters
    ----------
    aircraft : (3,) array
        Aircraft position, m (Earth-centred).
    satellites : (K, 3) array
        Satellite positions, m (same frame).

    Returns
    -------
    (K, 3) ndarray
        Unit vectors aircraft -> satellite (dimensionless).

    Raises
    ------
    ValueError
        If a satellite coincides with the aircraft or an input is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.2.2c).

    Examples
    --------
    >>> line_of_sight_matrix([0.0, 0.0, 0.0], [[0.0, 0.0, 10.0], [3.0, 4.0, 0.0]]).tolist()
    [[0.0, 0.0, 1.0], [0.6, 0.8, 0.0]]
    """
    sats = np.atleast_2d(as_finite_array("satellites", satellites))
    ac = np.reshape(aircraft, 3)  # finite: checked at the public boundary
    d = sats - ac[None, :]
    n = np.linalg.norm(d, axis=1)
    if np.any(n == 0):
        raise ValueError("satellites must not coincide with the aircraft")
    return d / n[:, None]


def zenith_angles(aircraft: np.ndarray, satellites: np.ndarray, *, deg: bool = False) -> np.ndarray:
    """Zenith angle of each satellite seen from the aircraft (spherical local vertical).

    Parameters
    ----------
    aircraft : (3,) array
        Aircraft position, m (Earth-centred).
    satellites : (K, 3) array
        Satellite positions, m (same frame).
    deg : bool, default False
        Return degrees.

    Returns
    -------
    (K,) ndarray
        Zenith angles, rad (deg with ``deg=True``).

    Raises
    ------
    ValueError
        If a satellite coincides with the aircraft or an input is not finite.

    Examples
    --------
    >>> sats = [[0.0, 0.0, 2.0e7], [2.0e7, 0.0, 6.4e6]]
    >>> zenith_angles([0.0, 0.0, 6.4e6], sats, deg=True).round(3).tolist()
    [0.0, 90.0]
    """
    ac = np.reshape(aircraft, 3)  # finite: checked at the public boundary
    up = ac / np.linalg.norm(ac)
    toward_sat = line_of_sight_matrix(ac, satellites)
    angle = np.arccos(np.clip(toward_sat @ up, -1.0, 1.0))
    return np.degrees(angle) if deg else angle


def _check_f(F: np.ndarray) -> np.ndarray:
    F = np.atleast_2d(as_finite_array("F", F))
    if F.ndim != 2 or F.shape[1] != 3 or F.shape[0] < 3:
        raise ValueError(f"F must be K x 3 with K >= 3, got shape {F.shape}")
    norm = np.linalg.norm(F, axis=1)
    if np.max(np.abs(norm - 1.0)) > 1e-6:
        raise ValueError(
            "F must have unit line-of-sight rows (norm 1 to within 1e-6), got a row norm of "
            f"{float(norm[np.argmax(np.abs(norm - 1.0))]):.6g}; satellite positions are not lines "
            "of sight (line_of_sight_matrix(aircraft, satellites) makes them)"
        )
    if np.linalg.matrix_rank(F) < 3:
        raise ValueError("F must have rank 3 (satellites not coplanar with the aircraft)")
    return F


@implements("ATC10 4.5.2")
def beta_parameter(F: np.ndarray) -> float:
    r""":math:`\beta = K - \mathbf{1}'F(F'F)^{-1} F'\mathbf{1} = |(I - P)\mathbf{1}|^2` (ATC-10
    Eq. 4.5.2, "K minus" reading).

    Zero for :math:`K = 3` (:math:`P = I`), which is why the clock cannot be estimated with
    three satellites. Computed as the squared least-squares residual of :math:`\mathbf{1}` on
    :math:`F`.

    Parameters
    ----------
    F : (K, 3) array
        Geometry matrix: unit line-of-sight rows (dimensionless, ``K >= 3``).

    Returns
    -------
    float
        :math:`\beta` (dimensionless, :math:`\ge 0`).

    Raises
    ------
    ValueError
        If ``F`` is not a finite ``(K, 3)`` array of rank 3 with ``K >= 3``.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.2).

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    >>> round(beta_parameter(F), 4), round(beta_parameter(F[:3]), 12)
    (0.08, 0.0)
    """
    F = _check_f(F)
    ones = np.ones(F.shape[0])
    coef, *_ = np.linalg.lstsq(F, ones, rcond=None)
    r = ones - F @ coef
    return float(r @ r)


def position_trace(F: np.ndarray) -> float:
    r""":math:`\operatorname{tr}\{(F'F)^{-1}\}`: the position dilution with the clock known.

    Parameters
    ----------
    F : (K, 3) array
        Geometry matrix: unit line-of-sight rows (dimensionless, ``K >= 3``).

    Returns
    -------
    float
        Trace (dimensionless).

    Raises
    ------
    ValueError
        If ``F`` is not a finite ``(K, 3)`` array of rank 3 with ``K >= 3``.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.35) (the first term).

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    >>> round(position_trace(F), 4)
    2.5
    """
    F = _check_f(F)
    return float(np.trace(np.linalg.inv(F.T @ F)))


@implements("ATC10 4.5.30")
def clock_direction_term(F: np.ndarray) -> float:
    r""":math:`S = \mathbf{1}'F(F'F)^{-2} F'\mathbf{1}`, the position error per unit
    clock-error variance.

    It equals :math:`|(F'F)^{-1} F'\mathbf{1}|^2`; for :math:`K = 3` it is the rotation
    invariant :math:`\mathbf{1}'(FF')^{-1} \mathbf{1}` (the correct quantity for ATC-10
    Eq. 4.5.30, erratum ATC10-E4.1-three-satellite-clock-term).

    Parameters
    ----------
    F : (K, 3) array
        Geometry matrix: unit line-of-sight rows (dimensionless, ``K >= 3``).

    Returns
    -------
    float
        :math:`S` (dimensionless).

    Raises
    ------
    ValueError
        If ``F`` is not a finite ``(K, 3)`` array of rank 3 with ``K >= 3``.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.30) and erratum
    ATC10-E4.1-three-satellite-clock-term.

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    >>> round(clock_direction_term(F), 4)
    2.48
    """
    F = _check_f(F)
    v = np.linalg.solve(F.T @ F, F.T @ np.ones(F.shape[0]))
    return float(v @ v)


@implements("ATC10 4.5.30")
def frame_dependent_clock_term(F: np.ndarray) -> float:
    r""":math:`\mathbf{1}'(F'F)^{-1} \mathbf{1}` for :math:`K = 3`: the term printed in ATC-10
    Eq. 4.5.30.

    It is NOT invariant under a rotation of the coordinate frame (:math:`F \to F R'`): kept
    only to
    reproduce what the paper tabulated (erratum ATC10-E4.1-three-satellite-clock-term).

    Parameters
    ----------
    F : (3, 3) array
        Geometry of three satellites (unit line-of-sight rows).

    Returns
    -------
    float
        The printed term (dimensionless).

    Raises
    ------
    ValueError
        If ``F`` is not a finite 3 x 3 array.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.5.30) and erratum
    ATC10-E4.1-three-satellite-clock-term.

    Examples
    --------
    >>> import numpy as np
    >>> F3 = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.6, 0.0, 0.8]])
    >>> round(frame_dependent_clock_term(F3), 4), round(clock_direction_term(F3), 4)
    (2.625, 2.25)
    """
    F = _check_f(F)
    if F.shape[0] != 3:
        raise ValueError(f"F must be 3 x 3 for the printed three-satellite term, got {F.shape}")
    ones = np.ones(3)
    return float(ones @ np.linalg.solve(F.T @ F, ones))


@implements("ATC10 4.1.1")
def position_dilution_covariance(F: np.ndarray, H: np.ndarray | None = None) -> np.ndarray:
    r"""Position error covariance per unit :math:`\sigma^2`, :math:`[F'H'(HH')^{-1} H F]^{-1}`
    (Eq. 4.1.1).

    ``H`` is any :math:`(K-1) \times K` matrix of full row rank whose rows sum to zero (it removes the
    common emission time by differencing). The default differences against satellite 1.

    Parameters
    ----------
    F : (K, 3) array
        Geometry matrix: unit line-of-sight rows (dimensionless, ``K >= 3``).
    H : (K-1, K) array, optional
        Differencing matrix (rows summing to zero).

    Returns
    -------
    (3, 3) ndarray
        Position error covariance per unit time-of-arrival variance; its trace is :math:`k^2` of
        :func:`position_dilution` (PDOP squared).

    Raises
    ------
    ValueError
        If ``F`` or ``H`` has the wrong shape or ``H``'s rows do not sum to zero.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eq. (4.1.1).

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    >>> C = position_dilution_covariance(F)
    >>> round(float(np.trace(C)), 4), round(position_dilution(F) ** 2, 4)
    (33.5, 33.5)
    """
    F = _check_f(F)
    K = F.shape[0]
    if H is None:
        H = np.hstack([-np.ones((K - 1, 1)), np.eye(K - 1)])
    H = np.atleast_2d(as_finite_array("H", H))
    if H.shape != (K - 1, K):
        raise ValueError(f"H must be (K-1) x K = {(K - 1, K)}, got {H.shape}")
    if not np.allclose(H.sum(axis=1), 0.0, atol=1e-12 * max(1.0, np.abs(H).max())):
        raise ValueError("H must have rows summing to zero (differencing matrix)")
    HF = H @ F
    info = HF.T @ np.linalg.solve(H @ H.T, HF)
    return np.linalg.inv(info)


@implements("ATC10 4.1.2", "ATC10 4.6.2")
def position_dilution(F: np.ndarray) -> float:
    r"""PDOP :math:`k = \sqrt{\operatorname{tr}\{(F'F)^{-1}\} + S / \beta}` (Eqs. 4.1.2 and
    4.6.2); ``inf`` when :math:`\beta = 0`.

    ATC-10 calls :math:`k` the geometric dilution; it is the position dilution of precision of
    the time-of-arrival solution, whose unknown emission time acts as a receiver clock: the
    PDOP of :func:`navcore.gnss.dop.dop_from_lines_of_sight` for the same lines of sight.

    Parameters
    ----------
    F : (K, 3) array
        Geometry matrix: unit line-of-sight rows (dimensionless, ``K >= 3``).

    Returns
    -------
    float
        Position dilution :math:`k` (PDOP: position error per unit time-of-arrival noise;
        ``inf`` for three satellites).

    Raises
    ------
    ValueError
        If ``F`` is not a finite ``(K, 3)`` array of rank 3 with ``K >= 3``.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (4.1.2) and (4.6.2).

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    >>> round(position_dilution(F), 4), position_dilution(F[:3])
    (5.7879, inf)
    """
    b = beta_parameter(F)
    if b <= 1e-12 * F.shape[0]:
        return math.inf
    return math.sqrt(position_trace(F) + clock_direction_term(F) / b)


@dataclass(frozen=True)
class ConstellationParameters:
    r"""The invariants of a constellation (ATC-10 Table 4.2 columns) for one satellite set.

    Attributes
    ----------
    beta : float
        :math:`\beta = \mathbf{1}'(I - P)\mathbf{1}` (Eq. 4.5.2).
    trace : float
        :math:`\operatorname{tr}\{(F'F)^{-1}\}`.
    clock_term : float
        :math:`S = \mathbf{1}'F(F'F)^{-2} F'\mathbf{1}`.
    dilution : float
        Position dilution :math:`k` (PDOP; ATC-10's geometric dilution, Eqs. 4.1.2, 4.6.2).
    """

    beta: float
    trace: float
    clock_term: float
    dilution: float


def constellation_parameters(F: np.ndarray) -> ConstellationParameters:
    r"""Compute :math:`\beta`, :math:`\operatorname{tr}\{(F'F)^{-1}\}`, :math:`S` and the
    position dilution :math:`k` (PDOP) of ``F``.

    Parameters
    ----------
    F : (K, 3) array
        Geometry matrix: unit line-of-sight rows (dimensionless, ``K >= 3``).

    Returns
    -------
    ConstellationParameters
        ``beta``, ``trace``, ``clock_term`` and ``dilution`` (all dimensionless).

    Raises
    ------
    ValueError
        If ``F`` is not a finite ``(K, 3)`` array of rank 3 with ``K >= 3``.

    References
    ----------
    Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic
    Management System", MIT Lincoln Laboratory ATC-10 (1972), Eqs. (4.1.2), (4.5.2), (4.5.30), (4.6.2).

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    >>> p = constellation_parameters(F)
    >>> round(p.trace, 4), round(p.dilution, 4)
    (2.5, 5.7879)
    """
    F = _check_f(F)
    return ConstellationParameters(
        beta=beta_parameter(F),
        trace=position_trace(F),
        clock_term=clock_direction_term(F),
        dilution=position_dilution(F),
    )


def most_widely_spaced_triplet(
    aircraft: np.ndarray,
    satellites: np.ndarray,
    cone_half_angle: float,
    criterion: str = "trace",
    *,
    deg: bool = False,
) -> tuple[tuple[int, int, int], float]:
    r"""Best three satellites inside the cone about the local vertical (0-based indices).


    ``criterion``: ``"trace"`` minimises :math:`\operatorname{tr}\{(F_3'F_3)^{-1}\}`;
    ``"det"`` maximises :math:`|\det F_3|`;
    ``"angle"`` maximises the smallest pairwise angle between the lines of sight. Returns the
    triplet and its score (trace, ``|det|`` or angle).

    Parameters
    ----------
    aircraft : (3,) array
        Aircraft position, m (Earth-centred).
    satellites : (K, 3) array
        Satellite positions, m (same frame).
    cone_half_angle : float
        Half-angle of the visibility cone about the local vertical, rad (deg with
        ``deg=True``), in (0, 90] deg.
    criterion : {"trace", "det", "angle"}, default "trace"
        What "widely spaced" means (see above).
    deg : bool, default False
        The cone angle, and the score of the ``"angle"`` criterion, in degrees.

    Returns
    -------
    triplet : tuple of int
        Indices of the three satellites.
    score : float
        Its score: the trace (dimensionless), ``|det F3|`` or the smallest angle (rad, deg
        with ``deg=True``).

    Raises
    ------
    ValueError
        If the cone angle is outside [0, 90], the criterion is unknown, or fewer than three
        satellites lie inside the cone.

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Sec. 4.5 (the three satellites that
    remain after the others are lost).

    Examples
    --------
    >>> sats = [[0.0, 0.0, 2.0e7], [1.0e7, 0.0, 2.0e7], [0.0, 1.0e7, 2.0e7], [-1.0e7, 0.0, 2.0e7]]
    >>> tri, score = most_widely_spaced_triplet([0.0, 0.0, 6.4e6], sats, 60.0, deg=True)
    >>> tri, round(score, 3)
    ((1, 2, 3), 6.47)
    """
    cone_half_angle_deg = cone_half_angle if deg else math.degrees(cone_half_angle)
    require_in_range("cone_half_angle", cone_half_angle_deg, 0.0, 90.0)
    if criterion not in ("trace", "det", "angle"):
        raise ValueError(f"criterion must be 'trace', 'det' or 'angle', got {criterion!r}")
    U = line_of_sight_matrix(aircraft, satellites)
    inside = np.flatnonzero(zenith_angles(aircraft, satellites, deg=True) <= cone_half_angle_deg + 1e-9)
    best: tuple[tuple[int, int, int], float] | None = None
    for tri in itertools.combinations(inside.tolist(), 3):
        F3 = U[list(tri)]
        if criterion == "trace":
            d = abs(np.linalg.det(F3))
            score = math.inf if d < 1e-12 else float(np.trace(np.linalg.inv(F3.T @ F3)))
            better = best is None or score < best[1]
        elif criterion == "det":
            score = float(abs(np.linalg.det(F3)))
            better = best is None or score > best[1]
        else:
            cosines = [float(F3[i] @ F3[j]) for i, j in ((0, 1), (0, 2), (1, 2))]
            score = float(np.degrees(np.arccos(np.clip(max(cosines), -1.0, 1.0))))
            better = best is None or score > best[1]
        if better:
            best = (tuple(tri), score)  # type: ignore[assignment]
    if best is None:
        raise ValueError("fewer than three satellites lie inside the cone")
    if criterion == "angle" and not deg:
        return best[0], math.radians(best[1])
    return best


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "radius": POSITIVE,
        "gm": POSITIVE,
        "period_s": POSITIVE,
        "trace": POSITIVE,
        "cone_half_angle": Angle(90.0, "a cone half-angle"),
        "lat": LATITUDE,
        "lon": LONGITUDE,
    },
)
