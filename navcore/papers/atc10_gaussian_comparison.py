"""ATC-10 Sec. 3.8: the Gaussian approximation compared with the multiple-access noise.

Eqs. (3.8.1)-(3.8.16), Figs. 3.9-3.10 and the worked example. Inputs are read from
:mod:`navcore.papers.atc10_multiple_access`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp
from scipy import integrate, special, stats

from navcore.claims import EXACT, Claim, Erratum, Tolerance, printed, prose, with_quotes
from navcore.claims.inputs import input_cache
from navcore.detection.multiple_access import (
    MultipleAccessNoise,
    gaussian_mixture_exact_tail,
    stratified_tail,
    triangular_exact_tail,
    two_point_exact_tail,
    uniform_exact_tail,
)
from navcore.detection.roc_bounds import (
    best_pf_at_pd,
    exponent_from_gaussian_exponent,
    gaussian_roc,
    quasi_optimal_exponent,
)
from navcore.papers.atc10_multiple_access import (
    CHECK_CONTOURS,
    DENSITY_NAMES,
    G_,
    IN,
    IN_COV,
    MA,
    PAGE_GAUSS,
    b_of_contour,
    gaussian_best_pf,
    psk_density,
    psk_physical_samples,
    worked_example_exp_g,
    worked_example_power,
)
from navcore.papers.atc10_quotes import QUOTES
from navcore.papers.atc10_roc_bounds import THETAS, contours

CLAIMS: list[Claim] = []
ERRATA: list[Erratum] = []


#: Printed results of the worked example (the claims compare with them).
P_EXAMPLE_PRINTED = "50"


EXP_G_EXAMPLE_PRINTED = "12.5"


EXP_EXAMPLE_PRINTED = "9"


RATIO_EXAMPLE_PRINTED = "1.4"


THETA_EDGE = 0.02


THETA_GRID = np.linspace(THETA_EDGE, 1.0 - THETA_EDGE, 193)


#: Samples per stratum (number K of overlapping interferers) of the stratified Monte Carlo of
#: the PSK simulation.
MC_PER_STRATUM = 20_000


@dataclass(frozen=True)
class ExactROC:
    """p_f and 1 - p_d on THETA_GRID, with Monte Carlo standard errors (zero where exact)."""

    theta: np.ndarray
    p_f: np.ndarray
    p_f_se: np.ndarray
    p_miss: np.ndarray
    p_miss_se: np.ndarray
    method: str


@input_cache
def exact_roc(name: str, x: float) -> ExactROC:
    """The actual ROC at the Sec. 3.6 parameters, exact for every density.

    Conditional on the number K of overlapping interferers the noise is a sum of K amplitudes:
    a compound binomial for the two-point density, a Gaussian for the Gaussian one, an
    Irwin-Hall law (rescaled) for the uniform one and one of 2K summands for the triangular one
    (each triangular amplitude the sum of two uniforms); the binomial weights of K are exact.
    p_f = P(n >= theta) and, the noise being symmetric, 1 - p_d = P(n < theta - 1) =
    P(n >= 1 - theta).
    """
    b = b_of_contour(x)
    th = THETA_GRID
    nint, q = IN.n_sec36 - 1, 2 * IN.tau_over_alpha_sec36
    z = np.zeros_like(th)
    if name == "C2 two-point":
        pf = two_point_exact_tail(np.sqrt(b), nint, q, th)
        pm = 1.0 - two_point_exact_tail(np.sqrt(b), nint, q, th - 1.0)  # P(n < theta - 1)
        return ExactROC(th, pf, z, pm, z, "exact binomial sums")
    tail, method = {
        "C1 uniform": (uniform_exact_tail, "exact Irwin-Hall mixture"),
        "C3 triangular": (triangular_exact_tail, "exact Irwin-Hall mixture"),
        "C4 Gaussian": (gaussian_mixture_exact_tail, "exact Gaussian mixture"),
    }[name]
    return ExactROC(th, tail(b, nint, q, th), z, tail(b, nint, q, 1.0 - th), z, method)


@input_cache
def gaussian_comparison_table() -> dict[tuple[str, float, float], tuple[float, float]]:
    """(density, x, pd_min) -> (actual best p_f, ROC_g p_f)."""
    out = {}
    for x in contours():
        for pd_min in (float(IN.comparison_pd), 0.99):
            g = gaussian_best_pf(x, pd_min)
            for name in DENSITY_NAMES:
                r = exact_roc(name, x)
                out[(name, x, pd_min)] = (best_pf_at_pd(r.p_f, r.p_miss, pd_min), g)
    return out


def gaussian_always_more_optimistic() -> bool:
    """Sec. 3.8 conclusion, from the actual ROC: ROC_g p_f below the actual p_f at every point."""
    return all(act > g for act, g in gaussian_comparison_table().values())


def gaussian_smallest_pf_ratio() -> float:
    """Smallest ratio actual best p_f / ROC_g p_f over densities, contours and p_d = 0.9, 0.99.

    The Sec. 3.8 conclusion 'ROC_g p_f always lower than the actual p_f' is this ratio > 1.
    """
    return float(min(act / g for act, g in gaussian_comparison_table().values()))


def worked_example_power_oracle() -> float:
    """Exact rational arithmetic of the same definition, as an independent check."""
    return float(
        Fraction(IN.n_effective_example - 1)
        / (Fraction(IN.bandwidth_example_hz) * Fraction(IN.alpha_example_s))
    )


def worked_example_exp() -> float:
    """Exp(N = 2e5, tau/alpha = 1e-5, Exp_g) from Eq. (3.8.16)."""
    return float(
        exponent_from_gaussian_exponent(
            IN.n_effective_example, IN.tau_over_alpha_fig310, worked_example_exp_g()
        )
    )


def worked_example_ratio() -> float:
    return worked_example_exp_g() / worked_example_exp()


def exp_monotone_in_n_below_exp_g() -> bool:
    """Figs. 3.9/3.10: Exp increases with N and stays below Exp_g, approaching it."""
    n = np.logspace(2, 9, 400)[:, None]
    g = np.array([0.5, 1, 2, 4, 8, 12.5, 20])[None, :]
    ok = True
    for r in (1e-6, 1e-5, 1e-4):
        e = exponent_from_gaussian_exponent(n, r, g)
        # increases, stays below Exp_g; that the gap closes is (3.8.15), ATC10-sec3.8-exp-limit
        ok &= bool(np.all(np.diff(e, axis=0) > 0) and np.all(e <= g + 1e-9))
    return ok


def exp_rate_faster_for_low_exp_g() -> bool:
    """Fig. 3.10: Exp/Exp_g is larger (closer to 1) for smaller Exp_g at every N."""
    g = np.linspace(0.5, 20, 40)
    for n in (1e4, 1e5, 2e5, 1e6, 1e7):
        ratio = exponent_from_gaussian_exponent(n, IN.tau_over_alpha_fig310, g) / g
        if np.any(np.diff(ratio) >= 0):
            return False
    return True


def exp_linearity_r2(n: float = 1e5) -> float:
    """R^2 of a straight-line fit of Exp against Exp_g on [0, 20] (Fig. 3.10 'practically linear')."""
    g = np.linspace(0.0, 20.0, 81)
    e = exponent_from_gaussian_exponent(n, IN.tau_over_alpha_fig310, np.maximum(g, 1e-12))
    coef = np.polyfit(g, e, 1)
    res = e - np.polyval(coef, g)
    return float(1 - res.var() / e.var())


def exp_fig39_shortfall() -> float:
    """Relative shortfall 1 - Exp/Exp_g at N = 1e5, tau/alpha = 1e-5, Exp_g = 4."""
    g = IN.exp_g_fig39
    return float(1 - exponent_from_gaussian_exponent(IN.n_fig39, IN.tau_over_alpha_fig39, g) / g)


def psk_contour() -> float:
    """1/sqrt(3b) of the simulated PSK amplitude density (about sqrt(2L))."""
    return float(1.0 / np.sqrt(3.0 * np.mean(psk_physical_samples() ** 2)))


@input_cache
def psk_roc() -> ExactROC:
    """Actual ROC of a matched filter in PSK multiple-access noise (N = 1e5, tau/alpha = 2e-5).

    Stratified Monte Carlo over the number of overlapping interferers, each drawn from the
    simulated n_ij (independent interferers make this exact up to sampling error).
    """
    noise = MultipleAccessNoise(IN.n_sec36, IN.tau_over_alpha_sec36, psk_density())
    th = THETA_GRID
    est = stratified_tail(noise, np.concatenate([th, th - 1.0]), MC_PER_STRATUM, np.random.default_rng(77))
    k = th.size
    return ExactROC(
        th,
        est.upper[:k],
        est.upper_se[:k],
        1.0 - est.upper[k:],
        est.upper_se[k:],
        "stratified Monte Carlo of the physical PSK simulation",
    )


def psk_gaussian_optimistic() -> bool:
    """At p_d >= 0.9 ROC_g (same power) promises a lower p_f than the simulated PSK ROC."""
    r = psk_roc()
    x = psk_contour()
    return best_pf_at_pd(r.p_f, r.p_miss, 0.9) > gaussian_best_pf(x, 0.9)


ERRATA += [
    Erratum(
        id="ATC10-E3-2",
        kind="typography",
        basis="text-only",
        locator="Sec. 3.8, worked example",
        printed="$p = 50$",
        finding="$p = (N-1)/(B \\alpha) = (2 \\times 10^{5} - 1)/(10^{7}\\,\\mathrm{Hz} \\times "
        "1\\,\\mathrm{s})$ $= 0.02 = 1/50$.",
        evidence="Direct arithmetic; the printed $\\mathrm{Exp}_g = 12.5 = 0.25/p$ follows $p = 1/50$, so no "
        "printed number depends on the slip.",
        claims=("ATC10-sec3.8-example-p",),
        discussed_in=PAGE_GAUSS,
    ),
    Erratum(
        id="ATC10-E3-4",
        kind="derivation",
        basis="text-only",
        locator="Eqs. (3.8.5)-(3.8.7)",
        printed="$E e^{\\mu n} = \\exp(\\mu^2/2)$; $p_f \\le \\exp(-\\mu\\theta - \\mu^2/2)$",
        finding="$E e^{\\mu n} = \\exp(\\mu^2 p/2)$ and $p_f \\le \\exp(-\\mu\\theta + \\mu^2 p/2)$; the "
        "optimum "
        "$\\mu = \\theta/p$ and the final bound $\\exp(-\\theta^2/(2p))$ are right.",
        evidence="sympy integration of the Gaussian MGF on the page.",
        discussed_in=PAGE_GAUSS,
        claims=("ATC10-eq3.8.6-printed",),
    ),
]


_p_example, _p_tol = printed(P_EXAMPLE_PRINTED)


_expg, _expg_tol = printed(EXP_G_EXAMPLE_PRINTED)


_exp, _exp_tol = printed(EXP_EXAMPLE_PRINTED)


_ratio, _ratio_tol = printed(RATIO_EXAMPLE_PRINTED)


CLAIMS += [
    Claim.statement(
        id="ATC10-sec3.8-gauss-always-optimistic",
        locator="Sec. 3.8, comparison of Figs. 3.3-3.6 with Fig. 3.8",
        quantity="the $p_f$ of $\\mathrm{ROC}_g$ is always lower than the actual $p_f$ ($N = 10^{5}$, "
        "$\\tau/\\alpha = 2 \\times 10^{-5}$, $C_1$ to $C_4$, $p_d = 0.9$ and 0.99, at the figures' "
        "contours)",
        kind="statement",
        compute=gaussian_always_more_optimistic,
        expected_status="not-reproducible",
        note="Actual ROCs computed exactly (binomial mixtures of two-point, Irwin-Hall and Gaussian sums): "
        "the smallest ratio "
        "of the actual best $p_f$ to the $\\mathrm{ROC}_g$ one is 0.87-1.13 over the assumed lowest "
        "contour. $\\mathrm{ROC}_g$ is more optimistic at high SNR but not at $1/\\sqrt{3b}$ = 3, where "
        "the continuous densities beat it (confirmed by the exact Gaussian-C mixture). The contour labels "
        "are lost: if the figures' lowest contour was 4 or more, the statement holds for them. The paper's "
        "evidence (the lower bound) is invalid (E3-1).",
        erratum="ATC10-E3-1",
        discussed_in=PAGE_GAUSS,
    ),
    Claim.statement(
        id="ATC10-sec3.8-exp-below-exp-g",
        locator="Sec. 3.8, Figs. 3.9-3.10",
        quantity="Exp increases monotonically with N and approaches $\\mathrm{Exp}_g$ from below",
        compute=exp_monotone_in_n_below_exp_g,
        note="Eq. (3.8.16) on $N = 10^{2}$ to $10^{9}$ (400 points), $\\tau/\\alpha = 10^{-6}$, $10^{-5}$, "
        "$10^{-4}$, seven "
        "$\\mathrm{Exp}_g$ values.",
        discussed_in=PAGE_GAUSS,
    ),
    Claim.statement(
        id="ATC10-fig3.9-shortfall",
        locator="Sec. 3.8, Fig. 3.9",
        quantity="at $N = 10^{5}$, $\\tau/\\alpha = 10^{-5}$, Exp is below $\\mathrm{Exp}_g = 4$ by a "
        "non-negligible amount",
        compute=lambda: exp_fig39_shortfall() > IN.non_negligible_fraction,
        expected_status="not-reproducible",
        note="Exp = 3.30 against 4, a shortfall of 17 %. The assumed reading of 'non-negligible' spans "
        "5-20 % of $\\mathrm{Exp}_g$: the statement holds for every reading up to the shortfall and fails "
        "only if 'non-negligible' means more than that.",
        discussed_in=PAGE_GAUSS,
    ),
    Claim(
        id="ATC10-fig3.9-exp-below",
        locator="Sec. 3.8, Fig. 3.9",
        quantity="Exp at $N = 10^{5}$, $\\tau/\\alpha = 10^{-5}$ is less than $\\mathrm{Exp}_g = 4$",
        published=float(IN.nominal("exp_g_fig39")),
        relation="<",
        unit="",
        kind="statement",
        compute=lambda: float(
            exponent_from_gaussian_exponent(IN.n_fig39, IN.tau_over_alpha_fig39, IN.exp_g_fig39)
        ),
        tolerance=EXACT,
        expected_status="reproduced",
        note="Eq. (3.8.16) gives Exp = 3.30, less than the printed $\\mathrm{Exp}_g = 4$; the row's "
        "published value is that 4, with the text's 'less than' as the relation. Whether the shortfall is "
        "non-negligible is a separate claim.",
        discussed_in=PAGE_GAUSS,
    ),
    Claim.statement(
        id="ATC10-fig3.10-rate",
        locator="Sec. 3.8, Fig. 3.10",
        quantity="the approach of Exp to $\\mathrm{Exp}_g$ is more rapid for lower $\\mathrm{Exp}_g$",
        compute=exp_rate_faster_for_low_exp_g,
        note="$\\mathrm{Exp}/\\mathrm{Exp}_g$ decreases with $\\mathrm{Exp}_g$ at $N = 10^{4}$, $10^{5}$, "
        "$2 \\times 10^{5}$, $10^{6}$, "
        "$10^{7}$ "
        "($\\tau/\\alpha = 10^{-5}$).",
        discussed_in=PAGE_GAUSS,
        table="exp-vs-expg",
    ),
    Claim.statement(
        id="ATC10-fig3.10-linear",
        locator="Sec. 3.8, Fig. 3.10",
        quantity="Exp is practically linear in $\\mathrm{Exp}_g$ ($R^2$ of a line fit on [0, 20], "
        "$N = 10^{5}$)",
        compute=lambda: exp_linearity_r2() >= IN.practically_linear_r2,
        expected_status="not-reproducible",
        note="$R^2$ of a least-squares line against the assumed reading of 'practically linear' ($R^2$ of "
        "0.95-0.999); the curve is visibly concave for $N \\le 2 \\times 10^{5}$ and straighter for "
        "$N \\ge 10^{6}$.",
        discussed_in=PAGE_GAUSS,
        table="exp-vs-expg",
    ),
    Claim(
        id="ATC10-sec3.8-example-p",
        locator="Sec. 3.8, worked example",
        quantity="average multiple-access noise power $p = (N-1)/(B \\alpha)$ under Ref. [1]'s assumption",
        published=_p_example,
        unit="(unit-energy signal)",
        compute=worked_example_power,
        tolerance=_p_tol,
        expected_status="discrepant",
        note="$N = 2 \\times 10^{5}$, $B = 10^{7}$ Hz, $\\alpha = 1$ s give $p = 0.02 = 1/50$.",
        erratum="ATC10-E3-2",
        oracle=worked_example_power_oracle,
        oracle_tolerance=Tolerance(
            reason="float against exact rational arithmetic", rel=1e-12, policy="exact"
        ),
        discussed_in=PAGE_GAUSS,
        table="worked-example",
    ),
    Claim(
        id="ATC10-sec3.8-example-expg",
        locator="Sec. 3.8, worked example",
        quantity="Gaussian exponent $\\mathrm{Exp}_g = a^2/p$ at $\\theta$ = 0.5",
        published=_expg,
        unit="",
        compute=worked_example_exp_g,
        tolerance=_expg_tol,
        expected_status="reproduced",
        note="With $p$ = 1/50 (E3-2), read as the one-sided density $N_0$ of an in-band white noise: the "
        "matched-filter output variance is $N_0/2$, so (3.8.8) gives $a^2/(2 \\cdot N_0/2) = a^2/p$ = 12.5, "
        "as the example writes it. Read as the output variance, (3.8.8)'s $a^2/(2p)$ gives 6.25.",
        discussed_in=PAGE_GAUSS,
        table="worked-example",
    ),
    Claim(
        id="ATC10-sec3.8-example-exp",
        locator="Sec. 3.8, worked example (Fig. 3.10)",
        quantity="Exp at $N = 2 \\times 10^{5}$, $\\tau/\\alpha = 10^{-5}$, $\\mathrm{Exp}_g = 12.5$",
        published=_exp,
        unit="",
        compute=worked_example_exp,
        tolerance=prose("≈", why="'Exp ≈ 9', read off Fig. 3.10"),
        expected_status="reproduced",
        note="Eq. (3.8.16) gives 9.70, within the prose band of '≈' (8.1-9.9); $N = 10^{5}$ would give 8.62.",
        discussed_in=PAGE_GAUSS,
        table="worked-example",
    ),
    Claim(
        id="ATC10-sec3.8-example-ratio",
        locator="Sec. 3.8, worked example",
        quantity="ratio $\\mathrm{Exp}_g/\\mathrm{Exp}$ in the worked example",
        published=_ratio,
        unit="",
        compute=worked_example_ratio,
        tolerance=prose("approximately", why="'approximately 1.4'"),
        expected_status="reproduced",
        note="12.5/9.70 = 1.29, within the prose band of 'approximately' (1.26-1.54); the paper's own "
        "12.5/9 = 1.39.",
        discussed_in=PAGE_GAUSS,
        table="worked-example",
    ),
    Claim.statement(
        id="ATC10-sec3.8-example-optimistic",
        locator="Sec. 3.8, worked example",
        quantity="the Gaussian assumption of Ref. [1] is optimistic ($\\mathrm{Exp}_g > \\mathrm{Exp}$)",
        compute=lambda: worked_example_ratio() > 1.0,
        note="$\\mathrm{Exp}_g/\\mathrm{Exp}$ = 1.29 > 1 for the exponent of the bound; 'much more "
        "optimistic' is "
        "a judgement.",
        discussed_in=PAGE_GAUSS,
        table="worked-example",
    ),
    Claim.statement(
        id="ATC10-sec3.1.3B-psk",
        locator="Sec. 3.1.3 B (and Sec. 1.2)",
        quantity="in PSK multiple-access noise the ROC is less preferable than with Gaussian noise "
        "of equal power",
        compute=psk_gaussian_optimistic,
        expected_status="consistent",
        note="The book's signature set: random PSK codes of $L$ chips (assumed 16-64; $1/\\sqrt{3b}$ about 8 "
        "at $L = 32$) at $N = 10^{5}$, $\\tau/\\alpha = 2 \\times 10^{-5}$. The best $p_f$ at "
        "$p_d \\ge 0.9$ from the stratified Monte Carlo is set against that of $\\mathrm{ROC}_g$ at the "
        "same power; the page comparing the Gaussian approximation gives both, the first with its "
        "standard error.",
        discussed_in=PAGE_GAUSS,
    ),
]


def _pd_printed(theta: np.ndarray, p: float) -> np.ndarray:
    """The p_d line printed after 'no uniform signature set ... more preferable than'."""
    return 0.5 + 0.5 * special.erf(theta * np.sqrt(1.0 / (2.0 * p)))


def _sec38_powers() -> list[float]:
    """Multiple-access noise powers 2 (N - 1) (tau/alpha) b of the check contours (Sec. 3.6 N and
    tau/alpha, published)."""
    return [2.0 * (MA.n_sec36 - 1) * MA.tau_over_alpha_sec36 * b_of_contour(x) for x in CHECK_CONTOURS]


def pd_line_is_roc_g() -> bool:
    """The printed p_d line equals the p_d of ROC_g, Eq. (3.8.4) (library: 1 - Q((1 - theta)/sqrt(p))),
    at every check power and every threshold theta != 1/2 of a 0.05-0.95 grid."""
    th = np.r_[np.linspace(0.05, 0.45, 9), np.linspace(0.55, 0.95, 9)]
    for p in _sec38_powers():
        _, lmiss = gaussian_roc(th, p)
        if np.any(np.abs(_pd_printed(th, p) - (1.0 - np.exp(lmiss))) > 1e-9):
            return False
    return True


def pd_line_oracle() -> bool:
    """Oracle: scipy.stats.norm for ROC_g's p_d, Phi((1 - theta)/sqrt(p)), against the printed line."""
    th = np.r_[np.linspace(0.05, 0.45, 9), np.linspace(0.55, 0.95, 9)]
    return all(
        bool(np.all(np.abs(_pd_printed(th, p) - stats.norm.cdf((1.0 - th) / np.sqrt(p))) <= 1e-9))
        for p in _sec38_powers()
    )


