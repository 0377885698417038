r"""The discrete Kalman filter: prediction, Joseph-form update, information-form update.

Model
-----
.. math::

    \begin{aligned}
    x_{k+1} &= \Phi_k x_k + w_k, & w_k &\sim N(0, Q_k);\\
    z_k &= H_k x_k + v_k, & v_k &\sim N(0, R_k).
    \end{aligned}

Prediction: :math:`x^- = \Phi x,\ P^- = \Phi P \Phi^T + Q`.
Update (Joseph form, valid for any gain and numerically symmetric):

.. math::

    \begin{aligned}
    S &= H P^- H^T + R, \qquad K = P^- H^T S^{-1},\\
    x^+ &= x^- + K (z - H x^-),\\
    P^+ &= (I - K H) P^- (I - K H)^T + K R K^T.
    \end{aligned}

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

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import lapack

from navcore._validate import (
    _SQRT_EPS,
    COVARIANCE_STACK,
    _potrf,
    as_finite_array,
    check_argument,
    check_public,
    check_symmetric_psd,
    checks_own_arguments,
    require_symmetric_psd,
)

__all__ = [
    "KalmanUpdate",
    "covariance_from_information",
    "information_from_covariance",
    "information_update",
    "joseph_update",
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
    return symmetrize_unchecked(np.asarray(P, dtype=float))


def symmetrize_unchecked(P: Array) -> Array:
    """:func:`symmetrize` without the argument checks, for loops over float arrays checked once.

    Parameters
    ----------
    P : (..., n, n) ndarray
        Float square matrix or stack of them (not checked).

    Returns
    -------
    ndarray
        ``(P + P^T) / 2``, the same numbers as :func:`symmetrize`.

    Examples
    --------
    >>> import numpy as np
    >>> symmetrize_unchecked(np.array([[1.0, 2.0], [0.0, 1.0]])).tolist()
    [[1.0, 1.0], [1.0, 1.0]]
    """
    return 0.5 * (P + np.swapaxes(P, -1, -2))


# The filter steps check their own arguments, once each (the generic wrapper,
# navcore._validate.checked, would cost a large part of the step): the vectors are numeric and
# finite, the covariances and the model matrices have their shapes, are finite, symmetric and
# definite as each must be; the matrices that passed are remembered by their numbers.
def _vector(name: str, value: ArrayLike) -> Array:
    arr = np.asarray(value, dtype=float)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-dimensional array, got shape {arr.shape}")
    return arr


def _finite(name: str, value: ArrayLike) -> Array:
    """``value`` as a float array, finite everywhere: the checks :func:`checked` makes, worded
    as it words them, at the cost of one scan for a float array (the filter steps' vectors)."""
    if type(value) is not np.ndarray or value.dtype.kind != "f":
        check_argument(name, value, "array")  # a type, a ragged list, a NaN: named as the wrapper does
        return np.asarray(value, dtype=float)
    # a short vector is scanned fastest as Python floats (a third of np.isfinite(...).all())
    if not (
        all(map(math.isfinite, value.tolist()))
        if value.ndim == 1 and value.size <= 64
        else np.isfinite(value).all()
    ):
        raise ValueError(f"{name} must be finite (no NaN or infinity)")
    return value


def _flag(name: str, value: object) -> None:
    if not isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be of type bool, got {value!r}")


def _covariance(name: str, value: ArrayLike, n: int, *, definite: bool = False) -> Array:
    """A covariance argument as a float (n, n) array, finite, symmetric and positive
    semi-definite (``definite``: definite): its one check, which the wrapper leaves to the body.

    The common case costs an exact-symmetry test and one Cholesky factorisation (which
    fails on a NaN and on an infinite off-diagonal element; an infinite diagonal is seen
    directly); anything else goes through the full checks, which word the error as the
    wrapper and :func:`navcore._validate.require_symmetric_psd` do.
    """
    arr = _matrix(name, value, (n, n))
    key = (definite, n, arr.tobytes())
    if key in _PASSED:  # these very numbers passed before (a model's Q or R, step after step)
        return arr
    if not (n and (arr == arr.T).all() and _cholesky_passes(arr, definite)):
        check_argument(name, arr, "array")  # finite, with the wrapper's message
        check_symmetric_psd(name, arr, definite=definite)
    _passed(arr, definite)
    return arr


def _passed(arr: Array, definite: bool = False) -> Array:
    """Remember that a covariance with these very numbers is valid (bounded memory)."""
    _remember((definite, arr.shape[0], arr.tobytes()))
    return arr


def _remember(key: tuple[bool, int, bytes]) -> None:
    """Add ``key`` to :data:`_PASSED`, which starts again empty when it holds 256 entries."""
    if len(_PASSED) >= 256:
        _PASSED.clear()
    _PASSED[key] = None


#: Contents of covariances known to be valid (the check is a function of the numbers alone,
#: so the same bytes pass again): those that passed :func:`_covariance`, and the exactly
#: symmetric covariances the checked steps return, which are positive semi-definite by
#: construction (``Phi P Phi' + Q`` and the Joseph form are sums of congruences of positive
#: semi-definite matrices), so that a checked loop checks its covariance once, not at every
#: step (a caller who changes one number of it makes it new bytes, checked again); and the
#: finite transition and measurement matrices (:func:`_model_matrix`). Bounded: emptied at 256
#: entries (a checked loop adds two covariances a step, so the model's ``Q``, ``R``, ``Phi``
#: and ``H`` are checked again every 128 steps).
_PASSED: dict[tuple[bool, int, bytes], None] = {}


def _cholesky_passes(arr: Array, definite: bool) -> bool:
    """An exactly symmetric matrix with a finite positive diagonal whose Cholesky factorisation
    succeeds (with every pivot well above round-off, for ``definite``) passes the full test."""
    top = float(arr.diagonal().max())
    if not 0.0 < top < np.inf:
        return False
    lower, info = _potrf(arr.copy())
    return info == 0 and (not definite or float(lower.diagonal().min()) ** 2 > _SQRT_EPS * top)


def _matrix(name: str, value: ArrayLike, shape: tuple[int, int]) -> Array:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:  # a string, a ragged list
        raise TypeError(
            f"{name} must be a {shape[0]}x{shape[1]} matrix of numbers, got {value!r} ({exc})"
        ) from None
    if arr.ndim < 2:
        arr = np.atleast_2d(arr)
    if arr.shape != shape:
        raise ValueError(f"{name} must have shape {shape}, got {arr.shape}")
    return arr


def _model_matrix(name: str, value: ArrayLike, shape: tuple[int, int]) -> Array:
    """A transition or measurement matrix as a float array of ``shape``, finite everywhere.

    A filter uses the same ``Phi`` and ``H`` step after step, so the matrices that passed are
    remembered by their numbers (as the covariances are, :data:`_PASSED`) and not scanned again.
    """
    arr = _matrix(name, value, shape)
    key = (False, -arr.shape[0], arr.tobytes())  # a negative size: never a covariance's key
    if key not in _PASSED:
        check_argument(name, arr, "array")  # finite, with the wrapper's message
        _remember(key)
    return arr


@checks_own_arguments
def kf_predict(
    x: ArrayLike, P: ArrayLike, Phi: ArrayLike, Q: ArrayLike, *, validate: bool = True
) -> tuple[Array, Array]:
    r"""Kalman prediction :math:`x^- = \Phi x`, :math:`P^- = \Phi P \Phi^T + Q`.

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
    The time update of Kalman (1960), reference 1 of the module. Each argument is checked
    once, in the body: the state (finite numbers), the covariances
    (shape, exact symmetry and one Cholesky factorisation, which also rejects a NaN or an
    infinity; a matrix that fails them goes through the full tests, eigenvalues included,
    for the error), the transition by the body (shape, finite). A covariance or transition
    with the very numbers of one that passed recently (the model's ``Q`` and ``Phi`` step
    after step, the covariance the previous checked step returned) is not scanned again.
    For 9 states and 3 measurements the checks still cost a good part of the arithmetic
    (``nox -s bench`` prints the checked and unchecked steps against filterpy's), so a
    filter loop can check its model once and then call ``kf_predict(..., validate=False)``
    and ``kf_update(..., validate=False)``, which costs less than filterpy's step.

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
    if validate is False:  # float ndarrays checked by the caller; np.dot is the cheapest product
        F = np.asarray(Phi)  # Phi is an ndarray already: no copy
        # P- is symmetric up to round-off here; kf_update symmetrizes what it returns
        return np.dot(F, x), np.dot(np.dot(F, P), F.T) + Q
    _flag("validate", validate)
    x = _vector("x", _finite("x", x))
    n = x.size
    P = _covariance("P", P, n)
    Phi = _model_matrix("Phi", Phi, (n, n))
    Q = _covariance("Q", Q, n)
    P_pred = np.dot(np.dot(Phi, P), Phi.T) + Q  # P- = Phi P Phi' + Q
    P_pred += P_pred.T  # made exactly symmetric, in place
    P_pred *= 0.5
    return np.dot(Phi, x), _passed(P_pred)


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
        Innovation covariance :math:`H P H^T + R`.
    """

    x: Array
    P: Array
    K: Array
    innovation: Array
    S: Array


@checks_own_arguments
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
    :math:`P^+ = (I - KH) P^- (I - KH)^T + K R K^T` (Joseph form, Bucy and Joseph 1968, reference 3 of
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
    if validate is False:  # float ndarrays checked by the caller
        if np.size(z) == 0:
            return _no_update(x, P)
        return _joseph_update(x, P, z, np.asarray(H), R)  # H is an ndarray already: no copy
    _flag("validate", validate)
    x = _vector("x", _finite("x", x))
    n = x.size
    P = _covariance("P", P, n)
    z = np.atleast_1d(_finite("z", z))
    if z.ndim != 1:
        raise ValueError(f"z must be a vector, got shape {z.shape}")
    m = z.size
    if m == 0:
        if np.size(H) or np.size(R):
            raise ValueError(
                f"H and R must be empty when z is (no measurement), got H {np.shape(H)} and R {np.shape(R)}"
            )
        return _no_update(x, P)
    H = _model_matrix("H", H, (m, n))
    R = _covariance("R", R, m, definite=True)
    update = _joseph_update(x, P, z, H, R)
    _passed(update.P)
    return update


def _joseph_update(x: ArrayLike, P: ArrayLike, z: ArrayLike, H: Array, R: ArrayLike) -> KalmanUpdate:
    """The arithmetic of :func:`kf_update` on checked float arrays (both of its paths)."""
    PHt = np.dot(P, H.T)
    S = np.dot(H, PHt) + R
    # K' = S^-1 (P H')' by Cholesky (LAPACK posv: S symmetric positive definite)
    _, Kt, info = lapack.dposv(S, PHt.T)
    if info != 0:
        raise ValueError("the innovation covariance H P H' + R is not positive definite")
    K: Array = Kt.T
    innovation = np.subtract(z, np.dot(H, x))
    P_post = joseph_unchecked(np.asarray(P), K, H, np.asarray(R))
    return KalmanUpdate(np.add(x, np.dot(K, innovation)), P_post, K, innovation, S)


def joseph_update(
    P: ArrayLike,
    K: ArrayLike,
    H: ArrayLike,
    R: ArrayLike,
    *,
    rows: ArrayLike | None = None,
    symmetric: bool = True,
) -> Array:
    r"""Joseph-form covariance update :math:`(I - K H) P (I - K H)^T + K R K^T`, for any gain.

    Parameters
    ----------
    P : (..., n, n) array
        Prior covariance (symmetric positive semi-definite), or a stack of them.
    K : (..., n, m) array
        Gain, any gain (optimal or not); with ``rows``, ``(..., k, m)``: the gain of the
        states ``rows`` of ``P``, zero on the others.
    H : (..., m, n) array
        Measurement matrix (over all ``n`` states of ``P``).
    R : (..., m, m) array
        Measurement-noise covariance (symmetric positive semi-definite).
    rows : (k,) array of int, optional
        The states of ``P`` that the gain corrects (the filter's states inside a larger truth
        model: the gain is :math:`E K` with :math:`E` the embedding of these rows). The update
        is then computed in its expanded form
        :math:`P - E K H P - (E K H P)^T + E K (H P H^T + R) K^T E^T`, which touches only those
        rows and columns (:math:`O(n^2 m)` instead of :math:`O(n^3)`).
    symmetric : bool, default True
        Return :math:`(P^+ + P^{+T}) / 2`, exactly symmetric; ``False`` returns the form as
        computed, symmetric up to round-off (for a loop that symmetrises once per step).

    Returns
    -------
    (..., n, n) ndarray
        Posterior covariance; the leading axes broadcast.

    Raises
    ------
    ValueError
        If the shapes do not match or an input is not finite.

    Notes
    -----
    The Joseph form (Bucy and Joseph 1968, reference 3 of the module) is valid for any gain
    and keeps the covariance symmetric positive semi-definite under round-off; with the
    optimal gain :math:`K = P H^T (H P H^T + R)^{-1}` it equals the short form
    :math:`(I - K H) P` of Kalman (1960). With a suboptimal gain it is the covariance of the
    true estimation error, which is how a covariance analysis of a mismodelled filter
    (Gelb 1974, Sec. 7.2) uses it. :func:`kf_update` updates its covariance with this
    function; batched over leading axes (a stack of runs, of jammer powers, of members).

    Examples
    --------
    >>> import numpy as np
    >>> joseph_update(np.eye(2), [[0.5], [0.0]], [[1.0, 0.0]], [[1.0]])
    array([[0.5, 0. ],
           [0. , 1. ]])

    A suboptimal gain (0.8 instead of the optimal 0.5) leaves more error, ``0.2**2 + 0.8**2``:

    >>> round(float(joseph_update(np.eye(1), [[0.8]], [[1.0]], [[1.0]])[0, 0]), 12)
    0.68
    """
    P = np.asarray(P, dtype=float)
    K = np.asarray(K, dtype=float)
    H = np.asarray(H, dtype=float)
    R = np.asarray(R, dtype=float)
    n = P.shape[-1]
    if P.ndim < 2 or P.shape[-2] != n or H.ndim < 2 or H.shape[-1] != n or K.ndim < 2:
        raise ValueError(f"P must be (..., n, n) and H (..., m, n), got P {P.shape} and H {H.shape}")
    m = H.shape[-2]
    k = n if rows is None else np.size(rows)
    if K.shape[-2:] != (k, m) or R.shape[-2:] != (m, m):
        raise ValueError(
            f"K must be (..., {k}, {m}) and R (..., {m}, {m}) for P {P.shape} and H {H.shape}, "
            f"got K {K.shape} and R {R.shape}"
        )
    if rows is None:
        return joseph_unchecked(P, K, H, R, symmetric=symmetric)
    idx = np.asarray(rows, dtype=np.intp)
    if idx.ndim != 1 or (idx.size and (idx.min() < -n or idx.max() >= n)):
        raise ValueError(f"rows must be a 1-D array of state indices below {n}, got {rows!r}")
    shape = np.broadcast_shapes(P.shape, (*K.shape[:-2], n, n))
    out = joseph_rows_unchecked(np.array(np.broadcast_to(P, shape)), K, H, R, idx)
    return symmetrize_unchecked(out) if symmetric else out


def joseph_unchecked(P: Array, K: Array, H: Array, R: Array | float, *, symmetric: bool = True) -> Array:
    """:func:`joseph_update` (without ``rows``) with no argument checks, for loops over float
    arrays checked once.

    Parameters
    ----------
    P, K, H : ndarray
        As :func:`joseph_update`: float arrays (not checked).
    R : ndarray or float
        As :func:`joseph_update`, or, for a single measurement (``m = 1``), its variance as a
        scalar: the noise term is then formed as ``R (K K^T)``.
    symmetric : bool, default True
        Return the symmetric part.

    Returns
    -------
    ndarray
        The same numbers as :func:`joseph_update`.

    Examples
    --------
    >>> import numpy as np
    >>> joseph_unchecked(np.eye(2), np.array([[0.5], [0.0]]), np.array([[1.0, 0.0]]), np.eye(1)).tolist()
    [[0.5, 0.0], [0.0, 1.0]]
    """
    I_KH = -(K @ H)
    n = I_KH.shape[-1]
    if I_KH.ndim == 2:
        I_KH.flat[:: n + 1] += 1.0  # I - K H
    else:
        diag = np.arange(n)
        I_KH[..., diag, diag] += 1.0
    Kt = np.swapaxes(K, -1, -2)
    P_post = I_KH @ P @ np.swapaxes(I_KH, -1, -2) + (R * (K @ Kt) if np.ndim(R) == 0 else K @ R @ Kt)
    if symmetric:  # made exactly symmetric, in place
        P_post += np.swapaxes(P_post, -1, -2)
        P_post *= 0.5
    return P_post


def joseph_rows_unchecked(P: Array, K: Array, H: Array, R: Array, rows: NDArray[np.intp] | slice) -> Array:
    """:func:`joseph_update` with ``rows``, in place on ``P``, not symmetrised, unchecked.

    The expanded form: ``M = -E K H P + E K (H P H' + R) K' E' / 2`` is added to the rows
    ``rows`` and its transpose to the columns (the symmetrisation the caller applies averages
    the two halves of ``E K S K' E'``).

    Parameters
    ----------
    P : (..., n, n) ndarray
        Float covariance of the caller's own, changed in place (not checked).
    K, H, R : ndarray
        As :func:`joseph_update` with ``rows`` (not checked).
    rows : (k,) ndarray of int
        The states the gain corrects.

    Returns
    -------
    ndarray
        ``P`` itself, updated.

    Examples
    --------
    >>> import numpy as np
    >>> P = np.eye(2)
    >>> joseph_rows_unchecked(P, np.array([[0.5]]), np.array([[1.0, 0.0]]), np.eye(1), np.array([0])).tolist()
    [[0.5, 0.0], [0.0, 1.0]]
    """
    HP = H @ P  # (..., m, n)
    M = K @ HP  # (..., k, n)
    M *= -1.0
    M[..., :, rows] += 0.5 * (K @ (HP @ np.swapaxes(H, -1, -2) + R) @ np.swapaxes(K, -1, -2))
    P[..., rows, :] += M
    P[..., :, rows] += np.swapaxes(M, -1, -2)
    return P


def _no_update(x: ArrayLike, P: ArrayLike) -> KalmanUpdate:
    """The update of an epoch without measurements: the prior, unchanged (copies)."""
    xa = np.array(x, dtype=float)
    Pa = np.array(P, dtype=float)
    n = xa.size
    return KalmanUpdate(xa, Pa, np.zeros((n, 0)), np.zeros(0), np.zeros((0, 0)))


def information_from_covariance(x: ArrayLike, P: ArrayLike) -> tuple[Array, Array]:
    """Return the information vector :math:`y = P^{-1} x` and matrix ``Y = P^-1``.

    Parameters
    ----------
    x : (n,) array
        State estimate (units of the state's layout).
    P : (n, n) array
        Its covariance (symmetric positive definite).

    Returns
    -------
    y : (n,) ndarray
        Information vector :math:`P^{-1} x`.
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
    """Return the state :math:`x = Y^{-1} y` and covariance ``P = Y^-1`` from information form.

    Parameters
    ----------
    y : (n,) array
        Information vector :math:`P^{-1} x` (units of the state divided by its variance).
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

    :math:`Y^+ = Y^- + H^T R^{-1} H` and :math:`y^+ = y^- + H^T R^{-1} z`. A zero information matrix
    (no prior knowledge) is allowed, which the covariance form cannot express.

    Parameters
    ----------
    y : (n,) array
        Prior information vector :math:`P^{-1} x`.
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
# kf_predict and kf_update check every argument in their bodies, once (checks_own_arguments).
check_public(globals(), joseph_update={"ranges": {"P": COVARIANCE_STACK, "R": COVARIANCE_STACK}})
