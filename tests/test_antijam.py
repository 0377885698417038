"""Anti-jam models against independent oracles (closed forms, brute force, Monte Carlo, filterpy-free KF)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from _oracles import van_loan_expm

from navcore.gnss import antijam as aj
from navcore.units import G0, GPS_L1_WAVELENGTH_M, GPS_P_CHIP_RATE_HZ, MILLI_G


def test_correlation_and_discriminator_shape() -> None:
    """Oracle: the piecewise-linear closed form of the half-chip early-minus-late discriminator."""
    tau = np.linspace(-2, 2, 4001)
    expected = np.where(
        np.abs(tau) <= 0.25,
        2 * tau,
        np.where(
            np.abs(tau) <= 0.75, 0.5 * np.sign(tau), np.clip(1.25 - np.abs(tau), 0, None) * np.sign(tau)
        ),
    )
    np.testing.assert_allclose(aj.early_minus_late(tau, 0.5), expected, atol=1e-12)
    assert aj.ideal_correlation(0.0) == 1.0
    assert aj.ideal_correlation(1.0) == 0.0


def test_spectral_separation_limits() -> None:
    """Oracle: Q -> 1 for a narrow jammer; Q = B/(Rc * 0.9028) for a 2 Rc-wide jammer (main-lobe fraction)."""
    assert aj.spectral_separation_q(1.0, 1e6) == pytest.approx(1.0, rel=1e-6)
    # fraction of BPSK power within +-Rc (main lobe) is 0.90282 (tabulated Si-function value)
    assert aj.spectral_separation_q(2e6, 1e6) == pytest.approx(2.0 / 0.90282, rel=1e-4)


def test_effective_cn0_inverse() -> None:
    """Oracle: the round trip through the inverse (the J/S that brings C/N0 to 19 dB-Hz)."""
    js = aj.js_for_effective_cn0(41.0, 19.0, GPS_P_CHIP_RATE_HZ, 2.0)
    assert aj.effective_cn0_dbhz(41.0, js, GPS_P_CHIP_RATE_HZ, 2.0) == pytest.approx(19.0, abs=1e-10)
    js = aj.js_for_effective_cn0(45.0, 30.0, 1.023e6, 1.3)
    assert aj.effective_cn0_dbhz(45.0, js, 1.023e6, 1.3) == pytest.approx(30.0, abs=1e-10)


@pytest.mark.parametrize("bandwidth_hz", [2e5, 3e6, 2 * GPS_P_CHIP_RATE_HZ])
def test_effective_cn0_from_despread_jammer_density(bandwidth_hz: float) -> None:
    """Oracle: the physics in watts. A flat jammer of power J over bandwidth B, centred on a
    BPSK signal of chip period Tc, leaves after despreading a white-noise density
    J kappa with kappa = int Tc sinc^2(f Tc) (1/B) df over +-B/2 (trapezoid rule on a
    200 001-point grid, numpy), so C/N0_eff = C / (N0 + J kappa) (Kaplan Sec. 6.3). The
    model's Q must be 1/(Rc kappa) and its effective C/N0 (from dB-Hz and dB inputs) this."""
    rc = GPS_P_CHIP_RATE_HZ
    f = np.linspace(-bandwidth_hz / 2, bandwidth_hz / 2, 200_001)
    kappa = np.trapezoid(np.sinc(f / rc) ** 2 / rc, f) / bandwidth_hz
    q = aj.spectral_separation_q(bandwidth_hz, rc)
    assert q == pytest.approx(1 / (rc * kappa), rel=1e-7)
    c_w, n0_w = 10 ** (-158.0 / 10), 10 ** (-204.0 / 10)
    j_w = np.array([1e-14, 1e-12, 1e-10])
    expected = 10 * np.log10(c_w / (n0_w + j_w * kappa))
    got = aj.effective_cn0_dbhz(10 * np.log10(c_w / n0_w), 10 * np.log10(j_w / c_w), rc, q)
    np.testing.assert_allclose(got, expected, atol=1e-6)


