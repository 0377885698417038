"""Numbers the book's pages print that are not ledger claims, each with the function computing it.

A page prints a number by gluing it (``glue("kzl00-schuler-min", value)``, with
:func:`navcore.book.glue`) and quoting it in its prose with a ``{glue:text}`` role. Every such
number is either a claim's value (the page's glue call reads a claim of the ledger, whose own
tests recompute it) or registered here, once, under its glue name, with the page that shows it
and the function that computes it. Two checks then hold a registered number:

- when a page glues a registered name, :func:`navcore.book.glue` calls :func:`check`, which
  recomputes the registered function and refuses a value that differs (the book's strict build
  fails), so the page prints what the function computes;
- ``tests/test_glue_values.py`` recomputes every registered function against an independent
  oracle (a closed form, scipy, a seeded Monte Carlo, or the paper's printed inputs in other
  arithmetic), and ``tests/test_glue_pages.py`` scans the pages and fails on a glued name that
  is neither a claim's value nor registered (nor in its shrinking to-do list).

A glue name may hold fields (``"atc10-erp-K{k}-{p_dl}"``) for a family a page glues in a loop;
the function then receives the fields as strings. The functions import their paper modules
when called (a page imports only its own paper's models) and read inputs through them.

Examples
--------
>>> entry, fields = lookup("kzl00-schuler-min")
>>> entry.quantity, entry.page, fields
('period of the Schuler oscillation (min)', 'kzl/00-requirements', {})
>>> round(value("kzl00-schuler-min"), 2)
84.45
>>> lookup("atc10-erp-K100-0.88")[1]
{'k': '100', 'p_dl': '0.88'}
>>> lookup("no-such-name") is None
True
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

__all__ = ["GluedValue", "check", "entries", "lookup", "register", "value"]


@dataclass(frozen=True)
class GluedValue:
    """A number a page prints, registered with the page that shows it and the function computing it.

    Attributes
    ----------
    pattern : str
        The glue name, with ``{field}`` placeholders for a family of names.
    page : str
        The page that glues it, relative to ``book/`` and without suffix
        (``"kzl/00-requirements"``).
    quantity : str
        What the number is, in words (with its unit).
    compute : callable
        Returns the number; called with the pattern's fields as keyword strings.
    """

    pattern: str
    page: str
    quantity: str
    compute: Callable[..., Any]

    @property
    def regex(self) -> re.Pattern[str]:
        """The pattern as a regular expression (a field matches one or more characters)."""
        parts = re.split(r"\{(\w+)\}", self.pattern)
        out = "".join(re.escape(p) if i % 2 == 0 else f"(?P<{p}>.+?)" for i, p in enumerate(parts))
        return re.compile(out + r"\Z")


_REGISTRY: dict[str, GluedValue] = {}


def register(pattern: str, page: str, quantity: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Register the function that computes the number a page glues under ``pattern``.

    Parameters
    ----------
    pattern : str
        The glue name (``"kzl00-schuler-min"``), or a family of names with ``{field}``
        placeholders.
    page : str
        The page that glues it, relative to ``book/``, without suffix.
    quantity : str
        What the number is, in words, with its unit.

    Returns
    -------
    callable
        A decorator that records the function and returns it unchanged.

    Raises
    ------
    ValueError
        If ``pattern`` is registered already, or ``page`` or ``quantity`` is empty.
    """
    if pattern in _REGISTRY:
        raise ValueError(f"glue name {pattern!r} is registered twice")
    if not page.strip():
        raise ValueError(f"glue name {pattern!r} needs the page that shows it")
    if not quantity.strip():
        raise ValueError(f"glue name {pattern!r} needs the quantity it prints, in words")

    def deco(fn: Callable[..., Any]) -> Callable[..., Any]:
        _REGISTRY[pattern] = GluedValue(pattern, page, quantity, fn)
        return fn

    return deco


def entries() -> dict[str, GluedValue]:
    """Every registered glue name (pattern) and its registration, sorted by pattern.

    Returns
    -------
    dict of str to GluedValue
        The registrations by pattern.
    """
    return dict(sorted(_REGISTRY.items()))


def lookup(name: str) -> tuple[GluedValue, dict[str, str]] | None:
    """The registration a glue name falls under, and its fields.

    Parameters
    ----------
    name : str
        A glue name as a page glues it (``"atc10-erp-K100-0.88"``).

    Returns
    -------
    tuple of (GluedValue, dict of str to str) or None
        The registration and the pattern's fields; ``None`` if the name is not registered.
    """
    if name in _REGISTRY:
        return _REGISTRY[name], {}
    for entry in _REGISTRY.values():
        if "{" in entry.pattern:
            m = entry.regex.match(name)
            if m:
                return entry, m.groupdict()
    return None


def value(name: str) -> Any:
    """Compute the number registered under the glue name ``name``.

    Parameters
    ----------
    name : str
        A glue name as a page glues it.

    Returns
    -------
    Any
        What the registered function computes.

    Raises
    ------
    ValueError
        If ``name`` is not registered.
    """
    found = lookup(name)
    if found is None:
        raise ValueError(f"glue name {name!r} is not registered in navcore.glued")
    entry, fields = found
    return entry.compute(**fields)


def _close(a: Any, b: Any, rtol: float) -> bool:
    if isinstance(a, str) or isinstance(b, str):
        return str(a) == str(b)
    x, y = float(a), float(b)
    if math.isnan(x) or math.isnan(y):
        return False
    return x == y or abs(x - y) <= rtol * max(abs(x), abs(y))


def _show(x: Any) -> str:
    return f"{x:.6g}" if isinstance(x, float) else repr(x)


def check(name: str, glued: Any, *, rtol: float = 1e-9) -> None:
    """Refuse a glued value that is not what its registered function computes.

    Names that are not registered pass here: they are claims' values, or in the to-do list of
    ``tests/test_glue_pages.py``, which fails on any other.

    Parameters
    ----------
    name : str
        The glue name the page uses.
    glued : Any
        The value the page glues.
    rtol : float, default 1e-9
        Relative tolerance: the page and the function compute the same arithmetic, so only
        rounding may separate them.

    Raises
    ------
    ValueError
        If ``name`` is registered and ``glued`` differs from the registered function's value
        by more than ``rtol`` (relative).

    Examples
    --------
    >>> check("kzl00-schuler-min", value("kzl00-schuler-min"))
    >>> check("kzl00-schuler-min", 1.3 * value("kzl00-schuler-min"))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: glued value 'kzl00-schuler-min' is 109.789, but its registered function computes 84.453 ...
    """
    found = lookup(name)
    if found is None:
        return
    entry, fields = found
    expected = entry.compute(**fields)
    if not _close(glued, expected, rtol):
        raise ValueError(
            f"glued value {name!r} is {_show(glued)}, but its registered function computes "
            f"{_show(expected)} ({entry.quantity})"
        )


# ---------------------------------------------------------------------------------------------
# The registrations, by kind. Each function imports what it reads.

# --- constants and unit conversions ----------------------------------------------------------


@register("kzl00-schuler-min", "kzl/00-requirements", "period of the Schuler oscillation (min)")
def schuler_period_min() -> float:
    """Schuler period 2 pi sqrt(a / g0) of navcore's Earth radius and standard gravity, in minutes."""
    from navcore.units import G0, WGS84_A

    return float(2 * math.pi * math.sqrt(WGS84_A / G0) / 60)


@register("atc10-32-c-ft-per-ns", "atc10/32-tracking-examples", "speed of light in feet per nanosecond")
def light_ft_per_ns() -> float:
    """Distance light travels in a nanosecond, in feet (ATC-10 Sec. 4 reads 1 ns as 1 ft)."""
    from navcore import units

    return float(units.C * 1e-9 / units.FT)


@register(
    "atc10-32-c-shrink-pct",
    "atc10/32-tracking-examples",
    "how much shorter a light-nanosecond is than a foot (%)",
)
def light_ns_short_of_foot_pct() -> float:
    """How much shorter a light-nanosecond is than a foot, in percent."""
    return 100 * (1 - light_ft_per_ns())


@register("atc10-13-30W-dbw", "atc10/13-tables", "30 W in dBW")
def thirty_watts_dbw() -> float:
    """30 W in dBW (ATC-10 Table 1.1's transmitter power)."""
    from navcore import units

    return float(units.dbw_from_watts(30.0))


@register("atc10-10-convention-db", "atc10/10-jamming-model", "a factor 2 in power, in dB")
@register(
    "atc10-12-erf-shift-db",
    "atc10/12-tracking-lists",
    "a factor 2 in power, in dB (the erf argument's convention)",
)
def factor_two_db() -> float:
    """A factor 2 in power, in dB."""
    return float(10 * math.log10(2))


@register(
    "wf04-trace-reading-shift-db",
    "wf/04-assessment",
    "a factor 3 in power (the trace against one axis), in dB",
)
def factor_three_db() -> float:
    """A factor 3 in power, in dB (the trace of an isotropic 3-D covariance against one axis)."""
    return float(10 * math.log10(3))


@register("wf89-fl1c", "wf/89-summary", "f_L1 / c with the defined c (cycles per metre)")
def f_l1_over_defined_c() -> float:
    """The GPS L1 carrier frequency over the defined speed of light (Wu & Fowler Sec. IV.D), 1/m."""
    from navcore.units import GPS_L1_HZ, C

    return float(GPS_L1_HZ / C)


@register("wf89-fl1c-3e8", "wf/89-summary", "f_L1 / c with c read as 3e8 m/s (cycles per metre)")
def f_l1_over_rounded_c() -> float:
    """The GPS L1 carrier frequency over the engineering speed of light 3e8 m/s, 1/m."""
    from navcore.units import GPS_L1_HZ

    return float(GPS_L1_HZ / 3e8)


@register(
    "atc10-31-small-alpha-coefficient",
    "atc10/31-clock-tracking",
    "the small-alpha coefficient (3/2) 2^(1/3) of psi",
)
def psi_small_alpha_coefficient() -> float:
    """Coefficient of alpha^(1/3) in the small-alpha form of psi (ATC-10 Eq. (4.5.38))."""
    return float(1.5 * 2.0 ** (1.0 / 3.0))


@register("atc10-30-orbit-radius-km", "atc10/30-tracking-geometry", "radius of the synchronous orbit (km)")
def synchronous_orbit_radius_km() -> float:
    """Radius of the geosynchronous orbit, in km."""
    from navcore.location.multilateration import synchronous_orbit_radius

    return float(synchronous_orbit_radius() / 1e3)


@register(
    "atc10-13-wavelength-m",
    "atc10/13-tables",
    "wavelength at the assumed jammer-dish frequency of Table 1.1 (m)",
)
def atc10_table11_wavelength_m() -> float:
    """Wavelength at the assumed frequency of Table 1.1's jammer dishes, in metres."""
    from navcore import units
    from navcore.papers import atc10_jamming as pj

    return float(units.C / pj.IN.dish_frequency_hz)


@register(
    "kzl01-levelling-tilt-deg",
    "kzl/01-mechanization",
    "levelling tilt from the Table 1 accelerometer bias (deg)",
)
@register(
    "kzl03-levelling-tilt-deg",
    "kzl/03-simulation",
    "levelling tilt from the Table 1 accelerometer bias (deg)",
)
def kzl_levelling_tilt_deg() -> float:
    """Tilt (small angle) that levelling leaves from KZL's Table 1 accelerometer bias, in degrees."""
    from navcore.papers.kzl_scenario import kzl_imu
    from navcore.units import G0

    return float(math.degrees(kzl_imu().accel_bias / G0))


@register(
    "kzl01-horizontal-earth-rate-deg-h",
    "kzl/01-mechanization",
    "horizontal Earth rate at 51 deg latitude (deg/h)",
)
def horizontal_earth_rate_deg_h() -> float:
    """Horizontal component of the Earth rate at 51 deg latitude, in deg/h."""
    import numpy as np

    from navcore.inertial.strapdown import earth_rate_ned
    from navcore.units import DEG, DEG_PER_H

    return float(np.linalg.norm(earth_rate_ned(51 * DEG)[:2]) / DEG_PER_H)


@register("wf05-sigma-f-velocity", "wf/05-end-to-end", "1 Hz frequency noise as a radial velocity (m/s)")
def wf_frequency_noise_velocity() -> float:
    """Wu & Fowler's frequency-measurement noise as a radial velocity at the 10 GHz carrier (m/s)."""
    from navcore import units
    from navcore.papers import wf_location_error

    return float(wf_location_error.SIGMA_F / (wf_location_error.F0 / units.C))


# --- sampling errors of Monte Carlo runs -----------------------------------------------------


@register(
    "kzl03-rms-rel-error-pct", "kzl/03-simulation", "relative standard error of an RMS over the KZL runs (%)"
)
def kzl_rms_relative_error_pct() -> float:
    """Relative standard error 1/sqrt(2 N) of an RMS over the N Monte Carlo runs, in percent."""
    from navcore.papers.kzl_scenario import N_RUNS

    return float(100 / math.sqrt(2 * N_RUNS))


@register(
    "sp06-cep-sd-pct",
    "sp/06-deep-integration",
    "relative standard error of a CEP from the SP runs per point (%)",
)
def sp_cep_sd_pct() -> float:
    """Relative standard error of a CEP taken from the runs per point of SP Sec. 3, in percent."""
    from navcore.gnss.antijam import cep_relative_sd
    from navcore.papers import sp_antijam as spj

    return float(100 * cep_relative_sd(spj.IN.runs))


@register("sp03-chi2", "sp/03-residual-acceleration", "radius holding 90 % of a 3-D standard normal (sigmas)")
def chi3_radius_90() -> float:
    """Radius, in standard deviations, that holds 90 % of an isotropic 3-D normal."""
    from scipy.stats import chi2

    return float(math.sqrt(chi2.ppf(0.9, 3)))


# --- counts ----------------------------------------------------------------------------------


@register("kzl01-n-states", "kzl/01-mechanization", "states of the KZL error model")
@register("kzl02-n-states", "kzl/02-error-model", "states of the KZL error model")
@register("kzl03-n-states", "kzl/03-simulation", "states of the KZL error model")
@register("across01-kzl-states", "across/01-filters-and-geometry", "states of the KZL error model")
def kzl_error_states() -> int:
    """Number of states of navcore's KZL error model (KZL Eq. (1))."""
    from navcore.inertial.error_model17 import ERROR_LAYOUT_17

    return int(ERROR_LAYOUT_17.size)


@register(
    "kzl02-dd-rows-{n}-satellites",
    "kzl/02-error-model",
    "rows of the KZL observation matrix for n satellites",
)
def kzl_dd_rows(n: str) -> int:
    """Rows of KZL's stacked observation matrix (Eq. (17)) for ``n`` satellites in view."""
    from navcore.integration.measurement_rows import dd_observation_rows_count

    return int(dd_observation_rows_count(int(n)))


@register("kzl03-dd-sigma-mm", "kzl/03-simulation", "standard deviation of a double-differenced phase (mm)")
def kzl_dd_phase_sigma_mm() -> float:
    """Standard deviation of one double-differenced carrier phase of the KZL scenario, in mm."""
    from navcore.gnss.carrier_phase import dd_covariance
    from navcore.papers.kzl_scenario import gnss_noise

    phase = gnss_noise().phase
    assert phase is not None  # the default mode uses every GPS noise
    return float(1e3 * math.sqrt(dd_covariance(2, phase)[0, 0]))


@register(
    "kzl90-residual-deg-h",
    "kzl/90-exercises",
    "gyro bias left after averaging the angle random walk over the initialisation (deg/h)",
)
@register(
    "kzl03-gyro-residual-deg-h",
    "kzl/03-simulation",
    "gyro bias left after averaging the angle random walk over the initialisation (deg/h)",
)
def kzl_gyro_residual_deg_h() -> float:
    """Standard deviation of a gyro bias estimated by averaging the Table 1 angle random walk
    over the initialisation time of the KZL scenario, in deg/h."""
    from navcore.papers.kzl_scenario import IN, kzl_imu
    from navcore.units import DEG_PER_H

    return float(kzl_imu().gyro_random_walk / math.sqrt(IN.init_time_s) / DEG_PER_H)


# --- model values: ATC-10 Section 2 (jamming) and 3 (multiple-access noise) -------------------


@register(
    "atc10-erp-K{k}-{p_dl}", "atc10/10-jamming-model", "jammer ERP at which N_ADL reaches 0.01 N_T (dBW)"
)
def atc10_adl_erp_dbw(k: str, p_dl: str) -> float:
    """Jammer ERP (dBW) at which the ambiguous-detection count reaches its level, for K lists."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.required_erp_dbw("ambiguous", float(p_dl), int(k)))


@register(
    "atc10-12-erp-K100-0.88",
    "atc10/12-tracking-lists",
    "jammer ERP at which N_ADL reaches 0.01 N_T, K = 100, P_DL = 0.88 (dBW)",
)
def atc10_erp_k100_088() -> float:
    """Jammer ERP (dBW) for K = 100, P_DL = 0.88."""
    return atc10_adl_erp_dbw("100", "0.88")


@register(
    "atc10-13-erp-K100-0.98",
    "atc10/13-tables",
    "jammer ERP at which N_ADL reaches 0.01 N_T, K = 100, P_DL = 0.98 (dBW)",
)
def atc10_erp_k100_098() -> float:
    """Jammer ERP (dBW) for K = 100, P_DL = 0.98."""
    return atc10_adl_erp_dbw("100", "0.98")


@register(
    "atc10-12-fig2.4-erp",
    "atc10/12-tracking-lists",
    "jammer ERP at which N_ADL reaches 0.01 N_T, K = 10, P_DL = 0.88 (dBW)",
)
def atc10_fig24_erp_dbw() -> float:
    """Jammer ERP (dBW) of Fig. 2.4's case, K = 10, P_DL = 0.88."""
    return atc10_adl_erp_dbw("10", "0.88")


@register("atc10-pd-k1000-{p_dl}", "atc10/10-jamming-model", "per-filter detection probability for K = 1000")
def atc10_pd_k1000(p_dl: str) -> float:
    """Per-filter p_d that gives P_DL = ``p_dl`` with K = 1000 lists (ATC-10 Eq. (2.4.2))."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.design_p_d(float(p_dl), 1000))


@register("atc10-pd4-k1000-0.999", "atc10/10-jamming-model", "p_d^4 for K = 1000, P_DL = 0.999")
def atc10_pd4_k1000_0999() -> float:
    """Fourth power of the per-filter p_d for K = 1000, P_DL = 0.999: one list's detection probability."""
    return atc10_pd_k1000("0.999") ** 4


@register("atc10-10-qK-k10-0.999", "atc10/10-jamming-model", "p_d^(4K) for K = 10, P_DL = 0.999")
def atc10_qk_k10_0999() -> float:
    """All ten lists detected, p_d^(4K) for K = 10 at P_DL = 0.999."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.design_p_d(0.999, 10) ** (4 * 10))


@register("atc10-10-n-v", "atc10/10-jamming-model", "samples n_v in a tracking window (C.14)")
@register("atc10-12-n-v", "atc10/12-tracking-lists", "samples n_v in a tracking window (C.14)")
@register("atc10-14-n-v", "atc10/14-monte-carlo", "samples n_v in a tracking window (C.14)")
def atc10_track_window_samples() -> float:
    """Samples (8 B / 3) v alpha / c in a tracking window of ATC-10's scenario (App. C, C.14)."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.geometry().samples_per_track_window)


@register(
    "atc10-11-samples-period", "atc10/11-single-pulse", "samples 2 B alpha in a repetition period (B.6)"
)
def atc10_period_samples() -> float:
    """Samples 2 B alpha in one repetition period of ATC-10's scenario (App. B, B.6)."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.geometry().samples_per_period)


@register("atc10-11-samples-window", "atc10/11-single-pulse", "samples 4 B beta in a delay window (B.6)")
def atc10_delay_window_samples() -> float:
    """Samples 4 B beta in a differential-delay window of ATC-10's scenario (App. B, B.6)."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.geometry().samples_per_delay_window)


@register(
    "atc10-20-mean-overlap", "atc10/20-multiple-access-noise", "mean number of overlapping pulses (N - 1) q"
)
@register("atc10-21-nq", "atc10/21-roc-bounds", "mean number of overlapping pulses (N - 1) q")
def atc10_mean_overlap() -> float:
    """Mean number of other aircraft's pulses overlapping a window, (N - 1) q, q = 2 tau/alpha (Sec. 3.6)."""
    from navcore.papers import atc10_multiple_access as pm

    return float((pm.IN.n_sec36 - 1) * 2 * pm.IN.tau_over_alpha_sec36)


@register("atc10-20-p-none", "atc10/20-multiple-access-noise", "probability that no other pulse overlaps")
def atc10_p_none() -> float:
    """Probability (1 - q)^(N - 1) that no other aircraft's pulse overlaps a window (Sec. 3.6)."""
    from navcore.papers import atc10_multiple_access as pm

    q = 2 * pm.IN.tau_over_alpha_sec36
    return float((1 - q) ** (pm.IN.n_sec36 - 1))


@register(
    "atc10-20-inverse-nq", "atc10/20-multiple-access-noise", "1 / (N q), the order of the excess kurtosis"
)
def atc10_inverse_nq() -> float:
    """1 / (N q), the order of the excess kurtosis of the multiple-access noise (Sec. 3.6)."""
    from navcore.papers import atc10_multiple_access as pm

    return float(1 / (pm.IN.n_sec36 * 2 * pm.IN.tau_over_alpha_sec36))


# --- model values: ATC-10 Section 3.9 (Zakai bandwidth) ---------------------------------------


@register(
    "atc10-23-w-msequence-1023",
    "atc10/23-zakai-bandwidth",
    "Zakai bandwidth of a 1023-chip m-sequence (per chip rate)",
)
def zakai_msequence_1023() -> float:
    """Zakai bandwidth of a 1023-chip m-sequence with unit chips."""
    from navcore.detection import zakai

    return float(zakai.psk_zakai_bandwidth(zakai.m_sequence(10), 1.0))


@register(
    "atc10-23-barker13-of-ideal",
    "atc10/23-zakai-bandwidth",
    "Zakai bandwidth of Barker 13 over the ideal 0.75",
)
def zakai_barker13_of_ideal() -> float:
    """Zakai bandwidth of the Barker-13 code with unit chips, over the ideal code's 0.75."""
    from navcore.detection import zakai

    return float(zakai.psk_zakai_bandwidth(zakai.barker_code(13), 1.0) / 0.75)


# --- model values: Wu & Fowler ---------------------------------------------------------------


