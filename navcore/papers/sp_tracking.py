"""SP Section 2.5 (first part): the third-order carrier loop, Fig. 2.1, Eq. (2.1), the jerk case.

Published inputs are typed here once with their locators; the reproduced values come from
:mod:`navcore.gnss.tracking`. The distance-to-phase conversion is an explicit wavelength:
the paper's 17.67 rad/s and 90 degrees are reproduced only with one cycle per foot, not
with the stated "code length of 300 m" nor with the L1 carrier (erratum SP-E-phase-conversion).
"""

from __future__ import annotations

from functools import cache

import numpy as np
from scipy import signal

from navcore.gnss.tracking import (
    aided_natural_frequency,
    distance_to_phase_deg,
    error_transfer_coefficients,
    jerk_pulse_error,
    natural_frequency_for_peak_error,
    third_order_loop_step_error,
    third_order_peak_step_error,
)
from navcore.ledger import EXACT, Claim, Erratum, Tolerance, printed
from navcore.units import FT, G0, GPS_L1_WAVELENGTH_M, GPS_P_CHIP_M, C

# --- published inputs (Sec. 2.5) --------------------------------------------------------
STEP_G = 6.0  # "a 6-g acceleration step" (Sec. 2.5, Fig. 2.1 caption)
PEAK_LIMIT_DEG = 90.0  # "phase error be less than 90 deg"
OMEGA0_FIG21 = 17.67  # rad/s, "a natural frequency of 17.67 rad/s" (Fig. 2.1 text)
JERK_G_PER_S = 10.0  # "a 10-g/s jerk, which lasts for 0.6 s"
JERK_DURATION_S = 0.6
CODE_LENGTH_M = 300.0  # "using the code length of 300 m" (the stated conversion)

#: The conversion that reproduces the paper's numbers: one cycle (360 deg) per foot.
FOOT_PER_CYCLE_M = FT

PAGE = "sp/02-tracking-loop"


def step_deg_s2(wavelength_m: float) -> float:
    """The 6-g step in deg/s^2 for a given metres-per-cycle conversion."""
    return float(distance_to_phase_deg(STEP_G * G0, wavelength_m))


def peak_deg(wavelength_m: float, omega0: float = OMEGA0_FIG21) -> float:
    """Peak phase error (deg) of the 6-g step for a conversion and natural frequency."""
    return third_order_peak_step_error(step_deg_s2(wavelength_m), omega0)


def lsim_peak_deg(wavelength_m: float, omega0: float = OMEGA0_FIG21) -> float:
    """Independent oracle: simulate E(s) = s^3/D(s) driven by R t^2/2 with scipy and take the max."""
    num, den = error_transfer_coefficients(omega0)
    t = np.linspace(0.0, 1.5, 60001)
    R = step_deg_s2(wavelength_m)
    _, y, _ = signal.lsim((num, den), 0.5 * R * t**2, t)
    return float(np.max(y))


def closed_form_matches_simulation() -> bool:
    """The closed form under Fig. 2.1 (exponent -w0 t/2) equals a time-domain simulation."""
    num, den = error_transfer_coefficients(OMEGA0_FIG21)
    t = np.linspace(0.0, 1.5, 30001)
    _, y, _ = signal.lsim((num, den), 0.5 * t**2, t)
    closed = third_order_loop_step_error(t, 1.0, OMEGA0_FIG21)
    return bool(np.max(np.abs(y - closed)) < 1e-6 * np.max(np.abs(closed)))


def printed_ocr_form(t: np.ndarray, step: float, omega0: float) -> np.ndarray:
    """The formula exactly as the source text prints it, with exp(-w0 t^2)."""
    tau = omega0 * t
    s3 = np.sqrt(3.0)
    return (step / omega0**2) * (
        np.exp(-tau) + np.exp(-omega0 * t**2) / s3 * (np.sin(s3 / 2 * tau) - s3 * np.cos(s3 / 2 * tau))
    )


def _grid_peak(step: float, omega0: float) -> float:
    t = np.linspace(0.0, 12.0 / omega0, 200001)
    return float(np.max(third_order_loop_step_error(t, step, omega0)))


def eq21_keeps_peak() -> bool:
    """Eq. (2.1): the aided frequency gives the unaided peak under the aided step (grid maxima)."""
    R_u, w_u = 6.0, 18.0
    ok = True
    for R_a in (0.011, 0.0026, 0.0019, 0.0014):
        w_a = float(aided_natural_frequency(R_a, R_u, w_u))
        ok &= abs(_grid_peak(R_a, w_a) - _grid_peak(R_u, w_u)) < 1e-9 * _grid_peak(R_u, w_u)
    return bool(ok)


@cache
def jerk_peak_deg(wavelength_m: float, omega0: float = OMEGA0_FIG21) -> float:
    """Peak error (deg) of the 10 g/s jerk held for 0.6 s."""
    t = np.linspace(0.0, 3.0, 60001)
    J = float(distance_to_phase_deg(JERK_G_PER_S * G0, wavelength_m))
    return float(np.max(jerk_pulse_error(t, J, JERK_DURATION_S, omega0)))


