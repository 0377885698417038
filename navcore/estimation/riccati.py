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
    """Steady-state variances and gain of a scalar Kalman filter."""

    prior: float
    posterior: float
    gain: float


def scalar_riccati_steady_state(phi: float, q: float, h: float, r: float) -> ScalarSteadyState:
    """Steady-state prior/posterior variance and gain of the scalar Kalman filter.

    Parameters
    ----------
    phi : float
        Transition coefficient.
    q : float
        Process-noise variance per step (``q > 0``; ``q = 0`` is allowed when
        ``|phi| > 1`` is false, giving the trivial steady state 0).
    h : float
        Measurement coefficient (``h != 0``).
    r : float
        Measurement-noise variance (``r > 0``).

    Returns
    -------
    ScalarSteadyState
        ``prior`` (P-), ``posterior`` (P+), ``gain`` K = P- h / (h^2 P- + r).
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
