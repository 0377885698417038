"""KZL Secs. 1-2: what footprint chasing and InSAR baselines ask of position and attitude
(Sec. 1), and the GNSS/INS background (Sec. 2): the inputs these sections leave out, their claims
and the computes those claims need.
"""

from __future__ import annotations

import numpy as np

from navcore.claims import PROSE_WORDS, Claim, InputSet, printed, prose, with_quotes
from navcore.papers.kzl_quotes import QUOTES
from navcore.papers.kzl_scenario import IN as SCEN
from navcore.papers.kzl_scenario import table1_los
from navcore.units import ARCSEC, DEG, DEG_PER_H

#: Inputs of the Sec. 1-2 claims that the paper states without their ingredients.
IN = InputSet("KZL", "models")
IN.assumed(
    "aircraft_speed_mps",
    100.0,
    low=80.0,
    high=140.0,
    reason="Sec. 1 gives no aircraft speed for the TerraSAR-X hybrid experiments; airborne SAR "
    "receivers of those experiments (C-160, Do-228 class) fly 80-140 m/s",
    unit="m/s",
    quantity="aircraft speed in the hybrid experiments",
)
IN.assumed(
    "terrasar_altitude_km",
    514.0,
    low=505.0,
    high=533.0,
    reason="TerraSAR-X flies a 514 km sun-synchronous orbit (505-533 km along the orbit); the paper "
    "names the satellite, not its orbit",
    unit="km",
    quantity="TerraSAR-X orbit altitude",
)
IN.assumed(
    "nav_grade_gyro_bias_deg_per_h",
    0.01,
    low=0.005,
    high=0.02,
    reason="Sec. 2.1 gives only a price (50,000-100,000 $); that buys a navigation-grade INS, whose "
    "gyro bias is 0.005-0.02 deg/h",
    unit="deg/h",
    quantity="gyro bias of a navigation-grade INS",
)
IN.published(
    "pointing_error_deg",
    0.5,
    locator="Sec. 1 ('an antenna pointing error of about 0.5 deg in all the three angles is acceptable')",
    unit="deg",
    quantity="acceptable antenna pointing error",
)
IN.convention(
    "earth_radius_m",
    6_378_137.0,
    unit="m",
    quantity="radius of the spherical Earth of the orbit and drift estimates",
    readings={
        "the WGS-84 equatorial radius, 6378.137 km": 6_378_137.0,
        "the IUGG mean Earth radius, 6371.0 km": 6_371_000.0,
    },
    reason="Secs. 1-2 state numbers (the satellite-to-aircraft speed ratio, the drift per hour) whose "
    "estimate needs the Earth's radius; the paper gives none, and a sphere's radius lies between the "
    "mean and the equatorial radius",
)
IN.convention(
    "gm_m3_s2",
    3.986004418e14,
    unit="m^3/s^2",
    quantity="Earth's gravitational constant GM",
    readings={
        "the WGS-84 value, 398600.4418 km³/s²": 3.986004418e14,
        "the WGS-72 value, 398600.8 km³/s²": 3.986008e14,
    },
    reason="the circular-orbit speed of TerraSAR-X follows from GM (the paper gives neither); the two "
    "geodetic standards of GM are both admissible",
)
#: Inputs first declared by the coverage sweep of issue 17: their section string, and so their
#: full names (``KZL.coverage.<name>``), stay.
IN_COVERAGE = InputSet("KZL", "coverage")
IN_COVERAGE.assumed(
    "receiver_footprint_km",
    15.0,
    low=5.0,
    high=30.0,
    reason="Sec. 1 gives no antenna footprint; the wide receive beam of an airborne SAR receiver at "
    "a few km altitude covers 5-30 km along track",
    unit="km",
    quantity="along-track footprint of the airborne receiver",
)
IN_COVERAGE.assumed(
    "look_angle_deg",
    30.0,
    low=20.0,
    high=45.0,
    reason="Sec. 1 names no InSAR geometry; 20-45 deg is the incidence range of TerraSAR-X",
    unit="deg",
    quantity="InSAR look angle",
)
IN_COVERAGE.assumed(
    "perp_baseline_m",
    200.0,
    low=100.0,
    high=300.0,
    reason="Sec. 1 gives no baseline; 100-300 m is the usual spaceborne across-track InSAR baseline",
    unit="m",
    quantity="InSAR perpendicular baseline",
)
IN_COVERAGE.assumed(
    "gps_position_sigma_m",
    10.0,
    low=5.0,
    high=15.0,
    reason="Sec. 1 gives no positioning accuracy; 5-15 m is single-frequency L1 code positioning",
    unit="m",
    quantity="stand-alone GPS position accuracy",
)
IN_COVERAGE.assumed(
    "receiver_filter_tau_s",
    2.0,
    low=1.0,
    high=5.0,
    reason="Sec. 2.2 gives no receiver filter; receiver navigation filters have 1-5 s time constants",
    unit="s",
    quantity="time constant of the receiver's navigation filter",
)
IN_COVERAGE.convention(
    "uncorrelated_below",
    float(np.exp(-1.0)),
    quantity="correlation below which outputs count as uncorrelated",
    readings={"below 1/e, a time constant apart": float(np.exp(-1.0)), "below 0.1": 0.1},
    reason="Sec. 2.2 accounts for the correlation of cascaded filters 'by considering this information "
    "only every >10 s' and gives no correlation; the book reads it as making the outputs nearly "
    "uncorrelated",
)
IN_COVERAGE.convention(
    "unit_level_decades",
    0.5,
    unit="decades",
    quantity="distance from the named unit that 'mm/cm' and 'arcsec' accuracy allow",
    readings={"within half a decade of the unit": 0.5, "within a decade of it": 1.0},
    reason="Sec. 1 names units, 'mm/cm (length) and arcsec (angle) accuracy', not values; an accuracy "
    "'of the unit' lies within some decades of it",
)

