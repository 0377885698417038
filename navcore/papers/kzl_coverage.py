"""KZL items the first sweep left without a claim (issue 17): Sec. 1 requirements, the rates of
Sec. 2, Eqs. (6), (9), (10)-(11), (15), (17), the loosely coupled half of Sec. 3.6, the baseline
trade-off of Sec. 3.7, and claims for errata KZL-E3 and KZL-E5.
"""

from __future__ import annotations

import itertools

import numpy as np
import scipy.linalg
from scipy.spatial.transform import Rotation

from navcore.claims import EXACT, PROSE_WORDS, Claim, InputSet, printed
from navcore.frames import skew
from navcore.inertial.error_model17 import ERROR_LAYOUT_17, error_dynamics_17
from navcore.papers.kzl_models import IN as MODELS
from navcore.papers.kzl_models import (
    PAGE0,
    PAGE1,
    PAGE2,
    discretisation_comparison,
    satellite_to_aircraft_speed,
    table1_attitude,
    table1_los,
)
from navcore.papers.kzl_quotes import quoted
from navcore.papers.kzl_scenario import IN as SCEN
from navcore.papers.kzl_simulation import PAGE3
from navcore.units import ARCSEC, DEG, G0, GPS_L1_WAVELENGTH_M

IN = InputSet("KZL", "coverage")
IN.assumed(
    "receiver_footprint_km",
    15.0,
    low=5.0,
    high=30.0,
    reason="Sec. 1 gives no antenna footprint; the wide receive beam of an airborne SAR receiver at "
    "a few km altitude covers 5-30 km along track",
    unit="km",
    quantity="along-track footprint of the airborne receiver",
)
IN.assumed(
    "look_angle_deg",
    30.0,
    low=20.0,
    high=45.0,
    reason="Sec. 1 names no InSAR geometry; 20-45 deg is the incidence range of TerraSAR-X",
    unit="deg",
    quantity="InSAR look angle",
)
IN.assumed(
    "perp_baseline_m",
    200.0,
    low=100.0,
    high=300.0,
    reason="Sec. 1 gives no baseline; 100-300 m is the usual spaceborne across-track InSAR baseline",
    unit="m",
    quantity="InSAR perpendicular baseline",
)
IN.assumed(
    "gps_position_sigma_m",
    10.0,
    low=5.0,
    high=15.0,
    reason="Sec. 1 gives no positioning accuracy; 5-15 m is single-frequency L1 code positioning",
    unit="m",
    quantity="stand-alone GPS position accuracy",
)
IN.assumed(
    "receiver_filter_tau_s",
    2.0,
    low=1.0,
    high=5.0,
    reason="Sec. 2.2 gives no receiver filter; receiver navigation filters have 1-5 s time constants",
    unit="s",
    quantity="time constant of the receiver's navigation filter",
)
IN.convention(
    "uncorrelated_below",
    float(np.exp(-1.0)),
    quantity="correlation below which outputs count as uncorrelated",
    readings={"below 1/e, a time constant apart": float(np.exp(-1.0)), "below 0.1": 0.1},
    reason="Sec. 2.2 accounts for the correlation of cascaded filters 'by considering this information "
    "only every >10 s' and gives no correlation; the book reads it as making the outputs nearly "
    "uncorrelated",
)
IN.convention(
    "unit_level_decades",
    0.5,
    unit="decades",
    quantity="distance from the named unit that 'mm/cm' and 'arcsec' accuracy allow",
    readings={"within half a decade of the unit": 0.5, "within a decade of it": 1.0},
    reason="Sec. 1 names units, 'mm/cm (length) and arcsec (angle) accuracy', not values; an accuracy "
    "'of the unit' lies within some decades of it",
)
IN.convention(
    "approx_rel",
    0.10,
    quantity="closeness that '≈' in $A(k) \\approx I + F T$ allows",
    readings={
        "within 10 %, the reading of 'approximately' in the ledger's table of prose words": 0.10,
        "within 1 %": 0.01,
    },
    reason="Eq. (6) writes '≈' in a formula and prints no number",
)


# --- Sec. 1 ----------------------------------------------------------------------------------
def footprint_overlap_s() -> float:
    """Receiver footprint over the satellite's ground speed (circular orbit), s."""
    v_air = MODELS.aircraft_speed_mps
    v_sat = satellite_to_aircraft_speed() * v_air
    r = MODELS.earth_radius_m / (MODELS.earth_radius_m + 1000.0 * MODELS.terrasar_altitude_km)
    return float(1000.0 * IN.receiver_footprint_km / (v_sat * r - v_air))


