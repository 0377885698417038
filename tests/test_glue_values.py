"""Every number registered in navcore.glued, recomputed against an independent oracle (issue 31, item 2).

A page prints these numbers in its prose; :func:`navcore.book.glue` makes the page print what the
registered function computes, and this file checks each function against something that does
not share its code: a closed form in other arithmetic, scipy, an ODE integration, a brute-force
integral, the paper's printed formula or text, or an independent solver. Each case names its
oracle and the tolerance it allows, fixed from the oracle's own accuracy (rounding, an
asymptotic remainder, a quadrature step), never from the result. ``test_every_registration_has_an_oracle``
fails on a registered name without a case here.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np
import pytest
import scipy.constants as sc
from _oracles import irwin_hall_cdf_mpmath
from scipy import integrate, optimize, signal, stats

from navcore import glued

# Defined or conventional constants typed in here, independent of navcore.units.
_G0 = 9.80665  # standard gravity, m/s^2 (CGPM 1901)
_WGS84_A = 6_378_137.0  # WGS-84 semi-major axis, m
_GM = 3.986004418e14  # Earth's gravitational parameter, m^3/s^2 (WGS-84)
_SIDEREAL_DAY = 86_164.0905  # s
_F_L1 = 154 * 10_230_000  # GPS L1 carrier: 154 x the 10.23 MHz fundamental, Hz
_C = 299_792_458  # speed of light, m/s (by definition)


@dataclass(frozen=True)
class Oracle:
    """An oracle for one glued name: the expected value and the tolerance the oracle allows."""

    name: str
    expected: Callable[[], Any]
    rtol: float = 0.0
    atol: float = 0.0
    why: str = ""
    band: Callable[[], float] | None = None  # an absolute tolerance the oracle computes (a sampling band)


def _schuler_period_min() -> float:
    """ODE oracle: integrate the Schuler pendulum theta'' = -(g/a) theta (scipy solve_ivp) and
    time two successive upward zero crossings."""
    w2 = _G0 / _WGS84_A

    def rhs(_t, y):
        return [y[1], -w2 * y[0]]

    def up(_t, y):
        return y[0]

    up.direction = 1  # type: ignore[attr-defined]
    sol = integrate.solve_ivp(
        rhs,
        (1.0, 12_000.0),
        [math.sin(math.sqrt(w2)), math.cos(math.sqrt(w2))],
        events=up,
        rtol=1e-12,
        atol=1e-14,
        method="DOP853",
    )
    t0, t1 = sol.t_events[0][:2]
    return (t1 - t0) / 60.0


def _small_alpha_coefficient() -> float:
    """Cubic oracle: the real root of psi^3 + q psi - q = 0 (ATC-10 Sec. 4.5, numpy.roots) with
    q = 27 alpha / 4, over alpha^(1/3) as alpha -> 0. The ratio is c (1 - a alpha^(1/3) + ...),
    so the values at alpha and 8 alpha extrapolate to c as 2 f(alpha) - f(8 alpha), leaving an
    O(alpha^(2/3)) remainder (1e-12 at alpha = 1e-18)."""

    def ratio(alpha: float) -> float:
        q = 27.0 * alpha / 4.0
        roots = np.roots([1.0, 0.0, q, -q])
        psi = float(next(r.real for r in roots if abs(r.imag) < 1e-9 * abs(r)))
        return psi / alpha ** (1.0 / 3.0)

    return 2.0 * ratio(1e-18) - ratio(8e-18)


def _orbit_radius_km() -> float:
    """Root-finder oracle: the radius where gravity GM/r^2 equals the centripetal w^2 r of a
    sidereal-day orbit (scipy brentq)."""
    w = 2.0 * math.pi / _SIDEREAL_DAY
    return optimize.brentq(lambda r: _GM / r**2 - w**2 * r, 1e7, 1e8, xtol=1e-6, rtol=1e-15) / 1e3


def _kzl_tilt_deg() -> float:
    """Levelling oracle: the exact tilt atan(b/g) that an accelerometer bias of b micro-g leaves
    (the bias from the KZL scenario's input, micro-g from its definition)."""
    from navcore.papers import kzl_scenario

    return math.degrees(math.atan(kzl_scenario.IN.accel_bias_micro_g * 1e-6))


def _horizontal_earth_rate_deg_h() -> float:
    """Earth rate as one turn per sidereal day, times cos(51 deg)."""
    return 360.0 / (_SIDEREAL_DAY / 3600.0) * math.cos(math.radians(51.0))


def _chi_cv_pct(dof: int) -> float:
    """Exact coefficient of variation of an RMS of ``dof`` normal samples (scipy's chi distribution)."""
    d = stats.chi(dof)
    return float(100 * d.std() / d.mean())


# KZL Eq. (1), the state vector as printed, typed in: its blocks and their components.
_KZL_EQ1_BLOCKS = {
    "position error": ("dx_n", "dx_e", "dx_d"),
    "velocity error": ("dv_n", "dv_e", "dv_d"),
    "misalignment": ("d_alpha", "d_beta", "d_gamma"),
    "accelerometer bias": ("db_ax", "db_ay", "db_az"),
    "gyroscope bias": ("db_wx", "db_wy", "db_wz"),
    "receiver clock": ("c dt_rb", "c dt_rd"),
}


def _kzl_states() -> int:
    """The components of KZL's Eq. (1) state vector, counted from the printed blocks."""
    return sum(len(block) for block in _KZL_EQ1_BLOCKS.values())


def _kzl_rows(n: int) -> int:
    """The paper's printed size: a (2 + (nu - 1) * 4) x 17 matrix for nu satellites (KZL Sec. 2.3)."""
    return 2 + (n - 1) * 4


# --- KZL Sec. 1-2 ------------------------------------------------------------------------------
_OMEGA_E = 7.292115e-5  # WGS-84 Earth rotation rate, rad/s (defined)
_WGS84_F = 1 / 298.257223563  # WGS-84 flattening (defined)
_ARCSEC_PER_RAD = 180 * 3600 / math.pi


def _kzl_in(module: str, name: str = "IN") -> Any:
    import importlib

    return getattr(importlib.import_module(f"navcore.papers.{module}"), name)


def _kzl00_overlap_s() -> float:
    """Kepler oracle: the satellite's angular rate sqrt(GM / r^3) times the Earth's radius is its
    ground-track speed; the footprint over that speed less the aircraft's."""
    m, c = _kzl_in("kzl_requirements"), _kzl_in("kzl_requirements", "IN_COVERAGE")
    r = m.earth_radius_m + m.terrasar_altitude_km * 1e3
    ground = math.sqrt(m.gm_m3_s2 / r**3) * m.earth_radius_m
    return c.receiver_footprint_km * 1e3 / (ground - m.aircraft_speed_mps)


def _kzl00_pointing_shift_m() -> float:
    """Vector oracle: the beam at the look angle from the Table 1 height, turned by the pointing
    error about the along-track axis (scipy's Rotation), meets the plane normal to the original
    beam at the slant range; the distance between the two points there."""
    from scipy.spatial.transform import Rotation

    m, c, s = _kzl_in("kzl_requirements"), _kzl_in("kzl_requirements", "IN_COVERAGE"), _kzl_in("kzl_scenario")
    look = math.radians(c.look_angle_deg)
    beam = np.array([0.0, math.sin(look), -math.cos(look)])  # x along track, z up
    slant = s.height_m / math.cos(look)
    turned = Rotation.from_euler("x", m.pointing_error_deg, degrees=True).apply(beam)
    hit = turned * slant / float(turned @ beam)  # on the plane {x : x . beam = slant}
    return float(np.linalg.norm(hit - slant * beam))


def _kzl00_baseline_arcsec() -> float:
    """InSAR oracle: height h = H - R cos(theta) with R sin(theta) fixed by the baseline tilt, so a
    tilt d alpha moves the height by R sin(theta) d alpha (differentiated numerically here by a
    central difference of the flat-earth geometry); the tilt giving 1 m, in arcsec."""
    m, c = _kzl_in("kzl_requirements"), _kzl_in("kzl_requirements", "IN_COVERAGE")
    H, th = m.terrasar_altitude_km * 1e3, math.radians(c.look_angle_deg)
    R = H / math.cos(th)

    def height(theta: float) -> float:
        return H - R * math.cos(theta)

    eps = 1e-6
    dh_dtheta = (height(th + eps) - height(th - eps)) / (2 * eps)
    return _ARCSEC_PER_RAD / dh_dtheta


def _kzl00_baseline_mm() -> float:
    """InSAR oracle: the interferometric phase of a perpendicular baseline B sees a height change
    dh as a look-angle change dh / (R sin theta), and a baseline length error dB as dB / (B tan
    theta); equal for 1 m: dB = B / (R sin theta tan theta), flat earth, in mm."""
    m, c = _kzl_in("kzl_requirements"), _kzl_in("kzl_requirements", "IN_COVERAGE")
    th = math.radians(c.look_angle_deg)
    R = m.terrasar_altitude_km * 1e3 / math.cos(th)
    return 1e3 * c.perp_baseline_m / (R * math.sin(th) * math.tan(th))


def _kzl00_correlation_10s() -> float:
    """Quadrature oracle: the normalised autocorrelation of white noise through the impulse
    response exp(-t / tau), integral of h(t) h(t + 10) over that of h^2 (scipy quad)."""
    tau = _kzl_in("kzl_requirements", "IN_COVERAGE").receiver_filter_tau_s
    num = integrate.quad(lambda t: math.exp(-t / tau) * math.exp(-(t + 10.0) / tau), 0, math.inf)[0]
    den = integrate.quad(lambda t: math.exp(-2 * t / tau), 0, math.inf)[0]
    return num / den


def _kzl_frame_rates(lat_deg: float, h: float, v_east: float) -> tuple[np.ndarray, np.ndarray]:
    """Earth rate and transport rate in NED for an eastward velocity: Omega (cos L, 0, -sin L) and
    v_e / (N + h) (1, 0, -tan L), N the WGS-84 prime-vertical radius (Titterton & Weston
    Eq. 3.61)."""
    L = math.radians(lat_deg)
    e2 = _WGS84_F * (2 - _WGS84_F)
    N = _WGS84_A / math.sqrt(1 - e2 * math.sin(L) ** 2)
    earth = _OMEGA_E * np.array([math.cos(L), 0.0, -math.sin(L)])
    return earth, v_east / (N + h) * np.array([1.0, 0.0, -math.tan(L)])


def _kzl01_neglected_rates_deg_h() -> float:
    s = _kzl_in("kzl_scenario")
    wie, wen = _kzl_frame_rates(s.lat_deg, s.height_m, s.velocity_east_mps)
    return float(np.linalg.norm(wie + wen)) * 180 / math.pi * 3600


def _kzl01_neglected_coriolis_micro_g() -> float:
    s = _kzl_in("kzl_scenario")
    wie, wen = _kzl_frame_rates(s.lat_deg, s.height_m, s.velocity_east_mps)
    v = np.array([0.0, s.velocity_east_mps, 0.0])
    return float(np.linalg.norm(np.cross(2 * wie + wen, v))) / (1e-6 * _G0)


@functools.cache
def _kzl01_first_order(T: float) -> float:
    """Riccati oracle: the exact covariance as the solution of P' = F P + P F^T + G Q G^T over the
    180 s (scipy solve_ivp, rtol 1e-11), against the printed first-order recursion of Eq. (6),
    P <- (I + F T) P (I + F T)^T + G Q G^T T, written out here; F, G Q G^T and P0 are the model's
    (the model under test is the discretisation)."""
    from navcore.integration.ekf_ins_gnss import _gqgt, _initial_covariance
    from navcore.papers.kzl_scenario import table1_attitude, table1_scenario
    from navcore.papers.kzl_tightly_coupled_filter import table1_F

    F, C = table1_F(), table1_attitude()
    gqg = _gqgt(table1_scenario())
    P0 = _initial_covariance(table1_scenario(), C, True)
    n = F.shape[0]

    def rhs(_t, p):
        P = p.reshape(n, n)
        return (F @ P + P @ F.T + gqg).ravel()

    exact = integrate.solve_ivp(rhs, (0, 180.0), P0.ravel(), rtol=1e-11, atol=1e-14, method="DOP853")
    Pe = exact.y[:, -1].reshape(n, n)
    A = np.eye(n) + F * T
    P1 = P0.copy()
    for _ in range(round(180.0 / T)):
        P1 = A @ P1 @ A.T + gqg * T
    return 100 * (1 - math.sqrt(P1[0, 0]) / math.sqrt(Pe[0, 0]))


def _exact_rank(rows: list[list[Fraction]]) -> int:
    """Rank by Gaussian elimination in exact rational arithmetic (no threshold)."""
    m = [r[:] for r in rows]
    rank, cols = 0, len(m[0]) if m else 0
    for c in range(cols):
        piv = next((i for i in range(rank, len(m)) if m[i][c] != 0), None)
        if piv is None:
            continue
        m[rank], m[piv] = m[piv], m[rank]
        for i in range(len(m)):
            if i != rank and m[i][c] != 0:
                f = m[i][c] / m[rank][c]
                m[i] = [a - f * b for a, b in zip(m[i], m[rank], strict=True)]
        rank += 1
    return rank


def _kzl_generic_rank(mode: str, nu: int) -> int:
    """Observability rank of KZL's Eq. (10) error model, written out here in level flight at the
    Table 1 heading (Earth rate dropped, as in Eq. (9)): p' = v, v' = -[f x] psi + C b_a,
    psi' = -C b_g, biases constant, clock bias' = drift; observed by code [-l 1] and delta range
    [-l 1] (Eq. 13), plus the three attitude angles (``"tc_att"``) or the double differences
    (l_i - l_1) . (psi x C b) on the two Table 1 baselines (``"tc_dd"``). The lines of sight are
    rational, drawn at random (seeded): a generic geometry, so this is the rank the model's
    structure allows; the rank is exact (rational Gaussian elimination)."""
    from navcore.papers.kzl_scenario import table1_baselines_b

    q = Fraction
    g = q(_G0)
    C = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]  # body to NED at heading 90 deg, level
    n = 17
    F = [[q(0)] * n for _ in range(n)]
    for i in range(3):
        F[i][3 + i] = q(1)  # p' = v
        for j in range(3):
            F[3 + i][9 + j] = q(C[i][j])  # v' += C b_a
            F[6 + i][12 + j] = -q(C[i][j])  # psi' = -C b_g
    fx = [[0, g, 0], [-g, 0, 0], [0, 0, 0]]  # [f x] for f = (0, 0, -g)
    for i in range(3):
        for j in range(3):
            F[3 + i][6 + j] = -fx[i][j]
    F[15][16] = q(1)
    rng = np.random.default_rng(1)
    los = [[q(int(x), 97) for x in rng.integers(-97, 98, 3)] for _ in range(nu)]
    H: list[list[Fraction]] = []
    for l in los:
        H.append([-a for a in l] + [q(0)] * 12 + [q(1), q(0)])
        H.append([q(0)] * 3 + [-a for a in l] + [q(0)] * 9 + [q(0), q(1)])
    if mode == "tc_att":
        for i in range(3):
            H.append([q(0)] * 6 + [q(int(i == j)) for j in range(3)] + [q(0)] * 8)
    elif mode == "tc_dd":
        for b in table1_baselines_b():
            cb = [sum(q(C[i][k]) * q(float(b[k])) for k in range(3)) for i in range(3)]
            for l in los[1:]:
                d = [l[i] - los[0][i] for i in range(3)]
                # d . (psi x cb) = psi . (cb x d)
                row = [cb[1] * d[2] - cb[2] * d[1], cb[2] * d[0] - cb[0] * d[2], cb[0] * d[1] - cb[1] * d[0]]
                H.append([q(0)] * 6 + row + [q(0)] * 8)
    blocks, Hk = [], H
    for _ in range(4):  # F^4 = 0
        blocks += Hk
        Hk = [[sum(r[k] * F[k][j] for k in range(n) if r[k] != 0) for j in range(n)] for r in Hk]
    return _exact_rank(blocks)


def _kzl02_full_rank_from_nu() -> int:
    return max(
        min(nu for nu in range(1, 9) if _kzl_generic_rank(mode, nu) == 17) for mode in ("tc_att", "tc_dd")
    )


# --- KZL Sec. 3.6: the simulation page --------------------------------------------------------
# The book's visibility schedule as its prose gives it: 8 satellites for 60 s, then 4, 3 and 2
# for 30 s each, then 5, at 1 Hz; the first epoch (the initial state) is left out.
_KZL_SEGMENT_EPOCHS = {
    8: range(1, 60),
    4: range(60, 90),
    3: range(90, 120),
    2: range(120, 150),
    5: range(150, 181),
}


def _kzl_table1_gyro() -> tuple[float, float, float, float, float]:
    """Gyro bias (deg/s), angle random walk (deg/sqrt(s)), initial heading sigma (deg), flight
    duration (s) and calibration time (s) from the KZL inputs, converted by hand (deg/h / 3600;
    deg/h/sqrt(Hz) = deg sqrt(s) / h, also / 3600)."""
    sc = _kzl_in("kzl_scenario")
    bias_deg_h, arw_deg_h_rthz = sc.gyro_bias_arw
    return bias_deg_h / 3600, arw_deg_h_rthz / 3600, sc.crab_angle_deg, sc.duration_s, sc.init_time_s


def _kzl_arw_position_km() -> float:
    """Quadrature oracle: the position error of a random-walk tilt is g N int_0^t (t - s)^2 / 2
    dW(s), whose variance is g^2 N^2 int_0^t (t - s)^4 / 4 ds (scipy quad)."""
    _, n, _, t, _ = _kzl_table1_gyro()
    var = integrate.quad(lambda s: (t - s) ** 4 / 4, 0, t)[0]
    return _G0 * math.radians(n) * math.sqrt(var) / 1e3


def _kzl_closed_heading_deg(calibrated: bool) -> float:
    """sqrt((b t)^2 + N^2 t + sigma0^2) in degrees, b the raw bias or N / sqrt(T_init)."""
    b, n, s0, t, t_init = _kzl_table1_gyro()
    if calibrated:
        b = n / math.sqrt(t_init)
    return math.sqrt((b * t) ** 2 + n**2 * t + s0**2)


def _kzl_runs_arrays(mode: str, initialise: bool = True) -> Any:
    from navcore.papers.kzl_scenario import monte_carlo

    return monte_carlo(mode, initialise)


def _kzl_rms_deg(err: np.ndarray, epochs: Any, col: int) -> np.ndarray:
    """RMS over runs written out: the root of the sum of squares over the runs' axis divided by
    the number of runs, per epoch, in degrees."""
    e = np.asarray(err)[:, list(epochs), col]
    return np.degrees(np.sqrt(np.einsum("rk,rk->k", e, e) / e.shape[0]))


def _kzl_segment_mean_deg(mode: str, col: int, counts: tuple[int, ...]) -> float:
    epochs = [k for n in counts for k in _KZL_SEGMENT_EPOCHS[n]]
    return float(np.mean(_kzl_rms_deg(_kzl_runs_arrays(mode).att_err, epochs, col)))


def _kzl_share_beyond_20deg() -> float:
    e = _kzl_runs_arrays("ins", False).att_err
    return sum(abs(float(e[r, 180, 2])) > math.radians(20.0) for r in range(e.shape[0])) / e.shape[0]


def _kzl_raw_att_deg() -> list[float]:
    e = _kzl_runs_arrays("ins", False).att_err
    return [float(_kzl_rms_deg(e, [180], c)[0]) for c in range(3)]


def _kzl_horizontal_rms(name: str, epoch: int) -> float:
    e = getattr(_kzl_runs_arrays("tc"), name)
    return math.sqrt(
        sum(float(e[r, epoch, 0]) ** 2 + float(e[r, epoch, 1]) ** 2 for r in range(e.shape[0])) / e.shape[0]
    )


def _kzl_removed(kind: str) -> float:
    """1 - (TC's time average over the flight) / (the stand-alone INS's), of the heading RMS or of
    the root sum square of the three angles' RMS, by hand from the run arrays."""
    epochs = range(1, 181)

    def average(mode: str) -> float:
        e = _kzl_runs_arrays(mode).att_err
        if kind == "heading":
            return float(np.mean(_kzl_rms_deg(e, epochs, 2)))
        per_axis = [_kzl_rms_deg(e, epochs, c) for c in range(3)]
        return float(np.mean(np.sqrt(sum(a**2 for a in per_axis))))

    return 1 - average("tc") / average("ins")


def _kzl_l1_wavelength() -> float:
    return _C / _F_L1


def _kzl_qcorr_residual_deg() -> float:
    """scipy Rotation oracle: the estimate R_hat = Exp(dpsi) R (an n-frame error), corrected on
    the body side as the printed right-hand product R_hat Exp(-dpsi); its angle to R."""
    from scipy.spatial.transform import Rotation

    from navcore.papers.kzl_tightly_coupled_filter import QCORR_DPSI

    R = Rotation.from_euler("ZYX", [90.0, 0.0, 0.0], degrees=True)  # Table 1: level, heading 90
    R_hat = Rotation.from_rotvec(QCORR_DPSI) * R
    corrected = R_hat * Rotation.from_rotvec(-QCORR_DPSI)
    return float(np.degrees((corrected * R.inv()).magnitude()))


def _kzl_dd_rank(printed: bool) -> int:
    """Exact rank of the two DD attitude rows (l_1 - l_2) x (C b) of Eq. (17), both with the
    y baseline as printed or with the x and y baselines, Table 1 heading 90 deg (C typed in)."""
    from navcore.papers.kzl_scenario import table1_los

    b = Fraction(_kzl_in("kzl_scenario").baseline_m)
    los = table1_los(2)
    d = [Fraction(float(los[0, i] - los[1, i])) for i in range(3)]
    C = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    rows = []
    for body in ([0, b, 0], [0, b, 0]) if printed else ([b, 0, 0], [0, b, 0]):
        v = [sum(C[i][k] * body[k] for k in range(3)) for i in range(3)]
        rows.append([d[1] * v[2] - d[2] * v[1], d[2] * v[0] - d[0] * v[2], d[0] * v[1] - d[1] * v[0]])
    return _exact_rank(rows)


def _kzl_crossover_s() -> float:
    """brentq oracle: the calibration time T at which (N / sqrt(T)) t equals the floor."""
    _, n, s0, t, _ = _kzl_table1_gyro()
    floor = math.sqrt(n**2 * t + s0**2)
    return optimize.brentq(lambda T: n / math.sqrt(T) * t - floor, 1.0, 1e6, xtol=1e-12, rtol=1e-15)


def _kzl_gain_closed() -> tuple[float, float]:
    """The heading after 180 s with 300 s and with 1200 s of calibration, closed form (deg)."""
    _, n, s0, t, _ = _kzl_table1_gyro()
    h = [math.sqrt((n / math.sqrt(T) * t) ** 2 + n**2 * t + s0**2) for T in (300.0, 1200.0)]
    return h[0], h[1]


# --- SP Sec. 2.5: the third-order loop, simulated with scipy ------------------------------------
# The loop's error transfer s^3 / D(s), D = (s + w)(s^2 + w s + w^2) = s^3 + 2 w s^2 + 2 w^2 s + w^3
# (the roots the page's jerk response shows): the error to an input whose jerk is j(t) is j
# filtered by 1 / D; a step of acceleration A is a jerk impulse of area A.


def _sp_in(module: str) -> Any:
    import importlib

    return importlib.import_module(f"navcore.papers.{module}").IN


def _sp_loop_peak(w: float, jerk: str = "step") -> float:
    """Peak error (m) for the 6-g step (``"step"``) or the 10 g/s jerk held 0.6 s (``"jerk"``),
    scipy's impulse / lsim on a grid of 5e-4 / w (the peak sampled to ~(5e-4)^2, 3e-7 relative)."""
    p = _sp_in("sp_tracking")
    den = [1.0, 2 * w, 2 * w**2, w**3]
    t = np.linspace(0.0, 30.0 / w, 60_001)
    if jerk == "step":
        _, y = signal.impulse(([p.step_g * _G0], den), T=t)
    else:
        j = np.where(t < p.jerk_duration_s, p.jerk_g_per_s * _G0, 0.0)
        _, y, _ = signal.lsim(([1.0], den), j, t)
    return float(np.max(y))


def _sp02_l1_w0() -> float:
    """The peak scales as 1 / w^2 (the impulse response of 1 / D at w is w^-2 h_1(w t)): the w
    holding the L1 peak at 90 deg from the peak at w = 1."""
    p = _sp_in("sp_tracking")
    peak_deg_at_1 = _sp_loop_peak(1.0) * 360 / (_C / _F_L1)
    return math.sqrt(peak_deg_at_1 / p.peak_limit_deg)


# --- SP Sec. 2.6: Table 2.6 column 2 against Table 2.5, typed in as printed ---------------------
_SP_TAB26_COL2_PPM = (1880.0, 431.0, 311.0, 225.0)  # grades 10, 1, 0.5, 0.2 nmi/h
_SP_TAB25_SF_PPM = (223.0, 179.0, 90.0, 21.0)
_SP_TAB25_MIS_ARCSEC = (22.0, 3.0, 1.5, 0.4)


def _sp03_n_above_monte_carlo() -> int:
    """Seeded Monte Carlo oracle: draw the six a-priori errors (scale factors and misalignments,
    Table 2.5 per grade), map them through the printed 3x6 sensitivity at a = (1, 1, 1), and take
    the 90 % quantile of the error's length (200 000 draws: the quantile's sampling error is
    ~0.3 %, and the four ratios are compared with 1)."""
    from navcore.papers import sp_residual_acceleration as spr

    H = np.array(spr.IN.printed_h, dtype=float)
    rng = np.random.default_rng(20261205)
    z = rng.standard_normal((200_000, 6))
    above = 0
    for col2, sf, mis in zip(_SP_TAB26_COL2_PPM, _SP_TAB25_SF_PPM, _SP_TAB25_MIS_ARCSEC, strict=True):
        sig = np.array([sf * 1e-6] * 3 + [mis * math.pi / 648_000] * 3)
        r90 = float(np.quantile(np.linalg.norm((z * sig) @ H.T, axis=1), 0.9)) * 1e6
        assert abs(col2 / r90 - 1) > 0.03, "a ratio within the sampling band of 1: the count is not decided"
        above += col2 > r90
    return above


# --- SP Sec. 2.5-2.6: Table 2.7 typed in as printed (code-phase intervals per satellite) ---------
_SP_TAB27 = {
    "TC 10": (73, 64, 70, 42, 82, 70, 43),
    "LC 1.0": (8, 8, 8, 6, 9, 8, 6),
    "TC 1.0": (7, 6, 6, 5, 7, 6, 5),
    "TC 0.5": (6, 6, 6, 5, 6, 6, 5),
    "TC 0.2": (6, 5, 6, 5, 6, 5, 5),
}
_SP_DWELL_S, _SP_RANGE_CELL_M = 0.020, 30.0  # Sec. 2.5: 20 ms per 30 m code-phase interval


