r"""Local velocity estimators and their federated fusion, with a correlation-free bound.

Local estimators (Wu & Fowler, WF Sec. IV.B)
--------------------------------------------
* Navigation-data mapping (WF Eqs. (10)-(11)): a map :math:`T` from navigation states to
  the local state, with Jacobian :math:`\boldsymbol\tau` and mapping uncertainty
  :math:`\mathbf Q_T`: :math:`\mathbf P_{DN} = \boldsymbol\tau\mathbf P_N\boldsymbol\tau^T + \mathbf Q_T`.
  :func:`lever_arm_velocity` is the rigid-body example
  :math:`T = \mathbf v + \boldsymbol\omega\times\mathbf r`.
* Accelerometer-driven Kalman filter (WF Eqs. (12)-(14)): a random walk driven by the
  measured acceleration, :math:`\mathbf x(k+1)=\mathbf x(k)+\mathbf y_a(k)T_s+\mathbf w_a(k)T_s`,
  updated with a local velocity measurement :math:`\mathbf y_L = \mathbf x + \mathbf v_L`.
  The innovation is :math:`\mathbf y_L - \hat{\mathbf x}` (WF prints :math:`\mathbf y_a`).
* GPS-Doppler update (WF Eqs. (15)-(17)): one Kalman update of the accelerometer prior.

Fusion (WF Sec. IV.C)
---------------------
* :func:`federated_fusion`: :math:`\mathbf P_D^{-1}=\sum_i\mathbf P_i^{-1}`,
  :math:`\hat{\mathbf x}_D=\mathbf P_D\sum_i\mathbf P_i^{-1}\hat{\mathbf x}_i` (WF Eqs. (18)-(19)),
  with an outage expressed as infinite covariance (zero information).
* :func:`fused_error_covariance`: the true covariance given the joint covariance of the
  local errors (WF Eq. (20)).
* :func:`federated_covariance_bound` and :func:`minkowski_trace_bound`: the bound of the
  theorem (WF Eqs. (21)-(23)), which needs only the local covariances. Any weights
  :math:`k_i > 0` with :math:`\sum_i 1/k_i = 1` give a valid matrix bound; WF Eq. (22) and the
  remark's choice are such weights.
* :func:`correlated_joint_covariance`: a random joint covariance of correlated local
  errors (a common and an independent part), on which the theorem can be exercised;
  :func:`random_covariance` draws one covariance.

Checking the theorem (WF Eqs. (20)-(23))
----------------------------------------
* :func:`fusion_gains`: the linear maps :math:`\hat{\mathbf x}_i \mapsto \hat{\mathbf x}_D`
  of WF Eqs. (18)-(19), read off :func:`federated_fusion`.
* :func:`federated_bound_margins`: the margins of the bound (21) and of both inequalities of
  (23) over random correlated joint covariances, exactly (Eq. (20)).
* :func:`federated_bound_monte_carlo` and :func:`federated_bound_monte_carlo_sweep`: seeded
  Monte Carlo of the fused error against the bound, the Minkowski term and Eq. (20), in
  sampling standard deviations.
* :func:`completely_correlated_trace_ratio`: Monte Carlo of the Minkowski term over the trace
  of the fused error for completely correlated local errors (WF Remark (ii)).
* :func:`navigation_mapped_error_samples`: draws of the navigation-mapped error of WF Eq. (10),
  whose covariance is Eq. (11).

Everything is general: any state dimension, any number of local estimators.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import solve_discrete_are

from navcore._validate import (
    COVARIANCE,
    NONNEGATIVE,
    POSITIVE,
    as_finite_array,
    check_public,
    require_in_range,
    require_integer,
    require_nonnegative,
    require_positive,
    require_symmetric_psd,
)
from navcore.estimation.kalman import KalmanUpdate, kf_predict, kf_update, symmetrize
from navcore.estimation.riccati import ScalarSteadyState, scalar_riccati_steady_state
from navcore.frames import skew
from navcore.trace import implements

__all__ = [
    "accelerometer_predict",
    "accelerometer_steady_state",
    "accelerometer_steady_state_isotropic",
    "completely_correlated_trace_ratio",
    "correlated_joint_covariance",
    "feasible_weights",
    "federated_bound_margins",
    "federated_bound_monte_carlo",
    "federated_bound_monte_carlo_sweep",
    "federated_covariance_bound",
    "federated_fusion",
    "federated_improvement_db",
    "fused_error_covariance",
    "fusion_gains",
    "gps_doppler_covariance",
    "gps_doppler_update",
    "lever_arm_velocity",
    "local_velocity_update",
    "minkowski_trace_bound",
    "navigation_mapped_covariance",
    "navigation_mapped_error_samples",
    "optimal_weights",
    "random_covariance",
]

Array = NDArray[np.float64]


# --------------------------------------------------------------------------- Eqs. (10)-(11)
@implements("WF 10")
def lever_arm_velocity(
    velocity: ArrayLike, angular_rate: ArrayLike, lever_arm: ArrayLike
) -> tuple[Array, Array]:
    r"""Rigid-body map from navigation states to aperture velocity and its Jacobian (WF Eq. (10)).

    :math:`T(\mathbf x_N) = \mathbf v + \boldsymbol\omega \times \mathbf r` with ``x_N = [v, omega]``, all in
    one frame.

    Parameters
    ----------
    velocity : (3,) array
        Velocity of the navigation reference point, m/s.
    angular_rate : (3,) array
        Angular rate of the body, rad/s.
    lever_arm : (3,) array
        Lever arm from the reference point to the aperture, m.

    Returns
    -------
    v_aperture : (3,) ndarray
        Mapped velocity, m/s.
    tau : (3, 6) ndarray
        :math:`\partial T/\partial\mathbf x_N = [\mathbf I,\; -[\mathbf r\times]]` (dimensionless
        in its first three columns, m in its last three).

    Raises
    ------
    ValueError
        If an input is not a finite 3-vector.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (10).

    Examples
    --------
    >>> v, tau = lever_arm_velocity([100.0, 0.0, 0.0], [0.0, 0.0, 0.1], [2.0, 0.0, 0.0])
    >>> v, tau.shape
    (array([100. ,   0.2,   0. ]), (3, 6))
    """
    v = as_finite_array("velocity", velocity, ndim=1)
    w = as_finite_array("angular_rate", angular_rate, ndim=1)
    r = as_finite_array("lever_arm", lever_arm, ndim=1)
    return v + np.cross(w, r), np.hstack([np.eye(3), -skew(r)])


@implements("WF 11")
def navigation_mapped_covariance(tau: ArrayLike, P_N: ArrayLike, Q_T: ArrayLike) -> Array:
    r"""Local-state covariance from navigation data (WF Eq. (11)).

    :math:`\mathbf P_{DN}=\boldsymbol\tau\mathbf P_N\boldsymbol\tau^T+\mathbf Q_T`.

    Assumes the mapping uncertainty :math:`\mathbf w_T` is independent of the navigation error.

    Parameters
    ----------
    tau : (m, k) array
        Jacobian of the map from navigation states to the local state (e.g. the second output
        of :func:`lever_arm_velocity`).
    P_N : (k, k) array
        Covariance of the navigation states (their units squared).
    Q_T : (m, m) array
        Covariance of the mapping uncertainty, (m/s)².

    Returns
    -------
    (m, m) ndarray
        Covariance of the mapped local state, (m/s)².

    Raises
    ------
    ValueError
        If the shapes disagree, an array is not finite, or ``P_N`` or ``Q_T`` is not symmetric
        positive semi-definite.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (11).

    Examples
    --------
    >>> P = navigation_mapped_covariance([[1.0, 2.0]], [[1.0, 0.0], [0.0, 0.25]], [[0.5]])
    >>> round(float(P[0, 0]), 4)
    2.5
    """
    tau = as_finite_array("tau", tau, ndim=2)
    P_N = require_symmetric_psd("P_N", P_N)
    Q_T = require_symmetric_psd("Q_T", Q_T)
    if P_N.shape[0] != tau.shape[1] or Q_T.shape[0] != tau.shape[0]:
        raise ValueError(f"shapes must agree: tau {tau.shape}, P_N {P_N.shape}, Q_T {Q_T.shape}")
    return symmetrize(tau @ P_N @ tau.T + Q_T)


# --------------------------------------------------------------------------- Eqs. (12)-(14)
@implements("WF 12", "WF 13", "WF 14")
def accelerometer_predict(
    x: ArrayLike, P: ArrayLike, accel: ArrayLike, Q_a: ArrayLike, Ts: float
) -> tuple[Array, Array]:
    r"""Time update of the accelerometer-integration filter (WF Eqs. (13)-(14), first lines).

    It propagates the process model of WF Eq. (12), :math:`\mathbf x(k+1) = \mathbf x(k) + \mathbf y_a(k) T_s
    + \mathbf w_a(k) T_s`
    with :math:`\operatorname{Cov} \mathbf w_a = \mathbf Q_a`: :math:`\mathbf x^- = \mathbf x + \mathbf y_a
    T_s` and :math:`\mathbf P^- = \mathbf P + \mathbf Q_a T_s^2`.

    Parameters
    ----------
    x : (n,) array
        Velocity estimate, m/s.
    P : (n, n) array
        Its covariance, (m/s)² (symmetric positive semi-definite).
    accel : (n,) array
        Measured acceleration ``y_a``, m/s².
    Q_a : (n, n) array
        Covariance of the accelerometer noise ``w_a``, (m/s²)².
    Ts : float
        Sample interval, s (``> 0``).

    Returns
    -------
    x_pred : (n,) ndarray
        Predicted velocity, m/s.
    P_pred : (n, n) ndarray
        Predicted covariance, (m/s)².

    Raises
    ------
    ValueError
        If ``Ts`` is not positive, an array is not finite or has the wrong shape, or ``P`` or
        ``Q_a`` is not symmetric positive semi-definite.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (12)-(14).

    Examples
    --------
    >>> import numpy as np
    >>> x, P = accelerometer_predict([1.0], [[0.04]], [0.5], [[0.01]], 0.1)
    >>> round(float(x[0]), 4), round(float(P[0, 0]), 4)
    (1.05, 0.0401)
    """
    require_positive("Ts", Ts)
    x = as_finite_array("x", x, ndim=1)
    a = as_finite_array("accel", accel, ndim=1)
    Q_a = require_symmetric_psd("Q_a", Q_a)
    x_pred, P_pred = kf_predict(x, P, np.eye(x.size), Q_a * Ts**2)
    return x_pred + a * Ts, P_pred


@implements("WF 12", "WF 13", "WF 14")
def local_velocity_update(x: ArrayLike, P: ArrayLike, y_L: ArrayLike, R_L: ArrayLike) -> KalmanUpdate:
    r"""Measurement update with a direct local velocity measurement (WF Eq. (13), corrected).

    The measurement model is the second line of WF Eq. (12), ``y_L = x + v_L`` with
    :math:`\operatorname{Cov} \mathbf v_L = \mathbf R_L`. The innovation is :math:`\mathbf y_L - \mathbf x^-`
    (a velocity); WF Eq. (13) prints
    :math:`\mathbf y_a - \mathbf x^-`. The posterior information is :math:`(\mathbf P^-)^{-1} + \mathbf
    R_L^{-1}` (WF Eq. (14), second line).

    Parameters
    ----------
    x : (n,) array
        Prior velocity, m/s.
    P : (n, n) array
        Its covariance, (m/s)².
    y_L : (n,) array
        Local velocity measurement, m/s.
    R_L : (n, n) array
        Its noise covariance, (m/s)² (positive definite).

    Returns
    -------
    KalmanUpdate
        Posterior velocity and covariance, gain, innovation (m/s) and its covariance.

    Raises
    ------
    ValueError
        As :func:`navcore.estimation.kalman.kf_update`.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (12)-(14).

    Examples
    --------
    >>> up = local_velocity_update([0.0], [[1.0]], [1.0], [[1.0]])
    >>> round(float(up.x[0]), 4), round(float(up.P[0, 0]), 4)
    (0.5, 0.5)
    """
    x = as_finite_array("x", x, ndim=1)
    return kf_update(x, P, y_L, np.eye(x.size), R_L)


@implements("WF 14")
def accelerometer_steady_state_isotropic(sigma_a: float, Ts: float, sigma_L: float) -> ScalarSteadyState:
    r"""Per-axis steady state of WF Eq. (14) for :math:`\mathbf Q_a = \sigma_a^2 I`, :math:`\mathbf R_L =
    \sigma_L^2 I`.

    Parameters
    ----------
    sigma_a : float
        Accelerometer noise standard deviation, m/s².
    Ts : float
        Update interval, s.
    sigma_L : float
        Local velocity measurement standard deviation, m/s.

    Returns
    -------
    ScalarSteadyState
        ``prior`` = P(k/k-1), ``posterior`` = P(k/k) in (m/s)², and the gain. For
        :math:`\sigma_a T_s \ll \sigma_L` the posterior is close to :math:`\sigma_a T_s \sigma_L`.

    Raises
    ------
    ValueError
        If ``sigma_a``, ``Ts`` or ``sigma_L`` is not positive.

    Examples
    --------
    >>> ss = accelerometer_steady_state_isotropic(1e-3, 0.02, 0.2)
    >>> round(ss.posterior ** 0.5, 6)
    0.002
    """
    require_positive("sigma_a", sigma_a)
    require_positive("Ts", Ts)
    require_positive("sigma_L", sigma_L)
    return scalar_riccati_steady_state(1.0, (sigma_a * Ts) ** 2, 1.0, sigma_L**2)


@implements("WF 14")
def accelerometer_steady_state(Q_a: ArrayLike, R_L: ArrayLike, Ts: float) -> tuple[Array, Array]:
    r"""Matrix steady state of WF Eq. (14): prior and posterior covariances.

    Solves the filter Riccati equation for :math:`\Phi = I,\ Q = \mathbf Q_a T_s^2,\ H = I,\ R = \mathbf R_L`
    with
    ``scipy.linalg.solve_discrete_are``.

    Parameters
    ----------
    Q_a : (n, n) array
        Covariance of the accelerometer noise, (m/s²)².
    R_L : (n, n) array
        Covariance of the local velocity measurement, (m/s)² (positive definite).
    Ts : float
        Sample interval, s (``> 0``).

    Returns
    -------
    prior : (n, n) ndarray
        Steady-state prior covariance, (m/s)².
    posterior : (n, n) ndarray
        Steady-state posterior covariance, (m/s)².

    Raises
    ------
    ValueError
        If ``Ts`` is not positive, ``Q_a`` is not symmetric positive semi-definite or ``R_L``
        not positive definite.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (14).

    Examples
    --------
    >>> import numpy as np
    >>> prior, post = accelerometer_steady_state(np.eye(2), np.eye(2), 1.0)
    >>> round(float(prior[0, 0]), 4), round(float(post[0, 0]), 4)
    (1.618, 0.618)
    """
    require_positive("Ts", Ts)
    Q = require_symmetric_psd("Q_a", Q_a) * Ts**2
    R = require_symmetric_psd("R_L", R_L, definite=True)
    n = Q.shape[0]
    prior = symmetrize(solve_discrete_are(np.eye(n), np.eye(n), Q, R))
    posterior = symmetrize(np.linalg.inv(np.linalg.inv(prior) + np.linalg.inv(R)))
    return prior, posterior


# --------------------------------------------------------------------------- Eqs. (15)-(17)
@implements("WF 16", "WF 15")
def gps_doppler_update(
    x_prior: ArrayLike, P_prior: ArrayLike, y_G: ArrayLike, H_G: ArrayLike, R_G: ArrayLike
) -> KalmanUpdate:
    r"""Single-step GPS-Doppler update of the accelerometer prior (WF Eq. (16)).

    :math:`\mathbf y_G = \mathbf H_G \mathbf x + \mathbf v_G` (WF Eq. (15)).

    Parameters
    ----------
    x_prior : (n,) array
        Prior velocity, m/s.
    P_prior : (n, n) array
        Its covariance, (m/s)².
    y_G : (m,) array
        Doppler measurement, Hz.
    H_G : (m, n) array
        Doppler measurement matrix, Hz per (m/s).
    R_G : (m, m) array
        Doppler noise covariance, Hz² (positive definite).

    Returns
    -------
    KalmanUpdate
        Posterior velocity and covariance, gain, innovation (Hz) and its covariance.

    Raises
    ------
    ValueError
        As :func:`navcore.estimation.kalman.kf_update`.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (15)-(16).

    Examples
    --------
    >>> up = gps_doppler_update([0.0], [[1.0]], [2.0], [[2.0]], [[4.0]])
    >>> round(float(up.x[0]), 4), round(float(up.P[0, 0]), 4)
    (0.5, 0.5)
    """
    return kf_update(x_prior, P_prior, y_G, H_G, R_G)


@implements("WF 17")
def gps_doppler_covariance(P_prior: ArrayLike, H_G: ArrayLike, R_G: ArrayLike) -> Array:
    r"""Information-form covariance after the GPS-Doppler update (WF Eq. (17)).

    :math:`\mathbf P_{DG}=[\mathbf P^{-1} + \mathbf H_G^T\mathbf R_G^{-1}\mathbf H_G]^{-1}`.

    Parameters
    ----------
    P_prior : (n, n) array
        Prior velocity covariance, (m/s)² (positive definite).
    H_G : (m, n) array
        Doppler measurement matrix, Hz per (m/s).
    R_G : (m, m) array
        Doppler noise covariance, Hz² (positive definite).

    Returns
    -------
    (n, n) ndarray
        Posterior covariance, (m/s)².

    Raises
    ------
    ValueError
        If ``P_prior`` or ``R_G`` is not symmetric positive definite or ``H_G`` is not a
        finite matrix.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (17).

    Examples
    --------
    >>> round(float(gps_doppler_covariance([[1.0]], [[2.0]], [[4.0]])[0, 0]), 4)
    0.5
    """
    P = require_symmetric_psd("P_prior", P_prior, definite=True)
    H = as_finite_array("H_G", H_G, ndim=2)
    R = require_symmetric_psd("R_G", R_G, definite=True)
    info = np.linalg.inv(P) + H.T @ np.linalg.solve(R, H)
    return symmetrize(np.linalg.inv(symmetrize(info)))


# --------------------------------------------------------------------------- Eqs. (18)-(20)
def _informations(covariances: Sequence[ArrayLike | float | None], n: int | None = None) -> list[Array]:
    """Information matrices; ``None`` or ``inf`` (an outage) gives zero information."""
    out = []
    for i, P in enumerate(covariances):
        if P is None or (np.ndim(P) == 0 and np.isinf(float(P))):  # type: ignore[arg-type]
            if n is None:
                raise ValueError("covariances: an outage needs the state size from another estimator")
            out.append(np.zeros((n, n)))
            continue
        try:
            Pa = np.asarray(P, dtype=float)
        except (TypeError, ValueError):
            raise TypeError(f"covariances[{i}] must be a matrix, None or inf, got {P!r}") from None
        if n is not None and Pa.shape != (n, n):
            raise ValueError(f"covariances[{i}] must have shape ({n}, {n}) like the others, got {Pa.shape}")
        if Pa.ndim == 2 and np.all(np.isinf(np.diag(Pa))):
            out.append(np.zeros_like(Pa))
            continue
        Pa = require_symmetric_psd(f"covariances[{i}]", Pa, definite=True)
        out.append(symmetrize(np.linalg.inv(Pa)))
    return out


def _state_size(covariances: Sequence[ArrayLike | float | None]) -> int:
    if isinstance(covariances, str) or not isinstance(covariances, Sequence | np.ndarray):
        raise TypeError(f"covariances must be a sequence of matrices, got {covariances!r}")
    for P in covariances:
        if P is not None and np.ndim(P) == 2:
            return int(np.shape(P)[0])
    raise ValueError("covariances must contain at least one matrix")


@implements("WF 18", "WF 19")
def federated_fusion(
    estimates: Sequence[ArrayLike], covariances: Sequence[ArrayLike | float | None]
) -> tuple[Array, Array]:
    r"""Information-weighted (federated) fusion of local estimates (WF Eqs. (18)-(19)).

    Parameters
    ----------
    estimates : sequence of (n,) arrays
        Local estimates :math:`\hat{\mathbf x}_i`.
    covariances : sequence of (n, n) arrays, ``None`` or ``inf``
        Their covariances. An outage is ``None``, ``inf`` or a matrix with infinite diagonal:
        that estimator gets zero weight.

    Returns
    -------
    x_D : (n,) array
        :math:`\mathbf P_D\sum_i\mathbf P_i^{-1}\hat{\mathbf x}_i`.
    P_D : (n, n) array
        :math:`(\sum_i\mathbf P_i^{-1})^{-1}`, the true covariance only if the local errors are
        uncorrelated.

    Raises
    ------
    ValueError
        If ``estimates`` and ``covariances`` are empty or differ in length, an estimate is
        not finite, or the estimators left after outages do not observe every state.

    Examples
    --------
    >>> import numpy as np
    >>> x, P = federated_fusion([np.array([1.0]), np.array([3.0])], [np.eye(1), np.eye(1)])
    >>> float(x[0]), float(P[0, 0])
    (2.0, 0.5)
    """
    if len(estimates) != len(covariances) or not estimates:
        raise ValueError("estimates and covariances must be non-empty and of equal length")
    n = _state_size(covariances)
    infos = _informations(covariances, n)
    total = symmetrize(sum(infos))
    if np.linalg.matrix_rank(total) < n:
        raise ValueError("covariances: the estimators left after outages do not observe every state")
    P_D = symmetrize(np.linalg.inv(total))
    y = sum(
        Y @ as_finite_array(f"estimates[{i}]", x, ndim=1) if np.any(Y) else 0.0
        for i, (Y, x) in enumerate(zip(infos, estimates, strict=True))
    )
    return P_D @ y, P_D


@implements("WF 20")
def fused_error_covariance(covariances: Sequence[ArrayLike | float | None], joint: ArrayLike) -> Array:
    r"""True covariance of the fused error given the joint local-error covariance (WF Eq. (20)).

    :math:`\operatorname{Cov} = \mathbf P_D [\mathbf P_1^{-1} \cdots \mathbf P_N^{-1}]\, \mathbf P\, [\mathbf
    P_1^{-1} \cdots \mathbf P_N^{-1}]^T \mathbf P_D`, where ``P`` is the
    ``(N n) x (N n)`` joint covariance of the stacked local errors, whose ``(i, j)`` block is the
    cross-covariance of estimators ``i`` and ``j`` (WF prints the (2, 3) block as ``P_NG``; it is
    ``P_LG``). Blocks belonging to outages are ignored (zero weight).

    Parameters
    ----------
    covariances : sequence of (n, n) array, float or None
        Covariance of each local estimator, (m/s)²; ``None``, a scalar or an infinite
        diagonal marks an outage.
    joint : (N n, N n) array
        Joint covariance of the stacked local errors, (m/s)² (symmetric positive
        semi-definite once outage blocks are zeroed).

    Returns
    -------
    (n, n) ndarray
        Covariance of the fused error, (m/s)².

    Raises
    ------
    ValueError
        If ``joint`` has the wrong shape or is not symmetric positive semi-definite.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (20).

    Examples
    --------
    >>> import numpy as np
    >>> C = fused_error_covariance([[[1.0]], [[1.0]]], [[1.0, 1.0], [1.0, 1.0]])
    >>> round(float(C[0, 0]), 4)
    1.0
    """
    n = _state_size(covariances)
    infos = _informations(covariances, n)
    P_D = symmetrize(np.linalg.inv(symmetrize(sum(infos))))
    joint = np.asarray(joint, dtype=float)
    N = len(infos)
    if joint.shape != (N * n, N * n):
        raise ValueError(f"joint must be ({N * n}, {N * n}), got {joint.shape}")
    J = np.where(np.isfinite(joint), joint, 0.0)  # outage blocks get zero weight anyway
    require_symmetric_psd("joint", J)
    A = P_D @ np.hstack(infos)  # [P_D P_1^-1, ..., P_D P_N^-1]
    return symmetrize(A @ J @ A.T)


# --------------------------------------------------------------------------- Eqs. (21)-(23)
@implements("WF 22")
def feasible_weights(
    covariances: Sequence[ArrayLike | float | None],
    directions: Sequence[ArrayLike] | None = None,
    sigmas: ArrayLike | None = None,
) -> Array:
    r"""Weights :math:`k_i` of the theorem (WF Eq. (22) or Remark (i)).

    With ``directions`` :math:`\mathbf z_i`: :math:`s_i=\sqrt{\mathbf z_i^T\mathbf P_i\mathbf z_i}`
    (WF Eq. (22)); with ``sigmas``: :math:`s_i=\sqrt{\sigma_i}` (Remark (i)); by default
    :math:`s_i=\sqrt{\sigma_{\max}(\mathbf P_i)}`. Then :math:`k_i=\sum_j s_j/s_i`, which always
    satisfies :math:`\sum_i 1/k_i = 1`. Outages get ``k_i = inf`` (their term vanishes).

    Parameters
    ----------
    covariances : sequence of (n, n) array, float or None
        Covariance of each local estimator, (m/s)²; ``None``, a scalar or an infinite
        diagonal marks an outage.
    directions : sequence of (n,) array, optional
        Non-zero direction :math:`\mathbf z_i` per estimator (WF Eq. (22)).
    sigmas : (N,) array, optional
        Positive variances :math:`\sigma_i`, (m/s)², per estimator (Remark (i)).

    Returns
    -------
    (N,) ndarray
        Weights :math:`k_i` (dimensionless), ``inf`` for outages.

    Raises
    ------
    ValueError
        If a direction is zero, not finite or of the wrong length, or a variance in ``sigmas``
        is not positive.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (22) and
    Remark (i).

    Examples
    --------
    >>> import numpy as np
    >>> feasible_weights([np.eye(2), 4.0 * np.eye(2)])
    array([3. , 1.5])
    """
    n = _state_size(covariances)
    _informations(covariances, n)  # checks each covariance (shape, symmetric positive definite)
    active = [
        P is not None and not (np.ndim(P) == 0) and not np.all(np.isinf(np.diag(np.asarray(P))))
        for P in covariances
    ]
    s = np.full(len(covariances), np.inf)
    for i, P in enumerate(covariances):
        if not active[i]:
            continue
        Pa = np.asarray(P, dtype=float)
        if directions is not None:
            z = as_finite_array(f"directions[{i}]", directions[i], ndim=1)
            if z.shape != (n,) or not np.any(z):
                raise ValueError(f"directions[{i}] must be a non-zero {n}-vector")
            s[i] = np.sqrt(z @ Pa @ z)
        elif sigmas is not None:
            s[i] = np.sqrt(float(require_positive(f"sigmas[{i}]", np.asarray(sigmas, dtype=float)[i])))
        else:
            s[i] = np.sqrt(np.linalg.eigvalsh(Pa)[-1])
    total = s[np.isfinite(s)].sum()
    with np.errstate(divide="ignore"):
        return np.where(np.isfinite(s), total / np.where(np.isfinite(s), s, 1.0), np.inf)


@implements("WF 21", "WF 23", "WF 22")
def optimal_weights(covariances: Sequence[ArrayLike | float | None]) -> Array:
    r"""Weights that minimise the trace of WF Eq. (21): :math:`k_i=\sum_j t_j/t_i`.

    Here :math:`t_i=\sqrt{\operatorname{tr}(\mathbf P_D\mathbf P_i^{-1}\mathbf P_D)}`; with them the
    trace of the bound equals :func:`minkowski_trace_bound` (the middle term of WF Eq. (23)).
    They are an instance of WF Eq. (22) with suitably scaled :math:`\mathbf z_i`, but in general
    not of Remark (i)'s choice with :math:`\sigma_j` inside the spectrum of :math:`\mathbf P_j`.

    Parameters
    ----------
    covariances : sequence of (n, n) array, float or None
        Covariance of each local estimator, (m/s)²; ``None``, a scalar or an infinite
        diagonal marks an outage.

    Returns
    -------
    (N,) ndarray
        Weights :math:`k_i` (dimensionless), ``inf`` for outages.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (21)-(23).

    Examples
    --------
    >>> import numpy as np
    >>> optimal_weights([np.eye(2), 4.0 * np.eye(2)])
    array([1.5, 3. ])
    """
    n = _state_size(covariances)
    infos = _informations(covariances, n)
    P_D = symmetrize(np.linalg.inv(symmetrize(sum(infos))))
    t = np.array([np.sqrt(np.trace(P_D @ Y @ P_D)) for Y in infos])
    with np.errstate(divide="ignore"):
        return np.where(t > 0, t.sum() / np.where(t > 0, t, 1.0), np.inf)


@implements("WF 21")
def federated_covariance_bound(
    covariances: Sequence[ArrayLike | float | None], weights: ArrayLike | None = None
) -> Array:
    r"""Correlation-free bound :math:`\mathbf P_D[\sum_i k_i\mathbf P_i^{-1}]\mathbf P_D` (WF Eq. (21)).

    Holds for any joint covariance of the local errors whenever :math:`k_i > 0` and
    :math:`\sum_i 1/k_i \le 1` (default weights: :func:`feasible_weights`).

    Parameters
    ----------
    covariances : sequence of (n, n) array, float or None
        Covariance of each local estimator, (m/s)²; ``None``, a scalar or an infinite
        diagonal marks an outage.
    weights : (N,) array, optional
        Weights :math:`k_i` (dimensionless); default :func:`feasible_weights`.

    Returns
    -------
    (n, n) ndarray
        Bound on the covariance of the fused error, (m/s)².

    Raises
    ------
    ValueError
        If ``weights`` has the wrong length, a non-positive entry, or
        :math:`\sum_i 1/k_i > 1`.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (21).

    Examples
    --------
    >>> import numpy as np
    >>> B = federated_covariance_bound([np.eye(2), np.eye(2)])
    >>> np.round(np.diag(B), 4)
    array([1., 1.])
    """
    n = _state_size(covariances)
    infos = _informations(covariances, n)
    P_D = symmetrize(np.linalg.inv(symmetrize(sum(infos))))
    k = feasible_weights(covariances) if weights is None else np.asarray(weights, dtype=float)
    if k.shape != (len(infos),):
        raise ValueError(f"weights must have one entry per estimator ({len(infos)}), got {k.shape}")
    fin = np.isfinite(k)
    if np.any(k[fin] <= 0) or np.sum(1.0 / k[fin]) > 1.0 + 1e-12:
        raise ValueError("weights must be positive with sum(1/k_i) <= 1")
    M = sum(ki * Y for ki, Y in zip(k, infos, strict=True) if np.isfinite(ki))
    return symmetrize(P_D @ M @ P_D)


@implements("WF 23", "WF 21")
def minkowski_trace_bound(covariances: Sequence[ArrayLike | float | None]) -> float:
    r"""Middle term of WF Eq. (23), the Minkowski trace bound.

    :math:`(\sum_i\sqrt{\operatorname{tr}(\mathbf P_D\mathbf P_i^{-1}\mathbf P_D)})^2`.

    Bounds :math:`E\|\mathbf x_D-\hat{\mathbf x}_D\|^2` for any correlation between the local
    errors; it equals the trace of WF Eq. (21) minimised over the weights.

    Parameters
    ----------
    covariances : sequence of (n, n) array, float or None
        Covariance of each local estimator, (m/s)²; ``None``, a scalar or an infinite
        diagonal marks an outage.

    Returns
    -------
    float
        Bound on the mean squared fused error, (m/s)².

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (21),
    (23).

    Examples
    --------
    >>> import numpy as np
    >>> round(minkowski_trace_bound([np.eye(2), np.eye(2)]), 4)
    2.0
    """
    n = _state_size(covariances)
    infos = _informations(covariances, n)
    P_D = symmetrize(np.linalg.inv(symmetrize(sum(infos))))
    return float(sum(np.sqrt(np.trace(P_D @ Y @ P_D)) for Y in infos) ** 2)


@implements("WF 23")
def federated_improvement_db(
    covariances: Sequence[ArrayLike | float | None], reference_sigma: float
) -> float:
    r"""Improvement (dB) of the federated per-axis bound over a reference per-axis :math:`\sigma`.

    :math:`20\log_{10}(\sigma_D/\sigma_{ref})` with
    :math:`\sigma_D = \sqrt{b/n}`, ``b`` the Minkowski trace bound of WF Eq. (23)
    (:func:`minkowski_trace_bound`) over the ``n`` states. Negative values are an
    improvement; WF Figs. 1-2 plot it with ``reference_sigma`` the aperture-velocity error
    without MEMS aiding.

    Parameters
    ----------
    covariances : sequence of (n, n) arrays, ``None`` or ``inf``
        The local estimators' error covariances (units²; an outage is ``None`` or ``inf``).
    reference_sigma : float
        Per-axis standard deviation to compare with, in the units of the states, ``> 0``.

    Returns
    -------
    float
        The ratio in dB.

    Raises
    ------
    ValueError
        If ``reference_sigma`` is not positive or a covariance is not positive definite.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (23).

    Examples
    --------
    >>> import numpy as np
    >>> round(federated_improvement_db([np.eye(3) * 0.01, np.eye(3) * 0.01], 0.1), 3)
    0.0
    """
    require_positive("reference_sigma", reference_sigma)
    n = _state_size(covariances)
    sigma_d = math.sqrt(minkowski_trace_bound(covariances) / n)
    return float(20.0 * math.log10(sigma_d / reference_sigma))


#: Largest joint state size ``n_states * n_estimators`` that
#: :func:`correlated_joint_covariance` draws.
MAX_JOINT_SIZE = 1000


def correlated_joint_covariance(
    rng: np.random.Generator, n_states: int, n_estimators: int, rho: float
) -> Array:
    r"""Draw a joint covariance of ``n_estimators`` correlated local errors of ``n_states`` states.

    Each local covariance is :math:`\mathbf P_i = \mathbf L_i \mathbf L_i^T` with
    :math:`\mathbf L_i` the Cholesky factor of :math:`\mathbf A_i \mathbf A_i^T + 0.1\,\mathbf I`,
    :math:`\mathbf A_i` standard normal (:func:`random_covariance`). The local errors share a
    common part of weight :math:`\rho`: :math:`\mathbf e_i = \mathbf L_i(\sqrt{\rho}\,\mathbf w +
    \sqrt{1 - \rho}\,\mathbf u_i)` with :math:`\mathbf w, \mathbf u_i` independent white, so
    the joint covariance has blocks :math:`\mathbf J_{ii} = \mathbf P_i` and
    :math:`\mathbf J_{ij} = \rho\,\mathbf L_i \mathbf L_j^T`. :math:`\rho = 0` gives
    independent local errors and :math:`\rho = 1` completely correlated ones: the family on
    which the theorem of WF Eqs. (20)-(23) (a bound for *any* correlation) can be exercised.

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the random factors (the draws are :math:`\mathbf A_1, \dots,
        \mathbf A_N` in order).
    n_states : int
        States per local estimator, ``>= 1``.
    n_estimators : int
        Number of local estimators, ``>= 1``; ``n_states * n_estimators`` at most
        ``MAX_JOINT_SIZE``.
    rho : float
        Weight of the common part, in [0, 1].

    Returns
    -------
    ndarray
        The joint covariance, shape ``(n_states * n_estimators, n_states * n_estimators)``;
        block ``i`` of its diagonal is the covariance of estimator ``i``.

    Raises
    ------
    TypeError
        If ``rng`` is not a ``numpy.random.Generator``.
    ValueError
        If ``n_states`` or ``n_estimators`` is not a positive integer, their product exceeds
        ``MAX_JOINT_SIZE``, or ``rho`` is outside [0, 1].

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (20)-(23).

    Examples
    --------
    >>> J = correlated_joint_covariance(np.random.default_rng(0), 2, 3, 0.5)
    >>> J.shape
    (6, 6)
    >>> bool(np.linalg.eigvalsh(J)[0] > 0)
    True
    """
    if not isinstance(rng, np.random.Generator):
        raise TypeError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    n = require_integer("n_states", n_states, minimum=1)
    N = require_integer("n_estimators", n_estimators, minimum=1)
    if n * N > MAX_JOINT_SIZE:
        raise ValueError(f"n_states * n_estimators must be at most {MAX_JOINT_SIZE}, got {n * N}")
    require_in_range("rho", rho, 0.0, 1.0)
    L = [np.linalg.cholesky(random_covariance(rng, n)) for _ in range(N)]
    common = np.vstack(L)
    J = rho * common @ common.T
    for i, Li in enumerate(L):
        J[n * i : n * i + n, n * i : n * i + n] += (1 - rho) * Li @ Li.T
    return J


def random_covariance(rng: np.random.Generator, n: int, floor: float = 0.1) -> Array:
    r"""Draw a random covariance :math:`\mathbf A \mathbf A^T + f\,\mathbf I` of size ``n``.

    :math:`\mathbf A` is ``n x n`` standard normal (one draw of ``rng``) and :math:`f` the
    ``floor`` that keeps the matrix away from singular: its smallest eigenvalue is at least
    :math:`f`, and its mean is :math:`(n + f)\,\mathbf I`. The local covariances on which
    WF's statements about Eqs. (11), (16)-(23) are exercised (they hold for any covariance)
    are such draws.

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of :math:`\mathbf A`.
    n : int
        Size, ``>= 1`` and at most ``MAX_JOINT_SIZE``.
    floor : float, optional
        :math:`f \ge 0` added to the diagonal (0.1).

    Returns
    -------
    (n, n) ndarray
        The symmetric positive semi-definite (definite for ``floor > 0``) matrix.

    Raises
    ------
    TypeError
        If ``rng`` is not a ``numpy.random.Generator``.
    ValueError
        If ``n`` is not a positive integer up to ``MAX_JOINT_SIZE`` or ``floor`` is negative.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (11),
    (16)-(23).

    Examples
    --------
    >>> P = random_covariance(np.random.default_rng(0), 3, floor=0.5)
    >>> bool(np.allclose(P, P.T) and np.linalg.eigvalsh(P)[0] >= 0.5)
    True
    """
    if not isinstance(rng, np.random.Generator):
        raise TypeError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    n = require_integer("n", n, minimum=1)
    if n > MAX_JOINT_SIZE:
        raise ValueError(f"n must be at most {MAX_JOINT_SIZE}, got {n}")
    require_nonnegative("floor", floor)
    A = rng.normal(size=(n, n))
    return A @ A.T + floor * np.eye(n)


def fusion_gains(covariances: Sequence[ArrayLike | float | None]) -> list[Array]:
    r"""The linear maps :math:`\hat{\mathbf x}_i \mapsto \hat{\mathbf x}_D` of WF Eqs. (18)-(19).

    :math:`\hat{\mathbf x}_D = \sum_i \mathbf G_i \hat{\mathbf x}_i` with
    :math:`\mathbf G_i = \mathbf P_D \mathbf P_i^{-1}`; each :math:`\mathbf G_i` is read off
    :func:`federated_fusion` column by column (the fusion of unit estimates), so it is the map
    the fusion applies, round-off included.

    Parameters
    ----------
    covariances : sequence of (n, n) array, float or None
        Covariance of each local estimator; ``None``, ``inf`` or an infinite diagonal marks an
        outage (its map is zero).

    Returns
    -------
    list of (n, n) ndarray
        :math:`\mathbf G_i`, one per estimator.

    Raises
    ------
    ValueError
        As :func:`federated_fusion`.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (18)-(19).

    Examples
    --------
    >>> G = fusion_gains([np.eye(2), 3.0 * np.eye(2)])
    >>> [float(g[0, 0]) for g in G]
    [0.75, 0.25]
    """
    n, N = _state_size(covariances), len(covariances)
    maps = []
    for i in range(N):
        cols = []
        for d in np.eye(n):
            xs = [d if j == i else np.zeros(n) for j in range(N)]
            cols.append(federated_fusion(xs, covariances)[0])
        maps.append(np.column_stack(cols))
    return maps


def federated_bound_margins(rng: np.random.Generator, cases: int) -> dict[str, float]:
    r"""Smallest margins of the theorem of WF Eqs. (21)-(23) over random correlated errors.

    Each of ``cases`` draws a joint covariance of three local errors of three states
    (:func:`correlated_joint_covariance`, correlation weight uniform in [0, 1], drawn first)
    and random directions :math:`\mathbf z_i` for the weights of Eq. (22)
    (:func:`feasible_weights`), and computes the exact covariance :math:`\mathbf C` of the
    fused error (Eq. (20)), the bound :math:`\mathbf B` of Eq. (21) and the Minkowski term
    :math:`m` of Eq. (23). The theorem holds when every margin is non-negative.

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the cases.
    cases : int
        Number of random cases, ``>= 1``.

    Returns
    -------
    dict
        ``"eig"``: smallest :math:`\lambda_{\min}(\mathbf B - \mathbf C)/\|\mathbf B\|` (Eq.
        (21)); ``"first"``: smallest :math:`(m - \operatorname{tr}\mathbf C)/m` and ``"second"``:
        smallest :math:`(\operatorname{tr}\mathbf B - m)/\operatorname{tr}\mathbf B` (the two
        inequalities of Eq. (23)).

    Raises
    ------
    TypeError
        If ``rng`` is not a ``numpy.random.Generator``.
    ValueError
        If ``cases`` is not a positive integer.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (20)-(23).

    Examples
    --------
    >>> m = federated_bound_margins(np.random.default_rng(0), 5)
    >>> all(v >= -1e-12 for v in m.values())
    True
    """
    if not isinstance(rng, np.random.Generator):
        raise TypeError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    require_integer("cases", cases, minimum=1)
    eig_margin, first, second = np.inf, np.inf, np.inf
    for _ in range(cases):
        J = correlated_joint_covariance(rng, 3, 3, rng.uniform())
        Ps = [J[3 * i : 3 * i + 3, 3 * i : 3 * i + 3] for i in range(3)]
        cov = fused_error_covariance(Ps, J)
        k = feasible_weights(Ps, directions=[rng.normal(size=3) for _ in range(3)])
        B = federated_covariance_bound(Ps, k)
        eig_margin = min(eig_margin, np.linalg.eigvalsh(B - cov)[0] / np.linalg.norm(B))
        mink = minkowski_trace_bound(Ps)
        first = min(first, (mink - np.trace(cov)) / mink)
        second = min(second, (np.trace(B) - mink) / np.trace(B))
    return {"eig": float(eig_margin), "first": float(first), "second": float(second)}


#: Kinds of joint covariance :func:`federated_bound_monte_carlo` draws.
MONTE_CARLO_KINDS = ("generic", "mixed", "complete")


def federated_bound_monte_carlo(
    rng: np.random.Generator, n_estimators: int, kind: str, samples: int
) -> dict[str, Any]:
    r"""Seeded Monte Carlo of the fused error against the theorem, WF Eqs. (18)-(23).

    Draws a joint covariance :math:`\mathbf J` of ``n_estimators`` local errors of 3 states:
    ``"generic"`` (:func:`random_covariance`, arbitrary correlations), ``"mixed"``
    (:func:`correlated_joint_covariance`, correlation weight uniform in [0, 1]) or
    ``"complete"`` (:math:`\mathbf e_i = \sigma_i \mathbf w` with one common :math:`\mathbf w`,
    isotropic, :math:`\sigma_i` uniform in [0.1, 2]). ``samples`` errors are drawn, fused with
    the maps of Eqs. (18)-(19) (:func:`fusion_gains`), and their sample covariance
    :math:`\mathbf S` is compared with the bound :math:`\mathbf B` of Eq. (21) (weights of Eq.
    (22) with random :math:`\mathbf z_i`; for ``"complete"`` the optimal weights, an instance of
    Eq. (22) for which :math:`\mathbf B` equals the true covariance, so the check has no slack),
    the Minkowski term of Eq. (23) and the exact covariance :math:`\mathbf C` of Eq. (20).

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the covariance, the errors and the directions, drawn in that order.
    n_estimators : int
        Number of local estimators, ``>= 1``.
    kind : {"generic", "mixed", "complete"}
        The joint covariance.
    samples : int
        Draws of the local errors, ``>= 2``.

    Returns
    -------
    dict
        ``"N"`` and ``"kind"`` as given; the criteria, in sampling standard deviations:
        ``"z_bound"`` :math:`(\lambda_{\max}(\mathbf B^{-1/2}\mathbf S\mathbf B^{-1/2}) - 1) /
        \sqrt{2/(n-1)}` (in any direction the whitened sample variance has sampling sd
        :math:`\sqrt{2/(n-1)}` times a true value at most 1), ``"z_trace"``
        :math:`(\operatorname{tr}\mathbf S - m) / \sqrt{2\operatorname{tr}(\mathbf S^2)/(n-1)}`,
        ``"z_eq20"`` the largest :math:`|S_{jk} - C_{jk}|` over its sampling sd
        :math:`\sqrt{(S_{jj}S_{kk} + S_{jk}^2)/(n-1)}`; ``"exact"`` the relative difference
        between :math:`\mathbf S` and Eq. (20) applied to the sample joint covariance of the
        local errors (zero to round-off: :math:`E[\mathbf S]` is Eq. (20) exactly); and, for
        further checks, the local covariances ``"Ps"``, ``"S"`` and ``"dof"`` (``samples - 1``).

    Raises
    ------
    TypeError
        If ``rng`` is not a ``numpy.random.Generator``.
    ValueError
        If ``kind`` is not one of the three, or ``n_estimators`` or ``samples`` is too small.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (18)-(23).

    Examples
    --------
    >>> r = federated_bound_monte_carlo(np.random.default_rng(1), 2, "mixed", 5000)
    >>> bool(r["z_bound"] <= 5 and r["exact"] < 1e-10)
    True
    """
    if not isinstance(rng, np.random.Generator):
        raise TypeError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    N = require_integer("n_estimators", n_estimators, minimum=1)
    require_integer("samples", samples, minimum=2)
    n = 3
    J: NDArray[Any]
    if kind == "generic":
        J = random_covariance(rng, n * N)
    elif kind == "mixed":
        J = correlated_joint_covariance(rng, n, N, rng.uniform())
    elif kind == "complete":
        sig = rng.uniform(0.1, 2.0, N)
        J = np.kron(np.outer(sig, sig), np.eye(n))
    else:
        raise ValueError(f"kind must be 'generic', 'mixed' or 'complete', got {kind!r}")
    Ps = [J[n * i : n * i + n, n * i : n * i + n] for i in range(N)]
    w, V = np.linalg.eigh(J)
    E = rng.normal(size=(samples, n * N)) @ (V * np.sqrt(np.clip(w, 0.0, None))).T
    fused = sum(E[:, n * i : n * i + n] @ A.T for i, A in enumerate(fusion_gains(Ps)))
    S = np.cov(fused.T)
    C = fused_error_covariance(Ps, J)
    z = list(rng.normal(size=(N, n)))
    k = optimal_weights(Ps) if kind == "complete" else feasible_weights(Ps, directions=z)
    B = federated_covariance_bound(Ps, k)
    Li = np.linalg.inv(np.linalg.cholesky(B))
    dof = samples - 1
    sd = np.sqrt((np.outer(np.diag(S), np.diag(S)) + S**2) / dof)
    return {
        "N": N,
        "kind": kind,
        "z_bound": float((np.linalg.eigvalsh(Li @ S @ Li.T)[-1] - 1) / np.sqrt(2 / dof)),
        "z_trace": float((np.trace(S) - minkowski_trace_bound(Ps)) / np.sqrt(2 * np.trace(S @ S) / dof)),
        "z_eq20": float(np.max(np.abs(S - C) / sd)),
        "exact": float(np.linalg.norm(S - fused_error_covariance(Ps, np.cov(E.T))) / np.linalg.norm(S)),
        "Ps": Ps,
        "S": S,
        "dof": dof,
    }


def federated_bound_monte_carlo_sweep(cases: int, samples: int, seed: int) -> tuple[dict[str, Any], ...]:
    r"""Cases of :func:`federated_bound_monte_carlo` over the kinds and 2-4 estimators.

    Case ``c`` (from 0) draws ``2 + c % 3`` estimators of kind
    ``MONTE_CARLO_KINDS[(c // 3) % 3]`` (three cases per kind, the kinds in turn), all from
    one generator seeded with ``seed``.

    Parameters
    ----------
    cases : int
        Number of cases, ``>= 1``.
    samples : int
        Draws per case, ``>= 2``.
    seed : int
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    tuple of dict
        Per case, ``"N"``, ``"kind"``, ``"z_bound"``, ``"z_trace"``, ``"z_eq20"`` and
        ``"exact"`` of :func:`federated_bound_monte_carlo`.

    Raises
    ------
    ValueError
        If ``cases`` or ``samples`` is too small.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (18)-(23).

    Examples
    --------
    >>> [(r["N"], r["kind"]) for r in federated_bound_monte_carlo_sweep(4, 1000, 0)]
    [(2, 'generic'), (3, 'generic'), (4, 'generic'), (2, 'mixed')]
    """
    require_integer("cases", cases, minimum=1)
    rng = np.random.default_rng(seed)
    out = []
    for case in range(cases):
        kind = MONTE_CARLO_KINDS[(case // 3) % 3]
        r = federated_bound_monte_carlo(rng, 2 + case % 3, kind, samples)
        out.append({key: r[key] for key in ("N", "kind", "z_bound", "z_trace", "z_eq20", "exact")})
    return tuple(out)


def completely_correlated_trace_ratio(
    factors: Sequence[ArrayLike], rng: np.random.Generator, samples: int
) -> float:
    r"""Monte Carlo of WF Remark (ii): the Minkowski term over the fused error's mean square.

    The local errors are completely correlated, :math:`\mathbf e_i = \mathbf L_i \mathbf w`
    with one common white :math:`\mathbf w`, so :math:`\mathbf P_i = \mathbf L_i \mathbf L_i^T`.
    ``samples`` draws of :math:`\mathbf w` are fused with the weights of Eqs. (18)-(19),
    :math:`\mathbf P_D \mathbf P_i^{-1}`; the result is the Minkowski term of Eq. (23)
    (:func:`minkowski_trace_bound`) over the trace of the sample covariance of the fused error.
    It tends to 1 (the bound exact) when the weighted errors are parallel (isotropic or
    commuting covariances), and stays above 1 otherwise.

    Parameters
    ----------
    factors : sequence of (n, n) array
        :math:`\mathbf L_i`, invertible, one per estimator.
    rng : numpy.random.Generator
        Source of :math:`\mathbf w`.
    samples : int
        Draws of :math:`\mathbf w`, ``>= 2``.

    Returns
    -------
    float
        Minkowski term over the sample mean square of the fused error.

    Raises
    ------
    TypeError
        If ``rng`` is not a ``numpy.random.Generator``.
    ValueError
        If a factor is not a square matrix of the common size or ``samples`` is too small.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (23) and
    Remark (ii).

    Examples
    --------
    >>> r = completely_correlated_trace_ratio([np.eye(2), 2.0 * np.eye(2)], np.random.default_rng(0), 1000)
    >>> bool(abs(r - 1.0) < 0.2)  # isotropic: the bound is exact, up to sampling
    True
    """
    if not isinstance(rng, np.random.Generator):
        raise TypeError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    require_integer("samples", samples, minimum=2)
    if isinstance(factors, str) or not isinstance(factors, Sequence | np.ndarray) or not len(factors):
        raise ValueError("factors must be a non-empty sequence of square matrices")
    L = [as_finite_array(f"factors[{i}]", Li, ndim=2) for i, Li in enumerate(factors)]
    n = L[0].shape[0]
    for i, Li in enumerate(L):
        if Li.shape != (n, n):
            raise ValueError(f"factors[{i}] must have shape ({n}, {n}), got {Li.shape}")
    Ps = [Li @ Li.T for Li in L]
    w = rng.normal(size=(samples, n))
    infos = [np.linalg.inv(P) for P in Ps]
    PD = np.linalg.inv(sum(infos))
    fused = sum((w @ (PD @ Y @ Li).T for Y, Li in zip(infos, L, strict=True)), start=np.zeros(w.shape))
    return float(minkowski_trace_bound(Ps) / np.trace(np.cov(fused.T)))


def navigation_mapped_error_samples(
    tau: ArrayLike, P_N: ArrayLike, Q_T: ArrayLike, rng: np.random.Generator, draws: int
) -> Array:
    r"""Draws of the navigation-mapped error :math:`\boldsymbol\tau\mathbf e_N + \mathbf w_T` (WF Eq. (10)).

    :math:`\mathbf e_N \sim N(0, \mathbf P_N)` and :math:`\mathbf w_T \sim N(0, \mathbf Q_T)`
    independent (each a standard normal draw times the Cholesky factor, :math:`\mathbf e_N`
    first); their covariance is :math:`\mathbf P_{DN}` of WF Eq. (11)
    (:func:`navigation_mapped_covariance`).

    Parameters
    ----------
    tau : (m, k) array
        Jacobian :math:`\boldsymbol\tau` of the map.
    P_N : (k, k) array
        Covariance of the navigation error, positive definite.
    Q_T : (m, m) array
        Covariance of the mapping uncertainty, positive definite.
    rng : numpy.random.Generator
        Source of the draws.
    draws : int
        Number of draws, ``>= 1``.

    Returns
    -------
    (draws, m) ndarray
        One error per row.

    Raises
    ------
    TypeError
        If ``rng`` is not a ``numpy.random.Generator``.
    ValueError
        If the shapes do not agree, a covariance is not positive definite, or ``draws`` is
        not a positive integer.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (10)-(11).

    Examples
    --------
    >>> e = navigation_mapped_error_samples(np.eye(2), np.eye(2), np.eye(2), np.random.default_rng(0), 10)
    >>> e.shape
    (10, 2)
    """
    if not isinstance(rng, np.random.Generator):
        raise TypeError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    n = require_integer("draws", draws, minimum=1)
    t = as_finite_array("tau", tau, ndim=2)
    PN = require_symmetric_psd("P_N", P_N, definite=True)
    QT = require_symmetric_psd("Q_T", Q_T, definite=True)
    if t.shape != (QT.shape[0], PN.shape[0]):
        raise ValueError(
            f"tau must have shape ({QT.shape[0]}, {PN.shape[0]}) to map P_N onto Q_T, got {t.shape}"
        )
    eN = rng.normal(size=(n, PN.shape[0])) @ np.linalg.cholesky(PN).T
    wT = rng.normal(size=(n, QT.shape[0])) @ np.linalg.cholesky(QT).T
    return eN @ t.T + wT


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "Ts": POSITIVE,
        "sigma_L": POSITIVE,
        "sigma_a": NONNEGATIVE,
        "P": COVARIANCE,
        "P_prior": COVARIANCE,
        "R_G": COVARIANCE,
        "R_L": COVARIANCE,
        "Q_a": COVARIANCE,
        "P_N": COVARIANCE,
        "Q_T": COVARIANCE,
    },
)