def test_free_space_js_friis() -> None:
    """Oracle: Friis received power P G (lambda / 4 pi d)^2 in watts, then the dB ratio by hand."""
    d, p, s_dbw = 9260.0, 100.0, -163.0
    received = p * (GPS_L1_WAVELENGTH_M / (4 * math.pi * d)) ** 2
    expected = 10 * math.log10(received) - s_dbw
    assert aj.free_space_js_db(p, d, GPS_L1_WAVELENGTH_M, s_dbw) == pytest.approx(expected, abs=1e-10)
    # a 6 dB antenna gain (factor 10^0.6 in received power), at an array of distances
    d = np.array([1e3, 5e4])
    received = p * 10**0.6 * (GPS_L1_WAVELENGTH_M / (4 * math.pi * d)) ** 2
    np.testing.assert_allclose(
        aj.free_space_js_db(p, d, GPS_L1_WAVELENGTH_M, s_dbw, jammer_gain_db=6.0),
        10 * np.log10(received) - s_dbw,
        atol=1e-10,
    )


def test_cep_estimator_on_a_large_seeded_sample() -> None:
    """Oracle: the median radius of a circular normal sample (seed 5, 1e6 samples) is the CEP."""
    rng = np.random.default_rng(5)
    e = 3.0 * rng.standard_normal((1_000_000, 2))
    assert aj.cep_from_horizontal_errors(e) == pytest.approx(np.median(np.hypot(e[:, 0], e[:, 1])), rel=3e-3)


def _m_sequence(taps: tuple[int, ...] = (10, 3), n: int = 10) -> np.ndarray:
    """+-1 chips of a maximal-length LFSR sequence (x^10 + x^3 + 1, the GPS G1 polynomial).

    Its periodic autocorrelation is -1/1023 off the peak, so rectangular chips sampled at an
    integer rate have the ideal triangle correlation up to 1/1023.
    """
    reg = [1] * n
    out = np.empty(2**n - 1)
    for i in range(out.size):
        out[i] = reg[-1]
        fb = reg[taps[0] - 1] ^ reg[taps[1] - 1]
        reg = [fb, *reg[:-1]]
    return 1.0 - 2.0 * out


