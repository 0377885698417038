r"""Strapdown mechanization in a local-level NED navigation frame, batched over runs.

Model (KZL Eqs. 7-9, with the neglected terms made switchable):

.. math::

    \begin{aligned}
    \dot x^n &= v^n,\\
    \dot v^n &= R_b^n f_{ib}^b + g^n - (2\omega_{ie}^n + \omega_{en}^n)\times v^n,\\
    \dot q_b^n &= \tfrac12 q_b^n \otimes [0, \omega_{ib}^b]
               - \tfrac12 [0, \omega_{in}^n] \otimes q_b^n,
    \end{aligned}

with :math:`\omega_{in}^n = \omega_{ie}^n + \omega_{en}^n`, Hamilton quaternions (scalar
first, :mod:`navcore.frames`), :math:`f_{ib}^b` the *specific force* (so a level IMU at rest
measures :math:`f^b = [0, 0, -g]`) and :math:`g^n = [0, 0, +g]`. With every switch off this
is the paper's simplified low-cost mechanization: flat, non-rotating Earth,
:math:`\dot q = \frac12 q \otimes [0,\omega_{ib}^b]` (KZL Eq. 9, right-most form). The Coriolis
switch includes the centripetal transport term :math:`\omega_{en}\times v`.

Position is kept in metres relative to a fixed origin, as curvilinear NED coordinates:
``pos[0]`` and ``pos[1]`` are the north and east *distances travelled over the Earth* (the
time integrals of :math:`v_N` and :math:`v_E`, i.e. arc lengths, not coordinates in a
tangent plane) and ``-pos[2]`` is the height gained. The velocity is resolved in the local
NED frame that moves with the vehicle. The latitude and height needed for Earth rate and
transport rate follow from ``lat = lat0 + pos[0] / (R_N(lat0) + h)`` and
``h = h0 - pos[2]``. Gravity is the constant ``terms.gravity`` along +down: there is no
latitude or height model of gravity (nor of its centripetal part).

When the navigation frame rotates (Earth rate or transport rate switched on), the
specific force is resolved with the attitude at mid-interval, which includes half of the
navigation frame's rotation over the interval, :math:`-\tfrac12\omega_{in}^n\Delta t`, as
well as half of the body increment (Groves Sec. 5.4.2).

All functions take arrays with a leading run axis (``(N, 3)``, ``(N, 4)``) so that Monte
Carlo runs are advanced together.

References
----------
.. [1] S. Knedlik, J. Zhou, O. Loffeld, "On Position and Attitude Estimation for Remote
   Sensing with Bistatic SAR", in Geoscience and Remote Sensing, InTech (2009), Eqs. (7)-(9).
.. [2] P. D. Groves (2013), Sec. 5.4 (local-navigation-frame mechanization).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import LATITUDE, POSITIVE, as_finite_array, check_public, require_positive, unchecked
from navcore.frames import quat_from_rotvec, radii_of_curvature
from navcore.trace import implements
from navcore.units import G0, OMEGA_EARTH

__all__ = [
    "MechanizationTerms",
    "NavState",
    "dcm_from_quat_batch",
    "earth_rate_ned",
    "quat_multiply_batch",
    "strapdown_interval",
    "strapdown_step",
    "transport_rate_ned",
]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class MechanizationTerms:
    """Switches for the terms the low-cost mechanization neglects (KZL Sec. 3.1/3.2).

    Attributes
    ----------
    earth_rate, transport_rate : bool
        Include :math:`\\omega_{ie}^n` / :math:`\\omega_{en}^n` in the attitude update.
    coriolis : bool
        Include :math:`-(2\\omega_{ie}^n + \\omega_{en}^n)\\times v^n` in the velocity update.
    gravity : float
        Local gravity magnitude (m/s²), along +down (default the constant ``G0`` the papers
        assume; :func:`navcore.gravity.normal_gravity` gives the WGS-84 value).
    lat0, h0 : float
        Latitude (rad, in :math:`[-\\pi/2, \\pi/2]`) and height (m) of the NED origin (used only
        by the switched terms).
    """

    earth_rate: bool = False
    transport_rate: bool = False
    coriolis: bool = False
    gravity: float = G0
    lat0: float = 0.0
    h0: float = 0.0

    def __post_init__(self) -> None:
        # an input record, checked where it is built (45.0 is a latitude in degrees)
        LATITUDE.check("MechanizationTerms.lat0", self.lat0)
        require_positive("MechanizationTerms.gravity", self.gravity)


@dataclass(frozen=True)
class NavState:
    """Position (m: north and east distance travelled, minus height gained, from the origin),
    velocity (m/s, NED) and attitude quaternion ``q_bn`` (body to NED).

    Each field has a leading run axis: ``pos (N, 3)``, ``vel (N, 3)``, ``quat (N, 4)``.

    Attributes
    ----------
    pos : (N, 3) ndarray
        Position from the origin, m (north, east, down).
    vel : (N, 3) ndarray
        Velocity, m/s (NED).
    quat : (N, 4) ndarray
        Attitude quaternion ``q_bn``, scalar first.
    """

    pos: Array
    vel: Array
    quat: Array


def quat_multiply_batch(q: Array, p: Array) -> Array:
    """Hamilton product ``q ⊗ p`` over a leading axis, without input validation (hot loop).

    Parameters
    ----------
    q : (..., 4) array
        Left quaternions, scalar first.
    p : (..., 4) array
        Right quaternions, scalar first.

    Returns
    -------
    (..., 4) ndarray
        The products.

    Examples
    --------
    >>> import numpy as np
    >>> quat_multiply_batch(np.array([0.0, 1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0, 0.0])).tolist()
    [0.0, 0.0, 0.0, 1.0]
    """
    w1, x1, y1, z1 = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    w2, x2, y2, z2 = p[..., 0], p[..., 1], p[..., 2], p[..., 3]
    # written into one array (no np.stack: this runs a dozen times per GPS epoch)
    out = np.empty((*np.broadcast_shapes(w1.shape, w2.shape), 4), dtype=np.result_type(q, p))
    out[..., 0] = w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2
    out[..., 1] = w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2
    out[..., 2] = w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2
    out[..., 3] = w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2
    return out


def dcm_from_quat_batch(q: Array) -> Array:
    """Rotation matrices ``(..., 3, 3)`` of unit quaternions ``(..., 4)`` (body to NED).

    Same convention as :func:`navcore.frames.dcm_from_quat`, which handles one quaternion.

    Parameters
    ----------
    q : (..., 4) array
        Unit quaternions, scalar first (not checked).

    Returns
    -------
    (..., 3, 3) ndarray
        Body-to-NED direction cosine matrices.

    Examples
    --------
    >>> import numpy as np
    >>> C = dcm_from_quat_batch(np.array([[np.cos(0.25), 0.0, 0.0, np.sin(0.25)]]))
    >>> np.round(C[0], 4).tolist()
    [[0.8776, -0.4794, 0.0], [0.4794, 0.8776, 0.0], [0.0, 0.0, 1.0]]
    """
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    C = np.empty((*w.shape, 3, 3), dtype=np.result_type(q, 1.0))
    C[..., 0, 0] = w * w + x * x - y * y - z * z
    C[..., 0, 1] = 2 * (x * y - w * z)
    C[..., 0, 2] = 2 * (x * z + w * y)
    C[..., 1, 0] = 2 * (x * y + w * z)
    C[..., 1, 1] = w * w - x * x + y * y - z * z
    C[..., 1, 2] = 2 * (y * z - w * x)
    C[..., 2, 0] = 2 * (x * z - w * y)
    C[..., 2, 1] = 2 * (y * z + w * x)
    C[..., 2, 2] = w * w - x * x - y * y + z * z
    return C


def earth_rate_ned(lat: ArrayLike, *, deg: bool = False) -> Array:
    r"""Earth rotation rate resolved in NED, :math:`\Omega[\cos L, 0, -\sin L]`.

    Parameters
    ----------
    lat : float or array
        Latitude, rad (deg with ``deg=True``), in [-90, 90] deg.
    deg : bool, default False
        The latitude is in degrees.

    Returns
    -------
    (..., 3) ndarray
        Earth rate in NED, rad/s.

    Notes
    -----
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    2nd ed. (2013), Ch. 5 (the local-navigation-frame mechanisation).

    Examples
    --------
    >>> [f"{x:.4e}" for x in earth_rate_ned(0.5)]
    ['6.3994e-05', '0.0000e+00', '-3.4960e-05']
    """
    lat = np.radians(np.asarray(lat, dtype=float)) if deg else np.asarray(lat, dtype=float)
    return OMEGA_EARTH * np.stack([np.cos(lat), np.zeros_like(lat), -np.sin(lat)], axis=-1)


def transport_rate_ned(vel: ArrayLike, lat: ArrayLike, h: ArrayLike, *, deg: bool = False) -> Array:
    r"""Transport rate :math:`\omega_{en}^n` of NED velocity ``vel`` (Groves Eq. 5.44).

    Parameters
    ----------
    vel : (..., 3) array
        NED velocity, m/s.
    lat : float or array
        Geodetic latitude, rad (deg with ``deg=True``), in [-90, 90] deg.
    h : float or array
        Height, m.
    deg : bool, default False
        The latitude is in degrees.

    Returns
    -------
    (..., 3) ndarray
        Transport rate in NED, rad/s (WGS-84 radii of curvature).

    Notes
    -----
    Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems,
    Eq. (5.44).

    Examples
    --------
    >>> w = transport_rate_ned([100.0, 0.0, 0.0], 0.0, 0.0)
    >>> f"{w[1]:.4e}"
    '-1.5784e-05'
    """
    vel = np.asarray(vel, dtype=float)
    lat = np.radians(np.asarray(lat, dtype=float)) if deg else np.asarray(lat, dtype=float)
    h = np.asarray(h, dtype=float)
    R_N, R_E = radii_of_curvature(lat)
    vn, ve = vel[..., 0], vel[..., 1]
    return np.stack([ve / (R_E + h), -vn / (R_N + h), -ve * np.tan(lat) / (R_E + h)], axis=-1)


@implements("KZL 7", "KZL 8", "KZL 9")
def strapdown_step(
    state: NavState,
    omega_ib_b: ArrayLike,
    f_ib_b: ArrayLike,
    dt: float,
    terms: MechanizationTerms = MechanizationTerms(),
) -> NavState:
    r"""Advance the mechanization by one IMU interval (KZL Eqs. 7-9).

    Parameters
    ----------
    state : NavState
        State at the start of the interval.
    omega_ib_b : (N, 3) array
        Body angular rate w.r.t. the inertial frame (rad/s), constant over the interval.
    f_ib_b : (N, 3) array
        Specific force (m/s²), constant over the interval.
    dt : float
        Interval (s), ``dt > 0``.
    terms : MechanizationTerms
        Which neglected terms to include (default: none, the paper's simplified form).

    Returns
    -------
    NavState
        The state at the end of the interval. The attitude update is exact for a constant
        body rate (:math:`q \otimes \exp(\omega\, dt / 2)`, then the navigation-frame rotation
        :math:`\exp(-\omega_{in}\, dt / 2) \otimes q`); velocity uses the mid-interval attitude (the start
        attitude rotated by half the body increment and by half the navigation-frame
        rotation); position is trapezoidal in velocity.

    Raises
    ------
    ValueError
        If ``dt`` is not positive or a rate or specific force is not finite.

    Examples
    --------
    A level IMU at rest measuring ``f = [0, 0, -g]`` stays at rest:

    >>> s = NavState(np.zeros((1, 3)), np.zeros((1, 3)), np.array([[1.0, 0, 0, 0]]))
    >>> s = strapdown_step(s, np.zeros((1, 3)), np.array([[0, 0, -G0]]), 0.01)
    >>> float(np.abs(s.vel).max()), float(np.abs(s.pos).max())
    (0.0, 0.0)
    """
    require_positive("dt", dt)
    w = np.atleast_2d(as_finite_array("omega_ib_b", omega_ib_b))
    f = np.atleast_2d(as_finite_array("f_ib_b", f_ib_b))
    q0 = state.quat
    # attitude: body-side increment (Eq. 9), exact for a constant rate over dt
    dq_b = quat_from_rotvec(w * dt)
    q_mid = quat_multiply_batch(q0, quat_from_rotvec(0.5 * w * dt))
    q1 = quat_multiply_batch(q0, dq_b)
    need_geo = terms.earth_rate or terms.transport_rate or terms.coriolis
    if need_geo:
        R_N, _ = radii_of_curvature(terms.lat0)
        h = terms.h0 - state.pos[..., 2]
        lat = terms.lat0 + state.pos[..., 0] / (R_N + h)
        w_ie = earth_rate_ned(lat)
        w_en = transport_rate_ned(state.vel, lat, h)
        w_in = np.zeros_like(w_ie)
        if terms.earth_rate:
            w_in = w_in + w_ie
        if terms.transport_rate:
            w_in = w_in + w_en
        if terms.earth_rate or terms.transport_rate:
            # n-frame rotation of the navigation frame itself: - 1/2 [0, w_in] ⊗ q, over the
            # whole interval for q1 and over its first half for the mid-interval attitude
            # that resolves the specific force (Groves Sec. 5.4.2/5.5.3: the attitude
            # averaged over the interval includes -1/2 Omega_in^n dt on the left)
            q1 = quat_multiply_batch(quat_from_rotvec(-w_in * dt), q1)
            q_mid = quat_multiply_batch(quat_from_rotvec(-0.5 * w_in * dt), q_mid)
    q1 = q1 / np.linalg.norm(q1, axis=-1, keepdims=True)
    # velocity (Eq. 8): specific force rotated with the mid-interval attitude, plus gravity
    C_mid = dcm_from_quat_batch(q_mid)
    acc = np.einsum("nij,nj->ni", C_mid, f)
    acc[..., 2] += terms.gravity
    if terms.coriolis:
        acc = acc - np.cross(2.0 * w_ie + w_en, state.vel)
    v1 = state.vel + acc * dt
    # position (Eq. 7)
    x1 = state.pos + 0.5 * (state.vel + v1) * dt
    return NavState(x1, v1, q1)


def strapdown_interval(
    state: NavState, omega_ib_b: ArrayLike, f_ib_b: ArrayLike, dt: float, gravity: float = G0
) -> tuple[NavState, Array]:
    """Advance the simplified mechanization (all switches off) over ``S`` IMU intervals at once.

    Same arithmetic as ``S`` calls of :func:`strapdown_step` with the default
    :class:`MechanizationTerms`, but vectorised over the intervals as well as the runs: the
    attitude increments are chained with a parallel prefix product of quaternions
    (``log2 S`` Hamilton products), velocity and position with cumulative sums.

    Parameters
    ----------
    state : NavState
        State at the start (leading run axis ``N``).
    omega_ib_b, f_ib_b : (N, S, 3) arrays
        Angular rate (rad/s) and specific force (m/s²) of each of the ``S`` intervals.
    dt : float
        IMU interval (s).
    gravity : float
        Local gravity along +down (m/s²).

    Returns
    -------
    state : NavState
        The state after the ``S`` intervals.
    f_n : (N, S, 3) array
        The specific force resolved in NED in each interval (for the error model's F23).

    Raises
    ------
    ValueError
        If ``dt`` is not positive or an input is not finite.

    Examples
    --------
    At rest, with the accelerometers reading the reaction to gravity, nothing moves:

    >>> import numpy as np
    >>> s0 = NavState(np.zeros((1, 3)), np.zeros((1, 3)), np.array([[1.0, 0.0, 0.0, 0.0]]))
    >>> f = np.tile([0.0, 0.0, -G0], (1, 100, 1))
    >>> s1, f_n = strapdown_interval(s0, np.zeros((1, 100, 3)), f, 0.01)
    >>> float(np.abs(s1.vel).max()) < 1e-12, f_n.shape
    (True, (1, 100, 3))
    """
    require_positive("dt", dt)
    w = np.asarray(omega_ib_b, dtype=float)
    f = np.asarray(f_ib_b, dtype=float)
    N, S = w.shape[:2]
    dq = _quat_from_rotvec(w * dt)  # (N, S, 4)
    # inclusive prefix product P_i = dq_0 ⊗ ... ⊗ dq_i (Hillis-Steele scan)
    pref = dq.copy()
    d = 1
    while d < S:
        pref[:, d:] = _quat_multiply(pref[:, :-d], pref[:, d:])
        d *= 2
    q0 = state.quat[:, None, :]
    start = np.concatenate([np.broadcast_to(q0, (N, 1, 4)), _quat_multiply(q0, pref[:, :-1])], axis=1)
    q_mid = _quat_multiply(start, _quat_from_rotvec(0.5 * w * dt))
    f_n = np.einsum("nsij,nsj->nsi", _dcm_from_quat(q_mid), f)
    acc = f_n.copy()
    acc[..., 2] += gravity
    v_all = state.vel[:, None, :] + np.cumsum(acc, axis=1) * dt  # v_1 .. v_S
    v_prev = np.concatenate([state.vel[:, None, :], v_all[:, :-1]], axis=1)
    x_end = state.pos + 0.5 * dt * np.sum(v_prev + v_all, axis=1)
    q_end = _quat_multiply(state.quat, pref[:, -1])
    q_end = q_end / np.linalg.norm(q_end, axis=-1, keepdims=True)
    return NavState(x_end, v_all[:, -1], q_end), f_n


# the kernels strapdown_interval calls at every step, without re-checking its checked arguments
_quat_multiply = quat_multiply_batch
_dcm_from_quat = dcm_from_quat_batch
_quat_from_rotvec = unchecked(quat_from_rotvec)

# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals(), {"dt": POSITIVE, "gravity": POSITIVE, "lat": LATITUDE})
