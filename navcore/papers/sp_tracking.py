"""SP Section 2.5 (first part): the third-order carrier loop, Fig. 2.1, Eq. (2.1), the jerk case.

Published inputs are typed here once with their locators; the reproduced values come from
:mod:`navcore.gnss.tracking`. The distance-to-phase conversion is an explicit wavelength:
the paper's 17.67 rad/s and 90 degrees are reproduced only with one cycle per foot, not
with the stated "code length of 300 m" nor with the L1 carrier (erratum SP-E-phase-conversion).
"""

from __future__ import annotations

import numpy as np
from scipy import signal

from navcore.claims import Claim, Erratum, InputSet, Tolerance, input_cache, printed, with_quotes
from navcore.gnss.tracking import (
    aided_natural_frequency,
    distance_to_phase_deg,
    error_transfer_coefficients,
    jerk_pulse_error,
    natural_frequency_for_peak_error,
    third_order_loop_step_error,
    third_order_peak_step_error,
)
from navcore.papers.sp_quotes import QUOTES
from navcore.units import FT, G0, GPS_L1_WAVELENGTH_M, GPS_P_CHIP_RATE_HZ

IN = InputSet("SP", "tracking")
IN.published("step_g", 6.0, locator="Sec. 2.5, Fig. 2.1", unit="g", quantity="acceleration step")
IN.published("peak_limit_deg", 90.0, locator="Sec. 2.5", unit="deg", quantity="allowed peak phase error")
IN.published("omega0_fig21", 17.67, locator="Sec. 2.5, Fig. 2.1", unit="rad/s", quantity="natural frequency")
IN.published("jerk_g_per_s", 10.0, locator="Sec. 2.5", unit="g/s", quantity="jerk")
IN.published("jerk_duration_s", 0.6, locator="Sec. 2.5", unit="s", quantity="jerk duration")
IN.published(
    "code_length_m",
    300.0,
    locator="Sec. 2.5",
    unit="m",
    quantity="stated distance-to-phase conversion (code length)",
)
IN.published(
    "carrier_loss_cn0_dbhz",
    19.0,
    locator="Sec. 2.5",
    unit="dB-Hz",
    quantity="tracking threshold ('signal-to-noise ratio dropped below 19 dB')",
)
IN.fitted(
    "foot_per_cycle_m",
    FT,
    fitted_to=("SP-fig2.1-peak", "SP-fig2.1-omega0"),
    unit="m",
    quantity="distance per 360 deg of phase behind Fig. 2.1",
    reason="the conversion that reproduces the printed 90 deg at 17.67 rad/s: solving peak = 90 deg gives "
    "0.3049 m, one cycle per foot (0.3048 m); neither the stated 300 m nor the L1 carrier does",
)

PAGE = "sp/02-tracking-loop"


def step_deg_s2(wavelength_m: float) -> float:
    """The 6-g step in deg/s^2 for a given metres-per-cycle conversion."""
    return float(distance_to_phase_deg(IN.step_g * G0, wavelength_m))


def peak_deg(wavelength_m: float, omega0: float | None = None) -> float:
    """Peak phase error (deg) of the 6-g step for a conversion and natural frequency (Fig. 2.1's if None)."""
    w0 = IN.omega0_fig21 if omega0 is None else omega0
    return third_order_peak_step_error(step_deg_s2(wavelength_m), w0)


def lsim_peak_deg(wavelength_m: float, omega0: float | None = None) -> float:
    """Independent oracle: simulate E(s) = s^3/D(s) driven by R t^2/2 with scipy and take the max."""
    num, den = error_transfer_coefficients(IN.omega0_fig21 if omega0 is None else omega0)
    t = np.linspace(0.0, 1.5, 60001)
    R = step_deg_s2(wavelength_m)
    _, y, _ = signal.lsim((num, den), 0.5 * R * t**2, t)
    return float(np.max(y))


