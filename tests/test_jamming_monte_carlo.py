"""The seeded first-stage Monte Carlo lies above the Sec. 2 bounds."""

from __future__ import annotations

import numpy as np
import pytest

from navcore.detection import jamming_monte_carlo as mc


def test_simulated_rates_exceed_bounds() -> None:
    """Oracle: seeded Monte Carlo of matched-filter samples and the list logic (the bounds must
    lie below the simulated rates, within three binomial standard errors)."""
    for r in mc.simulate():
        sigma = mc.binomial_sigma(r.false_alarm, r.trials)
        assert np.all(r.false_alarm_bound <= r.false_alarm + 3 * sigma)
        sigma_d = mc.binomial_sigma(r.detection, r.trials)
        assert np.all(r.detection_bound <= r.detection + 3 * sigma_d)
        assert np.all(np.isfinite(r.false_alarm_bound)) and np.all(r.false_alarm_bound > 0)


def test_list_logic_matches_explicit_search() -> None:
    """Oracle: an explicit loop over the definition of a non-empty list (a filter-1
    declaration at one of the n_a centre samples with a declaration of each of filters 2-4
    within +-w samples of it, both ends included), on seeded random declarations. The
    one-sided bound test alone missed an off-by-one window (12 % fewer false alarms)."""
    rng = np.random.default_rng(3)
    w, n_a = mc.HALF_WINDOW, mc.N_A
    decl = rng.random((60, 2, 4, n_a + 2 * w)) < 0.035
    # plant quadruplets whose farthest partner sits exactly at +w or -w
    decl[:5] = False
    for j, off in enumerate((w, -w, w, -w, w + 1)):
        c = w + 10 + 20 * j
        decl[j, 0, 0, c] = True
        decl[j, 0, 1:, c + off] = True
    expected = np.zeros(decl.shape[:2], bool)
    for trial in range(decl.shape[0]):
        for lst in range(decl.shape[1]):
            d = decl[trial, lst]
            expected[trial, lst] = any(
                d[0, i] and all(d[f, i - w : i + w + 1].any() for f in (1, 2, 3)) for i in range(w, w + n_a)
            )
    got = mc._nonempty(decl)
    assert np.array_equal(got, expected)
    assert got[:4, 0].all() and not got[4, 0]  # the window edges are inside, one beyond is not
    assert 0.1 < expected[5:].mean() < 0.9  # both outcomes occur, so the comparison has teeth


def test_false_track_search_matches_brute_force() -> None:
    """Oracle: explicit search over every chain of quadruplets, trial by trial, for K = 1-3."""
    rng = np.random.default_rng(7)
    for k in (1, 2, 3):
        r = mc.TRACK_W + (k - 1) * mc.TRACK_V
        decl = rng.random((200, k, 4, 12 + 2 * r)) < 0.25
        fast = mc.false_track_exists(decl, mc.TRACK_W, mc.TRACK_V)
        slow = mc.false_track_exists_brute_force(decl, mc.TRACK_W, mc.TRACK_V)
        assert np.array_equal(fast, slow)
        assert 0.05 < fast.mean() < 0.95  # both outcomes occur, so the comparison has teeth


def test_false_track_bound_below_simulation() -> None:
    """Oracle: the seeded false-track simulation; F G^(K-1) must not exceed it (3 sigma)."""
    for r in mc.simulate_false_tracks():
        sigma = mc.binomial_sigma(r.simulated, r.trials)
        assert np.all(r.bound <= r.simulated + 3 * sigma)
        assert np.all(np.diff(r.simulated) >= 0)  # common random numbers: monotone in p_f
    k1 = mc.simulate_false_tracks()[0]
    # K = 1: the event is a consistent quadruplet, as in the first-stage false-alarm bound
    assert k1.k == 1 and np.allclose(k1.bound, mc.false_track_bound(k1.p_f, 1))


def test_false_track_simulation_is_deterministic() -> None:
    """Oracle: a second, uncached run of the seeded simulation reproduces the cached one exactly."""
    first = mc.simulate_false_tracks()
    second = mc.simulate_false_tracks.__wrapped__()
    for a, b in zip(first, second, strict=True):
        assert np.array_equal(a.simulated, b.simulated) and np.array_equal(a.bound, b.bound)


