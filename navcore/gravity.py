r"""Normal gravity of a level ellipsoid (WGS-84 by default): Somigliana's formula with height.

On the ellipsoid, the magnitude of normal gravity (gravitation plus the centrifugal
acceleration of the Earth's rotation) at geodetic latitude :math:`\varphi` is Somigliana's
closed form

.. math::

    \gamma(\varphi) = \gamma_e\,\frac{1 + k\sin^2\varphi}{\sqrt{1 - e^2\sin^2\varphi}},
    \qquad k = \frac{b\,\gamma_p}{a\,\gamma_e} - 1,

and at a small height :math:`h` above it the second-order expansion of NIMA TR8350.2
(Eq. 4-3)

.. math::

    \gamma_h = \gamma\left[1 - \frac{2}{a}\left(1 + f + m - 2f\sin^2\varphi\right)h
        + \frac{3}{a^2}h^2\right],

    m = \frac{\omega^2 a^2 b}{GM}.

The equatorial and polar values :math:`\gamma_e, \gamma_p` are not typed in: they follow from
the four defining constants of the level ellipsoid (:math:`a, f, GM, \omega`) through the
closed forms of Heiskanen & Moritz (1967), Eqs. (2-141)-(2-142), with the second
eccentricity :math:`e' = \sqrt{a^2 - b^2}/b`,

.. math::

    q_0 = \tfrac12\left[\left(1 + \tfrac{3}{e'^2}\right)\arctan e' - \tfrac{3}{e'}\right],

    q_0' = 3\left(1 + \tfrac{1}{e'^2}\right)\left(1 - \tfrac{1}{e'}\arctan e'\right) - 1,

.. math::

    \gamma_e = \frac{GM}{ab}\left(1 - m - \frac{m}{6}\frac{e' q_0'}{q_0}\right),

    \gamma_p = \frac{GM}{a^2}\left(1 + \frac{m}{3}\frac{e' q_0'}{q_0}\right).

WGS-84 gives 9.7803253359 m/s² at the equator and 9.8321849378 m/s² at the poles
(TR8350.2, Table 3.4), against the standard gravity 9.80665 m/s² (``navcore.units.G0``): a
constant g is 2.7 mg too large at the equator and 2.6 mg too small at the poles.

The models of navcore take the gravity magnitude as an argument (``g``); their default is the
constant ``G0``, which is what the papers assume. Pass ``g=normal_gravity(lat, h)`` for the
WGS-84 value at the flight condition.

References
----------
.. [1] NIMA TR8350.2, "Department of Defense World Geodetic System 1984", 3rd ed. (2000),
   Eqs. (4-1) and (4-3), Table 3.4.
.. [2] W. A. Heiskanen and H. Moritz, Physical Geodesy (1967), Sec. 2-7 to 2-10.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import LATITUDE, Range, check_public
from navcore.frames import WGS84, Ellipsoid

__all__ = ["free_air_gradient", "normal_gravity", "normal_gravity_at_equator_and_pole"]

Array = NDArray[np.float64]


def normal_gravity_at_equator_and_pole(ellipsoid: Ellipsoid = WGS84) -> tuple[float, float]:
    """Equatorial and polar normal gravity of a level ellipsoid, from its defining constants.

    Parameters
    ----------
    ellipsoid : Ellipsoid, default WGS84
        Level ellipsoid: ``a``, ``f > 0``, ``gm`` and ``omega``.

    Returns
    -------
    gamma_e : float
        Normal gravity at the equator, m/s².
    gamma_p : float
        Normal gravity at the poles, m/s².

    Raises
    ------
    ValueError
        If the ellipsoid is a sphere (``f = 0``): a rotating sphere is not a level surface.

    References
    ----------
    Heiskanen & Moritz, Physical Geodesy (1967), Eqs. (2-141)-(2-142).

    Examples
    --------
    >>> ge, gp = normal_gravity_at_equator_and_pole()
    >>> round(ge, 10), round(gp, 9)
    (9.7803253359, 9.832184938)
    """
    if ellipsoid.f <= 0.0:
        raise ValueError("ellipsoid must be flattened (f > 0): normal gravity needs a level ellipsoid")
    a, b, gm, w = ellipsoid.a, ellipsoid.b, ellipsoid.gm, ellipsoid.omega
    ep = np.sqrt(a * a - b * b) / b  # second eccentricity e'
    m = w * w * a * a * b / gm
    q0 = 0.5 * ((1.0 + 3.0 / ep**2) * np.arctan(ep) - 3.0 / ep)
    q0p = 3.0 * (1.0 + 1.0 / ep**2) * (1.0 - np.arctan(ep) / ep) - 1.0
    gamma_e = gm / (a * b) * (1.0 - m - m / 6.0 * ep * q0p / q0)
    gamma_p = gm / (a * a) * (1.0 + m / 3.0 * ep * q0p / q0)
    return float(gamma_e), float(gamma_p)


def _terms(lat: Array, ell: Ellipsoid) -> tuple[Array, Array, float, Array]:
    ge, gp = normal_gravity_at_equator_and_pole(ell)
    s2 = np.sin(lat) ** 2
    k = ell.b * gp / (ell.a * ge) - 1.0
    gamma0 = ge * (1.0 + k * s2) / np.sqrt(1.0 - ell.e2 * s2)
    m = ell.omega**2 * ell.a**2 * ell.b / ell.gm
    return gamma0, s2, m, np.asarray(2.0 / ell.a * (1.0 + ell.f + m - 2.0 * ell.f * s2))


def normal_gravity(
    lat: ArrayLike, h: ArrayLike = 0.0, *, deg: bool = False, ellipsoid: Ellipsoid = WGS84
) -> Array:
    r"""Magnitude of normal gravity at geodetic latitude ``lat`` and height ``h``.

    Parameters
    ----------
    lat : float or array
        Geodetic latitude, rad (deg with ``deg=True``).
    h : float or array, default 0.0
        Height above the ellipsoid, m, in [-20 km, 100 km] (the second-order expansion in
        ``h / a``; its neglected third-order term is below :math:`4 \times 10^{-6}` of g at 100 km).
    deg : bool, default False
        The latitude is in degrees.
    ellipsoid : Ellipsoid, default WGS84
        Level ellipsoid (``a``, ``f``, ``gm``, ``omega``).

    Returns
    -------
    ndarray
        Normal gravity, m/s² (broadcast shape of ``lat`` and ``h``; 0-d for scalars).

    Raises
    ------
    ValueError
        If the latitude is out of range for its unit, the height outside [-20 km, 100 km],
        or the ellipsoid a sphere.

    References
    ----------
    NIMA TR8350.2 (2000), Eqs. (4-1) and (4-3).

    Examples
    --------
    >>> round(float(normal_gravity(45.0, deg=True)), 6), round(float(normal_gravity(0.0, 1000.0)), 6)
    (9.806198, 9.777238)
    """
    lat_r = np.radians(np.asarray(lat, dtype=float)) if deg else np.asarray(lat, dtype=float)
    hh = np.asarray(h, dtype=float)
    gamma0, _, _, c1 = _terms(lat_r, ellipsoid)
    return gamma0 * (1.0 - c1 * hh + 3.0 / ellipsoid.a**2 * hh**2)


def free_air_gradient(
    lat: ArrayLike, h: ArrayLike = 0.0, *, deg: bool = False, ellipsoid: Ellipsoid = WGS84
) -> Array:
    r"""Vertical gradient of normal gravity :math:`\partial\gamma / \partial h` (negative: gravity
    falls with height).

    Parameters
    ----------
    lat : float or array
        Geodetic latitude, rad (deg with ``deg=True``).
    h : float or array, default 0.0
        Height above the ellipsoid, m, in [-20 km, 100 km].
    deg : bool, default False
        The latitude is in degrees.
    ellipsoid : Ellipsoid, default WGS84
        Level ellipsoid.

    Returns
    -------
    ndarray
        Gradient, 1/s² (m/s² per m); about :math:`-3.086 \times 10^{-6}` (the free-air gradient of
        0.3086 mGal/m).

    Raises
    ------
    ValueError
        If the latitude is out of range for its unit or the height outside [-20 km, 100 km].

    References
    ----------
    NIMA TR8350.2 (2000), Eq. (4-3), differentiated in ``h``.

    Examples
    --------
    >>> round(float(free_air_gradient(45.0, deg=True)) * 1e6, 4)  # mGal/m is 1e-5 per s^2
    -3.0855
    """
    lat_r = np.radians(np.asarray(lat, dtype=float)) if deg else np.asarray(lat, dtype=float)
    hh = np.asarray(h, dtype=float)
    gamma0, _, _, c1 = _terms(lat_r, ellipsoid)
    return gamma0 * (-c1 + 6.0 / ellipsoid.a**2 * hh)


check_public(globals(), {"lat": LATITUDE, "h": Range(-20_000.0, 100_000.0)})