def closed_form_matches_simulation() -> bool:
    """The closed form under Fig. 2.1 (exponent -w0 t/2) equals a time-domain simulation."""
    w0 = IN.omega0_fig21
    num, den = error_transfer_coefficients(w0)
    t = np.linspace(0.0, 1.5, 30001)
    _, y, _ = signal.lsim((num, den), 0.5 * t**2, t)
    closed = third_order_loop_step_error(t, 1.0, w0)
    return bool(np.max(np.abs(y - closed)) < 1e-6 * np.max(np.abs(closed)))


def eq21_keeps_peak() -> bool:
    """Eq. (2.1): the aided frequency gives the unaided peak under the aided step (grid maxima).

    Checked for the unaided 6 g and 17.67 rad/s of Fig. 2.1 and aided steps spanning Table 2.6's
    column 3 (1e-3 to 2e-2 g): the identity does not depend on the particular values.
    """
    R_u, w_u = IN.step_g, IN.omega0_fig21

    def grid_peak(step: float, omega0: float) -> float:
        t = np.linspace(0.0, 12.0 / omega0, 200001)
        return float(np.max(third_order_loop_step_error(t, step, omega0)))

    ok = True
    for R_a in (0.02, 0.01, 0.003, 0.001):
        w_a = float(aided_natural_frequency(R_a, R_u, w_u))
        ok &= abs(grid_peak(R_a, w_a) - grid_peak(R_u, w_u)) < 1e-9 * grid_peak(R_u, w_u)
    return bool(ok)


@input_cache
def jerk_peak_deg(wavelength_m: float, omega0: float | None = None) -> float:
    """Peak error (deg) of the 10 g/s jerk held for 0.6 s."""
    t = np.linspace(0.0, 3.0, 60001)
    J = float(distance_to_phase_deg(IN.jerk_g_per_s * G0, wavelength_m))
    w0 = IN.omega0_fig21 if omega0 is None else omega0
    return float(np.max(jerk_pulse_error(t, J, IN.jerk_duration_s, w0)))


def step_more_stringent_than_jerk() -> bool:
    """The step's peak exceeds the jerk's (L1 conversion; the ratio does not depend on the conversion)."""
    return peak_deg(GPS_L1_WAVELENGTH_M) > jerk_peak_deg(GPS_L1_WAVELENGTH_M)


_peak90 = printed("90", why="the paper prints the peak as a round 90 deg")
_omega = printed("17.67")
_g6 = printed("6", why="the '6-g acceleration step'")
_LSIM_TOL = Tolerance(
    reason="time-domain simulation on a 25-us grid: $10^{-5}$ relative", rel=1e-5, policy="exact"
)

ERRATA = [
    Erratum(
        id="SP-E-phase-conversion",
        kind="units",
        basis="computed",
        locator="Sec. 2.5, Fig. 2.1",
        printed="distance converted to phase 'using the code length of 300 m'; "
        "17.67 rad/s gives a 90 deg peak",
        finding="With 300 m per cycle a 6-g step peaks at 0.09 deg, not 90 deg. The printed 17.67 rad/s "
        "and 90 deg follow from 360 deg per 0.3048 m (one cycle per foot). With the L1 carrier "
        "(0.1903 m) the peak is 144.2 deg and a 90 deg limit needs 22.37 rad/s, so every aided "
        "natural frequency of Table 2.6 would be 1.243 times larger.",
        evidence="Closed-form peak $0.404453\\, R/\\omega_0^2$ and an independent linear-system "
        "simulation of "
        "$s^3/D(s)$ driven by $R t^2/2$; the wavelength solving peak = 90 deg at 17.67 rad/s is 0.3049 m.",
        claims=("SP-fig2.1-peak-code300", "SP-fig2.1-peak-L1", "SP-fig2.1-peak", "SP-fig2.1-omega0"),
        discussed_in=PAGE,
    ),
    Erratum(
        id="SP-E-exponent-t2",
        kind="typography",
        basis="text-only",
        locator="Sec. 2.5, equation above Fig. 2.1",
        printed="$e^{-\\omega_0 t^2}$ in the second term",
        finding="The exponent is $-\\omega_0 t/2$ (the real part of the complex pole pair "
        "$-\\omega_0/2 \\pm j \\sqrt{3}\\, \\omega_0/2$); sin/cos arguments are $(\\sqrt{3}/2)\\, \\omega_0 "
        "t$. With $t^2$ "
        "the expression is not dimensionally consistent and is not the loop's response.",
        evidence="A symbolic inverse Laplace transform of $R/((s+\\omega_0)(s^2+\\omega_0 s+\\omega_0^2))$ "
        "equals "
        "the corrected "
        "form (difference 0), and a linear-system simulation agrees to $10^{-6}$ relative.",
        claims=("SP-eq2.u1-closed-form",),
        discussed_in=PAGE,
    ),
]

