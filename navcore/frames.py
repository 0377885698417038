r"""Rotations, quaternions, Euler angles and geodetic/ECEF/NED coordinates.

Conventions
-----------
- ``C_bn`` (direction-cosine matrix) maps body coordinates to navigation (NED)
  coordinates: :math:`v^n = C_b^n v^b`.
- Euler angles are roll :math:`\phi`, pitch :math:`\theta`, yaw :math:`\psi` of the
  3-2-1 sequence: :math:`C_b^n = R_z(\psi) R_y(\theta) R_x(\phi)`, where
  :math:`R_x, R_y, R_z` rotate *vectors* (active rotations) about the axes.
- Quaternions are Hamilton, scalar first, ``q = [w, x, y, z]``; ``q ⊗ p`` is the Hamilton
  product, and the quaternion of ``C_bn`` satisfies :math:`v^n = q \otimes v^b \otimes q^*`.
  A rotation by angle :math:`\alpha` about unit axis :math:`u` is
  :math:`q = [\cos(\alpha/2), u \sin(\alpha/2)]`.
- ``skew(v) @ w == cross(v, w)``.
- Geodesy on WGS-84; latitude and longitude in radians unless ``deg=True``; heights in
  metres above the ellipsoid.

References
----------
.. [1] P. D. Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation
   Systems, 2nd ed. (2013), Ch. 2 (Eqs. 2.15, 2.22, 2.34-2.35, 2.112, 2.150).
.. [2] J. Zhu, "Conversion of Earth-centered Earth-fixed coordinates to geodetic
   coordinates", IEEE Trans. AES 30(3) (1994) (closed-form inverse used here).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import as_finite_array, check_public
from navcore.units import WGS84_A, WGS84_B, WGS84_E2

__all__ = [
    "dcm_ecef_to_ned",
    "dcm_from_euler",
    "dcm_from_quat",
    "ecef_to_geodetic",
    "ecef_to_ned",
    "euler_from_dcm",
    "euler_from_quat",
    "geodetic_to_ecef",
    "ned_to_ecef",
    "quat_conjugate",
    "quat_from_dcm",
    "quat_from_euler",
    "quat_from_rotvec",
    "quat_multiply",
    "quat_normalize",
    "quat_rotate",
    "radii_of_curvature",
    "rot_x",
    "rot_y",
    "rot_z",
    "rotvec_from_quat",
    "skew",
]

Array = NDArray[np.float64]


def skew(v: ArrayLike) -> Array:
    """Skew-symmetric (cross-product) matrix: ``skew(v) @ w == np.cross(v, w)``.

    Parameters
    ----------
    v : (3,) array
        Vector (any unit).

    Returns
    -------
    (3, 3) ndarray
        ``[v x]``.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> skew([1.0, 2.0, 3.0]).tolist()
    [[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]]
    """
    v = as_finite_array("v", v)
    if v.shape != (3,):
        raise ValueError(f"v must be a 3-vector, got shape {v.shape}")
    x, y, z = v
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def rot_x(angle: float) -> Array:
    """Active rotation of vectors by ``angle`` about the x axis.

    Parameters
    ----------
    angle : float
        Rotation angle, rad.

    Returns
    -------
    (3, 3) ndarray
        Rotation matrix.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(rot_x(np.pi / 2) @ [0.0, 1.0, 0.0], 12) + 0.0).tolist()
    [0.0, 0.0, 1.0]
    """
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_y(angle: float) -> Array:
    """Active rotation of vectors by ``angle`` about the y axis.

    Parameters
    ----------
    angle : float
        Rotation angle, rad.

    Returns
    -------
    (3, 3) ndarray
        Rotation matrix.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(rot_y(np.pi / 2) @ [0.0, 0.0, 1.0], 12) + 0.0).tolist()
    [1.0, 0.0, 0.0]
    """
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def rot_z(angle: float) -> Array:
    """Active rotation of vectors by ``angle`` about the z axis.

    Parameters
    ----------
    angle : float
        Rotation angle, rad.

    Returns
    -------
    (3, 3) ndarray
        Rotation matrix.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(rot_z(np.pi / 2) @ [1.0, 0.0, 0.0], 12) + 0.0).tolist()
    [0.0, 1.0, 0.0]
    """
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def dcm_from_euler(roll: float, pitch: float, yaw: float) -> Array:
    """``C_bn = Rz(yaw) Ry(pitch) Rx(roll)`` (body to NED).

    Parameters
    ----------
    roll : float
        Roll, rad.
    pitch : float
        Pitch, rad.
    yaw : float
        Yaw (heading), rad.

    Returns
    -------
    (3, 3) ndarray
        Body-to-NED direction cosine matrix (3-2-1 sequence).

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(dcm_from_euler(0.0, 0.0, np.pi / 2), 12) + 0.0).tolist()
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    as_finite_array("roll, pitch, yaw", [roll, pitch, yaw])
    return rot_z(yaw) @ rot_y(pitch) @ rot_x(roll)


