r"""INS error-state dynamics in a local-level (NED) frame, :math:`\psi`-angle form.

State blocks (any subset, in any order, named as in :mod:`navcore.gnss.architectures`):

========================  ====  ================================================================
block                     size  meaning
========================  ====  ================================================================
``position``              3     NED position error (m)
``velocity``              3     velocity error in the computed frame (m/s)
``misalignment``          3     :math:`\psi` angle: computed-frame attitude error (rad)
``gyro bias``             3     gyro bias (the papers' gyro drift), random constant (rad/s)
``gyro scale factor``     3     (-)
``gyro misalignment``     3     small-angle input-axis misalignment of the gyro triad (rad)
``accel bias``            3     (m/s²)
``accel scale factor``    3     (-)
``accel misalignment``    3     small-angle input-axis misalignment of the accelerometers (rad)
``gravity``               3     gravity anomaly, first-order Gauss-Markov (m/s²)
``altimeter bias``        1     barometric altimeter bias, first-order Gauss-Markov (m)
``clock bias``            1     user clock bias (m)
``clock drift``           1     user clock drift (m/s)
``clock g-sensitivity``   1     clock frequency sensitivity to specific force (m/s per g)
``pseudorange bias``      n     one random-constant bias per receiver channel (m)
``range-rate bias``       n     one random-constant bias per receiver channel (m/s)
``doppler bias``          3     Doppler ground-speed sensor bias, body axes (m/s)
``doppler scale factor``  3     (-)
``doppler misalignment``  3     boresight misalignment (rad)
========================  ====  ================================================================

Dynamics (:math:`\psi`-angle form, Benson 1975):

.. math::

    \begin{aligned}
    \delta\dot r &= \delta v - \omega_{en}\times\delta r\\
    \delta\dot v &= -(2\omega_{ie}+\omega_{en})\times\delta v - \psi\times f^n\\
        &\quad + \tfrac{g}{R}\,\mathrm{diag}(-1,-1,2)\,\delta r + C^n_b\,\delta f^b + \delta g\\
    \dot\psi &= -(\omega_{ie}+\omega_{en})\times\psi - C^n_b\,\delta\omega^b_{ib}\\
    \delta f^b &= b_a + \mathrm{diag}(f^b)\,s_a + [f^b\times]\,\mu_a + w_a,\\
    \delta\omega^b_{ib} &= b_g + \mathrm{diag}(\omega^b_{ib})\,s_g + [\omega^b_{ib}\times]\,\mu_g + w_g
    \end{aligned}

Sign convention of the attitude error: every error is *computed minus true*, and the :math:`\psi`
angle is the small rotation that carries the true NED frame into the computed one, so the
computed body-to-NED attitude is

.. math::

    \hat C^n_b = (I - [\psi\times])\,C^n_b,

and a vector measured in body axes is resolved with the error :math:`\hat C^n_b x^b - C^n_b x^b
= -\psi\times(C^n_b x^b)`; that is where :math:`-\psi\times f^n` above comes from (and
the :math:`-C^b_n[v^n\times]\,\psi` term of the Doppler rows of
:func:`navcore.integration.schedules.doppler_schedule`).
:mod:`navcore.inertial.error_model17` and :mod:`navcore.location.target_location` use the
opposite sign, :math:`\hat C = (I + [\delta\alpha\times])\,C`, so
:math:`\delta\alpha = -\psi`; :func:`psi_to_attitude_error` converts a state or covariance
explicitly where the two meet.

The horizontal channels oscillate at the Schuler frequency :math:`\sqrt{g/R}` (84.4-min
period) and the :math:`\psi` angle rotates with Earth and transport rate; the vertical channel is
unstable (:math:`+2g/R`) and must be aided (barometer). A first-order Gauss-Markov
process characterised by a standard deviation and a *distance* constant :math:`d` (SP Table
2.4) has the time constant :math:`\tau = d/|v|` at ground speed :math:`|v|`: rate
:math:`\beta = |v|/d` and driving PSD :math:`2\sigma^2\beta`, so its variance stays
:math:`\sigma^2`. The clock bias integrates the drift plus the g-sensitive frequency error
:math:`k_g\,|f|/g`; its drift is a random walk.

References
----------
.. [1] D. O. Benson, "A Comparison of Two Approaches to Pure-Inertial and Doppler-Inertial
   Error Analysis", IEEE Trans. AES-11(4), 447-455 (1975) (psi-angle form).
.. [2] G. T. Schmidt and R. E. Phillips, NATO RTO-EN-SET-116, Sec. 2.3 and Tables 2.2-2.5.
.. [3] R. G. Brown and P. Y. C. Hwang, Introduction to Random Signals and Applied Kalman
   Filtering, 4th ed. (2012), Sec. 9.3 (clock model) and 2.9 (Gauss-Markov processes).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    COUNT0,
    COVARIANCE,
    LATITUDE,
    NONNEGATIVE,
    POSITIVE,
    ROTATION,
    check_public,
    require_nonnegative,
    require_positive,
)
from navcore.estimation.layout import StateBlock, StateLayout, ins_block_name
from navcore.inertial.imu import ImuSpec
from navcore.trace import implements
from navcore.units import G0, OMEGA_EARTH, WGS84_A

__all__ = [
    "SCHULER_RADIUS_M",
    "ClockModel",
    "ErrorSources",
    "GaussMarkov",
    "earth_rate_ned",
    "error_dynamics",
    "gravity_tuning_psd",
    "gyrocompass_alignment",
    "initial_covariance",
    "ins_error_layout",
    "levelling_alignment",
    "process_noise_psd",
    "psi_to_attitude_error",
    "schuler_frequency",
    "schuler_period",
    "skew_stack",
    "transport_rate_ned",
]

Array = NDArray[np.float64]

#: Earth radius used for the Schuler loop (m): the WGS-84 equatorial radius.
SCHULER_RADIUS_M = WGS84_A


def schuler_frequency(g: float = G0, radius: float = SCHULER_RADIUS_M) -> float:
    """Schuler angular frequency ``sqrt(g / R)``.

    Parameters
    ----------
    g : float, default G0
        Gravity magnitude, m/s² (``> 0``).
    radius : float, default SCHULER_RADIUS_M
        Earth radius, m (``> 0``).

    Returns
    -------
    float
        Angular frequency, rad/s.

    Raises
    ------
    ValueError
        If ``g`` or ``radius`` is not positive.

    Notes
    -----
    The natural frequency of the horizontal INS error loop (Schmidt & Phillips, Sec. 2.3).

    Examples
    --------
    >>> import numpy as np
    >>> round(2 * np.pi / schuler_frequency() / 60, 2)
    84.45
    """
    require_positive("g", g)
    require_positive("radius", radius)
    return float(np.sqrt(g / radius))


def schuler_period(g: float = G0, radius: float = SCHULER_RADIUS_M) -> float:
    r"""Schuler period :math:`2 \pi \sqrt{R / g}`.

    Parameters
    ----------
    g : float, default G0
        Gravity magnitude, m/s² (``> 0``).
    radius : float, default SCHULER_RADIUS_M
        Earth radius, m (``> 0``).

    Returns
    -------
    float
        Period, s (about 84.4 min).

    Raises
    ------
    ValueError
        If ``g`` or ``radius`` is not positive.

    Notes
    -----
    The period of the horizontal INS error oscillation (Schmidt & Phillips, Sec. 2.3).

    Examples
    --------
    >>> round(schuler_period() / 60, 2)
    84.45
    """
    return 2 * np.pi / schuler_frequency(g, radius)


@dataclass(frozen=True)
class GaussMarkov:
    r"""First-order Gauss-Markov process: 1-:math:`\sigma` and a distance constant (m).

    ``distance_constant_m = inf`` makes a random constant.

    Attributes
    ----------
    sigma : float
        Stationary 1-:math:`\sigma` (unit of the process).
    distance_constant_m : float
        Correlation distance, m (``inf`` for a random constant).
    """

    sigma: float
    distance_constant_m: float

    def __post_init__(self) -> None:
        require_nonnegative("GaussMarkov.sigma", self.sigma)
        require_positive("GaussMarkov.distance_constant_m", self.distance_constant_m)


@dataclass(frozen=True)
class ClockModel:
    r"""Receiver clock: initial sigmas and the two-state random-process PSDs.

    Attributes
    ----------
    bias_sigma : float
        Initial clock-bias 1-:math:`\sigma` (m).
    drift_sigma : float
        Initial clock-drift 1-:math:`\sigma` (m/s).
    g_sensitivity_sigma : float
        1-:math:`\sigma` g-sensitivity of the frequency (m/s per g).
    bias_psd : float
        White frequency-noise PSD driving the bias (m²/s).
    drift_psd : float
        Random-walk frequency PSD driving the drift (m²/s³).
    """

    bias_sigma: float
    drift_sigma: float
    g_sensitivity_sigma: float = 0.0
    bias_psd: float = 0.0
    drift_psd: float = 0.0

    def __post_init__(self) -> None:
        for name in ("bias_sigma", "drift_sigma", "g_sensitivity_sigma", "bias_psd", "drift_psd"):
            require_nonnegative(f"ClockModel.{name}", getattr(self, name))


@dataclass(frozen=True)
class ErrorSources:
    r"""Everything the error model needs besides the layout.

    Attributes
    ----------
    imu : ImuSpec
        Inertial instrument errors (biases and scale factors are random constants).
    gravity : GaussMarkov or None
        Gravity-anomaly process per axis (m/s²).
    altimeter : GaussMarkov or None
        Barometric altimeter bias (m).
    clock : ClockModel or None
    pseudorange_bias_sigma, range_rate_bias_sigma : float
        Per-channel constant biases (m, m/s).
    doppler_bias, doppler_scale_factor : (3,) arrays
        Doppler sensor 1-:math:`\sigma` per body axis (m/s, -).
    doppler_misalignment : float
        Doppler boresight misalignment 1-:math:`\sigma` per axis (rad).
    """

    imu: ImuSpec
    gravity: GaussMarkov | None = None
    altimeter: GaussMarkov | None = None
    clock: ClockModel | None = None
    pseudorange_bias_sigma: float = 0.0
    range_rate_bias_sigma: float = 0.0
    doppler_bias: tuple[float, float, float] = (0.0, 0.0, 0.0)
    doppler_scale_factor: tuple[float, float, float] = (0.0, 0.0, 0.0)
    doppler_misalignment: float = 0.0


_UNITS = {
    "position": "m",
    "velocity": "m/s",
    "misalignment": "rad",
    "gyro bias": "rad/s",
    "gyro scale factor": "-",
    "gyro misalignment": "rad",
    "accel bias": "m/s^2",
    "accel scale factor": "-",
    "accel misalignment": "rad",
    "gravity": "m/s^2",
    "altimeter bias": "m",
    "clock bias": "m",
    "clock drift": "m/s",
    "clock g-sensitivity": "m/s per g",
    "pseudorange bias": "m",
    "range-rate bias": "m/s",
    "doppler bias": "m/s",
    "doppler scale factor": "-",
    "doppler misalignment": "rad",
}


def ins_error_layout(*names: str, channels: int = 4, name: str = "") -> StateLayout:
    """A layout of the named error-state blocks (sizes from the table in the module docstring).

    Parameters
    ----------
    *names : str
        Block names (members of :class:`navcore.estimation.layout.InsBlock`), in state order.
    channels : int, default 4
        Size of the per-channel blocks (pseudorange and range-rate biases).
    name : str, default ""
        Name of the layout.

    Returns
    -------
    StateLayout
        The blocks with their sizes and units (m, m/s, rad, ...).

    Raises
    ------
    ValueError
        If a name is not a known block (the message suggests the closest one).

    Examples
    --------
    >>> ins_error_layout("position", "velocity", "misalignment").size
    9
    >>> ins_error_layout("position", "pseudorange bias", channels=5).size
    8
    """
    blocks = []
    for n in names:
        n = ins_block_name(n, argument="names").value  # raises naming the closest block
        size = (
            channels
            if n in ("pseudorange bias", "range-rate bias")
            else (1 if n in ("altimeter bias", "clock bias", "clock drift", "clock g-sensitivity") else 3)
        )
        blocks.append(StateBlock(n, size, _UNITS[n]))
    return StateLayout(tuple(blocks), name)


def psi_to_attitude_error(layout: StateLayout) -> Array:
    r"""Transform from this module's :math:`\psi` angle to the attitude error of the opposite sign.

    This module: :math:`\hat C^n_b = (I - [\psi\times])\,C^n_b`. The attitude error
    :math:`\delta\alpha` of :mod:`navcore.inertial.error_model17` (its :math:`\Delta\psi`) and of
    :func:`navcore.location.target_location.target_location_error`:
    :math:`\hat C^n_b = (I + [\delta\alpha\times])\,C^n_b`. Hence :math:`\delta\alpha = -\psi`:
    the returned diagonal matrix :math:`T` negates the ``misalignment`` block and keeps every
    other state, so a state converts as :math:`T x` and a covariance as :math:`T P T^T`.

    Parameters
    ----------
    layout : StateLayout
        A layout of this module containing the ``misalignment`` block.

    Returns
    -------
    (n, n) ndarray
        Diagonal of ones with -1 on the misalignment states (its own inverse).

    Raises
    ------
    ValueError
        If ``layout`` has no ``misalignment`` block.

    Examples
    --------
    >>> lay = ins_error_layout("position", "misalignment")
    >>> psi_to_attitude_error(lay).diagonal().tolist()
    [1.0, 1.0, 1.0, -1.0, -1.0, -1.0]
    """
    if "misalignment" not in layout.names:
        raise ValueError("layout must contain block 'misalignment'")
    d = np.ones(layout.size)
    d[layout.slice("misalignment")] = -1.0
    return np.diag(d)


def skew_stack(v: ArrayLike) -> Array:
    r"""Skew-symmetric cross-product matrices of vectors ``(..., 3) -> (..., 3, 3)``.

    Parameters
    ----------
    v : (..., 3) array
        Vectors (any unit).

    Returns
    -------
    (..., 3, 3) ndarray
        :math:`[v\times]` with :math:`[v\times] w = v \times w`.

    Examples
    --------
    >>> skew_stack([1.0, 2.0, 3.0]).tolist()
    [[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]]
    """
    v = np.asarray(v, dtype=float)
    if v.shape == (3,):
        x, y, w = v
        return np.array([[0.0, -w, y], [w, 0.0, -x], [-y, x, 0.0]])
    z = np.zeros(v.shape[:-1])
    x, y, w = v[..., 0], v[..., 1], v[..., 2]
    return np.stack([np.stack([z, -w, y], -1), np.stack([w, z, -x], -1), np.stack([-y, x, z], -1)], -2)


def earth_rate_ned(lat: ArrayLike, *, deg: bool = False) -> Array:
    r"""Earth rate in NED at latitude ``lat``: :math:`\Omega\, [\cos L, 0, -\sin L]`.

    Parameters
    ----------
    lat : float or (N,) array
        Geodetic latitude, rad (deg with ``deg=True``), in [-90, 90] deg.
    deg : bool, default False
        The latitude is in degrees.

    Returns
    -------
    (3,) or (N, 3) ndarray
        Earth rotation rate resolved in NED, rad/s.

    Notes
    -----
    The standard strapdown relation (Titterton & Weston, Strapdown Inertial Navigation
    Technology, 2nd ed., Ch. 3); the Earth rate is WGS-84's.

    Examples
    --------
    >>> import numpy as np
    >>> w = earth_rate_ned(np.deg2rad(60.0))
    >>> [f"{x:.4e}" for x in w]
    ['3.6461e-05', '0.0000e+00', '-6.3152e-05']
    """
    if deg:
        lat = np.radians(lat)
    if np.ndim(lat) == 0:
        return OMEGA_EARTH * np.array([np.cos(lat), 0.0, -np.sin(lat)])
    lat = np.asarray(lat, dtype=float)
    return OMEGA_EARTH * np.stack([np.cos(lat), np.zeros_like(lat), -np.sin(lat)], -1)


def transport_rate_ned(v_ned: ArrayLike, lat: ArrayLike, h: ArrayLike = 0.0, *, deg: bool = False) -> Array:
    r"""Transport rate :math:`[v_E, -v_N, -v_E \tan L] / (R + h)`, spherical Earth.

    Parameters
    ----------
    v_ned : (..., 3) array
        Ground velocity in NED, m/s.
    lat : float or array
        Latitude, rad (deg with ``deg=True``), in [-90, 90] deg.
    h : float or array, default 0.0
        Height, m.
    deg : bool, default False
        The latitude is in degrees.

    Returns
    -------
    (..., 3) ndarray
        Rate of the NED frame with respect to the Earth, rad/s.

    Notes
    -----
    The standard strapdown relation (Titterton & Weston, Ch. 3) with the Schuler radius.

    Examples
    --------
    >>> w = transport_rate_ned([0.0, 100.0, 0.0], 0.0)
    >>> f"{w[0]:.4e}"
    '1.5679e-05'
    """
    v = np.asarray(v_ned, dtype=float)
    lat = np.radians(np.asarray(lat, dtype=float)) if deg else np.asarray(lat, dtype=float)
    r = SCHULER_RADIUS_M + np.asarray(h, dtype=float)
    return np.stack([v[..., 1], -v[..., 0], -v[..., 1] * np.tan(lat)], -1) / r[..., None]


@implements("SP Sec. 2.3")
def error_dynamics(
    layout: StateLayout,
    *,
    f_ned: ArrayLike,
    C_bn: ArrayLike,
    omega_ib_b: ArrayLike = (0.0, 0.0, 0.0),
    v_ned: ArrayLike = (0.0, 0.0, 0.0),
    lat: float = 0.0,
    h: float = 0.0,
    sources: ErrorSources | None = None,
    g: float = G0,
    vertical_channel: bool = True,
    deg: bool = False,
) -> Array:
    """Continuous error-dynamics matrix ``F`` for one flight condition.

    Parameters
    ----------
    layout : StateLayout
        Blocks named as in :func:`ins_error_layout` (must contain position, velocity and
        misalignment).
    f_ned : (3,) array
        Specific force in NED (m/s²); ``(0, 0, -g)`` at rest.
    C_bn : (3, 3) array
        Body-to-NED direction cosine matrix (a rotation matrix).
    omega_ib_b : (3,) array
        Body angular rate with respect to inertial space, body axes (rad/s).
    v_ned : (3,) array
        Ground velocity (m/s) for the transport rate, Coriolis and Gauss-Markov rates.
    lat, h : float
        Latitude, rad (deg with ``deg=True``), in [-90, 90] deg; height, m.
    sources : ErrorSources, optional
        Supplies the Gauss-Markov distance constants (ignored if absent).
    g : float
        Gravity magnitude (m/s²); the default is the constant standard gravity ``G0`` (what the
        papers assume), :func:`navcore.gravity.normal_gravity` gives the WGS-84 value at
        ``lat``, ``h``.
    vertical_channel : bool
        ``False`` freezes the vertical position and velocity errors (rows and columns
        zeroed): the horizontal-only model of an unaided INS whose vertical channel is
        slaved to an external height reference that carries no horizontal information.
    deg : bool, default False
        The latitude is in degrees.

    Returns
    -------
    F : (n, n) ndarray
        Continuous error-dynamics matrix, 1/s (in the units of the layout's blocks).

    Raises
    ------
    ValueError
        If ``layout`` lacks the position, velocity or misalignment block, ``C_bn`` is not a
        rotation matrix, the latitude is out of range for its unit (45 given as radians), or
        an input is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.3 (INS error model).

    Examples
    --------
    At rest, a north tilt couples into the east velocity error through gravity:

    >>> import numpy as np
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> F = error_dynamics(lay, f_ned=[0.0, 0.0, -9.80665], C_bn=np.eye(3))
    >>> round(float(F[4, 6]), 5)
    -9.80665
    """
    n = layout.size
    F = np.zeros((n, n))
    names = set(layout.names)
    for req in ("position", "velocity", "misalignment"):
        if req not in names:
            raise ValueError(f"layout must contain block {req!r}")
    f = np.asarray(f_ned, dtype=float)
    C = np.asarray(C_bn, dtype=float)
    w_ib = np.asarray(omega_ib_b, dtype=float)
    v = np.asarray(v_ned, dtype=float)
    if deg:
        lat = float(np.radians(lat))
    f_b = C.T @ f
    w_ie = earth_rate_ned(lat)
    w_en = transport_rate_ned(v, lat, h)
    R = SCHULER_RADIUS_M + h
    sl = layout.slice
    p, vv, a = sl("position"), sl("velocity"), sl("misalignment")
    F[p, vv] = np.eye(3)
    F[p, p] = -skew_stack(w_en)
    F[vv, vv] = -skew_stack(2 * w_ie + w_en)
    F[vv, a] = skew_stack(f)  # -psi x f = f x psi
    F[vv, p] = (g / R) * np.diag([-1.0, -1.0, 2.0])
    F[a, a] = -skew_stack(w_ie + w_en)
    couplings = {
        "accel bias": (vv, C),
        "accel scale factor": (vv, C @ np.diag(f_b)),
        "accel misalignment": (vv, C @ skew_stack(f_b)),
        "gyro bias": (a, -C),
        "gyro scale factor": (a, -C @ np.diag(w_ib)),
        "gyro misalignment": (a, -C @ skew_stack(w_ib)),
    }
    for block, (rows, M) in couplings.items():
        if block in names:
            F[rows, sl(block)] = M
    speed = float(np.sqrt(v @ v))
    if "gravity" in names:
        F[vv, sl("gravity")] = np.eye(3)
        if sources is not None and sources.gravity is not None:
            beta = speed / sources.gravity.distance_constant_m
            F[sl("gravity"), sl("gravity")] = -beta * np.eye(3)
    if "altimeter bias" in names and sources is not None and sources.altimeter is not None:
        beta = speed / sources.altimeter.distance_constant_m
        F[sl("altimeter bias"), sl("altimeter bias")] = -beta
    if "clock bias" in names and "clock drift" in names:
        F[sl("clock bias"), sl("clock drift")] = 1.0
    if "clock bias" in names and "clock g-sensitivity" in names:
        F[sl("clock bias"), sl("clock g-sensitivity")] = np.linalg.norm(f) / G0
    if not vertical_channel:
        for i in (p.start + 2, vv.start + 2):
            F[i, :] = 0.0
            F[:, i] = 0.0
    return F


def _skew_unchecked(v: Array) -> Array:
    """:func:`skew_stack` of a ``(M, 3)`` stack without the argument checks: ``(M, 3, 3)``."""
    out = np.zeros((v.shape[0], 3, 3))
    x, y, w = v[:, 0], v[:, 1], v[:, 2]
    out[:, 0, 1], out[:, 0, 2] = -w, y
    out[:, 1, 0], out[:, 1, 2] = w, -x
    out[:, 2, 0], out[:, 2, 1] = -y, x
    return out


def _error_dynamics_stack(
    layout: StateLayout,
    *,
    f_ned: Array,
    C_bn: Array,
    omega_ib_b: Array,
    v_ned: Array,
    lat: Array,
    h: Array,
    sources: ErrorSources | None,
    g: float = G0,
    vertical_channel: bool = True,
) -> Array:
    """:func:`error_dynamics` for ``M`` flight conditions at once, without the argument checks.

    The covariance engine's kernel: its inputs are a trajectory's samples, checked where the
    trajectory was built. ``f_ned``, ``omega_ib_b``, ``v_ned`` are ``(M, 3)``, ``C_bn`` is
    ``(M, 3, 3)``, ``lat`` (rad) and ``h`` are ``(M,)``; returns ``(M, n, n)``, element for
    element the matrices :func:`error_dynamics` gives for each condition (the same
    arithmetic, batched).
    """
    M, n = f_ned.shape[0], layout.size
    F = np.zeros((M, n, n))
    names = set(layout.names)
    for req in ("position", "velocity", "misalignment"):
        if req not in names:
            raise ValueError(f"layout must contain block {req!r}")
    C, f, w_ib, v = C_bn, f_ned, omega_ib_b, v_ned
    f_b = np.einsum("mji,mj->mi", C, f)  # C^T f
    w_ie = OMEGA_EARTH * np.stack([np.cos(lat), np.zeros_like(lat), -np.sin(lat)], -1)
    R = SCHULER_RADIUS_M + h
    w_en = np.stack([v[:, 1], -v[:, 0], -v[:, 1] * np.tan(lat)], -1) / R[:, None]
    sl = layout.slice
    p, vv, a = sl("position"), sl("velocity"), sl("misalignment")
    F[:, p, vv] = np.eye(3)
    F[:, p, p] = -_skew_unchecked(w_en)
    F[:, vv, vv] = -_skew_unchecked(2 * w_ie + w_en)
    F[:, vv, a] = _skew_unchecked(f)
    F[:, vv, p] = (g / R)[:, None, None] * np.diag([-1.0, -1.0, 2.0])
    F[:, a, a] = -_skew_unchecked(w_ie + w_en)
    makers = {
        "accel bias": (vv, lambda: C),
        "accel scale factor": (vv, lambda: C * f_b[:, None, :]),
        "accel misalignment": (vv, lambda: C @ _skew_unchecked(f_b)),
        "gyro bias": (a, lambda: -C),
        "gyro scale factor": (a, lambda: -C * w_ib[:, None, :]),
        "gyro misalignment": (a, lambda: -C @ _skew_unchecked(w_ib)),
    }
    for block, (rows, make) in makers.items():
        if block in names:
            F[:, rows, sl(block)] = make()
    speed = np.sqrt(np.einsum("mi,mi->m", v, v))
    eye3 = np.eye(3)
    if "gravity" in names:
        F[:, vv, sl("gravity")] = eye3
        if sources is not None and sources.gravity is not None:
            beta = speed / sources.gravity.distance_constant_m
            F[:, sl("gravity"), sl("gravity")] = -beta[:, None, None] * eye3
    if "altimeter bias" in names and sources is not None and sources.altimeter is not None:
        beta = speed / sources.altimeter.distance_constant_m
        F[:, sl("altimeter bias"), sl("altimeter bias")] = -beta[:, None, None]
    if "clock bias" in names and "clock drift" in names:
        F[:, sl("clock bias"), sl("clock drift")] = 1.0
    if "clock bias" in names and "clock g-sensitivity" in names:
        f_abs = np.sqrt(np.einsum("mi,mi->m", f, f))
        F[:, sl("clock bias"), sl("clock g-sensitivity")] = (f_abs / G0)[:, None, None]
    if not vertical_channel:
        for i in (p.start + 2, vv.start + 2):
            F[:, i, :] = 0.0
            F[:, :, i] = 0.0
    return F


def _process_noise_diag_stack(layout: StateLayout, sources: ErrorSources, speed_mps: Array) -> Array:
    """Diagonals of :func:`process_noise_psd` at ``M`` ground speeds, unchecked: ``(M, n)``."""
    q = np.zeros((speed_mps.size, layout.size))
    names = layout.names
    imu = sources.imu
    q[:, layout.slice("velocity")] = imu.accel_random_walk**2
    q[:, layout.slice("misalignment")] = imu.gyro_random_walk**2
    if "gravity" in names and sources.gravity is not None:
        beta = speed_mps / sources.gravity.distance_constant_m
        q[:, layout.slice("gravity")] = (2 * sources.gravity.sigma**2 * beta)[:, None]
    if "altimeter bias" in names and sources.altimeter is not None:
        beta = speed_mps / sources.altimeter.distance_constant_m
        q[:, layout.slice("altimeter bias")] = (2 * sources.altimeter.sigma**2 * beta)[:, None]
    if sources.clock is not None:
        if "clock bias" in names:
            q[:, layout.slice("clock bias")] = sources.clock.bias_psd
        if "clock drift" in names:
            q[:, layout.slice("clock drift")] = sources.clock.drift_psd
    return q


def gravity_tuning_psd(layout: StateLayout, sources: ErrorSources, speed_mps: float) -> Array:
    r"""Filter tuning for an unmodelled gravity anomaly: white acceleration noise on the velocity.

    A filter without the ``gravity`` states stands the first-order Gauss-Markov anomaly of
    ``sources.gravity`` (stationary :math:`\sigma`, distance constant :math:`d`) in with white
    noise of its low-frequency power spectral density: the PSD
    :math:`2\sigma^2\tau / (1 + \omega^2\tau^2)` at :math:`\omega = 0`, :math:`2\sigma^2\tau`,
    with the correlation time :math:`\tau = d / v` at ground speed :math:`v`.

    Parameters
    ----------
    layout : StateLayout
        The filter's layout (must have a ``velocity`` block).
    sources : ErrorSources
        Error sources; ``sources.gravity`` is the anomaly (``None``: no tuning).
    speed_mps : float
        Ground speed, m/s (``>= 0``; ``0`` gives no tuning).

    Returns
    -------
    (n,) ndarray
        Added PSD per state of ``layout`` ((m/s²)²/Hz on the three velocity states, zero
        elsewhere), the ``filter_added_psd`` of
        :func:`navcore.integration.engine.run_covariance_analysis`.

    Raises
    ------
    ValueError
        If ``speed_mps`` is negative or not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6 (the integration filters of Figs. 2.4-2.8 do not model the gravity anomaly of
    their truth model); Gelb, *Applied Optimal Estimation* (1974), Table 3.8-1 (the PSD of a
    first-order Gauss-Markov process).

    Examples
    --------
    >>> from navcore.inertial.imu import ImuSpec
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> src = ErrorSources(ImuSpec("ideal"), gravity=GaussMarkov(1e-4, 20_000.0))
    >>> q = gravity_tuning_psd(lay, src, 200.0)
    >>> [float(x) for x in q[3:6]], float(q[:3].sum() + q[6:].sum())
    ([2e-06, 2e-06, 2e-06], 0.0)
    """
    q = np.zeros(layout.size)
    gm = sources.gravity
    if gm is not None and speed_mps > 0:
        q[layout.slice("velocity")] = 2 * gm.sigma**2 * gm.distance_constant_m / speed_mps
    return q


def process_noise_psd(layout: StateLayout, sources: ErrorSources, *, speed_mps: float = 0.0) -> Array:
    r"""Diagonal state-space noise PSD :math:`G Q G^T` for :func:`error_dynamics`.

    Velocity gets the accelerometer white noise (``accel_random_walk^2``), the :math:`\psi` angle the
    gyro white noise (``gyro_random_walk^2``); Gauss-Markov blocks get :math:`2 \sigma^2 \beta` with
    :math:`\beta = \text{speed} / \text{distance constant}`; the clock bias and drift their PSDs.

    Parameters
    ----------
    layout : StateLayout
        Error-state layout.
    sources : ErrorSources
        Noise magnitudes (root PSDs in SI).
    speed_mps : float, default 0.0
        Ground speed, m/s (sets the Gauss-Markov rates).

    Returns
    -------
    (n, n) ndarray
        Diagonal PSD, state unit squared per second.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.3 (error models).

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.inertial.imu import ImuSpec
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> Q = process_noise_psd(lay, ErrorSources(imu=ImuSpec("x", accel_random_walk=1e-3)))
    >>> np.diag(Q)[3:6].tolist()
    [1e-06, 1e-06, 1e-06]
    """
    q = np.zeros(layout.size)
    names = layout.names
    imu = sources.imu
    q[layout.slice("velocity")] = imu.accel_random_walk**2
    q[layout.slice("misalignment")] = imu.gyro_random_walk**2
    if "gravity" in names and sources.gravity is not None:
        beta = speed_mps / sources.gravity.distance_constant_m
        q[layout.slice("gravity")] = 2 * sources.gravity.sigma**2 * beta
    if "altimeter bias" in names and sources.altimeter is not None:
        beta = speed_mps / sources.altimeter.distance_constant_m
        q[layout.slice("altimeter bias")] = 2 * sources.altimeter.sigma**2 * beta
    if sources.clock is not None:
        if "clock bias" in names:
            q[layout.slice("clock bias")] = sources.clock.bias_psd
        if "clock drift" in names:
            q[layout.slice("clock drift")] = sources.clock.drift_psd
    return np.diag(q)


def initial_covariance(
    layout: StateLayout,
    sources: ErrorSources,
    *,
    position_sigma: tuple[float, float, float] = (0.0, 0.0, 0.0),
    velocity_sigma: tuple[float, float, float] = (0.0, 0.0, 0.0),
    attitude_sigma: tuple[float, float, float] = (0.0, 0.0, 0.0),
) -> Array:
    r"""Diagonal initial covariance: navigation errors as given, sensor states at their 1-:math:`\sigma`.

    Use :func:`navcore.inertial.error_dynamics.gyrocompass_alignment` afterwards to replace
    the attitude block by the instrument-dependent, correlated gyrocompass errors.

    Parameters
    ----------
    layout : StateLayout
        Error-state layout (blocks of :func:`ins_error_layout`).
    sources : ErrorSources
        Supplies the 1-:math:`\sigma` of every sensor and aiding state (SI, see :class:`ErrorSources`).
    position_sigma : (3,) tuple of float, default zeros
        Initial NED position 1-:math:`\sigma`, m (``>= 0``).
    velocity_sigma : (3,) tuple of float, default zeros
        Initial NED velocity 1-:math:`\sigma`, m/s (``>= 0``).
    attitude_sigma : (3,) tuple of float, default zeros
        Initial attitude 1-:math:`\sigma` (north, east, down), rad (``>= 0``).

    Returns
    -------
    (n, n) ndarray
        Diagonal covariance (state units squared).

    Raises
    ------
    ValueError
        If a 1-:math:`\sigma` is negative or not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.inertial.imu import ImuSpec
    >>> lay = ins_error_layout("position", "velocity", "misalignment", "accel bias")
    >>> P = initial_covariance(lay, ErrorSources(imu=ImuSpec("x", accel_bias=1e-3)),
    ...                        position_sigma=(10.0, 10.0, 10.0))
    >>> np.diag(P)[[0, 9]].tolist()
    [100.0, 1e-06]
    """
    s = np.zeros(layout.size)
    imu = sources.imu
    values: dict[str, Any] = {
        "position": position_sigma,
        "velocity": velocity_sigma,
        "misalignment": attitude_sigma,
        "gyro bias": imu.gyro_bias,
        "gyro scale factor": imu.gyro_scale_factor,
        "gyro misalignment": imu.gyro_misalignment,
        "accel bias": imu.accel_bias,
        "accel scale factor": imu.accel_scale_factor,
        "accel misalignment": imu.accel_misalignment,
        "gravity": sources.gravity.sigma if sources.gravity else 0.0,
        "altimeter bias": sources.altimeter.sigma if sources.altimeter else 0.0,
        "clock bias": sources.clock.bias_sigma if sources.clock else 0.0,
        "clock drift": sources.clock.drift_sigma if sources.clock else 0.0,
        "clock g-sensitivity": sources.clock.g_sensitivity_sigma if sources.clock else 0.0,
        "pseudorange bias": sources.pseudorange_bias_sigma,
        "range-rate bias": sources.range_rate_bias_sigma,
        "doppler bias": sources.doppler_bias,
        "doppler scale factor": sources.doppler_scale_factor,
        "doppler misalignment": sources.doppler_misalignment,
    }
    for b in layout.blocks:
        s[layout.slice(b.name)] = values[b.name]
    return np.diag(s**2)


def _sensor_error_rates(layout: StateLayout, *, lat: float, C_bn: ArrayLike | None, g: float):
    """Indices of the misalignment and sensor states, and ``(e_f, e_w)`` at rest.

    ``e_f`` (3 x n_s) is the north/east/down specific-force error and ``e_w`` the rate error
    ``C_bn delta omega`` produced by each sensor state (rows of :func:`error_dynamics`).
    """
    C_bn = np.eye(3) if C_bn is None else C_bn
    # at rest the gyros sense the Earth's rotation (their scale-factor and misalignment errors
    # act on it) and the accelerometers the reaction to gravity
    w_ib = np.asarray(C_bn, dtype=float).T @ earth_rate_ned(lat)
    F = error_dynamics(layout, f_ned=(0.0, 0.0, -g), C_bn=C_bn, omega_ib_b=w_ib, lat=lat, g=g)
    vv, a = layout.slice("velocity"), layout.slice("misalignment")
    sensor = [b.name for b in layout.blocks if b.name.startswith(("gyro", "accel"))]
    idx: NDArray[np.intp] = np.asarray(
        np.concatenate([np.arange(layout.size)[layout.slice(s)] for s in sensor]) if sensor else [],
        dtype=np.intp,
    )
    return np.arange(layout.size)[a], idx, F[vv][:, idx], -F[a][:, idx]


def _replace_attitude(
    P0: ArrayLike, layout: StateLayout, ai: NDArray[np.intp], idx: NDArray[np.intp], T: Array
) -> Array:
    """Covariance with ``psi = T x_s`` (sensor states ``idx``) and the rest of ``P0`` kept."""
    P0 = np.array(P0, dtype=float)
    A = np.eye(layout.size)
    A[ai, :] = 0.0
    A[np.ix_(ai, idx)] = T
    P_s = P0.copy()
    P_s[ai, :] = 0.0
    P_s[:, ai] = 0.0
    P = A @ P_s @ A.T
    return 0.5 * (P + P.T)


@implements("SP Sec. 2.6.1")
def gyrocompass_alignment(
    P0: ArrayLike,
    layout: StateLayout,
    *,
    lat: float,
    C_bn: ArrayLike | None = None,
    g: float = G0,
    deg: bool = False,
) -> Array:
    r"""Replace the attitude errors by the steady state of a stationary gyrocompass alignment.

    At rest the levelled, gyrocompassed platform has zero horizontal velocity-error rate and
    zero east :math:`\psi`-rate, which ties the attitude error to the sensor errors: with
    :math:`e_f = C^n_b\delta f^b` and :math:`e_\omega = C^n_b\delta\omega^b` (linear in the
    sensor states, rows of :func:`error_dynamics`),

    .. math::

        \psi_N = e_{f,E}/g,\quad \psi_E = -e_{f,N}/g,\quad
        \psi_D = \frac{e_{\omega,E} - \Omega\sin L\,\psi_N}{\Omega\cos L}

    (Earth-rate :math:`\Omega`, latitude :math:`L`). The returned covariance has
    :math:`\psi = T x_s` with the sensor covariance of ``P0`` and the correlations that make
    the tilt cancel the accelerometer bias and the heading cancel the east gyro bias.

    Parameters
    ----------
    P0 : (n, n) array
        Initial covariance over ``layout`` (e.g. from :func:`initial_covariance`).
    layout : StateLayout
        Error-state layout (needs ``"misalignment"``).
    lat : float
        Latitude, rad (deg with ``deg=True``), in [-90, 90] deg, not at a pole.
    C_bn : (3, 3) array, optional
        Body-to-NED attitude, a rotation matrix (default identity).
    g : float, default G0
        Gravity magnitude, m/s² (``G0`` is the papers' constant; see
        :func:`navcore.gravity.normal_gravity`).
    deg : bool, default False
        The latitude is in degrees.

    Returns
    -------
    (n, n) ndarray
        ``P0`` with its attitude rows and columns replaced (rad² and cross terms).

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6.1 (initial alignment).

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.inertial.imu import ImuSpec
    >>> from navcore.units import DEG_PER_H
    >>> lay = ins_error_layout("position", "velocity", "misalignment", "gyro bias")
    >>> src = ErrorSources(imu=ImuSpec("example", gyro_bias=0.01 * DEG_PER_H))
    >>> P = gyrocompass_alignment(initial_covariance(lay, src), lay, lat=np.deg2rad(45.0))
    >>> round(float(np.sqrt(P[8, 8])) * 1e3, 3)  # heading error, mrad
    0.94
    """
    if deg:
        lat = float(np.radians(lat))
    ai, idx, ef, ew = _sensor_error_rates(layout, lat=lat, C_bn=C_bn, g=g)
    T = np.zeros((3, idx.size))
    T[0] = ef[1] / g
    T[1] = -ef[0] / g
    W = OMEGA_EARTH
    # psi_dot_E = Omega sinL psi_N + Omega cosL psi_D - e_w,E = 0
    T[2] = (ew[1] - W * np.sin(lat) * T[0]) / (W * np.cos(lat))
    return _replace_attitude(P0, layout, ai, idx, T)


@implements("KZL Sec. 3.1")
def levelling_alignment(
    P0: ArrayLike,
    layout: StateLayout,
    *,
    heading_sigma: float,
    lat: float,
    C_bn: ArrayLike | None = None,
    g: float = G0,
    tilt_noise_sigma: float = 0.0,
    deg: bool = False,
) -> Array:
    r"""Attitude errors after levelling at rest and a heading from an external source.

    Levelling makes the computed specific force exactly vertical, so the tilt cancels the
    horizontal accelerometer errors, :math:`\psi_N = e_{f,E}/g` and
    :math:`\psi_E = -e_{f,N}/g` (as in :func:`gyrocompass_alignment`). The heading does not
    come from the gyros (a MEMS gyro cannot sense the Earth rate through its bias) but from
    outside, e.g. the GPS track of KZL Eq. 4: an independent error of 1-:math:`\sigma`
    ``heading_sigma``. ``tilt_noise_sigma`` adds an independent tilt per horizontal axis, e.g.
    the averaged accelerometer noise :math:`N_a/(g\sqrt{T})`.

    Parameters
    ----------
    P0 : (n, n) array
        Initial covariance over ``layout``.
    layout : StateLayout
        Error-state layout (needs ``"misalignment"``).
    heading_sigma : float
        1-:math:`\sigma` of the external heading, rad (``>= 0``).
    lat : float
        Latitude, rad (deg with ``deg=True``), in [-90, 90] deg.
    C_bn : (3, 3) array, optional
        Body-to-NED attitude, a rotation matrix (default identity).
    g : float, default G0
        Gravity magnitude, m/s².
    tilt_noise_sigma : float, default 0.0
        Independent tilt 1-:math:`\sigma` per horizontal axis, rad (``>= 0``).
    deg : bool, default False
        The latitude is in degrees.

    Returns
    -------
    (n, n) ndarray
        ``P0`` with its attitude rows and columns replaced.

    Raises
    ------
    ValueError
        If ``heading_sigma`` or ``tilt_noise_sigma`` is negative.

    References
    ----------
    Knedlik, Zhou & Loffeld (2009), Sec. 3.1 and Eq. (4) (initialisation).

    Examples
    --------
    >>> import numpy as np
    >>> from navcore.inertial.imu import ImuSpec
    >>> lay = ins_error_layout("position", "velocity", "misalignment")
    >>> P0 = initial_covariance(lay, ErrorSources(imu=ImuSpec("x")))
    >>> P = levelling_alignment(P0, lay, heading_sigma=0.01, lat=0.8)
    >>> round(float(P[8, 8]), 6)
    0.0001
    """
    require_nonnegative("heading_sigma", heading_sigma)
    require_nonnegative("tilt_noise_sigma", tilt_noise_sigma)
    if deg:
        lat = float(np.radians(lat))
    ai, idx, ef, _ = _sensor_error_rates(layout, lat=lat, C_bn=C_bn, g=g)
    T = np.zeros((3, idx.size))
    T[0] = ef[1] / g
    T[1] = -ef[0] / g
    P = _replace_attitude(P0, layout, ai, idx, T)
    P[ai, ai] += np.array([tilt_noise_sigma**2, tilt_noise_sigma**2, heading_sigma**2])
    return P


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "channels": COUNT0,
        "g": POSITIVE,
        "radius": POSITIVE,
        "speed_mps": NONNEGATIVE,
        "distance_constant_m": POSITIVE,
        "sigma": NONNEGATIVE,
        "drift_sigma": NONNEGATIVE,
        "bias_sigma": NONNEGATIVE,
        "drift_psd": NONNEGATIVE,
        "bias_psd": NONNEGATIVE,
        "g_sensitivity_sigma": NONNEGATIVE,
        "heading_sigma": NONNEGATIVE,
        "pseudorange_bias_sigma": NONNEGATIVE,
        "range_rate_bias_sigma": NONNEGATIVE,
        "tilt_noise_sigma": NONNEGATIVE,
        "position_sigma": NONNEGATIVE,
        "velocity_sigma": NONNEGATIVE,
        "attitude_sigma": NONNEGATIVE,
        "lat": LATITUDE,
        "C_bn": ROTATION,
        "P0": COVARIANCE,
    },
)
