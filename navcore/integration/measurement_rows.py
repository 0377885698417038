r"""Measurement rows of the 17-state INS error model (KZL): code and Doppler, Euler-angle
attitude, double-difference carrier phase.

The error state is the layout :data:`~navcore.inertial.error_model17.ERROR_LAYOUT_17`. The
code and delta-range rows of KZL Eq. 13 are
:func:`~navcore.inertial.error_model17.code_doppler_rows`; the attitude rows of Eq. 12/13 are
:math:`\partial(\phi,\theta,\psi)/\partial\Delta\psi = J_b^{-1}(\phi,\theta)\,\hat R_n^b`
(:func:`~navcore.gnss.carrier_phase.euler_rate_matrix_body` times the n-to-b rotation), and the
double-difference rows of Eq. 17 are the Jacobian of
:func:`~navcore.gnss.carrier_phase.double_difference_phase` with respect to the attitude
error, :math:`\frac{2\pi}{\lambda}(l^{(m)} - l^{(n)})^T [\hat R l^b_{0i}\times]_{\rm paper}`
with the paper's bracket :math:`[a\times]_{\rm paper} = -[a\times]` (with :math:`l_{01}` in the
first DD row).

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
)
from navcore.frames import skew
from navcore.gnss.carrier_phase import euler_rate_matrix_body
from navcore.inertial.error_model17 import ERROR_LAYOUT_17, code_doppler_rows
from navcore.trace import implements
from navcore.units import GPS_L1_WAVELENGTH_M

__all__ = [
    "attitude_observation_rows_count",
    "dd_observation_rows",
    "dd_observation_rows_count",
    "euler_attitude_rows",
    "tc_attitude_observation_matrix",
    "tc_dd_observation_matrix",
]

Array = NDArray[np.float64]
_A = ERROR_LAYOUT_17.slice("misalignment")


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
        "n_baselines": COUNT,
        "nu": COUNT0,
        "C_bn": ROTATION,
        "pitch": Angle(90.0, "a pitch angle"),
    },
)
