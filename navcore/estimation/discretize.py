r"""Discretisation of a continuous linear stochastic model: one discretiser, three methods.

For :math:`\dot x = F x + G w` with white noise of PSD :math:`Q_c`, the transition over
:math:`\Delta t` and the discrete process-noise covariance are

.. math::

    \Phi = e^{F\Delta t},\qquad
    Q_d = \int_0^{\Delta t} e^{F s} G Q_c G^T e^{F^T s}\, ds.

:func:`discretize` computes both, batched over leading axes, by one of three methods:

``"van_loan"``
    Van Loan's single matrix exponential, exact for any ``F``:

    .. math::

        \exp\!\left(\begin{bmatrix} -F & G Q_c G^T \\ 0 & F^T \end{bmatrix}\Delta t\right)
        = \begin{bmatrix} \cdot & \Phi^{-1} Q_d \\ 0 & \Phi^T \end{bmatrix}.

``"nilpotent"``
    For :math:`F^4 = 0` (the INS error chains gyro bias -> attitude -> velocity -> position):
    :math:`e^{Fs}` is the cubic :math:`I + Fs + (Fs)^2/2 + (Fs)^3/6`, the integrand a polynomial
    of degree 6 in ``s``, and the four-node Gauss-Legendre rule integrates it exactly.

``"series"``
    The transition :math:`\sum_{j \le 4} (F\Delta t)^j / j!` (:func:`taylor_transition`) and the
    noise integral by three-node Gauss-Legendre quadrature over that series: exact to
    :math:`(\|F\| \Delta t)^6` relative, the discretisation of the covariance engine, which
    relinearises often. For a stack of models whose random constants leave rows of ``F`` zero
    and a batch of diagonal noises, ``discretize_unchecked(..., diagonal=True, sparse=True)``
    computes the same series and quadrature on the rows that move and the columns that are
    driven only (the covariance engine's path, :mod:`navcore.integration.engine`).

:func:`first_order_transition` and :func:`taylor_transition` give the transition alone.

References
----------
.. [1] C. F. Van Loan, "Computing Integrals Involving the Matrix Exponential",
   IEEE Trans. Automatic Control 23(3), 395-404 (1978).
.. [2] P. S. Maybeck, Stochastic Models, Estimation, and Control, Vol. 1 (1979), Ch. 4.
"""

from __future__ import annotations

from typing import Literal

import numpy as np
import scipy.linalg
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    COVARIANCE_STACK,
    NONNEGATIVE,
    as_finite_array,
    check_public,
    require_positive,
    require_square,
)
from navcore.estimation.kalman import symmetrize_unchecked

__all__ = ["discretize", "first_order_transition", "taylor_transition"]

Array = NDArray[np.float64]

#: Gauss-Legendre nodes and weights on [-1, 1]: three for the series method, four for the
#: nilpotent one (exact for its degree-6 integrand).
_GAUSS3 = np.polynomial.legendre.leggauss(3)
_GAUSS4 = np.polynomial.legendre.leggauss(4)


def discretize(
    F: ArrayLike,
    GQGt: ArrayLike,
    dt: float,
    *,
    method: Literal["van_loan", "nilpotent", "series"] = "van_loan",
) -> tuple[Array, Array]:
    """Discrete transition and process-noise covariance of a linear model, batched.

    Parameters
    ----------
    F : (..., n, n) array
        Continuous dynamics matrix, 1/s (per the state's layout), or a stack of them.
    GQGt : (..., n, n) array
        :math:`G Q_c G^T`, the state-space noise PSD (state unit squared per second;
        symmetric positive semi-definite), or a stack of them; broadcast against ``F``.
    dt : float
        Step, s (``dt > 0``).
    method : {"van_loan", "nilpotent", "series"}, default "van_loan"
        ``"van_loan"``: the matrix exponential, exact for any ``F``; ``"nilpotent"``: the
        cubic transition and four-node quadrature, exact when :math:`F^4 = 0` (and only then);
        ``"series"``: the order-4 series and three-node quadrature (see the module docstring).

    Returns
    -------
    Phi : (..., n, n) ndarray
        Transition over ``dt``.
    Qd : (..., n, n) ndarray
        Discrete process-noise covariance over ``dt``, exactly symmetric.

    Raises
    ------
    ValueError
        If ``F`` or ``GQGt`` is not square of the same size, ``GQGt`` is not symmetric
        positive semi-definite, ``dt`` is not positive, or ``method`` is unknown.

    Notes
    -----
    Van Loan (1978), reference 1 of the module, and the quadratures of Maybeck (1979), Ch. 4,
    reference 2. The three methods agree to round-off for a nilpotent ``F`` of index 4 or less;
    each caller keeps its method, whose numbers it was validated with.

    Examples
    --------
    A double integrator driven by white acceleration of PSD ``q`` gives
    ``Qd = q [[dt^3/3, dt^2/2], [dt^2/2, dt]]`` by every method:

    >>> import numpy as np
    >>> exact = 2.0 * np.array([[0.5**3 / 3, 0.5**2 / 2], [0.5**2 / 2, 0.5]])
    >>> F, S = [[0.0, 1.0], [0.0, 0.0]], [[0.0, 0.0], [0.0, 2.0]]
    >>> methods = ("van_loan", "nilpotent", "series")
    >>> [bool(np.allclose(discretize(F, S, 0.5, method=m)[1], exact)) for m in methods]
    [True, True, True]
    >>> discretize(np.zeros((4, 3, 3)), np.eye(3), 1.0)[1].shape  # a stack of four models
    (4, 3, 3)
    """
    F = as_finite_array("F", F)
    if F.ndim < 2 or F.shape[-1] != F.shape[-2]:
        raise ValueError(f"F must be a square matrix or a stack of them, got shape {F.shape}")
    n = F.shape[-1]
    S = as_finite_array("GQGt", GQGt)
    if S.ndim < 2 or S.shape[-2:] != (n, n):
        raise ValueError(f"GQGt must be {n}x{n}, got shape {S.shape}")
    COVARIANCE_STACK.check("GQGt", S)
    require_positive("dt", dt)
    if method not in ("van_loan", "nilpotent", "series"):
        raise ValueError(f"method must be 'van_loan', 'nilpotent' or 'series', got {method!r}")
    return discretize_unchecked(F, S, dt, method=method)


