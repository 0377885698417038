"""SP Sections 2.5 (end), 2.6.2 and 2.6.4: acquisition search time, Table 2.7, target location.

Table 2.7 (code-phase intervals to search at reacquisition in the jammer flyby) is typed
here as input; the search times and the "32 %" follow from it and from the Delta T formula.
The target-location check uses the helicopter's printed 1 nmi/h position error (Sec. 2.6.4)
and an assumed gyrocompass heading error from the Table 2.5 gyro bias.
"""

from __future__ import annotations

import math

import numpy as np

from navcore.gnss.acquisition import (
    doppler_cell_hz,
    probability_outside_sigma_box,
    range_rate_from_doppler,
    search_time_from_cells,
)
from navcore.gnss.tracking import distance_to_phase_deg
from navcore.ledger import EXACT, Claim, Erratum, Tolerance, printed
from navcore.location.target_location import target_location_rss
from navcore.papers.sp_tables import table_2_5_value
from navcore.units import DEG, DEG_PER_H, GPS_L1_WAVELENGTH_M, OMEGA_EARTH

PAGE_ACQ = "sp/04-acquisition"
PAGE_TGT = "sp/05-target-location"

# --- Sec. 2.5: the search parameters as printed ------------------------------------------
DWELL_S = 0.020  # "a 20-ms integration period"
PHASE_STEP_DEG = 36.0  # "phase shift between 20-ms search intervals was 36 deg corresponding to 30 m"
RANGE_CELL_M = 30.0
DOPPLER_CELL_HZ = 50.0  # "frequency bandwidth was 50 Hz corresponding to 10 m/s"
RATE_CELL_MPS = 10.0
CODE_LENGTH_M = 300.0  # the Sec. 2.5 conversion (360 deg per 300 m)

# --- Table 2.7: range (code-phase) intervals to be searched, per satellite ----------------
TABLE_2_7_SATELLITES = (3, 11, 12, 15, 17, 18, 21)
TABLE_2_7 = {
    "Tightly coupled 10 nmi/h": (73, 64, 70, 42, 82, 70, 43),
    "Loosely coupled 1.0 nmi/h": (8, 8, 8, 6, 9, 8, 6),
    "Tightly coupled 1.0 nmi/h": (7, 6, 6, 5, 7, 6, 5),
    "Tightly coupled 0.5 nmi/h": (6, 6, 6, 5, 6, 6, 5),
    "Tightly coupled 0.2 nmi/h": (6, 5, 6, 5, 6, 5, 5),
}
TC10 = "Tightly coupled 10 nmi/h"
BETTER = tuple(k for k in TABLE_2_7 if k != TC10)

# --- Sec. 2.6.4: helicopter scout ---------------------------------------------------------
TARGET_RANGE_M = 8000.0  # "at some distance (8 km)"
HELICOPTER_ERROR_1NMI_M = 192.0  # "2750:192" (1 nmi/h, 19 min after loss of GPS, no Doppler)
HELICOPTER_ERROR_10NMI_M = 2750.0
#: Assumption for the pointing error: the steady-state gyrocompass heading error of the Table 2.5
#: gyro bias at latitude 45 deg, psi = eps / (Omega cos L); the paper gives no attitude error.
ASSUMED_LATITUDE_DEG = 45.0


def search_times_s(system: str) -> np.ndarray:
    """Search time (s) per satellite: 20 ms per code-phase interval, one Doppler cell."""
    return np.asarray(search_time_from_cells(np.array(TABLE_2_7[system]), 1, DWELL_S))


def better_max_s() -> float:
    return float(max(np.max(search_times_s(k)) for k in BETTER))


def table_2_7_monotone() -> bool:
    """Per satellite, intervals never increase with IMU quality, and TC 1.0 <= LC 1.0."""
    order = [TC10, "Loosely coupled 1.0 nmi/h", "Tightly coupled 1.0 nmi/h", "Tightly coupled 0.5 nmi/h"]
    order.append("Tightly coupled 0.2 nmi/h")
    rows = np.array([TABLE_2_7[k] for k in order])
    return bool(np.all(np.diff(rows, axis=0) <= 0))