def tail_ratio() -> float:
    """P(n > k sigma)/Gaussian tail at the Sec. 3.6 values, two-point density (exact sums), k the
    convention's tail point."""
    q = 2 * MA.tau_over_alpha_sec36
    b = b_of_contour(5.0)
    sd = math.sqrt((MA.n_sec36 - 1) * q * b)
    k = float(IN_COV.tail_point_sd)
    t = float(two_point_exact_tail(math.sqrt(b), MA.n_sec36 - 1, q, np.array([k * sd]))[0])
    return t / stats.norm.sf(k)


def exp_limit() -> bool:
    """(3.8.13)-(3.8.15): Exp -> Exp_g; (Exp_g - Exp) N tau/alpha -> Exp_g^2/12 (tau/alpha = 1e-5),
    both gaps evaluated at one large N."""
    r, eg = MA.tau_over_alpha_fig39, MA.exp_g_fig39
    n = 1e8
    e = float(exponent_from_gaussian_exponent(n, r, eg))
    return abs(e / eg - 1) < 1e-3 and abs((eg - e) * n * r / (eg**2 * (1 - 6 * r) / 12) - 1) < 0.01


def n_effective() -> float:
    """Effective pulse rate per aircraft x N: (5/2.5 + 4/2)/2 x 1e5."""
    return IN_COV.n_ref1 * 0.5 * (IN_COV.pulses_a / IN_COV.alpha_a_s + IN_COV.pulses_b / IN_COV.alpha_b_s)


