"""ATC-10 Sec. 4.6, Tables 4.1-4.2: the two examples' constellations.

The claims on Table 4.2 (beta, the trace and the clock-direction term of the seven- and
eight-satellite constellations of Table 4.1, and of satellites 1, 2, 3), the cone and the widest
triplet of Sec. 4.6, and the statements Sec. 4.6 makes about the printed table; the errata on
them. Inputs and the examples' geometry are read from
:mod:`navcore.papers.atc10_tracking_geometry`.
"""

from __future__ import annotations

import numpy as np

from navcore.claims import EXACT, Claim, Erratum, Tolerance, printed, with_quotes
from navcore.location.multilateration import (
    beta_parameter,
    clock_direction_term,
    position_dilution_covariance,
    position_trace,
)
from navcore.papers.atc10_quotes import QUOTES
from navcore.papers.atc10_tracking_geometry import (
    COLUMN_NAMES,
    COLUMNS,
    EXAMPLES,
    IN,
    PAGE_GEOMETRY,
    TABLE_4_2,
    TRIPLET_123,
    _example_row,
    _physical_geometry,
    _physical_oracle_invariants,
    _printed_table_4_2_as_computed,
    best_triplet,
    fitted_radius_ratio,
    physical_aircraft_ratio,
    physical_radius_ratio,
    physical_table_4_2,
    table_4_1,
    within_cone,
)

CLAIMS: list[Claim] = []
ERRATA: list[Erratum] = []


_GEOM_ORACLE_TOL = Tolerance(
    rel=1e-9, reason="two exact constructions of the same geometry; floating point", policy="exact"
)


_E1 = "ATC10-E4.1-three-satellite-clock-term"


_E2 = "ATC10-E4.2-effective-orbit-radius"


_E3 = "ATC10-E4.3-beta-definition"


_E6 = "ATC10-E4.6-widest-triplet"


_e1_claims: list[str] = []


_e2_claims: list[str] = []


#: The paper's own rounding of Table 4.1 (coordinates printed to 0.1 deg): Table 4.2 was computed
#: from the coordinates before rounding, so each Table 4.2 claim adds the largest change of its
#: quantity when every coordinate moves within +-0.05 deg (the linearised worst case, rounded up
#: to two figures; tests/test_atc10_tracking.py recomputes it from the printed coordinates and
#: checks these values). Keyed (geometry, example, column): "physical" at the synchronous orbit
#: (invariant S3), "fitted" at the fitted ratio (col. 5 with the printed formula).
_TAB41_ALLOWANCE: dict[tuple[str, str, str], float] = {
    ("physical", "I", "beta"): 6.2e-4,
    ("physical", "I", "trace_all"): 0.064,
    ("physical", "I", "trace_123"): 0.059,
    ("physical", "I", "s_all"): 2.0e-3,
    ("physical", "I", "s_123"): 2.1e-3,
    ("physical", "II", "beta"): 1.4e-4,
    ("physical", "II", "trace_all"): 0.019,
    ("physical", "II", "trace_123"): 0.11,
    ("physical", "II", "s_all"): 1.2e-3,
    ("physical", "II", "s_123"): 1.2e-3,
    ("fitted", "I", "beta"): 5.2e-4,
    ("fitted", "I", "trace_all"): 0.071,
    ("fitted", "I", "trace_123"): 0.065,
    ("fitted", "I", "s_all"): 1.8e-3,
    ("fitted", "I", "s_123"): 0.032,
    ("fitted", "II", "beta"): 1.2e-4,
    ("fitted", "II", "trace_all"): 0.020,
    ("fitted", "II", "trace_123"): 0.13,
    ("fitted", "II", "s_all"): 1.1e-3,
    ("fitted", "II", "s_123"): 0.14,
}


_TAB41_WHY = (
    "Table 4.1's coordinates are printed to 0.1 deg; moving each within its rounding moves this "
    "value by up to"
)


def _tab42_tolerance(geometry: str, example: str, column: str) -> Tolerance:
    allowance = _TAB41_ALLOWANCE[(geometry, example, column)]
    return printed(TABLE_4_2[example][column], extra_abs=allowance, why=f"{_TAB41_WHY} {allowance:g}")[1]