def euler_from_dcm(C_bn: ArrayLike) -> tuple[float, float, float]:
    """Roll, pitch, yaw of a body-to-NED matrix (inverse of :func:`dcm_from_euler`).

    Pitch is in [-pi/2, pi/2]; roll and yaw in (-pi, pi].

    Parameters
    ----------
    C_bn : (3, 3) array
        Body-to-NED direction cosine matrix.

    Returns
    -------
    roll : float
        Roll, rad.
    pitch : float
        Pitch, rad.
    yaw : float
        Yaw, rad.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> [round(a, 9) for a in euler_from_dcm(dcm_from_euler(0.1, -0.2, 0.3))]
    [0.1, -0.2, 0.3]
    """
    C = as_finite_array("C_bn", C_bn, ndim=2)
    if C.shape != (3, 3):
        raise ValueError(f"C_bn must be 3x3, got {C.shape}")
    pitch = float(np.arcsin(np.clip(-C[2, 0], -1.0, 1.0)))
    roll = float(np.arctan2(C[2, 1], C[2, 2]))
    yaw = float(np.arctan2(C[1, 0], C[0, 0]))
    return roll, pitch, yaw


def _quat(name: str, q: ArrayLike) -> Array:
    q = as_finite_array(name, q)
    if q.shape[-1] != 4:
        raise ValueError(f"{name} must have 4 components [w, x, y, z], got shape {q.shape}")
    return q


def quat_multiply(q: ArrayLike, p: ArrayLike) -> Array:
    """Hamilton product ``q ⊗ p`` (scalar first; broadcasts over leading axes).

    Parameters
    ----------
    q : (..., 4) array
        Left quaternion(s).
    p : (..., 4) array
        Right quaternion(s).

    Returns
    -------
    (..., 4) ndarray
        Product(s).

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> quat_multiply([0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]).tolist()
    [0.0, 0.0, 0.0, 1.0]
    """
    q = _quat("q", q)
    p = _quat("p", p)
    w1, x1, y1, z1 = np.moveaxis(q, -1, 0)
    w2, x2, y2, z2 = np.moveaxis(p, -1, 0)
    return np.stack(
        [
            w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        ],
        axis=-1,
    )


