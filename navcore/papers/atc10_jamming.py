"""ATC-10 Secs. 1-2.5: the jamming model of satellite multilateration, and the inputs of Secs. 1-2.

Every number this module takes from the paper is an input of :data:`IN`, declared once with
its provenance (LEDGER.md): the system parameters of Secs. 2.7-2.8 (N = 0.1 N_T, B = 10 MHz,
alpha = 1 s, beta = 24 ms, v = 600 mph), the 10 mJ pulse energy, the failure levels, the design
points of Tables 1.1 and 2.1, and the few values the paper leaves open (the antenna model behind
Table 1.1's rf and diameter columns, the P_DL behind the nominal 33 dBW). Every reproduced value
is computed by :mod:`navcore.detection.jamming`, :mod:`navcore.detection.neyman_pearson` and
:mod:`navcore.detection.antenna` from these inputs; :func:`geometry` is the paper's scenario as a
:class:`~navcore.detection.jamming.SurveillanceGeometry` preset.

The single-pulse, tracking-list, system-table and appendix modules
(:mod:`navcore.papers.atc10_single_pulse`, :mod:`navcore.papers.atc10_tracking_lists`,
:mod:`navcore.papers.atc10_system_tables`, :mod:`navcore.papers.atc10_jamming_appendices`)
read these inputs from here; :data:`IN_COV` holds those the coverage sweep of issue 17 added (a
few printed values and one assumption, the correlation of neighbouring matched-filter samples).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
from scipy import optimize, special, stats

from navcore import units
from navcore.claims import Claim, Erratum, with_quotes
from navcore.claims.inputs import InputSet, input_cache
from navcore.detection import antenna
from navcore.detection import jamming as jm
from navcore.papers.atc10_quotes import QUOTES

CLAIMS: list[Claim] = []
ERRATA: list[Erratum] = []


PAGE = "atc10/10-jamming-model"


#: Table 2.1 as printed: (K, P_DL, ERP dBW, relation). The K and P_DL of each row are inputs;
#: the ERP is the published value of the row's claim.
TABLE_2_1 = (
    (10, 0.88, "46", "="),
    (10, 0.999, "43", "="),
    (100, 0.88, "56", "="),
    (100, 0.999, "51", "="),
    (1000, 0.98, "130", ">"),
    (1000, 0.999, "77", "="),
)


#: Table 1.1 as printed: (K, ERP dBW, rf power dBW, antenna diameter ft, beamwidth deg).
TABLE_1_1 = (
    (1, 33, 15, 2, 15),
    (10, 43, 20, 4, 12),
    (100, 53, 23, 8, 5),
    (1000, 77, 40, 18, 2),
)


#: The transmission lengths of Table 1.1 and Sec. 1.1 (labels; computations read IN).
TABLE_1_1_KS = tuple(row[0] for row in TABLE_1_1)


#: Sec. 2.7, as printed: the nominal jamming level and the rf power that realises it.
NOMINAL_ERP_TEXT = "33"


NOMINAL_RF_TEXT = "30"


IN = InputSet("ATC10", "jamming")


IN.published("bandwidth_hz", 10e6, unit="Hz", locator="Sec. 2.7", quantity="signal bandwidth B")


IN.published("repetition_s", 1.0, unit="s", locator="Sec. 2.7", quantity="pulse repetition period $\\alpha$")


IN.published(
    "differential_delay_s",
    24e-3,
    unit="s",
    locator="Sec. 2.7",
    quantity="differential satellite delay $\\beta$",
)


IN.published("max_speed_mph", 600.0, unit="mph", locator="Sec. 2.8", quantity="maximum aircraft speed v")


IN.published("airborne_fraction", 0.1, locator="Sec. 2.7", quantity="$N / N_T$, the airborne fraction")


IN.published(
    "pulse_energy_j",
    10e-3,
    unit="J",
    locator="Sec. 2.7 and the captions of Tables 1.1 and 2.1",
    quantity="signal pulse energy $E = P_0 \\tau$",
)


IN.published(
    "pulse_power_dbw",
    30.0,
    unit="dBW",
    locator="Sec. 2.7 ('e.g. $P_0 = 30$ dbw')",
    quantity="pulse power $P_0$",
)


IN.published(
    "pulse_duration_s",
    10e-6,
    unit="s",
    locator="Sec. 2.7 ('$\\tau = 10$ usec')",
    quantity="pulse duration $\\tau$",
)


IN.published(
    "adl_level",
    0.01,
    locator="Sec. 2.7",
    quantity="failure level of $N_{ADL}$, as a fraction of $N_T$ ($0.01 N_T$)",
)


IN.published(
    "fl_level",
    0.9,
    locator="Sec. 2.7",
    quantity="failure level of $N_{FL}$, as a fraction of $N_T$ ($0.9 N_T$)",
)


IN.convention(
    "fl_fraction_of_level",
    0.99,
    readings={"99 % of the printed level": 0.99, "99.9 % of it": 0.999},
    reason="$0.9 N_T$ is the supremum $1 - N/N_T$ of $N_{FL}$, approached as J grows but never reached "
    "(the gap "
    "is below $10^{-10^{5}}$ at any J the figures show); the book takes the level as 99 % of it",
    quantity="fraction of the printed $N_{FL}$ level used as the failure level",
)


IN.convention(
    "plateau_fraction",
    0.001,
    readings={"within 0.1 % of its ceiling": 0.001, "within 1 % of its ceiling": 0.01},
    reason="'the bounds keep their maximum values' (Sec. 2.7) carries no number: how close to its "
    "J -> infinity ceiling a bound must stay, the book's reading fixed before computing",
    quantity="largest shortfall from the ceiling at which a bound 'keeps its maximum value'",
)


IN.published(
    "design_t",
    0.0,
    locator="Sec. 2.8 ('by just considering the curves corresponding to $t = 0$')",
    quantity="fraction t of the first-stage rule at which the required power is largest",
)


#: Table 2.1 prints each K on two rows (K = 10: rows 1-2, 100: rows 3-4, 1000: rows 5-6).
TABLE_2_1_K_ROWS = {10: (1, 2), 100: (3, 4), 1000: (5, 6)}


for _k, (_a, _b) in TABLE_2_1_K_ROWS.items():
    IN.published(f"tab21_k{_k}", _k, locator=f"Table 2.1, rows {_a}-{_b}", quantity="transmission length K")


for _r, (_k, _p, _text, _rel) in enumerate(TABLE_2_1, start=1):
    IN.published(f"tab21_r{_r}_p_dl", _p, locator=f"Table 2.1, row {_r}", quantity="design $P_{DL}$")


for _r, (_k, _erp, _rf, _dia, _bw) in enumerate(TABLE_1_1, start=1):
    IN.published(f"tab11_r{_r}_k", _k, locator=f"Table 1.1, row {_r}", quantity="transmission length K")
    IN.published(
        f"tab11_r{_r}_erp_dbw", float(_erp), unit="dBW", locator=f"Table 1.1, row {_r}", quantity="ERP"
    )
    IN.published(
        f"tab11_r{_r}_rf_dbw", float(_rf), unit="dBW", locator=f"Table 1.1, row {_r}", quantity="rf power"
    )
    IN.published(
        f"tab11_r{_r}_diameter_ft",
        float(_dia),
        unit="ft",
        locator=f"Table 1.1, row {_r}",
        quantity="dish diameter",
    )


IN.published(
    "caption_p_dl",
    0.88,
    locator="Sec. 1.1 and the caption of Table 1.1 ('a detection probability of at least 0.88')",
    quantity="design detection probability named for Table 1.1",
)


IN.convention(
    "table11_p_dl",
    0.999,
    readings={
        "$P_{DL} = 0.999$, the Table 2.1 rows that print Table 1.1's 43 and 77": 0.999,
        "the caption's $P_{DL} = 0.88$": 0.88,
        "$P_{DL} = 0.98$, Table 2.1's other $K = 1000$ design (at least 0.88, as the caption asks)": 0.98,
    },
    reason="the caption asks for 'at least 0.88', which a design for any higher $P_{DL}$ also meets; the "
    "three design values the paper uses in Sec. 2.8 and Table 2.1",
    quantity="design $P_{DL}$ of Table 1.1's $K = 10$, 100 and 1000 rows",
)


IN.convention(
    "figure_level_decades",
    0.0,
    unit="decades",
    readings={
        "the stated level, $0.01 N_T$": 0.0,
        "0.05 decade above it, as misread on a logarithmic axis": 0.05,
        "0.05 decade below it, as misread on a logarithmic axis": -0.05,
    },
    reason="Tables 1.1 and 2.1 and the nominal 33 dBW were read off the (lost) curves of Figs. 2.1-2.16 "
    "where they cross $0.01 N_T$ (Secs. 2.7-2.8); a hand reading places a level on a logarithmic axis to "
    "about 0.05 decade (12 %), which moves a shallow crossing by a dB or more",
    quantity="$N_{ADL}$ level of the figure readings",
)


IN.convention(
    "step_p_dl",
    0.999,
    readings={
        "Table 2.1's $P_{DL} = 0.999$ rows, the design Table 1.1 summarises": 0.999,
        "Table 2.1's $P_{DL} = 0.88$ rows, the caption's design": 0.88,
    },
    reason="Sec. 2.8's 'about 10 db more power' summarises Table 2.1, whose rows have two design values, "
    "and names neither",
    quantity="design $P_{DL}$ of the steps of Sec. 2.8",
)


IN.convention(
    "step_k1_reference",
    "nominal",
    readings={
        "Sec. 2.7's nominal 33 dBW, the paper's $K = 1$ level": "nominal",
        "the $K = 1$ threshold computed at the same $P_{DL}$": "computed",
    },
    reason="Sec. 2.8 compares a $K = 10$ system with 'a $K = 1$ system'; Sec. 2.7 takes 33 dBW as the "
    "nominal $K = 1$ level for any $P_{DL}$ from 0.9 to 0.999",
    quantity="$K = 1$ level the step from $K = 1$ to $K = 10$ starts from",
)


IN.published(
    "sec27_p_dl_low", 0.9, locator="Sec. 2.7 ('for a $P_{DL}$ of 0.9 and 0.999')", quantity="design $P_{DL}$"
)


IN.published(
    "sec27_p_dl_high",
    0.999,
    locator="Sec. 2.7 ('for a $P_{DL}$ of 0.9 and 0.999')",
    quantity="design $P_{DL}$",
)


IN.assumed(
    "nominal_p_dl",
    0.9,
    low=0.9,
    high=0.999,
    reason="Sec. 2.7 takes 33 dBW as the nominal level for $K = 1$ because the requirements for "
    "$P_{DL} = 0.9$ and 0.999 differ by less than 2 dB; the design it stands for is any "
    "$P_{DL}$ in that printed range",
    quantity="design $P_{DL}$ behind the nominal 33 dBW ($K = 1$)",
)


IN.published(
    "nominal_erp_dbw",
    float(NOMINAL_ERP_TEXT),
    unit="dBW",
    locator="Sec. 2.7",
    quantity="nominal jamming level",
)


IN.published("nominal_rf_w", float(NOMINAL_RF_TEXT), unit="W", locator="Sec. 2.7", quantity="rf power")


IN.assumed(
    "dish_frequency_hz",
    1.6e9,
    low=1.0e9,
    high=2.0e9,
    unit="Hz",
    reason="Sec. 2.1 places the system 'at L band' without a frequency; the range is the IEEE L band "
    "(1-2 GHz), the nominal 1.6 GHz the aeronautical satellite band (1.54-1.66 GHz)",
    quantity="jammer antenna frequency behind Table 1.1's rf and diameter columns",
)


IN.assumed(
    "dish_efficiency",
    0.6,
    low=0.5,
    high=0.7,
    reason="the paper gives no antenna model; 0.5-0.7 is the aperture efficiency of a practical "
    "parabolic dish, 0.6 the usual nominal",
    quantity="jammer dish aperture efficiency",
)


IN.published(
    "sec27_beamwidth_deg",
    20.0,
    unit="deg",
    locator="Sec. 2.7 ('30 watts of rf power and an antenna with a 20 degree beamwidth')",
    quantity="beamwidth of the antenna that gives the nominal 33 dBW from 30 W",
)


IN.fitted(
    "pencil_beam_constant_deg2",
    26_600.0,
    unit="deg^2",
    fitted_to=("ATC10-sec2.7-20deg",),
    reason="the paper gives no rule relating beamwidth to gain; the constant C of the pencil-beam rule "
    "$G = C/\\theta^2$ solved from Sec. 2.7's 20 degrees for 33 dBW from 30 W ($C = 400 \\times 66.5$). "
    "Textbook "
    "constants range from about 26 000 to 33 000 for practical dishes (41 253 for an ideal beam), and "
    "only 26 400-28 000 fits Sec. 2.7 and Table 1.1's $K = 10$-1000 rows together: a fit, not a reading",
    quantity="constant of the pencil-beam rule, beamwidth² × gain",
)


IN.published("toa_rms_error_s", 50e-9, unit="s", locator="Sec. 1.3", quantity="rms time-of-arrival error")


IN.published("update_interval_s", 1.0, unit="s", locator="Sec. 1.3", quantity="position update interval")


@input_cache
def geometry(sample_scale: float = 1.0) -> jm.SurveillanceGeometry:
    """The paper's system (Secs. 2.7-2.8) as a :class:`~navcore.detection.jamming.SurveillanceGeometry`.

    ``sample_scale`` scales the bandwidth of the sample counts only (0.5: half as many independent
    samples per window, a sensitivity; the ERP scale uses :func:`energy_bandwidth_dbw`).
    """
    return jm.SurveillanceGeometry(
        bandwidth_hz=IN.bandwidth_hz * sample_scale,
        repetition_s=IN.repetition_s,
        differential_delay_s=IN.differential_delay_s,
        max_speed_m_s=IN.max_speed_mph * units.MPH,
        airborne_fraction=IN.airborne_fraction,
        pulse_energy_j=IN.pulse_energy_j,
    )


def erp_dbw(x_db: float) -> float:
    """Jammer ERP (dBW) for ``10 log10(J / (P0 B tau)) = x_db``, with the paper's E and B."""
    return float(jm.jammer_erp_dbw(x_db, IN.pulse_energy_j, IN.bandwidth_hz))


