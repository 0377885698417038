r"""Linear minimum-mean-square-error estimation with a nonrandom nuisance vector.

Observation model (ATC-10 Appendix H, Eq. H.1):

.. math::

    z = F x + G y + n,

with :math:`x` random (mean :math:`\mu_x`, covariance :math:`P_x`), :math:`y` nonrandom and
completely unknown, and noise :math:`n` (mean :math:`\mu_n`, covariance :math:`P_n`,
cross-covariance :math:`P_{nx}` with :math:`x`). The estimator of :math:`y` is generalised
least squares with the "noise" :math:`\epsilon = n + F x` (Eqs. H.4-H.8); the estimator of
:math:`x` is the LMMSE estimator among linear functions of :math:`z` that do not depend on
:math:`y`, i.e. that annihilate the columns of :math:`G` (Eqs. H.9-H.16). With
:math:`P_{nx} = 0` the covariances take the information forms (H.21)-(H.22). For a scalar
:math:`x` and white noise the gain is

.. math::

    \gamma = \frac{\sigma_x^2}{\sigma^2 + \sigma_x^2 F'(I - P_G) F}

(Eq. H.26; the printed numerator :math:`\sigma^2` is erratum E4-10).

In ATC-10 Section 4 :math:`x` is the clock error :math:`\tau_n` (:math:`F = 1`) and
:math:`y` the aircraft position (:math:`G` = the satellite matrix).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from navcore._validate import (
    COVARIANCE,
    NONNEGATIVE,
    POSITIVE,
    as_finite_array,
    check_public,
    require_positive,
)
from navcore.estimation.kalman import symmetrize
from navcore.trace import implements

__all__ = [
    "NuisanceLMMSE",
    "lmmse_with_nuisance",
    "lmmse_with_nuisance_information_form",
    "scalar_nuisance_gain",
]


@dataclass(frozen=True)
class NuisanceLMMSE:
    r"""Gains and error covariances of the joint estimator (ATC-10 App. H).

    ``x_hat = H (z - mu_eps) + mu_x`` and ``y_hat = K (z - mu_eps)`` with
    :math:`\mu_\epsilon = \mu_n + F \mu_x`. ``P_x_err`` is (H.16) and ``P_y_err`` is (H.8).

    Attributes
    ----------
    H : (p, r) ndarray
        Gain of the estimator of x (Eq. H.15).
    K : (q, r) ndarray
        Gain of the estimator of y (Eq. H.6).
    P_x_err : (p, p) ndarray
        Error covariance of x (Eq. H.16).
    P_y_err : (q, q) ndarray
        Error covariance of y (Eq. H.8).
    mu_eps : (r,) ndarray
        Mean of ``n + F x``.
    mu_x : (p,) ndarray
        Prior mean of x.
    """

    H: np.ndarray
    K: np.ndarray
    P_x_err: np.ndarray
    P_y_err: np.ndarray
    mu_eps: np.ndarray
    mu_x: np.ndarray

    def estimate(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Return ``(x_hat, y_hat)`` for observation(s) z (shape r or n x r)."""
        d = np.asarray(z, dtype=float) - self.mu_eps
        return d @ self.H.T + self.mu_x, d @ self.K.T


