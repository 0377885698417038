"""Covariance-analysis engine against a seeded Monte Carlo of the same linear model, and
the measurement schedules against their definitions."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
from _oracles import van_loan_expm
from filterpy.kalman import KalmanFilter

from navcore.estimation.discretize import discretize, taylor_transition
from navcore.gnss.constellation import nominal_gps_constellation
from navcore.inertial.error_dynamics import (
    ErrorSources,
    GaussMarkov,
    error_dynamics,
    initial_covariance,
    ins_error_layout,
    process_noise_psd,
)
from navcore.inertial.imu import ImuSpec
from navcore.inertial.trajectories import straight_and_level
from navcore.integration.engine import circular_error_probable, embedding, run_covariance_analysis
from navcore.integration.geometry import lock_table, satellite_geometry
from navcore.integration.schedules import (
    baro_schedule,
    combine_schedules,
    loosely_coupled_schedule,
    tightly_coupled_schedule,
    without_step,
)
from navcore.units import DEG, DEG_PER_H, MICRO_G


def _monte_carlo(truth, filt, src, P0, tr, sched, runs, seed):
    """Independent implementation: sample true states, discretise with Van Loan (matrix
    exponential), run the filter's own Riccati recursion and gains, apply them to noisy
    measurements; return the sample covariance of the true estimation error at the end."""
    rng = np.random.default_rng(seed)
    n = truth.size
    idx = embedding(filt, truth)
    F = error_dynamics(
        truth, f_ned=tr.f_ned[0], C_bn=tr.C_bn[0], v_ned=tr.vel_ned[0], lat=tr.lat[0], sources=src
    )
    S = process_noise_psd(truth, src, speed_mps=float(tr.speed[0]))
    Phi, Qd = discretize(F, S, tr.dt)
    Lq = np.linalg.cholesky(Qd + 1e-30 * np.eye(n))
    x = rng.multivariate_normal(np.zeros(n), P0, size=runs, method="eigh")
    xh = np.zeros((runs, idx.size))
    Pf = P0[np.ix_(idx, idx)].copy()
    un = np.setdiff1d(np.arange(n), idx)
    for k in range(len(tr)):
        if k:
            x = x @ Phi.T + rng.standard_normal((runs, n)) @ Lq.T
            Pf_phi = Phi[np.ix_(idx, idx)]
            xh = xh @ Pf_phi.T
            Pf = Pf_phi @ Pf @ Pf_phi.T + Qd[np.ix_(idx, idx)]
        for m in sched(k):
            H, R = m.H, m.R
            Hf = H[:, idx]
            Rf = R + H[:, un] @ P0[np.ix_(un, un)] @ H[:, un].T
            K = Pf @ Hf.T @ np.linalg.inv(Hf @ Pf @ Hf.T + Rf)
            z = x @ H.T + rng.standard_normal((runs, H.shape[0])) @ np.linalg.cholesky(R).T
            xh = xh + (z - xh @ Hf.T) @ K.T
            Pf = (np.eye(idx.size) - K @ Hf) @ Pf
    err = x.copy()
    err[:, idx] -= xh
    return np.cov(err.T)


def test_static_suboptimal_covariance_matches_monte_carlo():
    """Oracle: 4000-run seeded Monte Carlo of the same linear model (Van Loan
    discretisation, explicit filter). The truth has a gravity anomaly and a position-fix
    bias the filter ignores. Agreement within 4 sampling sigmas (sigma of a variance
    estimate is sqrt(2/M) ~ 2.2 %)."""
    truth = ins_error_layout(
        "position", "velocity", "misalignment", "gyro bias", "accel bias", "gravity", "altimeter bias"
    )
    filt = ins_error_layout(
        "position", "velocity", "misalignment", "gyro bias", "accel bias", "altimeter bias"
    )
    spec = ImuSpec(
        "t",
        gyro_bias=0.05 * DEG_PER_H,
        accel_bias=100 * MICRO_G,
        gyro_random_walk=0.1 * DEG_PER_H,
        accel_random_walk=30 * MICRO_G,
    )
    src = ErrorSources(imu=spec, gravity=GaussMarkov(35 * MICRO_G, 1e12), altimeter=GaussMarkov(20.0, 1e12))
    P0 = initial_covariance(
        truth, src, position_sigma=(30, 30, 10), velocity_sigma=(0.3,) * 3, attitude_sigma=(1e-3, 1e-3, 5e-3)
    )
    tr = straight_and_level(600.0, dt=2.0, lat0=45 * DEG)
    n = truth.size
    p = truth.slice("position")

    def fixes(k):
        from navcore.estimation.covariance import Measurement

        if k % 15:
            return []
        H = np.zeros((2, n))
        H[0, p.start] = H[1, p.start + 1] = 1.0
        return [Measurement(H, np.eye(2) * 25.0)]

    sched = combine_schedules(fixes, baro_schedule(truth, noise_m=3.0, every=5))
    res = run_covariance_analysis(tr, truth, filt, src, P0, sched, snapshots=[-1])
    # engine uses a Taylor transition; MC uses the exact exponential: both at dt = 2 s
    C = _monte_carlo(truth, filt, src, P0, tr, sched, runs=4000, seed=7)
    got = np.diag(res.snapshots[len(tr) - 1])
    want = np.diag(C)
    check = [
        truth.index("position", 0),
        truth.index("position", 1),
        truth.index("velocity", 0),
        truth.index("velocity", 1),
        truth.index("misalignment", 2),
        truth.index("accel bias", 0),
    ]
    assert got[check] == pytest.approx(want[check], rel=4 * np.sqrt(2 / 4000))


def test_optimal_filter_matches_filterpy():
    """Oracle: filterpy's KalmanFilter on the same linear model, discretised exactly
    (scipy.linalg.expm of F dt, and Van Loan's block exponential for Q), with a barometric
    height measurement (-1 on the down position and on the altimeter bias, 3 m noise) every
    step; when truth and filter layouts coincide, both of the engine's recursions must agree
    with it (the truth's to the filter's to round-off)."""
    from navcore.inertial.error_dynamics import earth_rate_ned, transport_rate_ned

    lay = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "altimeter bias")
    src = ErrorSources(
        imu=ImuSpec("t", gyro_bias=0.01 * DEG_PER_H, gyro_random_walk=0.01 * DEG_PER_H),
        altimeter=GaussMarkov(50.0, 1e5),
    )
    P0 = initial_covariance(
        lay, src, position_sigma=(10,) * 3, velocity_sigma=(0.1,) * 3, attitude_sigma=(1e-3,) * 3
    )
    tr = straight_and_level(300.0, lat0=30 * DEG)  # at rest: one linearisation
    res = run_covariance_analysis(tr, lay, lay, src, P0, baro_schedule(lay, noise_m=3.0))
    assert res.true_var == pytest.approx(res.filter_var, rel=1e-9, abs=1e-20)

    n = lay.size
    w_in = earth_rate_ned(tr.lat[0]) + transport_rate_ned(tr.vel_ned[0], tr.lat[0], tr.h[0])
    F = error_dynamics(
        lay,
        f_ned=tr.f_ned[0],
        C_bn=tr.C_bn[0],
        omega_ib_b=tr.omega_nb_b[0] + tr.C_bn[0].T @ w_in,
        v_ned=tr.vel_ned[0],
        lat=float(tr.lat[0]),
        h=float(tr.h[0]),
        sources=src,
    )
    S = process_noise_psd(lay, src, speed_mps=0.0)
    Phi, Qd = van_loan_expm(F, S, tr.dt)
    kf = KalmanFilter(dim_x=n, dim_z=1)
    kf.F, kf.Q, kf.P = Phi, Qd, P0.copy()
    kf.H = np.zeros((1, n))
    kf.H[0, lay.index("position", 2)] = kf.H[0, lay.index("altimeter bias")] = -1.0
    kf.R = np.array([[9.0]])
    want = []
    for k in range(len(tr)):
        if k:
            kf.predict()
        kf.update(np.zeros(1))
        want.append(np.diag(kf.P))
    np.testing.assert_allclose(res.filter_var, want, rtol=1e-6)
    np.testing.assert_allclose(res.true_var, want, rtol=1e-6)
    np.testing.assert_array_equal(res.n_updates, np.ones(len(tr)))
    np.testing.assert_allclose(
        res.horizontal_position, np.sqrt(np.array(want)[:, 0] + np.array(want)[:, 1]), rtol=1e-6
    )
    np.testing.assert_allclose(
        res.horizontal_velocity, np.sqrt(np.array(want)[:, 3] + np.array(want)[:, 4]), rtol=1e-6
    )


def test_cep_against_monte_carlo():
    """Oracle: empirical median radius of 200000 seeded samples of an elliptical Gaussian."""
    P = np.array([[4.0, 1.0], [1.0, 1.0]])
    rng = np.random.default_rng(3)
    x = rng.multivariate_normal([0, 0], P, size=200_000)
    assert circular_error_probable(P) == pytest.approx(np.median(np.hypot(*x.T)), rel=0.01)
    with pytest.raises(ValueError, match="p must be"):
        circular_error_probable(P, 1.5)


def _circle_probability(P, r):
    """P(|x| < r) for x ~ N(0, P): rotate to the principal axes (numpy eigh), then
    integrate the marginal of the major-axis coordinate times the conditional probability
    of |y| < sqrt(r^2 - x^2) with scipy.integrate.quad."""
    from scipy.integrate import quad
    from scipy.stats import norm

    b, a = np.linalg.eigvalsh(P)  # x along the major axis
    f = lambda x: norm.pdf(x, scale=np.sqrt(a)) * (2 * norm.cdf(np.sqrt(r * r - x * x) / np.sqrt(b)) - 1)
    d = 50 * b / r  # |y| < sqrt(r^2 - x^2) turns from certain to impossible within ~b/r of |x| = r
    points = [-r + d, r - d] if d < r else None
    return quad(f, -r, r, points=points, epsabs=1e-14, epsrel=1e-13, limit=500)[0]


@pytest.mark.parametrize("scale", [1e-6, 1.0, 1e4])
@pytest.mark.parametrize("p", [0.5, 0.95])
def test_cep_against_quadrature(scale, p):
    """Oracle: the probability inside the circle by scipy quadrature (_circle_probability),
    solved for the radius with scipy's brentq, for an elongated, rotated covariance at three
    scales; and the circular closed form sigma sqrt(-2 ln(1 - p))."""
    from scipy.optimize import brentq

    c, s_ = np.cos(0.7), np.sin(0.7)
    Rm = np.array([[c, -s_], [s_, c]])
    P = scale * Rm @ np.diag([9.0, 0.25]) @ Rm.T
    want = brentq(
        lambda r: _circle_probability(P, r) - p,
        1e-9 * np.sqrt(scale),
        20 * np.sqrt(scale),
        xtol=1e-15 * np.sqrt(scale),
    )
    assert circular_error_probable(P, p) == pytest.approx(want, rel=1e-9)
    assert circular_error_probable(scale * np.eye(2), p) == pytest.approx(
        np.sqrt(-2 * scale * np.log(1 - p)), rel=1e-10
    )


@pytest.mark.parametrize("ratio", [1e-4, 1e-6, 1e-10, 0.0])
def test_cep_of_elongated_ellipses(ratio):
    """Oracle: scipy quadrature (_circle_probability) for error ellipses up to 10^5 : 1 in
    sigma, and for a degenerate (1-D) covariance the median of |x| for x ~ N(0, 4):
    2 * 0.6744897501960817 (scipy.stats.norm.ppf(0.75))."""
    from scipy.optimize import brentq
    from scipy.stats import norm

    P = np.diag([4.0, 4.0 * ratio])
    got = circular_error_probable(P)
    if ratio == 0.0:
        assert got == pytest.approx(2 * norm.ppf(0.75), rel=1e-9)
    else:
        want = brentq(lambda r: _circle_probability(P, r) - 0.5, 1e-6, 20.0, xtol=1e-15)
        assert got == pytest.approx(want, rel=1e-9)
    assert circular_error_probable(np.zeros((2, 2))) == 0.0
    # dimensional analysis: scaling the covariance by k scales the CEP by sqrt(k), to the last
    # digits, from a micrometre-sized error (k = 1e-14) to a kilometre-sized one (k = 1e6);
    # p outside (0, 1) is rejected, naming it
    P = np.array([[1.0, 0.3], [0.3, 0.5]])
    for k in (1e-20, 1e-14, 1e6):
        assert circular_error_probable(k * P) == pytest.approx(
            np.sqrt(k) * circular_error_probable(P), rel=1e-12
        )
    for p in (0.0, 1.0):
        with pytest.raises(ValueError, match=r"^p must be in \(0, 1\)"):
            circular_error_probable(P, p=p)


def test_lock_table_and_tightly_coupled_rows():
    """Oracle: the event list read by hand; H rows equal -u and the clock/bias unit entries."""
    t = np.arange(0.0, 10.0)
    code, carrier = lock_table(  # events in any order: applied in time order
        t, 2, [(8.0, 0, "code", True), (3.0, 0, "carrier", False), (5.0, 0, "code", False)]
    )
    assert carrier[:, 0].tolist() == [True] * 3 + [False] * 7
    assert code[:, 0].tolist() == [True] * 5 + [False] * 3 + [True] * 2
    assert code[:, 1].all()
    # simultaneous events apply in the order listed: the last one sets the state
    for last in (True, False):
        same_time = [(4.0, 1, "carrier", not last), (4.0, 1, "carrier", last)]
        _, c = lock_table(t, 2, same_time, start_locked=False)
        assert c[:, 1].tolist() == [False] * 4 + [last] * 6
    lay = ins_error_layout(
        "position", "velocity", "misalignment", "clock bias", "clock drift", "pseudorange bias", channels=2
    )
    tr = straight_and_level(9.0, lat0=40 * DEG)
    geo = satellite_geometry(tr, nominal_gps_constellation(), [0, 1])
    sched = tightly_coupled_schedule(lay, geo, code, carrier, pseudorange_noise=1.0, range_rate_noise=0.1)
    m = sched(6)  # channel 0: nothing; channel 1: code and carrier
    assert len(m) == 1 and m[0].H.shape == (2, lay.size)
    H = m[0].H
    assert H[0, :3] == pytest.approx(-geo.u_ned[6, 1])
    assert H[0, lay.slice("clock bias")] == 1.0
    assert H[0, lay.index("pseudorange bias", 1)] == 1.0
    assert H[0, lay.index("pseudorange bias", 0)] == 0.0
    assert H[1, 3:6] == pytest.approx(-geo.u_ned[6, 1])
    assert np.diag(m[0].R) == pytest.approx([1.0, 0.01])


#: The loosely coupled receiver's fix interval and EHE gate of the tests below (SP Sec. 2.1's values)
_LC = {"interval_steps": 10, "max_ehe_m": 100.0}


def test_loosely_coupled_gating():
    """Oracle: SP Sec. 2.1 rule: a fix every 10 s only with >= 4 codes and EHE < 100 m;
    its noise is sigma^2 (G'G)^-1 (least squares)."""
    tr = straight_and_level(30.0, lat0=40 * DEG)
    const = nominal_gps_constellation()
    from navcore.gnss.constellation import visible

    vis = np.flatnonzero(visible(const, 0.0, tr.lat[0], tr.lon[0], 0.0, mask_deg=10.0))[:5]
    geo = satellite_geometry(tr, const, vis)
    lay = ins_error_layout("position", "velocity", "misalignment")
    code = np.ones((len(tr), vis.size), bool)
    sched = loosely_coupled_schedule(lay, geo, code, pseudorange_noise=2.0, **_LC)
    assert sched(5) == [] and len(sched(10)) == 1
    code[:, :2] = False  # three codes left
    assert loosely_coupled_schedule(lay, geo, code, pseudorange_noise=2.0, **_LC)(10) == []
    code[:] = True
    assert (
        loosely_coupled_schedule(lay, geo, code, pseudorange_noise=2.0, interval_steps=10, max_ehe_m=0.1)(10)
        == []
    )
    m = sched(20)[0]
    u = geo.u_ned[20]
    G = np.hstack([-u, np.ones((vis.size, 1))])
    assert m.R == pytest.approx(4.0 * np.linalg.inv(G.T @ G)[:3, :3])
    # EHE = sigma_UERE * HDOP at the gate: HDOP from the sample covariance of least-squares
    # solutions (numpy lstsq) to seeded unit-variance range noise, not from (G'G)^-1
    rng = np.random.default_rng(8)
    u10 = geo.u_ned[10]
    G10 = np.hstack([-u10, np.ones((vis.size, 1))])
    sol = np.linalg.lstsq(G10, rng.standard_normal((vis.size, 200_000)), rcond=None)[0]
    hdop = np.sqrt(np.var(sol[0]) + np.var(sol[1]))
    sigma_uere = np.hypot(2.0, 1.5)
    ehe = sigma_uere * hdop
    assert 1.0 < ehe < 20.0  # a fix of metres, so the gate below tests the square root
    for factor, accepted in ((1.02, True), (0.98, False)):
        gate = loosely_coupled_schedule(
            lay,
            geo,
            code,
            pseudorange_noise=2.0,
            pseudorange_bias_sigma=1.5,
            interval_steps=10,
            max_ehe_m=factor * ehe,
        )
        assert (len(gate(10)) == 1) is accepted, factor


def test_embedding_requires_subset():
    a = ins_error_layout("position", "velocity", "misalignment")
    b = ins_error_layout("position", "velocity", "misalignment", "gravity")
    assert embedding(a, b).tolist() == list(range(9))
    with pytest.raises(ValueError, match="subset"):
        embedding(b, a)


def test_taylor_transition_close_to_exponential():
    """Oracle: scipy.linalg.expm; the fourth-order Taylor transition at 1 s differs by
    less than 1e-6 of the largest entry for a moving, turning aircraft."""
    lay = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "accel scale factor")
    F = error_dynamics(
        lay,
        f_ned=(1.0, 2.0, -9.9),
        C_bn=np.eye(3),
        omega_ib_b=(0.01, 0.02, 0.05),
        v_ned=(200.0, 50.0, 0.0),
        lat=0.6,
    )
    E = scipy.linalg.expm(F)
    assert np.max(np.abs(E - taylor_transition(F, 1.0))) < 1e-6 * np.max(np.abs(E))


def test_taylor_transition_is_the_truncated_exponential_series():
    """Oracle: the series sum_{j<=order} (F dt)^j / j! summed term by term with numpy matrix
    powers, for a dense, non-nilpotent F (every power contributes), at the default order 4
    and at orders 1, 2 and 6."""
    from math import factorial

    rng = np.random.default_rng(7)
    F, dt = rng.standard_normal((5, 5)), 0.7
    for order in (1, 2, 4, 6):
        series = sum(np.linalg.matrix_power(F * dt, j) / factorial(j) for j in range(order + 1))
        got = taylor_transition(F, dt) if order == 4 else taylor_transition(F, dt, order=order)
        np.testing.assert_allclose(got, series, rtol=0, atol=1e-13 * np.max(np.abs(series)))


def test_discrete_noise_against_van_loan():
    """Oracle: Van Loan's block exponential (scipy expm). For a dense F with |F| dt about
    0.05 the documented error is of order (|F| dt)^5 / 5! from the fourth-order transition
    and (|F| dt)^6 from the 3-point rule: below 1e-8 of the largest entry. A stack of PSDs
    gives the stack of results; the result is exactly symmetric."""
    rng = np.random.default_rng(11)
    n, dt = 4, 0.5
    F = rng.standard_normal((n, n))
    F *= 0.05 / (np.linalg.norm(F, 2) * dt)
    L = rng.standard_normal((3, n, n))
    S = L @ np.swapaxes(L, -1, -2)
    Q = discretize(F, S, dt, method="series")[1]
    assert Q.shape == (3, n, n)
    for b in range(3):
        _, Q_ref = van_loan_expm(F, S[b], dt)
        np.testing.assert_allclose(Q[b], Q_ref, rtol=0, atol=1e-8 * np.max(np.abs(Q_ref)))
        np.testing.assert_array_equal(Q[b], Q[b].T)
        np.testing.assert_allclose(discretize(F, S[b], dt, method="series")[1], Q[b], rtol=1e-15, atol=0)


def test_composite_steps_give_the_single_step_histories_between_fixes():
    """Oracle: the same analysis stepped one sample at a time (every step a single
    propagation, no composite). With ``measurement_steps`` the engine jumps ten measurement-
    free steps at once; the variances of the samples in between must be those single steps'
    (the saw-tooth growth after each fix), not an interpolation between fixes (which was up
    to 60 % low a few seconds after a fix), for the true and the filter covariance alike;
    the static states (random constants) keep their variance exactly."""
    truth = ins_error_layout(
        "position", "velocity", "misalignment", "gyro bias", "accel bias", "gravity", "altimeter bias"
    )
    filt = ins_error_layout(
        "position", "velocity", "misalignment", "gyro bias", "accel bias", "altimeter bias"
    )
    spec = ImuSpec(
        "t", gyro_bias=0.05 * DEG_PER_H, accel_bias=100 * MICRO_G, gyro_random_walk=0.1 * DEG_PER_H
    )
    src = ErrorSources(imu=spec, gravity=GaussMarkov(35 * MICRO_G, 37e3), altimeter=GaussMarkov(50.0, 460e3))
    P0 = initial_covariance(truth, src, position_sigma=(30, 30, 10), velocity_sigma=(0.3,) * 3)
    tr = straight_and_level(400.0, speed=200.0, heading=np.pi / 2, dt=1.0, lat0=45 * DEG)  # constant latitude
    n = truth.size
    p = truth.slice("position")

    def fixes(k):
        from navcore.estimation.covariance import Measurement

        if k % 10:
            return []
        H = np.zeros((2, n))
        H[0, p.start] = H[1, p.start + 1] = 1.0
        return [Measurement(H, np.eye(2) * 4.0)]

    sched = combine_schedules(fixes, baro_schedule(truth, noise_m=3.0, every=10))
    steps = np.arange(len(tr)) % 10 == 0
    fast = run_covariance_analysis(
        tr, truth, filt, [src, src], np.stack([P0, 2 * P0]), sched, measurement_steps=steps
    )
    slow = run_covariance_analysis(tr, truth, filt, [src, src], np.stack([P0, 2 * P0]), sched)
    for a, b in zip(fast, slow, strict=True):
        np.testing.assert_allclose(a.true_var, b.true_var, rtol=1e-9, atol=1e-18)
        np.testing.assert_allclose(a.filter_var, b.filter_var, rtol=1e-9, atol=1e-18)
        np.testing.assert_allclose(a.final_true, b.final_true, rtol=1e-9, atol=1e-18)
    # the saw-tooth: 9 s after a fix the position error is well above its value at the fix
    k = 109
    assert slow[0].horizontal_position[k] > 1.2 * slow[0].horizontal_position[100]


def _all_blocks_layout():
    return ins_error_layout(
        "position", "velocity", "clock bias", "clock drift", "misalignment", "gyro bias",
        "gyro scale factor", "gyro misalignment", "accel bias", "accel scale factor",
        "accel misalignment", "altimeter bias", "gravity", "clock g-sensitivity",
        "pseudorange bias", channels=3,
    )  # fmt: skip


def _all_sources(scale=1.0):
    from navcore.inertial.error_dynamics import ClockModel

    return ErrorSources(
        imu=ImuSpec("x", accel_random_walk=1e-3 * scale, gyro_random_walk=1e-6 * scale),
        gravity=GaussMarkov(sigma=3e-4 * scale, distance_constant_m=2.0e4),
        altimeter=GaussMarkov(sigma=10.0 * scale, distance_constant_m=5.0e4),
        clock=ClockModel(bias_sigma=1.0, drift_sigma=0.1, bias_psd=0.2 * scale, drift_psd=0.01),
    )


@pytest.mark.parametrize("vertical_channel", [True, False])
def test_batched_kernels_equal_the_checked_functions_per_condition(vertical_channel):
    """Oracle: the public, per-condition error_dynamics, process_noise_psd, taylor_transition and
    discretize (method "series"); the engine's batched, unchecked kernels (the row-sparse series of
    discretize_unchecked) give the same matrices for each of a
    stack of random flight conditions (every block of the model present)."""
    from scipy.spatial.transform import Rotation

    from navcore.estimation.discretize import discretize_unchecked
    from navcore.inertial.error_dynamics import _error_dynamics_stack, _process_noise_diag_stack

    rng = np.random.default_rng(7)
    lay = _all_blocks_layout()
    srcs = [_all_sources(), _all_sources(2.0)]
    M = 5
    f = rng.normal(0.0, 3.0, (M, 3)) + np.array([0.0, 0.0, -9.8])
    C = Rotation.random(M, random_state=3).as_matrix()
    w = rng.normal(0.0, 0.05, (M, 3))
    v = rng.normal(0.0, 150.0, (M, 3))
    lat, h, speed = rng.uniform(-1.2, 1.2, M), rng.uniform(0.0, 9e3, M), rng.uniform(0.0, 300.0, M)
    F = _error_dynamics_stack(
        lay, f_ned=f, C_bn=C, omega_ib_b=w, v_ned=v, lat=lat, h=h, sources=srcs[0],
        vertical_channel=vertical_channel,
    )  # fmt: skip
    q = np.stack([_process_noise_diag_stack(lay, s, speed) for s in srcs], axis=1)
    dt = 1.0
    Phi, Q = discretize_unchecked(F[:, None], q, dt, method="series", diagonal=True, sparse=True)
    Phi = Phi[:, 0]
    for m in range(M):
        F1 = error_dynamics(
            lay, f_ned=f[m], C_bn=C[m], omega_ib_b=w[m], v_ned=v[m], lat=float(lat[m]), h=float(h[m]),
            sources=srcs[0], vertical_channel=vertical_channel,
        )  # fmt: skip
        np.testing.assert_allclose(F[m], F1, rtol=1e-14, atol=1e-18)
        S1 = np.stack([process_noise_psd(lay, s, speed_mps=float(speed[m])) for s in srcs])
        np.testing.assert_array_equal(np.stack([np.diag(x) for x in q[m]]), S1)
        np.testing.assert_allclose(Phi[m], taylor_transition(F1, dt), rtol=1e-13, atol=1e-16)
        Q1 = discretize(F1, S1, dt, method="series")[1]
        np.testing.assert_allclose(Q[m], Q1, rtol=1e-12, atol=1e-14 * np.abs(Q1).max())


def test_transition_series_order_is_converged_on_a_turning_flight(monkeypatch):
    """Oracle: the same run with the transition series taken to order 12 instead of 4 (the
    truncation error of order 4 is below 1e-9 of the exponential at the 1-s step of a 4 deg/s
    break turn, the fastest rotation of the SP scenarios, and at the 10-s steps of a vehicle at
    rest): the series' order is a resolution, not an input, and moves no variance by more than
    1e-7 relative over ten minutes of turning flight with sensor scale factors."""
    import navcore.integration.engine as ca
    from navcore.inertial.trajectories import Segment, fly

    lay = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "gyro scale factor")
    src = ErrorSources(
        imu=ImuSpec(
            "t", gyro_bias=0.01 * DEG_PER_H, gyro_scale_factor=1e-4, gyro_random_walk=0.003 * DEG_PER_H
        )
    )
    P0 = initial_covariance(
        lay, src, position_sigma=(10,) * 3, velocity_sigma=(0.1,) * 3, attitude_sigma=(1e-3,) * 3
    )
    turn = 4.0 * DEG
    segs = [Segment(60.0), Segment(90.0, turn_rate=turn), Segment(60.0), Segment(90.0, turn_rate=-turn)]
    tr = fly(segs * 2, dt=1.0, lat0=35 * DEG, speed0=200.0, h0=7000.0)
    ca._TRANSITIONS.clear()  # the engine's store of transitions: each run computes its own
    base = run_covariance_analysis(tr, lay, lay, src, P0)
    monkeypatch.setattr(ca, "_SERIES_ORDER", 12)  # the transition and the noise's nodes
    ca._TRANSITIONS.clear()
    fine = run_covariance_analysis(tr, lay, lay, src, P0)
    ca._TRANSITIONS.clear()
    assert not np.array_equal(fine.true_var, base.true_var)  # the longer series was used
    np.testing.assert_allclose(fine.true_var, base.true_var, rtol=1e-7, atol=0.0)


