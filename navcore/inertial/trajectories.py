r"""Vehicle trajectories for covariance analysis, built from kinematic segments.

A trajectory is sampled on a uniform time grid and gives what the error dynamics need:
position (geodetic and local NED), ground velocity, specific force, body attitude and body
angular rate. It is generated from a list of :class:`Segment` objects, each holding the
rates of airspeed, heading and flight-path angle constant for its duration (point-mass
kinematics, coordinated turns, body x-axis along the velocity, no wind, spherical Earth of
radius :math:`a` for the latitude/longitude rates, integrated along the path):

.. math::

    \begin{gathered}
    v^n = V\,[\cos\gamma\cos\chi,\ \cos\gamma\sin\chi,\ -\sin\gamma],\qquad
    f^n = \dot v^n - g^n,\\
    \tan\phi = \frac{V\dot\chi\cos\gamma}{g\cos\gamma + V\dot\gamma},\\
    L(t) = L_0 + \int_0^t \frac{v_N}{a + h}\,dt,\qquad
    \lambda(t) = \lambda_0 + \int_0^t \frac{v_E}{(a + h)\cos L}\,dt.
    \end{gathered}

The bank angle :math:`\phi` (yaw :math:`\chi`, pitch :math:`\gamma`, roll :math:`\phi`) makes
the turn coordinated: the body-y specific force
:math:`f_y^b = V\dot\chi\cos\gamma\cos\phi - (g\cos\gamma + V\dot\gamma)\sin\phi` vanishes.
In a turn at constant flight-path angle this is :math:`\tan\phi = V\dot\chi/g`, not
:math:`V\dot\chi\cos\gamma/g` (which leaves 0.100 m/s² of side force at 200 m/s,
0.03 rad/s and a 0.2 rad climb); the root with :math:`|\phi| \le 90^\circ` is taken.

Frames and simplifications: ``vel_ned`` is the ground velocity in the local NED frame and
``pos_ned`` its time integral (north/east distance travelled and height loss, m);
``f_ned`` is the specific force (m/s²) in NED of a flat, non-rotating Earth with constant
gravity ``g`` along +down: it omits the Coriolis and transport terms
:math:`(2\omega_{ie} + \omega_{en})\times v` of the true specific force (about 2 mg at
200 m/s, 0.2 % of the 1 g that couples a tilt into the velocity error) and has no latitude
or height model of gravity. Nothing adds that term back: the error dynamics
(:mod:`navcore.inertial.error_dynamics`) use this ``f_ned`` in their tilt coupling
:math:`-\psi\times f^n`, and the Coriolis term they do carry,
:math:`-(2\omega_{ie} + \omega_{en})\times\delta v` in the velocity-error row
(:math:`F_{vv}`), acts on the velocity *error*, not on the vehicle's velocity. ``C_bn``
rotates body to NED and ``omega_nb_b`` (rad/s) is the body rate relative to NED, resolved in
the body frame (from the sampled ``C_bn`` by central differences).

That is the level of detail the SP Section 2.6 missions need: straight-and-level legs,
climbs, dives, turns and terrain-following height changes.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import NDArray

from navcore._validate import (
    COUNT,
    LATITUDE,
    LONGITUDE,
    NONNEGATIVE,
    POSITIVE,
    Angle,
    check_public,
    require_nonnegative,
    require_positive,
)
from navcore.units import G0, WGS84_A

__all__ = ["Segment", "Trajectory", "euler_to_dcm_stack", "fly", "straight_and_level", "trajectory_window"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Segment:
    """A flight segment with constant rates.

    Attributes
    ----------
    duration : float
        Seconds.
    speed_rate : float
        Along-track acceleration (m/s²).
    turn_rate : float
        Heading rate (rad/s), coordinated turn.
    path_angle_rate : float
        Flight-path-angle rate (rad/s); positive pitches up.
    """

    duration: float
    speed_rate: float = 0.0
    turn_rate: float = 0.0
    path_angle_rate: float = 0.0

    def __post_init__(self) -> None:
        require_positive("Segment.duration", self.duration)


@dataclass(frozen=True)
class Trajectory:
    """Trajectory samples on a uniform grid (all arrays have ``len(t)`` rows).

    Attributes
    ----------
    t : (N,) ndarray
        Times, s.
    lat : (N,) ndarray
        Geodetic latitude, rad.
    lon : (N,) ndarray
        Longitude, rad.
    h : (N,) ndarray
        Height, m.
    pos_ned : (N, 3) ndarray
        Position from the start, m (NED).
    vel_ned : (N, 3) ndarray
        Ground velocity, m/s (NED).
    f_ned : (N, 3) ndarray
        Specific force resolved in NED, m/s².
    C_bn : (N, 3, 3) ndarray
        Body-to-NED attitude.
    omega_nb_b : (N, 3) ndarray
        Body rate relative to the NED frame, body axes, rad/s.
    """

    t: Array
    lat: Array
    lon: Array
    h: Array
    pos_ned: Array
    vel_ned: Array
    f_ned: Array
    C_bn: Array
    omega_nb_b: Array

    @property
    def dt(self) -> float:
        return float(self.t[1] - self.t[0])

    @property
    def speed(self) -> Array:
        """Ground speed magnitude (m/s)."""
        return np.linalg.norm(self.vel_ned, axis=1)

    def __len__(self) -> int:
        return self.t.size


def euler_to_dcm_stack(roll: Array, pitch: Array, yaw: Array, *, deg: bool = False) -> Array:
    r""":math:`C_b^n = R_z(\text{yaw})\, R_y(\text{pitch})\, R_x(\text{roll})` for arrays of angles.

    Parameters
    ----------
    roll : (N,) array
        Roll angles, rad (deg with ``deg=True``).
    pitch : (N,) array
        Pitch angles, rad (deg); any value (a trajectory that loops passes +-90 deg).
    yaw : (N,) array
        Yaw (heading) angles, rad (deg).
    deg : bool, default False
        The angles are in degrees.

    Returns
    -------
    (N, 3, 3) ndarray
        Body-to-NED direction cosine matrices (3-2-1 sequence).

    Examples
    --------
    >>> import numpy as np
    >>> C = euler_to_dcm_stack(np.zeros(1), np.zeros(1), np.array([np.pi / 2]))
    >>> (np.round(C[0], 6) + 0.0).tolist()
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    if deg:
        roll, pitch, yaw = np.radians(roll), np.radians(pitch), np.radians(yaw)
    cr, sr = np.cos(roll), np.sin(roll)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cy, sy = np.cos(yaw), np.sin(yaw)
    return np.stack(
        [
            np.stack([cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr], -1),
            np.stack([sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr], -1),
            np.stack([-sp, cp * sr, cp * cr], -1),
        ],
        -2,
    )


