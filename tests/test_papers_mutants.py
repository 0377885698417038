"""Gaps in the tests of the paper modules found by mutation testing (issue 31, 8 December 2026).

The paper modules' claims are their tests; these tests reach what the claims leave unseen: a
statement whose check is never shown to fail (a planted counter-example must make it return
False, a case just inside its threshold True), a term of a statement's formula that the
published inputs make too small to see (an input moved with ``overriding`` makes it visible),
and helpers that only a book page calls. Each test names its oracle.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize, stats

from navcore.claims.inputs import overriding
from navcore.detection.roc_bounds import exponent_from_gaussian_exponent
from navcore.papers import atc10_clock_tracking as atc10_clock
from navcore.papers import atc10_gaussian_comparison as atc10_gauss
from navcore.papers import atc10_jamming as atc10_jam
from navcore.papers import atc10_jamming_appendices as atc10_jam_app
from navcore.papers import atc10_multiple_access as atc10_ma
from navcore.papers import atc10_roc_bounds as atc10_roc
from navcore.papers import atc10_tracking_examples as atc10_track_ex
from navcore.papers import atc10_tracking_procedures as atc10_track_proc
from navcore.papers import kzl_tightly_coupled_filter as kzl_tc
from navcore.papers import sp_antijam, sp_flyby, sp_tables
from navcore.papers import sp_mission_flights as sp_flights
from navcore.papers import sp_scenario_wiring as sp_wiring
from navcore.papers import wf_aperture_velocity as wf_velocity
from navcore.papers import wf_federated_fusion as wf_fusion

# --- ATC-10 Appendix E ---------------------------------------------------------------------


def test_appendix_e_cumulants_hold_where_the_sixth_order_terms_are_visible():
    """Oracle: Eqs. (E.4)-(E.9) hold for every overlap probability q = 2 tau/alpha in (0, 1],
    and at q = 1/2 (tau/alpha = 1/4) the three terms of the sixth cumulant are of one order
    (q m6 = 4.6e-6, 15 q^2 m4 m2 = 1.6e-5, 30 q^3 m2^3 = 8.9e-6 for the uniform C of contour
    x = 5), so the statement's check compares all of them (at the published q = 4e-5 the
    sixth cumulant, 3.7e-10, is below numpy's default atol and q^3 vs q^4 is invisible)."""
    name = atc10_ma.IN.input("tau_over_alpha_sec36").name
    with overriding({name: 0.25}):
        assert atc10_ma.appe_cumulants() is True
    # the statement at q = 1/2 is not vacuous: the q^3 term is about twice the q^4 term's size
    q, b = 0.5, atc10_ma.b_of_contour(5.0)
    assert 30 * q**3 * b**3 - 30 * q**4 * b**3 > 1e-3 * abs(q * 27 * b**3 / 7)


# --- ATC-10 Eq. (3.8.6): the Gaussian moment generating function ---------------------------


def test_printed_386_oracle_is_the_log_mgf_of_the_worked_example():
    """Oracle: the Gaussian MGF E exp(mu n) = exp(mu^2 p / 2), so at mu = 1 its logarithm is p/2
    with the worked example's p = (N - 1)/(B alpha) (computed here from the inputs); the
    quadrature of ``printed_386_log_mgf`` over [-1, 1] (seven standard deviations) agrees with
    it to its truncation, 1e-8 relative."""
    ma = atc10_gauss.MA
    p = (ma.n_effective_example - 1) / (ma.bandwidth_example_hz * ma.alpha_example_s)
    assert atc10_gauss.printed_386_oracle() == pytest.approx(p / 2, rel=1e-12)
    assert atc10_gauss.printed_386_log_mgf() == pytest.approx(p / 2, rel=1e-8)


# --- ATC-10 Sec. 2.8: the 10-dB steps keep their former ids ------------------------------


def test_printed_items_name_registered_claims_and_the_sec28_steps_keep_their_former_ids():
    """Oracle: the committed inventory of printed items (``navcore/papers/paper_items.json``),
    which names the Sec. 2.8 steps by their former ids ``...-pdl0.999`` and ``...-pdl0.88``:
    every claim an item names is a registered claim's id or alias, and those former ids
    resolve to the step claims ``ATC10-sec2.8-10dB-K1to10`` and ``-K10to100``."""
    from navcore import coverage, ledger

    assert [p for p in coverage.problems() if "unknown claim" in p] == []
    named = {c for it in coverage.items() for c in it.claims}
    for k_from, k_to in ((1, 10), (10, 100)):
        for p_dl in ("0.999", "0.88"):
            former = f"ATC10-sec2.8-10dB-K{k_from}to{k_to}-pdl{p_dl}"
            assert former in named
            assert ledger.claim(former).id == f"ATC10-sec2.8-10dB-K{k_from}to{k_to}"


