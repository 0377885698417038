"""WF: Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy".

Published inputs are declared once here (:data:`IN`), with their locators; every reproduced
value is computed by :mod:`navcore.location.emitter` and :mod:`navcore.estimation.federated`.
What the paper leaves open (the typical range and speed of Sec. III, the wing-tip deflection and
first mode, the INS/GPS accuracies of its reference [3]) is an ``assumed`` input with a
plausible range, and the ledger shows each claim across it.

The statements about the estimator of Sec. II (Eqs. (3) and (6)) and the identities of Sec. III
(Eqs. (8)-(9)) hold for any geometry; they are checked on a fixed test geometry
(:func:`orbit`, :data:`F0`, :data:`EMITTER`) or on seeded random geometries, which are test
fixtures, not inputs of the paper.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from navcore.claims import (
    EXACT,
    PROSE_WORDS,
    Claim,
    Erratum,
    InputSet,
    figure_reading,
    input_cache,
    printed,
    prose,
)
from navcore.estimation.federated import (
    accelerometer_steady_state_isotropic,
    correlated_joint_covariance,
    feasible_weights,
    federated_covariance_bound,
    federated_fusion,
    federated_improvement_db,
    fused_error_covariance,
    gps_doppler_covariance,
    minkowski_trace_bound,
    optimal_weights,
)
from navcore.location.emitter import (
    doppler_frequency,
    doppler_gradient_position,
    doppler_gradient_velocity,
    doppler_jacobian_emitter,
    emitter_gauss_newton,
    level_turn_track,
    linearized_location_error,
    location_error_covariance,
    position_sensitivity_bound,
    signal_model_error,
    velocity_to_position_sensitivity_ratio,
)
from navcore.papers.wf_quotes import quoted
from navcore.trace import implements
from navcore.units import FT, GPS_L1_HZ, MICRO_G, C

# ----------------------------------------------------------------------------- inputs
#: The registered inputs of the WF claims.
IN = InputSet("WF", "wf")
_IVD = "Sec. IV.D, parameter list"
IN.published(
    "sigma_n",
    0.02,
    locator=_IVD + " ($\\sigma_N$, [3] Table 1)",
    unit="m/s",
    quantity="on-board navigation velocity accuracy",
)
IN.published(
    "sigma_t_small",
    0.0,
    locator=_IVD + " ($\\sigma_T$, small)",
    unit="m/s",
    quantity="lever-arm adjustment uncertainty, small",
)
IN.published(
    "sigma_t_medium",
    0.2,
    locator=_IVD + " ($\\sigma_T$, medium)",
    unit="m/s",
    quantity="lever-arm adjustment uncertainty, medium",
)
IN.published(
    "sigma_t_large",
    2.0,
    locator=_IVD + " ($\\sigma_T$, large)",
    unit="m/s",
    quantity="lever-arm adjustment uncertainty, large",
)
IN.published(
    "sigma_a_low",
    10e-6,
    locator=_IVD + " ($\\sigma_a = 10$ µm/s² ~ 10 mm/s²)",
    unit="m/s^2",
    quantity="accelerometer resolution, high-resolution end",
)
IN.published(
    "sigma_a_high",
    10e-3,
    locator=_IVD + " ($\\sigma_a = 10$ µm/s² ~ 10 mm/s²)",
    unit="m/s^2",
    quantity="accelerometer resolution, medium-resolution end",
)
IN.published("ts", 0.02, locator=_IVD + " ($T_s = 0.02$ s)", unit="s", quantity="update interval")
IN.published(
    "sigma_l_per_sigma_a",
    200.0,
    locator=_IVD + " ($\\sigma_L = 200\\,\\sigma_a$)",
    unit="s",
    quantity="local velocity accuracy per unit accelerometer resolution",
)
IN.published("sigma_g", 1.0, locator=_IVD + " ($\\sigma_G = 1$ Hz)", unit="Hz", quantity="GPS Doppler noise")
IN.published(
    "sigma_a_example_micro_g",
    100.0,
    locator="Sec. IV.D ('a 100 µg local accelerometer')",
    unit="µg",
    quantity="the worked example's accelerometer",
)
IN.assumed(
    "speed_mps",
    200.0,
    low=100.0,
    high=300.0,
    unit="m/s",
    quantity="aircraft speed",
    reason="Sec. III speaks of 'the nominal velocity under consideration' without a value; 100-300 m/s "
    "spans surveillance and fighter aircraft",
)
IN.assumed(
    "emitter_distance_m",
    40e3,
    low=20e3,
    high=100e3,
    unit="m",
    quantity="horizontal emitter distance",
    reason="Sec. III speaks of 'the typical range under consideration' without a value; 20-100 km is "
    "the stand-off of airborne emitter location",
)
IN.assumed(
    "altitude_m",
    8000.0,
    low=3000.0,
    high=12000.0,
    unit="m",
    quantity="aircraft altitude",
    reason="not in the paper; 3-12 km is the cruise band of the aircraft of Sec. III",
)
IN.assumed(
    "deflection_ft",
    5.0,
    low=3.0,
    high=9.0,
    unit="ft",
    quantity="wing-tip deflection",
    reason="Sec. III: 'several feet'; 'several' is 3-9 (the ledger's table of prose words), 5 ft nominal",
)
IN.assumed(
    "vib_hz",
    3.0,
    low=3.0,
    high=9.0,
    unit="Hz",
    quantity="first flexible-mode frequency",
    reason="Sec. III: 'in the range of several Hertz'; 'several' is 3-9 (the ledger's table of prose words)",
)
IN.assumed(
    "vib_amplitude_m",
    0.1,
    low=0.05,
    high=0.3,
    unit="m",
    quantity="wing-tip amplitude of the first mode",
    reason="not in the paper; 5-30 cm tip amplitude of a first wing bending mode in turbulence",
)
IN.assumed(
    "ins_gps_position_m",
    10.0,
    low=5.0,
    high=30.0,
    unit="m",
    quantity="best INS/GPS position accuracy (1-$\\sigma$)",
    reason="Sec. III compares with 'the best position accuracy provided by an INS/GPS system [3]' "
    "without quoting it; integrated INS/GPS of the 1980s ([3], 1986) gave 5-30 m",
)
IN.assumed(
    "gps_doppler_velocity_mps",
    0.1,
    low=0.05,
    high=0.2,
    unit="m/s",
    quantity="GPS velocity accuracy per line of sight from Doppler",
    reason="Sec. IV.D calls $\\sigma_G = 1$ Hz 'consistent with the GPS velocity accuracy from Doppler shift "
    "measurement' without a value or reference; receivers of the time specify 0.05-0.2 m/s",
)
IN.assumed(
    "sigma_a_poor_max",
    1.0,
    low=0.1,
    high=1.0,
    unit="m/s^2",
    quantity="upper end of a 'very poor' accelerometer",
    reason="Sec. IV.D: GPS benefits 'become noticeable only when ... the local accelerometer accuracy is "
    "very poor'; beyond the stated 10 mm/s², up to 0.1-1 m/s²",
)
IN.published(
    "f_l1_over_c_printed",
    5.25,
    locator=_IVD + " ($f_o^{L1}/c = 5.25$ m$^{-1}$)",
    unit="1/m",
    quantity="GPS L1 frequency over the speed of light, as printed",
)
IN.convention(
    "c_of_fl1_mps",
    C,
    unit="m/s",
    quantity="speed of light in the printed $f_{L1}/c$",
    readings={
        "the defined speed of light, 299 792 458 m/s": C,
        "the engineering value 3 × 10⁸ m/s": 3.0e8,
        "the four-digit value 2.998 × 10⁸ m/s": 2.998e8,
    },
    reason="Sec. IV.D prints $f_o^{L1}/c = 5.25$ m⁻¹ without its c; 1575.42 MHz over the defined c is "
    "5.2550, "
    "a hair (0.00004) beyond half a unit in the last printed digit, while the engineering values of c "
    "give 5.2514 and 5.2549",
)
# Readings of the words the statements test (the paper prints no threshold; each reading is a
# declared convention, and a statement is accused only if it fails under every one).
IN.convention(
    "close_rel",
    0.01,
    quantity="closeness that 'as much as', 'close' and 'exact' allow",
    readings={
        "within 1 %": 0.01,
        "within 10 %, the reading of 'nearly' in the ledger's table of prose words": 0.10,
    },
    reason="Sec. II's 'as much as' and 'close to the true value', Remark (ii)'s 'tends to be exact' and "
    "Sec. IV.B.1's 'regardless' carry no number",
)
IN.convention(
    "contributes_rel",
    0.01,
    quantity="change of the local accuracy that makes a factor 'contribute'",
    readings={"more than 1 %": 0.01, "more than 10 %": 0.10},
    reason="'three factors contribute to the accuracy' (Sec. IV.B.2) carries no number",
)
IN.convention(
    "contribution_factor",
    2.0,
    quantity="change of $Q_a$, $R_L$ and $T_s$ at which their contribution is judged",
    readings={"each doubled": 2.0, "each increased by half": 1.5},
    reason="'three factors contribute to the accuracy' (Sec. IV.B.2) names no change of the factors; "
    "the book changes each in turn by a factor and asks whether the accuracy moves",
)
IN.convention(
    "noticeable_db",
    1.0,
    unit="dB",
    quantity="smallest noticeable change of the improvement bound",
    readings={"1 dB": 1.0, "3 dB, a factor 2 in power": 3.0},
    reason="'quite limited' and 'noticeable' (Sec. IV.D) carry no number",
)
IN.convention(
    "fig_resolution_db",
    0.5,
    unit="dB",
    quantity="resolution of the dB axis of Figs. 1-2",
    readings={"half a dB": 0.5, "a tenth of a dB": 0.1},
    reason="Figs. 1-2 are not in the transcription, so the resolution of their dB axis is not known; "
    "'virtually identical' and the order of the curves are read at it",
)
IN.convention(
    "slope_tol_db",
    0.5,
    unit="dB/decade",
    quantity="allowed deviation from 20 dB per decade",
    readings={"half a dB per decade": 0.5, "one dB per decade": 1.0},
    reason="the slope is the book's reading of Fig. 1 (no value is printed)",
)
IN.convention(
    "negligible_fraction",
    1.0,
    quantity="share of the on-board accuracy $\\sigma_N$ below which an error is negligible",
    readings={"below the on-board accuracy": 1.0, "below a tenth of the on-board accuracy": 0.1},
    reason="Sec. V's 'negligible level' carries no number; the on-board accuracy $\\sigma_N$ is the error "
    "the "
    "aircraft has without any flexure",
)
IN.convention(
    "mc_sigmas",
    5.0,
    quantity="allowance of a Monte Carlo check, in sampling standard deviations",
    readings={"5 sampling standard deviations": 5.0, "3 sampling standard deviations": 3.0},
    reason="the paper runs no Monte Carlo: the book's checks of Eqs. (6), (11) and (20)-(23) allow the "
    "sampling error of their own run counts",
)
IN.assumed(
    "turn_rate_deg_s",
    2.0,
    low=1.5,
    high=3.0,
    unit="deg/s",
    quantity="turn rate of the aperture track (the Sec. II test geometry and the Sec. III scenario)",
    reason="the paper gives no track; Eqs. (5)-(6) assume 'the location estimate is close to the true "
    "value': from 1.5 deg/s, where over 60 s the Eq. (6) RMS location error stays below 1 % of the range "
    "(at 0.5 deg/s it is 3-18 %, and the estimate is no longer close), to the 3 deg/s of a standard-rate "
    "turn",
)
IN.assumed(
    "aperture_duration_s",
    120.0,
    low=60.0,
    high=300.0,
    unit="s",
    quantity="length in time of the aperture track (the Sec. II test geometry and the Sec. III scenario)",
    reason="the paper gives no aperture length; 1-5 min spans a short to a long emitter-location pass "
    "(over this range and the turn rates above the Eq. (6) RMS error stays below 1 % of the range)",
)
IN.assumed(
    "emitter_bearing_deg",
    60.0,
    low=30.0,
    high=90.0,
    grid=5,
    unit="deg",
    quantity="bearing of the emitter from the start of the track, from the initial heading",
    reason="Sec. III gives no geometry; from 30 deg off the nose to abeam, where a pass sees the bearing "
    "change that locates the emitter (the ratio is not monotone in it: a grid)",
)
IN.assumed(
    "eq13_accel_amplitude_mps2",
    0.5,
    low=0.1,
    high=2.0,
    unit="m/s^2",
    quantity="amplitude of the aperture manoeuvre of the Eq. (13) simulation",
    reason="the paper gives no manoeuvre; 0.1-2 m/s² is a gentle to firm wing-tip acceleration",
)
IN.assumed(
    "eq13_accel_frequency_hz",
    0.2,
    low=0.05,
    high=1.0,
    unit="Hz",
    quantity="frequency of the aperture manoeuvre of the Eq. (13) simulation",
    reason="the paper gives no manoeuvre; 0.05-1 Hz spans slow turns to the lowest structural modes",
)


def sigma_t_values() -> tuple[float, float, float]:
    """The three lever-arm uncertainties sigma_T of Sec. IV.D (small, medium, large), m/s."""
    return (IN.sigma_t_small, IN.sigma_t_medium, IN.sigma_t_large)


def sigma_a_example() -> float:
    """The worked example's 100 ug accelerometer, m/s^2."""
    return IN.sigma_a_example_micro_g * MICRO_G


