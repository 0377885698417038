"""KZL Secs. 3.1-3.2: the error-state vector (Eq. 1), the initialisation by levelling and GPS
heading (Eqs. 2-4), the discretisation (Eqs. 5-6), the observability the preliminaries announce,
and the strapdown mechanization (Eqs. 7-9): their inputs, claims, errata and computes.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
from scipy.spatial.transform import Rotation

from navcore.claims import EXACT, Claim, Erratum, InputSet, input_cache, printed, with_quotes
from navcore.frames import dcm_from_euler, quat_multiply
from navcore.inertial.alignment import heading_from_velocity, levelling_as_printed
from navcore.inertial.error_model17 import ERROR_LAYOUT_17, error_dynamics_17, transition_exact
from navcore.inertial.strapdown import earth_rate_ned, transport_rate_ned
from navcore.papers.kzl_quotes import QUOTES
from navcore.papers.kzl_scenario import IN as SCEN
from navcore.papers.kzl_scenario import kzl_imu, table1_attitude, table1_scenario
from navcore.papers.kzl_tightly_coupled_filter import PAGE2, observability_ranks, table1_F
from navcore.units import DEG, DEG_PER_H, G0

#: Readings of Eq. (3) and of Sec. 3.2's 'can be neglected'.
IN = InputSet("KZL", "models")
IN.convention(
    "roll_formula",
    "atan2",
    quantity="arctangent of the printed roll of Eq. (3)",
    readings={
        "the two-argument arctangent that the name $\\arctan_2$ calls for": "atan2",
        "the one-argument arctangent of the printed ratio": "arctan",
    },
    reason="Eq. (3) prints '$\\arctan_2(a_y / a_z)$': the name of the two-argument arctangent with one "
    "argument, the ratio; read as the ratio's arctangent it returns the roll of a level specific "
    "force (for $|\\phi| < 90$ deg), read as atan2 it returns 180 deg",
)
IN.convention(
    "negligible_fraction",
    0.1,
    quantity="share of the gyro bias below which a rate is negligible",
    readings={"below a tenth of the gyro bias": 0.1, "below a fifth of it": 0.2},
    reason="'these terms can be neglected' (Sec. 3.2) carries no number",
)

#: Inputs first declared by the coverage sweep of issue 17: their section string, and so their
#: full names (``KZL.coverage.<name>``), stay.
IN_COVERAGE = InputSet("KZL", "coverage")
IN_COVERAGE.convention(
    "approx_rel",
    0.10,
    quantity="closeness that '≈' in $A(k) \\approx I + F T$ allows",
    readings={
        "within 10 %, the reading of 'approximately' in the ledger's table of prose words": 0.10,
        "within 1 %": 0.01,
    },
    reason="Eq. (6) writes '≈' in a formula and prints no number",
)


PAGE1 = "kzl/01-mechanization"


# --- Secs. 3.1-3.2: levelling, heading, discretisation, mechanization ------------------------
def table1_heading_deg() -> float:
    """KZL Eq. 4 applied to the Table 1 ENU velocity."""
    ve, vn = SCEN.velocity_east_mps, SCEN.velocity_north_mps
    return float(np.degrees(heading_from_velocity([vn, ve, 0.0])))


def printed_levelling_level_roll_deg() -> float:
    """Roll (deg) that printed Eq. 3 gives for the level Table 1 attitude, whose IMU measures the
    specific force R^T [0, 0, -g] of Eq. (8), under the reading of its arctangent used."""
    f_b = table1_attitude().T @ np.array([0.0, 0.0, -G0])
    roll, _ = levelling_as_printed(f_b, roll_form=IN.roll_formula)
    return float(np.degrees(roll)) + 0.0  # + 0.0: no negative zero


#: Pitch angles (deg) at which the printed Eq. (2) is tried: any nonzero pitch shows its sign.
PITCH_TEST_DEG = (-60.0, -20.0, -5.0, -1.0, 1.0, 5.0, 20.0, 60.0)


def printed_pitch_has_its_sign() -> bool:
    """Whether printed Eq. (2), applied to the specific force of Eq. (8) (a = f, R^T [0, 0, -g] at
    roll 0, the Table 1 heading and each pitch of :data:`PITCH_TEST_DEG`), returns the pitch with its
    sign (the roll reading does not enter Eq. (2))."""
    out = []
    for theta in PITCH_TEST_DEG:
        R = dcm_from_euler(SCEN.roll_deg * DEG, theta * DEG, SCEN.heading_deg * DEG)
        _, pitch = levelling_as_printed(R.T @ np.array([0.0, 0.0, -G0]))
        out.append(np.sign(pitch) == np.sign(theta))
    return bool(all(out))


def _printed_pitch_oracle() -> bool:
    """Independent: scipy's Rotation builds the attitudes and Eq. (2) is typed from the paper."""
    ok = True
    for theta in PITCH_TEST_DEG:
        R = Rotation.from_euler("ZYX", [90.0, theta, 0.0], degrees=True).as_matrix()
        ax, ay, az = R.T @ np.array([0.0, 0.0, -G0])
        pitch = np.arctan(-ax / np.sqrt(ay**2 + az**2))
        ok &= bool(np.sign(pitch) == np.sign(theta))
    return ok