def test_shared_transitions_give_the_uncached_run_and_a_changed_input_misses():
    """Oracle: the same analysis with the engine's store of transitions emptied first (every
    transition and noise computed afresh). A second run served from the store is bit for bit
    the uncached one; a run whose error sources differ in one number (and one whose trajectory
    differs) computes its own matrices and equals its own uncached run, not the first one."""
    import navcore.integration.engine as ca

    truth = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "gravity")
    filt = ins_error_layout("position", "velocity", "misalignment", "gyro bias")
    spec = ImuSpec("t", gyro_bias=0.05 * DEG_PER_H, gyro_random_walk=0.1 * DEG_PER_H)
    src = ErrorSources(imu=spec, gravity=GaussMarkov(35 * MICRO_G, 37e3))
    src2 = ErrorSources(imu=spec, gravity=GaussMarkov(35.01 * MICRO_G, 37e3))
    P0 = initial_covariance(truth, src, position_sigma=(30, 30, 10), velocity_sigma=(0.3,) * 3)
    tr = straight_and_level(200.0, speed=200.0, dt=1.0, lat0=45 * DEG)
    tr2 = straight_and_level(200.0, speed=201.0, dt=1.0, lat0=45 * DEG)
    sched = baro_schedule(truth, noise_m=3.0, every=10)

    def run(trajectory, sources, *, cold):
        if cold:
            ca._TRANSITIONS.clear()
        return run_covariance_analysis(trajectory, truth, filt, sources, P0, sched)

    def same(a, b):
        return all(
            np.array_equal(getattr(a, f), getattr(b, f)) for f in ("true_var", "filter_var", "final_true")
        )

    cold = run(tr, src, cold=True)
    assert len(ca._TRANSITIONS) > 0
    assert same(run(tr, src, cold=False), cold)
    for trajectory, sources in ((tr, src2), (tr2, src)):
        warm = run(trajectory, sources, cold=False)
        assert same(warm, run(trajectory, sources, cold=True))
        assert not same(warm, cold)
    assert ca._digest(35 * MICRO_G) != ca._digest(np.nextafter(35 * MICRO_G, 1.0))
    assert ca._digest(object()) is None  # a value it cannot spell exactly is never cached


