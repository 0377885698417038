"""WF items the first sweep left without a claim (issue 17): Eqs. (11), (16)-(17), the
remarks after Eqs. (11) and (14), Remark (ii)'s trend, and the Sec. IV.D prose numbers.

Inputs are read from :data:`navcore.papers.wf.IN` inside the computations.
"""

from __future__ import annotations

import itertools

import numpy as np

from navcore.claims import EXACT, PROSE_WORDS, Claim, printed
from navcore.estimation.federated import accelerometer_steady_state_isotropic
from navcore.papers.wf import (
    DOCS,
    IN,
    bound_tightness,
    f_l1_over_c_printed,
    sigma_a_example,
    sigma_d_bound,
)
from navcore.papers.wf_quotes import quoted

PAGE = DOCS["IVD"]
PAGE_IV = DOCS["IV"]


def _spd(rng: np.random.Generator, n: int = 3) -> np.ndarray:
    A = rng.normal(size=(n, n))
    return A @ A.T + n * np.eye(n)


#: Draws of the Eq. (11) Monte Carlo.
EQ11_DRAWS = 200_000


def eq11_sample_error() -> float:
    """Largest relative difference between tau P_N tau^T + Q_T (Eq. (11)) and the sample covariance
    of tau e_N + w_T (Eq. (10)) for seeded random tau, P_N, Q_T (200 000 draws)."""
    rng = np.random.default_rng(111)
    tau = rng.normal(size=(3, 3))
    PN, QT = _spd(rng), _spd(rng)
    n = EQ11_DRAWS
    eN = rng.normal(size=(n, 3)) @ np.linalg.cholesky(PN).T
    wT = rng.normal(size=(n, 3)) @ np.linalg.cholesky(QT).T
    sample = np.cov((eN @ tau.T + wT).T)
    formula = tau @ PN @ tau.T + QT
    return float(np.max(np.abs(sample - formula)) / np.max(np.abs(formula)))


def _eq11_holds() -> bool:
    """Eq. (11) is the covariance of the Eq. (10) error: the sample covariance within the allowed
    sampling standard deviations (sqrt(2/n) of the largest entry) of the formula."""
    return eq11_sample_error() <= IN.mc_sigmas * np.sqrt(2.0 / EQ11_DRAWS)


def large_qt_dominates() -> dict[str, float]:
    """sigma_DN / sigma_T at the large sigma_T of Sec. IV.D, for the published sigma_N and for a
    perfect (0) and a tenfold worse navigation system: P_DN = (sigma_N^2 + sigma_T^2) I."""
    st = IN.sigma_t_large
    out = {f"sigma_N={s:g}": float(np.hypot(s, st) / st) for s in (0.0, IN.sigma_n, 10 * IN.sigma_n)}
    return out


def _large_qt_regardless() -> bool:
    r = large_qt_dominates()
    return max(r.values()) - min(r.values()) < IN.close_rel


def eq14_dependence() -> dict[str, float]:
    """Steady-state sqrt(P_DL(k/k)) of Eq. (14) at the Sec. IV.D example (100 ug, T_s, sigma_L =
    200 sigma_a), and with Q_a, R_L, T_s each multiplied in turn by the declared change (doubled)
    at which a contribution is judged (m/s)."""
    sa, ts = sigma_a_example(), IN.ts
    sl = IN.sigma_l_per_sigma_a * sa
    f = IN.contribution_factor

    def s(a: float, t: float, L: float) -> float:
        return float(np.sqrt(accelerometer_steady_state_isotropic(a, t, L).posterior))

    # Q_a and R_L are variances: their standard deviations change by sqrt(f)
    return {
        "nominal": s(sa, ts, sl),
        "Q_a x2": s(np.sqrt(f) * sa, ts, sl),
        "R_L x2": s(sa, ts, np.sqrt(f) * sl),
        "T_s x2": s(sa, f * ts, sl),
    }


def _eq14_three_factors() -> bool:
    d = eq14_dependence()
    return all(d[k] > (1.0 + IN.contributes_rel) * d["nominal"] for k in ("Q_a x2", "R_L x2", "T_s x2"))