PAGE0 = "kzl/00-requirements"
PAGE2 = "kzl/02-error-model"


# --- Sec. 1 ----------------------------------------------------------------------------------
def satellite_to_aircraft_speed() -> float:
    """TerraSAR-X circular-orbit speed over the aircraft speed of the hybrid experiments (KZL Sec. 1)."""
    v_sat = np.sqrt(IN.gm_m3_s2 / (IN.earth_radius_m + 1000.0 * IN.terrasar_altitude_km))
    return float(v_sat / IN.aircraft_speed_mps)


def footprint_overlap_s() -> float:
    """Receiver footprint over the satellite's ground speed (circular orbit), s."""
    v_air = IN.aircraft_speed_mps
    v_sat = satellite_to_aircraft_speed() * v_air
    r = IN.earth_radius_m / (IN.earth_radius_m + 1000.0 * IN.terrasar_altitude_km)
    return float(1000.0 * IN_COVERAGE.receiver_footprint_km / (v_sat * r - v_air))


def _footprint_overlap_a_few() -> bool:
    """'A few seconds in maximum': the longest overlap in the prose table's 'a few' (2 to 5 s)."""
    word = PROSE_WORDS["a few"]
    return bool(word["centre"] - word["abs"] <= footprint_overlap_s() <= word["centre"] + word["abs"])


def pointing_shift_m() -> float:
    """Footprint shift of the acceptable pointing error (Sec. 1, 0.5 deg) at the slant range of the
    Table 1 height, m."""
    slant = SCEN.height_m / np.cos(IN_COVERAGE.look_angle_deg * DEG)
    return float(slant * np.tan(IN.pointing_error_deg * DEG))


def _positioning_less_strict() -> bool:
    return pointing_shift_m() > IN_COVERAGE.gps_position_sigma_m


def _insar_slant_sin() -> float:
    """R sin(theta) of the TerraSAR-X geometry (flat earth), m."""
    th = IN_COVERAGE.look_angle_deg * DEG
    return float(1000.0 * IN.terrasar_altitude_km * np.tan(th))


def baseline_angle_arcsec() -> float:
    """Baseline tilt error giving a 1 m height error: 1 m / (R sin theta), arcsec."""
    return float(1.0 / _insar_slant_sin() / ARCSEC)


def baseline_length_mm() -> float:
    """Baseline length error giving a 1 m height error: B / (R sin theta tan theta), mm."""
    th = IN_COVERAGE.look_angle_deg * DEG
    return float(1000.0 * IN_COVERAGE.perp_baseline_m / (_insar_slant_sin() * np.tan(th)))


