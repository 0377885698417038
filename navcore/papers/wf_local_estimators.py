"""WF Sec. IV.B, individual local velocity estimates: Eqs. (10)-(17).

The navigation-only estimate (Eqs. (10)-(11)), the aperture-local accelerometer filter
(Eqs. (12)-(14), erratum WF-E1 on the innovation of Eq. (13)) and the aperture-acquired GPS
update (Eqs. (15)-(17)). Models: :mod:`navcore.estimation.federated`; inputs:
:data:`navcore.papers.wf_inputs.IN`.
"""

from __future__ import annotations

import numpy as np

from navcore.claims import EXACT, Claim, Erratum, with_quotes
from navcore.estimation.federated import (
    accelerometer_steady_state_isotropic,
    navigation_mapped_error_samples,
    random_covariance,
)
from navcore.papers.wf_inputs import IN, f_l1_over_c_printed, sigma_a_example
from navcore.papers.wf_quotes import QUOTES

#: The page that discusses the claims of Secs. IV.B and IV.C.
PAGE = "wf/03-local-estimators"


#: Draws of the Eq. (11) Monte Carlo.
EQ11_DRAWS = 200_000


def _eq11_holds() -> bool:
    """Eq. (11) is the covariance of the Eq. (10) error: for seeded random tau, P_N, Q_T (diagonal
    floor 3), the sample covariance of tau e_N + w_T (200 000 draws) within the allowed sampling
    standard deviations (sqrt(2/n) of the largest entry) of tau P_N tau^T + Q_T."""
    rng = np.random.default_rng(111)
    tau = rng.normal(size=(3, 3))
    PN, QT = random_covariance(rng, 3, 3.0), random_covariance(rng, 3, 3.0)
    sample = np.cov(navigation_mapped_error_samples(tau, PN, QT, rng, EQ11_DRAWS).T)
    formula = tau @ PN @ tau.T + QT
    error = float(np.max(np.abs(sample - formula)) / np.max(np.abs(formula)))
    return error <= IN.mc_sigmas * np.sqrt(2.0 / EQ11_DRAWS)


def large_qt_dominates() -> dict[str, float]:
    """sigma_DN / sigma_T at the large sigma_T of Sec. IV.D, for the published sigma_N and for a
    perfect (0) and a tenfold worse navigation system: P_DN = (sigma_N^2 + sigma_T^2) I."""
    st = IN.sigma_t_large
    out = {f"sigma_N={s:g}": float(np.hypot(s, st) / st) for s in (0.0, IN.sigma_n, 10 * IN.sigma_n)}
    return out


def _large_qt_regardless() -> bool:
    r = large_qt_dominates()
    return max(r.values()) - min(r.values()) < IN.close_rel


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
    return ACCEL_DIMENSION == SPEED_DIMENSION


def _eq13_oracle() -> bool:
    """Independent of the dimensions: a seeded simulation of the printed recursion under the assumed
    manoeuvre (:func:`eq13_printed_error_ratio`) ends within the Monte Carlo band of the covariance of
    Eq. (14) (its RMS error over sqrt(P_DL(k/k)) within the allowed sampling standard deviations of 1)."""
    sd = 1.0 / np.sqrt(2 * _EQ13_PATHS)
    return bool(abs(eq13_printed_error_ratio() - 1.0) <= IN.mc_sigmas * sd)


#: SI dimension exponents (length, time) for the dimensional checks of Eqs. (13) and (24).
SPEED_DIMENSION = (1, -1)
ACCEL_DIMENSION = (1, -2)


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
            P = 1e-4 * random_covariance(rng, 3, 3.0)
            K = P @ H.T @ np.linalg.inv(H @ P @ H.T + R)
            short_form = P - K @ H @ P  # (I - K H) P of Eq. (16)
            info = np.linalg.inv(np.linalg.inv(P) + H.T @ np.linalg.inv(R) @ H)
            worst = max(worst, float(np.max(np.abs(short_form - info)) / np.max(np.abs(info))))
    return worst


def _eq16_17_agree() -> bool:
    """The Kalman update of Eq. (16) and the information form of Eq. (17) agree to round-off."""
    return eq16_17_information_form() < 1e-9


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
        discussed_in=PAGE,
    ),
]


