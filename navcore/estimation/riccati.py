r"""Steady state of the scalar discrete Riccati recursion.

For the scalar model :math:`x_{k+1} = \phi x_k + w_k` (variance :math:`q`),
:math:`z_k = h x_k + v_k` (variance :math:`r`), the prior and posterior variances obey

.. math::

    P^-_{k+1} = \phi^2 P^+_k + q,\qquad
    P^+_k = \frac{P^-_k r}{h^2 P^-_k + r}.

At the fixed point, :math:`P^-` is the positive root of

.. math::

    h^2 (P^-)^2 + \left(r (1 - \phi^2) - q h^2\right) P^- - q r = 0,

which is unique and positive whenever :math:`q > 0, r > 0, h \ne 0`. The root is computed in
the cancellation-free form :math:`2c / (-b - \sqrt{b^2 - 4ac})` when :math:`b > 0`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from navcore._validate import (
    COUNT,
    NONNEGATIVE,
    POSITIVE,
    check_public,
    require_finite,
    require_nonnegative,
    require_positive,
)

__all__ = ["ScalarSteadyState", "scalar_riccati_iterate", "scalar_riccati_steady_state"]


class ScalarSteadyState(NamedTuple):
    """Steady-state variances and gain of a scalar Kalman filter.

    Attributes
    ----------
    prior : float
        Prior variance ``P-`` (state unit squared).
    posterior : float
        Posterior variance ``P+``.
    gain : float
        Kalman gain ``K``.
    """

    prior: float
    posterior: float
    gain: float


def scalar_riccati_steady_state(phi: float, q: float, h: float, r: float) -> ScalarSteadyState:
    r"""Steady-state prior/posterior variance and gain of the scalar Kalman filter.

    Parameters
    ----------
    phi : float
        Transition coefficient (dimensionless).
    q : float
        Process-noise variance per step, in the state's unit squared (``q >= 0``; ``q = 0``
        with :math:`|\phi| \le 1` gives the trivial steady state 0).
    h : float
        Measurement coefficient (``h != 0``; measurement unit per state unit).
    r : float
        Measurement-noise variance, in the measurement's unit squared (``r > 0``).

    Returns
    -------
    ScalarSteadyState
        ``prior`` (P-), ``posterior`` (P+), ``gain`` :math:`K = P^- h / (h^2 P^- + r)`.

    Raises
    ------
    ValueError
        If ``phi`` is not finite, ``q`` is negative, ``r`` is not positive or ``h`` is zero or
        not finite.

    Notes
    -----
    The positive root of the steady-state scalar Riccati equation stated in the module
    docstring (the fixed point of the Kalman filter's variance recursion, Kalman 1960).

    Examples
    --------
    >>> s = scalar_riccati_steady_state(1.0, 1.0, 1.0, 1.0)
    >>> print(f"{s.prior:.4f} {s.posterior:.4f} {s.gain:.4f}")
    1.6180 0.6180 0.6180
    """
    require_finite("phi", phi)
    require_nonnegative("q", q)
    require_positive("r", r)
    if not math.isfinite(h) or h == 0:
        raise ValueError(f"h must be finite and non-zero (the state must be observed), got {h!r}")
    a = h * h
    b = r * (1.0 - phi * phi) - q * h * h
    c = -q * r
    disc = math.sqrt(b * b - 4.0 * a * c)  # b^2 + 4 h^2 q r >= b^2
    if q == 0.0 and abs(phi) > 1.0:
        prior = -b / a  # unstable noiseless state: the non-trivial root
    elif b > 0:
        prior = 2.0 * c / (-b - disc)
    else:
        prior = (-b + disc) / (2.0 * a)
    posterior = prior * r / (h * h * prior + r)
    gain = prior * h / (h * h * prior + r)
    return ScalarSteadyState(prior, posterior, gain)


def scalar_riccati_iterate(
    phi: float, q: float, h: float, r: float, p0: float, steps: int
) -> ScalarSteadyState:
    """Run the scalar Riccati recursion ``steps`` times from prior variance ``p0``.

    Used as the oracle for :func:`scalar_riccati_steady_state` in the tests.

    Parameters
    ----------
    phi : float
        Transition coefficient (dimensionless).
    q : float
        Process-noise variance per step (state unit squared, ``q >= 0``).
    h : float
        Measurement coefficient (measurement unit per state unit).
    r : float
        Measurement-noise variance (measurement unit squared, ``r > 0``).
    p0 : float
        Prior variance before the first update (state unit squared, ``p0 >= 0``).
    steps : int
        Number of update-and-predict steps (a count, bounded).

    Returns
    -------
    ScalarSteadyState
        ``prior`` after the last prediction, ``posterior`` and ``gain`` of the last update
        (NaN for the latter two when ``steps`` is 0).

    Raises
    ------
    ValueError
        If ``p0`` or ``q`` is negative, ``r`` not positive, or ``steps`` not a valid count.

    Notes
    -----
    The recursion of the module docstring, step by step.

    Examples
    --------
    >>> s = scalar_riccati_iterate(1.0, 1.0, 1.0, 1.0, 0.0, 50)
    >>> print(f"{s.prior:.4f} {s.gain:.4f}")
    1.6180 0.6180
    """
    require_nonnegative("p0", p0)
    prior = float(p0)
    posterior = gain = float("nan")
    for _ in range(steps):
        gain = prior * h / (h * h * prior + r)
        posterior = prior * r / (h * h * prior + r)
        prior = phi * phi * posterior + q
    return ScalarSteadyState(prior, posterior, gain)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(globals(), {"q": NONNEGATIVE, "r": POSITIVE, "p0": NONNEGATIVE, "steps": COUNT})
