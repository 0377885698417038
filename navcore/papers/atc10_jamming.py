"""ATC-10 Sections 1-2 and Appendices A-D: vulnerability of satellite multilateration to jamming.

Published values are typed once here, with their locators; every reproduced value is
computed by :mod:`navcore.detection.jamming`, :mod:`navcore.detection.neyman_pearson` and
:mod:`navcore.detection.antenna` from the paper's inputs (Sec. 2.7: N = 0.1 N_T, B = 10 MHz,
alpha = 1 s, beta = 24 ms, v = 600 mph, 10 mJ pulses; design point t = 0).
"""

from __future__ import annotations

import itertools
import math
from functools import cache

import mpmath
import numpy as np
from scipy import optimize, special, stats

from navcore import units
from navcore.detection import antenna
from navcore.detection import jamming as jm
from navcore.detection.neyman_pearson import (
    detection_index_from_jammer_ratio,
    erf_parameter_from_detection_probability,
    false_alarm_probability,
    log_false_alarm_probability,
)
from navcore.ledger import EXACT, Claim, Erratum, Tolerance, printed

PAGE = "atc10/10-jamming-model"
PAGE_K1 = "atc10/11-single-pulse"
PAGE_K = "atc10/12-tracking-lists"
PAGE_T11 = "atc10/13-tables"

GEOMETRY = jm.SurveillanceGeometry()
#: Level at which the ambiguous-detection bound makes the system inoperative (Sec. 2.7).
ADL_LEVEL = 0.01
#: Fraction of the N_FL supremum (1 - N/N_T) taken as "N_F = 0.9 N_T" (never attained).
FL_FRACTION_OF_CEILING = 0.99
#: Antenna model assumed for Table 1.1 (L band; not stated in the paper).
DISH_FREQUENCY_HZ = 1.6e9
DISH_EFFICIENCY = 0.60
#: Sec. 2.7, as printed: "10 mJoules (e.g. P0 = 30 dbw, tau = 10 usec)".
PULSE_POWER_DBW = 30.0
PULSE_DURATION_S = 10e-6
#: Sec. 1.3, as printed: 50 ns rms time-of-arrival error, one position update per second.
TOA_RMS_ERROR_S = 50e-9
UPDATE_INTERVAL_S = 1.0
#: The transmission lengths of Table 1.1 and Sec. 1.1.
TABLE_1_1_KS = (1, 10, 100, 1000)

#: Table 2.1 as printed: (K, P_DL, ERP dBW, relation).
TABLE_2_1 = (
    (10, 0.88, "46", "="),
    (10, 0.999, "43", "="),
    (100, 0.88, "56", "="),
    (100, 0.999, "51", "="),
    (1000, 0.98, "130", ">"),
    (1000, 0.999, "77", "="),
)
#: Table 1.1 as printed: (K, ERP dBW, rf power dBW, antenna diameter ft, beamwidth deg).
TABLE_1_1 = (
    (1, 33, 15, 2, 15),
    (10, 43, 20, 4, 12),
    (100, 53, 23, 8, 5),
    (1000, 77, 40, 18, 2),
)


# --------------------------------------------------------------------------------------
# shared computations
# --------------------------------------------------------------------------------------


@cache
def design_p_d(p_dl: float, k: int, t: float = 0.0) -> float:
    """Per-filter p_d that gives P_DL = p_dl for K lists at fraction t (Eq. 2.4.2)."""
    return jm.filter_detection_probability_for_bound(p_dl, k, t)


@cache
def required_erp_dbw(quantity: str, p_dl: float, k: int, t: float = 0.0) -> float:
    """Jammer ERP (dBW) at which N_ADL = 0.01 N_T ("ambiguous") or N_FL = 99 % of its
    supremum 0.9 N_T ("false"), at the design point (P_DL, K, t)."""
    if quantity == "ambiguous":
        level = ADL_LEVEL
    else:
        level = FL_FRACTION_OF_CEILING * (1.0 - GEOMETRY.airborne_fraction)
    p_d = design_p_d(p_dl, k, t)
    x_db = jm.jammer_ratio_threshold_db(quantity, level, p_d, k, t, GEOMETRY)
    return float(jm.jammer_erp_dbw(x_db, GEOMETRY.pulse_energy_j, GEOMETRY.bandwidth_hz))


@cache
def direct_adl_erp_dbw(p_dl: float, k: int) -> float:
    """Independent oracle for the t = 0 N_ADL threshold: plain floating-point probabilities
    (no logarithms), a per-list probability from the binomial, and a dense dB grid refined
    by bisection. Valid where nothing underflows (K <= 100 and the K = 1000 crossings)."""
    q = 1.0 - (1.0 - p_dl) ** (1.0 / k)
    p_d = q**0.25
    n_a, n_b, n_v = 2e7, 9.6e5, 8.0 / 3.0 * 1e7 * (600.0 / 3600.0) / 186282.397

    def n_adl(x_db: float) -> float:
        pf = stats.norm.sf(1.0 / math.sqrt(10 ** (x_db / 10)) - stats.norm.ppf(p_d))
        f = (1 - (1 - pf) ** n_a) * (1 - (1 - pf) ** n_b) ** 3
        g = (1 - (1 - pf) ** n_a) * (1 - (1 - pf) ** n_v) ** 3
        return 0.5 * 0.1 * stats.binom.sf(0, k, q) * g ** (k - 1) * f - ADL_LEVEL

    grid = np.arange(-40.0, 130.0, 0.5)
    vals = np.array([n_adl(x) for x in grid])
    idx = int(np.argmax(vals > 0))
    if vals[idx] <= 0:
        return math.inf
    lo, hi = grid[idx - 1], grid[idx]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if n_adl(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi) + 10 * math.log10(0.01 * 1e7)


@cache
def erf_argument_coefficient(x_db: float = 0.0, p_d: float = 0.5) -> float:
    """The coefficient c in p_f = 1/2 - 1/2 erf(c sqrt(P0 B tau / J) - phi), recovered from
    navcore's Neyman-Pearson p_f (App. D): c = (erfinv(1 - 2 p_f) + phi) / sqrt(P0 B tau / J)."""
    x = 10 ** (x_db / 10)
    pf = float(false_alarm_probability(p_d, detection_index_from_jammer_ratio(x)))
    phi = float(erf_parameter_from_detection_probability(p_d))
    return (float(special.erfinv(1.0 - 2.0 * pf)) + phi) / math.sqrt(1.0 / x)


@cache
def monte_carlo_erf_coefficient(x_db: float = 0.0, p_d: float = 0.5, n: int = 1_000_000) -> float:
    """Oracle for :func:`erf_argument_coefficient`: simulate the matched-filter output with
    noise variance J/B and signal amplitude sqrt(E), set the threshold from simulated
    signal-present samples so that a fraction p_d exceeds it, and count noise-only crossings."""
    rng = np.random.default_rng(20260722)
    energy, bandwidth = 0.01, 1e7
    jam = 10 ** (x_db / 10) * energy * bandwidth
    sigma = math.sqrt(jam / bandwidth)
    signal = math.sqrt(energy) + sigma * rng.standard_normal(n)
    threshold = np.quantile(signal, 1.0 - p_d)
    pf = float(np.mean(sigma * rng.standard_normal(n) > threshold))
    phi = float(special.erfinv(2 * p_d - 1))
    return (float(special.erfinv(1.0 - 2.0 * pf)) + phi) / math.sqrt(1.0 / 10 ** (x_db / 10))


def _dish_gain_db(diameter_ft: float) -> float:
    return float(10 * np.log10(antenna.dish_gain(diameter_ft * units.FT, DISH_FREQUENCY_HZ, DISH_EFFICIENCY)))