# --- ATC-10 Sec. 2.3: a segment of length alpha + beta holds a signature -------------------


@pytest.mark.parametrize("alpha_s", [0.05, 0.5, 1.0, 2.0])
def test_segment_holds_signature_at_other_repetition_periods(alpha_s):
    """Oracle: by hand. The quadruplet whose first pulse falls in the first alpha of a segment of
    length alpha + beta ends less than beta later (the delays lie in [0, beta)), so every segment
    holds one complete quadruplet whatever alpha (> beta = 24 ms) and the pulse phase, and some
    hold two: the statement holds with the repetition period moved from 1 s to 50 ms, 0.5 s
    and 2 s, phases drawn over the whole period."""
    with overriding({atc10_jam.IN_J.input("repetition_s").name: alpha_s}):
        assert atc10_jam._segment_holds_signature() is True


# --- ATC-10 Appendix A: the printed (A.7) against (A.4) -------------------------------------


def _a7_disagreements_by_hand(k: int) -> int:
    """With p0 = 1/5, p1 = 3/5 (a = 2, b = 1/3), (A.4) reads 6^K0 <= (3 lambda_1)^K and the printed
    (A.7) 6^K0 <= (lambda_1 / 3)^K; the second implies the first, so they disagree exactly for
    K ln(lambda_1/3)/ln 6 < K0 <= K ln(3 lambda_1)/ln 6, K0 in 0..K: floor(K ln 1.5/ln 6) + 1
    cases at lambda_1 = 1/2, floor(K ln 3/ln 6) + 1 at 1, and K at 3 (K0 = 0 is a tie, where
    both accept)."""
    return math.floor(k * math.log(1.5) / math.log(6)) + 1 + math.floor(k * math.log(3) / math.log(6)) + 1 + k


@pytest.mark.parametrize(("k", "exact"), [(10, True), (10, False), (400, False), (1000, True)])
def test_printed_a7_disagreements_count_by_hand(k, exact):
    """Oracle: the count worked by hand above (20 at the published K = 10, 737 at K = 400, 1841 at
    K = 1000, a transmission length of Table 2.1, moved into the K = 10 input), in exact rational
    arithmetic and in logarithms; at K = 1000, 6^K0 and 3^K leave the range of floats, which
    only the exact fractions survive."""
    name = atc10_jam_app.IN_J.input("tab21_k10").name
    with overriding({name: k}):
        assert atc10_jam_app.printed_a7_disagreements(exact) == _a7_disagreements_by_hand(k)


# --- ATC-10 Appendix C: the tracking window ------------------------------------------------


@pytest.mark.parametrize("alpha_s", [1.0, 0.1, 0.01])
def test_track_window_holds_at_shorter_repetition_periods(alpha_s):
    """Oracle: the triangle inequality. Between pulses an aircraft moves by |step| <= v alpha,
    so each satellite range changes by at most v alpha and their difference d_1 by at most
    2 v alpha (C.5), for any alpha: the statement holds at the printed alpha = 1 s and with
    the repetition period moved to 0.1 and 0.01 s (where a step drawn otherwise than with
    length uniform in [0, v alpha] leaves the bound)."""
    with overriding({atc10_jam_app.IN_J.input("repetition_s").name: alpha_s}):
        assert atc10_jam_app._track_window_holds() is True


# --- ATC-10 Fig. 3.10: Exp practically linear in Exp_g -------------------------------------


@pytest.mark.parametrize("n", [1e4, 1e5])
def test_exp_linearity_r2_is_the_squared_correlation_of_the_curve_from_zero(n):
    """Oracle: R^2 of a least-squares line with intercept is the squared correlation coefficient
    (scipy.stats.linregress), on Exp_g = 0, 0.25, ..., 20 with Exp(0) = 0, the limit of Eq.
    (3.8.16) as Exp_g -> 0 (both of its terms vanish)."""
    g = np.linspace(0.0, 20.0, 81)
    e = np.zeros_like(g)
    e[1:] = exponent_from_gaussian_exponent(n, atc10_gauss.IN.tau_over_alpha_fig310, g[1:])
    expected = stats.linregress(g, e).rvalue ** 2
    assert atc10_gauss.exp_linearity_r2(n) == pytest.approx(expected, abs=1e-9)


