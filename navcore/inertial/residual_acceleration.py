r"""Residual acceleration seen by an inertially aided tracking loop, and Gaussian sphere radii.

After inertial aiding, a tracking loop sees only what the IMU gets wrong about an
acceleration :math:`a`: the scale-factor errors :math:`sf_i` and the misalignment
:math:`\delta\theta` (SP Sec. 2.5)

.. math::

    \begin{gathered}
    \delta a = \operatorname{diag}(sf)\,a + \delta\theta\times a
             = H(a)\begin{bmatrix} sf \\ \delta\theta \end{bmatrix},\\
    H(a) = \big[\operatorname{diag}(a)\;\big|\; -[a\times]\big],
    \end{gathered}

with covariance :math:`\langle\delta a\,\delta a^T\rangle = H P H^T` for the 6x6 covariance
:math:`P` of scale factor and misalignment. The paper prints :math:`H` for
:math:`a = (1, 1, 1)` with the misalignment block of the opposite sign,
:math:`+[a\times]` (that is :math:`a\times\delta\theta`); both conventions are provided
(``convention="cross"`` for the printed skew matrix, ``"printed"`` for the printed 3x6
matrix). The sign only matters when scale factor and misalignment are correlated.

The loops are tuned to the radius of the sphere that encloses a probability :math:`p` of
:math:`\delta a`. In the eigenbasis of the covariance, :math:`|\delta a|^2 = \sum_i \lambda_i
z_i^2` with independent standard normal :math:`z_i` and :math:`\lambda_1\ge\lambda_2\ge\lambda_3`.
Conditioning on :math:`z_1, z_2` leaves :math:`P\{|z_3| \le \sqrt{(r^2-\lambda_1 z_1^2-\lambda_2
z_2^2)/\lambda_3}\}`, an error function; the substitutions :math:`z_1 = (r/\sqrt{\lambda_1})
\sin s`, :math:`z_2 = (r\cos s/\sqrt{\lambda_2})\sin t` map the ellipse onto a square and
remove the square-root edges (where the ellipse is wider than about nine standard
deviations the range is cut there instead), so that

.. math::

    \begin{aligned}
    P\{|\delta a|\le r\} = \int_{-\pi/2}^{\pi/2}\!\int_{-\pi/2}^{\pi/2}
        &\frac{r\cos s}{\sqrt{\lambda_1}}\,\varphi\Big(\frac{r\sin s}{\sqrt{\lambda_1}}\Big)\\
        &\times\frac{r\cos s\cos t}{\sqrt{\lambda_2}}\,
        \varphi\Big(\frac{r\cos s\sin t}{\sqrt{\lambda_2}}\Big)\\
        &\times\operatorname{erf}\Big(\frac{r\cos s\cos t}{\sqrt{2\lambda_3}}\Big)\,dt\,ds,
    \end{aligned}

a smooth integrand that Gauss-Legendre quadrature integrates to about :math:`10^{-10}` for eigenvalue
ratios up to :math:`10^{4}` (checked against the chi-square distribution and by Monte Carlo in the
tests). Two- and one-dimensional cases drop the outer integrals.

References
----------
.. [SP] G. T. Schmidt and R. E. Phillips, "INS/GPS Integration Architecture Performance
   Comparisons", NATO RTO-EN-SET-116, Sec. 2.5, Table 2.6.
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq
from scipy.special import erf

from navcore._validate import (
    COUNT,
    NONNEGATIVE,
    OPEN_PROBABILITY,
    as_finite_array,
    check_public,
    require_integer,
    require_probability,
    require_symmetric_psd,
)
from navcore.frames import skew
from navcore.trace import implements
from navcore.units import ARCSEC, PPM

__all__ = [
    "r90_from_apriori_ppm",
    "residual_acceleration_covariance",
    "scale_factor_misalignment_sensitivity",
    "sphere_probability",
    "sphere_radius",
    "sphere_radius_monte_carlo",
]

Array = NDArray[np.float64]


@implements("SP Table 2.6")
def scale_factor_misalignment_sensitivity(
    accel: ArrayLike = (1.0, 1.0, 1.0), convention: Literal["cross", "printed"] = "cross"
) -> Array:
    r"""3x6 sensitivity of the residual acceleration to
    :math:`(sf_1, sf_2, sf_3, \delta\theta_1, \delta\theta_2, \delta\theta_3)`.

    Parameters
    ----------
    accel : array_like, shape (3,)
        The acceleration step (any unit; the result is per unit of it). The paper's "unit
        acceleration step" is ``(1, 1, 1)``.
    convention : {"cross", "printed"}
        ``"cross"``: :math:`\delta a_{mis} = \delta\theta\times a` (the paper's skew
        matrix); ``"printed"``: the sign of the paper's printed 3x6 matrix,
        :math:`a\times\delta\theta`.

    Returns
    -------
    (3, 6) ndarray
        :math:`[\operatorname{diag}(a),\ \mp[a\times]]` (the sign by ``convention``): acceleration
        unit per unit scale factor and per rad.

    Raises
    ------
    ValueError
        If ``accel`` is not a finite 3-vector or ``convention`` is unknown.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.5,
    Table 2.6.

    Examples
    --------
    >>> scale_factor_misalignment_sensitivity(convention="printed").astype(int).tolist()
    [[1, 0, 0, 0, -1, 1], [0, 1, 0, 1, 0, -1], [0, 0, 1, -1, 1, 0]]
    """
    a = as_finite_array("accel", accel)
    if a.shape != (3,):
        raise ValueError(f"accel must have shape (3,), got {a.shape}")
    if convention == "cross":
        mis = -skew(a)
    elif convention == "printed":
        mis = skew(a)
    else:
        raise ValueError(f"convention must be 'cross' or 'printed', got {convention!r}")
    return np.hstack([np.diag(a), mis])


@implements("SP Table 2.6")
def residual_acceleration_covariance(sensitivity: ArrayLike, error_covariance: ArrayLike) -> Array:
    """Covariance :math:`H P H^T` of the residual acceleration (SP Sec. 2.5), symmetrised.

    Parameters
    ----------
    sensitivity : (m, n) array
        Sensitivity of the residual acceleration to the error states (e.g.
        :func:`scale_factor_misalignment_sensitivity`).
    error_covariance : (n, n) array
        Covariance of the error states (scale factors dimensionless, misalignments rad²).

    Returns
    -------
    (m, m) ndarray
        Covariance of the residual acceleration, in the unit of the acceleration step squared.

    Raises
    ------
    ValueError
        If the shapes disagree or ``error_covariance`` is not symmetric positive semi-definite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.5 and Table 2.6.

    Examples
    --------
    >>> import numpy as np
    >>> H = scale_factor_misalignment_sensitivity()
    >>> C = residual_acceleration_covariance(H, 1e-8 * np.eye(6))
    >>> [f"{x:.1e}" for x in np.diag(C)]
    ['3.0e-08', '3.0e-08', '3.0e-08']
    """
    H = as_finite_array("sensitivity", sensitivity)
    P = require_symmetric_psd("error_covariance", error_covariance)
    if H.ndim != 2 or H.shape[1] != P.shape[0]:
        raise ValueError(f"sensitivity columns ({H.shape}) must match error_covariance {P.shape}")
    C = H @ P @ H.T
    return 0.5 * (C + C.T)


def _eigen(cov: ArrayLike) -> Array:
    C = require_symmetric_psd("cov", cov)
    if C.shape[0] > 3:
        raise ValueError(f"cov must be at most 3x3, got {C.shape}")
    lam = np.sort(np.clip(np.linalg.eigvalsh(C), 0.0, None))[::-1]
    if not lam[0] > 0:
        raise ValueError("cov must have at least one positive eigenvalue")
    return lam[lam > 1e-300]


_X, _WX = np.polynomial.legendre.leggauss(160)
_ZMAX = 9.0  # |z| beyond which the standard normal density (< 3e-18) is dropped


def _phi(x: Array) -> Array:
    return np.exp(-0.5 * x * x) / math.sqrt(2 * math.pi)


def _half_range(a: Array | float) -> Array:
    """Limit of t in z = a sin t: pi/2, or arcsin(ZMAX/a) when the ellipse is wider than the density."""
    a = np.asarray(a, dtype=float)
    return np.arcsin(np.minimum(1.0, _ZMAX / np.maximum(a, 1e-300)))


def _probability_inside(lam: Array, radius: float) -> float:
    """P(sum lam_i z_i^2 <= radius^2), lam sorted in decreasing order (1 to 3 terms)."""
    if radius <= 0:
        return 0.0
    r = radius
    if lam.size == 1:
        return float(erf(r / math.sqrt(2 * lam[0])))
    a1 = r / math.sqrt(lam[0])
    h1 = float(_half_range(a1))
    s = h1 * _X
    ws = h1 * _WX
    cs = np.cos(s)
    g1 = a1 * cs * _phi(a1 * np.sin(s))  # dz1 * phi(z1)
    if lam.size == 2:
        return float(min(np.dot(ws, g1 * erf(r * cs / math.sqrt(2 * lam[1]))), 1.0))
    a2 = r * cs / math.sqrt(lam[1])  # per outer node
    h2 = _half_range(a2)[:, None]
    t = h2 * _X[None, :]
    wt = h2 * _WX[None, :]
    ct = np.cos(t)
    g2 = a2[:, None] * ct * _phi(a2[:, None] * np.sin(t))
    inner = np.sum(wt * g2 * erf(r * cs[:, None] * ct / math.sqrt(2 * lam[2])), axis=1)
    return float(min(np.dot(ws, g1 * inner), 1.0))


def sphere_probability(cov: ArrayLike, radius: float) -> float:
    r"""Probability that a zero-mean Gaussian with covariance ``cov`` lies within ``radius``.

    Numerical integration (module docstring) of the distribution of :math:`\sum\lambda_i z_i^2`.

    Parameters
    ----------
    cov : (n, n) array
        Covariance (symmetric positive semi-definite), unit squared.
    radius : float
        Sphere radius, same unit (finite, ``>= 0``).

    Returns
    -------
    float
        Probability in [0, 1].

    Raises
    ------
    ValueError
        If ``radius`` is negative or not finite, or ``cov`` is not a covariance.

    Examples
    --------
    >>> import numpy as np
    >>> round(sphere_probability(np.eye(3), 2.5002777), 6)
    0.9
    """
    lam = _eigen(cov)
    if not (radius >= 0 and math.isfinite(radius)):
        raise ValueError(f"radius must be finite and >= 0, got {radius!r}")
    return _probability_inside(lam, float(radius))


@implements("SP Table 2.6")
def sphere_radius(cov: ArrayLike, p: float = 0.9) -> float:
    r"""Radius of the sphere about the origin enclosing probability ``p`` of N(0, cov).

    For :math:`\mathrm{cov} = s^2 I` in 3-D and :math:`p = 0.9` this is :math:`2.500278\, s`; the 2-D :math:`p
    = 0.5` value is the
    CEP (1.17741 s). Any dimension and any (PSD) covariance.

    Parameters
    ----------
    cov : (n, n) array
        Covariance (symmetric positive semi-definite), unit squared.
    p : float, default 0.9
        Enclosed probability, in (0, 1).

    Returns
    -------
    float
        Radius, in the unit of ``cov``'s square root.

    Raises
    ------
    ValueError
        If ``p`` is not in (0, 1) or ``cov`` is not a covariance.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Table 2.6
    (the 90 % spherical residual acceleration).

    Examples
    --------
    >>> import numpy as np
    >>> round(sphere_radius(np.eye(3)), 6)
    2.500278
    """
    require_probability("p", p)
    if not 0 < p < 1:
        raise ValueError(f"p must be in (0, 1), got {p!r}")
    lam = _eigen(cov)
    scale = math.sqrt(float(np.sum(lam)))
    lo, hi = 1e-6 * scale, 10.0 * scale  # P(|x| > 10 sqrt(trace)) < 1e-20
    return float(brentq(lambda r: _probability_inside(lam, r) - p, lo, hi, xtol=1e-12 * scale, rtol=1e-12))


def sphere_radius_monte_carlo(cov: ArrayLike, p: float = 0.9, n: int = 200_000, seed: int = 0) -> float:
    """Monte Carlo estimate of :func:`sphere_radius`: the ``p`` quantile of ``|x|`` over ``n`` draws.

    Parameters
    ----------
    cov : (n, n) array
        Covariance (symmetric positive semi-definite), unit squared.
    p : float, default 0.9
        Enclosed probability.
    n : int, default 200000
        Number of draws.
    seed : int, default 0
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    float
        Estimated radius (unit of ``cov``'s square root).

    Raises
    ------
    ValueError
        If ``p`` is not a probability, ``n`` not an integer or ``cov`` not a covariance.

    Examples
    --------
    >>> import numpy as np
    >>> round(sphere_radius_monte_carlo(np.eye(3), n=20_000, seed=1), 1)
    2.5
    """
    require_probability("p", p)
    require_integer("n", n)
    C = require_symmetric_psd("cov", cov)
    rng = np.random.default_rng(seed)
    w, V = np.linalg.eigh(C)
    L = V * np.sqrt(np.clip(w, 0.0, None))
    x = rng.standard_normal((n, C.shape[0])) @ L.T
    return float(np.quantile(np.linalg.norm(x, axis=1), p))


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
@implements("SP Table 2.6")
def r90_from_apriori_ppm(sf_ppm: float, mis_arcsec: float, accel: ArrayLike = (1.0, 1.0, 1.0)) -> float:
    r"""90 % sphere radius of the residual acceleration from isotropic scale-factor and
    misalignment errors, in ppm of the acceleration step.

    The three accelerometer scale factors (1-:math:`\sigma` ``sf_ppm`` each) and the three
    misalignment angles (``mis_arcsec`` each) are independent; their covariance goes through the
    paper's printed sensitivity (:func:`scale_factor_misalignment_sensitivity` with
    ``convention="printed"``; with independent errors the sign of the misalignment block does not
    change the covariance) to the residual acceleration's covariance
    (:func:`residual_acceleration_covariance`), whose 90 % sphere radius
    (:func:`sphere_radius`) is returned per unit of the step.

    Parameters
    ----------
    sf_ppm : float
        Scale-factor error per axis, ppm (1-:math:`\sigma`, ``>= 0``).
    mis_arcsec : float
        Misalignment per axis, arcsec (1-:math:`\sigma`, ``>= 0``).
    accel : array_like, shape (3,), default (1, 1, 1)
        The acceleration step (the paper's "unit acceleration step" by default).

    Returns
    -------
    float
        The 90 % sphere radius, ppm of the step's unit.

    Raises
    ------
    ValueError
        If an error is negative or not finite, both are zero, or ``accel`` is not a finite
        3-vector.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.5,
    Table 2.6 column 2 (the 90 % residual error due to scale factor and misalignment).

    Examples
    --------
    With no misalignment, the residual on each axis is ``sf`` times the unit step, so the radius
    is that of :math:`s^2 I` in 3-D, :math:`2.500278\,s`:

    >>> round(r90_from_apriori_ppm(100.0, 0.0), 4)
    250.0278
    """
    H = scale_factor_misalignment_sensitivity(accel, convention="printed")
    P = np.diag([(sf_ppm * PPM) ** 2] * 3 + [(mis_arcsec * ARCSEC) ** 2] * 3)
    return sphere_radius(residual_acceleration_covariance(H, P), 0.9) / PPM


check_public(
    globals(),
    {
        "n": COUNT,
        "p": OPEN_PROBABILITY,
        "radius": NONNEGATIVE,
        "sf_ppm": NONNEGATIVE,
        "mis_arcsec": NONNEGATIVE,
    },
)
