r"""The discrete Kalman filter: prediction, Joseph-form update, information-form update.

Model
-----
.. math::

    x_{k+1} = \Phi_k x_k + w_k,\quad w_k \sim N(0, Q_k);\qquad
    z_k = H_k x_k + v_k,\quad v_k \sim N(0, R_k).

Prediction: :math:`x^- = \Phi x,\ P^- = \Phi P \Phi^T + Q`.
Update (Joseph form, valid for any gain and numerically symmetric):

.. math::

    S = H P^- H^T + R,\quad K = P^- H^T S^{-1},\quad
    x^+ = x^- + K (z - H x^-),\quad
    P^+ = (I - K H) P^- (I - K H)^T + K R K^T.

Information form: :math:`Y = P^{-1},\ y = P^{-1} x`, and the update adds
:math:`H^T R^{-1} H` and :math:`H^T R^{-1} z`.

All functions are pure: they take arrays and return new arrays. Covariances are returned
exactly symmetric.

References
----------
.. [1] R. E. Kalman, "A New Approach to Linear Filtering and Prediction Problems",
   J. Basic Eng. 82 (1960).
.. [2] P. S. Maybeck, Stochastic Models, Estimation, and Control, Vol. 1 (1979), Ch. 5.
.. [3] R. S. Bucy and P. D. Joseph, Filtering for Stochastic Processes (1968) (Joseph form).
"""

from __future__ import annotations

from typing import NamedTuple, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import lapack

from navcore._validate import as_finite_array, check_public, require_symmetric_psd

__all__ = [
    "KalmanUpdate",
    "covariance_from_information",
    "information_from_covariance",
    "information_update",
    "kf_predict",
    "kf_update",
    "symmetrize",
]

Array = NDArray[np.float64]


def symmetrize(P: ArrayLike) -> Array:
    """Return ``(P + P^T) / 2``, the symmetric part of a matrix (or a stack of matrices).

    Parameters
    ----------
    P : (..., n, n) array
        Square matrix or stack of square matrices.

    Returns
    -------
    ndarray
        The symmetric part, same shape as ``P``.

    Notes
    -----
    Used after every covariance update so that round-off does not break the symmetry the
    Kalman filter (Kalman 1960, reference 1 of the module) relies on.

    Examples
    --------
    >>> symmetrize([[1.0, 2.0], [0.0, 1.0]])
    array([[1., 1.],
           [1., 1.]])
    """
    P = np.asarray(P, dtype=float)
    return 0.5 * (P + np.swapaxes(P, -1, -2))


def _matrix(name: str, value: ArrayLike, shape: tuple[int, int]) -> Array:
    arr = as_finite_array(name, np.atleast_2d(np.asarray(value, dtype=float)))
    if arr.shape != shape:
        raise ValueError(f"{name} must have shape {shape}, got {arr.shape}")
    return arr


