r"""Target location error from a vehicle's position error and its attitude error over a lever arm.

An observer at a position in error by :math:`\delta r_v` locates a target at the vector
:math:`r` from itself with an attitude (pointing) error :math:`\delta\alpha`; the target's
coordinates are then in error by (SP Sec. 2.6.4)

.. math::

    \begin{gathered}
    \delta r_{tgt} = \delta r_v + \delta\alpha\times r = \delta r_v - [r\times]\,\delta\alpha,\\
    \langle\delta r_{tgt}\delta r_{tgt}^T\rangle = P_r + [r\times] P_\alpha [r\times]^T
    - P_{r\alpha}[r\times]^T - [r\times] P_{r\alpha}^T .
    \end{gathered}

Sign convention: errors are *computed minus true*, and :math:`\delta\alpha` is the small
rotation that carries the true frame into the computed one, :math:`\hat C = (I +
[\delta\alpha\times])\,C`: a lever arm measured in the vehicle frame is resolved as
:math:`\hat C r^b = r + \delta\alpha\times r`, which is the paper's formula. The angle :math:`\psi` of
:mod:`navcore.inertial.error_dynamics` has the opposite sign (:math:`\hat C = (I -
[\psi\times])\,C`, so :math:`\delta\alpha = -\psi`): convert a covariance of that model with
:func:`navcore.inertial.error_dynamics.psi_to_attitude_error` before passing it here, or the
position-attitude cross-covariance :math:`P_{r\alpha}` enters with the wrong sign.

References
----------
.. [SP] G. T. Schmidt and R. E. Phillips, "INS/GPS Integration Architecture Performance
   Comparisons", NATO RTO-EN-SET-116, Sec. 2.6.4 (helicopter scout, target at 8 km).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import as_finite_array, check_public, require_nonnegative, require_symmetric_psd
from navcore.frames import skew
from navcore.trace import implements

__all__ = [
    "pointing_error_m",
    "target_location_covariance",
    "target_location_error",
    "target_location_rss",
]

Array = NDArray[np.float64]


def _vec3(name: str, v: ArrayLike) -> Array:
    a = as_finite_array(name, v)
    if a.shape[-1] != 3:
        raise ValueError(f"{name} must have a last dimension of 3, got shape {a.shape}")
    return a


@implements("SP Sec. 2.6.4")
def target_location_error(dr_vehicle_m: ArrayLike, dalpha_rad: ArrayLike, r_target_m: ArrayLike) -> Array:
    r"""Target coordinate error: position error plus misalignment crossed with the lever arm.

    :math:`\delta r + \delta\alpha \times r`.

    Parameters
    ----------
    dr_vehicle_m : (3,) array
        Vehicle position error, m.
    dalpha_rad : (3,) array
        Attitude (misalignment) error, rad.
    r_target_m : (3,) array
        Lever arm from vehicle to target, m (same frame).

    Returns
    -------
    (3,) ndarray
        Target error, m.

    Raises
    ------
    ValueError
        If an input is not a finite 3-vector.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.6.4.

    Examples
    --------
    >>> target_location_error([1.0, 0, 0], [0, 0, 1e-3], [8000.0, 0, 0]).tolist()
    [1.0, 8.0, 0.0]
    """
    return _vec3("dr_vehicle_m", dr_vehicle_m) + np.cross(
        _vec3("dalpha_rad", dalpha_rad), _vec3("r_target_m", r_target_m)
    )


def target_location_covariance(
    P_position: ArrayLike,
    P_attitude: ArrayLike,
    r_target_m: ArrayLike,
    P_position_attitude: ArrayLike | None = None,
) -> Array:
    r"""Covariance of the target error :func:`target_location_error`.

    :math:`M P M^T` with :math:`M = [I, -[r\times]]` and ``P`` the joint covariance of the position and
    attitude errors: :math:`P_r + [r\times] P_\alpha [r\times]^T - P_{r\alpha} [r\times]^T - [r\times]
    P_{r\alpha}^T`.

    Parameters
    ----------
    P_position : (3, 3) array
        Vehicle position error covariance, m².
    P_attitude : (3, 3) array
        Attitude error covariance, rad².
    r_target_m : (3,) array
        Lever arm from vehicle to target, m (same frame).
    P_position_attitude : (3, 3) array, optional
        Cross-covariance :math:`E[\delta r\, \delta\alpha^T]`, m rad, with ``dalpha`` in the convention of the
        module (:math:`\hat C = (I + [\delta\alpha\times])\, C`); default zero (uncorrelated errors).

    Returns
    -------
    (3, 3) ndarray
        Target error covariance, m².

    Raises
    ------
    ValueError
        If a covariance is not 3x3 symmetric positive semi-definite, the joint covariance is
        not positive semi-definite, ``P_position_attitude`` is not a finite 3x3 matrix or
        ``r_target_m`` not a finite 3-vector.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.6.4.

    Examples
    --------
    >>> import numpy as np
    >>> C = target_location_covariance(np.eye(3), 1e-6 * np.eye(3), [8000.0, 0.0, 0.0])
    >>> np.round(np.diag(C), 6).tolist()
    [1.0, 65.0, 65.0]
    """
    Pr = require_symmetric_psd("P_position", P_position)
    Pa = require_symmetric_psd("P_attitude", P_attitude)
    for name, P in (("P_position", Pr), ("P_attitude", Pa)):
        if P.shape != (3, 3):
            raise ValueError(f"{name} must be 3x3, got shape {P.shape}")
    S = skew(_vec3("r_target_m", r_target_m))
    if P_position_attitude is None:
        C = Pr + S @ Pa @ S.T
    else:
        Pra = as_finite_array("P_position_attitude", P_position_attitude)
        if Pra.shape != (3, 3):
            raise ValueError(f"P_position_attitude must be 3x3, got shape {Pra.shape}")
        require_symmetric_psd(
            "the joint covariance of position and attitude", np.block([[Pr, Pra], [Pra.T, Pa]])
        )
        M = np.hstack([np.eye(3), -S])
        C = M @ np.block([[Pr, Pra], [Pra.T, Pa]]) @ M.T
    return 0.5 * (C + C.T)


def pointing_error_m(misalignment_rad: ArrayLike, range_m: ArrayLike) -> Array | float:
    """Displacement of the target caused by a misalignment perpendicular to the line of sight.

    Parameters
    ----------
    misalignment_rad : array_like
        Attitude error perpendicular to the line of sight, rad (``>= 0``).
    range_m : array_like
        Range to the target, m (``>= 0``).

    Returns
    -------
    float or ndarray
        Displacement, m (small-angle product).

    Raises
    ------
    ValueError
        If an argument is negative.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6.4 (target location).

    Examples
    --------
    >>> pointing_error_m(1e-3, 8000.0)
    8.0
    """
    m = require_nonnegative("misalignment_rad", misalignment_rad)
    r = require_nonnegative("range_m", range_m)
    out = np.multiply(m, r, dtype=float)
    return float(out) if out.ndim == 0 else out


@implements("SP Sec. 2.6.4")
def target_location_rss(
    position_rss_m: ArrayLike, misalignment_rad: ArrayLike, range_m: ArrayLike
) -> Array | float:
    """Root-sum-square of position error and pointing error (independent errors).

    Parameters
    ----------
    position_rss_m : array_like
        Vehicle position error (rss), m (``>= 0``).
    misalignment_rad : array_like
        Attitude error perpendicular to the line of sight, rad (``>= 0``).
    range_m : array_like
        Range to the target, m (``>= 0``).

    Returns
    -------
    float or ndarray
        Target error, m.

    Raises
    ------
    ValueError
        If an argument is negative.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.6.4.

    Examples
    --------
    >>> round(target_location_rss(6.0, 1e-3, 8000.0), 6)
    10.0
    """
    p = require_nonnegative("position_rss_m", position_rss_m)
    out = np.hypot(np.asarray(p, dtype=float), pointing_error_m(misalignment_rad, range_m))
    return float(out) if np.ndim(out) == 0 else out


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals())