def step_more_stringent_than_jerk() -> bool:
    return peak_deg(GPS_L1_WAVELENGTH_M) > jerk_peak_deg(GPS_L1_WAVELENGTH_M) and peak_deg(
        FT
    ) > jerk_peak_deg(FT)


_peak90 = printed("90", why="the paper prints the peak as a round 90 deg")
_omega = printed("17.67")

ERRATA = [
    Erratum(
        id="SP-E-phase-conversion",
        paper="SP",
        locator="Sec. 2.5, Fig. 2.1",
        printed="distance converted to phase 'using the code length of 300 m'; "
        "17.67 rad/s gives a 90 deg peak",
        finding="With 300 m per cycle a 6-g step peaks at 0.09 deg, not 90 deg. The printed 17.67 rad/s "
        "and 90 deg follow from 360 deg per 0.3048 m (one cycle per foot). With the L1 carrier "
        "(0.1903 m) the peak is 144.2 deg and a 90 deg limit needs 22.37 rad/s, so every aided "
        "natural frequency of Table 2.6 would be 1.243 times larger.",
        evidence="Closed-form peak 0.404453 R/w0^2 and an independent scipy.signal.lsim simulation of "
        "s^3/D(s) driven by R t^2/2; the wavelength solving peak = 90 deg at 17.67 rad/s is 0.3049 m.",
        claims=("SP-fig2.1-peak-code300", "SP-fig2.1-peak-L1", "SP-fig2.1-peak", "SP-fig2.1-omega0"),
        discussed_in=PAGE,
    ),
    Erratum(
        id="SP-E-exponent-t2",
        paper="SP",
        locator="Sec. 2.5, equation above Fig. 2.1",
        printed="e^{-omega_0 t^2} in the second term",
        finding="The exponent is -omega_0 t/2 (the real part of the complex pole pair "
        "-omega_0/2 +- j sqrt(3) omega_0/2); sin/cos arguments are (sqrt(3)/2) omega_0 t. With t^2 "
        "the expression is not dimensionally consistent and is not the loop's response.",
        evidence="sympy inverse Laplace transform of R/((s+w0)(s^2+w0 s+w0^2)) equals the corrected "
        "form (difference 0), and a scipy.signal.lsim simulation agrees to 1e-6 relative.",
        claims=("SP-eq2.u1-closed-form",),
        discussed_in=PAGE,
    ),
    Erratum(
        id="SP-E-slightly-stringent",
        paper="SP",
        locator="Sec. 2.5",
        printed="the 6-g step requirement is 'a slightly more stringent requirement' "
        "than a 10-g/s jerk lasting 0.6 s",
        finding="At 17.67 rad/s the step's peak error is about 4 times the jerk's (144 vs 36 deg at L1; "
        "90 vs 23 deg with the paper's conversion): far more than 'slightly'.",
        evidence="Closed-form step and jerk-pulse responses of the same loop (ratio independent of the "
        "conversion), checked against scipy.signal.lsim in the tests.",
        claims=("SP-sec2.5-step-vs-jerk",),
        discussed_in=PAGE,
    ),
]

