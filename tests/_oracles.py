"""Oracles shared by several test files, written independently of navcore."""

from __future__ import annotations

import numpy as np
import scipy.linalg


def van_loan_expm(F, Q, t):
    """Transition and noise covariance of x' = F x + w (PSD Q) over t by Van Loan's (1978)
    block exponential, with scipy's expm: the oracle for navcore's own discretisation."""
    F = np.asarray(F, dtype=float)
    n = F.shape[0]
    M = np.zeros((2 * n, 2 * n))
    M[:n, :n], M[:n, n:], M[n:, n:] = -F, Q, F.T
    E = scipy.linalg.expm(M * t)
    Phi = E[n:, n:].T
    return Phi, Phi @ E[:n, n:]


def irwin_hall_cdf_mpmath(n: int, x, dps: int | None = None):
    """P(U_1 + ... + U_n <= x) for i.i.d. U(0, 1) by the alternating sum
    sum_{j <= x} (-1)^j C(n, j) (x - j)^n / n! in mpmath (Hall 1927), at ``dps`` digits, or at the
    caller's working precision when ``dps`` is None; ``x`` (a float or an mpf) is taken exactly,
    so the sum's cancellation, at most ~n log10(n) digits, stays far below the working precision.
    The oracle for navcore's B-spline evaluation of the same law."""
    import mpmath

    with mpmath.workdps(dps if dps is not None else mpmath.mp.dps):
        xm = mpmath.mpf(x)
        if xm <= 0:
            return mpmath.mpf(0)
        if xm >= n:
            return mpmath.mpf(1)
        s = mpmath.fsum(
            (-1) ** j * mpmath.binomial(n, j) * (xm - j) ** n for j in range(int(mpmath.floor(xm)) + 1)
        )
        return s / mpmath.factorial(n)