def _sp05_heading_for_ratio(ratio: float) -> float:
    """brentq oracle: the heading error (mrad) at which hypot(pos, psi L) = ratio * pos, with the
    1 nmi/h helicopter's printed error and the printed target range."""
    from navcore.papers import sp_acquisition as spa

    pos, L = spa.IN.helicopter_error_1nmi_m, spa.IN.target_range_m
    return 1e3 * optimize.brentq(lambda psi: math.hypot(pos, psi * L) - ratio * pos, 0.0, 1.0, xtol=1e-15)


# --- SP Sec. 3: the spectral-separation factor in closed form ------------------------------------


def _sp06_q(bandwidth_hz: float) -> float:
    """Q = 1 / (R_c kappa), kappa the BPSK spectrum Tc sinc^2(f Tc) averaged over the jammer's band
    B: the integral over +-B/2 by adaptive quadrature (scipy's quad; the library uses the closed
    form with the sine integral, so the oracle integrates instead)."""
    from scipy.integrate import quad

    rc = _sp_in("sp_antijam").chip_rate_hz
    half = bandwidth_hz / 2
    frac, _ = quad(lambda f: np.sinc(f / rc) ** 2 / rc, -half, half, limit=400, points=[0.0], epsabs=0.0)
    return 1 / (rc * frac / bandwidth_hz)


def _sp06_threshold(js_db: float) -> float:
    """(C/N0)_eff = [1 / (C/N0) + (J/S) / (Q R_c)]^-1 (SP Sec. 3.1) in linear arithmetic, dB-Hz."""
    a = _sp_in("sp_antijam")
    cn0 = 10 ** ((a.signal_dbw - a.noise_density_dbw_hz) / 10)
    eff = 1 / (1 / cn0 + 10 ** (js_db / 10) / (_sp06_q(a.wideband_hz) * a.chip_rate_hz))
    return 10 * math.log10(eff)


# --- SP Sec. 2.6: the error budget ---------------------------------------------------------------


def _cep_by_quadrature(P: np.ndarray) -> float:
    """CEP of N(0, P) in 2-D: P(|x| < r) = 1 / (2 pi sqrt(l1 l2)) int_0^2pi (1 - exp(-r^2 a / 2)) / a
    dtheta with a(theta) = cos^2 / l1 + sin^2 / l2 (the radial integral done by hand, the angular
    one by scipy quad), solved for 1/2 by brentq."""
    l1, l2 = np.linalg.eigvalsh(P)

    def inside(r: float) -> float:
        def f(th: float) -> float:
            a = math.cos(th) ** 2 / l1 + math.sin(th) ** 2 / l2
            return -math.expm1(-(r**2) * a / 2) / a

        # a quarter turn by symmetry; the integrand peaks at the ends for an elongated ellipse
        quarter = integrate.quad(f, 0, math.pi / 2, epsabs=0.0, epsrel=1e-12, limit=500)[0]
        return 4 * quarter / (2 * math.pi * math.sqrt(l1 * l2))

    s = math.sqrt(l1 + l2)
    return optimize.brentq(lambda r: inside(r) - 0.5, 1e-6 * s, 10 * s, xtol=1e-12 * s)


def _sp20_rss_over_cep_max_pct() -> float:
    """The 1-h covariances are the model's; the CEP by quadrature and the rss by hand."""
    covs = glued._sp20_hour_horizontal_covariances()
    return 100 * (max(math.sqrt(P[0, 0] + P[1, 1]) / _cep_by_quadrature(P) for P in covs) - 1)


# --- SP Sec. 2.6.2: the jammer flyby ------------------------------------------------------------
_EARTH_MEAN_RADIUS = 6_371_000.0  # m, the round mean radius the flyby's propagation model states


def _sp22_lc_jitter_dbhz() -> float:
    """brentq oracle on the thermal-jitter rule of thumb (Kaplan & Hegarty Sec. 5.6.2),
    sigma = (180 / pi) sqrt(B_n / x (1 + 1 / (2 T x))) deg, for k sigma = the phase limit."""
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_scenario_wiring as sc

    bn = fb.carrier_loop(sc.SYSTEMS[0]).bandwidth_hz
    a = fb.IN

    def excess(db: float) -> float:
        x = 10 ** (db / 10)
        sigma = math.degrees(math.sqrt(bn / x * (1 + 1 / (2 * a.coherent_s * x))))
        return a.jitter_k_sigma * sigma - a.max_phase_error_deg

    return optimize.brentq(excess, 0.0, 60.0, xtol=1e-12)


def _sp22_horizon_exact() -> tuple[float, float]:
    """Tangent distance from height h to a sphere of radius R' = 4/3 R, sqrt((R' + h)^2 - R'^2), km,
    and the relative size h / (2 R') of the h^2 term the function's sqrt(2 R' h) drops."""
    h = _sp_in("sp_scenario_wiring").cruise_altitude_m
    r = 4 / 3 * _EARTH_MEAN_RADIUS
    return math.sqrt((r + h) ** 2 - r**2) / 1e3, h / (2 * r)


def _sp22_range_min_km() -> float:
    """The jammer abeam the straight cruise at the closest-approach time: hypot(cross-track
    offset, cruise altitude - jammer height), km."""
    fb = _sp_in("sp_flyby")
    return (
        math.hypot(
            fb.jammer_offset_km * 1e3, _sp_in("sp_scenario_wiring").cruise_altitude_m - fb.jammer_height_m
        )
        / 1e3
    )


def _wf05_location_rms_by_hand(case: str) -> float:
    """Horizontal location RMS over the seeded flights, from the returned per-flight errors: the
    root of the mean over flights of north^2 + east^2, written out."""
    from navcore.papers import wf_example as ex

    e = ex.run()["errors"][case]
    return math.sqrt(sum(float(e[i, 0]) ** 2 + float(e[i, 1]) ** 2 for i in range(e.shape[0])) / e.shape[0])


# --- ATC-10 Sec. 3.6-3.8: the physical PSK simulation's statistics -------------------------------


def _atc10_psk_moments() -> tuple[float, float]:
    """Second and fourth moments of the simulated amplitudes, as sums written out (einsum)."""
    from navcore.papers import atc10_multiple_access as pm

    x = np.asarray(pm.psk_physical_samples(), dtype=float)
    x2 = np.einsum("i,i->", x, x) / x.size
    x4 = np.einsum("i,i,i,i->", x, x, x, x) / x.size
    return float(x2), float(x4)


def _atc10_psk_threshold() -> tuple[float, float, float]:
    """The threshold the Monte Carlo ROC picks for p_d >= 0.9 (its p_f the smallest there), with
    the Monte Carlo's p_f and p_miss standard errors at it."""
    from navcore.papers import atc10_gaussian_comparison as pm

    roc = pm.psk_roc()
    ok = np.flatnonzero(roc.p_miss <= 0.1)
    j = ok[np.argmin(roc.p_f[ok])]
    return float(roc.theta[j]), float(roc.p_f_se[j]), float(roc.p_miss_se[j])


def _atc10_psk_exact_roc(theta: float) -> tuple[float, float]:
    """Exact p_f and p_miss of the matched filter at ``theta`` by characteristic functions: the
    simulated PSK amplitudes sit on a 1e-4 lattice, so the noise sum n of N - 1 interferers, each
    overlapping with probability q = 2 tau/alpha, has the lattice law whose transform is
    ((1 - q) + q phi_C)^(N-1) (numpy's FFT on 2^18 points, +-13.1, far beyond any sum with a
    probability above 1e-30); p_f = P(n >= theta), p_miss = P(n < theta - 1) (unit peak)."""
    from navcore.papers import atc10_multiple_access as pm

    density = pm.psk_density()
    units = np.rint(np.asarray(density.values) * 1e4).astype(np.int64)
    weights = np.asarray(density.weights, dtype=float)
    size = 1 << 18
    pmf = np.zeros(size)
    np.add.at(pmf, units % size, weights / weights.sum())
    q = 2.0 * pm.IN.tau_over_alpha_sec36
    law = np.fft.ifft(((1.0 - q) + q * np.fft.fft(pmf)) ** (pm.IN.n_sec36 - 1)).real
    lattice = np.fft.fftfreq(size, d=1.0 / size)  # 0, 1, ..., -2, -1 (units of 1e-4)
    p_f = float(law[lattice >= round(theta * 1e4)].sum())
    p_miss = float(law[lattice < round((theta - 1.0) * 1e4)].sum())
    return p_f, p_miss


def _atc10_psk_pf_exact() -> float:
    """The exact p_f at the Monte Carlo's chosen threshold (:func:`_atc10_psk_exact_roc`); the
    threshold must be admissible exactly too (p_miss <= 0.1 within four Monte Carlo standard
    errors), else the Monte Carlo picked a threshold the exact ROC refuses."""
    theta, _, miss_se = _atc10_psk_threshold()
    p_f, p_miss = _atc10_psk_exact_roc(theta)
    assert p_miss <= 0.1 + 4 * miss_se, f"the exact p_miss at {theta} is {p_miss}: not p_d >= 0.9"
    return p_f


def _atc10_psk_estimate_by_hand() -> str:
    """The Monte Carlo p_f at the threshold :func:`_atc10_psk_threshold` picks, and its standard
    error, written as the book writes an estimate: Python's exponent format with the error's two
    significant digits and the estimate's digits down to the error's first, in ×10ⁿ form."""
    from navcore.papers import atc10_gaussian_comparison as pm

    theta, se, _ = _atc10_psk_threshold()
    roc = pm.psk_roc()
    p_f = float(roc.p_f[int(np.flatnonzero(roc.theta == theta)[0])])
    places = int(f"{p_f:e}".split("e")[1]) - int(f"{se:e}".split("e")[1])  # digits after the first

    def sci(x: float, decimals: int) -> str:
        mantissa, exponent = f"{x:.{decimals}e}".split("e")
        return mantissa + "×10" + str(int(exponent)).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))

    return f"{sci(p_f, max(places, 0))} ± {sci(se, 1)}"


def _atc10_psk_pf_gauss() -> float:
    """ROC_g in Gaussian noise of power P = N q b (Theorem 3.1, q = 2 tau / alpha): p_d = Q((theta -
    1) / sqrt(P)) fixes theta at p_d = 0.9, and p_f = Q(theta / sqrt(P)) (scipy's normal)."""
    from navcore.papers import atc10_multiple_access as pm

    P = pm.IN.n_sec36 * 2 * pm.IN.tau_over_alpha_sec36 * _atc10_psk_moments()[0]
    theta = 1 + math.sqrt(P) * stats.norm.isf(0.9)
    return float(stats.norm.sf(theta / math.sqrt(P)))


def _atc10_convergence_speedup() -> float:
    """The gains of (4.5.16)-(4.5.25) iterated by hand, their limit psi / beta from the real root of
    psi^3 + q psi - q = 0, q = 27 alpha / 4 (numpy.roots), alpha = (8/27) sigma0^2 beta / sigma^2;
    the steps counted to the last gain more than 10 % from the limit."""
    from navcore.papers import atc10_clock_tracking as clock
    from navcore.papers import atc10_tracking_geometry as paper

    sigma = 50.0
    out = []
    for ex in ("I", "II"):
        beta = float(paper.TABLE_4_2[ex]["beta"])
        for s0 in clock.sigma0_values():
            q = 27 / 4 * (8 / 27) * s0**2 * beta / sigma**2
            psi = float(next(r.real for r in np.roots([1.0, 0.0, q, -q]) if abs(r.imag) < 1e-9))
            limit = psi / beta
            gamma, d, last_out = 1 / beta, 0.0, 0
            for n in range(1, 3001):
                s_n = 2 * s0**2 + sigma**2 * gamma + 2 * d
                gamma = s_n / (sigma**2 + beta * s_n)
                d = (1 - gamma * beta) * (s0**2 + d)
                if abs(gamma - limit) > 0.1 * limit:
                    last_out = n
            if abs(1 / beta - limit) > 0.1 * limit or last_out > 0:
                steps = last_out + 1
                out.append((2.3 / psi - 1) / steps)
    return float(np.median(out))


def _atc10_printed_ms_factors_by_hand() -> list[float]:
    """The gains of (4.5.16)-(4.5.25) iterated by hand for N = 150 epochs (sigma = 50 ns), then the
    clock variance one epoch after the drop, v = sigma^2 gamma_N + 2 sigma0^2 + 2 d_N, and the
    mean squares sigma^2 tr3 + v S3 with the printed and the invariant S3 (the geometry's columns
    are the model's, the inputs of this arithmetic)."""
    from navcore.papers import atc10_clock_tracking as clock
    from navcore.papers import atc10_tracking_geometry as paper

    sigma, n_last = 50.0, 150
    r_fit = paper.fitted_radius_ratio()
    out = []
    for ex in ("I", "II"):
        geo = paper.table_4_2_from_geometry(ex, r_fit)
        beta = geo["beta"]
        for s0 in clock.sigma0_values():
            gamma, d = 1 / beta, 0.0
            for _ in range(n_last):
                s_n = 2 * s0**2 + sigma**2 * gamma + 2 * d
                gamma = s_n / (sigma**2 + beta * s_n)
                d = (1 - gamma * beta) * (s0**2 + d)
            v = sigma**2 * gamma + 2 * s0**2 + 2 * d
            ms = [sigma**2 * geo["trace_123"] + v * s3 for s3 in (geo["s_123_printed"], geo["s_123"])]
            out.append(ms[0] / ms[1])
    return out


@functools.cache
def _atc10_ls_position_norm() -> tuple[float, float, float, float]:
    """Least squares at n = 0 of Example I (fitted geometry): position and clock from the K ranges
    with unit lines of sight F, so the position covariance is sigma^2 (F' (I - 1 1'/K) F)^-1 (ft^2
    at the declared ft per ns). Returns the exact E||xi||^2 and the sampling standard deviation of
    its mean over the tracker's 10 000 runs, sqrt(2 sum l_i^2 / runs), and Var||xi|| from 2e6
    seeded Gaussian draws with the standard deviation of a 10 000-run sample variance,
    sqrt((m4 - v^2) / runs), m4 the fourth central moment of the norm."""
    from navcore.papers import atc10_tracking_geometry as paper

    runs = 10_000
    F = _atc10_los("I", "fit")
    K = F.shape[0]
    center = np.eye(K) - np.ones((K, K)) / K
    scale = (paper.IN.sigma_ns * paper.IN.c_ft_per_ns) ** 2
    P = scale * np.linalg.inv(F.T @ center @ F)
    lam = np.linalg.eigvalsh(P)
    mse, mse_sd = float(lam.sum()), math.sqrt(2 * float(np.sum(lam**2)) / runs)
    z = np.random.default_rng(31).standard_normal((2_000_000, 3)) * np.sqrt(lam)
    norm = np.linalg.norm(z, axis=1)
    v = float(np.var(norm))
    m4 = float(np.mean((norm - norm.mean()) ** 4))
    return mse, mse_sd, v, math.sqrt((m4 - v**2) / runs)


def _atc10_coef_se_by_hand() -> float:
    """2 L times the standard error of a mean of the squared samples, the spread written out:
    sqrt(sum (x^2 - mean)^2 / n) / sqrt(n)."""
    from navcore.papers import atc10_multiple_access as pm

    x2 = np.asarray(pm.psk_physical_samples(), dtype=float) ** 2
    dev = x2 - x2.sum() / x2.size
    return 2 * pm.IN.psk_chips * math.sqrt(float(dev @ dev) / x2.size) / math.sqrt(x2.size)


def _atc10_convexity_worst() -> float:
    """The Chernoff tilt of the two-point density +-a (a = sqrt(b), b = 1 / (3 x^2)) solves
    theta = (N - 1) q a sinh(rho a) / (1 - q + q cosh(rho a)) (the derivative of the exponent);
    u = rho a by brentq for each contour x and threshold, and the largest u (= rho sqrt(b))."""
    from navcore.papers import atc10_multiple_access as pm
    from navcore.papers import atc10_roc_bounds as roc

    n, q = pm.IN.n_sec36, 2 * pm.IN.tau_over_alpha_sec36
    worst = 0.0
    for x in roc.contours():
        a = math.sqrt(1 / (3 * x * x))
        for theta in np.linspace(0.02, 0.98, 49):

            def slope(u: float, theta: float = float(theta), a: float = a) -> float:
                return (n - 1) * q * a * math.sinh(u) / (1 - q + q * math.cosh(u)) - theta

            worst = max(worst, optimize.brentq(slope, 0.0, 60.0, xtol=1e-14, rtol=1e-14))
    return worst


def _two_point_lower_efolds() -> float:
    """The same noise: the corrected (3.5.14) written out, mu(s) = (N - 1) ln(1 - q + q cosh(s a))
    with its derivatives by hand, the tilt r1 solving mu'(r1) - sqrt(2 mu''(r1)) = theta (brentq)
    and the bound -ln 2 + mu(r1) - r1 theta - 2 r1 sqrt(2 mu''(r1)); against the exact tail by
    scipy's binomial sums."""
    power, theta, n, q = 4 / 75, 0.5, 10_000_000, 4e-5
    a = math.sqrt(power / ((n - 1) * q))

    def d(s: float) -> float:
        return 1 - q + q * math.cosh(s * a)

    def mu1(s: float) -> float:
        return (n - 1) * q * a * math.sinh(s * a) / d(s)

    def mu2(s: float) -> float:
        return (n - 1) * (q * a * a * math.cosh(s * a) / d(s) - (q * a * math.sinh(s * a) / d(s)) ** 2)

    r1 = optimize.brentq(lambda s: mu1(s) - math.sqrt(2 * mu2(s)) - theta, 0.0, 50.0 / a, xtol=1e-14)
    lower = -math.log(2) + (n - 1) * math.log1p(q * (math.cosh(r1 * a) - 1)) - r1 * theta
    lower -= 2 * r1 * math.sqrt(2 * mu2(r1))
    ks = np.arange(0, 4001)
    pk = stats.binom.pmf(ks, n - 1, q)
    j_min = np.ceil((theta / a + ks) / 2 - 1e-12)
    tail = float(np.sum(pk * stats.binom.sf(j_min - 1, ks, 0.5)))
    return math.log(tail) - lower


def _atc10_lower_gaps_by_hand() -> list[float]:
    """For the two-point density +-a of Sec. 3.6 (N = 1e5, q = 2 tau / alpha, a = 1 / (sqrt(3) x)):
    the exact tail sum_K Bin(N - 1, q)(K) P(a (2J - K) >= theta_g), J ~ Bin(K, 1/2) (scipy), at the
    exact ROC's grid point theta_g nearest to theta, and the corrected (3.5.14) at theta by hand
    (brentq's tilt), in decades."""
    from navcore.papers import atc10_gaussian_comparison as gaussian
    from navcore.papers import atc10_multiple_access as pm

    n, q = pm.IN.n_sec36, 2 * pm.IN.tau_over_alpha_sec36
    grid = np.asarray(gaussian.THETA_GRID)
    ks = np.arange(0, 200)
    pk = stats.binom.pmf(ks, n - 1, q)
    out = []
    for x in (3.0, 5.0, 6.0):
        a = 1 / (math.sqrt(3) * x)

        def d(s: float, a: float = a) -> float:
            return 1 - q + q * math.cosh(s * a)

        def mu1(s: float, a: float = a) -> float:
            return (n - 1) * q * a * math.sinh(s * a) / d(s)

        def mu2(s: float, a: float = a) -> float:
            return (n - 1) * (q * a * a * math.cosh(s * a) / d(s) - (q * a * math.sinh(s * a) / d(s)) ** 2)

        for theta in (0.3, 0.5, 0.7):
            r1 = optimize.brentq(
                lambda s, t=theta: mu1(s) - math.sqrt(2 * mu2(s)) - t, 0.0, 200.0 / a, xtol=1e-14
            )
            lower = -math.log(2) + (n - 1) * math.log1p(q * (math.cosh(r1 * a) - 1)) - r1 * theta
            lower -= 2 * r1 * math.sqrt(2 * mu2(r1))
            tg = float(grid[int(np.argmin(abs(grid - theta)))])
            j_min = np.ceil((tg / a + ks) / 2 - 1e-12)
            tail = float(np.sum(pk * stats.binom.sf(j_min - 1, ks, 0.5)))
            out.append(math.log10(tail) - lower / math.log(10))
    return out


# Rule of thumb (4) of Sec. 4.6: "from about 30 to 60 seconds" (Example I, Example II)
_ATC10_RULE4_PRINTED_S = (("I", 30.0), ("II", 60.0))


def _atc10_outage_closed_form(ex: str) -> float:
    """Rule of thumb 4 in closed form: with the steady clock variance of (4.5.27), v(m) = sigma^2
    psi / beta + sigma0^2 ((2 - psi) / psi m + m^2), the three-satellite mean square sigma^2 tr3 +
    v(m) S3 first exceeds (f sd_0)^2, sd_0^2 = sigma^2 (tr + S / beta), at the integer above the
    positive root of that quadratic in m; the outage is one epoch (1 s) less. psi is the cubic's
    root; the geometry's columns are the model's (inputs of this arithmetic)."""
    from navcore.papers import atc10_tracking_geometry as paper

    sigma, s0, f = 50.0, 5.0, paper.IN.outage_threshold_factor
    g = paper.table_4_2_from_geometry(ex, paper.fitted_radius_ratio())
    beta = g["beta"]
    psi = _psi_cubic(8 / 27 * s0**2 * beta / sigma**2)
    limit = f**2 * sigma**2 * (g["trace_all"] + g["s_all"] / beta)
    # s0^2 m^2 + s0^2 (2 - psi) / psi m + sigma^2 psi / beta - (limit - sigma^2 tr3) / S3 > 0
    A, B = s0**2, s0**2 * (2 - psi) / psi
    C = sigma**2 * psi / beta - (limit - sigma**2 * g["trace_123"]) / g["s_123"]
    root = (-B + math.sqrt(B * B - 4 * A * C)) / (2 * A)
    m_first = math.floor(root) + 1  # the first integer m beyond the root
    return float(m_first - 1) * 1.0


def test_kzl_oracles_are_the_papers_text():
    """The typed-in oracles above are what the transcription prints (where it is beside the
    checkout): "the state vector comprises 17 states" and the (2 + (nu - 1) 4) x 17 matrix."""
    from navcore.traceability import paper_text_path

    path = paper_text_path("KZL")
    if not path.exists():
        pytest.skip("the KZL transcription is not beside the checkout")
    text = path.read_text(encoding="utf-8")
    assert f"the state vector comprises {_kzl_states()} states" in text
    assert r"$(2 + (\nu - 1) \cdot 4) \times 17$ matrix" in text


def _atc10_direct_erp(k: int, p_dl: float) -> Callable[[], float]:
    """ATC-10's direct oracle: plain probabilities on a dense grid and bisection, the paper's
    numbers typed in, no model code (navcore.papers.atc10_jamming.direct_adl_erp_dbw)."""

    def f() -> float:
        from navcore.papers import atc10_system_tables as pj

        return pj.direct_adl_erp_dbw(p_dl, k)

    return f


def _per_list_q(p_dl: float, k: int) -> float:
    """Closed form of Eq. (2.4.2) at t = 0: every one of K lists is detected with probability
    q = 1 - (1 - P_DL)^(1/K), and a list is detected when all four filters are, q = p_d^4."""
    from navcore.papers import atc10_jamming as pj

    assert pj.IN.design_t == 0.0, "the closed form holds at t = 0"
    return 1.0 - (1.0 - p_dl) ** (1.0 / k)


def _overlap() -> stats.rv_discrete:
    """scipy's binomial of the other N - 1 aircraft, each overlapping with probability q = 2 tau/alpha."""
    from navcore.papers import atc10_multiple_access as pm

    return stats.binom(pm.IN.n_sec36 - 1, 2 * pm.IN.tau_over_alpha_sec36)


def _brute_zakai(code: np.ndarray, oversample: int = 200) -> float:
    """Brute force: 1 / (2 int R^2) for the unit-energy rectangular-chip waveform, R by fine-grid
    correlation (scipy.signal) and the integral by Riemann sums (unit chips)."""
    c = np.asarray(code, float)
    dt = 1.0 / oversample
    s = np.repeat(c, oversample) / math.sqrt(c.size)
    r = signal.correlate(s, s, mode="full", method="fft") * dt
    return 1.0 / (2.0 * float(np.sum(r**2) * dt))


def _msequence_1023() -> np.ndarray:
    """The page's 1023-chip m-sequence built by scipy's register: primitive polynomial
    x^10 + x^7 + 1, all-ones fill (scipy lists the feedback tap as 10 - 7), as +-1 chips. A
    different m-sequence has other aperiodic sidelobes and another Zakai bandwidth (0.18 % apart)."""
    seq, _ = signal.max_len_seq(10, state=np.ones(10), taps=[3])
    return 1.0 - 2.0 * seq.astype(float)


# ATC-10's scenario as printed, typed in: B = 10 MHz, alpha = 1 s, beta = 24 ms (Sec. 2.7),
# v = 600 mph (Sec. 2.8).
_ATC10_B, _ATC10_ALPHA, _ATC10_BETA, _ATC10_V_MPH = 10_000_000, 1, Fraction(24, 1000), 600


def _atc10_n_v() -> float:
    """(8 B / 3) v alpha / c (C.14) in miles and hours: v in miles per second over c in miles per
    second (scipy.constants' c and mile)."""
    return 8 / 3 * _ATC10_B * (_ATC10_V_MPH / 3600) * _ATC10_ALPHA / (sc.c / sc.mile)


def _kzl_dd_sigma_mm() -> float:
    """A double difference (a_i - b_i) - (a_m - b_m) sums four independent phase errors of the
    same sigma: 2 sigma (closed form), sigma the scenario's phase noise."""
    from navcore.papers.kzl_scenario import IN

    return 2 * IN.phase_noise_m * 1e3


def _kzl_gyro_residual_deg_h() -> float:
    """White rate noise of density N (deg/h/sqrt(Hz)) averaged over T seconds leaves N / sqrt(T)
    (deg/h): the Table 1 reading of N (the convention input) and the initialisation time."""
    from navcore.papers.kzl_scenario import IN

    return IN.gyro_bias_arw[1] / math.sqrt(IN.init_time_s)


_BARKER13 = np.array([1, 1, 1, 1, 1, -1, -1, 1, 1, -1, 1, -1, 1], float)

