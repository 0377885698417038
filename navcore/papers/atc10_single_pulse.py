"""ATC-10 Sec. 2.7 (Figs. 2.1-2.2): single-pulse transmission (K = 1).

The claims of Sec. 2.7's K = 1 curves: the threshold behaviour, the plateau and the nominal jamming
level. Inputs are read from :mod:`navcore.papers.atc10_jamming`.
"""

from __future__ import annotations

import math

import numpy as np

from navcore import units
from navcore.claims import Claim, Erratum, Tolerance, figure_reading, printed, with_quotes
from navcore.claims.inputs import input_cache
from navcore.detection import jamming as jm
from navcore.papers.atc10_jamming import (
    IN,
    IN_COV,
    IN_J,
    K1_PDL_GRID,
    NOMINAL_ERP_TEXT,
    _log_bound,
    design_p_d,
    geometry,
    level,
    required_erp_dbw,
    table21_finite_designs,
)
from navcore.papers.atc10_quotes import QUOTES

CLAIMS: list[Claim] = []
ERRATA: list[Erratum] = []


PAGE_K1 = "atc10/11-single-pulse"


def _plateau_below_minus_12db() -> bool:
    """Sec. 2.7: both K = 1 bounds sit at their ceilings at -12 dB for every P_DL."""
    ok = True
    g = geometry()
    for p_dl in K1_PDL_GRID:
        p_d = design_p_d(p_dl, 1)
        x = 10 ** (-12 / 10)
        for fn, ceil in (
            (jm.log_false_location_bound, jm.log_false_location_ceiling),
            (jm.log_ambiguous_detection_bound, jm.log_ambiguous_detection_ceiling),
        ):
            ok &= float(fn(x, p_d, 1, 0.0, g)) - ceil(p_d, 1, 0.0, g) > math.log(1.0 - IN.plateau_fraction)
    return bool(ok)


#: Reading resolution of the lost Figs. 2.1-2.16 on their dB axis: Tables 1.1 and 2.1 print whole dB.
FIGURE_DB_RESOLUTION = 1.0


_FIGURE_DB_AXIS = "$J/(P_0 B \\tau)$ in dB; the whole-dB entries are read to 1 dB (the figures are lost)"


def _figure_tolerance(text: str, figures: str) -> Tolerance:
    """A whole-dB value read off the lost ``figures``: the reading resolution of their dB axis."""
    return figure_reading(FIGURE_DB_RESOLUTION, figure=figures, axis=_FIGURE_DB_AXIS)