def discretize_unchecked(
    F: Array,
    GQGt: Array,
    dt: float,
    *,
    method: Literal["van_loan", "nilpotent", "series"] = "van_loan",
    diagonal: bool = False,
    sparse: bool = False,
    order: int = 4,
) -> tuple[Array, Array]:
    """:func:`discretize` without the argument checks, for a loop over float arrays checked once.

    Parameters
    ----------
    F : (..., n, n) ndarray
        Float dynamics (not checked).
    GQGt : (..., n, n) ndarray, or (..., n) with ``diagonal``
        Float noise PSD (not checked); with ``diagonal``, the diagonals of diagonal PSDs.
    dt : float
        Step, s (``> 0``, not checked).
    method : {"van_loan", "nilpotent", "series"}, default "van_loan"
        As :func:`discretize`.
    diagonal : bool, default False
        ``GQGt`` holds diagonals: ``Phi S`` is formed as ``Phi * q``, the same numbers as the
        product with ``diag(q)`` at a fraction of its cost (``"nilpotent"`` and ``"series"``).
    sparse : bool, default False
        With ``method="series"`` and ``diagonal`` only: transform only the rows of ``F`` that
        are not zero in some member of the stack (a zero row, a random constant's, is a unit
        row of ``Phi``) and, for the noise, only the driven columns of ``Phi(s)``, the three
        nodes' products summed as one product over their stacked columns. The same series and
        quadrature, summed in another order: equal to the dense form to round-off, and
        exactly where both are exact (the unit rows, the zeros of undriven states).
    order : int, default 4
        With ``method="series"``: the highest power of the transition series (of the
        transition and of the quadrature's nodes).

    Returns
    -------
    Phi, Qd : ndarray
        As :func:`discretize`: ``Phi`` has the shape of ``F``, ``Qd`` the broadcast shape of
        ``F`` and ``GQGt``.

    Raises
    ------
    ValueError
        If ``sparse`` is asked for another method than ``"series"`` or without ``diagonal``.

    Examples
    --------
    >>> import numpy as np
    >>> F = np.array([[0.0, 1.0], [0.0, 0.0]])
    >>> full = discretize_unchecked(F, np.diag([0.0, 2.0]), 0.5, method="nilpotent")[1]
    >>> diag = discretize_unchecked(F, np.array([0.0, 2.0]), 0.5, method="nilpotent", diagonal=True)[1]
    >>> bool((diag == full).all())
    True

    A stack of two models ``(2, 1, n, n)``, each driven by three diagonal noises ``(2, 3, n)``,
    in the row-sparse form (the last state a random constant, the first undriven):

    >>> F = np.zeros((2, 1, 3, 3)); F[:, 0, 0, 1] = 1.0; F[1, 0, 1, 0] = -0.1
    >>> q = np.zeros((2, 3, 3)); q[:, :, 1] = [1.0, 2.0, 3.0]
    >>> Phi, Qd = discretize_unchecked(F, q, 0.5, method="series", diagonal=True, sparse=True)
    >>> Phi.shape, Qd.shape
    ((2, 1, 3, 3), (2, 3, 3, 3))
    >>> dense = discretize_unchecked(F, q, 0.5, method="series", diagonal=True)[1]
    >>> bool(np.allclose(Qd, dense, rtol=1e-14, atol=0.0))
    True
    """
    if sparse:
        if method != "series" or not diagonal:
            raise ValueError("sparse applies to method='series' with diagonal noise")
        return _series_sparse(F, GQGt, dt, order)
    S = GQGt
    if diagonal:
        if method == "van_loan":
            S = S[..., :, None] * np.eye(F.shape[-1])
        else:
            S = S[..., None, :]  # Phi * q scales the columns: Phi @ diag(q), exactly
    if method == "van_loan":
        return _van_loan(F, S, dt)
    if method == "nilpotent":
        return _nilpotent(F, S, dt, diagonal)
    return _taylor(F, dt, order), _series_noise(F, S, dt, diagonal, order)


