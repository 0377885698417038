"""Satellite multilateration geometry: unit vectors, the matrix F and its invariants.

An aircraft's pulse is received by K satellites; the times of arrival are linear (after
linearisation) in the aircraft position p and the unknown emission time tau,

    T = k + tau * 1 + F (p - p*) + eps,    F = U / c,

where the rows of U are unit vectors from the satellites to the aircraft (ATC-10 Eq. 4.2.3).
All the quality measures of the constellation are functions of the projector
``P = F (F'F)^-1 F'`` onto the column space of F:

* ``beta = K - 1'P1 = 1'(I - P)1`` (Eq. 4.5.2, with the "K minus" reading of the printed
  "K^-1", see ATC-10 erratum E4-3);
* ``tr{(F'F)^-1}`` (the position-only dilution);
* the clock-direction term ``S = 1'F(F'F)^-2 F'1``; for K = 3 it equals the rotation
  invariant ``1'(FF')^-1 1``;
* the geometric dilution ``k^2 = tr{(F'F)^-1} + S / beta`` (Eqs. 4.1.1-4.1.2, 4.6.2).

The geometry depends only on the ratio of the orbit radius to the Earth radius for a
spherical Earth; functions take radii in metres (any common unit works).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from navcore._validate import as_finite_array, require_in_range, require_positive
from navcore.trace import implements

__all__ = [
    "EARTH_MEAN_RADIUS_M",
    "GM_EARTH_M3_S2",
    "SIDEREAL_DAY_S",
    "ConstellationParameters",
    "beta_parameter",
    "clock_direction_term",
    "constellation_parameters",
    "frame_dependent_clock_term",
    "geometric_dilution",
    "geometric_dilution_covariance",
    "line_of_sight_matrix",
    "most_widely_spaced_triplet",
    "position_on_sphere",
    "position_trace",
    "synchronous_orbit_radius",
    "zenith_angles_deg",
]

#: IUGG mean Earth radius (spherical Earth model), m.
EARTH_MEAN_RADIUS_M = 6_371_000.0
#: WGS-84 Earth gravitational constant GM, m^3/s^2.
GM_EARTH_M3_S2 = 3.986004418e14
#: Sidereal day, s.
SIDEREAL_DAY_S = 86_164.0905


def synchronous_orbit_radius(gm: float = GM_EARTH_M3_S2, period_s: float = SIDEREAL_DAY_S) -> float:
    """Radius of a circular orbit whose period is one sidereal day (Kepler's third law), m.

    Examples
    --------
    >>> round(synchronous_orbit_radius() / 1e3, 1)
    42164.2
    """
    require_positive("gm", gm)
    require_positive("period_s", period_s)
    return float(np.cbrt(gm * period_s**2 / (4.0 * math.pi**2)))


def position_on_sphere(lat_deg: np.ndarray | float, lon_deg: np.ndarray | float, radius: float) -> np.ndarray:
    """Earth-centred Cartesian position at geocentric latitude/longitude on a sphere.

    Longitudes are east-positive. Returns shape ``(..., 3)``. A synchronous satellite whose
    sub-satellite point is (lat, lon) sits at ``position_on_sphere(lat, lon, r_orbit)``.
    """
    require_positive("radius", radius)
    lat = np.radians(as_finite_array("lat_deg", lat_deg))
    lon = np.radians(as_finite_array("lon_deg", lon_deg))
    return radius * np.stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)], axis=-1)


@implements("ATC10 4.2.2")
def line_of_sight_matrix(satellites: np.ndarray, aircraft: np.ndarray) -> np.ndarray:
    """Unit vectors from each satellite to the aircraft, one per row (K x 3).

    With c = 1 this is the matrix F of ATC-10 Eq. 4.2.2c (its sign is irrelevant to every
    invariant: they are quadratic in F).
    """
    sats = np.atleast_2d(as_finite_array("satellites", satellites))
    ac = as_finite_array("aircraft", aircraft).reshape(3)
    d = ac[None, :] - sats
    n = np.linalg.norm(d, axis=1)
    if np.any(n == 0):
        raise ValueError("satellites must not coincide with the aircraft")
    return d / n[:, None]


def zenith_angles_deg(satellites: np.ndarray, aircraft: np.ndarray) -> np.ndarray:
    """Zenith angle of each satellite seen from the aircraft (spherical local vertical), deg."""
    ac = as_finite_array("aircraft", aircraft).reshape(3)
    up = ac / np.linalg.norm(ac)
    toward_sat = -line_of_sight_matrix(satellites, ac)
    return np.degrees(np.arccos(np.clip(toward_sat @ up, -1.0, 1.0)))


def _check_f(F: np.ndarray) -> np.ndarray:
    F = np.atleast_2d(as_finite_array("F", F))
    if F.ndim != 2 or F.shape[1] != 3 or F.shape[0] < 3:
        raise ValueError(f"F must be K x 3 with K >= 3, got shape {F.shape}")
    if np.linalg.matrix_rank(F) < 3:
        raise ValueError("F must have rank 3 (satellites not coplanar with the aircraft)")
    return F


@implements("ATC10 4.5.2")
def beta_parameter(F: np.ndarray) -> float:
    """``beta = K - 1'F(F'F)^-1 F'1 = |(I - P)1|^2`` (ATC-10 Eq. 4.5.2, "K minus" reading).

    Zero for K = 3 (P = I), which is why the clock cannot be estimated with three
    satellites. Computed as the squared least-squares residual of 1 on F.
    """
    F = _check_f(F)
    ones = np.ones(F.shape[0])
    coef, *_ = np.linalg.lstsq(F, ones, rcond=None)
    r = ones - F @ coef
    return float(r @ r)


def position_trace(F: np.ndarray) -> float:
    """``tr{(F'F)^-1}``: the position dilution with the clock known."""
    F = _check_f(F)
    return float(np.trace(np.linalg.inv(F.T @ F)))


@implements("ATC10 4.5.30")
def clock_direction_term(F: np.ndarray) -> float:
    """``S = 1'F(F'F)^-2 F'1``, the position error per unit clock-error variance.

    It equals ``|(F'F)^-1 F'1|^2``; for K = 3 it is the rotation invariant ``1'(FF')^-1 1``
    (the correct quantity for ATC-10 Eq. 4.5.30, erratum E4-1).
    """
    F = _check_f(F)
    v = np.linalg.solve(F.T @ F, F.T @ np.ones(F.shape[0]))
    return float(v @ v)


@implements("ATC10 4.5.30")
def frame_dependent_clock_term(F: np.ndarray) -> float:
    """``1'(F'F)^-1 1`` for K = 3: the term printed in ATC-10 Eq. 4.5.30.

    It is NOT invariant under a rotation of the coordinate frame (F -> F R'): kept only to
    reproduce what the paper tabulated (erratum E4-1).
    """
    F = _check_f(F)
    if F.shape[0] != 3:
        raise ValueError(f"F must be 3 x 3 for the printed three-satellite term, got {F.shape}")
    ones = np.ones(3)
    return float(ones @ np.linalg.solve(F.T @ F, ones))


@implements("ATC10 4.1.1")
def geometric_dilution_covariance(F: np.ndarray, H: np.ndarray | None = None) -> np.ndarray:
    """Position error covariance per unit sigma^2, ``[F'H'(HH')^-1 H F]^-1`` (Eq. 4.1.1).

    ``H`` is any (K-1) x K matrix of full row rank whose rows sum to zero (it removes the
    common emission time by differencing). The default differences against satellite 1.
    """
    F = _check_f(F)
    K = F.shape[0]
    if H is None:
        H = np.hstack([-np.ones((K - 1, 1)), np.eye(K - 1)])
    H = np.atleast_2d(as_finite_array("H", H))
    if H.shape != (K - 1, K):
        raise ValueError(f"H must be (K-1) x K = {(K - 1, K)}, got {H.shape}")
    if not np.allclose(H.sum(axis=1), 0.0, atol=1e-12 * max(1.0, np.abs(H).max())):
        raise ValueError("H must have rows summing to zero (differencing matrix)")
    HF = H @ F
    info = HF.T @ np.linalg.solve(H @ H.T, HF)
    return np.linalg.inv(info)


@implements("ATC10 4.1.2", "ATC10 4.6.2")
def geometric_dilution(F: np.ndarray) -> float:
    """``k = sqrt(tr{(F'F)^-1} + S / beta)`` (Eqs. 4.1.2 and 4.6.2); inf when beta = 0."""
    b = beta_parameter(F)
    if b <= 1e-12 * F.shape[0]:
        return math.inf
    return math.sqrt(position_trace(F) + clock_direction_term(F) / b)


@dataclass(frozen=True)
class ConstellationParameters:
    """The invariants of a constellation (ATC-10 Table 4.2 columns) for one satellite set."""

    beta: float
    trace: float
    clock_term: float
    dilution: float


def constellation_parameters(F: np.ndarray) -> ConstellationParameters:
    """Compute beta, tr{(F'F)^-1}, S and the geometric dilution k of ``F``."""
    F = _check_f(F)
    return ConstellationParameters(
        beta=beta_parameter(F),
        trace=position_trace(F),
        clock_term=clock_direction_term(F),
        dilution=geometric_dilution(F),
    )


def most_widely_spaced_triplet(
    satellites: np.ndarray,
    aircraft: np.ndarray,
    cone_half_angle_deg: float,
    criterion: str = "trace",
) -> tuple[tuple[int, int, int], float]:
    """Best three satellites inside the cone about the local vertical (0-based indices).

    ``criterion``: ``"trace"`` minimises tr{(F3'F3)^-1}; ``"det"`` maximises |det F3|;
    ``"angle"`` maximises the smallest pairwise angle between the lines of sight. Returns the
    triplet and its score (trace, |det| or angle in degrees).
    """
    require_in_range("cone_half_angle_deg", cone_half_angle_deg, 0.0, 90.0)
    if criterion not in ("trace", "det", "angle"):
        raise ValueError(f"criterion must be 'trace', 'det' or 'angle', got {criterion!r}")
    U = line_of_sight_matrix(satellites, aircraft)
    inside = np.flatnonzero(zenith_angles_deg(satellites, aircraft) <= cone_half_angle_deg + 1e-9)
    best: tuple[tuple[int, int, int], float] | None = None
    for tri in itertools.combinations(inside.tolist(), 3):
        F3 = U[list(tri)]
        if criterion == "trace":
            d = abs(np.linalg.det(F3))
            score = math.inf if d < 1e-12 else float(np.trace(np.linalg.inv(F3.T @ F3)))
            better = best is None or score < best[1]
        elif criterion == "det":
            score = float(abs(np.linalg.det(F3)))
            better = best is None or score > best[1]
        else:
            cosines = [float(F3[i] @ F3[j]) for i, j in ((0, 1), (0, 2), (1, 2))]
            score = float(np.degrees(np.arccos(np.clip(max(cosines), -1.0, 1.0))))
            better = best is None or score > best[1]
        if better:
            best = (tuple(tri), score)  # type: ignore[assignment]
    if best is None:
        raise ValueError("fewer than three satellites lie inside the cone")
    return best