def neglected_rates_deg_per_h() -> float:
    """|omega_in^n| = |Earth rate + transport rate| (deg/h) in the Table 1 scenario."""
    lat, h = SCEN.lat_deg * DEG, SCEN.height_m
    ve = SCEN.velocity_east_mps
    w = earth_rate_ned(lat) + transport_rate_ned([0.0, ve, 0.0], lat, h)
    return float(np.linalg.norm(w) / DEG_PER_H)


def neglected_coriolis_micro_g() -> float:
    """|(2 omega_ie + omega_en) x v| (micro-g) in the Table 1 scenario."""
    lat, h = SCEN.lat_deg * DEG, SCEN.height_m
    v = np.array([0.0, SCEN.velocity_east_mps, 0.0])
    a = np.cross(2 * earth_rate_ned(lat) + transport_rate_ned(v, lat, h), v)
    return float(np.linalg.norm(a) / (1e-6 * G0))


def series_terminates() -> bool:
    """KZL Eq. 5: expm(F T) equals I + FT + (FT)^2/2 + (FT)^3/6 (F nilpotent) at T = 1 s."""
    F = table1_F()
    return bool(np.abs(scipy.linalg.expm(F) - transition_exact(F, 1.0)).max() < 1e-12)


@input_cache
def discretisation_comparison(dt: float = 1.0) -> dict[str, float]:
    """Stand-alone covariance over the 180 s Table 1 flight with the exact transition and Van
    Loan noise (Eq. 5) and with I + F T and Q_d = G Q G^T T (Eq. 6): north-position and
    east-velocity 1-sigma at 180 s."""
    from navcore.estimation import discretize, first_order_transition
    from navcore.integration.ekf_ins_gnss import _gqgt, _initial_covariance

    sc = table1_scenario()
    C = table1_attitude()
    F = error_dynamics_17(C, np.array([0.0, 0.0, -G0]))
    GQG = _gqgt(sc)
    P0 = _initial_covariance(sc, C, True)
    Phi_e, Qd_e = discretize(F, GQG, dt)
    Phi_1, Qd_1 = first_order_transition(F, dt), GQG * dt
    Pe, P1 = P0.copy(), P0.copy()
    for _ in range(round(180.0 / dt)):
        Pe = Phi_e @ Pe @ Phi_e.T + Qd_e
        P1 = Phi_1 @ P1 @ Phi_1.T + Qd_1
    return {
        "pos_exact_m": float(np.sqrt(Pe[0, 0])),
        "pos_first_order_m": float(np.sqrt(P1[0, 0])),
        "vel_exact_mps": float(np.sqrt(Pe[4, 4])),
        "vel_first_order_mps": float(np.sqrt(P1[4, 4])),
    }


def eq6_position_ratio() -> float:
    """180 s stand-alone north-position sigma with A = I + FT (Eq. 6) over that with e^{FT}."""
    d = discretisation_comparison(1.0 / SCEN.gps_rate_hz)
    return d["pos_first_order_m"] / d["pos_exact_m"]


def _eq6_approximates() -> bool:
    return abs(eq6_position_ratio() - 1.0) <= IN_COVERAGE.approx_rel


def eq9_quaternion_error_deg() -> float:
    """Integrate q' = q (x) [0, w]/2 (Eq. 9, omega_in neglected) over 1 s at a constant body rate
    with RK4 (1000 steps) from the Table 1 attitude; angle to scipy's closed form, deg."""
    w = np.array([0.1, -0.2, 0.3])
    R0 = Rotation.from_matrix(table1_attitude())
    x, y, z, s = R0.as_quat()
    q = np.array([s, x, y, z])
    f = lambda q: 0.5 * quat_multiply(q, np.concatenate([[0.0], w]))
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


# --- Sec. 3.1: observability (the ranks are the observation models', Eqs. (13)-(17)) ----------
def _complete_only_with_attitude() -> bool:
    r = observability_ranks()
    n = ERROR_LAYOUT_17.size  # complete: every one of the 17 states of Eq. (1)
    return all(r["tc"][nu] < n for nu in range(1, 9)) and all(
        r["tc_att"][nu] == n and r["tc_dd"][nu] == n for nu in range(4, 9)
    )