CLAIMS = [
    Claim(
        id="SP-fig2.1-peak",
        locator="Fig. 2.1",
        quantity="peak phase error of the third-order loop, 6-g step, 17.67 rad/s (one cycle per foot)",
        published=_peak90[0],
        unit="deg",
        kind="fit",
        compute=lambda: peak_deg(IN.foot_per_cycle_m),
        tolerance=_peak90[1],
        expected_status="consistent",
        note="Corrected closed form (exponent $-\\omega_0 t/2$), peak $0.404453\\, R/\\omega_0^2$, with the "
        "conversion fitted "
        "to this printed pair (90 deg at 17.67 rad/s): 360 deg per 0.3048 m. Not evidence. The stated "
        "300-m code length and the L1 carrier do not reproduce it (see the two discrepant claims and "
        "erratum SP-E-phase-conversion).",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim(
        id="SP-fig2.1-omega0",
        locator="Fig. 2.1",
        quantity="natural frequency keeping the 6-g step's peak error at 90 deg (one cycle per foot)",
        published=_omega[0],
        unit="rad/s",
        kind="fit",
        compute=lambda: natural_frequency_for_peak_error(step_deg_s2(IN.foot_per_cycle_m), IN.peak_limit_deg),
        tolerance=_omega[1],
        expected_status="consistent",
        note="$\\omega_0 = \\sqrt{f_{\\max} R / 90\\,\\mathrm{deg}}$ with $R$ = 6 g in deg/s² at the fitted "
        "360 deg per foot (fitted to "
        "this claim and SP-fig2.1-peak; not evidence). With the L1 carrier the same requirement gives "
        "22.37 rad/s. The conversion is a fit.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim(
        id="SP-fig2.1-peak-code300",
        locator="Sec. 2.5, Fig. 2.1",
        quantity="peak phase error at 17.67 rad/s with the stated conversion (360 deg per 300 m code length)",
        published=_peak90[0],
        unit="deg",
        compute=lambda: peak_deg(IN.code_length_m),
        tolerance=_peak90[1],
        expected_status="discrepant",
        erratum="SP-E-phase-conversion",
        oracle=lambda: lsim_peak_deg(IN.code_length_m),
        oracle_tolerance=_LSIM_TOL,
        note="The conversion the text states gives a peak about 1000 times smaller than printed.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim(
        id="SP-fig2.1-peak-L1",
        locator="Sec. 2.5, Fig. 2.1",
        quantity="peak L1 carrier-phase error at 17.67 rad/s for a 6-g step (physical conversion, 0.1903 m)",
        published=_peak90[0],
        unit="deg",
        compute=lambda: peak_deg(GPS_L1_WAVELENGTH_M),
        tolerance=_peak90[1],
        expected_status="discrepant",
        erratum="SP-E-phase-conversion",
        oracle=lambda: lsim_peak_deg(GPS_L1_WAVELENGTH_M),
        oracle_tolerance=_LSIM_TOL,
        note="A carrier loop tracks the L1 carrier, whose wavelength is c/1575.42 MHz = 0.1903 m: the 6-g "
        "step then peaks at 144.2 deg, and a 90 deg limit needs 22.37 rad/s.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim.statement(
        id="SP-eq2.u1-closed-form",
        locator="Sec. 2.5, equation above Fig. 2.1",
        quantity="the closed form (exponent read as $-\\omega_0 t/2$) is the third-order loop's step error",
        compute=closed_form_matches_simulation,
        note="Compared with a linear-system simulation of "
        "$E/\\Theta = s^3/(s^3 + 2\\omega_0 s^2 + 2\\omega_0^2 s + \\omega_0^3)$ driven by $t^2/2$ "
        "(Butterworth poles, $a_3 = b_3 = 2$); the $t^2$ of the source text is a misprint or a "
        "misreading of $t/2$ (erratum SP-E-exponent-t2).",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim.statement(
        id="SP-eq2.1-keeps-peak",
        locator="Eq. (2.1)",
        quantity="scaling $\\omega_0$ by the square root of the step ratio keeps the peak error unchanged",
        compute=eq21_keeps_peak,
        note="Peaks found on a fine time grid (not from the peak factor) for the four aided steps of "
        "Table 2.6 against the 6 g, 18 rad/s unaided loop: equal to $10^{-9}$ relative, because the error is "
        "$R/\\omega_0^2$ times a function of $\\omega_0 t$.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim(
        id="SP-sec2.5-jerk-6g",
        locator="Sec. 2.5",
        quantity="acceleration reached by a 10-g/s jerk lasting 0.6 s",
        published=_g6[0],
        unit="g",
        kind="cross-check",
        compute=lambda: IN.jerk_g_per_s * IN.jerk_duration_s,
        tolerance=_g6[1],
        expected_status="consistent",
        note="The step the paper substitutes for the jerk has the jerk's final acceleration: "
        "$10\\ \\mathrm{g/s} \\times 0.6\\ \\mathrm{s}$, "
        "arithmetic on printed numbers, a cross-check.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim.statement(
        id="SP-sec2.5-step-vs-jerk",
        locator="Sec. 2.5",
        quantity="the 6-g step gives a larger peak error than the 10-g/s, 0.6-s jerk (more stringent)",
        compute=step_more_stringent_than_jerk,
        note="Peaks at 17.67 rad/s with the L1 carrier; the ratio (about 4) does not depend on the "
        "conversion. 'Slightly' has no band in the prose table, and the requirement sets the natural "
        "frequency: there the step needs a natural frequency about 1.6 times the one the jerk needs (the "
        "jerk pulse's peak falls about as the cube of the natural frequency), while its peak error at "
        "one natural frequency is about 4 times the jerk's.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim(
        id="SP-sec2.5-half-chip-ns",
        locator="Sec. 2.5",
        quantity="half a code chip, in nanoseconds (code loss-of-lock threshold)",
        published=50.0,
        unit="ns",
        compute=lambda: 0.5 / GPS_P_CHIP_RATE_HZ * 1e9,
        tolerance=printed("50", why="'1/2 chip (50 ns)'")[1],
        expected_status="consistent",
        note="Half a P(Y) chip (10.23 Mchip/s) is 48.9 ns, which rounds to the printed 50 ns if its trailing "
        "zero is not significant; half a C/A chip would be 489 ns, so the code loop here tracks P(Y), "
        "while the 300-m phase convention of Fig. 2.1 suggests C/A.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
    Claim(
        id="SP-sec2.5-loose-carrier-5.83Hz",
        locator="Sec. 2.5",
        quantity="loosely coupled receiver's third-order carrier-loop bandwidth",
        published=5.83,
        unit="Hz",
        compute=None,
        tolerance=printed("5.83")[1],
        expected_status="not-reproducible",
        note="No design rule for it is given. For the Butterworth loop of Fig. 2.1 the noise bandwidth "
        "is $(5/6)\\,\\omega_0 = 14.7$ Hz at $\\omega_0 = 17.67$ rad/s; 5.83 Hz would need "
        "$\\omega_0 = 7.0$ rad/s. Missing: the loosely "
        "coupled loop's coefficients and the requirement behind 5.83 Hz, which Sec. 2.5 should give "
        "next to the value.",
        discussed_in=PAGE,
        table="tracking-loop",
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
