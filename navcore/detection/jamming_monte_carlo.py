r"""A seeded Monte Carlo of the first stage of the jamming bounds: lists and the K-list rule.

The bounds of :mod:`navcore.detection.jamming` (ATC-10 Sec. 2 and Appendices A-C) are
evaluated for :math:`2 \times 10^7`-sample segments; here the same structure is simulated at
reduced size, so that the events are frequent enough to count:

* each of the 4 filters of a list outputs i.i.d. unit-variance Gaussian samples (the
  matched-filter output normalised by :math:`\sqrt{J/B}`); the signature adds
  :math:`d = (J/(P_0 B \tau))^{-1/2}` at the true arrival, the same sample in all four
  filters;
* a filter declares a pulse where its sample exceeds :math:`\eta = d - \Phi^{-1}(p_d)`;
* a list is non-empty when some declaration of filter 1 among its :math:`n_a` samples has a
  declaration of each of filters 2-4 within :math:`\pm w` samples (a consistent quadruplet);
* the first stage decides "present" when more than :math:`K t` of the :math:`K` lists are
  non-empty.

:func:`simulate` compares the simulated false-alarm rate with :math:`F^{K t + 1}` (B.11),
where :math:`F = [1 - (1 - p_f)^{n_a}][1 - (1 - p_f)^{2w+1}]^3` is (B.6) for this window, and
the simulated detection rate with :math:`P_{DL}` of (2.4.2).

The ambiguous-detection bound (Appendix C) rests on false *tracks*: one noise quadruplet per
segment, the first a consistent list entry, each later one within the track window of the
previous one. :func:`false_track_exists` decides exactly whether such a chain exists (by
propagating the reachable offset triples; :func:`false_track_exists_brute_force` is the
explicit search), and :func:`simulate_false_tracks` compares its rate with
:math:`F G^{K-1}` of (B.6) and (C.14) at the reduced sizes. :func:`simulate_window_declarations`
tests the independent-sample product :math:`1 - (1 - p_f)^n` of one window itself, against
samples with correlation 1/2 between neighbours.

The sizes and seeds are module constants; each simulation is run once per process and
memoised.

References
----------
Schneider, Stiglitz & Eckberg, "Surveillance Aspects of the Advanced Air Traffic Management
System", MIT Lincoln Laboratory ATC-10 (1972), Sec. 2.4 and Appendices A-C.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import special

from navcore._validate import as_finite_array, require_integer
from navcore.detection import jamming as jm
from navcore.detection.neyman_pearson import detection_index_from_jammer_ratio, log_false_alarm_probability

__all__ = [
    "CASES",
    "HALF_WINDOW",
    "K_MAX",
    "N_A",
    "SEED",
    "TRACK_KS",
    "TRACK_N_A",
    "TRACK_PF",
    "TRACK_SEED",
    "TRACK_TRIALS",
    "TRACK_V",
    "TRACK_W",
    "TRIALS",
    "WINDOW_N",
    "WINDOW_PF",
    "WINDOW_SEED",
    "WINDOW_TRIALS",
    "X_DB",
    "FalseTrackRates",
    "ListRates",
    "WindowRates",
    "binomial_sigma",
    "false_track_bound",
    "false_track_exists",
    "false_track_exists_brute_force",
    "simulate",
    "simulate_false_tracks",
    "simulate_window_declarations",
]

FloatArray = NDArray[np.float64]

#: Filter-1 samples per segment in the first-stage simulation (reduced: the paper's segments
#: hold :math:`2\times10^7`, its windows :math:`9.6\times10^5`, a ratio of about 20 kept here).
N_A = 200
#: Half-width ``w`` of the list window, in samples.
HALF_WINDOW = 5
#: Trials per case of the first-stage simulation.
TRIALS = 1000
#: Seed of the first-stage simulation.
SEED = 19720622
#: Jammer-to-signal ratios ``x`` (dB) simulated.
X_DB = np.arange(-14.0, -6.5, 1.0)
#: :math:`(K, t, P_{DL})` cases simulated.
CASES = ((1, 0.0, 0.9), (3, 0.0, 0.9), (3, 1.0 / 3.0, 0.9))
#: Lists simulated per trial: the largest K of the cases.
K_MAX = max(k for k, _, _ in CASES)


@dataclass(frozen=True)
class ListRates:
    """Simulated and bound rates of the first stage on the grid ``X_DB`` for one :math:`(K, t, P_{DL})` case.

    Attributes
    ----------
    k : int
        Number of segments (lists) ``K``.
    t : float
        Fraction in the rule "more than ``K t`` lists non-empty".
    p_dl : float
        Detection probability the bound is designed for.
    p_d : float
        Per-sample detection probability that makes the bound equal ``p_dl``.
    false_alarm : ndarray
        Simulated false-alarm rate at each ``x`` of ``X_DB``.
    false_alarm_bound : ndarray
        :math:`F^{K t + 1}` (B.11) at each ``x``.
    detection : ndarray
        Simulated detection rate at each ``x``.
    detection_bound : float
        :math:`P_{DL}` of (2.4.2) at ``p_d``.
    trials : int
        Trials behind each simulated rate.
    """

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


@cache
def simulate() -> tuple[ListRates, ...]:
    """Simulate the first stage for every case of ``CASES`` (seeded; common random numbers over x).

    Returns
    -------
    tuple of ListRates
        One record per case, in the order of ``CASES``.

    Examples
    --------
    >>> rates = simulate()
    >>> [(r.k, round(r.t, 3)) for r in rates]
    [(1, 0.0), (3, 0.0), (3, 0.333)]
    >>> r = rates[0]
    >>> bool(np.all(r.false_alarm_bound <= r.false_alarm + 3 * binomial_sigma(r.false_alarm, r.trials)))
    True
    """
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


def binomial_sigma(rate: ArrayLike, trials: int) -> FloatArray:
    """Standard error of a simulated rate, with a floor of one event for zero counts.

    Parameters
    ----------
    rate : array_like
        Simulated rates, in [0, 1].
    trials : int
        Trials behind each rate (``>= 1``).

    Returns
    -------
    ndarray
        ``sqrt(r (1 - r) / trials)`` with ``r = max(rate, 1 / trials)``.

    Raises
    ------
    ValueError
        If a rate is not a probability or ``trials`` is not a positive integer.

    Examples
    --------
    >>> binomial_sigma(np.array([0.0, 0.5]), 100).round(4)
    array([0.0099, 0.05  ])
    """
    rate = as_finite_array("rate", rate)
    if np.any(rate < 0.0) or np.any(rate > 1.0):
        raise ValueError(f"rate must lie in [0, 1], got {rate!r}")
    trials = require_integer("trials", trials, minimum=1)
    r = np.maximum(rate, 1.0 / trials)
    return np.sqrt(r * (1 - r) / trials)


# --- ambiguous detections (Appendix C): false tracks across segments --------------------------

#: Filter-1 samples per segment in the false-track simulation (reduced size).
TRACK_N_A = 60
#: Half-width ``W`` of the list window (a consistent quadruplet), in samples.
TRACK_W = 2
#: Half-width ``V`` of the track window (how far a time difference may move from one segment
#: to the next), in samples.
TRACK_V = 1
#: Trials of the false-track simulation.
TRACK_TRIALS = 2000
#: Seed of the false-track simulation.
TRACK_SEED = 19720623
#: Per-sample false-alarm probabilities simulated.
TRACK_PF = np.geomspace(0.02, 0.3, 8)
#: Numbers of segments ``K`` simulated.
TRACK_KS = (1, 2, 3)


@dataclass(frozen=True)
class FalseTrackRates:
    """Simulated probability that a false track exists over K segments, and its bound :math:`F G^{K-1}`.

    Attributes
    ----------
    k : int
        Number of segments ``K``.
    p_f : ndarray
        Per-sample false-alarm probabilities.
    simulated : ndarray
        Simulated probability of a false track at each ``p_f``.
    bound : ndarray
        :math:`F G^{K-1}` at each ``p_f`` (:func:`false_track_bound`).
    trials : int
        Trials behind each simulated probability.
    """

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


def _check_declarations(decl: ArrayLike, w: int, v: int) -> tuple[NDArray[np.bool_], int, int]:
    """Check the arguments of the false-track search at the boundary."""
    arr = np.asarray(decl)
    if arr.dtype != np.bool_ or arr.ndim != 4 or arr.shape[2] != 4 or 0 in arr.shape:
        raise ValueError(
            f"decl must be a non-empty boolean array of shape (trials, K, 4, samples), got {decl!r}"
        )
    w = require_integer("w", w, minimum=0)
    v = require_integer("v", v, minimum=0)
    if arr.shape[3] - 2 * (w + (arr.shape[1] - 1) * v) < 1:
        raise ValueError(f"decl holds {arr.shape[3]} samples per filter: too few for w = {w}, v = {v}")
    return arr, w, v


def false_track_exists(decl: ArrayLike, w: int, v: int) -> NDArray[np.bool_]:
    r"""Decide, per trial, whether a false track exists among the declarations ``decl``.

    Filter 1 uses the central ``n_a`` samples; ``R = w + (K - 1) v`` pads filters 2-4. A false
    track is one quadruplet per segment: a filter-1 declaration at ``a_k`` and, for each filter
    ``j = 2..4``, a declaration at :math:`a_k + \delta_{kj}` with :math:`|\delta_{1j}| \le w` in the first
    segment (a consistent list entry) and :math:`|\delta_{kj} - \delta_{(k-1)j}| \le v` afterwards (a
    physically possible track; ATC-10 Appendix C). The existence is decided exactly, by
    propagating the set of reachable offset triples from segment to segment.

    Parameters
    ----------
    decl : array_like of bool
        Declarations, shape :math:`(\text{trials}, K, 4, n_a + 2R)`.
    w : int
        Half-width of the list window (``>= 0``), in samples.
    v : int
        Half-width of the track window (``>= 0``), in samples.

    Returns
    -------
    ndarray of bool
        Shape ``(trials,)``: whether a false track exists.

    Raises
    ------
    ValueError
        If ``decl`` is not a boolean array of that shape, ``w`` or ``v`` is not a
        non-negative integer, or ``decl`` holds fewer than ``2 R + 1`` samples per filter.

    Examples
    --------
    >>> decl = np.zeros((1, 2, 4, 5), bool)
    >>> decl[0, 0, :, 2] = True  # a quadruplet in segment 1 at offsets (0, 0, 0)
    >>> decl[0, 1, 0, 2] = decl[0, 1, 1:, 3] = True  # segment 2 at offsets (1, 1, 1)
    >>> false_track_exists(decl, w=1, v=1), false_track_exists(decl, w=1, v=0)
    (array([ True]), array([False]))
    """
    decl, w, v = _check_declarations(decl, w, v)
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


def false_track_exists_brute_force(decl: ArrayLike, w: int, v: int) -> NDArray[np.bool_]:
    r"""Decide the same as :func:`false_track_exists` by explicit search over every chain.

    Slow (a loop over trials, segments and quadruplets): an independent check of the
    propagation.

    Parameters
    ----------
    decl : array_like of bool
        Declarations, shape :math:`(\text{trials}, K, 4, n_a + 2R)` with ``R = w + (K - 1) v``.
    w : int
        Half-width of the list window (``>= 0``), in samples.
    v : int
        Half-width of the track window (``>= 0``), in samples.

    Returns
    -------
    ndarray of bool
        Shape ``(trials,)``: whether a false track exists.

    Raises
    ------
    ValueError
        As :func:`false_track_exists`.

    Examples
    --------
    >>> rng = np.random.default_rng(1)
    >>> decl = rng.random((20, 2, 4, 9)) < 0.3
    >>> bool(np.array_equal(false_track_exists_brute_force(decl, 1, 1), false_track_exists(decl, 1, 1)))
    True
    """
    decl, w, v = _check_declarations(decl, w, v)
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


def false_track_bound(p_f: ArrayLike, k: int) -> FloatArray:
    """:math:`F G^{K-1}` at the reduced sizes of the false-track simulation (ATC-10 (B.6), (C.14)).

    ``F`` and ``G`` are (B.6) and (C.14) with ``TRACK_N_A`` filter-1 samples and windows of
    :math:`2 w + 1` and :math:`2 v + 1` samples (``TRACK_W`` and ``TRACK_V``).

    Parameters
    ----------
    p_f : array_like
        Per-sample false-alarm probabilities, in (0, 1).
    k : int
        Number of segments ``K`` (``>= 1``).

    Returns
    -------
    ndarray
        The bound at each ``p_f``.

    Raises
    ------
    ValueError
        If a ``p_f`` is outside (0, 1) or ``k`` is not a positive integer.

    Examples
    --------
    >>> p = 0.1
    >>> f = (1 - (1 - p) ** TRACK_N_A) * (1 - (1 - p) ** (2 * TRACK_W + 1)) ** 3
    >>> bool(np.isclose(false_track_bound(p, 1), f))
    True
    """
    p_f = as_finite_array("p_f", p_f)
    if np.any(p_f <= 0.0) or np.any(p_f >= 1.0):
        raise ValueError(f"p_f must lie in (0, 1), got {p_f!r}")
    k = require_integer("k", k, minimum=1)
    log_pf = np.log(p_f)
    log_f = jm.log_one_minus_power(log_pf, TRACK_N_A) + 3 * jm.log_one_minus_power(log_pf, 2 * TRACK_W + 1)
    log_g = jm.log_one_minus_power(log_pf, TRACK_N_A) + 3 * jm.log_one_minus_power(log_pf, 2 * TRACK_V + 1)
    return np.exp(log_f + (k - 1) * log_g)


@cache
def simulate_false_tracks() -> tuple[FalseTrackRates, ...]:
    """Simulate false tracks for each K of ``TRACK_KS`` (seeded; common random numbers over p_f).

    Returns
    -------
    tuple of FalseTrackRates
        One record per K, in the order of ``TRACK_KS``.

    Examples
    --------
    >>> rates = simulate_false_tracks()
    >>> [r.k for r in rates]
    [1, 2, 3]
    >>> all(bool(np.all(r.bound <= r.simulated + 3 * binomial_sigma(r.simulated, r.trials))) for r in rates)
    True
    """
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

#: Window length in samples (the track window of (C.14) holds 23.86).
WINDOW_N = 24
#: Trials of the window simulation.
WINDOW_TRIALS = 400_000
#: Seed of the window simulation.
WINDOW_SEED = 19720624
#: Per-sample false-alarm probabilities simulated (the K >= 10 ambiguous-location thresholds
#: lie at :math:`p_f` of about 0.1-0.27).
WINDOW_PF = np.array([0.01, 0.03, 0.1, 0.2, 0.27])


@dataclass(frozen=True)
class WindowRates:
    """Probability that an n-sample window holds no declaration: independent and correlated samples.

    Attributes
    ----------
    p_f : ndarray
        Per-sample false-alarm probabilities.
    empty_formula : ndarray
        ``(1 - p_f)^n``, the independent-sample formula.
    empty_independent : ndarray
        Simulated probability of an empty window, independent samples.
    empty_correlated : ndarray
        Simulated probability of an empty window, neighbour correlation 1/2.
    n : int
        Samples per window.
    trials : int
        Trials behind each simulated probability.
    """

    p_f: np.ndarray
    empty_formula: np.ndarray
    empty_independent: np.ndarray
    empty_correlated: np.ndarray
    n: int
    trials: int


@cache
def simulate_window_declarations() -> WindowRates:
    """Simulate one window of ``WINDOW_N`` normalised matched-filter noise samples (seeded).

    Independent samples are i.i.d. N(0, 1). Correlated samples are ``(z_k + z_(k+1)) / sqrt(2)``:
    correlation 1/2 between neighbours and 0 beyond, the noise at the output of a filter matched to
    a code of rectangular chips sampled twice per chip (ATC-10's "twice the Nyquist rate"). Both
    use the same ``z`` (common random numbers). A sample is declared where it exceeds
    ``Q^{-1}(p_f)``, so each sample alone has false-alarm probability ``p_f`` in both cases.

    Returns
    -------
    WindowRates
        The empty-window probabilities at each ``p_f`` of ``WINDOW_PF``.

    Examples
    --------
    >>> r = simulate_window_declarations()
    >>> bool(np.all(r.empty_correlated > r.empty_formula))
    True
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
