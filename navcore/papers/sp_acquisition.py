"""SP Sections 2.5 (end), 2.6.2 and 2.6.4: acquisition search time, Table 2.7, target location.

Table 2.7 (code-phase intervals to search at reacquisition in the jammer flyby) is typed
here as input; the search times and the "32 %" follow from it and from the Delta T formula.
The target-location check uses the helicopter's printed 1 nmi/h position error (Sec. 2.6.4)
and an assumed gyrocompass heading error from the Table 2.5 gyro bias.
"""

from __future__ import annotations

import math

import numpy as np

from navcore.claims import Claim, Erratum, InputSet, printed, prose, with_quotes
from navcore.gnss.acquisition import (
    doppler_cell_hz,
    probability_outside_sigma_box,
    range_rate_from_doppler,
    search_time_from_cells,
)
from navcore.gnss.tracking import distance_to_phase_deg
from navcore.location.target_location import target_location_rss
from navcore.papers import sp_tracking as spt
from navcore.papers.sp_quotes import QUOTES
from navcore.papers.sp_tables import TABLE_2_5_PRINTED
from navcore.units import DEG, DEG_PER_H, GPS_L1_WAVELENGTH_M, OMEGA_EARTH

PAGE = "sp/04-acquisition"
PAGE_TGT = "sp/05-target-location"

# --- Table 2.7: range (code-phase) intervals to be searched, per satellite ----------------
TABLE_2_7_SATELLITES = (3, 11, 12, 15, 17, 18, 21)
#: Row labels of Table 2.7 and the names of their inputs.
TABLE_2_7_ROWS = {
    "Tightly coupled 10 nmi/h": "tab27_tc10",
    "Loosely coupled 1.0 nmi/h": "tab27_lc1",
    "Tightly coupled 1.0 nmi/h": "tab27_tc1",
    "Tightly coupled 0.5 nmi/h": "tab27_tc05",
    "Tightly coupled 0.2 nmi/h": "tab27_tc02",
}
TC10 = "Tightly coupled 10 nmi/h"
BETTER = tuple(k for k in TABLE_2_7_ROWS if k != TC10)

IN = InputSet("SP", "acquisition")
# --- Sec. 2.5: the search parameters as printed ------------------------------------------
IN.published(
    "dwell_s", 0.020, locator="Sec. 2.5 (acquisition)", unit="s", quantity="integration period per cell"
)
IN.published(
    "range_cell_m", 30.0, locator="Sec. 2.5 (acquisition)", unit="m", quantity="code-phase search cell"
)
IN.published(
    "doppler_cell_hz", 50.0, locator="Sec. 2.5 (acquisition)", unit="Hz", quantity="frequency search cell"
)
IN.convention(
    "search_dimensions",
    1,
    readings={
        "in code phase only, over the one Doppler cell of Sec. 2.6.2": 1,
        "a box in code phase and Doppler": 2,
    },
    reason="Sec. 2.6.2 searches one Doppler cell, so the bounds are in code phase only; the other reading "
    "is a 1-$\\sigma$ box in code phase and Doppler",
    quantity="dimensions of the 1-$\\sigma$ search bounds",
)
for _label, _name in TABLE_2_7_ROWS.items():
    IN.published(
        _name,
        {
            "tab27_tc10": (73, 64, 70, 42, 82, 70, 43),
            "tab27_lc1": (8, 8, 8, 6, 9, 8, 6),
            "tab27_tc1": (7, 6, 6, 5, 7, 6, 5),
            "tab27_tc05": (6, 6, 6, 5, 6, 6, 5),
            "tab27_tc02": (6, 5, 6, 5, 6, 5, 5),
        }[_name],
        locator=f"Table 2.7, row '{_label}'",
        unit="intervals",
        quantity=f"code-phase intervals to search per satellite, {_label}",
    )