def table11_rf_dbw(row: int) -> float:
    """rf power = printed ERP - gain of the printed dish diameter (1.6 GHz, eta = 0.6)."""
    _, erp, _, dia, _ = TABLE_1_1[row]
    return float(antenna.rf_power_dbw(erp, _dish_gain_db(dia)))


def table11_diameter_ft(row: int) -> float:
    """Dish diameter for the gain printed ERP - printed rf power (1.6 GHz, eta = 0.6)."""
    _, erp, rf, _, _ = TABLE_1_1[row]
    gain = units.power_ratio_from_db(erp - rf)
    return float(antenna.dish_diameter(gain, DISH_FREQUENCY_HZ, DISH_EFFICIENCY)) / units.FT


def table11_beamwidth_deg(row: int) -> float:
    """70 lambda / D for the dish of :func:`table11_diameter_ft`."""
    return float(antenna.dish_beamwidth_deg(table11_diameter_ft(row) * units.FT, DISH_FREQUENCY_HZ))


def table11_beamwidth_from_gain_deg(row: int) -> float:
    """Oracle: sqrt(27000 / G) with G = printed ERP - printed rf power."""
    _, erp, rf, _, _ = TABLE_1_1[row]
    return float(antenna.beamwidth_from_gain_deg(units.power_ratio_from_db(erp - rf)))


def _exponent_matches_numeric() -> bool:
    worst = 0.0
    for t, q in ((0.05, 0.3), (0.1, 0.2), (0.01, 0.0069), (0.4, 0.3), (0.2, 0.9)):

        def neg(nu: float, t: float = t, q: float = q) -> float:
            return -(nu * (1 - t) - (nu + math.log((1 - q) + q * math.exp(-nu))))

        res = optimize.minimize_scalar(neg, bounds=(0.0, 60.0), method="bounded", options={"xatol": 1e-12})
        worst = max(worst, abs(float(jm.list_rule_exponent(t, q)) - max(-res.fun, 0.0)))
    return worst < 1e-10


def _k1_bound_is_pd4() -> bool:
    p = np.linspace(0.05, 0.999, 50)
    return bool(np.allclose(jm.detection_lower_bound(p, 1, 0.0), p**4, rtol=1e-12, atol=0))


def _bound_tends_to_one() -> bool:
    """App. A: with t < p_d^4 the bound tends to 1 as K grows."""
    values = [float(jm.detection_lower_bound(0.7, k, 0.2)) for k in (10, 100, 1000, 10000)]
    return bool(np.all(np.diff(values) > 0) and values[-1] > 1 - 1e-12)


def _plateau_below_minus_12db() -> bool:
    """Sec. 2.7: both K = 1 bounds sit at their ceilings at -12 dB for every P_DL."""
    ok = True
    for p_dl in (0.88, 0.9, 0.99, 0.999):
        p_d = design_p_d(p_dl, 1)
        x = 10 ** (-12 / 10)
        for fn, ceil in (
            (jm.log_false_location_bound, jm.log_false_location_ceiling),
            (jm.log_ambiguous_detection_bound, jm.log_ambiguous_detection_ceiling),
        ):
            ok &= float(fn(x, p_d, 1)) - ceil(p_d, 1) > math.log(0.999)
    return bool(ok)


def _t_zero_needs_most_power() -> bool:
    ok = True
    for k, p_dl, _, _ in TABLE_2_1:
        if (k, p_dl) == (1000, 0.98):
            continue
        for quantity in ("ambiguous", "false"):
            erps = [required_erp_dbw(quantity, p_dl, k, t) for t in (0.0, 0.05, 0.1, 0.2, 0.3)]
            ok &= bool(np.all(np.diff(erps) < 0))
    return bool(ok)


def t_spread_db(quantity: str, p_dl: float, k: int) -> float:
    """ERP at t = 0 minus ERP at t = 0.3."""
    return required_erp_dbw(quantity, p_dl, k, 0.0) - required_erp_dbw(quantity, p_dl, k, 0.3)


def _fl_less_sensitive_to_t() -> bool:
    return all(
        t_spread_db("ambiguous", p, k) > t_spread_db("false", p, k)
        for k, p in ((10, 0.88), (100, 0.88), (1000, 0.999))
    )


def _fl_degrades_first() -> bool:
    return all(
        required_erp_dbw("false", p, k) < required_erp_dbw("ambiguous", p, k)
        for k, p, _, _ in TABLE_2_1
        if (k, p) != (1000, 0.98)
    )


@cache
def k1000_critical_p_dl() -> float:
    """Smallest P_DL at which the K = 1000 N_ADL ceiling reaches 0.01 N_T (t = 0)."""

    def f(p_dl: float) -> float:
        return jm.log_ambiguous_detection_ceiling(design_p_d(p_dl, 1000), 1000, 0.0, GEOMETRY) - math.log(
            ADL_LEVEL
        )

    return float(optimize.brentq(f, 0.98, 0.9999, xtol=1e-12))


def _k1000_depends_critically() -> bool:
    return (
        math.isinf(required_erp_dbw("ambiguous", 0.98, 1000))
        and math.isfinite(required_erp_dbw("ambiguous", 0.999, 1000))
        and 0.98 < k1000_critical_p_dl() < 0.999
    )


@cache
def threshold_log_pf(p_dl: float, k: int) -> float:
    """ln p_f at the t = 0 N_ADL = 0.01 N_T threshold of the design point (P_DL, K)."""
    p_d = design_p_d(p_dl, k)
    x_db = jm.jammer_ratio_threshold_db("ambiguous", ADL_LEVEL, p_d, k, 0.0, GEOMETRY)
    return float(log_false_alarm_probability(p_d, detection_index_from_jammer_ratio(10 ** (x_db / 10))))


#: The sample counts of (B.6) and (C.14) halved (B samples per second instead of 2B), with the
#: energy-bandwidth product, and so the ERP scale, unchanged: a sensitivity to sample correlation.
HALF_SAMPLES_GEOMETRY = jm.SurveillanceGeometry(bandwidth_hz=GEOMETRY.bandwidth_hz / 2)


@cache
def adl_erp_dbw_half_samples(p_dl: float, k: int) -> float:
    """N_ADL = 0.01 N_T ERP (t = 0) when every window holds half as many independent samples."""
    x_db = jm.jammer_ratio_threshold_db(
        "ambiguous", ADL_LEVEL, design_p_d(p_dl, k), k, 0.0, HALF_SAMPLES_GEOMETRY
    )
    return float(jm.jammer_erp_dbw(x_db, GEOMETRY.pulse_energy_j, GEOMETRY.bandwidth_hz))


@cache
def adl_erp_dbw_without_pdl_factor(p_dl: float, k: int) -> float:
    """ERP at which 1/2 N G^(K-1) F (the N_ADL bound without its P_DL factor) reaches 0.01 N_T.

    Solving N_ADL = 0.01 P_DL N_T with the printed bound is the same equation.
    """
    p_d = design_p_d(p_dl, k)
    x_db = jm.jammer_ratio_threshold_db("ambiguous", ADL_LEVEL * p_dl, p_d, k, 0.0, GEOMETRY)
    return float(jm.jammer_erp_dbw(x_db, GEOMETRY.pulse_energy_j, GEOMETRY.bandwidth_hz))


def max_pdl_factor_shift_db() -> float:
    """Largest drop of the t = 0 N_ADL threshold when the P_DL factor of (2.5.12) is dropped, over
    K = 1 (P_DL 0.88-0.999) and the finite Table 2.1 entries."""
    points = [(p, 1) for p in (0.88, 0.9, 0.99, 0.999)] + [(p, k) for k, p, _, rel in TABLE_2_1 if rel == "="]
    return max(required_erp_dbw("ambiguous", p, k) - adl_erp_dbw_without_pdl_factor(p, k) for p, k in points)


