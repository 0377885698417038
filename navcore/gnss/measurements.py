r"""Pseudorange and pseudorange-rate (delta-range) measurement models.

.. math::

    \rho_i = \lVert r_i - r \rVert + b,\qquad
    \dot\rho_i = u_i^T (v_i - v) + \dot b,\qquad
    u_i = \frac{r_i - r}{\lVert r_i - r \rVert}

with user position :math:`r` and velocity :math:`v`, satellite :math:`i` position
:math:`r_i` and velocity :math:`v_i`, clock bias :math:`b` and drift :math:`\dot b` in metres
and metres per second. Any frame may be used as long as all vectors share it (ECEF for
physics; the Jacobian rows can be rotated into NED with ``C_en``). Earth rotation during
signal transit (Sagnac) is neglected: over the 0.067-0.086 s transit the Earth turns by
:math:`\omega_{ie}\tau` up to about :math:`6.5 \times 10^{-6}` rad, which moves the range by
:math:`\omega_{ie}(x_i y - y_i x)/c`, up to a few tens of metres, so these models are for
error (Jacobian) analysis, not for positioning from real ECEF ephemerides.

Their Jacobians (with respect to :math:`r, b` and :math:`v, \dot b`), which the error models'
measurement rows implement (:mod:`navcore.inertial.error_model17`, checked against finite
differences of these functions):

.. math::

    \begin{gathered}
    \frac{\partial \rho_i}{\partial r} = -u_i^T,\quad \frac{\partial \rho_i}{\partial b} = 1;\qquad
    \frac{\partial \dot\rho_i}{\partial v} = -u_i^T,\quad
    \frac{\partial \dot\rho_i}{\partial \dot b} = 1;\\
    \frac{\partial \dot\rho_i}{\partial r} = -\frac{(v_i - v)^T (I - u_i u_i^T)}{\lVert r_i - r\rVert}.
    \end{gathered}

References
----------
.. [1] P. D. Groves (2013), Eqs. 8.47, 9.144 and 14.127 (measurement matrices for
   tightly coupled INS/GNSS).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import as_finite_array, check_public

__all__ = [
    "pseudorange",
    "pseudorange_rate",
]

Array = NDArray[np.float64]


def _sat(name: str, r: ArrayLike) -> Array:
    r = as_finite_array(name, r)
    if r.ndim == 1:
        r = r[None, :]
    if r.shape[-1] != 3:
        raise ValueError(f"{name} must have shape (N, 3), got {r.shape}")
    return r


def pseudorange(r_user: ArrayLike, r_sat: ArrayLike, clock_bias_m: float = 0.0) -> Array:
    """Pseudoranges from user position to each satellite, plus the clock bias.

    Parameters
    ----------
    r_user : (3,) array
        User position, m (ECEF or any frame shared with ``r_sat``).
    r_sat : (N, 3) array
        Satellite positions, m.
    clock_bias_m : float, default 0.0
        Receiver clock bias times the speed of light, m.

    Returns
    -------
    (N,) ndarray
        Pseudoranges, m.

    Raises
    ------
    ValueError
        If a position is not finite or ``r_sat`` has the wrong shape.

    Notes
    -----
    The code measurement model of the tightly coupled filter (Schmidt & Phillips, Sec. 2.2).

    Examples
    --------
    >>> pseudorange([0.0, 0.0, 0.0], [[3.0, 4.0, 0.0]], clock_bias_m=1.0).tolist()
    [6.0]
    """
    d = _sat("r_sat", r_sat) - as_finite_array("r_user", r_user)
    return np.linalg.norm(d, axis=-1) + clock_bias_m


def pseudorange_rate(
    r_user: ArrayLike, v_user: ArrayLike, r_sat: ArrayLike, v_sat: ArrayLike, clock_drift_mps: float = 0.0
) -> Array:
    """Pseudorange rates: line-of-sight relative velocity plus clock drift.

    Parameters
    ----------
    r_user : (3,) array
        User position, m.
    v_user : (3,) array
        User velocity, m/s.
    r_sat : (N, 3) array
        Satellite positions, m.
    v_sat : (N, 3) array
        Satellite velocities, m/s.
    clock_drift_mps : float, default 0.0
        Receiver clock drift times the speed of light, m/s.

    Returns
    -------
    (N,) ndarray
        Pseudorange rates, m/s.

    Raises
    ------
    ValueError
        If a satellite coincides with the user or an input is not finite.

    Notes
    -----
    The range-rate measurement model of the tightly coupled filter (Schmidt & Phillips,
    Sec. 2.2).

    Examples
    --------
    >>> pseudorange_rate([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [[10.0, 0.0, 0.0]], [[2.0, 5.0, 0.0]]).tolist()
    [2.0]
    """
    d = _sat("r_sat", r_sat) - as_finite_array("r_user", r_user)
    if np.any(np.linalg.norm(d, axis=-1) == 0.0):
        raise ValueError("r_sat must differ from r_user (zero range has no line of sight)")
    u = d / np.linalg.norm(d, axis=-1, keepdims=True)
    dv = _sat("v_sat", v_sat) - as_finite_array("v_user", v_user)
    return np.einsum("ij,ij->i", u, dv) + clock_drift_mps


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals())