def _van_loan(F: Array, S: Array, dt: float) -> tuple[Array, Array]:
    """Van Loan's block exponential (batched; a 2-D model gives one ``expm`` of ``2n x 2n``)."""
    n = F.shape[-1]
    M = np.zeros((*np.broadcast_shapes(F.shape[:-2], S.shape[:-2]), 2 * n, 2 * n))
    M[..., :n, :n] = -F
    M[..., :n, n:] = S
    M[..., n:, n:] = np.swapaxes(F, -1, -2)
    E = scipy.linalg.expm(M * dt)
    Phi = np.swapaxes(E[..., n:, n:], -1, -2)
    Qd = Phi @ E[..., :n, n:]
    return Phi, symmetrize_unchecked(Qd)


def _nilpotent(F: Array, S: Array, dt: float, diagonal: bool) -> tuple[Array, Array]:
    """The cubic transition and the four-node quadrature of its noise integral (batched), with
    the powers of ``F`` formed once for the transition and the nodes."""
    F2 = F @ F
    F3 = F2 @ F
    eye = np.eye(F.shape[-1])

    def phi(s: float) -> Array:
        return eye + F * s + F2 * (s * s / 2.0) + F3 * (s * s * s / 6.0)

    nodes, weights = _GAUSS4
    Qd = np.zeros_like(F)
    for s, w in zip(0.5 * dt * (nodes + 1.0), 0.5 * dt * weights, strict=True):
        P_s = phi(s)  # the nodes are interior: s > 0
        Qd = Qd + w * (P_s * S if diagonal else P_s @ S) @ np.swapaxes(P_s, -1, -2)
    return phi(dt), symmetrize_unchecked(Qd)


def _series_noise(F: Array, S: Array, dt: float, diagonal: bool = False, order: int = 4) -> Array:
    """The three-node quadrature of the noise integral over the series of ``order`` (batched)."""
    x, w = _GAUSS3
    Q: Array | float = 0.0
    for xi, wi in zip(x, w, strict=True):
        P = _taylor(F, 0.5 * dt * (xi + 1.0), order)
        Q = Q + (0.5 * dt * wi) * ((P * S if diagonal else P @ S) @ np.swapaxes(P, -1, -2))
    Q = np.asarray(Q)
    return 0.5 * (Q + np.swapaxes(Q, -1, -2))


def _series_sparse(F: Array, q: Array, dt: float, order: int) -> tuple[Array, Array]:
    """The series method for diagonal noises ``q`` ``(..., n)``, computed on the rows of ``F``
    that are not zero in some member of the stack (``sparse`` of :func:`discretize_unchecked`):
    ``Phi`` of the shape of ``F``, ``Qd`` of the broadcast shape of ``F`` and ``q``."""
    n = F.shape[-1]
    dyn = np.flatnonzero(np.any(F.reshape(-1, n, n) != 0.0, axis=(0, 2)))
    Phi = np.zeros(F.shape)
    Phi[..., np.arange(n), np.arange(n)] = 1.0
    Phi[..., dyn, :] = _series_rows(F, dt, dyn, order)
    return Phi, _series_noise_sparse(F, q, dt, dyn, order)


def _series_rows(F: Array, dt: float, dyn: NDArray[np.intp], order: int) -> Array:
    """The rows ``dyn`` of :func:`_taylor` of a stack ``(..., n, n)`` whose other rows are zero
    in every member (a zero row of ``F``, a random constant's, is a unit row of ``Phi``):
    ``(..., d, n)``.

    With ``F = [[a, b], [0, 0]]`` (dynamic rows first) the Horner step
    ``Phi <- I + F dt Phi / j`` keeps ``Phi = [[x, y], [0, I]]`` and updates
    ``[x, y] <- [I, 0] + (a dt [x, y] + [0, b dt]) / j``.
    """
    n = F.shape[-1]
    A = F[..., dyn, :] * dt  # (..., d, n)
    A_dd = A[..., :, dyn]
    A_ds = A.copy()
    A_ds[..., :, dyn] = 0.0  # the columns of the static states
    rows = np.eye(n)[dyn]
    X = rows
    for j in range(order, 0, -1):
        X = rows + (A_dd @ X + A_ds) / j
    return X


