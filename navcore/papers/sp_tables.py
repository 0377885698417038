"""SP Tables 2.4, 2.5 and 2.8 as typed input data, with units and locators.

Every number is typed once, as printed, together with the unit it is printed in; the SI
value is derived with the factors of :mod:`navcore.units`. The mission analysis of
:mod:`navcore.papers.sp_missions` reads these objects and nothing else from the tables.

Table 2.4 (INS-independent errors), Table 2.5 (the four IMU qualities) and Table 2.8 (the
Doppler ground-speed sensor) of G. T. Schmidt and R. E. Phillips, "INS/GPS Integration
Architecture Performance Comparisons", NATO RTO-EN-SET-116, Sec. 2.3-2.6.
"""

from __future__ import annotations

from dataclasses import dataclass

from navcore.inertial.imu import ImuSpec, imu_spec_from_published
from navcore.units import G0, KM, MICRO_G, MRAD, NMI_PER_H, PPM, C

__all__ = [
    "GRADE_LABELS_NMI_PER_H",
    "TABLE_2_4",
    "TABLE_2_5_PRINTED",
    "TABLE_2_5_ROWS",
    "TABLE_2_8",
    "DopplerErrorModel",
    "GaussMarkovSpec",
    "TableEntry",
    "sp_imu_grades",
    "table_2_4",
]


@dataclass(frozen=True)
class TableEntry:
    """One printed table cell: the value as printed, its unit, its SI value and locator."""

    name: str
    printed: str
    unit: str
    si: float
    components: int
    locator: str


@dataclass(frozen=True)
class GaussMarkovSpec:
    """A first-order Gauss-Markov process given by a 1-sigma and a distance constant (SI)."""

    sigma: float
    distance_constant_m: float


_T24 = "SP Table 2.4"

#: Table 2.4, row by row (name, printed value, printed unit, SI value, components).
TABLE_2_4: tuple[TableEntry, ...] = (
    TableEntry("initial position (vertical)", "16", "m", 16.0, 1, _T24),
    TableEntry("initial position (horizontal)", "600", "m", 600.0, 2, _T24),
    TableEntry("initial velocity", "0.3", "m/s", 0.3, 3, _T24),
    # "5000 ms" as printed; read as 5000 m of clock offset (see the clock-offset erratum note).
    TableEntry("clock initial offset", "5000", "ms (read as m)", 5000.0, 1, _T24),
    TableEntry("clock initial drift", "1e-2", "ppm", 1e-2 * PPM * C, 1, _T24),
    TableEntry("clock g-sensitive drift", "1e-3", "ppm/g", 1e-3 * PPM * C, 1, _T24),
    TableEntry("pseudorange bias", "3.0", "m", 3.0, 4, _T24),
    TableEntry("range-rate bias", "0.003", "m/s", 0.003, 4, _T24),
    TableEntry("gravity (Markov) sigma", "35", "micro-g", 35.0 * MICRO_G, 3, _T24),
    TableEntry("gravity (Markov) distance", "37", "km", 37.0 * KM, 3, _T24),
    TableEntry("barometer (Markov) sigma", "150", "m", 150.0, 1, _T24),
    TableEntry("barometer (Markov) distance", "460", "km", 460.0 * KM, 1, _T24),
    TableEntry("barometer noise", "3", "m", 3.0, 1, _T24),
)


def table_2_4() -> dict[str, TableEntry]:
    """Table 2.4 keyed by row name (SI values in ``.si``: m, m/s, m/s^2, m/s per g)."""
    return {e.name: e for e in TABLE_2_4}


#: Grade labels: the 1-hour unaided navigation error that names each column (nmi/h).
GRADE_LABELS_NMI_PER_H: tuple[float, ...] = (10.0, 1.0, 0.5, 0.2)

#: Table 2.5 rows in printed units, one value per grade (10, 1.0, 0.5, 0.2 nmi/h).
TABLE_2_5_ROWS: tuple[tuple[str, str, tuple[str, str, str, str]], ...] = (
    ("accel_bias_micro_g", "micro-g", ("223", "37", "19", "4.2")),
    ("accel_scale_factor_ppm", "ppm", ("223", "179", "90", "21")),
    ("accel_misalignment_arcsec", "arcsec", ("22", "3", "1.5", "0.4")),
    ("accel_random_walk_micro_g_per_sqrt_hz", "micro-g/sqrt(Hz)", ("56", "15", "7.5", "4.2")),
    ("gyro_bias_deg_per_h", "deg/h", ("0.11", "0.0045", "0.0022", "0.00084")),
    ("gyro_scale_factor_ppm", "ppm", ("112", "7.5", "3.5", "1.67")),
    ("gyro_misalignment_arcsec", "arcsec", ("22", "2.2", "1.1", "0.4")),
    ("gyro_random_walk_deg_per_h_per_sqrt_hz", "deg/h/sqrt(Hz)", ("4.7", "0.13", "0.066", "0.03")),
)

#: The same rows as floats: ``TABLE_2_5_PRINTED[row][grade index]``.
TABLE_2_5_PRINTED: dict[str, tuple[float, ...]] = {
    row: tuple(float(v) for v in values) for row, _, values in TABLE_2_5_ROWS
}


def sp_imu_grades() -> dict[float, ImuSpec]:
    """The four IMU qualities of SP Table 2.5 as :class:`ImuSpec` (keyed by nmi/h label).

    All errors except the random walks are 1-sigma biases (random constants).
    """
    grades = {}
    for j, label in enumerate(GRADE_LABELS_NMI_PER_H):
        kwargs = {row: TABLE_2_5_PRINTED[row][j] for row in TABLE_2_5_PRINTED}
        grades[label] = imu_spec_from_published(f"{label:g} nmi/h", source="SP Table 2.5", **kwargs)
    return grades


@dataclass(frozen=True)
class DopplerErrorModel:
    """1-sigma errors of a body-frame Doppler ground-speed sensor (SI).

    Attributes
    ----------
    bias_horizontal, bias_vertical : float
        Velocity bias per axis (m/s).
    scale_factor_horizontal, scale_factor_vertical : float
        Scale-factor error (dimensionless).
    misalignment : float
        Boresight misalignment per axis (rad).
    noise : float
        White measurement noise per axis and per sample (m/s). Not in the paper's table.
    """

    bias_horizontal: float
    bias_vertical: float
    scale_factor_horizontal: float
    scale_factor_vertical: float
    misalignment: float
    noise: float = 0.0


#: Table 2.8 (Sec. 2.6.4): bias 0.1 / 0.05 nmi/h, scale factor 0.25 % / 0.1 %, 2.0 mrad.
TABLE_2_8 = DopplerErrorModel(
    bias_horizontal=0.1 * NMI_PER_H,
    bias_vertical=0.05 * NMI_PER_H,
    scale_factor_horizontal=0.25e-2,
    scale_factor_vertical=0.1e-2,
    misalignment=2.0 * MRAD,
)

#: Table 2.4 Gauss-Markov processes.
GRAVITY_MARKOV = GaussMarkovSpec(35.0 * MICRO_G, 37.0 * KM)
BAROMETER_MARKOV = GaussMarkovSpec(150.0, 460.0 * KM)

#: Acceleration of gravity used to express g-sensitivity (m/s^2 per g).
G_UNIT = G0
