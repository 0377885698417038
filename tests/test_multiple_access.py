"""Tests of navcore.detection.multiple_access against independent oracles."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from _oracles import irwin_hall_cdf_mpmath
from scipy import integrate, special, stats

from navcore.detection.multiple_access import (
    GaussianDensity,
    LogMGFDensity,
    MultipleAccessNoise,
    PointMassDensity,
    TriangularDensity,
    UniformDensity,
    carrier_phase_density,
    cumulants_from_raw_moments,
    edgeworth_density,
    edgeworth_tail,
    gaussian_mixture_exact_tail,
    irwin_hall_cdf,
    psk_amplitude_samples,
    sample_noise,
    stratified_sums,
    stratified_tail,
    tabulated_density,
    triangular_exact_tail,
    two_point_density,
    two_point_exact_tail,
    uniform_exact_tail,
)
from navcore.detection.zakai import aperiodic_autocorrelation, piecewise_linear_inner

B = 1.0 / 75.0
DENSITIES = [two_point_density(B), UniformDensity(B), TriangularDensity(B), GaussianDensity(B)]


@pytest.mark.parametrize("dens", DENSITIES, ids=lambda d: d.name)
def test_log_mgf_and_derivatives_match_quadrature(dens):
    """Oracle: numerical integration of e^{sx} C(x) (scipy.integrate.quad) or direct sums."""
    s = np.array([0.0, 0.7, 5.0, 23.0])
    if dens.name == "two-point":
        a = np.sqrt(B)
        m0 = np.cosh(s * a)
        m1 = a * np.sinh(s * a)
        m2 = a**2 * np.cosh(s * a)
    else:
        if dens.name == "uniform":
            h = np.sqrt(3 * B)
            pdf, lo, hi = (lambda x: 1 / (2 * h)), -h, h
        elif dens.name == "triangular":
            h = np.sqrt(6 * B)
            pdf, lo, hi = (lambda x: (h - abs(x)) / h**2), -h, h
        else:
            pdf, lo, hi = (lambda x: stats.norm.pdf(x, scale=np.sqrt(B))), -12 * np.sqrt(B), 12 * np.sqrt(B)
        m0, m1, m2 = (
            np.array(
                [
                    integrate.quad(
                        lambda x, si=si, k=k: x**k * np.exp(si * x) * pdf(x),
                        lo,
                        hi,
                        epsabs=1e-12,
                        epsrel=1e-10,
                        points=[0.0],
                        limit=200,
                    )[0]
                    for si in s
                ]
            )
            for k in (0, 1, 2)
        )
    np.testing.assert_allclose(dens.log_mgf(s), np.log(m0), rtol=1e-9, atol=1e-13)
    np.testing.assert_allclose(dens.dlog_mgf(s), m1 / m0, rtol=1e-8, atol=1e-14)
    np.testing.assert_allclose(dens.d2_ratio(s), m2 / m0, rtol=1e-8)
    assert dens.second_moment == pytest.approx(B, rel=1e-12)


def test_tabulated_and_logmgf_densities_agree_with_closed_form():
    """Oracle: the uniform law's MGF sinh(hs)/(hs) and its derivatives by mpmath (40 digits);
    Gauss-Legendre with 60 nodes integrates e^{sx} on [-h, h] to round-off at these s."""
    import mpmath

    h = np.sqrt(3 * B)
    tab = tabulated_density(lambda x: np.full_like(x, 1 / (2 * h)), -h, h, n=60)
    lg = LogMGFDensity(lambda z: np.log(np.sinh(h * z) / (h * z)))
    for s in (0.5, 4.0, 12.0):
        with mpmath.workdps(40):

            def f(z):
                return mpmath.log(mpmath.sinh(h * z) / (h * z))

            d1 = mpmath.diff(f, mpmath.mpf(s))
            ratio2 = mpmath.diff(f, mpmath.mpf(s), 2) + d1**2
        assert float(tab.log_mgf(s)) == pytest.approx(float(f(mpmath.mpf(s))), rel=1e-10)
        assert float(tab.dlog_mgf(s)) == pytest.approx(float(d1), rel=1e-10)
        assert float(tab.d2_ratio(s)) == pytest.approx(float(ratio2), rel=1e-10)
        assert float(lg.dlog_mgf(s)) == pytest.approx(float(d1), rel=1e-6)
        assert float(lg.d2_ratio(s)) == pytest.approx(float(ratio2), rel=1e-5)
    assert tab.second_moment == pytest.approx(B, rel=1e-12)
    assert tab.moment(4) == pytest.approx(9 * B**2 / 5, rel=1e-12)  # h^4 / 5
    # an off-centre support: the ramp density 2 (x - 0.2) / 0.64 on [0.2, 1.0]
    ramp = tabulated_density(lambda x: 2 * (x - 0.2) / 0.64, 0.2, 1.0, n=30)
    for r in (1, 2, 3):
        expected = integrate.quad(lambda x, r=r: x**r * 2 * (x - 0.2) / 0.64, 0.2, 1.0)[0]
        assert ramp.moment(r) == pytest.approx(expected, rel=1e-12)
    assert min(ramp.values) > 0.2 and max(ramp.values) < 1.0


@pytest.mark.parametrize("which", ["two-point", "Gaussian"])
def test_stratified_monte_carlo_matches_exact_tails(which):
    """Oracles: exact compound-binomial tail (two-point) and exact Gaussian mixture."""
    dens = two_point_density(B) if which == "two-point" else GaussianDensity(B)
    noise = MultipleAccessNoise(100_000, 2e-5, dens)
    t = np.array([0.3, 0.5, 0.7])
    est = stratified_tail(noise, t, 20_000, np.random.default_rng(5))
    exact = (
        two_point_exact_tail(np.sqrt(B), 99_999, 4e-5, t)
        if which == "two-point"
        else gaussian_mixture_exact_tail(B, 99_999, 4e-5, t)
    )
    assert np.all(np.abs(est.upper - exact) < 4 * est.upper_se + 1e-12)
    assert np.all(np.abs(est.lower - exact) < 4 * est.lower_se + 1e-12)


def test_edgeworth_improves_on_gaussian_limit_at_large_n_q():
    """Oracle: exact Gaussian-mixture tail; Theorem 3.1 and the lambda_4 term of (E.15)."""
    t = np.array([0.1, 0.15])
    for n in (1_000_000, 10_000_000):
        noise = MultipleAccessNoise(n, 2e-5, GaussianDensity(B))
        exact = gaussian_mixture_exact_tail(B, n - 1, 4e-5, t * np.sqrt(n / 1e5))
        g0 = edgeworth_tail(noise, t * np.sqrt(n / 1e5), terms=0, use_n=False)
        g2 = edgeworth_tail(noise, t * np.sqrt(n / 1e5), terms=2, use_n=False)
        assert np.all(np.abs(g2 - exact) < np.abs(g0 - exact))


def test_psk_amplitude_second_moment_and_kurtosis():
    """Oracle: Eq. (F.5) averaged over random interferer codes, computed by navcore.detection.zakai."""
    rng = np.random.default_rng(7)
    code = rng.choice([-1.0, 1.0], 64)
    x = psk_amplitude_samples(code, 200_000, rng)
    # (F.5): E[n_ij^2 | overlap] = (1/(4 tau)) int R_ii E[R_jj]; E[R_jj] is the unit triangle of one chip.
    r_ii = aperiodic_autocorrelation(code)
    tri = np.zeros_like(r_ii)
    tri[63] = 1.0
    oracle = piecewise_linear_inner(r_ii, tri, 1.0) / (4 * 64)
    assert np.mean(x**2) == pytest.approx(oracle, rel=0.02)
    assert oracle == pytest.approx(1 / (6 * 64), rel=0.15)
    assert abs(np.mean(x)) < 5 * x.std() / np.sqrt(x.size)
    assert np.mean(x**4) / np.mean(x**2) ** 2 > 4.0


def test_bad_inputs_raise():
    with pytest.raises(ValueError, match="b"):
        UniformDensity(-1.0)
    with pytest.raises(ValueError, match="n_aircraft"):
        MultipleAccessNoise(1, 1e-5, GaussianDensity(1.0))


# --- brute-force oracles on a small, asymmetric case -------------------------------------------
# Atoms are dyadic rationals, so every sum of them is exact in floating point and a threshold
# can sit exactly on a support point (which tests whether a tail includes its end point).
ATOMS = (-0.5, 0.25, 0.75)
ATOM_W = (0.25, 0.5, 0.25)
N_SMALL, TA_SMALL = 4, 0.15  # three interferers, overlap probability q = 0.3


def _enumerated_law(values, weights, n_interferers, q):
    """Exact law of the noise by enumerating every interferer state (absent, or one atom):
    returns the support (sorted) and its probabilities. Uses only the definition of the model
    (independent gates of probability q, independent amplitudes), not the module's algebra."""
    states = [(0.0, 1.0 - q)] + [(v, q * w / sum(weights)) for v, w in zip(values, weights, strict=True)]
    law: dict[float, float] = {}
    for combo in itertools.product(states, repeat=n_interferers):
        x = sum(c[0] for c in combo)
        law[x] = law.get(x, 0.0) + float(np.prod([c[1] for c in combo]))
    support = np.array(sorted(law))
    return support, np.array([law[x] for x in support])