# --- Sec. 2.6.4: helicopter scout ---------------------------------------------------------
IN.published("target_range_m", 8000.0, locator="Sec. 2.6.4", unit="m", quantity="distance to the target")
IN.published(
    "helicopter_error_1nmi_m",
    192.0,
    locator="Sec. 2.6.4 ('2750:192')",
    unit="m",
    quantity="1 nmi/h position error",
)
IN.published(
    "helicopter_error_10nmi_m",
    2750.0,
    locator="Sec. 2.6.4 ('2750:192')",
    unit="m",
    quantity="10 nmi/h position error",
)
IN.assumed(
    "latitude_deg",
    45.0,
    low=30.0,
    high=60.0,
    unit="deg",
    quantity="latitude of the gyrocompass alignment",
    reason="the paper gives no attitude error; the steady-state gyrocompass heading error "
    "$\\varepsilon/(\\Omega \\cos L)$ is assumed, at a mid latitude of 30 to 60 deg",
)
IN.convention(
    "negligible_rel",
    0.01,
    readings={"within 1 %": 0.01, "within 10 % (the prose table's 'nearly')": 0.10},
    quantity="threshold of 'negligible' pointing (the share by which it may raise the target error "
    "over the position error)",
    reason="Sec. 2.6.4: 'the pointing error is negligible compared with the position error so that the "
    "target location errors and the aircraft position errors are essentially the same' carries no "
    "number",
)
GRADE_INDEX = {"10": 0, "1": 1}  # columns of Table 2.5 (sp_tables) for the two helicopter IMUs


def table_2_7(system: str) -> tuple[int, ...]:
    """One row of Table 2.7 (published input)."""
    return getattr(IN, TABLE_2_7_ROWS[system])


def search_times_s(system: str) -> np.ndarray:
    """Search time (s) per satellite: 20 ms per code-phase interval, one Doppler cell."""
    return np.asarray(search_time_from_cells(np.array(table_2_7(system)), 1, IN.dwell_s))


def better_max_s() -> float:
    return float(max(np.max(search_times_s(k)) for k in BETTER))


def table_2_7_monotone() -> bool:
    """Per satellite, intervals never increase with IMU quality, and TC 1.0 <= LC 1.0."""
    order = [TC10, "Loosely coupled 1.0 nmi/h", "Tightly coupled 1.0 nmi/h", "Tightly coupled 0.5 nmi/h"]
    order.append("Tightly coupled 0.2 nmi/h")
    rows = np.array([table_2_7(k) for k in order])
    return bool(np.all(np.diff(rows, axis=0) <= 0))


def gyrocompass_heading_error_rad(grade: str) -> float:
    """Assumed heading error: gyro bias / (Earth rate x cos latitude)."""
    bias = TABLE_2_5_PRINTED["gyro_bias_deg_per_h"][GRADE_INDEX[grade]]
    return bias * DEG_PER_H / (OMEGA_EARTH * math.cos(IN.latitude_deg * DEG))


def pointing_negligible() -> bool:
    """Target error within the declared 'negligible' share (1 %) of the position error for both
    printed helicopter errors."""
    ok = True
    for grade, pos in (("1", IN.helicopter_error_1nmi_m), ("10", IN.helicopter_error_10nmi_m)):
        tgt = target_location_rss(pos, gyrocompass_heading_error_rad(grade), IN.target_range_m)
        ok &= tgt / pos < 1.0 + IN.negligible_rel
    return bool(ok)


ERRATA: list[Erratum] = []

_t02 = printed("0.2")
_ABOUT_SEARCH = prose("about", why="'holds the search time to about 0.8 to 1.6 s'")
_p32 = printed("32")
_d36 = printed("36")
_hz50 = printed("50")