# --- errata -----------------------------------------------------------------------------------
ERRATA = [
    Erratum(
        id="KZL-E1-levelling-sign",
        kind="convention",
        basis="text-only",
        locator="Eqs. (2)-(3)",
        printed="$\\theta = \\arctan(-a_x / \\sqrt{a_y^2 + a_z^2})$, $\\phi = \\arctan_2(a_y / a_z)$",
        finding="The pitch of Eq. (2) has the wrong sign: with $a$ the specific force of Eq. (8) (a "
        "level IMU measures $[0, 0, -g]$ in NED body axes) a nose-up pitch comes out nose-down, under "
        "every reading. For the specific force: $\\theta = \\arctan(f_x / \\sqrt{f_y^2 + f_z^2})$, "
        "$\\phi = \\mathrm{atan2}(-f_y, -f_z)$. The printed pair is right for $a = -f$, a sign "
        "convention Eq. (8) contradicts. The roll of Eq. (3) is an open reading, not part of the "
        "finding: read as the one-argument arctangent of the printed ratio it returns the roll of a "
        "level aircraft (for $|\\phi| < 90$ deg), read as atan2 it returns 180 deg.",
        evidence="The printed Eq. (2) applied to the specific force of nose-up and nose-down attitudes "
        "built with scipy's Rotation; Table 1 is level, so no printed number depends on it.",
        claims=("KZL-eq2-pitch-sign",),
        discussed_in=PAGE1,
    ),
    Erratum(
        id="KZL-E2-time-invariant",
        kind="unstated-assumption",
        basis="text-only",
        locator="Eq. (5), preceding text",
        printed="in case of a time-variant system the state transition is described as $A(k) = e^{FT}$",
        finding="The chain $A = e^{FT} = \\mathcal{L}^{-1}\\{(sI - F)^{-1}\\}$ holds for a time-invariant "
        "$F$ (or $F$ frozen "
        "over $T$). For the simplified model $F$ is nilpotent ($F^4 = 0$), so the series ends at $(FT)^3/6$.",
        evidence="scipy.linalg.expm against the cubic polynomial at the Table 1 attitude.",
        claims=("KZL-eq5-series",),
        discussed_in=PAGE1,
    ),
]


