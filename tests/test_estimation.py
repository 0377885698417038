"""Estimation core: Kalman filter, information form, Riccati steady state, Van Loan, covariance
analysis, state layouts.

Oracles: filterpy's KalmanFilter on the same problem; closed-form discretisation of a double
integrator and of a first-order Gauss-Markov process; the iterated scalar Riccati recursion;
a seeded Monte Carlo of the same linear model for the covariance propagation.
"""

from __future__ import annotations

import numpy as np
import pytest
from filterpy.kalman import KalmanFilter
from hypothesis import given, settings
from hypothesis import strategies as st

from navcore.estimation import (
    CovarianceHistory,
    Measurement,
    StateBlock,
    StateLayout,
    covariance_from_information,
    discretize,
    first_order_transition,
    information_from_covariance,
    information_update,
    kf_predict,
    kf_update,
    propagate_covariance,
    scalar_riccati_iterate,
    scalar_riccati_steady_state,
)


def _random_spd(rng, n, scale=1.0):
    A = rng.normal(size=(n, n))
    return scale * (A @ A.T + n * np.eye(n))


def _step_beside_filterpy(rng, x, P, F, Q, H, R, *, steps, rtol, validate):
    """Run kf_predict/kf_update and filterpy's KalmanFilter side by side on the same random
    measurements; state, covariance, gain, innovation and its covariance agree at every step
    (and the checked path keeps P exactly symmetric)."""
    m, n = H.shape
    kf = KalmanFilter(dim_x=n, dim_z=m)
    kf.x, kf.P, kf.F, kf.Q, kf.H, kf.R = x.copy(), P.copy(), F, Q, H, R
    for _ in range(steps):
        z = rng.normal(size=m)
        x, P = kf_predict(x, P, F, Q, validate=validate)
        res = kf_update(x, P, z, H, R, validate=validate)
        x, P = res.x, res.P
        kf.predict()
        kf.update(z)
        for ours, theirs in ((x, kf.x), (P, kf.P), (res.K, kf.K), (res.innovation, kf.y), (res.S, kf.S)):
            np.testing.assert_allclose(ours, theirs, rtol=rtol, atol=1e-12)
        if validate:
            assert np.array_equal(P, P.T)


def _random_linear_model(rng, n, m, *, spread, q, r):
    """F = I + spread * N(0, 1), random SPD Q and R of scales q and r, H ~ N(0, 1) (m x n),
    drawn from ``rng`` in that order."""
    F = np.eye(n) + spread * rng.normal(size=(n, n))
    Q = _random_spd(rng, n, q)
    H = rng.normal(size=(m, n))
    return F, Q, H, _random_spd(rng, m, r)


def test_kalman_filter_matches_filterpy():
    """Oracle: filterpy.kalman.KalmanFilter (predict/update) over 50 steps of a 4-state model."""
    rng = np.random.default_rng(7)
    F, Q, H, R = _random_linear_model(rng, 4, 2, spread=0.1, q=0.01, r=0.1)
    x = np.zeros(4)
    P = _random_spd(rng, 4)
    _step_beside_filterpy(rng, x, P, F, Q, H, R, steps=50, rtol=1e-9, validate=True)


def test_kalman_fast_path_matches_filterpy():
    """Oracle: filterpy.kalman.KalmanFilter; the unchecked path (validate=False, float
    arrays) gives the same predict and update as the checked one."""
    rng = np.random.default_rng(17)
    F, Q, H, R = _random_linear_model(rng, 3, 2, spread=0.2, q=0.05, r=0.3)
    x, P = rng.normal(size=3), _random_spd(rng, 3)
    _step_beside_filterpy(rng, x, P, F, Q, H, R, steps=3, rtol=1e-10, validate=False)


