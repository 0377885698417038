"""KZL Secs. 3.1-3.5: state vector, initialisation, discretisation, mechanization, error and
observation models, correction step. Claims computed from the models, and the errata.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
from scipy.spatial.transform import Rotation

from navcore.claims import EXACT, Claim, Erratum, InputSet, input_cache, printed, prose
from navcore.estimation import kf_update
from navcore.frames import dcm_from_euler, dcm_from_quat, euler_from_dcm, quat_from_dcm, skew
from navcore.gnss.carrier_phase import dd_covariance, euler_rate_matrix_body
from navcore.inertial.alignment import heading_from_velocity, levelling_as_printed
from navcore.inertial.error_model17 import (
    ERROR_LAYOUT_17,
    code_doppler_rows,
    error_dynamics_17,
    observability_rank,
    transition_exact,
)
from navcore.inertial.strapdown import earth_rate_ned, transport_rate_ned
from navcore.integration.ekf_ins_gnss import correct_attitude, sequential_scalar_updates
from navcore.integration.measurement_rows import (
    attitude_observation_rows_count,
    dd_observation_rows_count,
    euler_attitude_rows,
    tc_attitude_observation_matrix,
    tc_dd_observation_matrix,
)
from navcore.papers.kzl_quotes import quoted
from navcore.papers.kzl_scenario import IN as SCEN
from navcore.papers.kzl_scenario import kzl_imu, table1_baselines_b, table1_scenario, table1_sky
from navcore.units import DEG, DEG_PER_H, G0

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

PAGE0 = "kzl/00-requirements"
PAGE1 = "kzl/01-mechanization"
PAGE2 = "kzl/02-error-model"


# --- helpers --------------------------------------------------------------------------------
def table1_attitude() -> np.ndarray:
    """Body-to-NED DCM of the Table 1 attitude (roll 0, pitch 0, heading 90 deg)."""
    return dcm_from_euler(SCEN.roll_deg * DEG, SCEN.pitch_deg * DEG, SCEN.heading_deg * DEG)


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


def table1_F() -> np.ndarray:
    C = table1_attitude()
    return error_dynamics_17(C, np.array([0.0, 0.0, -G0]))


def series_terminates() -> bool:
    """KZL Eq. 5: expm(F T) equals I + FT + (FT)^2/2 + (FT)^3/6 (F nilpotent) at T = 1 s."""
    F = table1_F()
    return bool(np.abs(scipy.linalg.expm(F) - transition_exact(F, 1.0)).max() < 1e-12)


def table1_los(nu: int, k: int = 0) -> np.ndarray:
    """Unit LOS (NED) of the first ``nu`` satellites in priority order at epoch ``k``."""
    sats = table1_sky()[0][k, :nu]
    d = sats - np.array([0.0, 0.0, 0.0])
    return d / np.linalg.norm(d, axis=1, keepdims=True)


@input_cache
def observability_ranks() -> dict[str, dict[int, int]]:
    """Observability ranks of TC, TC + attitude and TC + DD for nu = 1..8 (Table 1 geometry)."""
    F, C = table1_F(), table1_attitude()
    out: dict[str, dict[int, int]] = {"tc": {}, "tc_att": {}, "tc_dd": {}}
    for nu in range(1, 9):
        los = table1_los(nu)
        out["tc"][nu] = observability_rank(F, code_doppler_rows(los))
        out["tc_att"][nu] = observability_rank(F, tc_attitude_observation_matrix(los, C, 0.0, 0.0))
        out["tc_dd"][nu] = observability_rank(F, tc_dd_observation_matrix(los, C, table1_baselines_b()))
    return out


def heading_observable(mode: str = "tc", nu: int = 8) -> bool:
    """Is the heading error (psi_D) observable in the Table 1 flight with ``nu`` satellites?

    True when the unit vector of the heading state lies in the row space of the LTI
    observability matrix of code and delta range (``mode="tc"``), plus Euler attitude
    (``"tc_att"``) or DD phases (``"tc_dd"``): then a direct measurement of the heading
    added to the rows leaves :func:`~navcore.inertial.error_model17.observability_rank`
    unchanged (that row space is invariant under ``F``, so the added row's propagations
    ``e F^k`` add nothing either).
    """
    F, C, los = table1_F(), table1_attitude(), table1_los(nu)
    H = {
        "tc": lambda: code_doppler_rows(los),
        "tc_att": lambda: tc_attitude_observation_matrix(los, C, 0.0, 0.0),
        "tc_dd": lambda: tc_dd_observation_matrix(los, C, table1_baselines_b()),
    }[mode]()
    H = np.atleast_2d(H)
    e = np.zeros((1, F.shape[0]))
    e[0, ERROR_LAYOUT_17.slice("misalignment").start + 2] = 1.0
    return observability_rank(F, np.vstack([H, e])) == observability_rank(F, H)


def _complete_only_with_attitude() -> bool:
    r = observability_ranks()
    n = ERROR_LAYOUT_17.size  # complete: every one of the 17 states of Eq. (1)
    return all(r["tc"][nu] < n for nu in range(1, 9)) and all(
        r["tc_att"][nu] == n and r["tc_dd"][nu] == n for nu in range(4, 9)
    )


def _row_counts_eq13() -> bool:
    return all(attitude_observation_rows_count(nu) == 3 + 2 * nu for nu in range(1, 9))


def _row_counts_eq17() -> bool:
    nb = len(table1_baselines_b())  # Table 1's 3 antennas: two baselines from the master
    return all(dd_observation_rows_count(nu, nb) == 2 + 4 * (nu - 1) for nu in range(1, 9))


def _sequential_equals_batch() -> bool:
    """Eight satellites with DD: whitened sequential scalar updates vs one batch update."""
    C = table1_attitude()
    H = tc_dd_observation_matrix(table1_los(8), C, table1_baselines_b())
    n_code = code_doppler_rows(table1_los(8)).shape[0]  # pseudorange and delta range of 8 satellites
    R = scipy.linalg.block_diag(np.diag(np.tile([9.0, 0.0025], 8)), dd_covariance(8, 0.1))
    rng = np.random.default_rng(4)
    A = rng.normal(size=(17, 17))
    P = A @ A.T + np.eye(17)
    y = np.asarray(rng.normal(size=H.shape[0]))
    ref = kf_update(np.zeros(17), P, y, H, R)
    Linv = np.linalg.inv(np.linalg.cholesky(R[n_code:, n_code:]))
    Hw = np.vstack([H[:n_code], Linv @ H[n_code:]])
    yw = np.concatenate([y[:n_code], Linv @ y[n_code:]])
    rw = np.concatenate([np.diag(R)[:n_code], np.ones(len(y) - n_code)])
    x, Ps = sequential_scalar_updates(np.zeros((1, 17)), P[None], yw[None], Hw[None], rw)
    return bool(np.allclose(x[0], ref.x, atol=1e-9) and np.allclose(Ps[0], ref.P, atol=1e-9))


QCORR_DPSI = np.array([1.0, -0.5, 2.0]) * DEG


def printed_correction_removes_error() -> bool:
    """Whether the printed right-hand correction of Sec. 3.5 removes the estimated n-frame error
    (residual below 1e-9 deg, round-off), at the Table 1 attitude and the test error QCORR_DPSI."""
    return printed_correction_residual_deg() < 1e-9


def _printed_correction_oracle_removes() -> bool:
    return _printed_correction_oracle() < 1e-9


def printed_correction_residual_deg() -> float:
    """Residual attitude error (deg) after the printed right-hand correction at the Table 1 attitude."""
    C = table1_attitude()
    C_hat = scipy.linalg.expm(skew(QCORR_DPSI)) @ C
    q = correct_attitude(quat_from_dcm(C_hat)[None], QCORR_DPSI[None], "right")[0]
    return float(np.degrees(np.linalg.norm(Rotation.from_matrix(dcm_from_quat(q) @ C.T).as_rotvec())))


def _printed_correction_oracle() -> float:
    """Independent: scipy Rotation composes R_hat * Exp(-dpsi) (body side); residual angle to R, deg."""
    R = Rotation.from_matrix(table1_attitude())
    R_hat = Rotation.from_rotvec(QCORR_DPSI) * R
    corrected = R_hat * Rotation.from_rotvec(-QCORR_DPSI)
    return float(np.degrees((corrected * R.inv()).magnitude()))


def printed_R_is_euler_jacobian() -> bool:
    """Whether Eq. (13)'s block R (body rates to Euler-angle rates) is the Jacobian of the Euler
    angles with respect to the n-frame attitude error, at the Table 1 attitude (to round-off)."""
    return printed_R_block_error() < 1e-9


def _printed_R_oracle() -> bool:
    # central differences with a 1e-6 rad step: agreement to 1e-6
    return _printed_R_block_oracle() < 1e-6


def printed_R_block_error() -> float:
    """Largest entry of (printed block R - Euler-attitude Jacobian) at the Table 1 attitude."""
    C = table1_attitude()
    return float(np.max(np.abs(euler_rate_matrix_body(0.0, 0.0) - euler_attitude_rows(C, 0.0, 0.0)[:, 6:9])))


def _printed_R_block_oracle() -> float:
    """Independent: the printed block against central finite differences of euler_from_dcm(expm([d x]) C)."""
    C = table1_attitude()
    eps = 1e-6
    J = np.column_stack(
        [
            (
                np.array(euler_from_dcm(scipy.linalg.expm(skew(eps * e)) @ C))
                - np.array(euler_from_dcm(scipy.linalg.expm(skew(-eps * e)) @ C))
            )
            / (2 * eps)
            for e in np.eye(3)
        ]
    )
    return float(np.max(np.abs(euler_rate_matrix_body(0.0, 0.0) - J)))


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


def _geometry_rank_is_min_nu_4() -> bool:
    """Rank of the code geometry [-l^T 1] equals min(nu, 4) for nu = 1..8 (Table 1 sky)."""
    geometry = [np.hstack([-table1_los(nu), np.ones((nu, 1))]) for nu in range(1, 9)]
    # the unknowns: three position coordinates and the clock bias (the columns of [-l^T 1])
    return [np.linalg.matrix_rank(G) for G in geometry] == [min(G.shape) for G in geometry]


def rotation_vector_euler_mismatch() -> float:
    """Largest entry of d(roll, pitch, heading)/d(rotation vector) - I of a small rotation: the
    Jacobian at the identity (the rotation vector and the Euler angles of the rotation itself)."""
    return float(np.max(np.abs(euler_attitude_rows(np.eye(3), 0.0, 0.0)[:, 6:9] - np.eye(3))))


def _small_rotation_same() -> bool:
    # the Jacobian at the identity is exactly I (round-off)
    return rotation_vector_euler_mismatch() < 1e-9


def small_rotation_example_deg() -> tuple[np.ndarray, np.ndarray]:
    """The rotation vector (1, -0.5, 2) deg and the Euler angles (roll, pitch, heading) of its
    rotation, deg: equal to first order, apart by the second-order terms."""
    v = np.array([1.0, -0.5, 2.0])
    euler = Rotation.from_rotvec(v * DEG).as_euler("ZYX", degrees=True)[::-1]
    return v, euler


def satellite_to_aircraft_speed() -> float:
    """TerraSAR-X circular-orbit speed over the aircraft speed of the hybrid experiments (KZL Sec. 1)."""
    v_sat = np.sqrt(IN.gm_m3_s2 / (IN.earth_radius_m + 1000.0 * IN.terrasar_altitude_km))
    return float(v_sat / IN.aircraft_speed_mps)


def nav_grade_drift_km_per_h() -> float:
    """Long-term position drift R * eps (km/h) of an unaided INS with gyro bias eps (KZL Sec. 2.1)."""
    return float(IN.earth_radius_m * IN.nav_grade_gyro_bias_deg_per_h * DEG_PER_H * 3600.0 / 1000.0)


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
    Erratum(
        id="KZL-E3-skew-notation",
        kind="convention",
        basis="text-only",
        locator="Eq. (11)",
        printed="$F_{23} = [a \\times] = \\begin{bmatrix} 0 & a_d & -a_e \\\\ -a_d & 0 & a_n \\\\ "
        "a_e & -a_n & 0 \\end{bmatrix}$",
        finding="The explicit matrix is minus the usual cross-product matrix: $[a "
        "\\times]_{\\text{paper}}\\, b = b \\times a$. "
        "The explicit matrix is the right $F_{23}$ for error = estimated $-$ true and "
        "$\\hat{R} = (I + [\\Delta\\psi \\times]) R$; reading the bracket as the standard skew flips the "
        "sign of $F_{23}$ "
        "and of the DD rows of Eq. (17).",
        evidence="Finite differences of the nonlinear velocity-error rate.",
        claims=("KZL-eq11-bracket",),
        discussed_in=PAGE2,
    ),
    Erratum(
        id="KZL-E4-euler-rows",
        kind="derivation",
        basis="text-only",
        locator="Eq. (13), block R",
        printed="R is a frame rotation matrix for the transformation from body-axes angular rates to "
        "the Euler angle angular rates",
        finding="The Jacobian of the Euler angles with respect to the n-frame attitude error is "
        "$J_b^{-1}(\\phi, \\theta)\\, R_n^b$, not $J_b^{-1}$ alone. At the Table 1 attitude (heading 90 deg) "
        "they "
        "differ by swapping north/east tilt into roll/pitch.",
        evidence="Central finite differences of the Euler angles of $\\exp([\\Delta\\psi\\times])\\,R$ with "
        "respect to $\\Delta\\psi$. The paper describes R in words and prints no number from it.",
        claims=("KZL-eq13-R",),
        discussed_in=PAGE2,
    ),
    Erratum(
        id="KZL-E5-dd-typos",
        kind="typography",
        basis="text-only",
        locator="Eqs. (1), (10), (14), (17)",
        printed="Eq. (17): both DD rows use $l_{02}$ and rows 2 and 4 have an extra $0^T$ block; Eq. (14) "
        "lists "
        "$\\rho^{(n)}$ twice; Eq. (10) says O is the identity and I the zero matrix; Eq. (1)'s compact "
        "form drops $\\Delta\\psi$, $\\Delta b_\\omega$ and the clock",
        finding="The first DD row uses $l_{01}$; Eq. (14) has 6 rows for two satellites, matching "
        "$2 + 4 (\\nu - 1)$; O is the zero and I the identity matrix.",
        evidence="Row counts of the carrier-phase observation matrices the book's code builds; with "
        "$l_{02}$ in both "
        "rows "
        "the DD attitude block of one satellite pair has rank 1 instead of 2.",
        claims=("KZL-eq17-printed-rank",),
        discussed_in=PAGE2,
    ),
    Erratum(
        id="KZL-E6-quaternion-order",
        kind="convention",
        basis="text-only",
        locator="Sec. 3.5, attitude correction",
        printed="$q_b^{n,+} = q_b^{n,-} \\otimes q^n$ with the n-frame rotation quaternion $q^n$ of $\\phi = "
        "-\\Delta\\hat{\\psi}$",
        finding="An n-frame rotation multiplies $q_b^n$ from the left: $q^{n,+} = q^n \\otimes q^{n,-}$. The "
        "printed order rotates about body axes; at the Table 1 heading of 90 deg a 2.29 deg "
        "error leaves a 1.58 deg residual.",
        evidence="The filter's attitude correction applied in both orders and compared with an independent "
        "rotation library.",
        claims=("KZL-qcorr",),
        discussed_in=PAGE2,
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
    Claim(
        id="KZL-eq2-pitch-sign",
        locator="Eq. (2)",
        quantity="the printed levelling formula (Eq. 2), applied to the specific force of Eq. (8), returns "
        "the pitch of a nose-up or nose-down attitude with its sign",
        published=True,
        unit="statement",
        kind="statement",
        compute=printed_pitch_has_its_sign,
        tolerance=EXACT,
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
    Claim(
        id="KZL-sec3.1-gyro-bias-swamps-earth-rate",
        aliases=("KZL-c11-earth-rate",),
        locator="Sec. 3.1",
        quantity="a MEMS gyro bias of several 100 deg/h swamps the horizontal Earth rate (no gyrocompassing)",
        published=True,
        unit="statement",
        compute=lambda: (
            kzl_imu().gyro_bias > 10 * float(np.linalg.norm(earth_rate_ned(SCEN.lat_deg * DEG)[:2]))
        ),
        tolerance=EXACT,
        expected_status="reproduced",
        note="Table 1 gyro bias 360 deg/h against the horizontal Earth rate 9.46 deg/h at 51° N (38 times "
        "smaller).",
        discussed_in=PAGE1,
    ),
    Claim(
        id="KZL-sec3.2-earth-transport-rates-negligible",
        aliases=("KZL-c13-neglected-rates",),
        locator="Secs. 3.1-3.2",
        quantity="Earth and transport rate are negligible against the low-cost gyro bias",
        published=True,
        unit="statement",
        compute=lambda: (
            neglected_rates_deg_per_h() < IN.negligible_fraction * kzl_imu().gyro_bias / DEG_PER_H
        ),
        tolerance=EXACT,
        expected_status="reproduced",
        note="'Can be neglected' read as below a tenth (or a fifth) of the gyro bias: $|\\omega_{in}|$ = "
        "20.7 deg/h against 360 deg/h (factor 17). "
        "The neglected Coriolis term (about 1900 µg) is not small against the 2400 µg "
        "accelerometer bias; inside the GPS-aided filter it is absorbed by the accelerometer-bias "
        "states. The computation reads published inputs only.",
        discussed_in=PAGE1,
    ),
    Claim(
        id="KZL-eq5-series",
        locator="Eq. (5)",
        quantity="$e^{FT} = I + FT + (FT)^2/2 + \\ldots$ for the 17-state $F$",
        published=True,
        unit="statement",
        compute=series_terminates,
        tolerance=EXACT,
        expected_status="reproduced",
        note="$F$ is nilpotent ($F^4 = 0$): the series ends at $(FT)^3/6$ and equals scipy's expm to "
        "$10^{-12}$.",
        discussed_in=PAGE1,
    ),
    Claim(
        id="KZL-dim13",
        locator="Sec. 3.4, after Eq. (13)",
        quantity="rows of the observation matrix with redundant attitude = $3 + 2\\nu$ ($\\nu$ = 1..8)",
        published=True,
        unit="statement",
        compute=_row_counts_eq13,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Counted from the stacked measurement matrix built by the carrier-phase model.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-dim17",
        locator="Sec. 3.4, before Eq. (17)",
        quantity="rows of the DD observation matrix = $2 + 4 (\\nu - 1)$ ($\\nu$ = 1..8)",
        published=True,
        unit="statement",
        compute=_row_counts_eq17,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Code and $\\delta$ range per satellite plus two DDs (baselines $A_0$-$A_1$, $A_0$-$A_2$) per "
        "non-master "
        "satellite. Eq. (14) as printed has 7 rows for $\\nu = 2$ (a duplicated row); the formula gives 6.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-sec3.1-observability-needs-attitude",
        aliases=("KZL-c12-observability",),
        locator="Sec. 3.1",
        quantity="complete observability only with redundant attitude information, depending on $\\nu$",
        published=True,
        unit="statement",
        compute=_complete_only_with_attitude,
        tolerance=EXACT,
        expected_status="reproduced",
        note="LTI observability rank in straight and level flight at the Table 1 attitude: code and "
        "$\\delta$ range alone never reach 17 (heading and z-gyro bias are unobservable); with Euler "
        "attitude or DD phases the rank is 17 for $\\nu \\ge 4$.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-sec3.4-sequential-update",
        aliases=("KZL-c14-sequential",),
        locator="Sec. 3.4",
        quantity="sequential processing gives the batch update without inverting the full innovation matrix",
        published=True,
        unit="statement",
        compute=_sequential_equals_batch,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Equal posteriors for 8 satellites with DD rows, provided the correlated DD phases are "
        "whitened (Cholesky) first; the paper does not mention the correlation. The computation reads "
        "published inputs only (the whitening is part of the method).",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-eq13-R",
        locator="Eq. (13), block R",
        quantity="the block R of Eq. (13), body-axes rates to Euler-angle rates, is the Jacobian of the "
        "Euler angles with respect to the n-frame attitude error (at the Table 1 attitude)",
        published=True,
        unit="statement",
        kind="statement",
        compute=printed_R_is_euler_jacobian,
        tolerance=EXACT,
        expected_status="discrepant",
        note="At heading 90 deg the true block is $J_b^{-1} R_n^b$, a north/east swap of $J_b^{-1} = I$: "
        "entries differ by 1. The paper describes R in words and prints no number from it. Checked "
        "independently by central differences of the Euler angles.",
        erratum="KZL-E4-euler-rows",
        oracle=_printed_R_oracle,
        oracle_tolerance=EXACT,
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-qcorr",
        locator="Sec. 3.5",
        quantity="the printed correction $q^+ = q^- \\otimes q^n$ (right product) removes an estimated "
        "n-frame attitude error",
        published=True,
        unit="statement",
        kind="statement",
        compute=printed_correction_removes_error,
        tolerance=EXACT,
        expected_status="discrepant",
        note="Tried with an estimated (1, -0.5, 2) deg n-frame error at the Table 1 attitude (any error "
        "not about the vertical shows it): the right product leaves 1.58 deg, the left product nothing. "
        "Eq. (9) fixes the convention (Hamilton products, body rates on the right). Checked "
        "independently with scipy's Rotation.",
        erratum="KZL-E6-quaternion-order",
        oracle=_printed_correction_oracle_removes,
        oracle_tolerance=EXACT,
        discussed_in=PAGE2,
    ),
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
    ),
    Claim(
        id="KZL-sec2.1-four-measurements",
        aliases=("KZL-c7",),
        locator="Sec. 2.1",
        quantity="four or more simultaneous measurements are needed for 3-D position and clock bias",
        published=True,
        unit="statement",
        compute=_geometry_rank_is_min_nu_4,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Rank of the pseudorange geometry matrix $[-l^T\\ 1]$ is $\\min(\\nu, 4)$ for the first $\\nu$ "
        "satellites of the simulation's sky.",
        discussed_in=PAGE2,
    ),
    Claim(
        id="KZL-sec3.5-small-rotation-euler-angles",
        aliases=("KZL-c15",),
        locator="Sec. 3.5",
        quantity="for a small rotation there is approximately no difference between the components of its "
        "rotation vector and its Euler angles (the Jacobian at the identity is I)",
        published=True,
        unit="statement",
        kind="statement",
        compute=_small_rotation_same,
        tolerance=EXACT,
        expected_status="reproduced",
        note="The derivative of the Euler angles (roll, pitch, heading) of a rotation with respect to its "
        "rotation vector is the identity at zero rotation: the two agree to first order (the rotation "
        "vector (1, -0.5, 2) deg has Euler angles (0.991, -0.517, 1.996) deg). This is the small error "
        "rotation of Sec. 3.5 itself; the vehicle's Euler angles at heading 90 deg are another matter, "
        "the block R of Eq. (13) (KZL-E4).",
        discussed_in=PAGE2,
    ),
]

CLAIMS = quoted(CLAIMS)