# ----------------------------------------------------------------------------- claims
CLAIMS = [
    Claim.statement(
        id="WF-eq13-innovation",
        locator="Eq. (13)",
        quantity="the innovation of the printed filter, $y_a(k) - \\hat x_{DL}(k/k-1)$, is a velocity "
        "residual (a difference of like quantities), as a Kalman filter of Eq. (12) needs",
        compute=eq13_innovation_is_a_velocity_residual,
        expected_status="discrepant",
        erratum="WF-E1-eq13-innovation",
        oracle=_eq13_oracle,
        oracle_tolerance=EXACT,
        note="$y_a$ is the accelerometer output of Eq. (12), an acceleration; $\\hat x_{DL}$ a velocity: the "
        "printed innovation subtracts a velocity from an acceleration. Checked independently by a seeded "
        "simulation of the printed recursion (200 paths, 5000 steps, $\\sigma_a = 10^{-3}$ m/s², the assumed "
        "0.5 m/s² manoeuvre at 0.2 Hz): its error ends about 80 times $\\sqrt{P_{DL}(k/k)}$, far outside "
        "the covariance of Eq. (14). No printed number uses Eq. (13) (Figs. 1-2 follow Eq. (14)).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="WF-eq11-covariance",
        locator="Eq. (11)",
        quantity="$P_{DN} = \\tau P_N \\tau^T + Q_T$ is the covariance of the Eq. (10) error",
        compute=_eq11_holds,
        note="Seeded random $\\tau$, $P_N$ and $Q_T$, independent $w_T$ and navigation error; a 200 000-draw "
        "sample covariance within 5 (or 3) sampling standard deviations of the formula, which holds for "
        "any such matrices (linearity of the covariance).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="WF-eq11-large-QT",
        locator="Sec. IV.B.1, after Eq. (11)",
        quantity="with a large $Q_T$, $P_{DN}$ is large regardless of $P_N$: $\\sigma_{DN} / \\sigma_T$ at "
        "$\\sigma_T$ = 2 m/s hardly varies between $\\sigma_N$ = 0, 0.02 and 0.2 m/s",
        compute=_large_qt_regardless,
        note="With Eq. (24) read as $\\tau P_N \\tau^T = \\sigma_N^2 I$ (WF-E2), "
        "$\\sigma_{DN} = \\sqrt{\\sigma_N^2 + \\sigma_T^2}$: 1, 1.00005 and 1.005 times $\\sigma_T$ for "
        "$\\sigma_N$ = 0, 0.02 and 0.2 m/s, within 1 % (or 10 %), the readings of 'regardless'.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="WF-eq14-three-factors",
        locator="Sec. IV.B.2, after Eq. (14)",
        quantity="the local accuracy depends on $Q_a$, $R_L$ and the update rate: doubling each of $Q_a$, "
        "$R_L$, $T_s$ in turn raises the steady-state $\\sqrt{P_{DL}(k/k)}$",
        compute=_eq14_three_factors,
        note="Steady state of Eq. (14) at 100 µg, $T_s$ = 0.02 s, $\\sigma_L = 200 \\sigma_a$: about 0.0020 "
        "m/s; doubling $Q_a$ or $R_L$ raises it by about 19 % (the fourth root of 2), doubling $T_s$ by "
        "about 41 % "
        "(steady state close to $\\sqrt{\\sigma_a T_s \\sigma_L}$); 'contribute' read as more than 1 % (or "
        "10 %) for a doubling (or an increase by half) of each factor.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="WF-eq16-17-information",
        locator="Eqs. (16)-(17)",
        quantity="the single-step Kalman update of Eq. (16) gives the covariance of Eq. (17): $(I - K H_G) "
        "P_{DL} = [P_{DL}^{-1} + H_G^T R_G^{-1} H_G]^{-1}$",
        compute=_eq16_17_agree,
        note="$H_G$ of Eq. (25) (three and one satellite) with the printed "
        "$f_{L1}/c$, $R_G = \\sigma_G^2 I$, "
        "20 seeded priors each (the matrix inversion lemma); agreement to $10^{-9}$ relative, floating "
        "point.",
        discussed_in=PAGE,
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