# --- ATC-10 Sec. 3.7 and App. F: the seeded random codes ----------------------------------


@pytest.mark.parametrize("seed", [3, 11])
def test_random_codes_are_the_seeded_draws(seed):
    """Oracle: numpy's generator itself. ``_codes(seed)`` are the four length-31 +-1 codes that
    ``default_rng(seed)`` draws, scaled to unit energy, and the same on every call (the claims
    of (F.5) and Theorem 3.3 are evaluated on them)."""
    rng = np.random.default_rng(seed)
    expected = [rng.choice([-1.0, 1.0], 31) / math.sqrt(31) for _ in range(4)]
    for got in (atc10_roc._codes(seed), atc10_roc._codes(seed)):
        assert len(got) == 4
        for code, want in zip(got, expected, strict=True):
            np.testing.assert_array_equal(code, want)
            assert float(code @ code) == pytest.approx(1.0, rel=1e-15)


# --- ATC-10 Sec. 4.5: the printed (4.5.31) -------------------------------------------------


@pytest.mark.parametrize("example", ["I", "II"])
@pytest.mark.parametrize("sigma0_attr", ["sigma0_low_ns", "sigma0_mid_ns", "sigma0_high_ns"])
def test_printed_4531_closed_form_is_the_limit_of_the_printed_recursion(example, sigma0_attr):
    """Oracle: the printed recursion (4.5.31) iterated 5000 times (``printed_4531_sdn``), an
    independent computation of the same fixed point as the closed form through the cubic's
    root; with sigma0^2 printed where sigma^2 belongs, alpha = (8/27) sigma0^2 beta / sigma0^2
    = (8/27) beta, so the closed form does not depend on sigma0 (5, 50 or 500 ns)."""
    sigma0 = getattr(atc10_track_proc.TR, sigma0_attr)
    closed = atc10_track_proc.printed_4531_oracle(example, sigma0)
    assert closed == pytest.approx(atc10_track_proc.printed_4531_sdn(example, sigma0_attr), rel=1e-9)
    assert closed == pytest.approx(atc10_track_proc.printed_4531_oracle(example, 1.0), rel=1e-12)


# --- ATC-10 Sec. 4.5.2: the printed tau_n = sum w_i + alpha_0 -------------------------------


@pytest.mark.parametrize("n", [1, 2, 10, 30])
def test_printed_tau_sum_oracle_is_the_variance_of_n_plus_one_draws(n):
    """Oracle: closed form. The printed tau_n adds n + 1 independent N(0, sigma0^2) terms, so its
    variance is (n + 1) sigma0^2 and the ratio to (4.3.1c)'s (n + n^2) sigma0^2 is 1/n: the
    Monte Carlo of 2e5 draws agrees to 2 % (its relative standard error is sqrt(2/2e5) = 0.3 %)."""
    assert atc10_clock.printed_tau_sum_oracle(n) == pytest.approx((n + 1) / (n + n * n), rel=0.02)


# --- ATC-10 Sec. 4.5: the first tracking step of the printed (4.5.10) -----------------------


@pytest.mark.parametrize("example", ["I", "II"])
def test_first_step_variance_agrees_with_its_monte_carlo_and_the_optimal_gain(example):
    """Oracles: (a) a seeded Monte Carlo of the first step (``printed_4510_oracle``: 400 000 draws
    of the least-squares error, the clock increment and the projected noise) against the
    closed-form error variance of the printed gain 1/gamma_1, within five standard errors
    (sqrt(2/400 000) relative each); (b) algebra: with the optimal gain c = gamma_1 = s_1 /
    (sigma^2 + beta s_1) the variance c^2 sigma^2 beta + (1 - c beta)^2 s_1 is sigma^2 gamma_1
    exactly ((4.5.18))."""
    closed = atc10_clock.printed_4510_variance_ratio(example)
    assert atc10_clock.printed_4510_oracle(example) == pytest.approx(closed, rel=5 * math.sqrt(2 / 400_000))
    _, g1, var, _ = atc10_clock._first_step(example, atc10_clock.TR.sigma0_low_ns, inverse_gain=False)
    assert var == pytest.approx(atc10_clock.TR.sigma_ns**2 * g1, rel=1e-12)