# --- claims --------------------------------------------------------------------------------------
CLAIMS = [
    Claim(
        id="KZL-eq1-states",
        locator="Sec. 3.1, Eq. (1)",
        quantity="number of states of the tightly coupled error-state vector",
        published=17,
        unit="states",
        compute=lambda: ERROR_LAYOUT_17.size,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Position, velocity, misalignment, accelerometer and gyro bias (3 each) plus clock bias "
        "and drift, as a named layout.",
        discussed_in=PAGE1,
    ),
    Claim(
        id="KZL-eq4-heading",
        locator="Eq. (4) and Table 1",
        quantity="heading from the Table 1 GPS velocity (110 m/s east)",
        published=90.0,
        unit="deg",
        kind="cross-check",
        compute=table1_heading_deg,
        tolerance=printed("90")[1],
        expected_status="consistent",
        note="$\\operatorname{atan2}(v_E, v_N)$ with $v_{ENU}$ = [110, 0, 0] m/s, the Table 1 heading: Eq. "
        "(4) on two printed "
        "values of Table 1, a check of the table's consistency: arithmetic on printed values, a "
        "cross-check.",
        discussed_in=PAGE1,
    ),
    Claim(
        id="KZL-eq2-3-levelling",
        locator="Eqs. (2)-(3)",
        quantity="roll that the printed levelling formula (Eq. 3) returns for the level Table 1 attitude, "
        "from the specific force of Eq. (8)",
        published=0.0,
        unit="deg",
        kind="reproduction",
        compute=printed_levelling_level_roll_deg,
        tolerance=printed("0", why="Table 1 prints roll 0")[1],
        expected_status="consistent",
        note="A level IMU measures $f = [0, 0, -g]^T$. Eq. (3) prints '$\\arctan_2(a_y / a_z)$', the "
        "two-argument "
        "name with one argument: read as $\\operatorname{atan2}(a_y, a_z)$ it returns roll = 180 deg; read "
        "as the "
        "arctangent of the printed ratio it returns 0, the Table 1 roll (for any roll within $\\pm 90$ deg).",
        discussed_in=PAGE1,
    ),
    Claim.statement(
        id="KZL-eq2-pitch-sign",
        locator="Eq. (2)",
        quantity="the printed levelling formula (Eq. 2), applied to the specific force of Eq. (8), returns "
        "the pitch of a nose-up or nose-down attitude with its sign",
        compute=printed_pitch_has_its_sign,
        expected_status="discrepant",
        note="At pitch +-1, 5, 20 and 60 deg (Table 1 roll and heading) printed Eq. (2) returns minus the "
        "pitch: it is right for a = -f, while Eq. (8) makes a the specific force. Table 1 is level, so "
        "no printed number depends on it. Checked independently with scipy's Rotation and Eq. (2) typed "
        "from the paper.",
        erratum="KZL-E1-levelling-sign",
        oracle=_printed_pitch_oracle,
        oracle_tolerance=EXACT,
        printed="$$\\theta = \\arctan\\left(-a_{ib,x}^b / \\sqrt{(a_{ib,y}^b)^2 + (a_{ib,z}^b)^2}\\right)$$ "
        "[...] $$\\dot{\\mathbf{v}}^n = R_b^n \\mathbf{a}_{ib}^b + \\mathbf{g}_l^n \\tag{8}$$",
        discussed_in=PAGE1,
    ),
    Claim.statement(
        id="KZL-sec3.1-gyro-bias-swamps-earth-rate",
        aliases=("KZL-c11-earth-rate",),
        locator="Sec. 3.1",
        quantity="a MEMS gyro bias of several 100 deg/h swamps the horizontal Earth rate (no gyrocompassing)",
        compute=lambda: (
            kzl_imu().gyro_bias > 10 * float(np.linalg.norm(earth_rate_ned(SCEN.lat_deg * DEG)[:2]))
        ),
        note="Table 1 gyro bias 360 deg/h against the horizontal Earth rate 9.46 deg/h at 51° N (38 times "
        "smaller).",
        discussed_in=PAGE1,
        table="levelling",
    ),
    Claim.statement(
        id="KZL-sec3.2-earth-transport-rates-negligible",
        aliases=("KZL-c13-neglected-rates",),
        locator="Secs. 3.1-3.2, Eq. (9)",
        quantity="Earth and transport rate are negligible against the low-cost gyro bias",
        compute=lambda: (
            neglected_rates_deg_per_h() < IN.negligible_fraction * kzl_imu().gyro_bias / DEG_PER_H
        ),
        note="'Can be neglected' read as below a tenth (or a fifth) of the gyro bias: $|\\omega_{in}|$ = "
        "20.7 deg/h against 360 deg/h (factor 17). "
        "The neglected Coriolis term (about 1900 µg) is not small against the 2400 µg "
        "accelerometer bias; inside the GPS-aided filter it is absorbed by the accelerometer-bias "
        "states. The computation reads published inputs only.",
        discussed_in=PAGE1,
    ),
    Claim.statement(
        id="KZL-eq5-series",
        locator="Eq. (5)",
        quantity="$e^{FT} = I + FT + (FT)^2/2 + \\ldots$ for the 17-state $F$",
        compute=series_terminates,
        note="$F$ is nilpotent ($F^4 = 0$): the series ends at $(FT)^3/6$ and equals scipy's expm to "
        "$10^{-12}$.",
        discussed_in=PAGE1,
    ),
    Claim.statement(
        id="KZL-sec3.1-observability-needs-attitude",
        aliases=("KZL-c12-observability",),
        locator="Sec. 3.1",
        quantity="complete observability only with redundant attitude information, depending on $\\nu$",
        compute=_complete_only_with_attitude,
        note="LTI observability rank in straight and level flight at the Table 1 attitude: code and "
        "$\\delta$ range alone never reach 17 (heading and z-gyro bias are unobservable); with Euler "
        "attitude or DD phases the rank is 17 for $\\nu \\ge 4$.",
        discussed_in=PAGE2,
        table="observability",
    ),
    Claim.statement(
        id="KZL-eq6-first-order",
        locator="Eq. (6)",
        quantity="$A \\approx I + FT$: the first-order transition gives the 180 s stand-alone north-position "
        "$\\sigma$ of $e^{FT}$, at the Table 1 GPS interval",
        compute=_eq6_approximates,
        expected_status="consistent",
        note="Covariance propagation of the 17-state model over the Table 1 flight at $T$ = 1 s; the "
        "first-order noise $Q_d = G Q G^T T$ goes with Eq. (6). '≈' read as within 10 % (the reading "
        "of 'approximately' in the ledger's table of prose words) or 1 %.",
        discussed_in=PAGE1,
    ),
    Claim.statement(
        id="KZL-eq9-quaternion",
        locator="Eq. (9)",
        quantity="the quaternion rate $\\dot q = q \\otimes [0, \\omega]/2$ integrates to the rotation of "
        "the body rate",
        compute=_eq9_holds,
        note="Constant body rate (0.1, -0.2, 0.3) rad/s from the Table 1 attitude, $\\omega_{in}$ neglected "
        "as the paper does: RK4 at 1 ms steps ends within $10^{-6}$ deg of scipy's closed form after 1 s.",
        discussed_in=PAGE1,
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