def gaussian_roc_forms() -> bool:
    """(3.8.1)-(3.8.4): the erf forms equal the integrals of the Gaussian density."""
    p = 4.0 * b_of_contour(5.0)
    for th in THETAS:
        lpf, lpd = gaussian_roc(np.array([th]), p)
        pf, pd = np.exp(lpf), 1.0 - np.exp(lpd)
        ipf, _ = integrate.quad(lambda y: stats.norm.pdf(y, 0, math.sqrt(p)), th, np.inf)
        ipd, _ = integrate.quad(lambda y: stats.norm.pdf(y, 1, math.sqrt(p)), th, np.inf)
        if abs(pf[0] - ipf) > 1e-10 or abs(pd[0] - ipd) > 1e-10:
            return False
        if abs(pf[0] - (0.5 - 0.5 * special.erf(th / math.sqrt(2 * p)))) > 1e-14:
            return False
    return True


def printed_386_log_mgf() -> float:
    """ln E exp(mu n) at mu = 1 for Gaussian n of the worked example's power p = (N-1)/(B alpha)."""
    p = (MA.n_effective_example - 1) / (MA.bandwidth_example_hz * MA.alpha_example_s)
    val, _ = integrate.quad(lambda y: math.exp(y) * stats.norm.pdf(y, 0, math.sqrt(p)), -1, 1)
    return math.log(val)