CLAIMS += [
    Claim(
        id="ATC10-sec2.7-pulse-energy",
        locator="Sec. 2.7",
        quantity="pulse energy for $P_0 = 30$ dBW and $\\tau = 10$ µs",
        published=10.0,
        unit="mJ",
        compute=lambda: units.watts_from_dbw(IN.pulse_power_dbw) * IN.pulse_duration_s * 1e3,
        tolerance=printed("10", why="'10 mJoules'")[1],
        expected_status="consistent",
        kind="cross-check",
        note="Arithmetic on printed values only: $E = P_0 \\tau$ from the printed 30 dBW and 10 µs. Every "
        "ERP reads "
        "the one published pulse input, the printed 10 mJ of pulse energy; $P_0$ and $\\tau$ are the paper's "
        "'e.g.' and enter only this check. Sec. 2.6 calls $P_0$ the average power during the pulse and "
        "App. D "
        "the peak power: the two agree for a constant-envelope (PSK) signature, and only $E = P_0 \\tau$ "
        "enters any result.",
        discussed_in=PAGE_K1,
        table="nominal-level",
    ),
    Claim(
        id="ATC10-sec2.7-nominal-33dBW",
        locator="Sec. 2.7 (Figs. 2.1 and 2.2)",
        quantity="nominal jammer ERP for $K = 1$ ($N_{ADL} = 0.01 N_T$, $P_{DL}$ between 0.9 and 0.999)",
        published=float(NOMINAL_ERP_TEXT),
        unit="dBW",
        compute=lambda: required_erp_dbw("ambiguous", IN.nominal_p_dl, 1, figure_read=True),
        tolerance=_figure_tolerance(NOMINAL_ERP_TEXT, "Figs. 2.1 and 2.2"),
        expected_status="consistent",
        kind="reproduction",
        note="The design $P_{DL}$ behind the nominal is assumed anywhere in the printed 0.9-0.999 (band "
        "31.7-33.5 dBW); the caption's 0.88 would give 33.6 dBW. The $N_{FL}$ threshold (99 % of 0.9 $N_T$) "
        "is "
        "34.0 dBW at $P_{DL}$ = 0.9.",
        discussed_in=PAGE_K1,
        table="nominal-level",
    ),
    Claim(
        id="ATC10-sec2.7-lt2dB-ADL",
        locator="Sec. 2.7 (Figs. 2.1 and 2.2)",
        quantity="difference in required jammer ERP between $P_{DL} = 0.9$ and 0.999 ($K = 1$, $N_{ADL}$)",
        published=2.0,
        unit="dB",
        relation="<",
        compute=lambda: (
            required_erp_dbw("ambiguous", IN.sec27_p_dl_low, 1, figure_read=True)
            - required_erp_dbw("ambiguous", IN.sec27_p_dl_high, 1, figure_read=True)
        ),
        tolerance=_figure_tolerance("2", "Figs. 2.1 and 2.2"),
        expected_status="reproduced",
        kind="reproduction",
        note="Thresholds at $N_{ADL} = 0.01 N_T$; higher $P_{DL}$ needs less jamming.",
        discussed_in=PAGE_K1,
        table="nominal-level",
    ),
    Claim(
        id="ATC10-sec2.7-lt2dB-FL",
        locator="Sec. 2.7 (Figs. 2.1 and 2.2)",
        quantity="difference in required jammer ERP between $P_{DL} = 0.9$ and 0.999 ($K = 1$, $N_{FL}$)",
        published=2.0,
        unit="dB",
        relation="<",
        compute=lambda: (
            required_erp_dbw("false", IN.sec27_p_dl_low, 1) - required_erp_dbw("false", IN.sec27_p_dl_high, 1)
        ),
        tolerance=_figure_tolerance("2", "Figs. 2.1 and 2.2"),
        expected_status="reproduced",
        kind="reproduction",
        note="Thresholds at 99 % of the $N_{FL}$ supremum 0.9 $N_T$.",
        discussed_in=PAGE_K1,
        table="nominal-level",
    ),
    Claim.statement(
        id="ATC10-sec2.7-plateau",
        locator="Sec. 2.7",
        quantity="from -12 dB downwards the K = 1 bounds keep their maximum values over a large range",
        compute=_plateau_below_minus_12db,
        kind="statement",
        note="Both bounds are within 0.1 % (and so 1 %) of their $J \\to \\infty$ ceilings at -12 dB for "
        "$P_{DL}$ in "
        "{0.88, "
        "0.9, "
        "0.99, 0.999}; the threshold falls 2-4 dB further down.",
        discussed_in=PAGE_K1,
        table="nominal-level",
    ),
]


def _designs() -> list[tuple[int, float]]:
    """K = 1 at the printed P_DL 0.9 and 0.999 (Sec. 2.7) and the finite Table 2.1 rows."""
    return [(1, float(IN_J.sec27_p_dl_low)), (1, float(IN_J.sec27_p_dl_high)), *table21_finite_designs()]


def _crossing_db(quantity: str, p_d: float, k: int, t: float, log_target: float) -> float:
    """Smallest x (dB, on a 0.01 dB grid) where the log bound reaches ``log_target``."""
    grid = np.arange(-40.0, 120.0, 0.01)
    vals = _log_bound(quantity, grid, p_d, k, t)
    idx = np.flatnonzero(vals >= log_target)
    return float(grid[idx[0]]) if idx.size else math.inf