def level(quantity: str) -> float:
    """Failure level as a fraction of N_T: 0.01 for N_ADL, 99 % of 0.9 for N_FL (Sec. 2.7)."""
    if quantity == "ambiguous":
        return float(IN.adl_level)
    return float(IN.fl_fraction_of_level * IN.fl_level)


def table21_design(row: int) -> tuple[int, float]:
    """(K, P_DL) of Table 2.1's row ``row`` (1-6)."""
    k = TABLE_2_1[row - 1][0]
    return int(getattr(IN, f"tab21_k{k}")), float(getattr(IN, f"tab21_r{row}_p_dl"))


def table21_finite_designs() -> list[tuple[int, float]]:
    """The (K, P_DL) rows of Table 2.1 printed with a finite ERP ('=' rows)."""
    return [table21_design(r) for r, row in enumerate(TABLE_2_1, start=1) if row[3] == "="]


@input_cache
def design_p_d(p_dl: float, k: int, t: float | None = None) -> float:
    """Per-filter p_d that gives P_DL = p_dl for K lists at fraction t (Eq. 2.4.2; t = 0 by default)."""
    return jm.filter_detection_probability_for_bound(p_dl, k, IN.design_t if t is None else t)


@input_cache
def required_erp_dbw(
    quantity: str, p_dl: float, k: int, t: float | None = None, figure_read: bool = False
) -> float:
    """Jammer ERP (dBW) at which N_ADL = 0.01 N_T ("ambiguous") or N_FL = 99 % of its
    supremum 0.9 N_T ("false"), at the design point (P_DL, K, t).

    ``figure_read``: the value as read off a figure, at the N_ADL level moved by the
    convention ``figure_level_decades`` (for claims the paper read off Figs. 2.1-2.16).
    """
    t = IN.design_t if t is None else t
    p_d = design_p_d(p_dl, k, t)
    lev = level(quantity)
    if figure_read and quantity == "ambiguous":
        lev *= 10.0 ** float(IN.figure_level_decades)
    x_db = jm.jammer_ratio_threshold_db(quantity, lev, p_d, k, t, geometry())
    return erp_dbw(x_db)


