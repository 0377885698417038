r"""Multi-antenna attitude observations: double-difference carrier phase for three antennas
(master :math:`A_0`, :math:`A_1`, :math:`A_2`) and the Euler-rate matrix of an attitude fix.

Double difference between satellites n and master satellite m and antennas :math:`A_0`, :math:`A_i`
(KZL Eq. 15):

.. math::

    \begin{aligned}
    \nabla\Delta\varphi^{(n,m)}_{A0,Ai} &= \frac{2\pi}{\lambda}
    \big[(\rho^{(n)}_{Ai} - \rho^{(n)}_{A0}) - (\rho^{(m)}_{Ai} - \rho^{(m)}_{A0})\big]\\
    &\approx \frac{2\pi}{\lambda} (l^{(m)} - l^{(n)})^T R_b^n\, l^b_{0i}
    \end{aligned}

(plane-wave approximation; :func:`double_difference_phase` evaluates the exact ranges).
Receiver clocks and common-mode atmosphere cancel; with resolved ambiguities and no
multipath (KZL Table 1) only receiver noise is left (Eq. 16).

With :math:`\hat R = (I + [\Delta\psi\times])R`, the Jacobian of the predicted DD with respect
to the attitude error is :math:`\frac{2\pi}{\lambda}(l^{(m)} - l^{(n)})^T
[\hat R l^b_{0i}\times]_{\rm paper}` with the paper's bracket :math:`[a\times]_{\rm paper} =
-[a\times]` (KZL Eq. 17, with :math:`l_{01}` in the first DD row).

The Euler-angle attitude observation of KZL Eq. 12 has Jacobian
:math:`\partial(\phi,\theta,\psi)/\partial\Delta\psi = J_b^{-1}(\phi,\theta)\,\hat R_n^b`:
body-rate-to-Euler-rate matrix (:func:`euler_rate_matrix_body`) times the n-to-b rotation.
The rows of these observations in the 17-state error model are built in
:mod:`navcore.integration.measurement_rows`.

References
----------
.. [1] S. Knedlik, J. Zhou, O. Loffeld (2009), Eqs. (12)-(17).
.. [2] R. Hirokawa, T. Ebinuma, "A low-cost tightly coupled GPS/INS for small UAVs augmented
   with multiple GPS antennas", NAVIGATION 56(1) (2009).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    COUNT0,
    POSITIVE,
    Angle,
    as_finite_array,
    check_public,
    require_integer,
    require_positive,
)
from navcore.trace import implements
from navcore.units import GPS_L1_WAVELENGTH_M

__all__ = [
    "dd_covariance",
    "double_difference_phase",
    "euler_rate_matrix_body",
]

Array = NDArray[np.float64]


def _range_difference(sat: Array, a0: Array, ai: Array) -> Array:
    """``|sat - ai| - |sat - a0|`` without cancellation: ``(|d_i|^2 - |d_0|^2)/(|d_i| + |d_0|)``."""
    # d_i - d_0 = a0 - ai exactly (no cancellation of the ~2e7 m ranges)
    num = np.sum((a0 - ai) * (2.0 * sat - a0 - ai), axis=-1)
    den = np.linalg.norm(sat - ai, axis=-1) + np.linalg.norm(sat - a0, axis=-1)
    if np.any(den == 0.0):
        raise ValueError("sat_m and sat_n must not coincide with the antennas r_a0, r_ai")
    return num / den


@implements("KZL 15")
def double_difference_phase(
    sat_m: ArrayLike,
    sat_n: ArrayLike,
    r_a0: ArrayLike,
    r_ai: ArrayLike,
    wavelength: float = GPS_L1_WAVELENGTH_M,
) -> Array:
    """Double-difference carrier phase of KZL Eq. 15 from exact ranges.

    Parameters
    ----------
    sat_m : (..., 3) array
        Position of the master satellite m, m (any common frame).
    sat_n : (..., 3) array
        Position of satellite n, m.
    r_a0 : (..., 3) array
        Position of the master antenna :math:`A_0`, m.
    r_ai : (..., 3) array
        Position of antenna Ai, m.
    wavelength : float, default GPS_L1_WAVELENGTH_M
        Carrier wavelength, m (``> 0``).

    Returns
    -------
    ndarray
        Double-difference phase, rad (no integer ambiguity).

    Raises
    ------
    ValueError
        If ``wavelength`` is not positive or a position is not finite.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (15).

    Examples
    --------
    >>> import numpy as np
    >>> far = 2.0e7
    >>> phi = double_difference_phase([0.0, 0.0, -far], [far, 0.0, 0.0], [0.0, 0.0, 0.0],
    ...                               [0.1, 0.0, 0.0], wavelength=0.2)
    >>> round(float(phi), 4)
    -3.1416
    """
    require_positive("wavelength", wavelength)
    sm, sn = as_finite_array("sat_m", sat_m), as_finite_array("sat_n", sat_n)
    a0, ai = as_finite_array("r_a0", r_a0), as_finite_array("r_ai", r_ai)
    return 2 * np.pi / wavelength * (_range_difference(sn, a0, ai) - _range_difference(sm, a0, ai))


def dd_covariance(nu: int, sigma_phase: float, n_baselines: int = 2) -> Array:
    r"""Covariance of the ``(nu - 1) * n_baselines`` double differences of one epoch.

    Each undifferenced phase (per antenna and satellite) has standard deviation
    ``sigma_phase``; the DDs are :math:`D \phi` with the differencing matrix D, so the covariance is
    :math:`\sigma^2 D D^T`: :math:`4 \sigma^2` on the diagonal, :math:`2 \sigma^2` between DDs sharing a
    satellite or an antenna pair, ``sigma^2`` otherwise. Rows are ordered satellite by
    satellite (:math:`n = 1, \dots, \nu - 1`), baselines within.

    Parameters
    ----------
    nu : int
        Number of satellites, the first the master (``>= 2``).
    sigma_phase : float
        Standard deviation of an undifferenced phase, rad (``> 0``).
    n_baselines : int, default 2
        Number of baselines from the master antenna.

    Returns
    -------
    ((nu - 1) n_baselines, (nu - 1) n_baselines) ndarray
        Covariance, rad².

    Raises
    ------
    ValueError
        If ``nu < 2`` or ``sigma_phase`` is not positive.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eqs. (15)-(17) (the measurement noise of the DD rows).

    Examples
    --------
    >>> dd_covariance(3, 1.0, n_baselines=1).tolist()
    [[4.0, 2.0], [2.0, 4.0]]
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
def euler_rate_matrix_body(roll: float, pitch: float, *, deg: bool = False) -> Array:
    """Body-rate to Euler-rate matrix :math:`J_b^{-1}` of the 3-2-1 sequence (the "R" of KZL Eq. 13).

    Parameters
    ----------
    roll : float
        Roll, rad (deg with ``deg=True``).
    pitch : float
        Pitch, rad (deg), in (-90, 90) deg.
    deg : bool, default False
        The angles are in degrees.

    Returns
    -------
    (3, 3) ndarray
        Maps body rates (rad/s) to roll, pitch, yaw rates (rad/s).

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (13).

    Examples
    --------
    >>> import numpy as np
    >>> np.round(euler_rate_matrix_body(0.1, 0.2), 4).tolist()
    [[1.0, 0.0202, 0.2017], [0.0, 0.995, -0.0998], [0.0, 0.1019, 1.0152]]
    """
    if deg:
        roll, pitch = float(np.radians(roll)), float(np.radians(pitch))
    sr, cr = np.sin(roll), np.cos(roll)
    tp, cp = np.tan(pitch), np.cos(pitch)
    return np.array([[1.0, sr * tp, cr * tp], [0.0, cr, -sr], [0.0, sr / cp, cr / cp]])


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "wavelength": POSITIVE,
        "sigma_phase": POSITIVE,
        "n_baselines": COUNT,
        "nu": COUNT0,
        "pitch": Angle(90.0, "a pitch angle"),
    },
)
