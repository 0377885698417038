r"""Code tracking under jamming: correlation, effective :math:`C/N_0`, loss of lock, free-space J/S, CEP.

Ideal correlation and early-minus-late discriminator (spacing :math:`d` chips):

.. math::

    \begin{gathered}
    R_c(\tau) = \max(0, 1 - |\tau|),\\
    D(\tau) = R_c(\tau - d/2) - R_c(\tau + d/2).
    \end{gathered}

Effective carrier-to-noise density under a jammer of power ratio :math:`J/S`, for a code
of chip rate :math:`R_c` and spectral-separation factor :math:`Q`
(:math:`Q = 1/(R_c\kappa)`, :math:`\kappa = \int G_s G_j\,df`):

.. math::

    (C/N_0)_{eff} = \Big[\frac{1}{C/N_0} + \frac{J/S}{Q R_c}\Big]^{-1}.

A loop that needs :math:`(C/N_0)_{eff} \ge \gamma` loses lock at
:math:`J/S = Q R_c\,(1/\gamma - 1/(C/N_0))`. Free-space J/S for a jammer of power
:math:`P_J` at distance :math:`d` against a received signal power :math:`S`:
:math:`J/S = P_J G_J (\lambda/4\pi d)^2 / S`. Every 20 dB of anti-jam margin is a factor of
100 in jammer power, or 10 in distance.

The last part is a reduced navigator model for a guided munition: two horizontal channels,
each with position, velocity, tilt, a Markov accelerometer bias, a Markov gyro bias and a
fixed nonorthogonality term, updated once a second by a position fix whose noise follows
the code-tracking variance at the effective :math:`C/N_0` while the code loop is in lock, plus an
unestimated range bias. The Kalman gains depend only on the J/S history, so the Monte
Carlo runs are vectorised: all runs share one covariance recursion.

References
----------
.. [SP] G. T. Schmidt and R. E. Phillips, "INS/GPS Integration Architecture Performance
   Comparisons", NATO RTO-EN-SET-116, Sec. 3.
.. [Kaplan] E. D. Kaplan and C. J. Hegarty (eds.), *Understanding GPS*, 2nd ed., Sec. 6.3
   (effective C/N0 and spectral separation), Eq. 5.81 (DLL thermal noise).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import expm
from scipy.special import sici

from navcore._validate import (
    COUNT,
    NONNEGATIVE,
    POSITIVE,
    Range,
    as_finite_array,
    check_public,
    power_ratio_from_db,
    require_integer,
    require_positive,
)
from navcore.estimation.covariance import biased_filter_error_covariance
from navcore.estimation.kalman import joseph_unchecked
from navcore.trace import implements
from navcore.units import G0

__all__ = [
    "NavigatorErrorModel",
    "RunResult",
    "cep_from_horizontal_errors",
    "cep_relative_sd",
    "code_tracking_sigma_chips",
    "early_minus_late",
    "effective_cn0_dbhz",
    "free_space_js_db",
    "ideal_correlation",
    "impact_rms_m",
    "js_for_effective_cn0",
    "simulate_impact_errors",
    "spectral_separation_q",
]

Array = NDArray[np.float64]


def ideal_correlation(tau_chips: ArrayLike) -> Array | float:
    r"""Ideal code autocorrelation, :math:`1 - |\tau|` inside one chip, 0 outside (SP Sec. 3.0).

    Parameters
    ----------
    tau_chips : array_like
        Code-phase offset, chips.

    Returns
    -------
    float or ndarray
        Normalised correlation (dimensionless).

    Raises
    ------
    ValueError
        If ``tau_chips`` is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 3.0.

    Examples
    --------
    >>> [float(ideal_correlation(x)) for x in (0.0, 0.5, 1.5)]
    [1.0, 0.5, 0.0]
    """
    t = as_finite_array("tau_chips", tau_chips)
    out = np.clip(1.0 - np.abs(t), 0.0, None)
    return float(out) if out.ndim == 0 else out


def early_minus_late(tau_chips: ArrayLike, spacing_chips: float = 0.5) -> Array | float:
    """Early-minus-late discriminator ``R(tau - d/2) - R(tau + d/2)`` for correlator spacing d.

    Parameters
    ----------
    tau_chips : array_like
        Code-phase error, chips.
    spacing_chips : float, default 0.5
        Early-late spacing :math:`d`, chips (``> 0``).

    Returns
    -------
    float or ndarray
        Discriminator output (normalised correlation, dimensionless).

    Raises
    ------
    ValueError
        If ``spacing_chips`` is not positive or ``tau_chips`` is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 3.0 (code tracking).

    Examples
    --------
    >>> [round(float(early_minus_late(x)), 6) for x in (-0.1, 0.0, 0.1)]
    [-0.2, 0.0, 0.2]
    """
    require_positive("spacing_chips", spacing_chips)
    t = as_finite_array("tau_chips", tau_chips)
    out = np.asarray(ideal_correlation(t - spacing_chips / 2)) - np.asarray(
        ideal_correlation(t + spacing_chips / 2)
    )
    return float(out) if np.ndim(out) == 0 else out


def spectral_separation_q(jammer_bandwidth_hz: float, chip_rate_hz: float) -> float:
    r""":math:`Q = 1/(R_c \kappa)` for a flat jammer of the given bandwidth centred on a BPSK signal.

    ``kappa`` integrates the signal's normalised spectrum :math:`T_c \operatorname{sinc}^2(f T_c)` against the
    jammer's flat spectrum 1/B over +-B/2, in closed form: with :math:`x = B T_c / 2`,
    :math:`\int_{-x}^{x} \operatorname{sinc}^2 u \, du = (2/\pi)\,[\operatorname{Si}(2\pi x) -
    \sin^2(\pi x)/(\pi x)]`. A narrow jammer gives Q -> 1; a jammer as wide as the main lobe
    (B = 2 Rc) gives about 2.2, and a much wider one about :math:`B/R_c`.

    Parameters
    ----------
    jammer_bandwidth_hz : float
        Jammer bandwidth, Hz (``> 0``).
    chip_rate_hz : float
        Code chip rate, chips/s (``> 0``).

    Returns
    -------
    float
        Spectral-separation factor (dimensionless).

    Raises
    ------
    ValueError
        If a bandwidth or rate is not positive.

    References
    ----------
    Kaplan & Hegarty, Understanding GPS, Sec. 6.3 (reference of the module), as used in
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 3.1.

    Examples
    --------
    >>> round(spectral_separation_q(1.0, 1.023e6), 3)
    1.0
    >>> round(spectral_separation_q(2.046e6, 1.023e6), 2)
    2.22
    """
    require_positive("jammer_bandwidth_hz", jammer_bandwidth_hz)
    require_positive("chip_rate_hz", chip_rate_hz)
    x = 0.5 * jammer_bandwidth_hz / chip_rate_hz
    if x < 1e-4:  # the closed form cancels to first order: its series, exact to O(x^5)
        frac = 2.0 * x - (2.0 / 9.0) * np.pi**2 * x**3
    else:
        frac = (2.0 / np.pi) * (float(sici(2.0 * np.pi * x)[0]) - np.sin(np.pi * x) ** 2 / (np.pi * x))
    kappa = frac / jammer_bandwidth_hz
    return float(1.0 / (chip_rate_hz * kappa))


@implements("SP Sec. 3.1")
def effective_cn0_dbhz(
    cn0_dbhz: ArrayLike, js_db: ArrayLike, chip_rate_hz: float, q: float = 2.0
) -> Array | float:
    r"""Effective :math:`C/N_0` under jamming: :math:`-10 \log_{10}\left(\frac{1}{C/N_0} + \frac{J/S}{Q
    R_c}\right)`.

    Parameters
    ----------
    cn0_dbhz : array_like
        Unjammed carrier-to-noise density, dB-Hz.
    js_db : array_like
        Jammer-to-signal power ratio, dB.
    chip_rate_hz : float
        Code chip rate :math:`R_c`, chips/s (``> 0``).
    q : float, default 2.0
        Spectral-separation factor (``> 0``).

    Returns
    -------
    float or ndarray
        Effective :math:`C/N_0`, dB-Hz.

    Raises
    ------
    ValueError
        If ``chip_rate_hz`` or ``q`` is not positive or an input is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 3.1 (Kaplan, Understanding GPS, Sec. 6.3).

    Examples
    --------
    >>> round(float(effective_cn0_dbhz(45.0, 40.0, 1.023e6)), 2)
    23.08
    """
    require_positive("chip_rate_hz", chip_rate_hz)
    require_positive("q", q)
    c = as_finite_array("cn0_dbhz", cn0_dbhz)
    j = as_finite_array("js_db", js_db)
    # the sum of the two noise densities in logarithms, so that no power of ten overflows
    ln10 = np.log(10.0)
    noise = np.logaddexp(-c / 10.0 * ln10, (j / 10.0 - np.log10(q * chip_rate_hz)) * ln10)
    out = -10.0 * noise / ln10
    return float(out) if out.ndim == 0 else out


def js_for_effective_cn0(
    cn0_dbhz: float, threshold_dbhz: float, chip_rate_hz: float, q: float = 2.0
) -> float:
    """J/S at which the effective :math:`C/N_0` falls to ``threshold_dbhz`` (loss of lock).

    Parameters
    ----------
    cn0_dbhz : float
        Unjammed carrier-to-noise density, dB-Hz.
    threshold_dbhz : float
        Threshold, dB-Hz (below ``cn0_dbhz``).
    chip_rate_hz : float
        Code chip rate, chips/s (``> 0``).
    q : float, default 2.0
        Spectral-separation factor (``> 0``).

    Returns
    -------
    float
        Jammer-to-signal ratio, dB.

    Raises
    ------
    ValueError
        If ``threshold_dbhz`` is not below ``cn0_dbhz`` or ``chip_rate_hz`` or ``q`` is not
        positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 3.1 (the inverse of :func:`effective_cn0_dbhz`).

    Examples
    --------
    >>> js = js_for_effective_cn0(45.0, 28.0, 1.023e6)
    >>> round(js, 2), round(float(effective_cn0_dbhz(45.0, js, 1.023e6)), 9)
    (35.02, 28.0)
    """
    require_positive("chip_rate_hz", chip_rate_hz)
    require_positive("q", q)
    if not threshold_dbhz < cn0_dbhz:
        raise ValueError(f"threshold_dbhz must be below cn0_dbhz ({cn0_dbhz}), got {threshold_dbhz}")
    return 10.0 * math.log10(
        q * chip_rate_hz * (10.0 ** (-threshold_dbhz / 10.0) - 10.0 ** (-cn0_dbhz / 10.0))
    )


@implements("SP Sec. 3.3")
def free_space_js_db(
    jammer_power_w: ArrayLike,
    distance_m: ArrayLike,
    wavelength_m: float,
    signal_power_dbw: float,
    jammer_gain_db: float = 0.0,
) -> Array | float:
    r"""Free-space J/S: :math:`P_J + G_J - 20 \log_{10}(4 \pi d / \lambda) - S`.

    Parameters
    ----------
    jammer_power_w : array_like
        Jammer transmit power, W (``> 0``).
    distance_m : array_like
        Jammer-to-receiver distance, m (``> 0``).
    wavelength_m : float
        Wavelength, m (``> 0``).
    signal_power_dbw : float
        Received signal power, dBW.
    jammer_gain_db : float, default 0.0
        Jammer antenna gain plus receive gain towards it, dB.

    Returns
    -------
    float or ndarray
        Jammer-to-signal ratio, dB.

    Raises
    ------
    ValueError
        If a power, distance or the wavelength is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 3.3.

    Examples
    --------
    >>> round(float(free_space_js_db(1.0, 1.0e4, 0.19, -160.0)), 2)
    43.59
    """
    p = require_positive("jammer_power_w", as_finite_array("jammer_power_w", jammer_power_w))
    d = require_positive("distance_m", as_finite_array("distance_m", distance_m))
    require_positive("wavelength_m", wavelength_m)
    out = (
        10.0 * np.log10(p)
        + jammer_gain_db
        - 20.0 * np.log10(4.0 * np.pi * d / wavelength_m)
        - signal_power_dbw
    )
    return float(out) if np.ndim(out) == 0 else out


def code_tracking_sigma_chips(
    cn0_dbhz: ArrayLike, spacing_chips: float = 0.5, integration_s: float = 1.0, coherent_s: float = 0.02
) -> Array | float:
    r"""1-:math:`\sigma` code-phase error (chips) of a noncoherent early-minus-late power DLL.

    .. math::

        \begin{aligned}
        \sigma^2 &= \frac{B_n d}{2\,C/N_0}\Big[1 + \frac{2}{(2-d)\,(C/N_0)\,T_c}\Big]\\
        &= \frac{d}{4\,(C/N_0)\,T}\Big[1 + \frac{2}{(2-d)\,(C/N_0)\,T_c}\Big]
        \ \text{chips}^2
        \end{aligned}

    (Kaplan Eq. 5.81, infinite front-end bandwidth, with :math:`B_n = 1/(2T)`, the noise
    bandwidth of an average over the measurement interval :math:`T`).

    Derivation (unit chip, triangle correlation): the complex correlators over one coherent
    interval :math:`T_c` are :math:`E = a R(\tau - d/2) + n_E`, :math:`L = a R(\tau + d/2) + n_L`
    with :math:`a^2/\sigma_c^2 = (C/N_0) T_c` (:math:`\sigma_c^2` the complex noise variance
    of each) and noise correlation :math:`1 - d`. At :math:`\tau = 0`,
    :math:`D = |E|^2 - |L|^2 = 2\,\mathrm{Re}(S^*(n_E - n_L)) + |n_E|^2 - |n_L|^2` with
    :math:`S = a(1 - d/2)`, so :math:`\mathrm{var}\,D = 4|S|^2\sigma_c^2 d
    + 2\sigma_c^4 d(2-d)`; the gain is :math:`\partial D/\partial\tau = 4a^2(1-d/2)`. Their
    ratio is :math:`\frac{d}{4 (C/N_0) T_c}[1 + \frac{2}{(2-d)(C/N_0)T_c}]`, and averaging
    :math:`T/T_c` independent intervals divides it by :math:`T/T_c`. A simulation of sampled
    correlators confirms the formula.

    Parameters
    ----------
    cn0_dbhz : array_like
        Carrier-to-noise density (dB-Hz).
    spacing_chips : float
        Early-late correlator spacing :math:`d` (chips), ``0 < d < 2``.
    integration_s : float
        Measurement (averaging) interval :math:`T` (s); :math:`B_n = 1/(2T)`.
    coherent_s : float
        Coherent integration time :math:`T_c` (s) of each correlator output.

    Returns
    -------
    float or ndarray
        Code-phase error standard deviation (chips).

    Raises
    ------
    ValueError
        If ``spacing_chips``, ``integration_s`` or ``coherent_s`` is not positive or a :math:`C/N_0` is
        not finite.

    Examples
    --------
    >>> round(float(code_tracking_sigma_chips(45.0)), 5)
    0.00199
    """
    require_positive("spacing_chips", spacing_chips)
    require_positive("integration_s", integration_s)
    require_positive("coherent_s", coherent_s)
    cn0 = power_ratio_from_db("cn0_dbhz", cn0_dbhz)
    var = (
        spacing_chips / (4.0 * cn0 * integration_s) * (1.0 + 2.0 / ((2.0 - spacing_chips) * cn0 * coherent_s))
    )
    out = np.sqrt(var)
    return float(out) if out.ndim == 0 else out


@implements("SP Sec. 3.3")
def cep_from_horizontal_errors(errors_m: ArrayLike) -> float:
    """CEP from horizontal error samples: 1.1774 x the per-axis rms (circular normal).

    Parameters
    ----------
    errors_m : (N, 2) array
        Horizontal errors (north, east), m.

    Returns
    -------
    float
        Circular error probable, m.

    Raises
    ------
    ValueError
        If ``errors_m`` is not an ``(N, 2)`` finite array.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 3.3 (impact CEP).

    Examples
    --------
    >>> round(cep_from_horizontal_errors([[1.0, 1.0], [-1.0, -1.0]]), 4)
    1.1774
    """
    e = as_finite_array("errors_m", errors_m)
    if e.ndim != 2 or e.shape[1] != 2:
        raise ValueError(f"errors_m must have shape (N, 2), got {e.shape}")
    return float(math.sqrt(2.0 * math.log(2.0)) * math.sqrt(np.mean(e**2)))


def cep_relative_sd(runs: int) -> float:
    r"""Relative standard error of a CEP taken by :func:`cep_from_horizontal_errors` from ``runs`` runs.

    The CEP is 1.1774 times the rms of :math:`n = 2 \cdot` ``runs`` zero-mean Gaussian axis
    samples; the mean square has relative variance :math:`2/n`, so its square root, and the CEP
    with it, has relative standard error :math:`\tfrac{1}{2}\sqrt{2/n} = 1/\sqrt{4\,\mathrm{runs}}`
    (first order in :math:`1/n`).

    Parameters
    ----------
    runs : int
        Monte Carlo runs, each giving one horizontal (two-axis) error (``>= 1``).

    Returns
    -------
    float
        Relative standard error of the CEP (a fraction of it).

    Raises
    ------
    ValueError
        If ``runs`` is not a positive integer.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 3.3
    (the CEP of 25 runs per jammer power of Figs. 3.6-3.8).

    Examples
    --------
    >>> cep_relative_sd(25)
    0.1
    """
    return 1.0 / math.sqrt(4.0 * runs)


@dataclass(frozen=True)
class NavigatorErrorModel:
    r"""One horizontal channel of the reduced INS/GPS navigator (SI units, 1-:math:`\sigma`).

    Attributes
    ----------
    accel_bias, accel_tau_s : Markov accelerometer bias stability (m/s², 1 sigma,
        stationary) and its correlation time (s).
    gyro_bias, gyro_tau_s : Markov gyro bias stability (rad/s, 1 sigma, stationary) and its
        correlation time (s).
    accel_vrw : velocity random walk, m/s/sqrt(s).
    gyro_arw : angle random walk, rad/sqrt(s).
    nonorthogonality : fixed axis nonorthogonality (rad); times g it is a constant bias.
    init_pos, init_vel : initial position (m) and velocity (m/s) errors per axis.
    init_tilt : initial tilt (rad) per axis.
    range_bias : unestimated satellite range bias (m) per satellite.
    hdop_axis : position-per-range factor of the geometry, per horizontal axis.
    """

    accel_bias: float
    accel_tau_s: float
    gyro_bias: float
    gyro_tau_s: float
    accel_vrw: float
    gyro_arw: float
    nonorthogonality: float
    init_pos: float
    init_vel: float
    init_tilt: float
    range_bias: float
    hdop_axis: float


@dataclass(frozen=True)
class RunResult:
    r"""Monte Carlo output: impact errors (runs, 2), final filter :math:`\sigma` per axis, lock history.

    Attributes
    ----------
    impact_errors_m : (runs, 2) ndarray
        Horizontal impact errors (north, east), m.
    filter_sigma_m : float
        The filter's final 1-:math:`\sigma` per axis, m.
    locked : (N,) bool ndarray
        Code lock at each step.
    seed : int
        Seed of the run.
    """

    impact_errors_m: Array
    filter_sigma_m: float
    locked: NDArray[np.bool_]
    seed: int


def _initial_covariance(m: NavigatorErrorModel) -> Array:
    """The reduced navigator's a-priori covariance: its six initial sigmas, squared, on the diagonal."""
    return np.diag(
        [m.init_pos**2, m.init_vel**2, m.init_tilt**2, m.accel_bias**2, m.gyro_bias**2, m.nonorthogonality**2]
    )