def _within_decades(value: float, low: float, high: float) -> bool:
    """Whether ``value`` lies within the declared number of decades of the span ``[low, high]``."""
    d = IN_COVERAGE.unit_level_decades
    return bool(low * 10.0**-d <= value <= high * 10.0**d)


def _tilt_arcsec_level() -> bool:
    """'arcsec (angle) accuracy': the tilt accuracy for 1 m of height at the level of an arcsec."""
    return _within_decades(baseline_angle_arcsec(), 1.0, 1.0)


def _length_mm_cm_level() -> bool:
    """'mm/cm (length) accuracy': the length accuracy for 1 m of height between a mm and a cm."""
    return _within_decades(baseline_length_mm(), 1.0, 10.0)


# --- Sec. 2 ----------------------------------------------------------------------------------
def nav_grade_drift_km_per_h() -> float:
    """Long-term position drift R * eps (km/h) of an unaided INS with gyro bias eps (KZL Sec. 2.1)."""
    return float(IN.earth_radius_m * IN.nav_grade_gyro_bias_deg_per_h * DEG_PER_H * 3600.0 / 1000.0)


def _geometry_rank_is_min_nu_4() -> bool:
    """Rank of the code geometry [-l^T 1] equals min(nu, 4) for nu = 1..8 (Table 1 sky)."""
    geometry = [np.hstack([-table1_los(nu), np.ones((nu, 1))]) for nu in range(1, 9)]
    # the unknowns: three position coordinates and the clock bias (the columns of [-l^T 1])
    return [np.linalg.matrix_rank(G) for G in geometry] == [min(G.shape) for G in geometry]


def correlation_after_10s() -> float:
    """Correlation of a first-order receiver filter's output 10 s apart: exp(-10 / tau)."""
    return float(np.exp(-10.0 / IN_COVERAGE.receiver_filter_tau_s))


def _uncorrelated_after_10s() -> bool:
    return correlation_after_10s() < IN_COVERAGE.uncorrelated_below


def imu_rate() -> float:
    return SCEN.imu_rate_hz


def gps_rate() -> float:
    return SCEN.gps_rate_hz


_rate100, _rate100_tol = printed("100", why="Sec. 2.1 'e.g., 100 Hz' against Table 1's IMU rate")
_rate1, _rate1_tol = printed("1", why="Sec. 2.1 'e.g., 1 Hz' against Table 1's GPS rate")