for _ex in EXAMPLES:
    for _col in COLUMNS:
        _pub = printed(TABLE_4_2[_ex][_col])[0]
        _cid = f"ATC10-tab4.2-ex{_ex}-{_col}"
        _is_s3 = _col == "s_123"
        CLAIMS.append(
            Claim(
                id=_cid + "-physical",
                locator="Table 4.2",
                quantity=f"Example {_ex}: {COLUMN_NAMES[_col]}, physical geometry",
                published=_pub,
                unit="",
                kind="reproduction",
                compute=lambda ex=_ex, col=_col: physical_table_4_2(ex)[col],
                tolerance=_tab42_tolerance("physical", _ex, _col),
                expected_status="discrepant",
                note=(
                    "The stated system: satellites in synchronous orbits (Sec. 4.1; 42 164 km, 6.6 Earth "
                    "radii) above the Table 4.1 points, a spherical Earth, $F$ = unit vectors; every "
                    "reading of the Earth radius, GM, the period and the aircraft height is weighed. "
                    + (
                        "Correct rotation-invariant three-satellite term $1'(F_3F_3')^{-1} 1$: it stays "
                        "between 1.33 and 1.45 (Example I) and 1.16 and 1.22 (Example II) for every orbit "
                        "radius from 5 to 14 Earth radii, so no orbit gives the printed value."
                        if _is_s3
                        else "$\\beta = K - 1'F(F'F)^{-1}F'1$ (the 'K minus' reading). The radius that "
                        "reproduces Table 4.2, about 9.2 Earth radii, is a fit (the claims marked fitted), "
                        "not a reading of 'synchronous'."
                    )
                ),
                erratum=_E1 if _is_s3 else _E2,
                oracle=lambda ex=_ex, col=_col: _physical_oracle_invariants(ex)[col],
                oracle_tolerance=_GEOM_ORACLE_TOL,
                discussed_in=PAGE_GEOMETRY,
            )
        )
        (_e1_claims if _is_s3 else _e2_claims).append(_cid + "-physical")
        CLAIMS.append(
            Claim(
                id=_cid + "-fitted",
                locator="Table 4.2",
                quantity=f"Example {_ex}: {COLUMN_NAMES[_col]}, fitted radius ratio",
                published=_pub,
                unit="",
                kind="fit",
                compute=lambda ex=_ex, col=_col: _printed_table_4_2_as_computed(ex, fitted_radius_ratio())[
                    col
                ],
                tolerance=_tab42_tolerance("fitted", _ex, _col),
                expected_status="consistent",
                note="Same geometry with $r_{\\mathrm{orbit}}/R_E$ fitted to the ten Table 4.2 numbers "
                "(9.235, about 59 000 km: a 39-hour orbit, not a synchronous one); a fit claim, not "
                "evidence"
                + (
                    "; col. 5 with the printed, frame-dependent $1'(F_3'F_3)^{-1} 1$ in east-positive ECEF."
                    if _is_s3
                    else "."
                )
                + " The tolerance adds the paper's own rounding of Table 4.1 (coordinates to 0.1 deg): with "
                "it one radius reproduces all ten printed numbers.",
                discussed_in=PAGE_GEOMETRY,
            )
        )


CLAIMS += [
    Claim.statement(
        id="ATC10-sec4.6-cone-exI",
        locator="Sec. 4.6, Example I",
        quantity="Example I: all satellites within a 45 deg half-angle cone about the local vertical",
        compute=lambda: within_cone("I", physical_radius_ratio(), physical_aircraft_ratio()),
        expected_status="discrepant",
        note="The stated system (synchronous orbits): satellite 1 is at zenith angle 47.2 deg. Even at the "
        "fitted radius ratio, which is not a reading of the text, it is 45.2 deg, just outside.",
        erratum=_E2,
        oracle=lambda: _physical_oracle_invariants("I")["max_zenith_deg"] <= IN.cone_half_angle_deg,
        oracle_tolerance=EXACT,
        discussed_in=PAGE_GEOMETRY,
    ),
    Claim.statement(
        id="ATC10-sec4.6-cone-exII",
        locator="Sec. 4.6, Example II",
        quantity="Example II: all satellites within a 45 deg half-angle cone about the local vertical",
        compute=lambda: within_cone("II", physical_radius_ratio(), physical_aircraft_ratio()),
        note="The stated system (synchronous orbits): largest zenith angle 44.0 deg.",
        discussed_in=PAGE_GEOMETRY,
    ),
    Claim.statement(
        id="ATC10-sec4.6-triplet-exI",
        locator="Sec. 4.6, Example I",
        quantity="Example I: satellites 1, 2, 3 are the most widely spaced triplet",
        compute=lambda: (
            best_triplet("I", physical_radius_ratio(), IN.spacing_criterion, physical_aircraft_ratio())
            == TRIPLET_123
        ),
        note="Among all 35 triplets, satellites 1, 2, 3 have the smallest "
        "$\\operatorname{tr}\\{(F_3'F_3)^{-1}\\}$, the largest $|\\det F_3|$ and the largest smallest "
        "pairwise angle.",
        discussed_in=PAGE_GEOMETRY,
    ),
    Claim.statement(
        id="ATC10-sec4.6-triplet-exII",
        locator="Sec. 4.6, Example II",
        quantity="Example II: satellites 1, 2, 3 are the most widely spaced triplet",
        compute=lambda: (
            best_triplet("II", physical_radius_ratio(), IN.spacing_criterion, physical_aircraft_ratio())
            == TRIPLET_123
        ),
        expected_status="discrepant",
        note="Satellites 2, 3, 6 have $\\operatorname{tr}\\{(F_3'F_3)^{-1}\\} = 8.5$ against 13.6 for 1, 2, "
        "3; every measure of spacing prefers another triplet, and so does the fitted radius ratio.",
        erratum=_E6,
        oracle=lambda: _physical_oracle_invariants("II")["triplet_angle"] == TRIPLET_123,
        oracle_tolerance=EXACT,
        discussed_in=PAGE_GEOMETRY,
    ),
]