ORACLES = [
    # the quadratic's root in closed form: the same integer (exact)
    Oracle(
        "atc10-32-outage-corrected-I",
        lambda: _atc10_outage_closed_form("I"),
        rtol=1e-12,
        why="closed-form root",
    ),
    Oracle(
        "atc10-32-outage-corrected-II",
        lambda: _atc10_outage_closed_form("II"),
        rtol=1e-12,
        why="closed-form root",
    ),
    Oracle(
        "atc10-32-outage-ratio-lo",
        lambda: min(_atc10_outage_closed_form(ex) / p for ex, p in _ATC10_RULE4_PRINTED_S),
        rtol=1e-12,
        why="closed-form root over the printed outages",
    ),
    Oracle(
        "atc10-32-outage-ratio-hi",
        lambda: max(_atc10_outage_closed_form(ex) / p for ex, p in _ATC10_RULE4_PRINTED_S),
        rtol=1e-12,
        why="closed-form root over the printed outages",
    ),
    # scipy's binomial sums (K to 200, mean 4: nothing left) and brentq's tilt: 1e-6 on gaps of
    # decades
    Oracle(
        "atc10-21-lower-gap-lo",
        lambda: min(_atc10_lower_gaps_by_hand()),
        rtol=1e-6,
        why="binomial sums, bound by hand",
    ),
    Oracle(
        "atc10-21-lower-gap-hi",
        lambda: max(_atc10_lower_gaps_by_hand()),
        rtol=1e-6,
        why="binomial sums, bound by hand",
    ),
    # brentq on the tilt and scipy's binomial sums to K = 4000 (mean 400): 1e-6 on a difference of
    # logs of order 1, as for the upper bound
    Oracle(
        "atc10-21-lower-efolds",
        _two_point_lower_efolds,
        rtol=1e-6,
        why="corrected (3.5.14) by hand, scipy binomial sums",
    ),
    # the tilt by brentq on the exponent's derivative; navcore bisects to 2^-70 (1e-9)
    Oracle("atc10-21-convexity-worst", _atc10_convexity_worst, rtol=1e-9, why="brentq on the Chernoff tilt"),
    # Table 4.3 by hand from the printed Table 4.2 (the cubic's root: 1e-9)
    Oracle(
        "atc10-90-ms-left-5ns-I",
        lambda: (_table_43_row(_TABLE_42_I, 5.0)["sdN"] / _table_43_row(_TABLE_42_I, 5.0)["sd0"]) ** 2,
        rtol=1e-9,
        why="Table 4.3 by hand",
    ),
    Oracle(
        "atc10-90-ms-left-5ns-II",
        lambda: (_table_43_row(_TABLE_42_II, 5.0)["sdN"] / _table_43_row(_TABLE_42_II, 5.0)["sd0"]) ** 2,
        rtol=1e-9,
        why="Table 4.3 by hand",
    ),
    Oracle("atc10-23-coef-se", _atc10_coef_se_by_hand, rtol=1e-9, why="standard error written out"),
    # the tracker's Monte Carlo at n = 0 against least squares by hand, five sampling standard
    # deviations of 10 000 runs
    Oracle(
        "atc10-32-mse-I-5-n0",
        lambda: _atc10_ls_position_norm()[0],
        band=lambda: 5 * _atc10_ls_position_norm()[1],
        why="least-squares covariance, sampling band",
    ),
    Oracle(
        "atc10-32-normvar-I-5-n0",
        lambda: _atc10_ls_position_norm()[2],
        band=lambda: 5 * _atc10_ls_position_norm()[3],
        why="Gaussian norm's variance, sampling band",
    ),
    # the recursion and the extrapolation variance by hand: rounding only (1e-10)
    Oracle(
        "atc10-32-printed-ms-factor-lo",
        lambda: min(_atc10_printed_ms_factors_by_hand()),
        rtol=1e-10,
        why="recursion and extrapolation by hand",
    ),
    Oracle(
        "atc10-32-printed-ms-factor-hi",
        lambda: max(_atc10_printed_ms_factors_by_hand()),
        rtol=1e-10,
        why="recursion and extrapolation by hand",
    ),
    # the recursion iterated by hand against the closed-form limit: equal step counts, so the
    # ratios agree to rounding (1e-9)
    Oracle(
        "atc10-31-convergence-speedup",
        _atc10_convergence_speedup,
        rtol=1e-9,
        why="recursion by hand, cubic's root",
    ),
    # --- ATC-10 Sec. 3.6-3.8: the PSK sample moments written out (summation order: 1e-10), and
    # scipy's normal for ROC_g (1e-9)
    Oracle("atc10-20-psk-b", lambda: _atc10_psk_moments()[0], rtol=1e-10, why="moments written out"),
    Oracle(
        "atc10-20-psk-kurtosis",
        lambda: _atc10_psk_moments()[1] / _atc10_psk_moments()[0] ** 2,
        rtol=1e-10,
        why="moments written out",
    ),
    Oracle(
        "atc10-22-psk-kurtosis",
        lambda: _atc10_psk_moments()[1] / _atc10_psk_moments()[0] ** 2,
        rtol=1e-10,
        why="moments written out",
    ),
    Oracle("atc10-22-psk-pf-gauss", _atc10_psk_pf_gauss, rtol=1e-9, why="scipy's normal, Theorem 3.1 power"),
    # the Monte Carlo against the exact lattice law at its threshold: four of its standard errors
    Oracle(
        "atc10-22-psk-pf",
        _atc10_psk_pf_exact,
        band=lambda: 4 * _atc10_psk_threshold()[1],
        why="exact lattice law by FFT at the chosen threshold",
    ),
    # the estimate and its standard error at the threshold chosen by hand, rounded by hand: the
    # error to two significant digits, the estimate at the error's first digit
    Oracle("atc10-22-psk-pf-estimate", lambda: _atc10_psk_estimate_by_hand(), why="rounding by hand"),
    # the seeded flights' location errors recomputed by hand from the run's arrays (summation
    # order only: 1e-12)
    Oracle(
        "wf05-loc-nav-over-true",
        lambda: _wf05_location_rms_by_hand("navigation") / _wf05_location_rms_by_hand("true"),
        rtol=1e-12,
        why="RMS by hand from the flights' errors",
    ),
    Oracle(
        "wf05-loc-nav-over-fed",
        lambda: _wf05_location_rms_by_hand("navigation") / _wf05_location_rms_by_hand("federated"),
        rtol=1e-12,
        why="RMS by hand from the flights' errors",
    ),
    # --- SP Sec. 2.6.2 (brentq to 1e-12 dB; the horizon's dropped h^2 term bounds the difference)
    Oracle("sp22-lc-jitter-dbhz", _sp22_lc_jitter_dbhz, rtol=1e-9, why="brentq on the jitter rule of thumb"),
    Oracle(
        "sp22-horizon-km",
        lambda: _sp22_horizon_exact()[0],
        band=lambda: _sp22_horizon_exact()[0] * _sp22_horizon_exact()[1],
        why="exact tangent distance",
    ),
    Oracle("sp22-range-min-km", _sp22_range_min_km, rtol=1e-6, why="the jammer abeam, by hand"),
    # --- SP Sec. 2.6 (Table 2.4 as printed, '5000', read as metres; the CEP's quadrature and brentq
    # to 1e-9 relative, 1e-7 percentage points)
    Oracle("sp20-clock-offset-us", lambda: 5000 / _C * 1e6, rtol=1e-12, why="Table 2.4 typed in, over c"),
    Oracle("sp20-rss-over-cep-max-pct", _sp20_rss_over_cep_max_pct, atol=1e-6, why="CEP by quadrature"),
    # --- SP Sec. 3 (scipy's quad at its default 1.5e-8 against the closed form: 1e-7)
    Oracle(
        "sp06-q-wide",
        lambda: _sp06_q(_sp_in("sp_antijam").wideband_hz),
        rtol=1e-7,
        why="sine-integral closed form",
    ),
    Oracle(
        "sp06-q-narrow",
        lambda: _sp06_q(_sp_in("sp_antijam").narrowband_hz),
        rtol=1e-7,
        why="sine-integral closed form",
    ),
    Oracle(
        "sp06-tc-threshold",
        lambda: _sp06_threshold(_sp_in("sp_antijam").tc_loss_js_db),
        rtol=1e-7,
        why="Sec. 3.1's formula, linear arithmetic",
    ),
    Oracle(
        "sp06-di-threshold",
        lambda: _sp06_threshold(_sp_in("sp_antijam").di_lock_js_db),
        rtol=1e-7,
        why="Sec. 3.1's formula, linear arithmetic",
    ),
    # --- SP Sec. 2.5-2.6 (Table 2.7 typed in: exact up to rounding; brentq at 1e-15 rad)
    Oracle(
        "sp04-tc10-min-s", lambda: min(_SP_TAB27["TC 10"]) * _SP_DWELL_S, rtol=1e-12, why="Table 2.7 typed in"
    ),
    Oracle(
        "sp04-tc10-max-s", lambda: max(_SP_TAB27["TC 10"]) * _SP_DWELL_S, rtol=1e-12, why="Table 2.7 typed in"
    ),
    Oracle(
        "sp04-better-max-s",
        lambda: max(max(v) for k, v in _SP_TAB27.items() if k != "TC 10") * _SP_DWELL_S,
        rtol=1e-12,
        why="Table 2.7 typed in",
    ),
    Oracle(
        "sp04-tc10-sigma-min-m",
        lambda: min(_SP_TAB27["TC 10"]) * _SP_RANGE_CELL_M / 2,
        rtol=1e-12,
        why="Table 2.7 typed in",
    ),
    Oracle(
        "sp04-tc10-sigma-max-m",
        lambda: max(_SP_TAB27["TC 10"]) * _SP_RANGE_CELL_M / 2,
        rtol=1e-12,
        why="Table 2.7 typed in",
    ),
    Oracle(
        "sp05-mis-1pct-mrad",
        lambda: _sp05_heading_for_ratio(1.01),
        rtol=1e-9,
        why="brentq on the root sum square",
    ),
    Oracle(
        "sp05-mis-equal-mrad",
        lambda: _sp05_heading_for_ratio(math.sqrt(2)),
        rtol=1e-9,
        why="brentq on the root sum square",
    ),
    # --- SP Sec. 2.6 (the 90 % radius: brentq at 1e-12 on a quadrature; the isotropic case is
    # scipy's chi-square quantile, 1e-9)
    Oracle("sp03-iso", lambda: math.sqrt(stats.chi2.ppf(0.9, 3)), rtol=1e-9, why="scipy chi-square quantile"),
    Oracle("sp03-n-above", _sp03_n_above_monte_carlo, why="seeded Monte Carlo of the 90 % radius"),
    Oracle(
        "sp03-col2-fall",
        lambda: max(_SP_TAB26_COL2_PPM) / min(_SP_TAB26_COL2_PPM),
        rtol=1e-12,
        why="Table 2.6 typed in",
    ),
    Oracle(
        "sp03-sf-fall",
        lambda: max(_SP_TAB25_SF_PPM) / min(_SP_TAB25_SF_PPM),
        rtol=1e-12,
        why="Table 2.5 typed in",
    ),
    # --- SP Sec. 2.5 (the loop simulated on a fine grid: 1e-6)
    Oracle(
        "sp02-lam-fit",
        lambda: (
            360 * _sp_loop_peak(_sp_in("sp_tracking").omega0_fig21) / _sp_in("sp_tracking").peak_limit_deg
        ),
        rtol=1e-6,
        why="scipy impulse response of the loop",
    ),
    Oracle(
        "sp02-l1-peak",
        lambda: _sp_loop_peak(_sp_in("sp_tracking").omega0_fig21) * 360 / (_C / _F_L1),
        rtol=1e-6,
        why="scipy impulse response of the loop",
    ),
    Oracle("sp02-l1-w0", _sp02_l1_w0, rtol=1e-6, why="scipy impulse response, 1 / w^2 scaling"),
    Oracle(
        "sp02-l1-factor",
        lambda: _sp02_l1_w0() / _sp_in("sp_residual_acceleration").unaided_omega0,
        rtol=1e-6,
        why="scipy impulse response, 1 / w^2 scaling",
    ),
    Oracle(
        "sp02-step-over-jerk",
        lambda: (
            _sp_loop_peak(_sp_in("sp_tracking").omega0_fig21)
            / _sp_loop_peak(_sp_in("sp_tracking").omega0_fig21, "jerk")
        ),
        rtol=1e-6,
        why="scipy impulse and lsim of the loop",
    ),
    # --- KZL Sec. 3.6: closed forms in other units (rounding: 1e-12; scipy quad 1e-10)
    Oracle(
        "kzl03-arw-position-km",
        _kzl_arw_position_km,
        rtol=1e-9,
        why="variance of a twice-integrated random walk",
    ),
    Oracle(
        "kzl03-bias-heading-deg",
        lambda: _kzl_table1_gyro()[0] * _kzl_table1_gyro()[3],
        rtol=1e-12,
        why="deg/h times hours",
    ),
    Oracle(
        "kzl90-bias-term-raw-deg",
        lambda: _kzl_table1_gyro()[0] * _kzl_table1_gyro()[3],
        rtol=1e-12,
        why="deg/h times hours",
    ),
    Oracle(
        "kzl03-seed", lambda: int(f"{2006:04d}{10:02d}{29:02d}"), why="the flight's date, 29 October 2006"
    ),
    Oracle(
        "kzl03-raw-heading-closed-deg",
        lambda: _kzl_closed_heading_deg(False),
        rtol=1e-12,
        why="closed form in deg",
    ),
    Oracle(
        "kzl90-heading-uncalibrated-deg",
        lambda: _kzl_closed_heading_deg(False),
        rtol=1e-12,
        why="closed form in deg",
    ),
    Oracle(
        "kzl90-heading-calibrated-deg",
        lambda: _kzl_closed_heading_deg(True),
        rtol=1e-12,
        why="closed form in deg",
    ),
    Oracle(
        "kzl03-bias-for-20deg-deg-h",
        lambda: optimize.brentq(lambda b: b / 3600 * _kzl_table1_gyro()[3] - 20.0, 1.0, 1e4, xtol=1e-12),
        rtol=1e-10,
        why="brentq on b t = 20 deg",
    ),
    # Monte Carlo statistics recomputed by hand (sums of squares written out) from the returned run arrays,
    # the epochs from the schedule typed in above: the same numbers up to summation order (1e-12)
    Oracle("kzl03-share-beyond-20deg", _kzl_share_beyond_20deg, rtol=1e-12, why="runs counted by hand"),
    Oracle("kzl03-raw-att-min-deg", lambda: min(_kzl_raw_att_deg()), rtol=1e-12, why="RMS by hand"),
    Oracle("kzl03-raw-att-max-deg", lambda: max(_kzl_raw_att_deg()), rtol=1e-12, why="RMS by hand"),
    Oracle(
        "kzl03-tc-roll-gain",
        lambda: (
            _kzl_segment_mean_deg("ins", 0, (8, 4, 3, 2, 5)) / _kzl_segment_mean_deg("tc", 0, (8, 4, 3, 2, 5))
        ),
        rtol=1e-12,
        why="RMS by hand over the typed schedule",
    ),
    Oracle(
        "kzl03-tc-pitch-gain",
        lambda: (
            _kzl_segment_mean_deg("ins", 1, (8, 4, 3, 2, 5)) / _kzl_segment_mean_deg("tc", 1, (8, 4, 3, 2, 5))
        ),
        rtol=1e-12,
        why="RMS by hand over the typed schedule",
    ),
    Oracle(
        "kzl03-att-heading-many-deg",
        lambda: _kzl_segment_mean_deg("tc_att", 2, (8, 4, 5)),
        rtol=1e-12,
        why="RMS by hand over the typed schedule",
    ),
    Oracle(
        "kzl03-att-heading-growth",
        lambda: _kzl_segment_mean_deg("tc_att", 2, (3, 2)) / _kzl_segment_mean_deg("tc_att", 2, (8, 4, 5)),
        rtol=1e-12,
        why="RMS by hand over the typed schedule",
    ),
    Oracle(
        "kzl03-att-heading-3sat-deg",
        lambda: _kzl_segment_mean_deg("tc_att", 2, (3,)),
        rtol=1e-12,
        why="RMS by hand",
    ),
    Oracle(
        "kzl03-att-heading-2sat-deg",
        lambda: _kzl_segment_mean_deg("tc_att", 2, (2,)),
        rtol=1e-12,
        why="RMS by hand",
    ),
    Oracle(
        "kzl03-dd-heading-3sat-deg",
        lambda: _kzl_segment_mean_deg("tc_dd", 2, (3,)),
        rtol=1e-12,
        why="RMS by hand",
    ),
    Oracle(
        "kzl03-dd-heading-2sat-deg",
        lambda: _kzl_segment_mean_deg("tc_dd", 2, (2,)),
        rtol=1e-12,
        why="RMS by hand",
    ),
    Oracle(
        "kzl03-tc-pos-start-3sat-m", lambda: _kzl_horizontal_rms("pos_err", 89), rtol=1e-12, why="RMS by hand"
    ),
    Oracle(
        "kzl03-tc-pos-end-3sat-m", lambda: _kzl_horizontal_rms("pos_err", 119), rtol=1e-12, why="RMS by hand"
    ),
    Oracle(
        "kzl03-tc-pos-end-2sat-m", lambda: _kzl_horizontal_rms("pos_err", 149), rtol=1e-12, why="RMS by hand"
    ),
    Oracle(
        "kzl03-tc-vel-end-2sat-mps",
        lambda: _kzl_horizontal_rms("vel_err", 149),
        rtol=1e-12,
        why="RMS by hand",
    ),
    Oracle("kzl89-heading-removed", lambda: _kzl_removed("heading"), rtol=1e-12, why="RMS by hand"),
    Oracle("kzl89-attitude-removed", lambda: _kzl_removed("attitude"), rtol=1e-12, why="RMS by hand"),
    Oracle(
        "kzl03-candidates-2m",
        lambda: 2 * _kzl_in("kzl_scenario").baseline_m / _kzl_l1_wavelength() + 1,
        rtol=1e-12,
        why="lambda = c / (154 x 10.23 MHz)",
    ),
    Oracle(
        "kzl03-tilt-2m-mrad",
        lambda: 1e3 * 0.01 * _kzl_l1_wavelength() / _kzl_in("kzl_scenario").baseline_m,
        rtol=1e-12,
        why="lambda = c / (154 x 10.23 MHz)",
    ),
    # scipy's rotation composition against navcore's quaternion correction: round-off (1e-9)
    Oracle("kzl89-qcorr-residual-deg", _kzl_qcorr_residual_deg, rtol=1e-9, why="scipy Rotation"),
    Oracle(
        "kzl89-qcorr-error-deg",
        lambda: float(
            np.degrees(
                __import__("scipy.spatial.transform", fromlist=["Rotation"])
                .Rotation.from_rotvec(
                    __import__(
                        "navcore.papers.kzl_tightly_coupled_filter", fromlist=["QCORR_DPSI"]
                    ).QCORR_DPSI
                )
                .magnitude()
            )
        ),
        rtol=1e-12,
        why="scipy Rotation's angle",
    ),
    Oracle("kzl89-dd-printed-rank", lambda: _kzl_dd_rank(True), why="exact rank"),
    Oracle("kzl89-dd-rank", lambda: _kzl_dd_rank(False), why="exact rank"),
    Oracle(
        "kzl90-residual-deg-h",
        lambda: _kzl_in("kzl_scenario").gyro_bias_arw[1] / math.sqrt(_kzl_table1_gyro()[4]),
        rtol=1e-12,
        why="deg/h/sqrt(Hz) over sqrt(s)",
    ),
    Oracle(
        "kzl90-bias-term-calibrated-deg",
        lambda: (
            _kzl_in("kzl_scenario").gyro_bias_arw[1]
            / math.sqrt(_kzl_table1_gyro()[4])
            * _kzl_table1_gyro()[3]
            / 3600
        ),
        rtol=1e-12,
        why="deg/h times hours",
    ),
    Oracle(
        "kzl90-floor-deg",
        lambda: math.sqrt(_kzl_table1_gyro()[1] ** 2 * _kzl_table1_gyro()[3] + _kzl_table1_gyro()[2] ** 2),
        rtol=1e-12,
        why="closed form in deg",
    ),
    Oracle("kzl90-crossover-s", _kzl_crossover_s, rtol=1e-10, why="brentq"),
    # the covariance engine (Earth rate, transport rate and Schuler coupling on top) against the
    # closed form: the page holds each heading within 2 % of it, so the difference within 2 % of
    # their sum (this band cannot catch the function scaled by 1.3)
    Oracle(
        "kzl90-gain-300-1200-deg",
        lambda: _kzl_gain_closed()[0] - _kzl_gain_closed()[1],
        band=lambda: 0.02 * sum(_kzl_gain_closed()),
        why="closed form, the page's 2 % agreement",
    ),
    # --- KZL Sec. 1-2 (closed forms of the scenario's inputs in other arithmetic: 1e-9; the
    # pointing-shift oracle is exact geometry, the function's slant * tan(delta) the same: 1e-9)
    Oracle("kzl00-overlap-s", _kzl00_overlap_s, rtol=1e-9, why="Kepler ground-track speed"),
    Oracle("kzl00-pointing-shift-m", _kzl00_pointing_shift_m, rtol=1e-9, why="scipy Rotation of the beam"),
    # a central difference at 1e-6 rad of a cosine: truncation ~1e-12 relative, rounding ~1e-10
    Oracle("kzl00-baseline-arcsec", _kzl00_baseline_arcsec, rtol=1e-7, why="central difference of h(theta)"),
    Oracle("kzl00-baseline-mm", _kzl00_baseline_mm, rtol=1e-9, why="InSAR phase sensitivities"),
    # scipy quad on smooth exponentials: 1e-10 relative at least
    Oracle(
        "kzl00-correlation-10s", _kzl00_correlation_10s, rtol=1e-8, why="quadrature of the impulse response"
    ),
    Oracle(
        "kzl01-printed-roll-deg", lambda: math.degrees(math.atan2(0.0, -_G0)), rtol=1e-12, why="math.atan2"
    ),
    # the ODE at rtol 1e-11 gives the exact sigma to ~1e-10 relative, 1e-8 percentage points
    Oracle(
        "kzl01-first-order-low-pct-1s",
        lambda: _kzl01_first_order(1.0),
        atol=1e-6,
        why="Riccati ODE (scipy) against Eq. (6) written out",
    ),
    Oracle(
        "kzl01-first-order-low-pct-0.01s",
        lambda: _kzl01_first_order(0.01),
        atol=1e-6,
        why="Riccati ODE (scipy) against Eq. (6) written out",
    ),
    # same constants, same closed forms: rounding only
    Oracle(
        "kzl01-neglected-rates-deg-h", _kzl01_neglected_rates_deg_h, rtol=1e-9, why="Earth + transport rate"
    ),
    Oracle(
        "kzl01-neglected-coriolis-micro-g",
        _kzl01_neglected_coriolis_micro_g,
        rtol=1e-9,
        why="Coriolis by hand",
    ),
    # exact ranks of a generic geometry: equal counts
    Oracle("kzl02-rank-code-delta-range", lambda: _kzl_generic_rank("tc", 8), why="exact rank, generic sky"),
    Oracle("kzl03-rank-code-delta-range", lambda: _kzl_generic_rank("tc", 8), why="exact rank, generic sky"),
    Oracle("kzl02-full-rank-from-nu", _kzl02_full_rank_from_nu, why="exact rank, generic sky"),
    Oracle("kzl00-schuler-min", _schuler_period_min, rtol=1e-8, why="ODE solved to 1e-12"),
    Oracle("atc10-32-c-ft-per-ns", lambda: sc.c * 1e-9 / sc.foot, rtol=1e-12, why="scipy.constants"),
    Oracle(
        "atc10-32-c-shrink-pct", lambda: 100 * (1 - sc.c * 1e-9 / sc.foot), rtol=1e-9, why="scipy.constants"
    ),
    Oracle(
        "atc10-13-30W-dbw",
        lambda: 10 * (1 + math.log(3) / math.log(10)),
        rtol=1e-12,
        why="log10 30 = 1 + ln 3/ln 10",
    ),
    Oracle("atc10-10-convention-db", lambda: 10 * math.log(2) / math.log(10), rtol=1e-12, why="natural logs"),
    Oracle("atc10-12-erf-shift-db", lambda: 10 * math.log(2) / math.log(10), rtol=1e-12, why="natural logs"),
    Oracle(
        "wf04-trace-reading-shift-db", lambda: 10 * math.log(3) / math.log(10), rtol=1e-12, why="natural logs"
    ),
    Oracle(
        "wf89-fl1c", lambda: float(Fraction(_F_L1, _C)), rtol=1e-14, why="exact fraction of defined values"
    ),
    Oracle("wf89-fl1c-3e8", lambda: float(Fraction(_F_L1, 300_000_000)), rtol=1e-14, why="exact fraction"),
    Oracle("atc10-31-small-alpha-coefficient", _small_alpha_coefficient, rtol=1e-9, why="extrapolated limit"),
    Oracle("atc10-30-orbit-radius-km", _orbit_radius_km, rtol=1e-9, why="brentq to 1e-15"),
    Oracle("atc10-13-wavelength-m", lambda: sc.c / _atc10_dish_hz(), rtol=1e-12, why="scipy.constants"),
    # the page prints the small angle b/g; atan(b/g) is x^2/3 relative away (2e-6 at 2.4 mg),
    # and 1e-5 holds for any bias below 5 mg
    Oracle("kzl01-levelling-tilt-deg", _kzl_tilt_deg, rtol=1e-5, why="exact atan tilt"),
    Oracle("kzl03-levelling-tilt-deg", _kzl_tilt_deg, rtol=1e-5, why="exact atan tilt"),
    Oracle(
        "kzl01-horizontal-earth-rate-deg-h",
        _horizontal_earth_rate_deg_h,
        rtol=1e-6,
        why="sidereal day to 1e-9",
    ),
    Oracle("wf05-sigma-f-velocity", lambda: _wf_sigma_f_velocity(), rtol=1e-12, why="scipy.constants"),
    # 1/sqrt(2N) is the first term of the chi distribution's coefficient of variation; the next
    # is 1/(8N) relative, so twice that is allowed
    Oracle(
        "kzl03-rms-rel-error-pct", lambda: _chi_cv_pct(_kzl_runs()), rtol=1 / (4 * 30), why="chi(N), exact"
    ),
    Oracle(
        "sp06-cep-sd-pct", lambda: _chi_cv_pct(2 * _sp_runs()), rtol=1 / (4 * 50), why="chi(2 runs), exact"
    ),
    Oracle("sp03-chi2", lambda: float(stats.maxwell.ppf(0.9)), rtol=1e-9, why="scipy's Maxwell distribution"),
    Oracle("kzl01-n-states", _kzl_states, why="KZL Eq. (1) as printed"),
    Oracle("kzl02-n-states", _kzl_states, why="KZL Eq. (1) as printed"),
    Oracle("kzl03-n-states", _kzl_states, why="KZL Eq. (1) as printed"),
    Oracle("across01-kzl-states", _kzl_states, why="KZL Eq. (1) as printed"),
    Oracle("kzl02-dd-rows-2-satellites", lambda: _kzl_rows(2), why="the paper's printed size"),
    Oracle("kzl02-dd-rows-8-satellites", lambda: _kzl_rows(8), why="the paper's printed size"),
    # the two root-finders converge far below 1e-6 dB (bisection to 1e-17 dB here)
    Oracle("atc10-erp-K100-0.88", _atc10_direct_erp(100, 0.88), atol=1e-6, why="direct probabilities"),
    Oracle("atc10-erp-K100-0.999", _atc10_direct_erp(100, 0.999), atol=1e-6, why="direct probabilities"),
    Oracle("atc10-12-erp-K100-0.88", _atc10_direct_erp(100, 0.88), atol=1e-6, why="direct probabilities"),
    Oracle("atc10-13-erp-K100-0.98", _atc10_direct_erp(100, 0.98), atol=1e-6, why="direct probabilities"),
    Oracle("atc10-12-fig2.4-erp", _atc10_direct_erp(10, 0.88), atol=1e-6, why="direct probabilities"),
    Oracle("atc10-pd-k1000-0.88", lambda: _per_list_q(0.88, 1000) ** 0.25, rtol=1e-12, why="closed form"),
    Oracle("atc10-pd-k1000-0.98", lambda: _per_list_q(0.98, 1000) ** 0.25, rtol=1e-12, why="closed form"),
    Oracle("atc10-pd-k1000-0.999", lambda: _per_list_q(0.999, 1000) ** 0.25, rtol=1e-12, why="closed form"),
    Oracle("atc10-pd4-k1000-0.999", lambda: _per_list_q(0.999, 1000), rtol=1e-12, why="closed form"),
    Oracle("atc10-10-qK-k10-0.999", lambda: _per_list_q(0.999, 10) ** 10, rtol=1e-12, why="closed form"),
    Oracle("atc10-20-mean-overlap", lambda: float(_overlap().mean()), rtol=1e-12, why="scipy binomial"),
    Oracle("atc10-21-nq", lambda: float(_overlap().mean()), rtol=1e-12, why="scipy binomial"),
    Oracle("atc10-20-p-none", lambda: float(_overlap().pmf(0)), rtol=1e-9, why="scipy binomial"),
    Oracle(
        "atc10-20-inverse-nq",
        lambda: 1.0 / float(_overlap().mean() / (1 - 1 / _n_sec36())),
        rtol=1e-12,
        why="scipy binomial mean, rescaled to N aircraft",
    ),
    Oracle("atc10-10-n-v", _atc10_n_v, rtol=1e-12, why="the paper's B, v, alpha typed in"),
    Oracle("atc10-12-n-v", _atc10_n_v, rtol=1e-12, why="the paper's B, v, alpha typed in"),
    Oracle("atc10-14-n-v", _atc10_n_v, rtol=1e-12, why="the paper's B, v, alpha typed in"),
    Oracle("atc10-11-samples-period", lambda: float(2 * _ATC10_B * _ATC10_ALPHA), rtol=1e-15, why="exact"),
    Oracle("atc10-11-samples-window", lambda: float(4 * _ATC10_B * _ATC10_BETA), rtol=1e-15, why="exact"),
    Oracle("kzl03-dd-sigma-mm", _kzl_dd_sigma_mm, rtol=1e-12, why="closed form 2 sigma"),
    Oracle("kzl03-gyro-residual-deg-h", _kzl_gyro_residual_deg_h, rtol=1e-12, why="N / sqrt(T), deg/h units"),
    # the fine-grid integral of the piecewise-linear R^2 is good to ~1e-5 at 200 samples a chip
    Oracle(
        "atc10-23-w-msequence-1023", lambda: _brute_zakai(_msequence_1023()), rtol=2e-4, why="brute force"
    ),
    Oracle(
        "atc10-23-barker13-of-ideal", lambda: _brute_zakai(_BARKER13) / 0.75, rtol=2e-4, why="brute force"
    ),
]