def printed_386_oracle() -> float:
    pp = sp.Rational(199999, 10**7)
    return float(pp / 2)


def gaussian_bound() -> bool:
    """(3.8.7)-(3.8.9): min over mu of -mu theta + mu^2 p/2 is -theta^2/(2p) (sympy)."""
    mu, th, p = sp.symbols("mu theta p", positive=True)
    f = -mu * th + mu**2 * p / 2
    mstar = sp.solve(sp.diff(f, mu), mu)[0]
    return sp.simplify(f.subs(mu, mstar) + th**2 / (2 * p)) == 0


def series_3812() -> bool:
    x = sp.symbols("x")
    s = sp.series(sp.sqrt(1 + x), x, 0, 4).removeO()
    return sp.simplify(s - (1 + x / 2 - x**2 / 8 + x**3 / 16)) == 0


def exp_equals_closed_form() -> bool:
    """(3.8.10)-(3.8.16): Exp(N, tau/alpha, Exp_g) equals the closed form (3.7.24) at theta^2 = 2 p Exp_g."""
    r = MA.tau_over_alpha_fig310
    for n in (1e5, 2e5, 1e6):
        for eg in (1.0, 4.0, 12.5):
            p = 0.02
            th = math.sqrt(2 * p * eg)
            cf = float(quasi_optimal_exponent(th, p, int(n), r))
            e = float(exponent_from_gaussian_exponent(n, r, eg))
            if abs(cf - e) > 2e-3 * e:
                return False
    return True


