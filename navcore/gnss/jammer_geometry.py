r"""A ground jammer seen from a moving receiver: effective :math:`C/N_0`, lock thresholds, crossing times.

The receiver (antenna gain :math:`G_s(e)` towards a satellite at elevation :math:`e`,
:math:`G_{rj}` towards the jammer) receives the satellite's carrier power
:math:`C = S + G_s(e)` and, from a jammer of effective radiated power :math:`P_{ERP}` at
slant range :math:`d`, the power (free space, wavelength :math:`\lambda`)

.. math::

    J = P_{ERP} + G_{rj} - 20\log_{10}\frac{4\pi d}{\lambda}\quad\text{(dBW)}.

A jammer spread over the band adds the density :math:`J/(Q R_c)` to the thermal
:math:`N_0` (chip rate :math:`R_c`, spectral-separation factor :math:`Q`), so the effective
carrier-to-noise density is

.. math::

    (C/N_0)_{eff} = \frac{C}{N_0 + J/(Q R_c)} .

It falls below a threshold :math:`\gamma` when :math:`J > J^* = Q R_c (C/\gamma - N_0)`, i.e.
inside the *threshold range* :math:`d^* = \frac{\lambda}{4\pi}10^{(P_{ERP} + G_{rj} - J^*)/20}`.
Along a straight, level track at speed :math:`v` whose slant range at closest approach
(time :math:`t_{ca}`) is :math:`d_{min}`,
:math:`d(t)^2 = d_{min}^2 + v^2 (t - t_{ca})^2`, so the crossings solve a quadratic in
:math:`t`:

.. math::

    t_{in,out} = t_{ca} \mp \frac{\sqrt{d^{*2} - d_{min}^2}}{v}.

Loss of lock and reacquisition use different thresholds (hysteresis): a loop locked is lost
when :math:`(C/N_0)_{eff}` drops below its loss threshold and is back only when it rises
above its (higher) reacquisition threshold. A carrier loop's loss threshold is the larger of
a stated :math:`C/N_0` floor and the :math:`C/N_0` at which :math:`k` times its thermal phase jitter
(PLL, noise bandwidth :math:`B_n`, coherent integration :math:`T`)

.. math::

    \sigma_\phi^2 = \frac{B_n}{C/N_0}\Big(1 + \frac{1}{2T\,C/N_0}\Big)\ \text{rad}^2

reaches the allowed phase error :math:`\phi_{max}`; that :math:`C/N_0` is the positive root of
:math:`(\phi_{max}/k)^2 x^2 - B_n x - B_n/(2T) = 0`.

The allowed phase error depends on the loop's discriminator (Kaplan Sec. 5.6.2, rule of thumb
:math:`3\sigma \le` a quarter of the discriminator's pull-in range): a *pure PLL*
(``atan2``, pull-in :math:`\pm 180^\circ`, only for a data-free pilot or data-wiped signal)
keeps :math:`3\sigma_\phi \le 90^\circ`; a *Costas loop* (``atan(Q/I)``, insensitive to the
data bits, pull-in :math:`\pm 90^\circ`), which a data-modulated signal such as L1 C/A or
P(Y) needs, keeps :math:`3\sigma_\phi \le 45^\circ`. At :math:`B_n = 5.83` Hz and
:math:`T = 20` ms the thresholds are 15.6 and 20.2 dB-Hz. The functions below take the loop
type explicitly (``loop="costas"`` by default). SP Sec. 2.5 prints "carrier phase error
exceeded 90 deg", the pure-PLL rule, and ``navcore.papers.sp_flyby`` reproduces that
printed value (``max_phase_error_deg=90``); a Costas loop would put the loosely coupled
5.83 Hz loop's jitter threshold (20.2 dB-Hz) above the printed 19 dB-Hz floor.

References
----------
.. [SP] G. T. Schmidt and R. E. Phillips, "INS/GPS Integration Architecture Performance
   Comparisons", NATO RTO-EN-SET-116, Sec. 2.5 (thresholds) and 2.6.2 (jammer flyby).
.. [Kaplan] E. D. Kaplan and C. J. Hegarty (eds.), *Understanding GPS*, 2nd ed., Sec. 5.6
   (PLL thermal jitter) and Sec. 6.3 (effective C/N0 under interference).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from navcore._validate import (
    NONNEGATIVE,
    POSITIVE,
    Range,
    as_finite_array,
    check_public,
    power_ratio_from_db,
    require_nonnegative,
    require_positive,
)
from navcore.trace import implements

__all__ = [
    "LOOP_PHASE_LIMIT_DEG",
    "LockThresholds",
    "carrier_loss_threshold_dbhz",
    "dll_thermal_jitter_chips",
    "effective_cn0_with_jammer_dbhz",
    "elevation_gain_dbi",
    "free_space_loss_db",
    "hysteresis_from_conditions",
    "hysteresis_lock",
    "jammed_cn0_dbhz",
    "jammer_power_at_threshold_dbw",
    "outage_intervals",
    "pll_jitter_threshold_dbhz",
    "pll_thermal_jitter_deg",
    "received_jammer_power_dbw",
    "slant_range_m",
    "straight_track_crossing_times",
    "straight_track_range_m",
    "threshold_range_m",
]

Array = NDArray[np.float64]


def _out(x: Array) -> Array | float:
    return float(x) if np.ndim(x) == 0 else x


def straight_track_range_m(
    t_s: ArrayLike, speed_mps: float, closest_range_m: float, t_closest_s: float = 0.0
) -> Array | float:
    """Slant range along a straight, level track: ``sqrt(d_min^2 + v^2 (t - t_ca)^2)``.

    Parameters
    ----------
    t_s : array_like
        Times, s.
    speed_mps : float
        Ground speed, m/s (``> 0``).
    closest_range_m : float
        Slant range at closest approach, m (``>= 0``; combines altitude and cross-track offset).
    t_closest_s : float, default 0.0
        Time of closest approach, s.

    Returns
    -------
    float or ndarray
        Slant range, m.

    Raises
    ------
    ValueError
        If ``speed_mps`` is not positive or ``closest_range_m`` is negative.

    Examples
    --------
    >>> float(straight_track_range_m(10.0, 300.0, 4000.0))
    5000.0
    """
    require_positive("speed_mps", speed_mps)
    require_nonnegative("closest_range_m", closest_range_m)
    t = as_finite_array("t_s", t_s)
    return _out(np.hypot(closest_range_m, speed_mps * (t - t_closest_s)))


def slant_range_m(position_ned_m: ArrayLike, emitter_ned_m: ArrayLike) -> Array | float:
    """Distance from positions ``(..., 3)`` to an emitter at ``(3,)`` (same local frame).

    Parameters
    ----------
    position_ned_m : (..., 3) array
        Receiver positions, m.
    emitter_ned_m : (3,) array
        Emitter position, m.

    Returns
    -------
    float or ndarray
        Slant range, m.

    Raises
    ------
    ValueError
        If the shapes are wrong or a coordinate is not finite.

    Examples
    --------
    >>> float(slant_range_m([3000.0, 0.0, -4000.0], [0.0, 0.0, 0.0]))
    5000.0
    """
    p = as_finite_array("position_ned_m", position_ned_m)
    e = as_finite_array("emitter_ned_m", emitter_ned_m)
    if p.shape[-1:] != (3,):
        raise ValueError(f"position_ned_m must have shape (..., 3), got {p.shape}")
    if e.shape != (3,):
        raise ValueError(f"emitter_ned_m must have shape (3,), got {e.shape}")
    return _out(np.linalg.norm(p - e, axis=-1))


def free_space_loss_db(range_m: ArrayLike, wavelength_m: float) -> Array | float:
    r"""Free-space path loss :math:`20 \log_{10}(4 \pi d / \lambda)`.

    Parameters
    ----------
    range_m : array_like
        Distance, m (``> 0``).
    wavelength_m : float
        Wavelength, m (``> 0``).

    Returns
    -------
    float or ndarray
        Loss, dB.

    Raises
    ------
    ValueError
        If a range or the wavelength is not positive.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(free_space_loss_db(1.0 / (4 * np.pi), 1.0)), 12)
    0.0
    """
    require_positive("wavelength_m", wavelength_m)
    d = require_positive("range_m", as_finite_array("range_m", range_m))
    return _out(20.0 * np.log10(4.0 * np.pi * d / wavelength_m))


def received_jammer_power_dbw(
    erp_dbw: float, range_m: ArrayLike, wavelength_m: float, rx_gain_dbi: float = 0.0
) -> Array | float:
    r"""Jammer power at the receiver: :math:`\mathrm{ERP} + G_{rj} - 20 \log_{10}(4 \pi d / \lambda)`.

    Parameters
    ----------
    erp_dbw : float
        Effective radiated power of the jammer, dBW.
    range_m : array_like
        Slant range, m (``> 0``).
    wavelength_m : float
        Wavelength, m (``> 0``).
    rx_gain_dbi : float, default 0.0
        Receive-antenna gain towards the jammer, dBi.

    Returns
    -------
    float or ndarray
        Received power, dBW.

    Raises
    ------
    ValueError
        If a range or the wavelength is not positive or a power is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.6.2.

    Examples
    --------
    >>> round(float(received_jammer_power_dbw(10.0, 1.0e4, 0.19)), 2)
    -106.41
    """
    as_finite_array("erp_dbw", erp_dbw)
    as_finite_array("rx_gain_dbi", rx_gain_dbi)
    return _out(erp_dbw + rx_gain_dbi - np.asarray(free_space_loss_db(range_m, wavelength_m)))


@implements("SP Sec. 2.6.2")
def effective_cn0_with_jammer_dbhz(
    carrier_dbw: ArrayLike,
    jammer_dbw: ArrayLike,
    n0_dbw_hz: float,
    chip_rate_hz: float,
    q: float = 2.0,
) -> Array | float:
    r"""Effective :math:`C/N_0`: :math:`C - 10 \log_{10}(N_0 + J/(Q R_c))` (arrays broadcast).

    ``carrier_dbw`` of shape ``(n_sat,)`` and ``jammer_dbw`` of shape ``(N, 1)`` give
    ``(N, n_sat)``; ``jammer_dbw = -inf`` is not allowed (use a very low power instead).

    Parameters
    ----------
    carrier_dbw : array_like
        Received carrier power, dBW.
    jammer_dbw : array_like
        Received jammer power, dBW (finite).
    n0_dbw_hz : float
        Thermal noise density, dBW/Hz.
    chip_rate_hz : float
        Code chip rate :math:`R_c`, chips/s (``> 0``).
    q : float, default 2.0
        Spectral-separation factor :math:`Q` (dimensionless, ``> 0``).

    Returns
    -------
    float or ndarray
        Effective carrier-to-noise density, dB-Hz.

    Raises
    ------
    ValueError
        If ``chip_rate_hz`` or ``q`` is not positive or a power is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6.2 (jammer to signal).

    Examples
    --------
    >>> round(float(effective_cn0_with_jammer_dbhz(-160.0, -300.0, -204.0, 1e6)), 9)
    44.0
    """
    require_positive("chip_rate_hz", chip_rate_hz)
    require_positive("q", q)
    as_finite_array("n0_dbw_hz", n0_dbw_hz)
    c = as_finite_array("carrier_dbw", carrier_dbw)
    j = as_finite_array("jammer_dbw", jammer_dbw)
    dens = np.logaddexp(n0_dbw_hz * _LN10_10, j * _LN10_10 - math.log(q * chip_rate_hz)) / _LN10_10
    return _out(c - dens)


_LN10_10 = math.log(10.0) / 10.0


def jammer_power_at_threshold_dbw(
    carrier_dbw: ArrayLike, threshold_dbhz: ArrayLike, n0_dbw_hz: float, chip_rate_hz: float, q: float = 2.0
) -> Array | float:
    r"""Received jammer power that brings the effective :math:`C/N_0` down to ``threshold_dbhz``.

    :math:`J^* = Q R_c (C/\gamma - N_0)`.

    Parameters
    ----------
    carrier_dbw : array_like
        Received carrier power, dBW.
    threshold_dbhz : array_like
        :math:`C/N_0` threshold :math:`\gamma`, dB-Hz.
    n0_dbw_hz : float
        Thermal noise density, dBW/Hz.
    chip_rate_hz : float
        Code chip rate, chips/s (``> 0``).
    q : float, default 2.0
        Spectral-separation factor (``> 0``).

    Returns
    -------
    float or ndarray
        Jammer power :math:`J^*`, dBW.

    Raises
    ------
    ValueError
        If a threshold is not below the unjammed :math:`C/N_0` (the loop would never be in lock), or
        ``chip_rate_hz`` or ``q`` is not positive.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.6.2.

    Examples
    --------
    >>> j = float(jammer_power_at_threshold_dbw(-160.0, 28.0, -204.0, 1.023e6))
    >>> round(float(effective_cn0_with_jammer_dbhz(-160.0, j, -204.0, 1.023e6)), 9)
    28.0
    """
    require_positive("chip_rate_hz", chip_rate_hz)
    require_positive("q", q)
    c = as_finite_array("carrier_dbw", carrier_dbw)
    g = as_finite_array("threshold_dbhz", threshold_dbhz)
    margin = c - g - n0_dbw_hz  # unjammed C/N0 minus threshold, dB
    if np.any(margin <= 0):
        raise ValueError("threshold_dbhz must be below the unjammed C/N0 (carrier_dbw - n0_dbw_hz)")
    # Q Rc (C/gamma - N0) = Q Rc N0 (10^(margin/10) - 1), in the log domain
    out = 10.0 * np.log10(q * chip_rate_hz) + n0_dbw_hz + 10.0 * np.log10(np.expm1(margin * _LN10_10))
    return _out(out)


def threshold_range_m(
    erp_dbw: float, jammer_threshold_dbw: ArrayLike, wavelength_m: float, rx_gain_dbi: float = 0.0
) -> Array | float:
    """Range at which the received jammer power equals ``jammer_threshold_dbw`` (free space).

    Parameters
    ----------
    erp_dbw : float
        Effective radiated power of the jammer, dBW.
    jammer_threshold_dbw : array_like
        Received jammer power at the threshold, dBW.
    wavelength_m : float
        Wavelength, m (``> 0``).
    rx_gain_dbi : float, default 0.0
        Receive-antenna gain towards the jammer, dBi.

    Returns
    -------
    float or ndarray
        Threshold range :math:`d^*`, m.

    Raises
    ------
    ValueError
        If ``wavelength_m`` is not positive or a power is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons", Sec. 2.6.2.

    Examples
    --------
    >>> r = float(threshold_range_m(10.0, -100.0, 0.19))
    >>> round(float(received_jammer_power_dbw(10.0, r, 0.19)), 9)
    -100.0
    """
    require_positive("wavelength_m", wavelength_m)
    jt = as_finite_array("jammer_threshold_dbw", jammer_threshold_dbw)
    decades = (erp_dbw + rx_gain_dbi - jt) / 20.0 + np.log10(wavelength_m / (4.0 * np.pi))
    if np.any(decades > 300.0):
        raise ValueError(
            "threshold_range_m: erp_dbw + rx_gain_dbi - jammer_threshold_dbw is so large that the "
            f"range exceeds 1e300 m (erp_dbw={erp_dbw!r}, rx_gain_dbi={rx_gain_dbi!r})"
        )
    return _out(wavelength_m / (4.0 * np.pi) * 10.0 ** ((erp_dbw + rx_gain_dbi - jt) / 20.0))


@implements("SP Sec. 2.6.2")
def straight_track_crossing_times(
    threshold_range: ArrayLike, closest_range_m: float, speed_mps: float, t_closest_s: float = 0.0
) -> tuple[Array | float, Array | float]:
    """Times at which a straight track enters and leaves the sphere of radius ``threshold_range``.

    The roots of :math:`d_{min}^2 + v^2 (t - t_{ca})^2 = d^{*2}`; NaN where the track never comes
    that close (:math:`d^* < d_{min}`).

    Parameters
    ----------
    threshold_range : array_like
        Threshold range :math:`d^*`, m (``>= 0``).
    closest_range_m : float
        Slant range at closest approach, m (``>= 0``).
    speed_mps : float
        Ground speed, m/s (``> 0``).
    t_closest_s : float, default 0.0
        Time of closest approach, s.

    Returns
    -------
    t_in : float or ndarray
        Entry time, s (NaN if never inside).
    t_out : float or ndarray
        Exit time, s (NaN if never inside).

    Raises
    ------
    ValueError
        If ``speed_mps`` is not positive or a range is negative.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.6.2 (the jammer fly-by).

    Examples
    --------
    >>> t_in, t_out = straight_track_crossing_times(5000.0, 4000.0, 300.0)
    >>> float(t_in), float(t_out)
    (-10.0, 10.0)
    """
    require_positive("speed_mps", speed_mps)
    require_nonnegative("closest_range_m", closest_range_m)
    r = require_nonnegative("threshold_range", as_finite_array("threshold_range", threshold_range))
    disc = r**2 - closest_range_m**2
    half = np.where(disc >= 0, np.sqrt(np.clip(disc, 0.0, None)), np.nan) / speed_mps
    return _out(t_closest_s - half), _out(t_closest_s + half)


def elevation_gain_dbi(
    elevation_rad: ArrayLike, zenith_dbi: float, horizon_dbi: float, exponent: float = 1.0
) -> Array | float:
    r"""Antenna gain of a fixed upward-looking antenna against elevation.

    :math:`G(e) = G_z - (G_z - G_h)\,\big((90^\circ - e)/90^\circ\big)^p`: the zenith gain
    ``zenith_dbi`` at 90 deg, the horizon gain ``horizon_dbi`` at 0 deg, and a roll-off whose
    shape is set by ``exponent`` ``p`` (``p = 1``: linear in elevation; ``p > 1``: the gain
    holds up at mid elevations and falls near the horizon, as a patch's does). Elevations
    are clipped to [0, 90] deg.

    Parameters
    ----------
    elevation_rad : array_like
        Elevation, rad.
    zenith_dbi : float
        Gain at 90 deg, dBi.
    horizon_dbi : float
        Gain at 0 deg, dBi.
    exponent : float, default 1.0
        Shape of the roll-off (``> 0``).

    Returns
    -------
    float or ndarray
        Gain, dBi.

    Raises
    ------
    ValueError
        If an elevation is not finite or ``exponent`` is not positive.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(elevation_gain_dbi(np.pi / 4, 3.0, -5.0)), 6)
    -1.0
    >>> round(float(elevation_gain_dbi(np.pi / 4, 3.0, -5.0, exponent=2.0)), 6)
    1.0
    """
    require_positive("exponent", exponent)
    e = np.clip(as_finite_array("elevation_rad", elevation_rad), 0.0, np.pi / 2)
    return _out(zenith_dbi - (zenith_dbi - horizon_dbi) * (1.0 - e / (np.pi / 2)) ** exponent)


@implements("SP Sec. 2.6.2")
def jammed_cn0_dbhz(cn0_dbhz: ArrayLike, jammer_to_noise_db: ArrayLike) -> Array | float:
    r"""Effective :math:`C/N_0` under a jammer given as its density relative to the thermal noise.

    With :math:`x = J/(Q R_c N_0)` the jammer's noise density at the correlator output over
    the thermal density, :math:`(C/N_0)_{eff} = (C/N_0)/(1 + x)`, i.e. in dB
    :math:`(C/N_0) - 10 \log_{10}(1 + x)` (the form of
    :func:`effective_cn0_with_jammer_dbhz` with the signal, jammer power, chip rate and
    spectral separation folded into one ratio). Arrays broadcast.

    Parameters
    ----------
    cn0_dbhz : array_like
        Unjammed :math:`C/N_0`, dB-Hz.
    jammer_to_noise_db : array_like
        Jammer density over thermal density, dB.

    Returns
    -------
    float or ndarray
        Effective :math:`C/N_0`, dB-Hz.

    Raises
    ------
    ValueError
        If an argument is not finite.

    Examples
    --------
    >>> round(float(jammed_cn0_dbhz(44.0, 0.0)), 4)  # jammer density equal to the thermal
    40.9897
    """
    c = as_finite_array("cn0_dbhz", cn0_dbhz)
    x = as_finite_array("jammer_to_noise_db", jammer_to_noise_db)
    return _out(c - np.logaddexp(0.0, x * _LN10_10) / _LN10_10)


#: Allowed phase error :math:`k \sigma` (deg) of each carrier-loop type (Kaplan Sec. 5.6.2).
LOOP_PHASE_LIMIT_DEG = {"pll": 90.0, "costas": 45.0}


def _phase_limit_deg(loop: str, max_phase_error_deg: float | None) -> float:
    if loop not in LOOP_PHASE_LIMIT_DEG:
        raise ValueError(f"loop must be one of {sorted(LOOP_PHASE_LIMIT_DEG)}, got {loop!r}")
    if max_phase_error_deg is None:
        return LOOP_PHASE_LIMIT_DEG[loop]
    return require_positive("max_phase_error_deg", max_phase_error_deg)


def pll_jitter_threshold_dbhz(
    noise_bandwidth_hz: ArrayLike,
    max_phase_error_deg: float | None = None,
    k_sigma: float = 3.0,
    coherent_s: float = 0.02,
    *,
    loop: str = "costas",
) -> Array | float:
    r""":math:`C/N_0` (dB-Hz) at which ``k_sigma`` times the carrier loop's thermal jitter equals the
    allowed phase error.

    Positive root of :math:`a x^2 - B_n x - B_n/(2T) = 0` with :math:`a = (\phi_{max}/k)^2` (rad²).

    Parameters
    ----------
    noise_bandwidth_hz : array_like
        Carrier-loop noise bandwidth :math:`B_n` (Hz).
    max_phase_error_deg : float, optional
        Allowed phase error (deg); default: the rule of ``loop`` (45 deg for a Costas loop,
        90 deg for a pure PLL). A value given here overrides the rule (e.g. a printed one).
    k_sigma : float
        Multiple of the 1-:math:`\sigma` jitter that must stay within the allowed error.
    coherent_s : float
        Coherent integration (predetection) time :math:`T` (s).
    loop : {"costas", "pll"}
        Loop type: ``"costas"`` for a data-modulated signal (L1 C/A, P(Y)), ``"pll"`` for a
        pure PLL on a data-free signal.

    Returns
    -------
    float or ndarray
        Threshold :math:`C/N_0`, dB-Hz (shape of ``noise_bandwidth_hz``).

    Raises
    ------
    ValueError
        If ``loop`` is unknown, or a bandwidth, ``k_sigma``, ``coherent_s`` or the phase
        limit is not positive.

    Notes
    -----
    The thermal-jitter rule of thumb for Costas and PLL carrier loops (Kaplan & Hegarty,
    Understanding GPS, Sec. 5.6.2), used for the loss thresholds of Schmidt & Phillips,
    Sec. 2.5.

    Examples
    --------
    >>> round(float(pll_jitter_threshold_dbhz(5.83)), 2)  # Costas loop, 3 sigma <= 45 deg
    20.22
    >>> round(float(pll_jitter_threshold_dbhz(5.83, loop="pll")), 2)  # 3 sigma <= 90 deg
    15.57
    """
    max_phase_error_deg = _phase_limit_deg(loop, max_phase_error_deg)
    require_positive("k_sigma", k_sigma)
    require_positive("coherent_s", coherent_s)
    bn = require_positive("noise_bandwidth_hz", as_finite_array("noise_bandwidth_hz", noise_bandwidth_hz))
    a = (math.radians(max_phase_error_deg) / k_sigma) ** 2
    x = (bn + np.sqrt(bn**2 + 2.0 * a * bn / coherent_s)) / (2.0 * a)
    return _out(10.0 * np.log10(x))


@implements("SP Sec. 2.5")
def carrier_loss_threshold_dbhz(
    noise_bandwidth_hz: ArrayLike,
    floor_dbhz: float,
    max_phase_error_deg: float | None = None,
    k_sigma: float = 3.0,
    coherent_s: float = 0.02,
    *,
    loop: str = "costas",
) -> Array | float:
    r"""Carrier-loop loss threshold: the larger of a :math:`C/N_0` floor and the jitter threshold.

    The jitter threshold is :func:`pll_jitter_threshold_dbhz` for the given ``loop``.

    Parameters
    ----------
    noise_bandwidth_hz : array_like
        Carrier-loop noise bandwidth :math:`B_n`, Hz (``> 0``).
    floor_dbhz : float
        :math:`C/N_0` floor below which the loop is lost regardless of jitter, dB-Hz.
    max_phase_error_deg : float, optional
        Allowed phase error, deg (default: the rule of ``loop``).
    k_sigma : float, default 3.0
        Multiple of the 1-:math:`\sigma` jitter that must stay within the allowed error.
    coherent_s : float, default 0.02
        Coherent integration time, s.
    loop : {"costas", "pll"}
        Loop type (see :func:`pll_jitter_threshold_dbhz`).

    Returns
    -------
    float or ndarray
        Loss threshold, dB-Hz (shape of ``noise_bandwidth_hz``).

    Raises
    ------
    ValueError
        As :func:`pll_jitter_threshold_dbhz`, or if ``floor_dbhz`` is not finite.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.5 (tracking thresholds).

    Examples
    --------
    >>> [round(float(carrier_loss_threshold_dbhz(5.83, floor)), 2) for floor in (25.0, 15.0)]
    [25.0, 20.22]
    """
    jit = np.asarray(
        pll_jitter_threshold_dbhz(noise_bandwidth_hz, max_phase_error_deg, k_sigma, coherent_s, loop=loop)
    )
    return _out(np.maximum(as_finite_array("floor_dbhz", floor_dbhz), jit))


def pll_thermal_jitter_deg(
    cn0_dbhz: ArrayLike, noise_bandwidth_hz: ArrayLike, coherent_s: float = 0.02
) -> Array | float:
    r"""Carrier-loop thermal phase jitter, deg (1-:math:`\sigma`).

    :math:`\sigma_\phi^2 = \frac{B_n}{C/N_0}\big(1 + \frac{1}{2T\,C/N_0}\big)` rad² (Kaplan &
    Hegarty, Sec. 5.6.2), the quantity :func:`pll_jitter_threshold_dbhz` holds at its limit.
    Arrays broadcast.

    Parameters
    ----------
    cn0_dbhz : array_like
        :math:`C/N_0`, dB-Hz.
    noise_bandwidth_hz : array_like
        Loop noise bandwidth :math:`B_n`, Hz (``> 0``).
    coherent_s : float, default 0.02
        Coherent integration time :math:`T`, s (``> 0``).

    Returns
    -------
    float or ndarray
        Jitter, deg.

    Raises
    ------
    ValueError
        If a bandwidth or ``coherent_s`` is not positive or an argument is not finite.

    Examples
    --------
    >>> x = float(pll_jitter_threshold_dbhz(5.83, 90.0, 3.0, 0.02))
    >>> round(3.0 * float(pll_thermal_jitter_deg(x, 5.83, 0.02)), 9)
    90.0
    """
    require_positive("coherent_s", coherent_s)
    bn = require_positive("noise_bandwidth_hz", as_finite_array("noise_bandwidth_hz", noise_bandwidth_hz))
    c = power_ratio_from_db("cn0_dbhz", cn0_dbhz)
    return _out(np.degrees(np.sqrt(bn / c * (1.0 + 1.0 / (2.0 * coherent_s * c)))))


def dll_thermal_jitter_chips(
    cn0_dbhz: ArrayLike, noise_bandwidth_hz: ArrayLike, spacing_chips: float = 1.0, coherent_s: float = 0.02
) -> Array | float:
    r"""Code-loop (noncoherent early-minus-late power DLL) thermal jitter, chips (1-:math:`\sigma`).

    :math:`\sigma^2 = \frac{B_n d}{2\,C/N_0}\Big(1 + \frac{2}{T\,C/N_0\,(2 - d)}\Big)` chips²
    for an early-late spacing :math:`d` chips (Kaplan & Hegarty, Sec. 5.6.1). Arrays broadcast.

    Parameters
    ----------
    cn0_dbhz : array_like
        :math:`C/N_0`, dB-Hz.
    noise_bandwidth_hz : array_like
        Code-loop noise bandwidth, Hz (``> 0``).
    spacing_chips : float, default 1.0
        Early-late correlator spacing :math:`d`, chips (``0 < d < 2``).
    coherent_s : float, default 0.02
        Predetection integration time, s (``> 0``).

    Returns
    -------
    float or ndarray
        Jitter, chips.

    Raises
    ------
    ValueError
        If a bandwidth or ``coherent_s`` is not positive, ``spacing_chips`` is outside (0, 2),
        or an argument is not finite.

    Examples
    --------
    >>> round(float(dll_thermal_jitter_chips(40.0, 0.5)), 6)  # 0.5 Hz, 1 chip, 20 ms
    0.005025
    """
    require_positive("coherent_s", coherent_s)
    if not 0.0 < spacing_chips < 2.0:
        raise ValueError(f"spacing_chips must be in (0, 2), got {spacing_chips!r}")
    bn = require_positive("noise_bandwidth_hz", as_finite_array("noise_bandwidth_hz", noise_bandwidth_hz))
    c = power_ratio_from_db("cn0_dbhz", cn0_dbhz)
    d = spacing_chips
    return _out(np.sqrt(bn * d / (2.0 * c) * (1.0 + 2.0 / (coherent_s * c * (2.0 - d)))))


def hysteresis_from_conditions(
    lose: ArrayLike, regain: ArrayLike, *, initially_locked: bool = True
) -> NDArray[np.bool_]:
    """Lock state over time from per-sample loss and reacquisition conditions (vectorised).

    A channel is unlocked from the first sample where ``lose`` holds and locked again from
    the first later sample where ``regain`` holds (and ``lose`` does not); in between it
    keeps its state. :func:`hysteresis_lock` is the case of two :math:`C/N_0` thresholds.

    Parameters
    ----------
    lose, regain : (N, n) bool arrays
        Conditions per sample and channel.
    initially_locked : bool, default True
        Lock state before the first sample that decides it.

    Returns
    -------
    (N, n) bool ndarray
        Lock state per sample and channel.

    Raises
    ------
    ValueError
        If the conditions are not 2-D arrays of one shape.

    Examples
    --------
    >>> lose = [[False], [True], [False], [False]]
    >>> regain = [[True], [False], [False], [True]]
    >>> hysteresis_from_conditions(lose, regain)[:, 0].tolist()
    [True, False, False, True]
    """
    lo = np.asarray(lose, dtype=bool)
    hi = np.asarray(regain, dtype=bool)
    if lo.ndim != 2 or lo.shape != hi.shape:
        raise ValueError(f"lose and regain must be 2-D arrays of one shape, got {lo.shape} and {hi.shape}")
    set_ = hi & ~lo
    event = set_ | lo
    n = lo.shape[0]
    idx = np.where(event, np.arange(n)[:, None], -1)
    last = np.maximum.accumulate(idx, axis=0)  # index of the last decisive sample
    state = np.take_along_axis(set_, np.clip(last, 0, None), axis=0)
    return np.where(last >= 0, state, initially_locked)


@dataclass(frozen=True)
class LockThresholds:
    """Effective-:math:`C/N_0` thresholds (dB-Hz) of one receiver: loss and reacquisition, code and carrier.

    Attributes
    ----------
    code_loss : float
        Code-loop loss threshold, dB-Hz.
    carrier_loss : float
        Carrier-loop loss threshold, dB-Hz.
    code_reacquisition : float
        Code reacquisition threshold, dB-Hz.
    carrier_reacquisition : float
        Carrier reacquisition threshold, dB-Hz.
    """

    code_loss: float
    carrier_loss: float
    code_reacquisition: float
    carrier_reacquisition: float

    def __post_init__(self) -> None:
        for kind in ("code", "carrier"):
            lo, hi = getattr(self, f"{kind}_loss"), getattr(self, f"{kind}_reacquisition")
            if not (math.isfinite(lo) and math.isfinite(hi)):
                raise ValueError(f"LockThresholds.{kind}_loss and {kind}_reacquisition must be finite")
            if hi < lo:
                raise ValueError(f"LockThresholds.{kind}_reacquisition must be >= {kind}_loss")


@implements("SP Sec. 2.5")
def hysteresis_lock(
    cn0_dbhz: ArrayLike, loss_dbhz: ArrayLike, reacquisition_dbhz: ArrayLike, *, initially_locked: bool = True
) -> NDArray[np.bool_]:
    """Lock state over time of each channel with hysteresis (vectorised).

    A channel is unlocked from the first sample below ``loss_dbhz`` and locked again from the
    first later sample at or above ``reacquisition_dbhz``; in between it keeps its state.

    Parameters
    ----------
    cn0_dbhz : (N, n) array
        Effective :math:`C/N_0` per time sample and channel, dB-Hz.
    loss_dbhz : float or (n,) array
        Loss threshold, dB-Hz.
    reacquisition_dbhz : float or (n,) array
        Reacquisition threshold, dB-Hz (at least ``loss_dbhz``).
    initially_locked : bool, default True
        Lock state before the first sample that decides it.

    Returns
    -------
    (N, n) bool ndarray
        Lock state per sample and channel.

    Raises
    ------
    ValueError
        If ``cn0_dbhz`` is not 2-D or a reacquisition threshold is below its loss threshold.

    References
    ----------
    Schmidt & Phillips, "INS/GPS Integration Architecture Performance Comparisons",
    Sec. 2.5 (loss and reacquisition thresholds).

    Examples
    --------
    >>> hysteresis_lock([[30.0], [17.0], [20.0], [22.0]], 18.0, 21.0)[:, 0].tolist()
    [True, False, False, True]
    """
    c = as_finite_array("cn0_dbhz", cn0_dbhz)
    if c.ndim != 2:
        raise ValueError(f"cn0_dbhz must have shape (N, n), got {c.shape}")
    lo = as_finite_array("loss_dbhz", loss_dbhz)
    hi = as_finite_array("reacquisition_dbhz", reacquisition_dbhz)
    if np.any(hi < lo):
        raise ValueError("reacquisition_dbhz must be >= loss_dbhz")
    set_ = c >= hi
    reset = c < lo
    event = set_ | reset
    n = c.shape[0]
    idx = np.where(event, np.arange(n)[:, None], -1)
    last = np.maximum.accumulate(idx, axis=0)  # index of the last decisive sample
    state = np.take_along_axis(set_, np.clip(last, 0, None), axis=0)
    return np.where(last >= 0, state, initially_locked)


def outage_intervals(t_s: ArrayLike, available: ArrayLike) -> list[tuple[float, float]]:
    """``[(start, end), ...]`` of the stretches where ``available`` is False.

    ``start`` is the first unavailable sample's time and ``end`` the first available sample's
    time after it (the last sample's time if the outage lasts to the end).

    Parameters
    ----------
    t_s : (N,) array
        Sample times, s.
    available : (N,) bool array
        Availability per sample.

    Returns
    -------
    list of (float, float)
        Start and end times of each outage, s.

    Raises
    ------
    ValueError
        If ``available`` and ``t_s`` differ in shape.

    Examples
    --------
    >>> outage_intervals([0.0, 1.0, 2.0, 3.0, 4.0], [True, False, False, True, False])
    [(1.0, 3.0), (4.0, 4.0)]
    """
    t = as_finite_array("t_s", t_s)
    a = np.asarray(available, dtype=bool)
    if a.shape != t.shape:
        raise ValueError(f"available must have the shape of t_s {t.shape}, got {a.shape}")
    off = np.r_[False, ~a, False].astype(np.int8)
    d = np.diff(off)
    starts = np.flatnonzero(d == 1)
    ends = np.flatnonzero(d == -1)
    return [(float(t[s]), float(t[min(int(e), t.size - 1)])) for s, e in zip(starts, ends, strict=True)]


# Every public function checks its arguments against their annotations (finite numbers,
# numeric arrays) and names the parameter when it raises: see navcore._validate.checked.
check_public(
    globals(),
    {
        "chip_rate_hz": POSITIVE,
        "coherent_s": POSITIVE,
        "noise_bandwidth_hz": POSITIVE,
        "wavelength_m": POSITIVE,
        "speed_mps": POSITIVE,
        "range_m": POSITIVE,
        "closest_range_m": NONNEGATIVE,
        "q": POSITIVE,
        "k_sigma": POSITIVE,
        "max_phase_error_deg": Range(0.0, 180.0, low_open=True),
        "exponent": POSITIVE,
    },
)