# --- Wu & Fowler ------------------------------------------------------------------------------
# The Sec. IV.D oracles are per-axis scalar arithmetic: every covariance of Figs. 1-2 is diagonal,
# so Eq. (23)'s Minkowski term is written out axis by axis, and the accelerometer filter's
# steady state comes from scipy's discrete algebraic Riccati solver (not navcore's closed form).
# scipy's solver is good to about eps times the conditioning sqrt(r/q) ~ 1e4 here (1e-12); the
# tolerances below allow 1e-7 relative, and 1e-6 dB on a decibel value (1e-7 relative is 4e-7 dB).
_WF_RTOL, _WF_DB_ATOL = 1e-7, 1e-6
_WF_DARE = "closed-form diagonal arithmetic, scipy's Riccati solver"


def _wf_in():
    from navcore.papers import wf_inputs

    return wf_inputs.IN


def _wf_filter(sigma_a: float) -> tuple[float, float, float]:
    """Prior, posterior and gain of the accelerometer filter of WF Eq. (14) in steady state,
    x_k = x_k-1 + T_s a (process noise (sigma_a T_s)^2), y_L = x + n (sigma_L = 200 sigma_a):
    scipy.linalg.solve_discrete_are."""
    from scipy import linalg

    IN = _wf_in()
    q, r = (sigma_a * IN.ts) ** 2, (IN.sigma_l_per_sigma_a * sigma_a) ** 2
    one = np.ones((1, 1))
    prior = float(linalg.solve_discrete_are(one, one, q * one, r * one)[0, 0])
    return prior, prior * r / (prior + r), prior / (prior + r)


def _wf_sigma_a_example() -> float:
    return _wf_in().sigma_a_example_micro_g * 1e-6 * _G0


def _wf_gps_variance(prior: float, axes: int) -> list[float]:
    """Per-axis variance of the GPS estimate of Eq. (16)-(17): information form on the prior,
    f_L1/c = 5.25 1/m (the printed gain) on ``axes`` of the three axes, sigma_G = 1 Hz."""
    IN = _wf_in()
    h2 = IN.f_l1_over_c_printed**2 / IN.sigma_g**2
    return [1.0 / (1.0 / prior + h2) if a < axes else prior for a in range(3)]


def _wf_locals(sigma_a: float, sigma_t: float, n_sat: int, *, dl_prior: bool = False) -> list[list[float]]:
    """Per-axis variances of P_DN, P_DL (its posterior, or its prior) and P_DG of Sec. IV.D."""
    IN = _wf_in()
    prior, post, _ = _wf_filter(sigma_a)
    out = [[IN.sigma_n**2 + sigma_t**2] * 3, [prior if dl_prior else post] * 3]
    if n_sat:
        out.append(_wf_gps_variance(prior, n_sat))
    return out


def _minkowski_diag(variances: list[list[float]]) -> float:
    """Middle term of WF Eq. (23), (sum_i sqrt(tr(P_D P_i^-1 P_D)))^2, for diagonal covariances."""
    p_d = [1.0 / sum(1.0 / v[a] for v in variances) for a in range(3)]
    return sum(math.sqrt(sum(p_d[a] ** 2 / v[a] for a in range(3))) for v in variances) ** 2


def _wf_sigma_d(sigma_a: float, sigma_t: float, n_sat: int = 0) -> float:
    return math.sqrt(_minkowski_diag(_wf_locals(sigma_a, sigma_t, n_sat)) / 3)


def _wf_improvement_db(sigma_a: float, sigma_t: float, n_sat: int = 0) -> float:
    """20 log10(sigma_D / sigma_DN), sigma_DN = sqrt(sigma_N^2 + sigma_T^2)."""
    sigma_dn = math.sqrt(_wf_in().sigma_n ** 2 + sigma_t**2)
    return 20 * math.log10(_wf_sigma_d(sigma_a, sigma_t, n_sat) / sigma_dn)


def _wf_grid() -> list[float]:
    """The 31 log-spaced resolutions of Figs. 1-2 over the stated range, as a geometric sequence."""
    IN = _wf_in()
    lo, hi = IN.sigma_a_low, IN.sigma_a_high
    return [lo * (hi / lo) ** (k / 30) for k in range(31)]


def _wf_sigma_ts() -> tuple[float, float, float]:
    IN = _wf_in()
    return (IN.sigma_t_small, IN.sigma_t_medium, IN.sigma_t_large)


def _wf_gps_gain_max_db() -> float:
    return max(
        _wf_improvement_db(sa, st, 0) - _wf_improvement_db(sa, st, ns)
        for st in _wf_sigma_ts()
        for ns in (1, 3)
        for sa in _wf_grid()
    )


def _wf_three_vs_one_db() -> float:
    st = _wf_in().sigma_t_small
    return max(abs(_wf_improvement_db(sa, st, 3) - _wf_improvement_db(sa, st, 1)) for sa in _wf_grid())


def _wf_prior_instead_shift_db() -> float:
    return max(
        abs(
            10
            * math.log10(
                _minkowski_diag(_wf_locals(sa, st, ns, dl_prior=True))
                / _minkowski_diag(_wf_locals(sa, st, ns))
            )
        )
        for sa in _wf_grid()
        for st in _wf_sigma_ts()
        for ns in (0, 1, 3)
    )


def _wf03_scalars() -> dict[str, float]:
    """The page's worked joint covariance on one axis, in scalars: the accelerometer error
    (1 - K) e + K n_L and the GPS error (1 - k_G h) e + k_G n_G share the prior error e."""
    IN = _wf_in()
    sa = _wf_sigma_a_example()
    prior, post, K = _wf_filter(sa)
    h, sg2, sl2 = IN.f_l1_over_c_printed, IN.sigma_g**2, (IN.sigma_l_per_sigma_a * sa) ** 2
    k_g = prior * h / (h * h * prior + sg2)
    return {
        "N": IN.sigma_n**2 + IN.sigma_t_large**2,
        "L": (1 - K) ** 2 * prior + K**2 * sl2,
        "G": (1 - k_g * h) ** 2 * prior + k_g**2 * sg2,
        "LG": (1 - K) * (1 - k_g * h) * prior,
        "wL": post,
        "wG": 1.0 / (1.0 / prior + h * h / sg2),
    }


def _wf03_corr() -> float:
    s = _wf03_scalars()
    return s["LG"] / math.sqrt(s["L"] * s["G"])


def _wf03_naive_optimism() -> float:
    """Exact variance of the fused error sum_i a_i e_i, a_i = p_D / s_i (the Eq. (19) weights),
    over p_D, the variance Eq. (19) claims."""
    s = _wf03_scalars()
    w = {"N": s["N"], "L": s["wL"], "G": s["wG"]}
    p_d = 1.0 / sum(1.0 / x for x in w.values())
    a = {k: p_d / x for k, x in w.items()}
    exact = a["N"] ** 2 * s["N"] + a["L"] ** 2 * s["L"] + a["G"] ** 2 * s["G"] + 2 * a["L"] * a["G"] * s["LG"]
    return math.sqrt(exact / p_d)


def _wf_tightness_generic_rho1() -> float:
    """At rho = 1 every local error is L_i w of one common w: the fused error is (sum_i P_D P_i^-1 L_i) w.
    The seeded generic covariances typed in (A A^T + 0.1 I, A standard normal 3x3, seed 9)."""
    rng = np.random.default_rng(9)
    Ls = []
    for _ in range(3):
        A = rng.normal(size=(3, 3))
        Ls.append(np.linalg.cholesky(A @ A.T + 0.1 * np.eye(3)))
    Ps = [L @ L.T for L in Ls]
    P_d = np.linalg.inv(sum(np.linalg.inv(P) for P in Ps))
    M = sum(P_d @ np.linalg.solve(P, L) for P, L in zip(Ps, Ls, strict=True))
    true_trace = float(np.trace(M @ M.T))
    mink = sum(math.sqrt(float(np.trace(P_d @ np.linalg.solve(P, P_d)))) for P in Ps) ** 2
    return mink / true_trace


def _wf_tightness_isotropic_rho0() -> float:
    """Independent isotropic errors of sigmas s_i: tr Cov = 3 p_D, p_D = 1 / sum s_i^-2, and the
    Minkowski term 3 p_D^2 (sum 1/s_i)^2; the ratio p_D (sum 1/s_i)^2 (the sigmas 0.02, 0.002, 0.0019 m/s)."""
    s = (Fraction(2, 100), Fraction(2, 1000), Fraction(19, 10000))
    p_d = 1 / sum(1 / x**2 for x in s)
    return float(p_d * sum(1 / x for x in s) ** 2)


def _wf_mean_range_km() -> float:
    """Time average of the range over the continuous Sec. III turn (scipy quad): the track
    (r sin wt, r (1 - cos wt), h), r = v / w, and the emitter at distance d and bearing b."""
    IN = _wf_in()
    w = math.radians(IN.turn_rate_deg_s)
    r = IN.speed_mps / w
    b = math.radians(IN.emitter_bearing_deg)
    ex, ey = IN.emitter_distance_m * math.cos(b), IN.emitter_distance_m * math.sin(b)

    def rng_at(t: float) -> float:
        return math.sqrt(
            (ex - r * math.sin(w * t)) ** 2 + (ey - r * (1 - math.cos(w * t))) ** 2 + IN.altitude_m**2
        )

    T = IN.aperture_duration_s
    return integrate.quad(rng_at, 0.0, T, epsabs=0.0, epsrel=1e-12)[0] / T / 1e3


def _wf_bound_ratio_max() -> float:
    """Central differences of the Doppler term v.(e - p)/|e - p| in p (step 1e-5 R; truncation
    1e-10) over the printed bound 2 |v| / R of Eq. (9) (f0/c cancels), on the seeded geometries
    (p ~ N(0, 5 km), e = p + N(0, 30 km), v ~ N(0, 200 m/s), seed 11, 2000 draws, typed in)."""
    rng = np.random.default_rng(11)
    p = rng.normal(0, 5000, (2000, 3))
    e = p + rng.normal(0, 30000, (2000, 3))
    v = rng.normal(0, 200, (2000, 3))
    R = np.linalg.norm(e - p, axis=1)

    def term(pp: np.ndarray) -> np.ndarray:
        d = e - pp
        return np.sum(v * d, axis=1) / np.linalg.norm(d, axis=1)

    g = np.empty((2000, 3))
    for k in range(3):
        step = np.zeros((2000, 3))
        step[:, k] = 1e-5 * R
        g[:, k] = (term(p + step) - term(p - step)) / (2e-5 * R)
    return float(np.max(np.linalg.norm(g, axis=1) / (2 * np.linalg.norm(v, axis=1) / R)))


def _wf_leverage() -> dict[str, float]:
    """WF Eq. (6) by hand on the Sec. II turn: the Doppler model f0 (1 + v.u / c) written out
    (scipy.constants' c), its Jacobian in (emitter, f0) by central differences (step 1e-4 R)
    except the f0 column, exact; the errors by numpy's least squares."""
    from navcore.papers import wf_location_error

    f0, emitter = wf_location_error.F0, wf_location_error.EMITTER
    _, pos, vel = wf_location_error.orbit()

    def doppler(e: np.ndarray, p: np.ndarray, v: np.ndarray) -> np.ndarray:  # f - f0
        d = e - p
        return f0 / sc.c * np.sum(v * d, axis=1) / np.linalg.norm(d, axis=1)

    R = np.linalg.norm(emitter - pos, axis=1)
    H = np.empty((len(pos), 4))
    for k in range(3):
        step = np.zeros(3)
        step[k] = 1.0
        h = 1e-4 * R[:, None]
        H[:, k] = (doppler(emitter + h * step, pos, vel) - doppler(emitter - h * step, pos, vel)) / (
            2 * h[:, 0]
        )
    H[:, 3] = 1.0 + doppler(emitter, pos, vel) / f0
    dz = np.array([0.0, 0.0, 1.0])
    f_true = doppler(emitter, pos, vel)
    err_v = np.linalg.lstsq(H, f_true - doppler(emitter, pos, vel + dz), rcond=None)[0][:3]
    err_p = np.linalg.lstsq(H, f_true - doppler(emitter, pos + dz, vel), rcond=None)[0][:3]
    G = np.linalg.pinv(H)  # (H^T H)^-1 H^T
    # per-sample variances of independent unit errors: |df/dv|^2 = (f0/c)^2, |df/dp|^2 = |df/de|^2
    white_v = math.sqrt(float(np.sum(G[:3] ** 2)) * (f0 / sc.c) ** 2)
    white_p = math.sqrt(float(np.sum((G[:3] ** 2) @ np.sum(H[:, :3] ** 2, axis=1))))
    return {
        "z": float(np.linalg.norm(err_v) / np.linalg.norm(err_p)),
        "white": white_v / white_p,
    }


def _wf_eq13_ratio() -> tuple[float, float]:
    """Exact moments of WF Eq. (13) run as printed: x_k = (1 - K) x_k-1 + ((1 - K) T + K)(a_k + n_k),
    v_k = v_k-1 + a_k T, x_0 ~ N(0, P(k/k)), v_0 = 0 (Python loops, the seeded run's settings and
    scipy's Riccati gain). Returns the expected RMS error over sqrt(P(k/k)) and the sampling
    standard deviation of a 200-path RMS, from Var((mu + s z)^2) = 2 s^4 + 4 mu^2 s^2."""
    IN = _wf_in()
    sa, steps, paths = 1e-3, 5000, 200  # the seeded run's settings (WF Eq. (13) test case)
    _, post, K = _wf_filter(sa)
    ts = IN.ts
    c = (1 - K) * ts + K
    mean_x, var_x, v = 0.0, post, 0.0
    for k in range(steps):
        a = IN.eq13_accel_amplitude_mps2 * math.sin(2 * math.pi * IN.eq13_accel_frequency_hz * ts * k)
        v += a * ts
        mean_x = (1 - K) * mean_x + c * a
        var_x = (1 - K) ** 2 * var_x + c * c * sa * sa
    mu = mean_x - v
    ms = mu * mu + var_x
    sd_ms = math.sqrt((2 * var_x**2 + 4 * mu * mu * var_x) / paths)
    return math.sqrt(ms / post), 0.5 * sd_ms / ms * math.sqrt(ms / post)


def _wf_eq20_block() -> float:
    """The seeded joint of the Eq. (20) check typed in (A 9x9 standard normal, seed 17,
    J = A A^T + 0.5 I), the printed block (2, 3) read as P_NG, entry by entry in Python floats."""
    rows = np.random.default_rng(17).normal(size=(9, 9)).tolist()
    J = [
        [
            sum(x * y for x, y in zip(rows[i], rows[j], strict=True)) + (0.5 if i == j else 0.0)
            for j in range(9)
        ]
        for i in range(9)
    ]
    num = max(abs(J[i - 3][j] - J[i][j]) for i in range(3, 6) for j in range(6, 9))
    return num / max(abs(x) for row in J for x in row)


def _wf05_vibration_moments() -> tuple[float, float]:
    """Mean square of the worked example's vertical vibration velocity and the sampling standard
    deviation of its 20-flight estimate. Each flight sums 8 tones of displacement amplitude
    A / sqrt(8), frequencies uniform within +-0.5 Hz of f_v and uniform phases; over T seconds
    a flight's mean square is sum_k d_k + sum_{j<k} X_jk with d_k = (A^2/8)(2 pi f_k)^2 / 2 (exact
    moments of the uniform frequency) and cross terms X_jk of zero mean whose variance is
    (A^2/8 (2 pi)^2 E f^2)^2 E[sinc^2(pi df T)] / 2, E[sinc^2] = 1/T for the triangular density
    of a frequency difference (1 at 0)."""
    IN = _wf_in()
    A, f0, T = IN.vib_amplitude_m, IN.vib_hz, IN.aperture_duration_s
    tones, flights = 8, 20  # the example's tones and flights (its settings)
    ef2 = f0**2 + 1 / 12
    ef4 = ((f0 + 0.5) ** 5 - (f0 - 0.5) ** 5) / 5
    scale = A**2 / tones * (2 * math.pi) ** 2
    var_d = (scale / 2) ** 2 * (ef4 - ef2**2)
    var_x = (scale * ef2) ** 2 / (2 * T)
    ms = tones * scale * ef2 / 2
    var_ms = (tones * var_d + tones * (tones - 1) / 2 * var_x) / flights
    return ms, math.sqrt(var_ms)


def _wf05_vib_rms() -> tuple[float, float]:
    """Expected RMS vibration velocity and the sampling standard deviation of the 20-flight RMS."""
    ms, sd = _wf05_vibration_moments()
    return math.sqrt(ms), sd / (2 * math.sqrt(ms))


def _wf_uz_rms() -> float:
    """RMS of the vertical line-of-sight component h / R over the continuous Sec. II turn (scipy
    quad): 8 km altitude, 200 m/s, the emitter at (20, 35, 0) km (the test geometry, typed in)."""
    IN = _wf_in()
    w = math.radians(IN.turn_rate_deg_s)
    r = 200.0 / w

    def uz2(t: float) -> float:
        dx, dy = 20_000.0 - r * math.sin(w * t), 35_000.0 - r * (1 - math.cos(w * t))
        return 8000.0**2 / (dx * dx + dy * dy + 8000.0**2)

    T = IN.aperture_duration_s
    return math.sqrt(integrate.quad(uz2, 0.0, T, epsabs=0.0, epsrel=1e-12)[0] / T)


def _wf05_euler_rms() -> float:
    """Euler sums of point samples of A w cos(k theta), theta = w T_s, in closed form: the sum of
    cos(k theta) for k < n is (sin(n theta - theta/2) + sin(theta/2)) / (2 sin(theta/2)), so the
    error against A sin(n theta) oscillates with amplitude A |g exp(-i theta/2) - 1|,
    g = (theta/2) / sin(theta/2); its standard deviation over whole cycles is that over sqrt(2).
    A = sqrt(2) times the registered vibration RMS (checked by its own oracle)."""
    IN = _wf_in()
    theta = 2 * math.pi * IN.vib_hz * IN.ts
    g = (theta / 2) / math.sin(theta / 2)
    amp = abs(g * complex(math.cos(theta / 2), -math.sin(theta / 2)) - 1)
    return amp * glued.value("wf05-vib-rms")


def _wf05_velocity_moments() -> dict[str, float]:
    """Expected mean squares per axis of the navigation-only and federated velocity errors of the
    worked example, and the sampling standard deviation of the federated one.

    Navigation: white sigma_N per axis, plus the vibration on the vertical axis. Federated:
    a_N e_N + a_L e_L with the Eq. (19) weights a_i = p_D / s_i of the designer's covariances
    (s_N = sigma_N^2, vertically sigma_N^2 + the vibration's mean square; s_L = P(k/k)); e_L is
    the stationary accelerometer-filter error, variance P(k/k), correlated as (1 - K)^(30 k)
    between the measurement times 30 steps apart (so a flight gives few independent samples).
    The variance of the mean square of a Gaussian sequence is 2 sum_ij c(i - j)^2 / n^2 per axis
    and flight; 3 axes and 20 flights are independent."""
    IN = _wf_in()
    _, post, K = _wf_filter(_wf_sigma_a_example())
    vib_ms, _ = _wf05_vibration_moments()
    sn2 = IN.sigma_n**2
    fed = []
    for s_n, e_n in ((sn2, sn2), (sn2, sn2), (sn2 + vib_ms, sn2 + vib_ms)):
        p_d = 1 / (1 / s_n + 1 / post)
        a_n, a_l = p_d / s_n, p_d / post
        fed.append((a_n**2 * e_n, a_l**2 * post))
    n = round(IN.aperture_duration_s / IN.ts) // 30 + 1  # measurement times, one every 30 steps
    lags = np.arange(n)
    r = (1 - K) ** (30 * lags)
    counts = np.where(lags == 0, n, 2 * (n - lags))  # ordered pairs (i, j) at each lag
    var_series = []
    for white, corr in fed:
        c = corr * r
        c[0] += white
        var_series.append(2 * float(np.sum(counts * c**2)) / n**2)
    flights = 20
    var_ms = sum(var_series) / (9 * flights)
    return {
        "nav": (3 * sn2 + vib_ms) / 3,
        "fed": sum(w + c for w, c in fed) / 3,
        "fed_sd": math.sqrt(var_ms),
    }


def _wf05_fed_vel_mm() -> tuple[float, float]:
    m = _wf05_velocity_moments()
    return 1e3 * math.sqrt(m["fed"]), 1e3 * m["fed_sd"] / (2 * math.sqrt(m["fed"]))


def _wf05_vel_gain_db() -> tuple[float, float]:
    """20 log10 sqrt(nav / fed) and its sampling standard deviation (the federated mean square's,
    to first order; the navigation one is set by the vibration's, added in quadrature)."""
    m = _wf05_velocity_moments()
    _, vib_sd = _wf05_vibration_moments()
    rel_fed = m["fed_sd"] / m["fed"]
    rel_nav = vib_sd / 3 / m["nav"]
    return 10 * math.log10(m["nav"] / m["fed"]), 10 / math.log(10) * math.hypot(rel_fed, rel_nav)


# --- ATC-10 Section 2: the thresholds in plain probabilities ----------------------------------


def _atc10_counts(scale: float = 1.0, n_v: float | None = None) -> tuple[float, float, float]:
    """The paper's sample counts typed in: 2 B alpha = 2e7, 4 B beta = 9.6e5 and n_v of (C.14)
    from v = 600 mph and c in miles per second (scipy.constants), each times ``scale``."""
    nv = 8.0 / 3.0 * 1e7 * scale * (600.0 / 3600.0) / (sc.c / sc.mile) if n_v is None else n_v
    return 2e7 * scale, 9.6e5 * scale, nv


def _atc10_pd(p_dl: float, k: int) -> float:
    """p_d of Eq. (2.4.2) at t = 0: q = p_d^4, q = 1 - (1 - P_DL)^(1/K)."""
    return (1.0 - (1.0 - p_dl) ** (1.0 / k)) ** 0.25


def _atc10_pf(x_db: float, p_d: float) -> float:
    """p_f = Q(1/sqrt(x) - Q^-1(1 - p_d)) (scipy.stats.norm), x = J/(P0 B tau)."""
    return float(stats.norm.sf(1.0 / math.sqrt(10 ** (x_db / 10)) - stats.norm.ppf(p_d)))


def _hit(pf: float, n: float) -> float:
    """1 - (1 - p_f)^n, as -expm1(n log1p(-p_f))."""
    return -math.expm1(n * math.log1p(-pf))


def _atc10_adl(
    pf: float, p_dl: float, k: int, counts: tuple[float, float, float], pdl_factor: bool = True
) -> float:
    """N_ADL / N_T = 1/2 (N / N_T) P_DL G^(K-1) F, t = 0, N = 0.1 N_T, in plain probabilities."""
    n_a, n_b, n_v = counts
    f = _hit(pf, n_a) * _hit(pf, n_b) ** 3
    g = _hit(pf, n_a) * _hit(pf, n_v) ** 3
    return 0.5 * 0.1 * (p_dl if pdl_factor else 1.0) * g ** (k - 1) * f


def _atc10_fl(pf: float) -> float:
    """N_FL / N_T = (1 - N / N_T) F, t = 0."""
    n_a, n_b, _ = _atc10_counts()
    return 0.9 * _hit(pf, n_a) * _hit(pf, n_b) ** 3