@implements("ATC10 H.5", "ATC10 H.6", "ATC10 H.7", "ATC10 H.8")
def lmmse_with_nuisance(
    F: np.ndarray,
    G: np.ndarray,
    mu_x: np.ndarray,
    P_x: np.ndarray,
    mu_n: np.ndarray,
    P_n: np.ndarray,
    P_xn: np.ndarray | None = None,
) -> NuisanceLMMSE:
    r"""Joint estimator of random x and nonrandom y (ATC-10 Eqs. H.5-H.8, H.14-H.16).

    Parameters
    ----------
    F : (r, p) array
        Observation matrix of the random vector x (units of z per unit of x).
    G : (r, q) array
        Observation matrix of the nonrandom vector y; must have full column rank q (H.3).
    mu_x : (p,) array
        Prior mean of x.
    P_x : (p, p) array
        Prior covariance of x.
    mu_n : (r,) array
        Noise mean (units of z).
    P_n : (r, r) array
        Noise covariance (units of z squared).
    P_xn : (p, r) array, optional
        Cross-covariance :math:`E[(x - \mu_x)(n - \mu_n)']` (default 0).

    Returns
    -------
    NuisanceLMMSE
        Gains ``H`` (of x) and ``K`` (of y), error covariances ``P_x_err`` and ``P_y_err``,
        the mean ``mu_eps`` of ``n + F x`` and ``mu_x``.

    Raises
    ------
    ValueError
        If an array is not finite, ``G`` has a different number of rows from ``F`` or is
        column-rank deficient, or the covariance of ``n + F x`` is not positive definite
        (Eq. H.2).

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Appendix H, Eqs. (H.5)-(H.8) and
    (H.14)-(H.16).

    Examples
    --------
    >>> import numpy as np
    >>> G = np.array([[1.0], [1.0], [1.0]])
    >>> est = lmmse_with_nuisance([[1.0], [0.0], [0.0]], G, [0.0], [[1.0]], np.zeros(3), np.eye(3))
    >>> round(float(est.P_x_err[0, 0]), 4), round(float(est.P_y_err[0, 0]), 4)
    (0.6, 0.4)
    """
    F = np.atleast_2d(as_finite_array("F", F))
    G = np.atleast_2d(as_finite_array("G", G))
    r = F.shape[0]
    if G.shape[0] != r:
        raise ValueError(f"G must have {r} rows like F, got {G.shape}")
    if np.linalg.matrix_rank(G) < G.shape[1]:
        raise ValueError("G must have full column rank (Eq. H.3)")
    mu_x = as_finite_array("mu_x", mu_x).reshape(-1)
    mu_n = as_finite_array("mu_n", mu_n).reshape(-1)
    P_x = np.atleast_2d(as_finite_array("P_x", P_x))
    P_n = np.atleast_2d(as_finite_array("P_n", P_n))
    P_xn = np.zeros((F.shape[1], r)) if P_xn is None else np.atleast_2d(as_finite_array("P_xn", P_xn))
    P_xeps = P_x @ F.T + P_xn
    P_eps = symmetrize(P_n + F @ P_x @ F.T + P_xn.T @ F.T + F @ P_xn)
    if np.min(np.linalg.eigvalsh(P_eps)) <= 0:
        raise ValueError("P_n + F P_x F' + P_nx F' + F P_xn must be positive definite (Eq. H.2)")
    Pi = np.linalg.inv(P_eps)
    info_y = G.T @ Pi @ G
    K = np.linalg.solve(info_y, G.T @ Pi)  # (H.6)
    H = P_xeps @ Pi @ (np.eye(r) - G @ K)  # (H.15)
    middle = Pi - Pi @ G @ np.linalg.solve(info_y, G.T @ Pi)
    P_x_err = symmetrize(P_x - P_xeps @ middle @ P_xeps.T)  # (H.16)
    P_y_err = symmetrize(np.linalg.inv(info_y))  # (H.8)
    return NuisanceLMMSE(H=H, K=K, P_x_err=P_x_err, P_y_err=P_y_err, mu_eps=mu_n + F @ mu_x, mu_x=mu_x)


