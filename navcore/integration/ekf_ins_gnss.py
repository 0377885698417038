r"""Tightly coupled, indirect feedback INS/GPS extended Kalman filter, batched over Monte Carlo runs.

Structure (KZL Sec. 3.5, Fig. 3):

1. the strapdown mechanization (:mod:`navcore.inertial.strapdown`, simplified as in Eqs. 7-9)
   runs at the IMU rate on bias-corrected sensor data, the attitude chained one interval at a
   time as :func:`~navcore.inertial.strapdown.strapdown_step` chains it;
2. the 17-state error covariance (:mod:`navcore.inertial.error_model17`) is predicted at the
   GPS rate with the exact transition :math:`e^{FT}` (a cubic, F being nilpotent) and the
   exact discrete noise :math:`Q_d = \int_0^T e^{Fs} GQG^T e^{F^Ts} ds` (Gauss-Legendre with
   four nodes, exact for the degree-6 polynomial integrand: the ``"nilpotent"`` method of
   :func:`navcore.estimation.discretize.discretize`);
3. at each GPS epoch the measurements ``y = predicted - measured`` are processed one scalar
   at a time (correlated DD phases are whitened first with the Cholesky factor of their
   covariance), which gives the same posterior as one batch update;
4. feedback: position, velocity, biases and clock are corrected by subtraction, the
   attitude by the n-frame rotation :math:`q^+ = q(-\Delta\hat\psi)\otimes q^-`
   (:func:`correct_attitude`), and the error state is reset to zero.

Everything carries a leading run axis so that ``N`` Monte Carlo runs advance together;
:func:`run_monte_carlo_batch` advances the runs of several scenarios (a ledger band's) together
on that axis, each run with the random numbers and the arithmetic it has alone.

References
----------
.. [1] S. Knedlik, J. Zhou, O. Loffeld (2009), Secs. 3.4-3.6.
.. [2] P. S. Maybeck, Stochastic Models, Estimation, and Control, Vol. 1 (1979), Sec. 7.6.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Sequence
from dataclasses import dataclass, fields
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    NONNEGATIVE,
    POSITIVE,
    ROTATION_STACK,
    UNIT_QUATERNION_STACK,
    check_public,
    require_integer,
    unchecked,
)
from navcore.estimation.discretize import discretize_unchecked
from navcore.estimation.kalman import symmetrize_unchecked
from navcore.frames import dcm_from_euler, quat_from_dcm, quat_from_rotvec
from navcore.gnss.carrier_phase import dd_covariance
from navcore.inertial.alignment import heading_from_velocity, levelling
from navcore.inertial.error_model17 import ERROR_LAYOUT_17, error_dynamics_17
from navcore.inertial.imu import ImuSpec
from navcore.inertial.strapdown import (
    dcm_from_quat_batch,
    quat_multiply_batch,
)
from navcore.units import G0, GPS_L1_WAVELENGTH_M

__all__ = [
    "MODES",
    "GnssNoise",
    "MonteCarloResult",
    "Scenario",
    "batch_group_key",
    "correct_attitude",
    "euler_batch",
    "euler_jacobian_batch",
    "monte_carlo_key",
    "run_monte_carlo",
    "run_monte_carlo_batch",
    "sequential_scalar_updates",
]

Array = NDArray[np.float64]
Mode = Literal["ins", "tc", "tc_att", "tc_dd"]
#: Filter configurations: stand-alone INS, tightly coupled (code + delta range), plus Euler
#: attitude from a multi-antenna receiver (Eq. 12), plus double-difference phases (Eq. 17).
MODES = ("ins", "tc", "tc_att", "tc_dd")
#: Satellites a double difference needs: the master and one other (KZL Eq. (14), two satellites).
DD_MIN_SATELLITES = 2

L = ERROR_LAYOUT_17
_P, _V, _A = L.slice("position"), L.slice("velocity"), L.slice("misalignment")
_BA, _BG = L.slice("accel bias"), L.slice("gyro bias")
_CB, _CD = L.index("clock bias"), L.index("clock drift")


# --- small batched helpers ----------------------------------------------------------------
def correct_attitude(q: ArrayLike, dpsi: ArrayLike, side: Literal["left", "right"] = "left") -> Array:
    r"""Remove an estimated n-frame attitude error ``dpsi`` from ``q_bn`` (KZL Sec. 3.5).

    ``side="left"`` applies the n-frame rotation ``q(-dpsi) ⊗ q`` (correct for
    :math:`\hat R = (I + [\Delta\psi\times]) R`); ``side="right"`` is the printed order
    ``q ⊗ q(-dpsi)``, which rotates about *body* axes instead.

    Parameters
    ----------
    q : (..., 4) array
        Body-to-NED quaternions, scalar first.
    dpsi : (..., 3) array
        Estimated attitude error (rotation vector in the n frame), rad.
    side : {"left", "right"}, default "left"
        Order of the correction (see above).

    Returns
    -------
    (..., 4) ndarray
        Corrected unit quaternions.

    Raises
    ------
    ValueError
        If ``side`` is neither ``"left"`` nor ``"right"``.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with Bistatic SAR"
    (2009), Sec. 3.5 (feedback correction; the printed order is the ``"right"`` one).

    Examples
    --------
    >>> import numpy as np
    >>> q = correct_attitude([1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.1])
    >>> np.round(q, 4)
    array([ 0.9988,  0.    ,  0.    , -0.05  ])
    """
    if side not in ("left", "right"):
        raise ValueError(f"side must be 'left' or 'right', got {side!r}")
    q = np.asarray(q, dtype=float)
    dq = unchecked(quat_from_rotvec)(-np.asarray(dpsi, dtype=float))
    qmul = unchecked(quat_multiply_batch)
    out = qmul(dq, q) if side == "left" else qmul(q, dq)
    return out / np.linalg.norm(out, axis=-1, keepdims=True)


def euler_batch(C: Array) -> Array:
    """Roll, pitch, yaw of body-to-NED matrices (3-2-1 sequence), batched.

    Parameters
    ----------
    C : (..., 3, 3) array
        Body-to-NED direction cosine matrices.

    Returns
    -------
    (..., 3) ndarray
        Roll, pitch, yaw, rad.

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.frames import dcm_from_euler
    >>> np.round(euler_batch(dcm_from_euler(0.1, 0.2, 0.3)[None]), 6)
    array([[0.1, 0.2, 0.3]])
    """
    pitch = np.arcsin(np.clip(-C[..., 2, 0], -1.0, 1.0))
    roll = np.arctan2(C[..., 2, 1], C[..., 2, 2])
    yaw = np.arctan2(C[..., 1, 0], C[..., 0, 0])
    return np.stack([roll, pitch, yaw], axis=-1)


def euler_jacobian_batch(C: Array) -> Array:
    r""":math:`\partial(\text{roll}, \text{pitch}, \text{yaw})/\partial(\Delta\psi) = J_b^{-1} C^T`
    for :math:`C = (I + [\Delta\psi\times]) C_0` (batched).

    Parameters
    ----------
    C : (..., 3, 3) array
        Body-to-NED direction cosine matrices.

    Returns
    -------
    (..., 3, 3) ndarray
        Jacobian of the Euler angles (rad) with respect to the n-frame attitude error (rad).

    Notes
    -----
    Used for the attitude rows of the tightly coupled filter with attitude, KZL Sec. 3.4.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(euler_jacobian_batch(np.eye(3)[None])[0], 6)
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    e = unchecked(euler_batch)(C)
    sr, cr, tp, cp = np.sin(e[..., 0]), np.cos(e[..., 0]), np.tan(e[..., 1]), np.cos(e[..., 1])
    one, zero = np.ones_like(sr), np.zeros_like(sr)
    Jb = np.stack(
        [
            np.stack([one, sr * tp, cr * tp], -1),
            np.stack([zero, cr, -sr], -1),
            np.stack([zero, sr / cp, cr / cp], -1),
        ],
        -2,
    )
    return Jb @ np.swapaxes(C, -1, -2)