def _small_noise():
    return MultipleAccessNoise(N_SMALL, TA_SMALL, PointMassDensity(ATOMS, ATOM_W))


def test_cgf_and_tilted_moments_match_enumeration():
    """Oracle: brute-force enumeration of all 4^3 interferer states of an asymmetric point-mass
    density: ln E e^{sn}, the tilted mean and variance, E e^{jvn}, E n and E n^2."""
    noise = _small_noise()
    x, p = _enumerated_law(ATOMS, ATOM_W, 3, 0.3)
    for s in (-3.0, -0.4, 0.0, 0.9, 5.0):
        lw = np.log(p) + s * x
        tilt = np.exp(lw - special.logsumexp(lw))
        mean_t = tilt @ x
        assert float(noise.cgf(s)) == pytest.approx(special.logsumexp(lw), rel=1e-12, abs=1e-14)
        assert float(noise.cgf_d1(s)) == pytest.approx(mean_t, rel=1e-12, abs=1e-14)
        assert float(noise.cgf_d2(s)) == pytest.approx(tilt @ (x - mean_t) ** 2, rel=1e-12)
    v = np.array([0.5, 3.0, 11.0])
    np.testing.assert_allclose(noise.char_fn(v), np.exp(1j * v[:, None] * x) @ p, rtol=1e-12, atol=1e-14)
    assert noise.mean == pytest.approx(p @ x, rel=1e-12)
    assert noise.power == pytest.approx(p @ x**2, rel=1e-12)
    # Theorem 3.1's limit variance uses N (not N - 1) interferers: N q E(C^2), hand arithmetic
    assert noise.gaussian_limit_variance == pytest.approx(4 * 0.3 * (0.25 * 0.25 + 0.5 / 16 + 0.25 * 0.5625))
    assert noise.q == 0.3 and noise.n_interferers == 3