@register("wf01-mean-range-km", "wf/01-location-error", "mean aperture-to-emitter range of Sec. III (km)")
def wf_mean_range_km() -> float:
    """Mean aperture-to-emitter range over Wu & Fowler's Sec. III scenario track, in km."""
    from navcore.papers import wf_aperture_velocity

    return float(wf_aperture_velocity.mean_range() / 1e3)


#: Seeded Gauss-Newton fits of the Sec. II Monte Carlo on the WF location-error page (a run
#: count of the page's own check, not an input: the paper runs no Monte Carlo).
WF01_LS_TRIALS = 400


@register(
    "wf01-sd-sampling-error-pct",
    "wf/01-location-error",
    "relative standard error of a standard deviation from the Sec. II Monte Carlo fits (%)",
)
def wf_sd_sampling_error_pct() -> float:
    """Relative standard error 1/sqrt(2 n) of a standard deviation from n seeded fits, in percent."""
    return float(100 / math.sqrt(2 * WF01_LS_TRIALS))


@register(
    "wf02-largest-bound-ratio",
    "wf/02-velocity-sensitivity",
    "largest ||df/dp|| over the Eq. (9) bound, random geometries",
)
@register("wf89-bound-ratio", "wf/89-summary", "largest ||df/dp|| over the Eq. (9) bound, random geometries")
def wf_largest_bound_ratio() -> float:
    """Largest ratio of ||df/dp|| to its bound, WF Eq. (9), over the seeded geometries."""
    from navcore.papers import wf_aperture_velocity

    return float(wf_aperture_velocity.position_bound_ratios().max())


def _wf_dl_steady_state_example() -> Any:
    """Steady state of WF Eq. (14) for the worked example's 100 ug accelerometer (Sec. IV.D)."""
    from navcore.estimation.federated import accelerometer_steady_state_isotropic
    from navcore.papers import wf_inputs

    sa = wf_inputs.sigma_a_example()
    return accelerometer_steady_state_isotropic(sa, wf_inputs.IN.ts, wf_inputs.IN.sigma_l_per_sigma_a * sa)


@register("wf03-dl-gain", "wf/03-local-estimators", "steady-state gain of the Eq. (14) filter at 100 ug")
def wf_dl_gain() -> float:
    """Steady-state Kalman gain of WF Eq. (14) for the 100 ug accelerometer, sigma_L = 200 sigma_a."""
    return float(_wf_dl_steady_state_example().gain)


@register(
    "wf03-dl-time-constant",
    "wf/03-local-estimators",
    "time constant T_s / K of the Eq. (14) filter at 100 ug (s)",
)
def wf_dl_time_constant() -> float:
    """Time constant T_s / K of WF Eq. (14)'s steady-state filter for the 100 ug accelerometer, s."""
    from navcore.papers import wf_inputs

    return float(wf_inputs.IN.ts / _wf_dl_steady_state_example().gain)


def _wf03_joint() -> tuple[list[Any], Any]:
    """The page's worked joint covariance: local covariances (nav, DL, GPS with three satellites)
    and the joint covariance of their errors (WF Eq. (20)), sigma_T = 2 m/s."""
    import numpy as np

    from navcore.papers import wf_assessment, wf_inputs

    sa = wf_inputs.sigma_a_example()
    P_dn, P_dl, P_dg = wf_assessment.local_covariances(sa, wf_inputs.IN.sigma_t_large, n_sat=3)
    ss = _wf_dl_steady_state_example()
    I3 = np.eye(3)
    H = wf_inputs.f_l1_over_c_printed() * I3
    K_l = ss.gain * I3
    K_g = P_dg @ H.T / wf_inputs.IN.sigma_g**2
    maps = [
        np.hstack([0 * I3, I3, 0 * I3, 0 * I3]),
        np.hstack([I3 - K_l, 0 * I3, K_l, 0 * I3]),
        np.hstack([I3 - K_g @ H, 0 * I3, 0 * I3, K_g]),
    ]
    S = np.zeros((12, 12))
    blocks = [
        ss.prior * I3,
        P_dn,
        (wf_inputs.IN.sigma_l_per_sigma_a * sa) ** 2 * I3,
        wf_inputs.IN.sigma_g**2 * I3,
    ]
    for j, block in enumerate(blocks):
        S[3 * j : 3 * j + 3, 3 * j : 3 * j + 3] = block
    A = np.vstack(maps)
    return [P_dn, P_dl, P_dg], A @ S @ A.T


@register(
    "wf03-corr-dl-dg",
    "wf/03-local-estimators",
    "correlation of the accelerometer and GPS velocity errors per axis",
)
def wf_corr_dl_dg() -> float:
    """Correlation between the accelerometer-filter and GPS-Doppler velocity errors on one axis
    (both start from the same prior, WF Eqs. (14) and (16))."""
    _, joint = _wf03_joint()
    return float(joint[3, 6] / math.sqrt(joint[3, 3] * joint[6, 6]))


@register(
    "wf03-naive-optimism",
    "wf/03-local-estimators",
    "exact fused sigma (Eq. (20)) over the naive Eq. (19) sigma",
)
def wf_naive_optimism() -> float:
    """How much larger the exact fused error (WF Eq. (20)) is than Eq. (19) claims, per axis."""
    import numpy as np

    from navcore.estimation.federated import federated_fusion, fused_error_covariance

    Ps, joint = _wf03_joint()
    exact = fused_error_covariance(Ps, joint)
    _, naive = federated_fusion([np.zeros(3)] * 3, Ps)
    return float(math.sqrt(exact[0, 0] / naive[0, 0]))


@register(
    "wf03-generic-tightness-rho1",
    "wf/03-local-estimators",
    "Eq. (23) bound over the true trace, generic covariances, rho = 1",
)
@register(
    "wf89-rem2-generic", "wf/89-summary", "Eq. (23) bound over the true trace, generic covariances, rho = 1"
)
def wf_generic_tightness_rho1() -> float:
    """Minkowski bound of WF Eq. (23) over the true fused trace, seeded generic covariances, rho = 1."""
    from navcore.papers import wf_federated_fusion

    return float(wf_federated_fusion.bound_tightness(1.0, "generic"))


@register(
    "wf03-isotropic-tightness-rho0",
    "wf/03-local-estimators",
    "Eq. (23) bound over the true trace, isotropic covariances, rho = 0",
)
def wf_isotropic_tightness_rho0() -> float:
    """Minkowski bound of WF Eq. (23) over the true fused trace, isotropic covariances, uncorrelated."""
    from navcore.papers import wf_federated_fusion

    return float(wf_federated_fusion.bound_tightness(0.0, "isotropic"))


#: The page's example of Eq. (11) with a large Q_T: a navigation sigma of 0.2 m/s per axis beside a
#: 2 m/s flexure (tau = I), against no navigation error.
WF03_LARGE_QT = (0.2, 2.0)


@register(
    "wf03-large-qt-change-pct",
    "wf/03-local-estimators",
    "change of sigma_DN when a 0.2 m/s navigation error joins a 2 m/s flexure (%)",
)
def wf_large_qt_change_pct() -> float:
    """Relative change of the per-axis sigma of WF Eq. (11) when the navigation error is added to a
    large flexure term, in percent."""
    import numpy as np

    from navcore.estimation.federated import navigation_mapped_covariance

    sn, st = WF03_LARGE_QT
    sd = [
        math.sqrt(navigation_mapped_covariance(np.eye(3), s**2 * np.eye(3), st**2 * np.eye(3))[0, 0])
        for s in (0.0, sn)
    ]
    return float(100 * (sd[1] / sd[0] - 1))


@register(
    "wf04-trace-reading-100ug-db",
    "wf/04-assessment",
    "Fig. 1 improvement at 100 ug, sigma_T = 2 m/s, read as a trace against one axis (dB)",
)
def wf_trace_reading_100ug_db() -> float:
    """The 100 ug improvement of Fig. 1 (sigma_T = 2 m/s) plus the factor 3 of a trace read per axis, dB."""
    from navcore.papers import wf_assessment, wf_inputs

    return float(
        wf_assessment.improvement_db(wf_inputs.sigma_a_example(), wf_inputs.IN.sigma_t_large)
        + 10 * math.log10(3)
    )


@register(
    "wf04-prior-instead-shift-db",
    "wf/04-assessment",
    "largest change of a Fig. 1-2 curve if P_DL were the prior P_DL(k/k-1) (dB)",
)
def wf_prior_instead_shift_db() -> float:
    """Largest change (dB) of a curve of WF Figs. 1-2 if the accelerometer's prior replaced its posterior."""
    import numpy as np

    from navcore.estimation.federated import accelerometer_steady_state_isotropic, minkowski_trace_bound
    from navcore.papers import wf_assessment, wf_inputs

    shift = 0.0
    for sa in wf_assessment.sigma_a_grid():
        prior = accelerometer_steady_state_isotropic(
            sa, wf_inputs.IN.ts, wf_inputs.IN.sigma_l_per_sigma_a * sa
        ).prior
        for st in wf_inputs.sigma_t_values():
            for ns in wf_assessment.SATELLITE_CASES:
                Ps = wf_assessment.local_covariances(sa, st, ns)
                alt = [Ps[0], prior * np.eye(3), *Ps[2:]]
                shift = max(
                    shift, abs(10 * math.log10(minkowski_trace_bound(alt) / minkowski_trace_bound(Ps)))
                )
    return float(shift)


@register(
    "wf04-sigma-dl-max",
    "wf/04-assessment",
    "steady-state sigma of the Eq. (14) filter at the 10 mm/s^2 end (m/s)",
)
def wf_sigma_dl_max() -> float:
    """Steady-state per-axis sigma of WF Eq. (14) at the medium-resolution end of Sec. IV.D, m/s."""
    from navcore.estimation.federated import accelerometer_steady_state_isotropic
    from navcore.papers import wf_inputs

    sa = wf_inputs.IN.sigma_a_high
    return float(
        math.sqrt(
            accelerometer_steady_state_isotropic(
                sa, wf_inputs.IN.ts, wf_inputs.IN.sigma_l_per_sigma_a * sa
            ).posterior
        )
    )


@register("wf04-gps-velocity-sigma", "wf/04-assessment", "velocity sigma equivalent to sigma_G = 1 Hz (m/s)")
def wf_gps_velocity_sigma() -> float:
    """Line-of-sight velocity sigma equivalent to WF's 1 Hz GPS Doppler noise, m/s."""
    from navcore.papers import wf_assessment

    return float(wf_assessment.gps_doppler_velocity_sigma())


@register(
    "wf04-gps-velocity-over-sigma-n",
    "wf/04-assessment",
    "GPS-equivalent velocity sigma over the navigation sigma_N",
)
def wf_gps_velocity_over_sigma_n() -> float:
    """The GPS-equivalent velocity sigma over WF's navigation velocity accuracy sigma_N."""
    from navcore.papers import wf_assessment, wf_inputs

    return float(wf_assessment.gps_doppler_velocity_sigma() / wf_inputs.IN.sigma_n)


@register(
    "wf04-sigma-d-over-sigma-n",
    "wf/04-assessment",
    "fused bound at 100 ug, sigma_T = 2 m/s, over sigma_N",
)
def wf_sigma_d_over_sigma_n() -> float:
    """Per-axis fused bound of WF Eq. (23) at 100 ug and sigma_T = 2 m/s over sigma_N."""
    from navcore.papers import wf_assessment, wf_inputs

    return float(
        wf_assessment.sigma_d_bound(wf_inputs.sigma_a_example(), wf_inputs.IN.sigma_t_large)
        / wf_inputs.IN.sigma_n
    )


@register(
    "wf04-gps-gain-max-db", "wf/04-assessment", "largest GPS gain of Fig. 2 over Fig. 1, stated range (dB)"
)
@register("wf89-gps-gain", "wf/89-summary", "largest GPS gain of Fig. 2 over Fig. 1, stated range (dB)")
def wf_gps_gain_max_db() -> float:
    """Largest improvement (dB) the GPS estimate adds to the Fig. 1 bound: any sigma_T, one or three
    satellites, the stated sigma_a range."""
    import numpy as np

    from navcore.papers import wf_assessment, wf_inputs

    c = wf_assessment.improvement_curves()
    return float(
        max(
            np.max(c[(st, 0)] - c[(st, ns)])
            for st in wf_inputs.sigma_t_values()
            for ns in wf_assessment.GPS_CASES
        )
    )


@register(
    "wf04-three-vs-one-db",
    "wf/04-assessment",
    "largest difference of three satellites and one, sigma_T = 0 (dB)",
)
def wf_three_vs_one_db() -> float:
    """Largest |three-satellite - one-satellite| difference of Fig. 2 at sigma_T = 0, stated range, dB."""
    import numpy as np

    from navcore.papers import wf_assessment, wf_inputs

    c = wf_assessment.improvement_curves()
    st = wf_inputs.IN.sigma_t_small
    return float(np.max(np.abs(c[(st, 3)] - c[(st, 1)])))


#: The page's example of a severe accelerometer beyond the stated range, m/s^2.
WF04_WIDE_SIGMA_A = 0.3


@register(
    "wf04-gps-gain-wide-db",
    "wf/04-assessment",
    "GPS gain with three satellites at 0.3 m/s^2 and sigma_T = 2 m/s (dB)",
)
def wf_gps_gain_wide_db() -> float:
    """Improvement (dB) three satellites add at sigma_a = 0.3 m/s^2, sigma_T = 2 m/s."""
    from navcore.papers import wf_assessment, wf_inputs

    st = wf_inputs.IN.sigma_t_large
    return float(
        wf_assessment.improvement_db(WF04_WIDE_SIGMA_A, st, 0)
        - wf_assessment.improvement_db(WF04_WIDE_SIGMA_A, st, 3)
    )


@register(
    "wf89-leverage-z",
    "wf/89-summary",
    "emitter error from a constant 1 m/s vertical velocity error over that from 1 m (s)",
)
def wf_leverage_z() -> float:
    """Emitter-location error (WF Eq. (6)) from a constant 1 m/s aperture-velocity error along z
    over that from a constant 1 m position error along z, s."""
    from navcore.papers import wf_aperture_velocity

    lev = wf_aperture_velocity.location_error_leverage()
    return float(lev["bias_v"][2] / lev["bias_p"][2])


@register(
    "wf89-leverage-white",
    "wf/89-summary",
    "emitter error from independent 1 m/s velocity errors over that from 1 m errors (s)",
)
def wf_leverage_white() -> float:
    """RMS emitter-location error (WF Eq. (6)) from independent 1 m/s velocity errors per axis and
    sample over that from independent 1 m position errors, s."""
    from navcore.papers import wf_aperture_velocity

    lev = wf_aperture_velocity.location_error_leverage()
    return float(lev["white_v"] / lev["white_p"])


@register(
    "wf89-eq13-ratio",
    "wf/89-summary",
    "final RMS error of Eq. (13) as printed over sqrt(P_DL(k/k))",
)
def wf_eq13_ratio() -> float:
    """Final RMS error of WF Eq. (13) run as printed (seeded) over the Eq. (14) sigma."""
    from navcore.papers import wf_local_estimators

    return float(wf_local_estimators.eq13_printed_error_ratio())


@register(
    "wf89-eq20-block",
    "wf/89-summary",
    "largest entry of Eq. (20)'s printed block (2, 3) minus P_LG, over the largest of the joint",
)
def wf_eq20_block() -> float:
    """How far WF Eq. (20)'s printed block (2, 3), P_NG, is from the L-G cross-covariance (seeded joint)."""
    from navcore.papers import wf_federated_fusion

    return float(wf_federated_fusion.eq20_printed_block_error())


@register(
    "wf89-eq24-ratio",
    "wf/89-summary",
    "sigma_DN of Eq. (24) read literally, computed in cm/s over computed in m/s",
)
def wf_eq24_ratio() -> float:
    """WF Eq. (24) read literally: sigma_DN computed in cm/s (converted) over sigma_DN computed in m/s."""
    from navcore.papers import wf_assessment

    return float(wf_assessment.eq24_literal_unit_ratio())


# --- model values: Wu & Fowler's worked example (a seeded simulation of 20 flights) -----------


@register(
    "wf05-sigma-dl", "wf/05-end-to-end", "steady-state sigma of the accelerometer filter at 100 ug (m/s)"
)
def wf05_sigma_dl() -> float:
    """Steady-state per-axis sigma of the worked example's accelerometer filter (WF Eq. (14)), m/s."""
    from navcore.papers import wf_example as ex

    return float(ex.run()["sigma_dl"])


@register(
    "wf05-vib-rms", "wf/05-end-to-end", "RMS vertical velocity of the simulated wing-tip vibration (m/s)"
)
def wf05_vib_rms() -> float:
    """RMS of the vertical aperture velocity the worked example's vibration adds, over its flights, m/s."""
    from navcore.papers import wf_example as ex

    return float(ex.run()["vib_rms"])


@register(
    "wf05-uz",
    "wf/05-end-to-end",
    "RMS vertical component of the unit line of sight over the Sec. II turn",
)
def wf05_uz_rms() -> float:
    """RMS over the Sec. II turn's samples of the vertical component of the unit line of sight."""
    import numpy as np

    from navcore.papers import wf_location_error

    _, pos, _ = wf_location_error.orbit()
    u_z = np.abs(pos[:, 2] - wf_location_error.EMITTER[2]) / np.linalg.norm(
        pos - wf_location_error.EMITTER, axis=1
    )
    return float(np.sqrt(np.mean(u_z**2)))


@register(
    "wf05-freq-err",
    "wf/05-end-to-end",
    "RMS frequency error from the vibration along the line of sight (Hz)",
)
def wf05_freq_err() -> float:
    """Frequency error (Hz RMS) the unseen vertical vibration causes: f0/c times its RMS velocity times
    the RMS vertical line-of-sight component."""
    from navcore import units
    from navcore.papers import wf_location_error

    return float(wf_location_error.F0 / units.C * wf05_vib_rms() * wf05_uz_rms())


@register(
    "wf05-freq-err-over-noise",
    "wf/05-end-to-end",
    "the vibration's frequency error over the frequency measurement noise",
)
def wf05_freq_err_over_noise() -> float:
    """The vibration's RMS frequency error over the 1 Hz frequency-measurement noise."""
    from navcore.papers import wf_location_error

    return float(wf05_freq_err() / wf_location_error.SIGMA_F)


#: The page's Euler illustration: 60 s of a sinusoid sampled at T_s.
WF05_EULER_SECONDS = 60.0


@register(
    "wf05-euler-point-rms",
    "wf/05-end-to-end",
    "RMS error of Euler-integrating point samples of the vibration's acceleration (m/s)",
)
def wf05_euler_point_rms() -> float:
    """Standard deviation of the velocity error when point samples of a sinusoidal acceleration (the
    vibration's frequency and RMS velocity) are Euler-integrated at T_s for 60 s, m/s."""
    import numpy as np

    from navcore.papers import wf_example as ex

    ts, f_vib = ex.IN.ts, ex.IN.vib_hz
    t = np.arange(round(WF05_EULER_SECONDS / ts) + 1) * ts
    amp = math.sqrt(2) * wf05_vib_rms()
    v_true = amp * np.sin(2 * np.pi * f_vib * t)
    a_point = amp * 2 * np.pi * f_vib * np.cos(2 * np.pi * f_vib * t)
    v_euler = np.concatenate([[0.0], np.cumsum(a_point[:-1] * ts)])
    return float(np.std(v_euler - v_true))


def _wf05_velocity_rms(case: str) -> float:
    import numpy as np

    from navcore.papers import wf_example as ex

    return float(np.sqrt(np.mean(ex.run()["vel_err"][case] ** 2)))


@register(
    "wf05-fed-vel-mm",
    "wf/05-end-to-end",
    "RMS per axis of the federated aperture-velocity error over the flights (mm/s)",
)
def wf05_fed_vel_mm() -> float:
    """RMS per axis of the worked example's federated aperture-velocity error, mm/s."""
    return 1e3 * _wf05_velocity_rms("federated")


@register(
    "wf05-vel-gain-db",
    "wf/05-end-to-end",
    "navigation-only over federated velocity RMS (dB)",
)
def wf05_vel_gain_db() -> float:
    """20 log10 of the navigation-only over the federated velocity RMS of the worked example, dB."""
    return float(20 * math.log10(_wf05_velocity_rms("navigation") / _wf05_velocity_rms("federated")))


def _wf05_horizontal_location_rms(case: str) -> float:
    """Horizontal emitter-location RMS (m) of the worked example's flights with one aperture velocity."""
    from navcore.papers import wf_example as ex

    return {row[0]: row[2] for row in ex.summary_rows()}[case]


@register(
    "wf05-loc-nav-over-{other}",
    "wf/05-end-to-end",
    "horizontal location RMS with the navigation-only velocity over that with the true or federated one",
)
def wf05_loc_nav_over(other: str) -> float:
    """Horizontal emitter-location RMS of the worked example with the navigation-only aperture
    velocity over that with the true (``other="true"``) or the federated (``"fed"``) one."""
    case = {"true": "true", "fed": "federated"}[other]
    return float(_wf05_horizontal_location_rms("navigation") / _wf05_horizontal_location_rms(case))


# --- model values: ATC-10 Section 2, the jamming model's thresholds ---------------------------


@register(
    "atc10-pf-k1000-0.999",
    "atc10/10-jamming-model",
    "per-filter false-alarm probability at the N_ADL threshold, K = 1000, P_DL = 0.999",
)
def atc10_pf_k1000_0999() -> float:
    """p_f at the t = 0 N_ADL = 0.01 N_T threshold for K = 1000, P_DL = 0.999 (ATC-10 Sec. 2.5)."""
    from navcore.papers import atc10_tracking_lists as pj

    return float(math.exp(pj.threshold_log_pf(0.999, 1000)))


@register(
    "atc10-10-pf-K1-0.88",
    "atc10/10-jamming-model",
    "per-filter false-alarm probability at the N_ADL threshold, K = 1, P_DL = 0.88",
)
@register(
    "atc10-pf-threshold-K1-0.88",
    "atc10/14-monte-carlo",
    "per-filter false-alarm probability at the N_ADL threshold, K = 1, P_DL = 0.88",
)
def atc10_pf_k1_088() -> float:
    """p_f at the t = 0 N_ADL = 0.01 N_T threshold for K = 1, P_DL = 0.88 (ATC-10 Sec. 2.5)."""
    from navcore.papers import atc10_tracking_lists as pj

    return float(math.exp(pj.threshold_log_pf(0.88, 1)))