def _channel_matrices(m: NavigatorErrorModel, dt: float) -> tuple[Array, Array]:
    """Discrete transition and process noise of [pos, vel, tilt, b_a, b_g, n] (first order in dt)."""
    F = np.zeros((6, 6))
    F[0, 1] = 1.0
    F[1, 2] = G0
    F[1, 3] = 1.0
    F[1, 5] = G0
    F[2, 4] = 1.0
    F[3, 3] = -1.0 / m.accel_tau_s
    F[4, 4] = -1.0 / m.gyro_tau_s
    Phi = expm(F * dt)
    Q = np.zeros((6, 6))
    Q[1, 1] = m.accel_vrw**2 * dt
    Q[2, 2] = m.gyro_arw**2 * dt
    Q[3, 3] = m.accel_bias**2 * (1.0 - math.exp(-2.0 * dt / m.accel_tau_s))
    Q[4, 4] = m.gyro_bias**2 * (1.0 - math.exp(-2.0 * dt / m.gyro_tau_s))
    return Phi, Q


@implements("SP Sec. 3.3")
def simulate_impact_errors(
    model: NavigatorErrorModel,
    fix_sigma_m: ArrayLike,
    *,
    runs: int,
    seed: int = 0,
    dt: float = 1.0,
) -> RunResult:
    r"""Monte Carlo of the reduced navigator along a fix-noise history (NaN where unlocked).

    Parameters
    ----------
    model : NavigatorErrorModel
        Sensor, initial and geometry errors of one horizontal channel (SI, 1-:math:`\sigma`).
    fix_sigma_m : array_like
        Per-axis position-fix noise at each 1-s step (m); NaN or inf marks steps with no fix
        (code loop out of lock: free inertial).
    runs : int
        Monte Carlo runs; each run has two independent horizontal channels.
    seed : int
        Seed of ``numpy.random.default_rng`` (recorded in the result).
    dt : float
        Step (s) of the fix-noise history.

    Returns
    -------
    RunResult
        Horizontal impact errors per run ``(runs, 2)`` (m), the filter's final 1-:math:`\sigma` per
        axis (m), the lock history and the seed.

    Raises
    ------
    ValueError
        If ``runs`` is not a positive integer.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 3.3 (impact accuracy under jamming).

    Examples
    --------
    >>> import numpy as np
    >>> m = NavigatorErrorModel(accel_bias=1e-2, accel_tau_s=300.0, gyro_bias=5e-5, gyro_tau_s=300.0,
    ...     accel_vrw=1e-4, gyro_arw=1e-5, nonorthogonality=1e-3, init_pos=10.0, init_vel=0.2,
    ...     init_tilt=1e-3, range_bias=0.0, hdop_axis=1.0)
    >>> res = simulate_impact_errors(m, np.full(60, 5.0), runs=200, seed=1)
    >>> res.impact_errors_m.shape, bool(res.locked.all()), res.seed
    ((200, 2), True, 1)
    """
    runs = require_integer("runs", runs, minimum=1)
    sig = np.asarray(fix_sigma_m, dtype=float)
    locked = np.isfinite(sig)
    Phi, Q = _channel_matrices(model, dt)
    rng = np.random.default_rng(seed)
    n = 2 * runs
    P0 = _initial_covariance(model)
    x = rng.standard_normal((n, 6)) * np.sqrt(np.diag(P0))  # truth errors
    xh = np.zeros((n, 6))  # filter estimates
    bias = model.hdop_axis * model.range_bias * rng.standard_normal(n)  # unestimated, per channel
    P = P0.copy()
    Lq = np.linalg.cholesky(Q + 1e-30 * np.eye(6))
    H = np.zeros((1, 6))
    H[0, 0] = 1.0
    for k in range(sig.size):
        x = x @ Phi.T + rng.standard_normal((n, 6)) @ Lq.T
        xh = xh @ Phi.T
        P = Phi @ P @ Phi.T + Q
        if locked[k]:
            r = sig[k] ** 2
            z = x[:, 0] + bias + sig[k] * rng.standard_normal(n)
            S = P[0, 0] + r
            K = P[:, 0] / S
            xh = xh + np.outer(z - xh[:, 0], K)
            P = joseph_unchecked(P, K[:, None], H, r, symmetric=False)
    err = (x[:, 0] - xh[:, 0]).reshape(runs, 2)
    return RunResult(err, float(math.sqrt(P[0, 0])), locked, seed)