def erp_by_transmission_length(p_dl: float) -> tuple[float, ...]:
    """N_ADL = 0.01 N_T jammer ERP (dBW, t = 0) for K = 1, 10, 100, 1000 (``inf``: no finite power)."""
    return tuple(required_erp_dbw("ambiguous", p_dl, k) for k in TABLE_1_1_KS)


def _erp_rises_with_k() -> bool:
    """Sec. 1.1: the required ERP grows with K, at the caption's P_D = 0.88 and at Table 2.1's 0.999.

    The K < 100 values must be finite (a jammer exists); ``inf`` counts as larger than any number.
    """
    ok = True
    for p_dl in (0.88, 0.999):
        erps = erp_by_transmission_length(p_dl)
        ok &= all(math.isfinite(e) for e in erps[:2]) and all(a < b for a, b in itertools.pairwise(erps))
    return bool(ok)


def _k1000_beyond_practical() -> bool:
    """Sec. 1.1 "prohibit", for the caption's P_D >= 0.88 design: at K = 1000 the N_ADL ceiling
    (J -> inf) stays below 0.01 N_T, so the threshold search returns no finite ERP, which is
    beyond Table 2.1's ">130 dBW" (its K = 1000 entry for P_DL = 0.98)."""
    ceiling = jm.log_ambiguous_detection_ceiling(design_p_d(0.88, 1000), 1000, 0.0, GEOMETRY)
    table21_bound = next(float(text) for k, p, text, rel in TABLE_2_1 if k == 1000 and rel == ">")
    return bool(ceiling < math.log(ADL_LEVEL) and required_erp_dbw("ambiguous", 0.88, 1000) > table21_bound)


def _table11_matches_caption_pdl(direct: bool) -> bool:
    """Does every Table 1.1 ERP match the caption's P_D = 0.88 model within 1 dB?"""
    ok = True
    for k, erp, *_ in TABLE_1_1:
        model = direct_adl_erp_dbw(0.88, k) if direct else required_erp_dbw("ambiguous", 0.88, k)
        ok &= math.isfinite(model) and abs(model - erp) <= 1.0
    return bool(ok)


def printed_c1_equals_b6(use_mpmath: bool) -> bool:
    """Is (C.1) as printed, [1-p_f]^(2B alpha) [1-(1-p_f)^(4B beta)]^3, equal to F of (B.6)
    at the K = 1 design threshold (P_DL = 0.88)? (It should be, since (2.5.12) uses F.)"""
    p_d = design_p_d(0.88, 1)
    x = 10 ** (jm.jammer_ratio_threshold_db("ambiguous", ADL_LEVEL, p_d, 1) / 10)
    if use_mpmath:
        with mpmath.workdps(40):
            d = 1 / mpmath.sqrt(mpmath.mpf(x))
            pf = (
                mpmath.erfc((d - mpmath.sqrt(2) * mpmath.erfinv(2 * mpmath.mpf(p_d) - 1)) / mpmath.sqrt(2))
                / 2
            )
            window = (1 - (1 - pf) ** 9.6e5) ** 3
            printed_c1 = (1 - pf) ** 2e7 * window
            b6 = (1 - (1 - pf) ** 2e7) * window
            return bool(abs(printed_c1 / b6 - 1) < 1e-3)
    log_pf = math.log(float(false_alarm_probability(p_d, detection_index_from_jammer_ratio(x))))
    log_printed = GEOMETRY.samples_per_period * math.log1p(-math.exp(log_pf)) + 3 * float(
        jm.log_one_minus_power(log_pf, GEOMETRY.samples_per_delay_window)
    )
    return bool(abs(log_printed - float(jm.log_false_list_factor(log_pf, GEOMETRY))) < 1e-3)


def printed_a15_value(p_dl: float = 0.999, k: int = 10) -> float:
    """Right side of (A.15) read as printed, "1 exp -K(...)" = exp(-K E), at the t = 0 design point."""
    q = design_p_d(p_dl, k) ** 4
    return float(math.exp(-k * float(jm.list_rule_exponent(0.0, q))))


# --------------------------------------------------------------------------------------
# errata
# --------------------------------------------------------------------------------------

E_ERF = "ATC10-E-jam-erf-argument"
E_RULE = "ATC10-E-jam-decision-rule"
E_TAB11 = "ATC10-E-jam-table1.1-pdl"
E_BEAM = "ATC10-E-jam-beamwidth"
E_C1 = "ATC10-E-jam-appC-typos"
E_A15 = "ATC10-E-jam-A15-sign"
E_A7 = "ATC10-E-jam-A7-ratio"
E_KT = "ATC10-E-jam-floor-Kt"
E_SUP = "ATC10-E-jam-NF-supremum"
E_MINOR = "ATC10-E-jam-cosmetic"
E_P0 = "ATC10-E-jam-P0-average-peak"
E_INDEP = "ATC10-E-jam-sample-independence"
E_C2 = "ATC10-E-jam-C2-track-window"
E_B10 = "ATC10-E-jam-B10-reference"
E_A_END = "ATC10-E-jam-appA-strict-sign"
E_258 = "ATC10-E-jam-2.5.8-independence"
E_A16 = "ATC10-E-jam-A16-small-pd"