def test_window_simulation_against_independent_formula() -> None:
    """Oracle: the closed form (1 - p_f)^n for independent samples; correlated samples (neighbour
    correlation 1/2) leave a window empty more often (Slepian's inequality), by a clear margin at
    the K >= 10 threshold values of p_f."""
    r = mc.simulate_window_declarations()
    sigma = np.sqrt(r.empty_formula * (1 - r.empty_formula) / r.trials)
    assert np.all(np.abs(r.empty_independent - r.empty_formula) <= 4 * sigma)
    sigma_c = np.sqrt(r.empty_correlated * (1 - r.empty_correlated) / r.trials)
    assert np.all(r.empty_correlated >= r.empty_formula - 3 * sigma_c)
    high = r.p_f >= 0.1
    assert np.all(r.empty_correlated[high] > r.empty_formula[high] + 10 * sigma_c[high])
    assert np.all(np.diff(r.empty_correlated) < 0)  # common random numbers: monotone in p_f


def test_false_track_search_on_hand_built_chains() -> None:
    """Oracle: chains built by hand, whose existence follows from the definition alone: a
    quadruplet in segment 1 at offsets (0, 0, 0) and one in segment 2 at (1, 1, 1) form a
    track when the track window is +-1 and not when it is 0; a first quadruplet outside the
    list window forms none."""
    decl = np.zeros((2, 2, 4, 5), bool)
    decl[:, 0, 0, 2] = True
    decl[0, 0, 1:, 2] = True  # trial 0: offsets (0, 0, 0) in segment 1
    decl[1, 0, 1:, 4] = True  # trial 1: offsets (2, 2, 2), outside w = 1
    decl[:, 1, 0, 2] = True
    decl[:, 1, 1:, 3] = True  # both trials: offsets (1, 1, 1) in segment 2
    assert mc.false_track_exists(decl, 1, 1).tolist() == [True, False]
    assert mc.false_track_exists(decl, 1, 0).tolist() == [False, False]
    assert mc.false_track_exists(decl[:, :1], 2, 0).tolist() == [True, True]


def test_false_track_bound_is_the_product_formula() -> None:
    """Oracle: (B.6) and (C.14) written out with powers of 1 - p_f (no logarithms)."""
    p = np.array([0.02, 0.1, 0.3])
    f = (1 - (1 - p) ** mc.TRACK_N_A) * (1 - (1 - p) ** (2 * mc.TRACK_W + 1)) ** 3
    g = (1 - (1 - p) ** mc.TRACK_N_A) * (1 - (1 - p) ** (2 * mc.TRACK_V + 1)) ** 3
    for k in (1, 2, 3):
        assert np.allclose(mc.false_track_bound(p, k), f * g ** (k - 1), rtol=1e-12)


def test_binomial_sigma_floor() -> None:
    """Oracle: sqrt(r (1 - r) / n) by hand, with one event's rate for a zero count."""
    got = mc.binomial_sigma(np.array([0.0, 0.25]), 400)
    assert np.allclose(got, [np.sqrt(399 / 400**3), np.sqrt(0.1875) / 20])


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: mc.binomial_sigma(np.array([0.5, 1.5]), 10), "rate"),
        (lambda: mc.binomial_sigma(0.5, 0), "trials"),
        (lambda: mc.false_track_bound(0.0, 1), "p_f"),
        (lambda: mc.false_track_bound(0.1, 0), "k"),
        (lambda: mc.false_track_exists(np.zeros((2, 1, 3, 5), bool), 1, 1), "decl"),
        (lambda: mc.false_track_exists(np.zeros((2, 1, 4, 5)), 1, 1), "decl"),
        (lambda: mc.false_track_exists(np.zeros((2, 1, 4, 5), bool), -1, 1), "w"),
        (lambda: mc.false_track_exists_brute_force(np.zeros((2, 1, 4, 5), bool), 1, 1.5), "v"),
        (lambda: mc.false_track_exists(np.zeros((2, 3, 4, 5), bool), 1, 1), "decl"),
    ],
)
def test_bad_arguments_raise_naming_them(call, name) -> None:
    with pytest.raises(ValueError, match=name):
        call()
