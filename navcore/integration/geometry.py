r"""GPS geometry along a flight for the covariance engine: where the satellites are, which
channels are locked, which satellites to track.

:func:`satellite_geometry` gives the line of sight and elevation of each tracked satellite
at every sample of a trajectory; :func:`lock_table` the code and carrier lock of each
channel over time (losses and reacquisitions); :func:`best_geometry_channels` the fixed
channels of smallest mean PDOP. The schedules of :mod:`navcore.integration.schedules` read
them.

References
----------
.. [1] G. T. Schmidt and R. E. Phillips, NATO RTO-EN-SET-116, Sec. 2.1-2.6.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT,
    ModelDomainError,
    Range,
    check_public,
    require_positive,
)
from navcore.gnss.constellation import Constellation
from navcore.inertial.trajectories import Trajectory

__all__ = [
    "SatelliteGeometry",
    "best_geometry_channels",
    "lock_table",
    "satellite_geometry",
]

Array = NDArray[np.float64]


# --------------------------------------------------------------------------- GPS geometry


@dataclass(frozen=True)
class SatelliteGeometry:
    """Line-of-sight unit vectors (NED) and elevations of tracked channels over a trajectory.

    ``u_ned[k, c]`` points from the vehicle to the satellite of channel ``c`` at step ``k``.

    Attributes
    ----------
    prn : (c,) ndarray of int
        PRN of each channel.
    u_ned : (N, c, 3) ndarray
        Unit line-of-sight vectors in NED.
    elevation : (N, c) ndarray
        Elevations, rad.
    """

    prn: NDArray[np.int64]
    u_ned: Array
    elevation: Array


def satellite_geometry(
    trajectory: Trajectory, constellation: Constellation, channels: Sequence[int]
) -> SatelliteGeometry:
    """Vectorised line-of-sight geometry of satellites along a trajectory.

    Parameters
    ----------
    trajectory : Trajectory
        Sampled flight path (geodetic latitude and longitude in rad, height in m).
    constellation : Constellation
        Satellite orbits.
    channels : sequence of int
        Indices into the constellation of the tracked satellites.

    Returns
    -------
    SatelliteGeometry
        PRNs, NED unit vectors from vehicle to satellite ``(N, c, 3)`` and elevations ``(N, c)``
        in rad.

    Examples
    --------
    >>> from navcore.gnss.constellation import nominal_gps_constellation
    >>> from navcore.inertial.trajectories import straight_and_level
    >>> geo = satellite_geometry(straight_and_level(2.0), nominal_gps_constellation(), [0, 1])
    >>> geo.u_ned.shape, geo.elevation.shape
    ((3, 2, 3), (3, 2))
    """
    ch = np.asarray(channels, dtype=np.int64)
    lat, lon, h = trajectory.lat, trajectory.lon, trajectory.h
    from navcore.frames import geodetic_to_ecef

    r_user = geodetic_to_ecef(lat, lon, h)  # (N, 3)
    r_sat = constellation.positions_ecef(trajectory.t)[:, ch]  # (N, c, 3)
    d = r_sat - r_user[:, None, :]
    u = d / np.linalg.norm(d, axis=-1, keepdims=True)
    sl, cl, so, co = np.sin(lat), np.cos(lat), np.sin(lon), np.cos(lon)
    C_en = np.stack(
        [
            np.stack([-sl * co, -sl * so, cl], -1),
            np.stack([-so, co, np.zeros_like(lat)], -1),
            np.stack([-cl * co, -cl * so, -sl], -1),
        ],
        -2,
    )  # (N, 3, 3) ECEF -> NED
    u_ned = np.einsum("nij,ncj->nci", C_en, u)
    el = np.arcsin(np.clip(-u_ned[..., 2], -1.0, 1.0))
    return SatelliteGeometry(constellation.prn[ch], u_ned, el)


def lock_table(
    t: ArrayLike,
    n_channels: int,
    events: Sequence[tuple[float, int, str, bool]],
    *,
    start_locked: bool = True,
) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """Code and carrier lock of each channel over time from a list of events.

    Parameters
    ----------
    t : (N,) array
        Times, s.
    n_channels : int
        Number of receiver channels.
    events : sequence of ``(time, channel, "code" | "carrier", locked)``
        From ``time`` (s) on, the channel's code or carrier is (un)locked. Events apply in
        time order, whatever their order in the list; events at the same time apply in the
        order listed, so the last of them sets the state.
    start_locked : bool, default True
        Lock state of every channel before its first event.

    Returns
    -------
    code : (N, n_channels) bool ndarray
        Code lock per step and channel.
    carrier : (N, n_channels) bool ndarray
        Carrier lock per step and channel.

    Raises
    ------
    ValueError
        If an event's kind is not ``"code"`` or ``"carrier"``.

    Examples
    --------
    >>> code, carrier = lock_table([0.0, 1.0, 2.0], 2, [(1.0, 0, "carrier", False)])
    >>> carrier.tolist()
    [[True, True], [False, True], [False, True]]
    """
    t = np.asarray(t, dtype=float)
    code = np.full((t.size, n_channels), start_locked)
    carrier = np.full((t.size, n_channels), start_locked)
    for time, c, kind, locked in sorted(events, key=lambda e: e[0]):
        if kind not in ("code", "carrier"):
            raise ValueError(f"event kind must be 'code' or 'carrier', got {kind!r}")
        target = code if kind == "code" else carrier
        target[t >= time, c] = locked
    return code, carrier


def best_geometry_channels(
    trajectory: Trajectory, constellation: Constellation, n: int = 4, mask_deg: float = 10.0
) -> NDArray[np.int64]:
    """The ``n`` satellites with the smallest mean PDOP above ``mask_deg`` for the whole trajectory.

    Brute force over the combinations of the satellites that stay visible; the PDOP is
    averaged over 12 samples spread evenly from the trajectory's first sample to its last
    (indices ``linspace(0, N - 1, 12)`` rounded down).

    Parameters
    ----------
    trajectory : Trajectory
        Sampled flight path.
    constellation : Constellation
        Satellite orbits.
    n : int, default 4
        Number of channels to choose (``> 0``).
    mask_deg : float, default 10.0
        Elevation mask, degrees.

    Returns
    -------
    (n,) ndarray of int
        Indices into the constellation of the chosen satellites.

    Raises
    ------
    ValueError
        If ``n`` is not positive.
    ModelDomainError
        If fewer than ``n`` satellites stay above the mask for the whole trajectory, or no
        combination of them gives a usable geometry (a ``ValueError``: the fixed channels this
        selection models do not exist for that flight).

    Examples
    --------
    >>> from navcore.gnss.constellation import nominal_gps_constellation
    >>> from navcore.inertial.trajectories import straight_and_level
    >>> tr = straight_and_level(60.0, speed=100.0, dt=10.0, lat0=0.5)
    >>> best_geometry_channels(tr, nominal_gps_constellation(), n=4).size
    4
    """
    from itertools import combinations

    require_positive("n", n)
    geo = satellite_geometry(trajectory, constellation, range(constellation.prn.size))
    always = np.flatnonzero(np.all(geo.elevation >= mask_deg * np.pi / 180, axis=0))
    if always.size < n:
        raise ModelDomainError(
            f"only {always.size} satellites stay above mask_deg={mask_deg} for the whole trajectory",
            case=(
                f"only {always.size} satellites stay above the {mask_deg:g} deg elevation mask "
                "for the whole flight"
            ),
        )
    ks = np.linspace(0, len(trajectory) - 1, 12).astype(int)
    best, best_val = None, np.inf
    for combo in combinations(always.tolist(), n):
        u = geo.u_ned[np.ix_(ks, np.asarray(combo, dtype=np.intp))]  # (K, n, 3)
        G = np.concatenate([-u, np.ones((*u.shape[:2], 1))], axis=-1)
        GtG = np.einsum("kni,knj->kij", G, G)
        if np.any(np.abs(np.linalg.det(GtG)) < 1e-9):
            continue
        Q = np.linalg.inv(GtG)
        val = float(np.mean(np.sqrt(Q[:, 0, 0] + Q[:, 1, 1] + Q[:, 2, 2])))
        if val < best_val:
            best, best_val = combo, val
    if best is None:
        raise ModelDomainError(
            "no satellite combination gives a usable geometry",
            case=f"no {n} satellites that stay above the mask give a usable geometry throughout the flight",
        )
    return np.asarray(best, dtype=np.int64)


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "mask_deg": Range(-90.0, 90.0),
        "n_channels": COUNT,
    },
)