CLAIMS = [
    Claim(
        id="SP-sec2.5-phase-step-deg",
        locator="Sec. 2.5 (acquisition)",
        quantity="code-phase step between 20-ms search intervals for a 30-m cell",
        published=_d36[0],
        unit="deg",
        kind="cross-check",
        compute=lambda: float(distance_to_phase_deg(IN.range_cell_m, spt.IN.code_length_m)),
        tolerance=_d36[1],
        expected_status="consistent",
        note="36 deg per 30 m is the section's 360 deg per 300 m convention (close to a C/A chip, 293 m): "
        "arithmetic on printed numbers, a cross-check.",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim(
        id="SP-sec2.5-doppler-cell-hz",
        locator="Sec. 2.5 (acquisition)",
        quantity="frequency cell of a 20-ms coherent dwell",
        published=_hz50[0],
        unit="Hz",
        compute=lambda: doppler_cell_hz(IN.dwell_s),
        tolerance=_hz50[1],
        expected_status="reproduced",
        note="The frequency resolution of a T = 20 ms integration is 1/T.",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim(
        id="SP-sec2.5-doppler-cell-mps",
        locator="Sec. 2.5 (acquisition)",
        quantity="range rate corresponding to the 50-Hz frequency cell at L1",
        published=10.0,
        unit="m/s",
        compute=lambda: float(range_rate_from_doppler(IN.doppler_cell_hz, GPS_L1_WAVELENGTH_M)),
        tolerance=printed("10", why="'50 Hz corresponding to 10 m/s'")[1],
        expected_status="reproduced",
        note="$50\\ \\mathrm{Hz} \\times 0.1903\\ \\mathrm{m} = 9.51$ m/s, printed as 10 m/s.",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim.statement(
        id="SP-tab2.7-ordering",
        locator="Table 2.7",
        quantity="intervals never increase with IMU quality, and tight coupling needs fewer than loose",
        kind="cross-check",
        compute=table_2_7_monotone,
        expected_status="consistent",
        note="Checked per satellite on the printed table (TC10 $\\ge$ LC1.0 $\\ge$ TC1.0 $\\ge$ TC0.5 "
        "$\\ge$ TC0.2), the "
        "ordering the text attributes to better calibration: a check on printed numbers, a cross-check.",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim(
        id="SP-sec2.6.2-search-better",
        locator="Sec. 2.6.2",
        quantity="longest search time of the better IMUs (20 ms per interval)",
        published=_t02[0],
        unit="s",
        kind="cross-check",
        compute=better_max_s,
        tolerance=_t02[1],
        expected_status="consistent",
        note="$\\Delta T = 20\\ \\mathrm{ms} \\times$ intervals $\\times$ one Doppler cell: 0.10 to 0.18 "
        "s for the four better "
        "systems; "
        "arithmetic on printed numbers, a cross-check. One Doppler cell: the Sec. 2.5 formula's "
        "$\\lceil 2 \\sigma_{\\text{rng-rate}}/10 \\rceil$ is one 10-m/s interval when 'not greater than "
        "10 m/s' bounds "
        "the whole uncertainty span; the 30-m interval called a 'chip' is a P(Y) chip (29.3 m).",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim(
        id="SP-sec2.6.2-search-10-min",
        locator="Sec. 2.6.2",
        quantity="shortest search time of the 10 nmi/h system",
        published=0.8,
        unit="s",
        kind="cross-check",
        compute=lambda: float(np.min(search_times_s(TC10))),
        tolerance=_ABOUT_SEARCH,
        expected_status="consistent",
        note="42 intervals $\\times$ 20 ms = 0.84 s, arithmetic on printed numbers, a cross-check.",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim(
        id="SP-sec2.6.2-search-10-max",
        locator="Sec. 2.6.2",
        quantity="longest search time of the 10 nmi/h system",
        published=1.6,
        unit="s",
        kind="cross-check",
        compute=lambda: float(np.max(search_times_s(TC10))),
        tolerance=_ABOUT_SEARCH,
        expected_status="consistent",
        note="82 intervals $\\times$ 20 ms = 1.64 s, arithmetic on printed numbers, a cross-check.",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim(
        id="SP-sec2.6.2-outside-1sigma",
        locator="Sec. 2.6.2",
        quantity="probability that the signal lies outside the $1\\sigma$ search bounds",
        published=_p32[0],
        unit="%",
        compute=lambda: 100.0 * probability_outside_sigma_box(IN.search_dimensions, 1.0),
        tolerance=_p32[1],
        expected_status="reproduced",
        note="One-dimensional (code phase only, one Doppler cell): 31.73 %.",
        discussed_in=PAGE,
        table="acquisition",
    ),
    Claim.statement(
        id="SP-sec2.6.4-pointing-gyrocompass",
        locator="Sec. 2.6.4",
        quantity="pointing error over 8 km is negligible next to the helicopter's position error "
        "(gyrocompass heading error assumed)",
        compute=pointing_negligible,
        expected_status="consistent",
        note="Target error = rss of the printed position error (192 m, 2750 m) and misalignment "
        "$\\times$ 8 km; "
        "the attitude error is not published, so the steady-state gyrocompass heading error of the "
        "Table 2.5 gyro bias at 45 deg latitude is assumed (0.42 and 10.3 mrad): the target error is "
        "within 1 % of the position error for both IMUs ('negligible' read as within 1 %, or 10 %). "
        "The mission pages check the same statement "
        "with their end-of-mission covariance (SP-sec2.6.4-pointing-negligible).",
        discussed_in=PAGE_TGT,
        table="gyrocompass-pointing",
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