def _wrap(a: Array) -> Array:
    return (a + np.pi) % (2 * np.pi) - np.pi


def _dd_phase_batch(pos: Array, ant: Array, sat_n: Array, sat_m: Array) -> Array:
    """DD phase (rad) of KZL Eq. 15 for runs ``pos (N, 3)`` and antenna offsets ``ant (N, nb, 3)``.

    Cancellation-free form of :func:`navcore.gnss.carrier_phase.double_difference_phase`.
    """

    def rdiff(sat: Array) -> Array:
        a0 = pos[:, None, :]
        ai = a0 + ant
        num = np.sum((a0 - ai) * (2.0 * sat - a0 - ai), axis=-1)
        return num / (np.linalg.norm(sat - ai, axis=-1) + np.linalg.norm(sat - a0, axis=-1))

    return 2 * np.pi / GPS_L1_WAVELENGTH_M * (rdiff(sat_n) - rdiff(sat_m))


def _transition_and_noise(F: Array, q: Array, dt: float) -> tuple[Array, Array]:
    """The exact transition and discrete noise of one batch of ``F`` over ``dt`` for a diagonal
    ``GQG^T = diag(q)``: :func:`~navcore.estimation.discretize.discretize` with
    ``method="nilpotent"`` (``F^4 = 0``), unchecked. The inner-loop kernel of
    :func:`run_monte_carlo`."""
    return discretize_unchecked(F, q, dt, method="nilpotent", diagonal=True)


def _increment_quaternions(r: Array) -> tuple[tuple[Array, ...], tuple[Array, ...]]:
    """The quaternions of the rotation vectors ``r`` ``(N, S, 3)`` and of their halves, as
    :func:`~navcore.frames.quat_from_rotvec` gives them, each component an ``(S, N)`` array.

    One sine and one cosine of a quarter of the angle serve both: the half rotation is
    ``[cos(a/4), sin(a/4) r / a]`` and the whole one ``[1 - 2 sin²(a/4), 2 cos(a/4) sin(a/4) r / a]``
    (the double-angle identities; equal to round-off). Below an angle of 2e-8 rad, ``sin(a/4)/a``
    is its series ``1/4 - a²/384`` (the small-angle branch of ``quat_from_rotvec``).
    """
    rx, ry, rz = (np.ascontiguousarray(r[..., i].T) for i in range(3))  # (S, N) each
    angle2 = rx * rx + ry * ry + rz * rz
    angle = np.sqrt(angle2)
    quarter = 0.25 * angle
    s, c = np.sin(quarter), np.cos(quarter)
    small = angle < 2e-8
    k = np.where(small, 0.25 - angle2 / 384.0, s / np.where(small, 1.0, angle))
    k2 = 2.0 * c * k
    half = (c, k * rx, k * ry, k * rz)
    whole = (1.0 - 2.0 * s * s, k2 * rx, k2 * ry, k2 * rz)
    return whole, half


def _strapdown_rows(
    pos: Array, vel: Array, quat: Array, w: Array, f: Array, dt: float, gravity: float = G0
) -> tuple[Array, Array, Array, Array]:
    """The simplified mechanization of :func:`~navcore.inertial.strapdown.strapdown_interval` over
    ``S`` IMU intervals, chaining the attitude one interval at a time (the order of ``S`` calls of
    :func:`~navcore.inertial.strapdown.strapdown_step`) on arrays with the runs innermost.

    The inner-loop kernel of :func:`run_monte_carlo` (nothing is checked): for the thousands of
    rows of a batched band, ``S`` sequential Hamilton products on contiguous rows cost less than
    the ``log2 S`` products of the whole ``(N, S, 4)`` array of the parallel prefix product, and
    the result is the same to round-off (the products are associated in another order).

    Parameters
    ----------
    pos, vel : (N, 3) arrays
        Position (m) and velocity (m/s), NED.
    quat : (N, 4) array
        Attitude ``q_bn``, scalar first.
    w, f : (N, S, 3) arrays
        Angular rate (rad/s) and specific force (m/s²) of each interval.
    dt : float
        IMU interval, s.
    gravity : float
        Local gravity along +down (m/s²).

    Returns
    -------
    pos, vel, quat : arrays
        The state after the ``S`` intervals.
    f_n_mean : (N, 3) ndarray
        The specific force resolved in NED, averaged over the intervals (for the error model).
    """
    (dw, dx, dy, dz), hq = _increment_quaternions(w * dt)  # (S, N) each
    S = w.shape[1]
    # the attitude at the start of each interval: q_{s+1} = q_s ⊗ dq_s (strapdown_step's order)
    qs = np.empty((4, S + 1, w.shape[0]))
    a, b, c, d = (quat[:, i].copy() for i in range(4))
    for s in range(S):
        qs[0, s], qs[1, s], qs[2, s], qs[3, s] = a, b, c, d
        e, x, y, z = dw[s], dx[s], dy[s], dz[s]
        a, b, c, d = (
            a * e - b * x - c * y - d * z,
            a * x + b * e + c * z - d * y,
            a * y - b * z + c * e + d * x,
            a * z + b * y - c * x + d * e,
        )
    qs[0, S], qs[1, S], qs[2, S], qs[3, S] = a, b, c, d
    # mid-interval attitude (start ⊗ half increment) resolves the specific force
    a, b, c, d = qs[0, :S], qs[1, :S], qs[2, :S], qs[3, :S]
    e, x, y, z = hq
    mw = a * e - b * x - c * y - d * z
    mx = a * x + b * e + c * z - d * y
    my = a * y - b * z + c * e + d * x
    mz = a * z + b * y - c * x + d * e
    fx, fy, fz = (f[..., i].T for i in range(3))
    ww, xx, yy, zz = mw * mw, mx * mx, my * my, mz * mz
    fn = (ww + xx - yy - zz) * fx + 2 * (mx * my - mw * mz) * fy + 2 * (mx * mz + mw * my) * fz
    fe = 2 * (mx * my + mw * mz) * fx + (ww - xx + yy - zz) * fy + 2 * (my * mz - mw * mx) * fz
    fd = 2 * (mx * mz - mw * my) * fx + 2 * (my * mz + mw * mx) * fy + (ww - xx - yy + zz) * fz
    f_n = np.stack([fn, fe, fd])  # (3, S, N)
    acc = f_n.copy()
    acc[2] += gravity
    v_all = vel.T[:, None, :] + np.cumsum(acc, axis=1) * dt  # v_1 .. v_S, (3, S, N)
    v_prev = np.concatenate([vel.T[:, None, :], v_all[:, :-1]], axis=1)
    pos_end = pos + 0.5 * dt * np.sum(v_prev + v_all, axis=1).T
    q_end = qs[:, S].T
    q_end = q_end / np.linalg.norm(q_end, axis=-1, keepdims=True)
    return pos_end, np.ascontiguousarray(v_all[:, -1].T), q_end, f_n.mean(axis=1).T