def _series_noise_sparse(F: Array, q: Array, dt: float, dyn: NDArray[np.intp], order: int) -> Array:
    """:func:`_series_noise` of the systems ``F`` ``(..., n, n)`` driven by the diagonal PSDs
    ``diag(q)`` (``q``: ``(..., n)``), computed where it can differ from zero, given the rows
    ``dyn`` of ``F`` that are not zero in some member.

    ``P S = P * q`` for a diagonal ``S``, exactly; ``Phi(s) S Phi(s)^T`` reads only the driven
    columns of ``Phi(s)``, which are zero outside the dynamic rows and the driven states' own
    unit entries; the three nodes' products are one product over their stacked columns.
    """
    x, w = _GAUSS3
    n = F.shape[-1]
    Q = np.zeros((*np.broadcast_shapes(F.shape[:-2], q.shape[:-1]), n, n))
    driven = np.flatnonzero(np.any(q.reshape(-1, n) != 0.0, axis=0))  # only these columns of S are not 0
    if driven.size == 0:
        return Q
    rows = np.union1d(dyn, driven)  # the rows of Phi(s)[..., driven] that can be non-zero
    at_dyn = np.searchsorted(rows, dyn)
    static_driven = np.setdiff1d(driven, dyn)
    cols, parts = [], []
    for xi, wi in zip(x, w, strict=True):
        part = np.zeros((*F.shape[:-2], rows.size, driven.size))
        part[..., at_dyn, :] = _series_rows(F, 0.5 * dt * (xi + 1.0), dyn, order)[..., driven]
        # a driven random constant or random walk keeps its unit row
        part[..., np.searchsorted(rows, static_driven), np.searchsorted(driven, static_driven)] = 1.0
        parts.append(part)
        cols.append((0.5 * dt * wi) * q[..., None, driven])
    P = np.concatenate(parts, axis=-1)  # (..., r, 3 d)
    Qr = (P * np.concatenate(cols, axis=-1)) @ np.swapaxes(P, -1, -2)  # (..., r, r)
    Q[..., rows[:, None], rows] = 0.5 * (Qr + np.swapaxes(Qr, -1, -2))
    return Q


def first_order_transition(F: ArrayLike, dt: float) -> NDArray[np.float64]:
    r"""The first-order approximation :math:`\Phi = I + F \Delta t` of ``e^{F dt}``.

    Parameters
    ----------
    F : (n, n) array
        Continuous-time system matrix (1/s, per the state's layout).
    dt : float
        Step, s (``dt > 0``).

    Returns
    -------
    (n, n) ndarray
        Approximate state-transition matrix over ``dt``.

    Raises
    ------
    ValueError
        If ``F`` is not square and finite or ``dt`` is not positive.

    Notes
    -----
    The truncated series of the matrix exponential (Maybeck 1979, Ch. 4); adequate when
    ``||F|| dt`` is small, as for an INS error model over a filter step.

    Examples
    --------
    >>> first_order_transition([[0.0, 1.0], [0.0, 0.0]], 0.5)
    array([[1. , 0.5],
           [0. , 1. ]])
    """
    F = require_square("F", F)
    require_positive("dt", dt)
    return np.eye(F.shape[0]) + F * dt


def taylor_transition(F: ArrayLike, dt: float, order: int = 4) -> Array:
    r"""Transition :math:`\sum_{j \le \mathrm{order}} (F \Delta t)^j / j!` (Horner form).

    Parameters
    ----------
    F : (n, n) array
        Continuous-time system matrix, 1/s.
    dt : float
        Step, s.
    order : int, default 4
        Highest power kept (4 is exact for the nilpotent INS error chains).

    Returns
    -------
    (n, n) ndarray
        Truncated series of :math:`e^{F\,dt}`.

    Notes
    -----
    The transition of :func:`discretize` with ``method="series"`` (Maybeck 1979, Ch. 4,
    reference 2 of the module).

    Examples
    --------
    >>> taylor_transition([[0.0, 1.0], [0.0, 0.0]], 2.0).tolist()
    [[1.0, 2.0], [0.0, 1.0]]
    """
    return _taylor(np.asarray(F, dtype=float), dt, order)


def _taylor(F: Array, dt: float, order: int = 4) -> Array:
    """:func:`taylor_transition` without the argument checks (also of a stack ``(..., n, n)``)."""
    A = F * dt
    eye = np.eye(A.shape[-1])
    Phi = eye
    for j in range(order, 0, -1):
        Phi = eye + (A @ Phi) / j
    return Phi


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals(), {"dt": NONNEGATIVE, "order": COUNT})
