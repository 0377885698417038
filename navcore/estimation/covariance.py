r"""Linear covariance analysis over a schedule of measurement updates.

The optimal filter's covariance does not depend on the measurements' values, only on when
they arrive and with what geometry. Propagating

.. math::

    \begin{aligned}
    P^-_{k+1} &= \Phi_k P^+_k \Phi_k^T + Q_k,\\
    P^+_k &= (I - K_k H_k) P^-_k (I - K_k H_k)^T + K_k R_k K_k^T
    \end{aligned}

over a time grid with the measurements a schedule says are available is the covariance
analysis that the SP paper uses to compare architectures, and that the WF and ATC10
chapters use for their local filters and trackers.

A step with no measurement is a pure prediction; a measurement with infinite variance is
skipped (an outage). Schedules, and a time-varying ``Phi`` or ``Q``, are functions of the step
index ``k`` alone, as in :func:`navcore.integration.engine.run_covariance_analysis`
(the time is ``t[k]``).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import COVARIANCE, NONNEGATIVE, Covariance, check_public, require_square
from navcore.estimation.kalman import joseph_unchecked, symmetrize_unchecked

__all__ = ["CovarianceHistory", "Measurement", "biased_filter_error_covariance", "propagate_covariance"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Measurement:
    """A linear measurement ``z = H x + v`` with ``cov(v) = R``.

    Attributes
    ----------
    H : (m, n) ndarray
        Measurement matrix (measurement units per state unit).
    R : (m, m) ndarray
        Measurement-noise covariance (measurement units squared); an infinite diagonal
        entry marks an outage.
    """

    H: Array
    R: Array

    def __post_init__(self) -> None:
        shape_h, shape_r = np.shape(self.H), np.shape(self.R)
        m = 1 if len(shape_h) == 1 else shape_h[0]  # a single row may be given as a vector
        if len(shape_h) > 2 or shape_r != (m, m):
            raise ValueError(
                f"Measurement.R must be (m, m) for H of shape (m, n), got H {shape_h} and R {shape_r}"
            )

    @classmethod
    def _unchecked(cls, H: Array, R: Array) -> Measurement:
        """A measurement built by the library's own schedules, which run every step and whose
        ``R`` is a covariance by construction (from noise levels checked where the schedule
        was made): no check here. Not for users: the constructor checks ``R``."""
        m = object.__new__(cls)
        object.__setattr__(m, "H", H)
        object.__setattr__(m, "R", R)
        return m

    @classmethod
    def scalar(cls, h: ArrayLike, r: float) -> Measurement:
        """A scalar measurement with row ``h`` and variance ``r`` (``>= 0``, ``inf`` for an outage)."""
        if not r >= 0:
            raise ValueError(f"r must be a variance >= 0, got {r!r}")
        return cls(np.atleast_2d(np.asarray(h, dtype=float)), np.array([[float(r)]]))


@dataclass(frozen=True)
class CovarianceHistory:
    """Covariances over a time grid.

    Attributes
    ----------
    t : (N+1,) array
        Times; ``t[0]`` is the initial time.
    prior : (N+1, n, n) array
        Covariance before the updates at each time (``prior[0] = P0``).
    posterior : (N+1, n, n) array
        Covariance after the updates at each time.
    n_updates : (N+1,) int array
        Number of measurement updates applied at each time.
    """

    t: Array
    prior: Array
    posterior: Array
    n_updates: NDArray[np.int64]

    def sigma(self, index: int | slice | Sequence[int], *, posterior: bool = True) -> Array:
        r"""1-:math:`\sigma` of state(s) ``index`` over time (square root of the diagonal)."""
        P = self.posterior if posterior else self.prior
        diag = np.diagonal(P, axis1=1, axis2=2)[:, index]
        return np.sqrt(np.clip(diag, 0.0, None))

    def rss(self, indices: Sequence[int] | slice, *, posterior: bool = True) -> Array:
        r"""Root-sum-square 1-:math:`\sigma` of several states (e.g. horizontal position)."""
        P = self.posterior if posterior else self.prior
        diag = np.diagonal(P, axis1=1, axis2=2)[:, indices]
        return np.sqrt(np.clip(diag.sum(axis=1), 0.0, None))


MatrixOrFunc = ArrayLike | Callable[[int], ArrayLike]


def _at(value: MatrixOrFunc, k: int) -> Array:
    return np.asarray(value(k) if callable(value) else value, dtype=float)


def _model_matrix(name: str, value: ArrayLike, n: int, k: int | None = None) -> Array:
    """A transition or noise matrix as a finite float (n, n) array (``k``: the step that gave it)."""
    arr = np.asarray(value, dtype=float)
    where = "" if k is None else f" at step {k}"
    if arr.shape != (n, n):
        raise ValueError(f"{name}{where} must have shape ({n}, {n}), got {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name}{where} must be finite (no NaN or infinity)")
    return arr


def propagate_covariance(
    P0: ArrayLike,
    t: ArrayLike,
    Phi: MatrixOrFunc,
    Q: MatrixOrFunc,
    schedule: Callable[[int], Sequence[Measurement]] | None = None,
) -> CovarianceHistory:
    """Propagate a covariance over the grid ``t`` with scheduled measurement updates.

    Parameters
    ----------
    P0 : (n, n) array
        Initial covariance at ``t[0]`` (before any update at ``t[0]``).
    t : (N+1,) array
        Strictly increasing times.
    Phi, Q : (n, n) array or callable ``k -> array``
        Transition and process-noise covariance (symmetric positive semi-definite) from
        ``t[k-1]`` to ``t[k]`` (called for ``k = 1..N``; a callable ``Q`` is checked at
        ``k = 1``).
    schedule : callable ``k -> sequence of Measurement``, optional
        Measurements available at ``t[k]`` (``k = 0..N``), processed sequentially. A
        measurement whose ``R`` has an infinite diagonal entry is skipped (outage). The
        signature is that of the schedules of
        :func:`navcore.integration.engine.run_covariance_analysis`.

    Returns
    -------
    CovarianceHistory
        Times (s), prior and posterior covariances and update counts at every grid point.

    Raises
    ------
    ValueError
        If ``P0`` or ``Q`` is not a covariance (square, symmetric positive semi-definite),
        ``t`` not strictly increasing, or a matrix has the wrong shape.

    Notes
    -----
    The covariance recursion of the Kalman filter (Maybeck 1979, Ch. 5) with the
    Joseph-form update.

    Examples
    --------
    A random walk (unit variance per step) measured every step with unit noise:

    >>> import numpy as np
    >>> meas = [Measurement(np.eye(1), np.eye(1))]
    >>> hist = propagate_covariance(np.eye(1), np.arange(50.0), np.eye(1), np.eye(1), lambda k: meas)
    >>> round(float(hist.posterior[-1, 0, 0]), 4), round(float(hist.prior[-1, 0, 0]), 4)
    (0.618, 1.618)
    """
    P = require_square("P0", P0)
    COVARIANCE.check("P0", P)
    if not callable(Q):
        COVARIANCE.check("Q", Q)
    t = np.asarray(t, dtype=float)
    if t.ndim != 1 or t.size < 1 or np.any(np.diff(t) <= 0):
        raise ValueError("t must be a 1-D array of strictly increasing times")
    n = P.shape[0]
    N = t.size
    prior = np.empty((N, n, n))
    post = np.empty((N, n, n))
    counts = np.zeros(N, dtype=np.int64)
    # a constant transition or noise is checked once here; a callable's matrices at each step
    fixed_F = None if callable(Phi) else _model_matrix("Phi", Phi, n)
    fixed_Q = None if callable(Q) else _model_matrix("Q", Q, n)
    for k in range(N):
        if k > 0:
            F = fixed_F if fixed_F is not None else _model_matrix("Phi", _at(Phi, k), n, k)
            Qk = fixed_Q if fixed_Q is not None else _model_matrix("Q", _at(Q, k), n, k)
            if k == 1 and fixed_Q is None:
                COVARIANCE.check("Q(1)", Qk)  # a callable Q: its first matrix
            P = symmetrize_unchecked(F @ P @ F.T + Qk)  # P- = Phi P Phi' + Q
        prior[k] = P
        if schedule is not None:
            for meas in schedule(k):
                H = np.atleast_2d(meas.H)
                R = np.atleast_2d(meas.R)
                if H.shape[1] != n or R.shape != (H.shape[0], H.shape[0]):
                    raise ValueError(
                        f"measurement at t={t[k]} must have H of shape (m, {n}) and R (m, m); "
                        f"got {H.shape} and {R.shape}"
                    )
                if np.any(np.isinf(np.diag(R))):
                    continue  # outage: infinite variance carries no information
                S = H @ P @ H.T + R
                K = np.asarray(np.linalg.solve(S, H @ P).T, dtype=float)  # K = P H' S^-1
                P = joseph_unchecked(P, K, H, R)
                counts[k] += 1
        post[k] = P
    return CovarianceHistory(t, prior, post, counts)


def biased_filter_error_covariance(
    Phi: ArrayLike, Q: ArrayLike, P0: ArrayLike, h: ArrayLike, sigma: ArrayLike, bias_sigma: float
) -> Array:
    r"""Covariance of the true error of a filter that ignores a constant bias of its measurements.

    A Kalman filter of the model :math:`x_{k+1} = \Phi x_k + w_k` (``cov(w) = Q``) processes
    scalar measurements :math:`z_k = h^T x_k + b + v_k` with :math:`\mathrm{var}(v_k) =
    \sigma_k^2`, as if there were no bias :math:`b` (a random constant of standard deviation
    ``bias_sigma``). Its gains follow its own covariance recursion (prediction, then the
    update at each step that has a measurement); the true error :math:`e = x - \hat x` and the
    bias obey

    .. math::

        \begin{bmatrix} e \\ b \end{bmatrix}^+ =
        \begin{bmatrix} I - K h^T & -K \\ 0 & 1 \end{bmatrix}
        \begin{bmatrix} \Phi e + w \\ b \end{bmatrix} - \begin{bmatrix} K \\ 0 \end{bmatrix} v,

    whose covariance is propagated exactly: a Joseph-form update
    (:func:`navcore.estimation.kalman.joseph_update`) with the augmented gain and row
    :math:`[h^T, 1]`. Several sequences of measurement noise (rows of ``sigma``) are
    propagated together.

    Parameters
    ----------
    Phi : (n, n) array
        Transition over one step (the filter's and the truth's).
    Q : (n, n) array
        Process-noise covariance over one step (symmetric positive semi-definite).
    P0 : (n, n) array
        Initial covariance of the error, the filter's and the truth's (symmetric positive
        semi-definite).
    h : (n,) array
        Measurement row.
    sigma : (N,) or (B, N) array
        Standard deviation of the measurement noise at each step (measurement units);
        ``NaN`` where a step has no measurement.
    bias_sigma : float
        Standard deviation of the unmodelled constant bias (measurement units).

    Returns
    -------
    (B, n + 1, n + 1) ndarray
        Covariance of the true error and the bias after the last step, per row of ``sigma``
        (``B = 1`` for a 1-D ``sigma``); the bias is the last state. Symmetric up to round-off.

    Raises
    ------
    ValueError
        If the shapes do not match, a covariance is not symmetric positive semi-definite, or
        an input is not finite (``sigma`` may hold ``NaN``).

    Notes
    -----
    The sensitivity analysis of a suboptimal filter (Gelb 1974, Sec. 7.2): the truth model
    is the filter's model plus one unmodelled state. With ``bias_sigma = 0`` the true error
    covariance equals the filter's own (the optimal filter).

    Examples
    --------
    A random constant measured twice with unit noise, plus a bias of unit standard deviation
    the filter does not know (its own variance would be 1/3):

    >>> import numpy as np
    >>> C = biased_filter_error_covariance(np.eye(1), np.zeros((1, 1)), np.eye(1), [1.0], [1.0, 1.0], 1.0)
    >>> np.round(C[0], 6).tolist()
    [[0.777778, -0.666667], [-0.666667, 1.0]]
    """
    Phi = require_square("Phi", Phi)
    n = Phi.shape[0]
    Q = require_square("Q", Q, n)
    P0 = require_square("P0", P0, n)
    COVARIANCE.check("Q", Q)
    COVARIANCE.check("P0", P0)
    h = np.asarray(h, dtype=float)
    if h.shape != (n,):
        raise ValueError(f"h must have shape ({n},), got {h.shape}")
    sig = np.atleast_2d(np.asarray(sigma, dtype=float))
    if sig.ndim != 2 or np.isinf(sig).any() or (sig < 0).any():
        raise ValueError("sigma must be a (N,) or (B, N) array of standard deviations >= 0 or NaN")
    nb, nt = sig.shape
    P = np.broadcast_to(P0, (nb, n, n)).copy()  # the filter's covariance
    C = np.zeros((nb, n + 1, n + 1))  # the true error's and the bias's
    C[:, :n, :n] = P0
    C[:, n, n] = float(bias_sigma) ** 2
    A = np.eye(n + 1)
    A[:n, :n] = Phi
    Qa = np.zeros((n + 1, n + 1))
    Qa[:n, :n] = Q
    H = h[None, :]
    Ha = np.append(h, 1.0)[None, :]  # the measurement of the error and the bias
    for k in range(nt):
        P = Phi @ P @ Phi.T + Q
        C = A @ C @ A.T + Qa
        measured = np.isfinite(sig[:, k])
        if not measured.any():
            continue
        r = np.where(measured, sig[:, k], 0.0) ** 2
        Ph = P @ h  # (B, n)
        K = Ph / (Ph @ h + r)[:, None]
        K = np.where(measured[:, None], K, 0.0)[:, :, None]  # (B, n, 1); no update without one
        R = r[:, None, None]
        P = joseph_unchecked(P, K, H, R, symmetric=False)
        Ka = np.zeros((nb, n + 1, 1))
        Ka[:, :n] = K
        C = joseph_unchecked(C, Ka, Ha, R, symmetric=False)
    return C


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {"bias_sigma": NONNEGATIVE},
    biased_filter_error_covariance={"allow_inf": ("sigma",), "skip": ("sigma",)},
    Measurement={"allow_inf": ("R",), "ranges": {"R": Covariance(allow_inf_diagonal=True)}},
)