def table11_diameter_ft(row: int) -> float:
    """Dish diameter for the gain printed ERP - printed rf power (assumed frequency and efficiency)."""
    erp = float(getattr(IN, f"tab11_r{row + 1}_erp_dbw"))
    rf = float(getattr(IN, f"tab11_r{row + 1}_rf_dbw"))
    gain = units.power_ratio_from_db(erp - rf)
    return float(antenna.dish_diameter(gain, IN.dish_frequency_hz, IN.dish_efficiency)) / units.FT


def table11_beamwidth_deg(row: int) -> float:
    """70 lambda / D for the dish of :func:`table11_diameter_ft` (reads the assumed antenna model)."""
    return float(antenna.dish_beamwidth_deg(table11_diameter_ft(row) * units.FT, IN.dish_frequency_hz))


def _exponent_matches_numeric() -> bool:
    worst = 0.0
    for t, q in ((0.05, 0.3), (0.1, 0.2), (0.01, 0.0069), (0.4, 0.3), (0.2, 0.9)):

        def neg(nu: float, t: float = t, q: float = q) -> float:
            return -(nu * (1 - t) - (nu + math.log((1 - q) + q * math.exp(-nu))))

        res = optimize.minimize_scalar(neg, bounds=(0.0, 60.0), method="bounded", options={"xatol": 1e-12})
        worst = max(worst, abs(float(jm.list_rule_exponent(t, q)) - max(-res.fun, 0.0)))
    return worst < 1e-10


