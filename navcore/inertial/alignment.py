r"""Initial alignment of a low-cost IMU: accelerometer levelling and heading from GPS velocity.

Levelling (KZL Eqs. 2-3). A level, unaccelerated IMU measures the specific force
:math:`f^b = R_n^b [0, 0, -g]^T`, i.e. :math:`f^b = -g[-\sin\theta,\ \sin\phi\cos\theta,\
\cos\phi\cos\theta]`. Solving for roll and pitch gives

.. math::

    \theta = \arctan\frac{f_x}{\sqrt{f_y^2 + f_z^2}},\qquad
    \phi = \operatorname{atan2}(-f_y, -f_z).

The paper prints :math:`\theta = \arctan(-a_x/\sqrt{a_y^2+a_z^2})` and
:math:`\phi = \operatorname{atan2}(a_y, a_z)`, which is the same pair for
:math:`a = -f` (the *reaction* to gravity, "gravity measured by the accelerometer"), not for
the specific force of Eq. 8. :func:`levelling` implements both conventions so the book can
show the difference.

Heading (KZL Eq. 4): the track angle :math:`\psi = \operatorname{atan2}(v_E, v_N)`; equal to
the heading only without crab or sideslip.

References
----------
.. [1] S. Knedlik, J. Zhou, O. Loffeld (2009), Eqs. (2)-(4).
.. [2] P. D. Groves (2013), Sec. 5.6.2 (levelling).
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import as_finite_array, check_public
from navcore.trace import implements

__all__ = ["heading_from_velocity", "levelling", "levelling_as_printed"]

Array = NDArray[np.float64]


@implements("KZL 2", "KZL 3", "KZL 8")
def levelling(
    f_b: ArrayLike, convention: Literal["specific-force", "gravity-reaction"] = "specific-force"
) -> tuple[Array, Array]:
    """Roll and pitch (rad) from an averaged accelerometer vector (KZL Eqs. 2-3, corrected).

    Parameters
    ----------
    f_b : (..., 3) array
        Averaged accelerometer output in body axes (m/s²).
    convention : {"specific-force", "gravity-reaction"}
        ``"specific-force"``: ``f_b`` is the specific force of KZL Eq. 8 (level at rest:
        ``[0, 0, -g]``). ``"gravity-reaction"``: ``f_b`` is its negative, the convention
        under which the printed Eqs. 2-3 are right.

    Returns
    -------
    roll, pitch : arrays
        Bank (roll) ``phi`` and elevation (pitch) ``theta`` in radians.

    Raises
    ------
    ValueError
        If ``f_b`` does not end in an axis of 3 or is not finite, or ``convention`` is unknown.

    Examples
    --------
    >>> roll, pitch = levelling([0.0, 0.0, -9.81])
    >>> float(roll), float(pitch)
    (-0.0, 0.0)
    """
    f = as_finite_array("f_b", f_b)
    if f.shape[-1] != 3:
        raise ValueError(f"f_b must have shape (..., 3), got {f.shape}")
    if convention == "gravity-reaction":
        f = -f
    elif convention != "specific-force":
        raise ValueError(f"convention must be 'specific-force' or 'gravity-reaction', got {convention!r}")
    fx, fy, fz = f[..., 0], f[..., 1], f[..., 2]
    pitch = np.arctan(fx / np.hypot(fy, fz))
    roll = np.arctan2(-fy, -fz)
    return roll, pitch


@implements("KZL 2", "KZL 3")
def levelling_as_printed(a_b: ArrayLike, roll_form: str = "atan2") -> tuple[Array, Array]:
    """KZL Eqs. 2-3 exactly as printed.

    ``theta = arctan(-a_x/sqrt(a_y^2+a_z^2))``, ``phi = arctan_2(a_y / a_z)``. The printed roll
    names the two-argument arctangent but gives it one argument, the ratio ``a_y / a_z``:
    ``roll_form`` picks the reading. Correct only if ``a_b`` is minus the specific force (the
    one-argument reading also returns the roll of a level specific force, for ``|roll| < 90``
    deg, while the pitch has the wrong sign under every reading).

    Parameters
    ----------
    a_b : (..., 3) array
        Averaged accelerometer output in body axes, m/s².
    roll_form : {"atan2", "arctan"}, optional
        ``"atan2"``: ``atan2(a_y, a_z)``, the two-argument function the name ``arctan_2``
        calls for (default); ``"arctan"``: ``arctan(a_y / a_z)``, the one-argument arctangent of
        the printed ratio.

    Returns
    -------
    roll : ndarray
        Roll ``phi``, rad.
    pitch : ndarray
        Pitch ``theta``, rad.

    Raises
    ------
    ValueError
        If a y-z component is zero (pitch of +-90 deg), ``a_z`` is zero with ``roll_form="arctan"``,
        or ``roll_form`` is not one of the two readings.

    References
    ----------
    Knedlik, Zhou & Loffeld (2009), Eqs. (2)-(3).

    Examples
    --------
    >>> roll, pitch = levelling_as_printed([0.5, 0.0, 9.81])
    >>> round(float(roll), 4), round(float(pitch), 4)
    (0.0, -0.0509)
    >>> [round(float(np.degrees(levelling_as_printed([0.0, 0.0, -9.81], form)[0])), 1)
    ...  for form in ("atan2", "arctan")]
    [180.0, -0.0]
    """
    if roll_form not in ("atan2", "arctan"):
        raise ValueError(f"roll_form must be 'atan2' or 'arctan', got {roll_form!r}")
    a = as_finite_array("a_b", a_b)
    ax, ay, az = a[..., 0], a[..., 1], a[..., 2]
    if np.any(np.hypot(ay, az) == 0.0):
        raise ValueError("a_b must have a nonzero y-z component (pitch of +-90 deg is undefined here)")
    if roll_form == "arctan":
        if np.any(az == 0.0):
            raise ValueError("a_b must have a nonzero z component for the one-argument arctan(a_y / a_z)")
        roll = np.arctan(ay / az)
    else:
        roll = np.arctan2(ay, az)
    return roll, np.arctan(-ax / np.hypot(ay, az))


@implements("KZL 4")
def heading_from_velocity(v_ned: ArrayLike) -> Array:
    r"""Track angle ``atan2(v_E, v_N)`` from a NED velocity (KZL Eq. 4).

    Parameters
    ----------
    v_ned : (..., 3) array
        NED velocity, m/s (non-zero horizontal part).

    Returns
    -------
    ndarray
        Heading, rad in :math:`(-\pi, \pi]`.

    Raises
    ------
    ValueError
        If the last axis is not 3 long or a horizontal velocity is zero.

    References
    ----------
    Knedlik, Zhou & Loffeld (2009), Eq. (4).

    Examples
    --------
    >>> import numpy as np
    >>> round(float(np.degrees(heading_from_velocity([0.0, 110.0, 0.0]))), 9)
    90.0
    """
    v = as_finite_array("v_ned", v_ned)
    if v.shape[-1] != 3:
        raise ValueError(f"v_ned must have shape (..., 3), got {v.shape}")
    if np.any(np.hypot(v[..., 0], v[..., 1]) == 0):
        raise ValueError("v_ned must have a non-zero horizontal component to define a heading")
    return np.arctan2(v[..., 1], v[..., 0])


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals())