ERRATA += [
    Erratum(
        id="ATC10-E3-12-pd-line",
        kind="typography",
        basis="text-only",
        locator="Sec. 3.8 ('no uniform signature set ... more preferable than')",
        printed="$p_d = \\frac12 + \\frac12 \\operatorname{erf}(\\theta\\sqrt{1/2p})$",
        finding="$p_d = \\frac12 + \\frac12 \\operatorname{erf}((1 - \\theta)\\sqrt{1/2p})$, as the same "
        "ROC is printed a page later in (3.8.4): the detection threshold is $1 - \\theta$ below the unit "
        "peak. As printed, $p_d = 1 - p_f$ at every threshold, the chance line of no receiver.",
        evidence="The printed line against (3.8.4) at the check powers, computed with the library's "
        "Gaussian ROC and with scipy's normal distribution: they agree only at $\\theta = 1/2$.",
        claims=("ATC10-sec3.8-pd-line",),
        discussed_in=PAGE_GAUSS,
    ),
]

CLAIMS += [
    Claim.statement(
        id="ATC10-sec3.8-tail-ratio",
        locator="Sec. 3.8",
        quantity="the Gaussian approximation to the multiple-access noise is very poor in the tail "
        "($P(n > 4 \\sigma)$ against the Gaussian tail, two-point $C$, $N = 10^{5}$, "
        "$\\tau/\\alpha = 2 \\times 10^{-5}$)",
        compute=lambda: tail_ratio() > float(IN_COV.very_poor_factor),
        note="The exact sum over the lattice of two-point amplitudes puts the actual $4\\sigma$ tail at 7.2 "
        "times the Gaussian one.",
        discussed_in=G_,
        table="gaussian-checks",
    ),
    Claim.statement(
        id="ATC10-sec3.8-exp-limit",
        locator="Sec. 3.8, (3.8.13)-(3.8.15)",
        quantity="Exp tends to $\\mathrm{Exp}_g$ as N grows",
        compute=exp_limit,
        note="Within 0.1 % at $N = 10^{8}$; the shortfall times $N \\tau/\\alpha$ tends to "
        "$\\mathrm{Exp}_g^2 (1 - 6 \\tau/\\alpha)/12$.",
        discussed_in=G_,
    ),
    Claim(
        id="ATC10-sec3.8-example-n-effective",
        locator="Sec. 3.8, worked example",
        quantity="effective N from 5 pulses per 2.5 s or 4 per 2 s",
        published=2e5,
        unit="",
        compute=n_effective,
        tolerance=printed("2e5")[1],
        expected_status="consistent",
        kind="cross-check",
        note="$10^{5} \\times 5/2.5 = 10^{5} \\times 4/2 = 2 \\times 10^{5}$.",
        discussed_in=G_,
        table="gaussian-checks",
    ),
    Claim.statement(
        id="ATC10-eq3.8.3-gaussian-roc",
        locator="Eqs. (3.8.1)-(3.8.4)",
        quantity="the erf $\\mathrm{ROC}_g$",
        compute=gaussian_roc_forms,
        note="Against quadrature of the Gaussian density.",
        discussed_in=G_,
    ),
    Claim.statement(
        id="ATC10-eq3.8.6-printed",
        locator="Eq. (3.8.6)",
        quantity="(3.8.6) as printed, $E e^{\\mu n} = \\exp(\\mu^2/2)$, is the moment generating "
        "function of the Gaussian noise of (3.8.4) (checked at $\\mu = 1$, $p$ = 0.02)",
        compute=lambda: abs(printed_386_log_mgf() - 0.5) <= 1e-6,
        expected_status="discrepant",
        erratum="ATC10-E3-4",
        oracle=lambda: abs(printed_386_oracle() - 0.5) <= 1e-6,
        oracle_tolerance=EXACT,
        note="The Gaussian MGF is $\\exp(\\mu^2 p/2)$: its logarithm is 0.01 at $\\mu = 1$ and the worked "
        "example's $p$ = 0.02, not the printed 0.5. The final bound (3.8.7) is right.",
        discussed_in=G_,
    ),
    Claim.statement(
        id="ATC10-eq3.8.7-bound",
        locator="Eqs. (3.8.7)-(3.8.9)",
        quantity="$p_f \\le \\exp(-\\theta^2/(2p))$",
        compute=gaussian_bound,
        note="sympy.",
        discussed_in=G_,
    ),
    Claim.statement(
        id="ATC10-eq3.8.12-series",
        locator="Eq. (3.8.12)",
        quantity="$\\sqrt{1 + x}$ series",
        compute=series_3812,
        note="sympy.",
        discussed_in=G_,
    ),
    Claim.statement(
        id="ATC10-eq3.8.16-equals-closed-form",
        locator="Eqs. (3.8.10)-(3.8.11), (3.8.16)",
        quantity="Exp equals the closed form (3.7.24)",
        compute=exp_equals_closed_form,
        note="$N = 10^{5}$ to $10^{6}$, $\\mathrm{Exp}_g$ 1-12.5, $\\tau/\\alpha = 10^{-5}$.",
        discussed_in=G_,
    ),
    Claim.statement(
        id="ATC10-sec3.8-no-uniform-set-beats-roc-g",
        printed="no uniform signature set suffering this average multiple access noise power will "
        "yield an ROC more preferable than",
        locator="Sec. 3.8",
        quantity="no uniform signature set with this multiple-access power yields an ROC more "
        "preferable than $\\mathrm{ROC}_g$ (every actual $p_f$ above the Gaussian one at equal $p_d$)",
        compute=lambda: gaussian_smallest_pf_ratio() > 1.0,
        expected_status="not-reproducible",
        note="The sentence follows from Theorem 3.2, which orders the Chernoff upper bounds; checked on "
        "the actual ROCs of the four densities (computed exactly, as "
        "ATC10-sec3.8-gauss-always-optimistic) at $p_d$ = 0.9 and 0.99 and the figure contours: "
        "$\\mathrm{ROC}_g$ is the better ROC except at the lowest contour, 3, where the continuous "
        "densities beat it; the contour labels are lost (assumed). The bound's $p_d$ line is misprinted "
        "(ATC10-sec3.8-pd-line).",
        discussed_in=PAGE_GAUSS,
        table="too-optimistic",
    ),
    Claim.statement(
        id="ATC10-sec3.8-pd-line",
        printed="$p_d = \\frac{1}{2} + \\frac{1}{2} \\operatorname{erf} \\left(\\theta "
        "\\sqrt{\\frac{1}{2p}} \\right)$",
        locator="Sec. 3.8",
        quantity="the $p_d$ line of the bound after 'no uniform signature set' is the $p_d$ of "
        "$\\mathrm{ROC}_g$, Eq. (3.8.4)",
        compute=pd_line_is_roc_g,
        expected_status="discrepant",
        erratum="ATC10-E3-12-pd-line",
        oracle=pd_line_oracle,
        oracle_tolerance=EXACT,
        note="At the check powers (Sec. 3.6 N and $\\tau/\\alpha$) and thresholds 0.05-0.95 without "
        "1/2: the printed line has $\\theta$ where (3.8.4) has $1 - \\theta$.",
        discussed_in=PAGE_GAUSS,
        table="too-optimistic",
    ),
]

#: Every claim quotes the paper (issue 27, item 5).
CLAIMS = with_quotes(CLAIMS, QUOTES)