RHOS = (1.0, 0.9, 0.7, 0.5, 0.3, 0.0)


def tightness_by_correlation() -> dict[str, float]:
    """tr(bound)/tr(true) of Eq. (23) for the Sec. IV.D-like isotropic case, by correlation rho."""
    return {f"rho={r:g}": bound_tightness(r) for r in RHOS}


def _more_conservative_as_weaker() -> bool:
    v = list(tightness_by_correlation().values())
    return all(b > a for a, b in itertools.pairwise(v)) and abs(v[0] - 1.0) < 1e-9


def eq16_17_information_form() -> float:
    """Largest relative difference between the Kalman update (I - K H) P of Eq. (16) and the
    information form [P^-1 + H^T R^-1 H]^-1 of Eq. (17), with H_G of Eq. (25) (three and one
    satellite) and R_G = sigma_G^2 I, over seeded random priors P_DL."""
    rng = np.random.default_rng(1617)
    worst = 0.0
    for n_sat in (3, 1):
        H = f_l1_over_c_printed() * (np.eye(3) if n_sat == 3 else np.array([[1.0, 0.0, 0.0]]))
        R = IN.sigma_g**2 * np.eye(n_sat)
        for _ in range(20):
            P = 1e-4 * _spd(rng)
            K = P @ H.T @ np.linalg.inv(H @ P @ H.T + R)
            short_form = P - K @ H @ P  # (I - K H) P of Eq. (16)
            info = np.linalg.inv(np.linalg.inv(P) + H.T @ np.linalg.inv(R) @ H)
            worst = max(worst, float(np.max(np.abs(short_form - info)) / np.max(np.abs(info))))
    return worst


def _eq16_17_agree() -> bool:
    """The Kalman update of Eq. (16) and the information form of Eq. (17) agree to round-off."""
    return eq16_17_information_form() < 1e-9


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


_rate, _rate_tol = printed("50", why="'a 50 Hz measurement update rate' (axis label) against $T_s = 0.02$ s")