def _crossing_db(count: Callable[[float], float], level: float) -> float:
    """The first dB value where ``count`` reaches ``level``: a 0.5 dB grid from -40 dB to 130 dB and
    bisection (``inf`` if the grid never reaches it)."""
    grid = np.arange(-40.0, 130.0, 0.5)
    idx = next((i for i, x in enumerate(grid) if count(x) > level), None)
    if idx is None:
        return math.inf  # no jammer reaches the level (the count's supremum lies below it)
    lo, hi = grid[idx - 1], grid[idx]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if count(mid) < level else (lo, mid)
    return 0.5 * (lo + hi)


@functools.cache
def _atc10_direct_x_db(
    p_dl: float, k: int, *, scale: float = 1.0, pdl_factor: bool = True, n_v: float | None = None
) -> float:
    """10 log10 J/(P0 B tau) at which N_ADL = 0.01 N_T, t = 0, in plain probabilities (above);
    without ``pdl_factor`` the bound 1/2 N G^(K-1) F alone."""
    p_d, counts = _atc10_pd(p_dl, k), _atc10_counts(scale, n_v)
    return _crossing_db(lambda x: _atc10_adl(_atc10_pf(x, p_d), p_dl, k, counts, pdl_factor), 0.01)


@functools.cache
def _atc10_fl_x_db(p_dl: float, k: int, fraction: float = 0.99) -> float:
    """10 log10 J/(P0 B tau) at which N_FL reaches ``fraction`` of its supremum 0.9 N_T, t = 0."""
    p_d = _atc10_pd(p_dl, k)
    return _crossing_db(lambda x: _atc10_fl(_atc10_pf(x, p_d)), fraction * 0.9)


# Table 2.1's design points (K, P_DL) and its printed K = 1000, P_DL = 0.999 entry, typed in
_TABLE_21 = ((10, 0.88), (10, 0.999), (100, 0.88), (100, 0.999), (1000, 0.98), (1000, 0.999))
_TABLE_21_FINITE = tuple(r for r in _TABLE_21 if r != (1000, 0.98))
_TABLE_21_K1000_PRINTED = 77.0


def _atc10_ceiling(p_dl: float, k: int = 1000) -> float:
    """The N_ADL bound as the jammer grows without limit: plain probabilities at 300 dB, where p_f
    is p_d to double precision."""
    return _atc10_adl(_atc10_pf(300.0, _atc10_pd(p_dl, k)), p_dl, k, _atc10_counts())


def _atc10_critical_p_dl() -> float:
    """Bisection (100 halvings of [0.98, 0.9999]) of the K = 1000 ceiling against 0.01 N_T."""
    lo, hi = 0.98, 0.9999
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _atc10_ceiling(mid) < 0.01 else (lo, mid)
    return 0.5 * (lo + hi)


def _atc10_ln_adl_k1000(erp_dbw: float) -> float:
    return math.log(
        _atc10_adl(_atc10_pf(erp_dbw - 50.0, _atc10_pd(0.999, 1000)), 0.999, 1000, _atc10_counts())
    )


def _atc10_k1000_slope() -> float:
    erp = _atc10_direct_x_db(0.999, 1000) + 50.0
    return (_atc10_ln_adl_k1000(erp + 0.01) - _atc10_ln_adl_k1000(erp - 0.01)) / 0.02


def _atc10_erf_mc_band() -> float:
    """Sampling standard deviation of the Monte Carlo coefficient (10^6 samples, x = 1, p_d = 1/2):
    p_f = Q(1) from a binomial count, sqrt(p_f (1 - p_f) / n), and from the sample median used as
    the threshold, phi(1) sqrt(1/4 / n) / phi(0); c = erfinv(1 - 2 p_f) moves by
    sqrt(pi) exp(c^2) per unit p_f."""
    n = 1_000_000
    pf = float(stats.norm.sf(1.0))
    sd_pf = math.hypot(
        math.sqrt(pf * (1 - pf) / n), stats.norm.pdf(1.0) * math.sqrt(0.25 / n) / stats.norm.pdf(0.0)
    )
    return math.sqrt(math.pi) * math.exp(0.5) * sd_pf


def _atc10_direct_pf(p_dl: float, k: int) -> float:
    """p_f at the plain-probability crossing."""
    x_db = _atc10_direct_x_db(p_dl, k)
    q = 1.0 - (1.0 - p_dl) ** (1.0 / k)
    return float(stats.norm.sf(1.0 / math.sqrt(10 ** (x_db / 10)) - stats.norm.ppf(q**0.25)))


def _atc10_half_shift() -> float:
    return max(
        _atc10_direct_x_db(p, k, scale=0.5) - _atc10_direct_x_db(p, k)
        for k, ps in ((1, (0.88, 0.9, 0.99, 0.999)), (10, (0.88, 0.999)))
        for p in ps
    )


def _atc10_pdl_factor_shift() -> float:
    """Over K = 1 at P_DL 0.88, 0.9, 0.99, 0.999 and Table 2.1's finite entries (K, P_DL) = (10, 0.88),
    (10, 0.999), (100, 0.88), (100, 0.999), (1000, 0.999), typed in."""
    points = [(1, p) for p in (0.88, 0.9, 0.99, 0.999)] + [
        (10, 0.88),
        (10, 0.999),
        (100, 0.88),
        (100, 0.999),
        (1000, 0.999),
    ]
    return max(_atc10_direct_x_db(p, k) - _atc10_direct_x_db(p, k, pdl_factor=False) for k, p in points)


# Table 1.1 as printed, typed in: (K, ERP dBW, rf dBW, diameter ft, beamwidth deg)
_TABLE_11 = ((1, 33, 15, 2, 15), (10, 43, 20, 4, 12), (100, 53, 23, 8, 5), (1000, 77, 40, 18, 2))


def _dish_gain(diameter_ft: float) -> float:
    """eta (pi D / lambda)^2 of a parabolic dish (the assumed frequency and efficiency; feet and c
    from scipy.constants)."""
    from navcore.papers import atc10_jamming as pj

    lam = sc.c / pj.IN.dish_frequency_hz
    return pj.IN.dish_efficiency * (math.pi * diameter_ft * sc.foot / lam) ** 2


def _dish_beamwidth_for_gain(gain_db: float) -> float:
    """70 lambda / D for the dish of that gain: D / lambda = sqrt(G / eta) / pi, so 70 pi sqrt(eta / G)."""
    from navcore.papers import atc10_jamming as pj

    return 70 * math.pi * math.sqrt(pj.IN.dish_efficiency / 10 ** (gain_db / 10))


def _table11_rf_misfit(row: int) -> float:
    _, erp, rf, dia, _ = _TABLE_11[row]
    return abs(rf - (erp - 10 * math.log10(_dish_gain(dia))))


def _table11_bw_misfit(row: int) -> float:
    _, erp, rf, _, bw = _TABLE_11[row]
    return abs(bw - _dish_beamwidth_for_gain(erp - rf))


def _ma1_window_empty(pf: float, n: int = 24, half_width: float = 9.0, step: float = 2e-3) -> float:
    """Exact probability that n samples y_k = (z_k + z_(k+1)) / sqrt(2), z i.i.d. N(0, 1), all stay
    below Q^-1(p_f): the chain z_1, z_2, ... carried on a grid (trapezoid cumulative sums,
    numpy interpolation), f_(k+1)(z') = phi(z') int f_k(z) [z <= sqrt(2) u - z'] dz."""
    u = float(stats.norm.isf(pf))
    z = np.arange(-half_width, half_width + step / 2, step)
    phi = np.exp(-0.5 * z * z) / math.sqrt(2 * math.pi)
    f = phi.copy()
    for _ in range(n):
        cum = np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * step)])
        f = phi * np.interp(math.sqrt(2) * u - z, z, cum, left=0.0, right=cum[-1])
    return float(np.sum(0.5 * (f[1:] + f[:-1]) * step))


def _ma1_window_empty_rho(
    pf: float, rho: float, n: int = 24, half_width: float = 9.0, step: float = 2e-3
) -> float:
    """Exact probability that n samples y_k = a z_k + b z_(k+1), z i.i.d. N(0, 1), a^2 + b^2 = 1 and
    a b = rho (neighbours correlated rho, none beyond), all stay below Q^-1(p_f): the chain of z
    carried on a grid as in :func:`_ma1_window_empty`,
    f_(k+1)(z') = phi(z') int f_k(z) [a z <= u - b z'] dz."""
    u = float(stats.norm.isf(pf))
    a = math.sqrt((1 + math.sqrt(1 - 4 * rho * rho)) / 2)
    b = rho / a
    z = np.arange(-half_width, half_width + step / 2, step)
    phi = np.exp(-0.5 * z * z) / math.sqrt(2 * math.pi)
    f = phi.copy()
    for _ in range(n):
        cum = np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * step)])
        f = phi * np.interp((u - b * z) / a, z, cum, left=0.0, right=cum[-1])
    return float(np.sum(0.5 * (f[1:] + f[:-1]) * step))


def _atc10_exact_window_ratio(end: str) -> float:
    """The grid chain at the Table 2.1 threshold p_f and an end of the assumed correlation range
    (both read from the model's declarations), over (1 - p_f)^n."""
    from navcore.papers import atc10_jamming as model
    from navcore.papers import atc10_jamming_appendices as cj

    pf, n = cj.window_pf(), cj.window_n()
    rho = float(getattr(model.IN_COV.input("neighbour_correlation"), end))
    return _ma1_window_empty_rho(pf, rho, n) / (1 - pf) ** n


def _atc10_window(pf: float) -> tuple[float, float, float]:
    """(exact correlated empty probability, (1 - p_f)^24, sampling standard deviation of the
    400 000-trial estimate) for the page's 24-sample window."""
    exact = _ma1_window_empty(pf)
    return exact, (1 - pf) ** 24, math.sqrt(exact * (1 - exact) / 400_000)


def _atc10_window_dln(pf: float = 0.27) -> tuple[float, float]:
    """3 (K - 1)[ln(1 - e_c) - ln(1 - e_f)] at K = 1000 with the exact e_c, and its sampling
    standard deviation 3 (K - 1) sd / (1 - e_c)."""
    exact, formula, sd = _atc10_window(pf)
    return 3 * 999 * (math.log1p(-exact) - math.log1p(-formula)), 3 * 999 * sd / (1 - exact)


def _brute_cross_energy(ci: np.ndarray, cj: np.ndarray, oversample: int = 200) -> float:
    """int X_ij(t)^2 dt of the rectangular-chip waveforms' cross-correlation (unit chips, each code
    scaled to a unit-peak autocorrelation), by fine-grid correlation (scipy.signal) and Riemann sums:
    the left side of Parseval's identity that (F.6) rests on."""
    dt = 1.0 / oversample
    si = np.repeat(np.asarray(ci, float), oversample) / math.sqrt(ci.size)
    sj = np.repeat(np.asarray(cj, float), oversample) / math.sqrt(cj.size)
    x = signal.correlate(si, sj, mode="full", method="fft") * dt
    return float(np.sum(x**2) * dt)


def _atc10_f5_codes() -> tuple[np.ndarray, list[np.ndarray]]:
    """The page's seeded codes: 31 chips, the wanted one and four interferers (seed 1), typed in."""
    rng = np.random.default_rng(1)
    ci = rng.choice([-1.0, 1.0], 31)
    return ci, [rng.choice([-1.0, 1.0], 31) for _ in range(4)]


def _atc10_f5_power() -> float:
    ci, cjs = _atc10_f5_codes()
    return sum(_brute_cross_energy(ci, cj) for cj in cjs) / 2.0


def _atc10_f5_bound() -> float:
    ci, cjs = _atc10_f5_codes()
    wi = _brute_zakai(ci)
    return sum(1.0 / (4.0 * math.sqrt(wi * _brute_zakai(cj))) for cj in cjs)


def _atc10_w_random_1023() -> float:
    rng = np.random.default_rng(3)
    return float(np.mean([_brute_zakai(rng.choice([-1.0, 1.0], 1023)) for _ in range(20)]))


def _atc10_w_ideal(n: int = 10_000) -> float:
    """Closed form: R is 1 at 0, +-1/L alternating over L + e lags each side (e the assumed extra
    lags) and back to 0 one lag later (a chip waveform's autocorrelation is continuous); piecewise
    linear, int R^2 = 2 [(1 + 1/L + 1/L^2) + (L + e - 1) / L^2 + 1 / L^2] / 3."""
    from navcore.papers import atc10_multiple_access as pm

    e = int(pm.IN.fig311_extra_lags)
    energy = (
        2
        * (
            Fraction(1)
            + Fraction(1, n)
            + Fraction(1, n * n)
            + Fraction(n + e - 1, n * n)
            + Fraction(1, n * n)
        )
        / 3
    )
    return float(1 / (2 * energy))


# Reference [1]'s worked example as the paper prints it (end of Sec. 3.8), typed in:
# N = 2e5 a second, B = 10 MHz, alpha = 1 s, theta = 1/2, tau/alpha = 1e-5 (Fig. 3.10).
_EX_N, _EX_B, _EX_ALPHA, _EX_THETA, _EX_R = 200_000, 10_000_000, 1, Fraction(1, 2), 1e-5


def _ex_power() -> Fraction:
    return Fraction(_EX_N - 1, _EX_B * _EX_ALPHA)


def _ex_exp_g() -> float:
    """Exp_g under the ledger's reading of p (the convention noise_density_reading)."""
    from navcore.papers import atc10_multiple_access as pm

    return float(_EX_THETA**2 / (2 * Fraction(pm.IN.noise_density_reading) * _ex_power()))


def _chernoff_exponent(n: float, exp_g: float, r: float = _EX_R) -> float:
    """Chernoff exponent of the multiple-access noise, maximised numerically (scipy
    minimize_scalar): sup_rho [rho theta - (n - 1) ln(1 - q + q cosh(rho a))], q = 2 tau/alpha,
    a^2 = p / ((n - 1) q) (the noise power p shared by the overlaps), with theta fixed by
    Exp_g = theta^2 / (2 p n / (n - 1)) at any p (Eqs. (3.7.21)-(3.7.24))."""
    q = 2 * r
    p = 2e-3
    theta = math.sqrt(2 * p * n / (n - 1) * exp_g)
    a = math.sqrt(p / ((n - 1) * q))

    def minus(rho: float) -> float:
        return -(rho * theta - (n - 1) * math.log1p(q * (math.cosh(rho * a) - 1)))

    hi = 1.0
    while minus(2 * hi) < minus(hi):
        hi *= 2
    res = optimize.minimize_scalar(
        minus, bounds=(0.0, 2 * hi), method="bounded", options={"xatol": 1e-12 * hi}
    )
    return -float(res.fun)


def _psi_cubic(alpha: float) -> float:
    """psi as the real root of psi^3 + q psi - q = 0, q = 27 alpha / 4 (numpy.roots; ATC-10 Sec. 4.5)."""
    q = 27.0 * alpha / 4.0
    roots = np.roots([1.0, 0.0, q, -q])
    return float(next(r.real for r in roots if abs(r.imag) < 1e-9 * abs(r)))


def _psi_edge_error_pct() -> float:
    """Eq. (4.5.38)'s two forms as printed, 1.5 2^(1/3) [alpha^(1/3) - (alpha/2)^(2/3)] at alpha = 0.3
    and 1 - 4 / (27 alpha) at alpha = 1, against the cubic's root."""
    small = 1.5 * 2 ** (1 / 3) * (0.3 ** (1 / 3) - (0.3 / 2) ** (2 / 3))
    large = 1 - 4 / 27
    return 100 * max(abs(small / _psi_cubic(0.3) - 1), abs(large / _psi_cubic(1.0) - 1))


def _psk_one_over_6l() -> float:
    """Mean square of a random-code interferer's normalised correlation given overlap, in the
    continuum of delays: at a delay of d code lengths (uniform over (-1, 1)) a whole-chip lag sums
    L (1 - |d|) random chip products (variance (1 - |d|) / L), a uniform fractional chip offset f
    mixes two uncorrelated lags as (1 - f)^2 + f^2, and a uniform carrier phase gives E[cos^2] =
    1/2 (each mean by scipy quad)."""
    from navcore.papers import atc10_multiple_access as pm

    mix = integrate.quad(lambda f: (1 - f) ** 2 + f**2, 0.0, 1.0)[0]
    overlap = integrate.quad(lambda d: 1 - abs(d), -1.0, 1.0, points=[0.0])[0] / 2
    phase = integrate.quad(lambda ph: math.cos(ph) ** 2, 0.0, 2 * math.pi)[0] / (2 * math.pi)
    return phase * mix * overlap / pm.IN.psk_chips


# --- ATC-10 Sec. 4: the geometry of Table 4.1 by hand -----------------------------------------
# Table 4.2 as printed, typed in (its beta and trace columns)
_TABLE_42 = {
    "I": {"beta": 0.0543, "trace_all": 7.84, "trace_123": 9.39},
    "II": {"beta": 0.00355, "trace_all": 3.99, "trace_123": 14.9},
}


def _atc10_radius(which: str) -> float:
    """The synchronous orbit (brentq of GM/r^2 = w^2 r with the declared GM and period) over the
    declared Earth radius, or the declared fitted ratio."""
    from navcore.papers import atc10_tracking_geometry as paper

    if which == "fit":
        return float(paper.IN.radius_ratio)
    w = 2 * math.pi / paper.IN.orbit_period_s
    gm = paper.IN.gm_m3_s2
    r = optimize.brentq(lambda x: gm / x**2 - w**2 * x, 1e7, 1e8, xtol=1e-6, rtol=1e-15)
    return r / paper.IN.earth_radius_m


def _unit_sphere(lat_deg: float, lon_deg: float) -> np.ndarray:
    la, lo = math.radians(lat_deg), math.radians(lon_deg)
    return np.array([math.cos(la) * math.cos(lo), math.cos(la) * math.sin(lo), math.sin(la)])


def _atc10_los(example: str, which: str, aircraft_height: bool = False) -> np.ndarray:
    """Unit vectors satellite -> aircraft of a Table 4.1 example (the declared sub-satellite points
    and aircraft position), the aircraft on the unit sphere or, with ``aircraft_height``, at the
    declared height; a mirror of the longitudes changes none of the invariants below."""
    from navcore.papers import atc10_tracking_geometry as paper

    r = _atc10_radius(which)
    h = 1 + paper.IN.aircraft_height_m / paper.IN.earth_radius_m if aircraft_height else 1.0
    ac = h * _unit_sphere(*paper.aircraft_lat_lon())
    rows = [ac - r * _unit_sphere(lat, lon) for lat, lon in paper.table_4_1(example)]
    return np.array([v / np.linalg.norm(v) for v in rows])


def _atc10_invariants(example: str, which: str) -> dict[str, float]:
    """beta = K - |projection of 1 on F's columns|^2, tr (F'F)^-1 = sum 1/s_i^2 and, for three rows,
    1'(F F')^-1 1 = sum (u_i . 1)^2 / s_i^2, all from numpy's SVD of F."""
    F = _atc10_los(example, which)
    ones = np.ones(F.shape[0])
    u, sv, _ = np.linalg.svd(F, full_matrices=False)
    u3, sv3, _ = np.linalg.svd(F[:3])
    return {
        "beta": float(ones @ ones - np.sum((u.T @ ones) ** 2)),
        "trace_all": float(np.sum(1 / sv**2)),
        "trace_123": float(np.sum(1 / sv3**2)),
        "s_123": float(np.sum((u3.T @ np.ones(3)) ** 2 / sv3**2)),
    }


def _atc10_zenith_max(which: str) -> float:
    """Largest zenith angle of Example I's satellites: for central angle g between the aircraft (on
    the unit sphere) and a satellite at radius r, z = atan2(r sin g, r cos g - 1)."""
    from navcore.papers import atc10_tracking_geometry as paper

    r = _atc10_radius(which)
    ac = _unit_sphere(*paper.aircraft_lat_lon())
    out = []
    for lat, lon in paper.table_4_1("I"):
        g = math.acos(float(np.clip(ac @ _unit_sphere(lat, lon), -1, 1)))
        out.append(math.degrees(math.atan2(r * math.sin(g), r * math.cos(g) - 1)))
    return max(out)


def _atc10_misses() -> dict[tuple[str, str], float]:
    return {
        (ex, c): _atc10_invariants(ex, "phys")[c] / _TABLE_42[ex][c] - 1
        for ex in ("I", "II")
        for c in ("beta", "trace_all", "trace_123")
    }


def _atc10_best_triplet() -> tuple[tuple[int, ...], float]:
    """Brute force over every triplet of Example II's satellites (synchronous orbit): the smallest
    position trace by SVD of the geometry by hand, and its triplet."""
    import itertools

    F = _atc10_los("II", "phys")
    traces = {
        t: float(np.sum(1 / np.linalg.svd(F[list(t)], compute_uv=False) ** 2))
        for t in itertools.combinations(range(F.shape[0]), 3)
    }
    best = min(traces, key=traces.__getitem__)
    return best, traces[best]


def _table_43_row(t: dict[str, float], sigma0: float) -> dict[str, float]:
    """Table 4.3 by hand (Eqs. (4.5.27), (4.5.32)-(4.5.35) as the book reads them): alpha =
    (8/27) sigma0^2 beta / sigma^2, psi the cubic's root, sd_N = sigma sqrt(tr + (psi/beta) S) and
    sd_(N+1) = sigma sqrt(tr3 + gamma S3), gamma = (psi + (27/8) alpha (2/psi)) / beta; sigma = 50 ns
    and 1 ft a nanosecond, as the paper prints them; sd_0 = sigma sqrt(tr + S / beta) without tracking."""
    sigma = 50.0
    alpha = 8 / 27 * sigma0**2 * t["beta"] / sigma**2
    psi = _psi_cubic(alpha)
    gamma = (psi + 27 / 8 * alpha * 2 / psi) / t["beta"]
    return {
        "psi": psi,
        "sd0": sigma * math.sqrt(t["trace_all"] + t["s_all"] / t["beta"]),
        "sdN": sigma * math.sqrt(t["trace_all"] + psi / t["beta"] * t["s_all"]),
        "sdN1": sigma * math.sqrt(t["trace_123"] + gamma * t["s_123"]),
    }


# Table 4.2's Example II as printed, and Table 4.3's printed sd_N of Example II at 5 ns, typed in
_TABLE_42_II = {"beta": 0.00355, "trace_all": 3.99, "trace_123": 14.9, "s_all": 1.16, "s_123": 14.3}
_TABLE_43_SDN_II_5 = 205.0


_TABLE_42_I = {"beta": 0.0543, "trace_all": 7.84, "trace_123": 9.39, "s_all": 1.30, "s_123": 5.76}


def _atc10_geometry_inputs(example: str, which: str) -> dict[str, float]:
    """Table 4.2's columns of ``example`` from the geometry by hand (SVD) at ``which`` radius."""
    F = _atc10_los(example, which)
    u, sv, _ = np.linalg.svd(F, full_matrices=False)
    out = _atc10_invariants(example, which)
    out["s_all"] = float(np.sum((u.T @ np.ones(F.shape[0])) ** 2 / sv**2))
    return out


def _atc10_phys_lowering() -> list[float]:
    printed = {"I": _TABLE_42_I, "II": _TABLE_42_II}
    return [
        1 - _table_43_row(_atc10_geometry_inputs(ex, "phys"), s0)[c] / _table_43_row(printed[ex], s0)[c]
        for ex in ("I", "II")
        for s0 in (5.0, 50.0, 500.0)
        for c in ("sd0", "sdN")
    ]


def _atc10_s123_printed_residual_pct() -> float:
    """1'(F3'F3)^-1 1 in the Earth-fixed frame (the printed (4.5.30)): sum (v_i . 1)^2 / s_i^2 with
    F3 = U S V' by numpy's SVD, against Table 4.2's printed S3 (5.76 and 14.3)."""
    out = []
    for ex, printed in (("I", 5.76), ("II", 14.3)):
        _, sv, vt = np.linalg.svd(_atc10_los(ex, "fit")[:3])
        out.append(abs(float(np.sum((vt @ np.ones(3)) ** 2 / sv**2)) / printed - 1))
    return 100 * max(out)


def _atc10_col5_corrected(example: str, sigma0: float) -> float:
    """Table 4.3 col. (v) by hand from the printed Table 4.2 with S3 = 1'(F3 F3')^-1 1 of the stated
    system (synchronous orbit, the aircraft at its declared height): sum (u_i . 1)^2 / s_i^2 (SVD)."""
    u3, sv3, _ = np.linalg.svd(_atc10_los(example, "phys", aircraft_height=True)[:3])
    t = dict({"I": _TABLE_42_I, "II": _TABLE_42_II}[example])
    t["s_123"] = float(np.sum((u3.T @ np.ones(3)) ** 2 / sv3**2))
    return _table_43_row(t, sigma0)["sdN1"]


def _convexity_limit() -> float:
    """sympy differentiates h(x) = ln(1 - q + q cosh x) twice; scipy brentq finds where
    h'' - h'/x changes sign (q = 2 tau/alpha of Sec. 3.6)."""
    import sympy

    from navcore.papers import atc10_multiple_access as pm

    x = sympy.symbols("x", positive=True)
    q = sympy.Float(2 * pm.IN.tau_over_alpha_sec36)
    h = sympy.log(1 - q + q * sympy.cosh(x))
    margin = sympy.lambdify(x, sympy.diff(h, x, 2) - sympy.diff(h, x) / x, "math")
    return optimize.brentq(lambda v: float(margin(v)), 1.0, 30.0, xtol=1e-14, rtol=1e-14)


def _two_point_upper_efolds() -> float:
    """The page's two-point noise (power 4/75, theta = 1/2, N = 1e7, q = 4e-5): the Chernoff bound
    sup over rho of rho theta - (N - 1) ln(1 - q + q cosh(rho a)) (scipy minimize_scalar) against
    the exact tail sum_K Bin(N - 1, q)(K) P(a (2J - K) >= theta), J ~ Bin(K, 1/2) (scipy.stats)."""
    power, theta, n, q = 4 / 75, 0.5, 10_000_000, 4e-5
    a = math.sqrt(power / ((n - 1) * q))

    def minus(rho: float) -> float:
        return -(rho * theta - (n - 1) * math.log1p(q * (math.cosh(rho * a) - 1)))

    res = optimize.minimize_scalar(
        minus, bounds=(0.0, 50.0 / a), method="bounded", options={"xatol": 1e-10 / a}
    )
    ln_upper = float(res.fun)
    ks = np.arange(0, 4001)
    pk = stats.binom.pmf(ks, n - 1, q)
    j_min = np.ceil((theta / a + ks) / 2 - 1e-12)  # a (2J - K) >= theta
    tail = float(np.sum(pk * stats.binom.sf(j_min - 1, ks, 0.5)))
    return ln_upper - math.log(tail)