def _k1_bound_is_pd4() -> bool:
    p = np.linspace(0.0, 1.0, 52)[1:-1]  # 50 values of p_d strictly inside (0, 1)
    # the bound is 1 - exp(-K D): its rounding is absolute, a few ulp of 1, where p_d^4 is small
    atol = 4 * np.finfo(float).eps
    return bool(np.allclose(jm.detection_lower_bound(p, 1, 0.0), p**4, rtol=1e-12, atol=atol))


#: P_DL values drawn in Figs. 2.1-2.2 by the book (the paper's set is lost; it names 0.9 and 0.999).
K1_PDL_GRID = (0.88, 0.9, 0.99, 0.999)


def half_samples_geometry() -> jm.SurveillanceGeometry:
    """The sample counts of (B.6) and (C.14) halved (B samples per second instead of 2B), with the
    energy-bandwidth product, and so the ERP scale, unchanged: a sensitivity to sample correlation."""
    return geometry(0.5)


@input_cache
def adl_erp_dbw_half_samples(p_dl: float, k: int) -> float:
    """N_ADL = 0.01 N_T ERP (t = 0) when every window holds half as many independent samples."""
    x_db = jm.jammer_ratio_threshold_db(
        "ambiguous", level("ambiguous"), design_p_d(p_dl, k), k, 0.0, half_samples_geometry()
    )
    return erp_dbw(x_db)