ERRATA = [
    Erratum(
        id=E_ERF,
        paper="ATC10",
        locator="Eqs. (2.8.1), (2.8.3)",
        printed="p_f = 1/2 - 1/2 erf(1/2 sqrt(P0 B tau / J) - phi)",
        finding="The erf argument is sqrt(P0 B tau / (2 J)) - phi, as in (2.7.1), (2.8.4) and (D.17); "
        "the printed 1/2 should be 1/sqrt(2).",
        evidence="Appendix D re-derived in the book (sympy) and checked by a seeded Monte Carlo of the "
        "matched-filter output; Table 2.1 is reproduced only with the corrected argument (the printed one "
        "moves every threshold 3.01 dB lower).",
        claims=("ATC10-eq2.8.1-erf-coefficient",),
        discussed_in=PAGE_K,
    ),
    Erratum(
        id=E_RULE,
        paper="ATC10",
        locator="Eqs. (A.9)-(A.10) against (A.11), (B.1)",
        printed="Decide H1 if K_0 <= tK (K_0 the number of empty lists)",
        finding="The bounds (A.17), (B.11), the figures and the tables use the rule of (A.11)/(B.1) and of "
        "Sec. 2.4: decide H1 if more than tK lists are non-empty. (A.11) does not follow from (A.10); the "
        "two are the same family with t replaced by 1 - t.",
        evidence="Exact binomial probabilities: at the K = 10, P_DL = 0.999 design point the literal (A.9) "
        "rule with t = 0 detects with probability q^K = 9.6e-4, far below the bound 0.999 that holds "
        "(with equality) for the (A.11) rule.",
        claims=("ATC10-eqA.9-rule-at-design",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_TAB11,
        paper="ATC10",
        locator="Table 1.1 and Sec. 1.1",
        printed="ERP 33/43/53/77 dBW for K = 1/10/100/1000 'with a processor designed to achieve a detection "
        "probability of at least 0.88'",
        finding="Only the K = 1 entry uses P_DL = 0.88. The K = 10 and K = 1000 entries are Table 2.1's "
        "P_DL = 0.999 values (43, 77); with 0.88 they would be 46 dBW and no finite power. The K = 100 "
        "entry 53 matches neither Table 2.1 row (51, 56); P_DL = 0.98 happens to give 53.0.",
        evidence="The t = 0 thresholds of the log-domain model, checked by an independent plain-probability "
        "grid search.",
        claims=("ATC10-tab1.1-K100-erp", "ATC10-tab1.1-caption-pdl"),
        discussed_in=PAGE_T11,
    ),
    Erratum(
        id=E_BEAM,
        paper="ATC10",
        locator="Table 1.1, K = 1 beamwidth",
        printed="15 degrees",
        finding="About 20-21 degrees, as Sec. 2.7 itself says ('an antenna with a 20 degree beamwidth').",
        evidence="The 18 dB gain implied by the ERP and rf columns gives 21.4 degrees by 70 lambda/D "
        "(1.6 GHz, eta = 0.6) and 20.7 degrees by sqrt(27000/G); the other three rows agree with the same "
        "model within half a degree.",
        claims=("ATC10-tab1.1-K1-beamwidth",),
        discussed_in=PAGE_T11,
    ),
    Erratum(
        id=E_C1,
        paper="ATC10",
        locator="Eqs. (C.1), (C.11) and cross-references of App. C",
        printed="(C.1): [1 - p_f]^(2B alpha) [1 - (1 - p_f)^(4B beta)]^3; (C.11) conditions on gamma_D(i, "
        "K) = 1",
        finding="(C.1) should read [1 - (1 - p_f)^(2B alpha)][1 - (1 - p_f)^(4B beta)]^3 = F(p_f) of (B.6); "
        "(C.11) should condition on gamma_D(i, K-1) = 1; 'than (C.4)' means (C.5), 'in (C.8)' means (C.10) "
        "and 'applied to (C.14)' means (C.16).",
        evidence="At the K = 1 design threshold the printed (C.1) is smaller than F by a factor of about "
        "e^-20 (mpmath), whereas (2.5.12) and (C.17) use F; the recursion (C.15)-(C.16) only closes with "
        "gamma_D(i, K-1).",
        claims=("ATC10-eqC.1-printed",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_A15,
        paper="ATC10",
        locator="Eq. (A.15)",
        printed="P_D >= 1 exp -K(...)",
        finding="A minus sign is lost: P_D >= 1 - exp(-K(...)), as in (A.17) and (2.4.2).",
        evidence="Read literally the right side at the K = 10, P_DL = 0.999 design point is 0.001, which is "
        "the probability that all ten lists are empty (exact binomial), not a lower bound on detection.",
        claims=("ATC10-eqA.15-printed",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_A7,
        paper="ATC10",
        locator="Eqs. (A.7)-(A.8); text after (A.13), (A.18)",
        printed="K ln(lambda_1 P(rho=1|H0)/P(rho=1|H1)); the label (A.8) is empty; 'J' for nu",
        finding="The ratio is inverted: K ln(lambda_1 P(rho=1|H1)/P(rho=1|H0)). Harmless, since lambda_1 is "
        "free; 'J' in the text is the Chernoff parameter nu.",
        evidence="Taking logarithms of (A.6), Lambda_1 = a^K0 b^(K-K0) <= lambda_1^K, gives "
        "K_0 ln(a/b) <= K ln(lambda_1/b).",
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_KT,
        paper="ATC10",
        locator="Eqs. (2.5.4), (2.8.3), (B.9)-(B.11); (C.14)",
        printed="exponent Kt + 1; sample count (8B/3) v alpha / c",
        finding="When Kt is not an integer the count of lists is floor(Kt) + 1; the real exponent gives a "
        "valid but looser bound. Likewise (8B/3) v alpha/c = 23.86 is not an integer number of samples; "
        "the book follows the paper and uses both as real numbers.",
        evidence="Rounding n_v down to 23 moves the K = 1000, P_DL = 0.999 threshold from 75.7 to 81.7 dBW; "
        "the K <= 100 rows move by less than 0.4 dB.",
        discussed_in=PAGE_K,
    ),
    Erratum(
        id=E_SUP,
        paper="ATC10",
        locator="Sec. 2.7, level N_F = 0.9 N_T",
        printed="N_F of 0.9 N_T taken as the failure indicator",
        finding="0.9 N_T = N_T - N is the supremum of N_FL, approached as J grows but never reached; the "
        "book "
        "uses 99 % of it.",
        evidence="F(p_d) = 1 to double precision with the paper's sample counts, so N_FL -> 0.9 N_T from "
        "below.",
        discussed_in=PAGE_K1,
    ),
    Erratum(
        id=E_MINOR,
        paper="ATC10",
        locator="Sec. 2.8 and Figs. 2.13-2.14",
        printed="'Table 2.8.1'; heading 'K >> 1'; Fig. 2.13 (ADL) before Fig. 2.14 (FL); 'expanded in "
        "Section 2.6'",
        finding="Table 2.1; 'K > 1' as in the contents; the other figure pairs put FL first; the bounds are "
        "expanded in Secs. 2.7-2.8.",
        evidence="Cross-reading the text, the table of contents and the figure captions.",
        discussed_in=PAGE_K,
    ),
    Erratum(
        id=E_P0,
        paper="ATC10",
        locator="Sec. 2.6 and App. D (before (D.17))",
        printed="Sec. 2.6: 'The average power of s_i(t) during transmission is P_0 = E/tau'; App. D: "
        "'E = P_o tau, where P_o is peak signature power'",
        finding="The two names agree only for a constant-envelope signature; for any other the peak power "
        "exceeds E/tau. Read P0 as Sec. 2.6 defines it, the average power during the pulse, E/tau. No "
        "number changes: every result depends on P0 and tau only through E = P0 tau (10 mJ).",
        evidence="E is the integral of s_i(t)^2 over the pulse, so E = (average power) x tau by definition, "
        "while (peak power) x tau >= E with equality only for a constant envelope. (D.17) and every bound "
        "contain P0 only in the product P0 B tau = E B.",
        claims=("ATC10-sec2.7-pulse-energy",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_INDEP,
        paper="ATC10",
        locator="Eqs. (B.6), (C.14) and Sec. 2.3",
        printed="Prob(Phi_1 | H_0) = (1 - (1 - p_f)^(2B alpha)) (1 - (1 - p_f)^(4B beta))^3, with the "
        "filter output 'sampled at twice the Nyquist rate'",
        finding="The product treats the 2B samples per second of one filter as independent. At twice the "
        "Nyquist rate neighbouring samples of the matched-filter noise are correlated, and the segment edges "
        "are ignored, so the '=' of (B.6) and the window factor of (C.14) are approximations. F, G and the "
        "bounds N_FL and N_ADL built from them are therefore approximate lower bounds, not guaranteed ones, "
        "and so is the paper's upper bound on the required jammer power.",
        evidence="Positively correlated Gaussian samples cross a threshold somewhere in a window less often "
        "than independent ones (Slepian's inequality), so the independent-sample factor overstates the "
        "window probability. A seeded Monte Carlo of 24-sample windows with correlation 1/2 between "
        "neighbours (a rectangular-chip code sampled twice per chip) shows the window left empty markedly "
        "more often than (1 - p_f)^n at the K >= 10 threshold values of p_f. The list-level Monte Carlo of "
        "the same page draws independent samples by construction and so cannot test this assumption. As a "
        "sensitivity, counting half as many independent samples (B instead of 2B per second) moves the "
        "K = 100 thresholds from "
        f"{required_erp_dbw('ambiguous', 0.88, 100):.1f} to {adl_erp_dbw_half_samples(0.88, 100):.1f} dBW "
        f"(P_DL = 0.88) and from {required_erp_dbw('ambiguous', 0.999, 100):.1f} to "
        f"{adl_erp_dbw_half_samples(0.999, 100):.1f} dBW (0.999); K = 1000, P_DL = 0.999 then has "
        + (
            "no finite threshold."
            if math.isinf(adl_erp_dbw_half_samples(0.999, 1000))
            else f"a threshold of {adl_erp_dbw_half_samples(0.999, 1000):.1f} dBW."
        ),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_C2,
        paper="ATC10",
        locator="Eqs. (C.2)-(C.5)",
        printed="|T_1(1) - T_2(1)| <= v alpha / c seconds (and likewise for satellite 2)",
        finding="T_1(1) - T_2(1) is the change in satellite 1's reception time between two successive "
        "pulses: one repetition period alpha plus the change in range. Only the range change is bounded by "
        "v alpha / c. The periods cancel in the difference of differences of (C.2), so (C.5) is right when "
        "the triangle inequality is applied to the range-change terms alone. The bound also ignores the "
        "satellites' own motion: only the aircraft moves the ranges.",
        evidence=f"With alpha = {GEOMETRY.repetition_s:g} s and v = 600 mph, v alpha / c = "
        f"{GEOMETRY.max_speed_m_s * GEOMETRY.repetition_s / units.C * 1e6:.3f} us, while the printed left "
        "side is about alpha itself; (T_1(1) - T_2(1)) - (T_1(2) - T_2(2)) contains no alpha. Sec. 4 places "
        "the satellites in synchronous orbits, whose slow drift makes the omission of satellite motion "
        "small, but the appendix does not say so.",
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_B10,
        paper="ATC10",
        locator="Eq. (B.10)",
        printed="'From (B.8) and the statistical independence of rho(i,j), we obtain immediately' (B.10)",
        finding="(B.10) follows from the event inclusion (B.9) and independence; read 'From (B.9)'. (B.8) "
        "is the K = 1 bound, which enters only in the next step, (B.11).",
        evidence="(B.10) bounds P_F by the probability of the intersection of Kt + 1 events rho(i,j) = 1 "
        "named in (B.9), which factorises by independence; the text then applies (B.5) and (B.6), the "
        "ingredients of (B.8), to reach (B.11).",
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_A_END,
        paper="ATC10",
        locator="App. A, last line (after (A.18))",
        printed="P_D > p_d^4",
        finding="The K = 1 bound is P_D >= p_d^4, as printed in (2.4.1) and (A.10a). The appendix derives "
        "the non-strict bound, and p_d^4 is approached as p_f -> 0.",
        evidence="(2.4.1) and (A.10a) print >=. At K = 1 the list is non-empty with probability p_d^4 from "
        "the true arrival alone, plus what noise declarations add, which vanishes as the jammer power goes "
        "to zero; the closed-form bound at K = 1 equals p_d^4 exactly.",
        claims=("ATC10-eq2.4.1",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_258,
        paper="ATC10",
        locator="Eq. (2.5.8)",
        printed="Prob(Gamma_D, gamma_D, psi_D, theta_D = 1) = Prob(Gamma_D | gamma_D, psi_D, theta_D) "
        "Prob(gamma_D) Prob(psi_D | theta_D) Prob(theta_D)",
        finding="The factorisation takes the false-track indicator gamma_D to be independent of the "
        "detection and presence indicators (psi_D, theta_D), which the text does not state. It is not "
        "exact: a false track puts an entry on every one of the K lists, so gamma_D = 1 forces the first "
        "stage to decide 'present' (psi_D = 1) for any t < 1. The dependence is positive, so the product "
        "still bounds the joint probability from below, and the factor P_DL in (2.5.12) is conservative.",
        evidence="By the definitions of Sec. 2.5.2 and the rule of Sec. 2.4, Prob(gamma_D = 1, psi_D = 1 | "
        "theta_D = 1) = Prob(gamma_D = 1 | theta_D = 1) >= Prob(gamma_D = 1 | theta_D = 1) Prob(psi_D = 1 | "
        "theta_D = 1). The Appendix C bound on gamma_D uses noise-only declarations, so it holds given "
        "theta_D = 1 as well (up to the one signal sample per filter). Dropping the factor P_DL lowers the "
        "finite t = 0 thresholds of Table 2.1 and of K = 1 by at most "
        f"{max_pdl_factor_shift_db():.2f} dB"
        + (
            ", and leaves the K = 1000, P_DL = 0.98 entry without a finite power."
            if math.isinf(adl_erp_dbw_without_pdl_factor(0.98, 1000))
            else "."
        ),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_A16,
        paper="ATC10",
        locator="Eq. (A.16)",
        printed="P(rho = 1 | H_1) ~ p_d^4, 'the approximation holds closely assuming reasonably large "
        "enough values for p_d'",
        finding="The K = 1000 designs do not have a large p_d: "
        + ", ".join(f"p_d = {design_p_d(p, 1000):.3f} for P_DL = {p}" for p in (0.88, 0.98, 0.999))
        + f", so p_d^4 <= {design_p_d(0.999, 1000) ** 4:.4f}, while near the jamming threshold noise alone "
        "fills a list almost surely. The "
        "approximation fails there, but, as the text says, the bound (A.17) stays valid: it is only loose.",
        evidence="P(rho = 1 | H_1) >= p_d^4 because the true arrival alone fills the list, and the Chernoff "
        "exponent D(t || q) increases with q for q > t (dD/dq = (q - t) / (q (1 - q))), so replacing "
        "P(rho = 1 | H_1) by the smaller p_d^4 can only lower the bound. At the K = 1000, P_DL = 0.999 "
        "threshold p_f = "
        f"{math.exp(threshold_log_pf(0.999, 1000)):.2f}, and the noise-only list factor F(p_f) of (B.6) "
        "differs from 1 by "
        f"{-math.expm1(float(jm.log_false_list_factor(threshold_log_pf(0.999, 1000), GEOMETRY))):.0e}.",
        discussed_in=PAGE,
    ),
]


# --------------------------------------------------------------------------------------
# claims
# --------------------------------------------------------------------------------------

_READ = Tolerance(
    reason="Table entries are whole dB read off log-scale plots: half a dB of rounding plus half a dB of "
    "reading where the curve crosses the level at a shallow angle",
    abs=1.0,
)
_READ_FLAT = Tolerance(
    reason="At K = 1000 the N_ADL curve meets 0.01 N_T at a slope of only 0.1 (natural log) per dB, so a "
    "10 % misreading of the level moves the crossing by about 1 dB; plus whole-dB rounding",
    abs=2.0,
)
_ORACLE_DB = Tolerance(reason="grid search refined by 60 bisections: agreement to 1e-6 dB expected", abs=0.01)
_STRICT = Tolerance(reason="strict inequality as stated in the text; no allowance", abs=0.0)


def _table21_claim(k: int, p_dl: float, text: str, relation: str) -> Claim:
    value, tol = printed(text)
    status = "reproduced"
    if relation == ">":
        tol = Tolerance(reason="the paper prints a lower bound; the model gives no finite power", abs=0.0)
    elif k == 1000:
        tol, status = _READ_FLAT, "consistent"
    elif abs(required_erp_dbw("ambiguous", p_dl, k) - value) > tol.allowed(value):
        tol, status = _READ, "consistent"
    return Claim(
        id=f"ATC10-tab2.1-K{k}-pdl{p_dl}",
        paper="ATC10",
        locator="Table 2.1",
        quantity=f"jammer ERP per satellite for N_ADL = 0.01 N_T, K = {k}, P_DL = {p_dl}",
        published=value,
        unit="dBW",
        compute=lambda: required_erp_dbw("ambiguous", p_dl, k),
        tolerance=tol,
        expected_status=status,  # type: ignore[arg-type]
        relation=relation,  # type: ignore[arg-type]
        note="t = 0, p_f from (D.17) = (2.7.1), N_ADL of (2.8.4) with 2B alpha = 2e7, 4B beta = 9.6e5 and "
        "n_v = 23.86 samples; ERP = x_dB + 10 log10(P0 tau B) = x_dB + 50 dBW."
        + (
            " The N_ADL ceiling (J -> inf) is 0.0021 N_T < 0.01 N_T, so no power suffices."
            if relation == ">"
            else ""
        ),
        discussed_in=PAGE_K,
    )


CLAIMS: list[Claim] = [
    Claim(
        id="ATC10-sec1.1-erp-rises-with-K",
        paper="ATC10",
        locator="Sec. 1.1 and Table 1.1",
        quantity="the jammer ERP needed to disable the system rises with the transmission length K = 1, 10, "
        "100, 1000 ('for K less than 100 the required jammer is modest ... as K approaches 1000 ...')",
        published=True,
        unit="statement",
        compute=_erp_rises_with_k,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Threshold search for N_ADL = 0.01 N_T at t = 0, for the caption's P_D = 0.88 and for "
        "Table 2.1's P_DL = 0.999 (the design point most Table 1.1 entries use): both sequences increase "
        "strictly, and the K < 100 values are finite. 'Modest' is read as: a finite requirement for K = 1 "
        "and 10, of the size Table 1.1 equips with at most 20 dBW (100 W) of rf power and a 4 ft dish; the "
        "dollar cost is not testable.",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-sec1.1-K1000-prohibitive",
        paper="ATC10",
        locator="Sec. 1.1 and Table 2.1",
        quantity="as K approaches 1000 the barrage jammer becomes prohibitive: for the caption's P_D >= 0.88 "
        "design no finite ERP disables a K = 1000 system (beyond Table 2.1's '>130 dBW')",
        published=True,
        unit="statement",
        compute=_k1000_beyond_practical,
        tolerance=EXACT,
        expected_status="reproduced",
        note="'Prohibit' read at the caption's P_D = 0.88: the K = 1000 N_ADL ceiling (J -> inf) lies "
        "below 0.01 N_T, so the threshold search returns infinity, above the printed >130 dBW. At P_DL = "
        "0.999, the design Table 1.1's K = 1000 row actually uses, the ERP is finite (claim "
        "ATC10-tab1.1-K1000-erp); "
        "there 'prohibit' can only mean cost and complexity (Table 1.1: 40 dBW rf, an 18 ft dish), which "
        "the book cannot test.",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-sec1.3-oscillator",
        paper="ATC10",
        locator="Sec. 1.3",
        quantity="oscillator stability for 50 ns rms over a 1 s update",
        published=5e-8,
        unit="",
        compute=lambda: TOA_RMS_ERROR_S / UPDATE_INTERVAL_S,
        tolerance=printed("5e-8")[1],
        expected_status="reproduced",
        note="Arithmetic on two printed values only (50 ns rms, one update per second): fractional stability "
        "= time error / update interval. No navcore model is involved; the check guards the reading, not a "
        "computation.",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-sec2.7-pulse-energy",
        paper="ATC10",
        locator="Sec. 2.7",
        quantity="pulse energy for P0 = 30 dBW and tau = 10 us",
        published=10.0,
        unit="mJ",
        compute=lambda: units.watts_from_dbw(PULSE_POWER_DBW) * PULSE_DURATION_S * 1e3,
        tolerance=Tolerance(reason="exact arithmetic up to rounding", abs=1e-9),
        expected_status="reproduced",
        note="Arithmetic on printed values only: E = P0 tau from the module inputs PULSE_POWER_DBW and "
        "PULSE_DURATION_S (the printed 30 dBW and 10 us). The thresholds use GEOMETRY.pulse_energy_j, the "
        "printed 10 mJ, and a test checks that it equals P0 tau. P0 is the average power during the pulse "
        "(erratum ATC10-E-jam-P0-average-peak).",
        discussed_in=PAGE_K1,
    ),
    Claim(
        id="ATC10-eq2.4.1",
        paper="ATC10",
        locator="Eqs. (2.4.1), (A.10a)",
        quantity="for K = 1 the detection bound is p_d^4",
        published=True,
        unit="statement",
        compute=_k1_bound_is_pd4,
        tolerance=EXACT,
        expected_status="reproduced",
        note="The closed-form Chernoff bound at K = 1, t = 0 against p_d^4 on a grid of p_d.",
        discussed_in=PAGE,
    ),
    Claim(
        id="ATC10-eq2.4.2-nu-max",
        paper="ATC10",
        locator="Eqs. (2.4.2), (A.17)-(A.18)",
        quantity="the nu-maximised exponent of (2.4.2) equals the binary divergence D(t || p_d^4) for t < "
        "p_d^4 "
        "and 0 otherwise",
        published=True,
        unit="statement",
        compute=_exponent_matches_numeric,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Closed form against bounded numerical maximisation over nu >= 0 at five (t, q) pairs, to "
        "1e-10.",
        discussed_in=PAGE,
    ),
    Claim(
        id="ATC10-appA-limit",
        paper="ATC10",
        locator="App. A, after (A.18)",
        quantity="if t < p_d^4 then P_D -> 1 as K -> infinity",
        published=True,
        unit="statement",
        compute=_bound_tends_to_one,
        tolerance=EXACT,
        expected_status="reproduced",
        note="p_d = 0.7 (p_d^4 = 0.24), t = 0.2: the bound increases with K and exceeds 1 - 1e-12 at K = "
        "1e4.",
        discussed_in=PAGE,
    ),
    Claim(
        id="ATC10-eqA.9-rule-at-design",
        paper="ATC10",
        locator="Eqs. (A.9)-(A.10)",
        quantity="first-stage detection probability at the K = 10, P_DL = 0.999 design point (t = 0) "
        "under the "
        "rule as printed in (A.9), which the bound (A.17) claims is at least P_DL",
        published=0.999,
        unit="",
        relation=">=",
        compute=lambda: float(jm.empty_list_rule_detection_probability(design_p_d(0.999, 10) ** 4, 10, 0.0)),
        tolerance=Tolerance(reason="a lower bound as stated; no allowance", abs=0.0),
        expected_status="discrepant",
        erratum=E_RULE,
        oracle=lambda: design_p_d(0.999, 10) ** 40,
        oracle_tolerance=Tolerance(
            reason="binomial cdf against the closed form q^K: rounding only", rel=1e-10
        ),
        note="Under (A.9) with t = 0 every list must be non-empty: probability q^K. The bound holds for the "
        "rule of (A.11), which is what the paper uses.",
        discussed_in=PAGE,
    ),
    Claim(
        id="ATC10-eqA.15-printed",
        paper="ATC10",
        locator="Eq. (A.15)",
        quantity="right side of (A.15) as printed ('1 exp -K(...)') at the K = 10, P_DL = 0.999 design point",
        published=0.999,
        unit="",
        compute=printed_a15_value,
        tolerance=printed("0.999")[1],
        expected_status="discrepant",
        erratum=E_A15,
        oracle=lambda: float(stats.binom.pmf(0, 10, design_p_d(0.999, 10) ** 4)),
        oracle_tolerance=Tolerance(reason="exp(-K D) at t = 0 is (1-q)^K exactly: rounding only", rel=1e-9),
        note="Without the minus sign the expression is exp(-K E) = P(all lists empty); with it, 1 - "
        "exp(-K E) "
        "= 0.999 as designed.",
        discussed_in=PAGE,
    ),
    Claim(
        id="ATC10-eqC.1-printed",
        paper="ATC10",
        locator="Eq. (C.1)",
        quantity="(C.1) as printed equals F(p_f) of (B.6), the factor (2.5.12) uses for K = 1",
        published=True,
        unit="statement",
        compute=lambda: printed_c1_equals_b6(False),
        tolerance=EXACT,
        expected_status="discrepant",
        erratum=E_C1,
        oracle=lambda: printed_c1_equals_b6(True),
        oracle_tolerance=EXACT,
        note="Evaluated at the K = 1, P_DL = 0.88 threshold, p_f ~ 1e-6: (1 - p_f)^(2e7) ~ e^-20 where "
        "1 - (1 - p_f)^(2e7) ~ 1. Oracle: mpmath at 40 digits.",
        discussed_in=PAGE,
    ),
    Claim(
        id="ATC10-eq2.8.1-erf-coefficient",
        paper="ATC10",
        locator="Eqs. (2.8.1), (2.8.3)",
        quantity="coefficient c of sqrt(P0 B tau / J) in the erf argument of p_f",
        published=0.5,
        unit="",
        compute=erf_argument_coefficient,
        tolerance=Tolerance(reason="an exact coefficient; rounding only", abs=1e-9),
        expected_status="discrepant",
        erratum=E_ERF,
        oracle=monte_carlo_erf_coefficient,
        oracle_tolerance=Tolerance(
            reason="1e6-sample Monte Carlo: 4 sigma of p_f ~ 1.5e-3, i.e. about 4e-3 on c (threshold "
            "quantile adds less)",
            abs=6e-3,
        ),
        note="navcore's p_f (App. D, D.17) inverted for c at x = 0 dB, p_d = 0.5 gives 1/sqrt(2). (2.7.1) "
        "and "
        "(2.8.4) print the correct argument.",
        discussed_in=PAGE_K,
    ),
    # ---- Sec. 2.7, K = 1
    Claim(
        id="ATC10-sec2.7-nominal-33dBW",
        paper="ATC10",
        locator="Sec. 2.7",
        quantity="nominal jammer ERP for K = 1 (N_ADL = 0.01 N_T, P_DL = 0.9)",
        published=33.0,
        unit="dBW",
        compute=lambda: required_erp_dbw("ambiguous", 0.9, 1),
        tolerance=_READ,
        expected_status="consistent",
        note="Read off Fig. 2.2; 33.6 dBW for P_DL = 0.88 and 31.7 dBW for 0.999. The N_FL threshold "
        "(99 % of 0.9 N_T) is 34.0 dBW.",
        discussed_in=PAGE_K1,
    ),
    Claim(
        id="ATC10-sec2.7-lt2dB-ADL",
        paper="ATC10",
        locator="Sec. 2.7",
        quantity="difference in required jammer ERP between P_DL = 0.9 and 0.999 (K = 1, N_ADL)",
        published=2.0,
        unit="dB",
        relation="<",
        compute=lambda: required_erp_dbw("ambiguous", 0.9, 1) - required_erp_dbw("ambiguous", 0.999, 1),
        tolerance=_STRICT,
        expected_status="reproduced",
        note="Thresholds at N_ADL = 0.01 N_T; higher P_DL needs less jamming.",
        discussed_in=PAGE_K1,
    ),
    Claim(
        id="ATC10-sec2.7-lt2dB-FL",
        paper="ATC10",
        locator="Sec. 2.7",
        quantity="difference in required jammer ERP between P_DL = 0.9 and 0.999 (K = 1, N_FL)",
        published=2.0,
        unit="dB",
        relation="<",
        compute=lambda: required_erp_dbw("false", 0.9, 1) - required_erp_dbw("false", 0.999, 1),
        tolerance=_STRICT,
        expected_status="reproduced",
        note="Thresholds at 99 % of the N_FL supremum 0.9 N_T.",
        discussed_in=PAGE_K1,
    ),
    Claim(
        id="ATC10-sec2.7-plateau",
        paper="ATC10",
        locator="Sec. 2.7",
        quantity="from -12 dB downwards the K = 1 bounds keep their maximum values over a large range",
        published=True,
        unit="statement",
        compute=_plateau_below_minus_12db,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Both bounds are within 0.1 % of their J -> inf ceilings at -12 dB for P_DL in {0.88, 0.9, "
        "0.99, "
        "0.999}; the threshold falls 2-4 dB further down.",
        discussed_in=PAGE_K1,
    ),
    Claim(
        id="ATC10-sec2.7-30W",
        paper="ATC10",
        locator="Sec. 2.7",
        quantity="rf power for 33 dBW ERP with a 2 ft dish",
        published=30.0,
        unit="W",
        compute=lambda: units.watts_from_dbw(33.0 - _dish_gain_db(2.0)),
        tolerance=Tolerance(
            reason="'30 watts' is a round figure for a whole-dB ERP: +-0.5 dB is +-12 %; the dish model "
            "(1.6 GHz, eta = 0.6) is assumed",
            rel=0.12,
        ),
        expected_status="consistent",
        note="2 ft from Table 1.1; gain 17.97 dB at 1.6 GHz with efficiency 0.6.",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-sec2.7-20deg",
        paper="ATC10",
        locator="Sec. 2.7",
        quantity="beamwidth of an antenna giving 33 dBW ERP from 30 W",
        published=20.0,
        unit="deg",
        compute=lambda: float(
            antenna.beamwidth_from_gain_deg(units.power_ratio_from_db(33.0 - units.dbw_from_watts(30.0)))
        ),
        tolerance=printed("20")[1],
        expected_status="reproduced",
        note="G = 33 - 14.77 = 18.2 dB; beamwidth sqrt(27000/G) degrees (70 lambda/D for a 2 ft dish at 1.6 "
        "GHz gives 21.4).",
        discussed_in=PAGE_T11,
    ),
    # ---- Sec. 2.8, K > 1
    *[_table21_claim(k, p, text, rel) for k, p, text, rel in TABLE_2_1],
    Claim(
        id="ATC10-sec2.8-10dB-K1to10-pdl0.999",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="extra jammer ERP to disable K = 10 rather than K = 1 (P_DL = 0.999)",
        published=10.0,
        unit="dB",
        compute=lambda: required_erp_dbw("ambiguous", 0.999, 10) - required_erp_dbw("ambiguous", 0.999, 1),
        tolerance=Tolerance(reason="'about 10 dB' in prose: a band of +-2.5 dB (a quarter decade)", abs=2.5),
        expected_status="consistent",
        note="N_ADL = 0.01 N_T thresholds at t = 0.",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-sec2.8-10dB-K1to10-pdl0.88",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="extra jammer ERP to disable K = 10 rather than K = 1 (P_DL = 0.88)",
        published=10.0,
        unit="dB",
        compute=lambda: required_erp_dbw("ambiguous", 0.88, 10) - required_erp_dbw("ambiguous", 0.88, 1),
        tolerance=Tolerance(reason="'about 10 dB' in prose: a band of +-2.5 dB (a quarter decade)", abs=2.5),
        expected_status="consistent",
        note="N_ADL = 0.01 N_T thresholds at t = 0.",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-sec2.8-10dB-K10to100-pdl0.999",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="extra jammer ERP to disable K = 100 rather than K = 10 (P_DL = 0.999)",
        published=10.0,
        unit="dB",
        compute=lambda: required_erp_dbw("ambiguous", 0.999, 100) - required_erp_dbw("ambiguous", 0.999, 10),
        tolerance=Tolerance(reason="'about 10 dB' in prose: a band of +-2.5 dB (a quarter decade)", abs=2.5),
        expected_status="consistent",
        note="N_ADL = 0.01 N_T thresholds at t = 0.",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-sec2.8-10dB-K10to100-pdl0.88",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="extra jammer ERP to disable K = 100 rather than K = 10 (P_DL = 0.88)",
        published=10.0,
        unit="dB",
        compute=lambda: required_erp_dbw("ambiguous", 0.88, 100) - required_erp_dbw("ambiguous", 0.88, 10),
        tolerance=Tolerance(reason="'about 10 dB' in prose: a band of +-2.5 dB (a quarter decade)", abs=2.5),
        expected_status="consistent",
        note="N_ADL = 0.01 N_T thresholds at t = 0.",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-sec2.8-t0-worst",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="the t = 0 curves need the most jammer power (required ERP decreases as t increases)",
        published=True,
        unit="statement",
        compute=_t_zero_needs_most_power,
        tolerance=EXACT,
        expected_status="reproduced",
        note="t in {0, 0.05, 0.1, 0.2, 0.3}, both bounds, every finite Table 2.1 design point; p_d re-solved "
        "for each t so that P_DL stays fixed.",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-sec2.8-FL-less-t-sensitive",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="the N_FL curves are less sensitive to t than the N_ADL curves",
        published=True,
        unit="statement",
        compute=_fl_less_sensitive_to_t,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Spread of the required ERP between t = 0 and t = 0.3 at (K, P_DL) = (10, 0.88), (100, 0.88), "
        "(1000, 0.999).",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-sec2.8-FL-first",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="N_FL degrades at less jammer power than N_ADL",
        published=True,
        unit="statement",
        compute=_fl_degrades_first,
        tolerance=EXACT,
        expected_status="reproduced",
        note="At every finite Table 2.1 design point (t = 0) the N_FL threshold (99 % of 0.9 N_T) lies below "
        "the N_ADL threshold (0.01 N_T).",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-sec2.8-K1000-critical",
        paper="ATC10",
        locator="Sec. 2.8",
        quantity="for K = 1000 the required power depends critically on P_DL: unbounded at 0.98, finite "
        "at 0.999",
        published=True,
        unit="statement",
        compute=_k1000_depends_critically,
        tolerance=EXACT,
        expected_status="reproduced",
        note="The N_ADL ceiling at K = 1000 reaches 0.01 N_T only for P_DL above about 0.9954.",
        discussed_in=PAGE_K,
    ),
    Claim(
        id="ATC10-fig2.3-2.16-curve-sets",
        paper="ATC10",
        locator="Figs. 2.3-2.16",
        quantity="the (p_d, t) combinations of the curves in Figs. 2.3-2.16",
        published=True,
        unit="statement",
        compute=None,
        tolerance=EXACT,
        expected_status="not-reproducible",
        note="The figures survive only as captions; only the t = 0 curves are pinned down by the text. The "
        "book draws t in {0, 0.05, 0.1, 0.2, 0.3}.",
        discussed_in=PAGE_K,
    ),
    # ---- Table 1.1
    Claim(
        id="ATC10-tab1.1-K1-erp",
        paper="ATC10",
        locator="Table 1.1",
        quantity="jammer ERP for K = 1 (P_D >= 0.88 per the caption)",
        published=33.0,
        unit="dBW",
        compute=lambda: required_erp_dbw("ambiguous", 0.88, 1),
        tolerance=_READ,
        expected_status="consistent",
        note="N_ADL = 0.01 N_T, P_DL = p_d^4 = 0.88.",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-tab1.1-K10-erp",
        paper="ATC10",
        locator="Table 1.1",
        quantity="jammer ERP for K = 10 (the Table 2.1 P_DL = 0.999 design point)",
        published=43.0,
        unit="dBW",
        compute=lambda: required_erp_dbw("ambiguous", 0.999, 10),
        tolerance=printed("43")[1],
        expected_status="reproduced",
        note="Equals Table 2.1's P_DL = 0.999 row; the caption's 0.88 would give 45.8 dBW (erratum).",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-tab1.1-K100-erp",
        paper="ATC10",
        locator="Table 1.1",
        quantity="jammer ERP for K = 100 (the Table 2.1 P_DL = 0.999 design point)",
        published=53.0,
        unit="dBW",
        compute=lambda: required_erp_dbw("ambiguous", 0.999, 100),
        tolerance=_READ,
        expected_status="discrepant",
        erratum=E_TAB11,
        oracle=lambda: direct_adl_erp_dbw(0.999, 100),
        oracle_tolerance=_ORACLE_DB,
        note="51.2 dBW at P_DL = 0.999 and 55.3 at 0.88 (Table 2.1 prints 51 and 56); P_DL = 0.98 would "
        "give 53.0.",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-tab1.1-K1000-erp",
        paper="ATC10",
        locator="Table 1.1",
        quantity="jammer ERP for K = 1000 (the Table 2.1 P_DL = 0.999 design point)",
        published=77.0,
        unit="dBW",
        compute=lambda: required_erp_dbw("ambiguous", 0.999, 1000),
        tolerance=_READ_FLAT,
        expected_status="consistent",
        note="Same entry as Table 2.1; the caption's P_DL = 0.88 gives no finite power.",
        discussed_in=PAGE_T11,
    ),
    Claim(
        id="ATC10-tab1.1-caption-pdl",
        paper="ATC10",
        locator="Table 1.1 caption and Sec. 1.1",
        quantity="every Table 1.1 ERP is the requirement for a processor designed for P_D >= 0.88",
        published=True,
        unit="statement",
        compute=lambda: _table11_matches_caption_pdl(False),
        tolerance=EXACT,
        expected_status="discrepant",
        erratum=E_TAB11,
        oracle=lambda: _table11_matches_caption_pdl(True),
        oracle_tolerance=EXACT,
        note="Within 1 dB of the P_DL = 0.88 thresholds (33.6, 45.8, 55.3, none): only K = 1 matches.",
        discussed_in=PAGE_T11,
    ),
]

for _i, (_k, _erp, _rf, _dia, _bw) in enumerate(TABLE_1_1):
    CLAIMS.append(
        Claim(
            id=f"ATC10-tab1.1-K{_k}-rf",
            paper="ATC10",
            locator="Table 1.1",
            quantity=f"rf power for K = {_k}: printed ERP minus the gain of the printed {_dia} ft dish",
            published=float(_rf),
            unit="dBW",
            compute=lambda i=_i: table11_rf_dbw(i),
            tolerance=Tolerance(
                reason="whole-dB entries and whole-foot diameters; the dish model (1.6 GHz, eta = 0.6) is "
                "assumed, not stated",
                abs=1.0,
            ),
            expected_status="consistent",
            note="G = eta (pi D / lambda)^2 at 1.6 GHz, eta = 0.6.",
            discussed_in=PAGE_T11,
        )
    )
    CLAIMS.append(
        Claim(
            id=f"ATC10-tab1.1-K{_k}-diameter",
            paper="ATC10",
            locator="Table 1.1",
            quantity=f"dish diameter for K = {_k} from the gain ERP - rf power",
            published=float(_dia),
            unit="ft",
            compute=lambda i=_i: table11_diameter_ft(i),
            tolerance=Tolerance(reason="printed to whole feet; the dish model is assumed", abs=0.5),
            expected_status="consistent",
            note="D = (lambda/pi) sqrt(G/eta), 1.6 GHz, eta = 0.6 (chosen as a typical L-band dish; the pair "
            "is not unique).",
            discussed_in=PAGE_T11,
        )
    )
    if _k == 1:
        CLAIMS.append(
            Claim(
                id="ATC10-tab1.1-K1-beamwidth",
                paper="ATC10",
                locator="Table 1.1",
                quantity="beamwidth of the K = 1 jammer antenna",
                published=float(_bw),
                unit="deg",
                compute=lambda i=_i: table11_beamwidth_deg(i),
                tolerance=Tolerance(
                    reason="whole degrees, plus 0.5 deg for the beamwidth rule of thumb", abs=1.0
                ),
                expected_status="discrepant",
                erratum=E_BEAM,
                oracle=lambda i=_i: table11_beamwidth_from_gain_deg(i),
                oracle_tolerance=Tolerance(
                    reason="70 lambda/D and sqrt(27000/G) differ by up to 5 %", rel=0.05
                ),
                note="70 lambda/D for the dish of gain 18 dB; Sec. 2.7 itself says 20 degrees.",
                discussed_in=PAGE_T11,
            )
        )
    else:
        CLAIMS.append(
            Claim(
                id=f"ATC10-tab1.1-K{_k}-beamwidth",
                paper="ATC10",
                locator="Table 1.1",
                quantity=f"beamwidth of the K = {_k} jammer antenna",
                published=float(_bw),
                unit="deg",
                compute=lambda i=_i: table11_beamwidth_deg(i),
                tolerance=Tolerance(
                    reason="whole degrees, plus 0.5 deg for the beamwidth rule of thumb", abs=1.0
                ),
                expected_status="consistent",
                note="70 lambda/D for the dish whose gain is ERP - rf power (1.6 GHz, eta = 0.6).",
                discussed_in=PAGE_T11,
            )
        )