@implements("ATC10 H.21", "ATC10 H.22")
def lmmse_with_nuisance_information_form(
    F: np.ndarray, G: np.ndarray, P_x: np.ndarray, P_n: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    r"""Error covariances in information form for :math:`P_{nx} = 0` (ATC-10 Eqs. H.21-H.22).

    With :math:`A = (G' P_n^{-1} G)^{-1}`,

    .. math::

        P_{x,err} &= \left[P_x^{-1} + F' P_n^{-1} F\right. \\
            &\qquad \left. - F' P_n^{-1} G A G' P_n^{-1} F\right]^{-1}, \\
        P_{y,err} &= A + A G' P_n^{-1} F P_{x,err} F' P_n^{-1} G A.

    Parameters
    ----------
    F : (r, p) array
        Observation matrix of the random vector x.
    G : (r, q) array
        Observation matrix of the nonrandom vector y (full column rank).
    P_x : (p, p) array
        Prior covariance of x (positive definite).
    P_n : (r, r) array
        Noise covariance (positive definite).

    Returns
    -------
    P_x_err : (p, p) ndarray
        Error covariance of the estimate of x.
    P_y_err : (q, q) ndarray
        Error covariance of the estimate of y.

    Raises
    ------
    ValueError
        If an array has a non-finite element.
    numpy.linalg.LinAlgError
        If ``P_x``, ``P_n`` or :math:`G' P_n^{-1} G` is singular.

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Appendix H, Eqs. (H.21)-(H.22); equal to
    the covariances of :func:`lmmse_with_nuisance` when ``P_xn = 0``.

    Examples
    --------
    >>> import numpy as np
    >>> G = np.array([[1.0], [1.0], [1.0]])
    >>> Px, Py = lmmse_with_nuisance_information_form([[1.0], [0.0], [0.0]], G, [[1.0]], np.eye(3))
    >>> round(float(Px[0, 0]), 4), round(float(Py[0, 0]), 4)
    (0.6, 0.4)
    """
    F = np.atleast_2d(as_finite_array("F", F))
    G = np.atleast_2d(as_finite_array("G", G))
    P_x = np.atleast_2d(as_finite_array("P_x", P_x))
    Wn = np.linalg.inv(np.atleast_2d(as_finite_array("P_n", P_n)))
    A = np.linalg.inv(G.T @ Wn @ G)
    B = F.T @ Wn @ G
    P_x_err = symmetrize(np.linalg.inv(np.linalg.inv(P_x) + F.T @ Wn @ F - B @ A @ B.T))
    P_y_err = symmetrize(A + A @ B.T @ P_x_err @ B @ A)
    return P_x_err, P_y_err


@implements("ATC10 H.26")
def scalar_nuisance_gain(f: np.ndarray, G: np.ndarray, sigma: float, sigma_x: float) -> float:
    r"""Gain of the scalar-x corollary (ATC-10 Eq. H.26, corrected numerator).

    :math:`\hat x = \gamma f'(I - P_G)(z - f \mu_x - \mu_n) + \mu_x` with
    :math:`\gamma = \sigma_x^2 / (\sigma^2 + \sigma_x^2 f'(I - P_G) f)`; the error variance is
    :math:`\sigma^2 \gamma`. In ATC-10 Section 4 (f = 1, G = satellite matrix) this is
    :math:`\gamma_n = s_n / (\sigma^2 + \beta s_n)`.

    Parameters
    ----------
    f : (r,) array
        Observation vector of the scalar x.
    G : (r, q) array
        Observation matrix of the nonrandom vector y.
    sigma : float
        Standard deviation of the white measurement noise (units of z, ``> 0``).
    sigma_x : float
        Prior standard deviation of x (units of x, ``> 0``).

    Returns
    -------
    float
        The gain ``gamma`` (per unit of z squared).

    Raises
    ------
    ValueError
        If ``sigma`` or ``sigma_x`` is not positive or an array is not finite.

    References
    ----------
    Schneider, Stiglitz & Eckberg, ATC-10 (1972), Appendix H, Eq. (H.26); the printed
    numerator ``sigma^2`` is erratum E4-10, corrected here to ``sigma_x^2``.

    Examples
    --------
    >>> import numpy as np
    >>> round(scalar_nuisance_gain(np.ones(3), [[1.0], [0.0], [-1.0]], 1.0, 2.0), 4)
    0.3077
    """
    require_positive("sigma", sigma)
    require_positive("sigma_x", sigma_x)
    f = as_finite_array("f", f).reshape(-1)
    G = np.atleast_2d(as_finite_array("G", G))
    coef, *_ = np.linalg.lstsq(G, f, rcond=None)
    resid = f - G @ coef
    return sigma_x**2 / (sigma**2 + sigma_x**2 * float(resid @ resid))


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals(), {"sigma": POSITIVE, "sigma_x": NONNEGATIVE, "P_x": COVARIANCE, "P_n": COVARIANCE})
