"""SP Section 3: deep integration versus tight coupling under jamming.

Published inputs (the MEMS IMU, the thresholds, the PGM geometry, the run counts) are typed
here with their locators. What the paper leaves out is an explicit, named assumption:
the tracked code (P(Y), 10.23 Mchip/s), the unjammed C/N0 (41 dB-Hz at -163 dBW), the
spectral separation of the two jammers, the munition's speed and altitude profile (our
reconstruction of Fig. 3.4), the jammer-direction antenna gain, the geometry factor and the
initial tilt. The CEP Monte Carlo of Figs. 3.6-3.8 is a reduced two-channel navigator
(:func:`navcore.gnss.antijam.simulate_impact_errors`), not the paper's 6-DOF simulation.
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np

from navcore.gnss.antijam import (
    NavigatorErrorModel,
    cep_from_horizontal_errors,
    code_tracking_sigma_chips,
    effective_cn0_dbhz,
    free_space_js_db,
    js_for_effective_cn0,
    simulate_impact_errors,
    spectral_separation_q,
)
from navcore.ledger import EXACT, Claim, Erratum, Tolerance, printed
from navcore.units import (
    DEG_PER_H,
    DEG_PER_SQRT_H,
    GPS_L1_WAVELENGTH_M,
    GPS_P_CHIP_M,
    GPS_P_CHIP_RATE_HZ,
    MILLI_G,
    NMI,
    PPM,
    power_ratio_from_db,
)

PAGE = "sp/06-deep-integration"

# --- published inputs (Sec. 3.0 - 3.3) --------------------------------------------------
MEMS = {  # Sec. 3.0, "representative of a particular MEMS IMU"
    "accel_bias": 1.0 * MILLI_G,  # 1-mg bias stability
    "accel_scale_factor": 100.0 * PPM,  # 100-ppm scale-factor stability (not in the reduced model)
    "accel_vrw": 0.01 / 60.0,  # 1 cm/s/sqrt(h) -> m/s/sqrt(s)
    "gyro_bias": 10.0 * DEG_PER_H,  # 10 deg/h bias stability
    "gyro_arw": 0.03 * DEG_PER_SQRT_H,  # 0.03 deg/sqrt(h)
    "tau_s": 5.0 * 60.0,  # first-order Markov, 5 min
    "nonorthogonality": 1e-3,  # 1 mrad, fixed
}
RANGE_BIAS_M = 2.0  # unestimated ephemeris range bias, 2 m rms
WIDEBAND_HZ = 20e6  # wideband Gaussian jammer, 20 MHz
NARROWBAND_HZ = 1e3  # narrowband jammer, 1 kHz
TC_LOSS_JS_DB = 54.0  # "Code loop loss-of-lock was assumed to occur at J/S = 54 dB"
DI_LOCK_JS_DB = 65.0  # "maintain code lock up to 65 dB J/S"
DI_IMPROVEMENT_DB = 15.0  # "an improvement of approximately 15 dB"
CARRIER_LOSS_CN0 = 19.0  # Sec. 2.5: "signal-to-noise ratio dropped below 19 dB"
TARGET_RANGE_NMI = 63.0  # Sec. 3.3
JAMMER_BEFORE_TARGET_NMI = 5.0
RUNS = 25  # "A total of 25 Monte Carlo runs was made at each power level"
INIT_POS_M, INIT_VEL_MPS = 10.0, 0.2  # initial rms navigation errors per axis
POWERS_W = (1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0, 10000.0)  # "from 1 W to 10 kW"
PUBLISHED_CEP = {("DI", 100.0): "11", ("TC", 100.0): "120", ("DI", 10.0): "2.6", ("TC", 10.0): "71"}

# --- stated assumptions (not in the paper) -----------------------------------------------
CN0_DBHZ = 41.0  # P(Y) at -163 dBW with N0 = -204 dBW/Hz
SIGNAL_DBW = -163.0
JAMMER_GAIN_DB = -3.0  # antenna gain towards the (ground) jammer relative to the satellites
SPEED_MPS = 250.0  # munition ground speed
CRUISE_ALT_M = 9000.0  # cruise altitude
DIVE_START_M = 20_000.0  # linear dive to the target over the last 20 km
HDOP_AXIS = 1.5 / math.sqrt(2.0)  # four satellites, HDOP 1.5, per horizontal axis
INIT_TILT_RAD = 1e-3  # levelling with a 1-mg accelerometer: 1 mrad
SEED = 20000  # base seed of the Monte Carlo; each curve point offsets it (recorded)
LARGE_RUNS = 2000  # runs used to estimate the reduced model's own CEP for the claims


def navigator_model() -> NavigatorErrorModel:
    return NavigatorErrorModel(
        accel_bias=MEMS["accel_bias"],
        accel_tau_s=MEMS["tau_s"],
        gyro_bias=MEMS["gyro_bias"],
        gyro_tau_s=MEMS["tau_s"],
        accel_vrw=MEMS["accel_vrw"],
        gyro_arw=MEMS["gyro_arw"],
        nonorthogonality=MEMS["nonorthogonality"],
        init_pos=INIT_POS_M,
        init_vel=INIT_VEL_MPS,
        init_tilt=INIT_TILT_RAD,
        range_bias=RANGE_BIAS_M,
        hdop_axis=HDOP_AXIS,
    )


def q_factor(kind: str) -> float:
    """Spectral-separation factor of the wideband (20 MHz) or narrowband (1 kHz) jammer on P(Y)."""
    bw = {"wideband": WIDEBAND_HZ, "narrowband": NARROWBAND_HZ}[kind]
    return spectral_separation_q(bw, GPS_P_CHIP_RATE_HZ)


def threshold_dbhz(arch: str) -> float:
    """Effective-C/N0 threshold implied by the stated J/S limit (Q = 2, the usual wideband value)."""
    js = {"TC": TC_LOSS_JS_DB, "DI": DI_LOCK_JS_DB}[arch]
    return float(effective_cn0_dbhz(CN0_DBHZ, js, GPS_P_CHIP_RATE_HZ, 2.0))


def pgm_trajectory() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Time (s), along-track distance from launch (m) and altitude (m): our Fig. 3.4 reconstruction."""
    length = TARGET_RANGE_NMI * NMI
    n = int(length // SPEED_MPS)
    t = np.arange(1, n + 1, dtype=float)
    x = np.minimum(SPEED_MPS * t, length)
    to_go = length - x
    alt = np.where(to_go > DIVE_START_M, CRUISE_ALT_M, CRUISE_ALT_M * to_go / DIVE_START_M)
    return t, x, np.maximum(alt, 1.0)


def pgm_js_db(power_w: float) -> np.ndarray:
    """Free-space J/S along the trajectory for a ground jammer 5 nmi before the target (Fig. 3.5)."""
    _, x, alt = pgm_trajectory()
    jx = (TARGET_RANGE_NMI - JAMMER_BEFORE_TARGET_NMI) * NMI
    d = np.hypot(x - jx, alt)
    return np.asarray(free_space_js_db(power_w, d, GPS_L1_WAVELENGTH_M, SIGNAL_DBW, JAMMER_GAIN_DB))


def fix_sigma_m(power_w: float, arch: str, kind: str) -> np.ndarray:
    """Per-axis position-fix noise along the flight (NaN while the code loop is out of lock)."""
    cn0 = np.asarray(effective_cn0_dbhz(CN0_DBHZ, pgm_js_db(power_w), GPS_P_CHIP_RATE_HZ, q_factor(kind)))
    sigma = HDOP_AXIS * GPS_P_CHIP_M * np.asarray(code_tracking_sigma_chips(cn0))
    return np.where(cn0 >= threshold_dbhz(arch), sigma, np.nan)


def _seed(power_w: float, arch: str, kind: str) -> int:
    return (
        SEED + 10 * POWERS_W.index(power_w) + (1 if arch == "DI" else 0) + (5 if kind == "narrowband" else 0)
    )


@cache
def cep_curve(arch: str, kind: str, runs: int = RUNS) -> tuple[np.ndarray, tuple[int, ...]]:
    """CEP at impact (m) for each jammer power of :data:`POWERS_W`, and the seeds used."""
    ceps, seeds = [], []
    for p in POWERS_W:
        seed = _seed(p, arch, kind) + (0 if runs == RUNS else 1_000_000)
        res = simulate_impact_errors(navigator_model(), fix_sigma_m(p, arch, kind), runs=runs, seed=seed)
        ceps.append(cep_from_horizontal_errors(res.impact_errors_m))
        seeds.append(seed)
    return np.array(ceps), tuple(seeds)


@cache
def model_cep(arch: str, power_w: float, kind: str = "wideband") -> float:
    """The reduced model's CEP with LARGE_RUNS runs (its own sampling error about 1.6 %)."""
    seed = _seed(power_w, arch, kind) + 1_000_000
    res = simulate_impact_errors(
        navigator_model(), fix_sigma_m(power_w, arch, kind), runs=LARGE_RUNS, seed=seed
    )
    return cep_from_horizontal_errors(res.impact_errors_m)


def cep_relative_sd(runs: int) -> float:
    """Relative standard error of a CEP taken as 1.1774 x rms of ``runs`` 2-D samples: 1/sqrt(4 runs)."""
    return 1.0 / math.sqrt(4.0 * runs)


def aj_improvement_db(kind: str, cep_m: np.ndarray, runs: int = RUNS) -> np.ndarray:
    """Jammer-power ratio (dB) DI/TC at equal CEP, by interpolating log CEP against power in dB."""
    pdb = 10.0 * np.log10(np.array(POWERS_W))
    out = []
    for c in np.atleast_1d(cep_m):
        p = []
        for arch in ("TC", "DI"):
            curve = np.maximum.accumulate(cep_curve(arch, kind, runs)[0])
            p.append(np.interp(math.log(c), np.log(curve + 1e-9 * np.arange(curve.size)), pdb))
        out.append(p[1] - p[0])
    return np.array(out)


def di_better_at_10_and_100w() -> bool:
    return all(
        model_cep("DI", p, k) < model_cep("TC", p, k)
        for p in (10.0, 100.0)
        for k in ("wideband", "narrowband")
    )


def comparable_at_low_power() -> bool:
    return bool(abs(model_cep("TC", 1.0) / model_cep("DI", 1.0) - 1.0) < 0.25)


ERRATA = [
    Erratum(
        id="SP-E-di-improvement-15dB",
        paper="SP",
        locator="Sec. 3.1",
        printed="DI holds code lock up to 65 dB J/S, 'an improvement of approximately 15 dB' over TC, "
        "whose code loop loses lock at J/S = 54 dB (Sec. 3.0)",
        finding="The stated thresholds differ by 11 dB. Fifteen dB is the difference of the 5-dB grid "
        "levels 65 and 50 dB; with the grid, the DI limit lies in [65, 70) dB and the improvement in "
        "[11, 16) dB, so 15 dB holds only if the DI limit is near 69 dB.",
        evidence="Difference of the printed thresholds, and independently the difference of the "
        "effective-C/N0 thresholds they imply (19.08 and 8.11 dB-Hz for P(Y), Q = 2, 41 dB-Hz).",
        claims=("SP-sec3.1-improvement-15dB",),
        discussed_in=PAGE,
    ),
]

_js54 = printed("54")
_aj100 = Tolerance(reason="exact: 10^(20/10)", abs=1e-9)


def _cep_claim(arch: str, power: float) -> Claim:
    text = PUBLISHED_CEP[(arch, power)]
    value = float(text)
    cid = f"SP-sec3.3-cep-{arch.lower()}-{int(power)}W"
    name = "deeply integrated" if arch == "DI" else "tightly coupled"
    quantity = f"CEP at impact, {name}, {power:g}-W wideband jammer"
    if arch == "DI":
        rel = 2.0 * cep_relative_sd(RUNS)
        return Claim(
            id=cid,
            paper="SP",
            locator="Sec. 3.3, Fig. 3.6",
            quantity=quantity,
            published=value,
            unit="m",
            compute=lambda: model_cep(arch, power),
            tolerance=Tolerance(
                reason=f"two standard errors ({100 * rel:.0f} %) of a CEP estimated from the paper's 25 runs "
                "(50 horizontal-axis samples); the book's value uses 2000 runs",
                rel=rel,
            ),
            expected_status="consistent",
            note="Reduced two-channel navigator with the paper's MEMS IMU, initial errors and 2-m range "
            "bias; trajectory, antenna gain and code assumptions are the book's (listed on the page). The "
            "DI error here is set by the unestimated range bias and the short outage near the jammer.",
            discussed_in=PAGE,
        )
    return Claim(
        id=cid,
        paper="SP",
        locator="Sec. 3.3, Fig. 3.6",
        quantity=quantity,
        published=value,
        unit="m",
        compute=None,
        tolerance=Tolerance(reason="25-run sampling error, 10 % per standard error", rel=0.2),
        expected_status="not-reproducible",
        note="The TC error after loss of lock is free-inertial error growth over an outage whose length "
        "depends on the unpublished trajectory (Fig. 3.4), speed, antenna pattern, manoeuvres and "
        "reacquisition logic. The book's reduced model (page sp/06) does not match this value: its "
        "free-inertial error grows faster with outage length than the paper's 71 m -> 120 m.",
        discussed_in=PAGE,
    )


CLAIMS = [
    Claim(
        id="SP-sec3.0-tc-loss-54dB",
        paper="SP",
        locator="Sec. 3.0",
        quantity="J/S at which the tightly coupled code loop loses lock",
        published=_js54[0],
        unit="dB",
        compute=lambda: js_for_effective_cn0(CN0_DBHZ, CARRIER_LOSS_CN0, GPS_P_CHIP_RATE_HZ, 2.0),
        tolerance=_js54[1],
        expected_status="consistent",
        note="Assumptions: P(Y) code (10.23 Mchip/s), unjammed C/N0 41 dB-Hz, wideband Q = 2, and the "
        "Sec. 2.5 tracking threshold of 19 dB(-Hz): J/S = 10 log10(Q Rc (1/19 dB-Hz - 1/41 dB-Hz)).",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-sec3.1-improvement-15dB",
        paper="SP",
        locator="Sec. 3.1",
        quantity="J/S improvement of the deeply integrated code loop over the tightly coupled one",
        published=DI_IMPROVEMENT_DB,
        unit="dB",
        compute=lambda: DI_LOCK_JS_DB - TC_LOSS_JS_DB,
        tolerance=printed("15", why="'approximately 15 dB'")[1],
        expected_status="discrepant",
        erratum="SP-E-di-improvement-15dB",
        oracle=lambda: threshold_dbhz("TC") - threshold_dbhz("DI"),
        oracle_tolerance=Tolerance(
            reason="in the jammer-dominated regime a J/S difference maps 1:1 onto the effective-C/N0 "
            "threshold difference; thermal noise shifts it by 0.03 dB",
            abs=0.1,
        ),
        note="The stated thresholds 54 and 65 dB differ by 11 dB; see the erratum for the 5-dB grid.",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-sec3.3-aj-rule-100x",
        paper="SP",
        locator="Sec. 3.3 (second), 'Final comment'",
        quantity="jammer power factor needed to offset a 20-dB A/J improvement",
        published=100.0,
        unit="x",
        compute=lambda: power_ratio_from_db(20.0),
        tolerance=_aj100,
        expected_status="reproduced",
        note="10^(20/10) = 100; in free space the jammer could instead come 10 times closer.",
    ),
    Claim(
        id="SP-sec3.3-aj-rule-distance",
        paper="SP",
        locator="Sec. 3.3 (second), 'Final comment'",
        quantity="20 dB more J/S in free space equals a 10 times shorter jammer distance",
        published=True,
        unit="statement",
        compute=lambda: bool(
            abs(
                float(free_space_js_db(1.0, 1000.0, GPS_L1_WAVELENGTH_M, SIGNAL_DBW))
                - float(free_space_js_db(1.0, 10000.0, GPS_L1_WAVELENGTH_M, SIGNAL_DBW))
                - 20.0
            )
            < 1e-9
        ),
        tolerance=EXACT,
        expected_status="reproduced",
        note="Free-space loss grows as 20 log10(d).",
    ),
    *(_cep_claim(a, p) for a, p in (("DI", 100.0), ("TC", 100.0), ("DI", 10.0), ("TC", 10.0))),
    Claim(
        id="SP-sec3.3-di-better",
        paper="SP",
        locator="Sec. 3.3, Figs. 3.6-3.7",
        quantity="deep integration has a smaller CEP than tight coupling at 10 and 100 W, both jammer types",
        published=True,
        unit="statement",
        compute=di_better_at_10_and_100w,
        tolerance=EXACT,
        expected_status="consistent",
        note="Reduced navigator model with the book's trajectory and link assumptions (2000 runs per point).",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-sec3.3-low-power-comparable",
        paper="SP",
        locator="Sec. 3.3",
        quantity="as jammer power goes to zero both systems give comparable performance",
        published=True,
        unit="statement",
        compute=comparable_at_low_power,
        tolerance=EXACT,
        expected_status="consistent",
        note="At 1 W wideband the two CEPs of the reduced model agree within 25 %: both keep lock and are "
        "limited by the unestimated range bias.",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig3.8-aj-15dB",
        paper="SP",
        locator="Sec. 3.3, Fig. 3.8",
        quantity="A/J improvement of at least 15 dB for wideband CEPs from 6 to 120 m",
        published=15.0,
        unit="dB",
        relation=">=",
        compute=None,
        tolerance=Tolerance(reason="read from the text", abs=0.0),
        expected_status="not-reproducible",
        note="Needs the paper's CEP curves (Figs. 3.6-3.7), whose 6-DOF simulation inputs are not "
        "published. In the book's reduced model the improvement follows the stated 54/65 dB thresholds "
        "(11 dB apart, erratum SP-E-di-improvement-15dB) and stays below 15 dB; see the page.",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig3.3-aj-above-10dB",
        paper="SP",
        locator="Sec. 3.1, Fig. 3.3",
        quantity="A/J improvement of deep integration at every rss error (second scenario)",
        published=10.0,
        unit="dB",
        relation=">",
        compute=None,
        tolerance=Tolerance(reason="read from the text", abs=0.0),
        expected_status="not-reproducible",
        note="Figs. 3.1-3.3 come from a nonlinear 6-DOF Monte Carlo (27 and 35 runs) of two scenarios whose "
        "trajectories, receiver and filter tuning are not published; only the stated lock limits (54 and "
        "65 dB) can be checked, see SP-sec3.1-improvement-15dB.",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig3.3-aj-15dB-above-35m",
        paper="SP",
        locator="Sec. 3.1, Fig. 3.3",
        quantity="A/J improvement of deep integration for rss errors above 35 m",
        published=15.0,
        unit="dB",
        relation=">",
        compute=None,
        tolerance=Tolerance(reason="read from the text", abs=0.0),
        expected_status="not-reproducible",
        note="Needs the Fig. 3.2 rss curves (6-DOF Monte Carlo, 35 runs, 10 and 1 deg/h IMUs), not "
        "published; the reduced PGM model of this page is not the second scenario.",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-fig3.1-di-lower-initial-rss",
        paper="SP",
        locator="Sec. 3.1, Fig. 3.1",
        quantity="deep integration has the lower rss error during the 60-s, 30-dB initialisation phase",
        published=True,
        unit="statement",
        compute=None,
        tolerance=EXACT,
        expected_status="not-reproducible",
        note="The difference comes from how the deeply integrated filter weights the correlator outputs, "
        "which the paper does not describe; in the reduced model both navigators use the same fixes "
        "while in lock.",
        discussed_in=PAGE,
    ),
]
