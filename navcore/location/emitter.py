r"""Frequency-of-arrival (Doppler) emitter location from a single moving aperture.

Model
-----
A stationary emitter at position :math:`\mathbf p^e` radiates an unknown carrier
:math:`f_0`. An aperture at position :math:`\mathbf p(k)` moving with velocity
:math:`\mathbf v(k)` receives, to first order in :math:`v/c` (Wu & Fowler, WF Eq. (1)),

.. math::

    f(k) = f_0 + \frac{f_0}{c}\,\mathbf v(k)^T \mathbf u_R(k),\qquad
    \mathbf u_R(k) = \frac{\mathbf p^e - \mathbf p(k)}{\|\mathbf p^e - \mathbf p(k)\|}.

The emitter parameter vector is :math:`\boldsymbol\psi = [p^e_x, p^e_y, p^e_z, f_0]^T` and the
local (aperture) states are the positions and velocities. Weighted least squares solves
:math:`\mathbf H^T\mathbf W[\mathbf m - \mathbf f(\hat{\boldsymbol\psi})] = 0` (WF Eq. (3))
by Gauss-Newton, with :math:`\mathbf H = \partial\mathbf f/\partial\boldsymbol\psi` (WF Eq. (4)).
To first order the estimate error is (WF Eq. (6))

.. math::

    \hat{\boldsymbol\psi} - \boldsymbol\psi
    = (\mathbf H^T\mathbf W\mathbf H)^{-1}\mathbf H^T\mathbf W\,[\mathbf e + \tilde{\mathbf f}_\theta],

where :math:`\tilde{\mathbf f}_\theta` is the signal-model error caused by using estimated
aperture states. The gradients with respect to the aperture states (WF Eqs. (7)-(9)) are

.. math::

    \frac{\partial f}{\partial\mathbf v} = \frac{f_0}{c}\mathbf u_R^T,\qquad
    \frac{\partial f}{\partial\mathbf p} = -\frac{f_0}{c R}\,
        \big(\mathbf v - (\mathbf v^T\mathbf u_R)\mathbf u_R\big)^T,

so :math:`\|\partial f/\partial\mathbf p\| = (f_0/c)\|\mathbf v_\perp\|/R`, half of the bound
:math:`(f_0/c)\,2\|\mathbf v\|/R` printed as WF Eq. (9) at most.

:func:`level_turn_track` gives the aperture's path for the simplest geometry that
observes the emitter from changing directions: a level turn at constant speed and rate.

All quantities are SI: metres, metres per second, hertz.

References
----------
Wu, N. E. and Fowler, M. L., "Application of MEMS for improved emitter location accuracy".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    POSITIVE,
    as_finite_array,
    check_public,
    require_integer,
    require_positive,
    require_symmetric_psd,
)
from navcore.trace import implements
from navcore.units import C

__all__ = [
    "GaussNewtonResult",
    "doppler_frequency",
    "doppler_gradient_position",
    "doppler_gradient_velocity",
    "doppler_jacobian_emitter",
    "emitter_gauss_newton",
    "level_turn_track",
    "linearized_location_error",
    "location_error_covariance",
    "position_sensitivity_bound",
    "signal_model_error",
    "velocity_to_position_sensitivity_ratio",
]

Array = NDArray[np.float64]


def _track(name: str, value: ArrayLike) -> Array:
    a = as_finite_array(name, value)
    if a.ndim == 1:
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{name} must have shape (M, 3) or (3,), got {a.shape}")
    return a


def _geometry(emitter: ArrayLike, position: ArrayLike) -> tuple[Array, Array]:
    pe = np.asarray(emitter)  # finite: checked at the public boundary
    if pe.shape != (3,):
        raise ValueError(f"emitter must be a 3-vector, got shape {pe.shape}")
    p = _track("position", position)
    rel = pe[None, :] - p
    R = np.linalg.norm(rel, axis=1)
    if np.any(R <= 0):
        raise ValueError("position must differ from the emitter position (range > 0)")
    return rel / R[:, None], R


@implements("WF 1")
def doppler_frequency(f0: float, emitter: ArrayLike, position: ArrayLike, velocity: ArrayLike) -> Array:
    r"""Received frequency of a stationary emitter at a moving aperture (WF Eq. (1)).

    Parameters
    ----------
    f0 : float
        Emitter carrier frequency, Hz (> 0).
    emitter : (3,) array
        Emitter position, m.
    position, velocity : (M, 3) or (3,) arrays
        Aperture positions (m) and velocities (m/s) at the M measurement times.

    Returns
    -------
    (M,) array
        :math:`f_0 + (f_0/c)\, \mathbf v \cdot \mathbf u_R` in Hz; positive shift when closing on the emitter.

    Raises
    ------
    ValueError
        If ``f0`` is not positive, a position or velocity is not finite or has the wrong
        shape, or ``velocity`` and ``position`` differ in rows.

    Examples
    --------
    >>> float(doppler_frequency(1e9, [1000.0, 0, 0], [0.0, 0, 0], [299.792458, 0, 0])[0])
    1000001000.0
    """
    require_positive("f0", f0)
    u, _ = _geometry(emitter, position)
    v = _track("velocity", velocity)
    if v.shape[0] != u.shape[0]:
        raise ValueError(f"velocity must have as many rows as position, got {v.shape[0]} and {u.shape[0]}")
    return f0 + (f0 / C) * np.einsum("ij,ij->i", v, u)


@implements("WF 7", "WF 8")
def doppler_gradient_velocity(f0: float, emitter: ArrayLike, position: ArrayLike) -> Array:
    r"""Gradient of the received frequency w.r.t. aperture velocity, :math:`(f_0/c)\, \mathbf u_R` (WF Eq.
    (8)).

    It is the velocity term ``df/dv`` of the total differential WF Eq. (7).

    Parameters
    ----------
    f0 : float
        Emitter carrier frequency, Hz (``> 0``).
    emitter : (3,) array
        Emitter position, m.
    position : (M, 3) or (3,) array
        Aperture positions at the M measurement times, m.

    Returns
    -------
    (M, 3) ndarray
        Gradient, Hz per (m/s); each row has norm ``f0/c``.

    Raises
    ------
    ValueError
        If ``f0`` is not positive or a position is not finite or has the wrong shape.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (7), (8).

    Examples
    --------
    >>> np.round(doppler_gradient_velocity(1e9, [1000.0, 0.0, 0.0], [[0.0, 0.0, 0.0]]), 4).tolist()
    [[3.3356, 0.0, 0.0]]
    """
    require_positive("f0", f0)
    u, _ = _geometry(emitter, position)
    return (f0 / C) * u


@implements("WF 7", "WF 9")
def doppler_gradient_position(
    f0: float, emitter: ArrayLike, position: ArrayLike, velocity: ArrayLike
) -> Array:
    r"""Gradient of the received frequency w.r.t. aperture position (WF Eq. (9), exact form).

    :math:`\partial f/\partial \mathbf p = -\frac{f_0}{c R} (\mathbf v - (\mathbf v^T \mathbf u_R) \mathbf
    u_R)`: only the velocity component across the line
    of sight matters. It is the position term of the total differential WF Eq. (7).

    Parameters
    ----------
    f0 : float
        Emitter carrier frequency, Hz (``> 0``).
    emitter : (3,) array
        Emitter position, m.
    position : (M, 3) or (3,) array
        Aperture positions at the M measurement times, m.
    velocity : (M, 3) or (3,) array
        Aperture velocities, m/s.

    Returns
    -------
    (M, 3) ndarray
        Gradient, Hz per m.

    Raises
    ------
    ValueError
        If ``f0`` is not positive or a position or velocity is not finite or has the wrong
        shape.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (7), (9).

    Examples
    --------
    >>> import numpy as np
    >>> em, p, v = [1000.0, 0.0, 0.0], [[0.0, 0.0, 0.0]], [[100.0, 100.0, 0.0]]
    >>> (np.round(doppler_gradient_position(1e9, em, p, v), 6) + 0.0).tolist()
    [[0.0, -0.333564, 0.0]]
    """
    require_positive("f0", f0)
    u, R = _geometry(emitter, position)
    v = _track("velocity", velocity)
    v_perp = v - np.einsum("ij,ij->i", v, u)[:, None] * u
    return -(f0 / C) * v_perp / R[:, None]


@implements("WF 9")
def position_sensitivity_bound(f0: float, speed: ArrayLike, range_m: ArrayLike) -> Array:
    r"""The printed upper bound :math:`(f_0/c)\, 2\|\mathbf v\|/R` on :math:`\|\partial f/\partial \mathbf
    p\|` (WF Eq. (9)).

    Parameters
    ----------
    f0 : float
        Emitter carrier frequency, Hz (``> 0``).
    speed : array_like
        Aperture speed ``||v||``, m/s (``> 0``).
    range_m : array_like
        Range to the emitter, m (``> 0``).

    Returns
    -------
    ndarray
        Bound, Hz per m.

    Raises
    ------
    ValueError
        If an argument is not positive.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (9).

    Examples
    --------
    >>> f"{float(position_sensitivity_bound(1e9, 100.0, 1.0e4)):.4e}"
    '6.6713e-02'
    """
    require_positive("f0", f0)
    speed = np.asarray(require_positive("speed", speed), dtype=float)
    range_m = np.asarray(require_positive("range_m", range_m), dtype=float)
    return (f0 / C) * 2.0 * speed / range_m


@implements("WF 8", "WF 9")
def velocity_to_position_sensitivity_ratio(speed: ArrayLike, range_m: ArrayLike) -> Array:
    """Ratio of WF Eq. (8) to the bound of WF Eq. (9): ``R / (2 ||v||)``.

    The ratio carries units of seconds (m per m/s): it compares the frequency change caused
    by a 1 m/s velocity error with that of a 1 m position error.

    Parameters
    ----------
    speed : array_like
        Aperture speed, m/s (``> 0``).
    range_m : array_like
        Range to the emitter, m (``> 0``).

    Returns
    -------
    ndarray
        Ratio, s.

    Raises
    ------
    ValueError
        If an argument is not positive.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eqs. (8)-(9).

    Examples
    --------
    >>> float(velocity_to_position_sensitivity_ratio(100.0, 1.0e4))
    50.0
    """
    speed = np.asarray(require_positive("speed", speed), dtype=float)
    range_m = np.asarray(require_positive("range_m", range_m), dtype=float)
    return range_m / (2.0 * speed)


@implements("WF 4")
def doppler_jacobian_emitter(
    f0: float, emitter: ArrayLike, position: ArrayLike, velocity: ArrayLike
) -> Array:
    r"""Jacobian ``H = df/d[p^e, f0]`` of the stacked frequencies (WF Eq. (4)).

    Row k is :math:`[\,(f_0/c)(\mathbf v-(\mathbf v^T\mathbf u_R)\mathbf u_R)^T/R,\;
    1 + \mathbf v^T\mathbf u_R/c\,]`. The emitter-position block is minus the aperture-position
    gradient (only the difference of the two positions enters).

    Parameters
    ----------
    f0 : float
        Emitter carrier frequency, Hz (``> 0``).
    emitter : (3,) array
        Emitter position, m.
    position : (M, 3) or (3,) array
        Aperture positions at the M measurement times, m.
    velocity : (M, 3) or (3,) array
        Aperture velocities, m/s.

    Returns
    -------
    (M, 4) ndarray
        Columns in Hz/m (three) and Hz/Hz (one).

    Raises
    ------
    ValueError
        As :func:`doppler_gradient_position`.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (4).

    Examples
    --------
    >>> import numpy as np
    >>> em, p, v = [1000.0, 0.0, 0.0], [[0.0, 0.0, 0.0]], [[100.0, 100.0, 0.0]]
    >>> H = doppler_jacobian_emitter(1e9, em, p, v)
    >>> np.round(H, 6).tolist()
    [[0.0, 0.333564, 0.0, 1.0]]
    """
    dp = -doppler_gradient_position(f0, emitter, position, velocity)
    u, _ = _geometry(emitter, position)
    v = _track("velocity", velocity)
    df0 = 1.0 + np.einsum("ij,ij->i", v, u) / C
    return np.column_stack([dp, df0])


@implements("WF 6")
def signal_model_error(
    f0: float,
    emitter: ArrayLike,
    position: ArrayLike,
    velocity: ArrayLike,
    position_est: ArrayLike,
    velocity_est: ArrayLike,
) -> Array:
    r"""Signal-model error of WF Eq. (6).

    :math:`\tilde{\mathbf f}_\theta = \mathbf f(\mathbf p^e,\Theta) - \mathbf f(\mathbf p^e,\hat\Theta)`.

    The true aperture states are ``position, velocity``; the processing uses the estimates.

    Parameters
    ----------
    f0 : float
        Emitter carrier frequency, Hz (``> 0``).
    emitter : (3,) array
        Emitter position, m.
    position : (M, 3) or (3,) array
        Aperture positions at the M measurement times, m.
    velocity : (M, 3) or (3,) array
        Aperture velocities, m/s.
    position_est : (M, 3) or (3,) array
        Estimated aperture positions, m.
    velocity_est : (M, 3) or (3,) array
        Estimated aperture velocities, m/s.

    Returns
    -------
    (M,) ndarray
        Frequency error, Hz.

    Raises
    ------
    ValueError
        If ``f0`` is not positive or an array is not finite or has the wrong shape.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (6).

    Examples
    --------
    >>> e = signal_model_error(1e9, [1000.0, 0.0, 0.0], [[0.0, 0.0, 0.0]], [[0.0, 0.0, 0.0]],
    ...                        [[0.0, 0.0, 0.0]], [[0.1, 0.0, 0.0]])
    >>> round(float(e[0]), 4)
    -0.3336
    """
    return doppler_frequency(f0, emitter, position, velocity) - doppler_frequency(
        f0, emitter, position_est, velocity_est
    )


def _weight(W: ArrayLike | None, M: int) -> Array:
    if W is None:
        return np.eye(M)
    Wa = np.asarray(W, dtype=float)
    if Wa.ndim == 1:
        Wa = np.diag(Wa)
    require_symmetric_psd("W", Wa, definite=True)
    if Wa.shape != (M, M):
        raise ValueError(f"W must be ({M}, {M}) to match the measurements, got {Wa.shape}")
    return Wa


@implements("WF 5", "WF 6", "WF 4")
def linearized_location_error(H: ArrayLike, error: ArrayLike, W: ArrayLike | None = None) -> Array:
    r"""First-order emitter-parameter error (WF Eqs. (5)-(6)).

    :math:`(\mathbf H^T\mathbf W\mathbf H)^{-1}\mathbf H^T\mathbf W\,\boldsymbol\epsilon`: the
    weighted least-squares solution of the linearised model WF Eq. (5),

    .. math::

        \mathbf H(\mathbf p^e-\hat{\mathbf p}^e)
        = \mathbf f(\mathbf p^e,\hat\Theta)-\mathbf f(\hat{\mathbf p}^e,\hat\Theta),

    combined with the normal equation WF Eq. (3).

    Parameters
    ----------
    H : (M, n) array
        Jacobian of WF Eq. (4).
    error : (M,) or (M, T) array
        Total frequency error ``e + f_tilde`` (Hz); columns are independent trials.
    W : (M, M) or (M,) array, optional
        Positive-definite weight (identity by default; a vector means a diagonal).

    Returns
    -------
    (n,) or (n, T) array
        Error of ``[p^e, f0]`` in m and Hz.

    Raises
    ------
    ValueError
        If ``H`` or ``error`` is not finite or their rows differ, or ``W`` is not a valid
        weight.

    Examples
    --------
    >>> import numpy as np
    >>> H = np.array([[1.0, 0.0], [0.0, 2.0], [1.0, 1.0]])
    >>> linearized_location_error(H, [0.1, 0.2, 0.2]).round(6).tolist()
    [0.1, 0.1]
    """
    H = as_finite_array("H", H, ndim=2)
    e = as_finite_array("error", error)
    if e.shape[0] != H.shape[0]:
        raise ValueError(f"error must have {H.shape[0]} rows to match H, got {e.shape[0]}")
    Wm = _weight(W, H.shape[0])
    HtW = H.T @ Wm
    return np.asarray(np.linalg.solve(HtW @ H, HtW @ e), dtype=float)


@implements("WF 6")
def location_error_covariance(H: ArrayLike, error_covariance: ArrayLike, W: ArrayLike | None = None) -> Array:
    r"""Covariance of the WF Eq. (6) error for a frequency-error covariance :math:`\Sigma`.

    :math:`\mathbf G \Sigma \mathbf G^T` with :math:`\mathbf G = (\mathbf H^T \mathbf W \mathbf H)^{-1}
    \mathbf H^T \mathbf W`; it reduces to :math:`(\mathbf H^T \Sigma^{-1} \mathbf H)^{-1}`
    when ``W = Sigma^-1``.

    Parameters
    ----------
    H : (M, n) array
        Jacobian of WF Eq. (4) (Hz per m and Hz per Hz).
    error_covariance : (M, M) array
        Covariance :math:`\Sigma` of the frequency errors, Hz².
    W : (M, M) or (M,) array, optional
        Positive-definite weight (identity by default; a vector means a diagonal).

    Returns
    -------
    (n, n) ndarray
        Covariance of the error of ``[p^e, f0]`` (m², Hz² and cross terms).

    Raises
    ------
    ValueError
        If ``error_covariance`` is not symmetric positive semi-definite or a shape disagrees.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Eq. (6).

    Examples
    --------
    >>> import numpy as np
    >>> round(float(location_error_covariance([[2.0], [2.0]], np.eye(2))[0, 0]), 6)
    0.125
    """
    H = as_finite_array("H", H, ndim=2)
    S = require_symmetric_psd("error_covariance", error_covariance)
    Wm = _weight(W, H.shape[0])
    HtW = H.T @ Wm
    G = np.linalg.solve(HtW @ H, HtW)
    out = G @ S @ G.T
    return 0.5 * (out + out.T)


@dataclass(frozen=True)
class GaussNewtonResult:
    r"""Result of :func:`emitter_gauss_newton`.

    Attributes
    ----------
    estimate : (4,) array
        ``[p^e_x, p^e_y, p^e_z, f0]`` in m and Hz.
    jacobian : (M, 4) array
        ``H`` of WF Eq. (4) at the estimate.
    residual : (M,) array
        ``m - f(estimate)`` in Hz.
    normal_equation : (4,) array
        :math:`\mathbf H^T \mathbf W` times ``residual`` (WF Eq. (3)); zero at the solution.
    iterations : int
    converged : bool
    """

    estimate: Array
    jacobian: Array
    residual: Array
    normal_equation: Array
    iterations: int
    converged: bool


@implements("WF 2", "WF 3", "WF 4")
def emitter_gauss_newton(
    measurements: ArrayLike,
    position: ArrayLike,
    velocity: ArrayLike,
    initial: ArrayLike,
    W: ArrayLike | None = None,
    *,
    max_iter: int = 20,
    tol_m: float = 1e-3,
) -> GaussNewtonResult:
    """Weighted Gauss-Newton least squares for emitter position and frequency (WF Eqs. (2)-(4)).

    Parameters
    ----------
    measurements : (M,) array
        Measured frequencies ``m`` (Hz), WF Eq. (2).
    position, velocity : (M, 3) arrays
        Aperture states used by the processing (the estimates, WF's :math:`\\hat\\Theta`).
    initial : (4,) array
        Starting ``[p^e, f0]``.
    W : array, optional
        Positive-definite weight (identity by default).
    max_iter : int
        Iteration limit.
    tol_m : float
        Stop when the position step is below this (m).

    Returns
    -------
    GaussNewtonResult
        ``converged`` is True only if the step fell below ``tol_m`` *and* the Jacobian has
        full column rank 4 there (the four unknowns are determined by the data).

    Raises
    ------
    ValueError
        If there are fewer than 4 measurements, the arrays disagree in length, or an input
        is not finite; ``max_iter`` is bounded by ``navcore._validate.MAX_LOOP_COUNT``.

    Examples
    --------
    Noise-free frequencies along a curved, descending pass (a straight track leaves the
    emitter's rotation about it unobservable): the iteration returns the emitter.

    >>> import numpy as np
    >>> s = np.linspace(0.0, 1.0, 21)
    >>> p = np.column_stack([2000.0 * s, 500.0 * np.sin(np.pi * s), -1000.0 - 300.0 * s])
    >>> v = np.gradient(p, axis=0) * 20.0  # samples 0.05 s apart
    >>> m = doppler_frequency(1e9, [1000.0, 3000.0, 0.0], p, v)
    >>> res = emitter_gauss_newton(m, p, v, [900.0, 2800.0, -100.0, 1e9 + 5.0])
    >>> res.converged, (np.round(res.estimate, 3) + 0.0).tolist()
    (True, [1000.0, 3000.0, 0.0, 1000000000.0])
    """
    m = as_finite_array("measurements", measurements, ndim=1)
    if m.size < 4:
        raise ValueError(
            f"measurements must hold at least 4 frequencies for the 4 unknowns [x, y, z, f0], got {m.size}"
        )
    p = _track("position", position)
    v = _track("velocity", velocity)
    if p.shape[0] != m.size or v.shape[0] != m.size:
        raise ValueError("position and velocity must have one row per measurement")
    psi = as_finite_array("initial", initial, ndim=1).copy()
    if psi.shape != (4,):
        raise ValueError(f"initial must be [x, y, z, f0], got shape {psi.shape}")
    require_integer("max_iter", max_iter, minimum=1)
    require_positive("tol_m", tol_m)
    Wm = None if W is None else _weight(W, m.size)
    converged = False
    iterations = 0
    for iterations in range(1, max_iter + 1):  # noqa: B007 (reported after the loop)
        H = doppler_jacobian_emitter(psi[3], psi[:3], p, v)
        r = m - doppler_frequency(psi[3], psi[:3], p, v)
        HtW = H.T if Wm is None else H.T @ Wm
        step = np.linalg.lstsq(HtW @ H, HtW @ r, rcond=None)[0]
        psi = psi + step
        if np.linalg.norm(step[:3]) < tol_m:
            # a zero step on a rank-deficient problem (repeated apertures) is not a solution
            converged = bool(np.linalg.matrix_rank(H) == 4)
            break
    H = doppler_jacobian_emitter(psi[3], psi[:3], p, v)
    r = m - doppler_frequency(psi[3], psi[:3], p, v)
    HtW = H.T if Wm is None else H.T @ Wm
    return GaussNewtonResult(psi, H, r, HtW @ r, iterations, converged)


def level_turn_track(
    speed: float, altitude: float, n_samples: int, turn_rate_deg_s: float, duration: float
) -> tuple[Array, Array, Array]:
    r"""Times, positions and velocities of a level turn at constant speed and turn rate.

    The aperture starts at :math:`(0, 0, h)` heading along :math:`x` and turns at the rate
    :math:`\omega` (positive: towards :math:`+y`) on the circle of radius
    :math:`r = v/\omega`:

    .. math::

        \mathbf p(t) = (r \sin\omega t,\; r (1 - \cos\omega t),\; h),

        \mathbf v(t) = (v \cos\omega t,\; v \sin\omega t,\; 0),

    sampled at ``n_samples`` equally spaced times from 0 to ``duration``. WF Sec. III flies
    such a turn (200 m/s, 8 km) to locate an emitter by its Doppler history.

    Parameters
    ----------
    speed : float
        Ground speed :math:`v`, m/s (``> 0``).
    altitude : float
        Height :math:`h`, m.
    n_samples : int
        Number of samples (``>= 2``).
    turn_rate_deg_s : float
        Turn rate :math:`\omega`, deg/s (non-zero; negative turns towards :math:`-y`).
    duration : float
        Length of the track, s (``> 0``).

    Returns
    -------
    t : (n_samples,) ndarray
        Times, s.
    position : (n_samples, 3) ndarray
        Positions, m.
    velocity : (n_samples, 3) ndarray
        Velocities, m/s.

    Raises
    ------
    ValueError
        If ``speed`` or ``duration`` is not positive, ``turn_rate_deg_s`` is zero or not
        finite, or ``n_samples`` is not an integer of at least 2.

    References
    ----------
    Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy", Sec. III.

    Examples
    --------
    >>> t, p, v = level_turn_track(100.0, 1000.0, 3, 90.0, 2.0)  # a half circle of radius 63.7 m
    >>> p.round(1).tolist()
    [[0.0, 0.0, 1000.0], [63.7, 63.7, 1000.0], [0.0, 127.3, 1000.0]]
    >>> v.round(6).tolist()[2]
    [-100.0, 0.0, 0.0]
    """
    require_positive("speed", speed)
    altitude = float(as_finite_array("altitude", altitude))
    M = require_integer("n_samples", n_samples, minimum=2)
    if COUNT.high is not None and M > COUNT.high:
        raise ValueError(f"n_samples must be at most {COUNT.high}, got {M}")
    rate = float(as_finite_array("turn_rate_deg_s", turn_rate_deg_s))
    if rate == 0.0:
        raise ValueError("turn_rate_deg_s must be non-zero (a straight track has no turn radius)")
    require_positive("duration", duration)
    t = np.linspace(0.0, duration, M)
    w = np.deg2rad(rate)
    radius = speed / w
    pos = np.column_stack([radius * np.sin(w * t), radius * (1 - np.cos(w * t)), np.full(M, altitude)])
    vel = np.column_stack([speed * np.cos(w * t), speed * np.sin(w * t), np.zeros(M)])
    return t, pos, vel


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals(), {"f0": POSITIVE, "max_iter": COUNT, "tol_m": POSITIVE})