def test_information_update_equals_covariance_update():
    """Oracle: filterpy.kalman.KalmanFilter.update on the same prior and measurement."""
    rng = np.random.default_rng(8)
    n, m = 3, 2
    P = _random_spd(rng, n)
    x = rng.normal(size=n)
    H = rng.normal(size=(m, n))
    R = _random_spd(rng, m)
    z = rng.normal(size=m)
    y, Y = information_from_covariance(x, P)
    np.testing.assert_allclose(Y @ P, np.eye(n), atol=1e-12)
    np.testing.assert_allclose(P @ y, x, rtol=1e-12, atol=1e-14)
    y2, Y2 = information_update(y, Y, z, H, R)
    x2, P2 = covariance_from_information(y2, Y2)
    kf = KalmanFilter(dim_x=n, dim_z=m)
    kf.x, kf.P, kf.H, kf.R = x.copy(), P.copy(), H, R
    kf.update(z)
    np.testing.assert_allclose(P2, kf.P, rtol=1e-10)
    np.testing.assert_allclose(x2, kf.x, rtol=1e-10, atol=1e-12)


def test_information_update_from_zero_prior():
    """With no prior information, one full-rank update gives the weighted least-squares solution."""
    H = np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 2.0]])
    R = np.diag([1.0, 4.0, 2.0])
    z = np.array([1.0, 3.0, 4.0])
    y, Y = information_update(np.zeros(2), np.zeros((2, 2)), z, H, R)
    W = np.linalg.inv(R)
    ls = np.linalg.solve(H.T @ W @ H, H.T @ W @ z)
    np.testing.assert_allclose(np.linalg.solve(Y, y), ls)


@settings(max_examples=80, deadline=None)
@given(
    st.floats(-1.2, 1.2),
    st.floats(1e-4, 10.0),
    st.floats(0.1, 3.0),
    st.floats(1e-3, 10.0),
)
def test_scalar_riccati_steady_state_matches_scipy_dare(phi, q, h, r):
    """Oracle: scipy.linalg.solve_discrete_are for the prior P- (the filtering DARE with
    A = phi, B = h), then P+ = P- r / (h^2 P- + r) and K = P- h / (h^2 P- + r) (Kalman 1960)."""
    from scipy.linalg import solve_discrete_are

    ss = scalar_riccati_steady_state(phi, q, h, r)
    prior = float(
        solve_discrete_are(np.array([[phi]]), np.array([[h]]), np.array([[q]]), np.array([[r]]))[0, 0]
    )
    assert ss.prior == pytest.approx(prior, rel=1e-7)
    assert ss.posterior == pytest.approx(prior * r / (h * h * prior + r), rel=1e-7)
    assert ss.gain == pytest.approx(prior * h / (h * h * prior + r), rel=1e-7)


def test_scalar_riccati_iterate_matches_filterpy():
    """Oracle: filterpy's one-state KalmanFilter, update then predict, ``steps`` times from P0."""
    phi, q, h, r, p0 = 0.93, 0.4, 1.7, 2.5, 30.0
    kf = KalmanFilter(dim_x=1, dim_z=1)
    kf.F, kf.Q, kf.H, kf.R, kf.P = (
        np.array([[phi]]),
        np.array([[q]]),
        np.array([[h]]),
        np.array([[r]]),
        np.array([[p0]]),
    )
    for steps in range(1, 6):
        kf.update(np.array([[0.0]]))
        post, gain = float(kf.P[0, 0]), float(kf.K[0, 0])
        kf.predict()
        it = scalar_riccati_iterate(phi, q, h, r, p0=p0, steps=steps)
        assert it.prior == pytest.approx(float(kf.P[0, 0]), rel=1e-12)
        assert it.posterior == pytest.approx(post, rel=1e-12)
        assert it.gain == pytest.approx(gain, rel=1e-12)


def test_scalar_riccati_noiseless_unstable_and_unit_q():
    """Oracle: for q = 0 and |phi| > 1 the stabilising root P- = (phi^2 - 1) r / h^2 (from
    P- = phi^2 P- r / (h^2 P- + r)); for q = 0 and |phi| <= 1, P- = 0; q = 1 against scipy's
    DARE solver."""
    from scipy.linalg import solve_discrete_are

    ss = scalar_riccati_steady_state(-1.5, 0.0, 2.0, 3.0)
    assert ss.prior == pytest.approx((1.5**2 - 1) * 3.0 / 4.0, rel=1e-14)
    assert scalar_riccati_steady_state(0.8, 0.0, 2.0, 3.0).prior == 0.0
    for phi in (1.2, 0.7):
        want = solve_discrete_are(np.array([[phi]]), np.array([[0.5]]), np.array([[1.0]]), np.array([[2.0]]))
        assert scalar_riccati_steady_state(phi, 1.0, 0.5, 2.0).prior == pytest.approx(want[0, 0], rel=1e-10)