@pytest.mark.parametrize(("cn0_dbhz", "n_avg"), [(33.0, 1), (40.0, 4)])
def test_code_tracking_sigma_against_sampled_correlators(cn0_dbhz: float, n_avg: int) -> None:
    """Oracle: Monte Carlo of sampled waveforms, not the formula (Kaplan Eq. 5.81, B_n = 1/(2T)).

    A 1023-chip m-sequence, 4 samples per chip, random carrier phase and complex white noise
    of density N0 (variance N0 fs per sample) is correlated with early and late replicas
    (d = 0.5 chip, i.e. +-1 sample) over T_c = 1 ms; the noncoherent discriminator
    |E|^2 - |L|^2 at zero code error, divided by its gain 4 a^2 (1 - d/2), averaged over
    n_avg intervals (T = n_avg T_c) is the code-error estimate. 4000 estimates (seed 11)
    measure its variance to about 3 %; the old formula's variance was twice as large.
    """
    rng = np.random.default_rng(11)
    code = np.repeat(_m_sequence(), 4)
    m, t_c, d = code.size, 1e-3, 0.5
    fs = m / t_c
    cn0 = 10 ** (cn0_dbhz / 10)
    amp = 1.0  # sqrt(C)
    n0 = amp**2 / cn0
    early, late = np.roll(code, -1), np.roll(code, 1)  # replica advanced / delayed by d/2
    a = amp * m  # correlation peak amplitude
    gain = 4 * a**2 * (1 - d / 2)
    est = []
    for _ in range(4000 * n_avg // 500):
        phase = np.exp(2j * np.pi * rng.random((500, 1)))
        noise = rng.standard_normal((500, m)) + 1j * rng.standard_normal((500, m))
        r = amp * code * phase + np.sqrt(n0 * fs / 2) * noise
        e, lt = r @ early, r @ late
        est.append((np.abs(e) ** 2 - np.abs(lt) ** 2) / gain)
    tau = np.concatenate(est).reshape(-1, n_avg).mean(axis=1)
    sigma = aj.code_tracking_sigma_chips(cn0_dbhz, d, integration_s=n_avg * t_c, coherent_s=t_c)
    assert np.var(tau) == pytest.approx(sigma**2, rel=0.08)


def _model(**kw) -> aj.NavigatorErrorModel:
    base = dict(
        accel_bias=1 * MILLI_G,
        accel_tau_s=300.0,
        gyro_bias=4.8e-5,
        gyro_tau_s=300.0,
        accel_vrw=1e-4,
        gyro_arw=1e-5,
        nonorthogonality=1e-3,
        init_pos=10.0,
        init_vel=0.2,
        init_tilt=1e-3,
        range_bias=0.0,
        hdop_axis=1.0,
    )
    base.update(kw)
    return aj.NavigatorErrorModel(**base)


def _continuous_model(m: aj.NavigatorErrorModel) -> tuple[np.ndarray, np.ndarray]:
    """The channel's continuous-time physics, written from the model's description (not its code).

    State [position, velocity, tilt, accelerometer bias, gyro bias, nonorthogonality]:
    p' = v; v' = g tilt + b_a + g n + w_v; tilt' = b_g + w_t; b' = -b/tau + w (first-order
    Gauss-Markov, stationary variance s^2, so driving density 2 s^2/tau); n' = 0.
    """
    F = np.zeros((6, 6))
    F[0, 1] = 1.0
    F[1, [2, 3, 5]] = [G0, 1.0, G0]
    F[2, 4] = 1.0
    F[3, 3], F[4, 4] = -1.0 / m.accel_tau_s, -1.0 / m.gyro_tau_s
    markov = [2 * m.accel_bias**2 / m.accel_tau_s, 2 * m.gyro_bias**2 / m.gyro_tau_s]
    Qc = np.diag([0.0, m.accel_vrw**2, m.gyro_arw**2, *markov, 0.0])
    return F, Qc


def _filterpy_sigma(m: aj.NavigatorErrorModel, fix_sigma: np.ndarray, dt: float) -> float:
    """Oracle: filterpy's KalmanFilter on the continuous model discretised exactly (Van Loan)."""
    from filterpy.kalman import KalmanFilter

    F, Qc = _continuous_model(m)
    kf = KalmanFilter(dim_x=6, dim_z=1)
    kf.F, kf.Q = van_loan_expm(F, Qc, dt)
    kf.H = np.array([[1.0, 0, 0, 0, 0, 0]])
    kf.P = np.diag([m.init_pos, m.init_vel, m.init_tilt, m.accel_bias, m.gyro_bias, m.nonorthogonality]) ** 2
    for s in fix_sigma:
        kf.predict()
        if np.isfinite(s):
            kf.R = np.array([[s**2]])
            kf.update(np.array([0.0]))
    return math.sqrt(kf.P[0, 0])


_AIDED = dict(
    accel_bias=2e-3,
    accel_tau_s=200.0,
    gyro_bias=3e-5,
    gyro_tau_s=400.0,
    accel_vrw=3e-3,
    gyro_arw=2e-5,
    nonorthogonality=5e-4,
    init_pos=30.0,
    init_vel=2.0,
    init_tilt=2e-3,
    hdop_axis=1.5,
)


@pytest.mark.parametrize("range_bias", [0.0, 4.0])
def test_aided_navigator_against_filterpy_and_its_error_statistics(range_bias: float) -> None:
    """Oracles: (i) filterpy's Kalman filter on the continuous-time model of the channel,
    discretised exactly by Van Loan's method (the model's first-order noise injection
    differs by about 1e-4 here), for the final 1-sigma along a history of fixes of two
    sizes and two outages at dt = 0.5 s; (ii) the run-ensemble mean square of the impact
    errors (4000 runs, 8000 channels, seed 3, standard error about 1.6 %) equals that
    variance plus the unestimated range bias times the geometry factor, squared (the
    bias shifts every fix alike, which the filter cannot tell from a position offset).
    Every state, noise and initial sigma is nonzero and distinct, so a swapped or dropped
    term moves (i) by far more than 1e-3."""
    m = aj.NavigatorErrorModel(**_AIDED, range_bias=range_bias)
    sig = np.r_[np.full(100, 2.0), np.full(30, np.nan), np.full(60, 5.0), np.full(20, np.nan)]
    res = aj.simulate_impact_errors(m, sig, runs=4000, seed=3, dt=0.5)
    ref = _filterpy_sigma(m, sig, 0.5)
    assert res.filter_sigma_m == pytest.approx(ref, rel=1e-3)
    np.testing.assert_array_equal(res.locked, np.isfinite(sig))
    assert res.impact_errors_m.shape == (4000, 2)
    expected = ref**2 + (1.5 * range_bias) ** 2
    assert float(np.mean(res.impact_errors_m**2)) == pytest.approx(expected, rel=0.06)


_QUIET = dict(
    accel_bias=0.0,
    accel_tau_s=1e12,
    gyro_bias=0.0,
    gyro_tau_s=1e12,
    accel_vrw=0.0,
    gyro_arw=0.0,
    nonorthogonality=0.0,
    init_pos=0.0,
    init_vel=0.0,
    init_tilt=0.0,
    range_bias=0.0,
    hdop_axis=1.0,
)
_T = 50.0  # free-inertial time, s


@pytest.mark.parametrize(
    ("source", "value", "variance"),
    [
        ("init_pos", 7.0, lambda s: s**2),
        ("init_vel", 0.3, lambda s: (s * _T) ** 2),
        ("init_tilt", 2e-3, lambda s: (G0 * s * _T**2 / 2) ** 2),
        ("nonorthogonality", 1e-3, lambda s: (G0 * s * _T**2 / 2) ** 2),
        ("accel_bias", 1e-3, lambda s: (s * _T**2 / 2) ** 2),
        ("accel_vrw", 1e-2, lambda s: s**2 * _T**3 / 3),
        ("gyro_arw", 1e-4, lambda s: (G0 * s) ** 2 * _T**5 / 20),
    ],
)
def test_free_inertial_error_growth_closed_forms(source: str, value: float, variance) -> None:
    """Oracle: the free-inertial position error of each error source alone, in closed form
    from the continuous-time physics: p(T) = p0, v0 T, g tilt0 T^2/2, g n T^2/2, b T^2/2
    (constant accelerometer bias), the integrated random walk of velocity (var q T^3/3) and
    the twice-integrated tilt random walk through gravity (var g^2 q T^5/20). The filter's
    1-sigma with no fixes is this variance (to the O(1/N) of the model's end-of-step noise
    injection, N = 500 steps: < 0.6 %), and the Monte Carlo (4000 runs, 8000 channels,
    seed 9) reproduces it within its standard error of 1.6 % (tolerance 6 %)."""
    m = aj.NavigatorErrorModel(**{**_QUIET, source: value})
    res = aj.simulate_impact_errors(m, np.full(int(_T / 0.1), np.nan), runs=4000, seed=9, dt=0.1)
    assert res.filter_sigma_m**2 == pytest.approx(variance(value), rel=6e-3)
    assert not res.locked.any()
    assert float(np.mean(res.impact_errors_m**2)) == pytest.approx(variance(value), rel=0.06)


@pytest.mark.parametrize("source", ["accel", "gyro"])
def test_markov_bias_drift_matches_continuous_time_physics(source: str) -> None:
    """Oracle: continuous-time Gauss-Markov physics, not the model's discrete matrices.

    A stationary first-order Markov bias b (variance s^2, autocorrelation s^2 exp(-|u-v|/tau))
    drives the free-inertial position error p(t) = int k(t-u) b(u) du with k(w) = w for an
    accelerometer bias and k(w) = g w^2 / 2 for a gyro bias (through the tilt), so
    var p(t) = s^2 int int k(t-u) k(t-v) exp(-|u-v|/tau) du dv (scipy quad). A discrete
    driving noise off by a factor of 2 moves the 120-s variance by tens of percent; 4000
    seeded runs (8000 channels) resolve it to about 2 %. The model injects each step's driving noise
    at the end of the step (first order in dt, see its docstring), which lowers the
    gyro-driven variance by about 4 % at dt = 1 s (seeds 1-4: 0.94-0.97); hence 8 %.
    """
    from scipy.integrate import quad

    tau, t_end = 30.0, 120.0
    if source == "accel":
        s, kernel = 1 * MILLI_G, (lambda w: w)
        m = _model(accel_bias=s, accel_tau_s=tau, gyro_bias=0.0)
    else:
        s, kernel = 1e-5, (lambda w: G0 * w**2 / 2)
        m = _model(gyro_bias=s, gyro_tau_s=tau, accel_bias=0.0)
    m = aj.NavigatorErrorModel(
        **{**m.__dict__, "accel_vrw": 0.0, "gyro_arw": 0.0, "nonorthogonality": 0.0}
        | {"init_pos": 0.0, "init_vel": 0.0, "init_tilt": 0.0}
    )
    res = aj.simulate_impact_errors(m, np.full(int(t_end), np.nan), runs=4000, seed=21)
    var_mc = float(np.mean(res.impact_errors_m**2))
    # with s = |u - v|: var = 2 s^2 int_0^T exp(-s/tau) int_s^T k(w) k(w - s) dw ds (scipy quad)
    var = (
        2
        * quad(
            lambda lag: math.exp(-lag / tau) * quad(lambda w: kernel(w) * kernel(w - lag), lag, t_end)[0],
            0.0,
            t_end,
            epsrel=1e-10,
        )[0]
    )
    assert var_mc == pytest.approx(s**2 * var, rel=0.08)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: aj.js_for_effective_cn0(20.0, 30.0, 1e6), "threshold_dbhz"),
        (lambda: aj.effective_cn0_dbhz(41.0, 50.0, -1.0), "chip_rate_hz"),
        (lambda: aj.free_space_js_db(-1.0, 10.0, 0.19, -160.0), "jammer_power_w"),
        (lambda: aj.early_minus_late(0.0, 0.0), "spacing_chips"),
        (lambda: aj.cep_from_horizontal_errors(np.ones(3)), "errors_m"),
        (lambda: aj.simulate_impact_errors(_model(), np.ones(3), runs=0), "runs"),
    ],
)
def test_bad_input_raises(call, match) -> None:
    with pytest.raises(ValueError, match=match):
        call()