ERRATA += [
    Erratum(
        id=_E2,
        kind="inconsistent-numbers",
        basis="computed",
        locator="Table 4.2 (from Table 4.1)",
        printed="$\\beta$ = .0543/.00355, $\\operatorname{tr}$ = 7.84/3.99 (all), 9.39/14.9 (1,2,3), "
        "$S$ = 1.30/1.16",
        finding="The finding rests on reading Sec. 4.1's statement that the system's satellites are in "
        "synchronous orbits as applying to the constellations of Sec. 4.6, which are taken for that system. "
        "Synchronous orbits (42 164 km, 6.6 Earth radii) give $\\beta$ = .0658/.00425, "
        "$\\operatorname{tr}$ = 7.19/3.68 and 8.64/13.6, $S$ = 1.33/1.18, 2-21 % from the printed values "
        "under every admissible Earth radius, GM, period and aircraft height, and beyond the rounding of "
        "Table 4.1; Example I's satellite 1 is then outside the 45 deg cone (47.2 deg). The printed values "
        "fit an orbit of about 9.2 Earth radii (59 000 km, a 39-hour orbit): the paper's geometry is "
        "self-consistent but is not the stated one. That radius is a fit, shown for illustration, not "
        "evidence for the finding.",
        evidence="Geometry built twice (the book's library on a sphere; an independent geodesy library's "
        "azimuth/elevation with QR/SVD invariants); the WGS-84 ellipsoid with geodetic latitudes moves "
        "the invariants by less than 0.1 %, the 0.05 deg rounding of Table 4.1 by less than 1 % (3 % for "
        "Example II's $\\beta$); a one-parameter fit of $r/R_E$ reproduces all ten numbers within their "
        "digits and Table 4.1's rounding.",
        claims=(*_e2_claims, "ATC10-sec4.6-cone-exI"),
        discussed_in=PAGE_GEOMETRY,
    ),
    Erratum(
        id=_E3,
        kind="typography",
        basis="text-only",
        locator="Eqs. (4.5.11), (4.5.20), Sec. 4.5.4 ($\\beta$)",
        printed="$\\beta = K^{-1} 1'F(F'F)^{-1}F'1$",
        finding="$\\beta = K - 1'F(F'F)^{-1}F'1 = 1'(I - P)1$ (the minus sign read as an inverse).",
        evidence="$\\gamma_0 = 1/\\beta$ (Eq. 4.5.2); the text's '$\\beta_0 = 0$ for K = 3' holds only for K "
        "minus; "
        "Table 4.2 is reproduced with K minus, while $(1/K)1'(I-P)1$ gives .0094/.00053.",
        claims=("ATC10-sec4.5.4-beta-three-satellites",),
        discussed_in=PAGE_GEOMETRY,
    ),
    Erratum(
        id=_E6,
        kind="overstatement",
        basis="computed",
        locator="Sec. 4.6 (choice of satellites 1, 2, 3)",
        printed="satellites 1, 2 and 3 are the most widely spaced triplet",
        finding="For Example II, satellites 2, 3, 6 (and 1, 4, 7) are better by trace, determinant and "
        "smallest pairwise angle, for the synchronous orbits and for the fitted radius alike; the table's "
        "tr = 14.9 does belong to satellites 1, 2, 3, itself a sign of a poorly spaced triplet (3.99 with "
        "all "
        "eight).",
        evidence="Exhaustive search over the 56 triplets with each measure of spacing, in two independent "
        "constructions of the geometry.",
        claims=("ATC10-sec4.6-triplet-exII",),
        discussed_in=PAGE_GEOMETRY,
    ),
]


def tr_increases() -> bool:
    return all(
        position_trace(_physical_geometry(ex)[:3]) > position_trace(_physical_geometry(ex))
        for ex in ("I", "II")
    )


def s_increases_printed() -> bool:
    return all(
        _example_row(ex)["s_123"] > _example_row(ex)["s_all"]
        and _example_row(ex)["trace_123"] > _example_row(ex)["trace_all"]
        for ex in ("I", "II")
    )


def s_increases_invariant() -> bool:
    return all(
        clock_direction_term(_physical_geometry(ex)[:3]) > clock_direction_term(_physical_geometry(ex))
        for ex in ("I", "II")
    )


