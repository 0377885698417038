"""Tests of navcore.detection.roc_bounds against exact tails, Monte Carlo and closed forms."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import sympy as sp
from scipy import optimize, special

from navcore.detection.multiple_access import (
    GaussianDensity,
    MultipleAccessNoise,
    PointMassDensity,
    TriangularDensity,
    UniformDensity,
    gaussian_mixture_exact_tail,
    stratified_tail,
    two_point_density,
    two_point_exact_tail,
)
from navcore.detection.roc_bounds import (
    NegatedCGF,
    chernoff_log_tail,
    chernoff_log_tails,
    exponent_from_gaussian_exponent,
    exponent_from_gaussian_exponent_large_n,
    gallager_log_tail_lower,
    gallager_log_tails_lower,
    gated_cosh_log_curvature,
    gaussian_chernoff_exponent,
    gaussian_roc,
    quasi_optimal_amplitude,
    quasi_optimal_chernoff_parameter,
    quasi_optimal_exponent,
    quasi_optimal_exponent_approx,
    roc_lower_bound,
    roc_upper_bound,
)

N, TA = 100_000, 2e-5


def _noise(dens):
    return MultipleAccessNoise(N, TA, dens)


def test_chernoff_optimum_matches_bounded_scalar_minimisation():
    """Oracle: scipy.optimize.minimize_scalar of mu(r) - r t on a bracket."""
    noise = _noise(UniformDensity(1 / 75))
    for t in (0.2, 0.5, 0.8):
        res = optimize.minimize_scalar(
            lambda r, t=t: float(noise.cgf(r)) - r * t,
            bounds=(0, 200),
            method="bounded",
            options={"xatol": 1e-10},
        )
        b = chernoff_log_tail(noise, t)
        assert b.log_p == pytest.approx(res.fun, abs=1e-8)
    assert chernoff_log_tail(noise, -0.1).log_p == 0.0


def test_chernoff_infinite_when_support_cannot_reach():
    """Oracle: a bounded sum cannot exceed (N-1) max|x|."""
    small = MultipleAccessNoise(3, 0.25, PointMassDensity((-1.0, 1.0), (0.5, 0.5)))
    assert chernoff_log_tail(small, 2.5).log_p == -np.inf


@pytest.mark.parametrize("x", [3, 5, 6])
@pytest.mark.parametrize("kind", ["two-point", "uniform", "triangular", "Gaussian"])
def test_bounds_bracket_monte_carlo_exact_rates(x, kind):
    """Oracle: seeded stratified Monte Carlo (and exact sums for the two-point and Gaussian C).

    The Chernoff upper bound must never be below the simulated rate beyond 4 standard errors,
    and the corrected Gallager lower bound never above it.
    """
    b = 1 / (3 * x**2)
    dens = {
        "two-point": two_point_density(b),
        "uniform": UniformDensity(b),
        "triangular": TriangularDensity(b),
        "Gaussian": GaussianDensity(b),
    }[kind]
    noise = _noise(dens)
    th = np.array([0.3, 0.5, 0.7])
    est = stratified_tail(noise, th, 4000, np.random.default_rng(x))
    ub_f, ub_m = roc_upper_bound(noise, th)
    lb_f, lb_m = roc_lower_bound(noise, th)
    assert np.all(est.upper <= np.exp(ub_f) + 4 * est.upper_se)
    assert np.all(np.exp(lb_f) <= est.upper + 4 * est.upper_se)
    mest = stratified_tail(noise, 1 - th, 4000, np.random.default_rng(x + 100))
    miss, se = mest.lower, mest.lower_se
    assert np.all(miss <= np.exp(ub_m) + 4 * se)
    assert np.all(np.exp(lb_m) <= miss + 4 * se)
    if kind == "two-point":
        exact = two_point_exact_tail(np.sqrt(b), N - 1, 2 * TA, th)
    elif kind == "Gaussian":
        exact = gaussian_mixture_exact_tail(b, N - 1, 2 * TA, th)
    else:
        return
    assert np.all(np.exp(lb_f) <= exact) and np.all(exact <= np.exp(ub_f))


def test_gallager_bound_on_gaussian_against_exact_q_function():
    """Oracle: Q(t/sigma) for a Gaussian sum (many interferers, each Gaussian): lb <= Q <= ub."""
    noise = MultipleAccessNoise(2_000_000, 0.25, GaussianDensity(1e-6))
    var = noise.power
    for t in (0.5, 1.0, 1.5):
        exact = special.log_ndtr(-t / np.sqrt(var))
        assert gallager_log_tail_lower(noise, t).log_p <= exact <= chernoff_log_tail(noise, t).log_p


def test_negated_cgf_is_mirror_for_symmetric_density():
    """Oracle: symmetry of C implies mu(-s) = mu(s)."""
    noise = _noise(TriangularDensity(0.01))
    neg = NegatedCGF(noise)
    s = np.array([0.3, 3.0])
    np.testing.assert_allclose(neg.cgf(s), noise.cgf(s))
    np.testing.assert_allclose(neg.cgf_d1(s), -noise.cgf_d1(-s))


@pytest.mark.parametrize(("x", "theta"), [(3, 0.3), (3, 0.5), (3, 0.7), (5, 0.5), (5, 0.7)])
def test_quasi_optimal_closed_form_matches_numerical_chernoff(x, theta):
    """Oracle: the Chernoff optimum of the two-point density found numerically with scipy
    (brentq on the derivative of (N-1) ln(1 - q + q cosh(r a)) - r theta, written here from
    Eq. 3.7.1's atoms +-a with a^2 (N-1) q = p), Eqs. 3.7.21-3.7.24."""
    b = 1 / (3 * x**2)
    q, a = 2 * TA, np.sqrt(b)
    p = (N - 1) * q * b
    assert quasi_optimal_amplitude(p, N, TA) == pytest.approx(a, rel=1e-14)

    def mu(r):
        return (N - 1) * np.log1p(q * (np.cosh(r * a) - 1.0))

    def dmu(r):
        return (N - 1) * q * a * np.sinh(r * a) / (1.0 - q + q * np.cosh(r * a))

    r_star = optimize.brentq(lambda r: dmu(r) - theta, 0.0, 200.0, xtol=1e-14, rtol=1e-15)
    exponent = r_star * theta - mu(r_star)
    assert quasi_optimal_chernoff_parameter(theta, p, N, TA) == pytest.approx(r_star, rel=1e-9)
    assert quasi_optimal_exponent(theta, p, N, TA) == pytest.approx(exponent, rel=1e-10)
    assert -chernoff_log_tail(_noise(two_point_density(b)), theta).log_p == pytest.approx(exponent, rel=1e-9)
    # (3.7.26)/(3.7.27): N for N - 1, q sinh x = theta / (N a') with a' = sqrt(p / (N q)) (the
    # atanh term and the 1 - q dropped), solved numerically here
    a_n = np.sqrt(p / (N * q))
    x_ap = optimize.brentq(lambda z: N * q * a_n * np.sinh(z) - theta, 0.0, 50.0, xtol=1e-15, rtol=1e-15)
    approx = x_ap / a_n * theta - N * np.log1p(q * (np.cosh(x_ap) - 1.0))
    assert quasi_optimal_exponent_approx(theta, p, N, TA) == pytest.approx(approx, rel=1e-11)
    assert quasi_optimal_exponent_approx(theta, p, N, TA) == pytest.approx(exponent, rel=1e-4)


def test_gaussian_roc_and_its_chernoff_bound():
    """Oracles: scipy.special.erfc for both sides of ROC_g (Eq. 3.8.1-3.8.3), and the Gaussian
    Chernoff exponent as the numerical minimum over r of p r^2/2 - r theta (scipy)."""
    p = 4 / 75
    th = np.array([0.05, 0.3, 0.5, 0.8, 0.95])
    lpf, lmiss = gaussian_roc(th, p)
    np.testing.assert_allclose(np.exp(lpf), 0.5 * special.erfc(th / np.sqrt(2 * p)), rtol=1e-12)
    np.testing.assert_allclose(np.exp(lmiss), 0.5 * special.erfc((1 - th) / np.sqrt(2 * p)), rtol=1e-12)
    for t in th:
        res = optimize.minimize_scalar(
            lambda r, t=t: 0.5 * p * r**2 - r * t, bounds=(0, 100), method="bounded"
        )
        assert float(gaussian_chernoff_exponent(t, p)) == pytest.approx(-res.fun, rel=1e-8)
    assert np.all(lpf <= -gaussian_chernoff_exponent(th, p))
    assert np.all(lmiss <= -gaussian_chernoff_exponent(1 - th, p))


def test_exponent_from_gaussian_matches_closed_form_and_limits():
    """Oracles: (3.8.16) is (3.7.26)/(3.7.27) with theta eliminated through Exp_g = theta^2/(2p),
    for any p (checked against the numerically solved large-N form above); the exact
    quasi-optimal exponent (N - 1 interferers) at large N; sympy's series of (3.8.16) in 1/N for
    the first-order expansion; and Exp <= Exp_g (the two-point density is the worst case)."""
    for n, ta, g, p in ((200_000, 1e-5, 12.5, 0.02), (100_000, 1e-5, 4.0, 0.3), (500, 0.01, 2.0, 0.05)):
        theta = np.sqrt(2 * p * g)
        assert exponent_from_gaussian_exponent(n, ta, g) == pytest.approx(
            quasi_optimal_exponent_approx(theta, p, n, ta), rel=1e-12
        )
    n, ta, g, p = 200_000, 1e-5, 12.5, 0.02
    exact = quasi_optimal_exponent(np.sqrt(2 * p * g), p * (n - 1) / n, n, ta)
    assert exponent_from_gaussian_exponent(n, ta, g) == pytest.approx(exact, rel=1e-3)
    eps, r, gs = sp.symbols("epsilon r g", positive=True)
    nn = 1 / eps
    u = gs / (nn * r)
    full = sp.sqrt(4 * nn * r * gs) * sp.asinh(sp.sqrt(u)) - nn * sp.log(1 - 2 * r + 2 * r * sp.sqrt(1 + u))
    first = sp.series(full, eps, 0, 2).removeO()
    for n, ta, g in ((1e8, 1e-5, 4.0), (1e4, 0.003, 7.0), (300.0, 0.05, 1.5)):
        expected = float(first.subs({eps: 1 / sp.Float(n), r: ta, gs: g}))
        assert exponent_from_gaussian_exponent_large_n(n, ta, g) == pytest.approx(expected, rel=1e-12)
    big = exponent_from_gaussian_exponent(1e8, 1e-5, 4.0)
    assert big == pytest.approx(exponent_from_gaussian_exponent_large_n(1e8, 1e-5, 4.0), abs=1e-5)
    grid_n = np.logspace(2, 9, 60)[:, None]
    grid_g = np.linspace(0.1, 30, 40)[None, :]
    e = exponent_from_gaussian_exponent(grid_n, 1e-5, grid_g)
    assert np.all(e <= grid_g + 1e-7)
    assert np.all(np.diff(e, axis=0) > 0)


# An asymmetric case small enough to enumerate: three interferers, q = 0.3, atoms at dyadic
# rationals (exact sums). The two sides of the ROC then differ, so a sign slip shows.
ATOMS, ATOM_W = (-0.5, 0.25, 0.75), (0.25, 0.5, 0.25)


def _enumerated_law():
    """Exact law of the noise by enumerating all 4^3 interferer states (the model's definition)."""
    states = [(0.0, 0.7)] + [(v, 0.3 * w) for v, w in zip(ATOMS, ATOM_W, strict=True)]
    law: dict[float, float] = {}
    for combo in itertools.product(states, repeat=3):
        x = sum(c[0] for c in combo)
        law[x] = law.get(x, 0.0) + float(np.prod([c[1] for c in combo]))
    x = np.array(sorted(law))
    return x, np.array([law[v] for v in x])


def _tilted(x, p, r):
    """ln E e^{rX}, and the mean and variance of the law tilted by e^{rX}."""
    lw = np.log(p) + r * x
    k = special.logsumexp(lw)
    w = np.exp(lw - k)
    m = w @ x
    return k, m, w @ (x - m) ** 2


@pytest.mark.parametrize("side", ["false alarm", "miss"])
def test_bounds_match_first_principles_on_enumerated_law(side):
    """Oracle: the enumerated law. Chernoff: scipy's bounded minimisation of ln E e^{rS} - r t
    over r >= 0. Gallager (Eq. 3.5.14 as corrected): r1 from brentq on tilted mean minus
    sqrt(2 tilted variance) = t, then -ln 2 + ln E e^{r1 S} - r1 t - 2 r1 sqrt(2 var). S = n for
    the false-alarm side (t = theta), S = -n for the miss side (t = 1 - theta). Both bounds
    must bracket the exact tail P(S >= t)."""
    x, p = _enumerated_law()
    noise = MultipleAccessNoise(4, 0.15, PointMassDensity(ATOMS, ATOM_W))
    theta = np.array([0.3, 0.5, 0.8])
    sx = x if side == "false alarm" else -x
    t = theta if side == "false alarm" else 1.0 - theta
    ub = roc_upper_bound(noise, theta)[0 if side == "false alarm" else 1]
    lb = roc_lower_bound(noise, theta)[0 if side == "false alarm" else 1]
    cgf = noise if side == "false alarm" else NegatedCGF(noise)
    for i, ti in enumerate(t):
        res = optimize.minimize_scalar(
            lambda r, ti=ti: _tilted(sx, p, r)[0] - r * ti,
            bounds=(0.0, 60.0),
            method="bounded",
            options={"xatol": 1e-11},
        )
        assert ub[i] == pytest.approx(res.fun, abs=1e-9)
        ch = chernoff_log_tail(cgf, ti)
        assert ch.parameter == pytest.approx(res.x, rel=1e-5)

        def gap(r, ti=ti):
            _, m, v = _tilted(sx, p, r)
            return m - np.sqrt(2 * v) - ti

        r1 = optimize.brentq(gap, 0.0, 200.0, xtol=1e-14, rtol=1e-15)
        k, _, v = _tilted(sx, p, r1)
        expected = -np.log(2) + k - r1 * ti - 2 * r1 * np.sqrt(2 * v)
        assert lb[i] == pytest.approx(expected, rel=1e-9)
        ga = gallager_log_tail_lower(cgf, ti)
        assert ga.log_p == pytest.approx(expected, rel=1e-9) and ga.parameter == pytest.approx(r1, rel=1e-9)
        exact = p[sx >= ti].sum()
        assert np.exp(lb[i]) <= exact <= np.exp(ub[i])
    # a threshold at or below the mean: the Chernoff bound is 1, reached at r = 0 (exactly at
    # the mean too, where mu'(0) = t)
    mean = p @ sx
    assert chernoff_log_tail(cgf, mean - 0.1).log_p == 0.0
    assert chernoff_log_tail(cgf, mean - 0.1).parameter == 0.0
    at_mean = chernoff_log_tail(cgf, float(cgf.cgf_d1(0.0)))
    assert at_mean.parameter == 0.0 and at_mean.log_p == 0.0


def test_negated_cgf_on_asymmetric_law():
    """Oracle: the enumerated law of -n: ln E e^{-sn}, and the mean and variance of the law
    tilted by e^{-sn}."""
    x, p = _enumerated_law()
    neg = NegatedCGF(MultipleAccessNoise(4, 0.15, PointMassDensity(ATOMS, ATOM_W)))
    for s in (-1.5, 0.4, 3.0):
        k, m, v = _tilted(-x, p, s)
        assert float(neg.cgf(s)) == pytest.approx(k, rel=1e-12)
        assert float(neg.cgf_d1(s)) == pytest.approx(m, rel=1e-12)
        assert float(neg.cgf_d2(s)) == pytest.approx(v, rel=1e-12)


def test_thresholds_beyond_the_support_give_empty_tails():
    """Oracle: n <= 3 * 0.75 and -n <= 3 * 0.5 surely; beyond, both bounds are -inf (probability
    0) and the tilt infinite; the vectorised forms agree with the scalar ones."""
    noise = MultipleAccessNoise(4, 0.15, PointMassDensity(ATOMS, ATOM_W))
    for fn in (chernoff_log_tail, gallager_log_tail_lower):
        b = fn(noise, 2.4)
        assert b.log_p == -np.inf and b.parameter == np.inf
        b = fn(NegatedCGF(noise), 1.6)
        assert b.log_p == -np.inf and b.parameter == np.inf
    lp, r = chernoff_log_tails(noise, [0.5, 2.4, -1.0])
    assert lp[1] == -np.inf and r[1] == np.inf and lp[2] == 0.0 and r[2] == 0.0
    # the same bisection on arrays of other lengths: numpy's vectorised exp and log may round the
    # last bit differently (an AMD EPYC found the Gallager root 2 ulp apart and log_p 1 ulp
    # apart), so the forms agree to a few ulp, not bit for bit
    ulps = 8 * np.finfo(float).eps
    scalar = chernoff_log_tail(noise, 0.5)
    np.testing.assert_allclose([lp[0], r[0]], [scalar.log_p, scalar.parameter], rtol=ulps, atol=0)
    lg, r1 = gallager_log_tails_lower(noise, [0.5, 2.4])
    assert lg[1] == -np.inf and r1[1] == np.inf
    scalar = gallager_log_tail_lower(noise, 0.5)
    np.testing.assert_allclose([lg[0], r1[0]], [scalar.log_p, scalar.parameter], rtol=ulps, atol=0)


def test_best_pf_at_pd_is_the_brute_force_operating_point():
    """Oracle: a loop over the thresholds keeping the smallest p_f among those whose p_d reaches
    the requirement, on random ROCs; and NaN (index None) when none reaches it."""
    from navcore.detection.roc_bounds import best_pf_at_pd, best_pf_index_at_pd

    rng = np.random.default_rng(11)
    for _ in range(50):
        pf, miss = rng.uniform(size=12), rng.uniform(size=12)
        pd_min = float(rng.uniform(0.3, 0.95))
        best, best_j = math.inf, None
        for j in range(12):
            if miss[j] <= 1.0 - pd_min and pf[j] < best:
                best, best_j = pf[j], j
        assert best_pf_index_at_pd(pf, miss, pd_min) == best_j
        got = best_pf_at_pd(pf, miss, pd_min)
        assert (best_j is None and math.isnan(got)) or got == best


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (([0.1, 1.5], [0.1, 0.1], 0.9), "p_f"),
        (([0.1, 0.2], [0.1, -0.1], 0.9), "p_miss"),
        (([0.1, 0.2], [0.1, 0.1], 1.2), "pd_min"),
        (([0.1, 0.2], [0.1], 0.9), "p_miss"),
        (([], [], 0.9), "p_f"),
    ],
)
def test_best_pf_at_pd_rejects_bad_arguments(args, name):
    from navcore.detection.roc_bounds import best_pf_at_pd

    with pytest.raises(ValueError, match=name):
        best_pf_at_pd(*args)


