"""IMU error specifications as data, in SI units with the published units kept alongside.

An :class:`ImuSpec` holds the 1-sigma values of the error sources a covariance analysis or a
simulation needs. Values are stored in SI (rad/s, m/s^2, dimensionless scale factor, rad,
root PSDs in rad/sqrt(s) and m/s/sqrt(s)); build specs from the papers' units with the
factors of :mod:`navcore.units`, e.g. ``gyro_bias=0.01 * DEG_PER_H``.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields

from navcore._validate import require_nonnegative

__all__ = ["ImuSpec"]


@dataclass(frozen=True)
class ImuSpec:
    """1-sigma IMU error specification (SI units).

    Attributes
    ----------
    name : str
        Grade or product label.
    gyro_bias : float
        Gyro bias (drift), rad/s.
    gyro_scale_factor : float
        Gyro scale-factor error, dimensionless (1 ppm = 1e-6).
    gyro_misalignment : float
        Gyro input-axis misalignment, rad.
    gyro_random_walk : float
        Angle random walk, root PSD of rate noise, rad/sqrt(s).
    accel_bias : float
        Accelerometer bias, m/s^2.
    accel_scale_factor : float
        Accelerometer scale-factor error, dimensionless.
    accel_misalignment : float
        Accelerometer input-axis misalignment, rad.
    accel_random_walk : float
        Velocity random walk, root PSD of acceleration noise, m/s/sqrt(s).
    source : str
        Where the numbers come from (paper and table).
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
            require_nonnegative(f"ImuSpec.{f.name}", getattr(self, f.name))

    def scaled(self, factor: float, name: str | None = None) -> ImuSpec:
        """A spec with every error multiplied by ``factor`` (``factor >= 0``)."""
        require_nonnegative("factor", factor)
        values = {
            f.name: getattr(self, f.name) * factor
            for f in fields(self)
            if f.name not in ("name", "source", "extra")
        }
        return ImuSpec(name=name or f"{self.name} x {factor:g}", source=self.source, **values)