def _atc10_fit_worst_pct() -> float:
    """Table 4.2 the paper's way by hand at the fitted radius, the aircraft at its declared height:
    beta, the traces and S from numpy's SVD, col. 5 as the printed (4.5.30) 1'(F3'F3)^-1 1 in the
    Earth-fixed frame; the largest miss against the printed table (typed in)."""
    worst = 0.0
    for ex, printed in (("I", _TABLE_42_I), ("II", _TABLE_42_II)):
        F = _atc10_los(ex, "fit", aircraft_height=True)
        ones = np.ones(F.shape[0])
        u, sv, _ = np.linalg.svd(F, full_matrices=False)
        _, sv3, vt3 = np.linalg.svd(F[:3])
        mine = {
            "beta": float(ones @ ones - np.sum((u.T @ ones) ** 2)),
            "trace_all": float(np.sum(1 / sv**2)),
            "trace_123": float(np.sum(1 / sv3**2)),
            "s_all": float(np.sum((u.T @ ones) ** 2 / sv**2)),
            "s_123": float(np.sum((vt3 @ np.ones(3)) ** 2 / sv3**2)),
        }
        worst = max(worst, *(abs(mine[c] / printed[c] - 1) for c in printed))
    return 100 * worst


ORACLES += [
    # the samples' mean over M = 2001 equally spaced times differs from the time average by
    # ((f_0 + f_M)/2 - mean) / (M - 1): under 1/2000 relative while the range varies by less than its mean
    Oracle("wf01-mean-range-km", _wf_mean_range_km, rtol=1 / 2000, why="scipy quad over the continuous turn"),
    Oracle(
        "wf01-sd-sampling-error-pct",
        lambda: _chi_cv_pct(glued.WF01_LS_TRIALS),
        rtol=1 / (4 * glued.WF01_LS_TRIALS),
        why="chi(n), exact",
    ),
    Oracle(
        "wf02-largest-bound-ratio",
        _wf_bound_ratio_max,
        rtol=1e-7,
        why="central differences, Eq. (9) as printed",
    ),
    Oracle("wf89-bound-ratio", _wf_bound_ratio_max, rtol=1e-7, why="central differences, Eq. (9) as printed"),
    Oracle("wf03-dl-gain", lambda: _wf_filter(_wf_sigma_a_example())[2], rtol=_WF_RTOL, why=_WF_DARE),
    Oracle(
        "wf03-dl-time-constant",
        lambda: _wf_in().ts / _wf_filter(_wf_sigma_a_example())[2],
        rtol=_WF_RTOL,
        why=_WF_DARE,
    ),
    Oracle("wf03-corr-dl-dg", _wf03_corr, rtol=_WF_RTOL, why=_WF_DARE),
    Oracle("wf03-naive-optimism", _wf03_naive_optimism, rtol=_WF_RTOL, why=_WF_DARE),
    Oracle("wf03-generic-tightness-rho1", _wf_tightness_generic_rho1, rtol=1e-9, why="rho = 1 closed form"),
    Oracle("wf89-rem2-generic", _wf_tightness_generic_rho1, rtol=1e-9, why="rho = 1 closed form"),
    Oracle("wf03-isotropic-tightness-rho0", _wf_tightness_isotropic_rho0, rtol=1e-12, why="exact fractions"),
    Oracle(
        "wf03-large-qt-change-pct",
        lambda: 100 * (math.hypot(1.0, 0.2 / 2.0) - 1),
        rtol=1e-10,
        why="closed form sqrt(1 + (sigma_N / sigma_T)^2) - 1",
    ),
    Oracle(
        "wf04-trace-reading-100ug-db",
        lambda: _wf_improvement_db(_wf_sigma_a_example(), 2.0) + 10 * math.log(3) / math.log(10),
        atol=_WF_DB_ATOL,
        why=_WF_DARE,
    ),
    Oracle("wf04-prior-instead-shift-db", _wf_prior_instead_shift_db, atol=_WF_DB_ATOL, why=_WF_DARE),
    Oracle(
        "wf04-sigma-dl-max",
        lambda: math.sqrt(_wf_filter(_wf_in().sigma_a_high)[1]),
        rtol=_WF_RTOL,
        why=_WF_DARE,
    ),
    # the paper's sigma_G = 1 Hz, f_L1/c = 5.25 1/m and sigma_N = 0.02 m/s (Sec. IV.D), typed in
    Oracle("wf04-gps-velocity-sigma", lambda: float(1 / Fraction("5.25")), rtol=1e-15, why="printed values"),
    Oracle(
        "wf04-gps-velocity-over-sigma-n",
        lambda: float(1 / Fraction("5.25") / Fraction("0.02")),
        rtol=1e-15,
        why="printed values",
    ),
    Oracle(
        "wf04-sigma-d-over-sigma-n",
        lambda: _wf_sigma_d(_wf_sigma_a_example(), 2.0) / 0.02,
        rtol=_WF_RTOL,
        why=_WF_DARE,
    ),
    Oracle("wf04-gps-gain-max-db", _wf_gps_gain_max_db, atol=_WF_DB_ATOL, why=_WF_DARE),
    Oracle("wf89-gps-gain", _wf_gps_gain_max_db, atol=_WF_DB_ATOL, why=_WF_DARE),
    Oracle("wf04-three-vs-one-db", _wf_three_vs_one_db, atol=_WF_DB_ATOL, why=_WF_DARE),
    Oracle(
        "wf04-gps-gain-wide-db",
        lambda: _wf_improvement_db(0.3, 2.0, 0) - _wf_improvement_db(0.3, 2.0, 3),
        atol=_WF_DB_ATOL,
        why=_WF_DARE,
    ),
    # central differences to ~1e-8, amplified by the 4-parameter fit's conditioning (below 1e4)
    Oracle("wf89-leverage-z", lambda: _wf_leverage()["z"], rtol=1e-4, why="Eq. (6) by hand"),
    Oracle("wf89-leverage-white", lambda: _wf_leverage()["white"], rtol=1e-4, why="Eq. (6) by hand"),
    Oracle("wf89-eq20-block", _wf_eq20_block, rtol=1e-12, why="the seeded joint entry by entry"),
    Oracle("wf89-eq24-ratio", lambda: 100**-0.5, rtol=1e-15, why="P_N = sigma_N I scales as the unit"),
    # a seeded run of 200 paths: five sampling standard deviations of its RMS
    Oracle(
        "wf05-sigma-dl", lambda: math.sqrt(_wf_filter(_wf_sigma_a_example())[1]), rtol=_WF_RTOL, why=_WF_DARE
    ),
    # the samples' mean over M = 200 times differs from the time average by at most 1/199 of the
    # spread of u_z^2 (under its mean here); the square root halves it
    Oracle("wf05-uz", _wf_uz_rms, rtol=1 / 2 / 199, why="scipy quad over the continuous turn"),
    # the seeded flights' statistics: the expected value, within five sampling standard deviations
    Oracle(
        "wf05-vib-rms",
        lambda: _wf05_vib_rms()[0],
        band=lambda: 5 * _wf05_vib_rms()[1],
        why="the vibration's exact moments",
    ),
    Oracle(
        "wf05-freq-err",
        lambda: 10e9 / sc.c * _wf05_vib_rms()[0] * _wf_uz_rms(),
        band=lambda: 10e9 / sc.c * 5 * _wf05_vib_rms()[1] * _wf_uz_rms(),
        why="f0/c times the vibration's exact RMS and the quad u_z",
    ),
    Oracle(
        "wf05-freq-err-over-noise",
        lambda: 10e9 / sc.c * _wf05_vib_rms()[0] * _wf_uz_rms() / 1.0,
        band=lambda: 10e9 / sc.c * 5 * _wf05_vib_rms()[1] * _wf_uz_rms() / 1.0,
        why="the same over the 1 Hz noise",
    ),
    # 60 s of 3 Hz at 50 Hz is 180 whole cycles and one more sample: 1/3000 from whole cycles
    Oracle("wf05-euler-point-rms", _wf05_euler_rms, rtol=1e-3, why="closed-form Euler sum"),
    Oracle(
        "wf05-fed-vel-mm",
        lambda: _wf05_fed_vel_mm()[0],
        band=lambda: 5 * _wf05_fed_vel_mm()[1],
        why="expected federated error, correlated-sample band",
    ),
    Oracle(
        "wf05-vel-gain-db",
        lambda: _wf05_vel_gain_db()[0],
        band=lambda: 5 * _wf05_vel_gain_db()[1],
        why="expected mean squares",
    ),
    # bisection to 1e-16 dB: p_f moves by less than 100 relative per dB here, so 1e-6 holds
    Oracle(
        "atc10-pf-k1000-0.999", lambda: _atc10_direct_pf(0.999, 1000), rtol=1e-6, why="direct probabilities"
    ),
    Oracle("atc10-10-pf-K1-0.88", lambda: _atc10_direct_pf(0.88, 1), rtol=1e-6, why="direct probabilities"),
    Oracle(
        "atc10-10-printed-c1-ln-K1-0.88",
        lambda: 2e7 * math.log1p(-_atc10_direct_pf(0.88, 1)),
        rtol=1e-6,
        why="direct probabilities",
    ),
    # the dB crossings: bisection far below 1e-6 dB, as for the other ERP oracles (+50 dBW: P0 tau B = 1e5 W)
    Oracle(
        "atc10-erp-half-K100-0.88",
        lambda: _atc10_direct_x_db(0.88, 100, scale=0.5) + 50.0,
        atol=1e-6,
        why="direct probabilities, half the samples",
    ),
    Oracle(
        "atc10-erp-half-K100-0.999",
        lambda: _atc10_direct_x_db(0.999, 100, scale=0.5) + 50.0,
        atol=1e-6,
        why="direct probabilities, half the samples",
    ),
    Oracle("atc10-half-shift-small-k", _atc10_half_shift, atol=2e-6, why="direct probabilities"),
    Oracle("atc10-pdl-factor-shift", _atc10_pdl_factor_shift, atol=2e-6, why="direct probabilities"),
    Oracle(
        "atc10-v-alpha-over-c-us",
        lambda: 600 * sc.mile / 3600 * 1.0 / sc.c * 1e6,
        rtol=1e-12,
        why="600 mph, alpha = 1 s, scipy.constants",
    ),
    Oracle(
        "atc10-11-adl-erp-0.9",
        lambda: _atc10_direct_x_db(0.9, 1) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-11-gap-adl",
        lambda: _atc10_direct_x_db(0.9, 1) - _atc10_direct_x_db(0.999, 1),
        atol=2e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-11-fl-level-spread",
        lambda: _atc10_fl_x_db(0.88, 1, 0.999) - _atc10_fl_x_db(0.88, 1, 0.5),
        atol=2e-6,
        why="direct probabilities",
    ),
    Oracle("atc10-12-fig2.4-x", lambda: _atc10_direct_x_db(0.88, 10), atol=1e-6, why="direct probabilities"),
    Oracle(
        "atc10-12-fig2.16-x", lambda: _atc10_direct_x_db(0.999, 1000), atol=1e-6, why="direct probabilities"
    ),
    # p_f is p_d to 1e-15 at 300 dB; G^999 amplifies a p_f error by under 1e3
    Oracle(
        "atc10-12-ceiling-K1000-0.88", lambda: _atc10_ceiling(0.88), rtol=1e-8, why="direct probabilities"
    ),
    Oracle(
        "atc10-12-ceiling-K1000-0.98", lambda: _atc10_ceiling(0.98), rtol=1e-8, why="direct probabilities"
    ),
    Oracle(
        "atc10-12-ceiling-K1000-0.999", lambda: _atc10_ceiling(0.999), rtol=1e-8, why="direct probabilities"
    ),
    Oracle(
        "atc10-12-fl-erp-lo",
        lambda: min(_atc10_fl_x_db(p, k) for k, p in _TABLE_21) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-12-fl-erp-hi",
        lambda: max(_atc10_fl_x_db(p, k) for k, p in _TABLE_21) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-12-fl-pf",
        lambda: float(np.median([_atc10_pf(_atc10_fl_x_db(p, k), _atc10_pd(p, k)) for k, p in _TABLE_21])),
        rtol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-12-adl-pf-lo",
        lambda: min(_atc10_pf(_atc10_direct_x_db(p, k), _atc10_pd(p, k)) for k, p in _TABLE_21_FINITE),
        rtol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-12-adl-pf-hi",
        lambda: max(_atc10_pf(_atc10_direct_x_db(p, k), _atc10_pd(p, k)) for k, p in _TABLE_21_FINITE),
        rtol=1e-6,
        why="direct probabilities",
    ),
    Oracle("atc10-12-k1000-critical", _atc10_critical_p_dl, rtol=1e-9, why="bisection of the direct ceiling"),
    Oracle(
        "atc10-12-erp-K1000-0.999",
        lambda: _atc10_direct_x_db(0.999, 1000) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-12-K1000-below-printed",
        lambda: _TABLE_21_K1000_PRINTED - (_atc10_direct_x_db(0.999, 1000) + 50.0),
        atol=1e-6,
        why="direct probabilities, the printed 77 dBW",
    ),
    Oracle("atc10-12-K1000-slope", _atc10_k1000_slope, rtol=1e-6, why="direct probabilities"),
    Oracle(
        "atc10-12-K1000-misread-pct",
        lambda: 100 * (math.exp(_atc10_ln_adl_k1000(_TABLE_21_K1000_PRINTED)) / 0.01 - 1),
        rtol=1e-6,
        why="direct probabilities at the printed 77 dBW",
    ),
    Oracle(
        "atc10-12-nv23-K1000-0.999",
        lambda: _atc10_direct_x_db(0.999, 1000, n_v=23.0) + 50.0,
        atol=1e-6,
        why="direct probabilities, n_v = 23",
    ),
    Oracle(
        "atc10-12-nv23-small-k",
        lambda: max(
            abs(_atc10_direct_x_db(p, k, n_v=23.0) - _atc10_direct_x_db(p, k))
            for k, p in _TABLE_21_FINITE
            if k <= 100
        ),
        atol=2e-6,
        why="direct probabilities, n_v = 23",
    ),
    Oracle("atc10-12-erf-coef-model", lambda: 1 / math.sqrt(2), rtol=1e-9, why="(D.17): 1/sqrt(2)"),
    Oracle(
        "atc10-12-erf-coef-mc",
        lambda: 1 / math.sqrt(2),
        band=lambda: 5 * _atc10_erf_mc_band(),
        why="(D.17) within five sampling standard deviations",
    ),
    Oracle(
        "atc10-erp-by-K-1-0.88",
        lambda: _atc10_direct_x_db(0.88, 1) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-erp-by-K-10-0.88",
        lambda: _atc10_direct_x_db(0.88, 10) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-erp-by-K-100-0.88",
        lambda: _atc10_direct_x_db(0.88, 100) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-erp-by-K-1000-0.88", lambda: _atc10_direct_x_db(0.88, 1000) + 50.0, why="direct: no crossing"
    ),
    Oracle(
        "atc10-erp-by-K-1-0.999",
        lambda: _atc10_direct_x_db(0.999, 1) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-erp-by-K-10-0.999",
        lambda: _atc10_direct_x_db(0.999, 10) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-erp-by-K-100-0.999",
        lambda: _atc10_direct_x_db(0.999, 100) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-erp-by-K-1000-0.999",
        lambda: _atc10_direct_x_db(0.999, 1000) + 50.0,
        atol=1e-6,
        why="direct probabilities",
    ),
    Oracle("atc10-ceiling-K1000-0.88", lambda: _atc10_ceiling(0.88), rtol=1e-8, why="direct probabilities"),
    Oracle(
        "atc10-step-K100-K1000-0.999",
        lambda: _atc10_direct_x_db(0.999, 1000) - _atc10_direct_x_db(0.999, 100),
        atol=2e-6,
        why="direct probabilities",
    ),
    Oracle("atc10-13-rf-fit-K10", lambda: _table11_rf_misfit(1), rtol=1e-9, why="eta (pi D / lambda)^2"),
    Oracle(
        "atc10-13-rf-fit-others",
        lambda: max(_table11_rf_misfit(i) for i in (0, 2, 3)),
        rtol=1e-9,
        why="eta (pi D / lambda)^2",
    ),
    Oracle(
        "atc10-13-bw-K1-dish", lambda: _dish_beamwidth_for_gain(33 - 15), rtol=1e-9, why="70 pi sqrt(eta / G)"
    ),
    # theta^2 G is the same for both antennas: 20 deg x sqrt(G_2.7 / G_K1), G_2.7 = 10^3.3 / 30, G_K1 = 10^1.8
    Oracle(
        "atc10-13-bw-K1-scaled",
        lambda: 20 * math.sqrt(10**1.5 / 30),
        rtol=1e-12,
        why="the printed 20 deg, 30 W, 33 dBW and the row's 33 and 15 dBW",
    ),
    Oracle(
        "atc10-13-bw-fit-others",
        lambda: max(_table11_bw_misfit(i) for i in (1, 2, 3)),
        rtol=1e-9,
        why="70 pi sqrt(eta / G)",
    ),
    Oracle(
        "atc10-13-30W-gain-db",
        lambda: 33 - 10 * math.log(30) / math.log(10),
        rtol=1e-12,
        why="33 dBW - 10 log10 30",
    ),
    Oracle(
        "atc10-13-2ft-gain-db",
        lambda: 10 * math.log10(_dish_gain(2)),
        rtol=1e-12,
        why="eta (pi D / lambda)^2",
    ),
    Oracle(
        "atc10-13-2ft-rf-w", lambda: 10**3.3 / _dish_gain(2), rtol=1e-11, why="10^3.3 W over the dish gain"
    ),
    Oracle(
        "atc10-pf-threshold-K1-0.88", lambda: _atc10_direct_pf(0.88, 1), rtol=1e-6, why="direct probabilities"
    ),
    # the simulated window (400 000 seeded trials, p_f from 0.01 to 0.27) against the exact chain
    # probability, within five sampling standard deviations (the grid quadrature is good to 1e-6)
    # the page's Genz integration of the 24-dimensional orthant against a grid chain of the MA(1) samples
    Oracle(
        "atc10-14-exact-window-ratio-lo",
        lambda: _atc10_exact_window_ratio("low"),
        rtol=2e-3,
        why="exact MA(1) window by a grid chain",
    ),
    Oracle(
        "atc10-14-exact-window-ratio-hi",
        lambda: _atc10_exact_window_ratio("high"),
        rtol=2e-3,
        why="exact MA(1) window by a grid chain",
    ),
    Oracle(
        "atc10-mc-window-ratio-hi",
        lambda: _atc10_window(0.27)[0] / _atc10_window(0.27)[1],
        band=lambda: 5 * _atc10_window(0.27)[2] / _atc10_window(0.27)[1],
        why="exact MA(1) window by quadrature",
    ),
    Oracle(
        "atc10-mc-window-ratio-lo",
        lambda: _atc10_window(0.01)[0] / _atc10_window(0.01)[1],
        band=lambda: 5 * _atc10_window(0.01)[2] / _atc10_window(0.01)[1],
        why="exact MA(1) window by quadrature",
    ),
    Oracle(
        "atc10-mc-window-dln-k1000",
        lambda: _atc10_window_dln()[0],
        band=lambda: 5 * _atc10_window_dln()[1],
        why="exact MA(1) window by quadrature",
    ),
    Oracle(
        "atc10-mc-window-factor-k1000",
        lambda: math.exp(_atc10_window_dln()[0]),
        band=lambda: math.exp(_atc10_window_dln()[0]) * math.expm1(5 * _atc10_window_dln()[1]),
        why="exact MA(1) window by quadrature",
    ),
    # fine-grid integrals of piecewise-linear functions: the trapezoid error dt^2/12 int (R^2)''
    # is ~1e-5 relative at 200 samples a chip
    Oracle(
        "atc10-23-f5-power", _atc10_f5_power, rtol=2e-4, why="brute-force int X_ij^2, Parseval's other side"
    ),
    Oracle("atc10-23-f5-bound", _atc10_f5_bound, rtol=2e-4, why="brute-force Zakai bandwidths"),
    Oracle("atc10-23-w-random-1023", _atc10_w_random_1023, rtol=2e-4, why="brute-force Zakai bandwidths"),
    Oracle("atc10-23-thm-ratio", lambda: 1 / (4 * _atc10_w_ideal()), rtol=1e-12, why="closed form"),
    Oracle(
        "atc10-22-inverse-p", lambda: float(1 / _ex_power()), rtol=1e-15, why="exact fraction, printed values"
    ),
    Oracle(
        "atc10-22-exp-g-half",
        lambda: float(_EX_THETA**2 / (2 * _ex_power())),
        rtol=1e-15,
        why="exact fraction, printed values",
    ),
    # (3.8.16) is the large-N form of the exact exponent (N for N - 1, terms of order q dropped):
    # O(1/N + q) = 3e-5 relative here; allowed 1e-4 on the exponent and its ratio, and what that
    # becomes on 100 (ratio - 1) (ratio 1.29: 5e-4) and on exp(Exp_g - Exp) (Exp 8.6: 1e-3)
    Oracle(
        "atc10-22-exp-1e5", lambda: _chernoff_exponent(1e5, _ex_exp_g()), rtol=1e-4, why="numerical Chernoff"
    ),
    Oracle(
        "atc10-22-ratio-1e5",
        lambda: _ex_exp_g() / _chernoff_exponent(1e5, _ex_exp_g()),
        rtol=1e-4,
        why="numerical Chernoff",
    ),
    Oracle(
        "atc10-22-optimistic-pct",
        lambda: 100 * (_ex_exp_g() / _chernoff_exponent(_EX_N, _ex_exp_g()) - 1),
        rtol=5e-4,
        why="numerical Chernoff",
    ),
    Oracle(
        "atc10-22-pf-factor",
        lambda: math.exp(_ex_exp_g() - _chernoff_exponent(_EX_N, _ex_exp_g())),
        rtol=1e-3,
        why="numerical Chernoff",
    ),
    Oracle(
        "atc10-31-approx-edge-error-pct", _psi_edge_error_pct, rtol=1e-9, why="the cubic's root, numpy.roots"
    ),
    Oracle("atc10-20-psk-1-6L", _psk_one_over_6l, rtol=1e-12, why="random-code correlation, scipy quad"),
    Oracle(
        "atc10-20-envelope-m3",
        lambda: float(Fraction(4, 5) * Fraction(1, 2) ** 3 + Fraction(1, 5) * 2**3),
        rtol=1e-15,
        why="exact fractions of the envelope's two points (0.5 w.p. 0.8, 2 w.p. 0.2)",
    ),
    # E[cos^3] over a uniform phase grid is 0 exactly: the float sum leaves round-off of at most
    # (terms) x eps x sum |p v^3|, far below 1e-13 for a few hundred terms
    Oracle("atc10-20-model-m3", lambda: 0.0, atol=1e-13, why="zero by symmetry"),
    Oracle(
        "atc10-90-step-per-decade-lo",
        lambda: min(
            _atc10_direct_x_db(0.9, 10) - _atc10_direct_x_db(0.9, 1),
            _atc10_direct_x_db(0.9, 100) - _atc10_direct_x_db(0.9, 10),
        ),
        atol=2e-6,
        why="direct probabilities",
    ),
    Oracle(
        "atc10-90-step-per-decade-hi",
        lambda: max(
            _atc10_direct_x_db(0.9, 10) - _atc10_direct_x_db(0.9, 1),
            _atc10_direct_x_db(0.9, 100) - _atc10_direct_x_db(0.9, 10),
        ),
        atol=2e-6,
        why="direct probabilities",
    ),
    Oracle("atc10-90-ceiling-k1000", lambda: _atc10_ceiling(0.9), rtol=1e-8, why="direct probabilities"),
    Oracle(
        "atc10-90-beamwidth-k1",
        lambda: 20 * math.sqrt(10**1.5 / 30),
        rtol=1e-12,
        why="the printed 20 deg, 30 W, 33 dBW and the row's 33 and 15 dBW",
    ),
    # (3.8.16) against the exact exponent: its large-N remainder O(1/N + q), as for page 22
    Oracle(
        "atc10-90-exp-2e5",
        lambda: _chernoff_exponent(_EX_N, _ex_exp_g()),
        rtol=1e-4,
        why="numerical Chernoff",
    ),
    Oracle(
        "atc10-90-exp-1e5", lambda: _chernoff_exponent(1e5, _ex_exp_g()), rtol=1e-4, why="numerical Chernoff"
    ),
    Oracle(
        "atc10-90-ratio-2e5",
        lambda: _ex_exp_g() / _chernoff_exponent(_EX_N, _ex_exp_g()),
        rtol=1e-4,
        why="numerical Chernoff",
    ),
    Oracle(
        "atc10-90-ratio-1e5",
        lambda: _ex_exp_g() / _chernoff_exponent(1e5, _ex_exp_g()),
        rtol=1e-4,
        why="numerical Chernoff",
    ),
    # the geometry by hand: double-precision SVDs of well-conditioned 3-column matrices (1e-12)
    # after a brentq radius to 1e-15; beta of Example II is a small difference (0.0036 of K = 8:
    # 1e-12 x 8 / 0.0036 ~ 3e-9 relative), so 1e-8 throughout
    Oracle("atc10-30-r-phys", lambda: _atc10_radius("phys"), rtol=1e-9, why="brentq orbit radius"),
    Oracle("atc10-30-zenith-I-phys", lambda: _atc10_zenith_max("phys"), rtol=1e-9, why="spherical triangle"),
    Oracle("atc10-30-zenith-I-fit", lambda: _atc10_zenith_max("fit"), rtol=1e-9, why="spherical triangle"),
    Oracle("atc10-30-beta-phys-I", lambda: _atc10_invariants("I", "phys")["beta"], rtol=1e-8, why="SVD"),
    Oracle("atc10-30-beta-phys-II", lambda: _atc10_invariants("II", "phys")["beta"], rtol=1e-8, why="SVD"),
    Oracle(
        "atc10-30-beta-over-K-I",
        lambda: _atc10_invariants("I", "phys")["beta"] / 7,
        rtol=1e-8,
        why="SVD, K = 7",
    ),
    Oracle(
        "atc10-30-beta-over-K-II",
        lambda: _atc10_invariants("II", "phys")["beta"] / 8,
        rtol=1e-8,
        why="SVD, K = 8",
    ),
    Oracle(
        "atc10-30-trace-phys-I", lambda: _atc10_invariants("I", "phys")["trace_all"], rtol=1e-8, why="SVD"
    ),
    Oracle(
        "atc10-30-trace-phys-II", lambda: _atc10_invariants("II", "phys")["trace_all"], rtol=1e-8, why="SVD"
    ),
    Oracle(
        "atc10-30-trace-123-II", lambda: _atc10_invariants("II", "phys")["trace_123"], rtol=1e-8, why="SVD"
    ),
    Oracle("atc10-30-s123-invariant-I", lambda: _atc10_invariants("I", "fit")["s_123"], rtol=1e-8, why="SVD"),
    Oracle(
        "atc10-30-s123-invariant-II", lambda: _atc10_invariants("II", "fit")["s_123"], rtol=1e-8, why="SVD"
    ),
    Oracle("atc10-32-s123-invariant-I", lambda: _atc10_invariants("I", "fit")["s_123"], rtol=1e-8, why="SVD"),
    Oracle(
        "atc10-32-s123-invariant-II", lambda: _atc10_invariants("II", "fit")["s_123"], rtol=1e-8, why="SVD"
    ),
    Oracle(
        "atc10-30-miss-lo",
        lambda: 100 * min(abs(v) for v in _atc10_misses().values()),
        rtol=1e-6,
        why="SVD against Table 4.2 as printed",
    ),
    Oracle(
        "atc10-30-miss-hi",
        lambda: 100 * max(abs(v) for v in _atc10_misses().values()),
        rtol=1e-6,
        why="SVD against Table 4.2 as printed",
    ),
    Oracle(
        "atc10-30-beta-excess",
        lambda: 100 * max(_atc10_misses()[(ex, "beta")] for ex in ("I", "II")),
        rtol=1e-6,
        why="SVD against Table 4.2 as printed",
    ),
    Oracle(
        "atc10-30-trace-deficit",
        lambda: -100 * float(np.mean([v for (_, c), v in _atc10_misses().items() if c != "beta"])),
        rtol=1e-6,
        why="SVD against Table 4.2 as printed",
    ),
    Oracle(
        "atc10-30-trace-best-II",
        lambda: _atc10_best_triplet()[1],
        rtol=1e-8,
        why="brute force over triplets, SVD",
    ),
    Oracle(
        "atc10-90-best-trace",
        lambda: _atc10_best_triplet()[1],
        rtol=1e-8,
        why="brute force over triplets, SVD",
    ),
    Oracle("atc10-90-123-trace", lambda: _atc10_invariants("II", "phys")["trace_123"], rtol=1e-8, why="SVD"),
    Oracle(
        "atc10-90-best-triplet",
        lambda: ", ".join(str(i + 1) for i in _atc10_best_triplet()[0]),
        why="brute force over triplets, SVD (the same labels)",
    ),
    Oracle(
        "atc10-32-psi-exact-II-5",
        lambda: _table_43_row(_TABLE_42_II, 5.0)["psi"],
        rtol=1e-9,
        why="Table 4.3 by hand",
    ),
    Oracle(
        "atc10-32-sdN-exact-II-5",
        lambda: _table_43_row(_TABLE_42_II, 5.0)["sdN"],
        rtol=1e-9,
        why="Table 4.3 by hand",
    ),
    # (4.5.35) solved for psi in closed form: psi = beta ((sd_N / sigma)^2 - tr) / S (the page's
    # brentq stops within 2e-12 of psi ~ 0.04)
    Oracle(
        "atc10-32-psi-needed-II-5",
        lambda: (
            _TABLE_42_II["beta"]
            * ((_TABLE_43_SDN_II_5 / 50.0) ** 2 - _TABLE_42_II["trace_all"])
            / _TABLE_42_II["s_all"]
        ),
        rtol=1e-9,
        why="(4.5.35) inverted",
    ),
    Oracle(
        "atc10-32-sdN-I-5",
        lambda: _table_43_row(_atc10_geometry_inputs("I", "fit"), 5.0)["sdN"],
        rtol=1e-8,
        why="SVD geometry, by hand",
    ),
    Oracle(
        "atc10-32-sdN1-I-5",
        lambda: _table_43_row(_atc10_geometry_inputs("I", "fit"), 5.0)["sdN1"],
        rtol=1e-8,
        why="SVD geometry, by hand",
    ),
    Oracle(
        "atc10-32-phys-lowering-lo",
        lambda: 100 * min(_atc10_phys_lowering()),
        rtol=1e-7,
        why="SVD geometry and Table 4.3 by hand, the published sigma0 5, 50, 500 ns",
    ),
    Oracle(
        "atc10-32-phys-lowering-hi",
        lambda: 100 * max(_atc10_phys_lowering()),
        rtol=1e-7,
        why="SVD geometry and Table 4.3 by hand, the published sigma0 5, 50, 500 ns",
    ),
    Oracle(
        "atc10-30-s123-printed-residual-pct", _atc10_s123_printed_residual_pct, rtol=1e-6, why="SVD in ECEF"
    ),
    *(
        Oracle(
            f"atc10-32-col5-corrected-{example}-{sigma0:g}",
            lambda example=example, sigma0=sigma0: _atc10_col5_corrected(example, sigma0),
            rtol=1e-8,
            why="Table 4.3 by hand, SVD invariant",
        )
        for example in ("I", "II")
        for sigma0 in (5.0, 50.0, 500.0)
    ),
    Oracle("atc10-21-convexity-limit", _convexity_limit, rtol=1e-9, why="sympy's derivatives, brentq"),
    # the bounded maximisation is flat at its optimum (error ~ xtol^2); the binomial sums to K = 4000
    # (mean 400) leave nothing: 1e-6 on a difference of logs of order 1
    Oracle(
        "atc10-21-upper-efolds",
        _two_point_upper_efolds,
        rtol=1e-6,
        why="numerical Chernoff, scipy binomial sums",
    ),
    Oracle(
        "atc10-30-fit-worst-pct",
        _atc10_fit_worst_pct,
        rtol=1e-6,
        why="SVD geometry by hand, Table 4.2 typed in",
    ),
    Oracle(
        "wf89-eq13-ratio",
        lambda: _wf_eq13_ratio()[0],
        band=lambda: 5 * _wf_eq13_ratio()[1],
        why="exact moments of the printed recursion",
    ),
]