def kf_predict(
    x: ArrayLike, P: ArrayLike, Phi: ArrayLike, Q: ArrayLike, *, validate: bool = True
) -> tuple[Array, Array]:
    """Kalman prediction ``x- = Phi x``, ``P- = Phi P Phi^T + Q``.

    Parameters
    ----------
    x : (n,) array
        State estimate (units of the state's layout).
    P : (n, n) array
        Its covariance (symmetric positive semi-definite).
    Phi : (n, n) array
        State transition matrix over the step.
    Q : (n, n) array
        Discrete process-noise covariance over the step (symmetric positive semi-definite).
    validate : bool, default True
        Check shapes, finiteness and that ``P`` and ``Q`` are symmetric positive
        semi-definite. ``False`` skips every check: use it inside a loop, on float arrays
        that were checked once at its boundary (see the Notes).

    Returns
    -------
    x_pred : (n,) ndarray
        Predicted state.
    P_pred : (n, n) ndarray
        Predicted covariance, exactly symmetric.

    Raises
    ------
    ValueError
        If an array has the wrong shape or a non-finite element, or ``P`` or ``Q`` is not
        symmetric positive semi-definite (only with ``validate=True``).

    Notes
    -----
    The time update of Kalman (1960), reference 1 of the module. The checks cost more than
    the arithmetic for a small state (a 9-state step takes a few microseconds of matrix products and tens of
    microseconds of checks), so a filter loop checks its model once and then calls
    ``kf_predict(..., validate=False)`` and ``kf_update(..., validate=False)``.

    Examples
    --------
    >>> import numpy as np
    >>> x, P = kf_predict([0.0, 1.0], np.eye(2), [[1.0, 1.0], [0.0, 1.0]], 0.1 * np.eye(2))
    >>> x
    array([1., 1.])
    >>> P
    array([[2.1, 1. ],
           [1. , 1.1]])
    """
    if not validate:  # float ndarrays checked by the caller; np.dot is the cheapest product
        F = np.asarray(Phi)  # Phi is an ndarray already: no copy
        # P- is symmetric up to round-off here; kf_update symmetrizes what it returns
        return np.dot(F, x), np.dot(np.dot(F, P), F.T) + Q
    x = as_finite_array("x", x, ndim=1)
    n = x.size
    P = _matrix("P", P, (n, n))
    Phi = _matrix("Phi", Phi, (n, n))
    Q = _matrix("Q", Q, (n, n))
    require_symmetric_psd("P", P)
    require_symmetric_psd("Q", Q)
    return Phi @ x, symmetrize(Phi @ P @ Phi.T + Q)  # P- = Phi P Phi' + Q


class KalmanUpdate(NamedTuple):
    """Result of a measurement update.

    Attributes
    ----------
    x : (n,) ndarray
        Posterior state.
    P : (n, n) ndarray
        Posterior covariance.
    K : (n, m) ndarray
        Kalman gain.
    innovation : (m,) ndarray
        ``z - H x`` (measurement units).
    S : (m, m) ndarray
        Innovation covariance ``H P H^T + R``.
    """

    x: Array
    P: Array
    K: Array
    innovation: Array
    S: Array