# --- ATC-10 Sec. 4.5.4: the convergence rule's worst case ----------------------------------


@pytest.mark.parametrize("fraction", [0.1, 0.5])
def test_convergence_rule_worst_ratio_is_the_one_farthest_from_one(fraction):
    """Oracle: the docstring's definition, the ratio of the six whose logarithm is largest in
    magnitude, taken here from the six ratios (printed estimate -ln f / psi over the oracle's
    count + 1). At the printed f = 0.1 all exceed 1; with the criterion loosened to f = 0.5 all
    fall below 1, so the worst is the smallest, not the largest."""
    proc = atc10_track_proc
    with overriding({proc.IN.input("convergence_fraction").name: fraction}):
        ratios = []
        for (b, s0), count in zip(proc._six_cases(), proc._oracle_convergence_counts(), strict=True):
            p = float(proc.psi(proc.alpha_parameter(s0, proc.IN.sigma_ns, b)))
            ratios.append(-math.log(fraction) / p / (count + 1.0))
        worst = max(ratios, key=lambda r: abs(math.log(r)))
        assert proc._oracle_convergence_rule_worst_ratio() == pytest.approx(worst, rel=1e-12)
    if fraction == 0.5:
        assert worst == min(ratios) < 1.0


# --- ATC-10 Sec. 4.7: a later 1/f crossover helps -------------------------------------------


@pytest.mark.parametrize("sigma0_attr", ["sigma0_low_ns", "sigma0_mid_ns", "sigma0_high_ns"])
@pytest.mark.parametrize(("crossover_n", "helps"), [(1, False), (10, True), (100, True), (1000, True)])
def test_a_later_crossover_helps_at_every_sigma0(sigma0_attr, crossover_n, helps):
    """Oracle: a genie argument. The clock covariance is linear in sigma2^2 (random walk sigma1^2
    plus fractional Brownian sigma2^2 K, K positive definite), so the clock with the crossover
    at n (sigma2^2 = sigma0^2 / n) plus an independent fBm of variance scale sigma0^2 (1 - 1/n)
    is the clock with the crossover at 1; predicting the sum can only be worse than predicting
    the first part with the second known, and strictly for n > 1. At n = 1 the two clocks are
    one and the extrapolation is not smaller. Checked at the paper's three sigma0 (moved into
    the 5-ns input the claim reads) and the crossover input's readings 10, 100, 1000."""
    tr, cov = atc10_track_ex.TR, atc10_track_ex.IN_COV
    moved = {
        tr.input("sigma0_low_ns").name: getattr(tr, sigma0_attr),
        cov.input("sec47_crossover_n").name: crossover_n,
    }
    with overriding(moved):
        assert atc10_track_ex.crossover_100_helps() is helps


# --- KZL: heading observability with the default arguments ---------------------------------


def test_heading_observable_defaults_to_code_and_delta_range_with_eight_satellites():
    """Oracle: the docstring's defaults (``mode="tc"``: code and delta range; ``nu`` = 8) and the
    row-space test: the heading's unit vector e against the normalised rows of
    [H; HF; ...; HF^16], observable exactly when the least-squares residual is zero."""
    from navcore.inertial.error_model17 import ERROR_LAYOUT_17

    F, H = kzl_tc.table1_F(), np.atleast_2d(kzl_tc.code_doppler_rows(kzl_tc.table1_los(8)))
    rows = np.vstack([H @ np.linalg.matrix_power(F, k) for k in range(F.shape[0])])
    rows = rows[np.linalg.norm(rows, axis=1) > 0]
    rows = rows / np.linalg.norm(rows, axis=1)[:, None]
    e = np.zeros(F.shape[0])
    e[ERROR_LAYOUT_17.slice("misalignment").start + 2] = 1.0
    c = np.linalg.lstsq(rows.T, e, rcond=1e-9)[0]
    assert kzl_tc.heading_observable() == bool(np.linalg.norm(rows.T @ c - e) < 1e-6)


