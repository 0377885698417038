"""WF: Wu & Fowler, "Application of MEMS for Improved Emitter Location Accuracy": the inputs.

The registered inputs of every WF claim (:data:`IN`, one set, full names ``WF.wf.<name>``),
declared once here with their locators and read by the section modules
(:mod:`~navcore.papers.wf_location_error` for Sec. II,
:mod:`~navcore.papers.wf_aperture_velocity` for Sec. III,
:mod:`~navcore.papers.wf_local_estimators` and :mod:`~navcore.papers.wf_federated_fusion` for
Secs. IV.B-C, :mod:`~navcore.papers.wf_assessment` for Secs. IV.D and V). Most published values
are the Sec. IV.D parameter list. What the paper leaves open (the typical range and speed of
Sec. III, the wing-tip deflection and first mode, the INS/GPS accuracies of its reference [3])
is an ``assumed`` input with a plausible range, and the ledger shows each claim across it; the
readings of the words the statements test are ``convention`` inputs.
"""

from __future__ import annotations

from navcore.claims import InputSet
from navcore.units import MICRO_G, C

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


def f_l1_over_c_printed() -> float:
    """The printed f_o^L1/c of the Sec. IV.D parameter list (5.25 1/m): the gain of H_G in Eq. (25)."""
    return float(IN.f_l1_over_c_printed)
