"""Tracking the aircraft clock (emission time tau_n) to improve multilateration.

The aircraft emits a pulse about every tau_bar seconds; the emission times form a clock
process tau_n with increments Delta_n = tau_n - tau_{n-1} - tau_bar whose covariance is
``E[Delta_n Delta_m] = 2 sigma0^2`` for n = m and ``sigma0^2`` otherwise (ATC-10 Eq. 4.5.23,
the random-walk-plus-frequency-offset model Delta_n = w_n + A).

The estimator of ATC-10 Section 4.5 predicts ``tau_n`` from ``tau_hat_{n-1} + tau_bar`` and
corrects it with the time-of-arrival residuals projected off the position directions,

    tau_hat_n = tau_hat_{n-1} + tau_bar + gamma_n 1'(I - P)(T_n - k_n - (tau_hat_{n-1} + tau_bar) 1),

with the gain ``gamma_n = s_n / (sigma^2 + beta s_n)``, ``s_n`` the prior variance
(Eqs. 4.5.16-4.5.25). The error variance is ``sigma^2 gamma_n``; the position error
has mean square ``sigma^2 (tr{(F'F)^-1} + gamma_n S)`` (Eq. 4.5.35 corrected).
In steady state ``gamma = psi(alpha)/beta`` with ``alpha = (8/27) sigma0^2 beta / sigma^2``
and psi the real root of a cubic (Eqs. 4.5.26, 4.5.32-4.5.34). When only three
satellites remain, tau is extrapolated (Eqs. 4.5.27-4.5.30).

All variances are in the square of the time unit of ``sigma``; with F built from unit
vectors and c = 1 ft/ns (the paper's convention) position variances in ft^2 equal the
ns^2 numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from navcore._validate import as_finite_array, require_integer, require_nonnegative, require_positive
from navcore.trace import implements

__all__ = [
    "GainHistory",
    "TrackerMonteCarlo",
    "alpha_parameter",
    "convergence_steps",
    "convergence_steps_geometric",
    "gain_recursion",
    "position_mse",
    "psi",
    "psi_cubic_root",
    "psi_large_alpha",
    "psi_small_alpha",
    "simulate_tracker",
    "steady_state_gain",
    "three_satellite_clock_variance",
    "three_satellite_clock_variance_steady",
]


@implements("ATC10 4.5.32")
def alpha_parameter(sigma0: float, sigma: float, beta: float) -> float:
    """``alpha = (8/27) sigma0^2 beta / sigma^2`` (ATC-10 Eq. 4.5.32).

    Examples
    --------
    >>> round(alpha_parameter(5.0, 50.0, 0.0543), 7)
    0.0001609
    """
    require_nonnegative("sigma0", sigma0)
    require_positive("sigma", sigma)
    require_nonnegative("beta", beta)
    return 8.0 / 27.0 * sigma0**2 * beta / sigma**2


@implements("ATC10 4.5.34")
def psi(alpha: np.ndarray | float) -> np.ndarray | float:
    """Steady-state gain factor ``psi = gamma beta`` (ATC-10 Eq. 4.5.34), real cube roots.

    ``psi(alpha) = 1.5 alpha^(1/3) {cbrt(1 + sqrt(1 + alpha)) + cbrt(1 - sqrt(1 + alpha))}``.
    The second cube root has a negative argument: ``np.cbrt`` returns the real root,
    whereas ``x ** (1/3)`` would return a complex principal root. For large alpha the two
    cube roots nearly cancel, so the algebraically equal form
    ``1.5 alpha / (cbrt(a)^2 + cbrt(a) cbrt(b) + cbrt(b)^2)`` with ``a - b = 2 sqrt(1+alpha)``
    is not needed here; both are accurate to ~1e-12 for alpha <= 1e3.

    Examples
    --------
    >>> round(float(psi(1.61e-2)), 5)
    0.40204
    """
    a = as_finite_array("alpha", alpha)
    if np.any(a < 0):
        raise ValueError("alpha must be >= 0")
    s = np.sqrt(1.0 + a)
    out = 1.5 * np.cbrt(a) * (np.cbrt(1.0 + s) + np.cbrt(1.0 - s))
    return float(out) if out.ndim == 0 else out


def psi_cubic_root(alpha: float) -> float:
    """psi as the real root in (0, 1) of ``x^3 + q x - q = 0``, ``q = 27 alpha / 4``.

    Independent of :func:`psi`: uses ``numpy.roots`` (companion-matrix eigenvalues).
    """
    require_positive("alpha", alpha)
    q = 27.0 * alpha / 4.0
    r = np.roots([1.0, 0.0, q, -q])
    real = r[np.abs(r.imag) <= 1e-9 * max(1.0, q)].real
    return float(real[(real > 0) & (real < 1)][0])


@implements("ATC10 4.5.38")
def psi_small_alpha(alpha: np.ndarray | float) -> np.ndarray | float:
    """``1.5 * 2^(1/3) [alpha^(1/3) - (alpha/2)^(2/3)]``, the alpha <= 0.3 approximation (Eq. 4.5.38)."""
    a = as_finite_array("alpha", alpha)
    out = 1.5 * np.cbrt(2.0) * (np.cbrt(a) - np.cbrt(a / 2.0) ** 2)
    return float(out) if out.ndim == 0 else out


@implements("ATC10 4.5.38")
def psi_large_alpha(alpha: np.ndarray | float) -> np.ndarray | float:
    """``1 - 4 / (27 alpha)``, the alpha >= 1 approximation (Eq. 4.5.38)."""
    a = as_finite_array("alpha", alpha)
    if np.any(a <= 0):
        raise ValueError("alpha must be > 0")
    out = 1.0 - 4.0 / (27.0 * a)
    return float(out) if out.ndim == 0 else out


@implements("ATC10 4.5.33")
def steady_state_gain(beta: float, sigma: float, sigma0: float) -> float:
    """``gamma = psi(alpha) / beta`` (ATC-10 Eq. 4.5.33)."""
    require_positive("beta", beta)
    return float(psi(alpha_parameter(sigma0, sigma, beta))) / beta


@dataclass(frozen=True)
class GainHistory:
    """The gain recursion for n = 0..n_steps.

    Attributes
    ----------
    gamma : ndarray
        gamma_n; the clock-error variance is ``sigma^2 gamma_n`` (gamma_0 = 1/beta).
    prior_variance : ndarray
        ``s_n``, variance of the predicted clock error (``nan`` at n = 0).
    cross : ndarray
        ``d_n = -E[Delta_{n+1} xi_n]``, the correlation of the estimation error with the
        next clock increment (d_0 = 0).
    """

    gamma: np.ndarray
    prior_variance: np.ndarray
    cross: np.ndarray


@implements("ATC10 4.5.16", "ATC10 4.5.25")
def gain_recursion(beta: float, sigma: float, sigma0: float, n_steps: int) -> GainHistory:
    """Optimal gains of the constrained clock tracker (ATC-10 Eqs. 4.5.16-4.5.25, corrected).

    ``s_n = 2 sigma0^2 + sigma^2 gamma_{n-1} + 2 d_{n-1}``,
    ``gamma_n = s_n / (sigma^2 + beta s_n)``, ``a_n = 1 - gamma_n beta``,
    ``d_n = a_n (sigma0^2 + d_{n-1})``, starting from the least-squares ``gamma_0 = 1/beta``.
    """
    require_positive("beta", beta)
    require_positive("sigma", sigma)
    require_nonnegative("sigma0", sigma0)
    n_steps = require_integer("n_steps", n_steps, minimum=0)
    gamma = np.empty(n_steps + 1)
    prior = np.full(n_steps + 1, np.nan)
    cross = np.zeros(n_steps + 1)
    gamma[0] = 1.0 / beta
    s2, q2 = sigma**2, sigma0**2
    for n in range(1, n_steps + 1):
        s = 2.0 * q2 + s2 * gamma[n - 1] + 2.0 * cross[n - 1]
        prior[n] = s
        gamma[n] = s / (s2 + beta * s)
        cross[n] = (1.0 - gamma[n] * beta) * (q2 + cross[n - 1])
    return GainHistory(gamma=gamma, prior_variance=prior, cross=cross)


def three_satellite_clock_variance(
    gamma_last: float, cross_last: float, sigma: float, sigma0: float, m: np.ndarray | int
) -> np.ndarray:
    """Clock-error variance m epochs after the drop to three satellites (exact, any N).

    ``sigma^2 gamma_N + sigma0^2 (m + m^2) + 2 m d_N``: the extrapolation
    ``tau_hat_{N+m} = tau_hat_N + m tau_bar`` accumulates the clock increments.
    """
    mm = as_finite_array("m", m)
    return sigma**2 * gamma_last + sigma0**2 * (mm + mm**2) + 2.0 * mm * cross_last


@implements("ATC10 4.5.27")
def three_satellite_clock_variance_steady(
    beta: float, sigma: float, sigma0: float, m: np.ndarray | int
) -> np.ndarray:
    """Eq. 4.5.27: ``sigma^2 gamma + sigma0^2 [(2 - psi)/psi m + m^2]`` with gamma = psi/beta."""
    p = float(psi(alpha_parameter(sigma0, sigma, beta)))
    mm = as_finite_array("m", m)
    return sigma**2 * p / beta + sigma0**2 * ((2.0 - p) / p * mm + mm**2)


@implements("ATC10 4.5.35")
def position_mse(
    sigma: float, trace: float, clock_term: float, gamma: np.ndarray | float
) -> np.ndarray | float:
    """``E|xi_p|^2 = sigma^2 (tr{(F'F)^-1} + gamma S)`` (ATC-10 Eq. 4.5.35, corrected).

    For three satellites pass the clock term the caller believes in: the invariant
    ``1'(FF')^-1 1`` (correct) or the printed ``1'(F'F)^-1 1`` (erratum E4-1).
    """
    return sigma**2 * (trace + np.asarray(gamma) * clock_term)


def convergence_steps(history: GainHistory, rel: float) -> int:
    """First n after which ``|gamma_n - gamma_inf| <= rel * gamma_inf`` for all later n."""
    g = history.gamma
    limit = g[-1]
    bad = np.flatnonzero(np.abs(g - limit) > rel * limit)
    return 0 if bad.size == 0 else int(bad[-1] + 1)


def convergence_steps_geometric(psi_value: float, rel: float) -> float:
    """Steps for the geometric series ``sum (1 - psi)^i`` to come within ``rel`` of its limit.

    ``n = log(rel) / log(1 - psi) - 1``; for small psi about ``2.3 / psi - 1`` (rel = 0.1).
    """
    require_positive("psi_value", psi_value)
    return math.log(rel) / math.log1p(-psi_value) - 1.0


@dataclass(frozen=True)
class TrackerMonteCarlo:
    """Empirical second moments of the tracker's errors, per epoch n = 0..N+M."""

    clock_mse: np.ndarray
    position_mse: np.ndarray
    position_norm_variance: np.ndarray
    n_runs: int


def simulate_tracker(
    F_all: np.ndarray,
    F_three: np.ndarray,
    sigma: float,
    sigma0: float,
    n_last: int,
    m_after: int,
    n_runs: int,
    seed: int,
    tau_bar: float,
    tau_start: float = 12_345.0,
) -> TrackerMonteCarlo:
    """Monte Carlo of the whole tracker on simulated clocks and time-of-arrival noise.

    Epoch 0: least squares on all satellites; 1..N: the constrained tracker with the gains of
    :func:`gain_recursion`; N+1..N+M: three satellites, clock extrapolated, position from
    ``F3^-1``. The clock is ``tau_n = tau_start + n tau_bar + sum w_i + n A`` with
    ``w_i, A ~ N(0, sigma0^2)``; measurement noise ``N(0, sigma^2 I)``. The aircraft track
    is an arbitrary nonrandom sequence (it cancels in the errors because the estimator is
    exact for it); only errors are simulated. Vectorised over runs.
    """
    F = as_finite_array("F_all", F_all)
    F3 = as_finite_array("F_three", F_three)
    require_integer("n_runs", n_runs, minimum=2)
    require_integer("n_last", n_last, minimum=0)
    require_integer("m_after", m_after, minimum=0)
    rng = np.random.default_rng(seed)
    K = F.shape[0]
    ones = np.ones(K)
    L = np.linalg.solve(F.T @ F, F.T)  # (F'F)^-1 F'
    resid = ones - F @ (L @ ones)  # (I - P) 1
    beta = float(resid @ resid)
    hist = gain_recursion(beta, sigma, sigma0, n_last)
    total = n_last + m_after + 1
    clock_mse = np.empty(total)
    pos_mse = np.empty(total)
    pos_var = np.empty(total)
    A = rng.normal(0.0, sigma0, n_runs)
    tau = np.full(n_runs, tau_start)
    rng_track = np.linspace(-1.0, 1.0, 3)

    def record(n: int, tau_hat: np.ndarray, p_err: np.ndarray) -> None:
        e = tau_hat - tau
        clock_mse[n] = np.mean(e**2)
        sq = np.sum(p_err**2, axis=1)
        pos_mse[n] = np.mean(sq)
        pos_var[n] = np.var(np.sqrt(sq))

    tau_hat = np.zeros(n_runs)
    for n in range(total):
        if n > 0:
            tau = tau + tau_bar + rng.normal(0.0, sigma0, n_runs) + A
        track = 1.0e4 * n * rng_track  # nonrandom aircraft displacement p_n - p*
        if n <= n_last:
            z = tau[:, None] + (F @ track)[None, :] + rng.normal(0.0, sigma, (n_runs, K))
            if n == 0:
                tau_hat = (z @ resid) / beta
            else:
                pred = tau_hat + tau_bar
                tau_hat = pred + hist.gamma[n] * ((z - pred[:, None]) @ resid)
            p_hat = (z - tau_hat[:, None]) @ L.T
        else:
            z = tau[:, None] + (F3 @ track)[None, :] + rng.normal(0.0, sigma, (n_runs, 3))
            tau_hat = tau_hat + tau_bar
            p_hat = np.linalg.solve(F3, (z - tau_hat[:, None]).T).T
        record(n, tau_hat, p_hat - track[None, :])
    return TrackerMonteCarlo(
        clock_mse=clock_mse, position_mse=pos_mse, position_norm_variance=pos_var, n_runs=n_runs
    )