#: Sec. IV.D printed L1 frequency over c, 1/m (the figures read the published input).
F_L1_OVER_C_PRINTED = "5.25"

# ----------------------------------------------------------------------------- test geometry
#: Test fixture of the Sec. II estimator checks (not an input: Eqs. (3) and (6) hold for any
#: geometry): emitter carrier, aircraft speed and altitude, orbit, emitter, frequency noise.
F0 = 10e9
SPEED = 200.0
ALTITUDE = 8000.0
N_SAMPLES = 200
EMITTER = np.array([20_000.0, 35_000.0, 0.0])
SIGMA_F = 1.0  # Hz, frequency measurement noise

DOCS = {
    "II": "wf/01-location-error",
    "III": "wf/02-velocity-sensitivity",
    "IV": "wf/03-local-estimators",
    "IVD": "wf/04-assessment",
    "E2E": "wf/05-end-to-end",
}


def orbit(M: int = N_SAMPLES) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Times, positions and velocities of the test geometry: a turn at 8 km, 200 m/s, at the assumed
    turn rate (2 deg/s) for the assumed aperture duration (120 s)."""
    return level_turn_track(SPEED, ALTITUDE, M, IN.turn_rate_deg_s, IN.aperture_duration_s)


#: Samples along the Sec. III scenario track: a numerical resolution, not an input (the claims
#: take the minimum or the mean over the continuous track; at this density a 10 % change of it
#: moves them by round-off only).
SCENARIO_SAMPLES = 2001


def scenario_track(M: int = SCENARIO_SAMPLES) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The Sec. III scenario track: a turn at the assumed rate, speed and altitude, for the assumed
    aperture duration."""
    return level_turn_track(IN.speed_mps, IN.altitude_m, M, IN.turn_rate_deg_s, IN.aperture_duration_s)


def scenario_emitter() -> np.ndarray:
    """The emitter at the assumed horizontal distance and bearing from the start of the track."""
    b = np.deg2rad(IN.emitter_bearing_deg)
    return IN.emitter_distance_m * np.array([np.cos(b), np.sin(b), 0.0])


def mean_range() -> float:
    """Mean aperture-to-emitter range over the Sec. III scenario (assumed inputs), m."""
    _, pos, _ = scenario_track()
    return float(np.mean(np.linalg.norm(scenario_emitter() - pos, axis=1)))


# ----------------------------------------------------------------------------- Section II
#: Seeded trials of the Sec. II checks of :func:`_ls_trial`: enough that their RMS ratios are
#: estimates of the typical one (a single draw's ratio ranges over a factor 100 with the draw).
LS_TRIALS = 50


@input_cache
def _ls_trial(trials: int = LS_TRIALS) -> dict[str, float]:
    """Seeded nonlinear Gauss-Newton fits with frequency noise and aperture-velocity errors.

    ``rel_lin``: RMS distance of the nonlinear estimate from its linearisation (WF Eq. (6)) over
    the RMS of the linearised error; ``rel_same``: RMS distance between the fit with wrong aperture
    velocities and the fit with exact velocities and the same frequency error added to the
    measurements, over the RMS estimation error; ``normal_rel``: the largest relative residual of
    the normal equations (Eq. (3)). Ratios of RMS values over ``trials`` draws, so that no single
    draw with a small estimation error decides them.
    """
    rng = np.random.default_rng(20240601)
    _, pos, vel = orbit()
    truth = np.r_[EMITTER, F0]
    f_true = doppler_frequency(F0, EMITTER, pos, vel)
    d_lin, lin_err, d_same, err = (np.empty((trials, 3)) for _ in range(4))
    normal_rel = 0.0
    for i in range(trials):
        e = rng.normal(0.0, SIGMA_F, len(pos))
        vel_hat = vel + rng.normal(0.0, 0.05, vel.shape)
        m = f_true + e
        res = emitter_gauss_newton(m, pos, vel_hat, truth)
        H = doppler_jacobian_emitter(F0, EMITTER, pos, vel_hat)
        ft = signal_model_error(F0, EMITTER, pos, vel, pos, vel_hat)
        lin = linearized_location_error(H, e + ft)
        # the same frequency error labelled as measurement noise, with the true aperture states
        res_e = emitter_gauss_newton(f_true + e + ft, pos, vel, truth)
        Hn = res.jacobian
        d_lin[i], lin_err[i] = res.estimate[:3] - EMITTER - lin[:3], lin[:3]
        d_same[i], err[i] = res.estimate[:3] - res_e.estimate[:3], res.estimate[:3] - EMITTER
        normal_rel = max(
            normal_rel, float(np.linalg.norm(res.normal_equation) / (np.linalg.norm(Hn) * np.linalg.norm(m)))
        )

    def rms_ratio(a: np.ndarray, b: np.ndarray) -> float:
        return float(np.sqrt(np.sum(a**2) / np.sum(b**2)))

    return {
        "rel_lin": rms_ratio(d_lin, lin_err),
        "normal_rel": normal_rel,
        "rel_same": rms_ratio(d_same, err),
    }


@input_cache
def ls_monte_carlo(trials: int = 400, sigma_v: float = 0.05) -> dict[str, np.ndarray]:
    """Seeded Monte Carlo of the nonlinear estimator vs the WF Eq. (6) covariance (book geometry).

    White frequency noise (SIGMA_F) and white aperture-velocity errors (sigma_v per axis).
    Returns the per-axis sample std of the position error and the Eq. (6) prediction.
    """
    rng = np.random.default_rng(7)
    _, pos, vel = orbit()
    truth = np.r_[EMITTER, F0]
    f_true = doppler_frequency(F0, EMITTER, pos, vel)
    errs = np.empty((trials, 4))
    for i in range(trials):
        m = f_true + rng.normal(0.0, SIGMA_F, len(pos))
        vel_hat = vel + rng.normal(0.0, sigma_v, vel.shape)
        errs[i] = emitter_gauss_newton(m, pos, vel_hat, truth).estimate - truth
    H = doppler_jacobian_emitter(F0, EMITTER, pos, vel)
    var_f = SIGMA_F**2 + (F0 / C) ** 2 * sigma_v**2  # |u_R| = 1: isotropic velocity error
    cov = location_error_covariance(H, var_f * np.eye(len(pos)))
    return {"sample_std": errs.std(axis=0, ddof=1), "predicted_std": np.sqrt(np.diag(cov)), "errors": errs}


def _eq6_mc_agrees() -> bool:
    """Each axis's sample standard deviation within the allowed sampling standard deviations of the
    Eq. (6) prediction (the relative sampling sd of a standard deviation from n draws is 1/sqrt(2(n-1)))."""
    r = ls_monte_carlo()
    ratio = r["sample_std"][:3] / r["predicted_std"][:3]
    sd = 1.0 / np.sqrt(2 * (len(r["errors"]) - 1))
    return bool(np.all(np.abs(ratio - 1) < IN.mc_sigmas * sd))


# ----------------------------------------------------------------------------- Section III
@input_cache
def _random_geometries(n: int = 2000) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(11)
    p = rng.normal(0, 5000, (n, 3))
    e = p + rng.normal(0, 30000, (n, 3))
    v = rng.normal(0, 200, (n, 3))
    return p, e, v