def test_scalar_riccati_random_walk_closed_form():
    """Oracle: for phi = 1, h = 1, P- = (q + sqrt(q^2 + 4 q r)) / 2."""
    q, r = 0.3, 2.0
    ss = scalar_riccati_steady_state(1.0, q, 1.0, r)
    assert ss.prior == pytest.approx((q + np.sqrt(q * q + 4 * q * r)) / 2)


def test_scalar_riccati_tiny_q_no_cancellation():
    """With q -> 0 for a stable state, P- ~ q/(1-phi^2) must stay positive and accurate."""
    ss = scalar_riccati_steady_state(0.5, 1e-14, 1.0, 1.0)
    assert ss.prior > 0
    assert ss.prior == pytest.approx(1e-14 / 0.75, rel=1e-6)


@pytest.mark.parametrize("bad", [{"r": 0.0}, {"h": 0.0}, {"q": -1.0}, {"phi": float("nan")}])
def test_scalar_riccati_rejects_bad_input(bad):
    args = {"phi": 0.9, "q": 1.0, "h": 1.0, "r": 1.0} | bad
    with pytest.raises(ValueError, match=next(iter(bad))):
        scalar_riccati_steady_state(**args)


@pytest.mark.parametrize("dt", [0.01, 0.5, 3.0])
def test_van_loan_double_integrator_closed_form(dt):
    """Oracle: Qd = q [[dt^3/3, dt^2/2], [dt^2/2, dt]] for white acceleration of PSD q."""
    q = 0.7
    Phi, Qd = discretize([[0, 1], [0, 0]], [[0, 0], [0, q]], dt)
    np.testing.assert_allclose(Phi, [[1, dt], [0, 1]], atol=1e-14)
    np.testing.assert_allclose(Qd, q * np.array([[dt**3 / 3, dt**2 / 2], [dt**2 / 2, dt]]), rtol=1e-10)


def test_van_loan_gauss_markov_closed_form():
    """Oracle: first-order Markov x' = -x/T + w: Phi = e^{-dt/T}, Qd = sigma^2 (1 - e^{-2dt/T})."""
    T, sigma, dt = 37.0, 2.5, 1.3
    Phi, Qd = discretize([[-1 / T]], [[2 * sigma**2 / T]], dt)
    assert Phi[0, 0] == pytest.approx(np.exp(-dt / T))
    assert Qd[0, 0] == pytest.approx(sigma**2 * (1 - np.exp(-2 * dt / T)), rel=1e-10)


def test_first_order_transition():
    """Oracle: scipy.linalg.expm. The first-order transition differs from e^{F dt} by the
    Taylor remainder F^2 dt^2 / 2 + O(dt^3), so the gap shrinks fourfold per halving of dt
    and approaches F^2 dt^2 / 2 (an oscillator, a Markov decay and a nilpotent F)."""
    from scipy.linalg import expm

    for F in (
        np.array([[0.0, 1.0], [-4.0, 0.0]]),
        np.array([[-0.5, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 2.0, -1.0]]),
        np.array([[0.0, 1.0], [0.0, 0.0]]),
    ):
        gaps = []
        for dt in (0.02, 0.01, 0.005):
            gap = expm(F * dt) - first_order_transition(F, dt)
            scale = max(np.abs(F @ F).max(), 1e-300)
            np.testing.assert_allclose(gap, F @ F * dt**2 / 2, atol=scale * dt**2 * 0.1 + 1e-15)
            gaps.append(np.abs(gap).max())
        if gaps[0] > 0:
            assert gaps[0] / gaps[1] == pytest.approx(4.0, rel=0.05)
            assert gaps[1] / gaps[2] == pytest.approx(4.0, rel=0.05)
        else:  # F^2 = 0: e^{F dt} = I + F dt exactly
            np.testing.assert_allclose(first_order_transition(F, 0.3), expm(F * 0.3), atol=1e-15)