def _footprint_overlap_a_few() -> bool:
    """'A few seconds in maximum': the longest overlap in the prose table's 'a few' (2 to 5 s)."""
    word = PROSE_WORDS["a few"]
    return bool(word["centre"] - word["abs"] <= footprint_overlap_s() <= word["centre"] + word["abs"])


def pointing_shift_m() -> float:
    """Footprint shift of the acceptable pointing error (Sec. 1, 0.5 deg) at the slant range of the
    Table 1 height, m."""
    slant = SCEN.height_m / np.cos(IN.look_angle_deg * DEG)
    return float(slant * np.tan(MODELS.pointing_error_deg * DEG))


def _positioning_less_strict() -> bool:
    return pointing_shift_m() > IN.gps_position_sigma_m


def _insar_slant_sin() -> float:
    """R sin(theta) of the TerraSAR-X geometry (flat earth), m."""
    th = IN.look_angle_deg * DEG
    return float(1000.0 * MODELS.terrasar_altitude_km * np.tan(th))


def baseline_angle_arcsec() -> float:
    """Baseline tilt error giving a 1 m height error: 1 m / (R sin theta), arcsec."""
    return float(1.0 / _insar_slant_sin() / ARCSEC)


def baseline_length_mm() -> float:
    """Baseline length error giving a 1 m height error: B / (R sin theta tan theta), mm."""
    th = IN.look_angle_deg * DEG
    return float(1000.0 * IN.perp_baseline_m / (_insar_slant_sin() * np.tan(th)))


def _within_decades(value: float, low: float, high: float) -> bool:
    """Whether ``value`` lies within the declared number of decades of the span ``[low, high]``."""
    d = IN.unit_level_decades
    return bool(low * 10.0**-d <= value <= high * 10.0**d)


def _tilt_arcsec_level() -> bool:
    """'arcsec (angle) accuracy': the tilt accuracy for 1 m of height at the level of an arcsec."""
    return _within_decades(baseline_angle_arcsec(), 1.0, 1.0)


def _length_mm_cm_level() -> bool:
    """'mm/cm (length) accuracy': the length accuracy for 1 m of height between a mm and a cm."""
    return _within_decades(baseline_length_mm(), 1.0, 10.0)


# --- Sec. 2 ----------------------------------------------------------------------------------
def correlation_after_10s() -> float:
    """Correlation of a first-order receiver filter's output 10 s apart: exp(-10 / tau)."""
    return float(np.exp(-10.0 / IN.receiver_filter_tau_s))


def _uncorrelated_after_10s() -> bool:
    return correlation_after_10s() < IN.uncorrelated_below


# --- equations -------------------------------------------------------------------------------
def eq6_position_ratio() -> float:
    """180 s stand-alone north-position sigma with A = I + FT (Eq. 6) over that with e^{FT}."""
    d = discretisation_comparison(1.0 / SCEN.gps_rate_hz)
    return d["pos_first_order_m"] / d["pos_exact_m"]


def _eq6_approximates() -> bool:
    return abs(eq6_position_ratio() - 1.0) <= IN.approx_rel