def _atc10_dish_hz() -> float:
    from navcore.papers import atc10_jamming as pj

    return float(pj.IN.dish_frequency_hz)


def _wf_sigma_f_velocity() -> float:
    """A frequency error of sigma_f Hz at the carrier F0 is a radial velocity sigma_f c / F0."""
    from navcore.papers import wf_location_error

    return wf_location_error.SIGMA_F * sc.c / wf_location_error.F0


def _kzl_runs() -> int:
    from navcore.papers.kzl_scenario import N_RUNS

    assert N_RUNS == 30, "the tolerance above is written for 30 runs"
    return N_RUNS


def _sp_runs() -> int:
    from navcore.papers import sp_antijam as spj

    assert spj.IN.runs == 25, "the tolerance above is written for 25 runs"
    return int(spj.IN.runs)


def _n_sec36() -> int:
    from navcore.papers import atc10_multiple_access as pm

    return int(pm.IN.n_sec36)


# --- Across the papers: one filter, one geometry ----------------------------------------------
# SP Table 2.5's error sources as printed, typed in; the two random walks are noises, not states.
_SP_TABLE_25_SOURCES = (
    "accel. bias",
    "accel. scale factor",
    "accel. input axis misalign.",
    "accel. random walk",
    "gyro bias",
    "gyro scale factor",
    "gyro input axis misalign.",
    "gyro random walk",
)


def _sp_free_inertial_states() -> int:
    """Position, velocity and misalignment, and every Table 2.5 source that is not a random walk,
    each three components (one per axis of the triad)."""
    constants = [s for s in _SP_TABLE_25_SOURCES if not s.endswith("random walk")]
    return 3 * len(("position", "velocity", "misalignment")) + 3 * len(constants)


def _sp_noise_only_m(grade: float, minutes: float) -> float:
    """Van Loan oracle: the psi-angle error model of an inertial system at rest at the grade
    latitude, written out (NED; horizontal position and velocity, three angles; Schuler feedback
    -g/R on position, Coriolis -2 Omega x dv, angles driven by -Omega x psi), driven by the
    Table 2.5 column's random walks (micro-g/sqrt(Hz) and deg/h/sqrt(Hz) converted by hand);
    the covariance after ``minutes``, from zero, is the Van Loan block of scipy's expm; the rss
    of the two position variances (m)."""
    from scipy import linalg

    from navcore.papers import sp_missions, sp_tables

    vrw = sp_tables.table_2_5_value("accel_random_walk_micro_g_per_sqrt_hz", grade) * 1e-6 * _G0
    arw = math.radians(sp_tables.table_2_5_value("gyro_random_walk_deg_per_h_per_sqrt_hz", grade)) / 3600
    lat = math.radians(sp_missions.IN.grade_latitude_deg)
    w = 2 * math.pi / _SIDEREAL_DAY
    wn, wd = w * math.cos(lat), -w * math.sin(lat)  # Earth rate in NED: (cos L, 0, -sin L)
    ws2 = _G0 / _WGS84_A
    # x = [r_N, r_E, v_N, v_E, psi_N, psi_E, psi_D]
    F = np.zeros((7, 7))
    F[0, 2] = F[1, 3] = 1.0
    F[2, 0] = F[3, 1] = -ws2
    F[2, 3], F[3, 2] = 2 * wd, -2 * wd  # -2 Omega x dv with dv_D = 0
    F[2, 5], F[3, 4] = _G0, -_G0  # f x psi with f = (0, 0, -g)
    Om = np.array([[0.0, -wd, 0.0], [wd, 0.0, -wn], [0.0, wn, 0.0]])  # Omega x
    F[4:, 4:] = -Om
    Q = np.diag([0, 0, vrw**2, vrw**2, arw**2, arw**2, arw**2])
    M = np.block([[-F, Q], [np.zeros((7, 7)), F.T]]) * (minutes * 60.0)
    E = linalg.expm(M)
    P = E[7:, 7:].T @ E[:7, 7:]
    return math.sqrt(P[0, 0] + P[1, 1])


def _sp21_clock_digits() -> int:
    """Digit-string oracle: the two runs' errors 1 s before reacquisition, taken from the runs
    (not through the registered percentage), written out to 17 significant digits, and the
    number of leading digits the two strings share. It agrees with the registered count (the
    largest d with a relative change below 1e-d) to one digit, the most a carry can move it."""
    from navcore.papers import sp_mission_flights as sc
    from navcore.papers import sp_missions as spm

    runs = sc.initial_error_runs(spm.IN.initial_error_scale)
    t = sc.reacquisition_s() - 1.0
    a, b = (
        f"{float(runs[m].horizontal_position[runs[m].at(t)]):.16e}".replace(".", "")
        for m in ("nominal", "clock offset in ns")
    )
    return next((i for i, (x, y) in enumerate(zip(a, b, strict=True)) if x != y), 17)


def _sp21_position_block(run, rows: str = "position"):
    """Indices of the north and east position states (or of ``rows``) in a run's truth layout."""
    lay = run.truth_layout
    return [lay.index(rows, i) for i in range(3)]


def _sp21_initial_effect_pct(members: tuple[str, ...]) -> float:
    """The runs' own variance histories: the sample nearest 1 s before reacquisition found on the
    time axis (not through the run's lookup), the rss of the north and east variances there (not
    the run's horizontal error), and the largest relative change over ``members`` (%)."""
    from navcore.papers import sp_mission_flights as sms
    from navcore.papers import sp_missions as spm

    runs = sms.initial_error_runs(spm.IN.initial_error_scale)
    t = sms.reacquisition_s() - 1.0

    def error(run) -> float:
        i = int(np.argmin(np.abs(run.t - t)))
        n, e, _ = _sp21_position_block(run)
        return math.sqrt(run.true_var[i, n] + run.true_var[i, e])

    base = error(runs["nominal"])
    return max(100.0 * abs(error(runs[m]) - base) / base for m in members)


def _sp21_coupling_pct() -> float:
    """The head-on runs' final covariance matrices (not their variance histories): the rss of the
    north and east position variances of the loosely and tightly coupled 1 nmi/h systems, and
    their relative difference (%)."""
    from navcore.papers import sp_mission_flights as sms

    def final(arch: str, label: str) -> float:
        run = next(r for s_, r in sms.head_on_approach(arch).items() if s_.label == label)
        n, e, _ = _sp21_position_block(run)
        return math.sqrt(run.final_true[n, n] + run.final_true[e, e])

    return 100.0 * abs(final("loose", "LC 1 nmi/h") / final("tight", "TC 1 nmi/h") - 1.0)


def _sp21_momentary_pct() -> float:
    """Target location written out: the located target is in error by dr + r x psi (psi the
    engine's attitude error, the target level at the assumed bearing and the paper's 8 km), so
    its covariance is A P A' with A = [I, [r x]] on the final position and attitude block; the
    rss of its north and east variances with and without the momentary losses, both grades (%)."""
    from navcore.papers import sp_acquisition as spa
    from navcore.papers import sp_mission_flights as sms
    from navcore.papers import sp_missions as spm

    b = math.radians(sms.IN.target_bearing_deg)
    r = spa.IN.target_range_m * np.array([math.cos(b), math.sin(b), 0.0])
    cross = np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])  # [r x]
    A = np.hstack([np.eye(3), cross])

    def sigma(run) -> float:
        rows = _sp21_position_block(run) + _sp21_position_block(run, "misalignment")
        C = A @ run.final_true[np.ix_(rows, rows)] @ A.T
        return math.sqrt(C[0, 0] + C[1, 1])

    base = sms.helicopter(False)
    lossy = sms.helicopter_momentary_carrier_loss(spm.IN.momentary_loss_s)
    return max(100.0 * abs(sigma(lossy[g]) / sigma(base[g]) - 1.0) for g in (10.0, 1.0))


def _sp_noise_only_outage_m() -> float:
    """:func:`_sp_noise_only_m` for the second Table 2.5 column over the helicopter's jammed minutes."""
    from navcore.papers import sp_mission_flights as sms
    from navcore.papers import sp_tables

    return _sp_noise_only_m(sp_tables.GRADE_LABELS_NMI_PER_H[1], sms.IN.helicopter_jammed_min)


def _across01_dop_by_hand(name: str) -> float:
    """Least squares written out: for ATC-10 and SP, tr of the position block of [F 1]'[F 1]
    inverted, the common unknown a fourth column (ATC-10's geometry by hand, SP's flyby lines of
    sight from its model); for KZL, explicit double differences against the first satellite,
    D (2 I) D' their covariance in single-difference units, H = D F, tr (H' (2 D D')^-1 H)^-1,
    on the sky at the start and at 60 s (the schedule's prose: 8 satellites, then 4)."""
    if name in ("atc-i", "atc-ii"):
        F = _atc10_los(name[4:].upper(), "phys")
    elif name == "sp":
        from navcore.papers import sp_flyby

        F = -np.asarray(sp_flyby.flyby_geometry().u_ned[0])
    else:
        from navcore.papers import kzl_scenario

        n = max(_KZL_SEGMENT_EPOCHS) if name == "kzl" else _across01_kzl_late_n()
        epoch = 0 if name == "kzl" else _KZL_SEGMENT_EPOCHS[n].start
        d = kzl_scenario.table1_sky()[0][epoch, :n]
        F = -d / np.linalg.norm(d, axis=1)[:, None]
        D = np.hstack([-np.ones((n - 1, 1)), np.eye(n - 1)])
        H = D @ F
        return math.sqrt(np.trace(np.linalg.inv(H.T @ np.linalg.inv(2 * D @ D.T) @ H)))
    H = np.hstack([F, np.ones((F.shape[0], 1))])
    return math.sqrt(np.trace(np.linalg.inv(H.T @ H)[:3, :3]))


def _across01_kzl_late_n() -> int:
    """The fewest satellites of four or more in the schedule's prose."""
    return min(n for n in _KZL_SEGMENT_EPOCHS if n >= 4)


ORACLES += [
    Oracle(
        "across01-wf-bound-mm-s",
        lambda: 1e3 * _wf_sigma_d(_wf_sigma_a_example(), _wf_in().sigma_t_medium, 3),
        rtol=_WF_RTOL,
        why=_WF_DARE,
    ),
    # the oracle leaves out the vertical channel's Coriolis coupling 2 Omega_N dv_D (about 0.3 m
    # of 76 m after 19 min) and terms of order dr / R, and takes g0 and the equatorial radius
    # for the local gravity and radii (0.3 % in omega_s^2, ~0.1 % in the result): 1 %
    Oracle("across01-sp-outage-m", _sp_noise_only_outage_m, rtol=0.01, why="Van Loan on the psi-angle model"),
    Oracle("across01-sp-states", _sp_free_inertial_states, why="Table 2.5's sources, typed in"),
    # the covariance engine (Earth rate, transport and Schuler coupling on top) against the closed
    # form sqrt((b t)^2 + N^2 t + sigma0^2): the exercises page holds both within 2 %
    Oracle(
        "across01-kzl-raw-deg",
        lambda: _kzl_closed_heading_deg(False),
        rtol=0.02,
        why="closed form, the exercises page's 2 %",
    ),
    Oracle(
        "across01-kzl-init-deg",
        lambda: _kzl_closed_heading_deg(True),
        rtol=0.02,
        why="closed form, the exercises page's 2 %",
    ),
    # a 4-column normal matrix conditioned ~1 / beta (3e2 for Example II): rounding ~1e-13
    *(
        Oracle(
            f"across01-dop-{n}",
            functools.partial(_across01_dop_by_hand, n),
            rtol=1e-8,
            why="least squares by hand",
        )
        for n in ("atc-i", "atc-ii", "sp", "kzl", "kzl-late")
    ),
    Oracle("across01-kzl-late-n", _across01_kzl_late_n, why="the schedule's prose"),
]


# --- Across the papers: jamming ---------------------------------------------------------------
# As printed, typed in: ATC-10's B = 10 MHz (Sec. 2.4) and tau = 10 usec (Sec. 2.7); SP's code-loop
# loss of lock at J/S = 54 dB (TC) and lock held to 65 dB (DI), Sec. 3.1; the mean Earth radius
# 6371 km (the book's convention for heights above the Earth).
_ATC10_TAU_S = Fraction(10, 1_000_000)
_SP_JS_TC_DB, _SP_JS_DI_DB = 54, 65
_EARTH_MEAN_KM = 6371


def _across02_sync_km() -> float:
    """brentq's synchronous radius less the mean Earth radius, km."""
    return _orbit_radius_km() - _EARTH_MEAN_KM


def _friis_erp_dbw(received_dbw: float, d_m: float) -> float:
    """ERP that free space (isotropic receiver, wavelength c / f_L1) brings down to
    ``received_dbw`` at ``d_m``: the received power P_r = ERP (lambda / (4 pi d))^2 in watts."""
    lam = _C / _F_L1
    p_r = 10 ** (received_dbw / 10)
    return 10 * math.log10(p_r / (lam / (4 * math.pi * d_m)) ** 2)


def _friis_range_km(erp_dbw: float, received_dbw: float) -> float:
    """Range at which free space brings ``erp_dbw`` down to ``received_dbw``: brentq on the received
    power in watts, P_r(d) = ERP (lambda / (4 pi d))^2, over log d."""
    lam = _C / _F_L1
    erp, p_r = 10 ** (erp_dbw / 10), 10 ** (received_dbw / 10)
    x = optimize.brentq(
        lambda lg: math.log(erp * (lam / (4 * math.pi * math.exp(lg))) ** 2 / p_r), 0.0, 40.0, xtol=1e-14
    )
    return math.exp(x) / 1e3


def _sp_signal_dbw() -> float:
    return _sp_in("sp_antijam").signal_dbw


ORACLES += [
    Oracle(
        "across02-tb-db",
        lambda: 10 * math.log10(_ATC10_B * _ATC10_TAU_S),
        rtol=1e-12,
        why="B and tau as printed",
    ),
    Oracle(
        "across02-spread-db",
        lambda: 10 * math.log10(_sp06_q(_sp_in("sp_antijam").wideband_hz) * 10_230_000),
        atol=1e-6,
        why="sine-integral closed form, R_c = 10.23 MHz",
    ),
    Oracle(
        "across02-tc-threshold",
        lambda: _sp06_threshold(_SP_JS_TC_DB),
        rtol=1e-7,
        why="Sec. 3.1's formula, 54 dB",
    ),
    Oracle(
        "across02-di-threshold",
        lambda: _sp06_threshold(_SP_JS_DI_DB),
        rtol=1e-7,
        why="Sec. 3.1's formula, 65 dB",
    ),
    Oracle(
        "across02-di-gain-db", lambda: _SP_JS_DI_DB - _SP_JS_TC_DB, rtol=1e-12, why="the printed J/S limits"
    ),
    # brentq to 1e-15 relative on 42 000 km, less 6371 km
    Oracle("across02-sync-km", _across02_sync_km, rtol=1e-9, why="brentq on the orbit, mean radius typed in"),
    Oracle(
        "across02-erp-tc-sync",
        lambda: _friis_erp_dbw(_sp_signal_dbw() + _SP_JS_TC_DB, 1e3 * _across02_sync_km()),
        atol=1e-8,
        why="Friis in watts, the printed 54 dB",
    ),
    # the direct solver's ERP to 1e-6 dB (its bisection), the range then to 1.2e-7 relative
    Oracle("across02-k1-erp", _atc10_direct_erp(1, 0.88), atol=1e-6, why="direct probabilities, K = 1"),
    Oracle(
        "across02-k1-reach-km",
        lambda: _friis_range_km(_atc10_direct_erp(1, 0.88)(), _sp_signal_dbw() + _SP_JS_TC_DB),
        rtol=1e-6,
        why="brentq on Friis in watts, the direct K = 1 ERP",
    ),
    # the largest design of Table 2.1, K = 1000 at P_DL = 0.999 (typed in): the ERP grows with both
    Oracle(
        "across02-k1000-erp", _atc10_direct_erp(1000, 0.999), atol=1e-6, why="direct probabilities, K = 1000"
    ),
]


# --- ATC-10 Sec. 2: the first-stage simulation ------------------------------------------------
# The figure caption's reduced sizes, typed in: n_a = 200 samples, an 11-sample window (w = 5),
# P_DL = 0.9 and 1000 trials; the rule 'more than K t of K = 3 lists', t = 1/3.
_ATC10_MC_NA, _ATC10_MC_W, _ATC10_MC_TRIALS = 200, 5, 1000


def _atc10_list_exponent(t: float, q: float) -> float:
    """(A.15) as printed, max over nu >= 0 of nu (1 - t) - ln((1 - q) e^nu + q), by scipy's
    bounded scalar minimiser (a concave function of nu)."""
    res = optimize.minimize_scalar(
        lambda nu: -(nu * (1 - t) - math.log((1 - q) * math.exp(nu) + q)),
        bounds=(0.0, 50.0),
        method="bounded",
        options={"xatol": 1e-12},
    )
    return max(0.0, -float(res.fun))


def _atc10_t13_detection() -> tuple[float, float]:
    """Exact detection rate at the grid's lowest jammer ratio and its band. p_d solves
    (2.4.2), 1 - exp(-K E(t, p_d^4)) = 0.9, by brentq. A list holds the signature's quadruplet with
    probability p_d^4; noise adds at most 4 (1 - p_d) 2w p_f + n_a p_f ((2w + 1) p_f)^3 (a missing
    signature declaration replaced by noise within the window, or a noise quadruplet), p_f =
    Q(d - Phi^-1(p_d)), d = 10^(-x/20). The rule's probability is scipy's binomial survival of
    Binom(3, q) above 1; its slope in q is at most 1.5. With common random numbers a trial's
    detection cannot fall as the jammer grows (the signature's test, n > -Phi^-1(p_d), does not
    depend on d; the noise declarations only grow), so the simulated minimum is the rate at the
    lowest ratio. Band: 4 binomial standard errors of the 1000 trials plus 1.5 times the noise bound."""
    from navcore.detection import jamming_monte_carlo as mc

    k, t, p_dl = 3, 1 / 3, 0.9
    q = optimize.brentq(
        lambda q: -math.expm1(-k * _atc10_list_exponent(t, q)) - p_dl, 0.5, 1 - 1e-12, xtol=1e-14
    )
    p_d = q**0.25
    d = 10 ** (-float(min(mc.X_DB)) / 20)
    p_f = float(stats.norm.sf(d - stats.norm.ppf(p_d)))
    w, n_a = _ATC10_MC_W, _ATC10_MC_NA
    noise = 4 * (1 - p_d) * 2 * w * p_f + n_a * p_f * ((2 * w + 1) * p_f) ** 3
    exact = float(stats.binom(k, q).sf(math.floor(k * t)))
    sd = math.sqrt(exact * (1 - exact) / _ATC10_MC_TRIALS)
    return exact, 4 * sd + 1.5 * noise


ORACLES += [
    Oracle(
        "atc10-14-detection-t13-min",
        lambda: _atc10_t13_detection()[0],
        band=lambda: _atc10_t13_detection()[1],
        why="(2.4.2) by brentq, scipy's binomial, the 1000-trial band",
    ),
    # the prose: 'one window of n = 24 samples, about the size of the track window of (C.14)'
    Oracle("atc10-mc-window-n", lambda: round(_atc10_n_v()), why="(C.14)'s n_v by hand, rounded"),
    # the prose: the largest p_f is 'close to the K = 1000 threshold'; the page prints it to two
    # decimals, so the threshold rounded to two decimals: 0.005
    Oracle(
        "atc10-mc-window-pf-hi",
        lambda: _atc10_direct_pf(0.999, 1000),
        atol=0.005,
        why="the K = 1000, P_DL = 0.999 threshold by direct probabilities",
    ),
]


# --- KZL Sec. 3.6: the written-out recursion against the filter -------------------------------
def _kzl03_library_sigma_position() -> np.ndarray:
    """The same recursion through the library's own steps, none of the page's arithmetic: F from
    error_dynamics_17, the exact transition, Q_d by the nilpotent Gauss-Legendre quadrature (not
    Van Loan), the code and Doppler rows, and sequential scalar updates (not the batch Joseph
    form); the initial covariance the page writes (its only shared part) and the scenario's sky."""
    from navcore.estimation.discretize import discretize
    from navcore.frames import dcm_from_euler
    from navcore.glued import _kzl03_initialised_p0
    from navcore.inertial.error_model17 import code_doppler_rows, error_dynamics_17, transition_exact
    from navcore.integration.ekf_ins_gnss import sequential_scalar_updates
    from navcore.papers.kzl_scenario import table1_scenario

    sc = table1_scenario("tc")
    imu, T = sc.imu, 1.0 / sc.gps_rate
    F = error_dynamics_17(dcm_from_euler(*sc.attitude), np.array([0.0, 0.0, -_G0]))
    noise = [0.0] * 3 + [imu.accel_random_walk**2] * 3 + [imu.gyro_random_walk**2] * 3
    noise += (
        [sc.accel_bias_walk**2] * 3
        + [sc.gyro_bias_walk**2] * 3
        + [sc.clock_phase_walk**2, sc.clock_drift_walk**2]
    )
    Phi, Qd = transition_exact(F, T), discretize(F, np.diag(noise), T, method="nilpotent")[1]
    P = _kzl03_initialised_p0()
    out = [np.sqrt(np.diag(P)[:3])]
    for k in range(1, sc.n_epochs + 1):
        nu = sc.n_visible[k]
        d = sc.sat_pos_ned[k, :nu] - sc.velocity_ned * k * T
        H = code_doppler_rows(d / np.linalg.norm(d, axis=1, keepdims=True))
        r = np.tile([sc.gnss.pseudorange**2, sc.gnss.delta_range**2], nu)
        P = sequential_scalar_updates(
            np.zeros((1, 17)), (Phi @ P @ Phi.T + Qd)[None], np.zeros((1, 2 * nu)), H[None], r
        )[1][0]
        out.append(np.sqrt(np.diag(P)[:3]))
    return np.array(out)