def test_propagate_covariance_matches_monte_carlo():
    """Oracle: seeded Monte Carlo (20000 runs) of the same linear model and Kalman filter.

    The sample covariance of the estimation error must match the propagated posterior within
    the sampling error of a variance estimate (about 4 sqrt(2/N) relative).
    """
    rng = np.random.default_rng(11)
    dt, q, r = 1.0, 0.05, 4.0
    Phi, Q = discretize([[0, 1], [0, 0]], [[0, 0], [0, q]], dt)
    H = np.array([[1.0, 0.0]])
    R = np.array([[r]])
    P0 = np.diag([100.0, 1.0])
    t = np.arange(0, 31.0)
    meas = [Measurement(H, R)]
    hist = propagate_covariance(P0, t, Phi, Q, lambda k: meas if k % 3 == 0 else [])

    N = 20_000
    L0 = np.linalg.cholesky(P0)
    LQ = np.linalg.cholesky(Q)
    x = (L0 @ rng.normal(size=(2, N))).T  # truth
    xh = np.zeros((N, 2))  # estimate
    P = P0.copy()
    for k, _ in enumerate(t):
        if k > 0:
            x = x @ Phi.T + (LQ @ rng.normal(size=(2, N))).T
            xh = xh @ Phi.T
            P = Phi @ P @ Phi.T + Q
        if k % 3 == 0:
            z = x @ H.T + np.sqrt(r) * rng.normal(size=(N, 1))
            K = P @ H.T / (H @ P @ H.T + R)
            xh = xh + (z - xh @ H.T) @ K.T
            P = (np.eye(2) - K @ H) @ P
    err = x - xh
    sample = np.cov(err.T)
    rel = 4 * np.sqrt(2 / N)
    np.testing.assert_allclose(np.diag(sample), np.diag(hist.posterior[-1]), rtol=rel)
    assert hist.n_updates.sum() == len(range(0, 31, 3))


def test_propagate_covariance_outage_is_prediction():
    """An infinite-variance measurement carries no information: same as no measurement."""
    Phi, Q = discretize([[0, 1], [0, 0]], [[0, 0], [0, 0.1]], 1.0)
    t = np.arange(5.0)
    P0 = np.eye(2)
    outage = propagate_covariance(P0, t, Phi, Q, lambda k: [Measurement.scalar([1, 0], np.inf)])
    none = propagate_covariance(P0, t, Phi, Q)
    np.testing.assert_array_equal(outage.posterior, none.posterior)
    assert outage.n_updates.sum() == 0
    # closed form of the double integrator from P0 = I with white acceleration of PSD q:
    # [[1 + t^2 + q t^3 / 3, t + q t^2 / 2], [t + q t^2 / 2, 1 + q t]]
    for k, tk in enumerate(t):
        want = [[1 + tk**2 + 0.1 * tk**3 / 3, tk + 0.1 * tk**2 / 2], [tk + 0.1 * tk**2 / 2, 1 + 0.1 * tk]]
        np.testing.assert_allclose(none.posterior[k], want, rtol=1e-12)
        np.testing.assert_allclose(none.prior[k], want, rtol=1e-12)
        assert none.sigma(1)[k] == pytest.approx(np.sqrt(want[1][1]), rel=1e-12)
        assert none.sigma(0, posterior=False)[k] == pytest.approx(np.sqrt(want[0][0]), rel=1e-12)
        assert none.rss([0, 1])[k] == pytest.approx(np.sqrt(want[0][0] + want[1][1]), rel=1e-12)
        assert none.rss([0], posterior=False)[k] == pytest.approx(np.sqrt(want[0][0]), rel=1e-12)
    np.testing.assert_allclose(none.sigma(0)[0], 1.0)
    np.testing.assert_allclose(none.rss([0, 1])[0], np.sqrt(2.0))


