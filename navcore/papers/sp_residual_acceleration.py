"""SP Section 2.5 (second part): residual acceleration of an aided loop and Table 2.6.

Table 2.6 column 2 (the 90 % sphere radius of the post-calibration scale-factor and
misalignment error, ppm of a unit step) is typed here as input: it comes from a covariance
matrix the paper does not publish, and Table 2.5's a-priori errors do not produce it.
Columns 3 and 4 are computed from it as the paper describes: column 3 = column 2 x 6 g,
column 4 = Eq. (2.1) with 18 rad/s unaided, applied to column 3 as printed (two significant
figures), which is what the paper's worked example does.
"""

from __future__ import annotations

import numpy as np

from navcore.claims import EXACT, Claim, Erratum, InputSet, printed, with_quotes
from navcore.gnss.tracking import aided_natural_frequency, natural_frequency_for_peak_error
from navcore.inertial.residual_acceleration import scale_factor_misalignment_sensitivity
from navcore.papers import sp_tracking as spt
from navcore.papers.sp_quotes import QUOTES
from navcore.units import GPS_L1_WAVELENGTH_M, PPM

PAGE = "sp/03-residual-acceleration"

GRADES = ("10", "1", "0.5", "0.2")  # nmi/h labels of the Table 2.6 rows
#: Table 2.6 column 2 as printed, "Residual Error (90%) Due to Scale Factor and Misalignment (ppm)".
TAB26_COL2_PPM = {"10": "1880", "1": "431", "0.5": "311", "0.2": "225"}
#: Table 2.6 column 3 as printed, "Acceleration Seen by Tracking Loop Due to 6-g Acceleration Step" (g).
TAB26_COL3_G = {"10": "0.011", "1": "0.0026", "0.5": "0.0019", "0.2": "0.0014"}
#: Table 2.6 column 4 as printed, "Required Carrier Tracking Loop Bandwidth" (rad/s).
TAB26_COL4 = {"10": "0.77", "1": "0.37", "0.5": "0.32", "0.2": "0.27"}


def _key(grade: str) -> str:
    """Input-name suffix of a grade label ('0.5' -> '0p5')."""
    return grade.replace(".", "p")


IN = InputSet("SP", "residual")
for _g in GRADES:
    IN.published(
        f"col2_ppm_{_key(_g)}",
        float(TAB26_COL2_PPM[_g]),
        locator="Table 2.6, column 2",
        unit="ppm",
        quantity=f"90 % residual scale-factor/misalignment error, {_g} nmi/h IMU",
    )
    IN.published(
        f"col3_g_{_key(_g)}",
        float(TAB26_COL3_G[_g]),
        locator="Table 2.6, column 3",
        unit="g",
        quantity=f"acceleration seen by the {_g} nmi/h aided loop",
    )
    IN.published(
        f"col4_rad_s_{_key(_g)}",
        float(TAB26_COL4[_g]),
        locator="Table 2.6, column 4",
        unit="rad/s",
        quantity=f"required natural frequency of the {_g} nmi/h aided loop",
    )
IN.published(
    "unaided_omega0",
    18.0,
    locator="Table 2.6, row 'No inertial aiding'",
    unit="rad/s",
    quantity="unaided natural frequency",
)
#: The printed 3x6 matrix and the printed right factor of the covariance (Sec. 2.5), row by row.
IN.published(
    "printed_h",
    ((1, 0, 0, 0, -1, 1), (0, 1, 0, 1, 0, -1), (0, 0, 1, -1, 1, 0)),
    locator=r"Sec. 2.5, $3\times 6$ sensitivity matrix",
    quantity="printed sensitivity of the residual acceleration to scale factor and misalignment",
)
IN.published(
    "printed_right_factor",
    ((1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 1, -1), (-1, 0, 1), (1, -1, 0)),
    locator="Sec. 2.5, covariance of the residual acceleration",
    quantity="printed right factor of the covariance",
)