@register(
    "atc10-10-printed-c1-ln-K1-0.88",
    "atc10/10-jamming-model",
    "2 B alpha ln(1 - p_f) at the K = 1, P_DL = 0.88 threshold (the printed (C.1)'s exponent)",
)
def atc10_printed_c1_ln_k1_088() -> float:
    """The exponent 2 B alpha ln(1 - p_f) of (C.1) at the K = 1, P_DL = 0.88 threshold."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.geometry().samples_per_period * math.log1p(-atc10_pf_k1_088()))


@register(
    "atc10-erp-half-K{k}-{p_dl}",
    "atc10/10-jamming-model",
    "jammer ERP at which N_ADL reaches 0.01 N_T with half as many independent samples (dBW)",
)
def atc10_erp_half_samples(k: str, p_dl: str) -> float:
    """Jammer ERP (dBW) of the t = 0 N_ADL threshold when every window holds half the samples."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.adl_erp_dbw_half_samples(float(p_dl), int(k)))


#: The design points of the page's half-samples sensitivity: K = 1 over its P_DL grid, K = 10 at
#: Table 2.1's two P_DL.
ATC10_HALF_SHIFT_POINTS = ((1, (0.88, 0.9, 0.99, 0.999)), (10, (0.88, 0.999)))


@register(
    "atc10-half-shift-small-k",
    "atc10/10-jamming-model",
    "largest rise of the N_ADL threshold with half the samples, K = 1 and 10 (dB)",
)
def atc10_half_shift_small_k() -> float:
    """Largest rise (dB) of the t = 0 N_ADL threshold when the sample counts are halved, K = 1 and 10."""
    from navcore.papers import atc10_jamming as pj

    return float(
        max(
            pj.adl_erp_dbw_half_samples(p, k) - pj.required_erp_dbw("ambiguous", p, k)
            for k, ps in ATC10_HALF_SHIFT_POINTS
            for p in ps
        )
    )


@register(
    "atc10-pdl-factor-shift",
    "atc10/10-jamming-model",
    "largest drop of the N_ADL threshold without the P_DL factor of (2.5.12) (dB)",
)
def atc10_pdl_factor_shift() -> float:
    """Largest drop (dB) of the N_ADL threshold when the P_DL factor of (2.5.12) is dropped."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.max_pdl_factor_shift_db())


@register(
    "atc10-v-alpha-over-c-us",
    "atc10/10-jamming-model",
    "v alpha / c, the delay an aircraft's motion adds over a repetition period (us)",
)
def atc10_v_alpha_over_c_us() -> float:
    """v alpha / c of ATC-10's scenario (the largest speed over a repetition period), in microseconds."""
    from navcore import units
    from navcore.papers import atc10_jamming as pj

    g = pj.geometry()
    return float(g.max_speed_m_s * g.repetition_s / units.C * 1e6)


@register(
    "atc10-11-adl-erp-0.9",
    "atc10/11-single-pulse",
    "jammer ERP at which N_ADL reaches 0.01 N_T, K = 1, P_DL = 0.9 (dBW)",
)
def atc10_11_adl_erp_09() -> float:
    """Jammer ERP (dBW) of the t = 0 N_ADL threshold for K = 1, P_DL = 0.9 (Fig. 2.1)."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.required_erp_dbw("ambiguous", 0.9, 1))


def _atc10_k1_gap(quantity: str) -> float:
    from navcore.papers import atc10_jamming as pj

    return float(pj.required_erp_dbw(quantity, 0.9, 1) - pj.required_erp_dbw(quantity, 0.999, 1))


@register(
    "atc10-11-gap-adl",
    "atc10/11-single-pulse",
    "N_ADL threshold at P_DL = 0.9 minus that at 0.999, K = 1 (dB)",
)
def atc10_11_gap_adl() -> float:
    """How much more ERP the N_ADL threshold needs at P_DL = 0.9 than at 0.999, K = 1, dB."""
    return _atc10_k1_gap("ambiguous")


@register(
    "atc10-11-fl-level-spread",
    "atc10/11-single-pulse",
    "N_FL threshold at 99.9 % of its supremum minus that at 50 %, K = 1, P_DL = 0.88 (dB)",
)
def atc10_11_fl_level_spread() -> float:
    """Width (dB) of the N_FL rise: the threshold at 99.9 % of the supremum 0.9 N_T minus that at
    50 %, K = 1, P_DL = 0.88 (t = 0)."""
    from navcore.detection import jamming as jm
    from navcore.papers import atc10_jamming as pj

    g = pj.geometry()
    p_d = pj.design_p_d(0.88, 1)
    sup = 1.0 - g.airborne_fraction
    x50, x999 = (jm.jammer_ratio_threshold_db("false", f * sup, p_d, 1, 0.0, g) for f in (0.5, 0.999))
    return float(x999 - x50)


# --- ATC-10 Sec. 2.8, the tracking lists (Table 2.1) ------------------------------------------


def _atc10_x_db(p_dl: float, k: int, geometry: Any = None) -> float:
    """10 log10 J/(P0 B tau) of the t = 0 N_ADL = 0.01 N_T threshold."""
    from navcore.detection import jamming as jm
    from navcore.papers import atc10_jamming as pj

    g = pj.geometry() if geometry is None else geometry
    return float(
        jm.jammer_ratio_threshold_db("ambiguous", pj.IN.adl_level, pj.design_p_d(p_dl, k), k, 0.0, g)
    )


@register(
    "atc10-12-fig2.4-x",
    "atc10/12-tracking-lists",
    "J/(P0 B tau) of the N_ADL threshold, K = 10, P_DL = 0.88 (dB)",
)
def atc10_12_fig24_x() -> float:
    """10 log10 J/(P0 B tau) at which N_ADL reaches 0.01 N_T, K = 10, P_DL = 0.88 (Fig. 2.4)."""
    return _atc10_x_db(0.88, 10)


@register(
    "atc10-12-fig2.16-x",
    "atc10/12-tracking-lists",
    "J/(P0 B tau) of the N_ADL threshold, K = 1000, P_DL = 0.999 (dB)",
)
def atc10_12_fig216_x() -> float:
    """10 log10 J/(P0 B tau) at which N_ADL reaches 0.01 N_T, K = 1000, P_DL = 0.999 (Fig. 2.16)."""
    return _atc10_x_db(0.999, 1000)


@register(
    "atc10-12-ceiling-K1000-{p_dl}",
    "atc10/12-tracking-lists",
    "supremum of N_ADL / N_T as the jammer grows, K = 1000",
)
def atc10_12_ceiling_k1000(p_dl: str) -> float:
    """Supremum of the N_ADL bound (2.5.12) over jammer power (p_f -> p_d), K = 1000, t = 0."""
    from navcore.detection import jamming as jm
    from navcore.papers import atc10_jamming as pj

    return float(
        math.exp(
            jm.log_ambiguous_detection_ceiling(pj.design_p_d(float(p_dl), 1000), 1000, 0.0, pj.geometry())
        )
    )


def _atc10_threshold_pf(quantity: str, p_dl: float, k: int) -> float:
    """p_f at the t = 0 threshold of ``quantity`` for the design point (P_DL, K)."""
    from navcore.detection import jamming as jm
    from navcore.detection import neyman_pearson as npd
    from navcore.papers import atc10_jamming as pj

    g = pj.geometry()
    x_db = pj.required_erp_dbw(quantity, p_dl, k) - float(
        jm.jammer_erp_dbw(0.0, g.pulse_energy_j, g.bandwidth_hz)
    )
    return float(
        npd.false_alarm_probability(
            pj.design_p_d(p_dl, k), npd.detection_index_from_jammer_ratio(10 ** (x_db / 10))
        )
    )


def _atc10_fl_erps() -> list[float]:
    from navcore.papers import atc10_jamming as pj

    return [float(pj.required_erp_dbw("false", p, k)) for k, p, _, _ in pj.TABLE_2_1]


@register(
    "atc10-12-fl-erp-lo", "atc10/12-tracking-lists", "lowest N_FL threshold over Table 2.1's rows (dBW)"
)
def atc10_12_fl_erp_lo() -> float:
    """Lowest t = 0 N_FL threshold (jammer ERP, dBW) over Table 2.1's design points."""
    return min(_atc10_fl_erps())


@register(
    "atc10-12-fl-erp-hi", "atc10/12-tracking-lists", "highest N_FL threshold over Table 2.1's rows (dBW)"
)
def atc10_12_fl_erp_hi() -> float:
    """Highest t = 0 N_FL threshold (jammer ERP, dBW) over Table 2.1's design points."""
    return max(_atc10_fl_erps())


@register(
    "atc10-12-fl-pf", "atc10/12-tracking-lists", "median p_f at the N_FL thresholds of Table 2.1's rows"
)
def atc10_12_fl_pf() -> float:
    """Median per-filter p_f at the t = 0 N_FL thresholds of Table 2.1's design points."""
    import numpy as np

    from navcore.papers import atc10_jamming as pj

    return float(np.median([_atc10_threshold_pf("false", p, k) for k, p, _, _ in pj.TABLE_2_1]))


def _atc10_adl_pfs() -> list[float]:
    from navcore.papers import atc10_jamming as pj

    return [_atc10_threshold_pf("ambiguous", p, k) for k, p, _, rel in pj.TABLE_2_1 if rel == "="]


@register(
    "atc10-12-adl-pf-lo", "atc10/12-tracking-lists", "lowest p_f at the finite N_ADL thresholds of Table 2.1"
)
def atc10_12_adl_pf_lo() -> float:
    """Lowest per-filter p_f at the finite t = 0 N_ADL thresholds of Table 2.1."""
    return min(_atc10_adl_pfs())


@register(
    "atc10-12-adl-pf-hi", "atc10/12-tracking-lists", "highest p_f at the finite N_ADL thresholds of Table 2.1"
)
def atc10_12_adl_pf_hi() -> float:
    """Highest per-filter p_f at the finite t = 0 N_ADL thresholds of Table 2.1."""
    return max(_atc10_adl_pfs())


@register(
    "atc10-12-k1000-critical",
    "atc10/12-tracking-lists",
    "smallest P_DL at which the K = 1000 N_ADL ceiling reaches 0.01 N_T",
)
def atc10_12_k1000_critical() -> float:
    """Smallest P_DL whose K = 1000 N_ADL ceiling reaches 0.01 N_T (t = 0)."""
    from navcore.papers import atc10_tracking_lists as pj

    return float(pj.k1000_critical_p_dl())


@register(
    "atc10-12-erp-K1000-0.999",
    "atc10/12-tracking-lists",
    "jammer ERP at which N_ADL reaches 0.01 N_T, K = 1000, P_DL = 0.999 (dBW)",
)
def atc10_12_erp_k1000_0999() -> float:
    """Jammer ERP (dBW) of the t = 0 N_ADL threshold for K = 1000, P_DL = 0.999 (Table 2.1)."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.required_erp_dbw("ambiguous", 0.999, 1000))


def _atc10_printed_k1000_0999() -> float:
    from navcore.papers import atc10_jamming as pj

    return float(next(text for k, p, text, _ in pj.TABLE_2_1 if (k, p) == (1000, 0.999)))


@register(
    "atc10-12-K1000-below-printed",
    "atc10/12-tracking-lists",
    "how far the K = 1000, P_DL = 0.999 threshold lies below Table 2.1's 77 dBW (dB)",
)
def atc10_12_k1000_below_printed() -> float:
    """Table 2.1's printed K = 1000, P_DL = 0.999 entry minus the computed threshold, dB."""
    return _atc10_printed_k1000_0999() - atc10_12_erp_k1000_0999()


def _atc10_ln_adl_k1000_0999(erp_dbw: float) -> float:
    from navcore.detection import jamming as jm
    from navcore.papers import atc10_jamming as pj

    g = pj.geometry()
    erp0 = float(jm.jammer_erp_dbw(0.0, g.pulse_energy_j, g.bandwidth_hz))
    return float(
        jm.log_ambiguous_detection_bound(
            10 ** ((erp_dbw - erp0) / 10), pj.design_p_d(0.999, 1000), 1000, 0.0, g
        )
    )


@register(
    "atc10-12-K1000-slope",
    "atc10/12-tracking-lists",
    "slope of ln N_ADL at the K = 1000, P_DL = 0.999 crossing (per dB)",
)
def atc10_12_k1000_slope() -> float:
    """d ln N_ADL / d ERP at the K = 1000, P_DL = 0.999 crossing, by a +-0.01 dB difference, per dB."""
    erp = atc10_12_erp_k1000_0999()
    return (_atc10_ln_adl_k1000_0999(erp + 0.01) - _atc10_ln_adl_k1000_0999(erp - 0.01)) / 0.02


@register(
    "atc10-12-K1000-misread-pct",
    "atc10/12-tracking-lists",
    "N_ADL at the printed 77 dBW over the 0.01 N_T level, minus 1 (%)",
)
def atc10_12_k1000_misread_pct() -> float:
    """How far above the 0.01 N_T level N_ADL is at Table 2.1's printed 77 dBW (K = 1000, 0.999), %."""
    from navcore.papers import atc10_jamming as pj

    return float(
        100 * (math.exp(_atc10_ln_adl_k1000_0999(_atc10_printed_k1000_0999())) / pj.IN.adl_level - 1)
    )


def _atc10_nv23_shifts() -> dict[tuple[int, float], float]:
    """Shift (dB) of each finite Table 2.1 threshold when the (C.14) window holds 23 samples (the
    mean 23.86 rounded down: the speed scaled, the other counts unchanged)."""
    import dataclasses

    from navcore.papers import atc10_jamming as pj

    g = pj.geometry()
    geom_23 = dataclasses.replace(g, max_speed_m_s=g.max_speed_m_s * 23 / g.samples_per_track_window)
    return {
        (k, p): _atc10_x_db(p, k, geom_23) - _atc10_x_db(p, k) for k, p, _, rel in pj.TABLE_2_1 if rel == "="
    }


@register(
    "atc10-12-nv23-K1000-0.999",
    "atc10/12-tracking-lists",
    "the K = 1000, P_DL = 0.999 threshold with n_v = 23 (dBW)",
)
def atc10_12_nv23_k1000_0999() -> float:
    """Jammer ERP (dBW) of the K = 1000, P_DL = 0.999 threshold with 23 samples in the (C.14) window."""
    return atc10_12_erp_k1000_0999() + _atc10_nv23_shifts()[(1000, 0.999)]


@register(
    "atc10-12-nv23-small-k",
    "atc10/12-tracking-lists",
    "largest shift of a K <= 100 Table 2.1 threshold with n_v = 23 (dB)",
)
def atc10_12_nv23_small_k() -> float:
    """Largest |shift| (dB) of the finite K <= 100 Table 2.1 thresholds with n_v = 23 in (C.14)."""
    return max(abs(v) for (k, _), v in _atc10_nv23_shifts().items() if k <= 100)


@register(
    "atc10-12-erf-coef-model",
    "atc10/12-tracking-lists",
    "coefficient of sqrt(P0 B tau / J) in the erf argument of p_f (the detector model)",
)
def atc10_12_erf_coef_model() -> float:
    """The coefficient c of p_f = 1/2 - 1/2 erf(c sqrt(P0 B tau / J) - phi) in navcore's detector model."""
    from navcore.papers import atc10_tracking_lists as pj

    return float(pj.erf_argument_coefficient())


@register(
    "atc10-12-erf-coef-mc",
    "atc10/12-tracking-lists",
    "the erf argument's coefficient from a seeded Monte Carlo of the matched filter",
)
def atc10_12_erf_coef_mc() -> float:
    """The erf argument's coefficient recovered from a seeded Monte Carlo of matched-filter samples."""
    from navcore.papers import atc10_tracking_lists as pj

    return float(pj.monte_carlo_erf_coefficient())


# --- ATC-10 Sec. 1.1, Table 1.1 (transmission lengths) ----------------------------------------


@register(
    "atc10-erp-by-K-{k}-{p_dl}",
    "atc10/13-tables",
    "jammer ERP at which N_ADL reaches 0.01 N_T for Table 1.1's K (dBW; inf: never)",
)
def atc10_erp_by_k(k: str, p_dl: str) -> float:
    """Jammer ERP (dBW) of the t = 0 N_ADL threshold for Table 1.1's K (``inf`` where none is reached)."""
    from navcore.papers import atc10_jamming as model
    from navcore.papers import atc10_system_tables as pj

    erps = pj.erp_by_transmission_length(float(p_dl))
    return float(erps[model.TABLE_1_1_KS.index(int(k))])


@register(
    "atc10-ceiling-K1000-0.88",
    "atc10/13-tables",
    "supremum of N_ADL / N_T as the jammer grows, K = 1000, P_DL = 0.88",
)
def atc10_13_ceiling_k1000_088() -> float:
    """Supremum of the N_ADL bound over jammer power, K = 1000, P_DL = 0.88, t = 0."""
    return atc10_12_ceiling_k1000("0.88")


@register(
    "atc10-step-K100-K1000-0.999",
    "atc10/13-tables",
    "N_ADL threshold of K = 1000 minus that of K = 100, P_DL = 0.999 (dB)",
)
def atc10_step_k100_k1000_0999() -> float:
    """How much more ERP the t = 0 N_ADL threshold needs at K = 1000 than at K = 100, P_DL = 0.999, dB."""
    from navcore.papers import atc10_jamming as model
    from navcore.papers import atc10_system_tables as pj

    erps = pj.erp_by_transmission_length(0.999)
    ks = model.TABLE_1_1_KS
    return float(erps[ks.index(1000)] - erps[ks.index(100)])


def _atc10_table11_misfits() -> tuple[list[float], list[float]]:
    """|printed - model| of Table 1.1's rf column (dB) and beamwidth column (deg), by row."""
    from navcore.papers import atc10_jamming as pj
    from navcore.papers import atc10_system_tables as tables

    rf = [abs(r - tables.table11_rf_dbw(i)) for i, (_, _, r, _, _) in enumerate(pj.TABLE_1_1)]
    bw = [abs(b - pj.table11_beamwidth_deg(i)) for i, (*_, b) in enumerate(pj.TABLE_1_1)]
    return rf, bw


@register(
    "atc10-13-rf-fit-K10",
    "atc10/13-tables",
    "misfit of the dish model to Table 1.1's K = 10 rf power (dB)",
)
def atc10_13_rf_fit_k10() -> float:
    """|printed - model| rf power of Table 1.1's K = 10 row with the assumed dish, dB."""
    from navcore.papers import atc10_jamming as pj

    return _atc10_table11_misfits()[0][pj.TABLE_1_1_KS.index(10)]


@register(
    "atc10-13-rf-fit-others",
    "atc10/13-tables",
    "largest misfit of the dish model to Table 1.1's other rf powers (dB)",
)
def atc10_13_rf_fit_others() -> float:
    """Largest |printed - model| rf power of Table 1.1's rows other than K = 10, dB."""
    from navcore.papers import atc10_jamming as pj

    i10 = pj.TABLE_1_1_KS.index(10)
    return max(m for i, m in enumerate(_atc10_table11_misfits()[0]) if i != i10)


@register(
    "atc10-13-bw-K1-dish",
    "atc10/13-tables",
    "beamwidth 70 lambda / D of the dish for Table 1.1's K = 1 gain (deg)",
)
def atc10_13_bw_k1_dish() -> float:
    """Beamwidth (deg) 70 lambda / D of the assumed dish with the K = 1 row's gain (ERP - rf)."""
    from navcore.papers import atc10_jamming as pj

    return float(pj.table11_beamwidth_deg(0))


@register(
    "atc10-13-bw-K1-scaled",
    "atc10/13-tables",
    "Sec. 2.7's 20 deg scaled to Table 1.1's K = 1 gain (deg)",
)
def atc10_13_bw_k1_scaled() -> float:
    """Sec. 2.7's printed 20 deg beamwidth scaled by sqrt of the gain ratio to the K = 1 row, deg."""
    from navcore.papers import atc10_system_tables as pj

    return float(pj.table11_k1_beamwidth_scaled_deg())


@register(
    "atc10-13-bw-fit-others",
    "atc10/13-tables",
    "largest misfit of 70 lambda / D to Table 1.1's K = 10-1000 beamwidths (deg)",
)
def atc10_13_bw_fit_others() -> float:
    """Largest |printed - 70 lambda / D| beamwidth of Table 1.1's rows K = 10, 100, 1000, deg."""
    return max(_atc10_table11_misfits()[1][1:])


def _atc10_sec27_gain() -> float:
    """Sec. 2.7's antenna gain, the nominal ERP over the rf power, as a ratio."""
    from navcore import units
    from navcore.papers import atc10_jamming as pj

    return float(units.power_ratio_from_db(pj.IN.nominal_erp_dbw - units.dbw_from_watts(pj.IN.nominal_rf_w)))


@register(
    "atc10-13-30W-gain-db",
    "atc10/13-tables",
    "antenna gain that takes 30 W to 33 dBW (dB)",
)
def atc10_13_30w_gain_db() -> float:
    """Gain (dB) of Sec. 2.7's antenna: 33 dBW of ERP from 30 W of rf power."""
    return float(10 * math.log10(_atc10_sec27_gain()))


def _atc10_2ft_gain_db() -> float:
    from navcore import units
    from navcore.detection import antenna
    from navcore.papers import atc10_jamming as pj

    return float(
        10
        * math.log10(float(antenna.dish_gain(2 * units.FT, pj.IN.dish_frequency_hz, pj.IN.dish_efficiency)))
    )


@register(
    "atc10-13-2ft-gain-db",
    "atc10/13-tables",
    "gain of a 2 ft dish at the assumed frequency and efficiency (dB)",
)
def atc10_13_2ft_gain_db() -> float:
    """Gain (dB) of a 2 ft dish at the assumed frequency and efficiency of Table 1.1's dishes."""
    return _atc10_2ft_gain_db()


@register(
    "atc10-13-2ft-rf-w",
    "atc10/13-tables",
    "rf power a 2 ft dish needs for 33 dBW (W)",
)
def atc10_13_2ft_rf_w() -> float:
    """rf power (W) that gives Sec. 2.7's 33 dBW through a 2 ft dish."""
    from navcore import units
    from navcore.papers import atc10_jamming as pj

    return float(units.power_ratio_from_db(pj.IN.nominal_erp_dbw - _atc10_2ft_gain_db()))


# --- ATC-10 Appendix B-C checked by simulation: a window of correlated samples -----------------


def _atc10_window_rates() -> Any:
    from navcore.detection import jamming_monte_carlo as mc

    return mc.simulate_window_declarations()


def _atc10_window_ratio(index: int) -> float:
    w = _atc10_window_rates()
    return float(w.empty_correlated[index] / w.empty_formula[index])


@register(
    "atc10-mc-window-ratio-hi",
    "atc10/14-monte-carlo",
    "simulated empty-window probability, correlated samples, over (1 - p_f)^n at the largest p_f",
)
def atc10_mc_window_ratio_hi() -> float:
    """Simulated empty-window probability of correlated samples over (1 - p_f)^n, largest p_f."""
    import numpy as np

    return _atc10_window_ratio(int(np.argmax(_atc10_window_rates().p_f)))