def test_propagate_covariance_time_varying_model_and_several_measurements():
    """Oracle: a hand-run scalar filter. Phi, Q and the schedule given as functions of the
    step k (reading the time t[k]); an outage listed first must not stop the measurements
    after it; every processed scalar is counted; a single time is a valid grid (no
    prediction)."""
    t = np.array([0.0, 0.5, 2.0, 2.5])
    Phi = lambda k: [[1.0 + 0.1 * k + 0.01 * t[k]]]
    Q = lambda k: [[0.2 * k + t[k]]]

    def sched(k):
        if t[k] < 1.0:
            return [Measurement.scalar([1.0], np.inf), Measurement.scalar([2.0], 3.0)]
        return [Measurement.scalar([1.0], 1.0 + t[k]), Measurement.scalar([1.0], 4.0)]

    hist = propagate_covariance(np.eye(1) * 5.0, t, Phi, Q, sched)
    p, posts, priors = 5.0, [], []
    for k, tk in enumerate(t):
        if k:
            phi = 1.0 + 0.1 * k + 0.01 * tk
            p = phi * p * phi + 0.2 * k + tk
        priors.append(p)
        for h, r in [(2.0, 3.0)] if tk < 1.0 else [(1.0, 1.0 + tk), (1.0, 4.0)]:
            p = p * r / (h * h * p + r)
        posts.append(p)
    np.testing.assert_allclose(hist.prior[:, 0, 0], priors, rtol=1e-12)
    np.testing.assert_allclose(hist.posterior[:, 0, 0], posts, rtol=1e-12)
    np.testing.assert_array_equal(hist.n_updates, [1, 1, 2, 2])
    assert hist.n_updates.dtype == np.int64
    ints = propagate_covariance(np.eye(1), [0, 1, 2], [[1.0]], [[0.5]])
    assert ints.t.dtype == float
    np.testing.assert_allclose(ints.posterior[:, 0, 0], [1.0, 1.5, 2.0], rtol=1e-15)
    with pytest.raises(ValueError, match="must have H of shape"):
        propagate_covariance(
            np.eye(2),
            [0.0, 1.0],
            np.eye(2),
            np.eye(2),
            lambda k: [Measurement(np.ones((1, 3)), np.eye(1))],
        )
    with pytest.raises(ValueError, match="t must be"):
        propagate_covariance(np.eye(1), [[0.0, 1.0]], np.eye(1), np.eye(1))
    np.testing.assert_array_equal(hist.t, t)
    t = np.array([3.0])
    one = propagate_covariance(np.eye(1) * 5.0, t, Phi, Q, sched)
    assert one.posterior[0, 0, 0] == pytest.approx(1 / (1 / 5.0 + 1 / 4.0 + 1 / 4.0), rel=1e-12)
    m = Measurement.scalar([1, 2], 3)
    assert m.H.shape == (1, 2) and m.H.dtype == float and m.R.tolist() == [[3.0]]


def test_covariance_history_sigma_and_rss_by_hand():
    """Oracle: square roots written out by hand, for variances below 1 and a round-off
    negative variance (clipped to 0), posterior and prior."""
    post = np.array([[[0.25, 0.1], [0.1, 0.0625]], [[-1e-18, 0.0], [0.0, 0.09]]])
    prior = np.array([[[4.0, 0.0], [0.0, 0.01]], [[0.36, 0.0], [0.0, 0.64]]])
    h = CovarianceHistory(np.array([0.0, 1.0]), prior, post, np.array([1, 1]))
    np.testing.assert_array_equal(h.sigma(0), [0.5, 0.0])
    np.testing.assert_array_equal(h.sigma([0, 1]), [[0.5, 0.25], [0.0, 0.3]])
    np.testing.assert_array_equal(h.sigma(1, posterior=False), [0.1, 0.8])
    np.testing.assert_allclose(h.rss([0, 1]), [np.sqrt(0.3125), 0.3], rtol=1e-15)
    np.testing.assert_allclose(h.rss([0, 1], posterior=False), [np.sqrt(4.01), 1.0], rtol=1e-15)
    np.testing.assert_array_equal(h.rss([0]), [0.5, 0.0])


def test_kf_rejects_bad_shapes_and_noise():
    with pytest.raises(ValueError, match="H must have shape"):
        kf_update(np.zeros(2), np.eye(2), [1.0], np.ones((1, 3)), [[1.0]])
    with pytest.raises(ValueError, match="R must be positive definite"):
        kf_update(np.zeros(2), np.eye(2), [1.0], np.ones((1, 2)), [[0.0]])
    with pytest.raises(ValueError, match="x must be finite"):
        kf_predict([np.nan, 0.0], np.eye(2), np.eye(2), np.eye(2))
    with pytest.raises(ValueError, match="t must be"):
        propagate_covariance(np.eye(1), [0.0, 0.0], np.eye(1), np.eye(1))


