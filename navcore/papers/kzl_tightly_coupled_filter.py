"""KZL Secs. 3.3-3.5: the 17-state error model (Eqs. 10-11), the observation models with
redundant attitude and double-differenced carrier phases (Eqs. 12-17), sequential processing and
the attitude correction: their claims, errata and computes.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
from scipy.spatial.transform import Rotation

from navcore.claims import EXACT, Claim, Erratum, input_cache, with_quotes
from navcore.estimation import kf_update
from navcore.frames import dcm_from_quat, euler_from_dcm, quat_from_dcm, skew
from navcore.gnss.carrier_phase import dd_covariance, euler_rate_matrix_body
from navcore.inertial.error_model17 import (
    ERROR_LAYOUT_17,
    code_doppler_rows,
    error_dynamics_17,
    observability_rank,
)
from navcore.integration.ekf_ins_gnss import correct_attitude, sequential_scalar_updates
from navcore.integration.measurement_rows import (
    attitude_observation_rows_count,
    dd_observation_rows_count,
    euler_attitude_rows,
    tc_attitude_observation_matrix,
    tc_dd_observation_matrix,
)
from navcore.papers.kzl_quotes import QUOTES
from navcore.papers.kzl_scenario import IN as SCEN
from navcore.papers.kzl_scenario import table1_attitude, table1_baselines_b, table1_los
from navcore.units import DEG, G0, GPS_L1_WAVELENGTH_M

PAGE2 = "kzl/02-error-model"


# --- Eqs. (10)-(11): the error model ---------------------------------------------------------
def table1_F() -> np.ndarray:
    C = table1_attitude()
    return error_dynamics_17(C, np.array([0.0, 0.0, -G0]))


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


# --- Eqs. (12)-(17): the observation models, and observability -------------------------------
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


def _row_counts_eq13() -> bool:
    return all(attitude_observation_rows_count(nu) == 3 + 2 * nu for nu in range(1, 9))


def _row_counts_eq17() -> bool:
    nb = len(table1_baselines_b())  # Table 1's 3 antennas: two baselines from the master
    return all(dd_observation_rows_count(nu, nb) == 2 + 4 * (nu - 1) for nu in range(1, 9))


def _eq15_holds() -> bool:
    """The two groupings of Eq. (15) agree over 1000 random range sets: their largest difference
    (rad) relative to the largest double difference, below 1e-6 (floating point on 2e7 m ranges)."""
    rng = np.random.default_rng(15)
    rho = rng.uniform(2.0e7, 2.6e7, size=(1000, 2, 2))  # [antenna A0/A1, satellite m/n]
    k = 2 * np.pi / GPS_L1_WAVELENGTH_M
    first = k * ((rho[:, 1, 1] - rho[:, 1, 0]) - (rho[:, 0, 1] - rho[:, 0, 0]))
    second = k * ((rho[:, 1, 1] - rho[:, 0, 1]) - (rho[:, 1, 0] - rho[:, 0, 0]))
    return float(np.max(np.abs(first - second)) / np.max(np.abs(first))) < 1e-6


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


# --- Secs. 3.4-3.5: sequential processing and the correction step ---------------------------
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


def _small_rotation_same() -> bool:
    """The largest entry of d(roll, pitch, heading)/d(rotation vector) - I of a small rotation (the
    Jacobian at the identity: the rotation vector and the Euler angles of the rotation itself) is
    below 1e-9: the Jacobian is exactly I, to round-off."""
    return float(np.max(np.abs(euler_attitude_rows(np.eye(3), 0.0, 0.0)[:, 6:9] - np.eye(3)))) < 1e-9


# --- errata -----------------------------------------------------------------------------------
ERRATA = [
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
    Claim.statement(
        id="KZL-dim13",
        locator="Sec. 3.4, after Eq. (13)",
        quantity="rows of the observation matrix with redundant attitude = $3 + 2\\nu$ ($\\nu$ = 1..8)",
        compute=_row_counts_eq13,
        note="Counted from the stacked measurement matrix built by the carrier-phase model.",
        discussed_in=PAGE2,
    ),
    Claim.statement(
        id="KZL-dim17",
        locator="Sec. 3.4, before Eq. (17)",
        quantity="rows of the DD observation matrix = $2 + 4 (\\nu - 1)$ ($\\nu$ = 1..8)",
        compute=_row_counts_eq17,
        note="Code and $\\delta$ range per satellite plus two DDs (baselines $A_0$-$A_1$, $A_0$-$A_2$) per "
        "non-master "
        "satellite. Eq. (14) as printed has 7 rows for $\\nu = 2$ (a duplicated row); the formula gives 6.",
        discussed_in=PAGE2,
        table="state-dimensions",
    ),
    Claim.statement(
        id="KZL-sec3.4-sequential-update",
        aliases=("KZL-c14-sequential",),
        locator="Sec. 3.4",
        quantity="sequential processing gives the batch update without inverting the full innovation matrix",
        compute=_sequential_equals_batch,
        note="Equal posteriors for 8 satellites with DD rows, provided the correlated DD phases are "
        "whitened (Cholesky) first; the paper does not mention the correlation. The computation reads "
        "published inputs only (the whitening is part of the method).",
        discussed_in=PAGE2,
        table="sequential-update",
    ),
    Claim.statement(
        id="KZL-eq13-R",
        locator="Eq. (13), block R",
        quantity="the block R of Eq. (13), body-axes rates to Euler-angle rates, is the Jacobian of the "
        "Euler angles with respect to the n-frame attitude error (at the Table 1 attitude)",
        compute=printed_R_is_euler_jacobian,
        expected_status="discrepant",
        note="At heading 90 deg the true block is $J_b^{-1} R_n^b$, a north/east swap of $J_b^{-1} = I$: "
        "entries differ by 1. The paper describes R in words and prints no number from it. Checked "
        "independently by central differences of the Euler angles.",
        erratum="KZL-E4-euler-rows",
        oracle=_printed_R_oracle,
        oracle_tolerance=EXACT,
        discussed_in=PAGE2,
    ),
    Claim.statement(
        id="KZL-qcorr",
        locator="Sec. 3.5",
        quantity="the printed correction $q^+ = q^- \\otimes q^n$ (right product) removes an estimated "
        "n-frame attitude error",
        compute=printed_correction_removes_error,
        expected_status="discrepant",
        note="Tried with an estimated (1, -0.5, 2) deg n-frame error at the Table 1 attitude (any error "
        "not about the vertical shows it): the right product leaves 1.58 deg, the left product nothing. "
        "Eq. (9) fixes the convention (Hamilton products, body rates on the right). Checked "
        "independently with scipy's Rotation.",
        erratum="KZL-E6-quaternion-order",
        oracle=_printed_correction_oracle_removes,
        oracle_tolerance=EXACT,
        discussed_in=PAGE2,
        table="sequential-update",
    ),
    Claim.statement(
        id="KZL-sec3.5-small-rotation-euler-angles",
        aliases=("KZL-c15",),
        locator="Sec. 3.5",
        quantity="for a small rotation there is approximately no difference between the components of its "
        "rotation vector and its Euler angles (the Jacobian at the identity is I)",
        compute=_small_rotation_same,
        note="The derivative of the Euler angles (roll, pitch, heading) of a rotation with respect to its "
        "rotation vector is the identity at zero rotation: the two agree to first order (the rotation "
        "vector (1, -0.5, 2) deg has Euler angles (0.991, -0.517, 1.996) deg). This is the small error "
        "rotation of Sec. 3.5 itself; the vehicle's Euler angles at heading 90 deg are another matter, "
        "the block R of Eq. (13) (KZL-E4).",
        discussed_in=PAGE2,
        table="sequential-update",
    ),
    Claim.statement(
        id="KZL-eq10-11-fd",
        locator="Eqs. (10)-(11)",
        quantity="the velocity-attitude block of F (the explicit matrix of Eq. (11)) equals finite "
        "differences of the velocity-error rate",
        compute=_eq10_11_holds,
        note="Error = computed $-$ true, $\\hat R = e^{[\\Delta\\psi \\times]} R$; Table 1 attitude, "
        "specific force "
        "(0.5, -0.3, $-g$) m/s$^2$ in NED; central differences at $10^{-6}$ rad agree to $10^{-6}$ of g.",
        discussed_in=PAGE2,
    ),
    Claim.statement(
        id="KZL-eq11-bracket",
        locator="Eq. (11)",
        quantity="the explicit matrix of Eq. (11) is the cross-product matrix its bracket $[a \\times]$ "
        "names",
        compute=_eq11_is_bracket,
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
    Claim.statement(
        id="KZL-eq15-orderings",
        locator="Eq. (15)",
        quantity="the two groupings of the double difference in Eq. (15) are equal",
        compute=_eq15_holds,
        note="Between-satellite then between-antenna, or the reverse, over 1000 random range sets: equal to "
        "$10^{-6}$ relative (floating point on $2 \\times 10^{7}$ m ranges).",
        discussed_in=PAGE2,
    ),
    Claim.statement(
        id="KZL-eq17-printed-rank",
        locator="Eq. (17)",
        quantity="the two DD attitude rows of Eq. (17) as printed (both rows with $l_{02}$) are two "
        "independent observations of one satellite pair, as two baselines should give",
        compute=_eq17_printed_two_rows,
        expected_status="discrepant",
        erratum="KZL-E5-dd-typos",
        oracle=_eq17_oracle,
        oracle_tolerance=EXACT,
        note="Table 1 sky, first two satellites, 2 m baselines along body x and y. With $l_{02}$ twice the "
        "rows coincide (rank 1); with $l_{01}$ and $l_{02}$ the rank is 2 (KZL-eq17-rank). No printed "
        "number depends on it.",
        discussed_in=PAGE2,
        table="jacobian-checks",
    ),
    Claim.statement(
        id="KZL-eq17-rank",
        locator="Eq. (17)",
        quantity="the DD attitude rows with $l_{01}$ and $l_{02}$ (corrected Eq. (17)) are two independent "
        "observations",
        compute=_eq17_corrected_two_rows,
        note="Two satellites give two independent attitude observations, as Sec. 3.6 relies on.",
        discussed_in=PAGE2,
        table="jacobian-checks",
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