def test_impact_rms_without_range_bias_is_the_filters_own_sigma() -> None:
    """Oracle: the filter's own covariance recursion inside simulate_impact_errors (its Joseph
    update, not the augmented covariance): with no range bias the filter is optimal, so the true
    error's rms equals the filter's final sigma, here along a history with a 20-s outage."""
    sig = np.full(120, 4.0)
    sig[60:80] = np.nan
    m = _model()
    own = aj.simulate_impact_errors(m, sig, runs=1, seed=0).filter_sigma_m
    assert aj.impact_rms_m(m, sig)[0] == pytest.approx(own, rel=1e-9)


def test_impact_rms_matches_a_seeded_monte_carlo() -> None:
    """Oracle: a seeded Monte Carlo of the same navigator (simulate_impact_errors, 20000 runs,
    40000 axis samples, seed 5) with a 3-m range bias and an outage: the sample rms of the impact
    errors is within 2 % (about 6 standard errors) of the exact rms; rows are propagated alone."""
    m = _model(range_bias=3.0)
    sig = np.full(90, 6.0)
    sig[40:55] = np.nan
    exact = aj.impact_rms_m(m, np.stack([sig, np.full(90, 2.0)]))
    res = aj.simulate_impact_errors(m, sig, runs=20000, seed=5)
    assert float(np.sqrt(np.mean(res.impact_errors_m**2))) == pytest.approx(exact[0], rel=0.02)
    assert exact[1] == pytest.approx(aj.impact_rms_m(m, np.full(90, 2.0))[0], rel=1e-12)
    with pytest.raises(ValueError, match="fix_sigma_m"):
        aj.impact_rms_m(m, -sig)


