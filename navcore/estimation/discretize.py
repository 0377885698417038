r"""Discretisation of a continuous linear stochastic model (Van Loan's method).

For :math:`\dot x = F x + G w` with white noise of PSD :math:`Q_c`, the transition over
:math:`\Delta t` and the discrete process-noise covariance are

.. math::

    \Phi = e^{F\Delta t},\qquad
    Q_d = \int_0^{\Delta t} e^{F s} G Q_c G^T e^{F^T s}\, ds.

Van Loan computes both from one matrix exponential:

.. math::

    \exp\!\left(\begin{bmatrix} -F & G Q_c G^T \\ 0 & F^T \end{bmatrix}\Delta t\right)
    = \begin{bmatrix} \cdot & \Phi^{-1} Q_d \\ 0 & \Phi^T \end{bmatrix}.

References
----------
.. [1] C. F. Van Loan, "Computing Integrals Involving the Matrix Exponential",
   IEEE Trans. Automatic Control 23(3), 395-404 (1978).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    NONNEGATIVE,
    check_public,
    require_positive,
    require_square,
    require_symmetric_psd,
)
from navcore.estimation.kalman import symmetrize

__all__ = ["first_order_transition", "van_loan"]


def van_loan(F: ArrayLike, GQGt: ArrayLike, dt: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Exact discrete transition and process-noise covariance of a linear model.

    Parameters
    ----------
    F : (n, n) array
        Continuous dynamics matrix.
    GQGt : (n, n) array
        :math:`G Q_c G^T`, the state-space noise PSD (symmetric PSD).
    dt : float
        Step, ``dt > 0``.

    Returns
    -------
    Phi, Qd : arrays
        ``e^{F dt}`` and the (exactly symmetric) discrete covariance.

    Raises
    ------
    ValueError
        If ``F`` or ``GQGt`` is not square of the same size, ``GQGt`` is not symmetric
        positive semi-definite, or ``dt`` is not positive.

    Examples
    --------
    A double integrator driven by white acceleration of PSD ``q`` gives
    ``Qd = q [[dt^3/3, dt^2/2], [dt^2/2, dt]]``:

    >>> Phi, Qd = van_loan([[0, 1], [0, 0]], [[0, 0], [0, 2.0]], 0.5)
    >>> np.allclose(Qd, 2.0 * np.array([[0.5**3 / 3, 0.5**2 / 2], [0.5**2 / 2, 0.5]]))
    True
    """
    F = require_square("F", F)
    n = F.shape[0]
    GQGt = require_square("GQGt", GQGt, n)
    require_symmetric_psd("GQGt", GQGt)
    require_positive("dt", dt)
    M = np.zeros((2 * n, 2 * n))
    M[:n, :n] = -F
    M[:n, n:] = GQGt
    M[n:, n:] = F.T
    E = scipy.linalg.expm(M * dt)
    Phi = E[n:, n:].T
    Qd = Phi @ E[:n, n:]
    return Phi, symmetrize(Qd)


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


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals(), {"dt": NONNEGATIVE})
