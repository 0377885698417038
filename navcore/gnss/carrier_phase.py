r"""Multi-antenna attitude observations: Euler-angle attitude rows and double-difference
carrier phase for three antennas (master A0, A1, A2).

Double difference between satellites n and master satellite m and antennas A0, Ai
(KZL Eq. 15):

.. math::

    \nabla\Delta\varphi^{(n,m)}_{A0,Ai} = \frac{2\pi}{\lambda}
    \big[(\rho^{(n)}_{Ai} - \rho^{(n)}_{A0}) - (\rho^{(m)}_{Ai} - \rho^{(m)}_{A0})\big]
    \approx \frac{2\pi}{\lambda} (l^{(m)} - l^{(n)})^T R_b^n\, l^b_{0i}

(plane-wave approximation; :func:`double_difference_phase` evaluates the exact ranges).
Receiver clocks and common-mode atmosphere cancel; with resolved ambiguities and no
multipath (KZL Table 1) only receiver noise is left (Eq. 16).

With :math:`\hat R = (I + [\Delta\psi\times])R`, the Jacobian of the predicted DD with respect
to the attitude error is :math:`\frac{2\pi}{\lambda}(l^{(m)} - l^{(n)})^T
[\hat R l^b_{0i}\times]_{\rm paper}` with the paper's bracket :math:`[a\times]_{\rm paper} =
-[a\times]` (KZL Eq. 17, with :math:`l_{01}` in the first DD row).

The Euler-angle attitude observation of KZL Eq. 12 has Jacobian
:math:`\partial(\phi,\theta,\psi)/\partial\Delta\psi = J_b^{-1}(\phi,\theta)\,\hat R_n^b`
(:func:`euler_attitude_rows`): body-rate-to-Euler-rate matrix times the n-to-b rotation.

References
----------
.. [1] S. Knedlik, J. Zhou, O. Loffeld (2009), Eqs. (12)-(17).
.. [2] R. Hirokawa, T. Ebinuma, "A low-cost tightly coupled GPS/INS for small UAVs augmented
   with multiple GPS antennas", NAVIGATION 56(1) (2009).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import as_finite_array, require_integer, require_positive
from navcore.frames import skew
from navcore.inertial.error_model17 import ERROR_LAYOUT_17, code_doppler_rows
from navcore.trace import implements
from navcore.units import GPS_L1_WAVELENGTH_M

__all__ = [
    "attitude_observation_rows_count",
    "dd_covariance",
    "dd_observation_rows",
    "dd_observation_rows_count",
    "double_difference_phase",
    "euler_attitude_rows",
    "euler_rate_matrix_body",
    "tc_attitude_observation_matrix",
    "tc_dd_observation_matrix",
]

Array = NDArray[np.float64]
_A = ERROR_LAYOUT_17.slice("misalignment")

#: Body-frame baselines A0->A1 (2 m forward) and A0->A2 (2 m to the right wing), metres.


def _range_difference(sat: Array, a0: Array, ai: Array) -> Array:
    """``|sat - ai| - |sat - a0|`` without cancellation: ``(|d_i|^2 - |d_0|^2)/(|d_i| + |d_0|)``."""
    # d_i - d_0 = a0 - ai exactly (no cancellation of the ~2e7 m ranges)
    num = np.sum((a0 - ai) * (2.0 * sat - a0 - ai), axis=-1)
    return num / (np.linalg.norm(sat - ai, axis=-1) + np.linalg.norm(sat - a0, axis=-1))


@implements("KZL 15")
def double_difference_phase(
    sat_m: ArrayLike,
    sat_n: ArrayLike,
    r_a0: ArrayLike,
    r_ai: ArrayLike,
    wavelength: float = GPS_L1_WAVELENGTH_M,
) -> Array:
    """Double-difference carrier phase (rad) of KZL Eq. 15 from exact ranges.

    Parameters
    ----------
    sat_m, sat_n : (..., 3) arrays
        Positions of the master satellite m and satellite n (m), any common frame.
    r_a0, r_ai : (..., 3) arrays
        Positions of the master antenna A0 and antenna Ai (m).
    wavelength : float
        Carrier wavelength (m), L1 by default.
    """
    require_positive("wavelength", wavelength)
    sm, sn = as_finite_array("sat_m", sat_m), as_finite_array("sat_n", sat_n)
    a0, ai = as_finite_array("r_a0", r_a0), as_finite_array("r_ai", r_ai)
    return 2 * np.pi / wavelength * (_range_difference(sn, a0, ai) - _range_difference(sm, a0, ai))


@implements("KZL 17")
def dd_observation_rows(
    los_m: ArrayLike,
    los_n: ArrayLike,
    C_bn: ArrayLike,
    baselines_b: ArrayLike,
    wavelength: float = GPS_L1_WAVELENGTH_M,
) -> Array:
    """DD rows of KZL Eq. 17 (corrected: ``l_01`` in the first row, ``l_02`` in the second).

    Parameters
    ----------
    los_m, los_n : (3,) arrays
        Unit LOS (NED) to the master satellite m and to satellite n.
    C_bn : (3, 3) array
        Computed attitude :math:`\\hat R_b^n`.
    baselines_b : (k, 3) array
        Body baselines :math:`l^b_{0i}` (m).

    Returns
    -------
    H : (k, 17) array
        Non-zero only in the misalignment columns.
    """
    lm, ln = as_finite_array("los_m", los_m), as_finite_array("los_n", los_n)
    C = as_finite_array("C_bn", C_bn, ndim=2)
    B = as_finite_array("baselines_b", baselines_b, ndim=2)
    H = np.zeros((B.shape[0], 17))
    for i, b in enumerate(B):
        H[i, _A] = 2 * np.pi / wavelength * (lm - ln) @ (-skew(C @ b))  # [.x]_paper = -[.x]
    return H


def dd_covariance(nu: int, sigma_phase: float, n_baselines: int = 2) -> Array:
    """Covariance (rad^2) of the ``(nu - 1) * n_baselines`` DDs of one epoch.

    Each undifferenced phase (per antenna and satellite) has standard deviation
    ``sigma_phase`` (rad); the DDs are ``D phi`` with the differencing matrix D, so the
    covariance is ``sigma^2 D D^T``: ``4 sigma^2`` on the diagonal, ``2 sigma^2`` between DDs
    sharing a satellite or an antenna pair, ``sigma^2`` otherwise. Rows are ordered satellite
    by satellite (n = 1..nu-1), baselines within.
    """
    require_integer("nu", nu, minimum=2)
    require_positive("sigma_phase", sigma_phase)
    n_ant = n_baselines + 1
    # undifferenced phases indexed (satellite s, antenna a) -> s * n_ant + a; satellite 0 = master
    rows = []
    for s in range(1, nu):
        for a in range(1, n_ant):
            d = np.zeros(nu * n_ant)
            d[s * n_ant + a] += 1
            d[s * n_ant] -= 1
            d[a] -= 1
            d[0] += 1
            rows.append(d)
    D = np.array(rows)
    return sigma_phase**2 * D @ D.T


@implements("KZL 13")
def euler_rate_matrix_body(roll: float, pitch: float) -> Array:
    """Body-rate to Euler-rate matrix :math:`J_b^{-1}` of the 3-2-1 sequence (the "R" KZL Eq. 13 names)."""
    sr, cr = np.sin(roll), np.cos(roll)
    tp, cp = np.tan(pitch), np.cos(pitch)
    return np.array([[1.0, sr * tp, cr * tp], [0.0, cr, -sr], [0.0, sr / cp, cr / cp]])


@implements("KZL 12")
def euler_attitude_rows(C_bn: ArrayLike, roll: float, pitch: float) -> Array:
    """Rows (3 x 17) of the Euler-angle attitude observation (KZL Eq. 12/13, corrected block).

    The block is :math:`\\partial(\\phi,\\theta,\\psi)/\\partial\\Delta\\psi = J_b^{-1}\\hat R_n^b`.
    """
    C = as_finite_array("C_bn", C_bn, ndim=2)
    H = np.zeros((3, 17))
    H[:, _A] = euler_rate_matrix_body(roll, pitch) @ C.T
    return H


@implements("KZL 13")
def tc_attitude_observation_matrix(los_ned: ArrayLike, C_bn: ArrayLike, roll: float, pitch: float) -> Array:
    """Observation matrix of KZL Eq. 13 stacked over satellites: ``(2 nu + 3, 17)``."""
    return np.vstack([code_doppler_rows(los_ned), euler_attitude_rows(C_bn, roll, pitch)])


@implements("KZL 17")
def tc_dd_observation_matrix(los_ned: ArrayLike, C_bn: ArrayLike, baselines_b: ArrayLike) -> Array:
    """Observation matrix of KZL Eq. 17 for ``nu`` satellites (first = master): code/Doppler rows
    for every satellite, then the DD rows satellite by satellite."""
    L = as_finite_array("los_ned", los_ned, ndim=2)
    rows = [code_doppler_rows(L)]
    for n in range(1, L.shape[0]):
        rows.append(dd_observation_rows(L[0], L[n], C_bn, baselines_b))
    return np.vstack(rows)


@implements("KZL 13")
def attitude_observation_rows_count(nu: int) -> int:
    """Rows of the stacked Eq. 13 matrix, counted from the builder (code, Doppler, 3 angles)."""
    require_integer("nu", nu, minimum=1)
    los = np.tile([0.0, 0.0, -1.0], (nu, 1))
    return tc_attitude_observation_matrix(los, np.eye(3), 0.0, 0.0).shape[0]


@implements("KZL 17")
def dd_observation_rows_count(nu: int, n_baselines: int = 2) -> int:
    """Rows of the stacked Eq. 17 matrix, counted from the builder."""
    require_integer("nu", nu, minimum=1)
    los = np.tile([0.0, 0.0, -1.0], (nu, 1))
    return tc_dd_observation_matrix(los, np.eye(3), np.eye(3)[:n_baselines]).shape[0]