@input_cache
def adl_erp_dbw_without_pdl_factor(p_dl: float, k: int) -> float:
    """ERP at which 1/2 N G^(K-1) F (the N_ADL bound without its P_DL factor) reaches 0.01 N_T.

    Solving N_ADL = 0.01 P_DL N_T with the printed bound is the same equation.
    """
    p_d = design_p_d(p_dl, k)
    x_db = jm.jammer_ratio_threshold_db("ambiguous", level("ambiguous") * p_dl, p_d, k, 0.0, geometry())
    return erp_dbw(x_db)


def max_pdl_factor_shift_db() -> float:
    """Largest drop of the t = 0 N_ADL threshold when the P_DL factor of (2.5.12) is dropped, over
    K = 1 (P_DL 0.88-0.999) and the finite Table 2.1 entries."""
    points = [(p, 1) for p in K1_PDL_GRID] + [(p, k) for k, p in table21_finite_designs()]
    return max(required_erp_dbw("ambiguous", p, k) - adl_erp_dbw_without_pdl_factor(p, k) for p, k in points)


CLAIMS += [
    Claim.statement(
        id="ATC10-eq2.4.1",
        locator="Eqs. (2.4.1), (A.10a)",
        quantity="for K = 1 the detection bound is $p_d^4$",
        compute=_k1_bound_is_pd4,
        kind="statement",
        note="The closed-form Chernoff bound at $K = 1$, $t = 0$ against $p_d^4$ on a grid of $p_d$.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eq2.4.2-nu-max",
        locator="Eqs. (2.4.2), (A.17)-(A.18)",
        quantity="the $\\nu$-maximised exponent of (2.4.2) equals the binary divergence $D(t \\| p_d^4)$ for "
        "$t < p_d^4$ and 0 otherwise",
        compute=_exponent_matches_numeric,
        kind="statement",
        note="Closed form against bounded numerical maximisation over $\\nu \\ge 0$ at five (t, q) pairs, to "
        "$10^{-10}$.",
        discussed_in=PAGE,
        table="log-domain",
    ),
]