def gyrocompass_heading_error_rad(grade: str) -> float:
    """Assumed heading error: gyro bias / (Earth rate x cos latitude)."""
    return (
        table_2_5_value("gyro_bias_deg_per_h", float(grade))
        * DEG_PER_H
        / (OMEGA_EARTH * math.cos(ASSUMED_LATITUDE_DEG * DEG))
    )


def pointing_negligible() -> bool:
    """Target error within 1 % of the position error for both printed helicopter errors."""
    ok = True
    for grade, pos in (("1", HELICOPTER_ERROR_1NMI_M), ("10", HELICOPTER_ERROR_10NMI_M)):
        tgt = target_location_rss(pos, gyrocompass_heading_error_rad(grade), TARGET_RANGE_M)
        ok &= tgt / pos < 1.01
    return bool(ok)


ERRATA = [
    Erratum(
        id="SP-E-search-doppler-factor",
        paper="SP",
        locator="Sec. 2.5, Delta T formula; Sec. 2.6.2",
        printed="Delta T = 0.020 [2 sigma_rng/30] x [2 sigma_rng-rate/10]; 'one Doppler shift interval' "
        "for range-rate uncertainties up to 10 m/s",
        finding="Taken literally, sigma_rng-rate up to 10 m/s gives a Doppler factor up to 2, not 1; the "
        "brackets must be cell counts (ceilings, at least 1) and Sec. 2.6.2 counts a single 10-m/s "
        "interval. The 50-Hz cell is 9.5 m/s at L1, printed as 10 m/s. The '20 ms/chip' of Sec. 2.6.2 "
        "calls the 30-m interval a chip: it matches a P(Y) chip (29.3 m), while the 36 deg per 30 m "
        "phase convention is 360 deg per 300 m.",
        evidence="Search times recomputed from Table 2.7 with one Doppler cell reproduce the printed "
        "0.2 s and 0.8-1.6 s; 50 Hz x 0.1903 m = 9.51 m/s.",
        claims=("SP-sec2.6.2-search-better", "SP-sec2.5-doppler-cell-mps"),
        discussed_in=PAGE_ACQ,
    ),
]

_t02 = printed("0.2")
_t08 = printed("0.8", why="'about 0.8 to 1.6 s'")
_t16 = printed("1.6", why="'about 0.8 to 1.6 s'")
_p32 = printed("32")

