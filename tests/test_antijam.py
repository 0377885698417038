"""Anti-jam models against independent oracles (closed forms, brute force, Monte Carlo, filterpy-free KF)."""

from __future__ import annotations

import math

import numpy as np
import pytest

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
    """Oracle: the linear-power closed form solved by hand and the round trip through the inverse."""
    js = aj.js_for_effective_cn0(41.0, 19.0, GPS_P_CHIP_RATE_HZ, 2.0)
    assert aj.effective_cn0_dbhz(41.0, js, GPS_P_CHIP_RATE_HZ, 2.0) == pytest.approx(19.0, abs=1e-10)
    lin = 1 / (1 / 10**4.1 + 10 ** (54 / 10) / (2 * 10.23e6))
    assert aj.effective_cn0_dbhz(41.0, 54.0, GPS_P_CHIP_RATE_HZ, 2.0) == pytest.approx(10 * math.log10(lin))


def test_free_space_js_friis() -> None:
    """Oracle: Friis received power P G (lambda / 4 pi d)^2 in watts, then the dB ratio by hand."""
    d, p, s_dbw = 9260.0, 100.0, -163.0
    received = p * (GPS_L1_WAVELENGTH_M / (4 * math.pi * d)) ** 2
    expected = 10 * math.log10(received) - s_dbw
    assert aj.free_space_js_db(p, d, GPS_L1_WAVELENGTH_M, s_dbw) == pytest.approx(expected, abs=1e-10)


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


def test_code_tracking_sigma_issue_value() -> None:
    """Oracle: Kaplan Eq. 5.81 typed in directly: 45 dB-Hz, d = 0.5, T = 1 s, T_c = 20 ms."""
    cn0 = 10**4.5
    expected = math.sqrt(1 / (2 * 1.0) * 0.5 / (2 * cn0) * (1 + 2 / ((2 - 0.5) * 0.02 * cn0)))
    assert aj.code_tracking_sigma_chips(45.0) == pytest.approx(expected, rel=1e-12)
    assert aj.code_tracking_sigma_chips(45.0) == pytest.approx(0.001990, abs=5e-7)


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


def test_monte_carlo_matches_filter_covariance() -> None:
    """Oracle: the filter's own covariance; with a matched model the run-ensemble rms equals it (seed 3)."""
    sig = np.r_[np.full(200, 3.0), np.full(60, np.nan)]
    res = aj.simulate_impact_errors(_model(), sig, runs=4000, seed=3)
    rms = math.sqrt(np.mean(res.impact_errors_m**2))
    assert rms == pytest.approx(res.filter_sigma_m, rel=0.03)


def test_free_inertial_accel_bias_growth() -> None:
    """Oracle: with no fixes and only a constant accel bias, position error = b t^2 / 2 (closed form)."""
    m = _model(
        accel_tau_s=1e12,
        gyro_bias=0.0,
        accel_vrw=0.0,
        gyro_arw=0.0,
        nonorthogonality=0.0,
        init_pos=0.0,
        init_vel=0.0,
        init_tilt=0.0,
    )
    res = aj.simulate_impact_errors(m, np.full(100, np.nan), runs=20000, seed=9)
    rms = math.sqrt(np.mean(res.impact_errors_m**2))
    assert rms == pytest.approx(1 * MILLI_G * 100.0**2 / 2, rel=0.02)


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


def test_sp_exact_impact_covariance_matches_monte_carlo() -> None:
    """Oracle: the seeded Monte Carlo of the same reduced navigator (4000 runs, seed 11) for the SP
    PGM claims' exact CEP, at a power with an outage (100 W) and one without (1 W)."""
    from navcore.ledger.inputs import recording
    from navcore.papers import sp_antijam as spj

    with recording():
        model = spj.navigator_model()
        for p in (1.0, 100.0):
            for arch in ("TC", "DI"):
                sig = spj.fix_sigma_m(p, arch, "wideband")
                res = aj.simulate_impact_errors(model, sig, runs=4000, seed=11)
                mc = aj.cep_from_horizontal_errors(res.impact_errors_m)
                assert spj.model_cep(arch, p) == pytest.approx(mc, rel=0.04), (p, arch)