def test_symmetrize_a_stack_matrix_by_matrix():
    """Oracle: (A + A^T) / 2 of each matrix of a (2, 3, 3, 3) stack, one at a time with numpy's
    transpose; integer input gives floats."""
    from navcore.estimation.kalman import symmetrize

    A = np.random.default_rng(5).standard_normal((2, 3, 3, 3))
    want = np.array([[0.5 * (a + a.T) for a in row] for row in A])
    np.testing.assert_array_equal(symmetrize(A), want)
    np.testing.assert_array_equal(symmetrize([[1, 2], [0, 1]]), [[1.0, 1.0], [1.0, 1.0]])
    assert symmetrize([[1, 2], [0, 1]]).dtype == np.float64


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (
            lambda x, I: kf_predict(x[:, None], I, I, I),
            r"x must be a 1-dimensional array, got shape \(2, 1\)",
        ),
        (lambda x, I: kf_predict(x, np.eye(3), I, I), r"P must have shape \(2, 2\), got \(3, 3\)"),
        (lambda x, I: kf_predict(x, I, np.eye(3), I), r"Phi must have shape \(2, 2\), got \(3, 3\)"),
        (lambda x, I: kf_predict(x, I, I, np.eye(3)), r"Q must have shape \(2, 2\), got \(3, 3\)"),
        (lambda x, I: kf_update(x[:, None], I, [1.0], [[1.0, 0.0]], [[1.0]]), r"x must be a 1-dimensional"),
        (lambda x, I: kf_update(x, np.eye(3), [1.0], [[1.0, 0.0]], [[1.0]]), r"P must have shape \(2, 2\)"),
        (lambda x, I: kf_update(x, I, [1.0], [[1.0, 0.0]], I), r"R must have shape \(1, 1\), got \(2, 2\)"),
        (
            lambda x, I: information_update(x[:, None], I, [1.0], [[1.0, 0.0]], [[1.0]]),
            r"y must be a 1-dimensional",
        ),
        (
            lambda x, I: information_update(x, np.eye(3), [1.0], [[1.0, 0.0]], [[1.0]]),
            r"Y must have shape \(2, 2\)",
        ),
        (
            lambda x, I: information_update(x, I, [1.0], [[1.0, 0.0, 0.0]], [[1.0]]),
            r"H must have shape \(1, 2\)",
        ),
        (lambda x, I: information_update(x, I, [1.0], [[1.0, 0.0]], I), r"R must have shape \(1, 1\)"),
        (
            lambda x, I: information_update(x, I, [[1.0]], [[1.0, 0.0]], [[1.0]]),
            r"z must be a vector, got shape \(1, 1\)",
        ),
        (
            lambda x, I: kf_update(x, I, [[1.0]], [[1.0, 0.0]], [[1.0]]),
            r"z must be a vector, got shape \(1, 1\)",
        ),
        (lambda x, I: discretize(I, np.eye(3), 1.0), r"GQGt must be 2x2, got shape \(3, 3\)"),
        (lambda x, I: information_from_covariance(x, np.diag([1.0, 0.0])), r"P must be positive definite"),
        (lambda x, I: covariance_from_information(x, np.diag([1.0, 0.0])), r"Y must be positive definite"),
    ],
)
def test_kalman_forms_name_the_argument_of_the_wrong_shape(call, message):
    """Oracle: the shapes the docstrings state (x: (n,), P, Phi, Q, Y, GQGt: (n, n), H: (m, n),
    R: (m, m), z: (m,)) and the definiteness an inverse needs, each broken alone with the default
    checks on: the message names the argument as the caller spelled it, and its shape."""
    with pytest.raises(ValueError, match="^" + message):
        call(np.zeros(2), np.eye(2))


