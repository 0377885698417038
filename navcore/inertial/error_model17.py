r"""The 17-state error model of a low-cost tightly coupled INS/GNSS filter (NED frame).

State (KZL Eq. 1), error = estimated - true:

==================  ====  =====================================================
block               size  meaning
==================  ====  =====================================================
``position``        3     NED position error (m)
``velocity``        3     NED velocity error (m/s)
``misalignment``    3     n-frame attitude error :math:`\Delta\psi` (rad)
``accel bias``      3     accelerometer bias error (m/s²)
``gyro bias``       3     gyro bias error (rad/s)
``clock bias``      1     receiver clock bias (m)
``clock drift``     1     receiver clock drift (m/s)
==================  ====  =====================================================

Attitude-error convention: :math:`\hat R_b^n = (I + [\Delta\psi\times]) R_b^n` with the
standard cross-product matrix :math:`[a\times]b = a\times b` (:func:`navcore.frames.skew`):
error = estimated - true, and :math:`\Delta\psi` rotates the true frame into the estimated one
*with the plus sign*. This is the opposite sign of the :math:`\psi` angle of
:mod:`navcore.inertial.error_dynamics` (:math:`\hat C^n_b = (I - [\psi\times]) C^n_b`), so
:math:`\Delta\psi = -\psi`; convert with
:func:`navcore.inertial.error_dynamics.psi_to_attitude_error` wherever the two meet.
The sensor outputs are corrected by the estimated biases, so a bias *error* enters the
computed specific force and rate with a minus sign. Linearising KZL Eqs. 7-9 (flat,
non-rotating Earth) gives the reconstructed KZL Eq. 10:

.. math::

    \begin{aligned}
    \Delta\dot x &= \Delta v,\qquad \Delta\dot b = w_b,\\
    \Delta\dot v &= F_{23}\Delta\psi - \hat R_b^n \Delta b_a - \hat R_b^n w_a,\\
    \Delta\dot\psi &= -\hat R_b^n \Delta b_\omega - \hat R_b^n w_\omega,\\
    c\Delta\dot t_r &= c\Delta t_{r,d} + w_c,\qquad c\Delta\dot t_{r,d} = w_d,
    \end{aligned}

with :math:`F_{23} = -[\hat a^n\times]`. KZL Eq. 11 prints exactly this matrix,
``[[0, a_d, -a_e], [-a_d, 0, a_n], [a_e, -a_n, 0]]``, and calls it :math:`[\hat a^n\times]`:
the paper's bracket is the *negative* of the standard skew matrix
(:func:`skew_paper`). F is strictly block upper-triangular, so :math:`F^4 = 0` and
:math:`e^{FT}` is the cubic polynomial of KZL Eq. 5 (:func:`transition_exact`).

References
----------
.. [1] S. Knedlik, J. Zhou, O. Loffeld (2009), Eqs. (1), (5), (6), (10), (11), (13).
.. [2] P. D. Groves (2013), Sec. 14.2 (local-navigation-frame error model).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    NONNEGATIVE,
    POSITIVE,
    ROTATION_STACK,
    as_finite_array,
    check_public,
    require_nonnegative,
    require_positive,
    require_square,
)
from navcore.estimation.layout import StateBlock, StateLayout
from navcore.frames import skew
from navcore.trace import implements

__all__ = [
    "ERROR_LAYOUT_17",
    "code_doppler_rows",
    "error_dynamics_17",
    "noise_psd_17",
    "observability_rank",
    "skew_paper",
    "transition_exact",
    "transition_first_order",
]

Array = NDArray[np.float64]

#: KZL Eq. 1: the 17 error states, in order.
ERROR_LAYOUT_17 = StateLayout(
    (
        StateBlock("position", 3, "m", "NED position error"),
        StateBlock("velocity", 3, "m/s", "NED velocity error"),
        StateBlock("misalignment", 3, "rad", "n-frame attitude error (psi)"),
        StateBlock("accel bias", 3, "m/s^2", "accelerometer bias error"),
        StateBlock("gyro bias", 3, "rad/s", "gyro bias error"),
        StateBlock("clock bias", 1, "m", "receiver clock bias c*dt"),
        StateBlock("clock drift", 1, "m/s", "receiver clock drift c*dt_dot"),
    ),
    name="KZL 17-state tightly coupled",
)

_P = ERROR_LAYOUT_17.slice("position")
_V = ERROR_LAYOUT_17.slice("velocity")
_A = ERROR_LAYOUT_17.slice("misalignment")
_BA = ERROR_LAYOUT_17.slice("accel bias")
_BG = ERROR_LAYOUT_17.slice("gyro bias")
_CB = ERROR_LAYOUT_17.index("clock bias")
_CD = ERROR_LAYOUT_17.index("clock drift")


@implements("KZL 11")
def skew_paper(a: ArrayLike) -> Array:
    r"""The matrix KZL Eq. 11 prints as :math:`[a\times]`: ``-skew(a)``, so ``skew_paper(a) @ b``
    is :math:`b \times a`.

    Parameters
    ----------
    a : (3,) array
        Vector (any unit).

    Returns
    -------
    (3, 3) ndarray
        :math:`-[a\times]`.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (11).

    Examples
    --------
    >>> skew_paper([0.0, 0.0, 1.0]) @ [1.0, 0.0, 0.0]
    array([ 0., -1.,  0.])
    """
    return -skew(a)


@implements("KZL 10")
def error_dynamics_17(C_bn: ArrayLike, f_n: ArrayLike) -> Array:
    """Continuous-time dynamics matrix F (17 x 17) of KZL Eq. 10 (reconstructed).

    Parameters
    ----------
    C_bn : (3, 3) or (N, 3, 3) array
        Computed body-to-NED rotation :math:`\\hat R_b^n`.
    f_n : (3,) or (N, 3) array
        Computed specific force in NED, :math:`\\hat a^n_{ib} = \\hat R_b^n \\hat a^b_{ib}` (m/s²).

    Returns
    -------
    F : (17, 17) or (N, 17, 17) ndarray
        Continuous error dynamics, 1/s (in the units of the 17 states).

    Examples
    --------
    >>> F = error_dynamics_17(np.eye(3), [0.0, 0.0, -9.8])
    >>> F.shape, float(F[3, 7]), float(F[4, 6])
    ((17, 17), -9.8, 9.8)
    """
    C = np.asarray(C_bn, dtype=float)
    f = np.asarray(f_n, dtype=float)
    batch = C.shape[:-2]
    F = np.zeros((*batch, 17, 17))
    F[..., _P, _V] = np.eye(3)
    fx, fy, fz = f[..., 0], f[..., 1], f[..., 2]
    z = np.zeros_like(fx)
    # F23 = -[a x]: the explicit matrix of KZL Eq. 11
    F[..., _V, _A] = np.stack(
        [np.stack([z, fz, -fy], -1), np.stack([-fz, z, fx], -1), np.stack([fy, -fx, z], -1)], -2
    )
    F[..., _V, _BA] = -C
    F[..., _A, _BG] = -C
    F[..., _CB, _CD] = 1.0
    return F


def noise_psd_17(
    accel_noise: float,
    gyro_noise: float,
    accel_bias_walk: float = 0.0,
    gyro_bias_walk: float = 0.0,
    clock_drift_walk: float = 0.0,
    clock_bias_walk: float = 0.0,
) -> Array:
    r"""State-space noise PSD :math:`G Q G^T` (17 x 17) for isotropic sensor noises.

    The noise enters as ``-R w``; for isotropic noise :math:`R\, q I\, R^T = q I`, so the result does
    not depend on the attitude.

    Parameters
    ----------
    accel_noise : float
        Root PSD of the white accelerometer noise, m/s/√s (``>= 0``).
    gyro_noise : float
        Root PSD of the white gyro noise, rad/√s (``>= 0``).
    accel_bias_walk : float, default 0.0
        Root PSD of the accelerometer-bias random walk, m/s²/√s.
    gyro_bias_walk : float, default 0.0
        Root PSD of the gyro-bias random walk, rad/s/√s.
    clock_drift_walk : float, default 0.0
        Root PSD of the clock-drift random walk, m/s/√s.
    clock_bias_walk : float, default 0.0
        Root PSD of the clock-phase random walk, m/√s.

    Returns
    -------
    (17, 17) ndarray
        Diagonal PSD (state unit squared per second).

    Raises
    ------
    ValueError
        If any root PSD is negative.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Sec. 3.3 (the 17-state error model).

    Examples
    --------
    >>> import numpy as np
    >>> np.diag(noise_psd_17(0.01, 0.001))[3:9].tolist()
    [0.0001, 0.0001, 0.0001, 1e-06, 1e-06, 1e-06]
    """
    for name, value in locals().items():
        require_nonnegative(name, value)
    q = np.zeros(17)
    q[_V] = accel_noise**2
    q[_A] = gyro_noise**2
    q[_BA] = accel_bias_walk**2
    q[_BG] = gyro_bias_walk**2
    q[_CB] = clock_bias_walk**2
    q[_CD] = clock_drift_walk**2
    return np.diag(q)


@implements("KZL 5")
def transition_exact(F: ArrayLike, dt: float) -> Array:
    r""":math:`e^{F\,dt}` of the nilpotent 17-state F: :math:`I + F\,dt + (F\,dt)^2/2 + (F\,dt)^3/6`.

    Exact because :math:`F^4 = 0` (KZL Eq. 5: the series terminates). Broadcasts over a leading
    axis.

    Parameters
    ----------
    F : (..., n, n) array
        Error dynamics with :math:`F^4 = 0`, 1/s.
    dt : float
        Interval, s (``> 0``).

    Returns
    -------
    (..., n, n) ndarray
        State-transition matrix.

    Raises
    ------
    ValueError
        If ``dt`` is not positive.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (5).

    Examples
    --------
    >>> transition_exact([[0.0, 1.0], [0.0, 0.0]], 2.0).tolist()
    [[1.0, 2.0], [0.0, 1.0]]
    """
    require_positive("dt", dt)
    A = np.asarray(F, dtype=float) * dt
    A2 = A @ A
    return np.eye(A.shape[-1]) + A + A2 / 2.0 + (A2 @ A) / 6.0


@implements("KZL 6")
def transition_first_order(F: ArrayLike, dt: float) -> Array:
    """KZL Eq. 6: ``I + F dt``.

    Parameters
    ----------
    F : (..., n, n) array
        Error dynamics, 1/s.
    dt : float
        Interval, s (``> 0``).

    Returns
    -------
    (..., n, n) ndarray
        First-order state-transition matrix.

    Raises
    ------
    ValueError
        If ``dt`` is not positive.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (6).

    Examples
    --------
    >>> transition_first_order([[0.0, 1.0], [-1.0, 0.0]], 0.5).tolist()
    [[1.0, 0.5], [-0.5, 1.0]]
    """
    require_positive("dt", dt)
    return np.eye(np.shape(F)[-1]) + np.asarray(F, dtype=float) * dt


@implements("KZL 13")
def code_doppler_rows(los_ned: ArrayLike) -> Array:
    r"""Jacobian rows of pseudorange and delta range (KZL Eq. 13, first two rows per satellite).

    Parameters
    ----------
    los_ned : (nu, 3) array
        Unit line-of-sight vectors receiver -> satellite in NED (dimensionless).

    Returns
    -------
    H : (2 nu, 17) ndarray
        Rows :math:`[-l^T\ 0\ 0\ 0\ 0\ 1\ 0]` and :math:`[0\ {-l^T}\ 0\ 0\ 0\ 0\ 1]` for each satellite, in
        the
        order (:math:`\rho_1, \dot\rho_1, \rho_2, \dots`), for ``y = predicted - measured`` (m per m and
        m/s per m/s).

    Raises
    ------
    ValueError
        If ``los_ned`` is not a finite 2-D array.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (13).

    Examples
    --------
    >>> H = code_doppler_rows([[0.0, 0.0, -1.0]])
    >>> H.shape, H[0, :3].tolist(), float(H[0, 15])
    ((2, 17), [-0.0, -0.0, 1.0], 1.0)
    """
    L = as_finite_array("los_ned", los_ned, ndim=2)
    nu = L.shape[0]
    H = np.zeros((2 * nu, 17))
    H[0::2, _P] = -L
    H[0::2, _CB] = 1.0
    H[1::2, _V] = -L
    H[1::2, _CD] = 1.0
    return H


def observability_rank(F: ArrayLike, H: ArrayLike, rtol: float = 1e-9) -> int:
    """Rank of the LTI observability matrix ``[H; HF; ...; HF^{n-1}]``.

    Rows are normalised before the SVD so that blocks of different units count alike; the
    rank counts singular values above ``rtol`` times the largest.

    Parameters
    ----------
    F : (n, n) array
        System matrix, 1/s.
    H : (m, n) array
        Measurement matrix.
    rtol : float, default 1e-9
        Relative threshold on the singular values.

    Returns
    -------
    int
        Numerical rank, between 0 and ``n``.

    Examples
    --------
    >>> observability_rank([[0.0, 1.0], [0.0, 0.0]], [[1.0, 0.0]])
    2
    """
    F = require_square("F", F)
    H = np.atleast_2d(as_finite_array("H", H))
    n = F.shape[0]
    if n == 0:
        raise ValueError("observability_rank: F must have at least one state, got shape (0, 0)")
    if H.ndim != 2 or H.shape[1] != n:
        raise ValueError(
            f"observability_rank: H must have {n} columns (one per state of F), got shape {H.shape}"
        )
    blocks, M = [], H
    for _ in range(n):
        blocks.append(M)
        M = M @ F
    O_ = np.vstack(blocks)
    norms = np.linalg.norm(O_, axis=1)
    O_ = O_[norms > 0] / norms[norms > 0, None]
    if O_.size == 0:
        return 0
    s = np.linalg.svd(O_, compute_uv=False)
    return int(np.sum(s > rtol * s[0]))


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "dt": POSITIVE,
        "accel_noise": NONNEGATIVE,
        "gyro_noise": NONNEGATIVE,
        "accel_bias_walk": NONNEGATIVE,
        "gyro_bias_walk": NONNEGATIVE,
        "clock_bias_walk": NONNEGATIVE,
        "clock_drift_walk": NONNEGATIVE,
        "rtol": POSITIVE,
        "C_bn": ROTATION_STACK,
    },
)