def _qmul(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    w1, v1, w2, v2 = p[0], p[1:], q[0], q[1:]
    return np.concatenate([[w1 * w2 - v1 @ v2], w1 * v2 + w2 * v1 + np.cross(v1, v2)])


def eq9_quaternion_error_deg() -> float:
    """Integrate q' = q (x) [0, w]/2 (Eq. 9, omega_in neglected) over 1 s at a constant body rate
    with RK4 (1000 steps) from the Table 1 attitude; angle to scipy's closed form, deg."""
    w = np.array([0.1, -0.2, 0.3])
    R0 = Rotation.from_matrix(table1_attitude())
    x, y, z, s = R0.as_quat()
    q = np.array([s, x, y, z])
    f = lambda q: 0.5 * _qmul(q, np.concatenate([[0.0], w]))
    # RK4 over T = 1 s in 1000 steps (a resolution: the claim asks whether Eq. (9) holds)
    T, steps = 1.0, 1000
    h = T / steps
    for _ in range(steps):
        k1 = f(q)
        k2 = f(q + h / 2 * k1)
        k3 = f(q + h / 2 * k2)
        k4 = f(q + h * k3)
        q = q + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    num = Rotation.from_quat([q[1], q[2], q[3], q[0]])
    ref = R0 * Rotation.from_rotvec(w * T)
    return float(np.degrees((num * ref.inv()).magnitude()))


def _eq9_holds() -> bool:
    # RK4 at 1 ms steps integrates the rotation to far below 1e-6 deg
    return eq9_quaternion_error_deg() < 1e-6


def eq10_11_fd_error() -> float:
    """Largest difference, relative to g, between the velocity-attitude block of Eq. (10)-(11)
    and central finite differences of (R_hat - R) f^b with R_hat = e^{[d x]} R (error = computed
    - true), at the Table 1 attitude and a tilted specific force."""
    C = table1_attitude()
    f_n = np.array([0.5, -0.3, -G0])
    f_b = C.T @ f_n
    F = error_dynamics_17(C, f_n)
    v, a = ERROR_LAYOUT_17.slice("velocity"), ERROR_LAYOUT_17.slice("misalignment")
    eps = 1e-6
    J = np.column_stack(
        [
            ((scipy.linalg.expm(skew(eps * e)) - scipy.linalg.expm(skew(-eps * e))) @ C @ f_b) / (2 * eps)
            for e in np.eye(3)
        ]
    )
    return float(np.max(np.abs(F[v, a] - J)) / G0)


def _eq10_11_holds() -> bool:
    # central differences at a 1e-6 rad step agree to 1e-6 relative to g
    return eq10_11_fd_error() < 1e-6


def eq11_printed_vs_cross() -> float:
    """Eq. (11)'s explicit matrix (typed as printed) against the cross-product matrix its bracket
    names (navcore.frames.skew), largest entry difference relative to |a|, Table 1 specific force."""
    an, ae, ad = 0.0, 0.0, -G0
    printed_m = np.array([[0.0, ad, -ae], [-ad, 0.0, an], [ae, -an, 0.0]])
    a = np.array([an, ae, ad])
    return float(np.max(np.abs(printed_m - skew(a))) / np.linalg.norm(a))


def _eq11_is_bracket() -> bool:
    return eq11_printed_vs_cross() < 1e-12


def _eq11_oracle() -> bool:
    """Independent: printed matrix times unit vectors against numpy's cross product a x e."""
    a = np.array([0.0, 0.0, -G0])
    printed_m = np.array([[0.0, a[2], -a[1]], [-a[2], 0.0, a[0]], [a[1], -a[0], 0.0]])
    worst = max(np.max(np.abs(printed_m @ e - np.cross(a, e))) for e in np.eye(3)) / np.linalg.norm(a)
    return bool(worst < 1e-12)


def eq15_orderings() -> float:
    """Largest difference (rad) of the two groupings of Eq. (15) over random ranges."""
    rng = np.random.default_rng(15)
    rho = rng.uniform(2.0e7, 2.6e7, size=(1000, 2, 2))  # [antenna A0/A1, satellite m/n]
    k = 2 * np.pi / GPS_L1_WAVELENGTH_M
    first = k * ((rho[:, 1, 1] - rho[:, 1, 0]) - (rho[:, 0, 1] - rho[:, 0, 0]))
    second = k * ((rho[:, 1, 1] - rho[:, 0, 1]) - (rho[:, 1, 0] - rho[:, 0, 0]))
    return float(np.max(np.abs(first - second)) / np.max(np.abs(first)))


def _eq15_holds() -> bool:
    # floating point on 2e7 m ranges: 1e-6 relative
    return eq15_orderings() < 1e-6


def _dd_rows(b_first: np.ndarray, b_second: np.ndarray) -> np.ndarray:
    C = table1_attitude()
    los = table1_los(2)
    d = 2 * np.pi / GPS_L1_WAVELENGTH_M * (los[0] - los[1])
    return np.vstack([d @ skew(C @ b_first), d @ skew(C @ b_second)])


def eq17_printed_rank() -> int:
    """Rank of the two DD attitude rows of Eq. (17) as printed (both with l_02), Table 1 sky."""
    b = SCEN.baseline_m
    return int(np.linalg.matrix_rank(_dd_rows(np.array([0.0, b, 0.0]), np.array([0.0, b, 0.0]))))


def _eq17_printed_two_rows() -> bool:
    return eq17_printed_rank() == 2


def _eq17_oracle() -> bool:
    """Independent: count singular values above 1e-9 of the cross products d x (R l_02), twice."""
    C, los, b = table1_attitude(), table1_los(2), SCEN.baseline_m
    r = np.cross(C @ np.array([0.0, b, 0.0]), los[0] - los[1])
    s = np.linalg.svd(np.vstack([r, r]), compute_uv=False)
    return int(np.sum(s > 1e-9 * s[0])) == 2


def eq17_corrected_rank() -> int:
    """Rank of the DD attitude rows with l_01 and l_02 (the reading of erratum KZL-E5)."""
    b = SCEN.baseline_m
    return int(np.linalg.matrix_rank(_dd_rows(np.array([b, 0.0, 0.0]), np.array([0.0, b, 0.0]))))


def _eq17_corrected_two_rows() -> bool:
    return eq17_corrected_rank() == 2


# --- Sec. 3.6-3.7 ----------------------------------------------------------------------------
def _loose_three_no_fix() -> bool:
    """Three satellites: the code geometry [-l^T 1] has rank 3 < 4 unknowns, so a receiver alone
    gives no position fix and a loosely coupled filter gets no GNSS update."""
    G = np.hstack([-table1_los(3), np.ones((3, 1))])
    return int(np.linalg.matrix_rank(G)) == 3


def baseline_tradeoff(lengths=(0.5, 1.0, 2.0, 4.0)) -> dict[str, tuple[float, float]]:
    """Per baseline length (m): integer candidates per DD, 2 B / lambda + 1, and the attitude
    error from a 0.01-cycle phase error, lambda 0.01 / B (mrad)."""
    lam = GPS_L1_WAVELENGTH_M
    return {f"{b:g} m": (2 * b / lam + 1, 1e3 * 0.01 * lam / b) for b in (*lengths, SCEN.baseline_m)}


def _baseline_tradeoff() -> bool:
    v = [baseline_tradeoff()[k] for k in ("0.5 m", "1 m", "2 m", "4 m")]
    return all(b[0] > a[0] and b[1] < a[1] for a, b in itertools.pairwise(v))


def imu_rate() -> float:
    return SCEN.imu_rate_hz


def gps_rate() -> float:
    return SCEN.gps_rate_hz


_rate100, _rate100_tol = printed("100", why="Sec. 2.1 'e.g., 100 Hz' against Table 1's IMU rate")
_rate1, _rate1_tol = printed("1", why="Sec. 2.1 'e.g., 1 Hz' against Table 1's GPS rate")

CLAIMS = [
    Claim(
        id="KZL-sec1-footprint-overlap",
        aliases=("KZL-c26-overlap",),
        locator="Sec. 1",
        quantity="the longest footprint overlap in the hybrid experiment (receiver footprint over the "
        "satellite's ground speed) is a few seconds (2 to 5 s, the reading of 'a few' in the ledger's "
        "table of prose words)",
        published=True,
        unit="statement",
        kind="statement",
        compute=_footprint_overlap_a_few,
        tolerance=EXACT,
        expected_status="not-reproducible",
        note="Circular orbit at the TerraSAR-X altitude, ground speed about 7.0 km/s; a 15 km receiver "
        "footprint gives about 2.2 s, 5-30 km gives 0.7-4.4 s: 'a few' at the nominal footprint, not "
        "over the whole assumed range.",
        discussed_in=PAGE0,
    ),
    Claim(
        id="KZL-sec1-positioning-less-strict",
        aliases=("KZL-c27-positioning",),
        locator="Sec. 1",
        quantity="positioning requirements less strict than pointing: the footprint shift of a 0.5 deg "
        "pointing error exceeds the stand-alone GPS position error",
        published=True,
        unit="statement",
        compute=_positioning_less_strict,
        tolerance=EXACT,
        expected_status="consistent",
        note="At the Table 1 height (3 km) and a 30 deg look angle the slant range is 3.5 km and the "
        "acceptable 0.5 deg pointing error of Sec. 1 moves the footprint by about 30 m, against 5-15 m of "
        "L1 code positioning.",
        discussed_in=PAGE0,
    ),
    Claim(
        id="KZL-sec1-baseline-tilt-accuracy",
        aliases=("KZL-c28-baseline-angle",),
        locator="Sec. 1",
        quantity="the baseline tilt accuracy for a height error below 1 m (TerraSAR-X geometry) is at the "
        "level of an arcsec",
        published=True,
        unit="statement",
        kind="statement",
        compute=_tilt_arcsec_level,
        tolerance=EXACT,
        expected_status="consistent",
        note="$dh = R \\sin\\theta\\, d\\alpha$ with $R \\sin\\theta = h \\tan\\theta$ (flat earth): about "
        "0.7 arcsec at 30 deg, 0.4-1.1 arcsec over 20-45 deg. The paper names the unit, not a value: "
        "'arcsec accuracy' read as within half a decade (or a decade) of an arcsec.",
        discussed_in=PAGE0,
    ),
    Claim(
        id="KZL-sec1-baseline-length-accuracy",
        aliases=("KZL-c29-baseline-length",),
        locator="Sec. 1",
        quantity="the baseline length accuracy for a height error below 1 m (TerraSAR-X geometry) is at the "
        "level of a mm to a cm",
        published=True,
        unit="statement",
        kind="statement",
        compute=_length_mm_cm_level,
        tolerance=EXACT,
        expected_status="consistent",
        note="$dh = R \\sin\\theta \\tan\\theta \\, dB / B$: about 1.2 mm for $B$ = 200 m at 30 deg; 0.2-4.4 "
        "mm over "
        "the band. The paper names units, not a value: 'mm/cm accuracy' read as within half a decade (or "
        "a decade) of 1 mm to 1 cm. The 'cm' of the text fits longer baselines or airborne geometries.",
        discussed_in=PAGE0,
    ),
    Claim(
        id="KZL-sec2.1-ins-data-rate",
        aliases=("KZL-c30-ins-rate",),
        locator="Sec. 2.1",
        quantity="the example INS data rate of Sec. 2.1 against Table 1's IMU update rate",
        published=_rate100,
        unit="Hz",
        kind="cross-check",
        compute=imu_rate,
        tolerance=_rate100_tol,
        expected_status="consistent",
        note="Both 100 Hz (also the 'e.g., 100 Hz' of Sec. 3.5).",
        discussed_in=PAGE0,
    ),
    Claim(
        id="KZL-sec2.1-gnss-output-rate",
        aliases=("KZL-c31-gnss-rate",),
        locator="Sec. 2.1",
        quantity="the example GNSS output rate of Sec. 2.1 against Table 1's GPS update rate",
        published=_rate1,
        unit="Hz",
        kind="cross-check",
        compute=gps_rate,
        tolerance=_rate1_tol,
        expected_status="consistent",
        note="Both 1 Hz.",
        discussed_in=PAGE0,
    ),
    Claim(
        id="KZL-sec2.2-cascaded-nearly-uncorrelated",
        aliases=("KZL-c32-cascaded",),
        locator="Sec. 2.2",
        quantity="cascaded filters: using the GNSS outputs only every >10 s accounts for their time "
        "correlation (a first-order receiver filter's outputs 10 s apart are nearly uncorrelated)",
        published=True,
        unit="statement",
        kind="statement",
        compute=_uncorrelated_after_10s,
        tolerance=EXACT,
        expected_status="consistent",
        note="$\\exp(-10/\\tau)$: 0.007 for $\\tau = 2$ s, $5 \\times 10^{-5}$ to 0.14 for $\\tau = 1$-5 "
        "s. The paper "
        "prints no correlation: 'nearly uncorrelated' is the book's reading, below 1/e (or 0.1).",
        discussed_in=PAGE0,
    ),
    Claim(
        id="KZL-eq6-first-order",
        locator="Eq. (6)",
        quantity="$A \\approx I + FT$: the first-order transition gives the 180 s stand-alone north-position "
        "$\\sigma$ of $e^{FT}$, at the Table 1 GPS interval",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq6_approximates,
        tolerance=EXACT,
        expected_status="consistent",
        note="Covariance propagation of the 17-state model over the Table 1 flight at $T$ = 1 s; the "
        "first-order noise $Q_d = G Q G^T T$ goes with Eq. (6). '≈' read as within 10 % (the reading "
        "of 'approximately' in the ledger's table of prose words) or 1 %.",
        discussed_in=PAGE1,
    ),
    Claim(
        id="KZL-eq9-quaternion",
        locator="Eq. (9)",
        quantity="the quaternion rate $\\dot q = q \\otimes [0, \\omega]/2$ integrates to the rotation of "
        "the body rate",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq9_holds,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Constant body rate (0.1, -0.2, 0.3) rad/s from the Table 1 attitude, $\\omega_{in}$ neglected "
        "as the paper does: RK4 at 1 ms steps ends within $10^{-6}$ deg of scipy's closed form after 1 s.",
        discussed_in=PAGE1,
    ),
    Claim(
        id="KZL-eq10-11-fd",
        locator="Eqs. (10)-(11)",
        quantity="the velocity-attitude block of F (the explicit matrix of Eq. (11)) equals finite "
        "differences of the velocity-error rate",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq10_11_holds,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Error = computed $-$ true, $\\hat R = e^{[\\Delta\\psi \\times]} R$; Table 1 attitude, "
        "specific force "
        "(0.5, -0.3, $-g$) m/s$^2$ in NED; central differences at $10^{-6}$ rad agree to $10^{-6}$ of g.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-eq11-bracket",
        locator="Eq. (11)",
        quantity="the explicit matrix of Eq. (11) is the cross-product matrix its bracket $[a \\times]$ "
        "names",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq11_is_bracket,
        tolerance=EXACT,
        expected_status="discrepant",
        erratum="KZL-E3-skew-notation",
        oracle=_eq11_oracle,
        oracle_tolerance=EXACT,
        note="At the Table 1 specific force $(0, 0, -g)$ the printed matrix is $-[a \\times]$, the usual "
        "cross-product matrix with its sign flipped (entries apart by up to $2\\|a\\|$). The explicit "
        "matrix, which is what enters a computation, is right under the paper's "
        "own error convention; the bracket names the other sign, and no printed number depends on it. "
        "Checked independently: the printed matrix times unit vectors against the cross product computed "
        "directly.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-eq15-orderings",
        locator="Eq. (15)",
        quantity="the two groupings of the double difference in Eq. (15) are equal",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq15_holds,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Between-satellite then between-antenna, or the reverse, over 1000 random range sets: equal to "
        "$10^{-6}$ relative (floating point on $2 \\times 10^{7}$ m ranges).",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-eq17-printed-rank",
        locator="Eq. (17)",
        quantity="the two DD attitude rows of Eq. (17) as printed (both rows with $l_{02}$) are two "
        "independent observations of one satellite pair, as two baselines should give",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq17_printed_two_rows,
        tolerance=EXACT,
        expected_status="discrepant",
        erratum="KZL-E5-dd-typos",
        oracle=_eq17_oracle,
        oracle_tolerance=EXACT,
        note="Table 1 sky, first two satellites, 2 m baselines along body x and y. With $l_{02}$ twice the "
        "rows coincide (rank 1); with $l_{01}$ and $l_{02}$ the rank is 2 (KZL-eq17-rank). No printed "
        "number depends on it.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-eq17-rank",
        locator="Eq. (17)",
        quantity="the DD attitude rows with $l_{01}$ and $l_{02}$ (corrected Eq. (17)) are two independent "
        "observations",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq17_corrected_two_rows,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Two satellites give two independent attitude observations, as Sec. 3.6 relies on.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-fig5-loose-three-unbounded",
        aliases=("KZL-c33-loose-three",),
        locator="Sec. 3.6, discussion of Fig. 5",
        quantity="with three satellites a loosely coupled integration is not bounded: the receiver's "
        "code geometry has rank 3 < 4 unknowns, so it gives no fix to the fusion filter",
        published=True,
        unit="statement",
        compute=_loose_three_no_fix,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Table 1 sky, first three satellites. Without a fix the loosely coupled filter runs free "
        "inertial, whose error grows to about 1 km in 3 min (KZL-fig5-ins-position).",
        discussed_in=PAGE3,
    ),
    Claim(
        id="KZL-sec3.7-baseline-tradeoff",
        aliases=("KZL-c34-baselines",),
        locator="Sec. 3.7",
        quantity="shorter baselines shrink the integer search, longer baselines improve the attitude: "
        "over 0.5, 1, 2, 4 m the candidates per DD rise and the attitude error falls",
        published=True,
        unit="statement",
        compute=_baseline_tradeoff,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Candidates $2 B / \\lambda + 1$ (about 22 for the Table 1 2 m baselines); attitude error "
        "$0.01 \\lambda / B$ (about 1 mrad at 2 m).",
        discussed_in=PAGE3,
    ),
]

CLAIMS = quoted(CLAIMS)