def test_cumulants_match_derivatives_of_the_enumerated_cgf():
    """Oracle: mpmath's high-precision derivatives at 0 (orders 1..6) of ln E e^{sn}, with
    E e^{sn} summed over the enumerated law; also N(0,1) and Poisson(1) raw moments."""
    import mpmath

    x, p = _enumerated_law(ATOMS, ATOM_W, 3, 0.3)
    with mpmath.workdps(50):
        xs, ps = [mpmath.mpf(v) for v in x], [mpmath.mpf(v) for v in p]

        def cgf(z):
            return mpmath.log(mpmath.fsum(pi * mpmath.exp(xi * z) for xi, pi in zip(xs, ps, strict=True)))

        expected = [float(mpmath.diff(cgf, 0, r)) for r in range(1, 7)]
    np.testing.assert_allclose(_small_noise().cumulants(6), expected, rtol=1e-10, atol=1e-15)
    np.testing.assert_allclose(
        cumulants_from_raw_moments([0.0, 1.0, 0.0, 3.0, 0.0, 15.0]), [0, 1, 0, 0, 0, 0], atol=1e-12
    )
    np.testing.assert_allclose(
        cumulants_from_raw_moments([1.0, 2.0, 5.0, 15.0, 52.0]), [1.0] * 5
    )  # Bell numbers


def test_sampler_law_matches_enumeration():
    """Oracle: the enumerated law; seeded Monte Carlo frequencies of every support point (and of
    the density's own atoms) within 5 binomial standard errors."""
    noise = _small_noise()
    x, p = _enumerated_law(ATOMS, ATOM_W, 3, 0.3)
    n = 200_000
    draws = sample_noise(noise, n, np.random.default_rng(21))
    assert draws.shape == (n,)
    assert set(np.unique(draws)) <= set(x)
    freq = np.array([(draws == xi).mean() for xi in x])
    assert np.all(np.abs(freq - p) <= 5 * np.sqrt(p * (1 - p) / n) + 1e-12)
    atoms = noise.density.sample(np.random.default_rng(22), n)
    fa = np.array([(atoms == a).mean() for a in ATOMS])
    w = np.array(ATOM_W)
    assert np.all(np.abs(fa - w) <= 5 * np.sqrt(w * (1 - w) / n))


def test_stratified_tails_match_enumeration_at_support_points():
    """Oracle: the enumerated law. P(n >= t) and P(n <= -t) include their end points: thresholds
    sit on support points (exact dyadic sums), and the two tails differ (asymmetric C)."""
    noise = _small_noise()
    x, p = _enumerated_law(ATOMS, ATOM_W, 3, 0.3)
    t = np.array([0.0, 0.25, 0.5, 0.75, 1.0, 1.25])
    est = stratified_tail(noise, t, 20_000, np.random.default_rng(4))
    up = np.array([p[x >= ti].sum() for ti in t])
    lo = np.array([p[x <= -ti].sum() for ti in t])
    assert np.all(np.abs(est.upper - up) <= 4 * est.upper_se + 1e-12)
    assert np.all(np.abs(est.lower - lo) <= 4 * est.lower_se + 1e-12)
    assert np.all(est.upper_se > 0) and np.all(est.upper_se < 0.01)
    ss = stratified_sums(noise, 20_000, np.random.default_rng(4))
    scaled, se = ss.tail(t, scale=2.0)  # P(2 n >= t)
    up2 = np.array([p[2 * x >= ti].sum() for ti in t])
    assert np.all(np.abs(scaled - up2) <= 4 * se + 1e-12)
    assert np.all(ss.weights >= 0) and ss.weights.sum() == pytest.approx(1.0, abs=1e-15)