def test_sp_exact_impact_covariance_matches_monte_carlo() -> None:
    """Oracle: the seeded Monte Carlo of the same reduced navigator (4000 runs, seed 11) for the SP
    PGM claims' exact CEP, at a power with an outage (100 W) and one without (1 W)."""
    from navcore.claims.inputs import recording
    from navcore.papers import sp_antijam as spj

    with recording():
        model = spj.navigator_model()
        for p in (1.0, 100.0):
            for arch in ("TC", "DI"):
                sig = spj.fix_sigma_m(p, arch, "wideband")
                res = aj.simulate_impact_errors(model, sig, runs=4000, seed=11)
                mc = aj.cep_from_horizontal_errors(res.impact_errors_m)
                assert spj.model_cep(arch, p) == pytest.approx(mc, rel=0.04), (p, arch)


def test_sp_min_aj_improvement_is_the_minimum_of_the_curves() -> None:
    """Oracle: brute force, the A/J improvement sampled at 20001 CEPs across Fig. 3.8's ranges; the
    minimum taken at the curves' knots is never above any sample and within 1e-3 dB of the least."""
    from navcore.papers import sp_antijam as spj

    for kind, lo, hi in (("wideband", 6.0, 120.0), ("narrowband", 4.0, 80.0)):
        sampled = spj.aj_improvement_db(kind, np.geomspace(lo, hi, 20001))
        exact = spj.min_aj_improvement_db(kind, lo, hi)
        assert exact <= float(np.min(sampled)) + 1e-12
        assert exact == pytest.approx(float(np.min(sampled)), abs=1e-3)