@implements("SP Sec. 3.3")
def impact_rms_m(model: NavigatorErrorModel, fix_sigma_m: ArrayLike) -> Array:
    r"""Exact per-axis rms impact error of the reduced navigator, per fix-noise history.

    The same linear model as :func:`simulate_impact_errors` (1-s steps), evaluated without
    sampling: the filter's gains follow its own covariance recursion, and the true error
    :math:`e = x - \hat x` together with the unestimated range bias :math:`b` (standard
    deviation ``hdop_axis * range_bias``) obeys :math:`e^+ = (I - K H)(\Phi e + w) - K (b + v)`,
    whose 7x7 covariance is propagated exactly
    (:func:`navcore.estimation.covariance.biased_filter_error_covariance`). The error is
    Gaussian, so the CEP is 1.1774 times the per-axis rms. Rows (one per jammer power, say) are
    propagated together.

    Parameters
    ----------
    model : NavigatorErrorModel
        Sensor, initial and geometry errors of one horizontal channel (SI, 1-:math:`\sigma`).
    fix_sigma_m : (N,) or (B, N) array_like
        Per-axis position-fix noise at each 1-s step (m); NaN marks steps with no fix (code
        loop out of lock: free inertial).

    Returns
    -------
    (B,) ndarray
        Per-axis rms of the true position error after the last step, m, one per row of
        ``fix_sigma_m`` (``B = 1`` for a 1-D history).

    Raises
    ------
    ValueError
        If ``fix_sigma_m`` is not a (N,) or (B, N) array of standard deviations >= 0 or NaN.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 3.3 (impact accuracy under jamming, Figs. 3.6-3.8); Gelb, *Applied Optimal
    Estimation* (1974), Sec. 7.2 (the error covariance of a suboptimal filter).

    Examples
    --------
    >>> import numpy as np
    >>> m = NavigatorErrorModel(accel_bias=1e-2, accel_tau_s=300.0, gyro_bias=5e-5, gyro_tau_s=300.0,
    ...     accel_vrw=1e-4, gyro_arw=1e-5, nonorthogonality=1e-3, init_pos=10.0, init_vel=0.2,
    ...     init_tilt=1e-3, range_bias=2.0, hdop_axis=1.0)
    >>> rms = impact_rms_m(m, np.full((2, 60), 5.0))
    >>> rms.shape, bool(rms[0] == rms[1]), bool(rms[0] > 2.0)
    ((2,), True, True)
    """
    sig = np.asarray(fix_sigma_m, dtype=float)
    if sig.ndim not in (1, 2) or np.isinf(sig).any() or (sig < 0).any():
        raise ValueError("fix_sigma_m must be a (N,) or (B, N) array of standard deviations >= 0 or NaN")
    Phi, Q = _channel_matrices(model, 1.0)
    P0 = _initial_covariance(model)
    h = np.eye(6)[0]  # the fix measures the position error
    Cov = biased_filter_error_covariance(Phi, Q, P0, h, sig, model.hdop_axis * model.range_bias)
    return np.sqrt(Cov[:, 0, 0])


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "runs": COUNT,
        "dt": POSITIVE,
        "chip_rate_hz": POSITIVE,
        "coherent_s": POSITIVE,
        "integration_s": POSITIVE,
        "jammer_bandwidth_hz": POSITIVE,
        "spacing_chips": Range(0.0, 2.0, low_open=True, high_open=True),
        "q": POSITIVE,
        "wavelength_m": POSITIVE,
        "filter_sigma_m": NONNEGATIVE,
        "hdop_axis": POSITIVE,
        "accel_tau_s": POSITIVE,
        "gyro_tau_s": POSITIVE,
        "distance_m": POSITIVE,
        "jammer_power_w": NONNEGATIVE,
    },
    simulate_impact_errors={"skip": ("fix_sigma_m",)},
    impact_rms_m={"skip": ("fix_sigma_m",)},
)