def test_exact_tail_formulas_match_enumeration_and_simulation():
    """Oracles: enumeration for the two-point density (thresholds on support points, where the end
    point must be included) and a seeded Monte Carlo of Bernoulli-gated Gaussian amplitudes for
    the Gaussian mixture (written here from the model's definition, 10^6 samples)."""
    a, n_int, q = 0.25, 5, 0.4
    two = two_point_density(a**2)  # Eq. (3.7.1): masses 1/2 at +-sqrt(b)
    assert two.values == (-a, a) and two.weights == (0.5, 0.5)
    x, p = _enumerated_law((-a, a), (0.5, 0.5), n_int, q)
    t = np.array([-0.5, 0.0, 0.25, 0.5, 0.75, 1.25])
    np.testing.assert_allclose(
        two_point_exact_tail(a, n_int, q, t), [p[x >= ti].sum() for ti in t], rtol=1e-12, atol=1e-15
    )
    rng = np.random.default_rng(8)
    m, b = 1_000_000, 0.04
    k = rng.binomial(n_int, q, m)
    sims = rng.normal(0.0, 1.0, m) * np.sqrt(k * b)
    t = np.array([-0.3, 0.0, 0.2, 0.5, 0.9])
    emp = np.array([(sims >= ti).mean() for ti in t])
    got = gaussian_mixture_exact_tail(b, n_int, q, t)
    assert np.all(np.abs(got - emp) <= 5 * np.sqrt(emp * (1 - emp) / m) + 1e-12)


@pytest.mark.parametrize(
    "dens", [UniformDensity(B), TriangularDensity(B), GaussianDensity(B)], ids=lambda d: d.name
)
def test_continuous_densities_moments_char_fn_and_samplers(dens):
    """Oracles: scipy quadrature of x^r C(x) and cos(v x) C(x); a Kolmogorov-Smirnov test of the
    seeded sampler against scipy.stats' uniform, triangular and normal laws."""
    if dens.name == "uniform":
        h = np.sqrt(3 * B)
        law = stats.uniform(loc=-h, scale=2 * h)
    elif dens.name == "triangular":
        h = np.sqrt(6 * B)
        law = stats.triang(c=0.5, loc=-h, scale=2 * h)
    else:
        h = 12 * np.sqrt(B)
        law = stats.norm(scale=np.sqrt(B))
    for r in range(1, 7):
        # odd moments vanish by symmetry; even ones by quadrature
        expected = 0.0 if r % 2 else integrate.quad(lambda x, r=r: x**r * law.pdf(x), -h, h, points=[0.0])[0]
        assert dens.moment(r) == pytest.approx(expected, rel=1e-9, abs=1e-15)
    v = np.array([0.0, 2.0, 9.0, 30.0])
    cf = [
        integrate.quad(lambda x, vi=vi: np.cos(vi * x) * law.pdf(x), -h, h, points=[0.0], limit=200)[0]
        for vi in v
    ]
    np.testing.assert_allclose(dens.char_fn(v), cf, rtol=1e-9, atol=1e-12)
    draws = dens.sample(np.random.default_rng(2), 20_000)
    assert stats.kstest(draws, law.cdf).pvalue > 1e-3


def test_uniform_density_near_zero_tilt_matches_mpmath():
    """Oracle: mpmath at 40 digits of ln(sinh x / x) and its first two derivatives (the
    moments of the tilted uniform density), on both sides of the small-argument series."""
    import mpmath

    u = UniformDensity(B)
    a = u.half_width
    # the series branch (|a s| < 1e-3) is exact to ~1e-16 relative; just above it the direct
    # forms cancel (ln(sinh x / x) to ~3e-15 absolute, (coth x - 1/x) / x to ~1e-10 relative),
    # so the tolerances there are wider; values are ~1e-7, so every tolerance is explicit
    for s, rel, abs_ in (
        (4e-4 / a, 1e-13, 0.0),
        (-9.9e-4 / a, 1e-13, 0.0),
        (1.01e-3 / a, 1e-8, 1e-14),
        (0.5 / a, 1e-12, 0.0),
        (30.0 / a, 1e-12, 0.0),
    ):
        with mpmath.workdps(40):
            ms = mpmath.mpf(s)

            def f(z):
                return mpmath.log(mpmath.sinh(a * z) / (a * z))

            d1 = mpmath.diff(f, ms)
            d2 = mpmath.diff(f, ms, 2)
            expected = (float(f(ms)), float(d1), float(d2 + d1**2))
        assert float(u.log_mgf(s)) == pytest.approx(expected[0], rel=rel, abs=abs_)
        assert float(u.dlog_mgf(s)) == pytest.approx(expected[1], rel=rel, abs=abs_)
        assert float(u.d2_ratio(s)) == pytest.approx(expected[2], rel=rel, abs=abs_)


def test_log_mgf_density_moments():
    """Oracle: N(m, b) has ln E e^{sX} = m s + b s^2 / 2, so E X = m and E X^2 = b + m^2."""
    m, b = 0.3, 0.02
    d = LogMGFDensity(lambda s: m * s + 0.5 * b * s**2)
    assert d.moment(1) == pytest.approx(m, rel=1e-8)
    assert d.moment(2) == pytest.approx(b + m**2, rel=1e-6)
    assert d.second_moment == pytest.approx(b + m**2, rel=1e-6)
    with pytest.raises(ValueError):
        d.moment(3)