IN_COV = InputSet("ATC10", "jamming_coverage")


IN_COV.published(
    "sec11_airborne_share",
    0.10,
    locator="Sec. 1.1 ('at least 10% of the number of airborne aircraft are falsely located')",
    quantity="share of the airborne aircraft falsely located at the Table 1.1 level",
)


IN_COV.convention(
    "threshold_upper_fraction",
    0.9,
    readings={
        "90 % of the ceiling": 0.9,
        "half the ceiling": 0.5,
        "a tenth of the ceiling": 0.1,
    },
    reason="'a strong threshold behavior' (Sec. 2.1) and 'a strong thresholding property' (Sec. 2.8) name "
    "no level: the fall of a bound is measured from a fraction of its $J \\to \\infty$ ceiling down to "
    "$10^{-6}$ of "
    "it, and the text does not say from which",
    quantity="fraction of its ceiling from which a bound's fall (to a millionth of it) is measured",
)


IN_COV.convention(
    "threshold_width_db",
    10.0,
    unit="dB",
    readings={
        "10 dB, a tenth of the -20 to +80 dB that the figures span": 10.0,
        "5 dB, a twentieth of the span of the figures": 5.0,
    },
    reason="'strong' and 'very rapidly' carry no number: the book's reading of how narrow a fall makes a "
    "threshold, fixed before computing",
    quantity="widest fall that counts as a strong threshold",
)


IN_COV.convention(
    "near_threshold_db",
    1.0,
    unit="dB",
    readings={"within 1 dB, the whole-dB resolution of the tables": 1.0, "within 2 dB": 2.0},
    reason="'these are close to the threshold' (Sec. 2.7) carries no number: the book's reading",
    quantity="largest gap between a failure level and the half-ceiling point that counts as 'close'",
)


IN_COV.assumed(
    "neighbour_correlation",
    0.5,
    low=0.3,
    high=0.5,
    reason="Sec. 2.3 samples the matched-filter output at twice the Nyquist rate, so neighbouring noise "
    "samples 1/(2B) apart are correlated; for a spectrum inside |f| < B/2 the correlation "
    "$\\int S(f) \\cos(\\pi f / B)\\, df$ is positive. With correlation between neighbours only (a code of "
    "rectangular chips sampled twice per chip) it is 0.5, the largest such a process allows; 0.3 stands "
    "for chips shaped to put more power at the band edges",
    quantity="correlation of neighbouring matched-filter noise samples",
)