def col2_ppm(grade: str) -> float:
    """Table 2.6 column 2 (ppm of a unit step), the published input."""
    return getattr(IN, f"col2_ppm_{_key(grade)}")


def col3_printed_g(grade: str) -> float:
    """Table 2.6 column 3 as printed (g), the published input."""
    return getattr(IN, f"col3_g_{_key(grade)}")


def col4_printed_rad_s(grade: str) -> float:
    """Table 2.6 column 4 as printed (rad/s), the published input (read by the jammer-flyby model)."""
    return getattr(IN, f"col4_rad_s_{_key(grade)}")


def col3_g(grade: str) -> float:
    """Acceleration seen by the loop for the 6-g step (g): column 2 (ppm of a unit step) x 6 g."""
    return col2_ppm(grade) * PPM * spt.IN.step_g


def col4_rad_s(grade: str, unaided_omega0: float | None = None) -> float:
    """Eq. (2.1) applied to column 3 as printed (two significant figures), with the table's 18 rad/s."""
    w_u = IN.unaided_omega0 if unaided_omega0 is None else unaided_omega0
    return float(aided_natural_frequency(col3_printed_g(grade), spt.IN.step_g, w_u))


def unaided_omega0(wavelength_m: float | None = None) -> float:
    """Unaided natural frequency for 90 deg under 6 g with a conversion (Fig. 2.1's fitted one if None)."""
    lam = spt.IN.foot_per_cycle_m if wavelength_m is None else wavelength_m
    return natural_frequency_for_peak_error(spt.step_deg_s2(lam), spt.IN.peak_limit_deg)


def col4_l1_rad_s(grade: str) -> float:
    """Column 4 recomputed with the L1 carrier (unaided 22.37 rad/s, unrounded column 3)."""
    return float(aided_natural_frequency(col3_g(grade), spt.IN.step_g, unaided_omega0(GPS_L1_WAVELENGTH_M)))


def printed_h() -> np.ndarray:
    """The printed 3x6 sensitivity matrix (published input)."""
    return np.array(IN.printed_h, dtype=float)


def right_factor_is_transpose() -> bool:
    return bool(np.array_equal(np.array(IN.printed_right_factor, dtype=float), printed_h().T))


def printed_h_matches_skew_model() -> bool:
    """Is the printed 3x6 matrix the sensitivity of diag(sf) a + [dtheta x] a at a = (1, 1, 1)?"""
    return bool(
        np.allclose(scale_factor_misalignment_sensitivity((1, 1, 1), convention="cross"), printed_h())
    )


def printed_h_matches_cross_product_jacobian() -> bool:
    """Oracle: finite-difference Jacobian of diag(sf) a + cross(dtheta, a) with numpy's cross product."""
    a = np.ones(3)

    def da(x: np.ndarray) -> np.ndarray:
        return x[:3] * a + np.cross(x[3:], a)

    eps = 1e-6
    J = np.column_stack([(da(eps * e) - da(-eps * e)) / (2 * eps) for e in np.eye(6)])
    return bool(np.allclose(J, printed_h(), atol=1e-9))