CLAIMS = [
    Claim(
        id="SP-sec2.5-phase-step-deg",
        paper="SP",
        locator="Sec. 2.5 (acquisition)",
        quantity="code-phase step between 20-ms search intervals for a 30-m cell",
        published=PHASE_STEP_DEG,
        unit="deg",
        compute=lambda: float(distance_to_phase_deg(RANGE_CELL_M, CODE_LENGTH_M)),
        tolerance=Tolerance(reason="exact ratio of printed numbers", abs=1e-9),
        expected_status="reproduced",
        note="36 deg per 30 m is the section's 360 deg per 300 m convention (close to a C/A chip, 293 m).",
    ),
    Claim(
        id="SP-sec2.5-doppler-cell-hz",
        paper="SP",
        locator="Sec. 2.5 (acquisition)",
        quantity="frequency cell of a 20-ms coherent dwell",
        published=DOPPLER_CELL_HZ,
        unit="Hz",
        compute=lambda: doppler_cell_hz(DWELL_S),
        tolerance=Tolerance(reason="exact: 1/T", abs=1e-9),
        expected_status="reproduced",
        note="The frequency resolution of a T = 20 ms integration is 1/T.",
    ),
    Claim(
        id="SP-sec2.5-doppler-cell-mps",
        paper="SP",
        locator="Sec. 2.5 (acquisition)",
        quantity="range rate corresponding to the 50-Hz frequency cell at L1",
        published=RATE_CELL_MPS,
        unit="m/s",
        compute=lambda: float(range_rate_from_doppler(DOPPLER_CELL_HZ, GPS_L1_WAVELENGTH_M)),
        tolerance=printed("10", why="'10 m/s' read as one significant figure")[1],
        expected_status="reproduced",
        note="50 Hz x 0.1903 m = 9.51 m/s, printed as 10 m/s.",
    ),
    Claim(
        id="SP-tab2.7-intervals",
        paper="SP",
        locator="Table 2.7",
        quantity="code-phase intervals to be searched per satellite at reacquisition",
        published=73.0,
        unit="intervals",
        compute=None,
        tolerance=EXACT,
        expected_status="not-reproducible",
        note="Needs the flyby trajectory, jammer position and power, antenna pattern, satellite geometry "
        "and the covariance history of each system, none of which are published; the table is used as "
        "input (value shown: TC 10 nmi/h, SV 3).",
    ),
    Claim(
        id="SP-tab2.7-ordering",
        paper="SP",
        locator="Table 2.7",
        quantity="intervals never increase with IMU quality, and tight coupling needs fewer than loose",
        published=True,
        unit="statement",
        compute=table_2_7_monotone,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Checked per satellite on the typed table (TC10 >= LC1.0 >= TC1.0 >= TC0.5 >= TC0.2), the "
        "ordering the text attributes to better calibration.",
    ),
    Claim(
        id="SP-sec2.6.2-search-better",
        paper="SP",
        locator="Sec. 2.6.2",
        quantity="longest search time of the better IMUs (20 ms per interval)",
        published=_t02[0],
        unit="s",
        compute=better_max_s,
        tolerance=_t02[1],
        expected_status="reproduced",
        note="Delta T = 20 ms x intervals x one Doppler cell: 0.10 to 0.18 s for the four better systems.",
    ),
    Claim(
        id="SP-sec2.6.2-search-10-min",
        paper="SP",
        locator="Sec. 2.6.2",
        quantity="shortest search time of the 10 nmi/h system",
        published=_t08[0],
        unit="s",
        compute=lambda: float(np.min(search_times_s(TC10))),
        tolerance=_t08[1],
        expected_status="reproduced",
        note="42 intervals x 20 ms = 0.84 s.",
    ),
    Claim(
        id="SP-sec2.6.2-search-10-max",
        paper="SP",
        locator="Sec. 2.6.2",
        quantity="longest search time of the 10 nmi/h system",
        published=_t16[0],
        unit="s",
        compute=lambda: float(np.max(search_times_s(TC10))),
        tolerance=_t16[1],
        expected_status="reproduced",
        note="82 intervals x 20 ms = 1.64 s.",
    ),
    Claim(
        id="SP-sec2.6.2-outside-1sigma",
        paper="SP",
        locator="Sec. 2.6.2",
        quantity="probability that the signal lies outside the 1-sigma search bounds",
        published=_p32[0],
        unit="%",
        compute=lambda: 100.0 * probability_outside_sigma_box(1, 1.0),
        tolerance=_p32[1],
        expected_status="reproduced",
        note="One-dimensional (code phase only, one Doppler cell): 31.73 %. Outside a 1-sigma box in code "
        "and Doppler it would be 53.4 %.",
    ),
    Claim(
        id="SP-sec2.6.4-pointing-gyrocompass",
        paper="SP",
        locator="Sec. 2.6.4",
        quantity="pointing error over 8 km is negligible next to the helicopter's position error "
        "(gyrocompass heading error assumed)",
        published=True,
        unit="statement",
        compute=pointing_negligible,
        tolerance=EXACT,
        expected_status="consistent",
        note="Target error = rss of the printed position error (192 m, 2750 m) and misalignment x 8 km; "
        "the attitude error is not published, so the steady-state gyrocompass heading error of the "
        "Table 2.5 gyro bias at 45 deg latitude is assumed (0.42 and 10.3 mrad): the target error is "
        "within 1 % of the position error for both IMUs. The mission pages check the same statement "
        "with their end-of-mission covariance (SP-sec2.6.4-pointing-negligible).",
        discussed_in=PAGE_TGT,
    ),
]