def _cumulative_trapezoid(rate: Array, dt: float) -> Array:
    """Running integral of samples ``rate`` (along the first axis) by the trapezoid rule, from 0."""
    steps = 0.5 * (rate[1:] + rate[:-1]) * dt
    return np.concatenate([np.zeros((1, *rate.shape[1:])), np.cumsum(steps, axis=0)])


def fly(
    segments: Sequence[Segment],
    *,
    dt: float = 1.0,
    lat0: float = 0.0,
    lon0: float = 0.0,
    h0: float = 0.0,
    speed0: float = 0.0,
    heading0: float = 0.0,
    path_angle0: float = 0.0,
    g: float = G0,
    deg: bool = False,
) -> Trajectory:
    """Integrate a sequence of segments into a sampled trajectory.

    Parameters
    ----------
    segments : sequence of Segment
        Manoeuvres flown one after the other (durations in s, rates in rad/s, m/s²).
    dt : float
        Sample interval (s).
    lat0, lon0 : float
        Start latitude and longitude, rad (deg with ``deg=True``); the latitude in
        [-90, 90] deg.
    h0, speed0, heading0, path_angle0 : float
        Start height (m), speed (m/s), heading and flight-path angle (rad, deg with
        ``deg=True``; the flight-path angle in [-90, 90] deg).
    g : float
        Gravity magnitude (m/s²) in the specific force (default the constant ``G0`` the papers
        assume; :func:`navcore.gravity.normal_gravity` gives the WGS-84 value).
    deg : bool, default False
        The start angles (``lat0``, ``lon0``, ``heading0``, ``path_angle0``) are in degrees;
        the segments' rates stay in rad/s and the trajectory is returned in radians.

    Returns
    -------
    Trajectory
        Time (s), geodetic position (rad, rad, m), NED position (m) and velocity (m/s),
        specific force in NED (m/s²), body-to-NED attitude and body rates (rad/s) at
        every sample.

    Raises
    ------
    ValueError
        If ``dt`` or ``g`` is not positive, the segments are too short for two samples, an
        angle is out of range for its unit (a latitude of 45 given as radians), or an argument
        is not finite.

    Examples
    --------
    >>> tr = fly([Segment(100.0)], speed0=200.0, heading0=np.pi / 2)
    >>> round(float(tr.pos_ned[-1, 1]), 6), len(tr)
    (20000.0, 101)
    """
    require_positive("dt", dt)
    require_nonnegative("speed0", speed0)
    if deg:
        lat0, lon0, heading0, path_angle0 = (
            float(np.radians(a)) for a in (lat0, lon0, heading0, path_angle0)
        )
    if not segments:
        raise ValueError("segments must not be empty")
    n_steps = [round(s.duration / dt) for s in segments]
    rates = np.concatenate(
        [
            np.tile([s.speed_rate, s.turn_rate, s.path_angle_rate], (k, 1))
            for s, k in zip(segments, n_steps, strict=True)
        ]
    )
    N = rates.shape[0] + 1
    if N < 2:
        total = sum(s.duration for s in segments)
        raise ValueError(
            f"fly: the segments last {total:g} s, no sample interval of dt = {dt:g} s: a trajectory "
            "needs at least two samples"
        )
    t = np.arange(N) * dt
    # integrate the rates exactly (piecewise-constant)
    V = speed0 + np.concatenate([[0.0], np.cumsum(rates[:, 0]) * dt])
    chi = heading0 + np.concatenate([[0.0], np.cumsum(rates[:, 1]) * dt])
    gam = path_angle0 + np.concatenate([[0.0], np.cumsum(rates[:, 2]) * dt])
    if np.any(V < 0):
        raise ValueError("segments must not make the speed negative")
    v = V[:, None] * np.stack([np.cos(gam) * np.cos(chi), np.cos(gam) * np.sin(chi), -np.sin(gam)], -1)
    pos = _cumulative_trapezoid(v, dt)
    acc = np.gradient(v, dt, axis=0)
    f = acc - np.array([0.0, 0.0, g])
    chi_dot = np.concatenate([rates[:, 1], rates[-1:, 1]])
    gam_dot = np.concatenate([rates[:, 2], rates[-1:, 2]])
    # coordinated turn: zero body-y specific force; the root with |roll| <= 90 deg
    lift = g * np.cos(gam) + V * gam_dot
    roll = np.arctan2(V * chi_dot * np.cos(gam) * np.sign(lift + (lift == 0)), np.abs(lift))
    C = euler_to_dcm_stack(roll, gam, chi)
    # body rate from C^T dC/dt (central differences)
    dC = np.gradient(C, dt, axis=0)
    Om = np.einsum("nji,njk->nik", C, dC)
    w = np.stack([Om[:, 2, 1] - Om[:, 1, 2], Om[:, 0, 2] - Om[:, 2, 0], Om[:, 1, 0] - Om[:, 0, 1]], -1) / 2
    h = h0 - pos[:, 2]
    # the latitude rate v_N / (a + h) and the longitude rate v_E / ((a + h) cos lat),
    # integrated along the path (trapezoid rule, as the position): dividing the north distance
    # by the current a + h would rescale the whole distance already flown after a climb, and
    # dividing the east distance by the current cos(lat) would hold only along a parallel
    lat = lat0 + _cumulative_trapezoid(v[:, 0] / (WGS84_A + h), dt)
    lon_rate = v[:, 1] / ((WGS84_A + h) * np.cos(lat))
    lon = lon0 + _cumulative_trapezoid(lon_rate, dt)
    if np.any(h < -500.0):
        raise ValueError("segments must not fly the vehicle below -500 m")
    return Trajectory(t, lat, lon, h, pos, v, f, C, w)