ERRATA = [
    Erratum(
        id="SP-E-misalignment-sign",
        kind="convention",
        basis="text-only",
        locator=r"Sec. 2.5, $3\times 6$ sensitivity matrix",
        printed="misalignment block "
        "$\\begin{bmatrix}0&-1&1\\\\1&0&-1\\\\-1&1&0\\end{bmatrix}$ after the skew matrix "
        "$[\\delta\\theta \\times]\\, a$",
        finding="The printed skew matrix gives $\\delta\\theta \\times a$, whose Jacobian at $a = (1,1,1)$ "
        "is $\\begin{bmatrix}0&1&-1\\\\-1&0&1\\\\1&-1&0\\end{bmatrix}$: the printed block has the "
        "opposite sign (it is $a \\times "
        "\\delta\\theta$). "
        "The 'unit step' is also 1 g on every axis at once (magnitude $\\sqrt{3}$ g). The sign does not "
        "matter unless scale factor and misalignment are correlated ($c_{\\text{sf-mis}} \\neq 0$).",
        evidence="A finite-difference Jacobian of $\\operatorname{diag}(sf)\\, a + \\delta\\theta \\times a$ "
        "(cross product computed numerically) against the library's analytic $-[a\\times]$ block.",
        claims=("SP-sec2.5-H-sign",),
        discussed_in=PAGE,
    ),
    Erratum(
        id="SP-E-tab2.6-columns",
        kind="units",
        basis="text-only",
        locator="Table 2.6 and the text after it",
        printed="'the quantities in the third column are the required bandwidth'; column heading "
        "'Required Carrier Tracking Loop Bandwidth' with 18 rad/s unaided",
        finding="The required bandwidths are the fourth column (the text says 'third column' twice). "
        "They are natural frequencies $\\omega_0$ in rad/s, not bandwidths: the loop's noise bandwidth is "
        "$(5/6)\\, \\omega_0$ Hz. The unaided 18 rad/s is Fig. 2.1's 17.67 rad/s rounded; column 4 follows "
        "from "
        "18 rad/s and the rounded column 3 (17.67 would give 0.31 for the 0.5 nmi/h row).",
        evidence="Column 4 recomputed from column 3 with Eq. (2.1) both ways; noise bandwidth of "
        "the loop by quadrature of $|H(j\\omega)|^2$ against the closed form $(5/6)\\, \\omega_0$.",
        claims=tuple(f"SP-tab2.6-col4-{g}" for g in GRADES),
        discussed_in=PAGE,
    ),
]


def _col3_claim(g: str) -> Claim:
    value, tol = printed(
        TAB26_COL3_G[g],
        extra_abs=1e-12,
        why="floating-point slack: 225 ppm × 6 g = 0.00135 g is an exact tie that rounds half up to 0.0014",
    )
    return Claim(
        id=f"SP-tab2.6-col3-{g}",
        locator="Table 2.6, column 3",
        quantity=f"acceleration seen by the {g} nmi/h aided loop for a 6-g step",
        published=value,
        unit="g",
        kind="cross-check",
        compute=lambda g=g: col3_g(g),
        tolerance=tol,
        expected_status="consistent",
        note=f"Column 2 ({TAB26_COL2_PPM[g]} ppm of a unit step, printed) times the printed 6 g: arithmetic "
        "on printed numbers, a cross-check.",
        discussed_in=PAGE,
        table="residual-acceleration",
    )


def _col4_claim(g: str) -> Claim:
    value, tol = printed(TAB26_COL4[g])
    return Claim(
        id=f"SP-tab2.6-col4-{g}",
        locator="Table 2.6, column 4",
        quantity=f"required natural frequency of the {g} nmi/h aided carrier loop",
        published=value,
        unit="rad/s",
        compute=lambda g=g: col4_rad_s(g),
        tolerance=tol,
        expected_status="reproduced",
        note="Eq. (2.1) with 6 g and 18 rad/s unaided, applied to column 3 as printed (two significant "
        "figures; the paper's worked example uses 0.011 g). With column 2 $\\times$ 6 g unrounded the "
        "10 nmi/h row would be 0.78. With the L1 carrier all values are 1.243 times larger "
        "(erratum SP-E-phase-conversion).",
        discussed_in=PAGE,
        table="residual-acceleration",
    )