@register(
    "atc10-mc-window-ratio-lo",
    "atc10/14-monte-carlo",
    "simulated empty-window probability, correlated samples, over (1 - p_f)^n at the smallest p_f",
)
def atc10_mc_window_ratio_lo() -> float:
    """Simulated empty-window probability of correlated samples over (1 - p_f)^n, smallest p_f."""
    return _atc10_window_ratio(0)


@register(
    "atc10-mc-window-dln-k1000",
    "atc10/14-monte-carlo",
    "change of ln N_ADL at K = 1000 with (C.14)'s track-window factors at the simulated correlated value",
)
def atc10_mc_window_dln_k1000() -> float:
    """3 (K - 1) [ln(1 - e_c) - ln(1 - e_f)] at K = 1000 and the largest simulated p_f: how ln N_ADL
    moves if the track-window factors of (C.14) used the simulated correlated empty probability e_c."""
    import numpy as np

    w = _atc10_window_rates()
    i = int(np.argmax(w.p_f))
    return float(3 * 999 * (math.log1p(-w.empty_correlated[i]) - math.log1p(-w.empty_formula[i])))


@register(
    "atc10-mc-window-factor-k1000",
    "atc10/14-monte-carlo",
    "factor on N_ADL at K = 1000 from the simulated correlated window",
)
def atc10_mc_window_factor_k1000() -> float:
    """exp of :func:`atc10_mc_window_dln_k1000`: the factor on N_ADL at K = 1000."""
    return float(math.exp(atc10_mc_window_dln_k1000()))


@register(
    "atc10-mc-window-n",
    "atc10/14-monte-carlo",
    "samples in the simulated window, about the track window of (C.14)",
)
def atc10_mc_window_n() -> int:
    """Samples in the window of the seeded correlated-noise simulation."""
    return int(_atc10_window_rates().n)


@register(
    "atc10-mc-window-pf-hi",
    "atc10/14-monte-carlo",
    "largest per-sample false-alarm probability of the window simulation, near the K = 1000 threshold",
)
def atc10_mc_window_pf_hi() -> float:
    """Largest per-sample p_f of the window simulation's grid."""
    return float(max(_atc10_window_rates().p_f))


@register(
    "atc10-14-detection-t13-min",
    "atc10/14-monte-carlo",
    "smallest simulated first-stage detection rate, K = 3, t = 1/3, P_DL = 0.9",
)
def atc10_14_detection_t13_min() -> float:
    """Smallest simulated first-stage detection rate over the jammer grid for K = 3 lists, the
    rule 'more than K t non-empty' with t = 1/3, designed by (2.4.2) for P_DL = 0.9."""
    from navcore.detection import jamming_monte_carlo as mc

    return float(next(r for r in mc.simulate() if r.k == 3 and r.t > 0).detection.min())


def _atc10_exact_window_ratio(end: str) -> float:
    from navcore.papers import atc10_jamming as cj
    from navcore.papers import atc10_jamming_appendices as appendices

    rho = cj.IN_COV.input("neighbour_correlation")
    return float(appendices._window_empty_ratio(float(getattr(rho, end))))


@register(
    "atc10-14-exact-window-ratio-lo",
    "atc10/14-monte-carlo",
    "exact empty-window probability of the 24-sample track window over (1 - p_f)^24, neighbours "
    "correlated at the low end of the assumed range",
)
def atc10_exact_window_ratio_lo() -> float:
    """P(no declaration in the 24-sample window) over (1 - p_f)^24 at the Table 2.1 threshold p_f,
    neighbouring samples correlated at the low end of the assumed neighbour correlation (Genz)."""
    return _atc10_exact_window_ratio("low")


@register(
    "atc10-14-exact-window-ratio-hi",
    "atc10/14-monte-carlo",
    "exact empty-window probability of the 24-sample track window over (1 - p_f)^24, neighbours "
    "correlated at the high end of the assumed range",
)
def atc10_exact_window_ratio_hi() -> float:
    """As :func:`atc10_exact_window_ratio_lo`, at the high end of the assumed neighbour correlation."""
    return _atc10_exact_window_ratio("high")


# --- ATC-10 Sec. 3.9 and App. F: the Zakai bandwidth of PSK codes -----------------------------

#: The page's Appendix F example: a 31-chip random wanted code and four random interferers (seed 1).
ATC10_F5_CHIPS, ATC10_F5_INTERFERERS, ATC10_F5_SEED = 31, 4, 1
#: The page's random 1023-chip codes: 20 of them, seed 3.
ATC10_RANDOM_CODES, ATC10_RANDOM_SEED = 20, 3


def _atc10_f5_codes() -> tuple[Any, list[Any]]:
    import numpy as np

    rng = np.random.default_rng(ATC10_F5_SEED)
    ci = rng.choice([-1.0, 1.0], ATC10_F5_CHIPS)
    return ci, [rng.choice([-1.0, 1.0], ATC10_F5_CHIPS) for _ in range(ATC10_F5_INTERFERERS)]


@register(
    "atc10-23-f5-power",
    "atc10/23-zakai-bandwidth",
    "cross-term noise power of (F.6) for the page's random 31-chip codes (alpha = chip = 1)",
)
def atc10_23_f5_power() -> float:
    """E(n^2) of ATC-10 Eq. (F.6), (1 / 2 alpha) sum_j int R_ii R_jj, for the page's seeded codes."""
    from navcore.detection import zakai

    ci, cjs = _atc10_f5_codes()
    return float(zakai.cross_term_noise_power(ci, cjs, 1.0, 1.0))


@register(
    "atc10-23-f5-bound",
    "atc10/23-zakai-bandwidth",
    "the Zakai-bandwidth bound on that noise power (alpha = chip = 1)",
)
def atc10_23_f5_bound() -> float:
    """sum_j 1 / (4 alpha sqrt(W_i W_j)), the bound of App. F through the codes' Zakai bandwidths."""
    from navcore.detection import zakai

    ci, cjs = _atc10_f5_codes()
    return float(
        zakai.zakai_noise_power_bound(
            zakai.psk_zakai_bandwidth(ci, 1.0), [zakai.psk_zakai_bandwidth(c, 1.0) for c in cjs], 1.0
        )
    )


@register(
    "atc10-23-w-random-1023",
    "atc10/23-zakai-bandwidth",
    "mean Zakai bandwidth of 20 random 1023-chip codes (per chip rate)",
)
def atc10_23_w_random_1023() -> float:
    """Mean Zakai bandwidth (unit chips) of the page's 20 seeded random 1023-chip codes."""
    import numpy as np

    from navcore.detection import zakai

    rng = np.random.default_rng(ATC10_RANDOM_SEED)
    return float(
        np.mean(
            [zakai.psk_zakai_bandwidth(rng.choice([-1.0, 1.0], 1023), 1.0) for _ in range(ATC10_RANDOM_CODES)]
        )
    )


@register(
    "atc10-23-thm-ratio",
    "atc10/23-zakai-bandwidth",
    "1 / (4 W tau_c) of the idealised autocorrelation",
)
def atc10_23_thm_ratio() -> float:
    """1 / (4 W tau_c) for the idealised Fig. 3.11 autocorrelation, L = 10 000 chips."""
    from navcore.papers import atc10_zakai_bandwidth as pm

    return float(1 / (4 * pm.w_chip_limit_ideal()))


# --- ATC-10 Sec. 3.8: Reference [1]'s worked example ------------------------------------------


@register(
    "atc10-22-inverse-p",
    "atc10/22-gaussian-comparison",
    "1 / p of the worked example, p = (N - 1) / (B alpha)",
)
def atc10_22_inverse_p() -> float:
    """1 / p for Reference [1]'s worked example, p = (N - 1) / (B alpha) (end of ATC-10 Sec. 3.8)."""
    from navcore.papers import atc10_multiple_access as pm

    return float(1 / pm.worked_example_power())


@register(
    "atc10-22-exp-g-half",
    "atc10/22-gaussian-comparison",
    "theta^2 / (2 p) of the worked example, as (3.8.8) defines Exp_g",
)
def atc10_22_exp_g_half() -> float:
    """theta^2 / (2 p) with the worked example's theta and p: Exp_g as (3.8.8) defines it."""
    from navcore.papers import atc10_multiple_access as pm

    return float(pm.IN.theta_example**2 / (2 * pm.worked_example_power()))


#: The worked example's other aircraft count of the page: N = 1e5 instead of 2e5.
ATC10_EXAMPLE_N_LOW = 1e5


def _atc10_exp_1e5() -> float:
    from navcore.detection.roc_bounds import exponent_from_gaussian_exponent
    from navcore.papers import atc10_multiple_access as pm

    return float(
        exponent_from_gaussian_exponent(
            ATC10_EXAMPLE_N_LOW, pm.IN.tau_over_alpha_fig310, pm.worked_example_exp_g()
        )
    )


@register(
    "atc10-22-exp-1e5", "atc10/22-gaussian-comparison", "Exp of (3.8.16) at N = 1e5 for the worked example"
)
def atc10_22_exp_1e5() -> float:
    """The exponent Exp of ATC-10 Eq. (3.8.16) at N = 1e5 with the worked example's Exp_g and tau/alpha."""
    return _atc10_exp_1e5()


@register(
    "atc10-22-ratio-1e5", "atc10/22-gaussian-comparison", "Exp_g / Exp at N = 1e5 for the worked example"
)
def atc10_22_ratio_1e5() -> float:
    """Exp_g over the (3.8.16) exponent at N = 1e5: how optimistic the Gaussian assumption is there."""
    from navcore.papers import atc10_multiple_access as pm

    return float(pm.worked_example_exp_g() / _atc10_exp_1e5())


@register(
    "atc10-22-optimistic-pct",
    "atc10/22-gaussian-comparison",
    "how much the Gaussian exponent overstates Exp at N = 2e5 (%)",
)
def atc10_22_optimistic_pct() -> float:
    """100 (Exp_g / Exp - 1) for the worked example at N = 2e5, percent."""
    from navcore.papers import atc10_gaussian_comparison as pm

    return float(100 * (pm.worked_example_ratio() - 1))


@register(
    "atc10-22-pf-factor",
    "atc10/22-gaussian-comparison",
    "exp(Exp_g - Exp): the factor by which the Gaussian assumption understates p_f",
)
def atc10_22_pf_factor() -> float:
    """exp(Exp_g - Exp) at N = 2e5: the factor on p_f that the Gaussian assumption misses."""
    from navcore.papers import atc10_gaussian_comparison as gaussian
    from navcore.papers import atc10_multiple_access as pm

    return float(math.exp(pm.worked_example_exp_g() - gaussian.worked_example_exp()))


@register(
    "atc10-20-psk-1-6L",
    "atc10/20-multiple-access-noise",
    "1 / (6 L) for the L-chip PSK signatures of the physical simulation",
)
def atc10_20_psk_1_6l() -> float:
    """1 / (6 L): the mean square of a random-code PSK interferer's correlation given overlap, L chips."""
    from navcore.papers import atc10_multiple_access as pm

    return float(1 / (6 * pm.IN.psk_chips))


@register(
    "atc10-20-envelope-m3",
    "atc10/20-multiple-access-noise",
    "third moment of the envelope of the paper's amplitude model (the book's skewed envelope)",
)
def atc10_20_envelope_m3() -> float:
    """E[X^3] of the positive, skewed envelope X of the book's reading of the paper's amplitude model."""
    from navcore.papers import atc10_multiple_access as pm

    values, probs = pm._ENVELOPE
    return float(sum(p * v**3 for v, p in zip(values, probs, strict=True)))


@register(
    "atc10-20-model-m3",
    "atc10/20-multiple-access-noise",
    "|third moment| of the paper's amplitude model (zero but for round-off)",
)
def atc10_20_model_m3() -> float:
    """|E[n_ij^3]| of the paper's amplitude model, cos(phase) x envelope: zero to round-off (plus 1e-300,
    so that a log-scale format prints it)."""
    import numpy as np

    from navcore.detection.multiple_access import carrier_phase_density
    from navcore.papers import atc10_multiple_access as pm

    d = carrier_phase_density(*pm._ENVELOPE, n_phases=pm._N_PHASES)
    return abs(float(np.sum(np.asarray(d.weights) * np.asarray(d.values) ** 3))) + 1e-300


#: The stated ranges of the two approximations of Eq. (4.5.38): alpha <= 0.3 and alpha >= 1.
ATC10_PSI_EDGES = (0.3, 1.0)


@register(
    "atc10-31-approx-edge-error-pct",
    "atc10/31-clock-tracking",
    "largest relative error of Eq. (4.5.38)'s approximations of psi at the edges of their ranges (%)",
)
def atc10_31_approx_edge_error_pct() -> float:
    """Largest relative error (%) of the small- and large-alpha forms of psi (Eq. (4.5.38)) at alpha
    = 0.3 and alpha = 1, the edges of their stated ranges."""
    from navcore.location import clock_tracking as ct

    small, large = ATC10_PSI_EDGES
    errors = [
        abs(ct.psi_small_alpha(small) / ct.psi(small) - 1),
        abs(ct.psi_large_alpha(large) / ct.psi(large) - 1),
    ]
    return float(100 * max(errors))


# --- ATC-10 exercises -------------------------------------------------------------------------


def _atc10_90_steps() -> list[float]:
    """Rises (dB) of the t = 0 N_ADL threshold from K = 1 to 10 and from 10 to 100, P_DL = 0.9."""
    from navcore.papers import atc10_jamming as pj

    erp = [pj.required_erp_dbw("ambiguous", 0.9, k) for k in (1, 10, 100)]
    return [float(erp[1] - erp[0]), float(erp[2] - erp[1])]


@register(
    "atc10-90-step-per-decade-lo",
    "atc10/90-exercises",
    "smaller rise of the N_ADL threshold per decade of K, P_DL = 0.9 (dB)",
)
def atc10_90_step_lo() -> float:
    """The smaller of the K = 1 -> 10 and 10 -> 100 rises of the t = 0 N_ADL threshold, P_DL = 0.9, dB."""
    return min(_atc10_90_steps())


@register(
    "atc10-90-step-per-decade-hi",
    "atc10/90-exercises",
    "larger rise of the N_ADL threshold per decade of K, P_DL = 0.9 (dB)",
)
def atc10_90_step_hi() -> float:
    """The larger of the K = 1 -> 10 and 10 -> 100 rises of the t = 0 N_ADL threshold, P_DL = 0.9, dB."""
    return max(_atc10_90_steps())


@register(
    "atc10-90-ceiling-k1000",
    "atc10/90-exercises",
    "supremum of N_ADL / N_T as the jammer grows, K = 1000, P_DL = 0.9",
)
def atc10_90_ceiling_k1000() -> float:
    """Supremum of the N_ADL bound over jammer power, K = 1000, P_DL = 0.9, t = 0."""
    return atc10_12_ceiling_k1000("0.9")


@register(
    "atc10-90-beamwidth-k1",
    "atc10/90-exercises",
    "Sec. 2.7's 20 deg scaled by the pencil-beam rule to Table 1.1's K = 1 gain (deg)",
)
def atc10_90_beamwidth_k1() -> float:
    """20 deg x sqrt(G_2.7 / G_K1): Sec. 2.7's antenna scaled to Table 1.1's K = 1 gain, deg."""
    return atc10_13_bw_k1_scaled()


def _atc10_90_exp(n: float) -> float:
    """Eq. (3.8.16) written out, at N aircraft, tau/alpha = 1e-5 and the worked example's Exp_g."""
    from navcore.papers import atc10_multiple_access as pm

    exp_g, r = pm.worked_example_exp_g(), pm.IN.tau_over_alpha_fig310
    u = exp_g / (n * r)
    return math.sqrt(4 * n * r * exp_g) * math.log(math.sqrt(u) + math.sqrt(1 + u)) - n * math.log(
        (1 - 2 * r) + 2 * r * math.sqrt(1 + u)
    )


@register(
    "atc10-90-exp-{n}", "atc10/90-exercises", "Exp of (3.8.16) for the worked example at N = 1e5 or 2e5"
)
def atc10_90_exp(n: str) -> float:
    """Exp of ATC-10 Eq. (3.8.16) for the worked example, N = ``n`` (``"1e5"`` or ``"2e5"``)."""
    return _atc10_90_exp(float(n))


@register("atc10-90-ratio-{n}", "atc10/90-exercises", "Exp_g / Exp for the worked example at N = 1e5 or 2e5")
def atc10_90_ratio(n: str) -> float:
    """Exp_g over the (3.8.16) exponent for the worked example, N = ``n``."""
    from navcore.papers import atc10_multiple_access as pm

    return float(pm.worked_example_exp_g() / _atc10_90_exp(float(n)))


# --- ATC-10 Sec. 4: the tracking geometry of Table 4.1's examples -----------------------------


def _atc10_geometry_row(example: str, radius: str) -> dict[str, float]:
    """Table 4.2's columns of ``example`` at the synchronous orbit (``"phys"``) or the fitted ratio."""
    from navcore.papers import atc10_tracking_geometry as paper

    r = paper.physical_radius_ratio() if radius == "phys" else paper.fitted_radius_ratio()
    return paper.table_4_2_from_geometry(example, r)


@register(
    "atc10-30-r-phys",
    "atc10/30-tracking-geometry",
    "synchronous-orbit radius over the Earth radius",
)
def atc10_30_r_phys() -> float:
    """Synchronous-orbit radius over the declared Earth radius (ATC-10 Sec. 4.1)."""
    from navcore.papers import atc10_tracking_geometry as paper

    return float(paper.physical_radius_ratio())


@register(
    "atc10-30-zenith-I-{radius}",
    "atc10/30-tracking-geometry",
    "largest zenith angle of Example I's satellites at the aircraft (deg; phys or fit radius)",
)
def atc10_30_zenith_i(radius: str) -> float:
    """Largest zenith angle (deg) of Table 4.1 Example I's satellites seen from the aircraft, at the
    synchronous (``"phys"``) or fitted (``"fit"``) orbit radius."""
    from navcore.papers import atc10_tracking_geometry as paper

    r = paper.physical_radius_ratio() if radius == "phys" else paper.fitted_radius_ratio()
    return float(paper.max_zenith_angle_deg("I", r))


@register(
    "atc10-30-beta-phys-{ex}",
    "atc10/30-tracking-geometry",
    "beta of Eq. (4.5.2) for a Table 4.1 example at the synchronous orbit",
)
def atc10_30_beta_phys(ex: str) -> float:
    """beta = K - 1'F(F'F)^-1 F'1 (Eq. (4.5.2)) of example ``ex`` at the synchronous orbit."""
    return float(_atc10_geometry_row(ex, "phys")["beta"])


@register(
    "atc10-30-beta-over-K-{ex}",
    "atc10/30-tracking-geometry",
    "beta over the number of satellites K, synchronous orbit",
)
def atc10_30_beta_over_k(ex: str) -> float:
    """beta / K of example ``ex`` at the synchronous orbit."""
    from navcore.papers import atc10_tracking_geometry as paper

    return atc10_30_beta_phys(ex) / paper.table_4_1(ex).shape[0]


@register(
    "atc10-30-trace-phys-{ex}",
    "atc10/30-tracking-geometry",
    "position trace tr (F'F)^-1 with all satellites, synchronous orbit",
)
def atc10_30_trace_phys(ex: str) -> float:
    """tr (F'F)^-1 of example ``ex`` with all its satellites at the synchronous orbit."""
    return float(_atc10_geometry_row(ex, "phys")["trace_all"])


@register(
    "atc10-90-123-trace",
    "atc10/90-exercises",
    "position trace of Example II's satellites 1-3, synchronous orbit",
)
@register(
    "atc10-30-trace-123-II",
    "atc10/30-tracking-geometry",
    "position trace of Example II's satellites 1-3, synchronous orbit",
)
def atc10_30_trace_123_ii() -> float:
    """tr (F'F)^-1 of Example II's first three satellites at the synchronous orbit."""
    return float(_atc10_geometry_row("II", "phys")["trace_123"])


@register(
    "atc10-30-s123-invariant-{ex}",
    "atc10/30-tracking-geometry",
    "the invariant 1'(F3 F3')^-1 1 of satellites 1-3 at the fitted radius",
)
@register(
    "atc10-32-s123-invariant-{ex}",
    "atc10/32-tracking-examples",
    "the invariant 1'(F3 F3')^-1 1 of satellites 1-3 at the fitted radius",
)
def atc10_s123_invariant(ex: str) -> float:
    """1'(F3 F3')^-1 1 of example ``ex``'s satellites 1-3 at the fitted radius (the form of erratum
    ATC10-E4.1-three-satellite-clock-term)."""
    return float(_atc10_geometry_row(ex, "fit")["s_123"])


def _atc10_geometry_misses() -> dict[tuple[str, str], float]:
    """Relative misses of the synchronous-orbit beta and traces against Table 4.2 as printed."""
    from navcore.papers import atc10_tracking_geometry as paper

    return {
        (ex, c): _atc10_geometry_row(ex, "phys")[c] / float(paper.TABLE_4_2[ex][c]) - 1
        for ex in ("I", "II")
        for c in ("beta", "trace_all", "trace_123")
    }


@register("atc10-30-miss-lo", "atc10/30-tracking-geometry", "smallest |miss| of the physical geometry (%)")
def atc10_30_miss_lo() -> float:
    """Smallest |relative miss| (%) of the synchronous-orbit beta and traces against Table 4.2."""
    return float(100 * min(abs(v) for v in _atc10_geometry_misses().values()))


@register("atc10-30-miss-hi", "atc10/30-tracking-geometry", "largest |miss| of the physical geometry (%)")
def atc10_30_miss_hi() -> float:
    """Largest |relative miss| (%) of the synchronous-orbit beta and traces against Table 4.2."""
    return float(100 * max(abs(v) for v in _atc10_geometry_misses().values()))


@register("atc10-30-beta-excess", "atc10/30-tracking-geometry", "largest excess of the physical beta (%)")
def atc10_30_beta_excess() -> float:
    """Largest relative excess (%) of the synchronous-orbit beta over Table 4.2's."""
    m = _atc10_geometry_misses()
    return float(100 * max(m[(ex, "beta")] for ex in ("I", "II")))


@register("atc10-30-trace-deficit", "atc10/30-tracking-geometry", "mean deficit of the physical traces (%)")
def atc10_30_trace_deficit() -> float:
    """Mean relative deficit (%) of the synchronous-orbit traces against Table 4.2's."""
    m = _atc10_geometry_misses()
    vals = [v for (_, c), v in m.items() if c != "beta"]
    return float(-100 * sum(vals) / len(vals))