def _eq8_identity() -> bool:
    p, e, _ = _random_geometries()
    # only the difference of the positions enters: put the emitter at the origin, vectorised
    norms = np.linalg.norm(doppler_gradient_velocity(F0, np.zeros(3), p - e), axis=1)
    return bool(np.max(np.abs(norms / (F0 / C) - 1)) < 1e-12)


def position_bound_ratios() -> np.ndarray:
    """||df/dp|| divided by the printed bound of WF Eq. (9), over random geometries."""
    p, e, v = _random_geometries()
    g = np.linalg.norm(doppler_gradient_position(F0, np.zeros(3), p - e, v), axis=1)
    return g / position_sensitivity_bound(F0, np.linalg.norm(v, axis=1), np.linalg.norm(e - p, axis=1))


def _eq9_bound_holds() -> bool:
    return bool(np.max(position_bound_ratios()) <= 1.0)


def wingtip_velocity_amplitude() -> float:
    """Velocity amplitude 2 pi f A of the assumed first wing mode, m/s."""
    return float(2 * np.pi * IN.vib_hz * IN.vib_amplitude_m)


def sensitivity_ratios() -> np.ndarray:
    """||df/dv|| / ||df/dp|| at each sample of the book geometry (exact WF Eqs. (8)-(9)), s.

    The frequency change caused by a 1 m/s aperture-velocity error divided by that of a 1 m
    aperture-position error, each in its worst direction. Sec. III scenario (assumed speed,
    altitude and emitter distance; the carrier cancels).
    """
    _, pos, vel = scenario_track()
    emitter = scenario_emitter()
    gv = np.linalg.norm(doppler_gradient_velocity(F0, emitter, pos), axis=1)
    gp = np.linalg.norm(doppler_gradient_position(F0, emitter, pos, vel), axis=1)
    return gv / gp


@input_cache
def location_error_leverage() -> dict[str, np.ndarray]:
    """Emitter-position error per unit aperture error through WF Eq. (6), book geometry.

    ``"bias_v"`` / ``"bias_p"``: norm of the emitter-position error (m) caused by a constant
    1 m/s velocity error / 1 m position error along x, y, z of every sample (exact signal-model
    error of Eq. (6), propagated to first order). ``"white_v"`` / ``"white_p"``: RMS of the
    emitter-position error (m) for independent errors of 1 m/s / 1 m per axis and sample.
    """
    _, pos, vel = orbit()
    H = doppler_jacobian_emitter(F0, EMITTER, pos, vel)
    out: dict[str, np.ndarray] = {"bias_v": np.empty(3), "bias_p": np.empty(3)}
    for axis, d in enumerate(np.eye(3)):
        ft_v = signal_model_error(F0, EMITTER, pos, vel, pos, vel + d)
        ft_p = signal_model_error(F0, EMITTER, pos, vel, pos + d, vel)
        out["bias_v"][axis] = np.linalg.norm(linearized_location_error(H, ft_v)[:3])
        out["bias_p"][axis] = np.linalg.norm(linearized_location_error(H, ft_p)[:3])
    for key, g in (
        ("white_v", doppler_gradient_velocity(F0, EMITTER, pos)),
        ("white_p", doppler_gradient_position(F0, EMITTER, pos, vel)),
    ):
        cov = location_error_covariance(H, np.diag(np.sum(g**2, axis=1)))
        out[key] = np.array(np.sqrt(np.trace(cov[:3, :3])))
    return out


# ----------------------------------------------------------------------------- Section IV.A-C
#: Test case of the Eq. (13) simulation: accelerometer 1 mm/s^2 (inside the stated range),
#: sigma_L = 200 sigma_a, 5000 steps of T_s, 200 paths; the manoeuvre is an assumed input.
_EQ13_SA, _EQ13_STEPS, _EQ13_PATHS = 1e-3, 5000, 200


def _eq13_manoeuvre(ts: float) -> np.ndarray:
    """The assumed sinusoidal aperture acceleration of the Eq. (13) simulation, m/s^2."""
    amp, freq = IN.eq13_accel_amplitude_mps2, IN.eq13_accel_frequency_hz
    return amp * np.sin(2 * np.pi * freq * ts * np.arange(_EQ13_STEPS))


def eq13_printed_error_ratio() -> float:
    """Run WF Eq. (13) literally (innovation y_a - x): final RMS error over sqrt(P_DL(k/k)) of Eq. (14)."""
    rng = np.random.default_rng(3)
    ts = IN.ts
    ss = accelerometer_steady_state_isotropic(_EQ13_SA, ts, IN.sigma_l_per_sigma_a * _EQ13_SA)
    K = ss.gain
    v = np.zeros(_EQ13_PATHS)
    x = rng.normal(0, np.sqrt(ss.posterior), _EQ13_PATHS)
    acc = _eq13_manoeuvre(ts)
    for k in range(_EQ13_STEPS):
        v = v + acc[k] * ts
        y_a = acc[k] + rng.normal(0, _EQ13_SA, _EQ13_PATHS)
        x = x + y_a * ts
        x = x + K * (y_a - x)  # as printed
    return float(np.sqrt(np.mean((x - v) ** 2)) / np.sqrt(ss.posterior))


def eq13_innovation_is_a_velocity_residual() -> bool:
    """Whether the innovation y_a(k) - x_DL(k/k-1) of WF Eq. (13) as printed subtracts like quantities.

    y_a is the accelerometer output of Eq. (12), an acceleration; x_DL the local velocity. Only a
    difference of like quantities can drive a Kalman filter of Eq. (12) to the covariance of Eq. (14).
    """
    return _ACCEL == _SPEED


def _eq13_oracle() -> bool:
    """Independent of the dimensions: a seeded simulation of the printed recursion under the assumed
    manoeuvre (:func:`eq13_printed_error_ratio`) ends within the Monte Carlo band of the covariance of
    Eq. (14) (its RMS error over sqrt(P_DL(k/k)) within the allowed sampling standard deviations of 1)."""
    sd = 1.0 / np.sqrt(2 * _EQ13_PATHS)
    return bool(abs(eq13_printed_error_ratio() - 1.0) <= IN.mc_sigmas * sd)


#: SI dimension exponents (length, time) for the dimensional checks of Eqs. (13) and (24).
_SPEED = (1, -1)
_ACCEL = (1, -2)


def _dim_product(*dims: tuple[int, int]) -> tuple[int, int]:
    return (sum(d[0] for d in dims), sum(d[1] for d in dims))


def eq24_literal_unit_ratio() -> float:
    """WF Eq. (24) read literally (P_N P_N^T = sigma_N^2 I, so P_N = sigma_N I): sigma_DN computed with
    velocities in cm/s, converted to m/s, over sigma_DN computed in m/s (1 for a consistent reading)."""

    def sigma_dn(scale: float) -> float:  # velocities expressed in units of 1/scale m/s
        p_n = IN.sigma_n * scale  # P_N = sigma_N I (in the chosen unit) from P_N P_N^T = sigma_N^2 I
        return float(np.sqrt(p_n) / scale)

    return sigma_dn(100.0) / sigma_dn(1.0)


def eq24_literal_is_unit_consistent() -> bool:
    """Whether WF Eq. (24)'s P_N P_N^T = sigma_N^2 I, read literally, gives the same sigma_DN in any
    velocity unit (computed in cm/s and in m/s, to round-off)."""
    return bool(abs(eq24_literal_unit_ratio() - 1.0) < 1e-12)


def _eq24_oracle() -> bool:
    """Independent derivation: P_N P_N^T is in (m/s)^4 against sigma_N^2 in (m/s)^2; the two sides
    have the same dimension only if a variance squared is a variance."""
    variance = _dim_product(_SPEED, _SPEED)
    return _dim_product(variance, variance) == variance


def _joint_for_eq20() -> tuple[list[np.ndarray], np.ndarray]:
    rng = np.random.default_rng(17)
    A = rng.normal(size=(9, 9))
    J = A @ A.T + 0.5 * np.eye(9)
    return [J[3 * i : 3 * i + 3, 3 * i : 3 * i + 3] for i in range(3)], J


def _printed_joint(J: np.ndarray) -> np.ndarray:
    """The joint matrix as WF Eq. (20) prints it: block (2, 3) is P_NG instead of P_LG."""
    Jp = J.copy()
    Jp[3:6, 6:9] = J[0:3, 6:9]
    return Jp


def eq20_printed_block_error() -> float:
    """Largest entry of (printed block (2, 3) - the L-G cross-covariance), over the largest entry of J."""
    _, J = _joint_for_eq20()
    Jp = _printed_joint(J)
    return float(np.max(np.abs(Jp[3:6, 6:9] - J[3:6, 6:9])) / np.max(np.abs(J)))


def eq20_printed_is_covariance() -> bool:
    """Whether WF Eq. (20)'s joint matrix as printed is the covariance of the stacked errors: its block
    (2, 3) equal to the L-G cross-covariance, to round-off."""
    return eq20_printed_block_error() < 1e-12


def _eq20_oracle() -> bool:
    """Oracle: seeded Monte Carlo of the stacked errors; the printed P_NG in block (2, 3) against the
    sample (L, G) cross-covariance, within the allowed sampling standard deviations (sqrt(2/n) of the
    largest entry)."""
    _, J = _joint_for_eq20()
    rng = np.random.default_rng(18)
    n = 200_000
    E = rng.multivariate_normal(np.zeros(9), J, n)
    S = np.cov(E.T)
    deviation = float(np.max(np.abs(J[0:3, 6:9] - S[3:6, 6:9])) / np.max(np.abs(J)))
    return deviation <= IN.mc_sigmas * np.sqrt(2.0 / n)


def _spd(rng: np.random.Generator, n: int) -> np.ndarray:
    A = rng.normal(size=(n, n))
    return A @ A.T + 0.1 * np.eye(n)