def test_state_layout():
    lay = StateLayout.of(("position", 3), ("velocity", 3), ("clock", 2))
    assert lay.size == 8
    assert lay.slice("velocity") == slice(3, 6)
    assert lay.index("clock", 1) == 7
    assert StateLayout.of(("velocity", 3)).issubset(lay)
    assert not StateLayout.of(("velocity", 2)).issubset(lay)
    with pytest.raises(ValueError, match="unique names"):
        StateLayout.of(("a", 1), ("a", 2))
    with pytest.raises(ValueError, match="size must be an integer >= 1"):
        StateLayout.of(("a", 0))
    with pytest.raises(ValueError, match="name must be one of"):
        lay.slice("attitude")
    assert StateLayout.of(StateBlock("a", 2), ("b", 1), name="m").table() == [("a", 2), ("b", 1)]
    assert StateLayout.of(StateBlock("a", 2), name="m").name == "m"
    assert StateLayout.of(("a", 1)).name == ""


def test_state_layout_bad_input_names_the_argument():
    """Oracle: the constraints as the docstrings state them, probed on both sides of each
    bound: a component index lies in [0, block size); a block has a non-empty string name
    and an integer size >= 1 (not a bool, not a float); an INS block name is a string among
    the known ones, and the message names the caller's argument."""
    from navcore.estimation.layout import InsBlock, ins_block_name

    lay = StateLayout.of(("position", 3), ("clock", 2))
    assert lay.index("clock", 0) == 3 and lay.index("clock", 1) == 4
    for bad in (2, -1):
        with pytest.raises(ValueError, match=r"component must be in \[0, 2\), got " + str(bad)):
            lay.index("clock", bad)
    assert StateBlock("a", 1).size == 1
    with pytest.raises(ValueError, match=r"StateBlock\.name must be a non-empty string"):
        StateBlock("", 1)
    for name in (3, None):
        with pytest.raises(TypeError, match=r"^name must be of type str"):
            StateBlock(name, 1)
    for size in (0, -2):
        with pytest.raises(ValueError, match=r"StateBlock\.size must be an integer >= 1"):
            StateBlock("a", size)
    for size in (True, 1.0, "2"):
        with pytest.raises(TypeError, match=r"^size must be an integer"):
            StateBlock("a", size)
    assert ins_block_name("gyro bias") is InsBlock.GYRO_BIAS
    assert ins_block_name(InsBlock.GYRO_BIAS) is InsBlock.GYRO_BIAS
    with pytest.raises(TypeError, match=r"^name must be a string \(a block name\), got 3$"):
        ins_block_name(3)
    with pytest.raises(
        ValueError, match=r"^name must be among \['position'.*got 'gyro drift'; did you mean 'gyro bias'"
    ):
        ins_block_name("gyro drift")  # the papers' name is not an API name
    with pytest.raises(ValueError, match=r"^blocks must be among"):
        ins_block_name("tilt angle", argument="blocks")
    with pytest.raises(TypeError, match=r"^blocks must be a string"):
        ins_block_name(1.5, argument="blocks")
    from navcore.inertial.error_dynamics import ins_error_layout

    with pytest.raises(TypeError, match=r"^names must be a string"):  # the caller's own argument
        ins_error_layout("position", 3)


def test_state_layout_error_suggests_the_name():
    """Oracle: the messages read by hand: a misspelt block name gets the closest known one, a
    synonym of an INS block (whatever its case and spacing) gets the block's name, an unknown
    name gets no suggestion."""
    lay = StateLayout.of(("position", 3), ("velocity", 3), ("misalignment", 3), ("gyro bias", 3))
    with pytest.raises(ValueError, match=r"got 'velocty'; did you mean 'velocity'\?$"):
        lay.slice("velocty")
    with pytest.raises(ValueError, match=r"got ' Gyro Drift '; did you mean 'gyro bias'\?$"):
        lay.index(" Gyro Drift ")
    with pytest.raises(ValueError, match=r"got 'tilt'; did you mean 'misalignment'\?$"):
        lay.block("tilt")
    with pytest.raises(ValueError, match=r"got 'clock offset'$"):  # a synonym of a block not here
        lay.slice("clock offset")
    with pytest.raises(ValueError, match=r"got 'zzz'$"):
        lay.slice("zzz")
    with pytest.raises(ValueError, match=r"got 3$"):  # not a name at all
        lay.slice(3)