def _atc10_best_triplet_ii() -> tuple[int, ...]:
    """The triplet of Example II's satellites with the smallest position trace, synchronous orbit."""
    from navcore.papers import atc10_tracking_geometry as paper

    return tuple(paper.best_triplet("II", paper.physical_radius_ratio(), "trace"))


@register(
    "atc10-30-trace-best-II",
    "atc10/30-tracking-geometry",
    "smallest position trace of a triplet of Example II's satellites, synchronous orbit",
)
@register(
    "atc10-90-best-trace",
    "atc10/90-exercises",
    "smallest position trace of a triplet of Example II's satellites, synchronous orbit",
)
def atc10_trace_best_ii() -> float:
    """tr (F3'F3)^-1 of the best triplet of Example II's satellites at the synchronous orbit."""
    from navcore.location import multilateration as ml
    from navcore.papers import atc10_tracking_geometry as paper

    los = paper.example_line_of_sight("II", paper.physical_radius_ratio())
    return float(ml.position_trace(los[list(_atc10_best_triplet_ii())]))


@register(
    "atc10-90-best-triplet",
    "atc10/90-exercises",
    "the triplet of Example II's satellites with the smallest position trace (labels)",
)
def atc10_90_best_triplet() -> str:
    """The best triplet of Example II's satellites as the page prints it (1-based, comma-separated)."""
    return ", ".join(str(i + 1) for i in _atc10_best_triplet_ii())


# --- ATC-10 Sec. 4.6: Table 4.3's worked rows ---------------------------------------------------


def _atc10_exact_row_ii_5() -> tuple[float, ...]:
    """Table 4.3's row of Example II at sigma0 = 5 ns from the printed Table 4.2, exact psi."""
    from navcore.papers import atc10_clock_tracking as paper
    from navcore.papers import atc10_tracking_geometry as geometry

    return tuple(paper.table_4_3_row(geometry.printed_table_4_2("II"), 5.0))


@register(
    "atc10-32-psi-exact-II-5",
    "atc10/32-tracking-examples",
    "exact psi of Example II at sigma0 = 5 ns (printed Table 4.2)",
)
def atc10_32_psi_exact_ii_5() -> float:
    """The steady-state gain factor psi (Eq. (4.5.34)) of Example II at sigma0 = 5 ns."""
    return float(_atc10_exact_row_ii_5()[1])


@register(
    "atc10-32-sdN-exact-II-5",
    "atc10/32-tracking-examples",
    "tracking-limit rms error sd_N of Example II at sigma0 = 5 ns with the exact psi (ft)",
)
def atc10_32_sdn_exact_ii_5() -> float:
    """sd_N = c sigma sqrt(tr + (psi / beta) S) of Example II at sigma0 = 5 ns, exact psi, ft."""
    return float(_atc10_exact_row_ii_5()[3])


@register(
    "atc10-32-psi-needed-II-5",
    "atc10/32-tracking-examples",
    "the psi that Table 4.3's printed sd_N of Example II at 5 ns needs",
)
def atc10_32_psi_needed_ii_5() -> float:
    """The psi for which (4.5.35) with the printed Table 4.2 gives Table 4.3's printed sd_N (II, 5 ns)."""
    from scipy import optimize

    from navcore.papers import atc10_clock_tracking as clock
    from navcore.papers import atc10_tracking_geometry as paper

    printed = paper.printed_table_4_2("II")
    target = float(paper.TABLE_4_3[("II", 5.0)][3])
    return float(
        optimize.brentq(lambda p: clock.table_4_3_row(printed, 5.0, psi_value=p)[3] - target, 0.01, 0.1)
    )


def _atc10_fit_row_i_5() -> tuple[float, ...]:
    from navcore.papers import atc10_clock_tracking as clock
    from navcore.papers import atc10_tracking_geometry as paper

    return tuple(clock.table_4_3_row(paper.table_4_2_from_geometry("I", paper.fitted_radius_ratio()), 5.0))


@register(
    "atc10-32-sdN-I-5",
    "atc10/32-tracking-examples",
    "tracking-limit rms error sd_N of Example I at sigma0 = 5 ns, fitted geometry (ft)",
)
def atc10_32_sdn_i_5() -> float:
    """sd_N of Example I at sigma0 = 5 ns from the fitted-radius geometry, ft."""
    return float(_atc10_fit_row_i_5()[3])


@register(
    "atc10-32-sdN1-I-5",
    "atc10/32-tracking-examples",
    "first three-satellite rms error of Example I at sigma0 = 5 ns, fitted geometry (ft)",
)
def atc10_32_sdn1_i_5() -> float:
    """sd_(N+1), the first three-satellite estimate's rms error, Example I, 5 ns, fitted geometry, ft."""
    return float(_atc10_fit_row_i_5()[4])


def _atc10_phys_lowering() -> list[float]:
    """1 - (Table 4.3's sd_0 or sd_N from the synchronous-orbit geometry) / (the same from the printed
    Table 4.2), over both examples and the three sigma0."""
    from navcore.papers import atc10_clock_tracking as clock
    from navcore.papers import atc10_tracking_geometry as paper

    r_phys = paper.physical_radius_ratio()
    return [
        1
        - clock.table_4_3_row(paper.table_4_2_from_geometry(ex, r_phys), s0)[col]
        / clock.table_4_3_row(paper.printed_table_4_2(ex), s0)[col]
        for ex in ("I", "II")
        for s0 in clock.sigma0_values()
        for col in (2, 3)
    ]


@register(
    "atc10-32-phys-lowering-lo",
    "atc10/32-tracking-examples",
    "smallest lowering of Table 4.3's sd_0 and sd_N by the synchronous-orbit geometry (%)",
)
def atc10_32_phys_lowering_lo() -> float:
    """Smallest relative lowering (%) of sd_0 and sd_N when the synchronous geometry replaces Table 4.2."""
    return float(100 * min(_atc10_phys_lowering()))


@register(
    "atc10-32-phys-lowering-hi",
    "atc10/32-tracking-examples",
    "largest lowering of Table 4.3's sd_0 and sd_N by the synchronous-orbit geometry (%)",
)
def atc10_32_phys_lowering_hi() -> float:
    """Largest relative lowering (%) of sd_0 and sd_N when the synchronous geometry replaces Table 4.2."""
    return float(100 * max(_atc10_phys_lowering()))


@register(
    "atc10-30-s123-printed-residual-pct",
    "atc10/30-tracking-geometry",
    "largest miss of the printed Eq. (4.5.30) form 1'(F3'F3)^-1 1 against Table 4.2's S3 (%)",
)
def atc10_30_s123_printed_residual_pct() -> float:
    """Largest relative miss (%) of 1'(F3'F3)^-1 1 in ECEF at the fitted radius (the printed (4.5.30))
    against Table 4.2's printed S3, over both examples."""
    from navcore.papers import atc10_tracking_geometry as paper

    return float(
        100
        * max(
            abs(_atc10_geometry_row(ex, "fit")["s_123_printed"] / float(paper.TABLE_4_2[ex]["s_123"]) - 1)
            for ex in ("I", "II")
        )
    )


@register(
    "atc10-32-col5-corrected-{ex}-{s0}",
    "atc10/32-tracking-examples",
    "Table 4.3 col. (v) from the printed Table 4.2 with the invariant S3 of the stated system (ft)",
)
def atc10_32_col5_corrected(ex: str, s0: str) -> float:
    """sd_(N+1) of Table 4.3 col. (v) for example ``ex`` at sigma0 = ``s0`` ns, with the invariant
    1'(F3 F3')^-1 1 of the synchronous geometry in place of the printed S3 (erratum
    ATC10-E4.1-three-satellite-clock-term), ft."""
    from navcore.papers import atc10_tracking_examples as paper

    return float(paper.first_three_satellite_sd_invariant(ex, float(s0)))


# --- ATC-10 Sec. 3.5: the Chernoff bound and its convexity argument ---------------------------


@register(
    "atc10-21-convexity-limit",
    "atc10/21-roc-bounds",
    "largest x = rho sqrt(beta) up to which ln(1 - q + q cosh x) is convex in beta",
)
def atc10_21_convexity_limit() -> float:
    """Root of h''(x) = h'(x) / x for h(x) = ln(1 - q + q cosh x), q = 2 tau/alpha of Sec. 3.6: below
    it the log-moment term is convex in the power share beta (the step the paper argues in sqrt(beta))."""
    import numpy as np
    from scipy import optimize

    from navcore.papers import atc10_multiple_access as pm

    q = 2 * pm.IN.tau_over_alpha_sec36

    def margin(x: float) -> float:
        d = 1 - q + q * np.cosh(x)
        h1 = q * np.sinh(x) / d
        h2 = q * np.cosh(x) / d - h1**2
        return float(h2 - h1 / x)

    return float(optimize.brentq(margin, 1.0, 30.0))


#: The page's two-point example: the noise power of contour 5, the threshold, the largest N and
#: tau/alpha.
ATC10_TWO_POINT_POWER, ATC10_TWO_POINT_THETA = 4 / 75, 0.5
ATC10_TWO_POINT_N, ATC10_TWO_POINT_TAU_OVER_ALPHA = 10_000_000, 2e-5


@register(
    "atc10-21-upper-efolds",
    "atc10/21-roc-bounds",
    "Chernoff bound minus the exact ln p_f, two-point noise at N = 1e7 (e-folds)",
)
def atc10_21_upper_efolds() -> float:
    """ln (Chernoff bound (3.5.13)) - ln (exact tail) for two-point multiple-access noise, N = 1e7."""
    import numpy as np

    from navcore.detection.multiple_access import MultipleAccessNoise, two_point_density, two_point_exact_tail
    from navcore.detection.roc_bounds import chernoff_log_tails

    n, theta = ATC10_TWO_POINT_N, ATC10_TWO_POINT_THETA
    q = 2 * ATC10_TWO_POINT_TAU_OVER_ALPHA
    bb = ATC10_TWO_POINT_POWER / ((n - 1) * q)
    nz = MultipleAccessNoise(n, ATC10_TWO_POINT_TAU_OVER_ALPHA, two_point_density(bb))
    exact = float(np.log(two_point_exact_tail(np.sqrt(bb), n - 1, q, [theta])[0]))
    return float(chernoff_log_tails(nz, [theta])[0][0] - exact)


@register(
    "atc10-30-fit-worst-pct",
    "atc10/30-tracking-geometry",
    "largest miss of Table 4.2 computed the paper's way at the fitted radius against the printed table (%)",
)
def atc10_30_fit_worst_pct() -> float:
    """Largest relative miss (%) over both examples and the five columns of Table 4.2 computed as the
    paper did (the printed (4.5.30) for col. 5, the aircraft at its height) at the fitted radius."""
    from navcore.papers import atc10_tracking_geometry as paper
    from navcore.papers.atc10_tracking_geometry import _printed_table_4_2_as_computed as as_computed

    r_fit = paper.fitted_radius_ratio()
    return float(
        100
        * max(
            abs(as_computed(ex, r_fit)[c] / float(paper.TABLE_4_2[ex][c]) - 1)
            for ex in ("I", "II")
            for c in paper.COLUMNS
        )
    )


# --- KZL Sec. 1-2: the requirements page's simple models ---------------------------------------


@register(
    "kzl00-overlap-s",
    "kzl/00-requirements",
    "time the satellite's footprint stays within the receiver's footprint (s)",
)
def kzl00_overlap_s() -> float:
    """Receiver footprint over the speed of the satellite's ground track relative to the aircraft
    (KZL Sec. 1, circular orbit, the assumed footprint), in seconds."""
    from navcore.papers import kzl_requirements

    return float(kzl_requirements.footprint_overlap_s())


@register(
    "kzl00-pointing-shift-m",
    "kzl/00-requirements",
    "footprint shift of the 0.5 deg pointing error at the slant range (m)",
)
def kzl00_pointing_shift_m() -> float:
    """Shift of the footprint that KZL's acceptable pointing error (Sec. 1) gives at the slant
    range of the Table 1 height and the assumed look angle, in metres."""
    from navcore.papers import kzl_requirements

    return float(kzl_requirements.pointing_shift_m())


@register(
    "kzl00-baseline-arcsec",
    "kzl/00-requirements",
    "baseline tilt error that gives 1 m of InSAR height error (arcsec)",
)
def kzl00_baseline_arcsec() -> float:
    """Baseline tilt error giving 1 m of height error in the assumed TerraSAR-X geometry, arcsec."""
    from navcore.papers import kzl_requirements

    return float(kzl_requirements.baseline_angle_arcsec())


@register(
    "kzl00-baseline-mm",
    "kzl/00-requirements",
    "baseline length error that gives 1 m of InSAR height error (mm)",
)
def kzl00_baseline_mm() -> float:
    """Baseline length error giving 1 m of height error in the assumed TerraSAR-X geometry, mm."""
    from navcore.papers import kzl_requirements

    return float(kzl_requirements.baseline_length_mm())


@register(
    "kzl00-correlation-10s",
    "kzl/00-requirements",
    "correlation of a first-order receiver filter's output 10 s apart",
)
def kzl00_correlation_10s() -> float:
    """Correlation of the assumed first-order receiver filter's output 10 s apart (KZL Sec. 2.2)."""
    from navcore.papers import kzl_requirements

    return float(kzl_requirements.correlation_after_10s())


# --- KZL Sec. 2: the mechanization and error-model pages ----------------------------------------


@register(
    "kzl01-printed-roll-deg",
    "kzl/01-mechanization",
    "roll of a level IMU by Eq. (3) as printed, two-argument arctangent (deg)",
)
def kzl01_printed_roll_deg() -> float:
    """Roll that KZL's Eq. (3) as printed (``arctan_2(a_y, a_z)``) gives a level IMU at rest, whose
    specific force is [0, 0, -g] in NED body axes, in degrees."""
    import numpy as np

    from navcore.inertial.alignment import levelling_as_printed
    from navcore.units import G0

    roll, _ = levelling_as_printed(np.array([0.0, 0.0, -G0]))
    return float(np.degrees(roll))


@register(
    "kzl01-first-order-low-pct-{T}s",
    "kzl/01-mechanization",
    "how much lower the 180 s north-position sigma is with I + FT than with the exact transition (%)",
)
def kzl01_first_order_low_pct(T: str) -> float:
    """How much lower (%) the stand-alone north-position sigma at the end of the 180 s Table 1
    flight is with KZL's first-order transition (Eq. (6)) than with the exact one, step ``T`` s."""
    from navcore.papers.kzl_mechanization import discretisation_comparison

    d = discretisation_comparison(float(T))
    return float(100 * (1 - d["pos_first_order_m"] / d["pos_exact_m"]))


@register(
    "kzl01-neglected-rates-deg-h",
    "kzl/01-mechanization",
    "navigation-frame rate the simplified mechanization drops, Table 1 flight (deg/h)",
)
def kzl01_neglected_rates_deg_h() -> float:
    """|Earth rate + transport rate| of the Table 1 flight, dropped by KZL's Eq. (9), deg/h."""
    from navcore.papers.kzl_mechanization import neglected_rates_deg_per_h

    return float(neglected_rates_deg_per_h())


@register(
    "kzl01-neglected-coriolis-micro-g",
    "kzl/01-mechanization",
    "Coriolis and transport acceleration the simplified mechanization drops, Table 1 flight (micro-g)",
)
def kzl01_neglected_coriolis_micro_g() -> float:
    """|(2 omega_ie + omega_en) x v| of the Table 1 flight, dropped by KZL's Eq. (8), micro-g."""
    from navcore.papers.kzl_mechanization import neglected_coriolis_micro_g

    return float(neglected_coriolis_micro_g())


@register(
    "kzl02-rank-code-delta-range",
    "kzl/02-error-model",
    "observability rank with code and delta range only, eight satellites",
)
def kzl_rank_code_delta_range() -> int:
    """Rank of the observability matrix of KZL's error model in the Table 1 flight with the code
    and delta-range rows of Eq. (13) only, the largest over one to eight satellites."""
    from navcore.papers.kzl_tightly_coupled_filter import observability_ranks

    return int(max(observability_ranks()["tc"].values()))


@register(
    "kzl03-rank-code-delta-range",
    "kzl/03-simulation",
    "observability rank with code and delta range only, eight satellites",
)
def kzl03_rank_code_delta_range_8() -> int:
    """Rank of the observability matrix of KZL's error model in the Table 1 flight with the code
    and delta-range rows of Eq. (13) only, eight satellites."""
    from navcore.papers.kzl_tightly_coupled_filter import observability_ranks

    return int(observability_ranks()["tc"][8])


@register(
    "kzl02-full-rank-from-nu",
    "kzl/02-error-model",
    "satellites needed for full observability with attitude or DD rows (the larger of the two)",
)
def kzl02_full_rank_from_nu() -> int:
    """Fewest satellites that make every state of KZL's error model observable, with the attitude
    rows of Eq. (13) or the double differences of Eq. (17); the larger of the two counts."""
    from navcore.inertial.error_model17 import ERROR_LAYOUT_17
    from navcore.papers.kzl_tightly_coupled_filter import observability_ranks

    ranks = observability_ranks()
    return int(
        max(min(nu for nu, r in ranks[m].items() if r == ERROR_LAYOUT_17.size) for m in ("tc_att", "tc_dd"))
    )


# --- KZL Sec. 3.6: the simulation page (closed forms and the seeded Monte Carlo) ----------------


@register(
    "kzl03-arw-position-km",
    "kzl/03-simulation",
    "position error per axis from the angle random walk, 180 s (km)",
)
def kzl03_arw_position_km() -> float:
    """Stand-alone position error per horizontal axis that the Table 1 angle random walk N gives
    after the 180 s flight, g N sqrt(t^5 / 20), in km."""
    from navcore.papers.kzl_scenario import IN, kzl_imu
    from navcore.units import G0

    t = IN.duration_s
    return float(G0 * kzl_imu().gyro_random_walk * math.sqrt(t**5 / 20) / 1e3)


@register("kzl03-bias-heading-deg", "kzl/03-simulation", "heading error from the raw gyro bias, 180 s (deg)")
@register("kzl90-bias-term-raw-deg", "kzl/90-exercises", "heading error from the raw gyro bias, 180 s (deg)")
def kzl_bias_heading_deg() -> float:
    """Heading error that the uncalibrated Table 1 gyro bias b builds over the 180 s flight, b t,
    in degrees."""
    from navcore.papers.kzl_scenario import IN, kzl_imu

    return float(math.degrees(kzl_imu().gyro_bias * IN.duration_s))