def _col2_claim(g: str) -> Claim:
    value, tol = printed(TAB26_COL2_PPM[g])
    return Claim(
        id=f"SP-tab2.6-col2-{g}",
        locator="Table 2.6, column 2",
        quantity=f"90 % residual scale-factor and misalignment error, {g} nmi/h IMU",
        published=value,
        unit="ppm",
        compute=None,
        tolerance=tol,
        expected_status="not-reproducible",
        note="Needs the post-calibration $6\\times 6$ scale-factor/misalignment covariance ('taken from a "
        "covariance analysis after ... calibration maneuvers'), which Sec. 2.5 / Table 2.6 should give "
        "and does not. Table 2.5 does not give it either: read as the accelerometers' a-priori scale "
        "factor and input-axis misalignment, its values give 676, 450, 226 and 53 ppm for a (1,1,1) "
        "step; read as the a-priori scale factor with the filter's attitude error after calibration "
        "(the text: 'IMU misalignment causes acceleration to be rotated incorrectly'), the printed "
        "radii need about 100, 12 and 12 arcsec of attitude error for the 10, 0.5 and 0.2 nmi/h IMUs, "
        "and a scale factor below the a-priori 179 ppm for the 1 nmi/h IMU, plausible after "
        "calibration. Used as input.",
        discussed_in=PAGE,
        table="residual-acceleration",
    )


_w18 = printed("18", why="the table prints the unaided frequency to two figures")
_w077 = printed("0.77")

CLAIMS = [
    *(_col2_claim(g) for g in GRADES),
    *(_col3_claim(g) for g in GRADES),
    *(_col4_claim(g) for g in GRADES),
    Claim(
        id="SP-tab2.6-unaided",
        locator="Table 2.6, row 'No inertial aiding'",
        quantity="natural frequency of the unaided carrier loop (6-g step, 90 deg)",
        published=_w18[0],
        unit="rad/s",
        compute=unaided_omega0,
        tolerance=_w18[1],
        expected_status="consistent",
        note="Fig. 2.1's 17.67 rad/s with the fitted conversion (one cycle per foot), printed as 18; the "
        "table's other rows use 18. It reads the fitted conversion.",
        discussed_in=PAGE,
        table="residual-acceleration",
    ),
    Claim(
        id="SP-eq2.u7-worked-example",
        locator="Sec. 2.5, worked example after Table 2.6",
        quantity="aided natural frequency of the 10 nmi/h system, $\\sqrt{0.011\\,\\mathrm{g} / "
        "6\\,\\mathrm{g}} \\times 18$ rad/s",
        published=_w077[0],
        unit="rad/s",
        kind="cross-check",
        compute=lambda: col4_rad_s("10"),
        tolerance=_w077[1],
        expected_status="consistent",
        note="0.7707 rad/s: the worked example's own arithmetic on printed numbers (0.011 g, 6 g, 18 rad/s), "
        "a cross-check.",
        discussed_in=PAGE,
        table="residual-acceleration",
    ),
    Claim.statement(
        id="SP-sec2.5-right-factor",
        locator="Sec. 2.5, covariance of the residual acceleration",
        quantity="the printed right factor of the covariance is the transpose of the printed "
        "$3\\times 6$ matrix",
        kind="cross-check",
        compute=right_factor_is_transpose,
        expected_status="consistent",
        note="$\\langle \\delta a\\, \\delta a^T \\rangle = H P H^T$ with the middle factor a "
        "$6\\times 6$ block "
        "matrix written in $2\\times 2$ shorthand; a "
        "check of the two printed matrices against each other, a cross-check.",
        discussed_in=PAGE,
        table="residual-acceleration",
    ),
    Claim.statement(
        id="SP-sec2.5-H-sign",
        locator=r"Sec. 2.5, $3\times 6$ sensitivity matrix",
        quantity="the printed $3\\times 6$ matrix is the sensitivity of "
        "$\\operatorname{diag}(sf)\\, a + [\\delta\\theta \\times]\\, a$ for $a = (1,1,1)$",
        compute=printed_h_matches_skew_model,
        expected_status="discrepant",
        erratum="SP-E-misalignment-sign",
        oracle=printed_h_matches_cross_product_jacobian,
        oracle_tolerance=EXACT,
        note="The misalignment block has the opposite sign ($a \\times \\delta\\theta$); immaterial for "
        "uncorrelated "
        "errors, as in the radii computed here.",
        discussed_in=PAGE,
        table="residual-acceleration",
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
