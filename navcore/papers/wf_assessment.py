"""WF Sec. IV.D, assessment of benefits (Eqs. (24)-(25), Figs. 1-2), and the conclusion of Sec. V.

The local covariances of the Sec. IV.D parameter list (Eq. (24), erratum WF-E2; Eq. (25)), the
improvement bound of Figs. 1-2 and the prose numbers around them, and Sec. V's conclusion that
the aperture errors become negligible, which rests on the same bound. Models:
:mod:`navcore.estimation.federated`; inputs: :data:`navcore.papers.wf_inputs.IN`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from navcore.claims import (
    EXACT,
    PROSE_WORDS,
    Claim,
    Erratum,
    figure_reading,
    input_cache,
    printed,
    prose,
    with_quotes,
)
from navcore.estimation.federated import (
    accelerometer_steady_state_isotropic,
    federated_improvement_db,
    gps_doppler_covariance,
    minkowski_trace_bound,
)
from navcore.papers.wf_inputs import IN, f_l1_over_c_printed, sigma_a_example, sigma_t_values
from navcore.papers.wf_local_estimators import SPEED_DIMENSION
from navcore.papers.wf_quotes import QUOTES
from navcore.trace import implements
from navcore.units import GPS_L1_HZ

#: The page that discusses the claims of Secs. IV.D and V.
PAGE = "wf/04-assessment"


#: Sec. IV.D printed L1 frequency over c, 1/m (the figures read the published input).
F_L1_OVER_C_PRINTED = "5.25"


def f_l1_over_c_read() -> float:
    """GPS L1 frequency over the speed of light under the reading of c used (the convention
    ``c_of_fl1_mps``: the defined c, or the engineering 3e8 or 2.998e8 m/s), 1/m."""
    return GPS_L1_HZ / IN.c_of_fl1_mps


def gps_doppler_velocity_sigma() -> float:
    """Velocity accuracy per line of sight equivalent to sigma_G = 1 Hz: sigma_G / (f_L1/c), m/s."""
    return IN.sigma_g / f_l1_over_c_printed()


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
    # (length, time) exponents add in a product: a variance is speed x speed
    variance = tuple(2 * d for d in SPEED_DIMENSION)
    return tuple(2 * d for d in variance) == variance


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


def update_rate_hz() -> float:
    """The update rate 1/T_s of the Sec. IV.D parameter list, Hz."""
    return 1.0 / IN.ts


def sensitive_devices_ratio() -> float:
    """The 100 ug of the worked example over the high-resolution end (10 um/s^2) of the MEMS
    resolution range that Sec. IV.D itself lists from [4]."""
    return sigma_a_example() / IN.sigma_a_low


def _an_order_of_magnitude_finer() -> bool:
    """100 ug over the high-resolution end of the listed range is at least 'an order of magnitude' by
    the prose table (a factor 10 within half a decade: at least 10^0.5)."""
    return bool(
        np.log10(sensitive_devices_ratio()) >= 1.0 - PROSE_WORDS["an order of magnitude"]["abs_log10"]
    )


def negligible_margin() -> dict[str, float]:
    """The fused per-axis bound sigma_D at the worked example (100 ug, sigma_T = 2 m/s, no GPS)
    against the on-board navigation accuracy sigma_N, m/s."""
    return {"sigma_D": sigma_d_bound(sigma_a_example(), IN.sigma_t_large), "sigma_N": IN.sigma_n}


def _negligible() -> bool:
    m = negligible_margin()
    return m["sigma_D"] < IN.negligible_fraction * m["sigma_N"]


_fl1, _fl1_tol = printed(F_L1_OVER_C_PRINTED)
_c14r, _c14r_tol = printed("60")
_sL_lo, _sL_lo_tol = printed("0.002")
_sL_hi, _sL_hi_tol = printed("2")
_c17, _c17_tol = printed("0.2")
_c15, _c15_tol = printed("0.002")
_c15f, _c15f_tol = printed("1e3", why="'a factor of $10^{3}$', one significant digit")
_sg, _sg_tol = printed("1", why="'$\\sigma_G = 1$ Hz (consistent with the GPS velocity accuracy ...)'")
_rate, _rate_tol = printed("50", why="'a 50 Hz measurement update rate' (axis label) against $T_s = 0.02$ s")

FIG1_READING = figure_reading(
    0.5,
    figure="Fig. 1",
    axis="improvement $20 \\log_{10}(\\sigma_D / \\sigma_{DN})$ in dB; curves closer than half a dB are "
    "not told apart",
)


# ----------------------------------------------------------------------------- errata
ERRATA = [
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
        discussed_in=PAGE,
    ),
]


# ----------------------------------------------------------------------------- claims
CLAIMS = [
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
        discussed_in=PAGE,
        table="fig2-gps",
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
        discussed_in=PAGE,
        table="fig1-improvement",
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
        discussed_in=PAGE,
        table="fig1-improvement",
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
        discussed_in=PAGE,
        table="fig1-improvement",
    ),
    Claim.statement(
        id="WF-eq24-PN",
        locator="Eq. (24)",
        quantity="$P_N P_N^T = \\sigma_N^2 I$ is consistent with Eq. (11): the "
        "literal reading gives the same "
        "$\\sigma_{DN}$ in any velocity unit",
        compute=eq24_literal_is_unit_consistent,
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
        discussed_in=PAGE,
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
        discussed_in=PAGE,
        table="fig1-improvement",
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
        discussed_in=PAGE,
        table="fig1-improvement",
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
        discussed_in=PAGE,
        table="fig1-improvement",
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
        discussed_in=PAGE,
        table="fig1-improvement",
    ),
    Claim.statement(
        id="WF-fig1-slope",
        locator="Fig. 1",
        quantity="the $\\sigma_T$ = 2 m/s curve rises 20 dB per decade of accelerometer resolution",
        compute=_fig1_slope,
        note="Figure-only (no curve values printed); least-squares slope within 0.5 (or 1) dB/decade of 20 "
        "over 10 µm/s² to 10 mm/s², as $\\sigma_{DL} \\approx 2\\,\\mathrm{s} \\cdot \\sigma_a$ "
        "predicts. The computation reads published inputs and the reading of the slope only.",
        discussed_in=PAGE,
        table="fig1-improvement",
    ),
    Claim.statement(
        id="WF-fig1-order",
        locator="Fig. 1",
        quantity="larger lever-arm uncertainty gives more improvement: the curves $\\sigma_T$ = 2 below 0.2 "
        "below 0 m/s over the stated range",
        compute=_fig1_ordered,
        note="Figure-only; over the stated axis range 10 µm/s² to 10 mm/s², the curves are apart by at least "
        "19 dB. The page also shows that every curve is at or below 0 dB and that the $\\sigma_T = 2$ m/s "
        "curve rises monotonically. The computation reads published inputs only.",
        discussed_in=PAGE,
        table="fig1-improvement",
    ),
    Claim.statement(
        id="WF-fig2-gps-adds-little",
        aliases=("WF-c18-gps-little",),
        locator="Sec. IV.D, Fig. 2",
        quantity="GPS adds little to the accelerometer over the stated range (less than a noticeable change)",
        compute=_gps_adds_little,
        note="Fig. 2 differs from Fig. 1 by less than 1 dB (or 3 dB), the readings of 'noticeable', for 1 "
        "and 3 satellites, every $\\sigma_T$ and every $\\sigma_a$ in 10 µm/s² to 10 mm/s² (the page "
        "shows the largest difference). Beyond about 30 mm/s² it no "
        "longer holds.",
        discussed_in=PAGE,
        table="fig2-gps",
    ),
    Claim.statement(
        id="WF-sec4d-gps-noticeable-only-when-severe",
        aliases=("WF-c19-gps-noticeable",),
        locator="Sec. IV.D",
        quantity="GPS is noticeable only with severe $\\sigma_T$, a poor accelerometer and 3 satellites",
        compute=_gps_noticeable_only_when,
        expected_status="consistent",
        note="Holds only if the axis extends beyond the stated 10 mm/s²: inside the range no benefit "
        "exceeds 1 dB ('noticeable' read as 1 or 3 dB); on 10 µm/s² to the assumed 'very poor' end "
        "(1 m/s², range 0.1-1) the largest one is at $\\sigma_T = 2$ m/s, 3 satellites, above 10 mm/s².",
        discussed_in=PAGE,
        table="fig2-gps",
    ),
    Claim.statement(
        id="WF-fig2-three-vs-one-satellite",
        aliases=("WF-c20-three-vs-one",),
        locator="Sec. IV.D, Fig. 2",
        quantity="3 satellites virtually identical to 1 at $\\sigma_T$ = 0: the two "
        "improvement curves closer "
        "than Fig. 2 can show over the stated range",
        compute=_three_as_one,
        note="Over the stated $\\sigma_a$ range the two curves differ by less than the figure can show "
        "(the page gives the largest difference). 'Virtually "
        "identical' (the 3-satellite curve is not drawn) is read as closer than the figure's resolution "
        "(half or a tenth of a dB).",
        discussed_in=PAGE,
        table="fig2-gps",
    ),
    Claim.statement(
        id="WF-fig2-order",
        locator="Sec. IV.D, Fig. 2",
        quantity="more GPS satellites never give less improvement (3 satellites over 1, 1 over none, any "
        "$\\sigma_T$, over the stated $\\sigma_a$ range), as far as Fig. 2 can show",
        compute=_fig2_ordered,
        note="Figure-only (the paper's 'benefits' of GPS, Fig. 2 curves in order). The correlation-free "
        "bound is not monotone in the estimators: the GPS estimate is the accelerometer prior updated "
        "once, and an estimator worse than the current bound pulls the bound towards itself; while the "
        "accelerometer is the best local estimator (the whole stated range) the rise is at most the "
        "prior/posterior gap $10 \\log_{10}(P_{DL}(k/k-1)/P_{DL}(k/k))$ of the accelerometer filter (on the "
        "page), "
        "far below what Fig. 2 can show. Beyond the stated range the ordering fails by about 1 dB (one "
        "satellite at $\\sigma_T = 0$). Read at the figure's resolution (half or a tenth of a dB): the "
        "largest rise is 0.0002 dB.",
        discussed_in=PAGE,
        table="fig2-gps",
    ),
    Claim(
        id="WF-fig1-update-rate-50hz",
        aliases=("WF-c21-50Hz",),
        locator="Sec. IV.D, axis label of Figs. 1-2",
        quantity="the '50 Hz measurement update rate' of the axis label is $1/T_s$ of the parameter list",
        published=_rate,
        unit="Hz",
        kind="cross-check",
        compute=update_rate_hz,
        tolerance=_rate_tol,
        expected_status="consistent",
        note="1 / 0.02 s = 50 Hz: the label and the parameter list agree.",
        discussed_in=PAGE,
        table="conclusions",
    ),
    Claim.statement(
        id="WF-sec4d-mems-ten-times-more-sensitive",
        aliases=("WF-c22-mems-sensitive",),
        locator="Sec. IV.D, after Fig. 2",
        quantity="MEMS devices an order of magnitude more sensitive than 100 µg: the high-resolution end "
        "(10 µm/s²) of the range Sec. IV.D lists from [4] is at least that much finer",
        kind="cross-check",
        compute=_an_order_of_magnitude_finer,
        expected_status="consistent",
        note="100 µg = 981 µm/s², about 98 times 10 µm/s² (about 1 µg): the paper's own parameter list "
        "already holds devices two orders of magnitude finer, more than 'an order of magnitude' (read "
        "as in the ledger's table of prose words: a factor 10 within half a decade). Reference [4]'s "
        "device list itself is not checked.",
        discussed_in=PAGE,
        table="conclusions",
    ),
    Claim.statement(
        id="WF-sec5-aperture-errors-negligible",
        aliases=("WF-c23-negligible",),
        locator="Sec. V",
        quantity="the processing reduces the aperture errors' impact to a negligible level: the fused bound "
        "$\\sigma_D$ at 100 µg and $\\sigma_T$ = 2 m/s is below the on-board navigation accuracy $\\sigma_N$",
        compute=_negligible,
        note="$\\sigma_D$ about 0.0020 m/s against $\\sigma_N = 0.02$ m/s: the aperture adds less velocity "
        "error than the navigation system has without any flexure ('negligible' read as below $\\sigma_N$, "
        "or below a tenth of it).",
        discussed_in=PAGE,
        table="conclusions",
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