CLAIMS = [
    Claim(
        id="SP-fig2.1-peak",
        paper="SP",
        locator="Fig. 2.1",
        quantity="peak phase error of the third-order loop, 6-g step, 17.67 rad/s (one cycle per foot)",
        published=_peak90[0],
        unit="deg",
        compute=lambda: peak_deg(FOOT_PER_CYCLE_M),
        tolerance=_peak90[1],
        expected_status="reproduced",
        note="Corrected closed form (exponent -w0 t/2), peak 0.404453 R/w0^2, with the conversion that "
        "reproduces the paper: 360 deg per 0.3048 m. The stated 300-m code length and the L1 carrier do "
        "not reproduce it (see the two discrepant claims and erratum SP-E-phase-conversion).",
    ),
    Claim(
        id="SP-fig2.1-omega0",
        paper="SP",
        locator="Fig. 2.1",
        quantity="natural frequency keeping the 6-g step's peak error at 90 deg (one cycle per foot)",
        published=_omega[0],
        unit="rad/s",
        compute=lambda: natural_frequency_for_peak_error(step_deg_s2(FOOT_PER_CYCLE_M), PEAK_LIMIT_DEG),
        tolerance=_omega[1],
        expected_status="reproduced",
        note="w0 = sqrt(f_max R / 90 deg) with R = 6 g in deg/s^2 at 360 deg per foot. With the L1 "
        "carrier the same requirement gives 22.37 rad/s.",
    ),
    Claim(
        id="SP-fig2.1-peak-code300",
        paper="SP",
        locator="Sec. 2.5, Fig. 2.1",
        quantity="peak phase error at 17.67 rad/s with the stated conversion (360 deg per 300 m code length)",
        published=_peak90[0],
        unit="deg",
        compute=lambda: peak_deg(CODE_LENGTH_M),
        tolerance=_peak90[1],
        expected_status="discrepant",
        erratum="SP-E-phase-conversion",
        oracle=lambda: lsim_peak_deg(CODE_LENGTH_M),
        oracle_tolerance=Tolerance(reason="time-domain simulation on a 25-us grid: 1e-5 relative", rel=1e-5),
        note="The conversion the text states gives a peak about 1000 times smaller than printed.",
    ),
    Claim(
        id="SP-fig2.1-peak-L1",
        paper="SP",
        locator="Sec. 2.5, Fig. 2.1",
        quantity="peak L1 carrier-phase error at 17.67 rad/s for a 6-g step (physical conversion, 0.1903 m)",
        published=_peak90[0],
        unit="deg",
        compute=lambda: peak_deg(GPS_L1_WAVELENGTH_M),
        tolerance=_peak90[1],
        expected_status="discrepant",
        erratum="SP-E-phase-conversion",
        oracle=lambda: lsim_peak_deg(GPS_L1_WAVELENGTH_M),
        oracle_tolerance=Tolerance(reason="time-domain simulation on a 25-us grid: 1e-5 relative", rel=1e-5),
        note="A carrier loop tracks the L1 carrier, whose wavelength is c/1575.42 MHz = 0.1903 m: the 6-g "
        "step then peaks at 144.2 deg, and a 90 deg limit needs 22.37 rad/s.",
    ),
    Claim(
        id="SP-eq2.u1-closed-form",
        paper="SP",
        locator="Sec. 2.5, equation above Fig. 2.1",
        quantity="the closed form (exponent read as -w0 t/2) is the third-order loop's step error",
        published=True,
        unit="statement",
        compute=closed_form_matches_simulation,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Compared with a scipy.signal.lsim simulation of E/Theta = s^3/(s^3+2w0 s^2+2w0^2 s+w0^3) "
        "driven by t^2/2 (Butterworth poles, a3 = b3 = 2); the printed t^2 is an OCR error "
        "(erratum SP-E-exponent-t2).",
    ),
    Claim(
        id="SP-eq2.1-keeps-peak",
        paper="SP",
        locator="Eq. (2.1)",
        quantity="scaling w0 by the square root of the step ratio keeps the peak error unchanged",
        published=True,
        unit="statement",
        compute=eq21_keeps_peak,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Peaks found on a fine time grid (not from the peak factor) for the four aided steps of "
        "Table 2.6 against the 6 g, 18 rad/s unaided loop: equal to 1e-9 relative, because the error is "
        "R/w0^2 times a function of w0 t.",
    ),
    Claim(
        id="SP-sec2.5-jerk-6g",
        paper="SP",
        locator="Sec. 2.5",
        quantity="acceleration reached by a 10-g/s jerk lasting 0.6 s",
        published=STEP_G,
        unit="g",
        compute=lambda: JERK_G_PER_S * JERK_DURATION_S,
        tolerance=Tolerance(reason="exact product of the printed jerk and duration", abs=1e-12),
        expected_status="reproduced",
        note="The step the paper substitutes for the jerk has the jerk's final acceleration.",
    ),
    Claim(
        id="SP-sec2.5-step-vs-jerk",
        paper="SP",
        locator="Sec. 2.5",
        quantity="the 6-g step gives a larger peak error than the 10-g/s, 0.6-s jerk (more stringent)",
        published=True,
        unit="statement",
        compute=step_more_stringent_than_jerk,
        tolerance=EXACT,
        expected_status="reproduced",
        note="True for both conversions at 17.67 rad/s; but the ratio is about 4, not 'slightly' "
        "(erratum SP-E-slightly-stringent).",
    ),
    Claim(
        id="SP-sec2.5-half-chip-ns",
        paper="SP",
        locator="Sec. 2.5",
        quantity="half a code chip, in nanoseconds (code loss-of-lock threshold)",
        published=50.0,
        unit="ns",
        compute=lambda: 0.5 * GPS_P_CHIP_M / C * 1e9,
        tolerance=Tolerance(reason="'50 ns' has one significant figure: half a unit of 10 ns", abs=5.0),
        expected_status="reproduced",
        note="Half a P(Y) chip (10.23 Mchip/s) is 48.9 ns; half a C/A chip would be 489 ns, so the code "
        "loop here tracks P(Y), while the 300-m phase convention of Fig. 2.1 suggests C/A.",
    ),
    Claim(
        id="SP-sec2.5-loose-carrier-5.83Hz",
        paper="SP",
        locator="Sec. 2.5",
        quantity="loosely coupled receiver's third-order carrier-loop bandwidth",
        published=5.83,
        unit="Hz",
        compute=None,
        tolerance=printed("5.83")[1],
        expected_status="not-reproducible",
        note="No design rule for it is given. For the Butterworth loop of Fig. 2.1 the noise bandwidth "
        "is (5/6) w0 = 14.7 Hz at 17.67 rad/s; 5.83 Hz would need w0 = 7.0 rad/s. The loop's "
        "coefficients and the requirement behind 5.83 Hz are missing.",
    ),
]
