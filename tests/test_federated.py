"""Tests of navcore.estimation.federated (WF Eqs. (10)-(23)) against independent oracles."""

from __future__ import annotations

import numpy as np
import pytest
from filterpy.kalman import KalmanFilter
from hypothesis import given, settings
from hypothesis import strategies as st

from navcore.estimation.federated import (
    accelerometer_predict,
    accelerometer_steady_state,
    accelerometer_steady_state_isotropic,
    completely_correlated_trace_ratio,
    correlated_joint_covariance,
    feasible_weights,
    federated_bound_margins,
    federated_bound_monte_carlo,
    federated_bound_monte_carlo_sweep,
    federated_covariance_bound,
    federated_fusion,
    fused_error_covariance,
    fusion_gains,
    gps_doppler_covariance,
    gps_doppler_update,
    lever_arm_velocity,
    local_velocity_update,
    minkowski_trace_bound,
    navigation_mapped_covariance,
    navigation_mapped_error_samples,
    optimal_weights,
    random_covariance,
)


def _spd(rng, n, scale=1.0):
    A = rng.normal(size=(n, n))
    return scale * (A @ A.T + 0.1 * np.eye(n))


def test_lever_arm_jacobian_finite_difference():
    """Oracle: finite differences of v + omega x r (the map is linear, so FD is exact)."""
    r = np.array([1.0, 15.0, -0.5])
    v0, w0 = np.array([200.0, 3.0, -1.0]), np.array([0.01, -0.02, 0.05])
    _, tau = lever_arm_velocity(v0, w0, r)
    x0 = np.r_[v0, w0]
    fd = np.column_stack(
        [
            lever_arm_velocity((x0 + d)[:3], (x0 + d)[3:], r)[0] - lever_arm_velocity(v0, w0, r)[0]
            for d in np.eye(6)
        ]
    )
    np.testing.assert_allclose(tau, fd, atol=1e-12)


def test_mapped_covariance_monte_carlo():
    """Oracle: seeded Monte Carlo of WF Eq. (10) with independent w_T (1e5 samples)."""
    rng = np.random.default_rng(1)
    _, tau = lever_arm_velocity(np.zeros(3), np.zeros(3), [2.0, 10.0, 0.3])
    P_N, Q_T = _spd(rng, 6, 0.01), _spd(rng, 3, 0.5)
    n = 100_000
    e = rng.multivariate_normal(np.zeros(6), P_N, n) @ tau.T + rng.multivariate_normal(np.zeros(3), Q_T, n)
    np.testing.assert_allclose(np.cov(e.T), navigation_mapped_covariance(tau, P_N, Q_T), rtol=0.03, atol=2e-3)