def second_term_share(example: str) -> float:
    t = _example_row(example)
    return (t["s_all"] / t["beta"]) / (t["trace_all"] + t["s_all"] / t["beta"])


def second_term_dominates_p0() -> bool:
    return all(second_term_share(ex) > 0.5 for ex in ("I", "II"))


def dominance_stronger_exII() -> bool:
    return second_term_share("II") > second_term_share("I")


def k_identity() -> bool:
    """k = sqrt(tr + S/beta) equals sqrt(tr P)/sigma of (4.5.6) (geometric dilution, Sec. 4.6)."""
    for ex in ("I", "II"):
        F = _physical_geometry(ex)
        k2 = position_trace(F) + clock_direction_term(F) / beta_parameter(F)
        if abs(np.trace(position_dilution_covariance(F)) - k2) > 1e-9 * k2:
            return False
    return True


def satellite_counts_seven_or_eight() -> bool:
    """Sec. 4.6: the examples start with 'seven or eight satellites' (the rows of Table 4.1)."""
    return all(len(table_4_1(ex)) in (7, 8) for ex in ("I", "II"))


CLAIMS += [
    Claim.statement(
        id="ATC10-sec4.6-tr-increases",
        locator="Sec. 4.5.4, Sec. 4.6",
        quantity="$\\operatorname{tr}\\{(F'F)^{-1}\\}$ increases with three satellites",
        compute=tr_increases,
        note="Physical geometry: 8.64 > 7.19 (I), 13.6 > 3.68 (II).",
        discussed_in=PAGE_GEOMETRY,
        table="geometry-checks",
    ),
    Claim.statement(
        id="ATC10-sec4.6-s-increases-printed",
        locator="Sec. 4.6, Table 4.2",
        quantity="printed tr and S both larger for satellites 1, 2, 3",
        compute=s_increases_printed,
        expected_status="consistent",
        kind="cross-check",
        note="9.39 > 7.84, 5.76 > 1.30 (I); 14.9 > 3.99, 14.3 > 1.16 (II).",
        discussed_in=PAGE_GEOMETRY,
    ),
    Claim.statement(
        id="ATC10-sec4.6-s-increases-invariant",
        locator="Sec. 4.5.4, Sec. 4.6",
        quantity="the invariant $1'(F_3 F_3')^{-1} 1$ exceeds $1'F(F'F)^{-2}F'1$ (all satellites)",
        compute=s_increases_invariant,
        note="Physical geometry: 1.40 > 1.33 (I), 1.19 > 1.18 (II): an increase, though slight (erratum "
        "ATC10-E4.1-three-satellite-clock-term).",
        discussed_in=PAGE_GEOMETRY,
        table="geometry-checks",
    ),
    Claim.statement(
        id="ATC10-sec4.6-second-term-dominates-p0",
        locator="Sec. 4.6",
        quantity="$\\beta$ small: $S/\\beta$ dominates $\\mathrm{Var}[\\|\\xi_{p0}\\|]$",
        compute=second_term_dominates_p0,
        note="Share of $S/\\beta$ in $k^2$: 0.75 (I), 0.988 (II), printed Table 4.2.",
        discussed_in=PAGE_GEOMETRY,
        table="geometry-checks",
    ),
    Claim.statement(
        id="ATC10-sec4.6-dominance-stronger-exII",
        locator="Sec. 4.6",
        quantity="the dominance is particularly true in Example II",
        compute=dominance_stronger_exII,
        note="0.988 (II) > 0.75 (I).",
        discussed_in=PAGE_GEOMETRY,
        table="geometry-checks",
    ),
    Claim.statement(
        id="ATC10-sec4.6-k-identity",
        locator="Sec. 4.6, geometric dilution k",
        quantity="$k^2 = \\operatorname{tr} + S/\\beta = \\operatorname{tr} P / \\sigma^2$",
        compute=k_identity,
        note="Both examples, physical geometry.",
        discussed_in=PAGE_GEOMETRY,
        table="geometry-checks",
    ),
    Claim.statement(
        id="ATC10-sec4.6-satellite-count",
        locator="Sec. 4.6, Table 4.1",
        quantity="the two examples start with seven or eight satellites",
        compute=satellite_counts_seven_or_eight,
        expected_status="consistent",
        kind="cross-check",
        note="Table 4.1 lists 7 (I) and 8 (II) sub-satellite points.",
        discussed_in=PAGE_GEOMETRY,
    ),
]


_e1_claims.append("ATC10-sec4.6-rule3-jump-from-clock-term")


_e1_claims.append("ATC10-sec4.6-rule4-common-threshold")


#: Every claim quotes the paper (issue 27, item 5).
CLAIMS = with_quotes(CLAIMS, QUOTES)
