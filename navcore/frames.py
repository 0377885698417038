r"""Rotations, quaternions, Euler angles and geodetic/ECEF/NED/ENU/AER coordinates, in bulk.

Every function takes single values or stacks: a vector is ``(..., 3)``, a quaternion
``(..., 4)``, a rotation matrix ``(..., 3, 3)``, and a latitude, longitude, height or angle
any array shape; the leading axes broadcast against each other (many points from one
origin, one point from many origins, or one origin per point).

Conventions
-----------
- ``C_bn`` (direction-cosine matrix) maps body coordinates to navigation (NED)
  coordinates: :math:`v^n = C_b^n v^b`.
- Euler angles are roll :math:`\phi`, pitch :math:`\theta`, yaw :math:`\psi` of the
  3-2-1 sequence: :math:`C_b^n = R_z(\psi) R_y(\theta) R_x(\phi)`, where
  :math:`R_x, R_y, R_z` rotate *vectors* (active rotations) about the axes. Pitch lies in
  [-90, 90] deg.
- Quaternions are Hamilton, scalar first, ``q = [w, x, y, z]``; ``q ⊗ p`` is the Hamilton
  product, and the quaternion of ``C_bn`` satisfies :math:`v^n = q \otimes v^b \otimes q^*`.
  A rotation by angle :math:`\alpha` about unit axis :math:`u` is
  :math:`q = [\cos(\alpha/2), u \sin(\alpha/2)]`. A function that rotates with a quaternion
  requires it to be a unit quaternion (to within :math:`10^{-6}`); :func:`quat_multiply`,
  :func:`quat_conjugate` and :func:`quat_normalize` are algebra and take any.
- ``skew(v) @ w == cross(v, w)``.
- Angles in radians unless ``deg=True`` (then every angle in and out is in degrees);
  latitudes in [-90, 90] deg, longitudes and azimuths in [-360, 360] deg, and a value
  outside its range for the unit given raises (45 given as radians for a latitude).
- Geodesy on an :class:`Ellipsoid`, WGS-84 by default (``ellipsoid=``); heights in
  metres above it. Local frames at a geodetic origin: NED (north, east, down) and ENU
  (east, north, up); AER is azimuth (from north, towards east, in [0, 360) deg),
  elevation (above the local horizontal plane) and slant range (m).

References
----------
.. [1] P. D. Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation
   Systems, 2nd ed. (2013), Ch. 2 (Eqs. 2.15, 2.22, 2.34-2.35, 2.112, 2.150).
.. [2] J. Zhu, "Conversion of Earth-centered Earth-fixed coordinates to geodetic
   coordinates", IEEE Trans. AES 30(3) (1994) (closed-form inverse used here).
.. [3] NIMA TR8350.2, "Department of Defense World Geodetic System 1984", 3rd ed. (2000).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    AZIMUTH,
    ELEVATION,
    LATITUDE,
    LONGITUDE,
    NONNEGATIVE,
    ROTATION_STACK,
    UNIT_QUATERNION_STACK,
    Angle,
    Range,
    as_finite_array,
    check_public,
)
from navcore.units import OMEGA_EARTH, WGS84_A, WGS84_F

__all__ = [
    "GRS80",
    "WGS84",
    "Ellipsoid",
    "aer_to_ecef",
    "aer_to_enu",
    "aer_to_geodetic",
    "aer_to_ned",
    "dcm_ecef_to_enu",
    "dcm_ecef_to_ned",
    "dcm_from_euler",
    "dcm_from_quat",
    "ecef_to_aer",
    "ecef_to_enu",
    "ecef_to_geodetic",
    "ecef_to_ned",
    "enu_to_aer",
    "enu_to_ecef",
    "enu_to_geodetic",
    "euler_from_dcm",
    "euler_from_quat",
    "geodetic_to_aer",
    "geodetic_to_ecef",
    "geodetic_to_enu",
    "geodetic_to_ned",
    "ned_to_aer",
    "ned_to_ecef",
    "ned_to_geodetic",
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


# --- ellipsoids ------------------------------------------------------------------------
@dataclass(frozen=True)
class Ellipsoid:
    """A reference ellipsoid of revolution; with ``gm`` and ``omega`` a level ellipsoid.

    Attributes
    ----------
    name : str
        Label (``"WGS-84"``).
    a : float
        Semi-major (equatorial) axis, m (``> 0``).
    f : float
        Flattening ``(a - b) / a``, in [0, 1) (0: a sphere of radius ``a``).
    gm : float
        Geocentric gravitational constant GM, m³/s² (``> 0``; for normal gravity).
    omega : float
        Angular velocity of rotation, rad/s (``>= 0``; for normal gravity).

    Examples
    --------
    >>> round(WGS84.b, 4), round(WGS84.e2, 12)
    (6356752.3142, 0.00669437999)
    >>> sphere = Ellipsoid("sphere", 6_371_000.0, 0.0)
    >>> sphere.b == sphere.a
    True
    """

    name: str
    a: float
    f: float
    gm: float = 3.986_004_418e14
    omega: float = OMEGA_EARTH

    def __post_init__(self) -> None:
        if not 0.0 <= self.f < 1.0:
            raise ValueError(f"Ellipsoid.f must lie in [0, 1), got {self.f!r}")

    @property
    def b(self) -> float:
        """Semi-minor (polar) axis ``a (1 - f)``, m."""
        return self.a * (1.0 - self.f)

    @property
    def e2(self) -> float:
        """First eccentricity squared ``f (2 - f)``."""
        return self.f * (2.0 - self.f)


#: The WGS-84 ellipsoid (NIMA TR8350.2, Table 3.1): a, 1/f, GM and the rotation rate.
WGS84 = Ellipsoid("WGS-84", WGS84_A, WGS84_F, 3.986_004_418e14, OMEGA_EARTH)
#: The GRS-80 ellipsoid (Moritz, Geodetic Reference System 1980).
GRS80 = Ellipsoid("GRS-80", 6_378_137.0, 1.0 / 298.257_222_101, 3.986_005e14, 7.292_115e-5)


def _rad(deg: bool, *angles: Any) -> list[Array]:
    return [np.radians(np.asarray(a, dtype=float)) if deg else np.asarray(a, dtype=float) for a in angles]


def _out(deg: bool, angle: Array) -> Array:
    return np.degrees(angle) if deg else angle


def _float_or_array(x: Array) -> Any:
    """A Python float for a 0-d result (one attitude in, floats out), else the array."""
    return float(x) if x.ndim == 0 else x


def _vectors(name: str, v: ArrayLike, size: int = 3) -> Array:
    arr = as_finite_array(name, v)
    if arr.ndim == 0 or arr.shape[-1] != size:
        raise ValueError(f"{name} must have shape (..., {size}), got {arr.shape}")
    return arr


def _mv(C: Array, v: Array) -> Array:
    """``C @ v`` over broadcast stacks: (..., 3, 3) times (..., 3)."""
    if C.ndim == 2:  # one matrix for all vectors: one matrix product (rows of v times C^T)
        return v @ C.T
    return np.matmul(C, v[..., None])[..., 0]


def _mtv(C: Array, v: Array) -> Array:
    """``C.T @ v`` over broadcast stacks."""
    if C.ndim == 2:
        return v @ C
    return np.matmul(np.swapaxes(C, -1, -2), v[..., None])[..., 0]


def skew(v: ArrayLike) -> Array:
    r"""Skew-symmetric (cross-product) matrix: ``skew(v) @ w == np.cross(v, w)``.

    Parameters
    ----------
    v : (..., 3) array
        Vector(s) (any unit).

    Returns
    -------
    (..., 3, 3) ndarray
        :math:`[v\times]` for each vector.

    Raises
    ------
    ValueError
        If ``v`` does not end in an axis of 3 or is not finite.

    Examples
    --------
    >>> skew([1.0, 2.0, 3.0]).tolist()
    [[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]]
    >>> skew([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).shape
    (2, 3, 3)
    """
    v = _vectors("v", v)
    if v.ndim == 1:  # the common single vector, built directly
        a, b, c = v
        return np.array([[0.0, -c, b], [c, 0.0, -a], [-b, a, 0.0]])
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    o = np.zeros_like(x)
    return np.stack([np.stack([o, -z, y], -1), np.stack([z, o, -x], -1), np.stack([-y, x, o], -1)], -2)


def _rot(axis: int, angle: Array) -> Array:
    c, s = np.cos(angle), np.sin(angle)
    o, i = np.zeros_like(c), np.ones_like(c)
    if axis == 0:
        rows = [[i, o, o], [o, c, -s], [o, s, c]]
    elif axis == 1:
        rows = [[c, o, s], [o, i, o], [-s, o, c]]
    else:
        rows = [[c, -s, o], [s, c, o], [o, o, i]]
    return np.stack([np.stack(r, -1) for r in rows], -2)


def rot_x(angle: ArrayLike, *, deg: bool = False) -> Array:
    """Active rotation of vectors by ``angle`` about the x axis.

    Parameters
    ----------
    angle : float or array
        Rotation angle(s), rad (deg with ``deg=True``).
    deg : bool, default False
        The angle is in degrees.

    Returns
    -------
    (..., 3, 3) ndarray
        Rotation matrix, one per angle.

    Raises
    ------
    ValueError
        If an angle is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(rot_x(90.0, deg=True) @ [0.0, 1.0, 0.0], 12) + 0.0).tolist()
    [0.0, 0.0, 1.0]
    """
    (a,) = _rad(deg, angle)
    return _rot(0, a)


def rot_y(angle: ArrayLike, *, deg: bool = False) -> Array:
    """Active rotation of vectors by ``angle`` about the y axis.

    Parameters
    ----------
    angle : float or array
        Rotation angle(s), rad (deg with ``deg=True``).
    deg : bool, default False
        The angle is in degrees.

    Returns
    -------
    (..., 3, 3) ndarray
        Rotation matrix, one per angle.

    Raises
    ------
    ValueError
        If an angle is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(rot_y(np.pi / 2) @ [0.0, 0.0, 1.0], 12) + 0.0).tolist()
    [1.0, 0.0, 0.0]
    """
    (a,) = _rad(deg, angle)
    return _rot(1, a)


def rot_z(angle: ArrayLike, *, deg: bool = False) -> Array:
    """Active rotation of vectors by ``angle`` about the z axis.

    Parameters
    ----------
    angle : float or array
        Rotation angle(s), rad (deg with ``deg=True``).
    deg : bool, default False
        The angle is in degrees.

    Returns
    -------
    (..., 3, 3) ndarray
        Rotation matrix, one per angle.

    Raises
    ------
    ValueError
        If an angle is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(rot_z(np.pi / 2) @ [1.0, 0.0, 0.0], 12) + 0.0).tolist()
    [0.0, 1.0, 0.0]
    """
    (a,) = _rad(deg, angle)
    return _rot(2, a)


def dcm_from_euler(roll: ArrayLike, pitch: ArrayLike, yaw: ArrayLike, *, deg: bool = False) -> Array:
    r""":math:`C_b^n = R_z(\text{yaw})\, R_y(\text{pitch})\, R_x(\text{roll})` (body to NED), for single
    angles or stacks.

    Parameters
    ----------
    roll : float or array
        Roll, rad (deg with ``deg=True``).
    pitch : float or array
        Pitch, rad, in :math:`[-\pi/2, \pi/2]` (deg with ``deg=True``).
    yaw : float or array
        Yaw (heading), rad (deg with ``deg=True``).
    deg : bool, default False
        The angles are in degrees.

    Returns
    -------
    (..., 3, 3) ndarray
        Body-to-NED direction cosine matrix (3-2-1 sequence); the shape of the broadcast
        angles followed by (3, 3).

    Raises
    ------
    ValueError
        If an angle is not finite or the pitch is outside [-90, 90] deg.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(dcm_from_euler(0.0, 0.0, np.pi / 2), 12) + 0.0).tolist()
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    >>> dcm_from_euler([0.0, 10.0], 0.0, [30.0, 40.0], deg=True).shape
    (2, 3, 3)
    """
    r, p, y = _rad(deg, roll, pitch, yaw)
    return np.matmul(np.matmul(_rot(2, y), _rot(1, p)), _rot(0, r))


def euler_from_dcm(C_bn: ArrayLike, *, deg: bool = False) -> tuple[Any, Any, Any]:
    r"""Roll, pitch, yaw of body-to-NED matrices (inverse of :func:`dcm_from_euler`).

    Pitch is in :math:`[-\pi/2, \pi/2]`; roll and yaw in :math:`(-\pi, \pi]`.

    Parameters
    ----------
    C_bn : (..., 3, 3) array
        Body-to-NED direction cosine matrix (a rotation matrix), or a stack of them.
    deg : bool, default False
        Return degrees.

    Returns
    -------
    roll : float or ndarray
        Roll, rad (deg with ``deg=True``); a float for one matrix, an array of the stack's
        shape for a stack.
    pitch : float or ndarray
        Pitch, rad (deg).
    yaw : float or ndarray
        Yaw, rad (deg).

    Raises
    ------
    ValueError
        If ``C_bn`` is not a rotation matrix or a stack of them.

    Examples
    --------
    >>> [round(a, 9) for a in euler_from_dcm(dcm_from_euler(0.1, -0.2, 0.3))]
    [0.1, -0.2, 0.3]
    """
    C = np.asarray(C_bn, dtype=float)
    pitch = np.arcsin(np.clip(-C[..., 2, 0], -1.0, 1.0))
    roll = np.arctan2(C[..., 2, 1], C[..., 2, 2])
    yaw = np.arctan2(C[..., 1, 0], C[..., 0, 0])
    return (
        _float_or_array(_out(deg, roll)),
        _float_or_array(_out(deg, pitch)),
        _float_or_array(_out(deg, yaw)),
    )


def quat_multiply(q: ArrayLike, p: ArrayLike) -> Array:
    """Hamilton product ``q ⊗ p`` (scalar first; broadcasts over leading axes).

    Parameters
    ----------
    q : (..., 4) array
        Left quaternion(s) (any norm).
    p : (..., 4) array
        Right quaternion(s) (any norm).

    Returns
    -------
    (..., 4) ndarray
        Product(s).

    Raises
    ------
    ValueError
        If an input is not finite or does not end in an axis of 4.

    Examples
    --------
    >>> quat_multiply([0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]).tolist()
    [0.0, 0.0, 0.0, 1.0]
    """
    q = _vectors("q", q, 4)
    p = _vectors("p", p, 4)
    return _qmul(q, p)


def _qmul(q: Array, p: Array) -> Array:
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


_CONJ = np.array([1.0, -1.0, -1.0, -1.0])


def quat_conjugate(q: ArrayLike) -> Array:
    """Conjugate ``[w, -x, -y, -z]`` (the inverse rotation of a unit quaternion).

    Parameters
    ----------
    q : (..., 4) array
        Quaternion(s), scalar first (any norm).

    Returns
    -------
    (..., 4) ndarray
        Conjugate.

    Raises
    ------
    ValueError
        If an input is not finite or does not end in an axis of 4.

    Examples
    --------
    >>> quat_conjugate([1.0, 2.0, 3.0, 4.0]).tolist()
    [1.0, -2.0, -3.0, -4.0]
    """
    return _vectors("q", q, 4) * _CONJ


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
    q = _vectors("q", q, 4)
    norm = np.linalg.norm(q, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("q must be non-zero to normalise")
    return _canonical(q / norm)


def _canonical(unit: Array) -> Array:
    return np.where(unit[..., :1] < 0, -unit, unit)


def quat_from_rotvec(rotvec: ArrayLike) -> Array:
    """Quaternion of a rotation vector ``alpha * u``, accurate for small angles.

    Parameters
    ----------
    rotvec : (..., 3) array
        Rotation vector(s), rad.

    Returns
    -------
    (..., 4) ndarray
        Unit quaternion(s), scalar first.

    Raises
    ------
    ValueError
        If an input is not finite or does not end in an axis of 3.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(quat_from_rotvec([0.0, 0.0, np.pi / 2]), 6).tolist()
    [0.707107, 0.0, 0.0, 0.707107]
    """
    r = _vectors("rotvec", rotvec)
    angle = np.linalg.norm(r, axis=-1, keepdims=True)
    half = 0.5 * angle
    # sin(a/2)/a -> 1/2 - a^2/48 for small a
    small = angle < 1e-8
    k = np.where(small, 0.5 - angle**2 / 48.0, np.sin(half) / np.where(small, 1.0, angle))
    return np.concatenate([np.cos(half), k * r], axis=-1)


def rotvec_from_quat(q: ArrayLike) -> Array:
    r"""Rotation vector of a unit quaternion (angle in :math:`[0, \pi]`).

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
        If ``q`` is not a unit quaternion or a stack of them.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(rotvec_from_quat(quat_from_rotvec([0.0, 0.3, 0.0])), 12).tolist()
    [0.0, 0.3, 0.0]
    """
    q = np.asarray(q, dtype=float)
    q = _canonical(q / np.linalg.norm(q, axis=-1, keepdims=True))
    w = np.clip(q[..., :1], -1.0, 1.0)
    v = q[..., 1:]
    s = np.linalg.norm(v, axis=-1, keepdims=True)
    angle = 2.0 * np.arctan2(s, w)
    small = s < 1e-12
    k = np.where(small, 2.0 / np.where(w == 0, 1.0, w), angle / np.where(small, 1.0, s))
    return k * v


def _dcm_of_quat(q: Array) -> Array:
    w, x, y, z = np.moveaxis(q, -1, 0)
    return np.stack(
        [
            np.stack([w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z], -1),
        ],
        -2,
    )


def dcm_from_quat(q: ArrayLike) -> Array:
    """Rotation matrix of a unit quaternion (``v_n = C @ v_b`` for ``q`` = body to NED).

    Parameters
    ----------
    q : (..., 4) array
        Unit quaternion(s), scalar first.

    Returns
    -------
    (..., 3, 3) ndarray
        Direction cosine matrix, one per quaternion.

    Raises
    ------
    ValueError
        If ``q`` is not a unit quaternion or a stack of them.

    Examples
    --------
    >>> import numpy as np
    >>> q = quat_from_euler(0.0, 0.0, np.pi / 2)
    >>> np.allclose(dcm_from_quat(q), dcm_from_euler(0.0, 0.0, np.pi / 2))
    True
    >>> dcm_from_quat(np.tile([1.0, 0.0, 0.0, 0.0], (4, 1))).shape
    (4, 3, 3)
    """
    q = np.asarray(q, dtype=float)
    return _dcm_of_quat(q / np.linalg.norm(q, axis=-1, keepdims=True))


def quat_from_dcm(C: ArrayLike) -> Array:
    """Unit quaternion of a rotation matrix (Shepperd's method, numerically robust).

    Parameters
    ----------
    C : (..., 3, 3) array
        Rotation matrix, or a stack of them.

    Returns
    -------
    (..., 4) ndarray
        Unit quaternion(s), scalar first, non-negative scalar part.

    Raises
    ------
    ValueError
        If ``C`` is not a rotation matrix or a stack of them.

    References
    ----------
    Shepperd, S. W., "Quaternion from rotation matrix", J. Guidance and Control 1(3) (1978).

    Examples
    --------
    >>> import numpy as np
    >>> np.round(quat_from_dcm(dcm_from_euler(0.0, 0.0, np.pi / 2)), 6).tolist()
    [0.707107, 0.0, 0.0, 0.707107]
    """
    C = np.asarray(C, dtype=float)
    c00, c01, c02 = C[..., 0, 0], C[..., 0, 1], C[..., 0, 2]
    c10, c11, c12 = C[..., 1, 0], C[..., 1, 1], C[..., 1, 2]
    c20, c21, c22 = C[..., 2, 0], C[..., 2, 1], C[..., 2, 2]
    tr = c00 + c11 + c22
    # 4 q_k^2 for k = w, x, y, z; the largest gives the best-conditioned division (Shepperd)
    four_sq = np.stack([1.0 + tr, 1.0 + 2 * c00 - tr, 1.0 + 2 * c11 - tr, 1.0 + 2 * c22 - tr], -1)
    k = np.argmax(four_sq, axis=-1)[..., None]
    # 4 q_k * q for each choice of k; the chosen q_k = sqrt(four_sq_k) / 2 >= 1/2
    qk = 0.5 * np.sqrt(np.maximum(np.take_along_axis(four_sq, k, -1), 1.0))
    cand = np.stack(
        [
            np.stack([1.0 + tr, c21 - c12, c02 - c20, c10 - c01], -1),
            np.stack([c21 - c12, 1.0 + 2 * c00 - tr, c01 + c10, c02 + c20], -1),
            np.stack([c02 - c20, c01 + c10, 1.0 + 2 * c11 - tr, c12 + c21], -1),
            np.stack([c10 - c01, c02 + c20, c12 + c21, 1.0 + 2 * c22 - tr], -1),
        ],
        -2,
    )
    q = np.take_along_axis(cand, k[..., None], -2)[..., 0, :] / (4.0 * qk)
    np.put_along_axis(q, k, qk, -1)  # the chosen component itself, sqrt(4 q_k^2) / 2
    return _canonical(q / np.linalg.norm(q, axis=-1, keepdims=True))


def quat_from_euler(roll: ArrayLike, pitch: ArrayLike, yaw: ArrayLike, *, deg: bool = False) -> Array:
    r"""Quaternion of ``dcm_from_euler(roll, pitch, yaw)``, for single angles or stacks.

    Parameters
    ----------
    roll : float or array
        Roll, rad (deg with ``deg=True``).
    pitch : float or array
        Pitch, rad, in :math:`[-\pi/2, \pi/2]` (deg with ``deg=True``).
    yaw : float or array
        Yaw, rad (deg with ``deg=True``).
    deg : bool, default False
        The angles are in degrees.

    Returns
    -------
    (..., 4) ndarray
        Unit quaternion(s), body to NED, scalar first, non-negative scalar part.

    Raises
    ------
    ValueError
        If an angle is not finite or the pitch is outside [-90, 90] deg.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(quat_from_euler(0.0, 0.0, np.pi / 2), 6).tolist()
    [0.707107, 0.0, 0.0, 0.707107]
    """
    r, p, y = np.broadcast_arrays(*_rad(deg, roll, pitch, yaw))
    o = np.zeros_like(r)
    qx = np.stack([np.cos(r / 2), np.sin(r / 2), o, o], -1)
    qy = np.stack([np.cos(p / 2), o, np.sin(p / 2), o], -1)
    qz = np.stack([np.cos(y / 2), o, o, np.sin(y / 2)], -1)
    q = _qmul(_qmul(qz, qy), qx)
    return _canonical(q / np.linalg.norm(q, axis=-1, keepdims=True))


def euler_from_quat(q: ArrayLike, *, deg: bool = False) -> tuple[Any, Any, Any]:
    """Roll, pitch, yaw of body-to-NED unit quaternions.

    Parameters
    ----------
    q : (..., 4) array
        Unit quaternion(s), scalar first.
    deg : bool, default False
        Return degrees.

    Returns
    -------
    roll : float or ndarray
        Roll, rad (deg with ``deg=True``).
    pitch : float or ndarray
        Pitch, rad (deg).
    yaw : float or ndarray
        Yaw, rad (deg).

    Raises
    ------
    ValueError
        If ``q`` is not a unit quaternion or a stack of them.

    Examples
    --------
    >>> [round(a, 9) for a in euler_from_quat(quat_from_euler(0.1, -0.2, 0.3))]
    [0.1, -0.2, 0.3]
    """
    q = np.asarray(q, dtype=float)
    C = _dcm_of_quat(q / np.linalg.norm(q, axis=-1, keepdims=True))
    pitch = np.arcsin(np.clip(-C[..., 2, 0], -1.0, 1.0))
    roll = np.arctan2(C[..., 2, 1], C[..., 2, 2])
    yaw = np.arctan2(C[..., 1, 0], C[..., 0, 0])
    return (
        _float_or_array(_out(deg, roll)),
        _float_or_array(_out(deg, pitch)),
        _float_or_array(_out(deg, yaw)),
    )


def quat_rotate(q: ArrayLike, v: ArrayLike) -> Array:
    """Rotate vector(s) ``v`` by unit quaternion(s) ``q``: ``q ⊗ [0, v] ⊗ q*``.

    Parameters
    ----------
    q : (..., 4) array
        Unit quaternion(s), scalar first.
    v : (..., 3) array
        Vector(s) (any unit); broadcasts against ``q``.

    Returns
    -------
    (..., 3) ndarray
        Rotated vector(s), same unit.

    Raises
    ------
    ValueError
        If ``q`` is not a unit quaternion (a rotation by ``[2, 0, 0, 0]`` would scale by 4)
        or ``v`` does not end in an axis of 3.

    Examples
    --------
    >>> import numpy as np
    >>> q = quat_from_euler(0.0, 0.0, np.pi / 2)
    >>> (np.round(quat_rotate(q, [1.0, 0.0, 0.0]), 12) + 0.0).tolist()
    [0.0, 1.0, 0.0]
    """
    q = np.asarray(q, dtype=float)
    v = _vectors("v", v)
    vq = np.concatenate([np.zeros((*v.shape[:-1], 1)), v], axis=-1)
    return _qmul(_qmul(q, vq), q * _CONJ)[..., 1:]


# --- geodesy ---------------------------------------------------------------------------
def _radii(lat: Array, ell: Ellipsoid) -> tuple[Array, Array]:
    den = 1.0 - ell.e2 * np.sin(lat) ** 2
    return ell.a * (1.0 - ell.e2) / den**1.5, ell.a / np.sqrt(den)


def radii_of_curvature(
    lat: ArrayLike, *, deg: bool = False, ellipsoid: Ellipsoid = WGS84
) -> tuple[Array, Array]:
    """Meridian (north-south) radius ``R_N`` and transverse radius ``R_E`` at ``lat``.

    Parameters
    ----------
    lat : float or array
        Geodetic latitude, rad (deg with ``deg=True``).
    deg : bool, default False
        The latitude is in degrees.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    R_N : ndarray
        Meridian radius of curvature, m.
    R_E : ndarray
        Transverse (prime-vertical) radius of curvature, m.

    Raises
    ------
    ValueError
        If a latitude is not finite or outside [-90, 90] deg.

    References
    ----------
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    2nd ed. (2013), Eqs. (2.105)-(2.106).

    Examples
    --------
    >>> R_N, R_E = radii_of_curvature(0.0)
    >>> round(float(R_N), 3), round(float(R_E), 3)
    (6335439.327, 6378137.0)
    """
    (lat_r,) = _rad(deg, lat)
    return _radii(lat_r, ellipsoid)


def _ecef(lat: Array, lon: Array, h: Array, ell: Ellipsoid) -> Array:
    _, R_E = _radii(lat, ell)
    cl = np.cos(lat)
    x = (R_E + h) * cl * np.cos(lon)
    y = (R_E + h) * cl * np.sin(lon)
    z = (R_E * (1.0 - ell.e2) + h) * np.sin(lat)
    return np.stack(np.broadcast_arrays(x, y, z), axis=-1)


def geodetic_to_ecef(
    lat: ArrayLike, lon: ArrayLike, h: ArrayLike, *, deg: bool = False, ellipsoid: Ellipsoid = WGS84
) -> Array:
    """ECEF position of geodetic latitude, longitude, height (broadcast together).

    Parameters
    ----------
    lat : float or array
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : float or array
        Longitude, rad (deg with ``deg=True``).
    h : float or array
        Height above the ellipsoid, m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        ECEF position, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is outside [-90, 90] deg, or the shapes do
        not broadcast.

    References
    ----------
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    2nd ed. (2013), Eq. (2.112).

    Examples
    --------
    >>> geodetic_to_ecef(0.0, 0.0, 0.0).tolist()
    [6378137.0, 0.0, 0.0]
    >>> geodetic_to_ecef([0.0, 90.0], 0.0, 0.0, deg=True).round(4).tolist()
    [[6378137.0, 0.0, 0.0], [0.0, 0.0, 6356752.3142]]
    """
    lat_r, lon_r = _rad(deg, lat, lon)
    return _ecef(lat_r, lon_r, np.asarray(h, dtype=float), ellipsoid)


def _geodetic(r: Array, ell: Ellipsoid) -> tuple[Array, Array, Array]:
    x, y, z = r[..., 0], r[..., 1], r[..., 2]
    a, b, e2 = ell.a, ell.b, ell.e2
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
    return lat, lon, h


def ecef_to_geodetic(
    r_e: ArrayLike, *, deg: bool = False, ellipsoid: Ellipsoid = WGS84
) -> tuple[Array, Array, Array]:
    r"""Geodetic latitude, longitude, height of ECEF position(s) ``(..., 3)`` (Zhu 1994).

    Parameters
    ----------
    r_e : (..., 3) array
        ECEF position, m (at least 100 km from the Earth's centre).
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    lat : ndarray
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : ndarray
        Longitude in :math:`(-\pi, \pi]`, rad (deg with ``deg=True``).
    h : ndarray
        Height above the ellipsoid, m.

    Raises
    ------
    ValueError
        If ``r_e`` does not end in an axis of 3, is not finite, or is within 100 km of the
        Earth's centre.

    References
    ----------
    Zhu, J., "Conversion of Earth-centered Earth-fixed coordinates to geodetic coordinates",
    IEEE Trans. Aerospace and Electronic Systems 30(3) (1994).

    Examples
    --------
    >>> lat, lon, h = ecef_to_geodetic(geodetic_to_ecef(45.0, 10.0, 1000.0, deg=True), deg=True)
    >>> round(float(lat), 9), round(float(lon), 9), round(float(h), 4)
    (45.0, 10.0, 1000.0)
    """
    r = _vectors("r_e", r_e)
    if np.any(np.linalg.norm(r, axis=-1) < 1e5):
        raise ValueError("r_e must be at least 100 km from the Earth's centre (geodetic latitude undefined)")
    lat, lon, h = _geodetic(r, ellipsoid)
    return _out(deg, lat), _out(deg, lon), h


def _c_en(lat: Array, lon: Array) -> Array:
    sl, cl = np.sin(lat), np.cos(lat)
    so, co = np.sin(lon), np.cos(lon)
    sl, cl, so, co = np.broadcast_arrays(sl, cl, so, co)
    o = np.zeros_like(sl)
    return np.stack(
        [
            np.stack([-sl * co, -sl * so, cl], -1),
            np.stack([-so, co, o], -1),
            np.stack([-cl * co, -cl * so, -sl], -1),
        ],
        -2,
    )


_NED_TO_ENU = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])


def dcm_ecef_to_ned(lat: ArrayLike, lon: ArrayLike, *, deg: bool = False) -> Array:
    """``C_en``: maps ECEF vectors to NED at (lat, lon); one matrix per broadcast position.

    Parameters
    ----------
    lat : float or array
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : float or array
        Longitude, rad (deg with ``deg=True``).
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (..., 3, 3) ndarray
        Direction cosine matrix, ``v_n = C_en @ v_e``.

    Raises
    ------
    ValueError
        If an input is not finite or a latitude is outside [-90, 90] deg.

    References
    ----------
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    2nd ed. (2013), Eq. (2.150).

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(dcm_ecef_to_ned(0.0, 0.0), 12) + 0.0).tolist()
    [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    lat_r, lon_r = _rad(deg, lat, lon)
    return _c_en(lat_r, lon_r)


def dcm_ecef_to_enu(lat: ArrayLike, lon: ArrayLike, *, deg: bool = False) -> Array:
    """Maps ECEF vectors to ENU (east, north, up) at (lat, lon); one matrix per position.

    Parameters
    ----------
    lat : float or array
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : float or array
        Longitude, rad (deg with ``deg=True``).
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (..., 3, 3) ndarray
        Direction cosine matrix, ``v_enu = C @ v_e``.

    Raises
    ------
    ValueError
        If an input is not finite or a latitude is outside [-90, 90] deg.

    Examples
    --------
    >>> import numpy as np
    >>> (np.round(dcm_ecef_to_enu(0.0, 0.0), 12) + 0.0).tolist()
    [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]
    """
    lat_r, lon_r = _rad(deg, lat, lon)
    return np.matmul(_NED_TO_ENU, _c_en(lat_r, lon_r))


def _to_local(r: Array, lat0: Array, lon0: Array, h0: Array, ell: Ellipsoid) -> Array:
    """NED of ECEF points relative to geodetic origins (radians), broadcast."""
    return _mv(_c_en(lat0, lon0), r - _ecef(lat0, lon0, h0, ell))


def _from_local(ned: Array, lat0: Array, lon0: Array, h0: Array, ell: Ellipsoid) -> Array:
    return _mtv(_c_en(lat0, lon0), ned) + _ecef(lat0, lon0, h0, ell)


def _swap_enu(v: Array) -> Array:
    """NED <-> ENU (the same permutation both ways)."""
    return np.stack([v[..., 1], v[..., 0], -v[..., 2]], -1)


def ecef_to_ned(
    r_e: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> Array:
    """NED coordinates of ECEF point(s) relative to geodetic origin(s).

    Parameters
    ----------
    r_e : (..., 3) array
        ECEF positions, m.
    lat0 : float or array
        Latitude of the origin(s), rad (deg with ``deg=True``); broadcasts against the
        points' leading axes.
    lon0 : float or array
        Longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        NED coordinates, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> r = geodetic_to_ecef(0.0, 0.0, 100.0)
    >>> (ecef_to_ned(r, 0.0, 0.0, 0.0).round(9) + 0.0).tolist()
    [0.0, 0.0, -100.0]
    """
    r = _vectors("r_e", r_e)
    lat_r, lon_r = _rad(deg, lat0, lon0)
    return _to_local(r, lat_r, lon_r, np.asarray(h0, dtype=float), ellipsoid)


def ned_to_ecef(
    r_n: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> Array:
    """ECEF coordinates of NED point(s) relative to geodetic origin(s).

    Parameters
    ----------
    r_n : (..., 3) array
        NED coordinates, m.
    lat0 : float or array
        Latitude of the origin(s), rad (deg with ``deg=True``).
    lon0 : float or array
        Longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        ECEF positions, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> (ned_to_ecef([0.0, 0.0, -100.0], 0.0, 0.0, 0.0).round(6) + 0.0).tolist()
    [6378237.0, 0.0, 0.0]
    """
    ned = _vectors("r_n", r_n)
    lat_r, lon_r = _rad(deg, lat0, lon0)
    return _from_local(ned, lat_r, lon_r, np.asarray(h0, dtype=float), ellipsoid)


def ecef_to_enu(
    r_e: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> Array:
    """ENU coordinates (east, north, up) of ECEF point(s) relative to geodetic origin(s).

    Parameters
    ----------
    r_e : (..., 3) array
        ECEF positions, m.
    lat0 : float or array
        Latitude of the origin(s), rad (deg with ``deg=True``).
    lon0 : float or array
        Longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        ENU coordinates, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> r = geodetic_to_ecef(0.0, 0.0, 100.0)
    >>> (ecef_to_enu(r, 0.0, 0.0, 0.0).round(9) + 0.0).tolist()
    [0.0, 0.0, 100.0]
    """
    r = _vectors("r_e", r_e)
    lat_r, lon_r = _rad(deg, lat0, lon0)
    return _swap_enu(_to_local(r, lat_r, lon_r, np.asarray(h0, dtype=float), ellipsoid))


def enu_to_ecef(
    r_enu: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> Array:
    """ECEF coordinates of ENU point(s) relative to geodetic origin(s).

    Parameters
    ----------
    r_enu : (..., 3) array
        ENU coordinates, m.
    lat0 : float or array
        Latitude of the origin(s), rad (deg with ``deg=True``).
    lon0 : float or array
        Longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        ECEF positions, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> (enu_to_ecef([0.0, 0.0, 100.0], 0.0, 0.0, 0.0).round(6) + 0.0).tolist()
    [6378237.0, 0.0, 0.0]
    """
    enu = _vectors("r_enu", r_enu)
    lat_r, lon_r = _rad(deg, lat0, lon0)
    return _from_local(_swap_enu(enu), lat_r, lon_r, np.asarray(h0, dtype=float), ellipsoid)


def geodetic_to_ned(
    lat: ArrayLike,
    lon: ArrayLike,
    h: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> Array:
    """NED coordinates of geodetic point(s) relative to geodetic origin(s).

    Parameters
    ----------
    lat, lon : float or array
        Geodetic latitude and longitude of the point(s), rad (deg with ``deg=True``).
    h : float or array
        Height of the point(s), m.
    lat0, lon0 : float or array
        Latitude and longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        NED coordinates, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> geodetic_to_ned(0.0, 0.0, 50.0, 0.0, 0.0, 0.0).round(9).tolist()
    [0.0, 0.0, -50.0]
    """
    lat_r, lon_r, lat0_r, lon0_r = _rad(deg, lat, lon, lat0, lon0)
    r = _ecef(lat_r, lon_r, np.asarray(h, dtype=float), ellipsoid)
    return _to_local(r, lat0_r, lon0_r, np.asarray(h0, dtype=float), ellipsoid)


def geodetic_to_enu(
    lat: ArrayLike,
    lon: ArrayLike,
    h: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> Array:
    """ENU coordinates of geodetic point(s) relative to geodetic origin(s).

    Parameters
    ----------
    lat, lon : float or array
        Geodetic latitude and longitude of the point(s), rad (deg with ``deg=True``).
    h : float or array
        Height of the point(s), m.
    lat0, lon0 : float or array
        Latitude and longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        ENU coordinates, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> geodetic_to_enu(0.0, 0.0, 50.0, 0.0, 0.0, 0.0).round(9).tolist()
    [0.0, 0.0, 50.0]
    """
    return _swap_enu(geodetic_to_ned(lat, lon, h, lat0, lon0, h0, deg=deg, ellipsoid=ellipsoid))


def ned_to_geodetic(
    r_n: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> tuple[Array, Array, Array]:
    """Geodetic latitude, longitude, height of NED point(s) relative to geodetic origin(s).

    Parameters
    ----------
    r_n : (..., 3) array
        NED coordinates, m.
    lat0, lon0 : float or array
        Latitude and longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians, in and out.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    lat : ndarray
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : ndarray
        Longitude, rad (deg).
    h : ndarray
        Height above the ellipsoid, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> lat, lon, h = ned_to_geodetic([0.0, 0.0, -50.0], 10.0, 20.0, 0.0, deg=True)
    >>> round(float(lat), 9), round(float(lon), 9), round(float(h), 6)
    (10.0, 20.0, 50.0)
    """
    ned = _vectors("r_n", r_n)
    lat_r, lon_r = _rad(deg, lat0, lon0)
    lat, lon, h = _geodetic(_from_local(ned, lat_r, lon_r, np.asarray(h0, dtype=float), ellipsoid), ellipsoid)
    return _out(deg, lat), _out(deg, lon), h


def enu_to_geodetic(
    r_enu: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> tuple[Array, Array, Array]:
    """Geodetic latitude, longitude, height of ENU point(s) relative to geodetic origin(s).

    Parameters
    ----------
    r_enu : (..., 3) array
        ENU coordinates, m.
    lat0, lon0 : float or array
        Latitude and longitude of the origin(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the origin(s), m.
    deg : bool, default False
        Angles in degrees instead of radians, in and out.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    lat : ndarray
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : ndarray
        Longitude, rad (deg).
    h : ndarray
        Height above the ellipsoid, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> lat, lon, h = enu_to_geodetic([0.0, 0.0, 50.0], 10.0, 20.0, 0.0, deg=True)
    >>> round(float(lat), 9), round(float(lon), 9), round(float(h), 6)
    (10.0, 20.0, 50.0)
    """
    enu = _vectors("r_enu", r_enu)
    return ned_to_geodetic(_swap_enu(enu), lat0, lon0, h0, deg=deg, ellipsoid=ellipsoid)


def _aer_of_enu(enu: Array, deg: bool) -> tuple[Array, Array, Array]:
    e, n, u = enu[..., 0], enu[..., 1], enu[..., 2]
    horizontal = np.hypot(e, n)
    az = np.arctan2(e, n) % (2 * np.pi)
    el = np.arctan2(u, horizontal)
    return _out(deg, az), _out(deg, el), np.hypot(horizontal, u)


def _enu_of_aer(az: Array, el: Array, srange: Array) -> Array:
    horizontal = srange * np.cos(el)
    return np.stack(
        np.broadcast_arrays(horizontal * np.sin(az), horizontal * np.cos(az), srange * np.sin(el)), -1
    )


def enu_to_aer(r_enu: ArrayLike, *, deg: bool = False) -> tuple[Array, Array, Array]:
    r"""Azimuth, elevation and slant range of ENU vector(s).

    Parameters
    ----------
    r_enu : (..., 3) array
        ENU coordinates (east, north, up), m.
    deg : bool, default False
        Return degrees instead of radians.

    Returns
    -------
    az : ndarray
        Azimuth from north towards east, in :math:`[0, 2\pi)` rad (deg with ``deg=True``).
    el : ndarray
        Elevation above the horizontal plane, rad (deg).
    srange : ndarray
        Slant range, m.

    Raises
    ------
    ValueError
        If ``r_enu`` is not finite or does not end in an axis of 3.

    Examples
    --------
    >>> az, el, rng = enu_to_aer([1.0, 0.0, 1.0], deg=True)
    >>> float(az), round(float(el), 9), round(float(rng), 9)
    (90.0, 45.0, 1.414213562)
    """
    return _aer_of_enu(_vectors("r_enu", r_enu), deg)


def aer_to_enu(az: ArrayLike, el: ArrayLike, srange: ArrayLike, *, deg: bool = False) -> Array:
    """ENU vector(s) of azimuth, elevation and slant range (broadcast together).

    Parameters
    ----------
    az : float or array
        Azimuth from north towards east, rad (deg with ``deg=True``).
    el : float or array
        Elevation, rad (deg), in [-90, 90] deg.
    srange : float or array
        Slant range, m (``>= 0``).
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (..., 3) ndarray
        ENU coordinates, m.

    Raises
    ------
    ValueError
        If an input is not finite, the elevation is out of range or the range negative.

    Examples
    --------
    >>> aer_to_enu(90.0, 0.0, 10.0, deg=True).round(9).tolist()
    [10.0, 0.0, 0.0]
    """
    az_r, el_r = _rad(deg, az, el)
    return _enu_of_aer(az_r, el_r, np.asarray(srange, dtype=float))


def ned_to_aer(r_n: ArrayLike, *, deg: bool = False) -> tuple[Array, Array, Array]:
    r"""Azimuth, elevation and slant range of NED vector(s).

    Parameters
    ----------
    r_n : (..., 3) array
        NED coordinates (north, east, down), m.
    deg : bool, default False
        Return degrees instead of radians.

    Returns
    -------
    az : ndarray
        Azimuth from north towards east, in :math:`[0, 2\pi)` rad (deg with ``deg=True``).
    el : ndarray
        Elevation above the horizontal plane, rad (deg).
    srange : ndarray
        Slant range, m.

    Raises
    ------
    ValueError
        If ``r_n`` is not finite or does not end in an axis of 3.

    Examples
    --------
    >>> az, el, rng = ned_to_aer([0.0, 0.0, -5.0], deg=True)
    >>> float(el), float(rng)
    (90.0, 5.0)
    """
    return _aer_of_enu(_swap_enu(_vectors("r_n", r_n)), deg)


def aer_to_ned(az: ArrayLike, el: ArrayLike, srange: ArrayLike, *, deg: bool = False) -> Array:
    """NED vector(s) of azimuth, elevation and slant range (broadcast together).

    Parameters
    ----------
    az : float or array
        Azimuth from north towards east, rad (deg with ``deg=True``).
    el : float or array
        Elevation, rad (deg), in [-90, 90] deg.
    srange : float or array
        Slant range, m (``>= 0``).
    deg : bool, default False
        Angles in degrees instead of radians.

    Returns
    -------
    (..., 3) ndarray
        NED coordinates, m.

    Raises
    ------
    ValueError
        If an input is not finite, the elevation is out of range or the range negative.

    Examples
    --------
    >>> aer_to_ned(0.0, 90.0, 10.0, deg=True).round(9).tolist()
    [0.0, 0.0, -10.0]
    """
    az_r, el_r = _rad(deg, az, el)
    return _swap_enu(_enu_of_aer(az_r, el_r, np.asarray(srange, dtype=float)))


def ecef_to_aer(
    r_e: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> tuple[Array, Array, Array]:
    r"""Azimuth, elevation, slant range of ECEF point(s) seen from geodetic observer(s).

    Parameters
    ----------
    r_e : (..., 3) array
        ECEF positions of the targets, m.
    lat0, lon0 : float or array
        Latitude and longitude of the observer(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the observer(s), m.
    deg : bool, default False
        Angles in degrees instead of radians, in and out.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    az : ndarray
        Azimuth from north towards east, in :math:`[0, 2\pi)` rad (deg with ``deg=True``).
    el : ndarray
        Elevation above the observer's local horizontal plane, rad (deg).
    srange : ndarray
        Slant range, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> az, el, rng = ecef_to_aer(geodetic_to_ecef(0.0, 0.0, 1000.0), 0.0, 0.0, 0.0)
    >>> round(float(el), 12), round(float(rng), 6)
    (1.570796326795, 1000.0)
    """
    enu = ecef_to_enu(r_e, lat0, lon0, h0, deg=deg, ellipsoid=ellipsoid)
    return _aer_of_enu(enu, deg)


def aer_to_ecef(
    az: ArrayLike,
    el: ArrayLike,
    srange: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> Array:
    """ECEF position(s) of azimuth, elevation, slant range seen from geodetic observer(s).

    Parameters
    ----------
    az : float or array
        Azimuth from north towards east, rad (deg with ``deg=True``).
    el : float or array
        Elevation, rad (deg), in [-90, 90] deg.
    srange : float or array
        Slant range, m (``>= 0``).
    lat0, lon0 : float or array
        Latitude and longitude of the observer(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the observer(s), m.
    deg : bool, default False
        Angles in degrees instead of radians.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    (..., 3) ndarray
        ECEF positions, m.

    Raises
    ------
    ValueError
        If an input is not finite, an angle is out of range, the range negative, or the
        shapes do not broadcast.

    Examples
    --------
    >>> aer_to_ecef(0.0, 90.0, 100.0, 0.0, 0.0, 0.0, deg=True).round(6).tolist()
    [6378237.0, 0.0, 0.0]
    """
    az_r, el_r, lat_r, lon_r = _rad(deg, az, el, lat0, lon0)
    enu = _enu_of_aer(az_r, el_r, np.asarray(srange, dtype=float))
    return _from_local(_swap_enu(enu), lat_r, lon_r, np.asarray(h0, dtype=float), ellipsoid)


def geodetic_to_aer(
    lat: ArrayLike,
    lon: ArrayLike,
    h: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> tuple[Array, Array, Array]:
    r"""Azimuth, elevation, slant range of geodetic point(s) seen from geodetic observer(s).

    Parameters
    ----------
    lat, lon : float or array
        Latitude and longitude of the target(s), rad (deg with ``deg=True``).
    h : float or array
        Height of the target(s), m.
    lat0, lon0 : float or array
        Latitude and longitude of the observer(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the observer(s), m.
    deg : bool, default False
        Angles in degrees instead of radians, in and out.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    az : ndarray
        Azimuth from north towards east, in :math:`[0, 2\pi)` rad (deg with ``deg=True``).
    el : ndarray
        Elevation, rad (deg).
    srange : ndarray
        Slant range, m.

    Raises
    ------
    ValueError
        If an input is not finite, a latitude is out of range, or the shapes do not
        broadcast.

    Examples
    --------
    >>> az, el, rng = geodetic_to_aer(0.0, 0.001, 0.0, 0.0, 0.0, 0.0, deg=True)
    >>> round(float(az), 6), round(float(rng), 3)
    (90.0, 111.319)
    """
    return _aer_of_enu(geodetic_to_enu(lat, lon, h, lat0, lon0, h0, deg=deg, ellipsoid=ellipsoid), deg)


def aer_to_geodetic(
    az: ArrayLike,
    el: ArrayLike,
    srange: ArrayLike,
    lat0: ArrayLike,
    lon0: ArrayLike,
    h0: ArrayLike,
    *,
    deg: bool = False,
    ellipsoid: Ellipsoid = WGS84,
) -> tuple[Array, Array, Array]:
    """Geodetic coordinates of azimuth, elevation, slant range seen from geodetic observer(s).

    Parameters
    ----------
    az : float or array
        Azimuth from north towards east, rad (deg with ``deg=True``).
    el : float or array
        Elevation, rad (deg), in [-90, 90] deg.
    srange : float or array
        Slant range, m (``>= 0``).
    lat0, lon0 : float or array
        Latitude and longitude of the observer(s), rad (deg with ``deg=True``).
    h0 : float or array
        Height of the observer(s), m.
    deg : bool, default False
        Angles in degrees instead of radians, in and out.
    ellipsoid : Ellipsoid, default WGS84
        Reference ellipsoid.

    Returns
    -------
    lat : ndarray
        Geodetic latitude, rad (deg with ``deg=True``).
    lon : ndarray
        Longitude, rad (deg).
    h : ndarray
        Height above the ellipsoid, m.

    Raises
    ------
    ValueError
        If an input is not finite, an angle is out of range, the range negative, or the
        shapes do not broadcast.

    Examples
    --------
    >>> lat, lon, h = aer_to_geodetic(0.0, 90.0, 100.0, 10.0, 20.0, 0.0, deg=True)
    >>> round(float(lat), 9), round(float(lon), 9), round(float(h), 6)
    (10.0, 20.0, 100.0)
    """
    r = aer_to_ecef(az, el, srange, lat0, lon0, h0, deg=deg, ellipsoid=ellipsoid)
    lat, lon, h = _geodetic(r, ellipsoid)
    return _out(deg, lat), _out(deg, lon), h


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
# Angles are bounded by their unit (radians, or degrees with deg=True); quaternions that
# rotate must be unit quaternions and matrices rotations (stacks allowed everywhere).
_PITCH = Angle(90.0, "a pitch angle")
check_public(
    globals(),
    {
        "lat": LATITUDE,
        "lat0": LATITUDE,
        "lon": LONGITUDE,
        "lon0": LONGITUDE,
        "az": AZIMUTH,
        "el": ELEVATION,
        "pitch": _PITCH,
        "srange": NONNEGATIVE,
        "q": UNIT_QUATERNION_STACK,
        "C": ROTATION_STACK,
        "C_bn": ROTATION_STACK,
        "a": Range(0.0, None, low_open=True),
        "gm": Range(0.0, None, low_open=True),
        "omega": NONNEGATIVE,
    },
    quat_multiply={"ranges": {"q": None}},
    quat_conjugate={"ranges": {"q": None}},
    quat_normalize={"ranges": {"q": None}},
)