def test_accelerometer_filter_matches_filterpy():
    """Oracle: filterpy's KalmanFilter with F = I, B = Ts I, Q = Q_a Ts^2, H = I (WF Eqs. (12)-(14))."""
    rng = np.random.default_rng(2)
    Ts, Q_a, R_L = 0.02, _spd(rng, 3, 1e-4), _spd(rng, 3, 0.04)
    kf = KalmanFilter(dim_x=3, dim_z=3, dim_u=3)
    kf.F, kf.B, kf.H, kf.Q, kf.R, kf.P = np.eye(3), Ts * np.eye(3), np.eye(3), Q_a * Ts**2, R_L, np.eye(3)
    x, P = np.zeros(3), np.eye(3)
    for _ in range(50):
        a, y = rng.normal(size=3), rng.normal(size=3)
        kf.predict(u=a.reshape(3, 1))
        kf.update(y.reshape(3, 1))
        x, P = accelerometer_predict(x, P, a, Q_a, Ts)
        upd = local_velocity_update(x, P, y, R_L)
        x, P = upd.x, upd.P
    np.testing.assert_allclose(x, kf.x.ravel(), rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(P, kf.P, rtol=1e-9, atol=1e-15)


def test_steady_state_closed_form_and_matrix():
    """Oracle: closed form P+ = (-q + sqrt(q^2 + 4 q r))/2 of WF Eq. (14); iterating the recursion."""
    sa, Ts, sL = 1e-3, 0.02, 0.2
    q, r = (sa * Ts) ** 2, sL**2
    ss = accelerometer_steady_state_isotropic(sa, Ts, sL)
    assert ss.posterior == pytest.approx((-q + np.sqrt(q * q + 4 * q * r)) / 2, rel=1e-12)
    Q_a = np.diag([1e-6, 4e-6, 9e-6])
    prior, post = accelerometer_steady_state(Q_a, 0.04 * np.eye(3), Ts)
    qd = np.diag(Q_a) * Ts**2  # independent axes: the scalar closed form per axis is the oracle
    np.testing.assert_allclose(np.diag(post), (-qd + np.sqrt(qd * qd + 4 * qd * 0.04)) / 2, rtol=1e-9)
    np.testing.assert_allclose(post - np.diag(np.diag(post)), 0.0, atol=1e-15)
    np.testing.assert_allclose(prior, post + Q_a * Ts**2, rtol=1e-9)


def test_gps_update_matches_filterpy():
    """Oracle: filterpy's KalmanFilter.update for the WF Eq. (16) update (state and covariance);
    the information form of WF Eq. (17) must give the same covariance."""
    rng = np.random.default_rng(4)
    P = _spd(rng, 3, 1e-4)
    x0 = rng.normal(size=3)
    H = 5.255 * np.array([[1.0, 0.2, 0.0], [0.0, -0.5, 1.0]])
    R = np.array([[1.0, 0.3], [0.3, 2.0]])
    y = np.array([0.3, -1.1])
    kf = KalmanFilter(dim_x=3, dim_z=2)
    kf.x, kf.P, kf.H, kf.R = x0.copy(), P.copy(), H, R
    kf.update(y)
    upd = gps_doppler_update(x0, P, y, H, R)
    np.testing.assert_allclose(upd.x, kf.x, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(upd.P, kf.P, rtol=1e-9, atol=1e-18)
    np.testing.assert_allclose(gps_doppler_covariance(P, H, R), kf.P, rtol=1e-9, atol=1e-18)


def test_fusion_equals_stacked_gls_and_outage():
    """Oracle: generalized least squares on the stacked estimates with block-diagonal covariance."""
    rng = np.random.default_rng(5)
    Ps = [_spd(rng, 3) for _ in range(3)]
    xs = [rng.normal(size=3) for _ in range(3)]
    x, P = federated_fusion(xs, Ps)
    A = np.vstack([np.eye(3)] * 3)
    Winv = np.zeros((9, 9))
    for i, Pi in enumerate(Ps):
        Winv[3 * i : 3 * i + 3, 3 * i : 3 * i + 3] = np.linalg.inv(Pi)
    P_gls = np.linalg.inv(A.T @ Winv @ A)
    np.testing.assert_allclose(P, P_gls, rtol=1e-10)
    np.testing.assert_allclose(x, P_gls @ A.T @ Winv @ np.concatenate(xs), rtol=1e-10)
    x2, P2 = federated_fusion(xs, [Ps[0], None, Ps[2]])
    x3, P3 = federated_fusion([xs[0], xs[2]], [Ps[0], Ps[2]])
    np.testing.assert_allclose(x2, x3, rtol=1e-12)
    np.testing.assert_allclose(P2, P3, rtol=1e-12)
    x4, _ = federated_fusion(xs, [Ps[0], np.diag([np.inf] * 3), Ps[2]])
    np.testing.assert_allclose(x4, x3, rtol=1e-12)
    x5, P5 = federated_fusion([xs[1], xs[0], xs[2]], [np.inf, Ps[0], Ps[2]])  # a scalar inf outage, first
    np.testing.assert_allclose(x5, x3, rtol=1e-12)
    np.testing.assert_allclose(P5, P3, rtol=1e-12)
    with pytest.raises(ValueError, match="covariances"):
        federated_fusion(xs[:1], [None])
    with pytest.raises(ValueError, match="like the others"):
        federated_fusion(xs[:2], [Ps[0], np.eye(2)])
    with pytest.raises(TypeError, match="sequence of matrices"):
        federated_fusion(xs, "abc")
    # a singular covariance has no information form: the message names the list entry
    with pytest.raises(ValueError, match=r"^covariances\[1\] must be positive definite"):
        federated_fusion(xs, [Ps[0], np.diag([1.0, 1.0, 0.0]), Ps[2]])


def test_fused_covariance_monte_carlo():
    """Oracle: sample covariance of the fused error for correlated local errors (WF Eq. (20), 2e5 draws)."""
    rng = np.random.default_rng(6)
    J = _spd(rng, 9)
    Ps = [J[3 * i : 3 * i + 3, 3 * i : 3 * i + 3] for i in range(3)]
    E = rng.multivariate_normal(np.zeros(9), J, 200_000)
    infos = [np.linalg.inv(P) for P in Ps]
    PD = np.linalg.inv(sum(infos))
    fused = sum(E[:, 3 * i : 3 * i + 3] @ (PD @ infos[i]).T for i in range(3))
    np.testing.assert_allclose(fused_error_covariance(Ps, J), np.cov(fused.T), rtol=0.03, atol=0.01)


def test_correlated_joint_covariance_blocks():
    """Oracle: the construction written out with the same draws: A_i, L_i = chol(A_i A_i' + 0.1 I),
    blocks J_ii = L_i L_i' and J_ij = rho L_i L_j'; and a sample covariance of errors built as
    e_i = L_i (sqrt(rho) w + sqrt(1 - rho) u_i) matches J."""
    rho, n, N = 0.3, 2, 3
    J = correlated_joint_covariance(np.random.default_rng(4), n, N, rho)
    rng = np.random.default_rng(4)
    L = []
    for _ in range(N):
        A = rng.normal(size=(n, n))
        L.append(np.linalg.cholesky(A @ A.T + 0.1 * np.eye(n)))
    for i in range(N):
        for j in range(N):
            block = L[i] @ L[j].T * (1.0 if i == j else rho)
            np.testing.assert_allclose(J[n * i : n * i + n, n * j : n * j + n], block, rtol=1e-12, atol=1e-14)
    draws = np.random.default_rng(5)
    w = draws.normal(size=(200_000, n))
    e = np.hstack([(np.sqrt(rho) * w + np.sqrt(1 - rho) * draws.normal(size=w.shape)) @ Li.T for Li in L])
    np.testing.assert_allclose(np.cov(e.T), J, atol=0.02 * np.max(np.abs(J)))


@pytest.mark.parametrize(
    ("args", "name"),
    [
        ((0, 2, 0.5), "n_states"),
        ((2, 0, 0.5), "n_estimators"),
        ((2, 2, 1.5), "rho"),
        ((100, 100, 0.5), "n_states"),
    ],
)
def test_correlated_joint_covariance_rejects_bad_arguments(args, name):
    with pytest.raises(ValueError, match=name):
        correlated_joint_covariance(np.random.default_rng(0), *args)
    with pytest.raises(TypeError, match="rng"):
        correlated_joint_covariance(0, 2, 2, 0.5)


@settings(max_examples=50, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(1, 4), st.integers(2, 4), st.floats(0.0, 1.0))
def test_theorem_bound_holds(seed, n, N, rho):
    """Oracle: WF Eq. (20) exact covariance vs the bound (21) and the trace chain (23), any correlation."""
    rng = np.random.default_rng(seed)
    J = correlated_joint_covariance(rng, n, N, rho)
    Ps = [J[n * i : n * i + n, n * i : n * i + n] for i in range(N)]
    cov = fused_error_covariance(Ps, J)
    z = [rng.normal(size=n) + 1e-3 for _ in range(N)]
    k = feasible_weights(Ps, directions=z)
    assert np.sum(1 / k) == pytest.approx(1.0)
    B = federated_covariance_bound(Ps, k)
    assert np.linalg.eigvalsh(B - cov)[0] >= -1e-9 * np.linalg.norm(B)
    mink = minkowski_trace_bound(Ps)
    assert np.trace(cov) <= mink * (1 + 1e-9)
    assert mink <= np.trace(B) * (1 + 1e-9)


@pytest.mark.parametrize("N", [2, 3, 4])
@pytest.mark.parametrize("kind", ["generic", "mixed", "complete"])
def test_theorem_bound_monte_carlo(N, kind):
    """Oracle: seeded Monte Carlo of the fused error (the sample covariance S of 20 000 draws).

    Local errors of 3 states with a random joint covariance J ("generic": A A' + 0.1 I; "mixed": a
    common and an independent part, correlation uniform in [0, 1]; "complete": e_i = sigma_i w,
    where the bound with the optimal weights is exact) are fused with the weights of WF Eqs. (18)-(19)
    (``federated_bound_monte_carlo``, which the ledger claim WF-thm-montecarlo also runs, on other
    seeds). Criteria, in sampling standard deviations (sd) of S:

    * WF Eq. (21): whitening by the bound B, lambda_max(B^-1/2 S B^-1/2) - 1 <= 5 sd, sd = sqrt(2/(n-1))
      (the sd of a whitened sample variance whose true value is 1, the largest it can be);
    * WF Eq. (23): tr S - Minkowski term <= 5 sd, sd = sqrt(2 tr(S^2)/(n-1));
    * WF Eq. (20): |S_jk - C_jk| <= 5 sd_jk, sd_jk = sqrt((S_jj S_kk + S_jk^2)/(n-1)); and Eq. (20) applied to
      the sample joint covariance of the local errors is S itself (to round-off), so E[S] = Eq. (20) exactly.
    """
    rng = np.random.default_rng([N, ("generic", "mixed", "complete").index(kind), 31])
    r = federated_bound_monte_carlo(rng, N, kind, 20_000)
    assert r["z_bound"] <= 5 and r["z_trace"] <= 5 and r["z_eq20"] <= 5
    assert r["exact"] < 1e-10
    if kind == "complete":  # the criterion has power: it rejects the naive P_D of Eq. (19) as a bound
        S, n = r["S"], 3
        Ld = np.linalg.inv(np.linalg.cholesky(federated_fusion([np.zeros(n)] * N, r["Ps"])[1]))
        assert np.linalg.eigvalsh(Ld @ S @ Ld.T)[-1] - 1 > 5 * np.sqrt(2 / r["dof"])


def test_bound_exact_for_fully_correlated_isotropic():
    """Oracle: remark (ii): e_i = sigma_i * w with a common w makes (21) an equality for isotropic P_i."""
    s = np.array([0.02, 0.002, 0.5])
    n = 3
    J = np.kron(np.outer(s, s), np.eye(n))  # completely correlated
    Ps = [si**2 * np.eye(n) for si in s]
    cov = fused_error_covariance(Ps, J)
    np.testing.assert_allclose(federated_covariance_bound(Ps, optimal_weights(Ps)), cov, rtol=1e-12)
    # the remark (i) choice with sigma_i in the spectrum of P_i is valid but not the tight one here
    loose = federated_covariance_bound(Ps, feasible_weights(Ps, sigmas=s**2))
    assert np.trace(loose) > 10 * np.trace(cov)
    assert minkowski_trace_bound(Ps) == pytest.approx(np.trace(cov), rel=1e-12)


def test_weights_validation():
    """Validation: infeasible weights are rejected with the constraint named."""
    with pytest.raises(ValueError, match="weights"):
        federated_covariance_bound([np.eye(2), np.eye(2)], [1.5, 1.5])


def test_random_covariance_mean_and_floor():
    """Oracle: closed forms. E[A A^T] = n I for standard normal A, so the mean of 20 000 draws is
    (n + f) I within 5 sampling sd (an entry of A A^T has variance n (1 + delta_jk)); Weyl's
    inequality puts every eigenvalue at or above the floor f."""
    rng = np.random.default_rng(2024)
    n, f, m = 4, 0.7, 20_000
    draws = np.stack([random_covariance(rng, n, f) for _ in range(m)])
    assert np.abs(draws.mean(axis=0) - (n + f) * np.eye(n)).max() <= 5 * np.sqrt(2 * n / m)
    assert np.linalg.eigvalsh(draws).min() >= f - 1e-12
    assert np.array_equal(draws[0], draws[0].T)


def test_random_covariance_validation():
    """Validation: each argument is named as the caller spelled it."""
    with pytest.raises(TypeError, match="rng"):
        random_covariance(0, 3)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="n"):
        random_covariance(np.random.default_rng(0), 0)
    with pytest.raises(ValueError, match="floor"):
        random_covariance(np.random.default_rng(0), 3, -1.0)


def test_fusion_gains_closed_form():
    """Oracle: the closed form G_i = P_D P_i^-1, P_D = (sum_i P_i^-1)^-1 (WF Eqs. (18)-(19)), with
    numpy's inverse; an outage has a zero map and the maps of the others sum to I."""
    rng = np.random.default_rng(44)
    Ps = [_spd(rng, 3) for _ in range(3)]
    P_D = np.linalg.inv(sum(np.linalg.inv(P) for P in Ps))
    for G, P in zip(fusion_gains(Ps), Ps, strict=True):
        np.testing.assert_allclose(G, P_D @ np.linalg.inv(P), atol=1e-12)
    G = fusion_gains([Ps[0], None, Ps[2]])
    assert not np.any(G[1])
    np.testing.assert_allclose(G[0] + G[2], np.eye(3), atol=1e-12)


def _margins_by_hand(rng, cases):
    """The margins of WF Eqs. (21)-(23) written from the closed forms with numpy only."""
    out = {"eig": np.inf, "first": np.inf, "second": np.inf}
    for _ in range(cases):
        J = correlated_joint_covariance(rng, 3, 3, rng.uniform())
        Ps = [J[3 * i : 3 * i + 3, 3 * i : 3 * i + 3] for i in range(3)]
        infos = [np.linalg.inv(P) for P in Ps]
        P_D = np.linalg.inv(sum(infos))
        A = np.hstack([P_D @ Y for Y in infos])
        C = A @ J @ A.T  # Eq. (20)
        z = [rng.normal(size=3) for _ in range(3)]
        s = np.array([np.sqrt(zi @ P @ zi) for zi, P in zip(z, Ps, strict=True)])
        k = s.sum() / s  # Eq. (22)
        B = P_D @ sum(ki * Y for ki, Y in zip(k, infos, strict=True)) @ P_D  # Eq. (21)
        m = sum(np.sqrt(np.trace(P_D @ Y @ P_D)) for Y in infos) ** 2  # Eq. (23)
        out["eig"] = min(out["eig"], np.linalg.eigvalsh(B - C)[0] / np.linalg.norm(B))
        out["first"] = min(out["first"], (m - np.trace(C)) / m)
        out["second"] = min(out["second"], (np.trace(B) - m) / np.trace(B))
    return out


def test_federated_bound_margins_against_the_closed_forms():
    """Oracle: the margins recomputed from the closed forms of Eqs. (20)-(23) with numpy
    (``_margins_by_hand``), on a seed the claim does not use; the theorem: all non-negative."""
    got = federated_bound_margins(np.random.default_rng(5), 25)
    want = _margins_by_hand(np.random.default_rng(5), 25)
    for key in ("eig", "first", "second"):
        assert got[key] == pytest.approx(want[key], rel=1e-6, abs=1e-12)
        assert got[key] >= -1e-12
    with pytest.raises(ValueError, match="cases"):
        federated_bound_margins(np.random.default_rng(5), 0)
    with pytest.raises(TypeError, match="rng"):
        federated_bound_margins(5, 3)  # type: ignore[arg-type]


def test_federated_bound_monte_carlo_sweep_cases_and_criteria():
    """Oracle: the case plan written out by hand (three cases per kind, 2-4 estimators), and on a
    seed and sample count the claim does not use (seed 7, 8 000 draws) every criterion within 5
    sampling sd and Eq. (20) on the sample joint equal to S to round-off."""
    out = federated_bound_monte_carlo_sweep(7, 8_000, 7)
    assert [(r["N"], r["kind"]) for r in out] == [
        (2, "generic"), (3, "generic"), (4, "generic"),
        (2, "mixed"), (3, "mixed"), (4, "mixed"),
        (2, "complete"),
    ]  # fmt: skip
    for r in out:
        assert r["z_bound"] <= 5 and r["z_trace"] <= 5 and r["z_eq20"] <= 5 and r["exact"] < 1e-10
    with pytest.raises(ValueError, match="kind"):
        federated_bound_monte_carlo(np.random.default_rng(0), 2, "other", 100)
    with pytest.raises(ValueError, match="samples"):
        federated_bound_monte_carlo_sweep(2, 1, 0)


def test_completely_correlated_trace_ratio_against_eq20():
    """Oracle: the exact ratio, Minkowski term over tr of Eq. (20) with the joint covariance of
    e_i = L_i w (blocks L_i L_j^T), computed with numpy; the Monte Carlo on 200 000 draws within 5
    sampling sd of it (the relative sd of a sample trace is at most sqrt(2/(n-1))). Isotropic
    factors make the bound exact (WF Remark (ii)); non-commuting ones do not."""
    rng = np.random.default_rng(77)
    L = [np.linalg.cholesky(_spd(rng, 3)) for _ in range(3)]
    common = np.vstack(L)
    Ps = [Li @ Li.T for Li in L]
    infos = [np.linalg.inv(P) for P in Ps]
    P_D = np.linalg.inv(sum(infos))
    A = np.hstack([P_D @ Y for Y in infos])
    exact = minkowski_trace_bound(Ps) / np.trace(A @ common @ common.T @ A.T)
    samples = 200_000
    got = completely_correlated_trace_ratio(L, np.random.default_rng(78), samples)
    assert got == pytest.approx(exact, rel=5 * np.sqrt(2 / (samples - 1)))
    assert exact > 1.01
    iso = completely_correlated_trace_ratio([np.eye(3), 3.0 * np.eye(3)], np.random.default_rng(79), samples)
    assert iso == pytest.approx(1.0, rel=5 * np.sqrt(2 / (samples - 1)))
    with pytest.raises(ValueError, match=r"factors\[1\]"):
        completely_correlated_trace_ratio([np.eye(3), np.eye(2)], np.random.default_rng(0), 10)


def test_navigation_mapped_error_samples_covariance_is_eq11():
    """Oracle: WF Eq. (11) in closed form, tau P_N tau^T + Q_T (``navigation_mapped_covariance``),
    against the sample covariance of 100 000 draws of tau e_N + w_T (a 2 x 4 map), within 5
    sampling sd per entry, sqrt((S_jj S_kk + S_jk^2)/(n-1))."""
    rng = np.random.default_rng(1011)
    tau = rng.normal(size=(2, 4))
    P_N, Q_T = _spd(rng, 4, 0.3), _spd(rng, 2, 0.2)
    n = 100_000
    e = navigation_mapped_error_samples(tau, P_N, Q_T, rng, n)
    assert e.shape == (n, 2)
    S = np.cov(e.T)
    C = navigation_mapped_covariance(tau, P_N, Q_T)
    sd = np.sqrt((np.outer(np.diag(S), np.diag(S)) + S**2) / (n - 1))
    assert np.all(np.abs(S - C) <= 5 * sd)
    with pytest.raises(ValueError, match="tau"):
        navigation_mapped_error_samples(np.eye(3), P_N, Q_T, rng, 10)
    with pytest.raises(TypeError, match="rng"):
        navigation_mapped_error_samples(tau, P_N, Q_T, None, 10)  # type: ignore[arg-type]
