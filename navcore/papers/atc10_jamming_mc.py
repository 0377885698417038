"""A seeded Monte Carlo of the ATC-10 first stage: matched-filter samples, lists and the K-list rule.

The bounds of Sec. 2 and Appendices A-B are evaluated for 2e7-sample segments; here the same
structure is simulated at reduced size so that the events are frequent enough to count:

* each of the 4 filters of a list outputs i.i.d. unit-variance Gaussian samples (the
  matched-filter output normalised by sqrt(J/B)); the signature adds ``d = (J/(P0 B tau))^(-1/2)``
  at the true arrival, the same sample in all four filters;
* a filter declares a pulse where its sample exceeds ``eta = d - Phi^{-1}(p_d)``;
* a list is non-empty when some declaration of filter 1 among its ``n_a`` samples has a
  declaration of each of filters 2-4 within ``+-w`` samples (a consistent quadruplet);
* the first stage decides "present" when more than ``K t`` of the ``K`` lists are non-empty.

The simulated false-alarm rate is compared with ``F^(K t + 1)`` (B.11), where
``F = [1 - (1 - p_f)^n_a][1 - (1 - p_f)^(2w+1)]^3`` is (B.6) for this window, and the
simulated detection rate with ``P_DL`` of (2.4.2).

The ambiguous-detection bound (Appendix C) rests on false *tracks*: one noise quadruplet per
segment, the first a consistent list entry, each later one within the track window of the
previous one. :func:`simulate_false_tracks` decides exactly whether such a chain exists (by
propagating the reachable offset triples; :func:`false_track_exists_brute_force` is the
explicit search used as its test oracle) and compares the rate with ``F G^(K-1)`` of (B.6) and
(C.14) at the reduced sizes. :func:`simulate_window_declarations` tests the independent-sample
product ``1 - (1 - p_f)^n`` of one window itself, against samples with correlation 1/2 between
neighbours. No part of this module is a published claim: it reads no paper input and defines no
claim, and its sizes are the book's (the seeded runs are memoised with ``input_cache``, the
ledger's memo, like every memo in ``navcore.papers``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special

from navcore.claims.inputs import input_cache
from navcore.detection import jamming as jm
from navcore.detection.neyman_pearson import detection_index_from_jammer_ratio, log_false_alarm_probability

#: Reduced sizes: filter-1 samples per segment and window half-width (ratio 2e7 / 9.6e5 ~ 20).
N_A = 200
HALF_WINDOW = 5
TRIALS = 1000
SEED = 19720622
X_DB = np.arange(-14.0, -6.5, 1.0)
#: (K, t, P_DL) cases simulated.
CASES = ((1, 0.0, 0.9), (3, 0.0, 0.9), (3, 1.0 / 3.0, 0.9))
#: Lists simulated per trial: the largest K of the cases.
K_MAX = max(k for k, _, _ in CASES)


@dataclass(frozen=True)
class ListRates:
    """Simulated and bound rates on the grid :data:`X_DB` for one (K, t, P_DL) case."""

    k: int
    t: float
    p_dl: float
    p_d: float
    false_alarm: np.ndarray
    false_alarm_bound: np.ndarray
    detection: np.ndarray
    detection_bound: float
    trials: int


def _nonempty(decl: np.ndarray) -> np.ndarray:
    """Lists with a consistent quadruplet; ``decl`` has shape (trials, K, 4, n_a + 2w)."""
    w = HALF_WINDOW
    cs = np.concatenate(
        [np.zeros((*decl.shape[:-1], 1), np.int32), np.cumsum(decl, axis=-1, dtype=np.int32)], -1
    )
    centre = np.arange(w, w + N_A)
    counts = cs[..., centre + w + 1] - cs[..., centre - w]  # declarations within +-w of each centre sample
    ok = decl[:, :, 0, centre] & (counts[:, :, 1:, :] > 0).all(axis=2)
    return ok.any(axis=-1)


@input_cache
def simulate() -> tuple[ListRates, ...]:
    """Run the seeded simulation for every case in :data:`CASES` (common random numbers over x)."""
    rng = np.random.default_rng(SEED)
    length = N_A + 2 * HALF_WINDOW
    noise = rng.standard_normal((TRIALS, K_MAX, 4, length), dtype=np.float32)
    arrival = HALF_WINDOW + N_A // 2
    results = []
    for k, t, p_dl in CASES:
        p_d = jm.filter_detection_probability_for_bound(p_dl, k, t)
        n = noise[:, :k]
        fa, det, bound = [], [], []
        for x_db in X_DB:
            d = float(detection_index_from_jammer_ratio(10 ** (x_db / 10)))
            eta = np.float32(d - special.ndtri(p_d))
            decl = n > eta
            fa.append(np.mean(_nonempty(decl).sum(axis=1) > k * t))
            decl[..., arrival] = n[..., arrival] + np.float32(d) > eta
            det.append(np.mean(_nonempty(decl).sum(axis=1) > k * t))
            log_pf = float(log_false_alarm_probability(p_d, d))
            log_f = float(jm.log_one_minus_power(log_pf, N_A)) + 3 * float(
                jm.log_one_minus_power(log_pf, 2 * HALF_WINDOW + 1)
            )
            bound.append(math.exp((k * t + 1) * log_f))
        results.append(
            ListRates(
                k,
                t,
                p_dl,
                p_d,
                np.array(fa),
                np.array(bound),
                np.array(det),
                float(jm.detection_lower_bound(p_d, k, t)),
                TRIALS,
            )
        )
    return tuple(results)


def binomial_sigma(rate: np.ndarray, trials: int) -> np.ndarray:
    """Standard error of a simulated rate (with a floor of one event for zero counts)."""
    r = np.maximum(rate, 1.0 / trials)
    return np.sqrt(r * (1 - r) / trials)


# --- ambiguous detections (Appendix C): false tracks across segments --------------------------

#: Reduced sizes of the false-track simulation: filter-1 samples per segment, the list window
#: (+-W samples: a consistent quadruplet) and the track window (+-V samples: how far a time
#: difference may move from one segment to the next), trials, and the p_f grid.
TRACK_N_A = 60
TRACK_W = 2
TRACK_V = 1
TRACK_TRIALS = 2000
TRACK_SEED = 19720623
TRACK_PF = np.geomspace(0.02, 0.3, 8)
TRACK_KS = (1, 2, 3)


@dataclass(frozen=True)
class FalseTrackRates:
    """Simulated probability that a false track exists over K segments, and the bound F G^(K-1)."""

    k: int
    p_f: np.ndarray
    simulated: np.ndarray
    bound: np.ndarray
    trials: int


def _shift_or(reach: np.ndarray, v: int) -> np.ndarray:
    """Dilate a boolean (trials, S, S, S) array by +-v along the three offset axes."""
    out = reach.copy()
    for axis in (1, 2, 3):
        acc = out.copy()
        for s in range(1, v + 1):
            acc[(slice(None),) * axis + (slice(s, None),)] |= out[(slice(None),) * axis + (slice(None, -s),)]
            acc[(slice(None),) * axis + (slice(None, -s),)] |= out[(slice(None),) * axis + (slice(s, None),)]
        out = acc
    return out


def false_track_exists(decl: np.ndarray, w: int, v: int) -> np.ndarray:
    """Whether a false track exists, for declarations ``decl`` of shape (trials, K, 4, n_a + 2R).

    Filter 1 uses the central ``n_a`` samples; ``R = w + (K - 1) v`` pads filters 2-4. A false
    track is one quadruplet per segment: a filter-1 declaration at ``a_k`` and, for each filter
    ``j = 2..4``, a declaration at ``a_k + delta_kj`` with ``|delta_1j| <= w`` in the first
    segment (a consistent list entry) and ``|delta_kj - delta_(k-1)j| <= v`` afterwards (a
    physically possible track). The existence is decided exactly, by propagating the set of
    reachable offset triples from segment to segment.
    """
    trials, k, _, length = decl.shape
    r = w + (k - 1) * v
    n_a = length - 2 * r
    size = 2 * r + 1
    idx = np.arange(n_a)[:, None] + np.arange(size)[None, :]  # (n_a, S): sample of offset i - r
    central = np.zeros(size, bool)
    central[r - w : r + w + 1] = True
    reach = None
    for seg in range(k):
        d1 = decl[:, seg, 0, r : r + n_a].astype(np.float32)
        e2, e3, e4 = (decl[:, seg, j][:, idx].astype(np.float32) for j in (1, 2, 3))  # (T, n_a, S)
        pair = (d1[:, :, None, None] * e2[:, :, :, None] * e3[:, :, None, :]).reshape(
            trials, n_a, size * size
        )
        q = (np.matmul(pair.transpose(0, 2, 1), e4) > 0).reshape(trials, size, size, size)
        if reach is None:
            reach = q & central[:, None, None] & central[None, :, None] & central[None, None, :]
        else:
            reach = q & _shift_or(reach, v)
    assert reach is not None  # k >= 1 segments
    return reach.reshape(trials, -1).any(axis=1)


def false_track_exists_brute_force(decl: np.ndarray, w: int, v: int) -> np.ndarray:
    """The same decision by explicit search over every chain of quadruplets (slow; for tests)."""
    trials, k, _, length = decl.shape
    r = w + (k - 1) * v
    n_a = length - 2 * r
    out = np.zeros(trials, bool)
    for t in range(trials):
        states: set[tuple[int, int, int]] = set()
        for seg in range(k):
            new = set()
            for a in np.flatnonzero(decl[t, seg, 0, r : r + n_a]):
                lists = [[dj for dj in range(-r, r + 1) if decl[t, seg, j, r + a + dj]] for j in (1, 2, 3)]
                for d2 in lists[0]:
                    for d3 in lists[1]:
                        for d4 in lists[2]:
                            cand = (d2, d3, d4)
                            if seg == 0:
                                ok = max(map(abs, cand)) <= w
                            else:
                                ok = any(
                                    max(abs(c - p) for c, p in zip(cand, prev, strict=True)) <= v
                                    for prev in states
                                )
                            if ok:
                                new.add(cand)
            states = new
        out[t] = bool(states)
    return out


def false_track_bound(p_f: np.ndarray, k: int) -> np.ndarray:
    """``F G^(K-1)`` at the reduced sizes: (B.6) and (C.14) with n_a, 2W+1 and 2V+1 samples."""
    log_pf = np.log(p_f)
    log_f = jm.log_one_minus_power(log_pf, TRACK_N_A) + 3 * jm.log_one_minus_power(log_pf, 2 * TRACK_W + 1)
    log_g = jm.log_one_minus_power(log_pf, TRACK_N_A) + 3 * jm.log_one_minus_power(log_pf, 2 * TRACK_V + 1)
    return np.exp(log_f + (k - 1) * log_g)


@input_cache
def simulate_false_tracks() -> tuple[FalseTrackRates, ...]:
    """Seeded simulation of false tracks for K in :data:`TRACK_KS` (common random numbers over p_f)."""
    rng = np.random.default_rng(TRACK_SEED)
    k_max = max(TRACK_KS)
    r_max = TRACK_W + (k_max - 1) * TRACK_V
    u = rng.random((TRACK_TRIALS, k_max, 4, TRACK_N_A + 2 * r_max), dtype=np.float32)
    out = []
    for k in TRACK_KS:
        pad = r_max - (TRACK_W + (k - 1) * TRACK_V)
        uk = u[:, :k, :, pad : u.shape[-1] - pad]
        sim = np.array([false_track_exists(uk < p, TRACK_W, TRACK_V).mean() for p in TRACK_PF])
        out.append(FalseTrackRates(k, TRACK_PF, sim, false_track_bound(TRACK_PF, k), TRACK_TRIALS))
    return tuple(out)


# --- correlated samples (B.6)/(C.14): is one window's declaration probability 1 - (1 - p_f)^n? ------

#: Window length (samples; the track window of (C.14) holds 23.86), trials, seed and p_f grid (the
#: K >= 10 N_ADL thresholds lie at p_f of about 0.1-0.27).
WINDOW_N = 24
WINDOW_TRIALS = 400_000
WINDOW_SEED = 19720624
WINDOW_PF = np.array([0.01, 0.03, 0.1, 0.2, 0.27])


@dataclass(frozen=True)
class WindowRates:
    """Probability that an n-sample window holds no declaration: independent and correlated samples."""

    p_f: np.ndarray
    empty_formula: np.ndarray
    empty_independent: np.ndarray
    empty_correlated: np.ndarray
    n: int
    trials: int


@input_cache
def simulate_window_declarations() -> WindowRates:
    """Seeded simulation of one window of ``WINDOW_N`` normalised matched-filter noise samples.

    Independent samples are i.i.d. N(0, 1). Correlated samples are ``(z_k + z_(k+1)) / sqrt(2)``:
    correlation 1/2 between neighbours and 0 beyond, the noise at the output of a filter matched to
    a code of rectangular chips sampled twice per chip (the paper's "twice the Nyquist rate"). Both
    use the same ``z`` (common random numbers). A sample is declared where it exceeds
    ``Q^{-1}(p_f)``, so each sample alone has false-alarm probability ``p_f`` in both cases.
    """
    rng = np.random.default_rng(WINDOW_SEED)
    z = rng.standard_normal((WINDOW_TRIALS, WINDOW_N + 1))
    peak_independent = z[:, :WINDOW_N].max(axis=1)
    peak_correlated = ((z[:, :-1] + z[:, 1:]) / math.sqrt(2.0)).max(axis=1)
    threshold = -special.ndtri(WINDOW_PF)
    empty_i = np.array([np.mean(peak_independent <= u) for u in threshold])
    empty_c = np.array([np.mean(peak_correlated <= u) for u in threshold])
    formula = np.exp(WINDOW_N * np.log1p(-WINDOW_PF))
    return WindowRates(WINDOW_PF, formula, empty_i, empty_c, WINDOW_N, WINDOW_TRIALS)