@input_cache
def transition_widths_db() -> dict[tuple[str, int, float], float]:
    """dB between the bound at the convention's fraction of its ceiling and at 1e-6 of it (t = 0)."""
    out = {}
    g = geometry()
    upper = float(IN_COV.threshold_upper_fraction)
    for k, p_dl in _designs():
        p_d = design_p_d(p_dl, k)
        for quantity, ceil in (
            ("ambiguous", jm.log_ambiguous_detection_ceiling),
            ("false", jm.log_false_location_ceiling),
        ):
            c = float(ceil(p_d, k, 0.0, g))
            hi = _crossing_db(quantity, p_d, k, 0.0, c + math.log(upper))
            lo = _crossing_db(quantity, p_d, k, 0.0, c + math.log(1e-6))
            out[(quantity, k, p_dl)] = hi - lo
    return out


def _threshold_behaviour(k_one: bool) -> bool:
    width = float(IN_COV.threshold_width_db)
    return all(w < width for (_, k, _), w in transition_widths_db().items() if (k == 1) == k_one)


@input_cache
def near_threshold_gaps_db() -> list[float]:
    """K = 1: |x at the failure level - x at half the ceiling| for both bounds, P_DL 0.9 and 0.999."""
    g = geometry()
    gaps = []
    for p_dl in (IN_J.sec27_p_dl_low, IN_J.sec27_p_dl_high):
        p_d = design_p_d(p_dl, 1)
        for quantity, ceil in (
            ("ambiguous", jm.log_ambiguous_detection_ceiling),
            ("false", jm.log_false_location_ceiling),
        ):
            c = float(ceil(p_d, 1, 0.0, g))
            at_level = _crossing_db(quantity, p_d, 1, 0.0, math.log(level(quantity)))
            at_half = _crossing_db(quantity, p_d, 1, 0.0, c + math.log(0.5))
            gaps.append(abs(at_level - at_half))
    return gaps


CLAIMS += [
    Claim.statement(
        id="ATC10-sec2.1-threshold-behaviour",
        locator="Secs. 2.1, 2.7",
        quantity="the $K = 1$ bounds show a strong threshold behaviour: each falls very rapidly below a "
        "certain $J/(P_0 B \\tau)$",
        compute=lambda: _threshold_behaviour(True),
        note="Both bounds at $t = 0$, $P_{DL}$ 0.9 and 0.999: the fall from 90 % of the $J \\to \\infty$ "
        "ceiling down to $10^{-6}$ of it takes 1.1-1.3 dB, well within the 10 dB (or 5 dB) read as 'very "
        "rapidly'. The widths of every design are computed together, which is why the inputs list Table "
        "2.1's rows; only the $K = 1$ widths decide this claim.",
        discussed_in=PAGE_K1,
        table="threshold-sharpness",
    ),
    Claim.statement(
        id="ATC10-sec2.7-levels-near-threshold",
        locator="Sec. 2.7",
        quantity="the failure levels of the K = 1 curves are close to the threshold (each within the gap "
        "read as 'close' of the half-ceiling point)",
        kind="statement",
        compute=lambda: max(near_threshold_gaps_db()) < float(IN_COV.near_threshold_db),
        note="x where $N_{ADL} = 0.01 N_T$ and where $N_{FL} = 99$ % of 0.9 $N_T$, against x where each "
        "bound is half its ceiling, $P_{DL}$ 0.9 and 0.999, 0.01 dB grid: the largest gap is 0.37 dB.",
        discussed_in=PAGE_K1,
        table="threshold-sharpness",
    ),
]

#: Every claim quotes the paper (issue 27, item 5).
CLAIMS = with_quotes(CLAIMS, QUOTES)