CLAIMS = [
    Claim(
        id="WF-eq11-covariance",
        locator="Eq. (11)",
        quantity="$P_{DN} = \\tau P_N \\tau^T + Q_T$ is the covariance of the Eq. (10) error",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq11_holds,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Seeded random $\\tau$, $P_N$ and $Q_T$, independent $w_T$ and navigation error; a 200 000-draw "
        "sample covariance within 5 (or 3) sampling standard deviations of the formula, which holds for "
        "any such matrices (linearity of the covariance).",
        discussed_in=PAGE_IV,
    ),
    Claim(
        id="WF-eq11-large-QT",
        locator="Sec. IV.B.1, after Eq. (11)",
        quantity="with a large $Q_T$, $P_{DN}$ is large regardless of $P_N$: $\\sigma_{DN} / \\sigma_T$ at "
        "$\\sigma_T$ = 2 m/s hardly varies between $\\sigma_N$ = 0, 0.02 and 0.2 m/s",
        published=True,
        unit="statement",
        compute=_large_qt_regardless,
        tolerance=EXACT,
        expected_status="reproduced",
        note="With Eq. (24) read as $\\tau P_N \\tau^T = \\sigma_N^2 I$ (WF-E2), "
        "$\\sigma_{DN} = \\sqrt{\\sigma_N^2 + \\sigma_T^2}$: 1, 1.00005 and 1.005 times $\\sigma_T$ for "
        "$\\sigma_N$ = 0, 0.02 and 0.2 m/s, within 1 % (or 10 %), the readings of 'regardless'.",
        discussed_in=PAGE_IV,
    ),
    Claim(
        id="WF-eq14-three-factors",
        locator="Sec. IV.B.2, after Eq. (14)",
        quantity="the local accuracy depends on $Q_a$, $R_L$ and the update rate: doubling each of $Q_a$, "
        "$R_L$, $T_s$ in turn raises the steady-state $\\sqrt{P_{DL}(k/k)}$",
        published=True,
        unit="statement",
        compute=_eq14_three_factors,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Steady state of Eq. (14) at 100 µg, $T_s$ = 0.02 s, $\\sigma_L = 200 \\sigma_a$: about 0.0020 "
        "m/s; doubling $Q_a$ or $R_L$ raises it by about 19 % (the fourth root of 2), doubling $T_s$ by "
        "about 41 % "
        "(steady state close to $\\sqrt{\\sigma_a T_s \\sigma_L}$); 'contribute' read as more than 1 % (or "
        "10 %) for a doubling (or an increase by half) of each factor.",
        discussed_in=PAGE_IV,
    ),
    Claim(
        id="WF-rem2-weaker-correlation",
        locator="Remark (ii)",
        quantity="the bound grows more conservative as the correlation weakens: the ratio of the bound's "
        "trace to the true trace increases strictly as $\\rho$ falls from 1 to 0, and is 1 at $\\rho = 1$",
        published=True,
        unit="statement",
        compute=_more_conservative_as_weaker,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Three isotropic local errors with the Sec. IV.D-like sigmas (0.02, 0.002, 0.0019 m/s), "
        "pairwise correlation $\\rho = 1$, 0.9, 0.7, 0.5, 0.3, 0; exact covariance of the fused error "
        "(Eq. (20)) against the middle term of Eq. (23).",
        discussed_in=PAGE_IV,
    ),
    Claim(
        id="WF-eq16-17-information",
        locator="Eqs. (16)-(17)",
        quantity="the single-step Kalman update of Eq. (16) gives the covariance of Eq. (17): $(I - K H_G) "
        "P_{DL} = [P_{DL}^{-1} + H_G^T R_G^{-1} H_G]^{-1}$",
        published=True,
        unit="statement",
        kind="statement",
        compute=_eq16_17_agree,
        tolerance=EXACT,
        expected_status="reproduced",
        note="$H_G$ of Eq. (25) (three and one satellite) with the printed "
        "$f_{L1}/c$, $R_G = \\sigma_G^2 I$, "
        "20 seeded priors each (the matrix inversion lemma); agreement to $10^{-9}$ relative, floating "
        "point.",
        discussed_in=PAGE_IV,
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
    ),
    Claim(
        id="WF-sec4d-mems-ten-times-more-sensitive",
        aliases=("WF-c22-mems-sensitive",),
        locator="Sec. IV.D, after Fig. 2",
        quantity="MEMS devices an order of magnitude more sensitive than 100 µg: the high-resolution end "
        "(10 µm/s²) of the range Sec. IV.D lists from [4] is at least that much finer",
        published=True,
        unit="statement",
        kind="cross-check",
        compute=_an_order_of_magnitude_finer,
        tolerance=EXACT,
        expected_status="consistent",
        note="100 µg = 981 µm/s², about 98 times 10 µm/s² (about 1 µg): the paper's own parameter list "
        "already holds devices two orders of magnitude finer, more than 'an order of magnitude' (read "
        "as in the ledger's table of prose words: a factor 10 within half a decade). Reference [4]'s "
        "device list itself is not checked.",
        discussed_in=PAGE,
    ),
    Claim(
        id="WF-sec5-aperture-errors-negligible",
        aliases=("WF-c23-negligible",),
        locator="Sec. V",
        quantity="the processing reduces the aperture errors' impact to a negligible level: the fused bound "
        "$\\sigma_D$ at 100 µg and $\\sigma_T$ = 2 m/s is below the on-board navigation accuracy $\\sigma_N$",
        published=True,
        unit="statement",
        compute=_negligible,
        tolerance=EXACT,
        expected_status="reproduced",
        note="$\\sigma_D$ about 0.0020 m/s against $\\sigma_N = 0.02$ m/s: the aperture adds less velocity "
        "error than the navigation system has without any flexure ('negligible' read as below $\\sigma_N$, "
        "or below a tenth of it).",
        discussed_in=PAGE,
    ),
]

CLAIMS = quoted(CLAIMS)