def quat_conjugate(q: ArrayLike) -> Array:
    """Conjugate ``[w, -x, -y, -z]`` (the inverse rotation of a unit quaternion).

    Parameters
    ----------
    q : (..., 4) array
        Quaternion(s), scalar first.

    Returns
    -------
    (..., 4) ndarray
        Conjugate.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> quat_conjugate([1.0, 2.0, 3.0, 4.0]).tolist()
    [1.0, -2.0, -3.0, -4.0]
    """
    q = _quat("q", q)
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def quat_normalize(q: ArrayLike) -> Array:
    """Unit quaternion with non-negative scalar part.

    Parameters
    ----------
    q : (..., 4) array
        Non-zero quaternion(s).

    Returns
    -------
    (..., 4) ndarray
        Unit quaternion(s) with ``w >= 0``.

    Raises
    ------
    ValueError
        If a quaternion is zero or not finite.

    Examples
    --------
    >>> (quat_normalize([-2.0, 0.0, 0.0, 0.0]) + 0.0).tolist()
    [1.0, 0.0, 0.0, 0.0]
    """
    q = _quat("q", q)
    norm = np.linalg.norm(q, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("q must be non-zero to normalise")
    unit = q / norm
    return np.where(unit[..., :1] < 0, -unit, unit)


def quat_from_rotvec(rotvec: ArrayLike) -> Array:
    """Quaternion of a rotation vector ``alpha * u``, accurate for small angles.

    Parameters
    ----------
    rotvec : (..., 3) array
        Rotation vector, rad.

    Returns
    -------
    (..., 4) ndarray
        Unit quaternion(s), scalar first.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(quat_from_rotvec([0.0, 0.0, np.pi / 2]), 6).tolist()
    [0.707107, 0.0, 0.0, 0.707107]
    """
    r = as_finite_array("rotvec", rotvec)
    angle = np.linalg.norm(r, axis=-1, keepdims=True)
    half = 0.5 * angle
    # sin(a/2)/a -> 1/2 - a^2/48 for small a
    small = angle < 1e-8
    k = np.where(small, 0.5 - angle**2 / 48.0, np.sin(half) / np.where(small, 1.0, angle))
    return np.concatenate([np.cos(half), k * r], axis=-1)


def rotvec_from_quat(q: ArrayLike) -> Array:
    """Rotation vector of a unit quaternion (angle in [0, pi]).

    Parameters
    ----------
    q : (..., 4) array
        Unit quaternion(s), scalar first.

    Returns
    -------
    (..., 3) ndarray
        Rotation vector(s), rad.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(rotvec_from_quat(quat_from_rotvec([0.0, 0.3, 0.0])), 12).tolist()
    [0.0, 0.3, 0.0]
    """
    q = quat_normalize(q)
    w = np.clip(q[..., :1], -1.0, 1.0)
    v = q[..., 1:]
    s = np.linalg.norm(v, axis=-1, keepdims=True)
    angle = 2.0 * np.arctan2(s, w)
    small = s < 1e-12
    k = np.where(small, 2.0 / np.where(w == 0, 1.0, w), angle / np.where(small, 1.0, s))
    return k * v


def dcm_from_quat(q: ArrayLike) -> Array:
    """Rotation matrix of a unit quaternion (``v_n = C @ v_b`` for ``q`` = body to NED).

    Parameters
    ----------
    q : (4,) array
        Unit quaternion, scalar first.

    Returns
    -------
    (3, 3) ndarray
        Direction cosine matrix.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> q = quat_from_euler(0.0, 0.0, np.pi / 2)
    >>> np.allclose(dcm_from_quat(q), dcm_from_euler(0.0, 0.0, np.pi / 2))
    True
    """
    q = quat_normalize(q)
    w, x, y, z = q
    return np.array(
        [
            [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
        ]
    )


def quat_from_dcm(C: ArrayLike) -> Array:
    """Unit quaternion of a rotation matrix (Shepperd's method, numerically robust).

    Parameters
    ----------
    C : (3, 3) array
        Rotation matrix.

    Returns
    -------
    (4,) ndarray
        Unit quaternion, scalar first, non-negative scalar part.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    References
    ----------
    S. W. Shepperd, "Quaternion from rotation matrix", J. Guidance and Control 1(3) (1978).

    Examples
    --------
    >>> import numpy as np
    >>> np.round(quat_from_dcm(dcm_from_euler(0.0, 0.0, np.pi / 2)), 6).tolist()
    [0.707107, 0.0, 0.0, 0.707107]
    """
    C = as_finite_array("C", C, ndim=2)
    if C.shape != (3, 3):
        raise ValueError(f"C must be 3x3, got {C.shape}")
    tr = np.trace(C)
    cand = np.array([tr, C[0, 0], C[1, 1], C[2, 2]])
    i = int(np.argmax(cand))
    if i == 0:
        w = 0.5 * np.sqrt(1.0 + tr)
        q = [w, (C[2, 1] - C[1, 2]) / (4 * w), (C[0, 2] - C[2, 0]) / (4 * w), (C[1, 0] - C[0, 1]) / (4 * w)]
    elif i == 1:
        x = 0.5 * np.sqrt(1.0 + 2 * C[0, 0] - tr)
        q = [(C[2, 1] - C[1, 2]) / (4 * x), x, (C[0, 1] + C[1, 0]) / (4 * x), (C[0, 2] + C[2, 0]) / (4 * x)]
    elif i == 2:
        y = 0.5 * np.sqrt(1.0 + 2 * C[1, 1] - tr)
        q = [(C[0, 2] - C[2, 0]) / (4 * y), (C[0, 1] + C[1, 0]) / (4 * y), y, (C[1, 2] + C[2, 1]) / (4 * y)]
    else:
        z = 0.5 * np.sqrt(1.0 + 2 * C[2, 2] - tr)
        q = [(C[1, 0] - C[0, 1]) / (4 * z), (C[0, 2] + C[2, 0]) / (4 * z), (C[1, 2] + C[2, 1]) / (4 * z), z]
    return quat_normalize(np.array(q))


def quat_from_euler(roll: float, pitch: float, yaw: float) -> Array:
    """Quaternion of ``dcm_from_euler(roll, pitch, yaw)``.

    Parameters
    ----------
    roll : float
        Roll, rad.
    pitch : float
        Pitch, rad.
    yaw : float
        Yaw, rad.

    Returns
    -------
    (4,) ndarray
        Unit quaternion, body to NED, scalar first.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(quat_from_euler(0.0, 0.0, np.pi / 2), 6).tolist()
    [0.707107, 0.0, 0.0, 0.707107]
    """
    qx = np.array([np.cos(roll / 2), np.sin(roll / 2), 0.0, 0.0])
    qy = np.array([np.cos(pitch / 2), 0.0, np.sin(pitch / 2), 0.0])
    qz = np.array([np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)])
    return quat_normalize(quat_multiply(quat_multiply(qz, qy), qx))


def euler_from_quat(q: ArrayLike) -> tuple[float, float, float]:
    """Roll, pitch, yaw of a body-to-NED quaternion.

    Parameters
    ----------
    q : (4,) array
        Unit quaternion, scalar first.

    Returns
    -------
    roll : float
        Roll, rad.
    pitch : float
        Pitch, rad.
    yaw : float
        Yaw, rad.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> [round(a, 9) for a in euler_from_quat(quat_from_euler(0.1, -0.2, 0.3))]
    [0.1, -0.2, 0.3]
    """
    return euler_from_dcm(dcm_from_quat(q))


def quat_rotate(q: ArrayLike, v: ArrayLike) -> Array:
    """Rotate vector(s) ``v`` by unit quaternion ``q``: ``q ⊗ [0, v] ⊗ q*``.

    Parameters
    ----------
    q : (..., 4) array
        Unit quaternion(s), scalar first.
    v : (..., 3) array
        Vector(s) (any unit).

    Returns
    -------
    (..., 3) ndarray
        Rotated vector(s), same unit.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> q = quat_from_euler(0.0, 0.0, np.pi / 2)
    >>> (np.round(quat_rotate(q, [1.0, 0.0, 0.0]), 12) + 0.0).tolist()
    [0.0, 1.0, 0.0]
    """
    v = as_finite_array("v", v)
    vq = np.concatenate([np.zeros((*v.shape[:-1], 1)), v], axis=-1)
    return quat_multiply(quat_multiply(q, vq), quat_conjugate(q))[..., 1:]


# --- geodesy ---------------------------------------------------------------------------
def radii_of_curvature(lat: ArrayLike) -> tuple[Array, Array]:
    """Meridian (north-south) radius ``R_N`` and transverse radius ``R_E`` at ``lat`` (WGS-84).

    Parameters
    ----------
    lat : array_like
        Geodetic latitude, rad.

    Returns
    -------
    R_N : ndarray
        Meridian radius of curvature, m.
    R_E : ndarray
        Transverse (prime-vertical) radius of curvature, m.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    References
    ----------
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    2nd ed. (2013), Ch. 2 (frames and their transformations).

    Examples
    --------
    >>> R_N, R_E = radii_of_curvature(0.0)
    >>> round(float(R_N), 3), round(float(R_E), 3)
    (6335439.327, 6378137.0)
    """
    s2 = np.sin(np.asarray(lat, dtype=float)) ** 2
    den = 1.0 - WGS84_E2 * s2
    R_N = WGS84_A * (1.0 - WGS84_E2) / den**1.5
    R_E = WGS84_A / np.sqrt(den)
    return R_N, R_E


def geodetic_to_ecef(lat: ArrayLike, lon: ArrayLike, h: ArrayLike, *, deg: bool = False) -> Array:
    """ECEF position of geodetic latitude, longitude, height (WGS-84).

    Parameters
    ----------
    lat : array_like
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : array_like
        Longitude, rad (deg with ``deg=True``).
    h : array_like
        Height above the ellipsoid, m.
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (..., 3) ndarray
        ECEF position, m.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    References
    ----------
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    2nd ed. (2013), Ch. 2 (frames and their transformations).

    Examples
    --------
    >>> geodetic_to_ecef(0.0, 0.0, 0.0).tolist()
    [6378137.0, 0.0, 0.0]
    """
    lat = as_finite_array("lat", lat)
    lon = as_finite_array("lon", lon)
    h = as_finite_array("h", h)
    if deg:
        lat, lon = np.radians(lat), np.radians(lon)
    if np.any(np.abs(lat) > np.pi / 2 + 1e-12):
        raise ValueError("lat must lie in [-90 deg, 90 deg]")
    _, R_E = radii_of_curvature(lat)
    cl = np.cos(lat)
    x = (R_E + h) * cl * np.cos(lon)
    y = (R_E + h) * cl * np.sin(lon)
    z = (R_E * (1.0 - WGS84_E2) + h) * np.sin(lat)
    return np.stack(np.broadcast_arrays(x, y, z), axis=-1)


def ecef_to_geodetic(r_e: ArrayLike, *, deg: bool = False) -> tuple[Array, Array, Array]:
    """Geodetic latitude, longitude, height of ECEF position(s) ``(..., 3)`` (Zhu 1994).

    Parameters
    ----------
    r_e : (..., 3) array
        ECEF position, m (at least 100 km from the Earth's centre).
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    lat : ndarray
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : ndarray
        Longitude, rad (deg with ``deg=True``).
    h : ndarray
        Height above the WGS-84 ellipsoid, m.

    Raises
    ------
    ValueError
        If ``r_e`` does not end in an axis of 3, is not finite, or is within 100 km of the
        Earth's centre.

    References
    ----------
    J. Zhu, "Conversion of Earth-centered Earth-fixed coordinates to geodetic coordinates",
    IEEE Trans. Aerospace and Electronic Systems 30(3) (1994).

    Examples
    --------
    >>> lat, lon, h = ecef_to_geodetic(geodetic_to_ecef(45.0, 10.0, 1000.0, deg=True), deg=True)
    >>> round(float(lat), 9), round(float(lon), 9), round(float(h), 4)
    (45.0, 10.0, 1000.0)
    """
    r = as_finite_array("r_e", r_e)
    if r.ndim == 0 or r.shape[-1] != 3:
        raise ValueError(f"r_e must have shape (..., 3), got {r.shape}")
    if np.any(np.linalg.norm(r, axis=-1) < 1e5):
        raise ValueError("r_e must be at least 100 km from the Earth's centre (geodetic latitude undefined)")
    x, y, z = r[..., 0], r[..., 1], r[..., 2]
    a, b, e2 = WGS84_A, WGS84_B, WGS84_E2
    ep2 = (a * a - b * b) / (b * b)
    p = np.hypot(x, y)
    # Ferrari's solution as given by Zhu (1994); exact to sub-micrometre for |h| < 1e7 m
    F = 54.0 * b * b * z * z
    G = p * p + (1 - e2) * z * z - e2 * (a * a - b * b)
    c = e2 * e2 * F * p * p / (G**3)
    s = np.cbrt(1 + c + np.sqrt(c * c + 2 * c))
    P = F / (3 * (s + 1 / s + 1) ** 2 * G * G)
    Q = np.sqrt(1 + 2 * e2 * e2 * P)
    r0 = -(P * e2 * p) / (1 + Q) + np.sqrt(
        np.clip(0.5 * a * a * (1 + 1 / Q) - P * (1 - e2) * z * z / (Q * (1 + Q)) - 0.5 * P * p * p, 0, None)
    )
    U = np.sqrt((p - e2 * r0) ** 2 + z * z)
    V = np.sqrt((p - e2 * r0) ** 2 + (1 - e2) * z * z)
    z0 = b * b * z / (a * V)
    h = U * (1 - b * b / (a * V))
    lat = np.arctan2(z + ep2 * z0, p)  # p >= 0; exact +-pi/2 on the polar axis (p = 0)
    lon = np.arctan2(y, x)
    if deg:
        return np.degrees(lat), np.degrees(lon), h
    return lat, lon, h


def dcm_ecef_to_ned(lat: float, lon: float, *, deg: bool = False) -> Array:
    """``C_en``: maps ECEF vectors to NED at (lat, lon).

    Parameters
    ----------
    lat : float
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : float
        Longitude, rad (deg with ``deg=True``).
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (3, 3) ndarray
        Direction cosine matrix, ``v_n = C_en @ v_e``.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    References
    ----------
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    2nd ed. (2013), Ch. 2 (frames and their transformations).

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(dcm_ecef_to_ned(0.0, 0.0), 12) + 0.0).tolist()
    [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    if deg:
        lat, lon = np.radians(lat), np.radians(lon)
    sl, cl = np.sin(lat), np.cos(lat)
    so, co = np.sin(lon), np.cos(lon)
    return np.array(
        [
            [-sl * co, -sl * so, cl],
            [-so, co, 0.0],
            [-cl * co, -cl * so, -sl],
        ]
    )


def ecef_to_ned(r_e: ArrayLike, lat0: float, lon0: float, h0: float, *, deg: bool = False) -> Array:
    """NED coordinates of ECEF point(s) relative to a geodetic origin.

    Parameters
    ----------
    r_e : (..., 3) array
        ECEF positions, m.
    lat0 : float
        Latitude of the origin, rad (deg with ``deg=True``).
    lon0 : float
        Longitude of the origin, rad (deg with ``deg=True``).
    h0 : float
        Height of the origin, m.
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (..., 3) ndarray
        NED coordinates, m.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> r = geodetic_to_ecef(0.0, 0.0, 100.0)
    >>> (ecef_to_ned(r, 0.0, 0.0, 0.0).round(9) + 0.0).tolist()
    [0.0, 0.0, -100.0]
    """
    origin = geodetic_to_ecef(lat0, lon0, h0, deg=deg)
    d = as_finite_array("r_e", r_e) - origin
    return d @ dcm_ecef_to_ned(lat0, lon0, deg=deg).T


def ned_to_ecef(r_n: ArrayLike, lat0: float, lon0: float, h0: float, *, deg: bool = False) -> Array:
    """ECEF coordinates of NED point(s) relative to a geodetic origin.

    Parameters
    ----------
    r_n : (..., 3) array
        NED coordinates, m.
    lat0 : float
        Latitude of the origin, rad (deg with ``deg=True``).
    lon0 : float
        Longitude of the origin, rad (deg with ``deg=True``).
    h0 : float
        Height of the origin, m.
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (..., 3) ndarray
        ECEF positions, m.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    Examples
    --------
    >>> (ned_to_ecef([0.0, 0.0, -100.0], 0.0, 0.0, 0.0).round(6) + 0.0).tolist()
    [6378237.0, 0.0, 0.0]
    """
    origin = geodetic_to_ecef(lat0, lon0, h0, deg=deg)
    return as_finite_array("r_n", r_n) @ dcm_ecef_to_ned(lat0, lon0, deg=deg) + origin


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals())