def straight_and_level(
    duration: float,
    *,
    speed: float = 0.0,
    heading: float = 0.0,
    dt: float = 1.0,
    lat0: float = 0.0,
    lon0: float = 0.0,
    h0: float = 0.0,
    deg: bool = False,
) -> Trajectory:
    """Constant speed, heading and height (``speed = 0`` gives a stationary vehicle).

    Parameters
    ----------
    duration : float
        Length, s (``>= 0``).
    speed : float, default 0.0
        Ground speed, m/s.
    heading : float, default 0.0
        Heading from north, rad (deg with ``deg=True``).
    dt : float, default 1.0
        Sample interval, s (``> 0``).
    lat0 : float, default 0.0
        Start latitude, rad (deg with ``deg=True``), in [-90, 90] deg.
    lon0 : float, default 0.0
        Start longitude, rad (deg with ``deg=True``).
    h0 : float, default 0.0
        Height, m.
    deg : bool, default False
        The angles are in degrees (the trajectory is returned in radians).

    Returns
    -------
    Trajectory
        Samples at ``0, dt, ..., duration``.

    Raises
    ------
    ValueError
        If ``dt`` is not positive, ``duration`` is negative or spans no sample interval
        (``round(duration / dt) < 1``: one sample), or an angle is out of range for its unit
        (``lat0=48.0`` without ``deg=True``).

    Examples
    --------
    >>> tr = straight_and_level(10.0, speed=50.0)
    >>> len(tr), round(float(tr.pos_ned[-1, 0]), 6)
    (11, 500.0)
    """
    require_positive("dt", dt)
    if not round(duration / dt) >= 1:
        raise ValueError(
            f"straight_and_level: duration must span at least one sample interval dt (two samples; "
            f"round(duration / dt) >= 1), got duration={duration!r} with dt={dt!r}"
        )
    return fly(
        [Segment(duration)], dt=dt, lat0=lat0, lon0=lon0, h0=h0, speed0=speed, heading0=heading, deg=deg
    )