def _kzl03_loop_vs_filter_pct() -> float:
    from navcore.papers.kzl_scenario import monte_carlo

    return float(
        100 * np.max(np.abs(_kzl03_library_sigma_position() / monte_carlo("tc", True).pos_sigma - 1))
    )


ORACLES += [
    # the library's quadrature Q_d and sequential updates agree with Van Loan and the batch Joseph
    # form to 1e-8 relative per step (the page checks it); through 180 contracting steps the
    # sigmas stay within ~1e-7, the percentage within 1e-5 points: 1e-4 points
    Oracle(
        "kzl03-loop-vs-filter-pct", _kzl03_loop_vs_filter_pct, atol=1e-4, why="the library's filter steps"
    ),
]


# --- SP Sec. 2.6: the calibrated outages and the flyby's ranges ------------------------------
def _sp22_model_tc10_min() -> float:
    """The flyby model's tightly coupled 10 nmi/h blackout (min): an input of these oracles."""
    from navcore.papers import sp_flyby as fb

    return float(fb.blackouts_min()["TC 10 nmi/h"])


def _sp22_scaled_tc10_m() -> float:
    """The model's TC 10 nmi/h error before reacquisition (an input) grown by the Van Loan ratio
    of the random-walk errors over 20 - 2 = 18 min (the paper's figures, typed in) and over the
    model's blackout."""
    from navcore.papers import sp_flyby as fb

    err = fb.errors_before_reacquisition()["TC 10 nmi/h"]
    return err * _sp_noise_only_m(10.0, 20 - 2) / _sp_noise_only_m(10.0, _sp22_model_tc10_min())


def _sp22_range_by_hand_km(when: str) -> float:
    """The straight cruise leg past the jammer by hand: the jammer abeam at the closest approach,
    hypot(cross-track offset, altitude - jammer height) away, the aircraft at cruise speed v, so
    r(t) = hypot(d_min, v (t - t_ca)) at the blackout's loss or return sample (whole seconds;
    the blackout's times from the model, an input). Both lie after the calibration turns."""
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_scenario_wiring as sc

    t = math.floor(fb._blackout_s(sc.SYSTEMS[0])[{"loss": 0, "back": 1}[when]])
    t_ca = _sp_in("sp_flyby").closest_approach_min * 60.0
    assert t > 15 * 60, "the straight leg starts after the second turn"
    v = _sp_in("sp_scenario_wiring").cruise_speed_mps
    return math.hypot(_sp22_range_min_km() * 1e3, v * (t - t_ca)) / 1e3


ORACLES += [
    # the Van Loan oracle's 1 % (the vertical channel's coupling and the gravity model it leaves
    # out); a ratio of two of them: 2 %
    Oracle("sp21-clock-digits", _sp21_clock_digits, atol=1, why="digit strings of the two runs' errors"),
    # the same runs read another way: the percentages agree to round-off of the errors (1e-12
    # relative), divided by the percentage itself
    Oracle(
        "sp21-init-effect-pct",
        lambda: _sp21_initial_effect_pct(("initial errors up", "initial errors down")),
        rtol=1e-6,
        why="the runs' variance histories on their time axis",
    ),
    Oracle(
        "sp21-mis-effect-pct",
        lambda: _sp21_initial_effect_pct(("misalignment up", "misalignment down")),
        rtol=1e-6,
        why="the runs' variance histories on their time axis",
    ),
    Oracle("sp21-coupling-pct", _sp21_coupling_pct, rtol=1e-9, why="the runs' final covariance matrices"),
    Oracle(
        "sp21-momentary-pct",
        _sp21_momentary_pct,
        rtol=1e-6,
        why="target location written out on the final position and attitude covariance",
    ),
    Oracle(
        "sp21-noise-only-10-19min-m",
        lambda: _sp_noise_only_m(10.0, 19.0),
        rtol=0.01,
        why="Van Loan on the psi-angle model, 19 min",
    ),
    Oracle(
        "sp22-noise-18-m",
        lambda: _sp_noise_only_m(10.0, 20 - 2),
        rtol=0.01,
        why="Van Loan on the psi-angle model, the paper's 20 - 2 min",
    ),
    Oracle(
        "sp22-noise-model-m",
        lambda: _sp_noise_only_m(10.0, _sp22_model_tc10_min()),
        rtol=0.01,
        why="Van Loan on the psi-angle model, the model's blackout",
    ),
    Oracle("sp22-scaled-tc10-m", _sp22_scaled_tc10_m, rtol=0.02, why="Van Loan ratio on the model's error"),
    # exact straight-line geometry, the model's sampled track: 1e-6 as for the closest approach
    Oracle(
        "sp22-range-loss-km",
        lambda: _sp22_range_by_hand_km("loss"),
        rtol=1e-6,
        why="the straight leg by hand",
    ),
    Oracle(
        "sp22-range-back-km",
        lambda: _sp22_range_by_hand_km("back"),
        rtol=1e-6,
        why="the straight leg by hand",
    ),
]


# --- ATC-10 Sec. 3.8: the exact actual ROCs against ROC_g at the highest contour ---------------
@functools.cache
def _atc10_22_exact_ratio_8(pd_min: float) -> float:
    """mpmath oracle (80 digits) of the best actual p_f over ROC_g at 1/sqrt(3b) = 8 and p_d >= pd_min.

    Each density's exact tail written out from the model's definition: given K ~ Bin(N - 1, q)
    overlaps (all K up to a binomial weight of 1e-45), the noise is a(2J - K), J ~ Bin(K, 1/2), for
    the two-point density (+-a, a = sqrt(b)); Gaussian of variance K b; h(2V - m) with V
    Irwin-Hall of m = K uniforms on [-h, h], h = sqrt(3b), for the uniform density and of
    m = 2K uniforms, h = sqrt(3b/2), for the triangular one, the Irwin-Hall CDF by its alternating
    sum (exact in 80 digits; the cancellation here is below 40). On the page's threshold grid,
    p_miss rises and p_f falls with theta, so the best p_f at p_d >= pd_min is p_f at the largest
    threshold whose p_miss = P(n > 1 - theta) is at most 1 - pd_min (found by bisection). ROC_g:
    Gaussian noise of the Theorem 3.1 power N q b (scipy's normal)."""
    import mpmath

    from navcore.papers import atc10_gaussian_comparison as gaussian
    from navcore.papers import atc10_multiple_access as pm

    with mpmath.workdps(80):
        n_int, q = pm.IN.n_sec36 - 1, mpmath.mpf(2 * pm.IN.tau_over_alpha_sec36)
        b = 1 / (3 * mpmath.mpf(8) ** 2)
        weights = []
        for k in range(n_int + 1):
            w = mpmath.binomial(n_int, k) * q**k * (1 - q) ** (n_int - k)
            if k > 4 and w < mpmath.mpf("1e-45"):
                break
            weights.append(w)

        def tail(name: str, t, strict: bool):
            """P(n > t) (strict) or P(n >= t), t > 0."""
            out = mpmath.mpf(0)
            for k, w in enumerate(weights[1:], start=1):
                if name == "C2 two-point":
                    a = mpmath.sqrt(b)
                    js = [
                        j for j in range(k + 1) if (a * (2 * j - k) > t if strict else a * (2 * j - k) >= t)
                    ]
                    p = mpmath.fsum(mpmath.binomial(k, j) for j in js) / mpmath.mpf(2) ** k
                elif name == "C4 Gaussian":
                    p = mpmath.erfc(t / mpmath.sqrt(2 * k * b)) / 2
                else:
                    per, h = (1, mpmath.sqrt(3 * b)) if name == "C1 uniform" else (2, mpmath.sqrt(3 * b / 2))
                    m = per * k
                    p = irwin_hall_cdf_mpmath(m, (m - t / h) / 2)
                out += w * p
            return out

        grid = [mpmath.mpf(float(t)) for t in gaussian.THETA_GRID]
        level = 1 - mpmath.mpf(pd_min)
        best = []
        for name in pm.DENSITY_NAMES:

            def ok(i: int, name: str = name) -> bool:
                return bool(tail(name, 1 - grid[i], True) <= level)

            last = len(grid) - 1
            if not ok(0):
                continue
            lo, hi = (last, last) if ok(last) else (0, last)  # ok(lo); not ok(hi) unless lo == hi
            while hi - lo > 1:
                mid = (lo + hi) // 2
                lo, hi = (mid, hi) if ok(mid) else (lo, mid)
            best.append(tail(name, grid[lo], False))
        P = float(pm.IN.n_sec36 * 2 * pm.IN.tau_over_alpha_sec36 * b)
        theta_g = 1 - math.sqrt(P) * stats.norm.ppf(pd_min)
        return float(min(best)) / float(stats.norm.sf(theta_g / math.sqrt(P)))


ORACLES += [
    # both exact (the library's spline against the 80-digit alternating sums, the same grid): the
    # library's relative round-off, a few hundred units (1e-9 allowed)
    Oracle(
        "atc10-22-ratio-8-lo",
        lambda: min(_atc10_22_exact_ratio_8(0.9), _atc10_22_exact_ratio_8(0.99)),
        rtol=1e-9,
        why="mpmath binomial mixtures of the four densities' exact sums",
    ),
    Oracle(
        "atc10-22-ratio-8-hi",
        lambda: max(_atc10_22_exact_ratio_8(0.9), _atc10_22_exact_ratio_8(0.99)),
        rtol=1e-9,
        why="mpmath binomial mixtures of the four densities' exact sums",
    ),
]


# --- SP Sec. 2.6.2: the flyby's blackouts by an independent lock scan ---------------------------
def _sp22_system(label: str) -> Any:
    from navcore.papers import sp_scenario_wiring as sc

    return next(s for s in sc.SYSTEMS if s.label == label)


@functools.cache
def _sp22_lock_scan(label: str, loop_of: str) -> tuple[np.ndarray, np.ndarray]:
    """Code lock per sample and channel of system ``label`` tracking with the carrier loop of
    system ``loop_of`` (``"unaided 18"``: Table 2.6's first row, 18 rad/s, unaided), by a plain
    sample-by-sample scan written here: a carrier is lost below its loss threshold, with its
    phase error (k-sigma jitter plus the dynamic error) above the limit or the satellite below
    the horizon, and regained at or above its reacquisition threshold otherwise; the code loop
    the same with its own thresholds and its jitter at the carrier-aided or inertial-aided
    bandwidth as the carrier is locked or not. Inputs from the model: the jammed C/N0 series,
    the elevations, the dynamic error and the two jitter formulas. Returns the code states and
    the sample times."""
    from navcore.gnss.jammer_geometry import dll_thermal_jitter_chips, pll_thermal_jitter_deg
    from navcore.gnss.tracking import third_order_noise_bandwidth_hz
    from navcore.papers import sp_flyby as fb

    IN = fb.IN
    system = _sp22_system(label)
    if loop_of == "unaided 18":
        loop = fb.CarrierLoop(18.0, 18.0 * third_order_noise_bandwidth_hz(1.0), aided=False)
    else:
        loop = fb.carrier_loop(_sp22_system(loop_of))
    cn0 = np.asarray(fb.effective_cn0(fb.calibrated_jammer_db()))
    up = np.asarray(fb.flyby_geometry().elevation) > 0.0
    k, T = IN.jitter_k_sigma, IN.coherent_s
    dyn = np.asarray(fb.dynamic_phase_error_deg(loop.omega0, loop.aided, system.grade))
    phase = k * np.asarray(pll_thermal_jitter_deg(cn0, loop.bandwidth_hz, T)) + dyn
    chips = 2.0 * IN.code_loss_chips
    err = {
        True: k * np.asarray(dll_thermal_jitter_chips(cn0, IN.code_loop_carrier_aided_hz, chips, T)),
        False: k * np.asarray(dll_thermal_jitter_chips(cn0, IN.code_loop_inertial_aided_hz, chips, T)),
    }
    n, m = cn0.shape
    carrier, code = [True] * m, [True] * m
    states = np.zeros((n, m), dtype=bool)
    for i in range(n):
        for c in range(m):
            s, u = cn0[i, c], up[i, c]
            if s < IN.carrier_loss_dbhz or phase[i, c] > IN.max_phase_error_deg or not u:
                carrier[c] = False
            elif s >= IN.carrier_reacquisition_dbhz:
                carrier[c] = True
            if s < IN.code_loss_dbhz or err[carrier[c]][i, c] > IN.code_loss_chips or not u:
                code[c] = False
            elif s >= IN.code_reacquisition_dbhz:
                code[c] = True
            states[i, c] = code[c]
    return states, np.asarray(fb.flyby_trajectory().t)


def _sp22_longest_outage(label: str, loop_of: str) -> tuple[float, float, int]:
    """(start s, end s, start sample) of the longest stretch with fewer codes than the system
    needs (four for the loosely coupled receiver, one for a tightly coupled filter), by a scan:
    the end is the first sample with enough codes again (the last sample if none)."""
    states, t = _sp22_lock_scan(label, loop_of)
    need = 4 if _sp22_system(label).architecture == "loose" else 1
    ok = states.sum(axis=1) >= need
    best, i, n = (0.0, 0.0, -1), 0, len(ok)
    while i < n:
        if ok[i]:
            i += 1
            continue
        j = i
        while j < n and not ok[j]:
            j += 1
        if t[min(j, n - 1)] - t[i] > best[1] - best[0] or best[2] < 0:
            best = (float(t[i]), float(t[min(j, n - 1)]), i)
        i = j
    return best


def _sp22_lock_blackout_min(label: str, loop_of: str) -> float:
    start, end, _ = _sp22_longest_outage(label, loop_of)
    return (end - start) / 60.0


def _sp22_blackout_by_hand_min(label: str) -> float:
    """Blackout (min) with search times: from the scanned outage start to the return of the
    satellite that gives the system enough codes again, the channels that never lose code from
    the start on counting as kept; the satellites' return times (reacquisition plus search)
    are the model's, an input."""
    from navcore.papers import sp_flyby as fb

    states, _ = _sp22_lock_scan(label, label)
    start, _, k0 = _sp22_longest_outage(label, label)
    kept = int(states[k0:].all(axis=0).sum())
    need = (4 if _sp22_system(label).architecture == "loose" else 1) - kept
    if need <= 0:
        return 0.0
    back = sorted(float(x) for x in fb.reacquisition_search()[label]["back_s"])
    return (back[need - 1] - start) / 60.0


def _sp22_search_s_by_hand(sigma_range_m: float, sigma_rate_mps: float) -> float:
    """Sec. 2.5's search time written out: dwell x ceil(2 sigma_r / range cell) x ceil(2
    sigma_rr / rate cell), each at least one cell (dwell 20 ms, 30 m and 10 m/s cells from the
    inputs)."""
    from navcore.papers import sp_acquisition as spa
    from navcore.papers import sp_flyby as fb

    nr = max(1, math.ceil(2 * sigma_range_m / spa.IN.range_cell_m - 1e-12))
    nd = max(1, math.ceil(2 * sigma_rate_mps / fb.IN.range_rate_cell_mps - 1e-12))
    return spa.IN.dwell_s * nr * nd


def _sp22_calibration_s_by_hand() -> float:
    """The 0.2 nmi/h system's first satellite back, searched with the loosely coupled
    receiver's 1-sigma range and range-rate uncertainty for that satellite (zero if that
    receiver never reacquires it) less with its own (the uncertainties from the model's runs)."""
    from navcore.papers import sp_flyby as fb

    search = fb.reacquisition_search()
    tc, lc = search["TC 0.2 nmi/h"], search["LC 1 nmi/h"]
    first = int(np.argmin(tc["back_s"]))
    own = _sp22_search_s_by_hand(tc["sigma_range_m"][first], tc["sigma_range_rate_mps"][first])
    prn = tc["prn"][first]
    if prn not in lc["prn"]:
        return -own
    j = lc["prn"].index(prn)
    return _sp22_search_s_by_hand(lc["sigma_range_m"][j], lc["sigma_range_rate_mps"][j]) - own


def _sp22_resistance_s_by_hand() -> float:
    return 60 * (
        _sp22_lock_blackout_min("TC 0.2 nmi/h", "LC 1 nmi/h")
        - _sp22_lock_blackout_min("TC 0.2 nmi/h", "TC 0.2 nmi/h")
    )


def _sp22_architecture_min_by_hand() -> float:
    total = _sp22_blackout_by_hand_min("LC 1 nmi/h") - _sp22_blackout_by_hand_min("TC 0.2 nmi/h")
    return total - (_sp22_resistance_s_by_hand() + _sp22_calibration_s_by_hand()) / 60


ORACLES += [
    # the scans on the model's 1-s samples against the model's vectorised hysteresis: the same
    # samples, so the times agree to rounding (1e-9 relative, 1e-9 s absolute for the zero
    # changes: the carrier loop's bandwidth moves no lock crossing here, so a 1.3x scaling of
    # those two cannot show; any changed crossing would, by a whole second)
    Oracle(
        "sp22-tc10-blackout-min",
        lambda: _sp22_blackout_by_hand_min("TC 10 nmi/h"),
        rtol=1e-9,
        why="lock scan by hand, the model's return times",
    ),
    Oracle(
        "sp22-grade-spread-s",
        lambda: (
            60
            * (
                max(_sp22_blackout_by_hand_min(f"TC {g} nmi/h") for g in ("10", "1", "0.5", "0.2"))
                - min(_sp22_blackout_by_hand_min(f"TC {g} nmi/h") for g in ("10", "1", "0.5", "0.2"))
            )
        ),
        rtol=1e-9,
        atol=1e-9,
        why="lock scan by hand, the model's return times",
    ),
    Oracle(
        "sp22-bandwidth-s",
        lambda: (
            60
            * (
                _sp22_lock_blackout_min("TC 1 nmi/h", "unaided 18")
                - _sp22_lock_blackout_min("TC 1 nmi/h", "TC 1 nmi/h")
            )
        ),
        rtol=1e-9,
        atol=1e-9,
        why="lock scan by hand",
    ),
    Oracle("sp22-resistance-s", _sp22_resistance_s_by_hand, rtol=1e-9, atol=1e-9, why="lock scan by hand"),
    Oracle(
        "sp22-calibration-s",
        _sp22_calibration_s_by_hand,
        rtol=1e-9,
        atol=1e-9,
        why="Sec. 2.5 search time by hand, the runs' uncertainties",
    ),
    Oracle(
        "sp22-architecture-min",
        _sp22_architecture_min_by_hand,
        rtol=1e-9,
        why="lock scan and search time by hand",
    ),
]


def test_sp22_lock_scan_reproduces_the_model_lock_tables():
    """The scan behind the zero-valued bandwidth and resistance oracles, on the five systems'
    own loops: the same code states as the model's vectorised hysteresis, sample by sample, and
    the same nonzero lock-table blackouts (so a zero difference is two equal nonzero times)."""
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_scenario_wiring as sc

    for system in sc.SYSTEMS:
        states, _ = _sp22_lock_scan(system.label, system.label)
        np.testing.assert_array_equal(states, fb._lock_tables()[system].code)
        start, end = fb._outage(system, fb._lock_tables()[system].code)
        assert end - start > 600.0
        assert _sp22_lock_blackout_min(system.label, system.label) == pytest.approx(
            (end - start) / 60, rel=1e-12
        )


# --- SP pages: the numbers the chapter's read-through glued ----------------------------------
_FOOT_M = 0.3048  # m, the international foot (by definition)


def _sp02_step_over_jerk_w0() -> float:
    """scipy impulse / lsim oracle: the step's w from its 1 / w^2 scaling, the jerk's by brentq on
    lsim's peak (the jerk's fixed duration breaks the scaling), both with one foot per cycle."""
    limit = _sp_in("sp_tracking").peak_limit_deg
    w_step = math.sqrt(_sp_loop_peak(1.0) * 360 / _FOOT_M / limit)
    w_jerk = optimize.brentq(
        lambda w: _sp_loop_peak(w, "jerk") * 360 / _FOOT_M - limit, 1.0, w_step, xtol=1e-10
    )
    return w_step / w_jerk


def _sp03_r90_monte_carlo(sf_ppm: float, mis_arcsec: float) -> float:
    """Seeded Monte Carlo 90 % radius (ppm) of the printed 3x6 sensitivity at a = (1, 1, 1) with
    isotropic scale-factor and misalignment errors (400 000 draws, common to every call)."""
    from navcore.papers import sp_residual_acceleration as spr

    H = np.array(spr.IN.printed_h, dtype=float)
    z = _sp03_draws()
    sig = np.array([sf_ppm * 1e-6] * 3 + [mis_arcsec * math.pi / 648_000] * 3)
    return float(np.quantile(np.linalg.norm((z * sig) @ H.T, axis=1), 0.9)) * 1e6


@functools.cache
def _sp03_draws() -> np.ndarray:
    return np.random.default_rng(20261206).standard_normal((400_000, 6))


def _sp03_needed(grade_index: int, what: str) -> float:
    """brentq on the Monte Carlo radius: the misalignment (at Table 2.5's scale factor, typed in
    as printed) or the scale factor alone (perfect alignment) that meets column 2 as printed."""
    col2 = _SP_TAB26_COL2_PPM[grade_index]
    sf = _SP_TAB25_SF_PPM[grade_index]
    if what == "sf":
        return optimize.brentq(lambda s: _sp03_r90_monte_carlo(s, 0.0) - col2, 1e-3, sf)
    return optimize.brentq(lambda m: _sp03_r90_monte_carlo(sf, m) - col2, 0.0, 1e3)


def _sp22_unaided_jitter_dbhz() -> float:
    """The jitter rule of thumb (as for the loosely coupled loop above) with the noise bandwidth of
    the paper's third-order loop at 18 rad/s integrated from its transfer function (scipy quad of
    |H(j 2 pi f)|^2 over f, H = (2 w s^2 + 2 w^2 s + w^3) / (s^3 + 2 w s^2 + 2 w^2 s + w^3))."""
    w = _sp_in("sp_residual_acceleration").unaided_omega0
    a = _sp_in("sp_flyby")

    def h2(f: float) -> float:
        s = 2j * math.pi * f
        return abs((2 * w * s**2 + 2 * w**2 * s + w**3) / (s**3 + 2 * w * s**2 + 2 * w**2 * s + w**3)) ** 2

    bn = integrate.quad(h2, 0.0, np.inf, limit=400)[0]

    def excess(db: float) -> float:
        x = 10 ** (db / 10)
        return a.jitter_k_sigma * math.degrees(math.sqrt(bn / x * (1 + 1 / (2 * a.coherent_s * x)))) - (
            a.max_phase_error_deg
        )

    return optimize.brentq(excess, 0.0, 60.0, xtol=1e-12)


def _sp22_gps_aided_ratio() -> float:
    """The flyby runs' true north and east variances read by time (not through the analysis'
    horizontal error or its sample lookup): sqrt(var_N + var_E) of each system at the last sample
    at or before 1 s ahead of the tightly coupled 10 nmi/h blackout."""
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_scenario_wiring as sc

    runs = {s.label: r for s, r in fb.flyby_runs().items()}
    start, _ = fb._blackout_s(next(s for s in sc.SYSTEMS if s.label == "TC 10 nmi/h"))

    def horizontal(label: str) -> float:
        r = runs[label]
        k = int(np.searchsorted(r.t, start - 1.0, side="right")) - 1
        p = r.truth_layout.slice("position").start
        return math.sqrt(r.true_var[k, p] + r.true_var[k, p + 1])

    return horizontal("TC 10 nmi/h") / horizontal("TC 0.2 nmi/h")


ORACLES += [
    Oracle("sp02-step-over-jerk-w0", _sp02_step_over_jerk_w0, rtol=1e-5, why="scipy lsim, brentq"),
    Oracle("sp03-l1-unaided", _sp02_l1_w0, rtol=1e-6, why="scipy impulse response, 1 / w^2 scaling"),
    Oracle("sp03-apriori-sf-1", lambda: _SP_TAB25_SF_PPM[1], why="Table 2.5 as printed, typed in"),
    Oracle("sp03-needed-sf-1", lambda: _sp03_needed(1, "sf"), rtol=0.01, why="seeded Monte Carlo radius"),
    Oracle("sp03-needed-mis-10", lambda: _sp03_needed(0, "mis"), rtol=0.01, why="seeded Monte Carlo radius"),
    Oracle("sp03-needed-mis-0.5", lambda: _sp03_needed(2, "mis"), rtol=0.03, why="seeded Monte Carlo radius"),
    Oracle("sp03-needed-mis-0.2", lambda: _sp03_needed(3, "mis"), rtol=0.03, why="seeded Monte Carlo radius"),
    Oracle(
        "sp22-unaided-jitter-dbhz", _sp22_unaided_jitter_dbhz, rtol=1e-6, why="quad noise bandwidth, brentq"
    ),
    Oracle("sp22-gps-aided-ratio", _sp22_gps_aided_ratio, rtol=1e-12, why="the runs' variances read by time"),
]


@pytest.mark.parametrize("oracle", ORACLES, ids=lambda o: o.name)
def test_glued_value_against_its_oracle(oracle: Oracle):
    """The registered function's value against the oracle named in the case."""
    got = glued.value(oracle.name)
    want = oracle.expected()
    if isinstance(want, str):  # a label the page prints (a triplet of satellites): the same text
        assert got == want, (
            f"{oracle.name}: registered function gives {got!r}, the oracle ({oracle.why}) {want!r}"
        )
        return
    atol = oracle.band() if oracle.band is not None else oracle.atol
    assert got == pytest.approx(want, rel=oracle.rtol, abs=atol), (
        f"{oracle.name}: registered function gives {got!r}, the oracle ({oracle.why}) {want!r}"
    )


def test_every_registration_has_an_oracle():
    """Each registered name (each pattern, through at least one of its names) has a case here."""
    covered = {glued.lookup(o.name)[0].pattern for o in ORACLES if glued.lookup(o.name) is not None}
    missing = sorted(set(glued.entries()) - covered)
    assert not missing, f"registered glue names without an oracle: {missing}"
    unregistered = [o.name for o in ORACLES if glued.lookup(o.name) is None]
    assert not unregistered, f"oracles for names not registered: {unregistered}"


def test_check_refuses_a_changed_value():
    """navcore.book.glue's check: the registered value passes, a value 30 % off is refused with
    the name and both numbers, and an unregistered name passes through."""
    v = glued.value("atc10-13-wavelength-m")
    glued.check("atc10-13-wavelength-m", v)
    with pytest.raises(ValueError, match=r"'atc10-13-wavelength-m' is 0\.243581.*computes 0\.18737"):
        glued.check("atc10-13-wavelength-m", 1.3 * v)
    glued.check("no-such-registered-name", 1.0)


def test_register_refuses_a_second_home():
    """A glue name is registered once, with its page and quantity."""
    with pytest.raises(ValueError, match="registered twice"):
        glued.register("kzl00-schuler-min", "kzl/00-requirements", "again")(lambda: 0.0)
    with pytest.raises(ValueError, match="needs the page"):
        glued.register("x-new", " ", "q")
    with pytest.raises(ValueError, match="needs the quantity"):
        glued.register("x-new", "p", "")