def test_defaults_return_types_and_boundaries() -> None:
    """Contracts and oracles by hand: the documented defaults (half-chip spacing; Q = 2; a
    1-s average of 20-ms coherent sums) give the same values as passing them; scalars give
    floats and arrays arrays; the discriminator is R(tau - d/2) - R(tau + d/2) by hand at
    tau = 0.1; a threshold equal to the unjammed C/N0 is rejected by name."""
    assert isinstance(aj.ideal_correlation(0.25), float) and aj.ideal_correlation(0.25) == 0.75
    np.testing.assert_allclose(aj.ideal_correlation(np.array([-0.5, 2.0])), [0.5, 0.0])
    assert isinstance(aj.early_minus_late(0.1), float)
    assert aj.early_minus_late(0.1) == pytest.approx((1 - 0.15) - (1 - 0.35), abs=1e-15)
    assert aj.early_minus_late(0.1, 1.0) == pytest.approx((1 - 0.4) - (1 - 0.6), abs=1e-15)
    assert aj.early_minus_late(0.5) == pytest.approx(0.75 - 0.25, abs=1e-15)  # R(0.25) - R(0.75)
    np.testing.assert_allclose(aj.early_minus_late(np.array([0.1, -0.1])), [0.2, -0.2], atol=1e-15)
    assert isinstance(aj.code_tracking_sigma_chips(45.0), float)
    assert aj.code_tracking_sigma_chips(45.0) == aj.code_tracking_sigma_chips(45.0, 0.5, 1.0, 0.02)
    np.testing.assert_allclose(
        aj.code_tracking_sigma_chips(np.array([40.0, 45.0])),
        [aj.code_tracking_sigma_chips(40.0), aj.code_tracking_sigma_chips(45.0)],
        rtol=1e-15,
    )
    assert aj.js_for_effective_cn0(45.0, 30.0, 1e6) == aj.js_for_effective_cn0(45.0, 30.0, 1e6, 2.0)
    assert aj.effective_cn0_dbhz(45.0, 30.0, 1e6) == aj.effective_cn0_dbhz(45.0, 30.0, 1e6, 2.0)
    with pytest.raises(ValueError, match="threshold_dbhz"):
        aj.js_for_effective_cn0(45.0, 45.0, 1e6)


def test_spectral_separation_of_a_very_wide_jammer() -> None:
    """Oracle: kappa by the trapezoid rule on a 2-million-point grid over +-100 chip rates
    (the sinc^2 spectrum has 200 lobes there): a wide flat jammer is despread to about its
    in-band fraction, Q = 1/(Rc kappa) ~ 200."""
    rc, b = 1.023e6, 200 * 1.023e6
    f = np.linspace(-b / 2, b / 2, 2_000_001)
    kappa = np.trapezoid(np.sinc(f / rc) ** 2 / rc, f) / b
    assert aj.spectral_separation_q(b, rc) == pytest.approx(1 / (rc * kappa), rel=1e-6)


def test_cep_relative_sd_matches_repeated_monte_carlo_ceps() -> None:
    """Oracle: 20000 seeded repetitions (seed 13) of a 25-run CEP of unit circular-normal errors
    (cep_from_horizontal_errors on 25 x 2 draws): the sample standard deviation of the CEPs over
    their mean is within 3 % of the first-order 1/sqrt(4 x 25) = 0.1."""
    rng = np.random.default_rng(13)
    ceps = np.array([aj.cep_from_horizontal_errors(rng.standard_normal((25, 2))) for _ in range(20000)])
    assert float(np.std(ceps) / np.mean(ceps)) == pytest.approx(aj.cep_relative_sd(25), rel=0.03)
    assert aj.cep_relative_sd(1) == 0.5
    with pytest.raises(ValueError, match="runs"):
        aj.cep_relative_sd(0)