# --- WF Eq. (8) ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("relative_error", "holds"), [(0.0, True), (1e-13, True), (1e-9, False), (0.5, False)]
)
def test_eq8_identity_rejects_a_gradient_off_by_more_than_its_threshold(monkeypatch, relative_error, holds):
    """Oracle: a planted counter-example. Eq. (8) says ||df/dv|| = f0/c for every geometry; a
    velocity gradient scaled by 1 + e violates it by e, and the statement's check (relative
    deviation < 1e-12) must reject e = 1e-9 and 0.5 and accept the true gradient and e = 1e-13
    (just inside, round-off being 2e-16)."""
    true_gradient = wf_velocity.doppler_gradient_velocity

    def planted(*args, **kwargs):
        return true_gradient(*args, **kwargs) * (1.0 + relative_error)

    monkeypatch.setattr(wf_velocity, "doppler_gradient_velocity", planted)
    assert wf_velocity._eq8_identity() is holds


# --- WF Remark (ii): the statement's closeness --------------------------------------------


def test_remark2_generic_flips_at_its_declared_closeness():
    """Oracle: the statement's definition, |tr(bound)/tr(true) - 1| <= close_rel. With the
    closeness input moved just above the seeded generic case's distance from 1 the statement
    holds, just below it does not (at the convention's readings, 1 % and 10 %, it does not:
    the generic bound is not exact)."""
    gap = abs(wf_fusion.bound_tightness(1.0, "generic") - 1.0)
    name = wf_fusion.IN.input("close_rel").name
    for close, holds in ((gap * 1.01, True), (gap * 0.99, False), (0.01, False), (0.1, False)):
        with overriding({name: close}):
            assert wf_fusion.remark2_generic_exact() is holds, close


# --- SP Sec. 3.3: the CEP claims compute the reduced model's CEP --------------------------


@pytest.mark.parametrize(("arch", "power"), [("DI", 100.0), ("TC", 100.0), ("DI", 10.0), ("TC", 10.0)])
def test_cep_claims_compute_the_reduced_models_cep(arch, power):
    """Oracle: the claims' declaration (the book's value is the reduced model's exact CEP at
    impact, no sampling): each Fig. 3.6 claim computes ``model_cep`` of its architecture and
    jammer power, a positive length in metres."""
    from navcore import ledger

    claim = ledger.claim(f"SP-sec3.3-cep-{arch.lower()}-{int(power)}W")
    value = claim.compute()
    assert value == sp_antijam.model_cep(arch, power)
    assert math.isfinite(value) and value > 0.0


# --- SP Sec. 2.6.2: the sequential outage's systems ---------------------------------------


@pytest.mark.parametrize(("architecture", "asked"), [(None, ["loose", "tight"]), ("tight", ["tight"])])
def test_sequential_outage_runs_each_architecture_once_and_returns_the_five_systems(
    monkeypatch, architecture, asked
):
    """Oracle: the docstring: without an architecture the five systems of the table, loosely and
    tightly coupled, each architecture run once (the runs replaced here by a stand-in that
    records what is asked, so no mission is flown), returned in the table's order."""
    calls = []

    def stand_in(arch, free_inertial):
        calls.append(arch)
        return {s: (arch, s.grade) for s in sp_wiring.SYSTEMS if s.architecture == arch}

    monkeypatch.setattr(sp_flights, "_sequential_group", stand_in)
    out = sp_flights.sequential_outage(architecture=architecture)
    assert calls == asked
    assert list(out) == [s for s in sp_wiring.SYSTEMS if s.architecture in asked]
    assert all(v == (s.architecture, s.grade) for s, v in out.items())


# --- SP Sec. 2.5: the carrier loop's phase error in the flyby --------------------------------


@pytest.mark.parametrize("system", [sp_wiring.System("loose", 1.0), sp_wiring.System("tight", 1.0)])
def test_flyby_carrier_phase_is_k_sigma_thermal_jitter_plus_the_dynamic_error(system):
    """Oracle: Kaplan & Hegarty's PLL thermal jitter, sigma^2 = B_n/(C/N0) (1 + 1/(2 T C/N0)) rad^2,
    typed here with the system's loop noise bandwidth and the coherent time, times the k-sigma
    input, plus the loop's dynamic error: the phase error the lock rules compare with the
    carrier-loss limit, at every sample of the flyby (a jammer 20 dB above thermal at 100 km)."""
    jammer_db = 20.0
    loop = sp_flyby.carrier_loop(system)
    c = 10.0 ** (sp_flyby.effective_cn0(jammer_db) / 10.0)
    T = sp_flyby.IN.coherent_s
    jitter = np.degrees(np.sqrt(loop.bandwidth_hz / c * (1.0 + 1.0 / (2.0 * T * c))))
    dyn = sp_flyby.dynamic_phase_error_deg(loop.omega0, loop.aided, system.grade)
    expected = sp_flyby.IN.jitter_k_sigma * jitter + dyn
    np.testing.assert_allclose(sp_flyby.locks(system, jammer_db).carrier_phase_deg, expected, rtol=1e-12)