def sequential_scalar_updates(x: Array, P: Array, y: Array, H: Array, r: Array) -> tuple[Array, Array]:
    """Process measurements one scalar at a time, for a batch of runs.

    Parameters
    ----------
    x : (N, n) array
        Error-state estimates (units of the state layout).
    P : (N, n, n) array
        Covariances (not checked: an inner-loop helper of :func:`run_monte_carlo`, which
        checks its scenario at entry).
    y : (N, m) array
        Measurements ``y = H x + v`` with uncorrelated noise of variances ``r``.
    H : (N, m, n) array
        Rows.
    r : (m,) or (N, m) array
        Noise variances (measurement units squared), shared by the runs or one row per run.

    Returns
    -------
    x_post : (N, n) ndarray
        Posterior error-state estimates.
    P_post : (N, n, n) ndarray
        Posterior covariances, exactly symmetric; equal to one batch update with
        ``R = diag(r)`` (:func:`navcore.estimation.kalman.kf_update`, Joseph form, is the batch
        oracle in the tests).

    Notes
    -----
    Sequential processing of uncorrelated scalar measurements (Maybeck 1979, Ch. 5),
    as in the filter of KZL Sec. 3.4.

    Examples
    --------
    >>> import numpy as np
    >>> x, P = sequential_scalar_updates(np.zeros((1, 1)), np.ones((1, 1, 1)), np.array([[2.0]]),
    ...                                  np.ones((1, 1, 1)), np.array([1.0]))
    >>> float(x[0, 0]), float(P[0, 0, 0])
    (1.0, 0.5)
    """
    for j in range(y.shape[-1]):
        h = H[:, j, :]
        Ph = np.einsum("nij,nj->ni", P, h)
        s = np.einsum("ni,ni->n", h, Ph) + r[..., j]
        K = Ph / s[:, None]
        x = x + K * (y[:, j] - np.einsum("ni,ni->n", h, x))[:, None]
        # P+ = P - K (P h)^T: the optimal-gain form, O(n^2) per scalar; symmetrised below
        P = P - K[:, :, None] * Ph[:, None, :]
    return x, symmetrize_unchecked(P)


# --- scenario ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class GnssNoise:
    r"""1-:math:`\sigma` GPS measurement noises (assumptions: the paper gives none).

    A noise is ``None`` when the scenario does not measure that quantity (a stand-alone INS
    has none of them); :func:`run_monte_carlo` raises if a mode needs one that is ``None``.

    Attributes
    ----------
    pseudorange : float or None
        Code pseudorange (m).
    delta_range : float or None
        Delta range / pseudorange rate (m/s).
    phase : float or None
        Undifferenced carrier phase per antenna and satellite (m); DDs have 4x its variance.
    attitude : float or None
        Each Euler angle from the multi-antenna attitude system (rad).
    """

    pseudorange: float | None
    delta_range: float | None
    phase: float | None
    attitude: float | None


@dataclass(frozen=True)
class Scenario:
    r"""A straight, unaccelerated flight observed by an IMU and a GPS receiver.

    Attributes
    ----------
    velocity_ned : (3,) array
        Constant true velocity (m/s).
    attitude : (3,) array
        Nominal roll, pitch, heading (rad); each run adds a heading offset ``heading_sigma``.
    duration, imu_rate, gps_rate : float
        Seconds and Hz.
    imu : ImuSpec
        Turn-on biases and scale factors (random constants per run) and white noises.
    sat_pos_ned, sat_vel_ned : (n_epochs + 1, n_sat, 3) arrays
        Satellite positions/velocities in the fixed NED frame of the origin at each epoch.
    n_visible : (n_epochs + 1,) int array
        How many satellites are tracked at each epoch: the first ``n_visible[k]`` in
        priority order (index 0 is the master satellite of the DDs).
    gnss : GnssNoise
        Measurement noises.
    init_time : float or None
        Averaging time (s) of the initialisation (levelling, gyro-bias and vertical
        accelerometer calibration); ``None`` for a run without initialisation.
    heading_sigma : float
        1-:math:`\sigma` true heading offset from the GPS track (crab angle), rad: what Eq. 4 cannot see.
    pos0_sigma, vel0_sigma : float
        Errors of the initial GPS position (m) and velocity (m/s).
    clock_bias_sigma, clock_drift_sigma : float
        Initial clock uncertainty (m, m/s).
    clock_phase_walk, clock_drift_walk : float
        Clock random walks, root PSD (m/√s, m/s/√s).
    accel_bias_walk, gyro_bias_walk : float
        Filter tuning of the bias random walks (the truth biases are constant).
    baselines_b : (nb, 3) array or None
        Antenna baselines :math:`A_0 \to A_1, \dots, A_0 \to A_{n_b}` in body axes (m),
        ``nb >= 1`` (KZL's system has two); ``None`` without a multi-antenna system (the
        double-difference mode needs them).
    """

    velocity_ned: Array
    attitude: Array
    duration: float
    imu_rate: float
    gps_rate: float
    imu: ImuSpec
    sat_pos_ned: Array
    sat_vel_ned: Array
    n_visible: NDArray[np.int64]
    gnss: GnssNoise
    init_time: float | None
    pos0_sigma: float
    vel0_sigma: float
    baselines_b: Array | None
    heading_sigma: float = 0.0
    clock_bias_sigma: float = 30.0
    clock_drift_sigma: float = 1.0
    clock_phase_walk: float = 0.1
    clock_drift_walk: float = 0.2
    accel_bias_walk: float = 1e-5
    gyro_bias_walk: float = 1e-6

    @property
    def n_epochs(self) -> int:
        return round(self.duration * self.gps_rate)

    @property
    def steps_per_epoch(self) -> int:
        return round(self.imu_rate / self.gps_rate)


@dataclass(frozen=True)
class MonteCarloResult:
    r"""Errors (estimated - true) at each GPS epoch, for every run, and the filter's 1-:math:`\sigma`.

    Attributes
    ----------
    t : (K,) array
        Epoch times (s), ``K = n_epochs + 1``.
    pos_err, vel_err : (N, K, 3) arrays
        NED position (m) and velocity (m/s) errors.
    att_err : (N, K, 3) arrays
        Roll, pitch, heading errors (rad).
    pos_sigma, vel_sigma, att_sigma : (K, 3) arrays
        Filter 1-:math:`\sigma` (root of the run-averaged variance); attitude mapped to Euler angles.
    n_visible : (K,) int array
    """

    t: Array
    pos_err: Array
    vel_err: Array
    att_err: Array
    pos_sigma: Array
    vel_sigma: Array
    att_sigma: Array
    n_visible: NDArray[np.int64]

    def rms(self, name: str) -> Array:
        """RMS over runs of ``pos_err``, ``vel_err`` or ``att_err``: shape (K, 3)."""
        return np.sqrt(np.mean(getattr(self, name) ** 2, axis=0))

    def horizontal_rms(self, name: str) -> Array:
        """RMS over runs of the horizontal (north-east) norm: shape (K,)."""
        e = getattr(self, name)
        return np.sqrt(np.mean(e[..., 0] ** 2 + e[..., 1] ** 2, axis=0))


def _gqgt(sc: Scenario) -> Array:
    q = np.zeros(17)
    q[_V] = sc.imu.accel_random_walk**2
    q[_A] = sc.imu.gyro_random_walk**2
    q[_BA] = sc.accel_bias_walk**2
    q[_BG] = sc.gyro_bias_walk**2
    q[_CB] = sc.clock_phase_walk**2
    q[_CD] = sc.clock_drift_walk**2
    return np.diag(q)


