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