def _edgeworth_oracle(n_aircraft, q, use_n, terms, xs):
    """Density and tail of the Edgeworth expansion (E.15) from first principles, at ``xs``:
    per-interferer cumulants by mpmath differentiation (50 digits) of ln(1 - q + q E e^{sC})
    (the asymmetric atoms above); the correction polynomial as the Taylor coefficients of
    exp(sum_{r=3..6} n kappa_r w^r / r!) in w = jv (kept: w^3, then w^4, then w^6, grouped by
    order in 1/sqrt(n) as App. E does); the density by numerical Fourier inversion and the tail
    by the Gil-Pelaez inversion formula, both with 160-node Gauss-Legendre quadrature."""
    import mpmath

    with mpmath.workdps(50):
        mq = mpmath.mpf(q)

        def one(z):
            return mpmath.log(
                1
                - mq
                + mq
                * mpmath.fsum(
                    mpmath.mpf(w) * mpmath.exp(mpmath.mpf(v) * z) for v, w in zip(ATOMS, ATOM_W, strict=True)
                )
            )

        kap = [mpmath.diff(one, 0, r) for r in range(1, 7)]
        nn = n_aircraft if use_n else n_aircraft - 1
        taylor = mpmath.taylor(
            lambda w: mpmath.exp(
                mpmath.fsum(nn * kap[r - 1] * w**r / mpmath.factorial(r) for r in range(3, 7))
            ),
            0,
            6,
        )
        coef = {k: float(taylor[k]) for k in (3, 4, 6)}
        var = float(nn * kap[1])
    keep = (3, 4, 6)[:terms]
    node, weight = np.polynomial.legendre.leggauss(160)
    top = 12.0 / np.sqrt(var)
    v = 0.5 * top * (node + 1.0)
    w = 0.5 * top * weight
    phi = np.exp(-0.5 * var * v**2) * (1.0 + sum(coef[k] * (1j * v) ** k for k in keep))
    rot = phi[None, :] * np.exp(-1j * np.outer(xs, v))
    density = (rot.real @ w) / np.pi
    tail = 0.5 + (rot.imag / v) @ w / np.pi
    return density, tail