def trajectory_window(trajectory: Trajectory, t0: float, t1: float, step: int = 1) -> Trajectory:
    """The samples of ``trajectory`` from the one nearest ``t0`` to the one nearest ``t1``.

    Every field is sliced alike (inclusive of both ends), keeping every ``step``-th sample, so
    a phase of a flight can be analysed on its own (at a coarser step if wanted).

    Parameters
    ----------
    trajectory : Trajectory
        The whole flight.
    t0, t1 : float
        Start and end times, s; each is taken to its nearest sample (the first on a tie).
    step : int, default 1
        Keep every ``step``-th sample from the start (``>= 1``).

    Returns
    -------
    Trajectory
        The window; empty when ``t1``'s sample precedes ``t0``'s.

    Raises
    ------
    ValueError
        If a time is not finite or ``step`` is not a positive integer.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6 (the missions of Figs. 2.4-2.8, evaluated in phases).

    Examples
    --------
    >>> tr = straight_and_level(10.0, speed=50.0)
    >>> w = trajectory_window(tr, 2.2, 8.0, step=3)
    >>> w.t.tolist(), w.pos_ned[:, 0].tolist()
    ([2.0, 5.0, 8.0], [100.0, 250.0, 400.0])
    """
    tr = trajectory
    i0 = int(np.argmin(np.abs(tr.t - t0)))
    i1 = int(np.argmin(np.abs(tr.t - t1)))
    sl = slice(i0, i1 + 1, step)
    return Trajectory(*(getattr(tr, f.name)[sl] for f in fields(tr)))


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "dt": POSITIVE,
        "duration": NONNEGATIVE,
        "g": POSITIVE,
        "lat0": LATITUDE,
        "lon0": LONGITUDE,
        "path_angle0": Angle(90.0, "a flight-path angle"),
        "step": COUNT,
    },
)
