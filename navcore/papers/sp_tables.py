"""SP Tables 2.4, 2.5 and 2.8 as published inputs, with units and locators.

Every number is declared once, as printed, in the unit it is printed in, as an input of
:data:`IN` (``InputSet("SP", "tables")``); the SI value is derived with the factors of
:mod:`navcore.units` inside the functions below, so every read is recorded by the ledger.
The mission analysis of :mod:`navcore.papers.sp_missions` reads these functions and nothing
else from the tables.

Input names: Table 2.4 rows by name (``IN.initial_position_horizontal_m``), Table 2.5 cells
as ``<row>_<grade key>`` (``IN.gyro_bias_deg_per_h_1`` for the 1.0 nmi/h column; grade keys
``10``, ``1``, ``0p5``, ``0p2``, see :func:`grade_key`), Table 2.8 as ``doppler_*``.

Table 2.4 (INS-independent errors), Table 2.5 (the four IMU qualities) and Table 2.8 (the
Doppler ground-speed sensor) of G. T. Schmidt and R. E. Phillips, "INS/GPS Integration
Architecture Performance Comparisons", NATO RTO-EN-SET-116, Sec. 2.3-2.6.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass

from navcore.claims import input_cache
from navcore.claims.inputs import InputSet
from navcore.inertial.imu import ImuSpec, imu_spec_from_published
from navcore.units import KM, MICRO_G, MRAD, NMI_PER_H, PPM, C

__all__ = [
    "GRADE_LABELS_NMI_PER_H",
    "IN",
    "TABLE_2_5_PRINTED",
    "TABLE_2_5_ROWS",
    "DopplerErrorModel",
    "GaussMarkovSpec",
    "TableEntry",
    "barometer_markov",
    "grade_key",
    "gravity_markov",
    "sp_imu_grade",
    "sp_imu_grades",
    "table_2_4",
    "table_2_5_printed",
    "table_2_5_value",
    "table_2_8",
]

IN = InputSet("SP", "tables")

_T24 = "Table 2.4"
_T25 = "Table 2.5"
_T28 = "Table 2.8"


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


# --- Table 2.4 ------------------------------------------------------------------------
#: (row name, input name, printed text, printed unit, components)
_TABLE_2_4_ROWS: tuple[tuple[str, str, str, str, int], ...] = (
    ("initial position (vertical)", "initial_position_vertical_m", "16", "m", 1),
    ("initial position (horizontal)", "initial_position_horizontal_m", "600", "m", 2),
    ("initial velocity", "initial_velocity_mps", "0.3", "m/s", 3),
    # "5000 ms" as printed; read as 5000 m of clock offset (see the clock-offset note).
    ("clock initial offset", "clock_initial_offset_m", "5000", "ms (read as m)", 1),
    ("clock initial drift", "clock_initial_drift_ppm", "1e-2", "ppm", 1),
    ("clock g-sensitive drift", "clock_g_sensitivity_ppm_per_g", "1e-3", "ppm/g", 1),
    ("pseudorange bias", "pseudorange_bias_m", "3.0", "m", 4),
    ("range-rate bias", "range_rate_bias_mps", "0.003", "m/s", 4),
    ("gravity (Markov) $\\sigma$", "gravity_sigma_micro_g", "35", "µg", 3),
    ("gravity (Markov) distance", "gravity_distance_km", "37", "km", 3),
    ("barometer (Markov) $\\sigma$", "barometer_sigma_m", "150", "m", 1),
    ("barometer (Markov) distance", "barometer_distance_km", "460", "km", 1),
    ("barometer noise", "barometer_noise_m", "3", "m", 1),
)
#: SI factor of each printed unit
_SI = {
    "m": 1.0,
    "m/s": 1.0,
    "ms (read as m)": 1.0,
    "ppm": PPM * C,
    "ppm/g": PPM * C,
    "µg": MICRO_G,
    "km": KM,
}

for _row, _name, _text, _unit, _n in _TABLE_2_4_ROWS:
    IN.published(
        _name,
        float(_text),
        locator=_T24 + (" (printed '5000 ms'; read as 5000 m of clock offset)" if "read as" in _unit else ""),
        unit=_unit.replace(" (read as m)", "") if "read as" not in _unit else "m",
        quantity=_row,
    )


def table_2_4() -> dict[str, TableEntry]:
    """Table 2.4 keyed by row name (SI values in ``.si``: m, m/s, m/s^2, m/s per g).

    Reads every Table 2.4 input; use the single input (``IN.pseudorange_bias_m``) where one
    row is needed.
    """
    out = {}
    for row, name, text, unit, n in _TABLE_2_4_ROWS:
        value = getattr(IN, name)
        out[row] = TableEntry(row, text, unit, value * _SI[unit], n, _T24)
    return out


def gravity_markov() -> GaussMarkovSpec:
    """Table 2.4 gravity anomaly: 35 µg, 37 km (SI)."""
    return GaussMarkovSpec(IN.gravity_sigma_micro_g * MICRO_G, IN.gravity_distance_km * KM)


def barometer_markov() -> GaussMarkovSpec:
    """Table 2.4 barometric altimeter error: 150 m, 460 km (SI)."""
    return GaussMarkovSpec(IN.barometer_sigma_m, IN.barometer_distance_km * KM)


# --- Table 2.5 ------------------------------------------------------------------------
#: Grade labels: the 1-hour unaided navigation error that names each column (nmi/h). They
#: are the columns' names (keys and ids), and the published values of SP-tab2.5-grade-*.
GRADE_LABELS_NMI_PER_H: tuple[float, ...] = (10.0, 1.0, 0.5, 0.2)

#: Table 2.5 rows in printed units, one value per grade (10, 1.0, 0.5, 0.2 nmi/h).
TABLE_2_5_ROWS: tuple[tuple[str, str, tuple[str, str, str, str]], ...] = (
    ("accel_bias_micro_g", "µg", ("223", "37", "19", "4.2")),
    ("accel_scale_factor_ppm", "ppm", ("223", "179", "90", "21")),
    ("accel_misalignment_arcsec", "arcsec", ("22", "3", "1.5", "0.4")),
    ("accel_random_walk_micro_g_per_sqrt_hz", "µg/√Hz", ("56", "15", "7.5", "4.2")),
    ("gyro_bias_deg_per_h", "deg/h", ("0.11", "0.0045", "0.0022", "0.00084")),
    ("gyro_scale_factor_ppm", "ppm", ("112", "7.5", "3.5", "1.67")),
    ("gyro_misalignment_arcsec", "arcsec", ("22", "2.2", "1.1", "0.4")),
    ("gyro_random_walk_deg_per_h_per_sqrt_hz", "deg/h/√Hz", ("4.7", "0.13", "0.066", "0.03")),
)


#: How a claim's text names each Table 2.5 row (the unit is said apart, from the input's unit).
TABLE_2_5_QUANTITIES: dict[str, str] = {
    "accel_bias_micro_g": "accelerometer bias",
    "accel_scale_factor_ppm": "accelerometer scale factor",
    "accel_misalignment_arcsec": "accelerometer misalignment",
    "accel_random_walk_micro_g_per_sqrt_hz": "accelerometer white noise (velocity random walk)",
    "gyro_bias_deg_per_h": "gyro bias",
    "gyro_scale_factor_ppm": "gyro scale factor",
    "gyro_misalignment_arcsec": "gyro misalignment",
    "gyro_random_walk_deg_per_h_per_sqrt_hz": "gyro white noise (angle random walk)",
}


def grade_key(label: float) -> str:
    """Input-name suffix of a Table 2.5 column: ``10``, ``1``, ``0p5``, ``0p2``."""
    return f"{label:g}".replace(".", "p")


for _row, _unit, _texts in TABLE_2_5_ROWS:
    for _label, _text in zip(GRADE_LABELS_NMI_PER_H, _texts, strict=True):
        IN.published(
            f"{_row}_{grade_key(_label)}",
            float(_text),
            locator=f"{_T25}, {_label:g} nmi/h column",
            unit=_unit,
            quantity=TABLE_2_5_QUANTITIES[_row],
        )


def table_2_5_value(row: str, grade: float) -> float:
    """One Table 2.5 cell in printed units (``row`` as in :data:`TABLE_2_5_ROWS`)."""
    return getattr(IN, f"{row}_{grade_key(grade)}")


def table_2_5_printed() -> dict[str, tuple[float, ...]]:
    """Table 2.5 as floats: ``[row][grade index]`` (reads every cell)."""
    return {
        row: tuple(table_2_5_value(row, g) for g in GRADE_LABELS_NMI_PER_H) for row, _, _ in TABLE_2_5_ROWS
    }


class _Table25View(Mapping):
    """``TABLE_2_5_PRINTED[row][grade index]``: reads the inputs when indexed (not at import)."""

    def __getitem__(self, row: str) -> tuple[float, ...]:
        if row not in {r for r, _, _ in TABLE_2_5_ROWS}:
            raise KeyError(row)
        return tuple(table_2_5_value(row, g) for g in GRADE_LABELS_NMI_PER_H)

    def __iter__(self) -> Iterator[str]:
        return iter(r for r, _, _ in TABLE_2_5_ROWS)

    def __len__(self) -> int:
        return len(TABLE_2_5_ROWS)


#: Table 2.5 cells as floats, ``TABLE_2_5_PRINTED[row][grade index]``; indexing reads the
#: inputs (so it works inside computations and on pages, not at a paper module's import).
TABLE_2_5_PRINTED: Mapping[str, tuple[float, ...]] = _Table25View()


@input_cache
def sp_imu_grade(label: float) -> ImuSpec:
    """One Table 2.5 column as an :class:`ImuSpec` (reads that column's inputs only)."""
    kwargs = {row: table_2_5_value(row, label) for row, _, _ in TABLE_2_5_ROWS}
    return imu_spec_from_published(f"{label:g} nmi/h", source="SP Table 2.5", **kwargs)


def sp_imu_grades() -> dict[float, ImuSpec]:
    """The four IMU qualities of SP Table 2.5 as :class:`ImuSpec` (keyed by nmi/h label).

    All errors except the random walks are 1-sigma biases (random constants).
    """
    return {label: sp_imu_grade(label) for label in GRADE_LABELS_NMI_PER_H}


# --- Table 2.8 ------------------------------------------------------------------------
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


IN.published(
    "doppler_bias_horizontal_nmi_per_h", 0.1, locator=_T28, unit="nmi/h", quantity="Doppler bias, horizontal"
)
IN.published(
    "doppler_bias_vertical_nmi_per_h", 0.05, locator=_T28, unit="nmi/h", quantity="Doppler bias, vertical"
)
IN.published(
    "doppler_scale_factor_horizontal_pct",
    0.25,
    locator=_T28,
    unit="%",
    quantity="Doppler scale factor, horizontal",
)
IN.published(
    "doppler_scale_factor_vertical_pct",
    0.1,
    locator=_T28,
    unit="%",
    quantity="Doppler scale factor, vertical",
)
IN.published(
    "doppler_misalignment_mrad", 2.0, locator=_T28, unit="mrad", quantity="Doppler boresight misalignment"
)


def table_2_8() -> DopplerErrorModel:
    """Table 2.8 (Sec. 2.6.4): bias 0.1 / 0.05 nmi/h, scale factor 0.25 % / 0.1 %, 2.0 mrad (SI)."""
    return DopplerErrorModel(
        bias_horizontal=IN.doppler_bias_horizontal_nmi_per_h * NMI_PER_H,
        bias_vertical=IN.doppler_bias_vertical_nmi_per_h * NMI_PER_H,
        scale_factor_horizontal=IN.doppler_scale_factor_horizontal_pct * 1e-2,
        scale_factor_vertical=IN.doppler_scale_factor_vertical_pct * 1e-2,
        misalignment=IN.doppler_misalignment_mrad * MRAD,
    )