def _kzl03_initialised_p0() -> Any:
    """The page's initial covariance of an initialised tightly coupled run (17 states: position,
    velocity, attitude, accelerometer bias, gyro bias, clock bias, clock drift): levelling ties
    each tilt to a horizontal accelerometer bias, heading from the GPS track plus the crab, the
    gyro bias known to its averaging residual."""
    import numpy as np

    from navcore.frames import dcm_from_euler
    from navcore.papers.kzl_scenario import table1_scenario
    from navcore.units import G0

    sc: Any = table1_scenario("tc")  # its optional fields are set for this flight
    imu = sc.imu
    C = dcm_from_euler(*sc.attitude)
    speed = np.linalg.norm(sc.velocity_ned)
    P0 = np.zeros((17, 17))
    P0[0:3, 0:3] = sc.pos0_sigma**2 * np.eye(3)
    P0[3:6, 3:6] = sc.vel0_sigma**2 * np.eye(3)
    T_init = sc.init_time
    S_b = np.diag(
        [imu.accel_bias**2 + imu.accel_random_walk**2 / T_init] * 2 + [imu.accel_random_walk**2 / T_init]
    )
    M = np.array([[0.0, 1 / G0, 0.0], [-1 / G0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    P0[6:9, 6:9] = M @ S_b @ M.T
    P0[8, 8] = sc.heading_sigma**2 + (sc.vel0_sigma / speed) ** 2
    P0[6:9, 9:12] = M @ S_b @ C
    P0[9:12, 6:9] = P0[6:9, 9:12].T
    P0[9:12, 9:12] = C.T @ S_b @ C
    P0[12:15, 12:15] = imu.gyro_random_walk**2 / T_init * np.eye(3)
    P0[15, 15], P0[16, 16] = sc.clock_bias_sigma**2, sc.clock_drift_sigma**2
    return P0


def _kzl03_loop_sigma_position() -> Any:
    """The page's covariance recursion written out for the tightly coupled filter (code and
    delta range) over the Table 1 flight: F of KZL Eq. (10), the cubic transition of Eq. (5),
    Van Loan's Q_d, two rows of Eq. (13) per tracked satellite and a Joseph update; the position
    1-sigma (m) per epoch, shape (epochs + 1, 3)."""
    import numpy as np
    from scipy.linalg import expm

    from navcore.frames import dcm_from_euler
    from navcore.papers.kzl_scenario import table1_scenario
    from navcore.units import G0

    sc: Any = table1_scenario("tc")  # its optional fields are set for this flight
    imu = sc.imu
    C = dcm_from_euler(*sc.attitude)

    def cross_matrix(a: Any) -> Any:
        return np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])

    T, I17 = 1.0 / sc.gps_rate, np.eye(17)
    a_n = np.array([0.0, 0.0, -G0])
    F = np.zeros((17, 17))
    F[0:3, 3:6] = np.eye(3)
    F[3:6, 6:9] = -cross_matrix(a_n)
    F[3:6, 9:12] = -C
    F[6:9, 12:15] = -C
    F[15, 16] = 1.0
    GQGt = np.diag(
        np.r_[
            np.zeros(3),
            np.full(3, imu.accel_random_walk**2),
            np.full(3, imu.gyro_random_walk**2),
            np.full(3, sc.accel_bias_walk**2),
            np.full(3, sc.gyro_bias_walk**2),
            sc.clock_phase_walk**2,
            sc.clock_drift_walk**2,
        ]
    )
    Phi = I17 + F * T + F @ F * T**2 / 2 + F @ F @ F * T**3 / 6
    V = expm(np.block([[-F, GQGt], [np.zeros((17, 17)), F.T]]) * T)
    Qd = V[17:, 17:].T @ V[:17, 17:]
    P = _kzl03_initialised_p0()
    sigma = [np.sqrt(np.diag(P)[0:3])]
    for k in range(1, sc.n_epochs + 1):
        P_prior = Phi @ P @ Phi.T + Qd
        nu = sc.n_visible[k]
        d = sc.sat_pos_ned[k, :nu] - sc.velocity_ned * k * T
        los = d / np.linalg.norm(d, axis=1, keepdims=True)
        H = np.zeros((2 * nu, 17))
        H[0::2, 0:3], H[0::2, 15] = -los, 1.0
        H[1::2, 3:6], H[1::2, 16] = -los, 1.0
        R = np.diag(np.tile([sc.gnss.pseudorange**2, sc.gnss.delta_range**2], nu))
        K = P_prior @ H.T @ np.linalg.inv(H @ P_prior @ H.T + R)
        P = (I17 - K @ H) @ P_prior @ (I17 - K @ H).T + K @ R @ K.T
        sigma.append(np.sqrt(np.diag(P)[0:3]))
    return np.array(sigma)


@register(
    "kzl03-loop-vs-filter-pct",
    "kzl/03-simulation",
    "largest relative gap of the written-out recursion's position 1-sigma from the filter's (%)",
)
def kzl03_loop_vs_filter_pct() -> float:
    """Largest |sigma_loop / sigma_filter - 1| over the flight and the three axes, in percent: the
    covariance recursion written out about the nominal flight against the position 1-sigma the
    Monte Carlo's tightly coupled filter reports (root of the run-averaged variance)."""
    import numpy as np

    from navcore.papers.kzl_scenario import monte_carlo

    filter_sigma = monte_carlo("tc", True).pos_sigma
    return float(100 * np.abs(_kzl03_loop_sigma_position() / filter_sigma - 1).max())


@register("kzl03-seed", "kzl/03-simulation", "seed of the KZL Monte Carlo")
def kzl03_seed() -> int:
    """The seed of the KZL Monte Carlo (the date of the paper's flight, 29 October 2006)."""
    from navcore.papers.kzl_scenario import SEED

    return int(SEED)


def _kzl_runs(mode: str, initialise: bool = True) -> Any:
    from navcore.papers.kzl_scenario import monte_carlo

    return monte_carlo(mode, initialise)


def _kzl_segment_mean(mode: str, col: int, counts: tuple[int, ...]) -> float:
    """Time average of a configuration's attitude RMS over the runs (deg), over the epochs of the
    segments with ``counts`` satellites (the first epoch, the initial state, left out)."""
    import numpy as np

    from navcore.papers.kzl_simulation import seg
    from navcore.units import DEG

    segments = seg()
    a = _kzl_runs(mode).rms("att_err") / DEG
    return float(np.concatenate([a[segments[n], col] for n in counts]).mean())


@register(
    "kzl03-share-beyond-20deg",
    "kzl/03-simulation",
    "share of the uninitialised stand-alone runs whose heading error ends beyond 20 deg",
)
def kzl03_share_beyond_20deg() -> float:
    """Share of the Monte Carlo runs of the stand-alone INS without initialisation whose heading
    error exceeds 20 deg at the end of the 180 s flight (KZL Sec. 3.6)."""
    import numpy as np

    from navcore.units import DEG

    return float(np.mean(np.abs(_kzl_runs("ins", False).att_err[:, -1, 2]) > 20 * DEG))


@register(
    "kzl03-raw-heading-closed-deg",
    "kzl/03-simulation",
    "1-sigma heading error of the uncalibrated stand-alone gyro after 180 s, closed form (deg)",
)
@register(
    "kzl90-heading-uncalibrated-deg",
    "kzl/90-exercises",
    "1-sigma heading error of the uncalibrated stand-alone gyro after 180 s, closed form (deg)",
)
def kzl_heading_closed_uncalibrated_deg() -> float:
    """sqrt((b t)^2 + N^2 t + sigma0^2) at t = 180 s with the raw Table 1 gyro bias, in degrees."""
    from navcore.papers.kzl_simulation import heading_closed_form_deg

    return float(heading_closed_form_deg(180.0, calibrated=False))


@register(
    "kzl90-heading-calibrated-deg",
    "kzl/90-exercises",
    "1-sigma heading error of the calibrated stand-alone gyro after 180 s, closed form (deg)",
)
def kzl_heading_closed_calibrated_deg() -> float:
    """sqrt((b' t)^2 + N^2 t + sigma0^2) at t = 180 s with the calibration residual
    b' = N / sqrt(T_init) for the gyro bias, in degrees."""
    from navcore.papers.kzl_simulation import heading_closed_form_deg

    return float(heading_closed_form_deg(180.0, calibrated=True))


@register(
    "kzl03-bias-for-20deg-deg-h",
    "kzl/03-simulation",
    "gyro bias that alone turns the heading 20 deg over the flight (deg/h)",
)
def kzl03_bias_for_20deg_deg_h() -> float:
    """Constant gyro bias that alone builds a 20 deg heading error over the 180 s flight, deg/h."""
    from navcore.papers.kzl_simulation import t_end

    return float(20.0 / (t_end() / 3600.0))


@register(
    "kzl03-raw-att-min-deg",
    "kzl/03-simulation",
    "smallest of the three attitude RMS errors of the uninitialised stand-alone runs at 180 s (deg)",
)
def kzl03_raw_att_min_deg() -> float:
    """Smallest over roll, pitch and heading of the RMS over runs of the uninitialised stand-alone
    INS's attitude error at the end of the flight, deg."""
    from navcore.papers.kzl_simulation import t_end
    from navcore.units import DEG

    return float((_kzl_runs("ins", False).rms("att_err")[t_end()] / DEG).min())


@register(
    "kzl03-raw-att-max-deg",
    "kzl/03-simulation",
    "largest of the three attitude RMS errors of the uninitialised stand-alone runs at 180 s (deg)",
)
def kzl03_raw_att_max_deg() -> float:
    """Largest over roll, pitch and heading of the RMS over runs of the uninitialised stand-alone
    INS's attitude error at the end of the flight, deg."""
    from navcore.papers.kzl_simulation import t_end
    from navcore.units import DEG

    return float((_kzl_runs("ins", False).rms("att_err")[t_end()] / DEG).max())


@register(
    "kzl03-tc-{axis}-gain",
    "kzl/03-simulation",
    "time-averaged attitude RMS of the stand-alone INS over that of the TC filter, one axis",
)
def kzl03_tc_gain(axis: str) -> float:
    """Ratio of the time-averaged RMS error of the initialised stand-alone INS to that of the
    tightly coupled filter (code and delta range), in roll or pitch, over the whole flight."""
    from navcore.papers.kzl_simulation import seg

    col = {"roll": 0, "pitch": 1}[axis]
    every = tuple(seg())
    return _kzl_segment_mean("ins", col, every) / _kzl_segment_mean("tc", col, every)


@register(
    "kzl03-att-heading-many-deg",
    "kzl/03-simulation",
    "time-averaged heading RMS of TC with attitude rows, segments with 4 or more satellites (deg)",
)
def kzl03_att_heading_many_deg() -> float:
    """Time-averaged heading RMS of the filter with attitude rows over the segments with 8, 4 and
    5 satellites, deg."""
    return _kzl_segment_mean("tc_att", 2, (8, 4, 5))


@register(
    "kzl03-att-heading-growth",
    "kzl/03-simulation",
    "heading RMS of TC with attitude rows, 2-3 satellites over 4 or more (ratio)",
)
def kzl03_att_heading_growth() -> float:
    """Time-averaged heading RMS of the filter with attitude rows over the 3- and 2-satellite
    segments, over that over the segments with 8, 4 and 5 satellites."""
    return _kzl_segment_mean("tc_att", 2, (3, 2)) / _kzl_segment_mean("tc_att", 2, (8, 4, 5))


@register(
    "kzl03-{mode}-heading-{n}sat-deg",
    "kzl/03-simulation",
    "time-averaged heading RMS of a TC filter over the segment with n satellites (deg)",
)
def kzl03_heading_segment_deg(mode: str, n: str) -> float:
    """Time-averaged heading RMS of the filter with attitude rows (``mode="att"``) or with double
    differences (``"dd"``) over the segment with ``n`` satellites, deg."""
    return _kzl_segment_mean({"att": "tc_att", "dd": "tc_dd"}[mode], 2, (int(n),))


@register(
    "kzl03-tc-{quantity}-{where}-{n}sat-{unit}",
    "kzl/03-simulation",
    "horizontal RMS error of the TC filter at the end of a satellite segment",
)
def kzl03_tc_horizontal(quantity: str, where: str, n: str, unit: str) -> float:
    """Horizontal (north-east norm) RMS over runs of the tightly coupled filter's position (m) or
    velocity (m/s) error at the last epoch of the segment with ``n`` satellites (``where="end"``)
    or of the segment before it (``"start"``)."""
    from navcore.papers.kzl_simulation import seg

    segments = seg()
    counts = list(segments)
    k = counts.index(int(n)) - (1 if where == "start" else 0)
    epoch = segments[counts[k]].stop - 1
    name = {"pos": "pos_err", "vel": "vel_err"}[quantity]
    return float(_kzl_runs("tc").horizontal_rms(name)[epoch])


@register(
    "kzl03-candidates-2m",
    "kzl/03-simulation",
    "integer candidates per double difference on a 2 m baseline, 2 B / lambda + 1",
)
def kzl03_candidates_2m() -> float:
    """Integer candidates per double difference of the Table 1 2 m baseline, 2 B / lambda + 1."""
    from navcore.papers.kzl_simulation import baseline_tradeoff

    return float(baseline_tradeoff()["2 m"][0])


@register(
    "kzl03-tilt-2m-mrad",
    "kzl/03-simulation",
    "baseline tilt from a 0.01-cycle phase error on a 2 m baseline (mrad)",
)
def kzl03_tilt_2m_mrad() -> float:
    """Tilt of the Table 1 2 m baseline from a 0.01-cycle phase error, 0.01 lambda / B, mrad."""
    from navcore.papers.kzl_simulation import baseline_tradeoff

    return float(baseline_tradeoff()["2 m"][1])


# --- KZL: the summary and the exercises ---------------------------------------------------------


@register(
    "kzl89-qcorr-residual-deg",
    "kzl/89-summary",
    "attitude error left by the printed right-hand quaternion correction (deg)",
)
def kzl89_qcorr_residual_deg() -> float:
    """Attitude error (deg) that the printed right-hand correction of KZL Sec. 3.5 leaves of the
    test error at the Table 1 attitude."""
    from navcore.papers import kzl_tightly_coupled_filter

    return float(kzl_tightly_coupled_filter.printed_correction_residual_deg())


@register("kzl89-qcorr-error-deg", "kzl/89-summary", "size of the test attitude error (deg)")
def kzl89_qcorr_error_deg() -> float:
    """Rotation angle of the test attitude error of the quaternion-correction check, in degrees."""
    import numpy as np

    from navcore.papers.kzl_tightly_coupled_filter import QCORR_DPSI

    return float(np.degrees(np.linalg.norm(QCORR_DPSI)))


@register(
    "kzl89-dd-printed-rank", "kzl/89-summary", "rank of the two DD attitude rows of Eq. (17) as printed"
)
def kzl89_dd_printed_rank() -> int:
    """Rank of the two double-difference attitude rows of KZL Eq. (17) as printed (both with the
    baseline l_02), Table 1 sky."""
    from navcore.papers import kzl_tightly_coupled_filter

    return int(kzl_tightly_coupled_filter.eq17_printed_rank())


@register("kzl89-dd-rank", "kzl/89-summary", "rank of the two DD attitude rows of Eq. (17), corrected")
def kzl89_dd_rank() -> int:
    """Rank of the two double-difference attitude rows of KZL Eq. (17) with l_01 and l_02."""
    from navcore.papers import kzl_tightly_coupled_filter

    return int(kzl_tightly_coupled_filter.eq17_corrected_rank())


@register(
    "kzl89-heading-removed",
    "kzl/89-summary",
    "fraction of the stand-alone time-averaged heading RMS the TC filter removes",
)
def kzl89_heading_removed() -> float:
    """Fraction of the initialised stand-alone INS's time-averaged heading RMS that the tightly
    coupled filter (code and delta range) removes, Monte Carlo."""
    from navcore.papers import kzl_simulation

    return float(kzl_simulation.tc_heading_improvement_mc())


@register(
    "kzl89-attitude-removed",
    "kzl/89-summary",
    "fraction of the stand-alone time-averaged attitude error the TC filter removes",
)
def kzl89_attitude_removed() -> float:
    """Fraction of the initialised stand-alone INS's time-averaged attitude error (root sum square
    of the three angles' RMS) that the tightly coupled filter removes, Monte Carlo."""
    from navcore.papers import kzl_simulation

    return float(kzl_simulation.tc_attitude_improvement_mc())


def _kzl_gyro_residual_deg_per_s() -> float:
    from navcore.papers.kzl_scenario import IN, kzl_imu
    from navcore.units import DEG

    return float(kzl_imu().gyro_random_walk / math.sqrt(IN.init_time_s) / DEG)


@register(
    "kzl90-bias-term-calibrated-deg",
    "kzl/90-exercises",
    "heading error from the calibration residual of the gyro bias, 180 s (deg)",
)
def kzl90_bias_term_calibrated_deg() -> float:
    """Heading error that the gyro-bias residual N / sqrt(T_init) builds over the 180 s, deg."""
    from navcore.papers.kzl_scenario import IN

    return _kzl_gyro_residual_deg_per_s() * IN.duration_s


def _kzl_heading_floor_deg() -> float:
    """The heading error no calibration removes after 180 s: sqrt(N^2 t + sigma0^2), deg."""
    from navcore.papers.kzl_scenario import IN, kzl_imu
    from navcore.units import DEG

    n_deg = kzl_imu().gyro_random_walk / DEG
    return float(math.sqrt(n_deg**2 * IN.duration_s + IN.crab_angle_deg**2))


@register(
    "kzl90-floor-deg",
    "kzl/90-exercises",
    "heading error after 180 s that no calibration removes (random walk and initial heading, deg)",
)
def kzl90_floor_deg() -> float:
    """sqrt(N^2 t + sigma0^2) at t = 180 s: the angle random walk and the initial heading error."""
    return _kzl_heading_floor_deg()


@register(
    "kzl90-crossover-s",
    "kzl/90-exercises",
    "averaging time at which the calibration residual's heading term equals the floor (s)",
)
def kzl90_crossover_s() -> float:
    """Averaging time T at which (N / sqrt(T)) t equals the floor after t = 180 s, in seconds."""
    from navcore.papers.kzl_scenario import IN, kzl_imu
    from navcore.units import DEG

    n_deg = kzl_imu().gyro_random_walk / DEG
    return float((n_deg * IN.duration_s / _kzl_heading_floor_deg()) ** 2)


@register(
    "kzl90-gain-300-1200-deg",
    "kzl/90-exercises",
    "heading error after 180 s, 300 s of calibration less 1200 s, covariance analysis (deg)",
)
def kzl90_gain_300_1200_deg() -> float:
    """How much lower the covariance analysis' heading 1-sigma after 180 s is with 1200 s of
    calibration at rest than with 300 s, deg."""
    from navcore.papers import kzl_covariance as kc

    return float(
        kc.standalone_sigma("misalignment", True, 300.0)[2]
        - kc.standalone_sigma("misalignment", True, 1200.0)[2]
    )


# --- SP Sec. 2.5: the tracking loop -------------------------------------------------------------


@register(
    "sp02-lam-fit", "sp/02-tracking-loop", "wavelength that gives Fig. 2.1's 90 deg peak at 17.67 rad/s (m)"
)
def sp02_lam_fit() -> float:
    """Metres per cycle that make the 6-g step peak at exactly 90 deg in the third-order loop at
    Fig. 2.1's natural frequency (SP Sec. 2.5)."""
    from navcore.gnss.tracking import wavelength_for_peak_error
    from navcore.papers import sp_tracking as spt
    from navcore.units import G0

    return float(wavelength_for_peak_error(spt.IN.step_g * G0, spt.IN.omega0_fig21, spt.IN.peak_limit_deg))


@register(
    "sp02-l1-peak", "sp/02-tracking-loop", "peak phase error of the 6-g step with the L1 wavelength (deg)"
)
def sp02_l1_peak() -> float:
    """Peak phase error of the 6-g step at Fig. 2.1's natural frequency with the L1 carrier's
    wavelength as the conversion, deg."""
    from navcore.papers import sp_tracking as spt
    from navcore.units import GPS_L1_WAVELENGTH_M

    return float(spt.peak_deg(GPS_L1_WAVELENGTH_M))


@register("sp02-l1-w0", "sp/02-tracking-loop", "natural frequency that holds the L1 peak at 90 deg (rad/s)")
def sp02_l1_w0() -> float:
    """Natural frequency of the third-order loop that holds the 6-g step's peak at 90 deg with the
    L1 wavelength, rad/s."""
    from navcore.gnss.tracking import natural_frequency_for_peak_error
    from navcore.papers import sp_tracking as spt
    from navcore.units import GPS_L1_WAVELENGTH_M

    return float(
        natural_frequency_for_peak_error(spt.step_deg_s2(GPS_L1_WAVELENGTH_M), spt.IN.peak_limit_deg)
    )


@register(
    "sp02-l1-factor", "sp/02-tracking-loop", "L1 natural frequency for 90 deg over the unaided 18 rad/s"
)
def sp02_l1_factor() -> float:
    """The L1 natural frequency for a 90 deg peak over the unaided 18 rad/s that Table 2.6 scales."""
    from navcore.papers import sp_residual_acceleration as spr

    return sp02_l1_w0() / float(spr.IN.unaided_omega0)


@register(
    "sp02-step-over-jerk", "sp/02-tracking-loop", "peak error of the 6-g step over that of the 10-g/s jerk"
)
def sp02_step_over_jerk() -> float:
    """Peak phase error of the 6-g step over that of the 10 g/s jerk held 0.6 s, Fig. 2.1's loop
    (the ratio does not depend on the conversion; one foot as the page shows it)."""
    from navcore.papers import sp_tracking as spt
    from navcore.units import FT

    return float(spt.peak_deg(FT) / spt.jerk_peak_deg(FT))


# --- SP Sec. 2.6: residual acceleration (Table 2.6) ---------------------------------------------


@register(
    "sp03-iso",
    "sp/03-residual-acceleration",
    "90 % sphere radius of a 3-D standard normal by quadrature (sigmas)",
)
def sp03_iso() -> float:
    """Radius of the sphere holding 90 % of N(0, I_3), by navcore's quadrature and root finding."""
    import numpy as np

    from navcore.inertial.residual_acceleration import sphere_radius

    return float(sphere_radius(np.eye(3), 0.9))


def _sp03_apriori_ratios() -> list[float]:
    """Table 2.6 column 2 over the 90 % radius of Table 2.5's a-priori accelerometer scale factor
    and misalignment, per grade."""
    from navcore.inertial.residual_acceleration import r90_from_apriori_ppm
    from navcore.papers import sp_residual_acceleration as spr
    from navcore.papers.sp_tables import TABLE_2_5_PRINTED

    sf = TABLE_2_5_PRINTED["accel_scale_factor_ppm"]
    mis = TABLE_2_5_PRINTED["accel_misalignment_arcsec"]
    return [spr.col2_ppm(g) / r90_from_apriori_ppm(sf[j], mis[j]) for j, g in enumerate(spr.GRADES)]


@register(
    "sp03-n-above",
    "sp/03-residual-acceleration",
    "grades whose Table 2.6 column 2 exceeds the a-priori 90 % radius of Table 2.5",
)
def sp03_n_above() -> int:
    """How many of the four grades print a Table 2.6 column 2 above the 90 % radius that Table
    2.5's a-priori accelerometer errors give."""
    return int(sum(r > 1 for r in _sp03_apriori_ratios()))


@register("sp03-col2-fall", "sp/03-residual-acceleration", "largest over smallest Table 2.6 column 2 value")
def sp03_col2_fall() -> float:
    """How much Table 2.6 column 2 falls from the worst grade to the best (largest over smallest)."""
    from navcore.papers import sp_residual_acceleration as spr

    col2 = [spr.col2_ppm(g) for g in spr.GRADES]
    return float(max(col2) / min(col2))


@register(
    "sp03-sf-fall",
    "sp/03-residual-acceleration",
    "largest over smallest Table 2.5 accelerometer scale factor",
)
def sp03_sf_fall() -> float:
    """How much Table 2.5's accelerometer scale factor falls from the worst grade to the best."""
    from navcore.papers.sp_tables import TABLE_2_5_PRINTED

    sf = TABLE_2_5_PRINTED["accel_scale_factor_ppm"]
    return float(max(sf) / min(sf))


# --- SP Sec. 2.5-2.6: acquisition (Table 2.7) and target location -------------------------------


def _sp04_search_s(system: str) -> Any:
    from navcore.papers import sp_acquisition as spa

    return spa.search_times_s(system)


@register("sp04-tc10-min-s", "sp/04-acquisition", "shortest Table 2.7 search of the TC 10 nmi/h system (s)")
def sp04_tc10_min_s() -> float:
    """Shortest search time over the satellites of Table 2.7's tightly coupled 10 nmi/h row, s."""
    from navcore.papers import sp_acquisition as spa

    return float(_sp04_search_s(spa.TC10).min())


@register("sp04-tc10-max-s", "sp/04-acquisition", "longest Table 2.7 search of the TC 10 nmi/h system (s)")
def sp04_tc10_max_s() -> float:
    """Longest search time over the satellites of Table 2.7's tightly coupled 10 nmi/h row, s."""
    from navcore.papers import sp_acquisition as spa

    return float(_sp04_search_s(spa.TC10).max())


@register("sp04-better-max-s", "sp/04-acquisition", "longest Table 2.7 search of the better systems (s)")
def sp04_better_max_s() -> float:
    """Longest search time of every Table 2.7 row but the tightly coupled 10 nmi/h one, s."""
    from navcore.papers import sp_acquisition as spa

    return float(spa.better_max_s())


@register(
    "sp04-tc10-sigma-{which}-m",
    "sp/04-acquisition",
    "1-sigma range uncertainty that the TC 10 nmi/h row's intervals imply (m)",
)
def sp04_tc10_sigma_m(which: str) -> float:
    """The 1-sigma range uncertainty of the fewest (``which="min"``) or most (``"max"``) code-phase
    intervals of Table 2.7's TC 10 nmi/h row: intervals of one cell span +-1 sigma, m."""
    from navcore.papers import sp_acquisition as spa

    cells = spa.table_2_7(spa.TC10)
    n = {"min": min, "max": max}[which](cells)
    return float(n * spa.IN.range_cell_m / 2)


@register(
    "sp05-mis-1pct-mrad",
    "sp/05-target-location",
    "heading error that adds 1 % to the 1 nmi/h helicopter's target error (mrad)",
)
def sp05_mis_1pct_mrad() -> float:
    """Heading error at which the pointing error over the target range adds 1 % (root sum square)
    to the 1 nmi/h helicopter's position error: sqrt(1.01^2 - 1) pos / L, mrad."""
    from navcore.papers import sp_acquisition as spa

    pos, lever = spa.IN.helicopter_error_1nmi_m, spa.IN.target_range_m
    return float(1e3 * math.sqrt(1.01**2 - 1) * pos / lever)


@register(
    "sp05-mis-equal-mrad",
    "sp/05-target-location",
    "heading error whose pointing error equals the 1 nmi/h helicopter's position error (mrad)",
)
def sp05_mis_equal_mrad() -> float:
    """Heading error whose pointing error over the target range equals the 1 nmi/h helicopter's
    position error, pos / L, mrad."""
    from navcore.papers import sp_acquisition as spa

    return float(1e3 * spa.IN.helicopter_error_1nmi_m / spa.IN.target_range_m)


# --- SP Sec. 3: deep integration ----------------------------------------------------------------


@register(
    "sp06-q-{kind}",
    "sp/06-deep-integration",
    "spectral-separation factor Q of the jammer on the P(Y) code (wide: 20 MHz, narrow: 1 kHz)",
)
def sp06_q(kind: str) -> float:
    """Spectral-separation factor Q = 1 / (R_c kappa) of SP Sec. 3's wideband (``kind="wide"``)
    or narrowband (``"narrow"``) jammer on the assumed code."""
    from navcore.papers import sp_antijam as spj

    return float(spj.q_factor({"wide": "wideband", "narrow": "narrowband"}[kind]))


@register(
    "sp06-{arch}-threshold",
    "sp/06-deep-integration",
    "effective C/N0 at the stated J/S limit of TC or DI against the wideband jammer (dB-Hz)",
)
def sp06_threshold(arch: str) -> float:
    """Effective C/N0 that the stated J/S limit of the tightly coupled (``arch="tc"``) or deeply
    integrated (``"di"``) receiver implies against the wideband jammer (SP Sec. 3.0-3.1), dB-Hz."""
    from navcore.papers import sp_antijam as spj

    return float(spj.threshold_dbhz(arch.upper()))


# --- SP Sec. 2.6: the inertial error budget (Table 2.4-2.5) -------------------------------------


@register(
    "sp20-clock-offset-us",
    "sp/20-inertial-errors",
    "Table 2.4's clock offset, read as metres, in microseconds",
)
def sp20_clock_offset_us() -> float:
    """Table 2.4's initial clock offset, printed '5000 ms' and read as metres, as a time in us."""
    from navcore.papers import sp_tables as spt
    from navcore.units import C

    entry = next(e for e in spt.table_2_4().values() if e.name == "clock initial offset")
    return float(entry.si / C * 1e6)


def _sp20_hour_horizontal_covariances() -> list[Any]:
    """The 1-h horizontal position covariances (m^2) of the Table 2.5 columns, gyrocompass-aligned
    at the grade latitude, in 10 s steps (as the inertial-errors page computes them)."""
    import numpy as np

    from navcore.inertial.error_dynamics import ErrorSources, gyrocompass_alignment, initial_covariance
    from navcore.inertial.trajectories import straight_and_level
    from navcore.integration.engine import run_covariance_analysis
    from navcore.papers import sp_missions as spm
    from navcore.papers import sp_tables as spt
    from navcore.units import DEG, HOUR

    grades = spt.sp_imu_grades()
    lay = spm.unaided_layout()
    lat = spm.IN.grade_latitude_deg * DEG
    srcs = [ErrorSources(imu=grades[g]) for g in spt.GRADE_LABELS_NMI_PER_H]
    P0 = [gyrocompass_alignment(initial_covariance(lay, src), lay, lat=lat) for src in srcs]
    hour = run_covariance_analysis(
        straight_and_level(HOUR, dt=10.0, lat0=lat),
        lay,
        lay,
        srcs,
        np.stack(P0),
        snapshots=(-1,),
        vertical_channel=False,
    )
    assert isinstance(hour, list)  # one run per stacked initial covariance
    out = []
    for r in hour:
        assert r.final_true is not None  # the snapshot asked for
        out.append(r.final_true[:2, :2])
    return out


@register(
    "sp20-rss-over-cep-max-pct",
    "sp/20-inertial-errors",
    "largest excess of the 1-h rss horizontal error over the CEP, Table 2.5 columns (%)",
)
def sp20_rss_over_cep_max_pct() -> float:
    """How much larger (%) the root-sum-square horizontal error is than the CEP after 1 h, the
    largest over the Table 2.5 columns."""
    import numpy as np

    from navcore.integration.engine import circular_error_probable

    ratios = [np.sqrt(np.trace(P)) / circular_error_probable(P) for P in _sp20_hour_horizontal_covariances()]
    return float(100 * (max(ratios) - 1))


# --- SP Sec. 2.6.2: the jammer flyby --------------------------------------------------------------


@register(
    "sp22-lc-jitter-dbhz",
    "sp/22-jammer-flyby",
    "C/N0 where the loosely coupled carrier loop's 3-sigma jitter reaches the phase limit (dB-Hz)",
)
def sp22_lc_jitter_dbhz() -> float:
    """C/N0 at which the thermal jitter rule of thumb puts the first system's (loosely coupled)
    carrier loop at its phase-error limit, k sigma = limit (SP Sec. 2.5), dB-Hz."""
    from navcore.gnss.jammer_geometry import pll_jitter_threshold_dbhz
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_scenario_wiring as sc

    return float(
        pll_jitter_threshold_dbhz(
            fb.carrier_loop(sc.SYSTEMS[0]).bandwidth_hz,
            fb.IN.max_phase_error_deg,
            fb.IN.jitter_k_sigma,
            fb.IN.coherent_s,
        )
    )


@register(
    "sp22-horizon-km", "sp/22-jammer-flyby", "radio horizon of the cruise altitude, 4/3-Earth radius (km)"
)
def sp22_horizon_km() -> float:
    """Radio horizon sqrt(2 (4/3) R h) of the missions' cruise altitude over a 4/3-radius Earth, km."""
    from navcore.location.multilateration import EARTH_MEAN_RADIUS_M
    from navcore.papers import sp_scenario_wiring as sc

    return float(math.sqrt(2 * 4 / 3 * EARTH_MEAN_RADIUS_M * sc.IN.cruise_altitude_m) / 1e3)


@register("sp22-range-min-km", "sp/22-jammer-flyby", "closest approach of the flyby to the jammer (km)")
def sp22_range_min_km() -> float:
    """Smallest slant range from the aircraft to the jammer over the flyby, km."""
    from navcore.papers import sp_flyby as fb

    return float(fb.jammer_range_m().min() / 1e3)


# --- ATC-10 Sec. 3.6-3.8: the physical PSK simulation --------------------------------------------


def _atc10_psk_samples() -> Any:
    from navcore.papers import atc10_multiple_access as pm

    return pm.psk_physical_samples()


@register(
    "atc10-20-psk-b",
    "atc10/20-multiple-access-noise",
    "second moment b of the simulated PSK amplitudes n_ij given an overlap",
)
def atc10_20_psk_b() -> float:
    """Mean square of the simulated amplitudes of overlapping PSK interferers (ATC-10 Sec. 3.6's b)."""
    import numpy as np

    return float(np.mean(_atc10_psk_samples() ** 2))


@register(
    "atc10-20-psk-kurtosis",
    "atc10/20-multiple-access-noise",
    "kurtosis E[x^4] / b^2 of the simulated PSK amplitudes",
)
@register(
    "atc10-22-psk-kurtosis",
    "atc10/22-gaussian-comparison",
    "kurtosis E[x^4] / b^2 of the simulated PSK amplitudes",
)
def atc10_psk_kurtosis() -> float:
    """Fourth moment over the squared second moment of the simulated PSK amplitudes."""
    import numpy as np

    x = _atc10_psk_samples()
    return float(np.mean(x**4) / np.mean(x**2) ** 2)


@register(
    "atc10-22-psk-pf-gauss",
    "atc10/22-gaussian-comparison",
    "ROC_g false-alarm probability at p_d = 0.9 with the simulated PSK density's power",
)
def atc10_22_psk_pf_gauss() -> float:
    """False-alarm probability of the Gaussian ROC (ATC-10 Eq. (3.8.3)) at p_d = 0.9, with the
    Theorem 3.1 power of the simulated PSK amplitude density."""
    from navcore.papers import atc10_gaussian_comparison as gaussian
    from navcore.papers import atc10_multiple_access as pm

    return float(pm.gaussian_best_pf(gaussian.psk_contour(), 0.9))


@register(
    "atc10-22-psk-pf",
    "atc10/22-gaussian-comparison",
    "best false-alarm probability at p_d >= 0.9 of the simulated 32-chip PSK set (Monte Carlo ROC)",
)
def atc10_22_psk_pf() -> float:
    """The smallest false-alarm probability over the thresholds whose detection probability is at
    least 0.9, on the stratified Monte Carlo ROC of a matched filter in multiple-access noise of
    the simulated PSK signatures (ATC-10 Sec. 3.6-3.8, N = 1e5)."""
    from navcore.detection.roc_bounds import best_pf_at_pd
    from navcore.papers import atc10_gaussian_comparison as pm

    roc = pm.psk_roc()
    return float(best_pf_at_pd(roc.p_f, roc.p_miss, 0.9))


@register(
    "atc10-22-psk-pf-estimate",
    "atc10/22-gaussian-comparison",
    "that false-alarm probability with its Monte Carlo standard error, to the digits the error supports",
)
def atc10_22_psk_pf_estimate() -> str:
    """The false-alarm probability of :func:`atc10_22_psk_pf` with the stratified Monte Carlo's
    standard error at the same threshold, as the book shows an estimate
    (:func:`navcore.formatting.estimate_text`)."""
    from navcore.detection.roc_bounds import best_pf_index_at_pd
    from navcore.formatting import estimate_text
    from navcore.papers import atc10_gaussian_comparison as pm

    roc = pm.psk_roc()
    j = best_pf_index_at_pd(roc.p_f, roc.p_miss, 0.9)
    if j is None:
        raise ValueError("the simulated PSK set reaches p_d = 0.9 at no threshold")
    return estimate_text(float(roc.p_f[j]), float(roc.p_f_se[j]))


# --- ATC-10 Sec. 4.5: the clock tracker's gain -------------------------------------------------------


@register(
    "atc10-31-convergence-speedup",
    "atc10/31-clock-tracking",
    "median over the examples and sigma0 of (2.3 / psi - 1) over the recursion's steps to 10 %",
)
def atc10_31_convergence_speedup() -> float:
    """How many times faster the gain recursion of ATC-10 Eqs. (4.5.16)-(4.5.25) comes within 10 %
    of its limit than the geometric series' 2.3 / psi - 1 steps, median over both examples and the
    three published sigma0 (sigma = 50 ns)."""
    import numpy as np

    from navcore.location import clock_tracking as ct
    from navcore.papers import atc10_clock_tracking as clock
    from navcore.papers import atc10_tracking_geometry as paper

    speedups = []
    for ex in ("I", "II"):
        b = float(paper.TABLE_4_2[ex]["beta"])
        for s0 in clock.sigma0_values():
            steps = ct.convergence_steps(ct.gain_recursion(b, 50.0, s0, 3000), 0.1)
            if steps > 0:
                speedups.append((2.3 / float(ct.psi(ct.alpha_parameter(s0, 50.0, b))) - 1) / steps)
    return float(np.median(speedups))


def _atc10_printed_ms_factors() -> list[float]:
    """(rms at N + 1 with the printed S3 over that with the invariant S3)^2, both examples and the
    three published sigma0, at the fitted geometry (the finite-N gains and the exact extrapolation)."""
    from navcore.papers import atc10_clock_tracking as paper
    from navcore.papers import atc10_tracking_examples as examples
    from navcore.papers import atc10_tracking_geometry as geometry

    r_fit = geometry.fitted_radius_ratio()
    out = []
    for ex in ("I", "II"):
        geo = geometry.table_4_2_from_geometry(ex, r_fit)
        printed_geo = dict(geo, s_123=geo["s_123_printed"])
        for s0 in paper.sigma0_values():
            pred = examples.rms_history_ft(geo, s0, paper.MC_N_LAST, 1)[1][-1]
            pred_p = examples.rms_history_ft(printed_geo, s0, paper.MC_N_LAST, 1)[1][-1]
            out.append(float((pred_p / pred) ** 2))
    return out


@register(
    "atc10-32-printed-ms-factor-{end}",
    "atc10/32-tracking-examples",
    "smallest or largest ratio of the N + 1 mean square with the printed S3 to that with the invariant S3",
)
def atc10_32_printed_ms_factor(end: str) -> float:
    """The smallest (``end="lo"``) or largest (``"hi"``) factor by which the printed S3 of (4.5.30)
    changes the mean-square position error at the first three-satellite epoch, over both examples
    and the three published sigma0."""
    return {"lo": min, "hi": max}[end](_atc10_printed_ms_factors())


@register(
    "atc10-32-mse-I-5-n0",
    "atc10/32-tracking-examples",
    "Monte Carlo mean-square position error, Example I, sigma0 = 5 ns, n = 0 (ft^2)",
)
def atc10_32_mse_i_5_n0() -> float:
    """E||xi_p||^2 at the least-squares epoch n = 0 from the seeded tracker Monte Carlo, Example I,
    sigma0 = 5 ns, ft^2."""
    from navcore.papers import atc10_clock_tracking as paper

    return float(paper.tracker_monte_carlo("I", 5.0).position_mse[0])


@register(
    "atc10-32-normvar-I-5-n0",
    "atc10/32-tracking-examples",
    "Monte Carlo variance of the position error's norm, Example I, sigma0 = 5 ns, n = 0 (ft^2)",
)
def atc10_32_normvar_i_5_n0() -> float:
    """Var ||xi_p|| at the least-squares epoch n = 0 from the seeded tracker Monte Carlo, Example I,
    sigma0 = 5 ns, ft^2."""
    from navcore.papers import atc10_clock_tracking as paper

    return float(paper.tracker_monte_carlo("I", 5.0).position_norm_variance[0])


@register(
    "atc10-90-ms-left-5ns-{ex}",
    "atc10/90-exercises",
    "fraction (sd_N / sd_0)^2 of the least-squares mean square that tracking leaves, sigma0 = 5 ns",
)
def atc10_90_ms_left_5ns(ex: str) -> float:
    """(sd_N / sd_0)^2 of Table 4.3 from the printed Table 4.2 of Example ``ex``, sigma0 = 5 ns."""
    from navcore.papers import atc10_tracking_examples as pt

    return float(pt.ms_ratio_tracking(ex, 5.0))


@register(
    "atc10-23-coef-se",
    "atc10/23-zakai-bandwidth",
    "standard error of the simulated PSK power coefficient 2 L E[x^2]",
)
def atc10_23_coef_se() -> float:
    """Standard error of the power coefficient 2 L E[n_ij^2] estimated from the PSK samples."""
    from navcore.papers import atc10_multiple_access as pm

    return float(pm.psk_power_coefficient_se())


@register(
    "atc10-21-convexity-worst",
    "atc10/21-roc-bounds",
    "largest rho sqrt(b) the Chernoff optimum reaches at the Sec. 3.6 operating points (two-point density)",
)
def atc10_21_convexity_worst() -> float:
    """Largest rho* sqrt(b) of the Chernoff bound's optimal tilt over the contours of Sec. 3.6 and
    thresholds 0.02-0.98, two-point amplitude density, N = 1e5."""
    import numpy as np

    from navcore.detection.roc_bounds import chernoff_log_tails
    from navcore.papers import atc10_multiple_access as pm
    from navcore.papers import atc10_roc_bounds as roc

    worst = 0.0
    for x in roc.contours():
        rho = chernoff_log_tails(pm.noise_sec36("C2 two-point", x), np.linspace(0.02, 0.98, 49))[1]
        worst = max(worst, float(np.max(rho)) * math.sqrt(pm.b_of_contour(x)))
    return worst


@register(
    "atc10-21-lower-efolds",
    "atc10/21-roc-bounds",
    "exact ln p_f minus the corrected lower bound (3.5.14), two-point noise at N = 1e7 (e-folds)",
)
def atc10_21_lower_efolds() -> float:
    """ln (exact tail) - ln (corrected lower bound (3.5.14)) for two-point multiple-access noise,
    N = 1e7 (the page's largest N)."""
    import numpy as np

    from navcore.detection.multiple_access import MultipleAccessNoise, two_point_density, two_point_exact_tail
    from navcore.detection.roc_bounds import gallager_log_tails_lower

    n, theta = ATC10_TWO_POINT_N, ATC10_TWO_POINT_THETA
    q = 2 * ATC10_TWO_POINT_TAU_OVER_ALPHA
    bb = ATC10_TWO_POINT_POWER / ((n - 1) * q)
    nz = MultipleAccessNoise(n, ATC10_TWO_POINT_TAU_OVER_ALPHA, two_point_density(bb))
    exact = float(np.log(two_point_exact_tail(np.sqrt(bb), n - 1, q, [theta])[0]))
    return float(exact - gallager_log_tails_lower(nz, [theta])[0][0])


def _atc10_21_lower_gaps() -> list[float]:
    """log10 (actual p_f / corrected lower bound (3.5.14)), two-point density, contours 3, 5, 6 and
    thresholds 0.3, 0.5, 0.7 (the actual p_f at the nearest point of the exact ROC's grid)."""
    import numpy as np

    from navcore.detection.roc_bounds import gallager_log_tails_lower
    from navcore.papers import atc10_gaussian_comparison as pm
    from navcore.papers import atc10_multiple_access as noise

    theta = np.array([0.3, 0.5, 0.7])
    out: list[float] = []
    for x in (3.0, 5.0, 6.0):
        lb = gallager_log_tails_lower(noise.noise_sec36("C2 two-point", x), theta)[0]
        idx = [int(np.argmin(abs(pm.THETA_GRID - t))) for t in theta]
        out += [float(v) for v in np.log10(pm.exact_roc("C2 two-point", x).p_f[idx]) - lb / np.log(10)]
    return out


@register(
    "atc10-21-lower-gap-{end}",
    "atc10/21-roc-bounds",
    "smallest or largest gap between the actual p_f and the corrected lower bound (decades)",
)
def atc10_21_lower_gap(end: str) -> float:
    """The smallest (``end="lo"``) or largest (``"hi"``) number of decades by which the corrected
    lower bound (3.5.14) lies below the actual p_f, over the page's nine two-point cases."""
    return {"lo": min, "hi": max}[end](_atc10_21_lower_gaps())


def _atc10_outage_corrected_s(ex: str) -> float:
    from navcore.papers import atc10_tracking_examples as examples
    from navcore.papers import atc10_tracking_geometry as paper

    return float(
        examples.acceptable_outage_s(ex, 5.0, paper.table_4_2_from_geometry(ex, paper.fitted_radius_ratio()))
    )


@register(
    "atc10-32-outage-corrected-{ex}",
    "atc10/32-tracking-examples",
    "acceptable three-satellite outage at sigma0 = 5 ns, fitted geometry with the invariant S3 (s)",
)
def atc10_32_outage_corrected(ex: str) -> float:
    """Seconds for which the three-satellite rms of Example ``ex`` stays below the fitted factor
    times the all-satellite least-squares rms (rule of thumb 4), sigma0 = 5 ns, fitted geometry."""
    return _atc10_outage_corrected_s(ex)


@register(
    "atc10-32-outage-ratio-{end}",
    "atc10/32-tracking-examples",
    "smallest or largest corrected acceptable outage over the printed one",
)
def atc10_32_outage_ratio(end: str) -> float:
    """The corrected acceptable outage over the printed one (rule of thumb 4), the smaller
    (``end="lo"``) or larger (``"hi"``) of the two examples."""
    from navcore import ledger

    ratios = [
        _atc10_outage_corrected_s(ex) / float(ledger.claim(f"ATC10-sec4.6-rule4-outage-ex{ex}").published)
        for ex in ("I", "II")
    ]
    return {"lo": min, "hi": max}[end](ratios)


# --- Across the papers: one filter, one geometry ------------------------------------------------


@register(
    "across01-wf-bound-mm-s",
    "across/01-filters-and-geometry",
    "WF fused velocity bound per axis, 100 ug, sigma_T = 0.2 m/s, three satellites (mm/s)",
)
def across01_wf_bound_mm_s() -> float:
    """Per-axis fused velocity bound of WF Eq. (23) at the worked example's accelerometer, the
    middle sigma_T and three GPS satellites, in mm/s."""
    from navcore.papers import wf_assessment, wf_inputs

    return float(
        1e3 * wf_assessment.sigma_d_bound(wf_inputs.sigma_a_example(), wf_inputs.sigma_t_values()[1], n_sat=3)
    )


@register(
    "across01-sp-outage-m",
    "across/01-filters-and-geometry",
    "SP rss horizontal error of the calibrated 1 nmi/h instrument after the helicopter's outage (m)",
)
def across01_sp_outage_m() -> float:
    """rss horizontal error (m) of the perfectly calibrated second Table 2.5 grade (random walks
    only) after the helicopter mission's jammed minutes of free inertial flight (SP Sec. 2.6)."""
    from navcore.papers import sp_mission_flights as sp_flights
    from navcore.papers import sp_missions
    from navcore.papers.sp_tables import GRADE_LABELS_NMI_PER_H

    return float(
        sp_missions.noise_only_error_m(GRADE_LABELS_NMI_PER_H[1], sp_flights.IN.helicopter_jammed_min)
    )


@register("across01-sp-states", "across/01-filters-and-geometry", "states of SP's free-inertial error model")
def across01_sp_states() -> int:
    """Size of the free-inertial error layout of SP's covariance analysis: navigation errors and
    every Table 2.5 error source that is not a random walk."""
    from navcore.papers import sp_missions

    return int(sp_missions.unaided_layout().size)


@register(
    "across01-kzl-{kind}-deg",
    "across/01-filters-and-geometry",
    "KZL heading 1-sigma after the 180 s flight, INS alone, covariance analysis (deg)",
)
def across01_kzl_heading_deg(kind: str) -> float:
    """Heading 1-sigma (deg) of the stand-alone KZL INS after the flight from the covariance
    analysis, without (``kind="raw"``) or with (``"init"``) the initialisation at rest."""
    from navcore.papers import kzl_covariance

    initialise = {"raw": False, "init": True}[kind]
    return float(kzl_covariance.standalone_sigma("misalignment", initialise=initialise)[2])


def _across01_dilution_geometries() -> dict[str, tuple[Any, float]]:
    """The page's line-of-sight rows and double-difference scale for each geometry, keyed as
    the page glues them: ATC-10 Examples I and II at the synchronous radius, the SP flyby's
    tracked satellites at the start, KZL's satellites at the start and at the first epoch
    with four (the fewest of four or more)."""
    import numpy as np

    from navcore.papers import atc10_tracking_geometry, kzl_scenario, sp_flyby

    radius = atc10_tracking_geometry.physical_radius_ratio()
    out: dict[str, tuple[Any, float]] = {
        "atc-i": (atc10_tracking_geometry.example_line_of_sight("I", radius), 1.0),
        "atc-ii": (atc10_tracking_geometry.example_line_of_sight("II", radius), 1.0),
        "sp": (-sp_flyby.flyby_geometry().u_ned[0], 1.0),
    }
    positions, _ = kzl_scenario.table1_sky()
    schedule = kzl_scenario.VISIBILITY_SCHEDULE
    t_late, n_late = _across01_kzl_late(schedule)
    for key, (t, n) in (("kzl", (0.0, schedule[0][1])), ("kzl-late", (t_late, n_late))):
        d = positions[round(t * kzl_scenario.IN.gps_rate_hz), :n]
        out[key] = (-d / np.linalg.norm(d, axis=1)[:, None], 2.0)
    return out


def _across01_kzl_late(schedule: Any) -> tuple[float, int]:
    """The first epoch of the KZL schedule with the fewest satellites of four or more."""
    return min(((t, n) for t, n in schedule if n >= 4), key=lambda tn: tn[1])


@register(
    "across01-dop-{name}",
    "across/01-filters-and-geometry",
    "position dilution of precision with the common unknown differenced away",
)
def across01_dop(name: str) -> float:
    """Position dilution of precision, sqrt(scale tr[F'(I - 11'/K)F]^-1), of one of the page's
    geometries (ATC-10 Sec. 4's differencing form; scale 2 for KZL's double differences)."""
    import numpy as np

    from navcore.location.multilateration import position_dilution_covariance

    U, scale = _across01_dilution_geometries()[name]
    return float(np.sqrt(scale * np.trace(position_dilution_covariance(U))))


@register(
    "across01-kzl-late-n",
    "across/01-filters-and-geometry",
    "satellites KZL's schedule tracks at its first epoch with the fewest of four or more",
)
def across01_kzl_late_n() -> int:
    """The fewest satellites of four or more in the KZL visibility schedule."""
    from navcore.papers import kzl_scenario

    return int(_across01_kzl_late(kzl_scenario.VISIBILITY_SCHEDULE)[1])


# --- Across the papers: jamming ------------------------------------------------------------------


@register("across02-tb-db", "across/02-jamming", "ATC-10 time-bandwidth product B tau (dB)")
def across02_tb_db() -> float:
    """ATC-10's time-bandwidth product 10 log10(B tau) of one pulse (Sec. 2.7), in dB."""
    from navcore.papers import atc10_jamming as atc

    return float(10 * math.log10(atc.IN.bandwidth_hz * atc.IN.pulse_duration_s))


@register("across02-spread-db", "across/02-jamming", "SP spreading gain Q R_c on the wideband jammer (dB-Hz)")
def across02_spread_db() -> float:
    """10 log10(Q R_c) of SP Sec. 3's wideband jammer on the assumed P(Y) code, dB-Hz."""
    from navcore.papers import sp_antijam as sp

    return float(10 * math.log10(sp.q_factor("wideband") * sp.IN.chip_rate_hz))


@register(
    "across02-{arch}-threshold",
    "across/02-jamming",
    "effective C/N0 at the stated J/S limit of TC or DI against the wideband jammer (dB-Hz)",
)
def across02_threshold(arch: str) -> float:
    """Effective C/N0 that the stated J/S limit of the tightly coupled (``arch="tc"``) or deeply
    integrated (``"di"``) receiver implies against the wideband jammer (SP Sec. 3.1), dB-Hz."""
    from navcore.papers import sp_antijam as sp

    return float(sp.threshold_dbhz(arch.upper()))


@register("across02-di-gain-db", "across/02-jamming", "J/S limit of DI over TC's loss of code lock (dB)")
def across02_di_gain_db() -> float:
    """SP Sec. 3's stated J/S at which the deeply integrated code loop holds lock less the one at
    which the tightly coupled loop loses it, dB."""
    from navcore.papers import sp_antijam as sp

    return float(sp.IN.di_lock_js_db - sp.IN.tc_loss_js_db)


def _across02_sync_height_m() -> float:
    from navcore.location.multilateration import EARTH_MEAN_RADIUS_M, synchronous_orbit_radius

    return float(synchronous_orbit_radius() - EARTH_MEAN_RADIUS_M)


@register(
    "across02-sync-km", "across/02-jamming", "height of the synchronous orbit above the mean Earth (km)"
)
def across02_sync_km() -> float:
    """Synchronous orbit radius less the mean Earth radius, km."""
    return _across02_sync_height_m() / 1e3


@register(
    "across02-erp-tc-sync",
    "across/02-jamming",
    "jammer ERP that breaks SP's tightly coupled code loop from the synchronous height (dBW)",
)
def across02_erp_tc_sync() -> float:
    """ERP (dBW) at which a jammer at the synchronous orbit's height reaches SP's tightly coupled
    J/S limit at an isotropic L1 receiver (free space)."""
    from navcore.gnss.antijam import free_space_js_db
    from navcore.papers import sp_antijam as sp
    from navcore.units import GPS_L1_WAVELENGTH_M

    js = free_space_js_db(1.0, _across02_sync_height_m(), GPS_L1_WAVELENGTH_M, sp.IN.signal_dbw)
    return float(sp.IN.tc_loss_js_db - js)


def _across02_k1_erp() -> float:
    from navcore.papers import atc10_jamming as atc
    from navcore.papers import atc10_system_tables as tables

    return float(atc.required_erp_dbw("ambiguous", atc.IN.caption_p_dl, tables.table11_k(0)))


@register(
    "across02-k1-erp",
    "across/02-jamming",
    "ATC-10 jammer ERP for ambiguous detections, Table 1.1's first K at the caption's P_DL (dBW)",
)
def across02_k1_erp() -> float:
    """Jammer ERP (dBW) at which ATC-10's ambiguous detections reach 0.01 N_T for Table 1.1's
    first design (K = 1) at the caption's P_DL."""
    return _across02_k1_erp()


@register(
    "across02-k1-reach-km",
    "across/02-jamming",
    "range out to which ATC-10's K = 1 jammer breaks SP's tightly coupled code loop (km)",
)
def across02_k1_reach_km() -> float:
    """Free-space range (km) at which a jammer of the K = 1 ERP still holds SP's tightly coupled
    code loop at its J/S limit (isotropic L1 receiver)."""
    from navcore.gnss.jammer_geometry import threshold_range_m
    from navcore.papers import sp_antijam as sp
    from navcore.units import GPS_L1_WAVELENGTH_M

    return float(
        threshold_range_m(_across02_k1_erp(), sp.IN.signal_dbw + sp.IN.tc_loss_js_db, GPS_L1_WAVELENGTH_M)
        / 1e3
    )


@register(
    "across02-k1000-erp",
    "across/02-jamming",
    "largest ATC-10 jammer ERP for ambiguous detections over the page's designs (dBW)",
)
def across02_k1000_erp() -> float:
    """Largest ERP (dBW) for ambiguous detections over Table 1.1's first design and Table 2.1's
    finite designs."""
    from navcore.papers import atc10_jamming as atc
    from navcore.papers import atc10_system_tables as tables

    designs = [(tables.table11_k(0), atc.IN.caption_p_dl), *atc.table21_finite_designs()]
    return float(max(atc.required_erp_dbw("ambiguous", p, k) for k, p in designs))


# --- SP Sec. 2.6: free-inertial errors of the calibrated instrument, the flyby's ranges ----------


@register(
    "sp21-noise-only-10-19min-m",
    "sp/21-missions",
    "rss horizontal error of the perfectly calibrated 10 nmi/h instrument after 19 min (m)",
)
def sp21_noise_only_10_19min_m() -> float:
    """rss horizontal error (m) of the 10 nmi/h Table 2.5 column with its random walks only,
    from zero, after the helicopter mission's 19 minutes without GPS (SP Sec. 2.6.3)."""
    from navcore.papers import sp_missions as spm

    return float(spm.noise_only_error_m(10.0, 19.0))


@register(
    "sp21-clock-digits",
    "sp/21-missions",
    "significant digits in which the clock offset read as 5000 ns leaves the 1 nmi/h error unchanged",
)
def sp21_clock_digits() -> int:
    """Number of leading significant digits the tightly coupled 1 nmi/h horizontal error 1 s before
    reacquisition keeps when Table 2.4's initial clock offset is read as 5000 ns instead of 5000 m:
    the largest d with a relative change below :math:`10^{-d}` (SP Table 2.4, Sec. 2.6.1)."""
    from navcore.papers import sp_missions as spm

    relative = spm.initial_error_effect_pct(("clock offset in ns",)) / 100.0
    return math.floor(-math.log10(relative)) if relative > 0 else 17


@register(
    "sp21-init-effect-pct",
    "sp/21-missions",
    "largest change of the 1 nmi/h error before reacquisition with all initial errors scaled (%)",
)
def sp21_init_effect_pct() -> float:
    """Largest relative change (%) of the tightly coupled 1 nmi/h horizontal error 1 s before
    reacquisition when Table 2.4's initial position, velocity and misalignment errors are all
    multiplied or divided by the assumed scale (SP Sec. 2.3, Sec. 2.6.1)."""
    from navcore.papers import sp_missions as spm

    return spm.initial_error_effect_pct(("initial errors up", "initial errors down"))


@register(
    "sp21-mis-effect-pct",
    "sp/21-missions",
    "largest change of the 1 nmi/h error before reacquisition with the misalignment alone scaled (%)",
)
def sp21_mis_effect_pct() -> float:
    """:func:`sp21_init_effect_pct` with only the initial misalignment scaled (SP Sec. 2.3)."""
    from navcore.papers import sp_missions as spm

    return spm.initial_error_effect_pct(("misalignment up", "misalignment down"))


@register(
    "sp21-coupling-pct",
    "sp/21-missions",
    "difference of the loosely and tightly coupled 1 nmi/h errors at bomb release (%)",
)
def sp21_coupling_pct() -> float:
    """Relative difference (%) of the loosely and tightly coupled 1 nmi/h horizontal errors at
    bomb release in the head-on approach, all satellites lost 159 s and 153 s before (SP Sec. 2.6.3)."""
    from navcore.papers import sp_missions as spm

    return spm.coupling_difference_pct()


@register(
    "sp21-momentary-pct",
    "sp/21-missions",
    "largest change of the helicopter's target-location error with momentary carrier losses (%)",
)
def sp21_momentary_pct() -> float:
    """Largest relative change (%) of the helicopter's target-location error 19 min after GPS loss
    (no Doppler, both grades) when every carrier is dropped for a moment at each pull-up (SP Sec. 2.6.4)."""
    from navcore.papers import sp_missions as spm

    return spm.momentary_loss_effect_pct()


def _sp22_tc10_blackout_min() -> float:
    from navcore.papers import sp_flyby as fb

    return float(fb.blackouts_min()["TC 10 nmi/h"])


def _sp22_noise_only_10(minutes: float) -> float:
    from navcore.papers import sp_missions as spm

    return float(spm.noise_only_error_m(10.0, minutes))


@register(
    "sp22-noise-model-m",
    "sp/22-jammer-flyby",
    "rss horizontal error of the calibrated 10 nmi/h instrument over the model's TC 10 blackout (m)",
)
def sp22_noise_model_m() -> float:
    """rss horizontal error (m) of the 10 nmi/h column's random walks alone, from zero, over the
    tightly coupled 10 nmi/h system's blackout in the flyby model."""
    return _sp22_noise_only_10(_sp22_tc10_blackout_min())


@register(
    "sp22-noise-18-m",
    "sp/22-jammer-flyby",
    "rss horizontal error of the calibrated 10 nmi/h instrument over the paper's 20 - 2 min blackout (m)",
)
def sp22_noise_18_m() -> float:
    """rss horizontal error (m) of the 10 nmi/h column's random walks alone over the paper's
    tightly coupled blackout: its 20-min loosely coupled outage less 'about 2 min' (Sec. 2.6.2)."""
    from navcore.papers import sp_flyby as fb

    return _sp22_noise_only_10(fb.LC_BLACKOUT_MIN - fb.BLACKOUT_REDUCTION_MIN)


@register(
    "sp22-scaled-tc10-m",
    "sp/22-jammer-flyby",
    "TC 10 nmi/h error before reacquisition grown to the paper's blackout by the random walks (m)",
)
def sp22_scaled_tc10_m() -> float:
    """The flyby model's tightly coupled 10 nmi/h error before reacquisition, times the ratio of
    the random-walk errors over the paper's blackout and over the model's (m)."""
    from navcore.papers import sp_flyby as fb

    err = fb.errors_before_reacquisition()["TC 10 nmi/h"]
    return float(err * sp22_noise_18_m() / sp22_noise_model_m())


@register(
    "sp22-range-{when}-km",
    "sp/22-jammer-flyby",
    "slant range to the jammer where the loosely coupled blackout starts (loss) or ends (back) (km)",
)
def sp22_range_km(when: str) -> float:
    """Slant range (km) from the aircraft to the jammer at the sample where the loosely coupled
    blackout starts (``when="loss"``) or ends (``"back"``)."""
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_scenario_wiring as sc

    t = fb._blackout_s(sc.SYSTEMS[0])[{"loss": 0, "back": 1}[when]]
    return float(fb.jammer_range_m()[int(t)] / 1e3)


# --- ATC-10 Sec. 3.8: the actual ROC against ROC_g ----------------------------------------------


def _atc10_22_best_ratios_8() -> list[float]:
    """Best actual p_f over the four densities divided by the ROC_g p_f, at the highest contour
    1/sqrt(3b) = 8, for p_d >= 0.9 and p_d >= 0.99 (the page's comparison table)."""
    from navcore.papers import atc10_gaussian_comparison as gaussian
    from navcore.papers import atc10_multiple_access as pm

    tab = gaussian.gaussian_comparison_table()
    return [
        min(tab[(n, 8.0, pd_min)][0] for n in pm.DENSITY_NAMES) / tab[(pm.DENSITY_NAMES[0], 8.0, pd_min)][1]
        for pd_min in (0.9, 0.99)
    ]


@register(
    "atc10-22-ratio-8-{end}",
    "atc10/22-gaussian-comparison",
    "smaller or larger, over p_d >= 0.9 and 0.99, of the best actual over the ROC_g p_f at 1/sqrt(3b) = 8",
)
def atc10_22_ratio_8(end: str) -> float:
    """How many times the ROC_g false-alarm rate the best of the four densities' exact actual
    ROCs reaches at 1/sqrt(3b) = 8 (ATC-10 Sec. 3.8), the smaller (``end="lo"``) or larger
    (``"hi"``) of the p_d >= 0.9 and p_d >= 0.99 cases."""
    return float({"lo": min, "hi": max}[end](_atc10_22_best_ratios_8()))


# --- SP Sec. 2.6.2: the flyby's blackouts and their causes --------------------------------------


@register(
    "sp22-tc10-blackout-min",
    "sp/22-jammer-flyby",
    "GPS blackout of the tightly coupled 10 nmi/h system in the flyby model, search time included (min)",
)
def sp22_tc10_blackout_min() -> float:
    """Blackout (min) of the tightly coupled 10 nmi/h system at the fitted jammer: from its code
    loss to the first satellite back, that satellite's search time included (SP Sec. 2.6.2)."""
    return _sp22_tc10_blackout_min()


@register(
    "sp22-grade-spread-s",
    "sp/22-jammer-flyby",
    "longest minus shortest tightly coupled blackout in the flyby model, search times included (s)",
)
def sp22_grade_spread_s() -> float:
    """Spread (s) of the four tightly coupled systems' blackouts at the fitted jammer."""
    from navcore.papers import sp_flyby as fb

    return float(60 * fb.grade_spread_min())


@register(
    "sp22-bandwidth-s",
    "sp/22-jammer-flyby",
    "change of the TC 1 nmi/h lock-table blackout with Table 2.6's first-row unaided carrier loop (s)",
)
def sp22_bandwidth_s() -> float:
    """How much (s) the tightly coupled 1 nmi/h lock-table blackout changes when its aided
    carrier loop is replaced by the unaided 18 rad/s loop of Table 2.6's first row."""
    from navcore.papers import sp_flyby as fb

    return float(60 * fb.bandwidth_effect_min())


def _sp22_part_min(part: str) -> float:
    from navcore.papers import sp_flyby as fb

    return float(fb.shortening_parts_min()[part])


@register(
    "sp22-resistance-s",
    "sp/22-jammer-flyby",
    "part of the blackout shortening due to the carrier loop (jamming resistance) (s)",
)
def sp22_resistance_s() -> float:
    """Change (s) of the 0.2 nmi/h system's lock-table blackout when it tracks with the loosely
    coupled receiver's carrier loop instead of its own."""
    return 60 * _sp22_part_min("jamming resistance")


@register(
    "sp22-calibration-s",
    "sp/22-jammer-flyby",
    "part of the blackout shortening due to the range uncertainty searched at reacquisition (s)",
)
def sp22_calibration_s() -> float:
    """Search time (s) the loosely coupled receiver's range uncertainty would add to the 0.2
    nmi/h system's first satellite back, over the 0.2 nmi/h system's own."""
    return 60 * _sp22_part_min("calibration")


@register(
    "sp22-architecture-min",
    "sp/22-jammer-flyby",
    "part of the blackout shortening due to the architecture (any code against four) (min)",
)
def sp22_architecture_min() -> float:
    """The loosely coupled to 0.2 nmi/h blackout shortening (min) less its carrier-loop and
    calibration parts."""
    return _sp22_part_min("architecture")


# --- SP pages: the numbers the chapter's read-through glued -----------------------------------


@register(
    "sp02-step-over-jerk-w0",
    "sp/02-tracking-loop",
    "natural frequency holding the 6-g step at 90 deg over that holding the 10-g/s jerk (one foot)",
)
def sp02_step_over_jerk_w0() -> float:
    """Fig. 2.1's loop with the one-foot conversion: the natural frequency that holds the 6-g
    step's peak at the phase limit over the one that holds the 10 g/s jerk's."""
    from scipy.optimize import brentq

    from navcore.papers import sp_residual_acceleration as spr
    from navcore.papers import sp_tracking as spt
    from navcore.units import FT

    w0_step = spr.unaided_omega0(FT)
    w0_jerk = brentq(lambda w: spt.jerk_peak_deg(FT, w) - spt.IN.peak_limit_deg, 1.0, w0_step)
    return float(w0_step / w0_jerk)


@register(
    "sp03-l1-unaided",
    "sp/03-residual-acceleration",
    "unaided natural frequency with the L1 conversion (rad/s)",
)
def sp03_l1_unaided() -> float:
    """Table 2.6's unaided natural frequency (90 deg under the 6-g step) with the L1 carrier's
    wavelength in place of one foot, rad/s."""
    from navcore.papers import sp_residual_acceleration as spr
    from navcore.units import GPS_L1_WAVELENGTH_M

    return float(spr.unaided_omega0(GPS_L1_WAVELENGTH_M))


@register(
    "sp03-apriori-sf-1", "sp/03-residual-acceleration", "Table 2.5 accelerometer scale factor, 1 nmi/h (ppm)"
)
def sp03_apriori_sf_1() -> float:
    """Table 2.5's a-priori accelerometer scale factor of the 1 nmi/h IMU, ppm (as printed)."""
    from navcore.papers.sp_tables import TABLE_2_5_PRINTED

    return float(TABLE_2_5_PRINTED["accel_scale_factor_ppm"][1])


@register(
    "sp03-needed-sf-1",
    "sp/03-residual-acceleration",
    "accelerometer scale factor that alone gives the printed 1 nmi/h radius of Table 2.6 (ppm)",
)
def sp03_needed_sf_1() -> float:
    """The scale factor (ppm) whose 90 % radius with a perfect alignment is the printed column 2
    of the 1 nmi/h IMU (Sec. 2.5's sensitivity at a = (1, 1, 1))."""
    from scipy.optimize import brentq

    from navcore.inertial.residual_acceleration import r90_from_apriori_ppm
    from navcore.papers import sp_residual_acceleration as spr

    return float(
        brentq(lambda s: r90_from_apriori_ppm(s, 0.0) - spr.col2_ppm("1"), 1e-3, sp03_apriori_sf_1())
    )


@register(
    "sp03-needed-mis-{g}",
    "sp/03-residual-acceleration",
    "misalignment that gives the printed Table 2.6 radius with the a-priori scale factor (arcsec)",
)
def sp03_needed_mis(g: str) -> float:
    """The misalignment (arcsec) whose 90 % radius, with Table 2.5's a-priori scale factor of
    grade ``g``, is the printed column 2 of that grade."""
    from scipy.optimize import brentq

    from navcore.inertial.residual_acceleration import r90_from_apriori_ppm
    from navcore.papers import sp_residual_acceleration as spr
    from navcore.papers.sp_tables import TABLE_2_5_PRINTED

    sf = float(TABLE_2_5_PRINTED["accel_scale_factor_ppm"][list(spr.GRADES).index(g)])
    return float(brentq(lambda m: r90_from_apriori_ppm(sf, m) - spr.col2_ppm(g), 0.0, 1e3))


@register(
    "sp22-unaided-jitter-dbhz",
    "sp/22-jammer-flyby",
    "C/N0 at which the unaided 18 rad/s loop's thermal jitter alone reaches the phase limit (dB-Hz)",
)
def sp22_unaided_jitter_dbhz() -> float:
    """The thermal-jitter threshold of Table 2.6's unaided loop (18 rad/s), dB-Hz."""
    from navcore.gnss.jammer_geometry import pll_jitter_threshold_dbhz
    from navcore.gnss.tracking import third_order_noise_bandwidth_hz
    from navcore.papers import sp_flyby as fb
    from navcore.papers import sp_residual_acceleration as spr

    bn = third_order_noise_bandwidth_hz(spr.IN.unaided_omega0)
    return float(
        pll_jitter_threshold_dbhz(bn, fb.IN.max_phase_error_deg, fb.IN.jitter_k_sigma, fb.IN.coherent_s)
    )


@register(
    "sp22-gps-aided-ratio",
    "sp/22-jammer-flyby",
    "horizontal error of TC 10 nmi/h over TC 0.2 nmi/h while GPS is tracked",
)
def sp22_gps_aided_ratio() -> float:
    """Sec. 2.8 assertion 1 in numbers: the 10 over the 0.2 nmi/h tightly coupled error 1 s
    before the tightly coupled blackout starts (flyby runs)."""
    from navcore.papers import sp_flyby

    return float(sp_flyby.gps_aided_error_ratio())