# --- SP Fig. 3.4: the guided munition's trajectory -----------------------------------------


def test_pgm_trajectory_is_sampled_every_second_from_launch():
    """Oracle: closed form of the Fig. 3.4 reconstruction: one sample a second from t = 1 s to the
    last whole second before the target range L at the assumed speed v (n = floor(L / v)),
    along-track x = v t, altitude the cruise altitude until the dive starts, then falling
    linearly towards the target (floored at 1 m)."""
    a = sp_antijam.IN
    length = a.target_range_nmi * 1852.0
    n = int(length // a.speed_mps)
    t, x, alt = sp_antijam.pgm_trajectory()
    np.testing.assert_array_equal(t, np.arange(1.0, n + 1.0))
    np.testing.assert_allclose(x, a.speed_mps * t, rtol=1e-15)
    to_go = length - x
    expected = np.where(to_go > a.dive_start_m, a.cruise_alt_m, a.cruise_alt_m * to_go / a.dive_start_m)
    np.testing.assert_allclose(alt, np.maximum(expected, 1.0), rtol=1e-12)


# --- SP Sec. 3.3: one jammer power or several --------------------------------------------


def test_pgm_js_db_of_one_power_is_a_history_and_scales_with_the_power():
    """Oracle: free space: J/S grows by 10 log10 of the power ratio at every sample (10 dB from
    10 W to 100 W), and one scalar power gives the history that the same power gives as a row
    of an array of powers (the docstring)."""
    one, ten = sp_antijam.pgm_js_db(10.0), sp_antijam.pgm_js_db(100.0)
    np.testing.assert_allclose(ten - one, 10.0, atol=1e-9)
    np.testing.assert_allclose(
        sp_antijam.pgm_js_db(np.array([10.0, 100.0])), np.vstack([one, ten]), rtol=1e-13
    )


@pytest.mark.parametrize("arch", ["TC", "DI"])
def test_fix_sigma_of_one_power_is_the_row_of_the_batched_call(arch):
    """Oracle: the docstring: the noise history of one jammer power (the Monte Carlo's call) is the
    row of that power in the batched call over powers (the exact model's), lock losses (NaN)
    included."""
    powers = np.array([10.0, 1000.0])
    batched = sp_antijam.fix_sigma_m(powers, arch, "wideband")
    for row, p in zip(batched, powers, strict=True):
        np.testing.assert_array_equal(sp_antijam.fix_sigma_m(float(p), arch, "wideband"), row)


# --- SP Sec. 3.3: the A/J improvement at equal CEP ----------------------------------------


@pytest.mark.parametrize("cep_m", [10.0, 30.0])
def test_aj_improvement_is_the_power_ratio_at_equal_cep(cep_m):
    """Oracle: the definition, solved independently. The TC and DI jammer powers (dB) at which the
    reduced model's CEP equals ``cep_m`` are found by root finding on the model's own curve
    (scipy's brentq on log CEP against 10 log10 P); their difference is the improvement, which
    the interpolation on the eighth-decade grid reproduces to 0.5 dB (0.3 dB at most here)."""
    powers_db = []
    for arch in ("TC", "DI"):

        def gap(x_db, arch=arch):
            return math.log(sp_antijam.model_cep(arch, 10 ** (x_db / 10))) - math.log(cep_m)

        powers_db.append(optimize.brentq(gap, -20.0, 60.0, xtol=1e-6))
    expected = powers_db[1] - powers_db[0]
    assert sp_antijam.aj_improvement_db("wideband", cep_m)[0] == pytest.approx(expected, abs=0.5)


# --- SP Sec. 2.6.3: the head-on mission starts along the assumed heading -------------------


@pytest.mark.parametrize("heading_deg", [0.0, 90.0, 180.0, 270.0])
def test_head_on_trajectory_starts_along_the_assumed_heading(heading_deg):
    """Oracle: the docstring ('from the assumed heading'): after take-off the aircraft's ground
    velocity points along the heading input, at each of its grid values (north, east, south,
    west)."""
    with overriding({sp_wiring.IN.input("heading_deg").name: heading_deg}):
        v = sp_flights.head_on_trajectory().vel_ned[1]
    azimuth = math.degrees(math.atan2(v[1], v[0])) % 360.0
    assert azimuth == pytest.approx(heading_deg, abs=1e-6)


# --- SP Table 2.5 --------------------------------------------------------------------------

#: SP Table 2.5 as printed (rows in the order of the table, columns 10, 1.0, 0.5, 0.2 nmi/h),
#: typed from the paper for this test.
PRINTED_TABLE_2_5 = {
    "accel_bias_micro_g": (223.0, 37.0, 19.0, 4.2),
    "accel_scale_factor_ppm": (223.0, 179.0, 90.0, 21.0),
    "accel_misalignment_arcsec": (22.0, 3.0, 1.5, 0.4),
    "accel_random_walk_micro_g_per_sqrt_hz": (56.0, 15.0, 7.5, 4.2),
    "gyro_bias_deg_per_h": (0.11, 0.0045, 0.0022, 0.00084),
    "gyro_scale_factor_ppm": (112.0, 7.5, 3.5, 1.67),
    "gyro_misalignment_arcsec": (22.0, 2.2, 1.1, 0.4),
    "gyro_random_walk_deg_per_h_per_sqrt_hz": (4.7, 0.13, 0.066, 0.03),
}


def test_table_2_5_printed_reads_every_cell():
    """Oracle: the printed Table 2.5, typed above; ``table_2_5_printed`` and the lazy view
    ``TABLE_2_5_PRINTED`` give it row by row in the printed order."""
    got = sp_tables.table_2_5_printed()
    assert list(got) == list(PRINTED_TABLE_2_5)
    assert got == PRINTED_TABLE_2_5
    assert dict(sp_tables.TABLE_2_5_PRINTED) == PRINTED_TABLE_2_5


# --- SP Table 2.8: the Doppler sensor's errors in the error sources ---------------------------


def test_error_sources_carry_table_2_8_doppler_errors():
    """Oracle: SP Table 2.8 as printed, typed here (bias 0.1 / 0.05 nmi/h, scale factor 0.25 % /
    0.1 %, boresight misalignment 2.0 mrad), in SI (1 nmi = 1852 m): the error sources of a
    system with the Doppler sensor carry every one of them, horizontal on the first two axes."""
    kt = 1852.0 / 3600.0
    src = sp_wiring.error_sources(sp_tables.sp_imu_grade(1.0), doppler=True)
    np.testing.assert_allclose(src.doppler_bias, (0.1 * kt, 0.1 * kt, 0.05 * kt), rtol=1e-12)
    np.testing.assert_allclose(src.doppler_scale_factor, (0.0025, 0.0025, 0.001), rtol=1e-12)
    assert src.doppler_misalignment == pytest.approx(2.0e-3, rel=1e-12)


# --- SP mission flights: the engine's inputs of the book's worked loop ---------------------


@pytest.mark.parametrize("seconds", [30.0, 10.0])
def test_engine_inputs_fly_the_first_seconds_of_the_sequential_outage(seconds):
    """Oracle: the docstring's definition. The trajectory is the sequential-outage mission's
    first ``seconds`` (its 1-s samples 0, 1, ..., seconds, both ends included: the mission's
    arrays sliced by index here), the a-priori covariance is square over the truth states, and
    the filter's added noise has one entry per filter state."""
    m = sp_flights.engine_inputs(sp_wiring.System("tight", 1.0), seconds=seconds)
    mission = sp_flights.sequential_outage_trajectory(sp_flights.end_free_s())
    n = int(seconds) + 1
    np.testing.assert_array_equal(m.trajectory.t, np.arange(n, dtype=float))
    for field in ("t", "lat", "lon", "h", "pos_ned", "vel_ned", "f_ned", "C_bn", "omega_nb_b"):
        np.testing.assert_array_equal(getattr(m.trajectory, field), getattr(mission, field)[:n])
    assert m.P0.shape == (m.truth.size, m.truth.size)
    assert len(m.filter_added_psd) == m.filter.size


def test_engine_inputs_refuse_a_loosely_coupled_system():
    """Oracle: the docstring: the engine's inputs are those of a tightly coupled system."""
    with pytest.raises(ValueError, match="tightly coupled"):
        sp_flights.engine_inputs(sp_wiring.System("loose", 1.0), seconds=10.0)