def kf_update(
    x: ArrayLike, P: ArrayLike, z: ArrayLike, H: ArrayLike, R: ArrayLike, *, validate: bool = True
) -> KalmanUpdate:
    """Kalman measurement update in Joseph form.

    Parameters
    ----------
    x : (n,) array
        Prior state.
    P : (n, n) array
        Prior covariance (symmetric positive semi-definite).
    z : (m,) array
        Measurement (units of the rows of ``H``).
    H : (m, n) array
        Measurement matrix.
    R : (m, m) array
        Measurement-noise covariance (symmetric positive definite).
    validate : bool, default True
        Check shapes, finiteness and definiteness; ``False`` skips every check (for use
        inside a loop on float arrays checked once at its boundary, see :func:`kf_predict`).

    Returns
    -------
    KalmanUpdate
        Posterior ``x`` and ``P``, gain ``K``, innovation ``z - H x`` and its covariance
        ``S``.

    Raises
    ------
    ValueError
        If an array has the wrong shape or a non-finite element, ``P`` is not positive
        semi-definite or ``R`` not positive definite (only with ``validate=True``).

    Notes
    -----
    ``P+ = (I-KH) P- (I-KH)^T + K R K^T`` (Joseph form, Bucy and Joseph 1968, reference 3 of
    the module): it stays symmetric and positive semi-definite under round-off, unlike ``(I-KH) P-``.

    An epoch without measurements (``z`` of length 0, an epoch without satellites) is a
    no-op: ``H`` must then have no rows and ``R`` no elements, and the update returns ``x``
    and ``P`` unchanged, an ``(n, 0)`` gain, an empty innovation and a ``(0, 0)`` ``S``.

    Examples
    --------
    >>> import numpy as np
    >>> up = kf_update([0.0, 0.0], np.eye(2), [2.0], [[1.0, 0.0]], [[1.0]])
    >>> up.x, up.K.ravel()
    (array([1., 0.]), array([0.5, 0. ]))
    >>> kf_update([1.0, 2.0], np.eye(2), [], np.zeros((0, 2)), np.zeros((0, 0))).x  # no measurement
    array([1., 2.])
    """
    if not validate:  # float ndarrays checked by the caller
        if np.size(z) == 0:
            return _no_update(x, P)
        Ha = np.asarray(H)  # H is an ndarray already: no copy
        PHt = np.dot(P, Ha.T)
        S = np.dot(Ha, PHt) + R
        # K' = S^-1 (P H')' by Cholesky (LAPACK posv: S symmetric positive definite)
        _, Kt, info = lapack.dposv(S, PHt.T)
        if info != 0:
            raise ValueError("the innovation covariance H P H' + R is not positive definite")
        K: Array = Kt.T
        innovation = np.subtract(z, np.dot(Ha, x))
        I_KH = -np.dot(K, Ha)
        I_KH.flat[:: I_KH.shape[0] + 1] += 1.0  # I - K H
        P_post = np.dot(np.dot(I_KH, P), I_KH.T) + np.dot(np.dot(K, R), K.T)
        P_post += P_post.T  # Joseph form, made exactly symmetric
        P_post *= 0.5
        return KalmanUpdate(np.add(x, np.dot(K, innovation)), P_post, K, innovation, S)
    x = as_finite_array("x", x, ndim=1)
    n = x.size
    P = _matrix("P", P, (n, n))
    require_symmetric_psd("P", P)
    z = np.atleast_1d(z)  # finite: checked at the public boundary
    if z.ndim != 1:
        raise ValueError(f"z must be a vector, got shape {z.shape}")
    m = z.size
    if m == 0:
        if np.size(H) or np.size(R):
            raise ValueError(
                f"H and R must be empty when z is (no measurement), got H {np.shape(H)} and R {np.shape(R)}"
            )
        return _no_update(x, P)
    H = _matrix("H", H, (m, n))
    R = _matrix("R", R, (m, m))
    require_symmetric_psd("R", R, definite=True)
    innovation = z - H @ x
    S = symmetrize(H @ P @ H.T + R)
    K = cast(Array, np.linalg.solve(S, H @ P.T).T)  # K = P H' S^-1 (S symmetric)
    I_KH = np.eye(n) - K @ H
    P_post = symmetrize(I_KH @ P @ I_KH.T + K @ R @ K.T)  # Joseph form
    return KalmanUpdate(x + K @ innovation, P_post, K, innovation, S)


def _no_update(x: ArrayLike, P: ArrayLike) -> KalmanUpdate:
    """The update of an epoch without measurements: the prior, unchanged (copies)."""
    xa = np.array(x, dtype=float)
    Pa = np.array(P, dtype=float)
    n = xa.size
    return KalmanUpdate(xa, Pa, np.zeros((n, 0)), np.zeros(0), np.zeros((0, 0)))


def information_from_covariance(x: ArrayLike, P: ArrayLike) -> tuple[Array, Array]:
    """Return the information vector ``y = P^-1 x`` and matrix ``Y = P^-1``.

    Parameters
    ----------
    x : (n,) array
        State estimate (units of the state's layout).
    P : (n, n) array
        Its covariance (symmetric positive definite).

    Returns
    -------
    y : (n,) ndarray
        Information vector ``P^-1 x``.
    Y : (n, n) ndarray
        Information matrix ``P^-1``, exactly symmetric.

    Raises
    ------
    ValueError
        If ``P`` is not symmetric positive definite or has a non-finite element.

    Notes
    -----
    The information form of Maybeck (1979), Ch. 5 (reference 2 of the module).

    Examples
    --------
    >>> import numpy as np
    >>> y, Y = information_from_covariance([1.0, 2.0], np.diag([0.5, 4.0]))
    >>> y, np.diag(Y)
    (array([2. , 0.5]), array([2.  , 0.25]))
    """
    P = require_symmetric_psd("P", P, definite=True)
    Y = symmetrize(np.linalg.inv(P))
    return Y @ np.asarray(x, dtype=float), Y