def test_random_constants_skipped_only_where_they_are_constant(monkeypatch):
    """Oracle: the plain recursion written out with the public, per-condition functions
    (error_dynamics, process_noise_psd, taylor_transition, discretize): both covariances
    propagated in full (Phi P Phi^T + Q), the filter's gain from its own covariance, the truth
    updated in Joseph form with that gain.

    The engine propagates only the states that are not random constants (unit transition row,
    no noise), with the structure read from the first linearisation points. Here the gravity
    and altimeter Gauss-Markov states are random constants while the vehicle stands still (their
    correlation time is distance over speed) and not once it moves; with two linearisation
    points per batch, the later batches do not fit the first one's structure and must be
    propagated in full. The filter leaves the gravity out (a suboptimal filter)."""
    import navcore.integration.engine as ca
    from navcore.estimation.covariance import Measurement
    from navcore.inertial.error_dynamics import earth_rate_ned, transport_rate_ned
    from navcore.inertial.trajectories import Segment, fly

    monkeypatch.setattr(ca, "_LIN_CHUNK", 2)
    paths = []  # True: only the dynamic rows propagated, False: in full
    real = ca._propagate

    def recorded(P, Phi, Q, dyn_T, d):
        paths.append(dyn_T is not None)
        return real(P, Phi, Q, dyn_T, d)

    monkeypatch.setattr(ca, "_propagate", recorded)
    truth = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "gravity", "altimeter bias")
    filt = ins_error_layout("position", "velocity", "misalignment", "gyro bias", "altimeter bias")
    src = ErrorSources(
        imu=ImuSpec(
            "t", gyro_bias=0.05 * DEG_PER_H, gyro_random_walk=0.1 * DEG_PER_H, accel_random_walk=50 * MICRO_G
        ),
        gravity=GaussMarkov(35 * MICRO_G, 2.0e3),
        altimeter=GaussMarkov(20.0, 5.0e3),
    )
    P0 = initial_covariance(truth, src, position_sigma=(30, 30, 10), velocity_sigma=(0.3,) * 3)
    tr = fly([Segment(6.0), Segment(20.0, speed_rate=5.0)], dt=1.0, lat0=45 * DEG)
    assert tr.speed[0] == 0.0 and tr.speed[-1] > 50.0
    n = truth.size
    p = truth.slice("position")

    def fixes(k):
        if k % 3:
            return []
        H = np.zeros((2, n))
        H[0, p.start] = H[1, p.start + 1] = 1.0
        return [Measurement(H, np.eye(2) * 25.0)]

    sched = combine_schedules(fixes, baro_schedule(truth, noise_m=3.0, every=2))
    got = run_covariance_analysis(tr, truth, filt, src, P0, sched, relinearize_every=1)
    assert True in paths and False in paths  # the first batches skip the constants, later ones do not

    idx = embedding(filt, truth)
    unmodelled = np.setdiff1d(np.arange(n), idx)
    Pt, Pf = P0.copy(), P0[np.ix_(idx, idx)].copy()
    want_t, want_f = [], []
    for k in range(len(tr)):
        if k:
            j = k - 1
            w_in = earth_rate_ned(tr.lat[j]) + transport_rate_ned(tr.vel_ned[j], tr.lat[j], tr.h[j])
            F = error_dynamics(
                truth,
                f_ned=tr.f_ned[j],
                C_bn=tr.C_bn[j],
                omega_ib_b=tr.omega_nb_b[j] + tr.C_bn[j].T @ w_in,
                v_ned=tr.vel_ned[j],
                lat=float(tr.lat[j]),
                h=float(tr.h[j]),
                sources=src,
            )
            S = process_noise_psd(truth, src, speed_mps=float(tr.speed[j]))
            Phi, Q = taylor_transition(F, tr.dt), discretize(F, S, tr.dt, method="series")[1]
            Pt = Phi @ Pt @ Phi.T + Q
            Pf = Phi[np.ix_(idx, idx)] @ Pf @ Phi[np.ix_(idx, idx)].T + Q[np.ix_(idx, idx)]
        meas = sched(k)
        if meas:
            H = np.vstack([m.H for m in meas])
            R = scipy.linalg.block_diag(*[m.R for m in meas])
            Hf, Hu = H[:, idx], H[:, unmodelled]
            Rf = R + Hu @ P0[np.ix_(unmodelled, unmodelled)] @ Hu.T
            K = Pf @ Hf.T @ np.linalg.inv(Hf @ Pf @ Hf.T + Rf)
            Pf = (np.eye(idx.size) - K @ Hf) @ Pf @ (np.eye(idx.size) - K @ Hf).T + K @ Rf @ K.T
            EK = np.zeros((n, H.shape[0]))
            EK[idx] = K
            A = np.eye(n) - EK @ H
            Pt = A @ Pt @ A.T + EK @ R @ EK.T
        want_t.append(np.diag(Pt))
        want_f.append(np.diag(Pf))
    np.testing.assert_allclose(got.true_var, want_t, rtol=1e-9, atol=1e-24)
    np.testing.assert_allclose(got.filter_var, want_f, rtol=1e-9, atol=1e-24)


def test_without_step_drops_one_step_only() -> None:
    """Oracle: the schedule's own output, step by step: the same measurements (H and R) at every
    step but the dropped one, none there; a negative step is rejected by name."""
    from navcore.inertial.error_dynamics import ins_error_layout

    both = combine_schedules(
        baro_schedule(ins_error_layout("position", "velocity"), noise_m=3.0, every=2),
        baro_schedule(ins_error_layout("position", "velocity"), noise_m=5.0),
    )
    cut = without_step(both, 4)
    for k in range(8):
        want = [] if k == 4 else both(k)
        got = cut(k)
        assert len(got) == len(want)
        for a, b in zip(got, want, strict=True):
            np.testing.assert_array_equal(a.H, b.H)
            np.testing.assert_array_equal(a.R, b.R)
    with pytest.raises(ValueError, match="step"):
        without_step(both, -1)