@input_cache
def theorem_margins(cases: int = 200) -> dict[str, float]:
    """Check WF Eqs. (21)-(23) on random correlated joint covariances (3 estimators, 3 states)."""
    rng = np.random.default_rng(21)
    eig_margin, first, second = np.inf, np.inf, np.inf
    for _ in range(cases):
        J = correlated_joint_covariance(rng, 3, 3, rng.uniform())
        Ps = [J[3 * i : 3 * i + 3, 3 * i : 3 * i + 3] for i in range(3)]
        cov = fused_error_covariance(Ps, J)
        k = feasible_weights(Ps, directions=[rng.normal(size=3) for _ in range(3)])
        B = federated_covariance_bound(Ps, k)
        eig_margin = min(eig_margin, np.linalg.eigvalsh(B - cov)[0] / np.linalg.norm(B))
        mink = minkowski_trace_bound(Ps)
        first = min(first, (mink - np.trace(cov)) / mink)
        second = min(second, (np.trace(B) - mink) / np.trace(B))
    return {"eig": float(eig_margin), "first": float(first), "second": float(second)}


def _theorem_holds() -> bool:
    m = theorem_margins()
    return m["eig"] >= -1e-12 and m["first"] >= -1e-12 and m["second"] >= -1e-12


def _fusion_maps(Ps: list[np.ndarray]) -> list[np.ndarray]:
    """The linear maps x_i -> x_D of WF Eqs. (18)-(19), read off federated_fusion column by column."""
    n, N = Ps[0].shape[0], len(Ps)
    maps = []
    for i in range(N):
        cols = []
        for d in np.eye(n):
            xs = [d if j == i else np.zeros(n) for j in range(N)]
            cols.append(federated_fusion(xs, Ps)[0])
        maps.append(np.column_stack(cols))
    return maps


