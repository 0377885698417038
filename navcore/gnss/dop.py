r"""Dilution of precision (GDOP, PDOP, HDOP, VDOP, TDOP) in the receiver's local frame.

A receiver that solves for its position and clock bias from pseudoranges has, after
linearisation, the geometry matrix with one row per satellite

.. math::

    G = \begin{bmatrix} -u_1^T & 1\\ \vdots & \vdots\\ -u_K^T & 1\end{bmatrix},

where :math:`u_i` is the unit line of sight from the receiver to satellite :math:`i`. With
independent range errors of variances :math:`\sigma^2/w_i` the weighted least-squares
solution has the covariance :math:`\sigma^2 (G^T W G)^{-1}`, :math:`W = \mathrm{diag}(w_i)`,
and the dilutions of precision are the square roots of sums of its diagonal per unit
:math:`\sigma^2`, with the lines of sight resolved in the local north-east-down frame:

.. math::

    \mathrm{HDOP} = \sqrt{D_{NN} + D_{EE}},\quad \mathrm{VDOP} = \sqrt{D_{DD}},

    \mathrm{PDOP} = \sqrt{D_{NN} + D_{EE} + D_{DD}},\quad \mathrm{TDOP} = \sqrt{D_{tt}},

    \mathrm{GDOP} = \sqrt{\mathrm{tr}\,D}.

Satellites below the elevation mask get weight zero; where the usable geometry has fewer
than four satellites or is singular, every DOP is infinite (no solution), never NaN.

PDOP is what ATC-10 calls the geometric dilution ``k`` of a time-of-arrival system (its
Eqs. 4.1.2 and 4.6.2, :func:`navcore.location.multilateration.position_dilution`): there the
unknown emission time plays the role of the receiver clock, and the sign of the lines of
sight does not matter (the covariance is quadratic in them).

:func:`satellite_priority` orders the visible satellites so that every prefix of the list
has a good geometry (the order in which a receiver with few channels should track them).

References
----------
.. [1] P. D. Groves (2013), Sec. 9.4.3 (dilution of precision).
.. [2] E. D. Kaplan and C. J. Hegarty, Understanding GPS/GNSS, 3rd ed. (2017), Sec. 11.2.1.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import ELEVATION, LATITUDE, LONGITUDE, NONNEGATIVE, as_finite_array, check_public
from navcore.frames import WGS84, Ellipsoid, dcm_ecef_to_ned, ecef_to_geodetic, geodetic_to_ecef
from navcore.gnss.constellation import elevation_azimuth

__all__ = ["DilutionOfPrecision", "dilution_of_precision", "dop_from_lines_of_sight", "satellite_priority"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class DilutionOfPrecision:
    r"""Dilutions of precision of one geometry, or a stack of geometries (arrays).

    Attributes
    ----------
    gdop : float or ndarray
        Geometric DOP, :math:`\sqrt{\operatorname{tr} D}`.
    pdop : float or ndarray
        Position DOP (3-D).
    hdop : float or ndarray
        Horizontal DOP (north and east).
    vdop : float or ndarray
        Vertical DOP.
    tdop : float or ndarray
        Time (clock) DOP, in units of range (the clock bias times c).
    n_used : int or ndarray
        Satellites used (above the mask, with a positive weight).
    covariance : (..., 4, 4) ndarray
        :math:`D = (G^T W G)^{-1}` per unit range variance, order north, east, down, clock;
        infinite where the geometry has no solution.
    """

    gdop: Array
    pdop: Array
    hdop: Array
    vdop: Array
    tdop: Array
    n_used: NDArray[np.int64]
    covariance: Array


def _scalar(x: NDArray[Any]) -> Any:
    return x[()] if x.ndim == 0 else x


def _dop(u_ned: Array, w: Array) -> DilutionOfPrecision:
    """DOP from lines of sight (..., K, 3) and weights (..., K), vectorised."""
    G = np.concatenate([-u_ned, np.ones((*u_ned.shape[:-1], 1))], axis=-1)  # (..., K, 4)
    GtW = np.swapaxes(G * w[..., None], -1, -2)
    info = GtW @ G  # (..., 4, 4)
    used = np.count_nonzero(w > 0, axis=-1)
    eig = np.linalg.eigvalsh(info)
    ok = (used >= 4) & (eig[..., 0] > 1e-12 * np.maximum(eig[..., -1], 1e-300))
    safe = np.where(ok[..., None, None], info, np.eye(4))
    D = np.where(ok[..., None, None], np.linalg.inv(safe), np.inf)
    D = 0.5 * (D + np.swapaxes(D, -1, -2))
    d = np.diagonal(D, axis1=-2, axis2=-1)
    return DilutionOfPrecision(
        gdop=_scalar(np.sqrt(d.sum(-1))),
        pdop=_scalar(np.sqrt(d[..., :3].sum(-1))),
        hdop=_scalar(np.sqrt(d[..., :2].sum(-1))),
        vdop=_scalar(np.sqrt(d[..., 2])),
        tdop=_scalar(np.sqrt(d[..., 3])),
        n_used=_scalar(used),
        covariance=D,
    )


def _weights(weights: ArrayLike | None, shape: tuple[int, ...]) -> Array:
    if weights is None:
        return np.ones(shape)
    w = np.asarray(weights, dtype=float)
    try:
        return np.broadcast_to(w, shape).copy()
    except ValueError:
        raise ValueError(
            f"weights must broadcast to one weight per satellite {shape}, got shape {w.shape}"
        ) from None


def dop_from_lines_of_sight(u_ned: ArrayLike, *, weights: ArrayLike | None = None) -> DilutionOfPrecision:
    """DOP of unit lines of sight from the receiver, resolved in its local NED frame.

    Parameters
    ----------
    u_ned : (..., K, 3) array
        Unit vectors from the receiver to each of K satellites, north-east-down (a stack of
        geometries broadcasts over the leading axes). The sign does not change the DOP.
    weights : (..., K) array, optional
        Relative inverse range variances ``sigma^2 / sigma_i^2`` (``>= 0``; 0 drops a
        satellite); default all ones. The DOP is then per unit ``sigma``.

    Returns
    -------
    DilutionOfPrecision
        GDOP, PDOP, HDOP, VDOP, TDOP (floats for one geometry, arrays for a stack), the
        number of satellites used and the covariance per unit range variance.

    Raises
    ------
    ValueError
        If a row of ``u_ned`` is not a unit vector (to within :math:`10^{-6}`: positions in metres are
        not lines of sight), ``u_ned`` does not end in (K, 3), or a weight is negative.

    References
    ----------
    Groves (2013), Sec. 9.4.3.

    Examples
    --------
    Four satellites, one at the zenith and three at zero elevation 120 deg apart:

    >>> import numpy as np
    >>> az = np.radians([0.0, 120.0, 240.0])
    >>> u = np.vstack([[0.0, 0.0, -1.0], np.c_[np.cos(az), np.sin(az), np.zeros(3)]])
    >>> d = dop_from_lines_of_sight(u)
    >>> round(float(d.hdop), 4), round(float(d.vdop), 4), round(float(d.tdop), 4)
    (1.1547, 1.1547, 0.5774)
    """
    u = np.asarray(u_ned, dtype=float)
    if u.ndim < 2 or u.shape[-1] != 3:
        raise ValueError(f"u_ned must have shape (..., K, 3), got {u.shape}")
    norm = np.linalg.norm(u, axis=-1)
    if u.size and np.max(np.abs(norm - 1.0)) > 1e-6:
        raise ValueError(
            "u_ned must hold unit lines of sight (norm 1 to within 1e-6), got a norm of "
            f"{float(norm.ravel()[np.argmax(np.abs(norm - 1.0))]):.6g}; positions need "
            "dilution_of_precision(r_receiver, r_sat)"
        )
    w = _weights(weights, u.shape[:-1])
    return _dop(u, w)


def dilution_of_precision(
    r_receiver: ArrayLike,
    r_sat: ArrayLike,
    *,
    mask: float = 0.0,
    weights: ArrayLike | None = None,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> DilutionOfPrecision:
    """DOP of satellites seen from a receiver, in the receiver's local NED frame.

    Parameters
    ----------
    r_receiver : (..., 3) array
        Receiver ECEF position(s), m (a stack of receivers broadcasts against ``r_sat``).
    r_sat : (..., K, 3) array
        Satellite ECEF positions, m.
    mask : float, default 0.0
        Elevation mask, rad (deg with ``deg=True``): satellites below it are not used.
    weights : (..., K) array, optional
        Relative inverse range variances (``>= 0``), default ones.
    deg : bool, default False
        The mask is in degrees.
    ellipsoid : Ellipsoid, default WGS84
        Ellipsoid that defines the receiver's local vertical.

    Returns
    -------
    DilutionOfPrecision
        GDOP, PDOP, HDOP, VDOP, TDOP, satellites used, covariance (infinite DOP with fewer
        than four usable satellites).

    Raises
    ------
    ValueError
        If a position is not finite, a satellite coincides with the receiver, the shapes do
        not broadcast or the mask is out of range for its unit.

    References
    ----------
    Groves (2013), Sec. 9.4.3; Kaplan & Hegarty (2017), Sec. 11.2.1.

    Examples
    --------
    >>> from navcore.gnss.constellation import nominal_gps_constellation
    >>> from navcore.frames import geodetic_to_ecef
    >>> r = geodetic_to_ecef(48.0, 11.0, 500.0, deg=True)
    >>> d = dilution_of_precision(r, nominal_gps_constellation().positions_ecef(0.0), mask=10.0, deg=True)
    >>> int(d.n_used), bool(d.hdop < d.vdop < d.pdop < d.gdop)
    (7, True)
    """
    r = np.asarray(r_receiver, dtype=float)
    sats = np.asarray(r_sat, dtype=float)
    if r.ndim < 1 or r.shape[-1] != 3:
        raise ValueError(f"r_receiver must have shape (..., 3), got {r.shape}")
    if sats.ndim < 2 or sats.shape[-1] != 3:
        raise ValueError(f"r_sat must have shape (..., K, 3), got {sats.shape}")
    d = sats - r[..., None, :]
    rho = np.linalg.norm(d, axis=-1)
    if np.any(rho == 0.0):
        raise ValueError("r_sat must not coincide with r_receiver (no line of sight)")
    if np.any(np.linalg.norm(r, axis=-1) < 1e5):
        raise ValueError(
            "r_receiver must be at least 100 km from the Earth's centre (an ECEF position in metres; "
            f"its geodetic latitude is undefined there), got {r!r}"
        )
    lat, lon, _ = ecef_to_geodetic(r, ellipsoid=ellipsoid)
    C_en = dcm_ecef_to_ned(lat, lon)[..., None, :, :]  # one rotation per receiver
    u = np.matmul(C_en, (d / rho[..., None])[..., None])[..., 0]  # lines of sight in NED
    mask_rad = np.radians(mask) if deg else float(mask)
    elevation = np.arcsin(np.clip(-u[..., 2], -1.0, 1.0))
    w = _weights(weights, u.shape[:-1]) * (elevation >= mask_rad)
    return _dop(u, w)


def satellite_priority(
    r_sat: ArrayLike, lat: float, lon: float, h: float, *, mask: float = 0.0, deg: bool = False
) -> NDArray[np.intp]:
    r"""Indices of the visible satellites in tracking priority, each prefix a good geometry.

    The highest satellite comes first (the master of double differences); then, greedily, the
    one that most increases :math:`\log\det(G^T G + 10^{-3} I)` of the geometry matrix
    :math:`G` (rows :math:`[-u_i^T, 1]`) of those already chosen, so that the first four are
    a well-conditioned fix and each later one adds the most information. The small
    regularisation ranks the first three, whose :math:`G^T G` is singular.

    Parameters
    ----------
    r_sat : (K, 3) array_like
        Satellite ECEF positions, m.
    lat, lon : float
        Receiver geodetic latitude and longitude, rad (deg with ``deg=True``).
    h : float
        Receiver height above the ellipsoid, m.
    mask : float, default 0.0
        Elevation mask, rad (deg with ``deg=True``): satellites below it are left out.
    deg : bool, default False
        ``lat``, ``lon`` and ``mask`` are in degrees.

    Returns
    -------
    ndarray of int
        Indices into ``r_sat`` of the satellites at or above the mask, in priority order.

    Raises
    ------
    ValueError
        If ``r_sat`` is not a finite (K, 3) array or an angle is out of range for its unit.

    References
    ----------
    Kaplan & Hegarty, Understanding GPS/GNSS, 3rd ed. (2017), Sec. 11.2.1 (geometry and
    satellite selection); KZL's Table 1 flight tracks its satellites in this order.

    Examples
    --------
    >>> from navcore.gnss.constellation import nominal_gps_constellation
    >>> sats = nominal_gps_constellation().positions_ecef(0.0)
    >>> order = satellite_priority(sats, 48.0, 11.0, 500.0, mask=10.0, deg=True)
    >>> len(order), int(dilution_of_precision(
    ...     geodetic_to_ecef(48.0, 11.0, 500.0, deg=True), sats[order[:4]]).n_used)
    (7, 4)
    """
    positions = as_finite_array("r_sat", r_sat, ndim=2)
    if positions.shape[1] != 3:
        raise ValueError(f"r_sat must have shape (K, 3), got {positions.shape}")
    if deg:
        lat, lon, mask = np.radians(lat), np.radians(lon), np.radians(mask)
    r_user = geodetic_to_ecef(lat, lon, h)
    el, _ = elevation_azimuth(r_user, positions, lat, lon)
    vis = np.flatnonzero(el >= mask)
    d = positions[vis] - r_user
    u = d / np.linalg.norm(d, axis=1, keepdims=True)
    G = np.hstack([-u, np.ones((len(vis), 1))])
    if len(vis) == 0:
        return vis
    order = [int(np.argmax(el[vis]))]
    while len(order) < len(vis):
        best, best_val = None, -np.inf
        for c in range(len(vis)):
            if c in order:
                continue
            Gs = G[[*order, c]]
            val = np.linalg.slogdet(Gs.T @ Gs + 1e-3 * np.eye(4))[1]
            if val > best_val:
                best, best_val = c, val
        assert best is not None  # every remaining satellite is a candidate
        order.append(int(best))
    return vis[order]


check_public(
    globals(),
    {"mask": ELEVATION, "weights": NONNEGATIVE, "lat": LATITUDE, "lon": LONGITUDE},
)