def test_state_layout_concatenation_and_union():
    """Oracle: block tables and names written out by hand. ``+`` keeps every block of both
    (and so rejects a shared name); ``union`` appends only the other's new blocks."""
    a = StateLayout.of(("position", 3), ("velocity", 3), name="nav")
    b = StateLayout.of(("velocity", 3), ("clock", 2), ("gravity", 1), name="aid")
    c = StateLayout.of(("clock", 2), ("gravity", 1), name="extra")
    s = a + c
    assert s.table() == [("position", 3), ("velocity", 3), ("clock", 2), ("gravity", 1)]
    assert s.name == "nav+extra"
    assert s.size == 9 and s.index("gravity") == 8
    assert (c + a).table() == [("clock", 2), ("gravity", 1), ("position", 3), ("velocity", 3)]
    with pytest.raises(ValueError, match="unique names"):
        a + b
    u = a.union(b)
    assert u.table() == [("position", 3), ("velocity", 3), ("clock", 2), ("gravity", 1)]
    assert u.name == "nav|aid"
    assert u.slice("clock") == slice(6, 8)
    v = b.union(a)
    assert v.table() == [("velocity", 3), ("clock", 2), ("gravity", 1), ("position", 3)]
    assert v.name == "aid|nav"
    assert a.union(a).table() == a.table()
    assert a.union(StateLayout.of(name="")).name == "nav|"


def test_a_checked_step_checks_again_a_covariance_changed_after_it_was_returned():
    """The checked steps remember the covariances they return (valid by construction) by their
    numbers, so a loop does not re-check them; one changed in place is new numbers, checked
    again. Oracle: the definition of symmetry and of a finite matrix."""
    n = 3
    x, P = kf_predict(np.zeros(n), np.eye(n), np.eye(n), 0.1 * np.eye(n))
    up = kf_update(x, P, [0.5], [[1.0, 0.0, 0.0]], [[1.0]])  # P as returned: passes
    assert np.array_equal(up.P, up.P.T)
    P[0, 1] += 1.0  # no longer symmetric
    with pytest.raises(ValueError, match="P must be symmetric"):
        kf_update(x, P, [0.5], [[1.0, 0.0, 0.0]], [[1.0]])
    P_post = up.P
    P_post[2, 2] = np.nan
    with pytest.raises(ValueError, match="P must be finite"):
        kf_predict(up.x, P_post, np.eye(n), 0.1 * np.eye(n))


def test_the_filter_steps_check_each_argument_in_their_body_as_the_wrapper_words_it():
    """kf_predict and kf_update check their own arguments (no generic wrapper around them).
    Oracle: the wrapper's wording (navcore._validate.checked): the parameter as the caller
    spelled it and the constraint, for a NaN, a wrong type and a flag that is not a bool; and a
    transition or measurement matrix remembered as finite is checked again once changed."""
    n = 3
    x, P, F, Q = np.zeros(n), np.eye(n), np.eye(n), 0.1 * np.eye(n)
    H, R = np.array([[1.0, 0.0, 0.0]]), np.eye(1)
    with pytest.raises(ValueError, match="x must be finite"):
        kf_predict(np.array([0.0, np.nan, 0.0]), P, F, Q)
    with pytest.raises(ValueError, match="x must be finite"):
        kf_predict([0.0, np.inf, 0.0], P, F, Q)  # a list: the wrapper's path
    with pytest.raises(TypeError, match="x must be a number or an array of numbers"):
        kf_predict("abc", P, F, Q)
    with pytest.raises(ValueError, match="z must be finite"):
        kf_update(x, P, np.array([np.nan]), H, R)
    with pytest.raises(TypeError, match="validate must be of type bool"):
        kf_predict(x, P, F, Q, validate=0)
    with pytest.raises(TypeError, match="validate must be of type bool"):
        kf_update(x, P, [0.5], H, R, validate="no")
    kf_predict(x, P, F, Q)  # F passes, and is remembered
    F[1, 2] = np.inf
    with pytest.raises(ValueError, match="Phi must be finite"):
        kf_predict(x, P, F, Q)
    kf_update(x, P, [0.5], H, R)  # H passes, and is remembered
    H[0, 1] = np.nan
    with pytest.raises(ValueError, match="H must be finite"):
        kf_update(x, P, [0.5], H, R)
    with pytest.raises(ValueError, match=r"Phi must have shape \(3, 3\)"):
        kf_predict(x, P, np.eye(2), Q)