@pytest.mark.parametrize("use_n", [True, False])
@pytest.mark.parametrize("terms", [0, 1, 2, 3])
def test_edgeworth_density_and_tail_match_fourier_inversion(terms, use_n):
    """Oracle: Fourier inversion of the truncated expansion with sympy-derived coefficients (see
    _edgeworth_oracle), for an asymmetric C so that the odd (lambda_3) terms count."""
    noise = MultipleAccessNoise(60, 0.1, PointMassDensity(ATOMS, ATOM_W))
    sig = np.sqrt(
        (60 if use_n else 59) * 0.2 * (0.25 * 0.25 + 0.5 / 16 + 0.25 * 0.5625)
        - (60 if use_n else 59) * (0.2 * 0.125) ** 2
    )
    xs = sig * np.array([-2.5, -0.7, 0.0, 0.4, 1.8])
    density, tail = _edgeworth_oracle(60, 0.2, use_n, terms, xs)
    got_d = edgeworth_density(noise, xs, terms=terms, use_n=use_n)
    got_t = edgeworth_tail(noise, xs, terms=terms, use_n=use_n)
    np.testing.assert_allclose(got_d, density, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(got_t, tail, rtol=1e-8, atol=1e-12)


def _psk_overlap_simulation(code_i, n_events, rng):
    """Independent physics of Eq. (3.3.7): the correlation of chip waveforms computed by summing
    the exact overlap length of every pair of rectangular chips, for a fresh random +-1 code
    delayed by d ~ U(-L, L) chips and a uniform carrier phase; unit energy per signature."""
    ci = np.asarray(code_i, float)
    L = ci.size
    d = rng.uniform(-L, L, n_events)
    cj = rng.choice([-1.0, 1.0], (n_events, L))
    m = np.arange(L)
    # overlap of chip m of i, [m, m+1), with chip n of j delayed by d, [n+d, n+d+1)
    lo = np.maximum(m[None, :, None], m[None, None, :] + d[:, None, None])
    hi = np.minimum(m[None, :, None] + 1.0, m[None, None, :] + d[:, None, None] + 1.0)
    overlap = np.clip(hi - lo, 0.0, None)
    x = np.einsum("m,emn,en->e", ci, overlap, cj) / L
    return np.cos(rng.uniform(0.0, 2 * np.pi, n_events)) * x


def test_psk_amplitude_law_matches_chip_overlap_simulation():
    """Oracle: a seeded simulation written from the waveforms (exact chip-pair overlaps, see
    _psk_overlap_simulation): the two samples' laws agree (two-sample Kolmogorov-Smirnov), and
    so do E x^2 and E x^4 within 4 standard errors. Chunking must not change the law either."""
    code = np.array([1.0, 1.0, 1.0, -1.0, -1.0, 1.0, -1.0])  # Barker 7
    n = 40_000
    got = psk_amplitude_samples(code, n, np.random.default_rng(12), chunk=7_000)
    ref = _psk_overlap_simulation(code, n, np.random.default_rng(13))
    assert stats.ks_2samp(got, ref).pvalue > 1e-3
    for r in (2, 4):
        se = np.sqrt(np.var(got**r) / n + np.var(ref**r) / n)
        assert abs(np.mean(got**r) - np.mean(ref**r)) < 4 * se
    assert np.abs(got).max() <= 1.0 + 1e-12


def test_psk_amplitude_samples_do_not_depend_on_chunk():
    """Oracle: the same generator state gives the same samples whatever the batch size (the batch
    bounds memory only); a different seed gives different samples."""
    code = np.array([1.0, 1.0, 1.0, -1.0, -1.0, 1.0, -1.0])  # Barker 7
    ref = psk_amplitude_samples(code, 10_001, np.random.default_rng(4), chunk=10_001)
    for chunk in (1, 999, 4_000):
        got = psk_amplitude_samples(code, 10_001, np.random.default_rng(4), chunk=chunk)
        assert np.array_equal(got, ref)
    assert not np.array_equal(psk_amplitude_samples(code, 10_001, np.random.default_rng(5)), ref)


def test_point_mass_density_construction():
    """Oracle: the validation contract and the definition of a point-mass law: weights are
    normalised (1:3 -> 1/4, 3/4), a zero weight is allowed and its atom never drawn, one atom is
    a valid (degenerate) law, integer atoms give real samples; mismatched lengths, negative,
    infinite or NaN weights, infinite atoms and an all-zero weight vector are rejected."""
    d = PointMassDensity((1, 3), (1, 3))
    assert d.moment(1) == pytest.approx(0.25 * 1 + 0.75 * 3, rel=1e-15)
    draws = d.sample(np.random.default_rng(0), 40_000)
    assert draws.dtype == np.float64 and abs((draws == 3.0).mean() - 0.75) < 5 * np.sqrt(0.75 * 0.25 / 40_000)
    z = PointMassDensity((-1.0, 0.0, 2.0), (0.5, 0.0, 0.5))
    assert z.moment(2) == pytest.approx(2.5, rel=1e-15) and not np.any(
        z.sample(np.random.default_rng(1), 1000) == 0.0
    )
    one = PointMassDensity((0.3,), (1.0,))
    assert float(one.log_mgf(2.0)) == pytest.approx(0.6, rel=1e-15)
    for values, weights in (
        ((0.1, 0.2), (1.0, 1.0, 1.0)),
        ((0.1, 0.2), (-0.5, 1.5)),
        ((0.1, 0.2), (np.inf, 1.0)),
        ((0.1, 0.2), (np.nan, 1.0)),
        ((np.inf, 0.2), (0.5, 0.5)),
        ((0.1, 0.2), (0.0, 0.0)),
        ((), ()),
    ):
        with pytest.raises(ValueError):
            PointMassDensity(values, weights)


def test_documented_defaults_and_returned_fields():
    """Oracle: the documented defaults (six cumulants; Edgeworth with two correction terms and N
    interferers; 200 quadrature nodes named 'tabulated') and the fields of the returned tail
    estimate (the thresholds, as reals, for integer input)."""
    noise = MultipleAccessNoise(60, 0.1, PointMassDensity(ATOMS, ATOM_W))
    assert noise.cumulants().shape == (6,)
    xs = np.array([-0.3, 0.1, 0.4])
    density, tail = _edgeworth_oracle(60, 0.2, True, 2, xs)
    np.testing.assert_allclose(edgeworth_density(noise, xs), density, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(edgeworth_tail(noise, xs), tail, rtol=1e-8, atol=1e-12)
    tab = tabulated_density(lambda x: np.full_like(x, 0.5), -1.0, 1.0)
    assert len(tab.values) == 200 and tab.name == "tabulated"
    assert tabulated_density(lambda x: np.full_like(x, 0.5), -1.0, 1.0, n=4, name="flat").name == "flat"
    est = stratified_tail(_small_noise(), [0, 1], 100, np.random.default_rng(0))
    assert est.t.dtype == np.float64 and est.t.tolist() == [0.0, 1.0]
    # integer thresholds are thresholds like any other (enumerated two-point law)
    x, p = _enumerated_law((-0.25, 0.25), (0.5, 0.5), 4, 0.5)
    np.testing.assert_allclose(
        two_point_exact_tail(0.25, 4, 0.5, [-1, 0, 1]), [p[x >= t].sum() for t in (-1, 0, 1)]
    )


def test_integer_tilts_and_negative_characteristic_base():
    """Oracles: closed forms of the Gaussian law at an integer tilt too large to square in 64-bit
    integers (ln M(s) = b s^2 / 2, phi(v) = exp(-b v^2 / 2) = 0); and, for q = 0.9 and a uniform
    C, E e^{jvn} as the binomial mixture sum_k P(K = k) phi_C(v)^k (phi_C by quadrature), where
    1 - q + q phi_C(v) < 0 so the power must be taken in complex arithmetic."""
    g = GaussianDensity(1e-20)
    s = 4_000_000_000
    assert float(g.log_mgf(s)) == pytest.approx(0.5 * 1e-20 * 1.6e19, rel=1e-15)
    assert float(GaussianDensity(0.04).char_fn(s)) == 0.0
    u = UniformDensity(B)
    h = u.half_width
    v = 4.49 / h  # sinc(4.49) ~ -0.217, its most negative value
    phi_c = integrate.quad(lambda x: np.cos(v * x) / (2 * h), -h, h)[0]
    noise = MultipleAccessNoise(4, 0.45, u)
    expected = sum(stats.binom.pmf(k, 3, 0.9) * phi_c**k for k in range(4))
    assert 1 - 0.9 + 0.9 * phi_c < 0
    assert complex(noise.char_fn(v)) == pytest.approx(expected, rel=1e-12, abs=1e-15)


def test_stratified_standard_error_is_calibrated():
    """Oracle: the spread of the estimator itself: over 300 seeded repetitions the standard
    deviation of the stratified estimate of P(n >= t) matches the reported standard error (the
    mean of its square, within 20 %), for the enumerated asymmetric case."""
    noise = _small_noise()
    t = np.array([0.25, 0.75])
    ests, ses = [], []
    for seed in range(300):
        ss = stratified_sums(noise, 50, np.random.default_rng(1000 + seed))
        e, se = ss.tail(t)
        ests.append(e)
        ses.append(se)
    spread = np.std(ests, axis=0, ddof=1)
    reported = np.sqrt(np.mean(np.square(ses), axis=0))
    np.testing.assert_allclose(reported, spread, rtol=0.2)


def test_gaussian_moments_are_exact():
    """Oracle: Isserlis' theorem, E X^{2m} = (2m - 1)!! b^m, for b = 1/2, where every value is a
    dyadic rational and so must come out exactly."""
    g = GaussianDensity(0.5)
    assert [g.moment(r) for r in (1, 2, 3, 4, 6, 8)] == [0.0, 0.5, 0.0, 0.75, 1.875, 6.5625]


# --- exact tails of the uniform and triangular densities (Irwin-Hall mixtures) -----------------


def _irwin_hall_cdf_mpmath(n: int, x: float, dps: int = 120):
    """The shared oracle (Hall's alternating sum in mpmath) at 120 digits unless told otherwise."""
    return irwin_hall_cdf_mpmath(n, x, dps)


@pytest.mark.parametrize("n", [1, 2, 3, 7, 20, 33, 60, 90])
def test_irwin_hall_cdf_matches_mpmath_alternating_sum(n):
    """Oracle: the alternating sum in 120-digit arithmetic. The points run from the far lower
    tail (values down to 1e-300) through the middle, where the double-precision alternating sum
    cancels, to the upper end; the spline evaluation keeps a relative error of a few round-off
    units everywhere (1e-13 allowed: n de Boor steps of convex combinations)."""
    xs = np.array([1e-3, 0.37, 1.0, 1.5, n / 7, n / 3, n / 2 - 0.25, n / 2, n / 2 + 0.6, 0.9 * n, n - 0.01])
    xs = xs[(xs > 0) & (xs < n)]
    got = irwin_hall_cdf(n, xs)
    want = np.array([float(_irwin_hall_cdf_mpmath(n, float(x))) for x in xs])
    normal = want > 1e-300  # below, the value underflows (n = 90 at x = 1e-3): both are ~0
    assert normal.sum() >= xs.size - 1 and np.all(got[~normal] < 1e-290)
    np.testing.assert_allclose(got[normal], want[normal], rtol=1e-13, atol=0)
    # outside the support, and the symmetry F(x) + F(n - x) = 1
    np.testing.assert_array_equal(irwin_hall_cdf(n, [-1.0, 0.0, n, n + 2.5]), [0.0, 0.0, 1.0, 1.0])
    np.testing.assert_allclose(irwin_hall_cdf(n, xs) + irwin_hall_cdf(n, n - xs), 1.0, rtol=1e-14)


def test_irwin_hall_cdf_matches_monte_carlo():
    """Oracle: a seeded Monte Carlo of sums of 12 uniforms (numpy), 10^6 sums, within five
    binomial standard errors at each point."""
    rng = np.random.default_rng(12)
    sums = rng.random((1_000_000, 12)).sum(axis=1)
    xs = np.array([2.5, 4.0, 6.0, 7.3, 9.0])
    emp = np.array([(sums <= x).mean() for x in xs])
    se = np.sqrt(emp * (1 - emp) / sums.size)
    assert np.all(np.abs(irwin_hall_cdf(12, xs) - emp) <= 5 * se)


def _mixture_tail_mpmath(half_width: float, per: int, n_int: int, q: float, t: float):
    """Oracle: the binomial mixture written out in mpmath (all K, no truncation), each
    conditional tail the 120-digit alternating sum."""
    import mpmath

    with mpmath.workdps(120):
        total = mpmath.mpf(0)
        for k in range(n_int + 1):
            w = mpmath.binomial(n_int, k) * mpmath.mpf(q) ** k * (1 - mpmath.mpf(q)) ** (n_int - k)
            if k == 0:
                total += w * (1 if t <= 0 else 0)
                continue
            m = per * k
            # P(h (2V - m) >= t) = P(V <= (m - t/h)/2) for V Irwin-Hall(m) (symmetry)
            total += w * _irwin_hall_cdf_mpmath(m, (m - mpmath.mpf(t) / mpmath.mpf(half_width)) / 2)
        return total


@pytest.mark.parametrize("which", ["uniform", "triangular"])
def test_uniform_and_triangular_exact_tails_match_mpmath_mixture(which):
    """Oracle: the whole binomial mixture in mpmath with every overlap count (no truncation),
    on a small system (12 interferers, q = 0.3, so no overlap count is dropped) whose
    thresholds reach tails of 1e-16 to 1e-23; the spline round-off stays within 1e-12
    relative (a few hundred round-off units) at every threshold."""
    b, n_int, q = 0.04, 12, 0.3
    t = np.array([-0.2, 0.0, 0.1, 0.5, 1.0, 2.0, 3.0, 4.0])
    if which == "uniform":
        got, h, per = uniform_exact_tail(b, n_int, q, t), np.sqrt(3 * b), 1
    else:
        got, h, per = triangular_exact_tail(b, n_int, q, t), np.sqrt(1.5 * b), 2
    want = np.array([float(_mixture_tail_mpmath(h, per, n_int, q, float(x))) for x in t])
    assert want[-1] < 1e-15  # the far tail is exercised
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=0)


@pytest.mark.parametrize("which", ["uniform", "triangular"])
def test_uniform_and_triangular_exact_tails_match_simulation(which):
    """Oracle: a seeded Monte Carlo of the model from its definition (Bernoulli-gated
    interferers, each drawing a numpy uniform, or the sum of two for the triangular density),
    10^6 samples at the Sec. 3.6 overlap rate scaled up (2000 interferers, q = 0.002), within
    five binomial standard errors at each threshold."""
    rng = np.random.default_rng(44 if which == "uniform" else 45)
    b, n_int, q, m = 0.02, 2000, 0.002, 1_000_000
    k = rng.binomial(n_int, q, m)
    if which == "uniform":
        h = np.sqrt(3 * b)
        draws = rng.uniform(-h, h, int(k.sum()))
        exact = uniform_exact_tail(b, n_int, q, [0.1, 0.3, 0.6, 0.9])
    else:
        h = np.sqrt(1.5 * b)
        draws = rng.uniform(-h, h, int(k.sum())) + rng.uniform(-h, h, int(k.sum()))
        exact = triangular_exact_tail(b, n_int, q, [0.1, 0.3, 0.6, 0.9])
    sims = np.bincount(np.repeat(np.arange(m), k), weights=draws, minlength=m)
    emp = np.array([(sims >= t).mean() for t in (0.1, 0.3, 0.6, 0.9)])
    se = np.sqrt(emp * (1 - emp) / m)
    assert np.all(emp > 0) and np.all(np.abs(exact - emp) <= 5 * se)


def test_irwin_hall_and_exact_tails_refuse_bad_input():
    """Bad input raises ValueError (TypeError for a non-integer count) naming the parameter."""
    with pytest.raises(ValueError, match=r"^n must be an integer"):
        irwin_hall_cdf(0, 0.5)
    with pytest.raises(TypeError, match=r"^n must be an integer"):
        irwin_hall_cdf(2.5, 0.5)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^n must be an integer <= "):
        irwin_hall_cdf(10_000, 0.5)
    with pytest.raises(ValueError, match="x"):
        irwin_hall_cdf(3, [0.5, np.nan])
    for fn in (uniform_exact_tail, triangular_exact_tail):
        with pytest.raises(ValueError, match=r"^b must be"):
            fn(0.0, 10, 0.1, [0.5])
        with pytest.raises(ValueError, match="q"):
            fn(0.1, 10, 1.5, [0.5])
        with pytest.raises(ValueError, match="n_interferers"):
            fn(0.1, -1, 0.1, [0.5])


@pytest.mark.parametrize("n_phases", [6, 12])
def test_carrier_phase_density_moments_against_quadrature(n_phases):
    """Oracle: scipy quadrature of E cos^r(phi) over a uniform phase times the envelope's own
    moments, E n^r = E cos^r E X^r (ATC-10 Sec. 3.4): exact for every order r < n_phases, so the
    odd moments vanish (lambda_3 = 0) though the envelope is skewed."""
    values, weights = (0.5, 2.0), (0.8, 0.2)
    d = carrier_phase_density(values, weights, n_phases=n_phases)
    assert len(d.values) == n_phases * len(values)
    for r in range(1, n_phases):
        e_cos, _ = integrate.quad(lambda ph, r=r: np.cos(ph) ** r / (2 * np.pi), 0.0, 2 * np.pi)
        e_x = sum(w * v**r for v, w in zip(values, weights, strict=True))
        assert d.moment(r) == pytest.approx(e_cos * e_x, abs=1e-12), r


def test_carrier_phase_density_rejects_bad_arguments():
    """Oracle: the documented boundary, each argument named as the caller spelled it."""
    with pytest.raises(ValueError, match="n_phases"):
        carrier_phase_density((1.0,), (1.0,), n_phases=0)
    with pytest.raises(ValueError, match="envelope_values and envelope_weights"):
        carrier_phase_density((1.0, 2.0), (1.0,))
    with pytest.raises(ValueError, match="envelope_weights"):
        carrier_phase_density((1.0,), (np.nan,))
    with pytest.raises(ValueError, match="envelope_weights must be > 0"):  # no atom of zero probability
        carrier_phase_density((1.0, 2.0), (1.0, 0.0))
    with pytest.raises(ValueError, match="envelope_values"):  # a matrix is not a list of atoms
        carrier_phase_density(np.eye(3), np.eye(3))