@pytest.mark.parametrize("q", [4e-5, 0.3])
def test_gated_cosh_log_curvature_against_hand_derivative(q):
    """Oracle: the second derivative in beta of ln(1 - q + q cosh sqrt(beta)) by hand, with
    u = sqrt(beta), D = 1 - q + q cosh u: g' = q sinh u / (2 u D) and
    g'' = [q cosh u / (u D) - q sinh u / (u^2 D) - (q sinh u)^2 / (u D^2)] / (4 u), in float64
    (cosh(25) does not overflow); and the sign the Theorem 3.2 claims read (ATC-10 Eq. 3.7.15):
    convex at small x, concave at large x where g grows as sqrt(beta)."""
    x = np.linspace(0.5, 25.0, 50)
    c, s, d = q * np.cosh(x), q * np.sinh(x), 1 - q + q * np.cosh(x)
    hand = (c / (x * d) - s / (x**2 * d) - s**2 / (x * d**2)) / (4 * x)
    np.testing.assert_allclose(gated_cosh_log_curvature(x, q), hand, rtol=1e-8, atol=1e-300)
    assert gated_cosh_log_curvature([1.0], q)[0] > 0 > gated_cosh_log_curvature([30.0], q)[0]


def test_gated_cosh_log_curvature_rejects_bad_arguments():
    """Oracle: the documented boundary, each argument named as the caller spelled it."""
    with pytest.raises(ValueError, match="q"):
        gated_cosh_log_curvature([1.0], 1.5)
    with pytest.raises(ValueError, match="x"):
        gated_cosh_log_curvature([np.inf], 0.1)
