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
simulated detection rate with ``P_DL`` of (2.4.2). No part of this module is a published claim.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache

import numpy as np
from scipy import special

from navcore.detection import jamming as jm
from navcore.detection.neyman_pearson import detection_index_from_jammer_ratio, log_false_alarm_probability

#: Reduced sizes: filter-1 samples per segment and window half-width (ratio 2e7 / 9.6e5 ~ 20).
N_A = 200
HALF_WINDOW = 5
TRIALS = 1000
K_MAX = 3
SEED = 19720622
X_DB = np.arange(-14.0, -6.5, 1.0)
#: (K, t, P_DL) cases simulated.
CASES = ((1, 0.0, 0.9), (3, 0.0, 0.9), (3, 1.0 / 3.0, 0.9))


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


@cache
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
