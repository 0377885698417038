"""ATC-10 Appendices A-D: the derivations behind the jamming model.

The majority test and the Chernoff bound (App. A), the window products of (B.6) and (C.14),
the Monte Carlo checks of Apps. B-C and the Gaussian algebra of Appendix D, with their errata.
Inputs are read from :mod:`navcore.papers.atc10_jamming`.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp
from scipy import special, stats

from navcore import units
from navcore.claims import EXACT, Claim, Erratum, with_quotes
from navcore.detection import jamming as jm
from navcore.detection import jamming_monte_carlo as mc
from navcore.detection.neyman_pearson import (
    detection_index_from_jammer_ratio,
    false_alarm_probability,
)
from navcore.papers.atc10_jamming import (
    IN,
    IN_COV,
    IN_J,
    PAGE,
    design_p_d,
    geometry,
    level,
    table21_design,
)
from navcore.papers.atc10_quotes import QUOTES
from navcore.papers.atc10_tracking_lists import threshold_log_pf

CLAIMS: list[Claim] = []
ERRATA: list[Erratum] = []


def _bound_tends_to_one() -> bool:
    """App. A: with t < p_d^4 the bound tends to 1 as K grows (K = 10 to 10^6)."""
    p_d, t = 0.7, 0.2
    if not t < p_d**4:
        raise ValueError(f"the test point must satisfy App. A's premise t < p_d^4, got t = {t}, p_d = {p_d}")
    values = [float(jm.detection_lower_bound(p_d, k, t)) for k in (10, 100, 1000, 10_000, 100_000, 1_000_000)]
    return bool(np.all(np.diff(values) >= 0) and values[0] < values[-1] and values[-1] > 1 - 1e-12)


def printed_c1_log_ratio(use_mpmath: bool) -> float:
    """ln of (C.1) as printed, [1-p_f]^(2B alpha) [1-(1-p_f)^(4B beta)]^3, over F of (B.6), at the
    K = 1 design threshold (the caption's P_DL = 0.88). It should be 0, since (2.5.12) uses F."""
    g = geometry()
    p_d = design_p_d(IN.caption_p_dl, 1)
    x = 10 ** (jm.jammer_ratio_threshold_db("ambiguous", level("ambiguous"), p_d, 1, 0.0, g) / 10)
    if use_mpmath:
        with mpmath.workdps(40):
            d = 1 / mpmath.sqrt(mpmath.mpf(x))
            pf = (
                mpmath.erfc((d - mpmath.sqrt(2) * mpmath.erfinv(2 * mpmath.mpf(p_d) - 1)) / mpmath.sqrt(2))
                / 2
            )
            return float(2e7 * mpmath.log1p(-pf) - mpmath.log(1 - (1 - pf) ** 2e7))
    log_pf = math.log(float(false_alarm_probability(p_d, detection_index_from_jammer_ratio(x))))
    log_printed = g.samples_per_period * math.log1p(-math.exp(log_pf)) + 3 * float(
        jm.log_one_minus_power(log_pf, g.samples_per_delay_window)
    )
    return log_printed - float(jm.log_false_list_factor(log_pf, g))


def printed_a15_value(row: int = 2) -> float:
    """Right side of (A.15) read as printed, "1 exp -K(...)" = exp(-K E), at the t = 0 design point
    of Table 2.1's row ``row`` (K = 10, P_DL = 0.999)."""
    k, p_dl = table21_design(row)
    q = design_p_d(p_dl, k, 0.0) ** 4
    return float(math.exp(-k * float(jm.list_rule_exponent(0.0, q))))


E_RULE = "ATC10-E-jam-decision-rule"


E_C1 = "ATC10-E-jam-appC-typos"


E_A15 = "ATC10-E-jam-A15-sign"


E_A7 = "ATC10-E-jam-A7-ratio"


E_C2 = "ATC10-E-jam-C2-track-window"


E_B10 = "ATC10-E-jam-B10-reference"


ERRATA += [
    Erratum(
        id=E_RULE,
        kind="derivation",
        basis="text-only",
        locator="Eqs. (A.9)-(A.10) against (A.11), (B.1)",
        printed="Decide $H_1$ if $K_0 \\le tK$ ($K_0$ the number of empty lists)",
        finding="The bounds (A.17), (B.11), the figures and the tables use the rule of (A.11)/(B.1) and of "
        "Sec. 2.4: decide $H_1$ if more than $tK$ lists are non-empty. (A.11) does not follow from (A.10); "
        "the two are the same family with $t$ replaced by $1 - t$.",
        evidence="Exact binomial probabilities: at the $K = 10$, $P_{DL} = 0.999$ design point the literal "
        "(A.9) "
        "rule with $t = 0$ detects only when every one of the $K$ lists is non-empty, with probability "
        "$q^K$ ($q$ that of one list), far below the bound 0.999 that holds (with equality) for the (A.11) "
        "rule.",
        claims=("ATC10-eqA.9-rule-at-design",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_C1,
        kind="typography",
        basis="text-only",
        locator="Eqs. (C.1), (C.11) and cross-references of App. C",
        printed="(C.1): $[1 - p_f]^{2B\\alpha} [1 - (1 - p_f)^{4B\\beta}]^3$; (C.11) conditions on "
        "$\\gamma_D(i, K) = 1$",
        finding="(C.1) should read $[1 - (1 - p_f)^{2B\\alpha}][1 - (1 - p_f)^{4B\\beta}]^3 = F(p_f)$ of "
        "(B.6); "
        "(C.11) should condition on $\\gamma_D(i, K-1) = 1$; 'than (C.4)' means (C.5), 'in (C.8)' means "
        "(C.10) "
        "and 'applied to (C.14)' means (C.16).",
        evidence="At the K = 1 design threshold the printed (C.1) is smaller than F by a factor of about "
        "$e^{-20}$ (mpmath), whereas (2.5.12) and (C.17) use F; the recursion (C.15)-(C.16) only closes with "
        "$\\gamma_D(i, K-1)$.",
        claims=("ATC10-eqC.1-printed",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_A15,
        kind="typography",
        basis="text-only",
        locator="Eq. (A.15)",
        printed="$P_D \\ge 1 \\exp -K(\\ldots)$",
        finding="A minus sign is lost: $P_D \\ge 1 - \\exp(-K(\\ldots))$, as in (A.17) and (2.4.2).",
        evidence="Read literally the right side at the $K = 10$, $P_{DL} = 0.999$ design point is 0.001, "
        "which is "
        "the probability that all ten lists are empty (exact binomial), not a lower bound on detection.",
        claims=("ATC10-eqA.15-printed",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_A7,
        kind="typography",
        basis="text-only",
        locator="Eqs. (A.7)-(A.8); text after (A.13), (A.18)",
        printed="$K \\ln(\\lambda_1 P(\\rho=1|H_0)/P(\\rho=1|H_1))$; the label (A.8) is empty; 'J' for "
        "$\\nu$",
        finding="The ratio is inverted: $K \\ln(\\lambda_1 P(\\rho=1|H_1)/P(\\rho=1|H_0))$. Harmless, since "
        "$\\lambda_1$ is "
        "free; 'J' in the text is the Chernoff parameter $\\nu$.",
        evidence="Taking logarithms of (A.6), $\\Lambda_1 = a^{K_0} b^{K-K_0} \\le \\lambda_1^K$, gives "
        "$K_0 \\ln(a/b) \\le K \\ln(\\lambda_1/b)$.",
        claims=("ATC10-eqA.7-printed",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_C2,
        kind="derivation",
        basis="text-only",
        locator="Eqs. (C.2)-(C.5)",
        printed="$|T_1(1) - T_2(1)| \\le v \\alpha / c$ seconds (and likewise for satellite 2)",
        finding="$T_1(1) - T_2(1)$ is the change in satellite 1's reception time between two successive "
        "pulses: one repetition period $\\alpha$ plus the change in range. Only the range change is bounded "
        "by "
        "$v \\alpha / c$. The periods cancel in the difference of differences of (C.2), so (C.5) is right "
        "when "
        "the triangle inequality is applied to the range-change terms alone. The bound also ignores the "
        "satellites' own motion: only the aircraft moves the ranges.",
        evidence="With $\\alpha = 1$ s and $v = 600$ mph, $v \\alpha / c$ = 0.895 µs, while the printed left "
        "side is about $\\alpha$ itself; $(T_1(1) - T_2(1)) - (T_1(2) - T_2(2))$ contains no $\\alpha$. "
        "Sec. 4 "
        "places "
        "the satellites in synchronous orbits, whose slow drift makes the omission of satellite motion "
        "small, but the appendix does not say so.",
        claims=("ATC10-eqC.2-printed",),
        discussed_in=PAGE,
    ),
    Erratum(
        id=E_B10,
        kind="typography",
        basis="text-only",
        locator="Eq. (B.10)",
        printed="'From (B.8) and the statistical independence of $\\rho(i,j)$, we obtain immediately' (B.10)",
        finding="(B.10) follows from the event inclusion (B.9) and independence; read 'From (B.9)'. (B.8) "
        "is the K = 1 bound, which enters only in the next step, (B.11).",
        evidence="(B.10) bounds $P_F$ by the probability of the intersection of $Kt + 1$ events $\\rho(i,j) "
        "= 1$ "
        "named in (B.9), which factorises by independence; the text then applies (B.5) and (B.6), the "
        "ingredients of (B.8), to reach (B.11).",
        no_claim_reason="a wrong cross-reference in the prose; (B.10) itself holds (claim "
        "ATC10-eqB.11-monte-carlo checks the chain (B.1)-(B.11))",
        discussed_in=PAGE,
    ),
]

CLAIMS += [
    Claim.statement(
        id="ATC10-appA-limit",
        locator="App. A, after (A.18)",
        quantity="if $t < p_d^4$ then $P_D \\to 1$ as $K \\to \\infty$",
        compute=_bound_tends_to_one,
        kind="statement",
        note="$p_d = 0.7$ ($p_d^4 = 0.24$), $t = 0.2$: the bound does not decrease with K and exceeds "
        "$1 - 10^{-12}$ by $K = 10^{6}$.",
        discussed_in=PAGE,
        table="log-domain",
    ),
    Claim.statement(
        id="ATC10-eqA.9-rule-at-design",
        locator="Eqs. (A.9)-(A.10)",
        quantity="the rule as printed in (A.9) meets the bound (A.17) at the $K = 10$, $P_{DL} = 0.999$ "
        "design "
        "point ($t = 0$): it detects with probability at least $P_{DL}$",
        compute=lambda: (
            float(
                jm.empty_list_rule_detection_probability(
                    design_p_d(table21_design(2)[1], table21_design(2)[0]) ** 4, table21_design(2)[0], 0.0
                )
            )
            >= table21_design(2)[1]
        ),
        expected_status="discrepant",
        kind="statement",
        erratum=E_RULE,
        oracle=lambda: ((1 - (1 - 0.999) ** (1 / 10)) ** 0.25) ** 40 >= 0.999,
        oracle_tolerance=EXACT,
        note="Under (A.9) with $t = 0$ every list must be non-empty: probability "
        "$q^K = 9.5 \\times 10^{-4}$ at the "
        "design point, far below 0.999. The bound holds for the rule of (A.11), which is what the paper "
        "uses everywhere else. The design point is Table 2.1's, a test point: (A.9) prints no number.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eqA.15-printed",
        locator="Eq. (A.15)",
        quantity="the right side of (A.15) as printed, $1 \\exp -K(\\ldots)$, is the lower bound on $P_D$ "
        "(the design $P_{DL}$ at Table 2.1's $K = 10$, $P_{DL} = 0.999$ point)",
        compute=lambda: abs(printed_a15_value() - table21_design(2)[1]) <= 1e-9,
        expected_status="discrepant",
        kind="statement",
        erratum=E_A15,
        oracle=lambda: abs(float(stats.binom.pmf(0, 10, 1 - (1 - 0.999) ** (1 / 10))) - 0.999) <= 1e-9,
        oracle_tolerance=EXACT,
        note="Read literally the right side is $\\exp(-K E)$ = 0.001 at the design point, the probability "
        "that all ten lists are empty; with the lost minus, $1 - \\exp(-K E)$ = 0.999 as designed. "
        "(2.4.2), (A.17) and (2.5.12) print the minus.",
        discussed_in=PAGE,
        table="log-domain",
    ),
    Claim.statement(
        id="ATC10-eqC.1-printed",
        locator="Eq. (C.1)",
        quantity="(C.1) as printed equals $F(p_f)$ of (B.6), the factor (2.5.12) uses for $K = 1$",
        compute=lambda: abs(printed_c1_log_ratio(False)) <= 1e-6,
        expected_status="discrepant",
        kind="statement",
        erratum=E_C1,
        oracle=lambda: abs(printed_c1_log_ratio(True)) <= 1e-6,
        oracle_tolerance=EXACT,
        note="Evaluated at the $K = 1$, $P_{DL} = 0.88$ threshold, $p_f \\approx 10^{-6}$: "
        "$(1 - p_f)^{2 \\times 10^7} \\approx e^{-20}$ where $1 - (1 - p_f)^{2 \\times 10^7} \\approx 1$, so "
        "the printed form is $e^{-19.6}$ times $F$ (the check allows $10^{-6}$ in the logarithm, for "
        "rounding only). Checked independently with 40-digit arbitrary-precision arithmetic.",
        discussed_in=PAGE,
    ),
]


PAGE_MC = "atc10/14-monte-carlo"


#: The Table 2.1 row whose threshold p_f the correlated-sample check uses (K = 100, P_DL = 0.999:
#: p_f = 0.197; the K >= 10 thresholds lie at 0.11-0.27); the window is the track window of (C.14),
#: 23.86 samples, rounded.
WINDOW_ROW = 4


def window_pf() -> float:
    """p_f at the N_ADL threshold of Table 2.1's row :data:`WINDOW_ROW` (t = 0)."""
    k, p_dl = table21_design(WINDOW_ROW)
    return math.exp(threshold_log_pf(p_dl, k))


def window_n() -> int:
    """Samples in the track window of (C.14), n_v = (8B/3) v alpha / c, rounded to a whole window."""
    return round(geometry().samples_per_track_window)


#: K and t at which the list count of (B.9) is checked (K from Table 2.1; Kt = 2.5 not an integer).
B9_T = 0.25


#: The list probabilities at which the test of (A.3)-(A.9) is checked: P(rho = 1 | H0), P(rho = 1 | H1).
A_CASES = ((0.05, 0.6), (0.2, 0.3), (0.001, 0.0069), (0.4, 0.99))


def _majority_test() -> bool:
    """(A.6): Lambda_1 = a^K0 b^(K-K0) by enumeration; ln(a/b) > 0, so the test is a threshold on K0."""
    ok = True
    k = int(IN_J.tab21_k10)
    for p0, p1 in A_CASES:
        if not 0 < p0 < p1 < 1:
            raise ValueError(
                f"A_CASES: the test needs 0 < P(rho = 1 | H0) < P(rho = 1 | H1) < 1, got ({p0}, {p1})"
            )
        a, b = (1 - p0) / (1 - p1), p0 / p1
        ok &= a > 1 > b
        for r in itertools.product((0, 1), repeat=k):
            lam = math.prod((p0 if ri else 1 - p0) / (p1 if ri else 1 - p1) for ri in r)
            k0 = r.count(0)
            ok &= math.isclose(lam, a**k0 * b ** (k - k0), rel_tol=1e-12)
        ratios = [a**k0 * b ** (k - k0) for k0 in range(k + 1)]
        ok &= bool(np.all(np.diff(ratios) > 0))
    return bool(ok)


def printed_a7_disagreements(exact: bool) -> float:
    """Number of (lambda_1, K0) cases where the printed (A.7), K0 ln(a/b) <= K ln(lambda_1 b), decides
    otherwise than Lambda_1 <= lambda_1^K (A.4)."""
    k = int(IN_J.tab21_k10)
    p0, p1 = (Fraction(1, 5), Fraction(3, 5)) if exact else (0.2, 0.6)
    a, b = (1 - p0) / (1 - p1), p0 / p1
    count = 0
    for lam1 in (Fraction(1, 2), Fraction(1), Fraction(3)) if exact else (0.5, 1.0, 3.0):
        for k0 in range(k + 1):
            correct = a**k0 * b ** (k - k0) <= lam1**k
            if exact:
                printed_test = (a / b) ** k0 <= (lam1 * b) ** k  # both sides exponentiated, exactly
            else:
                printed_test = k0 * math.log(a / b) <= k * math.log(lam1 * b)
            count += printed_test != correct
    return float(count)


def _chernoff_below_exact() -> bool:
    """(A.11)-(A.17): the Chernoff bound never exceeds the exact binomial P_D of the (A.11) rule."""
    ok = True
    for k in (2, 5, 10, 100, 1000):
        for t in (0.0, 0.05, 0.1, 0.3, 0.6):
            for q in (0.002, 0.05, 0.2, 0.5, 0.9):
                bound = float(jm.detection_lower_bound(q**0.25, k, t))
                exact = float(jm.list_rule_detection_probability(q, k, t))
                ok &= bound <= exact + 1e-12
    return bool(ok)


def _exponent_rises_with_q() -> bool:
    """(A.16): D(t || q) does not decrease in q, so using p_d^4 <= P(rho = 1 | H1) keeps (A.15) a bound."""
    q = np.linspace(0.001, 0.999, 400)
    ok = True
    for t in (0.0, 0.01, 0.1, 0.3, 0.7):
        ok &= bool(np.all(np.diff(np.asarray(jm.list_rule_exponent(t, q), float)) >= -1e-12))
    return bool(ok)


def _any_pd_reachable() -> bool:
    """For each (P_D, K) some p_d < 1 at t = 0 makes (A.17) equal the required P_D."""
    ok = True
    for p_dl in (0.88, 0.98, 0.999):
        for k in (2, 10, 100, 1000):
            p_d = jm.filter_detection_probability_for_bound(p_dl, k, 0.0)
            ok &= 0 < p_d < 1 and math.isclose(
                float(jm.detection_lower_bound(p_d, k, 0.0)), p_dl, rel_tol=1e-9
            )
    return bool(ok)


def _false_alarm_above_bound() -> bool:
    """Seeded list simulation (reduced sizes): false alarms >= F^(Kt+1) (B.11), detections >= P_DL."""
    ok = True
    for r in mc.simulate():
        sig = mc.binomial_sigma(r.false_alarm, r.trials)
        ok &= bool(np.all(r.false_alarm >= r.false_alarm_bound - 3 * sig))
        ok &= bool(np.all(r.detection >= r.detection_bound - 3 * mc.binomial_sigma(r.detection, r.trials)))
    return bool(ok)


def _false_tracks_above_bound() -> bool:
    """Seeded false-track simulation: P(gamma_D = 1) >= F G^(K-1) (C.17) within 3 standard errors."""
    ok = True
    for r in mc.simulate_false_tracks():
        ok &= bool(np.all(r.simulated >= r.bound - 3 * mc.binomial_sigma(r.simulated, r.trials)))
    return bool(ok)


def _window_empty_ratio(rho: float) -> float:
    """P(no declaration in an n-sample window) for neighbours correlated rho, over (1 - p_f)^n."""
    n, pf = window_n(), window_pf()
    cov = np.eye(n) + rho * (np.eye(n, k=1) + np.eye(n, k=-1))
    u = -special.ndtri(pf)
    dist = stats.multivariate_normal(
        mean=np.zeros(n), cov=cov, maxpts=2_000_000, abseps=1e-7, releps=1e-5, seed=19720626
    )
    p_empty = dist.cdf(np.full(n, u))
    return float(p_empty / (1 - pf) ** n)


def window_empty_ratio() -> float:
    return _window_empty_ratio(float(IN_COV.neighbour_correlation))


def b9_real_exponent_bound_holds(n_f: int = 99) -> bool:
    """(B.10)-(B.11) with a real exponent: F^(Kt+1) <= P(at least floor(Kt)+1 of K lists non-empty),
    K = 10 (Table 2.1), t = 0.25, over a grid of list probabilities F in (0, 1)."""
    k = int(IN_J.tab21_k10)
    # fewest non-empty lists among K for which the rule 'more than Kt non-empty' decides H1 (enumeration)
    need = min(sum(r) for r in itertools.product((0, 1), repeat=k) if sum(r) > k * B9_T)
    f = np.linspace(0.0, 1.0, n_f + 2)[1:-1]  # n_f points strictly inside (0, 1)
    exact = stats.binom.sf(need - 1, k, f)
    return bool(need == math.floor(k * B9_T) + 1 and np.all(f ** (k * B9_T + 1) <= exact + 1e-15))


def _track_time_ratio() -> float:
    """|T_1(1) - T_2(1)| over the printed bound v alpha / c (aircraft flying at v toward a satellite)."""
    alpha = float(IN_J.repetition_s)
    v = float(IN_J.max_speed_mph) * units.MPH
    r0 = 36_000e3  # range to a synchronous satellite, m
    t_tx = 0.3
    first = t_tx + r0 / units.C
    second = t_tx + alpha + (r0 - v * alpha) / units.C
    return abs(first - second) / (v * alpha / units.C)


def _oracle_track_time_ratio() -> float:
    """The period term alone: alpha / (v alpha / c) = c / v (the range change adds at most 1)."""
    return units.C / (float(IN_J.max_speed_mph) * units.MPH)


def _track_window_holds() -> bool:
    """(C.5): random straight flights at speed <= v and static satellites never move d_1 by more
    than 2 v alpha / c between pulses; Definition C.1's (2/3) v alpha / c window is inside it."""
    rng = np.random.default_rng(19720625)
    alpha = float(IN_J.repetition_s)
    v = float(IN_J.max_speed_mph) * units.MPH
    n = 20000
    sats = rng.normal(size=(n, 2, 3))
    sats *= (42_000e3 / np.linalg.norm(sats, axis=2))[..., None]
    pos = rng.normal(scale=1e6, size=(n, 3))
    step = rng.normal(size=(n, 3))
    step *= (rng.uniform(0, v * alpha, n) / np.linalg.norm(step, axis=1))[:, None]
    r_before = np.linalg.norm(sats - pos[:, None, :], axis=2) / units.C
    r_after = np.linalg.norm(sats - (pos + step)[:, None, :], axis=2) / units.C
    d_change = np.abs((r_before[:, 0] - r_before[:, 1]) - (r_after[:, 0] - r_after[:, 1]))
    bound = 2 * v * alpha / units.C
    return bool(np.all(d_change <= bound * (1 + 1e-9)) and (2 / 3) * v * alpha / units.C < bound)


def _appendix_d_algebra() -> bool:
    """(D.7)-(D.17) with sympy: the LR threshold, p_f (D.9), p_d (D.13), and (D.16) after (D.15)."""
    y, e, n0, lam = sp.symbols("y E N lambda", positive=True)  # n0 = J/B
    log_lr = sp.expand(
        sp.log(sp.exp(-(y**2) / (2 * n0))) - sp.log(sp.exp(-((y - sp.sqrt(e)) ** 2) / (2 * n0)))
    )
    y_th = sp.solve(sp.Eq(sp.expand_log(log_lr, force=True), sp.log(lam)), y)[0]
    ok = sp.simplify(y_th - (sp.sqrt(e) / 2 - n0 * sp.log(lam) / sp.sqrt(e))) == 0
    s = sp.sqrt(e / (2 * n0))
    pf_d9 = sp.Rational(1, 2) - sp.erf(s / 2 - sp.sqrt(n0 / (2 * e)) * sp.log(lam)) / 2
    pf_direct = sp.erfc(y_th / sp.sqrt(2 * n0)) / 2
    pd_d13 = sp.Rational(1, 2) + sp.erf(s / 2 + sp.sqrt(n0 / (2 * e)) * sp.log(lam)) / 2
    pd_direct = sp.erfc((y_th - sp.sqrt(e)) / sp.sqrt(2 * n0)) / 2
    phi = s / 2 + sp.sqrt(n0 / (2 * e)) * sp.log(lam)  # (D.15)
    pf_d16 = sp.Rational(1, 2) - sp.erf(s - phi) / 2
    rng = np.random.default_rng(7)
    for _ in range(20):
        vals = {
            e: float(rng.uniform(0.1, 10)),
            n0: float(rng.uniform(0.1, 10)),
            lam: float(rng.uniform(0.05, 20)),
        }
        for lhs, rhs in ((pf_d9, pf_direct), (pd_d13, pd_direct), (pf_d16, pf_d9)):
            ok &= abs(float(lhs.subs(vals)) - float(rhs.subs(vals))) < 1e-12
    return bool(ok)


def _d17_matches_direct() -> bool:
    """(D.17)/(2.7.1) against the Gaussian tails with the paper's E and B, and its limits in J."""
    energy, bandwidth = float(IN_J.pulse_energy_j), float(IN_J.bandwidth_hz)
    ok = True
    for p_d in (0.3, 0.66, 0.9685, 0.9997):
        for x_db in (-20.0, -16.0, -10.0, 0.0, 10.0):
            jam = 10 ** (x_db / 10) * energy * bandwidth
            sigma = math.sqrt(jam / bandwidth)
            y_th = stats.norm.isf(p_d, loc=math.sqrt(energy), scale=sigma)
            direct = stats.norm.sf(y_th, scale=sigma)
            model = float(false_alarm_probability(p_d, detection_index_from_jammer_ratio(10 ** (x_db / 10))))
            ok &= math.isclose(model, direct, rel_tol=1e-9)
        low = float(false_alarm_probability(p_d, detection_index_from_jammer_ratio(1e-6)))
        high = float(false_alarm_probability(p_d, detection_index_from_jammer_ratio(1e12)))
        ok &= low < 1e-100 and math.isclose(high, p_d, rel_tol=1e-5)
    return bool(ok)


CLAIMS += [
    Claim.statement(
        id="ATC10-eqA.6-majority-test",
        locator="Eqs. (A.3)-(A.9), App. A",
        quantity="$\\Lambda_1 = a^{K_0} b^{K-K_0}$; the coefficient of (A.7) is positive, so the "
        "Neyman-Pearson test on the list indicators is a threshold on the number of empty lists",
        compute=_majority_test,
        note="All $2^{10}$ indicator vectors ($K = 10$ from Table 2.1) for four ($P(\\rho=1|H_0)$, "
        "$P(\\rho=1|H_1)$) "
        "pairs: the "
        "ratio depends on $K_0$ only, equals $a^{K_0} b^{K-K_0}$ and increases strictly with $K_0$ "
        "($a > 1 > b$).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eqA.7-printed",
        locator="Eq. (A.7)",
        quantity="(A.7) as printed decides as the test (A.4) it rewrites, for every ($\\lambda_1$, $K_0$)",
        kind="statement",
        compute=lambda: printed_a7_disagreements(False) == 0,
        expected_status="discrepant",
        erratum="ATC10-E-jam-A7-ratio",
        oracle=lambda: printed_a7_disagreements(True) == 0,
        oracle_tolerance=EXACT,
        note="$K = 10$, $P(\\rho=1|H_0) = 0.2$, $P(\\rho=1|H_1) = 0.6$, $\\lambda_1$ in {0.5, 1, 3}, $K_0$ "
        "= 0-10: the printed right side $K \\ln(\\lambda_1 b)$ decides otherwise in 20 of the 33 cases; "
        "$K \\ln(\\lambda_1 / b)$, $b = P(\\rho=1|H_0)/P(\\rho=1|H_1)$, in none. $\\lambda_1$ is free, so "
        "no printed number depends on it. Checked independently with exact rational arithmetic.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eqA.13-chernoff-below-exact",
        locator="Eqs. (A.11)-(A.17)",
        quantity="the Chernoff bound (A.17) never exceeds the exact detection probability of the rule of "
        "(A.11)",
        compute=_chernoff_below_exact,
        note="K in {2, 5, 10, 100, 1000}, t in {0, 0.05, 0.1, 0.3, 0.6}, $q = p_d^4$ in {0.002, ..., 0.9}: "
        "bound $\\le$ exact binomial P(more than Kt lists non-empty).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eqA.16-bound-stays-valid",
        locator="Eq. (A.16)",
        quantity="when $P(\\rho = 1 | H_1) \\approx p_d^4$ is not exact the lower bound stays true",
        compute=_exponent_rises_with_q,
        note="$P(\\rho=1|H_1) \\ge p_d^4$ and the exponent $\\max_\\nu[\\nu(1-t) - \\ln((1-q)e^\\nu + q)]$ "
        "does not decrease in q (checked on a 400-point grid for five t), so the smaller q can only lower "
        "the bound.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-appA-any-pd-reachable",
        locator="App. A, after (A.18)",
        quantity="for given $P_D$ and K, (A.17) can be made to hold by taking t small and $p_d$ large",
        compute=_any_pd_reachable,
        note="At $t = 0$ the design $p_d = [1 - (1 - P_D)^{1/K}]^{1/4} < 1$ makes the bound equal $P_D$, for "
        "$P_D$ in "
        "{0.88, 0.98, 0.999} and K in {2, 10, 100, 1000}.",
        discussed_in=PAGE,
        table="appendix-steps",
    ),
    Claim.statement(
        id="ATC10-eqB.11-monte-carlo",
        locator="Eqs. (B.1)-(B.11), (2.5.4), (2.4.2)",
        quantity="the simulated first-stage false-alarm rate is at least $F^{Kt+1}$ and the detection rate "
        "at least $P_{DL}$",
        compute=_false_alarm_above_bound,
        note="Seeded simulation of matched-filter samples, lists and the $K$-list rule at reduced sizes "
        f"({mc.N_A} filter-1 samples, windows of $\\pm {mc.HALF_WINDOW}$, {mc.TRIALS} trials; cases "
        "($K$, $t$, $P_{DL}$) = (1, 0, 0.9), (3, 0, 0.9), (3, 1/3, 0.9)), $J/(P_0 B \\tau)$ from -14 to "
        "-7 dB: every rate at or above its bound within 3 binomial standard errors.",
        discussed_in=PAGE_MC,
    ),
    Claim.statement(
        id="ATC10-eqC.17-monte-carlo",
        locator="Eqs. (C.10)-(C.17), (2.5.11)",
        quantity="the simulated probability of a noise-only track over K segments is at least $F G^{K-1}$",
        compute=_false_tracks_above_bound,
        note=f"Seeded false-track simulation (exact existence search, {mc.TRACK_TRIALS} trials, $K$ = 1-3, "
        "$p_f$ 0.02-0.3, reduced windows): every rate at or above the bound within 3 binomial standard "
        "errors.",
        discussed_in=PAGE_MC,
    ),
    Claim.statement(
        id="ATC10-eqB.9-lists-needed",
        locator="Eqs. (B.9)-(B.11), (2.5.4)",
        quantity="with a non-integer $Kt$ the bound $F^{Kt+1}$ of (B.10)-(B.11) still bounds the false-alarm "
        "probability of the rule 'more than Kt lists non-empty' from below",
        kind="statement",
        compute=b9_real_exponent_bound_holds,
        note="K = 10, t = 0.25: the rule needs $\\lfloor Kt \\rfloor + 1 = 3$ non-empty lists (enumeration "
        "of the $2^{10}$ list patterns), which is what the intersection of (B.9) over $j \\le Kt + 1$ "
        "takes; the exact probability of at least 3 non-empty lists exceeds $F^{3.5}$ (and $F^3$) for every "
        "list probability F, since $F \\le 1$. The real exponent gives a valid, slightly looser bound; "
        "for an integer Kt the two coincide.",
        discussed_in=PAGE,
        table="appendix-steps",
    ),
    Claim.statement(
        id="ATC10-eqB.6-correlated-samples",
        locator="Eqs. (B.6), (C.14); Sec. 2.3",
        quantity="(B.6)'s product gives the probability that a window of samples taken at twice the Nyquist "
        "rate holds no declaration (the 24-sample track window at the $K = 100$, $P_{DL} = 0.999$ "
        "threshold, $p_f = 0.20$)",
        kind="statement",
        compute=lambda: abs(window_empty_ratio() - 1.0) <= 1e-3,
        expected_status="inconsistent",
        note="Neighbouring samples correlated, farther ones not (assumed 0.3-0.5; Genz integration of the "
        "24-dimensional Gaussian orthant, $10^{-3}$ allowing for its error): correlated samples leave a "
        "window "
        "empty 2.3-4.1 times more often than the product assumes (Slepian's inequality), so $F$ and $G$, "
        "and the bounds built on them, are approximations. The product misses across the whole assumed "
        "range of the correlation, hence the verdict; yet it is a caveat, not a finding (no erratum): its "
        "size needs the signature's spectrum, which the paper does not give, and read with $B$ a one-sided "
        "baseband bandwidth the samples are independent for a flat spectrum. A seeded simulation of one "
        "24-sample window with neighbour correlation 1/2 shows the same (section 'Correlated samples in one "
        "window' of the page on the bounds against a simulated detector).",
        discussed_in=PAGE_MC,
    ),
    Claim.statement(
        id="ATC10-eqC.2-printed",
        locator="Eqs. (C.2)-(C.5)",
        quantity="the printed step $|T_1(1) - T_2(1)| \\le v \\alpha / c$ holds for the reception times it "
        "names",
        kind="statement",
        compute=lambda: _track_time_ratio() <= 1.0,
        expected_status="discrepant",
        erratum="ATC10-E-jam-C2-track-window",
        oracle=lambda: _oracle_track_time_ratio() - 1.0 <= 1.0,
        oracle_tolerance=EXACT,
        note="An aircraft at $v = 600$ mph flying toward a synchronous satellite: successive receptions are "
        "$\\alpha$ plus the range change apart, about $c/v = 1.1 \\times 10^{6}$ times the printed bound. "
        "Only the range "
        "change is bounded by $v \\alpha / c$; the $\\alpha$'s cancel in (C.2)'s difference of differences, "
        "and (C.5)-(C.6) and $n_v$ follow the correct form.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eqC.5-track-window",
        locator="Eqs. (C.5)-(C.6), Definition C.1",
        quantity="between successive pulses a time difference moves by at most $2 v \\alpha / c$, and "
        "Definition C.1's $(2/3) v \\alpha / c$ is more stringent",
        compute=_track_window_holds,
        note="20000 seeded straight flights of at most $v \\alpha$ with random directions and static "
        "satellites at 42000 km: the change of $T(1) - T(2)$ never exceeds $2 v \\alpha / c$ (the "
        "transmission periods cancel).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eqD-derivation",
        locator="Eqs. (D.7)-(D.16)",
        quantity="the Gaussian densities (D.7)-(D.8) give the threshold, $p_f$ (D.9), $p_d$ (D.13) and, "
        "with (D.15), $p_f$ (D.16)",
        compute=_appendix_d_algebra,
        note="sympy solves the log-likelihood-ratio threshold exactly; (D.9), (D.13) and (D.16) are compared "
        "with the Gaussian tails at 20 random (E, J/B, $\\lambda$) points to $10^{-12}$.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eqD.17-direct",
        locator="Eqs. (D.17), (2.7.1)",
        quantity="$p_f = \\frac{1}{2} - \\frac{1}{2} \\operatorname{erf}(\\sqrt{P_0 B \\tau / (2 J)} - "
        "\\phi)$, with $p_f \\to 0$ as $J \\to 0$ and $p_f \\to p_d$ as $J \\to \\infty$",
        compute=_d17_matches_direct,
        note="The book's $p_f$ against the threshold set from $p_d$ and the noise-only Gaussian tail of a "
        "standard library, with $E$ = 10 mJ and $B$ = 10 MHz, at four $p_d$ and five $J$, to $10^{-9}$ "
        "relative; and the two limits.",
        discussed_in=PAGE,
    ),
]

#: Every claim quotes the paper (issue 27, item 5).
CLAIMS = with_quotes(CLAIMS, QUOTES)