def _needed(value: Any, name: str, what: str) -> Any:
    """``value``, or a ValueError saying that ``what`` needs it (it is ``None``)."""
    if value is None:
        raise ValueError(f"{name} must be given for {what}, got None")
    return value


def _sigma(value: float | None) -> float:
    """A noise draw's scale: 0 for a quantity not measured (the draw is still made, so every
    mode consumes the same random numbers)."""
    return 0.0 if value is None else float(value)


def _initial_covariance(sc: Scenario, C0: Array, init_time: float | None) -> Array:
    """P0 of the error state, with the tilt/accel-bias correlation that levelling creates.

    ``init_time`` is the levelling and gyro-calibration time, s, or ``None`` for a run that
    starts from the nominal attitude without initialisation."""
    P = np.zeros((17, 17))
    P[_P, _P] = sc.pos0_sigma**2 * np.eye(3)
    P[_V, _V] = sc.vel0_sigma**2 * np.eye(3)
    P[_CB, _CB] = sc.clock_bias_sigma**2
    P[_CD, _CD] = sc.clock_drift_sigma**2
    imu = sc.imu
    speed = float(np.hypot(sc.velocity_ned[0], sc.velocity_ned[1]))
    if init_time is not None:
        T = init_time
        # levelling makes the computed specific force exactly vertical: beta = R dba (n-frame)
        # and the tilt satisfy dpsi_n = beta_e / g, dpsi_e = -beta_n / g.
        s_h2 = imu.accel_bias**2 + imu.accel_random_walk**2 / T
        Sb = np.diag([s_h2, s_h2, imu.accel_random_walk**2 / T])
        M = np.array([[0.0, 1.0 / G0, 0.0], [-1.0 / G0, 0.0, 0.0], [0.0, 0.0, 0.0]])
        P[_A, _A] = M @ Sb @ M.T
        P[_A.start + 2, _A.start + 2] = sc.heading_sigma**2 + (sc.vel0_sigma / speed) ** 2
        P[_A, _BA] = M @ Sb @ C0
        P[_BA, _A] = P[_A, _BA].T
        P[_BA, _BA] = C0.T @ Sb @ C0
        P[_BG, _BG] = imu.gyro_random_walk**2 / T * np.eye(3)
    else:
        P[_A, _A] = np.diag([0.0, 0.0, sc.heading_sigma**2])
        P[_BA, _BA] = (imu.accel_bias**2 + (imu.accel_scale_factor * G0) ** 2 / 3) * np.eye(3)
        P[_BG, _BG] = imu.gyro_bias**2 * np.eye(3)
    return P


