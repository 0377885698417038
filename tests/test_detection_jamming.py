"""Tests of navcore.detection.jamming against independent oracles (mpmath, scipy, brute force)."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from scipy import optimize, stats

from navcore.detection import jamming as jm
from navcore.detection.neyman_pearson import detection_index_from_jammer_ratio
from navcore.figures import atc10_jamming as fj
from navcore.papers import atc10_jamming as paper

GEOM = paper.geometry()  # the paper's scenario: the library has no default geometry


def _mp_log_one_minus_power(p: mpmath.mpf, n: float) -> mpmath.mpf:
    return mpmath.log(-mpmath.expm1(n * mpmath.log1p(-p)))


def _mp_log_pf(x_db: float, p_d: float) -> mpmath.mpf:
    d = mpmath.mpf(float(detection_index_from_jammer_ratio(10 ** (x_db / 10))))
    z = d - mpmath.sqrt(2) * mpmath.erfinv(2 * mpmath.mpf(p_d) - 1)
    return mpmath.log(mpmath.erfc(z / mpmath.sqrt(2)) / 2)


def test_sample_counts() -> None:
    """Oracle: hand arithmetic, 2 B alpha = 2e7, 4 B beta = 9.6e5, (8/3) B v alpha / c = 23.8586."""
    assert GEOM.samples_per_period == 2e7
    assert GEOM.samples_per_delay_window == pytest.approx(9.6e5, rel=1e-15)
    assert GEOM.samples_per_track_window == pytest.approx(8 / 3 * 1e7 * (1 / 6) / 186282.397, rel=1e-6)
    assert GEOM.energy_bandwidth_dbw == pytest.approx(50.0, abs=1e-12)


@pytest.mark.parametrize("log10_p", [-0.5, -3, -6, -10, -17, -20, -40, -60, -200])
@pytest.mark.parametrize("n", [2e7, 9.6e5, 23.8586])
def test_log_one_minus_power_matches_mpmath(log10_p: float, n: float) -> None:
    """Oracle: ln(1 - (1-p)^n) at 80 digits with mpmath."""
    with mpmath.workdps(80):
        expected = float(_mp_log_one_minus_power(mpmath.mpf(10) ** log10_p, n))
    got = float(jm.log_one_minus_power(log10_p * math.log(10), n))
    assert got == pytest.approx(expected, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("a", [1e-300, 1e-20, 1e-5, 0.5, math.log(2), 1.0, 30.0, 800.0])
def test_log1mexp_matches_mpmath(a: float) -> None:
    """Oracle: mpmath log(1 - exp(-a)) at 50 digits."""
    with mpmath.workdps(50):
        expected = float(mpmath.log(-mpmath.expm1(-mpmath.mpf(a))))
    assert float(jm.log1mexp(a)) == pytest.approx(expected, rel=1e-14, abs=1e-300)


@pytest.mark.parametrize(("t", "q"), [(0.05, 0.3), (0.2, 0.5), (0.01, 0.0069), (0.4, 0.3), (0.3, 0.9)])
def test_exponent_closed_form_matches_numeric_maximisation(t: float, q: float) -> None:
    """Oracle: bounded numerical maximisation over nu >= 0 of nu(1-t) - ln((1-q) e^nu + q)."""

    def neg(nu: float) -> float:
        return -(nu * (1 - t) - (nu + math.log((1 - q) + q * math.exp(-nu))))

    res = optimize.minimize_scalar(neg, bounds=(0.0, 60.0), method="bounded", options={"xatol": 1e-12})
    numeric = max(-res.fun, 0.0)
    assert float(jm.list_rule_exponent(t, q)) == pytest.approx(numeric, abs=1e-10)
    if t < q:
        assert float(jm.list_rule_optimal_nu(t, q)) == pytest.approx(res.x, rel=1e-4)


def test_t_zero_bound_is_exact_binomial() -> None:
    """Oracle: scipy.stats.binom, P(at least one of K lists non-empty) = 1 - (1-q)^K."""
    for k in (1, 10, 100, 1000):
        for p_d in (0.2145, 0.5, 0.84):
            q = p_d**4
            exact = stats.binom.sf(0, k, q)
            assert float(jm.detection_lower_bound(p_d, k, 0.0)) == pytest.approx(exact, rel=1e-12)


def test_bound_below_exact_for_positive_t() -> None:
    """Oracle: the exact binomial probability of the (A.11) rule dominates the Chernoff bound."""
    for k in (10, 100, 1000):
        for t in (0.05, 0.1, 0.3):
            for q in np.linspace(0.05, 0.95, 19):
                bound = float(jm.detection_lower_bound(q**0.25, k, t))
                assert bound <= float(jm.list_rule_detection_probability(q, k, t)) + 1e-15


def test_design_point_inversion() -> None:
    """Oracle: the forward definitions: at t = 0, P(at least one of K lists non-empty) with
    scipy.stats.binom and q = p_d^4; for t > 0 the forward bound (itself checked against mpmath)."""
    for k, p_dl in ((1, 0.88), (10, 0.88), (250, 0.999)):
        p_d = jm.filter_detection_probability_for_bound(p_dl, k)
        assert stats.binom.sf(0, k, p_d**4) == pytest.approx(p_dl, rel=1e-12)
        assert jm.list_probability_for_detection_bound(p_dl, k) == pytest.approx(p_d**4, rel=1e-13)
    for k, t in ((10, 0.1), (100, 0.05), (1000, 0.2)):
        p_d = jm.filter_detection_probability_for_bound(0.999, k, t)
        assert float(jm.detection_lower_bound(p_d, k, t)) == pytest.approx(0.999, rel=1e-10)


def test_literal_a9_rule_differs() -> None:
    """Oracle: binomial probabilities of the two readings at K=10, q=0.3, t=0.2."""
    assert float(jm.empty_list_rule_detection_probability(0.3, 10, 0.2)) == pytest.approx(
        stats.binom.cdf(2, 10, 0.7), rel=1e-12
    )
    assert float(jm.list_rule_detection_probability(0.3, 10, 0.2)) == pytest.approx(
        stats.binom.sf(2, 10, 0.3)
    )


@pytest.mark.parametrize(
    ("x_db", "k", "p_d"), [(-10.0, 1000, 0.288), (0.0, 1000, 0.288), (-18.0, 1, 0.9685), (-8.0, 10, 0.66)]
)
def test_ambiguous_bound_matches_mpmath(x_db: float, k: int, p_d: float) -> None:
    """Oracle: the whole N_ADL product (K-1 factors of G) evaluated directly at 60 digits."""
    with mpmath.workdps(60):
        pf = mpmath.exp(_mp_log_pf(x_db, p_d))
        q = mpmath.mpf(p_d) ** 4
        pdl = 1 - (1 - q) ** k
        f = _mp_log_one_minus_power(pf, 2e7) + 3 * _mp_log_one_minus_power(pf, 9.6e5)
        g = _mp_log_one_minus_power(pf, 2e7) + 3 * _mp_log_one_minus_power(pf, GEOM.samples_per_track_window)
        expected = float(mpmath.log(mpmath.mpf("0.05") * pdl) + (k - 1) * g + f)
    got = float(jm.log_ambiguous_detection_bound(10 ** (x_db / 10), p_d, k, 0.0, GEOM))
    assert got == pytest.approx(expected, rel=1e-11)


def _figure_sweep_cases() -> list:
    """Every (quantity, K, P_DL, t) that Figs. 2.1-2.16 draw, with the figure's J range in dB.

    The ranges are widened to include -40..+20 dB (the original sweep) for every case.
    """
    cases = []
    for p_dl in fj.K1_PDL:
        for quantity in ("false", "ambiguous"):
            cases.append(
                pytest.param(quantity, 1, p_dl, 0.0, (-40.0, 20.0), id=f"{quantity}-K1-pdl{p_dl}-t0")
            )
    for _, quantity, k, p_dl in fj.K_FIGURES:
        for t in fj.T_VALUES:
            cases.append(
                pytest.param(quantity, k, p_dl, t, (-40.0, 80.0), id=f"{quantity}-K{k}-pdl{p_dl}-t{t:g}")
            )
    return cases


def _mp_log_bound(quantity: str, x_db: float, p_d: float, k: int, t: float) -> float:
    """ln N_FL/N_T or ln N_ADL/N_T of (2.5.5)/(2.5.12) at 60 digits, with P_DL = 1 - exp(-K D(t || q))."""
    with mpmath.workdps(60):
        pf = mpmath.exp(_mp_log_pf(x_db, p_d))
        f = _mp_log_one_minus_power(pf, 2e7) + 3 * _mp_log_one_minus_power(pf, 9.6e5)
        if quantity == "false":
            return float(mpmath.log(mpmath.mpf("0.9")) + (k * mpmath.mpf(t) + 1) * f)
        q = mpmath.mpf(p_d) ** 4
        tt = mpmath.mpf(t)
        if t == 0:
            div = -mpmath.log(1 - q)
        else:
            div = tt * mpmath.log(tt / q) + (1 - tt) * mpmath.log((1 - tt) / (1 - q))
        pdl = -mpmath.expm1(-k * div)
        g = _mp_log_one_minus_power(pf, 2e7) + 3 * _mp_log_one_minus_power(pf, GEOM.samples_per_track_window)
        return float(mpmath.log(mpmath.mpf("0.05") * pdl) + (k - 1) * g + f)


@pytest.mark.parametrize(("quantity", "k", "p_dl", "t", "x_range"), _figure_sweep_cases())
def test_figure_sweeps_are_finite_exact_and_monotone(
    quantity: str, k: int, p_dl: float, t: float, x_range: tuple[float, float]
) -> None:
    """Oracle: 60-digit mpmath at the ends and the middle of the sweep, plus properties.

    Every bound the figures draw, on a 0.1 dB grid over the figure's range (and -40..+20 dB), with
    every numpy floating-point error raising, underflow included: no NaN, no -inf (a silent zero in
    the linear domain), non-decreasing in J, and equal to the 60-digit value where a clamp or an
    underflowed intermediate would show (the low end, where the bounds are smallest).
    """
    lo, hi = x_range
    x_db = np.linspace(lo, hi, round((hi - lo) * 10) + 1)
    p_d = paper.design_p_d(p_dl, k, t)
    fn = jm.log_false_location_bound if quantity == "false" else jm.log_ambiguous_detection_bound
    with np.errstate(all="raise"):
        log_bound = np.asarray(fn(10 ** (x_db / 10), p_d, k, t, GEOM))
        log10_fig = fj.log10_bound(quantity, x_db, p_dl, k, t)
    assert log_bound.shape == x_db.shape
    assert np.all(np.isfinite(log_bound)) and np.all(np.isfinite(log10_fig))
    assert np.all(np.diff(log_bound) >= -1e-12)
    np.testing.assert_allclose(log10_fig, log_bound / math.log(10), rtol=1e-14, atol=0)
    # no silent zero: wherever the bound is representable as a float, it is strictly positive
    representable = log_bound > math.log(np.finfo(float).tiny)
    with np.errstate(under="ignore"):
        assert np.all(np.exp(log_bound[representable]) > 0)
    # the bound stays below its J -> inf ceiling, which the top of every K > 1 range approaches
    ceil = (jm.log_false_location_ceiling if quantity == "false" else jm.log_ambiguous_detection_ceiling)(
        p_d, k, t, GEOM
    )
    assert np.all(log_bound <= ceil + 1e-12 * abs(ceil))
    for i in (0, len(x_db) // 2, len(x_db) - 1):
        expected = _mp_log_bound(quantity, float(x_db[i]), p_d, k, t)
        assert float(log_bound[i]) == pytest.approx(expected, rel=1e-10, abs=1e-12)


def test_bounds_approach_ceiling_as_jamming_grows() -> None:
    """Oracle: p_f -> p_d as J -> inf, so the bounds approach their J = inf values."""
    for k, p_dl in ((1, 0.88), (100, 0.999), (1000, 0.999)):
        p_d = jm.filter_detection_probability_for_bound(p_dl, k)
        for fn, ceil in (
            (jm.log_false_location_bound, jm.log_false_location_ceiling),
            (jm.log_ambiguous_detection_bound, jm.log_ambiguous_detection_ceiling),
        ):
            assert float(fn(1e12, p_d, k, 0.0, GEOM)) == pytest.approx(ceil(p_d, k, 0.0, GEOM), abs=1e-4)
    assert math.exp(jm.log_false_location_ceiling(0.9, 1, 0.0, GEOM)) == pytest.approx(0.9, rel=1e-15)


def test_threshold_root_and_infinite_case() -> None:
    """Oracle: re-evaluating the bound at the returned root gives the level; ceiling < level gives inf."""
    p_d = jm.filter_detection_probability_for_bound(0.88, 100)
    x_db = jm.jammer_ratio_threshold_db("ambiguous", 0.01, p_d, 100, 0.0, GEOM)
    assert math.exp(
        float(jm.log_ambiguous_detection_bound(10 ** (x_db / 10), p_d, 100, 0.0, GEOM))
    ) == pytest.approx(0.01, rel=1e-8)
    p_d = jm.filter_detection_probability_for_bound(0.98, 1000)
    assert jm.jammer_ratio_threshold_db("ambiguous", 0.01, p_d, 1000, 0.0, GEOM) == math.inf
    assert jm.jammer_ratio_threshold_db("false", 0.9, 0.9, 1, 0.0, GEOM) == math.inf
    with pytest.raises(ValueError):
        jm.jammer_ratio_threshold_db("other", 0.01, 0.9, 1, 0.0, GEOM)
    with pytest.raises(ValueError):
        jm.detection_lower_bound(0.5, 0)


def test_erp_conversion() -> None:
    """Oracle: 10 mJ x 10 MHz = 1e5 W = 50 dBW (both arguments required: no paper default)."""
    assert float(jm.jammer_erp_dbw(0.0, 10e-3, 10e6)) == pytest.approx(50.0, abs=1e-12)
    with pytest.raises(TypeError):
        jm.jammer_erp_dbw(0.0)  # type: ignore[call-arg]
    with pytest.raises(TypeError):
        jm.SurveillanceGeometry()  # type: ignore[call-arg]


# A geometry unlike the paper's (every count different), for the closed-form checks below.
OTHER = jm.SurveillanceGeometry(
    bandwidth_hz=2.5e6,
    repetition_s=0.8,
    differential_delay_s=0.004,
    max_speed_m_s=250.0,
    airborne_fraction=0.3,
    pulse_energy_j=4e-3,
)


def test_sample_counts_of_another_geometry() -> None:
    """Oracle: hand arithmetic, 2 B alpha = 4e6, 4 B beta = 4e4, (8/3) B v alpha / c, and
    10 log10(4e-3 J x 2.5e6 Hz) = 40 dBW."""
    assert OTHER.samples_per_period == pytest.approx(4e6, rel=1e-15)
    assert OTHER.samples_per_delay_window == pytest.approx(4e4, rel=1e-15)
    assert OTHER.samples_per_track_window == pytest.approx(
        8 / 3 * 2.5e6 * 250.0 * 0.8 / 299_792_458.0, rel=1e-15
    )
    assert OTHER.energy_bandwidth_dbw == pytest.approx(40.0, abs=1e-12)


def _mp_bounds(log_pf: mpmath.mpf, p_d: float, k: int, t: float, g: jm.SurveillanceGeometry) -> tuple:
    """ln N_FL/N_T and ln N_ADL/N_T at 60 digits from ln p_f, written from (2.5.5), (2.5.12),
    (B.6), (C.14) and P_DL = 1 - exp(-K D(t || p_d^4))."""
    with mpmath.workdps(60):
        pf = mpmath.exp(log_pf)
        f = _mp_log_one_minus_power(pf, g.samples_per_period) + 3 * _mp_log_one_minus_power(
            pf, g.samples_per_delay_window
        )
        gg = _mp_log_one_minus_power(pf, g.samples_per_period) + 3 * _mp_log_one_minus_power(
            pf, g.samples_per_track_window
        )
        q, tt = mpmath.mpf(p_d) ** 4, mpmath.mpf(t)
        div = (
            -mpmath.log(1 - q)
            if t == 0
            else tt * mpmath.log(tt / q) + (1 - tt) * mpmath.log((1 - tt) / (1 - q))
        )
        pdl = -mpmath.expm1(-k * div)
        nfl = mpmath.log(1 - mpmath.mpf(g.airborne_fraction)) + (k * tt + 1) * f
        nadl = mpmath.log(mpmath.mpf(g.airborne_fraction) / 2 * pdl) + (k - 1) * gg + f
        return float(nfl), float(nadl)


@pytest.mark.parametrize(("k", "t"), [(1, 0.0), (7, 0.0), (20, 0.15), (300, 0.05)])
def test_bounds_and_ceilings_of_another_geometry_match_mpmath(k: int, t: float) -> None:
    """Oracle: _mp_bounds at 60 digits; the ceilings (J -> inf) at p_f = p_d exactly."""
    p_d = 0.8
    q = p_d**4
    if t >= q:
        pytest.skip("vacuous")
    for x_db in (-12.0, 0.0, 9.0):
        with mpmath.workdps(60):
            log_pf = _mp_log_pf(x_db, p_d)
        nfl, nadl = _mp_bounds(log_pf, p_d, k, t, OTHER)
        x = 10 ** (x_db / 10)
        assert float(jm.log_false_location_bound(x, p_d, k, t, OTHER)) == pytest.approx(nfl, rel=1e-10)
        assert float(jm.log_ambiguous_detection_bound(x, p_d, k, t, OTHER)) == pytest.approx(nadl, rel=1e-10)
    nfl, nadl = _mp_bounds(mpmath.log(mpmath.mpf(p_d)), p_d, k, t, OTHER)
    assert jm.log_false_location_ceiling(p_d, k, t, OTHER) == pytest.approx(nfl, rel=1e-12, abs=1e-14)
    assert jm.log_ambiguous_detection_ceiling(p_d, k, t, OTHER) == pytest.approx(nadl, rel=1e-12)
    with mpmath.workdps(40):
        tt, qq = mpmath.mpf(t), mpmath.mpf(q)
        div = (
            -mpmath.log(1 - qq)
            if t == 0
            else tt * mpmath.log(tt / qq) + (1 - tt) * mpmath.log((1 - tt) / (1 - qq))
        )
        log_pdl = float(mpmath.log(-mpmath.expm1(-k * div)))
    assert float(jm.log_detection_lower_bound(p_d, k, t)) == pytest.approx(log_pdl, rel=1e-12, abs=1e-15)
    assert float(jm.detection_lower_bound(p_d, k, t)) == pytest.approx(math.exp(log_pdl), rel=1e-12)


def test_threshold_search_bracket_and_false_quantity() -> None:
    """Oracle: forward re-evaluation of the bound at the returned root; the bracket's ends: a
    level the bound passes below the lower end raises, one it reaches only above the upper end
    gives inf, one inside the bracket is found (the defaults are -60 and +160 dB)."""
    p_d, k, t = 0.8, 7, 0.0

    def level_at(x_db: float, quantity: str = "ambiguous") -> float:
        fn = jm.log_false_location_bound if quantity == "false" else jm.log_ambiguous_detection_bound
        return math.exp(float(fn(10 ** (x_db / 10), p_d, k, t, OTHER)))

    for quantity, points in (("false", (-25.0, -17.0)), ("ambiguous", (-6.0, 3.5))):
        for x_db in points:
            got = jm.jammer_ratio_threshold_db(quantity, level_at(x_db, quantity), p_d, k, t, OTHER)
            assert got == pytest.approx(x_db, abs=1e-7)
    with pytest.raises(ValueError, match="lower_db"):
        jm.jammer_ratio_threshold_db("ambiguous", level_at(-3.0), p_d, k, t, OTHER, lower_db=-2.0)
    assert jm.jammer_ratio_threshold_db("ambiguous", level_at(-3.0), p_d, k, t, OTHER, lower_db=-4.0) == (
        pytest.approx(-3.0, abs=1e-7)
    )
    assert (
        jm.jammer_ratio_threshold_db("ambiguous", level_at(-3.0), p_d, k, t, OTHER, upper_db=-4.0) == math.inf
    )
    # the default upper end, 160 dB: with K = 7 the bound still creeps up there (p_f -> p_d like
    # 1/sqrt(x)), so a level reached at 159.5 dB is found and one reached at 160.5 dB is not
    assert jm.jammer_ratio_threshold_db("ambiguous", level_at(159.5), p_d, k, t, OTHER) == pytest.approx(
        159.5, abs=0.05
    )
    assert jm.jammer_ratio_threshold_db("ambiguous", level_at(160.5), p_d, k, t, OTHER) == math.inf
    # a level at or above the ceiling is never reached
    ceiling = math.exp(jm.log_ambiguous_detection_ceiling(p_d, k, t, OTHER))
    assert jm.jammer_ratio_threshold_db("ambiguous", ceiling, p_d, k, t, OTHER) == math.inf


def test_divergence_and_optimal_tilt() -> None:
    """Oracles: scipy.stats.entropy of the two Bernoulli laws; the tilt nu* from the stationarity
    of nu (1 - t) - ln((1 - q) e^nu + q) solved by brentq; inf at t = 0, 0 for t >= q."""
    for t, q in ((0.0, 0.3), (0.1, 0.3), (0.6, 0.2), (0.999, 0.4), (0.35, 0.35)):
        assert float(jm.binary_divergence(t, q)) == pytest.approx(
            stats.entropy([t, 1 - t], [q, 1 - q]), abs=1e-15
        )
    for t, q in ((0.1, 0.3), (0.02, 0.9), (0.4, 0.45)):
        nu = optimize.brentq(
            lambda v, t=t, q=q: (1 - t) - (1 - q) * math.exp(v) / ((1 - q) * math.exp(v) + q), 0, 50
        )
        assert float(jm.list_rule_optimal_nu(t, q)) == pytest.approx(nu, rel=1e-9)
    assert float(jm.list_rule_optimal_nu(0.0, 0.3)) == math.inf
    assert float(jm.list_rule_optimal_nu(0.5, 0.3)) == 0.0
    assert float(jm.list_rule_exponent(0.5, 0.3)) == 0.0
    assert float(jm.log1mexp(0.0)) == -math.inf
    assert -1e-300 < float(jm.log1mexp(800.0)) <= 0.0  # -e^-800 is below the smallest normal double


@pytest.mark.parametrize("log_p", [-19.99, -20.01, -29.99, -30.01, -31.0, -45.0, -700.5, -800.0])
@pytest.mark.parametrize("n", [1.0, 3.7, 2e7])
def test_log_one_minus_power_to_the_last_bits(log_p: float, n: float) -> None:
    """Oracle: mpmath at 60 digits, to 1e-15 relative (a few units in the last place), on both
    sides of the switches between series and direct forms (ln p = -20, ln u = -30) and below
    the exp(-700) underflow guard; n = 1 gives ln(1 - (1 - p)) = ln p exactly."""
    with mpmath.workdps(60):
        expected = float(_mp_log_one_minus_power(mpmath.exp(mpmath.mpf(log_p)), n))
    assert float(jm.log_one_minus_power(log_p, n)) == pytest.approx(expected, rel=1e-15, abs=0)


def test_edge_inputs_of_the_log_helpers() -> None:
    """Oracles: exact values and the validation contract. ln(1 - (1-p)^n) = 0 (to 1e-300) when
    (1-p)^n underflows (n = 1e305, 1e308); ln p = -20 exactly sits on the series switch (mpmath);
    p = 1 (ln p = 0) and a negative argument of ln(1 - e^-a) are rejected; the literal (A.9)
    rule at its default t = 0 is q^K."""
    for log_p, n in ((math.log(0.5), 1e305), (-1e-10, 1e308)):  # ln u up to 712: e^u would overflow
        assert -1e-300 < float(jm.log_one_minus_power(log_p, n)) <= 0.0
    with mpmath.workdps(60):
        expected = float(_mp_log_one_minus_power(mpmath.exp(mpmath.mpf(-20)), 3.7))
    assert float(jm.log_one_minus_power(-20.0, 3.7)) == pytest.approx(expected, rel=1e-15)
    with pytest.raises(ValueError, match="log_p"):
        jm.log_one_minus_power(0.0, 5.0)
    with pytest.raises(ValueError):
        jm.log1mexp(-0.5)
    assert float(jm.empty_list_rule_detection_probability(0.6, 3)) == pytest.approx(0.6**3, rel=1e-14)


def test_geometry_validation_and_tiny_sample_counts() -> None:
    """Oracles: the validation contract (N/N_T strictly below 1), and 50-digit mpmath ceilings for
    a geometry with only a few samples per window, where F(p_d) and G(p_d) differ from 1 and so
    the J -> inf ceilings depend on every factor of (2.5.5) and (2.5.12)."""
    fields = dict(
        bandwidth_hz=2.0, repetition_s=1.0, differential_delay_s=0.1, max_speed_m_s=3e7, pulse_energy_j=1.0
    )
    with pytest.raises(ValueError, match="airborne_fraction"):
        jm.SurveillanceGeometry(**fields, airborne_fraction=1.0)
    tiny = jm.SurveillanceGeometry(**fields, airborne_fraction=0.4)
    assert tiny.samples_per_period == 4.0 and tiny.samples_per_delay_window == pytest.approx(0.8, rel=1e-15)
    for p_d, k, t in ((0.5, 1, 0.0), (0.6, 3, 0.0), (0.7, 6, 0.1)):
        nfl, nadl = _mp_bounds(mpmath.log(mpmath.mpf(p_d)), p_d, k, t, tiny)
        assert -10 < nfl < -0.6  # F well below 1: the exponent K t + 1 matters
        assert jm.log_false_location_ceiling(p_d, k, t, tiny) == pytest.approx(nfl, rel=1e-12)
        assert jm.log_ambiguous_detection_ceiling(p_d, k, t, tiny) == pytest.approx(nadl, rel=1e-12)
