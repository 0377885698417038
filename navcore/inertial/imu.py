r"""IMU error specifications as data, in SI units with the published units kept alongside.

An :class:`ImuSpec` holds the 1-:math:`\sigma` values of the error sources a covariance analysis or a
simulation needs. Values are stored in SI (rad/s, m/s², dimensionless scale factor, rad,
root PSDs in rad/√s and m/s/√s); build specs from the papers' units with the
factors of :mod:`navcore.units`, e.g. ``gyro_bias=0.01 * DEG_PER_H``. A value beyond what
any inertial sensor has (:data:`IMU_SPEC_LIMITS`: a gyro bias above 0.1 rad/s, about
20 000 deg/h) is a unit mistake and raises, naming the field and the unit it was probably
given in.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

from navcore._validate import NONNEGATIVE, POSITIVE, check_public, require_nonnegative, require_positive
from navcore.trace import implements
from navcore.units import (
    ARCSEC,
    DEG_PER_H,
    DEG_PER_H_PER_SQRT_HZ,
    MICRO_G,
    MICRO_G_PER_SQRT_HZ,
    PPM,
)

__all__ = [
    "IMU_SPEC_LIMITS",
    "ImuSpec",
    "angle_random_walk_deg_per_sqrt_h",
    "gyro_bias_calibrated_at_rest",
    "imu_spec_from_published",
    "noise_only",
    "velocity_random_walk_m_per_s_per_sqrt_h",
]


#: Largest plausible 1-:math:`\sigma` of each error source (SI), beyond the worst consumer MEMS parts,
#: with the unit mistake a larger value usually is. A specification beyond it raises.
IMU_SPEC_LIMITS: dict[str, tuple[float, str]] = {
    "gyro_bias": (0.1, "rad/s (about 20 600 deg/h; a value in deg/h? multiply by navcore.units.DEG_PER_H)"),
    "gyro_scale_factor": (0.5, "(50 %; a value in ppm? multiply by navcore.units.PPM)"),
    "gyro_misalignment": (0.1, "rad (5.7 deg; a value in arcsec? multiply by navcore.units.ARCSEC)"),
    "gyro_random_walk": (
        0.01,
        "rad/sqrt(s) (34 deg/sqrt(h); a value in deg/sqrt(h)? multiply by navcore.units.DEG_PER_SQRT_H)",
    ),
    "accel_bias": (1.0, "m/s^2 (about 100 mg; a value in micro-g? multiply by navcore.units.MICRO_G)"),
    "accel_scale_factor": (0.5, "(50 %; a value in ppm? multiply by navcore.units.PPM)"),
    "accel_misalignment": (0.1, "rad (5.7 deg; a value in arcsec? multiply by navcore.units.ARCSEC)"),
    "accel_random_walk": (
        0.1,
        "m/s/sqrt(s) (about 10 mg/sqrt(Hz); a value in micro-g/sqrt(Hz)? multiply by "
        "navcore.units.MICRO_G_PER_SQRT_HZ)",
    ),
}


@dataclass(frozen=True)
class ImuSpec:
    r"""1-:math:`\sigma` IMU error specification (SI units).

    Attributes
    ----------
    name : str
        Grade or product label.
    gyro_bias : float
        Gyro bias (drift), rad/s.
    gyro_scale_factor : float
        Gyro scale-factor error, dimensionless (1 ppm = :math:`10^{-6}`).
    gyro_misalignment : float
        Gyro input-axis misalignment, rad.
    gyro_random_walk : float
        Angle random walk, root PSD of rate noise, rad/√s.
    accel_bias : float
        Accelerometer bias, m/s².
    accel_scale_factor : float
        Accelerometer scale-factor error, dimensionless.
    accel_misalignment : float
        Accelerometer input-axis misalignment, rad.
    accel_random_walk : float
        Velocity random walk, root PSD of acceleration noise, m/s/√s.
    source : str
        Where the numbers come from (paper and table).
    extra : dict of str to float
        Further named values kept with the specification (no model reads them).
    """

    name: str
    gyro_bias: float = 0.0
    gyro_scale_factor: float = 0.0
    gyro_misalignment: float = 0.0
    gyro_random_walk: float = 0.0
    accel_bias: float = 0.0
    accel_scale_factor: float = 0.0
    accel_misalignment: float = 0.0
    accel_random_walk: float = 0.0
    source: str = ""
    extra: dict[str, float] = field(default_factory=dict, compare=False)

    def __post_init__(self) -> None:
        for f in fields(self):
            if f.name in ("name", "source", "extra"):
                continue
            value = getattr(self, f.name)
            require_nonnegative(f"ImuSpec.{f.name}", value)
            limit, unit = IMU_SPEC_LIMITS[f.name]
            if value > limit:
                raise ValueError(f"ImuSpec.{f.name} must be <= {limit:g} {unit}, got {value!r}")

    def scaled(self, factor: float, name: str | None = None) -> ImuSpec:
        """A spec with every error multiplied by ``factor`` (``factor >= 0``)."""
        require_nonnegative("factor", factor)
        values = {
            f.name: getattr(self, f.name) * factor
            for f in fields(self)
            if f.name not in ("name", "source", "extra")
        }
        return ImuSpec(name=name or f"{self.name} x {factor:g}", source=self.source, **values)


def angle_random_walk_deg_per_sqrt_h(root_psd_deg_per_h_per_sqrt_hz: float) -> float:
    """Convert a gyro rate-noise root PSD in deg/h/√Hz to angle random walk in deg/√h.

    1 deg/h/√Hz = 1 (deg/h)·√s = (1/60) deg/√h.

    Parameters
    ----------
    root_psd_deg_per_h_per_sqrt_hz : float
        Rate-noise root PSD, deg/h/√Hz (``>= 0``).

    Returns
    -------
    float
        Angle random walk, deg/√h.

    Raises
    ------
    ValueError
        If the input is negative.

    Examples
    --------
    >>> round(angle_random_walk_deg_per_sqrt_h(4.7), 4)
    0.0783
    """
    require_nonnegative("root_psd_deg_per_h_per_sqrt_hz", root_psd_deg_per_h_per_sqrt_hz)
    return root_psd_deg_per_h_per_sqrt_hz / 60.0


def velocity_random_walk_m_per_s_per_sqrt_h(root_psd_micro_g_per_sqrt_hz: float) -> float:
    r"""Convert an accelerometer noise root PSD in micro-g/√Hz to velocity random walk in m/s/√h.

    1 micro-g/√Hz = :math:`9.80665 \times 10^{-6}` m/s/√s = :math:`9.80665 \times 10^{-6} \cdot 60` m/s/√h.

    Parameters
    ----------
    root_psd_micro_g_per_sqrt_hz : float
        Acceleration-noise root PSD, micro-g/√Hz (``>= 0``).

    Returns
    -------
    float
        Velocity random walk, m/s/√h.

    Raises
    ------
    ValueError
        If the input is negative.

    Examples
    --------
    >>> round(velocity_random_walk_m_per_s_per_sqrt_h(56.0), 4)
    0.033
    """
    require_nonnegative("root_psd_micro_g_per_sqrt_hz", root_psd_micro_g_per_sqrt_hz)
    return root_psd_micro_g_per_sqrt_hz * MICRO_G * 60.0


@implements("SP Table 2.5")
def imu_spec_from_published(
    name: str,
    *,
    accel_bias_micro_g: float,
    accel_scale_factor_ppm: float,
    accel_misalignment_arcsec: float,
    accel_random_walk_micro_g_per_sqrt_hz: float,
    gyro_bias_deg_per_h: float,
    gyro_scale_factor_ppm: float,
    gyro_misalignment_arcsec: float,
    gyro_random_walk_deg_per_h_per_sqrt_hz: float,
    source: str = "",
) -> ImuSpec:
    r"""Build an :class:`ImuSpec` from the units in which IMU tables are usually printed.

    Parameters
    ----------
    name : str
        Name of the instrument.
    accel_bias_micro_g : float
        Accelerometer bias 1-:math:`\sigma`, micro-g.
    accel_scale_factor_ppm : float
        Accelerometer scale-factor error 1-:math:`\sigma`, ppm.
    accel_misalignment_arcsec : float
        Accelerometer misalignment 1-:math:`\sigma`, arcsec.
    accel_random_walk_micro_g_per_sqrt_hz : float
        Accelerometer white-noise root PSD, micro-g/√Hz.
    gyro_bias_deg_per_h : float
        Gyro bias 1-:math:`\sigma`, deg/h.
    gyro_scale_factor_ppm : float
        Gyro scale-factor error 1-:math:`\sigma`, ppm.
    gyro_misalignment_arcsec : float
        Gyro misalignment 1-:math:`\sigma`, arcsec.
    gyro_random_walk_deg_per_h_per_sqrt_hz : float
        Gyro white-noise root PSD, deg/h/√Hz.
    source : str, default ""
        Where the numbers come from.

    Returns
    -------
    ImuSpec
        The instrument in SI (see :class:`ImuSpec`).

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Table 2.5
    (the IMU grades are printed in these units).

    Examples
    --------
    >>> s = imu_spec_from_published("x", accel_bias_micro_g=100, accel_scale_factor_ppm=0,
    ...     accel_misalignment_arcsec=0, accel_random_walk_micro_g_per_sqrt_hz=0,
    ...     gyro_bias_deg_per_h=0.01, gyro_scale_factor_ppm=0, gyro_misalignment_arcsec=0,
    ...     gyro_random_walk_deg_per_h_per_sqrt_hz=0)
    >>> round(s.accel_bias, 9), round(s.gyro_bias * 180 / 3.141592653589793 * 3600, 6)
    (0.000980665, 0.01)
    """
    return ImuSpec(
        name=name,
        gyro_bias=gyro_bias_deg_per_h * DEG_PER_H,
        gyro_scale_factor=gyro_scale_factor_ppm * PPM,
        gyro_misalignment=gyro_misalignment_arcsec * ARCSEC,
        gyro_random_walk=gyro_random_walk_deg_per_h_per_sqrt_hz * DEG_PER_H_PER_SQRT_HZ,
        accel_bias=accel_bias_micro_g * MICRO_G,
        accel_scale_factor=accel_scale_factor_ppm * PPM,
        accel_misalignment=accel_misalignment_arcsec * ARCSEC,
        accel_random_walk=accel_random_walk_micro_g_per_sqrt_hz * MICRO_G_PER_SQRT_HZ,
        source=source,
    )


def noise_only(spec: ImuSpec) -> ImuSpec:
    """The spec with every bias-type error removed, keeping only the two random walks.

    This is the "perfectly calibrated" instrument: what remains after GPS has estimated
    every bias, scale factor and misalignment exactly.

    Parameters
    ----------
    spec : ImuSpec
        The instrument (SI).

    Returns
    -------
    ImuSpec
        Same random walks and source; biases, scale factors and misalignments zero.

    Examples
    --------
    >>> s = noise_only(ImuSpec("x", gyro_bias=1e-6, gyro_random_walk=1e-5))
    >>> s.gyro_bias, s.gyro_random_walk
    (0.0, 1e-05)
    """
    return ImuSpec(
        name=f"{spec.name} (noise only)",
        gyro_random_walk=spec.gyro_random_walk,
        accel_random_walk=spec.accel_random_walk,
        source=spec.source,
    )


@implements("KZL Sec. 3.1")
def gyro_bias_calibrated_at_rest(spec: ImuSpec, averaging_time: float) -> ImuSpec:
    r"""The spec after the turn-on gyro bias was measured by averaging at rest for ``averaging_time``.

    Averaging white rate noise of root PSD :math:`N` for :math:`T` seconds leaves a random
    constant residual of 1-:math:`\sigma` :math:`N/\sqrt{T}`; that residual replaces ``gyro_bias``
    (KZL Sec. 3.1: the gyro biases are calibrated while the vehicle is stationary). The
    Earth rate the gyros also sense is assumed known and removed.

    Parameters
    ----------
    spec : ImuSpec
        The instrument (SI).
    averaging_time : float
        Averaging time at rest, s (``> 0``).

    Returns
    -------
    ImuSpec
        A copy whose ``gyro_bias`` is the residual, rad/s.

    Raises
    ------
    ValueError
        If ``averaging_time`` is not positive.

    References
    ----------
    Knedlik, Zhou & Loffeld (2009), Sec. 3.1.

    Examples
    --------
    >>> from navcore.units import DEG_PER_H, DEG_PER_H_PER_SQRT_HZ
    >>> s = ImuSpec("x", gyro_bias=360 * DEG_PER_H, gyro_random_walk=180 * DEG_PER_H_PER_SQRT_HZ)
    >>> round(gyro_bias_calibrated_at_rest(s, 300.0).gyro_bias / DEG_PER_H, 3)
    10.392
    """
    require_positive("averaging_time", averaging_time)
    return replace(
        spec,
        name=f"{spec.name} (gyro bias calibrated over {averaging_time:g} s)",
        gyro_bias=spec.gyro_random_walk / math.sqrt(averaging_time),
    )


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "averaging_time": POSITIVE,
        "gyro_random_walk": NONNEGATIVE,
        "accel_random_walk": NONNEGATIVE,
        "root_psd_deg_per_h_per_sqrt_hz": NONNEGATIVE,
        "root_psd_micro_g_per_sqrt_hz": NONNEGATIVE,
        "accel_random_walk_micro_g_per_sqrt_hz": NONNEGATIVE,
        "gyro_random_walk_deg_per_h_per_sqrt_hz": NONNEGATIVE,
    },
)