def run_monte_carlo(
    sc: Scenario,
    mode: Mode,
    n_runs: int,
    seed: int,
    *,
    initialise: bool = True,
    attitude_min_sats: int = 4,
    batches: int = 1,
    n_jobs: int | None = None,
) -> MonteCarloResult:
    r"""Seeded Monte Carlo of one filter configuration over ``n_runs`` runs, batched.

    The same ``seed`` gives the same truth (IMU errors, noises, GPS noises) for every
    ``mode``, so configurations are compared on common random numbers. The runs advance
    together (vectorised over a leading run axis); ``batches > 1`` splits them into that many
    independent tasks, each with its own seed (``numpy.random.SeedSequence(seed).spawn``,
    :func:`navcore.parallel.task_seeds`), which ``n_jobs`` workers run
    (:func:`navcore.parallel.run_tasks`: every core with ``-1``, a dask cluster under joblib's
    dask backend). The numbers depend on ``batches`` only: serial, parallel and dask runs of the
    same batches agree bit for bit.

    Parameters
    ----------
    sc : Scenario
        The flight, the IMU, the satellites and the visibility schedule.
    mode : {"ins", "tc", "tc_att", "tc_dd"}
        Stand-alone INS, tightly coupled, plus Euler attitude (only with at least
        ``attitude_min_sats`` satellites), plus double-difference phases.
    n_runs, seed : int
        Number of runs and the random seed.
    initialise : bool, default True
        Levelling + GPS heading + gyro-bias/vertical-accelerometer calibration (KZL Sec. 3.1);
        ``False`` starts from the nominal attitude with uncompensated sensors.
    attitude_min_sats : int, default 4
        Fewest visible satellites for the ``"tc_att"`` mode to use the carrier-phase
        attitude rows.
    batches : int, default 1
        Independent tasks the runs are split into (at most ``n_runs``). ``1`` draws every run
        from ``numpy.random.default_rng(seed)``; ``k > 1`` draws batch ``i`` (runs
        ``i * n_runs // k`` up to the next batch's first) from the ``i``-th child seed, so its
        numbers differ from ``batches=1`` but not with ``n_jobs`` or the backend.
    n_jobs : int or None, default None
        Workers for the batches (joblib's convention: ``-1`` every core); ``None`` runs them
        in this process.

    Returns
    -------
    MonteCarloResult
        Per-run position (m), velocity (m/s) and Euler-angle (rad) errors at each GPS epoch,
        the filter's mean 1-:math:`\sigma` of each, and the number of visible satellites.

    Raises
    ------
    ValueError
        If ``mode`` is unknown, ``n_runs`` is not a positive integer, ``batches`` is not in
        ``1..n_runs``, or the scenario lacks an input the mode needs (initialisation time,
        GNSS noise, antenna baselines).

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Secs. 3.1-3.5 (initialisation, strapdown Eqs. (7)-(9), error
    model, tightly coupled updates with double-difference phases Eq. (17), feedback).

    Examples
    --------
    Five seconds of level flight with four fixed satellites: the tightly coupled filter ends
    with a smaller horizontal error than the stand-alone INS on the same random numbers.

    >>> import numpy as np
    >>> from navcore.inertial.imu import ImuSpec
    >>> sats = np.array([[2e7, 0.0, -1e7], [-2e7, 0.0, -1e7], [0.0, 2e7, -1e7], [0.0, -2e7, -1e7]])
    >>> sc = Scenario(velocity_ned=np.array([100.0, 0.0, 0.0]), attitude=np.zeros(3),
    ...     duration=5.0, imu_rate=100.0, gps_rate=1.0, imu=ImuSpec("example", accel_bias=1e-2),
    ...     sat_pos_ned=np.tile(sats, (6, 1, 1)), sat_vel_ned=np.zeros((6, 4, 3)),
    ...     n_visible=np.full(6, 4), gnss=GnssNoise(3.0, 0.1, None, None), init_time=None,
    ...     pos0_sigma=3.0, vel0_sigma=0.1, baselines_b=None)
    >>> ins = run_monte_carlo(sc, "ins", 50, seed=1, initialise=False)
    >>> tc = run_monte_carlo(sc, "tc", 50, seed=1, initialise=False)
    >>> [round(float(r.horizontal_rms("pos_err")[-1]), 2) for r in (ins, tc)]
    [4.42, 1.48]

    Split into two batches, the runs are the same numbers in this process and on two workers:

    >>> a = run_monte_carlo(sc, "tc", 50, seed=1, initialise=False, batches=2)
    >>> b = run_monte_carlo(sc, "tc", 50, seed=1, initialise=False, batches=2, n_jobs=2)
    >>> all(np.array_equal(getattr(a, f), getattr(b, f)) for f in ("pos_err", "att_sigma"))
    True
    """
    if mode not in MODES:
        raise ValueError(f"mode must be one of {MODES}, got {mode!r}")
    require_integer("n_runs", n_runs, minimum=1)
    require_integer("batches", batches, minimum=1)
    if batches > n_runs:
        raise ValueError(f"batches must be at most n_runs ({n_runs}), got {batches}")
    if initialise:
        _needed(sc.init_time, "sc.init_time", "an initialising run")
    if batches == 1:
        parts = _monte_carlo_batch([sc], mode, n_runs, seed, initialise, [attitude_min_sats])
    else:
        from navcore.parallel import run_tasks, task_seeds

        edges = [i * n_runs // batches for i in range(batches + 1)]
        tasks = [
            ([sc], mode, edges[i + 1] - edges[i], child, initialise, [attitude_min_sats])
            for i, child in enumerate(task_seeds(seed, batches))
        ]
        parts = [task[0] for task in run_tasks(_monte_carlo_batch, tasks, n_jobs=n_jobs)]
    return _join_batches(parts)


def _digest(h: Any, name: str, value: Any) -> None:
    """Feed one named argument to ``h`` exactly: arrays by dtype, shape and bytes, other values by
    their ``repr`` (a float's ``repr`` round-trips, a frozen dataclass's lists its fields)."""
    h.update(name.encode() + b"=")
    if isinstance(value, np.ndarray):
        a = np.ascontiguousarray(value)
        h.update(f"{a.dtype.str}{a.shape}".encode())
        h.update(a.tobytes())
    else:
        h.update(repr(value).encode())
    h.update(b";")


def monte_carlo_key(
    sc: Scenario,
    mode: Mode,
    n_runs: int,
    seed: int,
    *,
    initialise: bool = True,
    attitude_min_sats: int = 4,
    batches: int = 1,
) -> str:
    r"""Digest of everything the numbers of :func:`run_monte_carlo` depend on, for memoising runs.

    Two calls with the same key return the same errors and 1-:math:`\sigma` (``n_jobs`` does not change
    them; the result's ``n_visible`` echoes the scenario's schedule). The
    key holds every argument and every field of the scenario exactly, except what the call
    provably never reads: the stand-alone INS (``"ins"``) uses no GPS measurement, so of the
    satellites it keeps only how many there are (that sets how many GPS noises are drawn, and so
    which draws the IMU noise takes next) and of the antennas only their count (the phase noises
    drawn), and none of the visibility schedule or the GPS noises; a run without initialisation
    does not read ``init_time``; only ``"tc_att"`` reads ``attitude_min_sats``. So the runs of a
    band's corners that differ only in what the mode never reads share one key.

    Parameters
    ----------
    sc, mode, n_runs, seed, initialise, attitude_min_sats, batches
        As for :func:`run_monte_carlo`.

    Returns
    -------
    str
        A hexadecimal SHA-256 digest.

    Raises
    ------
    ValueError
        If ``mode`` is unknown.

    Examples
    --------
    >>> import numpy as np
    >>> from dataclasses import replace
    >>> from navcore.inertial.imu import ImuSpec
    >>> sats = np.array([[2e7, 0.0, -1e7], [-2e7, 0.0, -1e7], [0.0, 2e7, -1e7], [0.0, -2e7, -1e7]])
    >>> sc = Scenario(velocity_ned=np.array([100.0, 0.0, 0.0]), attitude=np.zeros(3),
    ...     duration=5.0, imu_rate=100.0, gps_rate=1.0, imu=ImuSpec("example", accel_bias=1e-2),
    ...     sat_pos_ned=np.tile(sats, (6, 1, 1)), sat_vel_ned=np.zeros((6, 4, 3)),
    ...     n_visible=np.full(6, 4), gnss=GnssNoise(3.0, 0.1, None, None), init_time=None,
    ...     pos0_sigma=3.0, vel0_sigma=0.1, baselines_b=None)
    >>> three = replace(sc, n_visible=np.full(6, 3))
    >>> key = lambda s, mode: monte_carlo_key(s, mode, 50, 1, initialise=False)
    >>> key(sc, "ins") == key(three, "ins"), key(sc, "tc") == key(three, "tc")
    (True, False)
    """
    if mode not in MODES:
        raise ValueError(f"mode must be one of {MODES}, got {mode!r}")
    h = hashlib.sha256()
    _digest(h, "call", (mode, int(n_runs), int(seed), bool(initialise), int(batches)))
    if mode == "tc_att":
        _digest(h, "attitude_min_sats", int(attitude_min_sats))
    for f in fields(sc):
        value = getattr(sc, f.name)
        if f.name == "init_time" and not initialise:
            continue
        if mode == "ins" and f.name in ("sat_pos_ned", "sat_vel_ned"):
            value = np.shape(value)[1]
        elif mode == "ins" and f.name == "baselines_b":
            value = None if value is None else np.shape(value)[0]
        elif mode == "ins" and f.name in ("n_visible", "gnss"):
            continue
        _digest(h, f.name, value)
    return h.hexdigest()


#: The fields of a :class:`Scenario` that every scenario of one :func:`run_monte_carlo_batch` call
#: shares (the flight, the rates and so the array shapes, the satellites, the antennas); the others
#: are values per row of the batch.
_BATCH_SHARED_FIELDS = (
    "velocity_ned",
    "attitude",
    "duration",
    "imu_rate",
    "gps_rate",
    "sat_pos_ned",
    "sat_vel_ned",
    "baselines_b",
)


def batch_group_key(sc: Scenario) -> str:
    """Digest of the fields of ``sc`` that the scenarios of one batch share (the flight, the
    rates, the satellites and the antennas); scenarios with equal keys can run in one
    :func:`run_monte_carlo_batch` call.

    Parameters
    ----------
    sc : Scenario
        The flight, the IMU, the satellites and the visibility schedule.

    Returns
    -------
    str
        A hexadecimal SHA-256 digest.

    Examples
    --------
    >>> import numpy as np
    >>> from dataclasses import replace
    >>> from navcore.inertial.imu import ImuSpec
    >>> sats = np.array([[2e7, 0.0, -1e7], [-2e7, 0.0, -1e7], [0.0, 2e7, -1e7], [0.0, -2e7, -1e7]])
    >>> sc = Scenario(velocity_ned=np.array([100.0, 0.0, 0.0]), attitude=np.zeros(3),
    ...     duration=5.0, imu_rate=100.0, gps_rate=1.0, imu=ImuSpec("example", accel_bias=1e-2),
    ...     sat_pos_ned=np.tile(sats, (6, 1, 1)), sat_vel_ned=np.zeros((6, 4, 3)),
    ...     n_visible=np.full(6, 4), gnss=GnssNoise(3.0, 0.1, None, None), init_time=None,
    ...     pos0_sigma=3.0, vel0_sigma=0.1, baselines_b=None)
    >>> batch_group_key(sc) == batch_group_key(replace(sc, gnss=GnssNoise(6.0, 0.1, None, None)))
    True
    >>> batch_group_key(sc) == batch_group_key(replace(sc, duration=4.0))
    False
    """
    h = hashlib.sha256()
    for name in _BATCH_SHARED_FIELDS:
        _digest(h, name, getattr(sc, name))
    return h.hexdigest()


def run_monte_carlo_batch(
    scenarios: Sequence[Scenario],
    mode: Mode,
    n_runs: int,
    seed: int,
    *,
    initialise: bool = True,
    attitude_min_sats: int = 4,
) -> list[MonteCarloResult]:
    r""":func:`run_monte_carlo` of several scenarios in one vectorised call (a band's runs).

    The leading axis of every array is (scenario x Monte Carlo run). Each scenario takes exactly
    the random numbers it takes alone (common random numbers across the scenarios: each draw is
    made once and scaled by each scenario's own :math:`\sigma`), and each run sees the arithmetic it sees
    alone, so the results equal ``[run_monte_carlo(sc, mode, n_runs, seed, ...) for sc in
    scenarios]`` (``batches=1``). The scenarios must share the flight, the rates, the satellites
    and the antennas (:func:`batch_group_key`); noises, initial sigmas, the IMU's errors, the
    filter's tuning and the visibility schedule may differ.

    Parameters
    ----------
    scenarios : sequence of Scenario
        At least one; all with the same :func:`batch_group_key`.
    mode, n_runs, seed, initialise, attitude_min_sats
        As for :func:`run_monte_carlo`.

    Returns
    -------
    list of MonteCarloResult
        One per scenario, in order.

    Raises
    ------
    ValueError
        If ``scenarios`` is empty or its scenarios differ in a shared field, or as
        :func:`run_monte_carlo` raises.

    Examples
    --------
    >>> import numpy as np
    >>> from dataclasses import replace
    >>> from navcore.inertial.imu import ImuSpec
    >>> sats = np.array([[2e7, 0.0, -1e7], [-2e7, 0.0, -1e7], [0.0, 2e7, -1e7], [0.0, -2e7, -1e7]])
    >>> sc = Scenario(velocity_ned=np.array([100.0, 0.0, 0.0]), attitude=np.zeros(3),
    ...     duration=5.0, imu_rate=100.0, gps_rate=1.0, imu=ImuSpec("example", accel_bias=1e-2),
    ...     sat_pos_ned=np.tile(sats, (6, 1, 1)), sat_vel_ned=np.zeros((6, 4, 3)),
    ...     n_visible=np.full(6, 4), gnss=GnssNoise(3.0, 0.1, None, None), init_time=None,
    ...     pos0_sigma=3.0, vel0_sigma=0.1, baselines_b=None)
    >>> noisy = replace(sc, gnss=GnssNoise(6.0, 0.1, None, None))
    >>> both = run_monte_carlo_batch([sc, noisy], "tc", 50, seed=1, initialise=False)
    >>> [round(float(r.horizontal_rms("pos_err")[-1]), 2) for r in both]
    [1.48, 2.58]
    >>> alone = run_monte_carlo(noisy, "tc", 50, seed=1, initialise=False)
    >>> bool(np.allclose(both[1].pos_err, alone.pos_err, rtol=1e-10, atol=0.0))
    True
    """
    if mode not in MODES:
        raise ValueError(f"mode must be one of {MODES}, got {mode!r}")
    require_integer("n_runs", n_runs, minimum=1)
    scenarios = list(scenarios)
    if not scenarios:
        raise ValueError("scenarios must hold at least one Scenario, got none")
    keys = {batch_group_key(sc) for sc in scenarios}
    if len(keys) > 1:
        raise ValueError(f"scenarios must share the fields {_BATCH_SHARED_FIELDS} to run in one batch")
    if initialise:
        for sc in scenarios:
            _needed(sc.init_time, "sc.init_time", "an initialising run")
    parts = _monte_carlo_batch(
        scenarios, mode, n_runs, seed, initialise, [attitude_min_sats] * len(scenarios)
    )
    return [_join_batches([part]) for part in parts]


def _join_batches(parts: list[tuple[MonteCarloResult, Array, Array, Array]]) -> MonteCarloResult:
    """One result from batches: runs concatenated, the run-averaged variances weighted by runs."""
    first = parts[0][0]
    if len(parts) == 1:
        var = parts[0][1:]
    else:
        n = [p[0].pos_err.shape[0] for p in parts]
        var = tuple(sum(k * p[1 + i] for k, p in zip(n, parts, strict=True)) / sum(n) for i in range(3))
    return MonteCarloResult(
        t=first.t,
        pos_err=np.concatenate([p[0].pos_err for p in parts]),
        vel_err=np.concatenate([p[0].vel_err for p in parts]),
        att_err=np.concatenate([p[0].att_err for p in parts]),
        pos_sigma=np.sqrt(var[0]),
        vel_sigma=np.sqrt(var[1]),
        att_sigma=np.sqrt(var[2]),
        n_visible=first.n_visible,
    )


def _monte_carlo_batch(
    scs: Sequence[Scenario],
    mode: str,
    n_runs: int,
    seed: int | np.random.SeedSequence,
    initialise: bool,
    attitude_min_sats: Sequence[int],
) -> list[tuple[MonteCarloResult, Array, Array, Array]]:
    r"""``n_runs`` runs from ``default_rng(seed)`` of each scenario of ``scs`` (one task of
    :func:`run_monte_carlo`, or one batch of :func:`run_monte_carlo_batch`): per scenario, the
    result without its 1-:math:`\sigma` columns, and the run-averaged variances of position, velocity and
    attitude.

    The scenarios share everything :func:`batch_group_key` digests; what else they hold (noises,
    sigmas, the IMU's errors, the visibility schedule, ``attitude_min_sats``) is a value per row
    of the leading axis, row ``b * n_runs + n`` being run ``n`` of scenario ``b``. Every
    scenario takes the draws of ``default_rng(seed)`` that it takes alone (each standard normal
    is drawn once for ``n_runs`` rows and scaled per row), and every row sees the arithmetic it
    sees alone (element by element, or a measurement update on the rows with its satellite
    count), so a row's numbers do not depend on the other scenarios of the batch.
    """
    sc = scs[0]  # the fields every scenario of the batch shares (batch_group_key)
    B, N = len(scs), n_runs
    M = B * N
    rng = np.random.default_rng(seed)
    dt = 1.0 / sc.imu_rate
    T = 1.0 / sc.gps_rate
    K = sc.n_epochs
    steps = sc.steps_per_epoch
    v_true = np.asarray(sc.velocity_ned, dtype=float)
    roll0, pitch0, yaw0 = (float(a) for a in sc.attitude)

    def per_row(get: Any) -> Array:
        """One value per scenario, repeated over its ``N`` rows: ``(M,)``."""
        return np.repeat(np.array([float(get(s)) for s in scs]), N)

    def shared(z: Array) -> Array:
        """Draws ``z`` of shape ``(N, ...)``, the same for every scenario: ``(M, ...)``."""
        return z if B == 1 else np.broadcast_to(z, (B, *z.shape)).reshape(M, *z.shape[1:])

    imus = [s.imu for s in scs]
    gyro_rw = np.repeat(np.array([i.gyro_random_walk for i in imus]), N)
    accel_rw = np.repeat(np.array([i.accel_random_walk for i in imus]), N)

    # --- truth (constant attitude and velocity; flat non-rotating Earth, as in Eqs. 7-9) ---
    yaw_true = yaw0 + per_row(lambda s: s.heading_sigma) * shared(rng.standard_normal(N))
    C_true = np.stack([dcm_from_euler(roll0, pitch0, y) for y in yaw_true])
    f_true_b = np.einsum("nji,j->ni", C_true, np.array([0.0, 0.0, -G0]))
    b_g = per_row(lambda s: s.imu.gyro_bias)[:, None] * shared(rng.standard_normal((N, 3)))
    b_a = per_row(lambda s: s.imu.accel_bias)[:, None] * shared(rng.standard_normal((N, 3)))
    shared(rng.standard_normal((N, 3)))  # gyro scale factors: drawn for the record, the true rate is zero
    s_a = per_row(lambda s: s.imu.accel_scale_factor)[:, None] * shared(rng.standard_normal((N, 3)))
    f_sensor_const = f_true_b * (1.0 + s_a) + b_a  # accelerometer output without noise
    clock = np.stack(
        [
            per_row(lambda s: s.clock_bias_sigma) * shared(rng.standard_normal(N)),
            per_row(lambda s: s.clock_drift_sigma) * shared(rng.standard_normal(N)),
        ],
        -1,
    )

    # --- initialisation (KZL Sec. 3.1) ---
    if initialise:
        Tinit = per_row(lambda s: _needed(s.init_time, "sc.init_time", "an initialising run"))
    else:
        Tinit = np.full(M, math.inf)
    pos_hat = per_row(lambda s: s.pos0_sigma)[:, None] * shared(rng.standard_normal((N, 3)))
    v_meas0 = v_true + per_row(lambda s: s.vel0_sigma)[:, None] * shared(rng.standard_normal((N, 3)))
    f_avg = f_sensor_const + (accel_rw / np.sqrt(Tinit))[:, None] * shared(rng.standard_normal((N, 3)))
    w_avg = b_g + (gyro_rw / np.sqrt(Tinit))[:, None] * shared(rng.standard_normal((N, 3)))
    if initialise:
        roll_h, pitch_h = levelling(f_avg)
        yaw_h = heading_from_velocity(v_meas0)
        C_hat0 = np.stack([dcm_from_euler(r, p, y) for r, p, y in zip(roll_h, pitch_h, yaw_h, strict=True)])
        bg_hat = w_avg.copy()
        ba_hat = f_avg - np.einsum("nji,j->ni", C_hat0, np.array([0.0, 0.0, -G0]))
    else:
        C_hat0 = np.tile(dcm_from_euler(roll0, pitch0, yaw0), (M, 1, 1))
        bg_hat = np.zeros((M, 3))
        ba_hat = np.zeros((M, 3))
    quat = np.stack([quat_from_dcm(C) for C in C_hat0])
    pos, vel = pos_hat, v_meas0.copy()
    clock_hat = np.zeros((M, 2))
    C0 = dcm_from_euler(roll0, pitch0, yaw0)
    P = np.repeat(
        np.stack([_initial_covariance(s, C0, s.init_time if initialise else None) for s in scs]), N, axis=0
    )
    # GQG^T is diagonal (isotropic noises, _gqgt): its diagonal per row, to scale columns
    q_diag = np.repeat(np.stack([np.diag(_gqgt(s)) for s in scs]), N, axis=0)  # (runs, n)
    noise = {
        name: [getattr(s.gnss, name) for s in scs]
        for name in ("pseudorange", "delta_range", "phase", "attitude")
    }
    sig = {name: np.repeat(np.array([_sigma(v) for v in vals]), N) for name, vals in noise.items()}
    given = {name: np.repeat(np.array([v is not None for v in vals]), N) for name, vals in noise.items()}
    clock_phase_walk = per_row(lambda s: s.clock_phase_walk)
    clock_drift_walk = per_row(lambda s: s.clock_drift_walk)
    n_vis = np.repeat(np.stack([np.asarray(s.n_visible) for s in scs]), N, axis=0)
    att_min = np.repeat(np.asarray(attitude_min_sats, dtype=np.int64), N)
    k2pi = 2 * np.pi / GPS_L1_WAVELENGTH_M
    # phase noise of every antenna is drawn in every mode (common random numbers); without
    # baselines, three antennas' worth, as for KZL's two baselines
    n_antennas = 1 + (2 if sc.baselines_b is None else np.shape(sc.baselines_b)[0])

    out_pos = np.zeros((M, K + 1, 3))
    out_vel = np.zeros((M, K + 1, 3))
    out_att = np.zeros((M, K + 1, 3))
    var_pos = np.zeros((B, K + 1, 3))
    var_vel = np.zeros((B, K + 1, 3))
    var_att = np.zeros((B, K + 1, 3))
    eul_true = euler_batch(C_true)

    # the scenarios and the arguments are checked: the loop calls the kernels without re-checking
    _k_dcm_from_quat_batch = unchecked(dcm_from_quat_batch)
    _k_error_dynamics_17 = unchecked(error_dynamics_17)
    _k_sequential_scalar_updates = unchecked(sequential_scalar_updates)
    _k_euler_batch = unchecked(euler_batch)
    _k_euler_jacobian_batch = unchecked(euler_jacobian_batch)
    _k_correct_attitude = unchecked(correct_attitude)

    def run_mean(a: Array) -> Array:
        """Mean over each scenario's runs of a per-row ``(M, 3)`` array: ``(B, 3)``."""
        return np.mean(a.reshape(B, N, 3), axis=1)

    def record(k: int, t: float) -> None:
        C_hat = _k_dcm_from_quat_batch(quat)
        out_pos[:, k] = pos - v_true * t
        out_vel[:, k] = vel - v_true
        out_att[:, k] = _wrap(_k_euler_batch(C_hat) - eul_true)
        J = _k_euler_jacobian_batch(C_hat)
        var_pos[:, k] = run_mean(np.diagonal(P[:, _P, _P], axis1=1, axis2=2))
        var_vel[:, k] = run_mean(np.diagonal(P[:, _V, _V], axis1=1, axis2=2))
        Pe = J @ P[:, _A, _A] @ np.swapaxes(J, -1, -2)
        var_att[:, k] = run_mean(np.diagonal(Pe, axis1=1, axis2=2))

    def need(name: str, rows: Any) -> Array:
        """The per-row noise ``name`` of ``rows``; a ValueError if a scenario lacks it."""
        if not np.all(given[name][rows]):
            _needed(None, f"sc.gnss.{name}", f"mode {mode!r}")
        return sig[name][rows]

    def update(
        rows: Any, nu: int, k: int, C_hat: Array, e_pr: Array, e_prr: Array, e_ph: Array, e_att: Array
    ) -> None:
        """The measurement update and feedback of epoch ``k`` on ``rows``, which see ``nu`` satellites."""
        t = k * T
        p_r, v_r, q_r, C_r = pos[rows], vel[rows], quat[rows], C_hat[rows]
        m = p_r.shape[0]
        sats = sc.sat_pos_ned[k, :nu]
        svel = sc.sat_vel_ned[k, :nu]
        x_true = v_true * t
        d_hat = sats[None] - p_r[:, None]
        rho_hat = np.linalg.norm(d_hat, axis=-1)
        u_hat = d_hat / rho_hat[..., None]
        d_true = sats - x_true
        rho_true = np.linalg.norm(d_true, axis=-1)
        u_true = d_true / rho_true[:, None]
        ch, c = clock_hat[rows], clock[rows]
        y_rho = (rho_hat + ch[:, :1]) - (rho_true[None] + c[:, :1] + e_pr[rows, :nu])
        rate_hat = np.einsum("nsi,nsi->ns", u_hat, svel[None] - v_r[:, None]) + ch[:, 1:]
        rate_true = np.einsum("si,si->s", u_true, svel - v_true)[None] + c[:, 1:] + e_prr[rows, :nu]
        y = np.empty((m, 2 * nu))
        y[:, 0::2] = y_rho
        y[:, 1::2] = rate_hat - rate_true
        H = np.zeros((m, 2 * nu, 17))
        H[:, 0::2, _P] = -u_hat
        H[:, 0::2, _CB] = 1.0
        H[:, 1::2, _V] = -u_hat
        H[:, 1::2, _CD] = 1.0
        r = np.tile(np.stack([need("pseudorange", rows) ** 2, need("delta_range", rows) ** 2], -1), (1, nu))
        dx = np.zeros((m, 17))
        dx, P_r = _k_sequential_scalar_updates(dx, P[rows], y, H, r)
        if mode == "tc_att":
            att = np.flatnonzero(nu >= att_min[rows])  # the rows with the multi-antenna attitude
            if att.size:
                sub = slice(None) if att.size == m else att
                C_a = C_r[sub]
                eul_hat = _k_euler_batch(C_a)
                y_att = _wrap(eul_hat - (eul_true[rows][sub] + e_att[rows][sub]))
                H_att = np.zeros((C_a.shape[0], 3, 17))
                H_att[:, :, _A] = _k_euler_jacobian_batch(C_a)
                sig_att = need("attitude", rows)[sub]
                # the attitude rows see the already-updated error state through H dx
                dx_a, P_a = _k_sequential_scalar_updates(
                    dx[sub], P_r[sub], y_att, H_att, np.repeat((sig_att**2)[:, None], 3, axis=1)
                )
                dx[sub], P_r[sub] = dx_a, P_a
        if mode == "tc_dd" and nu >= DD_MIN_SATELLITES:
            base_b = _needed(sc.baselines_b, "sc.baselines_b", f"mode {mode!r}")
            nb = base_b.shape[0]
            ant_hat = np.einsum("nij,bj->nbi", C_r, base_b)  # (m, nb, 3) NED
            ant_true = np.einsum("nij,bj->nbi", C_true[rows], base_b)
            e_r = e_ph[rows]
            y_dd = np.zeros((m, (nu - 1) * nb))
            H_dd = np.zeros((m, (nu - 1) * nb, 17))
            for s in range(1, nu):
                dd_hat = _dd_phase_batch(p_r, ant_hat, sats[s], sats[0])
                ph = e_r[:, s, 1:] - e_r[:, s, :1] - e_r[:, 0, 1:] + e_r[:, 0, :1]
                dd_meas = (
                    _dd_phase_batch(np.broadcast_to(x_true, (m, 3)), ant_true, sats[s], sats[0])
                    + k2pi * ph[:, :nb]
                )
                cols = slice((s - 1) * nb, s * nb)
                y_dd[:, cols] = dd_hat - dd_meas
                # Eq. 17 (corrected): (l_m - l_n)^T [R l x]_paper = (R l) x (l_m - l_n)
                H_dd[:, cols, _A] = k2pi * np.cross(ant_hat, (u_hat[:, 0] - u_hat[:, s])[:, None, :])
            sig_ph = need("phase", rows)
            for value in np.unique(sig_ph):  # rows of one phase noise share one whitening
                same = np.flatnonzero(sig_ph == value)
                sub = slice(None) if same.size == m else same
                Lc = np.linalg.cholesky(dd_covariance(nu, k2pi * float(value), nb))
                Linv = np.linalg.inv(Lc)
                y_w = np.einsum("ij,nj->ni", Linv, y_dd[sub])
                H_w = np.einsum("ij,njk->nik", Linv, H_dd[sub])
                dx_d, P_d = _k_sequential_scalar_updates(dx[sub], P_r[sub], y_w, H_w, np.ones(y_w.shape[1]))
                dx[sub], P_r[sub] = dx_d, P_d
        # feedback correction and reset (KZL Sec. 3.5)
        pos[rows] = p_r - dx[:, _P]
        vel[rows] = v_r - dx[:, _V]
        quat[rows] = _k_correct_attitude(q_r, dx[:, _A], "left")
        ba_hat[rows] = ba_hat[rows] - dx[:, _BA]
        bg_hat[rows] = bg_hat[rows] - dx[:, _BG]
        clock_hat[rows] = ch - dx[:, _CB : _CD + 1]
        P[rows] = P_r

    record(0, 0.0)
    nsat_all = sc.sat_pos_ned.shape[1]
    for k in range(1, K + 1):
        # IMU noise for this second, drawn in the same order for every mode
        n_a = (accel_rw / np.sqrt(dt))[:, None, None] * shared(rng.standard_normal((N, steps, 3)))
        n_g = (gyro_rw / np.sqrt(dt))[:, None, None] * shared(rng.standard_normal((N, steps, 3)))
        # 100 Hz strapdown on bias-corrected data (Eqs. 7-9), vectorised over the interval
        w_hat = (b_g - bg_hat)[:, None, :] + n_g
        f_hat = (f_sensor_const - ba_hat)[:, None, :] + n_a
        pos, vel, quat, f_n_mean = _strapdown_rows(pos, vel, quat, w_hat, f_hat, dt)
        clock = clock + np.stack([clock[:, 1] * T, np.zeros(M)], -1)
        clock = clock + np.stack(
            [
                clock_phase_walk * np.sqrt(T) * shared(rng.standard_normal(N)),
                clock_drift_walk * np.sqrt(T) * shared(rng.standard_normal(N)),
            ],
            -1,
        )
        clock_hat = clock_hat + np.stack([clock_hat[:, 1] * T, np.zeros(M)], -1)
        # GPS noise draws (always drawn, used or not)
        e_pr = sig["pseudorange"][:, None] * shared(rng.standard_normal((N, nsat_all)))
        e_prr = sig["delta_range"][:, None] * shared(rng.standard_normal((N, nsat_all)))
        e_ph = sig["phase"][:, None, None] * shared(rng.standard_normal((N, nsat_all, n_antennas)))
        e_att = sig["attitude"][:, None] * shared(rng.standard_normal((N, 3)))

        # covariance prediction over the GPS interval
        C_hat = _k_dcm_from_quat_batch(quat)
        F = _k_error_dynamics_17(C_hat, f_n_mean)
        Phi, Qd = _transition_and_noise(F, q_diag, T)
        P = symmetrize_unchecked(Phi @ P @ np.swapaxes(Phi, -1, -2) + Qd)

        if mode != "ins":
            counts = n_vis[:, k]
            for nu in np.unique(counts):  # the rows that see nu satellites are updated together
                if nu < 1:
                    continue
                same = np.flatnonzero(counts == nu)
                update(slice(None) if same.size == M else same, int(nu), k, C_hat, e_pr, e_prr, e_ph, e_att)
        record(k, k * T)

    empty = np.zeros((0, 3))
    out = []
    for b, s in enumerate(scs):
        rows = slice(b * N, (b + 1) * N)
        result = MonteCarloResult(
            t=np.arange(K + 1, dtype=float) * T,
            pos_err=out_pos[rows],
            vel_err=out_vel[rows],
            att_err=out_att[rows],
            pos_sigma=empty,
            vel_sigma=empty,
            att_sigma=empty,
            n_visible=np.asarray(s.n_visible),
        )
        out.append((result, var_pos[b], var_vel[b], var_att[b]))
    return out


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "dt": POSITIVE,
        "n_runs": COUNT,
        "imu_rate": POSITIVE,
        "gps_rate": POSITIVE,
        "duration": POSITIVE,
        "pos0_sigma": NONNEGATIVE,
        "vel0_sigma": NONNEGATIVE,
        "heading_sigma": NONNEGATIVE,
        "clock_bias_sigma": NONNEGATIVE,
        "clock_drift_sigma": NONNEGATIVE,
        "accel_bias_walk": NONNEGATIVE,
        "gyro_bias_walk": NONNEGATIVE,
        "clock_drift_walk": NONNEGATIVE,
        "clock_phase_walk": NONNEGATIVE,
        "init_time": NONNEGATIVE,
        "attitude_min_sats": COUNT,
        "q": UNIT_QUATERNION_STACK,
        "C": ROTATION_STACK,
        "batches": COUNT,
    },
)