@input_cache
def theorem_monte_carlo(cases: int = 12, samples: int = 20_000, seed: int = 29) -> tuple[dict, ...]:
    """Seeded Monte Carlo of the theorem, WF Eqs. (18)-(23), on correlated local errors.

    Each case draws a joint covariance J of N = 2, 3 or 4 local errors of 3 states: "generic"
    (J = A A' + 0.1 I, arbitrary correlations), "mixed" (a common and an independent part,
    correlation uniform in [0, 1]) or "complete" (e_i = sigma_i w with one common w, isotropic).
    ``samples`` errors are drawn, fused with the weights of Eqs. (18)-(19), and their sample
    covariance S is compared with the bound B of Eq. (21) (weights of Eq. (22) with random z_i;
    for "complete" the optimal weights, an instance of Eq. (22) for which B equals the true
    covariance, so the check has no slack), the Minkowski term of Eq. (23) and the exact
    covariance C of Eq. (20). For each case:

    * ``z_bound``: (lambda_max(B^-1/2 S B^-1/2) - 1) / sqrt(2/(n-1)); in any direction the
      whitened sample variance has sampling sd sqrt(2/(n-1)) times a true value <= 1;
    * ``z_trace``: (tr S - Minkowski term) / sqrt(2 tr(S^2)/(n-1));
    * ``z_eq20``: largest |S_jk - C_jk| over its sampling sd sqrt((S_jj S_kk + S_jk^2)/(n-1));
    * ``exact``: relative difference between S and Eq. (20) applied to the sample joint
      covariance of the local errors (zero up to round-off: E[S] equals Eq. (20) exactly).
    """
    rng = np.random.default_rng(seed)
    out = []
    for case in range(cases):
        kind = ("generic", "mixed", "complete")[(case // 3) % 3]
        r = theorem_monte_carlo_case(rng, 2 + case % 3, kind, samples)
        out.append({key: r[key] for key in ("N", "kind", "z_bound", "z_trace", "z_eq20", "exact")})
    return tuple(out)


def theorem_monte_carlo_case(rng: np.random.Generator, N: int, kind: str, samples: int) -> dict:
    """One case of :func:`theorem_monte_carlo`: ``N`` local errors of 3 states of the given kind.

    Returns the criteria (``z_bound``, ``z_trace``, ``z_eq20``, ``exact``) and, for further checks,
    the local covariances ``Ps``, the sample covariance ``S`` of the fused error and ``dof``.
    """
    n = 3
    if kind == "generic":
        J = _spd(rng, n * N)
    elif kind == "mixed":
        J = correlated_joint_covariance(rng, n, N, rng.uniform())
    elif kind == "complete":
        sig = rng.uniform(0.1, 2.0, N)
        J = np.kron(np.outer(sig, sig), np.eye(n))
    else:
        raise ValueError(f"kind must be 'generic', 'mixed' or 'complete', got {kind!r}")
    Ps = [J[n * i : n * i + n, n * i : n * i + n] for i in range(N)]
    w, V = np.linalg.eigh(J)
    E = rng.normal(size=(samples, n * N)) @ (V * np.sqrt(np.clip(w, 0.0, None))).T
    fused = sum(E[:, n * i : n * i + n] @ A.T for i, A in enumerate(_fusion_maps(Ps)))
    S = np.cov(fused.T)
    C = fused_error_covariance(Ps, J)
    z = list(rng.normal(size=(N, n)))
    k = optimal_weights(Ps) if kind == "complete" else feasible_weights(Ps, directions=z)
    B = federated_covariance_bound(Ps, k)
    Li = np.linalg.inv(np.linalg.cholesky(B))
    dof = samples - 1
    sd = np.sqrt((np.outer(np.diag(S), np.diag(S)) + S**2) / dof)
    return {
        "N": N,
        "kind": kind,
        "z_bound": float((np.linalg.eigvalsh(Li @ S @ Li.T)[-1] - 1) / np.sqrt(2 / dof)),
        "z_trace": float((np.trace(S) - minkowski_trace_bound(Ps)) / np.sqrt(2 * np.trace(S @ S) / dof)),
        "z_eq20": float(np.max(np.abs(S - C) / sd)),
        "exact": float(np.linalg.norm(S - fused_error_covariance(Ps, np.cov(E.T))) / np.linalg.norm(S)),
        "Ps": Ps,
        "S": S,
        "dof": dof,
    }


def _theorem_mc_holds() -> bool:
    k = IN.mc_sigmas
    return all(
        r["z_bound"] <= k and r["z_trace"] <= k and r["z_eq20"] <= k and r["exact"] < 1e-12
        for r in theorem_monte_carlo()
    )


def _remark1_any_sigma() -> bool:
    rng = np.random.default_rng(5)
    Ps = [_spd(rng, 3) for _ in range(3)]
    ok = True
    for _ in range(100):
        k = feasible_weights(Ps, sigmas=rng.uniform(1e-3, 1e3, 3))
        ok &= bool(np.isclose(np.sum(1 / k), 1.0))
    return ok


def bound_tightness(rho: float, kind: str = "isotropic") -> float:
    """tr(Minkowski bound) / tr(true Cov) for correlation rho between three local errors.

    ``kind``: "isotropic" uses the Sec. IV.D-like sigmas (0.02, 0.002, 0.0019) m/s on identity
    covariances; "one-small" makes one sensor 1000 times better; "generic" draws non-commuting
    covariances (seeded).
    """
    n = 3
    if kind == "generic":
        rng = np.random.default_rng(9)
        L = [np.linalg.cholesky(_spd(rng, n)) for _ in range(3)]
    else:
        s = (0.02, 0.002, 0.0019) if kind == "isotropic" else (1.0, 1.0, 1e-3)
        L = [si * np.eye(n) for si in s]
    common = np.vstack(L)
    J = rho * common @ common.T
    for i, Li in enumerate(L):
        J[n * i : n * i + n, n * i : n * i + n] += (1 - rho) * Li @ Li.T
    Ps = [J[n * i : n * i + n, n * i : n * i + n] for i in range(3)]
    return minkowski_trace_bound(Ps) / float(np.trace(fused_error_covariance(Ps, J)))


def remark2_generic_exact() -> bool:
    """Remark (ii) for completely correlated errors with general (non-commuting) covariances: the trace
    of the bound equals the true trace within the declared closeness."""
    return abs(bound_tightness(1.0, "generic") - 1.0) <= IN.close_rel


def _remark2_generic_oracle() -> bool:
    """Oracle: Monte Carlo of completely correlated generic errors, the bound against the sample trace,
    within the declared closeness."""
    return abs(_remark2_generic_ratio_mc() - 1.0) <= IN.close_rel


def _remark2_generic_ratio_mc() -> float:
    """Monte Carlo of completely correlated generic errors: Minkowski trace bound over the sample trace."""
    rng = np.random.default_rng(9)
    L = [np.linalg.cholesky(_spd(rng, 3)) for _ in range(3)]
    Ps = [Li @ Li.T for Li in L]
    w = np.random.default_rng(10).normal(size=(100_000, 3))
    infos = [np.linalg.inv(P) for P in Ps]
    PD = np.linalg.inv(sum(infos))
    fused = sum((w @ (PD @ Y @ Li).T for Y, Li in zip(infos, L, strict=True)), start=np.zeros(w.shape))
    return float(minkowski_trace_bound(Ps) / np.trace(np.cov(fused.T)))


def _fusion_is_wls() -> bool:
    rng = np.random.default_rng(12)
    Ps = [_spd(rng, 3) for _ in range(3)]
    xs = [rng.normal(size=3) for _ in range(3)]
    x, _ = federated_fusion(xs, Ps)
    # weighted LS cost sum (x - x_i)' P_i^-1 (x - x_i): its gradient vanishes at x
    grad = sum(np.linalg.solve(P, x - xi) for P, xi in zip(Ps, xs, strict=True))
    return bool(np.linalg.norm(grad) < 1e-9)


def _outage_is_infinite_covariance() -> bool:
    rng = np.random.default_rng(13)
    Ps = [_spd(rng, 3) for _ in range(3)]
    xs = [rng.normal(size=3) for _ in range(3)]
    a = federated_fusion(xs, [Ps[0], np.diag([np.inf] * 3), Ps[2]])
    b = federated_fusion([xs[0], xs[2]], [Ps[0], Ps[2]])
    big = federated_fusion(xs, [Ps[0], 1e12 * np.eye(3), Ps[2]])
    return bool(np.allclose(a[0], b[0]) and np.allclose(a[1], b[1]) and np.allclose(big[0], b[0], atol=1e-9))


# ----------------------------------------------------------------------------- Section IV.D
def f_l1_over_c() -> float:
    """GPS L1 frequency over the defined speed of light, 1/m (5.2550)."""
    return GPS_L1_HZ / C


def f_l1_over_c_printed() -> float:
    """The printed f_o^L1/c of the Sec. IV.D parameter list (5.25 1/m): the gain of H_G in Eq. (25)."""
    return float(IN.f_l1_over_c_printed)


def f_l1_over_c_read() -> float:
    """GPS L1 frequency over the speed of light under the reading of c used (the convention
    ``c_of_fl1_mps``: the defined c, or the engineering 3e8 or 2.998e8 m/s), 1/m."""
    return GPS_L1_HZ / IN.c_of_fl1_mps


def gps_doppler_velocity_sigma() -> float:
    """Velocity accuracy per line of sight equivalent to sigma_G = 1 Hz: sigma_G / (f_L1/c), m/s."""
    return IN.sigma_g / f_l1_over_c_printed()


#: The satellite cases of Figs. 1-2 (Eq. (25)): no GPS, one satellite, three satellites; labels
#: of the cases the paper draws, not quantities (:func:`local_covariances` takes no other).
SATELLITE_CASES = (0, 1, 3)
GPS_CASES = SATELLITE_CASES[1:]


@implements("WF 24", "WF 25")
def local_covariances(sigma_a: float, sigma_t: float, n_sat: int = 0) -> list[np.ndarray]:
    """P_DN, P_DL(k/k) and, with satellites, P_DG of Sec. IV.D in steady state (3x3 each).

    Reading of Eq. (24) used: tau P_N tau^T = sigma_N^2 I (erratum WF-E2), so
    P_DN = (sigma_N^2 + sigma_T^2) I; sigma_L = 200 sigma_a; H_G of Eq. (25) with the printed
    f_L1/c = 5.25 1/m; P_DG from Eq. (17) on the prior P_DL(k/k-1).
    """
    ss = accelerometer_steady_state_isotropic(sigma_a, IN.ts, IN.sigma_l_per_sigma_a * sigma_a)
    Ps = [(IN.sigma_n**2 + sigma_t**2) * np.eye(3), ss.posterior * np.eye(3)]
    if n_sat:
        if n_sat not in (1, 3):
            raise ValueError(f"n_sat must be 0, 1 or 3 (Eq. (25)), got {n_sat}")
        H = f_l1_over_c_printed() * (np.eye(3) if n_sat == 3 else np.array([[1.0, 0.0, 0.0]]))
        Ps.append(gps_doppler_covariance(ss.prior * np.eye(3), H, IN.sigma_g**2 * np.eye(n_sat)))
    return Ps


def sigma_d_bound(sigma_a: float, sigma_t: float, n_sat: int = 0) -> float:
    """Per-axis 1-sigma federated velocity bound: sqrt(middle term of Eq. (23) / 3), m/s."""
    return float(np.sqrt(minkowski_trace_bound(local_covariances(sigma_a, sigma_t, n_sat)) / 3))


def improvement_db(sigma_a: float, sigma_t: float, n_sat: int = 0) -> float:
    """20 log10(sigma_D / sigma_DN) of Figs. 1-2, dB (negative = improvement)."""
    return federated_improvement_db(
        local_covariances(sigma_a, sigma_t, n_sat), float(np.hypot(IN.sigma_n, sigma_t))
    )


def sigma_a_grid(lo: float | None = None, hi: float | None = None, n: int = 31) -> np.ndarray:
    """The log grid of accelerometer resolutions on which Figs. 1-2 are drawn, m/s^2.

    ``lo``/``hi`` default to the stated range of Sec. IV.D.
    """
    lo = IN.sigma_a_low if lo is None else lo
    hi = IN.sigma_a_high if hi is None else hi
    return np.logspace(np.log10(lo), np.log10(hi), n)


@input_cache
def improvement_curves(lo: float | None = None, hi: float | None = None, n: int = 31) -> dict:
    """Curves of Figs. 1-2 on a log grid of sigma_a: {(sigma_t, n_sat): dB array} and the grid."""
    grid = sigma_a_grid(lo, hi, n)
    out: dict[Any, np.ndarray] = {"sigma_a": grid}
    for st in sigma_t_values():
        for ns in SATELLITE_CASES:
            out[(st, ns)] = np.array([improvement_db(sa, st, ns) for sa in grid])
    return out


def gps_largest_benefit_db() -> float:
    """Largest |Fig. 2 - Fig. 1| (dB) over 1 and 3 satellites, every sigma_T, the stated sigma_a range."""
    c = improvement_curves()
    return float(max(np.max(np.abs(c[(st, ns)] - c[(st, 0)])) for st in sigma_t_values() for ns in GPS_CASES))


def _gps_adds_little() -> bool:
    return gps_largest_benefit_db() < IN.noticeable_db


def three_vs_one_at_zero_db() -> float:
    """Largest |3-satellite - 1-satellite| improvement (dB) at the smallest sigma_T, stated range."""
    c = improvement_curves()
    st = IN.sigma_t_small
    return float(np.max(np.abs(c[(st, GPS_CASES[1])] - c[(st, GPS_CASES[0])])))


def _gps_noticeable_only_when() -> bool:
    """Benefit > 1 dB appears only beyond the stated sigma_a range; the largest is at sigma_T = 2, 3 sats."""
    inside = improvement_curves()
    wide = improvement_curves(IN.sigma_a_low, IN.sigma_a_poor_max, 41)
    sts = sigma_t_values()
    none_inside = all(
        np.min(inside[(st, ns)] - inside[(st, 0)]) > -IN.noticeable_db for st in sts for ns in GPS_CASES
    )
    gains = {(st, ns): np.min(wide[(st, ns)] - wide[(st, 0)]) for st in sts for ns in GPS_CASES}
    best = min(gains, key=lambda key: gains[key])
    idx = int(np.argmin(wide[best] - wide[(best[0], 0)]))
    return bool(
        none_inside and best == (IN.sigma_t_large, GPS_CASES[-1]) and wide["sigma_a"][idx] > IN.sigma_a_high
    )


def accelerometer_prior_gap_db(lo: float | None = None, hi: float | None = None, n: int = 31) -> float:
    """Largest 10 log10(P_DL(k/k-1) / P_DL(k/k)) over the sigma_a grid of the figures, dB.

    The GPS estimate of Eq. (16) starts from the accelerometer prior, which is worse than the
    accelerometer posterior by one step of process noise: on every axis P_DG <= P_DL(k/k-1).
    For isotropic covariances the per-axis bound of Eq. (23) is the mean of the local sigmas
    weighted by their squared information, sum_i (1/sigma_i) / sum_i (1/sigma_i^2); a new
    estimator therefore moves the bound towards its own sigma. While the accelerometer is the
    best local estimator (the bound is then at least sigma_DL), adding the isotropic
    three-satellite GPS estimate can raise the bound by at most this gap.
    """
    gaps = []
    for sa in sigma_a_grid(lo, hi, n):
        ss = accelerometer_steady_state_isotropic(sa, IN.ts, IN.sigma_l_per_sigma_a * sa)
        gaps.append(10 * np.log10(ss.prior / ss.posterior))
    return float(max(gaps))


def fig2_order_excess(lo: float | None = None, hi: float | None = None, n: int = 31) -> float:
    """Largest amount (dB) by which more satellites give a worse bound (3 vs 1, 1 vs 0), all sigma_T."""
    c = improvement_curves(lo, hi, n)
    return float(
        max(
            np.max(c[(st, more)] - c[(st, fewer)])
            for st in sigma_t_values()
            for more, fewer in ((3, 1), (1, 0))
        )
    )


def fig1_slope_db_per_decade() -> float:
    """Least-squares slope of the sigma_T = 2 m/s curve of Fig. 1 over the stated range, dB per decade."""
    c = improvement_curves()
    return float(np.polyfit(np.log10(c["sigma_a"]), c[(IN.sigma_t_large, 0)], 1)[0])


def _fig1_slope() -> bool:
    # 20 dB per decade: sigma_DL grows in proportion to sigma_a (20 log10 of a factor 10)
    return bool(abs(fig1_slope_db_per_decade() - 20.0) < IN.slope_tol_db)


def fig1_order_margin() -> float:
    """Smallest separation (dB) of the Fig. 1 curves: sigma_T large below medium below small."""
    c = improvement_curves()
    small, medium, large = sigma_t_values()
    a, b, d = c[(large, 0)], c[(medium, 0)], c[(small, 0)]
    return float(min(np.min(b - a), np.min(d - b)))


def _fig1_ordered() -> bool:
    return fig1_order_margin() > 0.0


def _fig2_ordered() -> bool:
    return fig2_order_excess() < IN.fig_resolution_db


def _three_as_one() -> bool:
    return three_vs_one_at_zero_db() < IN.fig_resolution_db


def flexible_mode_is_several() -> bool:
    """'An adverse velocity component of several meters/second': the assumed first mode's velocity
    amplitude within the prose table's 'several' (3 to 9 m/s)."""
    word = PROSE_WORDS["several"]
    v = wingtip_velocity_amplitude()
    return bool(word["centre"] - word["abs"] <= v <= word["centre"] + word["abs"])


# ----------------------------------------------------------------------------- errata
ERRATA = [
    Erratum(
        id="WF-E1-eq13-innovation",
        kind="typography",
        basis="text-only",
        locator="Eq. (13)",
        printed="$x_{DL}(k/k) = x_{DL}(k/k-1)$ $+ K_{DL}(k)[y_a(k) - x_{DL}(k/k-1)]$",
        finding="The innovation must be $y_L(k) - x_{DL}(k/k-1)$: the local velocity measurement of "
        "Eq. (12), not the acceleration $y_a$.",
        evidence="Dimensional analysis (acceleration minus velocity) and a seeded simulation of the "
        "printed recursion under an assumed manoeuvre, whose error departs from the Eq. (14) covariance; "
        "the corrected filter matches filterpy's Kalman filter. No printed number uses Eq. (13).",
        claims=("WF-eq13-innovation",),
        discussed_in=DOCS["IV"],
    ),
    Erratum(
        id="WF-E2-eq24-PN",
        kind="units",
        basis="text-only",
        locator="Eq. (24)",
        printed="$P_N P_N^T = \\sigma_N^2 I$",
        finding="Should read $\\tau P_N \\tau^T = \\sigma_N^2 I$, the term that enters Eq. (11); then "
        "$\\sigma_{DN}^2 = \\sigma_N^2 + \\sigma_T^2$.",
        evidence="Units: $P_N P_N^T$ is in (m/s)$^4$; the literal reading makes $\\sigma_{DN}$ depend on the "
        "velocity unit. The one printed number that depends on it, the 60 dB of Sec. IV.D at "
        "$\\sigma_T$ = 2 m/s, holds under both readings, the corrected one and the literal one in "
        "(m/s)$^2$ (the claim on Eq. (24) gives both values): the finding rests on the units alone.",
        claims=("WF-eq24-PN",),
        discussed_in=DOCS["IVD"],
    ),
    Erratum(
        id="WF-E3-eq20-PNG",
        kind="typography",
        basis="text-only",
        locator="Eq. (20)",
        printed="row 2 of the joint covariance: $[P_{LN}, P_{DL}, P_{NG}]$",
        finding="The (2, 3) block is the L-G cross-covariance $P_{LG}$; with $P_{NG}$ the matrix is not a "
        "covariance of the stacked errors (it is not symmetric: block (3, 2) is $P_{GL}$).",
        evidence="Symmetry of the printed matrix and a seeded Monte Carlo of the stacked errors.",
        claims=("WF-eq20-PNG",),
        discussed_in=DOCS["IV"],
    ),
    Erratum(
        id="WF-E4-remark2-correlated",
        kind="unstated-assumption",
        basis="text-only",
        locator="Remark (ii) after the Theorem",
        printed="The upper bound tends to be exact ... when the estimation errors of all processors "
        "are completely correlated.",
        finding="True when the weighted errors $P_D P_i^{-1} e_i$ are parallel (isotropic or commuting "
        "covariances, the Sec. IV.D case); for general, non-commuting covariances the bound stays "
        "conservative even with completely correlated errors.",
        evidence="Exact covariance (Eq. (20)) and a seeded Monte Carlo for a completely correlated "
        "generic case: trace bound / true trace about 1.26.",
        claims=("WF-rem2-generic",),
        discussed_in=DOCS["IV"],
    ),
]


# ----------------------------------------------------------------------------- claims
_fl1, _fl1_tol = printed(F_L1_OVER_C_PRINTED)
_c14r, _c14r_tol = printed("60")
_sL_lo, _sL_lo_tol = printed("0.002")
_sL_hi, _sL_hi_tol = printed("2")
_c17, _c17_tol = printed("0.2")
_c14, _c14_tol = printed("-60")
_c15, _c15_tol = printed("0.002")
_c15f, _c15f_tol = printed("1e3", why="'a factor of $10^{3}$', one significant digit")
_c8, _c8_tol = printed("100")
_c6, _c6_tol = printed("1e4", why="'$10^{4}$ %', one significant digit")
_c3, _c3_tol = printed("10")
_c2, _c2_tol = printed("0.01")
_sg, _sg_tol = printed("1", why="'$\\sigma_G = 1$ Hz (consistent with the GPS velocity accuracy ...)'")

ORDER = prose("on the order of", why="'R/2|v| is on the order of 100'")
APPROX = prose("approximately", why="'approximately 1 % relative to the nominal velocity'")
FIG1_READING = figure_reading(
    0.5,
    figure="Fig. 1",
    axis="improvement $20 \\log_{10}(\\sigma_D / \\sigma_{DN})$ in dB; curves closer than half a dB are "
    "not told apart",
)

CLAIMS = [
    # Section II
    Claim(
        id="WF-eq3-normal",
        locator="Eq. (3)",
        quantity="the Gauss-Newton solution satisfies the weighted LS normal equation",
        published=True,
        unit="statement",
        compute=lambda: _ls_trial()["normal_rel"] < 1e-12,
        tolerance=EXACT,
        expected_status="consistent",
        note="Book geometry (2 deg/s turn at 8 km, 200 m/s, 120 s, 200 samples, the ground "
        "emitter of the chapter's geometry (its mean range is on the page), "
        "$f_0 = 10$ GHz, 1 Hz noise, 0.05 m/s velocity errors), 50 seeded trials; the largest "
        "$\\|\\mathbf H^T\\mathbf W\\,\\mathbf r\\| / (\\|\\mathbf H\\|\\,\\|\\mathbf m\\|)$ "
        "is below $10^{-12}$.",
        discussed_in=DOCS["II"],
    ),
    Claim(
        id="WF-eq6-linear",
        locator="Eq. (6)",
        quantity="first-order location error agrees with the nonlinear estimate (within 1 %)",
        published=True,
        unit="statement",
        compute=lambda: _ls_trial()["rel_lin"] < IN.close_rel,
        tolerance=EXACT,
        expected_status="consistent",
        note="50 seeded trials on the book geometry, RMS difference over RMS linearised error; the "
        "difference is second order in the errors. "
        "'Agrees' is read as within 1 % (or 10 %): the paper prints no accuracy.",
        discussed_in=DOCS["II"],
    ),
    Claim(
        id="WF-eq6-montecarlo",
        locator="Eq. (6)",
        quantity="Eq. (6) predicts the Monte Carlo spread of the nonlinear estimator (each axis within the "
        "sampling error)",
        published=True,
        unit="statement",
        compute=_eq6_mc_agrees,
        tolerance=EXACT,
        expected_status="consistent",
        note="400 seeded trials; 1 Hz white frequency noise and 0.05 m/s white velocity errors per axis; "
        "each axis's sample standard deviation within 5 (or 3) sampling standard deviations (3.5 % each "
        "for 400 draws) of the Eq. (6) prediction.",
        discussed_in=DOCS["II"],
    ),
    Claim(
        id="WF-eq6-model-error-acts-like-noise",
        aliases=("WF-c1-additive",),
        locator="Sec. II, after Eq. (6)",
        quantity="a signal-model error moves the estimate as much as the same measurement error",
        published=True,
        unit="statement",
        compute=lambda: _ls_trial()["rel_same"] < IN.close_rel,
        tolerance=EXACT,
        expected_status="consistent",
        note="The nonlinear fit with wrong aperture velocities vs the fit with exact velocities and the "
        "same frequency error added to the measurements, 50 seeded trials, RMS difference over RMS "
        "estimation error; 'as much as' read as within 1 % (or 10 %).",
        discussed_in=DOCS["II"],
    ),
    # Section III
    Claim(
        id="WF-sec3-tip-position-vs-range",
        aliases=("WF-c2-position",),
        locator="Sec. III",
        quantity="wing-tip position perturbation relative to range",
        published=_c2,
        unit="%",
        compute=lambda: 100 * IN.deflection_ft * FT / mean_range(),
        tolerance=_c2_tol,
        expected_status="not-reproducible",
        relation="<=",
        note="'Several feet' (assumed 5 ft, 3-9) over the mean range of the Sec. III scenario (assumed "
        "speed, altitude and emitter distance). 'At most 0.01 %' is read as an upper bound, with half a "
        "unit in its last printed digit.",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-sec3-tip-position-vs-ins",
        aliases=("WF-c3-position-ins",),
        locator="Sec. III",
        quantity="wing-tip position perturbation relative to the best INS/GPS position accuracy",
        published=_c3,
        unit="%",
        kind="reproduction",
        compute=lambda: 100 * IN.deflection_ft * FT / IN.ins_gps_position_m,
        tolerance=_c3_tol,
        expected_status="not-reproducible",
        relation="<=",
        note="The INS/GPS position accuracy of reference [3] (Graham & Johnston 1986, Table 1) is not "
        "quoted: assumed 10 m (5-30 m). At the nominal 5 ft it gives 15 %; 'at most 10 %' needs an "
        "accuracy of 15 m or worse (or a smaller deflection).",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-sec3-flexible-mode-velocity",
        aliases=("WF-c4-flexible-mode",),
        locator="Sec. III",
        quantity="a first flexible mode of several hertz gives an aperture velocity amplitude of several "
        "m/s (3 to 9 m/s, the reading of 'several' in the ledger's table of prose words)",
        published=True,
        unit="statement",
        kind="statement",
        compute=flexible_mode_is_several,
        tolerance=EXACT,
        expected_status="not-reproducible",
        note="The velocity amplitude $2\\pi f A$ of the assumed first wing mode: $f$ = 3 Hz (3-9, "
        "'several Hertz') with a tip amplitude $A$ = 0.1 m (5-30 cm) gives 1.9 m/s, below 'several'. The "
        "paper says the mode 'can result in' several m/s, a "
        "possibility: across the assumed frequency and amplitude the velocity amplitude spans 0.94-17 "
        "m/s and lies in 3-9 m/s over part of that range, not at the nominal mode. The paper prints no "
        "number: 'several' is read as 3-9, as in the ledger's table of prose words.",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-sec3-velocity-vs-nominal",
        aliases=("WF-c5-velocity-nominal",),
        locator="Sec. III",
        quantity="velocity perturbation relative to the nominal velocity",
        published=1.0,
        unit="%",
        compute=lambda: 100 * IN.sigma_t_large / IN.speed_mps,
        tolerance=APPROX,
        expected_status="consistent",
        note="Perturbation = the large $\\sigma_T$ of Sec. IV.D (2 m/s); nominal speed assumed 200 m/s "
        "(100-300).",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-sec3-velocity-vs-ins",
        aliases=("WF-c6-velocity-ins",),
        locator="Sec. III",
        quantity="velocity perturbation relative to the best INS/GPS velocity accuracy",
        published=_c6,
        unit="%",
        kind="cross-check",
        compute=lambda: 100 * IN.sigma_t_large / IN.sigma_n,
        tolerance=_c6_tol,
        expected_status="consistent",
        note="$\\sigma_T = 2$ m/s over $\\sigma_N = 0.02$ m/s, both printed in Sec. IV.D: arithmetic on "
        "printed values, a cross-check.",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-eq8-norm",
        locator="Eq. (8)",
        quantity="$\\|\\partial f/\\partial \\mathbf{v}\\| = f_0/c$ for every geometry",
        published=True,
        unit="statement",
        compute=_eq8_identity,
        tolerance=EXACT,
        expected_status="reproduced",
        note="2000 seeded random geometries; relative deviation < $10^{-12}$.",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-eq9-bound",
        locator="Eq. (9)",
        quantity="$\\|\\partial f/\\partial \\mathbf{p}\\| \\le (f_0/c)\\, 2\\|\\mathbf{v}\\|/R$ for every "
        "geometry",
        published=True,
        unit="statement",
        compute=_eq9_bound_holds,
        tolerance=EXACT,
        expected_status="reproduced",
        note="2000 seeded random geometries. The exact norm is $(f_0/c)\\|\\mathbf{v}_\\perp\\|/R$, so the "
        "bound is "
        "loose by at least a factor 2.",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-eq9-velocity-position-ratio",
        aliases=("WF-c7-ratio",),
        locator="Sec. III, after Eq. (9)",
        quantity="$R / (2 \\|\\mathbf{v}\\|)$, velocity-to-position sensitivity ratio",
        published=100.0,
        unit="s",
        compute=lambda: float(velocity_to_position_sensitivity_ratio(IN.speed_mps, mean_range())),
        tolerance=ORDER,
        expected_status="not-reproducible",
        note="Mean range of the Sec. III scenario (assumed speed, altitude and emitter distance). With the "
        "exact Eq. (9) norm the ratio is at least $R/\\|\\mathbf{v}\\|$, twice as large.",
        discussed_in=DOCS["III"],
    ),
    Claim(
        id="WF-eq9-velocity-error-dominates",
        aliases=("WF-c8-effective",),
        locator="Sec. III, after Eq. (9)",
        quantity="a 1 m/s velocity error changes the modelled frequency at least 100 times as much as a "
        "1 m position error (smallest "
        "$\\|\\partial f/\\partial \\mathbf{v}\\| / \\|\\partial f/\\partial \\mathbf{p}\\|$ over the track)",
        published=_c8,
        unit="s",
        compute=lambda: float(np.min(sensitivity_ratios())),
        tolerance=_c8_tol,
        expected_status="not-reproducible",
        relation=">=",
        note="'At least 100 times more effective', read with the exact gradients of Eqs. (8)-(9) over the "
        "Sec. III scenario (assumed speed, altitude and emitter distance: the paper gives none). The "
        "exact ratio is $R/\\|\\mathbf{v}_\\perp\\| \\ge R/\\|\\mathbf{v}\\|$, "
        "so it holds on any track with $R \\ge$ 100 s $\\cdot \\|\\mathbf{v}\\|$. The paper's own "
        "argument, $R/(2\\|\\mathbf{v}\\|)$ "
        "(WF-eq9-velocity-position-ratio), "
        "falls short of 100 on this geometry. Through Eq. (6) the location-error leverage depends on the "
        "error: a constant vertical velocity error is mostly absorbed by the $f_0$ estimate (shown on this "
        "page).",
        discussed_in=DOCS["III"],
    ),
    # Section IV.A-C
    Claim(
        id="WF-eq13-innovation",
        locator="Eq. (13)",
        quantity="the innovation of the printed filter, $y_a(k) - \\hat x_{DL}(k/k-1)$, is a velocity "
        "residual (a difference of like quantities), as a Kalman filter of Eq. (12) needs",
        published=True,
        unit="statement",
        kind="statement",
        compute=eq13_innovation_is_a_velocity_residual,
        tolerance=EXACT,
        expected_status="discrepant",
        erratum="WF-E1-eq13-innovation",
        oracle=_eq13_oracle,
        oracle_tolerance=EXACT,
        note="$y_a$ is the accelerometer output of Eq. (12), an acceleration; $\\hat x_{DL}$ a velocity: the "
        "printed innovation subtracts a velocity from an acceleration. Checked independently by a seeded "
        "simulation of the printed recursion (200 paths, 5000 steps, $\\sigma_a = 10^{-3}$ m/s², the assumed "
        "0.5 m/s² manoeuvre at 0.2 Hz): its error ends about 80 times $\\sqrt{P_{DL}(k/k)}$, far outside "
        "the covariance of Eq. (14). No printed number uses Eq. (13) (Figs. 1-2 follow Eq. (14)).",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-eq20-PNG",
        locator="Eq. (20)",
        quantity="the printed joint matrix (block (2,3) = $P_{NG}$) is the covariance of the stacked errors",
        published=True,
        unit="statement",
        kind="statement",
        compute=eq20_printed_is_covariance,
        tolerance=EXACT,
        expected_status="discrepant",
        erratum="WF-E3-eq20-PNG",
        oracle=_eq20_oracle,
        oracle_tolerance=EXACT,
        note="A seeded random $9 \\times 9$ joint covariance; with $P_{NG}$ in block (2,3) the matrix is "
        "not symmetric "
        "and not the covariance of the stacked errors. Checked independently against the Monte Carlo L-G "
        "cross-covariance.",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-eq19-outage-infinite-covariance",
        aliases=("WF-c11-outage",),
        locator="Sec. IV.C, after Eq. (19)",
        quantity="an outage is handled by setting its covariance to infinity",
        published=True,
        unit="statement",
        compute=_outage_is_infinite_covariance,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Infinite covariance = fusion of the remaining estimators = limit of a huge covariance.",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-eq19-weighted-least-squares",
        aliases=("WF-c12-wls",),
        locator="Sec. IV.C, after Eq. (19)",
        quantity="Eq. (18) is the solution of a weighted least-squares cost",
        published=True,
        unit="statement",
        compute=_fusion_is_wls,
        tolerance=EXACT,
        expected_status="reproduced",
        note="The gradient of $\\sum_i (\\mathbf x - \\hat{\\mathbf x}_i)^T \\mathbf P_i^{-1} (\\mathbf x "
        "- \\hat{\\mathbf x}_i)$ vanishes at the fused estimate. The "
        "proof "
        "in [7] is not available; the minimum-variance reading holds for uncorrelated local errors.",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-thm-bound",
        locator="Theorem, Eqs. (21)-(23)",
        quantity="the matrix bound (21) and both inequalities of (23) hold for any correlation",
        published=True,
        unit="statement",
        compute=_theorem_holds,
        tolerance=EXACT,
        expected_status="reproduced",
        note="200 seeded random joint covariances (3 estimators, 3 states, correlation uniform in "
        "[0, 1]) with random $z_i$ in Eq. (22); exact covariance from Eq. (20).",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-thm-montecarlo",
        locator="Theorem, Eqs. (21)-(23)",
        quantity="sampled fused errors stay below the bounds (21) and (23) and match Eq. (20), within "
        "sampling error",
        published=True,
        unit="statement",
        compute=_theorem_mc_holds,
        tolerance=EXACT,
        expected_status="reproduced",
        note="12 seeded cases (2-4 estimators, 3 states; generic, mixed and completely correlated joint "
        "covariances), 20 000 draws each, fused with the Eqs. (18)-(19) weights. Criterion: the excess of "
        "the sample covariance over the bound (largest eigenvalue after whitening by the bound), the trace "
        "excess over the Minkowski term and every deviation from Eq. (20) stay within 5 sampling standard "
        "deviations; Eq. (20) on the sample joint covariance equals the sample covariance to round-off.",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-rem1-weights",
        locator="Remark (i)",
        quantity="$k_i = \\sum_j \\sqrt{\\sigma_j}/\\sqrt{\\sigma_i}$ is feasible",
        published=True,
        unit="statement",
        compute=_remark1_any_sigma,
        tolerance=EXACT,
        expected_status="reproduced",
        note="$\\sum 1/k_i = 1$ for any positive $\\sigma_j$, so the remark's range restriction is not "
        "needed.",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-rem2-isotropic",
        locator="Remark (ii)",
        quantity="the bound is exact for completely correlated errors (isotropic covariances)",
        published=True,
        unit="statement",
        compute=lambda: abs(bound_tightness(1.0, "isotropic") - 1) < 1e-9,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Sec. IV.D-like sigmas; trace of the Minkowski bound / true trace = 1.",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-rem2-one-small",
        locator="Remark (ii)",
        quantity="the bound tends to be exact when one sensor error is much smaller",
        published=True,
        unit="statement",
        compute=lambda: bound_tightness(0.0, "one-small") - 1.0 <= IN.close_rel,
        tolerance=EXACT,
        expected_status="reproduced",
        note="One sensor 1000 times better, uncorrelated errors; 'tends to be exact' read as within 1 % (or "
        "10 %) of the true trace.",
        discussed_in=DOCS["IV"],
    ),
    Claim(
        id="WF-rem2-generic",
        locator="Remark (ii)",
        quantity="the bound tends to be exact for completely correlated errors, general (non-commuting) "
        "covariances",
        published=True,
        unit="statement",
        kind="statement",
        compute=remark2_generic_exact,
        tolerance=EXACT,
        expected_status="discrepant",
        erratum="WF-E4-remark2-correlated",
        oracle=_remark2_generic_oracle,
        oracle_tolerance=EXACT,
        note="Seeded non-commuting covariances, completely correlated errors: the trace of the bound stays "
        "about 1.26 times the true trace, outside 1 % and 10 % alike. Checked independently against a "
        "Monte Carlo of the fused error (100 000 draws).",
        discussed_in=DOCS["IV"],
    ),
    # Section IV.D
    Claim(
        id="WF-eq25-fL1c",
        locator="Sec. IV.D",
        quantity="$f_{L1} / c$",
        published=_fl1,
        unit="1/m",
        compute=f_l1_over_c_read,
        tolerance=_fl1_tol,
        expected_status="consistent",
        note="1575.42 MHz ($154 \\times 10.23$ MHz) over $c$. With the defined $c$ (299 792 458 m/s) "
        "the ratio is 5.2550, which rounds to 5.26, 0.00004 beyond half a unit in the last printed "
        "digit; with the engineering $c$ of $3 \\times 10^{8}$ m/s (5.2514) or $2.998 \\times 10^{8}$ m/s "
        "(5.2549) it rounds to the printed 5.25. "
        "The figures use the printed 5.25.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-sec4d-sigma-g-from-gps-doppler",
        aliases=("WF-c13-sigmaG",),
        locator="Sec. IV.D",
        quantity="$\\sigma_G$ = 1 Hz is consistent with the GPS velocity accuracy from Doppler: the Doppler "
        "noise equivalent to that accuracy per line of sight",
        published=_sg,
        unit="Hz",
        kind="reproduction",
        compute=lambda: IN.gps_doppler_velocity_mps * f_l1_over_c_printed(),
        tolerance=_sg_tol,
        expected_status="not-reproducible",
        note="The paper gives no value (and no reference) for the GPS Doppler velocity accuracy it compares "
        "with: assumed 0.1 m/s per line of sight (0.05-0.2), times the printed $f_{L1}/c$. Conversely "
        "$\\sigma_G = 1$ Hz is "
        "$\\sigma_G c / f_{L1} = 0.19$ m/s per line of sight (computed on the page), an order of magnitude "
        "above "
        "$\\sigma_N$, which is an integrated INS/GPS accuracy ([3]) and not the quantity meant.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-sec4d-sigma-l-high-resolution",
        aliases=("WF-c13-sigmaL-high-res",),
        locator="Sec. IV.D",
        quantity="$\\sigma_L = 200 \\sigma_a$ at $\\sigma_a$ = 10 µm/s²",
        published=_sL_lo,
        unit="m/s",
        kind="cross-check",
        compute=lambda: IN.sigma_l_per_sigma_a * IN.sigma_a_low,
        tolerance=_sL_lo_tol,
        expected_status="consistent",
        note="Both ends of the printed $\\sigma_L$ range follow from $\\sigma_L = 200 \\sigma_a$ and the "
        "printed "
        "$\\sigma_a$ range: arithmetic on printed values, a cross-check.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-sec4d-sigma-l-medium-resolution",
        aliases=("WF-c13-sigmaL-medium-res",),
        locator="Sec. IV.D",
        quantity="$\\sigma_L = 200 \\sigma_a$ at $\\sigma_a$ = 10 mm/s²",
        published=_sL_hi,
        unit="m/s",
        kind="cross-check",
        compute=lambda: IN.sigma_l_per_sigma_a * IN.sigma_a_high,
        tolerance=_sL_hi_tol,
        expected_status="consistent",
        note="Both ends of the printed $\\sigma_L$ range follow from $\\sigma_L = 200 \\sigma_a$ and the "
        "printed "
        "$\\sigma_a$ range: arithmetic on printed values, a cross-check.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-eq24-PN",
        locator="Eq. (24)",
        quantity="$P_N P_N^T = \\sigma_N^2 I$ is consistent with Eq. (11): the "
        "literal reading gives the same "
        "$\\sigma_{DN}$ in any velocity unit",
        published=True,
        unit="statement",
        kind="statement",
        compute=eq24_literal_is_unit_consistent,
        tolerance=EXACT,
        expected_status="discrepant",
        erratum="WF-E2-eq24-PN",
        oracle=_eq24_oracle,
        oracle_tolerance=EXACT,
        note="A consistent reading gives the same $\\sigma_{DN}$ in any velocity unit. Under the literal "
        "reading, the navigation-only error $\\sigma_{DN}$ of a rigid wing ($\\sigma_T = 0$), computed in "
        "cm/s and converted back, is 0.1 times the value computed in m/s. Checked independently by the "
        "derivation "
        "($P_N P_N^T$ in (m/s)$^4$ against $\\sigma_N^2$ in (m/s)$^2$). The one printed number that "
        "depends on Eq. (24), the 60 dB of Fig. 1 at $\\sigma_T$ = 2 m/s, holds under both readings "
        "(-60.16 and -60.18 dB).",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-fig1-improvement-at-100ug",
        aliases=("WF-c14-60dB",),
        locator="Sec. IV.D, Fig. 1",
        quantity="reduction of the local velocity error with a 100 µg accelerometer at $\\sigma_T$ = 2 m/s, "
        "read off Fig. 1",
        published=_c14r,
        unit="dB",
        compute=lambda: -improvement_db(sigma_a_example(), IN.sigma_t_large),
        tolerance=FIG1_READING,
        expected_status="reproduced",
        relation=">=",
        note="'At least a 60dB reduction', which the paper reads off Fig. 1. Per-axis $\\sigma_D "
        "= \\sqrt{\\text{Eq. (23) middle term} / 3}$; "
        "1 µg = $9.80665 \\times 10^{-6}$ m/s²; steady state; $P_{DL}(k/k)$. Under the full-trace reading "
        "(the whole middle term of Eq. (23), not a third of it) the reduction falls short of 60 dB; the "
        "page shows the value.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-sec4d-improvement-factor",
        aliases=("WF-c15-factor",),
        locator="Sec. IV.D",
        quantity="accuracy improvement factor $\\sigma_{DN} / \\sigma_D$ at 100 µg, $\\sigma_T$ = 2 m/s",
        published=_c15f,
        unit="",
        compute=lambda: float(
            np.hypot(IN.sigma_n, IN.sigma_t_large) / sigma_d_bound(sigma_a_example(), IN.sigma_t_large)
        ),
        tolerance=_c15f_tol,
        expected_status="reproduced",
        relation=">=",
        note="'A factor of $10^3$', read with the 'at least' of the same sentence.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-sec4d-fused-velocity-accuracy",
        aliases=("WF-c15-sigmaD",),
        locator="Sec. IV.D",
        quantity="improved local velocity accuracy at 100 µg, $\\sigma_T$ = 2 m/s",
        published=_c15,
        unit="m/s",
        compute=lambda: sigma_d_bound(sigma_a_example(), IN.sigma_t_large),
        tolerance=_c15_tol,
        expected_status="reproduced",
        relation="<=",
        note="'At least $2 \\times 10^{-3} = 0.002$ m/s': the per-axis bound is $1.963 \\times 10^{-3}$ m/s.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-sec4d-unfiltered-velocity-accuracy",
        aliases=("WF-c17-unfiltered",),
        locator="Sec. IV.D",
        quantity="local velocity accuracy without filtering at 100 µg",
        published=_c17,
        unit="m/s",
        kind="cross-check",
        compute=lambda: IN.sigma_l_per_sigma_a * sigma_a_example(),
        tolerance=prose("around", why="'at around 0.2m/s'"),
        expected_status="consistent",
        note="$\\sigma_L = 200 \\sigma_a = 0.196$ m/s, from printed values (and g): arithmetic on printed "
        "values, a cross-check.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-fig1-slope",
        locator="Fig. 1",
        quantity="the $\\sigma_T$ = 2 m/s curve rises 20 dB per decade of accelerometer resolution",
        published=True,
        unit="statement",
        compute=_fig1_slope,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Figure-only (no curve values printed); least-squares slope within 0.5 (or 1) dB/decade of 20 "
        "over 10 µm/s² to 10 mm/s², as $\\sigma_{DL} \\approx 2\\,\\mathrm{s} \\cdot \\sigma_a$ "
        "predicts. The computation reads published inputs and the reading of the slope only.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-fig1-order",
        locator="Fig. 1",
        quantity="larger lever-arm uncertainty gives more improvement: the curves $\\sigma_T$ = 2 below 0.2 "
        "below 0 m/s over the stated range",
        published=True,
        unit="statement",
        kind="statement",
        compute=_fig1_ordered,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Figure-only; over the stated axis range 10 µm/s² to 10 mm/s², the curves are apart by at least "
        "19 dB. The page also shows that every curve is at or below 0 dB and that the $\\sigma_T = 2$ m/s "
        "curve rises monotonically. The computation reads published inputs only.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-fig2-gps-adds-little",
        aliases=("WF-c18-gps-little",),
        locator="Sec. IV.D, Fig. 2",
        quantity="GPS adds little to the accelerometer over the stated range (less than a noticeable change)",
        published=True,
        unit="statement",
        compute=_gps_adds_little,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Fig. 2 differs from Fig. 1 by less than 1 dB (or 3 dB), the readings of 'noticeable', for 1 "
        "and 3 satellites, every $\\sigma_T$ and every $\\sigma_a$ in 10 µm/s² to 10 mm/s² (the page "
        "shows the largest difference). Beyond about 30 mm/s² it no "
        "longer holds.",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-sec4d-gps-noticeable-only-when-severe",
        aliases=("WF-c19-gps-noticeable",),
        locator="Sec. IV.D",
        quantity="GPS is noticeable only with severe $\\sigma_T$, a poor accelerometer and 3 satellites",
        published=True,
        unit="statement",
        compute=_gps_noticeable_only_when,
        tolerance=EXACT,
        expected_status="consistent",
        note="Holds only if the axis extends beyond the stated 10 mm/s²: inside the range no benefit "
        "exceeds 1 dB ('noticeable' read as 1 or 3 dB); on 10 µm/s² to the assumed 'very poor' end "
        "(1 m/s², range 0.1-1) the largest one is at $\\sigma_T = 2$ m/s, 3 satellites, above 10 mm/s².",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-fig2-three-vs-one-satellite",
        aliases=("WF-c20-three-vs-one",),
        locator="Sec. IV.D, Fig. 2",
        quantity="3 satellites virtually identical to 1 at $\\sigma_T$ = 0: the two "
        "improvement curves closer "
        "than Fig. 2 can show over the stated range",
        published=True,
        unit="statement",
        kind="statement",
        compute=_three_as_one,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Over the stated $\\sigma_a$ range the two curves differ by less than the figure can show "
        "(the page gives the largest difference). 'Virtually "
        "identical' (the 3-satellite curve is not drawn) is read as closer than the figure's resolution "
        "(half or a tenth of a dB).",
        discussed_in=DOCS["IVD"],
    ),
    Claim(
        id="WF-fig2-order",
        locator="Sec. IV.D, Fig. 2",
        quantity="more GPS satellites never give less improvement (3 satellites over 1, 1 over none, any "
        "$\\sigma_T$, over the stated $\\sigma_a$ range), as far as Fig. 2 can show",
        published=True,
        unit="statement",
        kind="statement",
        compute=_fig2_ordered,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Figure-only (the paper's 'benefits' of GPS, Fig. 2 curves in order). The correlation-free "
        "bound is not monotone in the estimators: the GPS estimate is the accelerometer prior updated "
        "once, and an estimator worse than the current bound pulls the bound towards itself; while the "
        "accelerometer is the best local estimator (the whole stated range) the rise is at most the "
        "prior/posterior gap $10 \\log_{10}(P_{DL}(k/k-1)/P_{DL}(k/k))$ of the accelerometer filter (on the "
        "page), "
        "far below what Fig. 2 can show. Beyond the stated range the ordering fails by about 1 dB (one "
        "satellite at $\\sigma_T = 0$). Read at the figure's resolution (half or a tenth of a dB): the "
        "largest rise is 0.0002 dB.",
        discussed_in=DOCS["IVD"],
    ),
]

CLAIMS = quoted(CLAIMS)