IN_J = IN


def _log_bound(quantity: str, x_db: np.ndarray, p_d: float, k: int, t: float) -> np.ndarray:
    fn = jm.log_ambiguous_detection_bound if quantity == "ambiguous" else jm.log_false_location_bound
    return np.asarray(fn(10 ** (np.asarray(x_db) / 10), p_d, k, t, geometry()), float)


def _coherent_beats_envelope() -> bool:
    """Matched-filter (coherent) p_d >= matched filter-envelope p_d at equal p_f and energy."""
    d = np.linspace(0.5, 10.0, 40)[:, None]
    pf = np.geomspace(1e-9, 0.3, 30)[None, :]
    coherent = stats.norm.sf(stats.norm.isf(pf) - d)
    envelope = stats.ncx2.sf(-2.0 * np.log(pf), 2, d**2)
    return bool(np.all(coherent >= envelope))


def _segment_holds_signature() -> bool:
    """Every segment of length alpha + beta holds one complete quadruplet; some hold two."""
    rng = np.random.default_rng(19720622)
    alpha, beta = float(IN_J.repetition_s), float(IN_J.differential_delay_s)
    n = 20000
    delays = rng.uniform(0.0, beta, (n, 4))
    phase = rng.uniform(0.0, alpha, n)
    start = rng.uniform(0.0, 10 * alpha, n)
    pulses = np.arange(-2, 14)[None, :, None] * alpha + phase[:, None, None] + delays[:, None, :]
    inside = (pulses >= start[:, None, None]) & (pulses < (start + alpha + beta)[:, None, None])
    complete = inside.all(axis=2).sum(axis=1)
    return bool(np.all(complete >= 1) and np.any(complete == 2))


def _random_pick_at_least_half() -> bool:
    """(2.5.10): a uniform pick from a set with >= 1 wrong and <= 1 correct position is wrong w.p. >= 1/2."""
    worst = min(Fraction(wrong, wrong + correct) for wrong in range(1, 50) for correct in (0, 1))
    return worst == Fraction(1, 2)


def _plain_bounds(x_db: float, p_d: float, k: int, t: float) -> tuple[float, float]:
    """N_FL/N_T and N_ADL/N_T typed from (2.5.5), (2.5.12), (2.7.1) with plain floats.

    Each factor is typed in the form that keeps its digits where it is small: ``0.5 erfc`` for
    the tail of (2.7.1) (``0.5 - 0.5 erf`` cancels), ``1 - (1 - p_f)^n`` as
    ``-expm1(n log1p(-p_f))`` (``1 - p_f`` rounds to 1 for ``p_f`` below 1e-16), and at t = 0
    the nu -> infinity limit of (2.4.2), ``1 - (1 - q)^K``, in the same form.
    """
    g = geometry()
    phi = special.erfinv(2 * p_d - 1)
    x = 10 ** (x_db / 10)
    pf = 0.5 * special.erfc(math.sqrt(0.5 / x) - phi)
    na, nb, nv = g.samples_per_period, g.samples_per_delay_window, g.samples_per_track_window

    def some(n: float) -> float:  # 1 - (1 - p_f)^n
        return -math.expm1(n * math.log1p(-pf))

    f = some(na) * some(nb) ** 3
    gg = some(na) * some(nv) ** 3
    n_share = g.airborne_fraction
    if k == 1 and t == 0:  # the printed K = 1 line; with t > 0 a single list follows (2.4.2)
        pdl = p_d**4
    else:
        q = p_d**4
        if t > 0:
            nu = math.log((1 - t) * q / (t * (1 - q)))
            pdl = -math.expm1(-k * (nu * (1 - t) - math.log((1 - q) * math.exp(nu) + q)))
        else:
            pdl = -math.expm1(k * math.log1p(-q))
    n_fl = (1 - n_share) * f ** (k * t + 1)
    n_adl = 0.5 * n_share * pdl * gg ** (k - 1) * f
    return n_fl, n_adl