CLAIMS = [
    Claim(
        id="KZL-sec1-satellite-aircraft-speed-ratio",
        aliases=("KZL-c1",),
        locator="Sec. 1",
        quantity="satellite speed about 76 times the aircraft speed in the hybrid experiments",
        published=76.0,
        unit="",
        kind="reproduction",
        compute=satellite_to_aircraft_speed,
        tolerance=prose("about"),
        expected_status="consistent",
        note="Circular-orbit speed $\\sqrt{GM / (R + h)}$ of TerraSAR-X (7.6 km/s at the assumed 514 km) "
        "over "
        "the assumed aircraft speed; the paper gives neither. A ratio of 76 means about 100 m/s; Table 1's "
        "110 m/s would give 69. The book computes it under stated assumptions.",
        discussed_in=PAGE0,
        table="footprint-chasing",
    ),
    Claim(
        id="KZL-sec2.1-ins-drift-per-hour",
        aliases=("KZL-c6",),
        locator="Sec. 2.1",
        quantity="position error of a 50,000-100,000 $ INS without aiding, km per hour",
        published=1.0,
        unit="km/h",
        kind="reproduction",
        compute=nav_grade_drift_km_per_h,
        tolerance=prose("about"),
        expected_status="not-reproducible",
        note="No sensor specification is given for the navigation-grade INS. Long-term (beyond the "
        "84-min Schuler period) position drift of an unaided INS with gyro bias $\\varepsilon$: "
        "$R\\varepsilon$, with the assumed $\\varepsilon$ = 0.01 deg/h (0.005-0.02) giving 1.1 km/h, "
        "the classic 1 nmi/h class.",
        discussed_in=PAGE0,
        table="ins-gnss",
    ),
    Claim.statement(
        id="KZL-sec2.1-four-measurements",
        aliases=("KZL-c7",),
        locator="Sec. 2.1",
        quantity="four or more simultaneous measurements are needed for 3-D position and clock bias",
        compute=_geometry_rank_is_min_nu_4,
        note="Rank of the pseudorange geometry matrix $[-l^T\\ 1]$ is $\\min(\\nu, 4)$ for the first $\\nu$ "
        "satellites of the simulation's sky.",
        discussed_in=PAGE2,
        table="observability",
    ),
    Claim.statement(
        id="KZL-sec1-footprint-overlap",
        aliases=("KZL-c26-overlap",),
        locator="Sec. 1",
        quantity="the longest footprint overlap in the hybrid experiment (receiver footprint over the "
        "satellite's ground speed) is a few seconds (2 to 5 s, the reading of 'a few' in the ledger's "
        "table of prose words)",
        compute=_footprint_overlap_a_few,
        expected_status="not-reproducible",
        note="Circular orbit at the TerraSAR-X altitude, ground speed about 7.0 km/s; a 15 km receiver "
        "footprint gives about 2.2 s, 5-30 km gives 0.7-4.4 s: 'a few' at the nominal footprint, not "
        "over the whole assumed range.",
        discussed_in=PAGE0,
        table="footprint-chasing",
    ),
    Claim.statement(
        id="KZL-sec1-positioning-less-strict",
        aliases=("KZL-c27-positioning",),
        locator="Sec. 1",
        quantity="positioning requirements less strict than pointing: the footprint shift of a 0.5 deg "
        "pointing error exceeds the stand-alone GPS position error",
        compute=_positioning_less_strict,
        expected_status="consistent",
        note="At the Table 1 height (3 km) and a 30 deg look angle the slant range is 3.5 km and the "
        "acceptable 0.5 deg pointing error of Sec. 1 moves the footprint by about 30 m, against 5-15 m of "
        "L1 code positioning.",
        discussed_in=PAGE0,
        table="footprint-chasing",
    ),
    Claim.statement(
        id="KZL-sec1-baseline-tilt-accuracy",
        aliases=("KZL-c28-baseline-angle",),
        locator="Sec. 1",
        quantity="the baseline tilt accuracy for a height error below 1 m (TerraSAR-X geometry) is at the "
        "level of an arcsec",
        compute=_tilt_arcsec_level,
        expected_status="consistent",
        note="$dh = R \\sin\\theta\\, d\\alpha$ with $R \\sin\\theta = h \\tan\\theta$ (flat earth): about "
        "0.7 arcsec at 30 deg, 0.4-1.1 arcsec over 20-45 deg. The paper names the unit, not a value: "
        "'arcsec accuracy' read as within half a decade (or a decade) of an arcsec.",
        discussed_in=PAGE0,
        table="footprint-chasing",
    ),
    Claim.statement(
        id="KZL-sec1-baseline-length-accuracy",
        aliases=("KZL-c29-baseline-length",),
        locator="Sec. 1",
        quantity="the baseline length accuracy for a height error below 1 m (TerraSAR-X geometry) is at the "
        "level of a mm to a cm",
        compute=_length_mm_cm_level,
        expected_status="consistent",
        note="$dh = R \\sin\\theta \\tan\\theta \\, dB / B$: about 1.2 mm for $B$ = 200 m at 30 deg; 0.2-4.4 "
        "mm over "
        "the band. The paper names units, not a value: 'mm/cm accuracy' read as within half a decade (or "
        "a decade) of 1 mm to 1 cm. The 'cm' of the text fits longer baselines or airborne geometries.",
        discussed_in=PAGE0,
        table="footprint-chasing",
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
        table="ins-gnss",
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
        table="ins-gnss",
    ),
    Claim.statement(
        id="KZL-sec2.2-cascaded-nearly-uncorrelated",
        aliases=("KZL-c32-cascaded",),
        locator="Sec. 2.2",
        quantity="cascaded filters: using the GNSS outputs only every >10 s accounts for their time "
        "correlation (a first-order receiver filter's outputs 10 s apart are nearly uncorrelated)",
        compute=_uncorrelated_after_10s,
        expected_status="consistent",
        note="$\\exp(-10/\\tau)$: 0.007 for $\\tau = 2$ s, $5 \\times 10^{-5}$ to 0.14 for $\\tau = 1$-5 "
        "s. The paper "
        "prints no correlation: 'nearly uncorrelated' is the book's reading, below 1/e (or 0.1).",
        discussed_in=PAGE0,
        table="ins-gnss",
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