def covariance_from_information(y: ArrayLike, Y: ArrayLike) -> tuple[Array, Array]:
    """Return the state ``x = Y^-1 y`` and covariance ``P = Y^-1`` from information form.

    Parameters
    ----------
    y : (n,) array
        Information vector ``P^-1 x`` (units of the state divided by its variance).
    Y : (n, n) array
        Information matrix ``P^-1`` (symmetric positive definite).

    Returns
    -------
    x : (n,) ndarray
        State estimate.
    P : (n, n) ndarray
        Its covariance, exactly symmetric.

    Raises
    ------
    ValueError
        If ``Y`` is not symmetric positive definite or has a non-finite element.

    Notes
    -----
    The inverse of the information form of Maybeck (1979), Ch. 5 (reference 2 of the module).

    Examples
    --------
    >>> import numpy as np
    >>> x, P = covariance_from_information([2.0, 1.0], np.diag([4.0, 1.0]))
    >>> x, np.diag(P)
    (array([0.5, 1. ]), array([0.25, 1.  ]))
    """
    Y = require_symmetric_psd("Y", Y, definite=True)
    P = symmetrize(np.linalg.inv(Y))
    return P @ np.asarray(y, dtype=float), P


def information_update(
    y: ArrayLike, Y: ArrayLike, z: ArrayLike, H: ArrayLike, R: ArrayLike
) -> tuple[Array, Array]:
    """Information-form measurement update.

    ``Y+ = Y- + H^T R^-1 H`` and ``y+ = y- + H^T R^-1 z``. A zero information matrix
    (no prior knowledge) is allowed, which the covariance form cannot express.

    Parameters
    ----------
    y : (n,) array
        Prior information vector ``P^-1 x``.
    Y : (n, n) array
        Prior information matrix ``P^-1`` (positive semi-definite).
    z : (m,) array
        Measurement (units of the rows of ``H``).
    H : (m, n) array
        Measurement matrix.
    R : (m, m) array
        Measurement-noise covariance (symmetric positive definite).

    Returns
    -------
    y_post : (n,) ndarray
        Posterior information vector.
    Y_post : (n, n) ndarray
        Posterior information matrix, exactly symmetric.

    Raises
    ------
    ValueError
        If an array has the wrong shape or a non-finite element, ``Y`` is not positive
        semi-definite or ``R`` not positive definite.

    Notes
    -----
    The information filter of Maybeck (1979), Ch. 5 (reference 2 of the module); it gives
    the same posterior as :func:`kf_update` whenever the prior is proper. An empty ``z`` (with
    empty ``H`` and ``R``) returns the prior unchanged, as :func:`kf_update` does.

    Examples
    --------
    >>> import numpy as np
    >>> y, Y = information_update([0.0], [[0.0]], [3.0], [[1.0]], [[2.0]])
    >>> y, Y
    (array([1.5]), array([[0.5]]))
    """
    y = as_finite_array("y", y, ndim=1)
    n = y.size
    Y = _matrix("Y", Y, (n, n))
    require_symmetric_psd("Y", Y)
    z = np.atleast_1d(z)  # finite: checked at the public boundary
    if z.ndim != 1:
        raise ValueError(f"z must be a vector, got shape {z.shape}")
    m = z.size
    if m == 0:  # no measurement: the prior, unchanged (as kf_update)
        if np.size(H) or np.size(R):
            raise ValueError(
                f"H and R must be empty when z is (no measurement), got H {np.shape(H)} and R {np.shape(R)}"
            )
        return y.copy(), Y.copy()
    H = _matrix("H", H, (m, n))
    R = _matrix("R", R, (m, m))
    require_symmetric_psd("R", R, definite=True)
    Rinv_H = np.linalg.solve(R, H)
    return y + Rinv_H.T @ z, symmetrize(Y + H.T @ Rinv_H)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals())
