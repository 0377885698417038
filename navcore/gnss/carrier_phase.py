r"""Multi-antenna attitude observations: Euler-angle attitude rows and double-difference
carrier phase for three antennas (master :math:`A_0`, :math:`A_1`, :math:`A_2`).

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

from navcore._validate import (
    COUNT,
    COUNT0,
    POSITIVE,
    ROTATION,
    Angle,
    as_finite_array,
    check_public,
    require_integer,
    require_positive,
)
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


@implements("KZL 17")
def dd_observation_rows(
    los_m: ArrayLike,
    los_n: ArrayLike,
    C_bn: ArrayLike,
    baselines_b: ArrayLike,
    wavelength: float = GPS_L1_WAVELENGTH_M,
) -> Array:
    r"""DD rows of KZL Eq. 17 (corrected: ``l_01`` in the first row, ``l_02`` in the second).

    Parameters
    ----------
    los_m : (3,) array
        Unit LOS (NED) to the master satellite m.
    los_n : (3,) array
        Unit LOS (NED) to satellite n.
    C_bn : (3, 3) array
        Computed attitude :math:`\hat R_b^n`.
    baselines_b : (k, 3) array
        Body baselines :math:`l^b_{0i}`, m.
    wavelength : float, default GPS_L1_WAVELENGTH_M
        Carrier wavelength, m.

    Returns
    -------
    H : (k, 17) ndarray
        Non-zero only in the misalignment columns (rad of phase per rad of attitude error).

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong number of dimensions.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (17) (the printed baselines are swapped between the two rows).

    Examples
    --------
    >>> import numpy as np
    >>> H = dd_observation_rows([0.0, 0.0, -1.0], [1.0, 0.0, 0.0], np.eye(3), [[1.0, 0.0, 0.0]])
    >>> H.shape, np.flatnonzero(H[0]).tolist()
    ((1, 17), [7])
    """
    lm, ln = as_finite_array("los_m", los_m), as_finite_array("los_n", los_n)
    C = as_finite_array("C_bn", C_bn, ndim=2)
    B = as_finite_array("baselines_b", baselines_b, ndim=2)
    H = np.zeros((B.shape[0], 17))
    for i, b in enumerate(B):
        H[i, _A] = 2 * np.pi / wavelength * (lm - ln) @ (-skew(C @ b))  # [.x]_paper = -[.x]
    return H


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


@implements("KZL 12")
def euler_attitude_rows(C_bn: ArrayLike, roll: float, pitch: float, *, deg: bool = False) -> Array:
    r"""Rows (3 x 17) of the Euler-angle attitude observation (KZL Eq. 12/13, corrected block).

    The block is :math:`\partial(\phi,\theta,\psi)/\partial\Delta\psi = J_b^{-1}\hat R_n^b`.

    Parameters
    ----------
    C_bn : (3, 3) array
        Computed body-to-NED attitude (a rotation matrix).
    roll : float
        Roll, rad (deg with ``deg=True``).
    pitch : float
        Pitch, rad (deg), in (-90, 90) deg.
    deg : bool, default False
        The angles are in degrees.

    Returns
    -------
    (3, 17) ndarray
        Non-zero only in the misalignment columns (rad per rad).

    Raises
    ------
    ValueError
        If ``C_bn`` is not a rotation matrix or an angle is out of range for its unit.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eqs. (12)-(13).

    Examples
    --------
    >>> import numpy as np
    >>> H = euler_attitude_rows(np.eye(3), 0.0, 0.0)
    >>> H[:, 6:9].tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    """
    C = as_finite_array("C_bn", C_bn, ndim=2)
    H = np.zeros((3, 17))
    H[:, _A] = euler_rate_matrix_body(roll, pitch, deg=deg) @ C.T
    return H


@implements("KZL 13")
def tc_attitude_observation_matrix(
    los_ned: ArrayLike, C_bn: ArrayLike, roll: float, pitch: float, *, deg: bool = False
) -> Array:
    r"""Observation matrix of KZL Eq. 13 stacked over satellites: :math:`(2 \nu + 3) \times 17`.

    Parameters
    ----------
    los_ned : (nu, 3) array
        Unit LOS vectors receiver -> satellite in NED.
    C_bn : (3, 3) array
        Computed body-to-NED attitude (a rotation matrix).
    roll : float
        Roll, rad (deg with ``deg=True``).
    pitch : float
        Pitch, rad (deg), in (-90, 90) deg.
    deg : bool, default False
        The angles are in degrees.

    Returns
    -------
    (2 nu + 3, 17) ndarray
        Code and Doppler rows per satellite, then the three Euler-angle rows.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (13).

    Examples
    --------
    >>> import numpy as np
    >>> tc_attitude_observation_matrix(np.tile([0.0, 0.0, -1.0], (4, 1)), np.eye(3), 0.0, 0.0).shape
    (11, 17)
    """
    return np.vstack([code_doppler_rows(los_ned), euler_attitude_rows(C_bn, roll, pitch, deg=deg)])


@implements("KZL 17")
def tc_dd_observation_matrix(los_ned: ArrayLike, C_bn: ArrayLike, baselines_b: ArrayLike) -> Array:
    """Observation matrix of KZL Eq. 17 for ``nu`` satellites (first = master).

    Code/Doppler rows for every satellite, then the DD rows satellite by satellite.

    Parameters
    ----------
    los_ned : (nu, 3) array
        Unit LOS vectors receiver -> satellite in NED (the first is the master).
    C_bn : (3, 3) array
        Computed body-to-NED attitude.
    baselines_b : (k, 3) array
        Body baselines, m.

    Returns
    -------
    (2 nu + (nu - 1) k, 17) ndarray
        Stacked observation matrix.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (17).

    Examples
    --------
    >>> import numpy as np
    >>> tc_dd_observation_matrix(np.tile([0.0, 0.0, -1.0], (4, 1)), np.eye(3), np.eye(3)[:2]).shape
    (14, 17)
    """
    L = as_finite_array("los_ned", los_ned, ndim=2)
    rows = [code_doppler_rows(L)]
    for n in range(1, L.shape[0]):
        rows.append(dd_observation_rows(L[0], L[n], C_bn, baselines_b))
    return np.vstack(rows)


@implements("KZL 13")
def attitude_observation_rows_count(nu: int) -> int:
    r"""Rows of the stacked Eq. 13 matrix, counted from the builder (code, Doppler, 3 angles).

    Parameters
    ----------
    nu : int
        Number of visible satellites (``>= 1``).

    Returns
    -------
    int
        :math:`2 \nu + 3`.

    Raises
    ------
    ValueError
        If ``nu`` is not an integer of at least 1.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (13).

    Examples
    --------
    >>> attitude_observation_rows_count(5)
    13
    """
    require_integer("nu", nu, minimum=1)
    los = np.tile([0.0, 0.0, -1.0], (nu, 1))
    return tc_attitude_observation_matrix(los, np.eye(3), 0.0, 0.0).shape[0]


@implements("KZL 17")
def dd_observation_rows_count(nu: int, n_baselines: int = 2) -> int:
    r"""Rows of the stacked Eq. 17 matrix, counted from the builder.

    Parameters
    ----------
    nu : int
        Number of visible satellites (``>= 1``).
    n_baselines : int, default 2
        Number of baselines.

    Returns
    -------
    int
        :math:`2 \nu + (\nu - 1) n_b` with :math:`n_b` = ``n_baselines``.

    Raises
    ------
    ValueError
        If ``nu`` is not an integer of at least 1.

    References
    ----------
    Knedlik, Zhou & Loffeld, "On Position and Attitude Estimation for Remote Sensing with
    Bistatic SAR" (2009), Eq. (17).

    Examples
    --------
    >>> dd_observation_rows_count(5)
    18
    """
    require_integer("nu", nu, minimum=1)
    los = np.tile([0.0, 0.0, -1.0], (nu, 1))
    return tc_dd_observation_matrix(los, np.eye(3), np.eye(3)[:n_baselines]).shape[0]


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "wavelength": POSITIVE,
        "sigma_phase": POSITIVE,
        "n_baselines": COUNT,
        "nu": COUNT0,
        "C_bn": ROTATION,
        "pitch": Angle(90.0, "a pitch angle"),
    },
)