def _composition(which: int) -> bool:
    ok = True
    for k, t in ((1, 0.0), (10, 0.0), (10, 0.1), (100, 0.05)):
        p_d = design_p_d(0.999, k, t)
        for x_db in (-16.0, -12.0, -8.0, -4.0, 0.0):
            plain = _plain_bounds(x_db, p_d, k, t)[which]
            quantity = "false" if which == 0 else "ambiguous"
            model = math.exp(float(_log_bound(quantity, np.array([x_db]), p_d, k, t)[0]))
            if plain > 1e-250:
                ok &= math.isclose(model, plain, rel_tol=1e-6)
    return bool(ok)


CLAIMS += [
    Claim.statement(
        id="ATC10-sec2.3-coherent-beats-envelope",
        locator="Sec. 2.3",
        quantity="a matched filter detector (phase known) always performs better than a matched "
        "filter-envelope detector",
        compute=_coherent_beats_envelope,
        note="At equal $p_f$ and energy: coherent $p_d = Q(Q^{-1}(p_f) - d)$ against the envelope (Rician) "
        "$p_d = Q_1(d, \\sqrt{-2 \\ln p_f})$ (noncentral $\\chi$-square, 2 degrees of freedom), $d$ from "
        "0.5 to "
        "10 "
        "and $p_f$ "
        "from $10^{-9}$ to 0.3.",
        discussed_in=PAGE,
        table="appendix-steps",
    ),
    Claim.statement(
        id="ATC10-sec2.3-segment-holds-signature",
        locator="Sec. 2.3",
        quantity="every segment of length $\\alpha + \\bar\\beta$ holds a present aircraft's signature at "
        "all four filters at least once, possibly twice",
        compute=_segment_holds_signature,
        note="20000 seeded random phases, satellite delays in [0, $\\beta$] and segment origins, $\\alpha = "
        "1$ s, $\\beta = 24$ ms: every segment holds a complete quadruplet and some hold two.",
        discussed_in=PAGE,
        table="appendix-steps",
    ),
    Claim.statement(
        id="ATC10-eq2.5.10-random-pick",
        locator="Eq. (2.5.10)",
        quantity="a random pick from a position set holding a wrong position is wrong with probability "
        "$\\ge 0.5$",
        compute=_random_pick_at_least_half,
        note="The set holds at least one wrong position and at most one correct one; the smallest share of "
        "wrong positions over set sizes up to 50 is exactly 1/2 (one wrong, one correct).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eq2.5.5-composition",
        locator="Eqs. (2.5.1)-(2.5.5), (2.7.3), (B.11)",
        quantity="$N_{FL} = (N_T - N)\\, e^{(Kt + 1) \\ln F(p_f)}$ with $p_f$ of (2.7.1)",
        compute=lambda: _composition(0),
        note="The book's log-domain bound against the printed formulas typed with plain floats (erf, "
        "powers) at $K$ = 1, 10 and 100, $t$ from 0 to 0.1 and $J/(P_0 B \\tau)$ from -16 to 0 dB, to "
        "$10^{-6}$ relative (each factor typed in the form that keeps its digits where it is small); at $t "
        "= 0$ the exponent is 1, so (B.11) gives (B.8).",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="ATC10-eq2.5.12-composition",
        locator="Eqs. (2.5.12), (2.7.3), (2.8.4), (C.17)",
        quantity="$N_{ADL} = 0.5 N P_{DL} G(p_f)^{K-1} F(p_f)$, with $P_{DL} = p_d^4$ at $K = 1$",
        compute=lambda: _composition(1),
        note="As for $N_{FL}$: the printed $K = 1$ and $K > 1$ lines ($P_{DL}$ from (2.4.2) with its $\\nu$ "
        "maximiser) typed "
        "with plain floats, against the book's log-domain bound, to $10^{-6}$ relative where nothing "
        "underflows.",
        discussed_in=PAGE,
    ),
]

#: Every claim quotes the paper (issue 27, item 5).
CLAIMS = with_quotes(CLAIMS, QUOTES)
